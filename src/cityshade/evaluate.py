"""``cityshade evaluate``: every shadow technique's error against ``raytrace`` and its run time.

For each view (camera), sun position, technique and shadow-map size, the camera pass runs once
and the shadow stage runs ``repeat + 1`` times on the same G-buffer: the first run is reported
separately as the warm-up (Numba compile or cache load, first-touch allocations), the median
of the others as the run time. The error is measured on the same pixels against the exact
reference, ``raytrace``:

- misclassified pixels in % of the pixels that show a surface, split into false-lit (the
  technique says sun, the reference shadow) and false-shadow; a pixel counts as lit when its
  lit fraction is ≥ 0.5 (filtered techniques return fractions);
- the mean absolute difference of the lit fraction (what a soft technique gets wrong on top);
- the shadow-edge displacement in metres: for each wrong pixel, the distance in render space
  from its surface point to the surface point of the nearest pixel (in the image) that truly
  has the class the technique gave it, i.e. how far the true edge would have to move to make
  the pixel right; mean, 95th percentile and maximum;
- for map techniques, the aliasing measure m (screen extent of one shadow-map texel, max and
  mean; Lloyd et al. 2008) that the techniques report, and for ``hybrid`` the share of the
  surface pixels it ray traced.

:func:`write_report` writes ``results.csv``, ``report.md`` (tables and which techniques are on
the Pareto front of error against time, per view), a PNG plot of error against time per view
(log axes, drawn here with numpy: no plotting library is needed) and difference images of the
worst cases (false-lit red, false-shadow blue over the shaded picture).

:func:`skipped_work` lists what a frame left out because the scene or request did not need it
(no time dimension, no textures, culled kd-tree nodes, casters outside the light frustum,
cascades that cover no pixel, pixels that needed no ray) and an estimate of the time saved.
"""
from __future__ import annotations

import csv
import math
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np
from numba import njit, prange

from cityshade.errors import OutputError, UsageError

#: The map techniques of the product (DESIGN §8); ``all`` evaluates each of them, each with
#: the screen-space smoothing, and ``hybrid`` on each of them as base.
MAP_TECHNIQUES = ("shadowmap", "pcf", "vsm", "psm", "lispsm", "xpsm", "csm")
#: Pixels whose lit fraction is at least this count as lit (filtered techniques return
#: fractions; 0.5 is the unbiased threshold of a fraction).
LIT_THRESHOLD = 0.5


@dataclass(frozen=True)
class EvaluateSettings:
    """Tunables of ``cityshade evaluate``.

    Attributes
    ----------
    repeat : int
        Timed runs per technique and size after the warm-up run; the median is reported.
        3 keeps the median robust to one disturbed run on a shared 2-core machine.
    sizes : tuple of int
        Shadow-map sides in texels (``map_px``; per cascade for ``csm``).
    worst_cases : int
        Difference images written per view (the techniques and sizes with the most wrong
        pixels).
    edge_percentile : float
        Percentile of the edge displacement reported next to its mean.
    """

    repeat: int = 3
    sizes: tuple[int, ...] = (1024, 2048, 4096)
    worst_cases: int = 3
    edge_percentile: float = 95.0

    def __post_init__(self) -> None:
        if not (isinstance(self.repeat, (int, np.integer)) and 1 <= self.repeat <= 100):
            raise UsageError(f"repeat must be an integer in [1, 100], not {self.repeat!r}")
        sizes = tuple(self.sizes)
        if not sizes or not all(isinstance(s, (int, np.integer)) and 16 <= s <= 16384
                                for s in sizes):
            raise UsageError(f"map sizes must be integers in [16, 16384], not {self.sizes!r}")
        if not (isinstance(self.worst_cases, (int, np.integer)) and 0 <= self.worst_cases <= 100):
            raise UsageError(f"worst_cases must be an integer in [0, 100], "
                             f"not {self.worst_cases!r}")
        if not 0.0 < self.edge_percentile <= 100.0:
            raise UsageError(f"edge_percentile must be in (0, 100], not {self.edge_percentile}")


def expand_techniques(spec: str | Sequence[str]) -> list[str]:
    """Technique names of ``--shadows``: ``all``, or a comma list of registry names.

    ``all`` is every map technique of :data:`MAP_TECHNIQUES`, each ``+smooth``, and
    ``hybrid:NAME`` for each of them. ``raytrace`` is always the reference and is not listed.
    Unknown names raise the registry's :class:`~cityshade.errors.UsageError`.
    """
    from cityshade.shadows import get_technique

    names = [s.strip() for s in (spec.split(",") if isinstance(spec, str) else spec)]
    names = [n for n in names if n]
    if not names:
        raise UsageError("--shadows needs 'all' or a comma-separated list of techniques")
    out: list[str] = []
    for name in names:
        group = ([*MAP_TECHNIQUES, *(f"{n}+smooth" for n in MAP_TECHNIQUES),
                  *(f"hybrid:{n}" for n in MAP_TECHNIQUES)] if name == "all" else [name])
        for n in group:
            if n == "raytrace":
                continue
            get_technique(n)  # unknown names fail before any work
            if n not in out:
                out.append(n)
    return out


def uses_map(technique: str) -> bool:
    """Whether the technique draws shadow maps (so its ``map_px`` matters)."""
    return technique.partition("+")[0] != "raytrace"


# --- error against the reference --------------------------------------------------------------

@njit(cache=True, parallel=True)
def _nearest_feature_kernel(feature, near_row, near_col):
    """Exact Euclidean feature transform: for every pixel, the nearest ``feature`` pixel.

    Two separable passes (Felzenszwalb & Huttenlocher 2012): per column the nearest feature
    row, then per row the lower envelope of the parabolas ``(x - q)² + (y - row(q))²``.
    ``near_row``/``near_col`` (H, W) int64 get -1 when the image has no feature pixel.
    """
    h, w = feature.shape
    col_row = np.empty((h, w), np.int64)
    # Scan each column down and up for the nearest feature row.
    for x in prange(w):
        last = -1
        for y in range(h):
            if feature[y, x]:
                last = y
            col_row[y, x] = last
        nxt = -1
        for y in range(h - 1, -1, -1):
            if feature[y, x]:
                nxt = y
            if nxt >= 0 and (col_row[y, x] < 0 or nxt - y < y - col_row[y, x]):
                col_row[y, x] = nxt
    # Lower envelope of the columns' parabolas along each row.
    for y in prange(h):
        v = np.empty(w, np.int64)
        z = np.empty(w + 1, np.float64)
        k = -1
        for q in range(w):
            if col_row[y, q] < 0:
                continue
            fq = float((y - col_row[y, q]) ** 2)
            if k < 0:
                k = 0
                v[0] = q
                z[0] = -np.inf
                z[1] = np.inf
                continue
            while True:
                p = v[k]
                fp = float((y - col_row[y, p]) ** 2)
                s = ((fq + q * q) - (fp + p * p)) / (2.0 * (q - p))
                if s <= z[k]:
                    k -= 1   # z[0] = -inf stops this before k < 0
                else:
                    break
            k += 1
            v[k] = q
            z[k] = s
            z[k + 1] = np.inf
        if k < 0:
            for x in range(w):
                near_row[y, x] = -1
                near_col[y, x] = -1
            continue
        j = 0
        for x in range(w):
            while z[j + 1] < x:
                j += 1
            near_col[y, x] = v[j]
            near_row[y, x] = col_row[y, v[j]]


def nearest_feature(feature: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row and column of the nearest ``True`` pixel of ``feature`` for every pixel.

    Parameters
    ----------
    feature : (H, W) bool

    Returns
    -------
    near_row, near_col : (H, W) int64
        Nearest feature pixel by Euclidean distance in pixel units (ties: any of them); -1
        everywhere when ``feature`` has no ``True`` pixel.
    """
    feature = np.ascontiguousarray(feature, dtype=np.bool_)
    if feature.ndim != 2:
        raise UsageError(f"feature must be (H, W), not {feature.shape}")
    near_row = np.empty(feature.shape, np.int64)
    near_col = np.empty(feature.shape, np.int64)
    if feature.size:
        _nearest_feature_kernel(feature, near_row, near_col)
    return near_row, near_col


@dataclass
class Reference:
    """The exact answer of one view and sun, prepared for comparisons."""

    lit: np.ndarray           # (H, W) bool: raytrace says sun
    valid: np.ndarray         # (H, W) bool: a surface is seen
    position_m: np.ndarray    # (H, W, 3) float64 render space
    #: Nearest truly lit / truly shadowed valid pixel of every pixel ((row, col), -1 if none).
    near_lit: tuple[np.ndarray, np.ndarray]
    near_shadow: tuple[np.ndarray, np.ndarray]


def make_reference(ref_lit: np.ndarray, valid: np.ndarray, position_m: np.ndarray) -> Reference:
    """Prepare the reference of one frame (two feature transforms, shared by all comparisons)."""
    valid = np.asarray(valid, bool)
    lit = (np.asarray(ref_lit) >= LIT_THRESHOLD) & valid
    return Reference(lit=lit, valid=valid, position_m=np.asarray(position_m, np.float64),
                     near_lit=nearest_feature(lit), near_shadow=nearest_feature(valid & ~lit))


def _displacement_m(ref: Reference, wrong: np.ndarray, near) -> np.ndarray:
    """Render-space distance from each wrong pixel to its nearest pixel of the other class."""
    rows, cols = np.nonzero(wrong)
    nr, nc = near[0][rows, cols], near[1][rows, cols]
    ok = nr >= 0
    d = ref.position_m[nr[ok], nc[ok]] - ref.position_m[rows[ok], cols[ok]]
    return np.sqrt(np.einsum("ij,ij->i", d, d))


def compare(lit: np.ndarray, ref: Reference, percentile: float = 95.0) -> dict[str, Any]:
    """Error of one technique's lit fraction against the reference on the same pixels.

    Returns
    -------
    dict
        ``valid_px``, ``wrong_px``, ``misclassified_pct``, ``false_lit_pct``,
        ``false_shadow_pct`` (of the valid pixels), ``lit_mae`` (mean |lit − reference| over
        valid pixels), ``edge_mean_m``, ``edge_p95_m``, ``edge_max_m`` (None when no wrong
        pixel has a pixel of the other class in the image), ``false_lit`` and
        ``false_shadow`` (H, W) bool masks.
    """
    lit = np.asarray(lit, np.float32)
    if lit.shape != ref.valid.shape:
        raise UsageError(f"lit fraction {lit.shape} and reference {ref.valid.shape} differ")
    says_lit = lit >= LIT_THRESHOLD
    false_lit = ref.valid & says_lit & ~ref.lit
    false_shadow = ref.valid & ~says_lit & ref.lit
    n_valid = int(ref.valid.sum())
    share = 100.0 / max(n_valid, 1)
    dist = np.concatenate([_displacement_m(ref, false_lit, ref.near_lit),
                           _displacement_m(ref, false_shadow, ref.near_shadow)])
    diff = np.abs(np.nan_to_num(lit, nan=0.0) - ref.lit.astype(np.float32))
    out = {
        "valid_px": n_valid,
        "wrong_px": int(false_lit.sum() + false_shadow.sum()),
        "false_lit_pct": float(false_lit.sum() * share),
        "false_shadow_pct": float(false_shadow.sum() * share),
        "lit_mae": float(diff[ref.valid].mean()) if n_valid else 0.0,
        "edge_mean_m": float(dist.mean()) if dist.size else None,
        "edge_p95_m": float(np.percentile(dist, percentile)) if dist.size else None,
        "edge_max_m": float(dist.max()) if dist.size else None,
        "false_lit": false_lit, "false_shadow": false_shadow,
    }
    out["misclassified_pct"] = out["false_lit_pct"] + out["false_shadow_pct"]
    if out["wrong_px"] == 0:
        out.update(edge_mean_m=0.0, edge_p95_m=0.0, edge_max_m=0.0)
    return out


def pareto_front(times: Sequence[float], errors: Sequence[float]) -> list[int]:
    """Indices of the points no other point beats in both time and error, by time.

    A point is dominated when another is at most as slow and at most as wrong, and strictly
    better in one of the two.
    """
    order = sorted(range(len(times)), key=lambda i: (times[i], errors[i]))
    front, best = [], math.inf
    for i in order:
        if errors[i] < best:
            front.append(i)
            best = errors[i]
    return front


# --- what a frame left out ----------------------------------------------------------------

def _ms(seconds: float) -> str:
    return f"≈ {seconds * 1000:.1f} ms" if seconds >= 5e-5 else "< 0.1 ms"


def _depth_map_skips(stats: dict, where: str) -> list[str]:
    out = []
    removed = int(stats.get("frustum_refs_removed", 0))
    drawn = int(stats.get("casters_drawn", 0))
    raster = stats.get("timings_s", {})
    per_caster = (raster.get("setup_s", 0.0) + raster.get("raster_s", 0.0)) / max(drawn, 1)
    if stats.get("culling") == "the model lies inside the light view":
        out.append(f"{where}: kd-tree walk skipped (the whole model lies inside the light "
                   f"view: nothing to cull, a linear time filter is cheaper)")
    elif removed:
        out.append(f"{where}: {removed} caster references outside the light frustum not drawn "
                   f"({drawn} drawn of {stats.get('triangles', 0)} triangles; "
                   f"{_ms(removed * per_caster)})")
    if int(stats.get("time_refs_removed", 0)):
        out.append(f"{where}: {stats['time_refs_removed']} caster references not standing at "
                   f"the city time skipped")
    return out


def skipped_work(scene, gbuffer_stats: dict | None = None,
                 shadow_diagnostics: dict | None = None, surfaces=None,
                 sun=None) -> list[str]:
    """What a frame left out because the scene or the request did not need it, with why and
    an estimate of the time it saved, one line per item.

    Parameters
    ----------
    scene : Scene
        Its kd-tree statistics and textures.
    gbuffer_stats : dict, optional
        :attr:`cityshade.raster.gbuffer.GBuffer.stats` of the camera pass.
    shadow_diagnostics : dict, optional
        The shadow technique's diagnostics (nested ``base`` of ``hybrid`` are read too).
    surfaces : Surfaces, optional
        For the textured-pixel count.
    sun : SunPosition, optional

    Notes
    -----
    Savings are estimates: the number of things left out times the measured cost per thing of
    the same stage in this frame (e.g. raster time per drawn triangle), marked "≈".
    """
    out: list[str] = []
    tree = getattr(scene, "kdtree", None)
    if tree is not None and not tree.has_time:
        out.append(f"kd-tree: no time dimension (the model has no dates): "
                   f"{tree.stats.get('time_splits', 0)} time splits, no time test in any "
                   f"traversal")
    if sun is not None and not sun.above_horizon:
        out.append("shadows: no ray and no map (the sun is below the horizon)")
    textures = list(getattr(scene, "textures", []) or [])
    if not textures:
        out.append("shading: no texture sampling (the model has no textures)")
    elif surfaces is not None:
        texture = np.asarray(surfaces.texture)
        if not (np.asarray(surfaces.valid) & (texture >= 0)).any():
            out.append("shading: no texture sampling (no visible pixel is textured)")
    g = gbuffer_stats or {}
    if g:
        drawn = int(g.get("triangles_drawn", 0))
        t = g.get("timings_s", {})
        per_tri = max(t.get("total_s", 0.0) - t.get("walk_s", 0.0), 0.0) / max(drawn, 1)
        if g.get("walk_skipped"):
            out.append(f"camera pass: kd-tree walk skipped ({g['walk_skipped']}: nothing to "
                       f"cull, a linear time filter is cheaper)")
        for key, what in (("frustum_refs_removed", "outside the view frustum"),
                          ("occlusion_refs_removed", "hidden behind drawn surfaces "
                                                     "(occlusion queries)"),
                          ("time_refs_removed", "not standing at the city time")):
            n = int(g.get(key, 0))
            if n:
                out.append(f"camera pass: {n} triangle references {what} not drawn "
                           f"({_ms(n * per_tri)})")
    d = shadow_diagnostics or {}
    inner = d.get("base") if isinstance(d.get("base"), dict) else None
    if "self_shadowed_px" in (inner or d):
        n = int((inner or d)["self_shadowed_px"])
        if n:
            out.append(f"shadows: {n} pixels facing away from the sun are shadow without a ray "
                       f"or lookup")
    for diag, where in ((d, "shadow map"), (inner or {}, "base shadow map")):
        if isinstance(diag.get("depth_map"), dict):
            out += _depth_map_skips(diag["depth_map"], where)
        skipped = diag.get("cascades_skipped") or []
        if skipped:
            rendered = [e for e in diag.get("per_cascade", []) if "skipped" not in e]
            per = statistics.fmean(e.get("depth_s", 0.0) for e in rendered) if rendered else 0.0
            out.append(f"{where}: {len(skipped)} of {diag.get('cascades', 0)} cascades cover no "
                       f"visible pixel and were not drawn ({_ms(len(skipped) * per)})")
    if "traced_px" in d and "facing_px" in d:
        untraced = int(d["facing_px"]) - int(d["traced_px"])
        rays_s = d.get("timings_s", {}).get("rays_s", 0.0)
        per_ray = rays_s / max(int(d["traced_px"]), 1)
        out.append(f"hybrid: {untraced} of {d['facing_px']} sun-facing pixels decided by the map "
                   f"without a ray ({_ms(untraced * per_ray)})")
    return out


# --- the evaluation -------------------------------------------------------------------------

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


def _median(values: Sequence[float]) -> float:
    return float(statistics.median(values)) if values else 0.0


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
    return {k: _median(v) for k, v in keys.items()}


def _timed_runs(tech, ctx, runs: int):
    """Run a technique ``runs`` times; returns (seconds per run, diagnostics per run, last
    result). Every run is timed around ``run`` as the renderer calls it."""
    seconds, diags, result = [], [], None
    for _ in range(runs):
        t = time.perf_counter()
        result = tech.run(ctx)
        seconds.append(time.perf_counter() - t)
        diags.append(result.diagnostics)
    return seconds, diags, result


def _finite_check(result) -> str | None:
    lit = np.asarray(result.lit)
    if not np.isfinite(lit).all():
        return "lit fraction has NaN or infinity"
    if lit.size and (lit.min() < 0.0 or lit.max() > 1.0):
        return "lit fraction outside [0, 1]"
    for name, ch in result.extra_channels.items():
        if not np.isfinite(np.asarray(ch, np.float64)).all():
            return f"extra channel {name} has NaN or infinity"
    return None


def evaluate_frame(scene, camera, view: str, sun, t_days: float, techniques: Sequence[str],
                   sizes: Sequence[int], settings: EvaluateSettings,
                   evaluation: Evaluation, options: dict | None = None,
                   progress: Callable[[str], None] | None = None,
                   reference_lit: np.ndarray | None = None) -> dict[str, Any]:
    """Evaluate every technique and size on one view and sun; rows go into ``evaluation``.

    Returns a dict with the frame's G-buffer, surfaces, reference lit fraction and the
    results of the last run of each (technique, size) (``results``), for callers (the stress
    set) that check more.
    """
    from cityshade.raster.gbuffer import resolve
    from cityshade.raster.rasterize import rasterize
    from cityshade.shadows import ShadowContext, get_technique

    runs = settings.repeat + 1
    g_times, r_times = [], []
    for _ in range(runs):
        t0 = time.perf_counter()
        gbuf = rasterize(scene, camera, t_days)
        t1 = time.perf_counter()
        surfaces = resolve(scene, gbuf)
        g_times.append(t1 - t0)
        r_times.append(time.perf_counter() - t1)
    gbuffer_s, resolve_s = _median(g_times[1:]), _median(r_times[1:])
    label = sun_label(sun)
    base_opts = dict(options or {})
    common = {"view": view, "view_px": f"{camera.width_px}x{camera.height_px}",
              "camera": camera.kind, "sun": label,
              "sun_az_deg": round(float(sun.azimuth_true_deg), 6),
              "sun_el_deg": round(float(sun.elevation_deg), 6),
              "gbuffer_s": gbuffer_s, "resolve_s": resolve_s}
    if progress:
        progress(f"{view} {label} raytrace")
    ctx = ShadowContext(scene=scene, surfaces=surfaces, camera=camera, sun=sun, t_days=t_days,
                        options=base_opts)
    rt = get_technique("raytrace")
    secs, diags, ref_result = _timed_runs(rt, ctx, runs)
    ref_lit = ref_result.lit if reference_lit is None else reference_lit
    ref = make_reference(ref_lit, surfaces.valid, surfaces.position_m)
    row = {**common, "technique": "raytrace", "map_px": "", "runs": settings.repeat,
           "warmup_s": secs[0], "shadow_s": _median(secs[1:]), "valid_px": int(ref.valid.sum()),
           "wrong_px": 0, "misclassified_pct": 0.0, "false_lit_pct": 0.0,
           "false_shadow_pct": 0.0, "lit_mae": 0.0, "edge_mean_m": 0.0, "edge_p95_m": 0.0,
           "edge_max_m": 0.0, "aliasing_max_m": "", "aliasing_mean_m": "",
           "traced_share": 1.0, "stages": _fmt_stages(_stage_medians(diags[1:])), "error": ""}
    bad = _finite_check(ref_result)
    if bad:
        row["error"] = bad
    row["frame_s"] = gbuffer_s + resolve_s + row["shadow_s"]
    evaluation.rows.append(row)
    skipped = evaluation.skipped.setdefault(view, [])
    if not skipped:
        skipped += skipped_work(scene, gbuf.stats, ref_result.diagnostics, surfaces, sun)
    _keep_picture(scene, camera, gbuf, surfaces, ref.lit, sun, view, label, evaluation)
    results: dict[tuple[str, int | None], Any] = {("raytrace", None): ref_result}
    for name in techniques:
        tech = get_technique(name)
        for size in (sizes if uses_map(name) else [None]):
            if progress:
                progress(f"{view} {label} {name} {size or ''}".rstrip())
            opts = dict(base_opts)
            if size is not None:
                opts["map_px"] = int(size)
            ctx = ShadowContext(scene=scene, surfaces=surfaces, camera=camera, sun=sun,
                                t_days=t_days, options=opts)
            row = {**common, "technique": name, "map_px": size or "", "runs": settings.repeat}
            try:
                secs, diags, result = _timed_runs(tech, ctx, runs)
            except Exception as exc:  # a crash is a result of the evaluation, not its end
                row.update(error=f"{type(exc).__name__}: {exc}", warmup_s="", shadow_s="",
                           frame_s="")
                evaluation.rows.append(row)
                results[(name, size)] = exc
                continue
            results[(name, size)] = result
            err = compare(result.lit, ref, settings.edge_percentile)
            d = result.diagnostics
            alias = d.get("aliasing_m") or {}
            if not (alias.get("max") or alias.get("mean")):
                alias = {}   # not measured (e.g. hybrid's base in classify-only mode)
            row.update({
                "warmup_s": secs[0], "shadow_s": _median(secs[1:]),
                "valid_px": err["valid_px"], "wrong_px": err["wrong_px"],
                **{k: err[k] for k in ("misclassified_pct", "false_lit_pct", "false_shadow_pct",
                                       "lit_mae", "edge_mean_m", "edge_p95_m", "edge_max_m")},
                "aliasing_max_m": alias.get("max", ""), "aliasing_mean_m": alias.get("mean", ""),
                "traced_share": d.get("traced_share", ""),
                "stages": _fmt_stages(_stage_medians(diags[1:])),
                "error": _finite_check(result) or "",
            })
            row["frame_s"] = gbuffer_s + resolve_s + row["shadow_s"]
            evaluation.rows.append(row)
            if len(skipped) and not any(s.startswith(("shadow map", "hybrid")) for s in skipped):
                skipped += [s for s in skipped_work(scene, None, d) if
                            s.startswith(("shadow map", "base shadow map", "hybrid"))]
            _keep_worst(evaluation, settings.worst_cases, Case(
                view, label, name, size, err["misclassified_pct"], err["false_lit"],
                err["false_shadow"]))
    return {"gbuffer": gbuf, "surfaces": surfaces, "reference": ref, "results": results}


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
    from cityshade.shading import shade, to_srgb8

    if evaluation.meta.get("no_pictures"):
        return
    rgb = shade(scene, surfaces, camera, ref_lit.astype(np.float32), sun.direction,
                prim_id=gbuf.prim_id)
    evaluation.pictures[(view, label)] = to_srgb8(rgb)


def make_camera(scene, view: str, size: tuple[int, int] = (1280, 720),
                pixel_size_m: float | None = None, t_days: float | None = None):
    """Camera of a view name: ``overview``, ``map`` or a preset of ``configs/cameras.toml``."""
    from cityshade.raster import camera as cams

    w, h = size
    if view == "overview":
        return cams.overview(scene, w, h, t_days=t_days)
    if view == "map":
        return cams.map_view(scene, pixel_size_m)
    return cams.preset(view, scene, w, h)


def run_evaluation(scene, views: Sequence[tuple[str, Any]], suns: Sequence, t_days: float,
                   techniques: Sequence[str], settings: EvaluateSettings | None = None,
                   options: dict | None = None,
                   progress: Callable[[int, int, str], None] | None = None,
                   model: str = "") -> Evaluation:
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
    options : dict, optional
        Technique options besides ``map_px`` (e.g. ``cascades``).
    progress : callable(done, total, label), optional
        Called before each technique run.
    model : str
        Name of the model for the rows.

    Returns
    -------
    Evaluation
    """
    settings = settings or EvaluateSettings()
    if scene.kdtree is None:
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
        for sun in suns:
            evaluate_frame(scene, camera, view, sun, t_days, techniques, settings.sizes,
                           settings, evaluation, options, step)
    for row in evaluation.rows:
        row["model"] = model
    if progress:
        progress(total, total, "done")
    return evaluation


# --- report ---------------------------------------------------------------------------------

CSV_COLUMNS = ("model", "view", "view_px", "camera", "sun", "sun_az_deg", "sun_el_deg",
               "technique", "map_px", "runs", "warmup_s", "shadow_s", "gbuffer_s", "resolve_s",
               "frame_s", "valid_px", "wrong_px", "misclassified_pct", "false_lit_pct",
               "false_shadow_pct", "lit_mae", "edge_mean_m", "edge_p95_m", "edge_max_m",
               "aliasing_max_m", "aliasing_mean_m", "traced_share", "stages", "error")


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def write_csv(path, rows: Sequence[dict]) -> None:
    """``results.csv``: one row per view × sun × technique × map size (:data:`CSV_COLUMNS`)."""
    from cityshade.util import atomic_write

    with atomic_write(path, newline="", what="the results table") as fh:
        writer = csv.writer(fh)
        writer.writerow(CSV_COLUMNS)
        for row in rows:
            writer.writerow([_cell(row.get(c)) for c in CSV_COLUMNS])


def summary(rows: Sequence[dict]) -> dict[str, list[dict[str, Any]]]:
    """Per view: one entry per (technique, map size), averaged over the suns.

    Error figures are means over the suns, times are medians; entries carry ``key``
    (``technique@size``) and are sorted by time.
    """
    groups: dict[str, dict[tuple, list[dict]]] = {}
    for r in rows:
        if r.get("error") or r.get("shadow_s") in ("", None):
            continue
        groups.setdefault(r["view"], {}).setdefault((r["technique"], r["map_px"]), []).append(r)
    out: dict[str, list[dict[str, Any]]] = {}
    for view, g in groups.items():
        entries = []
        for (tech, size), rs in g.items():
            def mean(key):
                vals = [float(r[key]) for r in rs if r.get(key) not in ("", None)]
                return statistics.fmean(vals) if vals else None

            entries.append({
                "technique": tech, "map_px": size, "key": f"{tech}@{size}" if size else tech,
                "shadow_s": _median([float(r["shadow_s"]) for r in rs]),
                "warmup_s": _median([float(r["warmup_s"]) for r in rs]),
                "frame_s": _median([float(r["frame_s"]) for r in rs]),
                **{k: mean(k) for k in ("misclassified_pct", "false_lit_pct", "false_shadow_pct",
                                        "lit_mae", "edge_mean_m", "edge_p95_m",
                                        "aliasing_max_m", "aliasing_mean_m", "traced_share")},
                "suns": len(rs),
            })
        entries.sort(key=lambda e: e["shadow_s"])
        front = pareto_front([e["shadow_s"] for e in entries],
                             [e["misclassified_pct"] for e in entries])
        for i, e in enumerate(entries):
            e["pareto"] = i in front
        out[view] = entries
    return out


def _f(value, fmt: str, empty: str = "–") -> str:
    return empty if value in (None, "") else format(float(value), fmt)


def report_markdown(evaluation: Evaluation, images: dict[str, list[str]] | None = None,
                    title: str | None = None, heading_level: int = 1) -> str:
    """The Markdown report: a reading of the Pareto front, then the table of every view."""
    h = "#" * heading_level
    meta = evaluation.meta
    lines = [f"{h} {title or 'Shadow error against run time'}", ""]
    if meta.get("model"):
        lines.append(f"Model `{meta['model']}`; city time {meta.get('city_time', '')}; "
                     f"map sizes {', '.join(str(s) for s in meta.get('sizes', []))}; "
                     f"{meta.get('repeat', '')} timed runs after one warm-up run.")
        lines.append("")
    lines += ["Error: pixels whose sun/shadow class differs from `raytrace` on the same pixels "
              "(% of surface pixels, mean over the suns); edge: distance from a wrong pixel to "
              "the nearest pixel that truly has its class (metres); shadow: median time of the "
              "shadow stage as `render` runs it (ms); warm-up: the first run.", ""]
    images = images or {}
    for view, entries in summary(evaluation.rows).items():
        lines += [f"{h}# View `{view}`", ""]
        front = [e for e in entries if e["pareto"]]
        rt = next((e for e in entries if e["technique"] == "raytrace"), None)
        reading = ", then ".join(f"`{e['key']}` ({_f(e['misclassified_pct'], '.3f')} % wrong, "
                                 f"{e['shadow_s'] * 1000:.1f} ms)" for e in front)
        lines.append(f"Pareto front (fastest first): {reading}.")
        if rt is not None:
            cheaper = [e for e in entries if e["shadow_s"] < rt["shadow_s"]
                       and e["technique"] != "raytrace"]
            exact = [e for e in entries if e["technique"] != "raytrace"
                     and (e["misclassified_pct"] or 0.0) == 0.0]
            lines.append(f"`raytrace` (exact) takes {rt['shadow_s'] * 1000:.1f} ms; "
                         f"{len(cheaper)} of {len(entries) - 1} technique/size pairs are faster; "
                         f"{len(exact)} match it exactly"
                         + (f" (fastest: `{min(exact, key=lambda e: e['shadow_s'])['key']}`)"
                            if exact else "") + ".")
        lines.append("")
        lines.append("| technique | map px | shadow ms | warm-up ms | wrong % | false-lit % | "
                     "false-shadow % | lit MAE | edge mean m | edge p95 m | alias m max | "
                     "alias m mean | traced % | front |")
        lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|")
        for e in entries:
            lines.append(
                f"| `{e['technique']}` | {e['map_px'] or '–'} | {e['shadow_s'] * 1000:.1f} | "
                f"{e['warmup_s'] * 1000:.1f} | {_f(e['misclassified_pct'], '.3f')} | "
                f"{_f(e['false_lit_pct'], '.3f')} | {_f(e['false_shadow_pct'], '.3f')} | "
                f"{_f(e['lit_mae'], '.4f')} | {_f(e['edge_mean_m'], '.3f')} | "
                f"{_f(e['edge_p95_m'], '.3f')} | {_f(e['aliasing_max_m'], '.3g')} | "
                f"{_f(e['aliasing_mean_m'], '.3g')} | "
                f"{_f(None if e['traced_share'] is None else 100 * e['traced_share'], '.2f')} | "
                f"{'●' if e['pareto'] else ''} |")
        lines.append("")
        failures = [r for r in evaluation.rows if r["view"] == view and r.get("error")]
        for r in failures:
            lines.append(f"- **failed**: `{r['technique']}` map {r['map_px'] or '–'} "
                         f"{r['sun']}: {r['error']}")
        if failures:
            lines.append("")
        skipped = evaluation.skipped.get(view) or []
        if skipped:
            lines += ["Left out because this scene and view did not need it:", ""]
            lines += [f"- {s}" for s in skipped]
            lines.append("")
        for img in images.get(view, []):
            lines.append(f"![{Path(img).stem}]({img})")
        if images.get(view):
            lines.append("")
    return "\n".join(lines)


def diff_image(picture: np.ndarray, false_lit: np.ndarray, false_shadow: np.ndarray) -> np.ndarray:
    """(H, W, 3) uint8: the picture dimmed to grey, false-lit pixels red, false-shadow blue."""
    pic = np.asarray(picture, np.float32)
    grey = (0.25 * pic.mean(axis=2, keepdims=True) + 0.5 * 255 * 0.25).repeat(3, axis=2)
    out = np.clip(grey + 0.35 * pic, 0, 255).astype(np.uint8)
    out[false_lit] = (230, 20, 20)
    out[false_shadow] = (20, 60, 230)
    return out


def _safe(text: str) -> str:
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in text)


def write_report(evaluation: Evaluation, outdir, title: str | None = None) -> list[Path]:
    """Write ``results.csv``, ``report.md``, ``error_vs_time_<view>.png`` and the worst cases'
    ``diff_<view>_<technique>_<size>.png`` into ``outdir`` (created). Returns the paths."""
    from cityshade import imageio
    from cityshade.util import write_text_atomic

    outdir = Path(outdir)
    try:
        outdir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the report folder: {exc.strerror}",
                          path=str(outdir)) from None
    written = []
    write_csv(outdir / "results.csv", evaluation.rows)
    written.append(outdir / "results.csv")
    images: dict[str, list[str]] = {}
    for view, entries in summary(evaluation.rows).items():
        png = outdir / f"error_vs_time_{_safe(view)}.png"
        imageio.write_image(png, error_time_plot(entries, f"{evaluation.meta.get('model', '')} "
                                                          f"{view}".strip()))
        written.append(png)
        images.setdefault(view, []).append(png.name)
    for view, cases in evaluation.worst.items():
        for case in cases:
            picture = evaluation.pictures.get((view, case.sun_label))
            if picture is None:
                continue
            name = _safe(f"diff_{view}_{case.technique}_{case.map_px or ''}_{case.sun_label}")
            png = outdir / f"{name}.png"
            imageio.write_image(png, diff_image(picture, case.false_lit, case.false_shadow))
            written.append(png)
            images.setdefault(view, []).append(png.name)
    md = outdir / "report.md"
    write_text_atomic(md, report_markdown(evaluation, images, title) + "\n", what="the report")
    written.append(md)
    return written


# --- the error-against-time plot (numpy raster, no plotting library) --------------------------

#: 3×5 glyphs (rows top to bottom, 1 = ink) of the plot's labels.
_FONT = {
    "a": "010101111101101", "b": "110101110101110", "c": "011100100100011",
    "d": "110101101101110", "e": "111100110100111", "f": "111100110100100",
    "g": "011100101101011", "h": "101101111101101", "i": "111010010010111",
    "j": "001001001101010", "k": "101101110101101", "l": "100100100100111",
    "m": "101111111101101", "n": "110101101101101", "o": "010101101101010",
    "p": "110101110100100", "q": "010101101110011", "r": "110101110101101",
    "s": "011100010001110", "t": "111010010010010", "u": "101101101101111",
    "v": "101101101101010", "w": "101101111111101", "x": "101101010101101",
    "y": "101101010010010", "z": "111001010100111",
    "0": "111101101101111", "1": "010110010010111", "2": "111001111100111",
    "3": "111001111001111", "4": "101101111001001", "5": "111100111001111",
    "6": "111100111101111", "7": "111001001001001", "8": "111101111101111",
    "9": "111101111001111", " ": "000000000000000", ".": "000000000000010",
    ",": "000000000010100", ":": "000010000010000", "+": "000010111010000",
    "-": "000000111000000", "%": "101001010100101", "@": "010101111100011",
    "(": "010100100100010", ")": "010001001001010", "/": "001001010100100",
    "=": "000111000111000", "_": "000000000000111", "*": "000101010101000",
}

#: Colour per base technique (Okabe–Ito palette, distinguishable with colour-blindness).
_COLOURS = {"raytrace": (0, 0, 0), "shadowmap": (230, 159, 0), "pcf": (86, 180, 233),
            "vsm": (0, 158, 115), "psm": (204, 121, 167), "lispsm": (213, 94, 0),
            "xpsm": (0, 114, 178), "csm": (120, 120, 120)}


def _text(img: np.ndarray, text: str, x: int, y: int, scale: int = 2,
          colour=(0, 0, 0)) -> int:
    """Draw ``text`` with its top-left at (x, y), clipped; returns the x after the text."""
    h, w = img.shape[:2]
    for ch in text.lower():
        glyph = _FONT.get(ch, _FONT["*"])
        for k, bit in enumerate(glyph):
            if bit == "1":
                r, c = divmod(k, 3)
                y0, x0 = y + r * scale, x + c * scale
                img[max(y0, 0):max(min(y0 + scale, h), 0),
                    max(x0, 0):max(min(x0 + scale, w), 0)] = colour
        x += 4 * scale
    return x


def _line(img: np.ndarray, x0: float, y0: float, x1: float, y1: float, colour,
          width: int = 1) -> None:
    """A straight line sampled at half-pixel steps, ``width`` pixels thick."""
    n = int(max(abs(x1 - x0), abs(y1 - y0)) * 2) + 1
    xs = np.rint(np.linspace(x0, x1, n)).astype(np.int64)
    ys = np.rint(np.linspace(y0, y1, n)).astype(np.int64)
    h, w = img.shape[:2]
    for dy in range(-(width // 2), width - width // 2):
        for dx in range(-(width // 2), width - width // 2):
            ok = (ys + dy >= 0) & (ys + dy < h) & (xs + dx >= 0) & (xs + dx < w)
            img[ys[ok] + dy, xs[ok] + dx] = colour


def _marker(img: np.ndarray, x: float, y: float, r: int, shape: str, colour) -> None:
    """A filled marker: ``o`` disc, ``s`` square, ``^`` triangle, ``d`` diamond; black rim."""
    h, w = img.shape[:2]
    yy, xx = np.mgrid[-r - 1:r + 2, -r - 1:r + 2]
    if shape == "s":
        inside, rim = np.maximum(abs(xx), abs(yy)) <= r, np.maximum(abs(xx), abs(yy)) <= r + 1
    elif shape == "^":
        inside = (yy >= -r) & (yy <= r) & (abs(xx) <= (yy + r) / 2.0)
        rim = (yy >= -r - 1) & (yy <= r + 1) & (abs(xx) <= (yy + r + 1) / 2.0 + 0.5)
    elif shape == "d":
        inside, rim = abs(xx) + abs(yy) <= r, abs(xx) + abs(yy) <= r + 1
    else:
        inside, rim = xx * xx + yy * yy <= r * r, xx * xx + yy * yy <= (r + 1) ** 2
    cx, cy = int(round(x)), int(round(y))
    for mask, col in ((rim, (0, 0, 0)), (inside, colour)):
        py, px = yy[mask] + cy, xx[mask] + cx
        ok = (py >= 0) & (py < h) & (px >= 0) & (px < w)
        img[py[ok], px[ok]] = col


def _style(technique: str) -> tuple[tuple[int, int, int], str]:
    """Colour (base technique) and marker shape (plain o, +smooth s, hybrid ^, raytrace d)."""
    base = technique.partition("+")[0]
    shape = "s" if technique.endswith("+smooth") else "o"
    if base.startswith("hybrid"):
        base, shape = base.partition(":")[2] or "vsm", "^"
    if base == "raytrace":
        shape = "d"
    return _COLOURS.get(base.partition(":")[0], (90, 90, 90)), shape


def _decades(lo: float, hi: float) -> tuple[int, int]:
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    return a, max(b, a + 1)


def _tick(exp: int) -> str:
    return f"{10.0 ** exp:g}" if exp >= -4 else f"1e{exp}"


def error_time_plot(entries: Sequence[dict], title: str = "") -> np.ndarray:
    """Error against run time on log axes, one marker per technique and size.

    Parameters
    ----------
    entries : sequence of dict
        :func:`summary` entries of one view (``technique``, ``map_px``, ``shadow_s``,
        ``misclassified_pct``, ``pareto``).
    title : str

    Returns
    -------
    (H, W, 3) uint8
        x: shadow-stage time in ms, y: misclassified pixels in %; points with no error sit on
        a "0" row below the lowest decade; marker colour = base technique, shape = plain (o),
        smoothed (square), hybrid (triangle), raytrace (diamond), size grows with the map; the
        Pareto front is the black staircase.
    """
    width, height = 1100, 640
    left, right, top, bottom = 90, 820, 50, 560
    img = np.full((height, width, 3), 255, np.uint8)
    pts = [e for e in entries if e.get("misclassified_pct") is not None]
    if not pts:
        _text(img, "no results", left, top)
        return img
    t_ms = np.array([max(e["shadow_s"] * 1000.0, 1e-3) for e in pts])
    err = np.array([float(e["misclassified_pct"]) for e in pts])
    tx0, tx1 = _decades(t_ms.min(), t_ms.max())
    nonzero = err[err > 0]
    ey0, ey1 = _decades(nonzero.min(), nonzero.max()) if nonzero.size else (-3, 0)
    zero_y = bottom - 12
    plot_bottom = bottom - 40  # the "0" row sits below the lowest decade

    def px(t):
        return left + (math.log10(t) - tx0) / (tx1 - tx0) * (right - left)

    def py(e):
        if e <= 0:
            return zero_y
        return plot_bottom - (math.log10(e) - ey0) / (ey1 - ey0) * (plot_bottom - top)

    # Grid and decade labels.
    for k in range(tx0, tx1 + 1):
        x = px(10.0 ** k)
        _line(img, x, top, x, bottom, (225, 225, 225))
        label = _tick(k)
        _text(img, label, int(x - len(label) * 4), bottom + 8)
    for k in range(ey0, ey1 + 1):
        y = py(10.0 ** k)
        _line(img, left, y, right, y, (225, 225, 225))
        label = _tick(k)
        _text(img, label, left - 8 - len(label) * 8, int(y - 5))
    _line(img, left, zero_y, right, zero_y, (225, 225, 225))
    _text(img, "0", left - 16, zero_y - 5)
    _line(img, left, top, left, bottom, (0, 0, 0))
    _line(img, left, bottom, right, bottom, (0, 0, 0))
    _text(img, "shadow stage time, ms (log)", (left + right) // 2 - 110, bottom + 28)
    _text(img, "wrong pixels, % (log)", 8, top - 30)
    if title:
        _text(img, title, left + 200, 12, 3)
    # Pareto staircase.
    front = sorted((i for i, e in enumerate(pts) if e.get("pareto")), key=lambda i: t_ms[i])
    for a, b in zip(front, front[1:]):
        xa, ya, xb, yb = px(t_ms[a]), py(err[a]), px(t_ms[b]), py(err[b])
        _line(img, xa, ya, xb, ya, (0, 0, 0), 2)
        _line(img, xb, ya, xb, yb, (0, 0, 0), 2)
    # Markers, largest first so small ones stay visible.
    order = sorted(range(len(pts)), key=lambda i: -(int(pts[i]["map_px"] or 0)))
    for i in order:
        e = pts[i]
        colour, shape = _style(e["technique"])
        size = int(e["map_px"] or 1024)
        r = int(np.clip(2 + math.log2(max(size, 256) / 256.0), 2, 8))
        _marker(img, px(t_ms[i]), py(err[i]), r, shape, colour)
    # Legend.
    y = top
    _text(img, "colour: base technique", right + 30, y)
    y += 18
    for name, colour in _COLOURS.items():
        _marker(img, right + 38, y + 4, 4, "o" if name != "raytrace" else "d", colour)
        _text(img, name, right + 50, y)
        y += 16
    y += 10
    for shape, what in (("o", "plain"), ("s", "+smooth"), ("^", "hybrid:base"),
                        ("d", "raytrace")):
        _marker(img, right + 38, y + 4, 4, shape, (255, 255, 255))
        _text(img, what, right + 50, y)
        y += 16
    y += 10
    _text(img, "bigger marker:", right + 30, y)
    _text(img, "bigger map", right + 30, y + 14)
    y += 40
    _line(img, right + 30, y + 4, right + 46, y + 4, (0, 0, 0), 2)
    _text(img, "pareto front", right + 50, y)
    return img


# --- inputs of the command ----------------------------------------------------------------

def open_scene(path, settings=None):
    """A scene with its kd-tree: a ``.cityshade`` file is loaded, a CityGML file is built in
    memory (nothing written)."""
    from cityshade.build import build_scene_from_file
    from cityshade.scenefile import load_scene

    path = Path(path)
    if path.suffix.lower() in (".gml", ".xml"):
        return build_scene_from_file(path, settings)
    return load_scene(path)


def parse_suns(text: str, scene) -> list:
    """``"az,el;az,el"`` (degrees, azimuth from true north) → sun positions of the model."""
    from cityshade.sun import sun_from_angles

    suns = []
    for part in (p.strip() for p in text.split(";")):
        if not part:
            continue
        try:
            az, el = (float(v) for v in part.split(","))
        except ValueError:
            raise UsageError(f"--sun must be 'AZIMUTH,ELEVATION;...' in degrees, not {part!r}") \
                from None
        suns.append(sun_from_angles(az, el, scene.crs, scene.origin_m))
    if not suns:
        raise UsageError("--sun needs at least one 'AZIMUTH,ELEVATION' pair")
    return suns


def suns_of_day(day: str, times: str, tz: str | None, scene, refraction: bool = True) -> list:
    """Sun positions (SPA) at local ``times`` ("HH:MM,HH:MM") of ``day`` (YYYY-MM-DD)."""
    from cityshade.citygml.temporal import parse_user_date
    from cityshade.sun import SpaSettings, suns_from_instants

    instants = []
    for t in (s.strip() for s in times.split(",")):
        if t:
            instants.append(parse_user_date(f"{day.strip()}T{t}", tz).instant_utc)
    if not instants:
        raise UsageError("--times needs at least one HH:MM")
    return suns_from_instants(instants, scene.crs, scene.origin_m,
                              SpaSettings(refraction=refraction))
