"""The answers of ``cityshade compare`` as GIS layers and as places on the map.

:func:`compare_layers`: the layers of ``results.gpkg`` (:mod:`cityshade.present.gis`) —
``surfaces`` (the rows of ``surfaces.csv``), ``openings`` (the rows of ``openings.csv`` and the
reference point), ``buildings`` (footprints with area-weighted means and the largest loss) and
``rules`` (one feature per verdict; an area rule's area as its geometry) — with, on surfaces
and openings, a ``rule_<id>`` column per point rule that judged them — and, when the state
after adds a proposal, ``proposal_surfaces`` (its own surfaces: the rows ``surfaces.csv``
gives them, outlines from the scene after; no value before).
:func:`rule_places`: where a verdict's receivers and area lie, for the report's maps.
"""
from __future__ import annotations

from typing import Sequence

import numpy as np

__all__ = ["compare_layers", "rule_places", "receiver_points"]


def _statuses(verdicts: Sequence, receivers: str) -> dict[str, dict[str, str]]:
    """``rule_<id>`` → {receiver label → pass/fail} of the point rules on ``receivers``."""
    out: dict[str, dict[str, str]] = {}
    for v in verdicts:
        if v.rule.receivers == receivers and v.details:
            out[f"rule_{v.rule.id}"] = {str(d["receiver"]): d["status"] for d in v.details}
    return out


def receiver_points(comp) -> dict[str, np.ndarray]:
    """Receiver label (opening id, polygon id) → (3,) model-CRS point: an opening's reference
    point, a surface's sample centroid."""
    samples = comp.samples
    if samples is None:
        return {}
    origin = np.asarray(comp.scene_before.origin_m, np.float64)
    scene = comp.scene_before
    out: dict[str, np.ndarray] = {}
    sums = np.zeros((len(scene.poly_ids), 3))
    np.add.at(sums, samples.polygon, np.asarray(samples.points_m, np.float64))
    counts = np.bincount(samples.polygon, minlength=len(scene.poly_ids))
    for p in np.flatnonzero(counts):
        out[scene.poly_ids[p] or str(p)] = sums[p] / counts[p] + origin
    for k, op in enumerate(comp.openings):
        ref = int(comp.opening["ref_sample"][k])
        if ref >= 0:
            out[op.opening_id] = np.asarray(samples.points_m[ref], np.float64) + origin
    return out


def rule_places(comp, verdict, points: dict[str, np.ndarray] | None = None):
    """(failing points (N, 3), passing points (M, 3), area outline (K, 2) or None) of a
    verdict, in model CRS metres; receivers whose place is unknown are left out."""
    from cityshade.planning.rules import area_bbox

    points = receiver_points(comp) if points is None else points
    fail, ok = [], []
    for d in verdict.details:
        p = points.get(str(d["receiver"]))
        if p is not None:
            (fail if d["status"] == "fail" else ok).append(p)
    area = None
    rule = verdict.rule
    if rule.area_polygon is not None:
        area = np.asarray(rule.area_polygon, np.float64)
    elif rule.receivers == "area" and area_bbox(rule) is not None:
        x0, y0, x1, y1 = area_bbox(rule)
        area = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], np.float64)
    return (np.asarray(fail, np.float64).reshape(-1, 3), np.asarray(ok, np.float64).reshape(-1, 3),
            area)


def _surface_columns(rows) -> dict[str, list]:
    from cityshade.planning.compare import SURFACE_COLUMNS
    from cityshade.present.gis import finite_or_none

    columns = {name: [r[i] for r in rows] for i, name in enumerate(SURFACE_COLUMNS)}
    for name in SURFACE_COLUMNS[6:]:
        columns[name] = finite_or_none(columns[name])
    return columns


def _proposal_layer(comp):
    """The proposal's own surfaces (receivers of the state after only): the rows
    ``surfaces.csv`` gives them, their outlines from the scene after."""
    from cityshade.planning.compare import proposal_rows
    from cityshade.present.gis import surface_layer

    rows = list(proposal_rows(comp))
    return surface_layer(comp.scene_after, [r[2] for r in rows], _surface_columns(rows),
                         name="proposal_surfaces")


def _surface_layer(comp, verdicts):
    from cityshade.planning.compare import surface_rows
    from cityshade.present.gis import surface_layer

    scene = comp.scene_before
    rows = list(surface_rows(comp))
    columns = _surface_columns(rows)
    labels = [scene.poly_ids[r[2]] or str(r[2]) for r in rows]
    for col, status in _statuses(verdicts, "surfaces").items():
        columns[col] = [status.get(label, "") for label in labels]
    return surface_layer(scene, [r[2] for r in rows], columns), rows


def _opening_layer(comp, verdicts):
    from cityshade.planning.compare import (
        LIGHT_COLUMNS,
        OPENING_COLUMNS,
        light_percent,
        loss_percent,
    )
    from cityshade.present.gis import Layer, finite_or_none, polygon_outlines

    scene, o = comp.scene_before, comp.opening
    b, a = o["before_h"], o["after_h"]
    pct = loss_percent(b, a)
    values = {
        "opening_id": [op.opening_id for op in comp.openings],
        "object_id": [scene.obj_ids[op.object_index] for op in comp.openings],
        "surface_class": [op.surface_class for op in comp.openings],
        "polygon_ids": [" ".join(scene.poly_ids[p] or str(p) for p in op.polygons)
                        for op in comp.openings],
        "area_m2": o["area_m2"], "samples": [int(s) for s in o["samples"]],
        "facing_deg": o["facing_deg"], "hours_before": b, "hours_after": a, "loss_h": b - a,
        "loss_pct": pct, "ref_hours_before": o["ref_before_h"], "ref_hours_after": o["ref_after_h"],
        "ref_longest_before_h": o["ref_longest_before_h"],
        "ref_longest_after_h": o["ref_longest_after_h"],
        **{c: light_percent(comp, c) for c in LIGHT_COLUMNS}}
    columns = {name: values[name] for name in OPENING_COLUMNS}
    for name in OPENING_COLUMNS[4:]:
        if name != "samples":
            columns[name] = finite_or_none(columns[name])
    points = receiver_points(comp)
    ref = np.array([points.get(op.opening_id, np.full(3, np.nan)) for op in comp.openings],
                   np.float64).reshape(-1, 3)
    for k, axis in enumerate(("ref_x", "ref_y", "ref_z")):
        columns[axis] = finite_or_none(ref[:, k])
    for col, status in _statuses(verdicts, "openings").items():
        columns[col] = [status.get(op.opening_id, "") for op in comp.openings]
    return Layer("openings", polygon_outlines(scene, [op.polygons for op in comp.openings]),
                 columns)


def _rule_layer(comp, verdicts):
    import shapely

    from cityshade.present.gis import Layer

    geoms, columns = [], {k: [] for k in ("rule", "name", "source", "receivers", "status",
                                          "summary", "receivers_failing")}
    for v in verdicts:
        area = rule_places(comp, v, {})[2]
        geoms.append(None if area is None else shapely.MultiPolygon([shapely.Polygon(area)]))
        for key, value in (("rule", v.rule.id), ("name", v.rule.name),
                           ("source", v.rule.source), ("receivers", v.rule.receivers),
                           ("status", v.status), ("summary", v.summary),
                           ("receivers_failing",
                            sum(d.get("status") == "fail" for d in v.details))):
            columns[key].append(value)
    return Layer("rules", geoms, columns, geometry_type="MultiPolygon")


def compare_layers(comp, verdicts: Sequence = ()) -> list:
    """The layers of a comparison (see the module docstring); none without surface
    receivers."""
    from cityshade.present.gis import building_layer

    if comp.samples is None:
        return []
    layers = []
    surfaces, rows = _surface_layer(comp, verdicts)
    layers.append(surfaces)
    if comp.openings:
        layers.append(_opening_layer(comp, verdicts))
    if rows:
        col = {name: np.array([np.nan if r[i] is None else float(r[i]) for r in rows])
               for name, i in (("hours_before", 6), ("hours_after", 7), ("loss_h", 8))}
        layers.append(building_layer(comp.scene_before, [r[2] for r in rows], col,
                                     {"max_loss_h": col["loss_h"]}))
    if comp.proposal is not None:
        layers.append(_proposal_layer(comp))
    if verdicts:
        layers.append(_rule_layer(comp, verdicts))
    return layers
