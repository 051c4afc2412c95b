"""Daylight rules as data: a small TOML format and the engine that turns hours into verdicts.

A rule names its receivers (pixels of an area, surfaces of some classes, or openings), the day
and time window it is measured on, what is measured (total hours, the longest continuous
stretch, hours in stretches of a minimum length; or, for windows, the vertical sky component
``vsc`` or the probable sunlight hours ``apsh`` of a weather file), the threshold, the share of
the area that must reach it, and an "after >= k x before" comparison. The format and the
shipped rules (BRE 209 garden, VSC and APSH tests, EN 17037 sunlight exposure, a minimum
continuous sunshine rule of the Chinese kind) are documented in ``docs/RULES.md``; the files
are the package's ``rules_data/*.toml``.

The engine (:func:`evaluate`) works on plain arrays (:class:`Measures`, :class:`WindowMeasures`),
so it is tested on synthetic values; :func:`measures_from` and :func:`window_measures_from` take
them from a :class:`cityshade.planning.compare.Comparison`.
"""
from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from datetime import date
from pathlib import Path
from typing import Any

import numpy as np

from cityshade.errors import ConfigError, UsageError

__all__ = ["Rule", "Measures", "WindowMeasures", "Verdict", "load_rules", "evaluate",
           "rule_day", "measures_from", "window_measures_from", "RULES_DIR", "MEASURES",
           "LIGHT_MEASURES"]

RULES_DIR = Path(__file__).resolve().parent / "rules_data"
#: What a rule measures per receiver: hours of the sun over the rule's steps, or (openings
#: only) a fraction 0-1 at each window's reference point: the vertical sky component (``vsc``)
#: or the annual probable sunlight hours of a weather file (``apsh``, with its winter share).
HOUR_MEASURES = ("total", "longest", "stretches")
LIGHT_MEASURES = ("vsc", "apsh")
MEASURES = HOUR_MEASURES + LIGHT_MEASURES
_RECEIVERS = ("area", "surfaces", "openings")
_KEYS = {
    "id": str, "name": str, "source": str, "receivers": str, "classes": list,
    "area_bbox": list, "area_polygon": list, "facing_deg": list, "date": str, "from": str,
    "to": str, "tz": str, "every": str, "every_day": int, "to_date": str,
    "min_elevation_deg": (int, float), "measure": str, "min_stretch_min": (int, float),
    "min_hours": (int, float), "levels": dict, "share": (int, float),
    "relative": (int, float), "reference": str, "not_assessed": list, "notes": str,
    "min_fraction": (int, float), "min_winter_fraction": (int, float),
    "max_loss_fraction": (int, float), "sky": str,
}
#: Keys that only the light measures read, and the hour-measure keys they do not.
_LIGHT_KEYS = {"min_fraction", "min_winter_fraction", "max_loss_fraction", "sky"}
_HOUR_ONLY_KEYS = {"date", "from", "to", "tz", "every", "every_day", "to_date",
                   "min_elevation_deg", "min_stretch_min", "min_hours", "levels", "share",
                   "reference"}


@dataclass(frozen=True)
class Rule:
    """One rule (see ``docs/RULES.md`` for every key)."""

    id: str
    name: str
    source: str
    receivers: str
    date: str
    measure: str = "total"
    min_hours: float = 0.0
    classes: tuple[str, ...] = ()
    area_bbox: tuple[float, ...] | None = None
    area_polygon: tuple[tuple[float, float], ...] | None = None
    facing_deg: tuple[float, float] | None = None
    time_from: str = "00:00"
    time_to: str = "24:00"
    tz: str | None = None
    every: str | None = None
    every_day: int = 1
    to_date: str | None = None
    min_elevation_deg: float = 0.0
    min_stretch_min: float = 0.0
    levels: tuple[tuple[str, float], ...] = ()
    share: float | None = None
    relative: float | None = None
    reference: str = "mean"
    not_assessed: tuple[str, ...] = ()
    notes: str = ""
    min_fraction: float | None = None
    min_winter_fraction: float | None = None
    max_loss_fraction: float | None = None
    sky: str | None = None

    @property
    def is_light(self) -> bool:
        """The rule measures light at windows (``vsc``/``apsh``), not hours over steps."""
        return self.measure in LIGHT_MEASURES

    @property
    def min_stretch_h(self) -> float:
        return self.min_stretch_min / 60.0


def _rule_from(table: dict, where: str) -> Rule:
    for key, value in table.items():
        if key not in _KEYS:
            raise ConfigError(f"{where}: unknown key {key!r} (known: {', '.join(sorted(_KEYS))})")
        if not isinstance(value, _KEYS[key]) or isinstance(value, bool):
            raise ConfigError(f"{where}: {key} has the wrong type ({type(value).__name__})")
    measure = table.get("measure", "total")
    if measure not in MEASURES:
        raise ConfigError(f"{where}: measure must be one of {', '.join(MEASURES)}")
    light = measure in LIGHT_MEASURES
    for key in ("id", "name", "source", "receivers") + (() if light else ("date",)):
        if key not in table:
            raise ConfigError(f"{where}: a rule needs {key!r}")
    if table["receivers"] not in _RECEIVERS:
        raise ConfigError(f"{where}: receivers must be one of {', '.join(_RECEIVERS)}")
    if light:
        _check_light_rule(table, measure, where)
    elif set(table) & _LIGHT_KEYS:
        raise ConfigError(f"{where}: {', '.join(sorted(set(table) & _LIGHT_KEYS))} belong to "
                          f"the measures {' and '.join(LIGHT_MEASURES)}, not {measure!r}")
    levels = tuple(sorted(((str(k), float(v)) for k, v in table.get("levels", {}).items()),
                          key=lambda kv: kv[1]))
    if not light and "min_hours" not in table and not levels:
        raise ConfigError(f"{where}: a rule needs min_hours or levels")
    bbox = table.get("area_bbox")
    if bbox is not None and (len(bbox) != 4 or not bbox[0] < bbox[2] or not bbox[1] < bbox[3]):
        raise ConfigError(f"{where}: area_bbox must be [x0, y0, x1, y1] with x0 < x1, y0 < y1")
    poly = table.get("area_polygon")
    if poly is not None and (len(poly) < 3 or any(len(p) != 2 for p in poly)):
        raise ConfigError(f"{where}: area_polygon must be at least three [x, y] points")
    facing = table.get("facing_deg")
    if facing is not None and len(facing) != 2:
        raise ConfigError(f"{where}: facing_deg must be [from, to] in degrees")
    for key in ("share", "relative"):
        v = table.get(key)
        if v is not None and not 0.0 < float(v) <= 1.0:
            raise ConfigError(f"{where}: {key} must be in (0, 1], not {v}")
    return Rule(
        id=table["id"], name=table["name"], source=table["source"],
        receivers=table["receivers"], date=table.get("date", ""), measure=measure,
        min_hours=float(table.get("min_hours", levels[0][1] if levels else 0.0)),
        classes=tuple(table.get("classes", ())),
        area_bbox=tuple(float(v) for v in bbox) if bbox else None,
        area_polygon=tuple((float(x), float(y)) for x, y in poly) if poly else None,
        facing_deg=tuple(float(v) for v in facing) if facing else None,
        time_from=table.get("from", "00:00"), time_to=table.get("to", "24:00"),
        tz=table.get("tz"), every=table.get("every"), every_day=int(table.get("every_day", 1)),
        to_date=table.get("to_date"),
        min_elevation_deg=float(table.get("min_elevation_deg", 0.0)),
        min_stretch_min=float(table.get("min_stretch_min", 0.0)), levels=levels,
        share=float(table["share"]) if "share" in table else None,
        relative=float(table["relative"]) if "relative" in table else None,
        reference=table.get("reference", "mean"),
        not_assessed=tuple(str(v) for v in table.get("not_assessed", ())),
        notes=table.get("notes", ""),
        **{k: (float(table[k]) if k != "sky" else table[k]) for k in _LIGHT_KEYS if k in table})


def _check_light_rule(table: dict, measure: str, where: str) -> None:
    """A ``vsc``/``apsh`` rule: windows, a ``min_fraction``, only the keys its measure reads."""
    if table["receivers"] != "openings":
        raise ConfigError(f"{where}: measure {measure!r} is measured at openings "
                          f"(receivers = \"openings\")")
    if "min_fraction" not in table:
        raise ConfigError(f"{where}: a {measure!r} rule needs min_fraction")
    foreign = set(table) & (_HOUR_ONLY_KEYS | ({"min_winter_fraction", "max_loss_fraction"}
                                               if measure == "vsc" else {"sky"}))
    if foreign:
        raise ConfigError(f"{where}: measure {measure!r} does not read "
                          f"{', '.join(sorted(foreign))}")
    for key in ("min_fraction", "min_winter_fraction", "max_loss_fraction"):
        v = table.get(key)
        if v is not None and not 0.0 <= float(v) <= 1.0:
            raise ConfigError(f"{where}: {key} is a fraction in [0, 1], not {v}")
    if "sky" in table:
        from cityshade.light.sky import named_sky

        try:
            named_sky(table["sky"])
        except UsageError as exc:
            raise ConfigError(f"{where}: {exc}") from None


def load_rules(path) -> list[Rule]:
    """The ``[[rule]]`` tables of a TOML file; a bare name (``bre209``) is a shipped file.

    Raises
    ------
    ConfigError
        Unreadable or malformed file, an unknown key, a missing or bad value (the message
        names the file and the rule).
    """
    path = Path(path)
    if not path.suffix and not path.exists():
        shipped = RULES_DIR / f"{path.name}.toml"
        if not shipped.exists():
            names = ", ".join(sorted(p.stem for p in RULES_DIR.glob("*.toml")))
            raise ConfigError(f"no rule file {path} and no shipped rule set of that name "
                              f"(shipped: {names})")
        path = shipped
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise ConfigError(f"cannot read the rule file {path}: {exc.strerror}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise ConfigError(f"{path}: not valid TOML ({exc})") from None
    tables = data.get("rule")
    if not isinstance(tables, list) or not tables or set(data) - {"rule"}:
        raise ConfigError(f"{path}: a rule file holds [[rule]] tables and nothing else")
    rules = [_rule_from(t, f"{path} rule {i + 1} ({t.get('id', '?')})")
             for i, t in enumerate(tables)]
    ids = [r.id for r in rules]
    if len(set(ids)) != len(ids):
        raise ConfigError(f"{path}: rule ids must be unique")
    return rules


def rule_day(rule: Rule, year: int, text: str | None = None) -> date:
    """The day of ``rule.date`` (``MM-DD`` in ``year``, or a full ``YYYY-MM-DD``)."""
    text = (text or rule.date).strip()
    try:
        if len(text) == 5:
            return date(year, int(text[:2]), int(text[3:]))
        return date.fromisoformat(text)
    except ValueError:
        raise UsageError(f"rule {rule.id}: cannot read the date {text!r} (MM-DD or "
                         f"YYYY-MM-DD)") from None


# --- the engine ---------------------------------------------------------------------------------

@dataclass
class Measures:
    """What a rule looks at, per receiver (pixel, surface or opening), in one state.

    total_h, longest_h, stretches_h : (N,) float — hours, the longest continuous stretch, hours
    in stretches >= the rule's minimum stretch. weight : (N,) float — area (m²) each receiver
    stands for. labels : receiver names (openings' gml:ids) for the details.
    """

    total_h: np.ndarray
    longest_h: np.ndarray
    stretches_h: np.ndarray
    weight: np.ndarray
    labels: list[str] = field(default_factory=list)

    def value(self, measure: str) -> np.ndarray:
        return np.asarray({"total": self.total_h, "longest": self.longest_h,
                           "stretches": self.stretches_h}[measure], np.float64)


@dataclass
class WindowMeasures:
    """What a light rule (``vsc``/``apsh``) looks at, per window, in one state: fractions 0–1.

    value : (N,) float — the vertical sky component, or the annual probable sunlight hours as a
    share of the place's (APSH). winter : (N,) float, optional — the winter (21 September to
    21 March) probable sunlight hours as a share of the same ANNUAL total (BRE 209).
    labels : the windows' gml:ids.
    """

    value: np.ndarray
    labels: list[str] = field(default_factory=list)
    winter: np.ndarray | None = None


@dataclass
class Verdict:
    """A rule's answer. ``status``: ``pass``, ``fail`` or ``not assessed``; ``numbers``: the
    measured values the verdict rests on; ``details``: one line per receiver for point rules."""

    rule: Rule
    status: str
    summary: str
    numbers: dict[str, Any] = field(default_factory=dict)
    details: list[dict[str, Any]] = field(default_factory=list)
    not_assessed: tuple[str, ...] = ()


# Hours are compared with a tolerance of 1e-9 h (3.6 µs): sums of step weights (e.g. six 20-minute steps)
# are not exact in binary, and a receiver with exactly 2 h of sun must meet a 2 h threshold.
_EPS_H = 1e-9


def _meets(values: np.ndarray, hours: float) -> np.ndarray:
    return values >= hours - _EPS_H


def _grade(value: float, levels) -> str:
    grade = "below " + levels[0][0]
    for name, hours in levels:
        if value >= hours - _EPS_H:
            grade = name
    return grade


def evaluate(rule: Rule, after: Measures, before: Measures | None = None) -> Verdict:
    """The verdict of ``rule`` on the measures of the state after (and before) a change.

    Area rules (``share`` set): the share of the area whose value reaches ``min_hours`` must be
    at least ``share``, or, with ``relative`` and a before state, at least ``relative`` × its
    former share (BRE 209's garden test: it fails only when both fail). Point rules: every
    receiver's value must reach ``min_hours`` (``levels`` grade it), or, with ``relative``,
    at least ``relative`` × its former value.
    """
    if rule.is_light:
        return _evaluate_light(rule, after, before)
    needs = tuple(rule.not_assessed)
    value_a = after.value(rule.measure)
    value_b = before.value(rule.measure) if before is not None else None
    what = {"total": "hours of sun", "longest": "longest continuous stretch",
            "stretches": f"hours in stretches of at least {rule.min_stretch_min:g} min"}[
        rule.measure]
    if value_a.size == 0:
        return Verdict(rule, "not assessed", "no receiver of this rule in the model",
                       not_assessed=needs)
    if rule.share is not None:
        w = np.asarray(after.weight, np.float64)
        share_a = float(w[_meets(value_a, rule.min_hours)].sum() / w.sum())
        numbers = {"area_m2": float(w.sum()), "share_after": share_a,
                   "min_hours": rule.min_hours, "share_required": rule.share}
        ok = share_a >= rule.share - 1e-12
        text = (f"{100 * share_a:.1f} % of {w.sum():.0f} m² has ≥ {rule.min_hours:g} h "
                f"({what}) after; {100 * rule.share:g} % required")
        if value_b is not None:
            wb = np.asarray(before.weight, np.float64)
            share_b = float(wb[_meets(value_b, rule.min_hours)].sum() / wb.sum())
            numbers["share_before"] = share_b
            text += f"; before {100 * share_b:.1f} %"
            if rule.relative is not None and not ok:
                ratio = share_a / share_b if share_b > 0 else math.inf
                numbers["ratio"] = ratio
                ok = share_a >= rule.relative * share_b - 1e-12
                text += (f"; after/before = {ratio:.3f} "
                         f"({'≥' if ok else '<'} {rule.relative:g})")
        return Verdict(rule, "pass" if ok else "fail", text, numbers, not_assessed=needs)
    # Point rules: every receiver on its own.
    details = []
    n_ok = 0
    relative_only = rule.min_hours <= 0.0 and rule.relative is not None
    for i in range(value_a.size):
        va = float(value_a[i])
        row: dict[str, Any] = {"receiver": after.labels[i] if i < len(after.labels) else str(i),
                               "after_h": va}
        # Without an absolute threshold (min_hours 0, e.g. BRE's APSH test whose absolute part
        # needs data we lack) only the relative test decides.
        ok = not relative_only and bool(_meets(np.array([va]), rule.min_hours)[0])
        if rule.levels:
            row["grade"] = _grade(va, rule.levels)
        if value_b is not None:
            vb = float(value_b[i])
            row["before_h"] = vb
            if rule.relative is not None:
                row["ratio"] = va / vb if vb > 0 else math.inf
                if not ok:
                    ok = va >= rule.relative * vb - _EPS_H
        elif relative_only:
            ok = True  # nothing to compare with
        row["status"] = "pass" if ok else "fail"
        n_ok += ok
        details.append(row)
    n = value_a.size
    status = "pass" if n_ok == n else "fail"
    if relative_only:
        text = (f"{n_ok} of {n} receivers keep ≥ {rule.relative:g} × their former {what}")
        if needs:
            status = "not assessed"
            text += " (an indication only: the rule's own test is not assessed, see below)"
    else:
        text = f"{n_ok} of {n} receivers reach ≥ {rule.min_hours:g} h ({what})"
        if rule.relative is not None and value_b is not None:
            text += f" or keep ≥ {rule.relative:g} × their former value"
    return Verdict(rule, status, text, {"receivers": n, "passing": n_ok,
                                        "min_hours": rule.min_hours}, details, needs)


# Fractions are compared with a tolerance of 1e-12: an APSH of 683 of 2732 hours is 0.25 exactly in
# the decimal sense but may round below it in binary.
_EPS_FRACTION = 1e-12


def _pct1(v: float) -> str:
    return f"{100.0 * v:.1f} %"


def _light_row(rule: Rule, i: int, after: WindowMeasures, before: WindowMeasures | None):
    """One window of a light rule: its numbers and whether it passes (BRE 209's tests)."""
    eps, k = _EPS_FRACTION, rule.relative
    va = float(after.value[i])
    row: dict[str, Any] = {"receiver": after.labels[i] if i < len(after.labels) else str(i),
                           f"{rule.measure}_after": va}
    low = va < rule.min_fraction - eps
    wa = None
    if after.winter is not None:
        wa = float(after.winter[i])
        row["winter_after"] = wa
        low |= rule.min_winter_fraction is not None and wa < rule.min_winter_fraction - eps
    if before is None:
        row["status"] = "fail" if low else "pass"
        return row
    vb = float(before.value[i])
    row[f"{rule.measure}_before"] = vb
    row["ratio"] = va / vb if vb > 0 else math.inf
    kept = k is None or va >= k * vb - eps
    if before.winter is not None and wa is not None:
        wb = float(before.winter[i])
        row["winter_before"] = wb
        row["winter_ratio"] = wa / wb if wb > 0 else math.inf
        # BRE 209: less than 0.8 times its former sunlight hours during EITHER period.
        kept &= k is None or wa >= k * wb - eps
    fails = low and not kept
    if rule.max_loss_fraction is not None:
        row["loss"] = vb - va
        fails &= vb - va > rule.max_loss_fraction + eps
    row["status"] = "fail" if fails else "pass"
    return row


def _evaluate_light(rule: Rule, after: WindowMeasures, before: WindowMeasures | None) -> Verdict:
    """Per window: fails when below the absolute thresholds (``min_fraction``, and
    ``min_winter_fraction`` for APSH) AND below ``relative`` × its former value (in either
    period) AND, with ``max_loss_fraction``, losing more than that share over the year."""
    n = int(np.asarray(after.value).size)
    if n == 0:
        return Verdict(rule, "not assessed", "no window of this rule in the model",
                       not_assessed=rule.not_assessed)
    details = [_light_row(rule, i, after, before) for i in range(n)]
    n_ok = sum(d["status"] == "pass" for d in details)
    what = {"vsc": f"VSC ≥ {_pct1(rule.min_fraction)}",
            "apsh": f"APSH ≥ {_pct1(rule.min_fraction)}"
            + (f" and winter APSH ≥ {_pct1(rule.min_winter_fraction)}"
               if rule.min_winter_fraction is not None else "")}[rule.measure]
    text = f"{n_ok} of {n} windows keep {what}"
    if rule.relative is not None and before is not None:
        text += f", or ≥ {rule.relative:g} × their former value"
        if rule.max_loss_fraction is not None:
            text += f", or lose at most {_pct1(rule.max_loss_fraction)} of APSH over the year"
    key = f"{rule.measure}_after"
    worst = min(details, key=lambda d: d[key])
    text += f" (lowest after: {_pct1(worst[key])} at {worst['receiver']})"
    numbers = {"receivers": n, "passing": n_ok, "min_fraction": rule.min_fraction}
    for name in ("min_winter_fraction", "max_loss_fraction", "relative"):
        if getattr(rule, name) is not None:
            numbers[name] = getattr(rule, name)
    return Verdict(rule, "pass" if n_ok == n else "fail", text, numbers, details,
                   rule.not_assessed)


# --- receivers of a rule in a comparison --------------------------------------------------------

def _in_area(rule: Rule, xy: np.ndarray) -> np.ndarray:
    inside = np.ones(len(xy), bool)
    if rule.area_bbox is not None:
        x0, y0, x1, y1 = rule.area_bbox
        inside &= (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)
    if rule.area_polygon is not None:
        inside &= points_in_polygon(xy, np.asarray(rule.area_polygon, np.float64))
    return inside


def points_in_polygon(xy: np.ndarray, ring: np.ndarray) -> np.ndarray:
    """(N,) bool: points inside a polygon ring (even-odd rule; a point exactly on an edge may
    fall either way)."""
    x, y = xy[:, 0], xy[:, 1]
    inside = np.zeros(len(xy), bool)
    x1, y1 = ring[-1]
    for x2, y2 in ring:
        crosses = (y1 > y) != (y2 > y)
        with np.errstate(divide="ignore", invalid="ignore"):
            x_at = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
        inside ^= crosses & (x < x_at)
        x1, y1 = x2, y2
    return inside


def area_bbox(rule: Rule) -> tuple[float, float, float, float] | None:
    """Model-CRS box of the rule's area (bbox, or the polygon's box)."""
    if rule.area_bbox is not None:
        return rule.area_bbox
    if rule.area_polygon is not None:
        p = np.asarray(rule.area_polygon)
        return (float(p[:, 0].min()), float(p[:, 1].min()), float(p[:, 0].max()),
                float(p[:, 1].max()))
    return None


def receiver_polygons(rule: Rule, scene) -> np.ndarray | None:
    """(P,) bool: the polygons a surface/opening rule samples (None for area rules)."""
    from cityshade.citygml.namespaces import SURFACE_CODE

    if rule.receivers == "area":
        return None
    classes = rule.classes or (("window", "door") if rule.receivers == "openings" else ())
    codes = [SURFACE_CODE[c] for c in classes if c in SURFACE_CODE]
    unknown = [c for c in classes if c not in SURFACE_CODE]
    if unknown:
        raise UsageError(f"rule {rule.id}: unknown surface class {unknown[0]!r}")
    poly = np.isin(np.asarray(scene.poly_class), codes) if codes else \
        np.ones(len(scene.poly_ids), bool)
    return poly


def _facing_ok(rule: Rule, facing: np.ndarray) -> np.ndarray:
    if rule.facing_deg is None:
        return np.ones(len(facing), bool)
    a, b = rule.facing_deg
    f = np.mod(facing - a, 360.0)
    return f <= np.mod(b - a, 360.0)


def measures_from(rule: Rule, comp) -> tuple[Measures, Measures]:
    """(before, after) :class:`Measures` of the rule's receivers in a comparison (computed for
    this rule's day, window and minimum stretch)."""
    if rule.receivers == "area":
        if comp.camera is None or comp.camera.kind != "map":
            raise UsageError(f"rule {rule.id}: an area rule needs the map view")
        xy = comp.camera.pixel_centres_world(comp.scene_before.origin_m).reshape(-1, 2)
        keep = _in_area(rule, xy) & ~comp.changed.reshape(-1) & \
            comp.before.valid.reshape(-1) & comp.after.valid.reshape(-1)
        px_area = comp.camera.pixel_size_m ** 2
        out = []
        for res in (comp.before, comp.after):
            st = res.stretches
            total = res.hours.reshape(-1)[keep].astype(np.float64)
            out.append(Measures(total, st.pixels.longest_h[keep],
                                st.pixels.qualified_h[keep] if rule.min_stretch_h > 0 else total,
                                np.full(int(keep.sum()), px_area)))
        return out[0], out[1]
    if rule.receivers == "openings":
        o = comp.opening
        keep = _facing_ok(rule, o["facing_deg"]) & (o["ref_sample"] >= 0) & \
            np.isfinite(o["ref_after_h"])
        labels = [op.opening_id for op, k in zip(comp.openings, keep) if k]
        use_ref = rule.reference == "point"
        out = []
        for tag in ("before", "after"):
            total = o[f"ref_{tag}_h"] if use_ref else o[f"{tag}_h"]
            stretches = o[f"ref_qualified_{tag}_h"] if rule.min_stretch_h > 0 else \
                o[f"ref_{tag}_h"]
            out.append(Measures(total[keep], o[f"ref_longest_{tag}_h"][keep], stretches[keep],
                                o["area_m2"][keep], labels))
        return out[0], out[1]
    # Surfaces: per polygon, area-weighted means; longest = the longest of its samples.
    from cityshade.planning.compare import polygon_longest
    from cityshade.sunhours.surfaces import polygon_means

    wanted = receiver_polygons(rule, comp.scene_before)
    keep = comp.samples.sampled & wanted & comp.polygon_standing_after
    labels = [comp.scene_before.poly_ids[p] or str(p) for p in np.flatnonzero(keep)]
    area = np.asarray(comp.scene_before.poly_area_m2)[keep]
    out = []
    for tag, res in (("before", comp.before), ("after", comp.after)):
        q = polygon_means(comp.samples, res.stretches.samples.qualified_h) \
            if rule.min_stretch_h > 0 else res.polygon_hours
        out.append(Measures(res.polygon_hours[keep], polygon_longest(comp, tag)[keep],
                            q[keep], area, labels))
    return out[0], out[1]


def window_measures_from(rule: Rule, comp) -> tuple[WindowMeasures, WindowMeasures]:
    """(before, after) :class:`WindowMeasures` of a light rule's openings in a comparison whose
    ``opening`` holds the light columns (:func:`cityshade.planning.light.add_opening_light`):
    the openings of the rule's classes (default windows and doors) facing its sector, standing
    in both states.

    Raises
    ------
    UsageError
        The comparison has no values of the rule's measure (``apsh`` without a weather file).
    """
    o = comp.opening
    key = rule.measure
    if f"{key}_before" not in o:
        raise UsageError(f"rule {rule.id}: the comparison has no {key} of its openings")
    classes = rule.classes or ("window", "door")
    keep = (np.isin([op.surface_class for op in comp.openings], classes)
            & _facing_ok(rule, o["facing_deg"]) & np.isfinite(o[f"{key}_before"])
            & np.isfinite(o[f"{key}_after"]))
    labels = [op.opening_id for op, k in zip(comp.openings, keep) if k]
    out = []
    for tag in ("before", "after"):
        winter = o[f"winter_{key}_{tag}"][keep] if f"winter_{key}_{tag}" in o else None
        out.append(WindowMeasures(o[f"{key}_{tag}"][keep], labels, winter))
    return out[0], out[1]
