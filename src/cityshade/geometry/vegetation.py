"""Vegetation in a scene: which triangles are crowns, the scene without them, and the light
each crown lets through (docs/DESIGN.md §21).

A vegetation object (CityGML ``SolitaryVegetationObject``, ``PlantCover``, explicit or placed
by ImplicitGeometry; CityJSON the same types) is one *crown*: a sun ray keeps the product of
the transmissivities of the distinct crowns it crosses, and nothing behind an opaque triangle.
A crown is a closed surface that a ray enters and leaves, so each object counts once whatever
number of its triangles the ray meets.

The exact engines split the work in two (:func:`cityshade.shadows.visibility.transmission`):
the opaque triangles (:attr:`SceneVegetation.opaque`, a scene with its own kd-tree) through the
engines' any-hit paths as they are, then the crowns for the rays left unblocked. A scene without
vegetation never builds any of this: :func:`scene_vegetation` returns None and the engines run
as before.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import numpy as np

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.config import VegetationSettings
from cityshade.errors import UsageError

#: Object types that are vegetation, and the ``[vegetation]`` sub-table of each.
VEGETATION_TYPES = {"SolitaryVegetationObject": "solitary", "PlantCover": "plant_cover"}
#: Crown class codes (:attr:`SceneVegetation.crown_class`), in the order of these tables.
CLASS_TABLES = ("solitary", "plant_cover")


def vegetation_objects(scene) -> np.ndarray:
    """(O,) int8: per object its crown class code (index into :data:`CLASS_TABLES`), -1 for
    objects that are not vegetation. A part of a vegetation object is vegetation too."""
    n = len(scene.obj_types)
    code = np.array([CLASS_TABLES.index(VEGETATION_TYPES[t]) if t in VEGETATION_TYPES else -1
                     for t in scene.obj_types], np.int8)
    parent = np.asarray(scene.obj_parent)
    for _ in range(16):  # parts inherit their ancestor's class (nesting is shallow)
        inherit = (code < 0) & (parent >= 0)
        if not inherit.any():
            break
        took = code[np.where(inherit, parent, 0)]
        changed = inherit & (took >= 0)
        if not changed.any():
            break
        code = np.where(changed, took, code)
    return code if n else np.empty(0, np.int8)


def vegetation_mask(scene) -> np.ndarray:
    """(T,) bool: triangles of vegetation objects, or of surface class ``vegetation``."""
    tri_object = np.asarray(scene.tri_object)
    by_object = vegetation_objects(scene)[tri_object] >= 0 if len(tri_object) else \
        np.zeros(0, bool)
    return by_object | (np.asarray(scene.tri_class) == SURFACE_CODE["vegetation"])


def object_codes(scene) -> dict[int, dict]:
    """Object index → its vegetation codes from the data (``class``, ``function``, ``usage``,
    ``species``: name → values, the build report's ``vegetation_codes``); a part without
    codes of its own takes its nearest ancestor's."""
    codes = {int(i): c for i, c in (scene.report or {}).get("vegetation_codes", [])}
    if not codes:
        return {}
    parent = np.asarray(scene.obj_parent)
    out = {}
    for i in np.flatnonzero(vegetation_objects(scene) >= 0).tolist():
        j, depth = i, 0
        while j >= 0 and j not in codes and depth < 16:
            j, depth = int(parent[j]), depth + 1
        if j >= 0 and j in codes:
            out[i] = codes[j]
    return out


def evergreen_objects(scene, settings: VegetationSettings) -> np.ndarray:
    """(O,) bool: objects whose crowns keep their in-leaf transmissivity all year: their
    class table says ``evergreen``, or their codes in the data are one of
    ``evergreen_values``. Objects that are not vegetation count as solitary (a triangle of
    surface class vegetation in them is a crown of that class)."""
    code = vegetation_objects(scene)
    by_class = np.array([getattr(settings, n).evergreen for n in CLASS_TABLES])
    out = by_class[np.where(code < 0, 0, code)] if code.size else np.zeros(0, bool)
    for i, codes in object_codes(scene).items():
        out[i] |= settings.is_evergreen(codes)
    return out


#: The two kd-trees of a scene with vegetation (:func:`vegetation_kdtrees`), by name: the
#: opaque triangles' and the crowns' (their records index the subset's triangles in order).
KDTREE_PARTS = ("opaque", "crowns")


def _subscene(scene, keep: np.ndarray, part: str | None = None):
    """The scene with only the triangles ``keep`` (a bool mask), the object, polygon and
    vertex tables unchanged, and a kd-tree of its own over them: the one its file stored for
    ``part`` (:data:`KDTREE_PARTS`; None: none matches ``keep``), else built here."""
    rows = np.flatnonzero(keep)
    fields = {name: np.ascontiguousarray(np.asarray(getattr(scene, name))[rows])
              for name in ("triangles", "tri_object", "tri_polygon", "tri_class",
                           "tri_material", "tri_texture", "tri_t_begin_days",
                           "tri_t_end_days")}
    tree = None if part is None else \
        (scene.__dict__.get("stored_vegetation_kdtrees") or {}).get(part)
    if tree is None:
        from cityshade.accel.kdtree_build import build_kdtree

        tree = build_kdtree(scene.vertices, fields["triangles"], fields["tri_t_begin_days"],
                            fields["tri_t_end_days"], fields["tri_material"])
    return dataclasses.replace(scene, kdtree=tree, **fields)


def vegetation_kdtrees(scene) -> dict[str, Any] | None:
    """The opaque triangles' and the crowns' kd-trees of ``scene`` by :data:`KDTREE_PARTS`
    name (built once, as :func:`scene_vegetation` uses them), for a scene file to store: a
    process that loads them builds neither (docs/DESIGN.md §21). None without vegetation."""
    veg = scene_vegetation(scene)
    if veg is None:
        return None
    return {"opaque": veg.opaque.kdtree, "crowns": veg.tree}


def vegetation_settings(scene) -> VegetationSettings:
    """The ``[vegetation]`` settings ``scene``'s crowns use (:func:`with_vegetation`), else the
    defaults."""
    return scene.__dict__.get("vegetation_settings") or VegetationSettings()


def with_vegetation(scene, settings: VegetationSettings):
    """``scene`` as ``settings`` want it: without its vegetation when ``enabled`` is false
    (:func:`without_vegetation`), else the scene itself, its crowns using ``settings``."""
    if not settings.enabled:
        return without_vegetation(scene)
    scene.__dict__["vegetation_settings"] = settings
    return scene


def without_vegetation(scene):
    """The scene without its vegetation (``--no-vegetation``: trees neither cast nor receive),
    with a kd-tree of its own; the scene itself when it has none.

    Raises
    ------
    UsageError
        A tiled cache's view with vegetation (its tiles' trees hold it).
    """
    mask = vegetation_mask(scene)
    if not mask.any():
        return scene
    if scene.is_tiled:
        raise UsageError("--no-vegetation is not available on a tiled cache: build the model "
                         "without --tile-m, or without its vegetation")
    return _subscene(scene, ~mask, "opaque")


def window_light_scene(scene):
    """The scene the openings' daylight and sunlight are traced in (``[vegetation]
    window_trees``): without its deciduous crowns ("evergreen", BRE 209's practice), without
    any crown ("none"), or as it is ("all"). The settings stay with the scene; a tiled cache's
    view (vegetation opaque in its tiles) is returned as it is."""
    settings = vegetation_settings(scene)
    mask = vegetation_mask(scene)
    if settings.window_trees == "all" or not mask.any() or scene.is_tiled:
        return scene
    drop = mask
    if settings.window_trees == "evergreen":
        drop = mask & ~evergreen_objects(scene, settings)[np.asarray(scene.tri_object)]
    if not drop.any():
        return scene
    # Every crown dropped: the opaque triangles, whose tree the file may hold.
    sub = _subscene(scene, ~drop, "opaque" if np.array_equal(drop, mask) else None)
    sub.__dict__["vegetation_settings"] = settings
    return sub


@dataclass
class SceneVegetation:
    """The crowns of a scene, as the exact engines take them."""

    #: The scene without vegetation, with its own kd-tree: the opaque casters.
    opaque: Any
    #: Scene triangle ids of the vegetation triangles.
    tri: np.ndarray
    #: (len(tri),) int32: the crown (index into :attr:`crown_object`) of each.
    tri_crown: np.ndarray
    #: (C,) int32 object id and (C,) int8 class code of each crown, ascending object ids.
    crown_object: np.ndarray
    crown_class: np.ndarray
    #: The vegetation triangles' own kd-tree (``raytrace``; record ids index :attr:`tri`).
    tree: Any
    #: Vertices and the vegetation triangles' vertex indices and validity (``izb``).
    vertices: np.ndarray
    triangles: np.ndarray
    t_begin_days: np.ndarray
    t_end_days: np.ndarray
    #: Crown index → its object's codes from the data (:func:`object_codes`), crowns with
    #: codes only.
    crown_codes: dict = dataclasses.field(default_factory=dict)

    def evergreen(self, settings: VegetationSettings) -> np.ndarray:
        """(C,) bool: crowns with their in-leaf transmissivity all year, by their class table
        or their codes (:func:`evergreen_objects`' rule)."""
        by_class = np.array([getattr(settings, n).evergreen for n in CLASS_TABLES])
        out = by_class[self.crown_class]
        for c, codes in self.crown_codes.items():
            out[c] |= settings.is_evergreen(codes)
        return out

    def transmissivity(self, settings: VegetationSettings,
                       day_of_year: int | None) -> np.ndarray:
        """(C,) float64: the fraction of the sun each crown lets through on ``day_of_year``
        (None: a sun without a date)."""
        return self.transmissivity_in(settings, settings.in_leaf(day_of_year))

    def transmissivity_in(self, settings: VegetationSettings, leaf: bool) -> np.ndarray:
        """(C,) float64: each crown's transmissivity with deciduous crowns in leaf (``leaf``)
        or leafless; an evergreen crown (:meth:`evergreen`) keeps its in-leaf value."""
        tables = [getattr(settings, name) for name in CLASS_TABLES]
        on = np.asarray([t.leaf_on_transmissivity for t in tables], np.float64)[self.crown_class]
        if leaf:
            return on
        off = np.asarray([t.leaf_off_transmissivity for t in tables],
                         np.float64)[self.crown_class]
        return np.where(self.evergreen(settings), on, off)


def scene_vegetation(scene) -> SceneVegetation | None:
    """The crowns of ``scene`` (made once, kept with it), or None: no vegetation, or a tiled
    cache's view (whose tiles' trees hold the vegetation as opaque casters)."""
    cached = scene.__dict__.get("_vegetation", False)
    if cached is not False:
        return cached
    veg = None
    if not scene.is_tiled and scene.n_triangles:
        mask = vegetation_mask(scene)
        if mask.any():
            veg = _make_vegetation(scene, mask)
    scene.__dict__["_vegetation"] = veg
    return veg


def _make_vegetation(scene, mask: np.ndarray) -> SceneVegetation:
    codes = object_codes(scene)
    crowns = _subscene(scene, mask, "crowns")
    objects = np.asarray(crowns.tri_object)
    crown_object, tri_crown = np.unique(objects, return_inverse=True)
    classes = vegetation_objects(scene)[crown_object]
    # Triangles of surface class vegetation in an object of another type: solitary.
    classes = np.where(classes < 0, 0, classes).astype(np.int8)
    return SceneVegetation(
        opaque=_subscene(scene, ~mask, "opaque"), tri=np.flatnonzero(mask).astype(np.int32),
        tri_crown=tri_crown.astype(np.int32), crown_object=crown_object.astype(np.int32),
        crown_class=classes, tree=crowns.kdtree,
        vertices=np.ascontiguousarray(scene.vertices, dtype=np.float32),
        triangles=np.ascontiguousarray(crowns.triangles, dtype=np.int32),
        t_begin_days=np.ascontiguousarray(crowns.tri_t_begin_days, dtype=np.float64),
        t_end_days=np.ascontiguousarray(crowns.tri_t_end_days, dtype=np.float64),
        crown_codes={c: codes[o] for c, o in enumerate(crown_object.tolist()) if o in codes})


def day_of_year(sun) -> int | None:
    """Day of the year (1-366) of a sun position's UTC instant; None for a sun given by its
    angles."""
    instant = getattr(sun, "instant_utc", None)
    if not instant:
        return None
    return datetime.fromisoformat(str(instant)).timetuple().tm_yday
