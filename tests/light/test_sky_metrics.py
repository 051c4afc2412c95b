"""Sky view factor and vertical sky component against closed forms and published values, the
visibility bits of both exact engines, and the receivers of openings and maps."""
from __future__ import annotations

import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city
from conftest import shared_file

from cityshade.light import (DEFAULT_SKY, named_sky, polygon_reference_points, sky_view_factor,
                             sky_visibility, vertical_sky_component)


def _build(tmp_path, *members, name="m.gml"):
    from cityshade.build import build_scene_from_file

    path = tmp_path / name
    path.write_text(city(*members))
    return build_scene_from_file(path)


def _render(scene, world_points):
    return np.asarray(world_points, np.float64) - scene.origin_m


H_M = W_M = 10.0


@pytest.fixture(scope="module")
def canyon(tmp_path_factory):
    """Two 10 m high, 400 m (40 H) long blocks along y, 10 m apart (H/W = 1)."""
    tmp = tmp_path_factory.mktemp("canyon")
    long_m = 40 * H_M
    west = building("W", box_polygons(-W_M / 2 - 10, -long_m / 2, 0.0, 10.0, long_m, H_M, "w"))
    east = building("E", box_polygons(W_M / 2, -long_m / 2, 0.0, 10.0, long_m, H_M, "e"))
    return _build(tmp, west, east)


def test_street_canyon_floor_takes_oke_s_sky_view_factor(canyon):
    """SVF at the floor centre of a long canyon = cos(arctan(2H/W)) (Oke 1988): 0.447 for
    H/W = 1; with the sky laid out around a north 30° off the canyon's axis as well."""
    expected = math.cos(math.atan(2 * H_M / W_M))
    assert round(expected, 3) == 0.447
    for gamma in (0.0, 30.0):
        sky = named_sky(DEFAULT_SKY, gamma)
        vis = sky_visibility(canyon, _render(canyon, [[0.0, 0.0, 0.0]]), [[0.0, 0.0, 1.0]], sky)
        assert sky_view_factor(vis)[0] == pytest.approx(expected, abs=0.005)


def test_open_ground_and_a_free_wall(canyon):
    sky = named_sky()
    # A roof point with nothing above it: open horizontal ground.
    vis = sky_visibility(canyon, _render(canyon, [[-10.0, 0.0, H_M]]), [[0.0, 0.0, 1.0]], sky)
    assert vis.visible().all()
    assert sky_view_factor(vis)[0] == pytest.approx(1.0, abs=1e-9)
    # The outer walls of the canyon see nothing of the city: half the sky. The east-facing
    # wall's plane cuts the patches centred on north and south through their centres.
    pts = _render(canyon, [[-W_M / 2 - 10, 0.0, 5.0], [W_M / 2 + 10, 0.0, 5.0],
                           [-10.0, -20 * H_M, 5.0]])
    nrm = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]]
    for name in ("tregenza", DEFAULT_SKY):
        svf = sky_view_factor(sky_visibility(canyon, pts, nrm, named_sky(name)))
        np.testing.assert_allclose(svf, 0.5, atol=0.005)
    # Inside the canyon, a wall's foot sees less than half.
    inner = sky_visibility(canyon, _render(canyon, [[-W_M / 2, 0.0, 0.5]]), [[1.0, 0.0, 0.0]],
                           sky)
    assert sky_view_factor(inner)[0] < 0.4


@pytest.fixture(scope="module")
def windows(tmp_path_factory):
    """A 20 x 10 x 20 m house whose south wall holds the window centre at (0, 0, 5), and the
    long obstructions south of it (2 km along the window, 20 m away) that subtend 25° and 45°
    above the window centre at right angles to the window."""
    tmp = tmp_path_factory.mktemp("vsc")
    house = building("H", box_polygons(-10.0, 0.0, 0.0, 20.0, 10.0, 20.0, "h"))
    scenes = {None: _build(tmp, house, name="free.gml")}
    for angle in (25, 45):
        top = 5.0 + 20.0 * math.tan(math.radians(angle))
        block = building(f"B{angle}", box_polygons(-1000.0, -30.0, 0.0, 2000.0, 10.0, top, "b"))
        scenes[angle] = _build(tmp, house, block, name=f"b{angle}.gml")
    return scenes


@pytest.mark.parametrize("angle,published_pct", [(None, 39.6), (25, 27.3), (45, 15.4)])
def test_vertical_sky_component_of_bre209(windows, angle, published_pct):
    """BRE 209: 39.6 % for an unobstructed vertical window (its maximum), 27.3 % facing a long
    obstruction at 25° (the case the 27 % criterion comes from), 15.4 % at 45°."""
    scene = windows[angle]
    vis = sky_visibility(scene, _render(scene, [[0.0, 0.0, 5.0]]), [[0.0, -1.0, 0.0]],
                         named_sky())
    assert 100 * vertical_sky_component(vis)[0] == pytest.approx(published_pct, abs=0.2)


def test_reference_point_of_a_polygon_is_its_centre_on_the_outer_face(windows):
    scene = windows[None]
    south = scene.poly_ids.index("hs")
    pts, nrm = polygon_reference_points(scene, [(south,), ()])
    np.testing.assert_allclose(pts[0] + scene.origin_m, [0.0, 0.0, 10.0], atol=1e-4)
    np.testing.assert_allclose(nrm[0], [0.0, -1.0, 0.0], atol=1e-6)
    assert np.isnan(pts[1]).all()


def _assert_same_bits(scene, points, normals, sky, t_days):
    a = sky_visibility(scene, points, normals, sky, t_days, engine="izb")
    b = sky_visibility(scene, points, normals, sky, t_days, engine="raytrace", block=8)
    np.testing.assert_array_equal(a.bits, b.bits)
    seen = a.visible()
    assert 0.05 < seen.mean() < 0.95           # a real mix of seen and blocked directions
    return a


def test_engines_give_the_same_bits_on_the_sample_city(sample_city_scene):
    from cityshade.frame.pipeline import camera_pass
    from cityshade.geo.temporal import parse_user_date
    from cityshade.light import map_receivers
    from cityshade.raster.camera import map_view
    from cityshade.sunhours.surfaces import sample_surfaces

    scene = sample_city_scene
    t = parse_user_date("1990").city_days
    sky = named_sky("tregenza")
    cp = camera_pass(scene, map_view(scene, 6.0), t)
    points, normals, pixels = map_receivers(cp)
    assert len(pixels) > 500 and np.isfinite(points).all()
    vis = _assert_same_bits(scene, points, normals, sky, t)
    svf = sky_view_factor(vis)
    assert ((svf > 0.0) & (svf <= 1.0 + 1e-9)).all() and svf.min() < 0.9
    samples = sample_surfaces(scene, 0.05, t)
    rows = np.random.default_rng(0).choice(samples.n, min(samples.n, 1500), replace=False)
    _assert_same_bits(scene, samples.points_m[rows], samples.normals[rows], sky, t)


def test_packed_bits_equal_the_obvious_gather_and_pack(sample_city_scene):
    """The per-direction kernels (rays of the receivers in front, answers straight into the
    packed bits) against the twin that gathers, traces and packs with numpy."""
    from reference import reference_sky_bits

    from cityshade.sunhours.surfaces import sample_surfaces

    scene = sample_city_scene
    t = 7_300.0
    samples = sample_surfaces(scene, 0.05, t)
    rows = np.random.default_rng(2).choice(samples.n, min(samples.n, 1200), replace=False)
    pts, nrm = samples.points_m[rows], samples.normals[rows]
    sky = named_sky("tregenza")                # 145 directions: a partial last byte
    for engine in ("izb", "raytrace"):
        vis = sky_visibility(scene, pts, nrm, sky, t, engine=engine, block=40)
        want = reference_sky_bits(scene, pts, nrm, sky, t, engine)
        np.testing.assert_array_equal(vis.bits, want)
        assert 0.05 < vis.visible().mean() < 0.95


@pytest.mark.parametrize("luminance", ["uniform", "cie"])
def test_patch_weights_equal_the_definition_subsample_by_subsample(luminance):
    """The kernel's rows (whole patches as n · Σ lw d, wholly hidden ones skipped, cut patches
    summed and moved to the nearest front centre) against every subsample of every patch, for
    a horizontal roof, free walls, tilted roofs and random planes, and the same row whatever
    other normals are computed with it."""
    from reference import reference_patch_weights

    from cityshade.light.metrics import (cie_overcast_luminance, distinct_normals,
                                         patch_weights, uniform_luminance)
    from cityshade.light.sky import named_sky

    lum = uniform_luminance if luminance == "uniform" else cie_overcast_luminance
    sky = named_sky("tregenza")
    rng = np.random.default_rng(5)
    special = [[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.6, 0.0, 0.8],
               [0.0, -0.5, -np.sqrt(0.75)], [0.0, 0.0, -1.0]]
    normals = np.vstack([special, rng.normal(size=(24, 3))])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    weights, inverse = patch_weights(sky, normals, lum, k=4)
    unique, _ = distinct_normals(normals)
    unit = unique / np.linalg.norm(unique, axis=1, keepdims=True)
    want = reference_patch_weights(sky, unit, 4, lum)
    np.testing.assert_allclose(weights, want, rtol=1e-12, atol=1e-15)
    assert (weights[inverse[5]] == 0.0).all()           # a downward face sees no sky
    alone, inv_alone = patch_weights(sky, normals[7:8], lum, k=4)
    np.testing.assert_array_equal(alone[inv_alone[0]], weights[inverse[7]])


def test_weighted_sums_equal_the_plain_loop_and_do_not_depend_on_the_other_rows():
    """The kernel adding each receiver's visible weights from the packed bits equals the twin's
    plain loop exactly, and a receiver's sum is the same computed alone, in any subset or
    order: what makes a tiled sky run equal an untiled one."""
    from reference import reference_visible_weight_sums

    from cityshade.light.kernels import visible_weight_sums

    rng = np.random.default_rng(5)
    n, p, u = 257, 145, 7                    # 145 directions: a partial last byte
    bits = np.packbits(rng.random((n, p)) < 0.6, axis=1)
    weights = rng.random((u, p)) * 1e-2
    inverse = rng.integers(0, u, n).astype(np.int64)
    out = np.zeros(n)
    visible_weight_sums(bits, inverse, weights, out)
    np.testing.assert_array_equal(out, reference_visible_weight_sums(bits, inverse, weights))
    for rows in (np.arange(3, 40), rng.permutation(n)[:101], np.array([n - 1])):
        part = np.zeros(len(rows))
        visible_weight_sums(np.ascontiguousarray(bits[rows]), inverse[rows], weights, part)
        np.testing.assert_array_equal(part, out[rows])


@pytest.mark.parametrize("threads", [1, 2])
def test_front_rays_and_bits_in_chunks_equal_one_pass_over_the_receivers(threads):
    """More receivers than a thread's chunk (three chunks): the rays of the receivers in front
    are those of one numpy pass in receiver order, with the same float64 origins, and the
    answers land in the bits numpy's pack gives, whatever the threads (the bits are held and
    put in chunks on the kernel threads), other bits untouched."""
    import numba

    from cityshade.light.kernels import RECEIVER_CHUNK, front_origins, hold_visible, put_held
    from cityshade.light.sky import FRONT_MIN_COS
    from cityshade.trace import SHADOW_OFFSET_MIN_SCALE_M, SHADOW_OFFSET_REL

    rng = np.random.default_rng(11)
    n = 2 * RECEIVER_CHUNK + 4321
    pts = rng.uniform(-800.0, 800.0, (n, 3))
    nrm = rng.normal(size=(n, 3))
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    d = np.array([0.3, -0.5, 0.81])
    d /= np.linalg.norm(d)
    rows, origins = np.empty(n, np.int64), np.empty((n, 3))
    before = numba.get_num_threads()
    numba.set_num_threads(threads)
    try:
        k = front_origins(pts, nrm, d, FRONT_MIN_COS, SHADOW_OFFSET_REL,
                          SHADOW_OFFSET_MIN_SCALE_M, rows, origins)
        want = np.flatnonzero((nrm[:, 0] * d[0] + nrm[:, 1] * d[1]) + nrm[:, 2] * d[2]
                              > FRONT_MIN_COS)
        assert 0 < k == len(want) < n
        np.testing.assert_array_equal(rows[:k], want)
        scale = SHADOW_OFFSET_REL * np.maximum(np.abs(pts[want]).max(axis=1),
                                               SHADOW_OFFSET_MIN_SCALE_M)
        np.testing.assert_array_equal(origins[:k], pts[want] + (nrm[want] + d) * scale[:, None])
        # Eight directions' answers held, then put in columns of three bytes, out of order.
        columns = [141, 7, 8, 143, 9, 0, 140, 142]
        other = rng.random((n, 152)) < 0.3       # bits of other directions, kept
        other[:, columns] = False
        bits = np.packbits(other, axis=1)
        held = np.zeros(n, np.uint8)
        want_bits = other.copy()
        for slot, c in enumerate(columns):
            blocked = rng.random(k) < 0.4
            hold_visible(held, rows[:k], blocked, slot)
            want_bits[want[~blocked], c] = True
        put_held(bits, held, columns)
        np.testing.assert_array_equal(bits, np.packbits(want_bits, axis=1))
        assert not held.any()
    finally:
        numba.set_num_threads(before)


@pytest.mark.parametrize("relative", ["berlin-lichtenberg-trees/lod2_buildings_berlin_test_area.gml",
                                      "munich-tum-campus-lod2/TUM Munich.gml"])
def test_engines_give_the_same_bits_on_real_buildings(relative):
    from cityshade.build import build_scene_from_file
    from cityshade.geo.sun import sun_from_angles
    from cityshade.light import sky_for_scene
    from cityshade.sunhours.surfaces import sample_surfaces

    scene = build_scene_from_file(shared_file(relative))
    sky = sky_for_scene(scene, "tregenza")
    # The sky is turned like the sun: by the meridian convergence at the origin.
    assert sky.convergence_deg == sun_from_angles(0.0, 30.0, scene.crs,
                                                  scene.origin_m).convergence_deg
    assert sky.convergence_deg != 0.0
    t = 20_000.0
    samples = sample_surfaces(scene, 0.05, t)
    rows = np.random.default_rng(1).choice(samples.n, min(samples.n, 2000), replace=False)
    _assert_same_bits(scene, samples.points_m[rows], samples.normals[rows], sky, t)


def test_bad_requests(canyon):
    from cityshade.errors import UsageError

    with pytest.raises(UsageError, match="izb or raytrace"):
        sky_visibility(canyon, [[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]], named_sky("tregenza"),
                       engine="shadowmap")
    with pytest.raises(UsageError, match="multiple of 8"):
        sky_visibility(canyon, [[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]], named_sky("tregenza"),
                       block=12)
    vis = sky_visibility(canyon, np.zeros((0, 3)), np.zeros((0, 3)), named_sky("tregenza"))
    assert vis.bits.shape == (0, 19) and sky_view_factor(vis).shape == (0,)


def test_distinct_normals_equal_numpy_s_unique_rows():
    from cityshade.light.metrics import NORMAL_ROUND, distinct_normals

    rng = np.random.default_rng(3)
    n = rng.normal(size=(5000, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    axes = np.array([[0, 0, 1], [0, 0, -1], [1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]], float)
    walls = n[:50] + rng.normal(scale=1e-7, size=(50, 3))   # float32-like scatter: merges
    # Runs of equal rows too (a map's neighbouring pixels), which the sort skips over.
    normals = np.concatenate([n, axes, axes + 3e-8, walls, n[:50], np.repeat(n[:300], 4, 0)])
    unique, inverse = distinct_normals(normals)
    want_u, want_inv = np.unique(np.round(normals / NORMAL_ROUND) * NORMAL_ROUND, axis=0,
                                 return_inverse=True)
    np.testing.assert_array_equal(unique, want_u)
    np.testing.assert_array_equal(inverse, want_inv.reshape(-1))
    assert len(unique) < len(normals)


@pytest.mark.parametrize("name", ["tregenza", "reinhart577", "reinhart2305"])
def test_directions_are_traced_grouped_by_the_casters_key_order(name):
    """izb sorts its casters again at each change of key order: the tracing order visits each
    direction once and changes order only between the hemisphere's five groups (Tregenza's own
    band order changes it 21 times), keeping the sky's order inside a group."""
    from cityshade.light.visibility import direction_order
    from cityshade.lightspace import caster_order

    dirs = named_sky(name).directions
    order = direction_order(dirs)
    assert sorted(order.tolist()) == list(range(len(dirs)))
    keys = [caster_order(dirs[i]) for i in order]
    changes = sum(a != b for a, b in zip(keys[:-1], keys[1:]))
    assert changes == len(set(keys)) - 1 <= 4
    for key in set(keys):
        inside = [i for i, k in zip(order, keys) if k == key]
        assert inside == sorted(inside)
