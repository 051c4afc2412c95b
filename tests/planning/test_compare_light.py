"""compare with a weather file: BRE 209's VSC and APSH rules on a south-facing window, against a
count made here from the TMY file's DNI column and pvlib's sun; the CLI's lines."""
from __future__ import annotations

import csv
import math
import os
from datetime import date, datetime, timedelta, timezone
from pathlib import Path

import numpy as np
import pytest
from citygml_snippets import box_polygons, building, city, wall_with_window
from click.testing import CliRunner

# A TMY3 file that ships inside pvlib: Greensboro NC (36.1° N, 79.95° W, UTC-5).
GREENSBORO = os.path.join(os.path.dirname(__import__("pvlib").__file__), "data",
                          "723170TYA.CSV")
PLACE = (-79.95, 36.1)
SRS = "EPSG:32617"


def _utm(lon_deg, lat_deg):
    from pyproj import Transformer

    return Transformer.from_crs("EPSG:4326", SRS, always_xy=True).transform(lon_deg, lat_deg)


def _turn(points, x0, y0):
    """Points given with the window's normal along -y, turned so that it faces true south at
    the place (two points of its meridian projected with pyproj), moved to (x0, y0)."""
    (xn, yn), (xs, ys) = _utm(PLACE[0], PLACE[1] + 0.001), _utm(PLACE[0], PLACE[1] - 0.001)
    angle = math.atan2(ys - yn, xs - xn) - math.atan2(-1.0, 0.0)
    c, s = math.cos(angle), math.sin(angle)
    return [(x0 + c * x - s * y, y0 + s * x + c * y, z) for x, y, z in points]


def _wall_with_window(x0, y0):
    """A free 10 m x 3 m wall whose 1 m x 0.2 m window (gml:id WIN, centre 1.1 m up) faces
    true south."""
    return wall_with_window(lambda pts: _turn(pts, x0, y0), SRS)


@pytest.fixture(scope="module")
def window_files(tmp_path_factory):
    """The wall's scene file and a proposal: a 30 m high, 200 m long block 5 m south of it."""
    from cityshade.build import build_scene_from_file
    from cityshade.store.scenefile import save_scene

    tmp = tmp_path_factory.mktemp("bre")
    x0, y0 = (round(v) for v in _utm(*PLACE))
    (tmp / "wall.gml").write_text(city(_wall_with_window(x0, y0)))
    scene_path = tmp / "wall.cityshade"
    save_scene(build_scene_from_file(tmp / "wall.gml"), scene_path, {}, {})
    faces = [(cls, pid, _turn([(x - x0, y - y0, z) for x, y, z in pts], x0, y0))
             for cls, pid, pts in box_polygons(x0 - 100.0, y0 - 15.0, 0.0, 200.0, 10.0, 30.0,
                                               "b")]
    (tmp / "block.gml").write_text(city(building("BLOCK", faces, srs=SRS)))
    return scene_path, tmp / "block.gml"


def _independent_apsh(scene):
    """(APSH, winter APSH) of a free window facing true south, counted from the TMY3 file:
    hours whose DNI field is >= 120 W/m² with pvlib's apparent sun above the horizon at the
    middle of the hour (records stamp the hour's END in local standard time, UTC-5), those
    with the sun's azimuth within 90° of south, and of them those from 21 September to
    21 March."""
    import pandas as pd
    import pvlib
    from pyproj import Transformer

    lon, lat = Transformer.from_crs(SRS, "EPSG:4326", always_xy=True).transform(
        scene.origin_m[0], scene.origin_m[1])
    with open(GREENSBORO, newline="") as f:
        rows = list(csv.reader(f))[2:]
    local = timezone(timedelta(hours=-5))
    times = [datetime.strptime(r[0], "%m/%d/%Y").replace(tzinfo=local)
             + timedelta(hours=int(r[1][:2]) - 0.5) for r in rows]
    z = float(scene.origin_m[2])
    sun = pvlib.solarposition.get_solarposition(pd.DatetimeIndex(times), lat, lon, altitude=z,
                                                pressure=pvlib.atmosphere.alt2pres(z),
                                                temperature=12.0)
    dni = np.array([float(r[7]) for r in rows])
    sunny = (dni >= 120.0) & (sun["apparent_elevation"].to_numpy() > 0.0)
    front = sunny & (np.abs(sun["azimuth"].to_numpy() - 180.0) < 90.0)
    winter = np.array([(t.month, t.day) >= (9, 21) or (t.month, t.day) <= (3, 21)
                       for t in times])
    return front.sum() / sunny.sum(), (front & winter).sum() / sunny.sum(), sunny.sum()


def test_bre209_window_rules_with_a_tmy_file(window_files):
    """Before: the free window's APSH is the independent count; its VSC is BRE's 39.6 %
    (unobstructed). After: the block takes its sky and sun; both rules fail, with the
    numbers they rest on."""
    from cityshade.planning.rules import load_rules
    from cityshade.planning.run import (
        CompareRequest,
        CompareStates,
        TimePlan,
        run_compare,
    )
    from cityshade.store.scenefile import load_scene

    scene_path, block = window_files
    rules = [r for r in load_rules("bre209") if r.id != "bre209-garden"]
    request = CompareRequest(scene_path, TimePlan(date(2025, 3, 21), from_s=43200, to_s=46800,
                                                  every_s=3600.0, tz="UTC"),
                             CompareStates(proposal=block), camera=None, surfaces=False,
                             rules=rules, weather=GREENSBORO)
    result = run_compare(request)
    vsc, apsh = result.verdicts
    apsh_h, winter_h, sunny_h = _independent_apsh(load_scene(scene_path))
    (d,) = apsh.details
    assert d["receiver"] == "WIN" and apsh.numbers["sunny_h"] == sunny_h
    assert d["apsh_before"] == apsh_h and d["winter_before"] == winter_h
    assert 0.3 < apsh_h < 0.9 and 0.05 < winter_h < apsh_h
    # Behind the block (its top 75° above the window) little sun is left.
    assert d["apsh_after"] < 0.25 * d["apsh_before"] and d["loss"] > 0.04
    assert (d["status"], apsh.status) == ("fail", "fail")
    (w,) = vsc.details
    assert w["vsc_before"] == pytest.approx(0.396, abs=0.002)
    assert w["vsc_after"] < 0.8 * w["vsc_before"] and vsc.status == "fail"
    o = result.comparison.opening
    assert o["apsh_before"][0] == apsh_h and o["vsc_after"][0] == w["vsc_after"]
    warnings = result.comparison.warnings
    assert not any("weather was recorded" in x for x in warnings)  # 2 km from the station


def test_compare_cli_without_weather_and_with_a_garbled_one(window_files, tmp_path):
    from cityshade.cli.main import cli

    scene_path, block = window_files
    args = ["compare", str(scene_path), "--with", str(block), "--rules", "bre209",
            "--date", "2025-03-21", "--from", "12:00", "--to", "13:00", "--every", "1h",
            "--tz", "UTC", "--pixel-size", "4", "--no-decorate", "--no-gis"]
    r = CliRunner().invoke(cli, args + ["-o", str(tmp_path / "a")])
    assert r.exit_code == 0, r.output
    lines = r.output.splitlines()
    assert ("bre209-window: NOT ASSESSED — needs --weather FILE: annual probable sunlight "
            "hours are the sunny hours (direct normal irradiance ≥ 120 W/m²) of a "
            "typical-year weather file (EPW, TMY3 or TMY2) that reach each window") in lines
    vsc = lines.index(next(x for x in lines if x.startswith("bre209-vsc: FAIL")))
    assert lines[vsc + 1].startswith("  WIN: VSC 39.") and lines[vsc + 1].endswith(": FAIL")
    header = (tmp_path / "a" / "openings.csv").read_text().splitlines()[0]
    assert header.endswith("vsc_before_pct,vsc_after_pct,apsh_before_pct,apsh_after_pct,"
                           "winter_apsh_before_pct,winter_apsh_after_pct")
    # A record with a garbled DNI: one line naming the file and the line, nothing written.
    lines = Path(GREENSBORO).read_text().splitlines()
    fields = lines[10].split(",")
    fields[7] = "abc"
    lines[10] = ",".join(fields)
    bad = tmp_path / "bad.csv"
    bad.write_text("\n".join(lines) + "\n")
    r = CliRunner().invoke(cli, args + ["--weather", str(bad), "-o", str(tmp_path / "b")])
    assert r.exit_code != 0
    assert r.output.strip().splitlines() == [(
        f"cityshade: error: {bad}:11: dni of record 9 is 'abc': not a number within 0 to 1500 W/m² "
        f"(EPW writes 9999 for missing)")]
    assert not (tmp_path / "b").exists()
