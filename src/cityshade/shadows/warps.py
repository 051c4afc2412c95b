"""Perspective warps of the shadow map against perspective aliasing: ``psm``, ``lispsm``, ``xpsm``
(the matrices; :class:`cityshade.shadows.planners.Warped` plans the maps with them).

Every warp here is one (4, 4) float64 projective matrix ``clip_from_world`` (render space →
OpenGL-style light clip space, x, y, z in [-w, w]) handed to the shadow-map core
(:mod:`cityshade.shadows.shadowmap`), which rasterizes the casters with it and looks the
receivers up through it. The matrices are built so that, on every point that matters:

* ``w > 0`` (the focus points lie in front of every projection centre);
* the light's rays (render-space lines along the sun direction ``d``) map to lines of constant
  NDC ``(x, y)`` — one shadow-map texel per light ray — because ``M @ (d, 0)`` has zero x, y
  and w;
* NDC depth increases *away* from the sun along each ray (``(M @ (-d, 0))_z > 0``), so the
  core's "smaller depth is closer to the light" test is right whatever the warp did to the
  light (this is where PSM's inverted light is handled, see :func:`psm_matrix`);
* the visible receivers fill NDC x, y in [-1, 1] (plus a small margin) and the receivers and
  the casters that can shade them fill NDC z in [-1, 1].

The focus region
----------------
``receivers_m`` (N, 3) are the visible surface points that face the sun; ``casters_m`` (N, 3)
are the same points pushed toward the sun to where they leave the scene's bounding box
(:func:`extrude_to_box`). Any triangle that can shadow a receiver meets the segment between
the two, so fitting depth (and the warps' projection centres) to both keeps every relevant
caster inside the light frustum; fitting x, y to the receivers alone is enough because a
caster and the receiver it shades share their NDC x, y.

Warps
-----
``lispsm``
    Wimmer, Scherzer, Purgathofer, "Light Space Perspective Shadow Maps", EGSR 2004. In light
    space (z along the light, y = view direction projected on the shadow-map plane) a
    perspective frustum looking along y, whose centre sits ``n`` before the near face of the
    focus body; ``n_opt = (z_n + sqrt(z_n z_f)) / sin(gamma)`` with ``z_f = z_n + d sin(gamma)``
    (``d`` the depth of the body along y, ``gamma`` the angle between view and light
    direction). ``n`` grows without bound as ``gamma → 0`` and the warp fades smoothly into
    the uniform map; past ``max_n_rel`` body depths it *is* the uniform map.
``xpsm``
    Extended perspective shadow maps (the thesis slides): step 1, the optimal warping effect,
    a projective map acting only in the shadow-map plane, ``w = 1 + k (y - y_near)`` with the
    warp direction y = the view direction projected on the shadow-map plane and the strength
    ``k = 1 / n_opt`` (the same optimal parameter as LiSPSM, capped at ``xpsm_max_warp``);
    step 2, an affine map that does not change that warping: the rotation, scale and shift
    that put the warped receivers' minimum-area bounding rectangle onto [-1, 1]².
``psm``
    Stamminger and Drettakis, "Perspective Shadow Maps", SIGGRAPH 2002, with the fixes of
    Kozlov, "Perspective Shadow Maps: Care and Feeding", GPU Gems 2004: the map is made in the
    post-perspective space of a *virtual* camera, slid back along its axis until every focus
    point (casters behind the eye included) lies at least ``psm_min_near_far`` of the far
    distance in front of it. There the sun becomes a point light on the plane at infinity
    (or stays directional when it is parallel to the view plane). When the sun is behind
    the camera the light is "inverted": rays converge on that point instead of leaving it, and
    the depth order along them is reversed — the z row of the light projection is negated
    (the inverted projection of Kozlov), which the final sign rule above does.

Orthographic (map) cameras have no perspective aliasing: every warp is the uniform map there.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from cityshade.config import WarpSettings
from cityshade.errors import UsageError

#: Names of the warps (``none`` is the uniform orthographic map).
WARPS = ("none", "psm", "lispsm", "xpsm")


# --- small helpers ------------------------------------------------------------------------------

def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v)


def apply_h(matrix, points_m) -> np.ndarray:
    """(N, 4) homogeneous clip coordinates of render-space points (N, 3) under a (4, 4) matrix."""
    p = np.asarray(points_m, dtype=np.float64)
    m = np.asarray(matrix, dtype=np.float64)
    return p @ m[:, :3].T + m[:, 3]


def ndc(matrix, points_m) -> np.ndarray:
    """(N, 3) normalised device coordinates (after the divide by w)."""
    h = apply_h(matrix, points_m)
    return h[:, :3] / h[:, 3:4]


def extrude_to_box(points_m, sun_direction, box_m, out=None) -> np.ndarray:
    """Points pushed toward the sun to where their ray leaves the box (into ``out``, an
    (N, 3) float64 array, when given).

    Parameters
    ----------
    points_m : (N, 3) float64
        Render-space points inside (or on) the box.
    sun_direction : (3,) float64
        Unit vector toward the sun, render space.
    box_m : (2, 3) float64
        Axis-aligned box (min row, max row) holding every triangle.

    Returns
    -------
    (N, 3) float64
        ``p + t d`` with ``t >= 0`` the exit distance (0 for a point already outside).
    """
    p = np.ascontiguousarray(points_m, dtype=np.float64).reshape(-1, 3)
    out = np.empty_like(p) if out is None else out
    _extrude_kernel(p, np.ascontiguousarray(sun_direction, np.float64).reshape(3),
                    np.ascontiguousarray(box_m, np.float64).reshape(2, 3), out)
    return out


@njit(cache=True, parallel=True)
def _extrude_kernel(p, d, box, out):
    """:func:`extrude_to_box` per point (one pass, no (N,) temporaries)."""
    for i in prange(p.shape[0]):
        t = np.inf
        for k in range(3):
            # Distance to the slab face ahead of the ray on axis k (none when it is parallel).
            if d[k] > 0.0:
                t = min(t, (box[1, k] - p[i, k]) / d[k])
            elif d[k] < 0.0:
                t = min(t, (box[0, k] - p[i, k]) / d[k])
        t = max(t, 0.0) if np.isfinite(t) else 0.0
        for k in range(3):
            out[i, k] = p[i, k] + t * d[k]


#: Chunks of :func:`_ndc_bounds`' parallel pass over the focus points.
_CHUNKS = 64


@njit(cache=True, parallel=True)
def _ndc_bounds(m, points, lo, hi):
    """Fold the NDC x, y, z (after the divide by w) of ``points`` under the (4, 4) matrix ``m``
    into ``lo``/``hi`` (3,); returns the smallest w (:func:`ndc`'s arithmetic, one pass over
    chunks in parallel: minima and maxima do not depend on the order)."""
    n = points.shape[0]
    per = max(1, -(-n // _CHUNKS))
    chunks = -(-n // per)
    part = np.empty((chunks, 7))
    for ch in prange(chunks):
        wmin = np.inf
        c_lo = np.full(3, np.inf)
        c_hi = np.full(3, -np.inf)
        for i in range(ch * per, min(n, (ch + 1) * per)):
            x, y, z = points[i, 0], points[i, 1], points[i, 2]
            w = x * m[3, 0] + y * m[3, 1] + z * m[3, 2] + m[3, 3]
            wmin = min(wmin, w)
            for k in range(3):
                c = x * m[k, 0] + y * m[k, 1] + z * m[k, 2] + m[k, 3]
                if w != 1.0:  # c / 1.0 is c exactly: an orthographic map divides nothing
                    c /= w
                c_lo[k] = min(c_lo[k], c)
                c_hi[k] = max(c_hi[k], c)
        part[ch, 0] = wmin
        part[ch, 1:4] = c_lo
        part[ch, 4:7] = c_hi
    wmin = np.inf
    for ch in range(chunks):
        wmin = min(wmin, part[ch, 0])
        for k in range(3):
            lo[k] = min(lo[k], part[ch, 1 + k])
            hi[k] = max(hi[k], part[ch, 4 + k])
    return wmin


@njit(cache=True)
def _mean_point(points):
    """(3,) mean of ``points`` (N, 3): each coordinate summed in row order, then divided by N,
    which is numpy's ``mean(axis=0)`` of a C-ordered (N, 3) array bit for bit (its reduction
    over the outer axis adds row after row) at a tenth of its time (54 against 6 ms for the
    3.4 M receivers of the 1M city's 2049² map)."""
    s0 = 0.0
    s1 = 0.0
    s2 = 0.0
    for i in range(points.shape[0]):
        s0 += points[i, 0]
        s1 += points[i, 1]
        s2 += points[i, 2]
    n = points.shape[0]
    return np.array([s0 / n, s1 / n, s2 / n])


@njit(cache=True, parallel=True)
def _all_finite(points):
    """Whether every coordinate of ``points`` (N, 3) is finite (no (N, 3) bool temporary)."""
    bad = 0
    for i in prange(points.shape[0]):
        for k in range(3):
            if not np.isfinite(points[i, k]):
                bad += 1
    return bad == 0


@njit(cache=True, inline="always")
def _ndc_point(m, points, i):
    x, y, z = points[i, 0], points[i, 1], points[i, 2]
    w = x * m[3, 0] + y * m[3, 1] + z * m[3, 2] + m[3, 3]
    return ((x * m[0, 0] + y * m[0, 1] + z * m[0, 2] + m[0, 3]) / w,
            (x * m[1, 0] + y * m[1, 1] + z * m[1, 2] + m[1, 3]) / w,
            (x * m[2, 0] + y * m[2, 1] + z * m[2, 2] + m[2, 3]) / w)


@njit(cache=True)
def _ndc_sum(m, points, total, centre, unit):
    """Add up the points' NDC positions into ``total`` (3,); with ``unit``, their unit
    directions from ``centre`` instead (PSM's light axis)."""
    for i in range(points.shape[0]):
        qx, qy, qz = _ndc_point(m, points, i)
        if unit:
            qx, qy, qz = qx - centre[0], qy - centre[1], qz - centre[2]
            length = math.sqrt(qx * qx + qy * qy + qz * qz)
            qx, qy, qz = qx / length, qy / length, qz / length
        total[0] += qx
        total[1] += qy
        total[2] += qz


@njit(cache=True)
def _min_cos(m, points, centre, axis):
    """Smallest cosine between ``axis`` and the points' NDC directions from ``centre``."""
    lowest = np.inf
    for i in range(points.shape[0]):
        qx, qy, qz = _ndc_point(m, points, i)
        qx, qy, qz = qx - centre[0], qy - centre[1], qz - centre[2]
        length = math.sqrt(qx * qx + qy * qy + qz * qz)
        lowest = min(lowest, (qx * axis[0] + qy * axis[1] + qz * axis[2]) / length)
    return lowest


def ndc_bounds(matrix, points_m) -> tuple[float, np.ndarray, np.ndarray]:
    """(smallest w, lo (3,), hi (3,)) of the points' homogeneous w and NDC coordinates under a
    (4, 4) matrix: what a fit needs of :func:`ndc`, without the (N, 4) array."""
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    wmin = _ndc_bounds(np.ascontiguousarray(matrix, np.float64),
                       np.ascontiguousarray(points_m, np.float64).reshape(-1, 3), lo, hi)
    return float(wmin), lo, hi


def light_basis(sun_direction, forward=None) -> np.ndarray:
    """(3, 3) rows ``x_l, y_l, z_l`` of light space: ``z_l = -d`` (the way light travels),
    ``y_l`` the view direction ``forward`` projected on the shadow-map plane (any
    perpendicular when there is none), ``x_l = y_l × z_l``."""
    z = -_unit(sun_direction)
    y = None
    if forward is not None:
        f = np.asarray(forward, dtype=np.float64)
        proj = f - (f @ z) * z
        if np.linalg.norm(proj) > 1e-9:
            y = _unit(proj)
    if y is None:
        helper = np.array([0.0, 1.0, 0.0]) if abs(z[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
        y = _unit(helper - (helper @ z) * z)
    x = np.cross(y, z)
    return np.stack([x, y, z])


def _affine4(rot3, origin) -> np.ndarray:
    """(4, 4) matrix of ``p → rot3 (p - origin)``."""
    m = np.eye(4)
    m[:3, :3] = rot3
    m[:3, 3] = -np.asarray(rot3) @ np.asarray(origin, dtype=np.float64)
    return m


def _fit(k_matrix, receivers_m, casters_m, margin_rel) -> np.ndarray:
    """Compose an axis-aligned scale and shift after ``k_matrix`` so that the receivers' NDC x, y
    and the receivers' and casters' NDC z fill [-1, 1] (x, y with a margin)."""
    w_r, lo, hi = ndc_bounds(k_matrix, receivers_m)
    w_c, lo_c, hi_c = ndc_bounds(k_matrix, casters_m)
    if not min(w_r, w_c) > 0.0:
        raise UsageError("warp geometry: a focus point lies behind a projection centre")
    lo[2] = min(lo[2], lo_c[2])
    hi[2] = max(hi[2], hi_c[2])
    span = hi - lo
    # A flat focus (one pixel, one wall seen edge-on) still needs a non-zero extent.
    span = np.maximum(span, 1e-9 * (np.abs(lo) + np.abs(hi)) + 1e-12)
    lo[:2] -= margin_rel * span[:2]
    span[:2] *= 1.0 + 2.0 * margin_rel
    # z gets a relative margin too, so float32 depths at the extremes stay inside [-1, 1].
    lo[2] -= 1e-6 * span[2]
    span[2] *= 1.0 + 2e-6
    o = np.eye(4)
    o[[0, 1, 2], [0, 1, 2]] = 2.0 / span
    o[:3, 3] = -1.0 - 2.0 * lo / span
    return o @ k_matrix


def _depth_away_from_sun(matrix, sun_direction) -> np.ndarray:
    """Negate the z row when NDC depth would decrease away from the sun (inverted lights)."""
    m = np.array(matrix, dtype=np.float64)
    away = m @ np.append(-np.asarray(sun_direction, dtype=np.float64), 0.0)
    if away[2] < 0.0:
        m[2, :] = -m[2, :]
    return m


def _check_inputs(sun_direction, receivers_m, casters_m):
    d = np.asarray(sun_direction, dtype=np.float64).reshape(-1)
    if d.shape != (3,) or not np.isfinite(d).all() or np.linalg.norm(d) == 0.0:
        raise UsageError("sun direction must be 3 finite numbers, not all zero")
    r = np.ascontiguousarray(receivers_m, dtype=np.float64).reshape(-1, 3)
    c = np.ascontiguousarray(casters_m, dtype=np.float64).reshape(-1, 3)
    if len(r) == 0:
        raise UsageError("a shadow map needs at least one receiver point")
    if not (_all_finite(r) and _all_finite(c)):
        raise UsageError("receiver and caster points must be finite")
    if len(c) == 0:
        c = r
    return _unit(d), r, c


# --- the uniform map ------------------------------------------------------------------------------

def uniform_matrix(sun_direction, receivers_m, casters_m, settings: WarpSettings | None = None,
                   forward=None) -> tuple[np.ndarray, dict]:
    """Orthographic light projection fitted to the focus (the map every warp degenerates to).

    Parameters
    ----------
    sun_direction : (3,) unit vector toward the sun, render space.
    receivers_m, casters_m : (N, 3), (M, 3) float64 render space (see the module docstring).
    forward : (3,), optional
        View direction: orients the map's y axis along its projection (as LiSPSM does), which
        makes the LiSPSM → uniform limit continuous.

    Returns
    -------
    clip_from_world : (4, 4) float64
    info : dict
        ``warp`` = "none".
    """
    d, r, c = _check_inputs(sun_direction, receivers_m, casters_m)
    return _uniform(d, r, c, settings or WarpSettings(), forward)


def _uniform(d, r, c, s: WarpSettings, forward=None) -> tuple[np.ndarray, dict]:
    """:func:`uniform_matrix` of inputs :func:`_check_inputs` has made (the warps' fallback)."""
    k = _affine4(light_basis(d, forward), _mean_point(r))
    return _fit(k, r, c, s.fit_margin_rel), {"warp": "none"}


# --- LiSPSM -----------------------------------------------------------------------------------

def lispsm_n_opt(z_near_m: float, z_far_m: float, sin_gamma: float) -> float:
    """Optimal distance of the LiSPSM projection centre from the near face of the body
    (Wimmer et al. 2004, eq. for ``n_opt``): ``(z_n + sqrt(z_n z_f)) / sin(gamma)``; +inf
    when ``sin_gamma`` is 0 (view along the light: the uniform map is optimal)."""
    if not (z_near_m > 0.0 and z_far_m >= z_near_m and 0.0 <= sin_gamma <= 1.0 + 1e-12):
        raise UsageError(f"LiSPSM needs 0 < z_n <= z_f and 0 <= sin(gamma) <= 1, not z_n "
                         f"{z_near_m}, z_f {z_far_m}, sin {sin_gamma}")
    if sin_gamma == 0.0:
        return math.inf
    return (z_near_m + math.sqrt(z_near_m * z_far_m)) / sin_gamma


def _warp_frame(camera, d):
    """Eye, forward, sin(gamma) and the light basis of a perspective camera."""
    _, _, fwd = camera.frame()
    eye = np.asarray(camera.eye_m, dtype=np.float64)
    cos_gamma = float(np.clip(fwd @ d, -1.0, 1.0))
    sin_gamma = math.sqrt(max(0.0, 1.0 - cos_gamma * cos_gamma))
    return eye, fwd, sin_gamma, light_basis(d, fwd)


def _body_params(camera, d, r, c):
    """LiSPSM/XPSM parameters of the body: light-space coordinates, n_opt and friends."""
    eye, fwd, sin_gamma, basis = _warp_frame(camera, d)
    # Light-space y (rows 0) and view depth (row 1) of the receivers, in one pass.
    _, lo, hi = ndc_bounds(_affine4(np.stack([basis[1], fwd, fwd]), eye), r)
    y0, y1 = float(lo[0]), float(hi[0])
    depth_y_m = max(y1 - y0, 0.0)
    # z_n: the nearest receiver's view depth (a tight near plane, not the camera's tiny one).
    z_n = max(float(lo[1]), camera.near_m, 1e-6)
    z_f = z_n + depth_y_m * sin_gamma
    n = lispsm_n_opt(z_n, z_f, min(sin_gamma, 1.0))
    return eye, basis, sin_gamma, y0, depth_y_m, z_n, z_f, n


def _perspective_focus(camera, sun_direction, receivers_m, casters_m, settings):
    """Checked inputs of a warp; for an orthographic camera also the uniform map it becomes
    (no perspective aliasing to fight)."""
    s = settings or WarpSettings()
    d, r, c = _check_inputs(sun_direction, receivers_m, casters_m)
    uniform = None
    if camera.kind != "perspective":
        m, info = _uniform(d, r, c, s)
        uniform = m, dict(info, note="orthographic camera: no perspective aliasing, uniform map")
    return s, d, r, c, uniform


def lispsm_matrix(camera, sun_direction, receivers_m, casters_m,
                  settings: WarpSettings | None = None) -> tuple[np.ndarray, dict]:
    """Light-space perspective shadow map (Wimmer, Scherzer, Purgathofer 2004).

    Parameters
    ----------
    camera : cityshade.raster.camera.Camera
    sun_direction : (3,) unit vector toward the sun.
    receivers_m, casters_m : (N, 3), (M, 3) float64 focus points (module docstring).

    Returns
    -------
    clip_from_world : (4, 4) float64
    info : dict
        ``warp``, ``n_m`` (centre distance before the body, inf when uniform), ``gamma_deg``,
        ``z_near_m``, ``z_far_m``, ``body_depth_m``.
    """
    s, d, r, c, uniform = _perspective_focus(camera, sun_direction, receivers_m, casters_m,
                                             settings)
    if uniform is not None:
        return uniform
    eye, basis, sin_gamma, y0, depth_y_m, z_n, z_f, n = _body_params(camera, d, r, c)
    info = {"warp": "lispsm", "gamma_deg": math.degrees(math.asin(min(sin_gamma, 1.0))),
            "z_near_m": z_n, "z_far_m": z_f, "body_depth_m": depth_y_m, "n_m": n}
    if not math.isfinite(n) or n > s.lispsm_max_n_rel * max(depth_y_m, 1e-9):
        m, _ = _uniform(d, r, c, s, forward=camera.frame()[2])
        return m, dict(info, warp="none", n_m=math.inf)
    f = n + depth_y_m
    # Light space with the projection centre at the origin: x, y (> 0, along the warp), z.
    centre_l = np.array([0.0, y0 - n, 0.0])
    view = _affine4(basis, eye + basis.T @ centre_l)
    # Perspective along +y: w = y; y maps [n, f] to [-1, 1]; x and z are divided by y.
    proj = np.zeros((4, 4))
    proj[0, 0] = 1.0
    proj[1, 1] = (f + n) / (f - n) if f > n else 1.0
    proj[1, 3] = -2.0 * f * n / (f - n) if f > n else 0.0
    proj[2, 2] = 1.0
    proj[3, 1] = 1.0
    m = _fit(proj @ view, r, c, s.fit_margin_rel)
    return _depth_away_from_sun(m, d), info


# --- XPSM -------------------------------------------------------------------------------------

@njit(cache=True)
def _hull_2d(xy):
    """Convex hull (counter-clockwise, no repeated end) of points sorted by (x, y): Andrew's
    monotone chain."""
    n = xy.shape[0]
    hull = np.empty((2 * n + 1, 2))
    k = 0
    for i in range(n):
        while k >= 2 and ((hull[k - 1, 0] - hull[k - 2, 0]) * (xy[i, 1] - hull[k - 2, 1])
                          - (hull[k - 1, 1] - hull[k - 2, 1]) * (xy[i, 0] - hull[k - 2, 0])) <= 0.0:
            k -= 1
        hull[k] = xy[i]
        k += 1
    lower = k + 1
    for i in range(n - 2, -1, -1):
        while k >= lower and ((hull[k - 1, 0] - hull[k - 2, 0]) * (xy[i, 1] - hull[k - 2, 1])
                              - (hull[k - 1, 1] - hull[k - 2, 1]) * (xy[i, 0] - hull[k - 2, 0])) <= 0.0:
            k -= 1
        hull[k] = xy[i]
        k += 1
    return hull[:max(k - 1, 1)].copy()


#: The 8 directions of the Akl–Toussaint octagon: the axes and the diagonals.
_OCTAGON_DIRS = np.array([[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1]],
                         dtype=np.float64)


@njit(cache=True)
def _extreme_points(p, dirs):
    """(8,) index of the first point of ``p`` (N, 2) farthest along each direction (numpy's
    ``argmax(p @ dirs.T, axis=0)``, in one pass without the (N, 8) products)."""
    best = np.full(dirs.shape[0], -np.inf)
    at = np.zeros(dirs.shape[0], np.int64)
    for i in range(p.shape[0]):
        for k in range(dirs.shape[0]):
            v = p[i, 0] * dirs[k, 0] + p[i, 1] * dirs[k, 1]
            if v > best[k]:
                best[k] = v
                at[k] = i
    return at


@njit(cache=True)
def _outside_polygon(p, poly):
    """The points of ``p`` (N, 2) not strictly inside the convex polygon ``poly`` (counter-
    clockwise), in their order."""
    out = np.empty_like(p)
    m = 0
    k = poly.shape[0]
    for i in range(p.shape[0]):
        inside = True
        for j in range(k):
            a0, a1 = poly[j, 0], poly[j, 1]
            b0, b1 = poly[(j + 1) % k, 0], poly[(j + 1) % k, 1]
            if not (b0 - a0) * (p[i, 1] - a1) - (b1 - a1) * (p[i, 0] - a0) > 0.0:
                inside = False
                break
        if not inside:
            out[m] = p[i]
            m += 1
    return out[:m].copy()


def convex_hull_2d(points_xy) -> np.ndarray:
    """(H, 2) convex hull of finite 2-D points, counter-clockwise.

    Points strictly inside the octagon of the 8 extreme points in the axis and diagonal
    directions cannot be on the hull (Akl–Toussaint); they are dropped before the sort, which
    leaves few of a dense pixel cloud (893 of the 403,579 receivers of the 1M city's overview).
    Two passes over the points, no per-point temporaries: the fit runs on every frame.
    """
    p = np.ascontiguousarray(points_xy, dtype=np.float64).reshape(-1, 2)
    if len(p) > 64:
        ext = p[_extreme_points(p, _OCTAGON_DIRS)]
        _, idx = np.unique(np.round(ext, 15), axis=0, return_index=True)
        poly = ext[np.sort(idx)]
        if len(poly) >= 3:
            p = _outside_polygon(p, poly)
    p = np.unique(p, axis=0)          # sorted by (x, y), duplicates removed
    if len(p) < 3:
        return p
    return _hull_2d(p)


def min_area_rectangle(points_xy) -> tuple[float, float]:
    """Angle (radians) and area of the minimum-area bounding rectangle of 2-D points
    (rotating calipers: one side lies on a hull edge, Freeman and Shapira 1975). The angle
    rotates the rectangle's sides onto the axes: ``(x, y) → (c x + s y, -s x + c y)``."""
    hull = convex_hull_2d(points_xy)
    if len(hull) < 3:
        return 0.0, 0.0
    edges = np.roll(hull, -1, axis=0) - hull
    theta = np.arctan2(edges[:, 1], edges[:, 0])
    cos, sin = np.cos(theta), np.sin(theta)
    u = hull[:, 0][None, :] * cos[:, None] + hull[:, 1][None, :] * sin[:, None]
    v = -hull[:, 0][None, :] * sin[:, None] + hull[:, 1][None, :] * cos[:, None]
    area = (u.max(axis=1) - u.min(axis=1)) * (v.max(axis=1) - v.min(axis=1))
    best = int(np.argmin(area))
    return float(theta[best]), float(area[best])


def xpsm_matrix(camera, sun_direction, receivers_m, casters_m,
                settings: WarpSettings | None = None) -> tuple[np.ndarray, dict]:
    """Extended perspective shadow map: the optimal warp in the shadow-map plane, then the
    affine fit that does not change it (module docstring).

    Returns
    -------
    clip_from_world : (4, 4) float64
    info : dict
        ``warp``, ``warp_ratio`` (w at the far / near end of the body), ``k_per_m``,
        ``rotation_deg`` of the affine step, ``gamma_deg``.
    """
    s, d, r, c, uniform = _perspective_focus(camera, sun_direction, receivers_m, casters_m,
                                             settings)
    if uniform is not None:
        return uniform
    eye, basis, sin_gamma, y0, depth_y_m, z_n, z_f, n = _body_params(camera, d, r, c)
    # Step 1: strength of the warp w = 1 + k (y - y0) along the projected view direction.
    ratio = 1.0 + depth_y_m / n if math.isfinite(n) and n > 0.0 else 1.0
    ratio = min(ratio, s.xpsm_max_warp)
    k = (ratio - 1.0) / depth_y_m if depth_y_m > 0.0 else 0.0
    view = _affine4(basis, eye)
    warp = np.eye(4)
    warp[3, 1] = k
    warp[3, 3] = 1.0 - k * y0
    kw = warp @ view
    # Step 2: rotate the warped receivers' minimum-area rectangle onto the axes, then fit.
    h = apply_h(kw, r)
    theta, _ = min_area_rectangle(h[:, :2] / h[:, 3:4])
    rot = np.eye(4)
    rot[0, 0], rot[0, 1] = math.cos(theta), math.sin(theta)
    rot[1, 0], rot[1, 1] = -math.sin(theta), math.cos(theta)
    m = _fit(rot @ kw, r, c, s.fit_margin_rel)
    info = {"warp": "xpsm" if k > 0.0 else "none", "warp_ratio": ratio, "k_per_m": k,
            "rotation_deg": math.degrees(theta),
            "gamma_deg": math.degrees(math.asin(min(sin_gamma, 1.0)))}
    return _depth_away_from_sun(m, d), info


# --- PSM --------------------------------------------------------------------------------------

def _perspective(eye, right, up, fwd, vfov_deg, aspect, near_m, far_m) -> np.ndarray:
    """OpenGL perspective clip_from_world of a camera frame."""
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = right, up, -fwd
    view[:3, 3] = -view[:3, :3] @ eye
    cot = 1.0 / math.tan(math.radians(vfov_deg) / 2.0)
    proj = np.zeros((4, 4))
    proj[0, 0] = cot / aspect
    proj[1, 1] = cot
    proj[2, 2] = (far_m + near_m) / (near_m - far_m)
    proj[2, 3] = 2.0 * far_m * near_m / (near_m - far_m)
    proj[3, 2] = -1.0
    return proj @ view


def psm_matrix(camera, sun_direction, receivers_m, casters_m,
               settings: WarpSettings | None = None) -> tuple[np.ndarray, dict]:
    """Perspective shadow map in the post-perspective space of a slid-back virtual camera
    (Stamminger and Drettakis 2002; Kozlov 2004).

    Returns
    -------
    clip_from_world : (4, 4) float64
    info : dict
        ``warp``; ``light`` = "point" (sun in front of the camera), "inverted" (behind) or
        "directional" (parallel to the view plane); ``slide_back_m``; virtual ``near_m``,
        ``far_m``.
    """
    s = settings or WarpSettings()
    d, r, c = _check_inputs(sun_direction, receivers_m, casters_m)
    if camera.kind != "perspective":
        m, info = _uniform(d, r, c, s)
        return m, dict(info, note="orthographic camera: no perspective aliasing, uniform map")
    right, up, fwd = camera.frame()
    eye = np.asarray(camera.eye_m, dtype=np.float64)
    # View depth of every focus point (receivers and casters), one pass each.
    along = _affine4(np.stack([fwd, fwd, fwd]), eye)
    _, lo_r, hi_r = ndc_bounds(along, r)
    _, lo_c, hi_c = ndc_bounds(along, c)
    dmin, dmax = float(min(lo_r[0], lo_c[0])), float(max(hi_r[0], hi_c[0]))
    # Slide the virtual camera back until every focus point is in front of a near plane of at
    # least psm_min_near_far times the far distance (casters behind the eye included).
    rho = s.psm_min_near_far
    dmax = max(dmax, dmin + 1e-6 * (abs(dmin) + 1.0))
    slide = max(0.0, (rho * dmax - dmin) / (1.0 - rho))
    near_v, far_v = dmin + slide, dmax + slide
    eye_v = eye - slide * fwd
    # Near and far sit exactly on focus points: widen by a hair so none is on a clip plane.
    cam_v = _perspective(eye_v, right, up, fwd, camera.vfov_deg,
                         camera.width_px / camera.height_px, near_v * (1.0 - 1e-6),
                         far_v * (1.0 + 1e-6))
    light_pp = cam_v @ np.append(d, 0.0)          # the sun in post-perspective space
    info = {"warp": "psm", "slide_back_m": slide, "near_m": near_v, "far_m": far_v}
    length = float(np.linalg.norm(light_pp[:3]))
    n_focus = r.shape[0] + c.shape[0]
    if abs(light_pp[3]) <= s.psm_directional_eps * length:
        # Directional in post-perspective space too: orthographic along -L (toward the sun is +L).
        basis = light_basis(light_pp[:3])
        total = np.zeros(3)
        for pts in (r, c):
            _ndc_sum(cam_v, pts, total, np.zeros(3), False)
        k = _affine4(basis, total / n_focus) @ cam_v
        info["light"] = "directional"
    else:
        centre = light_pp[:3] / light_pp[3]
        info["light"] = "point" if light_pp[3] > 0.0 else "inverted"
        # Axis of the light's frustum: the mean direction toward the focus; every focus point
        # lies beyond the plane z = (f + n) / (f - n) of the sun's image, so -z is a safe axis.
        total = np.zeros(3)
        for pts in (r, c):
            _ndc_sum(cam_v, pts, total, centre, True)
        axis = _unit(total)
        if not min(_min_cos(cam_v, r, centre, axis), _min_cos(cam_v, c, centre, axis)) > 1e-3:
            axis = np.array([0.0, 0.0, -1.0])
        basis = light_basis(-axis)                # rows x, y, axis
        view_pp = _affine4(basis, centre)
        # w = distance along the axis; x, y divided by it; z_ndc = -1 / w (then fitted),
        # increasing away from the centre — the sign rule below inverts it for "inverted".
        proj = np.zeros((4, 4))
        proj[0, 0] = proj[1, 1] = 1.0
        proj[2, 3] = -1.0
        proj[3, 2] = 1.0
        k = proj @ view_pp @ cam_v
    m = _fit(k, r, c, s.fit_margin_rel)
    return _depth_away_from_sun(m, d), info


def warp_matrix(warp: str, camera, sun_direction, receivers_m, casters_m,
                settings: WarpSettings | None = None) -> tuple[np.ndarray, dict]:
    """Dispatch by name: ``none`` | ``psm`` | ``lispsm`` | ``xpsm``."""
    if warp == "none":
        fwd = camera.frame()[2] if camera.kind == "perspective" else None
        return uniform_matrix(sun_direction, receivers_m, casters_m, settings, forward=fwd)
    if warp == "psm":
        return psm_matrix(camera, sun_direction, receivers_m, casters_m, settings)
    if warp == "lispsm":
        return lispsm_matrix(camera, sun_direction, receivers_m, casters_m, settings)
    if warp == "xpsm":
        return xpsm_matrix(camera, sun_direction, receivers_m, casters_m, settings)
    raise UsageError(f"unknown warp {warp!r}; valid: {', '.join(WARPS)}")


# --- the focus region -----------------------------------------------------------------------

def focus(ctx, work=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Facing mask (H, W), receivers (N, 3), their oriented normals (N, 3) and the receivers
    extruded toward the sun to the scene box (N, 3) of a shadow context (in ``work``, a held
    :class:`cityshade.runtime.memory.Scratch`, when given: valid until it is given back)."""
    from cityshade.shadows import shadowmap as sm

    faces = ctx.faces
    receivers = ctx.facing_points
    out = None if work is None else work.get("focus.casters", (receivers.shape[0], 3))
    casters = extrude_to_box(receivers, ctx.sun.direction, sm.scene_bounds(ctx.scene), out)
    return faces, receivers, ctx.facing_normals, casters
