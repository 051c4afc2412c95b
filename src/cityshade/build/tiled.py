"""The tiled cache's write side: objects to grid cells, one ordinary cache per tile, the index.

The format and its read side are :mod:`cityshade.store.tiled`; this module writes it, from one
scene in memory (:func:`save_tiled`) or from many files without assembling the city
(:func:`build_tiled_from_files`: each file's objects spilled to their tiles on disk).
"""
from __future__ import annotations

import json
import math
import os
import shutil
from pathlib import Path
from typing import Any, Callable

import numpy as np

from cityshade.errors import OutputError, UsageError
from cityshade.build.merge import SceneMerger
from cityshade.geometry.scene import Scene, root_objects
from cityshade.store.tiled import (GLOBAL_PREFIX, INDEX_KIND, INDEX_NAME, INDEX_VERSION,
                                   OBJ_FIELDS, TILE_GROUPS, is_tiled_cache, POLY_FIELDS, TRI_FIELDS, VERT_FIELDS)


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
    for f in OBJ_FIELDS:
        fields[f] = np.asarray(getattr(scene, f))[g_obj]
    parent = fields["obj_parent"].astype(np.int64)
    fields["obj_parent"] = np.where(parent >= 0, obj_map[np.maximum(parent, 0)], -1
                                    ).astype(np.int32)
    for f in POLY_FIELDS:
        fields[f] = np.asarray(getattr(scene, f))[g_poly]
    fields["poly_object"] = obj_map[fields["poly_object"]].astype(np.int32)
    for f in TRI_FIELDS[1:]:
        fields[f] = np.asarray(getattr(scene, f))[g_tri]
    fields["triangles"] = vert_map[tris].astype(np.int32)
    fields["tri_object"] = obj_map[fields["tri_object"]].astype(np.int32)
    fields["tri_polygon"] = poly_map[fields["tri_polygon"]].astype(np.int32)
    for f in VERT_FIELDS:
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


def _is_empty_folder(folder: Path) -> bool:
    return folder.is_dir() and next(folder.iterdir(), None) is None


def _start(folder: Path, tile_m) -> Path:
    """Check the tile side and the output; make and return the temporary folder beside it."""
    if not (isinstance(tile_m, (int, float)) and math.isfinite(tile_m) and tile_m > 0):
        raise UsageError(f"--tile-m must be a positive number of metres, not {tile_m!r}")
    # An empty folder is taken: the CLI creates the output folder before the work, when it
    # checks that it can write there.
    if folder.exists() and not is_tiled_cache(folder) and not _is_empty_folder(folder):
        raise OutputError("exists and is not a tiled cache (a folder with index.json): "
                          "give another -o", path=str(folder))
    tmp = folder.with_name(f".{folder.name}.{os.getpid()}.tmp")
    try:
        tmp.mkdir(parents=True)
    except OSError as exc:
        raise OutputError(f"cannot write here: {exc.strerror}", path=str(folder)) from None
    return tmp


def _write_tile(part: Scene, globals_: dict[str, np.ndarray], tmp: Path, key, tile_m, settings,
                source, build_options) -> dict:
    """Build ``part``'s kd-tree, write it as ``tile_C_R.cityshade`` in ``tmp``; its index entry."""
    from cityshade.build import build_tree
    from cityshade.store.cache import open_cache
    from cityshade.store.scenefile import save_scene

    col, row = key
    timings: dict[str, float] = {}
    part.kdtree = build_tree(part, settings, None, timings)
    part.report = {"tile": [col, row], "tile_m": tile_m, "timings": timings}
    name = f"tile_{col}_{row}.cityshade"
    extra = {GLOBAL_PREFIX + g: np.asarray(globals_[g]).astype(np.int64) for g in TILE_GROUPS}
    size = save_scene(part, tmp / name, source, build_options, extra_arrays=extra,
                      vegetation_trees=False)  # a tiled view's vegetation casts as opaque
    digest = open_cache(tmp / name, verify=False).header_digest
    return {"key": [col, row], "file": name, "size": size, "header_blake2b": digest,
            "box_m": _box(part.vertices),
            "time_days": _time_range(part.tri_t_begin_days, part.tri_t_end_days),
            "triangles": part.n_triangles, "objects": len(part.obj_ids),
            "polygons": len(part.poly_ids), "vertices": int(len(part.vertices)),
            "kdtree": {k: part.kdtree.stats.get(k) for k in
                       ("nodes", "leaves", "duplication", "sah_cost", "build_s")}}


def _finish(tmp: Path, folder: Path, index: dict, tiles: list[dict]) -> int:
    """Write the index into ``tmp``, put ``tmp`` in place of ``folder`` (an old tiled cache
    there is replaced), stamp the tiles; returns the index's bytes."""
    from cityshade.store.cache import write_verified_stamp

    blob = json.dumps(index, sort_keys=True, indent=1).encode("utf-8")
    (tmp / INDEX_NAME).write_bytes(blob)
    if folder.exists():
        old = folder.with_name(f".{folder.name}.{os.getpid()}.old")
        os.replace(folder, old)
        os.replace(tmp, folder)
        shutil.rmtree(old, ignore_errors=True)
    else:
        os.replace(tmp, folder)
    # The stamps name the files' paths: stamp them again under the folder's final name (the
    # rename of the folder changed no file), so the first use maps a tile without a full check.
    for t in tiles:
        write_verified_stamp(folder / t["file"], t["header_blake2b"])
    return len(blob)


def _index(whole: dict, tile_m, source, build_options, tiles: list[dict]) -> dict:
    """The index: ``whole`` (the city's figures: origin_m, crs, box_m, counts, time_days,
    ground_m, report, materials, textures, object_types, surface_classes) and the tiles."""
    return {"kind": INDEX_KIND, "index_version": INDEX_VERSION, "tile_m": tile_m,
            "source": source, "build_options": build_options, "tiles": tiles, **whole}


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
    from cityshade.geometry.ground import ground_height_m
    from cityshade.runtime.memory import release_freed_memory

    folder = Path(folder)
    tmp = _start(folder, tile_m)
    try:
        keys = tile_keys(scene, tile_m)
        cells, cell_of = np.unique(keys, axis=0, return_inverse=True)
        cell_of = cell_of.ravel()
        tiles = []
        total = 0
        for i, key in enumerate(cells.tolist()):
            if progress:
                progress(f"tile {i + 1}/{len(cells)}", i, len(cells))
            part, globals_ = subset_scene(scene, cell_of == i)
            tiles.append(_write_tile(part, globals_, tmp, key, tile_m, settings, source,
                                     build_options))
            total += tiles[-1]["size"]
            del part, globals_
            release_freed_memory()
        whole = {"ground_m": {m: ground_height_m(scene, m) for m in ("min", "auto")},
                 "origin_m": np.asarray(scene.origin_m, np.float64).tolist(),
                 "crs": scene.crs.to_json(), "box_m": _box(scene.vertices),
                 "counts": {"objects": len(scene.obj_ids), "polygons": len(scene.poly_ids),
                            "triangles": scene.n_triangles, "vertices": int(len(scene.vertices))},
                 "time_days": _time_range(scene.tri_t_begin_days, scene.tri_t_end_days),
                 "report": scene.report, "materials": scene.materials,
                 "textures": scene.textures, "object_types": sorted(set(scene.obj_types)),
                 "surface_classes": np.bincount(np.asarray(scene.tri_class)).tolist()}
        total += _finish(tmp, folder, _index(whole, tile_m, source, build_options, tiles), tiles)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return total


# --- the streaming build of several files ------------------------------------------------------
#
# A city in many files is never assembled: each file's new objects (in the merged numbering, as
# SceneMerger keeps them) are spilled to disk per tile, the float64 model coordinates kept; the
# origin is chosen after the last file from the exact box of every kept vertex, and each tile
# is then read back, cast to float32 around that origin and built. The result is the tiled
# cache of the assembled city bit for bit: the same origin, every object in the tile
# tile_keys gives it, the same arrays in the same order.
#
# A file's objects are spilled to the cell of their root's box so far, in float64 model
# metres; tile_keys decides on float32 render-space corners around the final origin, and a
# later file can still add a part to a building. Objects whose final cell differs (a centre
# within float32 rounding of a cell edge, a part in a later file, an object without triangles)
# are moved once, before the tiles are built.

#: Arrays of a spilled record set per group (the group's own key holds the global indices).
_SPILL = {"obj": OBJ_FIELDS, "poly": POLY_FIELDS, "tri": TRI_FIELDS, "vert": ("world", "uv")}
_PENDING = (None, None)  # the bucket of objects whose root has no triangle yet


def _subset_records(rec: dict, obj_mask: np.ndarray) -> dict:
    """The records of the objects ``obj_mask`` (bool over ``rec["obj"]``): their polygons,
    triangles and the vertices those use (indices stay global)."""
    g_obj = rec["obj"][obj_mask]
    masks = {"obj": obj_mask, "poly": np.isin(rec["poly_object"], g_obj),
             "tri": np.isin(rec["tri_object"], g_obj)}
    masks["vert"] = np.isin(rec["vert"], rec["triangles"][masks["tri"]])
    out = {}
    for group, names in _SPILL.items():
        for k in (group,) + names:
            out[k] = rec[k][masks[group]]
    out["poly_ids"] = [rec["poly_ids"][i] for i in np.flatnonzero(masks["poly"]).tolist()]
    return out


def _save_records(path: Path, rec: dict) -> None:
    from cityshade.store.cache import pack_strings

    blob, offsets = pack_strings(rec["poly_ids"])
    with open(path, "wb") as fh:
        np.savez(fh, poly_id_blob=blob, poly_id_offsets=offsets,
                 **{k: v for k, v in rec.items() if k != "poly_ids"})


def _load_records(path: Path) -> dict:
    from cityshade.store.cache import unpack_strings

    with np.load(path) as z:
        rec = {k: z[k] for k in z.files}
    rec["poly_ids"] = unpack_strings(rec.pop("poly_id_blob"), rec.pop("poly_id_offsets"))
    return rec


class TiledBuild:
    """What a streaming tiled build returns in place of the scene (for the build's summary)."""

    def __init__(self, n_triangles: int, obj_ids: list[str], report: dict):
        self.n_triangles = n_triangles
        self.obj_ids = obj_ids
        self.report = report


class TileSpill(SceneMerger):
    """A :class:`SceneMerger` that spills each file's new objects to per-tile record
    files in ``spill_dir`` instead of keeping them, and keeps only per-object figures."""

    def __init__(self, spill_dir: Path, tile_m: float, crs_given: bool = False):
        super().__init__(crs_given)
        self.dir = spill_dir
        self.tile_m = float(tile_m)
        self.parent = np.zeros(0, np.int64)
        self.root_lo = np.zeros((0, 2))
        self.root_hi = np.zeros((0, 2))
        self.obj_time: dict[str, list[np.ndarray]] = {
            f: [] for f in ("obj_t_begin_days", "obj_t_end_days", "obj_time_source")}
        self.world_lo = np.full(3, np.inf)
        self.world_hi = np.full(3, -np.inf)
        self.tri_days = [np.inf, -np.inf]
        self.classes = np.zeros(0, np.int64)
        self.chunks: dict[tuple, list[tuple[Path, np.ndarray]]] = {}  # bucket → (file, objects)
        self.n_chunks = 0

    def _spill(self, bucket: tuple, rec: dict) -> None:
        path = self.dir / f"chunk_{self.n_chunks}.npz"
        self.n_chunks += 1
        _save_records(path, rec)
        self.chunks.setdefault(bucket, []).append((path, rec["obj"]))

    def keep(self, part: dict) -> None:
        self.obj_ids += part["obj_ids"]
        self.obj_types += part["obj_types"]
        n = len(part["obj_ids"])
        o0, p0, t0, v0 = self.n_obj, self.n_poly, self.n_tri, self.n_vert
        rec = {"obj": np.arange(o0, o0 + n), "poly_ids": part["poly_ids"],
               "poly": np.arange(p0, p0 + len(part["poly_ids"])),
               "tri": np.arange(t0, t0 + len(part["tri"]["tri_object"])),
               "vert": np.arange(v0, v0 + len(part["world"])),
               "world": part["world"], "uv": part["uv"],
               **part["obj"], **part["poly"], **part["tri"]}
        rec["poly_normal"] = rec["poly_normal"].reshape(-1, 3)
        rec["triangles"] = rec["triangles"].reshape(-1, 3)
        for f, parts in self.obj_time.items():
            parts.append(rec[f])
        world = rec["world"]
        if len(world):
            self.world_lo = np.minimum(self.world_lo, world.min(axis=0))
            self.world_hi = np.maximum(self.world_hi, world.max(axis=0))
        if len(rec["tri"]):
            self.tri_days = [min(self.tri_days[0], float(np.min(rec["tri_t_begin_days"]))),
                             max(self.tri_days[1], float(np.max(rec["tri_t_end_days"])))]
            counts = np.bincount(np.asarray(rec["tri_class"], np.int64))
            size = max(len(counts), len(self.classes))
            self.classes = (np.pad(self.classes, (0, size - len(self.classes)))
                            + np.pad(counts, (0, size - len(counts))))
        # Each object's box in model metres, then its root's box so far.
        corners = world[rec["triangles"] - v0][:, :, :2]
        lo = np.full((n, 2), np.inf)
        hi = np.full((n, 2), -np.inf)
        local = np.asarray(rec["tri_object"], np.int64) - o0
        np.minimum.at(lo, local, corners.min(axis=1))
        np.maximum.at(hi, local, corners.max(axis=1))
        del corners
        self.parent = np.concatenate([self.parent, np.asarray(rec["obj_parent"], np.int64)])
        self.root_lo = np.concatenate([self.root_lo, np.full((n, 2), np.inf)])
        self.root_hi = np.concatenate([self.root_hi, np.full((n, 2), -np.inf)])
        root = root_objects(self.parent)[o0:]
        np.minimum.at(self.root_lo, root, lo)
        np.maximum.at(self.root_hi, root, hi)
        box_lo, box_hi = self.root_lo[root], self.root_hi[root]
        has = np.isfinite(box_lo).all(axis=1)
        cell = np.zeros((n, 2), np.int64)
        cell[has] = np.floor(0.5 * (box_lo[has] + box_hi[has]) / self.tile_m)
        if not has.all():
            self._spill(_PENDING, _subset_records(rec, ~has))
        if has.any():
            keys, inverse = np.unique(cell[has], axis=0, return_inverse=True)
            inverse = inverse.ravel()
            where = np.flatnonzero(has)
            for j, key in enumerate(keys.tolist()):
                mask = np.zeros(n, bool)
                mask[where[inverse == j]] = True
                self._spill(tuple(key), _subset_records(rec, mask))

    def final_keys(self, origin: np.ndarray) -> np.ndarray:
        """(O, 2) int64: every object's cell as :func:`tile_keys` gives it in the
        assembled city (float32 render-space corners around ``origin``)."""
        root = root_objects(self.parent)
        has = np.isfinite(self.root_lo).all(axis=1)
        o = np.asarray(origin, np.float64)[:2]
        # float32 rounding is monotonic: the min of the cast corners is the cast min.
        lo = (self.root_lo[has] - o).astype(np.float32).astype(np.float64)
        hi = (self.root_hi[has] - o).astype(np.float32).astype(np.float64)
        keys = np.zeros((len(self.parent), 2), np.int64)
        keys[has] = np.floor((0.5 * (lo + hi) + o) / self.tile_m).astype(np.int64)
        if has.any() and not has.all():
            first = keys[has][np.lexsort((keys[has][:, 0], keys[has][:, 1]))[0]]
            keys[~has] = first
        return keys[root]

    def move(self, keys: np.ndarray) -> None:
        """Copy the objects spilled to another bucket than their final cell into theirs
        (the source keeps them; a tile takes only its own objects)."""
        for bucket in list(self.chunks):
            for path, g_obj in list(self.chunks[bucket]):
                dest = keys[g_obj]
                away = (np.ones(len(g_obj), bool) if bucket == _PENDING
                        else (dest != np.asarray(bucket)).any(axis=1))
                if not away.any():
                    continue
                rec = _load_records(path)
                for key in np.unique(dest[away], axis=0).tolist():
                    mask = away & (dest == np.asarray(key)).all(axis=1)
                    self._spill(tuple(key), _subset_records(rec, mask))
                del rec
        self.chunks.pop(_PENDING, None)

    def tile(self, key: tuple, keys: np.ndarray, origin: np.ndarray
             ) -> tuple[Scene, dict[str, np.ndarray]]:
        """Cell ``key``'s part in render space and its global indices (as
        :func:`subset_scene` of the assembled city gives them)."""
        recs = []
        for path, g_obj in self.chunks.get(key, []):
            rec = _load_records(path)
            mine = (keys[g_obj] == np.asarray(key)).all(axis=1)
            recs.append(rec if mine.all() else _subset_records(rec, mine))
            path.unlink()
        cat = {k: np.concatenate([r[k] for r in recs])
               for k in recs[0] if k != "poly_ids"}
        poly_ids = [pid for r in recs for pid in r["poly_ids"]]
        del recs
        fields: dict[str, Any] = {"origin_m": np.asarray(origin, np.float64)}
        g: dict[str, np.ndarray] = {}
        for group in ("obj", "poly", "tri"):
            order = np.argsort(cat[group], kind="stable")
            g[group] = cat[group][order]
            for f in _SPILL[group]:
                fields[f] = cat[f][order]
            if group == "poly":
                poly_ids = [poly_ids[i] for i in order.tolist()]
        g["vert"], first = np.unique(cat["vert"], return_index=True)
        fields["vertices"] = (cat["world"][first] - origin).astype(np.float32)
        fields["uv"] = cat["uv"][first]
        del cat
        parent = fields["obj_parent"].astype(np.int64)
        fields["obj_parent"] = np.where(parent >= 0, np.searchsorted(
            g["obj"], np.maximum(parent, 0)), -1).astype(np.int32)
        fields["poly_object"] = np.searchsorted(g["obj"], fields["poly_object"]
                                                ).astype(np.int32)
        fields["tri_object"] = np.searchsorted(g["obj"], fields["tri_object"]
                                               ).astype(np.int32)
        fields["tri_polygon"] = np.searchsorted(g["poly"], fields["tri_polygon"]
                                                ).astype(np.int32)
        fields["triangles"] = np.searchsorted(g["vert"], fields["triangles"]
                                              ).astype(np.int32)
        part = Scene(crs=self.crs, obj_ids=[self.obj_ids[i] for i in g["obj"].tolist()],
                     obj_types=[self.obj_types[i] for i in g["obj"].tolist()],
                     poly_ids=poly_ids, materials=self.materials, textures=self.textures,
                     report={}, **fields)
        return part, g


def build_tiled_from_files(sources: list[Path], folder: str | os.PathLike, tile_m: float,
                           settings, source: dict[str, Any], build_options: dict[str, Any],
                           progress: Callable[[str, int, int], None] | None = None
                           ) -> tuple[TiledBuild, int]:
    """Build the tiled cache of several city model files without assembling the city: memory
    holds one file's read model and scene plus one tile (module comment above); the result
    is :func:`save_tiled` of the assembled city bit for bit. Returns the build's summary and
    the bytes written.

    Raises
    ------
    UsageError, OutputError
        As :func:`save_tiled`.
    CRSError, EmptyModelError
        As :func:`cityshade.build.build_scene_from_files`.
    """
    import time

    from cityshade.build import read_files
    from cityshade.errors import EmptyModelError
    from cityshade.geometry.scene import render_origin
    from cityshade.runtime.memory import release_freed_memory

    folder = Path(folder)
    tmp = _start(folder, tile_m)
    try:
        spill_dir = tmp / "spill"
        spill_dir.mkdir()
        merger, timings = read_files(sources, settings, progress,
                                     lambda crs_given: TileSpill(spill_dir, tile_m, crs_given))
        if merger.n_vert == 0:
            raise EmptyModelError("the files hold no surface geometry")
        t = time.perf_counter()
        origin = render_origin(merger.world_lo, merger.world_hi).astype(np.float64)
        keys = merger.final_keys(origin)
        merger.move(keys)
        timings["spill_s"] = time.perf_counter() - t
        cells = np.unique(keys, axis=0).tolist()
        tiles, lowest, total = [], [], 0
        t = time.perf_counter()
        for i, key in enumerate(cells):
            if progress:
                progress(f"tile {i + 1}/{len(cells)}", i, len(cells))
            part, globals_ = merger.tile(tuple(key), keys, origin)
            # Each object lies in one tile: its lowest point for the ground's "auto" median.
            tri_z = np.asarray(part.vertices, np.float64)[part.triangles][:, :, 2].min(axis=1)
            low = np.full(len(part.obj_ids), np.inf)
            np.minimum.at(low, np.asarray(part.tri_object), tri_z)
            lowest.append(low[np.isfinite(low)])
            tiles.append(_write_tile(part, globals_, tmp, key, tile_m, settings, source,
                                     build_options))
            total += tiles[-1]["size"]
            del part, globals_
            release_freed_memory()
        timings["tiles_s"] = time.perf_counter() - t
        shutil.rmtree(spill_dir)
        fields = {f: np.concatenate(v) for f, v in merger.obj_time.items()}
        report = merger.report_for(fields)
        report["timings"] = {k: round(v, 4) for k, v in timings.items()}
        box = [(np.asarray(b) - origin).astype(np.float32).astype(np.float64).tolist()
               for b in (merger.world_lo, merger.world_hi)]
        days = ([None, None] if merger.n_tri == 0 else
                [d if math.isfinite(d) else None for d in merger.tri_days])
        whole = {"ground_m": {"min": box[0][2], "auto": float(np.median(np.concatenate(lowest)))},
                 "origin_m": origin.tolist(), "crs": merger.crs.to_json(), "box_m": box,
                 "counts": {"objects": merger.n_obj, "polygons": merger.n_poly,
                            "triangles": merger.n_tri, "vertices": merger.n_vert},
                 "time_days": days, "report": report, "materials": merger.materials,
                 "textures": merger.textures, "object_types": sorted(set(merger.obj_types)),
                 "surface_classes": merger.classes.tolist()}
        total += _finish(tmp, folder, _index(whole, tile_m, source, build_options, tiles), tiles)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return TiledBuild(merger.n_tri, merger.obj_ids, report), total


