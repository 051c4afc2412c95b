"""``cityshade sky FILE``: sky view factor and, from a weather file, irradiation (kWh/m²) of
every map pixel and every surface."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand
from cityshade.cli.options import (camera_options, city_date_option, ground_option,
                                   make_camera, parse_size, parse_triple, presentation_options,
                                   shadow_options)


@click.command("sky", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@city_date_option("today")
@camera_options("map")
@shadow_options("exact", technique_help="Exact technique tracing the sky and the suns: exact "
                "(default: izb or raytrace, whichever is faster for the run), izb or raytrace "
                "(the same answer).", map_px=False, tunables=False)
@ground_option
@click.option("--sky", "sky_name", default="reinhart2305", show_default=True,
              help="Sky directions: tregenza (145 patches), reinhart577, reinhart2305, or "
              "uniform<degrees>.")
@click.option("--svf/--no-svf", default=True, show_default=True,
              help="Write the sky view factor (svf.exr/.tif/.png; a surfaces.csv column).")
@click.option("--vsc", is_flag=True, help="Also the vertical sky component, CIE overcast sky, "
              "of every pixel and surface on its own plane (vsc.exr/.tif/.png, percent; a "
              "surfaces.csv column): BRE 209's VSC on walls, 100 % on open ground.")
@click.option("--season", type=click.Choice(["leaf-on", "leaf-off"]),
              help="Deciduous tree crowns of the sky view factor: in leaf or leafless "
              "(default: [vegetation] season, or leaf-on when it is auto); the irradiance "
              "takes each weather hour's own leaf state.")
@click.option("--weather", type=click.Path(path_type=Path),
              help="Hourly weather file: EnergyPlus .epw, TMY3 .csv or TMY2 .tm2.")
@click.option("--irradiance", is_flag=True, help="Write the irradiation of every receiver "
              "over the weather hours (irradiance_kwh_m2.exr/.tif/.png; surfaces.csv and "
              "buildings.csv columns); needs --weather.")
@click.option("--date", "instant_date", help="Day of --times, YYYY-MM-DD (its month and day "
              "pick the weather file's records; the year is the sun's).")
@click.option("--times", "times_text", help="Instants of --date, HH:MM separated by commas: "
              "irradiance_w_m2_<HHMM>.exr/.tif/.png and surfaces.csv columns in W/m², each "
              "from the weather record of the hour containing it (hour-ending) with the sun "
              "at the instant; needs --weather.")
@click.option("--tz", help="Time zone of --times: an IANA name or local-mean/local-apparent "
              "(default: the weather file's own standard time, its UTC offset).")
@click.option("--sky-model", type=click.Choice(["perez", "isotropic", "haydavies"]),
              default="perez", show_default=True, help="pvlib's diffuse sky model.")
@click.option("--albedo", type=click.FloatRange(0.0, 1.0), default=0.2, show_default=True,
              help="Ground albedo of the ground-reflected part.")
@click.option("--from-date", "from_date", help="First day of the weather summed, MM-DD or "
              "YYYY-MM-DD (the year is ignored: typical years mix years); default the file's "
              "first hour.")
@click.option("--to-date", "to_date", help="Last day summed (included), MM-DD or YYYY-MM-DD; "
              "before --from-date it wraps over the new year.")
@click.option("--surfaces", is_flag=True, help="Also per surface: surfaces.csv (one row per "
              "polygon, roofs and walls apart) and buildings.csv (totals per building).")
@click.option("--samples-per-m2", type=float, help="Density of the surface sample points "
              "(default 1, or [batch] samples_per_m2).")
@click.option("--no-map", is_flag=True, help="Surfaces only: no map (with --surfaces).")
@click.option("--tile-px", type=int, help="Split the map pixels (and the surface samples) "
              "into tiles of N × N pixels, each a separate task whose work alone is in "
              "memory; finished tiles are kept, so the same command after Ctrl-C resumes; the "
              "numbers are identical.")
@click.option("--scheduler", help="Run the tiles on Dask, as batch does: local or local:N (N "
              "worker processes here) or tcp://HOST:8786 (a running cluster; workers must see "
              "FILE and the output folder under the same paths). Needs the [dask] extra.")
@presentation_options
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created; holds manifest.json, and the "
              "state of an unfinished run).")
@click.option("--overwrite", is_flag=True, help="Discard a run of other parameters in OUTDIR; "
              "compute a finished run of the same parameters again.")
@click.option("-v", "--verbose", is_flag=True, help="Timings and counts.")
def sky(file, city_date, camera, eye, target, fov, size, pixel_size, cameras_file, settings,
        ground, sky_name, svf, vsc, season, weather, irradiance, instant_date, times_text, tz,
        sky_model, albedo, from_date, to_date,
        surfaces, samples_per_m2, no_map, tile_px, scheduler, no_decorate, no_gis, outdir,
        overwrite, verbose):
    """Sky view factor of FILE (a .cityshade scene) per map pixel (svf.exr/.tif/.png) and,
    with --surfaces, per polygon and building; with --vsc the vertical sky component; with
    --weather FILE --irradiance, the kWh/m² received over the file's hours (direct, diffuse
    from pvlib's sky model and ground-reflected, each weighted by what the receiver sees of
    it), and with --date and --times the W/m² at those instants; report.html sums it up.
    Tree crowns let their transmissivity through. With --tile-px the receivers run in tiles
    (here or on Dask with --scheduler); running the same command again continues an interrupted run where it
    stopped, and does nothing for a finished one.
    """
    import dataclasses
    import datetime as dt
    import time

    from cityshade.cli.options import check_scheduler_scene
    from cityshade.errors import UsageError
    from cityshade.geo.temporal import parse_user_date
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.light.irradiance import hours_between
    from cityshade.light.run import SkyRequest
    from cityshade.light.weather import read_weather
    from cityshade.store.scenefile import open_scene, scene_for_camera
    from cityshade.sunhours.surfaces import SampleSettings
    from cityshade.util import check_outputs

    t_start = time.perf_counter()
    clocks, day = _check_outputs_asked(irradiance, weather, instant_date, times_text, tz,
                                       no_map, surfaces, svf, vsc)
    density = samples_per_m2 if samples_per_m2 is not None else settings.batch.samples_per_m2
    if surfaces:
        SampleSettings(samples_per_m2=density)
    if (eye is None) != (target is None):
        raise UsageError("give both --eye and --target, or neither")
    parse_triple(eye, "--eye"), parse_triple(target, "--target"), parse_size(size)
    city = parse_user_date(city_date or dt.date.today().isoformat())
    if season is None:   # auto has no date for a view factor: in leaf, the most shade
        season = "leaf-off" if settings.vegetation.season == "leaf_off" else "leaf-on"
    request = SkyRequest(sky=sky_name, technique=settings.shadows.technique, model=sky_model,
                         albedo=albedo, svf=svf, vsc=vsc, season=season.replace("-", "_"),
                         ground=ground, t_days=city.city_days,
                         spa=settings.sun, samples_per_m2=density if surfaces else None,
                         decorate=not no_decorate, gis=not no_gis,
                         camera=None if no_map else "map", tile_px=tile_px,
                         scheduler=scheduler, scene_path=file)
    # The sky, model, technique and tiles, before the files are read (what is asked for was
    # checked above; the weather is not read yet).
    request.check(outputs=False)
    if tz is not None:
        from cityshade.geo.temporal import SOLAR_TIME_ZONES, zone_info

        if tz not in SOLAR_TIME_ZONES:
            zone_info(tz)  # an unknown name fails before the files are read
    wx = read_weather(weather) if weather is not None and (irradiance or clocks) else None
    hours = hours_between(wx, from_date, to_date) if wx is not None else None
    check_outputs(("-o", outdir, None))
    check_scheduler_scene(scheduler, settings, file)
    scene = open_scene(file)
    cam = None if no_map else make_camera(scene, camera, eye, target, fov, size, pixel_size,
                                          cameras_file)
    scene = with_vegetation(scene_for_camera(scene, None if surfaces else cam,
                                             request.technique), settings.vegetation)
    instants = _instants(day, clocks, tz, wx, scene)
    request = dataclasses.replace(request, camera=cam, weather=wx, hours=hours,
                                  period=irradiance, instants=tuple(t for t, _ in instants),
                                  instant_labels=tuple(label for _, label in instants),
                                  provenance={
        "file": Path(file).name, "city_date": city_date, "sky": sky_name, "season": season,
        "weather": Path(weather).name if wx is not None else None, "from_date": from_date,
        "to_date": to_date, "technique": request.technique, "date": instant_date,
        "times": times_text, "tz": tz})
    run = _run(outdir, scene, request, overwrite, verbose,
               Path(file).stat().st_size if Path(file).is_file() else None)
    if run.already_complete:
        click.echo(f"{outdir}: already complete (same request); nothing to do "
                   f"(--overwrite computes it again)")
        return
    for warning in run.result.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    if verbose:
        _echo_verbose(run.result, scheduler, time.perf_counter() - t_start)
    click.echo(" ".join(str(p) for p in run.written))


def _run(outdir, scene, request, overwrite: bool, verbose: bool = False,
         file_bytes: int | None = None):
    """:func:`cityshade.light.run.run_sky` with batch's progress: a bar (or lines) of tiles,
    within a run of one tile lines of sky directions and weather hours; resume notes; with
    ``verbose`` the memory estimate before the work, and the size of the scene file
    (``file_bytes``) whose pages the resident set holds beside it: the camera pass reads
    every triangle of the map (749 MB of the 10^7-triangle city's 2,127 MB file)."""
    from cityshade.cli.batch import Progress, note
    from cityshade.cli.options import ProgressLines
    from cityshade.light.run import run_sky

    def memory(need: int) -> None:
        if verbose:
            mapped = "" if file_bytes is None else f" of {file_bytes / 1e6:,.0f} MB"
            click.echo(f"memory   about {need / 1e6:,.0f} MB estimated (camera pass, receivers "
                       f"kept, one tile traced), besides the pages it maps of the scene "
                       f"file{mapped}", err=True)

    lines = {"sky": ProgressLines("sky directions"), "hours": ProgressLines("weather hours")}
    with Progress("tiles") as bar:
        return run_sky(outdir, scene, request, overwrite=overwrite,
                       progress=lambda phase, d, t: lines[phase](d, t),
                       on_plan=lambda todo, total: bar.plan(todo if total > 1 else 0),
                       on_tile=lambda done, total: bar.step(done, total, None), on_note=note,
                       on_memory=memory)


def _echo_verbose(result, scheduler, command_s: float) -> None:
    """``-v``: timings, counts, tiles."""
    timings = {**result.timings_s, "command_s": command_s}
    click.echo("timings  " + "  ".join(f"{k[:-2]} {v:.2f} s" for k, v in timings.items()),
               err=True)
    click.echo(f"receivers {len(result.svf):,} ({result.n_pixels:,} map pixels), "
               f"{result.sky.n} sky directions, about {result.bytes_per_receiver} bytes "
               f"per receiver", err=True)
    tiles = result.tiles
    if tiles["tile_px"] is not None or scheduler is not None:
        click.echo(f"tiles    {tiles['tiles']} of {tiles['tile_px'] or 'all'} px, "
                   f"{tiles['tiles_resumed']} taken from the saved state"
                   + (f", {tiles['workers']} Dask workers ({scheduler}), "
                      f"{tiles['tasks_on_driver']} tiles run here while they started"
                      if scheduler is not None else ""), err=True)


def _check_outputs_asked(irradiance, weather, instant_date, times_text, tz, no_map, surfaces,
                         svf, vsc):
    """The options that go together checked before any file is read; (clock times of
    --times, the --date day or None)."""
    from cityshade.cli.batch import parse_day
    from cityshade.errors import UsageError

    if irradiance and weather is None:
        raise UsageError("--irradiance needs --weather FILE (an .epw, TMY3 .csv or TMY2 .tm2)")
    if (instant_date is None) != (times_text is None):
        raise UsageError("give --date and --times together (the instants of the irradiance "
                         "in W/m²)")
    if times_text is not None and weather is None:
        raise UsageError("--times needs --weather FILE (an .epw, TMY3 .csv or TMY2 .tm2)")
    if tz is not None and times_text is None:
        raise UsageError("--tz is the time zone of --times; give --date and --times")
    clocks = _clocks(times_text) if times_text is not None else ()
    day = parse_day(instant_date, "--date") if instant_date is not None else None
    if no_map and not surfaces:
        raise UsageError("--no-map leaves nothing to compute without --surfaces")
    if not svf and not vsc and not irradiance and not clocks:
        raise UsageError("nothing to write: --no-svf without --vsc, --irradiance or --times")
    if weather is not None and not irradiance and not clocks:
        click.echo("cityshade: warning: --weather without --irradiance or --times: the "
                   "weather file is not read", err=True)
    return clocks, day

def _clocks(text: str) -> tuple[int, ...]:
    """``09:00,12:00`` → seconds after midnight, sorted, no repeats (before 24:00)."""
    from cityshade.errors import UsageError
    from cityshade.sunhours.plan import parse_clock_s

    clocks = tuple(sorted({parse_clock_s(part) for part in text.split(",")}))
    if any(c >= 86_400 for c in clocks):
        raise UsageError("a time of --times must be before 24:00")
    return clocks


def _instants(day, clocks, tz, weather, scene) -> list:
    """(aware datetime, ``HHMM`` label) of every time of ``day``: in ``tz`` (an IANA name, or
    solar time at the model's longitude), else in the weather file's standard time."""
    import datetime as dt

    from cityshade.cli.options import solar_zone_of_scene
    from cityshade.geo.temporal import zone_info

    if not clocks:
        return []
    if tz is None:
        zone = dt.timezone(dt.timedelta(hours=weather.location.utc_offset_h))
    else:
        zone = zone_info(solar_zone_of_scene(tz, scene))
    out = []
    for c in clocks:
        h, m, sec = c // 3600, c // 60 % 60, c % 60
        label = f"{h:02d}{m:02d}" + (f"{sec:02d}" if sec else "")
        out.append((dt.datetime(day.year, day.month, day.day, h, m, sec, tzinfo=zone), label))
    return out
