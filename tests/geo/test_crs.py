"""Tests of cityshade.geo.crs: srsName spellings, a file's CRS, geographic projection,
meridian convergence."""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

from cityshade.geo.crs import (
    NO_CRS, CrsInfo, GeographicProjector, grid_convergence_deg, parse_srs_name,
    resolve_model_crs, resolve_model_crs_detailed, to_wgs84,
)
from cityshade.errors import CRSError
from conftest import shared_file

# (spelling, horizontal EPSG, vertical EPSG, is_geographic). Compound codes are split into their
# parts, so EPSG:6697 ("JGD2011 + JGD2011 (vertical) height") is 6668 + 6695 and
# EPSG:7415 ("Amersfoort / RD New + NAP height") is 28992 + 5709 (EPSG registry).
SPELLINGS = [
    ("EPSG:25832", 25832, None, False),
    ("epsg:25832", 25832, None, False),
    ("EPSG:3946", 3946, None, False),
    ("EPSG:32755", 32755, None, False),
    ("urn:ogc:def:crs:EPSG::25832", 25832, None, False),
    ("urn:ogc:def:crs:EPSG::28992", 28992, None, False),
    ("urn:ogc:def:crs:EPSG::4326", 4326, None, True),
    ("urn:ogc:def:crs:EPSG:6.12:25833", 25833, None, False),
    ("urn:x-ogc:def:crs:EPSG:6.12:25833", 25833, None, False),
    ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783", 25832, 5783, False),
    ("urn:ogc:def:crs,crs:EPSG::31466,crs:EPSG::5783", 31466, 5783, False),
    ("urn:ogc:def:crs,crs:EPSG:6.12:31466,crs:EPSG:6.12:5783", 31466, 5783, False),
    ("urn:ogc:def:crs,crs:EPSG:6.12:25833,crs:EPSG:6.12:5783", 25833, 5783, False),
    ("urn:ogc:def:crs,crs:EPSG:6.12:3068,crs:EPSG:6.12:5783", 3068, 5783, False),
    ("urn:ogc:def:crs,crs:EPSG:7.7:31468,crs:EPSG:7.7:5783", 31468, 5783, False),
    ("urn:ogc:def:crs:EPSG:25832, crs:EPSG:5783", 25832, 5783, False),
    ("http://www.opengis.net/def/crs/EPSG/0/6697", 6668, 6695, True),
    ("https://www.opengis.net/def/crs/EPSG/0/25832", 25832, None, False),
    ("http://www.opengis.net/def/crs/EPSG/6.12/3068", 3068, None, False),
    ("http://www.opengis.net/gml/srs/epsg.xml#4326", 4326, None, True),
    ("http://www.opengis.net/def/crs-compound?1=http://www.opengis.net/def/crs/EPSG/0/25832"
     "&2=http://www.opengis.net/def/crs/EPSG/0/5783", 25832, 5783, False),
    ("EPSG:25832+5783", 25832, 5783, False),
    ("EPSG:5555", 25832, 5783, False),
    ("EPSG:7415", 28992, 5709, False),
    ("EPSG:4979", 4979, None, True),
    ("EPSG:4258", 4258, None, True),
    ("EPSG:4937", 4937, None, True),
    ("urn:adv:crs:ETRS89_UTM32", 25832, None, False),
    ("urn:adv:crs:ETRS89_UTM33", 25833, None, False),
    ("urn:adv:crs:ETRS89_UTM32*DE_DHHN92_NH", 25832, 5783, False),
    ("urn:adv:crs:ETRS89_UTM33*DE_DHHN92_NH", 25833, 5783, False),
    ("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH", 25832, 7837, False),
    ("urn:adv:crs:DE_DHDN_3GK2*DE_DHHN92_NH", 31466, 5783, False),
    ("urn:adv:crs:DE_DHDN_3GK3*DE_DHHN92_NH", 31467, 5783, False),
    ("urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH", 31468, 5783, False),
    ("urn:adv:crs:DE_DHDN_3GK5*DE_DHHN92_NH", 31469, 5783, False),
    ("urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH", 31468, 5783, False),  # typo in the Munich tile
    ("urn:adv:crs:DE_DHDN_3GK4", 31468, None, False),
    ("urn:adv:crs:ETRS89_Lat-Lon", 4258, None, True),
    ("  EPSG:25832  ", 25832, None, False),
]


@pytest.mark.parametrize("spelling, h_epsg, v_epsg, geographic", SPELLINGS)
def test_spelling_resolves_to_epsg(spelling, h_epsg, v_epsg, geographic):
    info = parse_srs_name(spelling)
    assert (info.horizontal_epsg, info.vertical_epsg, info.is_geographic, info.local) == \
        (h_epsg, v_epsg, geographic, False), info
    assert info.srs_name == spelling
    assert info.name


def test_names_are_human_readable():
    assert parse_srs_name("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783").name == \
        "ETRS89 / UTM zone 32N + DHHN92 height"
    assert parse_srs_name("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH").name == \
        "ETRS89 / UTM zone 32N + DHHN2016 height"


@pytest.mark.parametrize("spelling", ["#local-CRS-1", "#myEngineeringCRS", " #x "])
def test_local_references(spelling):
    info = parse_srs_name(spelling)
    assert info.local and info.horizontal_epsg is None and not info.is_geographic


@pytest.mark.parametrize("spelling, fragment", [
    ("foo", "'foo'"),
    ("EPSG:", "'EPSG:'"),
    ("urn:adv:crs:ETRS89_UTM99", "ETRS89_UTM99"),
    ("urn:adv:crs:ETRS89_UTM32*DE_XYZ_NH", "DE_XYZ_NH"),
    ("urn:ogc:def:crs,crs:EPSG::25832,crs:FOO::1", "crs:FOO::1"),
    ("EPSG:999999", "EPSG:999999"),
    ("EPSG:4978", "Geocentric"),        # geocentric XYZ cannot be a city's map
    ("EPSG:5783", "height system"),     # heights only
    ("EPSG:2263", "US survey foot"),    # projected in feet: the scene is in metres
    ("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::25833", "not a height system"),
    ("", "empty srsName"),
])
def test_unusable_spellings_raise_with_useful_message(spelling, fragment):
    with pytest.raises(CRSError) as info:
        parse_srs_name(spelling)
    message = str(info.value)
    assert fragment in message
    if fragment != "US survey foot":
        assert "--crs" in message


def test_non_text_srs_name_raises():
    with pytest.raises(CRSError):
        parse_srs_name(25832)


def test_parse_is_cached():
    assert parse_srs_name("urn:adv:crs:ETRS89_UTM32*DE_DHHN92_NH") is \
        parse_srs_name("urn:adv:crs:ETRS89_UTM32*DE_DHHN92_NH")


def test_json_round_trip():
    for info in (parse_srs_name("urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH"), NO_CRS,
                 parse_srs_name("#local-CRS-1")):
        again = CrsInfo.from_json(json.loads(json.dumps(info.to_json())))
        assert again == info


@pytest.mark.parametrize("record", [
    {"srs_name": "EPSG:25832"},
    {**NO_CRS.to_json(), "extra": 1},
    {**NO_CRS.to_json(), "horizontal_epsg": "25832"},
    {**NO_CRS.to_json(), "horizontal_epsg": True},
    {**NO_CRS.to_json(), "local": 1},
    [1, 2],
])
def test_from_json_rejects_bad_records(record):
    with pytest.raises(CRSError):
        CrsInfo.from_json(record)


# --- resolve_model_crs ---------------------------------------------------------------------

def test_resolve_mixed_list_takes_most_frequent_horizontal():
    # The 'several attributes' example: GK4 on geometry, EPSG::4326 on one point, plus locals.
    names = (["urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH"] * 3 + ["urn:ogc:def:crs:EPSG::4326"]
             + ["#local-CRS-1"] * 5)
    result = resolve_model_crs_detailed(iter(names))
    assert result.crs.horizontal_epsg == 31468 and result.crs.vertical_epsg == 5783
    assert len(result.warnings) == 1 and "WGS 84 (1×)" in result.warnings[0]
    assert resolve_model_crs(names) == result.crs


def test_resolve_counts_spellings_of_one_crs_together():
    names = ["EPSG:25833"] * 2 + ["urn:ogc:def:crs,crs:EPSG::25833,crs:EPSG::5783"] * 2 \
        + ["EPSG:25832"] * 3
    crs = resolve_model_crs(names)
    assert crs.horizontal_epsg == 25833
    # Equal counts within the group: the spelling that also names the heights is preferred.
    assert crs.vertical_epsg == 5783


def test_resolve_override_wins_and_no_names_is_none():
    assert resolve_model_crs(["EPSG:25832"] * 10, override="EPSG:3946").horizontal_epsg == 3946
    crs = resolve_model_crs([])
    assert crs.local and crs.name == "none" and crs.srs_name is None
    assert resolve_model_crs([], override="urn:adv:crs:ETRS89_UTM32").horizontal_epsg == 25832
    with pytest.raises(CRSError):
        resolve_model_crs(["EPSG:25832"], override="not a crs")


def test_resolve_only_local():
    crs = resolve_model_crs(["#local-CRS-1", "#local-CRS-1"])
    assert crs.local and crs.srs_name == "#local-CRS-1"


def test_resolve_unknown_spellings():
    result = resolve_model_crs_detailed(["EPSG:25832"] * 3 + ["bogus"])
    assert result.crs.horizontal_epsg == 25832
    assert any("bogus" in w for w in result.warnings)
    # A known CRS wins over unknown spellings whatever their counts (issue 13 point 3).
    result = resolve_model_crs_detailed(["EPSG:25832"] + ["bogus"] * 2)
    assert result.crs.horizontal_epsg == 25832 and any("bogus" in w for w in result.warnings)
    # Only unknown spellings: the model builds with its CRS recorded as unknown.
    result = resolve_model_crs_detailed(["bogus", "bogus", "#local-CRS-1"])
    assert result.crs.local and result.crs.name == "unknown (bogus)"
    assert len(result.warnings) == 1 and "--crs" in result.warnings[0]


# --- every srsName of the real data ---------------------------------------------------------

#: srsNames in the real data that must be refused: EPSG:23632 (libcitygml's
#: BridgeAndBuilding.gml) is not an EPSG code (ED50 / UTM zone 32N is EPSG:23032).
KNOWN_INVALID = {"EPSG:23632"}


def test_every_srs_name_in_real_data_parses(shared_data):
    pattern = re.compile(rb"""srsName\s*=\s*(?:"([^"]*)"|'([^']*)')""")
    found: set[str] = set()
    for path in shared_data.rglob("*.gml"):
        for match in pattern.finditer(path.read_bytes()):
            found.add((match.group(1) or match.group(2)).decode("utf-8"))
    assert len(found) >= 19, found  # SOURCES.md lists at least this many distinct spellings
    for name in sorted(found - KNOWN_INVALID):
        info = parse_srs_name(name)
        assert info.local or info.horizontal_epsg is not None, name
    for name in found & KNOWN_INVALID:
        with pytest.raises(CRSError, match="23632"):
            parse_srs_name(name)


# --- geographic projection ------------------------------------------------------------------

def _pos_lists(path, limit):
    """First ``limit`` posLists of a file as (N, 3) arrays (plain regex, no reader)."""
    text = path.read_text(encoding="utf-8")
    arrays = []
    for match in re.finditer(r"<gml:posList[^>]*>([^<]+)</gml:posList>", text):
        arrays.append(np.array(match.group(1).split(), dtype=np.float64).reshape(-1, 3))
        if len(arrays) == limit:
            break
    return np.concatenate(arrays)


def test_plateau_6697_projects_to_utm54(shared_data):
    path = shared_file("plateau-tokyo-meiji-gallery/53394517_bldg_6697_2_op_CityGML3.gml")
    xyz = _pos_lists(path, 50)
    crs = parse_srs_name("http://www.opengis.net/def/crs/EPSG/0/6697")
    projector = GeographicProjector(crs, xyz)
    # Latitude first, as EPSG:6697 and the http spelling say (the warning says so).
    assert projector.axis_lat_first and "read latitude first" in projector.warning
    # Longitude 139.7°E lies in UTM zone floor((139.7 + 180) / 6) + 1 = 54, north.
    assert projector.target.horizontal_epsg == 32654
    out = projector.project(xyz)
    assert out.shape == xyz.shape and out.dtype == np.float64
    # Hand estimate at (35.679°N, 139.717°E), CM 141°E: easting ≈ 500 km + k0·N·cosφ·Δλ ≈
    # 384 km; northing ≈ k0 × meridian arc to 35.68° ≈ 3,949 km.
    assert np.all((383_000 < out[:, 0]) & (out[:, 0] < 385_500))
    assert np.all((3_945_000 < out[:, 1]) & (out[:, 1] < 3_955_000))
    np.testing.assert_array_equal(out[:, 2], xyz[:, 2])  # heights kept as written
    # Distances agree with geodesic distances on the ellipsoid (Karney) up to the UTM scale
    # factor near 140 km from the central meridian (0.9996 … 1.0000).
    from pyproj import Geod
    geod = Geod(ellps="GRS80")
    i, j = 0, len(xyz) - 1
    _, _, dist_m = geod.inv(xyz[i, 1], xyz[i, 0], xyz[j, 1], xyz[j, 0])
    grid_m = math.hypot(*(out[j, :2] - out[i, :2]))
    assert dist_m > 10 and 0.9995 < grid_m / dist_m < 1.0001


def test_longitude_first_under_4979_is_detected():
    crs = parse_srs_name("EPSG:4979")
    lon_first = np.array([[-77.005, 38.888, 5.0]])
    lat_first = lon_first[:, [1, 0, 2]]
    p_lon = GeographicProjector(crs, lon_first)
    p_lat = GeographicProjector(crs, lat_first)
    assert not p_lon.axis_lat_first and "longitude first" in p_lon.warning
    assert p_lat.axis_lat_first and "beyond 75°" in p_lat.warning
    assert p_lon.target.horizontal_epsg == p_lat.target.horizontal_epsg == 32618
    a, b = p_lon.project(lon_first), p_lat.project(lat_first)
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-6)
    # Hand estimate, CM 75°W: easting ≈ 500 km − k0·N·cos(38.888°)·2.005° ≈ 326.1 km.
    assert 325_000 < a[0, 0] < 327_500 and 4_300_000 < a[0, 1] < 4_312_000
    assert a[0, 2] == 5.0


def test_jefferson_file_is_longitude_first(shared_data):
    path = shared_file("ogc-citygml3-building-examples/building/"
                       "JeffersonBuilding_CityGML3.0_LOD1_with_xAL3_CommonTypes.gml")
    xyz = _pos_lists(path, 20)
    projector = GeographicProjector(parse_srs_name("EPSG:4979"), xyz)
    assert not projector.axis_lat_first and projector.warning
    out = projector.project(xyz)
    assert np.all((320_000 < out[:, 0]) & (out[:, 0] < 330_000))


def test_axis_order_heuristic_edges():
    crs = parse_srs_name("urn:ogc:def:crs:EPSG::4326")
    # Both orders fit and neither latitude is polar: the spelling decides (the URN: lat first;
    # the short form: longitude first, GML 3.1 practice).
    assert GeographicProjector(crs, np.array([[50.0, 10.0, 0.0]])).axis_lat_first
    assert not GeographicProjector(parse_srs_name("EPSG:4326"),
                                   np.array([[50.0, 10.0, 0.0]])).axis_lat_first
    # A polar reading is rejected in favour of the city-like one: (80, 10) is lon 80°, lat 10°.
    p = GeographicProjector(crs, np.array([[80.0, 10.0, 0.0]]))
    assert not p.axis_lat_first and "longitude first" in p.warning
    assert GeographicProjector(crs, np.array([[10.0, 80.0, 0.0]])).axis_lat_first
    # Southern hemisphere: UTM south zone (Melbourne 144.96°E, 37.8°S → zone 55S).
    p = GeographicProjector(crs, np.array([[-37.8, 144.96, 0.0]]))
    assert p.target.horizontal_epsg == 32755
    # Neither order gives degrees: projected coordinates under a geographic srsName.
    with pytest.raises(CRSError, match="not degrees"):
        GeographicProjector(crs, np.array([[4468000.0, 5334000.0, 500.0]]))
    with pytest.raises(CRSError):
        GeographicProjector(crs, np.full((2, 3), np.nan))
    with pytest.raises(CRSError):
        GeographicProjector(crs, np.zeros((2, 2)))
    with pytest.raises(CRSError):
        GeographicProjector(parse_srs_name("EPSG:25832"), np.zeros((1, 3)))
    with pytest.raises(CRSError, match="--crs"):
        GeographicProjector(NO_CRS, np.zeros((1, 3)))


def test_projector_accepts_read_only_input():
    xyz = np.array([[35.68, 139.72, 10.0]])
    xyz.setflags(write=False)
    p = GeographicProjector(parse_srs_name("EPSG:6697"), xyz)
    assert np.isfinite(p.project(xyz)).all()


# --- convergence and WGS 84 ----------------------------------------------------------------

def _grid_azimuth_of_true_north_deg(epsg, x, y):
    """Independent estimate: step 1e-5° north along the meridian, measure the grid bearing."""
    from pyproj import Transformer
    to_geo = Transformer.from_crs(epsg, f"{_geodetic_of(epsg)}", always_xy=True)
    to_grid = Transformer.from_crs(f"{_geodetic_of(epsg)}", epsg, always_xy=True)
    lon, lat = to_geo.transform(x, y)
    x0, y0 = to_grid.transform(lon, lat)
    x1, y1 = to_grid.transform(lon, lat + 1e-5)
    return math.degrees(math.atan2(x1 - x0, y1 - y0)), lon, lat


def _geodetic_of(epsg):
    from pyproj import CRS
    return CRS.from_epsg(epsg).geodetic_crs.to_wkt()


@pytest.mark.parametrize("spelling, x, y, central_meridian_deg", [
    ("EPSG:25832", 300_000.0, 5_500_000.0, 9.0),      # 200 km west of the central meridian
    ("EPSG:25832", 700_000.0, 5_500_000.0, 9.0),      # 200 km east
    ("urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH", 4_468_000.0, 5_334_000.0, 12.0),  # Munich, GK4
    ("EPSG:32755", 320_000.0, 5_812_000.0, 147.0),    # Melbourne, southern hemisphere
])
def test_grid_convergence(spelling, x, y, central_meridian_deg):
    from pyproj import Proj
    crs = parse_srs_name(spelling)
    gamma_deg = grid_convergence_deg(crs, x, y)
    # 1. pyproj's own factor has the same sign convention.
    proj = Proj(f"EPSG:{crs.horizontal_epsg}")
    lon, lat = proj(x, y, inverse=True)
    assert gamma_deg == pytest.approx(proj.get_factors(lon, lat).meridian_convergence, abs=1e-12)
    # 2. Definition check: true north (true azimuth 0) has grid azimuth 0 − γ.
    north_grid_deg, lon, lat = _grid_azimuth_of_true_north_deg(crs.horizontal_epsg, x, y)
    assert north_grid_deg == pytest.approx(0.0 - gamma_deg, abs=1e-5)
    # 3. Textbook Transverse Mercator: γ ≈ atan(tan Δλ · sin φ) (sphere; the ellipsoid adds
    #    terms of order e'² Δλ³ ≈ 1e-4° here).
    d_lon = math.radians(lon - central_meridian_deg)
    approx_deg = math.degrees(math.atan(math.tan(d_lon) * math.sin(math.radians(lat))))
    assert gamma_deg == pytest.approx(approx_deg, abs=2e-3)
    # West of the central meridian in the north, grid north is west of true north: γ < 0.
    assert math.copysign(1, gamma_deg) == math.copysign(1, d_lon * lat)


def test_grid_convergence_needs_a_crs():
    with pytest.raises(CRSError, match="give --crs"):
        grid_convergence_deg(NO_CRS, 0.0, 0.0)
    with pytest.raises(CRSError, match="give --crs"):
        grid_convergence_deg(parse_srs_name("#local-CRS-1"), 0.0, 0.0)
    assert grid_convergence_deg(parse_srs_name("EPSG:4326"), 10.0, 50.0) == 0.0


def test_to_wgs84():
    # UTM zone 32N: the false easting 500 km lies on the central meridian 9°E; northing 0 is the
    # equator. ETRS89 and WGS 84 coincide here to PROJ's (null) transformation.
    lon, lat, h = to_wgs84(parse_srs_name("EPSG:25832"), 500_000.0, 0.0, 12.5)
    assert (lon, lat, h) == (pytest.approx(9.0, abs=1e-9), pytest.approx(0.0, abs=1e-9), 12.5)
    lon, lat, _ = to_wgs84(parse_srs_name("EPSG:25832"), 500_000.0, 5_500_000.0)
    assert lon == pytest.approx(9.0, abs=1e-9) and 49.6 < lat < 49.7
    # Munich GK4 (DHDN, a Helmert shift of ~100 m to WGS 84): TUM campus is near 11.57°E 48.15°N.
    lon, lat, _ = to_wgs84(parse_srs_name("urn:adv:crs:DE_DHDN_3GK4*DE_DHN92_NH"),
                           4_468_000.0, 5_334_700.0)
    assert 11.55 < lon < 11.59 and 48.14 < lat < 48.16
    assert to_wgs84(parse_srs_name("EPSG:4326"), 10.0, 50.0) == (10.0, 50.0, 0.0)
    with pytest.raises(CRSError, match="--crs"):
        to_wgs84(NO_CRS, 0.0, 0.0)


def test_import_is_cheap():
    code = ("import sys, cityshade.geo.crs, cityshade.geo.temporal; "
            "print(','.join(m for m in ('pyproj', 'lxml', 'numba', 'click') "
            "if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == ""

