"""Shadow techniques: one registry, one signature, one output.

Every technique takes a :class:`ShadowContext` (scene, resolved G-buffer surfaces, camera, sun,
city time) and returns a :class:`ShadowResult`: the per-pixel lit fraction (0 = shadow,
1 = sun; NaN never) and its own diagnostics. Techniques are chosen by name with
:func:`get_technique`; unknown names raise a :class:`~cityshade.errors.UsageError` listing the
valid ones.

Shared rule (DESIGN §14): a surface facing away from the sun (N·L ≤ 0, with N turned towards
the viewer) is in shadow without any test, in every technique, so techniques agree there.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from cityshade.errors import UsageError

#: name → "module:class". Later techniques (shadow maps, hybrid) register here too.
TECHNIQUES: dict[str, str] = {
    "raytrace": "cityshade.shadows.raytraced:RayTraced",
    "izb": "cityshade.shadows.izb:LightSpace",
    "shadowmap": "cityshade.shadows.shadowmap:ShadowMap",
    "pcf": "cityshade.shadows.shadowmap:PCF",
    "vsm": "cityshade.shadows.shadowmap:VSM",
    "psm": "cityshade.shadows.warps:PSM",
    "lispsm": "cityshade.shadows.warps:LiSPSM",
    "xpsm": "cityshade.shadows.warps:XPSM",
    "csm": "cityshade.shadows.cascades:Cascaded",
    "csm:psm": "cityshade.shadows.cascades:CascadedPSM",
    "csm:lispsm": "cityshade.shadows.cascades:CascadedLiSPSM",
    "csm:xpsm": "cityshade.shadows.cascades:CascadedXPSM",
}


@dataclass
class ShadowContext:
    """Everything a technique may use for one frame."""

    scene: Any
    surfaces: Any          # cityshade.raster.gbuffer.Surfaces
    camera: Any            # cityshade.raster.camera.Camera
    sun: Any               # cityshade.sun.SunPosition
    t_days: float
    options: dict[str, Any] = field(default_factory=dict)


@dataclass
class MapUse:
    """A depth map a map technique used, and for which pixels (what ``hybrid`` classifies with)."""

    depth_map: Any              # cityshade.shadows.shadowmap.DepthMap
    pixels: np.ndarray          # (H, W) bool: the facing pixels looked up in this map
    filter_radius_px: int       # texels around the lookup the technique's filter reads
    settings: Any               # ShadowMapSettings used for the bias


@dataclass
class ShadowResult:
    """Per-pixel lit fraction and diagnostics of one technique run."""

    lit: np.ndarray                       # (H, W) float32 in [0, 1]; 0 where no surface
    diagnostics: dict[str, Any] = field(default_factory=dict)
    extra_channels: dict[str, np.ndarray] = field(default_factory=dict)
    #: Map techniques list the depth maps they used (empty for ``raytrace``).
    maps: list[MapUse] = field(default_factory=list)


class Technique(Protocol):
    name: str

    def run(self, ctx: ShadowContext) -> ShadowResult: ...


def technique_names() -> list[str]:
    return sorted(TECHNIQUES)


def get_technique(name: str) -> Technique:
    """The technique registered under ``name`` (an instance ready to run).

    ``NAME+smooth`` is technique NAME followed by the depth-aware screen-space smoothing
    (:class:`cityshade.shadows.filtering.Smoothed`).
    """
    base, plus, suffix = name.partition("+")
    if plus and suffix == "smooth" and (base in TECHNIQUES or base.startswith("hybrid")):
        from cityshade.shadows.filtering import Smoothed

        return Smoothed(get_technique(base))
    if name == "hybrid" or name.startswith("hybrid:"):
        from cityshade.shadows.hybrid import Hybrid

        return Hybrid(name.partition(":")[2] or "vsm")
    entry = TECHNIQUES.get(name)
    if entry is None:
        raise UsageError(f"unknown shadow technique {name!r}; valid: "
                         f"{', '.join(technique_names())}, hybrid[:BASE] (each also as "
                         f"NAME+smooth)")
    module, cls = entry.split(":")
    return getattr(importlib.import_module(module), cls)()


def oriented_normals(surfaces, camera) -> np.ndarray:
    """Unit normals (H, W, 3) float64 turned to the side the camera sees.

    A pixel may show the back of a triangle (an open model, a wall seen from inside); its
    surface for shading and shadows is the side that is seen.
    """
    normal = np.asarray(surfaces.normal, dtype=np.float64)
    if camera.kind == "map":
        to_viewer = np.asarray(camera.eye_m, np.float64) - np.asarray(camera.target_m, np.float64)
        to_viewer = np.broadcast_to(to_viewer, normal.shape)
    else:
        to_viewer = np.asarray(camera.eye_m, np.float64) - surfaces.position_m
    seen_from_back = np.einsum("ijk,ijk->ij", normal, to_viewer) < 0
    return np.where(seen_from_back[..., None], -normal, normal)


def facing_sun(surfaces, camera, sun_direction) -> tuple[np.ndarray, np.ndarray]:
    """(oriented normals, mask of surface pixels that face the sun): the shared rule."""
    normal = oriented_normals(surfaces, camera)
    faces = (normal @ np.asarray(sun_direction, dtype=np.float64)) > 0
    return normal, faces & np.asarray(surfaces.valid, bool)
