"""Peak memory per pixel of a frame (render: map and perspective views, each technique family)
and of a batch (per receiver pixel): the figures behind ``pipeline.FRAME_BYTES_PER_PX``.

Each measurement runs in a fresh child process on a ``.cityshade`` scene (default: the sample
city, built into a temporary folder): load the scene, run the same command once on a small
frame (kernels loaded, caches warm), then reset the process's peak resident set
(``/proc/self/clear_refs``), run the frame at full size and read the peak (``VmHWM``) minus the
resident set before it. Two sizes per case give the bytes per pixel as the slope (fixed costs
such as a shadow map's texels cancel) and the fixed part as the intercept. render = render_frame
+ write_frame (EXR + PNG); batch = sun_hours over ``--steps`` sun positions + its outputs;
sky = ``cityshade sky``'s run and outputs (``sky:tregenza``: the sky view factor and VSC of the
map with that sky; ``irradiance:tregenza``: with the irradiance of the first ``--steps`` days of
pvlib's TMY3 file).

Usage: python benchmarks/memory.py [--scene city.cityshade] [--pixels 1000000,4000000]
       [--cases map:raytrace,persp:izb,sky:tregenza,irradiance:tregenza,...] [--steps 4]
       [--json out.json]
Linux only (``/proc``).
"""
from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DAY_2000 = 10957.0
TECHNIQUES = ("raytrace", "izb", "shadowmap", "hybrid:vsm")
DEFAULT_CASES = ",".join([*(f"map:{t}" for t in TECHNIQUES), *(f"persp:{t}" for t in TECHNIQUES),
                          "batch:izb", "batch:raytrace"])


def _status_kb(field: str) -> int:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith(field + ":"):
            return int(line.split()[1])
    raise RuntimeError(f"no {field} in /proc/self/status")


def _camera(scene, view: str, pixels: int):
    from cityshade.raster import camera as C

    if view in ("map", "batch", "sky", "irradiance"):
        box = C.scene_box(scene, DAY_2000)
        area_m2 = float((box[1, 0] - box[0, 0]) * (box[1, 1] - box[0, 1]))
        return C.map_view(scene, pixel_size_m=math.sqrt(area_m2 / pixels))
    width = int(round(math.sqrt(pixels * 16 / 9)))
    return C.overview(scene, width, int(round(width * 9 / 16)), t_days=DAY_2000)


def _run(scene, view: str, technique: str, pixels: int, steps: int, out: Path) -> int:
    """Run one case; returns the camera's pixel count."""
    import datetime as dt

    from cityshade.geo.sun import sun_from_angles

    cam = _camera(scene, view, pixels)
    if view == "batch":
        from cityshade.sunhours.accumulate import sun_hours
        from cityshade.sunhours.outputs import colour_map_png
        from cityshade.imageio import write_exr, write_png_rgb

        t0 = dt.datetime(2024, 6, 21, 6, tzinfo=dt.timezone.utc)
        instants = [t0 + dt.timedelta(hours=2 * k) for k in range(steps)]
        result = sun_hours(scene, cam, instants, DAY_2000, technique=technique)
        write_exr(out / "h.exr", {"sun_hours": result.hours}, {})
        write_png_rgb(out / "h.png", colour_map_png(result.hours))
    elif view in ("sky", "irradiance"):
        import os

        import numpy as np
        import pvlib

        from cityshade.light.run import SkyRequest, run_sky
        from cityshade.light.weather import read_weather

        weather, hours = None, None
        if view == "irradiance":                       # the first `steps` days of pvlib's TMY
            weather = read_weather(Path(os.path.dirname(pvlib.__file__)) / "data"
                                   / "723170TYA.CSV")
            hours = np.zeros(weather.n_hours, bool)
            hours[:24 * steps] = True
        request = SkyRequest(camera=cam, ground="auto", t_days=DAY_2000, sky=technique,
                             weather=weather, hours=hours, vsc=True)
        for f in out.iterdir():                        # run_sky writes into an empty folder
            f.unlink()
        run_sky(out, scene, request)
    else:
        from cityshade.frame.render import render_frame, write_frame

        sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
        frame = render_frame(scene, cam, DAY_2000, sun, technique)
        write_frame(frame, scene, "2000-01-01", exr=out / "f.exr", png=out / "f.png")
    return int(cam.width_px) * int(cam.height_px)


def child(scene_path: str, case: str, pixels: int, steps: int) -> None:
    from cityshade.store.scenefile import load_scene

    view, technique = case.split(":", 1)
    scene = load_scene(scene_path)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        _run(scene, view, technique, 20_000, steps, out)        # warm: kernels, caches
        rss_kb = _status_kb("VmRSS")
        Path("/proc/self/clear_refs").write_text("5")         # peak := now
        px = _run(scene, view, technique, pixels, steps, out)
        peak_kb = _status_kb("VmHWM")
    print(json.dumps({"case": case, "pixels": px, "rss_before_kb": rss_kb,
                      "peak_kb": peak_kb, "frame_bytes": (peak_kb - rss_kb) * 1024}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", help=".cityshade file (default: the sample city, built)")
    ap.add_argument("--pixels", default="1000000,4000000")
    ap.add_argument("--cases", default=DEFAULT_CASES)
    ap.add_argument("--steps", type=int, default=4, help="sun positions of a batch")
    ap.add_argument("--json")
    ap.add_argument("--child", nargs=4, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(args.child[0], args.child[1], int(args.child[2]), int(args.child[3]))
        return
    with tempfile.TemporaryDirectory() as tmp:
        scene = args.scene
        if scene is None:
            scene = str(Path(tmp) / "sample.cityshade")
            subprocess.run([sys.executable, "-m", "cityshade", "build",
                            str(REPO / "sample_data" / "sample_city.gml"), "-o", scene, "-q"],
                           check=True)
        sizes = [int(v) for v in args.pixels.split(",")]
        rows = []
        for case in args.cases.split(","):
            points = []
            for n in sizes:
                done = subprocess.run([sys.executable, __file__, "--child", scene, case, str(n),
                                       str(args.steps)], capture_output=True, text=True)
                if done.returncode != 0:
                    sys.exit(f"{case} at {n} px failed:\n{done.stderr}")
                points.append(json.loads(done.stdout.strip().splitlines()[-1]))
            (a, b) = points[0], points[-1]
            slope = (b["frame_bytes"] - a["frame_bytes"]) / max(b["pixels"] - a["pixels"], 1)
            rows.append({"case": case, "points": points, "bytes_per_px": slope,
                         "fixed_mb": (a["frame_bytes"] - slope * a["pixels"]) / 1e6,
                         "peak_bytes_per_px_at_max": b["frame_bytes"] / b["pixels"]})
            print(f"{case:<18} {slope:7.1f} B/px (slope)  {rows[-1]['fixed_mb']:8.1f} MB fixed"
                  f"  {rows[-1]['peak_bytes_per_px_at_max']:7.1f} B/px at {b['pixels']} px",
                  flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
