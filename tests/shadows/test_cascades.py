"""Cascaded shadow maps: the practical split scheme, gap-free coverage of the visible frustum,
skipped empty cascades, and renders against the exact ray-traced shadows."""
from __future__ import annotations

import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city
from test_warps import MIN_AGREEMENT, _camera_looking, _context, agreement

from cityshade.errors import UsageError
from cityshade.raster import camera as cams
from cityshade.shadows import cascades as C
from cityshade.shadows import get_technique
from cityshade.shadows import shadowmap as sm


def test_practical_splits_blend_log_and_uniform():
    # λ = 0: uniform; λ = 1: logarithmic (geometric); λ = 0.5: their mean (Zhang et al. 2006).
    np.testing.assert_allclose(C.practical_splits(10.0, 50.0, 4, 0.0), [10, 20, 30, 40, 50])
    np.testing.assert_allclose(C.practical_splits(1.0, 10000.0, 4, 1.0), [1, 10, 100, 1000, 1e4])
    half = C.practical_splits(1.0, 10000.0, 4, 0.5)
    np.testing.assert_allclose(half[1:-1], 0.5 * (np.array([10, 100, 1000])
                                                  + np.array([2500.75, 5000.5, 7500.25])))
    assert half[0] == 1.0 and half[-1] == 10000.0 and (np.diff(half) > 0).all()
    assert C.practical_splits(5.0, 5.0, 3, 0.5).tolist() == [5.0] * 4
    with pytest.raises(UsageError):
        C.practical_splits(0.0, 5.0, 3, 0.5)
    with pytest.raises(UsageError):
        C.CascadeSettings(count=0)


def test_every_depth_falls_in_exactly_one_slice():
    splits = C.practical_splits(2.0, 200.0, 4, 0.5)
    z = np.concatenate([np.linspace(2.0, 200.0, 1001), splits])
    idx = C.assign_cascades(z, splits)
    lo, hi = splits[idx], splits[idx + 1]
    assert ((lo <= z) & ((z < hi) | ((idx == 3) & (z == hi)))).all()
    # A split value belongs to the slice that starts there.
    assert C.assign_cascades(splits[1:4], splits).tolist() == [1, 2, 3]


@pytest.fixture(scope="module")
def sample(sample_city_scene):
    return sample_city_scene


def test_cascades_cover_the_visible_frustum_without_gaps(sample):
    from cityshade.geo.temporal import parse_user_date
    from cityshade.shadows import facing_sun
    from cityshade.geo.sun import sun_from_angles

    t = parse_user_date("1990").city_days
    cam = cams.overview(sample, 256, 160)
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize
    from cityshade.shadows import ShadowContext

    sun = sun_from_angles(135.0, 30.0, sample.crs, sample.origin_m)
    ctx = ShadowContext(sample, resolve(sample, rasterize(sample, cam, t)), cam, sun, t,
                        measure=True)
    tech = get_technique("csm")
    result = tech.run(ctx)
    layers, views = result.prepared.layers, result.prepared.views
    d = result.diagnostics
    _, faces = facing_sun(ctx.surfaces, cam, ctx.sun.direction)
    points = ctx.surfaces.position_m[faces]
    depth = C.view_depth_m(cam, points)
    splits = np.array(d["splits_m"])
    assert d["cascades"] == 4 and d["cascades_rendered"] == 4 and d["cascades_skipped"] == []
    # The slices span exactly the visible depth range and every facing pixel is in one.
    assert splits[0] == pytest.approx(depth.min()) and splits[-1] == pytest.approx(depth.max())
    idx = C.assign_cascades(depth, splits)
    assert sum(e["pixels"] for e in d["per_cascade"]) == points.shape[0]
    assert layers.shape == (4, 2048, 2048)
    # Each pixel lands inside its own cascade's map (no gaps) ...
    for k, view in enumerate(views):
        u, v, z = sm.project(view, points[idx == k])
        assert ((u >= 0) & (u < view.width_px) & (v >= 0) & (v < view.height_px)).all()
        assert (np.abs(z) <= 1.0).all()
        # ... and the cascade's map holds depths where its receivers are.
        col, row = np.floor(u).astype(int), np.floor(v).astype(int)
        assert np.isfinite(layers[k][row, col]).mean() > 0.99
    # Nearer cascades have finer texels at their receivers.
    texels = [e["texel_m"] for e in d["per_cascade"]]
    assert texels[0] < texels[-1]


@pytest.fixture(scope="module")
def near_and_far(tmp_path_factory):
    """Two blocks 300 m apart and nothing between: the middle slices hold no pixel."""
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("nearfar")
    src = tmp / "nf.gml"
    src.write_text(city(building("near", box_polygons(-3, 0, 0, 6, 6, 4, "n")),
                        building("far", box_polygons(-60, 300, 0, 120, 10, 60, "f"))))
    out, _, _ = build_file(src, tmp / "nf.cityshade")
    return load_scene(out)


def test_a_cascade_covering_no_pixel_is_skipped(near_and_far):
    from cityshade.geo.sun import sun_from_angles

    cam = _camera_looking(np.array([0.0, -40.0, 10.0]) - near_and_far.origin_m, 0.0, 0.0)
    options = {"cascades": 4, "split_lambda": 0.0, "map_px": 512}
    ctx = _context(near_and_far, cam, sun_from_angles(200.0, 30.0), options)
    tech = get_technique("csm")
    result = tech.run(ctx)
    d = result.diagnostics
    assert d["cascades_skipped"] == [1, 2], d["splits_m"]
    assert d["cascades_rendered"] == 2 and len(d["map_px"]) == 2
    assert result.prepared.views[1] is None and result.prepared.views[2] is None
    assert np.isinf(result.prepared.layers[1]).all() and np.isinf(result.prepared.layers[2]).all()
    assert "skipped" in d["per_cascade"][1]
    share, _ = agreement(near_and_far, cam, 0.0, sun_from_angles(200.0, 30.0), "csm", options)
    assert share >= MIN_AGREEMENT


@pytest.mark.parametrize("technique", ["csm", "csm:lispsm", "csm:psm", "csm:xpsm"])
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
        assert len(d["map_px"]) == d["cascades_rendered"] >= 1
        assert d["texel_m"] > 0 and d["aliasing_m"]["max"] >= d["aliasing_m"]["mean"] > 0
        if view == "map":
            assert d["cascades"] == 1 and "orthographic" in d["note"]


def test_warp_option_and_bad_values():
    with pytest.raises(UsageError):
        C.CascadeSettings(count=40)
    with pytest.raises(UsageError):
        C.CascadeSettings(split_lambda=1.5)
    with pytest.raises(UsageError, match="unknown warp"):
        get_technique("csm:nope")
    assert math.isclose(C.CascadeSettings().split_lambda, 0.5)
