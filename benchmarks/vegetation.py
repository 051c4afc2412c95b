"""The cost of trees (issue 38): the Berlin-Lichtenberg trees and their LoD2 buildings, with
the trees against the same run without them (goal: at most 1.3x the time without trees).

The scene is the README's: ``cityshade build trees.gml buildings.gml`` (the 288 LiDAR trees,
ImplicitGeometry of 10 prototypes, and the buildings of the same blocks) into ``--workdir``;
``buildings.cityshade`` is the buildings alone, a second anchor (nothing to leave out).

- ``build``: the two-file build, whole process: wall and CPU seconds, peak RSS (``wait4`` of
  the child), the file's size.
- ``render``: ``cityshade render --camera map`` (135°/30°) by ``raytrace``, ``izb`` and
  ``exact``, each with the trees, with ``--no-vegetation`` on the same file, and on the
  buildings' file; whole process (imports, load, camera pass, shadows, EXR).
- ``day``: ``cityshade batch`` of one day (21 June 2025, 15-minute steps, Europe/Berlin, the
  map camera), ``izb`` and ``exact``, the same three states.
- ``in_process``: the per-process set-up of the crowns (``scene_vegetation``) and the shadow
  pass of a map's pixels (the batch's ``_PixelRays.lit``) at five suns, by each engine, with
  against without the trees (CPU seconds, ``time.process_time``: both threads).

Every figure is the median of ``--runs`` runs, the states alternated within each round; the
ratios divide figures of the same round's medians. The CPU time of a whole process (user +
system, its threads included) is the steadier figure on a shared machine; the wall time is
printed too. A first run compiles changed kernels: pass ``--warm`` (one untimed round).

Usage, from the repository root::

    python benchmarks/vegetation.py [--runs 3] [--workdir bench_out/vegetation] [--warm]
        [--only build,render,day,in_process] [--day-engines izb,exact] [--src DIR]
        [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (also: one BLAS thread, before numpy)

REPO = Path(__file__).resolve().parents[1]
DATA = REPO.parent / "shared" / "data" / "citygml" / "berlin-lichtenberg-trees"
TREES = DATA / "semantic_3D_tree_model_berlin_test_area.gml"
BUILDINGS = DATA / "lod2_buildings_berlin_test_area.gml"
STATES = ("with", "no-vegetation", "buildings")
#: The sources the child processes run (``--src``: another checkout's, for a before/after).
SRC = REPO / "src"
DAY_ENGINES = ("izb", "exact")
SUNS = ((90.0, 20.0), (135.0, 40.0), (180.0, 60.0), (225.0, 40.0), (270.0, 20.0))


def _run_child(*args: str) -> dict:
    """One ``python -m cityshade`` process: wall and CPU seconds (user + system, its threads
    included) and peak RSS, its own (the child reaped by ``wait4``)."""
    env = dict(os.environ, PYTHONPATH=str(SRC))
    t0 = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "cityshade", *args], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - t0
    if proc.returncode:
        raise SystemExit(f"cityshade {' '.join(args)} failed:\n{err.decode()[-2000:]}")
    return {"wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime,
            "peak_rss_mb": usage.ru_maxrss / 1024}


def _median(runs: list[dict]) -> dict:
    return {k: round(statistics.median(r[k] for r in runs), 3) for k in runs[0]}


def build_figures(work: Path, runs: int) -> dict:
    scene = work / "berlin.cityshade"
    rows = [_run_child("build", str(TREES), str(BUILDINGS), "-o", str(scene))
            for _ in range(runs)]
    return {**_median(rows), "file_mb": round(scene.stat().st_size / 2**20, 2)}


def ensure_scenes(work: Path) -> None:
    """Build each scene file the workdir lacks, on its own: any partial state of the workdir
    (one file left by an earlier run, the other deleted) works."""
    for name, sources in (("berlin.cityshade", (TREES, BUILDINGS)),
                          ("buildings.cityshade", (BUILDINGS,))):
        if not (work / name).exists():
            _run_child("build", *map(str, sources), "-o", str(work / name))


def _states(work: Path) -> dict[str, list[str]]:
    scene = str(work / "berlin.cityshade")
    return {"with": [scene], "no-vegetation": [scene, "--no-vegetation"],
            "buildings": [str(work / "buildings.cityshade")]}


def _compare(name: str, make_args, engines, work: Path, runs: int, warm: bool) -> dict:
    states = _states(work)
    figures: dict = {}
    for engine in engines:
        per: dict[str, list[dict]] = {s: [] for s in STATES}
        for r in range(runs + (1 if warm else 0)):
            for state in STATES:
                row = _run_child(*make_args(states[state], engine))
                if r or not warm:
                    per[state].append(row)
        med = {s: _median(v) for s, v in per.items()}
        figures[engine] = {
            **med,
            "ratio_cpu": {s: round(med["with"]["cpu_s"] / med[s]["cpu_s"], 3)
                          for s in STATES[1:]},
            "ratio_wall": {s: round(med["with"]["wall_s"] / med[s]["wall_s"], 3)
                           for s in STATES[1:]}}
        print(f"{name} {engine}: {json.dumps(figures[engine])}", file=sys.stderr)
    return figures


def render_figures(work: Path, runs: int, warm: bool) -> dict:
    out = work / "render.exr"

    def args(state, engine):
        file, *extra = state
        return ["render", file, "--camera", "map", "--sun-azimuth", "135", "--sun-elevation",
                "30", "--shadows", engine, *extra, "-o", str(out)]

    return _compare("render", args, ("raytrace", "izb", "exact"), work, runs, warm)


def day_figures(work: Path, runs: int, warm: bool) -> dict:
    def args(state, engine):
        file, *extra = state
        out = work / f"day_{engine}"
        import shutil

        shutil.rmtree(out, ignore_errors=True)  # a run continues a saved state otherwise
        return ["batch", file, "--date", "2025-06-21", "--from", "00:00", "--to", "24:00",
                "--every", "15min", "--tz", "Europe/Berlin", "--camera", "map", "--shadows",
                engine, *extra, "-o", str(out)]

    return _compare("day", args, DAY_ENGINES, work, runs, warm)


def in_process_figures(work: Path, runs: int) -> dict:
    """The crowns' per-process set-up and the shadow pass of a map's pixels at five suns."""
    from cityshade.frame.pipeline import camera_pass
    from cityshade.geo.sun import sun_from_angles
    from cityshade.geometry.vegetation import scene_vegetation, without_vegetation
    from cityshade.raster import camera as cameras
    from cityshade.store.scenefile import load_scene
    from cityshade.sunhours.accumulate import _PixelRays

    setup = []
    for _ in range(runs):
        scene = load_scene(work / "berlin.cityshade")
        t0 = time.process_time()
        scene_vegetation(scene)
        setup.append(time.process_time() - t0)
    t0 = time.process_time()
    bare = without_vegetation(scene)
    without_s = time.process_time() - t0
    cam = cameras.map_view(scene)
    passes = {}
    for name, sc in (("with", scene), ("no-vegetation", bare)):
        cp = camera_pass(sc, cam, 0.0, ground="auto")
        passes[name] = (sc, cp)
    figures = {"scene_vegetation_cpu_s": round(statistics.median(setup), 4),
               "without_vegetation_cpu_s": round(without_s, 4), "engines": {}}
    for engine in ("raytrace", "izb", "exact"):
        cpu: dict[str, list[float]] = {s: [] for s in passes}
        for r in range(runs + 1):  # the first round compiles and sorts: not counted
            for name, (sc, cp) in passes.items():
                rays = _PixelRays(cp, engine, calls=len(SUNS))
                t0 = time.process_time()
                for az, el in SUNS:
                    rays.lit(sc, sun_from_angles(az, el, sc.crs, sc.origin_m), 0.0)
                if r:
                    cpu[name].append(time.process_time() - t0)
        med = {s: round(statistics.median(v), 4) for s, v in cpu.items()}
        figures["engines"][engine] = {
            "cpu_s_per_5_suns": med, "pixels": int(passes["with"][1].valid.sum()),
            "ratio": round(med["with"] / med["no-vegetation"], 3)}
    return figures


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out" / "vegetation")
    ap.add_argument("--warm", action="store_true", help="One untimed round first (compiles).")
    ap.add_argument("--only", default="build,render,day,in_process")
    ap.add_argument("--day-engines", default="izb,exact")
    ap.add_argument("--src", type=Path, help="The children's sources (default: this "
                    "checkout's src/); the in-process part imports what PYTHONPATH says.")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)
    global SRC, DAY_ENGINES
    SRC = args.src or SRC
    DAY_ENGINES = tuple(args.day_engines.split(","))
    if not TREES.exists():
        raise SystemExit(f"no Berlin data at {DATA}")
    args.workdir.mkdir(parents=True, exist_ok=True)
    only = set(args.only.split(","))
    report: dict = {"commit": commit(), "children_src": str(SRC), "machine": platform.node(), "cpus": os.cpu_count(),
                    "runs": args.runs, "load_before": [round(x, 2) for x in os.getloadavg()]}
    if "build" in only:
        report["build"] = build_figures(args.workdir, args.runs)
    ensure_scenes(args.workdir)
    if "render" in only:
        report["render"] = render_figures(args.workdir, args.runs, args.warm)
    if "day" in only:
        report["day"] = day_figures(args.workdir, args.runs, args.warm)
    if "in_process" in only:
        report["in_process"] = in_process_figures(args.workdir, args.runs)
    report["load_after"] = [round(x, 2) for x in os.getloadavg()]
    print(json.dumps(report, indent=1))
    _table(report)
    if args.json:
        args.json.write_text(json.dumps(report, indent=1))
    return report


def _table(report: dict) -> None:
    print(f"\ncommit {report['commit']}, load {report['load_before']} -> {report['load_after']}")
    if "build" in report:
        b = report["build"]
        print(f"build (trees + buildings): {b['wall_s']:.2f} s wall, {b['cpu_s']:.2f} s CPU, "
              f"peak {b['peak_rss_mb']:.0f} MB, file {b['file_mb']} MB")
    for kind in ("render", "day"):
        if kind not in report:
            continue
        print(f"\n{kind:6} {'engine':9} {'with CPU s':>10} {'no-veg CPU':>10} "
              f"{'bldg CPU':>9} {'with/no-veg':>11} {'with/bldg':>9} {'wall ratios':>14}")
        for engine, f in report[kind].items():
            print(f"{'':6} {engine:9} {f['with']['cpu_s']:10.2f} "
                  f"{f['no-vegetation']['cpu_s']:10.2f} {f['buildings']['cpu_s']:9.2f} "
                  f"{f['ratio_cpu']['no-vegetation']:11.2f} {f['ratio_cpu']['buildings']:9.2f} "
                  f"{f['ratio_wall']['no-vegetation']:6.2f}/{f['ratio_wall']['buildings']:.2f}")
    if "in_process" in report:
        p = report["in_process"]
        print(f"\nin process: scene_vegetation {p['scene_vegetation_cpu_s']:.3f} s CPU, "
              f"without_vegetation {p['without_vegetation_cpu_s']:.3f} s CPU")
        for engine, f in p["engines"].items():
            m = f["cpu_s_per_5_suns"]
            print(f"  shadow pass of {f['pixels']} px, 5 suns, {engine:9} with {m['with']:.3f} s, "
                  f"without {m['no-vegetation']:.3f} s CPU: {f['ratio']:.2f}x")


if __name__ == "__main__":
    main()
