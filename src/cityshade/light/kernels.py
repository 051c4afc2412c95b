"""The sky tracing's per-direction bookkeeping as kernels: the rays of one direction and their
answers put straight into the packed bits.

A map's sky is 2 M receivers × 145 to 2,305 directions; numpy's gather of the receivers in
front of a direction, its scatter of the answers into an unpacked block and the pack cost
0.16 s a direction on the 1M-triangle city's map, as much as izb's query. One pass each here.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from cityshade.runtime.threadpool import run_chunks


@njit(cache=True, inline="always")
def _faces(normals, i, dx, dy, dz, min_cos):
    """The in-front test of :func:`cityshade.light.sky.in_front`: ``n · d > min_cos``, this one
    expression for the tracing and the weights alike."""
    return (np.float64(normals[i, 0]) * dx + np.float64(normals[i, 1]) * dy
            + np.float64(normals[i, 2]) * dz) > min_cos


@njit(cache=True)
def in_front_table(normals, directions, min_cos, out):
    """``out[i, p]`` = receiver ``i`` faces direction ``p`` (:func:`_faces`)."""
    for i in range(normals.shape[0]):
        for p in range(directions.shape[0]):
            out[i, p] = _faces(normals, i, directions[p, 0], directions[p, 1], directions[p, 2],
                               min_cos)


#: Receivers a thread takes at a time in the bits and the weighted sums (a 1 m map's 2.1 M
#: receivers: 33 chunks).
RECEIVER_CHUNK = 65536


@njit(cache=True)
def front_origins(points, normals, direction, min_cos, offset_rel, min_scale_m, rows, origins):
    """The shadow rays of one direction from the receivers in front of it.

    For every ``i`` facing ``direction`` (:func:`_faces`; in order) writes ``rows[k] = i`` and ``origins[k]`` =
    the point pushed off its surface, in the float64 order of
    :func:`cityshade.trace.bricks.shadow_origins` (``p + (n + d) * offset_rel * max(|p|_inf,
    min_scale_m)``: the same origins, so the same bits). Returns ``k``, the number of rays.
    The caller checks points and normals once (:func:`cityshade.trace.shadow_rays_from_surface`).
    One pass on one thread: it runs at memory speed (two passes over chunks on two threads,
    counting then writing, took 8.7 ms a direction of a 1 m map against 5.6).
    """
    k = 0
    dx, dy, dz = direction[0], direction[1], direction[2]
    for i in range(points.shape[0]):
        if not _faces(normals, i, dx, dy, dz, min_cos):
            continue
        px, py, pz = np.float64(points[i, 0]), np.float64(points[i, 1]), np.float64(points[i, 2])
        offset = offset_rel * max(max(max(abs(px), abs(py)), abs(pz)), min_scale_m)
        origins[k, 0] = px + (np.float64(normals[i, 0]) + dx) * offset
        origins[k, 1] = py + (np.float64(normals[i, 1]) + dy) * offset
        origins[k, 2] = pz + (np.float64(normals[i, 2]) + dz) * offset
        rows[k] = i
        k += 1
    return k


#: Directions whose answers wait in one byte per receiver (:func:`hold_visible`) before they go
#: into the packed bits together (:func:`put_held`). Setting each direction's bit straight in
#: the rows read and wrote a cache line per receiver and direction once the rows are wider
#: than a line (2,305 directions: 289 bytes), and a branch on each answer missed at every end
#: of a run of equal answers; held, the byte is set without a branch in an array that stays
#: in cache, and each row is written once per eight directions.
HELD_DIRECTIONS = 8


def hold_visible(held, rows, blocked, slot):
    """Bit ``slot`` (0-7, low first) of ``held[rows[k]]`` set where ray ``k`` is not blocked,
    other bits untouched (:func:`put_held` puts them into the bits). The rows are distinct
    (:func:`front_origins`), so the kernel threads write distinct bytes."""
    run_chunks(_hold, blocked.shape[0], RECEIVER_CHUNK, held, rows, blocked, slot)


@njit(cache=True, nogil=True)
def _hold(held, rows, blocked, slot, k0, k1):
    for k in range(k0, k1):      # branch-free: a blocked ray ORs a zero
        held[rows[k]] |= np.uint8((1 - blocked[k]) << slot)


def put_held(bits, held, columns):
    """Bit ``columns[s]`` of row ``i`` of ``bits`` set where bit ``s`` of ``held[i]`` is, in
    ``np.packbits``' big bit order (bit 0 the high bit of byte 0), other bits untouched;
    ``held`` cleared. ``columns``: the held directions' columns, slot by slot (at most 8)."""
    columns = np.asarray(columns, np.int64)
    targets, slot_target = np.unique(columns >> 3, return_inverse=True)
    # table[v, t]: the bits byte targets[t] gets from a held byte v (distinct bits: + is |).
    slot_bits = (np.arange(256)[:, None] >> np.arange(len(columns))[None, :]) & 1
    per_slot = slot_bits * (0x80 >> (columns & 7))[None, :]
    table = np.zeros((256, len(targets)), np.uint8)
    for s, t in enumerate(slot_target.reshape(-1)):
        table[:, t] += per_slot[:, s].astype(np.uint8)
    run_chunks(_put_held, held.shape[0], RECEIVER_CHUNK, bits, held, targets, table)


@njit(cache=True, nogil=True)
def _put_held(bits, held, targets, table, i0, i1):
    for i in range(i0, i1):
        v = held[i]
        if v:
            for t in range(targets.shape[0]):
                bits[i, targets[t]] |= table[v, t]
            held[i] = 0


def visible_weight_sums(bits, inverse, weights, out):
    """``out[i] = Σ_p bit(i, p) · weights[inverse[i], p]``, the directions added in increasing
    ``p`` from 0.0, one receiver at a time, straight from the packed bits (big bit order).

    One row's sum never depends on the other rows, so any split of the receivers (a sky run's
    tiles, the kernel threads' chunks) gives the same bits; BLAS's product of the unpacked bits
    did not promise that (its kernels sum a row in an order that depends on the row's place in
    the block)."""
    run_chunks(_weight_sums, bits.shape[0], RECEIVER_CHUNK, bits, inverse, weights, out)


@njit(cache=True, nogil=True)
def _weight_sums(bits, inverse, weights, out, i0, i1):
    n_p = weights.shape[1]
    for i in range(i0, i1):
        u = inverse[i]
        s = 0.0
        for byte in range(bits.shape[1]):
            b = bits[i, byte]
            if b == 0:
                continue
            base = byte * 8
            for k in range(8):
                if b & (0x80 >> k) and base + k < n_p:
                    s += weights[u, base + k]
        out[i] = s


#: Front centres whose cosine to a cut subsample is within this of the nearest's count as
#: equally near, and the first of them takes its weight: a plane symmetric to the patches (a
#: roof facing a patch boundary's azimuth) has subsamples exactly halfway between two centres,
#: and the rounding of the cosines must not choose.
NEAREST_TIE = 1e-12


def patch_weight_rows(unit, centres, front, dx, dy, dz, lw, moment, cos_r, sin_r, margin_cos,
                      out):
    """The rows of :func:`cityshade.light.metrics.patch_weights`, one distinct normal at a time
    on the kernel threads (each row its own: any split of the normals gives the same rows).

    ``unit`` (U, 3) unit normals; ``centres`` (P, 3) the patches' centres and ``front`` (U, P)
    which of them lie in front (:func:`in_front_table`); ``dx, dy, dz, lw`` (P, S) the
    patches' subsample directions and luminance × solid angle; ``moment`` (P, 3) ``Σ lw d``;
    ``cos_r, sin_r`` (P,) the cosine and sine of the angle from a patch's centre to its
    farthest subsample; ``out`` (U, P) float64, every entry written.

    A patch whose subsamples all lie ``margin_cos`` in front of the plane weighs
    ``n · moment``, one whose subsamples all lie behind it nothing; the others sum
    ``max(0, n · d) lw`` subsample by subsample: into the patch when its centre is in front,
    else, where positive, into the nearest centre in front (highest ``d · centre``, the first
    within :data:`NEAREST_TIE` of it), patches and subsamples in increasing order. The numpy
    form this replaces took 0.65 s for a 1 m map's 4,733 normals (this 0.29 s), most of it in
    temporaries of the cut patches."""
    run_chunks(_patch_weight_rows, unit.shape[0], 64, unit, centres, front, dx, dy, dz, lw,
               moment, cos_r, sin_r, margin_cos, out)


@njit(cache=True, nogil=True)
def _patch_weight_rows(unit, centres, front, dx, dy, dz, lw, moment, cos_r, sin_r, margin_cos,
                       out, u0, u1):
    n_p, n_s = dx.shape
    cut = np.empty(n_p, np.bool_)
    for u in range(u0, u1):
        nx, ny, nz = unit[u, 0], unit[u, 1], unit[u, 2]
        any_front = False
        for p in range(n_p):
            any_front |= front[u, p]
        for p in range(n_p):
            cos_c = min(max(nx * centres[p, 0] + ny * centres[p, 1] + nz * centres[p, 2],
                            -1.0), 1.0)
            sin_c = np.sqrt(1.0 - cos_c * cos_c)
            out[u, p] = 0.0
            behind = cos_c * cos_r[p] + sin_c * sin_r[p] < -margin_cos   # wholly
            cut[p] = not front[u, p] and not behind
            if behind:
                continue
            if front[u, p]:
                if cos_c * cos_r[p] - sin_c * sin_r[p] > margin_cos:   # wholly in front
                    out[u, p] = nx * moment[p, 0] + ny * moment[p, 1] + nz * moment[p, 2]
                else:
                    w = 0.0
                    for k in range(n_s):
                        w += max(dx[p, k] * nx + dy[p, k] * ny + dz[p, k] * nz, 0.0) * lw[p, k]
                    out[u, p] = w
        if not any_front:
            continue
        # Cut patches whose centre lies behind: their front part to the nearest front centre,
        # after every patch's own weight (the order the sums are made in).
        for p in range(n_p):
            if not cut[p]:
                continue
            for k in range(n_s):
                f = max(dx[p, k] * nx + dy[p, k] * ny + dz[p, k] * nz, 0.0) * lw[p, k]
                if not f > 0.0:
                    continue
                top = -np.inf
                for c in range(n_p):
                    if front[u, c]:
                        top = max(top, dx[p, k] * centres[c, 0] + dy[p, k] * centres[c, 1]
                                  + dz[p, k] * centres[c, 2])
                for c in range(n_p):
                    if front[u, c] and (dx[p, k] * centres[c, 0] + dy[p, k] * centres[c, 1]
                                        + dz[p, k] * centres[c, 2]) >= top - NEAREST_TIE:
                        out[u, c] += f
                        break
