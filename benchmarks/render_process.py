"""Whole-process map render of the benchmark city: what a user waits for (issue 41's goal: the
default exact technique ≤ 0.7 × the issue's `--shadows raytrace`, peak ≤ 911 MiB, the unit of
the issue's figures: ru_maxrss in KiB / 1024).

Each run is one ``python -m cityshade render SCENE --camera map --pixel-size 1 --sun-azimuth
135 --sun-elevation 30 --shadows T -o OUT.exr`` in a fresh process, timed from outside, its
peak resident set read by a one-run wrapper process (``getrusage(RUSAGE_CHILDREN)``). The cases
run alternately, round after round, after one warm-up each (which may compile into its own
checkout's Numba cache): this checkout with the default technique and with ``raytrace``, and,
with ``--anchor SRC``, another checkout's ``raytrace`` (the issue's figure was taken at
cd5487c). Medians with every round's figure; the ratios are to the anchor of the same run.

Each checkout's modules are byte-compiled first (``compileall``, into its ``__pycache__``), as
``pip install .`` installs them: a user's process reads bytecode. Where
``PYTHONDONTWRITEBYTECODE`` is set (this project's benchmark machine), a process started on a
source tree without it compiles every module it imports, about 0.1 s of the 1M map's render
(58 modules); ``--from-source`` measures that way, as the figures before session 35 did (it
deletes the checkouts' ``.pyc`` files, never Numba's cache).

Usage::

    python benchmarks/render_process.py --scene /work/bench/city_1M.cityshade --rounds 7 \\
        --anchor /path/to/cd5487c/src
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

REPO = Path(__file__).resolve().parents[1]

#: One render in a child, its wall time and peak RSS (ru_maxrss: KiB on Linux); a fresh wrapper
#: process sees only this child. The child starts with the kernel's transparent huge pages,
#: whatever its parent had (the flag is inherited), so each checkout runs as its own command
#: decides: since session 33 ``render`` turns them off.
_WRAPPER = r"""
import ctypes, json, resource, subprocess, sys, time
try:
    ctypes.CDLL(None).prctl(41, 0, 0, 0, 0)   # PR_SET_THP_DISABLE off: the kernel's setting
except (OSError, AttributeError):
    pass
t0 = time.perf_counter()
proc = subprocess.run(sys.argv[1:], capture_output=True, text=True)
seconds = time.perf_counter() - t0
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"returncode": proc.returncode, "seconds": seconds,
                  "cpu_s": usage.ru_utime + usage.ru_stime,
                  "peak_mib": usage.ru_maxrss / 1024,
                  "stderr": proc.stderr.strip().splitlines()[-1:]}))
"""


def _run(src: Path, scene: Path, shadows: str | None, out: Path) -> dict:
    args = [sys.executable, "-m", "cityshade", "render", str(scene), "--camera", "map",
            "--pixel-size", "1", "--sun-azimuth", "135", "--sun-elevation", "30",
            "-o", str(out)]
    if shadows:
        args += ["--shadows", shadows]
    env = dict(os.environ, PYTHONPATH=str(src))
    done = subprocess.run([sys.executable, "-c", _WRAPPER, *args], env=env,
                          capture_output=True, text=True, check=True)
    result = json.loads(done.stdout)
    if result["returncode"] != 0:
        raise SystemExit(f"render with {src} failed: {result['stderr']}")
    return result


def _byte_compile(src: Path) -> None:
    """Write the bytecode of every module under ``src`` that is missing or stale."""
    done = subprocess.run([sys.executable, "-m", "compileall", "-q", str(src)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"byte-compiling {src} failed: {done.stdout.strip()[-300:]}")


def _drop_bytecode(src: Path) -> None:
    """Delete the bytecode under ``src`` (the ``.pyc`` files of its ``__pycache__`` folders)."""
    for pyc in src.rglob("__pycache__/*.pyc"):
        pyc.unlink()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", type=Path, required=True, help="the 1M city's .cityshade")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--anchor", type=Path, help="another checkout's src/: its raytrace too")
    ap.add_argument("--from-source", action="store_true",
                    help="leave the checkouts without bytecode (see above)")
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    cases = {"default": (REPO / "src", None), "raytrace": (REPO / "src", "raytrace")}
    if a.anchor:
        cases["anchor raytrace"] = (a.anchor, "raytrace")
    for src in {src for src, _ in cases.values()}:
        (_drop_bytecode if a.from_source else _byte_compile)(src)
    runs: dict[str, list[dict]] = {name: [] for name in cases}
    loads = []
    with tempfile.TemporaryDirectory(prefix="cityshade-render-process-") as tmp:
        out = Path(tmp) / "frame.exr"
        for src, shadows in cases.values():
            _run(src, a.scene, shadows, out)  # warm-up: kernels compiled or loaded, pages read
        for _ in range(a.rounds):
            loads.append(os.getloadavg()[0])
            for name, (src, shadows) in cases.items():
                runs[name].append(_run(src, a.scene, shadows, out))
    median = {name: {"wall_s": statistics.median(r["seconds"] for r in rs),
                     "cpu_s": statistics.median(r["cpu_s"] for r in rs),
                     "peak_mib": statistics.median(r["peak_mib"] for r in rs)}
              for name, rs in runs.items()}
    anchor = "anchor raytrace" if a.anchor else "raytrace"
    report = {"commit": commit(REPO / "src"),
              "anchor_commit": commit(a.anchor) if a.anchor else None,
              "scene": str(a.scene), "rounds": a.rounds, "load": loads, "median": median,
              "bytecode": "source" if a.from_source else "compiled",
              "runs_s": {n: [round(r["seconds"], 3) for r in rs] for n, rs in runs.items()},
              "default_over_anchor": median["default"]["wall_s"] / median[anchor]["wall_s"]}
    print(json.dumps(report, indent=1))
    print(f"\nwhole-process map render, {a.scene.name}, median of {a.rounds} (load "
          f"{min(loads):.1f}-{max(loads):.1f}; modules {report['bytecode']})")
    print(f"{'case':<18}{'wall s':>8}{'CPU s':>8}{'peak MiB':>9}{'/ ' + anchor:>20}  rounds")
    for name, m in median.items():
        each = ", ".join(f"{r['seconds']:.2f}" for r in runs[name])
        print(f"{name:<18}{m['wall_s']:>8.2f}{m['cpu_s']:>8.2f}{m['peak_mib']:>9.0f}"
              f"{m['wall_s'] / median[anchor]['wall_s']:>19.2f}x  [{each}]")
    if a.json:
        a.json.write_text(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
