"""One frame: city time + sun + camera → pipeline (camera pass, shadow pass) → shading → outputs.

The library entry points are :func:`render_frame` (arrays in, arrays out) and
:func:`write_frame` (EXR, PNG, shadow mask, georeferenced mask). The CLI (`cli/render.py`) only
parses options into these calls.
"""
from __future__ import annotations

import contextlib
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from cityshade import __version__
from cityshade.config import ShadowSettings
from cityshade.frame.diagnostics import FrameDiagnostics
from cityshade.errors import UsageError
from cityshade.shadows import TechniqueSpec, describe, get_technique

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera
    from cityshade.geo.sun import SunPosition


@dataclass
class Frame:
    """A rendered frame and everything needed to write or inspect it."""

    camera: Any
    gbuffer: Any
    surfaces: Any
    lit: np.ndarray                 # (H, W) float32, 0 shadow … 1 sun; 0 where no surface
    rgb: np.ndarray                 # (H, W, 3) float32 linear
    sun: Any
    t_days: float
    technique: str
    timings_s: dict[str, float] = field(default_factory=dict)
    diagnostics: FrameDiagnostics = field(default_factory=FrameDiagnostics)
    warnings: list[str] = field(default_factory=list)
    #: Technique-specific EXR channels (e.g. ``refined`` of ``hybrid``), (H, W) each.
    extra_channels: dict[str, np.ndarray] = field(default_factory=dict)


def city_time_range(scene) -> tuple[float, float] | None:
    """[earliest begin, latest end) over the model's objects in days (±inf for open ends);
    None for a model without dates."""
    if not scene.has_time:
        return None
    return (float(np.min(scene.obj_t_begin_days)), float(np.max(scene.obj_t_end_days)))


def only_terrain_stands(scene, t_days: float) -> bool:
    """Whether terrain triangles are present at ``t_days`` and nothing else is."""
    from cityshade.citygml.namespaces import SURFACE_CODE

    t = float(t_days)
    present = (np.asarray(scene.tri_t_begin_days) <= t) & (t < np.asarray(scene.tri_t_end_days))
    terrain = np.asarray(scene.tri_class) == SURFACE_CODE["terrain"]
    return bool((present & terrain).any()) and not bool((present & ~terrain).any())


def _range_text(rng) -> str:
    from cityshade.geo.temporal import days_to_iso

    return f"{days_to_iso(rng[0])} … {days_to_iso(rng[1])}"


#: A map frame of an exact technique whose estimate (:func:`cityshade.frame.pipeline.frame_bytes`)
#: exceeds this is rendered in strips of rows (:func:`strip_rows_for`) ...
STRIP_FRAME_BYTES = 2 * 1024 ** 3
#: ... each of them estimated at about this many bytes (about 90 rows of a 5000-pixel map): on
#: the 1M city's 20 Mpx izb map, strips of 186 rows peaked at 1976 MB, of 60 rows at 1865 MB.
STRIP_BYTES = 128 * 1024 ** 2
#: Rows each strip computes above and below its own and then drops: a texture's mip level
#: comes from the pixel's neighbours (:func:`cityshade.frame.textures.lod_from_uv_neighbours`), and
#: at the strip's edge they must be the whole map's.
STRIP_HALO_ROWS = 1
#: The whole-map arrays of a strip-wise frame: name, dtype, values per pixel.
_STRIP_KEPT = (("lit", np.float32, 1), ("rgb", np.float32, 3), ("valid", np.bool_, 1),
               ("depth", np.float32, 1), ("normal", np.float32, 3), ("obj_id", np.int32, 1),
               ("prim_id", np.int32, 1))
#: Bytes per pixel that a strip-wise frame keeps for the whole map (41: lit 4, RGB 12, valid 1,
#: depth 4, normal 12, object and triangle ids 4 + 4). They go to a temporary file
#: (:class:`_Spool`), not to memory: 0.82 GB of a 20 Mpx map beside the strips' work.
STRIP_KEPT_BYTES_PER_PX = sum(n * np.dtype(dtype).itemsize for _, dtype, n in _STRIP_KEPT)
#: Bytes per pixel of the whole map that the writers of a strip-wise frame hold in memory: the
#: shadow mask (1) and its temporaries (3, :func:`cityshade.imageio.mask_from_lit`).
STRIP_WRITE_BYTES_PER_PX = 4


def strip_rows_for(camera: "Camera", technique: str | TechniqueSpec = "raytrace",
                   settings: ShadowSettings | None = None, strip_rows: int | None = None
                   ) -> int | None:
    """Rows per strip of a frame, or None for the whole frame at once.

    ``strip_rows`` (``render --strip-rows``) asks for strips of that many rows; without it a
    map of an exact technique goes in strips when its estimate exceeds
    :data:`STRIP_FRAME_BYTES`. Only the exact techniques (raytrace, izb) and map views can: a
    shadow map is fitted to the whole view, so a strip's map would differ, and a perspective
    view's pixel rays depend on its whole height.

    Raises
    ------
    UsageError
        ``strip_rows`` below 1, for a perspective view or a technique that is not exact.
    """
    from cityshade.frame.pipeline import frame_bytes

    spec = describe(technique)
    height, width = camera.shape
    if strip_rows is not None:
        if int(strip_rows) < 1:
            raise UsageError(f"--strip-rows must be at least 1, not {strip_rows}")
        if camera.kind != "map":
            raise UsageError("--strip-rows needs the map view (--camera map)")
        if not spec.exact:
            raise UsageError(f"--strip-rows needs an exact technique (raytrace or izb), not "
                             f"{spec.name}: a shadow map is fitted to the whole view")
        return None if int(strip_rows) >= height else int(strip_rows)
    if camera.kind != "map" or not spec.exact:
        return None
    need, per_px = frame_bytes(camera, spec, settings)
    if need <= STRIP_FRAME_BYTES:
        return None
    return max(1, min(height, STRIP_BYTES // (width * per_px)))


def render_frame(scene: "Scene", camera: "Camera", t_days: float, sun: "SunPosition",
                 technique: str | TechniqueSpec = "raytrace",
                 settings: ShadowSettings | None = None, sky: bool = True,
                 ground: str | None = None, measure: bool = False,
                 strip_rows: int | None = None, last_frame: bool = False) -> Frame:
    """Render one frame: the pipeline's camera pass and shadow pass, then shading.

    Parameters
    ----------
    scene : Scene
        With its kd-tree (loaded from a .cityshade file).
    camera : cityshade.raster.camera.Camera
    t_days : float
        City time, days since 1970-01-01 UTC.
    sun : cityshade.geo.sun.SunPosition
    technique : str or TechniqueSpec
        A name of the shadow registry, or its parsed :func:`cityshade.shadows.describe`.
    settings : ShadowSettings, optional
        The techniques' tunables (``[shadows]`` of the settings file).
    ground : str, optional
        "min", "auto" or a CRS height: add a ground plane where no surface was drawn
        (:mod:`cityshade.geometry.ground`).
    measure : bool
        Also the map techniques' per-frame measures (texel footprint, aliasing m), as
        ``render -v`` reports them.
    strip_rows : int, optional
        Render a map in strips of this many rows (:func:`strip_rows_for`, which also decides
        when a large map goes in strips without it). The pixels are the whole frame's, bit for
        bit; the frame then keeps only what :func:`write_frame` writes
        (:data:`STRIP_KEPT_BYTES_PER_PX`): ``surfaces`` has ``valid``, ``normal``, ``depth``,
        ``obj_id`` and ``prim_id`` (the rest None), ``gbuffer`` ``prim_id`` and ``depth``;
        these, ``lit`` and ``rgb`` are read-only memory maps of a temporary file (in
        :func:`tempfile.gettempdir`, ``TMPDIR``), not memory.
    last_frame : bool
        The caller renders no other frame of this scene: the light-space engine's work
        arrays are let go as each of its calls returns (:func:`cityshade.lightspace.
        last_calls`) and its sorted casters after the shadow pass
        (:func:`~cityshade.lightspace.forget_casters`), then every work array kept for a next
        frame (:func:`cityshade.runtime.memory.release_kept_memory`), before shading needs the
        memory (the 1M city's map: 0.3 GB with izb, 0.1 GB with raytrace).
    """
    from cityshade.frame.pipeline import camera_pass, check_frame_memory, shadow_pass
    from cityshade.frame.shading import shade

    if not scene.can_trace:
        raise UsageError("the scene file has no kd-tree; rebuild it with `cityshade build`")
    spec = describe(technique)
    tech = get_technique(spec)
    rows = strip_rows_for(camera, spec, settings, strip_rows)
    if rows is None:
        check_frame_memory(camera, technique=spec, settings=settings)  # before allocating
    else:
        check_strip_memory(camera, rows, spec, settings)
    warnings: list[str] = []
    if not sun.above_horizon:
        warnings.append(f"the sun is at or below the horizon (elevation {sun.elevation_deg:g}°): "
                        f"everything is in shadow")
    rng = city_time_range(scene)
    if only_terrain_stands(scene, t_days):
        warnings.append("only terrain stands at this date: no building or other object is "
                        "present then (`cityshade info` shows the model's time range)")
    elif rng is not None and not rng[0] <= t_days < rng[1]:
        warnings.append(f"the date is outside the model's time range ({_range_text(rng)}): "
                        f"nothing stands then")
    if rows is not None:
        return _render_strips(scene, camera, t_days, sun, spec.name, tech, settings, sky,
                              ground, measure, rows, warnings)
    cp = camera_pass(scene, camera, t_days, ground=ground)
    timings: dict[str, float] = dict(cp.timings_s)
    from cityshade.lightspace import forget_casters, last_calls
    from cityshade.runtime.memory import release_kept_memory

    if last_frame:
        release_kept_memory()

    with last_calls(scene) if last_frame else contextlib.nullcontext():
        sp = shadow_pass(cp, sun, tech, settings, measure)
    timings["shadow_s"] = sp.seconds
    if last_frame:
        forget_casters(scene)
        release_kept_memory()
    t = time.perf_counter()
    shade_report: dict = {}
    rgb = shade(scene, cp.surfaces, camera, sp.lit, sun.direction, sky=sky,
                prim_id=cp.gbuffer.prim_id, report=shade_report)
    timings["shade_s"] = time.perf_counter() - t
    warnings += list(shade_report.get("texture_warnings", []))
    return Frame(camera=camera, gbuffer=cp.gbuffer, surfaces=cp.surfaces, lit=sp.lit, rgb=rgb,
                 sun=sun, t_days=t_days, technique=spec.name, timings_s=timings,
                 diagnostics=sp.diagnostics(cp), warnings=warnings,
                 extra_channels=dict(sp.result.extra_channels))


def check_strip_memory(camera: "Camera", rows: int, technique: str | TechniqueSpec,
                       settings: ShadowSettings | None = None) -> int:
    """The estimated peak bytes of a strip-wise frame (one strip's work plus the writers' whole
    mask: the whole-map arrays go to a temporary file); refuse one that does not fit in the
    available memory, or whose file does not fit in the temporary folder.

    Raises
    ------
    UsageError
        The estimate exceeds the available memory, or the file the free disk space.
    """
    from cityshade.frame.pipeline import available_memory_bytes, frame_bytes

    import shutil
    import tempfile

    height, width = camera.shape
    strip = camera.strip(0, min(height, rows + 2 * STRIP_HALO_ROWS))
    need = height * width * STRIP_WRITE_BYTES_PER_PX + frame_bytes(strip, technique, settings)[0]
    have = available_memory_bytes()
    if have is not None and need > have:
        raise UsageError(f"the picture of {width} × {height} pixels in strips of {rows} rows "
                         f"needs about {need / 1e9:.1f} GB but {have / 1e9:.1f} GB are "
                         f"available: use a larger --pixel-size")
    spool = height * width * STRIP_KEPT_BYTES_PER_PX
    folder = tempfile.gettempdir()
    free = shutil.disk_usage(folder).free
    if spool > free:
        raise UsageError(f"the picture of {width} × {height} pixels in strips keeps "
                         f"{spool / 1e9:.1f} GB in a temporary file but {folder} has "
                         f"{free / 1e9:.1f} GB free: set TMPDIR to a larger disk or use a "
                         f"larger --pixel-size")
    return need


class _Spool:
    """The whole-map arrays of a strip-wise frame (:data:`_STRIP_KEPT`) in an unlinked
    temporary file: each strip's rows are written with ``os.pwrite`` (no page of them stays
    resident), and :meth:`arrays` maps the complete file read-only, so the writers' reads are
    clean file pages (:func:`cityshade.runtime.memory.release_pages` drops them, the OS page cache
    keeps them). Nothing is left on disk however the process ends."""

    def __init__(self, height: int, width: int):
        import mmap
        import tempfile

        self.shape = (height, width)
        self.offsets: dict[str, int] = {}
        end = 0
        for name, dtype, per_px in _STRIP_KEPT:
            self.offsets[name] = end
            end += height * width * per_px * np.dtype(dtype).itemsize
            end += -end % mmap.ALLOCATIONGRANULARITY     # each array on a page of its own
        self.file = tempfile.TemporaryFile(prefix="cityshade-strips-")
        self.file.truncate(end)     # sparse: the strips fill it
        self.size = end

    def write_rows(self, name: str, row0: int, values: np.ndarray) -> None:
        """Rows ``row0 …`` of array ``name`` (whole rows)."""
        data = memoryview(np.ascontiguousarray(values)).cast("B")
        offset = self.offsets[name] + row0 * (data.nbytes // len(values))  # bytes of a row
        while data.nbytes:          # pwrite may write less than asked
            done = os.pwrite(self.file.fileno(), data, offset)
            data, offset = data[done:], offset + done

    def arrays(self) -> dict[str, np.ndarray]:
        """The complete arrays, read-only memory maps of the file (closed with them)."""
        whole = np.memmap(self.file, dtype=np.uint8, mode="r", shape=(self.size,))
        self.file.close()           # the map keeps the file
        out = {}
        for name, dtype, per_px in _STRIP_KEPT:
            shape = self.shape + ((per_px,) if per_px > 1 else ())
            n = int(np.prod(shape)) * np.dtype(dtype).itemsize
            start = self.offsets[name]
            out[name] = whole[start:start + n].view(dtype).reshape(shape)
        return out


def _render_strips(scene, camera, t_days, sun, technique, tech, settings, sky, ground, measure,
                   rows, warnings) -> Frame:
    """:func:`render_frame` of a map in strips of ``rows`` rows (each with
    :data:`STRIP_HALO_ROWS` more on either side, dropped), written into the whole-map arrays
    of a :class:`_Spool`."""
    from cityshade.frame.pipeline import camera_pass, shadow_pass
    from cityshade.raster.gbuffer import GBuffer, Surfaces
    from cityshade.store.scenefile import release_scene_pages
    from cityshade.frame.shading import shade

    height, width = camera.shape
    spool = _Spool(height, width)
    extra: dict[str, np.ndarray] = {}
    timings: dict[str, float] = {}
    ground_z = ground_box = None
    if ground is not None:
        from cityshade.geometry.ground import ground_box_m, ground_height_m

        ground_z = ground_height_m(scene, ground)  # once, not per strip
        ground_box = ground_box_m(scene)
    diagnostics = None
    filled = 0
    n_strips = 0
    for r0 in range(0, height, rows):
        r1 = min(height, r0 + rows)
        h0, h1 = max(0, r0 - STRIP_HALO_ROWS), min(height, r1 + STRIP_HALO_ROWS)
        # Each strip maps back what it reads: the file pages of a whole city (and those the
        # ground height read) would otherwise stay resident (1.8 of the 10^7-triangle city's
        # 6.5 GB 20 Mpx map).
        release_scene_pages(scene)
        cp = camera_pass(scene, camera.strip(h0, h1), t_days, ground=ground,
                         ground_z_m=ground_z, ground_box_m=ground_box)
        sp = shadow_pass(cp, sun, tech, settings, measure)
        t = time.perf_counter()
        shade_report: dict = {}
        strip_rgb = shade(scene, cp.surfaces, cp.camera, sp.lit, sun.direction, sky=sky,
                          prim_id=cp.gbuffer.prim_id, report=shade_report)
        for key, value in {**cp.timings_s, "shadow_s": sp.seconds,
                           "shade_s": time.perf_counter() - t}.items():
            timings[key] = timings.get(key, 0.0) + value
        warnings += [w for w in shade_report.get("texture_warnings", []) if w not in warnings]
        a, b = r0 - h0, r1 - h0          # the strip's own rows in its arrays
        s = cp.surfaces
        for name, values in (("lit", sp.lit), ("rgb", strip_rgb), ("valid", s.valid),
                             ("depth", s.depth), ("normal", s.normal), ("obj_id", s.obj_id),
                             ("prim_id", cp.gbuffer.prim_id)):
            spool.write_rows(name, r0, np.asarray(values)[a:b])
        for name, values in sp.result.extra_channels.items():
            if name not in extra:
                extra[name] = np.zeros((height, width), np.float32)
            extra[name][r0:r1] = np.asarray(values, np.float32)[a:b]
        if cp.ground is not None:   # the plane's pixels of the strip's own rows
            filled += int(np.count_nonzero(s.valid[a:b] & (cp.gbuffer.prim_id[a:b] < 0)))
        diagnostics = sp.diagnostics(cp)
        n_strips += 1
        del cp, sp, strip_rgb, s
    # The diagnostics are the last strip's, with the whole map's ground pixels and the count.
    diagnostics.gbuffer = {**diagnostics.gbuffer, "strips": n_strips, "strip_rows": rows}
    if diagnostics.ground is not None:
        from dataclasses import replace

        diagnostics.ground = replace(diagnostics.ground, pixels=filled)
    kept = spool.arrays()
    gbuffer = GBuffer(camera=camera, prim_id=kept["prim_id"], bary=None, depth=kept["depth"],
                      stats=diagnostics.gbuffer)
    surfaces = Surfaces(position_m=None, normal=kept["normal"], obj_id=kept["obj_id"],
                        material=None, texture=None, uv=None, cls=None, valid=kept["valid"],
                        prim_id=kept["prim_id"], depth=kept["depth"])
    return Frame(camera=camera, gbuffer=gbuffer, surfaces=surfaces, lit=kept["lit"],
                 rgb=kept["rgb"], sun=sun,
                 t_days=t_days, technique=technique, timings_s=timings,
                 diagnostics=diagnostics, warnings=warnings, extra_channels=extra)


def shadow_mask(frame: Frame, scene=None) -> np.ndarray:
    """(H, W) uint8: 255 sunlit, 0 shadow, 128 no surface (:func:`imageio.mask_from_lit`);
    on a scene with vegetation, the fraction of sun as a grey level, whatever the technique
    (:func:`imageio.grey_mask_from_lit`: trees let part of it through, docs/DESIGN.md §21)."""
    from cityshade.geometry.vegetation import scene_vegetation
    from cityshade.imageio import grey_mask_from_lit, mask_from_lit

    if scene is not None and scene_vegetation(scene) is not None:
        return grey_mask_from_lit(frame.lit, frame.surfaces.valid)
    return mask_from_lit(frame.lit, frame.surfaces.valid)


def frame_metadata(frame: Frame, scene, date_text: str) -> dict[str, Any]:
    """Provenance recorded in every output (docs/DESIGN.md §15)."""
    from cityshade.geo.temporal import days_to_iso

    header = scene.header or {}
    meta = {
        "cityshade:version": __version__,
        "cityshade:date": date_text,
        "cityshade:city_time": days_to_iso(frame.t_days) if math.isfinite(frame.t_days) else "any",
        "cityshade:sun_azimuth_true_deg": frame.sun.azimuth_true_deg,
        "cityshade:sun_azimuth_grid_deg": frame.sun.azimuth_grid_deg,
        "cityshade:sun_elevation_deg": frame.sun.elevation_deg,
        "cityshade:meridian_convergence_deg": frame.sun.convergence_deg,
        "cityshade:sun_source": frame.sun.source,
        "cityshade:technique": frame.technique,
        "cityshade:camera": frame.camera.kind,
        "cityshade:source_sha256": header.get("source", {}).get("sha256", ""),
        "cityshade:crs": scene.crs.name,
        "cityshade:crs_epsg": scene.crs.horizontal_epsg or 0,
        "cityshade:origin_m": " ".join(f"{v:.3f}" for v in scene.origin_m),
        "cityshade:timings_s": " ".join(f"{k}={v:.4f}" for k, v in frame.timings_s.items()),
    }
    if frame.sun.note:
        meta["cityshade:sun_note"] = frame.sun.note
    ground = frame.diagnostics.ground
    meta["cityshade:ground"] = (f"{ground.mode} plane at z={ground.z_crs_m:.3f} m"
                                if ground else "none")
    return meta


#: The outputs of a frame: option, keyword of write_frame, allowed extensions.
FRAME_OUTPUTS = (("-o", "exr", (".exr",)), ("--png", "png", (".png",)),
                 ("--mask", "mask", (".png",)), ("--geotiff", "georef", (".tif", ".tiff")))


def check_frame_outputs(camera_kind: str | None, **paths) -> None:
    """Check every output of a frame before any work (:func:`cityshade.util.check_outputs`:
    extension, no two outputs on the same file, a writable folder, created when missing as
    ``build`` does) and that a GeoTIFF has the map view (unless ``camera_kind`` is None: not
    known yet).

    Raises
    ------
    UsageError
        An extension, a GeoTIFF of a perspective view or a clash.
    OutputError
        A folder that cannot be created or written, or an output path that is a folder.
    """
    from cityshade.util import check_outputs

    check_outputs(*((option, paths.get(key), suffixes) for option, key, suffixes in FRAME_OUTPUTS))
    if paths.get("georef") is not None and camera_kind not in (None, "map"):
        raise UsageError("--geotiff needs the map view (--camera map): a perspective "
                         "picture has no place on a map")


def write_frame(frame: Frame, scene, date_text: str, exr: Path | None = None,
                png: Path | None = None, mask: Path | None = None,
                georef: Path | None = None, decorate: bool = False,
                exr_precision: str = "half") -> list[Path]:
    """Write the requested outputs, all of them renamed into place together at the end
    (:func:`cityshade.util.output_group`: a failing or interrupted write leaves none);
    returns the paths written. ``decorate`` (a map view): the PNG and the mask as RGB
    pictures in a margin with title, scale bar, north arrow, CRS and (mask) legend
    (:func:`decorated_picture`); the EXR and GeoTIFF keep their values. ``exr_precision``:
    ``"half"`` stores colour and normals as half (:data:`EXR_HALF_CHANNELS`), ``"full"``
    every channel as float32; the EXR is uncompressed either way (docs/DESIGN.md §15).

    Raises
    ------
    UsageError
        ``decorate`` for a perspective view.
    """
    from cityshade.util import output_group

    check_frame_outputs(frame.camera.kind, exr=exr, png=png, mask=mask, georef=georef)
    if exr_precision not in ("half", "full"):
        raise UsageError(f"--exr-precision must be half or full, not {exr_precision!r}")
    if decorate and frame.camera.kind != "map":
        raise UsageError("--decorate needs a map view (--camera map): a perspective picture "
                         "has no single scale or north")
    with output_group():  # all the files appear together at the end, or none
        return _write_frame(frame, scene, date_text, exr, png, mask, georef, decorate,
                            exr_precision)


def decorated_picture(rgb: np.ndarray, frame: Frame, scene, date_text: str,
                      mask: bool = False) -> np.ndarray:
    """A map view's picture (or shadow mask as RGB) with title (date and sun), scale bar,
    north arrow, CRS and, for a mask, the legend of its three values
    (:func:`cityshade.present.maps.decorate_or_plain`; unchanged without matplotlib)."""
    from cityshade import imageio
    from cityshade.present.maps import Categories, MapContext, decorate_or_plain

    sun = frame.sun
    title = (f"{date_text}; sun azimuth {sun.azimuth_true_deg:.1f}° (true), elevation "
             f"{sun.elevation_deg:.1f}°")
    legend = Categories(((((imageio.MASK_LIT,) * 3), "sun"), (((imageio.MASK_SHADOW,) * 3),
                         "shadow"), (((imageio.MASK_NODATA,) * 3), "no surface"))) \
        if mask else None
    return decorate_or_plain(rgb, MapContext(frame.camera.geotransform(scene.origin_m),
                                             scene.crs, title, legend))


#: The frame's EXR channels stored as half by default: colour (a linear radiance, shown to a
#: person) and the unit normals keep 11 significant bits, 5e-4 relative, far below what
#: they are used for; the shadow fraction (the product: a half could round 0.49995 to
#: 0.5, across the mask's threshold), Z (half steps are 1 m at 1.5 km), the ids and the
#: extra channels stay float32.
EXR_HALF_CHANNELS = ("R", "G", "B", "N.x", "N.y", "N.z")


def _write_frame(frame: Frame, scene, date_text: str, exr, png, mask, georef,
                 decorate: bool = False, exr_precision: str = "half") -> list[Path]:
    from cityshade import imageio
    from cityshade.runtime.memory import release_pages
    from cityshade.frame.shading import to_srgb8

    meta = frame_metadata(frame, scene, date_text)
    written = []
    s = frame.surfaces
    if exr is not None:
        shape = s.valid.shape

        def lazy(values, fill, *read):
            """Computed per strip of the EXR (no full-size temporaries); the rows of ``read``
            leave the resident set once read (a strip-wise frame's mapped arrays)."""
            def rows(y0, y1):
                out = np.where(s.valid[y0:y1], values[y0:y1], fill).astype(np.float32)
                release_pages(*(a[y0:y1] for a in read))
                return out
            return imageio.LazyChannel(shape, rows)

        channels = {
            "R": frame.rgb[..., 0], "G": frame.rgb[..., 1], "B": frame.rgb[..., 2],
            "shadow": frame.lit,
            # The resolved depth: the ground plane's pixels carry the plane's.
            "Z": lazy(s.depth, np.inf, s.depth),
            "N.x": lazy(s.normal[..., 0], 0.0), "N.y": lazy(s.normal[..., 1], 0.0),
            "N.z": lazy(s.normal[..., 2], 0.0, s.normal, s.valid),   # the last reader
            "primid": frame.gbuffer.prim_id, "objid": s.obj_id,
        }
        # A tiled cache's view writes the whole city's ids.
        channels["primid"] = scene.global_triangle_ids(frame.gbuffer.prim_id)
        channels["objid"] = scene.global_object_ids(s.obj_id)
        for name, values in frame.extra_channels.items():
            channels[name] = np.asarray(values, dtype=np.float32)
        # Uncompressed: zip cost 3× the frame's EXR time for 1/8 of the bytes (issue 41).
        imageio.write_exr(exr, channels, meta, compression="none",
                          half=EXR_HALF_CHANNELS if exr_precision == "half" else ())
        written.append(Path(exr))
    if png is not None:
        rgb8 = to_srgb8(frame.rgb)
        if decorate:
            rgb8 = decorated_picture(rgb8, frame, scene, date_text)
        imageio.write_png_rgb(png, rgb8, attributes=meta)
        written.append(Path(png))
    # The mask only for the outputs made of it (3.5 ms of a 1080p frame otherwise).
    mask_px = shadow_mask(frame, scene) if mask is not None or georef is not None else None
    release_pages(frame.lit, s.valid)
    if mask is not None and decorate:
        grey = np.repeat(np.asarray(mask_px).reshape(mask_px.shape[0], mask_px.shape[1], 1), 3,
                         axis=2)
        imageio.write_png_rgb(mask, decorated_picture(grey, frame, scene, date_text, True),
                              attributes=meta)
        written.append(Path(mask))
    elif mask is not None:
        imageio.write_mask_png(mask, mask_px, attributes=meta,
                               grey=bool(np.isin(mask_px, (0, 128, 255), invert=True).any()))
        written.append(Path(mask))
    if georef is not None:
        written += imageio.write_georeferenced(
            georef, mask_px, frame.camera.geotransform(scene.origin_m),
            epsg=scene.crs.horizontal_epsg, nodata=imageio.MASK_NODATA, attributes=meta)
    return written
