"""Tests of cityshade.raster.camera: frames, clip matrices, overview fit, map georeference, presets."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from cityshade.errors import ConfigError, UsageError
from cityshade.raster import camera as cams
from cityshade.raster.camera import Camera
from cityshade.errors import UnknownPresetError


def box_scene(lo=(-50.0, -30.0, 0.0), hi=(70.0, 40.0, 25.0), origin=(690000.0, 5336000.0, 500.0)):
    """A scene whose triangles span exactly the box (two triangles on opposite corners)."""
    lo, hi = np.asarray(lo, np.float32), np.asarray(hi, np.float32)
    v = np.array([lo, [hi[0], lo[1], lo[2]], [lo[0], hi[1], lo[2]],
                  hi, [lo[0], hi[1], hi[2]], [hi[0], lo[1], hi[2]]], np.float32)
    return SimpleNamespace(vertices=v, triangles=np.array([[0, 1, 2], [3, 4, 5]], np.int32),
                           tri_t_begin_days=np.array([-np.inf, 100.0]),
                           tri_t_end_days=np.array([np.inf, np.inf]),
                           origin_m=np.asarray(origin, np.float64))


def corners(lo, hi):
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                     for z in (lo[2], hi[2])], float)


def ndc(cam, points):
    p = np.c_[points, np.ones(len(points))] @ cam.clip_from_world().T
    return p[:, :3] / p[:, 3:4], p[:, 3]


def test_perspective_rays_and_clip_matrix_agree():
    cam = cams.perspective((10.0, -40.0, 30.0), (0.0, 0.0, 5.0), vfov_deg=50.0, width_px=64,
                           height_px=48, near_m=0.5, far_m=500.0)
    origins, dirs = cam.primary_rays()
    assert origins.shape == dirs.shape == (64 * 48, 3)
    np.testing.assert_allclose(np.linalg.norm(dirs, axis=1), 1.0, rtol=1e-12)
    # A point 20 m along pixel (col, row)'s ray projects to that pixel's centre.
    for col, row in [(0, 0), (63, 0), (5, 47), (31, 24)]:
        i = row * 64 + col
        p, w = ndc(cam, (origins[i] + 20.0 * dirs[i])[None])
        assert w[0] > 0
        np.testing.assert_allclose(p[0, 0], (col + 0.5) / 64 * 2 - 1, atol=1e-9)
        np.testing.assert_allclose(p[0, 1], 1 - (row + 0.5) / 48 * 2, atol=1e-9)
    # The target is at the image centre; near and far map to -1 and 1.
    fwd = (cam.target_m - cam.eye_m) / np.linalg.norm(cam.target_m - cam.eye_m)
    p, _ = ndc(cam, np.array([cam.target_m, cam.eye_m + 0.5 * fwd, cam.eye_m + 500.0 * fwd]))
    np.testing.assert_allclose(p[0, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(p[1:, 2], [-1.0, 1.0], atol=1e-9)
    # The image's up is world up projected (the horizon is level).
    right, up, fwd2 = cam.frame()
    assert abs(right[2]) < 1e-12 and up[2] > 0
    np.testing.assert_allclose(np.cross(right, up), -fwd2, atol=1e-12)


def test_straight_down_camera_uses_north_as_up():
    cam = cams.perspective((0.0, 0.0, 100.0), (0.0, 0.0, 0.0), width_px=8, height_px=8,
                           near_m=1.0, far_m=200.0)
    right, up, fwd = cam.frame()
    np.testing.assert_allclose([right, up, fwd], [[1, 0, 0], [0, 1, 0], [0, 0, -1]], atol=1e-12)


def test_overview_frames_the_model_from_the_south_west():
    scene = box_scene()
    cam = cams.overview(scene, 320, 180)
    lo, hi = scene.vertices.min(0), scene.vertices.max(0)
    centre = (lo + hi) / 2.0
    right, up, fwd = cam.frame()
    assert math.isclose(math.degrees(math.asin(-fwd[2])), 35.0, abs_tol=1e-9)
    assert math.isclose(math.degrees(math.atan2(fwd[0], fwd[1])), 45.0, abs_tol=1e-9)  # looks NE
    assert cam.eye_m[0] < centre[0] and cam.eye_m[1] < centre[1]
    p, w = ndc(cam, corners(lo, hi))
    assert (w > cam.near_m).all()
    assert np.abs(p[:, :2]).max() <= 1.0                                 # all inside ...
    assert np.abs(p[:, :2]).max(axis=0).max() > 0.9                      # ... and fitted
    assert (p[:, 2] > -1).all() and (p[:, 2] < 1).all()                  # not clipped
    # With a date, the box is that of the triangles present then (the second is from day 100).
    early = cams.overview(scene, 320, 180, t_days=0.0)
    assert not np.allclose(early.eye_m, cam.eye_m)


def test_near_far_contain_the_box_from_inside_and_outside():
    scene = box_scene()
    inside = cams.perspective((0.0, 0.0, 10.0), (50.0, 0.0, 10.0), scene=scene)
    far_corner = np.linalg.norm(corners((-50, -30, 0), (70, 40, 25)) - [0, 0, 10], axis=1).max()
    assert 0 < inside.near_m <= 0.01 and inside.far_m > far_corner
    outside = cams.perspective((-500.0, 0.0, 10.0), (0.0, 0.0, 10.0), scene=scene)
    assert 400.0 < outside.far_m and outside.near_m <= 450.0 * 0.5 + 1e-9
    with pytest.raises(UsageError):
        cams.perspective((0.0, 0.0, 0.0), (1.0, 0.0, 0.0))        # no near/far, no scene


def test_map_view_georeference():
    scene = box_scene()
    cam = cams.map_view(scene, 0.5)
    gt = cam.geotransform(scene.origin_m)
    x_ul, px, _, y_ul, _, neg_px = gt
    assert px == 0.5 and neg_px == -0.5 and gt[2] == gt[4] == 0.0
    # Grid corners on multiples of the pixel size in the CRS, covering the model's box.
    assert x_ul % 0.5 == 0.0 and y_ul % 0.5 == 0.0
    assert x_ul <= 690000.0 - 50.0 < x_ul + px
    assert y_ul - px < 5336000.0 + 40.0 <= y_ul
    assert x_ul + cam.width_px * px >= 690000.0 + 70.0
    assert y_ul - cam.height_px * px <= 5336000.0 - 30.0
    centres = cam.pixel_centres_world(scene.origin_m)
    assert centres.shape == (cam.height_px, cam.width_px, 2)
    np.testing.assert_allclose(centres[0, 0], (x_ul + 0.25, y_ul - 0.25), atol=1e-9)
    np.testing.assert_allclose(centres[-1, -1], (x_ul + (cam.width_px - 0.5) * 0.5,
                                                 y_ul - (cam.height_px - 0.5) * 0.5), atol=1e-9)
    # Pixel centres ↔ pixels, both ways.
    back = cam.pixel_of_world(centres.reshape(-1, 2), scene.origin_m)
    rows, cols = np.divmod(np.arange(cam.width_px * cam.height_px), cam.width_px)
    np.testing.assert_array_equal(back, np.c_[cols, rows])
    # Map rays run straight down from above the model.
    origins, dirs = cam.primary_rays()
    assert (dirs == [0.0, 0.0, -1.0]).all() and (origins[:, 2] > 25.0).all()
    np.testing.assert_allclose(origins[:, :2] + scene.origin_m[:2], centres.reshape(-1, 2),
                               atol=1e-9)
    # Clip matrix: pixel centres go to their NDC positions.
    p, _ = ndc(cam, np.c_[origins[:3, :2], [0.0, 0.0, 0.0]])
    np.testing.assert_allclose(p[:, 0], (np.arange(3) + 0.5) / cam.width_px * 2 - 1, atol=1e-9)
    np.testing.assert_allclose(p[:, 1], 1 - 1.0 / cam.height_px, atol=1e-9)


def test_map_view_bbox_default_size_and_errors():
    scene = box_scene()
    cam = cams.map_view(scene, 2.0, bbox=(0.0, 0.0, 10.0, 5.0))
    assert (cam.width_px, cam.height_px) == (5, 3)          # 10 m / 2 m; y 4999..5336005 → 3 px
    auto = cams.map_view(scene)
    assert auto.pixel_size_m in (0.05, 0.1) and max(auto.width_px, auto.height_px) <= 2048 + 1
    with pytest.raises(UsageError, match="exceeds"):
        cams.map_view(scene, 0.001)
    with pytest.raises(UsageError):
        cams.map_view(scene, -1.0)
    with pytest.raises(UsageError):
        cams.map_view(scene, 1.0, bbox=(5.0, 0.0, 1.0, 1.0))
    with pytest.raises(UsageError):
        cams.perspective((0, 0, 0), (1, 0, 0), near_m=1.0, far_m=2.0).geotransform(
            scene.origin_m)


def test_nice_pixel_sizes():
    assert [cams.nice_ceil(x) for x in (0.07, 0.1, 0.11, 0.3, 4.0, 7.0)] == \
        [0.1, 0.1, 0.2, 0.5, 5.0, 10.0]


def test_shipped_presets_and_unknown_names_fail(tmp_path):
    # The presets are the package's configs/cameras.toml (one copy; an installed package reads
    # it through importlib.resources, tests/cli/test_cli.py checks that on a built wheel).
    shipped = Path(cams.__file__).resolve().parents[1] / "configs" / "cameras.toml"
    with shipped.open("rb") as fh:
        assert cams.load_presets() == tomllib.load(fh)
    assert sorted(cams.load_presets()) == ["bird", "east", "north", "overview", "south", "west"]
    assert cams.load_presets()["overview"] == {"azimuth_deg": 225.0, "elevation_deg": 35.0,
                                               "vfov_deg": 40.0, "zoom": 1.0}
    scene = box_scene()
    south = cams.preset("south", scene, 160, 90)
    _, _, fwd = south.frame()
    assert fwd[1] > 0.9 and abs(fwd[0]) < 1e-12                 # looks north
    with pytest.raises(UnknownPresetError, match="bird, east, north, overview, south, west"):
        cams.preset("nadir", scene, 160, 90)
    bad = tmp_path / "cams.toml"
    bad.write_text("[x]\nazimuth_deg = 1\nelevation_deg = 2\nfocal = 3\n")
    with pytest.raises(ConfigError, match="focal"):
        cams.load_presets(bad)
    bad.write_text("[x]\nazimuth_deg = 1\n")
    with pytest.raises(ConfigError, match="elevation_deg"):
        cams.load_presets(bad)


def test_camera_validation():
    good = dict(kind="perspective", width_px=4, height_px=4, eye_m=(0, 0, 0),
                target_m=(1, 0, 0), up=(0, 0, 1), vfov_deg=40.0, near_m=0.1, far_m=10.0)
    Camera(**good)
    for change in ({"kind": "fisheye"}, {"width_px": 0}, {"vfov_deg": 180.0},
                   {"near_m": 0.0}, {"far_m": 0.05}, {"target_m": (0, 0, 0)},
                   {"eye_m": (0, 0, np.nan)}):
        with pytest.raises(UsageError):
            Camera(**{**good, **change})


def test_scene_box_is_the_used_vertices_box(sample_city_scene):
    """scene_box's one-pass kernel against its twin: the sample city (all triangles, and those
    standing at a date), a vertex no triangle uses (ignored) and a NaN vertex (NaN, as numpy)."""
    from reference import reference_used_vertex_box

    scene = sample_city_scene
    box = cams.scene_box(scene)
    assert box.dtype == np.float64 and box.shape == (2, 3)
    assert box.tobytes() == reference_used_vertex_box(scene.vertices, scene.triangles).tobytes()
    t = 0.0
    present = (scene.tri_t_begin_days <= t) & (t < scene.tri_t_end_days)
    assert cams.scene_box(scene, t).tobytes() == reference_used_vertex_box(
        scene.vertices, np.asarray(scene.triangles)[present]).tobytes()
    s = box_scene()
    s.vertices = np.vstack([s.vertices, [[1e6, -1e6, 7.0]]]).astype(np.float32)
    assert cams.scene_box(s).tobytes() == reference_used_vertex_box(
        s.vertices, s.triangles).tobytes()
    assert cams.scene_box(s)[1, 0] == 70.0
    s.vertices[4, 1] = np.nan
    got, want = cams.scene_box(s), reference_used_vertex_box(s.vertices, s.triangles)
    assert np.isnan(got[:, 1]).all() and got.tobytes() == want.tobytes()
