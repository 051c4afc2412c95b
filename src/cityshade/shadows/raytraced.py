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
        points, normals = ctx.receivers(faces)
        if len(points):
            scatter_pixels(self.sunlit(ctx.scene, points, normals, ctx.sun, ctx.t_days,
                                       diagnostics).astype(np.float32), faces, lit)
        diagnostics.rays = int(len(points))
        diagnostics.shadow_s = time.perf_counter() - t0
        return ShadowResult(lit=lit, diagnostics=diagnostics)

    def sunlit(self, scene, points, normals, sun, t_days,
               diagnostics: TechniqueDiagnostics) -> np.ndarray:
        """(N,) float64: the exact per-point fraction of the sun (here one kd-tree shadow ray
        per point; vegetation lets part through, docs/DESIGN.md §21)."""
        from cityshade.shadows.visibility import sun_fraction

        return sun_fraction(scene, points, normals, sun, t_days, engine="raytrace")
