"""What a frame did and left out: the typed diagnostics of the pipeline.

:class:`FrameDiagnostics` is what :func:`cityshade.frame.pipeline.camera_pass` and
:func:`cityshade.frame.pipeline.shadow_pass` report about one frame (the camera pass's statistics,
the ground plane, the shadow technique's own diagnostics); :func:`skipped_work` turns them into
the lines ``render -v`` prints and ``evaluate`` reports: what the scene and request let the
frame leave out, with an estimate of the time saved.
"""
from __future__ import annotations

import statistics
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from cityshade.util import plural

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.shadows import TechniqueDiagnostics
    from cityshade.raster.gbuffer import Surfaces
    from cityshade.geo.sun import SunPosition


@dataclass(frozen=True)
class GroundInfo:
    """The ground plane a frame added (:mod:`cityshade.geometry.ground`)."""

    mode: str           # "min", "auto" or the height the user gave
    z_crs_m: float      # height of the plane in the model's CRS, metres
    pixels: int         # pixels it filled


@dataclass
class FrameDiagnostics:
    """What one frame did.

    Attributes
    ----------
    gbuffer : dict
        :attr:`cityshade.raster.gbuffer.GBuffer.stats` of the camera pass (culling counts,
        timings).
    shadow : TechniqueDiagnostics
        The shadow technique's own diagnostics (``technique``, ``map_px``, ``traced_px``...).
    ground : GroundInfo or None
    skipped : list of str
        :func:`skipped_work` of the frame, one item per line.
    """

    gbuffer: dict[str, Any] = field(default_factory=dict)
    shadow: "TechniqueDiagnostics | None" = None
    ground: GroundInfo | None = None
    skipped: list[str] = field(default_factory=list)

    def lines(self) -> list[tuple[str, Any]]:
        """(label, value) rows for ``render -v``: the technique's items, then the camera
        pass, the ground plane and what was left out."""
        shadow = self.shadow.as_dict() if self.shadow is not None else {}
        rows = [(k, v) for k, v in shadow.items() if not isinstance(v, (bytes, bytearray))]
        rows.append(("gbuffer", self.gbuffer))
        rows.append(("skipped", "\n         ".join(self.skipped) or "nothing"))
        if self.ground is not None:
            rows.append(("ground", self.ground))
        return rows


def _ms(seconds: float) -> str:
    return f"≈ {seconds * 1000:.1f} ms" if seconds >= 5e-5 else "< 0.1 ms"


def _depth_map_skips(stats: dict, where: str) -> list[str]:
    out = []
    removed = int(stats.get("frustum_refs_removed", 0))
    drawn = int(stats.get("casters_drawn", 0))
    raster = stats.get("timings_s", {})
    per_caster = (raster.get("setup_s", 0.0) + raster.get("raster_s", 0.0)) / max(drawn, 1)
    if stats.get("culling") == "the model lies inside the light view":
        out.append(f"{where}: kd-tree walk skipped (the whole model lies inside the light "
                   f"view: nothing to cull, a linear time filter is cheaper)")
    elif stats.get("culling") == "most of the model lies inside the light view":
        out.append(f"{where}: kd-tree walk skipped (most of the model lies inside the light "
                   f"view: too little to cull for the walk's cost, a linear time filter is "
                   f"cheaper)")
    elif removed:
        out.append(f"{where}: {removed} caster references outside the light frustum not drawn "
                   f"({drawn} drawn of {stats.get('triangles', 0)} triangles; "
                   f"{_ms(removed * per_caster)})")
    if int(stats.get("time_refs_removed", 0)):
        out.append(f"{where}: {stats['time_refs_removed']} caster references not standing at "
                   f"the city time skipped")
    return out


def skipped_work(scene: "Scene", gbuffer_stats: dict | None = None,
                 shadow_diagnostics: "TechniqueDiagnostics | None" = None,
                 surfaces: "Surfaces | None" = None, sun: "SunPosition | None" = None) -> list[str]:
    """What a frame left out because the scene or the request did not need it, with why and
    an estimate of the time it saved, one line per item.

    Parameters
    ----------
    scene : Scene
        Its kd-tree statistics and textures.
    gbuffer_stats : dict, optional
        :attr:`cityshade.raster.gbuffer.GBuffer.stats` of the camera pass.
    shadow_diagnostics : TechniqueDiagnostics, optional
        The shadow technique's diagnostics (nested ``base`` of ``hybrid`` are read too).
    surfaces : Surfaces, optional
        For the textured-pixel count.
    sun : SunPosition, optional

    Notes
    -----
    Savings are estimates: the number of things left out times the measured cost per thing of
    the same stage in this frame (e.g. raster time per drawn triangle), marked "≈".
    """
    out: list[str] = []
    tree = getattr(scene, "kdtree", None)
    if tree is not None and not tree.has_time:
        out.append(f"kd-tree: no time dimension (the model has no dates): "
                   f"{tree.stats.get('time_splits', 0)} time splits, no time test in any "
                   f"traversal")
    if sun is not None and not sun.above_horizon:
        out.append("shadows: no ray and no map (the sun is below the horizon)")
    textures = list(getattr(scene, "textures", []) or [])
    if not textures:
        out.append("shading: no texture sampling (the model has no textures)")
    elif surfaces is not None:
        texture = np.asarray(surfaces.texture)
        if not (np.asarray(surfaces.valid) & (texture >= 0)).any():
            out.append("shading: no texture sampling (no visible pixel is textured)")
    g = gbuffer_stats or {}
    if g:
        drawn = int(g.get("triangles_drawn", 0))
        t = g.get("timings_s", {})
        per_tri = max(t.get("total_s", 0.0) - t.get("walk_s", 0.0), 0.0) / max(drawn, 1)
        if g.get("walk_skipped"):
            out.append(f"camera pass: kd-tree walk skipped ({g['walk_skipped']}: nothing to "
                       f"cull, a linear time filter is cheaper)")
        for key, what in (("frustum_refs_removed", "outside the view frustum"),
                          ("occlusion_refs_removed", "hidden behind drawn surfaces "
                                                     "(occlusion queries)"),
                          ("time_refs_removed", "not standing at the city time")):
            n = int(g.get(key, 0))
            if n:
                out.append(f"camera pass: {n} triangle references {what} not drawn "
                           f"({_ms(n * per_tri)})")
    d = shadow_diagnostics or {}
    inner = d.get("base")
    if "self_shadowed_px" in (inner or d):
        n = int((inner or d)["self_shadowed_px"])
        if n:
            out.append(f"shadows: {plural(n, 'pixel')} facing away from the sun "
                       f"{'is' if n == 1 else 'are'} shadow without a ray "
                       f"or lookup")
    for diag, where in ((d, "shadow map"), (inner or {}, "base shadow map")):
        if isinstance(diag.get("depth_map"), dict):
            out += _depth_map_skips(diag["depth_map"], where)
        skipped = diag.get("cascades_skipped") or []
        if skipped:
            rendered = [e for e in diag.get("per_cascade", []) if "skipped" not in e]
            per = statistics.fmean(e.get("depth_s", 0.0) for e in rendered) if rendered else 0.0
            out.append(f"{where}: {len(skipped)} of {diag.get('cascades', 0)} cascades cover no "
                       f"visible pixel and were not drawn ({_ms(len(skipped) * per)})")
    if "traced_px" in d and "facing_px" in d:
        untraced = int(d["facing_px"]) - int(d["traced_px"])
        rays_s = d.get("timings_s", {}).get("rays_s", 0.0)
        per_ray = rays_s / max(int(d["traced_px"]), 1)
        out.append(f"hybrid: {untraced} of {d['facing_px']} sun-facing pixels decided by the map "
                   f"without a ray ({_ms(untraced * per_ray)})")
    return out
