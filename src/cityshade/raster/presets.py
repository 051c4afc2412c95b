"""Named camera presets (``configs/cameras.toml`` and the user's ``--cameras`` file).

Free of numpy, so that ``cityshade --help`` can list the preset names without loading it.
"""
from __future__ import annotations

from pathlib import Path

from cityshade.errors import ConfigError

#: The camera presets shipped in the package (``cityshade/configs/cameras.toml``), read
#: through :mod:`importlib.resources`: an installed package has no repository around it.
PRESETS_RESOURCE = ("configs", "cameras.toml")

PRESET_KEYS = {"azimuth_deg": float, "elevation_deg": float, "vfov_deg": float, "zoom": float}


def load_presets(path: str | Path | None = None) -> dict[str, dict[str, float]]:
    """Named perspective presets from a TOML file (default: the package's
    ``configs/cameras.toml``, :data:`PRESETS_RESOURCE`).

    Each table is a preset with ``azimuth_deg``, ``elevation_deg`` (required), ``vfov_deg``
    (default 40) and ``zoom`` (default 1); see :func:`fitted`. Unknown keys are errors.
    """
    from importlib import resources

    from cityshade.util import read_toml

    if path is None:
        with resources.as_file(resources.files("cityshade").joinpath(*PRESETS_RESOURCE)) as p:
            return load_presets(p)
    path = Path(path)
    data = read_toml(path, "camera presets")
    presets = {}
    for name, table in data.items():
        if not isinstance(table, dict):
            raise ConfigError(f"camera preset {name!r} must be a table", path=str(path))
        unknown = sorted(set(table) - set(PRESET_KEYS))
        if unknown:
            raise ConfigError(f"unknown key(s) in camera preset {name!r}: {', '.join(unknown)} "
                              f"(valid: {', '.join(PRESET_KEYS)})", path=str(path))
        for key in ("azimuth_deg", "elevation_deg"):
            if key not in table:
                raise ConfigError(f"camera preset {name!r} lacks {key}", path=str(path))
        values = {"vfov_deg": 40.0, "zoom": 1.0}
        for key, value in table.items():
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise ConfigError(f"{name}.{key} must be a number", path=str(path))
            values[key] = float(value)
        presets[name] = values
    return presets
