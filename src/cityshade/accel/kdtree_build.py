"""Build the 4-D (x, y, z, time) SAH kd-tree of a scene's triangles.

The tree follows the thesis slides ("Data structure") and docs/DESIGN.md §5:

* Spatial splits are chosen by the surface-area heuristic (SAH): the probability that a ray
  which hits a node also hits a child is the ratio of their 3-D surface areas.
* Rays carry one constant time, so a node's "surface" is its 3-D surface area times its
  duration. A time split keeps the box, so its probability is the ratio of the durations.
  Open (infinite) validity ends are clamped to the model's finite time range for the heuristic;
  a model without dates never considers a time split and pays nothing for the fourth dimension.
* Straddling triangles go to both children with "perfect splits": the triangle is clipped to
  the child box (Sutherland-Hodgman) and the child keeps the clipped extent.
* Large nodes choose their plane from binned counts; nodes with at most
  ``KdTreeSettings.sweep_threshold`` references run the exact sorted event sweep of
  Wald & Havran, "On building fast kd-trees for ray tracing, and on doing that in O(N log N)"
  (2006), including their treatment of triangles lying in the plane.
* Termination by cost (``C_t + C_i (P_L N_L + P_R N_R)`` against ``C_i N``), with an
  empty-space bonus and a depth cap.
* Nodes with at most ``KdTreeSettings.subtree_refs`` references are built as independent
  subtrees, several at once from threads (the kernel runs without the GIL), and stitched back
  in depth-first order: the arrays are those of one undivided build for any thread count.

Every split position is a float32 value and every reference box is rounded outward to float32,
so the float32 node layout of :mod:`cityshade.accel.kdtree_layout` routes rays exactly as the
build classified the triangles.
"""
from __future__ import annotations

import time

import numpy as np
from numba import njit

from cityshade.accel.kdtree_layout import (LEAF_CODE, TIME_AXIS, KdTree, pack_nodes,
                                           triangle_records)
# The tunables (``[kdtree]``) live in a module without kernels: every command reads them.
from cityshade.accel.settings import MAX_DEPTH_LIMIT, KdTreeSettings
from cityshade.errors import KdTreeInputError
from cityshade.runtime.interpret import InterpretBudget, run_range, twin_if
from cityshade.runtime.memory import release_freed_memory

#: Axis code of a placeholder node whose subtree is built separately (never stored).
DEFERRED = -1

# --------------------------------------------------------------------------------------------
# Numba kernels
# --------------------------------------------------------------------------------------------

@njit(cache=True)
def _f32_down(x):
    """Largest float32 value <= x (as float64); infinities pass through."""
    f = np.float32(x)
    if float(f) > x:
        f = np.nextafter(f, np.float32(-np.inf))
    # np.float64, not float: interpreted (runtime/interpret.py) a Python float would make
    # NumPy compare a float32 with it in float32; Numba widens to float64 either way.
    return np.float64(f)


@njit(cache=True)
def _f32_up(x):
    """Smallest float32 value >= x (as float64); infinities pass through."""
    f = np.float32(x)
    if float(f) < x:
        f = np.nextafter(f, np.float32(np.inf))
    return np.float64(f)  # not float: see _f32_down


@njit(cache=True)
def _clip_poly(poly, src, dst, n, axis, value, keep_below):
    """Clip polygon ``poly[src, :, :n]`` to ``coord <= value`` (or ``>=``) into ``poly[dst]``;
    returns the new count.

    Points on the plane are kept (inclusive), and crossing points get their ``axis`` coordinate
    set exactly to ``value`` so clipping never drifts outside the box. One (2, 3, 16) buffer
    indexed in place: row views would cost a reference-count update each, per clip.
    """
    m = 0
    for i in range(n):
        j = (i + 1) % n
        ci = poly[src, axis, i]
        cj = poly[src, axis, j]
        di = (value - ci) if keep_below else (ci - value)
        dj = (value - cj) if keep_below else (cj - value)
        if di >= 0.0:
            for c in range(3):
                poly[dst, c, m] = poly[src, c, i]
            m += 1
        if (di > 0.0 and dj < 0.0) or (di < 0.0 and dj > 0.0):
            s = di / (di - dj)
            for c in range(3):
                poly[dst, c, m] = poly[src, c, i] + s * (poly[src, c, j] - poly[src, c, i])
            poly[dst, axis, m] = value
            m += 1
    return m


@njit(cache=True)
def _clipped_box(tri_v, tri, box_lo, box_hi, out_lo, out_hi, poly):
    """Bounding box of triangle ``tri`` clipped to the 3-D box; False if nothing is left.
    ``poly`` is a (2, 3, 16) float64 work buffer."""
    for i in range(3):
        for c in range(3):
            poly[0, c, i] = tri_v[tri, i, c]
    # Arguments as np.int64/np.bool_, not literals: Numba compiles a callee once per literal
    # value it is passed (and for the literal type a counter has before it is widened), so
    # literals here cost a compile each on first use (issue 40).
    n = np.int64(3)
    src0, dst1 = np.int64(0), np.int64(1)
    keep_above, keep_below = np.bool_(False), np.bool_(True)
    for axis in range(3):
        n = _clip_poly(poly, src0, dst1, n, axis, box_lo[axis], keep_above)
        if n == 0:
            return False
        n = _clip_poly(poly, dst1, src0, n, axis, box_hi[axis], keep_below)
        if n == 0:
            return False
    for axis in range(3):
        out_lo[axis] = np.inf
        out_hi[axis] = -np.inf
    for i in range(n):
        for axis in range(3):
            c = poly[0, axis, i]
            out_lo[axis] = min(out_lo[axis], c)
            out_hi[axis] = max(out_hi[axis], c)
    return True


@njit(cache=True)
def _area(lo, hi):
    """Surface area of the 3-D part of a 4-D box."""
    ex = hi[0] - lo[0]
    ey = hi[1] - lo[1]
    ez = hi[2] - lo[2]
    return 2.0 * (ex * ey + ex * ez + ey * ez)


@njit(cache=True)
def _surface(lo, hi, has_time, t0, t1):
    """The slides' 4-D "surface": 3-D area times the clamped duration (area alone if dateless)."""
    a = _area(lo, hi)
    if has_time:
        return a * (min(hi[3], t1) - max(lo[3], t0))
    return a


@njit(cache=True)
def _plane_terms(lo, hi, axis, t0, t1):
    """The per-node terms of the split probabilities on one axis, computed once per sweep:
    (start, end, cap, side, norm); ``norm`` <= 0 when the probabilities are undefined.

    A spatial split's probabilities are the child areas over the node's (the faces parallel
    to the plane, ``cap``, plus the perimeter ``side`` times the child's extent); a time
    split's are the ratios of the clamped durations."""
    if axis == TIME_AXIS:
        a = max(lo[3], t0)
        b = min(hi[3], t1)
        return a, b, 0.0, 0.0, b - a
    ex = hi[0] - lo[0]
    ey = hi[1] - lo[1]
    ez = hi[2] - lo[2]
    area = 2.0 * (ex * ey + ex * ez + ey * ez)
    if axis == 0:
        e1, e2 = ey, ez
    elif axis == 1:
        e1, e2 = ex, ez
    else:
        e1, e2 = ex, ey
    return lo[axis], hi[axis], e1 * e2, e1 + e2, area


@njit(cache=True, inline="always")
def _probabilities_at(is_time, p, start, end, cap, side, norm):
    """(P_L, P_R) of a split at ``p`` from :func:`_plane_terms`; scalars only (passing the
    box arrays per event would cost reference-count updates each)."""
    if is_time:
        return (p - start) / norm, (end - p) / norm
    return 2.0 * (cap + (p - start) * side) / norm, 2.0 * (cap + (end - p) * side) / norm


@njit(cache=True)
def _split_cost(pl, pr, nl, nr, ct, ci, bonus):
    cost = ct + ci * (pl * nl + pr * nr)
    if nl == 0 or nr == 0:
        cost *= 1.0 - bonus
    return cost


@njit(cache=True)
def _sweep_axis(lo, hi, axis, ord_lo, ord_hi, blo, bhi, t0, t1, ct, ci, bonus, best,
                events):
    """Exact SAH sweep over the sorted events of one axis (Wald & Havran 2006, §4.2).

    ``ord_lo`` / ``ord_hi`` list the references in increasing ``lo`` / ``hi`` on ``axis``
    (kept sorted from node to node by :func:`_child_orders`, so no sort happens here).
    ``best`` = [cost, axis, position, planar_left] is updated in place when a cheaper plane is
    found. Events: a start at ``lo``, an end at ``hi``, or a planar event when ``lo == hi``.
    ``events`` is a (3, >= n) float64 work buffer (rows: starts, ends, planars), allocated once
    per build instead of three arrays per node and axis.
    """
    n = lo.shape[0]
    ns = 0
    npl = 0
    for i in range(n):
        r = ord_lo[i]
        a = lo[r, axis]
        if a == hi[r, axis]:
            events[2, npl] = a
            npl += 1
        else:
            events[0, ns] = a
            ns += 1
    ne = 0
    for i in range(n):
        r = ord_hi[i]
        b = hi[r, axis]
        if lo[r, axis] != b:
            events[1, ne] = b
            ne += 1
    is_time = axis == TIME_AXIS
    if is_time:
        a_lo = max(blo[3], t0)
        a_hi = min(bhi[3], t1)
    else:
        a_lo = blo[axis]
        a_hi = bhi[axis]
    start, end, cap, side, norm = _plane_terms(blo, bhi, axis, t0, t1)
    i = 0
    j = 0
    k = 0
    n_left = np.int64(0)  # not a literal: one compile of _split_cost (_clipped_box says why)
    n_right = n
    while i < ns or j < ns or k < npl:
        p = np.inf
        if i < ns:
            p = events[0, i]
        if j < ns and events[1, j] < p:
            p = events[1, j]
        if k < npl and events[2, k] < p:
            p = events[2, k]
        p_end = 0
        while j < ns and events[1, j] == p:
            j += 1
            p_end += 1
        p_planar = 0
        while k < npl and events[2, k] == p:
            k += 1
            p_planar += 1
        p_start = 0
        while i < ns and events[0, i] == p:
            i += 1
            p_start += 1
        if p == np.inf:
            break
        n_right -= p_planar + p_end
        if a_lo < p < a_hi and norm > 0.0:
            pl, pr = _probabilities_at(is_time, p, start, end, cap, side, norm)
            c_left = _split_cost(pl, pr, n_left + p_planar, n_right, ct, ci, bonus)
            if c_left < best[0]:
                best[0] = c_left
                best[1] = axis
                best[2] = p
                best[3] = 1.0
            # Without planar events both sides cost the same: only the left one can win.
            if p_planar:
                c_right = _split_cost(pl, pr, n_left, n_right + p_planar, ct, ci, bonus)
                if c_right < best[0]:
                    best[0] = c_right
                    best[1] = axis
                    best[2] = p
                    best[3] = 0.0
        n_left += p_start + p_planar


@njit(cache=True)
def _binned_axis(lo, hi, axis, blo, bhi, t0, t1, ct, ci, bonus, nbins, best):
    """Approximate SAH over ``nbins`` equal bins of one axis (counts per bin, O(n))."""
    n = lo.shape[0]
    if axis == TIME_AXIS:
        a = max(blo[3], t0)
        b = min(bhi[3], t1)
    else:
        a = blo[axis]
        b = bhi[axis]
    if not (b > a):
        return
    scale = nbins / (b - a)
    is_time = axis == TIME_AXIS
    start, end, cap, side, norm = _plane_terms(blo, bhi, axis, t0, t1)
    # np.empty and a loop, not np.zeros: its overload and fill compile apart (issue 40).
    start_count = np.empty(nbins, np.int64)
    end_count = np.empty(nbins, np.int64)
    for i in range(nbins):
        start_count[i] = 0
        end_count[i] = 0
    for r in range(n):
        # Widened as Numba does: interpreted, NumPy would subtract a Python float ``t0`` in
        # float32 (runtime/interpret.py).
        x = np.float64(lo[r, axis])
        if x <= a:
            sb = 0
        elif x >= b:
            sb = nbins - 1
        else:
            sb = min(int((x - a) * scale), nbins - 1)
        x = np.float64(hi[r, axis])
        if x <= a:
            eb = 0
        elif x >= b:
            eb = nbins - 1
        else:
            eb = min(int((x - a) * scale), nbins - 1)
        start_count[sb] += 1
        end_count[eb] += 1
    n_left = np.int64(0)  # not a literal: one compile of _split_cost (_clipped_box says why)
    n_right = n
    for i in range(1, nbins):
        n_left += start_count[i - 1]
        n_right -= end_count[i - 1]
        p = _f32_down(a + i * (b - a) / nbins)
        if not (a < p < b) or norm <= 0.0:
            continue
        pl, pr = _probabilities_at(is_time, p, start, end, cap, side, norm)
        c = _split_cost(pl, pr, n_left, n_right, ct, ci, bonus)
        if c < best[0]:
            best[0] = c
            best[1] = axis
            best[2] = p
            best[3] = 1.0


#: Bits per pass of the event sort (three passes cover a 32-bit key).
RADIX_BITS = 11


@njit(cache=True)
def _f32_key(u):
    """Order-preserving unsigned image of the float32 bits ``u`` (uint32): sign flipped for
    positives, all bits for negatives; -0.0 keyed as +0.0, so ties are a comparison's."""
    sign = np.uint32(0x80000000)
    if u == sign:  # -0.0
        u = np.uint32(0)
    return ~u if u & sign else u | sign


@njit(cache=True)
def _heapsort(keys, n):
    """Sort ``keys[:n]`` (int64) in place, ascending: a heapsort, O(n log n), no allocation.
    Written by hand: ``np.sort``/``np.argsort`` in a kernel instantiate Numba's quicksort or
    mergesort, 1.5-2 s of first-use compiling each (issue 40)."""
    top = n // 2
    m = n
    while True:
        if top > 0:  # heap construction: sift down every inner node
            top -= 1
            x = keys[top]
        else:  # the largest goes behind the heap, the last one is sifted down from the root
            m -= 1
            if m <= 0:
                break
            x = keys[m]
            keys[m] = keys[0]
        j = top
        c = 2 * j + 1
        while c < m:
            if c + 1 < m and keys[c + 1] > keys[c]:
                c += 1
            if keys[c] <= x:
                break
            keys[j] = keys[c]
            j = c
            c = 2 * j + 1
        keys[j] = x


@njit(cache=True)
def _radix_order(values, out, keys, keys_tmp, idx_tmp, counts):
    """Stable order of the float32 ``values`` into ``out`` (int32): an LSD radix sort on the
    order-preserving unsigned image of the bits (sign flipped for positives, all bits for
    negatives; -0.0 keyed as +0.0, so ties are those of a comparison sort). Three passes of
    ``RADIX_BITS`` bits; a pass whose digit is the same for every key (the high bits of the
    coordinates of one node usually are) is skipped. It is 3-4x cheaper than a comparison
    argsort on the event columns; only sorted values reach the sweep, so the tree is the same.
    ``counts`` is a (3, 2^RADIX_BITS) int64 work buffer, the others (>= n,) like ``out``."""
    n = values.shape[0]
    bits = values.view(np.uint32)
    mask = np.uint32((1 << RADIX_BITS) - 1)
    for d in range(3):  # loops, not ``counts[:] = 0``: see _grow
        for b in range(counts.shape[1]):
            counts[d, b] = 0
    for i in range(n):
        k = _f32_key(bits[i])
        keys[i] = k
        out[i] = i
        for d in range(3):
            counts[d, (k >> np.uint32(d * RADIX_BITS)) & mask] += 1
    src_k, src_i, dst_k, dst_i = keys, out, keys_tmp, idx_tmp
    in_out = True
    for d in range(3):
        if counts[d, (src_k[0] >> np.uint32(d * RADIX_BITS)) & mask] == n:
            continue  # one digit for all: this pass would not move anything
        total = 0
        for b in range(counts.shape[1]):
            c = counts[d, b]
            counts[d, b] = total
            total += c
        for i in range(n):
            b = (src_k[i] >> np.uint32(d * RADIX_BITS)) & mask
            w = counts[d, b]
            counts[d, b] = w + 1
            dst_k[w] = src_k[i]
            dst_i[w] = src_i[i]
        src_k, src_i, dst_k, dst_i = dst_k, dst_i, src_k, src_i
        in_out = not in_out
    if not in_out:
        for i in range(n):  # loops, not slice copies: see _grow
            out[i] = src_i[i]


@njit(cache=True)
def _event_orders(lo, hi, n_axes):
    """(8, n) int32: row 2a lists the references by increasing ``lo[:, a]``, row 2a + 1 by
    increasing ``hi[:, a]`` (rows past ``n_axes`` unused). Sorted once where a node enters
    the exact sweep; its descendants inherit them through :func:`_child_orders`."""
    n = lo.shape[0]
    orders = np.empty((8, n), np.int32)
    if n == 0:
        return orders
    column = np.empty(n, np.float32)
    keys = np.empty(n, np.uint32)
    keys_tmp = np.empty(n, np.uint32)
    idx_tmp = np.empty(n, np.int32)
    counts = np.empty((3, 1 << RADIX_BITS), np.int64)
    for q in range(2 * n_axes):
        for i in range(n):
            column[i] = hi[i, q >> 1] if q & 1 else lo[i, q >> 1]
        _radix_order(column, orders[q], keys, keys_tmp, idx_tmp, counts)
    return orders


@njit(cache=True)
def _sort_by_value(refs, lo, hi, axis, use_hi, out):
    """``refs`` sorted by ``hi[:, axis]`` (``use_hi``) or ``lo[:, axis]``, into ``out``:
    insertion sort for the usual few, a heapsort of (value key, position) beyond 32 (ties in
    any order: only the sorted values reach the sweep)."""
    k = refs.shape[0]
    if k > 32:
        value = np.empty(k, np.float32)
        for i in range(k):
            value[i] = hi[refs[i], axis] if use_hi else lo[refs[i], axis]
        bits = value.view(np.uint32)
        key = np.empty(k, np.int64)
        for i in range(k):
            # The unsigned key shifted to a signed range first: its top bit would be the sign.
            key[i] = ((np.int64(_f32_key(bits[i])) - 0x80000000) << 32) | i
        _heapsort(key, k)
        for i in range(k):
            out[i] = refs[key[i] & 0xFFFFFFFF]
        return
    for i in range(k):
        r = refs[i]
        v = hi[r, axis] if use_hi else lo[r, axis]
        j = i
        while j > 0:
            w = hi[out[j - 1], axis] if use_hi else lo[out[j - 1], axis]
            if w <= v:
                break
            out[j] = out[j - 1]
            j -= 1
        out[j] = r


@njit(cache=True)
def _merge_by_value(rest, n_rest, extra, lo, hi, axis, use_hi, out, q):
    """Merge two index lists, each sorted by ``hi`` or ``lo`` on ``axis``, into ``out[q]``."""
    i = 0
    j = 0
    m = 0
    n_extra = extra.shape[0]
    while i < n_rest and j < n_extra:
        a = rest[i]
        b = extra[j]
        va = hi[a, axis] if use_hi else lo[a, axis]
        vb = hi[b, axis] if use_hi else lo[b, axis]
        if va <= vb:
            out[q, m] = a
            i += 1
        else:
            out[q, m] = b
            j += 1
        m += 1
    while i < n_rest:
        out[q, m] = rest[i]
        i += 1
        m += 1
    while j < n_extra:
        out[q, m] = extra[j]
        j += 1
        m += 1


@njit(cache=True)
def _child_orders(p_ord, o, n, side, work, lo_l, hi_l, lo_r, hi_r, n_axes, clipped):
    """The event orders of both children from the parent's (Wald & Havran 2006, §4.3), in the
    order pool: the parent's in columns ``o .. o + n``, the right child's written over them
    (``o .. o + n_r``), the left child's just behind (``o + n_r .. o + n_r + n_l``).

    A reference on one side keeps its box, so filtering the parent's order keeps it sorted.
    When ``clipped`` (a spatial split), the straddling references have new, clipped boxes:
    they alone are sorted (usually a few) and merged in. After a time split every box is
    unchanged and filtering suffices. ``work`` is an (8, >= n) int32 work buffer.
    """
    map_l, map_r, both_l, both_r = work[0], work[1], work[2], work[3]
    rest_l, rest_r, extra_l, extra_r = work[4], work[5], work[6], work[7]
    n_l = lo_l.shape[0]
    n_r = lo_r.shape[0]
    il = 0
    ir = 0
    n_both = 0
    for r in range(n):
        s = side[r]
        if s & 1:
            map_l[r] = il
            il += 1
        if s & 2:
            map_r[r] = ir
            ir += 1
        if s == 3:
            n_both += 1
    if not clipped:
        n_both = 0
    k = 0
    if n_both:
        for r in range(n):
            if side[r] == 3:
                both_l[k] = map_l[r]
                both_r[k] = map_r[r]
                k += 1
    # The left child's orders go behind the parent's first (the parent's are still read),
    # then move down next to the right child's.
    out_l = p_ord[:, o + n:o + n + n_l]
    out_r = p_ord[:, o:o + n_r]
    for q in range(2 * n_axes):
        axis = q >> 1
        use_hi = (q & 1) == 1
        row = p_ord[q, o:o + n]
        nl = np.int64(0)  # not literals: one compile of _merge_by_value (_clipped_box)
        nr = np.int64(0)
        if n_both == 0:  # nothing re-sorted: the filtered orders are the children's
            for i in range(n):  # the right child's written in place: nr <= i
                r = row[i]
                s = side[r]
                if s & 1:
                    out_l[q, nl] = map_l[r]
                    nl += 1
                if s & 2:
                    out_r[q, nr] = map_r[r]
                    nr += 1
            continue
        for i in range(n):
            r = row[i]
            s = side[r]
            if s == 3:
                continue
            if s & 1:
                rest_l[nl] = map_l[r]
                nl += 1
            if s & 2:
                rest_r[nr] = map_r[r]
                nr += 1
        _sort_by_value(both_l[:n_both], lo_l, hi_l, axis, use_hi, extra_l)
        _sort_by_value(both_r[:n_both], lo_r, hi_r, axis, use_hi, extra_r)
        _merge_by_value(rest_l, nl, extra_l[:n_both], lo_l, hi_l, axis, use_hi, out_l, q)
        _merge_by_value(rest_r, nr, extra_r[:n_both], lo_r, hi_r, axis, use_hi, out_r, q)
    for q in range(2 * n_axes):
        for i in range(n_l):
            p_ord[q, o + n_r + i] = p_ord[q, o + n + i]


@njit(cache=True)
def _grow(a, n):
    """``a`` with room for at least ``n`` entries (doubling; the first entries kept)."""
    if n <= a.shape[0]:
        return a
    b = np.empty(max(n, 2 * a.shape[0]), a.dtype)
    # Copied by a loop: a slice copy (``b[:m] = a``) makes Numba compile its shape-mismatch
    # message (string formatting) once per pair of ranks, seconds of first-use compiling.
    for i in range(a.shape[0]):
        b[i] = a[i]
    return b


@njit(cache=True)
def _grow_2d(a, n, columns):
    """2-D ``a`` with room for at least ``n`` rows (or ``columns``), growing by half; the
    first kept."""
    rows, cols = a.shape
    size = cols if columns else rows
    if n <= size:
        return a
    size = max(n, size + size // 2)
    b = np.empty((rows, size), a.dtype) if columns else np.empty((size, cols), a.dtype)
    for r in range(rows):  # loops, not slice copies: see _grow
        for c in range(cols):
            b[r, c] = a[r, c]
    return b


@njit(cache=True)
def _add_task(t_meta, t_box, k, start, n, depth, blo, bhi):
    """Record task ``k``: its references are rows ``start .. start + n`` of the task pool, its
    node box ``blo``-``bhi`` and depth go into ``t_meta`` (3 per task) and ``t_box`` (8 per
    task); returns the two arrays, grown if needed. Arrays, not typed lists: a typed list's
    methods took seconds of first-use compiling (issue 40)."""
    t_meta = _grow(t_meta, 3 * k + 3)
    t_box = _grow(t_box, 8 * k + 8)
    t_meta[3 * k] = start
    t_meta[3 * k + 1] = n
    t_meta[3 * k + 2] = depth
    for c in range(4):
        t_box[8 * k + c] = blo[c]
        t_box[8 * k + 4 + c] = bhi[c]
    return t_meta, t_box


@njit(cache=True, nogil=True)
def _build_kernel(tri_v, material, ids0, lo0, hi0, root_lo, root_hi, has_time, t0, t1,
                  ct, ci, bonus, max_depth, min_leaf, sweep_threshold, nbins, depth0,
                  root_surface, defer_n):
    """Depth-first build with an explicit stack; returns the raw node and primitive arrays.

    Output nodes are in depth-first order: the left child of inner node i is i + 1, and
    ``node_child[i]`` is the right child; a leaf holds ``node_child`` = count and
    ``node_first`` = first index into ``prims``.

    The node ``root_lo``-``root_hi`` at depth ``depth0`` is the root of this call; the SAH
    statistic is relative to ``root_surface`` (the whole tree's). A node with at most
    ``defer_n`` references (``defer_n`` > 0) is not built but left as a placeholder
    (axis ``DEFERRED``, ``node_first`` = its index in the returned task lists): the caller
    builds it with this kernel (``defer_n`` = 0) and puts the result in its place. A node's
    subtree depends only on the node, so the stitched tree equals the undivided build.
    Runs without the GIL (nogil), so several subtrees are built at once from threads.

    The references of the nodes on the stack live in one pool used as a stack: a node is a
    range of rows, its children are written behind it and moved down over it (right child
    first, so the left child, popped next, is on top). Event orders of swept nodes live in a
    second pool the same way. Nothing is allocated per node: a tree of 10^6 nodes would
    otherwise make some 2 x 10^7 small allocations.
    """
    n_tri = ids0.shape[0]
    # Leaf order key (material, triangle id): ids are below the scene's triangle count.
    n_key = np.int64(tri_v.shape[0]) + 1
    cap = max(16, 4 * n_tri // 3)
    node_axis = np.empty(cap, np.int64)
    node_child = np.empty(cap, np.int64)
    node_first = np.empty(cap, np.int64)
    node_split = np.empty(cap)  # each form of np.empty's dtype compiles an overload of its own
    prims = np.empty(max(16, 2 * n_tri), np.int64)
    n_nodes = 0
    n_prims = 0

    scratch = np.empty((2, 3, 16))
    n_sweep = max(1, min(sweep_threshold, n_tri))
    events = np.empty((3, n_sweep))
    clo = np.empty(3)
    chi = np.empty(3)

    # Reference pool (rows: id, box low, box high) and event-order pool (8 rows, columns).
    p_cap = max(64, 2 * n_tri)
    p_ids = np.empty(p_cap, ids0.dtype)
    p_lo = np.empty((p_cap, 4), lo0.dtype)
    p_hi = np.empty((p_cap, 4), hi0.dtype)
    for i in range(n_tri):  # loops, not slice copies: see _grow
        p_ids[i] = ids0[i]
        for c in range(4):
            p_lo[i, c] = lo0[i, c]
            p_hi[i, c] = hi0[i, c]
    p_ord = np.empty((8, 4 * n_sweep + 64), np.int32)
    # Per-node work buffers: sides of every node, the order bookkeeping of swept ones
    # (children of a swept node have at most as many references as it has).
    side = np.empty(max(1, n_tri), np.int8)
    work = np.empty((8, n_sweep), np.int32)
    blo = np.empty(4)
    bhi = np.empty(4)
    blo_l = np.empty(4)
    bhi_l = np.empty(4)
    blo_r = np.empty(4)
    bhi_r = np.empty(4)

    n_stack = 4 * MAX_DEPTH_LIMIT + 8
    st_start = np.empty(n_stack, np.int64)   # first pool row
    st_n = np.empty(n_stack, np.int64)       # reference count
    st_ord = np.empty(n_stack, np.int64)     # first order-pool column
    st_sorted = np.empty(n_stack, np.int8)   # event orders present (exact sweep); int8 as
    #                                          ``side``: one np.empty overload fewer
    st_task = np.empty(n_stack, np.int64)    # deferred: its task index, else -1
    st_blo = np.empty((n_stack, 4))
    st_bhi = np.empty((n_stack, 4))
    st_depth = np.empty(n_stack, np.int64)
    st_parent = np.empty(n_stack, np.int64)
    st_start[0] = 0
    st_n[0] = n_tri
    st_ord[0] = 0
    st_sorted[0] = 0
    for c in range(4):  # loops, not row copies: see _grow
        st_blo[0, c] = root_lo[c]
        st_bhi[0, c] = root_hi[c]
    st_depth[0] = depth0
    st_parent[0] = -1
    st_task[0] = -1
    sp = 1

    # Deferred subtrees: their references one after the other in a task pool (rows: id, box
    # low, box high), each task a range of it (see _add_task).
    t_cap = n_tri + 16 if defer_n > 0 else 16
    t_ids = np.empty(t_cap, ids0.dtype)
    t_lo = np.empty((t_cap, 4), lo0.dtype)
    t_hi = np.empty((t_cap, 4), hi0.dtype)
    t_meta = np.empty(48, np.int64)
    t_box = np.empty(128)
    t_n = np.int64(0)  # not literals: one compile of _add_task (_clipped_box says why)
    n_tasks = np.int64(0)
    sah = 0.0
    n_leaves = 0
    n_empty = 0
    depth_max = 0
    depth_sum = 0
    time_splits = 0
    best = np.empty(4)

    while sp > 0:
        sp -= 1
        s0 = st_start[sp]
        n = st_n[sp]
        o = st_ord[sp]
        has_orders = st_sorted[sp] != 0
        for c in range(4):
            blo[c] = st_blo[sp, c]
            bhi[c] = st_bhi[sp, c]
        depth = st_depth[sp]
        parent = st_parent[sp]
        task = st_task[sp]
        ids = p_ids[s0:s0 + n]
        lo = p_lo[s0:s0 + n]
        hi = p_hi[s0:s0 + n]

        node = n_nodes
        n_nodes += 1
        if n_nodes > node_axis.shape[0]:
            node_axis = _grow(node_axis, n_nodes)
            node_child = _grow(node_child, n_nodes)
            node_first = _grow(node_first, n_nodes)
            node_split = _grow(node_split, n_nodes)
        if parent >= 0:
            node_child[parent] = node
        if task >= 0:
            # A child deferred when its parent split (its references went to the task).
            node_axis[node] = DEFERRED
            node_child[node] = 0
            node_first[node] = task
            node_split[node] = 0.0
            continue
        if defer_n > 0 and n <= defer_n:  # the root of this call only
            # Defer: built later as an independent subtree and stitched in at this node.
            node_axis[node] = DEFERRED
            node_child[node] = 0
            node_first[node] = n_tasks
            node_split[node] = 0.0
            if t_n + n > t_ids.shape[0]:
                t_ids = _grow(t_ids, t_n + n)
                t_lo = _grow_2d(t_lo, t_n + n, False)
                t_hi = _grow_2d(t_hi, t_n + n, False)
            for i in range(n):  # loops, not slice copies: see _grow
                t_ids[t_n + i] = ids[i]
                for c in range(4):
                    t_lo[t_n + i, c] = lo[i, c]
                    t_hi[t_n + i, c] = hi[i, c]
            t_meta, t_box = _add_task(t_meta, t_box, n_tasks, t_n, n, depth, blo, bhi)
            t_n += n
            n_tasks += 1
            continue
        surf = _surface(blo, bhi, has_time, t0, t1) / root_surface

        # Choose the cheapest plane over all axes, if splitting is allowed at all.
        best[0] = np.inf
        best[1] = -1.0
        n_axes = 4 if has_time else 3
        sweep = n <= sweep_threshold
        if n > min_leaf and depth < max_depth:
            if sweep and not has_orders:
                p_ord = _grow_2d(p_ord, o + n, True)
                orders = _event_orders(lo, hi, n_axes)
                for q in range(2 * n_axes):  # loops, not a slice copy: see _grow
                    for i in range(n):
                        p_ord[q, o + i] = orders[q, i]
                has_orders = True
            for axis in range(n_axes):
                if not sweep:
                    _binned_axis(lo, hi, axis, blo, bhi, t0, t1, ct, ci, bonus, nbins, best)
                else:
                    _sweep_axis(lo, hi, axis, p_ord[2 * axis, o:o + n],
                                p_ord[2 * axis + 1, o:o + n], blo, bhi, t0, t1, ct, ci, bonus,
                                best, events)
        if best[1] < 0.0 or best[0] >= ci * n:
            # Leaf: references sorted by (material, triangle id) make the draw batches.
            prims = _grow(prims, n_prims + n)
            if n <= 32:
                # Insertion sort in place (keys are unique): most leaves hold a few
                # references (no key and order arrays per leaf).
                for r in range(n):
                    t = ids[r]
                    k = (np.int64(material[t]) + 1) * n_key + t
                    j = n_prims + r
                    while j > n_prims:
                        u = prims[j - 1]
                        if (np.int64(material[u]) + 1) * n_key + u <= k:
                            break
                        prims[j] = u
                        j -= 1
                    prims[j] = t
            else:
                key = np.empty(n, np.int64)
                for r in range(n):
                    key[r] = (np.int64(material[ids[r]]) + 1) * n_key + ids[r]
                _heapsort(key, n)  # unique keys: any sort gives this order
                for r in range(n):
                    prims[n_prims + r] = key[r] % n_key
            node_axis[node] = LEAF_CODE
            node_child[node] = n
            node_first[node] = n_prims
            node_split[node] = 0.0
            n_prims += n
            n_leaves += 1
            if n == 0:
                n_empty += 1
            depth_max = max(depth_max, depth)
            depth_sum += depth
            sah += ci * n * surf
            continue

        axis = int(best[1])
        p = best[2]
        planar_left = best[3] > 0.5
        sah += ct * surf
        if axis == TIME_AXIS:
            time_splits += 1

        # Classify: 1 = left only, 2 = right only, 3 = both (straddling, clipped below).
        n_l = np.int64(0)  # not literals: one compile of _add_task (_clipped_box says why)
        n_r = np.int64(0)
        for r in range(n):
            a = lo[r, axis]
            b = hi[r, axis]
            if axis == TIME_AXIS:
                s = (1 if a < p else 0) | (2 if b > p else 0)
            elif a == b and a == p:
                s = 1 if planar_left else 2
            elif b <= p:
                s = 1
            elif a >= p:
                s = 2
            else:
                s = 3
            side[r] = s
            if s & 1:
                n_l += 1
            if s & 2:
                n_r += 1

        for c in range(4):
            blo_l[c] = blo[c]
            bhi_l[c] = bhi[c]
            blo_r[c] = blo[c]
            bhi_r[c] = bhi[c]
        bhi_l[axis] = p
        blo_r[axis] = p
        # The left child is written behind the node (rows l0 ..), the right child over the
        # node itself (its row ir <= r, so no row is overwritten before it is read). A child
        # small enough to be deferred goes straight into its own task arrays instead.
        defer_l = defer_n > 0 and n_l <= defer_n
        defer_r = defer_n > 0 and n_r <= defer_n
        l0 = s0 + n
        if l0 + n_l > p_ids.shape[0]:
            p_ids = _grow(p_ids, l0 + n_l)
            p_lo = _grow_2d(p_lo, l0 + n_l, False)
            p_hi = _grow_2d(p_hi, l0 + n_l, False)
        d_ids_l, d_lo_l, d_hi_l, bl = p_ids, p_lo, p_hi, l0
        d_ids_r, d_lo_r, d_hi_r, br = p_ids, p_lo, p_hi, s0
        t_need = t_n + (n_l if defer_l else 0) + (n_r if defer_r else 0)
        if t_need > t_ids.shape[0]:
            t_ids = _grow(t_ids, t_need)
            t_lo = _grow_2d(t_lo, t_need, False)
            t_hi = _grow_2d(t_hi, t_need, False)
        if defer_l:
            d_ids_l, d_lo_l, d_hi_l, bl = t_ids, t_lo, t_hi, t_n
        if defer_r:
            d_ids_r, d_lo_r, d_hi_r, br = t_ids, t_lo, t_hi, t_n + (n_l if defer_l else 0)
        il = 0
        ir = 0
        for r in range(n):
            s = side[r]
            if s & 1:
                # Written out for each side: a shared helper taking the 17 arguments costs
                # 40 % of the whole build (1M-triangle city, 10.1 s against 7.2 s), even inlined.
                w = bl + il
                d_ids_l[w] = ids[r]
                for c in range(4):
                    d_lo_l[w, c] = lo[r, c]
                    d_hi_l[w, c] = hi[r, c]
                if s == 3 and axis != TIME_AXIS:
                    # Perfect split: the true extent of the triangle inside the child box.
                    if _clipped_box(tri_v, ids[r], blo_l, bhi_l, clo, chi, scratch):
                        for c in range(3):
                            d_lo_l[w, c] = max(lo[r, c], max(blo_l[c], _f32_down(clo[c])))
                            d_hi_l[w, c] = min(hi[r, c], min(bhi_l[c], _f32_up(chi[c])))
                    else:
                        d_hi_l[w, axis] = p
                il += 1
            if s & 2:
                w = br + ir
                d_ids_r[w] = ids[r]
                for c in range(4):
                    d_lo_r[w, c] = lo[r, c]
                    d_hi_r[w, c] = hi[r, c]
                if s == 3 and axis != TIME_AXIS:
                    if _clipped_box(tri_v, ids[r], blo_r, bhi_r, clo, chi, scratch):
                        for c in range(3):
                            d_lo_r[w, c] = max(d_lo_r[w, c], max(blo_r[c], _f32_down(clo[c])))
                            d_hi_r[w, c] = min(d_hi_r[w, c], min(bhi_r[c], _f32_up(chi[c])))
                    else:
                        d_lo_r[w, axis] = p
                ir += 1
        # Left child down next to the right one (destination below the source).
        n_r_pool = 0 if defer_r else n_r
        if not defer_l:
            for i in range(n_l):
                p_ids[s0 + n_r_pool + i] = p_ids[l0 + i]
                for c in range(4):
                    p_lo[s0 + n_r_pool + i, c] = p_lo[l0 + i, c]
                    p_hi[s0 + n_r_pool + i, c] = p_hi[l0 + i, c]
        task_l = -1
        task_r = -1
        # Tasks are numbered as they are made; the stitch finds each by its placeholder's
        # node_first, so the numbering never shows in the tree.
        if defer_l:
            task_l = n_tasks
            t_meta, t_box = _add_task(t_meta, t_box, n_tasks, bl, n_l, depth + 1, blo_l, bhi_l)
            n_tasks += 1
        if defer_r:
            task_r = n_tasks
            t_meta, t_box = _add_task(t_meta, t_box, n_tasks, br, n_r, depth + 1, blo_r, bhi_r)
            n_tasks += 1
        t_n = t_need

        node_axis[node] = axis
        node_split[node] = p
        node_first[node] = 0
        child_orders = (sweep and depth + 1 < max_depth and (n_l > min_leaf or n_r > min_leaf)
                        and not (defer_l or defer_r))  # a task sorts anew, so does its sibling
        if child_orders:
            p_ord = _grow_2d(p_ord, o + n + n_l, True)
            _child_orders(p_ord, o, n, side, work, p_lo[s0 + n_r:s0 + n_r + n_l],
                          p_hi[s0 + n_r:s0 + n_r + n_l], p_lo[s0:s0 + n_r], p_hi[s0:s0 + n_r],
                          n_axes, axis != TIME_AXIS)
        # Push the right child first so the left child is emitted next, at node + 1.
        st_start[sp] = s0
        st_n[sp] = n_r
        st_ord[sp] = o
        st_sorted[sp] = 1 if child_orders else 0
        for c in range(4):
            st_blo[sp, c] = blo_r[c]
            st_bhi[sp, c] = bhi_r[c]
        st_depth[sp] = depth + 1
        st_parent[sp] = node
        st_task[sp] = task_r
        sp += 1
        st_start[sp] = s0 + n_r_pool
        st_n[sp] = n_l
        st_ord[sp] = o + n_r if child_orders else o
        st_sorted[sp] = 1 if child_orders else 0
        for c in range(4):
            st_blo[sp, c] = blo_l[c]
            st_bhi[sp, c] = bhi_l[c]
        st_depth[sp] = depth + 1
        st_parent[sp] = -1
        st_task[sp] = task_l
        sp += 1

    stats = np.array([float(n_leaves), float(n_empty), float(depth_max), float(depth_sum),
                      float(time_splits), sah])
    # Copies, so the over-allocated buffers (4/3 nodes and 2 references per input reference)
    # are freed now and not kept alive by views until the subtrees are stitched.
    return (node_axis[:n_nodes].copy(), node_child[:n_nodes].copy(),
            node_first[:n_nodes].copy(), node_split[:n_nodes].copy(), prims[:n_prims].copy(),
            stats,
            (t_ids[:t_n], t_lo[:t_n], t_hi[:t_n], t_meta[:3 * n_tasks], t_box[:8 * n_tasks]))


#: Triangles (or references) per call of the corner and box kernels: some 0.5-1 ms of work, so
#: the call per chunk is lost in it.
CORNER_CHUNK = 1 << 16


@njit(cache=True, nogil=True)
def _corners_range(vertices, triangles, tri_v, i0, i1):
    """The (3, 3) float32 corners of triangles ``i0 .. i1`` into ``tri_v``."""
    for t in range(i0, i1):
        for i in range(3):
            v = triangles[t, i]
            for c in range(3):
                tri_v[t, i, c] = vertices[v, c]


@njit(cache=True, nogil=True)
def _boxes_range(tri_v, ids, t_begin, t_end, lo, hi, i0, i1):
    """The float32 low and high box corners of references ``i0 .. i1`` (triangles ``ids``):
    corner extents, and the validity rounded outward to float32 (so every time split is a
    float32 value, see the module doc)."""
    for r in range(i0, i1):
        t = ids[r]
        for c in range(3):
            lo[r, c] = min(tri_v[t, 0, c], min(tri_v[t, 1, c], tri_v[t, 2, c]))
            hi[r, c] = max(tri_v[t, 0, c], max(tri_v[t, 1, c], tri_v[t, 2, c]))
        lo[r, 3] = np.float32(_f32_down(t_begin[t]))
        hi[r, 3] = np.float32(_f32_up(t_end[t]))


def _corners_and_boxes(vertices, triangles, ids, t_begin, t_end, interpret=False):
    """The (T, 3, 3) float32 corners of every triangle and the (K, 4) float32 low and high
    box corners of the triangles ``ids``. Serial kernels over chunks on the thread pool, not
    ``prange`` ones: those took 2-3x longer to compile on first use (issue 40)."""
    tri_v = np.empty((triangles.shape[0], 3, 3), np.float32)
    run_range(_corners_range, interpret, triangles.shape[0], CORNER_CHUNK, vertices, triangles,
              tri_v)
    lo = np.empty((ids.shape[0], 4), np.float32)
    hi = np.empty((ids.shape[0], 4), np.float32)
    run_range(_boxes_range, interpret, ids.shape[0], CORNER_CHUNK, tri_v, ids, t_begin, t_end,
              lo, hi)
    return tri_v, lo, hi


# --------------------------------------------------------------------------------------------
# Public API
# --------------------------------------------------------------------------------------------

def _task_inputs(tasks) -> list[tuple]:
    """Each deferred subtree's inputs (references, boxes, node box, depth) copied out of the
    kernel's task pool, so each is freed once its subtree is built (the pool goes now)."""
    t_ids, t_lo, t_hi, t_meta, t_box = tasks
    inputs = []
    for k in range(t_meta.size // 3):
        start, n, depth = (int(x) for x in t_meta[3 * k:3 * k + 3])
        inputs.append((t_ids[start:start + n].copy(), t_lo[start:start + n].copy(),
                       t_hi[start:start + n].copy(), t_box[8 * k:8 * k + 4].copy(),
                       t_box[8 * k + 4:8 * k + 8].copy(), depth))
    return inputs


def _build_subtrees(tri_v, material, inputs, constants, root_surface,
                    interpret=False) -> list[tuple]:
    """Build every deferred subtree of :func:`_task_inputs` (largest first, one per Numba
    thread at a time; interpreted, all in this thread: threads would take turns holding the
    GIL); the results are kept by task index, so their order never depends on the threads."""
    import numba

    n_tasks = len(inputs)
    results: list[tuple | None] = [None] * n_tasks
    kernel = twin_if(interpret, _build_kernel)

    def build(k: int) -> None:
        ids, lo, hi, blo, bhi, depth = inputs[k]
        inputs[k] = None  # the task's arrays are freed as soon as its subtree is built
        *tree, _ = kernel(tri_v, material, ids, lo, hi, blo, bhi, *constants, depth,
                          root_surface, 0)
        results[k] = tuple(tree)

    order = sorted(range(n_tasks), key=lambda k: -inputs[k][0].shape[0])
    workers = 1 if interpret else min(numba.get_num_threads(), n_tasks)
    if workers > 1:
        from concurrent.futures import ThreadPoolExecutor

        with ThreadPoolExecutor(max_workers=workers) as pool:
            list(pool.map(build, order))  # re-raises a worker's exception here
    else:
        for k in order:
            build(k)
    return results


def _stitch(top: list, subtrees: list[tuple]) -> tuple:
    """Put every subtree in place of its placeholder: the arrays of the undivided build.

    Depth-first order keeps a subtree contiguous, so each placeholder becomes the subtree's
    nodes (right-child indices shifted by where it lands) and the primitives are laid out
    in the new node order (leaf first indices shifted). Statistics add up in task order.
    """
    t_axis, t_child, t_first, t_split, t_prims, t_stats = top
    deferred = t_axis == DEFERRED
    if not deferred.any():
        return t_axis, t_child, t_first, t_split, t_prims, t_stats
    size = np.ones(t_axis.size, np.int64)
    size[deferred] = [subtrees[k][0].size for k in t_first[deferred]]
    new_index = np.cumsum(size) - size
    n_nodes = int(size.sum())
    leaf = t_axis == LEAF_CODE
    n_prims = int(t_child[leaf].sum()) + sum(subtrees[k][4].size for k in t_first[deferred])
    # Filled in place and each subtree dropped once copied: the stitched tree never exists
    # twice (half a gigabyte of nodes and references for a 10^7-triangle city).
    axis_out = np.empty(n_nodes, np.int64)
    child_out = np.empty(n_nodes, np.int64)
    first_out = np.empty(n_nodes, np.int64)
    split_out = np.empty(n_nodes, t_split.dtype)
    prims_out = np.empty(n_prims, t_prims.dtype)
    stats = t_stats.copy()
    prim_pos = 0
    for i in range(t_axis.size):
        at = int(new_index[i])
        if deferred[i]:
            k = int(t_first[i])
            s_axis, s_child, s_first, s_split, s_prims, s_stats = subtrees[k]
            subtrees[k] = None
            m = s_axis.size
            s_leaf = s_axis == LEAF_CODE
            axis_out[at:at + m] = s_axis
            child_out[at:at + m] = np.where(s_leaf, s_child, s_child + at)
            first_out[at:at + m] = np.where(s_leaf, s_first + prim_pos, 0)
            split_out[at:at + m] = s_split
            prims_out[prim_pos:prim_pos + s_prims.size] = s_prims
            prim_pos += s_prims.size
            stats[0] += s_stats[0]  # leaves
            stats[1] += s_stats[1]  # empty leaves
            stats[2] = max(stats[2], s_stats[2])  # deepest leaf
            stats[3] += s_stats[3]  # depth sum
            stats[4] += s_stats[4]  # time splits
            stats[5] += s_stats[5]  # SAH cost
            del s_axis, s_child, s_first, s_split, s_prims
        elif leaf[i]:
            count, first = int(t_child[i]), int(t_first[i])
            axis_out[at], child_out[at], first_out[at], split_out[at] = (
                t_axis[i], count, prim_pos, t_split[i])
            prims_out[prim_pos:prim_pos + count] = t_prims[first:first + count]
            prim_pos += count
        else:
            axis_out[at], child_out[at], first_out[at], split_out[at] = (
                t_axis[i], new_index[t_child[i]], 0, t_split[i])
    return axis_out, child_out, first_out, split_out, prims_out, stats


def model_time_range(t_begin_days: np.ndarray, t_end_days: np.ndarray,
                     valid: np.ndarray | None = None, *,
                     interpret: bool = False) -> tuple[float, float] | None:
    """Finite time range ``(t0, t1)`` in days used by the heuristic, or None for a dateless model.

    The range spans every finite begin and end (of the triangles where ``valid`` is true, if
    given), padded by 1 % of its length (at least one day) so that the first and last dates are
    strictly inside and a single date still has a duration. ``interpret``: run the kernel's
    Python source (see :data:`INTERPRET_TRIANGLES`).
    """
    t_begin_days = np.ascontiguousarray(t_begin_days, np.float64)
    t_end_days = np.ascontiguousarray(t_end_days, np.float64)
    if valid is None:
        valid = np.ones(t_begin_days.shape[0], bool)
    lo, hi, n_finite = twin_if(interpret, _finite_range)(t_begin_days, t_end_days,
                                                         np.ascontiguousarray(valid, bool))
    if n_finite == 0:
        return None
    pad = max(1.0, 0.01 * (hi - lo))
    return lo - pad, hi + pad


@njit(cache=True)
def _finite_range(t_begin, t_end, valid):
    """(min, max, count) of the finite begins and ends of the valid triangles, in one pass
    (the masked copies, isfinite and concatenation took 0.7 s for the 10M city)."""
    lo = np.inf
    hi = -np.inf
    n = 0
    for i in range(t_begin.shape[0]):
        if valid[i]:
            for v in (t_begin[i], t_end[i]):
                if np.isfinite(v):
                    lo = min(lo, v)
                    hi = max(hi, v)
                    n += 1
    return lo, hi, n


#: Triangles a process builds with the kernels' Python source while the build kernel is
#: neither compiled nor cached (:mod:`cityshade.runtime.interpret`). Interpreted, a build
#: takes 0.7-0.85 CPU ms a triangle on generated cities (the sample city's 1,386: 1.06 s;
#: 6,000: 5.0 s; 10,000: 8.5 s; 20,000: 13.9 s) and up to 1.4 ms on dense random boxes
#: (tests' box_city, 6,000: 8.3 s), against some 13-15 CPU s of compiling the kernels on
#: first use (Dec 2026). At 6,000 even the dense case stays well under the compile.
INTERPRET_TRIANGLES = 6_000
_INTERPRET = InterpretBudget(INTERPRET_TRIANGLES, _build_kernel)


def _checked_inputs(vertices, triangles, t_begin_days, t_end_days, material):
    """The inputs of :func:`build_kdtree` checked and made contiguous.

    Returns
    -------
    vertices32 : (V, 3) float32, triangles : (T, 3) int, t_begin, t_end : (T,) float64 days,
    material : (T,) int32

    Raises
    ------
    KdTreeInputError
        Arrays of the wrong shape, non-finite vertices, indices out of range or NaN times.
    """
    vertices = np.asarray(vertices)
    triangles = np.asarray(triangles)
    if vertices.ndim != 2 or vertices.shape[1] != 3:
        raise KdTreeInputError(f"vertices must have shape (V, 3), not {vertices.shape}")
    if triangles.ndim != 2 or triangles.shape[1] != 3:
        raise KdTreeInputError(f"triangles must have shape (T, 3), not {triangles.shape}")
    if not np.issubdtype(triangles.dtype, np.integer):
        raise KdTreeInputError(f"triangles must be integer indices, not {triangles.dtype}")
    n_tri = triangles.shape[0]
    if n_tri >= 2**29:
        raise KdTreeInputError(f"{n_tri} triangles exceed the layout's limit of 2^29")
    vertices32 = np.ascontiguousarray(vertices, dtype=np.float32)
    if not np.all(np.isfinite(vertices32)):
        raise KdTreeInputError("vertices contain NaN or infinite coordinates")
    if n_tri and (triangles.min() < 0 or triangles.max() >= vertices32.shape[0]):
        raise KdTreeInputError("triangle vertex indices out of range")
    t_begin = np.ascontiguousarray(t_begin_days, dtype=np.float64)
    t_end = np.ascontiguousarray(t_end_days, dtype=np.float64)
    material = np.ascontiguousarray(material, dtype=np.int32)
    for name, arr in (("t_begin_days", t_begin), ("t_end_days", t_end), ("material", material)):
        if arr.shape != (n_tri,):
            raise KdTreeInputError(f"{name} must have shape ({n_tri},), not {arr.shape}")
    if np.isnan(t_begin).any() or np.isnan(t_end).any():
        raise KdTreeInputError("validity times contain NaN (use -inf/+inf for open ends)")
    return vertices32, np.ascontiguousarray(triangles), t_begin, t_end, material


def build_kdtree(vertices, triangles, t_begin_days, t_end_days, material,
                 settings: KdTreeSettings | None = None):
    """Build the 4-D SAH kd-tree of a triangle scene.

    Parameters
    ----------
    vertices : (V, 3) float32 array
        Render-space vertex positions (x east, y north, z up, metres, relative to the scene
        origin). Other float types are converted to float32.
    triangles : (T, 3) int array
        Vertex indices; winding gives the outward normal (right-hand rule).
    t_begin_days, t_end_days : (T,) float64 arrays
        Validity interval ``[begin, end)`` of each triangle, days since 1970-01-01 UTC; open ends
        are -inf / +inf. Triangles with ``begin >= end`` are never valid and left out.
    material : (T,) int32 array
        Material index per triangle (-1 = none); leaves list triangles sorted by it.
    settings : KdTreeSettings, optional
        Build tunables; defaults to ``KdTreeSettings()``.

    Returns
    -------
    KdTree
        The flat tree (:class:`cityshade.accel.kdtree_layout.KdTree`) with its build statistics.

    Raises
    ------
    KdTreeInputError
        Arrays of the wrong shape, non-finite vertices, indices out of range or NaN times.
    """
    settings = settings or KdTreeSettings()
    started = time.perf_counter()
    vertices32, triangles, t_begin, t_end, material = _checked_inputs(
        vertices, triangles, t_begin_days, t_end_days, material)
    n_tri = triangles.shape[0]
    # Small on first use: every kernel of the build runs its Python source (the same tree).
    interpret = _INTERPRET.take(n_tri)
    valid = t_begin < t_end
    ids0 = np.flatnonzero(valid).astype(np.int32)
    time_range = model_time_range(t_begin, t_end, valid, interpret=interpret)
    has_time = time_range is not None
    t0, t1 = time_range if has_time else (0.0, 0.0)

    # (T, 3, 3) corners kept in float32 (the kernel widens them exactly): half the memory.
    # Reference boxes in float32: every bound is a float32 value (corners, outward-rounded
    # times and clipped extents, float32 split planes), so the narrow type is exact and halves
    # the build's largest arrays.
    tri_v, lo0, hi0 = _corners_and_boxes(vertices32, triangles, ids0, t_begin, t_end, interpret)
    if ids0.size:
        root_lo = np.append(lo0[:, :3].min(axis=0), -np.inf)
        root_hi = np.append(hi0[:, :3].max(axis=0), np.inf)
    else:
        root_lo = np.array([0.0, 0.0, 0.0, -np.inf])
        root_hi = np.array([0.0, 0.0, 0.0, np.inf])

    depth_cap = settings.depth_cap(ids0.size)
    root_surface = float(twin_if(interpret, _surface)(root_lo, root_hi, has_time, t0, t1))
    if root_surface <= 0.0:
        root_surface = 1.0
    constants = (has_time, t0, t1, float(settings.traversal_cost),
                 float(settings.intersection_cost), float(settings.empty_bonus), depth_cap,
                 settings.min_leaf_triangles, settings.sweep_threshold, settings.bins)
    # The top of the tree in this thread; nodes small enough become subtree tasks.
    *top, tasks = twin_if(interpret, _build_kernel)(
        tri_v, material, ids0, lo0, hi0, root_lo, root_hi, *constants, 0, root_surface,
        settings.subtree_cap(ids0.size))
    del lo0, hi0
    inputs = _task_inputs(tasks)
    del tasks
    subtrees = _build_subtrees(tri_v, material, inputs, constants, root_surface, interpret)
    del inputs, tri_v
    release_freed_memory()  # the kernel's per-node arrays, freed, fragment the heap
    node_axis, node_child, node_first, node_split, prims, raw = _stitch(top, subtrees)
    del top, subtrees
    release_freed_memory()
    nodes = pack_nodes(node_axis, node_child, node_first, node_split, interpret)
    n_nodes = int(node_axis.size)
    # The wide working arrays go before the records (the tree's largest array) are made.
    del node_axis, node_child, node_first, node_split
    prim_indices = prims.astype(np.int32)
    del prims
    records = triangle_records(vertices32, triangles, t_begin, t_end, material, prim_indices,
                               interpret)

    bounds = np.empty((2, 4))
    bounds[0, :3] = root_lo[:3]
    bounds[1, :3] = root_hi[:3]
    bounds[0, 3] = t0
    bounds[1, 3] = t1
    n_leaves, n_empty, depth_max, depth_sum, time_splits, sah = raw
    n_ref = int(prim_indices.size)
    stats = {
        "triangles_in": int(n_tri),
        "triangles_valid": int(ids0.size),
        "references": n_ref,
        "duplication": float(n_ref / ids0.size) if ids0.size else 0.0,
        "nodes": n_nodes,
        "leaves": int(n_leaves),
        "empty_leaves": int(n_empty),
        "max_depth": int(depth_max),
        "mean_depth": float(depth_sum / n_leaves) if n_leaves else 0.0,
        "mean_leaf_triangles": float(n_ref / (n_leaves - n_empty)) if n_leaves > n_empty else 0.0,
        "sah_cost": float(sah),
        "time_splits": int(time_splits),
        "has_time": bool(has_time),
        "depth_cap": int(depth_cap),
        "build_s": time.perf_counter() - started,
    }
    return KdTree(nodes=nodes, prim_indices=prim_indices, tri_records=records, bounds=bounds,
                  stats=stats)
