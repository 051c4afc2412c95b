"""The depth-only pass for light views (shadow maps) under any 4×4 projective matrix.

The triangle core of :mod:`cityshade.raster.triangles` with the light's clip coordinates
``(X, Y, Z, W) = clip_from_world @ (p, 1)``: the texel centres' NDC coordinates are the screen
coordinates, clip Z and W are affine in world space, so interpolating them with the exact
barycentrics is exact for any projective matrix (warped maps included); the stored depth is
``Z / W`` (NDC depth, -1 at the near plane, +1 at the far plane, smaller is nearer the light).

Depth clamping: fragments nearer than the near plane (NDC z < -1) are kept with depth -1
("pancaking": a caster between the sun and the near plane still casts), fragments beyond the
far plane and fragments with ``W <= 0`` (behind a projective centre) are dropped.

Texel convention: texel ``(col, row)`` has its centre at NDC
``x = 2 (col + 0.5) / W - 1``, ``y = 1 - 2 (row + 0.5) / H`` (row 0 at the top, NDC y up),
the same as :meth:`cityshade.raster.camera.Camera.clip_from_world`.

Casters are culled by the kd-tree walk against the view's side and far planes (the near plane
is left out on purpose: casters nearer the sun are clamped, not clipped), walked from the
light's side (the view's centre of projection).
"""
from __future__ import annotations

import math
import time
from typing import Any

import numba
import numpy as np
from numba import njit, prange

from cityshade.errors import UsageError
from cityshade.raster import culling as cull
from cityshade.raster import triangles as tc
from cityshade.trace.bricks import static_schedule
from cityshade.runtime.memory import Recycler
from cityshade.util import check_t_days


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


def frustum_planes(clip_from_world, pad_m: float) -> np.ndarray:
    """(P <= 5, 4) float64 planes ``(n, d)`` (unit ``n``) of the view's side and far planes;
    inside is ``n . p + d >= -pad_m`` (Gribb and Hartmann's extraction from the clip matrix)."""
    m = np.asarray(clip_from_world, np.float64)
    rows = [m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[3] - m[2]]
    planes = []
    for r in rows:
        norm = float(np.linalg.norm(r[:3]))
        if norm > 0.0:
            planes.append(np.r_[r[:3] / norm, r[3] / norm + pad_m])
    return np.array(planes).reshape(-1, 4)


def box_planes(box, pad_m: float) -> np.ndarray:
    """(6, 4) planes of an axis-aligned box ``[[x0, y0, z0], [x1, y1, z1]]`` (inside >= -pad)."""
    b = np.asarray(box, dtype=np.float64)
    if b.shape != (2, 3) or not np.isfinite(b).all() or (b[1] < b[0]).any():
        raise UsageError("casters_box must be [[x0, y0, z0], [x1, y1, z1]] with lo <= hi")
    planes = np.zeros((6, 4))
    for a in range(3):
        planes[2 * a, a] = 1.0
        planes[2 * a, 3] = -b[0, a] + pad_m
        planes[2 * a + 1, a] = -1.0
        planes[2 * a + 1, 3] = b[1, a] + pad_m
    return planes


def projection_centre(clip_from_world) -> np.ndarray:
    """The light's position as the walk's order point (:func:`cityshade.raster.culling.walk`).

    The centre of projection is the homogeneous point the X, Y and W rows all map to zero. An
    orthographic view has it at infinity: ``(d, 0)`` with ``d`` the direction towards the light
    (along which NDC depth decreases); a projective one at ``(c, 1)``.
    """
    m = np.asarray(clip_from_world, np.float64)
    centre = np.linalg.svd(m[[0, 1, 3]])[2][-1]
    if abs(centre[3]) > 1e-12 * float(np.abs(centre[:3]).max()):
        return np.r_[centre[:3] / centre[3], 1.0]
    d = centre[:3] if m[2, :3] @ centre[:3] <= 0.0 else -centre[:3]
    return np.r_[d, 0.0]


#: See :data:`cityshade.raster.triangles.NARROW_COLS` (the setup leaves the column bounds of
#: such boxes out).
NARROW_COLS = tc.NARROW_COLS
#: The culled walk is skipped for the linear time filter when at least this share of the
#: model's vertices (:func:`inside_share`) lies inside the light view: the walk of the 1M-city's
#: tree costs 16 ms on one thread and culled nothing from the fitted map of the 1080p overview
#: (835,660 casters either way; depth pass at 2 threads 88 against 71 ms linear). The map is
#: the same either way.
LINEAR_INSIDE_SHARE = 0.75
#: Vertices :func:`inside_share` samples.
INSIDE_SAMPLES = 4096
#: The maps' memory, used again once the caller has let go of a map (a cascade's four maps and
#: their triangle ids fit).
_MAPS = Recycler(keep=8)


@njit(cache=True, inline="always")
def _keep(depth, prim, r, c, zp, tri):
    """Depth-test a fragment of NDC depth ``zp``: beyond the far plane dropped, nearer than the
    near plane clamped to -1."""
    if zp > 1.0:
        return
    d = np.float32(max(zp, -1.0))
    if tc.nearer(d, tri, depth[r, c], prim[r, c]):
        depth[r, c] = d
        prim[r, c] = tri


@njit(cache=True, inline="always")
def _keep_span(depth, prim, r, c0, c1, xs, pz, ypart, tri):
    """:func:`_keep` for the fragments of row ``r``, columns ``[c0, c1]``, of a triangle with
    depth plane ``pz x + ypart``: the same decisions, written without branches over slices
    indexed from 0, which LLVM turns into SIMD (a third of the time of the per-texel calls on
    the wide casters of a 4096² map of the 1M-triangle city)."""
    x = xs[c0:c1 + 1]
    drow = depth[r, c0:c1 + 1]
    prow = prim[r, c0:c1 + 1]
    for c in range(x.shape[0]):
        zp = pz * x[c] + ypart
        d = np.float32(max(zp, -1.0))
        cur = drow[c]
        cur_tri = prow[c]
        take = (zp <= 1.0) & ((d < cur) | ((d == cur) & (tri < cur_tri)))
        drow[c] = d if take else cur
        prow[c] = tri if take else cur_tri


@njit(cache=True, inline="always")
def _bound(y, sa, sb, kind, c_lo, c_hi):
    """Narrow the columns ``[c_lo, c_hi]`` of a row at screen y by one edge's bound ``A y + B``
    (kind 1 lower, -1 upper, 0 none; see ``triangles.SPAN_WORD``) with one column of slack (the
    exact test decides; a NaN bound leaves the columns as they are)."""
    if kind != 0.0:
        col = sa * y + sb
        if kind > 0.0:
            if col - 1.0 > c_lo:
                c_lo = col - 1.0
        elif col + 1.0 < c_hi:
            c_hi = col + 1.0
    return c_lo, c_hi


@njit(cache=True, inline="always")
def _column_bounds(y, c_lo, c_hi, sa0, sb0, sk0, sa1, sb1, sk1, sa2, sb2, sk2):
    """Columns of a row at screen y where all three edge functions can be >= 0."""
    c_lo, c_hi = _bound(y, sa0, sb0, sk0, c_lo, c_hi)
    c_lo, c_hi = _bound(y, sa1, sb1, sk1, c_lo, c_hi)
    return _bound(y, sa2, sb2, sk2, c_lo, c_hi)


@njit(cache=True, parallel=True)
def _raster_depth_tiles(order, start, items, ids, coef, vals, bbox, xs, ys, tile_px, tiles_x,
                        clear, depth, prim):
    """Depth-test the binned triangles into ``depth`` (H, W) float32 / ``prim`` (H, W) int32,
    one tile per work item, tiles in ``order`` (:func:`cityshade.raster.triangles.tile_order`;
    each tile owns its texels); with ``clear``, each tile is set to (+inf, -1) first (the first batch: the tile is
    then in cache for its casters, where a separate clearing pass wrote the whole map to memory
    first)."""
    for k in prange(order.shape[0]):
        tile = order[k]
        m0, m1, tc0, tc1, tr0, tr1 = tc.tile_span(start, tile, tiles_x, tile_px, depth.shape)
        if clear:
            for r in range(tr0, tr1 + 1):
                depth[r, tc0:tc1 + 1] = np.inf
                prim[r, tc0:tc1 + 1] = -1
        for mm in range(m0, m1):
            j = items[mm]
            a0, b0, k0, a1, b1, k1, a2, b2, k2, own0, own1, own2 = tc.edges(coef, j)
            tri = ids[j]
            cb0 = max(bbox[j, 0], tc0)
            cb1 = min(bbox[j, 1], tc1)
            rb0 = max(bbox[j, 2], tr0)
            rb1 = min(bbox[j, 3], tr1)
            if vals[j, tc.GENERAL_WORD] != 0.0:
                _general_entry(vals, j, a0, b0, k0, a1, b1, k1, a2, b2, k2, own0, own1, own2,
                               tri, cb0, cb1, rb0, rb1, xs, ys, depth, prim)
                continue
            pz = vals[j, tc.PLANE_WORD]
            qz = vals[j, tc.PLANE_WORD + 1]
            rz = vals[j, tc.PLANE_WORD + 2]
            if cb1 - cb0 < NARROW_COLS:
                # At most NARROW_COLS texels a row: each is tested whole (one branch, not
                # one per edge as in covered_span's scans).
                for r in range(rb0, rb1 + 1):
                    y = ys[r]
                    row0, row1, row2 = b0 * y + k0, b1 * y + k1, b2 * y + k2
                    ypart = qz * y + rz
                    for c in range(cb0, cb1 + 1):
                        x = xs[c]
                        if (tc.edge_covers(a0 * x + row0, own0)
                                & tc.edge_covers(a1 * x + row1, own1)
                                & tc.edge_covers(a2 * x + row2, own2)):
                            _keep(depth, prim, r, c, pz * x + ypart, tri)
                continue
            sw = tc.SPAN_WORD
            sa0, sb0, sk0 = vals[j, sw], vals[j, sw + 1], vals[j, sw + 2]
            sa1, sb1, sk1 = vals[j, sw + 3], vals[j, sw + 4], vals[j, sw + 5]
            sa2, sb2, sk2 = vals[j, sw + 6], vals[j, sw + 7], vals[j, sw + 8]
            for r in range(rb0, rb1 + 1):
                y = ys[r]
                # Bounds are clamped to the tile before the integer conversion (huge or NaN
                # values have no int64).
                c_lo, c_hi = _column_bounds(y, np.float64(cb0), np.float64(cb1), sa0, sb0, sk0,
                                            sa1, sb1, sk1, sa2, sb2, sk2)
                if not c_lo <= c_hi:
                    continue
                row0, row1, row2 = b0 * y + k0, b1 * y + k1, b2 * y + k2
                ypart = qz * y + rz
                c0, c1 = tc.covered_span(xs, int(math.ceil(c_lo)), int(math.floor(c_hi)), a0,
                                         row0, own0, a1, row1, own1, a2, row2, own2)
                if c0 <= c1:
                    _keep_span(depth, prim, r, c0, c1, xs, pz, ypart, tri)


@njit(cache=True)
def _general_entry(vals, j, a0, b0, k0, a1, b1, k1, a2, b2, k2, own0, own1, own2, tri, cb0, cb1,
                   rb0, rb1, xs, ys, depth, prim):
    """A triangle crossing W = 0 over one tile: exact barycentrics → clip Z and W of the plane
    point of each covered texel (rare: projective views only)."""
    zv0, dz1, dz2 = tc.vertex_words(vals, j, tc.Z_WORD)
    wv0, dw1, dw2 = tc.vertex_words(vals, j, tc.W_WORD)
    sw = tc.SPAN_WORD
    for r in range(rb0, rb1 + 1):
        y = ys[r]
        c_lo, c_hi = _column_bounds(y, np.float64(cb0), np.float64(cb1), vals[j, sw],
                                    vals[j, sw + 1], vals[j, sw + 2], vals[j, sw + 3],
                                    vals[j, sw + 4], vals[j, sw + 5], vals[j, sw + 6],
                                    vals[j, sw + 7], vals[j, sw + 8])
        if not c_lo <= c_hi:
            continue
        row0, row1, row2 = b0 * y + k0, b1 * y + k1, b2 * y + k2
        for c in range(int(math.ceil(c_lo)), int(math.floor(c_hi)) + 1):
            inside, e0, e1, e2 = tc.covers(xs[c], a0, row0, own0, a1, row1, own1, a2, row2, own2)
            if not inside:
                continue
            ok, u, v = tc.barycentrics(e0, e1, e2)
            if not ok:
                continue
            wp = wv0 + u * dw1 + v * dw2
            if not wp > 0.0:
                continue
            _keep(depth, prim, r, c, (zv0 + u * dz1 + v * dz2) / wp, tri)


@njit(cache=True, parallel=True)
def _clear(depth, prim):
    """``depth = +inf``, ``prim = -1``, rows in parallel (the first touch of the map's pages is
    shared by the threads too)."""
    for r in prange(depth.shape[0]):
        for c in range(depth.shape[1]):
            depth[r, c] = np.inf
            prim[r, c] = -1


def inside_share(vertices, planes, samples: int = INSIDE_SAMPLES) -> float:
    """Share of the vertices inside all ``planes`` (``n . p + d >= 0``), from every k-th of
    them (about ``samples``): how much of the model a view holds."""
    step = max(1, vertices.shape[0] // samples)
    points = np.asarray(vertices[::step], np.float64)
    if points.shape[0] == 0:
        return 0.0
    inside = (points @ planes[:, :3].T + planes[:, 3] >= 0.0).all(axis=1)
    return float(inside.mean())


def render_depth(scene, clip_from_world, width_px: int, height_px: int, t_days: float, *,
                 casters_box=None, culling: bool = True, tile_px: int = tc.TILE_PX
                 ) -> tuple[np.ndarray, np.ndarray, dict[str, Any]]:
    """Rasterize the triangles standing at ``t_days`` into a light view's depth map.

    Parameters
    ----------
    scene : Scene
        Render-space triangles (arrays may be read-only memory maps) and its kd-tree.
    clip_from_world : (4, 4) float64
        Any projective light view (finite).
    width_px, height_px : int
        Map size in texels.
    t_days : float
        City time, days since 1970-01-01 UTC; triangles with ``begin <= t_days < end`` cast.
    casters_box, culling, tile_px
        As for :func:`cityshade.shadows.shadowmap.render_depth_map`.

    Returns
    -------
    depth : (H, W) float32
        NDC depth of the nearest caster (``+inf`` where none).
    prim_id : (H, W) int32
        Its triangle id (-1 where none).
    stats : dict
        See :class:`cityshade.shadows.shadowmap.DepthMap`.
    """
    t = check_t_days(t_days)
    if not (isinstance(tile_px, (int, np.integer)) and 8 <= tile_px <= 4096):
        raise UsageError(f"tile_px must be an integer in [8, 4096], not {tile_px!r}")
    tc.check_scene(scene)
    started = time.perf_counter()
    h, w = int(height_px), int(width_px)
    tile = int(tile_px)
    xs, ys, to_px = texel_params(w, h)
    view = tc.clip_view(clip_from_world, np.zeros(3), to_px, xs, ys)
    depth = _MAPS.empty((h, w), np.float32)
    prim = _MAPS.empty((h, w), np.int32)
    tiles_x = -(-w // tile)
    cleared = [False]
    order = tc.tile_order(tiles_x, -(-h // tile), int(numba.get_num_threads()))

    def raster(start, binned, ids, coef, vals, bbox):
        # A static schedule: each thread its own part of ``order`` in every batch.
        with static_schedule():
            _raster_depth_tiles(order, start, binned, ids, coef, vals, bbox, xs, ys, tile,
                                tiles_x, not cleared[0], depth, prim)
        cleared[0] = True

    batcher = tc.Batcher(scene, view, True, tile, raster)
    tree = getattr(scene, "kdtree", None)
    stats: dict[str, Any] = {"triangles": int(scene.triangles.shape[0]), "casters_drawn": 0,
                             "frustum_refs_removed": 0, "time_refs_removed": 0}
    walk_s = 0.0
    use_tree = bool(culling) and tree is not None
    if use_tree:
        lo, hi, size = tree.box_scale_m()
        pad = cull.FRUSTUM_PAD_REL * size
        planes = frustum_planes(clip_from_world, pad)
        if casters_box is not None:
            planes = np.vstack([planes, box_planes(casters_box, pad)])
        outside, inside_mask = cull.outside_view(planes, lo, hi, (1 << planes.shape[0]) - 1)
        if outside:
            stats["culling"] = "the model lies outside the light view"
            stats["frustum_refs_removed"] = int(tree.prim_indices.shape[0])
        elif inside_mask == 0:
            # The whole model is in the view: a linear time filter beats the walk.
            use_tree = False
            stats["culling"] = "the model lies inside the light view"
        elif inside_share(scene.vertices, planes) >= LINEAR_INSIDE_SHARE:
            # Nearly all of it: the serial walk would cull too little to pay for itself.
            use_tree = False
            stats["culling"] = "most of the model lies inside the light view"
        else:
            stats["culling"] = "kd-tree walk"
            walk = tc.CulledWalk(tree, t, planes, projection_centre(clip_from_world),
                                 scene.triangles.shape[0])
            while not walk.done:
                batcher.draw(walk.next(batcher.batch), True)
            named = walk.stat_dict()
            walk_s = walk.walk_s
            stats["frustum_refs_removed"] = named["frustum_refs_removed"]
            stats["time_refs_removed"] = named["time_refs_removed"]
            stats["walk"] = named
    if not use_tree:
        if "culling" not in stats:
            stats["culling"] = "off"
        stats["time_refs_removed"], walk_s = batcher.draw_present(scene, t)
    if not cleared[0]:
        _clear(depth, prim)         # nothing was drawn
    timings = {"walk_s": walk_s, **batcher.timings, "total_s": time.perf_counter() - started}
    stats.update({"casters_drawn": batcher.drawn, "texels": int(w * h), "tile_px": tile,
                  "threads": int(numba.get_num_threads()), "timings_s": timings})
    return depth, prim, stats
