"""Texture images for shading: sRGB decode, mip pyramids and trilinear sampling.

Each texture image of a scene is read once per process (through :mod:`cityshade.imageio`, the
only OpenImageIO user), decoded to linear RGB, given an alpha channel and reduced to a mip
pyramid. All pyramids of a scene are packed into one flat texel array so one ``@njit`` kernel
samples any of them.

Conventions
-----------
* Texture coordinates follow CityGML/OpenGL: ``(u, v) = (0, 0)`` is the LOWER-left corner of
  the image, ``(1, 1)`` the upper-right; texel ``(i, j)`` of a level of size ``w × h`` (row ``j``
  counted from the TOP, as images are stored) has its centre at
  ``u = (i + 0.5) / w``, ``v = 1 - (j + 0.5) / h``.
* Texels are linear RGB premultiplied by alpha, plus alpha: ``(r·a, g·a, b·a, a)``. Premultiplied
  values filter correctly (a transparent texel adds no colour); the shader composites a sample
  over the surface's material colour as ``rgb + (1 - a) · material``.
* Level ``l + 1`` has size ``max(1, w // 2) × max(1, h // 2)``; each of its texels is the exact
  area average of the part of level ``l`` it covers (a 2×2 box for even sizes; for odd sizes
  the boxes overlap texels fractionally, so the level mean is preserved exactly).
* Wrap modes (CityGML ``wrapMode``): ``none`` — the texture covers [0, 1]² only, outside it the
  surface shows its material colour (inside, texel addressing clamps to the edge); ``wrap`` —
  repeat; ``mirror`` — repeat mirrored; ``clamp`` — edge texels extend outward; ``border`` —
  texels outside the image are the border colour (transparent if none is given).
"""
from __future__ import annotations

import functools
import math
import os
import threading
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numba import njit, prange

from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks

__all__ = [
    "WRAP_MODES", "MipPyramid", "TextureSet", "srgb_to_linear", "linear_to_srgb",
    "texels_from_image", "build_mip_levels", "load_mip_pyramid", "load_texture_set",
    "sample_trilinear", "composite_textures", "lod_from_uv_neighbours", "clear_texture_cache",
]

#: CityGML wrap modes → kernel codes (the order is the codes).
WRAP_MODES = ("none", "wrap", "mirror", "clamp", "border")
_WRAP_NONE, _WRAP_REPEAT, _WRAP_MIRROR, _WRAP_CLAMP, _WRAP_BORDER = range(5)

#: Slack (in uv units) around [0, 1]² inside which wrap mode "none" still shows the texture:
#: uv interpolated in float32 lands up to ~1e-7 outside an exact 0 or 1 edge, which must not
#: show the material colour along every facade border; 1e-5 is far below one texel of any
#: texture smaller than 100 000 px.
_NONE_UV_SLACK = 1e-5

#: Two neighbouring pixels belong to the same texture patch only if their normals differ by
#: less than about 1.1° (cos = 0.9998): across a crease the uv mapping jumps.
_SAME_PATCH_COS = 0.9998


# --- colour transfer -------------------------------------------------------------------------

def srgb_to_linear(encoded: np.ndarray) -> np.ndarray:
    """Decode sRGB-encoded values (IEC 61966-2-1) to linear light.

    Parameters
    ----------
    encoded : array_like, any shape
        sRGB values in 0..1.

    Returns
    -------
    numpy.ndarray, same shape, float32
        Linear values in 0..1.
    """
    x = np.asarray(encoded, dtype=np.float64)
    out = np.where(x <= 0.04045, x / 12.92, ((x + 0.055) / 1.055) ** 2.4)
    return out.astype(np.float32)


def linear_to_srgb(linear: np.ndarray) -> np.ndarray:
    """Encode linear values to sRGB (IEC 61966-2-1); input is clipped to 0..1 first.

    Parameters
    ----------
    linear : array_like, any shape

    Returns
    -------
    numpy.ndarray, same shape, float64
        sRGB-encoded values in 0..1.
    """
    x = np.clip(np.asarray(linear, dtype=np.float64), 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * x ** (1.0 / 2.4) - 0.055)


#: 8-bit sRGB → linear, one entry per code value (textures are mostly 8-bit).
_SRGB8_TO_LINEAR = srgb_to_linear(np.arange(256) / 255.0)


def texels_from_image(pixels: np.ndarray) -> np.ndarray:
    """Convert an image as read from a file to premultiplied linear RGBA float32.

    Parameters
    ----------
    pixels : numpy.ndarray, shape (H, W, C)
        Row 0 at the top. uint8/uint16 values are sRGB-encoded (decoded here); float values are
        taken as linear already (EXR/float TIFF convention). C = 1 (grey), 2 (grey + alpha),
        3 (RGB), 4 (RGBA) or more (extra channels ignored).

    Returns
    -------
    numpy.ndarray, shape (H, W, 4), float32
        ``(r·a, g·a, b·a, a)``, linear, in 0..1.

    Raises
    ------
    ValueError
        Not a 3-D array with 1 or more channels, or an unsupported pixel type.
    """
    pixels = np.asarray(pixels)
    if pixels.ndim != 3 or pixels.shape[2] < 1 or pixels.shape[0] < 1 or pixels.shape[1] < 1:
        raise ValueError(f"texture pixels must have shape (H, W, C), not {pixels.shape}")
    channels = pixels.shape[2]
    if pixels.dtype == np.uint8:
        colour = _SRGB8_TO_LINEAR[pixels]
        alpha = pixels.astype(np.float32) / np.float32(255.0)
    elif pixels.dtype == np.uint16:
        colour = srgb_to_linear(pixels / 65535.0)
        alpha = (pixels / 65535.0).astype(np.float32)
    elif pixels.dtype.kind == "f":
        colour = np.clip(np.nan_to_num(pixels.astype(np.float32)), 0.0, 1.0)
        alpha = colour
    else:
        raise ValueError(f"unsupported texture pixel type {pixels.dtype}")
    height, width = pixels.shape[:2]
    out = np.empty((height, width, 4), np.float32)
    if channels <= 2:  # grey, grey + alpha
        out[:, :, :3] = colour[:, :, :1]
    else:
        out[:, :, :3] = colour[:, :, :3]
    if channels == 2:
        out[:, :, 3] = alpha[:, :, 1]
    elif channels >= 4:
        out[:, :, 3] = alpha[:, :, 3]
    else:
        out[:, :, 3] = 1.0
    out[:, :, :3] *= out[:, :, 3:4]
    return out


# --- mip pyramid -----------------------------------------------------------------------------

@functools.lru_cache(maxsize=256)  # textures of a city share a few sizes
def _axis_weights(n_src: int, n_dst: int):
    """Exact area weights of a box reduction from ``n_src`` to ``n_dst`` cells along one axis.

    Output cell ``k`` covers source interval ``[k·r, (k+1)·r)`` with ``r = n_src / n_dst``;
    the weight of source cell ``i`` is its overlap with that interval divided by ``r``.
    Returns (first (n_dst,) int64, count (n_dst,) int64, weight (n_dst, 4) float64); at most
    4 taps because ``r < 3`` for the halving rule ``n_dst = max(1, n_src // 2)``, except
    ``n_src = n_dst`` (1 tap).
    """
    first = np.empty(n_dst, np.int64)
    count = np.zeros(n_dst, np.int64)
    weight = np.zeros((n_dst, 4), np.float64)
    ratio = n_src / n_dst
    for k in range(n_dst):
        lo = k * ratio
        hi = (k + 1) * ratio
        i0 = int(math.floor(lo))
        first[k] = i0
        i = i0
        while i < n_src and i < hi:
            overlap = min(hi, i + 1.0) - max(lo, float(i))
            if overlap > 0.0:
                weight[k, count[k]] = overlap / ratio
                count[k] += 1
            elif count[k] == 0:
                first[k] = i + 1
            i += 1
    for a in (first, count, weight):
        a.setflags(write=False)  # shared by every texture of these sizes
    return first, count, weight


def _reduce_level(src: np.ndarray) -> np.ndarray:
    """One mip step: ``(h, w, 4)`` → ``(max(1, h // 2), max(1, w // 2), 4)`` area averages."""
    h, w, _ = src.shape
    # The weights in Python (a few thousand steps for the largest texture): inside the kernel
    # they were 0.9 of its 1.9 CPU s of compiling, on a first render's critical path.
    return _reduce_kernel(src, *_axis_weights(w, max(1, w // 2)),
                          *_axis_weights(h, max(1, h // 2)))


@njit(cache=True)
def _reduce_kernel(src, xf, xc, xw, yf, yc, yw):
    h, _, nc = src.shape
    nh, nw = len(yf), len(xf)
    # Reduce along x into float64 rows, then along y: separable, exact area weights.
    rows = np.zeros((h, nw, nc), np.float64)
    for j in range(h):
        for k in range(nw):
            for t in range(xc[k]):
                wt = xw[k, t]
                i = xf[k] + t
                for c in range(nc):
                    rows[j, k, c] += wt * src[j, i, c]
    dst = np.zeros((nh, nw, nc), np.float32)
    for k in range(nh):
        for i in range(nw):
            for c in range(nc):
                acc = 0.0
                for t in range(yc[k]):
                    acc += yw[k, t] * rows[yf[k] + t, i, c]
                dst[k, i, c] = acc
    return dst


def build_mip_levels(texels: np.ndarray) -> list[np.ndarray]:
    """Mip pyramid of an image, finest first, down to 1×1.

    Parameters
    ----------
    texels : numpy.ndarray, shape (H, W, C), float32
        Level 0 (any channel count; premultiplied RGBA in cityshade).

    Returns
    -------
    list of numpy.ndarray, each (h_l, w_l, C) float32
        ``h_{l+1} = max(1, h_l // 2)``, same for widths; the last level is 1×1.
    """
    level = np.ascontiguousarray(texels, dtype=np.float32)
    if level.ndim != 3 or level.shape[0] < 1 or level.shape[1] < 1:
        raise ValueError(f"texels must have shape (H, W, C), not {level.shape}")
    levels = [level]
    while level.shape[0] > 1 or level.shape[1] > 1:
        level = _reduce_level(level)
        levels.append(level)
    return levels


@dataclass(frozen=True)
class MipPyramid:
    """The mip levels of one texture image.

    Attributes
    ----------
    levels : tuple of numpy.ndarray, each (h_l, w_l, 4) float32
        Premultiplied linear RGBA, finest first, row 0 at the top.
    path : str
        The image file.
    """

    levels: tuple
    path: str

    @property
    def width_px(self) -> int:
        return int(self.levels[0].shape[1])

    @property
    def height_px(self) -> int:
        return int(self.levels[0].shape[0])


_CACHE: dict[tuple, MipPyramid] = {}
_CACHE_LOCK = threading.Lock()


def clear_texture_cache() -> None:
    """Forget every cached mip pyramid (tests; long-running processes after file changes)."""
    with _CACHE_LOCK:
        _CACHE.clear()


def load_mip_pyramid(path: str | os.PathLike) -> MipPyramid:
    """Read an image file and build its mip pyramid, once per process per file version.

    The cache key is the absolute path with the file's size and modification time, so an edited
    image is read again.

    Raises
    ------
    cityshade.imageio.ImageIOError
        The file is missing, unreadable, not an image, or has an unsupported pixel type.
    """
    from cityshade.errors import ImageIOError
    from cityshade.imageio import read_image

    path = Path(path).absolute()
    try:
        stat = path.stat()
    except OSError as exc:
        raise ImageIOError(f"cannot read texture: {exc.strerror}", path=str(path)) from None
    key = (str(path), stat.st_size, stat.st_mtime_ns)
    with _CACHE_LOCK:
        hit = _CACHE.get(key)
    if hit is not None:
        return hit
    pixels, _ = read_image(path)
    try:
        texels = texels_from_image(pixels)
    except ValueError as exc:
        raise ImageIOError(f"cannot use texture: {exc}", path=str(path)) from None
    pyramid = MipPyramid(levels=tuple(build_mip_levels(texels)), path=str(path))
    with _CACHE_LOCK:
        _CACHE[key] = pyramid
    return pyramid


@dataclass(frozen=True)
class TextureSet:
    """All texture pyramids of a scene packed for the sampling kernel.

    Attributes
    ----------
    texels : numpy.ndarray, shape (N, 4), float32
        Every level of every texture, row-major, concatenated.
    level_offset, level_width, level_height : numpy.ndarray, shape (L,), int64
        First texel row in ``texels`` and size of each level.
    first_level : numpy.ndarray, shape (K + 1,), int64
        Levels of texture ``k`` are ``first_level[k]:first_level[k + 1]``; an empty range means
        the texture could not be loaded (the surface shows its material colour).
    wrap : numpy.ndarray, shape (K,), int64
        Wrap-mode code (index into :data:`WRAP_MODES`).
    border : numpy.ndarray, shape (K, 4), float32
        Premultiplied linear border colour (wrap mode ``border``).
    warnings : tuple of str
        One line per texture that could not be used.
    counters : dict
        ``loaded``, ``failed``, ``unknown_wrap_modes`` counts.
    """

    texels: np.ndarray
    level_offset: np.ndarray
    level_width: np.ndarray
    level_height: np.ndarray
    first_level: np.ndarray
    wrap: np.ndarray
    border: np.ndarray
    warnings: tuple = ()
    counters: dict = field(default_factory=dict)

    @property
    def n_textures(self) -> int:
        return len(self.wrap)


def _border_rgba(values) -> np.ndarray:
    """Premultiplied linear RGBA of a CityGML borderColor (sRGB + opacity; none → transparent)."""
    values = [float(v) for v in (values or [])]
    if len(values) not in (3, 4) or not all(math.isfinite(v) for v in values):
        return np.zeros(4, np.float32)
    alpha = min(max(values[3], 0.0), 1.0) if len(values) == 4 else 1.0
    rgb = srgb_to_linear(np.clip(values[:3], 0.0, 1.0))
    return np.array([*(rgb * alpha), alpha], np.float32)


def load_texture_set(textures: list[dict], used: np.ndarray | None = None) -> TextureSet:
    """Load the textures of a scene (``Scene.textures``) into one :class:`TextureSet`.

    Parameters
    ----------
    textures : list of dict
        ``path`` (absolute image path), ``wrap_mode`` (CityGML name), optional ``border_color``.
    used : array_like of bool, shape (K,), optional
        Load only these textures (others get an empty level range); default all.

    Returns
    -------
    TextureSet
        A texture that cannot be read is never an error: it gets no levels, a line in
        ``warnings`` and a count in ``counters["failed"]``.
    """
    from cityshade.errors import ImageIOError

    n = len(textures)
    used = np.ones(n, bool) if used is None else np.asarray(used, bool)
    chunks, offsets, widths, heights = [], [], [], []
    first = np.zeros(n + 1, np.int64)
    wrap = np.zeros(n, np.int64)
    border = np.zeros((n, 4), np.float32)
    messages: list[str] = []
    counters = {"loaded": 0, "failed": 0, "unknown_wrap_modes": 0}
    total = 0
    for k, tex in enumerate(textures):
        first[k] = len(offsets)
        mode = str(tex.get("wrap_mode") or "none").strip().lower()
        if mode not in WRAP_MODES:
            counters["unknown_wrap_modes"] += 1
            messages.append(f"texture {tex.get('path')}: unknown wrapMode {mode!r}, using 'none'")
            mode = "none"
        wrap[k] = WRAP_MODES.index(mode)
        border[k] = _border_rgba(tex.get("border_color"))
        if not used[k]:
            continue
        try:
            pyramid = load_mip_pyramid(tex["path"])
        except (ImageIOError, KeyError, TypeError) as exc:
            counters["failed"] += 1
            messages.append(f"texture not used, surfaces keep their material colour: {exc}")
            continue
        counters["loaded"] += 1
        for level in pyramid.levels:
            h, w = level.shape[:2]
            offsets.append(total)
            widths.append(w)
            heights.append(h)
            chunks.append(level.reshape(h * w, 4))
            total += h * w
    first[n] = len(offsets)
    texels = np.concatenate(chunks) if chunks else np.zeros((0, 4), np.float32)
    return TextureSet(texels=texels, level_offset=np.array(offsets, np.int64),
                      level_width=np.array(widths, np.int64),
                      level_height=np.array(heights, np.int64), first_level=first,
                      wrap=wrap, border=border, warnings=tuple(messages), counters=counters)


# --- sampling --------------------------------------------------------------------------------

@njit(cache=True, inline="always")
def _address(i, n, mode):
    """Texel index for integer coordinate ``i`` on an axis of ``n`` texels; -1 = outside."""
    if 0 <= i < n:
        return i
    if mode == _WRAP_REPEAT:
        return i % n
    if mode == _WRAP_MIRROR:
        m = i % (2 * n)
        return m if m < n else 2 * n - 1 - m
    if mode == _WRAP_BORDER:
        return -1
    # clamp, and "none" (whose outside is decided on uv before sampling)
    return 0 if i < 0 else n - 1


@njit(cache=True)
def _bilinear(texels, offset, w, h, mode, border, u, v, scale, out):
    """Add ``scale`` × the bilinear sample of one level at (u, v) into ``out`` (4,)."""
    x = u * w - 0.5
    y = (1.0 - v) * h - 0.5
    x0 = math.floor(x)
    y0 = math.floor(y)
    fx = x - x0
    fy = y - y0
    for dy in range(2):
        wy = fy if dy == 1 else 1.0 - fy
        if wy == 0.0:
            continue
        j = _address(int(y0) + dy, h, mode)
        for dx in range(2):
            wx = fx if dx == 1 else 1.0 - fx
            if wx == 0.0:
                continue
            i = _address(int(x0) + dx, w, mode)
            wt = wx * wy * scale
            if i < 0 or j < 0:
                for c in range(4):
                    out[c] += wt * border[c]
            else:
                row = offset + j * w + i
                for c in range(4):
                    out[c] += wt * texels[row, c]


@njit(cache=True)
def _sample_one(texels, level_offset, level_width, level_height, first_level, wrap, border,
                tex, u, v, lod, out):
    """Trilinear sample of texture ``tex`` at (u, v) and level ``lod`` into ``out[:4]``."""
    for c in range(4):
        out[c] = 0.0
    if tex < 0 or tex >= len(wrap):
        return
    l_begin = first_level[tex]
    n_levels = first_level[tex + 1] - l_begin
    if n_levels == 0 or not (math.isfinite(u) and math.isfinite(v)):
        return
    mode = wrap[tex]
    if mode == _WRAP_NONE and (u < -_NONE_UV_SLACK or u > 1.0 + _NONE_UV_SLACK
                               or v < -_NONE_UV_SLACK or v > 1.0 + _NONE_UV_SLACK):
        return  # outside the texture: transparent, the material shows
    # Clamp the level: below 0 is magnification (level 0), beyond the 1×1 level nothing coarser.
    if not math.isfinite(lod) or lod <= 0.0:
        lod = 0.0
    if lod > n_levels - 1:
        lod = float(n_levels - 1)
    l0 = int(math.floor(lod))
    t = lod - l0
    # Blend the two nearest levels (trilinear); t == 0 reads one level only.
    lev = l_begin + l0
    _bilinear(texels, level_offset[lev], level_width[lev], level_height[lev], mode,
              border[tex], u, v, 1.0 - t, out)
    if t > 0.0:
        lev = l_begin + l0 + 1
        _bilinear(texels, level_offset[lev], level_width[lev], level_height[lev], mode,
                  border[tex], u, v, t, out)


@njit(cache=True, parallel=True)
def _sample_kernel(texels, level_offset, level_width, level_height, first_level, wrap, border,
                   tex_id, uv, lod, out):
    n = len(tex_id)
    for p in prange(n):
        acc = np.zeros(4, np.float64)
        _sample_one(texels, level_offset, level_width, level_height, first_level, wrap, border,
                    tex_id[p], uv[p, 0], uv[p, 1], lod[p], acc)
        for c in range(4):
            out[p, c] = acc[c]


def sample_trilinear(texture_set: TextureSet, tex_id: np.ndarray, uv: np.ndarray,
                     lod: np.ndarray) -> np.ndarray:
    """Sample textures with trilinear filtering (bilinear in a level, linear between levels).

    Parameters
    ----------
    texture_set : TextureSet
    tex_id : array_like, shape (N,), int
        Texture per sample; -1 (or an unloaded texture) gives transparent black.
    uv : array_like, shape (N, 2), float
        Texture coordinates (CityGML convention, v up).
    lod : array_like, shape (N,), float
        Mip level: 0 = finest; fractional values blend two levels; clamped to the pyramid.

    Returns
    -------
    numpy.ndarray, shape (N, 4), float32
        Premultiplied linear RGBA.
    """
    tex_id = np.ascontiguousarray(tex_id, dtype=np.int64).ravel()
    uv = np.ascontiguousarray(uv, dtype=np.float64).reshape(-1, 2)
    lod = np.ascontiguousarray(lod, dtype=np.float64).ravel()
    if not len(tex_id) == len(uv) == len(lod):
        raise ValueError(f"tex_id, uv and lod must have the same length, not {len(tex_id)}, "
                         f"{len(uv)}, {len(lod)}")
    out = np.empty((len(tex_id), 4), np.float32)
    ts = texture_set
    _sample_kernel(ts.texels, ts.level_offset, ts.level_width, ts.level_height,
                   ts.first_level, ts.wrap, ts.border, tex_id, uv, lod, out)
    return out


@njit(cache=True, nogil=True)
def _composite_kernel(texels, level_offset, level_width, level_height, first_level, wrap, border,
                      tex_id, uv, lod, albedo, r0, r1):
    """Rows ``[r0, r1)`` of :func:`composite_textures` (serial, for ``run_chunks``: see
    ``runtime.threadpool.ROW_CHUNK``)."""
    height, width = tex_id.shape
    one = np.float32(1.0)
    for r in range(r0, r1):
        acc = np.zeros(4, np.float64)
        for c in range(width):
            k = tex_id[r, c]
            if k < 0:
                continue
            _sample_one(texels, level_offset, level_width, level_height, first_level, wrap,
                        border, k, np.float64(uv[r, c, 0]), np.float64(uv[r, c, 1]),
                        np.float64(lod[r, c]), acc)
            # float32 throughout, as numpy's (N, 4) float32 samples composite.
            keep = one - np.float32(acc[3])
            for i in range(3):
                albedo[r, c, i] = np.float32(acc[i]) + keep * albedo[r, c, i]


def composite_textures(texture_set: TextureSet, tex_id: np.ndarray, uv: np.ndarray,
                       lod: np.ndarray, albedo: np.ndarray) -> None:
    """Composite the premultiplied trilinear sample (:func:`sample_trilinear`) of every pixel
    with a texture over ``albedo`` in place: ``rgb + (1 - alpha) * albedo``, float32.

    One parallel pass over the picture instead of gathering the textured pixels, sampling and
    scattering back (serial numpy, most of a 1080p frame's shading time).

    Parameters
    ----------
    tex_id : (H, W) int
        Texture per pixel; -1: none (the pixel is left as it is).
    uv : (H, W, 2) float; lod : (H, W) float
    albedo : (H, W, 3) float32
    """
    tex_id = _native(tex_id, "iu", np.int64)
    uv = _native(uv, "f", np.float64)
    lod = _native(lod, "f", np.float64)
    if uv.shape != tex_id.shape + (2,) or lod.shape != tex_id.shape \
            or albedo.shape != tex_id.shape + (3,) or albedo.dtype != np.float32:
        raise ValueError("tex_id (H, W), uv (H, W, 2), lod (H, W) and float32 albedo (H, W, 3) "
                         "must describe the same pixels")
    ts = texture_set
    run_chunks(_composite_kernel, tex_id.shape[0], ROW_CHUNK, ts.texels, ts.level_offset,
               ts.level_width, ts.level_height, ts.first_level, ts.wrap, ts.border, tex_id, uv,
               lod, albedo)


# --- level of detail -------------------------------------------------------------------------

@njit(cache=True, inline="always")
def _same_patch(group, tex, normal, r0, c0, r1, c1):
    if group[r1, c1] != group[r0, c0] or tex[r1, c1] != tex[r0, c0]:
        return False
    # float64 products of the values as given (float32 normals need no float64 copy).
    dot = (np.float64(normal[r0, c0, 0]) * np.float64(normal[r1, c1, 0])
           + np.float64(normal[r0, c0, 1]) * np.float64(normal[r1, c1, 1])
           + np.float64(normal[r0, c0, 2]) * np.float64(normal[r1, c1, 2]))
    return dot > _SAME_PATCH_COS


@njit(cache=True, inline="always")
def _shorter_uv_step(uv, group, tex, normal, r, c, rr, cc, tw, th, best):
    """``best`` or, when shorter (or ``best`` < 0: none yet), the length in level-0 texels of
    the uv step from pixel (r, c) to its neighbour (rr, cc) on the same patch."""
    if not _same_patch(group, tex, normal, r, c, rr, cc):
        return best
    du = (np.float64(uv[rr, cc, 0]) - np.float64(uv[r, c, 0])) * tw
    dv = (np.float64(uv[rr, cc, 1]) - np.float64(uv[r, c, 1])) * th
    d = math.sqrt(du * du + dv * dv)
    return d if best < 0.0 or d < best else best


@njit(cache=True, nogil=True)
def _lod_kernel(uv, tex, group, normal, base_w, base_h, n_levels, bias, out, r0, r1):
    """Rows ``[r0, r1)`` of :func:`lod_from_uv_neighbours` (serial, for ``run_chunks``)."""
    height, width = tex.shape
    for r in range(r0, r1):
        for c in range(width):
            k = tex[r, c]
            if k < 0 or k >= len(base_w) or n_levels[k] == 0:
                out[r, c] = 0.0
                continue
            tw = base_w[k]
            th = base_h[k]
            # Screen-space uv derivative along each axis, in level-0 texels: of the two
            # one-sided differences on the same patch take the shorter (one side may cross a
            # uv seam of the atlas); none → unknown.
            best_x = -1.0
            for dc in (-1, 1):
                if 0 <= c + dc < width:
                    best_x = _shorter_uv_step(uv, group, tex, normal, r, c, r, c + dc, tw, th,
                                              best_x)
            best_y = -1.0
            for dr in (-1, 1):
                if 0 <= r + dr < height:
                    best_y = _shorter_uv_step(uv, group, tex, normal, r, c, r + dr, c, tw, th,
                                              best_y)
            if best_x < 0.0 and best_y < 0.0:
                # A patch one pixel across shows the whole texture in that pixel: its average.
                out[r, c] = n_levels[k] - 1
                continue
            rho = max(best_x, best_y)
            if rho <= 0.0:
                out[r, c] = 0.0
                continue
            lod = math.log2(rho) + bias
            out[r, c] = min(max(lod, 0.0), n_levels[k] - 1.0)


def _native(a, kinds: str, fallback) -> np.ndarray:
    """``a`` as a C-contiguous array of its own dtype when that is of ``kinds``, else of
    ``fallback``."""
    a = np.asarray(a)
    return np.ascontiguousarray(a, dtype=a.dtype if a.dtype.kind in kinds else fallback)


def lod_from_uv_neighbours(uv: np.ndarray, texture: np.ndarray, group: np.ndarray,
                           normal: np.ndarray, texture_set: TextureSet, *,
                           bias: float = 0.0) -> np.ndarray:
    """Mip level per pixel from finite uv differences between neighbouring pixels.

    ``lod = log2(max(|∂uv/∂x|, |∂uv/∂y|)) + bias`` with derivatives in level-0 texels per
    pixel (the OpenGL isotropic rule), clamped to the texture's pyramid. A neighbour counts
    only if it has the same ``group`` and texture id and nearly the same normal.

    Parameters
    ----------
    uv : numpy.ndarray, shape (H, W, 2), float
    texture : numpy.ndarray, shape (H, W), int
        Texture id per pixel, -1 none.
    group : numpy.ndarray, shape (H, W), int
        Continuous-uv patch id per pixel (polygon or triangle id).
    normal : numpy.ndarray, shape (H, W, 3), float
        Unit surface normal.
    texture_set : TextureSet
    bias : float
        Added to every level (positive = blurrier).

    Returns
    -------
    numpy.ndarray, shape (H, W), float32
    """
    # The kernel reads the arrays as they are (float32 or float64, any integer type) and
    # computes in float64: copies to float64 cost more than the kernel on a 1080p frame.
    texture = _native(texture, "iu", np.int64)
    height, width = texture.shape
    uv = _native(uv, "f", np.float64)
    group = _native(group, "iu", np.int64)
    normal = _native(normal, "f", np.float64)
    if uv.shape != (height, width, 2) or group.shape != (height, width) \
            or normal.shape != (height, width, 3):
        raise ValueError("uv (H, W, 2), texture (H, W), group (H, W) and normal (H, W, 3) "
                         "must describe the same pixels")
    ts = texture_set
    n_tex = ts.n_textures
    n_levels = np.diff(ts.first_level).astype(np.int64)
    base_w = np.ones(n_tex, np.float64)
    base_h = np.ones(n_tex, np.float64)
    for k in range(n_tex):
        if n_levels[k]:
            base_w[k] = ts.level_width[ts.first_level[k]]
            base_h[k] = ts.level_height[ts.first_level[k]]
    out = np.empty((height, width), np.float32)
    run_chunks(_lod_kernel, height, ROW_CHUNK, uv, texture, group, normal, base_w, base_h,
               n_levels, float(bias), out)
    return out
