"""Sun-hours accumulation: the camera pass once, then per sun position the shadow stage.

The camera does not move in a batch, so the camera pass (rasterize + resolve, docs/DESIGN.md §10) runs
once; for each distinct sun position above the horizon (:func:`cityshade.sunhours.plan.plan_units`)
only the shadow stage runs and its lit flags are added, weighted by the position's hours, to
float64 sums in the order of the positions (so a resumed run is bit-identical to a straight
one, :class:`cityshade.sunhours.checkpoint.Checkpoint`).

:func:`sun_hours` is the untiled run (any technique); :func:`cityshade.sunhours.tiled.tiled_sun_hours`
the tiled one (exact techniques). Both share :func:`prepare` (checks, suns, units, receivers)
and :func:`make_result`.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from datetime import datetime
from typing import TYPE_CHECKING, Any, Callable, Sequence

import numpy as np

from cityshade.errors import UsageError
from cityshade.sunhours.checkpoint import Checkpoint, SaveThrottle
from cityshade.sunhours.plan import Unit, plan_run, step_weights
from cityshade.sunhours.request import SunHoursRequest

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera

__all__ = ["SunHours", "Prepared", "prepare", "make_result", "receivers_pass", "sun_hours",
           "compute", "surface_sun_hours"]


@dataclass
class SunHours:
    """Result of :func:`sun_hours`.

    Attributes
    ----------
    hours : (H, W) float32 or None
        Sun-hours per pixel; NaN where no surface. None without a camera.
    valid : (H, W) bool or None
        Pixels showing a surface.
    surfaces : cityshade.raster.gbuffer.Surfaces or None
        The camera pass (done once).
    samples : cityshade.sunhours.surfaces.SurfaceSamples or None
    sample_hours : (N,) float64 or None
        Sun-hours of each surface sample.
    polygon_hours : (P,) float64 or None
        Area-weighted mean sun-hours per polygon, NaN where not sampled.
    steps, steps_below_horizon, steps_duplicate, units, units_resumed : int
        Counts: all steps, skipped (sun down), sharing a sun position, distinct positions
        computed, positions taken from a saved state.
    hours_total, hours_sun_up : float
        Time covered by all steps, and by those with the sun above the horizon.
    suns : list of SunPosition
    timings_s : dict
        ``suns_s, camera_s, samples_s, shadow_s, surface_rays_s, checkpoint_s, total_s``.
    warnings : list of str
    """

    hours: np.ndarray | None
    valid: np.ndarray | None
    surfaces: Any
    samples: Any
    sample_hours: np.ndarray | None
    polygon_hours: np.ndarray | None
    steps: int
    steps_below_horizon: int
    steps_duplicate: int
    units: int
    units_resumed: int
    hours_total: float
    hours_sun_up: float
    suns: list
    timings_s: dict[str, float] = field(default_factory=dict)
    diagnostics: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    #: The sunlit stretches (:class:`cityshade.sunhours.stretches.Stretches`) when asked for, else None.
    stretches: Any = None


class _PixelRays:
    """The camera pass of a batch, kept for every step: per step the shared rule decides which
    pixels face the sun (:attr:`cityshade.shadows.ShadowContext.faces`, as for the
    ``raytrace`` technique) and only those are decided, from
    :func:`cityshade.trace.shadow_rays_from_surface` (whose origin steps along the normal and
    toward the sun, so it is made per step), by the exact ``engine``: ``izb`` (rebinned per
    step) or ``raytrace`` (:func:`cityshade.shadows.visibility.occluded`), the same answer."""

    def __init__(self, cp, engine: str = "exact", calls: int = 1):
        from cityshade.lightspace import SurfaceReceivers
        from cityshade.shadows import gather_pixels

        self.cp = cp
        self.valid = cp.valid
        self.engine = engine
        self.calls = calls      # sun positions sharing an izb set-up (``exact``'s choice)
        self.chosen: list = []  # ``exact``'s choice of each call (``batch -v``)
        # The valid pixels' points, normals and offsets, checked once: per step one pass makes
        # the facing pixels' origins (the numpy gathers and temporaries cost more than izb's
        # binning on the 1M-triangle city).
        self.receivers = SurfaceReceivers(gather_pixels(cp.surfaces.position_m, self.valid),
                                          gather_pixels(cp.normal, self.valid))

    def lit(self, scene, sun, t_days: float) -> np.ndarray:
        """(H, W) float32: 1 lit, 0 shadow or no surface, between where only vegetation is in
        the way (its transmission, docs/DESIGN.md §21)."""
        from cityshade.geometry.vegetation import day_of_year
        from cityshade.shadows import scatter_pixels
        from cityshade.shadows.visibility import transmission

        faces = self.cp.context(sun).faces
        lit = np.zeros(self.valid.shape, np.float32)
        if faces.any():
            direction = np.asarray(sun.direction, dtype=np.float64)
            origins = self.receivers.origins(direction, faces[self.valid])
            # Rows in parallel: numpy's boolean assignment took 6-8 ms of a 2.1 M-pixel step.
            scatter_pixels(transmission(scene, origins, direction, t_days, engine=self.engine,
                                        day_of_year=day_of_year(sun), calls=self.calls,
                                        chosen=self.chosen), faces, lit)
        return lit



def receivers_pass(scene, camera, t_days: float, ground, samples_per_m2, timings: dict,
                   diagnostics: dict):
    """What a batch computes once: the camera pass (None without a camera) and the surface
    samples (None without ``samples_per_m2``); fills ``camera_s``/``samples_s`` and the
    G-buffer and ground diagnostics."""
    cp = samples = None
    if camera is not None:
        from cityshade.frame.pipeline import camera_pass

        t0 = time.perf_counter()
        cp = camera_pass(scene, camera, float(t_days), ground=ground)
        diagnostics["gbuffer"] = cp.gbuffer.stats
        if cp.ground is not None:
            diagnostics["ground"] = cp.ground
        timings["camera_s"] = time.perf_counter() - t0
    if samples_per_m2 is not None:
        from cityshade.sunhours.surfaces import sample_surfaces

        t0 = time.perf_counter()
        samples = sample_surfaces(scene, samples_per_m2, float(t_days))
        timings["samples_s"] = time.perf_counter() - t0
    return cp, samples


@dataclass
class Prepared:
    """What a run computes before its loop (:func:`prepare`)."""

    instants: list
    weights: np.ndarray
    suns: list
    units: list[Unit]
    below: list[int]
    duplicates: int
    cp: Any                # the camera pass, or None
    samples: Any           # the surface samples, or None
    timings: dict[str, float]
    diagnostics: dict[str, Any]
    warnings: list[str]
    t_start: float


def prepare(scene, request: SunHoursRequest, timing_keys: Sequence[str]) -> Prepared:
    """Check ``request`` against ``scene``, compute its suns (one SPA call, unless given),
    group them into units and run the receivers' pass (camera pass, surface samples).

    Raises
    ------
    UsageError
        No kd-tree, nothing to compute, no instants, bad weights or suns, an unknown
        technique.
    """
    t_start = time.perf_counter()
    request.check(scene)
    instants = list(request.instants_utc)
    if not instants:
        raise UsageError("a batch needs at least one instant")
    for t in instants:
        if not isinstance(t, datetime) or t.utcoffset() is None:
            raise UsageError(f"instants must be aware datetimes, not {t!r}")
    if math.isnan(float(request.t_days)):
        raise UsageError("t_days must be a number of days, not NaN")
    weights = step_weights(instants, request.weights_h)
    if request.camera is not None:
        from cityshade.shadows import get_technique

        get_technique(request.technique)  # unknown names fail before any work
    timings = dict.fromkeys(timing_keys, 0.0)
    warnings: list[str] = []
    # Sun positions: one SPA call for all instants, or the caller's.
    t0 = time.perf_counter()
    if request.suns is None:
        from cityshade.geo.sun import suns_from_instants

        suns = suns_from_instants(instants, scene.crs, scene.origin_m, request.spa)
    else:
        suns = list(request.suns)
        if len(suns) != len(instants):
            raise UsageError(f"give one sun per instant ({len(instants)}), not {len(suns)}")
    timings["suns_s"] = time.perf_counter() - t0
    t_days = float(request.t_days)
    units, below, duplicates = plan_run(scene, instants, t_days, suns, weights, warnings)
    diagnostics: dict[str, Any] = {}
    cp, sampled = receivers_pass(scene, request.camera, t_days, request.ground,
                                 request.samples_per_m2 if request.samples is None else None,
                                 timings, diagnostics)
    samples = request.samples if request.samples is not None else sampled
    return Prepared(instants, weights, suns, units, below, duplicates, cp, samples, timings,
                    diagnostics, warnings, t_start)


def make_result(prep: Prepared, hours, sample_hours, units_resumed: int,
                stretches) -> SunHours:
    """The :class:`SunHours` of a finished run (per-pixel ``hours``, per-sample
    ``sample_hours`` or None)."""
    polygon_hours = None
    if sample_hours is not None:
        from cityshade.sunhours.surfaces import polygon_means

        polygon_hours = polygon_means(prep.samples, sample_hours)
    prep.timings["total_s"] = time.perf_counter() - prep.t_start
    below_set = set(prep.below)
    cp = prep.cp
    return SunHours(hours=hours, valid=None if cp is None else cp.valid,
                    surfaces=None if cp is None else cp.surfaces, samples=prep.samples,
                    sample_hours=sample_hours, polygon_hours=polygon_hours,
                    steps=len(prep.suns), steps_below_horizon=len(prep.below),
                    steps_duplicate=prep.duplicates, units=len(prep.units),
                    units_resumed=units_resumed, hours_total=float(prep.weights.sum()),
                    hours_sun_up=float(sum(w for i, w in enumerate(prep.weights)
                                           if i not in below_set)),
                    suns=list(prep.suns), timings_s=prep.timings,
                    diagnostics=prep.diagnostics, warnings=prep.warnings, stretches=stretches)


def sun_hours(scene: "Scene", camera: "Camera | None", instants_utc: Sequence[datetime],
              t_days: float, *, checkpoint: Checkpoint | None = None,
              on_step: Callable[[int, int, Unit], None] | None = None,
              on_frame: Callable[[Unit, np.ndarray, np.ndarray], None] | None = None,
              stretches=None, **options) -> SunHours:
    """Sun-hours per pixel of a fixed camera (and per surface) over many sun positions.

    Parameters
    ----------
    scene : Scene
        With its kd-tree (or a tiled cache's view).
    camera : Camera or None
        The view of the sun-hour map; None computes only per-surface values.
    instants_utc : sequence of aware datetime
        The instants of the steps (centres of their intervals).
    t_days : float
        City time (days since 1970-01-01 UTC): the city as it stood then is used for all
        steps (the camera pass is done once).
    checkpoint : Checkpoint, optional
        Resume from and save to this state: every ``CHECKPOINT_EVERY_S`` seconds, after the
        last sun position, and when the run stops (an exception, e.g. KeyboardInterrupt).
    on_step : callable(units_done, units_total, unit), optional
        Called after each position is accumulated (progress; an exception raised here, e.g.
        KeyboardInterrupt, stops the run with the state saved).
    on_frame : callable(unit, lit, valid), optional
        Receives each position's per-pixel lit fraction (for ``--frames``).
    stretches : cityshade.sunhours.stretches.Stretches, optional
        Also keep every receiver's sunlit stretches (continuous sunshine) over the steps,
        which must be the instants' steps; returned as ``result.stretches``.
    **options
        Further fields of :class:`cityshade.sunhours.request.SunHoursRequest`: ``weights_h``
        (hours per instant; default the even spacing), ``technique`` (default ``izb``;
        surface samples are always exact, through ``raytrace``'s kd-tree when that is the
        technique, else through the light-space engine, the same answer), ``shadows``
        (``[shadows]`` tunables), ``ground``, ``spa``, ``suns`` (one per instant: no SPA, no
        CRS needed), ``samples_per_m2`` or ``samples``, ``reuse_rays`` (``izb`` and
        ``raytrace``: the pixels' oriented normals and shadow-ray origins do not depend on
        the sun, so they are made once; identical to ``False``, which is tested).

    Returns
    -------
    SunHours

    Raises
    ------
    UsageError
        No kd-tree, no instants, bad weights or suns, a saved state of another run.
    CRSError
        Sun positions from instants for a model without CRS.
    """
    request = SunHoursRequest(camera=camera, instants_utc=tuple(instants_utc),
                              t_days=t_days, **options)
    return compute(scene, request, checkpoint=checkpoint, on_step=on_step, on_frame=on_frame,
                   stretches=stretches)


def _unit_lit(scene, prep: Prepared, request: SunHoursRequest, unit: Unit, rays, tech,
              sample_engine: str):
    """(pixel lit (H, W) float32 or None, sample lit (S,) bool or None) of one position:
    the pixels by ``rays`` (an exact engine's reused rays) or the technique ``tech``, the
    surface samples by the exact ``sample_engine``."""
    lit = slit = None
    timings, t_days = prep.timings, float(request.t_days)
    if prep.cp is not None:
        t0 = time.perf_counter()
        if rays is not None:
            lit = rays.lit(scene, unit.sun, t_days)
        else:
            from cityshade.frame.pipeline import shadow_pass

            lit = shadow_pass(prep.cp, unit.sun, tech, request.shadows).lit
        timings["shadow_s"] += time.perf_counter() - t0
    if prep.samples is not None:
        from cityshade.sunhours.surfaces import samples_lit

        t0 = time.perf_counter()
        slit = samples_lit(scene, prep.samples, unit.sun, t_days, engine=sample_engine)
        timings["surface_rays_s"] += time.perf_counter() - t0
    return lit, slit


def compute(scene, request: SunHoursRequest, *, checkpoint: Checkpoint | None = None,
            on_step: Callable[[int, int, Unit], None] | None = None,
            on_frame: Callable[[Unit, np.ndarray, np.ndarray], None] | None = None,
            stretches=None) -> SunHours:
    """The untiled run of ``request`` (:func:`sun_hours`'s parameters)."""
    from cityshade.shadows import describe, get_technique

    prep = prepare(scene, request, ("suns_s", "camera_s", "samples_s", "shadow_s",
                                    "surface_rays_s", "checkpoint_s"))
    cp, units = prep.cp, prep.units
    valid = cp.valid if cp is not None else None
    # What decides a position, made once for the whole run.
    spec = describe(request.technique)
    rays = _PixelRays(cp, spec.engine, len(units)) \
        if cp is not None and request.reuse_rays and spec.exact else None
    tech = get_technique(spec) if cp is not None and rays is None else None
    sample_engine = spec.engine if spec.exact else "exact"

    # Running float64 sums, restored from a saved state when there is one.
    pixel_shape = valid.shape if valid is not None else (0, 0)
    pixel_sum = np.zeros(pixel_shape, np.float64)
    sample_sum = np.zeros(prep.samples.n if prep.samples is not None else 0, np.float64)
    done = 0
    if checkpoint is not None:
        state = checkpoint.load(len(units), pixel_shape, sample_sum.shape[0])
        if state is not None:
            done, pixel_sum, sample_sum = state
    if stretches is not None:
        stretches.plan(units, valid.shape if valid is not None else None, sample_sum.shape[0])
        if done:
            stretches.restore(checkpoint.extra)
    resumed = accumulated = saved = done  # accumulated: positions whose sums are complete

    def save() -> None:
        nonlocal saved
        checkpoint.save(accumulated, pixel_sum, sample_sum,
                        stretches.state() if stretches is not None else None)
        saved = accumulated

    throttle = SaveThrottle(save if checkpoint is not None else None, prep.timings)
    try:
        for k in range(done, len(units)):
            unit = units[k]
            lit, slit = _unit_lit(scene, prep, request, unit, rays, tech, sample_engine)
            # The sums change together: an interruption inside this block saves nothing.
            throttle.consistent = False
            if lit is not None:
                pixel_sum += unit.weight_h * lit.astype(np.float64)
            if slit is not None:
                sample_sum += unit.weight_h * slit.astype(np.float64)
            if stretches is not None:
                stretches.add(k, lit, slit)
            accumulated = k + 1
            throttle.consistent = True
            if lit is not None and on_frame is not None:
                on_frame(unit, lit, valid)
            throttle.maybe(last=accumulated == len(units))
            if on_step is not None:
                on_step(k + 1, len(units), unit)
    finally:
        # A run that stops (Ctrl-C, an error) keeps what it finished; a finished run has saved.
        if throttle.consistent and accumulated > saved:
            throttle.save()

    if stretches is not None:
        stretches.finish()
    if rays is not None and rays.chosen:
        from cityshade.shadows.exact import describe_choices

        prep.diagnostics["engine"] = describe_choices(rays.chosen, "sun positions")
    hours = None
    if cp is not None:
        hours = np.where(valid, pixel_sum, np.nan).astype(np.float32)
    return make_result(prep, hours, sample_sum if prep.samples is not None else None, resumed,
                       stretches)


def surface_sun_hours(scene, instants_utc: Sequence[datetime], t_days: float, *,
                      samples_per_m2: float = 1.0, **kwargs) -> SunHours:
    """Per-surface sun-hours only (no camera): :func:`sun_hours` with ``camera=None``; read
    ``polygon_hours`` (P,) and ``samples`` of the result."""
    return sun_hours(scene, None, instants_utc, t_days, samples_per_m2=samples_per_m2,
                     **kwargs)
