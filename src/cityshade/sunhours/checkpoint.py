"""Checkpoints and the manifest of a sun-hours run.

Sums are float64 and are added in a fixed order (the order of first occurrence of each sun
position), so a run that was interrupted and resumed from its saved state
(:class:`Checkpoint`) gives a result bit-identical to a straight run. The state is saved every
:data:`CHECKPOINT_EVERY_S` (:class:`SaveThrottle`); the manifest's progress is written every
:data:`MANIFEST_EVERY_S` (:class:`ManifestProgress`), both at the end and when a run stops.
"""
from __future__ import annotations

import hashlib
import io
import json
import time
import zipfile
from pathlib import Path
from typing import Any, Callable, Iterable

import numpy as np

from cityshade.errors import UsageError

__all__ = ["Checkpoint", "SaveThrottle", "ManifestProgress", "params_key", "read_manifest",
           "write_manifest", "open_state", "finished_outputs", "relative_output",
           "MANIFEST_NAME", "STATE_NAME", "CHECKPOINT_EVERY_S", "MANIFEST_EVERY_S"]

MANIFEST_NAME = "manifest.json"
STATE_NAME = "state.npz"
#: Seconds between two writes of the manifest's progress in a batch (plain or tiled).
MANIFEST_EVERY_S = 1.0

# --- the saved state ---------------------------------------------------------------------------------

#: Seconds between two saves of a batch's state (and at its end and when it stops).
CHECKPOINT_EVERY_S = 10.0


class Checkpoint:
    """Running sums of an unfinished run, saved atomically (see ``CHECKPOINT_EVERY_S``).

    Parameters
    ----------
    path : path-like
        The state file (``OUTDIR/state.npz``).
    key : str
        Hash of the run's parameters (:func:`params_key`); a state with another key is
        refused, so results of different runs never mix.
    """

    def __init__(self, path, key: str):
        self.path = Path(path)
        self.key = str(key)
        self.saves = 0
        self.save_s = 0.0
        self.sha256: str | None = None  # of the last state written, for the manifest
        # Called with the new state's checksum before it replaces the old one (run_batch records
        # both in the manifest, so an interruption between the two writes loses nothing).
        self.before_write: Callable[[str], None] | None = None
        # Further arrays of the run (the sunlit stretches, :mod:`cityshade.sunhours.stretches`), saved with
        # the sums under ``x_`` names and read back by :meth:`load`.
        self.extra: dict[str, np.ndarray] = {}

    def load(self, n_units: int, pixel_shape, n_samples: int):
        """``(units_done, pixel_sum, sample_sum)`` of a saved state, or None when there is none.

        Raises
        ------
        UsageError
            The state belongs to other parameters, does not fit this run, or is damaged.
        """
        z = self.load_arrays(("units_done", "pixel_sum", "sample_sum"))
        if z is None:
            return None
        done = int(z["units_done"])
        pixel_sum = z["pixel_sum"].astype(np.float64, copy=False)
        sample_sum = z["sample_sum"].astype(np.float64, copy=False)
        self.extra = {n[2:]: v for n, v in z.items() if n.startswith("x_")}
        shape = tuple(pixel_shape) if pixel_shape is not None else (0, 0)
        if pixel_sum.shape != shape or sample_sum.shape != (n_samples,) or not \
                0 <= done <= n_units:
            self.refuse_misfit()
        return done, pixel_sum, sample_sum

    #: What a refused state's message advises.
    HINT = "re-run with --overwrite to start afresh"

    def load_arrays(self, required: Iterable[str] = ()) -> dict[str, np.ndarray] | None:
        """Every array of the saved state (``required`` among them; ``key`` checked and left
        out), or None when there is none: the one reader of a run's state (a batch's, plain or
        tiled, and a sky run's, :mod:`cityshade.light.run`).

        Raises
        ------
        UsageError
            The state belongs to other parameters or is damaged.
        """
        if not self.path.exists():
            return None
        try:
            with np.load(self.path, allow_pickle=False) as z:
                key = str(z["key"])
                arrays = {n: np.array(z[n]) for n in z.files if n != "key"}
            missing = [n for n in required if n not in arrays]
            if missing:
                raise KeyError(f"no {missing[0]!r}")
        except (OSError, ValueError, KeyError, zipfile.BadZipFile) as exc:
            raise UsageError(f"the saved state {self.path} is damaged ({exc}); {self.HINT}") \
                from None
        if key != self.key:
            raise UsageError(f"the saved state {self.path} belongs to a run with other "
                             f"parameters; {self.HINT}")
        return arrays

    def refuse_misfit(self):
        """Raise the one message of a state whose arrays do not fit the run."""
        raise UsageError(f"the saved state {self.path} does not fit this run; {self.HINT}")

    def units_done(self) -> int:
        """Units recorded as done in the saved state (0 without a state or for another key)."""
        try:
            with np.load(self.path, allow_pickle=False) as z:
                return int(z["units_done"]) if str(z["key"]) == self.key else 0
        except (OSError, ValueError, KeyError, zipfile.BadZipFile):
            return 0

    def file_sha256(self) -> str | None:
        """SHA-256 of the state file as it is on disk (None without one)."""
        try:
            return hashlib.sha256(self.path.read_bytes()).hexdigest()
        except FileNotFoundError:
            return None

    def save(self, units_done: int, pixel_sum: np.ndarray, sample_sum: np.ndarray,
             extra: dict[str, np.ndarray] | None = None) -> None:
        """Write the state (and ``extra`` arrays) to a temporary name and rename it over the
        previous one."""
        self.save_arrays(units_done, pixel_sum=pixel_sum, sample_sum=sample_sum,
                         **{f"x_{k}": v for k, v in (extra or {}).items()})

    def save_arrays(self, units_done: int, **arrays: np.ndarray) -> None:
        """:meth:`save` with other arrays (a tiled run's, :mod:`cityshade.sunhours.tiled`)."""
        from cityshade.util import atomic_write

        t0 = time.perf_counter()
        buf = io.BytesIO()
        np.savez(buf, key=np.array(self.key), units_done=np.array(units_done), **arrays)
        data = buf.getvalue()
        digest = hashlib.sha256(data).hexdigest()
        if self.before_write is not None:
            self.before_write(digest)
        with atomic_write(self.path, "wb", what="the batch state") as fh:
            fh.write(data)
        self.sha256 = digest
        self.saves += 1
        self.save_s += time.perf_counter() - t0

    def remove(self) -> None:
        self.path.unlink(missing_ok=True)


class SaveThrottle:
    """When a run saves its state: every :data:`CHECKPOINT_EVERY_S` seconds, after the last
    sun position, and when the run stops (Ctrl-C, an error) with consistent sums. Saving after
    every position cost more than the shadows once the sunlit stretches joined the state
    (2.1 M px: 54 s of 302 s on the 1M city).

    Parameters
    ----------
    save : callable()
        Writes the state (None: a run without checkpoint).
    timings : dict
        Its ``checkpoint_s`` adds the time spent saving.
    """

    def __init__(self, save: Callable[[], None] | None, timings: dict[str, float],
                 every_s: float | None = None):
        self._save = save
        self.timings = timings
        self.every_s = float(CHECKPOINT_EVERY_S if every_s is None else every_s)
        self.last_s = time.perf_counter()
        #: False while a sun position is half added: a stop then saves nothing.
        self.consistent = True

    def save(self) -> None:
        if self._save is None:
            return
        t0 = time.perf_counter()
        self._save()
        self.last_s = time.perf_counter()
        self.timings["checkpoint_s"] += self.last_s - t0

    def maybe(self, last: bool = False) -> bool:
        """Save when ``last`` or when the interval has passed; True when it saved."""
        if self._save is not None and (last or
                                       time.perf_counter() - self.last_s >= self.every_s):
            self.save()
            return True
        return False


def params_key(params: dict[str, Any]) -> str:
    """SHA-256 of the parameters as canonical JSON."""
    text = json.dumps(params, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def read_manifest(outdir) -> dict[str, Any] | None:
    """The manifest of OUTDIR, or None when there is none."""
    path = Path(outdir) / MANIFEST_NAME
    if not path.exists():
        return None
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise UsageError(f"{path} cannot be read ({exc}); re-run with --overwrite") from None


def write_manifest(outdir, manifest: dict[str, Any]) -> Path:
    """Write ``OUTDIR/manifest.json`` atomically."""
    from cityshade.util import write_text_atomic

    return write_text_atomic(Path(outdir) / MANIFEST_NAME,
                             json.dumps(manifest, indent=2, sort_keys=True) + "\n",
                             what="the manifest")


def relative_output(path, outdir) -> str:
    """``path`` as a manifest names it: relative to the run's folder."""
    try:
        return Path(path).relative_to(outdir).as_posix()
    except ValueError:
        return Path(path).name


def open_state(outdir, params: dict[str, Any], overwrite: bool
               ) -> tuple[Checkpoint, str | None]:
    """(checkpoint, warning or None): the saved state of ``outdir`` when it belongs to these
    parameters and its checksum matches the manifest; a run's resume rule (a batch's and a sky
    run's).

    Raises
    ------
    UsageError
        ``outdir`` holds a run of other parameters (the message names what differs) or a state
        without manifest, and not ``overwrite`` (which discards them).
    """
    outdir = Path(outdir)
    key = params_key(params)
    old = read_manifest(outdir)
    state = Checkpoint(outdir / STATE_NAME, key)
    if old is not None and old.get("key") != key:
        if not overwrite:
            before = old.get("params", {})
            changed = sorted(k for k in set(params) | set(before) if params.get(k) != before.get(k))
            raise UsageError(f"{outdir} holds a run with other parameters (differs in: "
                             f"{', '.join(changed) or 'version'}); use --overwrite or another "
                             f"-o folder")
        state.remove()
    elif old is None and state.path.exists():
        if not overwrite:
            raise UsageError(f"{state.path} has no manifest next to it; use --overwrite")
        state.remove()
    warning = None
    if old is not None and state.path.exists():
        # The manifest holds the checksum of the last state saved: a truncated or altered state
        # is discarded and its work is done again, never half-read.
        found = state.file_sha256()
        if found not in (old.get("state_sha256") or []):
            warning = (f"the saved state {state.path} is damaged (its checksum does not "
                       f"match the manifest); the unfinished steps start again")
            state.remove()
        else:
            state.sha256 = found
    return state, warning


def finished_outputs(outdir, params: dict[str, Any], version: str, overwrite: bool,
                     folders: Iterable[str] = ()) -> tuple[list[Path], dict[str, Any]] | None:
    """(outputs, manifest) of the run ``outdir`` already holds when it finished with the same
    request identity (:func:`params_key`) and ``version`` and its outputs (listed in the
    manifest's summary, relative to the folder) and ``folders`` are all there; None otherwise
    (``overwrite`` computes it again). A run of other parameters is left to
    :func:`open_state`, which refuses it."""
    if overwrite:
        return None
    outdir = Path(outdir)
    old = read_manifest(outdir)
    if old is None or old.get("status") != "finished" or old.get("key") != params_key(params) \
            or old.get("cityshade_version") != version:
        return None
    written = [outdir / name for name in (old.get("summary") or {}).get("outputs") or []]
    if not written or not all(p.is_file() for p in written) or \
            not all((outdir / f).is_dir() for f in folders):
        return None
    return written, old


class ManifestProgress:
    """The manifest of a run in progress: the finished steps and sun positions (and tasks of a
    tiled run), written every :data:`MANIFEST_EVERY_S`, with every state save (the new state's
    checksum first, so an interruption between the two writes loses nothing), at the end and
    when the run stops. The indented JSON of a day's steps costs 25-30 ms (a year's far more),
    and a resume reads the state, not this progress.

    Parameters
    ----------
    outdir : path-like
    manifest : dict
        Updated in place.
    checkpoint : Checkpoint
        Its :attr:`Checkpoint.before_write` is set to record each new state.
    finished : list of int
        Steps finished so far (sun down, resumed); extended as positions finish.
    """

    def __init__(self, outdir, manifest: dict[str, Any], checkpoint: Checkpoint,
                 finished: list[int]):
        self.outdir = Path(outdir)
        self.manifest = manifest
        self.checkpoint = checkpoint
        self.finished = finished
        self.positions_done: int | None = None
        self.written_s = time.perf_counter()
        checkpoint.before_write = self._before_state_write

    def _note(self) -> None:
        if self.positions_done is not None:
            self.manifest["finished_steps"] = sorted(self.finished)
            self.manifest["sun_positions_done"] = self.positions_done

    def write(self, state_sha256: list[str] | None = None) -> None:
        """Write the manifest now, with the progress so far."""
        self._note()
        if state_sha256 is not None:
            self.manifest["state_sha256"] = state_sha256
        elif self.checkpoint.sha256 is not None:
            self.manifest["state_sha256"] = [self.checkpoint.sha256]
        write_manifest(self.outdir, self.manifest)
        self.written_s = time.perf_counter()

    def _before_state_write(self, digest: str) -> None:
        self.write([h for h in (self.checkpoint.sha256, digest) if h is not None])

    def advance(self, done: int, total: int, steps: Iterable[int],
                positions_done: int | None, tasks: bool = False) -> None:
        """``done`` of ``total`` units of work (sun positions, or tasks when ``tasks``) are
        added; ``steps`` are the steps that finished with them and ``positions_done`` the sun
        positions now complete (None: unchanged)."""
        self.finished.extend(steps)
        if positions_done is not None:
            self.positions_done = positions_done
        if tasks:
            self._note()
            self.manifest["tasks_done"] = done
            self.manifest["tasks_total"] = total
        if done == total or time.perf_counter() - self.written_s >= MANIFEST_EVERY_S:
            self.write()
