"""Small work on first use: a kernel's own Python source run by the interpreter, not compiled.

Compiling a kernel costs seconds the first time (the triangulation about 8 CPU s, the
coordinate parser about 2), while the interpreter runs a small city's work through the same
source in a fraction of that (the sample city: triangulation 0.09 s, parse 0.2 s). So a kernel
whose compiled code is neither in this process nor in Numba's cache runs interpreted while its
work is small, and compiles once the work is large or the process has done enough of it.

:func:`python_twin` is the kernel's Python function with every ``@njit`` callee of its module
(and every one it imports, with that module's globals) replaced by the callee's Python function:
the same operations in the same order on IEEE doubles (Numba compiles without fast-math), so the
answers are the kernel's bit for bit (tested for each kernel that uses it). A kernel that relies
on Numba-only semantics (integer overflow, ``float ** int`` by repeated squaring, a ``prange``
reduction, whose order Numba chooses) must not use it; a ``prange`` loop whose iterations are
independent runs in order, the same. Nor may a float32 scalar meet a Python float in it: NumPy 2
computes and compares that in float32, Numba in float64 (widen with ``np.float64(...)``, which
compiles to the same code). Kernels a command runs over chunks on threads run interpreted once
over the whole range (:func:`run_range`).
"""
from __future__ import annotations

import pickle
import sys
import threading
import types

from numba.core.caching import NullCache
from numba.core.dispatcher import Dispatcher

from cityshade.runtime.threadpool import run_chunks

_TWINS: dict[str, dict] = {}
#: Kernels found in Numba's cache: they stay there for this process's sources, so the index is
#: read once (budgets and ``exact``'s choice ask per call).
_CACHED: set = set()
_LOCK = threading.RLock()     # a twin's imported kernels are twins too


def python_twin(kernel):
    """The interpreted twin of an ``@njit`` kernel (see the module's docstring)."""
    name = kernel.py_func.__module__
    with _LOCK:
        space = _TWINS.get(name)
        if space is None:
            space = dict(vars(sys.modules[name]))  # the module's globals as compiled: frozen
            _TWINS[name] = space
            for key, value in list(space.items()):
                if isinstance(value, Dispatcher):
                    f = value.py_func
                    if f.__module__ == name:
                        space[key] = types.FunctionType(f.__code__, space, f.__name__,
                                                        f.__defaults__, f.__closure__)
                    else:   # imported from another module: the twin reads that one's globals
                        space[key] = python_twin(value)
    return space[kernel.py_func.__name__]


def twin_if(interpret: bool, kernel):
    """``kernel``'s interpreted twin when ``interpret`` (an :class:`InterpretBudget`'s answer),
    else the kernel itself."""
    return python_twin(kernel) if interpret else kernel


def run_range(kernel, interpret: bool, n_items: int, chunk_items: int, *args) -> None:
    """``kernel(*args, i0, i1)`` over ``[0, n_items)``: compiled, in chunks on the thread pool
    (:func:`cityshade.runtime.threadpool.run_chunks`); interpreted, its twin once over the
    whole range in this thread (threads would only take turns holding the GIL)."""
    if not interpret:
        run_chunks(kernel, n_items, chunk_items, *args)
    elif n_items > 0:
        python_twin(kernel)(*args, 0, n_items)


def compiled_or_cached(kernel) -> bool:
    """Whether ``kernel`` has compiled code in this process or, for its current source, in
    Numba's cache (any signature: loading it costs a fraction of a second). A plain function
    (``NUMBA_DISABLE_JIT=1``) counts as compiled: it runs as it is."""
    if not isinstance(kernel, Dispatcher) or kernel.signatures:
        return True
    if kernel in _CACHED:
        return True
    if isinstance(kernel._cache, NullCache):  # ``cache=False``: nothing on disk
        return False
    try:
        # Numba's cache index of the function, empty when missing or stale (and read again
        # then: the first compile's children may be writing it).
        found = bool(kernel._cache._cache_file._load_index())
    except (AttributeError, OSError, EOFError, ValueError, pickle.UnpicklingError):
        return True     # another Numba's internals, or an unreadable index: compile as before
    if found:
        _CACHED.add(kernel)
    return found


class InterpretBudget:
    """Work a process may still run interpreted, in the kernel's own unit (points, bytes).

    ``take(n)`` says whether a call of ``n`` units runs interpreted: the kernels are neither
    compiled nor cached and ``n`` fits in what is left (then it is spent). Once the budget is
    spent, the kernels compile as before: a process that reads many small files pays the
    compile once instead of interpreting all of them.
    """

    def __init__(self, units: int, *kernels):
        self.left = units
        self.kernels = kernels
        self._lock = threading.Lock()

    def take(self, n: int) -> bool:
        with self._lock:
            if n > self.left or any(compiled_or_cached(k) for k in self.kernels):
                return False
            self.left -= n
            return True
