"""A scene coloured by a per-surface result, as binary glTF (``.glb``) and PLY
(``cityshade export``; docs/DESIGN.md §20).

Input: a scene and a ``surfaces.csv`` (of ``batch --surfaces``, ``compare``, or any command
writing one row per polygon with a ``polygon_index``) and the name of one of its numeric
columns (``mean_sun_hours``, ``hours_after``, ``loss_h``, …). Each polygon with a value is
written as its own triangles (vertices not shared between triangles, so colours stay flat)
with

- the viridis colour of the value between the legend's ends as ``COLOR_0`` (RGBA, uint8),
- the value itself as the custom vertex attribute ``_VALUE`` (float32; glTF custom
  attributes start with an underscore),

in the mesh ``result``; the polygons without a value form the grey mesh ``context`` (no
``_VALUE``). Positions are metres around the scene's origin, in glTF's axes (+Y up: model
(x, y, z) is glTF (x, z, −y)); ``asset.extras.cityshade`` (and the scene's extras, which
trimesh reads back as ``scene.metadata``) record the legend (column, unit, colour map,
range), the origin, the CRS and the axes. The PLY holds the same vertices in model-CRS
coordinates (float64, z up) with ``red, green, blue, alpha`` and ``_VALUE`` per vertex, its
context triangles with NaN.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from cityshade.errors import InputError, UsageError

#: Colour of the polygons without a value (the untextured city).
CONTEXT_RGBA = (200, 200, 200, 255)
#: Columns taken when none is named, in this order.
DEFAULT_COLUMNS = ("mean_sun_hours", "hours_after")


def column_unit(column: str) -> str:
    """The unit a column's name says (``_h``/hours → h, ``_pct`` → %, ``_m2`` → m²)."""
    name = column.lower()
    if name.endswith("_h") or "hours" in name:
        return "h"
    if name.endswith("_pct"):
        return "%"
    if name.endswith("_m2"):
        return "m²"
    return ""


def read_polygon_values(path: str | Path, column: str | None, scene) -> tuple[np.ndarray, str]:
    """(P,) float64 value per polygon of ``scene`` from a surfaces table (NaN where it has no
    row or an empty cell) and the column read. Rows are matched by ``polygon_index`` and
    checked against ``polygon_id``, so a table of another scene is refused; rows of polygons
    the scene does not have (a compare proposal's) are left out.

    Raises
    ------
    InputError
        No such file, no ``polygon_index`` or no such column, a row of another scene.
    """
    path = Path(path)
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh)
            rows = list(reader)
            header = reader.fieldnames or []
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise InputError(f"cannot read the surfaces table: {exc}", path=str(path)) from None
    if "polygon_index" not in header:
        raise InputError("not a surfaces table (no polygon_index column)", path=str(path))
    if column is None:
        column = next((c for c in DEFAULT_COLUMNS if c in header), None)
    if column not in header:
        raise UsageError(f"--column {column}: the table's columns are {', '.join(header)}")
    n_poly = len(scene.poly_ids)
    values = np.full(n_poly, np.nan)
    for line, row in enumerate(rows, start=2):
        p = int(row["polygon_index"])
        if p >= n_poly:
            continue
        pid = row.get("polygon_id") or ""
        if pid and scene.poly_ids[p] and pid != scene.poly_ids[p]:
            raise InputError(f"polygon {p} is {scene.poly_ids[p]!r} in the scene but {pid!r} "
                             f"here: the table is of another scene", path=str(path), line=line)
        text = (row.get(column) or "").strip()
        if text:
            try:
                values[p] = float(text)
            except ValueError:
                raise InputError(f"{column} is not a number: {text!r}", path=str(path),
                                 line=line) from None
    return values, column


def value_range(values: np.ndarray, given=None) -> tuple[float, float]:
    """The legend's ends: ``given``, else 0 (or the smallest value when negative) to the
    largest value (one unit wider when all are equal)."""
    if given is not None:
        lo, hi = (float(v) for v in given)
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise UsageError(f"--range must be LO,HI with LO < HI, not {given}")
        return lo, hi
    finite = values[np.isfinite(values)]
    if not finite.size:
        raise UsageError("the column has no value for any polygon of the scene")
    lo, hi = min(0.0, float(finite.min())), float(finite.max())
    return lo, hi if hi > lo else lo + 1.0


@dataclass
class ColouredMesh:
    """The two meshes of an export: vertices (render space, z up), faces, RGBA per vertex,
    the value per vertex (NaN for the context)."""

    vertices: np.ndarray
    faces: np.ndarray
    rgba: np.ndarray
    value: np.ndarray


def coloured_meshes(scene, values: np.ndarray, lo: float, hi: float, t_days: float = 0.0):
    """(result, context): the triangles standing at ``t_days`` of the polygons with a value,
    and of the others, each triangle with vertices of its own."""
    from cityshade.sunhours.outputs import viridis_rgb

    tri = np.asarray(scene.triangles)
    standing = ((np.asarray(scene.tri_t_begin_days) <= t_days)
                & (t_days < np.asarray(scene.tri_t_end_days)))
    tri_value = values[np.asarray(scene.tri_polygon)]
    out = []
    for keep in (standing & np.isfinite(tri_value), standing & ~np.isfinite(tri_value)):
        corners = np.asarray(scene.vertices)[tri[keep]].reshape(-1, 3)
        value = np.repeat(tri_value[keep], 3)
        if np.isfinite(value).all() and len(value):
            rgb = viridis_rgb((value - lo) / (hi - lo))
            rgba = np.column_stack([rgb, np.full(len(value), 255, np.uint8)])
        else:
            rgba = np.tile(np.array(CONTEXT_RGBA, np.uint8), (len(value), 1))
        out.append(ColouredMesh(corners.astype(np.float32),
                                np.arange(len(corners), dtype=np.int64).reshape(-1, 3), rgba,
                                value.astype(np.float32)))
    return tuple(out)


def export_extras(scene, column: str, unit: str, lo: float, hi: float, sources: dict) -> dict:
    """What a viewer needs to read the file: legend, axes, origin, CRS (``asset.extras``)."""
    crs = scene.crs
    origin = [float(v) for v in scene.origin_m]
    return {"cityshade": {
        "legend": {"column": column, "unit": unit, "colour_map": "viridis",
                   "range": [lo, hi], "no_value_rgba": list(CONTEXT_RGBA),
                   "value_attribute": "_VALUE"},
        "units": "m", "origin_m": origin,
        "crs": {"name": crs.name, "epsg": crs.horizontal_epsg, "srs_name": crs.srs_name},
        "axes": "glTF +Y up; model x = x + origin[0], y = -z + origin[1], z = y + origin[2]",
        "sources": sources}}


def write_glb(path: str | Path, result: ColouredMesh, context: ColouredMesh,
              extras: dict) -> None:
    """The two meshes as binary glTF (atomic write)."""
    import trimesh
    from trimesh.exchange.gltf import export_glb

    from cityshade.util import atomic_write

    scene = trimesh.Scene()
    for name, part in (("result", result), ("context", context)):
        if not len(part.faces):
            continue
        v = part.vertices
        mesh = trimesh.Trimesh(np.column_stack([v[:, 0], v[:, 2], -v[:, 1]]), part.faces,
                               vertex_colors=part.rgba, process=False)
        if name == "result":
            mesh.vertex_attributes["_VALUE"] = part.value
        scene.add_geometry(mesh, geom_name=name, node_name=name)
    scene.metadata.update(extras)

    def asset_extras(tree):
        tree["asset"]["extras"] = extras

    data = export_glb(scene, include_normals=False, tree_postprocessor=asset_extras)
    with atomic_write(path, mode="wb", what="the glTF file") as fh:
        fh.write(data)


def write_ply(path: str | Path, result: ColouredMesh, context: ColouredMesh,
              origin_m, extras: dict) -> None:
    """Both meshes in one PLY in model-CRS coordinates (binary, float64 positions)."""
    import trimesh

    from cityshade.util import atomic_write

    cat = np.concatenate
    v = cat([result.vertices, context.vertices]).astype(np.float64) + np.asarray(origin_m)
    faces = cat([result.faces, context.faces + len(result.vertices)])
    mesh = trimesh.Trimesh(v, faces, vertex_colors=cat([result.rgba, context.rgba]),
                           process=False)
    mesh.vertex_attributes["_VALUE"] = cat([result.value, context.value])
    data = trimesh.exchange.ply.export_ply(mesh, encoding="binary", include_attributes=True)
    with atomic_write(path, mode="wb", what="the PLY file") as fh:
        fh.write(data)


@dataclass(frozen=True)
class ExportRequest:
    """What ``cityshade export`` writes: ``scene`` (a .cityshade path or a Scene) coloured by
    ``column`` of ``surfaces`` (a surfaces.csv) into ``output`` (.glb) and ``ply``."""

    scene: object
    surfaces: Path
    output: Path
    column: str | None = None
    value_range: tuple[float, float] | None = None
    unit: str | None = None
    ply: Path | None = None


def run_export(request: ExportRequest) -> dict:
    """Write the glTF (and PLY) of ``request`` together (an output group); returns a summary
    (column, unit, range, polygons with and without a value).

    Raises
    ------
    InputError, UsageError
        As :func:`read_polygon_values` and :func:`value_range`; outputs that cannot be
        written.
    """
    from cityshade.util import check_outputs, output_group

    outputs = [("-o", request.output, (".glb",))]
    if request.ply is not None:
        outputs.append(("--ply", request.ply, (".ply",)))
    check_outputs(*outputs)
    scene = request.scene
    if isinstance(scene, (str, Path)):
        from cityshade.store.scenefile import whole_scene

        scene = whole_scene(scene)
    values, column = read_polygon_values(request.surfaces, request.column, scene)
    lo, hi = value_range(values, request.value_range)
    unit = column_unit(column) if request.unit is None else request.unit
    result, context = coloured_meshes(scene, values, lo, hi)
    extras = export_extras(scene, column, unit, lo, hi, {
        "scene": str(request.scene) if isinstance(request.scene, (str, Path)) else None,
        "surfaces": str(request.surfaces)})
    with output_group():
        write_glb(request.output, result, context, extras)
        if request.ply is not None:
            write_ply(request.ply, result, context, scene.origin_m, extras)
    poly = np.asarray(scene.tri_polygon)
    valued = np.isfinite(values[poly])
    return {"column": column, "unit": unit, "range": (lo, hi),
            "polygons": len(np.unique(poly[valued])),
            "context_polygons": len(np.unique(poly[~valued]))}
