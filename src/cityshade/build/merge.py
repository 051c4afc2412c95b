"""Many tiles → one scene: the objects of all files in one render space, duplicates kept once.

Each file is read and assembled on its own (:func:`cityshade.geometry.scene.build_scene` with
``render_space=False``: float64 model-CRS vertices), so memory holds one file's read model plus
the scene parts gathered so far. :class:`SceneMerger` drops the objects whose ``gml:id`` an
earlier file already had (tiles repeat the buildings on their borders), with their polygons,
triangles and vertices, and :meth:`SceneMerger.finish` chooses the origin of the whole city and
casts to float32 once — so a city split into tiles builds the same scene as the one file,
bit for bit.
"""
from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import numpy as np

from cityshade.geo.temporal import days_to_iso
from cityshade.errors import CRSError, EmptyModelError
from cityshade.geometry.scene import TIME_SOURCE_NAMES, Scene, render_origin

#: Per-object, per-polygon and per-triangle array fields of a scene (the rest are tables).
_OBJ_FIELDS = ("obj_parent", "obj_t_begin_days", "obj_t_end_days", "obj_time_source", "obj_lod")
_POLY_FIELDS = ("poly_object", "poly_class", "poly_area_m2", "poly_normal", "poly_repairs")
_TRI_FIELDS = ("triangles", "tri_object", "tri_polygon", "tri_class", "tri_material",
               "tri_texture", "tri_t_begin_days", "tri_t_end_days")
#: Report counters that add up over files.
_SUMMED = ("skipped", "left_out", "repairs", "lods", "lods_drawn", "counters")


def _crs_key(crs) -> tuple:
    return (crs.horizontal_epsg, crs.is_geographic, crs.local, crs.horizontal_epsg is None
            and crs.name)


class SceneMerger:
    """Gathers per-file scenes (float64 model coordinates) into one :class:`Scene`.

    Parameters
    ----------
    crs_given : bool
        True when the user named the target CRS (``--crs``): every part is already in it.
    """

    def __init__(self, crs_given: bool = False):
        self.crs_given = crs_given
        self.parts: list[dict] = []
        self.obj_index: dict[str, int] = {}  # gml:id → merged object index
        self.n_obj = self.n_poly = self.n_vert = self.n_tri = 0
        self.duplicates: Counter = Counter()  # file → objects dropped as already read
        self.files: list[dict] = []
        self.crs = None
        self.crs_file = None
        self.materials: list[dict] = []
        self.material_index: dict[str, int] = {}
        self.textures: list[dict] = []
        self.texture_index: dict[str, int] = {}
        self.reports: list[tuple[str, dict]] = []
        #: [merged object, codes] of the vegetation objects kept (report "vegetation_codes").
        self.vegetation_codes: list = []
        self.obj_ids: list[str] = []
        self.obj_types: list[str] = []
        self.poly_ids: list[str] = []

    def add(self, scene: Scene, path: str | Path) -> None:
        """Add one file's scene (built with ``render_space=False``); objects whose gml:id is
        already in the city are dropped and counted.

        Raises
        ------
        CRSError
            The file's CRS differs from the first file's and no ``--crs`` names the target.
        """
        name = str(path)
        if self.crs is None:
            self.crs, self.crs_file = scene.crs, name
        elif _crs_key(scene.crs) != _crs_key(self.crs):
            raise CRSError(f"the tiles are in different CRSs: {self.crs.name} in "
                           f"{self.crs_file}, {scene.crs.name} in {name}; give --crs EPSG:nnnn "
                           f"to project every tile to one")
        # Objects: keep the first of every gml:id (objects without one are always kept).
        n = len(scene.obj_ids)
        keep = np.ones(n, bool)
        remap = np.empty(n, np.int64)  # part object → merged object
        next_index = self.n_obj
        for i, oid in enumerate(scene.obj_ids):
            if oid and oid in self.obj_index:
                keep[i] = False
                remap[i] = self.obj_index[oid]
                continue
            if oid:
                self.obj_index[oid] = next_index
            remap[i] = next_index
            next_index += 1
        dropped = int(n - keep.sum())
        if dropped:
            self.duplicates[name] = dropped
        kept_obj = np.nonzero(keep)[0]
        obj = {f: np.asarray(getattr(scene, f))[kept_obj] for f in _OBJ_FIELDS}
        parent = obj["obj_parent"].astype(np.int64)
        obj["obj_parent"] = np.where(parent >= 0, remap[np.maximum(parent, 0)], -1).astype(np.int32)
        obj_ids = [scene.obj_ids[i] for i in kept_obj]
        obj_types = [scene.obj_types[i] for i in kept_obj]
        # Polygons and triangles of the kept objects.
        kept_poly = np.nonzero(keep[np.asarray(scene.poly_object)])[0]
        poly_remap = np.full(len(scene.poly_ids), -1, np.int64)
        poly_remap[kept_poly] = self.n_poly + np.arange(len(kept_poly))
        poly = {f: np.asarray(getattr(scene, f))[kept_poly] for f in _POLY_FIELDS}
        poly["poly_object"] = remap[poly["poly_object"]].astype(np.int32)
        poly_ids = [scene.poly_ids[i] for i in kept_poly]
        kept_tri = np.nonzero(keep[np.asarray(scene.tri_object)])[0]
        tri = {f: np.asarray(getattr(scene, f))[kept_tri] for f in _TRI_FIELDS}
        tri["tri_object"] = remap[tri["tri_object"]].astype(np.int32)
        tri["tri_polygon"] = poly_remap[tri["tri_polygon"]].astype(np.int32)
        tri["tri_material"] = self._tables(tri["tri_material"], scene.materials,
                                           self.materials, self.material_index,
                                           lambda m: json.dumps(m, sort_keys=True))
        tri["tri_texture"] = self._tables(tri["tri_texture"], scene.textures, self.textures,
                                          self.texture_index, lambda t: t["path"])
        # Vertices used by the kept triangles, in their order (as the one-file build keeps them).
        used = np.zeros(len(scene.vertices), bool)
        used[tri["triangles"].ravel()] = True
        new_index = np.cumsum(used) - 1 + self.n_vert
        tri["triangles"] = new_index[tri["triangles"]].astype(np.int32)
        world = np.asarray(scene.vertices, np.float64)[used]
        uv = np.asarray(scene.uv)[used]
        self.keep({"obj": obj, "poly": poly, "tri": tri, "world": world, "uv": uv,
                   "obj_ids": obj_ids, "obj_types": obj_types, "poly_ids": poly_ids})
        self.n_obj, self.n_poly, self.n_vert = (next_index, self.n_poly + len(kept_poly),
                                                self.n_vert + len(world))
        self.n_tri += int(len(kept_tri))
        self.vegetation_codes += [[int(remap[i]), codes] for i, codes in
                                  (scene.report or {}).get("vegetation_codes", []) if keep[i]]
        self.reports.append((name, scene.report))
        self.files.append({"path": name, "objects": n, "duplicates": dropped,
                           "triangles": int(len(kept_tri))})

    def keep(self, part: dict) -> None:
        """Keep one file's new objects (arrays in the merged numbering; called by :meth:`add`
        before the counts move on). Here they are gathered for :meth:`finish`; a tiled build
        spills them to disk instead (:class:`cityshade.build.tiled.TileSpill`)."""
        self.obj_ids += part.pop("obj_ids")
        self.obj_types += part.pop("obj_types")
        self.poly_ids += part.pop("poly_ids")
        self.parts.append(part)

    @staticmethod
    def _tables(codes: np.ndarray, records: list[dict], out: list[dict], index: dict,
                key) -> np.ndarray:
        """Renumber per-triangle material/texture codes into the merged table (equal records
        are shared: tiles repeat the same facade material)."""
        local = np.full(len(records) + 1, -1, np.int32)
        for i in np.unique(codes[codes >= 0]):  # only the records kept triangles use
            rec = records[int(i)]
            k = key(rec)
            if k not in index:
                index[k] = len(out)
                out.append(rec)
            local[i] = index[k]
        return local[np.where(codes >= 0, codes, len(records))]

    def finish(self) -> Scene:
        """The merged scene in render space (float32 around the whole city's rounded centre).

        Raises
        ------
        EmptyModelError
            Every object was a duplicate (cannot happen for the first file).
        """
        if not self.parts or self.n_vert == 0:
            raise EmptyModelError("the files hold no surface geometry")
        world = np.concatenate([p.pop("world") for p in self.parts])
        origin = render_origin(world.min(axis=0), world.max(axis=0))
        vertices = (world - origin).astype(np.float32)
        del world
        fields = {"vertices": vertices,
                  "uv": np.concatenate([p.pop("uv") for p in self.parts])}
        for group, names in (("obj", _OBJ_FIELDS), ("poly", _POLY_FIELDS), ("tri", _TRI_FIELDS)):
            for f in names:
                fields[f] = np.concatenate([p[group].pop(f) for p in self.parts])
        self.parts.clear()
        fields["poly_normal"] = fields["poly_normal"].reshape(-1, 3)
        fields["triangles"] = fields["triangles"].reshape(-1, 3)
        return Scene(origin_m=origin.astype(np.float64), crs=self.crs, obj_ids=self.obj_ids,
                     obj_types=self.obj_types, poly_ids=self.poly_ids,
                     materials=self.materials, textures=self.textures,
                     report=self.report_for(fields), **fields)

    def report_for(self, fields: dict) -> dict:
        """One build report for all files: counts summed, warnings named by file."""
        first = self.reports[0][1]
        rep = {k: v for k, v in first.items()}
        for key in _SUMMED:
            total: Counter = Counter()
            for _, r in self.reports:
                total.update(r.get(key) or {})
            rep[key] = dict(sorted(total.items()))
        skipped_ids: dict[str, list[str]] = {}
        for _, r in self.reports:
            for reason, ids in r.get("skipped_ids", {}).items():
                skipped_ids.setdefault(reason, []).extend(ids)
        rep["skipped_ids"] = dict(sorted(skipped_ids.items()))
        rep["versions"] = sorted({v for _, r in self.reports for v in r.get("versions", [])})
        formats = sorted({r.get("format") for _, r in self.reports})
        rep["format"] = ", ".join(formats)
        rep["objects_by_type"] = dict(sorted(Counter(self.obj_types).items()))
        polys = Counter()
        for _, r in self.reports:
            polys.update(r["polygons"])
        polys["drawn"] = self.n_poly
        rep["polygons"] = dict(polys)
        begin, end = fields["obj_t_begin_days"], fields["obj_t_end_days"]
        finite = np.concatenate([begin[np.isfinite(begin)], end[np.isfinite(end)]])
        rep["time_range"] = ([days_to_iso(float(finite.min())), days_to_iso(float(finite.max()))]
                             if finite.size else None)
        rep["creation_dates_unused"] = sum(r.get("creation_dates_unused", 0)
                                           for _, r in self.reports)
        rep["themes"] = sorted({t for _, r in self.reports for t in r.get("themes", [])})
        # The same warning from many tiles is said once, naming the files.
        by_text: dict[str, list[str]] = {}
        for name, r in self.reports:
            for w in r.get("warnings", []):
                by_text.setdefault(w, []).append(Path(name).name)
        rep["warnings"] = [f"{names[0]}: {w}" if len(names) == 1 else
                           f"{len(names)} files ({', '.join(names[:3])}"
                           f"{', …' if len(names) > 3 else ''}): {w}"
                           for w, names in by_text.items()]
        rep["time_sources_used"] = dict(sorted(Counter(
            TIME_SOURCE_NAMES[int(c)] for c in fields["obj_time_source"]).items()))
        rep.pop("vegetation_codes", None)
        if self.vegetation_codes:
            rep["vegetation_codes"] = self.vegetation_codes
        rep["tiles"] = {"files": len(self.files),
                        "duplicate_objects": int(sum(self.duplicates.values())),
                        "per_file": self.files}
        return rep
