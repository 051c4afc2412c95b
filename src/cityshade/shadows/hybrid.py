"""``hybrid[:BASE]``: a shadow map for the rough answer, exact rays for the uncertain pixels.

The thesis' central idea (slides "Shadows"): shadow maps are fast but alias; ray tracing is
exact. Use the map to classify every visible pixel as surely lit, surely in shadow, or
uncertain, and trace shadow rays only for the uncertain ones. Writes the "refine image" (which
pixels were traced) as the EXR channel ``refined``.

Classifiers (option ``classifier``):

``bracket`` (default)
    For each receiver, look at the depth-map texels within ``1 + r`` texels of its lookup
    (``r`` = the base's filter radius). Surely lit: every texel there is empty or behind the
    receiver. Surely in shadow: every texel is in front of it and all belong to one city
    object (one caster covering the whole neighbourhood, so no gap between casters can let
    light through). Everything else — casters both in front and behind (a shadow edge), or
    different casters in front (a possible gap) — is uncertain. This is the slides' "better
    shadow edge detection": it looks at the map's depth discontinuities, not at the filtered
    answer.
``vsm``
    The slides' original: uncertain where the base's filtered lit fraction lies strictly
    between ``low`` and ``high``. Kept to measure how many edge pixels it misses.

Either way, a final boundary pass traces every not-yet-traced pixel that touches a pixel of
the other class (4-neighbourhood), repeatedly, until no boundary pixel is untraced (bounded by
``max_boundary_passes``): every shadow boundary in the result is verified by rays on both sides.

Pixels facing away from the sun are shadow by the shared rule and never traced.
What remains wrong can only be a mistaken region that touches no verified boundary: a gap or a
caster narrower than a texel, inside a region the map calls sure. ``cityshade evaluate`` counts
those misses against ``raytrace``.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from numba import njit

from cityshade.errors import UsageError
from cityshade.shadows import (ShadowContext, ShadowResult, facing_sun, get_technique,
                               technique_names)

#: Receiver states of the classifiers.
SURE_LIT, SURE_SHADOW, UNCERTAIN = 0, 1, 2


@dataclass(frozen=True)
class HybridSettings:
    """Tunables of ``hybrid`` (``ctx.options`` keys in brackets)."""

    #: [classifier] "bracket" (map depth neighbourhood) or "vsm" (filtered value thresholds).
    classifier: str = "bracket"
    #: [low] / [high] "vsm" classifier thresholds on the base's lit fraction.
    low: float = 0.02
    high: float = 0.98
    #: [extra_texels] Texels added to the base's filter radius for the bracket neighbourhood:
    #: one texel covers the rasterization's half-texel position error on either side.
    extra_texels: int = 1
    #: [max_boundary_passes] Bound on the boundary-following passes (each traces one layer).
    max_boundary_passes: int = 64

    @classmethod
    def from_options(cls, options: dict | None) -> "HybridSettings":
        options = options or {}
        kwargs = {k: options[k] for k in ("classifier", "low", "high", "extra_texels",
                                          "max_boundary_passes") if k in options}
        settings = cls(**kwargs)
        if settings.classifier not in ("bracket", "vsm"):
            raise UsageError(f"hybrid classifier must be bracket or vsm, not {settings.classifier!r}")
        if not 0.0 <= settings.low < settings.high <= 1.0:
            raise UsageError("hybrid thresholds need 0 <= low < high <= 1")
        return settings


@njit(cache=True)
def _bracket_kernel(depth, texel_obj, u_px, v_px, z, radius, state):
    """Classify receivers from the depth-map texels around their lookup (see module doc)."""
    h, w = depth.shape
    for i in range(u_px.shape[0]):
        # Locate the receiver's texel; a non-finite lookup cannot be decided from the map.
        if not (np.isfinite(u_px[i]) and np.isfinite(v_px[i]) and np.isfinite(z[i])):
            state[i] = UNCERTAIN
            continue
        cu = int(np.floor(u_px[i]))
        cv = int(np.floor(v_px[i]))
        front = 0
        behind = 0
        first_obj = -2
        mixed = False
        for dv in range(-radius, radius + 1):
            row = cv + dv
            for du in range(-radius, radius + 1):
                col = cu + du
                # Outside the map nothing was drawn: empty, i.e. no caster there.
                if row < 0 or row >= h or col < 0 or col >= w:
                    behind += 1
                    continue
                d = depth[row, col]
                if d <= z[i]:
                    front += 1
                    obj = texel_obj[row, col]
                    if first_obj == -2:
                        first_obj = obj
                    elif obj != first_obj:
                        mixed = True
                else:
                    behind += 1
        if front == 0:
            state[i] = SURE_LIT
        elif behind == 0 and not mixed:
            state[i] = SURE_SHADOW
        else:
            state[i] = UNCERTAIN


def bracket_states(depth_map, scene, points_m, normals, sun_direction, map_settings,
                   radius_texels: int) -> np.ndarray:
    """(N,) uint8 receiver states from one depth map (biased exactly like the base lookup)."""
    from cityshade.shadows.shadowmap import offset_receivers, project

    q = offset_receivers(depth_map.view, points_m, normals, sun_direction, map_settings,
                         max(radius_texels - 1, 0))
    u, v, z = project(depth_map.view, q)
    prim = np.asarray(depth_map.prim_id)
    texel_obj = np.where(prim >= 0, np.asarray(scene.tri_object)[np.maximum(prim, 0)], -1)
    state = np.empty(len(u), np.uint8)
    _bracket_kernel(np.asarray(depth_map.depth), texel_obj.astype(np.int32),
                    np.ascontiguousarray(u, np.float64), np.ascontiguousarray(v, np.float64),
                    np.ascontiguousarray(z, np.float64), int(radius_texels), state)
    return state


def _boundary(binary: np.ndarray, candidates: np.ndarray) -> np.ndarray:
    """Candidates with a 4-neighbour candidate of the other class."""
    out = np.zeros_like(candidates)
    for axis in (0, 1):
        for shift in (1, -1):
            nb_bin = np.roll(binary, shift, axis=axis)
            nb_ok = np.roll(candidates, shift, axis=axis)
            # np.roll wraps around: discard the wrapped row/column.
            if axis == 0:
                edge = slice(0, 1) if shift == 1 else slice(-1, None)
                nb_ok[edge, :] = False
            else:
                edge = slice(0, 1) if shift == 1 else slice(-1, None)
                nb_ok[:, edge] = False
            out |= candidates & nb_ok & (nb_bin != binary)
    return out


class Hybrid:
    """``hybrid:BASE``: BASE's map(s) classify, exact rays decide the uncertain pixels."""

    def __init__(self, base: str = "vsm"):
        if base.startswith("hybrid") or base == "raytrace":
            raise UsageError(f"hybrid needs a shadow-map base technique, not {base!r}; valid: "
                             + ", ".join(n for n in technique_names()
                                         if n not in ("raytrace",) and not n.startswith("hybrid")))
        self.base_name = base
        self.base = get_technique(base)
        self.name = f"hybrid:{base}"

    def run(self, ctx: ShadowContext) -> ShadowResult:
        from cityshade.trace import occluded, shadow_rays_from_surface

        settings = HybridSettings.from_options(ctx.options)
        t0 = time.perf_counter()
        base = self.base.run(ctx)
        t1 = time.perf_counter()
        surfaces = ctx.surfaces
        shape = surfaces.valid.shape
        lit = np.zeros(shape, np.float32)
        refined = np.zeros(shape, bool)
        diagnostics = {"technique": self.name, "base": base.diagnostics,
                       "classifier": settings.classifier}
        if not ctx.sun.above_horizon:
            diagnostics.update(traced_px=0, traced_share=0.0, note="sun below the horizon")
            return ShadowResult(lit=lit, diagnostics=diagnostics,
                                extra_channels={"refined": refined.astype(np.float32)})
        normal, faces = facing_sun(surfaces, ctx.camera, ctx.sun.direction)
        # 1. Classify facing pixels.
        state = np.full(shape, SURE_SHADOW, np.uint8)
        maps = getattr(base, "maps", None) or []
        if settings.classifier == "bracket" and maps:
            for use in maps:
                mask = use.pixels & faces
                if mask.any():
                    state[mask] = bracket_states(
                        use.depth_map, ctx.scene, surfaces.position_m[mask], normal[mask],
                        ctx.sun.direction, use.settings, use.filter_radius_px + settings.extra_texels)
            classifier_used = "bracket"
        else:
            b = base.lit
            state[faces] = np.where(b[faces] >= settings.high, SURE_LIT,
                                    np.where(b[faces] <= settings.low, SURE_SHADOW, UNCERTAIN))
            classifier_used = "vsm" if settings.classifier == "vsm" else "vsm (base exposes no map)"
        diagnostics["classifier"] = classifier_used
        lit[faces & (state == SURE_LIT)] = 1.0
        t2 = time.perf_counter()

        def trace(mask: np.ndarray) -> int:
            points = surfaces.position_m[mask]
            if not len(points):
                return 0
            origins = shadow_rays_from_surface(points, normal[mask], ctx.sun.direction)
            directions = np.ascontiguousarray(np.broadcast_to(ctx.sun.direction, origins.shape))
            lit[mask] = (~occluded(ctx.scene, origins, directions, ctx.t_days)).astype(np.float32)
            refined[mask] = True
            return len(points)

        # 2. Exact rays for the uncertain pixels.
        classified_uncertain = faces & (state == UNCERTAIN)
        rays = trace(classified_uncertain)
        # 3. Follow the boundaries: trace untraced pixels next to the other class until stable.
        passes = 0
        boundary_rays = 0
        valid = np.asarray(surfaces.valid, bool)
        while passes < settings.max_boundary_passes:
            binary = lit >= 0.5
            todo = _boundary(binary, valid) & faces & ~refined
            if not todo.any():
                break
            boundary_rays += trace(todo)
            passes += 1
        t3 = time.perf_counter()
        n_facing = int(faces.sum())
        diagnostics.update({
            "uncertain_px": int(classified_uncertain.sum()),
            "boundary_px": boundary_rays, "boundary_passes": passes,
            "traced_px": rays + boundary_rays,
            "traced_share": (rays + boundary_rays) / max(int(valid.sum()), 1),
            "facing_px": n_facing,
            "map_px": base.diagnostics.get("map_px"), "texel_m": base.diagnostics.get("texel_m"),
            "aliasing_m": base.diagnostics.get("aliasing_m"),
            "shadow_s": t3 - t0,
            "timings_s": {"base_s": t1 - t0, "classify_s": t2 - t1, "rays_s": t3 - t2},
        })
        return ShadowResult(lit=lit, diagnostics=diagnostics,
                            extra_channels={"refined": refined.astype(np.float32)})
