"""Small helpers every writer and reader shares: atomic writes and the one TOML reader.

A leaf module (docs/DESIGN.md §17): it imports nothing of cityshade but :mod:`cityshade.errors`.
"""
from __future__ import annotations

import contextlib
import math
import os
import tomllib
import uuid
from pathlib import Path
from typing import IO, Any, Iterator

from cityshade.errors import CityshadeError, ConfigError, OutputError, UsageError

#: The open output groups (:func:`output_group`), innermost last: destination → temporary file.
_GROUPS: list[dict[Path, Path]] = []


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike, *, keep_suffix: bool = False,
                error: type[CityshadeError] = OutputError, what: str = "file") -> Iterator[Path]:
    """A unique temporary path next to ``path``, renamed over ``path`` when the block ends.

    The temporary file lives in the destination's folder (same file system, so the rename is
    atomic) under a unique name (so concurrent writers never share one; not ``mkstemp``, so
    the file gets the usual umask permissions). Any exception in the block, Ctrl-C included,
    removes it and leaves ``path`` as it was: an interrupted run never leaves a half file.
    Inside an :func:`output_group` the rename waits for the end of the group.

    Parameters
    ----------
    path : path-like
        The destination.
    keep_suffix : bool
        End the temporary name with the destination's suffix (OpenImageIO picks the format
        from it).
    error : CityshadeError subclass
        Raised (with ``path``) when the folder is missing or the rename fails.
    what : str
        What is written, for the message ("cannot write the manifest: ...").
    """
    path = Path(path)
    if not path.parent.is_dir():
        raise error(f"cannot write {what}: folder {path.parent} does not exist", path=str(path))
    tail = path.suffix.lower() if keep_suffix else ""
    tmp = path.parent / f".{path.name}.{os.getpid()}.{uuid.uuid4().hex}.tmp{tail}"
    try:
        yield tmp
        if _GROUPS:
            older = _GROUPS[-1].pop(path, None)
            _GROUPS[-1][path] = tmp
            _discard([older])
            tmp = None  # the group owns it now
        else:
            _replace(tmp, path, error, what)
    finally:
        _discard([tmp])


def _replace(tmp: Path, path: Path, error: type[CityshadeError], what: str) -> None:
    try:
        os.replace(tmp, path)
    except OSError as exc:
        raise error(f"cannot write {what}: {exc.strerror or exc}", path=str(path)) from None


def _discard(paths) -> None:
    for p in paths:
        if p is not None:
            with contextlib.suppress(OSError):
                p.unlink()


def pending_path(path: str | os.PathLike) -> Path:
    """Where the bytes of ``path`` are now: inside an :func:`output_group` a file written in the
    group stays under its temporary name until the group ends, so a writer that reads an
    earlier output of the same group (a report embedding its pictures) reads it there."""
    path = Path(path)
    for group in reversed(_GROUPS):
        if path in group:
            return group[path]
    return path


@contextlib.contextmanager
def output_group(error: type[CityshadeError] = OutputError) -> Iterator[None]:
    """All of a command's outputs at once, or none of them.

    Every file written through :func:`atomic_path` inside the block (so every writer of
    cityshade: images, EXR, GeoTIFF and its side files, CSV, Markdown) stays under its
    temporary name until the block ends; then they are renamed together, with Ctrl-C held off
    until the last rename. An exception in the block (a failing writer, Ctrl-C) removes every
    temporary file: no output of the command appears. A group inside a group joins the outer.
    """
    pending: dict[Path, Path] = {}
    _GROUPS.append(pending)
    try:
        yield
    except BaseException:
        _GROUPS.pop()
        _discard(pending.values())
        raise
    _GROUPS.pop()
    if _GROUPS:
        _GROUPS[-1].update(pending)
        return
    placed: list[Path] = []
    try:
        with interrupts_held():
            for path, tmp in list(pending.items()):
                _replace(tmp, path, error, "the outputs")
                placed.append(path)
                del pending[path]
    except BaseException:
        # A rename failed (or was refused): take back the ones already made, so that the
        # outputs of this command never appear in part.
        _discard(placed)
        _discard(pending.values())
        raise


@contextlib.contextmanager
def interrupts_held() -> Iterator[None]:
    """Hold a Ctrl-C (SIGINT) that arrives inside the block and deliver it to the handler
    that was installed before, once the block has ended. Only in the main thread (the only
    one that runs Python signal handlers); elsewhere the block runs as it is."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    held: list[int] = []
    before = signal.signal(signal.SIGINT, lambda signum, frame: held.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, before)
        if held and callable(before):
            before(signal.SIGINT, None)
        elif held and before == signal.SIG_DFL:
            raise KeyboardInterrupt


def check_outputs(*outputs: tuple[str, str | os.PathLike | None, tuple[str, ...] | None]
                  ) -> list[Path]:
    """Check the outputs of a command before any work; returns their paths.

    Each output is ``(option, path, suffixes)``: a file that must end in one of ``suffixes``,
    or, with ``suffixes`` None, an output folder; a path of None was not asked for. A file
    must not be a folder, a folder not a file; no two outputs may be the same path; every
    folder is created when missing (as ``build`` does) and must be writable. The messages name
    the option and the path.

    Raises
    ------
    UsageError
        A wrong extension, or two outputs on one path.
    OutputError
        A folder that cannot be created or written, or a path of the wrong kind.
    """
    taken: dict[Path, str] = {}
    checked: list[Path] = []
    for option, path, suffixes in outputs:
        if path is None:
            continue
        path = Path(path)
        if suffixes is not None and path.suffix.lower() not in suffixes:
            raise UsageError(f"{option} {path}: the file name must end in "
                             f"{' or '.join(suffixes)}, not {path.suffix or '(nothing)'!r}")
        resolved = path.resolve()
        if resolved in taken:
            raise UsageError(f"{option} and {taken[resolved]} would both write {path}")
        taken[resolved] = option
        if suffixes is not None and path.is_dir():
            raise OutputError(f"{option} {path} is a folder, not a file name")
        existing = next(a for a in (path, *path.parents) if a.exists())
        if not existing.is_dir() and existing != path:
            raise OutputError(f"{option} {path}: {existing} is a file, not a folder")
        if suffixes is None and path.exists() and not path.is_dir():
            raise OutputError(f"{option} {path} is a file, not a folder")
        folder = make_folder(path if suffixes is None else path.parent)
        problem = _cannot_write_in(folder)
        if problem:
            raise OutputError(f"{option} {path}: cannot write in the folder {folder} "
                              f"({problem})")
        checked.append(path)
    return checked


def _cannot_write_in(folder: Path) -> str | None:
    """Why no file can be created in ``folder`` (None when one can): a real file is made and
    removed, since the permission bits say yes to root and to folders such as /proc."""
    probe = folder / f".cityshade-probe.{os.getpid()}.{uuid.uuid4().hex}"
    fd = None
    try:
        fd = os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except OSError as exc:
        return exc.strerror or str(exc)
    finally:
        # Also when a Ctrl-C lands right after the open (a build interrupted at 0.3 s left
        # the probe behind once): the name is this call's own.
        if fd is not None:
            os.close(fd)
        with contextlib.suppress(OSError):
            os.unlink(probe)
    return None


#: The lock file of an output folder in use (:func:`folder_lock`).
LOCK_NAME = ".cityshade.lock"


def _pid_alive(pid: int) -> bool:
    """Whether a process ``pid`` runs on this machine (one of another user's counts)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except (OSError, OverflowError):
        return False
    return True


@contextlib.contextmanager
def folder_lock(folder: str | os.PathLike, on_note=None) -> Iterator[Path]:
    """Hold ``folder/.cityshade.lock`` (created with O_EXCL, holding this process's id) while
    the block runs, so that two commands never write one output folder at once. A lock left by
    a process that no longer runs is taken over, ``on_note(text)`` told so.

    Raises
    ------
    UsageError
        A live process holds the lock.
    """
    path = Path(folder) / LOCK_NAME
    for _attempt in range(3):
        try:
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        except FileExistsError:
            try:
                text = path.read_text(encoding="ascii").strip()
            except (OSError, UnicodeDecodeError):
                text = ""
            pid = int(text) if text.isdigit() else None
            if pid is not None and pid != os.getpid() and _pid_alive(pid):
                raise UsageError(f"{folder} is in use by another cityshade run (process "
                                 f"{pid}); wait for it to end or choose another -o folder")
            with contextlib.suppress(FileNotFoundError):
                path.unlink()
            if on_note is not None:
                who = f"process {pid}" if pid is not None else "a process"
                on_note(f"took over the lock {path} of {who}, which has ended")
            continue
        except OSError as exc:
            raise OutputError(f"cannot create the lock file: {exc.strerror}",
                              path=str(path)) from None
        break
    else:
        raise UsageError(f"{folder} is in use by another cityshade run ({path})")
    try:
        with os.fdopen(fd, "w", encoding="ascii") as fh:
            fh.write(f"{os.getpid()}\n")
        yield path
    finally:
        with contextlib.suppress(OSError):
            path.unlink()


def plural(count: int, noun: str, nouns: str | None = None) -> str:
    """``1 object``, ``2 objects``, ``1,386 triangles``: a count with its noun in agreement
    (``nouns`` for an irregular plural, e.g. ``plural(n, "vertex", "vertices")``)."""
    word = noun if count == 1 else (nouns or f"{noun}s")
    return f"{count:,} {word}"


@contextlib.contextmanager
def atomic_write(path: str | os.PathLike, mode: str = "w", *, encoding: str | None = "utf-8",
                 newline: str | None = None, fsync: bool = False, buffering: int = -1,
                 error: type[CityshadeError] = OutputError, what: str = "file"
                 ) -> Iterator[IO[Any]]:
    """An open file whose content replaces ``path`` only when the block ends without error.

    ``mode`` is "w" (text, ``encoding`` and ``newline`` apply) or "wb". ``fsync`` flushes the
    data to disk before the rename (the cache file: a crash never leaves a renamed but empty
    file); ``buffering`` is :func:`open`'s. An :class:`OSError` while writing becomes ``error`` naming ``path``.
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"atomic_write mode must be 'w' or 'wb', not {mode!r}")
    with atomic_path(path, error=error, what=what) as tmp:
        try:
            kwargs = {} if mode == "wb" else {"encoding": encoding, "newline": newline}
            with open(tmp, mode, buffering=buffering, **kwargs) as fh:
                yield fh
                if fsync:
                    fh.flush()
                    os.fsync(fh.fileno())
        except OSError as exc:
            raise error(f"cannot write {what}: {exc.strerror or exc}", path=str(path)) from None


def write_text_atomic(path: str | os.PathLike, text: str, *, encoding: str = "utf-8",
                      error: type[CityshadeError] = OutputError, what: str = "file") -> Path:
    """Write ``text`` to ``path`` atomically (:func:`atomic_write`); returns the path."""
    with atomic_write(path, encoding=encoding, newline="\n", error=error, what=what) as fh:
        fh.write(text)
    return Path(path)


def check_t_days(t_days, error: type[CityshadeError] = UsageError) -> float:
    """``t_days`` (city time, days since 1970-01-01 UTC) as a float; a NaN date is ``error``."""
    t = float(t_days)
    if math.isnan(t):
        raise error("t_days must be a number of days since 1970-01-01, not NaN")
    return t


#: Every folder :func:`make_folder` created, outermost first (:func:`folders_made`).
_MADE: list[Path] = []


def make_folder(path: str | os.PathLike, what: str = "output folder") -> Path:
    """Create ``path`` (and its parents) if needed; an :class:`OutputError` naming it when
    that is impossible. The folders it creates are recorded (:func:`remove_folders_made`)."""
    path = Path(path)
    missing = []
    for folder in (path, *path.parents):
        if folder.exists():
            break
        missing.append(folder)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the {what}: {exc.strerror}", path=str(path)) from None
    _MADE.extend(reversed(missing))
    return path


def folders_made() -> int:
    """A mark for :func:`remove_folders_made`: how many folders were created until now."""
    return len(_MADE)


def remove_folders_made(since: int) -> None:
    """Remove the folders :func:`make_folder` created after the mark ``since`` that are still
    empty, innermost first: a failed command leaves none of the folders it made (a folder with
    something in it, e.g. the saved state of an interrupted batch, stays)."""
    for folder in reversed(_MADE[since:]):
        with contextlib.suppress(OSError):
            folder.rmdir()
    del _MADE[since:]


def read_toml(path: str | os.PathLike, what: str = "config") -> dict[str, Any]:
    """The parsed TOML document at ``path``; unreadable or invalid files are a
    :class:`~cityshade.errors.ConfigError` naming the file (and the line for syntax errors)."""
    path = Path(path)
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except OSError as exc:
        raise ConfigError(f"cannot read {what}: {exc.strerror}", path=str(path)) from None
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"invalid TOML: {exc}", path=str(path)) from None
