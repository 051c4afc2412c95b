"""Batch runs: time steps, sun-hour maps against analytic shadows, resume bit for bit, CLI."""
from __future__ import annotations

import json
from datetime import date, datetime, timedelta, timezone

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city, ground

from cityshade.sunhours import accumulate as A
from cityshade.sunhours import checkpoint as C
from cityshade.sunhours import outputs as O
from cityshade.sunhours import plan as P
from cityshade.sunhours import run as R
from cityshade.sunhours.request import SunHoursRequest
from cityshade.errors import UsageError
from cityshade.geo.sun import sun_from_angles

#: Box 10 × 10 × 20 m centred on the origin of a 200 × 200 m plane, in EPSG:25832 near Munich.
X0, Y0, Z0 = 691_000.0, 5_334_000.0, 520.0
H = 20.0
PX = 2.0  # map pixel size in metres


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("batch")
    src = tmp / "box.gml"
    src.write_text(city(ground(X0 - 100, Y0 - 100, X0 + 100, Y0 + 100, Z0),
                        building("box", box_polygons(X0 - 5, Y0 - 5, Z0, 10, 10, H, "b"))))
    out, _, _ = build_file(src, tmp / "box.cityshade")
    return load_scene(out)


# --- time steps --------------------------------------------------------------------------------

def test_durations_and_clock():
    assert P.parse_duration_s("10min") == 600 and P.parse_duration_s("1h30min") == 5400
    assert P.parse_duration_s("30s") == 30 and P.parse_duration_s("0.5h") == 1800
    assert P.parse_clock_s("05:30") == 19_800 and P.parse_clock_s("24:00") == 86_400
    for bad in ("10", "10 minutes", "h", "0min", ""):
        with pytest.raises(UsageError):
            P.parse_duration_s(bad)
    for bad in ("5", "25:00", "12:60", "24:01"):
        with pytest.raises(UsageError):
            P.parse_clock_s(bad)


def test_plan_steps_midpoints_weights_and_days():
    steps = P.plan_steps(date(2024, 6, 21), P.parse_clock_s("05:00"), P.parse_clock_s("21:00"),
                         600, "Europe/Berlin")
    assert len(steps) == 96 and sum(s.weight_h for s in steps) == pytest.approx(16.0)
    assert steps[0].start_utc == datetime(2024, 6, 21, 3, 0, tzinfo=timezone.utc)  # CEST
    assert steps[0].centre_utc == datetime(2024, 6, 21, 3, 5, tzinfo=timezone.utc)
    # A step that does not divide the window: the last step is shorter.
    odd = P.plan_steps(date(2024, 1, 1), 0, 3600, 25 * 60, "UTC")
    assert [round(s.weight_h * 60) for s in odd] == [25, 25, 10]
    # Winter day: CET, one hour less offset than the summer day.
    winter = P.plan_steps(date(2024, 12, 21), P.parse_clock_s("05:00"), P.parse_clock_s("06:00"),
                          3600, "Europe/Berlin")
    assert winter[0].start_utc.hour == 4 and steps[0].start_utc.hour == 3
    # Several days, every 7 days, and --to-date.
    week = P.plan_steps(date(2024, 6, 1), 0, 86_400, 3600, "UTC", days=3, every_day=7)
    assert len(week) == 72 and week[24].start_utc.date() == date(2024, 6, 8)
    upto = P.plan_steps(date(2024, 6, 1), 0, 3600, 3600, "UTC", to_date=date(2024, 6, 30),
                        every_day=10)
    assert [s.start_utc.day for s in upto] == [1, 11, 21]
    # The night the clocks go forward has one real hour less between 00:00 and 06:00.
    spring = P.plan_steps(date(2024, 3, 31), 0, P.parse_clock_s("06:00"), 3600,
                          "Europe/Berlin")
    assert len(spring) == 5


def test_plan_steps_failures():
    with pytest.raises(UsageError, match="--to must be later"):
        P.plan_steps(date(2024, 6, 21), 3600, 3600, 600, "UTC")
    with pytest.raises(UsageError, match="not both"):
        P.plan_steps(date(2024, 6, 21), 0, 3600, 600, "UTC", days=2, to_date=date(2024, 7, 1))
    with pytest.raises(UsageError, match="unknown time zone"):
        P.plan_steps(date(2024, 6, 21), 0, 3600, 600, "Mars/Olympus")
    with pytest.raises(UsageError, match="before --date"):
        P.plan_steps(date(2024, 6, 21), 0, 3600, 600, "UTC", to_date=date(2024, 6, 1))
    with pytest.raises(UsageError, match="exceed the limit"):
        P.plan_steps(date(2024, 1, 1), 0, 86_400, 1, "UTC", days=30)
    with pytest.raises(UsageError, match="1000 to 3000"):
        P.plan_steps(date(3000, 12, 31), 0, 3600, 600, "UTC", days=2)


def test_plan_units_skips_night_and_merges_identical_suns():
    a, b, night = sun_from_angles(120, 30), sun_from_angles(200, 50), sun_from_angles(0, -3)
    units, below, dup = P.plan_units([a, night, b, a, night, a], [1, 2, 3, 4, 5, 6])
    assert below == [1, 4] and dup == 2
    assert [u.steps for u in units] == [(0, 3, 5), (2,)]
    assert [u.weight_h for u in units] == [11.0, 3.0]


# --- sun-hours against analytic shadows and the brute-force twin --------------------------------

def _box_blocks(points, d, origin_m):
    """Analytic: does the ray from each point (N, 3, render space) towards d hit the box?
    Returns (blocked, margin): margin is how far (m) the ray passes from the box's boundary."""
    lo = np.array([X0 - 5.0, Y0 - 5.0, Z0]) - origin_m
    hi = np.array([X0 + 5.0, Y0 + 5.0, Z0 + H]) - origin_m
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - points) / d
        t2 = (hi - points) / d
    tmin = np.nanmax(np.minimum(t1, t2), axis=1)
    tmax = np.nanmin(np.maximum(t1, t2), axis=1)
    blocked = (tmax >= np.maximum(tmin, 0.0))
    margin = np.abs(tmax - np.maximum(tmin, 0.0))
    return blocked, margin


SUNS = [(135.0, 25.0), (180.0, 40.0), (250.0, 15.0), (135.0, 25.0), (30.0, -2.0), (300.0, 60.0)]
WEIGHTS = [0.5, 1.0, 0.25, 0.5, 1.0, 2.0]


def _explicit_suns():
    return [sun_from_angles(az, el) for az, el in SUNS]  # the scene's +y is north


def _instants(n):
    t0 = datetime(2024, 6, 21, 4, tzinfo=timezone.utc)
    return [t0 + timedelta(minutes=30 * k) for k in range(n)]


def test_box_on_plane_equals_sum_of_analytic_steps(scene):
    from cityshade.citygml.namespaces import SURFACE_CODE
    from cityshade.raster.camera import map_view

    cam = map_view(scene, PX)
    res = A.sun_hours(scene, cam, _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                      suns=_explicit_suns())
    assert res.steps == 6 and res.steps_below_horizon == 1 and res.steps_duplicate == 1
    assert res.units == 4 and res.hours_sun_up == pytest.approx(4.25)
    ground_px = res.valid & (res.surfaces.cls == SURFACE_CODE["landuse"])
    points = res.surfaces.position_m[ground_px]
    expected = np.zeros(len(points))
    clear = np.ones(len(points), bool)
    for (az, el), w, sun in zip(SUNS, WEIGHTS, _explicit_suns()):
        if el <= 0:
            continue
        blocked, margin = _box_blocks(points, sun.direction, scene.origin_m)
        expected += np.where(blocked, 0.0, w)
        clear &= margin > 1e-3  # pixel centres on a shadow edge are ties; left out
    got = res.hours[ground_px].astype(np.float64)
    assert clear.mean() > 0.99
    np.testing.assert_array_equal(got[clear], expected[clear].astype(np.float32))
    assert (expected > 0).any() and (expected < 4.25).any()  # shadows and sun both present
    roof = res.valid & (res.surfaces.cls == SURFACE_CODE["roof"])
    assert roof.sum() > 10 and (res.hours[roof] == np.float32(4.25)).all()
    assert np.isnan(res.hours[~res.valid]).all()


def test_reused_rays_equal_the_technique_per_step(scene):
    """The batch's precomputed-origin path and ``raytrace`` run per step agree bit for bit."""
    from cityshade.raster.camera import perspective

    cams = [__import__("cityshade.raster.camera", fromlist=["map_view"]).map_view(scene, PX),
            perspective(np.array([40.0, -60.0, 30.0]), np.array([0.0, 0.0, 0.0]), vfov_deg=50,
                        width_px=96, height_px=64, scene=scene)]
    for cam in cams:
        fast = A.sun_hours(scene, cam, _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                           suns=_explicit_suns())
        slow = A.sun_hours(scene, cam, _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                           suns=_explicit_suns(), reuse_rays=False)
        assert fast.hours.tobytes() == slow.hours.tobytes()
        assert np.isfinite(fast.hours).any()


def test_surface_samples_match_brute_force_twin(scene):
    from reference import reference_sun_hours

    res = A.surface_sun_hours(scene, _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                              suns=_explicit_suns(), samples_per_m2=0.02)
    s = res.samples
    assert s.n < 2000 and s.sampled.all()
    # Every polygon's sample weights add up to its area (stratified, equal-area strata).
    area = np.bincount(s.polygon, weights=s.weight_m2, minlength=len(scene.poly_ids))
    np.testing.assert_allclose(area, scene.poly_area_m2, rtol=1e-9)
    ref = reference_sun_hours(scene.vertices, scene.triangles, s.points_m, s.normals,
                              [sun.direction for sun in _explicit_suns()], WEIGHTS)
    np.testing.assert_array_equal(res.sample_hours, ref)
    by_id = dict(zip(scene.poly_ids, res.polygon_hours))
    assert by_id["br"] == pytest.approx(4.25)  # roof: every step with the sun up
    assert by_id["bg"] == 0.0  # the box's floor faces down
    # The south wall (normal −y) sees the suns at 135°, 180°, 250° (and not 300°, 30°).
    assert by_id["bs"] == pytest.approx(0.5 + 1.0 + 0.25 + 0.5)


def test_flat_roof_gets_the_hours_of_sun_above_the_horizon(scene):
    """SPA sun for the model's place (Munich), 21 June, every 10 min over the whole day: the
    unobstructed roof's sun-hours equal the time with the sun above the horizon within one
    step, here found independently by a 30 s scan of the elevation."""
    from cityshade.geo.sun import spa_angles, unix_seconds

    steps = P.plan_steps(date(2024, 6, 21), 0, 86_400, 600, "Europe/Berlin")
    res = A.surface_sun_hours(scene, [s.centre_utc for s in steps], 0.0,
                              weights_h=[s.weight_h for s in steps], samples_per_m2=0.02)
    roof = res.polygon_hours[scene.poly_ids.index("br")]
    assert roof == res.hours_sun_up
    sun = res.suns[0]
    t0 = unix_seconds(steps[0].start_utc)
    scan = t0 + 15.0 + 30.0 * np.arange(2880)
    _, el = spa_angles(scan, sun.latitude_deg, sun.longitude_deg, sun.height_m, sun.delta_t_s)
    day_h = float((el > 0).sum()) * 30.0 / 3600.0
    assert 15.5 < day_h < 16.5
    assert abs(roof - day_h) <= 1.0 / 6.0, (roof, day_h)


def test_polar_night_lights_nothing(scene):
    from cityshade.raster.camera import map_view

    suns = [sun_from_angles(180.0, -1.0), sun_from_angles(180.0, 0.0)]
    res = A.sun_hours(scene, map_view(scene, 4.0), _instants(2), 0.0, suns=suns)
    assert res.units == 0 and res.steps_below_horizon == 2
    assert (res.hours[res.valid] == 0).all() and np.isfinite(res.hours[res.valid]).all()
    assert any("below the horizon in all 2 steps" in w for w in res.warnings)


def test_api_validation(scene):
    from cityshade.raster.camera import map_view

    cam = map_view(scene, 4.0)
    with pytest.raises(UsageError, match="at least one instant"):
        A.sun_hours(scene, cam, [], 0.0)
    with pytest.raises(UsageError, match="aware"):
        A.sun_hours(scene, cam, [datetime(2024, 6, 21, 12)], 0.0, weights_h=[1.0])
    with pytest.raises(UsageError, match="single instant"):
        A.sun_hours(scene, cam, _instants(1), 0.0)
    uneven = _instants(2) + [datetime(2024, 6, 21, 9, tzinfo=timezone.utc)]
    with pytest.raises(UsageError, match="evenly spaced"):
        A.sun_hours(scene, cam, uneven, 0.0)
    with pytest.raises(UsageError, match="one value per instant"):
        A.sun_hours(scene, cam, _instants(2), 0.0, weights_h=[1.0])
    with pytest.raises(UsageError, match="nothing to compute"):
        A.sun_hours(scene, None, _instants(2), 0.0)
    with pytest.raises(UsageError, match="one sun per instant"):
        A.sun_hours(scene, cam, _instants(2), 0.0, suns=_explicit_suns())
    with pytest.raises(UsageError, match="samples per m²"):
        A.surface_sun_hours(scene, _instants(2), 0.0, samples_per_m2=0.0)


# --- resume -------------------------------------------------------------------------------------

class Stop(Exception):
    pass


def test_interrupted_and_resumed_run_is_bit_identical(scene, tmp_path):
    from cityshade.raster.camera import map_view

    cam = map_view(scene, PX)
    steps = P.plan_steps(date(2024, 6, 21), P.parse_clock_s("05:00"), P.parse_clock_s("21:00"),
                         3600, "Europe/Berlin")
    kwargs = dict(weights_h=[s.weight_h for s in steps], samples_per_m2=0.05)
    instants = [s.centre_utc for s in steps]
    straight = A.sun_hours(scene, cam, instants, 0.0, **kwargs)

    def stop_after(n):
        def hook(done, total, unit):
            if done == n:
                raise Stop
        return hook

    ck = C.Checkpoint(tmp_path / C.STATE_NAME, "k1")
    with pytest.raises(Stop):
        A.sun_hours(scene, cam, instants, 0.0, checkpoint=ck, on_step=stop_after(3), **kwargs)
    with pytest.raises(Stop):  # a second interruption, resumed from the first one's state
        A.sun_hours(scene, cam, instants, 0.0, checkpoint=ck, on_step=stop_after(9), **kwargs)
    assert ck.units_done() == 9
    resumed = A.sun_hours(scene, cam, instants, 0.0, checkpoint=ck, **kwargs)
    assert resumed.units_resumed == 9 and resumed.units == straight.units == 16
    assert resumed.hours.tobytes() == straight.hours.tobytes()
    assert resumed.sample_hours.tobytes() == straight.sample_hours.tobytes()
    # A state of other parameters is refused.
    with pytest.raises(UsageError, match="other parameters"):
        A.sun_hours(scene, cam, instants, 0.0, checkpoint=C.Checkpoint(ck.path, "k2"),
                    **kwargs)
    # A damaged state is refused with the way out.
    ck.path.write_bytes(b"not a state")
    with pytest.raises(UsageError, match="damaged.*--overwrite"):
        A.sun_hours(scene, cam, instants, 0.0, checkpoint=ck, **kwargs)
    ck.path.write_bytes(b"PK\x03\x04" + b"\0" * 40)  # a truncated zip: not BadZipFile
    with pytest.raises(UsageError, match="damaged.*--overwrite"):
        A.sun_hours(scene, cam, instants, 0.0, checkpoint=ck, **kwargs)


# --- outputs ------------------------------------------------------------------------------------

def test_colour_map_png_has_legend():
    hours = np.array([[0.0, 4.0], [8.0, np.nan]], np.float32)
    img = O.colour_map_png(np.kron(hours, np.ones((50, 50))))
    assert img.dtype == np.uint8 and img.shape[1] == 100 and img.shape[0] > 100
    assert (img[75, 75] == 255).all()  # no surface: white
    assert tuple(img[10, 10]) == (68, 1, 84) and tuple(img[60, 10]) == (253, 231, 37)
    legend = img[100:]
    assert (legend == 0).all(axis=2).sum() > 20  # label ink
    assert len({tuple(c) for c in legend.reshape(-1, 3)}) > 20  # the colour bar


# --- CLI ----------------------------------------------------------------------------------------

def _run(*args):
    from cityshade.cli.main import cli

    return CliRunner().invoke(cli, [str(a) for a in args])


def _one_line_error(result, fragment, code):
    assert result.exit_code == code, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("cityshade: error: "), result.output
    assert fragment in lines[0], lines[0]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("batch_cli")
    src = tmp / "box.gml"
    src.write_text(city(ground(X0 - 100, Y0 - 100, X0 + 100, Y0 + 100, Z0),
                        building("box", box_polygons(X0 - 5, Y0 - 5, Z0, 10, 10, H, "b"))))
    out, _, _ = build_file(src, tmp / "box.cityshade")
    nocrs = tmp / "nocrs.gml"
    nocrs.write_text(city(building("b1", box_polygons(0, 0, 0, 10, 8, 6), solid_refs=False)))
    out2, _, _ = build_file(nocrs, tmp / "nocrs.cityshade")
    return out, out2


ARGS = ("--date", "2024-06-21", "--from", "05:00", "--to", "21:00", "--every", "1h", "--tz",
        "Europe/Berlin", "--pixel-size", "4")


def test_cli_batch_writes_everything(files, tmp_path):
    import csv

    from cityshade.imageio import read_exr, read_image
    from cityshade.store.scenefile import load_scene

    scene_path, _ = files
    out = tmp_path / "run"
    result = _run("batch", scene_path, *ARGS, "--frames", "--surfaces", "--samples-per-m2",
                  "0.05", "-o", out, "-v")
    assert result.exit_code == 0, result.output
    assert "16 sun positions computed" in result.output and "ΔT" in result.output
    # -v says which engine the default technique (exact) took for the pixels, and why.
    engine = [ln for ln in result.output.splitlines() if ln.startswith("engine   ")]
    assert len(engine) == 1 and engine[0].startswith(
        ("engine   exact engine izb over ", "engine   exact engine raytrace over ")), engine
    assert " sun positions; the first: " in engine[0] and " casters, " in engine[0]
    channels, meta = read_exr(out / "sun_hours.exr")
    hours = channels["sun_hours"]
    assert meta["cityshade:steps"] == 16 and meta["cityshade:refraction"] == "on"
    assert np.nanmax(hours) == pytest.approx(16.0)
    # The API gives the same numbers.
    scene = load_scene(scene_path)
    from cityshade.raster.camera import default_map_margin_m, map_extent, map_view

    steps = P.plan_steps(date(2024, 6, 21), 5 * 3600, 21 * 3600, 3600, "Europe/Berlin")
    # The command's map keeps a margin of twice the model's height around it.
    extent = map_extent(scene, None, default_map_margin_m(scene))
    api = A.sun_hours(scene, map_view(scene, 4.0, bbox=extent), [s.centre_utc for s in steps],
                      _city_days("2024-06-21"), weights_h=[s.weight_h for s in steps],
                      ground="auto")  # the command's default ground fills the margin
    np.testing.assert_array_equal(np.nan_to_num(hours, nan=-1), np.nan_to_num(api.hours, nan=-1))
    png, _ = read_image(out / "sun_hours.png")
    # Decorated by default (title, scale bar, north, CRS, colour bar in a margin): the map's
    # values are checked in the GeoTIFF; the picture is larger than the map.
    assert png.shape[0] > hours.shape[0] and png.shape[1] >= max(64, hours.shape[1])
    tif, _ = read_image(out / "sun_hours.tif")
    np.testing.assert_array_equal(np.nan_to_num(tif[..., 0], nan=-1),
                                  np.nan_to_num(hours, nan=-1))
    assert (out / "sun_hours.tfw").is_file() and (out / "sun_hours.prj").is_file()
    frames = sorted((out / "frames").glob("step_*.png"))
    assert len(frames) == 16
    with (out / "surfaces.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(scene.poly_ids) == 7
    roof = next(r for r in rows if r["polygon_id"] == "br")
    assert roof["object_id"] == "box" and roof["surface_class"] == "roof"
    assert float(roof["area_m2"]) == pytest.approx(100.0) and float(roof["mean_sun_hours"]) == 16
    # The same rows as GIS layers, and a report that opens in a browser.
    pyogrio = pytest.importorskip("pyogrio")
    meta, _, geoms, values = pyogrio.raw.read(out / "results.gpkg", layer="surfaces")
    fields = list(meta["fields"])
    assert [str(v) for v in values[fields.index("polygon_id")]] == [r["polygon_id"] for r in rows]
    assert [f"{v:.4f}" for v in values[fields.index("mean_sun_hours")]] == \
        [r["mean_sun_hours"] for r in rows]
    assert "<img src=\"data:image/png;base64," in (out / "report.html").read_text()
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["status"] == "finished" and manifest["finished_steps"] == list(range(16))
    assert manifest["params"]["tz"] == "Europe/Berlin" and len(manifest["key"]) == 64
    # The same command again: the run is complete, nothing is computed; with --overwrite it
    # computes again (a finished run keeps no state), the same.
    assert not (out / C.STATE_NAME).exists()
    args = (*ARGS, "--frames", "--surfaces", "--samples-per-m2", "0.05", "-o", out, "-v")
    again = _run("batch", scene_path, *args)
    assert again.exit_code == 0 and again.output.splitlines() == [
        f"{out}: already complete (same request); nothing to do (--overwrite computes it "
        f"again)"]
    again = _run("batch", scene_path, *args, "--overwrite")
    assert again.exit_code == 0 and "16 sun positions computed, 0 taken" in again.output
    assert read_exr(out / "sun_hours.exr")[0]["sun_hours"].tobytes() == hours.tobytes()


def _city_days(text):
    from cityshade.geo.temporal import parse_user_date

    return parse_user_date(text).city_days


def _resume_equals_straight(scene_path, straight, out):
    """Resume the run in ``out`` (5 positions saved) and compare it with ``straight``."""
    from cityshade.imageio import read_exr

    resumed = _run("batch", scene_path, *ARGS, "-o", out, "-v")
    assert resumed.exit_code == 0 and "5 taken from the saved state" in resumed.output
    a = read_exr(straight / "sun_hours.exr")[0]["sun_hours"]
    b = read_exr(out / "sun_hours.exr")[0]["sun_hours"]
    assert a.tobytes() == b.tobytes()


def test_cli_resumes_after_interruption(files, tmp_path, monkeypatch):
    scene_path, _ = files
    straight = tmp_path / "straight"
    assert _run("batch", scene_path, *ARGS, "-o", straight).exit_code == 0
    out = tmp_path / "interrupted"
    real_save = C.Checkpoint.save

    def save_then_interrupt(self, done, *a):
        real_save(self, done, *a)
        if done == 5:
            raise KeyboardInterrupt

    monkeypatch.setattr(C.Checkpoint, "save", save_then_interrupt)
    monkeypatch.setattr(C, "CHECKPOINT_EVERY_S", 0.0)  # a save after every position
    cut = _run("batch", scene_path, *ARGS, "-o", out)
    assert cut.exit_code == 130 and "cityshade: interrupted" in cut.output
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["status"] == "running" and manifest.get("sun_positions_done") in (4, 5)
    monkeypatch.setattr(C.Checkpoint, "save", real_save)
    _resume_equals_straight(scene_path, straight, out)


def test_interruption_between_saves_keeps_every_finished_position(files, tmp_path,
                                                                  monkeypatch):
    # With the default interval nothing is saved during this short run until the interruption
    # (inside the 6th position's shadows); the state must then hold the 5 finished positions.

    scene_path, _ = files
    straight = tmp_path / "straight"
    assert _run("batch", scene_path, *ARGS, "-o", straight).exit_code == 0
    out = tmp_path / "interrupted"
    saves = []
    real_save, real_lit = C.Checkpoint.save, A._PixelRays.lit
    calls = iter(range(1000))

    def counting_save(self, done, *a):
        saves.append(done)
        real_save(self, done, *a)

    def lit_then_interrupt(self, *a):
        if next(calls) == 5:
            raise KeyboardInterrupt
        return real_lit(self, *a)

    monkeypatch.setattr(C.Checkpoint, "save", counting_save)
    monkeypatch.setattr(A._PixelRays, "lit", lit_then_interrupt)
    cut = _run("batch", scene_path, *ARGS, "-o", out)
    assert cut.exit_code == 130 and saves == [5]
    monkeypatch.setattr(A._PixelRays, "lit", real_lit)
    _resume_equals_straight(scene_path, straight, out)


def test_cli_batch_failures(files, tmp_path):
    scene_path, nocrs = files
    out = tmp_path / "f"
    assert _run("batch", scene_path, *ARGS, "-o", out).exit_code == 0
    _one_line_error(_run("batch", scene_path, *ARGS[:-2], "--pixel-size", "8", "-o", out),
                    "other parameters (differs in: camera)", 2)
    ok = _run("batch", scene_path, *ARGS[:-2], "--pixel-size", "8", "-o", out, "--overwrite")
    assert ok.exit_code == 0, ok.output
    base = ("batch", scene_path, "--date", "2024-06-21", "--tz", "UTC", "-o", tmp_path / "g")
    _one_line_error(_run(*base, "--every", "10"), "cannot read duration", 2)
    _one_line_error(_run(*base, "--from", "10:00", "--to", "09:00"), "--to must be later", 2)
    _one_line_error(_run(*base, "--days", "2", "--to-date", "2024-07-01"), "not both", 2)
    _one_line_error(_run(*base, "--days", "0"), "--days must be >= 1", 2)
    _one_line_error(_run(*base[:3], "2024-13-01", *base[4:]), "--date must be a day", 2)
    _one_line_error(_run(*base[:5], "Europe/Nowhere", *base[6:]), "unknown time zone", 2)
    _one_line_error(_run(*base, "--shadows", "magic"), "unknown shadow technique", 2)
    _one_line_error(_run(*base, "--surfaces", "--samples-per-m2", "0"), "samples per m²", 2)
    _one_line_error(_run(*base, "--from", "5am"), "cannot read time of day", 2)
    _one_line_error(_run("batch", nocrs, *base[2:]), "--crs", 1)
    missing_tz = _run("batch", scene_path, "--date", "2024-06-21", "-o", tmp_path / "h")
    assert missing_tz.exit_code == 2 and "--tz" in missing_tz.output


@pytest.mark.parametrize("damage", ["truncated", "bit-flipped"])
def test_damaged_state_is_detected_and_its_steps_start_again(files, tmp_path, damage,
                                                             stop_batch_after):
    """Issue 13 point 9: a truncated or altered state.npz gave zipfile.BadZipFile (or, worse,
    was read); the manifest's checksum finds it, one warning line, the steps are redone."""
    from cityshade.imageio import read_exr

    scene_path, _ = files
    straight = tmp_path / "straight"
    assert _run("batch", scene_path, *ARGS, "-o", straight).exit_code == 0
    hours = read_exr(straight / "sun_hours.exr")[0]["sun_hours"].copy()
    # A finished run keeps no state: stop one part-way to have a state to damage.
    out = tmp_path / "run"
    stop_batch_after(5)
    assert _run("batch", scene_path, *ARGS, "-o", out).exit_code == 130
    stop_batch_after(None)
    state = out / C.STATE_NAME
    data = bytearray(state.read_bytes())
    if damage == "truncated":
        data = data[: len(data) // 2]
    else:
        data[len(data) - 200] ^= 0x10  # inside the pixel sums: still a readable zip
    state.write_bytes(bytes(data))
    again = _run("batch", scene_path, *ARGS, "-o", out, "-v")
    assert again.exit_code == 0, again.output
    warnings = [line for line in again.output.splitlines() if "warning" in line]
    assert warnings == [f"cityshade: warning: the saved state {state} is damaged (its checksum "
                        f"does not match the manifest); the unfinished steps start again"]
    assert "16 sun positions computed, 0 taken from the saved state" in again.output
    assert read_exr(out / "sun_hours.exr")[0]["sun_hours"].tobytes() == hours.tobytes()
    manifest = json.loads((out / "manifest.json").read_text())
    # Finished: the state served its purpose and is gone, and the manifest names none.
    assert not state.exists() and "state_sha256" not in manifest
    third = _run("batch", scene_path, *ARGS, "-o", out, "-v")
    assert third.exit_code == 0 and third.output.splitlines() == [
        f"{out}: already complete (same request); nothing to do (--overwrite computes it "
        f"again)"]


def test_run_batch_from_python_resumes_and_refuses_other_parameters(files, tmp_path):
    """The resume protocol without the CLI: manifest, parameter hash, state, overwrite."""
    import dataclasses

    from cityshade.config import Settings
    from cityshade.raster.camera import map_view
    from cityshade.store.scenefile import load_scene

    scene = load_scene(files[0])
    steps = P.plan_steps(date(2024, 6, 21), P.parse_clock_s("05:00"), P.parse_clock_s("21:00"),
                         3600.0, "Europe/Berlin")
    cam = map_view(scene, 4.0)
    out = tmp_path / "py"
    def request(settings=None):
        return SunHoursRequest.from_settings(steps, 0.0, settings, camera=cam,
                                             provenance={"what": "test"})

    first = R.run_batch(out, scene, request())
    assert first.manifest["status"] == "finished" and first.result.units_resumed == 0
    assert json.loads((out / "manifest.json").read_text())["key"] == first.manifest["key"]
    assert not (out / C.STATE_NAME).exists()  # a finished run keeps no state
    done = R.run_batch(out, scene, request())  # finished: nothing computed or written
    assert done.already_complete and done.result is None
    assert done.manifest == first.manifest and done.written == first.written
    again = R.run_batch(out, scene, request(), overwrite=True)
    assert again.result.units_resumed == 0 and again.result.units == first.result.units > 0
    assert again.result.hours.tobytes() == first.result.hours.tobytes()
    # Other shadow settings are other parameters: refused, unless overwrite.
    other = dataclasses.replace(Settings(), shadows=Settings().shadows.override(map_px=64))
    with pytest.raises(UsageError, match="differs in: shadow_settings"):
        R.run_batch(out, scene, request(other))
    redone = R.run_batch(out, scene, request(other), overwrite=True)
    assert redone.result.units_resumed == 0
    assert redone.result.hours.tobytes() == first.result.hours.tobytes()  # exact (izb): no map


def test_izb_default_equals_raytrace_for_pixels_and_surfaces(scene):
    """The default exact engine of a batch (izb) gives raytrace's sun-hours, bit for bit."""
    cam = __import__("cityshade.raster.camera", fromlist=["map_view"]).map_view(scene, PX)
    runs = [A.sun_hours(scene, cam, _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                        suns=_explicit_suns(), samples_per_m2=0.05, technique=name)
            for name in ("izb", "raytrace")]
    assert runs[0].hours.tobytes() == runs[1].hours.tobytes()
    assert runs[0].sample_hours.tobytes() == runs[1].sample_hours.tobytes()
    assert (runs[0].hours[runs[0].valid] > 0).any() and (runs[0].sample_hours == 0).any()


@pytest.mark.parametrize("compiled", [False, True])
def test_exact_batch_records_its_engine_choice(scene, monkeypatch, compiled):
    """The run's diagnostics say which engine ``exact`` took over its sun positions and why,
    the compile of izb counted while it is not compiled (shadows.exact.izb_compiled)."""
    from cityshade.raster.camera import map_view
    from cityshade.shadows import exact as E

    monkeypatch.setattr(E, "izb_compiled", lambda: compiled)
    run = A.sun_hours(scene, map_view(scene, PX), _instants(len(SUNS)), 0.0, weights_h=WEIGHTS,
                      suns=_explicit_suns(), technique="exact")
    note = run.diagnostics["engine"]
    # The suns above the horizon, less the repeated one, are the calls.
    assert note.startswith("exact engine ") and " over 4 sun positions; the first: " in note
    assert ("izb not compiled yet" in note) is (not compiled)
    if not compiled:       # a few small calls never win back izb's compile
        assert note.startswith("exact engine raytrace over ")
