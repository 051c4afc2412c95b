"""``cityshade evaluate``: error metrics against analytic cases, the feature transform against
its brute-force twin, the Pareto front, and the report written by the CLI."""
from __future__ import annotations

import csv

import numpy as np
import pytest
from citygml_snippets import box_polygons, building, city, ground
from click.testing import CliRunner
from reference import reference_nearest_feature_distance2

from cityshade.build import build_file
from cityshade.cli.main import cli
from cityshade.errors import UsageError
from cityshade.frame.diagnostics import skipped_work
from cityshade.evaluate import (EvaluateSettings, compare, diff_image, error_time_plot,
                                expand_techniques, make_reference, nearest_feature,
                                pareto_front)
from cityshade.store.scenefile import load_scene


@pytest.mark.parametrize("seed,density", [(0, 0.002), (1, 0.05), (2, 0.5), (3, 0.97)])
def test_nearest_feature_matches_brute_force(seed, density):
    rng = np.random.default_rng(seed)
    feature = rng.random((37, 53)) < density
    feature[rng.integers(37), rng.integers(53)] = True
    rows, cols = nearest_feature(feature)
    assert feature[rows, cols].all(), "every pixel must point at a feature pixel"
    r, c = np.mgrid[0:37, 0:53]
    d2 = (rows - r) ** 2 + (cols - c) ** 2
    np.testing.assert_array_equal(d2, reference_nearest_feature_distance2(feature))


def test_nearest_feature_without_features_and_read_only_input():
    empty = np.zeros((4, 5), bool)
    rows, cols = nearest_feature(empty)
    assert (rows == -1).all() and (cols == -1).all()
    one = np.zeros((6, 7), bool)
    one[2, 3] = True
    one.setflags(write=False)
    rows, cols = nearest_feature(one)
    assert (rows == 2).all() and (cols == 3).all()


def _flat_reference(shadow_cols: int, width=40, height=20, px_m=0.5):
    """A flat map: pixel (r, c) at (c·px, −r·px, 0); the reference is shadow in the first
    ``shadow_cols`` columns."""
    r, c = np.mgrid[0:height, 0:width]
    pos = np.stack([c * px_m, -r * px_m, np.zeros_like(r, float)], axis=-1).astype(np.float64)
    ref_lit = (c >= shadow_cols).astype(np.float32)
    return make_reference(ref_lit, np.ones((height, width), bool), pos), c


def test_shadow_too_long_by_three_pixels():
    ref, c = _flat_reference(10)
    lit = (c >= 13).astype(np.float32)          # the technique's shadow ends 3 px too late
    err = compare(lit, ref)
    # Columns 10, 11, 12 are false shadow, 1, 2 and 3 pixels (0.5 m each) from true shadow.
    assert err["wrong_px"] == 3 * 20 and err["false_lit_pct"] == 0.0
    assert err["false_shadow_pct"] == pytest.approx(100 * 3 / 40)
    assert err["misclassified_pct"] == pytest.approx(7.5)
    assert err["edge_mean_m"] == pytest.approx(1.0)   # (0.5 + 1.0 + 1.5) / 3
    assert err["edge_max_m"] == pytest.approx(1.5)
    assert err["edge_p95_m"] == pytest.approx(1.5, abs=0.06)
    assert err["lit_mae"] == pytest.approx(3 / 40)


def test_shadow_too_short_is_false_lit_and_fractions_threshold_at_half():
    ref, c = _flat_reference(10)
    lit = np.where(c >= 8, 1.0, 0.4).astype(np.float32)   # 0.4 counts as shadow
    err = compare(lit, ref)
    assert err["false_shadow_pct"] == 0.0
    assert err["false_lit_pct"] == pytest.approx(100 * 2 / 40)
    assert err["edge_mean_m"] == pytest.approx(0.75)        # 1 and 2 px from truly lit
    assert err["lit_mae"] == pytest.approx((8 * 0.4 + 2 * 1.0) / 40, rel=1e-6)
    same = compare(ref.lit.astype(np.float32), ref)
    assert same["wrong_px"] == 0 and same["edge_mean_m"] == 0.0


def test_invalid_pixels_never_count():
    ref, c = _flat_reference(10)
    valid = c < 10                                  # only the shadowed half shows a surface
    r = make_reference((c >= 10).astype(np.float32), valid, ref.position_m)
    err = compare(np.ones(valid.shape, np.float32), r)
    assert err["valid_px"] == 200 and err["false_lit_pct"] == pytest.approx(100.0)
    assert err["edge_mean_m"] is None               # no truly lit surface pixel to measure to


def test_pareto_front():
    times = [1.0, 2.0, 3.0, 2.5, 0.5, 4.0]
    errors = [5.0, 1.0, 0.0, 1.0, 9.0, 0.0]
    assert pareto_front(times, errors) == [4, 0, 1, 2]


def test_expand_techniques():
    names = expand_techniques("all")
    assert len(names) == 22 and "raytrace" not in names and names[0] == "izb"
    assert {"csm+smooth", "hybrid:xpsm", "lispsm"} <= set(names)
    assert expand_techniques("pcf, raytrace,pcf") == ["pcf"]
    # `evaluate --smooth` with the default `all`: every technique of `all`, smoothed, once.
    smoothed = expand_techniques("all+smooth")
    assert len(smoothed) == 16 and all(n.endswith("+smooth") for n in smoothed)
    assert {"raytrace+smooth", "izb+smooth", "pcf+smooth", "hybrid:vsm+smooth"} <= set(smoothed)
    with pytest.raises(UsageError, match="unknown shadow technique"):
        expand_techniques("pcf,nonsense")
    with pytest.raises(UsageError):
        EvaluateSettings(sizes=(8,))


def test_plot_and_diff_image():
    entries = [{"technique": t, "map_px": s, "shadow_s": ms / 1000, "misclassified_pct": e,
                "pareto": p} for t, s, ms, e, p in
               [("raytrace", "", 40.0, 0.0, True), ("shadowmap", 1024, 8.0, 1.5, True),
                ("pcf+smooth", 2048, 20.0, 2.0, False), ("hybrid:vsm", 1024, 30.0, 0.0, True)]]
    img = error_time_plot(entries, "test")
    assert img.shape == (640, 1100, 3) and img.dtype == np.uint8
    # The shadowmap marker's colour (Okabe-Ito orange) is drawn.
    assert (img == (230, 159, 0)).all(axis=2).sum() > 10
    pic = np.full((4, 5, 3), 200, np.uint8)
    fl = np.zeros((4, 5), bool)
    fs = np.zeros((4, 5), bool)
    fl[1, 1] = fs[2, 2] = True
    d = diff_image(pic, fl, fs)
    assert tuple(d[1, 1]) == (230, 20, 20) and tuple(d[2, 2]) == (20, 60, 230)
    assert d[0, 0, 0] == d[0, 0, 2]


@pytest.fixture(scope="module")
def box_file(tmp_path_factory):
    """A 10 × 10 × 20 m box on a 100 m plane, without dates or textures."""
    tmp = tmp_path_factory.mktemp("evalbox")
    src = tmp / "box.gml"
    src.write_text(city(ground(-50, -50, 50, 50),
                        building("b", box_polygons(-5, -5, 0, 10, 10, 20, "b"))))
    out, _, _ = build_file(src, tmp / "box.cityshade")
    return out


def test_dateless_model_has_no_time_splits_and_says_so(box_file):
    scene = load_scene(box_file)
    assert scene.kdtree.stats["time_splits"] == 0 and not scene.kdtree.has_time
    lines = skipped_work(scene)
    assert any("no time dimension" in s for s in lines)
    assert any("no texture sampling" in s for s in lines)


def test_cli_evaluate_writes_the_report(box_file, tmp_path):
    from cityshade.imageio import read_image

    out = tmp_path / "report"
    res = CliRunner().invoke(cli, ["evaluate", str(box_file), "--views", "map,overview",
                                   "--size", "96x64", "--pixel-size", "1",
                                   "--sun", "135,30;200,60", "--date", "2020",
                                   "--shadows", "shadowmap,hybrid:shadowmap",
                                   "--sizes", "128,512", "--repeat", "1", "-o", str(out)])
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(open(out / "results.csv")))
    # 2 views × 2 suns × (raytrace + 2 techniques × 2 sizes)
    assert len(rows) == 2 * 2 * 5
    for r in rows:
        assert r["error"] == ""
        assert float(r["shadow_s"]) > 0 and float(r["warmup_s"]) > 0
        assert 0.0 <= float(r["misclassified_pct"]) <= 100.0
        if r["technique"] == "hybrid:shadowmap":
            assert int(r["wrong_px"]) <= 1e-4 * int(r["valid_px"]), r
            assert 0.0 < float(r["traced_share"]) < 1.0
        if r["technique"] == "shadowmap" and r["view"] == "map":
            # A 1 m map of an axis-aligned box: only the shadow's edge pixels may differ.
            assert float(r["misclassified_pct"]) < 5.0, r
    md = (out / "report.md").read_text()
    assert "Pareto front" in md and "no time dimension" in md and "| `raytrace` |" in md
    # report.html: the same page with every picture embedded, nothing loaded from outside.
    page = (out / "report.html").read_text()
    assert page.count('<img src="data:image/png;base64,') == md.count("](") > 0
    assert "http://" not in page and "https://" not in page and "Pareto front" in page
    img, _ = read_image(out / "error_vs_time_map.png")
    assert img.shape[:2] == (640, 1100)


@pytest.mark.parametrize("args,message", [
    (["--quick"], "--quick only applies to --stress"),
    ([], "-o/--output"),
    (["--sun", "10", "-o", "x"], "--sun must be"),
    (["--shadows", "bogus", "-o", "x"], "unknown shadow technique"),
])
def test_cli_evaluate_failures(box_file, args, message):
    res = CliRunner().invoke(cli, ["evaluate", str(box_file), *args])
    assert res.exit_code == 2 and message in res.output, res.output


def test_render_lists_what_it_left_out(box_file):
    from cityshade.raster.camera import overview
    from cityshade.frame.render import render_frame
    from cityshade.geo.sun import sun_from_angles

    scene = load_scene(box_file)
    # Seen from the south-west, lit from the north-east: the two visible walls face away.
    frame = render_frame(scene, overview(scene, 96, 64), 0.0, sun_from_angles(45, 30),
                         "hybrid:shadowmap")
    lines = frame.diagnostics.skipped
    assert any("no time dimension" in s for s in lines)
    assert any("facing away from the sun" in s for s in lines)
    assert any(s.strip().startswith("hybrid:") and "without a ray" in s for s in lines)


def test_report_without_matplotlib_keeps_csv_and_markdown(box_file, tmp_path, monkeypatch):
    import cityshade.evaluate.plot as plot
    from cityshade.evaluate import parse_suns, run_evaluation, view_camera, write_report

    monkeypatch.setattr(plot, "have_matplotlib", lambda: False)
    scene = load_scene(box_file)
    evaluation = run_evaluation(scene, [("map", view_camera(scene, "map", pixel_size_m=2.0))],
                                parse_suns("135,30", scene), 0.0, ["shadowmap"],
                                EvaluateSettings(repeat=1, sizes=(64,)))
    written = {p.name for p in write_report(evaluation, tmp_path / "r")}
    assert {"results.csv", "report.md", "report.html"} <= written
    assert not any(n.startswith("error_vs_time") for n in written)
    assert "plot skipped: matplotlib is not installed" in (tmp_path / "r" / "report.md").read_text()


def test_evaluate_honours_ground_like_render(box_file):
    from cityshade.evaluate import Evaluation, FrameSetup, evaluate_frame, parse_suns, view_camera
    from cityshade.frame.render import render_frame

    scene = load_scene(box_file)
    cam = view_camera(scene, "overview", (96, 64))
    sun = parse_suns("135,30", scene)[0]
    out = evaluate_frame(FrameSetup(scene, cam, "overview", sun, 0.0, ground="min"), [], [64],
                         EvaluateSettings(repeat=1, worst_cases=0), Evaluation())
    frame = render_frame(scene, cam, 0.0, sun, "raytrace", ground="min")
    assert frame.diagnostics.ground is not None
    np.testing.assert_array_equal(out["surfaces"].valid, frame.surfaces.valid)
    np.testing.assert_array_equal(out["results"][("raytrace", None)].lit, frame.lit)


def test_a_time_axis_within_a_decade_labels_its_2_and_5_ticks():
    """120–900 ms holds no power of ten: 200 and 500 are labelled; over three decades the
    powers of ten are, and the minor ticks stay bare."""
    from cityshade.evaluate.plot import minor_time_label

    assert [minor_time_label(v, True) for v in (200.0, 300.0, 500.0, 800.0)] == \
        ["200", "", "500", ""]
    assert minor_time_label(200.0, False) == ""
