"""The answers as GIS layers: a GeoPackage in the model's CRS (pyogrio, which ships GDAL) and
GeoJSON in EPSG:4326 (RFC 7946, coordinates projected with pyproj) for the web.

Geometry (shapely):

- a **surface** is its polygon's outline: the polygon's triangles (the scene keeps triangles,
  not rings) laid into the polygon's plane, merged (``shapely.union_all``) and lifted back to
  3-D, so a polygon with holes gets its holes back; a MultiPolygon Z in model coordinates
  (a non-planar polygon is flattened onto the plane of its area-weighted normal);
- an **opening** (window, door) is the merge of its polygons, the same way;
- a **building** is its 2-D footprint: the union of the ground-surface polygons of the
  building and its parts seen from above (``footprint_source = "ground"``), else of its
  downward-facing polygons (LoD1 solids without classes: ``"downward"``), else the convex
  hull of all its points (``"convex_hull"``).

Values are handed in as columns (the same numbers that ``surfaces.csv`` and ``openings.csv``
print), so a layer and its table never disagree.
"""
from __future__ import annotations

import contextlib
import math
import sqlite3
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from cityshade.errors import OutputError

__all__ = ["Layer", "polygon_outlines", "building_footprints",
           "surface_layer", "building_layer", "write_gis", "finite_or_none",
           "rows_to_columns", "GEOPACKAGE_NAME", "STYLE_BY_FIELD", "layer_style",
           "write_layer_styles"]

#: The GeoPackage beside ``surfaces.csv``.
GEOPACKAGE_NAME = "results.gpkg"
#: Normal z below this makes a polygon face down (an LoD1 solid's bottom): its footprint.
DOWNWARD_NZ = -0.9
#: Triangles are merged on a grid of this size (metres): 0.1 mm closes the float rounding
#: between neighbours and is far below any surveyed coordinate's precision.
MERGE_GRID_M = 1e-4


@dataclass
class Layer:
    """One layer: a geometry (shapely, or None) per feature and columns of equal length.

    ``columns`` maps a field name to a sequence of str, int or float (NaN is written as
    NULL)."""

    name: str
    geometries: list
    columns: dict[str, Sequence] = field(default_factory=dict)
    geometry_type: str = "MultiPolygon Z"


def _triangles_by_polygon(scene) -> tuple[np.ndarray, np.ndarray]:
    """(order, starts): triangle indices sorted by polygon and where each polygon's start."""
    tri_polygon = np.asarray(scene.tri_polygon)
    order = np.argsort(tri_polygon, kind="stable")
    starts = np.searchsorted(tri_polygon[order], np.arange(len(scene.poly_ids) + 1))
    return order, starts


def _plane_basis(normal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors spanning the plane of ``normal``."""
    n = normal / (np.linalg.norm(normal) or 1.0)
    helper = np.array([0.0, 0.0, 1.0]) if abs(n[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(helper, n)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _merge_in_plane(points_m: np.ndarray, triangles: np.ndarray, normal: np.ndarray):
    """MultiPolygon Z (shapely) of triangles (k, 3) of ``points_m`` (n, 3) merged in their
    plane, or None when they have no area."""
    import shapely

    if not len(triangles):
        return None
    if not np.isfinite(normal).all() or np.linalg.norm(normal) == 0.0:
        c = points_m[triangles]
        normal = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]).sum(axis=0)
        if np.linalg.norm(normal) == 0.0:
            return None
    u, v = _plane_basis(np.asarray(normal, np.float64))
    p0 = points_m[triangles[0, 0]]
    rel = points_m - p0
    # Each point projected once, so the triangles that share it meet exactly.
    flat = np.column_stack([rel[:, 0] * u[0] + rel[:, 1] * u[1] + rel[:, 2] * u[2],
                            rel[:, 0] * v[0] + rel[:, 1] * v[1] + rel[:, 2] * v[2]])
    tris = shapely.polygons(flat[triangles])
    merged = shapely.union_all(tris[shapely.area(tris) > 0.0], grid_size=MERGE_GRID_M)
    parts = [g for g in getattr(merged, "geoms", [merged])
             if isinstance(g, shapely.Polygon) and not g.is_empty and g.area > 0.0]
    if not parts:
        return None

    def lift(ring) -> np.ndarray:
        c = np.asarray(ring.coords)
        return p0 + c[:, :1] * u + c[:, 1:2] * v

    return shapely.MultiPolygon([shapely.Polygon(lift(g.exterior),
                                                 [lift(r) for r in g.interiors])
                                 for g in parts])


def polygon_outlines(scene, groups: Sequence[Sequence[int]]) -> list:
    """One MultiPolygon Z (model CRS metres) per group of polygon indices: their triangles
    merged in the plane of the group's area-weighted normal (None for a group without area)."""
    order, starts = _triangles_by_polygon(scene)
    vertices = np.asarray(scene.vertices)
    origin = np.asarray(scene.origin_m, np.float64)
    triangles = np.asarray(scene.triangles)
    normals = np.asarray(scene.poly_normal, np.float64)
    areas = np.asarray(scene.poly_area_m2, np.float64)
    out = []
    for group in groups:
        group = [int(p) for p in group]
        if not group:
            out.append(None)
            continue
        tris = triangles[np.concatenate([order[starts[p]:starts[p + 1]] for p in group])]
        used, local = np.unique(tris, return_inverse=True)
        points = vertices[used].astype(np.float64) + origin
        normal = (normals[group] * areas[group, None]).sum(axis=0)
        out.append(_merge_in_plane(points, local.reshape(-1, 3), normal))
    return out


def _as_multipolygon(geom):
    """A MultiPolygon of the polygons in ``geom`` (lines and points of a collection dropped),
    or None when there are none."""
    import shapely

    if geom is None:
        return None
    parts = [g for g in getattr(geom, "geoms", [geom]) if g.geom_type == "Polygon"
             and not g.is_empty]
    return shapely.MultiPolygon(parts) if parts else None


def building_footprints(scene, buildings: Sequence[int]) -> tuple[list, list[str]]:
    """(2-D MultiPolygon or None, footprint source) per top-level object (see the module
    docstring)."""
    import shapely

    from cityshade.citygml.namespaces import SURFACE_CODE
    from cityshade.geometry.scene import root_objects

    root_of_poly = root_objects(scene.obj_parent)[np.asarray(scene.poly_object, np.int64)]
    poly_class = np.asarray(scene.poly_class)
    normal_z = np.asarray(scene.poly_normal, np.float64)[:, 2]
    order, starts = _triangles_by_polygon(scene)
    xy = (np.asarray(scene.vertices, np.float64) + np.asarray(scene.origin_m))[:, :2]
    triangles = np.asarray(scene.triangles)
    by_root: dict[int, list[int]] = {}
    for p, r in enumerate(root_of_poly):
        by_root.setdefault(int(r), []).append(p)
    geoms, sources = [], []
    for b in buildings:
        polys = np.asarray(by_root.get(int(b), []), np.int64)
        geom, source = None, "none"
        for name, pick in (("ground", poly_class[polys] == SURFACE_CODE["ground"]),
                           ("downward", normal_z[polys] < DOWNWARD_NZ)):
            chosen = polys[pick]
            if len(chosen):
                tris = np.concatenate([order[starts[p]:starts[p + 1]] for p in chosen])
                flat = shapely.polygons(xy[triangles[tris]])
                merged = shapely.union_all(flat[shapely.area(flat) > 0.0],
                                           grid_size=MERGE_GRID_M)
                if not merged.is_empty:
                    geom, source = merged, name
                    break
        if geom is None and len(polys):
            tris = np.concatenate([order[starts[p]:starts[p + 1]] for p in polys])
            if len(tris):
                hull = shapely.convex_hull(shapely.multipoints(xy[triangles[tris]].reshape(-1, 2)))
                if hull.area > 0.0:
                    geom, source = hull, "convex_hull"
        geoms.append(_as_multipolygon(geom))
        sources.append(source)
    return geoms, sources


def _field_arrays(layer: Layer) -> tuple[list[str], list[np.ndarray]]:
    names, arrays = [], []
    n = len(layer.geometries)
    for name, values in layer.columns.items():
        values = list(values)
        if len(values) != n:
            raise OutputError(f"layer {layer.name}: column {name} has {len(values)} values for "
                              f"{n} features")
        if all(isinstance(v, (int, np.integer)) and not isinstance(v, bool) for v in values) \
                and values:
            arr = np.asarray(values, np.int64)
        elif all(isinstance(v, (int, float, np.integer, np.floating)) or v is None
                 for v in values) and values:
            arr = np.asarray([np.nan if v is None else float(v) for v in values], np.float64)
        else:
            arr = np.asarray(["" if v is None else str(v) for v in values], dtype=object)
        names.append(name)
        arrays.append(arr)
    return names, arrays


def _write_layer(path: Path, layer: Layer, crs: str, driver: str, geometries: list,
                 **options) -> None:
    import shapely
    from pyogrio.raw import write

    names, arrays = _field_arrays(layer)
    wkb = np.array([None if g is None else shapely.to_wkb(g, output_dimension=3)
                    for g in geometries], dtype=object)
    write(str(path), wkb, arrays, names, layer=layer.name, driver=driver,
          geometry_type=layer.geometry_type, crs=crs, **options)


def _to_wgs84(geometries: list, epsg: int) -> list:
    """The geometries projected to longitude, latitude (degrees) with pyproj, z kept."""
    import shapely
    from pyproj import Transformer

    t = Transformer.from_crs(epsg, 4326, always_xy=True)

    def project(xyz: np.ndarray) -> np.ndarray:
        lon, lat = t.transform(xyz[:, 0], xyz[:, 1])
        return np.column_stack([lon, lat, xyz[:, 2]]) if xyz.shape[1] == 3 else \
            np.column_stack([lon, lat])

    return [None if g is None else shapely.transform(g, project, include_z=shapely.has_z(g))
            for g in geometries]


def write_gis(outdir, layers: Sequence[Layer], crs, *,
              geojson: bool = True) -> list[Path]:
    """Write ``results.gpkg`` (every layer, the model's CRS) and, for a CRS with an EPSG code,
    ``results_<layer>.geojson`` (EPSG:4326, RFC 7946) into ``outdir``; each renamed into
    place when complete (inside an :func:`cityshade.util.output_group`: with the group).

    Parameters
    ----------
    outdir : path-like
    layers : sequence of Layer
    crs : cityshade.geo.crs.CrsInfo
        The model's CRS: its horizontal EPSG code is the layers' (a model without one gets
        layers without a CRS and no GeoJSON).
    geojson : bool
        Also write the GeoJSON files.

    Returns
    -------
    list of pathlib.Path

    Raises
    ------
    OutputError
        GDAL cannot write a file, or a layer's columns disagree in length.
    """
    from cityshade.util import atomic_path

    outdir = Path(outdir)
    epsg = getattr(crs, "horizontal_epsg", None)
    crs_text = f"EPSG:{epsg}" if epsg else None
    written: list[Path] = []
    path = outdir / GEOPACKAGE_NAME
    try:
        with atomic_path(path, keep_suffix=True, what="the GeoPackage") as tmp:
            for layer in layers:
                _write_layer(tmp, layer, crs_text, "GPKG", layer.geometries)
            write_layer_styles(tmp, layers)
        written.append(path)
        if geojson and epsg:
            for layer in layers:
                gj = outdir / f"results_{layer.name}.geojson"
                geoms = layer.geometries if epsg == 4326 else _to_wgs84(layer.geometries, epsg)
                with atomic_path(gj, keep_suffix=True, what="the GeoJSON") as tmp:
                    _write_layer(tmp, layer, "EPSG:4326", "GeoJSON", geoms,
                                 layer_options={"RFC7946": "YES", "WRITE_NAME": "NO"})
                written.append(gj)
    except (OSError, RuntimeError, ValueError, sqlite3.Error) as exc:  # pyogrio's: RuntimeError
        raise OutputError(f"cannot write the GIS layers: {exc}", path=str(path)) from None
    return written


#: The shipped QGIS styles (``present/styles/*.qml``) by the field they colour, in the order a
#: layer's fields are looked up: a layer gets the first whose field it has.
STYLE_BY_FIELD = (("max_loss_h", "building_loss.qml"), ("loss_h", "loss.qml"),
                  ("mean_sun_hours", "sun_hours.qml"))


#: Fields of the sky's layers (``cityshade sky``) coloured by classes made on the fly from
#: the template's colour ramp (``sun_hours.qml``: seven classes, blue to red): the sky view
#: factor in fixed fifths-ish steps, the kWh/m² in equal steps up to the layer's round maximum
#: (a month and a year differ tenfold, so no fixed classes suit both).
GRADUATED_FIELDS = ("irradiance_kwh_m2", "svf")
SVF_EDGES = (0.0, 0.2, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0)


def _shipped(style: str) -> str:
    from importlib.resources import files

    return files("cityshade.present").joinpath("styles", style).read_text(encoding="utf-8")


def graduated_qml(field: str, edges: Sequence[float], unit: str = "") -> str:
    """A QGIS style colouring ``field`` in the seven classes ``edges`` (8 increasing bounds,
    the last class open above) with the colour ramp of ``sun_hours.qml``."""
    import re

    if len(edges) != 8 or any(b <= a for a, b in zip(edges[:-1], edges[1:])):
        raise ValueError(f"a graduated style needs 8 increasing bounds, not {list(edges)}")
    text = _shipped("sun_hours.qml")
    fmt = "g" if max(edges) <= 10 else ",.0f"
    ranges = []
    for k in range(7):
        lo, hi = edges[k], edges[k + 1]
        label = (f"{lo:{fmt}}–{hi:{fmt}}{unit}" if k < 6 else f"{lo:{fmt}}{unit} or more")
        upper = hi if k < 6 else 1e9
        ranges.append(f'      <range lower="{lo!r}" upper="{upper!r}" symbol="{k}" '
                      f'label="{label}" render="true"/>')
    text = re.sub(r"<ranges>.*?</ranges>", "<ranges>\n" + "\n".join(ranges) + "\n    </ranges>",
                  text, count=1, flags=re.S)
    return text.replace('attr="mean_sun_hours"', f'attr="{field}"').replace(
        "mean sun-hours (batch: surfaces, buildings); field mean_sun_hours",
        f"{field} (sky: surfaces, buildings), made for this file")


def _graduated_edges(field: str, values) -> tuple[float, ...]:
    if field == "svf":
        return SVF_EDGES
    finite = np.asarray(values, np.float64)
    finite = finite[np.isfinite(finite)]
    top = float(np.ceil(finite.max() / 70.0) * 70.0) if finite.size and finite.max() > 0 else 70.0
    return tuple(top * k / 7.0 for k in range(8))


def layer_style(layer: Layer) -> tuple[str, str] | None:
    """(style file name, its QML text) of the shipped style for ``layer`` (or, for the sky's
    fields, one made for its values: :func:`graduated_qml`), or None."""
    for name, style in STYLE_BY_FIELD:
        if name in layer.columns:
            return style, _shipped(style)
    for name in GRADUATED_FIELDS:
        if name in layer.columns:
            unit = " kWh/m²" if name.endswith("kwh_m2") else ""
            return f"{name}.qml", graduated_qml(name, _graduated_edges(name, layer.columns[name]),
                                                unit)
    return None


def write_layer_styles(gpkg, layers: Sequence[Layer]) -> int:
    """Each layer's shipped style into the GeoPackage's ``layer_styles`` table (QGIS's own
    schema), as its default: QGIS draws the layer with it when the layer is opened. The table
    is not registered in ``gpkg_contents``; GDAL lists it as a table all the same. Returns
    the number of styles written."""
    styles = [(layer.name, style) for layer in layers if (style := layer_style(layer))]
    if not styles:
        return 0
    with contextlib.closing(sqlite3.connect(str(gpkg))) as db, db:
        db.execute("CREATE TABLE IF NOT EXISTS layer_styles (id INTEGER PRIMARY KEY "
                   "AUTOINCREMENT, f_table_catalog TEXT(256), f_table_schema TEXT(256), "
                   "f_table_name TEXT(256), f_geometry_column TEXT(256), styleName TEXT(30), "
                   "styleQML TEXT, styleSLD TEXT, useAsDefault BOOLEAN, description TEXT, "
                   "owner TEXT(30), ui TEXT(30), update_time DATETIME DEFAULT "
                   "CURRENT_TIMESTAMP)")
        for table, (name, qml) in styles:
            db.execute("INSERT INTO layer_styles (f_table_catalog, f_table_schema, "
                       "f_table_name, f_geometry_column, styleName, styleQML, styleSLD, "
                       "useAsDefault, description, owner, ui) VALUES "
                       "('', '', ?, 'geom', ?, ?, '', 1, ?, '', '')",
                       (table, f"cityshade {name[:-4]}", qml, f"cityshade style {name}"))
    return len(styles)


def finite_or_none(values) -> list:
    """Floats with NaN/inf as None (NULL in a layer)."""
    return [None if v is None or not math.isfinite(float(v)) else float(v) for v in values]


def rows_to_columns(rows: Sequence[Sequence[Any]], names: Sequence[str]) -> dict[str, list]:
    """Columns of a table given as rows."""
    return {name: [r[i] for r in rows] for i, name in enumerate(names)}



def surface_layer(scene, polygons: Sequence[int], columns: dict[str, Sequence],
                  name: str = "surfaces") -> Layer:
    """One feature per polygon index in ``polygons``: its outline (:func:`polygon_outlines`)
    and the caller's columns (one value per polygon, in the same order)."""
    return Layer(name, polygon_outlines(scene, [[int(p)] for p in polygons]), dict(columns))


def building_layer(scene, polygons: Sequence[int], means: dict[str, Sequence],
                   maxima: dict[str, Sequence] | None = None) -> Layer:
    """One feature per building (top-level object of type ``Building…``; every top-level
    object when the model has none) with a polygon in ``polygons``: its footprint
    (:func:`building_footprints`, 2-D), the number and area of those polygons, and per column
    of ``means`` the area-weighted mean of its finite values (of ``maxima``: the largest).

    Parameters
    ----------
    polygons : (K,) int
        Polygon indices (the rows of ``surfaces.csv``).
    means, maxima : mapping of name → (K,) float
        Values per polygon, in the order of ``polygons``.
    """
    from cityshade.geometry.scene import root_objects

    polygons = np.asarray(polygons, np.int64)
    root = root_objects(scene.obj_parent)[np.asarray(scene.poly_object, np.int64)[polygons]]
    types = [str(t) for t in scene.obj_types]
    keep = np.array(["Building" in types[r] for r in root], bool)
    if not keep.any():
        keep[:] = True
    buildings, inv = np.unique(root[keep], return_inverse=True)
    n = len(buildings)
    area = np.asarray(scene.poly_area_m2, np.float64)[polygons][keep]
    geoms, sources = building_footprints(scene, buildings)
    columns: dict[str, list] = {
        "object_id": [scene.obj_ids[b] for b in buildings],
        "object_type": [types[b] for b in buildings],
        "footprint_source": sources,
        "surfaces": [int(c) for c in np.bincount(inv, minlength=n)],
        "area_m2": np.bincount(inv, area, minlength=n).tolist()}
    for col, values in means.items():
        v = np.asarray(values, np.float64)[keep]
        ok = np.isfinite(v)
        num = np.bincount(inv[ok], v[ok] * area[ok], minlength=n)
        den = np.bincount(inv[ok], area[ok], minlength=n)
        columns[col] = [float(a / d) if d > 0 else None for a, d in zip(num, den)]
    for col, values in (maxima or {}).items():
        v = np.asarray(values, np.float64)[keep]
        top = np.full(n, -np.inf)
        np.fmax.at(top, inv, np.where(np.isfinite(v), v, -np.inf))
        columns[col] = [float(t) if np.isfinite(t) else None for t in top]
    return Layer("buildings", geoms, columns, geometry_type="MultiPolygon")
