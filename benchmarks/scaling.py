"""Two-core scaling of every parallel kernel of the render, batch and build paths (issue 12
point 2: each ≥ 1.8× at 2 threads against 1).

On the 1M-triangle benchmark city of ``benchmarks/render.py`` (generated and built into
``--workdir`` when missing), each stage is timed at 1 and 2 Numba threads, the thread counts
interleaved within every repeat (median of ``--repeat``; one warm-up run first):

* ``gbuffer`` the culled G-buffer pass (``rasterize``), 1080p overview;
* ``resolve`` the G-buffer resolve and oriented normals (``camera_pass``'s ``resolve_s``);
* ``raytrace``, ``izb`` the shadow stage of those techniques on that camera pass (kd-tree
  any-hit rays; the light-space engine), and ``raytrace_map`` / ``izb_map`` on a top-down map
  of ``--map-px`` pixels (the map workload);
* ``shade`` the shading of the overview frame;
* ``depth_pass`` a ``--size``² orthographic sun depth map of the whole city;
* ``kdtree_build`` the kd-tree of the city's first ``--build-triangles`` triangles;
* ``sun_hours`` ``batch.sun_hours`` (izb) of the map over ``--steps`` sun positions.

Controls, before and after: the trivial ``prange`` loop of ``benchmarks/raytrace.py`` (about
2.0× when both cores were free during the run; a kernel's ratio means little when the probe's
is low) and STREAM's triad over three 256 MB arrays (GB/s at 1 and 2 threads: the most a
kernel streaming from memory can scale on the machine). Prints one JSON object and a table (ms
at 1 and 2 threads, ratio).

Usage: python benchmarks/scaling.py [--repeat 5] [--stages gbuffer,resolve,...]
       [--workdir bench_out] [--json out.json]
"""
from __future__ import annotations

import argparse
import datetime as dt
import json
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from provenance import commit  # noqa: E402
from render import DAY_2000, REPO, _machine, ensure_scene  # noqa: E402

STAGES = ["gbuffer", "resolve", "raytrace", "izb", "raytrace_map", "izb_map", "shade",
          "depth_pass", "kdtree_build", "sun_hours"]


def stage_runners(scene, args) -> tuple[dict, dict]:
    """Stage name → a function returning that stage's seconds for one run; and stage name → an
    untimed call run before each round's runs of that stage (the izb stages: the casters
    sorted for the benchmark sun, which ``sun_hours``' other suns replaced)."""
    import numpy as np

    from cityshade.accel import build_kdtree
    from cityshade.sunhours.accumulate import sun_hours
    from cityshade.frame.pipeline import camera_pass, shadow_pass
    from cityshade.raster import camera as cams
    from cityshade.raster.rasterize import rasterize
    from cityshade.frame.shading import shade
    from cityshade.shadows import shadowmap as sm
    from cityshade.geo.sun import sun_from_angles

    az, el = (float(v) for v in args.sun.split(","))
    sun = sun_from_angles(az, el, scene.crs, scene.origin_m)
    w, h = (int(v) for v in args.size_camera.split("x"))
    over = cams.overview(scene, w, h)
    box = cams.scene_box(scene, DAY_2000)
    area = float((box[1, 0] - box[0, 0]) * (box[1, 1] - box[0, 1]))
    mapcam = cams.map_view(scene, pixel_size_m=(area / args.map_px) ** 0.5)
    cp = camera_pass(scene, over, DAY_2000)
    cp_map = camera_pass(scene, mapcam, DAY_2000)
    lit = shadow_pass(cp, sun, "izb").lit
    # The whole city seen along the sun's rays (as render.py --shadow-map).
    b = sm.scene_bounds(scene)
    corners = np.array([[b[i, 0], b[j, 1], b[k, 2]] for i in (0, 1) for j in (0, 1)
                        for k in (0, 1)])
    light = corners @ np.stack(sm.light_basis(sun.direction), axis=1)
    lo, hi = light.min(axis=0), light.max(axis=0)
    light_view = sm.ortho_view(sun.direction, (lo[0], hi[0]), (lo[1], hi[1]),
                               (lo[2] - 1, hi[2] + 1), args.size, args.size)
    nb = min(int(args.build_triangles), scene.triangles.shape[0])
    tris = np.ascontiguousarray(scene.triangles[:nb])
    t0 = dt.datetime(2024, 6, 21, 6, tzinfo=dt.timezone.utc)
    instants = [t0 + dt.timedelta(minutes=90 * k) for k in range(args.steps)]

    def timed(fn):
        t = time.perf_counter()
        fn()
        return time.perf_counter() - t

    def izb_sorted():
        # The light-space engine keeps one sorted copy of the casters, for the last sun's
        # dominant axis: sun_hours leaves the day's last one, so without this the first izb
        # run of each round (the 1-thread one) also paid the sort (session 18's "1-thread
        # anomaly": 383-478 ms against 206-216 ms).
        from cityshade import lightspace
        lightspace.occluded(scene.kdtree, np.array([[0.0, 0.0, float(box[1, 2])]]), sun.direction,
                            DAY_2000)

    runners = {
        "gbuffer": lambda: timed(lambda: rasterize(scene, over, DAY_2000)),
        "resolve": lambda: camera_pass(scene, over, DAY_2000).timings_s["resolve_s"],
        "raytrace": lambda: shadow_pass(cp, sun, "raytrace").seconds,
        "izb": lambda: shadow_pass(cp, sun, "izb").seconds,
        "raytrace_map": lambda: shadow_pass(cp_map, sun, "raytrace").seconds,
        "izb_map": lambda: shadow_pass(cp_map, sun, "izb").seconds,
        "shade": lambda: timed(lambda: shade(scene, cp.surfaces, over, lit, sun.direction,
                                             prim_id=cp.gbuffer.prim_id)),
        "depth_pass": lambda: timed(lambda: sm.render_depth_map(scene, light_view, DAY_2000)),
        "kdtree_build": lambda: timed(lambda: build_kdtree(
            scene.vertices, tris, scene.tri_t_begin_days[:nb], scene.tri_t_end_days[:nb],
            scene.tri_material[:nb])),
        "sun_hours": lambda: timed(lambda: sun_hours(scene, mapcam, instants, DAY_2000)),
    }
    #: Untimed, before each round's runs of a stage: the state a frame of that sun has.
    prepare = {"izb": izb_sorted, "izb_map": izb_sorted}
    return runners, prepare


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--stages", default=",".join(STAGES))
    ap.add_argument("--size-camera", default="1920x1080")
    ap.add_argument("--map-px", type=int, default=2_000_000,
                    help="pixels of the top-down map (raytrace_map, izb_map, sun_hours)")
    ap.add_argument("--size", type=int, default=4096, help="depth map side in texels")
    ap.add_argument("--build-triangles", type=int, default=250_000)
    ap.add_argument("--steps", type=int, default=8, help="sun positions of sun_hours")
    ap.add_argument("--sun", default="135,30", help="azimuth,elevation in degrees")
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    import numba

    from cityshade.store.scenefile import load_scene
    from raytrace import core_probe, memory_probe

    if numba.config.NUMBA_NUM_THREADS < 2:
        raise SystemExit("needs 2 Numba threads (NUMBA_NUM_THREADS unset or >= 2)")
    names = [s for s in args.stages.split(",") if s]
    unknown = sorted(set(names) - set(STAGES))
    if unknown:
        raise SystemExit(f"unknown stage(s) {', '.join(unknown)}; valid: {', '.join(STAGES)}")
    scene = load_scene(ensure_scene(args.workdir, args.triangles, args.seed), verify=False)
    runners, prepare = stage_runners(scene, args)
    probe_before = core_probe([1, 2], 5)
    memory_before = memory_probe([1, 2], 7)
    times: dict = {name: {1: [], 2: []} for name in names}
    for name in names:
        for n in (1, 2):                    # warm-up: kernels loaded, work arrays made
            numba.set_num_threads(n)
            runners[name]()
    for _ in range(args.repeat):
        for name in names:
            if name in prepare:
                prepare[name]()
            for n in (1, 2):
                numba.set_num_threads(n)
                times[name][n].append(runners[name]())
    probe_after = core_probe([1, 2], 5)
    memory_after = memory_probe([1, 2], 7)
    numba.set_num_threads(2)
    report = {"benchmark": "two-core scaling", "commit": commit(), "machine": _machine(),
              "triangles": int(scene.triangles.shape[0]), "repeat": args.repeat,
              "probe_scaling": {"before": probe_before[1] / probe_before[2],
                                "after": probe_after[1] / probe_after[2]},
              "memory_triad_gb_s": {"before": memory_before, "after": memory_after},
              "stages": {}}
    for name in names:
        m1 = 1000 * statistics.median(times[name][1])
        m2 = 1000 * statistics.median(times[name][2])
        report["stages"][name] = {"ms_1t": m1, "ms_2t": m2, "scaling": m1 / m2,
                                  "runs_ms_1t": [1000 * v for v in times[name][1]],
                                  "runs_ms_2t": [1000 * v for v in times[name][2]]}
    print(json.dumps(report, default=float))
    if args.json:
        args.json.write_text(json.dumps(report, indent=1, default=float))
    print(f"\n{'stage':<14}{'1 thread ms':>13}{'2 threads ms':>14}{'scaling':>9}")
    for name, r in report["stages"].items():
        flag = "" if r["scaling"] >= 1.8 else "   < 1.8x"
        print(f"{name:<14}{r['ms_1t']:>13.1f}{r['ms_2t']:>14.1f}{r['scaling']:>8.2f}x{flag}")
    ps = report["probe_scaling"]
    print(f"trivial prange probe, 2 threads / 1 thread: {ps['before']:.2f}x before, "
          f"{ps['after']:.2f}x after (about 2 when both cores were free)")
    for when, mem in report["memory_triad_gb_s"].items():
        print(f"memory probe (triad) {when}: {mem[1]:.1f} GB/s at 1 thread, {mem[2]:.1f} at 2 "
              f"({mem[2] / mem[1]:.2f}x: the most a kernel streaming from memory can scale)")
    return report


if __name__ == "__main__":
    main()
