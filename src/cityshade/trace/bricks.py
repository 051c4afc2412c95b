"""Parallel tracing over bricks of rays, with a shadow-caster cache per brick.

A brick is ``brick_size`` consecutive rays (the thesis slides: "each thread handling a
brick"). Numba ``prange`` hands whole bricks to threads; each brick owns its traversal stacks
and its shadow-caster cache (the record index of the last occluder it found, tested first for
the next ray), so no state is shared between threads and results do not depend on the thread
count. Rays are most coherent when consecutive rays are neighbours in the image or map:
:func:`tile_order` gives that order for a raster.
"""
from __future__ import annotations

import numpy as np
import contextlib

import numba
from numba import njit, prange

from cityshade.accel.kdtree_layout import record_id
from cityshade.trace.kernels import any_hit_dir, closest_hit, direction_terms, new_stack

#: Rays per brick: large enough to amortise the per-brick stack allocation and to keep the
#: caster cache warm (a 16x16 pixel tile in tile order), small enough for two threads to
#: balance on uneven scenes (thousands of bricks per frame). Not tuned further.
DEFAULT_BRICK_SIZE = 256

#: Stripes of the brick interleave: ``prange`` hands each thread a contiguous range of
#: iterations, and costs vary smoothly over an image (sky at the top, near city at the bottom),
#: so iteration j is mapped to the brick ``(j % STRIPES) * per_stripe + j // STRIPES``: every
#: thread then takes part of every stripe of the image, and the two cores finish together.
STRIPES = 64
#: Bricks a thread takes at a time from the shared queue (dynamic scheduling): few enough that
#: a thread slowed by other load on the machine does not hold back the end of the call.
BRICKS_PER_CHUNK = 4


@njit(cache=True, inline="always")
def stripe_interleave(j, n_items, stripes):
    """Item handled at prange iteration j when iterations deal ``stripes`` contiguous stripes
    of the items out in turn (a permutation of 0..n_items-1; -1 = padding)."""
    per_stripe = (n_items + stripes - 1) // stripes
    b = (j % stripes) * per_stripe + j // stripes
    return b if b < n_items else -1


@njit(cache=True, inline="always")
def _brick_of(j, n_bricks):
    """Brick traced at prange iteration j (a permutation of 0..n_bricks-1; -1 = padding)."""
    return stripe_interleave(j, n_bricks, STRIPES)


@njit(cache=True, inline="always")
def _brick_rays(j, n, brick_size):
    """Rays ``[i0, i1)`` of the brick traced at prange iteration j (empty for padding)."""
    b = _brick_of(j, (n + brick_size - 1) // brick_size)
    if b < 0:
        return 0, 0
    return b * brick_size, min(n, (b + 1) * brick_size)


@njit(cache=True, inline="always")
def _n_iter(n, brick_size):
    """prange iterations over n rays: the bricks padded to a multiple of STRIPES."""
    return STRIPES * (((n + brick_size - 1) // brick_size + STRIPES - 1) // STRIPES)


#: Items (rays, points) below which a call of a short parallel kernel runs on one thread: with
#: Numba's OpenMP layer each parallel region wakes the other thread and lets it spin a while,
#: which costs more than ~0.1 ms of work (shadow origins of a 128² batch tile: 0.12 ms of CPU
#: on one thread, 0.5-4.9 ms of CPU on two on a loaded machine). The answer does not depend on
#: the thread count.
SMALL_CALL_ITEMS = 65_536


@contextlib.contextmanager
def one_thread_when_small(items: int, limit: int = SMALL_CALL_ITEMS):
    """Run the block on one Numba thread when ``items < limit`` (the calling thread's setting
    is restored after)."""
    threads = numba.get_num_threads()
    if threads > 1 and items < limit:
        numba.set_num_threads(1)
    try:
        yield
    finally:
        numba.set_num_threads(threads)


@contextlib.contextmanager
def dynamic_bricks():
    """Hand prange iterations (bricks) out ``BRICKS_PER_CHUNK`` at a time to whichever thread
    is free (dynamic scheduling): shadow and camera work is uneven across an image, and on a
    shared machine one core may be slowed by other load."""
    old = numba.set_parallel_chunksize(BRICKS_PER_CHUNK)
    try:
        yield
    finally:
        numba.set_parallel_chunksize(old)


@njit(cache=True, parallel=True)
def occluded_bricks(tree, box_lo, box_hi, origins, directions, tmin, tmax, t_days, brick_size,
                    out):
    """``out[i] = True`` when ray i hits a triangle valid at ``t_days`` within its segment.

    ``tree``: :class:`~cityshade.accel.kdtree_layout.KdViews`; ``origins``: (N, 3) float64;
    ``directions``: (N, 3) float64, or (1, 3) for rays that all share one direction (sun rays:
    its shear and inverses are then computed once); ``tmin``: scalar; ``tmax``: (N,) float64.
    """
    n = origins.shape[0]
    shared = directions.shape[0] == 1
    terms0 = direction_terms(directions[0, 0], directions[0, 1], directions[0, 2])
    for j in prange(_n_iter(n, brick_size)):
        i0, i1 = _brick_rays(j, n, brick_size)
        if i0 >= i1:
            continue
        stack = new_stack()
        cache_k = -1
        for i in range(i0, i1):
            terms = terms0 if shared else direction_terms(directions[i, 0], directions[i, 1],
                                                          directions[i, 2])
            k = any_hit_dir(tree, box_lo, box_hi, origins[i, 0], origins[i, 1],
                            origins[i, 2], terms, tmin, tmax[i], t_days, cache_k, stack)
            out[i] = k >= 0
            if k >= 0:
                cache_k = k


@njit(cache=True, parallel=True)
def intersect_bricks(tree, box_lo, box_hi, origins, directions, tmin, tmax, t_days, brick_size,
                     out_t, out_tri, out_u, out_v):
    """Closest hits of all rays; misses get ``t = inf``, ``tri = -1``, ``u = v = 0``."""
    n = origins.shape[0]
    for j in prange(_n_iter(n, brick_size)):
        i0, i1 = _brick_rays(j, n, brick_size)
        if i0 >= i1:
            continue
        stack = new_stack()
        for i in range(i0, i1):
            t, k, u, v = closest_hit(tree, box_lo, box_hi, origins[i, 0], origins[i, 1],
                                     origins[i, 2], directions[i, 0], directions[i, 1],
                                     directions[i, 2], tmin, tmax[i], t_days, stack)
            out_t[i] = t
            out_tri[i] = record_id(tree, k) if k >= 0 else -1
            out_u[i] = u
            out_v[i] = v


#: :func:`shadow_origins` check codes, in the order the wrapper reports them.
BAD_POINT = 1
BAD_NORMAL = 2
NOT_UNIT_NORMAL = 4


@njit(cache=True, parallel=True)
def shadow_origins(points, normals, sun, offset_rel, min_scale_m, unit_tol, out):
    """``out[i] = p + (n + s) * offset_rel * max(|p|_inf, min_scale_m)`` for every point, in
    the float64 order of the numpy twin; returns the OR of the check codes of the rays (a
    non-finite point or normal, a normal whose length is off 1 by more than ``unit_tol``).
    ``sun`` is (1, 3) (one direction) or (N, 3)."""
    n = points.shape[0]
    per_ray_sun = sun.shape[0] > 1
    flags = np.zeros(n, np.uint8)
    for i in prange(n):
        px, py, pz = np.float64(points[i, 0]), np.float64(points[i, 1]), np.float64(points[i, 2])
        nx, ny, nz = (np.float64(normals[i, 0]), np.float64(normals[i, 1]),
                      np.float64(normals[i, 2]))
        j = np.int64(i) if per_ray_sun else np.int64(0)
        f = 0
        if not (np.isfinite(px) and np.isfinite(py) and np.isfinite(pz)):
            f |= BAD_POINT
        if not (np.isfinite(nx) and np.isfinite(ny) and np.isfinite(nz)):
            f |= BAD_NORMAL
        elif abs(np.sqrt(nx * nx + ny * ny + nz * nz) - 1.0) > unit_tol:
            f |= NOT_UNIT_NORMAL
        flags[i] = f
        offset = offset_rel * max(max(max(abs(px), abs(py)), abs(pz)), min_scale_m)
        out[i, 0] = px + (nx + sun[j, 0]) * offset
        out[i, 1] = py + (ny + sun[j, 1]) * offset
        out[i, 2] = pz + (nz + sun[j, 2]) * offset
    code = 0
    for i in range(n):
        code |= flags[i]
    return code


def tile_order(height: int, width: int, tile_px: int = 16) -> np.ndarray:
    """Permutation of the ``height * width`` row-major pixels into square tiles.

    Parameters
    ----------
    height, width : int
        Raster size in pixels.
    tile_px : int
        Tile edge in pixels; tiles are listed row by row, pixels inside a tile row-major.

    Returns
    -------
    (height * width,) int64 array
        ``order[j]`` is the row-major pixel index of the j-th ray in tile order; trace
        ``rays[order]`` and scatter results back with ``out[order] = result``.
    """
    rows = np.arange(height)
    cols = np.arange(width)
    tile_r = rows // tile_px
    tile_c = cols // tile_px
    n_tc = (width + tile_px - 1) // tile_px
    # Key: tile index, then row inside the tile, then column.
    key = ((tile_r[:, None] * n_tc + tile_c[None, :]) * (tile_px * tile_px)
           + (rows % tile_px)[:, None] * tile_px + (cols % tile_px)[None, :])
    return np.argsort(key.ravel(), kind="stable")
