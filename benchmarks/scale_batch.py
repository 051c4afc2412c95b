"""Scale benchmark, batch part (issue 15): one day at 10-minute steps, with and without Dask.

Input: a built benchmark city (``--scene``, a .cityshade file; default the 10 M-triangle city
``/work/bench_data/city_10000000.cityshade`` when it exists, else the 1 M city
``city_1000000_s7.cityshade`` there; build them with ``python -m cityshade.samplegen
--triangles N`` and ``cityshade build``). The city as it stood on 2000-01-01; a top-down map of
the model's extent at ``--pixel-size`` (default 2 m); one day ``--date`` (2024-06-21,
Europe/Berlin, 00:00–24:00) every 10 minutes: the steps with the sun up are computed; ``izb``.

Runs, interleaved ``--repeat`` times, each into a fresh output folder through
``cityshade.sunhours.run.run_batch`` (what ``cityshade batch`` calls; the same numbers in every run,
checked byte for byte):

* ``plain-1t`` / ``plain-2t``: the untiled run without Dask, Numba on 1 / 2 threads;
* ``tiled-1t``: ``--tile-px`` without Dask, 1 thread (the same tasks, run in order here);
* ``local:1`` / ``local:2``: ``--scheduler local:N`` with ``--tile-px``, N worker processes of
  one Numba thread each (worker start-up included, as a user pays it; the driver runs the
  first tasks itself while the cluster starts, and the count is printed).

Reported: wall seconds of each (median), Dask's overhead (local:1 against tiled-1t and
against plain-1t; goal ≤ 5 %), the scaling from one to two workers (goal ≥ 1.8×), the
driver's serial share (adding the results: ``accumulate_s``), and the projected wall time of
a whole year at 10-minute steps at 1 m on 1, 10 and 100 such machines from the measured
per-worker cost (pixel·steps per second of one process running the tasks: the tiled run
without Dask) and the driver's serial cost per pixel·step (which bounds the speed-up of many
machines, Amdahl's law).

Usage: python benchmarks/scale_batch.py [--scene FILE] [--pixel-size 2] [--tile-px 512]
       [--repeat 1] [--runs plain-1t,plain-2t,tiled-1t,local:1,local:2] [--json out.json]
"""
from __future__ import annotations

import argparse
import hashlib
import json
import statistics
import sys
import tempfile
import time
from datetime import date
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)
from render import _machine  # noqa: E402

BENCH = Path("/work/bench_data")
DAY_2000 = 10957.0  # 2000-01-01 in days since 1970-01-01
ALL_RUNS = ("plain-1t", "plain-2t", "tiled-1t", "local:1", "local:2")


def _default_scene() -> Path:
    for name in ("city_10000000.cityshade", "city_1000000_s7.cityshade"):
        if (BENCH / name).exists():
            return BENCH / name
    raise SystemExit("no benchmark city: build one with python -m cityshade.samplegen and "
                     "cityshade build, and give it with --scene")


def _children_cpu_s() -> float:
    import resource

    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def _one(name: str, scene, scene_path, cam, steps, tile_px: int, outdir: Path) -> dict:
    import numba

    from cityshade.sunhours.run import run_batch

    threads = 2 if name.endswith("2t") else 1
    numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
    kw = {}
    if name.startswith("tiled") or name.startswith("local"):
        kw["tile_px"] = tile_px
    if name.startswith("local"):
        from cityshade.sunhours.distributed import DaskExecutor

        sha = (scene.header or {}).get("source", {}).get("sha256", "")
        kw["scheduler"] = DaskExecutor(name, scene_path, sha, threads_per_worker=1)
    # CPU of this process and of the worker processes it started and joined (Dask's local
    # workers are children of this process): the work done, whatever the machine's load.
    c0, k0 = time.process_time(), _children_cpu_s()
    t0 = time.perf_counter()
    from cityshade.sunhours.request import SunHoursRequest

    run = run_batch(outdir, scene, SunHoursRequest.from_settings(steps, DAY_2000, camera=cam,
                                                                 technique="izb", **kw))
    wall = time.perf_counter() - t0
    cpu, workers_cpu = time.process_time() - c0, _children_cpu_s() - k0
    res = run.result
    return {"wall_s": wall, "cpu_s": cpu + workers_cpu, "driver_cpu_s": cpu,
            "workers_cpu_s": workers_cpu, "timings_s": res.timings_s,
            "tiles": res.diagnostics.get("tiles"), "units": res.units,
            "pixels": int(res.valid.sum()),
            "digest": hashlib.sha256(res.hours.tobytes()).hexdigest()}


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", type=Path)
    ap.add_argument("--pixel-size", type=float, default=2.0)
    ap.add_argument("--tile-px", type=int, default=512)
    ap.add_argument("--date", default="2024-06-21")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--runs", default=",".join(ALL_RUNS))
    ap.add_argument("--json", type=Path)
    ap.add_argument("--workdir", type=Path, help="where the runs' output folders go (a "
                    "temporary folder inside it, removed at the end; default the system's)")
    args = ap.parse_args(argv)
    if args.workdir is not None:
        args.workdir.mkdir(parents=True, exist_ok=True)

    import numba

    from cityshade.sunhours import plan as B
    from cityshade.raster.camera import map_view
    from cityshade.store.scenefile import load_scene

    scene_path = args.scene or _default_scene()
    t0 = time.perf_counter()
    scene = load_scene(scene_path)
    load_s = time.perf_counter() - t0
    cam = map_view(scene, args.pixel_size)
    steps = B.plan_steps(date.fromisoformat(args.date), 0, 86_400, 600, "Europe/Berlin")
    runs = [r.strip() for r in args.runs.split(",") if r.strip()]
    print(f"scene {scene_path} ({scene.n_triangles:,} triangles, load {load_s:.2f} s), map "
          f"{cam.width_px} × {cam.height_px} px at {args.pixel_size} m, {len(steps)} steps, "
          f"tiles of {args.tile_px} px; Numba threads available {numba.config.NUMBA_NUM_THREADS}",
          flush=True)
    # Warm-up: compile/load every kernel a run uses (a small window, all code paths here).
    print("command: python benchmarks/scale_batch.py " + " ".join(argv if argv is not None
                                                                  else sys.argv[1:]), flush=True)
    with tempfile.TemporaryDirectory(dir=args.workdir) as tmp:
        small = map_view(scene, args.pixel_size * 16)
        _one("tiled-1t", scene, scene_path, small, steps[60:64], 64, Path(tmp) / "w")
        results: dict[str, list[dict]] = {r: [] for r in runs}
        for k in range(args.repeat):
            for name in runs:
                r = _one(name, scene, scene_path, cam, steps, args.tile_px,
                         Path(tmp) / f"{name.replace(':', '_')}_{k}")
                results[name].append(r)
                on_driver = (r["tiles"] or {}).get("tasks_on_driver")
                print(f"  {name:<9} {r['wall_s']:8.2f} s  cpu {r['cpu_s']:8.2f} s (workers "
                      f"{r['workers_cpu_s']:7.2f} s)  shadow {r['timings_s']['shadow_s']:7.2f}"
                      f" s  accumulate {r['timings_s'].get('accumulate_s', 0.0):6.2f} s"
                      + ("" if on_driver is None else
                         f"  tasks run by the driver while the cluster started {on_driver} of "
                         f"{r['tiles']['tasks']}"), flush=True)
    digests = {r["digest"] for rs in results.values() for r in rs}
    med = {n: statistics.median(r["wall_s"] for r in rs) for n, rs in results.items()}
    med_cpu = {n: statistics.median(r["cpu_s"] for r in rs) for n, rs in results.items()}
    any_run = next(iter(results.values()))[0]
    px_steps = any_run["pixels"] * any_run["units"]
    out = {"commit": commit(), "scene": str(scene_path),
           "triangles": scene.n_triangles, "pixel_size_m": args.pixel_size,
           "map_px": [cam.width_px, cam.height_px], "surface_px": any_run["pixels"],
           "sun_positions": any_run["units"], "tile_px": args.tile_px,
           "identical_in_all_runs": len(digests) == 1, "median_wall_s": med,
           "median_cpu_s": med_cpu, "load_average": list(__import__("os").getloadavg()),
           "runs": results, "machine": _machine()}
    if "local:1" in med and "tiled-1t" in med:
        out["dask_overhead_vs_tiled"] = med["local:1"] / med["tiled-1t"] - 1.0
    if "local:1" in med and "plain-1t" in med:
        out["dask_overhead_vs_plain"] = med["local:1"] / med["plain-1t"] - 1.0
    if "local:1" in med and "local:2" in med:
        out["scaling_1_to_2_workers"] = med["local:1"] / med["local:2"]
        # Work added by the second worker (the same tasks: ideally 1.0).
        out["cpu_local2_over_local1"] = med_cpu["local:2"] / med_cpu["local:1"]
    if "local:1" in med and "tiled-1t" in med:
        out["dask_cpu_overhead_vs_tiled"] = med_cpu["local:1"] / med_cpu["tiled-1t"] - 1.0
    # Projection of a year at 1 m: pixel·steps of the year over the measured rates.
    year = B.plan_steps(date(2024, 1, 1), 0, 86_400, 600, "Europe/Berlin",
                        to_date=date(2024, 12, 31))
    from cityshade.geo.sun import suns_from_instants

    suns = suns_from_instants([s.centre_utc for s in year], scene.crs, scene.origin_m)
    year_units = sum(1 for s in suns if s.above_horizon)
    px_1m = any_run["pixels"] * args.pixel_size ** 2
    year_px_steps = px_1m * year_units
    # One worker's rate: the tiled run without Dask is the same tasks in one process (a
    # ``local:N`` run also has the first tasks run by the driver while its cluster starts).
    base = "tiled-1t" if "tiled-1t" in results else ("local:1" if "local:1" in results
                                                     else runs[0])
    worker = statistics.median(r["timings_s"]["shadow_s"] - r["timings_s"].get(
        "accumulate_s", 0.0) for r in results[base])
    per_worker = px_steps / max(worker, 1e-9)  # pixel·steps/s of one worker process
    serial = statistics.median(r["timings_s"].get("accumulate_s", 0.0) for r in results[base])
    serial_per = serial / px_steps  # driver seconds per pixel·step
    workers_per_machine = 2
    scale = out.get("scaling_1_to_2_workers", 2.0) / 2.0  # efficiency of the 2nd worker
    proj = {}
    for machines in (1, 10, 100):
        parallel_s = year_px_steps / (per_worker * workers_per_machine * scale * machines)
        proj[machines] = {"hours": (parallel_s + year_px_steps * serial_per) / 3600.0,
                          "parallel_h": parallel_s / 3600.0,
                          "driver_serial_h": year_px_steps * serial_per / 3600.0}
    out["year"] = {"sun_up_steps": year_units, "surface_px_at_1m": px_1m,
                   "pixel_steps": year_px_steps, "per_worker_px_steps_per_s": per_worker,
                   "driver_s_per_px_step": serial_per, "machines": proj}
    print(f"identical in all runs: {out['identical_in_all_runs']}")
    print(f"{'run':<9} {'wall s':>8} {'cpu s':>8}")
    for n in med:
        print(f"{n:<9} {med[n]:8.2f} {med_cpu[n]:8.2f}")
    print(f"load average at the end: {out['load_average']}")
    for key in ("dask_overhead_vs_tiled", "dask_overhead_vs_plain", "dask_cpu_overhead_vs_tiled",
                "scaling_1_to_2_workers", "cpu_local2_over_local1"):
        if key in out:
            print(f"{key}: {out[key]:+.3f}" if "overhead" in key else f"{key}: {out[key]:.2f}×")
    print(f"year at 1 m: {year_units} sun-up steps × {px_1m / 1e6:.1f} Mpx = "
          f"{year_px_steps:.3g} pixel·steps; one worker {per_worker / 1e6:.2f} Mpx·steps/s; "
          f"driver {serial_per * 1e9:.2f} ns per pixel·step")
    for m, p in proj.items():
        print(f"  {m:>3} machine(s) of 2 workers: {p['hours']:8.1f} h "
              f"(parallel {p['parallel_h']:.1f} h + driver {p['driver_serial_h']:.1f} h)")
    if args.json:
        args.json.write_text(json.dumps(out, indent=2, default=str) + "\n")
    return out


if __name__ == "__main__":
    main(sys.argv[1:])
