"""Daylight and sunlight of the openings of a comparison: the vertical sky component and the
probable sunlight hours of a weather file at each window's BRE reference point, before and
after (docs/DESIGN.md §12, §18).

The reference point of an opening is the centre of the window on its outer face
(:func:`cityshade.light.visibility.polygon_reference_points`: the area centroid of its
polygons, with their mean normal), as BRE 209 takes it for the VSC; the same point serves the
probable sunlight hours (BRE takes those on the inner face of the wall, which city models do
not carry). The sky and the sun are traced from it through the scene of each state at that
state's city time, with an exact engine (:func:`cityshade.light.visibility.sky_visibility`,
:func:`cityshade.light.sunlight.probable_sunlight`).

The engine is ``raytrace`` unless asked otherwise: there is one receiver per opening, and
``raytrace`` takes all of a state's sky directions (or sunny hours) in one call, while the
light-space engine (``izb``) builds a pass per direction that only pays back over many
receivers (13 openings of FZK-Haus: 2,305 sky directions and ~2,700 sunny hours per state).
Both give the same bits (tests/light).
"""
from __future__ import annotations

import time

import numpy as np

__all__ = ["LIGHT_ENGINE", "add_opening_light"]

#: Engine of the openings' light (see the module's docstring).
LIGHT_ENGINE = "raytrace"


def add_opening_light(comp, *, vsc: bool = True, weather=None, sky: str | None = None,
                      engine: str = LIGHT_ENGINE) -> None:
    """Add the light columns of every opening of ``comp`` to ``comp.opening`` (in place).

    Parameters
    ----------
    comp : cityshade.planning.compare.Comparison
        With its openings (``comp.openings``).
    vsc : bool
        Compute the vertical sky component (``vsc_before``, ``vsc_after``: fractions).
    weather : cityshade.light.weather.Weather, optional
        Compute the probable sunlight hours (``apsh_before``/``_after`` and
        ``winter_apsh_before``/``_after``: shares of the place's annual probable sunny hours).
    sky : str, optional
        Sky of the VSC (:func:`cityshade.light.sky.named_sky`; default
        :data:`cityshade.light.sky.DEFAULT_SKY`, 2,305 patches).
    engine : str
        ``raytrace`` or ``izb``.

    ``comp.light`` records what was computed: the sky, the weather file, the place's sunny
    hours (annual and winter), the engine and the seconds each part took. Openings not standing
    after (demolished) get NaN after.
    """
    from cityshade.light import (
        DEFAULT_SKY,
        polygon_reference_points,
        probable_sunlight,
        sky_for_scene,
        sky_visibility,
        vertical_sky_component,
        weather_suns,
    )

    from cityshade.geometry.vegetation import window_light_scene

    # BRE 209 leaves deciduous trees out of these tests ([vegetation] window_trees).
    scene_b, scene_a = window_light_scene(comp.scene_before), window_light_scene(comp.scene_after)
    groups = [op.polygons for op in comp.openings]
    points, normals = polygon_reference_points(scene_b, groups)
    ok = np.isfinite(points).all(axis=1) & np.isfinite(normals).all(axis=1)
    standing = np.array([bool(comp.polygon_standing_after[list(g)].all()) for g in groups],
                        bool) if groups else np.zeros(0, bool)
    states = ((scene_b, comp.t_before_days, ok), (scene_a, comp.t_after_days, ok & standing))
    n = len(groups)
    info = comp.light
    info.update(engine=engine, reference_points=points + np.asarray(scene_b.origin_m))
    if vsc:
        t0 = time.perf_counter()
        info["sky"] = sky or DEFAULT_SKY
        sky_dirs = sky_for_scene(scene_b, info["sky"])
        for tag, (scene, t_days, rows) in zip(("before", "after"), states):
            out = np.full(n, np.nan)
            if rows.any():
                vis = sky_visibility(scene, points[rows], normals[rows], sky_dirs, t_days,
                                     engine=engine)
                out[rows] = vertical_sky_component(vis)
            comp.opening[f"vsc_{tag}"] = out
        info["vsc_s"] = time.perf_counter() - t0
    if weather is not None:
        t0 = time.perf_counter()
        info["weather"] = weather
        suns = weather_suns(weather, scene_b)  # the same place in both states
        for tag, (scene, t_days, rows) in zip(("before", "after"), states):
            apsh, winter = np.full(n, np.nan), np.full(n, np.nan)
            if rows.any():
                ps = probable_sunlight(scene, points[rows], normals[rows], weather, t_days,
                                       engine=engine, suns=suns)
                apsh[rows], winter[rows] = ps.apsh, ps.winter_apsh
                info["sunny_h"], info["winter_sunny_h"] = ps.total_h, ps.winter_total_h
            comp.opening[f"apsh_{tag}"] = apsh
            comp.opening[f"winter_apsh_{tag}"] = winter
        info["apsh_s"] = time.perf_counter() - t0
