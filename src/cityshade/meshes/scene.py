"""Objects made of triangle meshes → a :class:`~cityshade.geometry.scene.Scene`, and the ground
under points of a scene.

A mesh object (a register tree, a proposal's massing) has surfaces — groups of its triangles
that become the scene's polygons (rows of ``surfaces.csv``) — each with a surface class. The
vertices are float64 model-CRS coordinates until the one cast to float32 render space.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.errors import EmptyModelError
from cityshade.geometry.scene import TIME_SOURCE_NAMES, Scene, render_origin


@dataclass
class MeshObject:
    """One object of a mesh scene.

    Attributes
    ----------
    obj_id, obj_type : str
        Its id and type (a CityGML type name, e.g. ``SolitaryVegetationObject``).
    vertices_m : (V, 3) float64
        Model-CRS coordinates (metres).
    faces : (T, 3) int
        Vertex indices, counter-clockwise seen from outside.
    face_surface : (T,) int
        Index into ``surface_ids`` of each face.
    surface_ids : list of str
        Id of each surface (a polygon of the scene).
    surface_class : (S,) uint8
        Surface class code of each surface.
    t_begin_days, t_end_days : float
        Validity interval (days since 1970-01-01 UTC; ±inf for open ends).
    """

    obj_id: str
    obj_type: str
    vertices_m: np.ndarray
    faces: np.ndarray
    face_surface: np.ndarray
    surface_ids: list[str]
    surface_class: np.ndarray
    t_begin_days: float = -math.inf
    t_end_days: float = math.inf


def scene_from_objects(objects: list[MeshObject], crs, origin_m=None,
                       report: dict | None = None) -> Scene:
    """A scene of mesh objects in render space around ``origin_m`` (default: the centre of
    their box rounded to 1 m, as a build chooses it). Zero-area faces are dropped and counted
    (``report["skipped"]["degenerate_faces"]``). A polygon's normal is the area-weighted mean
    of its faces' (a closed crown's is about 0: then +z); its area their sum.

    Raises
    ------
    EmptyModelError
        No object has a face with an area.
    """
    verts, faces, face_poly, face_obj = [], [], [], []
    poly_obj, poly_cls, poly_ids = [], [], []
    nv = npoly = 0
    for i, ob in enumerate(objects):
        v = np.asarray(ob.vertices_m, np.float64).reshape(-1, 3)
        f = np.asarray(ob.faces, np.int64).reshape(-1, 3)
        verts.append(v)
        faces.append(f + nv)
        face_poly.append(np.asarray(ob.face_surface, np.int64) + npoly)
        face_obj.append(np.full(len(f), i, np.int64))
        poly_obj.append(np.full(len(ob.surface_ids), i, np.int64))
        poly_cls.append(np.asarray(ob.surface_class, np.uint8))
        poly_ids += list(ob.surface_ids)
        nv += len(v)
        npoly += len(ob.surface_ids)
    world = np.concatenate(verts) if verts else np.zeros((0, 3))
    tri = np.concatenate(faces) if faces else np.zeros((0, 3), np.int64)
    tri_poly = np.concatenate(face_poly) if face_poly else np.zeros(0, np.int64)
    tri_obj = np.concatenate(face_obj) if face_obj else np.zeros(0, np.int64)
    cross = np.cross(world[tri[:, 1]] - world[tri[:, 0]], world[tri[:, 2]] - world[tri[:, 0]])
    twice = np.linalg.norm(cross, axis=1)
    ok = twice > 0.0
    if not ok.any():
        raise EmptyModelError("the mesh has no face with an area")
    tri, tri_poly, tri_obj, cross, twice = tri[ok], tri_poly[ok], tri_obj[ok], cross[ok], twice[ok]
    poly_area = np.bincount(tri_poly, 0.5 * twice, minlength=npoly)
    normal = np.stack([np.bincount(tri_poly, cross[:, k], minlength=npoly) for k in range(3)], 1)
    length = np.linalg.norm(normal, axis=1)
    flat = length <= 1e-6 * np.maximum(2.0 * poly_area, 1e-300)
    normal = np.where(flat[:, None], [0.0, 0.0, 1.0], normal / np.where(flat, 1.0, length)[:, None])
    used = np.zeros(len(world), bool)
    used[tri.ravel()] = True
    new_index = np.cumsum(used) - 1
    world = world[used]
    if origin_m is None:
        origin_m = render_origin(world.min(axis=0), world.max(axis=0))
    origin = np.asarray(origin_m, np.float64)
    begin = np.array([ob.t_begin_days for ob in objects], np.float64)
    end = np.array([ob.t_end_days for ob in objects], np.float64)
    dated = np.isfinite(begin) | np.isfinite(end)
    source = np.where(dated, TIME_SOURCE_NAMES.index("attribute"), 0).astype(np.uint8)
    n_obj, n_tri = len(objects), len(tri)
    rep = {"polygons": {"read": npoly, "drawn": npoly}, "skipped": {},
           "left_out": {}, "repairs": {}, "warnings": []}
    if (~ok).sum():
        rep["skipped"] = {"degenerate_faces": int((~ok).sum())}
    rep.update(report or {})
    return Scene(
        origin_m=origin, crs=crs, vertices=(world - origin).astype(np.float32),
        uv=np.zeros((len(world), 2), np.float32), triangles=new_index[tri].astype(np.int32),
        tri_object=tri_obj.astype(np.int32), tri_polygon=tri_poly.astype(np.int32),
        tri_class=np.concatenate(poly_cls)[tri_poly].astype(np.uint8),
        tri_material=np.full(n_tri, -1, np.int32), tri_texture=np.full(n_tri, -1, np.int32),
        tri_t_begin_days=begin[tri_obj], tri_t_end_days=end[tri_obj],
        obj_ids=[ob.obj_id for ob in objects], obj_types=[ob.obj_type for ob in objects],
        obj_parent=np.full(n_obj, -1, np.int32), obj_t_begin_days=begin, obj_t_end_days=end,
        obj_time_source=source, obj_lod=np.full(n_obj, -1, np.int8), poly_ids=poly_ids,
        poly_object=np.concatenate(poly_obj).astype(np.int32),
        poly_class=np.concatenate(poly_cls).astype(np.uint8), poly_area_m2=poly_area,
        poly_normal=normal.astype(np.float32), poly_repairs=np.zeros(npoly, np.uint16),
        report=rep)


def ground_heights_m(scene, xy_m: np.ndarray, t_days: float = 0.0) -> tuple[np.ndarray, str]:
    """Model-CRS height of the ground under model-CRS points ``xy_m`` (N, 2): the highest
    terrain triangle (class ``terrain``) under each point, else the ground plane of
    ``render --ground auto`` (the median of the objects' lowest points). Returns the heights
    (N,) float64 and what they came from (``"terrain"``, ``"plane"`` or
    ``"terrain and plane"``)."""
    from cityshade.geometry.ground import ground_height_m

    xy = np.asarray(xy_m, np.float64).reshape(-1, 2)
    z = np.full(len(xy), np.nan)
    cls = np.asarray(scene.tri_class)
    terrain = np.flatnonzero(cls == SURFACE_CODE["terrain"])
    if len(terrain):
        z = _terrain_heights(scene, terrain, xy, t_days)
    missing = ~np.isfinite(z)
    if missing.any():
        z[missing] = ground_height_m(scene, "auto") + float(scene.origin_m[2])
    if not len(terrain) or missing.all():
        return z, "plane"
    return z, "terrain" if not missing.any() else "terrain and plane"


def _terrain_heights(scene, terrain: np.ndarray, xy: np.ndarray, t_days: float) -> np.ndarray:
    """Heights of the terrain triangles ``terrain`` under ``xy`` (NaN where none): one ray
    straight down from above the scene through a kd-tree of the terrain alone."""
    from cityshade.accel.kdtree_build import build_kdtree
    from cityshade.trace import intersect

    tri = np.asarray(scene.triangles)[terrain]
    tree = build_kdtree(np.asarray(scene.vertices), tri,
                        np.asarray(scene.tri_t_begin_days)[terrain],
                        np.asarray(scene.tri_t_end_days)[terrain],
                        np.full(len(tri), -1, np.int32))
    top = float(np.asarray(scene.vertices)[:, 2].max()) + 10.0
    origins = np.column_stack([xy - np.asarray(scene.origin_m[:2], np.float64),
                               np.full(len(xy), top)])
    dist, _, _, _ = intersect(tree, origins, np.tile([0.0, 0.0, -1.0], (len(xy), 1)), t_days)
    return np.where(np.isfinite(dist), top - dist + float(scene.origin_m[2]), np.nan)
