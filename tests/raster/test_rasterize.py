"""Tests of the rasterizer and G-buffer (cityshade.raster) against ray casting, brute force and
analytic scenes: fill rule, perspective-correct barycentrics, near clipping, time filtering,
culling invariance, thread invariance, map georeference."""
from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import numba
import numpy as np
import pytest

from cityshade.accel import build_kdtree
from cityshade.raster import camera as cams
from cityshade.raster.gbuffer import gbuffer_by_raycasting, resolve
from cityshade.raster.rasterize import rasterize
from conftest import run_with_and_without_jit, shared_file
from reference import reference_rasterize, reference_ray_hits
from synthetic import box_city

#: Pixels where rasterizer and ray casting may disagree: only on triangle edges (the fill rule
#: against the watertight test's both-sides rule, and float32 vertex rounding of edge ties).
MAX_EDGE_DISAGREEMENT = 1e-3


def mini_scene(vertices, triangles, begin=None, end=None, origin=(0.0, 0.0, 0.0), tree=True):
    """The arrays of a Scene the raster stage uses, with a kd-tree (or none)."""
    v = np.asarray(vertices, np.float32)
    t = np.asarray(triangles, np.int32).reshape(-1, 3)
    n = t.shape[0]
    begin = np.full(n, -np.inf) if begin is None else np.asarray(begin, np.float64)
    end = np.full(n, np.inf) if end is None else np.asarray(end, np.float64)
    material = (np.arange(n) % 3).astype(np.int32)
    return SimpleNamespace(
        vertices=v, triangles=t, tri_t_begin_days=begin, tri_t_end_days=end,
        origin_m=np.asarray(origin, np.float64), uv=np.zeros((v.shape[0], 2), np.float32),
        tri_object=np.arange(n, dtype=np.int32) // 2, tri_material=material,
        tri_texture=np.full(n, -1, np.int32), tri_class=np.full(n, 3, np.uint8),
        kdtree=build_kdtree(v, t, begin, end, material) if tree else None)


@pytest.fixture(scope="module")
def sample_scene(sample_city_scene):
    """sample_data/sample_city.gml built and loaded back (read-only memory-mapped arrays)."""
    scene = sample_city_scene
    assert not scene.vertices.flags.writeable
    return scene


@pytest.fixture(scope="module")
def dated_city():
    v, t, begin, end, _ = box_city(60, seed=5, extent_m=150.0)
    return mini_scene(v, t, begin, end)


def agreement(a, b):
    return float((a.prim_id == b.prim_id).mean())


def check_against_raycasting(scene, cam, t_days):
    g = rasterize(scene, cam, t_days)
    r = gbuffer_by_raycasting(scene, cam, t_days)
    frac = agreement(g, r)
    assert frac >= 1 - MAX_EDGE_DISAGREEMENT, \
        f"prim_id agrees with ray casting on {frac:.5%} of pixels (need >= 99.9 %)"
    same = (g.prim_id == r.prim_id) & (g.prim_id >= 0)
    assert same.sum() > 0.05 * same.size, "the view shows almost nothing"
    # Every disagreement is an edge tie: brute force finds both triangles on the pixel's ray.
    origins, dirs = cam.primary_rays()
    for row, col in np.argwhere(~same & ((g.prim_id >= 0) | (r.prim_id >= 0)))[:100]:
        i = row * cam.width_px + col
        _, ids = reference_ray_hits(scene.vertices, scene.triangles, scene.tri_t_begin_days,
                                    scene.tri_t_end_days, origins[i], dirs[i], t_days)
        assert g.prim_id[row, col] in ids and r.prim_id[row, col] in ids, \
            f"pixel {(row, col)}: rasterizer {g.prim_id[row, col]}, rays {r.prim_id[row, col]}"
    np.testing.assert_allclose(g.depth[same], r.depth[same], rtol=1e-5, atol=1e-4)
    np.testing.assert_allclose(g.bary[same], r.bary[same], atol=2e-4)
    assert np.isinf(g.depth[g.prim_id < 0]).all() and np.isfinite(g.depth[g.prim_id >= 0]).all()
    return g


def test_sample_city_overview_and_map_agree_with_raycasting(sample_scene):
    t_days = 20000.0                            # 2024: some buildings demolished by then
    check_against_raycasting(sample_scene, cams.overview(sample_scene, 320, 200), t_days)
    check_against_raycasting(sample_scene, cams.preset("east", sample_scene, 200, 120), t_days)
    # 0.7 m pixels: the generated city's coordinates are multiples of 0.5 m, so 1 m pixel
    # centres lie exactly on many edges, where the fill rule and the rays' lower-id rule pick
    # different (equally right) triangles (that case is checked just below).
    g = check_against_raycasting(sample_scene, cams.map_view(sample_scene, 0.7), t_days)
    assert (g.prim_id >= 0).mean() > 0.99      # the sample city has a terrain TIN
    cam = cams.map_view(sample_scene, 1.0)
    g, r = rasterize(sample_scene, cam, t_days), gbuffer_by_raycasting(sample_scene, cam, t_days)
    assert agreement(g, r) > 0.99


def test_tum_campus_agrees_with_raycasting(tmp_path):
    from cityshade.build import build_file

    path = shared_file("munich-tum-campus-lod2/TUM Munich.gml")
    _, scene, _ = build_file(path, tmp_path / "tum.cityshade")
    check_against_raycasting(scene, cams.overview(scene, 400, 250), 20000.0)
    check_against_raycasting(scene, cams.map_view(scene, 2.0), 20000.0)


def test_against_brute_force_twin(dated_city):
    cam = cams.overview(dated_city, 72, 48)
    for t_days in (-30000.0, 0.0, 15000.0):
        g = rasterize(dated_city, cam, t_days)
        prim, depth = reference_rasterize(dated_city.vertices, dated_city.triangles,
                                          dated_city.tri_t_begin_days,
                                          dated_city.tri_t_end_days, cam, t_days)
        assert (g.prim_id == prim).mean() >= 0.995
        same = (g.prim_id == prim) & (prim >= 0)
        np.testing.assert_allclose(g.depth[same], depth[same], rtol=1e-5)


def single_triangle_masks(vertices, triangles, cam):
    """Coverage mask of each triangle drawn alone (no kd-tree)."""
    masks = []
    for tri in np.asarray(triangles).reshape(-1, 3):
        g = rasterize(mini_scene(vertices, [tri], tree=False), cam, 0.0)
        masks.append(g.prim_id == 0)
    return np.array(masks)


def test_quad_top_left_rule_covers_each_pixel_once():
    # Map with 1 m pixels: pixel centres at k + 0.5, so all four edges and the diagonal of the
    # quad [0.5, 10.5]² run exactly through pixel centres. The top-left rule keeps the left
    # (x = 0.5) and top (y = 10.5) edges and drops the right and bottom ones: 10 x 10 pixels.
    v = [(0.5, 0.5, 0.0), (10.5, 0.5, 0.0), (10.5, 10.5, 0.0), (0.5, 10.5, 0.0)]
    scene = mini_scene(v, [(0, 1, 2), (0, 2, 3)])
    cam = cams.map_view(scene, 1.0, bbox=(-3.0, -3.0, 14.0, 14.0))
    assert cam.x_left_m == -3.0 and cam.y_top_m == 14.0
    masks = single_triangle_masks(v, [(0, 1, 2), (0, 2, 3)], cam)
    count = masks.sum(axis=0)
    assert count.max() == 1, "a pixel on the shared diagonal was drawn by both triangles"
    assert count.sum() == 100
    cols = np.arange(cam.width_px) - 3 + 0.5          # pixel-centre x
    rows = 14 - np.arange(cam.height_px) - 0.5        # pixel-centre y
    expect = ((cols[None, :] >= 0.5) & (cols[None, :] < 10.5) &
              (rows[:, None] > 0.5) & (rows[:, None] <= 10.5))
    np.testing.assert_array_equal(count == 1, expect)
    # The whole quad drawn at once: every covered pixel shows one of the two triangles.
    g = rasterize(scene, cam, 0.0)
    np.testing.assert_array_equal(g.prim_id >= 0, expect)
    # Either winding of either triangle gives the same coverage.
    flipped = single_triangle_masks(v, [(0, 2, 1), (0, 3, 2)], cam)
    np.testing.assert_array_equal(flipped, masks)


def test_perspective_fan_and_exact_ties_cover_each_pixel_once():
    # Camera straight down with an odd width: the centre column's rays lie exactly in the
    # plane x = 0 that holds the fan's shared edges along the y axis.
    rng = np.random.default_rng(3)
    angles = np.sort(rng.uniform(0, 2 * np.pi, 9))
    angles = np.concatenate([angles, [np.pi / 2, 3 * np.pi / 2]])
    angles.sort()
    ring = np.c_[8 * np.cos(angles), 8 * np.sin(angles), rng.uniform(-0.5, 0.5, angles.size)]
    ring[np.isclose(angles, np.pi / 2), 0] = 0.0
    ring[np.isclose(angles, 3 * np.pi / 2), 0] = 0.0
    v = np.vstack([[0.0, 0.0, 0.0], ring])
    tris = [(0, 1 + i, 1 + (i + 1) % len(ring)) for i in range(len(ring))]
    cam = cams.perspective((0.0, 0.0, 30.0), (0.0, 0.0, 0.0), vfov_deg=40.0, width_px=41,
                           height_px=37, near_m=1.0, far_m=100.0)
    masks = single_triangle_masks(v, tris, cam)
    count = masks.sum(axis=0)
    assert count.max() == 1
    whole = rasterize(mini_scene(v, tris), cam, 0.0)
    np.testing.assert_array_equal(whole.prim_id >= 0, count == 1)
    # No holes: the covered set is the pixels whose rays hit the fan (ray casting, which counts
    # edges as inside on both sides) up to pixels on the outer boundary.
    ray = gbuffer_by_raycasting(mini_scene(v, tris), cam, 0.0)
    assert ((ray.prim_id >= 0) & (count == 0)).sum() <= 2 * cam.width_px // 10
    assert (count[:, 20] == 1).sum() > 10   # the tie column is drawn, once


def test_perspective_correct_barycentrics_on_a_slanted_quad():
    # A quad slanted steeply away from the camera: screen-space (affine) interpolation would
    # be wrong by far more than the tolerance.
    v = np.array([(-10, 5, 0), (10, 5, 0), (10, 80, 30), (-10, 80, 30)], np.float64)
    tris = [(0, 1, 2), (0, 2, 3)]
    scene = mini_scene(v, tris)
    cam = cams.perspective((0.0, 0.0, 10.0), (0.0, 40.0, 10.0), vfov_deg=70.0, width_px=60,
                           height_px=60, near_m=0.5, far_m=200.0)
    g = rasterize(scene, cam, 0.0)
    origins, dirs = cam.primary_rays()
    hit = np.flatnonzero(g.prim_id.reshape(-1) >= 0)
    assert hit.size > 500
    max_affine_error = 0.0
    for i in hit[::7]:
        tri = v[list(tris[g.prim_id.flat[i]])]
        # Analytic: solve o + t d = v0 + u (v1 - v0) + w (v2 - v0) for (t, u, w).
        m = np.column_stack([dirs[i], tri[0] - tri[1], tri[0] - tri[2]])
        t, u, w = np.linalg.solve(m, tri[0] - origins[i])
        np.testing.assert_allclose(g.bary.reshape(-1, 2)[i], (u, w), atol=1e-5)
        np.testing.assert_allclose(g.depth.flat[i], t, rtol=1e-6)
        # What affine screen-space interpolation would give: barycentrics of the projections.
        p = cam.clip_from_world() @ np.c_[tri, np.ones(3)].T
        s = (p[:2] / p[3]).T
        row, col = divmod(i, 60)
        q = np.array([(col + 0.5) / 30 - 1, 1 - (row + 0.5) / 30])
        ua, wa = np.linalg.solve(np.column_stack([s[1] - s[0], s[2] - s[0]]), q - s[0])
        max_affine_error = max(max_affine_error, abs(ua - u), abs(wa - w))
    assert max_affine_error > 0.05      # the test would catch affine interpolation


def test_near_plane_clipping_keeps_the_part_in_front():
    # A huge ground triangle around and behind the eye (2 m above it, looking north along the
    # ground): it crosses the near plane and must be drawn, clipped at Z = near.
    v = [(-1000.0, -1000.0, 0.0), (1000.0, -1000.0, 0.0), (0.0, 1000.0, 0.0)]
    scene = mini_scene(v, [(0, 1, 2)])
    for near in (0.05, 10.0):
        cam = cams.perspective((0.0, 0.0, 2.0), (0.0, 100.0, 2.0), vfov_deg=60.0, width_px=40,
                               height_px=40, near_m=near, far_m=5000.0)
        g = rasterize(scene, cam, 0.0)
        _, ys = cam.screen_coordinates()
        # Row with screen y < 0 sees the ground at view depth Z = 2 / -ys (similar triangles);
        # it is drawn when near <= Z (and the far end is inside the triangle).
        z = np.where(ys < 0, 2.0 / np.maximum(-ys, 1e-300), np.inf)
        expect_rows = (z >= near) & (z <= 900.0)
        drawn_rows = (g.prim_id >= 0).all(axis=1)
        np.testing.assert_array_equal(drawn_rows[expect_rows], True)
        assert not (g.prim_id[z < near] >= 0).any()
        r = gbuffer_by_raycasting(scene, cam, 0.0)
        assert agreement(g, r) >= 0.99


def test_time_filtering_never_draws_absent_triangles(dated_city):
    cam = cams.overview(dated_city, 96, 64)
    begin, end = dated_city.tri_t_begin_days, dated_city.tri_t_end_days
    seen_absent = False
    for t_days in (-25000.0, -5000.0, 0.0, 5000.0, 25000.0):
        g = rasterize(dated_city, cam, t_days)
        shown = np.unique(g.prim_id[g.prim_id >= 0])
        assert ((begin[shown] <= t_days) & (t_days < end[shown])).all()
        absent = ~((begin <= t_days) & (t_days < end))
        seen_absent |= bool(absent.any())
    assert seen_absent
    # A triangle present only later is drawn then and not before.
    v = [(0, 0, 0), (10, 0, 0), (0, 10, 0)]
    scene = mini_scene(v, [(0, 1, 2)], begin=[100.0], end=[200.0])
    cam = cams.map_view(scene, 1.0)
    assert (rasterize(scene, cam, 99.0).prim_id < 0).all()
    assert (rasterize(scene, cam, 100.0).prim_id >= 0).any()
    assert (rasterize(scene, cam, 200.0).prim_id < 0).all()


def low_view(scene):
    """A low perspective view over the dated box city, with plenty of occlusion."""
    return cams.perspective((-60.0, -60.0, 12.0), (150.0, 100.0, 5.0), vfov_deg=30.0,
                            width_px=160, height_px=100, scene=scene)


def test_culling_on_and_off_give_the_same_gbuffer(dated_city, sample_scene):
    for scene, cam in ((dated_city, low_view(dated_city)),
                       (dated_city, cams.map_view(dated_city, 2.0)),
                       (dated_city, cams.map_view(dated_city, 1.5, bbox=(20, 20, 90, 70))),
                       (sample_scene, cams.overview(sample_scene, 200, 120))):
        for t_days in (-5000.0, 20000.0):
            plain = rasterize(scene, cam, t_days, culling=False)
            for occ, first, q in ((True, 16, 1), (True, 16, 64), (True, 2048, 4),
                                  (False, 0, 4), ("auto", 64, 4)):
                g = rasterize(scene, cam, t_days, occlusion_culling=occ, first_batch=first,
                              query_min_refs=q)
                np.testing.assert_array_equal(g.prim_id, plain.prim_id)
                np.testing.assert_array_equal(g.depth, plain.depth)
                np.testing.assert_array_equal(g.bary, plain.bary)
    g = rasterize(dated_city, low_view(dated_city), 20000.0, occlusion_culling=True,
                  first_batch=16, query_min_refs=4)
    assert g.stats["culling"] and g.stats["occlusion_culling"]
    assert g.stats["occlusion_refs_removed"] > 0, "the occlusion test removed nothing"
    assert g.stats["frustum_refs_removed"] > 0
    assert g.stats["time_refs_removed"] > 0
    assert g.stats["triangles_drawn"] < g.stats["triangles"]
    # A camera looking away from the city culls everything by the frustum.
    away = cams.perspective((-60.0, -60.0, 12.0), (-200.0, -200.0, 12.0), width_px=32,
                            height_px=32, scene=dated_city)
    g = rasterize(dated_city, away, 0.0)
    assert g.stats["triangles_drawn"] == 0 and (g.prim_id < 0).all()
    # A part of the map: the walk culls by the frustum, without occlusion queries ("auto").
    g = rasterize(dated_city, cams.map_view(dated_city, 1.5, bbox=(20, 20, 90, 70)), 0.0)
    assert g.stats["culling"] and not g.stats["occlusion_culling"]
    assert g.stats["frustum_refs_removed"] > 0
    # The whole model in view: nothing to cull, the walk is skipped (same picture, see above).
    g = rasterize(dated_city, cams.overview(dated_city, 64, 48), 0.0)
    assert not g.stats["culling"] and "walk_skipped" in g.stats


def test_tile_size_and_thread_count_do_not_change_the_result(sample_scene):
    cam = cams.overview(sample_scene, 150, 100)
    before = numba.get_num_threads()
    try:
        results = []
        for threads in (1, min(2, numba.config.NUMBA_NUM_THREADS)):
            numba.set_num_threads(threads)
            results.append(rasterize(sample_scene, cam, 20000.0, occlusion_culling=True))
            assert results[-1].stats["threads"] == threads
        results.append(rasterize(sample_scene, cam, 20000.0, tile_px=16))
        results.append(rasterize(sample_scene, cam, 20000.0))
    finally:
        numba.set_num_threads(before)
    for g in results[1:]:
        np.testing.assert_array_equal(g.prim_id, results[0].prim_id)
        np.testing.assert_array_equal(g.depth, results[0].depth)
        np.testing.assert_array_equal(g.bary, results[0].bary)


def test_map_georeference_vertex_lands_in_predicted_pixel():
    # A small triangle around a known CRS point, in a scene with a real-world origin.
    origin = (691234.0, 5335678.0, 512.0)
    p_crs = np.array([691234.0 + 37.3, 5335678.0 - 12.8])
    local = p_crs - origin[:2]
    v = [(local[0] - 0.05, local[1] - 0.05, 3.0), (local[0] + 0.1, local[1] - 0.05, 3.0),
         (local[0] - 0.05, local[1] + 0.1, 3.0), (-80, -80, 0), (80, -80, 0), (0, 80, 0)]
    scene = mini_scene(v, [(0, 1, 2), (3, 4, 5)], origin=origin)
    cam = cams.map_view(scene, 0.5)
    x_ul, px, _, y_ul, _, neg_px = cam.geotransform(scene.origin_m)
    col = int(np.floor((p_crs[0] - x_ul) / px))
    row = int(np.floor((p_crs[1] - y_ul) / neg_px))
    g = rasterize(scene, cam, 0.0)
    assert np.argwhere(g.prim_id == 0).tolist() == [[row, col]]
    centre = cam.pixel_centres_world(scene.origin_m)[row, col]
    assert np.abs(centre - p_crs).max() <= 0.25


def test_resolve_gives_points_on_the_rays_and_unit_normals(sample_scene):
    cam = cams.overview(sample_scene, 120, 80)
    g = rasterize(sample_scene, cam, 20000.0)
    s = resolve(sample_scene, g)
    valid = g.prim_id >= 0
    np.testing.assert_array_equal(s.valid, valid)
    origins, dirs = cam.primary_rays()
    along = (origins + dirs * g.depth.reshape(-1, 1).astype(np.float64)).reshape(120 * 80, 3)
    err = np.abs(along[valid.reshape(-1)] - s.position_m[valid]).max()
    assert err < 1e-3 * float(g.depth[valid].max())
    np.testing.assert_allclose(np.linalg.norm(s.normal[valid], axis=1), 1.0, atol=1e-5)
    assert np.isnan(s.position_m[~valid]).all()
    ids = g.prim_id[valid]
    np.testing.assert_array_equal(s.obj_id[valid], sample_scene.tri_object[ids])
    np.testing.assert_array_equal(s.cls[valid], sample_scene.tri_class[ids])
    np.testing.assert_array_equal(s.material[valid], sample_scene.tri_material[ids])
    assert (s.obj_id[~valid] == -1).all()
    # Normals are outward: walls and roofs seen by the camera face it (mostly; the terrain
    # and closed buildings are seen from outside).
    facing = np.einsum("ij,ij->i", s.normal[valid], dirs[valid.reshape(-1)])
    assert (facing < 0).mean() > 0.95


def test_kernels_run_without_jit():
    """NUMBA_DISABLE_JIT=1: the same code as plain Python gives the same G-buffer."""
    script = r"""
import json, sys
import numpy as np
sys.path[:0] = [sys.argv[1], sys.argv[1] + "/raster"]
from test_rasterize import mini_scene, low_view
from synthetic import box_city
from cityshade.raster.rasterize import rasterize
v, t, b, e, _ = box_city(6, seed=2, extent_m=40.0)
scene = mini_scene(v, t, b, e)
from cityshade.raster import camera as cams
cam = cams.overview(scene, 24, 16)
g = rasterize(scene, cam, 0.0, occlusion_culling=True)
print(json.dumps({"prim": g.prim_id.tolist(), "depth": g.depth.astype(float).tolist()}))
"""
    results = run_with_and_without_jit(script)
    assert results[0] == results[1]
    assert any(p >= 0 for row in results[0]["prim"] for p in row)


def test_bad_input_is_refused(sample_scene):
    from cityshade.errors import UsageError

    cam = cams.overview(sample_scene, 8, 8)
    with pytest.raises(UsageError):
        rasterize(sample_scene, cam, float("nan"))
    with pytest.raises(UsageError):
        rasterize(sample_scene, cam, 0.0, occlusion_culling="sometimes")
    with pytest.raises(UsageError):
        rasterize(sample_scene, cam, 0.0, tile_px=12)
    with pytest.raises(UsageError):
        rasterize(sample_scene, "overview", 0.0)


def test_auto_occlusion_switches_off_only_when_queries_do_not_pay():
    from cityshade.raster import culling as cull
    from cityshade.raster.rasterize import (AUTO_MIN_QUERIES, AUTO_REFS_PER_QUERY,
                                            _occlusion_does_not_pay)

    stats = np.zeros(cull.N_STATS, np.int64)
    stats[cull.ST_OCCLUSION_QUERIES] = AUTO_MIN_QUERIES - 1
    assert not _occlusion_does_not_pay(stats)                 # too early to judge
    stats[cull.ST_OCCLUSION_QUERIES] = AUTO_MIN_QUERIES
    assert _occlusion_does_not_pay(stats)                     # nothing removed
    stats[cull.ST_OCCLUSION_REFS] = int(AUTO_REFS_PER_QUERY * AUTO_MIN_QUERIES)
    assert not _occlusion_does_not_pay(stats)


def test_subtree_ranges_match_the_leaves(dated_city):
    from cityshade.raster.culling import tree_info

    tree = dated_city.kdtree
    refs, first, biggest = tree_info(tree)
    axis, child, second = tree.unpack()
    leaves = axis == 4
    assert refs[0] == tree.prim_indices.shape[0] and biggest == child[leaves].max()
    # Every contiguous range holds exactly the references of the leaves below the node.
    for node in np.flatnonzero(first >= 0)[:200]:
        below, todo = [], [node]
        while todo:
            n = todo.pop()
            if axis[n] == 4:
                below.extend(range(int(second[n]), int(second[n]) + int(child[n])))
            else:
                todo.extend([n + 1, int(child[n])])
        assert sorted(below) == list(range(first[node], first[node] + refs[node]))


@pytest.mark.parametrize("view", ["overview", "map"])
def test_resolve_and_seen_side_normals_equal_their_numpy_twins_bit_for_bit(sample_scene, view):
    from cityshade.shadows import oriented_normals
    from reference import reference_oriented_normals, reference_resolve

    cam = (cams.overview(sample_scene, 160, 90) if view == "overview"
           else cams.map_view(sample_scene, 1.0))
    g = rasterize(sample_scene, cam, 20000.0)
    s = resolve(sample_scene, g)
    ref = reference_resolve(sample_scene, g.prim_id, g.bary)
    assert ref["valid"].sum() > 1000
    for name, want in ref.items():
        got = getattr(s, name)
        assert got.dtype == want.dtype, name
        np.testing.assert_array_equal(got, want, err_msg=name)   # NaN == NaN here
    got = oriented_normals(s, cam)
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, reference_oriented_normals(s, cam))
    # Every triangle wound inward (seen from the back): each normal is turned again.
    inward = dataclasses.replace(s, normal=-s.normal)
    got = oriented_normals(inward, cam)
    np.testing.assert_array_equal(got, reference_oriented_normals(inward, cam))
    np.testing.assert_array_equal(got, oriented_normals(s, cam))


@pytest.mark.parametrize("view", ["overview", "street", "map"])
def test_ground_plane_equals_its_numpy_twin_bit_for_bit(sample_scene, view):
    from cityshade.geometry.ground import add_ground_plane, ground_box_m, ground_height_m
    from reference import reference_add_ground_plane

    if view == "overview":
        cam = cams.overview(sample_scene, 320, 180)
    elif view == "street":  # eye at 2 m looking along the ground: rays above the horizon too
        lo, hi = ground_box_m(sample_scene)
        eye = (lo[0] - 20.0, lo[1] - 20.0, lo[2] + 2.0)
        cam = cams.perspective(eye, (hi[0], hi[1], lo[2] + 2.0), vfov_deg=70.0, width_px=320,
                               height_px=180, scene=sample_scene)
    else:  # a map reaching past the model, where only the plane is
        lo, hi = ground_box_m(sample_scene)
        cam = cams.map_view(sample_scene, 1.0, bbox=(lo[0] - 80.0, lo[1] - 50.0, hi[0], hi[1]))
    z = ground_height_m(sample_scene, "auto")
    s = resolve(sample_scene, rasterize(sample_scene, cam, 20000.0))
    lo, hi = ground_box_m(sample_scene)
    filled = []
    for box in ((lo, hi), (lo, lo + 0.2 * (hi - lo))):  # the plane cut by its box's margin
        want, want_n = reference_add_ground_plane(cam, s, z, box)
        filled.append(want_n)
        before = {k: np.array(getattr(s, k), copy=True) for k in want}
        got, got_n = add_ground_plane(sample_scene, cam, s, z, box)
        assert got_n == want_n and want_n > 500, (view, want_n)
        for name, value in want.items():
            assert getattr(got, name).dtype == value.dtype, name
            np.testing.assert_array_equal(getattr(got, name), value, err_msg=name)
        np.testing.assert_array_equal(s.valid, before["valid"])  # the G-buffer's own
        np.testing.assert_array_equal(s.depth, before["depth"])
        s = resolve(sample_scene, rasterize(sample_scene, cam, 20000.0))
    assert filled[1] < filled[0]
