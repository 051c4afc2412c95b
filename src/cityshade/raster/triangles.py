"""The triangle core of both rasterizers: setup from a 4×4 matrix, binning, the date filter and
the culled batch driver.

The G-buffer pass (:mod:`cityshade.raster.rasterize`) and the light-view depth pass
(:mod:`cityshade.raster.depthpass`) share everything but their per-tile kernel.

Method
------
Homogeneous rasterization (Olano and Greer, "Triangle Scan Conversion using 2D Homogeneous
Coordinates", 1997). A :class:`ClipView` maps each render-space vertex ``p`` to
``(X, Y, Z, W) = m @ (p - origin, 1)``: screen position ``(X/W, Y/W)``, depth ``Z`` (the
G-buffer's view depth, or the light's clip Z; translating by ``origin`` first keeps the
camera-relative coordinates exact to the last bit). The three edge functions
``e_i(xs, ys) = (v~_j x v~_k) . (xs, ys, 1)`` of the 2-D homogeneous vertices
``v~ = (X, Y, W)`` are linear in the pixel centre's screen coordinates. A pixel is covered when
all three have the sign of ``det = v~_0 . (v~_1 x v~_2)``; then ``e_i / sum(e)`` are *exactly*
the barycentrics of the point where the pixel's ray meets the triangle's plane (so attributes,
and Z and W, which are affine in world space, interpolate perspective-correctly with no 1/w
step) and that point has ``W > 0``. Triangles crossing ``W = 0`` or the near plane need no
clipping into pieces: only their screen bounding box comes from the part with ``W`` above
:func:`box_w`, and each pass decides per pixel which depths it keeps.

Determinism
-----------
* Top-left fill rule (:func:`edge_covers`): a pixel centre exactly on an edge (``e_i == 0``)
  belongs to the triangle for which that edge is a left edge (``de/dxs > 0``) or a top edge
  (``de/dxs == 0`` and ``de/dys < 0``). Two triangles sharing an edge compute edge functions
  that are exact negations of each other (same float64 operations on the same vertices, in
  swapped order), so exactly one of them owns the pixel: no cracks, no double coverage.
* Depth test on ``(float32 depth, triangle id)`` lexicographically (:func:`nearer`): the
  nearest fragment wins and exact ties go to the lower id. The result does not depend on
  drawing order, so it is the same for any thread count, tile size, batch split or culling.

Parallelism: triangles are set up in parallel, binned into square tiles in drawing order
(one thread: see :func:`bin_triangles`), and the passes rasterize tiles in parallel
(``prange``); each tile owns its pixels.
"""
from __future__ import annotations

import time
from typing import NamedTuple

import numpy as np
from numba import njit, prange

from cityshade.accel.kdtree_layout import KdTree, KdViews, record_id
from cityshade.errors import UsageError
from cityshade.raster import culling as cull
from cityshade.runtime.interpret import InterpretBudget, twin_if
from cityshade.runtime.memory import Scratch

#: Tile side in pixels: 64² pixels × (4 + 4 + 8 bytes) = 64 KiB of G-buffer per tile fits the
#: L2 cache, and 1080p gives 510 tiles, plenty to balance two cores (a 4096² depth map: 4096).
TILE_PX = 64
#: Side, in tiles, of the blocks :func:`tile_order` deals to the threads (4: 256² pixels).
AFFINITY_BLOCK = 4
#: Triangles per drawing batch: bounds the transient setup arrays (about 150 bytes per triangle
#: for the G-buffer, 280 for the depth pass: 40-75 MB per batch). Every batch costs four
#: parallel regions; on a machine shared with other work a region can wait milliseconds for a
#: descheduled thread (1.2 ms per empty region at 2 threads measured here under load), so
#: batches should not be small either.
MAX_BATCH = 262144
#: The depth pass's batches: about 270 bytes per triangle make a 262144-triangle batch's arrays larger
#: than glibc's largest mmap threshold (32 MiB), so every map would take fresh pages (a fault
#: each; 25 ms of a 4096² map of the 1M-triangle city at one thread); half of it reuses freed
#: heap memory.
DEPTH_BATCH = 131072
#: Slack of the pixel bounding box, in pixels: projected vertex positions and the pixel mapping
#: are float64 (errors ~1e-12 px), so a centre the edge functions find inside is never outside
#: the box; the edge functions alone decide coverage inside it.
BOX_SLACK_PX = 1e-6
#: Smallest W of the part of a triangle that gives its screen box, relative to the largest |W|
#: of its vertices (a triangle crossing W = 0 projects to infinity there; the box is clamped to
#: the image, so a tiny value only widens the box, never the coverage).
W_NEAR_REL = 1e-9
#: An edge bounds the covered columns of a row (depth pass) only when
#: ``|a| >= SPAN_MIN_SLOPE |b|``: the bound ``col = A y + B`` of a nearly row-parallel edge has
#: huge A and B whose cancellation could exceed the one column of slack (the exact test still
#: decides every texel).
SPAN_MIN_SLOPE = 1e-6
#: Depth pass: boxes at most this many columns wide (clipped to the tile) are tested texel by
#: texel without the per-row column bounds: for them the bounds cost more than the texels they
#: skip (most casters of a 4096² map of the 1M-triangle city; 14 % less raster time there, one
#: thread). The setup leaves out the bounds of triangles whose whole box is that narrow.
NARROW_COLS = 4

# Words of a set-up triangle: ``coef`` rows (both passes) and ``vals`` rows (per pass; two
# arrays keep the G-buffer's rows at 96 + 24 bytes, the layout its tile kernel reads fastest).
#: coef 0-8: a, b, c of the three edge functions (positive inside); 9-11: tie-ownership flags.
EDGE_WORDS = 12
#: vals 0-2: Z at the three vertices. The G-buffer needs no more.
Z_WORD = 0
GBUFFER_WORDS = 3
#: Depth pass: vals 3-5 W at the vertices; 6 a flag for triangles crossing W = 0; 7-9 the
#: screen-space depth plane ``Z/W = p x + q y + r`` of the others; 10-18 per edge the column
#: bound ``A y + B`` and its kind (1 lower, -1 upper, 0 none).
W_WORD = 3
GENERAL_WORD = 6
PLANE_WORD = 7
SPAN_WORD = 10
DEPTH_WORDS = 19


class ClipView(NamedTuple):
    """A view for the setup kernel (build it with :func:`clip_view`).

    ``m`` (16,) float64: row-major 4×4 matrix applied to ``(p - origin, 1)``; ``origin`` (3,);
    ``to_px`` (4,): ``col = to_px[0] x + to_px[1]``, ``row = to_px[2] y + to_px[3]`` (pixel
    centres at integers, from screen coordinates ``x = X/W``, ``y = Y/W``); ``xs`` (W,),
    ``ys`` (H,): screen coordinates of the pixel centres; ``width``, ``height`` (float pixels);
    ``w_is_z``: the matrix's W row is its Z row (a perspective G-buffer: W = Z = view depth,
    computed once);
    ``w_clip``: the screen box comes from the part of a triangle with W at least this (and at
    least ``W_NEAR_REL`` of its largest |W|); ``near``, ``far``: the G-buffer's depth range.
    """

    m: np.ndarray
    origin: np.ndarray
    to_px: np.ndarray
    xs: np.ndarray
    ys: np.ndarray
    width: float
    height: float
    w_clip: float
    near: float
    far: float
    w_is_z: bool


def clip_view(matrix, origin, to_px, xs, ys, *, w_clip: float = 0.0, near: float = 0.0,
              far: float = np.inf) -> ClipView:
    """A :class:`ClipView` from a (4, 4) matrix, its origin and the pixel mapping.

    Every array is a fresh writable copy (a few numbers each): a read-only one (a camera's
    origin from a memory-mapped scene) is another Numba type, so every kernel taking a view
    would compile twice (``setup_triangles`` alone 20-70 s on a cold cache)."""
    xs = np.array(xs, np.float64)
    ys = np.array(ys, np.float64)
    m = np.array(matrix, np.float64).reshape(16)
    return ClipView(m, np.array(origin, np.float64).reshape(3),
                    np.array(to_px, np.float64), xs, ys, float(xs.shape[0]),
                    float(ys.shape[0]), float(w_clip), float(near), float(far),
                    bool(np.array_equal(m[8:12], m[12:16])))


# --- per-pixel rules shared by the tile kernels ------------------------------------------------

@njit(cache=True, inline="always")
def edge_covers(e, own):
    """Whether edge value ``e`` admits the pixel: inside, or exactly on an edge the triangle
    owns (top-left rule)."""
    return not (e < 0.0 or (e == 0.0 and not own))


@njit(cache=True, inline="always")
def nearer(d, tri, cur_d, cur_tri):
    """Depth test with ties to the lower triangle id (independent of drawing order)."""
    return d < cur_d or (d == cur_d and tri < cur_tri)


@njit(cache=True, inline="always")
def edges(coef, j):
    """The three edge functions of set-up triangle ``j`` and its ownership flags."""
    return (coef[j, 0], coef[j, 1], coef[j, 2], coef[j, 3], coef[j, 4], coef[j, 5],
            coef[j, 6], coef[j, 7], coef[j, 8],
            coef[j, 9] != 0.0, coef[j, 10] != 0.0, coef[j, 11] != 0.0)


@njit(cache=True, inline="always")
def covers(x, a0, row0, own0, a1, row1, own1, a2, row2, own2):
    """Coverage of the pixel at screen x on a row (``row_i = b_i y + c_i``) by the three edges
    under the top-left rule: ``(inside, e0, e1, e2)``; stops at the first edge that refuses."""
    e0 = a0 * x + row0
    if not edge_covers(e0, own0):
        return False, e0, 0.0, 0.0
    e1 = a1 * x + row1
    if not edge_covers(e1, own1):
        return False, e0, e1, 0.0
    e2 = a2 * x + row2
    return edge_covers(e2, own2), e0, e1, e2


@njit(cache=True, inline="always")
def covered_span(xs, c0, c1, a0, row0, own0, a1, row1, own1, a2, row2, own2):
    """The first and last column of ``[c0, c1]`` that :func:`covers` admits on a row (first >
    last when none), found from both ends; every column between them is covered too.

    Exact, not a bound: along a row each edge value ``fl(a x + row)`` is monotone in the column
    (``xs`` increases and rounding preserves order), so each edge admits a prefix or a suffix
    of the columns and the three together one interval. Testing only its ends and the columns
    outside it took 12 % off the raster time of a 4096² map of the 1M-triangle city.
    """
    while c0 <= c1 and not covers(xs[c0], a0, row0, own0, a1, row1, own1, a2, row2, own2)[0]:
        c0 += 1
    while c1 > c0 and not covers(xs[c1], a0, row0, own0, a1, row1, own1, a2, row2, own2)[0]:
        c1 -= 1
    return c0, c1


@njit(cache=True, inline="always")
def barycentrics(e0, e1, e2):
    """``(ok, u, v)``: the barycentrics ``e1 / s``, ``e2 / s`` of the point where a covered
    pixel's ray meets the triangle's plane (``s = e0 + e1 + e2``; not ok when ``s`` is not
    positive: the plane is seen edge-on or the point lies behind the projection centre)."""
    s = e0 + e1 + e2
    if not s > 0.0:
        return False, 0.0, 0.0
    inv = 1.0 / s
    return True, e1 * inv, e2 * inv


@njit(cache=True, inline="always")
def vertex_words(vals, j, word):
    """A per-vertex value of set-up triangle ``j`` (Z at ``Z_WORD``, W at ``W_WORD``) as
    (value at v0, v1 - v0, v2 - v0), for interpolation with barycentrics (u, v)."""
    v0 = vals[j, word]
    return v0, vals[j, word + 1] - v0, vals[j, word + 2] - v0


@njit(cache=True, inline="always")
def tile_span(start, tile, tiles_x, tile_px, shape):
    """A tile's entries ``[m0, m1)`` in the binned list and its first and last column and row
    (inclusive) in an image of ``shape`` (H, W, ...)."""
    tc0 = (tile % tiles_x) * tile_px
    tr0 = (tile // tiles_x) * tile_px
    return (start[tile], start[tile + 1], tc0, min(tc0 + tile_px, shape[1]) - 1, tr0,
            min(tr0 + tile_px, shape[0]) - 1)


# --- setup ------------------------------------------------------------------------------------
# The setup's small helpers are plain functions, not ``inline="always"``, with the same run
# time: Numba's parallel passes go over the whole ``prange`` body, and with the helpers' code
# in it the first compile of ``setup_triangles`` took 7.8 CPU s (render of the sample city,
# empty cache, side by side at load 2; 11.8-12 at load 4-10), 5.0 without. They keep numpy's
# error model, as in the ``prange`` body they were inlined into (a division by zero gives
# inf). Not ``_depth_words``, which writes the batch arrays: as a call it made the depth
# pass's setup some 20 % slower. The body itself stays a ``prange`` body: called per item or
# chunk from a plain kernel, the same code ran the setup 3-5x slower.

@njit(cache=True, error_model="numpy")
def _transform(m, origin, w_is_z, px, py, pz):
    """Render-space point → (X, Y, Z, W) = m @ (p - origin, 1)."""
    dx = px - origin[0]
    dy = py - origin[1]
    dz = pz - origin[2]
    z = m[8] * dx + m[9] * dy + m[10] * dz + m[11]
    return (m[0] * dx + m[1] * dy + m[2] * dz + m[3], m[4] * dx + m[5] * dy + m[6] * dz + m[7],
            z, z if w_is_z else m[12] * dx + m[13] * dy + m[14] * dz + m[15])


@njit(cache=True, error_model="numpy")
def _over_w(v, w):
    """``v / w``, skipping the division when ``w`` is exactly 1 (every vertex of an
    orthographic view; ``v / 1.0 == v`` exactly). With the column bounds left out of narrow
    boxes, 30 % less setup CPU for the 4096² map of the 1M-triangle city."""
    return v if w == 1.0 else v / w


@njit(cache=True, error_model="numpy")
def _grow(box, sx, sy):
    """Extend the screen box (xmin, xmax, ymin, ymax) by a point."""
    return min(box[0], sx), max(box[1], sx), min(box[2], sy), max(box[3], sy)


@njit(cache=True, error_model="numpy")
def _w_cross(xa, ya, wa, xb, yb, wb, wn):
    """Screen position of the point where edge a-b crosses W = wn."""
    s = (wn - wa) / (wb - wa)
    return (xa + s * (xb - xa)) / wn, (ya + s * (yb - ya)) / wn


@njit(cache=True, inline="always")
def _vertex(vertices, triangles, tree, from_records, item, corner):
    """Vertex ``corner`` of a triangle id, or of a kd-tree record when ``from_records``."""
    if from_records:
        c = 3 * corner
        return (np.float64(tree.recs[item, c]), np.float64(tree.recs[item, c + 1]),
                np.float64(tree.recs[item, c + 2]))
    q = triangles[item, corner]
    return np.float64(vertices[q, 0]), np.float64(vertices[q, 1]), np.float64(vertices[q, 2])


@njit(cache=True, parallel=True)
def setup_triangles(vertices, triangles, tree, from_records, items, view, depth_pass, ids, coef,
                    vals, bbox):
    """Per triangle: edge functions, vertex depths and the pixel bounding box.

    Parameters
    ----------
    vertices : (V, 3) float32; triangles : (T, 3) int32
        The scene (read when ``from_records`` is False).
    tree : KdViews
        The kd-tree, whose records (vertices and triangle id) are read in the walk's order
        without chasing vertex indices when ``from_records``.
    items : (N,) int32
        Triangle ids, or record indices when ``from_records``.
    view : ClipView
    depth_pass : bool
        False, the G-buffer: only triangles with some vertex depth Z in [near, far], and
        ``vals`` (N, GBUFFER_WORDS). True, the light's depth pass: only triangles with some
        vertex at W > 0 and not all beyond the far plane (Z > W), and ``vals``
        (N, DEPTH_WORDS) with the W values, depth plane and column bounds.
    ids : (N,) int32 out
        Triangle ids.
    coef : (N, EDGE_WORDS) float64 out; vals : (N, GBUFFER_WORDS or DEPTH_WORDS) float64 out
        Rows described at ``EDGE_WORDS`` ff.; not set where nothing is drawn.
    bbox : (N, 4) int32 out
        col0, col1, row0, row1 inclusive; col0 > col1 when the triangle covers no pixel.
    """
    n = items.shape[0]
    m = view.m
    org = view.origin
    to_px = view.to_px
    w_is_z = view.w_is_z
    for j in prange(n):
        bbox[j, 0] = 1
        bbox[j, 1] = 0
        bbox[j, 2] = 1
        bbox[j, 3] = 0
        item = items[j]
        ids[j] = record_id(tree, item) if from_records else item
        px, py, pz = _vertex(vertices, triangles, tree, from_records, item, 0)
        x0, y0, z0, w0 = _transform(m, org, w_is_z, px, py, pz)
        px, py, pz = _vertex(vertices, triangles, tree, from_records, item, 1)
        x1, y1, z1, w1 = _transform(m, org, w_is_z, px, py, pz)
        px, py, pz = _vertex(vertices, triangles, tree, from_records, item, 2)
        x2, y2, z2, w2 = _transform(m, org, w_is_z, px, py, pz)
        wmax = max(w0, w1, w2)
        if depth_pass:
            if not wmax > 0.0:
                continue            # entirely behind the projection centre (or NaN)
            if z0 > w0 and z1 > w1 and z2 > w2:
                continue            # entirely beyond the far plane
        elif max(z0, z1, z2) < view.near or min(z0, z1, z2) > view.far:
            continue
        # Screen box of the part with W >= wn.
        wn = max(view.w_clip, W_NEAR_REL * max(wmax, -min(w0, w1, w2)))
        box = (np.inf, -np.inf, np.inf, -np.inf)
        if w0 >= wn:
            box = _grow(box, _over_w(x0, w0), _over_w(y0, w0))
        if w1 >= wn:
            box = _grow(box, _over_w(x1, w1), _over_w(y1, w1))
        if w2 >= wn:
            box = _grow(box, _over_w(x2, w2), _over_w(y2, w2))
        if (w0 >= wn) != (w1 >= wn):
            sx, sy = _w_cross(x0, y0, w0, x1, y1, w1, wn)
            box = _grow(box, sx, sy)
        if (w1 >= wn) != (w2 >= wn):
            sx, sy = _w_cross(x1, y1, w1, x2, y2, w2, wn)
            box = _grow(box, sx, sy)
        if (w2 >= wn) != (w0 >= wn):
            sx, sy = _w_cross(x2, y2, w2, x0, y0, w0, wn)
            box = _grow(box, sx, sy)
        # Pixel centres inside the box (screen y up, rows down; a sub-pixel triangle between
        # centres gets none).
        c0 = max(np.ceil(to_px[0] * box[0] + to_px[1] - BOX_SLACK_PX), 0.0)
        c1 = min(np.floor(to_px[0] * box[1] + to_px[1] + BOX_SLACK_PX), view.width - 1.0)
        r0 = max(np.ceil(to_px[2] * box[3] + to_px[3] - BOX_SLACK_PX), 0.0)
        r1 = min(np.floor(to_px[2] * box[2] + to_px[3] + BOX_SLACK_PX), view.height - 1.0)
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
            continue        # plane through the eye (or zero area, or NaN): covers nothing
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
            # Top-left rule: the edge owns its exact zeros when it is a left edge (a > 0) or a
            # top edge (a == 0, b < 0; screen y grows upwards).
            a = coef[j, 3 * i]
            b = coef[j, 3 * i + 1]
            coef[j, 9 + i] = 1.0 if (a > 0.0 or (a == 0.0 and b < 0.0)) else 0.0
        vals[j, Z_WORD] = z0
        vals[j, Z_WORD + 1] = z1
        vals[j, Z_WORD + 2] = z2
        if depth_pass:
            _depth_words(coef, vals, j, x0, y0, z0, w0, x1, y1, z1, w1, x2, y2, z2, w2, to_px,
                         c1 - c0 >= NARROW_COLS)
        bbox[j, 0] = int(c0)
        bbox[j, 1] = int(c1)
        bbox[j, 2] = int(r0)
        bbox[j, 3] = int(r1)


@njit(cache=True, inline="always")
def _depth_words(coef, vals, j, x0, y0, z0, w0, x1, y1, z1, w1, x2, y2, z2, w2, to_px, wide):
    """The depth pass's extra words: W, depth plane, column bounds (see ``W_WORD`` ff.; the
    bounds only for a ``wide`` box or a triangle crossing W = 0, the others never read them)."""
    vals[j, W_WORD] = w0
    vals[j, W_WORD + 1] = w1
    vals[j, W_WORD + 2] = w2
    vals[j, GENERAL_WORD] = 1.0
    if w0 > 0.0 and w1 > 0.0 and w2 > 0.0:
        # NDC depth is affine in screen x, y over a plane (the z-buffer's classic property):
        # z = p x + q y + r through the three projected vertices; every point of the triangle
        # has W > 0, so no per-texel W test is needed either.
        nx0, ny0, nz0 = _over_w(x0, w0), _over_w(y0, w0), _over_w(z0, w0)
        ex1 = _over_w(x1, w1) - nx0
        ey1 = _over_w(y1, w1) - ny0
        ez1 = _over_w(z1, w1) - nz0
        ex2 = _over_w(x2, w2) - nx0
        ey2 = _over_w(y2, w2) - ny0
        ez2 = _over_w(z2, w2) - nz0
        den = ex1 * ey2 - ex2 * ey1
        if den > 0.0 or den < 0.0:
            pp = (ez1 * ey2 - ez2 * ey1) / den
            qq = (ex1 * ez2 - ex2 * ez1) / den
            vals[j, GENERAL_WORD] = 0.0
            vals[j, PLANE_WORD] = pp
            vals[j, PLANE_WORD + 1] = qq
            vals[j, PLANE_WORD + 2] = nz0 - pp * nx0 - qq * ny0
    if not wide and vals[j, GENERAL_WORD] == 0.0:
        return
    # Column bound of each edge in a row at screen y: e = a x + b y + c >= 0 gives
    # x >= -(b y + c) / a (a > 0) or x <= ... (a < 0); in pixel columns A y + B.
    for i in range(3):
        a = coef[j, 3 * i]
        b = coef[j, 3 * i + 1]
        kind = 0.0
        if abs(a) >= SPAN_MIN_SLOPE * abs(b) and (a > 0.0 or a < 0.0):
            kind = 1.0 if a > 0.0 else -1.0
            vals[j, SPAN_WORD + 3 * i] = -to_px[0] * b / a
            vals[j, SPAN_WORD + 1 + 3 * i] = -to_px[0] * coef[j, 3 * i + 2] / a + to_px[1]
        vals[j, SPAN_WORD + 2 + 3 * i] = kind


def tile_order(tiles_x: int, tiles_y: int, threads: int) -> np.ndarray:
    """Tiles in the order the passes' tile kernels hand them out under a static schedule
    (:func:`cityshade.trace.bricks.static_schedule`): row by row for one thread; for more,
    blocks of ``AFFINITY_BLOCK``² tiles dealt diagonally to the threads (block (bx, by) to
    thread (bx + by) mod threads), each thread's tiles one contiguous part of the order.

    A batch of the walk holds the triangles of one part of the model, i.e. of a few hundred
    tiles close together: dealt dynamically, a tile went to a different thread in each batch
    and its pixels moved between the cores' caches (the depth pass of a 4096² map of the
    1M-triangle city, raster at 2 threads 108-111 ms against 86 when all casters were one
    batch); with each tile always on one thread and the blocks spread over the threads,
    86-87 ms in 7 batches.
    """
    tiles = np.arange(tiles_x * tiles_y, dtype=np.int64)
    if threads <= 1:
        return tiles
    colour = ((tiles % tiles_x) // AFFINITY_BLOCK + (tiles // tiles_x) // AFFINITY_BLOCK) % threads
    return np.concatenate([tiles[colour == t] for t in range(threads)])


# --- binning and the date filter --------------------------------------------------------------

@njit(cache=True, inline="always")
def _tile_of(px, tile_px, shift):
    """``px // tile_px`` for a pixel index ``px >= 0``; a shift when ``shift >= 0`` (``tile_px``
    a power of two, the default: the four integer divisions per triangle and pass were half
    the binning's CPU for the 4096² map of the 1M-triangle city)."""
    return px >> shift if shift >= 0 else px // tile_px


@njit(cache=True)
def _bin_pass(bbox, tile_px, tiles_x, acc, items, write):
    """One binning pass over the triangles in drawing order: ``acc[tile] += 1`` for every tile
    a triangle's box meets, and first, when ``write``, ``items[acc[tile]] = triangle`` (``acc``
    then holds the fill positions)."""
    shift = -1
    if tile_px & (tile_px - 1) == 0:
        shift = 0
        while (1 << shift) < tile_px:
            shift += 1
    for j in range(bbox.shape[0]):
        if bbox[j, 0] > bbox[j, 1]:
            continue
        for ty in range(_tile_of(bbox[j, 2], tile_px, shift),
                        _tile_of(bbox[j, 3], tile_px, shift) + 1):
            for tx in range(_tile_of(bbox[j, 0], tile_px, shift),
                            _tile_of(bbox[j, 1], tile_px, shift) + 1):
                t = ty * tiles_x + tx
                if write:
                    items[acc[t]] = j
                acc[t] += 1


@njit(cache=True)
def bin_triangles(bbox, tile_px, tiles_x, tiles_y):
    """Tile lists in drawing order: ``(start (tiles + 1,) int64, items (M,) int32)``.

    One thread: the two passes took 10 ms for the 4096² map of the 1M-triangle city, and the
    earlier parallel passes over 16 chunks of triangles took 40-100 ms at 2 threads on this
    2-core machine, dynamic scheduling or not (cause not pinned down: the counting pass, whose
    chunks write apart, was as slow as the filling one).
    """
    n_tiles = tiles_x * tiles_y
    counts = np.zeros(n_tiles, np.int64)
    # The flag as np.bool_, not a literal: one compile of _bin_pass serves both passes.
    _bin_pass(bbox, tile_px, tiles_x, counts, np.empty(0, np.int32), np.bool_(False))
    start = np.zeros(n_tiles + 1, np.int64)
    # A running sum by a loop: ``start[1:] = np.cumsum(counts)`` made Numba compile the
    # slice copy's shape-mismatch message (string formatting), seconds on first use.
    for t in range(n_tiles):
        start[t + 1] = start[t] + counts[t]
    fill = start[:n_tiles].copy()
    items = np.empty(start[n_tiles], np.int32)
    _bin_pass(bbox, tile_px, tiles_x, fill, items, np.bool_(True))
    return start, items


@njit(cache=True)
def present_triangles(t_begin, t_end, t_days):
    """Ids (int32) of the triangles standing at ``t_days`` (``begin <= t_days < end``)."""
    n = t_begin.shape[0]
    out = np.empty(n, np.int32)
    k = 0
    for i in range(n):
        if t_begin[i] <= t_days < t_end[i]:
            out[k] = i
            k += 1
    return out[:k]


# --- drivers ----------------------------------------------------------------------------------

def check_scene(scene) -> None:
    """Refuse scene arrays the kernels cannot take."""
    v = scene.vertices
    tris = scene.triangles
    if v.ndim != 2 or v.shape[1] != 3 or v.dtype != np.float32:
        raise UsageError(f"scene vertices must be (V, 3) float32, not {v.shape} {v.dtype}")
    if tris.ndim != 2 or tris.shape[1] != 3 or tris.dtype != np.int32:
        raise UsageError(f"scene triangles must be (T, 3) int32, not {tris.shape} {tris.dtype}")


_NO_RECORDS = np.zeros((1, 16), np.float32)


def kernel_tree(scene) -> KdViews:
    """The scene's kd-tree views, or a one-record stand-in for a scene without kd-tree (the
    setup then reads triangle ids only)."""
    tree = getattr(scene, "kdtree", None)
    if isinstance(tree, KdTree):
        return tree.views
    nodes = np.zeros((1, 2), np.uint32)
    return KdViews(nodes, nodes.view(np.float32), np.zeros(1, np.int32), _NO_RECORDS,
                   _NO_RECORDS.view(np.float64), _NO_RECORDS.view(np.int32))


#: The batch arrays of the passes (one pass at a time holds them; see :class:`Batcher`).
_BATCH_SCRATCH = Scratch()

#: Triangles a process sets up and bins through the kernels' interpreted twins while neither
#: kernel is compiled or cached (:mod:`cityshade.runtime.interpret`): the sample city's 1990
#: overview, 1,190 triangles, took 57 + 10 ms interpreted, where compiling the two takes 5-7
#: CPU s on first use; 20,000 triangles are about a second.
INTERPRET_TRIANGLES = 20_000
_INTERPRET = InterpretBudget(INTERPRET_TRIANGLES, setup_triangles, bin_triangles)
#: The date filter's triangles likewise: 0.4 µs a triangle interpreted, 0.3 s to compile.
_INTERPRET_PRESENT = InterpretBudget(500_000, present_triangles)


def _setup_kernels(n: int):
    """``setup_triangles`` and ``bin_triangles``, or for ``n`` triangles within the budget of a
    first use their interpreted twins (the same operations: bit-identical, tested)."""
    interpret = _INTERPRET.take(n)
    return twin_if(interpret, setup_triangles), twin_if(interpret, bin_triangles)


class Batcher:
    """Set up, bin and rasterize batches of triangles into one target.

    ``raster(start, items, ids, coef, vals, bbox)`` is the pass's tile kernel call; timings of the
    three steps accumulate in ``timings`` (seconds). ``batch`` is the pass's batch size
    (``DEPTH_BATCH`` or ``MAX_BATCH``).
    """

    def __init__(self, scene, view: ClipView, depth_pass: bool, tile_px: int, raster):
        self.vertices = scene.vertices
        self.triangles = scene.triangles
        self.tree = kernel_tree(scene)
        self.view = view
        self.depth_pass = bool(depth_pass)
        self.words = DEPTH_WORDS if depth_pass else GBUFFER_WORDS
        self.tile_px = int(tile_px)
        self.tiles_x = -(-int(view.width) // self.tile_px)
        self.tiles_y = -(-int(view.height) // self.tile_px)
        self.raster = raster
        self.batch = DEPTH_BATCH if depth_pass else MAX_BATCH
        self.timings = {"setup_s": 0.0, "bin_s": 0.0, "raster_s": 0.0}
        self.batches = 0
        self.drawn = 0
        self.tile_triangles = 0

    def draw(self, items: np.ndarray, from_records: bool) -> None:
        """Draw triangle ids, or kd-tree record indices when ``from_records``."""
        n = items.shape[0]
        if n == 0:
            return
        t0 = time.perf_counter()
        # The batch arrays are kept for the later batches and passes (runtime.memory.Scratch): fresh
        # pages cost a fault and a zeroing each on first touch (about a third of the setup's
        # time when every batch allocated its own, and 100-200 ms of a 1M-triangle depth pass
        # on a loaded machine, depending on what ran before, when every pass did).
        ws = _BATCH_SCRATCH.take()
        try:
            kind = "depth" if self.depth_pass else "gbuffer"
            ids = ws.get(f"{kind}.ids", n, np.int32)
            coef = ws.get(f"{kind}.coef", (n, EDGE_WORDS))
            vals = ws.get(f"{kind}.vals", (n, self.words))
            bbox = ws.get(f"{kind}.bbox", (n, 4), np.int32)
            setup, binning = _setup_kernels(n)
            with np.errstate(all="ignore"):     # numpy's error model, as the kernels have
                setup(self.vertices, self.triangles, self.tree, from_records, items,
                      self.view, self.depth_pass, ids, coef, vals, bbox)
            t1 = time.perf_counter()
            start, binned = binning(bbox, self.tile_px, self.tiles_x, self.tiles_y)
            t2 = time.perf_counter()
            self.raster(start, binned, ids, coef, vals, bbox)
            t3 = time.perf_counter()
        finally:
            ws.give_back()
        self.timings["setup_s"] += t1 - t0
        self.timings["bin_s"] += t2 - t1
        self.timings["raster_s"] += t3 - t2
        self.batches += 1
        self.drawn += n
        self.tile_triangles += int(binned.shape[0])

    def draw_present(self, scene, t_days: float) -> tuple[int, float]:
        """Draw every triangle standing at ``t_days`` in id order (no kd-tree walk).

        Returns (triangles removed by the date, seconds spent filtering)."""
        t0 = time.perf_counter()
        present = twin_if(_INTERPRET_PRESENT.take(len(scene.triangles)), present_triangles)
        ids = present(np.asarray(scene.tri_t_begin_days, np.float64),
                      np.asarray(scene.tri_t_end_days, np.float64), t_days)
        filter_s = time.perf_counter() - t0
        for b in range(0, ids.shape[0], self.batch):
            self.draw(ids[b:b + self.batch], False)
        return int(scene.triangles.shape[0] - ids.shape[0]), filter_s


class CulledWalk:
    """The resumable front-to-back kd-tree walk (:func:`cityshade.raster.culling.walk`) that
    feeds a :class:`Batcher` the triangles standing at ``t_days`` inside ``planes``.

    Parameters
    ----------
    tree : KdTree
    t_days : float
    planes : (P, 4) float64
        Culling planes (P <= 63), inside ``n . p + d >= 0``.
    order_point : (4,) float64
        Walk order, homogeneous: ``(x, y, z, 1)`` walks nearest the point first (a camera's
        eye), ``(dx, dy, dz, 0)`` nearest a viewer infinitely far along the direction first (a
        map camera looking down, a light).
    n_triangles : int
        Triangles of the scene (each is emitted once though the tree may list it in several
        leaves).
    """

    def __init__(self, tree: KdTree, t_days: float, planes, order_point, n_triangles: int):
        self.tree = tree.views
        refs, first, biggest = cull.tree_info(tree)
        self.info = (refs, first)
        self.t_days = float(t_days)
        self.planes = np.ascontiguousarray(planes, np.float64)
        self.order_point = np.ascontiguousarray(order_point, np.float64)
        lo, hi, _ = tree.box_scale_m()
        st_node = np.zeros(cull.STACK_SIZE, np.int64)
        st_box = np.zeros((cull.STACK_SIZE, 6))
        st_mask = np.zeros(cull.STACK_SIZE, np.int64)
        st_mask[0] = (1 << self.planes.shape[0]) - 1
        st_box[0, :3], st_box[0, 3:] = lo, hi
        self.stack = (st_node, st_box, st_mask, np.ones(1, np.int64))
        self.drawn = np.zeros(int(n_triangles), np.uint8)
        self.out = np.empty(MAX_BATCH + biggest, np.int32)
        self.stats = np.zeros(cull.N_STATS, np.int64)
        self.walk_s = 0.0

    @property
    def done(self) -> bool:
        """Whether every node has been walked."""
        return self.stack[3][0] == 0

    def next(self, max_out: int = MAX_BATCH, occlusion=None) -> np.ndarray:
        """Record indices of the next about ``max_out`` (<= MAX_BATCH) triangles, in walk order.

        ``occlusion`` is None, or ``(query_min_refs, cam, hiz_block, hiz_tile, block_px,
        tile_px)`` for :func:`cityshade.raster.culling.box_occluded` queries.
        """
        t0 = time.perf_counter()
        n = cull.walk(self.tree, self.info, self.t_days, self.planes, self.order_point,
                      occlusion, self.stack, self.drawn, self.out, min(int(max_out), MAX_BATCH),
                      self.stats)
        self.walk_s += time.perf_counter() - t0
        return self.out[:n]

    def stat_dict(self) -> dict[str, int]:
        """The walk's counts by name (``culling.STAT_NAMES``)."""
        return {name: int(v) for name, v in zip(cull.STAT_NAMES, self.stats)}
