"""Build throughput: ``cityshade build`` against plain lxml parsing of the same CityGML file.

Generates (once, cached in ``--workdir``) the ~1-million-triangle synthetic city with
:mod:`cityshade.samplegen`, then measures, alternating in the same run, the median over
``--repeat`` runs of:

* anchor A — ``lxml.etree.iterparse`` over every ``cityObjectMember``, clearing it and deleting
  its previous siblings, nothing else (the floor of any streaming lxml reader);
* anchor B — the same, plus converting every ``gml:posList`` text to float64 with numpy;
* ours — ``python -m cityshade build FILE -o OUT`` in a subprocess: MB/s of GML, the child's
  peak RSS (``getrusage(RUSAGE_CHILDREN)`` in a small wrapper process, one per run) and the
  output size. Goal: peak RSS ≤ 1.5 × output size + 300 MB. The first run (which may compile
  Numba kernels into the cache) is excluded from the median and reported on its own.

MB are 10^6 bytes. Prints one JSON object (machine-readable, with the git commit), then a
plain-text table with the ratios ours / anchor A and ours / anchor B. If ``cityshade build``
fails or does not exist yet, the anchors are still measured and "ours" says why it is missing.

Usage (from the repository root)::

    python benchmarks/build_throughput.py                       # 1M triangles, 3 repeats
    python benchmarks/build_throughput.py --triangles 50000 --repeat 1   # quick smoke run
    python benchmarks/build_throughput.py --city path/to/file.gml       # any CityGML file
    python benchmarks/build_throughput.py --format cityjson --workdir /tmp/cj   # CityJSON

``--format cityjson`` writes the same city also as CityJSON 2.0 and CityJSONSeq (sample
generator) and measures, alternating: ``cityshade build`` of all three (MB/s, million
triangles/s, peak RSS, the memory goal) and ``json``, ``msgspec`` and (if installed) ``orjson``
reading the CityJSON file whole into Python objects (seconds inside the child, peak RSS).
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from dataclasses import asdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

import numpy as np
from lxml import etree

REPO = Path(__file__).resolve().parents[1]
MB = 1e6

#: Member elements of CityGML 1.0/2.0/3.0 city models (anchors clear each one when it ends).
_MEMBER_TAGS = [f"{{http://www.opengis.net/citygml/{v}}}cityObjectMember"
                for v in ("1.0", "2.0", "3.0")]
_POSLIST_TAGS = ("{http://www.opengis.net/gml}posList", "{http://www.opengis.net/gml/3.2}posList")

#: Runs the build in a child and reports that child's peak RSS: getrusage(RUSAGE_CHILDREN) of a
#: fresh wrapper process sees only this one build. ru_maxrss is in KiB on Linux.
_WRAPPER = r"""
import json, resource, subprocess, sys, time
t0 = time.perf_counter()
proc = subprocess.run(sys.argv[1:], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
seconds = time.perf_counter() - t0
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"returncode": proc.returncode, "seconds": seconds,
                  "peak_rss_bytes": usage.ru_maxrss * 1024,
                  "stderr_tail": proc.stderr.strip().splitlines()[-1:] or [""],
                  "stdout_tail": proc.stdout.strip().splitlines()[-1:] or [""]}))
"""


def _generator_digest() -> str:
    source = (REPO / "src" / "cityshade" / "samplegen.py").read_bytes()
    return hashlib.sha256(source).hexdigest()[:16]


def ensure_city(workdir: Path, triangles: int, seed: int, output_format: str = "citygml"
                ) -> tuple[Path, dict]:
    """The cached benchmark city; regenerated when missing or made by another generator."""
    from cityshade.samplegen import generate_city

    workdir.mkdir(parents=True, exist_ok=True)
    suffix = {"citygml": ".gml", "cityjson": ".city.json", "cityjsonseq": ".city.jsonl"}
    gml = workdir / f"city_{triangles}_s{seed}{suffix[output_format]}"
    meta_path = (gml.with_suffix(".json") if output_format == "citygml"
                 else gml.with_name(gml.name + ".meta"))
    digest = _generator_digest()
    if gml.exists() and meta_path.exists():
        meta = json.loads(meta_path.read_text())
        if meta.get("generator") == digest and meta.get("size_bytes") == gml.stat().st_size:
            return gml, meta
    t0 = time.perf_counter()
    info = generate_city(gml, target_triangles=triangles, seed=seed, output_format=output_format)
    meta = {k: (str(v) if isinstance(v, Path) else v) for k, v in asdict(info).items()}
    meta.update(generator=digest, generate_seconds=round(time.perf_counter() - t0, 2))
    meta_path.write_text(json.dumps(meta, indent=1))
    return gml, meta


def anchor_a(path: Path) -> float:
    """Seconds for iterparse + clear of every member, nothing else."""
    t0 = time.perf_counter()
    for _, elem in etree.iterparse(str(path), events=("end",), tag=_MEMBER_TAGS,
                                   huge_tree=True, resolve_entities=False, no_network=True):
        elem.clear()
        while elem.getprevious() is not None:
            del elem.getparent()[0]
    return time.perf_counter() - t0


def anchor_b(path: Path) -> tuple[float, int]:
    """Seconds for anchor A plus every posList converted to float64; also the value count."""
    values = 0
    t0 = time.perf_counter()
    for _, elem in etree.iterparse(str(path), events=("end",), tag=_MEMBER_TAGS,
                                   huge_tree=True, resolve_entities=False, no_network=True):
        for pos in elem.iter(_POSLIST_TAGS):
            values += np.array(pos.text.split(), dtype=np.float64).size
        elem.clear()
        while elem.getprevious() is not None:
            del elem.getparent()[0]
    return time.perf_counter() - t0, values


#: One JSON library reading a whole file into Python objects (timed inside the child, after
#: the import); the wrapper around it reports the child's peak RSS.
_JSON_CHILD = r"""
import json, sys, time
lib, path = sys.argv[1], sys.argv[2]
if lib == "orjson":
    import orjson
    loads = orjson.loads
elif lib == "msgspec":
    import msgspec
    loads = msgspec.json.decode
else:
    loads = json.loads
t0 = time.perf_counter()
with open(path, "rb") as fh:
    obj = loads(fh.read())
print(json.dumps({"seconds": time.perf_counter() - t0}))
"""


def json_anchor(lib: str, path: Path) -> dict:
    """Seconds (inside the child) and peak RSS of reading ``path`` whole with ``lib``."""
    cmd = [sys.executable, "-c", _WRAPPER, sys.executable, "-c", _JSON_CHILD, lib, str(path)]
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    if proc.returncode != 0:
        return {"error": (proc.stderr.strip().splitlines() or ["wrapper failed"])[-1]}
    run = json.loads(proc.stdout.strip().splitlines()[-1])
    if run["returncode"] != 0:
        return {"error": run["stderr_tail"][0] or f"exit status {run['returncode']}"}
    return {"seconds": json.loads(run["stdout_tail"][0])["seconds"],
            "peak_rss_bytes": run["peak_rss_bytes"]}


def _available(module: str) -> bool:
    import importlib.util

    return importlib.util.find_spec(module) is not None


def main_cityjson(args) -> int:
    """``--format cityjson``: the same city as CityGML, CityJSON and CityJSONSeq, and plain
    JSON libraries reading the CityJSON file, alternating in one run."""
    workdir = args.workdir.resolve()
    cities = {fmt: ensure_city(workdir, args.triangles, args.seed, fmt)
              for fmt in ("citygml", "cityjson", "cityjsonseq")}
    triangles = cities["citygml"][1]["triangles"]
    cj_path = cities["cityjson"][0]
    libs = ["json", "msgspec"] + (["orjson"] if _available("orjson") else [])
    outs = {fmt: workdir / f"{path.name}.cityshade" for fmt, (path, _) in cities.items()}
    first = {fmt: ours(path, outs[fmt]) for fmt, (path, _) in cities.items()}  # warm-up
    runs: dict[str, list[dict]] = {k: [] for k in [*cities, *libs]}
    for _ in range(args.repeat):
        for lib in libs:
            runs[lib].append(json_anchor(lib, cj_path))
        for fmt, (path, _) in cities.items():
            runs[fmt].append(ours(path, outs[fmt]))
    rows = {}
    for key, items in runs.items():
        path = cities[key][0] if key in cities else cj_path
        size = path.stat().st_size
        errors = [r["error"] for r in items if "error" in r] + (
            [first[key]["error"]] if key in first and "error" in first[key] else [])
        if errors:
            rows[key] = {"file": path.name, "unavailable": errors[0]}
            continue
        median = statistics.median(r["seconds"] for r in items)
        peak = statistics.median(r["peak_rss_bytes"] for r in items)
        row = {"file": path.name, "file_mb": round(size / MB, 1), "median_s": round(median, 3),
               "runs_s": [round(r["seconds"], 3) for r in items],
               "mb_per_s": round(size / MB / median, 1),
               "mtriangles_per_s": round(triangles / 1e6 / median, 3),
               "peak_rss_mb": round(peak / MB, 1)}
        if key in cities:
            reads = [r["stage_s"].get("read_s") for r in items]
            if all(v is not None for v in reads):
                row["read_s"] = round(statistics.median(reads), 3)
            out_bytes = items[-1]["output_bytes"]
            budget = 1.5 * out_bytes + 300 * MB
            row.update(output_mb=round(out_bytes / MB, 1), memory_goal_mb=round(budget / MB, 1),
                       memory_goal_met=bool(peak <= budget),
                       first_run_s=round(first[key]["seconds"], 3))
        rows[key] = row
    result = {"benchmark": "build_throughput", "format": "cityjson", "commit": commit(full=True),
              "machine": {"python": platform.python_version(), "platform": platform.platform(),
                          "cpus": os.cpu_count(), "numpy": np.__version__},
              "city": {fmt: meta for fmt, (_, meta) in cities.items()}, "triangles": triangles,
              "repeat": args.repeat, "results": rows}
    gml_row, cj_row = rows.get("citygml", {}), rows.get("cityjson", {})
    if "mtriangles_per_s" in gml_row and "mtriangles_per_s" in cj_row:
        result["ratios"] = {
            f"{k}_over_citygml_per_triangle": round(rows[k]["mtriangles_per_s"]
                                                    / gml_row["mtriangles_per_s"], 3)
            for k in ("cityjson", "cityjsonseq") if "mtriangles_per_s" in rows[k]}
    print(json.dumps(result, indent=1))
    print()
    print(f"build of the {triangles:,}-triangle city in three formats (commit "
          f"{result['commit'][:10]}, median of {args.repeat}); JSON libraries read the "
          f"CityJSON file whole")
    print(f"{'':30s}{'file MB':>8s}{'s':>8s}{'read s':>8s}{'MB/s':>8s}{'Mtri/s':>8s}"
          f"{'peak MB':>9s}{'goal MB':>9s}")
    names = {"json": "json.loads (stdlib)", "msgspec": "msgspec.json.decode",
             "orjson": "orjson.loads", "citygml": "cityshade build .gml",
             "cityjson": "cityshade build .city.json", "cityjsonseq": "cityshade build .jsonl"}
    for key, row in rows.items():
        if "unavailable" in row:
            print(f"{names[key]:30s} unavailable: {row['unavailable']}")
            continue
        goal = (f"{row['memory_goal_mb']:9.0f}{'' if row['memory_goal_met'] else ' NOT met'}"
                if "memory_goal_mb" in row else "")
        read = f"{row['read_s']:8.2f}" if "read_s" in row else f"{'':8s}"
        print(f"{names[key]:30s}{row['file_mb']:8.1f}{row['median_s']:8.2f}{read}"
              f"{row['mb_per_s']:8.1f}{row['mtriangles_per_s']:8.3f}{row['peak_rss_mb']:9.0f}"
              f"{goal}")
    for k, v in result.get("ratios", {}).items():
        print(f"{k}: {v:.2f}")
    return 0


def ours(path: Path, out: Path) -> dict:
    """One ``cityshade build`` in a wrapper process: seconds, peak RSS, output size."""
    if out.exists():
        out.unlink()
    cmd = [sys.executable, "-c", _WRAPPER, sys.executable, "-m", "cityshade", "build",
           str(path), "-o", str(out)]
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    if proc.returncode != 0:
        return {"error": (proc.stderr.strip().splitlines() or ["wrapper failed"])[-1]}
    run = json.loads(proc.stdout.strip().splitlines()[-1])
    if run["returncode"] != 0:
        return {"error": run["stderr_tail"][0] or run["stdout_tail"][0]
                or f"exit status {run['returncode']}"}
    if not out.exists():
        return {"error": f"no output file {out}"}
    run["output_bytes"] = out.stat().st_size
    try:  # the build's own stage timings (read, triangulate, kd-tree) from the file header
        from cityshade.store.scenefile import read_header

        run["stage_s"] = read_header(out).get("report", {}).get("timings", {})
    except Exception:  # an older file layout: the stage timings are only missing
        run["stage_s"] = {}
    return run


def _summary(seconds: list[float], size: int) -> dict:
    median = statistics.median(seconds)
    return {"median_s": round(median, 3), "mb_per_s": round(size / MB / median, 1),
            "runs_s": [round(s, 3) for s in seconds]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--workdir", type=Path, default=REPO / "bench_out",
                        help="cache folder for the generated city and outputs (bench_out/)")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs of each (3)")
    parser.add_argument("--triangles", type=int, default=1_000_000,
                        help="size of the generated city (1000000)")
    parser.add_argument("--seed", type=int, default=7, help="generator seed (7)")
    parser.add_argument("--city", type=Path, default=None,
                        help="measure this CityGML file instead of the generated city")
    parser.add_argument("--format", choices=("citygml", "cityjson"), default="citygml",
                        help="cityjson: the same city as CityGML, CityJSON and CityJSONSeq, "
                             "next to json/msgspec/orjson reading the CityJSON file")
    args = parser.parse_args(argv)
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    if args.format == "cityjson":
        if args.city is not None:
            parser.error("--city measures one CityGML file; --format cityjson generates its own")
        return main_cityjson(args)

    if args.city is not None:
        gml, city = args.city.resolve(), {"path": str(args.city)}
    else:
        gml, city = ensure_city(args.workdir.resolve(), args.triangles, args.seed)
    size = gml.stat().st_size
    city["size_bytes"] = size
    out = args.workdir.resolve() / (gml.stem + ".cityshade")
    out.parent.mkdir(parents=True, exist_ok=True)

    # Warm-up build: compiles (or loads) the Numba kernels; reported, not in the median.
    first = ours(gml, out)
    available = "error" not in first
    times_a, times_b, runs = [], [], []
    values = 0
    for _ in range(args.repeat):
        times_a.append(anchor_a(gml))
        seconds, values = anchor_b(gml)
        times_b.append(seconds)
        if available:
            run = ours(gml, out)
            if "error" in run:
                available, first = False, run
            else:
                runs.append(run)

    result = {
        "benchmark": "build_throughput",
        "commit": commit(full=True),
        "machine": {"python": platform.python_version(), "platform": platform.platform(),
                    "cpus": os.cpu_count(), "lxml": ".".join(map(str, etree.LXML_VERSION)),
                    "numpy": np.__version__},
        "city": city,
        "repeat": args.repeat,
        "anchor_a_iterparse": _summary(times_a, size),
        "anchor_b_iterparse_poslist": {**_summary(times_b, size), "float_values": values},
    }
    if available and runs:
        peak = statistics.median(r["peak_rss_bytes"] for r in runs)
        out_bytes = runs[-1]["output_bytes"]
        budget = 1.5 * out_bytes + 300 * MB
        result["ours"] = {
            **_summary([r["seconds"] for r in runs], size),
            "first_run_s": round(first["seconds"], 3),
            "first_run_peak_rss_mb": round(first["peak_rss_bytes"] / MB, 1),
            "peak_rss_mb": round(peak / MB, 1),
            "output_mb": round(out_bytes / MB, 1),
            "memory_goal_mb": round(budget / MB, 1),
            "memory_goal_met": bool(peak <= budget),
        }
        result["ratios"] = {
            "ours_over_anchor_a": round(result["ours"]["mb_per_s"]
                                        / result["anchor_a_iterparse"]["mb_per_s"], 3),
            "ours_over_anchor_b": round(result["ours"]["mb_per_s"]
                                        / result["anchor_b_iterparse_poslist"]["mb_per_s"], 3),
        }
    else:
        result["ours"] = {"unavailable": first.get("error", "no run")}
    print(json.dumps(result, indent=1))

    a, b, o = result["anchor_a_iterparse"], result["anchor_b_iterparse_poslist"], result["ours"]
    print()
    print(f"build throughput on {gml.name} ({size / MB:.1f} MB, commit {result['commit'][:10]},"
          f" median of {args.repeat})")
    print(f"{'':34s}{'MB/s':>9s}{'median s':>10s}{'ours/this':>11s}")
    if "mb_per_s" in o:
        print(f"{'anchor A: iterparse + clear':34s}{a['mb_per_s']:9.1f}{a['median_s']:10.2f}"
              f"{result['ratios']['ours_over_anchor_a']:11.2f}")
        print(f"{'anchor B: + posList -> float64':34s}{b['mb_per_s']:9.1f}{b['median_s']:10.2f}"
              f"{result['ratios']['ours_over_anchor_b']:11.2f}")
        print(f"{'ours: cityshade build':34s}{o['mb_per_s']:9.1f}{o['median_s']:10.2f}")
        print(f"ours: first run {o['first_run_s']:.2f} s (excluded); peak RSS "
              f"{o['peak_rss_mb']:.0f} MB, output {o['output_mb']:.0f} MB, goal <= "
              f"{o['memory_goal_mb']:.0f} MB: {'met' if o['memory_goal_met'] else 'NOT met'}")
    else:
        print(f"{'anchor A: iterparse + clear':34s}{a['mb_per_s']:9.1f}{a['median_s']:10.2f}")
        print(f"{'anchor B: + posList -> float64':34s}{b['mb_per_s']:9.1f}{b['median_s']:10.2f}")
        print(f"ours: unavailable ({o['unavailable']})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
