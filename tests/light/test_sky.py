"""Sky discretisations: the Tregenza table, Reinhart subdivisions, solid angles, north."""
from __future__ import annotations

import math

import numpy as np
import pytest

from cityshade.errors import UsageError
from cityshade.light.sky import (in_front, named_sky, reinhart_sky, tregenza_sky,
                                 uniform_sky)


def test_tregenza_matches_the_standard_table():
    sky = tregenza_sky()
    assert sky.n == 145
    # Tregenza (1987): 7 bands of 12° altitude with 30, 30, 24, 24, 18, 12, 6 patches, a cap.
    assert [int((sky.band == b).sum()) for b in range(8)] == [30, 30, 24, 24, 18, 12, 6, 1]
    for b, centre in enumerate([6, 18, 30, 42, 54, 66, 78, 90]):
        np.testing.assert_allclose(sky.altitude_deg[sky.band == b], centre, atol=1e-12)
    # Published solid angles: 0.0435 sr in the lowest band, 0.0344 sr for the zenith patch.
    assert sky.solid_angle_sr[0] == pytest.approx(2 * math.pi / 30 * math.sin(math.radians(12)),
                                                  rel=1e-12)
    assert round(float(sky.solid_angle_sr[0]), 4) == 0.0435
    assert round(float(sky.solid_angle_sr[-1]), 4) == 0.0344


@pytest.mark.parametrize("sky,n", [(tregenza_sky(), 145), (reinhart_sky(2), 577),
                                   (reinhart_sky(4), 2305), (uniform_sky(2.0), None),
                                   (named_sky("uniform0.5"), None)])
def test_solid_angles_sum_to_two_pi(sky, n):
    if n is not None:
        assert sky.n == n
    assert abs(sky.solid_angle_sr.sum() - 2 * math.pi) < 1e-11
    assert (sky.solid_angle_sr > 0).all()
    np.testing.assert_allclose(np.linalg.norm(sky.directions, axis=1), 1.0, atol=1e-15)
    np.testing.assert_allclose(sky.directions[:, 2], np.sin(np.radians(sky.altitude_deg)),
                               atol=1e-15)


def test_reinhart_rows_follow_radiance():
    # reinhart.cal: rows of 90 / (7 MF + 0.5) degrees, MF × the Tregenza count, one cap.
    sky = reinhart_sky(2)
    row = 90.0 / 14.5
    assert sky.alt_hi_deg[0] == pytest.approx(row)
    assert [int((sky.band == b).sum()) for b in range(15)] == \
        [60, 60, 60, 60, 48, 48, 48, 48, 36, 36, 24, 24, 12, 12, 1]
    assert sky.alt_lo_deg[-1] == pytest.approx(90.0 - row / 2)


def test_azimuth_is_clockwise_from_north_and_turned_to_grid_north():
    sky = tregenza_sky()
    alt = math.radians(6.0)
    np.testing.assert_allclose(sky.directions[0], [0.0, math.cos(alt), math.sin(alt)],
                               atol=1e-15)
    # The second patch of the lowest band is 12° east of north: x > 0.
    a = math.radians(12.0)
    np.testing.assert_allclose(sky.directions[1], [math.sin(a) * math.cos(alt),
                                                   math.cos(a) * math.cos(alt), math.sin(alt)],
                               atol=1e-15)
    # Grid north 7° east of true north (γ = 7): a true azimuth of 0 is a grid azimuth of -7.
    turned = tregenza_sky(7.0)
    g = math.radians(-7.0)
    np.testing.assert_allclose(turned.directions[0], [math.sin(g) * math.cos(alt),
                                                      math.cos(g) * math.cos(alt),
                                                      math.sin(alt)], atol=1e-15)
    assert turned.azimuth_deg[0] == pytest.approx(353.0)
    np.testing.assert_allclose(turned.solid_angle_sr, sky.solid_angle_sr)


def test_subsamples_integrate_the_hemisphere():
    for sky in (tregenza_sky(3.0), reinhart_sky(4)):
        d, w = sky.subsamples(4)
        np.testing.assert_allclose(w.sum(axis=1), sky.solid_angle_sr, rtol=1e-12)
        # ∫ sin(alt) dΩ = π, ∫ sin²(alt) dΩ = 2π/3, ∫ x² dΩ = 2π/3 over the upper hemisphere.
        assert (w * d[..., 2]).sum() == pytest.approx(math.pi, rel=1e-12)
        assert (w * d[..., 2] ** 2).sum() == pytest.approx(2 * math.pi / 3, rel=1e-12)
        assert (w * d[..., 0] ** 2).sum() == pytest.approx(2 * math.pi / 3, rel=1e-5)


def test_in_front_and_bad_names():
    sky = tregenza_sky()
    wall = in_front([[0.0, -1.0, 0.0]], sky.directions)[0]
    assert not wall[-1]                      # the zenith lies in a vertical wall's plane
    assert wall.sum() == (sky.directions[:, 1] < -1e-6).sum()
    with pytest.raises(UsageError, match="unknown sky"):
        named_sky("perez")
    with pytest.raises(UsageError):
        reinhart_sky(0)
    with pytest.raises(UsageError):
        uniform_sky(0.0)
