"""Strip-wise map renders (issue 15: a 20 Mpx map within 2 GB): every output of a map rendered in
strips of rows is the whole-frame render's, bit for bit."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from click.testing import CliRunner

from conftest import shared_file

from cityshade import imageio
from cityshade.errors import UsageError
from cityshade.raster.camera import map_view, overview
from cityshade.frame.render import render_frame, strip_rows_for, write_frame
from cityshade.geo.sun import sun_from_angles


def _outputs(scene, frame, folder):
    """Every output of ``frame`` read back: EXR channels, PNG, mask and GeoTIFF pixels."""
    folder.mkdir()
    paths = dict(exr=folder / "f.exr", png=folder / "f.png", mask=folder / "m.png",
                 georef=folder / "g.tif")
    write_frame(frame, scene, "2024-06-21", **paths)
    channels, _ = imageio.read_exr(paths["exr"])
    out = {f"exr:{k}": v for k, v in channels.items()}
    for key in ("png", "mask", "georef"):
        out[key] = imageio.read_image(paths[key])[0]
    return out


def _assert_same(a, b):
    assert a.keys() == b.keys()
    for key in a:
        # Bytes, not values: NaN nodata and the sign of zeros count too.
        assert a[key].shape == b[key].shape, key
        assert a[key].tobytes() == b[key].tobytes(), key


@pytest.mark.parametrize("technique,rows,ground", [("raytrace", 7, "auto"), ("izb", 1, None)])
def test_strips_equal_whole_frame(sample_city_scene, tmp_path, technique, rows, ground):
    """Sample city map at 1 m, 12 m beyond the model on every side (nodata pixels, or the ground
    plane's): strips of 7 rows (the last one shorter) and of 1 row give every output of the
    whole-frame render."""
    scene = sample_city_scene
    lo, hi = np.min(scene.vertices, axis=0), np.max(scene.vertices, axis=0)
    cam = map_view(scene, 1.0, bbox=(lo[0] - 12, lo[1] - 12, hi[0] + 12, hi[1] + 12))
    assert cam.height_px % rows or rows == 1
    sun = sun_from_angles(200.0, 25.0, scene.crs, scene.origin_m)
    whole = render_frame(scene, cam, 0.0, sun, technique, ground=ground)
    strips = render_frame(scene, cam, 0.0, sun, technique, ground=ground, strip_rows=rows)
    assert strips.diagnostics.gbuffer["strips"] == -(-cam.height_px // rows)
    if ground is None:
        assert 0.05 < (~whole.surfaces.valid).mean()
    else:
        assert strips.diagnostics.ground.pixels == whole.diagnostics.ground.pixels > 1000
    shadowed = whole.surfaces.valid & (whole.lit == 0.0)
    assert 0.05 < shadowed.mean() and (whole.lit == 1.0).mean() > 0.05  # shadows to compare
    _assert_same(_outputs(scene, whole, tmp_path / "whole"),
                 _outputs(scene, strips, tmp_path / "strips"))


def test_strips_equal_whole_frame_textured(tmp_path):
    """Real textured data (PLATEAU, Tokyo): the mip level reads each pixel's neighbours, which
    the strips' halo rows keep."""
    from cityshade.build import build_file

    path = shared_file("plateau-tokyo-meiji-gallery/53394517_bldg_6697_2_op_CityGML3.gml")
    _, scene, _ = build_file(path, tmp_path / "tokyo.cityshade")
    cam = map_view(scene, 0.48)
    sun = sun_from_angles(160.0, 40.0, scene.crs, scene.origin_m)
    whole = render_frame(scene, cam, 20000.0, sun, "raytrace")
    assert (whole.surfaces.valid & (whole.surfaces.texture >= 0)).mean() > 0.3  # textures seen
    strips = render_frame(scene, cam, 20000.0, sun, "raytrace", strip_rows=5)
    _assert_same(_outputs(scene, whole, tmp_path / "whole"),
                 _outputs(scene, strips, tmp_path / "strips"))


def test_strip_camera_keeps_the_pixel_centres(sample_city_scene):
    cam = map_view(sample_city_scene, 0.37)
    xs, ys = cam.screen_coordinates()
    strip = cam.strip(11, 30).strip(2, 9)    # rows 13 … 19
    sx, sy = strip.screen_coordinates()
    assert strip.row0_px == 13 and strip.shape == (7, cam.width_px)
    assert sx.tobytes() == xs.tobytes() and sy.tobytes() == ys[13:20].tobytes()
    gt, sgt = cam.geotransform(sample_city_scene.origin_m), strip.geotransform(
        sample_city_scene.origin_m)
    assert sgt[3] == pytest.approx(gt[3] - 13 * 0.37) and sgt[:3] == gt[:3]
    centre = strip.pixel_centres_world(sample_city_scene.origin_m)[3, 5]
    assert strip.pixel_of_world(centre, sample_city_scene.origin_m).tolist() == [[5, 3]]
    with pytest.raises(UsageError):
        cam.strip(5, 5)


def test_strips_refused_where_they_would_differ(sample_city_scene):
    scene = sample_city_scene
    cam = map_view(scene, 1.0)
    with pytest.raises(UsageError, match="exact technique"):
        strip_rows_for(cam, "shadowmap", strip_rows=8)
    with pytest.raises(UsageError, match="map view"):
        strip_rows_for(overview(scene, 64, 36), "raytrace", strip_rows=8)
    with pytest.raises(UsageError, match="at least 1"):
        strip_rows_for(cam, "raytrace", strip_rows=0)
    assert strip_rows_for(cam, "raytrace", strip_rows=cam.height_px) is None
    # Automatic: a 20 Mpx map of an exact technique goes in strips, a shadow map does not.
    big = dataclasses.replace(cam, width_px=5000, height_px=4000)
    rows = strip_rows_for(big, "izb")
    assert rows is not None and 1 <= rows < 4000
    assert strip_rows_for(big, "shadowmap") is None
    assert strip_rows_for(cam, "izb") is None      # small: the whole frame at once


def test_cli_strip_rows(sample_city_scene, tmp_path):
    from cityshade.cli.main import cli

    path = tmp_path / "s.cityshade"
    from golden_cases import REPO
    from cityshade.build import build_file

    build_file(REPO / "sample_data" / "sample_city.gml", path)
    args = ["render", str(path), "--camera", "map", "--pixel-size", "2", "--sun-azimuth",
            "200", "--sun-elevation", "25"]
    runner = CliRunner()
    for name, extra in (("whole", []), ("strips", ["--strip-rows", "9"])):
        res = runner.invoke(cli, args + ["-o", str(tmp_path / f"{name}.exr"), "--mask",
                                         str(tmp_path / f"{name}.png")] + extra)
        assert res.exit_code == 0, res.output
    a, _ = imageio.read_exr(tmp_path / "whole.exr")
    b, _ = imageio.read_exr(tmp_path / "strips.exr")
    assert all(a[k].tobytes() == b[k].tobytes() for k in a)
    res = runner.invoke(cli, args + ["-o", str(tmp_path / "x.exr"), "--strip-rows", "9",
                                     "--shadows", "shadowmap"])
    assert res.exit_code != 0 and "exact technique" in res.output
    assert not (tmp_path / "x.exr").exists()


def test_strip_arrays_live_in_a_temporary_file(sample_city_scene, tmp_path, monkeypatch):
    """A strip-wise frame's whole-map arrays are read-only maps of an unlinked temporary file
    in TMPDIR (nothing named is left there, in use or after), equal to the whole frame's; a
    temporary folder without room for them is refused before any work."""
    import shutil
    import tempfile

    from cityshade.runtime.memory import release_pages

    scene = sample_city_scene
    cam = map_view(scene, 2.0)
    sun = sun_from_angles(200.0, 25.0, scene.crs, scene.origin_m)
    spool = tmp_path / "tmp"
    spool.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(spool))
    whole = render_frame(scene, cam, 0.0, sun, "izb")
    strips = render_frame(scene, cam, 0.0, sun, "izb", strip_rows=4)
    assert list(spool.iterdir()) == []
    kept = (strips.lit, strips.rgb, strips.surfaces.valid, strips.surfaces.depth,
            strips.surfaces.normal, strips.surfaces.obj_id, strips.gbuffer.prim_id)
    for a in kept:
        assert not a.flags.writeable
    assert release_pages(*kept) >= sum(a.nbytes for a in kept)   # file pages, not memory
    assert release_pages(strips.rgb[..., 1]) >= strips.rgb.nbytes - 8   # a channel: its rows
    for a, b in zip(kept, (whole.lit, whole.rgb, whole.surfaces.valid, whole.surfaces.depth,
                           whole.surfaces.normal, whole.surfaces.obj_id,
                           whole.gbuffer.prim_id)):
        assert a.tobytes() == np.asarray(b).tobytes()
    monkeypatch.setattr(shutil, "disk_usage", lambda folder: shutil._ntuple_diskusage(1, 1, 0))
    with pytest.raises(UsageError, match="TMPDIR"):
        render_frame(scene, cam, 0.0, sun, "izb", strip_rows=4)
