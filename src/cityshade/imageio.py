"""Reading and writing images: the only module of cityshade that touches OpenImageIO.

Every image the package writes goes through :func:`write_image`, which guards against the two
ways OpenImageIO loses data without an error:

* a 2-D ``(H, W)`` array handed to OpenImageIO's Python ``write_image`` writes wrong pixels
  (DESIGN §14), so 2-D input is reshaped to ``(H, W, 1)`` here;
* a pixel type the format cannot store is converted silently (float → 8 bit in PNG, uint32 →
  half in EXR, uint32 → uint8 in TIFF), so each format accepts only the types it stores exactly
  and anything else is an :class:`ImageIOError`.

Files are written to a temporary name in the destination folder and renamed into place, so an
error never leaves a half-written image behind.

Conventions: arrays are ``(H, W, C)``, row 0 is the TOP row of the picture (image order, not map
order), channels last.
"""
from __future__ import annotations

import os
import uuid
from pathlib import Path
from typing import Mapping, Sequence

import numpy as np

from cityshade.errors import CityshadeError

__all__ = ["ImageIOError", "write_image", "read_image", "FORMAT_DTYPES"]


class ImageIOError(CityshadeError):
    """An image that cannot be written or read (carries the path)."""


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
        # OpenImageIO writes wrong pixels from a 2-D array (DESIGN §14): always hand it 3-D.
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
    import OpenImageIO as oiio  # heavy import only when an image is written (DESIGN §2)

    path = Path(path)
    ext = _extension(path)
    pixels = _checked_pixels(path, ext, pixels)
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

    # Write next to the destination (same file system, so the rename is atomic); the temporary
    # name keeps the extension because OpenImageIO picks the format from it. The name is made
    # unique rather than created with mkstemp so the file gets the usual (umask) permissions.
    folder = path.parent
    if not folder.is_dir():
        raise ImageIOError(f"cannot write image: folder {folder} does not exist",
                           path=str(path))
    tmp_name = str(folder / f".{path.name}.{os.getpid()}.{uuid.uuid4().hex}.tmp{ext}")
    try:
        out = oiio.ImageOutput.create(tmp_name)
        if out is None:
            raise ImageIOError(f"OpenImageIO has no writer for {ext}: {oiio.geterror()}",
                               path=str(path))
        if not out.open(tmp_name, spec):
            raise ImageIOError(f"cannot write image: {out.geterror() or oiio.geterror()}",
                               path=str(path))
        ok = out.write_image(pixels)
        error = out.geterror() if not ok else ""
        if not out.close() and ok:
            ok, error = False, out.geterror()
        if not ok:
            raise ImageIOError(f"cannot write image: {error or 'OpenImageIO failed'}",
                               path=str(path))
        try:
            os.replace(tmp_name, path)
        except OSError as exc:
            raise ImageIOError(f"cannot write image: {exc.strerror}", path=str(path)) from None
    except BaseException:
        try:
            os.unlink(tmp_name)
        except FileNotFoundError:
            pass
        raise


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
    import OpenImageIO as oiio  # heavy import only when an image is read (DESIGN §2)

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
