"""The sun as a direction in render space.

Convention (DESIGN §3): azimuth in degrees clockwise from TRUE north, elevation in degrees above
the horizon. Render space has grid north (+y of the projected CRS), which differs from true
north by the meridian convergence γ at the model's origin: ``azimuth_grid = azimuth_true − γ``
(γ > 0 where grid north lies east of true north; :func:`cityshade.citygml.crs.grid_convergence_deg`).
The sun is a direction, never a far-away point: float32 far points broke a peer (HORAYZON #12).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from cityshade.errors import UsageError


@dataclass(frozen=True)
class SunPosition:
    """A resolved sun position.

    Attributes
    ----------
    azimuth_true_deg, elevation_deg : float
        Clockwise from true north; above the horizon.
    azimuth_grid_deg : float
        Clockwise from grid north (+y of render space).
    convergence_deg : float
        Meridian convergence used (0 for a model without CRS).
    direction : (3,) float64
        Unit vector towards the sun in render space.
    source : str
        "explicit" (given angles) or the algorithm that computed it.
    note : str or None
        A caveat for the metadata (e.g. no CRS: grid north assumed true).
    """

    azimuth_true_deg: float
    elevation_deg: float
    azimuth_grid_deg: float
    convergence_deg: float
    direction: np.ndarray
    source: str = "explicit"
    note: str | None = None

    @property
    def above_horizon(self) -> bool:
        """True when the sun lights anything (elevation strictly above 0°)."""
        return self.elevation_deg > 0.0

    def metadata(self) -> dict:
        d = asdict(self)
        d["direction"] = [float(v) for v in self.direction]
        return d


def direction_from_angles(azimuth_deg: float, elevation_deg: float) -> np.ndarray:
    """Unit vector towards the sun: x east, y north (of the azimuth's frame), z up."""
    az, el = math.radians(azimuth_deg), math.radians(elevation_deg)
    # Exact values at the zenith and on the axes keep "sun at 90°" exactly vertical.
    d = np.array([math.sin(az) * math.cos(el), math.cos(az) * math.cos(el), math.sin(el)])
    if elevation_deg == 90.0:
        d = np.array([0.0, 0.0, 1.0])
    return d / np.linalg.norm(d)


def sun_from_angles(azimuth_true_deg: float, elevation_deg: float, crs=None,
                    origin_m=None) -> SunPosition:
    """Sun position from explicit angles, converted to grid north of the model's CRS.

    Parameters
    ----------
    azimuth_true_deg : float
        Degrees clockwise from true north (any value; taken modulo 360).
    elevation_deg : float
        Degrees above the horizon, in [-90, 90].
    crs : CrsInfo, optional
        The model CRS; a local or missing CRS means grid north is taken as true north.
    origin_m : (3,) array, optional
        Model origin in CRS coordinates (where the convergence is evaluated).

    Raises
    ------
    UsageError
        Non-finite angles or an elevation outside [-90, 90].
    """
    if not (math.isfinite(azimuth_true_deg) and math.isfinite(elevation_deg)):
        raise UsageError("sun azimuth and elevation must be finite numbers of degrees")
    if not -90.0 <= elevation_deg <= 90.0:
        raise UsageError(f"sun elevation must be between -90 and 90 degrees, not {elevation_deg}")
    azimuth_true_deg = azimuth_true_deg % 360.0
    convergence = 0.0
    note = None
    if crs is None or crs.local or crs.horizontal_epsg is None:
        note = "the model has no CRS: azimuth measured from the model's +y axis"
    elif origin_m is not None and not crs.is_geographic:
        from cityshade.citygml.crs import grid_convergence_deg

        convergence = grid_convergence_deg(crs, float(origin_m[0]), float(origin_m[1]))
    azimuth_grid = (azimuth_true_deg - convergence) % 360.0
    return SunPosition(azimuth_true_deg=azimuth_true_deg, elevation_deg=elevation_deg,
                       azimuth_grid_deg=azimuth_grid, convergence_deg=convergence,
                       direction=direction_from_angles(azimuth_grid, elevation_deg), note=note)
