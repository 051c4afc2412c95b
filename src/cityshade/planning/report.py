"""``report.md`` of ``cityshade compare``: what was compared, the maps, the worst-hit surfaces
and openings, and every rule's verdict with its source and numbers — a page a planner can
attach to a file. Also ``rules.json`` (the verdicts as data) and ``worst.png`` (the loss map
with the worst-hit surfaces numbered, map view, needs matplotlib)."""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Sequence

import numpy as np

__all__ = ["write_report", "worst_surfaces", "window_lines", "proposal_md"]

#: Surfaces smaller than this are left out of the worst-hit list (slivers say little).
MIN_LISTED_AREA_M2 = 1.0
#: Classes in the worst-hit list: the surfaces of buildings. Terrain and other ground surfaces
#: under a new building's footprint lose all their sun without anyone losing it (the maps show
#: the ground, with such pixels grey), so they are left out of the list, not of surfaces.csv.
LISTED_CLASSES = frozenset(("roof", "wall", "window", "door", "outer_ceiling", "outer_floor",
                            "closure", "installation", "unclassified", "generic"))


def _h(v) -> str:
    return "–" if v is None or not np.isfinite(v) else f"{float(v):.2f}"


def _pct(v) -> str:
    return "–" if v is None or not np.isfinite(v) else f"{float(v):.0f} %"


def worst_surfaces(comp, n: int = 10) -> list[tuple]:
    """The ``n`` surface rows (see :data:`cityshade.planning.compare.SURFACE_COLUMNS`) with the largest
    loss in hours, of polygons of at least :data:`MIN_LISTED_AREA_M2`."""
    from cityshade.planning.compare import surface_rows

    if comp.samples is None:
        return []
    rows = [r for r in surface_rows(comp) if r[4] >= MIN_LISTED_AREA_M2 and np.isfinite(r[8])
            and r[8] > 0.0 and r[3] in LISTED_CLASSES]
    rows.sort(key=lambda r: (-r[8], r[2]))
    return rows[:n]


def _worst_picture(outdir: Path, comp, rows, decorate: bool = True) -> Path | None:
    """loss.png with the worst-hit surfaces' centres numbered (map view only); ``decorate``:
    with scale bar, north, CRS and colour bar."""
    from cityshade.plotting import have_matplotlib

    cam = comp.camera
    if cam is None or cam.kind != "map" or not rows or not have_matplotlib():
        return None
    from cityshade import imageio
    from cityshade.planning.compare import loss_map, loss_picture
    from cityshade.present.maps import Mark, annotate_map
    from cityshade.sunhours.outputs import map_picture

    samples = comp.samples
    origin = np.asarray(comp.scene_before.origin_m)
    marks = []
    for k, row in enumerate(rows, 1):
        pts = samples.points_m[samples.polygon == row[2]]
        c = pts.mean(axis=0) + origin
        col, r = cam.pixel_of_world(c[None, :2], origin)[0]
        marks.append(Mark(float(col), float(r), str(k)))
    picture = None
    if decorate:
        rgb, vmax_h = loss_map(comp)
        picture = map_picture(annotate_map(rgb, marks), vmax_h, cam, comp.scene_before,
                              label="loss of sun-hours (h)",
                              title="The worst-hit surfaces (numbers as in the table)")
    if picture is None:
        picture = annotate_map(loss_picture(comp), marks)
    path = outdir / "worst.png"
    imageio.write_png_rgb(path, picture)
    return path


def _rule_figures(comp, verdicts: Sequence) -> dict[str, str]:
    """Rule name → an HTML figure of the loss map with the rule's failing receivers ringed in
    red (passing ones in green) and its area outlined (map view, matplotlib)."""
    from cityshade.plotting import have_matplotlib

    cam = comp.camera
    if cam is None or cam.kind != "map" or not verdicts or not have_matplotlib():
        return {}
    from cityshade.planning.compare import loss_map
    from cityshade.planning.gis import receiver_points, rule_places
    from cityshade.present.html import figure_html
    from cityshade.present.maps import Mark, annotate_map
    from cityshade.sunhours.outputs import map_picture

    origin = np.asarray(comp.scene_before.origin_m)
    points = receiver_points(comp)
    rgb, vmax_h = loss_map(comp)
    out: dict[str, str] = {}
    for v in verdicts:
        fail, ok, area = rule_places(comp, v, points)
        if not len(fail) and not len(ok) and area is None:
            continue
        marks = [Mark(float(c), float(r), str(k), "red") for k, (c, r) in
                 enumerate(cam.pixel_of_world(fail[:, :2], origin), 1)] if len(fail) else []
        marks += [Mark(float(c), float(r), "", "limegreen")
                  for c, r in cam.pixel_of_world(ok[:, :2], origin)] if len(ok) else []
        outlines = []
        if area is not None:
            corners = (area - origin[:2]) - [cam.x_left_m, cam.y_top_m]
            px = np.column_stack([corners[:, 0], -corners[:, 1]]) / cam.pixel_size_m
            outlines.append((px, "red" if v.status == "fail" else "limegreen"))
        title = f"{v.rule.name}: {v.status.upper()}"
        picture = map_picture(annotate_map(rgb, marks, outlines), vmax_h, cam,
                              comp.scene_before, label="loss of sun-hours (h)", title=title)
        if picture is None:
            continue
        what = (f"{len(fail)} failing receivers ringed in red and numbered in the order of "
                f"the table" if len(fail) else "no failing receiver")
        out[v.rule.name] = figure_html(picture, f"{title} — {what}"
                                       + (f"; {len(ok)} passing in green" if len(ok) else "")
                                       + ("; the area outlined" if area is not None else "")
                                       + ", on the loss map.")
    return out


def _p(v) -> str:
    """A fraction as a percentage with one decimal ('–' when unknown)."""
    return "–" if v is None or not np.isfinite(v) else f"{100.0 * float(v):.1f} %"


def _x(v) -> str:
    return "–" if v is None or not math.isfinite(v) else f"{float(v):.2f} ×"


def _light_cells(v, d) -> list[str]:
    """The numbers of one window of a light rule: value before, after, ratio (and for APSH the
    winter share before, after, ratio and the annual loss)."""
    m = v.rule.measure
    cells = [_p(d.get(f"{m}_before")), _p(d[f"{m}_after"]), _x(d.get("ratio"))]
    if m == "apsh":
        cells += [_p(d.get("winter_before")), _p(d.get("winter_after")),
                  _x(d.get("winter_ratio")), _p(d.get("loss"))]
    return cells


def window_lines(v) -> list[str]:
    """One line per window of a ``vsc``/``apsh`` verdict with the numbers it rests on (the
    CLI prints them under the verdict); no lines for other rules."""
    if not v.rule.is_light:
        return []
    out = []
    for d in v.details:
        c = _light_cells(v, d)
        text = f"{d['receiver']}: {v.rule.measure.upper()} {c[0]} → {c[1]} ({c[2]})"
        if v.rule.measure == "apsh":
            text += f", winter {c[3]} → {c[4]} ({c[5]}), loss {c[6]}"
        out.append(f"{text}: {d['status'].upper()}")
    return out


def _light_md(v) -> list[str]:
    m = v.rule.measure.upper()
    nums = v.numbers
    if v.rule.measure == "vsc":
        where = (f"- Measured at each window's centre on its outer face, sky "
                 f"`{nums.get('sky')}`, engine `{nums.get('engine')}`.")
        out = [where, "",
               f"| window | {m} before | {m} after | after/before | result |",
               "|---|---:|---:|---:|---|"]
    else:
        weather = (f"- Weather `{nums.get('weather')}`: {nums.get('sunny_h', 0):.0f} probable "
                   f"sunny hours in the year, {nums.get('winter_sunny_h', 0):.0f} of them from "
                   f"21 September to 21 March; engine `{nums.get('engine')}`. Shares of the "
                   "annual total; loss: APSH before − after.")
        header = ("| window | APSH before | APSH after | after/before | winter before | "
                  "winter after | after/before | loss | result |")
        out = [weather, "", header, "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for d in v.details[:25]:
        out.append(f"| `{d['receiver']}` | " + " | ".join(_light_cells(v, d))
                   + f" | {d['status']} |")
    if len(v.details) > 25:
        out.append(f"| … {len(v.details) - 25} more in rules.json |")
    return out


def _verdict_md(v) -> list[str]:
    r = v.rule
    out = [f"### {r.name}", "", f"- **Verdict: {v.status.upper()}** — {v.summary}",
           f"- Rule `{r.id}`; source: {r.source}"]
    nums = v.numbers
    if "period" in nums:
        out.append(f"- Measured on {nums['period']}, {r.time_from}–{r.time_to}"
                   f"{' (' + r.tz + ')' if r.tz else ''}, {nums['steps']} steps of "
                   f"{nums['step_min']:g} min (a stretch is exact to one step); measure: "
                   f"{r.measure}" + (f", stretches of at least {r.min_stretch_min:g} min"
                                     if r.measure == "stretches" else "")
                   + (f", sun above {r.min_elevation_deg:g}°" if r.min_elevation_deg else ""))
    if r.notes:
        out.append(f"- {r.notes}")
    for need in v.not_assessed:
        out.append(f"- *Not assessed:* {need}")
    if v.details and r.is_light:
        out += _light_md(v)
    elif v.details:
        out += ["", "| receiver | before h | after h | after/before | grade | result |",
                "|---|---:|---:|---:|---|---|"]
        for d in v.details[:25]:
            ratio = d.get("ratio")
            out.append(f"| `{d['receiver']}` | {_h(d.get('before_h'))} | {_h(d['after_h'])} | "
                       f"{'–' if ratio is None or not math.isfinite(ratio) else f'{ratio:.2f}'}"
                       f" | {d.get('grade', '')} | {d['status']} |")
        if len(v.details) > 25:
            out.append(f"| … {len(v.details) - 25} more in rules.json | | | | | |")
    out.append("")
    return out


def proposal_md(comp) -> list[str]:
    """The report's section on the proposal's own surfaces (none without a proposal): per
    surface class their area, the area-weighted mean sun-hours and the longest stretch."""
    from cityshade.planning.compare import proposal_rows

    rows = list(proposal_rows(comp))
    if not rows:
        return []
    out = ["## The proposal's own surfaces", "",
           f"The proposal's {len(rows)} surfaces are receivers too (after only: no loss). Per "
           "class, the area-weighted mean of their sun-hours and the longest continuous "
           "stretch of any of their samples:", "",
           "| class | surfaces | area m² | mean h | longest h |", "|---|---:|---:|---:|---:|"]
    for cls in sorted({r[3] for r in rows}):
        of_class = [r for r in rows if r[3] == cls]
        mine = [r for r in of_class if r[5] > 0]  # a surface too small for a sample has none
        area = np.array([r[4] for r in mine], np.float64)
        hours = np.array([r[7] for r in mine], np.float64)
        mean = float((area * hours).sum() / area.sum()) if area.sum() > 0 else float("nan")
        longest = max((r[11] for r in mine), default=float("nan"))
        out.append(f"| {cls} | {len(of_class)} | {area.sum():.1f} | {_h(mean)} | {_h(longest)} |")
    return out + ["", "Each surface: the rows of `surfaces.csv` with no hours before; GIS "
                      "layer `proposal_surfaces`.", ""]


def write_report(outdir, comp, verdicts: Sequence, request: dict[str, Any],
                 steps: Sequence, decorate: bool = True) -> list[Path]:
    """Write ``report.md``, ``report.html`` (the same, self-contained, with each rule's map),
    ``rules.json`` and (map view) ``worst.png``; returns the paths."""
    from cityshade.geo.temporal import days_to_iso
    from cityshade.util import write_text_atomic

    outdir = Path(outdir)
    written: list[Path] = []
    step_min = comp.step_h * 60.0
    sun_up = comp.before.hours_sun_up
    lines = ["# Sunlight before and after", "",
             f"Model `{Path(request['file']).name}`; before: the city on "
             f"{days_to_iso(comp.t_before_days)}; after: "
             + (f"with the proposal `{Path(request['with']).name}` added"
                if request.get("with") else f"the city on {days_to_iso(comp.t_after_days)}")
             + ".", "",
             f"Period: {request['date']}" + (f" to {request['to_date']}" if request.get("to_date")
                                             else "")
             + f", {request['from']}–{request['to']} ({request['tz']}), {len(steps)} steps of "
             f"{step_min:g} min, {sun_up:.2f} h with the sun up. Shadows: `{request['technique']}` "
             f"(exact). Each step counts whole when the sun reaches the receiver at its middle, "
             f"so sun-hours are exact to the midpoint rule and a continuous stretch is exact to "
             f"one step ({step_min:g} min).", ""]
    worst = worst_surfaces(comp)
    if comp.camera is not None:
        loss = comp.loss_h[np.isfinite(comp.loss_h)]
        changed = int(comp.changed.sum())
        px_m2 = (comp.camera.pixel_size_m ** 2) if comp.camera.kind == "map" else None
        lines += ["## Maps", "",
                  "| before | after | loss |", "|---|---|---|",
                  "| ![before](before.png) | ![after](after.png) | ![loss](loss.png) |", "",
                  f"Sun-hours per pixel on one colour scale (before, after) and the loss "
                  f"(before − after; grey: {changed} pixels whose surface changed — built over "
                  f"or demolished — and have no loss). Rasters: `compare.exr`"
                  + (", `before_h.tif`, `after_h.tif`, `loss_h.tif`, `loss_pct.tif` "
                     "(georeferenced)" if comp.camera.kind == "map" else "") + ".", ""]
        if loss.size:
            hit = loss > 0.5 * step_min / 60.0
            lines += [f"- Pixels compared: {loss.size}"
                      + (f" ({loss.size * px_m2:.0f} m²)" if px_m2 else "")
                      + f"; losing sun: {int(hit.sum())} ({100 * hit.mean():.1f} %); "
                      f"gaining: {int((loss < -0.5 * step_min / 60.0).sum())}.",
                      f"- Loss: mean {loss.mean():.2f} h, largest {loss.max():.2f} h.", ""]
        pic = _worst_picture(outdir, comp, worst, decorate)
        if pic is not None:
            written.append(pic)
            lines += ["The worst-hit surfaces (numbers as in the table below):", "",
                      "![worst-hit surfaces](worst.png)", ""]
    if worst:
        lines += ["## Worst-hit surfaces", "", "Roofs, walls, windows and doors of at least "
                  f"{MIN_LISTED_AREA_M2:g} m² with the largest loss:", "",
                  "| # | object | polygon | class | area m² | before h | after h | loss h | loss |",
                  "|---:|---|---|---|---:|---:|---:|---:|---:|"]
        for k, r in enumerate(worst, 1):
            lines.append(f"| {k} | `{r[0]}` | `{r[1] or r[2]}` | {r[3]} | {r[4]:.1f} | "
                         f"{_h(r[6])} | {_h(r[7])} | {_h(r[8])} | {_pct(r[9])} |")
        lines += ["", "All surfaces: `surfaces.csv` (area-weighted means of sample points; "
                  "longest continuous stretch of any sample).", ""]
    elif comp.samples is not None:
        lines += ["## Surfaces", "", "No surface of at least 1 m² loses sun.", ""]
    if comp.openings:
        o = comp.opening
        order = sorted(range(len(comp.openings)),
                       key=lambda k: -np.nan_to_num(o["before_h"][k] - o["after_h"][k], nan=-1))
        lines += ["## Windows and doors", "",
                  f"{len(comp.openings)} openings, each with its own sample points; at the "
                  "reference point (the sample nearest its centre): hours and the longest "
                  "continuous sunlit stretch.", "",
                  "| opening | class | facing | before h | after h | loss h | longest before h "
                  "| longest after h |", "|---|---|---:|---:|---:|---:|---:|---:|"]
        for k in order[:20]:
            op = comp.openings[k]
            lines.append(f"| `{op.opening_id}` | {op.surface_class} | {o['facing_deg'][k]:.0f}° | "
                         f"{_h(o['before_h'][k])} | {_h(o['after_h'][k])} | "
                         f"{_h(o['before_h'][k] - o['after_h'][k])} | "
                         f"{_h(o['ref_longest_before_h'][k])} | {_h(o['ref_longest_after_h'][k])} |")
        if len(order) > 20:
            lines.append(f"| … {len(order) - 20} more in openings.csv | | | | | | | |")
        lines += ["", "Facing: azimuth of the outward normal, clockwise from grid north.", ""]
    lines += proposal_md(comp)
    if verdicts:
        lines += ["## Rules", ""]
        for v in verdicts:
            lines += _verdict_md(v)
        data = [{"rule": v.rule.id, "name": v.rule.name, "source": v.rule.source,
                 "status": v.status, "summary": v.summary, "numbers": v.numbers,
                 "details": v.details, "not_assessed": list(v.not_assessed)} for v in verdicts]
        written.append(write_text_atomic(outdir / "rules.json",
                                         json.dumps(data, indent=2, default=float) + "\n",
                                         what="the rule verdicts"))
    for warning in comp.warnings:
        lines.append(f"> Warning: {warning}")
    lines += ["", f"Made by cityshade from `{json.dumps(request, sort_keys=True)}`.", ""]
    text = "\n".join(lines)
    written.append(write_text_atomic(outdir / "report.md", text, what="the report"))
    from cityshade.present.html import write_report_html

    written.append(write_report_html(outdir / "report.html", text,
                                     title="Sunlight before and after",
                                     after_heading=_rule_figures(comp, verdicts)))
    return written
