"""Issue 40's messages, each asserted as the exact line a user sees through the CLI: readable
skip reasons, nesting depth, binary files, plurals, dates out of range, --size over the limit
with its memory, an unwritable -o found before the work, a resumed batch, the state removed
after a finished batch, CityJSON in --help, "did you mean", and the output folder's lock."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city

from cityshade.cli.main import cli

X0, Y0, Z0 = 690_000.0, 5_336_000.0, 500.0


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def lines_of(result) -> list[str]:
    return [line for line in result.output.splitlines() if line.strip()]


def error_line(result, code=1) -> str:
    """The one line of a failing command."""
    assert result.exit_code == code, result.output
    assert "Traceback" not in result.output
    lines = lines_of(result)
    assert len(lines) == 1, result.output
    return lines[0]


# --- reading ---------------------------------------------------------------------------------

def test_no_polygon_triangulated_says_why_in_words(tmp_path):
    line = [(X0, Y0, Z0), (X0 + 1, Y0, Z0)]
    src = tmp_path / "few.gml"
    src.write_text(city(building("b1", [("RoofSurface", "r1", line)])))
    assert error_line(run("build", src)) == (
        f"cityshade: error: {src}: no polygon could be triangulated: 1 polygon has too few "
        f"points")
    src.write_text(city(building("b1", [("RoofSurface", "r1", line), ("RoofSurface", "r2", line),
                                        ("RoofSurface", "r3", [*line, (X0 + 2, Y0, Z0)])])))
    assert error_line(run("build", src)) == (
        f"cityshade: error: {src}: no polygon could be triangulated: 2 polygons have too few "
        f"points, 1 polygon has all its points on one line")
    assert not src.with_suffix(".cityshade").exists()


def test_deep_nesting_is_a_line_a_user_can_act_on(tmp_path):
    src = tmp_path / "deep.gml"
    depth = 5000  # over libxml2's limit of 2,048 (also with huge_tree)
    src.write_text("<a>" * depth + "</a>" * depth)
    assert error_line(run("build", src)) == (
        f"cityshade: error: {src}:1: malformed XML: elements nested more than 2,048 levels "
        f"deep (a city model needs a few dozen): the file is damaged or not a city model")


def test_binary_files_are_not_reported_as_json_or_xml(tmp_path):
    noise = bytes((i * 7919 + 13) % 256 for i in range(3000))  # every byte value, no order
    for name, data in (("noise.gml", noise), ("brace.gml", b"{" + noise), ("n.json", noise)):
        src = tmp_path / name
        src.write_bytes(data)
        assert error_line(run("build", src)) == (
            f"cityshade: error: {src}: not CityGML/XML or CityJSON: the file holds binary "
            f"data, not text")
    src = tmp_path / "city.gml.gz"
    src.write_bytes(b"\x1f\x8b\x08\x00" + noise)
    assert error_line(run("build", src)) == (
        f"cityshade: error: {src}: not CityGML/XML or CityJSON: a gzip-compressed file: "
        f"decompress it first")


def test_one_object_is_singular(tmp_path):
    """'1 objects' in the build summary and in the creationDate warning."""
    src = tmp_path / "one.gml"
    src.write_text(city(building("b1", box_polygons(X0, Y0, Z0, 10, 8, 6),
                                 extra="<creationDate>2015-03-11</creationDate>")))
    result = run("build", src, "-o", tmp_path / "one.cityshade")
    assert result.exit_code == 0, result.output
    lines = lines_of(result)
    assert lines[0].startswith("cityshade: warning: the only dates in the file are "
                               "creationDate/terminationDate (1 object): they are database")
    assert lines[1].startswith(f"{tmp_path / 'one.cityshade'}: 12 triangles from 6 polygons "
                               f"of 1 object; ")
    info = run("info", tmp_path / "one.cityshade")
    assert ("              creationDate/terminationDate of 1 object unused (database times; "
            "--time-source creation uses them)") in info.output.splitlines()


def test_plural_helper():
    from cityshade.util import plural

    assert [plural(n, "object") for n in (0, 1, 2, 1386)] == [
        "0 objects", "1 object", "2 objects", "1,386 objects"]
    assert plural(1, "vertex", "vertices") == "1 vertex"
    assert plural(3, "vertex", "vertices") == "3 vertices"


# --- options ---------------------------------------------------------------------------------

@pytest.mark.parametrize("date", ["99999", "0", "10000-01-01"])
def test_a_date_out_of_range_says_so(dated_box_file, tmp_path, date):
    result = run("render", dated_box_file, "--date", date, "--sun-azimuth", "100",
                 "--sun-elevation", "30", "-o", tmp_path / "a.exr")
    assert error_line(result, 2) == (f"cityshade: error: date '{date}' is out of range (years 1 "
                                     f"to 9999 are supported)")
    result = run("batch", dated_box_file, "--date", "99999-06-21", "--tz", "UTC",
                 "-o", tmp_path / "b")
    assert error_line(result, 2) == ("cityshade: error: --date '99999-06-21' is out of range "
                                     "(years 1 to 9999 are supported)")
    assert not (tmp_path / "b").exists()


def test_a_time_zone_without_a_clock_time_is_not_ignored_silently(dated_box_file, tmp_path):
    """--tz with the sun from angles and a state of whole days placed nothing, and said
    nothing (issue 40: no silent ignore)."""
    result = run("render", dated_box_file, "--date", "2000", "--sun-azimuth", "100",
                 "--sun-elevation", "30", "--tz", "Europe/Berlin", "--png", tmp_path / "a.png")
    assert result.exit_code == 0, result.output
    assert lines_of(result)[0] == ("cityshade: warning: --tz is not used: the sun comes from "
                                   "--sun-azimuth/--sun-elevation and the city's state is a day "
                                   "(a zone places a --time)")
    result = run("render", dated_box_file, "--date", "2000-06-21", "--time", "12:00", "--tz",
                 "Europe/Berlin", "--png", tmp_path / "b.png")
    assert result.exit_code == 0, result.output
    assert "warning" not in result.output


def test_evaluate_refuses_a_clock_time_with_suns_from_angles(dated_box_file, tmp_path):
    """Without --times the suns are angles and --date the city's state: its time of day set
    nothing and was taken silently (issue 40: no silent ignore)."""
    result = run("evaluate", dated_box_file, "--date", "2020-06-21T15:00+02:00", "-o",
                 tmp_path / "ev")
    assert error_line(result, 2) == (
        "cityshade: error: --date 2020-06-21T15:00+02:00 has a time of day, but the suns come "
        "from --sun (angles): give --times HH:MM,... for suns of that day, or a day alone for "
        "the city's state")
    assert not (tmp_path / "ev").exists()


def test_size_over_the_limit_gives_the_memory_it_would_need(dated_box_file, tmp_path):
    # 290 bytes per pixel for an exact technique's frame (frame/pipeline.py
    # FRAME_BYTES_PER_PX): 1e10 pixels × 290 B = 2,900 GB.
    result = run("render", dated_box_file, "--date", "2000", "--sun-azimuth", "100",
                 "--sun-elevation", "30", "--size", "100000x100000", "-o", tmp_path / "a.exr")
    assert error_line(result, 2) == (
        "cityshade: error: --size 100000x100000 exceeds the limit of 16384 pixels a side (the "
        "picture would need about 2,900 GB: 290 bytes per pixel for exact)")


def test_an_unwritable_output_fails_before_the_work(dated_box_file):
    """/proc passes a permission check (root, or its mode bits) but takes no new file: the
    render failed after the whole work, naming its temporary file."""
    result = run("render", dated_box_file, "--date", "2000", "--sun-azimuth", "100",
                 "--sun-elevation", "30", "-o", "/proc/x.exr")
    assert error_line(result) == ("cityshade: error: -o /proc/x.exr: cannot write in the "
                                  "folder /proc (No such file or directory)")
    result = run("build", dated_box_file, "-o", "/proc/x.cityshade")
    assert error_line(result) == ("cityshade: error: -o /proc/x.cityshade: cannot write in the "
                                  "folder /proc (No such file or directory)")


# --- the command group -----------------------------------------------------------------------

def test_help_names_cityjson_and_a_misspelled_command_gets_a_suggestion(capsys):
    from cityshade.cli.main import main

    result = run("--help")
    assert "CityGML and\n  CityJSON city models." in result.output
    assert "Build the .cityshade scene file of a CityGML or CityJSON model." in result.output
    for args, line in (
            (["rendr"], "cityshade: error: no command 'rendr'; did you mean 'render'? "
                        "(see 'cityshade --help')"),
            (["biuld", "x.gml"], "cityshade: error: no command 'biuld'; did you mean 'build'? "
                                 "(see 'cityshade --help')")):
        with pytest.raises(SystemExit) as done:
            main(args)
        assert done.value.code == 2
        assert capsys.readouterr().err.splitlines() == [line]


# --- batch: resume, state, lock ---------------------------------------------------------------

BATCH = ("--date", "2024-06-21", "--from", "06:00", "--to", "18:00", "--every", "2h", "--tz",
         "Europe/Berlin", "--pixel-size", "4", "--no-gis", "--no-decorate")


def test_a_resumed_batch_says_so_and_a_finished_one_drops_its_state(dated_box_file, tmp_path,
                                                                    stop_batch_after):
    from cityshade.sunhours.checkpoint import STATE_NAME

    out = tmp_path / "run"
    stop_batch_after(2)
    assert run("batch", dated_box_file, *BATCH, "-o", out).exit_code == 130
    assert (out / STATE_NAME).is_file()  # kept for the resume
    stop_batch_after(None)
    result = run("batch", dated_box_file, *BATCH, "-o", out)
    assert result.exit_code == 0, result.output
    # 06:00-18:00 every 2 h: 6 steps, the sun up in each (Munich, June), one position each.
    assert lines_of(result)[0] == (f"cityshade: resuming the run in {out}: 2 of 6 sun "
                                   f"positions (2 of 6 steps) were done before")
    assert not (out / STATE_NAME).exists()
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["status"] == "finished" and "state_sha256" not in manifest
    assert manifest["summary"]["sun_positions_resumed"] == 2
    assert not (out / ".cityshade.lock").exists()


def test_a_batch_refuses_a_folder_another_live_run_holds(dated_box_file, tmp_path):
    out = tmp_path / "run"
    out.mkdir()
    (out / ".cityshade.lock").write_text("1\n")  # process 1 always runs
    result = run("batch", dated_box_file, *BATCH, "-o", out)
    assert error_line(result, 2) == (f"cityshade: error: {out} is in use by another cityshade "
                                     f"run (process 1); wait for it to end or choose another "
                                     f"-o folder")
    assert (out / ".cityshade.lock").read_text() == "1\n"  # not ours to remove
    assert sorted(p.name for p in out.iterdir()) == [".cityshade.lock"]


def test_a_stale_lock_is_taken_over_with_a_note(dated_box_file, tmp_path):
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                           capture_output=True, text=True, check=True)
    pid = int(ended.stdout)
    out = tmp_path / "run"
    out.mkdir()
    (out / ".cityshade.lock").write_text(f"{pid}\n")
    result = run("batch", dated_box_file, *BATCH, "-o", out)
    assert result.exit_code == 0, result.output
    assert lines_of(result)[0] == (f"cityshade: took over the lock {out / '.cityshade.lock'} "
                                   f"of process {pid}, which has ended")
    assert not (out / ".cityshade.lock").exists()


def test_folder_lock_from_python(tmp_path):
    from cityshade.errors import UsageError
    from cityshade.util import LOCK_NAME, folder_lock

    with folder_lock(tmp_path) as lock:
        assert lock.read_text() == f"{os.getpid()}\n"
        (tmp_path / "other").mkdir()
        (tmp_path / "other" / LOCK_NAME).write_text("1\n")
        with pytest.raises(UsageError, match="process 1"):
            with folder_lock(tmp_path / "other"):
                pass
    assert not (tmp_path / LOCK_NAME).exists()


# --- no silent ignore ------------------------------------------------------------------------

SUN = ("--date", "2000", "--sun-azimuth", "100", "--sun-elevation", "30")


@pytest.mark.parametrize("args, line", [
    (("--camera", "map", "--size", "64x64"),
     "--size does not apply to the map view (--camera map): its size follows from "
     "--pixel-size (metres per pixel) and the model's extent"),
    (("--camera", "map", "--fov", "30"),
     "--fov does not apply to the map view (--camera map): its size follows from "
     "--pixel-size (metres per pixel) and the model's extent"),
    (("--pixel-size", "0.5"),
     "--pixel-size applies to the map view (--camera map); a perspective picture's size is "
     "--size WIDTHxHEIGHT"),
    (("--eye", "690005,5335950,520", "--target", "690005,5336004,503", "--pixel-size", "1"),
     "--pixel-size applies to the map view (--camera map); a perspective picture's size is "
     "--size WIDTHxHEIGHT"),
    (("--camera", "map", "--eye", "690005,5335950,520", "--target", "690005,5336004,503"),
     "--eye/--target place a perspective camera of their own: give them or --camera map, "
     "not both"),
    (("--camera", "low_south", "--fov", "30"),
     "--fov applies to a camera placed with --eye/--target; --camera low_south has its own "
     "field of view"),
    (("--png", "x.png", "--camera", "overview", "--decorate"),
     "--decorate needs a map view (--camera map): a perspective picture has no single scale "
     "or north"),
    (("--camera", "map", "--decorate"),
     "--decorate frames the --png and --mask pictures: give one of them"),
    (("--no-refraction",),
     "--no-refraction applies to the sun computed for a date and time; --sun-azimuth/"
     "--sun-elevation give the sun as it is"),
])
def test_render_refuses_options_its_camera_or_sun_would_ignore(dated_box_file, tmp_path, args,
                                                                line):
    args = [str(tmp_path / a) if a.endswith(".png") else a for a in args]
    result = run("render", dated_box_file, *SUN, "-o", tmp_path / "a.exr", *args)
    assert error_line(result, 2) == f"cityshade: error: {line}"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("azimuth, elevation, line", [
    ("400", "30", "sun azimuth must be from 0 to under 360 degrees (clockwise from true "
                  "north), not 400"),
    ("360", "30", "sun azimuth must be from 0 to under 360 degrees (clockwise from true "
                  "north), not 360"),
    ("-10", "30", "sun azimuth must be from 0 to under 360 degrees (clockwise from true "
                  "north), not -10"),
    ("100", "95", "sun elevation must be between -90 and 90 degrees, not 95"),
])
def test_angles_out_of_range_are_refused_not_wrapped(dated_box_file, tmp_path, azimuth, elevation,
                                                     line):
    result = run("render", dated_box_file, "--date", "2000", "--sun-azimuth", azimuth,
                 "--sun-elevation", elevation, "-o", tmp_path / "a.exr")
    assert error_line(result, 2) == f"cityshade: error: {line}"
    result = run("evaluate", dated_box_file, "--sun", f"{azimuth},{elevation}", "-o",
                 tmp_path / "e")
    assert error_line(result, 2) == f"cityshade: error: {line}"
    assert list(tmp_path.iterdir()) == []


def test_batch_and_compare_refuse_options_that_would_change_nothing(dated_box_file, tmp_path):
    out = tmp_path / "o"
    cases = [
        (("batch", *BATCH, "--samples-per-m2", "2"),
         "--samples-per-m2 sets the sample points of --surfaces: give --surfaces too"),
        (("batch", *BATCH, "--every-day", "7"),
         "--every-day spaces several days: give --days N or --to-date too"),
        (("batch", *BATCH, "--size", "64x64"),
         "--size does not apply to the map view (--camera map): its size follows from "
         "--pixel-size (metres per pixel) and the model's extent"),
        (("compare", *BATCH, "--before", "1850", "--after", "1990", "--no-surfaces",
          "--samples-per-m2", "2"),
         "--samples-per-m2 sets the sample points of the surfaces, which --no-surfaces "
         "skips: give one or the other"),
    ]
    for (command, *args), line in cases:
        result = run(command, dated_box_file, *args, "-o", out)
        assert error_line(result, 2) == f"cityshade: error: {line}", command
        assert not out.exists()


def test_compare_of_two_states_that_are_the_same_city_is_refused(dated_box_file, tmp_path):
    out = tmp_path / "o"
    hint = ("so nothing would change; give --before/--after dates around a change "
            "(cityshade info FILE shows the time range), or the proposal with --with")
    result = run("compare", dated_box_file, *BATCH, "--before", "1950", "--after", "2024",
                 "-o", out)
    assert error_line(result, 2) == ("cityshade: error: both states are the same city (no "
                                     f"object begins or ends between 1950 and 2024), {hint}")
    undated = tmp_path / "undated.gml"
    undated.write_text(city(building("b1", box_polygons(X0, Y0, Z0, 10, 8, 6))))
    assert run("build", undated, "-q").exit_code == 0
    result = run("compare", undated.with_suffix(".cityshade"), *BATCH, "--before", "1850",
                 "--after", "2024", "-o", out)
    assert error_line(result, 2) == ("cityshade: error: both states are the same city (the "
                                     f"model's objects carry no dates), {hint}")
    assert not out.exists()


def test_compare_refuses_a_folder_another_live_run_holds(dated_box_file, tmp_path):
    out = tmp_path / "c"
    out.mkdir()
    (out / ".cityshade.lock").write_text("1\n")
    result = run("compare", dated_box_file, *BATCH, "--before", "1850", "--after", "1990",
                 "-o", out)
    assert error_line(result, 2) == (f"cityshade: error: {out} is in use by another cityshade "
                                     f"run (process 1); wait for it to end or choose another "
                                     f"-o folder")
    assert sorted(p.name for p in out.iterdir()) == [".cityshade.lock"]
