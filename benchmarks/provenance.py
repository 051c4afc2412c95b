"""The commit a benchmark figure belongs to: one definition for every script here.

Imported by every in-process benchmark before numpy: it also gives the benchmark's process the
command's one BLAS thread (:func:`cityshade.runtime.startup.one_blas_thread`) and sleeping OpenMP
workers (:func:`~cityshade.runtime.startup.sleeping_omp_workers`), so that figures measure what
``cityshade`` does (idle OpenBLAS threads and OpenMP workers spin on the core Numba's second
thread needs; a LocalCluster's workers inherit the settings, as the command's do).
"""
from __future__ import annotations

import subprocess
from pathlib import Path

from cityshade.runtime.startup import one_blas_thread, sleeping_omp_workers

one_blas_thread()
sleeping_omp_workers()


def commit(where: str | Path | None = None, full: bool = False) -> str:
    """Commit of the checkout ``where`` (default: the one whose ``cityshade`` is imported, which
    is what the figures measure, not necessarily the script's own), with " (with uncommitted
    changes under src/)" when its sources differ from that commit; "unknown" outside git."""
    if where is None:
        import cityshade

        where = Path(cityshade.__file__).resolve().parent
    args = ["git", "rev-parse", "HEAD"] if full else ["git", "rev-parse", "--short", "HEAD"]
    try:
        out = subprocess.run(args, cwd=where, capture_output=True, text=True,
                             check=True).stdout.strip()
        top = subprocess.run(["git", "rev-parse", "--show-toplevel"], cwd=where,
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "src"], cwd=top,
                               capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return out + (" (with uncommitted changes under src/)" if dirty else "")
