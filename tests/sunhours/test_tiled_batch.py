"""Tiled, distributed and monthly batches: the same numbers as the untiled run, bit for bit."""
from __future__ import annotations

import json
import os
from datetime import date, timezone

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city, ground

from cityshade.sunhours import checkpoint as C
from cityshade.sunhours import plan as P
from cityshade.sunhours import run as R
from cityshade.sunhours.request import SunHoursRequest
from cityshade.errors import UsageError
from cityshade.sunhours.tiled import plan_tiles

X0, Y0, Z0 = 691_000.0, 5_334_000.0, 520.0
REPO_SAMPLE = "sample_data/sample_city.gml"


class Stop(Exception):
    pass


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """Two boxes on a plane (shadows across tile borders) and the sample city, built once."""
    from pathlib import Path

    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("tiles")
    src = tmp / "boxes.gml"
    src.write_text(city(ground(X0 - 60, Y0 - 60, X0 + 60, Y0 + 60, Z0),
                        building("a", box_polygons(X0 - 5, Y0 - 5, Z0, 10, 10, 20.0, "a")),
                        building("b", box_polygons(X0 + 20, Y0 + 8, Z0, 6, 12, 9.0, "b"))))
    boxes, _, _ = build_file(src, tmp / "boxes.cityshade")
    sample, _, _ = build_file(Path(__file__).parents[2] / REPO_SAMPLE, tmp / "sample.cityshade")
    return boxes, sample


def _steps(day=date(2024, 6, 21), every_s=5400, **kw):
    return P.plan_steps(day, P.parse_clock_s("04:00"), P.parse_clock_s("22:00"), every_s,
                        "Europe/Berlin", **kw)


def _run(path, outdir, technique="izb", steps=None, **kw):
    from cityshade.raster.camera import map_view
    from cityshade.store.scenefile import load_scene

    scene = load_scene(path)
    cam = map_view(scene, 2.0)
    run_kw = {k: kw.pop(k) for k in ("overwrite", "on_plan", "on_step") if k in kw}
    if kw.get("step_month") is not None:
        kw["step_month"] = tuple(kw["step_month"])
    request = SunHoursRequest.from_settings(steps or _steps(), 0.0, surfaces=True, camera=cam,
                                            technique=technique, ground="auto", **kw)
    return R.run_batch(outdir, scene, request, **run_kw)


@pytest.fixture(scope="module")
def sample_plain(files, tmp_path_factory):
    """The sample city's plain run that the distributed runs are checked against."""
    return _run(files[1], tmp_path_factory.mktemp("plain"), steps=_steps(every_s=5400))


def _same_stretches(a, b):
    """The sunlit stretches of two runs, bit for bit (pixels and samples)."""
    sa, sb = a.result.stretches, b.result.stretches
    assert sa is not None and sb is not None and sa.finished and sb.finished
    assert sa.pixel_longest_h().tobytes() == sb.pixel_longest_h().tobytes()
    assert sa.samples.longest_h.tobytes() == sb.samples.longest_h.tobytes()


def test_plan_tiles_splits_receivers_into_disjoint_squares():
    rng = np.random.default_rng(3)
    valid = rng.random((23, 37)) < 0.6
    pts = rng.random((23, 37, 3))
    nrm = rng.random((23, 37, 3))
    samples = rng.random((50, 3)) * 30.0
    plan = plan_tiles(valid, pts, nrm, samples, -samples, tile_px=8, sample_tile_m=10.0)
    n_px = 23 * 37
    # Every valid pixel and every sample exactly once, carrying its own point and normal.
    assert sorted(plan.slot.tolist()) == sorted(np.flatnonzero(valid.ravel()).tolist()
                                                + list(range(n_px, n_px + 50)))
    px = plan.slot < n_px
    r, c = np.divmod(plan.slot[px], 37)
    assert np.array_equal(plan.data[px, :3], pts[r, c])
    assert np.array_equal(plan.data[px, 3:], nrm[r, c])
    assert np.array_equal(plan.data[~px, :3], samples[plan.slot[~px] - n_px])
    # Tiles are contiguous runs inside one 8 × 8 square (or one 10 m square of samples).
    assert plan.start[0] == 0 and plan.start[-1] == plan.data.shape[0]
    assert plan.n_tiles == 5 * 3 + len(np.unique(np.floor(samples[:, :2] / 10.0), axis=0))
    for t in range(plan.n_tiles):
        s = plan.slot[plan.start[t]:plan.start[t + 1]]
        assert len(s) > 0
        if s[0] < n_px:
            rr, cc = np.divmod(s, 37)
            assert len(set(rr // 8)) == 1 and len(set(cc // 8)) == 1
        else:
            ij = np.floor(samples[s - n_px, :2] / 10.0)
            assert len(np.unique(ij, axis=0)) == 1
    one = plan_tiles(valid, pts, nrm, None, None, tile_px=None, sample_tile_m=1.0)
    assert one.n_tiles == 1
    with pytest.raises(UsageError, match="--tile-px"):
        plan_tiles(valid, pts, nrm, None, None, tile_px=0, sample_tile_m=1.0)


def test_accumulate_equals_numpy_fancy_add_bit_for_bit():
    from reference import reference_accumulate

    from cityshade.sunhours.tiled import accumulate

    rng = np.random.default_rng(11)
    sums = rng.random((3, 500)) * 40.0
    slots = rng.permutation(500)[:321]
    # Weights of odd sizes (a short last step, sums of steps), one row without weight.
    weights = np.array([0.1666666666666667, 0.0, 0.07500000000000001])
    before = sums.copy()
    expected = sums.copy()
    for _ in range(4):
        lit = rng.random(321) < 0.5
        expected = reference_accumulate(expected, slots, weights, lit)
        accumulate(sums, slots, weights, lit)
    assert sums.tobytes() == expected.tobytes()
    changed = (sums != before).any(axis=1)
    assert changed.tolist() == [True, False, True]  # the row without weight stays as it was


def test_tiled_exact_run_says_its_one_engine_choice(files, tmp_path, monkeypatch):
    from cityshade.shadows import exact as E

    monkeypatch.setattr(E, "izb_compiled", lambda: False)
    tiled = _run(files[0], tmp_path / "tiled", "exact", tile_px=7)
    note = tiled.result.diagnostics["engine"]
    # One choice for the whole run; its tasks are few and small: raytrace, izb uncompiled.
    assert note.startswith("exact engine raytrace: ") and "izb not compiled yet" in note


@pytest.mark.parametrize("technique", ["izb", "raytrace"])
def test_tiled_run_equals_untiled_bit_for_bit(files, tmp_path, technique):
    boxes, _ = files
    plain = _run(boxes, tmp_path / "plain", technique)
    tiled = _run(boxes, tmp_path / "tiled", technique, tile_px=7)
    assert tiled.result.diagnostics["tiles"]["tiles"] > 20
    assert plain.result.hours.tobytes() == tiled.result.hours.tobytes()
    assert plain.result.sample_hours.tobytes() == tiled.result.sample_hours.tobytes()
    assert (tmp_path / "plain" / "surfaces.csv").read_bytes() == \
        (tmp_path / "tiled" / "surfaces.csv").read_bytes()
    # Shadows cross the tile borders: some pixels lit less than the full day.
    hours = plain.result.hours
    assert np.nanmax(hours) > np.nanmin(hours) + 1.0
    # The sunlit stretches too, and the EXR carries them.
    _same_stretches(plain, tiled)
    longest = plain.result.stretches.pixel_longest_h()[plain.result.valid]
    assert longest.max() > longest.min() + 1.0
    assert (longest <= plain.result.hours[plain.result.valid]).all()
    from cityshade.imageio import read_exr

    exr = read_exr(tmp_path / "tiled" / "sun_hours.exr")[0]
    assert np.array_equal(exr["longest_sun_h"], read_exr(tmp_path / "plain" /
                                                         "sun_hours.exr")[0]["longest_sun_h"],
                          equal_nan=True)
    assert tiled.manifest["status"] == "finished"
    assert sorted(tiled.manifest["finished_steps"]) == list(range(len(_steps())))


def test_tiled_run_with_each_tiles_casters_walked_from_the_tree_equals_untiled(
        files, sample_plain, tmp_path, monkeypatch):
    """The sample city in tiles whose casters the kd-tree walk gathers (as on a big city):
    the plain run's numbers bit for bit, and the walk was taken."""
    from cityshade import lightspace

    monkeypatch.setattr(lightspace, "NEAR_MIN_CASTERS", 0)
    monkeypatch.setattr(lightspace, "NEAR_AREA_SHARE", 1.0)
    walks = []
    near_rows = lightspace._near_rows

    def spy(*args):
        rows = near_rows(*args)
        walks.append(rows is not None)
        return rows

    monkeypatch.setattr(lightspace, "_near_rows", spy)
    tiled = _run(files[1], tmp_path / "tiled", tile_px=48, steps=_steps(every_s=5400))
    assert tiled.result.diagnostics["tiles"]["tiles"] > 4 and any(walks)
    assert tiled.result.hours.tobytes() == sample_plain.result.hours.tobytes()
    assert tiled.result.sample_hours.tobytes() == sample_plain.result.sample_hours.tobytes()
    _same_stretches(sample_plain, tiled)


def test_sun_blocks_keep_one_caster_order_each():
    """Blocks cover the sun positions in order, at most ``block`` long, each with one caster
    order, and cut only where the order changes or the block is full."""
    from cityshade.lightspace import caster_order
    from cityshade.geo.sun import sun_from_angles
    from cityshade.sunhours.tiled import sun_blocks

    # A day's arc: east, up, west (the key axis changes from x or y to z and back).
    dirs = np.array([sun_from_angles(az, el).direction for az, el in
                     zip(np.linspace(60, 300, 37), 60 * np.sin(np.linspace(0.05, 3.1, 37)))])
    orders = [caster_order(d) for d in dirs]
    assert len(set(orders)) >= 3
    for block in (1, 3, 8, 100):
        blocks = sun_blocks(dirs, block)
        assert blocks[0][0] == 0 and blocks[-1][1] == len(dirs)
        assert all(a[1] == b[0] for a, b in zip(blocks, blocks[1:]))
        for lo, hi in blocks:
            assert 0 < hi - lo <= block and len(set(orders[lo:hi])) == 1
        for (lo, hi), (nxt, _) in zip(blocks, blocks[1:]):
            assert hi - lo == block or orders[hi - 1] != orders[nxt]
    assert sun_blocks(dirs[:0], 8) == []


def test_tiled_run_sorts_the_casters_as_often_as_the_untiled_one(files, tmp_path, monkeypatch):
    """Tasks run block by block over the tiles and no block crosses a caster-order change, so
    the many tiles sort the casters no more often than one untiled run (a sort per change)."""
    from cityshade import lightspace
    from cityshade.lightspace import kernels as K

    sorts = []
    keys = K.caster_keys

    def counted(*args):
        sorts.append(args[2:4])
        return keys(*args)

    monkeypatch.setattr(K, "caster_keys", counted)
    steps = _steps(every_s=1800)
    counts = {}
    for name, kw in (("plain", {}), ("tiled", {"tile_px": 24})):
        for kd in list(lightspace._CASTERS):
            lightspace.forget_casters(kd)
        sorts.clear()
        run = _run(files[1], tmp_path / name, steps=steps, **kw)
        counts[name] = len(sorts)
    assert run.result.diagnostics["tiles"]["tiles"] > 4
    assert counts["plain"] >= 3, "the day never changed the caster order: nothing tested"
    assert counts["tiled"] == counts["plain"]


def test_tiled_run_resumes_bit_identical_without_redoing_tasks(files, tmp_path):
    boxes, _ = files
    from cityshade.sunhours import tiled as tiles

    straight = _run(boxes, tmp_path / "straight", tile_px=16)
    calls = []
    real = tiles.task_lit

    def counting(*a, **kw):
        calls.append(a[2])
        return real(*a, **kw)

    def stop_after(n):
        def hook(done, total, unit):
            if done >= n:
                raise Stop
        return hook

    out = tmp_path / "cut"
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(tiles, "task_lit", counting)
        with pytest.raises(Stop):
            _run(boxes, out, tile_px=16, on_step=stop_after(5))
        first = len(calls)
        manifest = json.loads((out / C.MANIFEST_NAME).read_text())
        assert manifest["status"] == "running" and manifest["tasks_done"] == 5
        resumed = _run(boxes, out, tile_px=16)
    total = straight.result.diagnostics["tiles"]["tasks"]
    assert first == 5 and len(calls) == total  # finished tasks are not run again
    assert resumed.result.hours.tobytes() == straight.result.hours.tobytes()
    assert resumed.result.sample_hours.tobytes() == straight.result.sample_hours.tobytes()
    _same_stretches(resumed, straight)
    # Another tiling is another run.
    with pytest.raises(UsageError, match="differs in: tile_px"):
        _run(boxes, out, tile_px=8)


def test_monthly_sums_equal_runs_of_each_month(files, tmp_path):
    boxes, _ = files
    steps = _steps(date(2024, 1, 31), every_s=7200, days=2)
    months = [s.start_utc.astimezone(timezone.utc).strftime("%Y-%m") for s in steps]
    both = _run(boxes, tmp_path / "both", steps=steps, step_month=months)
    whole = _run(boxes, tmp_path / "whole", steps=steps)
    assert both.result.hours.tobytes() == whole.result.hours.tobytes()
    _same_stretches(both, whole)
    jan = _run(boxes, tmp_path / "jan", steps=_steps(date(2024, 1, 31), every_s=7200))
    feb = _run(boxes, tmp_path / "feb", steps=_steps(date(2024, 2, 1), every_s=7200))
    from cityshade.imageio import read_exr

    for label, single in (("2024-01", jan), ("2024-02", feb)):
        got = read_exr(tmp_path / "both" / "monthly" / f"sun_hours_{label}.exr")[0]
        assert got["sun_hours"].tobytes() == single.result.hours.tobytes()
        assert (tmp_path / "both" / "monthly" / f"sun_hours_{label}.tif").exists()
        csv = (tmp_path / "both" / "monthly" / f"surfaces_{label}.csv").read_bytes()
        assert csv == (tmp_path / ("jan" if label.endswith("1") else "feb") /
                       "surfaces.csv").read_bytes()


def test_cog_has_geokeys_tiles_and_the_values(tmp_path):
    rasterio = pytest.importorskip("rasterio")
    from cityshade.imageio import write_cog

    hours = np.arange(600 * 700, dtype=np.float32).reshape(600, 700) / 7.0
    hours[0, 0] = np.nan
    gt = (690_000.0, 0.5, 0.0, 5_336_000.0, 0.0, -0.5)
    write_cog(tmp_path / "h.tif", hours, gt, epsg=25832, nodata=float("nan"),
              attributes={"cityshade:units": "hours"})
    with rasterio.open(tmp_path / "h.tif") as ds:
        assert ds.crs.to_epsg() == 25832
        assert ds.transform.to_gdal() == gt
        assert ds.tags(ns="IMAGE_STRUCTURE")["LAYOUT"] == "COG"
        assert ds.block_shapes[0] == (512, 512) and ds.overviews(1) == [2]
        assert ds.tags()["cityshade_units"] == "hours"
        assert ds.read(1).tobytes() == hours.tobytes()


def test_year_of_suns_at_once_equals_each_instant():
    """The vectorised SPA of a whole run gives what one instant at a time gives, exactly."""
    from cityshade.geo.crs import parse_srs_name
    from cityshade.geo.sun import sun_from_instant, suns_from_instants

    crs = parse_srs_name("EPSG:25832")
    origin = np.array([X0, Y0, Z0])
    steps = P.plan_steps(date(2024, 1, 1), 0, 86_400, 3600, "Europe/Berlin",
                         to_date=date(2024, 12, 31), every_day=7)
    instants = [s.centre_utc for s in steps]
    suns = suns_from_instants(instants, crs, origin)
    for i in range(0, len(instants), 97):
        assert sun_from_instant(instants[i], crs, origin).metadata() == suns[i].metadata()


def test_cli_tile_and_scheduler_options(files, tmp_path):
    from cityshade.cli.main import cli

    boxes, _ = files
    base = ["batch", str(boxes), "--date", "2024-06-21", "--from", "06:00", "--to", "18:00",
            "--every", "3h", "--tz", "Europe/Berlin", "--camera", "map", "--pixel-size", "4"]
    runner = CliRunner()

    def fails(args, text):
        res = runner.invoke(cli, base + args + ["-o", str(tmp_path / "x")])
        assert res.exit_code == 2, res.output
        lines = [ln for ln in res.output.splitlines() if ln.strip()]
        assert len(lines) == 1 and text in lines[0], res.output
        assert not (tmp_path / "x").exists()

    fails(["--tile-px", "0"], "--tile-px must be >= 1")
    fails(["--scheduler", "lokal:2"], "--scheduler is local")
    fails(["--scheduler", "local:zwei"], "number of workers")
    fails(["--tile-px", "8", "--frames"], "--frames cannot be combined")
    fails(["--tile-px", "8", "--shadows", "pcf"], "exact technique")
    ok = runner.invoke(cli, base + ["--tile-px", "8", "--monthly", "-o", str(tmp_path / "ok")])
    assert ok.exit_code == 0, ok.output
    assert (tmp_path / "ok" / "monthly" / "sun_hours_2024-06.tif").exists()
    assert (tmp_path / "ok" / "sun_hours.tif").exists()


try:
    from distributed.diagnostics.plugin import SchedulerPlugin
except ImportError:  # without the [dask] extra these tests skip
    SchedulerPlugin = object


class TaskLog(SchedulerPlugin):
    """A Dask scheduler plugin (the LocalCluster's scheduler runs in this process): per task
    key, how often it started running and how often its result arrived; the workers lost."""

    name = "cityshade-task-log"

    def __init__(self):
        self.started: dict[str, int] = {}
        self.arrived: dict[str, int] = {}
        self.lost_workers = 0

    def transition(self, key, start, finish, *args, **kwargs):
        if finish == "processing":
            self.started[key] = self.started.get(key, 0) + 1
        elif finish == "memory":
            self.arrived[key] = self.arrived.get(key, 0) + 1

    def remove_worker(self, scheduler=None, worker=None, **kwargs):
        self.lost_workers += 1


def _logged_executor(sample, log_holder):
    """A DaskExecutor of 2 local workers (1 Numba thread each) whose scheduler logs tasks."""
    from cityshade.sunhours.distributed import DaskExecutor
    from cityshade.store.scenefile import load_scene

    sha = (load_scene(sample).header or {}).get("source", {}).get("sha256", "")

    class Logged(DaskExecutor):
        fetched: list[str] = []  # key prefixes of the results the driver has taken

        def run(self, plan, tasks, directions, t_days, engine, workdir, finished):
            def taken(t, lo, bits):
                self.fetched.append(f"cityshade-tile{t}-sun{lo}-")
                finished(t, lo, bits)

            super().run(plan, tasks, directions, t_days, engine, workdir, taken)

        def connect(self):
            fresh = self.client is None
            super().connect()
            if fresh:
                log = TaskLog()
                self.cluster.scheduler.add_plugin(log, name=TaskLog.name)
                log_holder.append(log)

    # Every task on the cluster (the driver runs none while it starts): the logs count them all.
    return Logged("local:2", sample, sha, threads_per_worker=1, driver_tasks=False)


def _scheduler_call(executor, fn):
    return executor.client.run_on_scheduler(lambda dask_scheduler: fn(dask_scheduler))


def test_local_cluster_survives_a_killed_worker(files, sample_plain, tmp_path, monkeypatch):
    """A LocalCluster of 2 workers, one killed mid-run: the run ends with the plain run's
    numbers, the tasks the driver had added are not run again, the killed worker's are,
    progress counts each task once."""
    pytest.importorskip("dask.distributed")
    import signal
    import time

    import numba

    _, sample = files
    steps = _steps(every_s=5400)
    plain = sample_plain
    # The driver's own thread count in its environment must not reach the workers.
    monkeypatch.setenv("NUMBA_NUM_THREADS", str(numba.config.NUMBA_NUM_THREADS))
    environ_before = dict(os.environ)
    logs: list[TaskLog] = []
    executor = _logged_executor(sample, logs)
    progress, seen = [], {}

    def hook(done, total, unit):
        progress.append((done, total))
        if done != 3:
            return
        client = executor.client
        seen["threads"] = set(client.run(lambda: os.environ.get("NUMBA_NUM_THREADS")).values())
        # Kill the worker holding the most finished results the driver has not taken yet,
        # once the scheduler has heard that the driver let go of the taken ones (the client
        # tells it in the background).
        taken = tuple(executor.fetched)
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and _scheduler_call(executor, lambda s: any(
                str(k).startswith(taken) for k in s.tasks)):
            time.sleep(0.05)
        held = _scheduler_call(executor, lambda s: {
            a: sorted(str(ts.key) for ts in ws.has_what) for a, ws in s.workers.items()})
        held = {a: [k for k in ks if not k.startswith(taken)] for a, ks in held.items()}
        victim = max(held, key=lambda a: len(held[a]))
        seen["lost"] = held[victim]
        seen["added"] = [k for k in logs[0].arrived if k.startswith(taken)]
        pid = client.run(os.getpid, workers=[victim])[victim]
        os.kill(pid, signal.SIGKILL)
        deadline = time.monotonic() + 60
        while logs[0].lost_workers == 0 and time.monotonic() < deadline:
            time.sleep(0.05)

    dask = _run(sample, tmp_path / "dask", steps=steps, tile_px=24, scheduler=executor,
                on_step=hook)
    log = logs[0]
    total = dask.result.diagnostics["tiles"]["tasks"]
    tiles = dask.result.diagnostics["tiles"]
    assert tiles["workers"] == 2 and tiles["tiles"] > 2
    assert total >= 12 and log.lost_workers >= 1
    assert seen["threads"] == {"1"}
    assert not (tmp_path / "dask" / "receivers.npy").exists()
    # The workers' environment does not stay in this process (Numba's threads would clash).
    keys = ("NUMBA_NUM_THREADS", "OMP_NUM_THREADS", "PYTHONHASHSEED", "MALLOC_TRIM_THRESHOLD_")
    assert {k: os.environ.get(k) for k in keys} == {k: environ_before.get(k) for k in keys}
    # Same numbers as without Dask.
    assert plain.result.hours.tobytes() == dask.result.hours.tobytes()
    assert plain.result.sample_hours.tobytes() == dask.result.sample_hours.tobytes()
    _same_stretches(plain, dask)
    assert dask.manifest["status"] == "finished" and dask.manifest["tasks_done"] == total
    assert sorted(dask.manifest["finished_steps"]) == list(range(len(steps)))
    # Progress: every task once, in order, out of the same total.
    assert progress == [(k, total) for k in range(1, total + 1)]
    # The results lost with the worker were computed again; the ones added before were not
    # (a result that arrives twice was computed twice; a task can start twice when Dask moves
    # it to the idle worker before it runs).
    assert seen["lost"], "the killed worker held no results"
    assert all(log.arrived[k] == 2 for k in seen["lost"]), \
        {k: (log.started[k], log.arrived[k]) for k in seen["lost"]}
    assert len(seen["added"]) >= 3 and all(log.arrived[k] == 1 for k in seen["added"]), \
        {k: (log.started[k], log.arrived[k]) for k in seen["added"]}
    assert len(log.started) == total


def test_stopped_distributed_run_resumes_to_the_plain_result(files, sample_plain, tmp_path):
    pytest.importorskip("dask.distributed")
    _, sample = files
    steps = _steps(every_s=5400)
    plain = sample_plain
    out = tmp_path / "dask"

    def stop_after(n):
        def hook(done, total, unit):
            if done >= n:
                raise Stop
        return hook

    first: list[TaskLog] = []
    with pytest.raises(Stop):
        _run(sample, out, steps=steps, tile_px=24, scheduler=_logged_executor(sample, first),
             on_step=stop_after(5))
    manifest = json.loads((out / C.MANIFEST_NAME).read_text())
    assert manifest["status"] == "running" and manifest["tasks_done"] == 5
    second: list[TaskLog] = []
    resumed = _run(sample, out, steps=steps, tile_px=24,
                   scheduler=_logged_executor(sample, second))
    total = resumed.result.diagnostics["tiles"]["tasks"]
    assert len(second[0].arrived) == total - 5  # only the tasks not added before
    assert set(second[0].arrived.values()) == {1}
    assert resumed.manifest["tasks_done"] == total
    assert plain.result.hours.tobytes() == resumed.result.hours.tobytes()
    assert plain.result.sample_hours.tobytes() == resumed.result.sample_hours.tobytes()
    _same_stretches(plain, resumed)


def test_driver_runs_tasks_while_the_cluster_starts(files, sample_plain, tmp_path):
    """A LocalCluster that takes a while to come up: the driver runs the first tasks itself
    meanwhile, the cluster the rest; the numbers are the plain run's, bit for bit, and every
    task is run and counted once."""
    pytest.importorskip("dask.distributed")
    import threading

    from cityshade.sunhours.distributed import DaskExecutor
    from cityshade.store.scenefile import load_scene

    _, sample = files
    steps = _steps(every_s=5400)
    sha = (load_scene(sample).header or {}).get("source", {}).get("sha256", "")
    go = threading.Event()
    logs: list[TaskLog] = []

    class Slow(DaskExecutor):
        def connect(self):
            fresh = self.client is None
            go.wait(60)  # the cluster starts once the driver has added 3 tasks
            super().connect()
            if fresh:
                logs.append(TaskLog())
                self.cluster.scheduler.add_plugin(logs[-1], name=TaskLog.name)

    executor = Slow("local:1", sample, sha, threads_per_worker=1)
    progress = []

    def hook(done, total, unit):
        progress.append((done, total))
        if done == 3:
            go.set()
            executor.ready.wait(60)  # and then hands the rest over

    dask = _run(sample, tmp_path / "dask", steps=steps, tile_px=24, scheduler=executor,
                on_step=hook)
    total = dask.result.diagnostics["tiles"]["tasks"]
    assert dask.result.diagnostics["tiles"]["tasks_on_driver"] == 3
    assert len(logs[0].arrived) == total - 3 and set(logs[0].arrived.values()) == {1}
    assert progress == [(k, total) for k in range(1, total + 1)]
    assert sample_plain.result.hours.tobytes() == dask.result.hours.tobytes()
    assert sample_plain.result.sample_hours.tobytes() == dask.result.sample_hours.tobytes()
    _same_stretches(sample_plain, dask)
    assert dask.manifest["status"] == "finished" and dask.manifest["tasks_done"] == total
