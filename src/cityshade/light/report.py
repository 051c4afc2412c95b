"""``report.html`` of a sky run: what was computed, on what, the maps, and the per-surface and
per-building answers summed up, as one self-contained page (:mod:`cityshade.present.html`),
like a batch's and a comparison's."""
from __future__ import annotations

import datetime as dt
from pathlib import Path

import numpy as np

#: Buildings listed in the report (the most irradiated roofs); every one is in buildings.csv.
REPORT_BUILDINGS = 10


def _what(request, result) -> str:
    parts = []
    if request.svf:
        parts.append("sky view factor")
    if result.vsc is not None:
        parts.append("vertical sky component")
    if result.irradiation is not None:
        parts.append("irradiation")
    if result.instants_w_m2 is not None:
        parts.append("irradiance at instants")
    text = ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1]
    return text[0].upper() + text[1:]


def _receivers(request, result) -> str:
    parts = []
    if result.cp is not None:
        cam = request.camera
        view = (f"a map at {cam.pixel_size_m:g} m per pixel" if cam.kind == "map"
                else f"a {cam.kind} view")
        parts.append(f"{result.n_pixels:,} surface pixels of {view} "
                     f"({result.shape[1]} × {result.shape[0]} px)")
    if result.samples is not None:
        n = int(np.count_nonzero(result.samples.sampled))
        parts.append(f"{n:,} surfaces sampled at {request.samples_per_m2:g} point(s) per m² "
                     f"({len(result.samples.polygon):,} points)")
    return " and ".join(parts)


def _weather_lines(scene, request, result) -> list[str]:
    from cityshade.light.weather import distance_km

    wx = request.weather
    loc = wx.location
    lines = ["## Weather", "",
             f"`{Path(wx.path).name}` ({wx.kind.upper()}, {wx.n_hours:,} hours), recorded at "
             f"{loc.name} ({loc.latitude_deg:.4f}° N, {loc.longitude_deg:.4f}° E)"]
    from cityshade.errors import CRSError
    from cityshade.geo.sun import model_place

    try:
        lat, lon, _ = model_place(scene.crs, scene.origin_m)
        lines[-1] += f", {distance_km(loc, lat, lon):,.0f} km from the model"
    except CRSError:
        pass  # a model without a place on Earth has no distance to state
    lines[-1] += "."
    irr = result.irradiation
    if irr is not None:
        hours = np.ones(wx.n_hours, bool) if request.hours is None else np.asarray(request.hours)
        ghi = float(np.nansum(np.asarray(wx.ghi_w_m2)[hours])) / 1000.0
        params = request.provenance or {}
        first, last = params.get("from_date"), params.get("to_date")
        period = (f"from {first or 'the first day of the file'} to {last or 'its last day'}"
                  if first or last else "of the whole file")
        lines += ["", f"Irradiation summed over the {irr.hours:,} hours with light {period} "
                  f"({irr.sun_hours_traced:,} suns traced), sky model `{irr.model}`, ground "
                  f"albedo {irr.albedo:g}. An unobstructed horizontal plane receives "
                  f"**{ghi:,.0f} kWh/m²** over these hours (the file's global horizontal "
                  f"irradiance): the anchor for the values below."]
    lines += ["", "The sky visibility of every receiver is exact for each direction traced; "
              "the irradiance inherits the weather file's and the sky model's uncertainty "
              "(hourly diffuse splits and transpositions are good to about ±15–20 %, a few "
              "percent over a year), and the ground reflection ignores the city's own.", ""]
    return lines


def _maps(written: list[Path]) -> list[str]:
    captions = {"svf": "Sky view factor (0–1) of each surface pixel, on its own plane.",
                "vsc": "Vertical sky component (%) of each surface pixel on its own plane "
                       "(CIE overcast sky; BRE 209's VSC on walls, 100 % on open ground).",
                "irradiance_kwh_m2": "Irradiation (kWh/m²) over the weather hours: direct, "
                                     "sky diffuse and ground-reflected."}
    lines: list[str] = []
    for p in written:
        if p.suffix != ".png":
            continue
        caption = captions.get(p.stem, "Irradiance (W/m²) at the instant in the title.")
        lines += [f"![{p.stem}]({p.name})", "", caption + f" Values: `{p.stem}.exr`"
                  + (f", `{p.stem}.tif`" if p.with_suffix(".tif") in written else "") + ".", ""]
    return ["## Maps", "", *lines] if lines else []


def _surface_lines(scene, result, values: dict[str, np.ndarray], gis: bool) -> list[str]:
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    polys = np.flatnonzero(result.samples.sampled)
    if not len(polys):
        return ["## Surfaces", "", "No surface was sampled.", ""]
    cls = np.asarray(scene.poly_class)[polys]
    area = np.asarray(scene.poly_area_m2, np.float64)[polys]
    cols = [(name, head, fmt) for name, head, fmt in
            (("svf", "mean SVF", ".3f"), ("vsc_pct", "mean VSC %", ".1f"),
             ("irradiance_kwh_m2", "mean kWh/m²", ",.0f")) if name in values]
    energy = "irradiance_kwh_m2" in values
    lines = ["## Surfaces", "",
             f"{len(polys):,} surfaces; per class the area-weighted mean of the surfaces' means"
             + (" and the energy they receive" if energy else "") + ". Every surface: "
             "`surfaces.csv`" + (", and as GIS layers `results.gpkg`" if gis else "") + ".", "",
             "| class | surfaces | area m² | " + " | ".join(h for _, h, _ in cols)
             + (" | MWh |" if energy else " |"),
             "|---|---:|---:|" + "---:|" * (len(cols) + energy)]
    order = sorted(np.unique(cls), key=lambda c: -area[cls == c].sum())
    for c in order:
        m = cls == c
        a = float(area[m].sum())
        name = SURFACE_CLASSES[int(c)] if int(c) < len(SURFACE_CLASSES) else str(c)
        row = [name, f"{int(m.sum()):,}", f"{a:,.0f}"]
        for key, _, fmt in cols:
            v = values[key][polys][m]
            row.append(format(float((v * area[m]).sum() / a), fmt) if a > 0 else "–")
        if energy:
            row.append(f"{float((values['irradiance_kwh_m2'][polys][m] * area[m]).sum()) / 1000:,.1f}")
        lines.append("| " + " | ".join(row) + " |")
    return lines + [""]


def _building_lines(rows: list[tuple], energy: bool) -> list[str]:
    if not rows:
        return []
    lines = ["## Buildings", "", f"{len(rows):,} buildings with sampled roofs or walls "
             "(`buildings.csv`: areas, mean sky view factor"
             + (", kWh/m² and kWh" if energy else "") + " of roofs and walls)."]
    if not energy:
        return lines + [""]
    top = sorted(rows, key=lambda r: -r[7])[:REPORT_BUILDINGS]
    lines += [f" The {len(top)} whose roofs receive the most energy:", "",
              "| building | roof m² | roof kWh/m² | roof MWh | wall m² | wall kWh/m² | wall MWh |",
              "|---|---:|---:|---:|---:|---:|---:|"]
    for r in top:
        wall = (f"{r[6]:,.0f}", f"{r[8] / 1000:,.1f}") if r[2] > 0 else ("–", "–")
        roof = (f"{r[5]:,.0f}", f"{r[7] / 1000:,.1f}") if r[1] > 0 else ("–", "–")
        lines.append(f"| `{r[0]}` | {r[1]:,.0f} | {roof[0]} | {roof[1]} | {r[2]:,.0f} | "
                     f"{wall[0]} | {wall[1]} |")
    return lines + [""]


def sky_report_markdown(scene, request, result, written: list[Path],
                        values: dict[str, np.ndarray] | None = None,
                        buildings: list[tuple] | None = None) -> str:
    """The text of a sky run's ``report.html``: what was computed on what (model, CRS, city
    state, directions, engine, receivers), the weather with its anchor (an open horizontal
    plane's kWh/m²), the maps of ``written``, the surfaces per class (``values``:
    :func:`cityshade.light.outputs.polygon_values`) and the buildings (``buildings``:
    :func:`cityshade.light.outputs.building_totals`), and the run's warnings."""
    from cityshade.geometry.vegetation import scene_vegetation

    params = dict(request.provenance or {})
    state = (dt.date(1970, 1, 1) + dt.timedelta(days=float(request.t_days))).isoformat()
    lines = [f"# {_what(request, result)}", "",
             f"Model `{params.get('file', '')}` ({scene.crs.name}), the city as of {state}. "
             f"{_receivers(request, result).capitalize()}; {result.sky.n:,} sky directions "
             f"(`{result.sky.name}`), traced by the exact engine of `{request.technique}` "
             f"(`{request.engine}`)" + (f"; deciduous crowns {request.season.replace('_', '-')}"
                                       if (request.svf or request.vsc)
                                       and scene_vegetation(scene) is not None else "")
             + ".", ""]
    if request.weather is not None:
        lines += _weather_lines(scene, request, result)
    lines += _maps(written)
    if result.samples is not None and values is not None:
        gis = any(p.name == "results.gpkg" for p in written)
        lines += _surface_lines(scene, result, values, gis)
        lines += _building_lines(buildings or [], "irradiance_kwh_m2" in values)
    for warning in result.warnings:
        lines += [f"> Warning: {warning}", ""]
    return "\n".join(lines)
