"""One sheet of a shadow study: the panels of a day on an A3 landscape page, with a title
block, legend, north arrow and scale bar (:mod:`cityshade.present.maps`' drawing helpers).

Laid out in inches on a matplotlib :class:`~matplotlib.figure.Figure` (object API, no pyplot),
so the same figure is a PDF page (vector text and lines, the panels as images at their full
resolution) and a PNG at :data:`PNG_DPI`. Every panel has the same scale: one scale bar and one
north arrow stand for all of them (map views are north up).
"""
from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["PNG_DPI", "SHEET_IN", "SheetInfo", "SheetText", "draw_sheet"]

#: A3 landscape in inches.
SHEET_IN = (420.0 / 25.4, 297.0 / 25.4)
#: Resolution of the PNG sheets (2480 × 1754 px for A3).
PNG_DPI = 150
_MARGIN_IN = 0.35
_COLUMN_IN = 3.35        # the title block on the right
_GAP_IN = 0.18
_TITLE_IN = 0.42         # two lines above each panel
_FONT_PT = 8.5
_DAY_NAMES = {(3, 21): "March equinox", (6, 21): "June solstice", (12, 21): "December solstice",
              (9, 21): "September equinox"}


@dataclass(frozen=True)
class SheetText:
    """The words of a sheet: ``rows`` of (label, value) for the title block, the ``notes``
    under the legend, and the footer's version, sheet number and count."""

    rows: Sequence[tuple[str, str]]
    notes: str
    version: str
    number: int
    count: int
    zone_label: str = ""


@dataclass(frozen=True)
class SheetInfo:
    """Where things are on the PNG of a sheet (pixels, row 0 at the top).

    Attributes
    ----------
    scale_bar_m : float
        The bar's stated length.
    scale_bar_px : float
        Its length on the PNG.
    scale_bar_row, scale_bar_col : int
        A row through the middle of the bar and its first column.
    px_per_m : float
        PNG pixels per metre of the panels.
    panel_boxes : list of (col0, row0, col1, row1)
        Each panel's map on the PNG.
    convergence_deg, true_north_cw_deg : float or None
        As :class:`cityshade.present.maps.Decorated`.
    scale_denominator : float
        1 : N on the printed A3 sheet.
    """

    scale_bar_m: float
    scale_bar_px: float
    scale_bar_row: int
    scale_bar_col: int
    px_per_m: float
    panel_boxes: list
    convergence_deg: float | None
    true_north_cw_deg: float | None
    scale_denominator: float


def _grid(n: int, aspect: float, width_in: float, height_in: float) -> tuple[int, int, float]:
    """(columns, rows, map width in inches) of ``n`` panels of width/height ``aspect`` that
    makes the panels largest."""
    best = (1, n, 0.0)
    for cols in range(1, n + 1):
        rows = math.ceil(n / cols)
        cell_w = (width_in - (cols - 1) * _GAP_IN) / cols
        cell_h = (height_in - (rows - 1) * _GAP_IN) / rows - _TITLE_IN
        w = min(cell_w, cell_h * aspect)
        if w > best[2]:
            best = (cols, rows, w)
    return best


def draw_sheet(panels: Sequence[Any], view, scene, text: SheetText,
               area: Sequence[float] | None = None):
    """(Figure, SheetInfo) of one day's ``panels`` (:class:`cityshade.study.panels.Panel`) on
    ``view`` (:class:`cityshade.study.panels.StudyView`)."""
    from matplotlib.figure import Figure

    from cityshade.present.maps import (
        MapContext,
        convergence_at_centre_deg,
        true_north_cw_deg,
    )

    fig = Figure(figsize=SHEET_IN, dpi=PNG_DPI)
    fig.patch.set_facecolor("white")
    camera = view.camera
    gt = camera.geotransform(scene.origin_m)
    h, w = camera.shape
    extent = (gt[0], gt[0] + w * gt[1], gt[3] + h * gt[5], gt[3])
    area_w = SHEET_IN[0] - 2 * _MARGIN_IN - _COLUMN_IN - _GAP_IN
    area_h = SHEET_IN[1] - 2 * _MARGIN_IN
    cols, rows, map_w_in = _grid(len(panels), w / h, area_w, area_h)
    map_h_in = map_w_in * h / w
    # The grid centred in the panels' area.
    left = _MARGIN_IN + 0.5 * (area_w - cols * map_w_in - (cols - 1) * _GAP_IN)
    top = SHEET_IN[1] - _MARGIN_IN - 0.5 * (area_h - rows * (map_h_in + _TITLE_IN)
                                             - (rows - 1) * _GAP_IN)
    boxes = []
    for k, panel in enumerate(panels):
        r, c = divmod(k, cols)
        x = left + c * (map_w_in + _GAP_IN)
        y_top = top - r * (map_h_in + _TITLE_IN + _GAP_IN) - _TITLE_IN
        ax = fig.add_axes((x / SHEET_IN[0], (y_top - map_h_in) / SHEET_IN[1],
                           map_w_in / SHEET_IN[0], map_h_in / SHEET_IN[1]))
        _panel(ax, panel, view, extent, area, text.zone_label)
        boxes.append(_box_px(x, y_top, map_w_in, map_h_in))
    gamma = convergence_at_centre_deg(MapContext(gt, scene.crs), (h, w))
    px_per_in = map_w_in / (w * gt[1])  # inches of paper per metre
    info = _title_block(fig, text, panels, area is not None, px_per_in, gamma,
                        true_north_cw_deg(gamma))
    return fig, SheetInfo(info[0], info[1], info[2], info[3], px_per_in * PNG_DPI, boxes,
                          gamma, true_north_cw_deg(gamma), 1.0 / (px_per_in * 0.0254))


def _box_px(x_in, y_top_in, w_in, h_in) -> tuple[int, int, int, int]:
    height_px = SHEET_IN[1] * PNG_DPI
    return (round(x_in * PNG_DPI), round(height_px - y_top_in * PNG_DPI),
            round((x_in + w_in) * PNG_DPI), round(height_px - (y_top_in - h_in)
                                                          * PNG_DPI))


def _panel(ax, panel, view, extent, area, zone_label: str) -> None:
    """A panel: the categories' picture, building outlines, the site, the time and the sun."""
    from matplotlib.patches import Rectangle
    from matplotlib.transforms import ScaledTranslation

    from cityshade.study.panels import panel_rgb

    ax.imshow(panel_rgb(panel.cats), extent=extent, interpolation="antialiased",
              interpolation_stage="rgba")
    for mask, colour, lw in ((view.building_after & ~view.new_building, "0.15", 0.35),
                             (view.new_building, "#1d3f8f", 0.6)):
        if mask.any():
            ax.contour(mask.astype(np.float32), levels=[0.5], extent=extent, origin="upper",
                       colors=colour, linewidths=lw)
    if area is not None:
        ax.add_patch(Rectangle((area[0], area[1]), area[2] - area[0], area[3] - area[1],
                               fill=False, edgecolor="#c8102e", lw=1.1, ls=(0, (4, 2))))
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_linewidth(0.6)
        spine.set_color("0.3")
    sun = panel.sun
    clock = panel.local.strftime("%H:%M") + (f" {zone_label}" if zone_label else "")
    above = ax.transAxes + ScaledTranslation(0.0, 0.05, ax.figure.dpi_scale_trans)
    ax.text(0.0, 1.0, f"sun azimuth {sun.azimuth_true_deg:.1f}°, elevation "
            f"{sun.elevation_deg:.1f}°", transform=above, ha="left", va="bottom",
            fontsize=7.5, color="0.2")
    ax.text(0.0, 1.0, clock, fontsize=10.5, weight="bold", ha="left", va="bottom",
            transform=ax.transAxes + ScaledTranslation(0.0, 0.2, ax.figure.dpi_scale_trans))
    if not panel.sun_up:
        ax.text(0.5, 0.5, "sun below the horizon", transform=ax.transAxes, ha="center",
                va="center", fontsize=9, bbox={"facecolor": "white", "edgecolor": "0.4",
                                               "boxstyle": "round,pad=0.4"})


def _legend_items(panels, has_area: bool) -> list[tuple[Any, str, str]]:
    """(colour, edge colour, label) of what the sheet shows."""
    from cityshade.study import panels as P

    present = set()
    for panel in panels:
        present.update(int(v) for v in np.unique(panel.cats))
    hexes = ["#{:02x}{:02x}{:02x}".format(*tuple(int(c) for c in P.PALETTE[k])) for k in range(len(P.LABELS))]
    items = [(hexes[P.SUN], "0.5", "sun", True),
             (hexes[P.ROOF_SUN], "0.15", "building (roof in sun)", P.ROOF_SUN in present),
             (hexes[P.SHADOW], "0.5", "existing shadow", True),
             (hexes[P.ROOF_SHADOW], "0.15", "existing shadow on a roof",
              P.ROOF_SHADOW in present),
             (hexes[P.NEW_SHADOW], "0.5", "new shadow (sun before, shadow after)", True),
             (hexes[P.SHADOW_GONE], "0.5", "shadow no longer cast", P.SHADOW_GONE in present),
             (hexes[P.NEW_BUILDING], "#1d3f8f", "new building (in sun)",
              P.NEW_BUILDING in present),
             (hexes[P.NEW_BUILDING_SHADOW], "#1d3f8f", "new building (in shadow)",
              P.NEW_BUILDING_SHADOW in present),
             *((hexes[k], "0.5", P.LABELS[k], k in present)
               for k in (P.TREE_CROWN, P.TREE_SHADE, P.NEW_TREE_SHADE))]
    items = [item[:3] for item in items if item[3]]
    if has_area:
        items.append(("none", "#c8102e", "site boundary"))
    return items


def _title_block(fig, text: SheetText, panels, has_area: bool, in_per_m: float, gamma,
                 true_cw) -> tuple[float, float, int, int]:
    """The right-hand column: title, day, table, legend, north arrow, scale bar, notes,
    footer. Returns the scale bar's (metres, PNG pixels, PNG row, PNG column)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Rectangle

    from cityshade.present.maps import (
        SCALE_BAR_SHARE,
        draw_north_arrow,
        draw_scale_bar,
        scale_bar_m,
    )

    inch = fig.dpi_scale_trans
    W, H = SHEET_IN
    x0 = W - _MARGIN_IN - _COLUMN_IN + 0.15
    fig.add_artist(Rectangle((_MARGIN_IN * 0.5, _MARGIN_IN * 0.5), W - _MARGIN_IN,
                             H - _MARGIN_IN, transform=inch, fill=False, lw=1.0,
                             edgecolor="0.2"))
    fig.add_artist(Line2D([x0 - 0.15, x0 - 0.15], [_MARGIN_IN * 0.5, H - _MARGIN_IN * 0.5],
                          transform=inch, lw=0.8, color="0.2"))
    y = H - _MARGIN_IN - 0.1
    fig.text(x0, y, "SHADOW STUDY", transform=inch, fontsize=17, weight="bold", va="top")
    y -= 0.45
    day = panels[0].day
    fig.text(x0, y, f"{day.day} {day:%B %Y}", transform=inch, fontsize=14, weight="bold",
             va="top")
    y -= 0.3
    if (day.month, day.day) in _DAY_NAMES:
        fig.text(x0, y, _DAY_NAMES[(day.month, day.day)], transform=inch, fontsize=10,
                 va="top", color="0.25")
        y -= 0.25
    y -= 0.1
    line_in = 1.4 * _FONT_PT / 72.0
    for label, value in text.rows:
        lines = textwrap.wrap(str(value), 34) or [""]
        fig.text(x0, y, label, transform=inch, fontsize=_FONT_PT, va="top", color="0.35")
        fig.text(x0 + 0.95, y, "\n".join(lines), transform=inch, fontsize=_FONT_PT, va="top",
                 linespacing=1.4)
        y -= line_in * len(lines) + 0.04
    y -= 0.15
    fig.text(x0, y, "Legend", transform=inch, fontsize=10, weight="bold", va="top")
    y -= 0.3
    for colour, edge, label in _legend_items(panels, has_area):
        fig.add_artist(Rectangle((x0, y - 0.12), 0.32, 0.17, transform=inch,
                                 facecolor=colour, edgecolor=edge,
                                 lw=1.1 if colour == "none" else 0.6,
                                 ls=(0, (4, 2)) if colour == "none" else "-"))
        fig.text(x0 + 0.45, y - 0.035, label, transform=inch, fontsize=_FONT_PT, va="center")
        y -= 0.27
    y -= 0.2
    # North arrow at the right, scale bar at the left of the same band.
    em = 11.0 / 72.0
    draw_north_arrow(fig, (W - _MARGIN_IN - 0.45, y - 3.6 * em), em, 10.0, true_cw, inch)
    # About 1.4 in of paper (a 1-2-5 length: between 0.9 and 2.2 in).
    bar_m = scale_bar_m(1.4 / in_per_m / SCALE_BAR_SHARE)
    bar_in, thick_in = bar_m * in_per_m, 0.07
    bar_y = y - 0.35
    fig.text(x0, y, "Scale (all panels)", transform=inch, fontsize=_FONT_PT, va="top",
             color="0.35")
    draw_scale_bar(fig, (x0, bar_y - thick_in), bar_in, thick_in, bar_m, _FONT_PT, 0.08, inch)
    fig.text(x0, bar_y - 0.2, f"1 : {_round_scale(1.0 / (in_per_m * 0.0254))} on A3",
             transform=inch, fontsize=_FONT_PT, va="top")
    north = ("Grid north up" if true_cw is None else
             f"Grid north up; true north (★) {abs(gamma):.2f}° "
             f"{'west' if gamma > 0 else 'east'}") if gamma is not None else \
        "Grid north up (no geodetic CRS)"
    fig.text(x0, bar_y - 0.45, north, transform=inch, fontsize=7.5, va="top", color="0.25")
    y -= 1.35
    fig.text(x0, y, "\n".join(textwrap.wrap(text.notes, 52)), transform=inch, fontsize=7.5,
             va="top", color="0.25", linespacing=1.35)
    fig.text(x0, _MARGIN_IN + 0.05, f"cityshade {text.version}    sheet {text.number} of "
             f"{text.count}", transform=inch, fontsize=_FONT_PT, va="bottom", color="0.25")
    row = round((H - (bar_y - thick_in / 2.0)) * PNG_DPI)
    return bar_m, bar_in * PNG_DPI, row, round(x0 * PNG_DPI)


def _round_scale(n: float) -> str:
    """N of a scale 1 : N to three significant digits, thin spaces between thousands."""
    return f"{float(f'{n:.3g}'):,.0f}".replace(",", "\u2009")
