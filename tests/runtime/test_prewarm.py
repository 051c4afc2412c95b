"""The commands' parallel first compile (cityshade.runtime.prewarm): the recorded manifest
matches the kernels, children compile into the command's cache and the command then compiles
nothing, the mark stops a second start, and a Ctrl-C while waiting leaves no child behind."""
from __future__ import annotations

import base64
import inspect
import json
import os
import pickle
import signal
import subprocess
import sys
import time
from pathlib import Path

import numba
import pytest

from cityshade.runtime import prewarm
from conftest import COMPILE_EVENTS, REPO


def test_shares_are_balanced_largest_first():
    entries = [{"compile_s": s} for s in (5.0, 4.0, 3.0, 3.0, 3.0)]
    # 5 -> A, 4 -> B, 3 -> B (7), 3 -> A (8), 3 -> B (10): the greedy longest-first split.
    assert prewarm.shares(entries, 2) == [[0, 3], [1, 2, 4]]
    assert prewarm.shares(entries, 1) == [[0, 1, 2, 3, 4]]
    assert prewarm.shares(entries[:1], 3) == [[0]]


def test_the_manifest_names_kernels_with_their_argument_count():
    data = prewarm.load_manifest()
    assert data["numba"] == numba.__version__, "re-record: python -m cityshade.cli.record_kernels"
    assert {"build", "render", "batch"} <= set(data["commands"])
    for command, entries in data["commands"].items():
        assert entries, command
        kernels = [(e["kernel"], prewarm.entry_types(e)) for e in entries]
        assert len(set(kernels)) == len(kernels), f"{command}: a kernel recorded twice"
        for entry in entries:
            dispatcher = prewarm._dispatcher(entry["kernel"])
            assert isinstance(dispatcher, numba.core.registry.CPUDispatcher), entry["kernel"]
            types = pickle.loads(base64.b64decode(entry["signature"]))
            params = inspect.signature(dispatcher.py_func).parameters
            assert len(types) == len(params), (command, entry["kernel"])


_PROBE = COMPILE_EVENTS + """
import sys, numpy as np
from cityshade.runtime import prewarm
waits = []
started = prewarm.start("probe", manifest=__import__("pathlib").Path(sys.argv[1]),
                        on_wait=waits.append)
from cityshade.lightspace.kernels import shear_of
from cityshade.geometry.bounds import used_vertex_box
shear_of(np.array([0.3, 0.2, 0.9]))
used_vertex_box(np.zeros((1, 3), np.int64), np.zeros((1, 3)), np.zeros((2, 3)))
prewarm.stop()
print(started, ",".join(compiled) or "-", *waits)
"""


def _entry(kernel, types):
    return {"kernel": kernel, "signature": base64.b64encode(pickle.dumps(types)).decode(),
            "compile_s": 0.1}


@pytest.mark.skipif(prewarm.usable_cores() < 2, reason="one core: nothing runs in parallel")
def test_children_compile_into_the_cache_and_the_command_compiles_nothing(tmp_path):
    from numba import types as t

    arr = lambda dtype, ndim: t.Array(dtype, ndim, "C")  # noqa: E731
    manifest = tmp_path / "kernels.json"
    manifest.write_text(json.dumps({"numba": numba.__version__, "commands": {"probe": [
        _entry("cityshade.lightspace.kernels:shear_of", (arr(t.float64, 1),)),
        _entry("cityshade.geometry.bounds:used_vertex_box",
               (arr(t.int64, 2), arr(t.float64, 2), arr(t.float64, 2)))]}}))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), CITYSHADE_PREWARM="1",
               PYTHONPATH=str(REPO / "src"))
    env.pop("NUMBA_NUM_THREADS", None)
    run = lambda: subprocess.run([sys.executable, "-c", _PROBE, str(manifest)], env=env,  # noqa: E731
                                 capture_output=True, text=True, check=True).stdout.split()
    first = run()
    # Two children, nothing compiled here, and the wait for the two announced once (unless
    # they were done before the first compile: then it is not).
    assert first in (["2", "-", "2"], ["2", "-"]), first
    assert len(list((tmp_path / "numba").glob("prewarmed-probe-*"))) == 1
    assert run() == ["0", "-"]              # marked: no children, everything from the cache
    # Without the children the same calls compile here: the probe can see a compile.
    env["CITYSHADE_PREWARM"] = "0"
    env["NUMBA_CACHE_DIR"] = str(tmp_path / "numba2")
    assert run() == ["0", "shear_of,used_vertex_box"]


_INTERPRETED_PROBE = """
import os, sys, numpy as np
from cityshade.runtime import prewarm
waits = []
started = prewarm.start("probe", manifest=__import__("pathlib").Path(sys.argv[1]),
                        on_wait=waits.append)
from cityshade.geometry.bounds import used_vertex_box   # an @njit: Numba sets its target up
from cityshade.runtime.interpret import python_twin
box = np.empty((2, 3))
python_twin(used_vertex_box)(np.zeros((1, 3), np.int64), np.ones((1, 3)), box)
running = sum(c.poll() is None for c in prewarm._state["children"])
nice = [int(open(f"/proc/{c.pid}/stat").read().rsplit(")", 1)[1].split()[16])
        for c in prewarm._state["children"]]
prewarm.stop()
print(started, running, len(waits), os.nice(0), *nice)
"""


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc (Linux)")
@pytest.mark.skipif(prewarm.usable_cores() < 2, reason="one core: nothing runs in parallel")
def test_a_command_that_only_interprets_never_waits_for_the_children(tmp_path):
    """Numba's compiler lock taken to set up its CPU target (the first ``@njit`` imported) is
    no compile: the command goes on while the children (niceness +10) compile the kd-tree's
    build kernel, some seconds each, and stops them at its end."""
    build = next(e for e in prewarm.load_manifest()["commands"]["build"]
                 if e["kernel"].endswith(":_build_kernel"))
    manifest = tmp_path / "kernels.json"
    manifest.write_text(json.dumps({"numba": numba.__version__,
                                    "commands": {"probe": [build, build]}}))
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"), CITYSHADE_PREWARM="1",
               PYTHONPATH=str(REPO / "src"))
    env.pop("NUMBA_NUM_THREADS", None)
    out = subprocess.run([sys.executable, "-c", _INTERPRETED_PROBE, str(manifest)], env=env,
                         capture_output=True, text=True, check=True).stdout.split()
    started, running, waits, own, *nice = map(int, out)
    assert started == 2 and running == 2, out   # still compiling: nobody waited for them
    assert waits == 0, out                      # so the terminal was told nothing
    assert nice == [min(own + prewarm.NICE, 19)] * 2, out  # 19: the lowest priority
    assert not list((tmp_path / "numba").glob("prewarmed-*"))


def _children_of_cache(folder: str) -> list[int]:
    pids = []
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit():
            continue
        try:
            if f"NUMBA_CACHE_DIR={folder}".encode() in (proc / "environ").read_bytes() \
                    and b"prewarm" in (proc / "cmdline").read_bytes():
                pids.append(int(proc.name))
        except OSError:
            continue
    return pids


@pytest.mark.skipif(not Path("/proc/self/environ").exists(), reason="needs /proc (Linux)")
@pytest.mark.skipif(prewarm.usable_cores() < 2, reason="one core: nothing runs in parallel")
def test_ctrl_c_while_the_children_compile_ends_them_and_the_command(tmp_path):
    from cityshade.accel.kdtree_build import INTERPRET_TRIANGLES
    from cityshade.samplegen import generate_city

    # Larger than a build interprets on first use (the sample city would be done in a
    # second or two): the command waits for its children, then compiles.
    generate_city(tmp_path / "city.gml", target_triangles=INTERPRET_TRIANGLES + 2000,
                  texture=False)
    cache = str(tmp_path / "numba")
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, CITYSHADE_PREWARM="1",
               PYTHONPATH=str(REPO / "src"))
    proc = subprocess.Popen([sys.executable, "-m", "cityshade", "build",
                             str(tmp_path / "city.gml"), "-o",
                             str(tmp_path / "city.cityshade")], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while not _children_of_cache(cache) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert _children_of_cache(cache), "no child started"
    time.sleep(1.0)
    proc.send_signal(signal.SIGINT)         # to the command only: it must end its children
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130
    assert err == "cityshade: interrupted\n"
    assert _children_of_cache(cache) == []
    assert not (tmp_path / "city.cityshade").exists()
    assert not list(Path(cache).glob("prewarmed-*"))


class _Stream:
    def __init__(self, tty):
        self.tty, self.text = tty, ""

    def isatty(self):
        return self.tty

    def write(self, text):
        self.text += text

    def flush(self):
        pass


def test_a_terminal_is_told_why_the_first_use_waits():
    from cityshade.cli.main import first_compile_line

    tty, log = _Stream(True), _Stream(False)
    first_compile_line("render", 2, tty)
    first_compile_line("render", 2, log)
    first_compile_line("render", 0, _Stream(True))
    assert tty.text == ("\r\033[Kcityshade: first use of render: compiling its kernels once "
                        "(2 processes)\n")    # the line cleared first: progress may be on it
    assert log.text == ""


class _FakeChild:
    """A child process as wait() and stop() see it: running until ``end()``."""

    def __init__(self):
        self.returncode, self.stdout = None, None

    def poll(self):
        return self.returncode

    def end(self):
        self.returncode = 0

    def kill(self):
        self.returncode = -9

    def wait(self):
        return self.returncode


def test_the_command_waits_only_for_the_kernel_it_needs(monkeypatch):
    """Each child reports an entry once it is in the cache; the command goes on as soon as
    the kernel it is about to compile is reported (the other child still compiling), waits
    while it is not, and does not wait at all for a kernel no child compiles."""
    import threading

    a, b = _FakeChild(), _FakeChild()
    done: set[int] = {0}
    monkeypatch.setattr(prewarm, "_state", dict(
        prewarm._state, children=[a, b], shares=[frozenset({0, 2}), frozenset({1})], done=done, mark=None,
        names={"m:first": [0], "m:second": [1], "m:third": [2]}, should_stop=None,
        on_wait=None, listener=None, told=False, used=False))
    assert prewarm.pending("m:second") and not prewarm.pending("m:first")
    assert not prewarm.pending("m:unrecorded")
    prewarm.wait("m:first")                 # reported: at once, both still running
    prewarm.wait("m:unrecorded")            # nobody compiles it: at once
    assert a.poll() is None and b.poll() is None
    timer = threading.Timer(0.2, lambda: (done.add(1), b.end()))
    timer.start()
    prewarm.wait("m:second")                # blocks until child b reports entry 1
    timer.join()
    assert 1 in done and a.poll() is None and prewarm._state["children"] == [a, b]
    a.end()
    done.add(2)
    prewarm.wait("m:third")                 # every child ended: stop() ran
    assert prewarm._state["children"] == []


def test_the_listener_names_the_kernel_numba_is_compiling():
    from numba import njit
    from numba.core import event
    from numba.core.dispatcher import Dispatcher

    seen = []

    class Probe(event.Listener):
        def on_start(self, ev):
            seen.append(prewarm._compiling(Dispatcher.compile.__code__))

        def on_end(self, ev):
            pass

    @njit
    def tiny_kernel(x):
        return x + 1

    listener = Probe()
    event.register("numba:compiler_lock", listener)
    try:
        assert tiny_kernel(1) == 2
    finally:
        event.unregister("numba:compiler_lock", listener)
    name = f"{__name__}:test_the_listener_names_the_kernel_numba_is_compiling.<locals>.tiny_kernel"
    assert seen and seen[0] == name, seen
