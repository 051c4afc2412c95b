"""``cityshade compare``: what a change takes away — sun-hours before and after, rules."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.options import (camera_options, ground_option, make_camera, shadow_options,
                                   time_plan_options)


@click.command("compare")
@click.argument("file", type=click.Path(path_type=Path))
@click.option("--before", "before_text", help="State of the city before (date or year); "
              "default: --date.")
@click.option("--after", "after_text", help="State of the city after (date or year), on the "
              "same model: a proposed building carries a later validFrom.")
@click.option("--with", "proposal", type=click.Path(dir_okay=False, path_type=Path),
              help="Proposal model (.cityshade, CityGML or CityJSON, same CRS) added to FILE "
                   "for the state after.")
@time_plan_options
@camera_options("map")
@shadow_options("izb")
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
@click.option("-o", "--output", "outdir", type=click.Path(file_okay=False, path_type=Path),
              required=True, help="Output folder (created).")
@click.option("-v", "--verbose", is_flag=True, help="Timings and counts.")
def compare(file, before_text, after_text, proposal, date_text, from_text, to_text, every_text,
            tz, days, to_date_text, every_day, camera, eye, target, fov, size, pixel_size,
            cameras_file, settings, ground, no_refraction, no_surfaces, samples_per_m2,
            min_stretch_text, rule_files, area_text, outdir, verbose):
    """Sun-hours of the same receivers in two states of FILE (a .cityshade scene or a tiled
    cache folder): --before and --after dates of one model, or FILE with the proposal --with
    added. Writes before,
    after and loss maps (EXR, PNG, GeoTIFF for the map view), surfaces.csv, openings.csv,
    the rule verdicts and report.md to OUTDIR."""
    import dataclasses
    import time

    from cityshade.sunhours import run as B
    from cityshade.planning import compare as C
    from cityshade.planning import report as planreport, rules as R
    from cityshade.geo.temporal import parse_user_date
    from cityshade.cli.batch import parse_day
    from cityshade.cli.options import solar_zone_of_scene, warn_lmt
    from cityshade.errors import UsageError
    from cityshade.store.scenefile import whole_scene
    from cityshade.shadows import get_technique
    from cityshade.sunhours.surfaces import SampleSettings
    from cityshade.util import check_outputs, output_group

    t_start = time.perf_counter()
    technique = settings.shadows.technique
    get_technique(technique)
    if technique not in ("izb", "raytrace"):
        raise UsageError(f"compare needs an exact technique (izb or raytrace), not {technique}")
    if samples_per_m2 is not None:
        settings = dataclasses.replace(settings, batch=dataclasses.replace(
            settings.batch, samples_per_m2=samples_per_m2))
    SampleSettings(samples_per_m2=settings.batch.samples_per_m2)
    if no_refraction:
        settings = dataclasses.replace(settings, sun=dataclasses.replace(settings.sun,
                                                                        refraction=False))
    if proposal is None and after_text is None:
        raise UsageError("give --after DATE (one model, two dates) or --with PROPOSAL")
    if proposal is not None and after_text is not None:
        raise UsageError("give --after or --with, not both (the proposal's own dates decide "
                         "when its objects stand)")
    min_stretch_h = B.parse_duration_s(min_stretch_text) / 3600.0 \
        if min_stretch_text.strip() not in ("0", "0min", "0s", "0h") else 0.0
    rules = [r for f in rule_files for r in R.load_rules(f)]
    area = _area(area_text)
    first_day = parse_day(date_text, "--date")
    to_date = parse_day(to_date_text, "--to-date") if to_date_text else None
    every_s = B.parse_duration_s(every_text)
    from_s, to_s = B.parse_clock_s(from_text), B.parse_clock_s(to_text)
    before = parse_user_date(before_text or first_day.isoformat())
    after = parse_user_date(after_text) if after_text else before

    check_outputs(("-o", outdir, None))  # once the options are valid, before any work
    scene = whole_scene(file)  # a tiled cache: the view of all its tiles
    steps = B.plan_steps(first_day, from_s, to_s, every_s, solar_zone_of_scene(tz, scene),
                         days=days, to_date=to_date, every_day=every_day)
    warn_lmt([step.start_utc for step in steps[:1]], tz)
    scene_after = scene
    if proposal is not None:
        scene_after = C.merge_scenes(scene, _load_any(proposal, settings), settings)
    cam = make_camera(scene_after, camera, eye, target, fov, size, pixel_size, cameras_file)
    progress = _progress("sun positions (before, after)")
    comp = C.compare_states(
        scene, before.city_days, scene_after, after.city_days, cam, steps,
        technique=technique, settings=settings, ground=ground,
        samples_per_m2=None if no_surfaces else settings.batch.samples_per_m2,
        min_stretch_h=min_stretch_h, on_step=progress)
    progress.close()
    verdicts = []
    for rule in rules:
        verdicts.append(_run_rule(rule, scene, scene_after, before, after, first_day.year, tz,
                                  every_text, cam, settings, ground, technique, area, C, R, B))
    meta = {"cityshade:kind": "compare", "cityshade:before": before_text or first_day.isoformat(),
            "cityshade:after": after_text or f"with {Path(proposal).name}",
            "cityshade:technique": technique, "cityshade:crs": scene.crs.name,
            "cityshade:steps": len(steps), "cityshade:step_s": every_s}
    request = {"file": str(file), "before": before_text or first_day.isoformat(),
               "after": after_text, "with": str(proposal) if proposal else None,
               "date": first_day.isoformat(), "from": from_text, "to": to_text,
               "every": every_text, "tz": tz, "days": days,
               "to_date": to_date.isoformat() if to_date else None, "every_day": every_day,
               "technique": technique, "camera": camera, "pixel_size": pixel_size,
               "ground": ground, "min_stretch": min_stretch_text,
               "rules": list(rule_files)}
    with output_group():  # the rasters, tables and report appear together, or none of them
        written = C.write_comparison(outdir, comp, meta)
        written += planreport.write_report(outdir, comp, verdicts, request, steps)
    for warning in comp.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    for v in verdicts:
        click.echo(f"{v.rule.id}: {v.status.upper()} — {v.summary}")
    if verbose:
        click.echo(f"timings  before {comp.before.timings_s['total_s']:.2f} s  after "
                   f"{comp.after.timings_s['total_s']:.2f} s  command "
                   f"{time.perf_counter() - t_start:.2f} s", err=True)
    click.echo(" ".join(str(p) for p in written))


def _area(text):
    from cityshade.errors import UsageError

    if text is None:
        return None
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        values = ()
    if len(values) != 4 or not (values[0] < values[2] and values[1] < values[3]):
        raise UsageError(f"--area must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not {text!r}")
    return values


def _load_any(path: Path, settings):
    """A scene file, or a city model built in memory (nothing written)."""
    from cityshade.build import build_scene_from_file
    from cityshade.store.scenefile import load_scene

    if path.suffix == ".cityshade":
        return load_scene(path)
    if not path.exists():
        from cityshade.errors import UsageError

        raise UsageError(f"the proposal {path} does not exist")
    return build_scene_from_file(path, settings)


class _progress:
    """Progress lines (or nothing) for the two runs."""

    def __init__(self, label: str):
        import sys

        from cityshade.cli.options import ProgressLines

        self.lines = None if sys.stderr.isatty() else ProgressLines(label)

    def __call__(self, done, total):
        if self.lines is not None:
            self.lines(done, total)

    def close(self):
        pass


def _run_rule(rule, scene, scene_after, before, after, year, tz, every_text, cam, settings,
              ground, technique, area, C, R, B):
    """The rule's own day, window and receivers, before and after → its verdict."""
    import dataclasses

    import numpy as np

    from cityshade.cli.options import solar_zone_of_scene
    from cityshade.raster.camera import map_view
    from cityshade.geo.sun import suns_from_instants

    day = R.rule_day(rule, year)
    to_date = R.rule_day(rule, year, rule.to_date) if rule.to_date else None
    steps = B.plan_steps(day, B.parse_clock_s(rule.time_from), B.parse_clock_s(rule.time_to),
                         B.parse_duration_s(rule.every or every_text),
                         solar_zone_of_scene(rule.tz or tz, scene), to_date=to_date,
                         every_day=rule.every_day)
    suns = suns_from_instants([s.centre_utc for s in steps], scene.crs, scene.origin_m,
                              settings.sun)
    if rule.min_elevation_deg > 0:
        # Below the rule's minimum altitude the sun does not count: such steps are sun-down.
        suns = [s if s.elevation_deg >= rule.min_elevation_deg else
                dataclasses.replace(s, elevation_deg=min(s.elevation_deg, 0.0)) for s in suns]
    polygons = R.receiver_polygons(rule, scene)
    if polygons is not None:
        if rule.receivers == "openings":
            polygons = polygons & np.isin(np.arange(len(polygons)), [
                p for o in C.openings_of(scene) for p in o.polygons])
        if not polygons.any():
            kind = "windows or doors (LoD3 openings)" if rule.receivers == "openings" else \
                f"surfaces of class {', '.join(rule.classes)}"
            return R.Verdict(rule, "not assessed", f"the model has no {kind}",
                             not_assessed=rule.not_assessed)
    camera = None
    if rule.receivers == "area":
        box = R.area_bbox(rule) or area
        if box is None:
            return R.Verdict(rule, "not assessed", "no area: give the rule an area_bbox or "
                             "area_polygon, or --area x0,y0,x1,y1", not_assessed=rule.not_assessed)
        if rule.area_bbox is None and rule.area_polygon is None:
            rule = dataclasses.replace(rule, area_bbox=tuple(box))
        o = scene.origin_m
        px = cam.pixel_size_m if cam is not None and cam.kind == "map" else 0.5
        camera = map_view(scene_after, min(px, 0.5),
                          bbox=(box[0] - o[0], box[1] - o[1], box[2] - o[0], box[3] - o[1]))
    comp = C.compare_states(
        scene, before.city_days, scene_after, after.city_days, camera, steps,
        technique=technique, settings=settings, ground=ground, suns=suns,
        samples_per_m2=settings.batch.samples_per_m2 if rule.receivers == "surfaces" else None,
        opening_samples_per_m2=0.0 if rule.receivers == "area" else C.OPENING_SAMPLES_PER_M2,
        polygons=polygons, min_stretch_h=rule.min_stretch_h)
    m_before, m_after = R.measures_from(rule, comp)
    verdict = R.evaluate(rule, m_after, m_before)
    verdict.numbers["steps"] = len(steps)
    verdict.numbers["step_min"] = (steps[0].weight_h * 60.0) if steps else 0.0
    verdict.numbers["period"] = f"{day.isoformat()}" + (f" to {to_date.isoformat()}"
                                                        if to_date else "")
    return verdict
