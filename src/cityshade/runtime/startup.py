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


#: ``prctl`` option (Linux 3.15 and later): no transparent huge pages for the calling process and
#: the processes it starts.
PR_SET_THP_DISABLE = 41
#: Set to 1 to keep transparent huge pages where :func:`no_transparent_huge_pages` would turn
#: them off.
HUGE_PAGES_VAR = "CITYSHADE_HUGE_PAGES"


def no_transparent_huge_pages() -> None:
    """No transparent huge pages from here on for this process and the processes it starts,
    unless ``CITYSHADE_HUGE_PAGES=1``; nothing where ``prctl`` is missing. ``cityshade render``
    calls it first thing: one frame's cost is mostly fresh memory, where a run of many steps
    (``batch``, ``sky``) reuses its arrays and gains from the huge pages' reach.

    With the kernel's THP setting ``always``, the first touch of fresh memory takes a whole
    2 MB page and zeroes it. On a virtual machine whose host takes back free memory in blocks
    of that size (virtio's free page reporting), the host must back each such page again on
    first touch: on the project's 2-core machine, 86 % of izb's first call in a process
    (1.1-1.8 s against 0.11 s warm on the 1M city's map) was that zeroing. Measured there,
    alternated, whole processes with huge pages against without: ``render`` of the 1M city's
    1 m map 2.1-3.7 s against 1.5-1.8 s, a day's ``batch`` at 30-minute steps 10.1-15.5 against
    7.7-13.6 s (every pair faster); its 1080p overview (less fresh memory) 1.21-1.30 against
    1.29-1.45 s and the ``build`` of the 1M GML 5.1-7.5 against 5.7-7.7 s, no gain. Warm
    kernels over large arrays ran 2-15 % slower without them (``benchmarks/batch.py`` 2 %, the
    izb and Mitsuba rays of ``benchmarks/raytrace.py``'s map 10-15 %: more TLB misses). Must
    run before the large allocations; the answers do not depend on it.
    """
    if os.environ.get(HUGE_PAGES_VAR) == "1" or not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0)
    except (OSError, AttributeError):  # no libc prctl: the kernel's setting stays
        pass


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
