"""The report of an evaluation: ``results.csv``, ``report.md``, plots, difference images."""
from __future__ import annotations

import csv
import statistics
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from cityshade.evaluate.metrics import median_s, pareto_front
from cityshade.evaluate.plot import error_time_plot
from cityshade.plotting import NO_MATPLOTLIB
from cityshade.evaluate.run import Evaluation


CSV_COLUMNS = ("model", "view", "view_px", "camera", "sun", "sun_az_deg", "sun_el_deg",
               "technique", "map_px", "runs", "warmup_s", "shadow_s", "gbuffer_s", "resolve_s",
               "frame_s", "valid_px", "wrong_px", "misclassified_pct", "false_lit_pct",
               "false_shadow_pct", "lit_mae", "edge_mean_m", "edge_p95_m", "edge_max_m",
               "aliasing_max_m", "aliasing_mean_m", "traced_share", "stages", "error")


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def write_csv(path, rows: Sequence[dict]) -> None:
    """``results.csv``: one row per view × sun × technique × map size (:data:`CSV_COLUMNS`)."""
    from cityshade.util import atomic_write

    with atomic_write(path, newline="", what="the results table") as fh:
        writer = csv.writer(fh)
        writer.writerow(CSV_COLUMNS)
        for row in rows:
            writer.writerow([_cell(row.get(c)) for c in CSV_COLUMNS])


def summary(rows: Sequence[dict]) -> dict[str, list[dict[str, Any]]]:
    """Per view: one entry per (technique, map size), averaged over the suns.

    Error figures are means over the suns, times are medians; entries carry ``key``
    (``technique@size``) and are sorted by time.
    """
    groups: dict[str, dict[tuple, list[dict]]] = {}
    for r in rows:
        if r.get("error") or r.get("shadow_s") in ("", None):
            continue
        groups.setdefault(r["view"], {}).setdefault((r["technique"], r["map_px"]), []).append(r)
    out: dict[str, list[dict[str, Any]]] = {}
    for view, g in groups.items():
        entries = []
        for (tech, size), rs in g.items():
            def mean(key):
                vals = [float(r[key]) for r in rs if r.get(key) not in ("", None)]
                return statistics.fmean(vals) if vals else None

            entries.append({
                "technique": tech, "map_px": size, "key": f"{tech}@{size}" if size else tech,
                "shadow_s": median_s([float(r["shadow_s"]) for r in rs]),
                "warmup_s": median_s([float(r["warmup_s"]) for r in rs]),
                "frame_s": median_s([float(r["frame_s"]) for r in rs]),
                **{k: mean(k) for k in ("misclassified_pct", "false_lit_pct", "false_shadow_pct",
                                        "lit_mae", "edge_mean_m", "edge_p95_m",
                                        "aliasing_max_m", "aliasing_mean_m", "traced_share")},
                "suns": len(rs),
            })
        entries.sort(key=lambda e: e["shadow_s"])
        front = pareto_front([e["shadow_s"] for e in entries],
                             [e["misclassified_pct"] for e in entries])
        for i, e in enumerate(entries):
            e["pareto"] = i in front
        out[view] = entries
    return out


def _f(value, fmt: str, empty: str = "–") -> str:
    return empty if value in (None, "") else format(float(value), fmt)


def report_markdown(evaluation: Evaluation, images: dict[str, list[str]] | None = None,
                    title: str | None = None, heading_level: int = 1) -> str:
    """The Markdown report: a reading of the Pareto front, then the table of every view."""
    h = "#" * heading_level
    meta = evaluation.meta
    lines = [f"{h} {title or 'Shadow error against run time'}", ""]
    if meta.get("model"):
        lines.append(f"Model `{meta['model']}`; city time {meta.get('city_time', '')}; "
                     f"map sizes {', '.join(str(s) for s in meta.get('sizes', []))}; "
                     f"{meta.get('repeat', '')} timed runs after one warm-up run.")
        lines.append("")
    lines += ["Error: pixels whose sun/shadow class differs from `raytrace` on the same pixels "
              "(% of surface pixels, mean over the suns); edge: distance from a wrong pixel to "
              "the nearest pixel that truly has its class (metres); shadow: median time of the "
              "shadow stage as `render` runs it (ms); warm-up: the first run.", ""]
    if meta.get("plot"):
        lines += [f"({meta['plot']}.)", ""]
    images = images or {}
    for view, entries in summary(evaluation.rows).items():
        lines += [f"{h}# View `{view}`", ""]
        front = [e for e in entries if e["pareto"]]
        rt = next((e for e in entries if e["technique"] == "raytrace"), None)
        reading = ", then ".join(f"`{e['key']}` ({_f(e['misclassified_pct'], '.3f')} % wrong, "
                                 f"{e['shadow_s'] * 1000:.1f} ms)" for e in front)
        lines.append(f"Pareto front (fastest first): {reading}.")
        if rt is not None:
            cheaper = [e for e in entries if e["shadow_s"] < rt["shadow_s"]
                       and e["technique"] != "raytrace"]
            exact = [e for e in entries if e["technique"] != "raytrace"
                     and (e["misclassified_pct"] or 0.0) == 0.0]
            lines.append(f"`raytrace` (exact) takes {rt['shadow_s'] * 1000:.1f} ms; "
                         f"{len(cheaper)} of {len(entries) - 1} technique/size pairs are faster; "
                         f"{len(exact)} match it exactly"
                         + (f" (fastest: `{min(exact, key=lambda e: e['shadow_s'])['key']}`)"
                            if exact else "") + ".")
        lines.append("")
        lines.append("| technique | map px | shadow ms | warm-up ms | wrong % | false-lit % | "
                     "false-shadow % | lit MAE | edge mean m | edge p95 m | alias m max | "
                     "alias m mean | traced % | front |")
        lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|")
        for e in entries:
            lines.append(
                f"| `{e['technique']}` | {e['map_px'] or '–'} | {e['shadow_s'] * 1000:.1f} | "
                f"{e['warmup_s'] * 1000:.1f} | {_f(e['misclassified_pct'], '.3f')} | "
                f"{_f(e['false_lit_pct'], '.3f')} | {_f(e['false_shadow_pct'], '.3f')} | "
                f"{_f(e['lit_mae'], '.4f')} | {_f(e['edge_mean_m'], '.3f')} | "
                f"{_f(e['edge_p95_m'], '.3f')} | {_f(e['aliasing_max_m'], '.3g')} | "
                f"{_f(e['aliasing_mean_m'], '.3g')} | "
                f"{_f(None if e['traced_share'] is None else 100 * e['traced_share'], '.2f')} | "
                f"{'●' if e['pareto'] else ''} |")
        lines.append("")
        failures = [r for r in evaluation.rows if r["view"] == view and r.get("error")]
        for r in failures:
            lines.append(f"- **failed**: `{r['technique']}` map {r['map_px'] or '–'} "
                         f"{r['sun']}: {r['error']}")
        if failures:
            lines.append("")
        skipped = evaluation.skipped.get(view) or []
        if skipped:
            lines += ["Left out because this scene and view did not need it:", ""]
            lines += [f"- {s}" for s in skipped]
            lines.append("")
        for img in images.get(view, []):
            lines.append(f"![{Path(img).stem}]({img})")
        if images.get(view):
            lines.append("")
    return "\n".join(lines)


def diff_image(picture: np.ndarray, false_lit: np.ndarray, false_shadow: np.ndarray) -> np.ndarray:
    """(H, W, 3) uint8: the picture dimmed to grey, false-lit pixels red, false-shadow blue."""
    pic = np.asarray(picture, np.float32)
    grey = (0.25 * pic.mean(axis=2, keepdims=True) + 0.5 * 255 * 0.25).repeat(3, axis=2)
    out = np.clip(grey + 0.35 * pic, 0, 255).astype(np.uint8)
    out[false_lit] = (230, 20, 20)
    out[false_shadow] = (20, 60, 230)
    return out


def _safe(text: str) -> str:
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in text)


def write_report(evaluation: Evaluation, outdir, title: str | None = None) -> list[Path]:
    """Write ``results.csv``, ``report.md`` and ``report.html`` (the same page, self-contained),
    ``error_vs_time_<view>.png`` (with matplotlib, the
    ``[plot]`` extra; without it the report says the plot was skipped) and the worst cases'
    ``diff_<view>_<technique>_<size>.png`` into ``outdir`` (created), all renamed into place
    together at the end (a failing or interrupted write leaves none). Returns the paths."""
    from cityshade.util import make_folder, output_group

    outdir = make_folder(outdir, "report folder")
    with output_group():
        return _write_report(evaluation, outdir, title)


def _write_report(evaluation: Evaluation, outdir: Path, title: str | None) -> list[Path]:
    from cityshade import imageio
    from cityshade.util import write_text_atomic

    written = []
    write_csv(outdir / "results.csv", evaluation.rows)
    written.append(outdir / "results.csv")
    images: dict[str, list[str]] = {}
    for view, entries in summary(evaluation.rows).items():
        plot = error_time_plot(entries, f"{evaluation.meta.get('model', '')} {view}".strip())
        if plot is None:
            evaluation.meta["plot"] = NO_MATPLOTLIB
            continue
        png = outdir / f"error_vs_time_{_safe(view)}.png"
        imageio.write_image(png, plot)
        written.append(png)
        images.setdefault(view, []).append(png.name)
    for view, cases in evaluation.worst.items():
        for case in cases:
            picture = evaluation.pictures.get((view, case.sun_label))
            if picture is None:
                continue
            name = _safe(f"diff_{view}_{case.technique}_{case.map_px or ''}_{case.sun_label}")
            png = outdir / f"{name}.png"
            imageio.write_image(png, diff_image(picture, case.false_lit, case.false_shadow))
            written.append(png)
            images.setdefault(view, []).append(png.name)
    md = outdir / "report.md"
    text = report_markdown(evaluation, images, title) + "\n"
    write_text_atomic(md, text, what="the report")
    written.append(md)
    from cityshade.present.html import write_report_html

    written.append(write_report_html(outdir / "report.html", text,
                                     title=title or "Shadow error against run time"))
    return written
