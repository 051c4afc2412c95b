"""Shadow maps: light views, the light-space depth pass, the biased lookups and the measures
(texel footprint, aliasing m) that every map technique (:mod:`cityshade.shadows.planners`)
shares.

Conventions
-----------
* A :class:`LightView` is an OpenGL-style ``clip_from_world`` matrix (render space → light clip
  space; x, y, z in [-w, w] inside) and a map size. Texel ``(col, row)`` covers NDC
  ``x in [2 col / W - 1, 2 (col + 1) / W - 1]``, row 0 at the top (NDC y = +1), exactly like
  :meth:`cityshade.raster.camera.Camera.clip_from_world`. :func:`project` returns continuous
  texel coordinates ``u_px = (x/w + 1) W / 2`` (texel ``floor(u_px)``; centres at ``+0.5``)
  and ``v_px = (1 - y/w) H / 2``, and the NDC depth ``z/w``.
* Depth maps store NDC depth ``z/w`` as float32: -1 at the near plane (toward the sun), +1 at the
  far plane, smaller is nearer the sun; ``+inf`` where no caster. Casters nearer than the near
  plane are clamped to -1 (they still cast).
* The uniform view (:func:`fit_uniform`) is orthographic along the sun's rays, so its NDC depth
  is affine in metres along the rays: one NDC unit is ``metres_per_ndc(view)`` metres.

Bias (the receiver side, so it works unchanged on warped and cascaded maps): a facing receiver
``p`` with oriented unit normal ``n`` is looked up at

    p' = p + bias_m · s + min(slope_bias · t · sinθ · (1 + r), max_bias_m) · n

where ``s`` is the unit vector toward the sun, ``θ`` the angle between ``n`` and ``s``, ``t`` the
light-space texel size at ``p`` (metres, perpendicular to the rays) and ``r`` the filter radius in
texels. The normal offset equals the classic slope-scaled depth bias ``slope_bias · t · tanθ``
(measured along the ray) but also moves the lookup toward the caster, so a shadow still starts
at the foot of a wall: a plane's depth within one texel differs from the texel centre's by at
most ``t/√2 · tanθ``, which an offset ``δ ≥ t/√2 · sinθ`` along the normal covers for every θ
(so ``slope_bias ≥ 0.71`` removes acne; the default adds margin for float32 depth).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numba import njit, prange

from cityshade.config import MAX_MAP_PX, MapSettings, ShadowSettings
from cityshade.errors import UsageError
from cityshade.raster.depthpass import render_depth
from cityshade.raster.triangles import TILE_PX
from cityshade.shadows import ShadowContext
from cityshade.runtime.memory import Scratch

#: Smallest extent (metres) of a fitted light view across or along the rays: a single visible
#: point still gets a non-degenerate map.
MIN_EXTENT_M = 0.01
#: Depth margin of the fitted view beyond the receivers and casters, relative to the depth range
#: (plus MIN_EXTENT_M): float32 rounding of vertices never pushes a surface out of the range.
DEPTH_MARGIN_REL = 1e-3


@dataclass(frozen=True, eq=False)
class LightView:
    """A shadow-map view.

    Attributes
    ----------
    clip_from_world : (4, 4) float64
        Render space → light clip space (OpenGL-style: inside is x, y, z in [-w, w]); may be
        projective (warps).
    width_px, height_px : int
        Map size in texels.
    name : str
        "uniform", "psm", "lispsm", "xpsm", "csm-k", ...
    """

    clip_from_world: np.ndarray
    width_px: int
    height_px: int
    name: str = "uniform"

    def __post_init__(self) -> None:
        m = np.asarray(self.clip_from_world, dtype=np.float64)
        if m.shape != (4, 4) or not np.isfinite(m).all():
            raise UsageError(f"a light view needs a finite (4, 4) clip_from_world, "
                             f"not shape {m.shape}")
        object.__setattr__(self, "clip_from_world", m)
        for name in ("width_px", "height_px"):
            value = getattr(self, name)
            if not (isinstance(value, (int, np.integer)) and 1 <= value <= MAX_MAP_PX):
                raise UsageError(f"light view {name} must be an integer in [1, {MAX_MAP_PX}], "
                                 f"not {value!r}")
            object.__setattr__(self, name, int(value))

    @property
    def is_projective(self) -> bool:
        """True for a warped view (its w row is not (0, 0, 0, 1))."""
        return not np.array_equal(self.clip_from_world[3], [0.0, 0.0, 0.0, 1.0])

    @property
    def shape(self) -> tuple[int, int]:
        """(H, W)."""
        return self.height_px, self.width_px


@dataclass(eq=False)
class DepthMap:
    """The light-space depth pass of one :class:`LightView`.

    Attributes
    ----------
    view : LightView
    depth : (H, W) float32
        NDC depth ``z/w`` of the caster nearest the sun at each texel centre, in [-1, 1]
        (nearer casters clamped to -1); ``+inf`` where no caster.
    prim_id : (H, W) int32
        Triangle id of that caster, -1 where none.
    stats : dict
        ``casters_drawn``, ``frustum_refs_removed``, ``time_refs_removed``, ``texels``,
        ``culling``, ``threads`` and ``timings_s`` (walk, setup, bin, raster, total). The
        covered texels are ``(prim_id >= 0).sum()``, counted by who needs them (a pass over the
        map: 2-3 ms at 4096²).
    """

    view: LightView
    depth: np.ndarray
    prim_id: np.ndarray
    stats: dict = field(default_factory=dict)


# --- light views ------------------------------------------------------------------------------

def light_basis(sun_direction) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit (right, up, forward) of a light looking along the sun's rays (forward = -sun).

    ``right`` is horizontal (perpendicular to the sun's azimuth); with the sun at the zenith
    the frame is east/north.
    """
    s = _unit_sun(sun_direction)
    fwd = -s
    side = np.cross(fwd, np.array([0.0, 0.0, 1.0]))
    if np.linalg.norm(side) < 1e-9:
        side = np.array([1.0, 0.0, 0.0])
    right = side / np.linalg.norm(side)
    up = np.cross(right, fwd)
    return right, up / np.linalg.norm(up), fwd


def ortho_view(sun_direction, x_range_m, y_range_m, depth_range_m, width_px: int,
               height_px: int, name: str = "uniform") -> LightView:
    """Orthographic light view along the sun's rays.

    Parameters
    ----------
    sun_direction : (3,) unit vector toward the sun.
    x_range_m, y_range_m : (lo, hi) along the light basis' right / up axes (metres, render
        space dot products).
    depth_range_m : (near, far) along the rays (``p · forward``); near is toward the sun.
    """
    right, up, fwd = light_basis(sun_direction)
    (x0, x1), (y0, y1), (n, f) = x_range_m, y_range_m, depth_range_m
    if not (x1 > x0 and y1 > y0 and f > n):
        raise UsageError(f"empty light view ranges {x_range_m}, {y_range_m}, {depth_range_m}")
    m = np.zeros((4, 4))
    m[0, :3] = 2.0 * right / (x1 - x0)
    m[0, 3] = -(x1 + x0) / (x1 - x0)
    m[1, :3] = 2.0 * up / (y1 - y0)
    m[1, 3] = -(y1 + y0) / (y1 - y0)
    m[2, :3] = 2.0 * fwd / (f - n)
    m[2, 3] = -(f + n) / (f - n)
    m[3, 3] = 1.0
    return LightView(m, int(width_px), int(height_px), name)


def _unit_sun(sun_direction) -> np.ndarray:
    s = np.asarray(sun_direction, dtype=np.float64).reshape(3)
    norm = float(np.linalg.norm(s))
    if not (math.isfinite(norm) and norm > 0.0):
        raise UsageError(f"sun direction must be a finite non-zero vector, not {sun_direction}")
    return s / norm


def _size_px(size_px) -> tuple[int, int]:
    if isinstance(size_px, (int, np.integer)):
        w = h = int(size_px)
    else:
        try:
            w, h = (int(v) for v in size_px)
        except (TypeError, ValueError):
            raise UsageError(f"map size must be an integer or (width, height), not {size_px!r}") \
                from None
    if not (1 <= w <= MAX_MAP_PX and 1 <= h <= MAX_MAP_PX):
        raise UsageError(f"map size must be in [1, {MAX_MAP_PX}] texels, not {w}x{h}")
    return w, h


def scene_bounds(scene) -> np.ndarray:
    """(2, 3) float64 render-space box of all triangles (the kd-tree's when there is one)."""
    tree = getattr(scene, "kdtree", None)
    if tree is not None:
        return np.asarray(tree.bounds[:, :3], np.float64)
    v = np.asarray(scene.vertices, np.float64)
    if v.shape[0] == 0:
        return np.zeros((2, 3))
    return np.stack([v.min(axis=0), v.max(axis=0)])


def receiver_points(ctx: ShadowContext) -> np.ndarray:
    """(N, 3) float64 points a fitted view must cover: the visible pixels facing the sun (the
    only ones a map is read at), else all visible pixels, else none."""
    surfaces = ctx.surfaces
    points = surfaces.position_m[ctx.faces]
    if points.shape[0] == 0:
        points = surfaces.position_m[np.asarray(surfaces.valid, bool)]
    return np.asarray(points, np.float64)


def fit_uniform(scene, ctx: ShadowContext, size_px, *, pad_px: int | None = None,
                receivers_m=None) -> LightView:
    """Uniform orthographic light view fitted to the visible receivers and their casters.

    Across the rays the view covers the light-space box of the visible receivers facing the sun
    (:func:`receiver_points`) plus ``pad_px`` texels on each side; along the rays it reaches from
    the scene's point nearest the sun (every caster that can shade a receiver lies in the
    receivers' box extruded toward the sun, and the depth pass culls the rest by the view's
    side planes) to the farthest receiver. Without receivers the whole scene box is covered.

    Parameters
    ----------
    scene : Scene
    ctx : ShadowContext
        Its surfaces, camera and sun are used.
    size_px : int or (width, height)
        Map size in texels.
    pad_px : int, optional
        Margin in texels (default ``MapSettings.fit_pad_px``).
    receivers_m : (N, 3) array_like, optional
        The receivers when the caller has them already (default :func:`receiver_points`).
    """
    w, h = _size_px(size_px)
    pad = MapSettings().fit_pad_px if pad_px is None else int(pad_px)
    if not 0 <= 2 * pad < min(w, h):
        raise UsageError(f"pad_px must be in [0, {min(w, h) // 2}), not {pad}")
    right, up, fwd = light_basis(ctx.sun.direction)
    box = scene_bounds(scene)
    corners = np.array([[box[i, 0], box[j, 1], box[k, 2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    points = (receiver_points(ctx) if receivers_m is None
              else np.asarray(receivers_m, np.float64).reshape(-1, 3))
    if points.shape[0] == 0:
        points = corners
    basis = np.stack([right, up, fwd], axis=1)
    lo, hi = light_box(points, basis)
    near = min(float((corners @ fwd).min()), float(lo[2]))
    far = float(hi[2])
    margin = DEPTH_MARGIN_REL * (far - near) + MIN_EXTENT_M
    near, far = near - margin, far + margin
    ranges = []
    for axis, n_px in ((0, w), (1, h)):
        extent = max(float(hi[axis] - lo[axis]), MIN_EXTENT_M)
        centre = 0.5 * float(hi[axis] + lo[axis])
        texel = extent / (n_px - 2 * pad)
        half = 0.5 * n_px * texel
        ranges.append((centre - half, centre + half))
    return ortho_view(ctx.sun.direction, ranges[0], ranges[1], (near, far), w, h, "uniform")


@njit(cache=True)
def _light_box_kernel(points, basis, lo, hi):
    for i in range(points.shape[0]):
        for j in range(3):
            d = (points[i, 0] * basis[0, j] + points[i, 1] * basis[1, j]
                 + points[i, 2] * basis[2, j])
            lo[j] = min(lo[j], d)
            hi[j] = max(hi[j], d)


def light_box(points_m, basis) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) (3,) of ``points_m @ basis`` over the points (one pass, no (N, 3) product)."""
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    _light_box_kernel(np.ascontiguousarray(points_m, np.float64),
                      np.ascontiguousarray(basis, np.float64), lo, hi)
    return lo, hi


def metres_per_ndc(view: LightView) -> float:
    """Metres along the rays per unit of NDC depth (exact for orthographic views, the value at
    ``w = 1`` for projective ones)."""
    return 1.0 / float(np.linalg.norm(view.clip_from_world[2, :3]))


# --- projections and measures -----------------------------------------------------------------

def project(view: LightView, points_m) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Project render-space points into the map.

    Parameters
    ----------
    view : LightView
    points_m : (N, 3) array_like
        Render-space points, metres.

    Returns
    -------
    u_px, v_px, depth : (N,) float64
        Continuous texel coordinates (texel ``floor(u_px), floor(v_px)``; column, row from the
        top-left corner) and NDC depth ``z/w``. Points with ``w <= 0`` get NaN.
    """
    p = np.asarray(points_m, dtype=np.float64).reshape(-1, 3)
    m = view.clip_from_world
    clip = p @ m[:, :3].T + m[:, 3]
    w = clip[:, 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = np.where(w > 0.0, 1.0 / np.where(w > 0.0, w, 1.0), np.nan)
    u = (clip[:, 0] * inv + 1.0) * (0.5 * view.width_px)
    v = (1.0 - clip[:, 1] * inv) * (0.5 * view.height_px)
    return u, v, clip[:, 2] * inv


@njit(cache=True, inline="always")
def _tangent_frame(nx, ny, nz):
    """Two unit tangents of the plane with normal (nx, ny, nz) (helper axis z, or x when the
    normal is nearly vertical)."""
    norm = math.sqrt(nx * nx + ny * ny + nz * nz)
    if norm > 0.0:
        nx, ny, nz = nx / norm, ny / norm, nz / norm
    if abs(nz) < 0.9:
        hx, hy, hz = 0.0, 0.0, 1.0
    else:
        hx, hy, hz = 1.0, 0.0, 0.0
    ax, ay, az = ny * hz - nz * hy, nz * hx - nx * hz, nx * hy - ny * hx
    la = math.sqrt(ax * ax + ay * ay + az * az)
    ax, ay, az = ax / la, ay / la, az / la
    return ax, ay, az, ny * az - nz * ay, nz * ax - nx * az, nx * ay - ny * ax


@njit(cache=True, inline="always")
def _image_jacobian(m, width, height, px, py, pz, t1x, t1y, t1z, t2x, t2y, t2z):
    """Derivatives of (column, row) of the image of clip matrix ``m`` (16,) along two tangents:
    (dc/dt1, dc/dt2, dr/dt1, dr/dt2)."""
    x = m[0] * px + m[1] * py + m[2] * pz + m[3]
    y = m[4] * px + m[5] * py + m[6] * pz + m[7]
    w = m[12] * px + m[13] * py + m[14] * pz + m[15]
    sc = 0.5 * width / (w * w)
    sr = -0.5 * height / (w * w)
    # d(x/w)/dp = (m0 w - x m3) / w², per axis.
    cx = sc * (m[0] * w - x * m[12])
    cy = sc * (m[1] * w - x * m[13])
    cz = sc * (m[2] * w - x * m[14])
    rx = sr * (m[4] * w - y * m[12])
    ry = sr * (m[5] * w - y * m[13])
    rz = sr * (m[6] * w - y * m[14])
    return (cx * t1x + cy * t1y + cz * t1z, cx * t2x + cy * t2y + cz * t2z,
            rx * t1x + ry * t1y + rz * t1z, rx * t2x + ry * t2y + rz * t2z)


@njit(cache=True, parallel=True)
def _footprint_kernel(m, width, height, points, normals, out):
    """Longer texel edge on each point's plane (metres); inf where the plane holds the ray."""
    for i in prange(points.shape[0]):
        t1x, t1y, t1z, t2x, t2y, t2z = _tangent_frame(normals[i, 0], normals[i, 1],
                                                      normals[i, 2])
        a, b, c, d = _image_jacobian(m, width, height, points[i, 0], points[i, 1],
                                     points[i, 2], t1x, t1y, t1z, t2x, t2y, t2z)
        det = a * d - b * c
        if not (det > 0.0 or det < 0.0):
            out[i] = np.inf
            continue
        # Columns of the inverse Jacobian: the texel's edges in tangent coordinates.
        e1 = math.sqrt(d * d + c * c) / abs(det)
        e2 = math.sqrt(b * b + a * a) / abs(det)
        v = max(e1, e2)
        out[i] = v if v == v else np.inf


@njit(cache=True, parallel=True)
def _aliasing_kernel(ml, wl, hl, mc, wc, hc, points, normals, out):
    """Screen pixels spanned by the longer edge of the texel at each point (inf if
    undefined)."""
    for i in prange(points.shape[0]):
        t1x, t1y, t1z, t2x, t2y, t2z = _tangent_frame(normals[i, 0], normals[i, 1],
                                                      normals[i, 2])
        a, b, c, d = _image_jacobian(ml, wl, hl, points[i, 0], points[i, 1], points[i, 2],
                                     t1x, t1y, t1z, t2x, t2y, t2z)
        det = a * d - b * c
        if not (det > 0.0 or det < 0.0):
            out[i] = np.inf
            continue
        # Inverse of the light Jacobian, then screen Jacobian @ inverse: texel edges on screen.
        ia, ib, ic, id_ = d / det, -b / det, -c / det, a / det
        sa, sb, sc, sd = _image_jacobian(mc, wc, hc, points[i, 0], points[i, 1], points[i, 2],
                                         t1x, t1y, t1z, t2x, t2y, t2z)
        k11 = sa * ia + sb * ic
        k12 = sa * ib + sb * id_
        k21 = sc * ia + sd * ic
        k22 = sc * ib + sd * id_
        v = max(math.sqrt(k11 * k11 + k21 * k21), math.sqrt(k12 * k12 + k22 * k22))
        out[i] = v if v == v else np.inf


def _points_normals(points_m, normals) -> tuple[np.ndarray, np.ndarray]:
    p = np.ascontiguousarray(np.asarray(points_m, dtype=np.float64).reshape(-1, 3))
    n = np.asarray(normals, dtype=np.float64)
    n = np.ascontiguousarray(np.broadcast_to(n.reshape(-1, 3) if n.ndim > 1 else n, p.shape))
    return p, n


def receiver_plane_gradient(view: LightView, points, normals, u0, v0, z0):
    """(dz/du, dz/dv) of each receiver's tangent plane in the light view: NDC depth change
    per texel along the map's columns and rows (Isidoro's receiver-plane depth gradient).

    ``points`` (N, 3) and their unit ``normals``; ``u0, v0, z0`` = :func:`project` of the
    points. A plane holding the light's rays (seen edge-on) gets 0.
    """
    # Two tangents of each receiver's plane, ~1 cm long (local linearisation of warped views).
    helper = np.where(np.abs(normals[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]])
    t1 = np.cross(normals, helper)
    t1 /= np.linalg.norm(t1, axis=1, keepdims=True)
    t2 = np.cross(normals, t1)
    step = 0.01
    u1, v1, z1 = project(view, points + step * t1)
    u2, v2, z2 = project(view, points + step * t2)
    a, b, c, d = u1 - u0, u2 - u0, v1 - v0, v2 - v0
    det = a * d - b * c
    with np.errstate(divide="ignore", invalid="ignore"):
        gu = ((z1 - z0) * d - (z2 - z0) * c) / det
        gv = ((z2 - z0) * a - (z1 - z0) * b) / det
    # A plane holding the light's rays (seen edge-on) has no gradient: fall back to the
    # own-polygon rule alone.
    bad = ~(np.isfinite(gu) & np.isfinite(gv))
    gu[bad] = 0.0
    gv[bad] = 0.0
    return gu, gv


def texel_footprint_m(view: LightView, points_m, normals) -> np.ndarray:
    """Size of one texel on the receiver surface, metres.

    The two edges of the texel at each point, mapped onto the plane through the point with the
    given normal (inverse Jacobian of texel coordinates on that plane); the longer edge is
    returned. With ``normals`` along the sun's rays this is the light-space texel size; on a
    surface inclined by θ to the rays the texel stretches by 1/cosθ. ``inf`` for a plane that
    contains the texel's ray.

    Parameters
    ----------
    view : LightView
    points_m : (N, 3) render-space points; normals : (N, 3) or (3,) plane normals.

    Returns
    -------
    (N,) float64 metres.
    """
    p, n = _points_normals(points_m, normals)
    out = np.empty(p.shape[0])
    if p.shape[0]:
        _footprint_kernel(np.ascontiguousarray(view.clip_from_world.reshape(16)),
                          float(view.width_px), float(view.height_px), p, n, out)
    return out


def aliasing_m(view: LightView, camera, surfaces, mask=None, points_m=None, normals=None
               ) -> dict[str, float]:
    """Aliasing measure m (Lloyd et al. 2008): screen extent of one shadow-map texel.

    At each visible pixel (``mask``, default: all valid pixels), the two edges of the texel
    that covers the pixel's surface point are mapped onto the surface and then onto the screen
    (Jacobians of texel and screen coordinates on the surface's tangent plane); m is the longer
    of the two, in pixels. m > 1: one texel covers several pixels (undersampling, blocky shadow
    edges); m < 1: several texels per pixel.

    ``points_m`` and ``normals`` (N, 3), when given, are those pixels' points and normals
    already gathered (row-major, as :func:`~cityshade.shadows.gather_pixels`); a normal turned
    to the seen side gives the same m, bit for bit (the tangent frame's first axis and both
    Jacobians' first columns change sign exactly, and their product does not).

    Returns
    -------
    dict
        ``max``, ``mean`` (over pixels with a finite m; 0 without any) and ``pixels``.
    """
    from cityshade.shadows import gather_pixels

    if points_m is None or normals is None:
        valid = np.asarray(surfaces.valid, bool) if mask is None else np.asarray(mask, bool)
        # The gather kernel: numpy's boolean gather of (H, W, 3) images is several times
        # slower.
        points_m = gather_pixels(surfaces.position_m, valid)
        normals = gather_pixels(surfaces.normal, valid)
    p, n = _points_normals(points_m, normals)
    if p.shape[0] == 0:
        return {"max": 0.0, "mean": 0.0, "pixels": 0}
    h, w = camera.shape
    edge_px = np.empty(p.shape[0])
    _aliasing_kernel(np.ascontiguousarray(view.clip_from_world.reshape(16)),
                     float(view.width_px), float(view.height_px),
                     np.ascontiguousarray(np.asarray(camera.clip_from_world(), np.float64)
                                          .reshape(16)), float(w), float(h), p, n, edge_px)
    finite = edge_px[np.isfinite(edge_px)]
    if finite.shape[0] == 0:
        return {"max": 0.0, "mean": 0.0, "pixels": 0}
    return {"max": float(finite.max()), "mean": float(finite.mean()),
            "pixels": int(finite.shape[0])}


# --- the depth pass ---------------------------------------------------------------------------

def render_depth_map(scene, view: LightView, t_days: float, *, casters_box=None,
                     culling: bool = True, tile_px: int = TILE_PX) -> DepthMap:
    """Rasterize the triangles present at ``t_days`` into the light view's depth map.

    Parameters
    ----------
    scene : Scene
        Render-space triangles (arrays may be read-only memory maps) and its kd-tree.
    view : LightView
        Any 4×4 projective light view.
    t_days : float
        City time, days since 1970-01-01 UTC; triangles with ``begin <= t_days < end`` cast.
    casters_box : (2, 3) array_like, optional
        Render-space box ``[[x0, y0, z0], [x1, y1, z1]]``: every caster meeting it is drawn,
        the kd-tree walk skips nodes outside it (so some casters outside it may be drawn too;
        without a kd-tree it has no effect).
    culling : bool
        Walk the kd-tree with time filtering and light-frustum culling
        (:func:`cityshade.raster.depthpass.render_depth`); False, a scene without kd-tree, or a view
        that holds the whole model draws the triangles present at ``t_days`` linearly. The
        map is the same either way.
    tile_px : int
        Tile side in texels (does not change the map).

    Returns
    -------
    DepthMap
    """
    if not isinstance(view, LightView):
        raise UsageError(f"expected a LightView, not {type(view).__name__}")
    reuse = _REUSE[-1] if _REUSE else None
    key = None
    if reuse is not None:
        key = (id(scene), float(t_days), view.clip_from_world.tobytes(), view.width_px,
               view.height_px, None if casters_box is None else
               np.asarray(casters_box, np.float64).tobytes(), bool(culling), int(tile_px))
        hit = reuse.maps.get(key)
        if hit is not None:
            reuse.reused_s += float(hit.stats["timings_s"]["total_s"])
            reuse.reused += 1
            return hit
    depth, prim, stats = render_depth(scene, view.clip_from_world, view.width_px,
                                      view.height_px, t_days, casters_box=casters_box,
                                      culling=culling, tile_px=tile_px)
    dmap = DepthMap(view=view, depth=depth, prim_id=prim, stats=stats)
    if reuse is not None:
        reuse.maps[key] = dmap      # shared: its users only read it
    return dmap


_REUSE: list["DepthMapReuse"] = []


class DepthMapReuse:
    """Inside ``with DepthMapReuse() as reuse:``, :func:`render_depth_map` draws each distinct
    request (scene, city time, view, options) once and hands the same :class:`DepthMap` (its
    users only read it) to every later request: what ``evaluate`` uses to run the techniques
    that share a map (``X``, ``X+smooth``, ``hybrid:X``, and every timed run of them) on one
    depth pass. ``reused_s`` adds up the depth-pass time of the maps handed out again, so a
    caller can still charge each run its full cost (:meth:`take_reused_s`). The maps stay
    until :meth:`clear`."""

    def __init__(self) -> None:
        self.maps: dict[tuple, DepthMap] = {}
        self.reused_s = 0.0
        self.reused = 0

    def __enter__(self) -> "DepthMapReuse":
        _REUSE.append(self)
        return self

    def __exit__(self, *exc) -> None:
        _REUSE.remove(self)

    def clear(self) -> None:
        """Drop the maps kept so far (their memory)."""
        self.maps.clear()

    def take_reused_s(self) -> float:
        """The depth-pass seconds of the maps reused since the last call (then reset)."""
        value, self.reused_s = self.reused_s, 0.0
        return value


# --- lookups ----------------------------------------------------------------------------------

def offset_receivers(view: LightView, points_m, normals, sun_direction,
                     settings: ShadowSettings, filter_radius_px: float = 0.0) -> np.ndarray:
    """Receivers moved by the constant and slope-scaled (normal-offset) bias.

    ``p' = p + bias_m s + min(slope_bias · t · sinθ · (1 + r), max_bias_m) n`` (module
    docstring; ``settings.bias``: ``constant_m``, ``slope``, ``max_m``), with ``t`` the light-space texel size at ``p`` (:func:`texel_footprint_m` on
    the plane across the rays) and ``r = filter_radius_px``.

    Parameters
    ----------
    points_m : (N, 3); normals : (N, 3) unit normals turned to the seen side (and facing the
        sun); sun_direction : (3,) toward the sun.

    Returns
    -------
    (N, 3) float64.
    """
    p = np.asarray(points_m, dtype=np.float64).reshape(-1, 3)
    n = np.asarray(normals, dtype=np.float64).reshape(-1, 3)
    s = _unit_sun(sun_direction)
    if p.shape[0] == 0:
        return p.copy()
    texel = texel_footprint_m(view, p, s)
    cos = np.clip(n @ s, -1.0, 1.0)
    sin = np.sqrt(1.0 - cos * cos)
    bias = settings.bias
    offset = np.minimum(bias.slope * texel * sin * (1.0 + float(filter_radius_px)), bias.max_m)
    offset = np.where(np.isfinite(offset), offset, bias.max_m)
    return p + bias.constant_m * s + offset[:, None] * n


@njit(cache=True, inline="always")
def clip_point(m, x, y, z, width, height):
    """(u_px, v_px, NDC depth) of a point in the view of clip matrix ``m`` (16,); NaN where
    ``w <= 0`` (:func:`project`'s arithmetic)."""
    cx = x * m[0] + y * m[1] + z * m[2] + m[3]
    cy = x * m[4] + y * m[5] + z * m[6] + m[7]
    cz = x * m[8] + y * m[9] + z * m[10] + m[11]
    cw = x * m[12] + y * m[13] + z * m[14] + m[15]
    inv = 1.0 / cw if cw > 0.0 else np.nan
    return (cx * inv + 1.0) * (0.5 * width), (1.0 - cy * inv) * (0.5 * height), cz * inv


@njit(cache=True, inline="always")
def plane_depth_gradient(m, width, height, px, py, pz, u, v, z, ax, ay, az, bx, by, bz):
    """(dz/du, dz/dv) in the view of clip matrix ``m`` (16,) of the plane through point p (at
    texel ``u, v``, depth ``z``) spanned by the unit tangents a and b, from two steps of 1 cm
    (:func:`receiver_plane_gradient`'s arithmetic); 0, 0 for a plane seen edge-on."""
    u1, v1, z1 = clip_point(m, px + 0.01 * ax, py + 0.01 * ay, pz + 0.01 * az, width, height)
    u2, v2, z2 = clip_point(m, px + 0.01 * bx, py + 0.01 * by, pz + 0.01 * bz, width, height)
    ja, jb, jc, jd = u1 - u, u2 - u, v1 - v, v2 - v
    det = ja * jd - jb * jc
    gu = ((z1 - z) * jd - (z2 - z) * jc) / det
    gv = ((z2 - z) * ja - (z1 - z) * jb) / det
    if not (np.isfinite(gu) and np.isfinite(gv)):
        return 0.0, 0.0
    return gu, gv


@njit(cache=True, inline="always")
def _light_texel_m(m, width, height, px, py, pz, t1x, t1y, t1z, t2x, t2y, t2z):
    """The longer edge (metres) of the texel at point p on the plane across the sun's rays
    (tangents t1, t2): what the slope bias of :func:`offset_receivers` scales with."""
    a, b, c, d = _image_jacobian(m, width, height, px, py, pz, t1x, t1y, t1z, t2x, t2y, t2z)
    det = a * d - b * c
    texel = np.inf
    if det > 0.0 or det < 0.0:
        texel = max(math.sqrt(d * d + c * c) / abs(det), math.sqrt(b * b + a * a) / abs(det))
        if texel != texel:
            texel = np.inf
    return texel


@njit(cache=True, inline="always")
def _receiver_uvz(m, width, height, projective, px, py, pz, nx, ny, nz, sx, sy, sz, texel,
                  constant_m, slope, max_m, radius):
    """One receiver of a lookup: the bias of :func:`offset_receivers` (``texel``: its
    :func:`_light_texel_m`), the projection of :func:`project` and, in a projective view, the
    receiver-plane depth bias of :func:`receiver_plane_gradient`. Returns ``(u_px, v_px,
    z)``."""
    cos = min(max(nx * sx + ny * sy + nz * sz, -1.0), 1.0)
    sin = math.sqrt(1.0 - cos * cos)
    offset = min(slope * texel * sin * (1.0 + radius), max_m)
    if not np.isfinite(offset):
        offset = max_m
    qx = px + constant_m * sx + offset * nx
    qy = py + constant_m * sy + offset * ny
    qz = pz + constant_m * sz + offset * nz
    u, v, z = clip_point(m, qx, qy, qz, width, height)
    if projective:
        # Two tangents of the receiver's plane, 1 cm long (receiver_plane_gradient).
        ax, ay, az, bx, by, bz = _tangent_frame(nx, ny, nz)
        gu, gv = plane_depth_gradient(m, width, height, qx, qy, qz, u, v, z,
                                      ax, ay, az, bx, by, bz)
        z = z - (abs(gu) + abs(gv)) * (0.5 + radius)
    return u, v, z


@njit(cache=True, parallel=True)
def _lookup_receivers(m, width, height, projective, points, normals, sun, constant_m, slope,
                      max_m, radius, u_out, v_out, z_out, depth, lit_out):
    """The receivers of a lookup in one pass (:func:`_receiver_uvz` per point, without the
    (N, 3) temporaries of the step-by-step twins): their (u, v, z) into ``u_out, v_out,
    z_out``, or, when ``lit_out`` is not empty, the plain shadow-map test against ``depth``
    into it instead: :func:`cityshade.shadows.filtering.pcf_lookup` with one tap (radius 0),
    the same tests, without writing and reading back (u, v, z) of every receiver (82 MB for
    a 2049² map)."""
    h, w = depth.shape
    hard = lit_out.shape[0] > 0
    sx, sy, sz = sun[0], sun[1], sun[2]
    # The light-space texel is measured on the plane across the rays (normal = sun). In an
    # affine view (w row 0 0 0 1) every term of its Jacobian is the same float at every finite
    # point (w = 1 and x·0 = 0 exactly), so it is computed once; a non-finite receiver gets
    # NaN coordinates either way.
    t1x, t1y, t1z, t2x, t2y, t2z = _tangent_frame(sx, sy, sz)
    affine_texel = _light_texel_m(m, width, height, 0.0, 0.0, 0.0, t1x, t1y, t1z, t2x, t2y,
                                  t2z)
    for i in prange(points.shape[0]):
        px, py, pz = points[i, 0], points[i, 1], points[i, 2]
        texel = affine_texel
        if projective:
            texel = _light_texel_m(m, width, height, px, py, pz, t1x, t1y, t1z, t2x, t2y, t2z)
        u, v, z = _receiver_uvz(m, width, height, projective, px, py, pz, normals[i, 0],
                                normals[i, 1], normals[i, 2], sx, sy, sz, texel, constant_m,
                                slope, max_m, radius)
        if not hard:
            u_out[i] = u
            v_out[i] = v
            z_out[i] = z
            continue
        lit = np.float32(1.0)
        # Non-finite or far outside the map: lit; outside the map or not behind the caster:
        # lit (the one-tap PCF's tests).
        if -1.0 <= u < w + 1.0 and -1.0 <= v < h + 1.0:
            c = int(math.floor(u))
            r = int(math.floor(v))
            if 0 <= r < h and 0 <= c < w and not z <= depth[r, c]:
                lit = np.float32(0.0)
        lit_out[i] = lit


#: The unused arguments of :func:`_lookup_receivers` in each of its two uses.
_NO_DEPTH = np.zeros((0, 0), np.float32)
_NO_VALUES = np.zeros(0)
_NO_LIT = np.zeros(0, np.float32)


def _lookup_args(view: LightView, points_m, normals, sun_direction,
                 settings: ShadowSettings) -> tuple:
    """The leading arguments of :func:`_lookup_receivers` (view, receivers as contiguous
    float64, unit sun, bias), for both of its uses."""
    bias = settings.bias
    return (np.ascontiguousarray(view.clip_from_world.reshape(16)), float(view.width_px),
            float(view.height_px), view.is_projective,
            np.ascontiguousarray(np.asarray(points_m, dtype=np.float64).reshape(-1, 3)),
            np.ascontiguousarray(np.asarray(normals, dtype=np.float64).reshape(-1, 3)),
            _unit_sun(sun_direction), float(bias.constant_m), float(bias.slope),
            float(bias.max_m))


def lookup_receivers(view: LightView, points_m, normals, sun_direction,
                     settings: ShadowSettings, filter_radius_px: int = 0, work=None
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(u_px, v_px, NDC depth) (N,) float64 of receivers offset by the bias and projected into
    the view, with the receiver-plane depth bias of projective views: what
    :func:`shadow_lookup` compares with the map. One kernel pass; :func:`offset_receivers`,
    :func:`project` and :func:`receiver_plane_gradient` are its step-by-step twins. ``work``
    (a :class:`cityshade.runtime.memory.Scratch`) holds the outputs instead of fresh arrays."""
    args = _lookup_args(view, points_m, normals, sun_direction, settings)
    count = args[4].shape[0]
    out = tuple(np.empty(count) if work is None else work.get(f"lookup.{k}", count)
                for k in "uvz")
    if count:
        _lookup_receivers(*args, float(filter_radius_px), *out, _NO_DEPTH, _NO_LIT)
    return out


def shadow_lookup(depth_map: DepthMap, points_m, normals, sun_direction,
                  settings: ShadowSettings, mode: str = "hard") -> np.ndarray:
    """Lit fraction (N,) float32 of receivers from one depth map.

    ``mode``: "hard" (one texel), "pcf" (``settings.pcf.kernel``² texels) or "vsm" (moments
    filtered with ``settings.vsm.blur_px``; Chebyshev bound, ``min_variance_m2``,
    ``bleed_reduction``). Receivers are offset first (:func:`offset_receivers`; PCF and VSM
    scale the slope term by their filter radius).
    """
    from cityshade.shadows import filtering as flt

    view = depth_map.view
    if mode == "hard":
        radius = 0
    elif mode == "pcf":
        radius = settings.pcf.kernel // 2
    elif mode == "vsm":
        radius = settings.vsm.blur_px
    else:
        raise UsageError(f"shadow lookup mode must be hard, pcf or vsm, not {mode!r}")
    # In a warped (projective) map a plane's NDC depth varies across a texel even when the
    # plane faces the light squarely (a flat roof under a high sun gets no slope bias): the
    # receiver plane's depth change over the texels the filter reads is subtracted
    # (receiver-plane depth bias, Isidoro 2006).
    # The temporaries (receivers, VSM moments) live in kept arrays: fresh ones of a 2049² map
    # view were faulted in anew every frame (kernel page zeroing: half a second and more per
    # frame on a loaded machine, depending on what ran before).
    if mode == "hard":
        args = _lookup_args(view, points_m, normals, sun_direction, settings)
        lit = np.empty(args[4].shape[0], np.float32)
        if len(lit):
            _lookup_receivers(*args, 0.0, _NO_VALUES, _NO_VALUES, _NO_VALUES, depth_map.depth,
                              lit)
        return lit
    work = _LOOKUP_SCRATCH.take()
    try:
        u, v, z = lookup_receivers(view, points_m, normals, sun_direction, settings, radius,
                                   work)
        if mode == "vsm":
            vsm = settings.vsm
            weights = (flt.gaussian_weights(vsm.blur_px / 2.0, vsm.blur_px)
                       if vsm.filter == "gaussian" else flt.box_weights(vsm.blur_px))
            scale = metres_per_ndc(view)
            moments = flt.vsm_moments(depth_map.depth, scale, weights, work)
            np.add(z, 1.0, out=z)
            np.multiply(z, scale, out=z)
            return flt.vsm_lookup(moments, u, v, z, vsm.min_variance_m2, vsm.bleed_reduction)
        return flt.pcf_lookup(depth_map.depth, u, v, z, 2 * radius + 1)
    finally:
        work.give_back()


#: The lookups' kept temporaries (:func:`shadow_lookup`).
_LOOKUP_SCRATCH = Scratch()


def map_diagnostics(views, ctx: ShadowContext, points_m, normals, faces) -> dict[str, Any]:
    """The diagnostics every map technique reports: ``map_px`` [(W, H)], ``texel_m`` (median
    texel footprint on the receivers, metres; with several views, the finest view at each
    receiver), ``texel_light_m`` (median light-space texel size) and ``aliasing_m``
    {max, mean} (of the first view when there are several and no per-pixel assignment)."""
    views = list(views)
    out: dict[str, Any] = {"map_px": [(v.width_px, v.height_px) for v in views]}
    p = np.asarray(points_m, np.float64)
    if p.shape[0] == 0:
        out.update({"texel_m": 0.0, "texel_light_m": 0.0,
                    "aliasing_m": {"max": 0.0, "mean": 0.0, "pixels": 0}})
        return out
    s = _unit_sun(ctx.sun.direction)
    surf = np.min([texel_footprint_m(v, p, normals) for v in views], axis=0)
    light = np.min([texel_footprint_m(v, p, s) for v in views], axis=0)
    out["texel_m"] = float(np.median(surf[np.isfinite(surf)])) if np.isfinite(surf).any() else 0.0
    out["texel_light_m"] = float(np.median(light))
    out["aliasing_m"] = aliasing_m(views[0], ctx.camera, ctx.surfaces, mask=faces, points_m=p,
                                   normals=normals)
    return out
