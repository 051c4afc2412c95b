"""The typed request of a sky run (sky view factor, irradiance from a weather file) and the run
itself: receivers once (the batch's camera pass and surface samples), the sky's visibility
once, the hours of the weather file, then the outputs written together
(:mod:`cityshade.light.outputs`). Built by ``cityshade sky`` or a Python caller."""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from collections.abc import Mapping
from typing import Any

import numpy as np

from cityshade.errors import UsageError

#: Leaf states the sky view factor can be taken in (deciduous crowns in leaf or leafless).
SEASONS = ("leaf_on", "leaf_off")

__all__ = ["SkyRequest", "SkyResult", "compute_sky", "run_sky", "sky_bytes_per_receiver"]


@dataclass(frozen=True)
class SkyRequest:
    """One sky run.

    Where
        ``camera`` (the map or view, as batch's; None: surfaces only), ``samples_per_m2``
        (per-surface values at this density; None: no surfaces), ``ground`` (batch's ground
        plane option).
    When
        ``t_days`` (the city's state, days since 1970-01-01 UTC).
    How
        ``sky`` (:func:`cityshade.light.sky.named_sky`), ``technique`` (an exact one, default
        ``exact`` as in every command: its engine traces the sky and the suns), ``spa`` (sun settings).
    What
        ``svf`` (the sky view factor's outputs), ``vsc`` (the vertical sky component of
        every receiver on its own plane,
        :func:`~cityshade.light.metrics.vertical_sky_component`), ``season`` (``leaf_on`` or
        ``leaf_off``: the deciduous crowns of the sky view factor and the VSC; the irradiance
        takes each hour's own leaf state), ``weather`` (a
        :class:`~cityshade.light.weather.Weather`: irradiance), ``hours`` ((H,) bool of the
        weather hours to sum; None: all, the file's year), ``period`` (False: no kWh/m² over
        the hours, only the instants), ``model``, ``albedo``;
        ``instants`` (aware datetimes: W/m² at each, from the weather record of the hour
        containing it with the sun at the instant) and their ``instant_labels`` (``0900``:
        the files' and columns' names).
    Outputs
        ``provenance`` (JSON-able, in the files' metadata), ``decorate`` (map PNGs with scale
        bar, north, CRS, title, colour bar), ``gis`` (``results.gpkg`` of the surfaces and
        buildings).
    """

    camera: Any = None
    samples_per_m2: float | None = None
    ground: str | None = None
    t_days: float = 0.0
    sky: str = "reinhart2305"
    technique: str = "exact"
    spa: Any = None
    svf: bool = True
    vsc: bool = False
    season: str = "leaf_on"
    weather: Any = None
    hours: Any = None
    model: str = "perez"
    albedo: float = 0.2
    period: bool = True
    instants: tuple = ()
    instant_labels: tuple = ()
    provenance: Mapping[str, Any] | None = None
    decorate: bool = True
    gis: bool = True

    @property
    def engine(self) -> str:
        from cityshade.sunhours.request import exact_engine

        return exact_engine(self.technique, "sky view factors and irradiance")

    def check(self, scene=None) -> None:
        """Refuse a request with nothing to compute or an unknown sky, model or technique."""
        from cityshade.light.irradiance import SKY_MODELS
        from cityshade.light.sky import named_sky

        if self.camera is None and self.samples_per_m2 is None:
            raise UsageError("nothing to compute: give a camera, samples_per_m2, or both")
        if not (self.svf or self.vsc) and self.weather is None:
            raise UsageError("nothing to compute: ask for the sky view factor, the vertical "
                             "sky component or irradiance (with a weather file)")
        if len(self.instants) != len(self.instant_labels):
            raise UsageError("every instant needs its label")
        if self.instants and self.weather is None:
            raise UsageError("irradiance at instants needs a weather file")
        if self.model not in SKY_MODELS:
            raise UsageError(f"the sky model is one of {', '.join(SKY_MODELS)}, not "
                             f"{self.model!r}")
        if self.season not in SEASONS:
            raise UsageError(f"the season of the sky view factor is one of "
                             f"{', '.join(SEASONS)}, not {self.season!r}")
        named_sky(self.sky)
        self.engine  # noqa: B018 - an inexact technique fails here, before any work
        if scene is not None:
            from cityshade.sunhours.request import check_scene

            check_scene(scene)


@dataclass
class SkyResult:
    """Per-receiver answers of a sky run: map pixels first (``pixels`` into the camera's
    frame), then surface samples.

    ``svf`` (N,), ``irradiation`` (:class:`~cityshade.light.irradiance.Irradiation` or
    None), ``shape`` (H, W) of the map or None, ``pixels`` (M,) flat indices, ``cp`` the camera
    pass, ``samples`` the surface samples or None, ``sky`` the directions used,
    ``bytes_per_receiver`` (the estimate), ``timings_s``, ``warnings``.
    """

    svf: np.ndarray
    irradiation: Any
    shape: tuple | None
    pixels: np.ndarray
    cp: Any
    samples: Any
    sky: Any
    bytes_per_receiver: int
    #: (K, N, 3) W/m² (direct, diffuse, reflected) at the request's instants, or None.
    instants_w_m2: Any = None
    #: (N,) vertical sky component (fraction) of every receiver on its own plane, or None.
    vsc: Any = None
    timings_s: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)

    @property
    def n_pixels(self) -> int:
        return len(self.pixels)

    def map_of(self, values: np.ndarray) -> np.ndarray:
        """(H, W) float32 of the per-pixel part of ``values`` (N,), NaN where no surface."""
        out = np.full(int(np.prod(self.shape)), np.nan, np.float32)
        out[self.pixels] = values[:self.n_pixels]
        return out.reshape(self.shape)

    def sample_values(self, values: np.ndarray) -> np.ndarray:
        return values[self.n_pixels:]


def sky_bytes_per_receiver(n_directions: int, irradiance: bool, instants: int = 0) -> int:
    """Bytes per receiver a sky run keeps beside the batch's camera pass
    (:data:`cityshade.frame.pipeline.BATCH_BYTES_PER_PX`): point and normal (48), the packed
    bits (ceil(P / 8)), one direction's ray origins and rows while tracing (32), the view
    factor and two shares (24), the plane index (8), the VSC (8); with irradiance the three
    float64 sums (24), the sun's bits and origins per hour (25); per instant its three float64
    W/m² (24). Not counted: the rays through vegetation crowns (24 B each,
    :class:`~cityshade.light.visibility.SkyCrowns`), known only after tracing.

    With the camera pass, 290 + 139 B per map pixel for 145 directions and 290 + 188 B with
    irradiance; measured (``python benchmarks/memory.py --cases sky:tregenza,irradiance:tregenza
    --pixels 500000,2000000 --steps 2``, e5e5e42, the sample city): 327 and 426 B per pixel.
    """
    return 48 + (n_directions + 7) // 8 + 32 + 24 + 8 + 8 \
        + (49 if irradiance or instants else 0) + 24 * int(instants)


def _check_memory(request: SkyRequest, n_directions: int, n_samples_max: int) -> int:
    """Refuse a run whose receivers would not fit, before any work: the camera's frame
    (batch's estimate) and the receivers (:func:`sky_bytes_per_receiver`; every pixel of the
    camera counted as a receiver), together."""
    from cityshade.frame.pipeline import available_memory_bytes, frame_bytes

    per = sky_bytes_per_receiver(n_directions, request.weather is not None and request.period,
                                 len(request.instants))
    n, frame = n_samples_max, 0
    if request.camera is not None:
        frame = frame_bytes(request.camera, batch=True)[0]
        n += request.camera.width_px * request.camera.height_px
    have = available_memory_bytes()
    need = frame + n * per
    if have is not None and need > have:
        raise UsageError(f"{n:,} receivers need about {need / 1e9:.1f} GB ({per} bytes "
                         f"each besides the camera's {frame / 1e9:.1f} GB) but "
                         f"{have / 1e9:.1f} GB are available: use a larger --pixel-size, fewer "
                         f"--samples-per-m2 or a coarser --sky")
    return per


def compute_sky(scene, request: SkyRequest, *, progress=None) -> SkyResult:
    """Receivers, the sky's visibility, the view factors and shares, the irradiance.

    ``progress(phase, done, total)`` with phase ``sky`` (directions) or ``hours``.
    """
    from cityshade.light.irradiance import irradiation, sky_shares
    from cityshade.light.sky import sky_for_scene
    from cityshade.light.visibility import map_receivers, sky_visibility
    from cityshade.sunhours.accumulate import receivers_pass

    request.check(scene)
    timings: dict[str, float] = {}
    sky = sky_for_scene(scene, request.sky)
    per = _check_memory(request, sky.n, 0)
    cp, samples = receivers_pass(scene, request.camera, request.t_days, request.ground,
                                 request.samples_per_m2, timings, {})
    points, normals, pixels = (np.zeros((0, 3)), np.zeros((0, 3)), np.zeros(0, np.int64))
    shape = None
    if cp is not None:
        points, normals, pixels = map_receivers(cp)
        shape = tuple(cp.valid.shape)
    if samples is not None:
        points = np.concatenate([points, samples.points_m])
        normals = np.concatenate([normals, samples.normals])
    t0 = time.perf_counter()
    vis = sky_visibility(scene, points, normals, sky, request.t_days, engine=request.engine,
                         progress=None if progress is None else
                         (lambda d, t: progress("sky", d, t)))
    svf, *shares = sky_shares(vis, leaf=request.season == "leaf_on")
    vsc = None
    if request.vsc:
        from cityshade.light.metrics import vertical_sky_component

        vsc = vertical_sky_component(vis, leaf=request.season == "leaf_on")
    leafless = None
    if vis.crowns is not None and request.weather is not None:
        # The irradiance takes each weather hour's leaf state: the shares of both.
        shares = sky_shares(vis, leaf=True)[1:]
        leafless = sky_shares(vis, leaf=False)[1:]
    timings["sky_s"] = time.perf_counter() - t0
    irr, warnings, at = None, [], None
    if request.weather is not None:
        from cityshade.light.weather import scene_location_warning

        warning = scene_location_warning(request.weather, scene)
        if warning:
            warnings.append(warning)
    shares_by_leaf = shares if leafless is None else {True: shares, False: leafless}
    if request.instants:
        from cityshade.geo.sun import suns_from_instants
        from cityshade.light.irradiance import irradiance_at

        t0 = time.perf_counter()
        suns = suns_from_instants(list(request.instants), scene.crs, scene.origin_m,
                                  request.spa)
        at = irradiance_at(scene, points, normals, request.weather, request.instants,
                           np.array([s.direction for s in suns], np.float64).reshape(-1, 3),
                           shares_by_leaf, t_days=request.t_days,
                           engine=request.engine, model=request.model, albedo=request.albedo)
        timings["instants_s"] = time.perf_counter() - t0
    if request.weather is not None and request.period:
        from cityshade.light.sunlight import weather_suns

        t0 = time.perf_counter()
        directions, _ = weather_suns(request.weather, scene, request.spa)
        irr = irradiation(scene, points, normals, request.weather, directions, shares_by_leaf,
                          hours=request.hours, t_days=request.t_days, engine=request.engine,
                          model=request.model, albedo=request.albedo,
                          progress=None if progress is None else
                          (lambda d, t: progress("hours", d, t)))
        timings["irradiance_s"] = time.perf_counter() - t0
    return SkyResult(svf=svf, irradiation=irr, shape=shape, pixels=pixels, cp=cp,
                     samples=samples, sky=sky, bytes_per_receiver=per, instants_w_m2=at, vsc=vsc,
                     timings_s=timings,
                     warnings=warnings)


def run_sky(outdir, scene, request: SkyRequest, *, progress=None) -> tuple[SkyResult,
                                                                           list[Path]]:
    """Compute (:func:`compute_sky`) and write the outputs into ``outdir`` together
    (:func:`cityshade.light.outputs.write_sky_outputs`): all of them or, on an error or
    Ctrl-C, none. Returns the result and the paths written."""
    from cityshade.light.outputs import write_sky_outputs

    result = compute_sky(scene, request, progress=progress)
    t0 = time.perf_counter()
    written = write_sky_outputs(Path(outdir), scene, request, result)
    result.timings_s["write_s"] = time.perf_counter() - t0
    return result, written
