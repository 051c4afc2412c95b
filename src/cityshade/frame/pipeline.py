"""The frame pipeline: the camera pass once, the shadow pass per sun.

Every command that makes pictures or numbers of shadows goes through here: ``render`` (one
frame), ``batch`` (one camera pass, a shadow pass per sun step), ``evaluate`` and the stress set
(one camera pass, every technique's shadow pass on it). None of them rasterizes or builds a
:class:`~cityshade.shadows.ShadowContext` on its own, so what is evaluated is what users run,
ground plane included.

:func:`camera_pass`
    Rasterize the kd-tree for the camera at the city time (:mod:`cityshade.raster.rasterize`),
    resolve the G-buffer into surfaces, add the optional ground plane and turn the normals to
    the seen side: everything that does not depend on the sun, in a :class:`CameraPass`.
:func:`shadow_pass`
    One technique for one sun on a camera pass (the facing-the-sun rule computed once for
    the context), the lit fraction cleaned for the outputs (0 where there is no surface).
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from cityshade.config import ShadowSettings
from cityshade.frame.diagnostics import FrameDiagnostics, GroundInfo, skipped_work
from cityshade.errors import ContractError, UsageError
from cityshade.shadows import TechniqueSpec, describe, get_technique

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera
    from cityshade.raster.gbuffer import GBuffer, Surfaces
    from cityshade.shadows import ShadowContext, ShadowResult, Technique
    from cityshade.geo.sun import SunPosition


@dataclass
class CameraPass:
    """The sun-independent part of a frame.

    Attributes
    ----------
    scene : Scene
    camera : Camera
    t_days : float
        City time, days since 1970-01-01 UTC.
    gbuffer : GBuffer
    surfaces : Surfaces
        Resolved pixels (with the ground plane's pixels when one was added).
    normal : (H, W, 3) float64
        Unit normals turned to the side the camera sees
        (:func:`cityshade.shadows.oriented_normals`).
    ground : GroundInfo or None
    timings_s : dict
        ``gbuffer_s``, ``resolve_s``.
    """

    scene: "Scene"
    camera: "Camera"
    t_days: float
    gbuffer: "GBuffer"
    surfaces: "Surfaces"
    normal: np.ndarray
    ground: GroundInfo | None = None
    timings_s: dict[str, float] = field(default_factory=dict)
    #: (sun direction, the shared arrays of :class:`ShadowContext`) of the last sun: the
    #: facing mask and gathered receivers, made once for every technique on that sun.
    per_sun: tuple = field(default=(None, None), repr=False)

    @property
    def valid(self) -> np.ndarray:
        """(H, W) bool: pixels showing a surface."""
        return np.asarray(self.surfaces.valid, bool)

    def context(self, sun: "SunPosition", settings: ShadowSettings | None = None,
                measure: bool = False) -> "ShadowContext":
        """The shadow context of one sun on this pass (``measure``: the map techniques' texel
        and aliasing measures too)."""
        from cityshade.shadows import ShadowContext

        key = np.asarray(sun.direction, np.float64).tobytes()
        if self.per_sun[0] != key:
            self.per_sun = (key, {})   # only the last sun's: a batch steps through many
        return ShadowContext(scene=self.scene, surfaces=self.surfaces, camera=self.camera,
                             sun=sun, t_days=float(self.t_days),
                             settings=settings or ShadowSettings(), oriented_normal=self.normal,
                             measure=bool(measure), shared=self.per_sun[1])


#: Peak bytes per pixel of a frame, by technique family, measured with
#: ``python benchmarks/memory.py`` (at 4663e5b, the sample city, 1 and 4 Mpx with every pixel
#: showing a surface, the map view; the slope of the peak resident set over the pixels):
#: raytrace 280.9, izb 280.8, shadowmap 274.3 (+ 65.7 MB for its 2048² map), hybrid:vsm 392.0
#: (+ 98.3 MB); a batch (izb or raytrace, 4 sun positions, its EXR and PNG) 280.9 per receiver
#: pixel. The overview camera, a third of it sky, measured 186-196. The exact paths peak in the
#: camera pass (``raster.gbuffer.resolve``'s float64 temporaries), hybrid in its base map's
#: lookup on top of the camera pass's 98 B/px. With resolve as one kernel (the kernels branch,
#: 0e5b9d0) the same command measured raytrace 217.1, hybrid:vsm 407.5, batch 198.1. The
#: larger of the two, rounded up; the map families add :data:`MAP_BYTES_PER_TEXEL` per texel
#: of their maps.
FRAME_BYTES_PER_PX = {"exact": 290, "map": 290, "hybrid": 410}
#: A batch per receiver pixel (the figure above, rounded up).
BATCH_BYTES_PER_PX = 290
#: Shadow-map texels (depth, caster ids, moments, the hybrid's thin-caster map): 65.7 MB and
#: 98.3 MB for the 4.19 M texels of a 2048² map, rounded up.
MAP_BYTES_PER_TEXEL = 24


def frame_bytes(camera: "Camera", technique: str | TechniqueSpec | None = None,
                settings: ShadowSettings | None = None, *, batch: bool = False
                ) -> tuple[int, int]:
    """(estimated peak bytes, bytes per pixel) of a frame of ``camera`` with ``technique``
    (a name or its :class:`~cityshade.shadows.TechniqueSpec`; None: the camera pass alone),
    or of a batch (per receiver pixel, whatever the technique) with ``batch``."""
    pixels = int(camera.width_px) * int(camera.height_px)
    if batch:
        return pixels * BATCH_BYTES_PER_PX, BATCH_BYTES_PER_PX
    spec = describe(technique or "raytrace")
    s = settings or ShadowSettings()
    per_px = FRAME_BYTES_PER_PX[spec.family]
    texels = spec.maps_per_frame(s) * int(s.map.px) ** 2
    return pixels * per_px + texels * MAP_BYTES_PER_TEXEL, per_px
def available_memory_bytes() -> int | None:
    """The memory the system can give without swapping (``MemAvailable``), None if unknown."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, AttributeError):
        return None


def check_frame_memory(camera: "Camera", available_bytes: int | None = None, *,
                       technique: str | TechniqueSpec | None = None,
                       settings: ShadowSettings | None = None, batch: bool = False) -> int:
    """The estimated peak bytes of a frame (or a batch) of ``camera`` (:func:`frame_bytes`);
    refuse one that does not fit in the available memory, before anything is allocated.

    Raises
    ------
    UsageError
        The estimate exceeds the available memory (the message gives both and the way out:
        larger pixels or a smaller picture; for a batch, tiles).
    """
    need, per_px = frame_bytes(camera, technique, settings, batch=batch)
    have = available_memory_bytes() if available_bytes is None else int(available_bytes)
    if have is not None and need > have:
        hint = "a larger --pixel-size" if camera.kind == "map" else "a smaller --size"
        if batch:
            hint += " or --tile-px N (the map in tiles of N × N pixels)"
        what = "sun-hour map" if batch else "picture"
        per = f"{per_px} bytes per {'receiver pixel' if batch else 'pixel'}"
        per += f" for {describe(technique).name}" if technique and not batch else ""
        raise UsageError(f"the {what} of {camera.width_px} × {camera.height_px} pixels needs "
                         f"about {need / 1e9:.1f} GB ({per}) but {have / 1e9:.1f} GB are "
                         f"available: use {hint}")
    return need


def camera_pass(scene: "Scene", camera: "Camera", t_days: float, *, ground: str | None = None,
                ground_z_m: float | None = None, ground_box_m=None) -> CameraPass:
    """Rasterize, resolve, add the ground plane: the camera pass of a frame.

    Parameters
    ----------
    scene : Scene
        With its kd-tree (loaded from a .cityshade file).
    camera : Camera
    t_days : float
        City time, days since 1970-01-01 UTC.
    ground : str, optional
        "min", "auto" or a CRS height: add a ground plane where no surface was drawn
        (:mod:`cityshade.geometry.ground`).
    ground_z_m : float, optional
        The render-space height of ``ground``'s plane when already known
        (:func:`cityshade.geometry.ground.ground_height_m`; the strips of one frame compute it once).
    ground_box_m : (lo, hi), optional
        :func:`cityshade.geometry.ground.ground_box_m` when already known (likewise).

    Raises
    ------
    UsageError
        The scene has no kd-tree, or the ground mode is not understood.
    """
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize
    from cityshade.shadows import oriented_normals

    if not scene.can_trace:
        raise UsageError("the scene file has no kd-tree; rebuild it with `cityshade build`")
    if not hasattr(camera, "kind"):
        raise ContractError(f"camera_pass needs a Camera, not {type(camera).__name__}")
    check_frame_memory(camera)  # before any allocation
    t = time.perf_counter()
    gbuf = rasterize(scene, camera, float(t_days))
    gbuffer_s = time.perf_counter() - t
    t = time.perf_counter()
    surfaces = resolve(scene, gbuf)
    ground_info = None
    if ground is not None:
        from cityshade.geometry.ground import add_ground_plane, ground_height_m

        z = ground_height_m(scene, ground) if ground_z_m is None else float(ground_z_m)
        surfaces, filled = add_ground_plane(scene, camera, surfaces, z, ground_box_m)
        ground_info = GroundInfo(mode=str(ground), z_crs_m=z + float(scene.origin_m[2]),
                                 pixels=int(filled))
    normal = oriented_normals(surfaces, camera)
    resolve_s = time.perf_counter() - t
    return CameraPass(scene=scene, camera=camera, t_days=float(t_days), gbuffer=gbuf,
                      surfaces=surfaces, normal=normal, ground=ground_info,
                      timings_s={"gbuffer_s": gbuffer_s, "resolve_s": resolve_s})


@dataclass
class ShadowPass:
    """One technique's answer for one sun on a camera pass.

    Attributes
    ----------
    result : ShadowResult
        As the technique returned it (evaluate checks it for NaN and range).
    lit : (H, W) float32
        The lit fraction for outputs: NaN-free, 0 where no surface.
    seconds : float
        Time of the technique's ``run``.
    """

    result: "ShadowResult"
    lit: np.ndarray
    seconds: float
    sun: "SunPosition | None" = None

    def diagnostics(self, cp: CameraPass) -> FrameDiagnostics:
        """The frame's typed diagnostics, with what it left out (:func:`skipped_work`)."""
        return FrameDiagnostics(
            gbuffer=cp.gbuffer.stats, shadow=self.result.diagnostics, ground=cp.ground,
            skipped=skipped_work(cp.scene, cp.gbuffer.stats, self.result.diagnostics,
                                 cp.surfaces, self.sun))


def shadow_pass(cp: CameraPass, sun: "SunPosition",
                technique: "str | TechniqueSpec | Technique",
                settings: ShadowSettings | None = None, measure: bool = False) -> ShadowPass:
    """Run one shadow technique (a registry name, its :class:`~cityshade.shadows.TechniqueSpec`
    or an instance) for one sun on ``cp`` (``measure``: with the map techniques' per-frame
    measures, :class:`ShadowContext`)."""
    if settings is not None and not isinstance(settings, ShadowSettings):
        raise ContractError(f"shadow settings must be a ShadowSettings, not "
                            f"{type(settings).__name__}")
    tech = (get_technique(technique) if isinstance(technique, (str, TechniqueSpec))
            else technique)
    ctx = cp.context(sun, settings, measure)
    t = time.perf_counter()
    result = tech.run(ctx)
    seconds = time.perf_counter() - t
    # One masked copy (nan_to_num, a float64 where and a cast took 17-30 ms on a 2049² map).
    lit = np.where(cp.valid & ~np.isnan(result.lit), result.lit, np.float32(0.0)).astype(
        np.float32, copy=False)
    return ShadowPass(result=result, lit=lit, seconds=seconds, sun=sun)
