"""Weather files: EnergyPlus EPW, TMY3 and TMY2, read through :mod:`pvlib.iotools`.

Every record of these files is an hour's integral (Wh/m², i.e. the hour's mean W/m²) stamped
with the END of its hour in local STANDARD time (no daylight saving): the EPW ``hour`` field
1–24 and TMY2's ``hour`` mean the hour ending then, TMY3's ``HH:MM`` likewise (``24:00`` the last).
pvlib stamps them differently (EPW and TMY2: ``hour − 1``, the hour's start; TMY3: the hour's
end); :class:`Weather` puts all of them back on the hour's end (:attr:`Weather.hour_end`) and
takes the sun at the MIDDLE of each hour (:attr:`Weather.sun_times`, ``hour_end − 30 min``),
the time the hour's mean irradiance stands for best.

Values are checked after pvlib has read them: a column cut from a line leaves that line short
(an empty last field, the fields after the cut moved left), a non-number gives an empty value,
EPW's missing-value code 9999 is out of range; each is refused with a
:class:`~cityshade.errors.WeatherFileError` naming the file and the line. A failure inside
pvlib is refused with pvlib's words (and the line when its parser names one).

A sunny hour is one whose direct normal irradiance reaches 120 W/m², the WMO's threshold of
bright sunshine (WMO-No. 8, Guide to Instruments and Methods of Observation, 2018, §8.1.1.3).

pvlib and pandas are imported only when a file is read.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from cityshade.errors import UsageError, WeatherFileError

#: WMO's threshold of bright sunshine on the direct normal irradiance, W/m².
SUNNY_DNI_W_M2 = 120.0

#: A weather file farther than this from the model is warned about. Typical-year files come
#: from airports and stations; within ~50 km (a city and its airport: London City Airport is
#: 12 km from Westminster) the hourly irradiance of a typical year is representative, beyond it
#: coasts, hills and urban haze make another climate often enough to say so. The sun positions
#: are always computed at the model's place: only the irradiance is borrowed.
MAX_WEATHER_DISTANCE_KM = 50.0

#: Highest plausible irradiance of an hour, W/m² (the solar constant is 1,361 W/m²): above it a
#: value is a missing-value code (EPW: 9999) or a garbled field.
MAX_IRRADIANCE_W_M2 = 1500.0

#: kind → (pvlib's reader, lines before the first record, hours pvlib's stamp lies before the
#: hour's end, pvlib's names of GHI, DNI, DHI and the air temperature, the temperature's scale).
_KINDS = {
    "epw": ("read_epw", 8, 1, ("ghi", "dni", "dhi", "temp_air"), 1.0),
    "tmy3": ("read_tmy3", 2, 0, ("ghi", "dni", "dhi", "temp_air"), 1.0),
    "tmy2": ("read_tmy2", 1, 1, ("GHI", "DNI", "DHI", "DryBulb"), 0.1),  # tenths of °C
}


@dataclass(frozen=True)
class WeatherLocation:
    """Where a weather file was recorded: WGS 84 degrees (north, east positive), metres above
    sea level, the UTC offset of its local standard time in hours, and its station name."""

    latitude_deg: float
    longitude_deg: float
    elevation_m: float
    utc_offset_h: float
    name: str


@dataclass(frozen=True)
class Weather:
    """An hourly weather file.

    Attributes
    ----------
    path : str
    kind : str
        ``epw``, ``tmy3`` or ``tmy2``.
    location : WeatherLocation
    hour_end : pandas.DatetimeIndex
        The end of each record's hour, local standard time (a fixed UTC offset).
    ghi_w_m2, dni_w_m2, dhi_w_m2 : (H,) float64
        Global horizontal, direct normal and diffuse horizontal irradiance, the hour's mean.
    temp_air_c : (H,) float64
        Dry-bulb air temperature, °C.
    """

    path: str
    kind: str
    location: WeatherLocation
    hour_end: object
    ghi_w_m2: np.ndarray
    dni_w_m2: np.ndarray
    dhi_w_m2: np.ndarray
    temp_air_c: np.ndarray
    #: The instants the records' suns stand for, when not the middle of each hour (records
    #: taken for instants: :func:`cityshade.light.irradiance.irradiance_at`).
    sun_at: object = None

    @property
    def n_hours(self) -> int:
        return int(len(self.dni_w_m2))

    def take(self, rows) -> "Weather":
        """The records ``rows`` (index array) of this file, in that order."""
        import dataclasses

        rows = np.asarray(rows, np.int64)
        return dataclasses.replace(
            self, hour_end=self.hour_end[rows], ghi_w_m2=self.ghi_w_m2[rows],
            dni_w_m2=self.dni_w_m2[rows], dhi_w_m2=self.dhi_w_m2[rows],
            temp_air_c=self.temp_air_c[rows],
            sun_at=None if self.sun_at is None else self.sun_at[rows])

    def hour_containing(self, instants) -> np.ndarray:
        """(K,) int: the record whose hour contains each aware datetime of ``instants``.

        A record stands for the hour that ENDS at its stamp (EPW, TMY: hour-ending averages,
        local standard time), so an instant t belongs to the hour ending at t rounded up to
        the whole hour (an instant on the hour: the hour ending then). Month, day and hour
        are matched in the file's standard time, the year ignored (a typical year mixes
        years).

        Raises
        ------
        UsageError
            No record holds the hour (29 February in a file without it, a partial file).
        """
        import pandas as pd

        ends = self.hour_end
        key: dict = {}
        for i, mdh in enumerate(zip(ends.month, ends.day, ends.hour)):
            key.setdefault(tuple(int(v) for v in mdh), i)
        out = []
        for t in instants:
            local = pd.Timestamp(t).tz_convert(ends.tz)
            end = local.ceil("h")
            i = key.get((end.month, end.day, end.hour))
            if i is None:
                raise UsageError(f"{Path(self.path).name} has no hour containing "
                                 f"{local.strftime('%Y-%m-%d %H:%M')} (its standard time)")
            out.append(i)
        return np.asarray(out, np.int64)

    @property
    def sun_times(self):
        """The middle of each hour (``hour_end − 30 min``), local standard time: the instant
        the hour's sun is computed for (``sun_at`` when set)."""
        import pandas as pd

        if self.sun_at is not None:
            return self.sun_at
        return self.hour_end - pd.Timedelta(minutes=30)

    def sunny(self, threshold_w_m2: float = SUNNY_DNI_W_M2) -> np.ndarray:
        """(H,) bool: hours whose direct normal irradiance is at least ``threshold_w_m2``
        (WMO's 120 W/m² by default).

        Examples
        --------
        >>> w = read_weather("London.epw")                  # doctest: +SKIP
        >>> int(w.sunny().sum())                            # doctest: +SKIP
        2755
        """
        return self.dni_w_m2 >= float(threshold_w_m2)


def weather_kind(path) -> str:
    """The kind of a weather file by its suffix: ``.epw``; ``.tm2`` (TMY2); ``.csv`` (TMY3).

    Examples
    --------
    >>> weather_kind("London.epw"), weather_kind("12839.tm2"), weather_kind("723170TYA.CSV")
    ('epw', 'tmy2', 'tmy3')
    """
    suffix = Path(path).suffix.lower()
    kinds = {".epw": "epw", ".tm2": "tmy2", ".tmy2": "tmy2", ".csv": "tmy3", ".tmy3": "tmy3"}
    if suffix not in kinds:
        raise UsageError(f"{path}: not a known weather file (.epw, .tm2 for TMY2, .csv for "
                         f"TMY3); name its kind")
    return kinds[suffix]


def read_weather(path, kind: str | None = None, *, coerce_year: int | None = None) -> Weather:
    """Read an EPW, TMY3 or TMY2 file through :mod:`pvlib.iotools`.

    Parameters
    ----------
    path : str or Path
    kind : str, optional
        ``epw``, ``tmy3`` or ``tmy2``; by default from the suffix (:func:`weather_kind`).
    coerce_year : int, optional
        Stamp every record with this year (typical years mix months of different years);
        passed to pvlib's EPW and TMY3 readers (TMY2 keeps its years).

    Returns
    -------
    Weather

    Raises
    ------
    WeatherFileError
        A missing file, an unreadable one, or garbled or missing values (the line named).
    UsageError
        An unknown kind.

    Examples
    --------
    >>> w = read_weather("../shared/data/weather/GBR_ENG_London.City.AP.037683_TMYx.2007-2021.epw")  # doctest: +SKIP
    >>> w.n_hours, w.location.latitude_deg, str(w.sun_times[0])  # doctest: +SKIP
    (8760, 51.505, '2014-01-01 00:30:00+00:00')
    """
    kind = weather_kind(path) if kind is None else kind
    if kind not in _KINDS:
        raise UsageError(f"weather files are {', '.join(_KINDS)}, not {kind!r}")
    path = Path(path)
    if not path.is_file():
        raise WeatherFileError("no such weather file", path=str(path))
    data, meta = _pvlib_read(path, kind, coerce_year)
    _, header_lines, shift_h, names, temp_scale = _KINDS[kind]
    if kind == "epw":
        # First: a cut field moves the later ones left, so a value check would blame the wrong
        # column of the right line.
        _check_full_lines(data, path, header_lines)
    values = _checked_columns(data, names, path, kind, header_lines)
    import pandas as pd

    location = _location(meta, path)
    hour_end = pd.DatetimeIndex(data.index) + pd.Timedelta(hours=shift_h)
    return Weather(path=str(path), kind=kind, location=location, hour_end=hour_end,
                   ghi_w_m2=values[0], dni_w_m2=values[1], dhi_w_m2=values[2],
                   temp_air_c=values[3] * temp_scale)


def _pvlib_read(path: Path, kind: str, coerce_year):
    import pvlib.iotools

    reader = getattr(pvlib.iotools, _KINDS[kind][0])
    kwargs = {} if kind == "tmy2" or coerce_year is None else {"coerce_year": int(coerce_year)}
    try:
        data, meta = reader(str(path), **kwargs)
    except (ValueError, KeyError, IndexError, TypeError, UnicodeDecodeError) as exc:
        # pandas' parser names the line of a record with too many fields ("... in line 12").
        found = re.search(r"line (\d+)", str(exc))
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        raise WeatherFileError(f"not a readable {kind.upper()} file (pvlib: {first})",
                               path=str(path), line=int(found.group(1)) if found else None) \
            from exc
    if len(data) == 0:
        raise WeatherFileError(f"the {kind.upper()} file holds no records", path=str(path))
    return data, meta


def _checked_columns(data, names, path: Path, kind: str, header_lines: int) -> list[np.ndarray]:
    """The GHI, DNI, DHI and temperature columns as float64, each value a finite number (and
    the irradiances within [0, MAX_IRRADIANCE_W_M2]); else the first bad record's line."""
    import pandas as pd

    out = []
    for k, name in enumerate(names):
        if name not in data.columns:
            raise WeatherFileError(f"the {kind.upper()} file has no column {name!r}",
                                   path=str(path))
        col = pd.to_numeric(data[name], errors="coerce").to_numpy(np.float64)
        bad = ~np.isfinite(col)
        if k < 3:
            bad |= (col < 0.0) | (col > MAX_IRRADIANCE_W_M2)
        if bad.any():
            row = int(np.flatnonzero(bad)[0])
            raw = data[name].iloc[row]
            raw = repr(raw) if isinstance(raw, str) else str(raw)
            raise WeatherFileError(
                f"{name} of record {row + 1} is {raw}: not a number"
                + (f" within 0 to {MAX_IRRADIANCE_W_M2:g} W/m² (EPW writes 9999 for missing)"
                   if k < 3 else ""), path=str(path), line=header_lines + row + 1)
        out.append(col)
    return out


def _check_full_lines(data, path: Path, header_lines: int) -> None:
    """EPW records have 35 fields: a line with a field cut leaves pvlib's last column empty."""
    last = data.iloc[:, -1]
    empty = last.isna().to_numpy()
    if empty.any():
        row = int(np.flatnonzero(empty)[0])
        raise WeatherFileError(f"record {row + 1} has fewer than the 35 fields of an EPW record "
                               f"(a column is missing)", path=str(path),
                               line=header_lines + row + 1)


def _location(meta: dict, path: Path) -> WeatherLocation:
    try:
        lat = float(meta["latitude"])
        lon = float(meta["longitude"])
        elevation = float(meta.get("altitude", float("nan")))
        tz = float(meta["TZ"])
    except (KeyError, TypeError, ValueError) as exc:
        raise WeatherFileError(f"the file's location header is unreadable ({exc})",
                               path=str(path), line=1) from exc
    if not (math.isfinite(lat) and math.isfinite(lon) and -90 <= lat <= 90
            and -180 <= lon <= 180 and math.isfinite(tz) and -14 <= tz <= 14):
        raise WeatherFileError(f"the file's location (latitude {lat}, longitude {lon}, UTC "
                               f"offset {tz} h) is not on Earth", path=str(path), line=1)
    name = str(meta.get("city") or meta.get("Name") or meta.get("City") or "").strip()
    return WeatherLocation(latitude_deg=lat, longitude_deg=lon, elevation_m=elevation,
                           utc_offset_h=tz, name=name)


def distance_km(location: WeatherLocation, latitude_deg: float, longitude_deg: float) -> float:
    """Geodesic distance on the WGS 84 ellipsoid (pyproj) from a weather file to a place, km.

    Examples
    --------
    >>> station = WeatherLocation(51.505, 0.055, 5.8, 0.0, "London.City.AP")
    >>> round(distance_km(station, 51.5007, -0.1246))           # Westminster
    12
    """
    from pyproj import Geod

    _, _, metres = Geod(ellps="WGS84").inv(location.longitude_deg, location.latitude_deg,
                                           float(longitude_deg), float(latitude_deg))
    return float(metres) / 1000.0


def location_warning(weather: Weather, latitude_deg: float, longitude_deg: float,
                     max_km: float = MAX_WEATHER_DISTANCE_KM) -> str | None:
    """A one-line warning when the weather file lies more than ``max_km`` from the place
    (:data:`MAX_WEATHER_DISTANCE_KM`), else None.

    Examples
    --------
    >>> location_warning(w, 51.5007, -0.1246)          # Westminster, 12 km  # doctest: +SKIP
    >>> location_warning(w, 48.15, 11.57)              # Munich              # doctest: +SKIP
    'London.City.AP.epw: the weather was recorded at London.City.AP (51.5050° N, 0.0550° E), 917 km from the model (more than 50 km): its irradiance may not be the model's climate'
    """
    km = distance_km(weather.location, latitude_deg, longitude_deg)
    if km <= float(max_km):
        return None
    loc = weather.location
    return (f"{Path(weather.path).name}: the weather was recorded at {loc.name or 'its station'} "
            f"({loc.latitude_deg:.4f}° N, {loc.longitude_deg:.4f}° E), {km:.0f} km from the "
            f"model (more than {float(max_km):g} km): its irradiance may not be the model's "
            f"climate")


def scene_location_warning(weather: Weather, scene,
                           max_km: float = MAX_WEATHER_DISTANCE_KM) -> str | None:
    """:func:`location_warning` at the scene's origin (:func:`cityshade.geo.sun.model_place`).

    Raises
    ------
    CRSError
        The scene has no CRS: its place, and so the distance, is unknown.
    """
    from cityshade.geo.sun import model_place

    lat, lon, _ = model_place(scene.crs, scene.origin_m)
    return location_warning(weather, lat, lon, max_km)
