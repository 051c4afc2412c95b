"""``cityshade study FILE``: shadow-study sheets of two city states at fixed times and days."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand
from cityshade.cli.options import (crs_option, ground_option, mesh_options, shadow_options,
                                   states_options)


@click.command("study", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@click.option("--year", type=int, help="Year of the default days: 21 March, 21 June and 21 "
              "December (default: this year).")
@click.option("--days", "days_text", help="The days instead, YYYY-MM-DD separated by commas; "
              "one sheet each.")
@click.option("--from", "from_text", help="First time of each day, HH:MM (default 08:00).")
@click.option("--to", "to_text", help="Last time of each day, HH:MM, included (default 18:00).")
@click.option("--every", "every_text", help="Time between panels: 1h, 2h, 30min (default 1h).")
@click.option("--times", "times_text", help="The times instead, HH:MM separated by commas.")
@click.option("--tz", required=True, help="IANA time zone of the times, e.g. Europe/London; "
              "local-apparent: solar time at the model's longitude (the sun due south at "
              "12:00), local-mean: mean solar time.")
@states_options("the first day", meshes=True)
@mesh_options
@click.option("--pixel-size", type=click.FloatRange(min=1e-3),
              help="Metres per pixel of the map (default: its longer side in 1024 px).")
@click.option("--area", "area_text", help="Site boundary x0,y0,x1,y1 (model CRS), drawn on "
              "every panel.")
@click.option("--extent", "extent_text", help="What the map shows, x0,y0,x1,y1 (model CRS; "
              "default: the whole model), e.g. the site and its surroundings.")
@shadow_options("exact", map_px=False)
@ground_option
@crs_option
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (no refraction).")
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created).")
@click.option("-v", "--verbose", is_flag=True, help="Timings.")
def study(file, year, days_text, from_text, to_text, every_text, times_text, tz, before_text,
          after_text, proposal, mesh_units, up_axis, place_text, pixel_size, area_text,
          extent_text, settings, ground, crs,
          no_refraction, outdir, verbose):
    """Shadow study of FILE (a .cityshade scene, a tiled cache folder, or a CityGML/CityJSON
    file): the shadows of the city before and after a change (--before/--after dates of one
    model, or --with a proposal: a model, or a mesh placed by --place) seen from above at each
    time of each day, existing shadow in grey and new shadow in orange; tree crowns in green,
    their partial shade apart. Writes OUTDIR/study.pdf (one A3 sheet per day),
    sheet_DAY.png, panels/*.tif (each panel's shadow masks, GeoTIFF) and study.json/.csv
    (sun position and shadow areas of every panel).
    """
    import dataclasses
    import time

    from cityshade.cli.batch import Progress
    from cityshade.cli.options import mesh_placement, parse_area, settings_for_source
    from cityshade.planning.run import CompareStates
    from cityshade.study import StudyRequest, run_study

    t0 = time.perf_counter()
    if no_refraction:
        settings = dataclasses.replace(settings, sun=dataclasses.replace(settings.sun,
                                                                        refraction=False))
    settings = settings_for_source(file, crs, settings)
    request = StudyRequest(
        file, _times(year, days_text, from_text, to_text, every_text, times_text, tz),
        CompareStates(before_text, after_text, proposal,
                      mesh_placement(mesh_units, up_axis, place_text)),
        technique=settings.shadows.technique,
        settings=settings, pixel_size_m=pixel_size, area=parse_area(area_text),
        extent=parse_area(extent_text, "--extent"), ground=ground,
        outdir=outdir, provenance={"file": str(file), "with": str(proposal) if proposal else
                                   None, "before_option": before_text,
                                   "after_option": after_text, "place": place_text})
    with Progress("panels") as bar:
        bar.plan(len(request.times.days) * len(request.times.clocks_s))
        result = run_study(request, on_panel=lambda done, total: bar.step(done, total, None))
    for warning in result.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    if result.scene is not None and (result.scene.crs.local
                                     or result.scene.crs.horizontal_epsg is None):
        click.echo("cityshade: warning: the panels' GeoTIFFs have no .prj: the model has no "
                   "known CRS (rebuild it with --crs EPSG:nnnn)", err=True)
    if verbose:
        click.echo(f"timings  study {time.perf_counter() - t0:.2f} s, "
                   f"{len(result.rows)} panels", err=True)
    click.echo(" ".join(str(p) for p in result.written
                        if p.suffix in (".pdf", ".png", ".json", ".csv")))


def _times(year, days_text, from_text, to_text, every_text, times_text, tz):
    """The study's :class:`~cityshade.study.StudyTimes` from the options."""
    import datetime as dt

    from cityshade.errors import UsageError
    from cityshade.study import StudyTimes
    from cityshade.study.request import (
        clock_range,
        default_days,
        parse_days,
        parse_times,
    )
    from cityshade.sunhours.plan import parse_clock_s, parse_duration_s

    if days_text is not None and year is not None:
        raise UsageError("give --days or --year, not both")
    days = parse_days(days_text) if days_text is not None else \
        default_days(year if year is not None else dt.date.today().year)
    if times_text is not None:
        if any(v is not None for v in (from_text, to_text, every_text)):
            raise UsageError("give --times or --from/--to/--every, not both")
        clocks = parse_times(times_text)
    else:
        clocks = clock_range(parse_clock_s(from_text or "08:00"),
                             parse_clock_s(to_text or "18:00"),
                             parse_duration_s(every_text or "1h"))
    return StudyTimes(days, clocks, tz)
