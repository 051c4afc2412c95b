"""cityshade compare: analytic before/after cases, openings, and compare == two batch runs."""

from __future__ import annotations

import math
from datetime import date, datetime, timedelta, timezone

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground, polygon
from reference import reference_stretches



# --- analytic cases -------------------------------------------------------------------------------

LAT_DEG = 45.0  # at the equinox the sun's profile angle on an east-west wall is 90° - latitude


def _equinox_suns(hour_angles_deg):
    """Explicit suns of 21 March (declination 0) at LAT_DEG: the direction (east, north, up)
    is (-sin h, -sin φ cos h, cos φ cos h)."""
    from cityshade.geo.sun import sun_from_angles

    phi = math.radians(LAT_DEG)
    out = []
    for h in hour_angles_deg:
        hr = math.radians(h)
        e, n, u = -math.sin(hr), -math.sin(phi) * math.cos(hr), math.cos(phi) * math.cos(hr)
        out.append(sun_from_angles(math.degrees(math.atan2(e, n)) % 360.0,
                                   math.degrees(math.asin(u))))
    return out


def _steps(day, minutes, every_min=60):
    """Steps of ``every_min`` starting at the given minutes after midnight UTC."""
    from cityshade.sunhours.plan import Step

    t0 = datetime(day.year, day.month, day.day, tzinfo=timezone.utc)
    return [Step(i, t0 + timedelta(minutes=m), t0 + timedelta(minutes=m + every_min))
            for i, m in enumerate(minutes)]


def _build(tmp_path, text, name="m.gml"):
    from cityshade.build import build_scene_from_file

    path = tmp_path / name
    path.write_text(text)
    return build_scene_from_file(path)


def test_box_south_of_a_garden_takes_the_analytic_share_on_21_march(tmp_path):
    """A 200 m long, 10 m high block built in 2030 on the south side of a 20 m x 10 m garden
    whose near edge lies 5 m north of it. At the equinox at 45° N the block's shadow reaches
    10 m north all day, so the garden's southern half (rows 5-10 m) loses all 10 hours and the
    northern half loses nothing: exactly half keeps >= 2 h, and BRE 209's garden test passes
    on its edge."""
    from cityshade.planning.compare import Receivers, compare_states
    from cityshade.raster.camera import map_view
    from cityshade.planning.rules import evaluate, load_rules, measures_from

    block = building("NEW", box_polygons(-100.0, -4.0, 0.0, 200.0, 4.0, 10.0, "b"),
                     extra="<bldg:yearOfConstruction>2030</bldg:yearOfConstruction>")
    scene = _build(tmp_path, city(block, ground(-60.0, -60.0, 60.0, 60.0)))
    o = scene.origin_m
    cam = map_view(scene, 0.5, bbox=(-10.0 - o[0], 5.0 - o[1], 10.0 - o[0], 15.0 - o[1]))
    hours = [7 + k for k in range(10)]  # 07:00-17:00 solar time, centres h = -67.5° ... 67.5°
    steps = _steps(date(2025, 3, 21), [60 * h for h in hours])
    suns = _equinox_suns([15.0 * (h + 0.5 - 12.0) for h in hours])
    t_2025, t_2031 = ((date(y, 6, 1) - date(1970, 1, 1)).days for y in (2025, 2031))
    comp = compare_states(scene, t_2025, scene, t_2031, cam, steps,
                          Receivers(samples_per_m2=None, opening_samples_per_m2=0.0), suns=suns)
    assert cam.shape == (20, 40)
    y = cam.pixel_centres_world(o)[..., 1]
    assert np.all(comp.before.hours == 10.0)
    assert np.all(comp.after.hours[y < 10.0] == 0.0) and np.all(comp.after.hours[y > 10.0] == 10.0)
    assert np.all(comp.loss_h[y < 10.0] == 10.0) and np.all(comp.loss_pct[y > 10.0] == 0.0)
    assert not comp.changed.any()
    # Stretches: all 10 hours in one stretch before; the lit half keeps it.
    assert np.all(comp.before.stretches.pixel_longest_h() == 10.0)
    garden = load_rules("bre209")[0]
    import dataclasses

    garden = dataclasses.replace(garden, area_bbox=(-10.0, 5.0, 10.0, 15.0))
    before, after = measures_from(garden, comp)
    v = evaluate(garden, after, before)
    assert (v.status, v.numbers["share_after"], v.numbers["share_before"]) == ("pass", 0.5, 1.0)
    assert v.numbers["area_m2"] == 200.0


def _window_building():
    """A wall facing south at y = 0 with a 1 m x 0.2 m window (z 1.0-1.2, gml:id WIN) in it."""
    wall = [(-5.0, 0.0, 0.0), (5.0, 0.0, 0.0), (5.0, 0.0, 3.0), (-5.0, 0.0, 3.0)]
    hole = [(-0.5, 0.0, 1.0), (-0.5, 0.0, 1.2), (0.5, 0.0, 1.2), (0.5, 0.0, 1.0)]
    win = [(-0.5, 0.0, 1.0), (0.5, 0.0, 1.0), (0.5, 0.0, 1.2), (-0.5, 0.0, 1.2)]
    return (
        '<bldg:Building gml:id="HOUSE"><bldg:boundedBy><bldg:WallSurface gml:id="WALL">'
        f"<bldg:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember>"
        f"{polygon(wall, 'WALLPOLY', holes=[hole])}</gml:surfaceMember></gml:MultiSurface>"
        "</bldg:lod3MultiSurface><bldg:opening><bldg:Window gml:id=\"WIN\">"
        f"<bldg:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember>{polygon(win, 'WINPOLY')}"
        "</gml:surfaceMember></gml:MultiSurface></bldg:lod3MultiSurface></bldg:Window>"
        "</bldg:opening></bldg:WallSurface></bldg:boundedBy></bldg:Building>")


def test_south_window_stretches_against_an_obstruction_by_hand(tmp_path):
    """A long wall 3 m south of the window rises 2 m above the window's centre: the
    obstruction angle is atan(2/3) = 33.7°. With the sun due south, a step is lit when the
    sun stands higher than that (every sample of the 0.2 m high window agrees: their angles lie
    within 32.3°-35.0°). By hand: lit steps (10 min each) 1 1 0 1 1 1 . 0 1 1 (one step with
    the sun down) give stretches of 20, 30 and 20 min."""
    from cityshade.planning.compare import Receivers, compare_states, openings_of
    from cityshade.geo.sun import sun_from_angles

    wall = building("OBST", box_polygons(-100.0, -3.2, 0.0, 200.0, 0.2, 3.1, "w"),
                    extra="<bldg:yearOfConstruction>2030</bldg:yearOfConstruction>")
    scene = _build(tmp_path, city(_window_building(), wall))
    (opening,) = openings_of(scene)
    assert opening.opening_id == "WIN" and opening.surface_class == "window"
    elevations = [50, 40, 20, 45, 60, 38, -5, 25, 36, 70]
    suns = [sun_from_angles(180.0, e) for e in elevations]
    steps = _steps(date(2025, 3, 21), [540 + 10 * k for k in range(10)], every_min=10)
    t_2025, t_2031 = ((date(y, 6, 1) - date(1970, 1, 1)).days for y in (2025, 2031))
    comp = compare_states(scene, t_2025, scene, t_2031, None, steps,
                          Receivers(samples_per_m2=None), suns=suns)
    o = comp.opening
    assert o["samples"][0] > 4
    # Before the wall: lit whenever the sun is up: 6 steps, the sun-down step, 3 steps.
    assert o["ref_before_h"][0] == pytest.approx(9 / 6, abs=1e-12)
    assert o["ref_longest_before_h"][0] == pytest.approx(6 / 6, abs=1e-12)
    assert o["ref_after_h"][0] == pytest.approx(7 / 6, abs=1e-12)
    assert o["ref_longest_after_h"][0] == pytest.approx(3 / 6, abs=1e-12)
    samples = comp.samples
    st = comp.after.stretches.samples
    lit = [e > math.degrees(math.atan(2 / 3)) for e in elevations]
    lit[6] = False
    exp_longest, exp_q = reference_stretches(np.array(lit)[:, None],
                                             [s.start_utc.timestamp() for s in steps],
                                             [s.end_utc.timestamp() for s in steps], 0.4)
    assert np.all(st.longest_h == exp_longest[0])
    assert np.all(comp.after.sample_hours == pytest.approx(7 / 6, abs=1e-12))
    assert samples.n == o["samples"][0]


# --- compare == two batch runs ------------------------------------------------------------------

def test_compare_between_two_dates_is_the_difference_of_two_batch_runs(sample_city_scene):
    from cityshade.sunhours.accumulate import sun_hours
    from cityshade.sunhours.plan import plan_steps
    from cityshade.geo.temporal import parse_user_date
    from cityshade.planning.compare import Receivers, compare_states
    from cityshade.raster.camera import map_view

    scene = sample_city_scene
    cam = map_view(scene, 4.0)
    steps = plan_steps(date(2024, 3, 21), 8 * 3600, 16 * 3600, 7200.0, "Europe/Berlin")
    t1, t2 = parse_user_date("1750").city_days, parse_user_date("1990").city_days
    comp = compare_states(scene, t1, scene, t2, cam, steps,
                          Receivers(samples_per_m2=0.05, opening_samples_per_m2=0.0),
                          ground="auto")
    instants = [s.centre_utc for s in steps]
    weights = [s.weight_h for s in steps]
    z = repr(__import__("cityshade.geometry.ground", fromlist=["x"]).ground_height_m(scene, "auto")
             + float(scene.origin_m[2]))
    b = sun_hours(scene, cam, instants, t1, weights_h=weights, ground=z, samples_per_m2=0.05)
    a = sun_hours(scene, cam, instants, t2, weights_h=weights, ground=z, samples_per_m2=0.05)
    assert comp.before.hours.tobytes() == b.hours.tobytes()
    assert comp.after.hours.tobytes() == a.hours.tobytes()
    same = comp.before.valid & comp.after.valid & ~comp.changed
    assert np.array_equal(comp.loss_h[same], (b.hours - a.hours)[same])
    assert np.isnan(comp.loss_h[comp.changed]).all() and comp.changed.any()
    # Per surface: before exactly batch's; after exactly batch's on polygons standing both times.
    assert np.array_equal(comp.polygon_before_h, b.polygon_hours, equal_nan=True)
    both = b.samples.sampled & a.samples.sampled
    assert both.sum() > 100
    assert np.array_equal(comp.polygon_after_h[both], a.polygon_hours[both])


def test_merge_scenes_keeps_the_existing_indices_and_refuses_another_crs(tmp_path):
    from cityshade.planning.compare import merge_scenes, openings_of
    from cityshade.errors import UsageError

    shed = building("SHED", box_polygons(20.0, 20.0, 0.0, 2.0, 2.0, 2.0, "s"))  # with a srsName
    existing = _build(tmp_path, city(_window_building(), shed), "a.gml")
    far = building("P", box_polygons(500.0, 800.0, 0.0, 10.0, 10.0, 10.0, "q"))
    proposal = _build(tmp_path, city(far), "b.gml")
    merged = merge_scenes(existing, proposal)
    n_poly, n_tri = len(existing.poly_ids), existing.n_triangles
    assert merged.poly_ids[:n_poly] == existing.poly_ids
    assert merged.obj_ids == ["HOUSE", "SHED", "P"]
    assert np.array_equal(merged.triangles[:n_tri], existing.triangles)
    assert np.array_equal(merged.tri_polygon[n_tri:], np.asarray(proposal.tri_polygon) + n_poly)
    # The proposal's points land where they are in the CRS.
    xyz = np.asarray(merged.vertices, np.float64)[merged.triangles[n_tri:]].reshape(-1, 3) \
        + merged.origin_m
    assert xyz[:, 0].min() == 500.0 and xyz[:, 1].max() == 810.0
    assert merged.kdtree is not None
    assert [o.opening_id for o in openings_of(merged)] == ["WIN"]
    other = _build(tmp_path, city(far.replace("EPSG:25832", "EPSG:25833")), "c.gml")
    with pytest.raises(UsageError, match="not the model's"):
        merge_scenes(existing, other)


@pytest.mark.shared
def test_fzk_haus_citygml3_openings_are_windows_and_doors_with_their_ids():
    """CityGML 3.0 con:WindowSurface/con:DoorSurface (filling surfaces of the walls) were read
    as walls before; each is now an opening of its own, named by its gml:id."""
    from conftest import shared_file

    from cityshade.build import build_scene_from_file
    from cityshade.planning.compare import openings_of

    scene = build_scene_from_file(
        shared_file("fzk-haus/citygml3.0/FZK-Haus-LoD3-KIT-IAI-KHH-B36-V1__v3.gml"))
    openings = {o.opening_id: o for o in openings_of(scene)}
    assert sorted(o.surface_class for o in openings.values()) == ["door"] * 2 + ["window"] * 11
    # gml:name "Window South" (it sits in the west wall, x = 457842.12) and "Door West".
    assert openings["GML_9e0e6137-a907-4e4b-bc30-a6b95641f4c0"].surface_class == "window"
    assert openings["GML_c137f11d-9a8c-4126-9aeb-9a6c9b4e1cbd"].surface_class == "door"
    assert all(len(o.polygons) == 1 for o in openings.values())
