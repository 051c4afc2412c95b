"""Transmission of sun rays through vegetation crowns along the kd-tree (``raytrace``).

A ray keeps the product of the transmissivities of the *distinct* crowns (vegetation objects)
whose triangles it meets at ``0 <= t``: every leaf its segment crosses is visited (no early
exit), every standing record tested with the watertight test, and each hit's crown added once
to the ray's set. The product runs over the set in ascending crown order
(:func:`crown_product`), so the light-space engine, which meets the same triangles in another
order, gives the same float64 bits.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from cityshade.accel.kdtree_layout import (
    LEAF_CODE,
    TIME_AXIS,
    leaf_first,
    node_split,
    node_word,
    record_id,
    record_present,
    word_axis,
    word_payload,
)
from cityshade.trace.kernels import (
    FAR_ONLY,
    NEAR_ONLY,
    STACK_SIZE,
    clip_to_box,
    hit_record,
    on_axes,
    push_segment,
    ray_shear,
    set_direction,
    split_side,
)

#: Starting size of a ray's crown set (grown by doubling when a ray crosses more crowns).
CROWN_SET = 16


@njit(cache=True, inline="always")
def has_crown(seen, n, crown):
    """Whether ``crown`` is in the set ``seen[:n]``: a ray that has met a crown skips its
    other triangles (the set, and so the product, is the same without their tests)."""
    for j in range(n):
        if seen[j] == crown:
            return True
    return False


@njit(cache=True, inline="always")
def add_crown(seen, n, crown):
    """Add ``crown`` to the set ``seen[:n]``; returns ``(seen, n)`` (``seen`` grown when
    full)."""
    for j in range(n):
        if seen[j] == crown:
            return seen, n
    if n == seen.shape[0]:
        grown = np.empty(2 * n, seen.dtype)
        grown[:n] = seen
        seen = grown
    seen[n] = crown
    return seen, n + 1


@njit(cache=True)
def crown_product(seen, n, crown_tau):
    """Product of ``crown_tau`` over the set ``seen[:n]``, multiplied in ascending crown order
    (sorted in place): the same bits whatever order the crowns were met in."""
    for a in range(1, n):  # insertion sort: sets are a few crowns
        c = seen[a]
        b = a - 1
        while b >= 0 and seen[b] > c:
            seen[b + 1] = seen[b]
            b -= 1
        seen[b + 1] = c
    tau = 1.0
    for j in range(n):
        tau *= crown_tau[seen[j]]
    return tau


@njit(cache=True, nogil=True)
def crowns_range(tree, box_lo, box_hi, origins, direction, t_days, rays, tri_crown, crown_tau,
                 out, i0, i1):
    """``out[rays[j]]`` = transmission of ray ``rays[j]`` for ``j`` in ``[i0, i1)``: the rays
    from ``origins`` along the one ``direction`` (3,), through the crowns' tree ``tree``
    (:class:`~cityshade.accel.kdtree_layout.KdViews`, record ids indexing ``tri_crown``).
    The traversal is :func:`cityshade.trace.kernels.trace_range`'s, without its early exits."""
    st_node = np.empty(STACK_SIZE, np.int64)
    st_t0 = np.empty(STACK_SIZE)
    st_t1 = np.empty(STACK_SIZE)
    ray = np.empty(9)
    dx, dy, dz = direction[0], direction[1], direction[2]
    kx, ky, kz, sx, sy, sz = ray_shear(dx, dy, dz)
    set_direction(ray, dx, dy, dz)
    seen = np.empty(CROWN_SET, np.int32)
    for j in range(i0, i1):
        i = rays[j]
        ox, oy, oz = origins[i, 0], origins[i, 1], origins[i, 2]
        okx, oky, okz = on_axes(ox, oy, oz, kx, ky, kz)
        n = 0
        seg0, seg1 = clip_to_box(box_lo, box_hi, ox, oy, oz, dx, dy, dz, 0.0, np.inf)
        if seg0 <= seg1:
            ray[0] = ox
            ray[1] = oy
            ray[2] = oz
            node = 0
            sp = 0
            while True:
                w0 = node_word(tree, node)
                axis = word_axis(w0)
                if axis == LEAF_CODE:
                    first = leaf_first(tree, node)
                    for k in range(first, first + word_payload(w0)):
                        if not record_present(tree, k, t_days):
                            continue
                        crown = tri_crown[record_id(tree, k)]
                        if has_crown(seen, n, crown):
                            continue  # counted once: another of its triangles cannot change it
                        hit, t, _, _ = hit_record(tree.recs, k, okx, oky, okz, kx, ky, kz, sx,
                                                  sy, sz)
                        if hit and t >= 0.0:
                            seen, n = add_crown(seen, n, crown)
                    if sp == 0:
                        break
                    sp -= 1
                    node = st_node[sp]
                    seg0 = st_t0[sp]
                    seg1 = st_t1[sp]
                    continue
                split = node_split(tree, node)
                right = word_payload(w0)
                if axis == TIME_AXIS:
                    node = node + 1 if t_days < split else right
                    continue
                o = ray[axis]
                d = ray[3 + axis]
                if d == 0.0:
                    if o < split:
                        node = node + 1
                    elif o > split:
                        node = right
                    else:
                        sp = push_segment(st_node, st_t0, st_t1, sp, right, seg0, seg1)
                        node = node + 1
                    continue
                t_split = (split - o) * ray[6 + axis]
                if d > 0.0:
                    near = node + 1
                    far = right
                else:
                    near = right
                    far = node + 1
                side, ts = split_side(t_split, seg0, seg1)
                if side == NEAR_ONLY:
                    node = near
                elif side == FAR_ONLY:
                    node = far
                else:
                    sp = push_segment(st_node, st_t0, st_t1, sp, far, ts, seg1)
                    node = near
                    seg1 = ts
        out[i] = crown_product(seen, n, crown_tau)


#: Rays per chunk handed to a thread.
CHUNK_RAYS = 1024


def transmission(tree, origins, direction, t_days, rays, tri_crown, crown_tau, out) -> None:
    """Fill ``out[rays]`` with the transmission of those sun rays through the crowns of the
    kd-tree ``tree`` (:class:`~cityshade.accel.kdtree_layout.KdTree` whose record ids index
    ``tri_crown`` (int32), the crown of each triangle; ``crown_tau`` (C,) float64 the
    transmissivity of each crown). ``origins`` (N, 3) float64, ``direction`` (3,) unit, one
    for every ray; ``rays`` int64 indices into ``origins``/``out``."""
    from cityshade.runtime.threadpool import run_chunks
    from cityshade.trace import padded_box

    if len(rays) == 0:
        return
    if tree.tri_records.shape[0] == 0:
        out[rays] = 1.0
        return
    lo, hi = padded_box(tree)
    run_chunks(crowns_range, len(rays), CHUNK_RAYS, tree.views, lo, hi, origins,
               np.ascontiguousarray(direction, dtype=np.float64), float(t_days),
               np.ascontiguousarray(rays, dtype=np.int64), tri_crown,
               np.ascontiguousarray(crown_tau, dtype=np.float64), out)
