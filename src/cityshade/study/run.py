"""One call for a shadow study: :func:`run_study` takes a :class:`~cityshade.study.request.
StudyRequest` and writes, together or not at all (:func:`cityshade.util.output_group`):

- ``study.pdf``: one A3 page per day (:func:`cityshade.study.sheet.draw_sheet`);
- ``sheet_<day>.png``: the same pages as pictures;
- ``panels/<day>_<HHMM>_before.tif`` and ``_after.tif``: each panel's shadow masks as
  georeferenced GeoTIFFs (+ world file and ``.prj``), the values of ``render --mask``;
- ``study.json`` and ``study.csv``: every panel's time, sun and shadow areas.

The city does not change during a study, so each state has one camera pass; each sun is a
shadow pass on both (:mod:`cityshade.study.panels`). Days are drawn and written one after the
other: a day's panels are dropped once its sheet is drawn.
"""
from __future__ import annotations

import csv
import io
import itertools
import json
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from cityshade import __version__

__all__ = ["INDEX_COLUMNS", "StudyResult", "run_study"]

#: Columns of ``study.csv`` (and keys of ``study.json``'s panels).
INDEX_COLUMNS = ("day", "time", "utc", "sun_azimuth_deg", "sun_elevation_deg",
                 "shadow_before_m2", "shadow_after_m2", "new_shadow_m2",
                 "shadow_gone_m2", "tree_shade_m2", "new_tree_shade_m2", "before_tif",
                 "after_tif")


@dataclass
class StudyResult:
    """What :func:`run_study` returns: the index rows (one per panel), the sheets' layout
    (:class:`cityshade.study.sheet.SheetInfo`, one per day), the files written, warnings."""

    rows: list = field(default_factory=list)
    sheets: list = field(default_factory=list)
    written: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    scene: Any = None
    camera: Any = None


def _is_path(value) -> bool:
    return isinstance(value, (str, os.PathLike))


def _open(request):
    """(scene before, scene after, city days before, after): the model opened or built, the
    proposal added."""
    from cityshade.build import load_or_build_scene
    from cityshade.planning.compare import merge_scenes
    from cityshade.planning.run import load_proposal

    before, after = request.states.dates(request.times.days[0])
    scene = (load_or_build_scene(request.scene, request.settings) if _is_path(request.scene)
             else request.scene)
    scene_after = scene
    if request.states.proposal is not None:
        proposal = load_proposal(request.states.proposal, request.settings, scene,
                                 request.states.mesh)
        scene_after = merge_scenes(scene, proposal, request.settings)
    return scene, scene_after, before.city_days, after.city_days


def run_study(request, *, on_panel: Callable[[int, int], None] | None = None) -> StudyResult:
    """Compute and write a shadow study (nothing written without ``request.outdir``).

    Parameters
    ----------
    request : cityshade.study.request.StudyRequest
    on_panel : callable(done, total), optional
        Progress over the panels.

    Raises
    ------
    UsageError
        A bad date, a proposal in another CRS, a map too large for memory.
    OutputError
        The output folder cannot be written.
    """
    from cityshade.frame.pipeline import check_frame_memory
    from cityshade.geo.sun import suns_from_instants
    from cityshade.shadows import get_technique
    from cityshade.study.panels import make_panel, study_camera, study_view
    from cityshade.study.request import DEFAULT_MAP_SIDE_PX
    from cityshade.util import check_outputs, output_group

    if request.outdir is not None:
        check_outputs(("-o", request.outdir, None))  # before any work
    scene, scene_after, t_before, t_after = _open(request)
    camera = study_camera(scene_after, request.pixel_size_m, DEFAULT_MAP_SIDE_PX,
                          request.extent)
    check_frame_memory(camera, technique=request.technique, settings=request.settings.shadows)
    view = study_view(scene, t_before, scene_after, t_after, camera, request.ground)
    tech = get_technique(request.technique)
    times = request.times
    total = len(times.days) * len(times.clocks_s)
    result = StudyResult(scene=scene, camera=camera)
    with output_group(), _Sheets(request.outdir) as sheets:
        for number, day in enumerate(times.days, 1):
            suns = suns_from_instants(times.utc(scene, day), scene.crs, scene.origin_m,
                                      request.settings.sun)
            panels = []
            for local, sun in zip(times.instants(scene, day), suns):
                panel = make_panel(view, day, local, sun, tech, request.settings.shadows)
                panels.append(panel)
                result.rows.append(_row(panel, request, scene, camera, sheets))
                if on_panel is not None:
                    on_panel(len(result.rows), total)
            text = _text(request, scene, camera, panels, number, len(times.days))
            result.sheets.append(sheets.draw(panels, view, scene, text, request.area))
            down = sum(not p.sun_up for p in panels)
            if down:
                result.warnings.append(f"{day}: the sun is below the horizon at {down} of "
                                       f"{len(panels)} times (those panels are all shadow)")
        if request.outdir is not None:
            sheets.index(result.rows, _provenance(request, scene, camera))
    result.written = sheets.written
    return result


class _Sheets:
    """The outputs of a study as they are made: the PDF open through the run, a PNG per
    sheet, the panels' GeoTIFFs; nothing is written without a folder."""

    def __init__(self, outdir):
        self.outdir = None if outdir is None else Path(outdir)
        self.written: list[Path] = []
        self.pdf = self._pdf_path = None

    def __enter__(self):
        if self.outdir is not None:
            from matplotlib.backends.backend_pdf import PdfPages

            from cityshade.util import atomic_path, make_folder

            make_folder(self.outdir / "panels")
            self._pdf_path = atomic_path(self.outdir / "study.pdf", keep_suffix=True)
            self.pdf = PdfPages(self._pdf_path.__enter__(), metadata={
                "Title": "Shadow study", "Creator": f"cityshade {__version__}"})
        return self

    def __exit__(self, *exc):
        if self.pdf is not None:
            self.pdf.close()
            self._pdf_path.__exit__(*exc)
            if exc[0] is None:
                self.written.insert(0, self.outdir / "study.pdf")
        return False

    def draw(self, panels, view, scene, text, area):
        """Draw a day's sheet; add it to the PDF and write its PNG."""
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        from cityshade.study.sheet import PNG_DPI, draw_sheet
        from cityshade.util import atomic_path

        fig, info = draw_sheet(panels, view, scene, text, area)
        FigureCanvasAgg(fig)
        if self.outdir is not None:
            self.pdf.savefig(fig)
            png = self.outdir / f"sheet_{panels[0].day.isoformat()}.png"
            with atomic_path(png, keep_suffix=True) as tmp:
                fig.savefig(tmp, dpi=PNG_DPI, format="png")
            self.written.append(png)
        self.figure = fig
        return info

    def panel_tifs(self, panel, scene, camera, meta) -> tuple[str, str]:
        """Write the panel's two masks as GeoTIFFs; their names relative to the folder."""
        from cityshade import imageio

        if self.outdir is None:
            return "", ""
        names = []
        for state, mask in (("before", panel.before), ("after", panel.after)):
            name = f"panels/{panel.day.isoformat()}_{panel.local:%H%M}_{state}.tif"
            self.written += imageio.write_georeferenced(
                self.outdir / name, mask, camera.geotransform(scene.origin_m),
                epsg=scene.crs.horizontal_epsg, nodata=imageio.MASK_NODATA,
                attributes={**meta, "cityshade:state": state})
            names.append(name)
        return names[0], names[1]

    def index(self, rows, provenance) -> None:
        """``study.json`` (what was asked and every panel) and ``study.csv``."""
        from cityshade.util import write_text_atomic

        text = io.StringIO()
        writer = csv.DictWriter(text, fieldnames=INDEX_COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
        write_text_atomic(self.outdir / "study.csv", text.getvalue())
        write_text_atomic(self.outdir / "study.json", json.dumps(
            {**provenance, "panels": rows}, indent=2, ensure_ascii=False) + "\n")
        self.written += [self.outdir / "study.csv", self.outdir / "study.json"]


def _row(panel, request, scene, camera, sheets: _Sheets) -> dict:
    """The index row of a panel (its GeoTIFFs written on the way)."""
    sun = panel.sun
    meta = {"cityshade:version": __version__, "cityshade:kind": "study",
            "cityshade:time": panel.local.isoformat(), "cityshade:sun_instant": sun.instant_utc,
            "cityshade:sun_azimuth_true_deg": sun.azimuth_true_deg,
            "cityshade:sun_elevation_deg": sun.elevation_deg,
            "cityshade:technique": request.technique, "cityshade:crs": scene.crs.name}
    before_tif, after_tif = sheets.panel_tifs(panel, scene, camera, meta)
    a = panel.area_m2
    return {"day": panel.day.isoformat(), "time": panel.local.strftime("%H:%M"),
            "utc": sun.instant_utc, "sun_azimuth_deg": round(sun.azimuth_true_deg, 3),
            "sun_elevation_deg": round(sun.elevation_deg, 3),
            "shadow_before_m2": round(a["before"], 2), "shadow_after_m2": round(a["after"], 2),
            "new_shadow_m2": round(a["new"], 2), "shadow_gone_m2": round(a["gone"], 2),
            "tree_shade_m2": round(a["tree_shade"], 2),
            "new_tree_shade_m2": round(a["new_tree_shade"], 2),
            "before_tif": before_tif, "after_tif": after_tif}


def _states(request) -> tuple[str, str]:
    states = request.states
    before, after = states.labels(request.times.days[0])
    if states.proposal is not None:
        return f"model as of {before}", after
    return f"model as of {before}", f"model as of {after}"


def _clock(seconds: int) -> str:
    return f"{seconds // 3600:02d}:{seconds % 3600 // 60:02d}"


def _times_text(clocks) -> str:
    steps = {b - a for a, b in itertools.pairwise(clocks)}
    if len(clocks) > 2 and len(steps) == 1:
        step = steps.pop()
        every = f"{step // 3600} h" if step % 3600 == 0 else f"{step // 60} min"
        return f"{_clock(clocks[0])} to {_clock(clocks[-1])}, every {every}"
    return ", ".join(_clock(c) for c in clocks)


def zone_label(panel, tz: str) -> str:
    """How a panel's clock time is labelled: the zone's abbreviation (CET, BST), or LAT/LMT
    for solar time."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    if tz in SOLAR_TIME_ZONES:
        return "LAT" if tz == "local-apparent" else "LMT"
    return panel.local.tzname() or ""


def _text(request, scene, camera, panels, number: int, count: int):
    """The words of a sheet."""
    import numpy as np

    from cityshade.errors import CRSError
    from cityshade.geo.sun import model_place
    from cityshade.study import panels as P
    from cityshade.study.sheet import SheetText

    try:
        lat, lon, _ = model_place(scene.crs, scene.origin_m)
        place = f"{abs(lat):.4f}° {'N' if lat >= 0 else 'S'}, {abs(lon):.4f}° " \
                f"{'E' if lon >= 0 else 'W'} (model centre)"
    except CRSError:
        place = "local coordinates"
    before, after = _states(request)
    tz = request.times.tz
    zone = {"local-apparent": "local apparent (solar) time, sun due south at 12:00",
            "local-mean": "local mean time"}.get(tz, tz)
    model = Path(request.scene).name if _is_path(request.scene) else "scene"
    rows = [("Model", model), ("Place", place), ("CRS", scene.crs.name),
            ("Existing", before), ("Proposed", after),
            ("Times", _times_text(request.times.clocks_s)), ("Time zone", zone),
            ("Shadows", "exact (izb or raytrace, the same pixels)"
             if request.technique == "exact" else f"{request.technique} (exact)"),
            ("Map", (f"{camera.pixel_size_m:g} m per pixel, "
                    f"{camera.shape[1]} × {camera.shape[0]} px, seen from above"))]
    notes = ("Shadows on the ground and on roofs at the times shown, both states of the "
             "city drawn on the same map. New shadow: shadow after the change where the "
             "same surface had sun before. Sun positions: NREL SPA at the model's place.")
    if any(np.isin(p.cats, (P.TREE_CROWN, P.TREE_SHADE, P.NEW_TREE_SHADE)).any()
           for p in panels):
        notes += (" Tree shade: shaded by tree crowns only, part of the sun passing through "
                  "the leaves (below half of it, it counts as shadow in study.csv's areas).")
    return SheetText(rows, notes, __version__, number, count,
                     zone_label(panels[0], tz) if panels else "")


def _provenance(request, scene, camera) -> dict:
    """What was asked, as ``study.json`` records it."""
    before, after = _states(request)
    return {"cityshade_version": __version__, "kind": "study",
            **(dict(request.provenance) if request.provenance else {}),
            "crs": scene.crs.name, "crs_epsg": scene.crs.horizontal_epsg,
            "technique": request.technique, "before": before, "after": after,
            "days": [d.isoformat() for d in request.times.days],
            "times": [_clock(c) for c in request.times.clocks_s], "tz": request.times.tz,
            "pixel_size_m": camera.pixel_size_m, "map_px": list(camera.shape),
            "geotransform": list(camera.geotransform(scene.origin_m)),
            "area": list(request.area) if request.area is not None else None,
            "columns": list(INDEX_COLUMNS)}
