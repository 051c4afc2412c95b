"""Tiled batches: the receivers of a batch split into disjoint tiles, tasks of tile × sun block.

A batch's receivers are the surface points whose sun-hours it sums: the map's pixels (the
camera pass, done once) and the surface samples of ``--surfaces``. Both get the same exact
per-step rule as the untiled run (:func:`cityshade.sunhours.accumulate.compute`,
:func:`cityshade.sunhours.surfaces.samples_lit`): a receiver is lit when its oriented normal faces the
sun and its shadow ray is free. That rule reads one receiver at a time, so any split of the
receivers gives the same booleans; the sums are float64 added in the order of the sun
positions for every receiver, so a tiled run equals the untiled one bit for bit.

Layout: the receivers are stored tile by tile, each tile a contiguous range of one
(N, 6) float64 array (point, normal), written once to ``OUTDIR/receivers.npy`` so that
the workers of a distributed run memory-map it (:mod:`cityshade.sunhours.distributed`); ``slot``
maps each receiver to its place in one flat vector of sums (the H × W pixels, then the
samples). A task is (tile, block of sun positions); it returns the lit bits of its receivers
for each position of the block, packed, and the driver adds them in position order
(:func:`accumulate`, the one place where a step's result enters the sums).

Casters: each tile's shadow rays reach only the casters within its sun-ward sweep. The
light-space engine (``izb``) culls the casters to the light-plane box of the rays it is given,
so a tile pays for its own sweep only. Through the kd-tree (``raytrace``) a ray visits only
the nodes it crosses; :func:`halo_m` gives the horizontal reach of that sweep, (highest caster
− lowest receiver) / tan(lowest sun elevation), which the manifest reports per run.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
from numba import njit

from cityshade.errors import UsageError
from cityshade.sunhours.checkpoint import SaveThrottle
from cityshade.sunhours.request import SunHoursRequest

__all__ = ["TilePlan", "plan_tiles", "plan_receivers", "receiver_lit", "task_lit", "accumulate", "add_lit", "halo_m",
           "tiled_sun_hours", "run_tiled", "RECEIVERS_NAME"]

RECEIVERS_NAME = "receivers.npy"


@dataclass
class TilePlan:
    """Receivers stored tile by tile.

    Attributes
    ----------
    data : (N, 6) float64
        Point (render-space metres) and unit normal (turned to the seen side) of every receiver.
    slot : (N,) int64
        Index of each receiver in the flat sums: ``row * W + col`` for a pixel, ``H·W + i`` for
        surface sample ``i``.
    start : (T + 1,) int64
        Tile ``t`` holds receivers ``start[t]:start[t + 1]``.
    n_slots : int
        ``H·W + samples``.
    pixel_shape : (H, W)
    n_samples : int
    tile_px : int or None
    """

    data: np.ndarray
    slot: np.ndarray
    start: np.ndarray
    n_slots: int
    pixel_shape: tuple[int, int]
    n_samples: int
    tile_px: int | None

    @property
    def n_tiles(self) -> int:
        return int(self.start.shape[0] - 1)


def _grid_order(ij: np.ndarray, extra: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(order, tile key of each sorted item) for items with integer tile coordinates (N, 2)."""
    if ij.shape[0] == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    lo = ij.min(axis=0)
    rel = ij - lo
    key = rel[:, 0] * (int(rel[:, 1].max()) + 1) + rel[:, 1]
    order = np.argsort(key, kind="stable")
    return order, key[order]


def plan_tiles(valid: np.ndarray | None, points_px: np.ndarray | None,
               normals_px: np.ndarray | None, sample_points: np.ndarray | None,
               sample_normals: np.ndarray | None, tile_px: int | None,
               sample_tile_m: float) -> TilePlan:
    """Split the receivers into tiles of ``tile_px`` × ``tile_px`` pixels (and the samples into
    squares of ``sample_tile_m`` in plan); ``tile_px=None``: one tile of pixels, one of samples.

    Parameters
    ----------
    valid : (H, W) bool or None
        Pixels showing a surface (None: no camera).
    points_px, normals_px : (H, W, 3) float64 or None
    sample_points, sample_normals : (S, 3) float64 or None
    tile_px : int or None
    sample_tile_m : float
        Plan size of a sample tile, metres.
    """
    if tile_px is not None and int(tile_px) < 1:
        raise UsageError(f"--tile-px must be >= 1, not {tile_px}")
    shape = (0, 0) if valid is None else tuple(int(v) for v in valid.shape)
    n_pixels = shape[0] * shape[1]
    # (points, normals, their rows in tile order, the rows' slots, tile keys or None for one
    # tile); the plan's rows are gathered once into one array (a 1 m map's 2.14 M pixels:
    # 0.7 s of fresh pages for the copies a gather per part and a concatenation made).
    sources = []
    if valid is not None:
        flat = np.flatnonzero(np.asarray(valid, bool))          # row-major, as np.nonzero
        keys = None
        if tile_px is not None:
            rows, cols = np.divmod(flat, shape[1])
            order, keys = _grid_order(np.column_stack([rows // tile_px, cols // tile_px]))
            flat = flat[order]
        sources.append((points_px, normals_px, flat, flat, keys))
    n_samples = 0 if sample_points is None else int(sample_points.shape[0])
    if n_samples:
        order, keys = np.arange(n_samples), None
        if tile_px is not None:
            ij = np.floor(np.asarray(sample_points, np.float64)[:, :2]
                          / float(sample_tile_m)).astype(np.int64)
            order, keys = _grid_order(ij)
        sources.append((sample_points, sample_normals, order, n_pixels + order.astype(np.int64),
                        keys))
    n = sum(src[2].shape[0] for src in sources)
    data = np.empty((n, 6))
    slot = np.empty(n, np.int64)
    starts = [0]
    for points, normals, rows, slots, keys in sources:
        q, k = starts[-1], rows.shape[0]
        np.take(np.asarray(points, np.float64).reshape(-1, 3), rows, axis=0,
                out=data[q:q + k, :3], mode="clip")
        np.take(np.asarray(normals, np.float64).reshape(-1, 3), rows, axis=0,
                out=data[q:q + k, 3:], mode="clip")
        slot[q:q + k] = slots
        # Tiles are runs of equal key in sorted order.
        if keys is not None:
            starts.extend(q + int(c) for c in np.flatnonzero(np.diff(keys)) + 1)
        if k:
            starts.append(q + k)
    return TilePlan(data=data, slot=slot, start=np.asarray(starts, np.int64),
                    n_slots=n_pixels + n_samples, pixel_shape=shape, n_samples=n_samples,
                    tile_px=None if tile_px is None else int(tile_px))


def receiver_lit(scene, points: np.ndarray, normals: np.ndarray, direction: np.ndarray,
                 t_days: float, engine: str, receivers=None) -> np.ndarray:
    """(N,) bool: the receiver faces the sun (N·L > 0, the shared rule) and its shadow ray
    (:func:`cityshade.trace.shadow_rays_from_surface`) is free; the untiled batch's rule.
    ``receivers``: the same points as a :class:`cityshade.lightspace.SurfaceReceivers`, whose
    one pass gives the same origins bit for bit (as the untiled run makes them)."""
    from cityshade.shadows import facing_mask
    from cityshade.trace import shadow_rays_from_surface

    faces = facing_mask(normals, True, direction)
    lit = np.zeros(points.shape[0], bool)
    if faces.any():
        if receivers is not None:
            origins = receivers.origins(direction, faces)
        else:
            origins = shadow_rays_from_surface(points[faces], normals[faces], direction)
        from cityshade.shadows.visibility import occluded

        lit[faces] = ~occluded(scene, origins, direction, t_days, engine=engine)
    return lit


def task_lit(scene, data: np.ndarray, lo: int, hi: int, directions: np.ndarray,
             t_days: float, engine: str) -> np.ndarray:
    """One task: (K, ceil((hi − lo) / 8)) uint8, the packed lit bits of receivers ``lo:hi`` of
    ``data`` for each of the K sun directions."""
    from cityshade.lightspace import SurfaceReceivers

    block = np.asarray(data[lo:hi], dtype=np.float64)
    points = np.ascontiguousarray(block[:, :3])
    normals = np.ascontiguousarray(block[:, 3:])
    # Checked and offset once per task; per sun one pass makes the facing receivers' origins.
    receivers = SurfaceReceivers(points, normals) if hi > lo else None
    out = np.zeros((directions.shape[0], (hi - lo + 7) // 8), np.uint8)
    for k in range(directions.shape[0]):
        direction = np.ascontiguousarray(directions[k], dtype=np.float64)
        out[k] = np.packbits(receiver_lit(scene, points, normals, direction, t_days, engine,
                                          receivers))
    return out


@njit(cache=True)
def add_lit(sums, slots, weights_h, lit):
    """``sums[row, slots[i]] += weights_h[row] * (1.0 if lit[i] else 0.0)`` for each row with a
    weight: numpy's fancy-indexed ``+=`` of :func:`accumulate` as one pass (the same float64
    product and sum per element, so bit for bit the same)."""
    for row in range(weights_h.shape[0]):
        w = weights_h[row]
        if w > 0.0:
            for i in range(slots.shape[0]):
                sums[row, slots[i]] += w * (1.0 if lit[i] else 0.0)


def accumulate(sums: np.ndarray, slots: np.ndarray, weights_h: np.ndarray,
               lit: np.ndarray) -> None:
    """Add one sun position's result: ``sums[row, slots] += weights_h[row] · lit`` for each
    row (the total and, with ``--monthly``, the month) with a weight.

    The same float64 products as the untiled run (weight · 1.0 or weight · 0.0), added in the
    order of the sun positions (:func:`add_lit`; its numpy twin is in ``tests/reference.py``)."""
    add_lit(sums, np.ascontiguousarray(slots, np.int64),
            np.ascontiguousarray(weights_h, np.float64), np.ascontiguousarray(lit, np.bool_))


def sun_blocks(directions: np.ndarray, block: int) -> list[tuple[int, int]]:
    """The sun positions cut into runs ``[lo, hi)`` of at most ``block`` that each keep one
    caster order of the light-space engine (:func:`cityshade.lightspace.caster_order`).

    Tasks run block by block over the tiles, so a block that crossed an order change made
    every tile sort the casters twice (once per order) where an untiled run sorts once: 40
    sorts of the 10^7-triangle city (2-5 s each) per such block of its 20 tiles, half the
    tiled day's time."""
    from cityshade.lightspace import caster_order

    orders = [caster_order(d) for d in directions]
    blocks: list[tuple[int, int]] = []
    lo = 0
    for k in range(1, len(orders) + 1):
        if k == len(orders) or k - lo == block or orders[k] != orders[lo]:
            blocks.append((lo, k))
            lo = k
    return blocks


def halo_m(scene, lowest_receiver_z_m: float, elevations_deg: Sequence[float]) -> float:
    """Horizontal reach of a receiver's shadow rays over the run: (highest caster − lowest
    receiver) / tan(lowest sun elevation above the horizon); 0 without a sun up."""
    up = [float(e) for e in elevations_deg if e > 0.0]
    if not up or not scene.can_trace:
        return 0.0
    # A tiled cache's view: the whole city's top.
    hi = scene.tiling.source.box_m[1] if scene.is_tiled else scene.kdtree.box_scale_m()[1]
    rise = max(0.0, float(hi[2]) - float(lowest_receiver_z_m))
    return rise / math.tan(math.radians(min(up)))


# --- the tiled run ----------------------------------------------------------------------------

@dataclass
class TiledState:
    """Where a tiled run stands: per tile, how many sun positions are added, and the sums."""

    tile_done: np.ndarray      # (T,) int64
    sums: np.ndarray           # (1 + months, n_slots) float64
    #: Per tile, the arrays of its sunlit stretches (:meth:`cityshade.sunhours.stretches.Stretches.state`).
    stretches: dict[int, dict[str, np.ndarray]] = field(default_factory=dict)


def _load_state(checkpoint, n_tiles: int, n_units: int, shape: tuple[int, int]):
    """A saved tiled state that fits, else None
    (:meth:`cityshade.sunhours.checkpoint.Checkpoint.load_arrays`)."""
    z = None if checkpoint is None else checkpoint.load_arrays(("tile_done", "sums"))
    if z is None:
        return None
    tile_done = z["tile_done"].astype(np.int64, copy=False)
    sums = z["sums"].astype(np.float64, copy=False)
    stretches: dict[int, dict[str, np.ndarray]] = {}
    for name, value in z.items():
        if name.startswith("st") and "_" in name and name[2:name.index("_")].isdigit():
            stretches.setdefault(int(name[2:name.index("_")]), {})[name[name.index("_") + 1:]] \
                = value
    if tile_done.shape != (n_tiles,) or sums.shape != shape or \
            not ((tile_done >= 0) & (tile_done <= n_units)).all():
        checkpoint.refuse_misfit()
    return TiledState(tile_done, sums, stretches)


def _save_state(checkpoint, state: TiledState, parts=None) -> None:
    """Atomically, the manifest told the new checksum first; ``units_done`` is what every
    tile has added (what :meth:`cityshade.sunhours.checkpoint.Checkpoint.units_done` reads); with
    ``parts``, each tile's sunlit stretches as ``st{tile}_{name}``."""
    done = int(state.tile_done.min()) if state.tile_done.size else 0
    extra = {f"st{t}_{k}": v for t, part in enumerate(parts or ())
             for k, v in part.state().items()}
    checkpoint.save_arrays(done, tile_done=state.tile_done, sums=state.sums, **extra)


@dataclass
class TiledRun:
    """What :func:`tiled_sun_hours` adds to :class:`cityshade.sunhours.accumulate.SunHours`."""

    plan: TilePlan
    month_hours: dict[str, np.ndarray] = field(default_factory=dict)
    month_sample_hours: dict[str, np.ndarray] = field(default_factory=dict)
    tasks: int = 0
    tasks_resumed: int = 0
    halo_m: float = 0.0


def _resume(checkpoint, plan: TilePlan, units, n_rows: int, pixel_shape, stretches):
    """The run's state (saved, or zeros) and each tile's sunlit stretches (None without)."""
    n_tiles = plan.n_tiles
    state = _load_state(checkpoint, n_tiles, len(units), (n_rows, plan.n_slots))
    if state is None:
        state = TiledState(np.zeros(n_tiles, np.int64), np.zeros((n_rows, plan.n_slots),
                                                                   np.float64))
    parts = None
    if stretches is not None:
        stretches.plan(units, pixel_shape, plan.n_samples)
        parts = [stretches.part(int(plan.start[t + 1] - plan.start[t]))
                 for t in range(n_tiles)]
        for t, part in enumerate(parts):
            if state.tile_done[t]:
                part.restore(state.stretches.get(t, {}))
    return state, parts


def plan_receivers(cp, samples, camera, tile_px: int | None) -> TilePlan:
    """:func:`plan_tiles` of a camera pass's pixels (``cp``, or None) and surface samples
    (or None): the samples in squares as wide as a tile of the map's pixels (1 m a pixel for
    a perspective view). A batch's and a sky run's tiles."""
    pixel_m = float(camera.pixel_size_m) if camera is not None and camera.kind == "map" else 1.0
    return plan_tiles(None if cp is None else cp.valid,
                      None if cp is None else cp.surfaces.position_m,
                      None if cp is None else cp.normal,
                      None if samples is None else samples.points_m,
                      None if samples is None else samples.normals,
                      tile_px, (tile_px or 1) * pixel_m)


def _plan_receivers(scene, request: SunHoursRequest, prep) -> tuple[TilePlan, float]:
    """The receivers of a prepared run in tiles, and the reach of their shadow rays."""
    plan = plan_receivers(prep.cp, prep.samples, request.camera, request.tile_px)
    low_z = float(plan.data[:, 2].min()) if plan.data.shape[0] else 0.0
    return plan, halo_m(scene, low_z, [u.sun.elevation_deg for u in prep.units])


def _tiled_result(prep, run: TiledRun, state: TiledState, months: list[str], parts,
                  stretches, units_resumed: int):
    """The SunHours of a finished tiled run (and ``run``'s per-month hours); the stretches of
    the tiles merged."""
    from cityshade.sunhours.accumulate import make_result

    plan, cp, samples = run.plan, prep.cp, prep.samples
    n_px = plan.pixel_shape[0] * plan.pixel_shape[1]

    def pixels(row):
        return np.where(cp.valid, row[:n_px].reshape(plan.pixel_shape), np.nan
                        ).astype(np.float32)

    if parts is not None:
        for part in parts:
            part.finish()
        stretches.merge(parts, [plan.slot[plan.start[t]:plan.start[t + 1]]
                                for t in range(plan.n_tiles)])
    for m, month in enumerate(months):
        if cp is not None:
            run.month_hours[month] = pixels(state.sums[1 + m])
        if samples is not None:
            from cityshade.sunhours.surfaces import polygon_means

            run.month_sample_hours[month] = polygon_means(samples, state.sums[1 + m, n_px:])
    return make_result(prep, pixels(state.sums[0]) if cp is not None else None,
                       state.sums[0, n_px:].copy() if samples is not None else None,
                       units_resumed, stretches)


def _run_engine(engine: str, scene, rays_per_task: int, tasks: int, diagnostics: dict) -> str:
    """The run's exact engine: ``exact`` chosen once for the whole run (fresh workers would
    never see a warm caster sort), the choice and why in ``diagnostics`` (``batch -v``)."""
    if engine != "exact":
        return engine
    from cityshade.shadows.exact import describe_choices, run_choice

    choice = run_choice(scene, rays_per_task, tasks)
    diagnostics["engine"] = describe_choices([choice], "tasks")
    return choice.engine


def tiled_sun_hours(scene, request: SunHoursRequest, *, checkpoint=None, executor=None,
                    workdir=None, on_plan: Callable[[int], None] | None = None,
                    on_task: Callable[[int, int, list, int], None] | None = None,
                    stretches=None, save_every_s: float | None = None):
    """:func:`cityshade.sunhours.accumulate.sun_hours` over tiles of receivers (and optionally
    per month): ``request.tile_px`` (None: one tile), ``request.block`` sun positions per task,
    ``request.step_month`` (a YYYY-MM label per step: also sum per month); the technique must
    be exact.

    Parameters
    ----------
    scene : Scene
    request : cityshade.sunhours.request.SunHoursRequest
    checkpoint : cityshade.sunhours.checkpoint.Checkpoint, optional
        Saved every ``save_every_s`` seconds (default ``CHECKPOINT_EVERY_S``) and when the
        run stops (Ctrl-C included).
    executor : cityshade.sunhours.distributed.DaskExecutor, optional
        Runs the tasks elsewhere; default: here, in order.
    workdir : path-like, optional
        Where ``receivers.npy`` is written for the workers of ``executor``.
    on_plan : callable(tasks_to_run)
    on_task : callable(tasks_done, tasks_total, units_finished, units_done)
        After each task is added; ``units_finished`` lists the sun positions (Unit) that
        every tile has now added, ``units_done`` counts them all.
    stretches : cityshade.sunhours.stretches.Stretches, optional
        Also keep the sunlit stretches: each tile replays its own receivers' steps in time
        order (its blocks arrive in sun-position order), so every receiver sees the steps of
        the untiled run; merged at the end (``result.stretches``). Kept for the whole run,
        not per month.

    Returns
    -------
    (SunHours, TiledRun)
    """
    from cityshade.sunhours.accumulate import prepare
    from cityshade.sunhours.plan import unit_month_weights
    from cityshade.sunhours.request import exact_engine

    engine = exact_engine(request.technique, "--tile-px, --scheduler and --monthly")
    prep = prepare(scene, request, ("suns_s", "camera_s", "samples_s", "shadow_s",
                                    "accumulate_s", "checkpoint_s"))
    cp, units, t_days = prep.cp, prep.units, float(request.t_days)
    months, unit_w = unit_month_weights(units, prep.weights, request.step_month)
    plan, reach = _plan_receivers(scene, request, prep)
    n_tiles, n_units = plan.n_tiles, len(units)
    state, parts = _resume(checkpoint, plan, units, 1 + len(months),
                           None if cp is None else plan.pixel_shape, stretches)
    directions = np.array([np.asarray(u.sun.direction, np.float64) for u in units]
                          ).reshape(n_units, 3)
    blocks = sun_blocks(directions, request.block)
    # Tasks of a tile whose first sun positions are saved resume at the saved count. Block by
    # block over the tiles: the light-space engine re-sorts its casters when the sun's dominant
    # axis changes, i.e. a few times a day in sun order, but that many times per tile if each
    # tile ran through the day alone (12 sorts instead of 3 for 4 tiles of the 1M city); and
    # no block crosses such a change (sun_blocks).
    tasks = [(t, max(lo, int(state.tile_done[t])), hi) for lo, hi in blocks
             for t in range(n_tiles) if hi > state.tile_done[t]]
    total = n_tiles * len(blocks)
    resumed_tasks = total - len(tasks)
    engine = _run_engine(engine, scene, plan.n_slots // max(n_tiles, 1), max(len(tasks), 1),
                         prep.diagnostics)
    if on_plan is not None:
        on_plan(len(tasks))
    units_resumed = int(state.tile_done.min()) if n_tiles else n_units
    progress = {"units": units_resumed, "tasks": resumed_tasks}
    pending: dict[int, dict[int, np.ndarray]] = {t: {} for t in range(n_tiles)}
    throttle = SaveThrottle(None if checkpoint is None else
                            (lambda: _save_state(checkpoint, state, parts)),
                            prep.timings, save_every_s)

    def add(t: int, lo: int, bits: np.ndarray) -> None:
        a, b = int(plan.start[t]), int(plan.start[t + 1])
        for k in range(bits.shape[0]):
            lit = np.unpackbits(bits[k], count=b - a).view(np.bool_)
            throttle.consistent = False  # a sun position half added: nothing is saved
            accumulate(state.sums, plan.slot[a:b], unit_w[lo + k], lit)
            if parts is not None:
                parts[t].add(lo + k, lit, None)
            state.tile_done[t] = lo + k + 1
            throttle.consistent = True

    def finished(t: int, lo: int, bits: np.ndarray) -> None:
        # Blocks of one tile are added in sun-position order; a block that comes early waits.
        pending[t][lo] = bits
        while int(state.tile_done[t]) in pending[t]:
            start = int(state.tile_done[t])
            t0 = time.perf_counter()
            add(t, start, pending[t].pop(start))
            prep.timings["accumulate_s"] += time.perf_counter() - t0
            progress["tasks"] += 1
            now_done = int(state.tile_done.min())
            newly = units[progress["units"]:now_done]
            progress["units"] = now_done
            throttle.maybe()
            if on_task is not None:
                on_task(progress["tasks"], total, newly, now_done)

    t0 = time.perf_counter()
    completed = False
    try:
        if executor is None:
            for t, lo, hi in tasks:
                a, b = int(plan.start[t]), int(plan.start[t + 1])
                finished(t, lo, task_lit(scene, plan.data, a, b, directions[lo:hi], t_days,
                                         engine))
        else:
            executor.run(plan, tasks, directions, t_days, engine, workdir, finished)
        completed = True
    finally:
        prep.timings["shadow_s"] = time.perf_counter() - t0
        if throttle.consistent and (tasks or not completed):
            throttle.save()

    run = TiledRun(plan=plan, tasks=total, tasks_resumed=resumed_tasks, halo_m=reach)
    prep.diagnostics["tiles"] = {"tiles": n_tiles, "tile_px": plan.tile_px, "tasks": total,
                                 "sun_positions_per_task": request.block, "halo_m": reach,
                                 "receivers": int(plan.data.shape[0])}
    result = _tiled_result(prep, run, state, months, parts, stretches, units_resumed)
    return result, run


def run_tiled(scene, request: SunHoursRequest, *, checkpoint=None, progress=None,
              workdir=None, on_step=None, stretches=None):
    """The tiled run of :func:`cityshade.sunhours.run.run_batch`, here or on Dask
    (``request.scheduler``): (SunHours, TiledRun).

    Parameters
    ----------
    progress : cityshade.sunhours.checkpoint.ManifestProgress, optional
        Told each task's finished sun positions; written when the run stops.
    on_step : callable(tasks_done, tasks_total, None), optional
    """
    import contextlib

    from cityshade.errors import CityshadeError

    request.check(scene)
    scheduler, executor = request.scheduler, None
    if scheduler is not None and not isinstance(scheduler, str):
        executor, scheduler = scheduler, getattr(scheduler, "spec", "executor")
    elif scheduler is not None:
        from cityshade.sunhours.distributed import DaskExecutor

        if request.scene_path is None:
            raise UsageError("a distributed batch needs the scene's cache file path")
        sha = (scene.header or {}).get("source", {}).get("sha256", "")
        executor = DaskExecutor(scheduler, request.scene_path, sha)

    def on_task(done, total, newly, units_done):
        if progress is not None:
            progress.advance(done, total, [i for u in newly for i in u.steps],
                             units_done if newly else None, tasks=True)
        if on_step is not None:
            on_step(done, total, None)

    if hasattr(executor, "start"):
        first = next((s.direction for s in request.suns or () if s.above_horizon), None)
        executor.start(scene, first, float(request.t_days), request.technique)
    elif hasattr(executor, "connect"):
        executor.connect()
    try:
        result, run = tiled_sun_hours(scene, request, checkpoint=checkpoint, executor=executor,
                                      workdir=workdir, on_task=on_task, stretches=stretches)
    except BaseException:
        if progress is not None:
            with contextlib.suppress(OSError, CityshadeError):  # the first error is told
                progress.write()  # the progress of a stopped run, as far as it got
        raise
    finally:
        if hasattr(executor, "close"):
            executor.close()
    if executor is not None:
        result.diagnostics["tiles"]["scheduler"] = scheduler
        result.diagnostics["tiles"]["workers"] = getattr(executor, "workers", 0)
        result.diagnostics["tiles"]["tasks_on_driver"] = getattr(executor, "tasks_on_driver", 0)
    return result, run
