"""Batch benchmark: sun-hours of a summer day on the 1M-triangle city, map view at 1 m.

Input: the synthetic benchmark city of ``cityshade.samplegen`` (1 000 000 triangles, seed 7),
generated into ``--workdir`` (default ``bench_out/``) and built once, as in
``benchmarks/render.py``. The city as it stood on 2000-01-01.

Work: ``cityshade.sunhours.accumulate.sun_hours`` with the technique ``--shadows`` (default ``izb``, as
``cityshade batch``; ``raytrace`` is the kd-tree), a top-down map view of the model's extent at
``--pixel-size`` (default 1 m; ``--side 2048`` takes a 2048² window centred on the model
instead), one day ``--date`` (default the summer solstice 2024-06-21; 2024-12-21 is the low-sun
day with the longest shadows; Europe/Berlin, 00:00–24:00) every ``--every`` (default 10 min):
144 steps, of which those with the sun up are computed. ``--compare raytrace`` also runs that
technique once and reports whether the sun-hours are identical, byte for byte.

Reported (median of ``--repeat`` runs after one warm-up run that compiles the kernels):

* total seconds of the call (camera pass once + every sun position + sums);
* Mpixel-steps/s = surface pixels × computed sun positions / total seconds;
* the shadow-kernel seconds (the technique's ``run``) and the share of time spent outside it
  (sun positions, camera pass, masking and float64 sums);
* one run with a checkpoint (the state saved after every step, as ``cityshade batch`` does)
  and its extra seconds.

Peer context (different work and machine): SOLWEIG reports ~1.45 Mpx/s per time step for its
full pipeline on a laptop. Goal of the issue: ≥ 20 Mpixel-steps/s with exact shadows.

Usage: python benchmarks/batch.py [--repeat 3] [--pixel-size 1] [--side 0] [--every 10min]
       [--shadows raytrace|izb|...] [--date 2024-06-21] [--compare raytrace]
       [--workdir bench_out] [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import tempfile
import time
from datetime import date
from pathlib import Path


REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)
from render import ensure_scene  # noqa: E402  (same input city as the render benchmark)

DAY_2000 = 10957.0  # 2000-01-01 in days since 1970-01-01


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--pixel-size", type=float, default=1.0)
    ap.add_argument("--side", type=int, default=0,
                    help="square window of this many pixels centred on the model (0: extent)")
    ap.add_argument("--every", default="10min")
    ap.add_argument("--shadows", default="izb",
                    help="technique: izb or raytrace (exact, the same answer), or e.g. "
                         "hybrid:shadowmap")
    ap.add_argument("--date", default="2024-06-21", help="the day (YYYY-MM-DD)")
    ap.add_argument("--compare", default=None,
                    help="also run this technique once; report identical sun-hours")
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    import numba

    from cityshade.sunhours import accumulate as A
    from cityshade.sunhours import checkpoint as C
    from cityshade.sunhours import plan as P
    from cityshade.raster.camera import map_view, scene_box
    from cityshade.store.scenefile import load_scene
    from cityshade.geo.sun import suns_from_instants

    scene = load_scene(ensure_scene(args.workdir, args.triangles, args.seed))
    if args.side:
        box = scene_box(scene)
        cx, cy = 0.5 * (box[0, :2] + box[1, :2])
        half = 0.5 * args.side * args.pixel_size
        cam = map_view(scene, args.pixel_size, bbox=(cx - half, cy - half, cx + half - 1e-6,
                                                     cy + half - 1e-6), max_px=16384)
    else:
        cam = map_view(scene, args.pixel_size, max_px=16384)
    steps = P.plan_steps(date.fromisoformat(args.date), 0, 86_400, P.parse_duration_s(args.every),
                         "Europe/Berlin")
    instants = [s.centre_utc for s in steps]
    weights = [s.weight_h for s in steps]
    t = time.perf_counter()
    suns_from_instants(instants, scene.crs, scene.origin_m)  # SPA alone, for the table
    spa_s = time.perf_counter() - t

    def run(checkpoint=None, technique=args.shadows):
        return A.sun_hours(scene, cam, instants, DAY_2000, weights_h=weights,
                           checkpoint=checkpoint, technique=technique)

    # Warm-up: compile every kernel on two sun positions.
    noon = len(instants) // 2  # sun up at midday whatever --every is
    A.sun_hours(scene, cam, instants[noon:noon + 2], DAY_2000, weights_h=weights[noon:noon + 2],
                technique=args.shadows)
    runs = [run() for _ in range(args.repeat)]
    totals = [r.timings_s["total_s"] for r in runs]
    shadow = [r.timings_s["shadow_s"] for r in runs]
    med = statistics.median(totals)
    r0 = runs[0]
    valid_px = int(r0.valid.sum())
    mpx_steps = valid_px * r0.units / 1e6
    with tempfile.TemporaryDirectory(dir=args.workdir) as tmp:
        ck = C.Checkpoint(Path(tmp) / C.STATE_NAME, "bench")
        with_ck = run(checkpoint=ck)
    same = all(r.hours.tobytes() == r0.hours.tobytes() for r in runs + [with_ck])
    compared = None
    if args.compare:
        other = run(technique=args.compare)
        compared = {"technique": args.compare, "total_s": other.timings_s["total_s"],
                    "mpixel_steps_per_s": mpx_steps / other.timings_s["total_s"],
                    "identical_sun_hours": other.hours.tobytes() == r0.hours.tobytes(),
                    "differing_px": int((other.hours != r0.hours).sum())}
    result = {
        "benchmark": "batch",
        "commit": commit(),
        "machine": {"cpu_count": os.cpu_count(), "platform": platform.platform(),
                    "python": platform.python_version(), "numba_threads": numba.get_num_threads()},
        "scene": {"triangles": scene.n_triangles, "city_date": "2000-01-01"},
        "technique": args.shadows,
        "map": {"width_px": cam.width_px, "height_px": cam.height_px,
                "pixel_size_m": cam.pixel_size_m, "surface_px": valid_px},
        "day": {"date": args.date, "tz": "Europe/Berlin", "every": args.every,
                "steps": r0.steps, "steps_below_horizon": r0.steps_below_horizon,
                "sun_positions_computed": r0.units, "hours_sun_up": r0.hours_sun_up},
        "spa_s_all_steps": spa_s,
        "total_s_runs": totals,
        "total_s_median": med,
        "shadow_kernel_s_median": statistics.median(shadow),
        "share_outside_shadow_kernel": 1.0 - statistics.median(shadow) / med,
        "camera_pass_s": r0.timings_s["camera_s"],
        "mpixel_steps": mpx_steps,
        "mpixel_steps_per_s": mpx_steps / med,
        "mpixel_per_s_per_step_incl_camera": valid_px / 1e6 / (med / r0.units),
        "with_checkpoint_total_s": with_ck.timings_s["total_s"],
        "checkpoint_s": with_ck.timings_s["checkpoint_s"],
        "results_identical_across_runs": same,
        "compared": compared,
        "goal_mpixel_steps_per_s": 20.0,
        "peer_context": "SOLWEIG ~1.45 Mpx/s per time step (laptop, full pipeline; other work)",
    }
    print(json.dumps(result, indent=2))
    rows = [
        ("map", f"{cam.width_px}x{cam.height_px} px at {cam.pixel_size_m:g} m, "
                f"{valid_px / 1e6:.2f} M surface px"),
        ("steps", f"{r0.steps} ({r0.steps_below_horizon} sun down), {r0.units} computed"),
        ("total (median)", f"{med:.2f} s  (runs: {', '.join(f'{v:.2f}' for v in totals)})"),
        ("Mpixel-steps/s", f"{result['mpixel_steps_per_s']:.1f}  (goal 20)"),
        ("shadow kernel", f"{result['shadow_kernel_s_median']:.2f} s; outside it "
                          f"{100 * result['share_outside_shadow_kernel']:.1f} %"),
        ("camera pass", f"{r0.timings_s['camera_s']:.2f} s (once)"),
        ("SPA, all steps", f"{spa_s * 1000:.1f} ms"),
        ("with checkpoint", f"{with_ck.timings_s['total_s']:.2f} s "
                            f"(state saves {with_ck.timings_s['checkpoint_s']:.2f} s)"),
        ("identical runs", str(same)),
    ]
    if compared:
        rows.append((f"vs {compared['technique']}",
                     f"{compared['mpixel_steps_per_s']:.1f} Mpixel-steps/s "
                     f"({compared['total_s']:.2f} s); identical sun-hours: "
                     f"{compared['identical_sun_hours']} ({compared['differing_px']} px differ)"))
    print()
    for k, v in rows:
        print(f"{k:<18} {v}")
    if args.json:
        args.json.write_text(json.dumps(result, indent=2) + "\n")
    return result


if __name__ == "__main__":
    main()
