"""Planning answers: sun-hours of the same receivers in two states of a city.

Two states are either two dates of one time-dependent model (a proposed building carries a
``validFrom`` in the future) or the existing model and the same model with a proposal added
(:func:`merge_scenes`; the existing objects, polygons and triangles keep their indices, so a
receiver means the same surface in both). :func:`compare_states` runs :func:`cityshade.sunhours.accumulate.sun_hours`
once per state over the same steps, camera and surface samples, with the sunlit stretches
(:mod:`cityshade.sunhours.stretches`) of every receiver, and derives the loss. Pixels whose surface is not
the same in both states (a new building stands there, or an old one is gone) are *changed*:
they have no loss. Openings (:func:`openings_of`) get their own denser samples and a reference
point. :func:`write_comparison` writes the pictures, rasters and tables; :mod:`cityshade.report`
... see :func:`write_report`.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from itertools import chain
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from cityshade.errors import UsageError

__all__ = ["Opening", "Comparison", "Receivers", "merge_scenes", "openings_of",
           "compare_states", "write_comparison", "loss_percent", "loss_map", "SURFACE_COLUMNS",
           "OPENING_COLUMNS"]

#: Sample density on openings (points per m²): a 1.2 m² window gets ~36 points.
OPENING_SAMPLES_PER_M2 = 30.0


@dataclass(frozen=True)
class Opening:
    """A window or door: its gml:id (the Window/Door element's, else the polygon's), object,
    class and polygons."""

    opening_id: str
    object_index: int
    surface_class: str
    polygons: tuple[int, ...]


def openings_of(scene) -> list[Opening]:
    """The openings of a scene: Window/Door elements recorded by the reader (their polygons
    grouped), then every other window/door polygon as an opening of its own (CityJSON
    semantics, scene files built before openings were kept)."""
    from cityshade.citygml.namespaces import SURFACE_CLASSES, SURFACE_CODE

    codes = (SURFACE_CODE["window"], SURFACE_CODE["door"])
    poly_class = np.asarray(scene.poly_class)
    out: list[Opening] = []
    grouped = np.zeros(len(poly_class), bool)
    for oid, polys in (scene.report or {}).get("openings", []):
        polys = tuple(int(p) for p in polys if poly_class[int(p)] in codes)
        if not polys:
            continue
        grouped[list(polys)] = True
        out.append(Opening(str(oid), int(scene.poly_object[polys[0]]),
                           SURFACE_CLASSES[int(poly_class[polys[0]])], polys))
    for p in np.flatnonzero(np.isin(poly_class, codes) & ~grouped):
        pid = scene.poly_ids[p] or f"{scene.obj_ids[int(scene.poly_object[p])]}#polygon{p}"
        out.append(Opening(pid, int(scene.poly_object[p]), SURFACE_CLASSES[int(poly_class[p])],
                           (int(p),)))
    return out


def merge_scenes(existing, proposal, settings=None):
    """The existing scene with the proposal's objects added (same CRS), with a new kd-tree.

    The existing arrays come first, so its object, polygon and triangle indices stay valid;
    the proposal's coordinates are moved into the existing scene's origin.

    Raises
    ------
    UsageError
        The two scenes are in different (or unknown) CRSs.
    """
    from cityshade.build import build_tree
    from cityshade.config import Settings
    from cityshade.geometry.scene import append_scene

    ea, pa = existing.crs.horizontal_epsg, proposal.crs.horizontal_epsg
    if ea != pa or (ea is None and existing.crs.name != proposal.crs.name):
        raise UsageError(f"the proposal's CRS ({proposal.crs.name}) is not the model's "
                         f"({existing.crs.name}); give both in the same CRS")
    no, npoly = len(existing.obj_ids), len(existing.poly_ids)
    scene = append_scene(existing, proposal)
    scene.report = {**(existing.report or {}),
                    "openings": list((existing.report or {}).get("openings", [])) + [
                        [oid, [int(p) + npoly for p in polys]]
                        for oid, polys in (proposal.report or {}).get("openings", [])],
                    "proposal_objects": [no, no + len(proposal.obj_ids)]}
    scene.kdtree = build_tree(scene, settings or Settings(), None, {})
    return scene


@dataclass
class Comparison:
    """Result of :func:`compare_states`.

    Pixel arrays are (H, W) float32, NaN where there is no surface; ``loss_*`` also NaN on
    ``changed`` pixels. Per polygon (P,) float64, NaN where not sampled. Per opening (O,)
    float64. ``*_longest_h``: the longest continuous sunlit stretch.
    """

    before: Any
    after: Any
    camera: Any
    scene_before: Any
    scene_after: Any
    t_before_days: float
    t_after_days: float
    step_h: float
    changed: np.ndarray | None = None
    loss_h: np.ndarray | None = None
    loss_pct: np.ndarray | None = None
    polygon_before_h: np.ndarray | None = None
    polygon_after_h: np.ndarray | None = None
    polygon_standing_after: np.ndarray | None = None
    openings: list[Opening] = field(default_factory=list)
    opening: dict[str, np.ndarray] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    light: dict[str, Any] = field(default_factory=dict)
    #: The proposal's own surfaces (receivers after only): ``polygons`` (indices into the
    #: scene after), ``samples``, ``after_h`` and ``longest_after_h`` per polygon; None when
    #: the state after adds no surface.
    proposal: dict[str, np.ndarray] | None = None

    @property
    def samples(self):
        return self.before.samples


def _standing(scene, t_days: float) -> np.ndarray:
    """(P,) bool: polygons whose object stands at ``t_days``."""
    obj = np.asarray(scene.poly_object)
    return ((np.asarray(scene.obj_t_begin_days)[obj] <= t_days)
            & (t_days < np.asarray(scene.obj_t_end_days)[obj]))


def loss_percent(before, after):
    """Loss in % of the hours before (NaN where there were none), elementwise."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(before > 0, 100.0 * (before - after) / before, np.nan)


@dataclass(frozen=True, eq=False)
class Receivers:
    """The surface receivers of :func:`compare_states` and how their stretches count.

    Attributes
    ----------
    samples_per_m2 : float or None
        Sample density on the polygons standing before (None: no surface receivers except
        the openings).
    opening_samples_per_m2 : float
        Density on windows and doors (0: like the other polygons).
    polygons : (P,) bool, optional
        Only these polygons are surface receivers (rules that look at some surfaces only).
    min_stretch_h : float
        Stretches shorter than this do not count toward the ``qualified`` hours.
    """

    samples_per_m2: float | None = 1.0
    opening_samples_per_m2: float = OPENING_SAMPLES_PER_M2
    polygons: np.ndarray | None = None
    min_stretch_h: float = 0.0


def compare_states(scene_before, t_before_days: float, scene_after, t_after_days: float,
                   camera, steps: Sequence, receivers: Receivers | None = None, *,
                   technique: str = "exact", settings=None, ground: str | None = None, suns=None,
                   on_step: Callable[[int, int], None] | None = None) -> Comparison:
    """Sun-hours before and after, on the same receivers.

    Parameters
    ----------
    scene_before, scene_after : Scene
        The same scene (two dates) or the existing one and :func:`merge_scenes`'s result.
    t_before_days, t_after_days : float
        City times of the two states.
    camera : Camera or None
        Pixel receivers (the same view in both states); None: surfaces only.
    steps : sequence of cityshade.sunhours.plan.Step
        Time steps (:func:`cityshade.sunhours.plan.plan_steps`).
    receivers : Receivers, optional
        Surface samples (default: 1 per m² on every polygon standing before, denser on the
        openings) and the shortest stretch that counts.
    technique : str
        An exact technique.
    settings : cityshade.config.Settings, optional
        ``[shadows]``, ``[sun]`` (when ``suns`` is None) and ``[batch]`` (``reuse_rays``).
    ground : str, optional
        Ground plane (``auto``, ``min``, metres), placed once from ``scene_before``.
    suns : sequence of Sun, optional
        One per step (default: the sun at the steps' centres).
    on_step : callable(done, total), optional
        Progress over both states' sun positions.
    """
    from cityshade.config import Settings
    from cityshade.geo.sun import suns_from_instants
    from cityshade.sunhours.accumulate import sun_hours
    from cityshade.sunhours.plan import plan_units
    from cityshade.sunhours.stretches import Stretches
    from cityshade.sunhours.surfaces import sample_surfaces

    settings = settings or Settings()
    receivers = receivers or Receivers()
    samples_per_m2, polygons = receivers.samples_per_m2, receivers.polygons
    opening_samples_per_m2 = receivers.opening_samples_per_m2
    if not steps:
        raise UsageError("a comparison needs at least one time step")
    instants = [s.centre_utc for s in steps]
    weights = [s.weight_h for s in steps]
    if suns is None:
        suns = suns_from_instants(instants, scene_before.crs, scene_before.origin_m,
                                  settings.sun)
    if ground is not None:
        from cityshade.geometry.ground import ground_height_m

        # One height for both states (a proposal must not move the ground plane).
        ground = repr(ground_height_m(scene_before, ground) + float(scene_before.origin_m[2]))

    # Receivers: surface samples of the polygons standing before, denser on openings.
    openings = openings_of(scene_before)
    n_poly = len(scene_before.poly_ids)
    density = np.full(n_poly, float(samples_per_m2 or 0.0))
    if polygons is not None:
        density[~np.asarray(polygons, bool)] = 0.0
    if opening_samples_per_m2 > 0:
        for o in openings:
            for p in o.polygons:
                if polygons is None or polygons[p]:
                    density[p] = opening_samples_per_m2
    samples = None
    if density.any():
        samples = sample_surfaces(scene_before, 1.0, float(t_before_days),
                                  settings=None, polygon_density=density)
    if camera is None and samples is None:
        raise UsageError("nothing to compare: no pixels and no surface receivers")
    # A proposal's own surfaces are receivers of the state after (polygons is None: every
    # surface is asked for), sampled after the shared samples.
    samples_after = samples
    if samples is not None and polygons is None:
        samples_after = _with_proposal_samples(samples, scene_before, scene_after,
                                               float(t_after_days), float(samples_per_m2 or 0))
    n_units = len(plan_units(suns, weights)[0])
    results = []
    for k, (scene, t, smp) in enumerate(((scene_before, t_before_days, samples),
                                         (scene_after, t_after_days, samples_after))):
        def progress(done, total, unit, k=k):
            if on_step is not None:
                on_step(k * n_units + done, 2 * n_units)

        results.append(sun_hours(
            scene, camera, instants, float(t), weights_h=weights, technique=technique,
            shadows=settings.shadows, ground=ground, suns=suns, samples=smp,
            reuse_rays=settings.batch.reuse_rays, on_step=progress,
            stretches=Stretches.for_steps(steps, receivers.min_stretch_h)))
    before, after = results
    proposal = _split_proposal(after, samples, n_poly) if samples_after is not samples else None
    comp = Comparison(before=before, after=after, camera=camera, scene_before=scene_before,
                      scene_after=scene_after, t_before_days=float(t_before_days),
                      t_after_days=float(t_after_days),
                      step_h=float(max(weights)) if weights else 0.0,
                      warnings=[w for w in before.warnings] +
                      [w for w in after.warnings if w not in before.warnings],
                      proposal=proposal)
    if camera is not None:
        same = (before.valid & after.valid
                & (np.asarray(before.surfaces.obj_id) == np.asarray(after.surfaces.obj_id)))
        comp.changed = (before.valid | after.valid) & ~same
        b = np.where(same, before.hours, np.nan)
        a = np.where(same, after.hours, np.nan)
        comp.loss_h = (b - a).astype(np.float32)
        comp.loss_pct = loss_percent(b, a).astype(np.float32)
    if samples is not None:
        standing = _standing(scene_after, float(t_after_days))[:n_poly]
        comp.polygon_standing_after = standing
        comp.polygon_before_h = before.polygon_hours
        comp.polygon_after_h = np.where(standing, after.polygon_hours, np.nan)
        comp.openings = [o for o in openings if samples.sampled[list(o.polygons)].any()]
        comp.opening = _opening_results(comp)
    return comp


def _with_proposal_samples(samples, scene_before, scene_after, t_days: float,
                           samples_per_m2: float):
    """``samples`` followed by samples on the proposal's polygons (those after the existing
    ones in :func:`merge_scenes`'s scene), or ``samples`` itself when there are none."""
    from cityshade.sunhours.surfaces import SurfaceSamples, sample_surfaces

    n_poly, n_after = len(scene_before.poly_ids), len(scene_after.poly_ids)
    if scene_after is scene_before or n_after == n_poly or samples_per_m2 <= 0:
        return samples
    density = np.zeros(n_after)
    density[n_poly:] = samples_per_m2
    extra = sample_surfaces(scene_after, 1.0, t_days, polygon_density=density)
    if not extra.n:
        return samples
    sampled = extra.sampled.copy()
    sampled[:n_poly] = samples.sampled
    cat = np.concatenate
    return SurfaceSamples(points_m=cat([samples.points_m, extra.points_m]),
                          normals=cat([samples.normals, extra.normals]),
                          weight_m2=cat([samples.weight_m2, extra.weight_m2]),
                          polygon=cat([samples.polygon, extra.polygon]).astype(np.int32),
                          sampled=sampled, samples_per_m2=samples.samples_per_m2)


def _split_proposal(after, samples, n_poly: int) -> dict[str, np.ndarray]:
    """The proposal's per-polygon results out of the run after, whose samples and
    stretches are then cut back to the shared ``samples`` (so both states' arrays match)."""
    n = samples.n
    extra_poly = np.asarray(after.samples.polygon[n:])
    polygons = np.unique(extra_poly)
    longest = np.full(int(after.samples.sampled.shape[0]), -np.inf)
    track = after.stretches.samples
    np.maximum.at(longest, extra_poly, track.longest_h[n:])
    out = {"polygons": polygons,
           "samples": np.bincount(extra_poly, minlength=len(longest))[polygons],
           "after_h": np.asarray(after.polygon_hours)[polygons],
           "longest_after_h": longest[polygons]}
    after.samples = samples
    after.sample_hours = np.asarray(after.sample_hours)[:n]
    after.polygon_hours = np.asarray(after.polygon_hours)[:n_poly]
    for name in ("current_h", "longest_h", "qualified_h"):
        setattr(track, name, getattr(track, name)[:n])
    return out


def _opening_results(comp: Comparison) -> dict[str, np.ndarray]:
    """Per opening: area, samples, mean hours before/after, and at its reference point (the
    sample nearest the opening's area centroid) hours, longest stretch and qualified hours."""
    samples = comp.samples
    scene = comp.scene_before
    n = len(comp.openings)
    out = {k: np.full(n, np.nan) for k in (
        "area_m2", "samples", "before_h", "after_h", "ref_before_h", "ref_after_h",
        "ref_longest_before_h", "ref_longest_after_h", "ref_qualified_before_h",
        "ref_qualified_after_h", "facing_deg")}
    out["ref_sample"] = np.full(n, -1, np.int64)
    if not n:
        return out
    opening_of_poly = np.full(len(scene.poly_ids), -1, np.int64)
    for k, o in enumerate(comp.openings):
        opening_of_poly[list(o.polygons)] = k
    sample_opening = opening_of_poly[samples.polygon]
    b_h, a_h = comp.before.sample_hours, comp.after.sample_hours
    bs, as_ = comp.before.stretches.samples, comp.after.stretches.samples
    for k, o in enumerate(comp.openings):
        idx = np.flatnonzero(sample_opening == k)
        if not len(idx):
            continue
        w = samples.weight_m2[idx]
        centroid = (samples.points_m[idx] * w[:, None]).sum(axis=0) / w.sum()
        ref = int(idx[np.argmin(np.linalg.norm(samples.points_m[idx] - centroid, axis=1))])
        normal = (samples.normals[idx] * w[:, None]).sum(axis=0)
        standing = bool(comp.polygon_standing_after[list(o.polygons)].all())
        out["area_m2"][k] = float(np.asarray(scene.poly_area_m2)[list(o.polygons)].sum())
        out["samples"][k] = len(idx)
        out["before_h"][k] = float((b_h[idx] * w).sum() / w.sum())
        out["after_h"][k] = float((a_h[idx] * w).sum() / w.sum()) if standing else np.nan
        out["ref_sample"][k] = ref
        out["ref_before_h"][k] = b_h[ref]
        out["ref_longest_before_h"][k] = bs.longest_h[ref]
        out["ref_qualified_before_h"][k] = bs.qualified_h[ref]
        if standing:
            out["ref_after_h"][k] = a_h[ref]
            out["ref_longest_after_h"][k] = as_.longest_h[ref]
            out["ref_qualified_after_h"][k] = as_.qualified_h[ref]
        out["facing_deg"][k] = math.degrees(math.atan2(normal[0], normal[1])) % 360.0
    return out


# --- outputs ------------------------------------------------------------------------------------

SURFACE_COLUMNS = ("object_id", "polygon_id", "polygon_index", "surface_class", "area_m2",
                   "samples", "hours_before", "hours_after", "loss_h", "loss_pct",
                   "longest_before_h", "longest_after_h")
OPENING_COLUMNS = ("opening_id", "object_id", "surface_class", "polygon_ids", "area_m2",
                   "samples", "facing_deg", "hours_before", "hours_after", "loss_h", "loss_pct",
                   "ref_hours_before", "ref_hours_after", "ref_longest_before_h",
                   "ref_longest_after_h") + (
                   "vsc_before_pct", "vsc_after_pct", "apsh_before_pct", "apsh_after_pct",
                   "winter_apsh_before_pct", "winter_apsh_after_pct")
#: The light columns of the openings (:mod:`cityshade.planning.light`, fractions in
#: ``Comparison.opening``) and their percentage columns in openings.csv; empty when not computed.
LIGHT_COLUMNS = {"vsc_before_pct": "vsc_before", "vsc_after_pct": "vsc_after",
                 "apsh_before_pct": "apsh_before", "apsh_after_pct": "apsh_after",
                 "winter_apsh_before_pct": "winter_apsh_before",
                 "winter_apsh_after_pct": "winter_apsh_after"}


def light_percent(comp, column: str) -> np.ndarray:
    """(O,) an openings.csv light column (``vsc_before_pct``, ...) in %, NaN when not computed."""
    values = comp.opening.get(LIGHT_COLUMNS[column])
    return np.full(len(comp.openings), np.nan) if values is None else 100.0 * values


def _f(v, digits=4) -> str:
    return "" if v is None or not np.isfinite(v) else f"{float(v):.{digits}f}"


def polygon_longest(comp: Comparison, which: str) -> np.ndarray:
    """(P,) the longest stretch of any sample of each polygon (before or after)."""
    res = comp.before if which == "before" else comp.after
    longest = res.stretches.samples.longest_h
    out = np.full(len(comp.scene_before.poly_ids), -np.inf)
    np.maximum.at(out, comp.samples.polygon, longest)
    out[~np.isfinite(out)] = np.nan
    if which == "after" and comp.polygon_standing_after is not None:
        out[~comp.polygon_standing_after] = np.nan
    return out


def surface_rows(comp: Comparison):
    """Rows of ``surfaces.csv`` as tuples (see :data:`SURFACE_COLUMNS`), numbers unformatted."""
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    scene, samples = comp.scene_before, comp.samples
    counts = np.bincount(samples.polygon, minlength=len(scene.poly_ids))
    lb, la = polygon_longest(comp, "before"), polygon_longest(comp, "after")
    b, a = comp.polygon_before_h, comp.polygon_after_h
    pct = loss_percent(b, a)
    for p in np.flatnonzero(samples.sampled):
        cls = int(scene.poly_class[p])
        yield (scene.obj_ids[int(scene.poly_object[p])], scene.poly_ids[p], int(p),
               SURFACE_CLASSES[cls] if cls < len(SURFACE_CLASSES) else str(cls),
               float(scene.poly_area_m2[p]), int(counts[p]), b[p], a[p], b[p] - a[p], pct[p],
               lb[p], la[p])


def proposal_rows(comp: Comparison):
    """Rows of ``surfaces.csv`` for the proposal's own surfaces (:data:`SURFACE_COLUMNS`; no
    value before, so no loss), their polygon index that of the scene after."""
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    if comp.proposal is None:
        return
    scene, prop, nan = comp.scene_after, comp.proposal, float("nan")
    for k, p in enumerate(prop["polygons"]):
        cls = int(scene.poly_class[p])
        yield (scene.obj_ids[int(scene.poly_object[p])], scene.poly_ids[p], int(p),
               SURFACE_CLASSES[cls] if cls < len(SURFACE_CLASSES) else str(cls),
               float(scene.poly_area_m2[p]), int(prop["samples"][k]), nan,
               float(prop["after_h"][k]), nan, nan, nan, float(prop["longest_after_h"][k]))


def loss_map(comp: Comparison) -> tuple[np.ndarray, float]:
    """((H, W, 3) uint8 map of the loss in hours, gains shown as 0, changed pixels grey; the
    top of its colour scale in hours)."""
    from cityshade.sunhours.outputs import colour_mapped

    loss = np.where(np.isfinite(comp.loss_h), np.maximum(comp.loss_h, 0.0), np.nan)
    rgb, vmax_h = colour_mapped(loss)
    rgb[comp.changed] = CHANGED_RGB
    return rgb, vmax_h


#: Pixels built over or demolished (no loss) in the loss maps.
CHANGED_RGB = (150, 150, 150)


def loss_picture(comp: Comparison) -> np.ndarray:
    """(H + legend, W, 3) uint8: the loss in hours colour-mapped with its legend (gains shown as
    0), changed pixels grey."""
    from cityshade.sunhours.outputs import colour_map_png

    loss = np.where(np.isfinite(comp.loss_h), np.maximum(comp.loss_h, 0.0), np.nan)
    img = colour_map_png(loss)
    h, w = comp.changed.shape
    img[:h, :w][comp.changed] = CHANGED_RGB  # built over or demolished: no loss
    return img


def _pictures(comp: Comparison, meta: dict[str, Any], decorate: bool):
    """(name, picture) of before.png, after.png (one colour scale) and loss.png: a map view
    ``decorate``-d (:func:`cityshade.sunhours.outputs.map_picture`), else with legend bands."""
    from cityshade.sunhours.outputs import colour_map_png, colour_mapped, map_picture

    before, after = comp.before, comp.after
    finite = np.concatenate([h[np.isfinite(h)] for h in (before.hours, after.hours)])
    vmax = max(1.0, math.ceil(float(finite.max()))) if finite.size else 1.0
    scene = comp.scene_before
    cam = comp.camera if decorate else None
    for name, hours in (("before", before.hours), ("after", after.hours)):
        label = meta.get(f"cityshade:{name}", name)
        picture = map_picture(colour_mapped(hours, vmax)[0], vmax, cam, scene,
                              title=f"Sun-hours {name}: {label}")
        yield name, colour_map_png(hours, vmax) if picture is None else picture
    rgb, vmax_loss = loss_map(comp)
    picture = map_picture(rgb, vmax_loss, cam, scene, label="loss of sun-hours (h)",
                          title="Loss (before − after); grey: built over or demolished")
    yield "loss", loss_picture(comp) if picture is None else picture


def write_comparison(outdir, comp: Comparison, meta: dict[str, Any],
                     decorate: bool = True) -> list[Path]:
    """Write ``compare.exr`` (before_h, after_h, loss_h, loss_pct, longest stretches, changed,
    objid), ``before.png``/``after.png`` (one colour scale) and ``loss.png`` (a map view
    ``decorate``-d with title, scale bar, north, CRS and colour bar; else with legend bands),
    for map views ``before_h/after_h/loss_h/loss_pct.tif`` (+ .tfw, .prj), ``surfaces.csv``
    and ``openings.csv``. Returns the paths written."""
    from cityshade import imageio
    from cityshade.util import atomic_write

    outdir = Path(outdir)
    written: list[Path] = []
    attrs = {k: str(v) for k, v in meta.items()}
    cam = comp.camera
    if cam is not None:
        before, after = comp.before, comp.after
        lb = np.where(before.valid, before.stretches.pixel_longest_h(), np.nan)
        la = np.where(after.valid, after.stretches.pixel_longest_h(), np.nan)
        exr = outdir / "compare.exr"
        imageio.write_exr(exr, {
            "before_h": before.hours, "after_h": after.hours, "loss_h": comp.loss_h,
            "loss_pct": comp.loss_pct, "longest_before_h": lb.astype(np.float32),
            "longest_after_h": la.astype(np.float32), "changed": comp.changed.astype(np.uint8),
            "objid_before": np.asarray(before.surfaces.obj_id),
            "objid_after": np.asarray(after.surfaces.obj_id)}, meta)
        written.append(exr)
        for name, picture in _pictures(comp, meta, decorate):
            png = outdir / f"{name}.png"
            imageio.write_png_rgb(png, picture, attributes=attrs)
            written.append(png)
        if cam.kind == "map":
            gt = cam.geotransform(comp.scene_before.origin_m)
            epsg = comp.scene_before.crs.horizontal_epsg
            for name, arr in (("before_h", before.hours), ("after_h", after.hours),
                              ("loss_h", comp.loss_h), ("loss_pct", comp.loss_pct)):
                written += imageio.write_georeferenced(outdir / f"{name}.tif", arr, gt,
                                                       epsg=epsg, nodata=float("nan"),
                                                       attributes=attrs)
    if comp.samples is not None:
        path = outdir / "surfaces.csv"
        with atomic_write(path, newline="", what="the surface table") as fh:
            writer = csv.writer(fh)
            writer.writerow(SURFACE_COLUMNS)
            for row in chain(surface_rows(comp), proposal_rows(comp)):
                writer.writerow(list(row[:4]) + [f"{row[4]:.3f}", row[5]] +
                                [_f(v) for v in row[6:10]] + [_f(v) for v in row[10:]])
        written.append(path)
        path = outdir / "openings.csv"
        with atomic_write(path, newline="", what="the openings table") as fh:
            writer = csv.writer(fh)
            writer.writerow(OPENING_COLUMNS)
            o = comp.opening
            scene = comp.scene_before
            light = {c: light_percent(comp, c) for c in LIGHT_COLUMNS}
            for k, op in enumerate(comp.openings):
                b, a = o["before_h"][k], o["after_h"][k]
                writer.writerow([op.opening_id, scene.obj_ids[op.object_index], op.surface_class,
                                 " ".join(scene.poly_ids[p] or str(p) for p in op.polygons),
                                 _f(o["area_m2"][k], 3), int(o["samples"][k]),
                                 _f(o["facing_deg"][k], 1), _f(b), _f(a), _f(b - a),
                                 _f(loss_percent(np.array(b), np.array(a))),
                                 _f(o["ref_before_h"][k]), _f(o["ref_after_h"][k]),
                                 _f(o["ref_longest_before_h"][k]),
                                 _f(o["ref_longest_after_h"][k])]
                                + [_f(light[c][k], 2) for c in LIGHT_COLUMNS])
        written.append(path)
    return written
