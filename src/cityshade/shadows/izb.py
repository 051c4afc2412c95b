"""``izb``: exact shadows from the light-space engine — ``raytrace``'s answer on every pixel,
by binning the casters in the sun's light plane instead of tracing each ray through the tree
(:mod:`cityshade.lightspace`)."""
from __future__ import annotations

import numpy as np

from cityshade.shadows.raytraced import RayTraced


class LightSpace(RayTraced):
    """Exact shadows through the light-space engine, at the frame's city time: the same pixels,
    normals and shadow-ray origins as :class:`RayTraced`, another engine for the decision."""

    name = "izb"

    def sunlit(self, scene, origins, sun, t_days, diagnostics) -> np.ndarray:
        from cityshade.shadows.visibility import origins_sun_fraction

        engine: dict = {}
        lit = origins_sun_fraction(scene, origins, sun, t_days, engine="izb", stats=engine)
        diagnostics.engine = engine
        return lit
