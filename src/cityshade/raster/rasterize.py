"""The tile-parallel Numba triangle rasterizer that fills the G-buffer.

The triangle core (:mod:`cityshade.raster.triangles`: homogeneous setup, fill and tie rules,
binning, date filter, culled batch driver) is shared with the light-view depth pass; this module
holds the G-buffer's view (:func:`camera_view`) and its tile kernel. Each vertex becomes
``(X, Y, Z, W)`` in the camera frame: perspective ``(right, up, forward, forward) . (p - eye)``,
maps ``(x, y, eye_z - z, 1)``; ``Z`` is the view depth. A triangle crossing the near plane gets
its screen box from the part in front of it, and each pixel keeps the fragment only when its
interpolated view depth lies in [near, far]. Depth is that view depth times the pixel ray's
length, i.e. the distance from the eye along the ray (maps: below the camera plane), stored as
float32; ties go to the lower triangle id, so the G-buffer is the same for any thread count,
tile size, batch split or culling setting.
"""
from __future__ import annotations

import time

import numba
import numpy as np
from numba import njit, prange

from cityshade.errors import UsageError
from cityshade.raster import culling as cull
from cityshade.raster import triangles as tc
from cityshade.raster.camera import Camera
from cityshade.raster.gbuffer import GBuffer
from cityshade.trace.bricks import static_schedule
from cityshade.runtime.memory import Recycler
from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks
from cityshade.util import check_t_days

#: Side of the blocks of the hierarchical max-depth buffer (8 blocks per tile side).
BLOCK_PX = 8
#: First batch with occlusion culling: small, so the nearest surfaces are in the depth buffer
#: before the first queries; later batches double up to ``triangles.MAX_BATCH``.
FIRST_OCCLUSION_BATCH = 2048
#: "auto" occlusion culling judges the queries after this many of them ...
AUTO_MIN_QUERIES = 2000
#: ... and switches them off (and the max-depth refresh) unless they removed at least this
#: many triangle references per query: on the 1M-triangle city (benchmarks/render.py, one
#: thread) a query cost about as much as drawing 2-3 references (references include the
#: tree's duplicates and the triangles absent at the date).
AUTO_REFS_PER_QUERY = 3.0


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
        cam[18], cam[19] = -1.0 / px, camera.y_top_m / px - 0.5 - camera.row0_px
    else:
        p = camera.pitch
        cam[16], cam[17] = 1.0 / p, w / 2.0 - 0.5
        cam[18], cam[19] = -1.0 / p, h / 2.0 - 0.5
    cam[20], cam[21] = w, h
    return cam, xs, ys


def camera_view(camera: Camera) -> tuple[tc.ClipView, np.ndarray, np.ndarray]:
    """The camera as the triangle core's view, its walk-order point and its parameter vector.

    Returns
    -------
    view : ClipView
        Perspective: rows ``right, up, forward, forward`` about the eye (X, Y in the camera
        frame, Z = W = view depth; the box is clipped at W = near). Map: ``(x, y, eye_z - z, 1)``.
    order_point : (4,) float64
        The eye ``(x, y, z, 1)``, or for a map the direction up ``(0, 0, 1, 0)``.
    cam : (24,) float64
        :func:`camera_params` (for the occlusion queries).
    """
    cam, xs, ys = camera_params(camera)
    m = np.zeros((4, 4))
    if camera.kind == "map":
        m[0, 0] = m[1, 1] = m[3, 3] = 1.0
        m[2, 2], m[2, 3] = -1.0, camera.eye_m[2]
        origin = np.zeros(3)
        order_point = np.array([0.0, 0.0, 1.0, 0.0])
        w_clip = 0.0
    else:
        right, up, fwd = camera.frame()
        m[0, :3], m[1, :3], m[2, :3], m[3, :3] = right, up, fwd, fwd
        origin = np.asarray(camera.eye_m, np.float64)
        order_point = np.r_[origin, 1.0]
        w_clip = camera.near_m
    view = tc.clip_view(m, origin, cam[16:20], xs, ys, w_clip=w_clip, near=camera.near_m,
                        far=camera.far_m)
    return view, order_point, cam


@njit(cache=True, parallel=True)
def _raster_tiles(order, start, items, ids, coef, vals, bbox, xs, ys, near, far, ortho, tile_px,
                  tiles_x, prim, depth, bary, update_hiz, hiz_block, hiz_tile, block_px):
    """Rasterize the binned triangles, one tile per work item, tiles in ``order``
    (:func:`cityshade.raster.triangles.tile_order`); refresh the max-depth buffer."""
    for k in prange(order.shape[0]):
        _raster_tile(order[k], start, items, ids, coef, vals, bbox, xs, ys, near, far, ortho,
                     tile_px, tiles_x, prim, depth, bary, update_hiz, hiz_block, hiz_tile,
                     block_px)


@njit(cache=True)
def _raster_tile(tile, start, items, ids, coef, vals, bbox, xs, ys, near, far, ortho, tile_px,
                 tiles_x, prim, depth, bary, update_hiz, hiz_block, hiz_tile, block_px):
    """:func:`_raster_tiles` of one tile. A function of its own, not the ``prange`` body:
    Numba's parallel passes over the whole body nearly doubled the first compile (6.1 CPU s
    against 3.4, render of the sample city with an empty cache)."""
    m0, m1, tc0, tc1, tr0, tr1 = tc.tile_span(start, tile, tiles_x, tile_px, prim.shape)
    if m0 == m1:
        return
    for m in range(m0, m1):
        j = items[m]
        a0, b0, k0, a1, b1, k1, a2, b2, k2, own0, own1, own2 = tc.edges(coef, j)
        tri = ids[j]
        z0, dz1, dz2 = tc.vertex_words(vals, j, tc.Z_WORD)
        cb0 = max(bbox[j, 0], tc0)
        cb1 = min(bbox[j, 1], tc1)
        for r in range(max(bbox[j, 2], tr0), min(bbox[j, 3], tr1) + 1):
            y = ys[r]
            row0, row1, row2 = b0 * y + k0, b1 * y + k1, b2 * y + k2
            c0, c1 = tc.covered_span(xs, cb0, cb1, a0, row0, own0, a1, row1, own1, a2, row2,
                                     own2)
            for c in range(c0, c1 + 1):
                x = xs[c]
                # The edge values exactly as covers() computed them.
                e0 = a0 * x + row0
                e1 = a1 * x + row1
                e2 = a2 * x + row2
                # Exact barycentrics of the ray/plane point; its view depth.
                ok, u, v = tc.barycentrics(e0, e1, e2)
                if not ok:
                    continue
                z = z0 + u * dz1 + v * dz2
                if z < near or z > far:
                    continue
                if ortho:
                    d = np.float32(z)
                else:
                    d = np.float32(z * np.sqrt(x * x + y * y + 1.0))
                if tc.nearer(d, tri, depth[r, c], prim[r, c]):
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


#: The G-buffers' memory (three arrays a frame), used again once nothing refers to it.
_GBUFFERS = Recycler(keep=6)


@njit(cache=True, nogil=True)
def _clear(prim, depth, bary, r0, r1):
    """``prim = -1``, ``depth = +inf``, ``bary = 0``, rows in parallel."""
    for r in range(r0, r1):
        for c in range(prim.shape[1]):
            prim[r, c] = -1
            depth[r, c] = np.inf
            bary[r, c, 0] = np.float32(0.0)
            bary[r, c, 1] = np.float32(0.0)


class _Target:
    """The G-buffer being drawn and the tile kernel call the triangle core's batcher makes."""

    def __init__(self, camera: Camera, tile_px: int, occlusion: bool):
        self.view, self.order_point, self.cam = camera_view(camera)
        self.ortho = camera.kind == "map"
        self.near, self.far = float(camera.near_m), float(camera.far_m)
        h, w = camera.shape
        self.tile_px = tile_px
        self.tiles_x = -(-w // tile_px)
        self.tiles_y = -(-h // tile_px)
        self.order = tc.tile_order(self.tiles_x, self.tiles_y, int(numba.get_num_threads()))
        # The memory of dropped G-buffers again, cleared in parallel (numpy's fills were
        # serial, on fresh pages).
        self.prim = _GBUFFERS.empty((h, w), np.int32)
        self.depth = _GBUFFERS.empty((h, w), np.float32)
        self.bary = _GBUFFERS.empty((h, w, 2), np.float32)
        run_chunks(_clear, h, ROW_CHUNK, self.prim, self.depth, self.bary)
        self.occlusion = occlusion
        self.hiz_block = np.full((-(-h // BLOCK_PX), -(-w // BLOCK_PX)), np.inf, np.float32)
        self.hiz_tile = np.full((self.tiles_y, self.tiles_x), np.inf, np.float32)

    def __call__(self, start, items, ids, coef, vals, bbox) -> None:
        with static_schedule():     # each thread its own part of ``order`` in every batch
            _raster_tiles(self.order, start, items, ids, coef, vals, bbox, self.view.xs,
                          self.view.ys, self.near, self.far, self.ortho, self.tile_px,
                          self.tiles_x, self.prim, self.depth, self.bary, self.occlusion,
                          self.hiz_block, self.hiz_tile, BLOCK_PX)

    def queries(self, query_min_refs: int):
        """The walk's occlusion argument: None when the queries are off."""
        if not self.occlusion:
            return None
        return (int(query_min_refs), self.cam, self.hiz_block, self.hiz_tile, BLOCK_PX,
                self.tile_px)


def _occlusion_does_not_pay(walk_stats) -> bool:
    """Whether the occlusion queries so far removed too little to be worth their cost."""
    queries = walk_stats[cull.ST_OCCLUSION_QUERIES]
    removed = walk_stats[cull.ST_OCCLUSION_REFS]
    return queries >= AUTO_MIN_QUERIES and removed < AUTO_REFS_PER_QUERY * queries


def _validate(scene, camera, t_days, tile_px) -> float:
    if not isinstance(camera, Camera):
        raise UsageError(f"expected a Camera, not {type(camera).__name__}")
    t = check_t_days(t_days)
    if tile_px < BLOCK_PX or tile_px % BLOCK_PX:
        raise UsageError(f"tile_px must be a positive multiple of {BLOCK_PX}, not {tile_px}")
    tc.check_scene(scene)
    return t


def rasterize(scene, camera: Camera, t_days: float, *, occlusion_culling="auto",
              culling: bool = True, tile_px: int = tc.TILE_PX,
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
        double up to ``triangles.MAX_BATCH``); does not change the picture.
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
        lo, hi, size = tree.box_scale_m()
        planes = cull.frustum_planes(camera, cull.FRUSTUM_PAD_REL * size)
        _, inside_mask = cull.outside_view(planes, lo, hi, (1 << planes.shape[0]) - 1)
        if inside_mask == 0 and (auto or not occlusion):
            # The whole model is in view: the frustum test cannot remove anything, and a
            # scene seen whole from outside has too little occlusion to pay for the queries
            # (benchmarks/render.py), so a linear time filter beats the walk.
            use_tree = occlusion = False
            stats["walk_skipped"] = "the model lies inside the view frustum"
    stats.update({"culling": use_tree, "occlusion_culling": occlusion})
    target = _Target(camera, int(tile_px), occlusion)
    batcher = tc.Batcher(scene, target.view, False, target.tile_px, target)
    if use_tree:
        walk = tc.CulledWalk(tree, t, planes, target.order_point, scene.triangles.shape[0])
        batch = max(1, min(int(first_batch), tc.MAX_BATCH)) if occlusion else tc.MAX_BATCH
        while not walk.done:
            batcher.draw(walk.next(batch, target.queries(query_min_refs)), True)
            batch = min(2 * batch, tc.MAX_BATCH)
            if auto and occlusion and _occlusion_does_not_pay(walk.stats):
                # Switch the queries (and the max-depth refresh) off for the rest of the walk.
                occlusion = target.occlusion = False
                stats["occlusion_switched_off_at_batch"] = batcher.batches
                batch = tc.MAX_BATCH
        stats.update(walk.stat_dict())
        stats["references"] = int(tree.prim_indices.shape[0])
        walk_s = walk.walk_s
    else:
        stats["time_refs_removed"], walk_s = batcher.draw_present(scene, t)
        stats["triangles_drawn"] = batcher.drawn
    timings = {"walk_s": walk_s, **batcher.timings, "total_s": time.perf_counter() - started}
    stats.update({"batches": batcher.batches, "tile_px": target.tile_px,
                  "tiles": target.tiles_x * target.tiles_y,
                  "tile_triangle_pairs": batcher.tile_triangles,
                  "threads": int(numba.get_num_threads()), "timings_s": timings})
    return GBuffer(camera=camera, prim_id=target.prim, bary=target.bary, depth=target.depth,
                   stats=stats)
