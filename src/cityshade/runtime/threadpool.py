"""Serial ``nogil`` Numba kernels run over chunks of work on a small pool of Python threads.

Numba's ``prange`` compiles the loop body into a separate function, and a kernel loaded from
Numba's cache runs the copy compiled inside the caller's linked module, which LLVM may lay out
differently from the first, in-process compile. For the kd-tree's shadow rays that copy was
1.7x slower (the same kernel: 8.0 Mrays/s freshly compiled, 4.6 from the cache, one thread,
1M city), while a plain ``@njit(nogil=True)`` kernel runs the same from the cache as compiled.
So the hot traversal kernels are serial kernels over a range ``[i0, i1)`` of work items, and
:func:`run_chunks` hands chunks of the range to ``numba.get_num_threads()`` threads (the
calling thread included), a chunk at a time to whichever thread is free: dynamic scheduling,
so a core slowed by other load on a shared machine does not hold back the end of the call.
Each item's result depends only on the item, so it is the same for any thread count.
"""
from __future__ import annotations

import itertools
import threading
from concurrent.futures import ThreadPoolExecutor

import numba

#: Image rows a thread takes at a time from the row kernels (G-buffer resolve, shading,
#: encoding): 16 rows of a 1080p frame are some 0.1-0.3 ms of work, so the call per chunk
#: (tens of µs) is lost in it, and a frame still makes some 70 chunks to share unevenly
#: busy rows. Serial kernels over rows, not ``prange`` ones: Numba's parallel passes made
#: each such kernel's first compile 2-3x longer (``_shade_kernel`` 1.06 CPU s against 0.41).
ROW_CHUNK = 16

_POOL: ThreadPoolExecutor | None = None
_POOL_LOCK = threading.Lock()


def _pool() -> ThreadPoolExecutor:
    """The process's worker threads (one fewer than Numba's thread count: the caller works
    too), made on first use."""
    global _POOL
    with _POOL_LOCK:
        if _POOL is None:
            _POOL = ThreadPoolExecutor(max(1, numba.config.NUMBA_NUM_THREADS - 1),
                                       thread_name_prefix="cityshade-kernel")
        return _POOL


def shutdown() -> None:
    """Stop the pool's threads (idle between calls: this only joins them); the next
    :func:`run_chunks` makes a new pool."""
    global _POOL
    with _POOL_LOCK:
        pool, _POOL = _POOL, None
    if pool is not None:
        pool.shutdown(wait=True)


def run_chunks(kernel, n_items: int, chunk_items: int, *args) -> None:
    """Call ``kernel(*args, i0, i1)`` over ``[0, n_items)`` in chunks of ``chunk_items``.

    ``kernel`` must release the GIL while it works (a ``nogil`` Numba function, or a Python
    function whose time is spent in such calls, e.g. numpy's sort:
    :func:`cityshade.lightspace.stable_argsort`) and its result for an item must not depend on
    which call handled it. The chunks go to ``numba.get_num_threads()`` threads (at most one
    per chunk; one thread runs them in the calling thread, in order). An exception in any
    thread (Ctrl-C in the calling one) stops the others after their current chunk, and the
    first is raised once every thread has stopped.
    """
    n_chunks = -(-n_items // chunk_items) if n_items > 0 else 0
    threads = min(numba.get_num_threads(), n_chunks)
    if threads <= 1:
        if n_items > 0:
            kernel(*args, 0, n_items)
        return
    counter = itertools.count()
    stop = threading.Event()

    def work():
        done = False
        try:
            while not stop.is_set():
                c = next(counter)
                if c >= n_chunks:
                    break
                kernel(*args, c * chunk_items, min(n_items, (c + 1) * chunk_items))
            done = True
        finally:
            if not done:
                stop.set()      # failed or interrupted: the others stop after their chunk

    futures = [_pool().submit(work) for _ in range(threads - 1)]
    try:
        work()
    finally:
        stop.set()
        for f in futures:
            f.exception()       # wait for every thread before anything is raised
    for f in futures:
        f.result()
