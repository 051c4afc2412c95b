"""``cityshade batch FILE``: sun-hour maps (and per-surface sun-hours) over many sun positions."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand

from cityshade.cli.options import (camera_options, city_date_option, ground_option,
                                   make_camera, parse_size, parse_triple, presentation_options,
                                   shadow_options, time_plan_options)


@click.command("batch", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@time_plan_options
@city_date_option("the first --date day; the city does not change during a run")
@camera_options("map")
@shadow_options("exact")
@ground_option
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (no refraction).")
@click.option("--frames", is_flag=True, help="Also write every step's shadow mask (frames/).")
@click.option("--surfaces", is_flag=True, help="Also write surfaces.csv: mean sun-hours of "
              "every polygon (roofs, walls...), from sample points on the surfaces.")
@click.option("--samples-per-m2", type=float, help="Density of the surface sample points (at "
              "least one per triangle; default 1, or [batch] samples_per_m2).")
@click.option("--tile-px", type=int, help="Split the map pixels (and the surface samples) "
              "into tiles of N × N pixels, each a separate task; the numbers are identical. "
              "Writes sun_hours.tif as a Cloud-Optimized GeoTIFF.")
@click.option("--scheduler", help="Run the tasks (tile × block of sun positions) on Dask: "
              "local or local:N (N worker processes here) or tcp://HOST:8786 (a running "
              "cluster; workers must see FILE and the output folder under the same paths). "
              "Needs the [dask] extra.")
@click.option("--monthly", is_flag=True, help="Also write the sun-hours of each month "
              "(local time in --tz) to OUTDIR/monthly/.")
@presentation_options
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created; holds manifest.json and the state).")
@click.option("--overwrite", is_flag=True, help="Discard a run of other parameters in OUTDIR; compute a finished run of the same "
              "parameters again.")
@click.option("-v", "--verbose", is_flag=True, help="Timings, counts and the sun of each end.")
def batch(file, date_text, from_text, to_text, every_text, tz, days, to_date_text, every_day,
          city_date, camera, eye, target, fov, size, pixel_size, cameras_file, settings, ground,
          no_refraction, frames, surfaces, samples_per_m2, tile_px, scheduler, monthly,
          no_decorate, no_gis, outdir, overwrite, verbose):
    """Sun-hours of FILE (a .cityshade scene) from --date, each day from --from to --to every
    --every (local time in --tz): sun_hours.exr/.png (+ .tif for the map view), report.html,
    optional frames, and with --surfaces surfaces.csv and results.gpkg in OUTDIR. Running the
    same command again continues an interrupted run where it stopped, and does nothing for a
    finished one."""
    import dataclasses
    import time

    from cityshade.cli.options import (check_every_day, check_scheduler_scene,
                                       solar_zone_of_scene, warn_lmt)
    from cityshade.errors import UsageError
    from cityshade.geo.temporal import parse_user_date
    from cityshade.shadows import get_technique
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.store.scenefile import open_scene, scene_for_camera
    from cityshade.sunhours.plan import parse_clock_s, parse_duration_s, plan_steps, step_months
    from cityshade.sunhours.request import SunHoursRequest, check_execution
    from cityshade.sunhours.run import run_batch
    from cityshade.util import check_outputs

    t_start = time.perf_counter()
    technique = settings.shadows.technique
    get_technique(technique)  # unknown names fail before any work
    settings = _sample_settings(settings, surfaces, samples_per_m2)
    check_every_day(days, to_date_text)
    if no_refraction:
        settings = dataclasses.replace(settings, sun=dataclasses.replace(settings.sun,
                                                                        refraction=False))
    if (eye is None) != (target is None):
        raise UsageError("give both --eye and --target, or neither")
    parse_triple(eye, "--eye"), parse_triple(target, "--target")  # fail early
    parse_size(size, batch=True)
    first_day = parse_day(date_text, "--date")
    to_date = parse_day(to_date_text, "--to-date") if to_date_text else None
    every_s = parse_duration_s(every_text)
    check_execution(technique, tile_px, scheduler, monthly, frames)
    check_outputs(("-o", outdir, None))  # once the options are valid, before any work
    scene = open_scene(file)  # once: also the solar time zone's longitude
    zone = solar_zone_of_scene(tz, scene)
    steps = plan_steps(first_day, parse_clock_s(from_text), parse_clock_s(to_text), every_s,
                       zone, days=days, to_date=to_date, every_day=every_day)
    warn_lmt([step.start_utc for step in steps[:1]], tz)
    city = parse_user_date(city_date or first_day.isoformat())
    cam = make_camera(scene, camera, eye, target, fov, size, pixel_size, cameras_file)
    check_scheduler_scene(scheduler, settings, file)
    scene = with_vegetation(scene_for_camera(scene, None if surfaces else cam, technique),
                            settings.vegetation)
    provenance = {
        "file": Path(file).name,
        "source_sha256": (scene.header or {}).get("source", {}).get("sha256", ""),
        "date": first_day.isoformat(), "from": from_text, "to": to_text, "every_s": every_s,
        "tz": tz, "days": days, "to_date": to_date.isoformat() if to_date else None,
        "every_day": every_day, "vegetation": dataclasses.asdict(settings.vegetation),
    }
    request = SunHoursRequest.from_settings(
        steps, city.city_days, settings, surfaces=surfaces, camera=cam, technique=technique,
        ground=ground, frames=frames, provenance=provenance, tile_px=tile_px,
        decorate=not no_decorate, gis=not no_gis,
        scheduler=scheduler, scene_path=file,
        step_month=tuple(step_months(steps, zone)) if monthly else None)
    with Progress("tasks (tile × sun positions)" if request.tiled else "sun positions") as bar:
        run = run_batch(outdir, scene, request, overwrite=overwrite, on_plan=bar.plan,
                        on_step=bar.step, on_note=note)
    if run.already_complete:
        click.echo(f"{outdir}: already complete (same request); nothing to do "
                   f"(--overwrite computes it again)")
        return
    for warning in run.result.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    if verbose:
        echo_verbose(run, time.perf_counter() - t_start)
    click.echo(" ".join(str(p) for p in run.written))


def _sample_settings(settings, surfaces: bool, samples_per_m2):
    """The settings with --samples-per-m2 applied and checked; refused without --surfaces."""
    import dataclasses

    from cityshade.errors import UsageError
    from cityshade.sunhours.surfaces import SampleSettings

    if samples_per_m2 is not None:
        settings = dataclasses.replace(settings, batch=dataclasses.replace(
            settings.batch, samples_per_m2=samples_per_m2))
    if surfaces:
        SampleSettings(samples_per_m2=settings.batch.samples_per_m2)
    elif samples_per_m2 is not None:
        raise UsageError("--samples-per-m2 sets the sample points of --surfaces: give "
                         "--surfaces too")
    return settings


def note(text: str) -> None:
    """A line of the library about the run (resumed, a stale lock taken over) on stderr."""
    click.echo(f"cityshade: {text}", err=True)


class Progress:
    """A progress bar on a terminal, plain lines otherwise (:class:`ProgressLines`)."""

    def __init__(self, label: str):
        self.label = label
        self.bar = self.lines = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.__exit__(None, None, None)

    def plan(self, todo: int) -> None:
        import sys

        if todo > 0 and sys.stderr.isatty():
            self.bar = click.progressbar(length=todo, label=self.label, show_eta=True,
                                         file=sys.stderr)
            self.bar.__enter__()
        elif todo > 0:
            from cityshade.cli.options import ProgressLines

            self.lines = ProgressLines(self.label)

    def step(self, done: int, total: int, unit) -> None:
        if self.bar is not None:
            self.bar.update(1)
        elif self.lines is not None:
            self.lines(done, total)


def echo_verbose(run, command_s: float) -> None:
    """``-v``: timings, counts, tiles and the sun of the first and last step with the sun up."""
    result = run.result
    timings = {**result.timings_s, "write_s": run.write_s, "command_s": command_s}
    click.echo("timings  " + "  ".join(f"{k[:-2]} {v * 1000:.1f} ms"
                                       for k, v in timings.items()), err=True)
    click.echo(f"steps    {result.steps} ({result.steps_below_horizon} with the sun down, "
               f"{result.steps_duplicate} sharing a sun position), {result.units} sun "
               f"positions computed, {result.units_resumed} taken from the saved state",
               err=True)
    if result.diagnostics.get("engine"):
        click.echo(f"engine   {result.diagnostics['engine']}", err=True)
    tiles = result.diagnostics.get("tiles")
    if tiles:
        click.echo(f"tiles    {tiles['tiles']} of {tiles['tile_px'] or 'all'} px, "
                   f"{tiles['tasks']} tasks of {tiles['sun_positions_per_task']} sun "
                   f"positions, {tiles['receivers']:,} receivers, shadow reach "
                   f"{tiles['halo_m']:.0f} m"
                   + (f", {tiles['workers']} Dask workers ({tiles['scheduler']}), "
                      f"{tiles.get('tasks_on_driver', 0)} tasks run here while they started"
                      if tiles.get("scheduler") else ""), err=True)
    up = [s for s in run.suns if s.above_horizon] or run.suns
    for label, s in (("first", up[0]), ("last", up[-1])):
        click.echo(f"{label:<8} {s.instant_utc} UTC: azimuth {s.azimuth_true_deg:.3f}° "
                   f"true / {s.azimuth_grid_deg:.3f}° grid, elevation "
                   f"{s.elevation_deg:.3f}°, ΔT {s.delta_t_s:.2f} s", err=True)


def parse_day(text: str, option: str):
    """A calendar day from ``text`` (YYYY-MM-DD), or a one-line error naming ``option``."""
    import datetime as dt

    from cityshade.errors import UsageError
    from cityshade.geo.temporal import check_year_range

    check_year_range(text, option)
    try:
        return dt.date.fromisoformat(text.strip())
    except ValueError:
        raise UsageError(f"{option} must be a day YYYY-MM-DD, not {text!r}") from None
