"""Sky view factor and vertical sky component from the visibility bits of a sky.

Both are integrals over the part of the sky a receiver sees, weighted by the cosine of the
angle to its normal and by a sky luminance:

``I(L) = Σ_p bit_p ∫_{patch p ∩ front} L(d) (n · d) dΩ``.

The cosine and the luminance vary over a patch, so each patch's weight is integrated, not
sampled at its centre: a Gauss–Legendre rule in (sin altitude, azimuth) per patch
(:meth:`cityshade.light.sky.Sky.subsamples`), clipped to the half-space in front of the
receiver. A patch cut by the receiver's plane whose centre lies behind it was not traced
(:mod:`cityshade.light.visibility`); its front part takes the bit of the nearest traced centre
in front, so a free wall sees exactly its half of the sky rather than losing the slivers of the
cut patches (up to 0.005 of a wall's view factor with the 145 patches). The visibility itself is
one bit per patch, decided at the patch's centre: that, not the weights, is the discretisation
error left (docs/DESIGN.md §18).

- **Sky view factor** (Oke 1988; the cosine-weighted view of the sky of a plane):
  ``SVF = I(1) / π``: 1 for open horizontal ground, 0.5 for a free vertical wall,
  ``cos(arctan(2H/W))`` at the floor centre of a long canyon of height H and width W.
- **Vertical sky component** (BRE 209, Littlefair 2022, appendix C): the illuminance on the
  window's plane from the visible CIE standard overcast sky, ``L(α) = L_z (1 + 2 sin α) / 3``
  (Moon & Spencer 1942, CIE S 011 sky type 1), over the illuminance of an unobstructed
  horizontal plane under the same sky, ``7π/9 · L_z``: ``VSC = I(L / L_z) / (7π/9)``,
  0.396 (39.6 %) for an unobstructed vertical window, at the window's centre on its outer face.
"""
from __future__ import annotations

import math

import numpy as np

from cityshade.errors import UsageError

#: Unobstructed horizontal illuminance under the CIE overcast sky, in units of the zenith
#: luminance: ∫ (1 + 2 sin α)/3 · sin α dΩ over the hemisphere = 7π/9.
CIE_OVERCAST_HORIZONTAL = 7.0 * math.pi / 9.0

#: Gauss–Legendre points per patch (all patches together) the weights aim at: about 40,000
#: directions (17² per patch for 145 patches, 4² for 2,305) keep the weight of a free wall within
#: 1e-4 of its closed form while a normal's weights cost ~1 ms.
TARGET_SUBSAMPLES = 40_000

#: Receivers whose unit normals differ by less than this share one row of weights (a wall's
#: float32 normals scatter by ~1e-7; rounding them changes a weight by the same order).
NORMAL_ROUND = 1e-6


def uniform_luminance(directions) -> np.ndarray:
    """A sky of uniform luminance 1: the sky view factor's weighting.

    Examples
    --------
    >>> uniform_luminance(np.zeros((2, 5, 3))).shape
    (2, 5)
    """
    return np.ones(np.asarray(directions).shape[:-1])


def cie_overcast_luminance(directions) -> np.ndarray:
    """CIE standard overcast sky relative to its zenith: ``(1 + 2 sin α) / 3`` with
    ``sin α = d_z`` (render-space z up).

    Examples
    --------
    >>> cie_overcast_luminance(np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]))  # horizon, zenith
    array([0.33333333, 1.        ])
    """
    return (1.0 + 2.0 * np.asarray(directions)[..., 2]) / 3.0


def subsamples_per_axis(sky) -> int:
    """Gauss–Legendre points per patch axis for ``sky`` (:data:`TARGET_SUBSAMPLES`).

    Examples
    --------
    >>> from cityshade.light.sky import named_sky
    >>> subsamples_per_axis(named_sky("tregenza")), subsamples_per_axis(named_sky("reinhart2305"))
    (17, 4)
    """
    return max(2, int(round(math.sqrt(TARGET_SUBSAMPLES / sky.n))))


def distinct_normals(normals) -> tuple[np.ndarray, np.ndarray]:
    """The distinct rows of ``normals`` rounded to :data:`NORMAL_ROUND`, sorted as
    ``np.unique(rounded, axis=0)`` sorts them, and the row of each normal.

    ``np.unique`` along an axis sorts rows as opaque records (17 s for a 1 m map's 2.14 M
    receivers on a loaded 2-core machine); the rounded components are integers of at most 21
    bits (|n| <= 1), so one int64 key per row orders them the same way, at a plain sort's cost.

    Returns
    -------
    unique : (U, 3) float64
        The rounded distinct normals (not renormalised).
    inverse : (N,) int64

    Examples
    --------
    >>> u, inv = distinct_normals([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0 + 1e-8]])
    >>> u.tolist(), inv.tolist()
    ([[0.0, -1.0, 0.0], [0.0, 0.0, 1.0]], [1, 0, 1])
    """
    nrm = np.asarray(normals, np.float64).reshape(-1, 3)
    if not np.isfinite(nrm).all():
        raise UsageError("receiver normals contain NaN or infinite values")
    steps = np.round(nrm / NORMAL_ROUND)
    if np.abs(steps).max(initial=0.0) >= 2.0 ** 20:
        raise UsageError("receiver normals must be unit vectors")
    cells = (steps + 2.0 ** 20).astype(np.int64)          # 0 .. 2^21 - 1 per component
    keys = (cells[:, 0] << 42) | (cells[:, 1] << 21) | cells[:, 2]
    # Neighbouring receivers (a map's pixels) mostly share their normal: the sort is over the
    # runs of equal keys (a 1 m map's 2.14 M receivers: 0.29 s for every row).
    runs = np.flatnonzero(np.concatenate(([True], keys[1:] != keys[:-1]))) if len(keys) else \
        np.zeros(0, np.int64)
    unique_keys, run_inverse = np.unique(keys[runs], return_inverse=True)
    inverse = np.repeat(run_inverse.reshape(-1), np.diff(np.append(runs, len(keys))))
    unique = np.stack([((unique_keys >> s) & ((1 << 21) - 1)) - 2 ** 20 for s in (42, 21, 0)],
                      axis=1).astype(np.float64) * NORMAL_ROUND
    return unique, inverse.reshape(-1)


#: A patch counts as wholly in front of (behind) a plane when its farthest (nearest)
#: subsample's cosine to the normal is bounded above (below) zero by this much.
_WHOLE_MARGIN = 1e-9


def patch_weights(sky, normals, luminance=uniform_luminance, *, k: int | None = None
                  ) -> tuple[np.ndarray, np.ndarray]:
    """The weight of every patch for every distinct receiver normal.

    ``W[u, p] = ∫ L(d) max(0, n_u · d) dΩ`` over patch p (steradians × luminance), the front
    parts of the patches whose centres lie behind the plane moved to the nearest centre in front
    (see the module's docstring).

    Parameters
    ----------
    sky : Sky
    normals : (N, 3) float array
        Unit receiver normals.
    luminance : callable
        ``luminance(directions (..., 3)) -> (...)`` relative sky luminance.
    k : int, optional
        Gauss–Legendre points per patch axis (default :func:`subsamples_per_axis`).

    Returns
    -------
    weights : (U, P) float64
        One row per distinct normal (rounded to :data:`NORMAL_ROUND`).
    inverse : (N,) int64
        Row of ``weights`` of each receiver.

    Examples
    --------
    >>> from cityshade.light.sky import named_sky
    >>> w, inv = patch_weights(named_sky("tregenza"), [[0.0, -1.0, 0.0]])
    >>> round(float(w[inv[0]].sum() / math.pi), 3)     # a free vertical wall
    0.5
    """
    from cityshade.light.kernels import patch_weight_rows
    from cityshade.light.sky import in_front

    unique, inverse = distinct_normals(normals)
    d, w = sky.subsamples(subsamples_per_axis(sky) if k is None else k)
    lw = w * luminance(d)                       # (P, k²)
    centres = np.ascontiguousarray(sky.directions, np.float64)
    # A patch whose subsamples all lie in front of the plane weighs n · Σ lw d (the clipped
    # cosine is the cosine there), one whose subsamples all lie behind it nothing: only the
    # patches the plane's horizon crosses are summed subsample by subsample. Each normal's row
    # is made on its own (a tiled sky equals the untiled one).
    dx, dy, dz = (np.ascontiguousarray(d[:, :, c]) for c in range(3))   # (P, k²) each
    moment = np.stack([(lw * dx).sum(axis=1), (lw * dy).sum(axis=1), (lw * dz).sum(axis=1)], 1)
    cx, cy, cz = (centres[:, c] for c in range(3))
    cos_r = np.minimum((dx * cx[:, None] + dy * cy[:, None] + dz * cz[:, None]).min(axis=1), 1.0)
    sin_r = np.sqrt(1.0 - cos_r * cos_r)          # the patch's subsamples' angular radius
    unit = np.ascontiguousarray(unique / np.sqrt((unique * unique).sum(axis=1))[:, None])
    out = np.empty((len(unique), sky.n))
    patch_weight_rows(unit, centres, in_front(unit, centres), dx, dy, dz,
                      np.ascontiguousarray(lw, np.float64), moment, cos_r, sin_r,
                      _WHOLE_MARGIN, out)
    return out, inverse.reshape(-1)


def sky_integral(visibility, luminance=uniform_luminance, *, k: int | None = None,
                 leaf: bool = True) -> np.ndarray:
    """(N,) ``Σ_p bit_p τ_p W[p]``: the cosine-weighted visible sky of every receiver under a
    relative luminance (see :func:`patch_weights`); ``τ_p`` the transmission of the crowns in
    the way (in leaf or leafless, ``leaf``), 1 without vegetation.

    Examples
    --------
    >>> vis = sky_visibility(scene, points, normals, sky)               # doctest: +SKIP
    >>> sky_integral(vis, cie_overcast_luminance)                     # doctest: +SKIP
    """
    weights, inverse = patch_weights(visibility.sky, visibility.normals, luminance, k=k)
    return weighted_sum(visibility, weights, inverse, leaf=leaf)


def weighted_sum(visibility, weights, inverse, *, leaf: bool = True) -> np.ndarray:
    """(N,) ``Σ_p bit_p τ_p weights[inverse[i], p]``: the visible part of per-plane patch
    weights (:func:`patch_weights`), each receiver's directions added in order from the
    packed bits (:func:`cityshade.light.kernels.visible_weight_sums`: the same number for a
    receiver whatever other receivers it is computed with). A ray through crowns
    (:attr:`~cityshade.light.visibility.SkyVisibility.crowns`) gives back ``(1 − τ)`` of its
    weight, τ in leaf or leafless (``leaf``); without vegetation nothing is subtracted."""
    from cityshade.light.kernels import visible_weight_sums

    out = np.zeros(visibility.n_receivers)
    visible_weight_sums(np.ascontiguousarray(visibility.bits),
                        np.ascontiguousarray(inverse, np.int64),
                        np.ascontiguousarray(weights, np.float64), out)
    crowns = visibility.crowns
    if crowns is not None and len(crowns.rows):
        loss = (1.0 - crowns.transmission(leaf)) * weights[inverse[crowns.rows], crowns.cols]
        out -= np.bincount(crowns.rows, weights=loss, minlength=len(out))
    return out


def sky_view_factor(visibility, *, k: int | None = None, leaf: bool = True) -> np.ndarray:
    """(N,) sky view factor of each receiver for its own plane, in [0, 1].

    ``Σ visible cos(angle to the normal) dΩ / π`` over the half-space in front: 1 for open
    horizontal ground, 0.5 for a free vertical wall.

    Parameters
    ----------
    visibility : SkyVisibility
        From :func:`cityshade.light.visibility.sky_visibility`.
    k : int, optional
        Gauss–Legendre points per patch axis.

    Examples
    --------
    >>> from cityshade.light import named_sky, sky_visibility, sky_view_factor
    >>> vis = sky_visibility(scene, points, normals, named_sky())      # doctest: +SKIP
    >>> sky_view_factor(vis)                                          # doctest: +SKIP
    array([0.4471...])
    """
    return sky_integral(visibility, uniform_luminance, k=k, leaf=leaf) / math.pi


def vertical_sky_component(visibility, *, k: int | None = None, leaf: bool = True
                           ) -> np.ndarray:
    """(N,) vertical sky component of each receiver (BRE 209), as a fraction: 0.396 (39.6 %)
    for an unobstructed vertical window; BRE's 27 % test is ``vsc >= 0.27``.

    The receivers are the windows' reference points (the centre of the window on its outer
    face, :func:`cityshade.light.visibility.polygon_reference_points`) with the windows'
    normals; any receiver works (a map pixel's VSC is that of its own plane).

    Examples
    --------
    >>> from cityshade.light import named_sky, sky_visibility, vertical_sky_component
    >>> vis = sky_visibility(scene, window_centres, window_normals, named_sky())  # doctest: +SKIP
    >>> 100 * vertical_sky_component(vis)                                      # doctest: +SKIP
    array([27.2...])
    """
    return sky_integral(visibility, cie_overcast_luminance, k=k,
                        leaf=leaf) / CIE_OVERCAST_HORIZONTAL
