"""Reader throughput: ``read_citygml`` + ``build_scene`` against plain lxml parsing.

Measures, alternating in the same process and the same run, the median over ``--repeat`` runs
of:

* anchor — ``lxml.etree.iterparse`` over every ``cityObjectMember``, clearing it and deleting
  its previous siblings, nothing else (the floor of any streaming lxml reader; the same as
  anchor A of ``build_throughput.py``);
* read — :func:`cityshade.citygml.reader.read_citygml` of the file;
* scene — :func:`cityshade.geometry.scene.build_scene` of that model (no kd-tree).

One warm-up read + build runs first (Numba kernels load from their cache) and is excluded.
Peak memory of one read + build is measured first, in a fresh child process (its ``VmHWM``),
so that the timing runs do not inflate it. With ``--profile`` a cProfile of one read is
printed instead (top functions by own time).

MB are 10^6 bytes. Prints one JSON object (with the git commit) and a plain-text table.

Usage (from the repository root)::

    python benchmarks/reader_profile.py                      # bench_out/city_1000000_s7.gml, 5 runs
    python benchmarks/reader_profile.py --city FILE --repeat 3
    python benchmarks/reader_profile.py --profile
"""
from __future__ import annotations

import argparse
import cProfile
import gc
import json
import pstats
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

from lxml import etree

REPO = Path(__file__).resolve().parents[1]
MB = 1e6

#: Member elements of CityGML 1.0/2.0/3.0 city models (the anchor clears each one when it ends).
_MEMBER_TAGS = [f"{{http://www.opengis.net/citygml/{v}}}cityObjectMember"
                for v in ("1.0", "2.0", "3.0")]

#: Child program for the memory figure: one read + build in a fresh process, then its peak RSS.
#: VmHWM of /proc/self/status belongs to the new process image; ru_maxrss (KiB on Linux) is kept
#: across fork + exec and would report the parent's peak, so it is only the fallback.
_MEMORY_CHILD = r"""
import json, resource, sys
from cityshade.citygml.reader import read_citygml
from cityshade.geometry.scene import build_scene

def peak_bytes():
    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024

raw = read_citygml(sys.argv[1])
read_peak = peak_bytes()
scene = build_scene(raw)
print(json.dumps({"read_peak_rss_bytes": read_peak, "peak_rss_bytes": peak_bytes(),
                  "triangles": int(len(scene.triangles))}))
"""


def anchor(path: Path) -> float:
    """Seconds for iterparse + clear of every member, nothing else."""
    t0 = time.perf_counter()
    for _, elem in etree.iterparse(str(path), events=("end",), tag=_MEMBER_TAGS,
                                   huge_tree=True, resolve_entities=False, no_network=True):
        elem.clear()
        while elem.getprevious() is not None:
            del elem.getparent()[0]
    return time.perf_counter() - t0


def read_and_build(path: Path) -> tuple[float, float, int]:
    """(read seconds, build_scene seconds, triangles) of one run."""
    from cityshade.citygml.reader import read_citygml
    from cityshade.geometry.scene import build_scene

    gc.collect()
    t0 = time.perf_counter()
    raw = read_citygml(path)
    t1 = time.perf_counter()
    scene = build_scene(raw)
    t2 = time.perf_counter()
    return t1 - t0, t2 - t1, int(len(scene.triangles))


def _summary(seconds: list[float], size: int) -> dict:
    median = statistics.median(seconds)
    return {"median_s": round(median, 3), "mb_per_s": round(size / MB / median, 1),
            "runs_s": [round(s, 3) for s in seconds]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--city", type=Path, default=REPO / "bench_out" / "city_1000000_s7.gml",
                        help="CityGML file (default: the generated 1M-triangle city; make it "
                             "with python -m cityshade.samplegen bench_out/city_1000000_s7.gml "
                             "--triangles 1000000 --seed 7)")
    parser.add_argument("--repeat", type=int, default=5, help="timed runs of each (5)")
    parser.add_argument("--profile", action="store_true",
                        help="print a cProfile of one read instead of timing")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    if not args.city.is_file():
        parser.error(f"no such file: {args.city}")
    path = args.city.resolve()
    size = path.stat().st_size

    if args.profile:
        from cityshade.citygml.reader import read_citygml

        read_citygml(path)  # warm-up: Numba kernels load from the cache
        profiler = cProfile.Profile()
        profiler.runcall(read_citygml, path)
        pstats.Stats(profiler).sort_stats("tottime").print_stats(25)
        return 0

    # Memory first, in a child started while this process is still small.
    child = subprocess.run([sys.executable, "-c", _MEMORY_CHILD, str(path)], cwd=REPO,
                           capture_output=True, text=True)
    memory = (json.loads(child.stdout.strip().splitlines()[-1]) if child.returncode == 0
              else {"error": (child.stderr.strip().splitlines() or ["failed"])[-1]})
    read_and_build(path)  # warm-up, excluded
    times_anchor, times_read, times_scene, times_total = [], [], [], []
    triangles = 0
    for _ in range(args.repeat):
        times_anchor.append(anchor(path))
        read_s, scene_s, triangles = read_and_build(path)
        times_read.append(read_s)
        times_scene.append(scene_s)
        times_total.append(read_s + scene_s)

    result = {
        "benchmark": "reader_profile",
        "commit": commit(full=True),
        "city": {"path": str(path), "size_bytes": size, "triangles": triangles},
        "repeat": args.repeat,
        "anchor_iterparse": _summary(times_anchor, size),
        "read": _summary(times_read, size),
        "scene": _summary(times_scene, size),
        "read_plus_scene": _summary(times_total, size),
        "memory": {k: (round(v / MB, 1) if k.endswith("_bytes") else v)
                   for k, v in memory.items()},
    }
    result["ratio_read_plus_scene_over_anchor"] = round(
        result["read_plus_scene"]["mb_per_s"] / result["anchor_iterparse"]["mb_per_s"], 3)
    print(json.dumps(result, indent=1))

    print()
    print(f"reader throughput on {path.name} ({size / MB:.1f} MB, commit "
          f"{result['commit'][:10]}, median of {args.repeat})")
    print(f"{'':28s}{'MB/s':>9s}{'median s':>10s}")
    for label, key in (("anchor: iterparse + clear", "anchor_iterparse"), ("read_citygml", "read"),
                       ("build_scene", "scene"), ("read + scene", "read_plus_scene")):
        print(f"{label:28s}{result[key]['mb_per_s']:9.1f}{result[key]['median_s']:10.2f}")
    print(f"read + scene / anchor: {result['ratio_read_plus_scene_over_anchor']:.2f}")
    if "peak_rss_bytes" in memory:
        print(f"peak RSS after read {memory['read_peak_rss_bytes'] / MB:.0f} MB, after "
              f"build_scene {memory['peak_rss_bytes'] / MB:.0f} MB")
    else:
        print(f"memory: {memory.get('error')}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
