"""Sky benchmark: the sky view factor of a city's map and a year of hourly irradiance (issue 37).

Input: ``--scene`` (a .cityshade file; default the sample city, built in memory),
its map view at ``--pixel-size`` (default 1 m) with batch's ground plane, the city as it stood
on 2000-01-01. Work, through :func:`cityshade.light.run.compute_sky` as ``cityshade sky`` runs
it (no files written):

* ``svf``: the visibility of every sky patch of ``--sky`` (default Tregenza's 145) from every
  map pixel with a surface, by ``izb``, and the sky view factor and the sky shares;
* ``year``: the same plus the irradiance of every pixel over ``--hours`` weather hours
  (default all 8,760 of ``--weather``; default pvlib's TMY3 file), the sun traced every hour.

One warm-up run at 20 × the pixel size and 24 hours compiles the kernels first (tracing by
``izb``, so that its kernels are compiled too and the measured runs' ``exact`` can take it). Reported: wall
seconds of the camera pass, the sky and the hours, CPU seconds (a loaded machine's wall
time overstates), receivers, Mpx·directions/s and
Mpx·hours/s, peak RSS. Goals of the issue (the 1M-triangle city at 1 m, 2.14 M px, 2 threads):
SVF with 145 patches ≤ 20 s; a year of hourly irradiance ≤ 10 min.

``--day-step N`` sums every N-th day of the hours only and extrapolates the hours' time to all
of them in proportion to the lit hours (a year in a few minutes; the figure says so).

Usage: python benchmarks/sky.py [--scene F.cityshade] [--pixel-size 1] [--sky tregenza]
       [--weather FILE] [--hours 8760] [--day-step 1] [--skip-year] [--json out.json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

DAY_2000 = 10957.0  # 2000-01-01 in days since 1970-01-01


def _scene(args):
    from cityshade.build import build_scene_from_file
    from cityshade.store.scenefile import load_scene

    if args.scene is not None:
        return load_scene(args.scene)
    return build_scene_from_file(REPO / "sample_data" / "sample_city.gml")


def _hours_mask(weather, hours: int, day_step: int):
    """The first ``hours`` hours of the file, and of them only every ``day_step``-th day's."""
    import numpy as np

    mask = np.zeros(weather.n_hours, bool)
    mask[:hours] = True
    if day_step > 1:
        mask &= (np.arange(weather.n_hours) // 24) % day_step == 0
    return mask


def _sun_hours(weather, mask) -> int:
    """Hours of ``mask`` with light (the hours the irradiance sums)."""
    return int((mask & ((weather.ghi_w_m2 > 0) | (weather.dni_w_m2 > 0)
                        | (weather.dhi_w_m2 > 0))).sum())


def _run(scene, pixel_size, sky, weather, hours, day_step=1, technique="exact"):
    from cityshade.light.run import SkyRequest, compute_sky
    from cityshade.raster.camera import map_view

    mask = None
    if weather is not None:
        mask = _hours_mask(weather, hours, day_step)
    request = SkyRequest(camera=map_view(scene, pixel_size), ground="auto", t_days=DAY_2000,
                         sky=sky, weather=weather, hours=mask, technique=technique)
    t0, c0 = time.perf_counter(), time.process_time()
    result = compute_sky(scene, request)
    result.timings_s["cpu_s"] = time.process_time() - c0  # both threads: shared-machine proof
    return result, time.perf_counter() - t0


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", type=Path)
    ap.add_argument("--pixel-size", type=float, default=1.0)
    ap.add_argument("--sky", default="tregenza")
    ap.add_argument("--weather", type=Path)
    ap.add_argument("--hours", type=int, default=8760)
    ap.add_argument("--day-step", type=int, default=1,
                    help="sum every N-th day only and extrapolate to --hours by the lit hours")
    ap.add_argument("--skip-year", action="store_true")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    import numba
    import pvlib

    from cityshade.light.weather import read_weather

    weather_path = args.weather or Path(os.path.dirname(pvlib.__file__)) / "data" / "723170TYA.CSV"
    weather = read_weather(weather_path)
    scene = _scene(args)
    # Compile the kernels, izb's too: on a cache without them `exact` keeps raytrace for a
    # run that would not win their compile back (the warm-up's), and then for every run of
    # this process (the 1M city's SVF: 35 s against 21 s).
    _run(scene, 20 * args.pixel_size, args.sky, weather, 24, technique="izb")
    figures = {}
    svf, svf_s = _run(scene, args.pixel_size, args.sky, None, 0)
    figures["svf"] = {"wall_s": svf_s, "receivers": len(svf.svf), "map_px": int(
        svf.shape[0] * svf.shape[1]), "directions": svf.sky.n, **svf.timings_s,
        "mpx_directions_per_s": len(svf.svf) * svf.sky.n / svf.timings_s["sky_s"] / 1e6}
    if not args.skip_year:
        year, year_s = _run(scene, args.pixel_size, args.sky, weather, args.hours,
                            args.day_step)
        irr = year.irradiation
        # The hours' seconds ("irradiance_s" before the sky's tiles, "hours_s" since).
        hours_s = year.timings_s.get("hours_s", year.timings_s.get("irradiance_s", 0.0))
        year.timings_s["irradiance_s"] = hours_s
        # A sample of days stands for all of --hours in proportion to the lit hours summed.
        scale = _sun_hours(weather, _hours_mask(weather, args.hours, 1)) / max(irr.hours, 1)
        figures["year"] = {"wall_s": year_s, "receivers": len(year.svf), "hours": irr.hours,
                           "day_step": args.day_step,
                           "irradiance_extrapolated_s": year.timings_s["irradiance_s"] * scale,
                           "sun_hours_traced": irr.sun_hours_traced, **year.timings_s,
                           "mpx_hours_per_s": len(year.svf) * irr.hours
                           / year.timings_s["irradiance_s"] / 1e6,
                           "mean_kwh_m2": float(irr.total_kwh_m2.mean())}
    out = {"benchmark": "sky", "provenance": {"commit": commit(REPO), "machine":
                                              platform.node(), "cpus": os.cpu_count(),
                                              "numba_threads": numba.get_num_threads()},
           "scene": str(args.scene or "sample_city"), "pixel_size_m": args.pixel_size,
           "sky": args.sky, "weather": Path(weather_path).name, "figures": figures,
           "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
           "load_average": os.getloadavg()}
    print(json.dumps(out, indent=1))
    print(f"{'run':<6} {'receivers':>10} {'work':>14} {'camera s':>9} {'sky s':>8} "
          f"{'hours s':>9} {'wall s':>8} {'cpu s':>8}")
    for name, f in figures.items():
        work = f"{f['directions']} dirs" if name == "svf" else f"{f['hours']} h"
        if name == "year" and f["day_step"] > 1:
            print(f"year: every {f['day_step']}th day, {f['hours']} lit hours in "
                  f"{f['irradiance_s']:.1f} s; all of --hours extrapolated: "
                  f"{f['irradiance_extrapolated_s']:.0f} s")
        print(f"{name:<6} {f['receivers']:>10,} {work:>14} {f.get('camera_s', 0):>9.2f} "
              f"{f.get('sky_s', 0):>8.2f} {f.get('irradiance_s', 0):>9.2f} {f['wall_s']:>8.2f} "
              f"{f['cpu_s']:>8.2f}")
    if args.json:
        args.json.write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main()
