"""Rendering with exact shadows: analytic shadow lengths, time slices, real data, outputs."""
from __future__ import annotations

import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground


from cityshade.build import build_file
from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.store.scenefile import load_scene
from cityshade.geo.sun import sun_from_angles

PX = 0.5  # map pixel size in metres
H1 = 20.0  # height of the tall box


def _scene(tmp_path_factory, name, *members):
    tmp = tmp_path_factory.mktemp(name)
    src = tmp / f"{name}.gml"
    src.write_text(city(ground(-150, -150, 150, 150), *members))
    out, _, _ = build_file(src, tmp / f"{name}.cityshade")
    return load_scene(out)


@pytest.fixture(scope="module")
def one_box(tmp_path_factory):
    """A 10 × 10 × 20 m box at the centre of a 200 × 200 m plane."""
    return _scene(tmp_path_factory, "one", building("tall", box_polygons(-5, -5, 0, 10, 10, H1, "t")))


@pytest.fixture(scope="module")
def box_scene(tmp_path_factory):
    """The tall box and a 4 × 4 × 5 m box north of it (in its shadow when the sun is south)."""
    return _scene(tmp_path_factory, "two", building("tall", box_polygons(-5, -5, 0, 10, 10, H1, "t")),
                  building("low", box_polygons(-2, 12, 0, 4, 4, 5, "l")))


def map_frame(scene, az, el, technique="raytrace"):
    from cityshade.raster.camera import map_view
    from cityshade.frame.render import render_frame

    cam = map_view(scene, PX)
    sun = sun_from_angles(az, el)  # no CRS correction: the scene's +y is north
    return render_frame(scene, cam, 0.0, sun, technique)


def ground_shadow_end(frame, scene, az_deg):
    """Distance from the box centre to the end of the shadow along the shadow direction."""
    cam = frame.camera
    d = -np.array([math.sin(math.radians(az_deg)), math.cos(math.radians(az_deg))])
    lit = frame.lit
    cls = frame.surfaces.cls
    last = 0.0
    for s in np.arange(0.0, 150.0, PX / 8):
        x, y = s * d
        col = int(math.floor((x - cam.x_left_m) / PX))
        row = int(math.floor((cam.y_top_m - y) / PX))
        if not (0 <= row < lit.shape[0] and 0 <= col < lit.shape[1]):
            break
        if cls[row, col] == SURFACE_CODE["landuse"] and lit[row, col] < 0.5:
            last = s
    return last


@pytest.mark.parametrize("el", [10.0, 30.0, 60.0])
@pytest.mark.parametrize("az", [135.0, 180.0, 250.0])
def test_box_shadow_length_and_direction(one_box, az, el):
    frame = map_frame(one_box, az, el)
    length = H1 / math.tan(math.radians(el))
    d = np.array([math.sin(math.radians(az)), math.cos(math.radians(az))])
    exit_footprint = 5.0 / max(abs(d[0]), abs(d[1]))  # box half-size 5 m along the line
    expected = exit_footprint + length
    if expected > 145:  # shadow leaves the plane: the plane's edge ends it
        pytest.skip("shadow longer than the test plane")
    measured = ground_shadow_end(frame, one_box, az)
    assert abs(measured - expected) <= PX * 1.5, \
        f"shadow end at {measured:.2f} m, analytic {expected:.2f} m (pixel {PX} m)"
    # Direction: the ground shadow is (hull of the footprint and its copy moved by L along
    # -sun) minus the footprint; both are centred on the line from the box centre along -sun,
    # so the shadow's centroid lies on it.
    cam = frame.camera
    rows, cols = np.nonzero((frame.lit < 0.5) & (frame.surfaces.cls == SURFACE_CODE["landuse"]))
    xs = cam.x_left_m + (cols + 0.5) * PX
    ys = cam.y_top_m - (rows + 0.5) * PX
    angle = math.degrees(math.atan2(-xs.mean(), -ys.mean())) % 360
    assert abs((angle - az + 180) % 360 - 180) < 1.0, f"shadow towards {angle:.2f}°, sun at {az}°"


def test_box_in_shadow_is_shaded_on_the_right_faces(box_scene):
    """Sun in the south at 30°: the low box stands in the tall box's shadow — its roof and
    south wall are shadowed; its north wall faces away from the sun (self-shadowed)."""
    from cityshade.raster.camera import perspective
    from cityshade.frame.render import render_frame

    low = box_scene.obj_ids.index("low")
    frame = map_frame(box_scene, 180.0, 30.0)
    roof = (frame.surfaces.obj_id == low) & (frame.surfaces.cls == SURFACE_CODE["roof"])
    assert roof.sum() > 40 and (frame.lit[roof] == 0).all()
    tall_roof = (frame.surfaces.obj_id == box_scene.obj_ids.index("tall")) & \
        (frame.surfaces.cls == SURFACE_CODE["roof"])
    assert (frame.lit[tall_roof] == 1).all()
    # From the south-east at eye height, the south wall of the tall box is lit and the low
    # box (behind it) gets no sun on any face.
    cam = perspective(np.array([30.0, -60.0, 15.0]), np.array([0.0, 5.0, 5.0]), vfov_deg=50,
                      width_px=160, height_px=120, scene=box_scene)
    view = render_frame(box_scene, cam, 0.0, sun_from_angles(180.0, 30.0), "raytrace")
    s = view.surfaces
    tall_south = (s.obj_id == box_scene.obj_ids.index("tall")) & (s.normal[..., 1] < -0.9)
    assert tall_south.sum() > 50 and (view.lit[tall_south] == 1).all()
    low_px = s.obj_id == low
    assert (view.lit[low_px] == 0).all()


def test_sun_below_horizon_is_all_shadow(box_scene):
    frame = map_frame(box_scene, 180.0, -5.0)
    assert (frame.lit == 0).all() and np.isfinite(frame.rgb).all()
    assert any("below the horizon" in w for w in frame.warnings)


@pytest.fixture(scope="module")
def sample_scene(sample_city_scene):
    return sample_city_scene


@pytest.mark.parametrize("year", [1750, 1900, 1990])
def test_time_slices_show_only_standing_buildings(sample_scene, year):
    from cityshade.geo.temporal import parse_xsd_datetime_days
    from cityshade.raster.camera import map_view
    from cityshade.frame.render import render_frame

    t = parse_xsd_datetime_days(str(year))
    frame = render_frame(sample_scene, map_view(sample_scene, 1.0), t, sun_from_angles(180, 45))
    seen = set(np.unique(frame.surfaces.obj_id[frame.surfaces.valid]).tolist())
    standing = {i for i in range(len(sample_scene.obj_ids))
                if sample_scene.obj_t_begin_days[i] <= t < sample_scene.obj_t_end_days[i]}
    assert seen <= standing, f"objects drawn that do not stand in {year}: {seen - standing}"
    buildings = {i for i in standing if sample_scene.obj_types[i] == "Building"}
    seen_buildings = {i for i in seen if sample_scene.obj_types[i] == "Building"}
    # From above every standing building shows its roof.
    assert seen_buildings == buildings


def test_time_changes_the_picture(sample_scene):
    from cityshade.geo.temporal import parse_xsd_datetime_days as days
    from cityshade.raster.camera import map_view
    from cityshade.frame.render import render_frame

    cam = map_view(sample_scene, 1.0)
    a = render_frame(sample_scene, cam, days("1750"), sun_from_angles(180, 45))
    b = render_frame(sample_scene, cam, days("1990"), sun_from_angles(180, 45))
    assert (a.gbuffer.prim_id != b.gbuffer.prim_id).mean() > 0.05
