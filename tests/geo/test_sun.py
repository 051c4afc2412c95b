"""Sun direction conventions: azimuth clockwise from true north, grid north via convergence."""
from __future__ import annotations

import math

import numpy as np
import pytest

from cityshade.geo.crs import parse_srs_name
from cityshade.errors import UsageError
from cityshade.geo.sun import direction_from_angles, sun_from_angles


@pytest.mark.parametrize("az, el, expected", [
    (0, 0, (0, 1, 0)), (90, 0, (1, 0, 0)), (180, 0, (0, -1, 0)), (270, 0, (-1, 0, 0)),
    (123, 90, (0, 0, 1)),
    (135, 30, (math.sin(math.radians(135)) * math.cos(math.radians(30)),
               math.cos(math.radians(135)) * math.cos(math.radians(30)), 0.5)),
])
def test_direction_convention(az, el, expected):
    np.testing.assert_allclose(direction_from_angles(az, el), expected, atol=1e-15)


def test_zenith_is_exactly_vertical():
    assert direction_from_angles(200.0, 90.0).tolist() == [0.0, 0.0, 1.0]


def test_grid_north_uses_pyproj_convergence():
    """EPSG:25832 far west of the 9°E meridian: grid azimuth = true azimuth − γ (pyproj's γ)."""
    from pyproj import Proj

    crs = parse_srs_name("EPSG:25832")
    x, y = 300_000.0, 5_500_000.0
    lon, lat = Proj("EPSG:25832")(x, y, inverse=True)
    gamma = Proj("EPSG:25832").get_factors(lon, lat).meridian_convergence
    assert gamma < -1.0  # about −2° here: the test would not notice a missing correction
    sun = sun_from_angles(180.0, 40.0, crs, np.array([x, y, 0.0]))
    assert sun.convergence_deg == pytest.approx(gamma, abs=1e-6)
    assert sun.azimuth_grid_deg == pytest.approx(180.0 - gamma, abs=1e-6)
    np.testing.assert_allclose(sun.direction, direction_from_angles(180.0 - gamma, 40.0))


def test_local_crs_and_validation():
    sun = sun_from_angles(370.0, -5.0, parse_srs_name("#local-CRS-1"), np.zeros(3))
    assert sun.azimuth_true_deg == pytest.approx(10.0) and sun.convergence_deg == 0.0
    assert not sun.above_horizon and "no CRS" in sun.note
    with pytest.raises(UsageError, match="between -90 and 90"):
        sun_from_angles(0.0, 91.0)
    with pytest.raises(UsageError, match="finite"):
        sun_from_angles(float("nan"), 10.0)
