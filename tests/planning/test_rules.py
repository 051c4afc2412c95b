"""The rule engine (cityshade.planning.rules) on synthetic arrays: shares, levels, stretches,
relative tests, loading and refusing rule files."""

from __future__ import annotations


import numpy as np
import pytest


from cityshade.errors import ConfigError


# --- the rule engine on synthetic arrays ----------------------------------------------------------

def _rule(**kw):
    from cityshade.planning.rules import _rule_from

    table = {"id": "r", "name": "r", "source": "s", "receivers": "area", "date": "03-21",
             "min_hours": 2.0}
    table.update(kw)
    if "levels" in kw:
        del table["min_hours"]  # the lowest level is the threshold
    return _rule_from(table, "test")


def _m(values, weight=None, longest=None, stretches=None):
    from cityshade.planning.rules import Measures

    v = np.asarray(values, float)
    return Measures(v, v if longest is None else np.asarray(longest, float),
                    v if stretches is None else np.asarray(stretches, float),
                    np.ones(len(v)) if weight is None else np.asarray(weight, float),
                    [f"o{i}" for i in range(len(v))])


def test_bre_garden_share_and_relative_edges():
    from cityshade.planning.rules import evaluate

    rule = _rule(share=0.5, relative=0.8)
    six_steps = sum([1 / 3] * 6)  # 2 h from 20-minute steps: just below 2.0 in binary
    assert six_steps < 2.0
    # Exactly half the area has exactly 2 h: passes.
    v = evaluate(rule, _m([six_steps, 2.0, 1.99, 0.0]), _m([3, 3, 3, 3]))
    assert v.status == "pass" and v.numbers["share_after"] == 0.5
    # Less than half, and less than 0.8 x the former share: fails.
    v = evaluate(rule, _m([2.0, 1.9, 1.9, 1.9]), _m([3, 3, 3, 3]))
    assert v.status == "fail" and v.numbers["share_after"] == 0.25
    assert v.numbers["ratio"] == 0.25
    # Less than half, but kept 0.8 x the former share (0.4 of 0.5): passes.
    w = [1] * 10
    v = evaluate(rule, _m([2] * 4 + [0] * 6, w), _m([2] * 5 + [0] * 5, w))
    assert v.status == "pass" and v.numbers["share_before"] == 0.5
    v = evaluate(rule, _m([2] * 3 + [0] * 7, w), _m([2] * 5 + [0] * 5, w))
    assert v.status == "fail"
    # Area weights count, not receivers.
    v = evaluate(rule, _m([2, 0], [3, 1]))
    assert v.numbers["share_after"] == 0.75 and v.status == "pass"


def test_en17037_levels_and_chinese_stretches():
    from cityshade.planning.rules import evaluate

    en = _rule(receivers="openings", levels={"minimum": 1.5, "medium": 3.0, "high": 4.0})
    v = evaluate(en, _m([1.5, 1.4999, 3.0, 4.5]))
    assert [d["grade"] for d in v.details] == ["minimum", "below minimum", "medium", "high"]
    assert [d["status"] for d in v.details] == ["pass", "fail", "pass", "pass"]
    assert v.status == "fail" and v.numbers["passing"] == 3
    cn = _rule(receivers="openings", measure="stretches", min_stretch_min=5, min_hours=2.0)
    # Same total, but receiver 1's sun comes in stretches too short to count.
    v = evaluate(cn, _m([2.5, 2.5], stretches=[2.0, 1.5]))
    assert [d["status"] for d in v.details] == ["pass", "fail"]
    longest = _rule(receivers="openings", measure="longest", min_hours=1.0)
    assert evaluate(longest, _m([3, 3], longest=[1.0, 0.99])).details[1]["status"] == "fail"


def test_point_rule_with_only_a_relative_test_is_not_assessed_but_shows_the_ratio():
    from cityshade.planning.rules import evaluate

    rule = _rule(receivers="openings", min_hours=0.0, relative=0.8,
                 not_assessed=["needs APSH"])
    v = evaluate(rule, _m([80.0, 79.0]), _m([100.0, 100.0]))
    assert v.status == "not assessed" and v.not_assessed == ("needs APSH",)
    assert [d["status"] for d in v.details] == ["pass", "fail"]
    assert v.details[1]["ratio"] == 0.79


def test_shipped_rules_load_and_bad_files_are_refused(tmp_path):
    from cityshade.planning.rules import load_rules

    ids = [r.id for name in ("bre209", "en17037", "china-sunshine") for r in load_rules(name)]
    assert ids == ["bre209-garden", "bre209-window", "en17037-sunlight", "gb50180-great-cold"]
    bad = tmp_path / "bad.toml"
    bad.write_text('[[rule]]\nid="x"\nname="x"\nsource="s"\nreceivers="area"\ndate="03-21"\n'
                   'min_hours=2\nshare=0.5\ncolour="red"\n')
    with pytest.raises(ConfigError, match="unknown key 'colour'"):
        load_rules(bad)
    bad.write_text('[[rule]]\nid="x"\nname="x"\nsource="s"\nreceivers="garden"\ndate="03-21"\n')
    with pytest.raises(ConfigError, match="receivers must be one of"):
        load_rules(bad)
    with pytest.raises(ConfigError, match="no shipped rule set"):
        load_rules("nonesuch")


def test_points_in_polygon():
    from cityshade.planning.rules import points_in_polygon

    ring = np.array([(0, 0), (4, 0), (4, 4), (2, 2), (0, 4)], float)
    pts = np.array([(1, 1), (3, 1), (2, 3), (1, 2.5), (5, 1)], float)
    assert points_in_polygon(pts, ring).tolist() == [True, True, False, True, False]
