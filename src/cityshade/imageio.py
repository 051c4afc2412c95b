"""Reading and writing images: the only module of cityshade that touches OpenImageIO.

Every image the package writes goes through :func:`write_image`, which guards against the two
ways OpenImageIO loses data without an error:

* a 2-D ``(H, W)`` array handed to OpenImageIO's Python ``write_image`` writes wrong pixels
  (docs/DESIGN.md §15), so 2-D input is reshaped to ``(H, W, 1)`` here;
* a pixel type the format cannot store is converted silently (float → 8 bit in PNG, uint32 →
  half in EXR, uint32 → uint8 in TIFF), so each format accepts only the types it stores exactly
  and anything else is an :class:`ImageIOError`.

Files are written to a temporary name in the destination folder and renamed into place, so an
error never leaves a half-written image behind.

On top of that: :func:`write_exr` (named channels, float32 and integer ids, provenance header),
:func:`write_png_rgb`, :func:`write_mask_png` (255 sunlit, 0 shadow, 128 nodata) and
:func:`write_georeferenced` (GeoTIFF tags, world file, ``.prj``) for map views.

Conventions: arrays are ``(H, W, C)``, row 0 is the TOP row of the picture (image order, not map
order), channels last.
"""
from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Callable, Collection, Mapping, NamedTuple, Sequence

import numpy as np

from cityshade.errors import ImageIOError

__all__ = ["ImageIOError", "write_image", "read_image", "FORMAT_DTYPES", "write_exr", "read_exr",
           "write_png_rgb", "write_mask_png", "mask_from_lit", "write_georeferenced",
           "world_file_lines", "MASK_LIT", "MASK_SHADOW", "MASK_NODATA"]


#: Pixel types each format stores exactly, by file extension. OpenImageIO converts any other
#: type without an error (and without telling), so these are the only types we hand it.
FORMAT_DTYPES: dict[str, tuple[np.dtype, ...]] = {
    ".png": (np.dtype(np.uint8), np.dtype(np.uint16)),
    ".exr": (np.dtype(np.float32), np.dtype(np.float16)),
    ".tif": (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32)),
    ".tiff": (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32)),
    ".jpg": (np.dtype(np.uint8),),
    ".jpeg": (np.dtype(np.uint8),),
}

#: Channel counts a format can hold: PNG gray, gray+alpha, RGB, RGBA; baseline JPEG gray or RGB.
_FORMAT_CHANNELS: dict[str, tuple[int, ...] | None] = {
    ".png": (1, 2, 3, 4),
    ".jpg": (1, 3),
    ".jpeg": (1, 3),
    ".exr": None,
    ".tif": None,
    ".tiff": None,
}

_OIIO_TYPE_NAMES = {
    np.dtype(np.uint8): "uint8",
    np.dtype(np.uint16): "uint16",
    np.dtype(np.float16): "half",
    np.dtype(np.float32): "float",
}

#: OpenEXR stores channels sorted by name, so a reader gets them in another order than they were
#: written; we record the written order in this attribute and restore it on reading.
_CHANNEL_ORDER_ATTRIBUTE = "cityshade:channelOrder"


def _extension(path: Path) -> str:
    ext = path.suffix.lower()
    if ext not in FORMAT_DTYPES:
        raise ImageIOError(f"unsupported image extension {path.suffix or '(none)'!r}; use one of "
                           f"{', '.join(sorted(FORMAT_DTYPES))}", path=str(path))
    return ext


def _checked_pixels(path: Path, ext: str, pixels: np.ndarray) -> np.ndarray:
    """Validate ``pixels`` for format ``ext`` and return a C-contiguous ``(H, W, C)`` array."""
    pixels = np.asarray(pixels)
    if pixels.ndim == 2:
        # OpenImageIO writes wrong pixels from a 2-D array (docs/DESIGN.md §15): always hand it 3-D.
        pixels = pixels[:, :, np.newaxis]
    if pixels.ndim != 3:
        raise ImageIOError(f"pixels must have shape (H, W) or (H, W, C), not {pixels.shape}",
                           path=str(path))
    height, width, channels = pixels.shape
    if height == 0 or width == 0 or channels == 0:
        raise ImageIOError(f"cannot write an empty image of shape {pixels.shape}", path=str(path))
    allowed = FORMAT_DTYPES[ext]
    if pixels.dtype not in allowed:
        raise ImageIOError(
            f"{ext} cannot store {pixels.dtype} pixels exactly; use "
            f"{' or '.join(str(d) for d in allowed)} (or another format)", path=str(path))
    counts = _FORMAT_CHANNELS[ext]
    if counts is not None and channels not in counts:
        raise ImageIOError(f"{ext} cannot store {channels} channels (only "
                           f"{', '.join(map(str, counts))})", path=str(path))
    return np.ascontiguousarray(pixels)


def _set_attribute(spec, path: Path, name: str, value) -> None:
    if not isinstance(name, str) or not name:
        raise ImageIOError(f"attribute names must be non-empty strings, not {name!r}",
                           path=str(path))
    # bool is an int subclass: store it as 0/1 rather than refusing it.
    if isinstance(value, (bool, np.bool_)):
        spec.attribute(name, int(value))
    elif isinstance(value, (int, np.integer)):
        spec.attribute(name, int(value))
    elif isinstance(value, (float, np.floating)):
        spec.attribute(name, float(value))
    elif isinstance(value, str):
        spec.attribute(name, value)
    else:
        raise ImageIOError(f"attribute {name!r} must be a str, int or float, not "
                           f"{type(value).__name__}", path=str(path))


#: Rows of an EXR written by strips (:func:`write_exr`): only one strip's interleaved buffer
#: exists at a time (a multiple of the 16-row blocks of its zip compression).
EXR_STRIP_ROWS = 64


class Strips(NamedTuple):
    """Pixels produced strip by strip: ``rows(y0, y1)`` gives rows ``[y0, y1)`` as a
    ``(y1 - y0, W, C)`` array of ``dtype``; ``shape`` is the whole image's (H, W, C)."""

    shape: tuple
    dtype: np.dtype
    rows: Callable[[int, int], np.ndarray]


class LazyChannel(NamedTuple):
    """A float channel of :func:`write_exr` computed per strip of rows: ``rows(y0, y1)`` gives
    rows ``[y0, y1)`` of the (H, W) ``shape`` (so no full-size temporary is made for it)."""

    shape: tuple
    rows: Callable[[int, int], np.ndarray]


def _write_atomically(path: Path, parts: Sequence[tuple], finish=None) -> None:
    """Write ``parts`` [(ImageSpec, pixels), ...] (several = a multi-part EXR) to ``path``;
    pixels given as :class:`Strips` are written ``EXR_STRIP_ROWS`` scanlines at a time.

    The image goes to a temporary name next to the destination (:func:`cityshade.util.atomic_path`;
    the name keeps the extension because OpenImageIO picks the format from it).
    ``finish(tmp_path)``, if given, edits the complete temporary file before the rename. Any
    failure removes the temporary file.
    """
    import OpenImageIO as oiio  # heavy import only when an image is written (docs/DESIGN.md §17)

    from cityshade.util import atomic_path

    ext = path.suffix.lower()
    with atomic_path(path, keep_suffix=True, error=ImageIOError, what="image") as tmp:
        tmp_name = str(tmp)
        out = oiio.ImageOutput.create(tmp_name)
        if out is None:
            raise ImageIOError(f"OpenImageIO has no writer for {ext}: {oiio.geterror()}",
                               path=str(path))
        if len(parts) > 1 and not out.supports("multiimage"):
            raise ImageIOError(f"{ext} cannot hold several parts", path=str(path))
        specs = [spec for spec, _ in parts]
        ok, error = True, ""
        for index, (spec, pixels) in enumerate(parts):
            if index == 0:
                opened = out.open(tmp_name, specs) if len(parts) > 1 else out.open(tmp_name, spec)
            else:
                opened = out.open(tmp_name, spec, "AppendSubimage")
            if not opened:
                raise ImageIOError(f"cannot write image: {out.geterror() or oiio.geterror()}",
                                   path=str(path))
            if isinstance(pixels, Strips):
                for y0 in range(0, pixels.shape[0], EXR_STRIP_ROWS):
                    y1 = min(y0 + EXR_STRIP_ROWS, pixels.shape[0])
                    ok = out.write_scanlines(y0, y1, 0, np.ascontiguousarray(pixels.rows(y0, y1)))
                    if not ok:
                        break
            else:
                ok = out.write_image(pixels)
            if not ok:
                error = out.geterror()
                break
        if not out.close() and ok:
            ok, error = False, out.geterror()
        if not ok:
            raise ImageIOError(f"cannot write image: {error or 'OpenImageIO failed'}",
                               path=str(path))
        if finish is not None:
            finish(tmp_name)


def write_image(path: str | os.PathLike, pixels: np.ndarray, *,
                attributes: Mapping[str, str | float | int] | None = None,
                channel_names: Sequence[str] | None = None) -> None:
    """Write an image atomically; the format comes from the extension.

    Parameters
    ----------
    path : str or path-like
        Destination; extension ``.png``, ``.exr``, ``.tif``/``.tiff`` or ``.jpg``/``.jpeg``.
        An existing file is replaced only once the new one is complete.
    pixels : numpy.ndarray, shape (H, W, C) or (H, W)
        Row 0 is the top row. A 2-D array is written as one channel. Types stored exactly:
        PNG uint8/uint16 (1–4 channels); EXR float32/float16; TIFF uint8/uint16/float32; JPEG
        uint8 (1 or 3 channels, lossy). Other combinations raise :class:`ImageIOError`.
    attributes : mapping of str to str, int or float, optional
        Metadata written into the header (e.g. EXR provenance: date, sun, technique).
    channel_names : sequence of str, optional
        One name per channel (e.g. ``("lit", "depth")`` in an EXR). OpenEXR sorts channels by
        name; the written order is recorded and :func:`read_image` restores it.

    Raises
    ------
    ImageIOError
        Bad shape, type, channel count, names or attributes; the folder does not exist or is
        not writable; OpenImageIO fails. No file is left behind in any of these cases.
    """
    path = Path(path)
    ext = _extension(path)
    pixels = _checked_pixels(path, ext, pixels)
    spec = _make_spec(path, ext, pixels, attributes, channel_names)
    _write_atomically(path, [(spec, pixels)])


def _make_spec(path: Path, ext: str, pixels: np.ndarray, attributes, channel_names):
    """The ImageSpec of checked ``pixels`` with channel names and attributes."""
    import OpenImageIO as oiio  # heavy import only when an image is written (docs/DESIGN.md §17)

    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, _OIIO_TYPE_NAMES[pixels.dtype])
    if channel_names is not None:
        names = tuple(channel_names)
        if len(names) != channels or not all(isinstance(n, str) and n for n in names):
            raise ImageIOError(f"channel_names must be {channels} non-empty strings, not "
                               f"{names!r}", path=str(path))
        if len(set(names)) != len(names):
            raise ImageIOError(f"channel names must be distinct: {names!r}", path=str(path))
        spec.channelnames = names
        if ext == ".exr":
            _set_attribute(spec, path, _CHANNEL_ORDER_ATTRIBUTE, ",".join(names))
    # Pixels are stored as given: never (un)premultiplied by an alpha channel (OpenImageIO
    # otherwise assumes associated alpha and divides colour by alpha when writing a PNG).
    spec.attribute("oiio:UnassociatedAlpha", 1)
    for name, value in (attributes or {}).items():
        _set_attribute(spec, path, name, value)
    return spec


def read_image(path: str | os.PathLike) -> tuple[np.ndarray, dict]:
    """Read an image in the type stored in the file.

    Parameters
    ----------
    path : str or path-like
        Any format OpenImageIO reads.

    Returns
    -------
    pixels : numpy.ndarray, shape (H, W, C)
        Row 0 is the top row; dtype is the file's (uint8, uint16, float16, float32, ...). A file
        whose channels have different types is read as float32.
    attributes : dict
        The header metadata (name → value) plus ``"channel_names"``: a tuple with one name per
        channel of ``pixels``, in the order they were written by :func:`write_image`.

    Raises
    ------
    ImageIOError
        The file is missing, unreadable or not an image.
    """
    import OpenImageIO as oiio  # heavy import only when an image is read (docs/DESIGN.md §17)

    path = Path(path)
    if not path.is_file():
        raise ImageIOError("cannot read image: no such file", path=str(path))
    # Ask for alpha as stored: without this, PNG/TIFF colour is premultiplied by alpha on reading.
    config = oiio.ImageSpec()
    config.attribute("oiio:UnassociatedAlpha", 1)
    inp = oiio.ImageInput.open(str(path), config)
    if inp is None:
        raise ImageIOError(f"cannot read image: {oiio.geterror() or 'unknown format'}",
                           path=str(path))
    try:
        spec = inp.spec()
        mixed = len(set(str(f) for f in spec.channelformats)) > 1
        pixels = inp.read_image(oiio.FLOAT if mixed else oiio.UNKNOWN)
        if pixels is None:
            raise ImageIOError(f"cannot read image: {inp.geterror() or 'read failed'}",
                               path=str(path))
        attributes = {p.name: p.value for p in spec.extra_attribs}
        names = tuple(spec.channelnames)
    finally:
        inp.close()
    pixels = np.asarray(pixels)
    if pixels.ndim == 2:
        pixels = pixels[:, :, np.newaxis]
    # Restore the channel order write_image was given (OpenEXR stores channels sorted by name).
    order = attributes.get(_CHANNEL_ORDER_ATTRIBUTE)
    if isinstance(order, str):
        wanted = tuple(order.split(","))
        if sorted(wanted) == sorted(names) and wanted != names:
            index = [names.index(n) for n in wanted]
            pixels = np.ascontiguousarray(pixels[:, :, index])
            names = wanted
    attributes["channel_names"] = names
    return pixels, attributes


# --- EXR with named channels -----------------------------------------------------------------

#: Integer values float32 holds exactly: every integer of magnitude up to 2**24.
_FLOAT32_EXACT_INT = 2 ** 24
#: Attribute listing the channels that were integers (stored as exact float32 values).
_INT_CHANNELS_ATTRIBUTE = "cityshade:intChannels"
#: uint32 value that stands for -1 ("none") in the uint32 part of an EXR.
_UINT32_NONE = 0xFFFFFFFF


def write_exr(path: str | os.PathLike, channels: Mapping[str, np.ndarray],
              attributes: Mapping[str, str | float | int] | None = None, *,
              half: Collection[str] = (), compression: str = "zip") -> None:
    """Write named (H, W) channels to an OpenEXR file atomically.

    Float channels are stored as float32 (NaN and ±inf kept). Integer and bool channels (ids,
    -1 = none) are stored as float32 too when every value is an integer of magnitude
    ≤ 2**24, which float32 holds exactly (scenes up to 16.7 M triangles); their names are
    recorded in the header attribute ``cityshade:intChannels``. Larger ids go into a second
    EXR part named ``ids`` as uint32, with -1 stored as 0xFFFFFFFF. :func:`read_exr` undoes
    both.

    Parameters
    ----------
    path : str or path-like
        Destination ending in ``.exr``.
    channels : mapping of str to numpy.ndarray (H, W) or :class:`LazyChannel`
        E.g. ``R, G, B, shadow, Z, N.x, N.y, N.z, primid, objid``; order is kept on reading.
        The file is written by strips of ``EXR_STRIP_ROWS`` rows: beside the channels only one
        strip's buffer is held (a lazy channel's strip is computed when written).
    attributes : mapping of str to str, int or float, optional
        Header metadata (provenance: date, sun, technique, CRS, timings...), in every part.
    half : collection of str
        Float channels stored as half (16-bit: values rounded to the nearest half, ties to
        even, as ``numpy.float16``; beyond ±65504 they become ±inf); the others stay float32.
    compression : str
        ``"zip"`` (OpenEXR's zlib in blocks of 16 rows, through OpenImageIO) or ``"none"``
        (:func:`_write_exr_uncompressed`: about 3× faster on a 1080p frame, files ~8× larger).
        A file that needs the uint32 ``ids`` part is always written with zip.

    Raises
    ------
    ImageIOError
        Wrong extension, no channels, shapes that differ or are not 2-D, unsupported types,
        integers outside -1 … 2**32 - 2, bad names or attributes, an unknown compression or
        ``half`` naming no float channel, or a write failure.
    """
    path = Path(path)
    if path.suffix.lower() != ".exr":
        raise ImageIOError(f"write_exr needs a .exr path, not {path.suffix or '(none)'!r}",
                           path=str(path))
    if not channels:
        raise ImageIOError("write_exr needs at least one channel", path=str(path))
    shape, float_names, float_planes, uint_names, uint_planes, int_names = \
        _sorted_channels(path, channels)
    if compression not in ("zip", "none"):
        raise ImageIOError(f"EXR compression must be zip or none, not {compression!r}",
                           path=str(path))
    half = frozenset(half)
    stray = sorted(half.difference(float_names).union(half.intersection(int_names)))
    if stray:
        raise ImageIOError(f"half channels must be float channels: {', '.join(stray)}",
                           path=str(path))
    attrs = dict(attributes or {})
    if int_names:
        attrs[_INT_CHANNELS_ATTRIBUTE] = ",".join(int_names)
    if compression == "none" and not uint_names:
        if len(set(float_names)) != len(float_names):
            raise ImageIOError(f"channel names must be distinct: {float_names!r}",
                               path=str(path))
        for name, value in attrs.items():   # the checks and types OpenImageIO's path applies
            _set_attribute(_AttributeCheck(), path, name, value)
        _write_exr_uncompressed(path, float_names, float_planes, attrs, half)
        return
    parts = []
    for part_name, names, planes in (("data", float_names, float_planes),
                                     ("ids", uint_names, uint_planes)):
        if not names:
            continue
        if len(set(names)) != len(names):
            raise ImageIOError(f"channel names must be distinct: {names!r}", path=str(path))
        # Interleaved strips, each plane converted straight into them (exact: integers in the
        # float part are at most 2**24 in magnitude).
        pixels = Strips(shape + (len(planes),), np.dtype(np.float32 if part_name == "data"
                                                          else np.uint32),
                        _interleaver(planes, part_name == "ids"))
        part_attrs = dict(attrs)
        part_attrs["name"] = part_name
        if pixels.dtype == np.uint32:
            spec = _make_uint32_spec(path, pixels, part_attrs, names)
        else:
            spec = _make_spec(path, ".exr", pixels, part_attrs, names)
            if half:   # OpenImageIO rounds the float32 strips into the half channels
                import OpenImageIO as oiio

                spec.channelformats = tuple(oiio.TypeDesc("half" if n in half else "float")
                                            for n in names)
        parts.append((spec, pixels))
    _write_atomically(path, parts)


def _sorted_channels(path: Path, channels: Mapping) -> tuple:
    """:func:`write_exr`'s channels checked and sorted: (shape, float names, float planes,
    uint32 id names, their planes, the names of the integer channels stored as floats)."""
    from cityshade.runtime.memory import release_pages

    shape = None
    float_names, float_planes, uint_names, uint_planes = [], [], [], []
    int_names = []
    for name, values in channels.items():
        if not isinstance(name, str) or not name or "," in name:
            raise ImageIOError(f"channel names must be non-empty strings without commas, "
                               f"not {name!r}", path=str(path))
        if isinstance(values, LazyChannel):
            if len(values.shape) != 2 or 0 in values.shape:
                raise ImageIOError(f"channel {name!r} must be a non-empty (H, W) channel, not "
                                   f"{values.shape}", path=str(path))
            if shape is None:
                shape = tuple(values.shape)
            elif tuple(values.shape) != shape:
                raise ImageIOError(f"channel {name!r} has shape {values.shape}, others {shape}",
                                   path=str(path))
            float_names.append(name)
            float_planes.append(values)
            continue
        values = np.asarray(values)
        if values.ndim != 2 or 0 in values.shape:
            raise ImageIOError(f"channel {name!r} must be a non-empty (H, W) array, not "
                               f"{values.shape}", path=str(path))
        if shape is None:
            shape = values.shape
        elif values.shape != shape:
            raise ImageIOError(f"channel {name!r} has shape {values.shape}, others {shape}",
                               path=str(path))
        kind = values.dtype.kind
        if kind == "f":
            float_names.append(name)
            float_planes.append(values)
        elif kind in "biu":
            lo, hi = int(values.min()), int(values.max())
            release_pages(values)   # a mapped array's pages read for the range (a strip-wise frame)
            if lo >= -_FLOAT32_EXACT_INT and hi <= _FLOAT32_EXACT_INT:
                float_names.append(name)
                float_planes.append(values)
                int_names.append(name)
            elif lo >= -1 and hi < _UINT32_NONE:
                uint_names.append(name)
                uint_planes.append(values)      # -1 → _UINT32_NONE per strip
            else:
                raise ImageIOError(f"channel {name!r} has values {lo} … {hi}; EXR ids must lie "
                                   f"in -1 … {_UINT32_NONE - 1}", path=str(path))
        else:
            raise ImageIOError(f"channel {name!r} has type {values.dtype}; EXR stores floats "
                               f"and integer ids", path=str(path))
    return shape, float_names, float_planes, uint_names, uint_planes, int_names


def _interleaver(planes, ids: bool) -> Callable[[int, int], np.ndarray]:
    """``rows(y0, y1)``: rows ``[y0, y1)`` of the planes interleaved as one (rows, W, C)
    float32 strip, or uint32 with -1 as ``_UINT32_NONE`` when ``ids``."""
    from cityshade.runtime.memory import release_pages

    width = planes[0].shape[1]

    def rows(y0: int, y1: int) -> np.ndarray:
        strip = np.empty((y1 - y0, width, len(planes)), np.uint32 if ids else np.float32)
        for index, plane in enumerate(planes):
            if isinstance(plane, LazyChannel):
                strip[..., index] = plane.rows(y0, y1)
            elif ids:
                wide = plane[y0:y1].astype(np.int64)
                strip[..., index] = np.where(wide < 0, _UINT32_NONE, wide)
            else:
                strip[..., index] = plane[y0:y1]
        # A read-only map's rows (a strip-wise frame's) leave the resident set once read.
        release_pages(*(p[y0:y1] for p in planes if not isinstance(p, LazyChannel)))
        return strip

    return rows


class _AttributeCheck:
    """Stands for an ImageSpec in :func:`_set_attribute` (its checks without OpenImageIO)."""

    def attribute(self, name, value):
        pass


#: EXR pixel types (OpenEXR file layout, "PixelType") of the direct writer.
_EXR_HALF, _EXR_FLOAT = 1, 2


def _exr_attribute(name: str, type_name: str, payload: bytes) -> bytes:
    return (name.encode() + b"\0" + type_name.encode() + b"\0"
            + len(payload).to_bytes(4, "little") + payload)


def _write_exr_uncompressed(path: Path, names: Sequence[str], planes: Sequence,
                            attributes: Mapping, half: Collection[str]) -> None:
    """Write a single-part scanline EXR without compression, straight from the planes.

    Written by hand because OpenEXR's writer copies every value through its byte-wise
    converter: about 13 ns per value under load even uncompressed (a 1080p frame's 20.7 M
    values: 220 ms CPU, 680 ms with zip), where the file's rows are the planes' rows as they
    are (little-endian, one channel after the other in name order): here numpy copies them
    at memory speed, strip by strip (``EXR_STRIP_ROWS``). Files readable by every OpenEXR
    reader (the layout of the OpenEXR file-format document: magic, version, header, one
    offset per scanline, then each scanline as y, byte count, channel rows); tests read them
    back through OpenImageIO. Attributes: str → ``string``, int → ``int``, float → ``float``
    (32-bit), as OpenImageIO writes them.
    """
    import struct

    from cityshade.halffloat import float32_to_half_bits
    from cityshade.runtime.memory import release_pages
    from cityshade.util import atomic_path

    height, width = planes[0].shape
    order = sorted(range(len(names)), key=lambda i: names[i].encode())  # file order: by name
    dtypes = [np.dtype("<f2" if names[i] in half else "<f4") for i in order]
    chlist = b"".join(names[i].encode() + b"\0" + struct.pack(
        "<iB3xii", _EXR_HALF if dt.itemsize == 2 else _EXR_FLOAT, 0, 1, 1)
        for i, dt in zip(order, dtypes)) + b"\0"
    box = struct.pack("<4i", 0, 0, width - 1, height - 1)
    attrs = {**attributes, _CHANNEL_ORDER_ATTRIBUTE: ",".join(names), "name": "data"}
    header = [_exr_attribute("channels", "chlist", chlist),
              _exr_attribute("compression", "compression", b"\0"),
              _exr_attribute("dataWindow", "box2i", box),
              _exr_attribute("displayWindow", "box2i", box),
              _exr_attribute("lineOrder", "lineOrder", b"\0"),
              _exr_attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)),
              _exr_attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0)),
              _exr_attribute("screenWindowWidth", "float", struct.pack("<f", 1.0))]
    for name, value in attrs.items():
        if isinstance(value, str):
            header.append(_exr_attribute(name, "string", value.encode()))
        elif isinstance(value, (bool, np.bool_, int, np.integer)):
            header.append(_exr_attribute(name, "int", struct.pack("<i", int(value))))
        else:
            header.append(_exr_attribute(name, "float", struct.pack("<f", float(value))))
    long_names = any(len(n.encode()) > 31 for n in attrs)
    head = (b"\x76\x2f\x31\x01" + struct.pack("<I", 2 | (0x400 if long_names else 0))
            + b"".join(header) + b"\0")
    row_bytes = 8 + width * sum(dt.itemsize for dt in dtypes)
    first = len(head) + 8 * height
    offsets = first + row_bytes * np.arange(height, dtype=np.uint64)
    with atomic_path(path, keep_suffix=True, error=ImageIOError, what="image") as tmp:
        try:
            with open(tmp, "wb") as fh:
                fh.write(head)
                fh.write(offsets.astype("<u8").tobytes())
                for y0 in range(0, height, EXR_STRIP_ROWS):
                    y1 = min(y0 + EXR_STRIP_ROWS, height)
                    strip = np.empty((y1 - y0, row_bytes), np.uint8)
                    lead = strip[:, :8].view("<i4")
                    lead[:, 0] = np.arange(y0, y1)
                    lead[:, 1] = row_bytes - 8
                    at = 8
                    for i, dt in zip(order, dtypes):
                        plane = planes[i]
                        rows = plane.rows(y0, y1) if isinstance(plane, LazyChannel) \
                            else plane[y0:y1]
                        target = strip[:, at:at + width * dt.itemsize]
                        if dt.itemsize == 2:
                            float32_to_half_bits(np.ascontiguousarray(rows, np.float32),
                                                 target.view("<u2"))
                        else:
                            target.view(dt)[:] = rows
                        at += width * dt.itemsize
                    release_pages(*(p[y0:y1] for p in planes if not isinstance(p, LazyChannel)))
                    fh.write(strip.data)
        except OSError as exc:
            raise ImageIOError(f"cannot write image: {exc.strerror or exc}",
                               path=str(path)) from None


def _make_uint32_spec(path: Path, pixels, attributes, names):
    """ImageSpec of a uint32 EXR part (not a type :func:`write_image` accepts)."""
    import OpenImageIO as oiio

    height, width, channels = pixels.shape
    spec = oiio.ImageSpec(width, height, channels, "uint")
    spec.channelnames = tuple(names)
    _set_attribute(spec, path, _CHANNEL_ORDER_ATTRIBUTE, ",".join(names))
    for name, value in attributes.items():
        _set_attribute(spec, path, name, value)
    return spec


def read_exr(path: str | os.PathLike) -> tuple[dict[str, np.ndarray], dict]:
    """Read every channel of every part of an EXR written by :func:`write_exr`.

    Returns
    -------
    channels : dict of str to numpy.ndarray, each (H, W)
        In the written order. Float channels float32 (half → float32); channels written as
        integers are int64 (-1 = none); other uint32 channels uint32.
    attributes : dict
        Header of the first part, plus ``"channel_names"`` (tuple, written order).

    Raises
    ------
    ImageIOError
        Missing or unreadable file.
    """
    import OpenImageIO as oiio

    path = Path(path)
    if not path.is_file():
        raise ImageIOError("cannot read image: no such file", path=str(path))
    inp = oiio.ImageInput.open(str(path))
    if inp is None:
        raise ImageIOError(f"cannot read image: {oiio.geterror() or 'unknown format'}",
                           path=str(path))
    channels: dict[str, np.ndarray] = {}
    attributes: dict = {}
    try:
        part = 0
        while inp.seek_subimage(part, 0):
            spec = inp.spec()
            attrs = {p.name: p.value for p in spec.extra_attribs}
            if part == 0:
                attributes = attrs
            names = tuple(spec.channelnames)
            formats = [str(f) for f in spec.channelformats] or [str(spec.format)] * len(names)
            int_names = set(str(attrs.get(_INT_CHANNELS_ATTRIBUTE, "")).split(","))
            order = attrs.get(_CHANNEL_ORDER_ATTRIBUTE)
            wanted = tuple(order.split(",")) if isinstance(order, str) else names
            if sorted(wanted) != sorted(names):
                wanted = names
            for name in wanted:
                c = names.index(name)
                fmt = formats[c]
                # Read one channel in its stored type (a mixed read would go through float).
                plane = inp.read_image(part, 0, c, c + 1, "uint" if fmt == "uint" else "float")
                if plane is None:
                    raise ImageIOError(f"cannot read image: {inp.geterror() or 'read failed'}",
                                       path=str(path))
                plane = np.asarray(plane).reshape(spec.height, spec.width)
                if fmt == "uint" and attrs.get("name") == "ids":
                    wide = plane.astype(np.int64)
                    plane = np.where(wide == _UINT32_NONE, -1, wide)
                elif name in int_names:
                    plane = plane.astype(np.int64)
                channels[name] = plane
            part += 1
    finally:
        inp.close()
    attributes["channel_names"] = tuple(channels)
    return channels, attributes


# --- PNG beauty image and shadow masks -------------------------------------------------------

#: 8-bit shadow-mask values (docs/DESIGN.md §15): nodata is distinct from both lit and shadow.
MASK_LIT, MASK_SHADOW, MASK_NODATA = 255, 0, 128


def write_png_rgb(path: str | os.PathLike, rgb8: np.ndarray,
                  attributes: Mapping[str, str | float | int] | None = None) -> None:
    """Write an 8-bit sRGB picture, shape (H, W, 3) uint8, row 0 at the top, as PNG."""
    path = Path(path)
    rgb8 = np.asarray(rgb8)
    if path.suffix.lower() != ".png":
        raise ImageIOError("write_png_rgb needs a .png path", path=str(path))
    if rgb8.ndim != 3 or rgb8.shape[2] != 3 or rgb8.dtype != np.uint8:
        raise ImageIOError(f"an RGB picture must be (H, W, 3) uint8, not {rgb8.shape} "
                           f"{rgb8.dtype}", path=str(path))
    write_image(path, rgb8, attributes=attributes)


def mask_from_lit(lit_fraction: np.ndarray, valid: np.ndarray | None = None, *,
                  threshold: float = 0.5) -> np.ndarray:
    """8-bit mask of a lit fraction: 255 where lit ≥ ``threshold``, 0 below, 128 no surface.

    NaN lit fractions and pixels where ``valid`` is False are nodata (128).
    """
    lit = np.asarray(lit_fraction)
    if lit.dtype.kind != "f":
        lit = lit.astype(np.float64)
    # Compared in float64 chunk by chunk (a float64 scalar), not through float64 and int64
    # copies of the whole map: 2 bytes per pixel of temporaries instead of 16.
    mask = np.full(lit.shape, MASK_SHADOW, np.uint8)
    mask[np.greater_equal(lit, np.float64(threshold))] = MASK_LIT
    nodata = np.isnan(lit)
    if valid is not None:
        nodata |= ~np.asarray(valid, bool)
    mask[nodata] = MASK_NODATA
    return mask


def grey_mask_from_lit(lit_fraction: np.ndarray, valid: np.ndarray | None = None) -> np.ndarray:
    """8-bit mask of a lit fraction as a grey level: ``v = round(254 × lit)``, plus one from
    128 up, so 0 is shadow, 255 sun, 128 still only no surface (NaN or ``valid`` False), and
    a fraction between (sun through vegetation) is a grey in 1..254 but 128."""
    lit = np.clip(np.nan_to_num(np.asarray(lit_fraction, np.float64), nan=0.0), 0.0, 1.0)
    grey = np.rint(lit * 254.0).astype(np.uint8)
    grey[grey >= MASK_NODATA] += 1
    nodata = np.isnan(np.asarray(lit_fraction, np.float64))
    if valid is not None:
        nodata |= ~np.asarray(valid, bool)
    grey[nodata] = MASK_NODATA
    return grey


def _checked_mask(path: Path, mask: np.ndarray, grey: bool = False) -> np.ndarray:
    mask = np.asarray(mask)
    if mask.dtype == np.bool_:
        mask = np.where(mask, MASK_LIT, MASK_SHADOW).astype(np.uint8)
    if mask.ndim != 2 or mask.dtype != np.uint8:
        raise ImageIOError(f"a shadow mask must be (H, W) uint8 or bool, not {mask.shape} "
                           f"{mask.dtype} (use mask_from_lit for lit fractions)", path=str(path))
    bad = ~np.isin(mask, (MASK_LIT, MASK_SHADOW, MASK_NODATA))
    if not grey and bad.any():
        raise ImageIOError(f"a shadow mask holds only 255 (lit), 0 (shadow) and 128 (nodata); "
                           f"found {int(mask[bad][0])}", path=str(path))
    return mask


def write_mask_png(path: str | os.PathLike, mask: np.ndarray,
                   attributes: Mapping[str, str | float | int] | None = None,
                   grey: bool = False) -> None:
    """Write a shadow mask as an 8-bit grey PNG: 255 sunlit, 0 shadow, 128 no surface/nodata
    (``grey``: any other value too, :func:`grey_mask_from_lit`'s levels).

    Parameters
    ----------
    mask : numpy.ndarray, shape (H, W)
        uint8 with only those three values, or bool (True = sunlit).
    """
    path = Path(path)
    if path.suffix.lower() != ".png":
        raise ImageIOError("write_mask_png needs a .png path", path=str(path))
    write_image(path, _checked_mask(path, mask, grey), attributes=attributes)


# --- georeferenced rasters -------------------------------------------------------------------

def world_file_lines(geotransform: Sequence[float]) -> list[str]:
    """The six lines of an ESRI world file for a GDAL geotransform.

    GDAL's geotransform ``(x0, a, b, y0, d, e)`` maps pixel CORNER coordinates
    ``(col, row)`` to ``x = x0 + a·col + b·row``, ``y = y0 + d·col + e·row``; a world file
    gives ``A, D, B, E`` and the CENTRE ``(C, F)`` of the upper-left pixel, i.e. the map
    position of ``(col, row) = (0.5, 0.5)``.
    """
    x0, a, b, y0, d, e = (float(v) for v in geotransform)
    c = x0 + 0.5 * a + 0.5 * b
    f = y0 + 0.5 * d + 0.5 * e
    # repr is the shortest text that reads back to the same double: no precision lost.
    return [repr(v) for v in (a, d, b, e, c, f)]


def _crs_of(crs_wkt, epsg):
    """A pyproj CRS from a WKT string or an EPSG code; None if neither is given."""
    if crs_wkt is None and epsg is None:
        return None
    from pyproj import CRS
    from pyproj.exceptions import CRSError as ProjCRSError

    from cityshade.errors import CRSError

    try:
        return CRS.from_epsg(int(epsg)) if epsg is not None else CRS.from_user_input(crs_wkt)
    except (ProjCRSError, ValueError, TypeError) as exc:
        raise CRSError(f"cannot georeference with CRS {epsg or crs_wkt!r}: {exc}") from None


def _write_text_atomically(path: Path, text: str) -> None:
    from cityshade.util import atomic_write

    with atomic_write(path, encoding="ascii", newline="\n", error=ImageIOError) as fh:
        fh.write(text)


# TIFF field types and GeoTIFF tags/keys (GeoTIFF 1.1, OGC 19-008r4).
_TIFF_ASCII, _TIFF_SHORT, _TIFF_LONG, _TIFF_DOUBLE = 2, 3, 4, 12
_TIFF_TYPE_SIZE = {1: 1, 2: 1, 3: 2, 4: 4, 5: 8, 6: 1, 7: 1, 8: 2, 9: 4, 10: 8, 11: 4, 12: 8,
                   16: 8, 17: 8, 18: 8}
_TAG_MODEL_PIXEL_SCALE = 33550
_TAG_MODEL_TIEPOINT = 33922
_TAG_MODEL_TRANSFORMATION = 34264
_TAG_GEO_KEY_DIRECTORY = 34735
_TAG_GDAL_NODATA = 42113
_KEY_MODEL_TYPE, _KEY_RASTER_TYPE = 1024, 1025
_KEY_GEOGRAPHIC_TYPE, _KEY_PROJECTED_CS_TYPE, _KEY_VERTICAL_CS_TYPE = 2048, 3072, 4096
_MODEL_PROJECTED, _MODEL_GEOGRAPHIC = 1, 2
_RASTER_PIXEL_IS_AREA = 1


def _geotiff_tags(geotransform, crs, nodata) -> list[tuple[int, int, bytes | tuple]]:
    """GeoTIFF tags (tag, type, values) for a geotransform, an optional CRS and nodata."""
    x0, a, b, y0, d, e = (float(v) for v in geotransform)
    tags: list[tuple[int, int, tuple | bytes]] = []
    if b == 0.0 and d == 0.0:
        # North-up: pixel scale + tie point of the upper-left corner (raster (0,0) ↔ model).
        tags.append((_TAG_MODEL_PIXEL_SCALE, _TIFF_DOUBLE, (a, -e, 0.0)))
        tags.append((_TAG_MODEL_TIEPOINT, _TIFF_DOUBLE, (0.0, 0.0, 0.0, x0, y0, 0.0)))
    else:
        tags.append((_TAG_MODEL_TRANSFORMATION, _TIFF_DOUBLE,
                     (a, b, 0.0, x0, d, e, 0.0, y0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)))
    keys = [(_KEY_RASTER_TYPE, _RASTER_PIXEL_IS_AREA)]
    if crs is not None:
        horizontal = crs.sub_crs_list[0] if crs.is_compound else crs
        code = horizontal.to_epsg()
        if code is not None and horizontal.is_projected:
            keys += [(_KEY_MODEL_TYPE, _MODEL_PROJECTED), (_KEY_PROJECTED_CS_TYPE, code)]
        elif code is not None and horizontal.is_geographic:
            keys += [(_KEY_MODEL_TYPE, _MODEL_GEOGRAPHIC), (_KEY_GEOGRAPHIC_TYPE, code)]
        if crs.is_compound and len(crs.sub_crs_list) > 1:
            vcode = crs.sub_crs_list[1].to_epsg()
            if vcode is not None:
                keys.append((_KEY_VERTICAL_CS_TYPE, vcode))
    keys.sort()
    directory = [1, 1, 0, len(keys)]
    for key, value in keys:
        directory += [key, 0, 1, value]
    tags.append((_TAG_GEO_KEY_DIRECTORY, _TIFF_SHORT, tuple(directory)))
    if nodata is not None:
        tags.append((_TAG_GDAL_NODATA, _TIFF_ASCII, repr(nodata).encode("ascii") + b"\0"))
    return tags


def _add_tiff_tags(tiff_path: str, new_tags) -> None:
    """Add tags to the first IFD of a classic TIFF by writing a new IFD at the end of the file.

    The old IFD stays in place unreferenced; the entries' existing data offsets remain valid
    because nothing before the end of the file moves.
    """
    import struct

    with open(tiff_path, "r+b") as fh:
        data = fh.read()
        order = {b"II": "<", b"MM": ">"}.get(data[:2])
        if order is None or struct.unpack(order + "H", data[2:4])[0] != 42:
            raise ImageIOError("cannot georeference: not a classic TIFF", path=tiff_path)
        ifd = struct.unpack(order + "I", data[4:8])[0]
        count = struct.unpack(order + "H", data[ifd:ifd + 2])[0]
        entries = {}
        for k in range(count):
            raw = data[ifd + 2 + 12 * k: ifd + 14 + 12 * k]
            entries[struct.unpack(order + "H", raw[:2])[0]] = raw
        next_ifd = data[ifd + 2 + 12 * count: ifd + 6 + 12 * count]
        for tag, _, _ in new_tags:
            entries.pop(tag, None)
        # Layout at the end: [new IFD][tag data...], word-aligned.
        end = len(data) + (len(data) % 2)
        n_entries = len(entries) + len(new_tags)
        data_at = end + 2 + 12 * n_entries + 4
        blobs = []
        for tag, ftype, values in new_tags:
            if ftype == _TIFF_ASCII:
                payload, n = values, len(values)
            else:
                fmt = {_TIFF_SHORT: "H", _TIFF_LONG: "I", _TIFF_DOUBLE: "d"}[ftype]
                payload, n = struct.pack(order + fmt * len(values), *values), len(values)
            head = struct.pack(order + "HHI", tag, ftype, n)
            if len(payload) <= 4:
                entries[tag] = head + payload.ljust(4, b"\0")
            else:
                entries[tag] = head + struct.pack(order + "I", data_at)
                blobs.append(payload + (b"\0" if len(payload) % 2 else b""))
                data_at += len(blobs[-1])
        ifd_bytes = struct.pack(order + "H", n_entries)
        ifd_bytes += b"".join(entries[t] for t in sorted(entries)) + next_ifd
        fh.seek(len(data))
        fh.write(b"\0" * (end - len(data)) + ifd_bytes + b"".join(blobs))
        fh.seek(4)
        fh.write(struct.pack(order + "I", end))


def write_georeferenced(path: str | os.PathLike, array: np.ndarray,
                        geotransform: Sequence[float], crs_wkt: str | None = None, *,
                        epsg: int | None = None, nodata: float | int | None = None,
                        attributes: Mapping[str, str | float | int] | None = None) -> list[Path]:
    """Write a raster that GIS software places exactly: GeoTIFF + world file + ``.prj``.

    Writes ``path`` (a TIFF with GeoTIFF tags: pixel scale and tie point, or a transformation
    matrix when rotated; GeoKeys for an EPSG-coded CRS; raster type PixelIsArea; GDAL's nodata
    tag), ``path.with_suffix(".tfw")`` (the world file: pixel-CENTRE convention, converted from
    the corner-based geotransform, see :func:`world_file_lines`) and, with a CRS,
    ``path.with_suffix(".prj")`` (ESRI WKT1, what QGIS and ArcGIS expect next to a world file).
    Each file is written to a temporary name and renamed.

    Parameters
    ----------
    path : str or path-like
        ``.tif`` or ``.tiff``.
    array : numpy.ndarray, shape (H, W) or (H, W, C)
        Row 0 = north edge (top); uint8, uint16 or float32 (NaN as nodata for floats).
    geotransform : sequence of 6 float
        GDAL convention: ``(x_ul, pixel_w, row_rot, y_ul, col_rot, -pixel_h)``, the UPPER-LEFT
        CORNER of pixel (0, 0), in CRS units.
    crs_wkt : str, optional
        The CRS as WKT (or anything pyproj reads); ``epsg`` wins if both are given.
    epsg : int, optional
    nodata : number, optional
        Value meaning "no surface" (e.g. 128 in a shadow mask), written as GDAL_NODATA.
    attributes : mapping, optional
        TIFF header metadata.

    Returns
    -------
    list of pathlib.Path
        The files written.

    Raises
    ------
    ImageIOError
        Bad extension, geotransform, array or a write failure.
    cityshade.errors.CRSError
        A CRS pyproj does not know.
    """
    path = Path(path)
    if path.suffix.lower() not in (".tif", ".tiff"):
        raise ImageIOError("a georeferenced raster must be a .tif/.tiff", path=str(path))
    gt = tuple(float(v) for v in geotransform)
    if len(gt) != 6 or not all(math.isfinite(v) for v in gt):
        raise ImageIOError(f"geotransform must be 6 finite numbers, not {geotransform!r}",
                           path=str(path))
    if gt[1] * gt[5] - gt[2] * gt[4] == 0.0:
        raise ImageIOError(f"geotransform {gt!r} is singular (zero pixel size)", path=str(path))
    if nodata is not None and not isinstance(nodata, (int, float, np.integer, np.floating)):
        raise ImageIOError(f"nodata must be a number, not {nodata!r}", path=str(path))
    crs = _crs_of(crs_wkt, epsg)
    ext = _extension(path)
    pixels = _checked_pixels(path, ext, array)
    spec = _make_spec(path, ext, pixels, attributes, None)
    nodata_value = None if nodata is None else (float(nodata) if isinstance(
        nodata, (float, np.floating)) else int(nodata))
    tags = _geotiff_tags(gt, crs, nodata_value)
    _write_atomically(path, [(spec, pixels)], finish=lambda tmp: _add_tiff_tags(tmp, tags))
    written = [path]
    world = path.with_suffix(".tfw")
    _write_text_atomically(world, "\n".join(world_file_lines(gt)) + "\n")
    written.append(world)
    if crs is not None:
        prj = path.with_suffix(".prj")
        _write_text_atomically(prj, crs.to_wkt("WKT1_ESRI") + "\n")
        written.append(prj)
    return written


def write_cog(path: str | os.PathLike, array: np.ndarray, geotransform: Sequence[float],
              crs_wkt: str | None = None, *, epsg: int | None = None,
              nodata: float | int | None = None,
              attributes: Mapping[str, str | float | int] | None = None,
              block_px: int = 512) -> list[Path]:
    """Write a Cloud-Optimized GeoTIFF with GDAL (rasterio, the ``[cog]`` extra): internal
    ``block_px`` tiles, overviews, DEFLATE with the floating-point predictor, GeoKeys of the
    CRS (the same geotransform and CRS handling as :func:`write_georeferenced`) and the
    attributes as GDAL metadata. Written to a temporary name and renamed.

    Returns
    -------
    list of pathlib.Path
        ``[path]``.

    Raises
    ------
    ImageIOError
        No rasterio, a bad array, geotransform or extension, or a write failure.
    cityshade.errors.CRSError
        A CRS pyproj does not know.
    """
    path = Path(path)
    if path.suffix.lower() not in (".tif", ".tiff"):
        raise ImageIOError("a Cloud-Optimized GeoTIFF must be a .tif/.tiff", path=str(path))
    try:
        import rasterio
        from rasterio.transform import Affine
    except ImportError:
        raise ImageIOError("writing a Cloud-Optimized GeoTIFF needs rasterio: pip install "
                           "'cityshade[cog]'", path=str(path)) from None
    gt = tuple(float(v) for v in geotransform)
    if len(gt) != 6 or not all(math.isfinite(v) for v in gt) or \
            gt[1] * gt[5] - gt[2] * gt[4] == 0.0:
        raise ImageIOError(f"geotransform must be 6 finite numbers, not singular: {gt!r}",
                           path=str(path))
    pixels = np.asarray(array)
    if pixels.ndim != 2 or pixels.dtype not in (np.float32, np.uint8, np.uint16):
        raise ImageIOError(f"a COG band must be (H, W) float32, uint8 or uint16, not "
                           f"{pixels.shape} {pixels.dtype}", path=str(path))
    crs = _crs_of(crs_wkt, epsg)
    from cityshade.util import atomic_path

    profile = {"driver": "COG", "width": pixels.shape[1], "height": pixels.shape[0],
               "count": 1, "dtype": pixels.dtype.name, "transform": Affine.from_gdal(*gt),
               "crs": None if crs is None else crs.to_wkt(), "nodata": nodata,
               "blocksize": int(block_px), "compress": "DEFLATE",
               "predictor": 3 if pixels.dtype == np.float32 else 2, "overviews": "AUTO",
               "BIGTIFF": "IF_SAFER"}
    with atomic_path(path, keep_suffix=True, error=ImageIOError, what="image") as tmp:
        try:
            with rasterio.Env(GDAL_NUM_THREADS="1"):
                with rasterio.open(tmp, "w", **profile) as dst:
                    dst.write(pixels, 1)
                    if attributes:
                        # GDAL reads "a:b=c" as key "a"; keys keep their text with ":" as "_".
                        dst.update_tags(**{str(k).replace(":", "_"): str(v)
                                           for k, v in attributes.items()})
        except rasterio.errors.RasterioError as exc:
            raise ImageIOError(f"cannot write the GeoTIFF: {exc}", path=str(path)) from None
    return [path]
