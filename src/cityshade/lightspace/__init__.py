"""lightspace stage of cityshade: exact sun shadows by binning casters in the sun's light plane.

The ``izb`` engine (irregular z-buffer / light buffer; Haines & Greenberg 1986, Aila & Laine
2004, Johnson et al. 2005): for one sun direction and a set of shadow-ray origins, every ray has
the same direction, so the watertight test's shear is shared and "is o in shadow" becomes a
point-in-triangle question in the light plane plus a depth test. The casters standing at the
city time that can reach the receivers are binned into a grid over the receivers' light-plane
box and each receiver tests its cell's list with the same predicate and segment limits as
:func:`cityshade.trace.occluded` (kernels and the proof sketch in
:mod:`cityshade.lightspace.kernels`). The answer is the one of ``raytrace``, bit for bit; the
tests compare them on every pixel.

Conventions as in :mod:`cityshade.trace`: render-space metres, unit sun direction, city time in
days since 1970-01-01 UTC, a triangle present when ``begin <= t_days < end``, shadow rays from
:func:`cityshade.trace.shadow_rays_from_surface` to the scene bounds.
"""
from __future__ import annotations

import contextlib
import math
import time
import weakref

import numba
import numpy as np

from cityshade.accel.kdtree_layout import REC_ID, KdTree
from cityshade.runtime.memory import release_pages
from cityshade.trace.bricks import one_thread_when_small
from cityshade.lightspace import kernels as K
from cityshade.runtime.threadpool import run_chunks
from cityshade.runtime.interpret import compiled_or_cached, twin_if
from cityshade.runtime.memory import Recycler, Scratch
from cityshade.trace import UNIT_LENGTH_TOL, tree_of, shadow_offset_m, shadow_rays_from_surface
from cityshade.errors import TraceInputError

__all__ = ["occluded", "sunlit", "Casters", "casters_of", "casters_ready", "forget_casters",
           "last_calls",
           "SurfaceReceivers",
           "MARGIN_REL", "caster_order"]

#: Widening of every caster's light-plane box per metre of coordinate magnitude. The binning
#: projection and the kernel's per-ray differences round differently by a few float64 ulps
#: (~1e-15 relative); 2^-30 ≈ 9e-10 (4 µm at 4 km) is a millionfold margin and costs nothing
#: (cells are metres wide).
MARGIN_REL = 2.0 ** -30
#: A caster's depth plane (moved sunward by its own float32 rounding bound) must lie this far
#: behind a receiver along the shear axis before the receiver skips it: 15 µm + 2^-22 of the
#: coordinate magnitude (1 mm at 4 km), far above hit_record's rounding of t (~4e-9 of the
#: scene size for the planes used) and below the shadow-ray offset (2^-18 of the magnitude),
#: so a receiver skips its own surface but never a caster its test would hit at t >= 0.
DEPTH_MARGIN_M = 2.0 ** -16
DEPTH_MARGIN_REL = 2.0 ** -22
#: Candidate cell sizes, as multiples of the size that holds one receiver per cell on average;
#: the one with the lowest estimated cost is used (:func:`_choose_cell_m`).
CELL_FACTORS = (0.35, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0, 32.0, 45.0,
                64.0)
#: Cost model of one sun, nanoseconds per unit, fitted to CPU times on one thread (the 1M
#: city's camera and map workloads of benchmarks/raytrace.py, cells 2-13 m): a reference of a
#: caster in an occupied cell costs ~40 ns (count, fill, and the query's per-caster setup of a
#: cell's receivers, mostly a cache miss on the caster); a receiver tests each entry of its
#: cell's list at ~1.5 ns (one lane of the caster-major mask); a cell ~1.5 ns to clear and sum.
#: Receivers are not spread evenly (a perspective camera crowds them near the eye), so the
#: list lengths and the occupied cells come from a coarse grid of receiver and caster counts.
COST_REF_NS = 40.0
COST_SCAN_NS = 1.5
COST_CELL_NS = 1.5
#: Cells of the coarse density grid of the model, and receivers sampled for it.
DENSITY_CELLS = 4096
DENSITY_SAMPLE = 1 << 18
#: Receivers + casters below which a call runs on one thread: a call is a dozen short parallel
#: passes, and each waits for every worker thread; on a busy machine a descheduled worker costs
#: a scheduler time slice (milliseconds) per pass, more than the whole small call. The answer
#: does not depend on the thread count.
SINGLE_THREAD_WORK = 300_000
#: Upper bound on grid cells per receiver (memory: two int32 counts per cell and thread).
MAX_CELLS_PER_RECEIVER = 8
#: Casters culled per pass (bounds the float64 box work array: 32 MB) and tree records read
#: per chunk when the casters are gathered.
CULL_ROWS = 1 << 20
GATHER_ROWS = 1 << 20
#: Cells of the receiver occupancy grid that drops casters whose box holds no receiver (at
#: most one per receiver): a map strip's receivers are a thin slanted band in the light plane
#: and their box holds most of the city (4.6 M of 10 M casters kept for a strip of 94 rows).
#: 2^16 cells (256 KB, cache-resident) still resolve such a band (cells of ~15 m against its
#: ~90 m width) where 2^20 (4 MB) missed the cache on every receiver.
OCCUPANCY_CELLS = 1 << 16
#: Casters are gathered by a kd-tree walk instead of a scan of all of them when there are at
#: least this many and the receivers' light-plane box covers at most ``NEAR_AREA_SHARE`` of
#: the scene's: a tiled batch's task (one 512-px tile of the 10^7-triangle city's 2 m map)
#: scanned all 10^7 casters per sun, 130-280 ms against a 20-35 ms query, so its 20 tiles cost
#: the cull 20 times over (tiled run 590 s against 237 s untiled).
NEAR_MIN_CASTERS = 1 << 18
NEAR_AREA_SHARE = 0.25


class Casters:
    """The triangles of a kd-tree as one record each (the tree repeats a triangle in every leaf
    it straddles), with the key order of the last sun used, so a batch sorts once per change
    of the shear axis instead of once per step.

    Only the sorted copy is kept (``first`` indexes the tree's records, one row per triangle),
    with the words the kernels read (``K.CASTER_WORDS`` of 16) and float32 keys (a key is a
    float32 vertex coordinate, exact): the tree's records are read a chunk at a time in file
    order and their memory-mapped pages released, so the 10^7-triangle city holds one 560 MB
    copy and 40 MB of keys instead of two full copies plus its 1.2 GB of mapped records.
    """

    def __init__(self, tree: KdTree):
        self._tree_records = recs = tree.tri_records
        ids = np.empty(recs.shape[0], np.int32)
        for c0 in range(0, recs.shape[0], GATHER_ROWS):
            part = recs[c0:c0 + GATHER_ROWS]
            ids[c0:c0 + part.shape[0]] = part.view(np.int32)[:, REC_ID]
            release_pages(part)
        # Each triangle's first record in row order, as np.unique(return_index) sorted would
        # give, without its sorted copies (0.3 GB of temporaries at 10^7 triangles).
        seen = np.zeros(int(ids.max()) + 1 if ids.size else 0, np.bool_)
        first = np.empty(min(ids.size, seen.size), np.int32)
        n = K.first_records(ids, seen, first)
        del ids, seen
        self.first = first[:n].copy() if n < first.size else first
        self._axis = None
        self._sorted = None
        self._rows = None
        # Grow-only work arrays (~300 MB on the 1M-triangle map, faulted in anew every sun
        # step of a batch without them).
        self.scratch = Scratch()
        # The sorted copy's memory, again for the next sun's sort once nothing holds the last
        # one (65 MB of fresh pages per sort of the 1M-triangle city's casters otherwise).
        self._memory = Recycler(keep=2)

    def _chunks(self):
        """(row range of ``first``, its rows of the tree's records), in file order, each
        chunk's mapped pages released once the caller is done with it."""
        recs, first = self._tree_records, self.first
        for c0 in range(0, first.size, GATHER_ROWS):
            c1 = min(first.size, c0 + GATHER_ROWS)
            yield c0, c1, first[c0:c1]
            release_pages(recs[first[c0]:first[c1 - 1] + 1])

    def sorted_for(self, kz: int, sgn: float):
        """(records, keys) sorted by depth key descending for shear axis ``kz`` and sign."""
        if self._axis != (kz, sgn):
            self._sorted = self._axis = self._rows = None
            n = self.first.size
            recs = self._tree_records
            keys = np.empty(n)      # negated depth keys: ascending = descending depth
            for c0, c1, rows in self._chunks():
                K.caster_keys(recs, rows, kz, sgn, keys[c0:c1])
            order = stable_argsort(keys)
            sorted_keys = self._memory.empty(n, np.float32)
            rank = np.empty(n, np.int32)
            K.ranks_of(order, keys, sorted_keys, rank)
            del keys, order
            # Scattered to their sorted rows while the tree's records are read in file order.
            records = self._memory.empty((n, K.CASTER_WORDS), recs.dtype)
            for c0, c1, rows in self._chunks():
                K.scatter_records(recs, rows, rank[c0:c1], records)
            self._sorted = (records, sorted_keys)
            self._axis = (kz, sgn)
        return self._sorted

    def forget_sorted(self) -> None:
        """Let the sorted copy and its memory go (a last call, :func:`last_calls`, once its
        casters are packed); the next :meth:`sorted_for` sorts again."""
        self._sorted = self._axis = self._rows = None
        self._memory.clear()

    def rows_of_triangles(self) -> np.ndarray:
        """(max id + 1,) int32: each triangle's row in the last sorted copy (once per sort)."""
        if self._rows is None:
            ids = self._sorted[0].view(np.int32)[:, REC_ID]
            rows = np.full(int(ids.max()) + 1 if ids.size else 0, -1, np.int32)
            rows[ids] = np.arange(ids.size, dtype=np.int32)
            self._rows = rows
        return self._rows


#: Keys from which :func:`stable_argsort` sorts the two halves on two threads (numpy's sort
#: releases the GIL): the casters of the 1M-triangle city sort in 24-44 ms, a tenth of a
#: frame's izb stage.
PARALLEL_SORT_MIN = 1 << 16


def stable_argsort(keys: np.ndarray) -> np.ndarray:
    """``np.argsort(keys, kind="stable")``, the halves sorted on two threads
    (:func:`~cityshade.runtime.threadpool.run_chunks`) and merged when there are two Numba threads and
    at least ``PARALLEL_SORT_MIN`` keys (the same order)."""
    n = keys.shape[0]
    if numba.get_num_threads() < 2 or n < max(PARALLEL_SORT_MIN, 2):
        return np.argsort(keys, kind="stable")
    bounds = (0, n // 2, n)
    halves: list = [None, None]
    run_chunks(_sort_halves, 2, 1, keys, bounds, halves)
    out = np.empty(n, halves[0].dtype)
    K.merge_orders(keys, halves[0], halves[1], out)
    return out


def _sort_halves(keys, bounds, halves, i0, i1):
    for half in range(i0, i1):
        a, b = bounds[half], bounds[half + 1]
        halves[half] = np.argsort(keys[a:b], kind="stable") + a


_CASTERS: "weakref.WeakKeyDictionary[KdTree, Casters]" = weakref.WeakKeyDictionary()


def casters_of(tree) -> Casters:
    """The :class:`Casters` of a tree, made once per tree and kept with it."""
    kd = tree_of(tree)
    c = _CASTERS.get(kd)
    if c is None:
        c = _CASTERS[kd] = Casters(kd)
    return c


def _choose_cell_m(boxes, xs, ys, box, ext_x, ext_y, n_max_cells):
    """Cell size (light-plane metres) of lowest estimated cost among :data:`CELL_FACTORS`.

    Per cell of a coarse grid over the receivers' box (``box`` x0, x1, y0, y1): its receivers
    R and casters M (by box centre). A candidate size s gives each caster (w/s + 1)(h/s + 1)
    references (:func:`refs_per_size`, summed: ``refs``); a
    coarse cell of area A then holds lists of refs * (M / M_all) * s^2 / A entries, scanned by
    each of its R receivers, and R spread at random over its A / s^2 cells occupy a fraction
    1 - exp(-R s^2 / A) of them (only occupied cells get references).
    """
    n = xs.shape[0]
    base = math.sqrt(ext_x * ext_y / max(n, 1))
    if base <= 0.0:
        base = max(ext_x, ext_y) / max(n, 1)
    sizes = np.array([base * f for f in CELL_FACTORS])
    coarse = math.sqrt(ext_x * ext_y / DENSITY_CELLS)
    cnx = max(1, min(DENSITY_CELLS, math.ceil(ext_x / coarse)))
    cny = max(1, min(DENSITY_CELLS, math.ceil(ext_y / coarse)))
    inv_c = 1.0 / max(ext_x / cnx, ext_y / cny)
    n_chunks = 4
    r_c = np.empty((n_chunks, cnx * cny))
    m_c = np.empty((n_chunks, cnx * cny))
    box_sums = np.empty((n_chunks, 3))
    K.density_grid(xs, ys, max(1, n // DENSITY_SAMPLE), boxes, box[0], box[2], inv_c, cnx, cny,
                   r_c, m_c, box_sums)
    refs = refs_per_size(box_sums, sizes)
    r_c = r_c.sum(axis=0)
    m_c = m_c.sum(axis=0)
    keep = (r_c > 0) & (m_c > 0)
    r_c = r_c[keep]
    m_frac = m_c[keep] / max(boxes.shape[0], 1)
    area_c = 1.0 / (inv_c * inv_c)
    cells = np.ceil(ext_x / sizes) * np.ceil(ext_y / sizes)
    fits = cells <= n_max_cells
    if not fits.any():
        return float(max(ext_x, ext_y) / math.sqrt(n_max_cells)) * 1.01
    sizes, refs, cells = sizes[fits], refs[fits], cells[fits]
    share = (sizes * sizes / area_c)[:, None]                  # (K, 1): cell area / coarse area
    per_cell = refs[:, None] * m_frac[None, :] * share          # list length per coarse cell
    occupied = -np.expm1(-r_c[None, :] * share)                 # fraction of its cells in use
    refs_used = (per_cell * occupied).sum(axis=1) / share[:, 0]
    scans = (per_cell * r_c[None, :]).sum(axis=1)
    cost = COST_REF_NS * refs_used + COST_SCAN_NS * scans + COST_CELL_NS * cells
    return float(sizes[int(np.argmin(cost))])


def refs_per_size(box_sums, cell_sizes_m) -> np.ndarray:
    """(K,) cell references the casters would make for each cell size: the sum over their
    boxes of ``(w / s + 1) (h / s + 1)``, from the chunks' sums of ``w h``, ``w + h`` and 1
    (:func:`~cityshade.lightspace.kernels.density_grid`), added chunk by chunk."""
    area = sides = count = 0.0
    for a, b, c in np.asarray(box_sums, np.float64):
        area, sides, count = area + a, sides + b, count + c
    inv = 1.0 / np.asarray(cell_sizes_m, np.float64)
    return area * inv * inv + sides * inv + count


def _key_sign(sz: float) -> float:
    """Sign of the casters' depth key for the shear's ``sz``: ``sgn`` of ``max_v sgn·v[kz]``."""
    return 1.0 if sz > 0.0 else -1.0


def caster_order(sun_direction) -> tuple[int, float]:
    """``(kz, sgn)`` of a sun direction: the casters' key order (:meth:`Casters.sorted_for`),
    which sorts them again whenever it changes from one call to the next."""
    # Asked per frame by ``exact``'s choice (shadows/exact.py): interpreted until izb compiled it.
    shear = twin_if(not compiled_or_cached(K.shear_of), K.shear_of)
    _, _, kz, _, _, sz = shear(np.ascontiguousarray(sun_direction, np.float64))
    return int(kz), _key_sign(sz)


def _unit_sun(sun_direction) -> np.ndarray:
    """The sun direction as a checked float64 (3,) unit vector."""
    sun = np.ascontiguousarray(sun_direction, dtype=np.float64)
    if sun.shape != (3,) or not np.isfinite(sun).all():
        raise TraceInputError(f"sun_direction must be a finite (3,) vector, not {sun!r}")
    if abs(float(np.sqrt(sun @ sun)) - 1.0) > UNIT_LENGTH_TOL:
        raise TraceInputError("sun_direction must be unit length")
    return sun


def occluded(tree, origins, sun_direction, t_days: float = 0.0, *, stats: dict | None = None,
             cell_m: float | None = None) -> np.ndarray:
    """Whether each shadow ray toward the sun hits a triangle present at ``t_days``.

    The same answer as ``cityshade.trace.occluded(tree, origins, broadcast(sun_direction),
    t_days)`` on every ray.

    Parameters
    ----------
    tree : KdTree
    origins : (N, 3) float array
        Shadow-ray origins, render-space metres (from
        :func:`cityshade.trace.shadow_rays_from_surface`).
    sun_direction : (3,) float array
        Unit direction toward the sun, shared by all rays.
    t_days : float
        City time, days since 1970-01-01 UTC.
    stats : dict, optional
        Filled with the grid, counts and per-stage seconds (a profile).
    cell_m : float, optional
        Force the grid's cell size (light-plane metres) instead of the cost model (benchmarks).

    Returns
    -------
    (N,) bool array, True where the ray ``[0, inf)`` is blocked.

    Raises
    ------
    TraceInputError
        Wrong shapes, non-finite values, a non-unit sun direction, a NaN time.
    """
    kd = tree_of(tree)
    origins = np.ascontiguousarray(origins, dtype=np.float64)
    if origins.ndim != 2 or origins.shape[1] != 3:
        raise TraceInputError(f"origins must have shape (N, 3), not {origins.shape}")
    sun = _unit_sun(sun_direction)
    t = float(t_days)
    if math.isnan(t):
        raise TraceInputError("t_days must be a number of days since 1970-01-01, not NaN")
    n = origins.shape[0]
    out = np.zeros(n, np.bool_)
    if n == 0 or kd.tri_records.shape[0] == 0:
        return out
    casters = casters_of(kd)
    ws = casters.scratch.take()
    try:
        with one_thread_when_small(n + kd.tri_records.shape[0], SINGLE_THREAD_WORK):
            return _occluded(kd, casters, ws, origins, sun, t, out, stats, cell_m,
                             kd in _LAST_CALLS)
    finally:
        if kd in _LAST_CALLS:
            ws.clear()
        ws.give_back()


def casters_ready(tree, kz: int, sgn: float) -> bool:
    """Whether this process already holds the tree's casters sorted for the key order
    ``(kz, sgn)`` (:func:`caster_order`): a call then pays no gathering or sort."""
    c = _CASTERS.get(tree_of(tree))
    return c is not None and c._axis == (kz, sgn)


#: Trees whose calls drop their work arrays when they return (:func:`last_calls`).
_LAST_CALLS: "weakref.WeakSet[KdTree]" = weakref.WeakSet()


@contextlib.contextmanager
def last_calls(tree):
    """Within the block, each :func:`occluded` call on ``tree``'s kd-tree (a scene's) lets its
    work arrays go when it returns instead of keeping them for the next sun (a one-frame
    render: the 1M city's map holds 0.25 GB less while its shadow pass finishes and shades),
    and each array and the sorted casters as soon as it has read them for the last time (the
    call's peak: 75 MB less); another call on the tree sorts the casters again."""
    kd = getattr(tree, "kdtree", tree)
    if not isinstance(kd, KdTree):
        yield
        return
    _LAST_CALLS.add(kd)
    try:
        yield
    finally:
        _LAST_CALLS.discard(kd)


def forget_casters(tree) -> None:
    """Drop the :class:`Casters` (sorted copy and work arrays) kept with a tree or scene, for
    a caller done with its suns (a one-frame render before it writes: 0.7 GB at 10^7)."""
    kd = getattr(tree, "kdtree", tree)
    if isinstance(kd, KdTree):
        _CASTERS.pop(kd, None)


def _occluded(kd, casters, ws, origins, sun, t, out, stats, cell_m, last):
    """The engine behind :func:`occluded` on validated inputs, work arrays from ``ws``; fills and
    returns ``out``. A ``last`` call (:func:`last_calls`) lets each array go after its last
    read instead of keeping it for the next sun."""
    n = origins.shape[0]
    timing = {}
    t0 = time.perf_counter()
    kx, ky, kz, sx, sy, sz = K.shear_of(sun)
    sgn = _key_sign(sz)
    recs, keys = casters.sorted_for(kz, sgn)
    timing["sort_s"] = time.perf_counter() - t0

    # Project the receivers; their light-plane box and lowest key bound the casters.
    t0 = time.perf_counter()
    n_chunks = max(1, numba.get_num_threads())
    # Work arrays share memory with later ones once they are read for the last time (the 1M
    # city's map: 116 MB less at the peak): the light-plane points with the receivers' origins
    # in cell order (gathered once the casters are packed), the culled boxes with the cell
    # ranges and then the packed casters.
    xy = ws.get("rec_origins", 3 * n)
    xs, ys, rkeys = xy[:n], xy[n:2 * n], xy[2 * n:]
    part = np.empty((n_chunks, K.N_STATS))
    K.project_receivers(origins, kx, ky, kz, sx, sy, sgn, n_chunks, xs, ys, rkeys, part)
    if part[:, 5].sum() > 0:
        raise TraceInputError("ray origins contain NaN or infinite values")
    box = np.array([part[:, 0].min(), part[:, 1].max(), part[:, 2].min(), part[:, 3].max()])
    min_key = float(part[:, 4].min())
    scale = max(float(np.abs(kd.bounds[:, :3]).max()), float(np.abs(box).max()), 1.0)
    margin_m = MARGIN_REL * scale
    rows = _near_rows(kd, casters, box, min_key, (kx, ky, kz, sx, sy, sgn), t)
    if rows is not None:
        # The same casters in the same (key) order as the scan's, less some that cannot
        # shade a receiver: the cull below keeps what the scan would of them.
        recs, keys = recs[rows], keys[rows]
    # Receiver occupancy: a caster whose (widened) box holds no receiver point cannot shade
    # one, and the box's coarse cells then hold none either (cells are monotone in x, y).
    occ = math.sqrt(max(box[1] - box[0], 1e-9 * scale) * max(box[3] - box[2], 1e-9 * scale)
                    / max(1, min(n, OCCUPANCY_CELLS)))
    onx = max(1, min(OCCUPANCY_CELLS, math.ceil((box[1] - box[0]) / occ)))
    ony = max(1, min(OCCUPANCY_CELLS // onx, math.ceil((box[3] - box[2]) / occ)))
    occ_inv = 1.0 / max((box[1] - box[0]) / onx, (box[3] - box[2]) / ony, 1e-9 * scale)
    occupied = ws.get("occupied", (ony + 1, onx + 1), np.int32)
    K.occupancy_table(xs, ys, box[0], box[2], occ_inv, onx, ony, occupied)
    # The casters a chunk at a time: the box work array stays small.
    n_recs = recs.shape[0]
    chunk_boxes = ws.get("ranges", (max(1, min(n_recs, CULL_ROWS)), 4))
    parts = []
    for c0 in range(0, n_recs, CULL_ROWS):
        c1 = min(n_recs, c0 + CULL_ROWS)
        b = chunk_boxes[:c1 - c0]
        K.cull_casters(recs[c0:c1], recs[c0:c1].view(np.float64), keys[c0:c1], t, kx, ky, kz,
                       sx, sy, margin_m, box, min_key, b)
        K.cull_unoccupied(b, box[0], box[2], occ_inv, onx, ony, occupied)
        local = np.flatnonzero(~np.isnan(b[:, 0]))
        if local.size:
            # One chunk (up to 10^6 casters) keeps its boxes in the work array; more chunks
            # keep their kept boxes, since the next chunk reuses it.
            parts.append((c0, c1, local, None if n_recs <= CULL_ROWS else b[local]))
    kept_size = sum(p[2].size for p in parts)
    kept_boxes = ws.get("kept_boxes", (kept_size, 4))
    q = 0
    for c0, c1, local, local_boxes in parts:   # in key order, as one pass would
        if local_boxes is None:
            K.gather_rows(chunk_boxes[:c1 - c0], local, kept_boxes[q:q + local.size])
        else:
            kept_boxes[q:q + local.size] = local_boxes
        q += local.size
    b = chunk_boxes = None        # their memory takes the cell ranges, then the packed casters
    timing["project_s"] = time.perf_counter() - t0

    # Grid over the receivers' box, cell size from the counts.
    t0 = time.perf_counter()
    ext_x, ext_y = max(box[1] - box[0], 1e-9 * scale), max(box[3] - box[2], 1e-9 * scale)
    max_cells = max(MAX_CELLS_PER_RECEIVER * n, 1024)
    size = (float(cell_m) if cell_m else
            _choose_cell_m(kept_boxes, xs, ys, box, ext_x, ext_y, max_cells))
    nx, ny = max(1, math.ceil(ext_x / size)), max(1, math.ceil(ext_y / size))
    inv = 1.0 / size
    # Called again (a batch's suns, a sky's directions), the origins are ordered by cell as the
    # receivers are binned; a last call orders them once the casters are packed (less memory).
    rec_start, rec_order, ref_start, refs, dest, n_cells, rec_origins = bin_grid(
        ws, xs, ys, kept_boxes, box[0], box[2], inv, nx, ny, n_chunks, True,
        None if last else origins)
    del xs, ys, rkeys, xy         # their memory takes the ordered origins
    if last:
        ws.drop("rec_origins")    # the 1M city's map: 63 MB less while the casters are packed
    n_refs = refs.size
    packed = ws.get("ranges", (kept_size, K.PACK_WORDS), np.float32)   # ranges are done
    q = 0
    for c0, c1, local, _ in parts:
        K.pack_casters(recs[c0:c1], keys[c0:c1], kept_boxes[q:q + local.size], local,
                       dest[q:q + local.size], kx, ky, kz, sx, sy, sgn, scale, packed)
        q += local.size
    del parts, recs, keys, kept_boxes, dest
    if last:   # the query reads only the packed casters: the sorted copy and the boxes go
        # before the ordered origins come (the 1M city's map: 87 MB less at the peak)
        ws.drop("kept_boxes", "dest")
        casters.forget_sorted()
    if rec_origins is None:
        rec_origins = ordered_origins(ws, origins, rec_order)
    timing["bin_s"] = time.perf_counter() - t0

    # Test each receiver against its cell's casters, nearest-to-the-sun first.
    t0 = time.perf_counter()
    n_tiles = n_cells // K.TILE_CELLS
    tests = np.zeros(n_tiles, np.int64)
    hit_sorted = ws.get("hit_sorted", n, np.bool_)
    run_chunks(K.query, n_tiles, K.QUERY_CHUNK_TILES, packed, ref_start, refs, rec_start,
               rec_origins, kx, ky, kz, sx, sy, sz, sgn,
               DEPTH_MARGIN_M + DEPTH_MARGIN_REL * scale, 0.0, np.inf, hit_sorted, tests)
    K.scatter_back(rec_order, hit_sorted, out)
    timing["query_s"] = time.perf_counter() - t0
    if stats is not None:
        stats.update(timing)
        stats.update(receivers=n, casters=int(kept_size),
                     grid=(nx, ny), cell_m=size, references=int(n_refs),
                     walked_casters=-1 if rows is None else int(rows.size),
                     tests=int(tests.sum()), occluded=int(out.sum()))
    return out


def bin_grid(ws, xs, ys, boxes, x0, y0, inv, nx, ny, n_chunks, tile_ordered, origins=None):
    """Receivers and casters binned into one grid (``nx`` by ``ny`` cells of ``1 / inv`` from
    ``(x0, y0)``, numbered tile by tile: :func:`~cityshade.lightspace.kernels.tile_cell`), work
    arrays from the :class:`~cityshade.runtime.memory.Scratch` ``ws``. Returns ``rec_start``
    (cells + 1,) and ``rec_order`` the receivers grouped by cell (receiver order inside a
    cell; their origins in that order: :func:`ordered_origins`); ``ref_start`` (cells + 1,)
    and ``refs`` each cell's casters in row order, only in cells holding a receiver, as the
    rows ``dest`` the casters (rows of ``boxes``, NaN in column 0 for a culled one) get in the
    packed array: with ``tile_ordered`` the order of their first tile
    (:func:`~cityshade.lightspace.kernels.tile_order`, the opaque query's), else their own
    rows; the number of cells; and with ``origins`` (N, 3) the receivers' origins in cell
    order in ``ws``'s array ``rec_origins`` (whose memory ``xs`` and ``ys`` may share: they
    are read before it is written), else None. The same lists whatever the thread count. The
    casters' cell
    ranges are ``ws``'s array ``ranges`` (a caller may have used its memory for an array it is
    done with, or use it after); the receivers' cells share theirs with ``refs``."""
    n = xs.shape[0]
    ntx, n_cells = K.tiled_cells(nx, ny)
    # int32 cells while they fit: the buffer then takes the int32 references (10 MB less).
    cells = ws.get("cells", n, np.int32 if n_cells < 2 ** 31 else np.int64)
    K.receiver_cells(xs, ys, x0, y0, inv, inv, nx, ny, cells)
    counts = ws.get("counts", (n_chunks, n_cells), np.int32)
    K.count_receivers(cells, counts)
    rec_start = ws.get("rec_start", n_cells + 1, np.int64)
    K.prefix_sum(counts, rec_start)
    rec_order = ws.get("rec_order", n, np.int32)
    rec_origins = None if origins is None else ws.get("rec_origins", (n, 3))
    K.order_receivers(cells, counts, np.empty((0, 3)) if origins is None else origins,
                      rec_order, np.empty((0, 3)) if rec_origins is None else rec_origins)
    m = boxes.shape[0]
    ranges = ws.get("ranges", (m, 4), np.int64)
    K.caster_ranges(boxes, x0, y0, inv, inv, nx, ny, ranges)
    dest = ws.get("dest", m, np.int32)
    if tile_ordered:
        tile_counts = ws.get("tile_counts", (n_chunks, n_cells // K.TILE_CELLS), np.int32)
        K.tile_order(ranges, ntx, tile_counts, False, dest)
        K.prefix_sum(tile_counts, ws.get("tile_start", n_cells // K.TILE_CELLS + 1, np.int64))
        K.tile_order(ranges, ntx, tile_counts, True, dest)
    else:
        dest[:] = np.arange(m, dtype=np.int32)
    refs = np.empty(0, np.int32)
    K.scatter_casters(ranges, rec_start, nx, counts, dest, refs, False)
    ref_start = ws.get("ref_start", n_cells + 1, np.int64)
    n_refs = K.prefix_sum(counts, ref_start)
    del cells        # filled in: the references take its memory
    refs = ws.get("cells", n_refs, np.int32)
    K.scatter_casters(ranges, rec_start, nx, counts, dest, refs, True)
    return rec_start, rec_order, ref_start, refs, dest, n_cells, rec_origins


def ordered_origins(ws, origins, rec_order):
    """``origins[rec_order]`` (the receivers' origins in cell order, read sequentially by the
    query) in ``ws``'s array ``rec_origins``."""
    out = ws.get("rec_origins", (rec_order.size, 3))
    K.gather_rows(origins, rec_order, out)
    return out


def _near_rows(kd, casters, box, min_key, shear, t_days: float):
    """Sorted rows (ascending, int32) of the casters a kd-tree walk finds in the region that
    can shade the receivers, or None when a scan of all casters is the cheaper way.

    The region is the receivers' light-plane box ``box`` swept sunward from the lowest
    receiver key: a ray from a receiver meets a caster only at a point of that prism, which
    lies in a leaf the walk keeps (planes padded by :data:`FRUSTUM_PAD_REL` of the scene size,
    far beyond rounding). A caster the walk leaves out is one the query could not find a hit
    with, so the answer is the scan's bit for bit.
    """
    from cityshade.raster import culling as cull
    from cityshade.raster.triangles import CulledWalk

    if casters.first.size < NEAR_MIN_CASTERS:
        return None
    kx, ky, kz, sx, sy, sgn = shear
    lo, hi, size = kd.box_scale_m()
    corners = np.array([[a, b, c] for a in (lo[0], hi[0]) for b in (lo[1], hi[1])
                        for c in (lo[2], hi[2])])
    u = corners[:, kx] - sx * corners[:, kz]
    v = corners[:, ky] - sy * corners[:, kz]
    whole = (u.max() - u.min()) * (v.max() - v.min())
    part = (max(0.0, min(box[1], u.max()) - max(box[0], u.min()))
            * max(0.0, min(box[3], v.max()) - max(box[2], v.min())))
    if not part <= NEAR_AREA_SHARE * whole:
        return None
    pad = cull.FRUSTUM_PAD_REL * size
    planes = np.zeros((5, 4))
    for i, (axis, shear_k, lo_b, hi_b) in enumerate(((kx, sx, box[0], box[1]),
                                                      (ky, sy, box[2], box[3]))):
        normal = np.zeros(3)
        normal[axis] = 1.0
        normal[kz] = -shear_k
        length = float(np.sqrt(normal @ normal))
        # lo_b - pad <= n . p <= hi_b + pad, as two planes n' . p + d >= 0 with unit n'.
        planes[2 * i, :3], planes[2 * i, 3] = normal / length, (pad - lo_b) / length
        planes[2 * i + 1, :3], planes[2 * i + 1, 3] = -normal / length, (hi_b + pad) / length
    planes[4, kz] = sgn
    planes[4, 3] = pad - min_key
    order = np.zeros(4)
    order[kz] = sgn  # sunward first (any order gives the same set)
    walk = CulledWalk(kd, float(t_days), planes, order, casters.rows_of_triangles().size)
    found = []
    while not walk.done:
        found.append(kd.prim_indices[walk.next()])
    tris = np.concatenate(found) if found else np.zeros(0, np.int32)
    rows = casters.rows_of_triangles()[tris]
    rows.sort()
    return rows


def sunlit(tree, points, normals, sun_direction, t_days: float = 0.0, *,
           stats: dict | None = None) -> np.ndarray:
    """Whether each surface point sees the sun: :func:`cityshade.trace.sunlit`'s answer (same
    ray origins, same test) through the light-space engine.

    Parameters
    ----------
    tree : KdTree
    points, normals : (N, 3) float arrays
        Surface points (render space, metres) and unit normals on the side facing the sun.
    sun_direction : (3,) float array
        Unit direction toward the sun.
    t_days : float
        City time.
    stats : dict, optional
        Profile of the run (:func:`occluded`).

    Returns
    -------
    (N,) bool array, True where nothing blocks the sun.
    """
    origins = shadow_rays_from_surface(points, normals, sun_direction)
    return ~occluded(tree, origins, sun_direction, t_days, stats=stats)


class SurfaceReceivers:
    """Surface points whose shadow rays are traced for many suns (a batch: the points and
    normals never change, only which of them face the sun and the origins' step toward it).

    Checks the points and normals once and keeps them with their offsets
    (:func:`cityshade.trace.shadow_offset_m`); :meth:`origins` then gives, per sun, exactly
    ``shadow_rays_from_surface(points[select], normals[select], sun)`` from one parallel pass
    instead of numpy's gathers and temporaries.

    Parameters
    ----------
    points, normals : (N, 3) float arrays
        Surface points (render space, metres) and their unit normals on the side the ray
        leaves from.

    Raises
    ------
    TraceInputError
        Wrong shapes, non-finite values, non-unit normals.
    """

    def __init__(self, points, normals):
        points = np.ascontiguousarray(points, dtype=np.float64)
        normals = np.ascontiguousarray(normals, dtype=np.float64)
        shadow_rays_from_surface(points, normals, (0.0, 0.0, 1.0))  # its checks, once
        self.points = points
        self.normals = normals
        self.offsets_m = np.ascontiguousarray(shadow_offset_m(points))
        self._out = np.empty((0, 3))

    def __len__(self) -> int:
        return self.points.shape[0]

    def origins(self, sun_direction, select=None) -> np.ndarray:
        """(M, 3) shadow-ray origins of the selected points (a bool mask (N,) or indices; all
        when None) toward ``sun_direction`` (unit (3,)). The array is reused by the next call."""
        sun = _unit_sun(sun_direction)
        n = len(self)
        if select is None:
            index = np.arange(n, dtype=np.int64)
        else:
            select = np.asarray(select)
            index = np.flatnonzero(select) if select.dtype == np.bool_ else select.astype(np.int64)
        if self._out.shape[0] < index.size:
            self._out = np.empty((index.size, 3))
        out = self._out[:index.size]
        K.surface_origins(self.points, self.normals, self.offsets_m, index, sun, out)
        return out
