"""--bbox and --margin-m (issue 40 point 3): a map of part of a model, whose shadows still come
from every caster of the model, and a default whole-model map with a margin that keeps the
shadows falling past the model's edge."""
from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city, ground

from cityshade.cli.main import cli

X0, Y0, Z0 = 690_000.0, 5_336_000.0, 500.0
H = 60.0  # the tower
#: A box 20-60 m north of the 10 × 10 m tower, which it does not contain. At noon-like sun
#: (azimuth 180°, elevation 45°) the tower's shadow reaches 60 m north into it.
BOX = (X0 - 10, Y0 + 20, X0 + 30, Y0 + 60)
SUN = ("--date", "2000", "--sun-azimuth", "180", "--sun-elevation", "45")


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


@pytest.fixture(scope="module")
def tower(tmp_path_factory):
    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("extent")
    src = tmp / "tower.gml"
    src.write_text(city(ground(X0 - 40, Y0 - 40, X0 + 50, Y0 + 90, Z0),
                        building("t", box_polygons(X0, Y0, Z0, 10, 10, H, "t"))))
    out, _, _ = build_file(src, tmp / "tower.cityshade")
    return out


def mask_of(tmp_path, scene, name, *args):
    """The 8-bit mask (255 sun, 0 shadow, 128 no surface) of a 1 m map render."""
    from cityshade.imageio import read_image

    path = tmp_path / f"{name}.png"
    result = run("render", scene, *SUN, "--camera", "map", "--pixel-size", "1", *args,
                 "-o", tmp_path / f"{name}.exr", "--mask", path)
    assert result.exit_code == 0, result.output
    pixels = read_image(path)[0]
    return pixels[..., 0] if pixels.ndim == 3 else pixels


@pytest.mark.parametrize("technique", ["raytrace", "izb"])
def test_a_box_is_shaded_by_a_caster_outside_it_as_in_the_whole_map(tower, tmp_path, technique):
    whole = mask_of(tmp_path, tower, "whole", "--shadows", technique, "--margin-m", "0")
    part = mask_of(tmp_path, tower, "part", "--shadows", technique,
                   "--bbox", ",".join(f"{v:.0f}" for v in BOX))
    # The model's box is the ground's (x 689960..690050, y 5335960..5336090) at 1 m pixels,
    # both grids on whole metres of the CRS: the box's pixels are rows 30..70, columns 30..70
    # of the whole map (rows from the north edge).
    assert whole.shape == (130, 90) and part.shape == (40, 40)
    same = whole[90 - 60:90 - 20, 30:70]
    assert np.array_equal(part, same)
    # The shadow of the tower, 10 m wide, reaches y = Y0 + 10 + 60 = Y0 + 70 (45° sun), so it
    # crosses the box in the tower's 10 columns, slanted by the grid convergence (about 1.9°
    # at x = 690,000 in UTM 32: 1.3 m over the 40 m of the box).
    shadow = part == 0
    assert 0.85 * 400 <= shadow.sum() <= 1.15 * 400
    assert shadow[:, 12:18].all()
    assert not shadow[:, :7].any() and not shadow[:, 23:].any()


def test_the_default_map_keeps_a_margin_up_to_where_the_ground_plane_ends(tower, tmp_path):
    """Model box 90 × 130 m, 60 m high: two heights (120 m) of margin would reach past the
    ground plane (half the box's diagonal, 79.1 m), where a map shows no surface at all; the
    margin stops before it (at 0.9 of it: the extent is rounded up to whole pixels), so every
    pixel of the default map is a surface."""
    from cityshade.geometry.ground import GROUND_MARGIN_REL
    from cityshade.imageio import read_image
    from cityshade.raster.camera import default_map_margin_m
    from cityshade.store.scenefile import load_scene

    margin = 0.9 * GROUND_MARGIN_REL * np.hypot(90.0, 130.0)
    assert margin < 2 * H
    assert default_map_margin_m(load_scene(tower)) == pytest.approx(margin)
    tif, mask = tmp_path / "m.tif", tmp_path / "m.png"
    result = run("render", tower, *SUN, "--camera", "map", "--pixel-size", "1",
                 "-o", tmp_path / "m.exr", "--geotiff", tif, "--mask", mask)
    assert result.exit_code == 0, result.output
    rows, cols = read_image(tif)[0].shape[:2]
    assert abs(cols - (90 + 2 * margin)) <= 2 and abs(rows - (130 + 2 * margin)) <= 2
    world = [float(v) for v in tif.with_suffix(".tfw").read_text().split()]
    assert abs(world[4] - (X0 - 40 - margin + 0.5)) <= 1.0
    assert not (read_image(mask)[0] == 128).any()


def test_bbox_errors_are_one_line(tower, tmp_path):
    cases = [
        (("--camera", "map", "--bbox", "1,2,3"),
         "cityshade: error: --bbox must be X0,Y0,X1,Y1 in the model CRS (metres), not "
         "'1,2,3'"),
        (("--camera", "map", "--bbox", f"{X0 + 10:.0f},{Y0:.0f},{X0:.0f},{Y0 + 10:.0f}"),
         "cityshade: error: the map box must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not "
         "690010,5336000,690000,5336010"),
        (("--bbox", f"{X0:.0f},{Y0:.0f},{X0 + 10:.0f},{Y0 + 10:.0f}"),
         "cityshade: error: --bbox and --margin-m apply to the map view (--camera map)"),
        (("--camera", "map", "--margin-m", "-5"),
         "cityshade: error: the map margin must be a number of metres >= 0, not -5.0"),
        (("--camera", "map", "--bbox", f"{X0 - 1e5:.0f},{Y0:.0f},{X0 + 1e5:.0f},{Y0 + 10:.0f}",
          "--pixel-size", "0.5"),
         "cityshade: error: a map of 400000x20 pixels exceeds the limit of 16384 per side; "
         "choose a pixel size of at least 12.2 m"),
    ]
    for args, line in cases:
        result = run("render", tower, *SUN, *args, "-o", tmp_path / "x.exr")
        assert result.exit_code == 2 and result.output.strip().splitlines() == [line], args
