"""The light-space engine (``izb``) gives ``raytrace``'s answer on every pixel, bit for bit.

Equality is asserted as 0 differing receivers (never a fraction): on the sample city, the TUM
campus and the Munich CityGML 3.0 tile, map and overview views, suns from 0.5° to 90° at several
azimuths, with and without ground, at dates before and after buildings stand; on rays aimed at
the shared edges and vertices of closed solids; for 1 and 2 threads; without JIT. The analytic
box shadow and a brute-force twin (tests/reference.py) check numbers the engine did not compute.
"""
from __future__ import annotations

import math

import numba
import numpy as np
import pytest

from conftest import REPO, run_with_and_without_jit, shared_file
from reference import reference_ray_hits
from synthetic import BOX_FACES, box_city
from synthetic import closed_box_tree, edge_and_vertex_targets, unit

from cityshade import lightspace
from cityshade.accel import build_kdtree
from cityshade.build import build_file
from cityshade.store.scenefile import load_scene
from cityshade.shadows import ShadowContext, get_technique
from cityshade.geo.sun import sun_from_angles
from cityshade.errors import TraceInputError
from cityshade.trace import occluded, shadow_rays_from_surface

#: (elevation, azimuth) pairs covering the issue's suns: grazing to zenith, several azimuths
#: (axis-aligned ones put walls edge-on to the sun; 90° is straight down the z axis).
SUNS = [(0.5, 250.0), (3.0, 90.0), (10.0, 135.0), (30.0, 200.0), (30.0, 0.0), (60.0, 315.0),
        (89.9, 45.0), (90.0, 0.0)]


def _built(path, tmp_path_factory, name):
    out, _, _ = build_file(path, tmp_path_factory.mktemp(name) / f"{name}.cityshade")
    return load_scene(out)


@pytest.fixture(scope="module")
def sample_scene(tmp_path_factory):
    return _built(REPO / "sample_data" / "sample_city.gml", tmp_path_factory, "sample")


def _surfaces(scene, camera, t_days, ground):
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize

    surfaces = resolve(scene, rasterize(scene, camera, t_days))
    if ground is not None:
        from cityshade.geometry.ground import add_ground_plane, ground_height_m

        surfaces, _ = add_ground_plane(scene, camera, surfaces, ground_height_m(scene, ground))
    return surfaces


def _assert_same_as_raytrace(scene, camera, t_days, suns, ground=None, crs=False):
    """Run ``raytrace`` and ``izb`` on one G-buffer for every sun; 0 differing pixels."""
    surfaces = _surfaces(scene, camera, t_days, ground)
    rt, izb = get_technique("raytrace"), get_technique("izb")
    shadowed = 0
    for el, az in suns:
        sun = (sun_from_angles(az, el, scene.crs, scene.origin_m) if crs
               else sun_from_angles(az, el))
        ctx = ShadowContext(scene=scene, surfaces=surfaces, camera=camera, sun=sun,
                            t_days=t_days)
        a = rt.run(ctx).lit
        b = izb.run(ctx).lit
        diff = int((a != b).sum())
        assert diff == 0, (f"izb differs from raytrace on {diff} of {a.size} pixels at sun "
                           f"{el}°/{az}°, t={t_days}, ground={ground}")
        shadowed += int(((a == 0) & surfaces.valid).sum())
    assert shadowed > 0, "no shadow at all: the comparison would prove nothing"


@pytest.mark.parametrize("year", ["1750", "1990"])
@pytest.mark.parametrize("ground", [None, "min"])
def test_sample_city_map_and_overview_equal_raytrace(sample_scene, year, ground):
    from cityshade.geo.temporal import parse_xsd_datetime_days
    from cityshade.raster.camera import map_view, overview

    t = parse_xsd_datetime_days(year)
    _assert_same_as_raytrace(sample_scene, map_view(sample_scene, 1.0), t, SUNS, ground)
    _assert_same_as_raytrace(sample_scene, overview(sample_scene, 320, 200), t, SUNS, ground)


def test_tum_campus_equals_raytrace(tmp_path_factory):
    from cityshade.raster.camera import map_view, overview

    scene = _built(shared_file("munich-tum-campus-lod2/TUM Munich.gml"), tmp_path_factory,
                   "tum")
    suns = [(0.5, 100.0), (10.0, 135.0), (30.0, 200.0), (60.0, 250.0), (90.0, 0.0)]
    _assert_same_as_raytrace(scene, map_view(scene, 2.0), 20000.0, suns, "auto", crs=True)
    _assert_same_as_raytrace(scene, overview(scene, 320, 200), 20000.0, suns, "auto", crs=True)


def test_munich_citygml3_tile_equals_raytrace(tmp_path_factory):
    from cityshade.raster.camera import map_view, overview

    scene = _built(shared_file("munich-lod2-citygml3-tile/"
                               "Buildings_CityGML3.0_LOD2_with_PointClouds_external_one_laz_file.gml"),
                   tmp_path_factory, "munich")
    suns = [(3.0, 120.0), (30.0, 180.0), (89.9, 10.0)]
    _assert_same_as_raytrace(scene, map_view(scene, 3.0), 20000.0, suns, None, crs=True)
    _assert_same_as_raytrace(scene, overview(scene, 320, 200), 20000.0, suns, "auto", crs=True)


def _inside_closed_mesh(points, verts, faces, clearance_m=1e-3):
    """Points strictly inside a convex closed mesh with outward winding."""
    v = verts.astype(np.float64)
    inside = np.ones(len(points), bool)
    for a, b, c in faces:
        n = np.cross(v[b] - v[a], v[c] - v[a])
        n /= np.linalg.norm(n)
        inside &= (points - v[a]) @ n < -clearance_m
    return inside


@pytest.mark.parametrize("rotation_seed", [None, 1, 2])
def test_rays_at_shared_edges_and_vertices_of_a_closed_box(rotation_seed):
    """Shadow rays from inside a closed box, each aimed exactly at a vertex or a point of an
    edge, never escape (watertight), and izb says so on every ray, as raytrace does."""
    verts, tree = closed_box_tree(rotation_seed=rotation_seed)
    targets = edge_and_vertex_targets(verts, BOX_FACES)
    checked = 0
    for el, az in SUNS:
        d = np.asarray(sun_from_angles(az, el).direction, np.float64)
        for back_m in (0.3, 1.0, 2.5):
            origins = targets - back_m * d
            origins = origins[_inside_closed_mesh(origins, verts, BOX_FACES)]
            if not len(origins):
                continue
            izb = lightspace.occluded(tree, origins, d)
            ref = occluded(tree, origins, np.broadcast_to(d, origins.shape).copy())
            assert izb.all(), f"{(~izb).sum()} rays slipped through the box at {el}°/{az}°"
            np.testing.assert_array_equal(izb, ref)
            checked += len(origins)
    assert checked > 500


def test_random_rays_agree_with_raytrace_and_brute_force():
    """Seeded random shadow rays in a dated random city, at times before, between and after
    the boxes stand: equal to trace.occluded everywhere, to a Moller-Trumbore brute force
    away from edges."""
    city = box_city(60, seed=5, extent_m=120.0)
    v, t, begin, end, _ = city
    tree = build_kdtree(*city)
    rng = np.random.default_rng(11)
    origins = rng.uniform((-10, -10, -2), (140, 140, 45), (4000, 3))
    for t_days in (-30000.0, 0.0, 15000.0, 40000.0):
        for el, az in SUNS:
            d = np.asarray(sun_from_angles(az, el).direction, np.float64)
            izb = lightspace.occluded(tree, origins, d, t_days)
            ref = occluded(tree, origins, np.broadcast_to(d, origins.shape).copy(), t_days)
            np.testing.assert_array_equal(izb, ref, err_msg=f"sun {el}°/{az}°, t={t_days}")
            for i in range(0, len(origins), 211):
                hits, _ = reference_ray_hits(v, t, begin, end, origins[i], d, t_days)
                assert izb[i] == (hits.size > 0), f"ray {i}, sun {el}°/{az}°, t={t_days}"


def test_box_shadow_length_is_h_over_tan_elevation():
    """A 10 m box on a plane: the ground behind it is shadowed out to h / tan(el) and lit
    beyond (an analytic number)."""
    h = 10.0
    corners = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                        (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], np.float64)
    box = (np.array([-5.0, -5.0, 0.0]) + corners * [10.0, 10.0, h]).astype(np.float32)
    n = 12
    tree = build_kdtree(box, BOX_FACES.astype(np.int32), np.full(n, -np.inf), np.full(n, np.inf),
                        np.zeros(n, np.int32))
    for el in (20.0, 35.0, 60.0):
        d = np.asarray(sun_from_angles(180.0, el).direction, np.float64)  # sun in the south
        length = h / math.tan(math.radians(el))
        ys = 5.0 + np.array([0.02, 0.5, 0.98]) * length
        behind = np.column_stack([np.zeros(3), ys, np.zeros(3)])
        beyond = np.column_stack([np.zeros(2), 5.0 + length + np.array([0.05, 1.0]), np.zeros(2)])
        pts = np.vstack([behind, beyond])
        origins = shadow_rays_from_surface(pts, np.tile([0.0, 0.0, 1.0], (len(pts), 1)), d)
        got = lightspace.occluded(tree, origins, d)
        assert got.tolist() == [True, True, True, False, False], f"elevation {el}°"


def test_thread_count_does_not_change_the_answer(sample_scene, monkeypatch):
    from cityshade.raster.camera import map_view

    monkeypatch.setattr(lightspace, "SINGLE_THREAD_WORK", 0)  # small calls use all threads too

    cam = map_view(sample_scene, 1.0)
    surfaces = _surfaces(sample_scene, cam, 20000.0, "min")
    d = np.asarray(sun_from_angles(135.0, 10.0).direction, np.float64)
    points = surfaces.position_m[surfaces.valid]
    normals = np.asarray(surfaces.normal, np.float64)[surfaces.valid]
    normals[normals @ d < 0] *= -1.0
    default = numba.get_num_threads()
    results = []
    try:
        for threads in sorted({1, min(2, numba.config.NUMBA_NUM_THREADS)}):
            numba.set_num_threads(threads)
            results.append(lightspace.sunlit(sample_scene.kdtree, points, normals, d, 20000.0))
    finally:
        numba.set_num_threads(default)
    for r in results[1:]:
        np.testing.assert_array_equal(r, results[0])
    assert 0 < results[0].mean() < 1


def test_read_only_inputs_and_validation(tmp_path):
    from cityshade.accel import KdTree

    city = box_city(10, seed=2, extent_m=60.0)
    tree = build_kdtree(*city)
    for name, arr in tree.to_arrays().items():
        np.save(tmp_path / f"{name}.npy", arr)
    mapped = KdTree.from_arrays({name: np.load(tmp_path / f"{name}.npy", mmap_mode="r")
                                 for name in tree.to_arrays()})
    origins = np.random.default_rng(3).uniform(-5, 70, (300, 3))
    origins.setflags(write=False)
    d = unit([0.3, -0.4, 0.6])
    np.testing.assert_array_equal(lightspace.occluded(mapped, origins, d),
                                  occluded(tree, origins, np.broadcast_to(d, origins.shape)))
    assert lightspace.occluded(tree, np.zeros((0, 3)), d).shape == (0,)
    # One receiver; receivers no caster can reach; a time when nothing stands.
    for one in origins[:40]:
        assert lightspace.occluded(tree, one[None], d)[0] == occluded(tree, one[None], d[None])[0]
    assert not lightspace.occluded(tree, origins + [0.0, 0.0, 500.0], d).any()
    empty_tree = build_kdtree(city[0], city[1], np.full(len(city[1]), 5.0),
                              np.full(len(city[1]), 6.0), city[4])
    assert not lightspace.occluded(empty_tree, origins, d, 0.0).any()
    with pytest.raises(TraceInputError, match="unit length"):
        lightspace.occluded(tree, origins, [0.0, 0.0, 2.0])
    with pytest.raises(TraceInputError, match="shape"):
        lightspace.occluded(tree, origins[:, :2], d)
    with pytest.raises(TraceInputError, match="NaN"):
        lightspace.occluded(tree, np.full((2, 3), np.nan), d)
    with pytest.raises(TraceInputError, match="NaN"):
        lightspace.occluded(tree, origins, d, float("nan"))


def test_surface_receivers_make_the_origins_of_shadow_rays_from_surface():
    """A batch's receivers (points checked once, origins per sun from one kernel) give
    shadow_rays_from_surface's origins bit for bit, for masks, index lists and every sun."""
    rng = np.random.default_rng(5)
    points = rng.uniform(-3000.0, 3000.0, (500, 3))
    points[:50] *= 1e-4  # below the offset's 1 m floor
    normals = rng.normal(size=(500, 3))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    receivers = lightspace.SurfaceReceivers(points, normals)
    for elevation, azimuth in SUNS:
        d = np.asarray(sun_from_angles(azimuth, elevation).direction, np.float64)
        faces = normals @ d > 0
        np.testing.assert_array_equal(receivers.origins(d, faces),
                                      shadow_rays_from_surface(points[faces], normals[faces], d))
    index = np.array([7, 3, 499, 3])
    np.testing.assert_array_equal(receivers.origins(d, index),
                                  shadow_rays_from_surface(points[index], normals[index], d))
    np.testing.assert_array_equal(receivers.origins(d),
                                  shadow_rays_from_surface(points, normals, d))
    with pytest.raises(TraceInputError, match="unit length"):
        lightspace.SurfaceReceivers(points, normals * 2.0)
    with pytest.raises(TraceInputError, match="NaN"):
        lightspace.SurfaceReceivers(np.full((2, 3), np.nan), normals[:2])
    with pytest.raises(TraceInputError, match="unit length"):
        receivers.origins([0.0, 0.0, 2.0])


def test_kernels_run_without_jit():
    """NUMBA_DISABLE_JIT=1: the engine as plain Python gives the compiled engine's answer."""
    script = r"""
import json, numpy as np, sys
sys.path.insert(0, sys.argv[1])
from synthetic import box_city
from cityshade.accel import build_kdtree
from cityshade import lightspace
tree = build_kdtree(*box_city(4, seed=9, extent_m=30.0))
o = np.random.default_rng(1).uniform(-5, 40, (60, 3))
d = np.array([0.48, -0.36, 0.8])
print(json.dumps([lightspace.occluded(tree, o, d, 0.0).tolist(),
                  lightspace.occluded(tree, o, -d, 0.0).tolist()]))
"""
    results = run_with_and_without_jit(script)
    assert results[0] == results[1]
    assert any(results[0][0]) and not all(results[0][0])


def test_occupancy_cull_drops_only_casters_whose_box_holds_no_receiver():
    """cull_unoccupied against the one-by-one twin: every box holding a receiver point is
    kept, and boxes far from the receivers' band are dropped."""
    from reference import reference_boxes_holding_a_point
    from cityshade.lightspace import kernels as K

    rng = np.random.default_rng(4)
    t = rng.uniform(0.0, 100.0, 3000)
    xs, ys = t, 0.5 * t + rng.uniform(-1.0, 1.0, t.size)        # a thin slanted band
    x0 = rng.uniform(-5.0, 105.0, 5000)
    y0 = rng.uniform(-5.0, 55.0, 5000)
    w = rng.uniform(0.0, 3.0, (2, 5000))
    boxes = np.column_stack([x0, x0 + w[0], y0, y0 + w[1]])
    boxes[::97, 0] = np.nan
    holds = reference_boxes_holding_a_point(boxes, xs, ys)
    for nx, ny in ((1, 1), (37, 19), (400, 200)):
        inv = 1.0 / max((xs.max() - xs.min()) / nx, (ys.max() - ys.min()) / ny)
        table = np.empty((ny + 1, nx + 1), np.int32)
        K.occupancy_table(xs, ys, xs.min(), ys.min(), inv, nx, ny, table)
        assert table[-1, -1] == len({(K._cell(y, ys.min(), inv, ny), K._cell(x, xs.min(), inv, nx))
                                     for x, y in zip(xs, ys)})
        got = boxes.copy()
        K.cull_unoccupied(got, xs.min(), ys.min(), inv, nx, ny, table)
        kept = ~np.isnan(got[:, 0])
        assert not (holds & ~kept).any()
        if nx == 400:
            assert kept.sum() < 0.5 * (~np.isnan(boxes[:, 0])).sum()


def test_a_thin_band_of_receivers_equals_raytrace_with_and_without_the_occupancy_cull(
        monkeypatch):
    """A map strip's receivers (a thin band, slanted in the light plane): the answer is
    trace.occluded's with the occupancy cull and without it (one cell), and the cull keeps
    fewer casters; the casters culled a few rows at a time give the same answer."""
    city = box_city(200, seed=9, extent_m=300.0)
    tree = build_kdtree(*city)
    rng = np.random.default_rng(2)
    origins = np.column_stack([rng.uniform(0, 300, 5000), rng.uniform(140, 146, 5000),
                               rng.uniform(0.0, 20.0, 5000)])
    d = np.asarray(sun_from_angles(135.0, 30.0).direction, np.float64)
    ref = occluded(tree, origins, np.broadcast_to(d, origins.shape).copy())
    kept = {}
    for cells, rows in ((1, lightspace.CULL_ROWS), (lightspace.OCCUPANCY_CELLS, 97)):
        monkeypatch.setattr(lightspace, "OCCUPANCY_CELLS", cells)
        monkeypatch.setattr(lightspace, "CULL_ROWS", rows)
        stats: dict = {}
        np.testing.assert_array_equal(lightspace.occluded(tree, origins, d, stats=stats), ref)
        kept[cells] = stats["casters"]
    assert 0 < ref.mean() < 1
    assert kept[lightspace.OCCUPANCY_CELLS] < 0.5 * kept[1]


def _walked_tiles_equal_raytrace(scene, camera, t_days, suns, monkeypatch, crs=False):
    """Receivers of a G-buffer cut into 3 × 3 tiles: each tile's izb answer with its casters
    gathered by the kd-tree walk equals raytrace's, and the walk leaves casters out."""
    surfaces = _surfaces(scene, camera, t_days, "min")
    monkeypatch.setattr(lightspace, "NEAR_MIN_CASTERS", 0)
    monkeypatch.setattr(lightspace, "NEAR_AREA_SHARE", 1.0)
    from cityshade.raster.gbuffer import seen_side_normals

    rows, cols = np.nonzero(surfaces.valid)
    points = surfaces.position_m[rows, cols].astype(np.float64)
    normals = seen_side_normals(surfaces, camera)[rows, cols].astype(np.float64)
    tile = np.minimum(3 * rows // surfaces.valid.shape[0], 2) * 3 + np.minimum(
        3 * cols // surfaces.valid.shape[1], 2)
    n_casters = lightspace.casters_of(scene.kdtree).first.size
    walked = shadowed = 0
    for el, az in suns:
        sun = (sun_from_angles(az, el, scene.crs, scene.origin_m) if crs
               else sun_from_angles(az, el))
        d = np.asarray(sun.direction, np.float64)
        facing = (normals @ d) > 0.0
        for k in range(9):
            sel = (tile == k) & facing
            if not sel.any():
                continue
            origins = shadow_rays_from_surface(points[sel], normals[sel], d)
            ref = occluded(scene.kdtree, origins, np.broadcast_to(d, origins.shape).copy(), t_days)
            stats: dict = {}
            got = lightspace.occluded(scene.kdtree, origins, d, t_days, stats=stats)
            diff = int((got != ref).sum())
            assert diff == 0, f"{diff} rays differ, tile {k}, sun {el}°/{az}°, t={t_days}"
            shadowed += int(ref.sum())
            if 0 <= stats["walked_casters"] < n_casters:
                walked += 1
    assert shadowed > 0, "no shadow at all: the comparison would prove nothing"
    assert walked > 0, "the walk never left a caster out: it was not tested"


@pytest.mark.parametrize("year", ["1750", "1990"])
def test_casters_walked_from_the_tree_for_a_tile_equal_raytrace(sample_scene, year,
                                                                 monkeypatch):
    """A tile's casters gathered by the kd-tree walk (what a tiled batch does on a big city),
    on the sample city at two dates (the walk's time axis), map and overview receivers."""
    from cityshade.geo.temporal import parse_xsd_datetime_days
    from cityshade.raster.camera import map_view, overview

    t = parse_xsd_datetime_days(year)
    _walked_tiles_equal_raytrace(sample_scene, map_view(sample_scene, 1.0), t, SUNS,
                                 monkeypatch)
    _walked_tiles_equal_raytrace(sample_scene, overview(sample_scene, 320, 200), t, SUNS,
                                 monkeypatch)


def test_casters_walked_from_the_tree_equal_raytrace_on_real_lod2(tmp_path_factory,
                                                                   monkeypatch):
    from cityshade.raster.camera import map_view

    scene = _built(shared_file("munich-tum-campus-lod2/TUM Munich.gml"), tmp_path_factory,
                   "tum_walk")
    suns = [(0.5, 100.0), (3.0, 300.0), (10.0, 135.0), (30.0, 200.0), (60.0, 250.0),
            (90.0, 0.0)]
    _walked_tiles_equal_raytrace(scene, map_view(scene, 2.0), 20000.0, suns, monkeypatch,
                                 crs=True)


@pytest.mark.parametrize("parallel_sort_min", [2, 1 << 30])
def test_casters_gathered_in_chunks_are_the_tree_records_once_each_in_key_order(
        tmp_path, monkeypatch, parallel_sort_min):
    """Casters read from a memory-mapped tree a few rows at a time: one row per triangle (its
    first record), sorted by depth key descending, stable, as one gather of all would be;
    with the halves sorted on two threads and merged, and with one sort."""
    from cityshade.accel import KdTree

    monkeypatch.setattr(lightspace, "GATHER_ROWS", 13)
    monkeypatch.setattr(lightspace, "PARALLEL_SORT_MIN", parallel_sort_min)
    tree = build_kdtree(*box_city(40, seed=3, extent_m=100.0))
    for name, arr in tree.to_arrays().items():
        np.save(tmp_path / f"{name}.npy", arr)
    mapped = KdTree.from_arrays({name: np.load(tmp_path / f"{name}.npy", mmap_mode="r")
                                 for name in tree.to_arrays()})
    recs = tree.tri_records
    _, first = np.unique(recs.view(np.int32)[:, lightspace.REC_ID], return_index=True)
    once = recs[np.sort(first)]
    for kz, sgn in ((2, 1.0), (0, -1.0), (2, 1.0)):
        keys = (sgn * once[:, [kz, 3 + kz, 6 + kz]].astype(np.float64)).max(axis=1)
        order = np.argsort(-keys, kind="stable")
        got_recs, got_keys = lightspace.Casters(mapped).sorted_for(kz, sgn)
        # The words the kernels read, and the keys as float32 (exact: float32 coordinates).
        assert got_recs.shape[1] == lightspace.K.CASTER_WORDS < recs.shape[1]
        assert got_recs.tobytes() == np.ascontiguousarray(
            once[order][:, :lightspace.K.CASTER_WORDS]).tobytes()
        assert got_keys.dtype == np.float32
        np.testing.assert_array_equal(got_keys.astype(np.float64), keys[order])


@pytest.mark.parametrize("n", [2, 3, 1000, 70_001])
def test_stable_argsort_is_numpys_stable_argsort(n, monkeypatch):
    """Two halves sorted on two threads and merged: numpy's stable order, ties included (keys
    from a few values, so most are ties; the right half must come after the left on a tie)."""
    import numba

    monkeypatch.setattr(lightspace, "PARALLEL_SORT_MIN", 2)
    keys = np.random.default_rng(n).integers(0, 7, n).astype(np.float64)
    keys[::5] = -np.inf
    threads = numba.get_num_threads()
    try:
        for t in sorted({1, min(2, numba.config.NUMBA_NUM_THREADS)}):
            numba.set_num_threads(t)
            np.testing.assert_array_equal(lightspace.stable_argsort(keys),
                                          np.argsort(keys, kind="stable"))
    finally:
        numba.set_num_threads(threads)


def test_forget_casters_drops_what_the_tree_kept():
    tree = build_kdtree(*box_city(10, seed=2, extent_m=60.0))
    origins = np.random.default_rng(3).uniform(-5, 70, (50, 3))
    d = unit([0.3, -0.4, 0.6])
    first = lightspace.occluded(tree, origins, d)
    assert tree in lightspace._CASTERS
    lightspace.forget_casters(tree)
    assert tree not in lightspace._CASTERS
    np.testing.assert_array_equal(lightspace.occluded(tree, origins, d), first)


def test_cells_numbered_tile_by_tile_are_each_cell_once_and_a_tile_is_one_block():
    """tile_cell maps the nx by ny grid one to one into the padded range, each tile's cells
    to TILE_CELLS consecutive indices (the query's block), rows of tiles in order."""
    from cityshade.lightspace import kernels as K

    for nx, ny in ((1, 1), (7, 3), (8, 8), (17, 9), (64, 33)):
        ntx, n_cells = K.tiled_cells(nx, ny)
        idx = np.array([[K.tile_cell(ix, iy, ntx) for ix in range(nx)] for iy in range(ny)])
        assert len(np.unique(idx)) == nx * ny and idx.min() >= 0 and idx.max() < n_cells
        assert n_cells == -(-nx // K.TILE) * -(-ny // K.TILE) * K.TILE_CELLS
        for iy in range(ny):
            for ix in range(nx):
                tile = (iy // K.TILE) * ntx + ix // K.TILE
                assert idx[iy, ix] // K.TILE_CELLS == tile


def test_tile_order_is_the_stable_order_by_first_tile_for_any_thread_count():
    from reference import reference_tile_order
    from cityshade.lightspace import kernels as K

    rng = np.random.default_rng(8)
    nx, ny, n = 45, 30, 5000
    ntx, n_cells = K.tiled_cells(nx, ny)
    ix0 = rng.integers(0, nx, n)
    iy0 = rng.integers(0, ny, n)
    ranges = np.column_stack([ix0, np.minimum(ix0 + rng.integers(0, 4, n), nx - 1),
                              iy0, np.minimum(iy0 + rng.integers(0, 4, n), ny - 1)])
    want = reference_tile_order(ranges, K.TILE, ntx)
    for n_chunks in (1, 2, 3):
        counts = np.full((n_chunks, n_cells // K.TILE_CELLS), 7, np.int32)
        dest = np.empty(n, np.int32)
        K.tile_order(ranges, ntx, counts, False, dest)
        K.prefix_sum(counts, np.empty(n_cells // K.TILE_CELLS + 1, np.int64))
        K.tile_order(ranges, ntx, counts, True, dest)
        np.testing.assert_array_equal(dest, want)


def test_estimated_references_are_the_box_by_box_sum():
    """The density grid's box sums give the references of every cell size as the box-by-box
    sum does, the culled boxes left out of both, and its caster counts hold the kept boxes."""
    from reference import reference_refs_per_size
    from cityshade.lightspace import kernels as K
    from cityshade.lightspace import refs_per_size

    rng = np.random.default_rng(5)
    x0, y0 = rng.uniform(-50, 50, (2, 400))
    w, h = rng.uniform(0, 9, (2, 400))
    boxes = np.column_stack([x0, x0 + w, y0, y0 + h])
    boxes[::13, 0] = np.nan
    sizes = np.array([0.7, 2.0, 5.5, 30.0])
    xs, ys = rng.uniform(-50, 50, (2, 1000))
    r_c, m_c, box_sums = np.empty((4, 64)), np.empty((4, 64)), np.empty((4, 3))
    K.density_grid(xs, ys, 1, boxes, -60.0, -60.0, 8.0 / 130.0, 8, 8, r_c, m_c, box_sums)
    np.testing.assert_allclose(refs_per_size(box_sums, sizes),
                               reference_refs_per_size(boxes, sizes), rtol=1e-12)
    assert m_c.sum() == np.count_nonzero(~np.isnan(boxes[:, 0])) and r_c.sum() == len(xs)


def test_last_calls_let_the_work_arrays_go_and_answer_the_same(sample_scene):
    """Inside ``lightspace.last_calls`` a call drops its work arrays as it returns (a one-frame
    render's memory) and its sorted casters once packed, and answers as a call outside it
    (twice: the second sorts again); outside, the arrays stay for the next sun. A render with
    ``last_frame`` equals one without."""
    from cityshade.frame.render import render_frame
    from cityshade.raster.camera import map_view

    kd = sample_scene.kdtree
    rng = np.random.default_rng(5)
    lo, hi = kd.bounds[0, :3], kd.bounds[1, :3]
    origins = lo + (hi - lo) * rng.random((4000, 3))
    sun = unit([0.3, -0.5, 0.8])
    kept = lightspace.occluded(kd, origins, sun)
    scratch = lightspace.casters_of(kd).scratch
    assert scratch._arrays                                   # kept for the next sun
    with lightspace.last_calls(sample_scene):
        assert np.array_equal(lightspace.occluded(kd, origins, sun), kept)
        assert not lightspace.casters_ready(kd, *lightspace.caster_order(sun))
        assert np.array_equal(lightspace.occluded(kd, origins, sun), kept)
    assert not scratch._arrays and not lightspace.casters_of(kd)._memory._buffers
    assert np.array_equal(lightspace.occluded(kd, origins, sun), kept)
    assert scratch._arrays
    view = map_view(sample_scene, 2.0)
    s = sun_from_angles(135.0, 30.0)
    frames = [render_frame(sample_scene, view, 19000.0, s, "izb", last_frame=last)
              for last in (False, True)]
    assert np.array_equal(frames[0].lit, frames[1].lit)
    assert np.array_equal(frames[0].rgb, frames[1].rgb)
    assert sample_scene.kdtree not in lightspace._CASTERS
