"""Typed errors of the cityshade library.

The library raises these and never prints or exits; the CLI turns each into one line on stderr
and a non-zero exit status. Every error can carry the file, line and ``gml:id`` where it is known.
"""
from __future__ import annotations


class CityshadeError(Exception):
    """Base class: a failure with a one-line, user-facing message.

    Parameters
    ----------
    message : str
        What went wrong, in one line, phrased for the user.
    path : str, optional
        File the error concerns.
    line : int, optional
        1-based line number in ``path``.
    gml_id : str, optional
        ``gml:id`` of the object concerned.
    """

    exit_code = 1

    def __init__(self, message: str, *, path: str | None = None, line: int | None = None,
                 gml_id: str | None = None):
        super().__init__(message)
        self.message = message
        self.path = path
        self.line = line
        self.gml_id = gml_id

    def __str__(self) -> str:
        where = ""
        if self.path:
            where = str(self.path)
            if self.line:
                where += f":{self.line}"
            where += ": "
        what = f" (gml:id {self.gml_id})" if self.gml_id else ""
        return f"{where}{self.message}{what}"


class UsageError(CityshadeError):
    """An option or argument that makes no sense (exit status 2, like click's usage errors)."""

    exit_code = 2


class InputError(CityshadeError):
    """The input file cannot be used: missing, unreadable, malformed, not CityGML, empty."""


class XMLSyntaxError(InputError):
    """Malformed or truncated XML, or an XML construct refused for safety (entities, DTDs)."""


class NotCityGMLError(InputError):
    """Well-formed XML that is not a CityGML model."""


class EmptyModelError(InputError):
    """A CityGML model with no usable geometry."""


class CRSError(CityshadeError):
    """An unknown or unusable coordinate reference system."""


class CacheError(CityshadeError):
    """A cache file that cannot be used; the message always says to rebuild."""


class CacheVersionError(CacheError):
    """A cache written by another format version."""


class CacheCorruptError(CacheError):
    """A truncated or tampered cache (size or checksum mismatch)."""


class ConfigError(UsageError):
    """A TOML configuration with unknown keys or values of the wrong type."""


class OutputError(CityshadeError):
    """An output file that cannot be written (folder missing or not writable, disk full)."""


class ContractError(Exception):
    """Internal misuse of a library function: a bug in the caller, not the user's fault.

    Deliberately not a :class:`CityshadeError` (those are the user's input and options): the
    CLI reports it as one line "internal error: ..." with exit status 70 (EX_SOFTWARE) and
    shows the traceback only with ``-v``/``--verbose``.
    """

    exit_code = 70


class TraceInputError(ContractError):
    """Rays handed to the tracing API of the wrong shape or with non-finite values."""


class KdTreeLayoutError(CityshadeError):
    """Arrays that do not make a flat kd-tree (wrong shape or type, missing, too large)."""


class SampleGenError(CityshadeError):
    """The sample city cannot be written (folder missing, disk full, ...)."""


class TriangulationInputError(InputError, ValueError):
    """Arrays handed to :func:`triangulate_polygons` that do not describe polygons.

    This is a programming error of the caller (wrong shape, dtype or offsets), not bad geometry:
    bad geometry is never an error, it is skipped and counted.
    """


class UnknownPresetError(ConfigError):
    """A camera preset name that the shipped presets (and ``--cameras``) do not define."""


class ImageIOError(CityshadeError):
    """An image that cannot be written or read (carries the path)."""


class KdTreeInputError(UsageError):
    """Arrays handed to :func:`build_kdtree` of the wrong shape, type or content."""


class ShadingError(CityshadeError):
    """Inputs to :func:`shade` that do not fit together (shapes, NaN lit fractions, sun)."""


class DistributedError(CityshadeError):
    """The Dask cluster cannot be reached or lost the work (workers died repeatedly)."""


class WeatherFileError(InputError):
    """A weather file (EPW, TMY2, TMY3) that cannot be used: missing, of an unknown kind, or
    with garbled or missing columns (carries the path, and the line where it is known)."""


class TreeRegisterError(InputError):
    """A tree register (``build --trees``) that cannot be read: format, columns, values, CRS."""


class MeshFileError(InputError):
    """A mesh file (a proposal's OBJ, glTF, PLY or STL) that cannot be read or placed."""
