"""The triangulated scene: flat arrays in render space, plus object/polygon/material tables.

Render space (docs/DESIGN.md §1): x east, y north, z up, metres, float32, relative to a float64
origin (the rounded centre of the model's bounding box). Everything before the final cast — parsing,
projection, triangulation, areas and normals — is float64.

:func:`build_scene` turns a :class:`~cityshade.citygml.reader.RawModel` into a :class:`Scene`:
it resolves ``xlink:href`` references (forward ones included), chooses the LoD of every object,
makes sure each polygon is drawn once, triangulates, applies OrientableSurface flips, resolves
the chosen appearance theme into per-triangle material/texture and per-vertex texture
coordinates, and computes validity intervals.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from itertools import repeat
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, NamedTuple, Protocol

import numpy as np
from numba import njit

from cityshade.citygml.appearance import (georeferenced_uv, read_world_file,
                                          resolve_image_path)
from cityshade.geo.crs import (CrsInfo, GeographicProjector, area_of_use_warning,
                                   reproject_horizontal, resolve_model_crs_detailed)
from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.geo.temporal import (choose_interval, days_to_iso, has_creation_dates,
                                        parse_time_attribute)
from cityshade.config import BuildSettings
from cityshade.errors import ContractError, EmptyModelError, UsageError
from cityshade.geometry.bounds import all_vertices_box, vertex_box
from cityshade.runtime.interpret import InterpretBudget, twin_if
from cityshade.util import plural

if TYPE_CHECKING:   # the reader (and its parser) is loaded by a build, not by a loaded scene
    from cityshade.citygml.reader import RawModel

#: Time-source codes stored per object (uint8); new sources are appended (codes are stored).
TIME_SOURCE_NAMES = ("none", "valid", "construction", "creation", "inherited", "attribute")

#: Depth limit when following references to aggregates that reference further aggregates:
#: real files nest at most Solid → CompositeSurface → surfaceMember; 16 also stops cycles.
_MAX_REFERENCE_DEPTH = 16


@dataclass
class Scene:
    """A triangulated city model in render space.

    Attributes
    ----------
    origin_m : (3,) float64
        Render-space origin in the model CRS (metres); world = vertices + origin.
    crs : CrsInfo
        CRS of the render space (the projected CRS when the file was geographic).
    vertices : (V, 3) float32
        Render-space positions, metres.
    uv : (V, 2) float32
        Texture coordinates (0 where the vertex has no texture).
    triangles : (T, 3) int32
        Vertex indices; counter-clockwise seen from the side the polygon faces (outward).
    tri_object, tri_polygon : (T,) int32
        Index into the object and polygon tables.
    tri_class : (T,) uint8
        Surface class code (:data:`cityshade.citygml.namespaces.SURFACE_CLASSES`).
    tri_material, tri_texture : (T,) int32
        Index into :attr:`materials` / :attr:`textures`, -1 for none.
    tri_t_begin_days, tri_t_end_days : (T,) float64
        Validity interval [begin, end) of the triangle's object, days since 1970-01-01 UTC.
    obj_ids, obj_types : list of str
        gml:id ("" when absent) and local type name of each object.
    obj_parent : (O,) int32
        Parent object index, -1 for top-level objects.
    obj_t_begin_days, obj_t_end_days : (O,) float64
        Validity interval of each object.
    obj_time_source : (O,) uint8
        Code into :data:`TIME_SOURCE_NAMES`.
    obj_lod : (O,) int8
        LoD drawn for each object (-1: none/unknown).
    poly_ids : list of str
        gml:id of each drawn polygon ("" when absent).
    poly_object : (P,) int32; poly_class : (P,) uint8; poly_area_m2 : (P,) float64;
    poly_normal : (P, 3) float32; poly_repairs : (P,) uint16
        Per drawn polygon: owner, class, area (holes removed, measured in the polygon's
        plane), unit outward normal, and the bitmask of repairs applied
        (:data:`cityshade.geometry.triangulate.REPAIR_NAMES`).
    materials, textures : list of dict
        Material parameters; texture image paths (absolute) and wrap mode.
    report : dict
        Build report: counts, skipped polygons by reason, repairs, warnings, time range...
    """

    origin_m: np.ndarray
    crs: CrsInfo
    vertices: np.ndarray
    uv: np.ndarray
    triangles: np.ndarray
    tri_object: np.ndarray
    tri_polygon: np.ndarray
    tri_class: np.ndarray
    tri_material: np.ndarray
    tri_texture: np.ndarray
    tri_t_begin_days: np.ndarray
    tri_t_end_days: np.ndarray
    obj_ids: list[str]
    obj_types: list[str]
    obj_parent: np.ndarray
    obj_t_begin_days: np.ndarray
    obj_t_end_days: np.ndarray
    obj_time_source: np.ndarray
    obj_lod: np.ndarray
    poly_ids: list[str]
    poly_object: np.ndarray
    poly_class: np.ndarray
    poly_area_m2: np.ndarray
    poly_normal: np.ndarray
    poly_repairs: np.ndarray
    materials: list[dict] = field(default_factory=list)
    textures: list[dict] = field(default_factory=list)
    report: dict[str, Any] = field(default_factory=dict)
    kdtree: Any = None
    #: Header of the file the scene was loaded from (empty for a freshly built scene).
    header: dict[str, Any] = field(default_factory=dict)
    #: Set on a tiled cache's view (:meth:`cityshade.store.tiled.TiledCache.view`): the tiles it
    #: gathers and where its ids sit in the whole city. None for a scene of its own.
    tiling: "TiledParts | None" = None
    #: Values derived from the arrays, by name (:meth:`derived`); a copy
    #: (``dataclasses.replace``) starts without them.
    _derived: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    #: Array attributes stored in the cache (name → attribute).
    ARRAY_FIELDS = ("origin_m", "vertices", "uv", "triangles", "tri_object", "tri_polygon",
                    "tri_class", "tri_material", "tri_texture", "tri_t_begin_days",
                    "tri_t_end_days", "obj_parent", "obj_t_begin_days", "obj_t_end_days",
                    "obj_time_source", "obj_lod", "poly_object", "poly_class", "poly_area_m2",
                    "poly_normal", "poly_repairs")

    @property
    def n_triangles(self) -> int:
        return int(self.triangles.shape[0])

    @property
    def has_time(self) -> bool:
        """True when some object has a finite validity bound (the tree needs a time axis)."""
        return bool(np.isfinite(self.obj_t_begin_days).any() or
                    np.isfinite(self.obj_t_end_days).any())

    def world_from_render(self, xyz: np.ndarray) -> np.ndarray:
        """Render-space points (N, 3) → model CRS coordinates, float64."""
        return np.asarray(xyz, dtype=np.float64) + self.origin_m

    # --- the scene as a view: one scene of its own, or some tiles of a tiled cache -----------

    @property
    def is_tiled(self) -> bool:
        """Whether this is a view of some tiles of a tiled cache (:attr:`tiling`)."""
        return self.tiling is not None

    @property
    def can_trace(self) -> bool:
        """Whether shadow rays can be traced: a kd-tree of its own, or the tiles' trees."""
        return self.kdtree is not None or self.tiling is not None

    def global_triangle_ids(self, ids: np.ndarray) -> np.ndarray:
        """Triangle ids of this scene (-1: none) as the whole city's: themselves for a scene of
        its own, the one-cache ids for a tiled view (same dtype and shape)."""
        return ids if self.tiling is None else _to_global(self.tiling.global_tri, ids)

    def global_object_ids(self, ids: np.ndarray) -> np.ndarray:
        """Object ids of this scene (-1: none) as the whole city's (see
        :meth:`global_triangle_ids`)."""
        return ids if self.tiling is None else _to_global(self.tiling.global_obj, ids)

    def derived(self, name: str, compute: Callable[[], np.ndarray]) -> np.ndarray:
        """A copy of ``compute()``, an array derived from the vertices and triangles, computed
        once per scene while neither can change (the same read-only arrays: the memory maps
        of a loaded scene), else each time: a one-frame render asks for the model's box three
        times (extent, margin, camera)."""
        arrays = (self.vertices, self.triangles)
        if any(a.flags.writeable for a in arrays):
            return compute()
        kept = self._derived.get(name)
        if kept is None or any(a is not b for a, b in zip(kept[0], arrays)):
            kept = self._derived[name] = (arrays, compute())
        return kept[1].copy()

    def city_box_m(self) -> tuple[np.ndarray, np.ndarray]:
        """(lo (3,), hi (3,)) float64 render-space box of the whole city: the tiled cache's for
        a view of some of its tiles, else this scene's vertices' (float32 extremes cast to
        float64: exact, without a float64 copy of every vertex)."""
        if self.tiling is not None:
            lo, hi = (np.asarray(b, np.float64) for b in self.tiling.source.box_m)
            return lo, hi
        box = self.derived("city_box_m", lambda: all_vertices_box(np.asarray(self.vertices)))
        return box[0], box[1]

    def any_hit(self, origins: np.ndarray, directions: np.ndarray,
                hit: Callable[[Any, Any], np.ndarray]) -> np.ndarray:
        """(N,) bool: which rays are blocked, by ``hit(kdtree, rays)``, an exact any-hit test of
        the rays ``rays`` (an index array, or ``slice(None)`` for all) against one kd-tree.

        A scene of its own asks its own tree once. A tiled view asks each tile that the rays
        can reach (:meth:`TileSource.tiles_reaching`) for the rays not yet blocked, and ORs
        the answers: each tile's answer is exact, so the OR is the one tree's answer."""
        if self.tiling is None:
            if self.kdtree is None:
                raise ContractError("the scene has no kd-tree: nothing to trace rays through")
            return hit(self.kdtree, slice(None))
        origins = np.asarray(origins, np.float64).reshape(-1, 3)
        dirs = np.asarray(directions, np.float64).reshape(-1, 3)
        blocked = np.zeros(len(origins), bool)
        if len(dirs) > 1 and (dirs == dirs[0]).all():
            dirs = dirs[:1]
        source = self.tiling.source
        for i in source.tiles_reaching(origins, dirs):
            todo = np.flatnonzero(~blocked)
            if len(todo) == 0:
                break
            blocked[todo] |= hit(source.tile(i).kdtree, todo)
        return blocked


class TileSource(Protocol):
    """What a tiled view needs of its tiled cache (:class:`cityshade.store.tiled.TiledCache`)."""

    #: Render-space box of the whole city, [[x, y, z], [x, y, z]] metres.
    box_m: Any
    #: The whole city's ground heights by mode (``{"min": z, "auto": z}``, render space).
    ground_m: dict[str, float]
    #: One entry per tile of the cache.
    tiles: list

    def tile(self, i: int) -> "Scene":
        """Tile ``i`` as a scene with its own kd-tree (memory-mapped on first use)."""

    def tiles_reaching(self, origins: np.ndarray, directions: np.ndarray) -> list[int]:
        """The tiles a ray from ``origins`` along ``directions`` ((1, 3) or (N, 3)) can hit."""

    @property
    def tiles_mapped(self) -> list[int]:
        """The tiles memory-mapped so far."""


@dataclass(frozen=True, eq=False)
class TiledParts:
    """What makes a :class:`Scene` a view of some tiles of a tiled cache."""

    source: TileSource
    #: The tiles gathered in the view, ascending.
    tile_ids: list[int]
    #: (T,) / (O,) int: the whole city's id of each triangle / object of the view.
    global_tri: np.ndarray
    global_obj: np.ndarray


def root_objects(obj_parent: np.ndarray) -> np.ndarray:
    """(O,) int64: each object's top-level ancestor (itself for a top-level object; a
    BuildingPart's Building)."""
    root = np.arange(len(obj_parent), dtype=np.int64)
    parent = np.asarray(obj_parent, np.int64)
    for _ in range(64):  # nesting depth; real files nest 2-3 levels
        up = parent[root]
        step = up >= 0
        if not step.any():
            break
        root = np.where(step, up, root)
    return root


def _to_global(global_index: np.ndarray, ids: np.ndarray) -> np.ndarray:
    """A view's ids (-1: none) as the one cache's ids, in ``ids``' dtype and shape."""
    ids = np.asarray(ids)
    return np.where(ids >= 0, np.asarray(global_index)[np.maximum(ids, 0)], -1).astype(ids.dtype)


# ---------------------------------------------------------------------------------------------
def _object_intervals(raw: RawModel, source: str, counters: Counter,
                      time_attribute: str | None = None):
    """Validity intervals per object, the source code of each, and the number of objects whose
    creation/termination dates were left unused (database times, docs/DESIGN.md §1)."""
    n = len(raw.obj_ids)
    begin = np.full(n, -np.inf)
    end = np.full(n, np.inf)
    used = np.zeros(n, np.uint8)
    code = {name: i for i, name in enumerate(TIME_SOURCE_NAMES)}
    names = parse_time_attribute(time_attribute) if time_attribute else None
    creation_unused = 0
    for i, attrs in enumerate(raw.obj_time):
        parent = raw.obj_parent[i]
        if attrs:
            interval = choose_interval(attrs, source, names)
            b, e, src = interval.begin_days, interval.end_days, interval.source
            if interval.bad_values:
                counters["unparseable_time_values"] += len(interval.bad_values)
            if src != "creation" and has_creation_dates(attrs):
                creation_unused += 1
        else:
            b, e, src = -np.inf, np.inf, "none"
        if parent >= 0:
            # A part exists only while its whole exists.
            if src == "none" and used[parent] != 0:
                src = "inherited"
            b, e = max(b, begin[parent]), min(e, end[parent])
        begin[i], end[i], used[i] = b, e, code[src]
        if e <= b:
            counters["objects_never_existing"] += 1
    return begin, end, used, creation_unused


#: gml:ids of skipped polygons kept per reason in the report (the counts are always complete).
MAX_SKIPPED_IDS = 1000


def _note_ids(out: dict[str, list[str]], reason: str, raw: RawModel, polys) -> None:
    """Add the gml:ids (first :data:`MAX_SKIPPED_IDS`) of skipped polygons under ``reason``;
    a polygon without one is named by its object: ``"(no id) in OBJECT_ID, line N"``."""
    ids = out.setdefault(reason, [])
    for p in polys[:max(0, MAX_SKIPPED_IDS - len(ids))]:
        pid = raw.poly_ids[int(p)]
        if not pid:
            o = int(raw.poly_obj[int(p)])
            pid = (f"(no id) in {raw.obj_ids[o] or 'an object without id'}, line "
                   f"{raw.obj_line[o]}" if o >= 0 else "(no id)")
        ids.append(pid)


def _resolve_references(raw: RawModel, counters: Counter):
    """Expand every reference into (object, polygon, lod, flip, class) item arrays."""
    poly_by_id, aggregates = raw.poly_by_id, raw.aggregates
    targets = raw.ref_target
    # Most references name a polygon directly (solids made of boundary polygons): one dict
    # look-up each. Only the rest (aggregates, nested references) go through the slow path.
    direct = _direct_polygons(poly_by_id, targets)
    ref_obj = np.asarray(raw.ref_obj, np.int64)
    ref_lod = np.asarray(raw.ref_lod, np.int64)
    ref_flip = np.asarray(raw.ref_flip, np.int64)
    ref_cls = np.asarray(raw.ref_cls, np.int64)
    hit = direct >= 0
    obj, poly, lod, flip, cls = ([ref_obj[hit]], [direct[hit]], [ref_lod[hit]],
                                 [ref_flip[hit]], [ref_cls[hit]])
    extra: list[tuple[int, int, int, int, int]] = []

    def expand(target: str, o: int, lo: int, fl: int, cl: int, depth: int) -> bool:
        p = poly_by_id.get(target)
        if p is not None:
            extra.append((o, p, lo, fl, cl))
            return True
        agg = aggregates.get(target)
        if agg is None or depth > _MAX_REFERENCE_DEPTH:
            return False
        p0, p1, r0, r1 = agg
        extra.extend((o, p, lo, fl, cl) for p in range(p0, p1))
        for r in range(r0, r1):
            inner_cls = int(ref_cls[r]) if ref_cls[r] != 0 else cl
            expand(targets[r], o, lo, fl ^ int(ref_flip[r]), inner_cls, depth + 1)
        return True

    unresolved = 0
    for r in np.nonzero(~hit)[0]:
        if not expand(targets[r], int(ref_obj[r]), int(ref_lod[r]), int(ref_flip[r]),
                      int(ref_cls[r]), 0):
            unresolved += 1
    # The recursive closure refers to itself: break the cycle, or the read model's id tables
    # it holds outlive the model until a garbage collection (hundreds of MB on large files).
    expand = None
    if unresolved:
        counters["unresolved_references"] += unresolved
    if extra:
        cols = np.array(extra, np.int64).T
        for out, col in zip((obj, poly, lod, flip, cls), cols):
            out.append(col)
    return tuple(np.concatenate(parts) for parts in (obj, poly, lod, flip, cls))


def _direct_polygons(poly_by_id: dict, targets: list[str]) -> np.ndarray:
    """The polygon index each target id names, -1 where it names no polygon."""
    return np.fromiter(map(poly_by_id.get, targets, repeat(-1)), np.int64, len(targets))


def _expand_ranges(starts: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """Concatenate ``arange(s, s + n)`` for every (s, n)."""
    lengths = np.asarray(lengths, np.int64)
    out = np.empty(int(lengths.sum()), np.int64)
    kernel = twin_if(_INTERPRET_RANGES.take(out.size), _expand_ranges_kernel)
    kernel(np.asarray(starts, np.int64), lengths, out)
    return out


@njit(cache=True)
def _expand_ranges_kernel(starts, lengths, out):
    # One pass, no temporaries (numpy's repeat + arange took 1 s for the 10M city's points).
    k = 0
    for i in range(starts.shape[0]):
        s = starts[i]
        for j in range(lengths[i]):
            out[k] = s + j
            k += 1


@njit(cache=True)
def _render_vertices(points, index, origin):
    """``float32(points[index] - origin)``: gathered, shifted and rounded once, in one pass
    (no float64 copy of the gathered points and of their difference)."""
    out = np.empty((index.shape[0], 3), np.float32)
    for k in range(index.shape[0]):
        i = index[k]
        for a in range(3):
            out[k, a] = np.float32(points[i, a] - origin[a])
    return out


# Items a process runs through each kernel's Python source while it is neither compiled nor
# cached (:mod:`cityshade.runtime.interpret`; the kd-tree's kernels have their own budget).
# Interpreted CPU per item against first-use compiling (Dec 2026, 10^5 random items): the
# ranges 0.17 µs an entry (0.12-0.45 s to compile), the render vertices 2.7 µs a point
# (0.2-0.35 s; the box: geometry.bounds.vertex_box). The sample city: 3,662 points.
_INTERPRET_RANGES = InterpretBudget(1_000_000, _expand_ranges_kernel)
_INTERPRET_RENDER = InterpretBudget(80_000, _render_vertices)


def _polygon_targets(raw: RawModel, target: str, depth: int = 0) -> list[int]:
    """Polygons an appearance target names: a polygon, or every polygon of an aggregate."""
    p = raw.poly_by_id.get(target)
    if p is not None:
        return [p]
    agg = raw.aggregates.get(target)
    if agg is None or depth > _MAX_REFERENCE_DEPTH:
        return []
    p0, p1, r0, r1 = agg
    out = list(range(p0, p1))
    for r in range(r0, r1):
        out += _polygon_targets(raw, raw.ref_target[r], depth + 1)
    return out


def lod_label(raw: RawModel, code: int) -> str:
    """How the report spells a LoD code: "2" (CityGML), "2.2" or "1" (CityJSON, as written)."""
    if raw.lod_scale == 1:
        return str(code)
    label = raw.lod_labels.get(code)
    if label is None:
        whole, tenth = divmod(code, raw.lod_scale)
        label = f"{whole}.{tenth}" if tenth else str(whole)
    return label


def lod_request_range(request: int | float | str | None, lod_scale: int
                      ) -> tuple[int, int] | None:
    """The LoD codes ``--lod`` selects: (lowest, highest), None for "the highest of each object".

    CityGML (``lod_scale`` 1) has whole LoDs: ``2`` selects 2. CityJSON (``lod_scale`` 10)
    also has refined ones: ``2.2`` selects exactly 2.2, and ``2`` selects the highest of 2,
    2.0 … 2.9 each object has.

    Raises
    ------
    UsageError
        A refined LoD asked of a CityGML model, or a value that is no LoD.
    """
    if request is None:
        return None
    text = str(request).strip()
    whole, dot, tenth = text.partition(".")
    if not (whole.isdigit() and 0 <= int(whole) <= 4 and (not dot or tenth.isdigit()
                                                           and len(tenth) == 1)):
        raise UsageError(f"--lod {text}: a LoD is 0 to 4, or for CityJSON 0.0 to 4.9")
    if dot:
        if lod_scale == 1:
            if int(tenth) == 0:
                return int(whole), int(whole)
            raise UsageError(f"--lod {text}: CityGML has whole LoDs 0 to 4 (refined LoDs "
                             f"such as 2.2 exist in CityJSON only)")
        code = int(whole) * lod_scale + int(tenth)
        return code, code
    return int(whole) * lod_scale, int(whole) * lod_scale + lod_scale - 1


def render_origin(lo_m: np.ndarray, hi_m: np.ndarray) -> np.ndarray:
    """The render-space origin of a model with this bounding box: its centre rounded to 1 m."""
    return np.round(0.5 * (np.asarray(lo_m) + np.asarray(hi_m)))


@dataclass
class _BuildLog:
    """What a build finds on the way, for the scene's report: filled stage by stage."""

    counters: Counter
    warnings: list[str]
    #: reason → gml:ids of skipped polygons.
    skipped_ids: dict[str, list[str]] = field(default_factory=dict)
    #: reason → polygons skipped for it.
    skipped: Counter = field(default_factory=Counter)
    #: repair name → polygons repaired so.
    repairs: Counter = field(default_factory=Counter)
    #: Inner shells of solids (cavities), read but not drawn.
    cavities: int = 0
    source_crs: CrsInfo | None = None
    axis_order: str | None = None
    theme: str | None = None
    #: Triangulated polygons and triangles left out by reason (``closure_polygons``, ...).
    left_out: Counter = field(default_factory=Counter)


class _Validity(NamedTuple):
    """Validity intervals per object (days since 1970-01-01 UTC, open ends ±inf)."""

    begin_days: np.ndarray
    end_days: np.ndarray
    source: np.ndarray          # TIME_SOURCE_NAMES code per object
    creation_unused: int        # objects whose only dates are creation/termination dates


@dataclass
class _Selection:
    """The polygons drawn once each at the chosen LoD of every object."""

    polys: np.ndarray           # (P,) original polygon index, ascending
    p_obj: np.ndarray           # (P,) object of each
    p_flip: np.ndarray          # (P,) OrientableSurface "-" of each
    poly_cls: np.ndarray        # (n_polygons,) thematic class, upgraded from references
    obj_max_lod: np.ndarray     # (n_obj,) highest LoD code of each object (-1: none)
    chosen: np.ndarray          # (n_obj,) LoD code drawn
    lod_table: dict[int, int]   # LoD code → objects having it


def build_scene(raw: RawModel, settings: BuildSettings | None = None, *,
                target_crs: CrsInfo | None = None, render_space: bool = True,
                consume_raw: bool = False) -> Scene:
    """Select, triangulate and assemble the scene of a read CityGML file.

    Parameters
    ----------
    target_crs : CrsInfo, optional
        The CRS of a multi-file build (its ``--crs``): the file's coordinates are projected to
        it from the file's own CRS (taken to be in it when the file has none or an unknown
        one). Without it the file's CRS (or ``settings.crs``, which overrides the srsName) is
        the scene's.
    render_space : bool
        False keeps the vertices as float64 model-CRS coordinates with a zero origin, for
        :func:`cityshade.build.merge.merge_scenes` to choose the origin of all tiles and
        cast once (so a tiled build equals the one-file build bit for bit).
    consume_raw : bool
        True when the caller drops ``raw`` afterwards: its coordinates (``raw.xyz``, set to
        None) are freed once gathered and used, not held to the end with the scene's arrays.

    Raises
    ------
    EmptyModelError
        Nothing triangulable is left (every polygon skipped, or the LoD asked for is absent).
    CRSError
        The CRS cannot be resolved (unknown srsName, bad ``settings.crs``).
    """
    settings = settings or BuildSettings()
    log = _BuildLog(Counter(raw.counters), list(raw.warnings))
    times = _validity_intervals(raw, settings, log)                       # 1.
    sel = _select_polygons(raw, settings, log.counters)                   # 2.–4.
    rings, coords, ring_offsets, poly_ring_offsets = _gather_rings(       # 5.
        raw, sel, log, consume_raw)
    coords, crs = _to_model_crs(raw, settings, target_crs, coords, ring_offsets, log)  # 6.
    triangles, tri_poly_local, tri_area_m2, tri_repairs, normals, ok = _triangulate(  # 7.
        raw, settings, coords, (ring_offsets, poly_ring_offsets), sel, log)
    if settings.closure_surfaces == "omit":
        triangles, tri_poly_local, ok = _leave_out_closures(
            raw, sel, (triangles, tri_poly_local), ok, log)

    # 8. Keep drawn polygons only and renumber; compact the vertices.
    drawn = np.nonzero(ok)[0]
    # int32 renumbering tables: the per-triangle results come out in the stored dtype.
    remap_poly = np.full(len(sel.polys), -1, np.int32)
    remap_poly[drawn] = np.arange(len(drawn))
    tri_polygon = remap_poly[tri_poly_local]
    del tri_poly_local
    box = vertex_box(triangles, coords)  # of the points drawn (numpy's min/max took 1.6 s)
    if not crs.is_geographic:
        # A wrong CRS (or a 10^7 m offset) puts the model somewhere else on Earth: say so.
        area_warning = area_of_use_warning(crs, box[0], box[1])
        if area_warning:
            log.warnings.append(area_warning)
    used = np.zeros(len(coords), bool)
    used[triangles.ravel()] = True
    used_points = np.nonzero(used)[0]
    new_index = np.cumsum(used, dtype=np.int32) - 1
    del used
    triangles = new_index[triangles]
    del new_index
    if render_space:
        origin = render_origin(box[0], box[1])
        vertices = twin_if(_INTERPRET_RENDER.take(len(used_points)), _render_vertices)(
            coords, used_points, origin)
    else:
        origin, vertices = np.zeros(3), coords[used_points]

    # 9. Appearance of the chosen theme.
    look = _theme_appearance(raw, settings, drawn, sel.polys, rings,
                             (ring_offsets, poly_ring_offsets), coords, used_points, log)
    del coords, used_points

    # 10. Tables.
    orig_poly = sel.polys[drawn]
    p_obj_drawn = sel.p_obj[drawn].astype(np.int32)
    tri_object = p_obj_drawn[tri_polygon]
    poly_class = sel.poly_cls[orig_poly].astype(np.uint8)
    obj_lod_code = np.where(sel.obj_max_lod >= 0, sel.chosen, -1)
    # The cache keeps the whole LoD (0–4) in both formats; the report spells the codes.
    obj_lod = np.where(obj_lod_code >= 0, obj_lod_code // raw.lod_scale, -1).astype(np.int8)
    report = _build_report(raw, settings, log, times, sel.lod_table, obj_lod_code, len(drawn))
    poly_ids = raw.poly_ids
    openings = _opening_groups(getattr(raw, "openings", ()), orig_poly)
    if openings:
        report["openings"] = openings
    codes = getattr(raw, "obj_codes", None)
    if codes:  # the scene's objects are the raw model's, one for one
        report["vegetation_codes"] = [[i, codes[i]] for i in sorted(codes)]
    obj_begin, obj_end = times.begin_days, times.end_days
    return Scene(
        origin_m=origin.astype(np.float64), crs=crs, vertices=vertices, uv=look.uv,
        triangles=triangles, tri_object=tri_object, tri_polygon=tri_polygon,
        tri_class=poly_class[tri_polygon],
        tri_material=look.poly_material[tri_polygon],
        tri_texture=look.poly_texture[tri_polygon],
        tri_t_begin_days=obj_begin[tri_object], tri_t_end_days=obj_end[tri_object],
        obj_ids=[i or "" for i in raw.obj_ids], obj_types=list(raw.obj_types),
        obj_parent=np.asarray(raw.obj_parent, np.int32), obj_t_begin_days=obj_begin,
        obj_t_end_days=obj_end, obj_time_source=times.source, obj_lod=obj_lod,
        poly_ids=[poly_ids[p] or "" for p in orig_poly.tolist()],
        poly_object=p_obj_drawn, poly_class=poly_class,
        poly_area_m2=np.asarray(tri_area_m2, np.float64)[drawn],
        poly_normal=normals[drawn].astype(np.float32),
        poly_repairs=np.asarray(tri_repairs, np.uint16)[drawn],
        materials=look.materials, textures=look.textures, report=report)


def _validity_intervals(raw: RawModel, settings: BuildSettings, log: _BuildLog) -> _Validity:
    """Stage 1: every object's validity interval, with the warnings on unused dates."""
    obj_begin, obj_end, obj_source, creation_unused = _object_intervals(
        raw, settings.time_source, log.counters, settings.time_attribute)
    dated = np.isin(obj_source, [TIME_SOURCE_NAMES.index(n)
                                 for n in ("valid", "construction", "attribute")])
    if creation_unused and not dated.any():
        log.warnings.append(
            f"the only dates in the file are creationDate/terminationDate "
            f"({plural(creation_unused, 'object')}): they are database times (when a feature entered or left the database), "
            f"not the life of the buildings, so every object stands at every date; "
            f"--time-source creation uses them, --time-attribute begin=NAME reads a year "
            f"from a generic attribute")
    if settings.time_attribute and not (obj_source == TIME_SOURCE_NAMES.index("attribute")).any():
        begin_name = parse_time_attribute(settings.time_attribute)[0]
        log.warnings.append(f"no object has the generic attribute {begin_name!r} named by "
                            f"--time-attribute (or no value of it is a year or date)")
    return _Validity(obj_begin, obj_end, obj_source, creation_unused)


def _select_polygons(raw: RawModel, settings: BuildSettings, counters: Counter) -> _Selection:
    """Stages 2–4: every polygon where it is defined and where it is referenced, the LoD of
    each object, each polygon once.

    Raises
    ------
    EmptyModelError
        No polygon is left at the chosen LoDs.
    """
    n_poly_all = raw.n_polygons
    # 2. Items: every polygon where it is defined, and where it is referenced.
    ref_items = _resolve_references(raw, counters)
    own_obj = np.asarray(raw.poly_obj, np.int64)
    own_lod = np.asarray(raw.poly_lod, np.int64)
    own_flip = np.asarray(raw.poly_flip, np.int64)
    poly_cls = np.array(raw.poly_cls, np.int64)  # a copy: classes are upgraded below
    item_obj = np.concatenate([own_obj, ref_items[0]])
    item_poly = np.concatenate([np.arange(n_poly_all), ref_items[1]])
    item_lod = np.concatenate([own_lod, ref_items[2]])
    item_flip = np.concatenate([own_flip, own_flip[ref_items[1]] ^ ref_items[3]])
    # A polygon defined without a thematic surface takes the class of a surface referencing it.
    ref_cls = ref_items[4]
    upgrade = (poly_cls[ref_items[1]] == 0) & (ref_cls != 0)
    poly_cls[ref_items[1][upgrade]] = ref_cls[upgrade]

    # 3. LoD per object.
    obj_max_lod, chosen, lod_table = _choose_lods(raw, settings, item_obj, item_lod, counters)
    selected = (item_lod == chosen[item_obj]) | (item_lod < 0)
    sel_idx = np.nonzero(selected)[0]
    # 4. Each polygon once: own definitions come first in the item order, so they win
    # (assigning in reverse order leaves the first selected item of each polygon).
    first_item = np.full(n_poly_all, -1, np.int64)
    first_item[item_poly[sel_idx[::-1]]] = sel_idx[::-1]
    keep = first_item[first_item >= 0]  # ordered by polygon index
    polys = item_poly[keep]
    counters["polygons_not_selected_lod"] = int(n_poly_all - len(polys))
    if len(polys) == 0:
        lod_msg = f" at LoD {settings.lod}" if settings.lod is not None else ""
        raise EmptyModelError(f"the model has no surface geometry{lod_msg} "
                              f"({plural(len(raw.obj_ids), 'object')}, "
                              f"{plural(n_poly_all, 'polygon')} read)",
                              path=str(raw.path))
    return _Selection(polys, item_obj[keep], item_flip[keep], poly_cls, obj_max_lod, chosen,
                      lod_table)


def _choose_lods(raw: RawModel, settings: BuildSettings, item_obj: np.ndarray,
                 item_lod: np.ndarray, counters: Counter):
    """Stage 3: the LoD code of every object, the highest it has within the requested range,
    else the highest.

    Returns
    -------
    obj_max_lod, chosen : (n_obj,) int64
        Highest LoD code of each object (-1: none) and the one drawn.
    lod_table : dict
        LoD code → objects having it (an object with LoD 1 and 2 counts under both).
    """
    n_obj = len(raw.obj_ids)
    obj_max_lod = np.full(n_obj, -1, np.int64)
    np.maximum.at(obj_max_lod, item_obj, item_lod)
    # Objects per LoD they have (an object with LoD 1 and 2 counts under both).
    known = item_lod >= 0
    has = np.zeros((n_obj, max(5, int(obj_max_lod.max(initial=-1)) + 1)), bool)
    has[item_obj[known], item_lod[known]] = True
    lod_table = {lod: int(n) for lod, n in enumerate(has.sum(axis=0)) if n}
    lod_range = lod_request_range(settings.lod, raw.lod_scale)
    if lod_range is None:
        chosen = obj_max_lod
    else:
        lo, hi = lod_range
        in_range = (item_lod >= lo) & (item_lod <= hi)
        chosen = np.full(n_obj, -1, np.int64)
        np.maximum.at(chosen, item_obj[in_range], item_lod[in_range])
        has_lod = chosen >= 0
        has_lod[item_obj[item_lod < 0]] = True
        chosen[chosen < 0] = lo
        has_geometry = np.zeros(n_obj, bool)
        has_geometry[item_obj] = True
        missing = int((has_geometry & ~has_lod).sum())
        if missing:
            counters["objects_without_requested_lod"] = missing
    return obj_max_lod, chosen, lod_table


def _gather_rings(raw: RawModel, sel: _Selection, log: _BuildLog, consume_raw: bool):
    """Stage 5: the rings of the selected polygons gathered into contiguous arrays; polygons
    with bad coordinates are dropped from ``sel``.

    Returns
    -------
    rings : (R,) int64
        Original ring index of every gathered ring.
    coords : (N, 3) float64
        Gathered points, ring after ring (``raw.xyz`` itself when every point is used).
    ring_offsets : (R + 1,) int64
        First point of every ring in ``coords``.
    poly_ring_offsets : (P + 1,) int64
        First ring of every selected polygon.
    """
    polys = sel.polys
    poly_ring0 = np.append(raw.poly_ring0, len(raw.ring_points)).astype(np.int64)
    ring_start = np.concatenate([[0], np.cumsum(raw.ring_points)])
    p_nrings = poly_ring0[polys + 1] - poly_ring0[polys]
    rings = _expand_ranges(poly_ring0[polys], p_nrings)
    bad_ring = raw.ring_bad[rings].astype(bool) if len(rings) else np.zeros(0, bool)
    poly_of_ring = np.repeat(np.arange(len(polys)), p_nrings)
    bad_poly = np.zeros(len(polys), bool)
    bad_poly[poly_of_ring[bad_ring]] = True
    if bad_poly.any():
        log.counters["skipped_bad_coordinates"] = int(bad_poly.sum())
        _note_ids(log.skipped_ids, "bad_coordinates", raw, polys[bad_poly])
        good = ~bad_poly
        sel.polys, sel.p_obj, sel.p_flip = polys[good], sel.p_obj[good], sel.p_flip[good]
        polys, p_nrings = sel.polys, p_nrings[good]
        rings = _expand_ranges(poly_ring0[polys], p_nrings)
    ring_len = raw.ring_points[rings]
    if raw.point_vertex is None and int(ring_len.sum()) == len(raw.xyz):
        # Every point is used: the ranges are ascending and disjoint, so the gather is the
        # identity and the copy (a third of the read model's memory) is spared.
        coords = raw.xyz
    else:
        point_idx = _expand_ranges(ring_start[rings], ring_len)
        if raw.point_vertex is not None:
            point_idx = raw.point_vertex[point_idx]  # a shared vertex list (CityJSON)
        coords = raw.xyz[point_idx]
        del point_idx
    if consume_raw:
        raw.xyz = None  # gathered (or the very array): freed with coords after stage 9
    ring_offsets = np.concatenate([[0], np.cumsum(ring_len)]).astype(np.int64)
    poly_ring_offsets = np.concatenate([[0], np.cumsum(p_nrings)]).astype(np.int64)
    return rings, coords, ring_offsets, poly_ring_offsets


def _to_model_crs(raw: RawModel, settings: BuildSettings, target_crs: CrsInfo | None,
                  coords: np.ndarray, ring_offsets: np.ndarray, log: _BuildLog):
    """Stage 6: the scene's CRS, and ``coords`` in it (geographic coordinates projected to
    metres, a tile of a multi-file build reprojected to ``target_crs``). The file's own CRS
    and axis order go to ``log``.

    Returns
    -------
    coords : (N, 3) float64, crs : CrsInfo
    """
    resolution = resolve_model_crs_detailed(raw.srs_names.elements(),
                                            settings.crs if target_crs is None else None)
    crs = resolution.crs
    if target_crs is not None and crs.local:
        # A tile without a (known) CRS is taken to be in the one named for all tiles.
        crs = target_crs
    else:
        log.warnings += list(resolution.warnings)
    log.source_crs = crs
    if crs.is_geographic:
        projector = GeographicProjector(crs, coords, axis_order=settings.axis_order,
                                        ring_offsets=ring_offsets, target=(
                                            None if target_crs is None or target_crs.is_geographic
                                            else target_crs))
        log.warnings.append(projector.warning)
        log.axis_order = "latlon" if projector.axis_lat_first else "lonlat"
        coords = projector.project(coords)
        crs = projector.target
    elif target_crs is not None and crs.horizontal_epsg != target_crs.horizontal_epsg:
        coords = reproject_horizontal(coords, crs, target_crs)
        crs = target_crs
    elif settings.axis_order is not None:
        log.warnings.append(f"--axis-order {settings.axis_order} ignored: {crs.name} is not a "
                            f"geographic CRS (its coordinates are read easting first)")
    return coords, crs


def _leave_out_closures(raw: RawModel, sel: _Selection, tris: tuple[np.ndarray, np.ndarray],
                        ok: np.ndarray, log: _BuildLog):
    """Stage 7b: ClosureSurfaces (class ``closure``) are virtual: they close a solid where no
    wall stands (between building parts, across a passage), so they neither cast nor receive.
    Their triangles are dropped and counted (``log.left_out``) after the triangulation, so the
    counts are those a kept build would draw.

    ``tris`` is (triangles (T, 3), tri_poly_local (T,)) of :func:`_triangulate`.

    Returns
    -------
    triangles, tri_poly_local, ok : without the closure polygons' triangles.
    """
    triangles, tri_poly_local = tris
    is_closure = sel.poly_cls[sel.polys] == SURFACE_CODE["closure"]
    if not is_closure.any():
        return triangles, tri_poly_local, ok
    keep_tri = ~is_closure[tri_poly_local]
    n_left = len(keep_tri) - int(np.count_nonzero(keep_tri))
    if n_left == len(keep_tri):
        raise EmptyModelError("the model has only ClosureSurfaces, which are virtual and left "
                              "out (build --closure-surfaces keep draws them)",
                              path=str(raw.path))
    log.left_out["closure_polygons"] += int(np.count_nonzero(ok & is_closure))
    log.left_out["closure_triangles"] += n_left
    return triangles[keep_tri], tri_poly_local[keep_tri], ok & ~is_closure


def _triangulate(raw: RawModel, settings: BuildSettings, coords: np.ndarray,
                 offsets: tuple[np.ndarray, np.ndarray], sel: _Selection, log: _BuildLog):
    """Stage 7: the selected polygons triangulated in float64, OrientableSurface flips
    applied; skips and repairs counted in ``log``.

    ``offsets`` is (ring_offsets, poly_ring_offsets) of :func:`_gather_rings`.

    Returns
    -------
    triangles : (T, 3) int, tri_poly_local : (T,) int (selected-polygon index),
    area_m2 : (P,), repairs : (P,), normals : (P, 3) float64 (flipped), ok : (P,) bool

    Raises
    ------
    EmptyModelError
        No polygon could be triangulated.
    """
    from cityshade.geometry.triangulate import (REPAIR_NAMES, SKIP_REASONS, describe_skips,
                                                triangulate_polygons)

    ring_offsets, poly_ring_offsets = offsets
    polys, p_flip, counters, skipped = sel.polys, sel.p_flip, log.counters, log.skipped
    tri = triangulate_polygons(
        coords, ring_offsets, poly_ring_offsets, merge_distance_m=settings.merge_distance_m,
        collinear_rel_tol=settings.collinear_rel_tol, area_rel_tol=settings.area_rel_tol,
        min_rel_area=settings.min_rel_area, nonplanar_rel_tol=settings.nonplanar_rel_tol)
    for code, count in zip(*np.unique(tri.status, return_counts=True)):
        if code != 0:
            skipped[SKIP_REASONS[int(code)]] += int(count)
            _note_ids(log.skipped_ids, SKIP_REASONS[int(code)], raw,
                      polys[np.asarray(tri.status) == code])
    if counters.get("skipped_bad_coordinates"):
        skipped["bad_coordinates"] += counters.pop("skipped_bad_coordinates")
    log.cavities = counters.pop("cavity_polygons", 0)
    if log.cavities:
        skipped["solid_cavity_shell"] += log.cavities
    for bit, name in REPAIR_NAMES.items():
        n = int(((tri.repairs & bit) != 0).sum())
        if n:
            log.repairs[name] = n
    ok = tri.status == 0
    if not ok.any():
        raise EmptyModelError(f"no polygon could be triangulated: {describe_skips(skipped)}",
                              path=str(raw.path))
    # The result's arrays are ours: flipped and renumbered in place of copies (the
    # per-triangle arrays are the largest of the build).
    triangles, tri_poly_local = tri.triangles, tri.tri_polygon
    tri_area_m2, tri_repairs = tri.area_m2, tri.repairs
    normals = tri.normal * np.where(p_flip != 0, -1.0, 1.0)[:, None]
    del tri
    # OrientableSurface "-": reverse the winding.
    flip_tri = np.nonzero(p_flip[tri_poly_local] != 0)[0]
    triangles[flip_tri] = triangles[flip_tri][:, ::-1]
    del flip_tri
    return triangles, tri_poly_local, tri_area_m2, tri_repairs, normals, ok


@dataclass
class _Appearance:
    """Materials and textures of the drawn polygons (per polygon: -1 = none)."""

    poly_material: np.ndarray   # (P,) int32 index into ``materials``
    poly_texture: np.ndarray    # (P,) int32 index into ``textures``
    point_uv: np.ndarray        # (N, 2) float32 texture coordinates of the gathered points
    materials: list[dict] = field(default_factory=list)
    textures: list[dict] = field(default_factory=list)
    uv: np.ndarray | None = None  # (V, 2) float32 of the scene's vertices


def _theme_appearance(raw: RawModel, settings: BuildSettings, drawn: np.ndarray,
                      polys: np.ndarray, rings: np.ndarray,
                      offsets: tuple[np.ndarray, np.ndarray], coords: np.ndarray,
                      used_points: np.ndarray, log: _BuildLog) -> _Appearance:
    """Stage 9: the appearance of the chosen theme (``settings.theme``, else the file's
    first), resolved into per-polygon material/texture and per-vertex texture coordinates."""
    theme = raw.appearance.choose_theme(settings.theme)
    log.theme = theme
    if settings.theme is not None and theme is None:
        names = ", ".join(repr(t) for t in raw.appearance.themes()) or "none"
        log.warnings.append(f"appearance theme {settings.theme!r} not found; themes in the "
                            f"file: {names}")
    # float32: each texture coordinate is rounded once either way (the cache stores float32).
    look = _Appearance(np.full(len(drawn), -1, np.int32), np.full(len(drawn), -1, np.int32),
                       np.zeros((len(coords) if theme is not None else 0, 2), np.float32))
    if theme is not None:
        _apply_appearance(raw, theme, drawn, polys, rings, offsets, coords, look, log)
    look.uv = (look.point_uv[used_points] if theme is not None
               else np.zeros((len(used_points), 2), np.float32))
    look.point_uv = None
    return look


def _build_report(raw: RawModel, settings: BuildSettings, log: _BuildLog, times: _Validity,
                  lod_table: dict[int, int], obj_lod_code: np.ndarray, n_drawn: int) -> dict:
    """Stage 10: the scene's build report (what was read, drawn, skipped, repaired, chosen)."""
    obj_begin, obj_end = times.begin_days, times.end_days
    finite = np.concatenate([obj_begin[np.isfinite(obj_begin)], obj_end[np.isfinite(obj_end)]])
    time_range = ([days_to_iso(float(finite.min())), days_to_iso(float(finite.max()))]
                  if finite.size else None)
    sources = Counter(TIME_SOURCE_NAMES[int(c)] for c in times.source)
    counters, skipped = log.counters, log.skipped
    return {
        "format": raw.format,
        "versions": sorted(raw.versions),
        "objects_by_type": dict(sorted(Counter(raw.obj_types).items())),
        "polygons": {"read": raw.n_polygons + log.cavities, "drawn": int(n_drawn),
                     "skipped": int(sum(skipped.values())),
                     "not_selected_lod": counters.pop("polygons_not_selected_lod"),
                     "left_out": int(log.left_out["closure_polygons"])},
        "skipped": dict(sorted(skipped.items())),
        "left_out": dict(sorted(log.left_out.items())),
        "closure_surfaces": settings.closure_surfaces,
        "skipped_ids": dict(sorted(log.skipped_ids.items())),
        "repairs": dict(sorted(log.repairs.items())),
        "lods": {lod_label(raw, k): v for k, v in sorted(lod_table.items())},
        "lods_drawn": {lod_label(raw, int(k)): int(v) for k, v in zip(
            *np.unique(obj_lod_code[obj_lod_code >= 0], return_counts=True))},
        "lod_requested": settings.lod,
        "time_source": settings.time_source,
        "time_sources_used": dict(sorted(sources.items())),
        "time_attribute": settings.time_attribute,
        "creation_dates_unused": int(times.creation_unused),
        "time_range": time_range,
        "theme": log.theme,
        "themes": raw.appearance.themes(),
        "source_crs": log.source_crs.to_json(),
        "axis_order": log.axis_order,
        "counters": {k: int(v) for k, v in sorted(counters.items())},
        "warnings": log.warnings,
    }


def _opening_groups(openings, orig_poly) -> list:
    """``[[gml:id, [drawn polygon, ...]], ...]`` of the openings (Window/Door elements) whose
    polygons are drawn; a nested opening's polygons belong to the innermost one."""
    if not len(openings):
        return []
    owner = {}
    for k, (_, p0, p1) in enumerate(openings):
        for p in range(p0, p1):
            owner.setdefault(p, k)  # inner elements end first, so they are listed first
    groups: dict[int, list[int]] = {}
    for d, p in enumerate(np.asarray(orig_poly).tolist()):
        k = owner.get(p)
        if k is not None:
            groups.setdefault(k, []).append(d)
    return [[openings[k][0], groups[k]] for k in sorted(groups)]


def _apply_appearance(raw, theme, drawn, polys, rings, offsets, coords, look: _Appearance,
                      log: _BuildLog) -> None:
    """Fill ``look``'s per-polygon material/texture indices and per-point uv for one theme.

    ``offsets`` is (ring_offsets, poly_ring_offsets) of :func:`_gather_rings`; refused
    textures and bad texture coordinates are counted (and a few said) in ``log``.
    """
    ring_offsets, poly_ring_offsets = offsets
    poly_material, poly_texture, point_uv = look.poly_material, look.poly_texture, look.point_uv
    materials, textures = look.materials, look.textures
    warnings, counters = log.warnings, log.counters
    app = raw.appearance
    # Gathered point range of every original ring (-1: not gathered), and the drawn-polygon
    # index of every original polygon (-1: not drawn).
    ring_first = np.full(len(raw.ring_points), -1, np.int64)
    ring_first[rings] = ring_offsets[:-1]
    ring_count = np.zeros(len(raw.ring_points), np.int64)
    ring_count[rings] = np.diff(ring_offsets)
    local_of_orig = np.full(raw.n_polygons, -1, np.int64)
    local_of_orig[polys[drawn]] = np.arange(len(drawn))
    for rec in app.materials:
        if rec.theme != theme:
            continue
        # Most targets name a polygon: one dict look-up each, the rest (aggregates) one by one.
        direct = _direct_polygons(raw.poly_by_id, rec.targets)
        nested = [p for k in np.nonzero(direct < 0)[0]
                  for p in _polygon_targets(raw, rec.targets[k])]
        local = local_of_orig[np.concatenate([direct[direct >= 0],
                                              np.asarray(nested, np.int64)])]
        local = local[local >= 0]
        if len(local):
            poly_material[local] = len(materials)
            materials.append(rec.to_json())
    texture_index: dict[str, int] = {}
    for rec in app.textures:
        if rec.theme != theme:
            continue
        image, reason = resolve_image_path(rec.image_uri, raw.path)
        if image is None:
            counters["textures_refused"] += 1
            if len([w for w in warnings if w.startswith("texture")]) < 10:
                warnings.append(reason)
            continue
        key = str(image)
        if key not in texture_index:
            texture_index[key] = len(textures)
            textures.append({"path": key, "uri": rec.image_uri, "wrap_mode": rec.wrap_mode,
                             "border_color": list(rec.border_color)})
        tex = texture_index[key]
        georef = None
        if rec.kind == "georeferenced":
            georef = _georeference(rec, image)
            if georef is None:
                counters["georeferenced_textures_without_placement"] += 1
                continue
        for target, ring_uvs, matrix in rec.targets:
            for p in _polygon_targets(raw, target):
                local = local_of_orig[p]
                if local < 0:
                    continue
                sel = drawn[local]
                r0, r1 = poly_ring_offsets[sel], poly_ring_offsets[sel + 1]
                a, b = ring_offsets[r0], ring_offsets[r1]
                if georef is not None:
                    point_uv[a:b] = georeferenced_uv(coords[a:b, :2], *georef)
                elif matrix is not None:
                    m = np.asarray(matrix).reshape(3, 4)
                    h = np.column_stack([coords[a:b], np.ones(b - a)]) @ m.T
                    with np.errstate(divide="ignore", invalid="ignore"):
                        st = h[:, :2] / h[:, 2:3]
                    point_uv[a:b] = np.nan_to_num(st, nan=0.0, posinf=0.0, neginf=0.0)
                else:
                    for ring_id, text in ring_uvs:
                        r = raw.ring_by_id.get(ring_id)
                        if r is None or ring_first[r] < 0:
                            continue
                        start, n = ring_first[r], ring_count[r]
                        try:
                            values = np.array(text.split(), dtype=np.float64)
                        except ValueError:
                            values = np.empty(0)
                        if values.size != 2 * n or not np.isfinite(values).all():
                            counters["texture_coordinate_count_mismatch"] += 1
                            continue
                        point_uv[start:start + n] = values.reshape(n, 2)
                poly_texture[local] = tex


def _georeference(rec, image: Path):
    """(reference point, orientation, width, height) of a GeoreferencedTexture, or None."""
    from cityshade.errors import CityshadeError
    from cityshade.imageio import read_image

    try:
        pixels, _ = read_image(image)
    except CityshadeError:  # an unreadable image is counted by the caller
        return None
    height, width = pixels.shape[:2]
    if rec.reference_point is not None and rec.orientation is not None:
        return rec.reference_point, rec.orientation, width, height
    world = read_world_file(image)
    if world is None:
        return None
    a, d, b, e, c, f = world
    return (c, f), (a, b, d, e), width, height


def append_scene(existing: Scene, addition: Scene) -> Scene:
    """The scene ``existing`` followed by the objects of ``addition`` (same CRS; the caller
    checks), without a kd-tree: the existing arrays come first, so its object, polygon and
    triangle indices stay valid, and the addition's coordinates are moved to the existing
    origin (float64 shift, one float32 cast). Report and header are the existing scene's."""
    import dataclasses

    shift = np.asarray(addition.origin_m, np.float64) - np.asarray(existing.origin_m, np.float64)
    nv, no, npoly = len(existing.vertices), len(existing.obj_ids), len(existing.poly_ids)
    nmat, ntex = len(existing.materials), len(existing.textures)

    def offset(a, n):
        a = np.asarray(a)
        return np.where(a >= 0, a + n, a).astype(a.dtype)

    def cat(name, n=None, dtype=None):
        a, b = np.asarray(getattr(existing, name)), np.asarray(getattr(addition, name))
        if n is not None:
            b = offset(b, n)
        return np.concatenate([a, b]).astype(dtype or a.dtype)

    return dataclasses.replace(
        existing,
        vertices=np.concatenate([np.asarray(existing.vertices),
                                 (np.asarray(addition.vertices, np.float64) + shift).astype(
                                     np.asarray(existing.vertices).dtype)]),
        uv=cat("uv"), triangles=cat("triangles", nv, np.int32),
        tri_object=cat("tri_object", no, np.int32), tri_polygon=cat("tri_polygon", npoly, np.int32),
        tri_class=cat("tri_class"), tri_material=cat("tri_material", nmat),
        tri_texture=cat("tri_texture", ntex), tri_t_begin_days=cat("tri_t_begin_days"),
        tri_t_end_days=cat("tri_t_end_days"),
        obj_ids=list(existing.obj_ids) + list(addition.obj_ids),
        obj_types=list(existing.obj_types) + list(addition.obj_types),
        obj_parent=cat("obj_parent", no, np.int32), obj_t_begin_days=cat("obj_t_begin_days"),
        obj_t_end_days=cat("obj_t_end_days"), obj_time_source=cat("obj_time_source"),
        obj_lod=cat("obj_lod"), poly_ids=list(existing.poly_ids) + list(addition.poly_ids),
        poly_object=cat("poly_object", no, np.int32), poly_class=cat("poly_class"),
        poly_area_m2=cat("poly_area_m2"), poly_normal=cat("poly_normal"),
        poly_repairs=cat("poly_repairs"),
        materials=list(existing.materials) + list(addition.materials),
        textures=list(existing.textures) + list(addition.textures),
        report=dict(existing.report or {}), kdtree=None, header=dict(existing.header or {}))
