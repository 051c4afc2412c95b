"""A command's Numba kernels compiled in parallel processes on its first use.

Numba compiles one kernel at a time in a process (its compiler lock), so the first use of a
command on an empty cache spends 20-40 s compiling on one core while the others idle. The
kernels each command compiles, with the argument types it compiles them for, are recorded in
``kernels.json`` beside this module (``python -m cityshade.cli.record_kernels``, run on the bundled sample city). When a
command starts and its kernels are not known to be in the cache yet, :func:`start` hands them
to one child process per usable core (``python -m cityshade.runtime.prewarm --compile``),
largest first, balanced by their recorded compile times; each child compiles its share into
the command's Numba cache folder (``NUMBA_CACHE_DIR``, inherited). The command meanwhile reads
its input; its first use of Numba's compiler waits for the children (a listener on Numba's
``numba:compiler_lock`` event, which fires before the cache is looked at; the CPU target is
set up first, as that takes the lock too), and from there on
the kernels load from the cache. Answers cannot change: what a child writes is what the command
would have compiled itself, and a kernel whose types changed since the recording is compiled by
the command as before. A mark in the cache folder (one per command and manifest) says the work
is done; a child that fails or is stopped leaves no mark, and the command compiles what is
missing itself.

``CITYSHADE_PREWARM=0`` turns it off (the test suite does; its own tests turn it on).
"""
from __future__ import annotations

import base64
import hashlib
import json
import os
import pickle
import subprocess
import sys
import time
from pathlib import Path

MANIFEST = Path(__file__).with_name("kernels.json")
#: Environment variable: "0" turns the parallel first compile off.
ENV_SWITCH = "CITYSHADE_PREWARM"
#: Seconds between two looks at the children while the command waits for them.
POLL_S = 0.02
#: Niceness a child adds to its own (lower priority than the command's work).
NICE = 10

_state: dict = {"children": [], "mark": None, "listener": None, "should_stop": None,
                "on_wait": None}


def usable_cores() -> int:
    """Cores this process may use (its CPU affinity), capped by ``NUMBA_NUM_THREADS`` when the
    caller's environment sets it."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:      # not on Linux
        cores = os.cpu_count() or 1
    limit = os.environ.get("NUMBA_NUM_THREADS", "")
    return max(1, min(cores, int(limit))) if limit.isdigit() and int(limit) > 0 else cores


def load_manifest(path: Path = MANIFEST) -> dict:
    """The recorded manifest: ``{"numba": version, "commands": {name: [entry, ...]}}``, each
    entry ``{"kernel": "module:qualname", "signature": base64 pickle, "compile_s": s}``;
    an empty one when the file is missing or unreadable."""
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return {"commands": {}}


def _mark_path(command: str, manifest_text: bytes) -> Path | None:
    folder = os.environ.get("NUMBA_CACHE_DIR")
    if not folder:
        return None
    digest = hashlib.sha1(manifest_text).hexdigest()[:12]
    return Path(folder) / f"prewarmed-{command}-{digest}"


def shares(entries: list[dict], n: int) -> list[list[int]]:
    """Entry indices split into ``n`` shares of about equal recorded compile time: largest
    first, each to the share with the least so far (each share in that order)."""
    loads = [0.0] * n
    out: list[list[int]] = [[] for _ in range(n)]
    order = sorted(range(len(entries)), key=lambda i: -float(entries[i].get("compile_s", 0.0)))
    for i in order:
        k = loads.index(min(loads))
        out[k].append(i)
        loads[k] += float(entries[i].get("compile_s", 0.0))
    return [s for s in out if s]


def start(command: str, should_stop=None, manifest: Path = MANIFEST, on_wait=None) -> int:
    """Start the children that compile ``command``'s recorded kernels, unless it is off, one
    core is all there is, the command has none recorded, or the mark says they are cached.
    Returns the number of children started. ``should_stop()`` (a Ctrl-C seen) stops waiting
    for them and stops them; ``on_wait(children)`` is called once when the command starts
    waiting for them (never, when its small work all runs interpreted)."""
    cores = usable_cores()
    if os.environ.get(ENV_SWITCH, "1") == "0" or _state["children"] or cores < 2:
        return 0
    try:
        text = manifest.read_bytes()
    except OSError:
        return 0
    mark = _mark_path(command, text)
    if mark is None or mark.exists():
        return 0        # every later run of the command: no manifest parsed
    try:
        entries = json.loads(text)["commands"].get(command, [])
    except (ValueError, KeyError, AttributeError):
        return 0
    if not entries:
        return 0
    try:
        mark.parent.mkdir(parents=True, exist_ok=True)
    except OSError:
        return 0
    if not os.access(mark.parent, os.W_OK):
        return 0        # the children could not save: the command would compile it all again
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1")
    children = []
    for share in shares(entries, cores):
        cmd = [sys.executable, "-m", "cityshade.runtime.prewarm", "--compile", str(manifest),
               command, ",".join(map(str, share))]
        try:
            children.append(subprocess.Popen(cmd, env=env, stdin=subprocess.DEVNULL,
                                             stdout=subprocess.DEVNULL,
                                             stderr=subprocess.DEVNULL))
        except OSError:
            break
    _state.update(children=children, mark=mark, should_stop=should_stop, on_wait=on_wait)
    if children:
        # Numba takes its compiler lock once to set up its CPU target (at the first ``@njit``
        # the command imports), which is no compile: done before listening, so a command
        # whose kernels all run interpreted (runtime/interpret.py) never waits.
        from numba.core.registry import cpu_target

        cpu_target.target_context  # the property sets the target up
        _listen()
    return len(children)


def _listen() -> None:
    """Wait for the children at this process's first use of Numba's compiler."""
    from numba.core import event

    class FirstCompile(event.Listener):
        def on_start(self, ev):
            wait()

        def on_end(self, ev):
            pass

    listener = FirstCompile()
    event.register("numba:compiler_lock", listener)
    _state["listener"] = listener


def wait() -> None:
    """Block until every child has ended (or a Ctrl-C is seen: then stop them); write the
    mark when all of them compiled their share. Does nothing without children."""
    children = _state["children"]
    if not children:
        return
    should_stop, on_wait = _state["should_stop"], _state["on_wait"]
    try:
        if on_wait is not None and any(c.poll() is None for c in children):
            on_wait(len(children))
        while any(c.poll() is None for c in children):
            if should_stop is not None and should_stop():
                break
            time.sleep(POLL_S)
    finally:
        ok = all(c.poll() == 0 for c in children)
        stop()
    if ok and _state["mark"] is not None:
        try:
            _state["mark"].touch()
        except OSError:
            pass        # a read-only or full cache: the next run compiles in parallel again


def stop() -> None:
    """End the children that still run (the command ended before it compiled anything, or was
    interrupted) and stop listening."""
    children, _state["children"] = _state["children"], []
    for c in children:
        if c.poll() is None:
            c.kill()
        c.wait()
    listener, _state["listener"] = _state["listener"], None
    if listener is not None:
        from numba.core import event

        event.unregister("numba:compiler_lock", listener)


def entry_types(entry: dict) -> tuple:
    """The recorded argument types of a manifest entry."""
    return pickle.loads(base64.b64decode(entry["signature"]))


def _dispatcher(name: str):
    import importlib

    module, _, qualname = name.partition(":")
    obj = importlib.import_module(module)
    for part in qualname.split("."):
        obj = getattr(obj, part)
    return obj


def compile_share(entries: list[dict]) -> None:
    """Compile (or load, when already cached) each entry's kernel for its recorded types.
    An entry that cannot be read or compiled any more (types of another Numba, a kernel
    renamed or given other parameters) is left to the command."""
    from numba.core.errors import NumbaError

    for entry in entries:
        try:
            types = entry_types(entry)
            dispatcher = _dispatcher(entry["kernel"])
            dispatcher.compile(tuple(types))
        except (ImportError, AttributeError, KeyError, ValueError, EOFError,
                pickle.UnpicklingError, NumbaError):
            continue    # a stale entry (renamed, other types): the command compiles it itself


def _main(argv: list[str]) -> None:
    """``--compile MANIFEST COMMAND I,J,...``: a child's share (see :func:`start`)."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_DFL)     # a Ctrl-C ends a child at once
    # Below the command: one that runs small work interpreted (runtime/interpret.py) while
    # its children compile for later runs keeps its cores; one that waits for them is idle.
    if hasattr(os, "nice"):  # not on Windows
        os.nice(NICE)
    manifest, command, share = argv[1], argv[2], argv[3]
    entries = load_manifest(Path(manifest))["commands"].get(command, [])
    compile_share([entries[int(i)] for i in share.split(",") if i])


if __name__ == "__main__":
    _main(sys.argv[1:])
