"""Tests of cityshade.geo.temporal: XSD values to days, intervals, --date."""
from __future__ import annotations

import math
from datetime import datetime, timedelta, timezone
from zoneinfo import ZoneInfo

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cityshade.geo.temporal import (
    DAYS_OPEN_BEGIN, DAYS_OPEN_END, TIME_ATTRIBUTES, Interval, choose_interval, datetime_to_days,
    days_to_iso, parse_user_date, parse_xsd_datetime_days,
)
from cityshade.errors import UsageError
from conftest import shared_file


def _is_leap(year: int) -> bool:
    return year % 4 == 0 and (year % 100 != 0 or year % 400 == 0)


def _days_by_counting(year: int, month: int, day: int) -> int:
    """Days from 1970-01-01 to a date by summing year and month lengths (no datetime)."""
    month_days = [31, 29 if _is_leap(year) else 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
    within = sum(month_days[:month - 1]) + day - 1
    if year >= 1970:
        return sum(366 if _is_leap(y) else 365 for y in range(1970, year)) + within
    return within - sum(366 if _is_leap(y) else 365 for y in range(year, 1970))


def test_counting_helper_against_known_values():
    # 2000-01-01T00:00Z is POSIX time 946684800 s = 10957 days.
    assert _days_by_counting(2000, 1, 1) == 946_684_800 // 86_400 == 10957
    assert _days_by_counting(1969, 12, 31) == -1
    # 1700..1969: 270 years, 65 leap years (68 multiples of 4 minus 1700, 1800, 1900).
    assert _days_by_counting(1700, 1, 1) == -(270 * 365 + 65) == -98615


H = 1.0 / 24.0

XSD_CASES = [
    ("1970-01-01", 0.0),
    ("1970-01-02", 1.0),
    ("2000-01-01", 10957.0),
    ("1700-01-01", -98615.0),
    ("1850", _days_by_counting(1850, 1, 1)),
    ("2008-12-09", _days_by_counting(2008, 12, 9)),
    ("2008-12-09Z", _days_by_counting(2008, 12, 9)),
    # Local midnight at +01:00 is 23:00 UTC the day before.
    ("2008-12-09+01:00", _days_by_counting(2008, 12, 9) - H),
    ("2008-12-09-05:30", _days_by_counting(2008, 12, 9) + 5.5 * H),
    ("2017-01-23T00:00:00+01:00", _days_by_counting(2017, 1, 23) - H),
    ("2015-09-24T00:00:00", _days_by_counting(2015, 9, 24)),
    ("2025-01-02T00:00:00+01:00", _days_by_counting(2025, 1, 2) - H),
    ("2000-01-01T12:00:00", 10957.5),
    ("2000-01-01T06:00:00.5Z", 10957.25 + 0.5 / 86400),
    ("2000-01-01T00:00:00.125-01:00", 10957.0 + H + 0.125 / 86400),
    ("1999-12-31T24:00:00", 10957.0),               # XSD end of day = next midnight
    ("  2015-03-11\n", _days_by_counting(2015, 3, 11)),
    ("2000-02-29", _days_by_counting(2000, 2, 29)),  # 2000 is a leap year (÷400)
    ("1000", _days_by_counting(1000, 1, 1)),
    ("1000-03-01", _days_by_counting(1000, 3, 1)),  # proleptic Gregorian: 1000 not leap
    ("3000-12-31T23:59:59Z", _days_by_counting(3000, 12, 31) + 86399 / 86400),
    ("1850+02:00", _days_by_counting(1850, 1, 1) - 2 * H),
]


@pytest.mark.parametrize("text, expected", XSD_CASES)
def test_parse_xsd_datetime_days(text, expected):
    assert parse_xsd_datetime_days(text) == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize("text", [
    "", "   ", "abc", "2001-02-29", "1900-02-29", "2008-13-01", "2008-12-32", "0000",
    "2000-01-01T25:00:00", "2000-01-01T24:00:01", "2000-01-01T12:60:00", "2000-01-01T12:00:60",
    "2000-01-01T12:00", "2000-01-01+15:00", "2000-01-01+01:60", "2008-12", "-1850",
    "2000/01/01", "12.03.2015", "2000-01-01T",
])
def test_invalid_xsd_values_raise_value_error(text):
    with pytest.raises(ValueError):
        parse_xsd_datetime_days(text)


@settings(max_examples=200, deadline=None)
@given(st.dates(min_value=datetime(1000, 1, 1).date(), max_value=datetime(3000, 12, 31).date()),
       st.integers(0, 86399), st.integers(-14 * 60, 14 * 60))
def test_parse_matches_counting(day, seconds, offset_min):
    sign = "-" if offset_min < 0 else "+"
    hh, mm = divmod(abs(offset_min), 60)
    h, rest = divmod(seconds, 3600)
    text = f"{day.isoformat()}T{h:02d}:{rest // 60:02d}:{rest % 60:02d}{sign}{hh:02d}:{mm:02d}"
    expected = _days_by_counting(day.year, day.month, day.day) + \
        (seconds - offset_min * 60) / 86400
    assert parse_xsd_datetime_days(text) == pytest.approx(expected, abs=1e-9)


def test_days_to_iso():
    assert days_to_iso(0.0) == "1970-01-01"
    assert days_to_iso(10957.5) == "2000-01-01T12:00:00Z"
    assert days_to_iso(-0.25) == "1969-12-31T18:00:00Z"
    assert days_to_iso(parse_xsd_datetime_days("2000-01-01T06:00:00.25Z")) == \
        "2000-01-01T06:00:00.250Z"
    assert days_to_iso(parse_xsd_datetime_days("1000-01-01")) == "1000-01-01"
    assert days_to_iso(parse_xsd_datetime_days("3000-06-01T10:30:00+02:00")) == \
        "3000-06-01T08:30:00Z"
    assert days_to_iso(DAYS_OPEN_BEGIN) == days_to_iso(DAYS_OPEN_END) == "open"
    with pytest.raises(ValueError):
        days_to_iso(math.nan)
    with pytest.raises(ValueError):
        days_to_iso(1e9)


def test_datetime_to_days():
    assert datetime_to_days(datetime(1970, 1, 2, tzinfo=timezone.utc)) == 1.0
    assert datetime_to_days(datetime(2000, 1, 1, 1, tzinfo=timezone(timedelta(hours=1)))) \
        == 10957.0
    berlin = ZoneInfo("Europe/Berlin")
    assert datetime_to_days(datetime(2024, 6, 21, 12, tzinfo=berlin)) == pytest.approx(
        _days_by_counting(2024, 6, 21) + 10 * H, abs=1e-9)
    assert datetime_to_days(datetime(1000, 1, 1, tzinfo=timezone.utc)) == \
        _days_by_counting(1000, 1, 1)
    with pytest.raises(ValueError, match="naive"):
        datetime_to_days(datetime(2000, 1, 1))
    with pytest.raises(ValueError):
        datetime_to_days("2000-01-01")


# --- choose_interval ------------------------------------------------------------------------

ALL_FAMILIES = {
    "validFrom": "2001-01-01", "validTo": "2002-01-01",
    "yearOfConstruction": "1901", "yearOfDemolition": "2021",
    "creationDate": "2010-01-01", "terminationDate": "2011-01-01",
}
D = _days_by_counting


@pytest.mark.parametrize("source, expected", [
    ("valid", (D(2001, 1, 1), D(2002, 1, 1), "valid")),
    ("construction", (D(1901, 1, 1), D(2021, 1, 1), "construction")),
    ("creation", (D(2010, 1, 1), D(2011, 1, 1), "creation")),
    ("auto", (D(2001, 1, 1), D(2002, 1, 1), "valid")),
])
def test_choose_interval_each_source(source, expected):
    got = choose_interval(ALL_FAMILIES, source)
    assert (got.begin_days, got.end_days, got.source) == expected and got.bad_values == ()


def test_choose_interval_auto_order():
    no_valid = {k: v for k, v in ALL_FAMILIES.items() if not k.startswith("valid")}
    assert choose_interval(no_valid, "auto").source == "construction"
    # creationDate is a database time (issue 13): auto never takes it, creation does.
    only_creation = {"creationDate": "2010-01-01"}
    assert choose_interval(only_creation, "auto") == Interval(-math.inf, math.inf, "none", ())
    got = choose_interval(only_creation, "creation")
    assert got == Interval(D(2010, 1, 1), DAYS_OPEN_END, "creation", ())
    # An end alone is enough to select a family; the begin is then open.
    got = choose_interval({"validTo": "1990-01-01", "creationDate": "2010-01-01"}, "auto")
    assert got == Interval(DAYS_OPEN_BEGIN, D(1990, 1, 1), "valid", ())


def test_choose_interval_none_and_missing_family():
    assert choose_interval({}, "auto") == Interval(-math.inf, math.inf, "none", ())
    assert choose_interval({"creationDate": "2010-01-01"}, "valid").source == "none"
    # Empty values (CityJSON writes terminationDate "") are unknown, not bad.
    got = choose_interval({"creationDate": "2010-01-01", "terminationDate": ""}, "creation")
    assert got.end_days == DAYS_OPEN_END and got.bad_values == ()
    # Other attributes are ignored.
    assert choose_interval({"function": "1000", "name": "x"}, "auto").source == "none"


def test_construction_year_is_january_first_for_both_ends():
    got = choose_interval({"yearOfConstruction": "1950", "yearOfDemolition": "2021"},
                          "construction")
    assert not got.contains(parse_user_date("2021").city_days)   # demolished in 2021
    assert got.contains(parse_user_date("2020-12-31T23:59Z").city_days)
    assert got.contains(parse_user_date("1950").city_days)       # stands from 1950-01-01
    assert not got.contains(parse_user_date("1949-12-31").city_days)
    # CityGML 3 dateOf* wins over the 2.0 yearOf* when both are given.
    both = {"dateOfConstruction": "1950-06-15", "yearOfConstruction": "1950"}
    assert choose_interval(both, "construction").begin_days == D(1950, 6, 15)


def test_choose_interval_bad_values_are_reported_and_skipped():
    got = choose_interval({"validFrom": "someday", "yearOfConstruction": "1850",
                           "dateOfConstruction": "1850-02-30"}, "auto")
    assert got.source == "construction" and got.begin_days == D(1850, 1, 1)
    assert got.bad_values == ("validFrom='someday'", "dateOfConstruction='1850-02-30'")
    got = choose_interval({"creationDate": "nope"}, "creation")
    assert got == Interval(-math.inf, math.inf, "none", ("creationDate='nope'",))


def test_interval_that_never_exists_is_kept():
    got = choose_interval({"creationDate": "2015-01-01", "terminationDate": "2000-01-01"},
                          "creation")
    assert (got.begin_days, got.end_days) == (D(2015, 1, 1), D(2000, 1, 1))
    assert got.never_exists and not got.contains(D(2010, 1, 1))
    same = choose_interval({"creationDate": "1967-08-13", "terminationDate": "1967-08-13"},
                           "creation")
    assert same.never_exists
    assert not choose_interval(ALL_FAMILIES, "auto").never_exists


def test_choose_interval_unknown_source():
    with pytest.raises(UsageError, match="auto, valid, construction, attribute, creation"):
        choose_interval({}, "demolition")


def test_time_attributes_are_the_families_names():
    assert set(TIME_ATTRIBUTES) == set(ALL_FAMILIES) | {"dateOfConstruction",
                                                        "dateOfDemolition"}


def test_lyon_versioning_example(shared_data):
    from lxml import etree
    path = shared_file("ogc-citygml3-versioning-lyon/"
                       "historicalSuccession_CityGML_3.0_LOD2_Versioning.gml")
    gml_id = "{http://www.opengis.net/gml/3.2}id"
    intervals = {}
    for building in etree.parse(str(path)).iter("{http://www.opengis.net/citygml/building/3.0}"
                                                "Building"):
        attrs = {etree.QName(child).localname: child.text for child in building
                 if isinstance(child.tag, str)
                 and etree.QName(child).localname in TIME_ATTRIBUTES}
        # The versioning module's dates are creationDate/terminationDate: database times,
        # which only --time-source creation uses (auto leaves them open, with a warning).
        assert choose_interval(attrs, "auto").source == "none"
        intervals[building.get(gml_id)] = choose_interval(attrs, "creation")
    assert len(intervals) == 4
    old = intervals["BU_69381AL47_2000-01-01"]
    assert (old.begin_days, old.end_days, old.source) == (D(2000, 1, 1), D(2015, 1, 1),
                                                          "creation")
    at_2010 = parse_user_date("2010-01-01").city_days
    at_2016 = parse_user_date("2016-01-01").city_days
    assert old.contains(at_2010) and not old.contains(at_2016)
    # The replacement of AL49 and the inserted AL50 stand from 2015 on, with no end.
    for gid in ("BU_69381AL49_2015-01-01", "BU_69381AL50_2015-01-01"):
        new = intervals[gid]
        assert (new.begin_days, new.end_days) == (D(2015, 1, 1), DAYS_OPEN_END)
        assert new.contains(at_2016) and not new.contains(at_2010)
    # Exactly one version of AL49 stands at any date.
    al49 = [intervals["BU_69381AL49_2000-01-01"], intervals["BU_69381AL49_2015-01-01"]]
    for day in (at_2010, D(2015, 1, 1), at_2016):
        assert sum(i.contains(day) for i in al49) == 1


# --- parse_user_date ------------------------------------------------------------------------

def test_user_date_year_and_date_give_city_state_only():
    got = parse_user_date("1850")
    assert (got.city_days, got.instant_utc, got.text) == (D(1850, 1, 1), None, "1850")
    got = parse_user_date("1850-06-21", tz="Europe/Berlin")
    assert (got.city_days, got.instant_utc) == (D(1850, 6, 21), None)


def test_user_date_with_offset():
    got = parse_user_date("1850-06-21T15:00+01:00")
    assert got.instant_utc == datetime(1850, 6, 21, 14, 0, tzinfo=timezone.utc)
    assert got.instant_utc.utcoffset() == timedelta(0)
    assert got.city_days == pytest.approx(D(1850, 6, 21) + 14 * H, abs=1e-9)
    for text in ("2024-06-21T10:00Z", "2024-06-21T10:00:00Z", "2024-06-21 12:00+02:00",
                 "2024-06-21T12:00+0200", "2024-06-21T12:00+02",
                 "2024-06-21T05:30:00.000-04:30"):
        assert parse_user_date(text).instant_utc == datetime(2024, 6, 21, 10,
                                                             tzinfo=timezone.utc), text


def test_user_date_without_offset_needs_tz():
    with pytest.raises(UsageError, match="has no UTC offset; add one .*--tz ZONE"):
        parse_user_date("1850-06-21T15:00")


def test_user_date_tz_with_and_without_daylight_saving():
    summer = parse_user_date("2024-06-21T12:00", tz="Europe/Berlin")
    winter = parse_user_date("2024-12-21T12:00", tz="Europe/Berlin")
    assert summer.instant_utc.hour == 10 and winter.instant_utc.hour == 11
    assert summer.city_days == pytest.approx(D(2024, 6, 21) + 10 * H, abs=1e-9)
    # An explicit offset wins over --tz.
    assert parse_user_date("2024-06-21T12:00Z", tz="Europe/Berlin").instant_utc.hour == 12
    # 02:30 on 2024-03-31 was skipped in Berlin (clocks jumped from 02:00 to 03:00).
    with pytest.raises(UsageError, match="does not exist"):
        parse_user_date("2024-03-31T02:30", tz="Europe/Berlin")
    # 02:30 on 2024-10-27 happened twice: the first (summer time, +02:00) is taken.
    assert parse_user_date("2024-10-27T02:30", tz="Europe/Berlin").instant_utc.hour == 0


def test_user_date_years_1000_and_3000():
    got = parse_user_date("1000-06-21T12:00Z")
    assert got.city_days == pytest.approx(D(1000, 6, 21) + 0.5, abs=1e-9)
    got = parse_user_date("3000-06-21T12:00+01:00")
    assert got.city_days == pytest.approx(D(3000, 6, 21) + 11 * H, abs=1e-9)
    assert parse_user_date("1000").city_days == D(1000, 1, 1)
    assert parse_user_date("3000").city_days == D(3000, 1, 1)


@pytest.mark.parametrize("text, tz", [
    ("yesterday", None), ("1850-06-31", None), ("1850-06-21T25:00Z", None),
    ("1850-06-21T15", None), ("2024-01-01T00:00", "Mars/Olympus_Mons"),
    ("2024-01-01", "Not/AZone"), ("", None),
])
def test_user_date_errors(text, tz):
    with pytest.raises(UsageError):
        parse_user_date(text, tz=tz)
