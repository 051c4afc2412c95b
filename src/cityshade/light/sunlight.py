"""Probable sunlight hours of receivers from a weather file (BRE 209's APSH and winter share).

An hour of the weather file is a probable sunny hour of the place when its direct normal
irradiance reaches the WMO's 120 W/m² (:data:`cityshade.light.weather.SUNNY_DNI_W_M2`) with the
sun above the horizon. It reaches a receiver (a window's reference point) when the sun is in
front of the receiver's plane and the shadow ray towards the sun, at its exact position of that
hour (the middle of the hour at the model's place, NREL SPA through
:func:`cityshade.geo.sun.suns_from_instants`; not snapped to a sky patch), is not blocked
(:func:`cityshade.shadows.visibility.occluded`).

BRE 209 (Littlefair 2022, §3.1): the annual probable sunlight hours (APSH) of a window are the
hours that reach it as a share of the place's annual probable sunny hours (criterion ≥ 25 %);
the winter hours (21 September to 21 March, both days included) are counted as a share of the
same ANNUAL total (criterion ≥ 5 %).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cityshade.errors import UsageError

#: First and last (month, day) of BRE 209's winter period, both included.
WINTER_FROM, WINTER_TO = (9, 21), (3, 21)


@dataclass(frozen=True)
class ProbableSunlight:
    """Probable sunlight hours of N receivers over a weather file.

    Attributes
    ----------
    annual_h, winter_h : (N,) float64
        Sunny hours that reach each receiver, over the year and in the winter period.
    total_h, winter_total_h : float
        The place's probable sunny hours (unobstructed), over the year and in winter.
    front_h : (N,) float64
        Sunny hours with the sun in front of each receiver, obstructions ignored.
    """

    annual_h: np.ndarray
    winter_h: np.ndarray
    total_h: float
    winter_total_h: float
    front_h: np.ndarray

    @property
    def apsh(self) -> np.ndarray:
        """(N,) annual probable sunlight hours as a share of the year's (0–1)."""
        return self.annual_h / self.total_h if self.total_h > 0 else np.full_like(self.annual_h,
                                                                                 np.nan)

    @property
    def winter_apsh(self) -> np.ndarray:
        """(N,) winter probable sunlight hours as a share of the YEAR's total (BRE 209)."""
        return self.winter_h / self.total_h if self.total_h > 0 else np.full_like(self.winter_h,
                                                                                 np.nan)


def weather_suns(weather, scene, settings=None) -> tuple[np.ndarray, np.ndarray]:
    """The sun of every weather hour at the model's place, at the middle of the hour.

    Parameters
    ----------
    weather : Weather
    scene : Scene
        Its CRS and origin give the place and grid north.
    settings : SpaSettings, optional

    Returns
    -------
    directions : (H, 3) float64
        Unit directions towards the sun, render space (grid north).
    elevation_deg : (H,) float64
        Apparent elevation (refraction on by default).

    Raises
    ------
    CRSError
        The scene has no CRS.

    Examples
    --------
    >>> directions, elevation_deg = weather_suns(read_weather("London.epw"), scene)  # doctest: +SKIP
    >>> directions.shape                                                          # doctest: +SKIP
    (8760, 3)
    """
    from cityshade.geo.sun import suns_from_instants

    instants = [t.to_pydatetime() for t in weather.sun_times]
    suns = suns_from_instants(instants, scene.crs, scene.origin_m, settings)
    directions = np.array([s.direction for s in suns], np.float64).reshape(-1, 3)
    elevation = np.array([s.elevation_deg for s in suns], np.float64)
    return directions, elevation


def winter_hours(weather) -> np.ndarray:
    """(H,) bool: hours whose middle falls from 21 September to 21 March (both included).

    Examples
    --------
    >>> int(winter_hours(read_weather("London.epw")).sum())                 # doctest: +SKIP
    4368
    """
    t = weather.sun_times
    md = np.asarray(t.month) * 100 + np.asarray(t.day)
    return (md >= WINTER_FROM[0] * 100 + WINTER_FROM[1]) | (md <= WINTER_TO[0] * 100
                                                            + WINTER_TO[1])


def probable_sunlight(scene, points, normals, weather, t_days: float = 0.0, *,
                      engine: str = "izb", threshold_w_m2: float | None = None,
                      settings=None, suns=None) -> ProbableSunlight:
    """Annual and winter probable sunlight hours of receivers (windows' reference points).

    Parameters
    ----------
    scene : Scene
        With a CRS (the sun's place) and a kd-tree or a tiled view.
    points, normals : (N, 3) float arrays
        Receivers (render-space metres) and their unit normals
        (:func:`cityshade.light.visibility.polygon_reference_points` for openings).
    weather : Weather
        :func:`cityshade.light.weather.read_weather`.
    t_days : float
        City time of the obstructions, days since 1970-01-01 UTC.
    engine : str
        ``izb`` or ``raytrace`` (the same answer).
    threshold_w_m2 : float, optional
        Direct normal irradiance of a sunny hour (default WMO's 120 W/m²).
    settings : SpaSettings, optional
    suns : (directions, elevation_deg), optional
        :func:`weather_suns` of this weather and scene, when already computed (two states of
        one place share them).

    Returns
    -------
    ProbableSunlight

    Examples
    --------
    >>> w = read_weather("London.epw")                                     # doctest: +SKIP
    >>> pts, nrm = polygon_reference_points(scene, [o.polygons for o in openings])  # doctest: +SKIP
    >>> ps = probable_sunlight(scene, pts, nrm, w, t_days)                  # doctest: +SKIP
    >>> ps.apsh >= 0.25, ps.winter_apsh >= 0.05                             # doctest: +SKIP
    """
    from cityshade.light.sky import in_front
    from cityshade.light.visibility import BATCH_RAYS, ENGINES
    from cityshade.light.weather import SUNNY_DNI_W_M2
    from cityshade.shadows.visibility import occluded
    from cityshade.trace import shadow_rays_from_surface

    if engine not in (*ENGINES, "exact"):
        raise UsageError(f"sunlight is traced with {' or '.join(ENGINES)}, not {engine!r}")
    pts = np.ascontiguousarray(points, np.float64).reshape(-1, 3)
    nrm = np.ascontiguousarray(normals, np.float64).reshape(-1, 3)
    if pts.shape != nrm.shape:
        raise UsageError(f"points {pts.shape} and normals {nrm.shape} differ in shape")
    threshold = SUNNY_DNI_W_M2 if threshold_w_m2 is None else float(threshold_w_m2)
    directions, elevation = weather_suns(weather, scene, settings) if suns is None else suns
    sunny = weather.sunny(threshold) & (elevation > 0.0)
    winter = winter_hours(weather)
    n = len(pts)
    annual, win, front_h = np.zeros(n), np.zeros(n), np.zeros(n)
    hours = np.flatnonzero(sunny)
    if engine == "exact":      # the sunny hours are calls of the same receivers: one choice
        from cityshade.shadows.exact import engine_for_run

        engine = engine_for_run(engine, scene, n, len(hours))
    # izb: one light-space pass per hour; raytrace: many hours per call (a direction per ray,
    # BATCH_RAYS rays at most), the same rays as hour by hour. With vegetation, hour by hour:
    # an hour counts with the transmission of the crowns in the way (its date's leaf state).
    from cityshade.geometry.vegetation import scene_vegetation

    veg = scene_vegetation(scene) is not None
    per = max(1, BATCH_RAYS // max(n, 1)) if engine == "raytrace" and not veg else 1
    days = None
    if veg:
        from cityshade.light.irradiance import hour_days
        from cityshade.shadows.visibility import transmission

        days = hour_days(weather.sun_times)
    for s in range(0, len(hours), per):
        hs = hours[s:s + per]
        front = in_front(nrm, directions[hs])              # (N, hours of the chunk)
        front_h += front.sum(axis=1)
        rows, cols = np.nonzero(front)
        if not len(rows):
            continue
        d = directions[hs[0]] if len(hs) == 1 else np.ascontiguousarray(directions[hs[cols]])
        origins = shadow_rays_from_surface(pts[rows], nrm[rows], d)
        if veg:
            frac = transmission(scene, origins, d, t_days, engine=engine,
                                day_of_year=int(days[hs[0]]))
            annual += np.bincount(rows, weights=frac, minlength=n)
            win += np.bincount(rows, weights=frac * winter[hs[cols]], minlength=n)
            continue
        lit = ~occluded(scene, origins, d, t_days, engine=engine)
        annual += np.bincount(rows[lit], minlength=n)
        win += np.bincount(rows[lit & winter[hs[cols]]], minlength=n)
    return ProbableSunlight(annual_h=annual, winter_h=win, total_h=float(sunny.sum()),
                            winter_total_h=float((sunny & winter).sum()), front_h=front_h)
