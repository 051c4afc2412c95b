"""cityshade: exact, fast shadow pictures and shadow data from CityGML 3D city models.

Importing the package is cheap: heavy modules (numba, lxml, pyproj, OpenImageIO) are imported
only by the stages that use them, so ``cityshade --help`` stays instant.
"""
from __future__ import annotations

from cityshade.runtime.startup import command_is_starting, hold_ctrl_c_while_starting, one_blas_thread

hold_ctrl_c_while_starting()  # first: a Ctrl-C from here on is one line and status 130
if command_is_starting():
    one_blas_thread()  # before numpy is imported

import os as _os  # noqa: E402

__version__ = "0.1.0"


def _sources_key() -> str:
    """Short hash of the package's source files (path, size, modification time).

    Numba's cache checks only the modification time of the file that defines a kernel, not of
    the files whose functions it inlines: a changed helper in another module would leave stale
    machine code in use. Keying the cache folder by all sources makes any change start afresh.
    Only ``stat`` calls: cheap enough for every import.
    """
    import hashlib

    root = _os.path.dirname(_os.path.abspath(__file__))
    digest = hashlib.sha1(__version__.encode())
    for folder, dirs, files in sorted(_os.walk(root)):
        dirs.sort()
        for name in sorted(files):
            if name.endswith(".py"):
                st = _os.stat(_os.path.join(folder, name))
                digest.update(f"{folder[len(root):]}/{name}:{st.st_size}:{st.st_mtime_ns};".encode())
    return digest.hexdigest()[:16]


def _default_numba_cache_dir() -> str:
    # Numba's default cache sits next to the source files, which fails on a read-only install
    # (site-packages owned by root, a container image); a per-user cache folder always works.
    base = _os.environ.get("XDG_CACHE_HOME") or _os.path.join(_os.path.expanduser("~"), ".cache")
    return _os.path.join(base, "cityshade", "numba", _sources_key())


_os.environ.setdefault("NUMBA_CACHE_DIR", _default_numba_cache_dir())
