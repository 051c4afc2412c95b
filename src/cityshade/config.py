"""All tunables and tolerances in one place, loadable from TOML.

Each stage has a frozen dataclass of settings with documented defaults. A TOML file holds one
table per stage (``[build]``, ``[kdtree]``, ...); unknown tables or keys and values of the wrong
type are errors (:class:`~cityshade.errors.ConfigError`), never silently ignored.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from cityshade.errors import ConfigError

TIME_SOURCES = ("auto", "valid", "construction", "creation")


@dataclass(frozen=True)
class BuildSettings:
    """Reading and triangulating a CityGML file."""

    #: LoD to take from every object; None takes the highest LoD each object has.
    lod: int | None = None
    #: Appearance theme; None takes the theme with the most targeted surfaces.
    theme: str | None = None
    #: Override of the file's CRS, e.g. "EPSG:25832" (needed for files without srsName).
    crs: str | None = None
    #: Where validity intervals come from (DESIGN §3); "auto" takes the first available of
    #: valid → construction → creation per object.
    time_source: str = "auto"
    #: Points closer than this (metres) are one point; below GML files' usual mm precision.
    merge_distance_m: float = 1e-6
    #: A point farther than this from the line of its neighbours, relative to the polygon size,
    #: is not collinear (relative so 10^7 m offsets behave the same as local coordinates).
    collinear_rel_tol: float = 1e-9
    #: Triangulated area must match the polygon's (with holes) to this relative tolerance,
    #: otherwise the polygon is self-intersecting or its holes are invalid and it is skipped.
    area_rel_tol: float = 1e-6
    #: Polygons whose area relative to its bounding square is below this are zero-area slivers.
    min_rel_area: float = 1e-12
    #: Distance (relative to polygon size) beyond which a polygon counts as non-planar in the
    #: report; it is still triangulated (the triangles keep the true 3-D vertices).
    nonplanar_rel_tol: float = 1e-3

    def __post_init__(self) -> None:
        if self.time_source not in TIME_SOURCES:
            raise ConfigError(f"time_source must be one of {', '.join(TIME_SOURCES)}, "
                              f"not {self.time_source!r}")
        if self.lod is not None and not 0 <= self.lod <= 4:
            raise ConfigError(f"lod must be between 0 and 4, not {self.lod}")
        for name in ("merge_distance_m", "collinear_rel_tol", "area_rel_tol", "min_rel_area",
                     "nonplanar_rel_tol"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0):
                raise ConfigError(f"{name} must be a finite number >= 0, not {value}")


def _kdtree_settings():
    # The kd-tree's tunables live next to its build kernel; importing them here lazily keeps
    # `import cityshade.config` (and so `cityshade --help`) free of numba.
    from cityshade.accel.kdtree_build import KdTreeSettings

    return KdTreeSettings()


@dataclass(frozen=True)
class Settings:
    """All settings, one field per TOML table."""

    build: BuildSettings = field(default_factory=BuildSettings)
    kdtree: Any = field(default_factory=_kdtree_settings)


_TOML_TYPES = {"int": int, "float": float, "str": str, "bool": bool}


def _coerce(cls: type, table: Mapping[str, Any], where: str) -> Any:
    """Build dataclass ``cls`` from a TOML table, rejecting unknown keys and wrong types."""
    if not isinstance(table, Mapping):
        raise ConfigError(f"{where} must be a table")
    fields = {f.name: f for f in dataclasses.fields(cls)}
    unknown = sorted(set(table) - set(fields))
    if unknown:
        raise ConfigError(f"unknown key(s) in {where}: {', '.join(unknown)} "
                          f"(valid: {', '.join(sorted(fields))})")
    kwargs = {}
    for key, value in table.items():
        default = getattr(cls(), key)
        if dataclasses.is_dataclass(default):
            kwargs[key] = _coerce(type(default), value, f"{where}.{key}")
            continue
        if isinstance(default, bool) and not isinstance(value, bool):
            raise ConfigError(f"{where}.{key} must be true or false")
        if isinstance(default, float) and isinstance(value, int) and not isinstance(value, bool):
            value = float(value)
        if default is not None:
            allowed: tuple[type, ...] = (type(default),)
        else:  # an optional setting: its annotation names the type, e.g. "int | None"
            names = str(fields[key].type).replace(" ", "").split("|")
            allowed = tuple(_TOML_TYPES[n] for n in names if n in _TOML_TYPES)
        if allowed and not isinstance(value, allowed):
            raise ConfigError(f"{where}.{key} must be of type "
                              f"{' or '.join(t.__name__ for t in allowed)}")
        kwargs[key] = value
    return cls(**kwargs)


def settings_from_mapping(data: Mapping[str, Any], where: str = "config") -> Settings:
    """Validate a parsed TOML document into :class:`Settings`."""
    return _coerce(Settings, data, where)


def load_settings(path: str | Path) -> Settings:
    """Read a TOML configuration file; unknown keys are a :class:`ConfigError`."""
    from cityshade.util import read_toml

    return settings_from_mapping(read_toml(path, "config"), where=str(path))
