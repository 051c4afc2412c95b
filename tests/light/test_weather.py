"""Weather files through pvlib: location, hour convention, sunny hours, garbled copies."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from cityshade.errors import UsageError, WeatherFileError
from cityshade.light.weather import location_warning, read_weather

WEATHER = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "weather"
LONDON = WEATHER / "GBR_ENG_London.City.AP.037683_TMYx.2007-2021.epw"


def _pvlib_data(name: str) -> Path:
    import pvlib

    return Path(pvlib.__file__).parent / "data" / name


@pytest.fixture
def london() -> Path:
    if not LONDON.is_file():
        pytest.skip(f"real data not available: {LONDON} is absent")
    return LONDON


def _epw_records(path):
    """The data records of an EPW file, read with the csv module (8 header lines)."""
    with open(path, newline="") as f:
        return list(csv.reader(f))[8:]


def test_london_epw_reads_with_its_location_and_hours(london):
    w = read_weather(london)
    assert w.kind == "epw" and w.n_hours == 8760
    loc = w.location
    assert (loc.latitude_deg, loc.longitude_deg, loc.elevation_m, loc.utc_offset_h) == \
        (51.505, 0.055, 5.8, 0.0)
    assert loc.name == "London.City.AP"
    records = _epw_records(london)
    # EPW hour 1 of 1 January is the hour ending 01:00 local standard time; its sun is at 00:30.
    year, month, day, hour = (int(v) for v in records[0][:4])
    assert (year, month, day, hour) == (2015, 1, 1, 1)
    first_end = w.hour_end[0]
    assert (first_end.year, first_end.month, first_end.day, first_end.hour, first_end.minute) \
        == (2015, 1, 1, 1, 0)
    assert first_end.utcoffset().total_seconds() == 0.0
    sun = w.sun_times[0]
    assert (sun.day, sun.hour, sun.minute) == (1, 0, 30)
    # The last record (31 December, hour 24) ends at midnight; its sun is at 23:30.
    assert (w.sun_times[-1].month, w.sun_times[-1].day, w.sun_times[-1].hour,
            w.sun_times[-1].minute) == (12, 31, 23, 30)
    # Every record's sun is half an hour before its end.
    assert ((w.hour_end - w.sun_times).total_seconds() == 1800).all()


def test_sunny_hours_count_the_dni_column(london):
    """Sunny hour = DNI >= 120 W/m² (WMO), counted here from the file's 15th field."""
    dni = np.array([float(r[14]) for r in _epw_records(london)])
    expected = int((dni >= 120.0).sum())
    w = read_weather(london)
    assert int(w.sunny().sum()) == expected
    assert 500 < expected < 3000
    np.testing.assert_array_equal(w.dni_w_m2, dni)
    assert int(w.sunny(200.0).sum()) == int((dni >= 200.0).sum())


def _garbled(tmp_path, source, line_no, edit, name="garbled.epw"):
    lines = Path(source).read_text().splitlines(keepends=True)
    lines[line_no - 1] = edit(lines[line_no - 1])
    out = tmp_path / name
    out.write_text("".join(lines))
    return out


def _cut_field(line, k=14):
    fields = line.rstrip("\r\n").split(",")
    return ",".join(fields[:k] + fields[k + 1:]) + "\n"


def _non_number(line, k=14):
    fields = line.rstrip("\r\n").split(",")
    fields[k] = "abc"
    return ",".join(fields) + "\n"


@pytest.mark.parametrize("edit,words", [(_cut_field, "fewer than the 35 fields"),
                                        (_non_number, "'abc'")])
def test_garbled_epw_names_the_file_and_line(london, tmp_path, edit, words):
    bad = _garbled(tmp_path, london, 1000, edit)
    with pytest.raises(WeatherFileError) as err:
        read_weather(bad)
    assert err.value.path == str(bad) and err.value.line == 1000
    assert words in str(err.value) and str(bad) in str(err.value)


def test_missing_value_code_and_missing_file(london, tmp_path):
    def missing(line):
        fields = line.rstrip("\r\n").split(",")
        fields[14] = "9999"
        return ",".join(fields) + "\n"

    bad = _garbled(tmp_path, london, 500, missing)
    with pytest.raises(WeatherFileError, match="9999") as err:
        read_weather(bad)
    assert err.value.line == 500
    with pytest.raises(WeatherFileError, match="no such weather file"):
        read_weather(tmp_path / "none.epw")
    with pytest.raises(UsageError, match="not a known weather file"):
        read_weather(tmp_path / "weather.txt")
    # A file that is not an EPW at all: pvlib's own failure, with the file named.
    junk = tmp_path / "junk.epw"
    junk.write_text("LOCATION,nowhere\nnot,a,weather,file\n")
    with pytest.raises(WeatherFileError) as err:
        read_weather(junk)
    assert err.value.path == str(junk)


def test_pvlib_tmy3_and_tmy2_files():
    tmy3 = _pvlib_data("723170TYA.CSV")
    w = read_weather(tmy3)
    with open(tmy3, newline="") as f:
        rows = list(csv.reader(f))
    station = rows[0]
    assert w.kind == "tmy3" and w.n_hours == len(rows) - 2 == 8760
    assert (w.location.latitude_deg, w.location.longitude_deg, w.location.utc_offset_h) == \
        (float(station[4]), float(station[5]), float(station[3]))
    # TMY3 "01:00" on the first date is the hour ending 01:00; its sun is at 00:30.
    assert rows[2][1] == "01:00"
    assert (w.hour_end[0].hour, w.sun_times[0].hour, w.sun_times[0].minute) == (1, 0, 30)
    dni_col = rows[1].index("DNI (W/m^2)")
    assert int(w.sunny().sum()) == sum(float(r[dni_col]) >= 120.0 for r in rows[2:])

    tmy2 = _pvlib_data("12839.tm2")
    w2 = read_weather(tmy2)
    assert w2.kind == "tmy2" and w2.n_hours == 8760
    assert w2.location.latitude_deg == pytest.approx(25 + 48 / 60)
    assert w2.location.longitude_deg == pytest.approx(-(80 + 16 / 60))
    assert (w2.hour_end[0].hour, w2.sun_times[0].hour, w2.sun_times[0].minute) == (1, 0, 30)
    # TMY2 columns: DNI is the 4 digits at characters 24-27 (1-based) of each record.
    records = Path(tmy2).read_text().splitlines()[1:]
    assert int(w2.sunny().sum()) == sum(int(r[23:27]) >= 120 for r in records)


def test_location_warning_past_the_distance(london):
    w = read_weather(london)
    assert location_warning(w, 51.5007, -0.1246) is None          # Westminster, 12 km
    msg = location_warning(w, 48.1496, 11.5680)                   # Munich
    assert msg is not None and "km from the model" in msg and "London.City.AP" in msg
    km = int(msg.split(" km from")[0].rsplit(" ", 1)[1])
    assert 900 < km < 1000                                        # London–Munich ≈ 940 km
