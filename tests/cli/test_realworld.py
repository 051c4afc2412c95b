"""Issue 13: real models from real producers, placed and timed right (hand-made files).

Each test reproduces one reported case with a small file written here (no third-party data)
and asserts the message and the result: for the axis order the projected footprint and the sun
direction, for the time sources the object counts per date.
"""
from __future__ import annotations

import math
from datetime import datetime, timezone

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import CG2, box_polygons, building, city, polygon

from cityshade.geo.crs import (GeographicProjector, grid_convergence_deg, parse_srs_name,
                                   resolve_model_crs_detailed)
from cityshade.citygml.reader import read_citygml
from cityshade.geo.temporal import parse_user_date, parse_xsd_datetime_days
from cityshade.config import BuildSettings
from cityshade.errors import CRSError, UsageError
from cityshade.geometry.scene import build_scene

CG2_GEN = CG2 + ' xmlns:gen="http://www.opengis.net/citygml/generics/2.0"'


def _envelope_city(srs: str, *members: str, ns: str = CG2) -> str:
    """A city whose only srsName is on the envelope (as shapefile converters write it)."""
    text = city(*members, ns=ns)
    head, sep, rest = text.partition(">")          # the XML declaration
    head2, sep2, rest2 = rest.partition(">")        # the CityModel start tag
    envelope = (f'<gml:boundedBy><gml:Envelope srsName="{srs}" srsDimension="3">'
                f'<gml:lowerCorner>0 0 0</gml:lowerCorner><gml:upperCorner>1 1 1'
                f'</gml:upperCorner></gml:Envelope></gml:boundedBy>')
    return head + sep + head2 + sep2 + envelope + rest2


def _build(tmp_path, text: str, name: str = "city.gml", **settings):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    generic = [v for k, v in settings.items() if k == "time_attribute" and v]
    names = []
    if generic:
        from cityshade.geo.temporal import parse_time_attribute
        names = [n for n in parse_time_attribute(generic[0]) if n]
    return build_scene(read_citygml(path, generic_attributes=names), BuildSettings(**settings))


# --- 1. axis order of geographic coordinates -------------------------------------------------

#: Karlsruhe-like place of the reported file: 8.40–8.42° E, 49.00–49.02° N, in WGS 84 / UTM 32N.
_UTM32_E, _UTM32_N = 456_500.0, 5_428_600.0
#: Footprints: (centre east, centre north offsets in m, rotation in degrees); all 20 m × 10 m.
_FOOTPRINTS = [(0, 0, 30.0), (60, 10, 17.0), (-50, 40, 62.0), (20, -70, 45.0), (-80, -40, 80.0),
               (90, 80, 5.0)]


def _rotated_box_utm(cx, cy, angle_deg, w=20.0, d=10.0, h=12.0):
    """Faces (class, id, points) of a w × d box rotated by angle, in UTM 32N metres."""
    a = math.radians(angle_deg)
    ux, uy = math.cos(a), math.sin(a)
    vx, vy = -uy, ux
    corners = [(cx + sx * w / 2 * ux + sy * d / 2 * vx, cy + sx * w / 2 * uy + sy * d / 2 * vy)
               for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    bottom = [(x, y, 100.0) for x, y in corners]
    top = [(x, y, 100.0 + h) for x, y in corners]
    faces = [("GroundSurface", bottom[::-1]), ("RoofSurface", top)]
    for k in range(4):
        p, q = bottom[k], bottom[(k + 1) % 4]
        faces.append(("WallSurface", [p, q, (q[0], q[1], q[2] + h), (p[0], p[1], p[2] + h)]))
    return faces, corners


def _geographic_city(lat_first: bool, srs: str) -> tuple[str, list]:
    """The footprints written in degrees (via pyproj's inverse UTM 32N), in the given order."""
    from pyproj import Transformer
    to_deg = Transformer.from_crs("EPSG:32632", "EPSG:4326", always_xy=True)
    members, footprints = [], []
    for k, (dx, dy, angle) in enumerate(_FOOTPRINTS):
        faces, corners = _rotated_box_utm(_UTM32_E + dx, _UTM32_N + dy, angle)
        footprints.append(corners)
        deg_faces = []
        for j, (cls, pts) in enumerate(faces):
            xyz = np.array(pts)
            lon, lat = to_deg.transform(xyz[:, 0], xyz[:, 1])
            a, b = (lat, lon) if lat_first else (lon, lat)
            deg_faces.append((cls, f"b{k}_{j}", [(f"{u:.10f}", f"{v:.10f}", z)
                                                 for u, v, z in zip(a, b, xyz[:, 2])]))
        members.append(building(f"b{k}", deg_faces, solid_refs=False))
    return _envelope_city(srs, *members), footprints


def _footprint_of(scene, obj_id):
    """Sorted horizontal edge lengths of an object's roof (metres) and its corner angles."""
    o = scene.obj_ids.index(obj_id)
    from cityshade.citygml.namespaces import SURFACE_CODE
    tris = scene.triangles[(scene.tri_object == o) & (scene.tri_class == SURFACE_CODE["roof"])]
    world = scene.vertices.astype(np.float64)[np.unique(tris)] + scene.origin_m
    return world


def _check_footprints(scene, footprints, tol_m=0.01):
    for k, corners in enumerate(footprints):
        world = _footprint_of(scene, f"b{k}")
        expected = np.array(corners)
        # Every expected corner is a roof vertex (float32 render space: ~1 mm here).
        d = np.hypot(world[:, None, 0] - expected[None, :, 0], world[:, None, 1] - expected[None, :, 1])
        assert d.min(axis=0).max() < tol_m, f"building b{k}: footprint off by {d.min(axis=0).max()} m"


def test_short_epsg_4326_longitude_first_is_placed_and_timed_right(tmp_path):
    """The reported file: srsName EPSG:4326 on the envelope only, longitude first."""
    text, footprints = _geographic_city(lat_first=False, srs="EPSG:4326")
    scene = _build(tmp_path, text)
    assert scene.crs.horizontal_epsg == 32632, "UTM zone 32N, not 39N"
    _check_footprints(scene, footprints)
    lo = scene.vertices.min(axis=0)
    hi = scene.vertices.max(axis=0)
    assert hi[0] - lo[0] < 200 and hi[1] - lo[1] < 200
    warning = [w for w in scene.report["warnings"] if "first" in w]
    assert len(warning) == 1 and "read longitude first" in warning[0]
    assert "--axis-order latlon" in warning[0]
    assert scene.report["axis_order"] == "lonlat"
    # The sun at true solar noon of the model's place stands due south; its elevation is
    # 90° − latitude + declination (23.44° at the June solstice): 64.4° at 49.01° N (a reading
    # at latitude 8.4° would give 75°).
    from cityshade.geo.sun import solar_time_zone, sun_from_instant
    zone = solar_time_zone("local-apparent", scene.crs, scene.origin_m)
    instant = parse_user_date("2024-06-21T12:00", zone).instant_utc
    sun = sun_from_instant(instant, scene.crs, scene.origin_m)
    assert sun.azimuth_true_deg == pytest.approx(180.0, abs=0.05)
    assert sun.elevation_deg == pytest.approx(90.0 - 49.0 + 23.44, abs=0.2)
    # Grid north in UTM 32N at 8.41° E: convergence ≈ (λ − 9°) · sin φ ≈ −0.45°.
    assert sun.convergence_deg == pytest.approx((8.41 - 9.0) * math.sin(math.radians(49.01)),
                                                abs=0.02)
    assert sun.direction[1] < -0.4 and abs(sun.direction[0]) < 0.01  # toward grid south


def test_urn_spelling_but_longitude_first_is_decided_by_right_angles(tmp_path):
    text, footprints = _geographic_city(lat_first=False, srs="urn:ogc:def:crs:EPSG::4326")
    scene = _build(tmp_path, text)
    assert scene.crs.horizontal_epsg == 32632
    _check_footprints(scene, footprints)
    warning = next(w for w in scene.report["warnings"] if "first" in w)
    assert "read longitude first" in warning and "right-angled" in warning
    assert "although" in warning and "latitude first" in warning


def test_latitude_first_urn_file_and_the_override(tmp_path):
    text, footprints = _geographic_city(lat_first=True, srs="urn:ogc:def:crs:EPSG::4326")
    scene = _build(tmp_path, text)
    _check_footprints(scene, footprints)
    assert scene.report["axis_order"] == "latlon"
    # Forcing the wrong order is obeyed (and said), and visibly distorts the footprints.
    forced = _build(tmp_path, text, axis_order="lonlat")
    assert forced.crs.horizontal_epsg != 32632
    assert any("--axis-order lonlat" in w for w in forced.report["warnings"])
    with pytest.raises(AssertionError):
        _check_footprints(forced, footprints, tol_m=1.0)


def test_geometric_test_is_undecided_for_axis_aligned_boxes():
    """Axis-parallel rectangles stay right-angled under the wrong order's stretch: the
    spelling decides then."""
    ring = np.array([[8.41, 49.01, 0], [8.4103, 49.01, 0], [8.4103, 49.0101, 0],
                     [8.41, 49.0101, 0], [8.41, 49.01, 0]], float)
    for srs, lat_first in (("EPSG:4326", False), ("urn:ogc:def:crs:EPSG::4326", True)):
        p = GeographicProjector(parse_srs_name(srs), ring, ring_offsets=np.array([0, 5]))
        assert p.axis_lat_first is lat_first and "spelling" in p.warning


@pytest.mark.parametrize("spelling", ["OGC:CRS84", "urn:ogc:def:crs:OGC:1.3:CRS84",
                                      "http://www.opengis.net/def/crs/OGC/1.3/CRS84", "CRS84"])
def test_crs84_spellings_are_accepted_longitude_first(spelling):
    crs = parse_srs_name(spelling)
    assert crs.is_geographic and crs.horizontal_epsg == 4326
    p = GeographicProjector(crs, np.array([[8.41, 49.01, 0.0]]))
    assert not p.axis_lat_first and "longitude first by definition" in p.warning


def test_crs84_override_builds(tmp_path):
    text, footprints = _geographic_city(lat_first=False, srs="urn:ogc:def:crs:EPSG::4326")
    scene = _build(tmp_path, text, crs="urn:ogc:def:crs:OGC:1.3:CRS84")
    _check_footprints(scene, footprints)


# --- 2. compound CRS with a height system PROJ does not know -----------------------------------

def _bng_city(srs):
    return city(building("uk", box_polygons(530_000.0, 180_000.0, 10.0, 12.0, 8.0, 9.0),
                         srs=srs))


def test_compound_with_unknown_height_system_uses_the_horizontal_part(tmp_path):
    srs = "urn:ogc:def:crs,crs:EPSG::27700,crs:EPSG::5101"
    scene = _build(tmp_path, _bng_city(srs))
    assert scene.crs.horizontal_epsg == 27700 and scene.crs.vertical_epsg is None
    assert scene.crs.name == "OSGB36 / British National Grid"
    warning = [w for w in scene.report["warnings"] if "5101" in w]
    assert len(warning) == 1 and "using the horizontal part EPSG:27700" in warning[0]
    assert not any("25832" in w for w in scene.report["warnings"])
    # London: the sun of a date is computed there (not in Germany, not in the north).
    from cityshade.geo.sun import sun_from_instant
    sun = sun_from_instant(datetime(2024, 6, 21, 12, 0, tzinfo=timezone.utc), scene.crs,
                           scene.origin_m)
    assert sun.latitude_deg == pytest.approx(51.5, abs=0.1)
    assert abs(sun.longitude_deg) < 0.5 and 170 < sun.azimuth_true_deg < 190


def test_no_hint_names_a_foreign_crs():
    for bad in ("EPSG:999999", "bogus", "EPSG:4978"):
        with pytest.raises(CRSError) as info:
            parse_srs_name(bad)
        assert "25832" not in str(info.value) and "--crs" in str(info.value)


# --- 3. an unknown CRS builds ----------------------------------------------------------------

def test_unknown_crs_builds_and_geodesy_fails_later_naming_crs(tmp_path):
    text = city(building("b", box_polygons(500_000.0, 5_400_000.0, 0.0, 10, 10, 10),
                         srs="EPSG:23632"))
    scene = _build(tmp_path, text)
    assert scene.crs.local and scene.crs.horizontal_epsg is None
    assert scene.crs.name == "unknown (EPSG:23632)"
    warning = [w for w in scene.report["warnings"] if "23632" in w]
    assert len(warning) == 1 and "does not exist" in warning[0] and "--crs" in warning[0]
    from cityshade.geo.sun import sun_from_angles, sun_from_instant
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)  # explicit sun: works
    assert sun.azimuth_grid_deg == 135.0 and "no CRS" in sun.note
    with pytest.raises(CRSError, match="rebuild it with --crs"):
        sun_from_instant(datetime(2024, 6, 21, 12, tzinfo=timezone.utc), scene.crs,
                         scene.origin_m)
    with pytest.raises(CRSError, match="rebuild the scene with --crs"):
        grid_convergence_deg(scene.crs, 500_000.0, 5_400_000.0)
    # With --crs it is placed.
    placed = _build(tmp_path, text, crs="EPSG:25832")
    assert placed.crs.horizontal_epsg == 25832


def test_crs_that_does_not_exist_says_so():
    with pytest.raises(CRSError, match="EPSG:999999 does not exist"):
        resolve_model_crs_detailed(["EPSG:25832"], override="EPSG:999999")


def test_info_on_gml_accepts_crs(tmp_path):
    from cityshade.cli.main import cli
    path = tmp_path / "c.gml"
    path.write_text(city(building("b", box_polygons(690_000.0, 5_336_000.0, 0.0, 10, 10, 10),
                                  srs="EPSG:23632")), encoding="utf-8")
    result = CliRunner().invoke(cli, ["info", str(path), "--crs", "EPSG:25832"])
    assert result.exit_code == 0, result.output
    assert "ETRS89 / UTM zone 32N (EPSG:25832)" in result.output
    result = CliRunner().invoke(cli, ["info", str(path)])
    assert result.exit_code == 0 and "unknown (EPSG:23632)" in result.output


# --- 4. coordinates outside the CRS's area of use --------------------------------------------

def test_shifted_model_is_warned_about_and_its_convergence_refused(tmp_path):
    shift = 1e7
    text = city(building("b", box_polygons(690_100.0 + shift, 5_336_050.0 + shift, 0.0,
                                           100, 80, 10)))
    scene = _build(tmp_path, text)
    warning = [w for w in scene.report["warnings"] if "area of use" in w]
    assert len(warning) == 1 and "ETRS89 / UTM zone 32N" in warning[0]
    from cityshade.geo.sun import sun_from_angles
    with pytest.raises(CRSError) as info:
        sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    message = str(info.value)
    assert "+139.8°" in message and "--crs" in message   # the convergence the issue measured


def test_london_in_utm32_is_warned_about(tmp_path):
    scene = _build(tmp_path, _bng_city("EPSG:27700"), crs="EPSG:25832")
    assert any("outside the area of use" in w and "1.6" in w for w in scene.report["warnings"])
    right = _build(tmp_path, _bng_city("EPSG:27700"))
    assert not any("area of use" in w for w in right.report["warnings"])


# --- 5. time sources ---------------------------------------------------------------------------

def _dated_building(bid, x, extra):
    return building(bid, box_polygons(690_000.0 + x, 5_336_000.0, 0.0, 10, 10, 10, prefix=bid),
                    extra=extra)


def _time_city():
    creation = "<creationDate>2015-12-14</creationDate>"
    return city(
        _dated_building("a", 0, creation),
        _dated_building("b", 20, creation + "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"),
        _dated_building("c", 40, creation + '<gen:intAttribute name="baujahr"><gen:value>1850'
                                            '</gen:value></gen:intAttribute>'),
        ns=CG2_GEN)


def _standing(scene, year):
    t = parse_xsd_datetime_days(str(year))
    return int(((scene.obj_t_begin_days <= t) & (t < scene.obj_t_end_days)).sum())


def test_creation_dates_are_database_times(tmp_path):
    auto = _build(tmp_path, _time_city())
    assert [_standing(auto, y) for y in (1800, 1870, 1950, 2016)] == [2, 2, 3, 3]
    assert auto.report["time_sources_used"] == {"construction": 1, "none": 2}
    assert auto.report["creation_dates_unused"] == 3
    attr = _build(tmp_path, _time_city(), time_attribute="begin=baujahr")
    assert [_standing(attr, y) for y in (1800, 1870, 1950, 2016)] == [1, 2, 3, 3]
    assert attr.report["time_sources_used"] == {"attribute": 1, "construction": 1, "none": 1}
    creation = _build(tmp_path, _time_city(), time_source="creation")
    assert [_standing(creation, y) for y in (1800, 2015, 2016)] == [0, 0, 3]
    assert not any("creationDate" in w for w in auto.report["warnings"])


def test_only_creation_dates_are_warned_about(tmp_path):
    creation = "<creationDate>2008-12-09+01:00</creationDate>"
    text = city(_dated_building("a", 0, creation), _dated_building("b", 20, creation))
    scene = _build(tmp_path, text)
    assert [_standing(scene, y) for y in (1850, 2020)] == [2, 2]   # not lost in 1850
    warning = [w for w in scene.report["warnings"] if "creationDate" in w]
    assert len(warning) == 1 and "database times" in warning[0]
    assert "--time-source creation" in warning[0]


def test_time_attribute_begin_and_end_citygml3(tmp_path):
    ns3 = ('xmlns="http://www.opengis.net/citygml/3.0" xmlns:gml="http://www.opengis.net/gml/3.2" '
           'xmlns:bldg="http://www.opengis.net/citygml/building/3.0" '
           'xmlns:con="http://www.opengis.net/citygml/construction/3.0" '
           'xmlns:gen="http://www.opengis.net/citygml/generics/3.0"')
    attrs = ('<genericAttribute><gen:IntAttribute><gen:name>built</gen:name><gen:value>1890'
             '</gen:value></gen:IntAttribute></genericAttribute>'
             '<genericAttribute><gen:StringAttribute><gen:name>razed</gen:name><gen:value>1944.0'
             '</gen:value></gen:StringAttribute></genericAttribute>')
    pts = [(690_000.0, 5_336_000.0, 0.0), (690_010.0, 5_336_000.0, 0.0),
           (690_010.0, 5_336_010.0, 0.0)]
    member = (f'<bldg:Building gml:id="b">{attrs}<lod2MultiSurface><gml:MultiSurface '
              f'srsName="EPSG:25832"><gml:surfaceMember>{polygon(pts, "p")}</gml:surfaceMember>'
              f'</gml:MultiSurface></lod2MultiSurface></bldg:Building>')
    text = city(member, ns=ns3)
    scene = _build(tmp_path, text, time_attribute="begin=built,end=razed")
    assert [_standing(scene, y) for y in (1880, 1900, 1944, 1950)] == [0, 1, 0, 0]
    with pytest.raises(UsageError, match="begin=NAME"):
        from cityshade.geo.temporal import parse_time_attribute
        parse_time_attribute("start=built")


def test_info_says_where_each_count_came_from(tmp_path):
    from cityshade.cli.main import cli
    path = tmp_path / "t.gml"
    path.write_text(_time_city(), encoding="utf-8")
    result = CliRunner().invoke(cli, ["info", str(path)])
    assert result.exit_code == 0, result.output
    assert "objects by source: construction 1, none 2" in result.output
    assert "creationDate/terminationDate of 3 objects unused" in result.output


# --- 6. historical local time ------------------------------------------------------------------

def test_lmt_is_warned_about():
    berlin_1850 = parse_user_date("1850-06-21T15:00", "Europe/Berlin")
    assert len(berlin_1850.warnings) == 1
    assert "LMT +0:53:28" in berlin_1850.warnings[0] and "--tz local-mean" in berlin_1850.warnings[0]
    assert parse_user_date("2024-06-21T15:00", "Europe/Berlin").warnings == ()
    assert parse_user_date("1850-06-21T15:00+01:00", "Europe/Berlin").warnings == ()


def test_local_mean_and_apparent_time():
    from cityshade.geo.sun import SolarTime
    # Munich's mean time: 11.5675° E × 4 min/° = +0:46:16.2 (the issue's +0:46:16).
    mean = SolarTime(11.5675, apparent=False)
    assert mean.utcoffset(None).total_seconds() == pytest.approx(46 * 60 + 16.2, abs=0.01)
    at = parse_user_date("1850-06-21T15:00", mean).instant_utc
    assert at == datetime(1850, 6, 21, 14, 13, 43, 800000, tzinfo=timezone.utc)
    # Apparent time: the equation of time on 3 November is about +16 min 25 s (almanacs), so
    # apparent noon falls at 11:43:35 mean time.
    apparent = SolarTime(11.5675, apparent=True)
    noon = parse_user_date("2024-11-03T12:00", apparent).instant_utc
    mean_noon = parse_user_date("2024-11-03T12:00", mean).instant_utc
    assert (mean_noon - noon).total_seconds() == pytest.approx(16 * 60 + 25, abs=10)


def test_render_with_local_apparent_time_puts_the_sun_south(tmp_path):
    from cityshade.build import build_file
    from cityshade.cli.main import cli
    from conftest import REPO
    scene_path = tmp_path / "s.cityshade"
    build_file(REPO / "sample_data" / "sample_city.gml", scene_path)
    base = ["render", str(scene_path), "--camera", "map", "--pixel-size", "8", "-o",
            str(tmp_path / "a.exr"), "-v"]
    result = CliRunner().invoke(cli, base + ["--date", "1850-06-21T12:00", "--tz",
                                             "local-apparent"])
    assert result.exit_code == 0, result.output
    sun_line = next(line for line in result.output.splitlines() if line.startswith("sun "))
    azimuth = float(sun_line.split("azimuth ")[1].split("°")[0])
    assert azimuth == pytest.approx(180.0, abs=0.05)
    result = CliRunner().invoke(cli, base + ["--date", "1850-06-21T15:00", "--tz",
                                             "Europe/Berlin"])
    assert result.exit_code == 0 and "LMT +0:53:28" in result.output
    assert "--tz local-mean" in result.output


# --- 11. ground plane by default ---------------------------------------------------------------

def _two_boxes_without_terrain(tmp_path):
    """A 20 m box at the south-west corner and a 2 m one at the north-east, no terrain: the map
    view spans 42 m × 42 m of which only 104 m² are roofs."""
    from cityshade.build import build_file
    x0, y0 = 690_000.0, 5_336_000.0
    src = tmp_path / "boxes.gml"
    src.write_text(city(building("tall", box_polygons(x0, y0, 0.0, 10, 10, 20, "t")),
                        building("low", box_polygons(x0 + 40, y0 + 40, 0.0, 2, 2, 2, "l"))),
                   encoding="utf-8")
    out, _, _ = build_file(src, tmp_path / "boxes.cityshade")
    return out


def test_ground_auto_is_the_default_and_none_switches_it_off(tmp_path):
    """Issue 13 point 11: without terrain a default render showed no cast shadow and the EXR Z
    was +inf on the plane; now --ground auto is the default, with the plane's depth in Z."""
    from cityshade.cli.main import cli
    from cityshade.imageio import read_exr
    scene_path = _two_boxes_without_terrain(tmp_path)
    base = ["render", str(scene_path), "--date", "2000", "--sun-azimuth", "180",
            "--sun-elevation", "45", "--camera", "map", "--pixel-size", "1", "--margin-m", "0"]
    result = CliRunner().invoke(cli, base + ["-o", str(tmp_path / "auto.exr")])
    assert result.exit_code == 0, result.output
    ch, meta = read_exr(tmp_path / "auto.exr")
    assert meta["cityshade:ground"] == "auto plane at z=0.000 m"
    ground_px = ch["objid"] == -1
    assert ground_px.sum() > 1500 and np.isfinite(ch["Z"]).all()
    roof_tall = ch["Z"] == ch["Z"].min()
    # The plane's depth is the camera height above z = 0: 20 m below the tall roof.
    assert set(np.unique(ch["Z"][ground_px] - ch["Z"].min())) == {20.0}
    assert roof_tall.sum() == 100
    # The tall box's shadow on the ground: 10 m wide, 20 m long (45°), north of it.
    in_shadow = ground_px & (ch["shadow"] == 0)
    assert 190 <= in_shadow.sum() <= 210
    rows, cols = np.nonzero(roof_tall)
    srows, scols = np.nonzero(in_shadow)
    assert srows.max() < rows.min() and set(scols) <= set(cols)  # north (up), same columns
    result = CliRunner().invoke(cli, base + ["-o", str(tmp_path / "none.exr"), "--ground",
                                             "none"])
    assert result.exit_code == 0, result.output
    ch, meta = read_exr(tmp_path / "none.exr")
    assert meta["cityshade:ground"] == "none"
    assert (np.isinf(ch["Z"]) == (ch["objid"] == -1)).all() and (ch["objid"] >= 0).sum() == 104
    help_text = CliRunner().invoke(cli, ["render", "--help"]).output
    assert "[default: auto]" in " ".join(help_text.split())


# --- 13. smaller things -----------------------------------------------------------------------

def test_scene_file_gets_the_umask(tmp_path):
    import os
    from cityshade.store.cache import write_cache
    old = os.umask(0o027)
    try:
        write_cache(tmp_path / "x.cityshade", {}, {"a": np.zeros(3)})
    finally:
        os.umask(old)
    assert (tmp_path / "x.cityshade").stat().st_mode & 0o777 == 0o640


def test_info_json_lists_skipped_polygon_ids(tmp_path):
    import json
    from cityshade.cli.main import cli
    good = box_polygons(690_000.0, 5_336_000.0, 0.0, 10, 10, 10)
    zero = [(690_020.0, 5_336_000.0, 0.0), (690_025.0, 5_336_000.0, 0.0),
            (690_030.0, 5_336_000.0, 0.0)]
    faces = good + [("WallSurface", "flat1", zero)]
    path = tmp_path / "s.gml"
    path.write_text(city(building("b", faces)), encoding="utf-8")
    result = CliRunner().invoke(cli, ["info", str(path), "--json"])
    assert result.exit_code == 0, result.output
    d = json.loads(result.output)
    (reason, ids), = d["skipped_ids"].items()
    assert ids == ["flat1"] and d["skipped"] == {reason: 1}


def test_top_level_help_lists_every_command():
    from cityshade.cli.main import COMMANDS, cli
    text = CliRunner().invoke(cli, ["--help"]).output
    usage = text.split("Options:")[0]
    for name in COMMANDS:
        assert f"cityshade {name} " in usage, name


def test_readme_dates_of_the_sample_match_info():
    import re
    from conftest import REPO
    raw = read_citygml(REPO / "sample_data" / "sample_city.gml")
    scene = build_scene(raw)
    first, last = (d[:4] for d in scene.report["time_range"])
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    found = re.search(r"dates from (\d{4}) to (\d{4})", readme)
    assert found and found.groups() == (first, last)
    sample = (REPO / "sample_data" / "README.md").read_text(encoding="utf-8")
    assert f"{first}–{last}" in sample


def test_geotiff_of_a_model_without_crs_warns_and_evaluate_crs_needs_gml(tmp_path):
    from cityshade.build import build_file
    from cityshade.cli.main import cli
    src = tmp_path / "u.gml"
    src.write_text(city(building("b", box_polygons(500_000.0, 5_400_000.0, 0.0, 10, 10, 10),
                                 srs="EPSG:23632")), encoding="utf-8")
    scene_path = tmp_path / "u.cityshade"
    build_file(src, scene_path)
    result = CliRunner().invoke(cli, [
        "render", str(scene_path), "--date", "2000", "--sun-azimuth", "135",
        "--sun-elevation", "30", "--camera", "map", "--pixel-size", "1", "-o",
        str(tmp_path / "m.exr"), "--geotiff", str(tmp_path / "m.tif")])
    assert result.exit_code == 0, result.output
    assert "m.tif has no .prj" in result.output and "--crs" in result.output
    assert not (tmp_path / "m.prj").exists()
    # A sun from a date needs the place: one line naming --crs.
    result = CliRunner().invoke(cli, ["render", str(scene_path), "--date", "2000-06-21T12:00Z",
                                      "-o", str(tmp_path / "d.exr")])
    assert result.exit_code == 1 and "rebuild it with --crs" in result.output
    assert len(result.output.strip().splitlines()) == 1
    result = CliRunner().invoke(cli, ["evaluate", str(scene_path), "--crs", "EPSG:25832", "-o",
                                      str(tmp_path / "rep")])
    assert result.exit_code == 2 and "--crs applies to a CityGML file" in result.output


def test_batch_and_evaluate_accept_solar_time(tmp_path):
    from cityshade.build import build_file
    from cityshade.cli.main import cli
    from conftest import REPO
    scene_path = tmp_path / "s.cityshade"
    build_file(REPO / "sample_data" / "sample_city.gml", scene_path)
    # One step of an hour around true solar noon: its sun (at the step's middle) is due south.
    result = CliRunner().invoke(cli, [
        "batch", str(scene_path), "--date", "1850-06-21", "--from", "11:30", "--to", "12:30",
        "--every", "1h", "--tz", "local-apparent", "--camera", "map", "--pixel-size", "8",
        "-o", str(tmp_path / "b"), "-v"])
    assert result.exit_code == 0, result.output
    first = next(line for line in result.output.splitlines() if line.startswith("first"))
    assert float(first.split("azimuth ")[1].split("°")[0]) == pytest.approx(180.0, abs=0.05)
    from cityshade.evaluate import suns_of_day
    from cityshade.store.scenefile import load_scene
    from cityshade.cli.options import solar_zone_of_scene
    scene = load_scene(scene_path)
    sun, = suns_of_day("2024-11-03", "12:00", solar_zone_of_scene("local-apparent", scene), scene)
    assert sun.azimuth_true_deg == pytest.approx(180.0, abs=0.05)


def test_explicit_sun_with_time_is_an_error(tmp_path):
    from cityshade.cli.main import cli
    scene_path = _two_boxes_without_terrain(tmp_path)
    result = CliRunner().invoke(cli, [
        "render", str(scene_path), "--date", "2024-06-21", "--time", "15:00", "--tz",
        "Europe/Berlin", "--sun-azimuth", "135", "--sun-elevation", "30", "-o",
        str(tmp_path / "x.exr")])
    assert result.exit_code == 2 and result.output.strip().splitlines() == [
        "cityshade: error: --time computes the sun for the model's place and --sun-azimuth/"
        "--sun-elevation give it: use one or the other"]
    assert not (tmp_path / "x.exr").exists()


def test_flags_of_other_techniques_are_warned_about_and_presets_listed(tmp_path):
    from cityshade.cli.main import cli
    from cityshade.cli.options import inapplicable_flags
    scene_path = _two_boxes_without_terrain(tmp_path)
    result = CliRunner().invoke(cli, [
        "render", str(scene_path), "--date", "2000", "--sun-azimuth", "135",
        "--sun-elevation", "30", "--camera", "map", "--pixel-size", "2", "--shadows",
        "raytrace", "--cascades", "3", "-o", str(tmp_path / "r.exr")])
    assert result.exit_code == 0 and (tmp_path / "r.exr").is_file()
    assert ("cityshade: warning: --cascades does not apply to --shadows raytrace; ignored"
            in result.output.splitlines())
    assert inapplicable_flags("csm:lispsm+smooth", {"cascades": 3, "pcf_kernel": 5}) == [
        "pcf_kernel"]
    assert inapplicable_flags("izb,hybrid", {"vsm_blur": 2, "bias": 0.1}) == []
    assert inapplicable_flags("izb", {"bias": 0.1, "map_px": None}) == ["bias"]
    help_text = " ".join(CliRunner().invoke(cli, ["render", "--help"]).output.split())
    assert "south, east, north, west, bird" in help_text


def test_progress_lines_every_tenth_or_ten_seconds(capsys):
    from cityshade.cli.options import ProgressLines
    now = [0.0]
    lines = ProgressLines("steps", clock=lambda: now[0])
    for done in range(1, 101):
        now[0] += 0.01 if done < 50 else 30.0  # slow from the 50th step on
        lines(done, 1000)
    seen = capsys.readouterr().err.splitlines()
    # 10 % is step 100; before step 50 nothing, then a line every step (each takes 30 s).
    # The ETA: the time per step since the first call times the steps left (at step 50:
    # 30.48 s / 49 steps × 950 steps = 590.9 s).
    assert seen[0] == "cityshade: steps 50/1000 (5 %, ETA 0:09:50)" and len(seen) == 51
    assert seen[-1] == "cityshade: steps 100/1000 (10 %, ETA 3:51:53)"


def test_batch_prints_progress_lines_when_stderr_is_not_a_terminal(tmp_path):
    from cityshade.cli.main import cli
    scene_path = _two_boxes_without_terrain(tmp_path)
    result = CliRunner().invoke(cli, [
        "batch", str(scene_path), "--date", "2024-06-21", "--from", "08:00", "--to", "18:00",
        "--every", "1h", "--tz", "Europe/Berlin", "--pixel-size", "4", "-o",
        str(tmp_path / "b")])
    assert result.exit_code == 0, result.output
    progress = [line for line in result.output.splitlines()
                if line.startswith("cityshade: sun positions ")]
    assert progress[-1] == "cityshade: sun positions 10/10 (100 %)" and len(progress) == 10


def test_only_terrain_standing_is_warned_about():
    from types import SimpleNamespace
    from cityshade.citygml.namespaces import SURFACE_CODE
    from cityshade.frame.render import only_terrain_stands
    terrain, roof = SURFACE_CODE["terrain"], SURFACE_CODE["roof"]
    scene = SimpleNamespace(tri_class=np.array([terrain, terrain, roof], np.uint8),
                            tri_t_begin_days=np.array([-np.inf, -np.inf, 100.0]),
                            tri_t_end_days=np.array([np.inf, np.inf, 200.0]))
    assert only_terrain_stands(scene, 50.0) and only_terrain_stands(scene, 200.0)
    assert not only_terrain_stands(scene, 100.0)
    scene.tri_class[:] = roof
    assert not only_terrain_stands(scene, 50.0)  # nothing at all stands: not "only terrain"


# --- 7. outputs checked before the work ----------------------------------------------------------

def test_render_checks_every_output_before_the_work(tmp_path, monkeypatch):
    """Issue 13 point 7: a bad --png extension or a --geotiff of a perspective view failed
    after rendering and left the EXR written before it."""
    from cityshade.frame import render as R
    from cityshade.cli.main import cli
    scene_path = _two_boxes_without_terrain(tmp_path)

    def no_work(*a, **k):
        raise AssertionError("rendered before the outputs were checked")

    monkeypatch.setattr(R, "render_frame", no_work)
    base = ["render", str(scene_path), "--date", "2000", "--sun-azimuth", "135",
            "--sun-elevation", "30", "-o", str(tmp_path / "a.exr")]
    cases = [
        (["--png", str(tmp_path / "a.jpg")], 2,
         f"--png {tmp_path / 'a.jpg'}: the file name must end in .png, not '.jpg'"),
        (["--geotiff", str(tmp_path / "a.tif")], 2,
         "--geotiff needs the map view (--camera map): a perspective picture has no place on "
         "a map"),
        (["--png", str(tmp_path / "p.png"), "--mask", str(tmp_path / "p.png")], 2,
         f"--mask and --png would both write {tmp_path / 'p.png'}"),
    ]
    for extra, code, message in cases:
        result = CliRunner().invoke(cli, base + extra)
        lines = result.output.strip().splitlines()
        assert result.exit_code == code and len(lines) == 1, result.output
        assert lines[0].startswith("cityshade: error: ") and message in lines[0], lines[0]
    exr = ["render", str(scene_path), "--date", "2000", "--sun-azimuth", "135",
           "--sun-elevation", "30", "-o"]
    (tmp_path / "dir.exr").mkdir()
    from cityshade.errors import OutputError
    with pytest.raises(OutputError, match="is a folder, not a file name"):
        R.check_frame_outputs("map", exr=tmp_path / "dir.exr")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["boxes.cityshade", "boxes.gml",
                                                          "dir.exr"]
    # A missing folder is created, as build does; then the work runs.
    monkeypatch.undo()
    result = CliRunner().invoke(cli, exr + [str(tmp_path / "new" / "sub" / "a.exr"), "--camera",
                                            "map", "--pixel-size", "4"])
    assert result.exit_code == 0 and (tmp_path / "new" / "sub" / "a.exr").is_file()


# --- 10. memory estimate before allocating -------------------------------------------------------

def test_a_frame_that_does_not_fit_in_memory_is_refused_before_allocating(tmp_path, monkeypatch):
    """Issue 13 point 10: --pixel-size 0.021 on the sample passed and needed about 50 GB."""
    from types import SimpleNamespace
    from cityshade.cli.main import cli
    from cityshade.frame.pipeline import check_frame_memory
    cam = SimpleNamespace(width_px=2000, height_px=1000, kind="map")
    # 290 B/px: the measured peak of the camera pass (benchmarks/memory.py, pipeline's table).
    assert check_frame_memory(cam, available_bytes=580_000_000) == 580_000_000
    with pytest.raises(UsageError) as err:
        check_frame_memory(cam, available_bytes=579_999_999)
    assert str(err.value) == ("the picture of 2000 × 1000 pixels needs about 0.6 GB (290 bytes "
                              "per pixel) but 0.6 GB are available: use a larger --pixel-size")
    # The map families add 24 B per texel of their maps (2048² by default; csm: 4 of them).
    huge = 10**12
    assert check_frame_memory(cam, huge, technique="hybrid:vsm") == 2_000_000 * 410 + 2048**2 * 24
    assert check_frame_memory(cam, huge, technique="csm") == 2_000_000 * 290 + 4 * 2048**2 * 24
    assert check_frame_memory(cam, huge, technique="izb+smooth") == 2_000_000 * 290
    scene_path = _two_boxes_without_terrain(tmp_path)
    import cityshade.frame.pipeline
    monkeypatch.setattr(cityshade.frame.pipeline, "available_memory_bytes", lambda: 800_000_000)
    result = CliRunner().invoke(cli, [
        "render", str(scene_path), "--date", "2000", "--sun-azimuth", "135",
        "--sun-elevation", "30", "--camera", "map", "--pixel-size", "0.003", "--margin-m", "0",
        "-o", str(tmp_path / "huge.exr")])
    lines = result.output.strip().splitlines()
    assert result.exit_code == 2 and len(lines) == 1, result.output
    import re
    # A map this large goes in strips of rows (56.8 GB whole at 290 B/px): the writers' whole
    # mask (4 B/px; the 41 B/px kept for the outputs go to a temporary file) plus one strip and
    # its two halo rows at 290 B/px still does not fit.
    found = re.fullmatch(r"cityshade: error: the picture of (\d+) × (\d+) pixels in strips of "
                         r"(\d+) rows needs about ([\d.]+) GB but 0.8 GB are available: use a "
                         r"larger --pixel-size", lines[0])
    assert found, lines[0]
    w, h, rows, gb = int(found[1]), int(found[2]), int(found[3]), float(found[4])
    assert 14_000 <= w <= 14_002 and 14_000 <= h <= 14_002  # 42 m at 3 mm
    assert rows == 128 * 1024 ** 2 // (w * 290)
    assert gb == pytest.approx((w * h * 4 + (rows + 2) * w * 290) / 1e9, abs=0.051)
    assert not (tmp_path / "huge.exr").exists()


def test_a_batch_that_does_not_fit_in_memory_is_refused_before_any_work(tmp_path, monkeypatch):
    """Issue 13 point 10 for batch: the estimate per receiver pixel, and tiles in the hint."""
    from cityshade.cli.main import cli
    scene_path = _two_boxes_without_terrain(tmp_path)
    import cityshade.frame.pipeline
    monkeypatch.setattr(cityshade.frame.pipeline, "available_memory_bytes", lambda: 8_000_000_000)
    result = CliRunner().invoke(cli, [
        "batch", str(scene_path), "--date", "2024-06-21", "--tz", "Europe/Berlin",
        "--pixel-size", "0.003", "--margin-m", "0", "-o", str(tmp_path / "b")])
    lines = result.output.strip().splitlines()
    assert result.exit_code == 2 and len(lines) == 1, result.output
    import re
    found = re.fullmatch(r"cityshade: error: the sun-hour map of (\d+) × (\d+) pixels needs "
                         r"about ([\d.]+) GB \(290 bytes per receiver pixel\) but 8.0 GB are "
                         r"available: use a larger --pixel-size or --tile-px N \(the map in "
                         r"tiles of N × N pixels\)", lines[0])
    assert found, lines[0]
    assert float(found[3]) == pytest.approx(56.8, abs=0.1)
    assert not (tmp_path / "b").exists()  # checked and made, then removed: nothing left
