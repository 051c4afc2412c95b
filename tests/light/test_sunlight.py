"""Probable sunlight hours of a window from the London EPW, against an independent count."""
from __future__ import annotations

import csv
import math
from datetime import datetime, timedelta, timezone

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city

from pathlib import Path

LONDON = (Path(__file__).resolve().parents[2].parent / "shared" / "data" / "weather"
          / "GBR_ENG_London.City.AP.037683_TMYx.2007-2021.epw")


def _utm31(lon_deg, lat_deg):
    from pyproj import Transformer

    return Transformer.from_crs("EPSG:4326", "EPSG:32631", always_xy=True).transform(lon_deg,
                                                                                      lat_deg)


def _true_south(lon_deg, lat_deg):
    """The UTM 31N (render-space) direction of true south at a place, from two points of its
    meridian projected with pyproj (independent of the library's meridian convergence)."""
    (xn, yn), (xs, ys) = _utm31(lon_deg, lat_deg + 0.001), _utm31(lon_deg, lat_deg - 0.001)
    v = np.array([xs - xn, ys - yn, 0.0])
    return v / np.linalg.norm(v)


def _turned(faces, x0, y0, south):
    """Box faces turned about (x0, y0) so that the face whose normal was -y faces ``south``."""
    angle = math.atan2(south[1], south[0]) - math.atan2(-1.0, 0.0)
    c, s = math.cos(angle), math.sin(angle)
    return [(cls, pid, [(x0 + c * (x - x0) - s * (y - y0), y0 + s * (x - x0) + c * (y - y0), z)
                        for x, y, z in pts]) for cls, pid, pts in faces]


@pytest.fixture(scope="module")
def london_house(tmp_path_factory):
    """A 20 x 10 x 20 m house at London City Airport (UTM 31N) whose south wall faces true
    south, and a copy with a 30 m high, 200 m long block 15 m south of it."""
    from cityshade.build import build_scene_from_file

    if not LONDON.is_file():
        pytest.skip(f"real data not available: {LONDON} is absent")
    x0, y0 = (round(v) for v in _utm31(0.055, 51.505))
    south = _true_south(0.055, 51.505)
    tmp = tmp_path_factory.mktemp("london")
    house = building("H", _turned(box_polygons(x0 - 10.0, y0, 0.0, 20.0, 10.0, 20.0, "h"),
                                  x0, y0, south), srs="EPSG:32631")
    block = building("B", _turned(box_polygons(x0 - 100.0, y0 - 25.0, 0.0, 200.0, 10.0, 30.0,
                                               "b"), x0, y0, south), srs="EPSG:32631")
    scenes = []
    for name, members in (("free.gml", (house,)), ("blocked.gml", (house, block))):
        path = tmp / name
        path.write_text(city(*members))
        scenes.append(build_scene_from_file(path))
    return (x0, y0), south, scenes


def test_apsh_of_a_free_south_window_is_the_independent_count(london_house):
    import pvlib

    from cityshade.light import probable_sunlight, read_weather

    from pyproj import Transformer

    (x0, y0), normal, (free, blocked) = london_house
    lon, lat = Transformer.from_crs("EPSG:32631", "EPSG:4326", always_xy=True).transform(
        free.origin_m[0], free.origin_m[1])
    point = np.array([x0, y0, 5.0]) - free.origin_m
    weather = read_weather(LONDON)
    ps = probable_sunlight(free, point[None], normal[None], weather)

    # The count: the file's DNI field and pvlib's sun at the middle of each hour ending at the
    # record's hour (local standard time, UTC+0 here), at the model's place.
    with open(LONDON, newline="") as f:
        rows = list(csv.reader(f))[8:]
    times = [datetime(int(r[0]), int(r[1]), int(r[2]), tzinfo=timezone.utc)
             + timedelta(hours=int(r[3]) - 0.5) for r in rows]
    import pandas as pd

    pressure = pvlib.atmosphere.alt2pres(float(free.origin_m[2]))
    sun = pvlib.solarposition.get_solarposition(pd.DatetimeIndex(times), lat, lon,
                                                altitude=float(free.origin_m[2]),
                                                pressure=pressure, temperature=12.0)
    dni = np.array([float(r[14]) for r in rows])
    sunny = (dni >= 120.0) & (sun["apparent_elevation"].to_numpy() > 0.0)
    az = sun["azimuth"].to_numpy()
    in_front = sunny & (np.abs(az - 180.0) < 90.0)
    winter = np.array([(t.month, t.day) >= (9, 21) or (t.month, t.day) <= (3, 21)
                       for t in times])

    assert ps.total_h == sunny.sum()
    assert ps.front_h[0] == in_front.sum() == ps.annual_h[0]
    assert ps.winter_h[0] == (in_front & winter).sum()
    assert 0.3 < ps.apsh[0] < 0.9 and 0.0 < ps.winter_apsh[0] < ps.apsh[0]

    # A 30 m block 15 m to the south takes hours away, exactly those whose sun rays it blocks
    # (checked by raytrace on each sunny hour in front: the hours sun-hours would lose).
    from cityshade.light.sunlight import weather_suns
    from cityshade.shadows.visibility import sunlit

    behind = probable_sunlight(blocked, point[None], normal[None], weather, engine="raytrace")
    dirs, elev = weather_suns(weather, blocked)
    lit = [bool(sunlit(blocked, point[None], normal[None], dirs[h])[0])
           for h in np.flatnonzero(weather.sunny() & (elev > 0) & (dirs @ normal > 1e-6))]
    assert behind.annual_h[0] == sum(lit) < ps.annual_h[0]
    assert behind.total_h == ps.total_h and behind.front_h[0] == ps.front_h[0]
    assert math.isfinite(behind.apsh[0])
