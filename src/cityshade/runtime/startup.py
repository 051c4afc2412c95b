"""Ctrl-C while the ``cityshade`` command starts, before it has installed its own handler.

The package's ``__init__`` is the first cityshade code that runs, in ``python -m cityshade``
(runpy imports the package before its ``__main__``) and in the console script (which imports
``cityshade.__main__``); it calls :func:`hold_ctrl_c_while_starting` first thing, and the
imports that follow (hashing the sources for the Numba cache folder, numba, lxml, pyproj)
leave with one line and status 130 on a Ctrl-C. Nothing is written before the command's own
handler (``cityshade.cli.options.on_sigint``) takes over. A program that imports the library
keeps its handler: only the command's process is touched.
"""
from __future__ import annotations

import os
import sys

import _signal  # the C module: ``signal`` builds its enums first, 25 ms of start-up


def interrupted_while_starting(signum, frame) -> None:
    """Leave at once: the imports are still running and nothing is written yet."""
    sys.stderr.write("cityshade: interrupted\n")
    sys.stderr.flush()
    os._exit(130)


def terminated_while_starting(signum, frame) -> None:
    """A SIGTERM (a job scheduler's, ``kill``'s) during the imports: as a Ctrl-C, status 143
    (the default action would end the process by the signal, status -15)."""
    sys.stderr.write("cityshade: terminated\n")
    sys.stderr.flush()
    os._exit(143)


def command_is_starting() -> bool:
    """Whether this process is the ``cityshade`` command on its way to ``main()``."""
    argv0 = sys.argv[0] if sys.argv else ""
    if argv0 == "-m":
        # ``python -m NAME``: runpy imports NAME's package with argv[0] = "-m" until it has
        # found the module; the module's name is in the original command line.
        args = getattr(sys, "orig_argv", [])
        for k, arg in enumerate(args[1:], 1):
            if arg == "-m":
                return args[k + 1:k + 2] == ["cityshade"]
            if arg.startswith("-m"):
                return arg == "-mcityshade"
        return False
    return os.path.basename(argv0).lower() in ("cityshade", "cityshade.exe",
                                               "cityshade-script.py")


#: Environment variables of numpy's BLAS thread count that the command sets to 1 when unset
#: (:func:`one_blas_thread`).
BLAS_THREAD_VARS = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def one_blas_thread() -> None:
    """One BLAS thread for the command's process, unless the caller's environment says.

    The command's BLAS products are small ((N, 3) by (3,) for the facing test, 4 × 4 transforms)
    and OpenBLAS's idle threads spin after each one on the core Numba's second thread needs:
    a tiled batch of the 10^7-triangle city (4 sun steps, 2 Numba threads) took 18.8 s with
    OpenBLAS's default 2 threads and 14.5 s with 1. Must run before numpy is imported; the
    answers do not depend on it (each product's element is one thread's sum either way).
    """
    for name in BLAS_THREAD_VARS:
        os.environ.setdefault(name, "1")


def sleeping_omp_workers() -> None:
    """Numba's OpenMP workers sleep once a parallel kernel ends, unless the caller's
    environment says (``OMP_WAIT_POLICY``).

    GNU OpenMP's default lets each worker spin for some 300,000 rounds after every parallel
    kernel, on the core the next step needs: the light-space engine's query, the sky's bits and
    the kd-tree's rays run on Python threads (:mod:`cityshade.runtime.threadpool`) right after
    such kernels, beside a worker still spinning. The sky view factor of the 1M-triangle
    city's map (145 directions, two threads) took 21.1 and 22.2 s with the spin against 20.2
    and 21.1 s without, in alternated runs, and 38.7 and 40.9 CPU seconds against 34.9 and
    36.8. Must run before Numba starts its threading layer (its first parallel kernel); the
    answers do not depend on it.
    """
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")


def hold_ctrl_c_while_starting() -> None:
    """In the command's process (:func:`command_is_starting`), :func:`install_start_handler`."""
    if command_is_starting():
        install_start_handler()


def install_start_handler() -> None:
    """With Python's own Ctrl-C handler still in place (not an ignored SIGINT, not a handler
    of the caller), install :func:`interrupted_while_starting`; with SIGTERM's default action,
    :func:`terminated_while_starting`."""
    try:
        if _signal.getsignal(_signal.SIGINT) is _signal.default_int_handler:
            _signal.signal(_signal.SIGINT, interrupted_while_starting)
        if _signal.getsignal(_signal.SIGTERM) == _signal.SIG_DFL:
            _signal.signal(_signal.SIGTERM, terminated_while_starting)
    except ValueError:  # not the main thread: not the command's start
        pass
