"""A resumable sun-hours run in an output folder: ``cityshade batch``'s library call.

:func:`run_batch` hashes the request's identity (:func:`batch_params`, :func:`params_key`) into
``OUTDIR/manifest.json``; running again with the same request continues from the saved state
(``state.npz``) without redoing finished sun positions and gives a bit-identical result; a run
that finished with the same request and left all its outputs is not computed again
(:attr:`BatchRun.already_complete`); other parameters are refused unless ``overwrite``. The
untiled run is :func:`cityshade.sunhours.accumulate.compute`, the tiled, distributed and
monthly one
:func:`cityshade.sunhours.tiled.run_tiled`; the outputs are written by
:mod:`cityshade.sunhours.outputs`.
"""
from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from cityshade import __version__
from cityshade.errors import UsageError
from cityshade.sunhours.accumulate import SunHours
from cityshade.sunhours.checkpoint import (Checkpoint, ManifestProgress, finished_outputs,
                                           open_state, relative_output, write_manifest)
from cityshade.sunhours.plan import Unit
from cityshade.sunhours.request import SunHoursRequest

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera

__all__ = ["BatchRun", "run_batch", "batch_params", "camera_params"]


@dataclass
class BatchRun:
    """Result of :func:`run_batch`.

    Attributes
    ----------
    result : SunHours
    written : list of Path
        The output files (sun-hour maps, surfaces.csv; not the frames).
    manifest : dict
        What ``OUTDIR/manifest.json`` holds (parameters, steps, status, summary).
    suns : list of SunPosition
        One per step.
    write_s : float
        Time spent writing the outputs.
    already_complete : bool
        The folder held this very run, finished, with its outputs: nothing was computed or
        written (``result`` is None, ``suns`` empty, ``written`` the outputs found).
    """

    result: SunHours | None
    written: list[Path]
    manifest: dict[str, Any]
    suns: list
    write_s: float
    already_complete: bool = False


def _iso(instant: datetime) -> str:
    return instant.isoformat().replace("+00:00", "Z")


def camera_params(camera: "Camera") -> dict[str, Any]:
    """The camera as it enters a run's parameter hash."""
    return {"kind": camera.kind, "width_px": camera.width_px, "height_px": camera.height_px,
            "eye_m": [float(v) for v in camera.eye_m],
            "target_m": [float(v) for v in camera.target_m],
            "vfov_deg": float(camera.vfov_deg), "pixel_size_m": camera.pixel_size_m}


def batch_params(request: SunHoursRequest) -> dict[str, Any]:
    """The identity of a batch (what a resume compares, hashed by :func:`params_key`): the
    caller's provenance, the city's date, camera, technique and its tunables, ground,
    refraction, outputs and, for a tiled run, the tile size. In the form the manifest gives
    back (JSON: tuples as lists), so a request compares equal to its own stored run."""
    import json

    from cityshade.config import Settings

    spa = request.spa if request.spa is not None else Settings().sun
    shadows = request.shadows if request.shadows is not None else Settings().shadows
    params = {**(request.provenance or {}), "city_days": float(request.t_days),
              "camera": camera_params(request.camera),
              "technique": request.technique, "ground": request.ground,
              "refraction": bool(spa.refraction), "frames": request.frames,
              "samples_per_m2": request.samples_per_m2,
              **({"tile_px": request.tile_px} if request.tiled else {}),
              **({"monthly": True} if request.step_month is not None else {}),
              "stretches": True,
              "shadow_settings": dataclasses.asdict(dataclasses.replace(shadows,
                                                                        technique=None))}
    return json.loads(json.dumps(params))


def _finished_run(outdir: Path, params: dict[str, Any], overwrite: bool) -> BatchRun | None:
    """The run ``outdir`` already holds, finished with the same request, its outputs (and
    frames) all there (:func:`cityshade.sunhours.checkpoint.finished_outputs`); else None."""
    found = finished_outputs(outdir, params, __version__, overwrite,
                             ("frames",) if params.get("frames") else ())
    if found is None:
        return None
    return BatchRun(result=None, written=found[0], manifest=found[1], suns=[], write_s=0.0,
                    already_complete=True)


def _check_memory(request: SunHoursRequest) -> None:
    """Refuse a frame that would not fit, before any work; a tiled run holds one tile's frame
    at a time (its sums are small)."""
    from types import SimpleNamespace

    from cityshade.frame.pipeline import check_frame_memory

    camera, tile_px = request.camera, request.tile_px
    if camera is not None:
        view = camera if tile_px is None else SimpleNamespace(
            width_px=min(tile_px, camera.width_px), height_px=min(tile_px, camera.height_px),
            kind=camera.kind)
        check_frame_memory(view, technique=request.technique, batch=True)


def _write_outputs(outdir: Path, scene, request: SunHoursRequest, result: SunHours, tiled,
                   params: dict[str, Any], below: list[int]) -> list[Path]:
    """The maps, surfaces.csv and the tiled extras (together), and the frames of the steps
    with the sun down."""
    from cityshade.sunhours.outputs import (frame_name, run_metadata, write_sun_hours,
                                            write_tiled_extras)
    from cityshade.util import output_group

    if request.frames and below:
        from cityshade.imageio import mask_from_lit, write_mask_png

        # The sun is down: every surface pixel is in shadow, the rest stays nodata.
        nothing_lit = mask_from_lit(np.zeros(result.valid.shape), result.valid)
        for i in below:
            write_mask_png(outdir / "frames" / frame_name(request.steps[i]), nothing_lit)
    meta = run_metadata(result, scene, params)
    with output_group():
        written = write_sun_hours(outdir, result, scene, request.camera, meta,
                                  surfaces_csv=request.samples_per_m2 is not None,
                                  cog=tiled is not None, decorate=request.decorate)
        if tiled is not None:
            written += write_tiled_extras(outdir, tiled, result, scene, request.camera, meta)
        written += _write_presentation(outdir, scene, request, result, meta)
    return written


def _write_presentation(outdir: Path, scene, request: SunHoursRequest, result: SunHours,
                        meta: dict[str, Any]) -> list[Path]:
    """``report.html`` and, with per-surface sun-hours and ``request.gis``, ``results.gpkg``
    and its GeoJSON twins."""
    from cityshade.present.html import write_report_html
    from cityshade.sunhours.outputs import batch_layers, batch_report_markdown

    written: list[Path] = []
    gis = request.gis and result.samples is not None and not scene.is_tiled
    if gis:
        from cityshade.present.gis import write_gis

        written += write_gis(outdir, batch_layers(result, scene), scene.crs)
    camera = request.camera
    text = batch_report_markdown(result, scene, meta,
                                 "sun_hours.png" if result.hours is not None else None,
                                 georeferenced=camera is not None and camera.kind == "map",
                                 gis=gis)
    written.append(write_report_html(outdir / "report.html", text, title="Sun-hours"))
    return written


def _compute(outdir: Path, scene, request: SunHoursRequest, state: Checkpoint,
             progress: ManifestProgress, on_step):
    """(SunHours, TiledRun or None): the run, untiled or tiled, with its progress."""
    from cityshade.sunhours.stretches import Stretches

    stretches = Stretches.for_steps(request.steps)
    if request.tiled:
        from cityshade.sunhours.tiled import run_tiled

        return run_tiled(scene, request, checkpoint=state, progress=progress, workdir=outdir,
                         on_step=on_step, stretches=stretches)
    from cityshade.sunhours.accumulate import compute
    from cityshade.sunhours.outputs import frame_name

    def step_done(done, total, unit):
        progress.advance(done, total, unit.steps, done)
        if on_step is not None:
            on_step(done, total, unit)

    def frame_done(unit, lit, valid):
        from cityshade.imageio import mask_from_lit, write_mask_png

        mask = mask_from_lit(lit, valid)
        for i in unit.steps:
            write_mask_png(outdir / "frames" / frame_name(request.steps[i]), mask)

    try:
        return compute(scene, request, checkpoint=state, on_step=step_done,
                       on_frame=frame_done if request.frames else None,
                       stretches=stretches), None
    except BaseException:
        import contextlib

        from cityshade.errors import CityshadeError

        with contextlib.suppress(OSError, CityshadeError):  # the first error is told
            progress.write()  # the progress of a stopped run, as far as it got
        raise


def run_batch(outdir, scene: "Scene", request: SunHoursRequest, *, overwrite: bool = False,
              on_plan: Callable[[int], None] | None = None,
              on_step: Callable[[int, int, Unit | None], None] | None = None,
              on_note: Callable[[str], None] | None = None) -> BatchRun:
    """A resumable sun-hour run of ``request`` in ``outdir``: manifest, parameter hash, saved
    state, outputs.

    Parameters
    ----------
    outdir : path-like
        Created when missing.
    scene : Scene
    request : cityshade.sunhours.request.SunHoursRequest
        With ``steps`` and a ``camera`` (:meth:`SunHoursRequest.from_settings`); its
        ``provenance`` (file, dates, zone...) is part of the hash and the manifest. ``frames``
        also writes every step's shadow mask to ``outdir/frames``; ``samples_per_m2`` also
        writes ``surfaces.csv``; ``tile_px``, ``scheduler`` (needs ``scene_path``) and
        ``step_month`` run over tiles (:mod:`cityshade.sunhours.tiled`), with the same numbers.
    overwrite : bool
        Discard a run of other parameters (or a state without manifest) in ``outdir``; a
        finished run of this request is computed again.
    on_plan : callable(units_to_compute), optional
        Called once the sun positions are known (progress bars).
    on_step : callable(units_done, units_total, unit), optional
        Called after each sun position (an exception raised here stops the run with the state
        saved). In a tiled run: after each task, ``(tasks_done, tasks_total, None)``.
    on_note : callable(text), optional
        Told, before the work, that the run resumes (how much was done) or took over the lock
        of a run that ended without removing it.

    The folder is locked while the run lasts (:func:`cityshade.util.folder_lock`); the saved
    state is removed once the outputs are written (it is kept only for a resume). A folder
    that holds this run finished, its outputs all there, is returned as it is
    (:attr:`BatchRun.already_complete`): nothing is computed or written.

    Raises
    ------
    UsageError
        ``outdir`` holds a run of other parameters (the message names what differs) or a
        state without manifest, and not ``overwrite``; a request that does not hold together;
        another live run holds the folder's lock.
    OutputError
        ``outdir`` cannot be created or written.
    """
    from cityshade.util import check_outputs, folder_lock

    outdir = Path(outdir)
    if request.steps is None:
        raise UsageError("a batch needs the time plan's steps (SunHoursRequest.for_steps)")
    request.check()
    params = batch_params(request)
    _check_memory(request)
    check_outputs(("-o", outdir, None))  # a folder that can be written, before any work
    with folder_lock(outdir, on_note):
        return _run_locked(outdir, scene, request, params, overwrite, on_plan, on_step, on_note)


def _run_locked(outdir: Path, scene, request: SunHoursRequest, params: dict[str, Any],
                overwrite: bool, on_plan, on_step, on_note) -> BatchRun:
    """:func:`run_batch` once the folder is checked and locked."""
    from cityshade.geo.sun import suns_from_instants
    from cityshade.sunhours.plan import plan_units
    from cityshade.util import make_folder, plural

    finished_run = _finished_run(outdir, params, overwrite)
    if finished_run is not None:
        return finished_run
    state, state_warning = open_state(outdir, params, overwrite)
    steps = request.steps
    manifest: dict[str, Any] = {
        "cityshade_version": __version__, "key": state.key, "params": params,
        "status": "running",
        "steps": [{"index": s.index, "start_utc": _iso(s.start_utc), "end_utc": _iso(s.end_utc),
                   "weight_h": s.weight_h} for s in steps],
        "finished_steps": [],
    }
    if state.sha256 is not None:
        manifest["state_sha256"] = [state.sha256]
    write_manifest(outdir, manifest)
    if request.frames:
        make_folder(outdir / "frames")

    t_suns = time.perf_counter()
    suns = suns_from_instants(list(request.instants_utc), scene.crs, scene.origin_m,
                              request.spa)
    suns_s = time.perf_counter() - t_suns  # the whole run's suns in one vectorised call
    units, below, _ = plan_units(suns, request.weights_h)
    finished: list[int] = list(below)  # nothing to compute for a sun below the horizon
    done_before = state.units_done()
    for unit in units[:done_before]:
        finished.extend(unit.steps)
    if done_before and on_note is not None:
        on_note(f"resuming the run in {outdir}: {done_before} of "
                f"{plural(len(units), 'sun position')} ({len(finished)} of "
                f"{plural(len(steps), 'step')}) were done before")
    if on_plan is not None:
        on_plan(len(units) - done_before)
    progress = ManifestProgress(outdir, manifest, state, finished)
    request = dataclasses.replace(request, suns=tuple(suns))
    result, tiled = _compute(outdir, scene, request, state, progress, on_step)
    result.timings_s["suns_s"] = suns_s
    if state_warning is not None:
        result.warnings.insert(0, state_warning)
    t1 = time.perf_counter()
    written = _write_outputs(outdir, scene, request, result, tiled, params, below)
    write_s = time.perf_counter() - t1
    # The state served a resume; the outputs now hold everything (TUM campus: 43 MB of state
    # beside 0.7 MB of results). Removed before the manifest stops naming it, so an interrupt
    # between the two leaves a run that starts again, never a state the manifest disowns.
    state.remove()
    manifest.pop("state_sha256", None)
    manifest["status"] = "finished"
    manifest["finished_steps"] = sorted(finished)
    manifest["summary"] = {
        "steps": result.steps, "steps_below_horizon": result.steps_below_horizon,
        "steps_same_sun": result.steps_duplicate, "sun_positions": result.units,
        "sun_positions_resumed": result.units_resumed, "hours_total": result.hours_total,
        "hours_sun_up": result.hours_sun_up,
        # Relative to the folder (monthly/...): a run again checks they are all there.
        "outputs": [relative_output(p, outdir) for p in written],
        "timings_s": {**result.timings_s, "write_s": write_s},
    }
    write_manifest(outdir, manifest)
    return BatchRun(result=result, written=written, manifest=manifest, suns=suns,
                    write_s=write_s)
