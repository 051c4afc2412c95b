"""cityshade: exact, fast shadow pictures and shadow data from CityGML 3D city models.

Importing the package is cheap: heavy modules (numba, lxml, pyproj, OpenImageIO) are imported
only by the stages that use them, so ``cityshade --help`` stays instant.
"""
from __future__ import annotations

import os as _os

__version__ = "0.1.0"


def _default_numba_cache_dir() -> str:
    # Numba's default cache sits next to the source files, which fails on a read-only install
    # (site-packages owned by root, a container image); a per-user cache folder always works.
    base = _os.environ.get("XDG_CACHE_HOME") or _os.path.join(_os.path.expanduser("~"), ".cache")
    return _os.path.join(base, "cityshade", "numba")


_os.environ.setdefault("NUMBA_CACHE_DIR", _default_numba_cache_dir())
