"""Lookups of the map techniques: how a receiver reads a depth map (``hard``, ``pcf``, ``vsm``).

A lookup is independent of how the map was planned (:mod:`cityshade.shadows.planners`): it
gets a :class:`~cityshade.shadows.shadowmap.DepthMap` of any 4×4 projective light view and the
receivers that map serves, applies the receiver-side bias and returns their lit fractions
(:func:`cityshade.shadows.shadowmap.shadow_lookup`). Its filter radius tells the planner how
much margin the map needs around the receivers.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cityshade.config import ShadowSettings


@dataclass(frozen=True)
class Lookup:
    """A lookup by mode: ``hard`` (one texel), ``pcf`` (``pcf.kernel``² texels) or ``vsm``
    (filtered moments, Chebyshev bound)."""

    mode: str = "hard"

    def radius_px(self, settings: ShadowSettings) -> int:
        """Texels around the receiver's texel that the filter reads."""
        if self.mode == "pcf":
            return settings.pcf.kernel // 2
        if self.mode == "vsm":
            return settings.vsm.blur_px
        return 0

    def __call__(self, depth_map, points_m: np.ndarray, normals: np.ndarray, sun_direction,
                 settings: ShadowSettings) -> np.ndarray:
        """(N,) float32 lit fractions of receivers ``points_m`` (N, 3) with oriented unit
        ``normals`` (N, 3), facing the sun."""
        from cityshade.shadows.shadowmap import shadow_lookup

        return shadow_lookup(depth_map, points_m, normals, sun_direction, settings, self.mode)


def make_lookup(name: str) -> Lookup:
    """The lookup of a registry name (``hard``, ``pcf``, ``vsm``; checked by the registry)."""
    return Lookup(name)
