"""The interpreted tier of small first-use work (cityshade.runtime.interpret): the budget's
rules and the cache check; each kernel that uses it tests its twin's bits in its own area."""
from __future__ import annotations

import importlib.util
import sys

import numba
import numpy as np

from cityshade.runtime.interpret import InterpretBudget, compiled_or_cached, python_twin
from conftest import COMPILE_EVENTS

SOURCE = '''
from numba import njit


@njit(cache=True)
def _half(x):
    return 0.5 * x


@njit(cache=True)
def kernel(a):
    s = 0.0
    for i in range(a.shape[0]):
        s += _half(a[i])
    return s
'''


def _module(tmp_path, monkeypatch, name):
    path = tmp_path / f"{name}.py"
    path.write_text(SOURCE)
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(tmp_path / "cache"))
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, mod)
    spec.loader.exec_module(mod)
    return mod


def test_twin_runs_the_python_source_and_its_callees_uncompiled(tmp_path, monkeypatch):
    mod = _module(tmp_path, monkeypatch, "interp_twin_mod")
    twin = python_twin(mod.kernel)
    a = np.array([1.0, 3.0, 0.25])
    assert twin(a) == 2.125
    assert not mod.kernel.signatures and not mod._half.signatures  # nothing compiled
    assert twin.__globals__["_half"] is not mod._half
    assert mod.kernel(a) == twin(a)


def test_budget_interprets_small_work_until_spent_or_compiled(tmp_path, monkeypatch):
    mod = _module(tmp_path, monkeypatch, "interp_budget_mod")
    budget = InterpretBudget(10, mod.kernel)
    assert not compiled_or_cached(mod.kernel)
    assert budget.take(6) and budget.left == 4
    assert not budget.take(5) and budget.left == 4   # too large for what is left
    assert budget.take(4) and budget.left == 0
    mod.kernel(np.ones(2))                           # compiled (and cached)
    assert compiled_or_cached(mod.kernel)
    assert not InterpretBudget(10, mod.kernel).take(1)


def test_a_kernel_in_numba_s_cache_is_not_interpreted(tmp_path, monkeypatch):
    """A new process finds the kernel in the cache without compiling it: a second dispatcher
    of the same function stands for it (no signature compiled in it)."""
    mod = _module(tmp_path, monkeypatch, "interp_cached_mod")
    mod.kernel(np.ones(2))
    fresh = numba.njit(cache=True)(mod.kernel.py_func)
    assert not fresh.signatures and compiled_or_cached(fresh)
    uncached = numba.njit(cache=False)(mod.kernel.py_func)
    assert not compiled_or_cached(uncached)
    assert compiled_or_cached(mod.kernel.py_func)  # NUMBA_DISABLE_JIT=1: runs as it is
    assert not InterpretBudget(10, mod.kernel.py_func).take(1)


_BUILD_PROBE = COMPILE_EVENTS + """
import sys
from cityshade.cli.main import _command
status = _command(["build", sys.argv[1], "-o", sys.argv[2]])
during = ",".join(compiled)
import numpy as np
from cityshade.geometry.bounds import used_vertex_box
used_vertex_box(np.zeros((1, 3), np.int64), np.zeros((1, 3)), np.zeros((2, 3)))
print(status, during, ",".join(compiled))
"""


def test_the_sample_city_builds_on_first_use_without_compiling(tmp_path):
    """Issue 40: an empty Numba cache, no parallel first compile, ``cityshade build`` of the
    sample city: every kernel on the way runs interpreted, none compiles (a second process
    with a fresh cache; the compile events are Numba's own)."""
    import os
    import subprocess

    from conftest import REPO

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), CITYSHADE_PREWARM="0",
               PYTHONPATH=str(REPO / "src"))
    env.pop("NUMBA_DISABLE_JIT", None)
    out = subprocess.run([sys.executable, "-c", _BUILD_PROBE,
                          str(REPO / "sample_data" / "sample_city.gml"),
                          str(tmp_path / "city.cityshade")], env=env, capture_output=True,
                         text=True, check=True).stdout.split("\n")[-2]
    # Exit status 0, nothing compiled; then a direct call does compile: the probe sees it.
    assert out == "0  used_vertex_box", out
    assert (tmp_path / "city.cityshade").stat().st_size > 100_000
