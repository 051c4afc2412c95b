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


@pytest.mark.parametrize("extra,line", [
    (["--irradiance"], ("cityshade: error: --irradiance needs --weather FILE (an .epw, TMY3 "
                        ".csv or TMY2 .tm2)")),
    (["--no-svf"], "cityshade: error: nothing to write: --no-svf without --irradiance"),
    (["--sky", "tregenza7"], ("cityshade: error: unknown sky 'tregenza7': one of tregenza, "
                              "reinhart577, reinhart2305 or uniform<degrees>")),
    (["--shadows", "pcf"], ("cityshade: error: sky view factors and irradiance need an exact "
                            "technique (exact, izb, raytrace), not 'pcf'")),
    (["--weather", "MISSING.epw", "--irradiance"],
     "cityshade: error: MISSING.epw: no such weather file"),  # a bad input file: status 1
    (["--weather", "MISSING.epw"], None),  # no --irradiance: the weather is not read
])
def test_bad_requests_say_one_line(small_file, tmp_path, extra, line):
    if line is None:
        extra = [*extra, "--no-map", "--surfaces", "--samples-per-m2", "0.001", "--sky",
                 "tregenza"]
    result = run("sky", small_file, "-o", tmp_path / "out", *extra)
    if line is None:
        assert result.exit_code == 0, result.output
        assert "cityshade: warning: --weather without --irradiance: the weather file is not " \
               "read" in result.output
        return
    assert result.exit_code == (1 if "MISSING" in line else 2)  # 2: a bad request
    assert result.output.splitlines() == [line]
    assert not (tmp_path / "out").exists()


def test_a_garbled_weather_file_is_named(small_file, tmp_path):
    bad = tmp_path / "bad.epw"
    bad.write_text("garbage\n1,2,3\n")
    result = run("sky", small_file, "-o", tmp_path / "out", "--weather", bad, "--irradiance")
    assert result.exit_code == 1
    assert result.output.splitlines() == [
        f"cityshade: error: {bad}: not a readable EPW file (pvlib: 'altitude')"]
