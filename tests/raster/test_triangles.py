"""The shared triangle core (raster/triangles.py), the depth pass's walk order and the kd-tree
layout's decoders and typed errors."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.accel import build_kdtree
from cityshade.accel import kdtree_layout as kl
from cityshade.errors import CityshadeError
from cityshade.raster import camera as cams
from cityshade.raster import triangles as tc
from cityshade.raster.depthpass import box_planes, projection_centre
from cityshade.shadows import shadowmap as sm
from synthetic import box_city
from test_rasterize import mini_scene


@pytest.fixture(scope="module")
def dated():
    v, t, b, e, m = box_city(150, seed=11, extent_m=200.0)
    return v, t, b, e, build_kdtree(v, t, b, e, m)


def _walk_all(tree, t_days, planes, order_point, n_triangles, batch):
    walk = tc.CulledWalk(tree, t_days, planes, order_point, n_triangles)
    emitted = []
    while not walk.done:
        emitted.extend(tree.prim_indices[walk.next(batch)].tolist())
    return emitted


@pytest.mark.parametrize("t_days", [-30000.0, 0.0, 12000.0])
def test_walk_emits_each_standing_triangle_once_in_any_order(dated, t_days):
    v, t, b, e, tree = dated
    standing = set(np.flatnonzero((b <= t_days) & (t_days < e)).tolist())
    orders = [np.array([-50.0, -50.0, 10.0, 1.0]), np.array([100.0, 100.0, 5.0, 1.0]),
              np.array([0.0, 0.0, 1.0, 0.0]), np.array([0.6, -0.64, -0.48, 0.0])]
    no_planes = np.zeros((0, 4))
    for order in orders:
        emitted = _walk_all(tree, t_days, no_planes, order, t.shape[0], 37)
        assert len(emitted) == len(set(emitted))
        assert set(emitted) == standing
    # Culled to a box: every order point emits the same triangles, all standing, and every
    # standing triangle lying inside the box among them (the walk is conservative).
    box = np.array([[40.0, 30.0, -5.0], [120.0, 90.0, 60.0]])
    planes = box_planes(box, 0.0)
    sets = []
    for order in orders:
        emitted = _walk_all(tree, t_days, planes, order, t.shape[0], 1000)
        assert len(emitted) == len(set(emitted))
        sets.append(set(emitted))
    assert all(s == sets[0] for s in sets) and sets[0] <= standing
    tri_lo, tri_hi = v[t].min(axis=1), v[t].max(axis=1)
    inside = np.flatnonzero(((tri_lo >= box[0]) & (tri_hi <= box[1])).all(axis=1))
    assert {int(i) for i in inside if int(i) in standing} <= sets[0]
    assert len(sets[0]) < len(standing)


def test_projection_centre_of_light_and_camera_views():
    for az, el in ((135.0, 30.0), (10.0, 80.0), (250.0, 3.0)):
        a, z = np.radians(az), np.radians(el)
        sun = np.array([np.sin(a) * np.cos(z), np.cos(a) * np.cos(z), np.sin(z)])
        view = sm.ortho_view(sun, (-50.0, 50.0), (-40.0, 40.0), (-200.0, 200.0), 64, 64)
        c = projection_centre(view.clip_from_world)
        assert c[3] == 0.0
        np.testing.assert_allclose(c[:3] / np.linalg.norm(c[:3]), sun, atol=1e-12)
    cam = cams.perspective([10.0, -250.0, 80.0], [0.0, 0.0, 0.0], vfov_deg=50.0, width_px=64,
                           height_px=48, near_m=0.5, far_m=2000.0)
    c = projection_centre(cam.clip_from_world())
    assert c[3] == 1.0
    np.testing.assert_allclose(c[:3], cam.eye_m, rtol=1e-9, atol=1e-6)


def test_kernel_tree_of_a_scene_without_kdtree():
    scene = mini_scene([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], tree=False)
    views = tc.kernel_tree(scene)
    assert isinstance(views, kl.KdViews) and views.recs.shape == (1, kl.RECORD_WORDS)


def test_layout_decoders_agree_with_unpack(dated):
    *_, tree = dated
    axis, child, second = tree.unpack()
    views = tree.views
    for node in range(0, tree.nodes.shape[0], max(1, tree.nodes.shape[0] // 300)):
        w0 = kl.node_word(views, node)
        assert kl.word_axis(w0) == axis[node] and kl.word_payload(w0) == child[node]
        if axis[node] == kl.LEAF_CODE:
            assert kl.leaf_first(views, node) == second[node]
        else:
            assert kl.node_split(views, node) == second[node]
    for k in range(0, tree.prim_indices.shape[0], 97):
        assert kl.record_id(views, k) == tree.prim_indices[k]
        begin, end = tree.records_f64[k, kl.REC_T_BEGIN64], tree.records_f64[k, kl.REC_T_END64]
        for t in (begin - 1.0, begin, end, 0.0):
            assert kl.record_present(views, k, t) == bool(begin <= t < end)


def test_layout_errors_are_typed(dated):
    *_, tree = dated
    arrays = tree.to_arrays()
    with pytest.raises(kl.KdTreeLayoutError, match="missing: kdtree_bounds"):
        kl.KdTree.from_arrays({k: a for k, a in arrays.items() if k != "kdtree_bounds"})
    with pytest.raises(kl.KdTreeLayoutError, match="uint32"):
        kl.KdTree.from_arrays({**arrays, "kdtree_nodes": arrays["kdtree_nodes"].astype(np.int64)})
    with pytest.raises(kl.KdTreeLayoutError, match="too large"):
        kl.pack_nodes([0], [2 ** 29], [0], [0.0])
    assert issubclass(kl.KdTreeLayoutError, CityshadeError)


@pytest.mark.parametrize("n", [0, 5, 70_000])
@pytest.mark.parametrize("tile_px", [64, 48])
def test_tile_lists_are_the_twins_at_any_thread_count(n, tile_px):
    """bin_triangles gives the twin's lists, in drawing order, at 1 and 2 threads; and
    tile_order deals every tile once, each thread's blocks one contiguous part."""
    import numba

    from reference import reference_tile_lists

    rng = np.random.default_rng(n + tile_px)
    w, h = 700, 300
    tiles_x, tiles_y = -(-w // tile_px), -(-h // tile_px)
    c0 = rng.integers(0, w, n)
    r0 = rng.integers(0, h, n)
    bbox = np.stack([c0, np.minimum(c0 + rng.integers(-3, 90, n), w - 1), r0,
                     np.minimum(r0 + rng.integers(0, 90, n), h - 1)], axis=1).astype(np.int32)
    want = reference_tile_lists(bbox, tile_px, tiles_x, tiles_y)
    before = numba.get_num_threads()
    try:
        for threads in (1, min(2, numba.config.NUMBA_NUM_THREADS)):
            numba.set_num_threads(threads)
            start, items = tc.bin_triangles(bbox, tile_px, tiles_x, tiles_y)
            got = [items[start[t]:start[t + 1]].tolist() for t in range(tiles_x * tiles_y)]
            assert got == want
    finally:
        numba.set_num_threads(before)
    for threads in (1, 2, 3):
        order = tc.tile_order(tiles_x, tiles_y, threads)
        assert sorted(order.tolist()) == list(range(tiles_x * tiles_y))
        block = tc.AFFINITY_BLOCK
        owner = ((order % tiles_x) // block + (order // tiles_x) // block) % threads
        assert (np.diff(owner) >= 0).all()              # each thread's tiles contiguous


def test_depth_pass_narrow_and_wide_boxes_agree_with_the_ray_cast_twin():
    # Casters of 1-3 texels (tested texel by texel) and of tens (within column bounds) over
    # several tiles of 8 texels: both tile-kernel paths against the numpy twin.
    from types import SimpleNamespace

    from cityshade.raster.depthpass import NARROW_COLS
    from cityshade.geo.sun import sun_from_angles
    from reference import reference_depth_map

    rng = np.random.default_rng(5)
    n_small, n_big = 300, 20
    centres = rng.uniform(-12, 12, (n_small + n_big, 1, 3))
    spread = np.r_[np.full(n_small, 0.25), np.full(n_big, 3.0)][:, None, None]
    verts = (centres + spread * rng.normal(0, 1, (n_small + n_big, 3, 3))).reshape(-1, 3)
    n = n_small + n_big
    scene = SimpleNamespace(vertices=verts.astype(np.float32),
                            triangles=np.arange(3 * n, dtype=np.int32).reshape(n, 3),
                            tri_t_begin_days=np.zeros(n), tri_t_end_days=np.full(n, np.inf),
                            kdtree=None)
    view = sm.ortho_view(sun_from_angles(120.0, 50.0).direction, (-16, 16), (-14, 14),
                         (-40, 40), 64, 56)
    dm = sm.render_depth_map(scene, view, 0.0, tile_px=8)
    depth, prim = reference_depth_map(scene.vertices, scene.triangles, scene.tri_t_begin_days,
                                      scene.tri_t_end_days, view.clip_from_world, 64, 56)
    # Texel centres exactly on a shared edge may go either way in the twin (closed edges).
    same = dm.prim_id == prim
    assert same.mean() >= 0.99, f"{(~same).sum()} of {same.size} texels differ"
    both = same & (prim >= 0)
    assert both.sum() > 0.1 * same.size
    np.testing.assert_allclose(dm.depth[both], depth[both], atol=2e-6)
    # Both paths were taken: boxes of at most NARROW_COLS columns and wider ones drawn.
    clip = np.c_[scene.vertices.astype(np.float64), np.ones(3 * n)] @ view.clip_from_world.T
    cols = (clip[:, 0] / clip[:, 3] + 1.0) * 32.0 - 0.5
    width = np.ptp(cols.reshape(n, 3), axis=1)
    drawn = set(dm.prim_id[dm.prim_id >= 0].tolist())
    assert any(width[i] < NARROW_COLS - 1 for i in drawn)
    assert any(width[i] > 3 * NARROW_COLS for i in drawn)


def test_covered_span_is_exactly_the_columns_covers_admits():
    # Edge functions through texel centres (exact zeros on both sides of shared edges) and
    # random ones: the span found from both ends holds every admitted column and no other.
    rng = np.random.default_rng(5)
    xs = 2.0 * (np.arange(64) + 0.5) / 64 - 1.0
    checked = 0
    for _ in range(3000):
        pts = rng.choice(xs, size=(3, 2)) if rng.random() < 0.5 else rng.uniform(-1.2, 1.2, (3, 2))
        x0, y0 = pts[0]
        x1, y1 = pts[1]
        x2, y2 = pts[2]
        coef = []
        for (ax, ay), (bx, by) in (((x1, y1), (x2, y2)), ((x2, y2), (x0, y0)),
                                   ((x0, y0), (x1, y1))):
            coef.append((ay - by, bx - ax, ax * by - ay * bx))
        det = x0 * coef[0][0] + y0 * coef[0][1] + coef[0][2]
        if det == 0.0:
            continue
        s = 1.0 if det > 0 else -1.0
        e = [(s * a, s * b, s * c, bool(s * a > 0 or (s * a == 0 and s * b < 0)))
             for a, b, c in coef]
        for y in rng.choice(xs, size=4):
            rows = [b * y + c for _, b, c, _ in e]
            args = (e[0][0], rows[0], e[0][3], e[1][0], rows[1], e[1][3], e[2][0], rows[2],
                    e[2][3])
            c_lo, c_hi = sorted(rng.integers(0, 64, 2))
            want = [c for c in range(c_lo, c_hi + 1) if tc.covers(xs[c], *args)[0]]
            first, last = tc.covered_span(xs, int(c_lo), int(c_hi), *args)
            assert list(range(first, last + 1)) == want
            checked += len(want) > 0
    assert checked > 1000


@pytest.mark.parametrize("case", ["overview", "map", "inside", "shadowmap", "lispsm"])
def test_interpreted_setup_and_binning_draw_what_the_kernels_draw(sample_city_scene, monkeypatch,
                                                                case):
    """A first use's small batches go through the kernels' interpreted twins
    (``_setup_kernels``): every pixel of the G-buffer and the shadows the same, bit for bit,
    also for a camera inside the city (triangles crossing W = 0 and the near plane) and the
    light's depth passes (orthographic and perspective)."""
    from cityshade.frame.render import render_frame
    from cityshade.geo.sun import sun_from_angles
    from cityshade.geo.temporal import parse_user_date
    from cityshade.runtime.interpret import InterpretBudget

    scene = sample_city_scene
    lo, hi = cams.scene_box(scene)[0], cams.scene_box(scene)[1]
    mid = (lo + hi) / 2
    cam = {"map": lambda: cams.map_view(scene, 1.0),
           "inside": lambda: cams.perspective((mid[0], mid[1], lo[2] + 1.7),
                                              (hi[0], mid[1] + 5.0, lo[2] + 8.0), vfov_deg=100,
                                              width_px=320, height_px=200, scene=scene)
           }.get(case, lambda: cams.overview(scene, 320, 180))()
    technique = {"shadowmap": "shadowmap", "lispsm": "lispsm"}.get(case, "exact")
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    t = parse_user_date("1990").city_days
    frames, used = [], []
    for budget in (InterpretBudget(0), InterpretBudget(10 ** 9)):
        monkeypatch.setattr(tc, "_INTERPRET", budget)
        monkeypatch.setattr(budget, "kernels", ())      # interpret even when compiled
        frames.append(render_frame(scene, cam, t, sun, technique))
        used.append(budget.left)
    assert used[0] == 0 and used[1] < 10 ** 9         # the second frame went interpreted
    compiled, twin = frames
    for name in ("prim_id", "bary", "depth"):
        a, b = getattr(compiled.gbuffer, name), getattr(twin.gbuffer, name)
        assert a.tobytes() == b.tobytes(), name
    assert compiled.lit.tobytes() == twin.lit.tobytes()
    assert compiled.rgb.tobytes() == twin.rgb.tobytes()
    assert (compiled.gbuffer.prim_id >= 0).mean() > 0.05


def test_interpreted_date_filter_box_tests_and_shear_agree_with_the_kernels():
    """The small kernels a first use runs interpreted from Python (``present_triangles``,
    ``box_outside``, ``lightspace.kernels.shear_of``) answer as compiled, on edge cases too."""
    from cityshade.lightspace import kernels as lk
    from cityshade.raster import culling
    from cityshade.runtime.interpret import python_twin

    rng = np.random.default_rng(3)
    begin = rng.choice([-np.inf, -10.0, 0.0, 5.0, 7.5], 400)
    end = np.maximum(begin, -1e300) + rng.choice([0.0, 1.0, 2.5, np.inf], 400)
    for t in (-np.inf, -10.0, 0.0, 4.9, 5.0, 7.5, 1e9):
        a = tc.present_triangles(begin, end, t)
        b = python_twin(tc.present_triangles)(begin, end, t)
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes()
    outside = python_twin(culling.box_outside)
    seen = set()
    for _ in range(500):
        planes = rng.normal(0, 1, (6, 4))
        planes[rng.random(6) < 0.2, :3] = 0.0          # degenerate normals
        lo = rng.normal(0, 1, 3)
        hi = lo + rng.choice([0.0, 0.5, 3.0], 3)
        mask = int(rng.integers(0, 64))
        got, want = outside(planes, lo, hi, mask), culling.box_outside(planes, lo, hi, mask)
        assert (bool(got[0]), int(got[1])) == (bool(want[0]), int(want[1]))
        seen.add((bool(want[0]), int(want[1]) != mask))
    # Boxes outside, boxes inside some planes (their bits dropped) and boxes straddling all.
    assert any(o for o, _ in seen) and (False, True) in seen and (False, False) in seen
    shear = python_twin(lk.shear_of)
    dirs = np.vstack([rng.normal(0, 1, (300, 3)), np.eye(3), -np.eye(3),
                      [[1, 1, 0], [0, -1, 1], [1, 1, 1], [-1, -1, -1]]]).astype(np.float64)
    for d in dirs / np.linalg.norm(dirs, axis=1)[:, None]:
        assert tuple(float(x) for x in shear(d)) == tuple(float(x) for x in lk.shear_of(d))
