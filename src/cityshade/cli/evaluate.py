"""``cityshade evaluate FILE``: shadow error against run time, and the stress set."""
from __future__ import annotations

import sys
from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand

from cityshade.cli.options import (city_date_option, crs_option, ground_option,
                                   map_extent_options, shadow_options)


class _Bar:
    """A one-line progress bar on a terminal's stderr; plain progress lines otherwise."""

    WIDTH = 30

    def __init__(self, enabled: bool | None = None):
        from cityshade.cli.options import ProgressLines

        self.enabled = sys.stderr.isatty() if enabled is None else enabled
        self.shown = False
        self.lines = ProgressLines("evaluate")

    def __call__(self, done: int, total: int, label: str) -> None:
        if not self.enabled:
            self.lines(done, total, label[:60])
            return
        fill = int(self.WIDTH * done / max(total, 1))
        sys.stderr.write(f"\r\033[K[{'#' * fill}{'.' * (self.WIDTH - fill)}] {done}/{total}  "
                         f"{label[:60]}")
        sys.stderr.flush()
        self.shown = True

    def close(self) -> None:
        if self.shown:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


def _int_list(text: str, what: str) -> tuple[int, ...]:
    try:
        values = tuple(int(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise click.BadParameter(f"{what} must be comma-separated integers, not {text!r}")
    if not values:
        raise click.BadParameter(f"{what} needs at least one value")
    return values


@click.command("evaluate", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@click.option("--views", default="overview,map", show_default=True,
              help="Comma list: overview, map, or camera presets (render --help lists them).")
@click.option("--sun", "sun_text", help="Sun positions 'AZ,EL;AZ,EL' in degrees (azimuth "
              "clockwise from true north). Default: '135,45;240,15'.")
@click.option("--date", "date_text", help="Day of the --times suns, YYYY-MM-DD (default: "
              "today). Without --times (the suns given by --sun) the short form of "
              "--city-date: --date 1850.")
@city_date_option("the --times day, else today")
@click.option("--times", help="Local times HH:MM,HH:MM of --date: suns computed by SPA.")
@click.option("--tz", help="IANA time zone of --times, e.g. Europe/Berlin; local-mean or "
              "local-apparent: solar time at the model's longitude.")
@shadow_options("all", map_px=False,
                technique_help="'all' (default) or a comma list of techniques (raytrace is "
                               "always the reference); names as for render --shadows.")
@click.option("--sizes", help="Shadow-map sizes in texels (per cascade for csm; default "
              "1024,2048,4096 or [evaluate] sizes).")
@click.option("--size", default="1280x720", show_default=True,
              help="WIDTHxHEIGHT of perspective views.")
@click.option("--pixel-size", type=click.FloatRange(min=1e-3), help="Metres per pixel of the "
              "map view (default: fits 2048 px).")
@click.option("--cameras", "cameras_file", type=click.Path(dir_okay=False),
              help="TOML file of more camera presets for --views.")
@ground_option
@click.option("--repeat", type=click.IntRange(1, 100), help="Timed runs after the warm-up run "
              "(median reported; default 3 or [evaluate] repeat).")
@click.option("--stress", is_flag=True, help="Run the fixed stress set and check its invariants "
              "(FILE gives the model; PASS/FAIL per case; exit status 1 on any FAIL).")
@click.option("--quick", is_flag=True, help="With --stress: small sizes, no 8192² maps.")
@click.option("-o", "--output", type=click.Path(file_okay=False, path_type=Path),
              help="Report folder (results.csv, report.md, plots, diff images); required "
                   "without --stress.")
@crs_option
@map_extent_options
def evaluate(file, views, sun_text, date_text, city_date, times, tz, settings, sizes, size,
             pixel_size, cameras_file, ground, repeat, stress, quick, output, crs):
    """Error of every shadow technique against the exact ray-traced shadows of FILE (a
    .cityshade scene, a tiled cache folder or a CityGML file), and its run time, per view,
    sun and map size."""
    import dataclasses

    from cityshade.cli.options import parse_size
    from cityshade.errors import UsageError

    if quick and not stress:
        raise UsageError("--quick only applies to --stress")
    from cityshade.util import check_outputs

    check_outputs(("-o", output, None))  # before any work
    bar = _Bar()
    if stress:
        _run_stress(file, settings, ground, quick, output, bar)
        return
    if output is None:
        raise UsageError("give the report folder with -o/--output")
    import datetime as dt

    from cityshade.geo.temporal import days_to_iso, parse_user_date
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.evaluate import (expand_techniques, load_or_build_scene, parse_suns,
                                    run_evaluation, suns_of_day, view_camera, write_report)

    if sun_text and times:
        raise UsageError("give either --sun or --date/--times, not both")
    techniques = expand_techniques(settings.shadows.technique)
    changes = {k: v for k, v in (("repeat", repeat),
                                 ("sizes", _int_list(sizes, "--sizes") if sizes else None))
               if v is not None}
    eval_settings = dataclasses.replace(settings.evaluate, **changes)
    width, height = parse_size(size)
    day = date_text or dt.date.today().isoformat()
    from cityshade.cli.options import (city_of_short_date, settings_for_source,
                                       solar_placeholder, solar_zone_of_scene)

    if times:
        city_text = city_date or day.split("T")[0]
    else:  # no sun to date: --date is the city's state (short for --city-date)
        if date_text and parse_user_date(date_text, solar_placeholder(tz)).instant_utc:
            raise UsageError(f"--date {date_text} has a time of day, but the suns come from "
                             f"--sun (angles): give --times HH:MM,... for suns of that day, or "
                             f"a day alone for the city's state")
        city_text = city_of_short_date(date_text, city_date, tz, "--times") or day
    city_days = parse_user_date(city_text, solar_placeholder(tz)).city_days
    scene = with_vegetation(load_or_build_scene(file, settings_for_source(file, crs, settings)),
                            settings.vegetation)
    tz = solar_zone_of_scene(tz, scene)
    suns = (suns_of_day(day, times, tz, scene, settings.sun) if times
            else parse_suns(sun_text or "135,45;240,15", scene))
    from cityshade.cli.options import map_extent_of_command

    names = [v for v in (s.strip() for s in views.split(",")) if v]
    # --bbox/--margin-m without a map among --views are refused there, not ignored.
    extent = map_extent_of_command(scene, "map" if "map" in names else "overview", False)
    cams = [(v, view_camera(scene, v, (width, height), pixel_size, city_days, cameras_file,
                            bbox=extent)) for v in names]
    if not cams:
        raise UsageError("--views needs at least one view")
    try:
        evaluation = run_evaluation(scene, cams, suns, city_days, techniques, eval_settings,
                                    settings.shadows, progress=bar, model=Path(file).name,
                                    ground=ground)
    finally:
        bar.close()
    evaluation.meta["city_time"] = days_to_iso(city_days)
    written = write_report(evaluation, output)
    failed = [r for r in evaluation.rows if r.get("error")]
    for r in failed:
        click.echo(f"cityshade: warning: {r['technique']} map {r['map_px'] or '-'} on "
                   f"{r['view']} {r['sun']}: {r['error']}", err=True)
    click.echo(" ".join(str(p) for p in written))


def _run_stress(file, settings, ground, quick: bool, output, bar: _Bar) -> None:
    """``evaluate --stress``: the stress set on FILE, its report into ``output`` (optional);
    exit status 1 on any FAIL."""
    import dataclasses

    from cityshade.config import StressSettings
    from cityshade.evaluate.stress import run_stress, stress_markdown
    from cityshade.util import make_folder, write_text_atomic

    stress_settings = StressSettings.quick_set() if quick else settings.stress
    # The stress set has its own cases with and without ground; only an explicit
    # --ground replaces them.
    if click.get_current_context().get_parameter_source("ground").name != "DEFAULT":
        stress_settings = dataclasses.replace(stress_settings, ground=ground)
    try:
        report = run_stress(file, stress_settings, progress=bar,
                            echo=lambda line: _echo_line(bar, line))
    finally:
        bar.close()
    if output is not None:
        make_folder(output, "report folder")
        write_text_atomic(output / "stress.md", stress_markdown(report) + "\n",
                          what="the stress report")
    failed = [c for c in report.cases if not c.passed]
    click.echo(f"stress: {len(report.cases) - len(failed)} of {len(report.cases)} cases "
               f"passed" + (f"; FAILED: {', '.join(c.name for c in failed)}" if failed else ""))
    if failed:
        sys.exit(1)


def _echo_line(bar: _Bar, line: str) -> None:
    bar.close()
    click.echo(line)
