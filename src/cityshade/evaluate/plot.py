"""The error-against-time plot of an evaluation, drawn with matplotlib (the optional
``[plot]`` extra; :func:`cityshade.plotting.agg_canvas`).

Without matplotlib :func:`error_time_plot` returns None and the report says the plot was
skipped; the CSV and the Markdown are written either way.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from cityshade.plotting import NO_MATPLOTLIB, agg_canvas, canvas_pixels, have_matplotlib

__all__ = ["OKABE_ITO", "NO_MATPLOTLIB", "base_technique", "technique_colour",
           "error_time_plot"]

#: Okabe–Ito palette (distinguishable with colour blindness), in the order of base techniques:
#: raytrace black, shadowmap orange, pcf sky blue, vsm green, psm purple, lispsm vermillion,
#: xpsm blue, csm grey, izb yellow; later names repeat the palette.
OKABE_ITO = ((0, 0, 0), (230, 159, 0), (86, 180, 233), (0, 158, 115), (204, 121, 167),
             (213, 94, 0), (0, 114, 178), (120, 120, 120), (240, 228, 66))

def base_technique(technique: str) -> str:
    """The planner (or alias, or exact technique) a name is built on: the colour key."""
    from cityshade.evaluate.run import map_family
    from cityshade.shadows import ALIASES, describe

    spec = describe(map_family(technique))
    if spec.family == "exact":
        return spec.engine
    return spec.name if spec.name in ALIASES else spec.planner


def technique_colour(technique: str) -> tuple[int, int, int]:
    """Colour of a technique's base in the registry's order (:data:`OKABE_ITO`)."""
    from cityshade.shadows import exact_technique_names, map_technique_names

    # The reference first, then the map techniques, then the other exact ones (later
    # additions never shift the colours of the existing names).
    names = ["raytrace", *map_technique_names(), *exact_technique_names()]
    bases = list(dict.fromkeys(base_technique(n) for n in names))
    base = base_technique(technique)
    index = bases.index(base) if base in bases else len(bases)
    return OKABE_ITO[index % len(OKABE_ITO)]


def _marker(technique: str) -> str:
    """Shape: plain o, +smooth square, hybrid triangle, exact techniques a diamond."""
    from cityshade.shadows import describe

    spec = describe(technique)
    if spec.family == "exact":
        return "D"
    if spec.family == "hybrid":
        return "^"
    return "s" if spec.smooth else "o"


def minor_time_label(value: float, few_decades: bool) -> str:
    """The label of a minor tick of the log time axis: 2 and 5 times a power of ten when the
    times span under two decades (there may be no labelled power of ten then), else none.

    >>> [minor_time_label(v, True) for v in (200.0, 300.0, 500.0, 0.05)]
    ['200', '', '500', '0.05']
    """
    if not few_decades or value <= 0.0:
        return ""
    mantissa = round(value / 10.0 ** math.floor(math.log10(value)), 6)
    return f"{value:g}" if mantissa in (2.0, 5.0) else ""


def error_time_plot(entries: Sequence[dict], title: str = "") -> np.ndarray | None:
    """Error against run time on log axes, one marker per technique and size.

    Parameters
    ----------
    entries : sequence of dict
        :func:`cityshade.evaluate.report.summary` entries of one view (``technique``,
        ``map_px``, ``shadow_s``, ``misclassified_pct``, ``pareto``).
    title : str

    Returns
    -------
    (640, 1100, 3) uint8, or None without matplotlib
        x: shadow-stage time in ms, y: misclassified pixels in %; points with no error sit on
        a "0" row below the lowest decade; marker colour = base technique, shape = plain (o),
        smoothed (square), hybrid (triangle), exact techniques (diamond), size grows with the map; the
        Pareto front is the black staircase.
    """
    if not have_matplotlib():
        return None
    from matplotlib.lines import Line2D

    fig, canvas = agg_canvas(1100, 640)
    ax = fig.add_axes((0.08, 0.1, 0.66, 0.8))
    pts = [e for e in entries if e.get("misclassified_pct") is not None]
    if not pts:
        ax.text(0.5, 0.5, "no results", ha="center", va="center", transform=ax.transAxes)
        return canvas_pixels(canvas)
    t_ms = np.array([max(e["shadow_s"] * 1000.0, 1e-3) for e in pts])
    err = np.array([float(e["misclassified_pct"]) for e in pts])
    nonzero = err[err > 0]
    # Error 0 cannot sit on a log axis: a "0" row one decade below the smallest error.
    zero_y = 10.0 ** (math.floor(math.log10(nonzero.min())) - 1) if nonzero.size else 1e-3
    y = np.where(err > 0, err, zero_y)
    from matplotlib.ticker import FuncFormatter

    ax.set_xscale("log")
    ax.set_yscale("log")
    plain = FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(plain)
    # Under two decades of times there may be no power of ten on the axis to label: the minor
    # ticks at 2 and 5 times one are labelled then.
    few = math.log10(max(float(t_ms.max()), 1e-3) / float(t_ms.min())) < 2.0
    ax.xaxis.set_minor_formatter(FuncFormatter(lambda v, _: minor_time_label(v, few)))
    ax.grid(True, which="major", color="#e1e1e1")
    ax.axhline(zero_y, color="#e1e1e1", lw=1)
    front = sorted((i for i, e in enumerate(pts) if e.get("pareto")), key=lambda i: t_ms[i])
    if len(front) > 1:
        ax.step(t_ms[front], y[front], where="post", color="black", lw=2, zorder=2)
    # Largest markers first so the small ones stay visible.
    for i in sorted(range(len(pts)), key=lambda i: -int(pts[i]["map_px"] or 0)):
        e = pts[i]
        size = int(e["map_px"] or 1024)
        r = float(np.clip(2 + math.log2(max(size, 256) / 256.0), 2, 8))
        colour = tuple(c / 255.0 for c in technique_colour(e["technique"]))
        ax.plot([t_ms[i]], [y[i]], _marker(e["technique"]), ms=3.0 * r, mfc=colour,
                mec="black", mew=1.0, zorder=3)
    ticks = [t for t in ax.get_yticks() if t > zero_y]
    ax.set_yticks([zero_y, *ticks], ["0", *(f"{t:g}" for t in ticks)])
    ax.set_ylim(zero_y / 2.0, max(float(y.max()), zero_y) * 2.0)
    ax.set_xlabel("shadow stage time, ms (log)")
    ax.set_ylabel("wrong pixels, % (log)")
    if title:
        ax.set_title(title)
    seen = list(dict.fromkeys(base_technique(e["technique"]) for e in pts))
    handles = [Line2D([], [], ls="", marker=_marker(b), ms=8, mec="black",
                      mfc=tuple(c / 255.0 for c in technique_colour(b)), label=b) for b in seen]
    handles += [Line2D([], [], ls="", marker=m, ms=8, mec="black", mfc="white", label=label)
                for m, label in (("o", "plain"), ("s", "+smooth"), ("^", "hybrid:base"),
                                 ("D", "exact"))]
    handles.append(Line2D([], [], color="black", lw=2, label="Pareto front"))
    fig.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.76, 0.9), frameon=False,
               title="colour: base technique\nbigger marker: bigger map")
    return canvas_pixels(canvas)
