"""``cityshade sky``: the sky view factor of a street canyon's floor (Oke's closed form) and of
open ground through the command, its files, and the exact line of each bad request."""
from __future__ import annotations

import csv
import math
import os

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city, ground

from cityshade.cli.main import cli

X0, Y0 = 690_000.0, 5_336_000.0
H_M = W_M = 10.0


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def _rows(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def canyon_file(tmp_path_factory):
    """Two 10 m high, 400 m long blocks along y, 10 m apart (H/W = 1), a 0.2 x 1 m floor patch
    at the canyon's centre and a 1 m² patch of open ground 150 m east of the canyon."""
    tmp = tmp_path_factory.mktemp("sky_canyon")
    long_m = 40 * H_M
    west = building("W", box_polygons(X0 - W_M / 2 - 10, Y0 - long_m / 2, 0.0, 10.0, long_m,
                                      H_M, "w"))
    east = building("E", box_polygons(X0 + W_M / 2, Y0 - long_m / 2, 0.0, 10.0, long_m, H_M,
                                      "e"))
    floor = ground(X0 - 0.1, Y0 - 0.5, X0 + 0.1, Y0 + 0.5, gid="floor")
    open_ground = ground(X0 + 150.0, Y0, X0 + 151.0, Y0 + 1.0, gid="open")
    gml = tmp / "canyon.gml"
    gml.write_text(city(west, east, floor, open_ground))
    out = tmp / "canyon.cityshade"
    result = run("build", gml, "-o", out)
    assert result.exit_code == 0, result.output
    return out


def test_canyon_floor_and_open_ground_through_the_command(canyon_file, tmp_path):
    result = run("sky", canyon_file, "-o", tmp_path / "out", "--no-map", "--surfaces",
                 "--samples-per-m2", "0.001", "--city-date", "2020-01-01")
    assert result.exit_code == 0, result.output
    rows = {r["polygon_id"] or r["object_id"]: r for r in _rows(tmp_path / "out" / "surfaces.csv")}
    # Oke (1988): cos(arctan(2H/W)) = 0.447 at the floor centre of a long canyon, H/W = 1.
    expected = math.cos(math.atan(2 * H_M / W_M))
    assert float(rows["floor_poly"]["svf"]) == pytest.approx(expected, abs=0.005)
    # Open ground 150 m from 10 m high blocks: the sky below 3.8° is all it misses.
    assert float(rows["open_poly"]["svf"]) == pytest.approx(1.0, abs=0.005)
    assert float(rows["wr"]["svf"]) == 1.0 and float(rows["er"]["svf"]) == 1.0
    # The outer walls see half the sky; the canyon's inner walls less.
    assert float(rows["ww"]["svf"]) == pytest.approx(0.5, abs=0.005)
    assert float(rows["we"]["svf"]) < 0.4
    buildings = {r["building_id"]: r for r in _rows(tmp_path / "out" / "buildings.csv")}
    assert set(buildings) >= {"W", "E"}
    assert float(buildings["W"]["roof_svf"]) == 1.0
    assert float(buildings["W"]["wall_area_m2"]) == pytest.approx(2 * 400 * 10 + 2 * 10 * 10)
    assert "roof_kwh" not in buildings["W"]  # no weather: no energy columns


@pytest.fixture(scope="module")
def small_file(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("sky_small")
    gml = tmp / "small.gml"
    # In Greensboro (UTM 17N), where pvlib's TMY3 file was recorded.
    x0, y0 = 608_000.0, 3_996_000.0
    gml.write_text(city(
        building("b1", box_polygons(x0, y0, 0.0, 10.0, 8.0, 6.0, "p"), srs="EPSG:32617"),
        building("b2", box_polygons(x0 + 30.0, y0, 0.0, 5.0, 5.0, 20.0, "q"), srs="EPSG:32617")))
    out = tmp / "small.cityshade"
    assert run("build", gml, "-o", out).exit_code == 0
    return out


def _tmy3():
    import pvlib

    return os.path.join(os.path.dirname(pvlib.__file__), "data", "723170TYA.CSV")


def test_maps_surfaces_and_irradiance_files(small_file, tmp_path):
    from cityshade.imageio import read_image

    out = tmp_path / "out"
    result = run("sky", small_file, "-o", out, "--sky", "tregenza", "--pixel-size", "2",
                 "--surfaces", "--samples-per-m2", "0.05", "--weather", _tmy3(), "--irradiance",
                 "--from-date", "06-20", "--to-date", "06-21", "--city-date", "2020-01-01")
    assert result.exit_code == 0, result.output
    for name in ("svf.exr", "svf.tif", "svf.png", "irradiance_kwh_m2.exr",
                 "irradiance_kwh_m2.tif", "irradiance_kwh_m2.png", "surfaces.csv",
                 "buildings.csv"):
        assert (out / name).is_file(), name
    assert "warning" not in result.output  # the model stands where the weather was recorded
    svf, _ = read_image(out / "svf.tif")
    svf = np.asarray(svf, np.float64).squeeze()
    finite = svf[np.isfinite(svf)]
    assert finite.max() == pytest.approx(1.0, abs=1e-6) and finite.min() >= 0.0
    rows = _rows(out / "surfaces.csv")
    roofs = [r for r in rows if r["surface_class"] == "roof"]
    walls = [r for r in rows if r["surface_class"] == "wall"]
    assert roofs and walls
    # Two days of June: a free roof gets more than a wall, every part non-negative.
    assert max(float(r["irradiance_kwh_m2"]) for r in roofs) > \
        max(float(r["irradiance_kwh_m2"]) for r in walls) > 0.0
    for r in rows:
        parts = [float(r[k]) for k in ("direct_kwh_m2", "diffuse_kwh_m2", "reflected_kwh_m2")]
        assert min(parts) >= 0.0
        assert sum(parts) == pytest.approx(float(r["irradiance_kwh_m2"]), abs=2e-4)
    _check_report(out, rows, tmp_path)
    _check_layers(out, rows)


def _check_layers(out, rows):
    """results.gpkg: the surfaces with surfaces.csv's ids and values in the model's CRS, and
    a default QGIS style colouring the kWh/m²."""
    import sqlite3
    import xml.etree.ElementTree as ET

    pyogrio = pytest.importorskip("pyogrio")
    gpkg = out / "results.gpkg"
    meta, _, _, fields = pyogrio.raw.read(gpkg, layer="surfaces", read_geometry=False)
    assert meta["crs"] == "EPSG:32617"
    table = dict(zip(meta["fields"], fields))
    assert list(table["polygon_id"]) == [r["polygon_id"] for r in rows]
    for name in ("surface_class", "object_id"):
        assert list(table[name]) == [r[name] for r in rows]
    for name in ("svf", "irradiance_kwh_m2", "area_m2"):
        np.testing.assert_allclose(np.asarray(table[name], float),
                                   [float(r[name]) for r in rows], atol=5e-4)
    with sqlite3.connect(gpkg) as db:
        styles = dict(db.execute("SELECT f_table_name, styleQML FROM layer_styles").fetchall())
    assert ET.fromstring(styles["surfaces"]).find("renderer-v2").get("attr") == \
        "irradiance_kwh_m2"


def _check_report(out, rows, tmp_path):
    """report.html: a valid self-contained page with both maps; its anchor (an open
    horizontal plane's kWh/m²) is the TMY3 file's GHI summed over the two days as pvlib reads
    it; its class table holds the area-weighted means of surfaces.csv."""
    import re

    import pvlib
    from htmlcheck import check_page

    assert len(check_page(out / "report.html", tmp_path)) == 2  # svf.png, irradiance png
    text = (out / "report.html").read_text(encoding="utf-8")
    data, _ = pvlib.iotools.read_tmy3(_tmy3(), map_variables=True)
    # TMY3 labels each record by its hour's end: the record of 00:00 belongs to the day before.
    middle = data.index - np.timedelta64(30, "m")
    days = (middle.month == 6) & np.isin(middle.day, (20, 21))
    ghi_kwh_m2 = float(data["ghi"].to_numpy()[days].sum()) / 1000.0
    anchor = re.search(r"receives <strong>([\d,]+) kWh/m²</strong>", text)
    assert anchor and int(anchor.group(1).replace(",", "")) == round(ghi_kwh_m2)
    for cls in ("roof", "wall"):
        mine = [r for r in rows if r["surface_class"] == cls]
        area = np.array([float(r["area_m2"]) for r in mine])
        kwh = np.array([float(r["irradiance_kwh_m2"]) for r in mine])
        cells = re.search(rf"<tr>\s*<td>{cls}</td>((?:\s*<td[^>]*>[^<]*</td>)+)", text)
        values = re.findall(r"<td[^>]*>([^<]*)</td>", cells.group(1))
        # surfaces, area m², mean SVF, mean kWh/m², MWh
        assert int(values[0]) == len(mine)
        assert float(values[1].replace(",", "")) == pytest.approx(area.sum(), abs=0.5)
        assert float(values[3].replace(",", "")) == pytest.approx(
            (area * kwh).sum() / area.sum(), abs=0.5)


@pytest.mark.parametrize("extra,line", [
    (["--irradiance"], ("cityshade: error: --irradiance needs --weather FILE (an .epw, TMY3 "
                        ".csv or TMY2 .tm2)")),
    (["--no-svf"], ("cityshade: error: nothing to write: --no-svf without --vsc, --irradiance "
                    "or --times")),
    (["--sky", "tregenza7"], ("cityshade: error: unknown sky 'tregenza7': one of tregenza, "
                              "reinhart577, reinhart2305 or uniform<degrees>")),
    (["--shadows", "pcf"], ("cityshade: error: sky view factors and irradiance need an exact "
                            "technique (exact, izb, raytrace), not 'pcf'")),
    (["--weather", "MISSING.epw", "--irradiance"],
     "cityshade: error: MISSING.epw: no such weather file"),  # a bad input file: status 1
    (["--weather", "MISSING.epw"], None),  # no --irradiance: the weather is not read
    (["--tile-px", "0"], "cityshade: error: --tile-px must be >= 1, not 0"),
    (["--scheduler", "lokal:2"],
     "cityshade: error: --scheduler is local, local:N or tcp://HOST:PORT, not 'lokal:2'"),
])
def test_bad_requests_say_one_line(small_file, tmp_path, extra, line):
    if line is None:
        extra = [*extra, "--no-map", "--surfaces", "--samples-per-m2", "0.001", "--sky",
                 "tregenza"]
    result = run("sky", small_file, "-o", tmp_path / "out", *extra)
    if line is None:
        assert result.exit_code == 0, result.output
        assert "cityshade: warning: --weather without --irradiance or --times: the weather " \
               "file is not read" in result.output
        return
    assert result.exit_code == (1 if "MISSING" in line else 2)  # 2: a bad request
    assert result.output.splitlines() == [line]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("extra,line", [
    # The map techniques' tunables are not options of sky (issue 40: none silently ignored).
    (["--bias", "0.1"], ("cityshade: error: No such option '--bias'. Did you mean '--times'? "
                         "(see 'cityshade sky --help')")),
    (["--smooth"], "cityshade: error: No such option '--smooth'. (see 'cityshade sky --help')"),
    (["--cascades", "2"], ("cityshade: error: No such option '--cascades'. (Did you mean one "
                           "of: '--cameras', '--shadows', '--surfaces'?) (see 'cityshade sky "
                           "--help')")),
    (["--season", "summer"], ("cityshade: error: Invalid value for '--season': 'summer' is not "
                              "one of 'leaf-on', 'leaf-off'. (see 'cityshade sky --help')")),
])
def test_options_sky_does_not_take_are_one_line(small_file, tmp_path, capsys, extra, line):
    from cityshade.cli.main import main

    with pytest.raises(SystemExit) as done:
        main(["sky", str(small_file), "-o", str(tmp_path / "out"), *extra])
    assert done.value.code == 2
    assert capsys.readouterr().err.splitlines() == [line]
    assert not (tmp_path / "out").exists()


def test_a_garbled_weather_file_is_named(small_file, tmp_path):
    bad = tmp_path / "bad.epw"
    bad.write_text("garbage\n1,2,3\n")
    result = run("sky", small_file, "-o", tmp_path / "out", "--weather", bad, "--irradiance")
    assert result.exit_code == 1
    assert result.output.splitlines() == [
        f"cityshade: error: {bad}: not a readable EPW file (pvlib: 'altitude')"]


def test_vsc_on_each_surface_s_plane(canyon_file, tmp_path):
    """``--vsc``: BRE 209's 39.6 % on a free vertical wall (the W block's outer wall), 100 %
    on a free roof and nearly on open ground (blocks 150 m away hide 3.8° of its horizon)."""
    out = tmp_path / "out"
    result = run("sky", canyon_file, "-o", out, "--no-map", "--surfaces", "--vsc", "--no-svf",
                 "--samples-per-m2", "0.001", "--city-date", "2020-01-01")
    assert result.exit_code == 0, result.output
    rows = {r["polygon_id"] or r["object_id"]: r for r in _rows(out / "surfaces.csv")}
    assert "svf" not in rows["ww"]
    assert float(rows["ww"]["vsc_pct"]) == pytest.approx(39.6, abs=0.2)
    assert float(rows["wr"]["vsc_pct"]) == pytest.approx(100.0, abs=1e-3)
    assert float(rows["open_poly"]["vsc_pct"]) == pytest.approx(100.0, abs=0.5)
    assert float(rows["we"]["vsc_pct"]) < 27.0      # the canyon's inner wall


def test_vsc_map_and_irradiance_at_instants(small_file, tmp_path):
    """A VSC map and W/m² at 12:20 file time (UTC−5, Greensboro's TMY3): the free top of the
    20 m block gets pvlib's horizontal irradiance of the hour ending 13:00 with pvlib's own
    sun at 12:20 (within 0.5 %: the two suns differ by the map's grid north and refraction)."""
    import datetime as dt

    import pvlib

    from cityshade.imageio import read_image
    from cityshade.light import read_weather

    out = tmp_path / "out"
    result = run("sky", small_file, "-o", out, "--sky", "tregenza", "--pixel-size", "2",
                 "--surfaces", "--samples-per-m2", "0.05", "--weather", _tmy3(), "--vsc",
                 "--date", "2025-06-11", "--times", "12:20,07:45", "--city-date", "2020-01-01",
                 "--no-gis")
    assert result.exit_code == 0, result.output
    for name in ("vsc.exr", "vsc.tif", "vsc.png", "irradiance_w_m2_1220.exr",
                 "irradiance_w_m2_1220.tif", "irradiance_w_m2_0745.png"):
        assert (out / name).is_file(), name
    assert not (out / "irradiance_kwh_m2.exr").exists()     # no --irradiance: no period
    vsc, _ = read_image(out / "vsc.tif")
    finite = np.asarray(vsc, np.float64)[np.isfinite(vsc)]
    assert finite.max() == pytest.approx(100.0, abs=1e-3) and finite.min() >= 0.0
    rows = {r["polygon_id"]: r for r in _rows(out / "surfaces.csv")}
    weather = read_weather(_tmy3())
    ends = weather.hour_end
    row = int(np.flatnonzero((ends.month == 6) & (ends.day == 11) & (ends.hour == 13))[0])
    t = dt.datetime(2025, 6, 11, 12, 20, tzinfo=dt.timezone(dt.timedelta(hours=-5)))
    loc = weather.location
    pos = pvlib.solarposition.get_solarposition(t, loc.latitude_deg, loc.longitude_deg)
    zenith = float(pos["apparent_zenith"].iloc[0])
    want = pvlib.irradiance.get_total_irradiance(
        0.0, 0.0, zenith, float(pos["azimuth"].iloc[0]), weather.dni_w_m2[row],
        weather.ghi_w_m2[row], weather.dhi_w_m2[row],
        dni_extra=pvlib.irradiance.get_extra_radiation(t),
        airmass=pvlib.atmosphere.get_relative_airmass(zenith), albedo=0.2, model="perez")
    assert float(rows["qr"]["irradiance_w_m2_1220"]) == pytest.approx(
        float(want["poa_global"]), rel=5e-3)
    assert float(rows["qr"]["vsc_pct"]) == pytest.approx(100.0, abs=1e-3)
    assert 0.0 < float(rows["ps"]["irradiance_w_m2_1220"]) < float(rows["qr"]["irradiance_w_m2_1220"])


@pytest.mark.parametrize("extra,line", [
    (["--date", "2025-06-11"], ("cityshade: error: give --date and --times together (the "
                                "instants of the irradiance in W/m²)")),
    (["--date", "2025-06-11", "--times", "12:00"],
     "cityshade: error: --times needs --weather FILE (an .epw, TMY3 .csv or TMY2 .tm2)"),
    (["--tz", "Europe/London"],
     "cityshade: error: --tz is the time zone of --times; give --date and --times"),
    (["--date", "2025-02-29", "--times", "12:00", "--weather", "w.epw"],
     "cityshade: error: --date must be a day YYYY-MM-DD, not '2025-02-29'"),
    (["--date", "2025-06-11", "--times", "25:00", "--weather", "w.epw"],
     "cityshade: error: time of day '25:00' does not exist; use 00:00 to 24:00"),
    (["--date", "2025-06-11", "--times", "12:00", "--weather", "w.epw", "--tz", "Mars/Olympus"],
     ("cityshade: error: unknown time zone 'Mars/Olympus'; give an IANA name such as "
      "Europe/Berlin")),
])
def test_bad_instants_say_one_line(small_file, tmp_path, extra, line):
    result = run("sky", small_file, "-o", tmp_path / "out", *extra)
    assert result.exit_code == 2, result.output
    assert result.output.splitlines() == [line]
    assert not (tmp_path / "out").exists()


def test_a_finished_run_again_does_nothing_and_other_parameters_are_refused(small_file,
                                                                            tmp_path):
    """The same command on a finished folder says so in one line and computes nothing; other
    parameters are refused, naming what differs; ``--overwrite`` computes them."""
    args = ["sky", small_file, "-o", tmp_path / "out", "--sky", "tregenza", "--no-map",
            "--surfaces", "--samples-per-m2", "0.01", "--tile-px", "4"]
    first = run(*args)
    assert first.exit_code == 0, first.output
    again = run(*args)
    assert again.exit_code == 0, again.output
    assert again.output.splitlines() == [f"{tmp_path / 'out'}: already complete (same "
                                         f"request); nothing to do (--overwrite computes it "
                                         f"again)"]
    other = run(*args, "--vsc")
    assert other.exit_code == 2
    assert other.output.splitlines() == [
        f"cityshade: error: {tmp_path / 'out'} holds a run with other parameters (differs in: "
        f"vsc); use --overwrite or another -o folder"]
    over = run(*args, "--vsc", "--overwrite")
    assert over.exit_code == 0, over.output
    assert "vsc_pct" in (tmp_path / "out" / "surfaces.csv").read_text().splitlines()[0]


def test_a_sky_that_does_not_fit_in_memory_is_refused_before_any_work(small_file, tmp_path,
                                                                      monkeypatch):
    """The camera pass (290 B a pixel, batch's measured figure) and the sky's own bytes per
    receiver (48 point and normal + 19 bits of 145 directions + 32 origins and rows + 1 held
    answers + 24 view factor and shares + 8 plane + 8 VSC = 140 B) are counted together."""
    import re

    import cityshade.frame.pipeline as pipeline

    monkeypatch.setattr(pipeline, "available_memory_bytes", lambda: 1000)
    result = run("sky", small_file, "-o", tmp_path / "out", "--sky", "tregenza",
                 "--pixel-size", "0.05")
    assert result.exit_code == 2, result.output
    m = re.fullmatch(r"cityshade: error: ([\d,]+) receivers need about ([\d.]+) GB \(140 bytes "
                     r"each besides the camera's ([\d.]+) GB\) but 0\.0 GB are available: use a "
                     r"larger --pixel-size, fewer --samples-per-m2 or a coarser --sky",
                     result.output.strip())
    assert m, result.output
    n = int(m.group(1).replace(",", ""))
    assert n > 10**6                            # a real size: the GB figures are not 0.0
    assert m.group(2) == f"{n * (290 + 140) / 1e9:.1f}" and m.group(3) == f"{n * 290 / 1e9:.1f}"
    assert not (tmp_path / "out").exists()


def test_verbose_says_the_memory_estimate_before_the_work(small_file, tmp_path):
    """``-v`` prints the estimate before the first tile: the camera pass (290 B a pixel,
    every pixel of the map), what is kept of every receiver (48 point and normal + 16 slot
    and place + 8 view factor = 72 B) and one tile's 140 B per receiver (the refusal's
    figures), and the size of the scene file whose pages are mapped beside it."""
    import json
    import re

    result = CliRunner().invoke(cli, [
        "sky", str(small_file), "-o", str(tmp_path / "out"), "--sky", "tregenza",
        "--pixel-size", "0.5", "--tile-px", "64", "--no-gis", "--no-decorate", "-v"])
    assert result.exit_code == 0, result.stderr
    lines = result.stderr.splitlines()
    m = re.fullmatch(r"memory   about ([\d,]+) MB estimated \(camera pass, receivers kept, one "
                     r"tile traced\), besides the pages it maps of the scene file of ([\d,]+) MB",
                     lines[0])
    assert m, result.stderr
    assert m.group(2) == f"{small_file.stat().st_size / 1e6:,.0f}"
    assert lines[1].startswith("cityshade: tiles 1/")
    camera = json.loads((tmp_path / "out" / "manifest.json").read_text())["params"]["camera"]
    w, h = camera["width_px"], camera["height_px"]
    assert w > 64 and h > 64
    assert m.group(1) == f"{(w * h * (290 + 72) + 64 * 64 * 140) / 1e6:,.0f}"
