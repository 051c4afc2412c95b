"""Discretisations of the upper hemisphere: the Tregenza and Reinhart sky patches, a uniform set.

Conventions (docs/DESIGN.md §1, §18): directions are unit vectors in render space, x east,
y north (GRID north of the scene's CRS), z up; an azimuth is in degrees clockwise from north
seen from above (``x = sin(az) cos(alt)``, ``y = cos(az) cos(alt)``, ``z = sin(alt)``), an
altitude in degrees above the horizon. Every patch is a rectangle in (altitude, azimuth):
``[alt_lo, alt_hi] x [az_lo, az_hi]``, so its solid angle is exact,
``Ω = Δaz (sin alt_hi − sin alt_lo)`` (radians), and the solid angles sum to 2π.

The patches follow Radiance's ``reinhart.cal`` (G. Ward 2009, from ``tregenza.cal``) with
multiplication factor ``MF``: ``7·MF`` rows of height ``α = 90° / (7·MF + 0.5)`` (12° for
MF = 1), row ``r`` holding ``MF × (30, 30, 24, 24, 18, 12, 6)[r // MF]`` patches, then one
polar cap of radius ``α / 2`` (the zenith patch). MF = 1 is Tregenza's 145 patches
(Tregenza 1987, Lighting Res. Technol. 19(1)), MF = 2 gives 577 and MF = 4 gives 2,305. In each
row the first patch is centred on north (``az = 0``) and the patches follow clockwise; a
patch's centre is the middle of its altitude and azimuth ranges (Radiance's ``x1 = x2 = .5``).
Radiance's patch 0 (the ground) is not part of a sky here.

A sky of patches is not symmetric under rotation, so the patches are laid out around TRUE
north and turned into grid north by the meridian convergence γ at the scene's origin
(``azimuth_grid = azimuth_true − γ``, as :mod:`cityshade.geo.sun` turns the sun): see
:func:`sky_for_scene`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from cityshade.errors import UsageError

#: Patches per Tregenza row, from the horizon up (the zenith cap apart): the standard table
#: (Tregenza 1987; Radiance ``tregenza.cal`` / ``reinhart.cal``: ``tnaz``).
TREGENZA_ROW_PATCHES = (30, 30, 24, 24, 18, 12, 6)

#: Named skies: name → Reinhart multiplication factor (``tregenza`` = MF 1, 145 patches).
SKY_NAMES = {"tregenza": 1, "reinhart577": 2, "reinhart2305": 4}

#: The sky the library uses when none is named: 2,305 patches. The closed-form tests
#: (tests/light) hold to 0.005 in the sky view factor and 0.2 points in the VSC with it; a patch
#: is seen or not by its centre, and with 577 patches a street canyon's view factor is already
#: 0.008 too high (0.020 with Tregenza's 145), so coarser skies are for quick looks.
DEFAULT_SKY = "reinhart2305"

#: A direction counts as in front of a receiver when ``cos(angle to the normal)`` exceeds this.
#: Exactly in the plane (the zenith seen from a vertical wall, whose float32 normal carries
#: ~1e-8 of z) is not in front: a ray grazing its own surface decides nothing.
FRONT_MIN_COS = 1e-6


@dataclass(frozen=True)
class Sky:
    """Patches of the upper hemisphere, each with its centre direction and exact solid angle.

    Attributes
    ----------
    name : str
        ``tregenza``, ``reinhart577``, ``reinhart2305`` or ``uniform<step>``.
    directions : (P, 3) float64
        Unit centre directions in render space (x east, y grid north, z up).
    altitude_deg, azimuth_deg : (P,) float64
        Centre altitude; centre azimuth clockwise from GRID north, in [0, 360).
    band : (P,) int32
        Row of the patch, 0 at the horizon (the zenith cap is the last row).
    solid_angle_sr : (P,) float64
        Exact solid angle of each patch, steradians; the sum is 2π.
    alt_lo_deg, alt_hi_deg, az_lo_deg, az_hi_deg : (P,) float64
        The patch's bounds; azimuths clockwise from grid north, ``az_hi > az_lo`` (a range may
        run past 360°; the zenith cap spans 360°).
    convergence_deg : float
        Meridian convergence γ the patches were turned by (true north = grid north + γ).
    """

    name: str
    directions: np.ndarray
    altitude_deg: np.ndarray
    azimuth_deg: np.ndarray
    band: np.ndarray
    solid_angle_sr: np.ndarray
    alt_lo_deg: np.ndarray
    alt_hi_deg: np.ndarray
    az_lo_deg: np.ndarray
    az_hi_deg: np.ndarray
    convergence_deg: float = 0.0

    @property
    def n(self) -> int:
        """Number of patches P."""
        return int(len(self.solid_angle_sr))

    def subsamples(self, k: int = 4) -> tuple[np.ndarray, np.ndarray]:
        """Gauss–Legendre points of every patch, for integrals over patches.

        Each patch is ``[sin alt_lo, sin alt_hi] × [az_lo, az_hi]`` in (u = sin alt, az), where
        ``dΩ = du daz``; a k × k Gauss–Legendre rule there integrates a function that is smooth
        over the patch to high order (exact for polynomials of degree 2k − 1 in u and az).

        Parameters
        ----------
        k : int
            Points per axis (k² per patch).

        Returns
        -------
        directions : (P, k², 3) float64
            Unit directions of the points.
        solid_angle_sr : (P, k²) float64
            Their weights; each patch's row sums to its solid angle.

        Examples
        --------
        >>> sky = reinhart_sky(1)
        >>> d, w = sky.subsamples(3)
        >>> d.shape, round(float(w.sum()), 12) == round(2 * math.pi, 12)
        ((145, 9, 3), True)
        """
        if not (isinstance(k, (int, np.integer)) and 1 <= k <= 64):
            raise UsageError(f"subsamples per axis must be an integer from 1 to 64, not {k!r}")
        x, w = np.polynomial.legendre.leggauss(int(k))
        u_lo, u_hi = np.sin(np.radians(self.alt_lo_deg)), np.sin(np.radians(self.alt_hi_deg))
        a_lo, a_hi = np.radians(self.az_lo_deg), np.radians(self.az_hi_deg)
        u = 0.5 * (u_lo + u_hi)[:, None] + 0.5 * (u_hi - u_lo)[:, None] * x[None]
        az = 0.5 * (a_lo + a_hi)[:, None] + 0.5 * (a_hi - a_lo)[:, None] * x[None]
        uu = np.repeat(u, k, axis=1)             # (P, k²): u varies slowest
        aa = np.tile(az, (1, k))
        ww = (0.25 * (u_hi - u_lo) * (a_hi - a_lo))[:, None] * np.outer(w, w).reshape(1, -1)
        c = np.sqrt(np.clip(1.0 - uu * uu, 0.0, 1.0))
        d = np.stack([np.sin(aa) * c, np.cos(aa) * c, uu], axis=-1)
        return d, ww


def _sky(name, alt_lo, alt_hi, az_lo_true, az_hi_true, band, convergence_deg) -> Sky:
    """A :class:`Sky` from patch bounds given around TRUE north, turned to grid north."""
    gamma = float(convergence_deg)
    az_lo = np.asarray(az_lo_true, np.float64) - gamma
    az_hi = np.asarray(az_hi_true, np.float64) - gamma
    alt_lo = np.asarray(alt_lo, np.float64)
    alt_hi = np.asarray(alt_hi, np.float64)
    cap = alt_hi >= 90.0
    # Radiance's centre: the middle of the altitude and azimuth ranges; the cap's is the zenith.
    alt_c = np.where(cap & (az_hi - az_lo >= 360.0), 90.0, 0.5 * (alt_lo + alt_hi))
    az_c = np.mod(0.5 * (az_lo + az_hi), 360.0)
    a, e = np.radians(az_c), np.radians(alt_c)
    d = np.column_stack([np.sin(a) * np.cos(e), np.cos(a) * np.cos(e), np.sin(e)])
    d[alt_c == 90.0] = (0.0, 0.0, 1.0)
    omega = np.radians(az_hi - az_lo) * (np.sin(np.radians(alt_hi)) - np.sin(np.radians(alt_lo)))
    return Sky(name=name, directions=d, altitude_deg=alt_c, azimuth_deg=az_c,
               band=np.asarray(band, np.int32), solid_angle_sr=omega, alt_lo_deg=alt_lo,
               alt_hi_deg=alt_hi, az_lo_deg=az_lo, az_hi_deg=az_hi, convergence_deg=gamma)


def reinhart_sky(mf: int = 1, convergence_deg: float = 0.0) -> Sky:
    """The Reinhart subdivision of the Tregenza sky with multiplication factor ``mf``.

    Parameters
    ----------
    mf : int
        1 (Tregenza, 145 patches), 2 (577) or 4 (2,305); any integer ≥ 1 works
        (``144·mf² + 1`` patches).
    convergence_deg : float
        Meridian convergence γ at the scene's origin (:func:`cityshade.geo.crs.grid_convergence_deg`):
        patches are laid out around true north and stored around grid north.

    Returns
    -------
    Sky

    Examples
    --------
    >>> sky = reinhart_sky(2)
    >>> sky.n, bool(abs(sky.solid_angle_sr.sum() - 2 * math.pi) < 1e-12)
    (577, True)
    >>> float(sky.altitude_deg[0]), float(sky.azimuth_deg[0])
    (3.103448275862069, 0.0)
    """
    if not (isinstance(mf, (int, np.integer)) and 1 <= mf <= 16):
        raise UsageError(f"the Reinhart multiplication factor must be an integer from 1 to 16, "
                         f"not {mf!r}")
    mf = int(mf)
    row_deg = 90.0 / (7 * mf + 0.5)
    alt_lo, alt_hi, az_lo, az_hi, band = [], [], [], [], []
    for r in range(7 * mf):
        n = mf * TREGENZA_ROW_PATCHES[r // mf]
        width = 360.0 / n
        col = np.arange(n)
        # Radiance: the patch of column c is centred on azimuth c·width (column 0 on north).
        az_lo.append((col - 0.5) * width)
        az_hi.append((col + 0.5) * width)
        alt_lo.append(np.full(n, r * row_deg))
        alt_hi.append(np.full(n, (r + 1) * row_deg))
        band.append(np.full(n, r))
    alt_lo.append([7 * mf * row_deg])
    alt_hi.append([90.0])
    az_lo.append([0.0])
    az_hi.append([360.0])
    band.append([7 * mf])
    name = {v: k for k, v in SKY_NAMES.items()}.get(mf, f"reinhart{144 * mf * mf + 1}")
    return _sky(name, np.concatenate(alt_lo), np.concatenate(alt_hi), np.concatenate(az_lo),
                np.concatenate(az_hi), np.concatenate(band), convergence_deg)


def tregenza_sky(convergence_deg: float = 0.0) -> Sky:
    """Tregenza's 145 patches (:func:`reinhart_sky` with MF = 1).

    Examples
    --------
    >>> sky = tregenza_sky()
    >>> [int((sky.band == b).sum()) for b in range(8)]
    [30, 30, 24, 24, 18, 12, 6, 1]
    """
    return reinhart_sky(1, convergence_deg)


def uniform_sky(step_deg: float = 2.0, convergence_deg: float = 0.0) -> Sky:
    """A dense, nearly uniform set (for tests and references): rows of ``step_deg`` altitude,
    each cut into ``max(1, round(360 cos(alt_mid) / step_deg))`` equal azimuth ranges, so the
    patches are close to squares of ``step_deg`` on a side; the top row touches the zenith.

    Parameters
    ----------
    step_deg : float
        Row height, degrees; 90 / step_deg rows (rounded up; the last row is shorter).
    convergence_deg : float
        As :func:`reinhart_sky`.

    Examples
    --------
    >>> sky = uniform_sky(1.0)
    >>> sky.n > 20_000, bool(abs(sky.solid_angle_sr.sum() - 2 * math.pi) < 1e-11)
    (True, True)
    """
    step = float(step_deg)
    if not (math.isfinite(step) and 0.05 <= step <= 45.0):
        raise UsageError(f"the uniform sky's step must be 0.05 to 45 degrees, not {step_deg!r}")
    edges = np.append(np.arange(0.0, 90.0, step), 90.0)
    alt_lo, alt_hi, az_lo, az_hi, band = [], [], [], [], []
    for r, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        n = max(1, round(360.0 * math.cos(math.radians(0.5 * (lo + hi))) / step))
        width = 360.0 / n
        col = np.arange(n)
        az_lo.append((col - 0.5) * width)
        az_hi.append((col + 0.5) * width)
        alt_lo.append(np.full(n, lo))
        alt_hi.append(np.full(n, hi))
        band.append(np.full(n, r))
    return _sky(f"uniform{step:g}", np.concatenate(alt_lo), np.concatenate(alt_hi),
                np.concatenate(az_lo), np.concatenate(az_hi), np.concatenate(band),
                convergence_deg)


def named_sky(name: str = DEFAULT_SKY, convergence_deg: float = 0.0) -> Sky:
    """A sky by name: ``tregenza`` (145), ``reinhart577``, ``reinhart2305``, ``uniform<step°>``.

    Raises
    ------
    UsageError
        An unknown name.

    Examples
    --------
    >>> named_sky("reinhart2305").n
    2305
    """
    if name in SKY_NAMES:
        return reinhart_sky(SKY_NAMES[name], convergence_deg)
    if name.startswith("uniform"):
        try:
            step = float(name[len("uniform"):] or 2.0)
        except ValueError:
            step = float("nan")
        return uniform_sky(step, convergence_deg)
    raise UsageError(f"unknown sky {name!r}: one of {', '.join(SKY_NAMES)} or uniform<degrees>")


def sky_for_scene(scene, name: str = DEFAULT_SKY) -> Sky:
    """The sky ``name`` laid out around the true north of ``scene`` (its CRS's meridian
    convergence at the origin, as :func:`cityshade.geo.sun.sun_from_angles` turns the sun).

    A scene with no CRS (or a local one) has no true north: its +y axis is taken as north,
    as for the sun.

    Examples
    --------
    >>> class NoCrs:  # a scene without a CRS
    ...     crs = None
    ...     origin_m = (0.0, 0.0, 0.0)
    >>> sky_for_scene(NoCrs(), "tregenza").convergence_deg
    0.0
    """
    crs = scene.crs
    gamma = 0.0
    if crs is not None and not crs.local and crs.horizontal_epsg is not None \
            and not crs.is_geographic:
        from cityshade.geo.crs import grid_convergence_deg

        gamma = grid_convergence_deg(crs, float(scene.origin_m[0]), float(scene.origin_m[1]))
    return named_sky(name, gamma)


def in_front(normals, directions) -> np.ndarray:
    """(N, P) bool: whether each direction lies in front of each receiver's plane
    (``n · d > FRONT_MIN_COS``). The one test shared by the tracing and the weights.

    Parameters
    ----------
    normals : (N, 3) float array
        Unit receiver normals.
    directions : (P, 3) float array
        Unit directions.

    Examples
    --------
    >>> in_front([[0.0, -1.0, 0.0]], [[0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])  # a south wall
    array([[ True, False]])
    """
    from cityshade.light.kernels import in_front_table

    n = np.ascontiguousarray(normals, np.float64).reshape(-1, 3)
    d = np.ascontiguousarray(directions, np.float64).reshape(-1, 3)
    out = np.empty((len(n), len(d)), bool)
    in_front_table(n, d, FRONT_MIN_COS, out)  # the tracing's own test (light/kernels.py)
    return out
