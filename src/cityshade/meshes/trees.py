"""Trees from a register (``build --trees``): points with a height, a crown diameter and a trunk
height, as most cities publish their trees, become crown-and-trunk meshes standing on the model.

Shape (docs/DESIGN.md §20): the crown is an ellipsoid — trimesh's icosphere (``[trees]
crown_subdivisions``, 2: 320 near-equal triangles, no slivers at the poles as a UV sphere has)
scaled to the crown diameter across and the crown height (tree height − trunk height) up, so
its box is exactly the register's crown; it sits on a cylinder trunk (``trimesh.creation.
cylinder``, ``trunk_sections`` sides) from the ground to the crown's base. A capsule was not
taken: its straight middle makes a crown fuller than the ellipsoid of the same box. Each tree
is a ``SolitaryVegetationObject`` (the reader's type for CityGML trees, so its triangles have
the class ``vegetation``) with two surfaces, ``<id>_crown`` and ``<id>_trunk``.
"""
from __future__ import annotations

import csv
import functools
import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.config import LENGTH_UNITS_M, TreeSettings
from cityshade.errors import CRSError, TreeRegisterError
from cityshade.meshes.scene import MeshObject, ground_heights_m, scene_from_objects

#: The CityGML type a register tree becomes (the reader's type for CityGML trees).
TREE_TYPE = "SolitaryVegetationObject"


@dataclass
class Register:
    """The trees of a register, in its own CRS and metres.

    Attributes
    ----------
    xy : (N, 2) float64
        Easting, northing (or longitude, latitude) of each tree.
    ground_m, height_m, crown_m, trunk_m, trunk_diameter_m : (N,) float64
        Ground height (NaN where none), tree height, crown diameter, trunk height and
        diameter.
    ids : list of str
    begin_days, end_days : (N,) float64
        Planting and felling (±inf where none).
    crs_text : str or None
        The register's CRS as written (GeoJSON ``crs`` member), None when it names none.
    skipped : dict
        Rows left out, by reason.
    """

    xy: np.ndarray
    ground_m: np.ndarray
    height_m: np.ndarray
    crown_m: np.ndarray
    trunk_m: np.ndarray
    trunk_diameter_m: np.ndarray
    ids: list[str]
    begin_days: np.ndarray
    end_days: np.ndarray
    crs_text: str | None
    skipped: dict


def read_register(path: str | Path, settings: TreeSettings | None = None) -> Register:
    """Read a tree register: GeoJSON (a FeatureCollection of Points, told by a first ``{``)
    or CSV (a header row). Rows without a usable height or crown diameter, or whose trunk is
    not below the tree's top, are left out and counted.

    Raises
    ------
    TreeRegisterError
        Unreadable file, a column the settings name that the register lacks, no tree left.
    """
    settings = settings or TreeSettings()
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise TreeRegisterError(f"cannot read the tree register: {exc}", path=str(path)) from None
    if text.lstrip().startswith("{"):
        rows, xy, crs_text = _geojson_rows(text, path, settings)
    else:
        rows, xy, crs_text = _csv_rows(text, path, settings)
    return _register_from_rows(rows, xy, crs_text, path, settings)


def _geojson_rows(text: str, path: Path, settings: TreeSettings):
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise TreeRegisterError(f"not valid JSON: {exc.msg} (line {exc.lineno})",
                                path=str(path)) from None
    features = doc.get("features") if isinstance(doc, dict) else None
    if not isinstance(features, list):
        raise TreeRegisterError("a GeoJSON tree register must be a FeatureCollection",
                                path=str(path))
    crs = doc.get("crs")
    crs_text = None
    if isinstance(crs, dict) and isinstance(crs.get("properties"), dict):
        crs_text = crs["properties"].get("name")
    rows, xy = [], []
    for feature in features:
        geom = (feature or {}).get("geometry") or {}
        props = (feature or {}).get("properties") or {}
        coords = geom.get("coordinates") if geom.get("type") == "Point" else None
        if coords is not None and len(coords) >= 2:
            xy.append((float(coords[0]), float(coords[1])))
        else:
            xy.append((_number(props.get(settings.x)), _number(props.get(settings.y))))
        rows.append(props)
    return rows, np.array(xy, np.float64).reshape(-1, 2), crs_text


def _csv_rows(text: str, path: Path, settings: TreeSettings):
    sample = text[:4096]
    try:
        dialect = csv.Sniffer().sniff(sample, delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel
    reader = csv.DictReader(text.splitlines(), dialect=dialect)
    rows = list(reader)
    header = reader.fieldnames or []
    for name in (settings.x, settings.y):
        if name not in header:
            raise TreeRegisterError(f"the register has no column {name!r} (columns: "
                                    f"{', '.join(header)}); name it in [trees] of --config",
                                    path=str(path))
    xy = np.array([(_number(r.get(settings.x)), _number(r.get(settings.y))) for r in rows],
                  np.float64).reshape(-1, 2)
    return rows, xy, None


def _number(value) -> float:
    """A register value as a float (NaN when empty or not a number)."""
    if value is None or isinstance(value, bool):
        return math.nan
    try:
        return float(str(value).strip().replace(",", ".") if isinstance(value, str) else value)
    except ValueError:
        return math.nan


def _date_days(value) -> float:
    """Days of a planting/felling year or date (NaN when empty or unreadable)."""
    from cityshade.geo.temporal import parse_time_attribute_value

    if value is None or not str(value).strip():
        return math.nan
    try:
        return parse_time_attribute_value(str(value))
    except ValueError:
        return math.nan


def _register_from_rows(rows, xy, crs_text, path: Path, settings: TreeSettings) -> Register:
    names = {"height": settings.height, "crown_diameter": settings.crown_diameter,
             "trunk_height": settings.trunk_height, "trunk_diameter": settings.trunk_diameter,
             "z": settings.z if settings.ground == "register" else "", "id": settings.id,
             "planted": settings.planted, "felled": settings.felled}
    present = set().union(*(r.keys() for r in rows)) if rows else set()
    for key, name in names.items():
        if name and key not in ("id",) and name not in present:
            raise TreeRegisterError(f"the register has no column {name!r} ([trees] {key}); "
                                    f"name it in [trees] of --config", path=str(path))
    unit = LENGTH_UNITS_M[settings.units]

    def column(key, default=math.nan):
        name = names[key]
        if not name:
            return np.full(len(rows), default)
        return np.array([_number(r.get(name)) for r in rows], np.float64)

    height, crown = column("height") * unit, column("crown_diameter") * unit
    trunk = column("trunk_height", 0.0) * unit
    trunk_d = column("trunk_diameter", settings.trunk_diameter_m / unit) * unit
    ground = column("z") * unit
    begin = np.array([_date_days(r.get(settings.planted)) if settings.planted else math.nan
                      for r in rows])
    end = np.array([_date_days(r.get(settings.felled)) if settings.felled else math.nan
                    for r in rows])
    reasons = {
        "no_position": ~np.isfinite(xy).all(axis=1),
        "no_height_or_crown": ~((height > 0) & (crown > 0)),
        "trunk_not_below_top": ~((trunk >= 0) & (trunk < height) & (trunk_d > 0)),
        "no_ground_height": ~np.isfinite(ground) if settings.ground == "register"
        else np.zeros(len(rows), bool),
    }
    bad = np.zeros(len(rows), bool)
    skipped = {}
    for reason, mask in reasons.items():
        mask = mask & ~bad
        if mask.any():
            skipped[reason] = int(mask.sum())
        bad |= mask
    keep = np.flatnonzero(~bad)
    if not len(keep):
        raise TreeRegisterError(f"no usable tree among {len(rows)} rows "
                                f"({', '.join(f'{k}: {v}' for k, v in skipped.items()) or 'empty'})",
                                path=str(path))
    ids = []
    for i in keep:
        value = rows[i].get(settings.id) if settings.id else None
        ids.append(str(value) if value not in (None, "") else f"tree_{i + 1}")
    return Register(xy=xy[keep], ground_m=ground[keep], height_m=height[keep],
                    crown_m=crown[keep], trunk_m=trunk[keep], trunk_diameter_m=trunk_d[keep],
                    ids=ids, begin_days=np.where(np.isfinite(begin), begin, -math.inf)[keep],
                    end_days=np.where(np.isfinite(end), end, math.inf)[keep],
                    crs_text=crs_text, skipped=skipped)


@functools.lru_cache(maxsize=8)
def unit_shapes(crown_subdivisions: int, trunk_sections: int):
    """The unit crown (icosphere of radius 1 around 0) and unit trunk (cylinder of radius 1
    from z = 0 to 1): ((vertices, faces), (vertices, faces)), read-only."""
    import trimesh

    crown = trimesh.creation.icosphere(subdivisions=crown_subdivisions)
    trunk = trimesh.creation.cylinder(radius=1.0, height=1.0, sections=trunk_sections)
    out = []
    for mesh, lift in ((crown, 0.0), (trunk, 0.5)):
        v = np.array(mesh.vertices, np.float64) + [0.0, 0.0, lift]
        f = np.array(mesh.faces, np.int64)
        v.flags.writeable = f.flags.writeable = False
        out.append((v, f))
    return tuple(out)


def tree_mesh(base_m, height_m: float, crown_m: float, trunk_m: float, trunk_diameter_m: float,
              settings: TreeSettings | None = None):
    """One tree standing at ``base_m`` (x, y, ground z): (vertices (V, 3) float64, faces
    (T, 3), face part (T,): 0 crown, 1 trunk). The crown's box is ``crown_m`` across and
    ``height_m - trunk_m`` high, its base at ``trunk_m``; no trunk when ``trunk_m`` is 0."""
    settings = settings or TreeSettings()
    (cv, cf), (tv, tf) = unit_shapes(settings.crown_subdivisions, settings.trunk_sections)
    base = np.asarray(base_m, np.float64)
    crown_h = height_m - trunk_m
    crown = cv * [crown_m / 2, crown_m / 2, crown_h / 2] + base + [0.0, 0.0, trunk_m + crown_h / 2]
    if trunk_m <= 0.0:
        return crown, cf, np.zeros(len(cf), np.int64)
    radius = min(trunk_diameter_m, crown_m) / 2
    trunk = tv * [radius, radius, trunk_m] + base
    faces = np.concatenate([cf, tf + len(cv)])
    part = np.concatenate([np.zeros(len(cf), np.int64), np.ones(len(tf), np.int64)])
    return np.concatenate([crown, trunk]), faces, part


def register_crs(register: Register, model_crs, crs_text: str | None):
    """The CRS of the register's points: ``crs_text`` (``--trees-crs``), else its GeoJSON
    ``crs`` member, else the model's; (CrsInfo, whether the points are longitude first)."""
    from cityshade.geo.crs import parse_srs_name

    text = crs_text or register.crs_text
    if not text:
        return model_crs, False
    crs = parse_srs_name(text)
    return crs, crs.is_geographic  # GeoJSON and CSV registers write longitude first


def add_trees(scene, path: str | Path, settings: TreeSettings | None = None,
              crs_text: str | None = None):
    """The scene with the trees of the register at ``path`` added (after its objects, without
    a kd-tree): reprojected to the scene's CRS, each standing on the ground under it
    (:func:`~cityshade.meshes.scene.ground_heights_m`, or the register's ground column with
    ``ground = "register"``). ``scene.report["trees"]`` says what was read and done.

    Raises
    ------
    TreeRegisterError
        As :func:`read_register`; a tree id the model already has.
    CRSError
        The register's CRS cannot be projected to the model's.
    """
    from cityshade.geo.crs import reproject_horizontal
    from cityshade.geometry.scene import append_scene

    settings = settings or TreeSettings()
    register = read_register(path, settings)
    crs, lonlat = register_crs(register, scene.crs, crs_text)
    xy = register.xy
    if crs is not scene.crs and crs.horizontal_epsg != scene.crs.horizontal_epsg:
        if scene.crs.local or scene.crs.horizontal_epsg is None:
            raise CRSError(f"the register is in {crs.name} but the model has no CRS; build "
                           f"with --crs EPSG:nnnn")
        xyz = np.column_stack([xy, np.zeros(len(xy))])
        xy = reproject_horizontal(xyz, crs, scene.crs, lonlat_source=lonlat)[:, :2]
    if settings.ground == "register":
        ground, ground_from = register.ground_m, "register"
    else:
        ground, ground_from = ground_heights_m(scene, xy)
    taken = set(scene.obj_ids)
    clash = next((i for i in register.ids if i in taken), None)
    if clash is not None:
        raise TreeRegisterError(f"tree id {clash!r} is already an object of the model",
                                path=str(path))
    objects = []
    for i, tid in enumerate(register.ids):
        v, f, part = tree_mesh((xy[i, 0], xy[i, 1], ground[i]), register.height_m[i],
                               register.crown_m[i], register.trunk_m[i],
                               register.trunk_diameter_m[i], settings)
        has_trunk = bool(part.max())
        objects.append(MeshObject(
            tid, TREE_TYPE, v, f, part,
            [f"{tid}_crown", f"{tid}_trunk"][:1 + has_trunk],
            np.full(1 + has_trunk, SURFACE_CODE["vegetation"], np.uint8),
            float(register.begin_days[i]), float(register.end_days[i])))
    trees = scene_from_objects(objects, scene.crs, origin_m=scene.origin_m)
    out = append_scene(scene, trees)
    # The trees' surfaces were read (from the register) and are drawn: the counts stay whole.
    polygons = dict(out.report.get("polygons", {}))
    for key in ("read", "drawn"):
        polygons[key] = polygons.get(key, 0) + len(trees.poly_ids)
    out.report["polygons"] = polygons
    by_type = dict(out.report.get("objects_by_type", {}))
    by_type[TREE_TYPE] = by_type.get(TREE_TYPE, 0) + len(objects)
    out.report["objects_by_type"] = by_type
    out.report["trees"] = {"file": str(Path(path).resolve()), "trees": len(objects),
                           "skipped": register.skipped, "crs": crs.name,
                           "ground": ground_from, "triangles": trees.n_triangles}
    return out
