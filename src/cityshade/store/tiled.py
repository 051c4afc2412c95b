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
has no kd-tree of its own: its shadow rays (:meth:`~cityshade.geometry.scene.Scene.any_hit`,
called by :mod:`cityshade.shadows.visibility`) run per tile through the tile's own tree and
are ORed; a tile whose box the receivers' box swept toward the sun cannot reach is skipped
without being mapped. Each tile's answer is exact, so the OR is the one tree's answer.
"""
from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Callable

import numpy as np

from cityshade.errors import CacheCorruptError, CacheError, InputError, UsageError
from cityshade.geometry.scene import Scene, TiledParts

INDEX_NAME = "index.json"
INDEX_KIND = "cityshade-tiled"
INDEX_VERSION = 1
#: Per-tile arrays: the global index of each object, polygon, triangle and vertex.
GLOBAL_PREFIX = "global/"
TILE_GROUPS = ("obj", "poly", "tri", "vert")
OBJ_FIELDS = ("obj_parent", "obj_t_begin_days", "obj_t_end_days", "obj_time_source", "obj_lod")
POLY_FIELDS = ("poly_object", "poly_class", "poly_area_m2", "poly_normal", "poly_repairs")
TRI_FIELDS = ("triangles", "tri_object", "tri_polygon", "tri_class", "tri_material",
               "tri_texture", "tri_t_begin_days", "tri_t_end_days")
VERT_FIELDS = ("vertices", "uv")
REBUILD_HINT = "rebuild it with `cityshade build --tile-m`"


def is_tiled_cache(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a tiled cache folder (holds an ``index.json``)."""
    p = Path(path)
    return p.is_dir() and (p / INDEX_NAME).is_file()


# --- the tiled scene ---------------------------------------------------------------------------------------

class TileTree:
    """A bounding-volume tree over the tile boxes, the top level above the tiles' kd-trees.

    Built on opening from the index's boxes (derived state, never stored): nodes split at the
    median of the tile centres along their longest axis, up to ``LEAF_TILES`` tiles per leaf;
    each node's box is the union of its tiles' boxes. :meth:`query` descends only into nodes
    whose box passes the test, and tests every tile of a leaf reached: a conservative test that
    is monotone in the box (a box inside a failing box fails too: the frustum-plane and overlap
    tests are, also in floating point, since rounding is monotone) gives the tiles the test of
    every tile in turn would give.
    """

    LEAF_TILES = 4

    def __init__(self, boxes: np.ndarray):
        boxes = np.asarray(boxes, np.float64).reshape(-1, 2, 3)
        self.boxes = boxes
        self.order = np.arange(len(boxes))
        lo, hi, first, count, children = [], [], [], [], []
        if len(boxes):
            todo = [(0, len(boxes), -1, 0)]  # (begin, end, parent node, which child)
            centre = boxes.mean(axis=1)
            while todo:
                begin, end, parent, side = todo.pop()
                node = len(lo)
                if parent >= 0:
                    children[parent][side] = node
                idx = self.order[begin:end]
                lo.append(boxes[idx, 0].min(axis=0))
                hi.append(boxes[idx, 1].max(axis=0))
                children.append([-1, -1])
                if end - begin <= self.LEAF_TILES:
                    first.append(begin)
                    count.append(end - begin)
                    continue
                first.append(begin)
                count.append(0)
                c = centre[idx]
                axis = int(np.argmax(c.max(axis=0) - c.min(axis=0)))
                self.order[begin:end] = idx[np.argsort(c[:, axis], kind="stable")]
                mid = (begin + end) // 2
                todo.append((mid, end, node, 1))
                todo.append((begin, mid, node, 0))
        self.lo = np.array(lo).reshape(-1, 3)
        self.hi = np.array(hi).reshape(-1, 3)
        self.first = np.array(first, np.int64)
        self.count = np.array(count, np.int64)
        self.children = np.array(children, np.int64).reshape(-1, 2)

    @property
    def n_nodes(self) -> int:
        return len(self.lo)

    def query(self, passes: Callable[[np.ndarray, np.ndarray], bool]) -> list[int]:
        """The tiles (ascending) whose box passes ``passes(lo, hi)``."""
        out: list[int] = []
        stack = [0] if self.n_nodes else []
        while stack:
            node = stack.pop()
            if not passes(self.lo[node], self.hi[node]):
                continue
            if self.count[node]:
                b = self.first[node]
                out += [int(t) for t in self.order[b:b + self.count[node]]
                        if passes(self.boxes[t, 0], self.boxes[t, 1])]
            else:
                stack += [int(self.children[node, 1]), int(self.children[node, 0])]
        return sorted(out)


class TiledCache:
    """An opened tiled cache: the index in memory, tiles memory-mapped on first use.

    It stands in for a scene where only the city's frame is needed (``origin_m``, ``crs``,
    ``header``, and ``vertices``/``triangles`` of its box corners, so the cameras frame the
    whole city as they frame a one-cache scene).
    """

    def __init__(self, path: Path, index: dict):
        from cityshade.geo.crs import CrsInfo

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
        self.tree = TileTree(self.boxes)
        box = np.asarray(index["box_m"], np.float64)
        self.vertices = box.astype(np.float32)
        self.triangles = np.array([[0, 1, 1]], np.int32)
        tr = index.get("time_days") or [None, None]
        self.tri_t_begin_days = np.array([-np.inf if tr[0] is None else tr[0]])
        self.tri_t_end_days = np.array([np.inf if tr[1] is None else tr[1]])
        self._open: dict[int, Scene] = {}
        self._globals: dict[int, dict[str, np.ndarray]] = {}
        self.kdtree = None
        # As a stand-in for a scene it is no view of tiles and traces nothing itself.
        self.tiling = None
        self.is_tiled = self.can_trace = False

    @property
    def box_m(self) -> list:
        """Render-space box of the whole city, [[x, y, z], [x, y, z]] metres."""
        return self.index["box_m"]

    def city_box_m(self) -> tuple[np.ndarray, np.ndarray]:
        """As a stand-in scene: the box of its corner vertices (float32, as a scene's box)."""
        return (self.vertices.min(axis=0).astype(np.float64),
                self.vertices.max(axis=0).astype(np.float64))

    @property
    def ground_m(self) -> dict[str, float]:
        """The whole city's ground heights (``min``, ``auto``; render space, metres)."""
        return self.index["ground_m"]

    @property
    def n_triangles(self) -> int:
        return int(self.index["counts"]["triangles"])

    def tile(self, i: int, verify: bool | str = "auto") -> Scene:
        """Tile ``i`` as a memory-mapped scene with its kd-tree (mapped once, then kept)."""
        scene = self._open.get(i)
        if scene is None:
            from cityshade.store.cache import open_cache
            from cityshade.store.scenefile import scene_from_cache

            entry = self.tiles[i]
            path = self.path / entry["file"]
            if not path.is_file():
                raise CacheCorruptError(f"the tile file {entry['file']} is missing; {REBUILD_HINT}",
                                        path=str(self.path))
            cache = open_cache(path, verify=verify)
            if cache.header_digest != entry["header_blake2b"]:
                raise CacheCorruptError(f"the tile file {entry['file']} is not the one the "
                                        f"index lists; {REBUILD_HINT}", path=str(self.path))
            scene = scene_from_cache(cache)
            self._globals[i] = {g: cache.array(GLOBAL_PREFIX + g) for g in TILE_GROUPS}
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
        culling pads it), found through the tree over the tiles."""
        from cityshade.raster import culling as cull

        if len(self.tiles) == 0:
            return []
        box = np.asarray(self.index["box_m"], np.float64)
        size = float(np.max(box[1] - box[0]))
        planes = cull.frustum_planes(camera, cull.FRUSTUM_PAD_REL * max(size, 1.0))
        mask = (1 << planes.shape[0]) - 1
        return self.tree.query(lambda lo, hi: not cull.outside_view(planes, lo, hi, mask)[0])

    def view(self, tile_ids: list[int] | None = None) -> Scene:
        """The tiles ``tile_ids`` (all when None) as one in-memory scene in the global order
        (see the module docstring), its :attr:`~cityshade.geometry.scene.Scene.tiling` set
        (this cache, the tiles, the one-cache index of each of its triangles and objects);
        ``kdtree`` is None (:meth:`~cityshade.geometry.scene.Scene.any_hit` traces shadow
        rays through the tiles' trees)."""
        ids = list(range(len(self.tiles))) if tile_ids is None else sorted(set(tile_ids))
        parts = [self.tile(i) for i in ids]
        if not parts:
            raise UsageError("the view reaches no tile of the tiled cache: nothing to draw")
        glob = {g: [np.asarray(self._globals[i][g]) for i in ids] for g in TILE_GROUPS}
        order, inverse, offsets = {}, {}, {}
        for g in TILE_GROUPS:
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

        gather("obj", OBJ_FIELDS)
        gather("poly", POLY_FIELDS)
        gather("tri", TRI_FIELDS)
        gather("vert", VERT_FIELDS)
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
        scene.tiling = TiledParts(source=self, tile_ids=ids,
                                  global_tri=np.concatenate(glob["tri"])[order["tri"]],
                                  global_obj=np.concatenate(glob["obj"])[order["obj"]])
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
        reach_lo, reach_hi = sweep_lo - pad, sweep_hi + pad
        return self.tree.query(lambda lo, hi: bool((lo <= reach_hi).all() and (hi >= reach_lo).all()))


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
        raise CacheError(f"not a tiled cache (no {INDEX_NAME} in the folder); {REBUILD_HINT}",
                         path=str(path)) from None
    except (OSError, ValueError, UnicodeDecodeError):
        raise CacheCorruptError(f"the tiled cache's {INDEX_NAME} is damaged; {REBUILD_HINT}",
                                path=str(path)) from None
    if not isinstance(index, dict) or index.get("kind") != INDEX_KIND:
        raise CacheCorruptError(f"{INDEX_NAME} is not a cityshade tiled-cache index; {REBUILD_HINT}",
                                path=str(path))
    if index.get("index_version") != INDEX_VERSION:
        raise CacheError(f"tiled-cache index version {index.get('index_version')}, this "
                         f"cityshade reads version {INDEX_VERSION}; {REBUILD_HINT}", path=str(path))
    return TiledCache(path, index)
