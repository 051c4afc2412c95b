"""The stress set: the quick set passes on the sample city (CI), the shift is exact, the
bounds table, and the exit status on a failing case."""
from __future__ import annotations

import numpy as np
from citygml_snippets import box_polygons, building, city
from click.testing import CliRunner
from conftest import REPO

from cityshade.cli.main import cli
from cityshade.evaluate.stress import (AGREEMENT, SHIFT_M, CaseResult, StressReport, error_bound_pct,
                              geometry_model_gml, shifted_gml)


def test_quick_stress_set_passes_on_the_sample_city(tmp_path):
    """CI: ``cityshade evaluate sample_city.gml --stress --quick`` passes every case."""
    res = CliRunner().invoke(cli, ["evaluate", str(REPO / "sample_data" / "sample_city.gml"),
                                   "--stress", "--quick", "-o", str(tmp_path)])
    lines = [ln for ln in res.output.splitlines() if ln.startswith(("PASS", "FAIL"))]
    failed = [ln for ln in lines if ln.startswith("FAIL")]
    assert res.exit_code == 0 and not failed, "\n".join(failed) or res.output
    # Every part of the set ran: 7 elevations, shift, geometry, wall foot, time, sizes,
    # cascades, street.
    assert len(lines) == 14, res.output
    table = (tmp_path / "stress.md").read_text()
    assert "identical pixels % 100" in table and "time splits 0" in table


def test_shifted_copy_moves_x_and_y_exactly(tmp_path):
    from lxml import etree

    src = tmp_path / "b.gml"
    src.write_text(city(building("b", box_polygons(690000.25, 5336000.5, 500.0, 10, 12, 20, "b"))))
    dst = tmp_path / "shifted.gml"
    n = shifted_gml(src, dst)
    assert n == 6 * 5   # 6 faces × 5 ring points (the solid refers to them by xlink)
    before = [np.array(e.text.split(), float).reshape(-1, 3) for e in etree.parse(str(src)).iter(
        "{http://www.opengis.net/gml}posList")]
    after = [np.array(e.text.split(), float).reshape(-1, 3) for e in etree.parse(str(dst)).iter(
        "{http://www.opengis.net/gml}posList")]
    assert len(before) == len(after) == 6
    for a, b in zip(before, after):
        np.testing.assert_array_equal(b[:, :2], a[:, :2] + SHIFT_M)
        np.testing.assert_array_equal(b[:, 2], a[:, 2])


def test_geometry_model_is_wellformed_and_dateless():
    from lxml import etree

    root = etree.fromstring(geometry_model_gml().encode())
    ids = root.xpath("//@*[local-name()='id']")
    assert len(ids) == len(set(ids)) and "tower" in ids and "thin" in ids
    assert not root.xpath("//*[local-name()='yearOfConstruction']")


def test_error_bounds():
    assert error_bound_pct("hybrid:vsm", 45.0, 4096) == 100 * (1 - AGREEMENT)
    assert error_bound_pct("pcf", -5.0, 4096) == 0.0
    assert error_bound_pct("shadowmap", 45.0, 256) == 2 * error_bound_pct("shadowmap", 45.0, 1024)
    assert error_bound_pct("csm", 0.1, 2048) > error_bound_pct("csm", 3.0, 2048) > \
        error_bound_pct("csm", 45.0, 2048)


def test_a_failing_case_gives_exit_status_1(monkeypatch, tmp_path):
    import cityshade.evaluate.stress as stress

    def fake(path, settings, progress=None, echo=None):
        cases = [CaseResult("fine", True, {"x": 1.0}),
                 CaseResult("broken", False, {"y": 2.0}, ["y too large"])]
        for c in cases:
            echo(c.line())
        return StressReport(cases=cases)

    monkeypatch.setattr(stress, "run_stress", fake)
    res = CliRunner().invoke(cli, ["evaluate", "whatever.gml", "--stress", "-o", str(tmp_path)])
    assert res.exit_code == 1
    assert "PASS  fine: x 1" in res.output and "FAIL  broken: y 2 — y too large" in res.output
    assert "1 of 2 cases passed; FAILED: broken" in res.output
    assert "**FAIL**" in (tmp_path / "stress.md").read_text()
