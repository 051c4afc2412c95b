"""trace stage of cityshade: closest-hit and shadow (any-hit) rays through the 4-D kd-tree.

Conventions: render space (x east, y north, z up, metres, relative to the scene origin), unit
ray directions, distances in metres along the ray, city time ``t_days`` in days since
1970-01-01 UTC (a triangle is present when ``begin <= t_days < end``). The sun is a direction,
so shadow rays end where they leave the scene box (``tmax=None``).
"""
from __future__ import annotations

import numpy as np

from cityshade.accel.kdtree_layout import KdTree
from cityshade.errors import TraceInputError
from cityshade.trace import bricks
from cityshade.trace.bricks import (DEFAULT_BRICK_SIZE, ClosestHits, intersect_bricks,
                                    occluded_bricks, tile_order)
from cityshade.runtime.memory import Recycler
from cityshade.util import check_t_days

__all__ = ["TraceInputError", "intersect", "occluded", "shadow_rays_from_surface",
           "shadow_rays_from_pixels", "sunlit", "tree_of",
           "tile_order", "SHADOW_OFFSET_REL", "SHADOW_OFFSET_MIN_SCALE_M"]

#: Shadow-ray origin offset per metre of coordinate magnitude. Surface points and vertices are
#: float32 (2^-24 ≈ 6e-8 relative rounding) and hit points carry a few such roundings; 2^-18
#: ≈ 3.8e-6 (64 float32 ulps) clears them with margin: 1.5 cm at 4 km from the origin.
SHADOW_OFFSET_REL = 2.0 ** -18
#: Coordinate magnitude below which the offset stops shrinking (points near the origin still
#: lie on triangles whose vertices are metres away): 1 m, i.e. an offset of at least 3.8 µm.
SHADOW_OFFSET_MIN_SCALE_M = 1.0
#: Accepted deviation of a direction's length from 1 (float32 normalisation is good to 1e-7).
UNIT_LENGTH_TOL = 1e-4
#: Root-box padding relative to the scene size, so triangles on the box faces are inside every
#: ray segment despite the rounding of the slab distances.
BOX_PAD_REL = 1e-6


#: The shadow-ray origins' memory, used again once the caller has let go of them (a map
#: frame's are 81 MB: fresh pages cost 15-150 ms on a loaded machine).
_ORIGINS = Recycler(keep=2)


def tree_of(tree) -> KdTree:
    """``tree`` checked to be one :class:`KdTree` (a scene, tiled or not, traces through
    :mod:`cityshade.shadows.visibility`, which hands each tree to the engines)."""
    if isinstance(tree, KdTree):
        return tree
    raise TraceInputError(f"expected a KdTree, not {type(tree).__name__}")


def padded_box(tree: KdTree) -> tuple[np.ndarray, np.ndarray]:
    lo, hi, scale_m = tree.box_scale_m()
    pad = BOX_PAD_REL * scale_m
    return lo - pad, hi + pad


def _rays(origins, directions, tmax):
    """Validated float64 (N, 3) origins, directions (N, 3), or (1, 3) when every ray has the
    same one (sun rays: the kernel then computes its terms once), and tmax (N,), or (1,) when
    shared. The checks are one pass over the rays (:func:`bricks.ray_checks`); the messages
    come from the numpy checks, run only when that pass found something."""
    origins = np.ascontiguousarray(origins, dtype=np.float64)
    directions = np.ascontiguousarray(directions, dtype=np.float64)
    if origins.ndim != 2 or origins.shape[1] != 3:
        raise TraceInputError(f"origins must have shape (N, 3), not {origins.shape}")
    if directions.shape in ((3,), (1, 3)):
        directions = directions.reshape(1, 3)
    elif directions.shape != origins.shape:
        raise TraceInputError(f"directions must have shape {origins.shape} or (3,), "
                              f"not {directions.shape}")
    code = bricks.ray_checks(origins, directions, UNIT_LENGTH_TOL)
    if code & (bricks.BAD_ORIGIN | bricks.BAD_DIRECTION | bricks.NOT_UNIT_DIRECTION):
        _explain_bad_rays(origins, directions)
    if directions.shape[0] > 1 and not code & bricks.OTHER_DIRECTION:
        directions = directions[:1]
    n = origins.shape[0]
    if tmax is None:
        return origins, directions, np.full(1, np.inf)
    tmax_arr = np.asarray(tmax, dtype=np.float64)
    if tmax_arr.ndim == 0 or tmax_arr.shape == (1,):
        tmax_arr = tmax_arr.reshape(1)
    elif tmax_arr.shape != (n,):
        raise TraceInputError(f"tmax must be a scalar or have shape ({n},), "
                              f"not {tmax_arr.shape}")
    else:
        tmax_arr = np.ascontiguousarray(tmax_arr)
    if np.isnan(tmax_arr).any() or (tmax_arr < 0).any():
        raise TraceInputError("tmax must be >= 0 (inf allowed), not NaN or negative")
    return origins, directions, tmax_arr


def _explain_bad_rays(origins, directions):
    """Raise the TraceInputError that names what is wrong with the rays."""
    if not np.isfinite(origins).all():
        raise TraceInputError("ray origins contain NaN or infinite values")
    if not np.isfinite(directions).all():
        raise TraceInputError("ray directions contain NaN or infinite values")
    length = np.sqrt(np.einsum("ij,ij->i", directions, directions))
    worst = int(np.argmax(np.abs(length - 1.0)))
    raise TraceInputError(f"ray directions must be unit length (ray {worst} has length "
                          f"{length[worst]:.6g})")


def _brick(brick_size) -> int:
    b = int(brick_size)
    if b < 1:
        raise TraceInputError(f"brick_size must be >= 1, not {brick_size}")
    return b


def occluded(tree, origins, directions, t_days: float = 0.0, tmax=None, *,
             brick_size: int = DEFAULT_BRICK_SIZE) -> np.ndarray:
    """Whether each ray hits any triangle present at city time ``t_days`` (shadow rays).

    Parameters
    ----------
    tree : KdTree
        The 4-D kd-tree.
    origins : (N, 3) float array
        Ray origins, render-space metres. For shadow rays use
        :func:`shadow_rays_from_surface` so rays do not re-hit their own surface.
    directions : (N, 3) or (3,) float array
        Unit directions (towards the sun for shadow rays); (3,): one for every ray.
    t_days : float
        City time, days since 1970-01-01 UTC; ignored by a model without dates.
    tmax : None, float or (N,) float array
        Segment end in metres (a float or a (1,) array: the same for every ray); None traces
        to the scene bounds (the sun is a direction).
    brick_size : int
        Rays per parallel work item; each brick keeps its own shadow-caster cache.

    Returns
    -------
    (N,) bool array
        True where the segment ``[0, tmax]`` of the ray is blocked.

    Raises
    ------
    TraceInputError
        Wrong shapes, non-finite values, non-unit directions, negative or NaN ``tmax``.
    """
    kd = tree_of(tree)
    origins, directions, tmax_arr = _rays(origins, directions, tmax)
    t = check_t_days(t_days, TraceInputError)
    brick = _brick(brick_size)
    out = np.zeros(origins.shape[0], np.bool_)
    if origins.shape[0] == 0 or kd.tri_records.shape[0] == 0:
        return out
    lo, hi = padded_box(kd)
    occluded_bricks(kd.views, lo, hi, origins, directions, 0.0, tmax_arr, t, brick, out)
    return out


def intersect(tree, origins, directions, t_days: float = 0.0, tmax=None, *,
              brick_size: int = DEFAULT_BRICK_SIZE):
    """Closest hit of each ray among the triangles present at city time ``t_days``.

    Parameters
    ----------
    tree, origins, directions, t_days, tmax, brick_size
        As for :func:`occluded`.

    Returns
    -------
    dist : (N,) float64
        Distance in metres to the hit (``inf`` on a miss).
    tri : (N,) int32
        Triangle id (index into the scene's triangles; -1 on a miss). Rays exactly through a
        shared edge report the lower id.
    u, v : (N,) float32
        Barycentrics of the hit: point = (1 - u - v) v0 + u v1 + v v2 (0 on a miss).
    """
    kd = tree_of(tree)
    origins, directions, tmax_arr = _rays(origins, directions, tmax)
    t = check_t_days(t_days, TraceInputError)
    brick = _brick(brick_size)
    n = origins.shape[0]
    dist = np.full(n, np.inf)
    tri = np.full(n, -1, np.int32)
    u = np.zeros(n, np.float32)
    v = np.zeros(n, np.float32)
    if n == 0 or kd.tri_records.shape[0] == 0:
        return dist, tri, u, v
    lo, hi = padded_box(kd)
    intersect_bricks(kd.views, lo, hi, origins, directions, 0.0, tmax_arr, t, brick,
                     ClosestHits(dist, tri, u, v))
    return dist, tri, u, v


def shadow_offset_m(points) -> np.ndarray:
    """(N,) offset in metres for shadow rays leaving ``points`` (N, 3): relative to magnitude."""
    points = np.asarray(points, dtype=np.float64)
    a = np.abs(points)
    # Column by column (the same maximum): numpy's reduction over rows of 3 took 78 ms for a
    # batch's 2.1 M receivers.
    scale = np.maximum(np.maximum(np.maximum(a[:, 0], a[:, 1]), a[:, 2]),
                       SHADOW_OFFSET_MIN_SCALE_M)
    return SHADOW_OFFSET_REL * scale


def shadow_rays_from_surface(points, normals, sun_dir, *, out: np.ndarray | None = None
                             ) -> np.ndarray:
    """Origins of shadow rays: surface points pushed off their surface along the normal.

    Parameters
    ----------
    points : (N, 3) float array
        Points on triangles, render-space metres.
    normals : (N, 3) float array
        Unit normals of the surfaces at the points, outward (the side the ray leaves from).
    sun_dir : (3,) or (N, 3) float array
        Unit direction towards the sun (not used for the offset, which is along the normal;
        checked so that a bad sun fails here rather than in the kernel).
    out : (N, 3) float64 C-contiguous array, optional
        Written instead of a new array (a caller that checks its receivers once and keeps a
        buffer of their size: the sky's 2 M receivers, 51 MB).

    Returns
    -------
    (N, 3) float64 array
        ``points + (normals + sun_dir) * offset`` with
        ``offset = SHADOW_OFFSET_REL * max(|p|_inf, 1 m)``: the offset scales with coordinate
        magnitude, because float32 rounding does. The step along the normal leaves the
        receiver's own surface; the step toward the sun leaves every *other* surface through
        the point, which the normal step keeps the origin in: at the foot of a sun-facing wall
        (a roof-step edge seen from above) the lower roof's point lies in the wall's plane, and
        moving up keeps it there, so the ray hit the wall at distance ≈ 0; one step along
        the ray itself puts it in front of any surface it crosses there (a surface it crosses
        at t = 0 it leaves for t > 0, whichever way that surface faces). Points whose normal
        faces away from the sun are offset all the same; callers treat those as
        self-shadowed (docs/DESIGN.md §9).
    """
    points = np.ascontiguousarray(points, dtype=np.float64)
    normals = np.ascontiguousarray(normals, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise TraceInputError(f"points must have shape (N, 3), not {points.shape}")
    if normals.shape != points.shape:
        raise TraceInputError(f"normals must have shape {points.shape}, not {normals.shape}")
    sun = _checked_sun(sun_dir, points.shape)
    if out is None:
        out = _ORIGINS.empty((points.shape[0], 3), np.float64)
    elif out.shape != points.shape or out.dtype != np.float64 or not out.flags.c_contiguous:
        raise TraceInputError(f"out must be a C-contiguous float64 array of shape "
                              f"{points.shape}")
    # One parallel pass: the checks and the offset (the numpy twin: tests/reference.py).
    with bricks.one_thread_when_small(points.shape[0]):
        code = bricks.shadow_origins(points, normals, np.ascontiguousarray(sun.reshape(-1, 3)),
                                     SHADOW_OFFSET_REL, SHADOW_OFFSET_MIN_SCALE_M,
                                     UNIT_LENGTH_TOL, out)
    _check_origins(code)
    return out


def _checked_sun(sun_dir, per_ray_shape=None) -> np.ndarray:
    """``sun_dir`` as float64, checked: shape (3,) (or ``per_ray_shape``, one per ray),
    finite, unit length."""
    sun = np.asarray(sun_dir, dtype=np.float64)
    if sun.shape not in ((3,), per_ray_shape):
        also = "" if per_ray_shape is None else f" or {per_ray_shape}"
        raise TraceInputError(f"sun_dir must have shape (3,){also}, not {sun.shape}")
    if not np.isfinite(sun).all():
        raise TraceInputError("sun_dir contain NaN or infinite values")
    if np.abs(np.linalg.norm(sun, axis=-1) - 1.0).max(initial=0.0) > UNIT_LENGTH_TOL:
        raise TraceInputError("sun_dir must be unit length")
    return sun


def _check_origins(code: int) -> None:
    """The error of :func:`bricks.shadow_origins`'s check code, if any."""
    if code & bricks.BAD_POINT:
        raise TraceInputError("points contain NaN or infinite values")
    if code & bricks.BAD_NORMAL:
        raise TraceInputError("normals contain NaN or infinite values")
    if code & bricks.NOT_UNIT_NORMAL:
        raise TraceInputError("normals must be unit length")


def shadow_rays_from_pixels(position_m, normals, mask, row_starts, sun_dir) -> np.ndarray:
    """:func:`shadow_rays_from_surface` of the pixels of a frame: ``shadow_rays_from_surface(
    position_m[mask], normals[mask], sun_dir)`` in row-major order, the same values, in one
    pass over the rows without gathering the points and normals first (a 1 m map of the 1M
    city: 2 × 63 MB of fresh memory, half of its raytrace shadow stage's first-touch cost).

    Parameters
    ----------
    position_m, normals : (H, W, 3) float arrays
    mask : (H, W) bool array
    row_starts : (H + 1,) int64
        Where each row's pixels of ``mask`` start in row-major order (the last: their count).
    sun_dir : (3,) float array, unit

    Raises
    ------
    TraceInputError
        As :func:`shadow_rays_from_surface`, or shapes that do not match.
    """
    mask = np.ascontiguousarray(mask, dtype=np.bool_)
    position_m, normals = np.asarray(position_m), np.asarray(normals)
    if (mask.ndim != 2 or position_m.shape != mask.shape + (3,)
            or normals.shape != position_m.shape):
        raise TraceInputError(f"points {position_m.shape} and normals {normals.shape} must be "
                              f"(H, W, 3) of the mask {mask.shape}")
    starts = np.asarray(row_starts, dtype=np.int64)
    if starts.shape != (mask.shape[0] + 1,):
        raise TraceInputError(f"row starts must have shape ({mask.shape[0] + 1},)")
    sun = _checked_sun(sun_dir)
    out = _ORIGINS.empty((int(starts[-1]), 3), np.float64)
    with bricks.one_thread_when_small(out.shape[0]):
        code = bricks.pixel_shadow_origins(position_m, normals, mask, starts, sun,
                                           SHADOW_OFFSET_REL, SHADOW_OFFSET_MIN_SCALE_M,
                                           UNIT_LENGTH_TOL, out)
    _check_origins(code)
    return out


def sunlit(tree, points, normals, sun_direction, t_days: float = 0.0) -> np.ndarray:
    """Whether each surface point sees the sun: one shadow ray per point, from the point
    pushed off its surface (:func:`shadow_rays_from_surface`) toward the sun, to the scene
    bounds.

    Parameters
    ----------
    tree : KdTree
    points, normals : (N, 3) float arrays
        Surface points (render space, metres) and their unit normals on the side facing the sun.
    sun_direction : (3,) float array
        Unit direction toward the sun.
    t_days : float
        City time.

    Returns
    -------
    (N,) bool array, True where nothing blocks the sun.
    """
    origins = shadow_rays_from_surface(points, normals, sun_direction)
    return ~occluded(tree, origins, np.asarray(sun_direction, dtype=np.float64), t_days)
