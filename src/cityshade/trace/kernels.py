"""Numba kernels: watertight ray/triangle test and kd-tree traversal (closest hit, any hit).

All kernels take the flat tree of :mod:`cityshade.accel.kdtree_layout` as one
:class:`~cityshade.accel.kdtree_layout.KdViews` tuple (views of the same memory, so they work on
read-only memory maps) and decode it with that module's inline decoders.

Ray/triangle test: Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1),
2013. The ray is sheared so that it runs along +z through the origin; the three 2-D edge
functions are then evaluated in float64 from the same sheared vertex values for every triangle
that shares an edge, so a ray through a shared edge or vertex gets edge functions of equal
magnitude and opposite sign on the two sides and can never slip between them. A ray exactly on
an edge hits both triangles (edge function 0 counts as inside); closest-hit breaks such exact
distance ties towards the lower triangle id, so results do not depend on traversal order.

Traversal: ray segments front to back (the thesis slides' "traversal algorithm based on ray
segments"), a fixed stack of ``STACK_SIZE`` entries (one per tree level at most), time nodes
send the ray to the child holding ``t_days``, leaves test only triangles valid at ``t_days``
(``begin <= t_days < end``).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from cityshade.accel.kdtree_layout import (LEAF_CODE, TIME_AXIS, leaf_first, node_split,
                                           node_word, record_id, record_present, word_axis,
                                           word_payload)

#: Entries of the fixed traversal stack: at most one push per level, and the build caps the
#: depth at 60 (``cityshade.accel.settings.MAX_DEPTH_LIMIT``).
STACK_SIZE = 64
#: Relative slack when deciding to skip a child: split distances and hit distances are both
#: float64 estimates of the same value (errors ~1e-15 relative), so a child is still visited
#: when the split lies this close outside the segment. Costs nothing measurable.
SPLIT_REL_TOL = 1e-9
#: Absolute floor of that slack, metres along a unit ray.
SPLIT_ABS_TOL = 1e-9


@njit(cache=True, inline="always")
def ray_shear(dx, dy, dz):
    """Permutation and shear constants of the watertight test for direction (dx, dy, dz).

    Returns ``(kx, ky, kz, sx, sy, sz)``: ``kz`` is the axis of largest ``|d|``; ``kx``, ``ky``
    follow cyclically and are swapped when ``d[kz] < 0`` to keep the triangle winding.
    """
    ax = abs(dx)
    ay = abs(dy)
    az = abs(dz)
    if ax > ay and ax > az:
        kz = 0
    elif ay > az:
        kz = 1
    else:
        kz = 2
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    dkz = dx if kz == 0 else (dy if kz == 1 else dz)
    if dkz < 0.0:
        kx, ky = ky, kx
    dkx = dx if kx == 0 else (dy if kx == 1 else dz)
    dky = dx if ky == 0 else (dy if ky == 1 else dz)
    return kx, ky, kz, dkx / dkz, dky / dkz, 1.0 / dkz


@njit(cache=True, inline="always")
def hit_record(recs, k, okx, oky, okz, kx, ky, kz, sx, sy, sz):
    """Watertight test of ray against record ``k``; returns ``(hit, t, u, v)``.

    ``okx, oky, okz`` are the ray origin's coordinates on axes ``kx, ky, kz`` and the rest come
    from :func:`ray_shear`. ``t`` is the distance along the ray in units of its direction,
    ``(u, v)`` the barycentrics of v1 and v2 (hit point = (1-u-v) v0 + u v1 + v v2).
    """
    return _watertight(recs[k, kx], recs[k, ky], recs[k, kz], recs[k, 3 + kx], recs[k, 3 + ky],
                       recs[k, 3 + kz], recs[k, 6 + kx], recs[k, 6 + ky], recs[k, 6 + kz],
                       okx, oky, okz, sx, sy, sz)


@njit(cache=True, inline="always")
def hit_triangle(vertices, triangles, t, okx, oky, okz, kx, ky, kz, sx, sy, sz):
    """:func:`hit_record` of scene triangle ``t`` (``vertices`` (V, 3) float32, ``triangles``
    (T, 3)): the same float32 coordinates as its records, so the same answer."""
    q0, q1, q2 = triangles[t, 0], triangles[t, 1], triangles[t, 2]
    return _watertight(vertices[q0, kx], vertices[q0, ky], vertices[q0, kz], vertices[q1, kx],
                       vertices[q1, ky], vertices[q1, kz], vertices[q2, kx], vertices[q2, ky],
                       vertices[q2, kz], okx, oky, okz, sx, sy, sz)


@njit(cache=True, inline="always")
def _watertight(ax_, ay_, az_, bx_, by_, bz_, cx_, cy_, cz_, okx, oky, okz, sx, sy, sz):
    """The watertight test of one triangle given by its vertices on the permuted axes."""
    # Translate the vertices to the ray origin, then shear so the ray runs along +z.
    a_z = az_ - okz
    b_z = bz_ - okz
    c_z = cz_ - okz
    a_x = (ax_ - okx) - sx * a_z
    a_y = (ay_ - oky) - sy * a_z
    b_x = (bx_ - okx) - sx * b_z
    b_y = (by_ - oky) - sy * b_z
    c_x = (cx_ - okx) - sx * c_z
    c_y = (cy_ - oky) - sy * c_z
    # Scaled barycentrics: 2-D edge functions of the three edges.
    e_u = c_x * b_y - c_y * b_x
    e_v = a_x * c_y - a_y * c_x
    e_w = b_x * a_y - b_y * a_x
    if (e_u < 0.0 or e_v < 0.0 or e_w < 0.0) and (e_u > 0.0 or e_v > 0.0 or e_w > 0.0):
        return False, 0.0, 0.0, 0.0
    det = e_u + e_v + e_w
    if det == 0.0:
        # Zero-area triangle or a ray in the triangle's plane: never a hit, never a NaN.
        return False, 0.0, 0.0, 0.0
    t_scaled = (e_u * a_z + e_v * b_z + e_w * c_z) * sz
    inv_det = 1.0 / det
    return True, t_scaled * inv_det, e_v * inv_det, e_w * inv_det


@njit(cache=True, inline="always")
def clip_to_box(box_lo, box_hi, ox, oy, oz, dx, dy, dz, tmin, tmax):
    """Segment ``[t0, t1]`` of the ray inside the box (``t0 > t1`` when it misses).

    Zero direction components are handled explicitly (no 0 × inf NaN).
    """
    t0 = tmin
    t1 = tmax
    for axis in range(3):
        o = ox if axis == 0 else (oy if axis == 1 else oz)
        d = dx if axis == 0 else (dy if axis == 1 else dz)
        lo = box_lo[axis]
        hi = box_hi[axis]
        if d == 0.0:
            if o < lo or o > hi:
                return 1.0, 0.0
            continue
        inv = 1.0 / d
        ta = (lo - o) * inv
        tb = (hi - o) * inv
        if ta > tb:
            ta, tb = tb, ta
        if ta > t0:
            t0 = ta
        if tb < t1:
            t1 = tb
    return t0, t1


@njit(cache=True, inline="always")
def on_axes(ox, oy, oz, kx, ky, kz):
    """A point's coordinates on the permuted axes ``kx, ky, kz`` of :func:`ray_shear`."""
    return (ox if kx == 0 else (oy if kx == 1 else oz), ox if ky == 0 else (oy if ky == 1 else oz),
            ox if kz == 0 else (oy if kz == 1 else oz))


@njit(cache=True, inline="always")
def _inverse(d):
    """1/d for the slab tests, 0 for a zero component (never used then: the ray is parallel)."""
    return 1.0 / d if d != 0.0 else 0.0


#: :func:`split_side` answers: the segment needs the near child, the far child, or both.
NEAR_ONLY = 0
FAR_ONLY = 1
BOTH_SIDES = 2


@njit(cache=True, inline="always")
def split_side(t_split, seg0, seg1):
    """Which children the segment ``[seg0, seg1]`` needs when the split plane lies at
    ``t_split`` along the ray: ``(side, cut)``, ``side`` one of ``NEAR_ONLY``, ``FAR_ONLY``,
    ``BOTH_SIDES``; ``cut`` (the split clamped to the segment) ends the near part and starts
    the far part when both are needed."""
    tol = SPLIT_REL_TOL * abs(t_split) + SPLIT_ABS_TOL
    if t_split > seg1 + tol:
        return NEAR_ONLY, t_split
    if t_split < seg0 - tol:
        return FAR_ONLY, t_split
    return BOTH_SIDES, min(max(t_split, seg0), seg1)


@njit(cache=True, inline="always")
def push_segment(st_node, st_t0, st_t1, sp, node, seg0, seg1):
    """Push a pending subtree and its segment on the stack; returns the new stack pointer."""
    st_node[sp] = node
    st_t0[sp] = seg0
    st_t1[sp] = seg1
    return sp + 1


@njit(cache=True, inline="always")
def set_direction(ray, dx, dy, dz):
    """Write a direction and its inverses into the per-axis ray terms ``ray`` (9,) of
    :func:`trace_range`: columns 3-5 the direction, 6-8 its inverses (0 for a zero component,
    never used then: the ray is parallel to that axis's planes)."""
    ray[3] = dx
    ray[4] = dy
    ray[5] = dz
    ray[6] = _inverse(dx)
    ray[7] = _inverse(dy)
    ray[8] = _inverse(dz)


@njit(cache=True, nogil=True)
def trace_range(tree, box_lo, box_hi, origins, directions, tmin, tmax, t_days, brick_size,
                closest, out_hit, out_t, out_tri, out_u, out_v, b0, b1):
    """Trace the rays of bricks ``[b0, b1)`` (ray ``i`` is in brick ``i // brick_size``).

    ``tree``: :class:`~cityshade.accel.kdtree_layout.KdViews`; ``box_lo`` / ``box_hi`` the
    (padded) scene box; ``origins`` (N, 3) float64; ``directions`` (N, 3), or (1, 3) for rays
    that all share one direction (sun rays: its shear and inverses computed once); ``tmin``
    scalar, ``tmax`` (N,) or (1,) (one for all): the segment of each ray at city time
    ``t_days``.

    ``closest``: write the closest hit of each ray to ``out_t`` (``inf`` on a miss),
    ``out_tri`` (triangle id, -1), ``out_u``, ``out_v`` (barycentrics of v1 and v2, 0); exact
    distance ties go to the lower triangle id, so the answer does not depend on the order of
    the traversal. Otherwise write ``out_hit[i]``: whether any triangle is hit; each brick keeps
    a shadow-caster cache, the record of its last hit, tested first for the next ray, so
    coherent shadow rays behind the same occluder skip the traversal. The other outputs are
    not touched (pass empty arrays).

    Traversal by ray segments, front to back, with a fixed stack: a spatial split the segment
    crosses pushes its far child with the far part of the segment; a time node sends the ray to
    the child holding ``t_days``; a leaf tests only its triangles standing at ``t_days``.

    The loop is written out here, for both kinds of ray, because Numba compiles it well only so
    (1M city, one thread, sun rays): the split step as a branching helper taking the stack
    arrays ran at 1.8 Mrays/s against 8.7, most of the time spent outside the kernel's own code
    (by its look, reference counting of the arrays on every call); straight-line helpers such
    as :func:`push_segment` cost nothing measurable. The ray's per-axis terms (origin, direction,
    inverse) sit in one small array read by the split's axis: a three-way branch on the axis
    mispredicted often enough to cost a fifth of a shadow ray (6.9 -> 8.7 Mrays/s).
    """
    n = origins.shape[0]
    shared = directions.shape[0] == 1
    tmax_step = 1 if tmax.shape[0] > 1 else 0
    st_node = np.empty(STACK_SIZE, np.int64)
    st_t0 = np.empty(STACK_SIZE)
    st_t1 = np.empty(STACK_SIZE)
    ray = np.empty(9)
    dx, dy, dz = directions[0, 0], directions[0, 1], directions[0, 2]
    kx, ky, kz, sx, sy, sz = ray_shear(dx, dy, dz)
    set_direction(ray, dx, dy, dz)
    for b in range(b0, b1):
        cache_k = -1
        for i in range(b * brick_size, min(n, (b + 1) * brick_size)):
            if not shared:
                dx, dy, dz = directions[i, 0], directions[i, 1], directions[i, 2]
                kx, ky, kz, sx, sy, sz = ray_shear(dx, dy, dz)
                set_direction(ray, dx, dy, dz)
            ox, oy, oz = origins[i, 0], origins[i, 1], origins[i, 2]
            okx, oky, okz = on_axes(ox, oy, oz, kx, ky, kz)
            tm = tmax[i * tmax_step]
            found = -1
            best_t = np.inf
            best_id = -1
            best_u = 0.0
            best_v = 0.0
            if not closest and cache_k >= 0 and record_present(tree, cache_k, t_days):
                hit, t, _, _ = hit_record(tree.recs, cache_k, okx, oky, okz, kx, ky, kz, sx,
                                          sy, sz)
                if hit and tmin <= t <= tm:
                    found = cache_k
            seg0, seg1 = clip_to_box(box_lo, box_hi, ox, oy, oz, dx, dy, dz, tmin, tm)
            if found < 0 and seg0 <= seg1:
                ray[0] = ox
                ray[1] = oy
                ray[2] = oz
                node = 0
                sp = 0
                while True:
                    w0 = node_word(tree, node)
                    axis = word_axis(w0)
                    if axis == LEAF_CODE:
                        # Test the leaf's triangles standing at t_days.
                        first = leaf_first(tree, node)
                        for k in range(first, first + word_payload(w0)):
                            if not record_present(tree, k, t_days):
                                continue
                            hit, t, u, v = hit_record(tree.recs, k, okx, oky, okz, kx, ky, kz,
                                                      sx, sy, sz)
                            if not (hit and tmin <= t <= tm):
                                continue
                            if not closest:
                                found = k
                                break
                            tri = record_id(tree, k)
                            if t < best_t or (t == best_t and tri < best_id):
                                best_t = t
                                found = k
                                best_id = tri
                                best_u = u
                                best_v = v
                        # Nothing unvisited lies before seg1, so a closest hit before it is
                        # final; any hit is.
                        if (found >= 0 and not closest) or best_t < seg1 or sp == 0:
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
                        # Parallel to the plane: one side, or both when the ray lies in it.
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
            if closest:
                out_t[i] = best_t
                out_tri[i] = best_id
                out_u[i] = best_u
                out_v[i] = best_v
            else:
                out_hit[i] = found >= 0
                if found >= 0:
                    cache_k = found
