"""Outputs of a sun-hours run: the colour map and its legend, the provenance, and the writers
(EXR, colour-mapped PNG, georeferenced float raster or COG, surfaces.csv, per-month files,
frames)."""
from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from cityshade import __version__
from cityshade.errors import UsageError

__all__ = ["batch_layers", "batch_report_markdown", "batch_title", "colour_map_png",
           "colour_mapped", "viridis_ramp", "map_picture", "legend_band", "run_metadata", "write_sun_hours",
           "write_tiled_extras", "frame_name"]


def frame_name(step) -> str:
    """File name of a step's shadow mask in ``OUTDIR/frames``."""
    return f"step_{step.index:05d}_{step.centre_utc.strftime('%Y%m%dT%H%M%SZ')}.png"


#: Anchors of the viridis colour map (perceptually uniform, readable in grey and by the
#: colour-blind), at 0, 1/4, 1/2, 3/4 and 1; linear in between.
_VIRIDIS = np.array([(68, 1, 84), (59, 82, 139), (33, 145, 140), (94, 201, 98),
                     (253, 231, 37)], dtype=np.float64)
#: Colour of pixels without a surface in the PNG (white: most map pixels of a model without
#: terrain are empty, docs/DESIGN.md §15).
_NODATA_RGB = (255, 255, 255)


def viridis_rgb(t: np.ndarray) -> np.ndarray:
    """(…) values in [0, 1] → (…, 3) uint8 viridis."""
    x = np.clip(t, 0.0, 1.0) * (len(_VIRIDIS) - 1)
    i = np.minimum(np.floor(x).astype(np.int64), len(_VIRIDIS) - 2)
    f = (x - i)[..., None]
    return np.rint(_VIRIDIS[i] * (1.0 - f) + _VIRIDIS[i + 1] * f).astype(np.uint8)


def _label(hours: float) -> str:
    return (f"{hours:.0f}" if hours == round(hours) else f"{hours:.1f}") + " h"


def colour_map_png(hours: np.ndarray, vmax_h: float | None = None) -> np.ndarray:
    """Colour-mapped sun-hours with a legend below the map.

    Parameters
    ----------
    hours : (H, W) float
        Sun-hours; NaN = no surface (white).
    vmax_h : float, optional
        Hours at the top of the scale (default: the largest value, at least 1 h, rounded up
        to a whole hour).

    Returns
    -------
    (H + legend, max(W, 64), 3) uint8
        Map on top, then the legend band drawn by matplotlib (:func:`legend_band`): a colour
        bar from 0 to ``vmax_h`` with labels at 0, the middle and the top. Without matplotlib
        (the ``[plot]`` extra) the band is left out.
    """
    rgb, vmax_h = colour_mapped(hours, vmax_h)
    h, w = rgb.shape[:2]
    width = max(w, 64)
    band = legend_band(width, float(vmax_h))
    img = np.full((h + (0 if band is None else band.shape[0]), width, 3), 255, np.uint8)
    img[:h, :w] = rgb
    if band is not None:
        img[h:] = band
    return img


def colour_mapped(hours: np.ndarray, vmax_h: float | None = None) -> tuple[np.ndarray, float]:
    """((H, W, 3) uint8 viridis picture of ``hours``, NaN white; the top of its scale in hours:
    ``vmax_h`` or the largest value, at least 1 h, rounded up to a whole hour)."""
    hours = np.asarray(hours, dtype=np.float64)
    if hours.ndim != 2:
        raise UsageError(f"hours must be (H, W), not {hours.shape}")
    if vmax_h is None:
        finite = hours[np.isfinite(hours)]
        vmax_h = max(1.0, math.ceil(float(finite.max()) if finite.size else 1.0))
    rgb = viridis_rgb(np.nan_to_num(hours / vmax_h, nan=0.0))
    rgb[~np.isfinite(hours)] = _NODATA_RGB
    return rgb, float(vmax_h)


def viridis_ramp(n: int = 256) -> np.ndarray:
    """(n, 3) uint8: the colours of :func:`colour_mapped` from 0 to the top of the scale."""
    return viridis_rgb(np.linspace(0.0, 1.0, n))


def map_picture(rgb: np.ndarray, vmax_h: float, camera, scene, *, title: str | None = None,
                label: str = "sun-hours (h)") -> np.ndarray | None:
    """A colour-mapped map view decorated for people (:func:`cityshade.present.maps.decorate_map`:
    scale bar, north, CRS, title, a colour bar from 0 to ``vmax_h`` labelled ``label``); None
    for a perspective view or without matplotlib (the caller writes the plain picture)."""
    from cityshade.plotting import have_matplotlib

    if camera is None or camera.kind != "map" or not have_matplotlib():
        return None
    from cityshade.present.maps import ColourBar, MapContext, decorate_map

    ctx = MapContext(camera.geotransform(scene.origin_m), scene.crs, title,
                     ColourBar(viridis_ramp(), 0.0, float(vmax_h), label))
    return decorate_map(rgb, ctx).image


def legend_band(width_px: int, vmax_h: float) -> np.ndarray | None:
    """(B, width_px, 3) uint8: the viridis bar from 0 to ``vmax_h`` hours with labels at 0,
    the middle and the top, drawn by matplotlib; None without it."""
    from cityshade.plotting import agg_canvas, canvas_pixels, have_matplotlib

    if not have_matplotlib():
        return None
    from matplotlib.colors import ListedColormap

    # Legend size follows the picture: text of ~1/40 of the width, within 7–14 pt.
    font_pt = float(np.clip(width_px / 40.0, 7.0, 14.0))
    fig, canvas = agg_canvas(width_px, int(round(4.5 * font_pt * 100 / 72)))
    ax = fig.add_axes((0.06, 0.55, 0.88, 0.35))
    ramp = viridis_rgb(np.linspace(0.0, 1.0, 256)) / 255.0
    ax.imshow(np.linspace(0.0, 1.0, 256)[None, :], aspect="auto", cmap=ListedColormap(ramp),
              extent=(0.0, vmax_h, 0.0, 1.0), interpolation="nearest")
    ax.set_yticks([])
    ax.set_xticks([0.0, vmax_h / 2.0, vmax_h],
                  [_label(v) for v in (0.0, vmax_h / 2.0, vmax_h)], fontsize=font_pt)
    return canvas_pixels(canvas)


def run_metadata(result, scene, params: dict[str, Any]) -> dict[str, Any]:
    """Provenance of a batch's outputs (docs/DESIGN.md §15)."""
    header = scene.header or {}
    suns = [s for s in result.suns if s.instant_utc is not None]
    meta = {
        "cityshade:version": __version__,
        "cityshade:kind": "sun-hours",
        "cityshade:units": "hours",
        "cityshade:steps": result.steps,
        "cityshade:steps_below_horizon": result.steps_below_horizon,
        "cityshade:sun_positions_computed": result.units,
        "cityshade:hours_total": result.hours_total,
        "cityshade:hours_sun_up": result.hours_sun_up,
        "cityshade:source_sha256": header.get("source", {}).get("sha256", ""),
        "cityshade:crs": scene.crs.name,
        "cityshade:crs_epsg": scene.crs.horizontal_epsg or 0,
        "cityshade:origin_m": " ".join(f"{v:.3f}" for v in scene.origin_m),
        "cityshade:params": json.dumps(params, sort_keys=True),
    }
    if suns:
        meta["cityshade:sun_source"] = suns[0].source
        meta["cityshade:first_instant_utc"] = suns[0].instant_utc
        meta["cityshade:last_instant_utc"] = suns[-1].instant_utc
        meta["cityshade:delta_t_s"] = float(suns[0].delta_t_s)
        meta["cityshade:refraction"] = "on" if suns[0].refraction else "off"
    return meta


def batch_title(meta: dict[str, Any]) -> str:
    """The title of a batch's map: its days and hours, from the run's provenance."""
    params = json.loads(meta.get("cityshade:params", "{}"))
    days = params.get("date", "")
    if params.get("to_date"):
        days += f" to {params['to_date']}"
    elif (params.get("days") or 1) > 1:
        days += f", {params['days']} days"
    return (f"Sun-hours, {days}, {params.get('from', '')}–{params.get('to', '')} "
            f"({params.get('tz', '')})")


def write_sun_hours(outdir, result, scene, camera, meta: dict[str, Any],
                    surfaces_csv: bool = False, cog: bool = False,
                    decorate: bool = True) -> list[Path]:
    """Write ``sun_hours.exr`` (channels ``sun_hours``, ``objid``), ``sun_hours.png``
    (colour-mapped; a map view ``decorate``-d with scale bar, north, CRS, title and colour bar
    (:func:`map_picture`), else with a legend band), for map views ``sun_hours.tif`` (+ .tfw,
    .prj; float32, NaN nodata; with ``cog`` a Cloud-Optimized GeoTIFF written by GDAL), and
    with ``surfaces_csv`` ``surfaces.csv``. Returns the paths written."""
    from cityshade import imageio

    outdir = Path(outdir)
    written: list[Path] = []
    if result.hours is not None:
        exr = outdir / "sun_hours.exr"
        channels = {"sun_hours": result.hours, "objid": np.asarray(result.surfaces.obj_id)}
        channels["objid"] = scene.global_object_ids(channels["objid"])  # a tiled view's: global
        if result.stretches is not None:
            # Longest continuous sunlit stretch per pixel (NaN where no surface).
            channels["longest_sun_h"] = np.where(result.valid, result.stretches.pixel_longest_h(),
                                                 np.nan).astype(np.float32)
        imageio.write_exr(exr, channels, meta)
        written.append(exr)
        png = outdir / "sun_hours.png"
        rgb, vmax_h = colour_mapped(result.hours)
        picture = map_picture(rgb, vmax_h, camera, scene, title=batch_title(meta)) \
            if decorate else None
        imageio.write_png_rgb(png, colour_map_png(result.hours) if picture is None else picture,
                              attributes={k: str(v) for k, v in meta.items()})
        written.append(png)
        if camera.kind == "map" and cog:
            written += imageio.write_cog(
                outdir / "sun_hours.tif", result.hours, camera.geotransform(scene.origin_m),
                epsg=scene.crs.horizontal_epsg, nodata=float("nan"),
                attributes={k: str(v) for k, v in meta.items()})
        elif camera.kind == "map":
            written += imageio.write_georeferenced(
                outdir / "sun_hours.tif", result.hours, camera.geotransform(scene.origin_m),
                epsg=scene.crs.horizontal_epsg, nodata=float("nan"),
                attributes={k: str(v) for k, v in meta.items()})
    if surfaces_csv and result.samples is not None:
        from cityshade.sunhours.surfaces import write_surface_csv

        written.append(write_surface_csv(outdir / "surfaces.csv", scene, result.samples,
                                         result.polygon_hours))
    return written



def write_tiled_extras(outdir, run, result, scene, camera, meta: dict[str, Any]) -> list[Path]:
    """Per-month outputs of a ``--monthly`` run: ``monthly/sun_hours_YYYY-MM.exr`` (and
    ``.tif``, a COG, for a map view; ``surfaces_YYYY-MM.csv`` with ``--surfaces``)."""
    from cityshade import imageio

    written: list[Path] = []
    months = sorted(set(run.month_hours) | set(run.month_sample_hours))
    if not months:
        return written
    from cityshade.util import make_folder

    folder = make_folder(Path(outdir) / "monthly")
    for month in months:
        attrs = {**meta, "cityshade:month": month}
        hours = run.month_hours.get(month)
        if hours is not None:
            exr = folder / f"sun_hours_{month}.exr"
            imageio.write_exr(exr, {"sun_hours": hours,
                                    "objid": np.asarray(result.surfaces.obj_id)}, attrs)
            written.append(exr)
            if camera.kind == "map":
                written += imageio.write_cog(folder / f"sun_hours_{month}.tif", hours,
                                             camera.geotransform(scene.origin_m),
                                             epsg=scene.crs.horizontal_epsg,
                                             nodata=float("nan"),
                                             attributes={k: str(v) for k, v in attrs.items()})
        poly = run.month_sample_hours.get(month)
        if poly is not None:
            from cityshade.sunhours.surfaces import write_surface_csv

            written.append(write_surface_csv(folder / f"surfaces_{month}.csv", scene,
                                             result.samples, poly))
    return written



def batch_layers(result, scene) -> list:
    """The GIS layers of a batch with per-surface sun-hours (:mod:`cityshade.present.gis`):
    ``surfaces`` (the rows of ``surfaces.csv``, each polygon's outline) and ``buildings``
    (footprints, area-weighted mean and largest mean sun-hours of their surfaces)."""
    from cityshade.present.gis import building_layer, surface_layer
    from cityshade.sunhours.surfaces import CSV_COLUMNS, surface_rows

    rows = list(surface_rows(scene, result.samples, result.polygon_hours))
    columns = {name: [r[i] for r in rows] for i, name in enumerate(CSV_COLUMNS)}
    polygons = columns["polygon_index"]
    layers = [surface_layer(scene, polygons, columns)]
    if rows:
        hours = np.asarray(columns["mean_sun_hours"], np.float64)
        layers.append(building_layer(scene, polygons, {"mean_sun_hours": hours},
                                     {"max_sun_hours": hours}))
    return layers


def batch_report_markdown(result, scene, meta: dict[str, Any], png: str | None,
                          georeferenced: bool = False, gis: bool = False) -> str:
    """A short report of a batch: what was computed, the map, and the per-surface sun-hours
    summed up per surface class (``report.html``'s text)."""
    from cityshade.sunhours.surfaces import surface_rows

    params = json.loads(meta.get("cityshade:params", "{}"))
    lines = [f"# {batch_title(meta)}", "",
             f"Model `{params.get('file', '')}` ({meta.get('cityshade:crs', '')}); "
             f"{result.steps} steps, {result.steps_below_horizon} with the sun down, "
             f"{result.hours_sun_up:.2f} h with the sun up; shadows "
             f"`{params.get('technique', '')}`.", ""]
    if png is not None:
        lines += ["## Map", "", f"![sun-hours]({png})", "",
                  "Sun-hours per pixel (white: no surface). Rasters: `sun_hours.exr`"
                  + (", `sun_hours.tif` (georeferenced)" if georeferenced else "") + ".", ""]
    if result.samples is not None and result.polygon_hours is not None:
        rows = list(surface_rows(scene, result.samples, result.polygon_hours))
        by_class: dict[str, list] = {}
        for r in rows:
            by_class.setdefault(str(r[3]), []).append(r)
        lines += ["## Surfaces", "", f"{len(rows)} surfaces with sample points; sun-hours per "
                  "class (area-weighted mean of the surfaces' means). Every surface: "
                  "`surfaces.csv`" + (", and as GIS layers `results.gpkg`" if gis else "")
                  + ".", "",
                  "| class | surfaces | area m² | mean h | least h | most h |",
                  "|---|---:|---:|---:|---:|---:|"]
        for cls, rs in sorted(by_class.items(), key=lambda kv: -sum(r[4] for r in kv[1])):
            area = np.array([r[4] for r in rs])
            hours = np.array([r[6] for r in rs])
            mean = float((area * hours).sum() / area.sum()) if area.sum() > 0 else float("nan")
            lines.append(f"| {cls} | {len(rs)} | {area.sum():.0f} | {mean:.2f} | "
                         f"{hours.min():.2f} | {hours.max():.2f} |")
        lines.append("")
    for warning in result.warnings:
        lines += [f"> Warning: {warning}", ""]
    return "\n".join(lines)
