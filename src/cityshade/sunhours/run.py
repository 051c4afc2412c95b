"""Batch runs over many sun positions: sun-hour maps and per-surface sun-hours.

The camera does not move in a batch, so the camera pass (rasterize + resolve, DESIGN §7) runs
once; for each sun position only the shadow stage runs. Each step stands for an interval of
time and is weighted by its length in hours; the sun of a step is taken at the interval's
centre (midpoint rule: the weights add up to the covered time exactly, and the error in
sun-hours is second order in the step). Steps with the sun at or below the horizon contribute
nothing and are skipped; steps with an identical sun direction are computed once, with their
weights summed.

Sums are float64 and are added in a fixed order (the order of first occurrence of each sun
position), so a run that was interrupted and resumed from its checkpoint (:class:`Checkpoint`)
gives a result bit-identical to a straight run.

Entry points: :func:`plan_steps` (dates, local times and a time zone → UTC steps),
:func:`sun_hours` (arrays in, arrays out; a per-surface variant is
:func:`surface_sun_hours`), :func:`write_sun_hours` (EXR, colour-mapped PNG with legend,
georeferenced float raster) and the manifest helpers used by ``cityshade batch``.
"""
from __future__ import annotations

import hashlib
import io
import json
import math
import re
import time
import zipfile
from dataclasses import dataclass, field
from datetime import date, datetime, timedelta, timezone
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Sequence

import numpy as np

from cityshade import __version__
from cityshade.config import ShadowSettings
from cityshade.errors import UsageError

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera

__all__ = ["Step", "Unit", "SunHours", "Checkpoint", "parse_duration_s", "parse_clock_s",
           "plan_steps", "plan_units", "sun_hours", "surface_sun_hours", "write_sun_hours",
           "colour_map_png", "params_key", "read_manifest", "write_manifest", "run_batch",
           "BatchRun", "MANIFEST_NAME", "STATE_NAME"]

MANIFEST_NAME = "manifest.json"
STATE_NAME = "state.npz"
#: Largest number of steps of one run: 1 year every minute is 525 600; more is a typo.
MAX_STEPS = 1_000_000
_DURATION_RE = re.compile(r"\s*(\d+(?:\.\d*)?)\s*(h|min|s)\s*")
_CLOCK_RE = re.compile(r"(\d{1,2}):(\d{2})(?::(\d{2}))?")


# --- time steps -------------------------------------------------------------------------------

def parse_duration_s(text: str) -> float:
    """Seconds of a duration such as ``10min``, ``1h``, ``30s`` or ``1h30min``.

    Raises
    ------
    UsageError
        No unit, an unknown unit, or a duration that is not positive.
    """
    pos, total = 0, 0.0
    text_s = str(text)
    for match in _DURATION_RE.finditer(text_s):
        if match.start() != pos:
            break
        total += float(match.group(1)) * {"h": 3600.0, "min": 60.0, "s": 1.0}[match.group(2)]
        pos = match.end()
    if pos != len(text_s) or pos == 0:
        raise UsageError(f"cannot read duration {text!r}; use e.g. 10min, 1h, 30s or 1h30min")
    if not total > 0.0:
        raise UsageError(f"a duration must be longer than 0 s, not {text!r}")
    return total


def parse_clock_s(text: str) -> int:
    """Seconds after midnight of a time of day ``HH:MM[:SS]``; ``24:00`` is the next midnight."""
    match = _CLOCK_RE.fullmatch(str(text).strip())
    if match is None:
        raise UsageError(f"cannot read time of day {text!r}; use HH:MM, e.g. 05:30")
    h, m, s = int(match.group(1)), int(match.group(2)), int(match.group(3) or 0)
    seconds = (h * 60 + m) * 60 + s
    if m >= 60 or s >= 60 or seconds > 86_400:
        raise UsageError(f"time of day {text!r} does not exist; use 00:00 to 24:00")
    return seconds


@dataclass(frozen=True)
class Step:
    """One time step: the interval ``[start_utc, end_utc)`` it stands for."""

    index: int
    start_utc: datetime
    end_utc: datetime

    @property
    def weight_h(self) -> float:
        return (self.end_utc - self.start_utc).total_seconds() / 3600.0

    @property
    def centre_utc(self) -> datetime:
        """Where the sun of the step is evaluated (midpoint rule)."""
        return self.start_utc + (self.end_utc - self.start_utc) / 2


def _local(day: date, seconds: int, zone) -> datetime:
    """Aware datetime of a wall-clock time on ``day`` in ``zone`` (24:00 = next midnight).

    A wall time skipped by a daylight-saving change is read with the offset before the change
    (zoneinfo's ``fold=0``), i.e. one hour later in real time.
    """
    extra_day, rest = divmod(seconds, 86_400)
    d = day + timedelta(days=extra_day)
    h, rem = divmod(rest, 3600)
    return datetime(d.year, d.month, d.day, h, rem // 60, rem % 60, tzinfo=zone)


def plan_steps(first_day: date, from_s: int, to_s: int, every_s: float, tz: str,
               days: int | None = None, to_date: date | None = None,
               every_day: int = 1) -> list[Step]:
    """Time steps of a batch: on each day, ``[from, to)`` local time cut into steps of
    ``every_s`` (the last one shorter when it does not divide).

    Parameters
    ----------
    first_day : datetime.date
    from_s, to_s : int
        Local times of day in seconds after midnight (:func:`parse_clock_s`), ``from < to``.
    every_s : float
        Step length in seconds, elapsed time (a daylight-saving change inside the window
        adds or removes steps, as it adds or removes real time).
    tz : str
        IANA time zone of the local times ("UTC" for UTC).
    days : int, optional
        Number of days (default 1), ``every_day`` apart.
    to_date : datetime.date, optional
        Last day (inclusive) instead of ``days``.
    every_day : int
        Days between the days taken.

    Returns
    -------
    list of Step

    Raises
    ------
    UsageError
        Unknown zone, empty window, both ``days`` and ``to_date``, non-positive counts, years
        outside 1000–3000, or more than :data:`MAX_STEPS` steps.
    """
    from cityshade.geo.temporal import zone_info

    if days is not None and to_date is not None:
        raise UsageError("give --days or --to-date, not both")
    if every_day < 1:
        raise UsageError(f"--every-day must be >= 1, not {every_day}")
    if not to_s > from_s:
        raise UsageError("--to must be later than --from on the same day (24:00 is midnight "
                         "at the end of the day)")
    if not (math.isfinite(every_s) and every_s > 0):
        raise UsageError(f"the step must be longer than 0 s, not {every_s}")
    zone = zone_info(tz)
    if to_date is not None:
        if to_date < first_day:
            raise UsageError(f"--to-date {to_date} is before --date {first_day}")
        n_days = (to_date - first_day).days // every_day + 1
    else:
        n_days = 1 if days is None else int(days)
        if n_days < 1:
            raise UsageError(f"--days must be >= 1, not {days}")
    per_day = math.ceil((to_s - from_s) / every_s)
    if n_days * per_day > MAX_STEPS:
        raise UsageError(f"{n_days * per_day} steps exceed the limit of {MAX_STEPS}; "
                         f"choose a longer step or fewer days")
    steps: list[Step] = []
    step = timedelta(seconds=every_s)
    for k in range(n_days):
        day = first_day + timedelta(days=k * every_day)
        if not 1000 <= day.year <= 3000:
            raise UsageError(f"dates must lie in the years 1000 to 3000, not {day}")
        start = _local(day, from_s, zone).astimezone(timezone.utc)
        end = _local(day, to_s, zone).astimezone(timezone.utc)
        s = start
        while s < end:
            e = min(s + step, end)
            steps.append(Step(len(steps), s, e))
            s = e
    return steps


# --- work units: distinct sun positions above the horizon -------------------------------------

@dataclass(frozen=True)
class Unit:
    """A distinct sun position above the horizon and the steps that share it."""

    sun: Any
    steps: tuple[int, ...]
    weight_h: float


def plan_units(suns: Sequence, weights_h: Sequence[float]) -> tuple[list[Unit], list[int], int]:
    """Group steps by identical sun direction, skipping those at or below the horizon.

    Returns
    -------
    units : list of Unit
        In the order of each position's first step; weights summed in step order.
    below : list of int
        Indices of the steps with the sun at or below the horizon.
    duplicates : int
        Steps that reuse an earlier step's identical sun position.
    """
    by_key: dict[tuple, int] = {}
    steps: list[list[int]] = []
    weights: list[float] = []
    order: list[Any] = []
    below: list[int] = []
    duplicates = 0
    for i, (sun, w) in enumerate(zip(suns, weights_h)):
        if not sun.above_horizon:
            below.append(i)
            continue
        key = tuple(float(v) for v in sun.direction)
        u = by_key.get(key)
        if u is None:
            by_key[key] = len(order)
            order.append(sun)
            steps.append([i])
            weights.append(float(w))
        else:
            duplicates += 1
            steps[u].append(i)
            weights[u] += float(w)
    units = [Unit(sun, tuple(s), w) for sun, s, w in zip(order, steps, weights)]
    return units, below, duplicates


# --- checkpoint ---------------------------------------------------------------------------------

#: Seconds between two saves of a batch's state (and at its end and when it stops).
CHECKPOINT_EVERY_S = 10.0


class Checkpoint:
    """Running sums of an unfinished run, saved atomically (see ``CHECKPOINT_EVERY_S``).

    Parameters
    ----------
    path : path-like
        The state file (``OUTDIR/state.npz``).
    key : str
        Hash of the run's parameters (:func:`params_key`); a state with another key is
        refused, so results of different runs never mix.
    """

    def __init__(self, path, key: str):
        self.path = Path(path)
        self.key = str(key)
        self.saves = 0
        self.save_s = 0.0
        self.sha256: str | None = None  # of the last state written, for the manifest
        # Called with the new state's checksum before it replaces the old one (run_batch records
        # both in the manifest, so an interruption between the two writes loses nothing).
        self.before_write: Callable[[str], None] | None = None
        # Further arrays of the run (the sunlit stretches, :mod:`cityshade.sunhours.stretches`), saved with
        # the sums under ``x_`` names and read back by :meth:`load`.
        self.extra: dict[str, np.ndarray] = {}

    def load(self, n_units: int, pixel_shape, n_samples: int):
        """``(units_done, pixel_sum, sample_sum)`` of a saved state, or None when there is none.

        Raises
        ------
        UsageError
            The state belongs to other parameters, does not fit this run, or is damaged.
        """
        if not self.path.exists():
            return None
        hint = "re-run with --overwrite to start afresh"
        try:
            with np.load(self.path, allow_pickle=False) as z:
                key = str(z["key"])
                done = int(z["units_done"])
                pixel_sum = np.array(z["pixel_sum"], dtype=np.float64)
                sample_sum = np.array(z["sample_sum"], dtype=np.float64)
                self.extra = {n[2:]: np.array(z[n]) for n in z.files if n.startswith("x_")}
        except (OSError, ValueError, KeyError, zipfile.BadZipFile) as exc:
            raise UsageError(f"the saved state {self.path} is damaged ({exc}); {hint}") from None
        if key != self.key:
            raise UsageError(f"the saved state {self.path} belongs to a run with other "
                             f"parameters; {hint}")
        shape = tuple(pixel_shape) if pixel_shape is not None else (0, 0)
        if pixel_sum.shape != shape or sample_sum.shape != (n_samples,) or not \
                0 <= done <= n_units:
            raise UsageError(f"the saved state {self.path} does not fit this run; {hint}")
        return done, pixel_sum, sample_sum

    def units_done(self) -> int:
        """Units recorded as done in the saved state (0 without a state or for another key)."""
        try:
            with np.load(self.path, allow_pickle=False) as z:
                return int(z["units_done"]) if str(z["key"]) == self.key else 0
        except (OSError, ValueError, KeyError, zipfile.BadZipFile):
            return 0

    def file_sha256(self) -> str | None:
        """SHA-256 of the state file as it is on disk (None without one)."""
        try:
            return hashlib.sha256(self.path.read_bytes()).hexdigest()
        except FileNotFoundError:
            return None

    def save(self, units_done: int, pixel_sum: np.ndarray, sample_sum: np.ndarray,
             extra: dict[str, np.ndarray] | None = None) -> None:
        """Write the state (and ``extra`` arrays) to a temporary name and rename it over the
        previous one."""
        self.save_arrays(units_done, pixel_sum=pixel_sum, sample_sum=sample_sum,
                         **{f"x_{k}": v for k, v in (extra or {}).items()})

    def save_arrays(self, units_done: int, **arrays: np.ndarray) -> None:
        """:meth:`save` with other arrays (a tiled run's, :mod:`cityshade.sunhours.tiled`)."""
        from cityshade.util import atomic_write

        t0 = time.perf_counter()
        buf = io.BytesIO()
        np.savez(buf, key=np.array(self.key), units_done=np.array(units_done), **arrays)
        data = buf.getvalue()
        digest = hashlib.sha256(data).hexdigest()
        if self.before_write is not None:
            self.before_write(digest)
        with atomic_write(self.path, "wb", what="the batch state") as fh:
            fh.write(data)
        self.sha256 = digest
        self.saves += 1
        self.save_s += time.perf_counter() - t0

    def remove(self) -> None:
        self.path.unlink(missing_ok=True)


# --- the run ------------------------------------------------------------------------------------

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
    toward the sun, so it is made per step), by the exact engine of ``technique``: ``izb``
    (:func:`cityshade.lightspace.occluded`, rebinned per step) or ``raytrace``
    (:func:`cityshade.trace.occluded`), the same answer."""

    def __init__(self, cp, technique: str = "izb"):
        from cityshade.lightspace import SurfaceReceivers

        self.cp = cp
        self.valid = cp.valid
        self.technique = technique
        # The valid pixels' points, normals and offsets, checked once: per step one pass makes
        # the facing pixels' origins (the numpy gathers and temporaries cost more than izb's
        # binning on the 1M-triangle city).
        self.receivers = SurfaceReceivers(cp.surfaces.position_m[self.valid],
                                          cp.normal[self.valid])

    def lit(self, scene, sun, t_days: float) -> np.ndarray:
        """(H, W) float32: 1 lit, 0 shadow or no surface."""
        from cityshade import lightspace
        from cityshade.trace import occluded

        faces = self.cp.context(sun).faces
        lit = np.zeros(self.valid.shape, np.float32)
        if faces.any():
            direction = np.asarray(sun.direction, dtype=np.float64)
            origins = self.receivers.origins(direction, faces[self.valid])
            if self.technique == "izb":
                blocked = lightspace.occluded(scene, origins, direction, t_days)
            else:
                blocked = occluded(scene, origins, direction, t_days)
            lit[faces] = ~blocked
        return lit


def step_weights(instants: list, weights_h) -> np.ndarray:
    """Hours each instant stands for: ``weights_h`` checked, or the even spacing."""
    if weights_h is not None:
        w = np.asarray(weights_h, dtype=np.float64)
        if w.shape != (len(instants),):
            raise UsageError(f"weights_h must have one value per instant ({len(instants)}), "
                             f"not shape {w.shape}")
        if not (np.isfinite(w).all() and (w >= 0).all()):
            raise UsageError("weights_h must be finite hours >= 0")
        return w
    if len(instants) < 2:
        raise UsageError("give weights_h (hours per instant) for a single instant")
    gaps = np.array([(b - a).total_seconds() for a, b in zip(instants, instants[1:])])
    if not np.all(gaps == gaps[0]) or gaps[0] <= 0:
        raise UsageError("instants are not evenly spaced; give weights_h (hours per instant)")
    return np.full(len(instants), gaps[0] / 3600.0)


def _city_changes(scene, instants, t_days) -> str | None:
    """A warning when objects appear or disappear between the first and last instant."""
    if not scene.has_time or not instants:
        return None
    from cityshade.geo.temporal import datetime_to_days

    lo = min(datetime_to_days(t) for t in instants)
    hi = max(datetime_to_days(t) for t in instants)
    ends = np.concatenate([scene.obj_t_begin_days, scene.obj_t_end_days])
    n = int(((ends > lo) & (ends <= hi)).sum())
    if n:
        from cityshade.geo.temporal import days_to_iso

        return (f"{n} object dates fall inside the run; the city is shown as it stood at "
                f"{days_to_iso(t_days) if math.isfinite(t_days) else 'any time'} throughout")
    return None


def plan_run(scene, instants, t_days: float, suns, weights, warnings: list[str]):
    """:func:`plan_units` of a run, with its warnings (sun never up, the city changing)."""
    units, below, duplicates = plan_units(suns, weights)
    if not units:
        warnings.append(f"the sun stays at or below the horizon in all {len(suns)} steps: "
                        f"nothing is lit, sun-hours are 0 everywhere")
    change = _city_changes(scene, instants, float(t_days))
    if change:
        warnings.append(change)
    return units, below, duplicates


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


def sun_hours(scene: "Scene", camera: "Camera | None", instants_utc: Sequence[datetime], t_days: float, *,
              weights_h=None, technique: str = "izb",
              settings: ShadowSettings | None = None,
              ground: str | None = None, spa=None, suns: Sequence | None = None,
              samples_per_m2: float | None = None, checkpoint: Checkpoint | None = None,
              reuse_rays: bool = True, on_step: Callable[[int, int, Unit], None] | None = None,
              on_frame: Callable[[Unit, np.ndarray, np.ndarray], None] | None = None,
              samples=None, stretches=None) -> SunHours:
    """Sun-hours per pixel of a fixed camera (and per surface) over many sun positions.

    Parameters
    ----------
    scene : Scene
        With its kd-tree.
    camera : Camera or None
        The view of the sun-hour map; None computes only per-surface values.
    instants_utc : sequence of aware datetime
        The instants of the steps (centres of their intervals).
    t_days : float
        City time (days since 1970-01-01 UTC): the city as it stood then is used for all
        steps (the camera pass is done once).
    weights_h : (N,) float, optional
        Hours each instant stands for; default: the spacing of evenly spaced instants.
    technique : str
        Shadow technique of the registry for the pixels (default ``izb``, exact). Surface
        samples are always exact: through ``raytrace``'s kd-tree when that is the technique,
        else through the light-space engine (the same answer).
    settings : ShadowSettings, optional
        The technique's tunables (``[shadows]``).
    ground : str, optional
        Ground plane where no surface is drawn ("min", "auto" or a height; see render).
    spa : cityshade.geo.sun.SpaSettings, optional
        Sun computation settings (refraction...).
    suns : sequence of SunPosition, optional
        Precomputed sun positions, one per instant (then no SPA and no CRS is needed).
    samples_per_m2 : float, optional
        With a value, also compute per-surface sun-hours from sample points at this density.
    checkpoint : Checkpoint, optional
        Resume from and save to this state: every ``CHECKPOINT_EVERY_S`` seconds, after the
        last sun position, and when the run stops (an exception, e.g. KeyboardInterrupt).
    reuse_rays : bool
        For ``izb`` and ``raytrace``: the oriented normals and shadow-ray origins of the
        pixels do not depend on the sun, so they are computed once with the camera pass and
        each step only selects the pixels facing the sun and traces them. The result is
        identical to running the technique per step (``False``), which is tested.
    on_step : callable(units_done, units_total, unit), optional
        Called after each position is accumulated (progress; an exception raised here, e.g.
        KeyboardInterrupt, stops the run with the state saved).
    on_frame : callable(unit, lit, valid), optional
        Receives each position's per-pixel lit fraction (for ``--frames``).
    samples : cityshade.sunhours.surfaces.SurfaceSamples, optional
        Surface samples to use instead of sampling at ``samples_per_m2`` (the same receivers
        in two runs, e.g. ``compare``).
    stretches : cityshade.sunhours.stretches.Stretches, optional
        Also keep every receiver's sunlit stretches (continuous sunshine) over the steps,
        which must be the instants' steps; returned as ``result.stretches``.

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
    from cityshade.frame.pipeline import shadow_pass
    from cityshade.shadows import get_technique

    t_start = time.perf_counter()
    if scene.kdtree is None and getattr(scene, "tiled", None) is None:
        raise UsageError("the scene file has no kd-tree; rebuild it with `cityshade build`")
    instants = list(instants_utc)
    if not instants:
        raise UsageError("a batch needs at least one instant")
    for t in instants:
        if not isinstance(t, datetime) or t.utcoffset() is None:
            raise UsageError(f"instants must be aware datetimes, not {t!r}")
    if math.isnan(float(t_days)):
        raise UsageError("t_days must be a number of days, not NaN")
    if camera is None and samples_per_m2 is None and samples is None:
        raise UsageError("nothing to compute: give a camera, samples_per_m2, or both")
    weights = step_weights(instants, weights_h)
    tech = get_technique(technique) if camera is not None else None
    timings = dict.fromkeys(("suns_s", "camera_s", "samples_s", "shadow_s", "surface_rays_s",
                             "checkpoint_s"), 0.0)
    warnings: list[str] = []

    # Sun positions: one SPA call for all instants, or the caller's.
    t0 = time.perf_counter()
    if suns is None:
        from cityshade.geo.sun import suns_from_instants

        suns = suns_from_instants(instants, scene.crs, scene.origin_m, spa)
    else:
        suns = list(suns)
        if len(suns) != len(instants):
            raise UsageError(f"give one sun per instant ({len(instants)}), not {len(suns)}")
    timings["suns_s"] = time.perf_counter() - t0
    units, below, duplicates = plan_run(scene, instants, t_days, suns, weights, warnings)

    # Camera pass, once.
    diagnostics: dict[str, Any] = {}
    cp, sampled = receivers_pass(scene, camera, t_days, ground,
                                 samples_per_m2 if samples is None else None, timings,
                                 diagnostics)
    samples = samples if samples is not None else sampled
    valid = cp.valid if cp is not None else None
    rays = _PixelRays(cp, technique) if cp is not None and reuse_rays and \
        technique in ("izb", "raytrace") else None

    # Running float64 sums, restored from a saved state when there is one.
    pixel_shape = valid.shape if valid is not None else (0, 0)
    pixel_sum = np.zeros(pixel_shape, np.float64)
    sample_sum = np.zeros(samples.n if samples is not None else 0, np.float64)
    done = 0
    if checkpoint is not None:
        state = checkpoint.load(len(units), pixel_shape, sample_sum.shape[0])
        if state is not None:
            done, pixel_sum, sample_sum = state
    if stretches is not None:
        stretches.plan(units, valid.shape if valid is not None else None, sample_sum.shape[0])
        if done:
            stretches.restore(checkpoint.extra)
    resumed = done

    # The state is saved every CHECKPOINT_EVERY_S, after the last position and when the run
    # stops (Ctrl-C, an error): saving after every position cost more than the shadows once
    # the sunlit stretches joined the state (2.1 M px: 54 s of 302 s on the 1M city).
    accumulated = done  # positions whose sums (and stretches) are complete
    saved = done
    last_save = time.perf_counter()

    def save() -> None:
        nonlocal saved, last_save
        t0 = time.perf_counter()
        checkpoint.save(accumulated, pixel_sum, sample_sum,
                        stretches.state() if stretches is not None else None)
        saved, last_save = accumulated, time.perf_counter()
        timings["checkpoint_s"] += last_save - t0

    consistent = True
    try:
        for k in range(done, len(units)):
            unit = units[k]
            lit = slit = None
            if camera is not None:
                t0 = time.perf_counter()
                if rays is not None:
                    lit = rays.lit(scene, unit.sun, float(t_days))
                else:
                    lit = shadow_pass(cp, unit.sun, tech, settings).lit
                timings["shadow_s"] += time.perf_counter() - t0
            if samples is not None:
                from cityshade.sunhours.surfaces import samples_lit

                t0 = time.perf_counter()
                slit = samples_lit(scene, samples, unit.sun, float(t_days),
                                   engine="raytrace" if technique == "raytrace" else "izb")
                timings["surface_rays_s"] += time.perf_counter() - t0
            # The sums change together: an interruption inside this block saves nothing.
            consistent = False
            if lit is not None:
                pixel_sum += unit.weight_h * lit.astype(np.float64)
            if slit is not None:
                sample_sum += unit.weight_h * slit.astype(np.float64)
            if stretches is not None:
                stretches.add(k, lit, slit)
            accumulated = k + 1
            consistent = True
            if lit is not None and on_frame is not None:
                on_frame(unit, lit, valid)
            if checkpoint is not None and (accumulated == len(units) or
                                           time.perf_counter() - last_save >= CHECKPOINT_EVERY_S):
                save()
            if on_step is not None:
                on_step(k + 1, len(units), unit)
    finally:
        # A run that stops (Ctrl-C, an error) keeps what it finished; a finished run has saved.
        if checkpoint is not None and consistent and accumulated > saved:
            save()

    if stretches is not None:
        stretches.finish()
    hours = None
    if camera is not None:
        hours = np.where(valid, pixel_sum, np.nan).astype(np.float32)
    sample_hours = polygon_hours = None
    if samples is not None:
        from cityshade.sunhours.surfaces import polygon_means

        sample_hours = sample_sum
        polygon_hours = polygon_means(samples, sample_sum)
    timings["total_s"] = time.perf_counter() - t_start
    below_set = set(below)
    return SunHours(hours=hours, valid=valid, surfaces=cp.surfaces if cp is not None else None,
                    samples=samples,
                    sample_hours=sample_hours, polygon_hours=polygon_hours, steps=len(suns),
                    steps_below_horizon=len(below), steps_duplicate=duplicates,
                    units=len(units), units_resumed=resumed,
                    hours_total=float(weights.sum()),
                    hours_sun_up=float(sum(w for i, w in enumerate(weights)
                                           if i not in below_set)),
                    suns=list(suns), timings_s=timings, diagnostics=diagnostics,
                    warnings=warnings, stretches=stretches)


def surface_sun_hours(scene, instants_utc: Sequence[datetime], t_days: float, *,
                      samples_per_m2: float = 1.0, **kwargs) -> SunHours:
    """Per-surface sun-hours only (no camera): :func:`sun_hours` with ``camera=None``; read
    ``polygon_hours`` (P,) and ``samples`` of the result."""
    return sun_hours(scene, None, instants_utc, t_days, samples_per_m2=samples_per_m2,
                     **kwargs)


# --- outputs ------------------------------------------------------------------------------------

#: Anchors of the viridis colour map (perceptually uniform, readable in grey and by the
#: colour-blind), at 0, 1/4, 1/2, 3/4 and 1; linear in between.
_VIRIDIS = np.array([(68, 1, 84), (59, 82, 139), (33, 145, 140), (94, 201, 98),
                     (253, 231, 37)], dtype=np.float64)
#: Colour of pixels without a surface in the PNG (white: most map pixels of a model without
#: terrain are empty, DESIGN §14).
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


def run_metadata(result: SunHours, scene, params: dict[str, Any]) -> dict[str, Any]:
    """Provenance of a batch's outputs (DESIGN §13.10)."""
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


def write_sun_hours(outdir, result: SunHours, scene, camera, meta: dict[str, Any],
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
        if getattr(scene, "tiled", None) is not None:  # a tiled cache's view: the global ids
            from cityshade.store.tiled import to_global

            channels["objid"] = to_global(scene.global_obj, channels["objid"])
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


# --- manifest ------------------------------------------------------------------------------------

def params_key(params: dict[str, Any]) -> str:
    """SHA-256 of the parameters as canonical JSON."""
    text = json.dumps(params, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def read_manifest(outdir) -> dict[str, Any] | None:
    """The manifest of OUTDIR, or None when there is none."""
    path = Path(outdir) / MANIFEST_NAME
    if not path.exists():
        return None
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise UsageError(f"{path} cannot be read ({exc}); re-run with --overwrite") from None


def write_manifest(outdir, manifest: dict[str, Any]) -> Path:
    """Write ``OUTDIR/manifest.json`` atomically."""
    from cityshade.util import write_text_atomic

    return write_text_atomic(Path(outdir) / MANIFEST_NAME,
                             json.dumps(manifest, indent=2, sort_keys=True) + "\n",
                             what="the manifest")


# --- a resumable run in an output folder ----------------------------------------------------------

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
    """

    result: SunHours
    written: list[Path]
    manifest: dict[str, Any]
    suns: list
    write_s: float


def _iso(instant: datetime) -> str:
    return instant.isoformat().replace("+00:00", "Z")


def frame_name(step: Step) -> str:
    """File name of a step's shadow mask in ``OUTDIR/frames``."""
    return f"step_{step.index:05d}_{step.centre_utc.strftime('%Y%m%dT%H%M%SZ')}.png"


def camera_params(camera: "Camera") -> dict[str, Any]:
    """The camera as it enters a run's parameter hash."""
    return {"kind": camera.kind, "width_px": camera.width_px, "height_px": camera.height_px,
            "eye_m": [float(v) for v in camera.eye_m],
            "target_m": [float(v) for v in camera.target_m],
            "vfov_deg": float(camera.vfov_deg), "pixel_size_m": camera.pixel_size_m}


def run_batch(outdir, scene: "Scene", camera: "Camera", steps: Sequence[Step], t_days: float, *,
              request: dict[str, Any] | None = None, technique: str = "izb",
              settings=None, ground: str | None = None, frames: bool = False,
              surfaces_csv: bool = False, overwrite: bool = False,
              on_plan: Callable[[int], None] | None = None,
              on_step: Callable[[int, int, Unit], None] | None = None,
              tile_px: int | None = None, scheduler: str | None = None,
              scene_path=None, step_month: Sequence[str] | None = None) -> BatchRun:
    """A resumable sun-hour run in ``outdir``: manifest, parameter hash, saved state, outputs.

    The parameters (``request``, the camera, technique, settings, ground, outputs) are hashed
    (:func:`params_key`) into the manifest; running again with the same parameters continues
    from the saved state (``state.npz``) without redoing finished sun positions and gives a
    bit-identical result; other parameters are refused unless ``overwrite``.

    Parameters
    ----------
    outdir : path-like
        Created when missing.
    scene, camera, t_days
        As for :func:`sun_hours`.
    steps : sequence of Step
        :func:`plan_steps`.
    request : dict, optional
        JSON-able description of the run from the caller (file, dates, zone...), part of the
        hash and the manifest.
    technique : str
    settings : cityshade.config.Settings, optional
        ``shadows`` for the technique, ``sun`` for SPA, ``batch`` for the surface samples.
    ground : str, optional
    frames : bool
        Also write every step's shadow mask to ``outdir/frames``.
    surfaces_csv : bool
        Also compute per-surface sun-hours (``settings.batch.samples_per_m2``) and write
        ``surfaces.csv``.
    overwrite : bool
        Discard a run of other parameters (or a state without manifest) in ``outdir``.
    on_plan : callable(units_to_compute), optional
        Called once the sun positions are known (progress bars).
    on_step : callable(units_done, units_total, unit), optional
        Called after each sun position (an exception raised here stops the run with the state
        saved). In a tiled run: after each task, ``(tasks_done, tasks_total, None)``.
    tile_px : int, optional
        Split the receivers into tiles of this many pixels a side (:mod:`cityshade.sunhours.tiled`);
        the result is identical.
    scheduler : str or cityshade.sunhours.distributed.DaskExecutor, optional
        ``local[:N]`` or ``tcp://HOST:PORT``: run the tasks on Dask (:mod:`cityshade.sunhours.distributed`);
        needs ``scene_path``, which every worker memory-maps. An executor object is used as
        it is (e.g. with another number of threads per worker).
    step_month : sequence of str, optional
        A month label per step: also write per-month sun-hours (``monthly/``).

    Raises
    ------
    UsageError
        ``outdir`` holds a run of other parameters (the message names what differs) or a
        state without manifest, and not ``overwrite``.
    OutputError
        ``outdir`` cannot be created or written.
    """
    import dataclasses

    from cityshade.config import Settings
    from cityshade.geo.sun import suns_from_instants
    from types import SimpleNamespace

    from cityshade.frame.pipeline import check_frame_memory
    from cityshade.util import check_outputs, make_folder, output_group

    settings = settings or Settings()
    outdir = Path(outdir)
    samples_per_m2 = settings.batch.samples_per_m2 if surfaces_csv else None
    params = {**(request or {}), "city_days": float(t_days), "camera": camera_params(camera),
              "technique": technique, "ground": ground,
              "refraction": bool(settings.sun.refraction), "frames": frames,
              "samples_per_m2": samples_per_m2,
              **({"tile_px": tile_px} if tile_px is not None or scheduler is not None
                 or step_month is not None else {}),
              **({"monthly": True} if step_month is not None else {}),
              "stretches": True,
              "shadow_settings": dataclasses.asdict(dataclasses.replace(settings.shadows,
                                                                        technique=None))}
    key = params_key(params)
    if camera is not None:
        # Before any work; a tiled run holds one tile's frame at a time (its sums are small).
        view = camera if tile_px is None else SimpleNamespace(
            width_px=min(tile_px, camera.width_px), height_px=min(tile_px, camera.height_px),
            kind=camera.kind)
        check_frame_memory(view, technique=technique, batch=True)
    check_outputs(("-o", outdir, None))  # a folder that can be written, before any work
    old = read_manifest(outdir)
    state = Checkpoint(outdir / STATE_NAME, key)
    if old is not None and old.get("key") != key:
        if not overwrite:
            before = old.get("params", {})
            changed = sorted(k for k in set(params) | set(before) if params.get(k) != before.get(k))
            raise UsageError(f"{outdir} holds a run with other parameters (differs in: "
                             f"{', '.join(changed) or 'version'}); use --overwrite or another "
                             f"-o folder")
        state.remove()
    elif old is None and state.path.exists():
        if not overwrite:
            raise UsageError(f"{state.path} has no manifest next to it; use --overwrite")
        state.remove()
    state_warning = None
    if old is not None and state.path.exists():
        # The manifest holds the checksum of the last state saved: a truncated or altered state
        # is discarded and its steps are computed again, never half-read.
        expected = old.get("state_sha256") or []
        found = state.file_sha256()
        if found not in expected:
            state_warning = (f"the saved state {state.path} is damaged (its checksum does not "
                             f"match the manifest); the unfinished steps start again")
            state.remove()
        else:
            state.sha256 = found

    manifest: dict[str, Any] = {
        "cityshade_version": __version__, "key": key, "params": params, "status": "running",
        "steps": [{"index": s.index, "start_utc": _iso(s.start_utc), "end_utc": _iso(s.end_utc),
                   "weight_h": s.weight_h} for s in steps],
        "finished_steps": [],
    }
    if state.sha256 is not None:
        manifest["state_sha256"] = [state.sha256]
    write_manifest(outdir, manifest)

    from cityshade.sunhours.distributed import MANIFEST_EVERY_S

    progress = {"done": None, "written_s": time.perf_counter()}

    def note_progress():
        if progress["done"] is not None:
            manifest["finished_steps"] = sorted(finished)
            manifest["sun_positions_done"] = progress["done"]

    def before_state_write(digest):
        note_progress()  # the state about to be written holds these positions
        manifest["state_sha256"] = [h for h in (state.sha256, digest) if h is not None]
        write_manifest(outdir, manifest)
        progress["written_s"] = time.perf_counter()

    state.before_write = before_state_write
    frames_dir = outdir / "frames"
    if frames:
        make_folder(frames_dir)

    instants = [s.centre_utc for s in steps]
    weights = [s.weight_h for s in steps]
    t_suns = time.perf_counter()
    suns = suns_from_instants(instants, scene.crs, scene.origin_m, settings.sun)
    suns_s = time.perf_counter() - t_suns  # the whole run's suns in one vectorised call
    units, below, _ = plan_units(suns, weights)
    finished: list[int] = list(below)  # nothing to compute for a sun below the horizon
    done_before = state.units_done()
    for unit in units[:done_before]:
        finished.extend(unit.steps)
    if on_plan is not None:
        on_plan(len(units) - done_before)

    def step_done(done, total, unit):
        finished.extend(unit.steps)
        progress["done"] = done
        # Written every MANIFEST_EVERY_S, with every state save and at the end: the indented
        # JSON of a day's steps costs 25-30 ms (a year's far more), and a resume reads the
        # state, not this progress.
        if done == total or time.perf_counter() - progress["written_s"] >= MANIFEST_EVERY_S:
            note_progress()
            if state.sha256 is not None:
                manifest["state_sha256"] = [state.sha256]
            write_manifest(outdir, manifest)
            progress["written_s"] = time.perf_counter()
        if on_step is not None:
            on_step(done, total, unit)

    def frame_done(unit, lit, valid):
        from cityshade.imageio import mask_from_lit, write_mask_png

        mask = mask_from_lit(lit, valid)
        for i in unit.steps:
            write_mask_png(frames_dir / frame_name(steps[i]), mask)

    from cityshade.sunhours.stretches import Stretches

    tiled = None
    if tile_px is not None or scheduler is not None or step_month is not None:
        from cityshade.sunhours.distributed import run_tiled

        result, tiled = run_tiled(scene, camera, instants, t_days, weights_h=weights, suns=suns,
                                  units=units, technique=technique, ground=ground,
                                  samples_per_m2=samples_per_m2, checkpoint=state,
                                  tile_px=tile_px, scheduler=scheduler, scene_path=scene_path,
                                  step_month=step_month, workdir=outdir, frames=frames,
                                  finished=finished, manifest=manifest,
                                  write_manifest=lambda: write_manifest(outdir, manifest),
                                  on_step=on_step, stretches=Stretches.for_steps(steps))
    else:
        result = sun_hours(scene, camera, instants, t_days, weights_h=weights,
                           technique=technique, settings=settings.shadows, ground=ground,
                           suns=suns, samples_per_m2=samples_per_m2, checkpoint=state,
                           reuse_rays=settings.batch.reuse_rays, on_step=step_done,
                           on_frame=frame_done if frames else None,
                           stretches=Stretches.for_steps(steps))
    result.timings_s["suns_s"] = suns_s
    if state_warning is not None:
        result.warnings.insert(0, state_warning)
    if frames and below:
        from cityshade.imageio import mask_from_lit, write_mask_png

        # The sun is down: every surface pixel is in shadow, the rest stays nodata.
        nothing_lit = mask_from_lit(np.zeros(result.valid.shape), result.valid)
        for i in below:
            write_mask_png(frames_dir / frame_name(steps[i]), nothing_lit)
    meta = run_metadata(result, scene, params)
    t1 = time.perf_counter()
    with output_group():  # the maps, surfaces.csv and the tiled extras appear together
        written = write_sun_hours(outdir, result, scene, camera, meta,
                                  surfaces_csv=surfaces_csv, cog=tiled is not None)
        if tiled is not None:
            from cityshade.sunhours.distributed import write_tiled_extras

            written += write_tiled_extras(outdir, tiled, result, scene, camera, meta)
    write_s = time.perf_counter() - t1
    manifest["status"] = "finished"
    manifest["finished_steps"] = sorted(finished)
    manifest["summary"] = {
        "steps": result.steps, "steps_below_horizon": result.steps_below_horizon,
        "steps_same_sun": result.steps_duplicate, "sun_positions": result.units,
        "sun_positions_resumed": result.units_resumed, "hours_total": result.hours_total,
        "hours_sun_up": result.hours_sun_up,
        "outputs": [p.name for p in written],
        "timings_s": {**result.timings_s, "write_s": write_s},
    }
    write_manifest(outdir, manifest)
    return BatchRun(result=result, written=written, manifest=manifest, suns=suns,
                    write_s=write_s)
