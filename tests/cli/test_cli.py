"""The CLI through click's CliRunner: success, and the one-line message of every failure."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city

from cityshade.cli.main import cli


@pytest.fixture
def gml(tmp_path):
    path = tmp_path / "city.gml"
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    path.write_text(city(building("b1", box_polygons(690_000, 5_336_000, 500, 10, 8, 6), extra=extra),
                         building("b2", box_polygons(690_030, 5_336_000, 500, 5, 5, 20, "q"))))
    return path


def run(*args):
    result = CliRunner().invoke(cli, [str(a) for a in args])
    return result


def assert_one_line_error(result, fragment, code=1):
    assert result.exit_code == code, result.output
    assert "Traceback" not in result.output
    lines = [l for l in result.output.splitlines() if l.strip()]
    assert len(lines) == 1, result.output
    assert lines[0].startswith("cityshade: error: ") and fragment in lines[0], lines[0]


def test_build_and_info(gml, tmp_path):
    out = tmp_path / "out.cityshade"
    result = run("build", gml, "-o", out)
    assert result.exit_code == 0, result.output
    assert "24 triangles" in result.output and out.is_file()
    info = run("info", out, "--json")
    assert info.exit_code == 0, info.output
    d = json.loads(info.output)
    for key in ("triangles", "objects", "crs", "origin", "bbox", "time_range", "skipped", "kdtree"):
        assert key in d
    assert d["triangles"] == 24 and d["objects"]["total"] == 2
    assert d["crs"]["horizontal_epsg"] == 25832
    assert d["time_range"] == ["1900-01-01", "1900-01-01"]
    assert d["bbox"]["min"] == pytest.approx([690_000, 5_336_000, 500])
    assert d["bbox"]["max"] == pytest.approx([690_035, 5_336_008, 520])
    text = run("info", out)
    assert text.exit_code == 0 and "objects       2 (2 Building)" in text.output


def test_build_default_output_and_info_on_gml(gml):
    assert run("build", gml, "-q").exit_code == 0
    assert gml.with_suffix(".cityshade").is_file()
    d = json.loads(run("info", gml, "--json").output)
    assert d["triangles"] == 24


def test_options_reach_the_build(gml, tmp_path):
    out = tmp_path / "o.cityshade"
    assert run("build", gml, "-o", out, "--crs", "EPSG:25833", "--time-source", "creation").exit_code == 0
    d = json.loads(run("info", out, "--json").output)
    assert d["crs"]["horizontal_epsg"] == 25833
    assert d["time_range"] is None and d["time_source"] == "creation"


def test_missing_file(tmp_path):
    assert_one_line_error(run("build", tmp_path / "nope.gml"), "no such file")


def test_malformed_xml(tmp_path):
    p = tmp_path / "bad.gml"
    p.write_text("<CityModel>\n<cityObjectMember>\n</CityModel>")
    result = run("build", p)
    assert_one_line_error(result, "malformed XML")
    assert "bad.gml:3" in result.output
    assert not p.with_suffix(".cityshade").exists()


def test_not_citygml(tmp_path):
    p = tmp_path / "x.gml"
    p.write_text("<svg/>")
    assert_one_line_error(run("build", p), "not a CityGML file")


def test_empty_model(tmp_path):
    p = tmp_path / "e.gml"
    p.write_text(city())
    assert_one_line_error(run("build", p), "no city objects")


def test_unknown_crs(gml):
    assert_one_line_error(run("build", gml, "--crs", "EPSG:999999"), "999999")


def test_absurd_options(gml):
    result = run("build", gml, "--lod", "7")
    assert result.exit_code == 2 and "7 is not in the range" in result.output
    result = run("build", gml, "--time-source", "soon")
    assert result.exit_code == 2 and "soon" in result.output
    assert_one_line_error(run("build", gml, "-o", gml), "overwrite the input", code=2)


def test_unwritable_output(gml, tmp_path):
    # The parent "folder" is a file: nothing can be written there.
    assert_one_line_error(run("build", gml, "-o", gml / "x.cityshade"),
                          f"{gml} is a file, not a folder")
    assert_one_line_error(run("build", gml, "-o", "/proc/x.cityshade"),
                          "cannot write in the folder /proc")


def test_config_unknown_key(gml, tmp_path):
    cfg = tmp_path / "c.toml"
    cfg.write_text("[build]\nlodd = 2\n")
    assert_one_line_error(run("build", gml, "--config", cfg), "unknown key(s) in", code=2)


def test_info_on_corrupt_cache(gml, tmp_path):
    out = tmp_path / "c.cityshade"
    run("build", gml, "-o", out)
    out.write_bytes(out.read_bytes()[:-10])
    assert_one_line_error(run("info", out), "rebuild")


def test_help_is_light():
    """`cityshade --help` imports none of the heavy libraries."""
    code = ("import sys; from cityshade.cli.main import cli\n"
            "try:\n    cli.main(['--help'], standalone_mode=False)\nexcept SystemExit: pass\n"
            "heavy = [m for m in ('numba', 'lxml', 'pyproj', 'OpenImageIO', 'numpy') if m in sys.modules]\n"
            "print('HEAVY', heavy)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "HEAVY []" in out.stdout, out.stdout


def test_python_m_cityshade(gml, tmp_path):
    out = subprocess.run([sys.executable, "-m", "cityshade", "info", str(tmp_path / "missing")],
                         capture_output=True, text=True)
    assert out.returncode == 1 and out.stderr.strip().startswith("cityshade: error:")
    assert "Traceback" not in out.stderr


def test_own_process_leaves_after_its_exit_handlers_without_the_teardown(tmp_path):
    """``python -m cityshade`` ends without the interpreter's teardown (a module global's
    finalizer never runs) once the exit handlers have run and what it printed is flushed into
    the pipe, with the command's status; under a profiler the ordinary exit stays, so the
    profiler's report is printed after the command."""
    code = ("import atexit, sys\n"
            f"atexit.register(lambda: open({str(tmp_path / 'exit-handler')!r}, 'w').close())\n"
            "class Kept:\n"
            f"    def __del__(self, open=open):\n"  # the builtins are gone by then
            f"        open({str(tmp_path / 'teardown')!r}, 'w').close()\n"
            "kept = Kept()\n"
            "sys.argv = ['cityshade', '--help']\n"
            "from cityshade.__main__ import run\nrun()\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0 and out.stdout.splitlines()[-1].strip().startswith("export")
    assert (tmp_path / "exit-handler").exists() and not (tmp_path / "teardown").exists()
    missing = subprocess.run([sys.executable, "-m", "cityshade", "info", str(tmp_path / "x")],
                             capture_output=True, text=True)
    assert missing.returncode == 1 and missing.stderr.startswith("cityshade: error:")
    profiled = subprocess.run([sys.executable, "-m", "cProfile", "-m", "cityshade", "--help"],
                              capture_output=True, text=True)
    assert profiled.returncode == 0 and "function calls" in profiled.stdout


# -- render ------------------------------------------------------------------------------------
@pytest.fixture
def built(gml, tmp_path):
    out = tmp_path / "city.cityshade"
    assert run("build", gml, "-o", out, "-q").exit_code == 0
    return out


def test_render_outputs(built, tmp_path):
    from cityshade import imageio

    exr, png, mask = tmp_path / "f.exr", tmp_path / "f.png", tmp_path / "m.png"
    result = run("render", built, "--date", "1950", "--sun-azimuth", "135", "--sun-elevation", "30",
                 "--size", "96x64", "-o", exr, "--png", png, "--mask", mask, "-v")
    assert result.exit_code == 0, result.output
    channels, attrs = imageio.read_exr(exr)
    assert {"R", "G", "B", "shadow", "Z", "N.x", "N.y", "N.z", "primid", "objid"} <= set(channels)
    assert channels["shadow"].shape == (64, 96)
    assert attrs["cityshade:technique"] == "exact"
    assert float(attrs["cityshade:sun_elevation_deg"]) == 30.0
    assert "timings" in result.output and "azimuth 135.000° true" in result.output
    pixels, _ = imageio.read_image(png)
    assert pixels.shape == (64, 96, 3)
    m, _ = imageio.read_image(mask)
    assert set(np.unique(m).tolist()) <= {0, 128, 255} and (m == 255).any() and (m == 0).any()


def test_render_exr_precision_half_by_default_full_on_request(built, tmp_path):
    import OpenImageIO as oiio

    from cityshade import imageio

    args = ("render", built, "--date", "1950", "--sun-azimuth", "135", "--sun-elevation", "30",
            "--size", "48x32")
    types = {}
    for name, extra in (("half", ()), ("full", ("--exr-precision", "full"))):
        result = run(*args, *extra, "-o", tmp_path / f"{name}.exr")
        assert result.exit_code == 0, result.output
        inp = oiio.ImageInput.open(str(tmp_path / f"{name}.exr"))
        spec = inp.spec()   # one type for every channel: no per-channel formats
        formats = [str(f) for f in spec.channelformats] or [str(spec.format)] * spec.nchannels
        types[name] = dict(zip(spec.channelnames, formats))
        inp.close()
    halves = {"R", "G", "B", "N.x", "N.y", "N.z"}
    assert types["half"] == {n: "half" if n in halves else "float" for n in types["half"]}
    assert set(types["full"].values()) == {"float"} and types["full"].keys() == types["half"].keys()
    half, _ = imageio.read_exr(tmp_path / "half.exr")
    full, _ = imageio.read_exr(tmp_path / "full.exr")
    for name in full:   # the same frame: the half channels are the full ones rounded
        want = full[name].astype(np.float16).astype(np.float32) if name in halves else full[name]
        np.testing.assert_array_equal(half[name], want, err_msg=name)


def test_render_map_georeferenced(built, tmp_path):
    tif = tmp_path / "mask.tif"
    result = run("render", built, "--date", "1950", "--sun-azimuth", "180", "--sun-elevation", "40",
                 "--camera", "map", "--pixel-size", "0.5", "-o", tmp_path / "m.exr", "--geotiff", tif)
    assert result.exit_code == 0, result.output
    world = [float(v) for v in tif.with_suffix(".tfw").read_text().split()]
    # World file: pixel size, rotations, then the CENTRE of the upper-left pixel.
    assert world[0] == 0.5 and world[3] == -0.5
    assert tif.with_suffix(".prj").read_text().startswith("PROJCS")


def test_render_failures(built, tmp_path):
    out = tmp_path / "x.exr"
    assert_one_line_error(run("render", built, "-o", out), "no sun position", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "-o", out),
                          "give both --sun-azimuth and --sun-elevation", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "--sun-elevation", "95",
                              "-o", out), "between -90 and 90", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "--sun-elevation", "30",
                              "--shadows", "magic", "-o", out), "unknown shadow technique", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "--sun-elevation", "30",
                              "--camera", "nowhere", "-o", out), "unknown camera 'nowhere'", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "--sun-elevation", "30",
                              "--date", "1850-06-21T15:00", "-o", out), "--tz", code=2)
    assert_one_line_error(run("render", built, "--sun-azimuth", "10", "--sun-elevation", "30",
                              "-o", built / "x.exr"), "x.exr")
    assert_one_line_error(run("render", tmp_path / "none.cityshade", "--sun-azimuth", "10",
                              "--sun-elevation", "30", "-o", out), "no such file")
    assert not out.exists()


def test_render_date_outside_range_warns(tmp_path):
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    src = tmp_path / "dated.gml"
    src.write_text(city(building("b1", box_polygons(0, 0, 0, 10, 8, 6), extra=extra)))
    assert run("build", src, "-q").exit_code == 0
    result = run("render", src.with_suffix(".cityshade"), "--date", "1800", "--sun-azimuth", "135",
                 "--sun-elevation", "30", "--size", "32x32", "-o", tmp_path / "a.exr")
    assert result.exit_code == 0
    assert "warning: the date is outside the model's time range" in result.output


def test_render_night_warns_and_is_dark(built, tmp_path):
    from cityshade import imageio

    result = run("render", built, "--date", "1950", "--sun-azimuth", "0", "--sun-elevation", "-10",
                 "--size", "32x32", "-o", tmp_path / "n.exr")
    assert result.exit_code == 0 and "below the horizon" in result.output
    channels, _ = imageio.read_exr(tmp_path / "n.exr")
    assert (channels["shadow"] == 0).all() and np.isfinite(channels["R"]).all()


def test_internal_error_is_exit_70_with_traceback_only_under_verbose(monkeypatch, tmp_path):
    # A contract error is a bug of the caller, not the user's: exit 70, "internal error".
    import cityshade.store.scenefile
    from cityshade.errors import ContractError

    def broken(*args, **kwargs):
        raise ContractError("scene arrays of the wrong dtype")

    monkeypatch.setattr(cityshade.store.scenefile, "load_scene", broken)
    args = ("render", tmp_path / "x.cityshade", "--sun-azimuth", "10", "--sun-elevation", "20",
            "-o", tmp_path / "x.exr")
    assert_one_line_error(run(*args), "internal error: scene arrays of the wrong dtype", code=70)
    verbose = run(*args, "-v")
    assert verbose.exit_code == 70 and "Traceback" in verbose.output
    assert verbose.output.strip().splitlines()[-1] == (
        "cityshade: error: internal error: scene arrays of the wrong dtype")


def test_config_file_shadows_table(built, tmp_path):
    """A misspelled [shadows] key fails with one line naming the key and the file; a [shadows]
    value changes the result exactly as the same flag does."""
    from cityshade.imageio import read_image

    bad = tmp_path / "bad.toml"
    bad.write_text('[shadows.map]\npxx = 64\n')
    base = ("render", built, "--date", "1950", "--sun-azimuth", "200", "--sun-elevation", "20",
            "--camera", "map", "--pixel-size", "0.25")
    res = run(*base, "--config", bad, "-o", tmp_path / "bad.exr")
    assert_one_line_error(res, "pxx", code=2)
    assert str(bad) in res.output and not (tmp_path / "bad.exr").exists()
    good = tmp_path / "good.toml"
    good.write_text('[shadows]\ntechnique = "shadowmap"\n\n[shadows.map]\npx = 16\n')
    masks = {}
    for name, extra in (("toml", ("--config", good)),
                        ("flag", ("--shadows", "shadowmap", "--map-px", "16")),
                        ("default", ("--shadows", "shadowmap"))):
        mask = tmp_path / f"{name}.png"
        res = run(*base, *extra, "-o", tmp_path / f"{name}.exr", "--mask", mask)
        assert res.exit_code == 0, res.output
        masks[name] = read_image(mask)[0]
    assert np.array_equal(masks["toml"], masks["flag"])
    # A 16² map is coarse: the shadow differs from the default 2048² map's.
    assert not np.array_equal(masks["toml"], masks["default"])
    # The flag overrides the file.
    res = run(*base, "--config", good, "--map-px", "2048", "-o", tmp_path / "o.exr",
              "--mask", tmp_path / "o.png")
    assert res.exit_code == 0 and np.array_equal(read_image(tmp_path / "o.png")[0],
                                                 masks["default"])


def test_camera_presets_from_a_user_file(built, tmp_path):
    presets = tmp_path / "mine.toml"
    presets.write_text("[low_south]\nazimuth_deg = 180.0\nelevation_deg = 10.0\n")
    args = ("render", built, "--date", "1950", "--sun-azimuth", "200", "--sun-elevation", "20",
            "--size", "64x48", "--camera", "low_south", "-o", tmp_path / "p.exr")
    assert_one_line_error(run(*args), "unknown camera 'low_south'", code=2)
    assert run(*args, "--cameras", presets).exit_code == 0


#: Run in the package laid out as ``pip install .`` lays it out, with no repository around it.
INSTALLED_CHILD = """
import sys
from importlib import resources
from pathlib import Path
import cityshade
from cityshade.config import Settings, load_settings
from cityshade.raster.camera import load_presets
from cityshade.planning.rules import load_rules
site = Path(sys.argv[1])
assert Path(cityshade.__file__).resolve().parent == site / "cityshade", cityshade.__file__
# The presets are read from the installed file, not from a copy inside the code.
with open(site / "cityshade" / "configs" / "cameras.toml", "a") as fh:
    fh.write("\\n[tower]\\nazimuth_deg = 10.0\\nelevation_deg = 80.0\\n")
print(sorted(load_presets()))
with resources.as_file(resources.files("cityshade") / "configs" / "default.toml") as p:
    print(load_settings(p) == Settings())
print(len(load_rules("bre209")))
"""


def test_a_non_editable_install_reads_its_presets_settings_and_rules(tmp_path):
    """``pip install .`` copies what setuptools' ``build_py`` lays out: the modules and the
    package data that pyproject.toml declares. The camera presets were read from the
    repository's ``configs/`` folder (``parents[3]``), with a second copy in the code for an
    install, and ``default.toml`` was not installed at all; both are package data now."""
    import shutil

    repo = Path(__file__).resolve().parents[2]
    shutil.copytree(repo / "src" / "cityshade", tmp_path / "src" / "cityshade",
                    ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(repo / name, tmp_path / name)
    site = tmp_path / "site"
    done = subprocess.run([sys.executable, "-c", "import setuptools; setuptools.setup()", "-q",
                           "build_py", "-d", str(site)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    (tmp_path / "child.py").write_text(INSTALLED_CHILD)
    env = dict(os.environ, PYTHONPATH=str(site))
    done = subprocess.run([sys.executable, str(tmp_path / "child.py"), str(site)], cwd=site,
                          capture_output=True, text=True, timeout=120, env=env)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "['bird', 'east', 'north', 'overview', 'south', 'tower', 'west']", "True", "3"]
    # pyproject.toml declares the package typed (PEP 561): the marker must be installed.
    assert (site / "cityshade" / "py.typed").is_file()


def test_help_does_not_load_numpy():
    """``cityshade --help`` lists the camera presets; reading them loaded numpy (and the
    camera module) before any command ran."""
    child = ("import sys\nfrom cityshade.cli.main import main\ntry:\n    main(['--help'])\n"
             "except SystemExit as e:\n    assert e.code == 0, e.code\n"
             "print(sorted(m for m in ('numpy', 'numba') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "[]"


def test_a_bad_option_is_one_line(capsys, tmp_path):
    """click's usage errors took four lines (usage, hint, blank line, message)."""
    from cityshade.cli.main import COMMANDS, main

    cases = [(["render", tmp_path / "a.cityshade", "--fov", "500"],
              "cityshade: error: Invalid value for '--fov': 500.0 is not in the range "
              "1<=x<=170. (see 'cityshade render --help')"),
             (["render"], "cityshade: error: Missing argument 'FILE'. "
                          "(see 'cityshade render --help')"),
             (["batch", tmp_path / "a.cityshade", "--xyzzy"],
              "cityshade: error: No such option '--xyzzy'. (see 'cityshade batch --help')"),
             (["nosuch"], "cityshade: error: no command 'nosuch'; the commands are "
                          f"{', '.join(COMMANDS)} (see 'cityshade --help')")]
    for args, line in cases:
        with pytest.raises(SystemExit) as done:
            main([str(a) for a in args])
        assert done.value.code == 2
        assert capsys.readouterr().err.splitlines() == [line]


def test_the_command_runs_numpy_on_one_blas_thread_unless_told(tmp_path):
    """The command's process (argv[0] ``cityshade``) sets one BLAS thread before numpy is
    imported and sleeping OpenMP workers; a value the caller set stays; a program importing
    the library is not touched."""
    probe = ("import sys; sys.argv[0] = {argv0!r}; import cityshade, os, numpy; "
             "print(os.environ.get('OPENBLAS_NUM_THREADS'), os.environ.get('MKL_NUM_THREADS'), "
             "os.environ.get('OMP_WAIT_POLICY'))")
    names = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_WAIT_POLICY")

    def run(argv0, **env):
        base = {k: v for k, v in os.environ.items() if k not in names}
        out = subprocess.run([sys.executable, "-c", probe.format(argv0=argv0)],
                             env={**base, **env}, capture_output=True, text=True, check=True)
        return out.stdout.split()

    assert run("/usr/bin/cityshade") == ["1", "1", "PASSIVE"]
    assert run("/usr/bin/cityshade", OPENBLAS_NUM_THREADS="3", OMP_WAIT_POLICY="ACTIVE") == \
        ["3", "1", "ACTIVE"]
    assert run("my_script.py") == ["None", "None", "None"]


def test_no_transparent_huge_pages_turns_them_off_unless_told():
    """``no_transparent_huge_pages`` sets the kernel's per-process flag (``THP_enabled`` in
    /proc/self/status) to 0; ``CITYSHADE_HUGE_PAGES=1`` leaves it as it was."""
    status = Path("/proc/self/status")
    if not status.exists() or "THP_enabled" not in status.read_text():
        pytest.skip("this kernel does not report THP_enabled in /proc/self/status")
    probe = ("from cityshade.runtime.startup import no_transparent_huge_pages as off; off(); "
             "print([line.split()[1] for line in open('/proc/self/status') "
             "if line.startswith('THP_enabled')][0])")

    def run(**env):
        base = {k: v for k, v in os.environ.items() if k != "CITYSHADE_HUGE_PAGES"}
        out = subprocess.run([sys.executable, "-c", probe], env={**base, **env},
                             capture_output=True, text=True, check=True)
        return out.stdout.strip()

    # The flag is inherited: with the variable, the child keeps what this process has.
    own = [line.split()[1] for line in status.read_text().splitlines()
           if line.startswith("THP_enabled")][0]
    assert run() == "0"
    assert run(CITYSHADE_HUGE_PAGES="1") == own


def test_render_turns_transparent_huge_pages_off_first(monkeypatch, capsys):
    """``cityshade render`` asks for no huge pages before anything else (here before it finds
    nothing to write)."""
    from cityshade.cli.main import main
    from cityshade.runtime import startup

    calls = []
    monkeypatch.setattr(startup, "no_transparent_huge_pages", lambda: calls.append(1))
    with pytest.raises(SystemExit) as done:
        main(["render", "nosuch.cityshade"])
    assert done.value.code != 0
    assert calls == [1]
