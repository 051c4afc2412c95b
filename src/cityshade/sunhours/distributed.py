"""The Dask executor of tiled batches: ``cityshade batch … --tile-px N --scheduler local:N``.

:func:`cityshade.sunhours.tiled.run_tiled` hands the tasks (:mod:`cityshade.sunhours.tiled`) to a
:class:`DaskExecutor` when a scheduler is given.

A Dask run ships no scene: the driver writes the receivers once to ``OUTDIR/receivers.npy``
and every worker memory-maps that file and the scene's cache file from their paths (on a
cluster of several machines both must lie on a file system all of them see, under the same
path). Workers keep what they opened for the tasks that follow. Results come back as packed
bits and are added in sun-position order per tile (:func:`cityshade.sunhours.tiled.accumulate`), so the
numbers are bit-identical to a run without Dask; a task lost with a worker is run again by Dask,
and a run stopped part-way resumes from its saved state with only the missing tasks.

``dask[distributed]`` is the optional ``[dask]`` extra, imported only here.
"""
from __future__ import annotations

import contextlib
import os
import threading
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from cityshade.errors import DistributedError, UsageError

__all__ = ["DaskExecutor", "DistributedError", "parse_scheduler"]


#: Environment of a local worker process (replaces Dask's ``pre-spawn-environ``).
WORKER_ENVIRON = {"OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}


def parse_scheduler(spec: str) -> tuple[str, int | str]:
    """``("local", workers)`` for ``local`` / ``local:N``, ``("address", spec)`` for
    ``tcp://HOST:PORT`` (or another Dask address such as ``tls://``)."""
    text = str(spec).strip()
    if text == "local" or text.startswith("local:"):
        count = text[6:] if text.startswith("local:") else ""
        if count == "":
            return "local", max(1, os.cpu_count() or 1)
        if not count.isdigit() or int(count) < 1:
            raise UsageError(f"--scheduler local:N needs a number of workers >= 1, not {count!r}")
        return "local", int(count)
    if "://" in text and text.split("://", 1)[1]:
        return "address", text
    raise UsageError(f"--scheduler is local, local:N or tcp://HOST:PORT, not {spec!r}")


def _restore_environ(saved: dict[str, str]) -> None:
    for key in [k for k in os.environ if k not in saved]:
        del os.environ[key]
    os.environ.update(saved)


# --- worker side ------------------------------------------------------------------------------

#: What a worker process has opened: {(path, size, mtime_ns): object}.
_OPENED: dict[tuple, Any] = {}


def _opened(path: str, loader):
    st = os.stat(path)
    key = (path, st.st_size, st.st_mtime_ns)
    obj = _OPENED.get(key)
    if obj is None:
        for old in [k for k in _OPENED if k[0] == path]:
            del _OPENED[old]
        obj = _OPENED[key] = loader(path)
    return obj


def _worker_task(scene_path: str, scene_sha: str, receivers_path: str, lo: int, hi: int,
                 fn: Callable, args: tuple):
    """One task on a worker: memory-map the scene and receivers (once per process) and return
    ``fn(scene, receivers, lo, hi, *args)`` (a batch's packed lit bits,
    :func:`cityshade.sunhours.tiled.task_lit`; a sky tile's values,
    :func:`cityshade.light.run.sky_tile`)."""
    from cityshade.store.scenefile import load_scene

    # The driver verified the cache file; a worker checks it is the same file.
    scene = _opened(scene_path, lambda p: load_scene(p, verify=False))
    found = (scene.header or {}).get("source", {}).get("sha256", "")
    if found != scene_sha:
        raise DistributedError(f"the worker's {scene_path} is another scene than the driver's; "
                               f"give every worker the same cache file")
    data = _opened(receivers_path, lambda p: np.load(p, mmap_mode="r"))
    return fn(scene, data, lo, hi, *args)


def _warm_worker(scene_path: str, scene_sha: str, direction, t_days: float,
                 engine: str) -> None:
    """Run on every worker as it joins (:meth:`DaskExecutor.start`): import the engine, map
    the scene, load the Numba kernels and sort the casters for the first sun, so that the
    first task costs what the others do (a cold worker: about 2 s of CPU)."""
    from cityshade.store.scenefile import load_scene
    from cityshade.sunhours.tiled import task_lit

    scene = _opened(scene_path, lambda p: load_scene(p, verify=False))
    if (scene.header or {}).get("source", {}).get("sha256", "") != scene_sha:
        return  # the first task says so in its own words
    # A sky run gives no sun: the scene mapped is the warm-up (its kernels load per tile).
    kd = scene.kdtree
    if direction is None or kd is None:
        return
    lo, hi = kd.box_scale_m()[:2]
    top = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, hi[2], 0.0, 0.0, 1.0]
    task_lit(scene, np.array([top]), 0, 1, np.array([direction], np.float64), t_days, engine)


# --- driver side ------------------------------------------------------------------------------

def _stop_local_workers(cluster) -> None:
    """End a LocalCluster's worker processes at once, before ``cluster.close()``.

    The results are in by then (or the run has failed) and a worker holds nothing to save,
    whereas Dask's own close retires each worker gracefully: 0.7 s (1 worker) and 1.7 s
    (2 workers) of wall time at the end of the 1M city's day here, more under load. Each
    nanny is told first that its worker's exit is no failure, so that it does not restart
    it; ``cluster.close()`` then joins the processes (their CPU stays counted)."""
    import signal

    for nanny in list(getattr(cluster, "workers", {}).values()):
        pid = getattr(nanny, "pid", None)
        graceful = getattr(nanny, "close_gracefully", None)
        if not pid or graceful is None:
            continue
        graceful()
        with contextlib.suppress(OSError):  # it has gone already
            os.kill(pid, signal.SIGKILL)


class DaskExecutor:
    """Runs tasks on a Dask cluster: a LocalCluster of N worker processes or an existing one.

    Parameters
    ----------
    scheduler : str
        ``local[:N]`` or an address (``tcp://HOST:8786``).
    scene_path : path-like
        The cache file every worker memory-maps.
    scene_sha : str
        Source checksum of the scene in the cache header (a worker refuses another file).
    threads_per_worker : int, optional
        Numba threads of each local worker (default: the cores shared out among the workers).
    """

    def __init__(self, scheduler: str, scene_path, scene_sha: str,
                 threads_per_worker: int | None = None, driver_tasks: bool = True):
        self.spec = str(scheduler)
        self.kind, self.target = parse_scheduler(scheduler)
        self.scene_path = str(Path(scene_path).resolve())
        self.scene_sha = scene_sha
        self.threads = threads_per_worker
        #: While a local cluster starts, the driver runs the first tasks itself.
        self.driver_tasks = bool(driver_tasks)
        self.tasks_on_driver = 0
        self.workers = 0
        self.client = self.cluster = None
        self._environ: dict[str, str] = {}
        self._starting: threading.Thread | None = None
        self._start_error: BaseException | None = None
        self._scene = None
        self._closing = False
        self.ready = threading.Event()

    def connect(self) -> None:
        """Start the LocalCluster or reach the scheduler (before any work, so that an
        unreachable cluster fails at once)."""
        if self.client is None:
            self.client, self.cluster = self._client()
            self.workers = len(self.client.scheduler_info().get("workers", {}))

    def start(self, scene=None, direction=None, t_days: float = 0.0,
              engine: str = "izb") -> None:
        """Connect, and warm every worker up for ``direction`` (:func:`_warm_worker`). A local
        cluster starts in the background: its worker processes take seconds to import and
        load, which the driver spends on its own work and, with ``scene``, on the first tasks
        (:meth:`run`). An address is reached at once, so that a wrong one fails at once."""
        if self.client is not None or self._starting is not None:
            return
        self._scene = scene
        self.ready.clear()

        def up():
            try:
                self.connect()
                if self._closing:  # the driver ran every task: no worker needs warming
                    return
                self.client.run(_warm_worker, self.scene_path, self.scene_sha,
                                None if direction is None else [float(v) for v in direction],
                                float(t_days), engine)
            except Exception as exc:  # raised in the driver's thread by _started()
                self._start_error = exc
            finally:
                self.ready.set()

        if self.kind != "local":
            up()
            self._started()
            return
        self._starting = threading.Thread(target=up, name="cityshade-dask-start", daemon=True)
        self._starting.start()

    def _started(self) -> None:
        """Wait for :meth:`start` and raise what it met."""
        if self._starting is not None:
            self._starting.join()
            self._starting = None
        error, self._start_error = self._start_error, None
        if error is not None:
            raise error
        self.connect()

    def close(self) -> None:
        self._closing = True
        if self._starting is not None:
            self._starting.join()
            self._starting = None
        self._closing = False
        self._start_error = None
        client, cluster, self.client, self.cluster = self.client, self.cluster, None, None
        if client is not None:
            client.close()
        if cluster is not None:
            _stop_local_workers(cluster)
            cluster.close()
            _restore_environ(self._environ)

    def _client(self):
        try:
            import dask
            from dask.distributed import Client, LocalCluster
        except ImportError:
            raise UsageError("--scheduler needs Dask: pip install 'cityshade[dask]'") from None
        import logging

        if self.kind == "local":
            n = int(self.target)
            threads = self.threads or max(1, (os.cpu_count() or 1) // n)
            # Workers are processes; each gets its share of the cores for Numba's threads.
            # Dask's default environment also sets MALLOC_TRIM_THRESHOLD_=64 KiB, which makes
            # glibc map and zero every large temporary afresh: the light-space engine's tasks
            # ran 1.3-1.8x slower in a worker than in the driver with it.
            # The nanny writes the pre-spawn environment into this process's os.environ before
            # each spawn (a killed worker's restart too) and leaves it there, and a variable
            # this process has wins over it; so Numba's thread count goes in ``env``, set in
            # the worker process only and over what it inherits (a NUMBA_NUM_THREADS changed
            # here would make this process's next compile fail).
            self._environ = dict(os.environ)
            try:
                with dask.config.set({"distributed.nanny.pre-spawn-environ": WORKER_ENVIRON}):
                    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                           dashboard_address=None, silence_logs=logging.ERROR,
                                           env={"NUMBA_NUM_THREADS": str(threads)},
                                           # No dashboard; the scheduler's HTTP routes on a
                                           # free port, not 8787 (taken by another cluster)
                                           scheduler_kwargs={"dashboard_address": ":0"})
            finally:
                _restore_environ(self._environ)
            return Client(cluster), cluster
        try:
            client = Client(self.target, timeout="20s")
        except (OSError, TimeoutError) as exc:
            raise DistributedError(f"cannot reach the Dask scheduler at {self.target} "
                                   f"({exc}); start it with `dask scheduler`") from None
        return client, None

    def run(self, plan, tasks: Sequence[tuple[int, int, int]], directions: np.ndarray,
            t_days: float, engine: str, workdir, finished: Callable) -> None:
        """A batch's ``tasks`` (tile, first, end sun position): ``finished(tile, first, bits)``
        for each as it comes back (:func:`cityshade.sunhours.tiled.task_lit`)."""
        from cityshade.sunhours.tiled import task_lit

        self.run_tasks(plan, task_lit, [
            (t, (t, lo), (np.ascontiguousarray(directions[lo:hi]), t_days, engine))
            for t, lo, hi in tasks], workdir, lambda key, out: finished(*key, out),
            lambda key: f"tile{key[0]}-sun{key[1]}")

    def run_tasks(self, plan, fn: Callable, tasks: Sequence[tuple[int, Any, tuple]],
                  workdir, finished: Callable, name: Callable = str) -> None:
        """Run ``fn(scene, plan.data, lo, hi, *args)`` for each task ``(tile, key, args)``
        (``lo:hi`` the tile's receivers) and call ``finished(key, result)`` as each comes back.
        ``fn`` is a module-level function (workers import it by name); the receivers go to
        ``workdir/receivers.npy`` for the workers to memory-map; ``name(key)`` names the
        task in Dask (``cityshade-NAME-...``)."""
        from cityshade.util import atomic_path

        if not tasks:
            return
        recv = Path(workdir) / "receivers.npy"
        with atomic_path(recv, keep_suffix=True, what="the receivers") as tmp:
            np.save(tmp, plan.data)
        try:
            first = 0
            if self.driver_tasks and self._scene is not None and self._starting is not None:
                # The cluster is still starting: run tasks here, in order, meanwhile.
                while first < len(tasks) and not self.ready.is_set():
                    t, key, args = tasks[first]
                    a, b = int(plan.start[t]), int(plan.start[t + 1])
                    finished(key, fn(self._scene, plan.data, a, b, *args))
                    first += 1
                self.tasks_on_driver = first
                if first == len(tasks):
                    return
            self._started()
            client = self.client
            from dask.distributed import as_completed
            from distributed.scheduler import KilledWorker

            futures = {}
            for t, key, args in tasks[first:]:
                a, b = int(plan.start[t]), int(plan.start[t + 1])
                fut = client.submit(_worker_task, self.scene_path, self.scene_sha,
                                    str(recv.resolve()), a, b, fn, args, pure=False,
                                    key=f"cityshade-{name(key)}-{os.getpid()}-{id(self)}")
                futures[fut] = key
            try:
                for fut in as_completed(futures):
                    key = futures.pop(fut)
                    out = fut.result()
                    # Let go of the result before adding it: a worker lost from here on does
                    # not make Dask compute it again.
                    fut.release()
                    finished(key, out)
            except KilledWorker as exc:
                raise DistributedError(f"Dask workers died while running a task ({exc}); "
                                       f"the finished tasks are saved, run the command "
                                       f"again to continue") from None
            finally:
                for fut in futures:
                    fut.cancel()
        finally:
            self.close()
            recv.unlink(missing_ok=True)
