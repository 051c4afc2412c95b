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

__all__ = ["colour_map_png", "legend_band", "run_metadata", "write_sun_hours",
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


def _colours(t: np.ndarray) -> np.ndarray:
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
    hours = np.asarray(hours, dtype=np.float64)
    if hours.ndim != 2:
        raise UsageError(f"hours must be (H, W), not {hours.shape}")
    if vmax_h is None:
        finite = hours[np.isfinite(hours)]
        vmax_h = max(1.0, math.ceil(float(finite.max()) if finite.size else 1.0))
    h, w = hours.shape
    width = max(w, 64)
    rgb = _colours(np.nan_to_num(hours / vmax_h, nan=0.0))
    rgb[~np.isfinite(hours)] = _NODATA_RGB
    band = legend_band(width, float(vmax_h))
    img = np.full((h + (0 if band is None else band.shape[0]), width, 3), 255, np.uint8)
    img[:h, :w] = rgb
    if band is not None:
        img[h:] = band
    return img


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
    ramp = _colours(np.linspace(0.0, 1.0, 256)) / 255.0
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


def write_sun_hours(outdir, result, scene, camera, meta: dict[str, Any],
                    surfaces_csv: bool = False, cog: bool = False) -> list[Path]:
    """Write ``sun_hours.exr`` (channels ``sun_hours``, ``objid``), ``sun_hours.png``
    (colour-mapped, legend), for map views ``sun_hours.tif`` (+ .tfw, .prj; float32, NaN
    nodata; with ``cog`` a Cloud-Optimized GeoTIFF written by GDAL), and with ``surfaces_csv``
    ``surfaces.csv``. Returns the paths written."""
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
        imageio.write_png_rgb(png, colour_map_png(result.hours),
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

