"""Does ``exact`` pick the faster engine? Whole-process renders by ``raytrace``, ``izb`` and
``exact`` on the same workloads, and what the cost model chose.

Each run is a fresh ``cityshade render`` process (so ``izb`` pays its caster gathering and sort
as a user's render does), timed as a whole, ``--runs`` times alternated; the median is printed.
The workloads: the map at ``--pixel-size`` and the 1920x1080 overview of ``--scene`` (default
the bundled sample city, built into ``--workdir``; the issue's figures use the 1M-triangle city:
``--scene bench_out/city_1M.cityshade``). ``exact``'s choice comes from its ``render -v`` note.

Usage: python benchmarks/exact_choice.py [--scene FILE] [--pixel-size 1] [--runs 3]
       [--workdir bench_out] [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
ENGINES = ("raytrace", "izb", "exact")


def _scene(args) -> Path:
    if args.scene:
        return Path(args.scene)
    out = Path(args.workdir) / "sample_city.cityshade"
    if not out.exists():
        out.parent.mkdir(parents=True, exist_ok=True)
        subprocess.run([sys.executable, "-m", "cityshade", "build",
                        str(REPO / "sample_data" / "sample_city.gml"), "-o", str(out)],
                       check=True, capture_output=True)
    return out


def _render(scene: Path, technique: str, view: list[str], out: Path) -> tuple[float, str]:
    cmd = [sys.executable, "-m", "cityshade", "render", str(scene), "--sun-azimuth", "135",
           "--sun-elevation", "30", "--shadows", technique, "-o", str(out), "-v", *view]
    t0 = time.perf_counter()
    run = subprocess.run(cmd, check=True, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    note = next((line.split(None, 1)[1] for line in (run.stdout + run.stderr).splitlines()
                 if line.startswith("note ")), "")
    return wall, note


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene")
    ap.add_argument("--pixel-size", type=float, default=1.0)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--workdir", default="bench_out")
    ap.add_argument("--json")
    args = ap.parse_args(argv)
    scene = _scene(args)
    out = Path(args.workdir) / "exact_choice.exr"
    views = {"map": ["--camera", "map", "--pixel-size", str(args.pixel_size)],
             "overview": ["--size", "1920x1080"]}
    result = {"commit": commit(), "scene": str(scene), "runs": args.runs, "workloads": {}}
    for name, view in views.items():
        _render(scene, "exact", view, out)          # compiles, warms the page cache
        walls: dict[str, list[float]] = {e: [] for e in ENGINES}
        note = ""
        for _ in range(args.runs):
            for engine in ENGINES:
                wall, n = _render(scene, engine, view, out)
                walls[engine].append(wall)
                note = n if engine == "exact" else note
        med = {e: statistics.median(w) for e, w in walls.items()}
        chose = "izb" if "engine izb" in note else "raytrace"
        faster = min(("raytrace", "izb"), key=med.get)
        result["workloads"][name] = {"median_s": med, "chose": chose, "faster": faster,
                                     "regret": med[chose] / med[faster], "note": note}
    print(json.dumps(result, indent=1))
    print(f"\n{'workload':10} {'raytrace s':>11} {'izb s':>8} {'exact s':>8} {'chose':>9} "
          f"{'faster':>9} {'chosen/faster':>14}")
    for name, w in result["workloads"].items():
        m = w["median_s"]
        print(f"{name:10} {m['raytrace']:11.2f} {m['izb']:8.2f} {m['exact']:8.2f} "
              f"{w['chose']:>9} {w['faster']:>9} {w['regret']:14.2f}")
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=1))
    return result


if __name__ == "__main__":
    main()
