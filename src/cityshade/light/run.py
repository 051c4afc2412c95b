"""The typed request of a sky run (sky view factor, irradiance from a weather file) and the run
itself: receivers once (the batch's camera pass and surface samples), split into tiles as a
batch's are (:func:`cityshade.sunhours.tiled.plan_tiles`); per tile the sky's visibility, its
metrics and the hours of the weather file (:func:`sky_tile`), here or on Dask workers (the
batch's :class:`~cityshade.sunhours.distributed.DaskExecutor`); finished tiles kept in the
output folder's state (the batch's :class:`~cityshade.sunhours.checkpoint.Checkpoint`), so
an interrupted run resumes; then the outputs written together
(:mod:`cityshade.light.outputs`). Built by ``cityshade sky`` or a Python caller.

Every value of a receiver is computed from that receiver alone (its bits, its planes' weights
summed in direction order, its hours in hour order), so any split into tiles gives the same
numbers bit for bit."""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from collections.abc import Mapping
from typing import Any

import numpy as np

from cityshade.errors import UsageError

#: Leaf states the sky view factor can be taken in (deciduous crowns in leaf or leafless).
SEASONS = ("leaf_on", "leaf_off")

__all__ = ["SkyRequest", "SkyResult", "SkyRun", "SkyWork", "compute_sky", "run_sky",
           "sky_tile", "sky_params", "sky_bytes_per_receiver", "CROWN_RAY_SHARE"]

#: Share of a receiver's directions whose rays cross a tree crown (and no opaque triangle),
#: counted by the memory estimate of a scene with vegetation at 24 B a ray
#: (:class:`~cityshade.light.visibility.SkyCrowns`): the number is known only after tracing.
#: Measured on the Berlin-Lichtenberg trees and buildings (docs/DESIGN.md §18), rounded up.
CROWN_RAY_SHARE = 0.08


@dataclass(frozen=True)
class SkyRequest:
    """One sky run.

    Where
        ``camera`` (the map or view, as batch's; None: surfaces only), ``samples_per_m2``
        (per-surface values at this density; None: no surfaces), ``ground`` (batch's ground
        plane option).
    When
        ``t_days`` (the city's state, days since 1970-01-01 UTC).
    How
        ``sky`` (:func:`cityshade.light.sky.named_sky`), ``technique`` (an exact one, default
        ``exact`` as in every command: its engine traces the sky and the suns), ``spa`` (sun settings).
    What
        ``svf`` (the sky view factor's outputs), ``vsc`` (the vertical sky component of
        every receiver on its own plane,
        :func:`~cityshade.light.metrics.vertical_sky_component`), ``season`` (``leaf_on`` or
        ``leaf_off``: the deciduous crowns of the sky view factor and the VSC; the irradiance
        takes each hour's own leaf state), ``weather`` (a
        :class:`~cityshade.light.weather.Weather`: irradiance), ``hours`` ((H,) bool of the
        weather hours to sum; None: all, the file's year), ``period`` (False: no kWh/m² over
        the hours, only the instants), ``model``, ``albedo``;
        ``instants`` (aware datetimes: W/m² at each, from the weather record of the hour
        containing it with the sun at the instant) and their ``instant_labels`` (``0900``:
        the files' and columns' names).
    Outputs
        ``provenance`` (JSON-able, in the files' metadata and the run's identity), ``decorate``
        (map PNGs with scale bar, north, CRS, title, colour bar), ``gis`` (``results.gpkg`` of
        the surfaces and buildings).
    Execution (as a batch's)
        ``tile_px`` (the map's pixels and the surface samples in tiles of N × N pixels, each a
        task, resumable; None: one tile), ``scheduler`` (Dask: ``local[:N]``, an address, or
        a :class:`~cityshade.sunhours.distributed.DaskExecutor`), ``scene_path`` (the cache
        file the workers map).
    """

    camera: Any = None
    samples_per_m2: float | None = None
    ground: str | None = None
    t_days: float = 0.0
    sky: str = "reinhart2305"
    technique: str = "exact"
    spa: Any = None
    svf: bool = True
    vsc: bool = False
    season: str = "leaf_on"
    weather: Any = None
    hours: Any = None
    model: str = "perez"
    albedo: float = 0.2
    period: bool = True
    instants: tuple = ()
    instant_labels: tuple = ()
    provenance: Mapping[str, Any] | None = None
    decorate: bool = True
    gis: bool = True
    tile_px: int | None = None
    scheduler: Any = None
    scene_path: Any = None

    @property
    def engine(self) -> str:
        from cityshade.sunhours.request import exact_engine

        return exact_engine(self.technique, "sky view factors and irradiance")

    def check(self, scene=None, outputs: bool = True) -> None:
        """Refuse a request with nothing to compute or an unknown sky, model or technique
        (``outputs`` False: not what it computes, which the CLI checks before it reads the
        weather file and the scene)."""
        from cityshade.light.irradiance import SKY_MODELS
        from cityshade.light.sky import named_sky

        if outputs and self.camera is None and self.samples_per_m2 is None:
            raise UsageError("nothing to compute: give a camera, samples_per_m2, or both")
        if outputs and not (self.svf or self.vsc) and self.weather is None:
            raise UsageError("nothing to compute: ask for the sky view factor, the vertical "
                             "sky component or irradiance (with a weather file)")
        if len(self.instants) != len(self.instant_labels):
            raise UsageError("every instant needs its label")
        if self.instants and self.weather is None:
            raise UsageError("irradiance at instants needs a weather file")
        if self.model not in SKY_MODELS:
            raise UsageError(f"the sky model is one of {', '.join(SKY_MODELS)}, not "
                             f"{self.model!r}")
        if self.season not in SEASONS:
            raise UsageError(f"the season of the sky view factor is one of "
                             f"{', '.join(SEASONS)}, not {self.season!r}")
        named_sky(self.sky)
        self.engine  # noqa: B018 - an inexact technique fails here, before any work
        from cityshade.sunhours.request import check_execution

        check_execution(self.technique, self.tile_px, self.scheduler, False, False)
        if scene is not None:
            from cityshade.sunhours.request import check_scene

            check_scene(scene)


@dataclass
class SkyResult:
    """Per-receiver answers of a sky run: map pixels first (``pixels`` into the camera's
    frame), then surface samples.

    ``svf`` (N,), ``irradiation`` (:class:`~cityshade.light.irradiance.Irradiation` or
    None), ``shape`` (H, W) of the map or None, ``pixels`` (M,) flat indices, ``cp`` the camera
    pass, ``samples`` the surface samples or None, ``sky`` the directions used,
    ``bytes_per_receiver`` (the estimate), ``timings_s``, ``warnings``.
    """

    svf: np.ndarray
    irradiation: Any
    shape: tuple | None
    pixels: np.ndarray
    cp: Any
    samples: Any
    sky: Any
    bytes_per_receiver: int
    #: (K, N, 3) W/m² (direct, diffuse, reflected) at the request's instants, or None.
    instants_w_m2: Any = None
    #: (N,) vertical sky component (fraction) of every receiver on its own plane, or None.
    vsc: Any = None
    timings_s: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    #: How the run went: tiles, tile size, tiles taken from the saved state, receivers, rays
    #: through crowns, Dask workers and the tiles the driver ran while they started.
    tiles: dict[str, Any] = field(default_factory=dict)

    @property
    def n_pixels(self) -> int:
        return len(self.pixels)

    def map_of(self, values: np.ndarray) -> np.ndarray:
        """(H, W) float32 of the per-pixel part of ``values`` (N,), NaN where no surface."""
        out = np.full(int(np.prod(self.shape)), np.nan, np.float32)
        out[self.pixels] = values[:self.n_pixels]
        return out.reshape(self.shape)

    def sample_values(self, values: np.ndarray) -> np.ndarray:
        return values[self.n_pixels:]


@dataclass
class SkyRun:
    """Result of :func:`run_sky`: the ``result`` (None when ``already_complete``: the folder
    held this very run, finished, its outputs all there, and nothing was computed), the
    output files ``written`` and the ``manifest``."""

    result: SkyResult | None
    written: list[Path]
    manifest: dict[str, Any]
    already_complete: bool = False


def sky_bytes_per_receiver(n_directions: int, irradiance: bool, instants: int = 0,
                           crowns: bool = False) -> int:
    """Bytes per receiver of the tile being traced, beside the batch's camera pass
    (:data:`cityshade.frame.pipeline.BATCH_BYTES_PER_PX`): point and normal (48), the packed
    bits (ceil(P / 8)), one direction's ray origins and rows while tracing (32) and eight
    directions' answers held (1), the view factor and two shares (24), the plane index (8),
    the VSC (8); with irradiance the three
    float64 sums (24), the sun's bits and origins per hour (25); per instant its three float64
    W/m² (24). With vegetation (``crowns``) the rays through crowns, 24 B each
    (:class:`~cityshade.light.visibility.SkyCrowns`), for :data:`CROWN_RAY_SHARE` of the
    directions (their number is known only after tracing), and 17 B of a direction's results.

    With the camera pass, 290 + 140 B per map pixel for 145 directions and 290 + 189 B with
    irradiance; measured (``python benchmarks/memory.py --cases sky:tregenza,irradiance:tregenza
    --pixels 500000,2000000 --steps 2``, e5e5e42, the sample city): 327 and 426 B per pixel.
    """
    from cityshade.light.visibility import SkyCrowns

    crown = 17 + math.ceil(SkyCrowns.NBYTES * CROWN_RAY_SHARE * n_directions) if crowns else 0
    return 48 + (n_directions + 7) // 8 + 32 + 1 + 24 + 8 + 8 \
        + (49 if irradiance or instants else 0) + 24 * int(instants) + crown


def _value_columns(request: SkyRequest) -> dict[str, slice]:
    """The float64 columns a sky run keeps per receiver for its whole run, by name: ``svf``,
    ``vsc``, ``irradiation`` (direct, diffuse, reflected kWh/m²), ``instants`` (direct,
    diffuse, reflected W/m² of each instant)."""
    widths = {"svf": 1}
    if request.vsc:
        widths["vsc"] = 1
    if request.weather is not None and request.period:
        widths["irradiation"] = 3
    if request.instants:
        widths["instants"] = 3 * len(request.instants)
    cols, at = {}, 0
    for name, w in widths.items():
        cols[name] = slice(at, at + w)
        at += w
    return cols


def _kept_bytes_per_receiver(request: SkyRequest) -> int:
    """Bytes a sky run keeps of every receiver across its tiles: point and normal (48), its
    slot and place (16), its values (8 per column of :func:`_value_columns`)."""
    return 48 + 16 + 8 * max(c.stop for c in _value_columns(request).values())


def _check_memory(request: SkyRequest, n_directions: int, n_samples_max: int,
                  crowns: bool = False) -> tuple[int, int]:
    """Refuse a run whose receivers would not fit, before any work: the camera's frame
    (batch's estimate), what is kept of every receiver (:func:`_kept_bytes_per_receiver`) and
    the work of one tile's receivers (:func:`sky_bytes_per_receiver`; every pixel of the
    camera counted as a receiver), together. Returns (the bytes per receiver of a tile, the
    estimate in bytes)."""
    from cityshade.frame.pipeline import available_memory_bytes, frame_bytes

    per = sky_bytes_per_receiver(n_directions, request.weather is not None and request.period,
                                 len(request.instants), crowns)
    n, frame, tile_n = n_samples_max, 0, n_samples_max
    if request.camera is not None:
        frame = frame_bytes(request.camera, batch=True)[0]
        n += request.camera.width_px * request.camera.height_px
        tile_n = n
        if request.tile_px is not None:
            tile_n = min(request.camera.width_px, request.tile_px) * \
                min(request.camera.height_px, request.tile_px)
    kept = _kept_bytes_per_receiver(request) if request.tile_px is not None else 0
    have = available_memory_bytes()
    need = frame + n * kept + tile_n * per
    if have is not None and need > have:
        each = f"{per} bytes each" if not kept else \
            f"{kept} bytes each kept and {per} each of a tile's {tile_n:,} while it is traced"
        raise UsageError(f"{n:,} receivers need about {need / 1e9:.1f} GB ({each} besides the "
                         f"camera's {frame / 1e9:.1f} GB) but "
                         f"{have / 1e9:.1f} GB are available: use a larger --pixel-size, fewer "
                         f"--samples-per-m2"
                         + (", a smaller --tile-px" if kept else "") + " or a coarser --sky")
    return per, need


@dataclass(frozen=True)
class SkyWork:
    """What every tile of a sky run needs besides its receivers; picklable (it goes to the
    Dask workers with :func:`sky_tile`): the ``request`` (without camera, provenance and
    scheduler), the ``sky``, the engine, the sun of every weather hour and of every instant."""

    request: SkyRequest
    sky: Any
    weather_directions: Any = None
    instant_directions: Any = None


#: Per tile: hours summed, sun hours traced, rays through crowns, sky seconds, hours seconds.
N_STATS = 5


def receiver_values(scene, work: SkyWork, points: np.ndarray, normals: np.ndarray, *,
                    progress=None) -> tuple[np.ndarray, np.ndarray]:
    """The sky's visibility of the receivers, their view factors and shares, VSC and
    irradiance: ``(values (N, C) float64`` in the columns of :func:`_value_columns`, ``stats
    (N_STATS,) float64)``. ``progress(phase, done, total)`` with phase ``sky`` (directions) or
    ``hours``."""
    from cityshade.light.irradiance import irradiation, sky_shares
    from cityshade.light.visibility import sky_visibility

    request = work.request
    cols = _value_columns(request)
    values = np.zeros((len(points), max(c.stop for c in cols.values())))
    stats = np.zeros(N_STATS)
    t0 = time.perf_counter()
    vis = sky_visibility(scene, points, normals, work.sky, request.t_days, engine=request.engine,
                         progress=None if progress is None else
                         (lambda d, t: progress("sky", d, t)))
    svf, *shares = sky_shares(vis, leaf=request.season == "leaf_on")
    values[:, cols["svf"]] = svf[:, None]
    if request.vsc:
        from cityshade.light.metrics import vertical_sky_component

        values[:, cols["vsc"]] = vertical_sky_component(
            vis, leaf=request.season == "leaf_on")[:, None]
    leafless = None
    if vis.crowns is not None:
        stats[2] = len(vis.crowns.rows)
        if request.weather is not None:
            # The irradiance takes each weather hour's leaf state: the shares of both.
            shares = sky_shares(vis, leaf=True)[1:]
            leafless = sky_shares(vis, leaf=False)[1:]
    del vis
    stats[3] = time.perf_counter() - t0
    t0 = time.perf_counter()
    shares_by_leaf = shares if leafless is None else {True: shares, False: leafless}
    if request.instants:
        from cityshade.light.irradiance import irradiance_at

        at = irradiance_at(scene, points, normals, request.weather, request.instants,
                           work.instant_directions, shares_by_leaf, t_days=request.t_days,
                           engine=request.engine, model=request.model, albedo=request.albedo)
        values[:, cols["instants"]] = at.transpose(1, 0, 2).reshape(len(points), -1)
    if request.weather is not None and request.period:
        irr = irradiation(scene, points, normals, request.weather, work.weather_directions,
                          shares_by_leaf, hours=request.hours, t_days=request.t_days,
                          engine=request.engine, model=request.model, albedo=request.albedo,
                          progress=None if progress is None else
                          (lambda d, t: progress("hours", d, t)))
        values[:, cols["irradiation"]] = np.stack(
            [irr.direct_kwh_m2, irr.diffuse_kwh_m2, irr.reflected_kwh_m2], axis=1)
        stats[0], stats[1] = irr.hours, irr.sun_hours_traced
    stats[4] = time.perf_counter() - t0
    return values, stats


def sky_tile(scene, data, lo: int, hi: int, work: SkyWork, *,
             progress=None) -> tuple[np.ndarray, np.ndarray]:
    """One task of a sky run: :func:`receiver_values` of receivers ``lo:hi`` of ``data``
    ((N, 6) float64 point and normal, a tile plan's; memory-mapped on a Dask worker). Then
    the scene's file pages the tile read leave the resident set
    (:func:`~cityshade.store.scenefile.release_scene_pages`): a tile's low directions read
    far across the city, and without this the 10^7-triangle city's tiles kept 1.9 of its
    2.1 GB cache file resident (2.6 GB peak for 0.6 GB of work)."""
    from cityshade.store.scenefile import release_scene_pages

    block = np.asarray(data[lo:hi], dtype=np.float64)
    out = receiver_values(scene, work, np.ascontiguousarray(block[:, :3]),
                          np.ascontiguousarray(block[:, 3:]), progress=progress)
    release_scene_pages(scene)
    return out


def _executor(scene, request: SkyRequest):
    """The Dask executor of ``request.scheduler`` (None: the tiles run here)."""
    scheduler = request.scheduler
    if scheduler is None or not isinstance(scheduler, str):
        return scheduler
    from cityshade.sunhours.distributed import DaskExecutor

    if request.scene_path is None:
        raise UsageError("a distributed sky run needs the scene's cache file path")
    sha = (scene.header or {}).get("source", {}).get("sha256", "")
    return DaskExecutor(scheduler, request.scene_path, sha)


def compute_sky(scene, request: SkyRequest, *, progress=None, checkpoint=None, workdir=None,
                on_plan=None, on_tile=None, on_note=None, on_memory=None,
                save_every_s: float | None = None) -> SkyResult:
    """Receivers, then per tile the sky's visibility, the view factors and shares, the
    irradiance (:func:`sky_tile`), here or on Dask (``request.scheduler``).

    Parameters
    ----------
    progress : callable(phase, done, total), optional
        Within the one tile of an untiled run (``request.tile_px`` None, no scheduler):
        phase ``sky`` (directions) or ``hours``.
    checkpoint : cityshade.sunhours.checkpoint.Checkpoint, optional
        The finished tiles' values, loaded when it holds some (the run resumes) and saved
        every ``save_every_s`` seconds and when the run stops (Ctrl-C included).
    workdir : path-like, optional
        Where a Dask run writes ``receivers.npy`` for its workers (the output folder).
    on_plan : callable(tiles_to_run, tiles_total), optional
    on_tile : callable(tiles_done, tiles_total), optional
        After each finished tile.
    on_note : callable(text), optional
        Told that the run resumes and how much was done before.
    on_memory : callable(bytes), optional
        Told the memory estimate (:func:`_check_memory`) before any work.
    """
    from cityshade.geometry.vegetation import scene_vegetation
    from cityshade.light.sky import sky_for_scene
    from cityshade.store.scenefile import release_scene_pages
    from cityshade.sunhours.accumulate import receivers_pass
    from cityshade.sunhours.checkpoint import SaveThrottle

    request.check(scene)
    timings: dict[str, float] = {"checkpoint_s": 0.0}
    sky = sky_for_scene(scene, request.sky)
    per, need = _check_memory(request, sky.n, 0, scene_vegetation(scene) is not None)
    if on_memory is not None:
        on_memory(need)
    cp, samples = receivers_pass(scene, request.camera, request.t_days, request.ground,
                                 request.samples_per_m2, timings, {})
    release_scene_pages(scene)  # the camera pass read every triangle of the map: let them go
    tile_px = request.tile_px
    plan, place, pixels = _plan(cp, samples, request.camera, tile_px)
    shape = None if cp is None else tuple(cp.valid.shape)
    cols = _value_columns(request)
    n, n_tiles = len(plan.data), plan.n_tiles
    tile_done, values, tile_stats = _saved_tiles(checkpoint, n_tiles, n, cols, on_note)
    warnings: list[str] = []
    if request.weather is not None:
        from cityshade.light.weather import scene_location_warning

        warning = scene_location_warning(request.weather, scene)
        if warning:
            warnings.append(warning)
    work = _work(scene, request, sky)
    todo = [t for t in range(n_tiles) if not tile_done[t]]
    if on_plan is not None:
        on_plan(len(todo), n_tiles)
    throttle = SaveThrottle(None if checkpoint is None else (
        lambda: checkpoint.save_arrays(int(tile_done.sum()), tile_done=tile_done, values=values,
                                       tile_stats=tile_stats)), timings, save_every_s)
    counts = {"done": n_tiles - len(todo), "new": 0}

    def finished(t: int, out) -> None:
        a, b = int(plan.start[t]), int(plan.start[t + 1])
        throttle.consistent = False  # a tile half written: nothing is saved
        values[place[a:b]] = out[0]
        tile_stats[t] = out[1]
        tile_done[t] = True
        throttle.consistent = True
        counts["done"] += 1
        counts["new"] += 1
        throttle.maybe()
        if on_tile is not None:
            on_tile(counts["done"], n_tiles)

    executor = _executor(scene, request)
    inner = progress if executor is None and tile_px is None else None
    t0 = time.perf_counter()
    completed = False
    try:
        if executor is None:
            for t in todo:
                finished(t, sky_tile(scene, plan.data, int(plan.start[t]),
                                     int(plan.start[t + 1]), work, progress=inner))
        else:
            if hasattr(executor, "start"):
                executor.start(scene, None, float(request.t_days), request.technique)
            executor.run_tasks(plan, sky_tile, [(t, t, (work,)) for t in todo], workdir,
                               finished, lambda t: f"skytile{t}")
        completed = True
    finally:
        if executor is not None and hasattr(executor, "close"):
            executor.close()
        timings["tiles_s"] = time.perf_counter() - t0
        if throttle.consistent and not completed and counts["new"]:
            throttle.save()
    timings["sky_s"] = float(tile_stats[:, 3].sum())
    if request.weather is not None:
        timings["hours_s"] = float(tile_stats[:, 4].sum())
    return SkyResult(svf=values[:, 0].copy(), shape=shape, pixels=pixels, cp=cp,
                     samples=samples, sky=sky, bytes_per_receiver=per, timings_s=timings,
                     warnings=warnings, **_unpacked(request, values, tile_stats),
                     tiles={"tiles": n_tiles, "tile_px": tile_px,
                            "tiles_resumed": n_tiles - len(todo), "receivers": n,
                            "crown_rays": int(tile_stats[:, 2].sum()),
                            "workers": getattr(executor, "workers", 0),
                            "tasks_on_driver": getattr(executor, "tasks_on_driver", 0)})


def _plan(cp, samples, camera, tile_px):
    """(tile plan, place of each planned receiver in the untiled order, the map's pixels with
    a surface): batch's tiles, or one tile of every receiver without ``tile_px`` (the sky
    traced once for all, as before tiles)."""
    from cityshade.light.visibility import map_pixels
    from cityshade.sunhours.tiled import plan_receivers

    pixels = np.zeros(0, np.int64) if cp is None else map_pixels(cp)
    plan = plan_receivers(cp, samples, camera, tile_px)
    if tile_px is None:
        plan.start = np.array([0, len(plan.data)], np.int64)
        # One tile: the plan is in the untiled order already.
        return plan, np.arange(len(plan.data)), pixels
    # The untiled order: the map's pixels row-major, then the samples.
    n_px = plan.pixel_shape[0] * plan.pixel_shape[1]
    place = np.where(plan.slot < n_px, np.searchsorted(pixels, plan.slot),
                     len(pixels) + plan.slot - n_px)
    return plan, place, pixels


def _saved_tiles(checkpoint, n_tiles: int, n: int, cols: dict, on_note):
    """(tile_done (T,) bool, values (N, C), tile_stats (T, N_STATS)): zeros, or the saved
    state's (the run resumes; ``on_note`` told how much was done)."""
    from cityshade.util import plural

    arrays = (np.zeros(n_tiles, bool), np.zeros((n, max(c.stop for c in cols.values()))),
              np.zeros((n_tiles, N_STATS)))
    names = ("tile_done", "values", "tile_stats")
    saved = None if checkpoint is None else checkpoint.load_arrays(names)
    if saved is None:
        return arrays
    if any(saved[k].shape != a.shape for k, a in zip(names, arrays)):
        checkpoint.refuse_misfit()
    tile_done, values, tile_stats = (saved["tile_done"].astype(bool),
                                     saved["values"].astype(np.float64),
                                     saved["tile_stats"].astype(np.float64))
    if tile_done.any() and on_note is not None:
        on_note(f"resuming the run in {Path(checkpoint.path).parent}: "
                f"{int(tile_done.sum())} of {plural(n_tiles, 'tile')} were done before")
    return tile_done, values, tile_stats


def _unpacked(request: SkyRequest, values: np.ndarray, tile_stats: np.ndarray) -> dict:
    """The ``vsc``, ``irradiation`` and ``instants_w_m2`` of a :class:`SkyResult` from the
    run's value columns (:func:`_value_columns`)."""
    cols = _value_columns(request)
    out: dict[str, Any] = {"vsc": None, "irradiation": None, "instants_w_m2": None}
    if "irradiation" in cols:
        from cityshade.light.irradiance import Irradiation

        kwh = values[:, cols["irradiation"]]
        # Every tile sums the same hours; the hours some tile traced, at least.
        out["irradiation"] = Irradiation(
            direct_kwh_m2=kwh[:, 0].copy(), diffuse_kwh_m2=kwh[:, 1].copy(),
            reflected_kwh_m2=kwh[:, 2].copy(), hours=int(tile_stats[:, 0].max(initial=0)),
            sun_hours_traced=int(tile_stats[:, 1].max(initial=0)), model=request.model,
            albedo=float(request.albedo))
    if "instants" in cols:
        out["instants_w_m2"] = values[:, cols["instants"]].reshape(
            len(values), -1, 3).transpose(1, 0, 2).copy()
    if "vsc" in cols:
        out["vsc"] = values[:, cols["vsc"].start].copy()
    return out


def _work(scene, request: SkyRequest, sky) -> SkyWork:
    """The tiles' common inputs: the suns of the weather hours and of the instants, once."""
    import dataclasses

    weather_dirs = instant_dirs = None
    if request.weather is not None and request.period:
        from cityshade.light.sunlight import weather_suns

        weather_dirs = weather_suns(request.weather, scene, request.spa)[0]
    if request.instants:
        from cityshade.geo.sun import suns_from_instants

        suns = suns_from_instants(list(request.instants), scene.crs, scene.origin_m,
                                  request.spa)
        instant_dirs = np.array([s.direction for s in suns], np.float64).reshape(-1, 3)
    return SkyWork(request=dataclasses.replace(request, camera=None, provenance=None,
                                               scheduler=None),
                   sky=sky, weather_directions=weather_dirs, instant_directions=instant_dirs)


def sky_params(request: SkyRequest) -> dict[str, Any]:
    """The identity of a sky run (what a resume compares, hashed by
    :func:`cityshade.sunhours.checkpoint.params_key`): the caller's provenance, the city's
    date, camera, technique, ground, sky, season, outputs, weather hours, model, albedo,
    instants, sun settings and the tile size. In the form the manifest gives back (JSON)."""
    import dataclasses
    import hashlib
    import json

    from cityshade.sunhours.run import camera_params

    hours = None
    if request.hours is not None:
        hours = hashlib.sha256(np.packbits(np.asarray(request.hours, bool)).tobytes()
                               ).hexdigest()
    params = {**(request.provenance or {}), "city_days": float(request.t_days),
              "camera": None if request.camera is None else camera_params(request.camera),
              "technique": request.technique, "ground": request.ground, "sky": request.sky,
              "svf": request.svf, "vsc": request.vsc, "season": request.season,
              "weather_hours": None if request.weather is None else int(request.weather.n_hours),
              "hours": hours, "period": request.period, "model": request.model,
              "albedo": float(request.albedo), "samples_per_m2": request.samples_per_m2,
              "instants": [t.isoformat() for t in request.instants],
              "spa": None if request.spa is None else dataclasses.asdict(request.spa),
              "decorate": request.decorate, "gis": request.gis,
              **({"tile_px": request.tile_px} if request.tile_px is not None else {})}
    return json.loads(json.dumps(params, default=str))


def run_sky(outdir, scene, request: SkyRequest, *, overwrite: bool = False, progress=None,
            on_plan=None, on_tile=None, on_note=None, on_memory=None) -> SkyRun:
    """A resumable sky run of ``request`` in ``outdir``, as a batch's
    (:func:`cityshade.sunhours.run.run_batch`): the folder locked while it lasts, the finished
    tiles saved in ``state.npz`` with ``manifest.json`` holding the run's identity
    (:func:`sky_params`) and the state's checksum; the same request again resumes
    (``on_note`` says so), another is refused unless ``overwrite``, a finished one with its
    outputs all there computes nothing (:attr:`SkyRun.already_complete`). Then the outputs
    (:func:`cityshade.light.outputs.write_sky_outputs`) together: all of them or, on an
    error or Ctrl-C, none; the state is removed once they are written.

    ``progress``, ``on_plan``, ``on_tile``, ``on_memory``: :func:`compute_sky`'s.
    """
    from cityshade import __version__
    from cityshade.light.outputs import write_sky_outputs
    from cityshade.sunhours.checkpoint import (finished_outputs, open_state, params_key,
                                               relative_output, write_manifest)
    from cityshade.util import check_outputs, folder_lock

    outdir = Path(outdir)
    request.check(scene)
    params = sky_params(request)
    check_outputs(("-o", outdir, None))
    with folder_lock(outdir, on_note):
        found = finished_outputs(outdir, params, __version__, overwrite)
        if found is not None:
            return SkyRun(result=None, written=found[0], manifest=found[1],
                          already_complete=True)
        state, warning = open_state(outdir, params, overwrite)
        manifest: dict[str, Any] = {"cityshade_version": __version__, "key": params_key(params),
                                    "params": params, "status": "running"}

        def before_state_write(digest: str) -> None:
            # The manifest is written with the first state (a run stopped before any tile
            # finished leaves nothing) and knows the new state's checksum before it lands.
            manifest["state_sha256"] = [h for h in (state.sha256, digest) if h is not None]
            write_manifest(outdir, manifest)

        state.before_write = before_state_write
        result = compute_sky(scene, request, progress=progress, checkpoint=state,
                             workdir=outdir, on_plan=on_plan, on_tile=on_tile, on_note=on_note,
                             on_memory=on_memory)
        if warning is not None:
            result.warnings.insert(0, warning)
        t0 = time.perf_counter()
        written = write_sky_outputs(outdir, scene, request, result)
        result.timings_s["write_s"] = time.perf_counter() - t0
        # The state served a resume; removed before the manifest stops naming it.
        state.remove()
        manifest.pop("state_sha256", None)
        manifest["status"] = "finished"
        manifest["summary"] = {"outputs": [relative_output(p, outdir) for p in written],
                               "tiles": result.tiles, "timings_s": result.timings_s}
        write_manifest(outdir, manifest)
    return SkyRun(result=result, written=written, manifest=manifest)
