"""Cascaded shadow maps (``csm``, ``csm:psm``, ``csm:lispsm``, ``csm:xpsm``): the split scheme.
:class:`cityshade.shadows.planners.Cascaded` plans the maps with it.

The view depth range of the visible receivers, ``[z_n, z_f]`` (metres along the camera's
forward axis), is split into N slices by the practical split scheme (Zhang, Sun, Xu, Lun,
"Parallel-Split Shadow Maps for Large-scale Virtual Environments", VRCIA 2006):

    C_i = λ z_n (z_f / z_n)^(i/N) + (1 - λ) (z_n + (z_f - z_n) i / N),   i = 0 … N

a blend of the logarithmic split (λ = 1, constant perspective aliasing per slice) and the
uniform one (λ = 0). Every visible pixel belongs to exactly one slice (slice i holds
``C_i <= z < C_{i+1}``, the last one also ``z = z_f``), so the cascades cover the view frustum's
visible part without gaps or overlaps. Each slice gets its own light view, fitted to its own
receivers (and the casters that can shade them) with any warp of :mod:`cityshade.shadows.warps`,
and its own depth map; the maps are stored as one (N, H, W) array, the CPU counterpart of a
texture array. A slice that holds no visible pixel facing the sun gets no map at all (its layer
stays empty, ``+inf``) and is reported in ``diagnostics["cascades_skipped"]``.

Orthographic (map) cameras have no perspective aliasing and their "view depth" is height, so
splitting buys nothing there: they use one cascade (reported as a note).
"""
from __future__ import annotations

import math

import numpy as np

from cityshade.config import CascadeSettings
from cityshade.errors import UsageError

__all__ = ["CascadeSettings", "practical_splits", "assign_cascades", "view_depth_m"]


def practical_splits(z_near_m: float, z_far_m: float, count: int,
                     split_lambda: float) -> np.ndarray:
    """(count + 1,) float64 split depths ``C_0 = z_n < C_1 < … < C_count = z_f`` of the
    practical split scheme (module docstring; Zhang et al. 2006).

    Parameters
    ----------
    z_near_m, z_far_m : float
        View depth range, metres, ``0 < z_n <= z_f``.
    count : int
        Number of slices (>= 1).
    split_lambda : float
        Blend in [0, 1]: 1 logarithmic, 0 uniform.
    """
    if not (math.isfinite(z_near_m) and math.isfinite(z_far_m) and 0.0 < z_near_m <= z_far_m):
        raise UsageError(f"split depths need 0 < near <= far, not {z_near_m}, {z_far_m}")
    if not (isinstance(count, (int, np.integer)) and count >= 1):
        raise UsageError(f"cascade count must be an integer >= 1, not {count!r}")
    if not 0.0 <= split_lambda <= 1.0:
        raise UsageError(f"split_lambda must be in [0, 1], not {split_lambda}")
    i = np.arange(count + 1, dtype=np.float64) / count
    log = z_near_m * (z_far_m / z_near_m) ** i
    uni = z_near_m + (z_far_m - z_near_m) * i
    c = split_lambda * log + (1.0 - split_lambda) * uni
    c[0], c[-1] = z_near_m, z_far_m        # exact ends, whatever the rounding of the blend
    return c


def assign_cascades(view_depth_m, splits) -> np.ndarray:
    """(N,) int64 slice index of each view depth: ``C_i <= z < C_{i+1}``, the far end in the
    last slice; depths outside ``[C_0, C_N]`` are clamped to the first / last slice."""
    z = np.asarray(view_depth_m, dtype=np.float64)
    c = np.asarray(splits, dtype=np.float64)
    idx = np.searchsorted(c, z, side="right") - 1
    return np.clip(idx, 0, len(c) - 2)


def view_depth_m(camera, points_m) -> np.ndarray:
    """(N,) metres along the camera's forward axis from the eye (perspective cameras)."""
    _, _, fwd = camera.frame()
    return (np.asarray(points_m, dtype=np.float64) - np.asarray(camera.eye_m)) @ fwd
