"""Parallel tracing over bricks of rays, with a shadow-caster cache per brick.

A brick is ``brick_size`` consecutive rays (the thesis slides: "each thread handling a
brick"). The tracing kernels are serial ``nogil`` kernels over a range of bricks, run on
:func:`cityshade.runtime.threadpool.run_chunks` (``BRICKS_PER_CHUNK`` bricks at a time to whichever
thread is free); each brick owns its traversal scratch and its shadow-caster cache (the record
index of the last occluder it found, tested first for the next ray), so no state is shared
between threads and results do not depend on the thread count. Rays are most coherent when
consecutive rays are neighbours in the image or map: :func:`tile_order` gives that order for a
raster, and a thread takes neighbouring bricks one after the other.
"""
from __future__ import annotations

import contextlib
from typing import NamedTuple

import numpy as np

import numba
from numba import njit

from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks
from cityshade.trace.kernels import trace_range

#: Rays per brick: large enough to amortise the per-brick scratch allocation and to keep the
#: caster cache warm (a 16x16 pixel tile in tile order), small enough for two threads to
#: balance on uneven scenes (thousands of bricks per frame). Not tuned further.
DEFAULT_BRICK_SIZE = 256

#: Bricks a thread takes at a time (dynamic scheduling): a chunk of 8 bricks of 256 sun rays
#: is about 0.2 ms of work, against about 2 µs to hand it out, and few enough that a thread
#: slowed by other load on the machine does not hold back the end of the call.
BRICKS_PER_CHUNK = 8
#: Iterations a thread takes at a time from the prange kernels of other stages
#: (:func:`dynamic_bricks`).
PRANGE_CHUNK = 4


@njit(cache=True, inline="always")
def stripe_interleave(j, n_items, stripes):
    """Item handled at prange iteration j when iterations deal ``stripes`` contiguous stripes
    of the items out in turn (a permutation of 0..n_items-1; -1 = padding)."""
    per_stripe = (n_items + stripes - 1) // stripes
    b = (j % stripes) * per_stripe + j // stripes
    return b if b < n_items else -1


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
    """Hand prange iterations (tiles, rows) out ``PRANGE_CHUNK`` at a time to whichever thread
    is free (dynamic scheduling): camera work is uneven across an image, and on a shared
    machine one core may be slowed by other load."""
    old = numba.set_parallel_chunksize(PRANGE_CHUNK)
    try:
        yield
    finally:
        numba.set_parallel_chunksize(old)


@contextlib.contextmanager
def static_schedule():
    """Split prange iterations into one contiguous part per thread, in thread order (Numba's
    default schedule), whatever chunk size the caller set: for kernels whose iteration order
    gives each thread its own items (:func:`cityshade.raster.depthpass.tile_order`)."""
    old = numba.set_parallel_chunksize(0)
    try:
        yield
    finally:
        numba.set_parallel_chunksize(old)


#: :func:`ray_checks` codes: a non-finite origin, a non-finite direction, a direction whose
#: length is off 1 by more than the tolerance, a direction other than the first ray's.
BAD_ORIGIN = 1
BAD_DIRECTION = 2
NOT_UNIT_DIRECTION = 4
OTHER_DIRECTION = 8
#: Rays a thread checks at a time (a pass over memory: about 0.1 ms).
CHECK_CHUNK = 65_536


@njit(cache=True, nogil=True)
def _check_range(origins, directions, unit_tol, codes, i0, i1):
    """:func:`ray_checks` of rays ``[i0, i1)``: their code ORed into ``codes[i0 //
    CHECK_CHUNK]``."""
    shared = directions.shape[0] == 1
    d0x, d0y, d0z = directions[0, 0], directions[0, 1], directions[0, 2]
    code = 0
    for i in range(i0, i1):
        if not (abs(origins[i, 0]) < np.inf and abs(origins[i, 1]) < np.inf
                and abs(origins[i, 2]) < np.inf):
            code |= BAD_ORIGIN
        j = 0 if shared else i
        dx, dy, dz = directions[j, 0], directions[j, 1], directions[j, 2]
        if not (abs(dx) < np.inf and abs(dy) < np.inf and abs(dz) < np.inf):
            code |= BAD_DIRECTION
        elif abs(np.sqrt(dx * dx + dy * dy + dz * dz) - 1.0) > unit_tol:
            code |= NOT_UNIT_DIRECTION
        if dx != d0x or dy != d0y or dz != d0z:
            code |= OTHER_DIRECTION
    codes[i0 // CHECK_CHUNK] |= code


def ray_checks(origins, directions, unit_tol: float) -> int:
    """The OR of the check codes (``BAD_ORIGIN`` …) of all rays, in one pass: ``origins`` (N,
    3) float64, ``directions`` (N, 3) or (1, 3) (one for all)."""
    n = origins.shape[0]
    codes = np.zeros(max(1, -(-n // CHECK_CHUNK)), np.uint8)
    if n:
        run_chunks(_check_range, n, CHECK_CHUNK, origins, directions, unit_tol, codes)
    return int(np.bitwise_or.reduce(codes))


_NO_BOOL = np.zeros(0, np.bool_)
_NO_F64 = np.zeros(0)
_NO_I32 = np.zeros(0, np.int32)
_NO_F32 = np.zeros(0, np.float32)


def occluded_bricks(tree, box_lo, box_hi, origins, directions, tmin, tmax, t_days, brick_size,
                    out):
    """``out[i] = True`` when ray i hits a triangle valid at ``t_days`` within its segment.

    ``tree``: :class:`~cityshade.accel.kdtree_layout.KdViews`; ``origins``: (N, 3) float64;
    ``directions``: (N, 3) float64, or (1, 3) for rays that all share one direction (sun rays:
    its shear and inverses are then computed once); ``tmin``: scalar; ``tmax``: (N,) float64,
    or (1,) for all.
    """
    n_bricks = (origins.shape[0] + brick_size - 1) // brick_size
    run_chunks(trace_range, n_bricks, BRICKS_PER_CHUNK, tree, box_lo, box_hi, origins,
               directions, tmin, tmax, t_days, brick_size, False, out, _NO_F64, _NO_I32,
               _NO_F32, _NO_F32)


class ClosestHits(NamedTuple):
    """Per-ray output arrays of :func:`intersect_bricks`, filled in place."""

    #: (N,) float64 distance in metres to the hit (``inf`` on a miss).
    dist: np.ndarray
    #: (N,) int32 triangle id (-1 on a miss).
    tri: np.ndarray
    #: (N,) float32 barycentric u of the hit (0 on a miss).
    u: np.ndarray
    #: (N,) float32 barycentric v of the hit (0 on a miss).
    v: np.ndarray


def intersect_bricks(tree, box_lo, box_hi, origins, directions, tmin, tmax, t_days, brick_size,
                     out: ClosestHits):
    """Closest hits of all rays into ``out``; misses get ``t = inf``, ``tri = -1``,
    ``u = v = 0``. The rays are as for :func:`occluded_bricks`."""
    n_bricks = (origins.shape[0] + brick_size - 1) // brick_size
    run_chunks(trace_range, n_bricks, BRICKS_PER_CHUNK, tree, box_lo, box_hi, origins,
               directions, tmin, tmax, t_days, brick_size, True, _NO_BOOL, out.dist, out.tri,
               out.u, out.v)


#: :func:`shadow_origins` check codes, in the order the wrapper reports them.
BAD_POINT = 1
BAD_NORMAL = 2
NOT_UNIT_NORMAL = 4


@njit(cache=True, inline="always")
def _origin(px, py, pz, nx, ny, nz, sx, sy, sz, offset_rel, min_scale_m, unit_tol, out, k):
    """``out[k]``, the shadow-ray origin of point p with normal n toward sun s (float64), and
    the point's check code."""
    code = 0
    if not (np.isfinite(px) and np.isfinite(py) and np.isfinite(pz)):
        code |= BAD_POINT
    if not (np.isfinite(nx) and np.isfinite(ny) and np.isfinite(nz)):
        code |= BAD_NORMAL
    elif abs(np.sqrt(nx * nx + ny * ny + nz * nz) - 1.0) > unit_tol:
        code |= NOT_UNIT_NORMAL
    offset = offset_rel * max(max(max(abs(px), abs(py)), abs(pz)), min_scale_m)
    out[k, 0] = px + (nx + sx) * offset
    out[k, 1] = py + (ny + sy) * offset
    out[k, 2] = pz + (nz + sz) * offset
    return code


@njit(cache=True, nogil=True)
def _origins_range(points, normals, sun, offset_rel, min_scale_m, unit_tol, out, codes, i0, i1):
    """:func:`shadow_origins` of points ``[i0, i1)``: their check code ORed into
    ``codes[i0 // CHECK_CHUNK]``. Serial, for ``run_chunks`` (as a ``prange`` kernel: 1.1 CPU s
    of a first render's compiling)."""
    per_ray_sun = sun.shape[0] > 1
    code = 0
    for i in range(i0, i1):
        j = np.int64(i) if per_ray_sun else np.int64(0)
        code |= _origin(np.float64(points[i, 0]), np.float64(points[i, 1]),
                        np.float64(points[i, 2]), np.float64(normals[i, 0]),
                        np.float64(normals[i, 1]), np.float64(normals[i, 2]), sun[j, 0],
                        sun[j, 1], sun[j, 2], offset_rel, min_scale_m, unit_tol, out, i)
    codes[i0 // CHECK_CHUNK] |= code


@njit(cache=True, nogil=True)
def _pixel_origins_rows(position, normal, mask, starts, sun, offset_rel, min_scale_m, unit_tol,
                        out, codes, r0, r1):
    """:func:`pixel_shadow_origins` of rows ``[r0, r1)``, each from its start ``starts[r]``;
    their check code ORed into ``codes[r0 // ROW_CHUNK]``."""
    code = 0
    for r in range(r0, r1):
        k = starts[r]
        for c in range(mask.shape[1]):
            if mask[r, c]:
                code |= _origin(np.float64(position[r, c, 0]), np.float64(position[r, c, 1]),
                                np.float64(position[r, c, 2]), np.float64(normal[r, c, 0]),
                                np.float64(normal[r, c, 1]), np.float64(normal[r, c, 2]),
                                sun[0], sun[1], sun[2], offset_rel, min_scale_m, unit_tol,
                                out, k)
                k += 1
    codes[r0 // ROW_CHUNK] |= code


def shadow_origins(points, normals, sun, offset_rel, min_scale_m, unit_tol, out) -> int:
    """``out[i] = p + (n + s) * offset_rel * max(|p|_inf, min_scale_m)`` for every point, in
    the float64 order of the numpy twin; returns the OR of the check codes of the rays (a
    non-finite point or normal, a normal whose length is off 1 by more than ``unit_tol``).
    ``sun`` is (1, 3) (one direction) or (N, 3)."""
    n = points.shape[0]
    codes = np.zeros(max(1, -(-n // CHECK_CHUNK)), np.uint8)
    if n:
        run_chunks(_origins_range, n, CHECK_CHUNK, points, normals, sun, offset_rel,
                   min_scale_m, unit_tol, out, codes)
    return int(np.bitwise_or.reduce(codes))


def pixel_shadow_origins(position, normal, mask, starts, sun, offset_rel, min_scale_m,
                         unit_tol, out) -> int:
    """:func:`shadow_origins` of the pixels of the (H, W) bool ``mask`` of the (H, W, 3)
    images ``position`` and ``normal``, in row-major order (row ``r``'s first at
    ``starts[r]``), rows in parallel; ``sun`` (3,). The same values as :func:`shadow_origins`
    of the gathered pixels, without gathering them."""
    codes = np.zeros(max(1, -(-mask.shape[0] // ROW_CHUNK)), np.uint8)
    if mask.shape[0]:
        run_chunks(_pixel_origins_rows, mask.shape[0], ROW_CHUNK, position, normal, mask,
                   starts, sun, offset_rel, min_scale_m, unit_tol, out, codes)
    return int(np.bitwise_or.reduce(codes))


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
