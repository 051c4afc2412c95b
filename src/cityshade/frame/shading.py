"""Shading: per-pixel colour from the G-buffer surfaces, the lit fraction and the sun.

Model (linear RGB, per pixel with a surface)::

    rgb = albedo · (sun_rgb · max(N·L, 0) · lit + ambient(N))
    ambient(N) = ground_ambient_rgb + (sky_ambient_rgb − ground_ambient_rgb) · (1 + N_z) / 2

``L`` is the unit direction toward the sun, ``lit`` the lit fraction (0 shadow, 1 sun) from a
shadow technique. The ambient term is hemisphere lighting: a normal facing straight up sees the
whole sky, one facing down sees only the ground. A normal facing away from the camera (a back
face: the inside of a wall, a roof seen from below) is flipped before shading, so the visible
side is lit as a surface.

Albedo, by priority: the texture where the pixel has one (trilinear mip sampling,
:mod:`cityshade.frame.textures`; a texture's alpha, and wrap mode ``none`` outside [0, 1]², show the
colour underneath); else the X3DMaterial diffuse colour; else a neutral default colour of the
pixel's surface class (:data:`DEFAULT_PALETTE_SRGB8`). Material and palette colours are
sRGB-encoded display values like the texture images, and are decoded to linear before shading;
material transparency is not rendered (surfaces are opaque).

Pixels without a surface get a sky gradient in perspective views (``sky=True``) and NaN
(nodata) in map views or with ``sky=False``. :func:`to_srgb8` turns the result into 8-bit sRGB.
Everything is deterministic: no random numbers, and every pixel is computed independently.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from cityshade.errors import ShadingError
from cityshade.frame.textures import (TextureSet, composite_textures, load_texture_set,
                                lod_from_uv_neighbours, srgb_to_linear)
from cityshade.runtime.memory import Recycler
from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks

__all__ = ["ShadingError", "ShadingSettings", "DEFAULT_PALETTE_SRGB8", "shade", "to_srgb8",
           "albedo_of_surfaces"]

#: Surface classes in code order (mirrors cityshade.citygml.namespaces.SURFACE_CLASSES, which a
#: test checks; kept here so shading does not import the CityGML reader package).
_SURFACE_CLASSES = (
    "unclassified", "roof", "wall", "ground", "closure", "outer_ceiling", "outer_floor",
    "floor", "interior_wall", "ceiling", "door", "window", "terrain", "traffic",
    "auxiliary_traffic", "water", "vegetation", "furniture", "landuse", "generic",
    "installation", "marking",
)

#: Neutral colour per surface class for models without appearance (8-bit sRGB): muted tones of
#: what such surfaces usually look like, distinct enough to tell roofs from walls from ground.
DEFAULT_PALETTE_SRGB8: dict[str, tuple[int, int, int]] = {
    "unclassified": (200, 200, 200),
    "roof": (158, 84, 62),             # reddish-brown tiles
    "wall": (228, 216, 192),           # light beige plaster
    "ground": (150, 150, 140),         # building footprint (seen only from below)
    "closure": (205, 205, 205),
    "outer_ceiling": (205, 196, 180),
    "outer_floor": (200, 190, 172),
    "floor": (190, 180, 165),
    "interior_wall": (235, 228, 215),
    "ceiling": (238, 236, 230),
    "door": (120, 86, 60),
    "window": (110, 140, 165),
    "terrain": (150, 163, 128),        # grey-green
    "traffic": (128, 128, 128),        # road grey
    "auxiliary_traffic": (160, 158, 150),
    "water": (72, 118, 178),           # blue
    "vegetation": (92, 146, 70),       # green
    "furniture": (140, 122, 104),
    "landuse": (180, 186, 148),
    "generic": (190, 190, 196),
    "installation": (178, 168, 158),
    "marking": (240, 240, 240),
}


#: The memory of the albedo, texture inputs and shaded images of earlier frames, used again
#: once nothing refers to it (fresh pages: a fault and the kernel's zeroing each).
_IMAGES = Recycler(keep=8)


def _rgb_tuple(name: str, value) -> tuple[float, float, float]:
    values = tuple(float(v) for v in value)
    if len(values) != 3 or not all(math.isfinite(v) and v >= 0 for v in values):
        raise ShadingError(f"{name} must be three finite numbers >= 0, not {value!r}")
    return values


@dataclass(frozen=True)
class ShadingSettings:
    """Tunables of :func:`shade` (all colours linear RGB unless named ``_srgb8``)."""

    #: Sun irradiance colour at normal incidence: slightly warm white, so a sunlit surface of
    #: albedo a at N·L = 1 shows a · (1 + sky) without clipping for plaster-like albedos.
    sun_rgb: tuple = (1.0, 0.96, 0.88)
    #: Ambient light seen by a normal facing straight up (blue sky dome, ~1/3 of the sun: the
    #: usual clear-sky diffuse share), and straight down (ground bounce, dim and neutral).
    sky_ambient_rgb: tuple = (0.30, 0.34, 0.42)
    ground_ambient_rgb: tuple = (0.10, 0.095, 0.085)
    #: Background gradient of perspective views: zenith, horizon and below-horizon colours.
    sky_zenith_rgb: tuple = (0.16, 0.32, 0.68)
    sky_horizon_rgb: tuple = (0.60, 0.70, 0.84)
    sky_below_rgb: tuple = (0.33, 0.33, 0.32)
    #: Sample textures at all (False: material/palette colours only, no image is read).
    textures: bool = True
    #: Added to every mip level (positive = blurrier, negative = sharper but shimmers).
    mip_bias: float = 0.0
    #: Default colours per surface class name (8-bit sRGB); classes missing here use
    #: "unclassified".
    palette_srgb8: dict = field(default_factory=lambda: dict(DEFAULT_PALETTE_SRGB8))

    def __post_init__(self) -> None:
        for name in ("sun_rgb", "sky_ambient_rgb", "ground_ambient_rgb", "sky_zenith_rgb",
                     "sky_horizon_rgb", "sky_below_rgb"):
            object.__setattr__(self, name, _rgb_tuple(name, getattr(self, name)))
        if not math.isfinite(self.mip_bias):
            raise ShadingError(f"mip_bias must be finite, not {self.mip_bias}")
        unknown = set(self.palette_srgb8) - set(_SURFACE_CLASSES)
        if unknown:
            raise ShadingError(f"palette has unknown surface classes: {sorted(unknown)}")
        if "unclassified" not in self.palette_srgb8:
            raise ShadingError("palette needs an 'unclassified' colour")
        for name, value in self.palette_srgb8.items():
            values = tuple(value)
            if len(values) != 3 or not all(isinstance(v, (int, np.integer)) and 0 <= v <= 255
                                           for v in values):
                raise ShadingError(f"palette colour of {name!r} must be three integers 0..255, "
                                   f"not {value!r}")

    def palette_linear(self) -> np.ndarray:
        """(len(SURFACE_CLASSES), 3) float32 linear albedo per surface class code."""
        fallback = self.palette_srgb8["unclassified"]
        rows = [self.palette_srgb8.get(name, fallback) for name in _SURFACE_CLASSES]
        return srgb_to_linear(np.array(rows, np.float64) / 255.0)


# --- surfaces --------------------------------------------------------------------------------

def _field(surfaces, *names, required=True):
    """A per-pixel array of ``surfaces`` under the first of ``names`` it has."""
    for name in names:
        value = getattr(surfaces, name, None)
        if value is None and isinstance(surfaces, dict):
            value = surfaces.get(name)
        if value is not None:
            return np.asarray(value)
    if required:
        raise ShadingError(f"surfaces have no {names[0]!r} array")
    return None


def _material_table(materials) -> tuple[np.ndarray, np.ndarray]:
    """(M, 3) float32 linear diffuse colours and (M,) bool usable flags of ``Scene.materials``."""
    colours = np.zeros((len(materials), 3), np.float32)
    usable = np.zeros(len(materials), bool)
    for k, mat in enumerate(materials):
        diffuse = (mat or {}).get("diffuse")
        try:
            rgb = np.array([float(v) for v in diffuse], np.float64)
        except (TypeError, ValueError):
            continue
        if rgb.shape == (3,) and np.isfinite(rgb).all():
            colours[k] = srgb_to_linear(np.clip(rgb, 0.0, 1.0))
            usable[k] = True
    return colours, usable


#: Texture sets of recent scenes, keyed by their texture list: a batch of frames concatenates
#: the pyramids once (the pyramids themselves are cached per file in cityshade.frame.textures).
_TEXTURE_SETS: dict[tuple, TextureSet] = {}
_TEXTURE_SETS_MAX = 4  # a few scenes per process; each set can be hundreds of MB


def _texture_set(textures: list[dict], used: np.ndarray) -> TextureSet:
    key = (tuple((str(t.get("path")), str(t.get("wrap_mode")), tuple(t.get("border_color") or ()))
                 for t in textures), used.tobytes())
    hit = _TEXTURE_SETS.get(key)
    if hit is None:
        if len(_TEXTURE_SETS) >= _TEXTURE_SETS_MAX:
            _TEXTURE_SETS.pop(next(iter(_TEXTURE_SETS)))
        hit = _TEXTURE_SETS[key] = load_texture_set(textures, used)
    return hit


@njit(cache=True, nogil=True)
def _base_albedo_kernel(valid, material, klass, mat_colours, mat_usable, palette, out, r0, r1):
    """Material colour where usable, else the palette colour of the class (0 = unclassified)."""
    height, width = valid.shape
    n_mat = len(mat_usable)
    for r in range(r0, r1):
        for c in range(width):
            if not valid[r, c]:
                for k in range(3):
                    out[r, c, k] = 0.0
                continue
            m = material[r, c]
            if 0 <= m < n_mat and mat_usable[m]:
                for k in range(3):
                    out[r, c, k] = mat_colours[m, k]
            else:
                code = klass[r, c]
                if code < 0 or code >= len(palette):
                    code = 0
                for k in range(3):
                    out[r, c, k] = palette[code, k]


@njit(cache=True, nogil=True)
def _texture_inputs_kernel(valid, texture, prim, polygon, mode, n_tex, tex_ids, group, used,
                           counts, r0, r1):
    """Per pixel of rows ``[r0, r1)``: ``tex_ids`` the texture (-1: no surface or none of the
    ``n_tex``), ``group`` its uv patch (mode 0: 0 everywhere; 1: the triangle ``prim``; 2: its
    ``polygon``; -1 without a triangle); ``used[k]`` set for every texture seen; ``counts[r]``
    the textured pixels of row r. Serial, for ``run_chunks`` (as a ``prange`` kernel: 1.3 CPU
    s of a first render's compiling)."""
    width = valid.shape[1]
    for r in range(r0, r1):
        count = 0
        for c in range(width):
            k = texture[r, c]
            if valid[r, c] and 0 <= k < n_tex:
                tex_ids[r, c] = k
                used[k] = True          # every thread writes the same True
                count += 1
            else:
                tex_ids[r, c] = -1
            if mode == 0:
                group[r, c] = 0
            elif mode == 1:
                group[r, c] = prim[r, c]
            elif prim[r, c] < 0:
                group[r, c] = -1
            else:
                group[r, c] = polygon[prim[r, c]]
        counts[r] = count


def albedo_of_surfaces(scene, surfaces, *, settings: ShadingSettings | None = None,
                       prim_id: np.ndarray | None = None,
                       report: dict | None = None) -> np.ndarray:
    """Linear albedo per pixel: texture over material colour over class palette.

    Parameters
    ----------
    scene : cityshade.geometry.scene.Scene
        For ``materials``, ``textures`` and (with ``prim_id``) ``tri_polygon``.
    surfaces : Surfaces
        ``valid``, ``material``, ``texture``, ``uv``, ``normal`` and the surface class
        (``surface_class``/``cls``/``klass``/``class``), all (H, W[, k]).
    settings : ShadingSettings, optional
    prim_id : numpy.ndarray, shape (H, W), int, optional
        Triangle per pixel (the G-buffer's); lets the mip level use exact uv patches (the
        polygon of each triangle). Without it, patches are pixels of one texture and normal.
    report : dict, optional
        Filled with ``texture_warnings`` (list of str) and ``texture_counts`` (dict).

    Returns
    -------
    numpy.ndarray, shape (H, W, 3), float32
        Linear albedo in 0..1; 0 where ``valid`` is False.
    """
    settings = settings or ShadingSettings()
    valid = _field(surfaces, "valid").astype(bool)
    height, width = valid.shape
    material = _field(surfaces, "material")
    klass = _field(surfaces, "surface_class", "cls", "klass", "class_", "class")
    palette = settings.palette_linear()
    materials = list(getattr(scene, "materials", []) or [])
    colours, usable = _material_table(materials)
    albedo = _IMAGES.empty((height, width, 3), np.float32)
    run_chunks(_base_albedo_kernel, height, ROW_CHUNK, valid, np.ascontiguousarray(material),
               np.ascontiguousarray(klass), colours, usable, palette, albedo)
    textures = list(getattr(scene, "textures", []) or [])
    if not (settings.textures and textures):
        return albedo
    texture = _field(surfaces, "texture")
    n_tex = len(textures)
    polygon = getattr(scene, "tri_polygon", None)
    if prim_id is None:
        prim_id = _field(surfaces, "prim_id", required=False)
    # One parallel pass: texture id per pixel (-1 where none is used), the uv patch (polygon
    # of the triangle, else the triangle; no ids: one patch) and which textures are seen.
    prim = np.zeros((1, 1), np.int32) if prim_id is None else np.ascontiguousarray(prim_id)
    mode = 0 if prim_id is None else (1 if polygon is None else 2)
    tex_ids = _IMAGES.empty((height, width), np.int64)
    group = _IMAGES.empty((height, width), np.int64)
    used = np.zeros(n_tex, bool)
    counts = np.zeros(height, np.int64)
    run_chunks(_texture_inputs_kernel, height, ROW_CHUNK, valid, np.ascontiguousarray(texture),
               prim, np.zeros(1, np.int32) if polygon is None else np.asarray(polygon), mode,
               n_tex, tex_ids, group, used, counts)
    if not counts.any():
        return albedo  # no texture work when no visible pixel needs it (docs/DESIGN.md §10)
    tex_set = _texture_set(textures, used)
    if report is not None:
        report["texture_warnings"] = list(tex_set.warnings)
        report["texture_counts"] = dict(tex_set.counters)
    uv = _field(surfaces, "uv")
    normal = _field(surfaces, "normal")
    lod = lod_from_uv_neighbours(uv, tex_ids, group, normal, tex_set, bias=settings.mip_bias)
    # The premultiplied texel over the material/palette colour.
    composite_textures(tex_set, tex_ids, uv, lod, albedo)
    return albedo


# --- lighting --------------------------------------------------------------------------------

@njit(cache=True, nogil=True)
def _shade_kernel(valid, normal, position, albedo, lit, sun_dir, eye, view_dir, perspective,
                  sun_rgb, sky_rgb, ground_rgb, out, r0, r1):
    height, width = valid.shape
    for r in range(r0, r1):
        for c in range(width):
            if not valid[r, c]:
                out[r, c, 0] = np.nan       # no surface (the sky kernel may paint it)
                out[r, c, 1] = np.nan
                out[r, c, 2] = np.nan
                continue
            nx = float(normal[r, c, 0])
            ny = float(normal[r, c, 1])
            nz = float(normal[r, c, 2])
            # Flip back faces: the side the camera sees is the one that is lit.
            if perspective:
                vx = position[r, c, 0] - eye[0]
                vy = position[r, c, 1] - eye[1]
                vz = position[r, c, 2] - eye[2]
            else:
                vx = view_dir[0]
                vy = view_dir[1]
                vz = view_dir[2]
            if nx * vx + ny * vy + nz * vz > 0.0:
                nx = -nx
                ny = -ny
                nz = -nz
            ndotl = nx * sun_dir[0] + ny * sun_dir[1] + nz * sun_dir[2]
            sun = max(ndotl, 0.0) * min(max(float(lit[r, c]), 0.0), 1.0)
            # Hemisphere ambient: sky weight 1 facing up, 0 facing down.
            up = 0.5 * (1.0 + min(max(nz, -1.0), 1.0))
            for k in range(3):
                ambient = ground_rgb[k] + (sky_rgb[k] - ground_rgb[k]) * up
                out[r, c, k] = albedo[r, c, k] * (sun_rgb[k] * sun + ambient)


@njit(cache=True, nogil=True)
def _sky_kernel(valid, xs, ys, right, up, fwd, zenith, horizon, below, out, r0, r1):
    height, width = valid.shape
    for r in range(r0, r1):
        for c in range(width):
            if valid[r, c]:
                continue
            # The pixel's unit ray direction, as Camera.primary_rays computes it.
            dx = xs[c] * right[0] + ys[r] * up[0] + fwd[0]
            dy = xs[c] * right[1] + ys[r] * up[1] + fwd[1]
            dz = xs[c] * right[2] + ys[r] * up[2] + fwd[2]
            dz = dz / np.sqrt(dx * dx + dy * dy + dz * dz)
            for k in range(3):
                if dz >= 0.0:
                    # Bright haze at the horizon fading quickly to the zenith blue.
                    t = math.sqrt(min(dz, 1.0))
                    out[r, c, k] = horizon[k] + (zenith[k] - horizon[k]) * t
                else:
                    # Below the horizon (a camera above the model sees past it): a ground tone
                    # reached within ~15° so the horizon line stays soft.
                    t = min(-dz * 4.0, 1.0)
                    out[r, c, k] = horizon[k] + (below[k] - horizon[k]) * t


def shade(scene, surfaces, camera, lit_fraction: np.ndarray, sun_dir_render, *,
          sky: bool = True, settings: ShadingSettings | None = None,
          prim_id: np.ndarray | None = None, report: dict | None = None) -> np.ndarray:
    """Shade every pixel: Lambert sun × lit fraction + hemisphere sky ambient, times albedo.

    Parameters
    ----------
    scene : cityshade.geometry.scene.Scene
    surfaces : Surfaces
        From ``cityshade.raster.gbuffer.resolve``: ``valid`` (H, W) bool, ``normal`` (H, W, 3)
        unit face normals, ``position_m`` (H, W, 3) render space, ``material``, ``texture``
        (H, W) int, ``uv`` (H, W, 2), surface class (H, W) uint8.
    camera : cityshade.raster.camera.Camera
        ``kind`` "perspective" or "map"; ``eye_m``, ``target_m``; perspective views use
        ``screen_coordinates()`` and ``frame()`` (the pixel rays of
        ``primary_rays()``) for the sky background.
    lit_fraction : numpy.ndarray, shape (H, W), float
        0 = shadow, 1 = sunlit; values are clipped to 0..1; ignored where not ``valid``; NaN on
        a valid pixel is an error.
    sun_dir_render : array_like, shape (3,)
        Direction TOWARD the sun in render space (x east, y north, z up); normalised here.
    sky : bool
        Perspective views: paint pixels without surface with the sky gradient (else NaN).
    settings : ShadingSettings, optional
    prim_id : numpy.ndarray, shape (H, W), optional
        G-buffer triangle ids; sharpen the mip-level choice at polygon borders.
    report : dict, optional
        Receives texture warnings and counts (see :func:`albedo_of_surfaces`).

    Returns
    -------
    numpy.ndarray, shape (H, W, 3), float32
        Linear RGB; NaN on pixels without surface in map views (nodata) and with ``sky=False``.

    Raises
    ------
    ShadingError
        Shapes that do not match, NaN lit fraction on a surface, a zero or non-finite sun
        direction, an unknown camera kind.
    """
    settings = settings or ShadingSettings()
    valid = _field(surfaces, "valid").astype(bool)
    if valid.ndim != 2:
        raise ShadingError(f"surfaces.valid must be (H, W), not {valid.shape}")
    height, width = valid.shape
    lit = np.asarray(lit_fraction, dtype=np.float32)
    if lit.shape != (height, width):
        raise ShadingError(f"lit_fraction has shape {lit.shape}, surfaces {valid.shape}")
    if np.isnan(lit[valid]).any():
        raise ShadingError("lit_fraction is NaN on pixels with a surface")
    sun = np.asarray(sun_dir_render, dtype=np.float64).reshape(-1)
    norm = float(np.linalg.norm(sun)) if sun.shape == (3,) else 0.0
    if not (math.isfinite(norm) and norm > 0.0):
        raise ShadingError(f"sun direction must be a finite non-zero 3-vector, not "
                           f"{sun_dir_render!r}")
    sun = sun / norm
    kind = getattr(camera, "kind", None)
    if kind not in ("perspective", "map"):
        raise ShadingError(f"camera kind must be 'perspective' or 'map', not {kind!r}")
    normal = np.ascontiguousarray(_field(surfaces, "normal"), dtype=np.float32)
    if normal.shape != (height, width, 3):
        raise ShadingError(f"surfaces.normal has shape {normal.shape}, expected "
                           f"{(height, width, 3)}")
    eye = np.asarray(camera.eye_m, np.float64).reshape(3)
    view_dir = np.asarray(camera.target_m, np.float64).reshape(3) - eye
    perspective = kind == "perspective"
    position = _field(surfaces, "position_m", "position", required=perspective)
    if position is None:
        position = np.zeros((1, 1, 3))
    position = np.ascontiguousarray(position, dtype=np.float64)
    if perspective and position.shape != (height, width, 3):
        raise ShadingError(f"surfaces.position_m has shape {position.shape}, expected "
                           f"{(height, width, 3)}")

    # Every row-parallel kernel below takes rows a few at a time (dynamic scheduling through
    # run_chunks): the surfaces and the sky of a view are uneven over its rows (the sky kernel
    # alone, rows split in two halves, scaled 1.67x at two threads).
    albedo = albedo_of_surfaces(scene, surfaces, settings=settings, prim_id=prim_id,
                                report=report)
    out = _IMAGES.empty((height, width, 3), np.float32)     # every pixel written
    run_chunks(_shade_kernel, height, ROW_CHUNK, valid, normal, position,
               np.ascontiguousarray(albedo, np.float32), lit, sun, eye, view_dir, perspective,
               np.array(settings.sun_rgb), np.array(settings.sky_ambient_rgb),
               np.array(settings.ground_ambient_rgb), out)
    if perspective and sky and not valid.all():
        xs, ys = camera.screen_coordinates()
        if xs.shape != (width,) or ys.shape != (height,):
            raise ShadingError(f"camera gives {len(xs)}×{len(ys)} pixels for "
                               f"{height}×{width}")
        right, up, fwd = camera.frame()
        run_chunks(_sky_kernel, height, ROW_CHUNK, valid, xs, ys, right, up, fwd,
                   np.array(settings.sky_zenith_rgb), np.array(settings.sky_horizon_rgb),
                   np.array(settings.sky_below_rgb), out)
    return out


def to_srgb8(rgb: np.ndarray, *, nodata_srgb8=(0, 0, 0)) -> np.ndarray:
    """Encode linear RGB to 8-bit sRGB: clip to 0..1, IEC 61966-2-1 curve, round to nearest.

    Parameters
    ----------
    rgb : numpy.ndarray, shape (H, W, 3), float
        Linear RGB (as :func:`shade` returns).
    nodata_srgb8 : tuple of 3 int
        Colour of pixels with any non-finite channel (nodata).

    Returns
    -------
    numpy.ndarray, shape (H, W, 3), uint8
        ``round(255 · srgb(x))`` (half up); e.g. linear 0.5 → 188, 0.0 → 0, 1.0 → 255.
    """
    rgb = np.asarray(rgb)
    if rgb.ndim != 3 or rgb.shape[2] != 3:
        raise ShadingError(f"rgb must have shape (H, W, 3), not {rgb.shape}")
    nodata = np.asarray(nodata_srgb8, np.uint8).reshape(3)
    out = np.empty(rgb.shape, np.uint8)
    run_chunks(_encode_kernel, rgb.shape[0], ROW_CHUNK, np.ascontiguousarray(rgb, dtype=np.float32),
               _SRGB8_THRESHOLDS, nodata, out)
    return out


def _srgb8_thresholds() -> np.ndarray:
    """Linear value at which the rounded 8-bit sRGB code steps from k - 1 to k (k = 1..255).

    ``round(255 · srgb(x)) ≥ k`` exactly when ``srgb(x) ≥ (k - 0.5) / 255``, i.e. when
    ``x ≥ srgb⁻¹((k - 0.5) / 255)``; counting the thresholds at or below x gives the code
    without evaluating a power per pixel (round half up, clipping to 0..255 for free).
    """
    return _srgb_to_linear_f64((np.arange(1, 256) - 0.5) / 255.0)


def _srgb_to_linear_f64(encoded: np.ndarray) -> np.ndarray:
    """sRGB decode in float64 (thresholds must not carry float32 rounding)."""
    x = np.asarray(encoded, dtype=np.float64)
    return np.where(x <= 0.04045, x / 12.92, ((x + 0.055) / 1.055) ** 2.4)


_SRGB8_THRESHOLDS = _srgb8_thresholds()


@njit(cache=True, nogil=True)
def _encode_kernel(rgb, thresholds, nodata, out, r0, r1):
    height, width, _ = rgb.shape
    for r in range(r0, r1):
        for c in range(width):
            if not (math.isfinite(rgb[r, c, 0]) and math.isfinite(rgb[r, c, 1])
                    and math.isfinite(rgb[r, c, 2])):
                for k in range(3):
                    out[r, c, k] = nodata[k]
                continue
            for k in range(3):
                x = float(rgb[r, c, k])
                # Binary search: number of thresholds <= x (0..255).
                lo = 0
                hi = len(thresholds)
                while lo < hi:
                    mid = (lo + hi) >> 1
                    if thresholds[mid] <= x:
                        lo = mid + 1
                    else:
                        hi = mid
                out[r, c, k] = lo
