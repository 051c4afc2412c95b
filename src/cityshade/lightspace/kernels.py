"""Numba kernels of the light-space sun engine: project, bin, query (docs/DESIGN.md §7).

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
  Casters are sorted by ``key = max_v sgn * v[kz]`` (descending) and a cell's receivers stop
  at the first key below the lowest ``sgn * o[kz]`` of those still lit: lit receivers stop
  early too.
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


#: Words of a caster record (:class:`cityshade.lightspace.Casters`): the tree record's first
#: 14, the vertices (0-8), the id (9) and the times (float64 words ``REC_T_BEGIN64`` and
#: ``REC_T_END64``), all the kernels read; the material and padding after them are dropped.
CASTER_WORDS = 2 * (REC_T_END64 + 1)


@njit(cache=True)
def first_records(ids, seen, out_rows):
    """Write to ``out_rows`` the rows ``i`` whose id ``ids[i]`` is not yet ``seen`` (a zeroed
    bool table), marking it; returns their count. On the records in file order this is each
    triangle's first record, in increasing row order."""
    m = 0
    for i in range(ids.shape[0]):
        t = ids[i]
        if not seen[t]:
            seen[t] = True
            out_rows[m] = i
            m += 1
    return m


@njit(cache=True, parallel=True)
def caster_keys(recs, rows, kz, sgn, out_key):
    """Sort key ``-max_v sgn * v[kz]`` (the depth key negated: ascending order is the casters'
    descending key order) of the tree records ``rows`` (float32 vertices, exact in float64);
    read in place, no gathered copy."""
    for j in prange(rows.shape[0]):
        r = rows[j]
        a = sgn * np.float64(recs[r, kz])
        b = sgn * np.float64(recs[r, 3 + kz])
        c = sgn * np.float64(recs[r, 6 + kz])
        out_key[j] = -max(a, max(b, c))


@njit(cache=True)
def merge_orders(keys, left, right, out):
    """``out``: the stable merge of two index arrays each in ascending ``keys`` order, ``left``
    first on equal keys; for the two halves' stable argsorts (``right`` holding the later
    indices) that is the stable argsort of the whole."""
    i = 0
    j = 0
    k = 0
    while i < left.shape[0] and j < right.shape[0]:
        if keys[right[j]] < keys[left[i]]:
            out[k] = right[j]
            j += 1
        else:
            out[k] = left[i]
            i += 1
        k += 1
    while i < left.shape[0]:
        out[k] = left[i]
        i += 1
        k += 1
    while j < right.shape[0]:
        out[k] = right[j]
        j += 1
        k += 1


@njit(cache=True, parallel=True)
def ranks_of(order, keys, out_sorted_keys, out_rank):
    """Where each caster goes (``out_rank[order[i]] = i``) and the depth keys in that order
    (``-keys``, float32: exact, a key is a float32 coordinate)."""
    for i in prange(order.shape[0]):
        o = order[i]
        out_sorted_keys[i] = np.float32(-keys[o])
        out_rank[o] = i


@njit(cache=True, parallel=True)
def scatter_records(recs, rows, rank, out):
    """``out[rank[j]] = recs[rows[j], :CASTER_WORDS]``: the tree's records read in file order,
    written to their sorted rows."""
    for j in prange(rows.shape[0]):
        r = rows[j]
        q = rank[j]
        for w in range(out.shape[1]):
            out[q, w] = recs[r, w]


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
PACK_EDGE = 17
PACK_WORDS = 26
#: Relative widening when the float64 box is stored as float32 (rounding is 2^-24 relative).
_F32_WIDEN = 2.0 ** -22
#: The depth plane is used only for casters of decent shape in the light plane: box
#: diagonal² / |2 area| <= 2^20, so hit_record's distance (a convex combination with weights
#: of absolute error <= ~12 eps diagonal² / |2 area|) is within ~4e-9 relative of the plane's.
_PLANE_MAX_ASPECT = 2.0 ** 20
#: Each plane is moved sunward by this fraction of its own terms' magnitudes, which bounds the
#: float32 rounding of its coefficients (2^-24 each) with a wide margin.
_PLANE_WIDEN = 2.0 ** -21
#: Each edge half-plane (:func:`pack_casters`) is moved outward by this fraction of the scene
#: scale plus the caster's box diagonal: far above hit_record's own rounding of its edge
#: functions for casters of decent shape (at most ~2^-27 of the scale, see pack_casters) and
#: of the float32 storage (2^-23 of the diagonal), far below a cell (1 mm at 1 km).
_EDGE_WIDEN = 2.0 ** -20


@njit(cache=True, parallel=True)
def pack_casters(recs, keys, boxes, kept, dest, kx, ky, kz, sx, sy, sgn, scale_m, out):
    """Float32 records (PACK_WORDS) of the kept casters ``kept`` (rows of ``recs``), each
    written to row ``dest[q]`` of ``out`` (:func:`tile_order`): columns 0-8 the vertices (as
    in the tree's records), ``PACK_KEY`` the key (float32 values, exact), ``PACK_BOX`` .. +3
    the light-plane box ``boxes[q]`` (float64, of kept caster q) rounded outward to float32,
    ``PACK_PLANE`` .. +2 the depth plane ``sgn * z = key + c + a (x - box x0) + b (y - box
    y0)`` as (a, b, c), moved sunward by its rounding bound, or (0, 0, +inf) where the plane
    is not trusted (never skips)."""
    for q in prange(kept.shape[0]):
        j = kept[q]
        d = dest[q]
        for c in range(9):
            out[d, c] = recs[j, c]
        out[d, PACK_KEY] = keys[j]
        for c in range(4):
            b = boxes[q, c]
            w = abs(b) * _F32_WIDEN + 2.0 ** -40
            out[d, PACK_BOX + c] = b - w if c % 2 == 0 else b + w
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
        bw = boxes[q, 1] - boxes[q, 0]
        bh = boxes[q, 3] - boxes[q, 2]
        pa = 0.0
        pb = 0.0
        pc = np.inf
        if det != 0.0 and (bw * bw + bh * bh) <= _PLANE_MAX_ASPECT * abs(det):
            pa = (z1 * y2 - z2 * y1) / det
            pb = (x1 * z2 - x2 * z1) / det
            bx0 = np.float64(out[d, PACK_BOX])
            by0 = np.float64(out[d, PACK_BOX + 2])
            pc = z0 + pa * (bx0 - x0) + pb * (by0 - y0) - keys[j]
            pc += _PLANE_WIDEN * (abs(pa) * (bw + 1.0) + abs(pb) * (bh + 1.0) + abs(pc)
                                  + abs(keys[j]))
        out[d, PACK_PLANE] = pa
        out[d, PACK_PLANE + 1] = pb
        out[d, PACK_PLANE + 2] = pc
        # Edge half-planes a (x - box x0) + b (y - box y0) + c >= 0 holding the triangle, with
        # (a, b) the inward unit normal (float32) and c moved outward (see _EDGE_WIDEN), or
        # (0, 0, +inf) (never rejects) where the plane is not trusted. Why they are safe: a
        # receiver in the box is within diag of every vertex, hit_record's sheared
        # coordinates are exact to ~2^-50 of the scale, so its edge function (|edge| times
        # the distance to the edge's line) is exact to ~2^-48 scale diag + 2^-51 diag^2; with
        # |edge| >= |det| / diag >= diag 2^-20 (the trust condition) a receiver more than
        # 2^-27 (scale + diag) outside an edge's line gets that edge's sign from hit_record.
        diag = np.sqrt(bw * bw + bh * bh)
        bx0 = np.float64(out[d, PACK_BOX])
        by0 = np.float64(out[d, PACK_BOX + 2])
        for e in range(3):
            out[d, PACK_EDGE + 3 * e] = 0.0
            out[d, PACK_EDGE + 3 * e + 1] = 0.0
            out[d, PACK_EDGE + 3 * e + 2] = np.inf
        if pc < np.inf:
            widen = _EDGE_WIDEN * (scale_m + diag)
            sign = 1.0 if det > 0.0 else -1.0
            for e in range(3):
                # Edge from vertex e to vertex e + 1, relative to vertex 0's projection.
                if e == 0:
                    ex0, ey0, ex1, ey1 = 0.0, 0.0, x1, y1
                elif e == 1:
                    ex0, ey0, ex1, ey1 = x1, y1, x2, y2
                else:
                    ex0, ey0, ex1, ey1 = x2, y2, 0.0, 0.0
                na = -(ey1 - ey0) * sign
                nb = (ex1 - ex0) * sign
                # One division, not two: the normal is unit to ~2^-52 before its float32
                # rounding (2^-24); c below is made from the rounded normal either way.
                inv_ln = 1.0 / np.sqrt(na * na + nb * nb)
                a32 = np.float32(na * inv_ln)
                b32 = np.float32(nb * inv_ln)
                # c: minus the normal's value at the edge's start, in box-corner coordinates.
                c = -(np.float64(a32) * (ex0 + x0 - bx0) + np.float64(b32) * (ey0 + y0 - by0))
                c += widen + abs(c) * 2.0 ** -22
                out[d, PACK_EDGE + 3 * e] = a32
                out[d, PACK_EDGE + 3 * e + 1] = b32
                out[d, PACK_EDGE + 3 * e + 2] = c


@njit(cache=True, parallel=True)
def density_grid(xs, ys, stride, boxes, x0, y0, inv, nx, ny, out_receivers, out_casters,
                 out_box_sums):
    """Receivers (every ``stride``-th, counted ``stride`` times) and casters (by box centre) per
    cell of a coarse grid (``nx`` by ``ny``, cell ``1 / inv`` wide from ``(x0, y0)``), for the
    cell-size model: ``out_receivers``, ``out_casters`` (n_chunks, nx * ny) float64, any
    content, each chunk's counts in its own row; and in the same pass over the boxes (NaN x0:
    culled, skipped) each chunk's sums of ``w h``, ``w + h`` and 1 in ``out_box_sums``
    (n_chunks, 3), from which :func:`cityshade.lightspace.refs_per_size` estimates the cell
    references of any cell size (a second pass over the boxes cost 1.4 of the 1M map's 5 ms
    model)."""
    n_chunks = out_receivers.shape[0]
    n = (xs.shape[0] + stride - 1) // stride
    m = boxes.shape[0]
    per_r = (n + n_chunks - 1) // n_chunks
    per_m = (m + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        out_receivers[c, :] = 0.0
        out_casters[c, :] = 0.0
        for q in range(c * per_r, min(n, (c + 1) * per_r)):
            i = q * stride
            out_receivers[c, _cell(ys[i], y0, inv, ny) * nx + _cell(xs[i], x0, inv, nx)] += stride
        area = 0.0
        sides = 0.0
        count = 0.0
        for j in range(c * per_m, min(m, (c + 1) * per_m)):
            if np.isnan(boxes[j, 0]):
                continue
            cx = 0.5 * (boxes[j, 0] + boxes[j, 1])
            cy = 0.5 * (boxes[j, 2] + boxes[j, 3])
            out_casters[c, _cell(cy, y0, inv, ny) * nx + _cell(cx, x0, inv, nx)] += 1.0
            w = boxes[j, 1] - boxes[j, 0]
            h = boxes[j, 3] - boxes[j, 2]
            area += w * h
            sides += w + h
            count += 1.0
        out_box_sums[c, 0] = area
        out_box_sums[c, 1] = sides
        out_box_sums[c, 2] = count


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
def occupancy_table(xs, ys, x0, y0, inv, nx, ny, out_table):
    """``out_table`` (ny + 1, nx + 1) int32 (any content): the summed-area table of the cells
    of a grid (``nx`` by ``ny``, cell ``1 / inv`` from ``(x0, y0)``, :func:`_cell`) that hold
    a receiver, ``out_table[iy, ix]`` the occupied cells below row iy and left of column ix."""
    out_table[:, :] = 0
    # Threads may mark one cell together: every store writes the same 1.
    for i in prange(xs.shape[0]):
        out_table[_cell(ys[i], y0, inv, ny) + 1, _cell(xs[i], x0, inv, nx) + 1] = 1
    for iy in range(1, ny + 1):
        row = 0
        for ix in range(1, nx + 1):
            row += out_table[iy, ix]
            out_table[iy, ix] = out_table[iy - 1, ix] + row


@njit(cache=True, parallel=True)
def cull_unoccupied(boxes, x0, y0, inv, nx, ny, table):
    """NaN in ``boxes[j, 0]`` for each kept caster whose box (x0, x1, y0, y1) covers no cell of
    :func:`occupancy_table`'s grid that holds a receiver: no receiver point lies in its box
    (:func:`_cell` is monotone), so by the binning argument it can shade none."""
    for j in prange(boxes.shape[0]):
        if np.isnan(boxes[j, 0]):
            continue
        ix0 = _cell(boxes[j, 0], x0, inv, nx)
        ix1 = _cell(boxes[j, 1], x0, inv, nx) + 1
        iy0 = _cell(boxes[j, 2], y0, inv, ny)
        iy1 = _cell(boxes[j, 3], y0, inv, ny) + 1
        if table[iy1, ix1] - table[iy0, ix1] - table[iy1, ix0] + table[iy0, ix0] == 0:
            boxes[j, 0] = np.nan


#: Cells are numbered tile by tile (:func:`tile_cell`): a tile of TILE x TILE cells is one
#: query block, so the casters a block loads are those over a square of cells (a caster over
#: 2 x 2 cells is loaded once per tile it touches; a row of 64 cells loaded it once per row).
TILE = 8
TILE_CELLS = TILE * TILE


@njit(cache=True, inline="always")
def tile_cell(ix, iy, ntx):
    """Index of cell (ix, iy) when cells are numbered tile by tile (``ntx`` tiles per row,
    tiles row-major, cells row-major inside a tile)."""
    return (((iy // TILE) * ntx + ix // TILE) * TILE_CELLS + (iy % TILE) * TILE
            + ix % TILE)


def tiled_cells(nx: int, ny: int) -> tuple[int, int]:
    """(tiles per row, cell indices) of an ``nx`` by ``ny`` grid numbered by :func:`tile_cell`
    (padded to whole tiles)."""
    ntx = -(-nx // TILE)
    return ntx, ntx * -(-ny // TILE) * TILE_CELLS


@njit(cache=True, parallel=True)
def receiver_cells(xs, ys, x0, y0, inv_x, inv_y, nx, ny, out_cell):
    """Grid cell of each receiver, numbered by :func:`tile_cell`."""
    ntx = (nx + TILE - 1) // TILE
    for i in prange(xs.shape[0]):
        out_cell[i] = tile_cell(_cell(xs[i], x0, inv_x, nx), _cell(ys[i], y0, inv_y, ny), ntx)


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
def tile_order(ranges, ntx, counts, fill, out_dest):
    """Rows of the packed casters in the order the query first needs them: by the tile of
    their box's first cell (:func:`tile_cell`), key order inside a tile, so a chunk of tiles
    reads its casters from a few contiguous stretches instead of all over the array (the
    query's loads of caster records were cache misses). Count pass (``fill`` False:
    ``counts`` (n_chunks, n_tiles) int32, any content, gets the casters per tile of each fixed
    chunk) or fill pass (``fill`` True: ``counts`` the cursors of :func:`prefix_sum`;
    ``out_dest[j]`` the row of caster j). The same order for any thread count."""
    n = ranges.shape[0]
    n_chunks = counts.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    for c in prange(n_chunks):
        if not fill:
            counts[c, :] = 0
        for j in range(c * per, min(n, (c + 1) * per)):
            t = (ranges[j, 2] // TILE) * ntx + ranges[j, 0] // TILE
            if fill:
                out_dest[j] = counts[c, t]
            counts[c, t] += 1


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
def scatter_casters(ranges, rec_start, nx, cursor, dest, out_refs, fill):
    """Count pass (``fill`` False: ``cursor`` (n_chunks, n_cells) int32, any content, gets the
    references per cell of each fixed chunk of casters; each chunk clears its own row first)
    or fill pass (``fill`` True: ``cursor`` holds the write positions of :func:`prefix_sum`
    and ``out_refs`` gets the casters' packed rows ``dest[j]``, in caster = key order inside a
    cell). Only cells holding a receiver (``rec_start`` (n_cells + 1,), the receivers' list
    starts) get references.
    """
    n = ranges.shape[0]
    n_chunks = cursor.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    ntx = (nx + TILE - 1) // TILE
    for c in prange(n_chunks):
        if not fill:
            cursor[c, :] = 0
        for j in range(c * per, min(n, (c + 1) * per)):
            if ranges[j, 0] < 0:
                continue
            for iy in range(ranges[j, 2], ranges[j, 3] + 1):
                for ix in range(ranges[j, 0], ranges[j, 1] + 1):
                    cell = tile_cell(ix, iy, ntx)
                    if rec_start[cell + 1] > rec_start[cell]:
                        if fill:
                            out_refs[cursor[c, cell]] = dest[j]
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
def order_receivers(cells, cursor, origins, out_order, out_origins):
    """Receiver indices grouped by cell (receiver order inside a cell), and with ``origins``
    (N, 3) (not empty) their origins in that order into ``out_origins``, so the query reads
    receivers sequentially (copied here, as each receiver's place is found, rather than
    gathered in a second pass over the order: :func:`gather_rows`)."""
    n = cells.shape[0]
    n_chunks = cursor.shape[0]
    per = (n + n_chunks - 1) // n_chunks
    copy = origins.shape[0] > 0
    for c in prange(n_chunks):
        for i in range(c * per, min(n, (c + 1) * per)):
            cell = cells[i]
            q = cursor[c, cell]
            out_order[q] = i
            if copy:
                out_origins[q, 0] = origins[i, 0]
                out_origins[q, 1] = origins[i, 1]
                out_origins[q, 2] = origins[i, 2]
            cursor[c, cell] = q + 1


@njit(cache=True, parallel=True)
def gather_rows(src, rows, out):
    """``out[q] = src[rows[q]]`` (2-D rows)."""
    for q in prange(rows.shape[0]):
        for w in range(src.shape[1]):
            out[q, w] = src[rows[q], w]


@njit(cache=True, parallel=True)
def scatter_back(order, sorted_values, out):
    """``out[order[q]] = sorted_values[q]``: results in cell order back to receiver order."""
    for q in prange(order.shape[0]):
        out[order[q]] = sorted_values[q]


#: Tiles per chunk of the query handed to a thread (:func:`query`): consecutive tiles of a
#: row share casters, so a chunk keeps them in cache; small enough for the threads to balance.
QUERY_CHUNK_TILES = 8


#: Receivers of a cell are queried caster by caster over chunks of this many (a branch-free
#: pass over the chunk per caster: box, depth plane and edge half-planes as one mask, then the
#: exact test where it is set, which is almost only where it hits), down the cell's list until
#: the casters lie behind every receiver still lit. Every cell, whatever its list's length:
#: with the lowest key of the lanes still lit (recomputed after a hit) a long list stops once
#: the casters lie behind the chunk's lit receivers, and the mask is cheaper than one test per
#: entry. Measured on the 1M-triangle city (query wall ms, two threads, against receiver by
#: receiver for lists over 60): overview at suns of 30, 3 and 12 degrees 36.6 / 32.0 / 26.1 ->
#: 25.4 / 24.9 / 21.6, 1 m map 58.0 / 54.5 / 46.7 -> 45.5 / 39.0 / 40.9, sky directions of the
#: 1 m map at 6-66 degrees 31.8-47.4 -> 26.5-38.8; benchmarks/raytrace.py's map at 30 degrees
#: (12 m cells of ~150 receivers, where each receiver stopped at its own first hit) 128 -> 133.
QUERY_CHUNK = 64
#: Lanes of the caster-major mask are padded to a multiple of this (see _query_caster_major).
QUERY_LANES = 8


@njit(cache=True, inline="always")
def _query_caster_major(packed, refs, p0, p1, origins, c0, m, kx, ky, kz, sx, sy, sz, sgn,
                        depth_margin_m, tmin, tmax, out, cache_k, rx, ry, rk, cand):
    """Receivers c0..c0+m of one cell (m <= QUERY_CHUNK; ``rx .. cand`` scratch of that size)
    against the last occluder, then the cell's list in key order: per caster one branch-free
    mask over the receivers still lit, then :func:`hit_record` where it is set; stops when
    every receiver is shadowed or the casters lie behind the lowest one still lit (sorted by
    key: that caster and all after it lie behind every such origin). Returns (tests, last
    occluder).

    The mask is False only where caster j cannot hit the receiver at light-plane ``(rx, ry)``
    with key ``rk``: behind its own key (t < 0), outside its widened box (the binning
    argument; ``rx - x0 >= 0`` is ``rx >= x0`` exactly), behind its depth plane by more than
    ``depth_margin_m`` (t < 0, see :func:`pack_casters`), or outside one of its widened edge
    half-planes (outside the triangle)."""
    tests = 0
    k_low = np.inf
    bx0 = np.inf
    bx1 = -np.inf
    by0 = np.inf
    by1 = -np.inf
    for q in range(m):
        okz = origins[c0 + q, kz]
        rx[q] = origins[c0 + q, kx] - sx * okz
        ry[q] = origins[c0 + q, ky] - sy * okz
        rk[q] = sgn * okz
        k_low = min(k_low, rk[q])
        bx0 = min(bx0, rx[q])
        bx1 = max(bx1, rx[q])
        by0 = min(by0, ry[q])
        by1 = max(by1, ry[q])
        out[c0 + q] = False
    # Lanes up to a multiple of QUERY_LANES, dead: a receiver's key of +inf fails the mask's
    # first test (a shadowed receiver gets it too), so the mask loop has no scalar tail. A
    # chunk of fewer receivers is not padded (a cell of 1-2 receivers would test 8 lanes).
    m_pad = m if m < QUERY_LANES else -(-m // QUERY_LANES) * QUERY_LANES
    for q in range(m, m_pad):
        rx[q] = 0.0
        ry[q] = 0.0
        rk[q] = np.inf
    left = m
    first = cache_k
    for p in range(p0 - 1, p1):
        if p < p0:
            j = first
            if j < 0:
                continue
        else:
            j = refs[p]
            if j == first:
                continue
        key = np.float64(packed[j, PACK_KEY])
        if key < k_low:
            if p < p0:
                continue
            break  # sorted by key: this caster and all after it lie behind every receiver
        x0 = np.float64(packed[j, PACK_BOX])
        x1 = np.float64(packed[j, PACK_BOX + 1])
        y0 = np.float64(packed[j, PACK_BOX + 2])
        y1 = np.float64(packed[j, PACK_BOX + 3])
        # No receiver of the chunk in the box: every lane's box test below would fail
        # (``rx - x0 >= 0`` is ``rx >= x0`` exactly), so the caster is skipped unread.
        if bx1 < x0 or bx0 > x1 or by1 < y0 or by0 > y1:
            continue
        pa = np.float64(packed[j, PACK_PLANE])
        pb = np.float64(packed[j, PACK_PLANE + 1])
        kc = key + np.float64(packed[j, PACK_PLANE + 2])
        ea0 = np.float64(packed[j, PACK_EDGE])
        eb0 = np.float64(packed[j, PACK_EDGE + 1])
        ec0 = np.float64(packed[j, PACK_EDGE + 2])
        ea1 = np.float64(packed[j, PACK_EDGE + 3])
        eb1 = np.float64(packed[j, PACK_EDGE + 4])
        ec1 = np.float64(packed[j, PACK_EDGE + 5])
        ea2 = np.float64(packed[j, PACK_EDGE + 6])
        eb2 = np.float64(packed[j, PACK_EDGE + 7])
        ec2 = np.float64(packed[j, PACK_EDGE + 8])
        n_cand = 0
        shadowed = False
        for q in range(m_pad):
            dx = rx[q] - x0
            dy = ry[q] - y0
            zp = kc + pa * dx + pb * dy
            ok = ((rk[q] <= key) & (dx >= 0.0) & (rx[q] <= x1) & (dy >= 0.0)
                  & (ry[q] <= y1) & (zp >= rk[q] - depth_margin_m)
                  & (ea0 * dx + eb0 * dy + ec0 >= 0.0) & (ea1 * dx + eb1 * dy + ec1 >= 0.0)
                  & (ea2 * dx + eb2 * dy + ec2 >= 0.0))
            cand[q] = ok
            n_cand += ok
        if n_cand == 0:
            continue
        for q in range(m):
            if cand[q]:
                i = c0 + q
                tests += 1
                hit, t, u, v = hit_record(packed, j, origins[i, kx], origins[i, ky],
                                          origins[i, kz], kx, ky, kz, sx, sy, sz)
                if hit and tmin <= t <= tmax:
                    out[i] = True
                    rk[q] = np.inf
                    cache_k = j
                    left -= 1
                    shadowed = True
        if left == 0:
            break
        if shadowed:     # the lowest receiver still lit may stand higher: stop sooner
            k_low = np.inf
            for q in range(m):
                k_low = min(k_low, rk[q])
    return tests, cache_k


@njit(cache=True, nogil=True)
def query(packed, ref_start, refs, rec_start, origins, kx, ky, kz, sx, sy, sz, sgn,
          depth_margin_m, tmin, tmax, out, out_tests, b0, b1):
    """``out[q]`` (every entry of tiles ``b0 .. b1`` written) True when the shadow ray of
    receiver q (in cell order) hits a caster of its cell.

    ``packed`` (M, PACK_WORDS) float32 caster records of :func:`pack_casters`, ``refs`` the
    cells' caster lists in key order (descending; ``ref_start`` (n_cells + 1,)), ``origins``
    the receivers' origins grouped by cell (``rec_start``), cells numbered by
    :func:`tile_cell`. A receiver outside a caster's widened box is outside the triangle (the
    binning argument), so the box check only skips tests that cannot hit; so does the depth
    plane: a caster whose plane lies more than ``depth_margin_m`` behind the receiver along
    the shear axis gives t < 0. The test is :func:`hit_record` with ``tmin <= t <= tmax``,
    exactly as in :func:`cityshade.trace.kernels.any_hit`; the decision is "some candidate
    passes", so the order in which a cell's pairs are tested (caster by caster, see
    :data:`QUERY_CHUNK`) changes only the time. ``out_tests`` (n_tiles,) int64 counts the
    triangle tests per tile (a profile, not used for the answer). A serial ``nogil`` kernel
    over a range of tiles, for :func:`cityshade.runtime.threadpool.run_chunks` (a ``prange``
    body loaded from Numba's cache may run slower than its first compile).
    """
    n_cells = ref_start.shape[0] - 1
    rx = np.empty(QUERY_CHUNK)
    ry = np.empty(QUERY_CHUNK)
    rk = np.empty(QUERY_CHUNK)
    cand = np.empty(QUERY_CHUNK, np.bool_)
    cache_k = -1
    for b in range(b0, b1):
        tests = 0
        for cell in range(b * TILE_CELLS, min(n_cells, (b + 1) * TILE_CELLS)):
            r0 = rec_start[cell]
            r1 = rec_start[cell + 1]
            p0 = ref_start[cell]
            p1 = ref_start[cell + 1]
            if p0 == p1:
                for i in range(r0, r1):
                    out[i] = False
                continue
            for c0 in range(r0, r1, QUERY_CHUNK):
                n_t, cache_k = _query_caster_major(
                    packed, refs, p0, p1, origins, c0, min(r1, c0 + QUERY_CHUNK) - c0,
                    kx, ky, kz, sx, sy, sz, sgn, depth_margin_m, tmin, tmax, out, cache_k,
                    rx, ry, rk, cand)
                tests += n_t
        out_tests[b] = tests
