"""``cityshade compare``: what a change takes away — sun-hours before and after, rules."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand
from cityshade.cli.options import (camera_options, ground_option, mesh_options,
                                   mesh_placement, presentation_options, shadow_options,
                                   states_options, time_plan_options)


@click.command("compare", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@states_options("--date", meshes=True)
@mesh_options
@time_plan_options
@camera_options("map")
@shadow_options("exact")
@ground_option
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (no refraction).")
@click.option("--no-surfaces", is_flag=True, help="Skip the per-surface table (pixels and "
              "openings only).")
@click.option("--samples-per-m2", type=float, help="Density of the surface sample points.")
@click.option("--min-stretch", "min_stretch_text", default="0min", show_default=True,
              help="Shortest sunlit stretch counted in the 'stretches' hours.")
@click.option("--rules", "rule_files", multiple=True, help="Rule file (TOML) or shipped set "
              "(bre209, en17037, china-sunshine); repeatable.")
@click.option("--area", "area_text", help="Garden/amenity area x0,y0,x1,y1 (model CRS) for "
              "area rules that name none.")
@click.option("--weather", "weather_file", type=click.Path(dir_okay=False, path_type=Path),
              help="Weather file (EPW; TMY3 .csv; TMY2 .tm2): each window's annual probable "
                   "sunlight hours before and after, and BRE 209's APSH test "
                   "(bre209-window) assessed.")
@presentation_options
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created).")
@click.option("-v", "--verbose", is_flag=True, help="Timings and counts.")
def compare(file, before_text, after_text, proposal, mesh_units, up_axis, place_text, date_text, from_text, to_text, every_text,
            tz, days, to_date_text, every_day, camera, eye, target, fov, size, pixel_size,
            cameras_file, settings, ground, no_refraction, no_surfaces, samples_per_m2,
            min_stretch_text, rule_files, area_text, weather_file, no_decorate, no_gis, outdir,
            verbose):
    """Sun-hours of the same receivers in two states of FILE (a .cityshade scene or a tiled
    cache folder): --before and --after dates of one model, or FILE with the proposal --with
    added. Writes before,
    after and loss maps (EXR, PNG, GeoTIFF for the map view), surfaces.csv, openings.csv,
    the rule verdicts, report.md and report.html, and results.gpkg (GIS layers) to OUTDIR.
    """
    import dataclasses
    import time

    from cityshade.cli.batch import parse_day
    from cityshade.cli.options import make_camera, parse_area, warn_lmt
    from cityshade.planning.report import window_lines
    from cityshade.planning.rules import load_rules
    from cityshade.planning.run import (CompareRequest, CompareStates, TimePlan, open_compare,
                                        require_exact, run_compare)
    from cityshade.sunhours.plan import parse_clock_s, parse_duration_s

    t_start = time.perf_counter()
    technique = settings.shadows.technique
    require_exact(technique)
    if samples_per_m2 is not None:
        if no_surfaces:
            from cityshade.errors import UsageError

            raise UsageError("--samples-per-m2 sets the sample points of the surfaces, which "
                             "--no-surfaces skips: give one or the other")
        settings = dataclasses.replace(settings, batch=dataclasses.replace(
            settings.batch, samples_per_m2=samples_per_m2))
    from cityshade.cli.options import check_every_day

    check_every_day(days, to_date_text)
    if no_refraction:
        settings = dataclasses.replace(settings, sun=dataclasses.replace(settings.sun,
                                                                        refraction=False))
    states = CompareStates(before_text, after_text, proposal,
                           mesh_placement(mesh_units, up_axis, place_text))
    min_stretch_h = parse_duration_s(min_stretch_text) / 3600.0 \
        if min_stretch_text.strip() not in ("0", "0min", "0s", "0h") else 0.0
    rules = [r for f in rule_files for r in load_rules(f)]
    area = parse_area(area_text)
    first_day = parse_day(date_text, "--date")
    to_date = parse_day(to_date_text, "--to-date") if to_date_text else None
    plan = TimePlan(first_day, every_s=parse_duration_s(every_text),
                    from_s=parse_clock_s(from_text), to_s=parse_clock_s(to_text), tz=tz,
                    days=days, to_date=to_date, every_day=every_day)
    provenance = {"file": str(file), "before": before_text or first_day.isoformat(),
                  "after": after_text, "with": str(proposal) if proposal else None,
                  "date": first_day.isoformat(), "from": from_text, "to": to_text,
                  "every": every_text, "tz": tz, "days": days,
                  "to_date": to_date.isoformat() if to_date else None, "every_day": every_day,
                  "technique": technique, "camera": camera, "pixel_size": pixel_size,
                  "ground": ground, "min_stretch": min_stretch_text, "rules": list(rule_files),
                  "weather": str(weather_file) if weather_file else None}
    view = camera
    request = CompareRequest(
        file, plan, states, technique=technique, settings=settings, ground=ground,
        camera=lambda scene: make_camera(scene, view, eye, target, fov, size, pixel_size,
                                         cameras_file),
        surfaces=not no_surfaces, min_stretch_h=min_stretch_h, rules=rules, area=area,
        outdir=outdir, provenance=provenance, decorate=not no_decorate, gis=not no_gis,
        weather=weather_file)
    inputs = open_compare(request)
    warn_lmt([step.start_utc for step in inputs.steps[:1]], tz)
    result = run_compare(request, inputs, on_step=_progress("sun positions (before, after)"))
    comp = result.comparison
    for warning in comp.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    for v in result.verdicts:
        click.echo(f"{v.rule.id}: {v.status.upper()} — {v.summary}")
        for line in window_lines(v):
            click.echo(f"  {line}")
    if verbose:
        click.echo(f"timings  before {comp.before.timings_s['total_s']:.2f} s  after "
                   f"{comp.after.timings_s['total_s']:.2f} s  "
                   + "".join(f"{k[:-2]} {comp.light[k]:.2f} s  " for k in ("vsc_s", "apsh_s")
                             if k in comp.light)
                   + "command "
                   f"{time.perf_counter() - t_start:.2f} s", err=True)
    click.echo(" ".join(str(p) for p in result.written))


class _progress:
    """Progress lines (or nothing) for the two runs."""

    def __init__(self, label: str):
        import sys

        from cityshade.cli.options import ProgressLines

        self.lines = None if sys.stderr.isatty() else ProgressLines(label)

    def __call__(self, done, total):
        if self.lines is not None:
            self.lines(done, total)
