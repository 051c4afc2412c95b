"""cityshade.runtime.threadpool.run_chunks: every item once, whatever the thread count; errors reach
the caller after every thread stopped."""
from __future__ import annotations

import threading

import numba
import numpy as np
import pytest
from numba import njit

from cityshade.runtime.threadpool import run_chunks


@njit(nogil=True, cache=True)
def _count(out, i0, i1):
    for i in range(i0, i1):
        out[i] += 1


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("n_items,chunk", [(0, 4), (1, 4), (7, 3), (1000, 1), (1000, 64),
                                           (1000, 5000)])
def test_every_item_once(threads, n_items, chunk):
    old = numba.get_num_threads()
    numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
    try:
        out = np.zeros(n_items, np.int64)
        run_chunks(_count, n_items, chunk, out)
    finally:
        numba.set_num_threads(old)
    np.testing.assert_array_equal(out, np.ones(n_items, np.int64))


def test_an_error_in_any_thread_reaches_the_caller_after_all_stopped():
    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs two Numba threads")
    running = []
    lock = threading.Lock()

    def kernel(i0, i1):
        with lock:
            running.append(1)
        try:
            if i0 == 30:
                raise ValueError("chunk 30")
        finally:
            with lock:
                running.pop()

    old = numba.get_num_threads()
    numba.set_num_threads(2)
    try:
        with pytest.raises(ValueError, match="chunk 30"):
            run_chunks(kernel, 100, 10)
    finally:
        numba.set_num_threads(old)
    assert running == []
