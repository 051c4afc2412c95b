"""Outputs checked before the work, and all of a command's outputs written together or not at
all (issue 13 point 7): a bad -o of batch or evaluate failed only after the work, and a render
whose last output failed left the ones written before it."""
from __future__ import annotations

import os
import signal

import pytest
from click.testing import CliRunner

from cityshade.cli.main import cli
from cityshade.errors import OutputError, UsageError
from cityshade.errors import ImageIOError
from cityshade.util import check_outputs, interrupts_held, output_group, write_text_atomic


def _one_error_line(args) -> str:
    result = CliRunner().invoke(cli, [str(a) for a in args])
    lines = result.output.strip().splitlines()
    assert result.exit_code != 0 and len(lines) == 1, result.output
    assert lines[0].startswith("cityshade: error: "), lines[0]
    return lines[0][len("cityshade: error: "):]


def test_batch_evaluate_compare_and_render_refuse_a_bad_output_before_reading_the_model(
        tmp_path):
    # The model file does not exist: a command that looked at it first would say so.
    model = tmp_path / "no_such.cityshade"
    blocker = tmp_path / "plain_file"
    blocker.write_text("not a folder")
    out = blocker / "out"
    sun = ["--date", "2000", "--sun-azimuth", "135", "--sun-elevation", "30"]
    cases = [
        (["batch", model, "--date", "2024-06-21", "--tz", "UTC", "-o", out],
         f"-o {out}: {blocker} is a file, not a folder"),
        (["evaluate", model, "-o", out], f"-o {out}: {blocker} is a file, not a folder"),
        (["compare", model, "--before", "1850", "--after", "1990", "--date", "2024-03-21",
          "--tz", "UTC", "-o", out], f"-o {out}: {blocker} is a file, not a folder"),
        (["evaluate", model, "--stress", "-o", out],
         f"-o {out}: {blocker} is a file, not a folder"),
        (["render", model, *sun, "-o", tmp_path / "a.exr", "--png", out / "a.png"],
         f"--png {out / 'a.png'}: {blocker} is a file, not a folder"),
        (["render", model, *sun, "-o", tmp_path / "a.png"],
         f"-o {tmp_path / 'a.png'}: the file name must end in .exr, not '.png'"),
    ]
    for args, message in cases:
        assert _one_error_line(args) == message
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain_file"]  # nothing written


def test_a_failed_command_leaves_none_of_the_folders_it_made(tmp_path):
    """check_outputs creates missing output folders before the work; when the command fails
    afterwards (here: the model does not exist) they were left behind, empty."""
    model = tmp_path / "no_such.cityshade"
    kept = tmp_path / "kept"
    kept.mkdir()  # there before the command: stays
    sun = ["--date", "2000", "--sun-azimuth", "135", "--sun-elevation", "30"]
    cases = [
        ["render", model, *sun, "-o", kept / "r" / "deep" / "a.exr", "--png", tmp_path / "p" / "a.png"],
        ["batch", model, "--date", "2024-06-21", "--tz", "UTC", "-o", tmp_path / "b" / "out"],
        ["evaluate", model, "-o", kept / "e"],
        ["compare", model, "--before", "1850", "--after", "1990", "--date", "2024-03-21",
         "--tz", "UTC", "-o", tmp_path / "c"],
    ]
    for args in cases:
        assert _one_error_line(args).startswith(f"{model}: ")
        assert sorted(p.name for p in tmp_path.iterdir()) == ["kept"], args
        assert list(kept.iterdir()) == [], args


def test_check_outputs_kinds_and_clashes(tmp_path):
    (tmp_path / "f.exr").write_text("")
    (tmp_path / "d.png").mkdir()
    with pytest.raises(OutputError, match=r"^-o .*f.exr is a file, not a folder$"):
        check_outputs(("-o", tmp_path / "f.exr", None))
    with pytest.raises(OutputError, match=r"^--png .*d.png is a folder, not a file name$"):
        check_outputs(("--png", tmp_path / "d.png", (".png",)))
    with pytest.raises(UsageError, match=r"^--mask and --png would both write "):
        check_outputs(("--png", tmp_path / "x.png", (".png",)),
                      ("--mask", tmp_path / "." / "x.png", (".png",)))
    # Missing folders are created (as build does); an existing file may be replaced.
    assert check_outputs(("-o", tmp_path / "new" / "sub", None),
                         ("--png", tmp_path / "f.exr.png", (".png",)),
                         ("--x", None, (".x",))) == [tmp_path / "new" / "sub",
                                                     tmp_path / "f.exr.png"]
    assert (tmp_path / "new" / "sub").is_dir()


def test_an_output_group_renames_its_files_together_or_leaves_none(tmp_path):
    (tmp_path / "b.txt").write_text("old")
    with output_group():
        write_text_atomic(tmp_path / "a.txt", "a")
        write_text_atomic(tmp_path / "b.txt", "b")
        with output_group():  # a group inside a group joins the outer one
            write_text_atomic(tmp_path / "c.txt", "c")
        assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith(".")) \
            == ["b.txt"] and (tmp_path / "b.txt").read_text() == "old"
    assert [(tmp_path / n).read_text() for n in ("a.txt", "b.txt", "c.txt")] == ["a", "b", "c"]
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]
    for failure in (OSError("disk full"), KeyboardInterrupt()):
        with pytest.raises(type(failure)):
            with output_group():
                write_text_atomic(tmp_path / "d.txt", "d")
                raise failure
        assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "b.txt", "c.txt"]


def test_interrupts_held_delivers_a_ctrl_c_after_the_block():
    seen = []
    before = signal.signal(signal.SIGINT, lambda signum, frame: seen.append("handler"))
    try:
        with interrupts_held():
            os.kill(os.getpid(), signal.SIGINT)
            seen.append("block finished")
        assert seen == ["block finished", "handler"]
    finally:
        signal.signal(signal.SIGINT, before)


@pytest.mark.parametrize("failure", [ImageIOError("cannot write the world file"),
                                     KeyboardInterrupt()])
def test_a_render_whose_last_output_fails_leaves_none_of_them(tmp_path, monkeypatch,
                                                              sample_city_scene, failure):
    from cityshade import imageio
    from cityshade.raster.camera import map_view
    from cityshade.frame.render import render_frame, write_frame
    from cityshade.geo.sun import sun_from_angles

    scene = sample_city_scene
    cam = map_view(scene, pixel_size_m=4.0)
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, 7305.0, sun, "raytrace")
    outs = {"exr": tmp_path / "a.exr", "png": tmp_path / "a.png", "mask": tmp_path / "m.png",
            "georef": tmp_path / "a.tif"}

    def world_file_fails(*args, **kwargs):
        raise failure  # after the GeoTIFF itself was written, before its .tfw

    monkeypatch.setattr(imageio, "world_file_lines", world_file_fails)
    with pytest.raises(type(failure)):
        write_frame(frame, scene, "2000", **outs)
    assert list(tmp_path.iterdir()) == []
    monkeypatch.undo()
    written = write_frame(frame, scene, "2000", **outs)
    assert {p.name for p in written} >= {"a.exr", "a.png", "m.png", "a.tif", "a.tfw"}
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in written)
