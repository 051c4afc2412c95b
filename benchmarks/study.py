"""Wall time of ``cityshade study`` as a user runs it (issue 39: under a minute each).

Two studies of the sample city (``sample_data/sample_city.gml``, built once into a temporary
scene file, not timed), each 21 March, 21 June and 21 December 2025, hourly 08:00-18:00 Berlin
time (33 panels, 66 shadow passes), izb, the default map (1024 px on the longer side):

- ``1750-vs-1990``: one model at two dates (``--before 1750 --after 1990``);
- ``proposal``: the model with ``sample_data/proposal_block.gml`` added (``--with``), the
  garden of the planning example as the site boundary.

Each study is one ``python -m cityshade study`` process (imports and Numba's cached kernels
included; a first run after a change of the kernels also compiles them: run twice). Prints
one JSON object and a table.

Usage, from the repository root::

    python benchmarks/study.py [--pixel-size M] [--out DIR]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

REPO = Path(__file__).resolve().parents[1]
SAMPLE = REPO / "sample_data" / "sample_city.gml"
PROPOSAL = REPO / "sample_data" / "proposal_block.gml"
COMMON = ["--year", "2025", "--from", "08:00", "--to", "18:00", "--every", "1h",
          "--tz", "Europe/Berlin"]
STUDIES = {
    "1750-vs-1990": ["--before", "1750", "--after", "1990"],
    "proposal": ["--with", str(PROPOSAL), "--area", "690110,5336122,690140,5336131"],
}


def _cityshade(*args: str, env: dict | None = None) -> tuple[float, float]:
    """(wall seconds, CPU seconds: user + system) of one ``python -m cityshade`` process
    (``env``: its environment, default this one with this checkout's ``src/``). On a shared
    machine the CPU time is the steadier figure: the wall time waits for the other processes'
    turns."""
    import resource

    env = env or dict(os.environ, PYTHONPATH=str(REPO / "src"))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    out = subprocess.run([sys.executable, "-m", "cityshade", *args], env=env,
                         capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if out.returncode != 0:
        raise SystemExit(f"cityshade {' '.join(args)} failed:\n{out.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return seconds, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pixel-size", help="Metres per map pixel (default: the command's).")
    parser.add_argument("--out", type=Path, help="Keep the studies here (default: a "
                        "temporary folder, removed).")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="cityshade-study-bench-") as tmp:
        out = args.out or Path(tmp)
        out.mkdir(parents=True, exist_ok=True)
        scene = out / "sample_city.cityshade"
        build_s, _ = _cityshade("build", str(SAMPLE), "-o", str(scene))
        extra = ["--pixel-size", args.pixel_size] if args.pixel_size else []
        rows = []
        for name, states in STUDIES.items():
            folder = out / name
            seconds, cpu = _cityshade("study", str(scene), *states, *COMMON, *extra,
                                    "-o", str(folder))
            index = json.loads((folder / "study.json").read_text(encoding="utf-8"))
            rows.append({"study": name, "wall_s": round(seconds, 2), "cpu_s": round(cpu, 2),
                         "panels": len(index["panels"]), "map_px": index["map_px"],
                         "pixel_size_m": index["pixel_size_m"],
                         "sheets": len(list(folder.glob("sheet_*.png")))})
    report = {"commit": commit(REPO), "machine": platform.node(), "cpus": os.cpu_count(),
              "load_1min": round(os.getloadavg()[0], 2),
              "build_s": round(build_s, 2), "studies": rows}
    print(json.dumps(report, indent=2))
    print(f"\n{'study':<14} {'panels':>6} {'map px':>11} {'px m':>6} {'wall s':>8} "
          f"{'CPU s':>8}")
    for r in rows:
        print(f"{r['study']:<14} {r['panels']:>6} {'×'.join(map(str, r['map_px'])):>11} "
              f"{r['pixel_size_m']:>6g} {r['wall_s']:>8.2f} {r['cpu_s']:>8.2f}")


if __name__ == "__main__":
    main()
