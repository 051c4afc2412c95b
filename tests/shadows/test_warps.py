"""Perspective warps (psm, lispsm, xpsm): matrix geometry, aliasing against the uniform map,
and full renders against the exact ray-traced shadows."""
from __future__ import annotations

import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground
from reference import reference_convex_hull

from cityshade.config import ShadowSettings
from cityshade.raster import camera as cams
from cityshade.shadows import warps as W

#: Agreement with raytrace required of every technique at default settings (issue 5).
MIN_AGREEMENT = 0.95


def _sun(az_deg, el_deg):
    a, e = math.radians(az_deg), math.radians(el_deg)
    return np.array([math.sin(a) * math.cos(e), math.cos(a) * math.cos(e), math.sin(e)])


def _camera_looking(eye, az_view_deg, down_deg, width_px=320, height_px=200):
    a, e = math.radians(az_view_deg), math.radians(down_deg)
    d = np.array([math.sin(a) * math.cos(e), math.cos(a) * math.cos(e), -math.sin(e)])
    eye = np.asarray(eye, np.float64)
    return cams.perspective(eye, eye + d, vfov_deg=50.0, width_px=width_px,
                            height_px=height_px, near_m=0.5, far_m=600.0)


# --- matrix geometry -------------------------------------------------------------------------

def test_n_opt_matches_the_published_formula_and_its_other_form():
    # Wimmer et al. 2004: n_opt = z_n + sqrt(z_n z_f) at gamma = 90°: 1 + sqrt(100) = 11.
    assert W.lispsm_n_opt(1.0, 100.0, 1.0) == pytest.approx(11.0)
    assert W.lispsm_n_opt(1.0, 100.0, 0.5) == pytest.approx(22.0)
    assert W.lispsm_n_opt(4.0, 9.0, 1.0) == pytest.approx(10.0)
    assert W.lispsm_n_opt(1.0, 100.0, 0.0) == math.inf
    # Their sample code's form d / (sqrt(z_f / z_n) - 1), with z_f = z_n + d sin(gamma).
    z_n, d, sin_g = 3.0, 250.0, 0.7
    assert W.lispsm_n_opt(z_n, z_n + d * sin_g, sin_g) == pytest.approx(
        d / (math.sqrt((z_n + d * sin_g) / z_n) - 1.0))


CAMERA = _camera_looking((0.0, -150.0, 30.0), 0.0, 10.0)
SUNS = {"front": _sun(0.0, 30.0), "behind": _sun(180.0, 30.0), "side": _sun(90.0, 45.0),
        "low_behind": _sun(200.0, 3.0), "high": _sun(10.0, 85.0)}


@pytest.fixture(scope="module")
def focus_points():
    rng = np.random.default_rng(5)
    receivers = rng.uniform([-100.0, -100.0, 0.0], [100.0, 100.0, 30.0], (3000, 3))
    box = np.array([[-100.0, -100.0, 0.0], [100.0, 100.0, 40.0]])
    return receivers, box


@pytest.mark.parametrize("warp", W.WARPS)
@pytest.mark.parametrize("sun_name", sorted(SUNS))
def test_warp_maps_light_rays_to_texels_and_orders_depth_away_from_the_sun(focus_points, warp,
                                                                         sun_name):
    receivers, box = focus_points
    d = SUNS[sun_name]
    casters = W.extrude_to_box(receivers, d, box)
    m, info = W.warp_matrix(warp, CAMERA, d, receivers, casters)
    h_r, h_c = W.apply_h(m, receivers), W.apply_h(m, casters)
    assert (h_r[:, 3] > 0).all() and (h_c[:, 3] > 0).all(), info
    n_r, n_c = W.ndc(m, receivers), W.ndc(m, casters)
    # The receivers fill the map: NDC x, y in [-1, 1] and touching the margin on every side.
    assert np.abs(n_r).max() <= 1.0
    assert n_r[:, 0].min() < -0.99 and n_r[:, 0].max() > 0.99
    assert n_r[:, 1].min() < -0.99 and n_r[:, 1].max() > 0.99
    assert np.abs(n_c[:, 2]).max() <= 1.0
    # A light ray is one texel: its caster end has the receiver's x, y.
    np.testing.assert_allclose(n_c[:, :2], n_r[:, :2], atol=1e-9)
    # Depth grows away from the sun along every ray (sampled at 1/4, 1/2, 3/4 of the way).
    prev = n_c[:, 2]
    for f in (0.25, 0.5, 0.75):
        cur = W.ndc(m, casters + f * (receivers - casters))[:, 2]
        moved = np.linalg.norm(casters - receivers, axis=1) > 1e-6
        assert (cur[moved] > prev[moved]).all(), (warp, sun_name, info)
        prev = cur
    assert (n_r[:, 2][moved] > prev[moved]).all()


def test_psm_light_behind_the_camera_is_inverted_in_front_is_a_point_parallel_is_directional(
        focus_points):
    receivers, box = focus_points
    _, _, fwd = CAMERA.frame()
    assert _sun(180.0, 30.0) @ fwd < 0 < _sun(0.0, 30.0) @ fwd
    for d, kind in ((_sun(180.0, 30.0), "inverted"), (_sun(0.0, 30.0), "point")):
        _, info = W.psm_matrix(CAMERA, d, receivers, W.extrude_to_box(receivers, d, box))
        assert info["light"] == kind
    # A sun in the view plane (perpendicular to the view direction) stays directional.
    side = np.cross(fwd, [0.0, 0.0, 1.0])
    up = np.cross(side, fwd)
    d = (side + up) / np.linalg.norm(side + up)
    _, info = W.psm_matrix(CAMERA, d, receivers, W.extrude_to_box(receivers, d, box))
    assert info["light"] == "directional"


def test_psm_slides_the_virtual_camera_back_behind_casters_behind_the_eye(focus_points):
    receivers, box = focus_points
    cam = _camera_looking((0.0, 0.0, 20.0), 0.0, 15.0)          # in the middle of the points
    ahead = receivers[(receivers - cam.eye_m) @ cam.frame()[2] > 1.0]
    d = _sun(180.0, 20.0)                                       # casters lie behind the eye
    casters = W.extrude_to_box(ahead, d, box)
    assert ((casters - cam.eye_m) @ cam.frame()[2]).min() < 0.0
    m, info = W.psm_matrix(cam, d, ahead, casters)
    assert info["slide_back_m"] > 0.0
    assert (W.apply_h(m, casters)[:, 3] > 0).all()
    assert info["near_m"] / info["far_m"] == pytest.approx(W.WarpSettings().psm_min_near_far)


def test_lispsm_fades_into_the_uniform_map_as_the_view_turns_into_the_light(focus_points):
    receivers, box = focus_points
    _, _, fwd = CAMERA.frame()
    d = -fwd                                  # looking exactly along the light: gamma = 0
    casters = W.extrude_to_box(receivers, d, box)
    m, info = W.lispsm_matrix(CAMERA, d, receivers, casters)
    uniform, _ = W.uniform_matrix(d, receivers, casters, forward=fwd)
    assert info["warp"] == "none"
    np.testing.assert_allclose(m, uniform)
    # A hair away from gamma = 0 the warp exists but barely changes the map.
    side = np.cross(fwd, [0.0, 0.0, 1.0])
    d2 = -fwd * math.cos(1e-4) + side / np.linalg.norm(side) * math.sin(1e-4)
    m2, info2 = W.lispsm_matrix(CAMERA, d2, receivers, W.extrude_to_box(receivers, d2, box))
    assert info2["warp"] == "lispsm"
    u2, _ = W.uniform_matrix(d2, receivers, W.extrude_to_box(receivers, d2, box), forward=fwd)
    assert np.abs(W.ndc(m2, receivers)[:, :2] - W.ndc(u2, receivers)[:, :2]).max() < 0.01
    # ... and the warp grows with gamma: the centre comes closer.
    ns = [W.lispsm_matrix(CAMERA, _sun(180.0, el), receivers,
                          W.extrude_to_box(receivers, _sun(180.0, el), box))[1]["n_m"]
          for el in (20.0, 50.0, 80.0)]
    assert ns[0] > ns[1] > ns[2]


def test_orthographic_cameras_get_the_uniform_map(focus_points):
    receivers, box = focus_points
    cam = cams.Camera("map", 100, 100, np.array([0.0, 0.0, 100.0]), np.array([0.0, 0.0, 0.0]),
                      np.array([0.0, 1.0, 0.0]), 0.0, 0.0, 200.0, pixel_size_m=2.0,
                      x_left_m=-100.0, y_top_m=100.0)
    d = _sun(135.0, 30.0)
    casters = W.extrude_to_box(receivers, d, box)
    uniform, _ = W.uniform_matrix(d, receivers, casters)
    for warp in ("psm", "lispsm", "xpsm"):
        m, info = W.warp_matrix(warp, cam, d, receivers, casters)
        assert info["warp"] == "none"
        np.testing.assert_allclose(m, uniform)


def test_convex_hull_matches_brute_force():
    rng = np.random.default_rng(11)
    for n in (3, 10, 80, 300):
        pts = rng.normal(size=(n, 2))
        pts[: n // 3] = np.round(pts[: n // 3], 1)        # duplicates and collinear runs
        hull = W.convex_hull_2d(pts)
        expected = reference_convex_hull(pts)
        assert {tuple(p) for p in hull} == {tuple(p) for p in expected}
        # Counter-clockwise: positive signed area.
        x, y = hull[:, 0], hull[:, 1]
        assert 0.5 * (x * np.roll(y, -1) - np.roll(x, -1) * y).sum() > 0


def test_convex_hull_of_a_dense_parallelogram_is_its_corners():
    """A dense pixel-like cloud (the octagon filter drops nearly all of it): a 300 × 300
    integer grid sheared into a parallelogram (exact coordinates, so the points on its sides
    are exactly collinear), whose hull is its four corners, counter-clockwise from the
    lowest-leftmost, whatever the order of the points."""
    i, j = np.meshgrid(np.arange(300.0), np.arange(300.0))
    pts = np.c_[(i + j).ravel(), j.ravel()]
    rng = np.random.default_rng(5)
    hull = W.convex_hull_2d(pts[rng.permutation(len(pts))])
    np.testing.assert_array_equal(hull, [[0.0, 0.0], [299.0, 0.0], [598.0, 299.0],
                                         [299.0, 299.0]])


def test_min_area_rectangle_of_a_rotated_rectangle():
    rng = np.random.default_rng(3)
    theta = math.radians(27.0)
    local = rng.uniform([-3.0, -1.0], [3.0, 1.0], (500, 2))
    local[:4] = [[-3, -1], [3, -1], [3, 1], [-3, 1]]             # the corners are in the set
    rot = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    pts = local @ rot.T + [10.0, -4.0]
    angle, area = W.min_area_rectangle(pts)
    assert area == pytest.approx(12.0)
    # The rectangle's sides are at 27° modulo 90°.
    assert min(abs((math.degrees(angle) - 27.0 + 45.0) % 90.0 - 45.0), 1.0) < 1e-9


def test_xpsm_affine_step_does_not_change_the_warp(focus_points):
    """The fit after the warp is affine: ratios of distances along a line are kept, so the
    texel density ratio along the warp direction is the warp's own."""
    receivers, box = focus_points
    d = _sun(90.0, 40.0)
    casters = W.extrude_to_box(receivers, d, box)
    m, info = W.xpsm_matrix(CAMERA, d, receivers, casters)
    assert info["warp"] == "xpsm" and 1.0 < info["warp_ratio"] <= W.WarpSettings().xpsm_max_warp
    # Three collinear points along the warp direction keep the ratio of the projective warp.
    _, y_axis, _ = W.light_basis(d, CAMERA.frame()[2])
    p0 = receivers.mean(axis=0)
    pts = p0 + np.outer([0.0, 10.0, 20.0], y_axis)
    xy = W.ndc(m, pts)[:, :2]
    w = W.apply_h(m, pts)[:, 3]
    # w is the warp's: affine along the warp direction with slope k (the fit left it alone).
    assert w[1] - w[0] == pytest.approx(10.0 * info["k_per_m"], rel=1e-9)
    assert w[2] - w[1] == pytest.approx(10.0 * info["k_per_m"], rel=1e-9)
    # Equal steps under a projective map have lengths ~ 1 / (w_i w_{i+1}); an affine fit keeps
    # the ratio of two collinear steps, so step1 / step2 = w_2 / w_0 exactly.
    step1, step2 = np.linalg.norm(xy[1] - xy[0]), np.linalg.norm(xy[2] - xy[1])
    assert step1 / step2 == pytest.approx(w[2] / w[0], rel=1e-9)
    assert step1 / step2 > 1.0          # nearer (smaller y) gets more texels


# --- aliasing (Lloyd et al.'s m, the core's measure) --------------------------------------------

@pytest.fixture(scope="module")
def grid_city(tmp_path_factory):
    """8 × 8 blocks of 12 × 12 × 15 m on a 300 m square: a deep view for a street camera."""
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("grid")
    src = tmp / "grid.gml"
    blocks = [building(f"b{i}{j}", box_polygons(-140 + 40 * i, -140 + 40 * j, 0, 12, 12, 15,
                                                f"b{i}{j}")) for i in range(8) for j in range(8)]
    src.write_text(city(ground(-150, -150, 150, 150), *blocks))
    out, _, _ = build_file(src, tmp / "grid.cityshade")
    return load_scene(out)


def _context(scene, cam, sun, options=None):
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize
    from cityshade.shadows import ShadowContext

    surfaces = resolve(scene, rasterize(scene, cam, 0.0))
    return ShadowContext(scene, surfaces, cam, sun, 0.0,
                         ShadowSettings().override(**(options or {})))


@pytest.mark.parametrize("sun_az, sun_el", [(0.0, 30.0), (45.0, 20.0), (0.0, 60.0)])
@pytest.mark.parametrize("relation", ["along", "across"])
def test_lispsm_lowers_mean_aliasing_below_uniform_at_equal_map_size(grid_city, sun_az, sun_el,
                                                                     relation):
    from cityshade.shadows import shadowmap as sm
    from cityshade.geo.sun import sun_from_angles

    view_az = sun_az + (180.0 if relation == "along" else 90.0)
    a = math.radians(view_az)
    cam = _camera_looking(np.array([-math.sin(a), -math.cos(a), 0.0]) * 150.0 + [0, 0, 20.0]
                          - grid_city.origin_m,
                          view_az, 8.0)
    ctx = _context(grid_city, cam, sun_from_angles(sun_az, sun_el))
    faces, receivers, _, casters = W.focus(ctx)
    size = 1024
    uniform = sm.aliasing_m(sm.fit_uniform(grid_city, ctx, size), cam, ctx.surfaces, mask=faces)
    m, info = W.lispsm_matrix(cam, ctx.sun.direction, receivers, casters)
    lispsm = sm.aliasing_m(sm.LightView(m, size, size, "lispsm"), cam, ctx.surfaces, mask=faces)
    assert info["warp"] == "lispsm"
    assert lispsm["mean"] < uniform["mean"], (
        f"mean m: lispsm {lispsm['mean']:.3f} >= uniform {uniform['mean']:.3f} "
        f"(gamma {info['gamma_deg']:.1f}°)")


# --- full renders against raytrace --------------------------------------------------------------

def agreement(scene, cam, t_days, sun, technique, options=None):
    """(share of valid pixels where technique and raytrace agree, frame)."""
    from cityshade.frame.render import render_frame

    ref = render_frame(scene, cam, t_days, sun, "raytrace")
    frame = render_frame(scene, cam, t_days, sun, technique,
                         ShadowSettings().override(**(options or {})), measure=True)
    assert not np.isnan(frame.lit).any()
    valid = ref.surfaces.valid
    same = (frame.lit >= 0.5) == (ref.lit >= 0.5)
    return float(same[valid].mean()), frame


def test_psm_with_the_sun_behind_the_camera_matches_raytrace(grid_city):
    from cityshade.geo.sun import sun_from_angles

    # Inside the city (render space is relative to the model's origin), looking north.
    cam = _camera_looking(np.array([-5.0, -30.0, 14.0]) - grid_city.origin_m, 0.0, 12.0)
    sun = sun_from_angles(180.0, 25.0)                         # from the south: behind the eye
    share, frame = agreement(grid_city, cam, 0.0, sun, "psm")
    info = frame.diagnostics.shadow["warp"]
    assert info["light"] == "inverted" and info["slide_back_m"] > 0.0
    assert share >= MIN_AGREEMENT, f"psm agrees with raytrace on {share:.4f} of pixels"
    assert not (frame.lit[frame.surfaces.valid] > 0.5).all()  # some shadow was found


@pytest.fixture(scope="module")
def sample(sample_city_scene):
    return sample_city_scene


@pytest.mark.parametrize("technique", ["psm", "lispsm", "xpsm"])
@pytest.mark.parametrize("view", ["overview", "map"])
def test_sample_city_agrees_with_raytrace(sample, technique, view):
    from cityshade.geo.temporal import parse_user_date
    from cityshade.geo.sun import sun_from_angles

    t = parse_user_date("1990").city_days
    cam = cams.overview(sample, 256, 160) if view == "overview" else cams.map_view(sample, 2.0)
    for el in (5.0, 30.0, 70.0):
        sun = sun_from_angles(135.0, el, sample.crs, sample.origin_m)
        share, frame = agreement(sample, cam, t, sun, technique)
        assert share >= MIN_AGREEMENT, f"{technique} {view} sun {el}°: {share:.4f} agree"
        d = frame.diagnostics.shadow
        assert d["map_px"] and d["texel_m"] > 0 and d["shadow_s"] >= 0
        assert d["aliasing_m"]["max"] >= d["aliasing_m"]["mean"] > 0


def test_night_is_all_shadow(sample):
    from cityshade.frame.render import render_frame
    from cityshade.geo.sun import sun_from_angles

    cam = cams.overview(sample, 64, 40)
    frame = render_frame(sample, cam, 0.0, sun_from_angles(135.0, -5.0), "lispsm")
    assert (frame.lit == 0).all()


def test_parallel_focus_bounds_equal_numpy_over_all_points():
    """ndc_bounds (chunks in parallel, no divide where w is 1) against numpy over every point,
    exactly, for a projective and an orthographic matrix; the focus mean against numpy's
    ``mean(axis=0)``, bit for bit; the finite check against numpy's; point counts that leave
    a short last chunk."""
    rng = np.random.default_rng(11)
    points = rng.normal(0.0, 300.0, (100_003, 3))
    d = _sun(135.0, 30.0)
    m, _ = W.uniform_matrix(d, points, W.extrude_to_box(points, d, np.array(
        [points.min(axis=0), points.max(axis=0)])))
    projective = m.copy()
    projective[3] = [1e-4, -2e-4, 3e-5, 1.0]   # w varies from point to point
    from reference import reference_ndc_bounds

    for n in (1, 7, 64, 65, 100_003):
        for matrix in (m, projective):
            wmin, lo, hi = W.ndc_bounds(matrix, points[:n])
            w_ref, lo_ref, hi_ref = reference_ndc_bounds(matrix, points[:n])
            assert wmin == w_ref
            assert lo.tolist() == lo_ref.tolist() and hi.tolist() == hi_ref.tolist()
        assert W._mean_point(points[:n]).tolist() == points[:n].mean(axis=0).tolist()
    assert W._all_finite(points)
    for bad in (np.nan, np.inf, -np.inf):
        p = points.copy()
        p[77_777, 2] = bad
        assert not W._all_finite(p)
