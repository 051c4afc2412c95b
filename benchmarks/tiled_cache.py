"""Figures of the tiled cache (issue 15 point 2, docs/SCALE.md): build, open, a district map.

Every figure runs in a child process (``--python``, as ``benchmarks/scale.py`` does) and
reports wall time and peak RSS:

* ``build`` — ``cityshade build CITY -o TILED --tile-m SIDE`` (skipped with ``--skip-build``);
  with ``--split N`` (CITY a CityJSONSeq file) the city is first written as N files of
  consecutive features (each with the header line) in ``WORKDIR/split_N/`` and the folder is
  built: the streaming build of many files, whose peak RSS the issue bounds by
  1.5 × the cache + 300 MB (``goal_peak_MB``).
* ``open`` — ``open_scene(TILED)`` in a fresh process (index only), median of ``--repeat``.
* ``district`` — a map of a ``--district-m`` square at the city's south-west corner at
  ``--pixel-size``, raytrace, one sun (azimuth 200°, elevation 30°): from the tiled cache
  (tiles in view, tiles mapped, peak RSS of the process) and, with ``--one CACHE`` (the same
  city built as one file), from that cache; the lit masks' digests must be equal.

Usage::

    python benchmarks/tiled_cache.py --city /work/bench_data/city_1000000_s7.gml \\
        --workdir /work/bench_data/s4_tiledcache --tile-m 250 \\
        [--one /work/bench_data/city_1000000_s7.cityshade] [--skip-build]
    python benchmarks/tiled_cache.py --city /work/bench_data/s5_tiles/city10m.city.jsonl \
        --split 16 --workdir /work/bench_data/s5_tiles --tile-m 500

MB are 10^6 bytes. Prints one JSON object (with the git commit).
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

from scale import MB, git_commit, run_measured

#: One district map in a fresh process: open, view, render; the process's own peak RSS.
_DISTRICT_CHILD = r"""
import hashlib, json, resource, sys, time
import numpy as np
from cityshade.raster import camera as cams
from cityshade.frame.render import render_frame
from cityshade.store.scenefile import open_scene, scene_for_camera
from cityshade.geo.sun import sun_from_angles
path, side, px = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
t0 = time.perf_counter()
scene = open_scene(path)
t_open = time.perf_counter() - t0
lo = np.asarray(scene.vertices, np.float64).min(axis=0) if not hasattr(scene, "index") \
    else np.asarray(scene.index["box_m"][0])
cam = cams.map_view(scene, px, bbox=(lo[0], lo[1], lo[0] + side, lo[1] + side))
sun = sun_from_angles(200.0, 30.0, scene.crs, scene.origin_m)
t1 = time.perf_counter()
view = scene_for_camera(scene, cam, "raytrace")
t_view = time.perf_counter() - t1
t2 = time.perf_counter()
frame = render_frame(view, cam, 19895.5, sun, "raytrace")
t_render = time.perf_counter() - t2
tiled = getattr(view, "tiled", None)
print(json.dumps({
    "open_s": t_open, "view_s": t_view, "render_s": t_render,
    "pixels": int(cam.width_px * cam.height_px), "timings_s": frame.timings_s,
    "lit_blake2b": hashlib.blake2b(frame.lit.tobytes(), digest_size=16).hexdigest(),
    "shadow_px": int((frame.lit == 0).sum()),
    "tiles_in_view": len(view.tile_ids) if tiled else None,
    "tiles_mapped": len(tiled.tiles_mapped) if tiled else None,
    "tiles": len(tiled.tiles) if tiled else None,
    "triangles_in_view": int(view.n_triangles),
    "peak_rss_bytes": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024}))
"""

_OPEN_CHILD = r"""
import json, sys, time
t0 = time.perf_counter()
from cityshade.store.scenefile import open_scene
t1 = time.perf_counter()
open_scene(sys.argv[1])
print(json.dumps({"open_s": time.perf_counter() - t1}))
"""


def _child(python: str, script: str, *args) -> dict:
    proc = subprocess.run([python, "-c", script, *map(str, args)], capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"child failed: {proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def split_cityjsonseq(city: Path, folder: Path, n_files: int) -> Path:
    """``city`` (CityJSONSeq) as ``n_files`` files of consecutive features in ``folder``, each
    starting with the header line; the images beside ``city`` are copied along."""
    import shutil

    folder.mkdir(parents=True, exist_ok=True)
    with open(city, "rb") as fh:
        header = fh.readline()
        features = sum(1 for _ in fh)
    with open(city, "rb") as fh:
        fh.readline()
        for i in range(n_files):
            stop = round((i + 1) * features / n_files) - round(i * features / n_files)
            with open(folder / f"part_{i:03d}.city.jsonl", "wb") as out:
                out.write(header)
                for _ in range(stop):
                    out.write(fh.readline())
    for image in city.parent.glob("*.png"):
        shutil.copy(image, folder)
    return folder


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--city", type=Path, required=True)
    ap.add_argument("--workdir", type=Path, required=True)
    ap.add_argument("--tile-m", type=float, default=500.0)
    ap.add_argument("--one", type=Path, help="the same city built as one cache file")
    ap.add_argument("--district-m", type=float, default=500.0)
    ap.add_argument("--pixel-size", type=float, default=1.0)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--skip-build", action="store_true")
    ap.add_argument("--split", type=int, metavar="N",
                    help="build from CITY (CityJSONSeq) written as N files")
    ap.add_argument("--python", default=sys.executable)
    args = ap.parse_args(argv)
    args.workdir.mkdir(parents=True, exist_ok=True)
    name = args.city.name.split(".")[0] + (f"_split{args.split}" if args.split else "")
    tiled = args.workdir / (name + f"_tiled{args.tile_m:g}.cityshade")
    out: dict = {"commit": git_commit(args.python), "city": str(args.city),
                 "tiled": str(tiled), "tile_m": args.tile_m}
    source = args.city
    if args.split:
        source = split_cityjsonseq(args.city, args.workdir / f"split_{args.split}", args.split)
        out["files"] = args.split
    if not args.skip_build:
        r = run_measured([args.python, "-m", "cityshade", "build", str(source), "-o",
                          str(tiled), "--tile-m", str(args.tile_m)])
        if r["returncode"] != 0:
            raise SystemExit(f"build failed: {r['stderr']}")
        out["build"] = {"seconds": r["seconds"], "peak_rss_MB": r["peak_rss_bytes"] / MB,
                        "summary": r["stdout"].strip()}
    index = json.loads((tiled / "index.json").read_text())
    out["tiles"] = len(index["tiles"])
    out["size_MB"] = sum(t["size"] for t in index["tiles"]) / MB
    out["goal_peak_MB"] = 1.5 * out["size_MB"] + 300.0
    out["largest_tile_triangles"] = max(t["triangles"] for t in index["tiles"])
    opens = [_child(args.python, _OPEN_CHILD, tiled)["open_s"] for _ in range(args.repeat)]
    out["open_s_median"] = statistics.median(opens)
    out["district_tiled"] = _child(args.python, _DISTRICT_CHILD, tiled, args.district_m,
                                   args.pixel_size)
    if args.one is not None:
        out["district_one"] = _child(args.python, _DISTRICT_CHILD, args.one, args.district_m,
                                     args.pixel_size)
        out["district_equal"] = (out["district_one"]["lit_blake2b"]
                                 == out["district_tiled"]["lit_blake2b"])
    print(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
