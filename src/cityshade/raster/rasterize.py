"""The tile-parallel Numba triangle rasterizer that fills the G-buffer.

Method
------
Homogeneous rasterization (Olano and Greer, "Triangle Scan Conversion using 2D Homogeneous
Coordinates", 1997). Each vertex becomes ``v~ = (X, Y, Z)`` in the camera frame (map views:
``(x, y, 1)``); the three edge functions ``e_i(xs, ys) = (v~_j x v~_k) . (xs, ys, 1)`` are
linear in the pixel's screen coordinates. A pixel is covered when all three have the sign of
``det = v~_0 . (v~_1 x v~_2)``; then ``e_i / sum(e)`` are *exactly* the barycentrics of the point
where the pixel's ray meets the triangle's plane (so attributes are perspective-correct by
construction, with no 1/w interpolation) and that point lies in front of the eye. Triangles
that cross the near plane need no clipping into pieces: only their screen bounding box comes
from the part in front of the near plane, and each pixel keeps the fragment only when its depth
lies in [near, far]. Depth is the interpolated view depth times the pixel ray's length, i.e.
the distance from the eye along the ray (maps: below the camera plane), stored as float32.

Determinism
-----------
* Top-left fill rule: a pixel centre exactly on an edge (``e_i == 0``) belongs to the triangle
  for which that edge is a left edge (``de/dxs > 0``) or a top edge (``de/dxs == 0`` and
  ``de/dys < 0``). Two triangles sharing an edge compute edge functions that are exact
  negations of each other (same float64 operations on the same vertices, in swapped order), so
  exactly one of them owns the pixel: no cracks, no double coverage.
* Depth test on ``(float32 depth, triangle id)`` lexicographically: the nearest fragment wins
  and exact ties go to the lower id. The result does not depend on drawing order, so it is the
  same for any thread count, tile size, batch split or culling setting.

Parallelism: triangles are set up in parallel, binned serially into square tiles (in drawing
order), and tiles are rasterized in parallel (``prange``); each tile owns its pixels.
"""
from __future__ import annotations

import math
import time

import numba
import numpy as np
from numba import njit, prange

from cityshade.errors import UsageError
from cityshade.raster import culling as cull
from cityshade.raster.camera import Camera
from cityshade.raster.gbuffer import GBuffer

#: Tile side in pixels: 64² pixels × (4 + 4 + 8 bytes) = 64 KiB of G-buffer per tile fits the
#: L2 cache, and 1080p gives 510 tiles, plenty to balance two cores.
TILE_PX = 64
#: Side of the blocks of the hierarchical max-depth buffer (8 blocks per tile side).
BLOCK_PX = 8
#: Triangles per drawing batch (bounds the transient setup arrays: 140 bytes per triangle,
#: 37 MB per batch). Every batch costs four parallel regions; on a machine shared with other
#: work a region can wait milliseconds for a descheduled thread (1.2 ms per empty region at 2
#: threads measured here under load), so batches should not be small either.
MAX_BATCH = 262144
#: First batch with occlusion culling: small, so the nearest surfaces are in the depth buffer
#: before the first queries; later batches double up to MAX_BATCH.
FIRST_OCCLUSION_BATCH = 2048
#: "auto" occlusion culling judges the queries after this many of them ...
AUTO_MIN_QUERIES = 2000
#: ... and switches them off (and the max-depth refresh) unless they removed at least this
#: many triangle references per query: on the 1M-triangle city (benchmarks/render.py, one
#: thread) a query cost about as much as drawing 2-3 references (references include the
#: tree's duplicates and the triangles absent at the date).
AUTO_REFS_PER_QUERY = 3.0
#: Slack of the pixel bounding box, in pixels: projected vertex positions and the pixel
#: mapping are float64 (errors ~1e-12 px), so a centre the edge functions find inside is never
#: outside the box; the edge functions alone decide coverage inside it.
BOX_SLACK_PX = 1e-6
#: Chunks of the parallel binning (several per thread for balance; any value gives the same
#: lists).
BIN_CHUNKS = 16
#: Words per set-up triangle: 3 × (a, b, c) edge coefficients, 3 tie-ownership flags.
_SETUP_WORDS = 12

# Camera parameter vector shared with culling.box_occluded (see camera_params).
_P_MODE, _P_NEAR, _P_FAR, _P_EYE_Z = 0, 13, 14, 15


def camera_params(camera: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flat camera description for the kernels.

    Returns
    -------
    cam : (24,) float64
        0 mode (0 perspective, 1 map); 1-3 eye; 4-6 right; 7-9 up; 10-12 forward; 13 near;
        14 far; 15 map camera-plane height; 16, 17 ``col = a xs + b``; 18, 19
        ``row = a ys + b`` (pixel-centre index from screen coordinates); 20 W; 21 H.
    xs : (W,) float64; ys : (H,) float64
        Screen coordinates of the pixel centres (:meth:`Camera.screen_coordinates`).
    """
    xs, ys = camera.screen_coordinates()
    right, up, fwd = camera.frame()
    cam = np.zeros(24)
    cam[0] = 1.0 if camera.kind == "map" else 0.0
    cam[1:4] = camera.eye_m
    cam[4:7], cam[7:10], cam[10:13] = right, up, fwd
    cam[13], cam[14] = camera.near_m, camera.far_m
    cam[15] = camera.eye_m[2]
    w, h = camera.width_px, camera.height_px
    if camera.kind == "map":
        px = camera.pixel_size_m
        cam[16], cam[17] = 1.0 / px, -camera.x_left_m / px - 0.5
        cam[18], cam[19] = -1.0 / px, camera.y_top_m / px - 0.5
    else:
        p = camera.pitch
        cam[16], cam[17] = 1.0 / p, w / 2.0 - 0.5
        cam[18], cam[19] = -1.0 / p, h / 2.0 - 0.5
    cam[20], cam[21] = w, h
    return cam, xs, ys


@njit(cache=True, inline="always")
def _camera_vertex(px, py, pz, cam, ortho):
    """Render-space point → homogeneous camera coordinates (X, Y, Z) and its view depth."""
    if ortho:
        return px, py, 1.0, cam[_P_EYE_Z] - pz
    dx = px - cam[1]
    dy = py - cam[2]
    dz = pz - cam[3]
    z = cam[10] * dx + cam[11] * dy + cam[12] * dz
    return (cam[4] * dx + cam[5] * dy + cam[6] * dz, cam[7] * dx + cam[8] * dy + cam[9] * dz,
            z, z)


@njit(cache=True, inline="always")
def _grow_box(box, sx, sy):
    """Extend the screen box (xmin, xmax, ymin, ymax) by a point."""
    return min(box[0], sx), max(box[1], sx), min(box[2], sy), max(box[3], sy)


@njit(cache=True, inline="always")
def _clip_point(xa, ya, za, xb, yb, zb, near):
    """Screen position of the point where edge a-b crosses the near plane."""
    s = (near - za) / (zb - za)
    return (xa + s * (xb - xa)) / near, (ya + s * (yb - ya)) / near


@njit(cache=True, parallel=True)
def _setup(vertices, triangles, recs, from_records, items, cam, ids, coef, zs, bbox):
    """Per triangle: normalised edge functions, vertex depths and the pixel bounding box.

    ``items`` (N,) are triangle ids (vertices through ``triangles``) or, when
    ``from_records``, indices of kd-tree triangle records (float32 (K, 16): vertices in
    columns 0-8, the triangle id's int32 bits in column 9), read in the walk's order without
    chasing vertex indices. Writes ``ids`` (N,) int32 triangle ids; ``coef`` (N, 12): a, b, c of
    the three edge functions (positive inside) and three 0/1 tie-ownership flags; ``zs``
    (N, 3): view depth of the vertices; ``bbox`` (N, 4) int32: col0, col1, row0, row1
    inclusive (col0 > col1 when nothing is drawn; then ``coef`` and ``zs`` are not set).
    """
    n = items.shape[0]
    rec_ids = recs.view(np.int32)
    w = cam[20]
    h = cam[21]
    near = cam[_P_NEAR]
    far = cam[_P_FAR]
    ortho = cam[_P_MODE] != 0.0
    for j in prange(n):
        bbox[j, 0] = 1
        bbox[j, 1] = 0
        bbox[j, 2] = 1
        bbox[j, 3] = 0
        item = items[j]
        # The three vertices in camera coordinates.
        if from_records:
            ids[j] = rec_ids[item, 9]
            x0, y0, z0, d0 = _camera_vertex(np.float64(recs[item, 0]), np.float64(recs[item, 1]),
                                            np.float64(recs[item, 2]), cam, ortho)
            x1, y1, z1, d1 = _camera_vertex(np.float64(recs[item, 3]), np.float64(recs[item, 4]),
                                            np.float64(recs[item, 5]), cam, ortho)
            x2, y2, z2, d2 = _camera_vertex(np.float64(recs[item, 6]), np.float64(recs[item, 7]),
                                            np.float64(recs[item, 8]), cam, ortho)
        else:
            ids[j] = item
            q0 = triangles[item, 0]
            q1 = triangles[item, 1]
            q2 = triangles[item, 2]
            x0, y0, z0, d0 = _camera_vertex(np.float64(vertices[q0, 0]),
                                            np.float64(vertices[q0, 1]),
                                            np.float64(vertices[q0, 2]), cam, ortho)
            x1, y1, z1, d1 = _camera_vertex(np.float64(vertices[q1, 0]),
                                            np.float64(vertices[q1, 1]),
                                            np.float64(vertices[q1, 2]), cam, ortho)
            x2, y2, z2, d2 = _camera_vertex(np.float64(vertices[q2, 0]),
                                            np.float64(vertices[q2, 1]),
                                            np.float64(vertices[q2, 2]), cam, ortho)
        if max(d0, d1, d2) < near or min(d0, d1, d2) > far:
            continue
        # Screen box of the part in front of the near plane (near-plane clipping).
        box = (np.inf, -np.inf, np.inf, -np.inf)
        if ortho:
            box = _grow_box(box, x0, y0)
            box = _grow_box(box, x1, y1)
            box = _grow_box(box, x2, y2)
        else:
            if z0 >= near:
                box = _grow_box(box, x0 / z0, y0 / z0)
            if z1 >= near:
                box = _grow_box(box, x1 / z1, y1 / z1)
            if z2 >= near:
                box = _grow_box(box, x2 / z2, y2 / z2)
            if (z0 >= near) != (z1 >= near):
                sx, sy = _clip_point(x0, y0, z0, x1, y1, z1, near)
                box = _grow_box(box, sx, sy)
            if (z1 >= near) != (z2 >= near):
                sx, sy = _clip_point(x1, y1, z1, x2, y2, z2, near)
                box = _grow_box(box, sx, sy)
            if (z2 >= near) != (z0 >= near):
                sx, sy = _clip_point(x2, y2, z2, x0, y0, z0, near)
                box = _grow_box(box, sx, sy)
        # Pixel centres inside the box (a sub-pixel triangle between centres gets none).
        c0 = max(np.ceil(cam[16] * box[0] + cam[17] - BOX_SLACK_PX), 0.0)
        c1 = min(np.floor(cam[16] * box[1] + cam[17] + BOX_SLACK_PX), w - 1.0)
        r0 = max(np.ceil(cam[18] * box[3] + cam[19] - BOX_SLACK_PX), 0.0)
        r1 = min(np.floor(cam[18] * box[2] + cam[19] + BOX_SLACK_PX), h - 1.0)
        if not (c0 <= c1 and r0 <= r1):
            continue
        # Edge function of the edge opposite vertex i: v~_j x v~_k (j, k = i+1, i+2).
        a0 = y1 * z2 - z1 * y2
        b0 = z1 * x2 - x1 * z2
        k0 = x1 * y2 - y1 * x2
        a1 = y2 * z0 - z2 * y0
        b1 = z2 * x0 - x2 * z0
        k1 = x2 * y0 - y2 * x0
        a2 = y0 * z1 - z0 * y1
        b2 = z0 * x1 - x0 * z1
        k2 = x0 * y1 - y0 * x1
        det = x0 * a0 + y0 * b0 + z0 * k0
        if not (det > 0.0 or det < 0.0):
            continue        # plane through the eye (or zero area, or NaN): never visible
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
            coef[j, 9 + i] = 1.0 if (a > 0.0 or (a == 0.0 and b < 0.0)) else 0.0
        zs[j, 0] = d0
        zs[j, 1] = d1
        zs[j, 2] = d2
        bbox[j, 0] = int(c0)
        bbox[j, 1] = int(c1)
        bbox[j, 2] = int(r0)
        bbox[j, 3] = int(r1)


@njit(cache=True, parallel=True)
def _bin(bbox, tile_px, tiles_x, tiles_y):
    """Tile lists in drawing order: ``start`` (tiles + 1,) int64 offsets into ``items``.

    The triangles are split into ``BIN_CHUNKS`` consecutive chunks counted and filled in
    parallel; each tile's list is its chunks' lists in chunk order, i.e. drawing order, for any
    number of threads.
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
def _raster_tiles(start, items, ids, coef, zs, bbox, cam, xs, ys, tile_px, tiles_x, prim,
                  depth, bary, update_hiz, hiz_block, hiz_tile, block_px):
    """Rasterize the binned triangles, one tile per work item; refresh the max-depth buffer."""
    n_tiles = start.shape[0] - 1
    w = prim.shape[1]
    h = prim.shape[0]
    near = cam[_P_NEAR]
    far = cam[_P_FAR]
    ortho = cam[_P_MODE] != 0.0
    for tile in prange(n_tiles):
        if start[tile] == start[tile + 1]:
            continue
        tc0 = (tile % tiles_x) * tile_px
        tr0 = (tile // tiles_x) * tile_px
        tc1 = min(tc0 + tile_px, w) - 1
        tr1 = min(tr0 + tile_px, h) - 1
        for m in range(start[tile], start[tile + 1]):
            j = items[m]
            tri = ids[j]
            a0, b0, k0 = coef[j, 0], coef[j, 1], coef[j, 2]
            a1, b1, k1 = coef[j, 3], coef[j, 4], coef[j, 5]
            a2, b2, k2 = coef[j, 6], coef[j, 7], coef[j, 8]
            own0 = coef[j, 9] != 0.0
            own1 = coef[j, 10] != 0.0
            own2 = coef[j, 11] != 0.0
            z0 = zs[j, 0]
            dz1 = zs[j, 1] - z0
            dz2 = zs[j, 2] - z0
            for r in range(max(bbox[j, 2], tr0), min(bbox[j, 3], tr1) + 1):
                y = ys[r]
                row0 = b0 * y + k0
                row1 = b1 * y + k1
                row2 = b2 * y + k2
                for c in range(max(bbox[j, 0], tc0), min(bbox[j, 1], tc1) + 1):
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
                    s = e0 + e1 + e2
                    if not s > 0.0:
                        continue
                    # Exact barycentrics of the ray/plane point; its view depth.
                    inv = 1.0 / s
                    u = e1 * inv
                    v = e2 * inv
                    z = z0 + u * dz1 + v * dz2
                    if z < near or z > far:
                        continue
                    if ortho:
                        d = np.float32(z)
                    else:
                        d = np.float32(z * np.sqrt(x * x + y * y + 1.0))
                    cur = depth[r, c]
                    if d < cur or (d == cur and tri < prim[r, c]):
                        depth[r, c] = d
                        prim[r, c] = tri
                        bary[r, c, 0] = np.float32(u)
                        bary[r, c, 1] = np.float32(v)
        if update_hiz:
            # Max depth of every block of this tile, and of the tile.
            tmax = np.float32(0.0)
            for br in range(tr0, tr1 + 1, block_px):
                for bc in range(tc0, tc1 + 1, block_px):
                    bmax = np.float32(0.0)
                    for r in range(br, min(br + block_px, tr1 + 1)):
                        for c in range(bc, min(bc + block_px, tc1 + 1)):
                            bmax = max(bmax, depth[r, c])
                    hiz_block[br // block_px, bc // block_px] = bmax
                    tmax = max(tmax, bmax)
            hiz_tile[tr0 // tile_px, tc0 // tile_px] = tmax


@njit(cache=True)
def _present(t_begin, t_end, t_days):
    n = t_begin.shape[0]
    out = np.empty(n, np.int32)
    k = 0
    for i in range(n):
        if t_begin[i] <= t_days < t_end[i]:
            out[k] = i
            k += 1
    return out[:k]


class _Target:
    """The G-buffer being drawn plus the kernel inputs that do not change between batches."""

    def __init__(self, scene, camera: Camera, tile_px: int, occlusion: bool):
        self.vertices = scene.vertices
        self.triangles = scene.triangles
        tree = getattr(scene, "kdtree", None)
        self.recs = tree.tri_records if tree is not None else np.zeros((1, 16), np.float32)
        self.cam, self.xs, self.ys = camera_params(camera)
        h, w = camera.shape
        self.tile_px = tile_px
        self.tiles_x = -(-w // tile_px)
        self.tiles_y = -(-h // tile_px)
        self.prim = np.full((h, w), -1, np.int32)
        self.depth = np.full((h, w), np.inf, np.float32)
        self.bary = np.zeros((h, w, 2), np.float32)
        self.occlusion = occlusion
        self.hiz_block = np.full((-(-h // BLOCK_PX), -(-w // BLOCK_PX)), np.inf, np.float32)
        self.hiz_tile = np.full((self.tiles_y, self.tiles_x), np.inf, np.float32)
        self.timings = {"setup_s": 0.0, "bin_s": 0.0, "raster_s": 0.0}
        self.batches = 0
        self.tile_triangles = 0

    def draw(self, items: np.ndarray, from_records: bool) -> None:
        """Draw triangle ids, or kd-tree record indices when ``from_records``."""
        n = items.shape[0]
        if n == 0:
            return
        t0 = time.perf_counter()
        ids = np.empty(n, np.int32)
        coef = np.empty((n, _SETUP_WORDS))
        zs = np.empty((n, 3))
        bbox = np.empty((n, 4), np.int32)
        _setup(self.vertices, self.triangles, self.recs, from_records, items, self.cam, ids,
               coef, zs, bbox)
        t1 = time.perf_counter()
        start, items = _bin(bbox, self.tile_px, self.tiles_x, self.tiles_y)
        t2 = time.perf_counter()
        _raster_tiles(start, items, ids, coef, zs, bbox, self.cam, self.xs, self.ys,
                      self.tile_px, self.tiles_x, self.prim, self.depth, self.bary,
                      self.occlusion, self.hiz_block, self.hiz_tile, BLOCK_PX)
        t3 = time.perf_counter()
        self.timings["setup_s"] += t1 - t0
        self.timings["bin_s"] += t2 - t1
        self.timings["raster_s"] += t3 - t2
        self.batches += 1
        self.tile_triangles += int(items.shape[0])


def _occlusion_does_not_pay(walk_stats) -> bool:
    """Whether the occlusion queries so far removed too little to be worth their cost."""
    queries = walk_stats[cull.ST_OCCLUSION_QUERIES]
    removed = walk_stats[cull.ST_OCCLUSION_REFS]
    return queries >= AUTO_MIN_QUERIES and removed < AUTO_REFS_PER_QUERY * queries


def _validate(scene, camera, t_days, tile_px) -> float:
    if not isinstance(camera, Camera):
        raise UsageError(f"expected a Camera, not {type(camera).__name__}")
    t = float(t_days)
    if math.isnan(t):
        raise UsageError("t_days must be a number of days since 1970-01-01, not NaN")
    if tile_px < BLOCK_PX or tile_px % BLOCK_PX:
        raise UsageError(f"tile_px must be a positive multiple of {BLOCK_PX}, not {tile_px}")
    v = scene.vertices
    tris = scene.triangles
    if v.ndim != 2 or v.shape[1] != 3 or v.dtype != np.float32:
        raise UsageError(f"scene vertices must be (V, 3) float32, not {v.shape} {v.dtype}")
    if tris.ndim != 2 or tris.shape[1] != 3 or tris.dtype != np.int32:
        raise UsageError(f"scene triangles must be (T, 3) int32, not {tris.shape} {tris.dtype}")
    return t


def rasterize(scene, camera: Camera, t_days: float, *, occlusion_culling="auto",
              culling: bool = True, tile_px: int = TILE_PX,
              first_batch: int = FIRST_OCCLUSION_BATCH,
              query_min_refs: int = cull.QUERY_MIN_REFS) -> GBuffer:
    """Rasterize the triangles present at city time ``t_days`` into a G-buffer.

    Parameters
    ----------
    scene : Scene
        Render-space triangles (arrays may be read-only memory maps) and, for culling, its
        kd-tree.
    camera : Camera
        Perspective or map camera.
    t_days : float
        City time, days since 1970-01-01 UTC; triangles with ``begin <= t_days < end`` are drawn.
    occlusion_culling : "auto", True or False
        Software occlusion queries during the front-to-back walk. ``"auto"`` uses them for
        perspective views and not for maps (a top-down view of a city has almost no occlusion:
        the queries would cost more than they save), and switches them off during the walk
        once ``AUTO_MIN_QUERIES`` queries removed fewer than ``AUTO_REFS_PER_QUERY`` triangle
        references each.
    culling : bool
        Walk the kd-tree front to back with time filtering and frustum culling. False (or a
        scene without kd-tree) draws every triangle present at ``t_days``; the picture is the
        same. The walk is skipped too when the whole model lies in the view frustum and
        occlusion culling is "auto" or off (nothing to cull: a linear time filter is faster).
    tile_px : int
        Tile side in pixels (a multiple of ``BLOCK_PX``); does not change the picture.
    first_batch : int
        With occlusion culling, triangles drawn before the first occlusion query (later batches
        double up to ``MAX_BATCH``); does not change the picture.
    query_min_refs : int
        With occlusion culling, only kd-tree nodes with at least this many triangle references
        below them are queried; does not change the picture.

    Returns
    -------
    GBuffer
        ``prim_id``, ``bary``, ``depth`` and ``stats`` (culling counts per step, timings in
        seconds, tiles, threads).
    """
    t = _validate(scene, camera, t_days, int(tile_px))
    if occlusion_culling not in ("auto", True, False):
        raise UsageError(f"occlusion_culling must be 'auto', True or False, "
                         f"not {occlusion_culling!r}")
    started = time.perf_counter()
    tree = getattr(scene, "kdtree", None)
    use_tree = bool(culling) and tree is not None
    auto = occlusion_culling == "auto"
    if auto:
        occlusion = use_tree and camera.kind == "perspective"
    else:
        occlusion = bool(occlusion_culling) and use_tree
    stats: dict = {"triangles": int(scene.triangles.shape[0])}
    if use_tree:
        lo = np.asarray(tree.bounds[0, :3], np.float64)
        hi = np.asarray(tree.bounds[1, :3], np.float64)
        size = max(float(np.max(hi - lo)), float(np.max(np.abs(np.r_[lo, hi]))), 1.0)
        planes = cull.frustum_planes(camera, cull.FRUSTUM_PAD_REL * size)
        _, inside_mask = cull.box_outside(planes, lo, hi, (1 << planes.shape[0]) - 1)
        if inside_mask == 0 and (auto or not occlusion):
            # The whole model is in view: the frustum test cannot remove anything, and a
            # scene seen whole from outside has too little occlusion to pay for the queries
            # (benchmarks/render.py), so a linear time filter beats the walk.
            use_tree = occlusion = False
            stats["walk_skipped"] = "the model lies inside the view frustum"
    stats.update({"culling": use_tree, "occlusion_culling": occlusion})
    target = _Target(scene, camera, int(tile_px), occlusion)
    walk_s = 0.0
    if use_tree:
        refs, first, biggest = cull.tree_info(tree)
        st_node = np.zeros(cull.STACK_SIZE, np.int64)
        st_box = np.zeros((cull.STACK_SIZE, 6))
        st_mask = np.zeros(cull.STACK_SIZE, np.int64)
        st_mask[0] = (1 << planes.shape[0]) - 1
        st_box[0, :3], st_box[0, 3:] = lo, hi
        state = np.ones(1, np.int64)
        drawn = np.zeros(scene.triangles.shape[0], np.uint8)
        walk_stats = np.zeros(cull.N_STATS, np.int64)
        batch = max(1, min(int(first_batch), MAX_BATCH)) if occlusion else MAX_BATCH
        out = np.empty(MAX_BATCH + biggest, np.int32)
        while state[0] > 0:
            w0 = time.perf_counter()
            n = cull.walk(tree.nodes, tree.node_splits, tree.prim_indices, tree.records_f64,
                          refs, first, t, planes, occlusion, int(query_min_refs), target.cam,
                          target.hiz_block, target.hiz_tile, BLOCK_PX, target.tile_px,
                          st_node, st_box, st_mask, state, drawn, out, batch, walk_stats)
            walk_s += time.perf_counter() - w0
            target.draw(out[:n], True)
            batch = min(2 * batch, MAX_BATCH)
            if auto and occlusion and _occlusion_does_not_pay(walk_stats):
                # Switch the queries (and the max-depth refresh) off for the rest of the walk.
                occlusion = target.occlusion = False
                stats["occlusion_switched_off_at_batch"] = target.batches
                batch = MAX_BATCH
        stats.update({name: int(v) for name, v in zip(cull.STAT_NAMES, walk_stats)})
        stats["references"] = int(tree.prim_indices.shape[0])
    else:
        w0 = time.perf_counter()
        ids = _present(np.asarray(scene.tri_t_begin_days, np.float64),
                       np.asarray(scene.tri_t_end_days, np.float64), t)
        walk_s = time.perf_counter() - w0
        stats["time_refs_removed"] = int(scene.triangles.shape[0] - ids.shape[0])
        stats["triangles_drawn"] = int(ids.shape[0])
        for b in range(0, ids.shape[0], MAX_BATCH):
            target.draw(ids[b:b + MAX_BATCH], False)
    timings = {"walk_s": walk_s, **target.timings, "total_s": time.perf_counter() - started}
    stats.update({"batches": target.batches, "tile_px": target.tile_px,
                  "tiles": target.tiles_x * target.tiles_y,
                  "tile_triangle_pairs": target.tile_triangles,
                  "threads": int(numba.get_num_threads()), "timings_s": timings})
    return GBuffer(camera=camera, prim_id=target.prim, bary=target.bary, depth=target.depth,
                   stats=stats)
