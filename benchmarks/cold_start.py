"""First use with an empty Numba cache: `build`, the first `render` (overview) and the first
`batch` of the bundled sample city, as a new user runs them one after the other (issue 40).

Each round empties a fresh Numba cache folder (``NUMBA_CACHE_DIR`` in a temporary folder) and
runs, in child processes of the ``cityshade`` command (``python -m cityshade``) of the checkout
given by ``--src`` (default: this one's ``src/``), in this order, so each command finds the
kernels the earlier ones compiled (as a user's cache does):

1. ``build sample_data/sample_city.gml``
2. ``render`` the overview (the README's demo line: 1990, sun 135°/30°, EXR + PNG)
3. ``batch`` a map day (2025-03-21 06:00-19:00 every 15 min, Europe/Berlin, map 1 m/px,
   ``--surfaces``)
4. the same ``render`` again, warm (everything from the cache): the anchor

Reported per command: wall seconds and CPU seconds (user + system of the child, from
``resource.getrusage``), the median of ``--rounds`` rounds, and the load average at the
start of each round. With ``--compare OTHER_SRC``, rounds alternate between the two checkouts
(same conditions), and the ratio of medians is printed.

Usage: python benchmarks/cold_start.py [--rounds 3] [--src PATH] [--compare PATH] [--json F]
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)
from study import _cityshade  # noqa: E402  (one child-process timer for the benchmarks)

REPO = Path(__file__).resolve().parents[1]
SAMPLE = REPO / "sample_data" / "sample_city.gml"


def _commands(work: Path) -> list[tuple[str, list[str]]]:
    scene = str(work / "city.cityshade")
    render = ["render", scene, "--city-date", "1990", "--sun-azimuth", "135",
              "--sun-elevation", "30", "-o", str(work / "city.exr"), "--png",
              str(work / "city.png")]
    return [
        ("build", ["build", str(SAMPLE), "-o", scene]),
        ("render", render),
        ("batch", ["batch", scene, "--date", "2025-03-21", "--from", "06:00", "--to", "19:00",
                   "--every", "15min", "--tz", "Europe/Berlin", "--camera", "map",
                   "--pixel-size", "1", "--surfaces", "-o", str(work / "march")]),
        ("render warm", render),
    ]


def one_round(src: Path) -> dict:
    with tempfile.TemporaryDirectory(prefix="cityshade-cold-") as tmp:
        work = Path(tmp)
        env = dict(os.environ, PYTHONPATH=str(src), NUMBA_CACHE_DIR=str(work / "numba"))
        out = {"load": os.getloadavg()[0]}
        for name, args in _commands(work):
            out[name] = _cityshade(*args, env=env)
        return out


def _summary(rounds: list[dict]) -> dict:
    names = [k for k in rounds[0] if k != "load"]
    return {name: {"wall_s": statistics.median(r[name][0] for r in rounds),
                   "cpu_s": statistics.median(r[name][1] for r in rounds)} for name in names}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--src", type=Path, default=REPO / "src")
    ap.add_argument("--compare", type=Path, default=None,
                    help="another checkout's src/, run alternately with --src")
    ap.add_argument("--json", type=Path, default=None)
    a = ap.parse_args()
    sources = [a.src] + ([a.compare] if a.compare else [])
    results: dict[str, list[dict]] = {str(s): [] for s in sources}
    for k in range(a.rounds):
        for src in sources:
            r = one_round(src)
            results[str(src)].append(r)
            print(f"round {k + 1} {src}: load {r['load']:.2f} " + ", ".join(
                f"{n} {v[0]:.1f} s ({v[1]:.1f} CPU s)" for n, v in r.items() if n != "load"),
                flush=True)
    summary = {src: _summary(rs) for src, rs in results.items()}
    for src, s in summary.items():
        print(f"median of {a.rounds}, {src} ({commit(src)}): " + ", ".join(
            f"{n} {v['wall_s']:.1f} s ({v['cpu_s']:.1f} CPU s)" for n, v in s.items()))
    if a.compare:
        base, new = summary[str(a.compare)], summary[str(a.src)]
        print("ratio --src / --compare (CPU): " + ", ".join(
            f"{n} {new[n]['cpu_s'] / base[n]['cpu_s']:.2f}x" for n in new))
    if a.json:
        a.json.write_text(json.dumps({"commits": {s: commit(s) for s in summary},
                                      "rounds": results, "median": summary}, indent=1))


if __name__ == "__main__":
    main()
