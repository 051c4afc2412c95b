"""Cascaded shadow maps (``csm``, ``csm:psm``, ``csm:lispsm``, ``csm:xpsm``).

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
import time
from dataclasses import dataclass

import numpy as np

from cityshade.errors import UsageError
from cityshade.shadows import MapUse, ShadowContext, ShadowResult, facing_sun


@dataclass(frozen=True)
class CascadeSettings:
    """Tunables of the cascades (option names of ``ctx.options`` in brackets)."""

    #: [cascades] Number of view-depth slices: 4 is the usual choice (Zhang et al. 2006 show
    #: diminishing returns beyond 4 at common depth ranges).
    count: int = 4
    #: [split_lambda] λ of the practical split scheme: 0.5 is the even blend Zhang et al.
    #: recommend; 1 is logarithmic, 0 uniform.
    split_lambda: float = 0.5

    def __post_init__(self) -> None:
        if not (isinstance(self.count, (int, np.integer)) and 1 <= self.count <= 16):
            raise UsageError(f"cascades must be an integer in [1, 16], not {self.count!r}")
        if not (isinstance(self.split_lambda, (int, float)) and 0.0 <= self.split_lambda <= 1.0):
            raise UsageError(f"split_lambda must be in [0, 1], not {self.split_lambda!r}")

    @classmethod
    def from_options(cls, options: dict | None) -> "CascadeSettings":
        """Settings from a technique options dict (``cascades``, ``split_lambda``)."""
        options = options or {}
        kwargs = {}
        if options.get("cascades") is not None:
            kwargs["count"] = options["cascades"]
        if options.get("split_lambda") is not None:
            kwargs["split_lambda"] = options["split_lambda"]
        return cls(**kwargs)


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


class Cascaded:
    """``csm``: cascaded shadow maps, each cascade uniform (subclasses set a warp)."""

    name = "csm"
    warp = "none"

    def run(self, ctx: ShadowContext) -> ShadowResult:
        from cityshade.shadows import shadowmap as sm
        from cityshade.shadows import warps

        settings = CascadeSettings.from_options(ctx.options)
        warp = ctx.options.get("warp") or self.warp
        if warp not in warps.WARPS:
            raise UsageError(f"unknown warp {warp!r}; valid: {', '.join(warps.WARPS)}")
        map_settings = sm.ShadowMapSettings.from_options(ctx.options)
        warp_settings = warps.WarpSettings()
        surfaces = ctx.surfaces
        lit = np.zeros(surfaces.valid.shape, np.float32)
        diagnostics: dict = {"technique": self.name, "warp": warp, "map_px": [],
                             "cascades": 0, "cascades_rendered": 0, "cascades_skipped": [],
                             "per_cascade": [], "texel_m": 0.0,
                             "aliasing_m": {"max": 0.0, "mean": 0.0}, "shadow_s": 0.0}
        if not ctx.sun.above_horizon:
            diagnostics["note"] = "sun at or below the horizon: everything in shadow"
            return ShadowResult(lit=lit, diagnostics=diagnostics)
        started = time.perf_counter()
        normal, faces = facing_sun(surfaces, ctx.camera, ctx.sun.direction)
        receivers = np.asarray(surfaces.position_m[faces], np.float64)
        normals = normal[faces]
        size = int(map_settings.map_px)
        if receivers.shape[0] == 0:
            diagnostics["note"] = "no visible surface faces the sun"
            diagnostics["shadow_s"] = time.perf_counter() - started
            return ShadowResult(lit=lit, diagnostics=diagnostics)
        box = sm.scene_bounds(ctx.scene)
        sun = np.asarray(ctx.sun.direction, np.float64)
        if ctx.camera.kind == "perspective":
            depth = view_depth_m(ctx.camera, receivers)
            z_n = max(float(depth.min()), ctx.camera.near_m)
            z_f = max(float(depth.max()), z_n)
            count = settings.count
            splits = practical_splits(z_n, z_f, count, settings.split_lambda)
            slice_of = assign_cascades(depth, splits)
        else:
            count = 1
            splits = np.array([0.0, math.inf])
            slice_of = np.zeros(receivers.shape[0], np.int64)
            diagnostics["note"] = ("orthographic camera: no perspective aliasing, one cascade")
        diagnostics["cascades"] = count
        diagnostics["splits_m"] = [float(v) for v in splits]
        # The texture array: one layer per cascade, +inf (no caster) where none was drawn.
        layers = np.full((count, size, size), np.inf, np.float32)
        lit_faces = np.zeros(receivers.shape[0], np.float32)
        texel_all = np.zeros(receivers.shape[0])
        face_rows, face_cols = np.nonzero(faces)
        views = []
        map_uses = []
        classify_only = bool(ctx.options.get("classify_only", False))
        for k in range(count):
            sel = slice_of == k
            entry = {"cascade": k, "near_m": float(splits[k]), "far_m": float(splits[k + 1]),
                     "pixels": int(sel.sum())}
            if not sel.any():
                diagnostics["cascades_skipped"].append(k)
                entry["skipped"] = "covers no visible pixel facing the sun"
                diagnostics["per_cascade"].append(entry)
                views.append(None)
                continue
            r = receivers[sel]
            m, info = warps.warp_matrix(warp, ctx.camera, sun, r, warps.extrude_to_box(r, sun, box),
                                        warp_settings)
            view = sm.LightView(m, size, size, f"csm-{k}")
            dmap = sm.render_depth_map(ctx.scene, view, ctx.t_days)
            layers[k] = dmap.depth
            mask = np.zeros(surfaces.valid.shape, bool)
            mask[face_rows[sel], face_cols[sel]] = True
            map_uses.append(MapUse(dmap, mask, 0, map_settings))
            # Under ``hybrid`` only the maps are wanted (option ``classify_only``).
            if classify_only:
                alias = {"max": 0.0, "mean": 0.0}
                texel_k = np.zeros(int(sel.sum()))
            else:
                lit_k, texel_k = warps.lookup(dmap, r, normals[sel], sun, map_settings,
                                              ctx.options)
                lit_faces[sel] = lit_k
                alias = sm.aliasing_m(view, ctx.camera, surfaces, mask=mask)
            texel_all[sel] = texel_k
            entry.update({"map_px": (size, size), "warp": info,
                          "texel_m": float(np.median(texel_k)),
                          "aliasing_m": {"max": alias["max"], "mean": alias["mean"]},
                          "casters_drawn": dmap.stats.get("casters_drawn", 0),
                          "depth_s": dmap.stats.get("timings_s", {}).get("total_s", 0.0)})
            diagnostics["per_cascade"].append(entry)
            diagnostics["map_px"].append((size, size))
            diagnostics["cascades_rendered"] += 1
            views.append(view)
        lit[faces] = lit_faces
        rendered = [e for e in diagnostics["per_cascade"] if "skipped" not in e]
        pixels = np.array([e["pixels"] for e in rendered], np.float64)
        diagnostics["texel_m"] = float(np.median(texel_all))
        diagnostics["aliasing_m"] = {
            "max": max(e["aliasing_m"]["max"] for e in rendered),
            "mean": float((pixels * [e["aliasing_m"]["mean"] for e in rendered]).sum()
                          / pixels.sum())}
        diagnostics["shadow_s"] = time.perf_counter() - started
        # Kept for callers that inspect the maps (tests, hybrid): the texture array and views.
        self.layers, self.views = layers, views
        return ShadowResult(lit=lit, diagnostics=diagnostics, maps=map_uses)


class CascadedPSM(Cascaded):
    """``csm:psm``: cascades, each a perspective shadow map."""

    name = "csm:psm"
    warp = "psm"


class CascadedLiSPSM(Cascaded):
    """``csm:lispsm``: cascades, each a light-space perspective shadow map."""

    name = "csm:lispsm"
    warp = "lispsm"


class CascadedXPSM(Cascaded):
    """``csm:xpsm``: cascades, each an extended perspective shadow map."""

    name = "csm:xpsm"
    warp = "xpsm"
