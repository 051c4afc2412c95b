"""Time of the city: XSD date/time values, validity intervals of city objects, ``--date``.

Conventions (docs/DESIGN.md §1)
-------------------------------
* A point in time is a float64 number of **days since 1970-01-01T00:00:00 UTC** in the
  proleptic Gregorian calendar (negative before 1970). Day counts come from
  :meth:`datetime.date.toordinal`, never from POSIX timestamps, so years 1..9999 work (the
  product promises 1000..3000). float64 resolves 5 µs at year 3000, far below any use here.
* Open ends are ``-inf`` (:data:`DAYS_OPEN_BEGIN`) and ``+inf`` (:data:`DAYS_OPEN_END`).
* A validity interval is half-open, ``[begin, end)``: an object demolished on a day does not
  stand on that day.
* A date without a time is midnight; a date or year with a UTC offset is midnight *at that
  offset*; without an offset it is midnight UTC (XSD leaves such values "untimezoned"; UTC is
  the documented choice). A year alone is January 1 of that year.
"""
from __future__ import annotations

import functools
import math
import re
from datetime import date, datetime, timedelta, timezone
from typing import Mapping, NamedTuple

from cityshade.errors import UsageError

__all__ = [
    "DAYS_OPEN_BEGIN", "DAYS_OPEN_END", "GENERIC_PREFIX", "Interval", "TIME_ATTRIBUTES",
    "TIME_SOURCES", "TIME_SOURCES_ORDER", "UserDate", "choose_interval", "datetime_to_days",
    "days_to_iso", "has_creation_dates", "lmt_warning", "parse_time_attribute",
    "parse_user_date", "SOLAR_TIME_ZONES", "zone_info",
    "parse_xsd_datetime_days",
]

DAYS_OPEN_BEGIN = -math.inf
DAYS_OPEN_END = math.inf

#: Proleptic Gregorian ordinal of 1970-01-01 (day 0).
_EPOCH_ORDINAL = date(1970, 1, 1).toordinal()
_SECONDS_PER_DAY = 86_400
_US_PER_DAY = _SECONDS_PER_DAY * 1_000_000
#: XSD limits time zone offsets to ±14:00.
_MAX_OFFSET_MIN = 14 * 60

#: xs:gYear, xs:date or xs:dateTime, each with an optional offset (Z, ±HH:MM; ±HHMM accepted).
_XSD_RE = re.compile(
    r"(?P<year>\d{4,})"
    r"(?:-(?P<month>\d{2})-(?P<day>\d{2})"
    r"(?:T(?P<hour>\d{2}):(?P<minute>\d{2}):(?P<second>\d{2})(?P<frac>\.\d+)?)?)?"
    r"(?P<tz>Z|[+-]\d{2}:?\d{2})?")
#: A user's date-time: like xs:dateTime, but seconds optional, 'T' or a space, and ±HH allowed.
_USER_DATETIME_RE = re.compile(
    r"(?P<year>\d{4,})-(?P<month>\d{2})-(?P<day>\d{2})[T ]"
    r"(?P<hour>\d{2}):(?P<minute>\d{2})(?::(?P<second>\d{2})(?P<frac>\.\d+)?)?"
    r"(?P<tz>Z|[+-]\d{2}(?::?\d{2})?)?")


def _offset_minutes(tz: str | None) -> int:
    """Minutes east of UTC of an offset text (``Z``, ``+01:00``, ``-0530``, ``+02``)."""
    if tz is None or tz == "Z":
        return 0
    digits = tz[1:].replace(":", "")
    hours = int(digits[:2])
    minutes = int(digits[2:]) if len(digits) > 2 else 0
    if minutes >= 60:
        raise ValueError(f"offset {tz!r} has {minutes} minutes")
    total = hours * 60 + minutes
    if total > _MAX_OFFSET_MIN:
        raise ValueError(f"offset {tz!r} is beyond ±14:00")
    return -total if tz[0] == "-" else total


def _days(year: int, month: int, day: int, seconds: int, frac_s: float,
          offset_min: int) -> float:
    """Days since the epoch of a local date and time at a UTC offset (calendar checked)."""
    day_count = date(year, month, day).toordinal() - _EPOCH_ORDINAL  # ValueError if invalid
    utc_seconds = seconds - offset_min * 60
    return day_count + (utc_seconds + frac_s) / _SECONDS_PER_DAY


@functools.lru_cache(maxsize=4096)  # files repeat the same few dates on thousands of objects
def _parse_xsd(text: str) -> float:
    match = _XSD_RE.fullmatch(text.strip())
    if match is None:
        raise ValueError(f"not an xs:date, xs:dateTime or xs:gYear: {text!r}")
    g = match.groupdict()
    year = int(g["year"])
    month = int(g["month"]) if g["month"] else 1
    day = int(g["day"]) if g["day"] else 1
    hour = int(g["hour"]) if g["hour"] else 0
    minute = int(g["minute"]) if g["minute"] else 0
    second = int(g["second"]) if g["second"] else 0
    frac_s = float(g["frac"]) if g["frac"] else 0.0
    if not 1 <= year <= 9999:
        raise ValueError(f"year {year} is outside 1..9999: {text!r}")
    # XSD allows 24:00:00 for the end of a day, i.e. the next day's midnight.
    end_of_day = hour == 24 and minute == 0 and second == 0 and frac_s == 0.0
    if not (hour < 24 or end_of_day) or minute >= 60 or second >= 60:
        raise ValueError(f"invalid time of day in {text!r}")
    try:
        return _days(year, month, day, hour * 3600 + minute * 60 + second, frac_s,
                     _offset_minutes(g["tz"]))
    except ValueError as exc:
        raise ValueError(f"invalid date {text!r}: {exc}") from None


def parse_xsd_datetime_days(text: str) -> float:
    """Days since 1970-01-01T00:00Z of an XSD date/time value as found in CityGML.

    Accepts ``xs:gYear`` (``'1850'``), ``xs:date`` (``'2008-12-09'``, ``'2008-12-09Z'``,
    ``'2008-12-09+01:00'``) and ``xs:dateTime`` (``'2017-01-23T00:00:00+01:00'``,
    ``'2015-09-24T00:00:00'``, fractional seconds, ``24:00:00``), with surrounding whitespace.
    Without an offset the value is UTC; a date or year with an offset is local midnight at that
    offset; a year alone is January 1, 00:00.

    Parameters
    ----------
    text : str
        The element's text.

    Returns
    -------
    float
        Days (proleptic Gregorian), e.g. 1.0 for ``'1970-01-02'``.

    Raises
    ------
    ValueError
        Not one of the forms above, an impossible date or time, a year outside 1..9999, an
        offset beyond ±14:00. (The reader turns this into a counted warning.)
    """
    if not isinstance(text, str):
        raise ValueError(f"date value must be text, not {type(text).__name__}")
    return _parse_xsd(text)


def datetime_to_days(dt: datetime) -> float:
    """Days since 1970-01-01T00:00Z of an aware :class:`~datetime.datetime`.

    Raises
    ------
    ValueError
        ``dt`` is naive (it has no UTC offset) or not a datetime.
    """
    if not isinstance(dt, datetime):
        raise ValueError(f"expected a datetime, not {type(dt).__name__}")
    offset = dt.utcoffset()
    if offset is None:
        raise ValueError(f"datetime {dt.isoformat()} is naive; give it a time zone")
    day_count = dt.date().toordinal() - _EPOCH_ORDINAL
    # Count in integer microseconds so whole days and seconds stay exact.
    local_us = ((dt.hour * 60 + dt.minute) * 60 + dt.second) * 1_000_000 + dt.microsecond
    utc_us = local_us - offset // timedelta(microseconds=1)
    return day_count + utc_us / _US_PER_DAY


def days_to_iso(days: float) -> str:
    """ISO 8601 text of a day count, for reports.

    Whole days are written as a date (``'2000-01-01'``), others as a UTC date-time rounded to
    the millisecond (``'2000-01-01T12:00:00Z'``, ``'…T12:00:00.250Z'``); ``±inf`` is
    ``'open'``.

    Raises
    ------
    ValueError
        NaN, or a day outside years 1..9999.
    """
    days = float(days)
    if math.isinf(days):
        return "open"
    if math.isnan(days):
        raise ValueError("day count is NaN")
    whole = math.floor(days)
    # Round to ms: float64 days carry ~5 µs of noise at year 3000.
    ms = round((days - whole) * _SECONDS_PER_DAY * 1000)
    if ms == _SECONDS_PER_DAY * 1000:
        whole, ms = whole + 1, 0
    try:
        day = date.fromordinal(_EPOCH_ORDINAL + whole)
    except (ValueError, OverflowError):
        raise ValueError(f"day {days} is outside years 1..9999") from None
    if ms == 0:
        return day.isoformat()
    seconds, ms_rest = divmod(ms, 1000)
    minutes, sec = divmod(seconds, 60)
    hour, minute = divmod(minutes, 60)
    text = f"{day.isoformat()}T{hour:02d}:{minute:02d}:{sec:02d}"
    return f"{text}.{ms_rest:03d}Z" if ms_rest else f"{text}Z"


# --- validity intervals of city objects -----------------------------------------------------

TIME_ATTRIBUTES = ("validFrom", "validTo", "yearOfConstruction", "yearOfDemolition",
                   "dateOfConstruction", "dateOfDemolition", "creationDate", "terminationDate")
#: Key prefix of generic attributes (``gen:stringAttribute name="baujahr"``) in the attribute
#: mapping of an object, so a generic "validFrom" never shadows the core one.
GENERIC_PREFIX = "generic:"

#: Families of attributes: (begin names, end names), each list in order of preference. The
#: CityGML 3 ``dateOf*`` (a full date) is preferred over the 2.0 ``yearOf*`` (a year).
_FAMILIES = {
    "valid": (("validFrom",), ("validTo",)),
    "construction": (("dateOfConstruction", "yearOfConstruction"),
                     ("dateOfDemolition", "yearOfDemolition")),
    "creation": (("creationDate",), ("terminationDate",)),
}
#: Order in which ``source='auto'`` tries the families (docs/DESIGN.md §1). ``creationDate`` and
#: ``terminationDate`` are database times (CityGML 2.0 §6.1, 3.0 Core: when the feature was
#: entered into or removed from the database), not the life of a building: 3DCityDB stamps
#: the import day on every object, so only ``source='creation'`` uses them.
TIME_SOURCES_ORDER = ("valid", "construction", "attribute")
#: Every source a user can name.
TIME_SOURCES = ("valid", "construction", "attribute", "creation")
#: A year written as a number by a generic int or double attribute: ``1905``, ``1905.0``.
_NUMERIC_YEAR_RE = re.compile(r"(\d{4})(?:\.0*)?")


def parse_time_attribute(text: str) -> tuple[str, str | None]:
    """``--time-attribute begin=NAME[,end=NAME]`` → (begin name, end name or None).

    Raises
    ------
    UsageError
        Not of that form (an unknown key, a key twice, an empty name, no ``begin``).
    """
    if not isinstance(text, str):
        raise UsageError(f"--time-attribute must be text, not {type(text).__name__}")
    names: dict[str, str] = {}
    for part in text.split(","):
        key, sep, name = part.partition("=")
        key, name = key.strip(), name.strip()
        if not sep or key not in ("begin", "end") or not name or key in names:
            raise UsageError(f"--time-attribute must be begin=NAME[,end=NAME] (generic "
                             f"attribute names, e.g. begin=baujahr), not {text!r}")
        names[key] = name
    if "begin" not in names:
        raise UsageError(f"--time-attribute needs begin=NAME, not {text!r}")
    return names["begin"], names.get("end")


def parse_time_attribute_value(raw: str) -> float:
    """Days of a generic attribute's year or date (``1905``, ``1905.0``, ``1905-03-01``)."""
    match = _NUMERIC_YEAR_RE.fullmatch(raw.strip())
    if match:
        return parse_xsd_datetime_days(match.group(1))
    return parse_xsd_datetime_days(raw)


class Interval(NamedTuple):
    """Validity interval ``[begin_days, end_days)`` of one city object.

    Attributes
    ----------
    begin_days, end_days : float
        Days since 1970-01-01T00:00Z; ``-inf``/``+inf`` for open ends.
    source : str
        Family used: ``'valid'``, ``'construction'``, ``'creation'`` or ``'none'``.
    bad_values : tuple of str
        ``"name='text'"`` of every unparseable value met (ignored, to be counted by the
        reader).
    """

    begin_days: float
    end_days: float
    source: str
    bad_values: tuple[str, ...]

    @property
    def never_exists(self) -> bool:
        """True when ``end <= begin``: the object exists at no time (the reader counts it)."""
        return self.end_days <= self.begin_days

    def contains(self, days: float) -> bool:
        """Whether the object stands at time ``days`` (half-open interval)."""
        return self.begin_days <= days < self.end_days


def _first_value(attrs: Mapping[str, str], names: tuple[str, ...],
                 bad: list[str], parse=parse_xsd_datetime_days) -> float | None:
    """Days of the first parseable, non-empty value among ``names``; bad ones go to ``bad``."""
    for name in names:
        raw = attrs.get(name)
        if raw is None or not str(raw).strip():
            continue  # absent or empty (e.g. CityJSON's terminationDate "") means unknown
        try:
            return parse(str(raw))
        except ValueError:
            bad.append(f"{name}={raw!r}")
    return None


def choose_interval(attrs: Mapping[str, str], source: str,
                    time_attribute: tuple[str, str | None] | None = None) -> Interval:
    """Validity interval of one city object from its time attributes.

    Parameters
    ----------
    attrs : mapping of str to str
        Local attribute names (those of :data:`TIME_ATTRIBUTES`; others are ignored) to their
        raw text, for ONE city object; generic attributes under ``GENERIC_PREFIX + name``.
    source : str
        ``'valid'`` (``validFrom``/``validTo``), ``'construction'`` (``dateOf*``, else
        ``yearOf*``; a year Y means Y-01-01 for both ends, so a building demolished in 2021
        does not stand at ``--date 2021``), ``'attribute'`` (the generic attributes named by
        ``time_attribute``: years, also written ``1905.0``, or dates), ``'creation'``
        (``creationDate``/``terminationDate``: database times, used only when asked for), or
        ``'auto'``: the first family, in the order valid → construction → attribute, that has
        a parseable begin or end.
    time_attribute : (begin name, end name or None), optional
        From :func:`parse_time_attribute`; without it the ``'attribute'`` family is empty.

    Returns
    -------
    Interval
        Missing ends are open; ``source`` is ``'none'`` when the chosen family (or, for
        ``'auto'``, every family) has no usable value, giving ``(-inf, inf)``. Unparseable
        values are skipped and listed in ``bad_values`` (for ``'auto'``: those of the families
        tried). When ``end <= begin`` the values are kept as they are and
        :attr:`Interval.never_exists` is True; the reader counts such objects.

    Raises
    ------
    UsageError
        Unknown ``source``.
    """
    if source == "auto":
        families = TIME_SOURCES_ORDER
    elif source in TIME_SOURCES:
        families = (source,)
    else:
        raise UsageError(f"unknown time source {source!r}; valid: auto, "
                         f"{', '.join(TIME_SOURCES)}")
    bad: list[str] = []
    for family in families:
        parse = parse_xsd_datetime_days
        if family == "attribute":
            if time_attribute is None:
                continue
            begin_names = (GENERIC_PREFIX + time_attribute[0],)
            end_names = (GENERIC_PREFIX + time_attribute[1],) if time_attribute[1] else ()
            parse = parse_time_attribute_value
        else:
            begin_names, end_names = _FAMILIES[family]
        begin = _first_value(attrs, begin_names, bad, parse)
        end = _first_value(attrs, end_names, bad, parse)
        if begin is not None or end is not None:
            return Interval(DAYS_OPEN_BEGIN if begin is None else begin,
                            DAYS_OPEN_END if end is None else end, family, tuple(bad))
    return Interval(DAYS_OPEN_BEGIN, DAYS_OPEN_END, "none", tuple(bad))


def has_creation_dates(attrs: Mapping[str, str]) -> bool:
    """Whether an object carries a (non-empty) ``creationDate`` or ``terminationDate``."""
    return any(str(attrs.get(n) or "").strip() for n in ("creationDate", "terminationDate"))


# --- the user's --date ----------------------------------------------------------------------

class UserDate(NamedTuple):
    """A parsed ``--date``.

    Attributes
    ----------
    city_days : float
        The time at which the city is shown (days since 1970-01-01T00:00Z).
    instant_utc : datetime or None
        The sun's instant as an aware UTC datetime; None when only a year or a date was given.
    text : str
        The text as given.
    warnings : tuple of str
        E.g. the zone resolved to the tz database's local mean time (:func:`lmt_warning`).
    """

    city_days: float
    instant_utc: datetime | None
    text: str
    warnings: tuple[str, ...] = ()


#: ``--tz`` names of solar time at the model's own longitude (:mod:`cityshade.geo.sun`).
SOLAR_TIME_ZONES = ("local-mean", "local-apparent")


def lmt_warning(zone, local: datetime, tz_name: str | None = None) -> str | None:
    """A warning when ``zone`` gives the tz database's local mean time (LMT) at ``local``.

    Before standard time the tz database gives each zone the mean time of its reference city
    (Europe/Berlin in 1850: +0:53:28, Berlin's), which is not the mean time of a model
    elsewhere in the zone (Munich: +0:46:16): "15:00" then puts the sun ~1.8° off.
    """
    aware = local if local.tzinfo is not None else local.replace(tzinfo=zone)
    if aware.tzname() != "LMT":
        return None
    offset = aware.utcoffset()
    total_s = round(offset.total_seconds())
    sign, total_s = ("+" if total_s >= 0 else "-"), abs(total_s)
    text = f"{sign}{total_s // 3600}:{total_s // 60 % 60:02d}:{total_s % 60:02d}"
    name = tz_name or str(zone)
    return (f"{name} on {aware.date().isoformat()} is the tz database's local mean time "
            f"(LMT {text}, the mean time of the zone's reference city), not the model's own; "
            f"for historical local time give --tz local-mean (mean solar time at the model's "
            f"longitude) or --tz local-apparent (true solar time)")


_DATE_FORMS = ("YYYY, YYYY-MM-DD, or YYYY-MM-DDTHH:MM[:SS][Z|±HH:MM] "
               "(e.g. 1850, 1850-06-21, 1850-06-21T15:00+01:00)")


def zone_info(tz):
    """tzinfo of ``--tz``: an IANA name (unknown names are a UsageError), or a tzinfo given as
    is (solar time of a model)."""
    from datetime import tzinfo
    from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

    if isinstance(tz, tzinfo):
        return tz
    if tz in SOLAR_TIME_ZONES:
        raise UsageError(f"--tz {tz} is solar time at the model's longitude; it needs the "
                         f"model (the render, batch and evaluate commands resolve it)")
    try:
        return ZoneInfo(tz)
    except (ZoneInfoNotFoundError, ValueError):
        raise UsageError(f"unknown time zone {tz!r}; give an IANA name such as "
                         f"Europe/Berlin") from None


_LEADING_YEAR = re.compile(r"\s*([+-]?\d+)(?:-\d|\s*$)")


def check_year_range(text: str, what: str = "date") -> None:
    """A date whose year is a number outside 1..9999 (``99999``, ``0``, ``-5``,
    ``10000-01-01``) is out of range, not unreadable: say so.

    Raises
    ------
    UsageError
    """
    match = _LEADING_YEAR.match(text)
    if match and not 1 <= int(match.group(1)) <= 9999:
        raise UsageError(f"{what} {text.strip()!r} is out of range (years 1 to 9999 are "
                         f"supported)")


def parse_user_date(text: str, tz: str | None = None) -> UserDate:
    """Parse ``--date`` into the state of the city and, when a time is given, the sun's instant.

    * ``'1850'`` → the city on 1850-01-01 00:00 UTC, no instant;
    * ``'1850-06-21'`` → the city that day 00:00 UTC, no instant;
    * ``'1850-06-21T15:00+01:00'`` (or ``Z``, ``±HHMM``, ``±HH``; seconds optional; a space
      instead of ``T``) → an aware instant, and the city at that instant;
    * ``'1850-06-21T15:00'`` without offset → local time in ``tz`` (an IANA name, resolved with
      :mod:`zoneinfo`, so daylight saving time and historical local mean times apply, the
      latter with a warning, :func:`lmt_warning`); an explicit offset in the text wins over
      ``tz``.

    Parameters
    ----------
    text : str
        The option's value.
    tz : str or tzinfo, optional
        IANA time zone name (``--tz``), or a tzinfo such as
        :func:`cityshade.geo.sun.solar_time_zone` of ``--tz local-mean|local-apparent``.

    Returns
    -------
    UserDate

    Raises
    ------
    UsageError
        Text in none of the forms, impossible date, a time without offset and without ``tz``,
        an unknown ``tz``, or a local time that does not exist in ``tz`` (skipped by a
        daylight-saving change). An ambiguous local time (repeated by the change back) takes
        its first occurrence.
    """
    if not isinstance(text, str):
        raise UsageError(f"date must be text, not {type(text).__name__}")
    check_year_range(text)
    zone = zone_info(tz) if tz is not None else None
    stripped = text.strip()
    match = _USER_DATETIME_RE.fullmatch(stripped)
    if match is None:
        # Take a year or a date (optionally with an offset) as a city state only.
        try:
            return UserDate(parse_xsd_datetime_days(stripped), None, text)
        except ValueError:
            raise UsageError(f"cannot read date {text!r}; use {_DATE_FORMS}") from None
    g = match.groupdict()
    frac = (g["frac"] or "")[1:7].ljust(6, "0")  # datetime keeps microseconds
    try:
        naive = datetime(int(g["year"]), int(g["month"]), int(g["day"]), int(g["hour"]),
                         int(g["minute"]), int(g["second"] or 0), int(frac))
        offset_text = g["tz"]
        if offset_text is not None:
            tzinfo = timezone(timedelta(minutes=_offset_minutes(offset_text)))
        elif zone is not None:
            tzinfo = zone
        else:
            raise UsageError(f"date {text!r} has no UTC offset; add one (e.g. +01:00 or Z) "
                             f"or give --tz ZONE")
        aware = naive.replace(tzinfo=tzinfo)
        instant_utc = aware.astimezone(timezone.utc)
        # Map back: a local time skipped by a DST change does not survive the round trip
        # (solar time has no such gaps: only IANA zones are checked).
        skipped = (offset_text is None and isinstance(tz, str)
                   and instant_utc.astimezone(zone).replace(tzinfo=None) != naive)
    except (ValueError, OverflowError) as exc:
        raise UsageError(f"cannot read date {text!r}: {exc}; use {_DATE_FORMS}") from None
    if skipped:
        raise UsageError(f"local time {stripped} does not exist in {tz} (skipped by a "
                         f"daylight-saving change); give a UTC offset")
    warning = lmt_warning(zone, aware, tz) if offset_text is None else None
    return UserDate(datetime_to_days(aware), instant_utc, text,
                    (warning,) if warning else ())
