"""A command's Numba kernels compiled in parallel processes on its first use.

Numba compiles one kernel at a time in a process (its compiler lock), so the first use of a
command on an empty cache spends 20-40 s compiling on one core while the others idle. The
kernels each command compiles, with the argument types it compiles them for, are recorded in
``kernels.json`` beside this module (``python -m cityshade.cli.record_kernels``, run on the bundled sample city). When a
command starts and its kernels are not known to be in the cache yet, :func:`start` hands them
to one child process per usable core (``python -m cityshade.runtime.prewarm --compile``),
balanced by their recorded compile times, each share in the order the command needs them;
each child compiles its share into the command's Numba cache folder (``NUMBA_CACHE_DIR``,
inherited) and prints each entry's index once it is saved. The command meanwhile reads its
input; whenever it is about to compile a kernel (a listener on Numba's
``numba:compiler_lock`` event, which fires before the cache is looked at; the CPU target is
set up first, as that takes the lock too) it waits until the child that has that kernel has
reported it, and loads it from the cache, while the children go on with the rest. Answers
cannot change: what a child writes is what the command would have compiled itself, and a
kernel whose types changed since the recording (or that no child compiles) is compiled by
the command as before. A mark in the cache folder (one per command and manifest) says the work
is done: a command that waited lets the children finish at its end; a child that fails or is
stopped leaves no mark, and the command compiles what is missing itself.

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
import threading
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
                "on_wait": None, "shares": [], "names": {}, "done": set(), "told": False,
                "used": False}


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
    first, each to the share with the least so far; each share then in the manifest's order,
    the order the command first needs them in (it goes on as soon as the one it needs is
    there)."""
    loads = [0.0] * n
    out: list[list[int]] = [[] for _ in range(n)]
    order = sorted(range(len(entries)), key=lambda i: -float(entries[i].get("compile_s", 0.0)))
    for i in order:
        k = loads.index(min(loads))
        out[k].append(i)
        loads[k] += float(entries[i].get("compile_s", 0.0))
    return [sorted(s) for s in out if s]


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
    children, started = [], []
    done: set[int] = set()
    for share in shares(entries, cores):
        cmd = [sys.executable, "-m", "cityshade.runtime.prewarm", "--compile", str(manifest),
               command, ",".join(map(str, share))]
        try:
            child = subprocess.Popen(cmd, env=env, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
        except OSError:
            break
        children.append(child)
        started.append(frozenset(share))
        threading.Thread(target=_read_reports, args=(child, done), daemon=True).start()
    names: dict[str, list[int]] = {}
    for i, entry in enumerate(entries):
        names.setdefault(str(entry.get("kernel", "")), []).append(i)
    _state.update(children=children, mark=mark, should_stop=should_stop, on_wait=on_wait,
                  shares=started, names=names, done=done, told=False, used=False)
    if children:
        # Numba takes its compiler lock once to set up its CPU target (at the first ``@njit``
        # the command imports), which is no compile: done before listening, so a command
        # whose kernels all run interpreted (runtime/interpret.py) never waits.
        from numba.core.registry import cpu_target

        cpu_target.target_context  # the property sets the target up
        _listen()
    return len(children)


def _read_reports(child, done: set) -> None:
    """Collect the entry indices a child says it has compiled (one per line)."""
    for line in child.stdout:
        try:
            done.add(int(line))
        except ValueError:
            continue


def _listen() -> None:
    """Wait for the children whenever this process is about to compile a kernel one of them
    has still to save; compile at once what none of them will."""
    from numba.core import event
    from numba.core.dispatcher import Dispatcher

    compile_code = Dispatcher.compile.__code__

    class KernelCompile(event.Listener):
        def on_start(self, ev):
            wait(_compiling(compile_code))

        def on_end(self, ev):
            pass

    listener = KernelCompile()
    event.register("numba:compiler_lock", listener)
    _state["listener"] = listener


def _compiling(compile_code) -> str | None:
    """``module:qualname`` of the kernel whose compile takes Numba's lock: the ``self`` of the
    ``Dispatcher.compile`` frame below the lock's event (Numba's event carries no name);
    None when there is none (then the command waits for every child, as it safely can)."""
    frame = sys._getframe(2)
    while frame is not None:
        if frame.f_code is compile_code:
            func = getattr(frame.f_locals.get("self"), "py_func", None)
            return None if func is None else f"{func.__module__}:{func.__qualname__}"
        frame = frame.f_back
    return None


def wait(kernel: str | None = None) -> None:
    """Block until the children have saved ``kernel`` (every recorded signature of it), or
    until every child has ended when ``kernel`` is None; at once when no child will save it.
    A Ctrl-C seen stops the children. When every child has ended, the mark is written if all
    of them compiled their share. Does nothing without children."""
    children = _state["children"]
    if not children:
        return
    should_stop = _state["should_stop"]
    wanted = None if kernel is None else set(_state["names"].get(kernel, ()))
    _state["used"] = True       # it compiles: the children's work is worth finishing
    finished = False
    try:
        if _pending(wanted) and not _state["told"] and _state["on_wait"] is not None:
            _state["told"] = True
            _state["on_wait"](len(children))
        while _pending(wanted):
            if should_stop is not None and should_stop():
                break
            time.sleep(POLL_S)
        else:
            finished = True
    finally:
        # Stopped (a Ctrl-C, an error raised while waiting) or every child has ended.
        if not finished or all(c.poll() is not None for c in children):
            stop()


def pending(kernel: str) -> bool:
    """Whether a child of this command is still to save ``kernel`` (``module:qualname``): a
    caller choosing by what is compiled (``exact``'s engine) waits for it with
    :func:`wait` instead of taking it for uncompiled."""
    return bool(_state["children"]) and _pending(set(_state["names"].get(kernel, ())))


def _pending(wanted: set | None) -> bool:
    """Whether a running child has still to report one of the entries ``wanted`` (None: any
    child still running)."""
    done = _state["done"]
    for child, share in zip(_state["children"], _state["shares"]):
        if child.poll() is None and (wanted is None or (share & wanted) - done):
            return True
    return False


def stop() -> None:
    """End the children and stop listening. A command that has waited for them (it compiles)
    and was not interrupted lets them finish their shares, as the first compile once waited
    for all of them; the mark is written when every child compiled its share. Otherwise (a
    command whose small work ran interpreted, a Ctrl-C) they are killed and no mark is
    written."""
    children, _state["children"] = _state["children"], []
    should_stop = _state["should_stop"]
    finish = _state["used"] and not (should_stop is not None and should_stop())
    try:
        for c in children:
            while finish and c.poll() is None:
                if should_stop is not None and should_stop():
                    finish = False
                    break
                time.sleep(POLL_S)
    finally:
        for c in children:      # unfinished, or a Ctrl-C while they finish: none left behind
            if c.poll() is None:
                c.kill()
            c.wait()
        listener, _state["listener"] = _state["listener"], None
        if listener is not None:
            from numba.core import event

            event.unregister("numba:compiler_lock", listener)
        for c in children:
            if c.stdout is not None:
                c.stdout.close()
    done = _state["done"]
    if children and all(c.returncode == 0 and share <= done
                        for c, share in zip(children, _state["shares"])):
        try:
            _state["mark"].touch()
        except (OSError, AttributeError):
            pass        # a read-only or full cache: the next run compiles in parallel again


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


def compile_share(entries: list[tuple[int, dict]], saved=None) -> None:
    """Compile (or load, when already cached) each ``(index, entry)``'s kernel for its
    recorded types and call ``saved(index)`` when it is in the cache. An entry that cannot be
    read or compiled any more (types of another Numba, a kernel renamed or given other
    parameters) is left to the command."""
    from numba.core.errors import NumbaError

    for index, entry in entries:
        try:
            types = entry_types(entry)
            dispatcher = _dispatcher(entry["kernel"])
            dispatcher.compile(tuple(types))
        except (ImportError, AttributeError, KeyError, ValueError, EOFError,
                pickle.UnpicklingError, NumbaError):
            pass        # a stale entry (renamed, other types): the command compiles it itself
        if saved is not None:   # saved (or never will be): a command waiting for it goes on
            saved(index)


def _report(index: int) -> None:
    """A child's line to its command (:func:`_read_reports`): an entry is saved."""
    sys.stdout.write(f"{index}\n")
    sys.stdout.flush()


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
    compile_share([(int(i), entries[int(i)]) for i in share.split(",") if i], _report)
    # Everything is saved and reported: the interpreter's teardown (the LLVM code of each
    # kernel) would only keep the command waiting at its end.
    os._exit(0)


if __name__ == "__main__":
    _main(sys.argv[1:])
