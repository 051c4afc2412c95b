"""Solar irradiance of receivers from a weather file: pvlib's plane-of-array components, each
weighted by what the receiver sees of its source (docs/DESIGN.md §18).

For every hour of the weather file and every distinct receiver plane (tilt and azimuth from
its normal), :func:`pvlib.irradiance.get_total_irradiance` gives the irradiance of that plane
with NO obstacle, split into its components (``diffuse_components=True``). Each component is
then weighted by what the receiver sees of the part of the sky it comes from:

- **direct** (``poa_direct``: DNI × cos incidence) × the exact visibility of that hour's sun
  (one shadow ray towards the sun at its position at the middle of the hour, the batch's
  rule :func:`cityshade.sunhours.tiled.receiver_lit`, ``izb`` or ``raytrace``; through
  vegetation crowns the product of their transmissivities, leaf state by the hour's date,
  :func:`receiver_sun`);
- **circumsolar** (Perez, Hay–Davies) × the same bit: the circumsolar disc is centred on the
  sun;
- **isotropic** × the receiver's visible sky fraction: its cosine-weighted visible sky over
  the same integral with every direction in front visible (its sky view factor relative to
  its plane's unobstructed one, :func:`sky_shares`; directions through crowns weighted by
  their transmission, in leaf or leafless by the hour's date);
- **horizon band** (Perez) × the visible fraction, cosine-weighted, of the patches centred
  below :data:`HORIZON_BAND_DEG` (Perez et al. 1987's horizon band);
- **ground-reflected** (albedo × GHI × (1 − cos tilt) / 2) as pvlib gives it: the plane's
  view of the ground, not reduced by obstructions (the surfaces that hide the sky are not
  taken to reflect; their own reflection is not modelled).

A sun below the horizon at the middle of its hour (a file's DNI of the sunrise hour, or
twilight's circumsolar light on a plane facing down) is blocked by the earth: no direct and no
circumsolar part, where pvlib counts them for a plane facing it. The sky diffuse part of a
receiver is clipped at 0 (a weighted Perez horizon band is negative
in some skies). An hour whose component pvlib cannot compute (NaN: the Perez model with no
diffuse light) adds nothing to it. A receiver with every sky direction in front visible and
its sun unblocked gets exactly pvlib's ``poa_global``: the test of the layering
(tests/light/test_irradiance.py).

Uncertainty: the visibility is exact (one bit per patch and per hour's sun), the weights are
integrals; the decomposition and transposition models behind the diffuse part (a weather
file's DHI is itself often modelled from GHI) are good to ±15–20 % hourly and a few percent
over a year (Gueymard 2009; Yang 2016): that, not the geometry, is the error of a kWh/m².
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from numba import njit
from cityshade.errors import UsageError

#: Sky models of pvlib's get_total_irradiance offered here (their components are weighted).
SKY_MODELS = ("perez", "isotropic", "haydavies")

#: Ground albedo by default: 0.2, the usual value for mixed urban and grassy ground (pvlib's
#: own default is 0.25); ``--albedo`` sets another.
DEFAULT_ALBEDO = 0.2

#: Patches centred below this altitude form the horizon band of the Perez model (Perez et al.
#: 1987, Solar Energy 39(3): a band 6.5° high along the horizon).
HORIZON_BAND_DEG = 6.5

#: Receiver normals closer than this share one pvlib plane (as :data:`~cityshade.light.metrics.
#: NORMAL_ROUND`: a wall's float32 normals scatter by ~1e-7).
NORMAL_ROUND = 1e-6

#: Shares closer than this to 1 are 1 (rounding of the two sums; one patch of the finest
#: sky weighs ~1e-4 of a plane's view).
SHARE_ONE = 1e-12

#: Names of the components summed per receiver, in the order of the kernel's output columns.
COMPONENTS = ("direct", "diffuse", "reflected")


@dataclass(frozen=True)
class Irradiation:
    """Energy received per m² over the weather hours, per receiver.

    Attributes
    ----------
    direct_kwh_m2, diffuse_kwh_m2, reflected_kwh_m2 : (N,) float64
        Beam, sky diffuse (isotropic + circumsolar + horizon band) and ground-reflected.
    hours : int
        Weather hours summed (those with any irradiance).
    sun_hours_traced : int
        Hours whose sun was traced (some receiver could receive direct or circumsolar light).
    model : str
    albedo : float
    """

    direct_kwh_m2: np.ndarray
    diffuse_kwh_m2: np.ndarray
    reflected_kwh_m2: np.ndarray
    hours: int
    sun_hours_traced: int
    model: str
    albedo: float

    @property
    def total_kwh_m2(self) -> np.ndarray:
        return self.direct_kwh_m2 + self.diffuse_kwh_m2 + self.reflected_kwh_m2


def plane_angles(normals) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distinct planes of unit ``normals`` (rounded to :data:`NORMAL_ROUND`): their tilt and
    azimuth in pvlib's convention (degrees; azimuth clockwise from the y axis, grid north) and
    the plane of each normal.

    Returns
    -------
    tilt_deg, azimuth_deg : (U,) float64
    inverse : (N,) int64

    Examples
    --------
    >>> t, a, inv = plane_angles([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])
    >>> t.tolist(), a.tolist(), inv.tolist()
    ([90.0, 0.0], [180.0, 0.0], [1, 0, 1])
    """
    from cityshade.light.metrics import distinct_normals

    unique, inverse = distinct_normals(normals)
    unique = unique / np.linalg.norm(unique, axis=1, keepdims=True)
    tilt = np.degrees(np.arccos(np.clip(unique[:, 2], -1.0, 1.0)))
    horizontal = np.hypot(unique[:, 0], unique[:, 1]) < NORMAL_ROUND
    azimuth = np.where(horizontal, 0.0,
                       np.mod(np.degrees(np.arctan2(unique[:, 0], unique[:, 1])), 360.0))
    return tilt, azimuth, inverse.reshape(-1)


def sun_angles(directions) -> tuple[np.ndarray, np.ndarray]:
    """(zenith_deg, azimuth_deg) of unit sun directions (render space, grid north), in pvlib's
    convention: the angles the shadow rays are traced along, so incidence and visibility agree.

    Examples
    --------
    >>> z, a = sun_angles([[0.0, -1.0, 1.0]])
    >>> round(float(z[0]), 9), round(float(a[0]), 9)
    (45.0, 180.0)
    """
    d = np.asarray(directions, np.float64).reshape(-1, 3)
    d = d / np.linalg.norm(d, axis=1, keepdims=True)
    zenith = np.degrees(np.arccos(np.clip(d[:, 2], -1.0, 1.0)))
    azimuth = np.mod(np.degrees(np.arctan2(d[:, 0], d[:, 1])), 360.0)
    return zenith, azimuth


def sky_shares(visibility, horizon_band_deg: float = HORIZON_BAND_DEG, *, leaf: bool = True
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per receiver: its sky view factor, its visible share of the sky in front (cosine-
    weighted, 1 when nothing blocks) and its visible share of the horizon band; a direction
    through vegetation crowns counts with their transmission, deciduous crowns in leaf or
    leafless (``leaf``).

    A receiver with nothing of a part in front (a downward face: no sky; a horizontal roof has a
    horizon band, thin but weighted) takes a share of 1: pvlib's component of its plane is 0.

    Returns
    -------
    svf, sky_share, horizon_share : (N,) float64
    """
    from cityshade.light.metrics import patch_weights, weighted_sum

    sky = visibility.sky
    weights, inverse = patch_weights(sky, visibility.normals)
    band = (sky.altitude_deg < float(horizon_band_deg)).astype(np.float64)
    if not band.any():
        band = (sky.band == 0).astype(np.float64)
    hweights = weights * band[None, :]
    seen = weighted_sum(visibility, weights, inverse, leaf=leaf)
    seen_h = weighted_sum(visibility, hweights, inverse, leaf=leaf)
    total, total_h = weights.sum(axis=1)[inverse], hweights.sum(axis=1)[inverse]
    share = np.divide(seen, total, out=np.ones_like(seen), where=total > 0.0)
    share_h = np.divide(seen_h, total_h, out=np.ones_like(seen_h), where=total_h > 0.0)
    # The same weights summed in another order: a receiver seeing all of it takes exactly 1.
    share[share > 1.0 - SHARE_ONE] = 1.0
    share_h[share_h > 1.0 - SHARE_ONE] = 1.0
    return seen / math.pi, share, share_h


def plane_irradiance(tilt_deg, azimuth_deg, zenith_deg: float, sun_azimuth_deg: float,
                     dni_w_m2: float, ghi_w_m2: float, dhi_w_m2: float, dni_extra_w_m2: float,
                     airmass: float, model: str, albedo: float) -> np.ndarray:
    """(5, U) W/m² of unobstructed planes for one hour, from pvlib: direct, circumsolar,
    isotropic, horizon band, ground-reflected (a component pvlib does not have is 0, NaN
    becomes 0)."""
    import pvlib

    r = pvlib.irradiance.get_total_irradiance(
        tilt_deg, azimuth_deg, zenith_deg, sun_azimuth_deg, dni_w_m2, ghi_w_m2, dhi_w_m2,
        dni_extra=dni_extra_w_m2, airmass=airmass, albedo=albedo, model=model,
        diffuse_components=True)
    zero = np.zeros(len(tilt_deg))
    out = np.stack([np.broadcast_to(np.asarray(r.get(k, zero), np.float64), zero.shape)
                    for k in ("poa_direct", "poa_circumsolar", "poa_isotropic", "poa_horizon",
                              "poa_ground_diffuse")])
    return np.nan_to_num(out, nan=0.0)


@njit(cache=True)
def add_hour(sums, inverse, lit, sky_share, horizon_share, comps):
    """Add one hour (W/m² × 1 h) to ``sums`` (N, 3): direct × sun fraction ``lit`` (float64:
    1, 0, or a crowns' transmission); sky diffuse = isotropic × sky share + circumsolar × sun
    fraction + horizon × horizon share, clipped at 0; reflected."""
    for i in range(inverse.shape[0]):
        u = inverse[i]
        sun = lit[i]
        sky = comps[2, u] * sky_share[i] + comps[1, u] * sun + comps[3, u] * horizon_share[i]
        sums[i, 0] += comps[0, u] * sun
        if sky > 0.0:
            sums[i, 1] += sky
        sums[i, 2] += comps[4, u]


def hourly_inputs(sun_times, directions) -> dict:
    """Per hour: the sun's zenith and azimuth (from the traced directions), the
    extraterrestrial DNI at ``sun_times`` and pvlib's relative airmass (Kasten–Young 1989), as
    pvlib's get_total_irradiance would compute them."""
    import pvlib

    zenith, azimuth = sun_angles(directions)
    return {"zenith_deg": zenith, "azimuth_deg": azimuth,
            "dni_extra_w_m2": np.asarray(pvlib.irradiance.get_extra_radiation(
                sun_times), np.float64),
            "airmass": np.asarray(pvlib.atmosphere.get_relative_airmass(zenith), np.float64)}


def receiver_sun(scene, points, normals, direction, t_days: float, engine: str, receivers,
                 day: int | None) -> np.ndarray:
    """(N,) float64: the fraction of the sun along ``direction`` each receiver gets: the
    batch's :func:`~cityshade.sunhours.tiled.receiver_lit` (facing rule, the same origins) as
    1 or 0 on a scene without vegetation; with vegetation the transmission of the crowns in
    the way (:func:`cityshade.shadows.visibility.transmission`, leaf state of ``day``, the
    hour's UTC day of the year). Written here because the batch's rule is a bit."""
    from cityshade.geometry.vegetation import scene_vegetation

    if scene_vegetation(scene) is None:
        from cityshade.sunhours.tiled import receiver_lit

        return receiver_lit(scene, points, normals, direction, t_days, engine,
                            receivers).astype(np.float64)
    from cityshade.shadows import facing_mask
    from cityshade.shadows.visibility import transmission

    faces = facing_mask(normals, True, direction)
    out = np.zeros(points.shape[0], np.float64)
    if faces.any():
        origins = receivers.origins(direction, faces)
        out[faces] = transmission(scene, origins, direction, t_days, engine=engine,
                                  day_of_year=day)
    return out


def hour_days(sun_times) -> np.ndarray:
    """(H,) int: the UTC day of the year (1-366) of every hour's sun (``Weather.sun_times``:
    the middle of the hour), the date the vegetation's leaf state is read from
    (docs/DESIGN.md §21)."""
    return np.asarray(sun_times.tz_convert("UTC").day_of_year, np.int64)


def irradiation(scene, points, normals, weather, directions, shares, *,
                hours=None, t_days: float = 0.0, engine: str = "izb", model: str = "perez",
                albedo: float = DEFAULT_ALBEDO, progress=None) -> Irradiation:
    """Energy per m² of every receiver over the weather hours (see the module's docstring).

    Parameters
    ----------
    scene : Scene
    points, normals : (N, 3) float arrays
        Receivers (render space) and their unit normals.
    weather : Weather
    directions : (H, 3) float64
        The sun of every weather hour (:func:`cityshade.light.sunlight.weather_suns`).
    shares : pair of (N,) float64, or {True: pair, False: pair}
        The sky share and horizon share of every receiver (:func:`sky_shares`; ones: no
        obstruction of the sky). With vegetation, a mapping by leaf state: True those with
        the crowns in leaf, False with the deciduous crowns leafless (``sky_shares(vis,
        leaf=False)``); an hour takes the pair of its leaf state (the ``[vegetation]``
        settings at the hour's UTC date). A plain pair serves every hour.
        The instant of every record's sun (``directions``: the extraterrestrial DNI, the leaf
        state) is ``weather.sun_times`` (the middle of each hour, or the instants a record
        was taken for).
    hours : (H,) bool, optional
        Hours to sum (default all: the file's year).
    t_days : float
        City time of the obstructions.
    engine : str
        ``izb`` or ``raytrace`` for the sun's visibility.
    model : str
        ``perez``, ``isotropic`` or ``haydavies``.
    albedo : float
    progress : callable, optional
        ``progress(done, total)`` hours.

    Returns
    -------
    Irradiation
    """
    from cityshade.lightspace import SurfaceReceivers

    if model not in SKY_MODELS:
        raise UsageError(f"the sky model is one of {', '.join(SKY_MODELS)}, not {model!r}")
    if not (math.isfinite(albedo) and 0.0 <= albedo <= 1.0):
        raise UsageError(f"the albedo must be from 0 to 1, not {albedo}")
    pts = np.ascontiguousarray(points, np.float64).reshape(-1, 3)
    nrm = np.ascontiguousarray(normals, np.float64).reshape(-1, 3)
    tilt, azimuth, inverse = plane_angles(nrm)
    times = weather.sun_times
    inputs = hourly_inputs(times, directions)
    use = np.ones(weather.n_hours, bool) if hours is None else np.asarray(hours, bool)
    use &= (weather.ghi_w_m2 > 0.0) | (weather.dni_w_m2 > 0.0) | (weather.dhi_w_m2 > 0.0)
    todo = np.flatnonzero(use)
    if len(todo):
        # The hours grouped by izb's caster key order (a sun's dominant axis: east in the
        # morning, up at noon, west in the evening): a year in time order re-sorted every
        # caster three times a day, grouped five times in all. Sums in this order whichever
        # engine traces, so the engines' kWh are the same.
        from cityshade.light.visibility import direction_order

        todo = todo[direction_order(directions[todo])]
    if engine == "exact":
        # One choice for the run, as batch makes it: chosen per hour, each hour would count
        # izb's caster sort as its own and take raytrace for every hour of the year.
        from cityshade.shadows.exact import engine_for_run

        engine = engine_for_run(engine, scene, len(pts), max(len(todo), 1))
    sums = np.zeros((len(pts), 3))
    receivers = SurfaceReceivers(pts, nrm) if len(pts) else None
    on, off = (shares[True], shares[False]) if isinstance(shares, dict) else (shares, shares)
    share, hshare = (np.ascontiguousarray(s, np.float64) for s in on)
    leafless = tuple(np.ascontiguousarray(s, np.float64) for s in off)
    days = hour_days(times)
    from cityshade.geometry.vegetation import scene_vegetation, vegetation_settings

    in_leaf = vegetation_settings(scene).in_leaf if scene_vegetation(scene) is not None \
        else (lambda day: True)
    no_sun = np.zeros(len(pts), np.float64)
    traced = 0
    for done, h in enumerate(todo, 1):
        comps = plane_irradiance(tilt, azimuth, inputs["zenith_deg"][h], inputs["azimuth_deg"][h],
                                 weather.dni_w_m2[h], weather.ghi_w_m2[h], weather.dhi_w_m2[h],
                                 inputs["dni_extra_w_m2"][h], inputs["airmass"][h], model, albedo)
        lit = no_sun
        if directions[h, 2] <= 0.0:
            # The earth blocks a sun below the horizon (pvlib counts it for a plane facing it).
            comps[:2] = 0.0
        elif len(pts) and ((comps[0] > 0.0) | (comps[1] > 0.0)).any():
            d = np.ascontiguousarray(directions[h], np.float64)
            lit = receiver_sun(scene, pts, nrm, d, t_days, engine, receivers, int(days[h]))
            traced += 1
        leaf = in_leaf(int(days[h]))
        add_hour(sums, inverse, lit, share if leaf else leafless[0],
                 hshare if leaf else leafless[1], comps)
        if progress is not None:
            progress(done, len(todo))
    kwh = sums / 1000.0
    return Irradiation(direct_kwh_m2=kwh[:, 0], diffuse_kwh_m2=kwh[:, 1],
                       reflected_kwh_m2=kwh[:, 2], hours=len(todo), sun_hours_traced=traced,
                       model=model, albedo=float(albedo))


def irradiance_at(scene, points, normals, weather, instants, directions, shares, *,
                  t_days: float = 0.0, engine: str = "izb",
                  model: str = "perez", albedo: float = DEFAULT_ALBEDO) -> np.ndarray:
    """(K, N, 3) W/m² (direct, diffuse, reflected) of every receiver at K instants.

    Each instant takes the weather record of the hour containing it
    (:meth:`~cityshade.light.weather.Weather.hour_containing`: the hour-ending average of DNI,
    GHI and DHI) with the sun AT the instant (``directions`` (K, 3), SPA at the model's place),
    and is layered as one hour of :func:`irradiation` (the same weights, the extraterrestrial
    DNI and the leaf state of the instant): an unobstructed receiver gets exactly pvlib's
    ``get_total_irradiance`` of that record and sun.
    """
    import pandas as pd

    import dataclasses

    rows = weather.hour_containing(instants)
    times = pd.DatetimeIndex([pd.Timestamp(t) for t in instants]).tz_convert(
        weather.hour_end.tz)
    records = dataclasses.replace(weather.take(rows), sun_at=times)
    dirs = np.ascontiguousarray(directions, np.float64).reshape(-1, 3)
    out = np.zeros((len(rows), len(np.asarray(points).reshape(-1, 3)), 3))
    for k in range(len(rows)):
        one = np.zeros(len(rows), bool)
        one[k] = True
        irr = irradiation(scene, points, normals, records, dirs, shares, hours=one,
                          t_days=t_days, engine=engine, model=model, albedo=albedo)
        # Wh/m² of one hour at a constant W/m² (the sums' unit is kWh): back to W/m².
        out[k] = np.stack([irr.direct_kwh_m2, irr.diffuse_kwh_m2, irr.reflected_kwh_m2],
                          axis=1) * 1000.0
    return out


def _month_day(text: str, option: str) -> int:
    """``MM-DD`` or ``YYYY-MM-DD`` → ``100 * month + day``; a one-line error naming
    ``option``."""
    import datetime as dt

    parts = text.strip().split("-")
    try:
        if len(parts) == 2:
            day = dt.date(2000, int(parts[0]), int(parts[1]))  # a leap year: 02-29 is a day
        else:
            day = dt.date.fromisoformat(text.strip())
    except ValueError:
        raise UsageError(f"{option} must be a day MM-DD or YYYY-MM-DD, not {text!r}") from None
    return day.month * 100 + day.day


def hours_between(weather, from_date: str | None, to_date: str | None) -> np.ndarray:
    """(H,) bool: the weather hours whose middle falls from ``from_date`` to ``to_date`` (both
    days included; month and day only, a typical year mixes years; a ``to_date`` before
    ``from_date`` wraps over the new year). Missing ends: the file's first or last day.

    Examples
    --------
    >>> hours_between(w, "06-01", "08-31").sum()                      # doctest: +SKIP
    2208
    """
    t = weather.sun_times
    md = np.asarray(t.month) * 100 + np.asarray(t.day)
    lo = _month_day(from_date, "--from-date") if from_date else int(md[0])
    hi = _month_day(to_date, "--to-date") if to_date else int(md[-1])
    if lo <= hi:
        return (md >= lo) & (md <= hi)
    return (md >= lo) | (md <= hi)
