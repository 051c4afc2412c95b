"""Map techniques as composition: a light-view planner + a lookup, one ``run``.

A planner decides which light views to draw and which camera pixels each one serves:

``shadowmap`` (:class:`Uniform`)
    One orthographic map along the sun's rays fitted to the visible receivers facing the sun
    (:func:`cityshade.shadows.shadowmap.fit_uniform`), padded by the lookup's filter radius.
``psm``, ``lispsm``, ``xpsm`` (:class:`Warped`)
    One perspective-warped map (:func:`cityshade.shadows.warps.warp_matrix`) against
    perspective aliasing.
``csm`` / ``csm:WARP`` (:class:`Cascaded`)
    The view depth range split by the practical split scheme
    (:mod:`cityshade.shadows.cascades`), one map per slice fitted to the slice's receivers
    with any warp (``none`` = the uniform fit of :func:`~cityshade.shadows.warps.uniform_matrix`);
    a slice holding no visible pixel facing the sun gets no map.

A :class:`MapTechnique` has two steps, which ``hybrid`` uses separately: :meth:`prepare` draws
the maps (:class:`PreparedMaps`), :meth:`look_up` reads them with the lookup
(:mod:`cityshade.shadows.lookups`) for the pixels each map serves. Every planner works with
every lookup.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from cityshade.shadows import (MapUse, ShadowContext, ShadowResult, TechniqueDiagnostics,
                               scatter_pixels)
from cityshade.shadows.lookups import Lookup
from cityshade.runtime.memory import Scratch


@dataclass
class PreparedMaps:
    """What a planner drew for one frame and sun.

    Attributes
    ----------
    maps : list of MapUse
        The depth maps drawn and the facing pixels each one serves (disjoint masks).
    views : list of LightView or None
        One per planned map; None for a cascade that covers no pixel (no map drawn).
    layers : (N, H, W) float32 or None
        The cascades' depth maps as one texture array (+inf where no map was drawn).
    sun_direction : (3,) float64
        The sun vector the lookups use (the warps look up with the normalised vector).
    diagnostics : TechniqueDiagnostics
        What the planner did (views, warps, cascades, depth-pass statistics, timings).
    """

    maps: list[MapUse] = field(default_factory=list)
    views: list[Any] = field(default_factory=list)
    layers: np.ndarray | None = None
    sun_direction: Any = None
    diagnostics: TechniqueDiagnostics = field(default_factory=TechniqueDiagnostics)


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v)


class Uniform:
    """``shadowmap``: one uniform orthographic map fitted to the visible receivers."""

    name = "shadowmap"

    def prepare(self, ctx: ShadowContext, radius_px: int) -> PreparedMaps:
        from cityshade.shadows import shadowmap as sm

        settings = ctx.settings
        faces = ctx.faces
        points = ctx.facing_points
        out = PreparedMaps(sun_direction=ctx.sun.direction)
        if points.shape[0] == 0:
            # No visible surface faces the sun: nothing to look up, no map to draw.
            out.diagnostics.note = "no visible surface faces the sun: no map drawn"
            return out
        t0 = time.perf_counter()
        px = settings.map.px
        pad = min(settings.map.fit_pad_px + radius_px, (px - 1) // 2)
        view = sm.fit_uniform(ctx.scene, ctx, px, pad_px=pad, receivers_m=points)
        t1 = time.perf_counter()
        depth_map = sm.render_depth_map(ctx.scene, view, ctx.t_days)
        t2 = time.perf_counter()
        out.maps.append(MapUse(depth_map, faces, radius_px))
        out.views.append(view)
        out.diagnostics.update(map_px=[(view.width_px, view.height_px)],
                               depth_map=depth_map.stats,
                               timings_s={"fit_s": t1 - t0, "depth_s": t2 - t1})
        return out

    def measure(self, ctx: ShadowContext, prepared: PreparedMaps) -> dict[str, Any]:
        """``map_px``, ``texel_m`` (on the surfaces), ``texel_light_m``, ``aliasing_m``."""
        from cityshade.shadows.shadowmap import map_diagnostics

        faces = ctx.faces
        return map_diagnostics(prepared.views, ctx, ctx.facing_points, ctx.facing_normals,
                               faces)


#: The warped maps' focus work arrays (:func:`cityshade.shadows.warps.focus`).
_FOCUS_SCRATCH = Scratch()


class Warped:
    """``psm``, ``lispsm``, ``xpsm``: one perspective-warped map."""

    def __init__(self, warp: str):
        self.warp = warp
        self.name = warp

    def prepare(self, ctx: ShadowContext, radius_px: int) -> PreparedMaps:
        from cityshade.shadows import shadowmap as sm
        from cityshade.shadows.warps import focus, warp_matrix

        out = PreparedMaps(sun_direction=_unit(ctx.sun.direction))
        t0 = time.perf_counter()
        # The extruded receivers (80 MB on the 1M city's 2049² map) only serve the fit: kept
        # between frames, not page-faulted in anew for each.
        work = _FOCUS_SCRATCH.take()
        try:
            faces, receivers, _, casters = focus(ctx, work)
            if receivers.shape[0] == 0:
                out.diagnostics.note = "no visible surface faces the sun"
                return out
            m, info = warp_matrix(self.warp, ctx.camera, ctx.sun.direction, receivers,
                                  casters, ctx.settings.warp)
        finally:
            work.give_back()
        size = int(ctx.settings.map.px)
        view = sm.LightView(m, size, size, self.name)
        t1 = time.perf_counter()
        dmap = sm.render_depth_map(ctx.scene, view, ctx.t_days)
        t2 = time.perf_counter()
        out.maps.append(MapUse(dmap, faces, radius_px))
        out.views.append(view)
        out.diagnostics.update(map_px=[(size, size)], warp=info, depth_map=dmap.stats,
                               timings_s={"fit_s": t1 - t0, "depth_s": t2 - t1})
        return out

    def measure(self, ctx: ShadowContext, prepared: PreparedMaps) -> dict[str, Any]:
        """``texel_m`` (light-space texel at the receivers) and ``aliasing_m``."""
        from cityshade.shadows import shadowmap as sm

        view = prepared.views[0]
        faces = ctx.faces
        texel_m = sm.texel_footprint_m(view, ctx.facing_points, prepared.sun_direction)
        alias = sm.aliasing_m(view, ctx.camera, ctx.surfaces, mask=faces,
                              points_m=ctx.facing_points, normals=ctx.facing_normals)
        return {"texel_m": float(np.median(texel_m)),
                "aliasing_m": {"max": alias["max"], "mean": alias["mean"]}}


class Cascaded:
    """``csm`` / ``csm:WARP``: cascaded maps, each fitted with ``warp`` (``none``: uniform)."""

    def __init__(self, warp: str = "none"):
        self.warp = warp
        self.name = "csm" if warp == "none" else f"csm:{warp}"

    def prepare(self, ctx: ShadowContext, radius_px: int) -> PreparedMaps:
        from cityshade.shadows import cascades as C
        from cityshade.shadows import shadowmap as sm
        from cityshade.shadows import warps

        settings = ctx.settings
        surfaces = ctx.surfaces
        sun = np.asarray(ctx.sun.direction, np.float64)
        t_start = time.perf_counter()
        depth_s = 0.0
        diagnostics = TechniqueDiagnostics(warp=self.warp, map_px=[], cascades=0,
                                           cascades_rendered=0, cascades_skipped=[],
                                           per_cascade=[])
        out = PreparedMaps(sun_direction=_unit(sun), diagnostics=diagnostics)
        faces = ctx.faces
        receivers = ctx.facing_points
        if receivers.shape[0] == 0:
            diagnostics.note = "no visible surface faces the sun"
            return out
        size = int(settings.map.px)
        box = sm.scene_bounds(ctx.scene)
        if ctx.camera.kind == "perspective":
            depth = C.view_depth_m(ctx.camera, receivers)
            z_n = max(float(depth.min()), ctx.camera.near_m)
            z_f = max(float(depth.max()), z_n)
            count = settings.cascades.count
            splits = C.practical_splits(z_n, z_f, count, settings.cascades.split_lambda)
            slice_of = C.assign_cascades(depth, splits)
        else:
            count = 1
            splits = np.array([0.0, math.inf])
            slice_of = np.zeros(receivers.shape[0], np.int64)
            diagnostics.note = "orthographic camera: no perspective aliasing, one cascade"
        diagnostics.cascades = count
        diagnostics.splits_m = [float(v) for v in splits]
        # The texture array: one layer per cascade, +inf (no caster) where none was drawn.
        out.layers = np.full((count, size, size), np.inf, np.float32)
        face_rows = face_cols = None
        work = _FOCUS_SCRATCH.take()
        try:
            for k in range(count):
                sel = slice_of == k
                n_sel = int(sel.sum())
                entry: dict[str, Any] = {"cascade": k, "near_m": float(splits[k]),
                                         "far_m": float(splits[k + 1]), "pixels": n_sel}
                diagnostics.per_cascade.append(entry)
                if not n_sel:
                    diagnostics.cascades_skipped.append(k)
                    entry["skipped"] = "covers no visible pixel facing the sun"
                    out.views.append(None)
                    continue
                # A cascade of every receiver (a map's only one) takes them as they are: no
                # 80 MB copy, no mask made texel by texel (the 1M city's 2049² map).
                whole = n_sel == receivers.shape[0]
                r = receivers if whole else receivers[sel]
                casters = warps.extrude_to_box(r, sun, box,
                                               work.get("focus.casters", (r.shape[0], 3)))
                m, info = warps.warp_matrix(self.warp, ctx.camera, sun, r, casters,
                                            settings.warp)
                view = sm.LightView(m, size, size, f"csm-{k}")
                t0 = time.perf_counter()
                dmap = sm.render_depth_map(ctx.scene, view, ctx.t_days)
                depth_s += time.perf_counter() - t0
                out.layers[k] = dmap.depth
                if whole:
                    mask = faces.copy()
                else:
                    if face_rows is None:
                        face_rows, face_cols = np.nonzero(faces)
                    mask = np.zeros(surfaces.valid.shape, bool)
                    mask[face_rows[sel], face_cols[sel]] = True
                out.maps.append(MapUse(dmap, mask, radius_px))
                out.views.append(view)
                entry.update({"map_px": (size, size), "warp": info,
                              "casters_drawn": dmap.stats.get("casters_drawn", 0),
                              "depth_s": dmap.stats.get("timings_s", {}).get("total_s", 0.0)})
                diagnostics.map_px.append((size, size))
                diagnostics.cascades_rendered += 1
        finally:
            work.give_back()
        # fit: splits, focus and warps of every cascade (all but the depth passes).
        diagnostics.timings_s = {"fit_s": time.perf_counter() - t_start - depth_s,
                                 "depth_s": depth_s}
        return out

    def measure(self, ctx: ShadowContext, prepared: PreparedMaps) -> dict[str, Any]:
        """Per cascade ``texel_m`` and ``aliasing_m``; overall the median texel and the
        pixel-weighted mean (and the max) of the cascades' aliasing."""
        from cityshade.shadows import shadowmap as sm

        per_cascade = prepared.diagnostics.per_cascade
        rendered = [e for e in per_cascade if "skipped" not in e]
        texel_all = []
        for entry, use in zip(rendered, prepared.maps):
            points, normals = ctx.receivers(use.pixels)
            texel_k = sm.texel_footprint_m(use.depth_map.view, points, prepared.sun_direction)
            alias = sm.aliasing_m(use.depth_map.view, ctx.camera, ctx.surfaces, mask=use.pixels,
                                  points_m=points, normals=normals)
            entry.update({"texel_m": float(np.median(texel_k)),
                          "aliasing_m": {"max": alias["max"], "mean": alias["mean"]}})
            texel_all.append(texel_k)
        pixels = np.array([e["pixels"] for e in rendered], np.float64)
        return {"per_cascade": per_cascade,
                "texel_m": float(np.median(np.concatenate(texel_all))),
                "aliasing_m": {
                    "max": max(e["aliasing_m"]["max"] for e in rendered),
                    "mean": float((pixels * [e["aliasing_m"]["mean"] for e in rendered]).sum()
                                  / pixels.sum())}}


def make_planner(name: str, warp: str | None = None):
    """The planner of a registry name (checked by the registry): ``shadowmap``, a warp, or
    ``csm`` with an optional warp."""
    if name == "shadowmap":
        return Uniform()
    if name == "csm":
        return Cascaded(warp or "none")
    return Warped(name)


class MapTechnique:
    """A planner and a lookup: ``prepare`` draws the maps, ``look_up`` reads them, ``run`` does
    both and reports (the one skeleton of every map technique)."""

    def __init__(self, name: str, planner, lookup: Lookup):
        self.name = name
        self.planner = planner
        self.lookup = lookup

    def prepare(self, ctx: ShadowContext) -> PreparedMaps:
        """The maps of this frame and sun (none when the sun is down or no pixel faces it)."""
        if not ctx.sun.above_horizon:
            return PreparedMaps(diagnostics=TechniqueDiagnostics(
                note="sun at or below the horizon: everything in shadow"))
        prepared = self.planner.prepare(ctx, self.lookup.radius_px(ctx.settings))
        prepared.diagnostics.self_shadowed_px = int((ctx.surfaces.valid & ~ctx.faces).sum())
        return prepared

    def look_up(self, ctx: ShadowContext, prepared: PreparedMaps) -> np.ndarray:
        """(H, W) float32 lit fraction: each map read for the pixels it serves, 0 elsewhere."""
        lit = np.zeros(ctx.surfaces.valid.shape, np.float32)
        for use in prepared.maps:
            points, normals = ctx.receivers(use.pixels)
            scatter_pixels(self.lookup(use.depth_map, points, normals, prepared.sun_direction,
                                       ctx.settings), use.pixels, lit)
        return lit

    def run(self, ctx: ShadowContext) -> ShadowResult:
        """The maps of the opaque casters, read; crowns as partial shade on top
        (:func:`~cityshade.shadows.visibility.with_crowns`)."""
        from cityshade.shadows.visibility import with_crowns

        return with_crowns(self._run, ctx)

    def _run(self, ctx: ShadowContext) -> ShadowResult:
        t0 = time.perf_counter()
        prepared = self.prepare(ctx)
        diagnostics = TechniqueDiagnostics(technique=self.name, map_px=[], texel_m=0.0,
                                           aliasing_m={"max": 0.0, "mean": 0.0},
                                           lookup=self.lookup.mode).update(prepared.diagnostics)
        t1 = time.perf_counter()
        lit = self.look_up(ctx, prepared)
        t2 = time.perf_counter()
        if prepared.maps and ctx.measure:
            diagnostics.update(self.planner.measure(ctx, prepared))
        t3 = time.perf_counter()
        diagnostics.shadow_s = t2 - t0
        diagnostics.timings_s = {**diagnostics.get("timings_s", {}), "lookup_s": t2 - t1,
                                 "diagnostics_s": t3 - t2}
        return ShadowResult(lit=lit, diagnostics=diagnostics, maps=prepared.maps,
                            prepared=prepared)
