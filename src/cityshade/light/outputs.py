"""The files of a sky run (``cityshade sky``), written together (an output group: all or none).

- ``svf.exr`` (channels ``svf``, ``objid``), ``svf.tif`` (map views: GeoTIFF, float32, NaN
  nodata) and ``svf.png`` (viridis 0–1; a map view decorated with scale bar, north, CRS, title
  and colour bar, as batch's ``sun_hours.png``);
- with ``vsc`` ``vsc.exr`` (channel ``vsc_pct``: the vertical sky component, in percent, of
  every pixel ON ITS OWN PLANE: BRE 209's VSC on a wall, 100 % on open horizontal ground),
  ``.tif`` and ``.png`` (0–100 %);
- with a weather file ``irradiance_kwh_m2.exr`` (channels ``total``, ``direct``, ``diffuse``,
  ``reflected``, ``objid``), ``.tif`` (the total) and ``.png``;
- per instant ``irradiance_w_m2_<HHMM>.exr`` (the same channels in W/m²), ``.tif`` and ``.png``;
- with surfaces ``surfaces.csv`` (one row per sampled polygon: batch's first six columns, then
  the area-weighted means ``svf`` and ``irradiance_kwh_m2``, ``direct_kwh_m2``,
  ``diffuse_kwh_m2``, ``reflected_kwh_m2``, ``vsc_pct`` with ``vsc``, and
  ``irradiance_w_m2_<HHMM>`` per instant) and ``buildings.csv`` (per building: roof and wall
  areas, mean sky view factor of its roofs and of its walls, kWh/m² and kWh received by its
  roofs and walls).
"""
from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

import numpy as np

from cityshade import __version__

#: Per-polygon columns of ``surfaces.csv`` after batch's first six, and their formats.
IRRADIANCE_COLUMNS = ("irradiance_kwh_m2", "direct_kwh_m2", "diffuse_kwh_m2",
                      "reflected_kwh_m2")

#: Columns of ``buildings.csv``.
BUILDING_COLUMNS = ("building_id", "roof_area_m2", "wall_area_m2", "roof_svf", "wall_svf",
                    "roof_kwh_m2", "wall_kwh_m2", "roof_kwh", "wall_kwh")


def sky_metadata(scene, request, result) -> dict[str, Any]:
    """Provenance of a sky run's files (docs/DESIGN.md §15)."""
    header = scene.header or {}
    meta = {"cityshade:version": __version__, "cityshade:kind": "sky",
            "cityshade:sky": result.sky.name, "cityshade:sky_patches": result.sky.n,
            "cityshade:technique": request.technique,
            "cityshade:source_sha256": header.get("source", {}).get("sha256", ""),
            "cityshade:crs": scene.crs.name, "cityshade:crs_epsg": scene.crs.horizontal_epsg or 0,
            "cityshade:origin_m": " ".join(f"{v:.3f}" for v in scene.origin_m),
            "cityshade:params": json.dumps(dict(request.provenance or {}), sort_keys=True)}
    irr = result.irradiation
    if request.weather is not None:
        meta.update({"cityshade:weather": Path(request.weather.path).name,
                     "cityshade:sky_model": request.model, "cityshade:albedo": request.albedo})
    if result.instants_w_m2 is not None:
        meta["cityshade:instants"] = " ".join(t.isoformat() for t in request.instants)
    if irr is not None:
        meta.update({"cityshade:weather": Path(request.weather.path).name,
                     "cityshade:sky_model": irr.model, "cityshade:albedo": irr.albedo,
                     "cityshade:weather_hours": irr.hours})
    return meta


def _write_map(outdir: Path, name: str, channels: dict, scene, camera, meta, *, vmax: float,
               title: str, label: str) -> list[Path]:
    """``name.exr`` (every channel), ``name.tif`` (the first channel; map views) and
    ``name.png`` (the first, viridis from 0 to ``vmax``)."""
    from cityshade import imageio
    from cityshade.sunhours.outputs import colour_map_png, colour_mapped, map_picture

    attrs = {k: str(v) for k, v in meta.items()}
    first = next(iter(channels.values()))
    imageio.write_exr(outdir / f"{name}.exr", channels, meta)
    written = [outdir / f"{name}.exr"]
    rgb, vmax = colour_mapped(first, vmax)
    picture = map_picture(rgb, vmax, camera, scene, title=title, label=label)
    imageio.write_png_rgb(outdir / f"{name}.png",
                          colour_map_png(first, vmax) if picture is None else picture,
                          attributes=attrs)
    written.append(outdir / f"{name}.png")
    if camera.kind == "map":
        written += imageio.write_georeferenced(
            outdir / f"{name}.tif", first, camera.geotransform(scene.origin_m),
            epsg=scene.crs.horizontal_epsg, nodata=float("nan"), attributes=attrs)
    return written


def _maps(outdir: Path, scene, request, result, meta) -> list[Path]:
    written: list[Path] = []
    objid = scene.global_object_ids(np.asarray(result.cp.surfaces.obj_id))
    what = f"{result.sky.name} sky, {result.sky.n} patches"
    if request.svf:
        written += _write_map(outdir, "svf", {"svf": result.map_of(result.svf), "objid": objid},
                              scene, request.camera, meta, vmax=1.0,
                              title=f"Sky view factor ({what})", label="sky view factor")
    if result.vsc is not None:
        written += _write_map(outdir, "vsc", {"vsc_pct": result.map_of(100.0 * result.vsc),
                                              "objid": objid},
                              scene, request.camera, meta, vmax=100.0,
                              title=f"Vertical sky component on each surface's plane, CIE "
                                    f"overcast sky ({what})", label="VSC %")
    irr = result.irradiation
    if irr is not None:
        channels = {"total": result.map_of(irr.total_kwh_m2)}
        for c in ("direct", "diffuse", "reflected"):
            channels[c] = result.map_of(getattr(irr, f"{c}_kwh_m2"))
        channels["objid"] = objid
        finite = channels["total"][np.isfinite(channels["total"])]
        top = float(np.ceil(finite.max() / 100.0) * 100.0) if finite.size else 1.0
        written += _write_map(outdir, "irradiance_kwh_m2", channels, scene, request.camera,
                              meta, vmax=max(top, 1.0),
                              title=f"Irradiation, {Path(request.weather.path).name}, "
                                    f"{irr.hours} h ({irr.model})", label="kWh/m²")
    for name, when, w in _instants(request, result):
        channels = {"total": result.map_of(w.sum(axis=1))}
        for c, col in zip(("direct", "diffuse", "reflected"), w.T):
            channels[c] = result.map_of(col)
        channels["objid"] = objid
        finite = channels["total"][np.isfinite(channels["total"])]
        top = float(np.ceil(finite.max() / 100.0) * 100.0) if finite.size else 1.0
        written += _write_map(outdir, name, channels, scene, request.camera, meta,
                              vmax=max(top, 100.0),
                              title=f"Irradiance {when}, {Path(request.weather.path).name} "
                                    f"({request.model})", label="W/m²")
    return written


def _instants(request, result):
    """(name, local time text, (N, 3) W/m²) of every instant: ``irradiance_w_m2_<HHMM>``."""
    if result.instants_w_m2 is None:
        return []
    return [(f"irradiance_w_m2_{label}", t.strftime("%Y-%m-%d %H:%M %Z"), w)
            for label, t, w in zip(request.instant_labels, request.instants,
                                   result.instants_w_m2)]


def polygon_values(result, request) -> dict[str, np.ndarray]:
    """Area-weighted means per polygon (P,) of the samples' values, by column name."""
    from cityshade.sunhours.surfaces import polygon_means

    samples = result.samples
    values = {}
    if request.svf:
        values["svf"] = polygon_means(samples, result.sample_values(result.svf))
    if result.vsc is not None:
        values["vsc_pct"] = polygon_means(samples, 100.0 * result.sample_values(result.vsc))
    irr = result.irradiation
    if irr is not None:
        for name, v in zip(IRRADIANCE_COLUMNS, (irr.total_kwh_m2, irr.direct_kwh_m2,
                                                irr.diffuse_kwh_m2, irr.reflected_kwh_m2)):
            values[name] = polygon_means(samples, result.sample_values(v))
    for name, _, w in _instants(request, result):
        values[name] = polygon_means(samples, result.sample_values(w.sum(axis=1)))
    return values


def write_surfaces_csv(path: Path, scene, samples, values: dict[str, np.ndarray]) -> Path:
    """One row per sampled polygon: batch's first six columns, then ``values``."""
    from cityshade.sunhours.surfaces import CSV_COLUMNS, polygon_rows
    from cityshade.util import atomic_write

    with atomic_write(path, newline="", what="the surface table") as fh:
        writer = csv.writer(fh)
        writer.writerow([*CSV_COLUMNS[:6], *values])
        for row in polygon_rows(scene, samples):
            writer.writerow([*row[:4], f"{row[4]:.3f}", row[5],
                             *(f"{v[row[2]]:.4f}" for v in values.values())])
    return path


def _area_mean(values: np.ndarray, area: np.ndarray, mask: np.ndarray) -> float:
    a = float(area[mask].sum())
    return float((values[mask] * area[mask]).sum() / a) if a > 0 else float("nan")


def building_totals(scene, samples, values: dict[str, np.ndarray]) -> list[tuple]:
    """Rows of ``buildings.csv`` (:data:`BUILDING_COLUMNS`): per top-level object with a
    sampled roof or wall, areas, area-weighted means and the kWh its roofs and walls receive."""
    from cityshade.citygml.namespaces import SURFACE_CODE
    from cityshade.geometry.scene import root_objects

    polys = np.flatnonzero(samples.sampled)
    cls = np.asarray(scene.poly_class)[polys]
    area = np.asarray(scene.poly_area_m2, np.float64)[polys]
    root = root_objects(scene.obj_parent)[np.asarray(scene.poly_object, np.int64)[polys]]
    svf = values.get("svf", np.full(len(scene.poly_ids), np.nan))[polys]
    kwh = values.get("irradiance_kwh_m2", np.full(len(scene.poly_ids), np.nan))[polys]
    rows = []
    for b in np.unique(root):
        parts = []
        for code in (SURFACE_CODE["roof"], SURFACE_CODE["wall"]):
            m = (root == b) & (cls == code)
            a = float(area[m].sum())
            parts.append((a, _area_mean(svf, area, m), _area_mean(kwh, area, m),
                          float((kwh[m] * area[m]).sum())))
        (ra, rs, rk, rt), (wa, ws, wk, wt) = parts
        if ra + wa > 0:
            rows.append((scene.obj_ids[int(b)], ra, wa, rs, ws, rk, wk, rt, wt))
    return rows


def write_buildings_csv(path: Path, rows: list[tuple], values: dict[str, np.ndarray]) -> Path:
    """``buildings.csv``: the columns of what was computed (the view factors with ``svf`` in
    ``values``, the kWh with ``irradiance_kwh_m2``)."""
    from cityshade.util import atomic_write

    keep = [0, 1, 2] + ([3, 4] if "svf" in values else []) \
        + ([5, 6, 7, 8] if "irradiance_kwh_m2" in values else [])
    fmt = {1: ".3f", 2: ".3f", 3: ".4f", 4: ".4f", 5: ".2f", 6: ".2f", 7: ".1f", 8: ".1f"}
    with atomic_write(path, newline="", what="the building table") as fh:
        writer = csv.writer(fh)
        writer.writerow([BUILDING_COLUMNS[k] for k in keep])
        for r in rows:
            writer.writerow([r[0], *(format(r[k], fmt[k]) for k in keep[1:])])
    return path


def _gis(outdir: Path, scene, samples, values: dict[str, np.ndarray]) -> list[Path]:
    """``results.gpkg`` (+ GeoJSON): the surfaces with their columns, the buildings with the
    area-weighted means of theirs (:mod:`cityshade.present.gis`)."""
    from cityshade.present.gis import building_layer, surface_layer, write_gis
    from cityshade.sunhours.surfaces import CSV_COLUMNS, polygon_rows

    polys = np.flatnonzero(samples.sampled)     # polygon_rows' order
    rows = list(polygon_rows(scene, samples))
    # surfaces.csv's columns: its first six (ids, class, area, samples), then the values.
    ids = {name: [r[i] for r in rows] for i, name in enumerate(CSV_COLUMNS[:6])}
    values = {name: v[polys] for name, v in values.items()}
    layers = [surface_layer(scene, polys, {**ids, **values})]
    if len(polys):
        layers.append(building_layer(scene, polys, values))
    return write_gis(outdir, layers, scene.crs)


def write_sky_outputs(outdir: Path, scene, request, result) -> list[Path]:
    """Every file of the run, in one output group; returns the paths written."""
    from cityshade.light.report import sky_report_markdown
    from cityshade.present.html import write_report_html
    from cityshade.util import output_group

    meta = sky_metadata(scene, request, result)
    written: list[Path] = []
    values = buildings = None
    with output_group():
        if result.cp is not None:
            written += _maps(outdir, scene, request, result, meta)
        if result.samples is not None:
            values = polygon_values(result, request)
            buildings = building_totals(scene, result.samples, values)
            written.append(write_surfaces_csv(outdir / "surfaces.csv", scene, result.samples,
                                              values))
            written.append(write_buildings_csv(outdir / "buildings.csv", buildings, values))
            if request.gis and not scene.is_tiled:
                written += _gis(outdir, scene, result.samples, values)
        text = sky_report_markdown(scene, request, result, written, values, buildings)
        written.append(write_report_html(outdir / "report.html", text, title="Sky and light"))
    return written
