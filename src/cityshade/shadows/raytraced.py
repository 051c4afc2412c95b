"""``raytrace``: the exact reference — one any-hit shadow ray per visible pixel toward the sun."""
from __future__ import annotations

import time

import numpy as np

from cityshade.shadows import (ShadowContext, ShadowResult, TechniqueDiagnostics,
                               scatter_pixels)


class RayTraced:
    """Exact shadows through the 4-D kd-tree, at the frame's city time."""

    name = "raytrace"

    def run(self, ctx: ShadowContext) -> ShadowResult:
        surfaces = ctx.surfaces
        shape = surfaces.valid.shape
        lit = np.zeros(shape, np.float32)
        diagnostics = TechniqueDiagnostics(technique=self.name, rays=0, self_shadowed_px=0)
        if not ctx.sun.above_horizon:
            diagnostics.note = "sun at or below the horizon: everything in shadow"
            return ShadowResult(lit=lit, diagnostics=diagnostics)
        t0 = time.perf_counter()
        faces = ctx.faces
        diagnostics.self_shadowed_px = int((surfaces.valid & ~faces).sum())
        origins = ctx.facing_origins
        if len(origins):
            scatter_pixels(self.sunlit(ctx.scene, origins, ctx.sun, ctx.t_days,
                                       diagnostics).astype(np.float32), faces, lit)
        diagnostics.rays = int(len(origins))
        diagnostics.shadow_s = time.perf_counter() - t0
        return ShadowResult(lit=lit, diagnostics=diagnostics)

    def sunlit(self, scene, origins, sun, t_days,
               diagnostics: TechniqueDiagnostics) -> np.ndarray:
        """(N,) float64: the exact fraction of the sun of each shadow ray from ``origins``
        (N, 3) (here one kd-tree ray each; vegetation lets part through, docs/DESIGN.md
        §21)."""
        from cityshade.shadows.visibility import origins_sun_fraction

        return origins_sun_fraction(scene, origins, sun, t_days, engine="raytrace")
