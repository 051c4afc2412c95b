"""Shadow maps: the light-space depth pass against a ray-cast twin, fitting, projections and
measures against analytic values, bias (acne and peter-panning) at a 3° sun, VSM light
bleeding, and every map technique against ``raytrace`` on the sample city."""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground
from reference import reference_depth_map

from cityshade.build import build_file
from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.config import ShadowSettings
from cityshade.errors import UsageError
from cityshade.raster import camera as cams
from cityshade.frame.render import render_frame
from cityshade.store.scenefile import load_scene
from cityshade.shadows import ShadowContext, facing_sun, get_technique
from cityshade.shadows import shadowmap as sm
from cityshade.geo.sun import sun_from_angles

T_1990 = 7305.0          # 1990-01-01 in days since 1970 (the sample city stands then)
MAP_TECHNIQUES = ("shadowmap", "pcf", "vsm")


def _build(tmp_path_factory, name, *members, half=150):
    tmp = tmp_path_factory.mktemp(name)
    src = tmp / f"{name}.gml"
    src.write_text(city(ground(-half, -half, half, half), *members))
    out, _, _ = build_file(src, tmp / f"{name}.cityshade")
    return load_scene(out)


@pytest.fixture(scope="module")
def sample(sample_city_scene):
    return sample_city_scene


@pytest.fixture(scope="module")
def one_box(tmp_path_factory):
    """A 10 × 10 × 20 m box on a 300 × 300 m plane."""
    return _build(tmp_path_factory, "box", building("b", box_polygons(-5, -5, 0, 10, 10, 20, "b")))


def _soup(seed=11, n=30):
    """A tiny scene without kd-tree: random triangles in a 20 m cube, one absent at t = 0."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-8, 8, (n, 1, 3))
    verts = (centres + rng.normal(0, 3, (n, 3, 3))).reshape(-1, 3).astype(np.float32)
    begin = np.zeros(n)
    begin[3] = 10.0
    return SimpleNamespace(vertices=verts, triangles=np.arange(3 * n, dtype=np.int32).reshape(n, 3),
                           tri_t_begin_days=begin, tri_t_end_days=np.full(n, np.inf), kdtree=None)


def _compare_with_twin(scene, view):
    dm = sm.render_depth_map(scene, view, 0.0)
    depth, prim = reference_depth_map(scene.vertices, scene.triangles, scene.tri_t_begin_days,
                                      scene.tri_t_end_days, view.clip_from_world,
                                      view.width_px, view.height_px)
    same = dm.prim_id == prim
    # Texel centres exactly on a shared edge may go either way in the twin (its edges are
    # closed): allow a handful of texels, never more.
    assert same.mean() >= 0.99, f"{(~same).sum()} of {same.size} texels differ"
    both = same & (prim >= 0)
    assert both.sum() > 0.1 * same.size
    np.testing.assert_allclose(dm.depth[both], depth[both], atol=2e-6)
    assert np.isinf(dm.depth[dm.prim_id < 0]).all()
    return dm


def test_depth_map_matches_ray_cast_twin_orthographic():
    scene = _soup()
    view = sm.ortho_view(sun_from_angles(200.0, 35.0).direction, (-14, 14), (-12, 12),
                         (-40, 40), 40, 32)
    dm = _compare_with_twin(scene, view)
    assert 3 not in set(dm.prim_id.ravel())          # absent at t = 0: never drawn
    assert dm.stats["casters_drawn"] == 29


def test_depth_map_matches_ray_cast_twin_projective():
    scene = _soup(seed=12)
    cam = cams.perspective([12.0, -15.0, 20.0], [0.0, 0.0, 0.0], vfov_deg=60, width_px=36,
                           height_px=28, near_m=5.0, far_m=120.0)
    view = sm.LightView(cam.clip_from_world(), 36, 28, "test")
    _compare_with_twin(scene, view)


def test_depth_map_culled_equals_unculled(sample):
    sun = sun_from_angles(135.0, 30.0)
    box = sm.scene_bounds(sample)
    centre = box.mean(axis=0)
    right, up, fwd = sm.light_basis(sun.direction)
    # A view over the middle third of the city: the walk has something to cull.
    half = 0.2 * float(np.max(box[1] - box[0]))
    c = centre @ np.stack([right, up], axis=1)
    view = sm.ortho_view(sun.direction, (c[0] - half, c[0] + half), (c[1] - half, c[1] + half),
                         (-500, 500), 256, 256)
    culled = sm.render_depth_map(sample, view, T_1990)
    full = sm.render_depth_map(sample, view, T_1990, culling=False)
    assert culled.stats["culling"] == "kd-tree walk"
    assert culled.stats["frustum_refs_removed"] > 0
    np.testing.assert_array_equal(culled.prim_id, full.prim_id)
    np.testing.assert_array_equal(culled.depth, full.depth)
    # Restricting casters to a box: every caster meeting the box is drawn (others may be,
    # culling is per kd-tree node), so where the full map's nearest caster meets the box the
    # restricted map has the same caster.
    cb = np.array([[centre[0] - 30, centre[1] - 30, box[0, 2]], [centre[0], centre[1], box[1, 2]]])
    part = sm.render_depth_map(sample, view, T_1990, casters_box=cb)
    corners = sample.vertices[sample.triangles[np.maximum(full.prim_id, 0)]]
    meets = ((full.prim_id >= 0) & (corners.min(axis=2) >= cb[0]).all(axis=-1)
             & (corners.max(axis=2) <= cb[1]).all(axis=-1))      # casters inside the box
    assert meets.sum() > 300
    np.testing.assert_array_equal(part.prim_id[meets], full.prim_id[meets])
    assert part.stats["casters_drawn"] < full.stats["casters_drawn"]


def test_depth_pass_skips_the_walk_when_the_view_holds_most_of_the_model(sample, monkeypatch):
    """inside_share against a count by hand, and a view holding the whole city but for a
    sliver of one side goes linear (the same map as the walk's)."""
    from cityshade.raster import depthpass as dp

    sun = sun_from_angles(135.0, 30.0)
    right, up, fwd = sm.light_basis(sun.direction)
    light = sample.vertices.astype(np.float64) @ np.stack([right, up], axis=1)
    lo, hi = light.min(axis=0), light.max(axis=0)
    cut = lo[0] + 0.1 * (hi[0] - lo[0])              # the view leaves out 10 % of the width
    view = sm.ortho_view(sun.direction, (cut, hi[0] + 1), (lo[1] - 1, hi[1] + 1), (-2000, 2000),
                         192, 192)
    planes = dp.frustum_planes(view.clip_from_world, 0.0)
    step = max(1, sample.vertices.shape[0] // dp.INSIDE_SAMPLES)
    want = float((light[::step, 0] >= cut).mean())
    assert 0.5 < dp.inside_share(sample.vertices, planes) == pytest.approx(want, abs=0.02)
    assert want >= dp.LINEAR_INSIDE_SHARE
    linear = sm.render_depth_map(sample, view, T_1990)
    assert linear.stats["culling"] == "most of the model lies inside the light view"
    monkeypatch.setattr(dp, "LINEAR_INSIDE_SHARE", 2.0)       # the walk, always
    walked = sm.render_depth_map(sample, view, T_1990)
    assert walked.stats["culling"] == "kd-tree walk" and walked.stats["frustum_refs_removed"]
    np.testing.assert_array_equal(linear.prim_id, walked.prim_id)
    np.testing.assert_array_equal(linear.depth, walked.depth)


def _context(scene, cam, sun, t=0.0, options=None):
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize

    surfaces = resolve(scene, rasterize(scene, cam, t))
    return ShadowContext(scene=scene, surfaces=surfaces, camera=cam, sun=sun, t_days=t,
                         settings=ShadowSettings().override(**(options or {})))


def test_fit_uniform_covers_receivers_and_casters(sample):
    cam = cams.overview(sample, 200, 120)
    sun = sun_from_angles(135.0, 20.0)
    ctx = _context(sample, cam, sun, T_1990)
    view = sm.fit_uniform(sample, ctx, (300, 200), pad_px=3)
    _, faces = facing_sun(ctx.surfaces, cam, sun.direction)
    u, v, z = sm.project(view, ctx.surfaces.position_m[faces])
    # Tight across the rays: the receivers span the map minus the padding on each side.
    assert u.min() == pytest.approx(3.0, abs=1e-6) and u.max() == pytest.approx(297.0, abs=1e-6)
    assert v.min() == pytest.approx(3.0, abs=1e-6) and v.max() == pytest.approx(197.0, abs=1e-6)
    assert z.max() < 1.0 and z.min() > -1.0
    # Every scene point is at or behind the near plane (casters are never clamped).
    _, _, zs = sm.project(view, sample.vertices.astype(np.float64))
    assert zs.min() >= -1.0


def test_project_and_texel_measures_analytic(one_box):
    el, az = 40.0, 210.0
    sun = sun_from_angles(az, el)
    view = sm.ortho_view(sun.direction, (-10, 10), (-10, 10), (-100, 100), 100, 100)
    right, up, fwd = sm.light_basis(sun.direction)
    # The point at light coordinates (x, y) = (3, -5) lands at texel (65, 75).
    p = 3.0 * right - 5.0 * up + 7.0 * fwd
    u, v, z = sm.project(view, p[None])
    assert (u[0], v[0]) == pytest.approx((65.0, 75.0))
    assert z[0] == pytest.approx(7.0 / 100.0)
    # Texel 0.2 m across the rays; on the ground it stretches to 0.2 / sin(el) along the sun.
    assert sm.texel_footprint_m(view, p[None], sun.direction)[0] == pytest.approx(0.2)
    assert sm.texel_footprint_m(view, p[None], [0, 0, 1.0])[0] == pytest.approx(
        0.2 / math.sin(math.radians(el)))
    assert sm.metres_per_ndc(view) == pytest.approx(100.0)


def test_aliasing_measure_analytic(one_box):
    """Map camera with 0.5 m pixels, sun at the zenith, 0.25 m texels: one texel is half a
    pixel (m = 0.5); with 2 m texels, m = 4."""
    cam = cams.map_view(one_box, 0.5)
    sun = sun_from_angles(0.0, 90.0)
    ctx = _context(one_box, cam, sun)
    for texel, m in ((0.25, 0.5), (2.0, 4.0)):
        n = 200
        view = sm.ortho_view(sun.direction, (-n * texel / 2, n * texel / 2),
                             (-n * texel / 2, n * texel / 2), (-100, 100), n, n)
        a = sm.aliasing_m(view, cam, ctx.surfaces)
        assert a["max"] == pytest.approx(m, rel=1e-6) and a["mean"] == pytest.approx(m, rel=1e-6)


def test_aliasing_measure_of_gathered_seen_side_normals_is_the_same(sample):
    """The techniques hand ``aliasing_m`` their gathered receivers, whose normals are turned to
    the seen side: m is the same, bit for bit, as from the G-buffer's own normals, for any
    normal turned (here all of them, and those the seen side turns)."""
    from cityshade.shadows import gather_pixels, oriented_normals

    for cam in (cams.overview(sample, 200, 120), cams.map_view(sample, 2.0)):
        sun = sun_from_angles(240.0, 15.0)
        ctx = _context(sample, cam, sun)
        view = sm.fit_uniform(sample, ctx, 256)
        valid = np.asarray(ctx.surfaces.valid)
        points = gather_pixels(ctx.surfaces.position_m, valid)
        normals = gather_pixels(ctx.surfaces.normal, valid)
        a = sm.aliasing_m(view, cam, ctx.surfaces)
        assert a["pixels"] > 1000
        for turned in (-normals, gather_pixels(oriented_normals(ctx.surfaces, cam), valid)):
            assert sm.aliasing_m(view, cam, ctx.surfaces, points_m=points,
                                 normals=turned) == a


@pytest.mark.parametrize("kind", ["overview", "map"])
@pytest.mark.parametrize("el", [5.0, 30.0, 70.0])
def test_techniques_agree_with_raytrace(sample, kind, el):
    cam = cams.overview(sample, 256, 160) if kind == "overview" else cams.map_view(sample, 2.0)
    sun = sun_from_angles(135.0, el)
    ref = render_frame(sample, cam, T_1990, sun, "raytrace")
    valid = ref.surfaces.valid
    for name in MAP_TECHNIQUES:
        frame = render_frame(sample, cam, T_1990, sun, name, measure=True)
        assert np.isfinite(frame.lit).all()
        agree = ((frame.lit[valid] >= 0.5) == (ref.lit[valid] >= 0.5)).mean()
        assert agree >= 0.95, f"{name}: {100 * agree:.2f} % of pixels agree with raytrace"
        d = frame.diagnostics.shadow
        assert d["map_px"] == [(2048, 2048)] and d["texel_m"] > 0 and d["shadow_s"] > 0
        assert 0 < d["aliasing_m"]["mean"] <= d["aliasing_m"]["max"]


@pytest.mark.parametrize("name", ["shadowmap+smooth", "vsm+smooth"])
def test_smoothed_techniques(sample, name):
    cam = cams.overview(sample, 256, 160)
    sun = sun_from_angles(135.0, 30.0)
    ref = render_frame(sample, cam, T_1990, sun, "raytrace")
    frame = render_frame(sample, cam, T_1990, sun, name)
    valid = ref.surfaces.valid
    assert np.isfinite(frame.lit).all() and frame.lit.min() >= 0 and frame.lit.max() <= 1
    agree = ((frame.lit[valid] >= 0.5) == (ref.lit[valid] >= 0.5)).mean()
    assert agree >= 0.95, f"{name}: {100 * agree:.2f} %"
    _, faces = facing_sun(frame.surfaces, cam, sun.direction)
    assert (frame.lit[valid & ~faces] == 0).all()          # the shared rule still holds
    assert frame.diagnostics.shadow["technique"] == name
    # Smoothing made some edge pixels fractional.
    assert ((frame.lit > 0.02) & (frame.lit < 0.98)).sum() > 10
    with pytest.raises(UsageError, match="unknown shadow technique"):
        get_technique("nope+smooth")


def test_bias_no_acne_no_gap_at_3_degrees(one_box):
    """Sun at 3°: sunlit faces are lit on ≥ 99.9 % of their pixels (no acne) and the ground
    shadow starts at the wall (no gap wider than 2 texels: no peter-panning)."""
    az, el = 200.0, 3.0
    sun = sun_from_angles(az, el)
    views = [cams.overview(one_box, 320, 200),
             cams.perspective([-40.0, -60.0, 12.0], [0.0, 0.0, 6.0], vfov_deg=50, width_px=320,
                              height_px=200, scene=one_box)]
    for cam in views:
        ref = render_frame(one_box, cam, 0.0, sun, "raytrace")
        frame = render_frame(one_box, cam, 0.0, sun, "shadowmap")
        sunlit = ref.lit > 0.5
        walls = sunlit & (ref.surfaces.cls == SURFACE_CODE["wall"])
        assert walls.sum() > 50
        share = (frame.lit[sunlit] > 0.5).mean()
        assert share >= 0.999, f"only {100 * share:.3f} % of sunlit pixels lit (acne)"
    # Along the shadow direction from the box centre on a 0.25 m map.
    px = 0.25
    cam = cams.map_view(one_box, px, bbox=(-40, -40, 40, 40))
    frame = render_frame(one_box, cam, 0.0, sun, "shadowmap", measure=True)
    texel = frame.diagnostics.shadow["texel_light_m"]
    d = -np.array([math.sin(math.radians(az)), math.cos(math.radians(az))])
    exit_m = 5.0 / max(abs(d[0]), abs(d[1]))             # the wall, box half-size 5 m
    first = None
    for s in np.arange(exit_m, 39.0, px / 8):
        x, y = s * d
        col = int(math.floor((x - cam.x_left_m) / px))
        row = int(math.floor((cam.y_top_m - y) / px))
        if frame.surfaces.cls[row, col] == SURFACE_CODE["landuse"]:
            if frame.lit[row, col] < 0.5:
                first = s
                break
    assert first is not None
    gap = first - exit_m
    assert gap <= 2 * texel + px, f"shadow starts {gap:.3f} m from the wall (texel {texel:.3f} m)"


@pytest.fixture(scope="module")
def stacked(tmp_path_factory):
    """Two plates south of a strip of ground, both shading it with the sun in the south at
    45°: a wide one 4 m up and a narrow one (x in [-5, 5]) 30 m up."""
    low = box_polygons(-15, -24, 4, 30, 20, 0.2, "l")
    high = box_polygons(-5, -34, 30, 10, 8, 0.2, "h")
    return _build(tmp_path_factory, "stacked", building("low", low), building("high", high),
                  half=60)


def test_vsm_light_bleeding_and_its_reduction(stacked):
    """On the ground strip y in [-3, -1] both plates are in the way. Across the upper plate's
    edges (x = ±5) the filtered moments mix two caster depths 26 m apart and Chebyshev's bound
    lets light through although the lower plate shadows everything (light bleeding).
    Bleeding reduction removes most of it; the hard map has none."""
    cam = cams.map_view(stacked, 0.1, bbox=(-10, -4, 10, 2))
    sun = sun_from_angles(180.0, 45.0)
    ref = render_frame(stacked, cam, 0.0, sun, "raytrace")
    s = ref.surfaces
    y = s.position_m[..., 1]
    strip = (s.cls == SURFACE_CODE["landuse"]) & (y > -3.0) & (y < -1.0)
    assert strip.sum() > 3000 and (ref.lit[strip] == 0).all()
    opts = {"map_px": 512, "vsm_blur": 6}
    raw = render_frame(stacked, cam, 0.0, sun, "vsm",
                       ShadowSettings().override(**opts, bleed_reduction=0.0)).lit
    cut = render_frame(stacked, cam, 0.0, sun, "vsm",
                       ShadowSettings().override(**opts, bleed_reduction=0.5)).lit
    hard = render_frame(stacked, cam, 0.0, sun, "shadowmap").lit
    # Measured on this scene: up to 0.59 leaks through at the edges without reduction (mean
    # 0.016 over the strip); with reduction 0.5, 0.18 (mean 0.002).
    assert raw[strip].max() > 0.4
    assert cut[strip].max() < 0.5 * raw[strip].max()
    assert cut[strip].mean() < 0.3 * raw[strip].mean()
    assert hard[strip].max() == 0.0


def test_sun_below_horizon_and_bad_options(one_box):
    cam = cams.map_view(one_box, 2.0)
    frame = render_frame(one_box, cam, 0.0, sun_from_angles(180.0, -3.0), "pcf")
    assert (frame.lit == 0).all()
    # Nothing visible: no map is drawn at all.
    sky = cams.perspective([0, 0, 500.0], [0, 0, 900.0], vfov_deg=30, width_px=32, height_px=24,
                           scene=one_box)
    frame = render_frame(one_box, sky, 0.0, sun_from_angles(180.0, 30.0), "vsm")
    assert (frame.lit == 0).all() and frame.diagnostics.shadow["map_px"] == []
    # Tiny maps with wide filters still work (the padding shrinks to fit).
    frame = render_frame(one_box, cam, 0.0, sun_from_angles(180.0, 30.0), "vsm",
                         ShadowSettings().override(map_px=8, vsm_blur=6))
    assert np.isfinite(frame.lit).all()
    with pytest.raises(UsageError, match="pcf_kernel"):
        render_frame(one_box, cam, 0.0, sun_from_angles(180.0, 30.0), "pcf",
                     ShadowSettings().override(pcf_kernel=4))
    with pytest.raises(UsageError, match="map_px"):
        ShadowSettings().override(map_px=0)
    with pytest.raises(UsageError, match="clip_from_world"):
        sm.LightView(np.eye(3), 4, 4)


def test_texel_measures_match_finite_difference_twins():
    """Footprint and aliasing kernels against finite differences, for an orthographic and a
    projective light and a perspective camera, on random points and normals."""
    from reference import reference_aliasing_px, reference_texel_footprint_m

    rng = np.random.default_rng(4)
    points = rng.uniform(-20, 20, (50, 3))
    normals = rng.normal(size=(50, 3))
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    sun = sun_from_angles(150.0, 35.0)
    ortho = sm.ortho_view(sun.direction, (-30, 30), (-25, 25), (-80, 80), 300, 200)
    persp = cams.perspective([60.0, -70.0, 80.0], [0.0, 0.0, 0.0], vfov_deg=50, width_px=256,
                             height_px=256, near_m=10.0, far_m=300.0)
    warped = sm.LightView(persp.clip_from_world(), 256, 256, "test")
    camera = cams.perspective([-50.0, -40.0, 30.0], [0.0, 0.0, 0.0], vfov_deg=45, width_px=320,
                              height_px=200, near_m=1.0, far_m=300.0)
    for view in (ortho, warped):
        fast = sm.texel_footprint_m(view, points, normals)
        slow = reference_texel_footprint_m(view.clip_from_world, view.width_px, view.height_px,
                                           points, normals)
        np.testing.assert_allclose(fast, slow, rtol=1e-5)
        surf = SimpleNamespace(valid=np.ones((1, 50), bool), position_m=points[None],
                               normal=normals[None].astype(np.float32))
        m = sm.aliasing_m(view, camera, surf)
        slow_m = reference_aliasing_px(view.clip_from_world, view.width_px, view.height_px,
                                       camera.clip_from_world(), 320, 200, points,
                                       normals.astype(np.float32))
        assert m["max"] == pytest.approx(slow_m.max(), rel=1e-5)
        assert m["mean"] == pytest.approx(slow_m.mean(), rel=1e-5)


def test_depth_map_same_for_any_thread_count_and_tile_size(sample):
    import numba

    sun = sun_from_angles(250.0, 12.0)
    box = sm.scene_bounds(sample)
    corners = np.array([[box[i, 0], box[j, 1], box[k, 2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    light = corners @ np.stack(sm.light_basis(sun.direction), axis=1)
    lo, hi = light.min(axis=0), light.max(axis=0)
    view = sm.ortho_view(sun.direction, (lo[0], hi[0]), (lo[1], hi[1]), (lo[2] - 1, hi[2] + 1),
                         300, 200)
    before = numba.get_num_threads()
    try:
        maps = []
        for threads, tile in ((1, 64), (2, 64), (2, 16), (1, 24)):
            numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
            maps.append(sm.render_depth_map(sample, view, T_1990, tile_px=tile))
    finally:
        numba.set_num_threads(before)
    for other in maps[1:]:
        np.testing.assert_array_equal(other.prim_id, maps[0].prim_id)
        np.testing.assert_array_equal(other.depth, maps[0].depth)


def test_every_planner_works_with_every_lookup(sample):
    """Techniques are planner + lookup: the short names are exactly their compositions, and
    the warps and cascades take the filtered lookups too (not only the hard one)."""
    cam = cams.overview(sample, 192, 120)
    sun = sun_from_angles(135.0, 30.0)
    ref = render_frame(sample, cam, T_1990, sun, "raytrace")
    valid = ref.surfaces.valid
    small = ShadowSettings().override(map_px=1024)
    for alias, spelled in (("pcf", "shadowmap/pcf"), ("vsm", "shadowmap/vsm"),
                           ("psm", "psm/hard"), ("csm:lispsm", "csm:lispsm/hard")):
        a = render_frame(sample, cam, T_1990, sun, alias, small).lit
        b = render_frame(sample, cam, T_1990, sun, spelled, small).lit
        assert a.tobytes() == b.tobytes(), (alias, spelled)
    for name in ("lispsm/pcf", "xpsm/vsm", "psm/pcf", "csm/vsm", "csm:xpsm/pcf"):
        frame = render_frame(sample, cam, T_1990, sun, name, small)
        assert np.isfinite(frame.lit).all() and frame.diagnostics.shadow["lookup"] in name
        agree = ((frame.lit[valid] >= 0.5) == (ref.lit[valid] >= 0.5)).mean()
        assert agree >= 0.95, f"{name}: {100 * agree:.2f} % of pixels agree with raytrace"
        if name.endswith("/vsm"):  # a filtered lookup gives fractions, not only 0 and 1
            soft = frame.lit[valid]
            assert ((soft > 0.0) & (soft < 1.0)).any(), name


@pytest.mark.parametrize("warp", ["uniform", "lispsm"])
def test_lookup_receivers_match_the_step_by_step_twins(sample, warp):
    """The fused lookup pass (bias, projection, receiver-plane bias of projective views)
    against offset_receivers + project + receiver_plane_gradient on the same receivers."""
    from cityshade.shadows.warps import focus, warp_matrix

    cam = cams.overview(sample, 160, 100)
    sun = sun_from_angles(135.0, 30.0, sample.crs, sample.origin_m)
    from cityshade.frame.pipeline import camera_pass

    ctx = camera_pass(sample, cam, T_1990).context(sun)
    faces, points, normals, casters = focus(ctx)
    if warp == "uniform":
        view = sm.fit_uniform(sample, ctx, 512)
    else:
        m, _ = warp_matrix(warp, cam, sun.direction, points, casters, ctx.settings.warp)
        view = sm.LightView(m, 512, 512, warp)
    settings = ShadowSettings()
    for radius in (0, 2):
        u, v, z = sm.lookup_receivers(view, points, normals, sun.direction, settings, radius)
        q = sm.offset_receivers(view, points, normals, sun.direction, settings, radius)
        u0, v0, z0 = sm.project(view, q)
        if view.is_projective:
            gu, gv = sm.receiver_plane_gradient(view, q, normals, u0, v0, z0)
            z0 = z0 - (np.abs(gu) + np.abs(gv)) * (0.5 + radius)
        assert view.is_projective == (warp != "uniform") and len(u) == len(points) > 1000
        np.testing.assert_allclose(u, u0, rtol=0, atol=1e-9)
        np.testing.assert_allclose(v, v0, rtol=0, atol=1e-9)
        # The projective receiver-plane bias is a 1 cm finite difference: it turns the paths'
        # last-bit differences (dot-product order) into up to ~1e-9 of NDC depth, still below
        # the float32 depth map's resolution (6e-8 near 1) that the lookup compares with.
        # The difference's cancellation error grows with |z| itself: a receiver far outside
        # the map's depth range (z = -8.6, 1 of 3197 here) differed by 2.3e-9 of its value
        # (2e-8) on an AMD EPYC whose vector code orders the sums otherwise; so 1e-8 in the
        # range [-1, 1] and 1e-8 of |z| beyond it.
        bound = (1e-8 if view.is_projective else 1e-12) * np.maximum(1.0, np.abs(z0))
        assert np.all(np.abs(z - z0) <= bound), np.max(np.abs(z - z0) / bound)
    # The hard lookup's fused pass: the one-tap PCF of these receivers, bit for bit.
    from cityshade.shadows import filtering as flt

    dm = sm.render_depth_map(sample, view, T_1990)
    u, v, z = sm.lookup_receivers(view, points, normals, sun.direction, settings, 0)
    got = sm.shadow_lookup(dm, points, normals, sun.direction, settings, "hard")
    want = flt.pcf_lookup(dm.depth, u, v, z, 1)
    assert got.tobytes() == want.tobytes() and 0.0 < got.mean() < 1.0


def test_light_box_matches_numpy():
    rng = np.random.default_rng(5)
    points = rng.normal(0, 300, (5000, 3))
    basis = np.stack(sm.light_basis([0.3, -0.5, 0.8]), axis=1)
    lo, hi = sm.light_box(points, basis)
    light = points @ basis
    np.testing.assert_allclose(lo, light.min(axis=0), rtol=1e-14)
    np.testing.assert_allclose(hi, light.max(axis=0), rtol=1e-14)


def test_depth_map_reuse_draws_each_map_once(one_box):
    """Inside DepthMapReuse the same request returns the same map (and its depth-pass time
    is counted as reused); another view, or no reuse block, draws anew."""
    sun = sun_from_angles(200.0, 30.0)
    cam = cams.overview(one_box, 64, 40)
    from cityshade.frame.pipeline import camera_pass

    ctx = camera_pass(one_box, cam, 0.0).context(sun)
    view = sm.fit_uniform(one_box, ctx, 128)
    other = sm.fit_uniform(one_box, ctx, 64)
    with sm.DepthMapReuse() as reuse:
        first = sm.render_depth_map(one_box, view, 0.0)
        assert reuse.take_reused_s() == 0.0
        again = sm.render_depth_map(one_box, view, 0.0)
        assert again is first and reuse.reused == 1
        assert reuse.take_reused_s() == first.stats["timings_s"]["total_s"] > 0
        assert sm.render_depth_map(one_box, other, 0.0) is not first
        assert sm.render_depth_map(one_box, view, 1e9) is not first     # another city time
        reuse.clear()
        assert sm.render_depth_map(one_box, view, 0.0) is not first
    outside = sm.render_depth_map(one_box, view, 0.0)
    assert outside is not first and np.array_equal(outside.depth, first.depth)


def test_scratch_hands_out_kept_arrays_one_holder_at_a_time():
    """runtime.memory.Scratch: the same memory on the next take, a private one while it is held, and
    buffers that grow when asked for more."""
    from cityshade.runtime.memory import Scratch

    ws = Scratch()
    first = ws.take()
    assert first is ws
    a = first.get("x", (4, 3))
    assert a.shape == (4, 3) and a.dtype == np.float64 and a.flags.c_contiguous
    other = ws.take()            # held: a private Scratch, never the same memory
    assert other is not ws and not np.shares_memory(other.get("x", (4, 3)), a)
    first.give_back()
    again = ws.take()
    assert again is ws and np.shares_memory(again.get("x", 12), a)
    bigger = again.get("x", (5, 3))
    assert bigger.shape == (5, 3) and not np.shares_memory(bigger, a)
    assert again.get("i", 7, np.int32).dtype == np.int32
    # One name, arrays of other types one after the other: the same bytes, aligned.
    as_int = again.get("x", (6, 2), np.int64)
    assert as_int.dtype == np.int64 and np.shares_memory(as_int, bigger)
    assert again.get("x", 30, np.float32).ctypes.data == bigger.ctypes.data
    # A dropped name's memory goes; the next get of it is a fresh buffer, others stay.
    kept_i = again.get("i", 7, np.int32)
    again.drop("x", "never-taken")
    assert "x" not in again._arrays and np.shares_memory(again.get("i", 7, np.int32), kept_i)
    assert not np.shares_memory(again.get("x", 12), bigger)
    again.give_back()


def test_recycler_hands_out_memory_nothing_refers_to():
    """runtime.memory.Recycler: a dropped array's memory comes back for the same dtype and a size up to
    the buffer's and at least half of it, never while the array or a view of it is alive,
    never for another dtype or a size it does not fit; the least recently used buffer is let go
    beyond ``keep``."""
    from cityshade.runtime.memory import Recycler

    pool = Recycler(keep=2)
    a = pool.empty((4, 3), np.float32)
    assert a.shape == (4, 3) and a.dtype == np.float32 and a.flags.c_contiguous
    a_ptr = a.__array_interface__["data"][0]
    del a
    b = pool.empty((4, 3), np.float32)
    assert b.__array_interface__["data"][0] == a_ptr      # dropped: the same memory again
    c = pool.empty((4, 3), np.float32)
    assert not np.shares_memory(b, c)                     # b is alive
    view = b[1:]
    del b
    d = pool.empty((4, 3), np.float32)
    assert not np.shares_memory(d, view) and not np.shares_memory(d, c)   # held by the view
    del c, view
    smaller = pool.empty((3, 3), np.float32)              # fits a dropped 12-item buffer
    assert smaller.shape == (3, 3) and smaller.flags.c_contiguous
    assert any(np.shares_memory(smaller, buf) for buf in pool._buffers)
    del d, smaller
    assert [buf.size for buf in pool._buffers] == [12, 12]
    kept = {buf.__array_interface__["data"][0] for buf in pool._buffers}   # no references
    tiny = pool.empty(5, np.float32)                      # under half of every kept buffer
    assert tiny.__array_interface__["data"][0] not in kept
    six = pool.empty(6, np.float32)                       # half: fits one
    assert six.__array_interface__["data"][0] in kept
    f = pool.empty((4, 3), np.int32)                      # another dtype: fresh
    assert f.dtype == np.int32 and not np.shares_memory(f, pool._buffers[0])
    assert len(pool._buffers) == 2                        # keep=2: the oldest were let go
    pool.clear()
    assert not pool._buffers


def test_kept_depth_maps_are_not_overwritten_and_an_empty_view_is_cleared(one_box):
    """The depth pass takes its maps' memory from a Recycler and clears tiles in its first
    batch: a map the caller still holds keeps its values while later maps of the same size
    are drawn, and a map with nothing in it is all (+inf, -1)."""
    views = [sm.ortho_view(sun_from_angles(az, 35.0).direction, (-60, 60), (-60, 60),
                           (-200, 200), 96, 96) for az in (100.0, 250.0)]
    first = sm.render_depth_map(one_box, views[0], 0.0)
    kept_depth, kept_prim = first.depth.copy(), first.prim_id.copy()
    for _ in range(3):
        other = sm.render_depth_map(one_box, views[1], 0.0)
        assert not np.shares_memory(other.depth, first.depth)
        assert not np.array_equal(other.prim_id, kept_prim)
        del other
    assert np.array_equal(first.depth, kept_depth) and np.array_equal(first.prim_id, kept_prim)
    away = sm.ortho_view(sun_from_angles(100.0, 35.0).direction, (5000, 5100), (5000, 5100),
                         (-200, 200), 96, 96)
    empty = sm.render_depth_map(one_box, away, 0.0)             # the model lies outside
    assert np.isinf(empty.depth).all() and (empty.prim_id == -1).all()
    assert empty.stats["casters_drawn"] == 0
    again = sm.render_depth_map(one_box, views[0], 0.0)
    assert np.array_equal(again.depth, kept_depth) and np.array_equal(again.prim_id, kept_prim)


def test_lookups_on_kept_temporaries_equal_the_fresh_twin(sample):
    """shadow_lookup's receivers and VSM moments live in kept arrays: every mode, at map sizes
    that grow and shrink between calls, is bit-identical to the same steps on fresh arrays."""
    from cityshade.frame.pipeline import camera_pass
    from cityshade.shadows import filtering as flt

    cam = cams.overview(sample, 160, 100)
    sun = sun_from_angles(135.0, 30.0, sample.crs, sample.origin_m)
    ctx = camera_pass(sample, cam, T_1990).context(sun)
    points, normals = ctx.facing_points, ctx.facing_normals
    settings = ShadowSettings()
    vsm = settings.vsm
    for px in (256, 512, 128):
        dm = sm.render_depth_map(sample, sm.fit_uniform(sample, ctx, px), T_1990)
        for mode, radius in (("hard", 0), ("pcf", settings.pcf.kernel // 2),
                             ("vsm", vsm.blur_px)):
            got = sm.shadow_lookup(dm, points, normals, sun.direction, settings, mode)
            u, v, z = sm.lookup_receivers(dm.view, points, normals, sun.direction, settings,
                                          radius)
            if mode == "vsm":
                scale = sm.metres_per_ndc(dm.view)
                moments = flt.vsm_moments(dm.depth, scale,
                                          flt.gaussian_weights(vsm.blur_px / 2.0, vsm.blur_px)
                                          if vsm.filter == "gaussian"
                                          else flt.box_weights(vsm.blur_px))
                want = flt.vsm_lookup(moments, u, v, (z + 1.0) * scale, vsm.min_variance_m2,
                                      vsm.bleed_reduction)
            else:
                want = flt.pcf_lookup(dm.depth, u, v, z, 2 * radius + 1)
            assert len(got) == len(points) > 1000
            assert got.tobytes() == want.tobytes(), (px, mode)
            assert 0.0 < got.mean() < 1.0


def test_facing_mask_agrees_with_its_twin(sample):
    """The facing rule is N·L > 0 summed left to right: the kernel's mask is the twin's, on the
    sample city's normals for suns all round, on normals that make N·L vanish or nearly
    (walls along the sun's azimuth, ±0), and with ``valid`` as an array or True."""
    from reference import reference_facing_mask

    from cityshade.frame.pipeline import camera_pass
    from cityshade.shadows import facing_mask

    cp = camera_pass(sample, cams.overview(sample, 160, 100), T_1990)
    normal = np.asarray(cp.normal)
    valid = np.asarray(cp.surfaces.valid)
    rng = np.random.default_rng(3)
    a = np.deg2rad(rng.uniform(0.0, 360.0, 4000))
    edge = np.stack([np.cos(a), np.sin(a), np.zeros_like(a)], axis=1)
    for az in range(0, 360, 15):
        sun = sun_from_angles(float(az), 20.0, sample.crs, sample.origin_m).direction
        got = facing_mask(normal, valid, sun)
        assert got.shape == valid.shape and got.dtype == bool
        assert np.array_equal(got, reference_facing_mask(normal, valid, sun))
        # Walls whose normal is square to the sun's azimuth: N·L within rounding of 0.
        along = np.array([-sun[1], sun[0], 0.0]) / np.hypot(sun[0], sun[1])
        walls = np.concatenate([edge, along[None], -along[None], [[0.0, 0.0, -0.0]]])
        assert np.array_equal(facing_mask(walls, True, sun),
                              reference_facing_mask(walls, True, sun))
    assert 0 < got.sum() < valid.sum()


def test_context_gathers_the_facing_receivers_once_per_sun(sample):
    """The contexts of one camera pass and sun share the facing mask and gathered receivers
    (evaluate runs every technique on them); another sun gets its own, equal to a fresh
    gather."""
    from cityshade.frame.pipeline import camera_pass
    from cityshade.shadows import facing_mask, gather_pixels

    cp = camera_pass(sample, cams.overview(sample, 96, 60), T_1990)
    sun_a = sun_from_angles(135.0, 30.0, sample.crs, sample.origin_m)
    sun_b = sun_from_angles(240.0, 20.0, sample.crs, sample.origin_m)
    a1, a2 = cp.context(sun_a), cp.context(sun_a)
    assert a1.facing_points is a2.facing_points and a1.faces is a2.faces
    b = cp.context(sun_b)
    faces_b = facing_mask(cp.normal, cp.surfaces.valid, sun_b.direction)
    assert b.faces.tobytes() == faces_b.tobytes() and faces_b.sum() != a1.faces.sum()
    assert b.facing_points.tobytes() == gather_pixels(cp.surfaces.position_m, faces_b).tobytes()
    assert b.facing_normals.tobytes() == gather_pixels(cp.normal, faces_b).tobytes()


def test_gather_pixels_is_the_boolean_gather_in_row_major_order():
    from cityshade.shadows import gather_pixels

    rng = np.random.default_rng(3)
    image = rng.random((23, 17, 3)).astype(np.float32)
    for mask in (rng.random((23, 17)) < 0.3, np.zeros((23, 17), bool), np.ones((23, 17), bool)):
        mask[5] = False             # an empty row
        got = gather_pixels(image, mask)
        assert got.dtype == np.float64 and np.array_equal(got, image[mask].astype(np.float64))


def test_take_pixels_is_numpys_fancy_index_of_rows():
    """take_pixels (rows in parallel) gathers rows of an image or a 2-D array at flat
    indices, repeated and unordered ones too, as numpy's fancy index does, and refuses an
    index outside the array."""
    from cityshade import shadows
    from cityshade.errors import ContractError

    rng = np.random.default_rng(5)
    image = rng.random((23, 17, 3)).astype(np.float32)
    flat = image.reshape(-1, 3)
    for at in (rng.integers(0, 23 * 17, 100), np.arange(0), np.array([390, 0, 0, 5])):
        for src in (image, flat.astype(np.float64)):
            got = shadows.take_pixels(src, at)
            assert got.dtype == np.float64 and got.shape == (at.size, 3)
            assert np.array_equal(got, flat[at].astype(np.float64))
    for bad in ([391], [-1]):
        with pytest.raises(ContractError, match="pixel indices"):
            shadows.take_pixels(image, np.array(bad))


def test_scatter_pixels_is_numpys_boolean_assignment():
    """scatter_pixels (rows in parallel) writes a mask's pixels as ``out[mask] = values``
    does, and refuses a wrong number of values."""
    from cityshade.errors import ContractError
    from cityshade.shadows import gather_pixels, scatter_pixels

    rng = np.random.default_rng(11)
    for shape, share in (((37, 53), 0.6), ((1, 9), 1.0), ((12, 5), 0.0)):
        mask = rng.random(shape) < share
        for values in (rng.random(int(mask.sum())).astype(np.float32),
                       rng.random(int(mask.sum())) < 0.5):
            out = np.full(shape, 7.0, np.float32)
            want = out.copy()
            want[mask] = values
            scatter_pixels(values, mask, out)
            assert out.tobytes() == want.tobytes()
        image = rng.random(shape + (1,))
        back = np.zeros(shape)
        scatter_pixels(gather_pixels(image, mask)[:, 0], mask, back)
        np.testing.assert_array_equal(back[mask], image[mask][:, 0])
    with pytest.raises(ContractError):
        scatter_pixels(np.zeros(3), np.ones((2, 2), bool), np.zeros((2, 2)))
