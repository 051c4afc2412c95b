"""The tiled cache: a folder of ordinary ``.cityshade`` tile files and an ``index.json``.

A city too large for one cache file (or for RAM) is stored as ``NAME/`` (docs/SCALE.md):

- ``index.json``: the shared origin and CRS, the whole city's box and report, and per tile its
  key (column, row of a ``tile_m`` grid in CRS metres), render-space box in x, y, z, time
  range, triangle/object counts, file name, size and header digest;
- ``tile_C_R.cityshade``: an ordinary scene cache (own kd-tree) of the objects whose *root*
  object's box centre lies in that grid cell — each object is stored once, a building with
  its parts — in the shared render space, plus ``global/obj``, ``global/poly``,
  ``global/tri``, ``global/vert``: the index of each of its objects, polygons, triangles and
  vertices in the same city built as one cache.

Opening reads the index only (:func:`open_tiled`); a tile is memory-mapped the first time
it is needed. A frame or batch uses a *view* (:meth:`TiledCache.view`): the tiles its camera
frustum reaches, gathered into one in-memory :class:`~cityshade.geometry.scene.Scene` in the
global order (a view of all tiles is the one-cache scene array for array), so the camera
pass, shading and outputs run unchanged and ids and ties are those of the one cache. A view
has no kd-tree of its own: its shadow rays (:func:`occluded_over_tiles`, called by
``trace.occluded`` and ``lightspace.occluded``) run per tile through the tile's own tree and
are ORed; a tile whose box the receivers' box swept toward the sun cannot reach is skipped
without being mapped. Each tile's answer is exact, so the OR is the one tree's answer.
"""
from __future__ import annotations

import json
import math
import os
import shutil
from pathlib import Path
from typing import Any, Callable

import numpy as np

from cityshade.errors import CacheCorruptError, CacheError, InputError, OutputError, UsageError
from cityshade.geometry.scene import Scene

INDEX_NAME = "index.json"
INDEX_KIND = "cityshade-tiled"
INDEX_VERSION = 1
#: Per-tile arrays: the global index of each object, polygon, triangle and vertex.
GLOBAL_PREFIX = "global/"
_GROUPS = ("obj", "poly", "tri", "vert")
_OBJ_FIELDS = ("obj_parent", "obj_t_begin_days", "obj_t_end_days", "obj_time_source", "obj_lod")
_POLY_FIELDS = ("poly_object", "poly_class", "poly_area_m2", "poly_normal", "poly_repairs")
_TRI_FIELDS = ("triangles", "tri_object", "tri_polygon", "tri_class", "tri_material",
               "tri_texture", "tri_t_begin_days", "tri_t_end_days")
_VERT_FIELDS = ("vertices", "uv")
_REBUILD = "rebuild it with `cityshade build --tile-m`"


def is_tiled_cache(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a tiled cache folder (holds an ``index.json``)."""
    p = Path(path)
    return p.is_dir() and (p / INDEX_NAME).is_file()


# --- build -------------------------------------------------------------------------------------

def root_objects(obj_parent: np.ndarray) -> np.ndarray:
    """(O,) int64: each object's top-level ancestor (itself for a top-level object)."""
    root = np.arange(len(obj_parent), dtype=np.int64)
    parent = np.asarray(obj_parent, np.int64)
    for _ in range(64):  # nesting depth; real files nest 2-3 levels
        up = parent[root]
        step = up >= 0
        if not step.any():
            break
        root = np.where(step, up, root)
    return root


def tile_keys(scene: Scene, tile_m: float) -> np.ndarray:
    """(O, 2) int64: the grid cell (column, row) of each object, by its root object's box
    centre in CRS metres (objects without triangles: their root's; roots without any: the
    lowest cell used)."""
    n_obj = len(scene.obj_ids)
    tri_obj = np.asarray(scene.tri_object, np.int64)
    root = root_objects(scene.obj_parent)
    tri_root = root[tri_obj]
    corners = np.asarray(scene.vertices)[np.asarray(scene.triangles)]  # (T, 3, 3)
    lo = np.full((n_obj, 2), np.inf)
    hi = np.full((n_obj, 2), -np.inf)
    np.minimum.at(lo, tri_root, corners[:, :, :2].min(axis=1))
    np.maximum.at(hi, tri_root, corners[:, :, :2].max(axis=1))
    del corners
    has = np.isfinite(lo).all(axis=1)
    centre = 0.5 * (lo[has] + hi[has]) + np.asarray(scene.origin_m, np.float64)[:2]
    keys = np.zeros((n_obj, 2), np.int64)
    keys[has] = np.floor(centre / float(tile_m)).astype(np.int64)
    if has.any() and not has.all():
        first = keys[has][np.lexsort((keys[has][:, 0], keys[has][:, 1]))[0]]
        keys[~has] = first
    return keys[root]


def subset_scene(scene: Scene, keep_obj: np.ndarray) -> tuple[Scene, dict[str, np.ndarray]]:
    """The part of ``scene`` holding the objects ``keep_obj`` (bool, (O,); a kept object's
    parent must be kept too), with their polygons, triangles and vertices, renumbered; and the
    global index of each kept object, polygon, triangle and vertex."""
    g_obj = np.flatnonzero(keep_obj)
    g_poly = np.flatnonzero(keep_obj[np.asarray(scene.poly_object)])
    g_tri = np.flatnonzero(keep_obj[np.asarray(scene.tri_object)])
    tris = np.asarray(scene.triangles)[g_tri]
    used = np.zeros(len(scene.vertices), bool)
    used[tris.ravel()] = True
    g_vert = np.flatnonzero(used)
    obj_map = np.full(len(keep_obj), -1, np.int64)
    obj_map[g_obj] = np.arange(len(g_obj))
    poly_map = np.full(len(scene.poly_ids), -1, np.int64)
    poly_map[g_poly] = np.arange(len(g_poly))
    vert_map = np.cumsum(used) - 1
    fields: dict[str, Any] = {"origin_m": np.asarray(scene.origin_m, np.float64)}
    for f in _OBJ_FIELDS:
        fields[f] = np.asarray(getattr(scene, f))[g_obj]
    parent = fields["obj_parent"].astype(np.int64)
    fields["obj_parent"] = np.where(parent >= 0, obj_map[np.maximum(parent, 0)], -1
                                    ).astype(np.int32)
    for f in _POLY_FIELDS:
        fields[f] = np.asarray(getattr(scene, f))[g_poly]
    fields["poly_object"] = obj_map[fields["poly_object"]].astype(np.int32)
    for f in _TRI_FIELDS[1:]:
        fields[f] = np.asarray(getattr(scene, f))[g_tri]
    fields["triangles"] = vert_map[tris].astype(np.int32)
    fields["tri_object"] = obj_map[fields["tri_object"]].astype(np.int32)
    fields["tri_polygon"] = poly_map[fields["tri_polygon"]].astype(np.int32)
    for f in _VERT_FIELDS:
        fields[f] = np.asarray(getattr(scene, f))[g_vert]
    part = Scene(crs=scene.crs, obj_ids=[scene.obj_ids[i] for i in g_obj],
                 obj_types=[scene.obj_types[i] for i in g_obj],
                 poly_ids=[scene.poly_ids[i] for i in g_poly], materials=scene.materials,
                 textures=scene.textures, report={}, **fields)
    return part, {"obj": g_obj, "poly": g_poly, "tri": g_tri, "vert": g_vert}


def _box(vertices: np.ndarray) -> list[list[float]]:
    v = np.asarray(vertices)
    if len(v) == 0:
        return [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    return [v.min(axis=0).astype(np.float64).tolist(), v.max(axis=0).astype(np.float64).tolist()]


def _time_range(begin, end) -> list[float | None]:
    """[min begin, max end] in days, None for an open end (JSON has no infinity)."""
    if len(begin) == 0:
        return [None, None]
    lo, hi = float(np.min(begin)), float(np.max(end))
    return [lo if math.isfinite(lo) else None, hi if math.isfinite(hi) else None]


def save_tiled(scene: Scene, folder: str | os.PathLike, tile_m: float, settings,
               source: dict[str, Any], build_options: dict[str, Any],
               progress: Callable[[str, int, int], None] | None = None) -> int:
    """Write ``scene`` (without kd-tree) as a tiled cache in ``folder``: one tile at a time
    (its part, its kd-tree, its file, then dropped), the index last; returns the bytes
    written. An existing tiled cache there is replaced; the new one is written beside it
    under a temporary name and renamed, so an interrupted build leaves the old one whole.

    Raises
    ------
    UsageError
        A tile side that is not a positive number.
    OutputError
        The folder exists and is not a tiled cache, or cannot be written.
    """
    from cityshade.build import build_tree
    from cityshade.cache import open_cache, write_verified_stamp
    from cityshade.scenefile import save_scene
    from cityshade.util import release_freed_memory

    if not (isinstance(tile_m, (int, float)) and math.isfinite(tile_m) and tile_m > 0):
        raise UsageError(f"--tile-m must be a positive number of metres, not {tile_m!r}")
    folder = Path(folder)
    if folder.exists() and not is_tiled_cache(folder):
        raise OutputError("exists and is not a tiled cache (a folder with index.json): "
                          "give another -o", path=str(folder))
    tmp = folder.with_name(f".{folder.name}.{os.getpid()}.tmp")
    try:
        tmp.mkdir(parents=True)
    except OSError as exc:
        raise OutputError(f"cannot write here: {exc.strerror}", path=str(folder)) from None
    try:
        keys = tile_keys(scene, tile_m)
        cells, cell_of = np.unique(keys, axis=0, return_inverse=True)
        cell_of = cell_of.ravel()
        tiles = []
        total = 0
        for i, (col, row) in enumerate(cells.tolist()):
            if progress:
                progress(f"tile {i + 1}/{len(cells)}", i, len(cells))
            part, globals_ = subset_scene(scene, cell_of == i)
            timings: dict[str, float] = {}
            part.kdtree = build_tree(part, settings, None, timings)
            part.report = {"tile": [col, row], "tile_m": tile_m, "timings": timings}
            name = f"tile_{col}_{row}.cityshade"
            extra = {GLOBAL_PREFIX + g: globals_[g].astype(np.int64) for g in _GROUPS}
            size = save_scene(part, tmp / name, source, build_options, extra_arrays=extra)
            digest = open_cache(tmp / name, verify=False).header_digest
            tiles.append({"key": [col, row], "file": name, "size": size, "header_blake2b": digest,
                          "box_m": _box(part.vertices),
                          "time_days": _time_range(part.tri_t_begin_days, part.tri_t_end_days),
                          "triangles": part.n_triangles, "objects": len(part.obj_ids),
                          "polygons": len(part.poly_ids), "vertices": int(len(part.vertices)),
                          "kdtree": {k: part.kdtree.stats.get(k) for k in
                                     ("nodes", "leaves", "duplication", "sah_cost", "build_s")}})
            total += size
            del part, globals_, extra
            release_freed_memory()
        from cityshade.ground import ground_height_m

        box = _box(scene.vertices)
        index = {
                 "ground_m": {m: ground_height_m(scene, m) for m in ("min", "auto")},"kind": INDEX_KIND, "index_version": INDEX_VERSION,
                 "tile_m": tile_m, "origin_m": np.asarray(scene.origin_m, np.float64).tolist(),
                 "crs": scene.crs.to_json(), "box_m": box,
                 "counts": {"objects": len(scene.obj_ids), "polygons": len(scene.poly_ids),
                            "triangles": scene.n_triangles, "vertices": int(len(scene.vertices))},
                 "time_days": _time_range(scene.tri_t_begin_days, scene.tri_t_end_days),
                 "source": source, "build_options": build_options, "report": scene.report,
                 "materials": scene.materials, "textures": scene.textures,
                 "object_types": sorted(set(scene.obj_types)), "tiles": tiles,
                 "surface_classes": np.bincount(np.asarray(scene.tri_class)).tolist()}
        blob = json.dumps(index, sort_keys=True, indent=1).encode("utf-8")
        (tmp / INDEX_NAME).write_bytes(blob)
        total += len(blob)
        if folder.exists():
            old = folder.with_name(f".{folder.name}.{os.getpid()}.old")
            os.replace(folder, old)
            os.replace(tmp, folder)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, folder)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    # The stamps name the files' paths: stamp them again under the folder's final name (the
    # rename of the folder changed no file), so the first use maps a tile without a full check.
    for t in tiles:
        write_verified_stamp(folder / t["file"], t["header_blake2b"])
    return total


# --- use ---------------------------------------------------------------------------------------

class TiledCache:
    """An opened tiled cache: the index in memory, tiles memory-mapped on first use.

    It stands in for a scene where only the city's frame is needed (``origin_m``, ``crs``,
    ``header``, and ``vertices``/``triangles`` of its box corners, so the cameras frame the
    whole city as they frame a one-cache scene).
    """

    def __init__(self, path: Path, index: dict):
        from cityshade.citygml.crs import CrsInfo

        self.path = path
        self.index = index
        self.crs = CrsInfo.from_json(index["crs"])
        self.origin_m = np.asarray(index["origin_m"], np.float64)
        self.header = {"source": index.get("source", {}), "report": index.get("report", {}),
                       "build_options": index.get("build_options", {})}
        self.report = index.get("report", {})
        self.materials = index.get("materials", [])
        self.textures = index.get("textures", [])
        self.tiles = index["tiles"]
        self.boxes = np.array([t["box_m"] for t in self.tiles], np.float64).reshape(-1, 2, 3)
        box = np.asarray(index["box_m"], np.float64)
        self.vertices = box.astype(np.float32)
        self.triangles = np.array([[0, 1, 1]], np.int32)
        tr = index.get("time_days") or [None, None]
        self.tri_t_begin_days = np.array([-np.inf if tr[0] is None else tr[0]])
        self.tri_t_end_days = np.array([np.inf if tr[1] is None else tr[1]])
        self._open: dict[int, Scene] = {}
        self._globals: dict[int, dict[str, np.ndarray]] = {}
        self.kdtree = None

    @property
    def n_triangles(self) -> int:
        return int(self.index["counts"]["triangles"])

    def tile(self, i: int, verify: bool | str = "auto") -> Scene:
        """Tile ``i`` as a memory-mapped scene with its kd-tree (mapped once, then kept)."""
        scene = self._open.get(i)
        if scene is None:
            from cityshade.cache import open_cache
            from cityshade.scenefile import scene_from_cache

            entry = self.tiles[i]
            path = self.path / entry["file"]
            if not path.is_file():
                raise CacheCorruptError(f"the tile file {entry['file']} is missing; {_REBUILD}",
                                        path=str(self.path))
            cache = open_cache(path, verify=verify)
            if cache.header_digest != entry["header_blake2b"]:
                raise CacheCorruptError(f"the tile file {entry['file']} is not the one the "
                                        f"index lists; {_REBUILD}", path=str(self.path))
            scene = scene_from_cache(cache)
            self._globals[i] = {g: cache.array(GLOBAL_PREFIX + g) for g in _GROUPS}
            self._open[i] = scene
        return scene

    def tile_globals(self, i: int) -> dict[str, np.ndarray]:
        """Tile ``i``'s one-cache index of each of its objects, polygons, triangles and
        vertices (``obj``, ``poly``, ``tri``, ``vert``)."""
        self.tile(i)
        return self._globals[i]

    @property
    def tiles_mapped(self) -> list[int]:
        """The tiles memory-mapped so far."""
        return sorted(self._open)

    def verify(self) -> None:
        """Check every tile file against its checksums (``info --verify``)."""
        for i in range(len(self.tiles)):
            self._open.pop(i, None)
            self.tile(i, verify=True)

    def tiles_in_view(self, camera) -> list[int]:
        """The tiles whose box the camera's frustum reaches (padded as the rasterizer's
        culling pads it)."""
        from cityshade.raster import culling as cull

        if len(self.tiles) == 0:
            return []
        box = np.asarray(self.index["box_m"], np.float64)
        size = float(np.max(box[1] - box[0]))
        planes = cull.frustum_planes(camera, cull.FRUSTUM_PAD_REL * max(size, 1.0))
        mask = (1 << planes.shape[0]) - 1
        return [i for i in range(len(self.tiles))
                if not cull.box_outside(planes, self.boxes[i, 0], self.boxes[i, 1], mask)[0]]

    def view(self, tile_ids: list[int] | None = None) -> Scene:
        """The tiles ``tile_ids`` (all when None) as one in-memory scene in the global order
        (see the module docstring): ``tiled`` (this cache), ``tile_ids`` and
        ``global_tri``/``global_obj`` (the one-cache index of each of its triangles and
        objects) are set; ``kdtree`` is None (shadow rays go through the tiles' trees)."""
        ids = list(range(len(self.tiles))) if tile_ids is None else sorted(set(tile_ids))
        parts = [self.tile(i) for i in ids]
        if not parts:
            raise UsageError("the view reaches no tile of the tiled cache: nothing to draw")
        glob = {g: [np.asarray(self._globals[i][g]) for i in ids] for g in _GROUPS}
        order, inverse, offsets = {}, {}, {}
        for g in _GROUPS:
            cat = np.concatenate(glob[g])
            sizes = [len(a) for a in glob[g]]
            offsets[g] = np.concatenate([[0], np.cumsum(sizes)])
            if g == "vert":  # a vertex shared by objects in two tiles is kept once
                uniq, first, inv = np.unique(cat, return_index=True, return_inverse=True)
                order[g], inverse[g] = first, inv.ravel()
            else:
                o = np.argsort(cat, kind="stable")
                inv = np.empty(len(o), np.int64)
                inv[o] = np.arange(len(o))
                order[g], inverse[g] = o, inv
        fields: dict[str, Any] = {"origin_m": self.origin_m.copy()}

        def gather(group, names):
            for f in names:
                cat = np.concatenate([np.asarray(getattr(p, f)) for p in parts])
                fields[f] = cat[order[group]]

        def remap(group, values, part_of):
            """Tile-local indices → view indices (``part_of``: the tile of each value)."""
            v = np.asarray(values, np.int64)
            return inverse[group][v + offsets[group][part_of]]

        gather("obj", _OBJ_FIELDS)
        gather("poly", _POLY_FIELDS)
        gather("tri", _TRI_FIELDS)
        gather("vert", _VERT_FIELDS)
        part_obj = np.repeat(np.arange(len(parts)), [len(a) for a in glob["obj"]])[order["obj"]]
        part_poly = np.repeat(np.arange(len(parts)), [len(a) for a in glob["poly"]])[order["poly"]]
        part_tri = np.repeat(np.arange(len(parts)), [len(a) for a in glob["tri"]])[order["tri"]]
        parent = fields["obj_parent"].astype(np.int64)
        fields["obj_parent"] = np.where(parent >= 0, remap("obj", np.maximum(parent, 0), part_obj),
                                        -1).astype(np.int32)
        fields["poly_object"] = remap("obj", fields["poly_object"], part_poly).astype(np.int32)
        fields["tri_object"] = remap("obj", fields["tri_object"], part_tri).astype(np.int32)
        fields["tri_polygon"] = remap("poly", fields["tri_polygon"], part_tri).astype(np.int32)
        fields["triangles"] = remap("vert", fields["triangles"], part_tri[:, None]
                                    ).astype(np.int32)
        # The id tables decoded once per tile (PackedStrings iterate fast, index slowly).
        obj_all = [oid for p in parts for oid in p.obj_ids]
        type_all = [t for p in parts for t in p.obj_types]
        poly_all = [pid for p in parts for pid in p.poly_ids]
        obj_ids = [obj_all[i] for i in order["obj"].tolist()]
        obj_types = [type_all[i] for i in order["obj"].tolist()]
        poly_ids = [poly_all[i] for i in order["poly"].tolist()]
        scene = Scene(crs=self.crs, obj_ids=obj_ids, obj_types=obj_types, poly_ids=poly_ids,
                      materials=self.materials, textures=self.textures, report=self.report,
                      **fields)
        scene.header = dict(self.header)
        scene.tiled = self
        scene.tile_ids = ids
        scene.global_tri = np.concatenate(glob["tri"])[order["tri"]]
        scene.global_obj = np.concatenate(glob["obj"])[order["obj"]]
        return scene

    def tiles_reaching(self, origins: np.ndarray, sun_direction: np.ndarray) -> list[int]:
        """The tiles a shadow ray from ``origins`` toward ``sun_direction`` can hit before it
        leaves the city: those whose box meets the origins' box swept toward the sun up to the
        city's top (a conservative box test)."""
        if len(origins) == 0:
            return []
        lo = origins.min(axis=0)
        hi = origins.max(axis=0)
        d = np.asarray(sun_direction, np.float64).reshape(-1, 3)
        top = float(np.asarray(self.index["box_m"])[1][2])
        sweep_lo, sweep_hi = lo.copy(), hi.copy()
        for dv in d:
            if dv[2] > 0.0:
                s = max(0.0, top - float(lo[2])) / dv[2]
                end = s * dv
            else:  # level or downward: to the far side of the city
                box = np.asarray(self.index["box_m"], np.float64)
                s = float(np.linalg.norm(box[1] - box[0])) + float(
                    np.max(np.abs(np.r_[lo - box[0], hi - box[1]])))
                end = s * dv
            sweep_lo = np.minimum(sweep_lo, lo + np.minimum(end, 0.0))
            sweep_hi = np.maximum(sweep_hi, hi + np.maximum(end, 0.0))
        pad = 1e-6 * max(1.0, float(np.max(np.abs(self.boxes)))) if len(self.boxes) else 0.0
        hit = ((self.boxes[:, 0] <= sweep_hi + pad) & (self.boxes[:, 1] >= sweep_lo - pad)
               ).all(axis=1)
        return [int(i) for i in np.flatnonzero(hit)]


def to_global(global_index: np.ndarray, ids: np.ndarray) -> np.ndarray:
    """A view's ids (-1: none) as the one cache's ids, in ``ids``' dtype and shape."""
    ids = np.asarray(ids)
    return np.where(ids >= 0, np.asarray(global_index)[np.maximum(ids, 0)], -1).astype(ids.dtype)


def occluded_over_tiles(view, origins, directions, engine: Callable) -> np.ndarray:
    """Shadow rays of a tiled view (``directions``: (3,) shared or (N, 3)): ``engine(tile_scene,
    rays)`` (an exact any-hit test of the rays with those indices) on every tile the rays can
    reach, ORed; rays already blocked are not traced again."""
    origins = np.asarray(origins, np.float64).reshape(-1, 3)
    dirs = np.asarray(directions, np.float64).reshape(-1, 3)
    blocked = np.zeros(len(origins), bool)
    if len(dirs) > 1 and (dirs == dirs[0]).all():
        dirs = dirs[:1]
    for i in view.tiled.tiles_reaching(origins, dirs):
        todo = np.flatnonzero(~blocked)
        if len(todo) == 0:
            break
        blocked[todo] |= engine(view.tiled.tile(i), todo)
    return blocked


def open_tiled(path: str | os.PathLike) -> TiledCache:
    """Open a tiled cache: read and check its index (no tile is read).

    Raises
    ------
    InputError
        No such folder.
    CacheError
        Not a tiled cache, another index version, or a damaged index.
    """
    path = Path(path)
    if not path.is_dir():
        raise InputError("no such folder", path=str(path))
    try:
        index = json.loads((path / INDEX_NAME).read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CacheError(f"not a tiled cache (no {INDEX_NAME} in the folder); {_REBUILD}",
                         path=str(path)) from None
    except (OSError, ValueError, UnicodeDecodeError):
        raise CacheCorruptError(f"the tiled cache's {INDEX_NAME} is damaged; {_REBUILD}",
                                path=str(path)) from None
    if not isinstance(index, dict) or index.get("kind") != INDEX_KIND:
        raise CacheCorruptError(f"{INDEX_NAME} is not a cityshade tiled-cache index; {_REBUILD}",
                                path=str(path))
    if index.get("index_version") != INDEX_VERSION:
        raise CacheError(f"tiled-cache index version {index.get('index_version')}, this "
                         f"cityshade reads version {INDEX_VERSION}; {_REBUILD}", path=str(path))
    return TiledCache(path, index)
