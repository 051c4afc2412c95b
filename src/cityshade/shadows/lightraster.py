"""Depth-only rasterizer for light views (shadow maps) under any 4×4 projective matrix.

Method
------
The G-buffer rasterizer's homogeneous method (Olano and Greer 1997; see
:mod:`cityshade.raster.rasterize`) with the light's clip coordinates: each vertex becomes
``(X, Y, Z, W) = clip_from_world @ (p, 1)`` and the 2-D homogeneous vertex ``v~ = (X, Y, W)``.
The three edge functions ``e_i(xs, ys) = (v~_j x v~_k) . (xs, ys, 1)`` are linear in the texel
centre's NDC coordinates; a texel is covered when all three have the sign of
``det = v~_0 . (v~_1 x v~_2)``, and then ``e_i / sum(e)`` are the exact barycentrics of the point
where the texel's ray meets the triangle's plane. Clip Z and W are affine in world space, so
interpolating them with those barycentrics is exact for any projective matrix (warped maps
included); the stored depth is ``Z / W`` (NDC depth, -1 at the near plane, +1 at the far plane,
smaller is nearer the light).

Depth clamping: fragments nearer than the near plane (NDC z < -1) are kept with depth -1
("pancaking": a caster between the sun and the near plane still casts), fragments beyond the
far plane and fragments with ``W <= 0`` (behind a projective centre) are dropped.

Determinism: the top-left fill rule on exact zeros and the depth test on
``(float32 depth, triangle id)`` (ties to the lower id) make the map independent of drawing
order, tile size and thread count.

Texel convention: texel ``(col, row)`` has its centre at NDC
``x = 2 (col + 0.5) / W - 1``, ``y = 1 - 2 (row + 0.5) / H`` (row 0 at the top, NDC y up),
the same as :meth:`cityshade.raster.camera.Camera.clip_from_world`.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

#: Tile side in texels: a 64² tile of float32 depth + int32 id is 32 KiB (fits L1/L2), and a
#: 4096² map has 4096 tiles, plenty to balance two cores.
TILE_PX = 64
#: Triangles per drawing batch: bounds the transient setup arrays (about 150 bytes per
#: triangle, 40 MB per batch) while keeping the number of parallel regions per pass small.
MAX_BATCH = 262144
#: Smallest clip W of a visible point, relative to the largest |W| of the triangle's vertices:
#: the screen box of a triangle crossing W = 0 is taken from its part with W above this (the
#: box is then clamped to the map, so a tiny value only widens the box, never the coverage).
W_NEAR_REL = 1e-9
#: Slack of the texel bounding box in texels (positions are float64, errors ~1e-12 texel): a
#: centre the edge functions find inside is never outside the box.
BOX_SLACK_PX = 1e-6
#: Chunks of the parallel binning (several per thread for balance; any value gives the same
#: tile lists).
BIN_CHUNKS = 16
#: An edge bounds the covered columns of a row only when ``|a| >= SPAN_MIN_SLOPE |b|``: the
#: bound ``col = A y + B`` of a nearly row-parallel edge has huge A and B whose cancellation
#: could exceed the one column of slack (the exact test still decides every texel).
SPAN_MIN_SLOPE = 1e-6
#: Words per set-up triangle: 3 × (a, b, c) edge coefficients, 3 tie-ownership flags,
#: clip Z and W at the three vertices, a flag for triangles crossing W = 0, the NDC depth
#: plane ``z = p x + q y + r`` of the others, and per edge the column bound ``A y + B`` with
#: its kind (1 lower, -1 upper, 0 none).
_SETUP_WORDS = 31


def texel_params(width_px: int, height_px: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """NDC coordinates of the texel centres and the NDC → texel-index mapping.

    Returns
    -------
    xs : (W,) float64; ys : (H,) float64
        NDC x of each column's centre, NDC y of each row's centre.
    to_px : (4,) float64
        ``col = to_px[0] x + to_px[1]``, ``row = to_px[2] y + to_px[3]`` (centres at integers).
    """
    w, h = int(width_px), int(height_px)
    xs = 2.0 * (np.arange(w, dtype=np.float64) + 0.5) / w - 1.0
    ys = 1.0 - 2.0 * (np.arange(h, dtype=np.float64) + 0.5) / h
    to_px = np.array([w / 2.0, w / 2.0 - 0.5, -h / 2.0, h / 2.0 - 0.5])
    return xs, ys, to_px


@njit(cache=True, inline="always")
def _clip(m, px, py, pz):
    """Render-space point → light clip coordinates (X, Y, Z, W)."""
    return (m[0] * px + m[1] * py + m[2] * pz + m[3],
            m[4] * px + m[5] * py + m[6] * pz + m[7],
            m[8] * px + m[9] * py + m[10] * pz + m[11],
            m[12] * px + m[13] * py + m[14] * pz + m[15])


@njit(cache=True, inline="always")
def _grow(box, sx, sy):
    return min(box[0], sx), max(box[1], sx), min(box[2], sy), max(box[3], sy)


@njit(cache=True, inline="always")
def _w_cross(xa, ya, wa, xb, yb, wb, wn):
    """NDC position of the point where edge a-b crosses W = wn."""
    s = (wn - wa) / (wb - wa)
    return (xa + s * (xb - xa)) / wn, (ya + s * (yb - ya)) / wn


@njit(cache=True, parallel=True)
def setup_triangles(vertices, triangles, recs, from_records, items, m, to_px, width, height,
                    ids, coef, bbox):
    """Per triangle: edge functions, clip Z/W of the vertices and the texel bounding box.

    Parameters
    ----------
    vertices : (V, 3) float32; triangles : (T, 3) int32
        The scene (read when ``from_records`` is False).
    recs : (K, 16) float32
        kd-tree triangle records (vertices in columns 0-8, triangle id bits in column 9), read
        when ``from_records``.
    items : (N,) int32
        Triangle ids, or record indices when ``from_records``.
    m : (16,) float64
        Row-major ``clip_from_world``.
    to_px : (4,) float64
        NDC → texel index mapping (:func:`texel_params`).
    ids : (N,) int32 out
        Triangle ids.
    coef : (N, 18) float64 out
        Edge coefficients (positive inside), tie flags, Z0..Z2, W0..W2.
    bbox : (N, 4) int32 out
        col0, col1, row0, row1 inclusive; col0 > col1 when the triangle covers no texel.
    """
    n = items.shape[0]
    rec_ids = recs.view(np.int32)
    for j in prange(n):
        bbox[j, 0] = 1
        bbox[j, 1] = 0
        bbox[j, 2] = 1
        bbox[j, 3] = 0
        item = items[j]
        # The three vertices in clip coordinates.
        if from_records:
            ids[j] = rec_ids[item, 9]
            x0, y0, z0, w0 = _clip(m, np.float64(recs[item, 0]), np.float64(recs[item, 1]),
                                   np.float64(recs[item, 2]))
            x1, y1, z1, w1 = _clip(m, np.float64(recs[item, 3]), np.float64(recs[item, 4]),
                                   np.float64(recs[item, 5]))
            x2, y2, z2, w2 = _clip(m, np.float64(recs[item, 6]), np.float64(recs[item, 7]),
                                   np.float64(recs[item, 8]))
        else:
            ids[j] = item
            q0 = triangles[item, 0]
            q1 = triangles[item, 1]
            q2 = triangles[item, 2]
            x0, y0, z0, w0 = _clip(m, np.float64(vertices[q0, 0]), np.float64(vertices[q0, 1]),
                                   np.float64(vertices[q0, 2]))
            x1, y1, z1, w1 = _clip(m, np.float64(vertices[q1, 0]), np.float64(vertices[q1, 1]),
                                   np.float64(vertices[q1, 2]))
            x2, y2, z2, w2 = _clip(m, np.float64(vertices[q2, 0]), np.float64(vertices[q2, 1]),
                                   np.float64(vertices[q2, 2]))
        wmax = max(w0, w1, w2)
        if not wmax > 0.0:
            continue            # entirely behind the projection centre (or NaN)
        # Reject triangles entirely beyond the far plane (z > w at every vertex).
        if z0 > w0 and z1 > w1 and z2 > w2:
            continue
        # NDC box of the part with W > wn.
        wn = W_NEAR_REL * max(wmax, -min(w0, w1, w2))
        box = (np.inf, -np.inf, np.inf, -np.inf)
        if w0 >= wn:
            box = _grow(box, x0 / w0, y0 / w0)
        if w1 >= wn:
            box = _grow(box, x1 / w1, y1 / w1)
        if w2 >= wn:
            box = _grow(box, x2 / w2, y2 / w2)
        if (w0 >= wn) != (w1 >= wn):
            sx, sy = _w_cross(x0, y0, w0, x1, y1, w1, wn)
            box = _grow(box, sx, sy)
        if (w1 >= wn) != (w2 >= wn):
            sx, sy = _w_cross(x1, y1, w1, x2, y2, w2, wn)
            box = _grow(box, sx, sy)
        if (w2 >= wn) != (w0 >= wn):
            sx, sy = _w_cross(x2, y2, w2, x0, y0, w0, wn)
            box = _grow(box, sx, sy)
        # Texel centres inside the box (NDC y up, rows down).
        c0 = max(np.ceil(to_px[0] * box[0] + to_px[1] - BOX_SLACK_PX), 0.0)
        c1 = min(np.floor(to_px[0] * box[1] + to_px[1] + BOX_SLACK_PX), width - 1.0)
        r0 = max(np.ceil(to_px[2] * box[3] + to_px[3] - BOX_SLACK_PX), 0.0)
        r1 = min(np.floor(to_px[2] * box[2] + to_px[3] + BOX_SLACK_PX), height - 1.0)
        if not (c0 <= c1 and r0 <= r1):
            continue
        # Edge function of the edge opposite vertex i: v~_j x v~_k with v~ = (X, Y, W).
        a0 = y1 * w2 - w1 * y2
        b0 = w1 * x2 - x1 * w2
        k0 = x1 * y2 - y1 * x2
        a1 = y2 * w0 - w2 * y0
        b1 = w2 * x0 - x2 * w0
        k1 = x2 * y0 - y2 * x0
        a2 = y0 * w1 - w0 * y1
        b2 = w0 * x1 - x0 * w1
        k2 = x0 * y1 - y0 * x1
        det = x0 * a0 + y0 * b0 + w0 * k0
        if not (det > 0.0 or det < 0.0):
            continue        # seen edge-on by the light (or zero area, or NaN): covers nothing
        sign = 1.0 if det > 0.0 else -1.0
        coef[j, 0] = sign * a0
        coef[j, 1] = sign * b0
        coef[j, 2] = sign * k0
        coef[j, 3] = sign * a1
        coef[j, 4] = sign * b1
        coef[j, 5] = sign * k1
        coef[j, 6] = sign * a2
        coef[j, 7] = sign * b2
        coef[j, 8] = sign * k2
        for i in range(3):
            a = coef[j, 3 * i]
            b = coef[j, 3 * i + 1]
            # NDC y grows upwards, so "top" edges are those with de/dy < 0 as in the G-buffer
            # rasterizer's screen coordinates.
            coef[j, 9 + i] = 1.0 if (a > 0.0 or (a == 0.0 and b < 0.0)) else 0.0
        coef[j, 12] = z0
        coef[j, 13] = z1
        coef[j, 14] = z2
        coef[j, 15] = w0
        coef[j, 16] = w1
        coef[j, 17] = w2
        coef[j, 18] = 1.0
        if w0 > 0.0 and w1 > 0.0 and w2 > 0.0:
            # NDC depth is affine in NDC x, y over a plane (the z-buffer's classic property):
            # z = p x + q y + r through the three projected vertices; every point of the
            # triangle has W > 0, so no per-texel W test is needed either.
            nx0, ny0, nz0 = x0 / w0, y0 / w0, z0 / w0
            ex1, ey1, ez1 = x1 / w1 - nx0, y1 / w1 - ny0, z1 / w1 - nz0
            ex2, ey2, ez2 = x2 / w2 - nx0, y2 / w2 - ny0, z2 / w2 - nz0
            den = ex1 * ey2 - ex2 * ey1
            if den > 0.0 or den < 0.0:
                pp = (ez1 * ey2 - ez2 * ey1) / den
                qq = (ex1 * ez2 - ex2 * ez1) / den
                coef[j, 18] = 0.0
                coef[j, 19] = pp
                coef[j, 20] = qq
                coef[j, 21] = nz0 - pp * nx0 - qq * ny0
        # Column bound of each edge in a row at NDC y: e = a x + b y + c >= 0 gives
        # x >= -(b y + c) / a (a > 0) or x <= ... (a < 0); in texel columns A y + B.
        for i in range(3):
            a = coef[j, 3 * i]
            b = coef[j, 3 * i + 1]
            kind = 0.0
            if abs(a) >= SPAN_MIN_SLOPE * abs(b) and (a > 0.0 or a < 0.0):
                kind = 1.0 if a > 0.0 else -1.0
                coef[j, 22 + 3 * i] = -to_px[0] * b / a
                coef[j, 23 + 3 * i] = -to_px[0] * coef[j, 3 * i + 2] / a + to_px[1]
            coef[j, 24 + 3 * i] = kind
        bbox[j, 0] = int(c0)
        bbox[j, 1] = int(c1)
        bbox[j, 2] = int(r0)
        bbox[j, 3] = int(r1)


@njit(cache=True, parallel=True)
def bin_triangles(bbox, tile_px, tiles_x, tiles_y):
    """Tile lists in drawing order: ``(start (tiles + 1,) int64, items (M,) int32)``.

    Triangles are split into ``BIN_CHUNKS`` consecutive chunks counted and filled in parallel;
    a tile's list is its chunks' lists in chunk order, i.e. drawing order, for any thread count.
    """
    n_tiles = tiles_x * tiles_y
    n = bbox.shape[0]
    counts = np.zeros((BIN_CHUNKS, n_tiles), np.int64)
    for ch in prange(BIN_CHUNKS):
        for j in range(ch * n // BIN_CHUNKS, (ch + 1) * n // BIN_CHUNKS):
            if bbox[j, 0] > bbox[j, 1]:
                continue
            for ty in range(bbox[j, 2] // tile_px, bbox[j, 3] // tile_px + 1):
                for tx in range(bbox[j, 0] // tile_px, bbox[j, 1] // tile_px + 1):
                    counts[ch, ty * tiles_x + tx] += 1
    # Offsets: tile by tile, chunk by chunk.
    start = np.zeros(n_tiles + 1, np.int64)
    fill = np.empty((BIN_CHUNKS, n_tiles), np.int64)
    running = 0
    for t in range(n_tiles):
        start[t] = running
        for ch in range(BIN_CHUNKS):
            fill[ch, t] = running
            running += counts[ch, t]
    start[n_tiles] = running
    items = np.empty(running, np.int32)
    for ch in prange(BIN_CHUNKS):
        for j in range(ch * n // BIN_CHUNKS, (ch + 1) * n // BIN_CHUNKS):
            if bbox[j, 0] > bbox[j, 1]:
                continue
            for ty in range(bbox[j, 2] // tile_px, bbox[j, 3] // tile_px + 1):
                for tx in range(bbox[j, 0] // tile_px, bbox[j, 1] // tile_px + 1):
                    t = ty * tiles_x + tx
                    items[fill[ch, t]] = j
                    fill[ch, t] += 1
    return start, items


@njit(cache=True, parallel=True)
def raster_depth_tiles(start, items, ids, coef, bbox, xs, ys, to_px, tile_px, tiles_x, depth,
                       prim):
    """Depth-test the binned triangles into ``depth`` (H, W) float32 / ``prim`` (H, W) int32,
    one tile per work item (each tile owns its texels)."""
    n_tiles = start.shape[0] - 1
    w = depth.shape[1]
    h = depth.shape[0]
    for tile in prange(n_tiles):
        if start[tile] == start[tile + 1]:
            continue
        tc0 = (tile % tiles_x) * tile_px
        tr0 = (tile // tiles_x) * tile_px
        tc1 = min(tc0 + tile_px, w) - 1
        tr1 = min(tr0 + tile_px, h) - 1
        for mm in range(start[tile], start[tile + 1]):
            j = items[mm]
            tri = ids[j]
            a0, b0, k0 = coef[j, 0], coef[j, 1], coef[j, 2]
            a1, b1, k1 = coef[j, 3], coef[j, 4], coef[j, 5]
            a2, b2, k2 = coef[j, 6], coef[j, 7], coef[j, 8]
            own0 = coef[j, 9] != 0.0
            own1 = coef[j, 10] != 0.0
            own2 = coef[j, 11] != 0.0
            general = coef[j, 18] != 0.0
            zv0 = coef[j, 12]
            dz1 = coef[j, 13] - zv0
            dz2 = coef[j, 14] - zv0
            wv0 = coef[j, 15]
            dw1 = coef[j, 16] - wv0
            dw2 = coef[j, 17] - wv0
            pz = coef[j, 19]
            qz = coef[j, 20]
            rz = coef[j, 21]
            cb0 = max(bbox[j, 0], tc0)
            cb1 = min(bbox[j, 1], tc1)
            for r in range(max(bbox[j, 2], tr0), min(bbox[j, 3], tr1) + 1):
                y = ys[r]
                row0 = b0 * y + k0
                row1 = b1 * y + k1
                row2 = b2 * y + k2
                # Columns where all three edge functions can be >= 0 (one column of slack on
                # each side; the exact test below decides). Bounds are clamped to the tile
                # before the integer conversion (huge or NaN values have no int64).
                c_lo = np.float64(cb0)
                c_hi = np.float64(cb1)
                for i in range(3):
                    kind = coef[j, 24 + 3 * i]
                    if kind != 0.0:
                        col = coef[j, 22 + 3 * i] * y + coef[j, 23 + 3 * i]
                        if kind > 0.0:
                            if col - 1.0 > c_lo:
                                c_lo = col - 1.0
                        elif col + 1.0 < c_hi:
                            c_hi = col + 1.0
                if not c_lo <= c_hi:
                    continue
                c_first = int(math.ceil(c_lo))
                c_last = int(math.floor(c_hi))
                ypart = qz * y + rz
                for c in range(c_first, c_last + 1):
                    x = xs[c]
                    # Coverage with the top-left rule for exact zeros.
                    e0 = a0 * x + row0
                    if e0 < 0.0 or (e0 == 0.0 and not own0):
                        continue
                    e1 = a1 * x + row1
                    if e1 < 0.0 or (e1 == 0.0 and not own1):
                        continue
                    e2 = a2 * x + row2
                    if e2 < 0.0 or (e2 == 0.0 and not own2):
                        continue
                    if general:
                        # Crosses W = 0: exact barycentrics → clip Z and W of the plane point.
                        s = e0 + e1 + e2
                        if not s > 0.0:
                            continue
                        inv = 1.0 / s
                        u = e1 * inv
                        v = e2 * inv
                        wp = wv0 + u * dw1 + v * dw2
                        if not wp > 0.0:
                            continue
                        zp = (zv0 + u * dz1 + v * dz2) / wp
                    else:
                        zp = pz * x + ypart
                    if zp > 1.0:
                        continue
                    d = np.float32(max(zp, -1.0))
                    cur = depth[r, c]
                    if d < cur or (d == cur and tri < prim[r, c]):
                        depth[r, c] = d
                        prim[r, c] = tri


@njit(cache=True)
def present_triangles(t_begin, t_end, t_days):
    """Ids (int32) of the triangles with ``begin <= t_days < end``."""
    n = t_begin.shape[0]
    out = np.empty(n, np.int32)
    k = 0
    for i in range(n):
        if t_begin[i] <= t_days < t_end[i]:
            out[k] = i
            k += 1
    return out[:k]
