"""``cityshade render FILE``: one picture and shadow mask of the city at a date and sun."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand

from cityshade.cli.options import (camera_options, city_date_option, ground_option,
                                   make_camera, parse_size, parse_triple, shadow_options)
from cityshade.runtime import startup


@click.command("render", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@click.option("--date", "date_text", help="Day of the sun for --time, YYYY-MM-DD (default: "
              "today), or the sun's instant 2025-06-21T15:00+02:00. Without a time of day "
              "(the sun given by --sun-azimuth/--sun-elevation) the short form of --city-date: "
              "--date 1850.")
@city_date_option("the sun's instant, else today")
@click.option("--tz", help="IANA time zone for a --date without UTC offset, e.g. Europe/Berlin; "
              "local-mean or local-apparent: mean or true solar time at the model's longitude "
              "(for historical dates).")
@click.option("--time", "time_text", help="Local time HH:MM[:SS] of the --date day: the sun "
              "is computed by SPA for the model's place at that instant.")
@click.option("--no-refraction", is_flag=True, help="Geometric sun elevation (SPA without "
              "atmospheric refraction).")
@click.option("--sun-azimuth", type=float, help="Degrees clockwise from true north.")
@click.option("--sun-elevation", type=float, help="Degrees above the horizon.")
@camera_options("overview")
@shadow_options("exact")
@click.option("-o", "--output", type=click.Path(dir_okay=False, path_type=Path),
              help="EXR with colour, shadow, Z, normals, primid, objid and provenance "
              "(optional beside --png, --mask or --geotiff).")
@click.option("--exr-precision", type=click.Choice(["half", "full"]), default="half",
              show_default=True, help="EXR channel types: half = colour and normals 16-bit, "
              "shadow, Z and ids 32-bit; full = every channel 32-bit float.")
@click.option("--png", type=click.Path(dir_okay=False, path_type=Path), help="sRGB picture.")
@click.option("--mask", type=click.Path(dir_okay=False, path_type=Path),
              help="8-bit shadow mask PNG: 255 sun, 0 shadow, 128 no surface.")
@click.option("--geotiff", type=click.Path(dir_okay=False, path_type=Path),
              help="Map view: georeferenced mask (TIFF + world file + .prj) for QGIS/GDAL.")
@click.option("--decorate", is_flag=True, help="Map view: --png and --mask as pictures for "
              "people, in a margin with title, scale bar, north arrow, CRS and legend (the mask "
              "then RGB; the EXR and GeoTIFF keep their values).")
@ground_option
@click.option("--strip-rows", type=int, help="Map view, raytrace or izb: render in strips of N "
              "rows (the same pixels in less memory; a map too large for memory as one frame "
              "goes in strips without it).")
@click.option("--no-sky", is_flag=True, help="Black background instead of the sky gradient.")
@click.option("-v", "--verbose", is_flag=True, help="Stage timings and technique diagnostics.")
def render(file, date_text, city_date, tz, time_text, no_refraction, sun_azimuth, sun_elevation,
           camera, eye, target, fov, size, pixel_size, cameras_file, settings, output, png, mask,
           exr_precision, geotiff, decorate, ground, strip_rows, no_sky, verbose):
    """Render FILE (a .cityshade scene) as the city stood on --city-date, lit by the sun at
    --sun-azimuth/--sun-elevation or by the sun computed for the model's place (NREL SPA) at
    --date and --time, from a perspective camera or as a top-down map. Writes the EXR (-o)
    and any of --png, --mask, --geotiff."""
    import time

    startup.no_transparent_huge_pages()  # one frame's cost is mostly fresh memory (see there)
    from cityshade.geo.temporal import parse_user_date
    from cityshade.cli.options import reparse_solar_date, solar_placeholder
    from cityshade.errors import UsageError
    from cityshade.frame.render import check_frame_outputs, render_frame, strip_rows_for, write_frame
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.store.scenefile import open_scene, scene_for_camera
    from cityshade.shadows import describe

    technique = describe(settings.shadows.technique)  # unknown names fail before any work
    if output is None and png is None and mask is None and geotiff is None:
        raise UsageError("nothing to write: give -o FILE.exr, --png, --mask or --geotiff")
    if (sun_azimuth is None) != (sun_elevation is None):
        raise UsageError("give both --sun-azimuth and --sun-elevation")
    if sun_azimuth is not None:
        from cityshade.geo.sun import check_user_angles

        check_user_angles(sun_azimuth, sun_elevation)
        if no_refraction:
            raise UsageError("--no-refraction applies to the sun computed for a date and time; "
                             "--sun-azimuth/--sun-elevation give the sun as it is")
    if decorate and png is None and mask is None:
        raise UsageError("--decorate frames the --png and --mask pictures: give one of them")
    if sun_azimuth is not None and time_text is not None:
        raise UsageError("--time computes the sun for the model's place and --sun-azimuth/"
                         "--sun-elevation give it: use one or the other")
    if (eye is None) != (target is None):
        raise UsageError("give both --eye and --target, or neither")
    parse_triple(eye, "--eye"), parse_triple(target, "--target")  # fail early
    parse_size(size, settings.shadows.technique)
    sun_date, city_text = _dates(date_text, city_date, time_text, tz, sun_azimuth is not None)
    if tz is not None and sun_date is None and len(city_text) <= 10:
        # A zone places a clock time; the sun from angles and a state of whole days have none.
        click.echo("cityshade: warning: --tz is not used: the sun comes from --sun-azimuth/"
                   "--sun-elevation and the city's state is a day (a zone places a --time)",
                   err=True)
    label = _label(sun_date, city_text, city_date)
    check_frame_outputs(None, exr=output, png=png, mask=mask, georef=geotiff)  # before any work
    t0 = time.perf_counter()
    scene = open_scene(file)
    load_s = time.perf_counter() - t0
    if sun_date is not None:
        sun_date = reparse_solar_date(sun_date, tz, scene)
        for warning in sun_date.warnings:
            click.echo(f"cityshade: warning: {warning}", err=True)
    city_days = (reparse_solar_date(parse_user_date(city_text, solar_placeholder(tz)), tz,
                                    scene) if city_text is not None else sun_date).city_days
    cam = make_camera(scene, camera, eye, target, fov, size, pixel_size, cameras_file)
    check_frame_outputs(cam.kind, exr=output, png=png, mask=mask, georef=geotiff)  # the view
    if decorate and cam.kind != "map":
        raise UsageError("--decorate needs a map view (--camera map): a perspective picture "
                         "has no single scale or north")
    strip_rows_for(cam, technique, settings.shadows, strip_rows)  # refused before any work
    scene = with_vegetation(scene_for_camera(scene, cam, technique), settings.vegetation)
    sun = _sun(scene, sun_azimuth, sun_elevation, sun_date, settings, no_refraction)
    frame = render_frame(scene, cam, city_days, sun, technique, settings.shadows,
                         sky=not no_sky, ground=ground, measure=verbose, strip_rows=strip_rows,
                         last_frame=True)
    for warning in frame.warnings:
        click.echo(f"cityshade: warning: {warning}", err=True)
    from cityshade.lightspace import forget_casters

    forget_casters(scene)  # this process renders one frame: the writers need the memory
    t1 = time.perf_counter()
    written = write_frame(frame, scene, label, exr=output, png=png, mask=mask, georef=geotiff,
                          decorate=decorate, exr_precision=exr_precision)
    if geotiff is not None:
        from cityshade.cli.options import warn_geotiff_without_crs

        warn_geotiff_without_crs(scene, geotiff)
    write_s = time.perf_counter() - t1
    if verbose:
        _report(scene, frame, {"load_s": load_s, **frame.timings_s, "write_s": write_s})
    click.echo(" ".join(str(p) for p in written))


def _dates(date_text, city_date, time_text, tz, angles: bool):
    """(the sun's date or None, the city's state text or None: the sun's instant) of
    --date, --time and --city-date; a --date without a time of day is the city's state
    (:func:`cityshade.cli.options.city_of_short_date`). Every text is read here, before any
    work.

    Raises
    ------
    UsageError
        No sun, a sun both from a date and from angles, contradicting states, bad text.
    """
    import datetime as dt

    from cityshade.cli.options import city_of_short_date, solar_placeholder
    from cityshade.errors import UsageError
    from cityshade.geo.temporal import parse_user_date

    if time_text is not None:
        date_text = _with_time(date_text or dt.date.today().isoformat(), time_text)
    sun_date = parse_user_date(date_text, solar_placeholder(tz)) if date_text else None
    city_text = city_date
    if sun_date is not None and sun_date.instant_utc is None:
        city_text, sun_date = city_of_short_date(date_text, city_date, tz, "--time HH:MM"), None
    if city_text is not None:
        parse_user_date(city_text, solar_placeholder(tz))  # fails early on bad text
    if sun_date is not None and angles:
        raise UsageError(f"--date {date_text} has a time of day, for which the sun is "
                         f"computed, and --sun-azimuth/--sun-elevation give it: use one or the "
                         f"other (the city's state alone is --city-date)")
    if sun_date is None and not angles:
        raise UsageError("no sun position: give --sun-azimuth and --sun-elevation (degrees), "
                         "or a --date with a time of day (e.g. 2024-06-21T15:00+02:00, or "
                         "--time 15:00 --tz Europe/Berlin)")
    if sun_date is None and city_text is None:
        city_text = dt.date.today().isoformat()
    return sun_date, city_text


def _label(sun_date, city_text, city_date) -> str:
    """The date a picture's title and provenance name: the sun's, and the city's state when
    --city-date sets it apart."""
    if sun_date is None:
        return city_text
    return sun_date.text if city_date is None else f"{sun_date.text} (city {city_date})"


def _sun(scene, sun_azimuth, sun_elevation, sun_date, settings, no_refraction):
    """The sun of the flags: the given angles, else SPA at the model's place for the date's
    instant."""
    import dataclasses

    from cityshade.geo.sun import sun_from_angles

    if sun_azimuth is not None:
        return sun_from_angles(sun_azimuth, sun_elevation, scene.crs, scene.origin_m)
    # pvlib (and pandas) load only here: a render with explicit angles never needs them.
    from cityshade.geo.sun import sun_from_instant

    spa = settings.sun
    if no_refraction:
        spa = dataclasses.replace(spa, refraction=False)
    return sun_from_instant(sun_date.instant_utc, scene.crs, scene.origin_m, spa)


def _report(scene, frame, timings: dict[str, float]) -> None:
    """``render -v``: stage timings, the sun, the frame's diagnostics, the tiles drawn."""
    sun = frame.sun
    click.echo("timings  " + "  ".join(f"{k[:-2]} {v * 1000:.1f} ms" for k, v in timings.items()),
               err=True)
    click.echo(f"sun      azimuth {sun.azimuth_true_deg:.3f}° true / {sun.azimuth_grid_deg:.3f}° "
               f"grid (convergence {sun.convergence_deg:+.4f}°), elevation "
               f"{sun.elevation_deg:.3f}°", err=True)
    if sun.instant_utc is not None:
        click.echo(f"instant  {sun.instant_utc} UTC, ΔT {sun.delta_t_s:.2f} s, refraction "
                   f"{'on' if sun.refraction else 'off'}, {sun.source} at "
                   f"{sun.latitude_deg:.6f}° N {sun.longitude_deg:.6f}° E "
                   f"{sun.height_m:.1f} m", err=True)
    for key, value in frame.diagnostics.lines():
        click.echo(f"{key:<8} {value}", err=True)
    if scene.is_tiled:
        tiled = scene.tiling
        click.echo(f"tiles    {len(tiled.tile_ids)} of {len(tiled.source.tiles)} in view, "
                   f"{len(tiled.source.tiles_mapped)} mapped (shadow rays reach the rest)",
                   err=True)


def _with_time(date_text: str, time_text: str | None) -> str:
    """``--date`` joined with ``--time`` (a day plus HH:MM[:SS]) into one date-time text."""
    import re

    from cityshade.errors import UsageError

    if time_text is None:
        return date_text
    if not re.fullmatch(r"\d{4,}-\d{2}-\d{2}", date_text.strip()):
        raise UsageError(f"--time needs --date as a day (YYYY-MM-DD), not {date_text!r}")
    if not re.fullmatch(r"\d{2}:\d{2}(:\d{2})?", time_text.strip()):
        raise UsageError(f"--time must be HH:MM or HH:MM:SS, not {time_text!r}")
    return f"{date_text.strip()}T{time_text.strip()}"
