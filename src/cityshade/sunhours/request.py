"""The typed request of a sun-hours run: what to compute, where, when, with which technique,
what to write and how to run it. Built once (by ``cityshade batch``, ``compare`` or a Python
caller) and passed unchanged through :func:`cityshade.sunhours.run.run_batch`, the tiled and
Dask drivers and the accumulation; its checks live here, once each."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping, Sequence

from cityshade.errors import UsageError

__all__ = ["SunHoursRequest", "DEFAULT_BLOCK", "check_execution", "check_scene", "exact_engine"]

#: Sun positions per task by default: enough work per task (tens of ms each) that the
#: scheduling cost of a distributed run stays small, few enough for a steady progress bar.
DEFAULT_BLOCK = 8


def exact_engine(technique: str, what: str) -> str:
    """The engine of an exact technique (``describe(technique).exact``); else a
    :class:`UsageError` saying that ``what`` needs one."""
    from cityshade.shadows import describe, exact_technique_names

    spec = describe(technique)
    if not spec.exact:
        raise UsageError(f"{what} need an exact technique "
                         f"({', '.join(sorted(exact_technique_names()))}), not {technique!r}")
    return spec.engine


def check_execution(technique: str, tile_px: int | None, scheduler, monthly: bool,
                    frames: bool) -> None:
    """The execution knobs agree: a tile size >= 1, a scheduler that parses, and a tiled,
    distributed or monthly run of an exact technique without frames (the map techniques fit
    their maps to the receivers, so tiles would change the answer)."""
    if tile_px is not None and int(tile_px) < 1:
        raise UsageError(f"--tile-px must be >= 1, not {tile_px}")
    if isinstance(scheduler, str):
        from cityshade.sunhours.distributed import parse_scheduler

        parse_scheduler(scheduler)
    if tile_px is not None or scheduler is not None or monthly:
        if frames:
            raise UsageError("--frames cannot be combined with --tile-px, --scheduler or "
                             "--monthly; run the frames without them")
        exact_engine(technique, "--tile-px, --scheduler and --monthly")


def check_scene(scene) -> None:
    """A scene whose shadow rays can be traced: with a kd-tree or a tiled cache's view."""
    if not scene.can_trace:
        raise UsageError("the scene file has no kd-tree; rebuild it with `cityshade build`")


@dataclass(frozen=True)
class SunHoursRequest:
    """One sun-hours run.

    When
        ``instants_utc`` (aware datetimes, the steps' centres), ``weights_h`` (hours each
        stands for; None: their even spacing), ``t_days`` (the city's state, days since
        1970-01-01 UTC, for all steps), ``suns`` (precomputed, one per instant) or ``spa``
        (:class:`cityshade.geo.sun.SpaSettings`), ``steps`` (the :class:`Step` plan behind the
        instants, for the manifest, the frames and the sunlit stretches of a batch) and
        ``step_month`` (a YYYY-MM label per step: also sum per month).
    Where
        ``camera`` (the map's view; None: surfaces only), ``samples_per_m2`` (per-surface
        sun-hours at this density) or ``samples`` (ready surface samples, the same in two
        runs).
    Which technique
        ``technique`` (a registry name), ``shadows`` (its ``[shadows]`` tunables), ``ground``,
        ``reuse_rays`` (exact techniques: normals and ray origins once, see
        :func:`cityshade.sunhours.accumulate.sun_hours`).
    Outputs
        ``frames`` (every step's shadow mask), ``provenance`` (JSON-able description from the
        caller: file, dates, zone...; part of the run's hash and manifest), ``decorate``
        (a map view's PNG with scale bar, north arrow, CRS and colour bar) and ``gis``
        (``results.gpkg`` and GeoJSON beside ``surfaces.csv``); neither is part of the hash
        (how the answers are shown does not change them).
    Execution
        ``tile_px`` (tiles of receivers), ``block`` (sun positions per task), ``scheduler``
        (``local[:N]``, ``tcp://HOST:PORT`` or an executor object) and ``scene_path`` (the
        cache file every Dask worker maps).
    """

    instants_utc: tuple = ()
    t_days: float = 0.0
    weights_h: tuple | None = None
    suns: tuple | None = None
    spa: Any = None
    steps: tuple | None = None
    step_month: tuple | None = None
    camera: Any = None
    samples_per_m2: float | None = None
    samples: Any = None
    technique: str = "exact"
    shadows: Any = None
    ground: str | None = None
    reuse_rays: bool = True
    frames: bool = False
    provenance: Mapping[str, Any] | None = None
    decorate: bool = True
    gis: bool = True
    tile_px: int | None = None
    block: int = DEFAULT_BLOCK
    scheduler: Any = None
    scene_path: Any = None

    @classmethod
    def for_steps(cls, steps: Sequence, t_days: float, **fields) -> "SunHoursRequest":
        """A request over the time plan ``steps`` (:func:`cityshade.sunhours.plan.plan_steps`):
        instants at the steps' centres, weighted by their lengths."""
        steps = tuple(steps)
        return cls(instants_utc=tuple(s.centre_utc for s in steps),
                   weights_h=tuple(s.weight_h for s in steps), t_days=float(t_days),
                   steps=steps, **fields)

    @classmethod
    def from_settings(cls, steps: Sequence, t_days: float, settings=None, *,
                      surfaces: bool = False, **fields) -> "SunHoursRequest":
        """:meth:`for_steps` with the tunables of ``settings`` (:class:`cityshade.config.Settings`):
        ``[shadows]``, ``[sun]`` and ``[batch]`` (``reuse_rays``, and ``samples_per_m2`` when
        ``surfaces``, per-surface sun-hours)."""
        from cityshade.config import Settings

        settings = settings or Settings()
        return cls.for_steps(steps, t_days, shadows=settings.shadows, spa=settings.sun,
                             reuse_rays=settings.batch.reuse_rays,
                             samples_per_m2=settings.batch.samples_per_m2 if surfaces else None,
                             **fields)

    @property
    def tiled(self) -> bool:
        """Run over tiles of receivers (tiled, distributed or monthly): the tiled driver."""
        return self.tile_px is not None or self.scheduler is not None or \
            self.step_month is not None

    def check(self, scene=None) -> None:
        """Refuse a request with nothing to compute, knobs that disagree, or a scene without
        a kd-tree."""
        if self.camera is None and self.samples_per_m2 is None and self.samples is None:
            raise UsageError("nothing to compute: give a camera, samples_per_m2, or both")
        if self.tiled:
            check_execution(self.technique, self.tile_px, self.scheduler,
                            self.step_month is not None, self.frames)
            if self.block < 1:
                raise UsageError(f"a task needs at least one sun position, not {self.block}")
        if scene is not None:
            check_scene(scene)
