"""Sun positions from date, time and place: NREL SPA through pvlib, ΔT, time zones, grid north."""
from __future__ import annotations

import math
import subprocess
import sys
from datetime import datetime, timedelta, timezone

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city
from conftest import REPO

from cityshade.geo.crs import parse_srs_name
from cityshade.geo.temporal import parse_user_date
from cityshade.errors import CRSError, UsageError
from cityshade.geo.sun import (SpaSettings, delta_t_seconds, direction_from_angles, spa_angles,
                           sun_from_instant, suns_from_instants, unix_seconds)

UTM32 = parse_srs_name("EPSG:25832")
#: Munich (Marienplatz) in EPSG:25832, 520 m above sea level.
MUNICH = np.array([691_000.0, 5_334_000.0, 520.0])


def test_spa_paper_example():
    """Reda & Andreas (2004), SPA paper Table A5.1: 2003-10-17 12:30:30 at −7 h, 39.742476° N,
    105.1786° W, 1830.14 m, 820 mbar, 11 °C, ΔT 67 s → topocentric zenith 50.11162°, azimuth
    194.34024°. Tolerance 1e-4° (the paper's printed precision is 1e-5°)."""
    instant = datetime(2003, 10, 17, 12, 30, 30, tzinfo=timezone(timedelta(hours=-7)))
    az, el = spa_angles([unix_seconds(instant)], 39.742476, -105.1786, 1830.14, 67.0,
                        pressure_hpa=820.0, temperature_c=11.0)
    assert 90.0 - el[0] == pytest.approx(50.11162, abs=1e-4)
    assert az[0] == pytest.approx(194.34024, abs=1e-4)
    # Without refraction the paper's e0 = 39.872046° (zenith 50.127954°).
    _, el0 = spa_angles([unix_seconds(instant)], 39.742476, -105.1786, 1830.14, 67.0,
                        refraction=False, pressure_hpa=820.0, temperature_c=11.0)
    assert el0[0] == pytest.approx(39.872046, abs=1e-4)


def _meeus_alt_az(lat_deg, lon_deg, jd_ut, ra_deg, dec_deg):
    """Horizontal coordinates from right ascension/declination by spherical trigonometry and the
    mean sidereal time of Meeus, Astronomical Algorithms (2nd ed.), eq. 12.4."""
    t = (jd_ut - 2451545.0) / 36525.0
    theta0 = (280.46061837 + 360.98564736629 * (jd_ut - 2451545.0) + 0.000387933 * t * t
              - t ** 3 / 38710000.0)
    h = math.radians((theta0 + lon_deg - ra_deg) % 360.0)
    phi, dec = math.radians(lat_deg), math.radians(dec_deg)
    el = math.asin(math.sin(phi) * math.sin(dec) + math.cos(phi) * math.cos(dec) * math.cos(h))
    az = math.atan2(math.sin(h), math.cos(h) * math.sin(phi) - math.tan(dec) * math.cos(phi))
    return (math.degrees(az) + 180.0) % 360.0, math.degrees(el)


@pytest.mark.parametrize("lat, lon", [(35.68, 139.69), (-33.87, 151.21), (48.14, 11.58)])
def test_spa_against_meeus_example_25a(lat, lon):
    """pvlib-independent check. Meeus, Astronomical Algorithms (2nd ed.), Example 25.a: on
    1992-10-13 at 0h TD the Sun's apparent position is α = 13h13m31.4s, δ = −7°47'06". With
    ΔT = 59 s that is UT 1992-10-12 23:59:01. Turned into azimuth/elevation with eq. 12.4 and
    spherical trigonometry, it must match SPA's geometric (unrefracted) position within 0.02°:
    the example's low-accuracy theory is good to ~0.003°, nutation in right ascension
    (ignored in the mean sidereal time) is below 0.005°, solar parallax below 0.003°."""
    ra = (13 + 13 / 60 + 31.4 / 3600) * 15.0
    dec = -(7 + 47 / 60 + 6 / 3600)
    ut = datetime(1992, 10, 12, 23, 59, 1, tzinfo=timezone.utc)
    jd_ut = unix_seconds(ut) / 86400.0 + 2440587.5
    az_ref, el_ref = _meeus_alt_az(lat, lon, jd_ut, ra, dec)
    az, el = spa_angles([unix_seconds(ut)], lat, lon, 0.0, 59.0, refraction=False)
    assert el[0] == pytest.approx(el_ref, abs=0.02)
    assert abs((az[0] - az_ref + 180.0) % 360.0 - 180.0) < 0.02


def test_historical_munich_uses_delta_t_model():
    """1850-06-21 and 1700-03-21 at local noon (Europe/Berlin: local mean time then)."""
    modern = delta_t_seconds([datetime(2024, 6, 21, tzinfo=timezone.utc)])[0]
    assert 60.0 < modern < 80.0  # 74.1 s by the 2005–2050 polynomial
    summer = sun_from_instant(parse_user_date("1850-06-21T12:00", "Europe/Berlin").instant_utc,
                              UTM32, MUNICH)
    spring = sun_from_instant(parse_user_date("1700-03-21T12:00", "Europe/Berlin").instant_utc,
                              UTM32, MUNICH)
    for sun, (el_lo, el_hi) in ((summer, (60.0, 66.0)), (spring, (38.0, 44.0))):
        assert np.isfinite(sun.direction).all() and sun.above_horizon
        assert el_lo < sun.elevation_deg < el_hi, sun  # noon: 90° − 48.1° + declination
        assert 150.0 < sun.azimuth_true_deg < 200.0, sun
        assert abs(sun.delta_t_s - modern) > 30.0, "ΔT must come from the historical model"
        assert sun.source.startswith("spa") and sun.refraction is True
    # Berlin's local mean time in 1850 was UTC+0:53:28 (tz database); 12:00 → 11:06:32 UTC.
    assert summer.instant_utc == "1850-06-21T11:06:32Z"
    assert summer.latitude_deg == pytest.approx(48.13, abs=0.02)
    assert summer.longitude_deg == pytest.approx(11.57, abs=0.02)


@pytest.mark.parametrize("year", [1000, 1500, 2999, 3000])
def test_far_years_are_finite(year):
    sun = sun_from_instant(datetime(year, 6, 21, 11, tzinfo=timezone.utc), UTM32, MUNICH)
    assert np.isfinite(sun.direction).all() and 55.0 < sun.elevation_deg < 70.0


def test_years_outside_range_and_naive_instants_fail():
    with pytest.raises(UsageError, match="1000 to 3000"):
        sun_from_instant(datetime(999, 6, 21, tzinfo=timezone.utc), UTM32, MUNICH)
    with pytest.raises(UsageError, match="no time zone"):
        sun_from_instant(datetime(2024, 6, 21, 12), UTM32, MUNICH)


def test_grid_north_far_from_the_central_meridian():
    """EPSG:25832 at 6.4° E (Aachen, 2.6° west of the 9° E meridian): the SPA sun's grid
    azimuth differs from its true azimuth by pyproj's meridian convergence."""
    from pyproj import Proj

    x, y = 295_000.0, 5_630_000.0
    proj = Proj("EPSG:25832")
    lon, lat = proj(x, y, inverse=True)
    gamma = proj.get_factors(lon, lat).meridian_convergence
    assert gamma < -1.5
    sun = sun_from_instant(datetime(2024, 6, 21, 12, tzinfo=timezone.utc), UTM32,
                           np.array([x, y, 200.0]))
    assert sun.convergence_deg == pytest.approx(gamma, abs=1e-9)
    assert sun.azimuth_grid_deg == pytest.approx((sun.azimuth_true_deg - gamma) % 360, abs=1e-9)
    np.testing.assert_allclose(sun.direction,
                               direction_from_angles(sun.azimuth_grid_deg, sun.elevation_deg))
    assert sun.longitude_deg == pytest.approx(lon, abs=1e-9)
    assert sun.latitude_deg == pytest.approx(lat, abs=1e-9)


def test_dst_and_standard_time_offsets():
    summer = parse_user_date("2024-06-21T12:00", "Europe/Berlin").instant_utc
    winter = parse_user_date("2024-12-21T12:00", "Europe/Berlin").instant_utc
    assert summer.hour == 10 and winter.hour == 11  # CEST +2 h, CET +1 h
    suns = suns_from_instants([summer, winter], UTM32, MUNICH)
    assert [s.instant_utc for s in suns] == ["2024-06-21T10:00:00Z", "2024-12-21T11:00:00Z"]
    with pytest.raises(UsageError, match="no UTC offset"):
        parse_user_date("2024-06-21T12:00")


def test_polar_day_and_night_are_finite():
    """Longyearbyen (78.22° N): the sun is up at midnight in June and down at noon in December."""
    wgs84 = parse_srs_name("EPSG:4326")
    place = np.array([15.65, 78.22, 10.0])
    day, night = suns_from_instants(
        [datetime(2024, 6, 21, 0, tzinfo=timezone(timedelta(hours=2))),
         datetime(2024, 12, 21, 12, tzinfo=timezone(timedelta(hours=1)))], wgs84, place)
    assert day.above_horizon and 8.0 < day.elevation_deg < 14.0
    assert not night.above_horizon and -14.0 < night.elevation_deg < -8.0
    for sun in (day, night):
        assert np.isfinite(sun.direction).all()
        assert np.linalg.norm(sun.direction) == pytest.approx(1.0)


def test_sun_at_the_zenith_is_finite():
    """At the subsolar point (latitude = declination, hour angle 0) the elevation is 90°."""
    import pvlib.spa

    ut = datetime(2024, 4, 10, 9, 30, tzinfo=timezone.utc)
    unix = np.array([unix_seconds(ut)])
    sidereal, ra, dec = (float(v[0]) for v in pvlib.spa.solar_position(
        unix, 0.0, 0.0, 0.0, 1013.25, 12.0, 69.0, 0.5667, sst=True))
    lon = ((ra - sidereal + 180.0) % 360.0) - 180.0
    az, el = spa_angles(unix, dec, lon, 0.0, 69.0, refraction=False)
    assert np.isfinite(az).all() and el[0] == pytest.approx(90.0, abs=0.01)
    assert np.isfinite(direction_from_angles(az[0], el[0])).all()


def test_refraction_switch_and_nan_guard(monkeypatch):
    unix = [unix_seconds(datetime(2024, 6, 21, 3, 25, tzinfo=timezone.utc))]
    _, refracted = spa_angles(unix, 48.14, 11.58, 520.0, 69.0)
    _, geometric = spa_angles(unix, 48.14, 11.58, 520.0, 69.0, refraction=False)
    assert 0.2 < refracted[0] - geometric[0] < 0.7  # ~0.5° near the horizon
    # SPA's refraction term is 0·NaN at e0 = −5.11° exactly: the geometric value is used.
    from cityshade.geo.sun import pvlib_spa

    def fake(*args, **kwargs):
        return np.array([[np.nan], [95.11], [np.nan], [-5.11], [10.0], [0.0]])

    monkeypatch.setattr(pvlib_spa(), "solar_position", fake)
    az, el = spa_angles(unix, 48.14, 11.58, 520.0, 69.0)
    assert el[0] == -5.11 and az[0] == 10.0


def test_model_without_crs_names_the_option():
    with pytest.raises(CRSError, match="--crs"):
        sun_from_instant(datetime(2024, 6, 21, tzinfo=timezone.utc),
                         parse_srs_name("#local-CRS-1"), np.zeros(3))
    with pytest.raises(CRSError, match="--crs"):
        suns_from_instants([datetime(2024, 6, 21, tzinfo=timezone.utc)], None, np.zeros(3))


def test_settings_validation():
    with pytest.raises(UsageError, match="pressure_hpa"):
        SpaSettings(pressure_hpa=0.0)
    with pytest.raises(UsageError, match="temperature_c"):
        SpaSettings(temperature_c=float("nan"))


# --- render CLI: the sun from a date ----------------------------------------------------------

@pytest.fixture(scope="module")
def built(tmp_path_factory):
    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("spa_cli")
    src = tmp / "city.gml"
    src.write_text(city(building("b1", box_polygons(690_000, 5_336_000, 500, 10, 8, 6))))
    out, _, _ = build_file(src, tmp / "city.cityshade")
    nocrs = tmp / "nocrs.gml"
    nocrs.write_text(city(building("b1", box_polygons(0, 0, 0, 10, 8, 6), solid_refs=False)))
    out2, _, _ = build_file(nocrs, tmp / "nocrs.cityshade")
    return out, out2


def _run(*args):
    return CliRunner().invoke(__import__("cityshade.cli.main", fromlist=["cli"]).cli,
                              [str(a) for a in args])


def _one_line_error(result, fragment, code):
    assert result.exit_code == code, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("cityshade: error: "), result.output
    assert fragment in lines[0], lines[0]


def test_render_cli_computes_the_sun(built, tmp_path):
    from cityshade.imageio import read_exr

    scene, _ = built
    out = tmp_path / "a.exr"
    result = _run("render", scene, "--date", "2024-06-21", "--time", "12:00", "--tz",
                  "Europe/Berlin", "--camera", "map", "--pixel-size", "1", "-o", out, "-v")
    assert result.exit_code == 0, result.output
    assert "instant  2024-06-21T10:00:00Z UTC" in result.output
    assert "ΔT 74.1" in result.output  # Espenak–Meeus for 2024.5 and "refraction on" in result.output
    _, meta = read_exr(out)
    assert str(meta["cityshade:sun_source"]).startswith("spa (pvlib")
    assert "ΔT" in str(meta["cityshade:sun_note"])
    el_on = float(meta["cityshade:sun_elevation_deg"])
    assert 60.0 < el_on < 66.0
    result = _run("render", scene, "--date", "2024-06-21T04:45+02:00", "--no-refraction",
                  "--camera", "map", "--pixel-size", "1", "-o", out)
    assert result.exit_code == 0, result.output
    _, meta = read_exr(out)
    assert "refraction off" in str(meta["cityshade:sun_note"])


def test_render_cli_sun_failures(built, tmp_path):
    scene, nocrs = built
    out = tmp_path / "a.exr"
    _one_line_error(_run("render", nocrs, "--date", "2024-06-21T12:00Z", "-o", out),
                    "--crs", 1)
    _one_line_error(_run("render", scene, "--date", "2024-06-21T12:00", "-o", out),
                    "no UTC offset", 2)
    _one_line_error(_run("render", scene, "--date", "2024-06-21", "-o", out),
                    "no sun position", 2)
    _one_line_error(_run("render", scene, "--date", "1850", "--time", "12:00", "-o", out),
                    "--time needs --date as a day", 2)
    _one_line_error(_run("render", scene, "--date", "2024-06-21", "--time", "noon", "-o", out),
                    "--time must be HH:MM", 2)
    _one_line_error(_run("render", scene, "--date", "0900-06-21T12:00Z", "-o", out),
                    "1000 to 3000", 2)


def _stdout_of_python(code: str) -> list[str]:
    """The stdout lines of ``python -c code`` run in a fresh process from the repository (it
    must succeed)."""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=REPO, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip().splitlines()


def test_explicit_angles_never_import_pvlib(built, tmp_path):
    """DESIGN §2: a render with an explicit sun imports neither pvlib nor pandas."""
    scene, _ = built
    code = (
        "import sys\n"
        "from cityshade.cli.main import main\n"
        "try:\n"
        f"    main(['render', {str(scene)!r}, '--date', '2024-06-21', '--sun-azimuth', '180',\n"
        f"          '--sun-elevation', '40', '--camera', 'map', '-o', {str(tmp_path / 'x.exr')!r}])\n"
        "except SystemExit as exc:\n"
        "    assert not exc.code, exc.code\n"
        "print(sorted(m for m in ('pvlib', 'pandas') if m in sys.modules))\n")
    assert _stdout_of_python(code)[-1] == "[]"


def test_a_date_and_time_render_loads_only_pvlibs_spa(built, tmp_path):
    """A render whose sun SPA computes loads pvlib's SPA module from its file alone: neither
    the pvlib package (its __init__ imports pandas, scipy and some 40 modules, 0.8 s) nor
    pandas, nor pyproj; and its sun is the one pvlib.spa and pyproj give (computed here)."""
    scene, _ = built
    out = tmp_path / "x.exr"
    code = (
        "import sys\n"
        "from cityshade.cli.main import main\n"
        "try:\n"
        f"    main(['render', {str(scene)!r}, '--date', '2024-06-21', '--time', '15:00',\n"
        f"          '--tz', 'Europe/Berlin', '--camera', 'map', '-o', {str(out)!r}])\n"
        "except SystemExit as exc:\n"
        "    assert not exc.code, exc.code\n"
        "from cityshade.geo.sun import pvlib_spa\n"
        "print(sorted(m for m in ('pvlib', 'pvlib.spa', 'pandas', 'pyproj') if m in sys.modules),"
        " pvlib_spa().__name__)\n")
    # Nor pyproj: the place of the model's origin is stored in the scene file.
    assert _stdout_of_python(code)[-1] == "[] cityshade_pvlib_spa"
    import pvlib

    from cityshade.imageio import read_exr
    from cityshade.store.scenefile import load_scene

    s = load_scene(scene)
    want = sun_from_instant(datetime(2024, 6, 21, 13, 0, tzinfo=timezone.utc), s.crs, s.origin_m)
    _, meta = read_exr(out)
    # The EXR's float attributes are float32.
    assert float(meta["cityshade:sun_azimuth_true_deg"]) == np.float32(want.azimuth_true_deg)
    assert float(meta["cityshade:sun_elevation_deg"]) == np.float32(want.elevation_deg)
    assert meta["cityshade:sun_source"] == f"spa (pvlib {pvlib.__version__})"


def test_pvlibs_spa_module_alone_is_pvlib_spa():
    """The SPA module loaded from its file alone computes what pvlib.spa does, bit for bit
    (the same code), and the standard atmosphere's pressure is pvlib's alt2pres."""
    import pvlib
    import pvlib.atmosphere
    import pvlib.spa

    from cityshade.geo import sun as S

    code = ("import sys, numpy as np\n"
            "from cityshade.geo.sun import pvlib_spa, pvlib_version\n"
            "m = pvlib_spa()\n"
            "u = np.array([1.7e9, 1.72e9, -5.0e9, 3.0e10])\n"
            "dt = m.calculate_deltat(np.array([2023.0, 2024.0, 1811.0, 2920.0]),"
            " np.array([11.0, 7.0, 5.0, 1.0]))\n"
            "out = np.asarray(m.solar_position(u, 48.1, 11.5, 519.0, 955.0, 12.0, dt, 0.5667))\n"
            "print(m.__name__, 'pvlib' in sys.modules, pvlib_version())\n"
            "print(np.concatenate([dt, out.ravel()]).tobytes().hex())\n")
    head, data = _stdout_of_python(code)[-2:]
    assert head == f"cityshade_pvlib_spa False {pvlib.__version__}"
    u = np.array([1.7e9, 1.72e9, -5.0e9, 3.0e10])
    dt = pvlib.spa.calculate_deltat(np.array([2023.0, 2024.0, 1811.0, 2920.0]),
                                    np.array([11.0, 7.0, 5.0, 1.0]))
    out = np.asarray(pvlib.spa.solar_position(u, 48.1, 11.5, 519.0, 955.0, 12.0, dt, 0.5667))
    assert bytes.fromhex(data) == np.concatenate([dt, out.ravel()]).tobytes()
    for h in (-500.0, 0.0, 519.04, 1234.5, 9000.0):
        assert S.standard_pressure_pa(h) == pvlib.atmosphere.alt2pres(h)
    assert S.pvlib_version() == pvlib.__version__


def test_the_scene_file_stores_its_origins_place(built):
    """Built, a scene's header holds its origin's grid convergence and WGS 84 position as
    pyproj gives them (the process that loads it answers from them); a model without a CRS
    stores none, and its sun still fails with the option to give."""
    from cityshade.geo import crs as C
    from cityshade.store.scenefile import load_scene, read_header

    scene_path, nocrs_path = built
    s = load_scene(scene_path)
    x, y = float(s.origin_m[0]), float(s.origin_m[1])
    place = read_header(scene_path)["place"]
    C._PLACES.clear()                                   # pyproj's answers, not the memo's
    assert place == {"point": [x, y], "convergence_deg": C.grid_convergence_deg(s.crs, x, y),
                     "wgs84": list(C.to_wgs84(s.crs, x, y)[:2])}
    load_scene(scene_path)
    assert C._PLACES[(s.crs, x, y)]["convergence_deg"] == place["convergence_deg"]
    assert read_header(nocrs_path)["place"] is None
    n = load_scene(nocrs_path)
    with pytest.raises(CRSError, match="--crs"):
        sun_from_instant(datetime(2024, 6, 21, tzinfo=timezone.utc), n.crs, n.origin_m)


def test_a_malformed_stored_place_is_left_to_pyproj():
    """remember_place takes only a well-formed record (a crafted or damaged header's place
    leaves the answers to pyproj, no traceback)."""
    from cityshade.geo import crs as C

    x, y = 691_000.0, 5_334_000.0
    want = C.grid_convergence_deg(UTM32, x, y)
    for bad in (None, {}, [], "place", {"point": [x, y]}, {"point": "xy", "convergence_deg": 1,
                "wgs84": [1, 2]}, {"point": [x, y], "convergence_deg": "nan", "wgs84": [1, 2]},
                {"point": [x, y], "convergence_deg": 1.0, "wgs84": [1.0, 95.0]},
                {"point": [x, y], "convergence_deg": 1.0, "wgs84": [1.0]}):
        C.remember_place(UTM32, bad)
        assert C.grid_convergence_deg(UTM32, x, y) == want, bad
    C.remember_place(UTM32, {"point": [x, y], "convergence_deg": 1.25, "wgs84": [11.5, 48.1]})
    try:
        assert C.grid_convergence_deg(UTM32, x, y) == 1.25
        assert C.to_wgs84(UTM32, x, y, 7.0) == (11.5, 48.1, 7.0)
    finally:
        C._PLACES.pop((UTM32, x, y))
