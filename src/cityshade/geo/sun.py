"""The sun as a direction in render space.

Convention (docs/DESIGN.md §1): azimuth in degrees clockwise from TRUE north, elevation in
degrees above the horizon. Render space has grid north (+y of the projected CRS), which differs from true
north by the meridian convergence γ at the model's origin: ``azimuth_grid = azimuth_true − γ``
(γ > 0 where grid north lies east of true north; :func:`cityshade.geo.crs.grid_convergence_deg`).
The sun is a direction, never a far-away point: float32 far points broke a peer (HORAYZON #12).

Sun positions from a date, a time and a place use NREL's Solar Position Algorithm (Reda &
Andreas 2004, corrigendum 2007) as implemented by pvlib (:func:`pvlib.spa.solar_position`), fed
with Unix time as a float computed from proleptic Gregorian day ordinals, so any year 1000–3000
works, and with ΔT from the Espenak–Meeus polynomials (:func:`pvlib.spa.calculate_deltat`).
Only pvlib's SPA module is loaded (:func:`pvlib_spa`), and only when a sun must be computed: a
render with explicit angles loads nothing of pvlib, one with a date and time not its package
(pandas, scipy and some 40 modules: 0.8 s of a 1.7 s render).
"""
from __future__ import annotations

import functools
import importlib.util
import math
import sys
from dataclasses import asdict, dataclass, replace
from datetime import date, datetime, timedelta, timezone, tzinfo

import numpy as np

from cityshade.errors import CRSError, UsageError


@dataclass(frozen=True)
class SunPosition:
    """A resolved sun position.

    Attributes
    ----------
    azimuth_true_deg, elevation_deg : float
        Clockwise from true north; above the horizon.
    azimuth_grid_deg : float
        Clockwise from grid north (+y of render space).
    convergence_deg : float
        Meridian convergence used (0 for a model without CRS).
    direction : (3,) float64
        Unit vector towards the sun in render space.
    source : str
        "explicit" (given angles) or the algorithm that computed it.
    note : str or None
        A caveat for the metadata (e.g. no CRS: grid north assumed true).
    """

    azimuth_true_deg: float
    elevation_deg: float
    azimuth_grid_deg: float
    convergence_deg: float
    direction: np.ndarray
    source: str = "explicit"
    note: str | None = None
    #: Set when the position was computed from a date (SPA): the UTC instant (ISO 8601),
    #: ΔT = TT − UT1 in seconds, whether refraction was applied, and the observer's place.
    instant_utc: str | None = None
    delta_t_s: float | None = None
    refraction: bool | None = None
    latitude_deg: float | None = None
    longitude_deg: float | None = None
    height_m: float | None = None

    @property
    def above_horizon(self) -> bool:
        """True when the sun lights anything (elevation strictly above 0°)."""
        return self.elevation_deg > 0.0

    def metadata(self) -> dict:
        d = asdict(self)
        d["direction"] = [float(v) for v in self.direction]
        return d


def direction_from_angles(azimuth_deg: float, elevation_deg: float) -> np.ndarray:
    """Unit vector towards the sun: x east, y north (of the azimuth's frame), z up."""
    az, el = math.radians(azimuth_deg), math.radians(elevation_deg)
    # Exact values at the zenith and on the axes keep "sun at 90°" exactly vertical.
    d = np.array([math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)])
    if elevation_deg == 90.0:
        d = np.array([0.0, 0.0, 1.0])
    return d / np.linalg.norm(d)


def check_user_angles(azimuth_deg: float, elevation_deg: float) -> None:
    """Refuse a user's sun outside azimuth [0, 360) and elevation [-90, 90] degrees, rather
    than wrap it (an azimuth of 400 is a typo more often than 40).

    Raises
    ------
    UsageError
    """
    if not 0.0 <= azimuth_deg < 360.0:
        raise UsageError(f"sun azimuth must be from 0 to under 360 degrees (clockwise from "
                         f"true north), not {azimuth_deg:g}")
    if not -90.0 <= elevation_deg <= 90.0:
        raise UsageError(f"sun elevation must be between -90 and 90 degrees, not "
                         f"{elevation_deg:g}")


def sun_from_angles(azimuth_true_deg: float, elevation_deg: float, crs=None,
                    origin_m=None, *, convergence_deg: float | None = None) -> SunPosition:
    """Sun position from explicit angles, converted to grid north of the model's CRS.

    Parameters
    ----------
    azimuth_true_deg : float
        Degrees clockwise from true north (any value; taken modulo 360).
    elevation_deg : float
        Degrees above the horizon, in [-90, 90].
    crs : CrsInfo, optional
        The model CRS; a local or missing CRS means grid north is taken as true north.
    origin_m : (3,) array, optional
        Model origin in CRS coordinates (where the convergence is evaluated).
    convergence_deg : float, optional
        The grid convergence at ``origin_m`` when the caller has it already (it depends on the
        place only: a year of suns evaluates it once).

    Raises
    ------
    UsageError
        Non-finite angles or an elevation outside [-90, 90].
    """
    if not (math.isfinite(azimuth_true_deg) and math.isfinite(elevation_deg)):
        raise UsageError("sun azimuth and elevation must be finite numbers of degrees")
    if not -90.0 <= elevation_deg <= 90.0:
        raise UsageError(f"sun elevation must be between -90 and 90 degrees, not {elevation_deg}")
    azimuth_true_deg = azimuth_true_deg % 360.0
    convergence = 0.0
    note = None
    if crs is None or crs.local or crs.horizontal_epsg is None:
        note = "the model has no CRS: azimuth measured from the model's +y axis"
    elif convergence_deg is not None:
        convergence = float(convergence_deg)
    elif origin_m is not None and not crs.is_geographic:
        from cityshade.geo.crs import grid_convergence_deg

        convergence = grid_convergence_deg(crs, float(origin_m[0]), float(origin_m[1]))
    azimuth_grid = (azimuth_true_deg - convergence) % 360.0
    return SunPosition(azimuth_true_deg=azimuth_true_deg, elevation_deg=elevation_deg,
                       azimuth_grid_deg=azimuth_grid, convergence_deg=convergence,
                       direction=direction_from_angles(azimuth_grid, elevation_deg), note=note)


# --- sun positions from date, time and place (SPA through pvlib) ---------------------------

#: Proleptic Gregorian ordinal of 1970-01-01 (Unix time 0).
_EPOCH_ORDINAL = 719_163
#: Years the product promises (docs/DESIGN.md §1) and pvlib's ΔT polynomials cover well.
SPA_YEAR_RANGE = (1000, 3000)


@dataclass(frozen=True)
class SpaSettings:
    """Tunables of the sun position computation.

    Attributes
    ----------
    refraction : bool
        Apply SPA's atmospheric refraction correction to the elevation (on by default: the
        apparent sun is what casts shadows; it lifts the sun by ~0.57° at the horizon).
    temperature_c : float
        Annual mean air temperature for the refraction formula; 12 °C is pvlib's default and
        a mid-latitude mean (the correction changes by ~0.4 % per °C).
    pressure_hpa : float or None
        Annual mean air pressure; None derives it from the model's height with the standard
        atmosphere (:func:`standard_pressure_pa`), 1013.25 hPa at sea level.
    atmos_refract_deg : float
        Refraction at sunrise/sunset, SPA's 0.5667° (it only gates where the correction stops
        below the horizon).
    """

    refraction: bool = True
    temperature_c: float = 12.0
    pressure_hpa: float | None = None
    atmos_refract_deg: float = 0.5667

    def __post_init__(self) -> None:
        if not (math.isfinite(self.temperature_c) and -90.0 <= self.temperature_c <= 60.0):
            raise UsageError(f"temperature_c must be between -90 and 60 °C, "
                             f"not {self.temperature_c}")
        if self.pressure_hpa is not None and not (math.isfinite(self.pressure_hpa)
                                                  and 1.0 <= self.pressure_hpa <= 1100.0):
            raise UsageError(f"pressure_hpa must be between 1 and 1100 hPa, "
                             f"not {self.pressure_hpa}")
        if not (math.isfinite(self.atmos_refract_deg) and 0.0 <= self.atmos_refract_deg < 5.0):
            raise UsageError(f"atmos_refract_deg must be in [0, 5), "
                             f"not {self.atmos_refract_deg}")


def _as_utc(instant) -> datetime:
    if not isinstance(instant, datetime):
        raise UsageError(f"a sun instant must be a datetime, not {type(instant).__name__}")
    if instant.utcoffset() is None:
        raise UsageError(f"instant {instant.isoformat()} has no time zone; give an aware "
                         f"datetime (or --tz ZONE)")
    utc = instant.astimezone(timezone.utc)
    if not SPA_YEAR_RANGE[0] <= utc.year <= SPA_YEAR_RANGE[1]:
        raise UsageError(f"sun positions are computed for years {SPA_YEAR_RANGE[0]} to "
                         f"{SPA_YEAR_RANGE[1]}, not {utc.year}")
    return utc


def unix_seconds(instant) -> float:
    """Seconds since 1970-01-01T00:00Z of an aware datetime, as a float.

    Counted from day ordinals (not :meth:`datetime.timestamp`), so years before 1970 and far
    from it are exact to the microsecond's float64 rounding (~0.1 µs at year 1000).
    """
    utc = _as_utc(instant)
    days = utc.toordinal() - _EPOCH_ORDINAL
    seconds = (utc.hour * 60 + utc.minute) * 60 + utc.second
    return days * 86_400.0 + seconds + utc.microsecond * 1e-6


#: Name of pvlib's SPA module when :func:`pvlib_spa` loads it on its own.
_SPA_ALONE = "cityshade_pvlib_spa"


@functools.cache
def pvlib_spa():
    """pvlib's SPA module (:mod:`pvlib.spa`), loaded from its file on its own while the pvlib
    package is not imported: the module needs only numpy, but ``import pvlib.spa`` first runs
    the package's ``__init__``, which imports pandas, scipy and some 40 modules (0.8 s, half
    of a one-frame render of the 1M city; the file alone takes a few ms). The same code, so
    the same numbers; :mod:`pvlib.spa` itself once pvlib is loaded, or where its file is not
    found."""
    if "pvlib" not in sys.modules:
        package = importlib.util.find_spec("pvlib")
        origin = getattr(package, "origin", None)
        if origin:
            from pathlib import Path

            spec = importlib.util.spec_from_file_location(_SPA_ALONE,
                                                          Path(origin).with_name("spa.py"))
            if spec is not None and spec.loader is not None:
                module = importlib.util.module_from_spec(spec)
                spec.loader.exec_module(module)
                return module
    import pvlib.spa

    return pvlib.spa


def pvlib_version() -> str:
    """The installed pvlib's version (as ``pvlib.__version__``), without importing it."""
    if "pvlib" in sys.modules:
        return sys.modules["pvlib"].__version__
    from importlib.metadata import version

    return version("pvlib")


def delta_t_seconds(instants) -> np.ndarray:
    """ΔT = TT − UT1 in seconds for each instant (Espenak–Meeus polynomials through pvlib).

    Parameters
    ----------
    instants : sequence of aware datetime

    Returns
    -------
    (N,) float64
    """
    calculate_deltat = pvlib_spa().calculate_deltat
    utc = [_as_utc(t) for t in instants]
    years = np.array([t.year for t in utc], dtype=np.float64)
    months = np.array([t.month for t in utc], dtype=np.float64)
    return np.atleast_1d(np.asarray(calculate_deltat(years, months), dtype=np.float64))


def spa_angles(unix_s, latitude_deg: float, longitude_deg: float, height_m: float,
               delta_t_s, *, refraction: bool = True, pressure_hpa: float = 1013.25,
               temperature_c: float = 12.0, atmos_refract_deg: float = 0.5667
               ) -> tuple[np.ndarray, np.ndarray]:
    """Topocentric sun azimuth and elevation by NREL's SPA (pvlib's implementation).

    Parameters
    ----------
    unix_s : (N,) float
        Instants, seconds since 1970-01-01T00:00 UTC (UT1 ≈ UTC).
    latitude_deg, longitude_deg : float
        Observer, WGS 84 degrees (north, east positive).
    height_m : float
        Observer height above sea level.
    delta_t_s : float or (N,) float
        ΔT = TT − UT1 in seconds.
    refraction : bool
        Apparent (refracted) elevation when True, geometric when False.
    pressure_hpa, temperature_c, atmos_refract_deg : float
        Refraction inputs (see :class:`SpaSettings`).

    Returns
    -------
    azimuth_deg, elevation_deg : (N,) float64
        Azimuth clockwise from true north in [0, 360); elevation in [-90, 90]. Never NaN.

    Raises
    ------
    UsageError
        A non-finite input or a latitude/longitude out of range.
    """
    unix = np.atleast_1d(np.asarray(unix_s, dtype=np.float64))
    dt = np.broadcast_to(np.asarray(delta_t_s, dtype=np.float64), unix.shape).copy()
    for name, value in (("latitude", latitude_deg), ("longitude", longitude_deg),
                        ("height", height_m)):
        if not math.isfinite(value):
            raise UsageError(f"observer {name} must be finite, not {value}")
    if not -90.0 <= latitude_deg <= 90.0 or not -180.0 <= longitude_deg <= 360.0:
        raise UsageError(f"observer at latitude {latitude_deg}, longitude {longitude_deg} is "
                         f"not on Earth")
    if not (np.isfinite(unix).all() and np.isfinite(dt).all()):
        raise UsageError("sun instants and ΔT must be finite")
    # Columns: apparent zenith, zenith, apparent elevation, elevation, azimuth, EoT.
    out = np.asarray(pvlib_spa().solar_position(unix, float(latitude_deg),
                                                float(longitude_deg), float(height_m),
                                                float(pressure_hpa), float(temperature_c), dt,
                                                float(atmos_refract_deg)), dtype=np.float64)
    geometric = out[3]
    elevation = out[2] if refraction else geometric
    # SPA's refraction term divides by (e0 + 5.11°) before it is switched off below the
    # horizon, so e0 = −5.11° exactly gives 0·NaN; there the correction is zero anyway.
    elevation = np.where(np.isfinite(elevation), elevation, geometric)
    azimuth = np.mod(out[4], 360.0)
    if not (np.isfinite(elevation).all() and np.isfinite(azimuth).all()):
        raise UsageError("the sun position algorithm returned no finite position")
    return azimuth, np.clip(elevation, -90.0, 90.0)


def model_place(crs, origin_m) -> tuple[float, float, float]:
    """(latitude_deg, longitude_deg, height_m) of the model's origin in WGS 84.

    Raises
    ------
    CRSError
        The model has no CRS (or a local one): its place on Earth, and so the sun of a date,
        is unknown; the message names ``--crs``.
    """
    from cityshade.geo.crs import to_wgs84

    if crs is None or crs.local or crs.horizontal_epsg is None:
        name = "none" if crs is None else crs.name
        raise CRSError(f"the sun of a date needs the model's place on Earth, but the model has "
                       f"no CRS ({name}); rebuild it with --crs EPSG:nnnn or give "
                       f"--sun-azimuth and --sun-elevation")
    origin = np.asarray(origin_m, dtype=np.float64)
    lon_deg, lat_deg, h = to_wgs84(crs, float(origin[0]), float(origin[1]), float(origin[2]))
    return lat_deg, lon_deg, h


def standard_pressure_pa(altitude_m: float) -> float:
    """Air pressure of the standard atmosphere at an altitude, pascals: the one line of
    :func:`pvlib.atmosphere.alt2pres` (the same operations, tested equal), written here
    because its module imports pandas (0.2 s) for a render's one sun."""
    return 100 * ((44331.514 - altitude_m) / 11880.516) ** (1 / 0.1902632)


def _pressure_hpa(settings: SpaSettings, height_m: float) -> float:
    if settings.pressure_hpa is not None:
        return settings.pressure_hpa
    # Clamp: model heights can be ellipsoidal or arbitrary; the formula needs a real altitude.
    return float(standard_pressure_pa(min(max(height_m, -500.0), 9000.0))) / 100.0


def suns_from_instants(instants, crs, origin_m, settings: SpaSettings | None = None
                       ) -> list[SunPosition]:
    """Sun positions for aware instants at the model's origin (SPA through pvlib).

    Parameters
    ----------
    instants : sequence of aware datetime
        Any time zone; converted to UTC. Years 1000 to 3000.
    crs : CrsInfo
        The model's CRS (render space); the origin is transformed to WGS 84 with pyproj and
        grid north is corrected by the meridian convergence there.
    origin_m : (3,) float
        Model origin in CRS coordinates; its z is the observer height.
    settings : SpaSettings, optional

    Returns
    -------
    list of SunPosition
        ``source`` "spa (pvlib x.y)", with instant, ΔT, refraction and place filled in. A sun
        at or below the horizon is returned as it is (``above_horizon`` False).

    Raises
    ------
    CRSError
        No CRS (names ``--crs``).
    UsageError
        A naive datetime or a year outside 1000–3000.
    """
    settings = settings or SpaSettings()
    utc = [_as_utc(t) for t in instants]
    if not utc:
        return []
    lat, lon, h = model_place(crs, origin_m)
    dts = delta_t_seconds(utc)
    unix = np.array([unix_seconds(t) for t in utc])
    az, el = spa_angles(unix, lat, lon, h, dts, refraction=settings.refraction,
                        pressure_hpa=_pressure_hpa(settings, h),
                        temperature_c=settings.temperature_c,
                        atmos_refract_deg=settings.atmos_refract_deg)
    suns = []
    source = f"spa (pvlib {pvlib_version()})"
    convergence = None
    for t, a, e, d in zip(utc, az, el, dts):
        sun = sun_from_angles(float(a), float(e), crs, origin_m, convergence_deg=convergence)
        convergence = sun.convergence_deg
        iso = t.isoformat().replace("+00:00", "Z")
        suns.append(replace(sun, source=source, instant_utc=iso, delta_t_s=float(d),
                            refraction=settings.refraction, latitude_deg=lat,
                            longitude_deg=lon, height_m=h,
                            note=f"SPA at {iso}, ΔT {float(d):.2f} s, refraction "
                                 f"{'on' if settings.refraction else 'off'}, "
                                 f"{lat:.6f}° N {lon:.6f}° E"))
    return suns


def sun_from_instant(instant, crs, origin_m, settings: SpaSettings | None = None) -> SunPosition:
    """One sun position of an aware instant at the model's origin (see
    :func:`suns_from_instants`)."""
    return suns_from_instants([instant], crs, origin_m, settings)[0]


# --- solar time at the model's longitude (--tz local-mean, --tz local-apparent) -------------

def equation_of_time_min(unix_s) -> np.ndarray:
    """Equation of time (apparent − mean solar time) in minutes, from NREL's SPA (pvlib).

    Parameters
    ----------
    unix_s : (N,) float
        Instants, seconds since 1970-01-01T00:00 UTC.

    Returns
    -------
    (N,) float64
        E.g. about +16.4 min in early November, −14.2 min in mid-February.
    """
    unix = np.atleast_1d(np.asarray(unix_s, dtype=np.float64))
    days = np.floor(unix / 86_400.0).astype(np.int64)
    instants = [datetime.fromordinal(int(d) + _EPOCH_ORDINAL).replace(tzinfo=timezone.utc)
                for d in days]
    dt = delta_t_seconds(instants)
    # The place does not enter the equation of time; SPA wants one anyway.
    out = pvlib_spa().solar_position(unix, 0.0, 0.0, 0.0, 1013.25, 12.0, dt, 0.5667)
    return np.asarray(out[5], dtype=np.float64)


class SolarTime(tzinfo):
    """Mean or apparent (true) solar time at a longitude, as a :class:`datetime.tzinfo`.

    Local mean time is UTC + longitude / 15° h (Munich, 11.575° E: +0:46:18). Local apparent
    time adds the equation of time, so the sun crosses the meridian at 12:00; the equation is
    taken once per local day (at mean noon: it changes by at most 30 s a day).
    """

    def __init__(self, longitude_deg: float, apparent: bool):
        if not (math.isfinite(longitude_deg) and -180.0 <= longitude_deg <= 360.0):
            raise UsageError(f"longitude {longitude_deg} is not on Earth")
        self.longitude_deg = float(((longitude_deg + 180.0) % 360.0) - 180.0)
        self.apparent = bool(apparent)
        self._mean = timedelta(seconds=self.longitude_deg * 240.0)

    def _eot(self, day: date) -> timedelta:
        return _eot_of_day(day.toordinal(), self.longitude_deg)

    def utcoffset(self, dt):
        if dt is None or not self.apparent:
            return self._mean
        return self._mean + self._eot(dt.date())

    def dst(self, dt):
        return timedelta(0)

    def tzname(self, dt):
        kind = "local apparent time" if self.apparent else "local mean time"
        return f"{kind} at {self.longitude_deg:.4f}° E"

    def fromutc(self, dt):
        local_mean = dt + self._mean
        if not self.apparent:
            return local_mean
        return local_mean + self._eot(local_mean.date())

    def __repr__(self) -> str:
        return f"SolarTime({self.longitude_deg!r}, apparent={self.apparent})"


@functools.lru_cache(maxsize=4096)
def _eot_of_day(ordinal: int, longitude_deg: float) -> timedelta:
    # Evaluate at the UTC instant of local mean noon of that day.
    unix = (ordinal - _EPOCH_ORDINAL) * 86_400.0 + 43_200.0 - longitude_deg * 240.0
    minutes = float(equation_of_time_min([unix])[0])
    return timedelta(microseconds=round(minutes * 60e6))


def solar_time_zone(kind: str, crs, origin_m) -> SolarTime:
    """The tzinfo of ``--tz local-mean`` or ``--tz local-apparent`` at the model's origin.

    Raises
    ------
    CRSError
        The model has no CRS (its longitude is unknown); the message names ``--crs``.
    UsageError
        ``kind`` is neither.
    """
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    if kind not in SOLAR_TIME_ZONES:
        raise UsageError(f"solar time is one of {', '.join(SOLAR_TIME_ZONES)}, not {kind!r}")
    if crs is None or crs.local or crs.horizontal_epsg is None:
        name = "none" if crs is None else crs.name
        raise CRSError(f"--tz {kind} needs the model's longitude, but the model has no CRS "
                       f"({name}); rebuild the scene with --crs EPSG:nnnn")
    _, lon_deg, _ = model_place(crs, origin_m)
    return SolarTime(lon_deg, apparent=kind == "local-apparent")
