"""The stress set of ``cityshade evaluate --stress``: stiff and extreme cases with invariants.

A fixed, seeded set of cases, each with PASS/FAIL and the measured numbers:

- sun elevations 0.1°, 1°, 3° (shadows crossing the whole model), 45°, 89.9°, exactly 90°
  and −5° (night) on the given model;
- the given model shifted by 10^7 m in x and y before building: ``raytrace`` must give the
  identical picture;
- a generated model of awkward geometry (built here as CityGML): sliver triangles (aspect
  10^6), zero-area and duplicate-vertex polygons, coplanar overlapping roofs, walls meeting the
  ground exactly, 1 cm thin walls, and a tower taller than the light frustum a map view's
  receivers would need (its shadow falls into a view that does not contain it);
- time slices exactly on every construction/demolition date of the model and one day
  before/after it (a triangle is present on ``[begin, end)``);
- shadow-map sizes from 256² to 8192² (8192² only without ``--quick``) and CSM with 1 to 8
  cascades;
- "leave out what the scene does not need": a model without dates builds a tree without time
  splits, and a map view of one street draws only a fraction of the model as casters.

Invariants: no NaN or infinity in any lit fraction or channel; ``raytrace`` identical after the
shift; ``raytrace`` agrees with Embree on the same rays on ≥ 99.99 % (when ``embreex`` is
importable); every ``hybrid`` agrees with ``raytrace`` on ≥ 99.99 %; no technique raises; each
map technique's misclassified share stays below the bound of :func:`error_bound_pct`.
"""
from __future__ import annotations

import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import numpy as np

from cityshade.config import StressSettings
from cityshade.errors import InputError
from cityshade.shadows import describe

#: Share of pixels (or rays) on which two exact methods must agree: 1 in 10^4 may differ on
#: exact ties (a ray through a shared edge, decided by different watertight rules).
AGREEMENT = 0.9999
#: Shift of the model in x and y (metres) for the large-coordinate case.
SHIFT_M = 1e7
#: Sun azimuth of the elevation cases (degrees from true north): south-east, so shadows run
#: diagonally across the grid of streets.
STRESS_AZIMUTH_DEG = 135.0


def error_bound_pct(technique: str, elevation_deg: float, map_px: int) -> float:
    """Largest misclassified share (% of surface pixels) a map technique may have.

    The bounds come from the measured errors of the sample city and the geometry case
    (docs/ACCURACY.md) with a margin of about 2×: a map of ``map_px`` texels cannot place an
    edge better than about one texel, so small maps and grazing suns (long, thin shadows
    whose edges cover many pixels) get larger bounds. ``hybrid`` must be exact
    (:data:`AGREEMENT`), so its bound is 0.01 %.
    """
    if describe(technique).family == "hybrid":
        return 100.0 * (1.0 - AGREEMENT)
    if elevation_deg <= 0.0:
        return 0.0                       # no sun: every technique must say shadow
    if elevation_deg < 2.0:
        bound = 30.0
    elif elevation_deg < 10.0:
        bound = 20.0
    else:
        bound = 8.0
    if map_px < 1024:
        bound *= 2.0
    return bound


@dataclass
class CaseResult:
    """One stress case: its invariants' outcome and the measured numbers."""

    name: str
    passed: bool
    numbers: dict[str, Any] = field(default_factory=dict)
    failures: list[str] = field(default_factory=list)
    seconds: float = 0.0

    def line(self) -> str:
        nums = ", ".join(f"{k} {_fmt(v)}" for k, v in self.numbers.items())
        why = f" — {'; '.join(self.failures)}" if self.failures else ""
        return f"{'PASS' if self.passed else 'FAIL'}  {self.name}: {nums}{why}"


@dataclass
class StressReport:
    cases: list[CaseResult] = field(default_factory=list)
    meta: dict[str, Any] = field(default_factory=dict)


def _fmt(v) -> str:
    if isinstance(v, float):
        return f"{v:.4g}"
    return str(v)


# --- checks shared by the cases -------------------------------------------------------------

class _Checker:
    """Collects failures and numbers of one case."""

    def __init__(self, name: str):
        self.case = CaseResult(name, True)
        self.t0 = time.perf_counter()

    def fail(self, message: str) -> None:
        self.case.passed = False
        self.case.failures.append(message)

    def done(self) -> CaseResult:
        self.case.seconds = time.perf_counter() - self.t0
        return self.case


def _frame(scene, camera, t_days, s: StressSettings):
    """The pipeline's camera pass, with the set's ground plane (as ``render --ground``)."""
    from cityshade.frame.pipeline import camera_pass

    return camera_pass(scene, camera, t_days, ground=s.ground)


def _run(cp, sun, technique: str, **flags):
    """One technique's result on a camera pass (flags: :meth:`ShadowSettings.override`)."""
    from cityshade.config import ShadowSettings
    from cityshade.frame.pipeline import shadow_pass

    return shadow_pass(cp, sun, technique, ShadowSettings().override(**flags)).result


def _check_techniques(chk: _Checker, scene, camera, sun, t_days, techniques, sizes,
                      s: StressSettings, label: str = "") -> dict:
    """Run raytrace and every technique × size on one frame; check finiteness, hybrid
    agreement and the error bounds. Returns {"ref": lit, "worst": {tech: pct}, ...}."""
    from cityshade.evaluate.metrics import compare, make_reference

    cp = _frame(scene, camera, t_days, s)
    gbuf, surfaces = cp.gbuffer, cp.surfaces
    for name, arr in (("depth", gbuf.depth[surfaces.valid]), ("position", surfaces.position_m[
            surfaces.valid]), ("normal", surfaces.normal[surfaces.valid])):
        if not np.isfinite(arr).all():
            chk.fail(f"{label}G-buffer {name} has NaN or infinity")
    ref_res = _run(cp, sun, "raytrace")
    _finite(chk, f"{label}raytrace", ref_res)
    ref = make_reference(ref_res.lit, surfaces.valid, surfaces.position_m)
    worst: dict[str, float] = {}
    for tech in techniques:
        for size in sizes:
            try:
                res = _run(cp, sun, tech, map_px=int(size))
            except Exception as exc:  # a crash is a FAIL of the case, not the end of the set
                chk.fail(f"{label}{tech}@{size} raised {type(exc).__name__}: {exc}")
                continue
            _finite(chk, f"{label}{tech}@{size}", res)
            err = compare(res.lit, ref)
            pct = err["misclassified_pct"]
            worst[tech] = max(worst.get(tech, 0.0), pct)
            bound = error_bound_pct(tech, sun.elevation_deg, size)
            if pct > bound + 1e-12:
                chk.fail(f"{label}{tech}@{size} {pct:.3f} % wrong > bound {bound:g} %")
    return {"ref": ref_res, "pass": cp, "surfaces": surfaces, "gbuffer": gbuf, "worst": worst,
            "valid_px": int(surfaces.valid.sum())}


def _finite(chk: _Checker, what: str, result) -> None:
    from cityshade.evaluate.metrics import finite_check

    bad = finite_check(result)
    if bad:
        chk.fail(f"{what}: {bad}")


def _facing_rays(cp, sun):
    from cityshade.trace import shadow_rays_from_surface

    ctx = cp.context(sun)
    faces = ctx.faces
    origins = shadow_rays_from_surface(cp.surfaces.position_m[faces], ctx.normal[faces],
                                       sun.direction)
    directions = np.ascontiguousarray(np.broadcast_to(sun.direction, origins.shape))
    return origins, directions


def embree_agreement(scene, origins, directions, t_days: float) -> float | None:
    """Share of shadow rays on which the kd-tree and Embree (``embreex``) agree; None when
    embreex is not importable. Embree gets the triangles present at ``t_days``."""
    try:
        from embreex import rtcore_scene
        from embreex.mesh_construction import TriangleMesh
    except ImportError:
        return None
    from cityshade.shadows.visibility import occluded

    if len(origins) == 0:
        return 1.0
    present = ((np.asarray(scene.tri_t_begin_days) <= t_days)
               & (t_days < np.asarray(scene.tri_t_end_days)))
    tris = np.asarray(scene.vertices, np.float32)[np.asarray(scene.triangles)[present]]
    ours = occluded(scene, origins, directions, t_days)
    if tris.shape[0] == 0:
        return float(np.mean(~ours))
    embree_scene = rtcore_scene.EmbreeScene()
    TriangleMesh(embree_scene, np.ascontiguousarray(tris))
    theirs = embree_scene.run(np.ascontiguousarray(origins, np.float32),
                              np.ascontiguousarray(directions, np.float32),
                              query="OCCLUDED") >= 0
    return float(np.mean(ours == theirs))


# --- generated models -----------------------------------------------------------------------

_CG2 = ('xmlns="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml" '
        'xmlns:bldg="http://www.opengis.net/citygml/building/2.0" '
        'xmlns:luse="http://www.opengis.net/citygml/landuse/2.0"')


def _poly(points, pid: str) -> str:
    pts = list(points) + [points[0]]
    text = " ".join(f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in pts)
    return (f'<gml:Polygon gml:id="{pid}"><gml:exterior><gml:LinearRing><gml:posList '
            f'srsDimension="3">{text}</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>')


def _box(x0, y0, z0, dx, dy, dz):
    """Six outward faces (class, points) of an axis-aligned box."""
    x1, y1, z1 = x0 + dx, y0 + dy, z0 + dz
    return [
        ("GroundSurface", [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)]),
        ("RoofSurface", [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]),
        ("WallSurface", [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)]),
        ("WallSurface", [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)]),
        ("WallSurface", [(x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)]),
        ("WallSurface", [(x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)]),
    ]


def _building(bid: str, faces) -> str:
    bounded = "".join(
        f"<bldg:boundedBy><bldg:{cls}><bldg:lod2MultiSurface><gml:MultiSurface>"
        f"<gml:surfaceMember>{_poly(pts, f'{bid}_{k}')}</gml:surfaceMember>"
        f"</gml:MultiSurface></bldg:lod2MultiSurface></bldg:{cls}></bldg:boundedBy>"
        for k, (cls, pts) in enumerate(faces))
    return f'<bldg:Building gml:id="{bid}">{bounded}</bldg:Building>'


#: Extent of the geometry model (metres, local CRS EPSG:25832 around Munich).
_GEOM_X0, _GEOM_Y0 = 690000.0, 5336000.0


def geometry_model_gml() -> str:
    """The awkward-geometry model as CityGML 2.0 text (deterministic).

    A 400 × 400 m ground plane at z = 0 and, on it (walls meeting the ground exactly): boxes,
    a 1 cm thin wall, a sliver wall (10 m × 10 µm: aspect 10^6), a zero-area polygon (collinear
    points), a polygon with duplicate vertices, two coplanar overlapping roofs, and a 600 m
    tower in the north-west corner whose shadow (sun from the south-east... north-west) reaches
    the map view of the south-east quarter.
    """
    x0, y0 = _GEOM_X0, _GEOM_Y0
    members = []
    ground = [(x0 - 200, y0 - 200, 0.0), (x0 + 200, y0 - 200, 0.0), (x0 + 200, y0 + 200, 0.0),
              (x0 - 200, y0 + 200, 0.0)]
    members.append(f'<luse:LandUse gml:id="ground"><luse:lod1MultiSurface><gml:MultiSurface>'
                   f'<gml:surfaceMember>{_poly(ground, "ground_p")}</gml:surfaceMember>'
                   f'</gml:MultiSurface></luse:lod1MultiSurface></luse:LandUse>')
    rng = np.random.default_rng(7)
    for k in range(12):
        bx = x0 - 150 + 60 * (k % 4) + float(rng.uniform(0, 20))
        by = y0 - 150 + 60 * (k // 4) + float(rng.uniform(0, 20))
        members.append(_building(f"box{k}", _box(bx, by, 0.0, 15.0, 12.0,
                                                 float(rng.uniform(8, 30)))))
    members.append(_building("thin", _box(x0 + 40, y0 + 40, 0.0, 20.0, 0.01, 8.0)))
    sliver = [(x0 + 70, y0 + 70, 5.0), (x0 + 80, y0 + 70, 5.0), (x0 + 80, y0 + 70, 5.00001),
              (x0 + 70, y0 + 70, 5.00001)]
    collinear = [(x0 + 90, y0 + 90, 0.0), (x0 + 95, y0 + 90, 5.0), (x0 + 100, y0 + 90, 10.0)]
    duplicate = [(x0 + 100, y0 + 40, 6.0), (x0 + 110, y0 + 40, 6.0), (x0 + 110, y0 + 40, 6.0),
                 (x0 + 110, y0 + 50, 6.0), (x0 + 100, y0 + 50, 6.0), (x0 + 100, y0 + 50, 6.0)]
    members.append(_building("degenerate", [("WallSurface", sliver),
                                            ("WallSurface", collinear),
                                            ("RoofSurface", duplicate)]))
    box = _box(x0 + 20, y0 + 100, 0.0, 20.0, 20.0, 12.0)
    overlap = [(x0 + 25, y0 + 105, 12.0), (x0 + 45, y0 + 105, 12.0), (x0 + 45, y0 + 125, 12.0),
               (x0 + 25, y0 + 125, 12.0)]
    members.append(_building("coplanar", box + [("RoofSurface", overlap)]))
    members.append(_building("tower", _box(x0 - 190, y0 + 170, 0.0, 10.0, 10.0, 600.0)))
    body = "".join(f"<cityObjectMember>{m}</cityObjectMember>" for m in members)
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<CityModel {_CG2}>'
            f'<gml:boundedBy><gml:Envelope srsName="EPSG:25832" srsDimension="3"/>'
            f'</gml:boundedBy>{body}</CityModel>\n')


def shifted_gml(source: Path, target: Path, shift_m: float = SHIFT_M) -> int:
    """Copy a CityGML file with ``shift_m`` added to every x and y coordinate.

    Coordinates of ``gml:posList``, ``gml:pos``, ``gml:lowerCorner``/``upperCorner`` and
    ``gml:coordinates`` are shifted (dimension from ``srsDimension``, default 3); the text is
    rewritten with the shortest float64 repr, so nothing but the shift changes. Returns the
    number of coordinate tuples shifted.
    """
    from lxml import etree

    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True,
                             recover=True)
    try:
        tree = etree.parse(str(source), parser)
    except (OSError, etree.XMLSyntaxError) as exc:
        raise InputError(f"cannot read the model to shift it: {exc}", path=str(source)) from None
    n = 0
    for el in tree.iter():
        if not isinstance(el.tag, str):
            continue
        local = etree.QName(el).localname
        if local not in ("posList", "pos", "lowerCorner", "upperCorner", "coordinates"):
            continue
        if not el.text or not el.text.strip():
            continue
        if local == "coordinates":
            tuples = [t.split(",") for t in el.text.split()]
            out = []
            for t in tuples:
                vals = [float(v) for v in t]
                vals[0] += shift_m
                if len(vals) > 1:
                    vals[1] += shift_m
                out.append(",".join(repr(v) for v in vals))
                n += 1
            el.text = " ".join(out)
            continue
        dim = 3
        node = el
        while node is not None:
            if node.get("srsDimension"):
                dim = int(node.get("srsDimension"))
                break
            node = node.getparent()
        vals = np.array([float(v) for v in el.text.split()])
        if vals.size % dim:
            dim = 3 if vals.size % 3 == 0 else 2
        vals = vals.reshape(-1, dim)
        vals[:, 0] += shift_m
        vals[:, 1] += shift_m
        n += vals.shape[0]
        el.text = " ".join(repr(float(v)) for v in vals.reshape(-1))
    tree.write(str(target), xml_declaration=True, encoding="UTF-8")
    return n


# --- the cases ------------------------------------------------------------------------------

def _views(scene, s: StressSettings, t_days: float | None = None):
    from cityshade.raster import camera as cams

    box = cams.scene_box(scene)
    side = float(np.max(box[1, :2] - box[0, :2]))
    w, h = s.view_px
    return [("overview", cams.overview(scene, w, h)),
            ("map", cams.map_view(scene, cams.nice_ceil(side / s.map_side_px)))]


def _street_view(scene, s: StressSettings):
    """A map of a fifth of the model's width around its centre: "one street"."""
    from cityshade.raster import camera as cams

    box = cams.scene_box(scene)
    c = 0.5 * (box[0, :2] + box[1, :2])
    half = 0.1 * float(np.max(box[1, :2] - box[0, :2]))
    px = cams.nice_ceil(2 * half / s.map_side_px)
    return cams.map_view(scene, px, bbox=(c[0] - half, c[1] - half, c[0] + half, c[1] + half))


def case_elevation(scene, s: StressSettings, elevation_deg: float, t_days: float) -> CaseResult:
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker(f"sun elevation {elevation_deg:g}°")
    sun = sun_from_angles(STRESS_AZIMUTH_DEG, elevation_deg, scene.crs, scene.origin_m)
    worst: dict[str, float] = {}
    for view, cam in _views(scene, s):
        out = _check_techniques(chk, scene, cam, sun, t_days, s.techniques, s.map_sizes, s,
                                label=f"{view}: ")
        for k, v in out["worst"].items():
            worst[k] = max(worst.get(k, 0.0), v)
        if elevation_deg <= 0.0 and (out["ref"].lit != 0).any():
            chk.fail(f"{view}: raytrace lit pixels with the sun below the horizon")
        if view == "overview" and elevation_deg > 0.0:
            o, d = _facing_rays(out["pass"], sun)
            agree = embree_agreement(scene, o, d, t_days)
            chk.case.numbers["embree agree %"] = ("n/a (embreex not installed)" if agree is None
                                                  else 100.0 * agree)
            if agree is not None and agree < AGREEMENT:
                chk.fail(f"raytrace agrees with Embree on {100 * agree:.4f} % < 99.99 %")
    map_worst = {k: v for k, v in worst.items() if describe(k).family != "hybrid"}
    if map_worst:
        k = max(map_worst, key=map_worst.get)
        chk.case.numbers["worst map technique"] = f"{k} {map_worst[k]:.3f} %"
    hyb = [v for k, v in worst.items() if describe(k).family == "hybrid"]
    if hyb:
        chk.case.numbers["hybrid worst %"] = max(hyb)
    return chk.done()


def case_shift(source_gml: Path, scene, s: StressSettings, t_days: float) -> CaseResult:
    from cityshade.build import build_scene_from_file
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker(f"model shifted by {SHIFT_M:g} m in x and y")
    with tempfile.TemporaryDirectory(prefix="cityshade-stress-") as tmp:
        target = Path(tmp) / "shifted.gml"
        n = shifted_gml(source_gml, target)
        base = build_scene_from_file(source_gml)
        moved = build_scene_from_file(target)
    chk.case.numbers["coordinates shifted"] = n
    chk.case.numbers["origin shift m"] = float(np.max(np.abs(
        moved.origin_m[:2] - base.origin_m[:2] - SHIFT_M)))
    if base.vertices.shape != moved.vertices.shape:
        chk.fail("the shifted model has a different number of vertices")
        return chk.done()
    dv = float(np.max(np.abs(base.vertices.astype(np.float64) - moved.vertices)))
    chk.case.numbers["max vertex difference m"] = dv
    total, same = 0, 0
    for elevation in (45.0, 3.0):
        for (view, cam_a), (_, cam_b) in zip(_views(base, s), _views(moved, s)):
            sun_a = sun_from_angles(STRESS_AZIMUTH_DEG, elevation, None)
            sun_b = sun_from_angles(STRESS_AZIMUTH_DEG, elevation, None)
            lits = []
            for sc, cam, sun in ((base, cam_a, sun_a), (moved, cam_b, sun_b)):
                res = _run(_frame(sc, cam, t_days, s), sun, "raytrace")
                _finite(chk, f"{view} raytrace", res)
                lits.append(res.lit)
            total += lits[0].size
            same += int((lits[0] == lits[1]).sum())
    chk.case.numbers["identical pixels %"] = 100.0 * same / max(total, 1)
    if same != total:
        chk.fail(f"raytrace differs on {total - same} of {total} pixels after the shift")
    return chk.done()


def case_geometry(s: StressSettings) -> CaseResult:
    from cityshade.build import build_scene_from_file
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker("awkward geometry (slivers 1e6, zero-area, duplicate vertices, coplanar "
                   "overlap, walls on the ground, 1 cm walls, 600 m tower)")
    with tempfile.TemporaryDirectory(prefix="cityshade-stress-") as tmp:
        src = Path(tmp) / "geometry.gml"
        src.write_text(geometry_model_gml(), encoding="utf-8")
        scene = build_scene_from_file(src)
    report = scene.report
    chk.case.numbers["triangles"] = scene.n_triangles
    skipped = report.get("skipped_polygons") or report.get("skipped") or {}
    if skipped:
        chk.case.numbers["polygons skipped"] = (sum(skipped.values()) if isinstance(skipped, dict)
                                                else skipped)
    if not np.isfinite(scene.vertices).all():
        chk.fail("the scene has non-finite vertices")
    ts = scene.kdtree.stats.get("time_splits", -1)
    chk.case.numbers["time splits"] = ts
    if ts != 0 or scene.kdtree.has_time:
        chk.fail(f"a model without dates built a tree with {ts} time splits")
    from cityshade.raster import camera as cams

    x0 = _GEOM_X0 - scene.origin_m[0]
    y0 = _GEOM_Y0 - scene.origin_m[1]
    # The south-east quarter, which the tower (north-west corner) shades at a low sun.
    corner = cams.map_view(scene, 400.0 / s.map_side_px, bbox=(x0, y0 - 200, x0 + 200, y0))
    views = _views(scene, s) + [("tower-shadow map", corner)]
    for elevation in (30.0, 3.0):
        # Sun from the north-west: the tower's shadow runs to the south-east quarter.
        sun = sun_from_angles(315.0, elevation, scene.crs, scene.origin_m)
        for view, cam in views:
            out = _check_techniques(chk, scene, cam, sun, 0.0, s.techniques, s.map_sizes, s,
                                    label=f"{view} el {elevation:g}: ")
            if view == "tower-shadow map" and elevation == 3.0:
                shade = 1.0 - float(out["ref"].lit[out["surfaces"].valid].mean())
                chk.case.numbers["tower view shadow %"] = 100.0 * shade
            if view == "overview":
                o, d = _facing_rays(out["pass"], sun)
                agree = embree_agreement(scene, o, d, 0.0)
                if agree is not None:
                    chk.case.numbers[f"embree agree % el {elevation:g}"] = 100.0 * agree
                    if agree < AGREEMENT:
                        chk.fail(f"raytrace agrees with Embree on {100 * agree:.4f} %")
            for k, v in out["worst"].items():
                key = "hybrid worst %" if describe(k).family == "hybrid" else "map worst %"
                chk.case.numbers[key] = max(chk.case.numbers.get(key, 0.0), v)
    return chk.done()


def wall_foot_case() -> CaseResult:
    """Points exactly at the foot of a sun-facing wall are lit, at the foot of a wall facing
    away in shadow (issue 13 point 12: the lower roof's point lies in the wall's plane, so a
    shadow ray offset only along the roof normal hit the wall at distance ≈ 0).

    A block whose middle third rises from 10 m to 20 m; points on both lower roofs exactly on
    the step edges, suns from the west at 5°–60° and from the north-west and south-west.
    """
    from cityshade.accel.kdtree_build import build_kdtree
    from cityshade.geo.sun import direction_from_angles
    from cityshade.trace import sunlit

    chk = _Checker("foot of a sun-facing wall (points on a roof-step edge)")
    faces = (_box(-10.0, -10.0, 0.0, 10.0, 20.0, 10.0) + _box(0.0, -10.0, 0.0, 10.0, 20.0, 20.0)
             + _box(10.0, -10.0, 0.0, 10.0, 20.0, 10.0))
    quads = np.array([pts for _, pts in faces], np.float32)          # (F, 4, 3)
    vertices = quads.reshape(-1, 3)
    base = 4 * np.arange(len(quads))[:, None]
    triangles = np.concatenate([base + [0, 1, 2], base + [0, 2, 3]]).astype(np.int32)
    n = len(triangles)
    tree = build_kdtree(vertices, triangles, np.full(n, -np.inf), np.full(n, np.inf),
                        np.zeros(n, np.int32))
    ys = np.arange(-9.5, 9.75, 0.25)
    west = np.column_stack([np.zeros_like(ys), ys, np.full_like(ys, 10.0)])   # sunny foot
    east = np.column_stack([np.full_like(ys, 10.0), ys, np.full_like(ys, 10.0)])
    up = np.tile([0.0, 0.0, 1.0], (len(ys), 1))
    wrong_lit = wrong_shadow = 0
    for azimuth in (225.0, 270.0, 315.0):
        for elevation in (5.0, 30.0, 60.0):
            sun = direction_from_angles(azimuth, elevation)
            wrong_shadow += int((~sunlit(tree, west, up, sun)).sum())
            wrong_lit += int(sunlit(tree, east, up, sun).sum())
    chk.case.numbers["points"] = 2 * 9 * len(ys)
    chk.case.numbers["false shadow"] = wrong_shadow
    chk.case.numbers["false lit"] = wrong_lit
    if wrong_shadow:
        chk.fail(f"{wrong_shadow} points at the foot of a sun-facing wall reported in shadow")
    if wrong_lit:
        chk.fail(f"{wrong_lit} points at the foot of a wall facing away reported lit")
    return chk.done()


def _model_dates(scene) -> list[float]:
    dates = np.concatenate([scene.obj_t_begin_days, scene.obj_t_end_days])
    return sorted(set(float(d) for d in dates[np.isfinite(dates)]))


def case_time_slices(scene, s: StressSettings) -> CaseResult:
    """On each date d of the model, the objects beginning at d are drawn and traced, and
    one day before they are not; objects ending at d are gone on d. Frames before, on and
    after each date pass the technique checks."""
    from cityshade.geo.sun import sun_from_angles
    from cityshade.trace import intersect

    chk = _Checker("time slices on, before and after the model's dates")
    dates = _model_dates(scene)
    if not dates:
        chk.case.numbers["dates"] = 0
        chk.case.numbers["note"] = "the model has no dates"
        return chk.done()
    if s.max_dates and len(dates) > s.max_dates:
        pick = np.linspace(0, len(dates) - 1, s.max_dates).round().astype(int)
        dates = [dates[i] for i in sorted(set(pick))]
    chk.case.numbers["dates"] = len(dates)
    sun = sun_from_angles(STRESS_AZIMUTH_DEG, 35.0, scene.crs, scene.origin_m)
    view = _views(scene, s)[1][1]
    tri_obj = np.asarray(scene.tri_object)
    begins, ends = np.asarray(scene.tri_t_begin_days), np.asarray(scene.tri_t_end_days)
    vertices = np.asarray(scene.vertices, np.float64)
    probes = 0
    for d in dates:
        # Probe rays straight at one triangle of each object that begins or ends at d.
        for which, expect_on in ((begins == d, True), (ends == d, False)):
            tris = np.flatnonzero(which)
            if tris.size == 0:
                continue
            firsts = tris[np.unique(tri_obj[tris], return_index=True)[1]]
            tri = np.asarray(scene.triangles)[firsts]
            p = vertices[tri].mean(axis=1)
            n = np.cross(vertices[tri[:, 1]] - vertices[tri[:, 0]],
                         vertices[tri[:, 2]] - vertices[tri[:, 0]])
            n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
            ok = np.isfinite(n).all(axis=1) & (np.linalg.norm(n, axis=1) > 0.5)
            origins = (p + 0.05 * n)[ok]
            dirs = -n[ok]
            firsts = firsts[ok]
            for t, present in ((d, expect_on), (d - 1.0, not expect_on)):
                _, hit, _, _ = intersect(scene.kdtree, origins, dirs, t,
                                         tmax=np.full(len(origins), 0.1))
                probes += len(origins)
                wrong = int(((hit == firsts) != present).sum())
                if wrong:
                    chk.fail(f"{wrong} probe rays disagree with [begin, end) at "
                             f"{'d' if t == d else 'd - 1 day'} (d = {d:g} days)")
        for t in (d - 1.0, d, d + 1.0):
            _check_techniques(chk, scene, view, sun, t, ("shadowmap", "hybrid:shadowmap"),
                              s.map_sizes[-1:], s, label=f"t {t:g}: ")
    chk.case.numbers["probe rays"] = probes
    return chk.done()


def case_map_sizes(scene, s: StressSettings, t_days: float) -> CaseResult:
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker(f"map sizes {s.sweep_sizes[0]}² to {s.sweep_sizes[-1]}²")
    sun = sun_from_angles(STRESS_AZIMUTH_DEG, 30.0, scene.crs, scene.origin_m)
    cam = _views(scene, s)[0][1]
    for size in s.sweep_sizes:
        out = _check_techniques(chk, scene, cam, sun, t_days, ("shadowmap", "pcf"), (size,), s,
                                label=f"{size}²: ")
        chk.case.numbers[f"{size}² wrong %"] = out["worst"].get("shadowmap", float("nan"))
    return chk.done()


def case_cascades(scene, s: StressSettings, t_days: float) -> CaseResult:
    from cityshade.evaluate.metrics import compare, make_reference
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker(f"CSM with {s.cascades[0]} to {s.cascades[-1]} cascades")
    sun = sun_from_angles(STRESS_AZIMUTH_DEG, 30.0, scene.crs, scene.origin_m)
    cam = _views(scene, s)[0][1]
    size = s.map_sizes[-1]
    cp = _frame(scene, cam, t_days, s)
    surfaces = cp.surfaces
    ref_res = _run(cp, sun, "raytrace")
    ref = make_reference(ref_res.lit, surfaces.valid, surfaces.position_m)
    for k in s.cascades:
        try:
            res = _run(cp, sun, "csm", cascades=k, map_px=size)
        except Exception as exc:
            chk.fail(f"csm with {k} cascades raised {type(exc).__name__}: {exc}")
            continue
        _finite(chk, f"csm {k}", res)
        d = res.diagnostics
        if d.get("cascades_rendered", 0) + len(d.get("cascades_skipped", [])) != d.get("cascades"):
            chk.fail(f"csm {k}: rendered + skipped cascades != cascades")
        pct = compare(res.lit, ref)["misclassified_pct"]
        chk.case.numbers[f"{k} wrong %"] = pct
        bound = error_bound_pct("csm", sun.elevation_deg, size)
        if pct > bound:
            chk.fail(f"csm with {k} cascades: {pct:.3f} % wrong > bound {bound:g} %")
    return chk.done()


def case_street(scene, s: StressSettings, t_days: float) -> CaseResult:
    """A view of one street does not shade the whole city."""
    from cityshade.geo.sun import sun_from_angles

    chk = _Checker("a view of one street draws a fraction of the city")
    cam = _street_view(scene, s)
    sun = sun_from_angles(STRESS_AZIMUTH_DEG, 30.0, scene.crs, scene.origin_m)
    cp = _frame(scene, cam, t_days, s)
    gbuf = cp.gbuffer
    present = int(((np.asarray(scene.tri_t_begin_days) <= t_days)
                   & (t_days < np.asarray(scene.tri_t_end_days))).sum())
    res = _run(cp, sun, "shadowmap")
    dm = res.diagnostics.get("depth_map", {})
    casters = int(dm.get("casters_drawn", present))
    chk.case.numbers["triangles standing"] = present
    chk.case.numbers["camera pass drew"] = int(gbuf.stats.get("triangles_drawn", present))
    chk.case.numbers["casters drawn"] = casters
    chk.case.numbers["caster share %"] = 100.0 * casters / max(present, 1)
    if present and casters >= present:
        chk.fail("the shadow map of one street drew every triangle of the model")
    if present and int(gbuf.stats.get("frustum_refs_removed", 0)) == 0:
        chk.fail("the camera pass of one street culled nothing")
    return chk.done()


def _model_source(path: Path) -> tuple[Any, Path | None]:
    """(scene, CityGML source) of FILE: a .gml is built in memory, a .cityshade is loaded and
    its recorded source used for the shift case (None when that file is gone)."""
    from cityshade.evaluate.run import load_or_build_scene

    path = Path(path)
    scene = load_or_build_scene(path)
    if path.suffix.lower() in (".gml", ".xml"):
        return scene, path
    src = (scene.header or {}).get("source", {}).get("path")
    return scene, (Path(src) if src and Path(src).exists() else None)


def run_stress(path, settings: StressSettings | None = None,
               progress: Callable[[int, int, str], None] | None = None,
               echo: Callable[[str], None] | None = None) -> StressReport:
    """Run the stress set on the model at ``path`` (.gml or .cityshade) and the generated
    geometry model; ``echo`` gets each case's PASS/FAIL line as it finishes."""
    from cityshade.geo.temporal import parse_user_date

    s = settings or StressSettings()
    scene, source = _model_source(path)
    # A city time at which the model stands: the latest begin date (or any time without dates).
    begins = np.asarray(scene.obj_t_begin_days)
    finite = begins[np.isfinite(begins)]
    t_days = float(finite.max()) + 1.0 if finite.size else parse_user_date("2000").city_days
    report = StressReport(meta={"model": str(path), "quick": s.quick, "t_days": t_days})
    jobs: list[tuple[str, Callable[[], CaseResult]]] = []
    for el in s.elevations_deg:
        jobs.append((f"elevation {el:g}", lambda el=el: case_elevation(scene, s, el, t_days)))
    if source is not None:
        jobs.append(("shift", lambda: case_shift(source, scene, s, t_days)))
    jobs.append(("geometry", lambda: case_geometry(s)))
    jobs.append(("wall foot", wall_foot_case))
    jobs.append(("time slices", lambda: case_time_slices(scene, s)))
    jobs.append(("map sizes", lambda: case_map_sizes(scene, s, t_days)))
    jobs.append(("cascades", lambda: case_cascades(scene, s, t_days)))
    jobs.append(("street", lambda: case_street(scene, s, t_days)))
    for i, (label, job) in enumerate(jobs):
        if progress:
            progress(i, len(jobs), label)
        try:
            case = job()
        except Exception as exc:  # the set reports every case, whatever one of them does
            case = CaseResult(label, False, failures=[f"{type(exc).__name__}: {exc}"])
        report.cases.append(case)
        if echo:
            echo(case.line())
    if source is None:
        case = CaseResult(f"model shifted by {SHIFT_M:g} m", False,
                          failures=["the CityGML source of the .cityshade file is not available"])
        report.cases.append(case)
        if echo:
            echo(case.line())
    if progress:
        progress(len(jobs), len(jobs), "done")
    return report


def stress_markdown(report: StressReport) -> str:
    """The stress set as a Markdown table (case, result, numbers, failures, seconds)."""
    lines = ["| case | result | measured | failures | s |", "|---|:---:|---|---|---:|"]
    for c in report.cases:
        nums = "; ".join(f"{k} {_fmt(v)}" for k, v in c.numbers.items())
        lines.append(f"| {c.name} | {'PASS' if c.passed else '**FAIL**'} | {nums} | "
                     f"{'; '.join(c.failures)} | {c.seconds:.1f} |")
    lines += ["", "Error bounds of the map techniques (misclassified % of surface pixels; "
              "`hybrid`: 0.01 %): sun ≥ 10°: 8 %; 2–10°: 20 %; < 2°: 30 %; doubled for maps "
              "smaller than 1024²; sun below the horizon: 0 %."]
    return "\n".join(lines)
