"""The frame loop of ``cityshade evaluate``: every technique on the pipeline's frames.

For each view (camera), the camera pass (:func:`cityshade.frame.pipeline.camera_pass`, ground plane
included) is timed ``repeat + 1`` times and serves every sun; for each sun position, technique
and shadow-map size the shadow pass runs ``repeat + 1`` times on it: the first run is reported
separately as the warm-up (Numba compile or cache load, first-touch allocations), the median
of the others as the run time. The error
against the exact reference, ``raytrace``, on the same pixels is :mod:`.metrics`'s; for map
techniques the rows also hold the aliasing measure m (screen extent of one shadow-map texel,
max and mean; Lloyd et al. 2008) that the techniques report, and for ``hybrid`` the share of
the surface pixels it ray traced. :mod:`.report` writes the results.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable, Sequence

import numpy as np

from cityshade.build import load_or_build_scene
from cityshade.config import EvaluateSettings, ShadowSettings
from cityshade.errors import UsageError
from cityshade.evaluate.metrics import compare, finite_check, make_reference, median_s
from cityshade.shadows.shadowmap import DepthMapReuse

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera
    from cityshade.geo.sun import SunPosition

__all__ = ["EvaluateSettings", "Case", "Evaluation", "expand_techniques", "map_family",
           "uses_map", "FrameSetup", "evaluate_frame", "TimedCameraPass", "timed_camera_pass",
           "run_evaluation", "sun_label", "view_camera", "load_or_build_scene",
           "parse_suns", "suns_of_day"]


def expand_techniques(spec: str | Sequence[str]) -> list[str]:
    """Technique names of ``--shadows``: ``all``, or a comma list of registry names.

    ``all`` is every exact technique but the reference
    (:func:`cityshade.shadows.exact_engine_names`: ``izb``), every map technique of the
    registry (:func:`cityshade.shadows.map_technique_names`), each ``+smooth``, and
    ``hybrid:NAME`` for each map technique; ``all+smooth`` (``--shadows all --smooth``) is
    each of those with the smoothing filter. ``raytrace`` is always the reference and is not
    listed.
    Unknown names raise the registry's :class:`~cityshade.errors.UsageError`.
    """
    from cityshade.shadows import (describe, exact_engine_names, get_technique,
                                   map_technique_names)

    names = [s.strip() for s in (spec.split(",") if isinstance(spec, str) else spec)]
    names = [n for n in names if n]
    if not names:
        raise UsageError("--shadows needs 'all' or a comma-separated list of techniques")
    out: list[str] = []
    for name in names:
        maps = [n for n in map_technique_names() if describe(n).warp is None]
        every = [*exact_engine_names(), *maps, *(f"{n}+smooth" for n in maps),
                 *(f"hybrid:{n}" for n in maps)]
        if name == "all":
            group = every
        elif name == "all+smooth":
            group = [n if describe(n).smooth else f"{n}+smooth" for n in every]
        else:
            group = [name]
        for n in group:
            if n == "raytrace":
                continue
            get_technique(n)  # unknown names fail before any work
            if n not in out:
                out.append(n)
    return out


def map_family(technique: str) -> str:
    """The map technique whose depth maps ``technique`` draws (``hybrid:pcf+smooth`` → ``pcf``,
    ``hybrid`` → ``vsm``; an exact technique, smoothed or not, is its own family)."""
    from cityshade.shadows import describe

    spec = describe(technique)
    if spec.smooth:
        spec = describe(spec.base)
    return spec.base if spec.family == "hybrid" else spec.name


def uses_map(technique: str) -> bool:
    """Whether the technique draws shadow maps (so its ``map_px`` matters)."""
    from cityshade.shadows import describe

    return describe(technique).family != "exact"


@dataclass
class Case:
    """One rendered comparison kept for a difference image."""

    view: str
    sun_label: str
    technique: str
    map_px: int | None
    misclassified_pct: float
    false_lit: np.ndarray
    false_shadow: np.ndarray


@dataclass
class Evaluation:
    """Result of :func:`run_evaluation`."""

    rows: list[dict[str, Any]] = field(default_factory=list)
    #: view name → list of worst cases (most wrong pixels first).
    worst: dict[str, list[Case]] = field(default_factory=dict)
    #: (view, sun label) → the shaded reference picture (H, W, 3) uint8.
    pictures: dict[tuple[str, str], np.ndarray] = field(default_factory=dict)
    #: view name → lines of :func:`skipped_work` (from its reference and first map frame).
    skipped: dict[str, list[str]] = field(default_factory=dict)
    meta: dict[str, Any] = field(default_factory=dict)


def sun_label(sun) -> str:
    """Short label of a sun position: ``az135 el30`` (true azimuth, elevation, degrees)."""
    return f"az{sun.azimuth_true_deg:g} el{sun.elevation_deg:g}"


def _stage_medians(diags: list[dict]) -> dict[str, float]:
    """Median of every ``timings_s`` entry of a technique's diagnostics over runs."""
    keys: dict[str, list[float]] = {}
    for d in diags:
        for k, v in (d.get("timings_s") or {}).items():
            if isinstance(v, (int, float)):
                keys.setdefault(k, []).append(float(v))
        smooth = d.get("smooth")
        if isinstance(smooth, dict) and isinstance(smooth.get("smooth_s"), (int, float)):
            keys.setdefault("smooth_s", []).append(float(smooth["smooth_s"]))
    return {k: median_s(v) for k, v in keys.items()}


@dataclass(frozen=True)
class FrameSetup:
    """One frame of an evaluation: a view's camera and one sun over a scene at a city time."""

    scene: "Scene"
    camera: "Camera"
    view: str                   # the view's name (the rows' ``view``)
    sun: "SunPosition"
    t_days: float               # city time, days since 1970-01-01 UTC
    ground: str | None = None   # ground plane, as ``render --ground``


def evaluate_frame(frame: FrameSetup, techniques: Sequence[str], sizes: Sequence[int],
                   settings: EvaluateSettings, evaluation: Evaluation,
                   shadows: ShadowSettings | None = None,
                   progress: Callable[[str], None] | None = None,
                   reference_lit: np.ndarray | None = None,
                   camera_runs: "TimedCameraPass | None" = None) -> dict[str, Any]:
    """Evaluate every technique and size on one view and sun; rows go into ``evaluation``.

    The frame is the pipeline's (:func:`cityshade.frame.pipeline.camera_pass`, with
    ``frame.ground`` like ``render --ground``), timed ``repeat + 1`` times (or ``camera_runs``,
    the view's camera pass timed once for all its suns); each technique runs through
    :func:`cityshade.frame.pipeline.shadow_pass` on the same camera pass.

    Returns a dict with the frame's G-buffer, surfaces, reference lit fraction and the
    results of the last run of each (technique, size) (``results``), for callers (the stress
    set) that check more.
    """
    from cityshade.frame.diagnostics import skipped_work
    from cityshade.shadows import get_technique

    scene, camera, view, sun = frame.scene, frame.camera, frame.view, frame.sun
    runs = settings.repeat + 1
    shadows = shadows or ShadowSettings()
    if camera_runs is None:
        camera_runs = timed_camera_pass(scene, camera, frame.t_days, settings.repeat,
                                        frame.ground)
    cp = camera_runs.cp
    gbuf, surfaces = cp.gbuffer, cp.surfaces
    label = sun_label(sun)
    common = {"view": view, "view_px": f"{camera.width_px}x{camera.height_px}",
              "camera": camera.kind, "sun": label,
              "sun_az_deg": round(float(sun.azimuth_true_deg), 6),
              "sun_el_deg": round(float(sun.elevation_deg), 6),
              "gbuffer_s": camera_runs.gbuffer_s, "resolve_s": camera_runs.resolve_s}
    reuse = DepthMapReuse()

    if progress:
        progress(f"{view} {label} raytrace")
    secs, diags, ref_result = _timed_shadow_passes(cp, sun, get_technique("raytrace"), shadows,
                                                   runs, reuse)
    ref_lit = ref_result.lit if reference_lit is None else reference_lit
    ref = make_reference(ref_lit, surfaces.valid, surfaces.position_m)
    evaluation.rows.append(_reference_row(common, settings.repeat, secs, diags, ref,
                                          ref_result))
    skipped = evaluation.skipped.setdefault(view, [])
    if not skipped:
        skipped += skipped_work(scene, gbuf.stats, ref_result.diagnostics, surfaces, sun)
    _keep_picture(scene, camera, gbuf, surfaces, ref.lit, sun, view, label, evaluation)
    results: dict[tuple[str, int | None], Any] = {("raytrace", None): ref_result}
    jobs = [(name, size) for name in techniques for size in (sizes if uses_map(name) else [None])]
    # The techniques that share depth maps (X, X+smooth, hybrid:X at one size) run one after
    # the other on the maps drawn once; the maps are dropped between groups (their memory).
    # The rows keep the order of the techniques and sizes.
    order = sorted(range(len(jobs)), key=lambda k: (map_family(jobs[k][0]), jobs[k][1] or 0, k))
    rows: dict[int, dict[str, Any]] = {}
    group = None
    for j in order:
        name, size = jobs[j]
        if (map_family(name), size) != group:
            group = (map_family(name), size)
            reuse.clear()
        tech = get_technique(name)
        if progress:
            progress(f"{view} {label} {name} {size or ''}".rstrip())
        sized = shadows.override(map_px=int(size)) if size is not None else shadows
        row = {**common, "technique": name, "map_px": size or "", "runs": settings.repeat}
        rows[j] = row
        try:
            secs, diags, result = _timed_shadow_passes(cp, sun, tech, sized, runs, reuse)
        except Exception as exc:  # a crash is a result of the evaluation, not its end
            row.update(error=f"{type(exc).__name__}: {exc}", warmup_s="", shadow_s="",
                       frame_s="")
            results[(name, size)] = exc
            continue
        results[(name, size)] = result
        err = compare(result.lit, ref, settings.edge_percentile)
        _fill_technique_row(row, secs, diags, result, err)
        if len(skipped) and not any(s.startswith(("shadow map", "hybrid")) for s in skipped):
            skipped += [s for s in skipped_work(scene, None, result.diagnostics) if
                        s.startswith(("shadow map", "base shadow map", "hybrid"))]
        _keep_worst(evaluation, settings.worst_cases, Case(
            view, label, name, size, err["misclassified_pct"], err["false_lit"],
            err["false_shadow"]))
    reuse.clear()
    evaluation.rows.extend(rows[j] for j in range(len(jobs)))
    return {"gbuffer": gbuf, "surfaces": surfaces, "reference": ref, "results": results}


def _timed_shadow_passes(cp, sun, tech, technique_settings, runs: int, reuse: DepthMapReuse):
    """(seconds per run, diagnostics per run, the warm-up run's result) of ``runs`` shadow
    passes on the camera pass ``cp``. The warm-up run also takes the map techniques'
    per-frame measures (aliasing m, texel size) for the row; the timed runs do what a frame
    does, no more. Depth maps come from ``reuse`` when an earlier run drew the same one; each
    run is charged the depth-pass time of the maps it reused, so its time is that of a frame
    of its own."""
    from cityshade.frame.pipeline import shadow_pass

    seconds, diags, result = [], [], None
    for k in range(runs):
        with reuse:
            sp = shadow_pass(cp, sun, tech, technique_settings, measure=(k == 0))
            seconds.append(sp.seconds + reuse.take_reused_s())
        diags.append(sp.result.diagnostics)
        result = sp.result if k == 0 else result
    return seconds, diags, result


def _reference_row(common: dict[str, Any], repeat: int, secs: list[float], diags: list[dict],
                   ref, ref_result) -> dict[str, Any]:
    """The row of the reference (``raytrace``): no error by definition, its times."""
    row = {**common, "technique": "raytrace", "map_px": "", "runs": repeat,
           "warmup_s": secs[0], "shadow_s": median_s(secs[1:]), "valid_px": int(ref.valid.sum()),
           "wrong_px": 0, "misclassified_pct": 0.0, "false_lit_pct": 0.0,
           "false_shadow_pct": 0.0, "lit_mae": 0.0, "edge_mean_m": 0.0, "edge_p95_m": 0.0,
           "edge_max_m": 0.0, "aliasing_max_m": "", "aliasing_mean_m": "",
           "traced_share": 1.0, "stages": _fmt_stages(_stage_medians(diags[1:])), "error": ""}
    bad = finite_check(ref_result)
    if bad:
        row["error"] = bad
    row["frame_s"] = row["gbuffer_s"] + row["resolve_s"] + row["shadow_s"]
    return row


def _fill_technique_row(row: dict[str, Any], secs: list[float], diags: list[dict], result,
                        err: dict[str, Any]) -> None:
    """A technique's times, error against the reference (``err``, :func:`.metrics.compare`)
    and measures into its ``row``."""
    d = result.diagnostics
    alias = d.get("aliasing_m") or {}
    if not (alias.get("max") or alias.get("mean")):
        alias = {}   # not measured (e.g. hybrid's base, whose maps are only prepared)
    row.update({
        "warmup_s": secs[0], "shadow_s": median_s(secs[1:]),
        "valid_px": err["valid_px"], "wrong_px": err["wrong_px"],
        **{k: err[k] for k in ("misclassified_pct", "false_lit_pct", "false_shadow_pct",
                               "lit_mae", "edge_mean_m", "edge_p95_m", "edge_max_m")},
        "aliasing_max_m": alias.get("max", ""), "aliasing_mean_m": alias.get("mean", ""),
        "traced_share": d.get("traced_share", ""),
        "stages": _fmt_stages(_stage_medians(diags[1:])),
        "error": finite_check(result) or "",
    })
    row["frame_s"] = row["gbuffer_s"] + row["resolve_s"] + row["shadow_s"]


@dataclass
class TimedCameraPass:
    """A view's camera pass and the medians of its timed runs (it does not depend on the sun,
    so one serves every sun of the view)."""

    cp: Any                     # cityshade.frame.pipeline.CameraPass
    gbuffer_s: float
    resolve_s: float


def timed_camera_pass(scene, camera, t_days: float, repeat: int, ground: str | None = None
                      ) -> TimedCameraPass:
    """The camera pass run ``repeat + 1`` times: the last one, and the medians of all runs
    but the first (the warm-up)."""
    from cityshade.frame.pipeline import camera_pass

    g_times, r_times = [], []
    for _ in range(repeat + 1):
        cp = camera_pass(scene, camera, t_days, ground=ground)
        g_times.append(cp.timings_s["gbuffer_s"])
        r_times.append(cp.timings_s["resolve_s"])
    return TimedCameraPass(cp, median_s(g_times[1:]), median_s(r_times[1:]))


def _fmt_stages(stages: dict[str, float]) -> str:
    return " ".join(f"{k[:-2] if k.endswith('_s') else k}={v * 1000:.2f}ms"
                    for k, v in stages.items())


def _keep_worst(evaluation: Evaluation, k: int, case: Case) -> None:
    if k <= 0 or case.misclassified_pct <= 0.0:
        return
    worst = evaluation.worst.setdefault(case.view, [])
    worst.append(case)
    worst.sort(key=lambda c: -c.misclassified_pct)
    del worst[k:]


def _keep_picture(scene, camera, gbuf, surfaces, ref_lit, sun, view, label, evaluation) -> None:
    """The shaded reference picture of a view and sun (the background of diff images)."""
    from cityshade.frame.shading import shade, to_srgb8

    if evaluation.meta.get("no_pictures"):
        return
    rgb = shade(scene, surfaces, camera, ref_lit.astype(np.float32), sun.direction,
                prim_id=gbuf.prim_id)
    evaluation.pictures[(view, label)] = to_srgb8(rgb)


def view_camera(scene, view: str, size: tuple[int, int] = (1280, 720),
                pixel_size_m: float | None = None, t_days: float | None = None,
                cameras_file=None, bbox=None):
    """Camera of a view name: ``overview``, ``map`` or a shipped camera preset
    (``cityshade/configs/cameras.toml``) or one of the user's preset file ``cameras_file``;
    ``bbox``: the map's render-space extent (:func:`cityshade.raster.camera.map_extent`)."""
    from cityshade.raster import camera as cams

    w, h = size
    if view == "overview":
        return cams.overview(scene, w, h, t_days=t_days)
    if view == "map":
        return cams.map_view(scene, pixel_size_m, bbox=bbox)
    return cams.preset(view, scene, w, h, extra=cameras_file)


def run_evaluation(scene: "Scene", views: Sequence[tuple[str, Any]], suns: Sequence, t_days: float,
                   techniques: Sequence[str], settings: EvaluateSettings | None = None,
                   shadows: ShadowSettings | None = None,
                   progress: Callable[[int, int, str], None] | None = None,
                   model: str = "", ground: str | None = None) -> Evaluation:
    """Evaluate techniques × sizes on every view and sun.

    Parameters
    ----------
    scene : Scene
        With its kd-tree.
    views : sequence of (name, Camera)
    suns : sequence of SunPosition
    t_days : float
        City time, days since 1970-01-01 UTC.
    techniques : sequence of str
        Registry names (see :func:`expand_techniques`); ``raytrace`` is always the reference.
    settings : EvaluateSettings, optional
    shadows : ShadowSettings, optional
        The techniques' tunables; ``map.px`` is replaced by each of ``settings.sizes``.
    progress : callable(done, total, label), optional
        Called before each technique run.
    model : str
        Name of the model for the rows.
    ground : str, optional
        Ground plane of every frame, as ``render --ground``.

    Returns
    -------
    Evaluation
    """
    settings = settings or EvaluateSettings()
    if not scene.can_trace:
        raise UsageError("the scene file has no kd-tree; rebuild it with `cityshade build`")
    if not views or not suns:
        raise UsageError("evaluate needs at least one view and one sun position")
    per_frame = 1 + sum(len(settings.sizes) if uses_map(n) else 1 for n in techniques)
    total = per_frame * len(views) * len(suns)
    done = [0]

    def step(label: str) -> None:
        if progress:
            progress(done[0], total, label)
        done[0] += 1

    evaluation = Evaluation(meta={"model": model, "t_days": t_days,
                                  "techniques": list(techniques),
                                  "sizes": list(settings.sizes), "repeat": settings.repeat})
    for view, camera in views:
        # The camera pass is the same for every sun: timed once per view.
        camera_runs = timed_camera_pass(scene, camera, t_days, settings.repeat, ground)
        for sun in suns:
            evaluate_frame(FrameSetup(scene, camera, view, sun, t_days, ground), techniques,
                           settings.sizes, settings, evaluation, shadows, step,
                           camera_runs=camera_runs)
        del camera_runs   # its frame's memory, before the next view
    for row in evaluation.rows:
        row["model"] = model
    if progress:
        progress(total, total, "done")
    return evaluation


# --- inputs of the command ----------------------------------------------------------------

def parse_suns(text: str, scene) -> list:
    """``"az,el;az,el"`` (degrees, azimuth from true north) → sun positions of the model."""
    from cityshade.geo.sun import check_user_angles, sun_from_angles

    suns = []
    for part in (p.strip() for p in text.split(";")):
        if not part:
            continue
        try:
            az, el = (float(v) for v in part.split(","))
        except ValueError:
            raise UsageError(f"--sun must be 'AZIMUTH,ELEVATION;...' in degrees, not {part!r}") \
                from None
        check_user_angles(az, el)
        suns.append(sun_from_angles(az, el, scene.crs, scene.origin_m))
    if not suns:
        raise UsageError("--sun needs at least one 'AZIMUTH,ELEVATION' pair")
    return suns


def suns_of_day(day: str, times: str, tz: str | None, scene, spa=None) -> list:
    """Sun positions (SPA) at local ``times`` ("HH:MM,HH:MM") of ``day`` (YYYY-MM-DD)."""
    from cityshade.geo.temporal import parse_user_date
    from cityshade.geo.sun import SpaSettings, suns_from_instants

    instants = []
    for t in (s.strip() for s in times.split(",")):
        if t:
            instants.append(parse_user_date(f"{day.strip()}T{t}", tz).instant_utc)
    if not instants:
        raise UsageError("--times needs at least one HH:MM")
    return suns_from_instants(instants, scene.crs, scene.origin_m, spa or SpaSettings())
