"""Shadow studies (issue 39): a panel is ``render``'s mask at that time, the new-shadow colour
only where the state after is in shadow and the state before is not, one sheet per day with a
scale bar as long as its metres and north by the meridian convergence, exact CLI errors."""
from __future__ import annotations

import csv
import re
from datetime import date, datetime
from pathlib import Path
from zoneinfo import ZoneInfo

import numpy as np
import pytest
from click.testing import CliRunner

pytest.importorskip("matplotlib")

REPO = Path(__file__).resolve().parents[2]
SAMPLE_GML = REPO / "sample_data" / "sample_city.gml"
DAYS = (date(2025, 3, 21), date(2025, 6, 21))
CLOCKS_S = (9 * 3600, 15 * 3600)
PIXEL_M = 4.0


@pytest.fixture(scope="module")
def study(sample_city_scene, tmp_path_factory):
    """The sample city, 1750 against 1990, two days at 09:00 and 15:00 Berlin time."""
    from cityshade.planning.run import CompareStates
    from cityshade.study import StudyRequest, StudyTimes, run_study

    out = tmp_path_factory.mktemp("study") / "out"
    request = StudyRequest(sample_city_scene, StudyTimes(DAYS, CLOCKS_S, "Europe/Berlin"),
                           CompareStates("1750", "1990"), pixel_size_m=PIXEL_M,
                           area=(690100.0, 5336050.0, 690160.0, 5336110.0), outdir=out)
    return request, run_study(request), out


def _tif(path) -> np.ndarray:
    from cityshade.imageio import read_image

    pixels, _ = read_image(path)
    return pixels[..., 0]


def _render_mask(scene, camera, city: str, instant: datetime) -> np.ndarray:
    """``cityshade render --camera map --mask`` of the library: the frame and its mask."""
    from cityshade.frame.render import render_frame, shadow_mask
    from cityshade.geo.sun import sun_from_instant
    from cityshade.geo.temporal import parse_user_date

    sun = sun_from_instant(instant, scene.crs, scene.origin_m)
    frame = render_frame(scene, camera, parse_user_date(city).city_days, sun, "izb",
                         ground="auto")
    return shadow_mask(frame)


def test_a_panel_is_the_render_mask_pixel_for_pixel(study, sample_city_scene):
    from cityshade.raster.camera import map_view

    _request, result, out = study
    row = next(r for r in result.rows if r["day"] == "2025-06-21" and r["time"] == "15:00")
    instant = datetime(2025, 6, 21, 15, 0, tzinfo=ZoneInfo("Europe/Berlin"))
    # The camera of `render --camera map --pixel-size 4`.
    camera = map_view(sample_city_scene, PIXEL_M)
    assert camera.geotransform(sample_city_scene.origin_m) == \
        result.camera.geotransform(sample_city_scene.origin_m)
    for state, city in (("before", "1750"), ("after", "1990")):
        panel = _tif(out / row[f"{state}_tif"])
        expected = _render_mask(sample_city_scene, camera, city, instant)
        assert panel.shape == expected.shape
        assert np.array_equal(panel, expected), (state, np.count_nonzero(panel != expected))
    assert (panel == 0).any() and (panel == 255).any()


def test_new_shadow_is_drawn_only_where_after_is_shadow_and_before_is_not(study,
                                                                          sample_city_scene):
    from cityshade.geo.temporal import parse_user_date
    from cityshade.study.panels import (
        NEW_SHADOW,
        PALETTE,
        categories,
        panel_rgb,
        study_view,
    )

    _request, result, out = study
    t0, t1 = (parse_user_date(y).city_days for y in ("1750", "1990"))
    view = study_view(sample_city_scene, t0, sample_city_scene, t1, result.camera)
    orange_seen = 0
    for row in result.rows:
        before, after = _tif(out / row["before_tif"]), _tif(out / row["after_tif"])
        rgb = panel_rgb(categories(before, after, view))
        orange = (rgb == PALETTE[NEW_SHADOW]).all(axis=2)
        assert ((after[orange] == 0) & (before[orange] == 255)).all()
        # ... and on every surface seen in both states where that holds.
        assert np.array_equal(orange, view.same & (after == 0) & (before == 255))
        assert row["new_shadow_m2"] == pytest.approx(orange.sum() * PIXEL_M ** 2)
        orange_seen += int(orange.sum())
    assert orange_seen > 0
    # No other category shares the colour.
    others = np.delete(PALETTE, NEW_SHADOW, axis=0)
    assert not (others == PALETTE[NEW_SHADOW]).all(axis=1).any()


def test_random_masks_get_the_new_shadow_colour_only_where_the_rule_says(sample_city_scene):
    from cityshade.study.panels import (
        NEW_SHADOW,
        PALETTE,
        StudyView,
        categories,
        panel_rgb,
    )

    rng = np.random.default_rng(3)
    shape = (40, 50)
    before = rng.choice(np.array([0, 128, 255], np.uint8), shape)
    after = rng.choice(np.array([0, 128, 255], np.uint8), shape)
    same, building = rng.random(shape) < 0.7, rng.random(shape) < 0.4
    view = StudyView(None, None, same, building, building & ~same)
    orange = (panel_rgb(categories(before, after, view)) == PALETTE[NEW_SHADOW]).all(axis=2)
    assert np.array_equal(orange, same & (after == 0) & (before == 255))


def test_an_extent_frames_the_map_on_whole_pixels(sample_city_scene):
    from cityshade.study.panels import study_camera

    extent = (690101.0, 5336041.0, 690199.0, 5336119.0)
    cam = study_camera(sample_city_scene, 2.0, 1024, extent)
    x0, px, _, y1, _, neg = cam.geotransform(sample_city_scene.origin_m)
    h, w = cam.shape
    assert px == 2.0 and neg == -2.0
    # The grid on multiples of the pixel size, covering the extent with at most a pixel more.
    assert x0 % 2.0 == 0.0 and y1 % 2.0 == 0.0
    assert extent[0] - 2.0 < x0 <= extent[0] and extent[3] <= y1 < extent[3] + 2.0
    assert extent[2] <= x0 + w * px < extent[2] + 4.0
    assert extent[1] - 4.0 < y1 - h * px <= extent[1]
    # Without a pixel size: the nice size that fits the longer side (98 m) into 1024 px.
    assert study_camera(sample_city_scene, None, 1024, extent).pixel_size_m == 0.1


def test_one_sheet_per_day_as_pdf_pages_and_pngs_with_the_index(study):
    _request, _result, out = study
    pdf = (out / "study.pdf").read_bytes()
    assert len(re.findall(rb"/Type\s*/Page(?![a-zA-Z])", pdf)) == len(DAYS)
    assert sorted(p.name for p in out.glob("sheet_*.png")) == [
        f"sheet_{d.isoformat()}.png" for d in DAYS]
    with open(out / "study.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    assert [(r["day"], r["time"]) for r in rows] == [
        (d.isoformat(), t) for d in DAYS for t in ("09:00", "15:00")]
    assert len(list((out / "panels").glob("*.tif"))) == 2 * len(DAYS) * len(CLOCKS_S)
    assert not list(out.rglob(".*.tmp*"))  # no temporary file left


def test_the_sheet_scale_bar_is_its_metres_and_north_turns_by_the_convergence(study):
    import pyproj

    from cityshade.imageio import read_image

    request, result, out = study
    info = result.sheets[0]
    sheet, _ = read_image(out / f"sheet_{DAYS[0].isoformat()}.png")
    row = sheet[info.scale_bar_row, :, :3]
    black = (row < 40).all(axis=1)
    n = 0
    while black[info.scale_bar_col + n]:
        n += 1
    # The bar: its stated metres at the panels' scale, which is the panel's drawn width over
    # the map's width in metres.
    col0, _row0, col1, _row1 = info.panel_boxes[0]
    h_px, w_px = result.camera.shape
    px_per_m = (col1 - col0) / (w_px * PIXEL_M)
    assert info.px_per_m == pytest.approx(px_per_m, abs=1.5 / (w_px * PIXEL_M))
    assert abs(n - info.scale_bar_m * px_per_m) <= 1.5, (n, info.scale_bar_m * px_per_m)
    assert info.scale_bar_px == pytest.approx(info.scale_bar_m * info.px_per_m)
    # North: PROJ's meridian convergence at the map centre.
    gt = result.camera.geotransform(request.scene.origin_m)
    proj = pyproj.Proj("EPSG:25832")
    lon, lat = proj(gt[0] + 0.5 * w_px * gt[1], gt[3] + 0.5 * h_px * gt[5], inverse=True)
    gamma = proj.get_factors(lon, lat).meridian_convergence
    assert info.convergence_deg == pytest.approx(gamma, abs=0.1)
    assert info.true_north_cw_deg == pytest.approx(-gamma, abs=0.1)  # γ ≈ 1.9° here


def _one_error_line(args) -> str:
    from cityshade.cli.main import cli

    result = CliRunner().invoke(cli, [str(a) for a in args])
    lines = result.output.strip().splitlines()
    assert result.exit_code != 0 and len(lines) == 1, result.output
    return lines[0]


def test_cli_errors_are_one_exact_line_and_write_nothing(tmp_path):
    out = tmp_path / "out"
    base = ["study", SAMPLE_GML, "--tz", "Europe/Berlin", "-o", out]
    cases = [
        ([], "cityshade: error: give --after DATE (one model, two dates) or --with PROPOSAL"),
        (["--after", "1990", "--days", "2025-13-01"], ("cityshade: error: --days must be days "
         "YYYY-MM-DD separated by commas, not '2025-13-01'")),
        (["--after", "1990", "--days", "2025-03-21", "--year", "2025"],
         "cityshade: error: give --days or --year, not both"),
        (["--after", "1990", "--times", "09:00", "--every", "2h"],
         "cityshade: error: give --times or --from/--to/--every, not both"),
        (["--after", "1990", "--every", "10min"], ("cityshade: error: 61 times a day make 61 "
         "panels on a sheet; at most 24: choose a longer --every or fewer --times")),
        (["--after", "1990", "--shadows", "pcf"],
         "cityshade: error: a study needs an exact technique (exact or izb or raytrace), not pcf"),
        (["--after", "1990", "--area", "1,2,3"], ("cityshade: error: --area must be "
         "x0,y0,x1,y1 with x0 < x1 and y0 < y1, not '1,2,3'")),
        (["--after", "1990", "--extent", "5,5,1,1"], ("cityshade: error: --extent must be "
         "x0,y0,x1,y1 with x0 < x1 and y0 < y1, not '5,5,1,1'")),
    ]
    for extra, line in cases:
        assert _one_error_line(base + extra) == line
    assert list(tmp_path.iterdir()) == []


def test_an_interrupted_study_leaves_nothing(tmp_path, monkeypatch):
    from cityshade.cli.main import cli
    from cityshade.study import panels

    made = []
    real = panels.make_panel

    def interrupted(*args, **kwargs):
        made.append(1)
        if len(made) == 3:
            raise KeyboardInterrupt
        return real(*args, **kwargs)

    monkeypatch.setattr(panels, "make_panel", interrupted)
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, [str(a) for a in [
        "study", SAMPLE_GML, "--before", "1750", "--after", "1990", "--days",
        "2025-03-21,2025-06-21", "--times", "09:00,15:00", "--tz", "Europe/Berlin",
        "--pixel-size", "8", "-o", out]])
    assert result.exit_code == 130, result.output
    assert result.output.strip().splitlines()[-1] == "cityshade: interrupted"
    assert len(made) == 3 and not out.exists()


@pytest.fixture(scope="module")
def tree_states(tmp_path_factory):
    """Ground 100 × 100 m with a 10 m building H at (20..30, -5..5); after, crown C over
    (10..16, -5..5) at z 5..11 is planted (the objects before keep their ids)."""
    from citygml_snippets import box_polygons, building, city, ground, tree

    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("study_trees")
    common = [ground(-50, -50, 50, 50), building("H", box_polygons(20, -5, 0, 10, 10, 10, "h"))]
    scenes = []
    for name, extra in (("before", []), ("after", [tree("C", box_polygons(10, -5, 5, 6, 10, 6,
                                                                          "c"))])):
        src = tmp / f"{name}.gml"
        src.write_text(city(*common, *extra))
        out, _, _ = build_file(src, tmp / f"{name}.cityshade")
        scenes.append(load_scene(out))
    return scenes


def test_tree_crowns_their_shade_and_new_tree_shade_are_drawn_apart(tree_states):
    """Sun from the south at 60° (the closed form of tests/shadows/test_vegetation.py: the
    ground north of a box at heights z0..z1 over y0..y1 is in its shade for y in
    [y0 + z0/tan 60°, y1 + z1/tan 60°]): north of crown C the ground had the whole sun and
    gets τ = 0.03 (new tree shade; tree shade when the crown stood before too), north of the
    building existing shadow, the crown's top is a crown, open ground sun; the masks are
    ``render --mask``'s grey levels."""
    from cityshade.frame.render import render_frame, shadow_mask
    from cityshade.geo.sun import sun_from_angles
    from cityshade.raster.camera import map_view
    from cityshade.study.panels import (NEW_TREE_SHADE, SHADOW, SUN, TREE_CROWN, TREE_SHADE,
                                        make_panel, study_view)

    before, after = tree_states
    sun = sun_from_angles(180.0, 60.0)
    cam = map_view(after, 1.0)
    when = datetime(2025, 6, 21, 12, tzinfo=ZoneInfo("UTC"))
    world = None
    for scene_before, under_crown in ((before, NEW_TREE_SHADE), (after, TREE_SHADE)):
        view = study_view(scene_before, 0.0, after, 0.0, cam, "auto")
        assert view.trees
        panel = make_panel(view, when.date(), when, sun, "exact")
        frame = render_frame(after, cam, 0.0, sun, "exact", ground="auto")
        np.testing.assert_array_equal(panel.after, shadow_mask(frame, after))
        world = frame.surfaces.position_m + after.origin_m
        on_ground = frame.surfaces.valid & (np.abs(world[..., 2]) < 1e-3)
        x, y = world[..., 0], world[..., 1]
        for want, (x0, x1, y0, y1) in ((under_crown, (11, 15, 6, 10.3)),
                                       (SHADOW, (21, 29, 6, 9.7)), (SUN, (35, 45, -40, 40))):
            px = on_ground & (x > x0) & (x < x1) & (y > y0) & (y < y1)
            assert px.sum() >= 10 and (panel.cats[px] == want).all(), (want, x0, y0)
        top = frame.surfaces.valid & (np.abs(world[..., 2] - 11.0) < 1e-3) & (x > 10) & (x < 16)
        assert top.sum() >= 10 and (panel.cats[top] == TREE_CROWN).all()
        assert panel.area_m2["tree_shade"] > 0.0
        if under_crown == NEW_TREE_SHADE:
            assert panel.area_m2["new_tree_shade"] == panel.area_m2["tree_shade"]
            assert panel.area_m2["new"] == 0.0  # the new shade is the trees'


def test_a_proposal_below_the_ground_does_not_move_the_ground_plane(sample_city_scene):
    """A block sunk 3 m below the model's typical ground and far outside the map: the ground
    plane stays where the model puts it, so nothing on the map changes (no new shadow, none
    gone: a moved plane would move every shadow edge on it)."""
    from citygml_snippets import box_polygons, building, city

    from cityshade.build import build_file
    from cityshade.config import Settings
    from cityshade.geo.sun import sun_from_angles
    from cityshade.planning.compare import merge_scenes
    from cityshade.planning.run import load_proposal
    from cityshade.study.panels import NEW_SHADOW, SHADOW_GONE, make_panel, study_camera, \
        study_view

    scene = sample_city_scene
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        z = float(scene.origin_m[2]) - 25.0
        src = Path(tmp) / "sunk.gml"
        src.write_text(city(building("SUNK", box_polygons(691000.0, 5337000.0, z, 5, 5, 1, "s"),
                                     srs="EPSG:25832")))
        out, _, _ = build_file(src, Path(tmp) / "sunk.cityshade")
        settings = Settings()
        after = merge_scenes(scene, load_proposal(out, settings, scene, None), settings)
        cam = study_camera(scene, 2.0, 1024)
        view = study_view(scene, 20000.0, after, 20000.0, cam, "auto")
        assert view.before.ground.z_crs_m == view.after.ground.z_crs_m
        when = datetime(2025, 3, 21, 9, tzinfo=ZoneInfo("UTC"))
        panel = make_panel(view, when.date(), when, sun_from_angles(135.0, 20.0), "exact")
    assert not np.isin(panel.cats, (NEW_SHADOW, SHADOW_GONE)).any()
