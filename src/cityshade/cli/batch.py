"""``cityshade batch FILE``: sun-hour maps (and per-surface sun-hours) over many sun positions."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.options import camera_options, make_camera, parse_size, parse_triple


@click.command("batch")
@click.argument("file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--date", "date_text", required=True, help="First day, YYYY-MM-DD.")
@click.option("--from", "from_text", default="00:00", show_default=True,
              help="Local start time of each day, HH:MM.")
@click.option("--to", "to_text", default="24:00", show_default=True,
              help="Local end time of each day, HH:MM (24:00 = midnight at the end).")
@click.option("--every", "every_text", default="10min", show_default=True,
              help="Step length: 10min, 1h, 30s, 1h30min.")
@click.option("--tz", required=True, help="IANA time zone of --from/--to, e.g. Europe/Berlin "
              "(UTC for UTC).")
@click.option("--days", type=int, help="Number of days (default 1), --every-day apart.")
@click.option("--to-date", "to_date_text", help="Last day (inclusive), YYYY-MM-DD.")
@click.option("--every-day", type=int, default=1, show_default=True, help="Days between days.")
@click.option("--city-date", help="State of the city (default: --date); the city does not "
              "change during a run.")
@camera_options("map")
@click.option("--shadows", "technique", default="izb", show_default=True,
              help="Shadow technique for the map and the surfaces: izb (exact, light-space "
              "engine) or raytrace (exact, kd-tree rays; the same answer); or any technique of "
              "render for the map.")
@click.option("--ground", help="Ground plane where the model has no surface: min, auto or a "
              "height in metres.")
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (no refraction).")
@click.option("--frames", is_flag=True, help="Also write every step's shadow mask (frames/).")
@click.option("--surfaces", is_flag=True, help="Also write surfaces.csv: mean sun-hours of "
              "every polygon (roofs, walls...), from sample points on the surfaces.")
@click.option("--samples-per-m2", type=float, default=1.0, show_default=True,
              help="Density of the surface sample points (at least one per triangle).")
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created; holds manifest.json and the state).")
@click.option("--overwrite", is_flag=True, help="Discard a run of other parameters in OUTDIR.")
@click.option("-v", "--verbose", is_flag=True, help="Timings, counts and the sun of each end.")
def batch(file, date_text, from_text, to_text, every_text, tz, days, to_date_text, every_day,
          city_date, camera, eye, target, fov, size, pixel_size, technique, ground,
          no_refraction, frames, surfaces, samples_per_m2, outdir, overwrite, verbose):
    """Sun-hours of FILE (a .cityshade scene) from --date, each day from --from to --to every
    --every (local time in --tz): sun_hours.exr/.png (+ .tif for the map view), optional
    frames and surfaces.csv in OUTDIR. Re-running the same command after an interruption
    continues where it stopped."""
    import sys
    import time

    import numpy as np

    from cityshade import batch as B
    from cityshade.citygml.temporal import parse_user_date
    from cityshade.errors import OutputError, UsageError
    from cityshade.scenefile import load_scene
    from cityshade.shadows import get_technique
    from cityshade.sun import SpaSettings
    from cityshade.surfaces import SampleSettings

    t_start = time.perf_counter()
    get_technique(technique)  # unknown names fail before any work
    if surfaces:
        SampleSettings(samples_per_m2=samples_per_m2)
    if (eye is None) != (target is None):
        raise UsageError("give both --eye and --target, or neither")
    parse_triple(eye, "--eye"), parse_triple(target, "--target"), parse_size(size)  # fail early
    first_day = _day(date_text, "--date")
    to_date = _day(to_date_text, "--to-date") if to_date_text else None
    every_s = B.parse_duration_s(every_text)
    steps = B.plan_steps(first_day, B.parse_clock_s(from_text), B.parse_clock_s(to_text),
                         every_s, tz, days=days, to_date=to_date, every_day=every_day)
    city = parse_user_date(city_date or first_day.isoformat())
    scene = load_scene(file)
    cam = make_camera(scene, camera, eye, target, fov, size, pixel_size)

    params = {
        "file": Path(file).name,
        "source_sha256": (scene.header or {}).get("source", {}).get("sha256", ""),
        "date": first_day.isoformat(), "from": from_text, "to": to_text, "every_s": every_s,
        "tz": tz, "days": days, "to_date": to_date.isoformat() if to_date else None,
        "every_day": every_day, "city_days": city.city_days,
        "camera": {"kind": cam.kind, "width_px": cam.width_px, "height_px": cam.height_px,
                   "eye_m": [float(v) for v in cam.eye_m],
                   "target_m": [float(v) for v in cam.target_m],
                   "vfov_deg": float(cam.vfov_deg), "pixel_size_m": cam.pixel_size_m},
        "technique": technique, "ground": ground, "refraction": not no_refraction,
        "frames": frames, "samples_per_m2": samples_per_m2 if surfaces else None,
    }
    key = B.params_key(params)
    try:
        outdir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder: {exc.strerror}",
                          path=str(outdir)) from None
    old = B.read_manifest(outdir)
    state = B.Checkpoint(outdir / B.STATE_NAME, key)
    if old is not None and old.get("key") != key:
        if not overwrite:
            changed = sorted(k for k in set(params) | set(old.get("params", {}))
                             if params.get(k) != old.get("params", {}).get(k))
            raise UsageError(f"{outdir} holds a run with other parameters (differs in: "
                             f"{', '.join(changed) or 'version'}); use --overwrite or another "
                             f"-o folder")
        state.remove()
    elif old is None and state.path.exists():
        if not overwrite:
            raise UsageError(f"{state.path} has no manifest next to it; use --overwrite")
        state.remove()

    manifest = {
        "cityshade_version": __import__("cityshade").__version__, "key": key,
        "params": params, "status": "running",
        "steps": [{"index": s.index, "start_utc": _iso(s.start_utc), "end_utc": _iso(s.end_utc),
                   "weight_h": s.weight_h} for s in steps],
        "finished_steps": [],
    }
    B.write_manifest(outdir, manifest)
    frames_dir = outdir / "frames"
    if frames:
        frames_dir.mkdir(exist_ok=True)

    finished: list[int] = []
    bar = None

    def on_step(done, total, unit):
        finished.extend(unit.steps)
        manifest["finished_steps"] = sorted(finished)
        manifest["sun_positions_done"] = done
        B.write_manifest(outdir, manifest)
        if bar is not None:
            bar.update(1)

    def on_frame(unit, lit, valid):
        from cityshade.imageio import mask_from_lit, write_mask_png

        mask = mask_from_lit(lit, valid)
        for i in unit.steps:
            write_mask_png(frames_dir / _frame_name(steps[i]), mask)

    instants = [s.centre_utc for s in steps]
    weights = [s.weight_h for s in steps]
    from cityshade.sun import suns_from_instants

    suns = suns_from_instants(instants, scene.crs, scene.origin_m,
                              SpaSettings(refraction=not no_refraction))
    units, below, _ = B.plan_units(suns, weights)
    finished.extend(below)  # nothing to compute for a sun below the horizon
    done_before = state.units_done()
    for unit in units[:done_before]:
        finished.extend(unit.steps)
    if sys.stderr.isatty() and len(units) - done_before > 0:
        bar = click.progressbar(length=len(units) - done_before, label="sun positions",
                                show_eta=True, file=sys.stderr)
        bar.__enter__()
    try:
        result = B.sun_hours(scene, cam, instants, city.city_days, weights_h=weights,
                             technique=technique, ground=ground, suns=suns,
                             samples_per_m2=samples_per_m2 if surfaces else None,
                             checkpoint=state, on_step=on_step,
                             on_frame=on_frame if frames else None)
    finally:
        if bar is not None:
            bar.__exit__(None, None, None)
    for warning in result.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    if frames and below:
        from cityshade.imageio import mask_from_lit, write_mask_png

        # The sun is down: every surface pixel is in shadow, the rest stays nodata.
        nothing_lit = mask_from_lit(np.zeros(result.valid.shape), result.valid)
        for i in below:
            write_mask_png(frames_dir / _frame_name(steps[i]), nothing_lit)
    meta = B.run_metadata(result, scene, params)
    t1 = time.perf_counter()
    written = B.write_sun_hours(outdir, result, scene, cam, meta, surfaces_csv=surfaces)
    write_s = time.perf_counter() - t1
    manifest["status"] = "finished"
    manifest["finished_steps"] = sorted(finished)
    manifest["summary"] = {
        "steps": result.steps, "steps_below_horizon": result.steps_below_horizon,
        "steps_same_sun": result.steps_duplicate, "sun_positions": result.units,
        "sun_positions_resumed": result.units_resumed, "hours_total": result.hours_total,
        "hours_sun_up": result.hours_sun_up,
        "outputs": [p.name for p in written],
        "timings_s": {**result.timings_s, "write_s": write_s},
    }
    B.write_manifest(outdir, manifest)
    if verbose:
        timings = {**result.timings_s, "write_s": write_s,
                   "command_s": time.perf_counter() - t_start}
        click.echo("timings  " + "  ".join(f"{k[:-2]} {v * 1000:.1f} ms"
                                           for k, v in timings.items()), err=True)
        click.echo(f"steps    {result.steps} ({result.steps_below_horizon} with the sun down, "
                   f"{result.steps_duplicate} sharing a sun position), {result.units} sun "
                   f"positions computed, {result.units_resumed} taken from the saved state",
                   err=True)
        up = [s for s in suns if s.above_horizon] or suns
        for label, s in (("first", up[0]), ("last", up[-1])):
            click.echo(f"{label:<8} {s.instant_utc} UTC: azimuth {s.azimuth_true_deg:.3f}° "
                       f"true / {s.azimuth_grid_deg:.3f}° grid, elevation "
                       f"{s.elevation_deg:.3f}°, ΔT {s.delta_t_s:.2f} s", err=True)
    click.echo(" ".join(str(p) for p in written))


def _day(text: str, option: str):
    import datetime as dt

    from cityshade.errors import UsageError

    try:
        return dt.date.fromisoformat(text.strip())
    except ValueError:
        raise UsageError(f"{option} must be a day YYYY-MM-DD, not {text!r}") from None


def _iso(instant) -> str:
    return instant.isoformat().replace("+00:00", "Z")


def _frame_name(step) -> str:
    return f"step_{step.index:05d}_{step.centre_utc.strftime('%Y%m%dT%H%M%SZ')}.png"
