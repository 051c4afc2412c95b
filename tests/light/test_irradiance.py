"""Irradiance of receivers: pvlib's get_total_irradiance for an unobstructed plane (the test of
the layering), only the ground-reflected and visible-sky parts under a roof, and the direct part
zero exactly where the raytrace engine says shadow."""
from __future__ import annotations

import math
import os

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city

#: Receiver normals of several tilts and azimuths, exact on the library's 1e-6 grouping grid
#: (Pythagorean triples): horizontal, vertical south / east / north-west, tilted, overhanging.
NORMALS = np.array([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [-0.6, 0.8, 0.0],
                    [0.0, -0.6, 0.8], [0.48, -0.64, 0.6], [-0.36, -0.48, 0.8],
                    [0.0, 0.8, -0.6], [0.0, 0.28, 0.96], [0.28, 0.0, -0.96]])
NORMALS = NORMALS / np.linalg.norm(NORMALS, axis=1, keepdims=True)

#: In Greensboro (UTM 17N), where pvlib's TMY3 file was recorded.
X0, Y0 = 608_000.0, 3_996_000.0


@pytest.fixture(scope="module")
def setting(tmp_path_factory):
    """A 40 x 40 m roof 3 m above the ground (a canopy 0.5 m thick) in UTM 17N, pvlib's TMY3
    file of Greensboro, and 8 days of its hours (in June and December)."""
    import pvlib

    from cityshade.build import build_scene_from_file
    from cityshade.light import read_weather, weather_suns
    from cityshade.light.irradiance import hours_between

    tmp = tmp_path_factory.mktemp("irradiance")
    path = tmp / "canopy.gml"
    path.write_text(city(building("C", box_polygons(X0 - 20.0, Y0 - 20.0, 3.0, 40.0, 40.0, 0.5,
                                                    "c"), srs="EPSG:32617")))
    scene = build_scene_from_file(path)
    weather = read_weather(os.path.join(os.path.dirname(pvlib.__file__), "data",
                                        "723170TYA.CSV"))
    hours = hours_between(weather, "06-10", "06-13") | hours_between(weather, "12-10", "12-13")
    directions, _ = weather_suns(weather, scene)
    # The hours with the sun up: below the horizon the earth blocks the sun, where pvlib
    # counts its direct and circumsolar light on a plane facing it.
    hours &= directions[:, 2] > 0.0
    return scene, weather, hours, directions


def _pvlib_sums(weather, hours, directions, normal, model, albedo):
    """Σ over ``hours`` of pvlib's poa_direct, poa_sky_diffuse, poa_ground_diffuse and their
    components for the plane of ``normal`` (NaN hours count 0), in kWh/m²."""
    import pvlib

    d = directions[hours]
    zenith = np.degrees(np.arccos(np.clip(d[:, 2], -1, 1)))
    azimuth = np.degrees(np.arctan2(d[:, 0], d[:, 1])) % 360.0
    tilt = math.degrees(math.acos(normal[2]))
    surface_az = math.degrees(math.atan2(normal[0], normal[1])) % 360.0 \
        if math.hypot(normal[0], normal[1]) > 1e-9 else 0.0
    r = pvlib.irradiance.get_total_irradiance(
        tilt, surface_az, zenith, azimuth, weather.dni_w_m2[hours], weather.ghi_w_m2[hours],
        weather.dhi_w_m2[hours],
        dni_extra=pvlib.irradiance.get_extra_radiation(weather.sun_times[hours]),
        airmass=pvlib.atmosphere.get_relative_airmass(zenith), albedo=albedo, model=model,
        diffuse_components=True)
    return {k: float(np.nansum(np.asarray(v, np.float64))) / 1000.0 for k, v in r.items()}


@pytest.mark.parametrize("model", ["perez", "isotropic", "haydavies"])
def test_an_unobstructed_plane_gets_pvlib_s_total_irradiance(setting, model):
    from cityshade.light import named_sky, sky_visibility
    from cityshade.light.irradiance import irradiation, sky_shares

    scene, weather, hours, directions = setting
    # 1 km from the canopy: nothing in any direction of the sky or towards any sun.
    points = np.tile([X0 + 1000.0, Y0, 10.0], (len(NORMALS), 1)) - scene.origin_m
    vis = sky_visibility(scene, points, NORMALS, named_sky("tregenza"))
    _, share, hshare = sky_shares(vis)
    np.testing.assert_array_equal(share, 1.0)
    np.testing.assert_array_equal(hshare, 1.0)
    got = irradiation(scene, points, NORMALS, weather, directions, (share, hshare), hours=hours,
                      model=model, albedo=0.2)
    for i, n in enumerate(NORMALS):
        want = _pvlib_sums(weather, hours, directions, n, model, 0.2)
        assert got.direct_kwh_m2[i] == pytest.approx(want["poa_direct"], rel=1e-9, abs=1e-12)
        assert got.diffuse_kwh_m2[i] == pytest.approx(want["poa_sky_diffuse"], rel=1e-9,
                                                      abs=1e-12)
        assert got.reflected_kwh_m2[i] == pytest.approx(want["poa_ground_diffuse"], rel=1e-9,
                                                        abs=1e-12)
        assert got.total_kwh_m2[i] == pytest.approx(want["poa_global"], rel=1e-9)
    assert got.total_kwh_m2[0] > 8.0  # 8 days of June and December: a real sum


def test_under_a_roof_only_the_ground_and_the_visible_sky(setting):
    """Under the canopy's centre, a south wall and the ground: the ground-reflected part is
    pvlib's, the diffuse part is the isotropic sky times the visible share of the sky, and the
    direct part counts exactly the hours whose sun ray the raytrace engine finds free."""
    from cityshade.light import named_sky, sky_view_factor, sky_visibility
    from cityshade.light.irradiance import irradiation, sky_shares
    from cityshade.shadows.visibility import occluded
    from cityshade.trace import shadow_rays_from_surface

    scene, weather, hours, directions = setting
    normals = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    points = np.array([[X0, Y0, 1.0], [X0, Y0, 0.0], [X0, Y0 - 19.0, 2.5]]) - scene.origin_m
    vis = sky_visibility(scene, points, normals, named_sky("tregenza"))
    svf, share, hshare = sky_shares(vis)
    np.testing.assert_allclose(svf, sky_view_factor(vis), rtol=1e-12)
    assert (share < 0.5).all()
    got = irradiation(scene, points, normals, weather, directions, (share, hshare), hours=hours,
                      engine="izb", model="isotropic", albedo=0.3)
    # The reference's sun bits: the raytrace engine, one ray per receiver and hour.
    direct = np.zeros(len(normals))
    for h in np.flatnonzero(hours & (weather.dni_w_m2 > 0.0)):
        d = directions[h]
        rows = np.flatnonzero(normals @ d > 0.0)
        if len(rows):
            origins = shadow_rays_from_surface(points[rows], normals[rows], d)
            free = ~occluded(scene, origins, d, 0.0, engine="raytrace")
            direct[rows[free]] += weather.dni_w_m2[h] * (normals[rows[free]] @ d)
    for i, n in enumerate(normals):
        free = _pvlib_sums(weather, hours, directions, n, "isotropic", 0.3)
        assert got.reflected_kwh_m2[i] == pytest.approx(free["poa_ground_diffuse"], rel=1e-9,
                                                        abs=1e-12)
        # The unobstructed plane's view factor: 1 horizontal, 1/2 vertical.
        assert got.diffuse_kwh_m2[i] == pytest.approx(
            free["poa_isotropic"] * svf[i] / ((1.0 + n[2]) / 2.0), rel=2e-3)
        assert got.diffuse_kwh_m2[i] < free["poa_sky_diffuse"]
        assert got.direct_kwh_m2[i] == pytest.approx(direct[i] / 1000.0, rel=1e-9, abs=1e-12)
        assert got.direct_kwh_m2[i] < free["poa_direct"]
    # The wall near the edge sees the low southern sun of December more than the centre's.
    assert got.direct_kwh_m2[2] > got.direct_kwh_m2[0] >= 0.0


def test_bad_model_albedo_and_dates(setting):
    from cityshade.errors import UsageError
    from cityshade.light.irradiance import hours_between, irradiation

    scene, weather, _, directions = setting
    one = np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]), np.ones(1), np.ones(1)
    with pytest.raises(UsageError, match="the sky model is one of perez, isotropic, haydavies"):
        irradiation(scene, one[0], one[1], weather, directions, one[2:], model="klucher")
    with pytest.raises(UsageError, match="the albedo must be from 0 to 1, not 1.5"):
        irradiation(scene, one[0], one[1], weather, directions, one[2:], albedo=1.5)
    with pytest.raises(UsageError, match="--from-date must be a day MM-DD or YYYY-MM-DD"):
        hours_between(weather, "13-01", None)
    # Wrapping over the new year: December and January.
    wrap = hours_between(weather, "12-01", "01-31")
    assert wrap.sum() == 62 * 24


@pytest.mark.parametrize("model", ["perez", "haydavies"])
def test_an_open_plane_at_an_instant_gets_pvlib_s_irradiance_of_its_hour(setting, model):
    """W/m² at 12:20 and 07:45 of 11 June, file standard time (UTC−5): the record of the hour
    containing the instant (hour-ending: the records stamped 13:00 and 08:00, found here from
    the file's stamps) with the sun AT the instant = pvlib's get_total_irradiance."""
    import datetime as dt

    import pvlib

    from cityshade.geo.sun import suns_from_instants
    from cityshade.light import named_sky, sky_visibility
    from cityshade.light.irradiance import irradiance_at, sky_shares

    scene, weather, _, _ = setting
    est = dt.timezone(dt.timedelta(hours=-5))
    instants = [dt.datetime(2025, 6, 11, 12, 20, tzinfo=est),
                dt.datetime(2025, 6, 11, 7, 45, tzinfo=est)]
    ends = weather.hour_end
    rows = [int(np.flatnonzero((ends.month == 6) & (ends.day == 11) & (ends.hour == h))[0])
            for h in (13, 8)]
    suns = suns_from_instants(instants, scene.crs, scene.origin_m)
    directions = np.array([s.direction for s in suns])
    points = np.tile([X0 + 1000.0, Y0, 10.0], (len(NORMALS), 1)) - scene.origin_m
    vis = sky_visibility(scene, points, NORMALS, named_sky("tregenza"))
    got = irradiance_at(scene, points, NORMALS, weather, instants, directions,
                        sky_shares(vis)[1:], model=model, albedo=0.2)
    # The sun at the instant, against pvlib's own SPA (refraction aside: a few hundredths of
    # a degree at these elevations).
    for sun, t in zip(suns, instants):
        pos = pvlib.solarposition.get_solarposition(t, sun.latitude_deg, sun.longitude_deg)
        assert sun.elevation_deg == pytest.approx(float(pos["apparent_elevation"].iloc[0]),
                                                  abs=0.05)
    for k, (row, d, t) in enumerate(zip(rows, directions, instants)):
        zenith = math.degrees(math.acos(d[2]))
        azimuth = math.degrees(math.atan2(d[0], d[1])) % 360.0
        for i, n in enumerate(NORMALS):
            tilt = math.degrees(math.acos(n[2]))
            surface_az = math.degrees(math.atan2(n[0], n[1])) % 360.0 \
                if math.hypot(n[0], n[1]) > 1e-9 else 0.0
            r = pvlib.irradiance.get_total_irradiance(
                tilt, surface_az, zenith, azimuth, weather.dni_w_m2[row], weather.ghi_w_m2[row],
                weather.dhi_w_m2[row], dni_extra=pvlib.irradiance.get_extra_radiation(
                    pd_timestamp(t)), airmass=pvlib.atmosphere.get_relative_airmass(zenith),
                albedo=0.2, model=model, diffuse_components=True)
            want = [float(np.nan_to_num(r[c])) for c in ("poa_direct", "poa_sky_diffuse",
                                                         "poa_ground_diffuse")]
            np.testing.assert_allclose(got[k, i], want, rtol=1e-9, atol=1e-9)
    assert got[0, 0].sum() > 300.0      # a real June noon


def pd_timestamp(t):
    import pandas as pd

    return pd.Timestamp(t)


def test_exact_is_chosen_once_for_the_hours(setting, monkeypatch):
    """``exact`` picks one engine for the whole run of hours (as batch does): chosen hour by
    hour, each hour would count izb's caster sort as its own and never take izb."""
    import cityshade.light.irradiance as irr
    from cityshade.shadows.exact import engine_for_run

    scene, weather, hours, directions = setting
    points = np.array([[X0, Y0, 0.0]]) - scene.origin_m
    normals = np.array([[0.0, 0.0, 1.0]])
    used = []
    real = irr.receiver_sun
    monkeypatch.setattr(irr, "receiver_sun", lambda *a: used.append(a[5]) or real(*a))
    todo = hours & ((weather.ghi_w_m2 > 0) | (weather.dni_w_m2 > 0) | (weather.dhi_w_m2 > 0))
    irr.irradiation(scene, points, normals, weather, directions, (np.ones(1), np.ones(1)),
                    hours=hours, engine="exact")
    assert used and set(used) == {engine_for_run("exact", scene, 1, int(todo.sum()))}


def test_hours_are_traced_grouped_by_the_casters_key_order(setting, monkeypatch):
    """The hours go to the engine grouped by izb's caster key order (five groups at most, where
    eight days in time order change it three times a day), and the sums match those of one hour
    at a time in time order."""
    import cityshade.light.irradiance as irr
    from cityshade.lightspace import caster_order

    scene, weather, hours, directions = setting
    points = np.array([[X0, Y0, 0.0], [X0, Y0 - 19.0, 2.5]]) - scene.origin_m
    normals = np.array([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
    shares = (np.ones(2), np.ones(2))
    seen = []
    real = irr.receiver_sun
    monkeypatch.setattr(irr, "receiver_sun",
                        lambda *a: seen.append(caster_order(a[3])) or real(*a))
    got = irr.irradiation(scene, points, normals, weather, directions, shares, hours=hours,
                          engine="raytrace")
    changes = sum(a != b for a, b in zip(seen[:-1], seen[1:]))
    assert len(seen) > 50 and changes == len(set(seen)) - 1 <= 4
    monkeypatch.setattr(irr, "receiver_sun", real)
    one_by_one = np.zeros((2, 3))
    for h in np.flatnonzero(hours):
        mask = np.zeros_like(hours)
        mask[h] = True
        part = irr.irradiation(scene, points, normals, weather, directions, shares, hours=mask,
                               engine="raytrace")
        one_by_one += np.stack([part.direct_kwh_m2, part.diffuse_kwh_m2,
                                part.reflected_kwh_m2], axis=1)
    np.testing.assert_allclose(np.stack([got.direct_kwh_m2, got.diffuse_kwh_m2,
                                         got.reflected_kwh_m2], axis=1), one_by_one,
                               rtol=1e-12)
