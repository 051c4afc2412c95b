"""``cityshade batch FILE``: sun-hour maps (and per-surface sun-hours) over many sun positions."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.options import (camera_options, ground_option, make_camera, parse_size,
                                   parse_triple, shadow_options)


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
              "(UTC for UTC); local-mean or local-apparent: mean or true solar time at the "
              "model's longitude (for historical dates).")
@click.option("--days", type=int, help="Number of days (default 1), --every-day apart.")
@click.option("--to-date", "to_date_text", help="Last day (inclusive), YYYY-MM-DD.")
@click.option("--every-day", type=int, default=1, show_default=True, help="Days between days.")
@click.option("--city-date", help="State of the city (default: --date); the city does not "
              "change during a run.")
@camera_options("map")
@shadow_options("izb")
@ground_option
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (no refraction).")
@click.option("--frames", is_flag=True, help="Also write every step's shadow mask (frames/).")
@click.option("--surfaces", is_flag=True, help="Also write surfaces.csv: mean sun-hours of "
              "every polygon (roofs, walls...), from sample points on the surfaces.")
@click.option("--samples-per-m2", type=float, help="Density of the surface sample points (at "
              "least one per triangle; default 1, or [batch] samples_per_m2).")
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created; holds manifest.json and the state).")
@click.option("--overwrite", is_flag=True, help="Discard a run of other parameters in OUTDIR.")
@click.option("-v", "--verbose", is_flag=True, help="Timings, counts and the sun of each end.")
def batch(file, date_text, from_text, to_text, every_text, tz, days, to_date_text, every_day,
          city_date, camera, eye, target, fov, size, pixel_size, cameras_file, settings, ground,
          no_refraction, frames, surfaces, samples_per_m2, outdir, overwrite, verbose):
    """Sun-hours of FILE (a .cityshade scene) from --date, each day from --from to --to every
    --every (local time in --tz): sun_hours.exr/.png (+ .tif for the map view), optional
    frames and surfaces.csv in OUTDIR. Re-running the same command after an interruption
    continues where it stopped."""
    import dataclasses
    import sys
    import time

    from cityshade import batch as B
    from cityshade.citygml.temporal import parse_user_date
    from cityshade.errors import UsageError
    from cityshade.scenefile import load_scene
    from cityshade.shadows import get_technique
    from cityshade.surfaces import SampleSettings
    from cityshade.util import check_outputs

    t_start = time.perf_counter()
    check_outputs(("-o", outdir, None))  # before any work
    technique = settings.shadows.technique
    get_technique(technique)  # unknown names fail before any work
    if samples_per_m2 is not None:
        settings = dataclasses.replace(settings, batch=dataclasses.replace(
            settings.batch, samples_per_m2=samples_per_m2))
    if surfaces:
        SampleSettings(samples_per_m2=settings.batch.samples_per_m2)
    if no_refraction:
        settings = dataclasses.replace(settings, sun=dataclasses.replace(settings.sun,
                                                                        refraction=False))
    if (eye is None) != (target is None):
        raise UsageError("give both --eye and --target, or neither")
    parse_triple(eye, "--eye"), parse_triple(target, "--target"), parse_size(size)  # fail early
    first_day = _day(date_text, "--date")
    to_date = _day(to_date_text, "--to-date") if to_date_text else None
    every_s = B.parse_duration_s(every_text)
    from cityshade.cli.options import solar_zone_of_file

    steps = B.plan_steps(first_day, B.parse_clock_s(from_text), B.parse_clock_s(to_text),
                         every_s, solar_zone_of_file(tz, file), days=days, to_date=to_date,
                         every_day=every_day)
    from cityshade.cli.options import warn_lmt

    warn_lmt([step.start_utc for step in steps[:1]], tz)
    city = parse_user_date(city_date or first_day.isoformat())
    scene = load_scene(file)
    cam = make_camera(scene, camera, eye, target, fov, size, pixel_size, cameras_file)
    request = {
        "file": Path(file).name,
        "source_sha256": (scene.header or {}).get("source", {}).get("sha256", ""),
        "date": first_day.isoformat(), "from": from_text, "to": to_text, "every_s": every_s,
        "tz": tz, "days": days, "to_date": to_date.isoformat() if to_date else None,
        "every_day": every_day,
    }
    bar = None
    lines = None

    def on_plan(todo):
        nonlocal bar, lines
        if todo > 0 and sys.stderr.isatty():
            bar = click.progressbar(length=todo, label="sun positions", show_eta=True,
                                    file=sys.stderr)
            bar.__enter__()
        elif todo > 0:
            from cityshade.cli.options import ProgressLines

            lines = ProgressLines("sun positions")

    def on_step(done, total, unit):
        if bar is not None:
            bar.update(1)
        elif lines is not None:
            lines(done, total)

    try:
        run = B.run_batch(outdir, scene, cam, steps, city.city_days, request=request,
                          technique=technique, settings=settings, ground=ground, frames=frames,
                          surfaces_csv=surfaces, overwrite=overwrite, on_plan=on_plan,
                          on_step=on_step)
    finally:
        if bar is not None:
            bar.__exit__(None, None, None)
    result = run.result
    for warning in result.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    if verbose:
        timings = {**result.timings_s, "write_s": run.write_s,
                   "command_s": time.perf_counter() - t_start}
        click.echo("timings  " + "  ".join(f"{k[:-2]} {v * 1000:.1f} ms"
                                           for k, v in timings.items()), err=True)
        click.echo(f"steps    {result.steps} ({result.steps_below_horizon} with the sun down, "
                   f"{result.steps_duplicate} sharing a sun position), {result.units} sun "
                   f"positions computed, {result.units_resumed} taken from the saved state",
                   err=True)
        up = [s for s in run.suns if s.above_horizon] or run.suns
        for label, s in (("first", up[0]), ("last", up[-1])):
            click.echo(f"{label:<8} {s.instant_utc} UTC: azimuth {s.azimuth_true_deg:.3f}° "
                       f"true / {s.azimuth_grid_deg:.3f}° grid, elevation "
                       f"{s.elevation_deg:.3f}°, ΔT {s.delta_t_s:.2f} s", err=True)
    click.echo(" ".join(str(p) for p in run.written))


def _day(text: str, option: str):
    import datetime as dt

    from cityshade.errors import UsageError

    try:
        return dt.date.fromisoformat(text.strip())
    except ValueError:
        raise UsageError(f"{option} must be a day YYYY-MM-DD, not {text!r}") from None
