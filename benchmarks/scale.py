"""Scale figures of issue 15 on the 10^7-triangle city: build, cache load, a 20 Mpx map render.

Every figure runs ``cityshade`` in a child process (``python -m cityshade`` of ``--python``,
so the same script measures another checkout: ``--python /path/to/base/.venv/bin/python``)
and reports its wall time and peak RSS (``getrusage(RUSAGE_CHILDREN)`` of a fresh wrapper per
run). Goals (issue 15 point 2): build peak RSS <= 1.5 x cache size + 300 MB, build <= 60 s on
both cores, a cache load <= 0.5 s however large, a 20 Mpx map render within 2 GB.

* ``build_figures`` — ``cityshade build CITY -o CACHE`` (once per thread count in
  ``--threads``: ``NUMBA_NUM_THREADS``), with the build's own stage timings.
* ``load_figures`` — ``load_scene`` in a child: the first load after the build, then
  ``--repeat`` more (median), and a load with every checksum checked (``verify=True``, what
  ``info --verify`` does), so the cost the verified stamp saves is measured beside it.
* ``render_figures`` — ``cityshade render CACHE --camera map --pixel-size P`` at the pixel
  size that gives about ``--megapixels`` over the model's box (EXR and mask PNG outputs), with
  ``--shadows`` and ``--strip-rows`` passed on (without ``--strip-rows`` the render decides:
  a map this large goes in strips of rows by itself), and the stage timings of ``-v``; a
  render at 20x the pixel size runs first, so the figure does not include compiling.

The tiled and Dask batch figures of the same issue: ``benchmarks/scale_batch.py``.

Usage::

    python benchmarks/scale.py --city /work/bench_data/city_10000000.gml \\
        --workdir /work/bench_data/build2 [--threads 2] [--repeat 5] [--skip-build]
    python benchmarks/scale.py --cache /work/bench_data/final10m/city_10000000.cityshade \
        --workdir /tmp/scale --render-only [--strip-rows N] [--shadows izb]

MB are 10^6 bytes. Prints one JSON object (with the git commit), then a table.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
MB = 1e6

#: Runs a command in a child and reports its wall time and peak RSS (ru_maxrss is KiB on Linux).
_WRAPPER = r"""
import json, resource, subprocess, sys, time
t0 = time.perf_counter()
proc = subprocess.run(sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
seconds = time.perf_counter() - t0
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"returncode": proc.returncode, "seconds": seconds,
                  "peak_rss_bytes": usage.ru_maxrss * 1024,
                  "stdout": proc.stdout[-4000:], "stderr": proc.stderr[-8000:]}))
"""

#: One load in a fresh process: seconds of load_scene alone (after the imports).
_LOAD_CHILD = r"""
import json, sys, time
from cityshade.store.scenefile import load_scene
verify = {"auto": "auto", "full": True}[sys.argv[2]]
t0 = time.perf_counter()
try:
    scene = load_scene(sys.argv[1], verify=verify)
except TypeError:  # a checkout older than the verified stamp: its default checks everything
    scene = load_scene(sys.argv[1], verify=sys.argv[2] == "full")
seconds = time.perf_counter() - t0
print(json.dumps({"load_s": seconds, "triangles": scene.n_triangles}))
"""


def git_commit(python: str) -> str:
    # absolute(), not resolve(): a venv's python links to the base interpreter (pyenv's repo)
    where = Path(python).absolute().parents[2] if "/.venv/" in python else REPO
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=where,
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def run_measured(cmd: list[str], env: dict | None = None) -> dict:
    """Wall time, peak RSS and output tails of ``cmd`` run in a child of a fresh wrapper."""
    proc = subprocess.run([sys.executable, "-c", _WRAPPER, *cmd], capture_output=True,
                          text=True, env=env)
    if proc.returncode != 0:
        return {"returncode": proc.returncode, "stderr": proc.stderr[-2000:]}
    return json.loads(proc.stdout.strip().splitlines()[-1])


def build_figures(python: str, city: Path, cache: Path, threads: int) -> dict:
    """One ``cityshade build`` of ``city`` into ``cache`` at ``threads`` Numba threads."""
    env = dict(os.environ, NUMBA_NUM_THREADS=str(threads))
    run = run_measured([python, "-m", "cityshade", "build", str(city), "-o", str(cache), "-q"],
                       env)
    if run.get("returncode"):
        return {"error": run.get("stderr", "")[-500:]}
    size = cache.stat().st_size
    header = _header(python, cache)
    peak = run["peak_rss_bytes"]
    goal = 1.5 * size + 300 * MB
    return {"threads": threads, "seconds": round(run["seconds"], 2),
            "city_mb": round(city.stat().st_size / MB, 1),
            "mb_per_s": round(city.stat().st_size / MB / run["seconds"], 1),
            "cache_mb": round(size / MB, 1), "peak_rss_mb": round(peak / MB),
            "goal_peak_mb": round(goal / MB), "peak_goal_met": peak <= goal,
            "time_goal_met": run["seconds"] <= 60.0,
            "stages_s": header.get("report", {}).get("timings"),
            "kdtree": {k: header.get("kdtree_stats", {}).get(k)
                       for k in ("nodes", "duplication", "sah_cost", "build_s")}}


def _header(python: str, cache: Path) -> dict:
    code = ("import json, sys; from cityshade.store.scenefile import read_header; "
            "h = read_header(sys.argv[1]); h.pop('arrays', None); print(json.dumps(h))")
    proc = subprocess.run([python, "-c", code, str(cache)], capture_output=True, text=True)
    return json.loads(proc.stdout) if proc.returncode == 0 else {}


def load_figures(python: str, cache: Path, repeat: int) -> dict:
    """Load times in fresh processes: first after the build, ``repeat`` more, and full checks."""
    def one(mode: str) -> dict:
        proc = subprocess.run([python, "-c", _LOAD_CHILD, str(cache), mode], capture_output=True,
                              text=True)
        if proc.returncode != 0:
            return {"error": proc.stderr.strip().splitlines()[-1:]}
        return json.loads(proc.stdout.strip().splitlines()[-1])

    first = one("auto")
    runs = [one("auto") for _ in range(repeat)]
    full = [one("full") for _ in range(max(1, repeat // 2))]
    if any("error" in r for r in [first, *runs, *full]):
        return {"error": next(r["error"] for r in [first, *runs, *full] if "error" in r)}
    median = statistics.median(r["load_s"] for r in runs)
    return {"first_after_build_s": round(first["load_s"], 3), "median_s": round(median, 3),
            "runs_s": [round(r["load_s"], 3) for r in runs],
            "full_check_median_s": round(statistics.median(r["load_s"] for r in full), 3),
            "goal_met": median <= 0.5}


def render_figures(python: str, cache: Path, workdir: Path, megapixels: float,
                   shadows: str = "raytrace", strip_rows: int | None = None) -> dict:
    """A top-down map render of about ``megapixels`` Mpx: wall time and peak RSS."""
    code = ("import json, sys; from cityshade.store.scenefile import load_scene; "
            "s = load_scene(sys.argv[1], with_kdtree=False); v = s.vertices; "
            "lo = v.min(axis=0); hi = v.max(axis=0); print(json.dumps([float(x) for x in hi - lo]))")
    proc = subprocess.run([python, "-c", code, str(cache)], capture_output=True, text=True)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-1:]}
    ex, ey, _ = json.loads(proc.stdout)
    pixel_m = math.sqrt(ex * ey / (megapixels * 1e6))
    pixel_m = math.ceil(pixel_m * 1000) / 1000
    out = workdir / "scale_map.exr"
    cmd = [python, "-m", "cityshade", "render", str(cache), "--camera", "map", "--pixel-size",
           str(pixel_m), "--sun-azimuth", "135", "--sun-elevation", "30", "--date", "2000",
           "-o", str(out), "--mask", str(workdir / "scale_map_mask.png"), "-v",
           "--shadows", shadows]
    if strip_rows is not None:
        cmd += ["--strip-rows", str(strip_rows)]
    # A coarse render first (1/400 of the pixels, same technique): on a fresh checkout the
    # measured run would otherwise include compiling the kernels (session 19: 16.6 s of
    # G-buffer on the first run, 1.0 s on the next).
    warm = cmd.copy()
    warm[warm.index("--pixel-size") + 1] = str(pixel_m * 20)
    warm[warm.index("-o") + 1] = str(workdir / "scale_warm.exr")
    warm[warm.index("--mask") + 1] = str(workdir / "scale_warm_mask.png")
    warm_run = run_measured(warm)
    run = run_measured(cmd)
    if run.get("returncode"):
        return {"error": run.get("stderr", "")[-500:], "pixel_m": pixel_m}
    peak = run["peak_rss_bytes"]
    return {"pixel_m": pixel_m, "megapixels": round(ex * ey / pixel_m ** 2 / 1e6, 1),
            "shadows": shadows, "strip_rows": strip_rows,
            "seconds": round(run["seconds"], 2), "peak_rss_mb": round(peak / MB),
            "warm_up_seconds": round(warm_run["seconds"], 2),
            "goal_met": peak <= 2000 * MB,
            "timings": next((ln for ln in run["stderr"].splitlines() if ln.startswith("timings")),
                            None),
            "log_tail": run["stderr"].strip().splitlines()[-12:]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--city", type=Path, default=Path("/work/bench_data/city_10000000.gml"))
    parser.add_argument("--workdir", type=Path, default=Path("/work/bench_data/scale"))
    parser.add_argument("--python", default=sys.executable,
                        help="Python of the checkout to measure (default: this one)")
    parser.add_argument("--threads", default="2", help="comma-separated thread counts")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--megapixels", type=float, default=20.0)
    parser.add_argument("--skip-build", action="store_true",
                        help="reuse WORKDIR/CITY.cityshade (no build figures)")
    parser.add_argument("--cache", type=Path,
                        help="an existing cache to load and render (read only; no build)")
    parser.add_argument("--render-only", action="store_true", help="only the map render")
    parser.add_argument("--shadows", default="raytrace", help="technique of the map render")
    parser.add_argument("--strip-rows", type=int,
                        help="render --strip-rows N (default: the render decides)")
    args = parser.parse_args(argv)
    args.workdir.mkdir(parents=True, exist_ok=True)
    cache = args.cache or args.workdir / (args.city.stem + ".cityshade")
    result = {"commit": git_commit(args.python), "python": args.python,
              "city": str(args.city if args.cache is None else cache)}
    if not (args.skip_build or args.cache or args.render_only):
        result["build"] = [build_figures(args.python, args.city, cache, int(t))
                           for t in args.threads.split(",")]
    if not args.render_only:
        result["load"] = load_figures(args.python, cache, args.repeat)
    result["render"] = render_figures(args.python, cache, args.workdir, args.megapixels,
                                      args.shadows, args.strip_rows)
    print(json.dumps(result, indent=1))
    for b in result.get("build", []):
        if "error" not in b:
            print(f"build {b['threads']} thr: {b['seconds']} s ({b['mb_per_s']} MB/s), peak "
                  f"{b['peak_rss_mb']} MB (goal {b['goal_peak_mb']}), cache {b['cache_mb']} MB")
    ld = result.get("load", {"error": "not run"})
    if "error" not in ld:
        print(f"load: median {ld['median_s']} s (first after build {ld['first_after_build_s']} "
              f"s, all checksums {ld['full_check_median_s']} s)")
    r = result["render"]
    if "error" not in r:
        print(f"map render {r['megapixels']} Mpx at {r['pixel_m']} m ({r['shadows']}, "
              f"strip rows {r['strip_rows'] or 'auto'}): {r['seconds']} s, peak "
              f"{r['peak_rss_mb']} MB (goal 2000: {'met' if r['goal_met'] else 'not met'})")
        print(f"  {r['timings']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
