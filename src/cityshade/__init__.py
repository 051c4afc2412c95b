"""cityshade: exact, fast shadow pictures and shadow data from CityGML 3D city models.

Importing the package is cheap: heavy modules (numba, lxml, pyproj, OpenImageIO) are imported
only by the stages that use them, so ``cityshade --help`` stays instant.
"""
from __future__ import annotations

from cityshade.runtime.startup import (command_is_starting, hold_ctrl_c_while_starting,
                                       one_blas_thread, sleeping_omp_workers)

hold_ctrl_c_while_starting()  # first: a Ctrl-C from here on is one line and status 130
if command_is_starting():
    one_blas_thread()  # before numpy is imported
    sleeping_omp_workers()  # before Numba's first parallel kernel

import os as _os  # noqa: E402

__version__ = "0.1.0"


def _sources_key(root: str | None = None) -> str:
    """Short hash of the package's source files (relative path and content).

    Numba's cache checks only the file that defines a kernel, not the files whose functions it
    inlines: a changed helper in another module would leave stale machine code in use. Keying
    the cache folder by all sources makes any change start afresh, and keying it by their
    content (not their modification times) lets a reinstall of the same code reuse it. Reading
    the sources costs about 10 ms per process.
    """
    import hashlib

    root = root or _os.path.dirname(_os.path.abspath(__file__))
    digest = hashlib.sha1(__version__.encode())
    for folder, dirs, files in _os.walk(root):     # top-down: the sorted dirs set the order
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for name in sorted(files):
            if name.endswith(".py"):
                digest.update(f"{folder[len(root):]}/{name};".encode())
                with open(_os.path.join(folder, name), "rb") as f:
                    digest.update(f.read())
    return digest.hexdigest()[:16]


#: Cache folders of other source versions are removed once unused for this many days, and at
#: most this many are kept beside the current one (each holds ~50-100 MB of machine code).
NUMBA_CACHE_KEEP_DAYS = 14
NUMBA_CACHE_KEEP_OTHERS = 3
#: A folder whose mark is younger than this is in use (its mark is refreshed once a day) and
#: never removed: several checkouts of different sources side by side (worktrees, a clone
#: beside an install) each keep their compiled kernels.
NUMBA_CACHE_IN_USE_S = 2 * 86400
_USED_MARK = ".last-used"


def _default_numba_cache_dir() -> str:
    # Numba's default cache sits next to the source files, which fails on a read-only install
    # (site-packages owned by root, a container image); a per-user cache folder always works.
    base = _os.environ.get("XDG_CACHE_HOME") or _os.path.join(_os.path.expanduser("~"), ".cache")
    return _os.path.join(base, "cityshade", "numba", _sources_key())


def _mark_used_and_prune(folder: str, now: float | None = None) -> None:
    """Mark ``folder`` used (at most once a day: one ``stat`` otherwise) and, when it is new,
    remove the folders of other source versions unused for ``NUMBA_CACHE_KEEP_DAYS`` or beyond
    the ``NUMBA_CACHE_KEEP_OTHERS`` most recently used, but none used within
    ``NUMBA_CACHE_IN_USE_S``. Never fails the import."""
    import shutil
    import time

    mark = _os.path.join(folder, _USED_MARK)
    now = time.time() if now is None else now
    try:
        fresh = not _os.path.exists(mark)
        if fresh or now - _os.stat(mark).st_mtime > 86400:
            _os.makedirs(folder, exist_ok=True)
            with open(mark, "a"):
                pass
            _os.utime(mark)
        if not fresh:
            return
        parent = _os.path.dirname(folder)
        others = []
        for name in _os.listdir(parent):
            path = _os.path.join(parent, name)
            if path != folder and _os.path.isdir(path):
                used = _os.path.join(path, _USED_MARK)
                others.append((_os.stat(used if _os.path.exists(used) else path).st_mtime, path))
        others.sort(reverse=True)
        for i, (used_s, path) in enumerate(others):
            if now - used_s < NUMBA_CACHE_IN_USE_S:
                continue
            if i >= NUMBA_CACHE_KEEP_OTHERS or now - used_s > NUMBA_CACHE_KEEP_DAYS * 86400:
                shutil.rmtree(path, ignore_errors=True)
    except OSError:
        pass


if "NUMBA_CACHE_DIR" not in _os.environ:
    _os.environ["NUMBA_CACHE_DIR"] = _default_numba_cache_dir()
    _mark_used_and_prune(_os.environ["NUMBA_CACHE_DIR"])
