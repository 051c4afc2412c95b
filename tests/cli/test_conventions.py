"""Issue 40, point 4: one meaning per option across commands. --city-date is the city's state
and --date the sun's day in every command (render and evaluate keep --date YEAR as the short
form of --city-date when the sun is given as angles); render writes only the outputs asked
for; a finished batch run again with the same request computes nothing."""
from __future__ import annotations

import json

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city

from cityshade.cli.main import cli

X0, Y0, Z0 = 690_000.0, 5_336_000.0, 500.0
ANGLES = ("--sun-azimuth", "100", "--sun-elevation", "30")
NOON = ("--date", "2024-06-21", "--time", "12:00", "--tz", "Europe/Berlin")


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def error_line(result, code=2) -> str:
    """The one line of a failing command."""
    assert result.exit_code == code, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and "Traceback" not in result.output, result.output
    return lines[0]


def _mask(dated_box_file, path, *args):
    from cityshade.imageio import read_image

    result = run("render", dated_box_file, *args, "--camera", "map", "--pixel-size", "1",
                 "--mask", path)
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[-1] == str(path)  # after a warning of an empty city
    return np.asarray(read_image(path)[0])


# --- render: the city's state and the sun's day ------------------------------------------------

def test_render_city_date_sets_the_state_and_date_the_sun(dated_box_file, tmp_path):
    """The box stands from 1900: in 1850 nothing casts a shadow (no 0 in the mask), in 1950
    and by default (the sun's day, 2024) it does. --date 1850 with angles is the same render
    as --city-date 1850."""
    shadow = 0  # imageio.MASK_SHADOW
    before = _mask(dated_box_file, tmp_path / "a.png", "--city-date", "1850", *ANGLES)
    short = _mask(dated_box_file, tmp_path / "b.png", "--date", "1850", *ANGLES)
    after = _mask(dated_box_file, tmp_path / "c.png", "--city-date", "1950", *ANGLES)
    assert not (before == shadow).any() and (after == shadow).any()
    assert np.array_equal(before, short)
    noon_1850 = _mask(dated_box_file, tmp_path / "d.png", "--city-date", "1850", *NOON)
    noon_2024 = _mask(dated_box_file, tmp_path / "e.png", *NOON)
    assert not (noon_1850 == shadow).any() and (noon_2024 == shadow).any()
    # The same state said twice is no contradiction.
    same = _mask(dated_box_file, tmp_path / "f.png", "--date", "1850", "--city-date", "1850-01-01",
                 *ANGLES)
    assert np.array_equal(before, same)
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"{c}.png" for c in "abcdef"]


@pytest.mark.parametrize("args, line", [
    (("--date", "1850", "--city-date", "1990", *ANGLES),
     "--date 1850 without a time of day is the city's state (short for --city-date), and "
     "--city-date says 1990: give one of them, or --time HH:MM to make --date the sun's day"),
    (("--date", "2024-06-21T12:00Z", *ANGLES),
     "--date 2024-06-21T12:00Z has a time of day, for which the sun is computed, and "
     "--sun-azimuth/--sun-elevation give it: use one or the other (the city's state alone is "
     "--city-date)"),
    (("--city-date", "1850"),
     "no sun position: give --sun-azimuth and --sun-elevation (degrees), or a --date with a "
     "time of day (e.g. 2024-06-21T15:00+02:00, or --time 15:00 --tz Europe/Berlin)"),
    (("--city-date", "18x0", *ANGLES),
     "cannot read date '18x0'; use YYYY, YYYY-MM-DD, or YYYY-MM-DDTHH:MM[:SS][Z|±HH:MM] "
     "(e.g. 1850, 1850-06-21, 1850-06-21T15:00+01:00)"),
])
def test_render_date_contradictions_are_one_line(dated_box_file, tmp_path, args, line):
    result = run("render", dated_box_file, *args, "--png", tmp_path / "a.png")
    assert error_line(result) == f"cityshade: error: {line}"
    assert list(tmp_path.iterdir()) == []


# --- render: only the outputs asked for ---------------------------------------------------------

def test_render_writes_only_a_png_or_only_a_mask(dated_box_file, tmp_path):
    result = run("render", dated_box_file, "--date", "2000", *ANGLES, "--size", "64x48",
                 "--png", tmp_path / "p.png")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.png"]
    result = run("render", dated_box_file, "--date", "2000", *ANGLES, "--camera", "map",
                 "--pixel-size", "2", "--geotiff", tmp_path / "g.tif")
    assert result.exit_code == 0, result.output
    assert {p.suffix for p in tmp_path.iterdir()} - {".png"} <= {".tif", ".tfw", ".prj"}
    assert not list(tmp_path.glob("*.exr"))


def test_render_without_any_output_says_so(dated_box_file, tmp_path):
    result = run("render", dated_box_file, "--date", "2000", *ANGLES)
    assert error_line(result) == ("cityshade: error: nothing to write: give -o FILE.exr, "
                                  "--png, --mask or --geotiff")


# --- evaluate, compare, study: the same words -------------------------------------------------

def test_evaluate_date_and_city_date(dated_box_file, tmp_path):
    result = run("evaluate", dated_box_file, "--sun", "100,30", "--date", "1850", "--city-date",
                 "1990", "-o", tmp_path / "e")
    assert error_line(result) == (
        "cityshade: error: --date 1850 without a time of day is the city's state (short for "
        "--city-date), and --city-date says 1990: give one of them, or --times to make --date "
        "the sun's day")
    assert list(tmp_path.iterdir()) == []


BATCH = ("--date", "2024-06-21", "--from", "06:00", "--to", "18:00", "--every", "2h", "--tz",
         "Europe/Berlin", "--pixel-size", "4", "--no-gis", "--no-decorate")


@pytest.mark.parametrize("command", ["compare", "study"])
def test_compare_and_study_city_date_is_the_state_of_with(dated_box_file, tmp_path, command):
    times = BATCH if command == "compare" else ("--tz", "Europe/Berlin")
    out = tmp_path / "o"
    result = run(command, dated_box_file, *times, "--city-date", "1850", "--after", "1990",
                 "-o", out)
    assert error_line(result) == (
        "cityshade: error: --city-date is the state of the city that --with adds a proposal "
        "to; two states of one model are --before and --after")
    result = run(command, dated_box_file, *times, "--city-date", "1850", "--before", "1990",
                 "--with", dated_box_file, "-o", out)
    assert error_line(result) == (
        "cityshade: error: --city-date 1850 and --before 1990 both give the state the "
        "proposal is added to, and they differ: give one of them")
    assert not out.exists()


def test_compare_city_date_is_before_with_a_proposal(dated_box_file, tmp_path):
    """--city-date X --with P is the request --before X --with P: the same provenance and
    the same sun-hours."""
    import re

    from cityshade.build import build_file
    from cityshade.imageio import read_image

    src = tmp_path / "p.gml"
    src.write_text(city(building("p1", box_polygons(X0 + 20, Y0, Z0, 6, 6, 12))))
    proposal, _, _ = build_file(src, tmp_path / "p.cityshade")
    runs = {}
    for name, state in (("a", ("--city-date", "1950")), ("b", ("--before", "1950"))):
        result = run("compare", dated_box_file, *BATCH, *state, "--with", proposal,
                     "--no-surfaces", "-o", tmp_path / name)
        assert result.exit_code == 0, result.output
        report = (tmp_path / name / "report.md").read_text()
        runs[name] = json.loads(re.search(r"Made by cityshade from `(\{.*?\})`", report)[1])
        for raster in ("before_h.tif", "after_h.tif"):
            runs[name, raster] = read_image(tmp_path / name / raster)[0]
    assert runs["a"] == {**runs["b"], "before": "1950"} and runs["a"]["before"] == "1950"
    for raster in ("before_h.tif", "after_h.tif"):
        assert np.array_equal(runs["a", raster], runs["b", raster], equal_nan=True)


def test_batch_city_date_is_the_state(dated_box_file, tmp_path):
    """06:00-18:00 CEST on 21 June in Munich the sun is up all along (it rises about 05:15,
    sets about 21:20): without the box (1850) the level ground gets 6 × 2 h = 12 h on every
    pixel; with it (the default state, the first --date day) some pixels get less."""
    from cityshade.imageio import read_exr

    hours = {}
    for name, state in (("then", ("--city-date", "1850")), ("now", ())):
        result = run("batch", dated_box_file, *BATCH, *state, "-o", tmp_path / name)
        assert result.exit_code == 0, result.output
        hours[name] = read_exr(tmp_path / name / "sun_hours.exr")[0]["sun_hours"]
        assert np.isfinite(hours[name]).any()
    assert (hours["then"][np.isfinite(hours["then"])] == 12.0).all()
    assert (hours["now"][np.isfinite(hours["now"])] < 12.0).any()


# --- batch: a finished run is not computed again ------------------------------------------------

def test_a_finished_batch_run_again_does_nothing(dated_box_file, tmp_path):
    out = tmp_path / "run"
    assert run("batch", dated_box_file, *BATCH, "-o", out).exit_code == 0
    files = {p: p.stat().st_mtime_ns for p in out.rglob("*")}
    assert out / "sun_hours.exr" in files and out / "manifest.json" in files
    result = run("batch", dated_box_file, *BATCH, "-o", out)
    assert result.exit_code == 0, result.output
    assert result.output.splitlines() == [f"{out}: already complete (same request); nothing "
                                          f"to do (--overwrite computes it again)"]
    assert {p: p.stat().st_mtime_ns for p in out.rglob("*")} == files
    # Another request on the finished folder: refused as before, nothing touched.
    result = run("batch", dated_box_file, *BATCH[:7], "3h", *BATCH[8:], "-o", out)
    assert error_line(result) == (f"cityshade: error: {out} holds a run with other parameters "
                                  f"(differs in: every_s); use --overwrite or another -o "
                                  f"folder")
    assert {p: p.stat().st_mtime_ns for p in out.rglob("*")} == files
    # An output gone: the run is computed again and the output is back.
    (out / "sun_hours.png").unlink()
    result = run("batch", dated_box_file, *BATCH, "-o", out)
    assert result.exit_code == 0 and "already complete" not in result.output
    assert (out / "sun_hours.png").is_file()
