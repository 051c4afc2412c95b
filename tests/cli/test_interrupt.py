"""Ctrl-C at any moment (issue 13 point 8): one line, exit status 130, no traceback, no
half-written file. The CLI runs in a subprocess and gets a real SIGINT at several moments of a
build, a render and a batch."""
from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import click
import numpy as np
import pytest


#: Triangles of the generated city the commands work on: big enough that a build (about 3 s
#: here) and a render (about 2 s) are still running at every delay below on a fast machine
#: (the 1,386-triangle sample city builds in half a second with warm kernels).
CITY_TRIANGLES = 100_000
SAMPLE = Path(__file__).resolve().parents[2] / "sample_data" / "sample_city.gml"
#: Seconds after the start at which SIGINT is sent: after Python's start-up (the handler is
#: installed first thing in main()), then spread over imports, reading, kernels and writing.
DELAYS_S = (0.6, 1.1, 1.7)

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")


def _interrupt(args, delay_s, cwd, sig=signal.SIGINT):
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen([sys.executable, "-m", "cityshade", *map(str, args)], cwd=cwd,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, text=True)
    time.sleep(delay_s)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=300)
    return proc.returncode, err


def _check(rc, err, folder, status=130, word="interrupted"):
    assert "Traceback" not in err, err
    leftovers = [p.name for p in folder.iterdir() if p.name.startswith(".") or
                 p.name.endswith(".tmp")]
    assert not leftovers, f"partial files left: {leftovers}"
    assert rc in (0, status), f"exit status {rc}: {err}"
    if rc == status:
        # Warnings and the progress lines of a non-terminal stderr may precede the last line.
        lines = [line for line in err.splitlines()
                 if line.strip() and not line.startswith("cityshade: warning:")
                 and not re.fullmatch(r"cityshade: .* \d+/\d+ \(\d+ %(, ETA [\d:]+)?\).*", line)]
        assert lines == [f"cityshade: {word}"], err
    return rc == status


@pytest.fixture(scope="module")
def city_gml(tmp_path_factory):
    from cityshade.samplegen import generate_city

    path = tmp_path_factory.mktemp("interrupt_city") / "city.gml"
    generate_city(path, target_triangles=CITY_TRIANGLES, seed=3)
    # One build without a signal, so that the interrupted builds load compiled kernels.
    done = subprocess.run([sys.executable, "-m", "cityshade", "build", str(path), "-o",
                           str(path.with_suffix(".cityshade")), "-q"], capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return path


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory, city_gml):
    """The city built once, then rendered and batched once without a signal: every kernel the
    interrupted runs use is compiled and cached before them (a Ctrl-C during a first-call
    compile has its own test, :func:`test_sigint_during_a_first_call_compile`)."""
    folder = tmp_path_factory.mktemp("interrupt")
    out = folder / "city.cityshade"
    for args in (["build", city_gml, "-o", out, "-q"],
                 [*render_args(out), "-o", folder / "w.exr", "--png", folder / "w.png"],
                 [*batch_args(out), "-o", folder / "warm"]):
        done = subprocess.run([sys.executable, "-m", "cityshade", *map(str, args)],
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
    return out


def render_args(scene):
    return ["render", scene, "--date", "1990", "--sun-azimuth", "135", "--sun-elevation", "30",
            "--size", "640x360"]


def batch_args(scene):
    return ["batch", scene, "--date", "2024-06-21", "--from", "06:00", "--to", "20:00",
            "--every", "30min", "--tz", "Europe/Berlin", "--camera", "map", "--pixel-size", "2"]


def _interrupted_builds(tmp_path, city, delays_s):
    from cityshade.store.cache import open_cache
    interrupted = 0
    for k, delay in enumerate(delays_s):
        folder = tmp_path / f"b{k}"
        folder.mkdir()
        out = folder / "city.cityshade"
        rc, err = _interrupt(["build", city, "-o", out], delay, folder)
        interrupted += _check(rc, err, folder)
        if out.exists():   # finished before the signal, or renamed just before it
            open_cache(out)
    return interrupted


def test_sigint_during_build(tmp_path, city_gml):
    """The sample city: the signal lands in start-up, reading, triangulation or writing."""
    interrupted = _interrupted_builds(tmp_path, SAMPLE, (0.3, 0.6, 1.1))
    assert interrupted, "no run was interrupted: the delays are too long for this machine"


def test_sigint_during_the_kdtree_build(tmp_path, city_gml):
    """A 100k-triangle build: the signal lands in the kd-tree build (about 0.7-1.5 s in here).
    A SIGINT while the kernel ran on the main thread with the GIL held crashed the process
    (status -11, with Python's own handler too); the kernel now runs without the GIL in
    worker threads while the main thread waits, and the interrupt is clean."""
    interrupted = _interrupted_builds(tmp_path, city_gml, (1.1, 1.4, 1.7))
    assert interrupted, "no run was interrupted: the delays are too long for this machine"


def test_sigterm_during_a_tiled_build_cleans_up(tmp_path, city_gml):
    """A job scheduler's or ``kill``'s SIGTERM killed the process where it stood and left the
    tiled build's hidden temporary folder behind; it now cleans up as Ctrl-C does (143)."""
    ended = 0
    for k, delay in enumerate((1.0, 1.6, 2.4)):
        folder = tmp_path / f"t{k}"
        folder.mkdir()
        rc, err = _interrupt(["build", city_gml, "--tile-m", "150", "-o", folder / "city"],
                             delay, folder, signal.SIGTERM)
        ended += _check(rc, err, folder, 143, "terminated")
    assert ended, "no run was terminated: the delays are too long for this machine"


def test_sigint_during_render(tmp_path, scene_file):
    interrupted = 0
    for k, delay in enumerate(DELAYS_S):
        folder = tmp_path / f"r{k}"
        folder.mkdir()
        rc, err = _interrupt([*render_args(scene_file), "-o", folder / "a.exr", "--png",
                              folder / "a.png"], delay, folder)
        if _check(rc, err, folder):
            interrupted += 1
            assert not (folder / "a.png").exists() or (folder / "a.exr").exists()
    assert interrupted


def test_sigint_during_batch(tmp_path, scene_file):
    interrupted = 0
    for k, delay in enumerate(DELAYS_S):
        folder = tmp_path / f"s{k}"
        rc, err = _interrupt([*batch_args(scene_file), "-o", folder], delay, tmp_path)
        folder.mkdir(exist_ok=True)
        interrupted += _check(rc, err, folder)
    assert interrupted


def test_sigint_during_sky(tmp_path, scene_file):
    """The sky's outputs are one group: an interrupted run leaves none of them (and no
    folder it made), a finished one all of them."""
    args = ["sky", scene_file, "--sky", "tregenza", "--pixel-size", "6", "--vsc"]
    warm = subprocess.run([sys.executable, "-m", "cityshade", *map(str, args), "-o",
                           tmp_path / "warm"], capture_output=True, text=True, timeout=600)
    assert warm.returncode == 0, warm.stderr
    complete = sorted(p.name for p in (tmp_path / "warm").iterdir())
    assert "svf.exr" in complete and "vsc.tif" in complete
    interrupted = 0
    for k, delay in enumerate((0.8, 1.5, 2.5)):
        folder = tmp_path / f"k{k}"
        rc, err = _interrupt([*args, "-o", folder], delay, tmp_path)
        if rc == 130:
            assert not folder.exists() or not any(folder.iterdir()), list(folder.iterdir())
        folder.mkdir(exist_ok=True)
        if _check(rc, err, folder):
            interrupted += 1
        else:
            assert sorted(p.name for p in folder.iterdir()) == complete
    assert interrupted


def test_sigint_during_a_tiled_sky_then_the_same_command_resumes(tmp_path, scene_file):
    """A sky run in tiles stopped by Ctrl-C keeps its finished tiles (``state.npz`` and
    ``manifest.json``, nothing half-written); the same command again says in one line that
    it resumes and writes the maps of an uninterrupted run, bit for bit, and leaves only its
    outputs."""
    from cityshade.imageio import read_exr

    args = ["sky", scene_file, "--sky", "tregenza", "--pixel-size", "6", "--vsc",
            "--tile-px", "32"]
    t0 = time.perf_counter()
    warm = subprocess.run([sys.executable, "-m", "cityshade", *map(str, args), "-o",
                           tmp_path / "warm"], capture_output=True, text=True, timeout=600)
    warm_s = time.perf_counter() - t0
    assert warm.returncode == 0, warm.stderr
    complete = sorted(p.name for p in (tmp_path / "warm").iterdir())
    assert "svf.exr" in complete and "state.npz" not in complete
    resumed = 0
    # While the tiles are traced: from about a third of the uninterrupted run (start-up and
    # the camera pass before) to before its writes (3.6 s in all on an idle machine, twice
    # that beside the rest of the suite).
    for k, share in enumerate((0.5, 0.62, 0.74)):
        delay = share * warm_s
        folder = tmp_path / f"t{k}"
        rc, err = _interrupt([*args, "-o", folder], delay, tmp_path)
        folder.mkdir(exist_ok=True)
        if not _check(rc, err, folder) or not (folder / "state.npz").exists():
            continue
        assert sorted(p.name for p in folder.iterdir()) == ["manifest.json", "state.npz"]
        again = subprocess.run([sys.executable, "-m", "cityshade", *map(str, args), "-o",
                                folder], capture_output=True, text=True, timeout=600)
        assert again.returncode == 0, again.stderr
        notes = [line for line in again.stderr.splitlines() if "resuming" in line]
        assert len(notes) == 1 and re.fullmatch(
            rf"cityshade: resuming the run in {re.escape(str(folder))}: \d+ of \d+ tiles "
            rf"were done before", notes[0]), again.stderr
        assert sorted(p.name for p in folder.iterdir()) == complete
        for name in ("svf.exr", "vsc.exr"):
            want, got = read_exr(tmp_path / "warm" / name)[0], read_exr(folder / name)[0]
            assert want.keys() == got.keys()
            for channel in want:
                np.testing.assert_array_equal(got[channel], want[channel])
        resumed += 1
    assert resumed, "no run was stopped with finished tiles: the delays do not fit this machine"


def test_sigint_during_a_first_call_compile(tmp_path):
    """A fresh Numba cache, as after an install: the render compiles its kernels first. A
    SIGINT that landed in the compiler printed llvmlite's traceback after the one line
    (``Exception ignored in: ObjectRef.__del__ ... 'PassBuilder' object has no attribute
    '_as_parameter_'``); it is now held to the end of the compiler's current pass."""
    scene = tmp_path / "sample.cityshade"
    done = subprocess.run([sys.executable, "-m", "cityshade", "build", str(SAMPLE), "-o",
                           str(scene), "-q"], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    cache = tmp_path / "numba_cache"
    out = tmp_path / "out"
    out.mkdir()
    env = dict(os.environ, PYTHONUNBUFFERED="1", NUMBA_CACHE_DIR=str(cache))
    proc = subprocess.Popen([sys.executable, "-m", "cityshade", *map(str, render_args(scene)),
                             "-o", out / "a.exr"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env, text=True)
    # The first kernel written to the fresh cache: the compiles have begun (about 5 s in
    # here), and the next one runs when the signal comes.
    while proc.poll() is None and not list(cache.rglob("*.nbi")):
        time.sleep(0.02)
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=300)
    assert _check(proc.returncode, err, out), "the render finished before the signal"
    assert not (out / "a.exr").exists()


#: A child that runs a Numba kernel returning typed lists between arrays (as the kd-tree
#: build's kernel does) under the command's Ctrl-C handler, as ``main()`` runs a command.
BOXING_CHILD = """
import sys, time
import numpy as np
from numba import njit
from numba.typed import List
from cityshade.cli.options import Interrupted, install_sigint_handler, translate_errors

@njit(nogil=True)
def kernel(seconds):
    x = 0.0
    for i in range(int(seconds * 2e8)):
        x += i * 1e-9
    return np.full(4, x), (List([np.zeros(3)]), List([np.zeros(2)])), np.zeros(5)

kernel(0.0)
install_sigint_handler()
print("ready", flush=True)
try:
    with translate_errors():
        kernel(float(sys.argv[1]))
        time.sleep(1.0)   # a held Ctrl-C is raised here at the latest
except Interrupted as exc:
    exc.show()
    sys.exit(130)
print("not interrupted")
"""


def test_sigint_while_a_kernel_runs_is_raised_after_numba_boxed_its_result(tmp_path):
    """The intermittent SIGSEGV of the kd-tree build (status -11, empty stderr): a SIGINT that
    arrives while a kernel runs is handled at the next bytecode, which is Python code run by
    Numba's wrapper to box the typed lists of the result. A KeyboardInterrupt raised there
    was not expected by the wrapper: it went on boxing with the exception set and freed a
    half-made array (``NRT_MemInfo_release(NULL)``), or returned the result with the
    exception set (``SystemError``). The signal is sent while the kernel runs, every time."""
    script = tmp_path / "child.py"
    script.write_text(BOXING_CHILD)
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen([sys.executable, str(script), "3"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env, text=True)
    assert proc.stdout.readline() == "ready\n"
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert (proc.returncode, err, out) == (130, "cityshade: interrupted\n", "")


def test_numba_on_stack_sees_numba_code_called_from_a_kernel_wrapper():
    """The rule behind the test above: the handler holds the interrupt while a frame of
    Numba's is on the stack (here numba's typeof, which asks the object for its type)."""
    import numba
    from cityshade.cli.options import numba_on_stack

    seen = []

    class Probe:
        @property
        def _numba_type_(self):
            seen.append(numba_on_stack(sys._getframe()))
            return numba.types.int64

    numba.typeof(Probe())
    assert seen == [True]
    assert not numba_on_stack(sys._getframe())


def test_import_on_stack_sees_a_module_being_imported(tmp_path, monkeypatch):
    """A Ctrl-C is held while a module is imported: raised in an extension module's start-up
    (OpenImageIO's nanobind enums, imported at the first texture read), it aborted the render
    with a traceback."""
    from cityshade.cli.options import import_on_stack

    (tmp_path / "probe_module_for_import.py").write_text(
        "import sys\nfrom cityshade.cli.options import import_on_stack\n"
        "SEEN = import_on_stack(sys._getframe())\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import probe_module_for_import

    assert probe_module_for_import.SEEN is True
    assert not import_on_stack(sys._getframe())


#: ``python -m cityshade`` (runpy imports the package with argv[0] "-m") and the console
#: script, each sent a Ctrl-C (or a SIGTERM) right after ``import cityshade``; and a program
#: that imports the library, whose handlers stay Python's.
START_CHILD = """
import os, signal, sys, time
kind = sys.argv[1]
if kind == "-m":
    sys.argv[0] = "-m"
    sys.orig_argv = [sys.executable, "-X", "utf8", "-m", "cityshade", "build", "x.gml"]
elif kind == "script":
    sys.argv[0] = os.path.join(os.path.dirname(sys.executable), "cityshade")
import cityshade
os.kill(os.getpid(), int(sys.argv[2]))
time.sleep(2)
print("still running")
"""


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
@pytest.mark.parametrize("kind", ["-m", "script", "library"])
def test_signal_while_the_package_is_imported(tmp_path, kind, sig):
    """Ctrl-C while the command's process imports the package (the Numba cache folder is
    keyed by a hash of the sources there, then numba, lxml, pyproj): one line and 130. The
    handler used to be installed by ``cityshade.__main__``, after the package's import: 8 of
    300 Ctrl-Cs 0.1-0.5 s into ``python -m cityshade build`` on a loaded machine gave
    Python's traceback and status -2. A SIGTERM there ended the process by the signal
    (status -15, no line: a CI run's tiled-build test met it); it is now 143 and one line."""
    script = tmp_path / "child.py"
    script.write_text(START_CHILD)
    # As from a terminal: a test run started in the background inherits an ignored SIGINT,
    # which the command leaves ignored.
    done = subprocess.run([sys.executable, str(script), kind, str(int(sig))],
                          capture_output=True, text=True, timeout=60, cwd=tmp_path,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    if kind == "library" and sig == signal.SIGINT:
        assert done.returncode == -signal.SIGINT and "KeyboardInterrupt" in done.stderr
    elif kind == "library":
        assert (done.returncode, done.stdout) == (-signal.SIGTERM, "")
    else:
        word, status = ("interrupted", 130) if sig == signal.SIGINT else ("terminated", 143)
        assert (done.returncode, done.stderr, done.stdout) == (status, f"cityshade: {word}\n",
                                                               "")


#: A SIGTERM in the last moments of a finished command: at ``sys.exit``, then at shutdown.
END_CHILD = """
import atexit, os, signal, sys
from cityshade.cli.main import main
atexit.register(lambda: os.kill(os.getpid(), signal.SIGTERM))
real_exit = sys.exit
def exit_now(status):
    os.kill(os.getpid(), signal.SIGTERM)
    real_exit(status)
sys.exit = exit_now
main(["--version"], own_process=True)
"""


def test_sigterm_after_the_command_ended_keeps_its_status(tmp_path):
    """A SIGTERM after the command's work (its status known): Python's shutdown resets the
    handlers to the default, and the process used to end by the signal (status -15, a CI run's
    tiled-build test met it); the command's own status stands."""
    script = tmp_path / "child.py"
    script.write_text(END_CHILD)
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=60, cwd=tmp_path)
    assert (done.returncode, done.stderr) == (0, ""), done.stderr
    assert done.stdout.startswith("cityshade, version")


def test_numba_systemerror_from_an_interrupt_is_an_interrupt():
    """Ctrl-C inside a Numba kernel surfaces as SystemError('CPUDispatcher(...) returned a
    result with an exception set') chained to the KeyboardInterrupt."""
    from cityshade.cli.options import Interrupted, translate_errors

    def kernel_call():
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as exc:
            raise SystemError("CPUDispatcher(<function _build_kernel>) returned a result "
                              "with an exception set") from exc

    with pytest.raises(Interrupted) as info:
        with translate_errors():
            kernel_call()
    assert info.value.exit_code == 130
    assert isinstance(info.value, click.ClickException)
    # A SystemError that no interrupt caused stays what it is.
    with pytest.raises(SystemError):
        with translate_errors():
            raise SystemError("something else")
