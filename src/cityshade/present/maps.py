"""Maps with context: a map picture framed in a margin with a scale bar, a north arrow, the CRS,
and optionally a title and a colour bar (or category legend) with units.

The map's own pixels are copied unchanged (``figimage`` at an integer offset, nothing drawn
over it): a decorated PNG is for people, the GeoTIFF and EXR beside it keep the values. Drawn
with matplotlib's object API on an Agg canvas (:func:`cityshade.plotting.agg_canvas`).

North: a map camera looks straight down with grid north up (docs/DESIGN.md §1), so the big
arrow points up. True north differs from grid north by the meridian convergence γ
(:func:`cityshade.geo.crs.grid_convergence_deg`, positive when grid north lies east of true
north); where |γ| > :data:`TRUE_NORTH_MIN_DEG` at the map's centre a second, thin arrow with a
star shows true north, turned by −γ (clockwise positive) from the top of the picture.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from cityshade.errors import CRSError, UsageError

__all__ = ["ColourBar", "Categories", "MapContext", "Decorated", "scale_bar_m",
           "convergence_at_centre_deg", "decorate_map", "decorate_or_plain", "Mark",
           "annotate_map", "draw_scale_bar", "draw_north_arrow", "true_north_cw_deg"]

#: The scale bar aims at this share of the map's width (then rounded to 1, 2 or 5 × 10^k m).
SCALE_BAR_SHARE = 0.2
#: True north is drawn when it differs from grid north by more than this (degrees): below it the
#: two arrows would be one on a printed map.
TRUE_NORTH_MIN_DEG = 1.0
#: Narrowest decorated picture (pixels): room for the scale bar's label, the arrow and the CRS.
MIN_WIDTH_PX = 480


@dataclass(frozen=True)
class ColourBar:
    """A continuous legend: ``ramp`` (N, 3) uint8 colours from ``vmin`` to ``vmax``, and the
    quantity with its units (``label``, e.g. ``"sun-hours (h)"``)."""

    ramp: Any
    vmin: float
    vmax: float
    label: str


@dataclass(frozen=True)
class Categories:
    """A legend of classes: ``items`` of ((r, g, b) uint8, label)."""

    items: tuple


@dataclass(frozen=True)
class MapContext:
    """Where a map lies and what it shows.

    Attributes
    ----------
    geotransform : sequence of 6 float
        GDAL convention, upper-left corner of pixel (0, 0), metres of the CRS, north up
        (``Camera.geotransform``).
    crs : cityshade.geo.crs.CrsInfo or None
        The scene's CRS (its name is printed; true north needs a known one).
    title : str, optional
    legend : ColourBar or Categories, optional
    """

    geotransform: Sequence[float]
    crs: Any = None
    title: str | None = None
    legend: ColourBar | Categories | None = None


@dataclass(frozen=True)
class Decorated:
    """A decorated map and where its parts are.

    Attributes
    ----------
    image : (H', W', 3) uint8
    map_row, map_col : int
        Top-left pixel of the map inside ``image`` (the map's pixels are there unchanged).
    scale_bar_m : float
        The bar's stated length.
    scale_bar_px : float
        Its length in pixels: ``scale_bar_m / pixel size``.
    scale_bar_row, scale_bar_col : int
        A row through the middle of the (black) bar, and the column where it starts.
    convergence_deg : float or None
        Meridian convergence γ at the map's centre (None: CRS without geodesy).
    true_north_cw_deg : float or None
        Direction of the true-north arrow, degrees clockwise from the top of the picture
        (−γ); None when it is not drawn (|γ| ≤ :data:`TRUE_NORTH_MIN_DEG` or unknown).
    """

    image: np.ndarray
    map_row: int
    map_col: int
    scale_bar_m: float
    scale_bar_px: float
    scale_bar_row: int
    scale_bar_col: int
    convergence_deg: float | None
    true_north_cw_deg: float | None


def scale_bar_m(width_m: float) -> float:
    """The round length (1, 2 or 5 × 10^k metres) nearest, on a log scale, to
    :data:`SCALE_BAR_SHARE` of ``width_m``."""
    if not (math.isfinite(width_m) and width_m > 0.0):
        raise UsageError(f"a map width must be > 0 metres, not {width_m}")
    target = SCALE_BAR_SHARE * width_m
    k = math.floor(math.log10(target))
    candidates = [m * 10.0 ** e for e in (k - 1, k, k + 1) for m in (1.0, 2.0, 5.0)]
    return min(candidates, key=lambda c: abs(math.log(c / target)))


def _length_label(metres: float) -> str:
    if metres >= 1000.0:
        return f"{metres / 1000.0:g} km"
    return f"{metres:g} m"


def convergence_at_centre_deg(ctx: MapContext, shape: tuple[int, int]) -> float | None:
    """γ (degrees) at the centre of a map of ``shape`` (H, W), or None for a CRS without
    geodesy (local, unknown, or coordinates outside it)."""
    from cityshade.geo.crs import grid_convergence_deg

    crs = ctx.crs
    if crs is None or crs.local or (crs.horizontal_epsg is None and not crs.is_geographic):
        return None
    gt = [float(v) for v in ctx.geotransform]
    h, w = shape
    x = gt[0] + 0.5 * w * gt[1] + 0.5 * h * gt[2]
    y = gt[3] + 0.5 * w * gt[4] + 0.5 * h * gt[5]
    try:
        return grid_convergence_deg(crs, x, y)
    except CRSError:
        return None


def true_north_cw_deg(gamma_deg: float | None) -> float | None:
    """Direction of the true-north arrow, degrees clockwise from grid north (−γ), or None when
    it is not drawn: |γ| ≤ :data:`TRUE_NORTH_MIN_DEG`, or γ unknown."""
    if gamma_deg is None or abs(gamma_deg) <= TRUE_NORTH_MIN_DEG:
        return None
    return -gamma_deg


@dataclass(frozen=True)
class _Layout:
    """Pixel layout of a decorated map (y down from the top of the picture)."""

    width: int
    height: int
    font_pt: float
    font_px: float
    pad: int
    map_row: int
    map_col: int
    legend_top: int
    scale_top: int
    text_top: int
    title: tuple[str, ...]
    text: tuple[str, ...]


def _wrap(text: str, width_px: float, char_px: float) -> tuple[str, ...]:
    """Lines of ``text`` that fit ``width_px`` at ~``char_px`` per character."""
    import textwrap

    return tuple(textwrap.wrap(text, max(12, int(width_px / char_px)))) or ("",)


def _layout(shape: tuple[int, int], ctx: MapContext, text: Sequence[str]) -> _Layout:
    h, w = shape
    font_pt = float(np.clip(max(w, MIN_WIDTH_PX) / 60.0, 8.0, 18.0))
    font_px = font_pt * 100.0 / 72.0
    pad = max(8, int(round(font_px)))
    width = max(w + 2 * pad, MIN_WIDTH_PX)
    # DejaVu Sans averages ~0.6 em per character; the title is 1.15 em and bold.
    title = _wrap(ctx.title, width - 2 * pad, 0.68 * 1.15 * font_px) if ctx.title else ()
    lines = tuple(line for t in text for line in _wrap(t, width - 2 * pad, 0.6 * 0.9 * font_px))
    title_h = int(round((0.8 + 1.45 * len(title)) * font_px)) if title else pad
    legend_h = int(round(4.2 * font_px)) if ctx.legend is not None else 0
    scale_h = int(round(4.2 * font_px))
    text_h = int(round((0.6 + 1.25 * len(lines)) * font_px))
    map_row = title_h
    legend_top = map_row + h + pad
    scale_top = legend_top + legend_h
    text_top = scale_top + scale_h
    return _Layout(width, text_top + text_h, font_pt, font_px, pad, map_row,
                   (width - w) // 2, legend_top, scale_top, text_top, title, lines)


def decorate_map(rgb: np.ndarray, ctx: MapContext) -> Decorated:
    """Frame a map picture with a scale bar, north arrow(s), the CRS, and the title and legend
    of ``ctx``. Needs matplotlib (:func:`cityshade.plotting.have_matplotlib`).

    Parameters
    ----------
    rgb : (H, W, 3) uint8
        The map, row 0 at the north edge; its pixels are copied unchanged.
    ctx : MapContext

    Returns
    -------
    Decorated

    Raises
    ------
    UsageError
        Not an (H, W, 3) uint8 picture, or a rotated or non-square-pixel geotransform.
    """
    from matplotlib.transforms import IdentityTransform

    from cityshade.plotting import agg_canvas, canvas_pixels

    rgb = np.asarray(rgb)
    if rgb.ndim != 3 or rgb.shape[2] != 3 or rgb.dtype != np.uint8:
        raise UsageError(f"a map picture must be (H, W, 3) uint8, not {rgb.shape} {rgb.dtype}")
    gt = [float(v) for v in ctx.geotransform]
    px_m = gt[1]
    if gt[2] != 0.0 or gt[4] != 0.0 or not (px_m > 0.0 and abs(gt[5] + px_m) <= 1e-9 * px_m):
        raise UsageError(f"a decorated map needs a north-up geotransform with square pixels, "
                         f"not {tuple(gt)}")
    h, w = rgb.shape[:2]
    gamma = convergence_at_centre_deg(ctx, (h, w))
    lay = _layout((h, w), ctx, _crs_lines(ctx, gt, (h, w), gamma))
    fig, canvas = agg_canvas(lay.width, lay.height)
    # Inches × dpi can land a hair below the whole pixel (418.99999 → 418): nudge it up.
    fig.set_size_inches((lay.width + 1e-3) / fig.dpi, (lay.height + 1e-3) / fig.dpi)
    width, height = canvas.get_width_height()
    fig.patch.set_facecolor("white")
    px = IdentityTransform()  # display pixels, origin at the bottom left

    def y_up(row: float) -> float:
        return height - row

    from matplotlib.patches import Rectangle

    # A thin frame just outside the map, drawn below it so it never touches a map pixel.
    fig.add_artist(Rectangle((lay.map_col - 1, y_up(lay.map_row + h) - 1), w + 2, h + 2,
                             transform=px, facecolor="none", edgecolor="0.35", lw=0.75,
                             antialiased=False, zorder=-5))
    # At an integer offset, one picture pixel per canvas pixel, no resampling: copied as is.
    fig.figimage(rgb, xo=lay.map_col, yo=height - (lay.map_row + h), origin="upper", zorder=5,
                 interpolation="nearest", resample=False)
    if lay.title:
        fig.text(width / 2.0, y_up(lay.map_row / 2.0), "\n".join(lay.title), transform=px,
                 ha="center", va="center", fontsize=lay.font_pt * 1.15, weight="bold",
                 linespacing=1.25)
    if isinstance(ctx.legend, ColourBar):
        _colour_bar(fig, lay, width, height, ctx.legend)
    elif isinstance(ctx.legend, Categories):
        _categories(fig, lay, height, ctx.legend)
    bar_m = scale_bar_m(w * px_m)
    bar_px = bar_m / px_m
    bar_row, bar_col = _scale_bar(fig, lay, height, bar_m, bar_px)
    true_cw = true_north_cw_deg(gamma)
    _north_arrows(fig, lay, width, height, true_cw)
    fig.text(lay.pad, height - lay.text_top - 0.2 * lay.font_px, "\n".join(lay.text),
             transform=px, ha="left", va="top", fontsize=lay.font_pt * 0.9, linespacing=1.35)
    image = canvas_pixels(canvas)
    if image.shape[:2] != (height, width):  # never: Agg draws the canvas it reports
        raise UsageError(f"the decorated map is {image.shape[:2]}, not {(height, width)}")
    return Decorated(image, lay.map_row, lay.map_col, bar_m, bar_px, bar_row, bar_col, gamma,
                     true_cw)


def _scale_bar(fig, lay: _Layout, height: int, bar_m: float, bar_px: float) -> tuple[int, int]:
    """A black bar of ``bar_px`` pixels at the left of the scale row, its length written to
    its right (a short bar has no room for labels at both ends); returns (row through its
    middle, first column)."""
    from matplotlib.transforms import IdentityTransform

    bar_h = max(4, int(round(0.45 * lay.font_px)))
    col0 = lay.pad
    top = lay.scale_top + int(round(1.9 * lay.font_px))
    draw_scale_bar(fig, (col0, height - top - bar_h), bar_px, bar_h, bar_m, lay.font_pt,
                   0.5 * lay.font_px, IdentityTransform())
    return top + bar_h // 2, col0


def draw_scale_bar(fig, corner, length: float, thickness: float, bar_m: float,
                   font_pt: float, gap: float, transform) -> None:
    """A black bar of ``length`` (units of ``transform``: display pixels, inches...) from its
    lower-left ``corner``, ``bar_m`` written ``gap`` to its right. Whole pixels, no
    anti-aliasing: the bar covers exactly the columns of its length."""
    from matplotlib.patches import Rectangle

    x, y = corner
    fig.add_artist(Rectangle((x, y), length, thickness, transform=transform,
                             facecolor="black", edgecolor="none", antialiased=False))
    fig.text(x + length + gap, y + thickness / 2.0, _length_label(bar_m), transform=transform,
             ha="left", va="center", fontsize=font_pt)


def _north_arrows(fig, lay: _Layout, width: int, height: int, true_cw: float | None) -> None:
    """Grid north at the right of the legend and scale rows (:func:`draw_north_arrow`)."""
    from matplotlib.transforms import IdentityTransform

    x = width - lay.pad - 1.6 * lay.font_px
    base = height - (lay.text_top - 0.4 * lay.font_px)
    draw_north_arrow(fig, (x, base), lay.font_px, lay.font_pt, true_cw, IdentityTransform())


def draw_north_arrow(fig, foot, em: float, font_pt: float, true_cw: float | None,
                     transform) -> None:
    """Grid north (up, bold, "N") from ``foot``, 3 ``em`` long (``em``: the font size in the
    units of ``transform``); true north (thin, a star at its tip) turned by ``true_cw``
    degrees clockwise when given."""
    from matplotlib.patches import FancyArrow

    x, base = foot
    length = 3.0 * em
    fig.add_artist(FancyArrow(x, base, 0.0, length, width=0.35 * em,
                              head_width=1.1 * em, head_length=0.9 * em,
                              length_includes_head=True, transform=transform, color="black"))
    if true_cw is None:
        fig.text(x, base + length + 0.15 * em, "N", transform=transform, ha="center",
                 va="bottom", fontsize=font_pt, weight="bold")
    else:  # beside the head: the true-north star stands above it
        fig.text(x - 0.8 * em, base + length - 0.45 * em, "N (grid)",
                 transform=transform, ha="right", va="center", fontsize=font_pt, weight="bold")
    if true_cw is not None:
        a = math.radians(true_cw)
        dx, dy = 1.25 * length * math.sin(a), 1.25 * length * math.cos(a)
        fig.add_artist(FancyArrow(x, base, dx, dy, width=0.08 * em,
                                  head_width=0.0, head_length=0.0, transform=transform,
                                  color="0.25"))
        fig.text(x + dx, base + dy, "★", transform=transform, ha="center", va="center",
                 fontsize=font_pt, color="0.25")


def _crs_lines(ctx: MapContext, gt, shape, gamma) -> list[str]:
    """What the map's coordinates are: the CRS and extent, and what north means."""
    h, w = shape
    x0, y1 = gt[0], gt[3]
    x1, y0 = x0 + w * gt[1], y1 + h * gt[5]
    name = ctx.crs.name if ctx.crs is not None else "unknown CRS"
    def m(v: float) -> str:
        return f"{v:,.0f}".replace(",", "\u2009")  # thin space between thousands

    lines = [f"{name}; x {m(x0)}–{m(x1)}, y {m(y0)}–{m(y1)} m; {gt[1]:g} m per pixel"]
    if gamma is None:
        lines.append("Grid north up (true north unknown: no geodetic CRS).")
    elif abs(gamma) > TRUE_NORTH_MIN_DEG:
        side = "west" if gamma > 0 else "east"
        lines.append(f"Grid north up; true north (★) {abs(gamma):.2f}° {side} of it "
                     f"(meridian convergence {gamma:+.2f}° at the centre).")
    else:
        lines.append(f"Grid north up (true north within {abs(gamma):.2f}° of it).")
    return lines


def _colour_bar(fig, lay: _Layout, width: int, height: int, bar: ColourBar) -> None:
    """The ramp from ``vmin`` to ``vmax`` with ticks and the quantity's label."""
    from matplotlib.colors import ListedColormap

    ramp = np.asarray(bar.ramp, np.float64).reshape(-1, 3) / 255.0
    left = lay.pad / width
    right = 1.0 - (lay.pad + 6.0 * lay.font_px) / width  # room for the arrow on the right
    bottom = (height - lay.legend_top - 1.5 * lay.font_px) / height
    ax = fig.add_axes((left, bottom, max(right - left, 0.2), 1.3 * lay.font_px / height))
    ax.imshow(np.linspace(0.0, 1.0, len(ramp))[None, :], aspect="auto",
              cmap=ListedColormap(ramp), extent=(bar.vmin, bar.vmax, 0.0, 1.0),
              interpolation="nearest")
    ax.set_yticks([])
    ax.tick_params(labelsize=lay.font_pt * 0.9, length=3)
    ax.set_xlabel(bar.label, fontsize=lay.font_pt * 0.9, labelpad=2)


def _categories(fig, lay: _Layout, height: int, legend: Categories) -> None:
    """A row of swatches with their labels."""
    from matplotlib.patches import Rectangle
    from matplotlib.transforms import IdentityTransform

    px = IdentityTransform()
    x = float(lay.pad)
    y = height - lay.legend_top - 1.6 * lay.font_px
    size = 1.2 * lay.font_px
    for colour, label in legend.items:
        fig.add_artist(Rectangle((x, y), size, size, transform=px,
                                 facecolor=np.asarray(colour, float) / 255.0, edgecolor="0.3",
                                 lw=0.6))
        fig.text(x + size + 0.4 * lay.font_px, y + size / 2, label, transform=px, ha="left",
                 va="center", fontsize=lay.font_pt)
        x += size + (1.2 + 0.62 * len(label)) * lay.font_px  # ~0.6 em per character


def decorate_or_plain(rgb: np.ndarray, ctx: MapContext | None) -> np.ndarray:
    """The decorated picture, or ``rgb`` itself when ``ctx`` is None or matplotlib (the
    ``[plot]`` extra) is not installed."""
    from cityshade.plotting import have_matplotlib

    if ctx is None or not have_matplotlib():
        return rgb
    return decorate_map(rgb, ctx).image


@dataclass(frozen=True)
class Mark:
    """A place pointed at on a map: the pixel (col, row) it lies in, a label, a colour."""

    col: float
    row: float
    label: str = ""
    colour: str = "red"


def annotate_map(rgb: np.ndarray, marks: Sequence[Mark] = (),
                 outlines: Sequence[tuple[np.ndarray, str]] = ()) -> np.ndarray:
    """(H, W, 3) uint8: ``rgb`` with rings at ``marks`` (their labels beside them) and closed
    ``outlines`` ((N, 2) corners in pixel units from the map's top-left corner, (x right,
    y down), and a colour) drawn over it. Needs matplotlib."""
    from cityshade.plotting import agg_canvas, canvas_pixels

    rgb = np.asarray(rgb)
    h, w = rgb.shape[:2]
    fig, canvas = agg_canvas(w, h)
    fig.set_size_inches((w + 1e-3) / fig.dpi, (h + 1e-3) / fig.dpi)  # whole pixels
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.imshow(rgb, interpolation="nearest")
    ax.set_xlim(-0.5, w - 0.5)
    ax.set_ylim(h - 0.5, -0.5)
    ax.set_axis_off()
    font = max(7, min(12, w // 60))
    for corners, colour in outlines:
        c = np.asarray(corners, np.float64).reshape(-1, 2)
        c = np.vstack([c, c[:1]]) - 0.5  # pixel edges, not centres
        ax.plot(c[:, 0], c[:, 1], "-", color=colour, lw=2.0)
    for m in marks:
        ax.plot([m.col], [m.row], "o", ms=10, mfc="none", mec=m.colour, mew=1.5)
        if m.label:
            ax.annotate(m.label, (m.col, m.row), xytext=(6, 6), textcoords="offset points",
                        color=m.colour, fontsize=font, weight="bold")
    return canvas_pixels(canvas)[:h, :w]
