"""Transmission of sun rays through vegetation crowns in the sun's light plane (``izb``).

The opaque engine's idea and set-up (docs/DESIGN.md §7), run on the crowns: all rays share the
sun direction, so in the watertight test's sheared frame a ray from o can meet a triangle only
where o's light-plane point lies in the triangle's projection. Per sun the crowns' triangles
that stand, reach the lowest receiver's depth key and whose widened light-plane box overlaps a
cell holding a receiver are packed (:func:`cityshade.lightspace.kernels.pack_casters`: box,
depth plane, edge half-planes), and receivers and packed crowns are binned into one grid by
the opaque engine's kernels. The query is caster-major per cell: the cell's crown triangles in
ascending crown order against each of its receivers; a triangle the filters cannot rule out
gets the watertight test (:func:`cityshade.trace.kernels.hit_record`, the same float32 vertices
as the tree's records) at ``t >= 0``, and a hit multiplies the receiver's transmission by its
crown's transmissivity once (the receiver remembers the last crown it met: the triangles come
crown by crown). Crowns are met in ascending order, so the product is
:func:`cityshade.trace.vegetation.crown_product`'s, bit for bit: ``raytrace``'s answer.

What does not change with the sun is made once per scene (:func:`crown_records`): the crowns'
triangles as records in crown order, their crowns, their coordinate magnitude, work arrays.
Rays an opaque triangle blocks never reach this pass (:func:`cityshade.shadows.visibility.
crown_transmission` hands over the others only).
"""
from __future__ import annotations

import math

import numba
import numpy as np
from numba import njit, prange

from cityshade.lightspace import (DEPTH_MARGIN_M, DEPTH_MARGIN_REL, MARGIN_REL,
                                  MAX_CELLS_PER_RECEIVER, OCCUPANCY_CELLS, bin_grid,
                                  ordered_origins)
from cityshade.lightspace import kernels as K
from cityshade.runtime.memory import Scratch
from cityshade.trace.kernels import hit_record, ray_shear

#: Target receivers per grid cell: the query is caster-major per cell, so a cell's crown
#: triangles are read once for all its receivers; bigger cells mean longer lists per receiver.
#: 32 was the fastest of 2, 4, 8, 16, 32 on the Berlin trees' map over a day (CPU, one thread).
RECEIVERS_PER_CELL = 32
#: Cells per parallel work item of the query (fixed, so the work split never changes a bit).
QUERY_BLOCK_CELLS = 64


class CrownRecords:
    """The crowns' triangles as the light-plane pass takes them, made once per scene: the
    crowns' kd-tree's records (:attr:`~cityshade.accel.kdtree_layout.KdTree.tri_records`),
    one per triangle, in ascending crown order (then triangle id), the crown of each, the
    largest coordinate magnitude, and work arrays.

    Taken from the tree (a scene file stores it) rather than filled again: the fill is a
    parallel kernel, and loading it from numba's cache cost 0.4-1.0 s of CPU per process on
    the Berlin trees (more than its work). A triangle the tree's build left out (degenerate)
    is one ``raytrace``'s crowns' walk never tests either."""

    def __init__(self, tree, tri_crown):
        tri_crown = np.asarray(tri_crown)
        ids = np.asarray(tree.prim_indices)
        # Each triangle's first record (a triangle straddling leaves has several, all equal).
        tri, first = np.unique(ids, return_index=True)
        order = np.argsort(tri_crown[tri], kind="stable")
        self.records = np.ascontiguousarray(np.asarray(tree.tri_records)[first[order]])
        self.crown = np.ascontiguousarray(tri_crown[tri[order]], np.int32)
        self.magnitude_m = float(np.abs(self.records[:, :9]).max()) if len(order) else 0.0
        self.scratch = Scratch()


def crown_records(veg) -> CrownRecords:
    """The :class:`CrownRecords` of a :class:`~cityshade.geometry.vegetation.SceneVegetation`,
    made once and kept with it (a batch's suns share them)."""
    made = veg.__dict__.get("_light_plane_crowns")
    if made is None:
        made = veg.__dict__["_light_plane_crowns"] = CrownRecords(veg.tree, veg.tri_crown)
    return made


@njit(cache=True)
def _ray_box(origins, rays, kx, ky, kz, sx, sy, sgn, stats):
    """``stats`` (5,): min x, max x, min y, max y of the light-plane points of the rays
    ``rays`` (indices into ``origins``) and their least depth key, read in place (no gathered
    copy, no stored points: :func:`_select` computes them again). The arithmetic of
    :func:`~cityshade.lightspace.kernels.project_receivers`."""
    x0 = np.inf
    x1 = -np.inf
    y0 = np.inf
    y1 = -np.inf
    k0 = np.inf
    for j in range(rays.shape[0]):
        i = rays[j]
        okz = origins[i, kz]
        x = origins[i, kx] - sx * okz
        y = origins[i, ky] - sy * okz
        x0 = min(x0, x)
        x1 = max(x1, x)
        y0 = min(y0, y)
        y1 = max(y1, y)
        k0 = min(k0, sgn * okz)
    stats[0] = x0
    stats[1] = x1
    stats[2] = y0
    stats[3] = y1
    stats[4] = k0


@njit(cache=True, parallel=True)
def _query(packed, kept_crown, ref_start, refs, rec_start, rec_origins, rec_order, rays, kx, ky,
           kz, sx, sy, sz, sgn, depth_margin_m, taus, max_cell, out):
    """Per cell (blocks of :data:`QUERY_BLOCK_CELLS` in parallel), its crown triangles in
    ascending crown order against each of its receivers (at most ``max_cell``);
    ``out[s, rays[rec_order[q]]]`` the product of ``taus[s]`` over the crowns receiver ``q``
    crosses, in ascending crown order."""
    n_cells = rec_start.shape[0] - 1
    n_sets = taus.shape[0]
    for b in prange((n_cells + QUERY_BLOCK_CELLS - 1) // QUERY_BLOCK_CELLS):
        last = np.empty(max_cell, np.int32)
        val = np.empty((max_cell, n_sets))
        rx = np.empty(max_cell)
        ry = np.empty(max_cell)
        rk = np.empty(max_cell)
        may = np.empty(max_cell, np.bool_)
        for c in range(b * QUERY_BLOCK_CELLS, min(n_cells, (b + 1) * QUERY_BLOCK_CELLS)):
            r0 = rec_start[c]
            m = rec_start[c + 1] - r0
            if m == 0:
                continue
            for q in range(m):
                okz = rec_origins[r0 + q, kz]
                rx[q] = rec_origins[r0 + q, kx] - sx * okz
                ry[q] = rec_origins[r0 + q, ky] - sy * okz
                rk[q] = sgn * okz
                last[q] = -1
                for s in range(n_sets):
                    val[q, s] = 1.0
            for e in range(ref_start[c], ref_start[c + 1]):
                j = refs[e]
                crown = kept_crown[j]
                # The filters of the opaque query (pack_casters' layout and arguments,
                # docs/DESIGN.md §7 (a)-(d)), each false only where hit_record cannot pass at
                # t >= 0: behind by the key, outside the widened box, behind the depth plane,
                # outside a widened edge half-plane. Branch-free over the cell's receivers.
                key = np.float64(packed[j, K.PACK_KEY])
                bx0 = np.float64(packed[j, K.PACK_BOX])
                bx1 = np.float64(packed[j, K.PACK_BOX + 1])
                by0 = np.float64(packed[j, K.PACK_BOX + 2])
                by1 = np.float64(packed[j, K.PACK_BOX + 3])
                pa = np.float64(packed[j, K.PACK_PLANE])
                pb = np.float64(packed[j, K.PACK_PLANE + 1])
                pc = key + np.float64(packed[j, K.PACK_PLANE + 2])
                e0a = np.float64(packed[j, K.PACK_EDGE])
                e0b = np.float64(packed[j, K.PACK_EDGE + 1])
                e0c = np.float64(packed[j, K.PACK_EDGE + 2])
                e1a = np.float64(packed[j, K.PACK_EDGE + 3])
                e1b = np.float64(packed[j, K.PACK_EDGE + 4])
                e1c = np.float64(packed[j, K.PACK_EDGE + 5])
                e2a = np.float64(packed[j, K.PACK_EDGE + 6])
                e2b = np.float64(packed[j, K.PACK_EDGE + 7])
                e2c = np.float64(packed[j, K.PACK_EDGE + 8])
                any_ = False
                for q in range(m):
                    dx = rx[q] - bx0
                    dy = ry[q] - by0
                    ok = ((last[q] != crown) & (key >= rk[q]) & (rx[q] >= bx0) & (rx[q] <= bx1)
                          & (ry[q] >= by0) & (ry[q] <= by1)
                          & (pc + pa * dx + pb * dy >= rk[q] - depth_margin_m)
                          & (e0a * dx + e0b * dy + e0c >= 0.0)
                          & (e1a * dx + e1b * dy + e1c >= 0.0)
                          & (e2a * dx + e2b * dy + e2c >= 0.0))
                    may[q] = ok
                    any_ |= ok
                if not any_:
                    continue
                for q in range(m):
                    if not may[q]:
                        continue
                    hit, t, _, _ = hit_record(packed, j, rec_origins[r0 + q, kx],
                                              rec_origins[r0 + q, ky], rec_origins[r0 + q, kz],
                                              kx, ky, kz, sx, sy, sz)
                    if hit and t >= 0.0:
                        last[q] = crown
                        for s in range(n_sets):
                            val[q, s] *= taus[s, crown]
            for q in range(m):
                i = rays[rec_order[r0 + q]]
                for s in range(n_sets):
                    out[s, i] = val[q, s]


@njit(cache=True)
def _select(origins, rays, kx, ky, kz, sx, sy, x0, y0, inv, nx, ny, covered, outs, out_origins,
            out_x, out_y, out_rays):
    """One pass over the rays ``rays``: each one's light-plane point and coarse cell
    (:func:`~cityshade.lightspace.kernels.receiver_cells`' numbering); a ray whose cell is
    ``covered`` is compacted (origin, point, ray index, in order), the others get 1 in every
    row of ``outs`` (no crown box reaches their cell). Returns the count compacted."""
    ntx = (nx + K.TILE - 1) // K.TILE
    m = 0
    for j in range(rays.shape[0]):
        i = rays[j]
        okz = origins[i, kz]
        x = origins[i, kx] - sx * okz
        y = origins[i, ky] - sy * okz
        if covered[K.tile_cell(K._cell(x, x0, inv, nx), K._cell(y, y0, inv, ny), ntx)]:
            out_origins[m, 0] = origins[i, 0]
            out_origins[m, 1] = origins[i, 1]
            out_origins[m, 2] = origins[i, 2]
            out_x[m] = x
            out_y[m] = y
            out_rays[m] = i
            m += 1
        else:
            for s in range(outs.shape[0]):
                outs[s, i] = 1.0
    return m


@njit(cache=True)
def _mark_covered(ranges, nx, out_table):
    """``out_table`` (cells,) uint8, zeroed: 1 in every cell (numbered as
    :func:`~cityshade.lightspace.kernels.receiver_cells` numbers them, tile by tile) a kept
    crown box's cell range (:func:`~cityshade.lightspace.kernels.caster_ranges`) covers."""
    ntx = (nx + K.TILE - 1) // K.TILE
    for j in range(ranges.shape[0]):
        if ranges[j, 0] < 0:
            continue
        for iy in range(ranges[j, 2], ranges[j, 3] + 1):
            for ix in range(ranges[j, 0], ranges[j, 1] + 1):
                out_table[K.tile_cell(ix, iy, ntx)] = 1


def transmission(crowns: CrownRecords, origins, direction, t_days, rays, taus, outs) -> None:
    """Fill ``outs[s][rays]`` with the transmission of those sun rays through the crowns with
    the transmissivities ``taus[s]`` ((C,) float64 per crown) for every ``s``. ``origins``
    (N, 3) float64, ``direction`` (3,) unit, one for every ray; ``rays`` indices into
    ``origins``; ``outs`` (S, N) float64."""
    rays = np.ascontiguousarray(rays, dtype=np.int64)
    n = len(rays)
    if n == 0:
        return
    taus = np.ascontiguousarray(np.asarray(taus, np.float64).reshape(len(outs), -1))
    if len(crowns.crown) == 0:
        outs[:, rays] = 1.0
        return
    ws = crowns.scratch.take()
    try:
        _transmission(crowns, ws, np.ascontiguousarray(origins, np.float64), direction,
                      float(t_days), rays, taus, outs)
    finally:
        ws.give_back()


def _transmission(crowns, ws, origins, direction, t_days, rays, taus, outs):
    n = len(rays)
    kx, ky, kz, sx, sy, sz = ray_shear(*(float(c) for c in direction))
    sgn = 1.0 if sz > 0.0 else -1.0
    stats = np.empty(5)
    _ray_box(origins, rays, kx, ky, kz, sx, sy, sgn, stats)
    box = stats[:4].copy()
    min_key = float(stats[4])
    scale = max(crowns.magnitude_m, float(np.abs(box).max()), 1.0)

    # The crowns that can reach a receiver, in crown order.
    recs = crowns.records
    m = recs.shape[0]
    neg_keys = ws.get("neg_keys", m)
    K.caster_keys(recs, np.arange(m, dtype=np.int64), kz, sgn, neg_keys)
    keys = ws.get("keys", m, np.float32)
    np.negative(neg_keys, out=keys, casting="same_kind")   # ± a float32 coordinate: exact
    boxes = ws.get("boxes", (m, 4))
    K.cull_casters(recs, recs.view(np.float64), keys, t_days, kx, ky, kz, sx, sy,
                   MARGIN_REL * scale, box, min_key, boxes)
    floor_m = 1e-9 * scale
    ext_x = max(box[1] - box[0], floor_m)
    ext_y = max(box[3] - box[2], floor_m)
    occ = math.sqrt(ext_x * ext_y / max(1, min(n, OCCUPANCY_CELLS)))
    onx = max(1, min(OCCUPANCY_CELLS, math.ceil(ext_x / occ)))
    ony = max(1, min(OCCUPANCY_CELLS // onx, math.ceil(ext_y / occ)))
    occ_inv = 1.0 / max(ext_x / onx, ext_y / ony)
    n_tiled = K.tiled_cells(onx, ony)[1]

    # Most receivers lie under no crown: those whose coarse cell no standing crown's box
    # covers get 1 (they lie outside every box: cells are monotone in x, y) and are never
    # binned. The others are exactly those whose cell an occupancy-kept crown covers (a crown
    # over a receiver's cell covers an occupied cell), so the occupancy table of the selected
    # receivers alone keeps the crowns that of all the receivers kept: the same crowns, cells
    # and receivers as one pass of each kind over all the rays, from two passes over them.
    ranges = ws.get("crown_ranges", (m, 4), np.int64)
    K.caster_ranges(boxes, box[0], box[2], occ_inv, occ_inv, onx, ony, ranges)
    covered = np.zeros(n_tiled, np.uint8)
    _mark_covered(ranges, onx, covered)
    o_sel, x_sel, y_sel = ws.get("o_sel", (n, 3)), ws.get("x_sel", n), ws.get("y_sel", n)
    rays_sel = ws.get("rays_sel", n, np.int64)
    n = _select(origins, rays, kx, ky, kz, sx, sy, box[0], box[2], occ_inv, onx, ony, covered,
                outs, o_sel, x_sel, y_sel, rays_sel)
    if n == 0:
        return
    o, xs, ys, rays = o_sel[:n], x_sel[:n], y_sel[:n], rays_sel[:n]
    occupied = ws.get("occupied", (ony + 1, onx + 1), np.int32)
    K.occupancy_table(xs, ys, box[0], box[2], occ_inv, onx, ony, occupied)
    K.cull_unoccupied(boxes, box[0], box[2], occ_inv, onx, ony, occupied)
    kept = np.flatnonzero(~np.isnan(boxes[:, 0]))
    packed = ws.get("packed", (kept.size, K.PACK_WORDS), np.float32)
    kept_boxes = boxes[kept]
    # Packed in kept (= crown) order: the query below multiplies in ascending crown order.
    K.pack_casters(recs, keys, kept_boxes, kept, np.arange(kept.size, dtype=np.int32), kx, ky,
                   kz, sx, sy, sgn, scale, packed)
    kept_crown = crowns.crown[kept]
    # The cells the kept crowns cover (the grid's size below counts them).
    covered[:] = 0
    _mark_covered(ranges[kept], onx, covered)
    covered_m2 = int(covered.sum()) / (occ_inv * occ_inv)

    # One grid over the receivers' box, cells of about RECEIVERS_PER_CELL of the covered
    # receivers: receivers in cell order, each cell's crown triangles in kept (= crown)
    # order, whatever the thread count.
    size = max(math.sqrt(covered_m2 * RECEIVERS_PER_CELL / n), floor_m,
               math.sqrt(ext_x * ext_y / (MAX_CELLS_PER_RECEIVER * n)))
    nx = max(1, math.ceil(ext_x / size))
    ny = max(1, math.ceil(ext_y / size))
    inv = 1.0 / size
    rec_start, rec_order, ref_start, refs, _, _, _ = bin_grid(
        ws, xs, ys, kept_boxes, box[0], box[2], inv, nx, ny,
        max(1, numba.get_num_threads()), False)
    rec_origins = ordered_origins(ws, o, rec_order)
    max_cell = int(np.diff(rec_start).max())
    _query(packed, kept_crown, ref_start, refs, rec_start, rec_origins, rec_order, rays, kx, ky,
           kz, sx, sy, sz, sgn, DEPTH_MARGIN_M + DEPTH_MARGIN_REL * scale, taus, max_cell, outs)

