"""Numba kernels of the light-space sun engine: project, bin, query (DESIGN §6b).

All rays of one sun share the direction d, so the watertight test's permutation and shear
(:func:`cityshade.trace.kernels.ray_shear`: axes kx, ky, kz and sx, sy, sz) are the same for
every receiver. In the sheared frame a ray from o hits a triangle only where o's light-plane
point ``(o[kx] - sx o[kz], o[ky] - sy o[kz])`` lies in the triangle's projection, so the
triangles are binned into a 2-D grid over the receivers' light-plane box and each receiver is
tested against its cell's list only, with the same :func:`~cityshade.trace.kernels.hit_record`
on the same float32 records, origin values and segment limits as the ``raytrace`` any-hit
kernel: the decision is the same bit for bit once the list holds every triangle that test could
accept (conservative binning, below).

Two exact facts make the lists short and safe:

* Depth: ``hit_record``'s distance is a convex combination of the vertices' ``(v[kz] - o[kz])
  * sz`` computed with sign-exact float operations, so a triangle whose vertices all have
  ``sgn * v[kz] < sgn * o[kz]`` (``sgn`` the sign of d[kz]) gives t < 0 and can never shade o.
  Casters are sorted by ``key = max_v sgn * v[kz]`` (descending) and a receiver stops at the
  first key below its own ``sgn * o[kz]``: lit receivers stop early too.
* Binning: a triangle goes into every cell its light-plane box widened by ``margin_m`` touches;
  the cell index is a monotone float function of the coordinate, so a receiver inside the
  widened box lands in a cell of the triangle's range. ``margin_m`` covers the difference
  between the binning projection ``v[kx] - sx v[kz]`` and the kernel's ``(v[kx] - o[kx]) -
  sx (v[kz] - o[kz])`` (a few ulps of the coordinate magnitude) with a wide margin.

Lists are built by a count pass, a prefix sum and a fill pass over fixed chunks of the casters
(each chunk writes its own slice of every cell), so every cell's list is in caster order,
hence sorted by key, whatever the thread count.
"""
from __future__ import annotations

import numpy as np
from numba import njit, prange

from cityshade.accel.kdtree_layout import REC_T_BEGIN64, REC_T_END64
from cityshade.trace.bricks import stripe_interleave
from cityshade.trace.kernels import hit_record, ray_shear

#: Statistics columns of :func:`project_receivers`: light-plane box, lowest depth key, count of
#: non-finite origins.
N_STATS = 6


@njit(cache=True)
def shear_of(sun_direction):
    """``(kx, ky, kz, sx, sy, sz)`` of the watertight test for the sun direction (3,)."""
    return ray_shear(sun_direction[0], sun_direction[1], sun_direction[2])


@njit(cache=True, parallel=True)
def project_receivers(origins, kx, ky, kz, sx, sy, sgn, n_chunks, out_x, out_y, out_key,
                      stats):
    """Light-plane point and depth key of every ray origin, and per-chunk box statistics.

    ``origins`` (N, 3) float64; writes ``out_x, out_y, out_key`` (N,) float64 and ``stats``
    (n_chunks, 6): min x, max x, min y, max y, min key of the chunk (inf/-inf when empty) and
    the number of origins with a non-finite coordinate (checked here, not in a numpy pass).
    """
    n = origins.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        x0 = np.inf
        x1 = -np.inf
        y0 = np.inf
        y1 = -np.inf
        k0 = np.inf
        bad = 0
        for i in range(c * per, min(n, (c + 1) * per)):
            okz = origins[i, kz]
            x = origins[i, kx] - sx * okz
            y = origins[i, ky] - sy * okz
            key = sgn * okz
            if not (abs(origins[i, 0]) < np.inf and abs(origins[i, 1]) < np.inf
                    and abs(okz) < np.inf):
                bad += 1
            out_x[i] = x
            out_y[i] = y
            out_key[i] = key
            x0 = min(x0, x)
            x1 = max(x1, x)
            y0 = min(y0, y)
            y1 = max(y1, y)
            k0 = min(k0, key)
        stats[c, 0] = x0
        stats[c, 1] = x1
        stats[c, 2] = y0
        stats[c, 3] = y1
        stats[c, 4] = k0
        stats[c, 5] = bad


@njit(cache=True, parallel=True)
def surface_origins(points, normals, offsets_m, index, sun, out):
    """``out[q] = points[i] + (normals[i] + sun) * offsets_m[i]`` for ``i = index[q]``: the
    shadow-ray origins of :func:`cityshade.trace.shadow_rays_from_surface`, the same float64
    operations in the same order (bit for bit), for the selected points only."""
    for q in prange(index.shape[0]):
        i = index[q]
        off = offsets_m[i]
        for a in range(3):
            out[q, a] = points[i, a] + (normals[i, a] + sun[a]) * off


@njit(cache=True, parallel=True)
def caster_keys(recs, kz, sgn, out_key):
    """Depth key ``max_v sgn * v[kz]`` of every record (float32 vertices, exact in float64)."""
    for j in prange(recs.shape[0]):
        a = sgn * np.float64(recs[j, kz])
        b = sgn * np.float64(recs[j, 3 + kz])
        c = sgn * np.float64(recs[j, 6 + kz])
        out_key[j] = max(a, max(b, c))


@njit(cache=True, parallel=True)
def cull_casters(recs, recs_f64, keys, t_days, kx, ky, kz, sx, sy, margin_m, box, min_key,
                 out_box):
    """Light-plane box of each caster that can shade a receiver, else NaN in ``out_box[j, 0]``.

    A caster is kept when it stands at ``t_days`` (``begin <= t < end``, the kernel's rule), its
    key reaches the lowest receiver key and its box widened by ``margin_m`` overlaps ``box``
    (x0, x1, y0, y1). ``out_box`` (M, 4): x0, x1, y0, y1 widened by the margin.
    """
    for j in prange(recs.shape[0]):
        out_box[j, 0] = np.nan
        if not (recs_f64[j, REC_T_BEGIN64] <= t_days < recs_f64[j, REC_T_END64]):
            continue
        if keys[j] < min_key:
            continue
        x0 = np.inf
        x1 = -np.inf
        y0 = np.inf
        y1 = -np.inf
        for v in range(3):
            vz = np.float64(recs[j, 3 * v + kz])
            x = np.float64(recs[j, 3 * v + kx]) - sx * vz
            y = np.float64(recs[j, 3 * v + ky]) - sy * vz
            x0 = min(x0, x)
            x1 = max(x1, x)
            y0 = min(y0, y)
            y1 = max(y1, y)
        x0 -= margin_m
        x1 += margin_m
        y0 -= margin_m
        y1 += margin_m
        if x1 < box[0] or x0 > box[1] or y1 < box[2] or y0 > box[3]:
            continue
        out_box[j, 0] = x0
        out_box[j, 1] = x1
        out_box[j, 2] = y0
        out_box[j, 3] = y1


#: Columns of the packed caster records (:func:`pack_casters`): the vertices where
#: :func:`hit_record` reads them, then the depth key, the light-plane box and the depth plane,
#: so a candidate is read from one record.
PACK_KEY = 9
PACK_BOX = 10
PACK_PLANE = 14
PACK_WORDS = 17
#: Relative widening when the float64 box is stored as float32 (rounding is 2^-24 relative).
_F32_WIDEN = 2.0 ** -22
#: The depth plane is used only for casters of decent shape in the light plane: box
#: diagonal² / |2 area| <= 2^20, so hit_record's distance (a convex combination with weights
#: of absolute error <= ~12 eps diagonal² / |2 area|) is within ~4e-9 relative of the plane's.
_PLANE_MAX_ASPECT = 2.0 ** 20
#: Each plane is moved sunward by this fraction of its own terms' magnitudes, which bounds the
#: float32 rounding of its coefficients (2^-24 each) with a wide margin.
_PLANE_WIDEN = 2.0 ** -21


@njit(cache=True, parallel=True)
def pack_casters(recs, keys, boxes, kept, kx, ky, kz, sx, sy, sgn, out, out_boxes):
    """(len(kept), PACK_WORDS) float32 records of the kept casters, in key order: columns 0-8
    the vertices (as in the tree's records), ``PACK_KEY`` the key (float32 values, exact),
    ``PACK_BOX`` .. +3 the light-plane box rounded outward to float32, ``PACK_PLANE`` .. +2 the
    depth plane ``sgn * z = key + c + a (x - box x0) + b (y - box y0)`` as (a, b, c), moved
    sunward by its rounding bound, or (0, 0, +inf) where the plane is not trusted (never
    skips). ``out_boxes`` (len(kept), 4) gets the float64 boxes of the kept casters."""
    for q in prange(kept.shape[0]):
        j = kept[q]
        for c in range(4):
            out_boxes[q, c] = boxes[j, c]
        for c in range(9):
            out[q, c] = recs[j, c]
        out[q, PACK_KEY] = keys[j]
        for c in range(4):
            b = boxes[j, c]
            w = abs(b) * _F32_WIDEN + 2.0 ** -40
            out[q, PACK_BOX + c] = b - w if c % 2 == 0 else b + w
        # Depth plane through the three projected vertices (float64, vertex 0 as origin).
        z0 = sgn * np.float64(recs[j, kz])
        x0 = np.float64(recs[j, kx]) - sx * np.float64(recs[j, kz])
        y0 = np.float64(recs[j, ky]) - sy * np.float64(recs[j, kz])
        z1 = sgn * np.float64(recs[j, 3 + kz]) - z0
        x1 = np.float64(recs[j, 3 + kx]) - sx * np.float64(recs[j, 3 + kz]) - x0
        y1 = np.float64(recs[j, 3 + ky]) - sy * np.float64(recs[j, 3 + kz]) - y0
        z2 = sgn * np.float64(recs[j, 6 + kz]) - z0
        x2 = np.float64(recs[j, 6 + kx]) - sx * np.float64(recs[j, 6 + kz]) - x0
        y2 = np.float64(recs[j, 6 + ky]) - sy * np.float64(recs[j, 6 + kz]) - y0
        det = x1 * y2 - y1 * x2
        bw = boxes[j, 1] - boxes[j, 0]
        bh = boxes[j, 3] - boxes[j, 2]
        pa = 0.0
        pb = 0.0
        pc = np.inf
        if det != 0.0 and (bw * bw + bh * bh) <= _PLANE_MAX_ASPECT * abs(det):
            pa = (z1 * y2 - z2 * y1) / det
            pb = (x1 * z2 - x2 * z1) / det
            bx0 = np.float64(out[q, PACK_BOX])
            by0 = np.float64(out[q, PACK_BOX + 2])
            pc = z0 + pa * (bx0 - x0) + pb * (by0 - y0) - keys[j]
            pc += _PLANE_WIDEN * (abs(pa) * (bw + 1.0) + abs(pb) * (bh + 1.0) + abs(pc)
                                  + abs(keys[j]))
        out[q, PACK_PLANE] = pa
        out[q, PACK_PLANE + 1] = pb
        out[q, PACK_PLANE + 2] = pc


@njit(cache=True, parallel=True)
def estimate_refs(boxes, cell_sizes_m):
    """Cell references the kept casters would make for each candidate cell size (K,)."""
    n_k = cell_sizes_m.shape[0]
    n = boxes.shape[0]
    n_chunks = 64
    per = (n + n_chunks - 1) // n_chunks
    part = np.zeros((n_chunks, n_k))
    for c in prange(n_chunks):
        for j in range(c * per, min(n, (c + 1) * per)):
            if np.isnan(boxes[j, 0]):
                continue
            w = boxes[j, 1] - boxes[j, 0]
            h = boxes[j, 3] - boxes[j, 2]
            for k in range(n_k):
                part[c, k] += (w / cell_sizes_m[k] + 1.0) * (h / cell_sizes_m[k] + 1.0)
    return part.sum(axis=0)


@njit(cache=True, inline="always")
def _cell(v, v0, inv, n):
    """Monotone cell index of coordinate v along one grid axis, clamped to [0, n - 1]."""
    c = np.floor((v - v0) * inv)
    if c < 0.0:
        return 0
    if c > n - 1:
        return n - 1
    return np.int64(c)


@njit(cache=True, parallel=True)
def receiver_cells(xs, ys, x0, y0, inv_x, inv_y, nx, ny, out_cell):
    """Grid cell of each receiver (row-major, ``iy * nx + ix``)."""
    for i in prange(xs.shape[0]):
        out_cell[i] = _cell(ys[i], y0, inv_y, ny) * nx + _cell(xs[i], x0, inv_x, nx)


@njit(cache=True, parallel=True)
def caster_ranges(boxes, x0, y0, inv_x, inv_y, nx, ny, out_range):
    """Cell range ix0, ix1, iy0, iy1 of each kept caster box (-1 in column 0 when culled)."""
    for j in prange(boxes.shape[0]):
        if np.isnan(boxes[j, 0]):
            out_range[j, 0] = -1
            continue
        out_range[j, 0] = _cell(boxes[j, 0], x0, inv_x, nx)
        out_range[j, 1] = _cell(boxes[j, 1], x0, inv_x, nx)
        out_range[j, 2] = _cell(boxes[j, 2], y0, inv_y, ny)
        out_range[j, 3] = _cell(boxes[j, 3], y0, inv_y, ny)


@njit(cache=True, parallel=True)
def count_receivers(cells, out_counts):
    """``out_counts`` (n_chunks, n_cells) int32 (any content; each chunk clears its own row):
    receivers per cell in each fixed chunk of receivers."""
    n = cells.shape[0]
    n_chunks = out_counts.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        out_counts[c, :] = 0
        for i in range(c * per, min(n, (c + 1) * per)):
            out_counts[c, cells[i]] += 1


@njit(cache=True, parallel=True)
def scatter_casters(ranges, rec_start, nx, cursor, out_refs, fill):
    """Count pass (``fill`` False: ``cursor`` (n_chunks, n_cells) int32, any content, gets the
    references per cell of each fixed chunk of casters; each chunk clears its own row first) or fill pass (``fill`` True: ``cursor`` holds the
    write positions of :func:`prefix_sum` and ``out_refs`` gets the caster indices, in caster =
    key order inside a cell). Only cells holding a receiver (``rec_start`` (n_cells + 1,), the
    receivers' list starts) get references.
    """
    n = ranges.shape[0]
    n_chunks = cursor.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        if not fill:
            cursor[c, :] = 0
        for j in range(c * per, min(n, (c + 1) * per)):
            if ranges[j, 0] < 0:
                continue
            for iy in range(ranges[j, 2], ranges[j, 3] + 1):
                row = iy * nx
                for ix in range(ranges[j, 0], ranges[j, 1] + 1):
                    cell = row + ix
                    if rec_start[cell + 1] > rec_start[cell]:
                        if fill:
                            out_refs[cursor[c, cell]] = j
                        cursor[c, cell] += 1


@njit(cache=True)
def prefix_sum(counts, out_start):
    """Turn ``counts`` (n_chunks, n_cells) into each chunk's write cursor, cell-major (cell 0's
    chunks first), and ``out_start`` (n_cells + 1,) into the cells' list starts."""
    n_chunks, n_cells = counts.shape
    total = 0
    for cell in range(n_cells):
        out_start[cell] = total
        for c in range(n_chunks):
            n = counts[c, cell]
            counts[c, cell] = total
            total += n
    out_start[n_cells] = total
    return total


@njit(cache=True, parallel=True)
def fill_receivers(cells, cursor, origins, out_order, out_origins):
    """Receiver indices grouped by cell (receiver order inside a cell) and their origins in
    that order, so the query reads receivers sequentially."""
    n = cells.shape[0]
    n_chunks = cursor.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        for i in range(c * per, min(n, (c + 1) * per)):
            cell = cells[i]
            q = cursor[c, cell]
            out_order[q] = i
            out_origins[q, 0] = origins[i, 0]
            out_origins[q, 1] = origins[i, 1]
            out_origins[q, 2] = origins[i, 2]
            cursor[c, cell] += 1


@njit(cache=True, parallel=True)
def scatter_back(order, sorted_values, out):
    """``out[order[q]] = sorted_values[q]``: results in cell order back to receiver order."""
    for q in prange(order.shape[0]):
        out[order[q]] = sorted_values[q]


@njit(cache=True, inline="always")
def _may_hit(packed, j, rx, ry, rkey, depth_margin_m):
    """False only when caster ``j`` cannot hit the receiver at light-plane ``(rx, ry)`` with key
    ``rkey``: outside its widened box (the binning argument), behind its own key, or behind
    its depth plane by more than ``depth_margin_m`` (see :func:`pack_casters`): t < 0."""
    if np.float64(packed[j, PACK_KEY]) < rkey:
        return False
    if (rx < packed[j, PACK_BOX] or rx > packed[j, PACK_BOX + 1]
            or ry < packed[j, PACK_BOX + 2] or ry > packed[j, PACK_BOX + 3]):
        return False
    zp = (np.float64(packed[j, PACK_KEY]) + np.float64(packed[j, PACK_PLANE + 2])
          + np.float64(packed[j, PACK_PLANE]) * (rx - packed[j, PACK_BOX])
          + np.float64(packed[j, PACK_PLANE + 1]) * (ry - packed[j, PACK_BOX + 2]))
    return zp >= rkey - depth_margin_m


#: Cells per parallel work item of the query: neighbouring cells share casters, so a block
#: keeps its last-occluder cache warm; small enough for the two cores to balance.
QUERY_BLOCK_CELLS = 64
#: Stripes of the block interleave (as in :mod:`cityshade.trace.bricks`, but few): each thread
#: takes part of every stripe so the cores finish together, and consecutive blocks of a stripe
#: are neighbouring cells whose casters (sorted by key, i.e. along the shear axis) are close in
#: memory; many stripes would spread one thread's working set over the whole caster array.
QUERY_STRIPES = 8


@njit(cache=True, parallel=True)
def query(packed, ref_start, refs, rec_start, origins, kx, ky, kz, sx, sy, sz, sgn,
          depth_margin_m, tmin, tmax, out, out_tests):
    """``out[q]`` (every entry written) True when the shadow ray of receiver q (in cell order)
    hits a caster of its cell.

    ``packed`` (M, 16) float32 caster records of :func:`pack_casters` sorted by key
    (descending), ``refs`` the cells' caster lists (``ref_start`` (n_cells + 1,)),
    ``origins`` the receivers' origins grouped by cell (``rec_start``). A receiver outside a caster's
    widened box is outside the triangle (the binning argument), so the box check only skips
    tests that cannot hit; so does the depth plane: a caster whose plane lies more than
    ``depth_margin_m`` behind the receiver along the shear axis gives t < 0. The test is :func:`hit_record` with ``tmin <= t <= tmax``, exactly as
    in :func:`cityshade.trace.kernels.any_hit`. ``out_tests`` (n_blocks,) int64 counts the
    triangle tests per block (a profile, not used for the answer).
    """
    n_cells = ref_start.shape[0] - 1
    n_blocks = (n_cells + QUERY_BLOCK_CELLS - 1) // QUERY_BLOCK_CELLS
    n_iter = QUERY_STRIPES * ((n_blocks + QUERY_STRIPES - 1) // QUERY_STRIPES)
    for it in prange(n_iter):
        b = stripe_interleave(it, n_blocks, QUERY_STRIPES)
        if b < 0:
            continue
        tests = 0
        cache_k = -1
        for cell in range(b * QUERY_BLOCK_CELLS, min(n_cells, (b + 1) * QUERY_BLOCK_CELLS)):
            r0 = rec_start[cell]
            r1 = rec_start[cell + 1]
            p0 = ref_start[cell]
            p1 = ref_start[cell + 1]
            if p0 == p1:
                for i in range(r0, r1):
                    out[i] = False
                continue
            for i in range(r0, r1):
                okx = origins[i, kx]
                oky = origins[i, ky]
                okz = origins[i, kz]
                rkey = sgn * okz
                rx = okx - sx * okz
                ry = oky - sy * okz
                out[i] = False
                # Test the block's last occluder first (coherent receivers share it), after the
                # same exact skips as a list entry: most receivers have left its box.
                if cache_k >= 0 and _may_hit(packed, cache_k, rx, ry, rkey, depth_margin_m):
                    tests += 1
                    hit, t, u, v = hit_record(packed, cache_k, okx, oky, okz, kx, ky, kz,
                                              sx, sy, sz)
                    if hit and tmin <= t <= tmax:
                        out[i] = True
                        continue
                for p in range(p0, p1):
                    j = refs[p]
                    # Sorted by key: this caster and all after it lie behind the origin.
                    if np.float64(packed[j, PACK_KEY]) < rkey:
                        break
                    if j == cache_k or not _may_hit(packed, j, rx, ry, rkey, depth_margin_m):
                        continue
                    tests += 1
                    hit, t, u, v = hit_record(packed, j, okx, oky, okz, kx, ky, kz, sx, sy, sz)
                    if hit and tmin <= t <= tmax:
                        out[i] = True
                        cache_k = j
                        break
        out_tests[b] = tests
