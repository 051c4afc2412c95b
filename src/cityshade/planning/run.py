"""One call for a planning question: :func:`run_compare` takes a :class:`CompareRequest` (the
model, its two states, the time plan, the receivers, the rules and where to write) and returns
a :class:`CompareResult` (the comparison, the rules' verdicts, the files written).

The run: open the model (:func:`open_compare`: the dates of the two states, the output folder
checked before any work, the time plan's steps), add the proposal, make the camera, compare
the two states (:func:`cityshade.planning.compare.compare_states`), then give every rule its own
day, window, sun altitude and receivers (:func:`run_rule`) and write the rasters, tables and
report together (:func:`cityshade.util.output_group`). ``cityshade compare`` parses its options
into these objects and prints the result; nothing here prints.
"""
from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass, field
from datetime import date
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from cityshade.errors import UsageError

__all__ = ["TimePlan", "CompareStates", "CompareRequest", "CompareInputs", "CompareResult",
           "require_exact", "open_compare", "run_compare", "run_rule", "load_proposal",
           "fit_map_view"]


def require_exact(technique: str, what: str = "compare") -> None:
    """Refuse a technique that is not exact (a comparison must not move with a map's error;
    ``what`` names the command in the message).

    Raises
    ------
    UsageError
        An unknown name (the registry's message), or a map, hybrid or smoothed technique.
    """
    from cityshade.shadows import describe, exact_technique_names

    if not describe(technique).exact:
        raise UsageError(f"{what} needs an exact technique "
                         f"({' or '.join(sorted(exact_technique_names()))}), not {technique}")


def fit_map_view(scene):
    """The default camera: a map view of the whole model, fitting 2048 px."""
    from cityshade.raster.camera import map_view

    return map_view(scene, None)


def _zone(tz: str, scene):
    """``tz``, or the solar-time tzinfo at the model's longitude (``local-mean``/``-apparent``)."""
    from cityshade.geo.sun import solar_time_zone
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    return solar_time_zone(tz, scene.crs, scene.origin_m) if tz in SOLAR_TIME_ZONES else tz


@dataclass(frozen=True)
class TimePlan:
    """The steps of a run, as ``cityshade batch`` plans them
    (:func:`cityshade.sunhours.plan.plan_steps`).

    Attributes
    ----------
    first_day : datetime.date
        First day.
    from_s, to_s : int
        Local start and end of each day, seconds after midnight (86400: midnight at its end).
    every_s : float
        Step length in seconds.
    tz : str
        IANA zone of ``from_s``/``to_s``, or ``local-mean``/``local-apparent`` (solar time at
        the model's longitude).
    days : int, optional
        Number of days (default 1), ``every_day`` apart.
    to_date : datetime.date, optional
        Last day (inclusive).
    every_day : int
        Days between days.
    """

    first_day: date
    from_s: int = 0
    to_s: int = 86_400
    every_s: float = 600.0
    tz: str = "UTC"
    days: int | None = None
    to_date: date | None = None
    every_day: int = 1

    def steps(self, scene) -> list:
        """The steps over ``scene`` (its longitude places solar time)."""
        from cityshade.sunhours.plan import plan_steps

        return plan_steps(self.first_day, self.from_s, self.to_s, self.every_s,
                          _zone(self.tz, scene), days=self.days, to_date=self.to_date,
                          every_day=self.every_day)


@dataclass(frozen=True)
class CompareStates:
    """The two states of the city: two dates of one model (``before``, ``after``), or the model
    at ``before`` and the model with ``proposal`` added.

    Attributes
    ----------
    before : str, optional
        Date or year of the state before (default: the time plan's first day).
    after : str, optional
        Date or year of the state after, on the same model.
    proposal : path or Scene, optional
        A ``.cityshade`` scene, CityGML or CityJSON file (same CRS), a mesh file (OBJ, glTF,
        GLB, PLY, STL: :mod:`cityshade.meshes.proposal`) or a loaded scene added to the model
        for the state after; its own dates decide when its objects stand.
    mesh : MeshPlacement, optional
        Units, up axis and placement of a mesh proposal
        (:class:`cityshade.meshes.proposal.MeshPlacement`; default: metres, the format's up
        axis, the mesh's own coordinates as model CRS).

    Raises
    ------
    UsageError
        Neither ``after`` nor ``proposal``, or both.
    """

    before: str | None = None
    after: str | None = None
    proposal: Any = None
    mesh: Any = None

    def __post_init__(self) -> None:
        if self.mesh is not None and not (_is_path(self.proposal) and Path(
                self.proposal).suffix.lower() in _mesh_suffixes()):
            raise UsageError("--mesh-units, --up-axis and --place are for a mesh proposal: "
                             "--with FILE.obj|.glb|.gltf|.ply|.stl")
        if self.proposal is None and self.after is None:
            raise UsageError("give --after DATE (one model, two dates) or --with PROPOSAL")
        if self.proposal is not None and self.after is not None:
            raise UsageError("give --after or --with, not both (the proposal's own dates "
                             "decide when its objects stand)")

    def labels(self, first_day: date) -> tuple[str, str]:
        """How the report names the two states."""
        name = Path(self.proposal).name if _is_path(self.proposal) else "proposal"
        return self.before or first_day.isoformat(), self.after or f"with {name}"

    def dates(self, first_day: date):
        """The two states as :class:`cityshade.geo.temporal.UserDate` (``.city_days``)."""
        from cityshade.geo.temporal import parse_user_date

        before = parse_user_date(self.labels(first_day)[0])
        return before, parse_user_date(self.after) if self.after else before


@dataclass(frozen=True)
class CompareRequest:
    """What :func:`run_compare` computes, on what, and where it writes.

    Attributes
    ----------
    scene : path or Scene
        A ``.cityshade`` file, a tiled cache folder (the view of all its tiles) or a loaded
        scene.
    plan : TimePlan
        The steps of both states (and of the rules that give no day of their own).
    states : CompareStates
        Before and after.
    camera : Camera, callable or None
        Pixel receivers: a camera, a function of the scene after (proposal added) that makes
        one, or None (surfaces only). Default: :func:`fit_map_view`.
    technique : str
        An exact technique (``izb`` or ``raytrace``).
    settings : cityshade.config.Settings, optional
        ``[shadows]``, ``[sun]`` and ``[batch]`` (``samples_per_m2``, ``reuse_rays``).
    ground : str or None
        Ground plane: ``auto``, ``min``, a height in metres, or None.
    surfaces : bool
        Per-surface sun-hours (``surfaces.csv``); openings are sampled either way.
    min_stretch_h : float
        Shortest sunlit stretch (hours) counted in the qualified hours.
    rules : sequence of cityshade.planning.rules.Rule
        Rules to assess (:func:`cityshade.planning.rules.load_rules`).
    area : (x0, y0, x1, y1), optional
        Garden area in model CRS metres for area rules that name none.
    outdir : path, optional
        Output folder (checked, and created, before any work); None: nothing is written.
    provenance : mapping, optional
        What was asked, as the report prints it (``cityshade compare`` gives its options' own
        text); None: made from these fields.
    decorate : bool
        Map views' PNGs with title, scale bar, north arrow, CRS and colour bar.
    gis : bool
        ``results.gpkg`` (and GeoJSON) of the surfaces, openings, buildings and rules.
    weather : path or Weather, optional
        An EPW, TMY3 or TMY2 file (:func:`cityshade.light.weather.read_weather`): the
        openings' probable sunlight hours (APSH) before and after, and the ``apsh`` rules
        assessed; without it those rules are not assessed.
    """

    scene: Any
    plan: TimePlan
    states: CompareStates
    camera: Any = fit_map_view
    technique: str = "exact"
    settings: Any = None
    ground: str | None = "auto"
    surfaces: bool = True
    min_stretch_h: float = 0.0
    rules: Sequence = ()
    area: tuple[float, float, float, float] | None = None
    outdir: str | os.PathLike | None = None
    provenance: Mapping[str, Any] | None = None
    decorate: bool = True
    gis: bool = True
    weather: Any = None

    def __post_init__(self) -> None:
        from cityshade.config import Settings
        from cityshade.sunhours.surfaces import SampleSettings

        require_exact(self.technique)
        if self.settings is None:
            object.__setattr__(self, "settings", Settings())
        SampleSettings(samples_per_m2=self.settings.batch.samples_per_m2)


@dataclass(frozen=True)
class CompareInputs:
    """The opened model of a request (:func:`open_compare`): the scene, the two states' dates
    (:class:`cityshade.geo.temporal.UserDate`), the time plan's steps and the weather file
    read (:class:`cityshade.light.weather.Weather`, or None)."""

    scene: Any
    before: Any
    after: Any
    steps: list
    weather: Any = None


@dataclass
class CompareResult:
    """What :func:`run_compare` returns.

    Attributes
    ----------
    comparison : cityshade.planning.compare.Comparison
        Sun-hours before and after, and the loss.
    verdicts : list of cityshade.planning.rules.Verdict
        One per rule, in the request's order.
    steps : list of cityshade.sunhours.plan.Step
        The time plan's steps.
    written : list of pathlib.Path
        The files written (empty without ``outdir``).
    """

    comparison: Any
    verdicts: list = field(default_factory=list)
    steps: list = field(default_factory=list)
    written: list = field(default_factory=list)


def _is_path(value) -> bool:
    return isinstance(value, (str, os.PathLike))


def _mesh_suffixes() -> tuple[str, ...]:
    from cityshade.meshes.proposal import MESH_SUFFIXES

    return MESH_SUFFIXES


def load_proposal(proposal, settings=None, model=None, mesh=None):
    """A scene file, a loaded scene (returned as is), a city model built in memory (nothing
    written), or a mesh file placed in ``model`` by ``mesh`` (a
    :class:`~cityshade.meshes.proposal.MeshPlacement`).

    Raises
    ------
    UsageError
        The proposal file does not exist.
    MeshFileError
        A mesh file trimesh cannot read.
    """
    from cityshade.build import build_scene_from_file
    from cityshade.store.scenefile import load_scene

    if not _is_path(proposal):
        return proposal
    path = Path(proposal)
    if path.suffix == ".cityshade":
        return load_scene(path)
    if not path.exists():
        raise UsageError(f"the proposal {path} does not exist")
    if path.suffix.lower() in _mesh_suffixes():
        from cityshade.meshes.proposal import proposal_scene

        if model is None:
            raise UsageError("a mesh proposal is placed in a model: give the model too")
        return proposal_scene(path, model, mesh)
    return build_scene_from_file(path, settings)


def open_compare(request: CompareRequest) -> CompareInputs:
    """The dates of the two states, the output folder checked (before any work), the model
    opened and the steps planned: what :func:`run_compare` starts from (a caller may look at
    the steps first, e.g. to warn about the tz database's local mean time)."""
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.store.scenefile import whole_scene
    from cityshade.util import check_outputs

    before, after = request.states.dates(request.plan.first_day)
    if request.outdir is not None:
        check_outputs(("-o", request.outdir, None))  # once the request is valid, before any work
    weather = request.weather
    if _is_path(weather):  # a garbled file is refused before the model is read
        from cityshade.light.weather import read_weather

        weather = read_weather(weather)
    # A tiled cache: the view of all its tiles.
    scene = whole_scene(request.scene) if _is_path(request.scene) else request.scene
    if request.states.proposal is None:
        check_states_differ(scene, before, after)
    scene = with_vegetation(scene, request.settings.vegetation)
    return CompareInputs(scene, before, after, request.plan.steps(scene), weather)


def check_states_differ(scene, before, after) -> None:
    """Refuse two dates of one model between which no object begins or ends: both states
    are the same city and the loss would be zero everywhere, whatever the buildings.

    Raises
    ------
    UsageError
    """
    import numpy as np

    lo, hi = sorted((float(before.city_days), float(after.city_days)))
    if scene.has_time:
        ends = np.concatenate([scene.obj_t_begin_days, scene.obj_t_end_days])
        if ((ends > lo) & (ends <= hi)).any():
            return
        why = f"no object begins or ends between {before.text} and {after.text}"
    else:
        why = "the model's objects carry no dates"
    raise UsageError(f"both states are the same city ({why}), so nothing would change; give "
                     f"--before/--after dates around a change (cityshade info FILE shows the "
                     f"time range), or the proposal with --with")


def run_compare(request: CompareRequest, inputs: CompareInputs | None = None, *,
                on_step: Callable[[int, int], None] | None = None) -> CompareResult:
    """Sun-hours of the same receivers in two states of a city, the rules' verdicts, and the
    outputs (``compare.exr``, PNGs, GeoTIFFs of a map view, ``surfaces.csv``, ``openings.csv``,
    ``rules.json``, ``report.md``, ``report.html``, ``results.gpkg`` and GeoJSON), written
    together or not at all.

    Parameters
    ----------
    request : CompareRequest
        What to compare.
    inputs : CompareInputs, optional
        :func:`open_compare`'s result for this request (default: opened here).
    on_step : callable(done, total), optional
        Progress over both states' sun positions (not the rules').

    Returns
    -------
    CompareResult

    Raises
    ------
    UsageError
        Nothing to compare, a proposal in another CRS, a bad date, two states that are the
        same city, another live run holding the output folder's lock.
    OutputError
        The output folder cannot be written.

    Examples
    --------
    >>> from datetime import date
    >>> from cityshade.planning.rules import load_rules
    >>> from cityshade.planning.run import (CompareRequest, CompareStates, TimePlan,
    ...                                      run_compare)
    >>> request = CompareRequest(
    ...     "city.cityshade", TimePlan(date(2025, 3, 21), tz="Europe/Berlin"),
    ...     CompareStates(proposal="sample_data/proposal_block.gml"),
    ...     rules=load_rules("bre209"), area=(690110, 5336122, 690140, 5336131),
    ...     outdir="planning")                                      # doctest: +SKIP
    >>> result = run_compare(request)                               # doctest: +SKIP
    >>> [(v.rule.id, v.status) for v in result.verdicts]            # doctest: +SKIP
    [('bre209-garden', 'pass'), ('bre209-window', 'not assessed')]
    """
    from cityshade.util import folder_lock

    inputs = inputs or open_compare(request)
    if request.outdir is None:
        return _compare(request, inputs, on_step)
    notes: list[str] = []
    # One run at a time in a folder; a lock left by a process that has ended is taken over.
    with folder_lock(request.outdir, notes.append):
        result = _compare(request, inputs, on_step)
    result.comparison.warnings[:0] = notes
    return result


def _compare(request: CompareRequest, inputs: CompareInputs, on_step) -> CompareResult:
    """:func:`run_compare` once the inputs are open (and the folder locked)."""
    from cityshade.geometry.vegetation import with_vegetation
    from cityshade.planning.compare import Receivers, compare_states, merge_scenes, \
        write_comparison
    from cityshade.planning.report import write_report
    from cityshade.util import output_group

    settings, scene = request.settings, inputs.scene
    scene_after, proposal_warnings = scene, []
    if request.states.proposal is not None:
        proposal = load_proposal(request.states.proposal, settings, scene, request.states.mesh)
        if "mesh" in (proposal.report or {}):  # a mesh's placement notes (a model's: at build)
            proposal_warnings = list(proposal.report.get("warnings", []))
        scene_after = with_vegetation(merge_scenes(scene, proposal, settings),
                                      settings.vegetation)
    camera = request.camera(scene_after) if callable(request.camera) else request.camera
    receivers = Receivers(
        samples_per_m2=settings.batch.samples_per_m2 if request.surfaces else None,
        min_stretch_h=request.min_stretch_h)
    comp = compare_states(scene, inputs.before.city_days, scene_after, inputs.after.city_days,
                          camera, inputs.steps, receivers, technique=request.technique,
                          settings=settings, ground=request.ground, on_step=on_step)
    comp.warnings[:0] = [w for w in proposal_warnings if w not in comp.warnings]
    _add_light(comp, request, inputs)
    verdicts = [run_rule(rule, request, inputs, scene_after, camera, comp)
                for rule in request.rules]
    written: list[Path] = []
    if request.outdir is not None:
        with output_group():  # the rasters, tables and report appear together, or none of them
            written = write_comparison(request.outdir, comp, _meta(request, inputs),
                                       request.decorate)
            written += write_report(request.outdir, comp, verdicts, _provenance(request),
                                    inputs.steps, request.decorate)
            if request.gis and comp.samples is not None and not scene.is_tiled:
                from cityshade.planning.gis import compare_layers
                from cityshade.present.gis import write_gis

                written += write_gis(request.outdir, compare_layers(comp, verdicts), scene.crs)
    return CompareResult(comp, verdicts, inputs.steps, written)


def _add_light(comp, request: CompareRequest, inputs: CompareInputs) -> None:
    """The openings' VSC (when a rule measures it) and probable sunlight hours (with a weather
    file), and the weather file's distance warning."""
    from cityshade.light.weather import scene_location_warning
    from cityshade.planning.light import add_opening_light

    if inputs.weather is not None:
        warning = scene_location_warning(inputs.weather, inputs.scene)
        if warning:
            comp.warnings.append(warning)
    vsc_rules = [r for r in request.rules if r.measure == "vsc"]
    if comp.openings and (vsc_rules or inputs.weather is not None):
        add_opening_light(comp, vsc=bool(vsc_rules), weather=inputs.weather,
                          sky=vsc_rules[0].sky if vsc_rules else None)


def _meta(request: CompareRequest, inputs: CompareInputs) -> dict[str, Any]:
    """The attributes of the rasters and pictures."""
    before, after = request.states.labels(request.plan.first_day)
    return {"cityshade:kind": "compare", "cityshade:before": before, "cityshade:after": after,
            "cityshade:technique": request.technique, "cityshade:crs": inputs.scene.crs.name,
            "cityshade:steps": len(inputs.steps), "cityshade:step_s": request.plan.every_s}


def _provenance(request: CompareRequest) -> dict[str, Any]:
    """The request as the report records it: the caller's own, or made from the fields."""
    if request.provenance is not None:
        return dict(request.provenance)
    plan, states = request.plan, request.states

    def clock(s):
        return f"{int(s) // 3600:02d}:{int(s) % 3600 // 60:02d}"

    return {"file": str(request.scene) if _is_path(request.scene) else "scene",
            "before": states.labels(plan.first_day)[0], "after": states.after,
            "with": str(states.proposal) if states.proposal is not None else None,
            "date": plan.first_day.isoformat(), "from": clock(plan.from_s),
            "to": clock(plan.to_s), "every": f"{plan.every_s:g}s", "tz": str(plan.tz),
            "days": plan.days, "to_date": plan.to_date.isoformat() if plan.to_date else None,
            "every_day": plan.every_day, "technique": request.technique,
            "ground": request.ground, "min_stretch": f"{request.min_stretch_h:g}h",
            "rules": [rule.id for rule in request.rules]}


# --- the rules ----------------------------------------------------------------------------------

def _rule_plan(rule, request: CompareRequest, scene):
    """The rule's own day(s), window and step (else the request's), and its suns: below the
    rule's minimum altitude the sun does not count, so those steps are sun-down."""
    from cityshade.geo.sun import suns_from_instants
    from cityshade.planning.rules import rule_day
    from cityshade.sunhours.plan import parse_clock_s, parse_duration_s

    year = request.plan.first_day.year
    plan = TimePlan(rule_day(rule, year), from_s=parse_clock_s(rule.time_from),
                    to_s=parse_clock_s(rule.time_to),
                    every_s=parse_duration_s(rule.every) if rule.every else request.plan.every_s,
                    tz=rule.tz or request.plan.tz,
                    to_date=rule_day(rule, year, rule.to_date) if rule.to_date else None,
                    every_day=rule.every_day)
    steps = plan.steps(scene)
    suns = suns_from_instants([s.centre_utc for s in steps], scene.crs, scene.origin_m,
                              request.settings.sun)
    if rule.min_elevation_deg > 0:
        suns = [s if s.elevation_deg >= rule.min_elevation_deg else
                dataclasses.replace(s, elevation_deg=min(s.elevation_deg, 0.0)) for s in suns]
    return plan, steps, suns


def _rule_polygons(rule, scene):
    """(P,) bool of the rule's surface receivers (None: every surface), or the verdict
    ``not assessed`` when the model has none of them."""
    from cityshade.planning.compare import openings_of
    from cityshade.planning.rules import Verdict, receiver_polygons

    polygons = receiver_polygons(rule, scene)
    if polygons is None:
        return None
    if rule.receivers == "openings":
        polygons = polygons & np.isin(np.arange(len(polygons)), [
            p for o in openings_of(scene) for p in o.polygons])
    if not polygons.any():
        kind = "windows or doors (LoD3 openings)" if rule.receivers == "openings" else \
            f"surfaces of class {', '.join(rule.classes)}"
        return Verdict(rule, "not assessed", f"the model has no {kind}",
                       not_assessed=rule.not_assessed)
    return polygons


def _rule_area(rule, request: CompareRequest, scene, scene_after, camera):
    """(rule with its area, map view of the area) for an area rule, or the verdict ``not
    assessed`` when neither the rule nor the request names an area. The view's pixels are
    the request's map pixels, at most 0.5 m."""
    from cityshade.planning.rules import Verdict, area_bbox
    from cityshade.raster.camera import map_view

    box = area_bbox(rule) or request.area
    if box is None:
        return Verdict(rule, "not assessed", "no area: give the rule an area_bbox or "
                       "area_polygon, or --area x0,y0,x1,y1", not_assessed=rule.not_assessed)
    if rule.area_bbox is None and rule.area_polygon is None:
        rule = dataclasses.replace(rule, area_bbox=tuple(box))
    o = scene.origin_m
    px = camera.pixel_size_m if camera is not None and camera.kind == "map" else 0.5
    return rule, map_view(scene_after, min(px, 0.5),
                          bbox=(box[0] - o[0], box[1] - o[1], box[2] - o[0], box[3] - o[1]))


#: Why an ``apsh`` rule is not assessed without a weather file.
NEEDS_WEATHER = ("needs --weather FILE: annual probable sunlight hours are the sunny hours "
                 "(direct normal irradiance ≥ 120 W/m²) of a typical-year weather file "
                 "(EPW, TMY3 or TMY2) that reach each window")


def _light_verdict(rule, inputs: CompareInputs, comp):
    """A ``vsc``/``apsh`` rule's verdict from the openings' light columns of ``comp``."""
    from pathlib import Path

    from cityshade.planning.rules import Verdict, evaluate, window_measures_from

    if rule.measure == "apsh" and inputs.weather is None:
        return Verdict(rule, "not assessed", NEEDS_WEATHER, not_assessed=rule.not_assessed)
    polygons = _rule_polygons(rule, inputs.scene)
    if isinstance(polygons, Verdict):
        return polygons
    if comp is None or not comp.openings:
        return Verdict(rule, "not assessed", "the comparison sampled no openings",
                       not_assessed=rule.not_assessed)
    before, after = window_measures_from(rule, comp)
    verdict = evaluate(rule, after, before)
    info = comp.light
    verdict.numbers["engine"] = info.get("engine")
    if rule.measure == "vsc":
        verdict.numbers["sky"] = info.get("sky")
    else:
        verdict.numbers.update(weather=Path(inputs.weather.path).name,
                               sunny_h=info.get("sunny_h"),
                               winter_sunny_h=info.get("winter_sunny_h"))
    return verdict


def run_rule(rule, request: CompareRequest, inputs: CompareInputs, scene_after, camera,
             comp=None):
    """The rule's own day, window and receivers, before and after → its
    :class:`cityshade.planning.rules.Verdict` (``camera``: the request's, whose map pixels an
    area rule keeps; ``comp``: the request's comparison, whose openings' light columns a
    ``vsc``/``apsh`` rule reads)."""
    from cityshade.planning.compare import OPENING_SAMPLES_PER_M2, Receivers, compare_states
    from cityshade.planning.rules import Verdict, evaluate, measures_from

    if rule.is_light:
        return _light_verdict(rule, inputs, comp)
    scene = inputs.scene
    plan, steps, suns = _rule_plan(rule, request, scene)
    polygons = _rule_polygons(rule, scene)
    if isinstance(polygons, Verdict):
        return polygons
    rule_camera = None
    if rule.receivers == "area":
        area = _rule_area(rule, request, scene, scene_after, camera)
        if isinstance(area, Verdict):
            return area
        rule, rule_camera = area
    receivers = Receivers(
        samples_per_m2=request.settings.batch.samples_per_m2
        if rule.receivers == "surfaces" else None,
        opening_samples_per_m2=0.0 if rule.receivers == "area" else OPENING_SAMPLES_PER_M2,
        polygons=polygons, min_stretch_h=rule.min_stretch_h)
    comp = compare_states(scene, inputs.before.city_days, scene_after, inputs.after.city_days,
                          rule_camera, steps, receivers, technique=request.technique,
                          settings=request.settings, ground=request.ground, suns=suns)
    m_before, m_after = measures_from(rule, comp)
    verdict = evaluate(rule, m_after, m_before)
    verdict.numbers["steps"] = len(steps)
    verdict.numbers["step_min"] = (steps[0].weight_h * 60.0) if steps else 0.0
    verdict.numbers["period"] = f"{plan.first_day.isoformat()}" + (
        f" to {plan.to_date.isoformat()}" if plan.to_date else "")
    return verdict
