"""A proposal drawn as a mesh (OBJ, glTF/GLB, PLY, STL through trimesh), placed in the model
for ``compare --with`` (docs/DESIGN.md §20).

- **Units** (``--mesh-units``): the file's numbers times the unit's metres.
- **Up axis** (``--up-axis``): glTF is Y-up by its specification (+Y up, +Z forward), so a
  ``.gltf``/``.glb`` defaults to ``y``; OBJ, PLY and STL carry no convention and default to
  ``z`` (SketchUp, Rhino and Revit's OBJ exports are often Y-up: say ``--up-axis y``). Y-up
  points (x, y, z) become (x, −z, y): a rotation (+90° about x), so windings stay outward.
- **Placement** (``--place X,Y[,Z][,ROTATION_DEG]``): the mesh's own origin goes to (X, Y, Z)
  of the model CRS after turning it ROTATION_DEG counter-clockwise seen from above; Z
  defaults to the ground under (X, Y) (:func:`~cityshade.meshes.scene.ground_heights_m`).
  Without ``--place`` the mesh's coordinates are taken as model-CRS coordinates.
- **Faces**: every triangle is kept; internal faces (floor slabs of a cell complex) are just
  triangles that never see the sun. Exporters wind faces either way (the Topologic massing
  has half its walls and its roof facing in), so each face is turned to face the side from
  which more of a set of directions escape the mesh (traced against the mesh itself); a face
  enclosed on both sides keeps its winding. An open or non-manifold mesh (not watertight in
  trimesh's sense) is accepted with a warning.
- **Surfaces**: trimesh's facets (coplanar adjacent faces) are the polygons, each other face
  a polygon of its own; classes by the outward normal as CityGML names them: roof (up, more
  than 30° above the horizon), ground (down, at the mesh's lowest level), outer_ceiling
  (down, above it), wall (the rest). So the proposal's own surfaces get rows in
  ``surfaces.csv`` like a CityGML building's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.config import LENGTH_UNITS_M
from cityshade.errors import MeshFileError, UsageError
from cityshade.meshes.scene import MeshObject, ground_heights_m, scene_from_objects

#: File endings read as meshes by ``compare --with``.
MESH_SUFFIXES = (".obj", ".glb", ".gltf", ".ply", ".stl")
UP_AXES = ("z", "y")
#: sin 30°: a face whose outward normal rises more than 30° above the horizon is a roof.
_ROOF_MIN_NZ = 0.5
#: Directions per side of a face traced to tell its outside (Fibonacci hemisphere).
_SIDE_RAYS = 16


@dataclass(frozen=True)
class MeshPlacement:
    """How a mesh proposal is scaled, stood up and placed (module docstring)."""

    units: str = "m"
    #: "z", "y" or None (by format: y for glTF, z otherwise).
    up_axis: str | None = None
    #: (X, Y, Z or None, rotation_deg) in the model CRS, or None: the mesh is in model CRS.
    place: tuple | None = None

    def __post_init__(self) -> None:
        if self.units not in LENGTH_UNITS_M:
            raise UsageError(f"--mesh-units must be one of {', '.join(LENGTH_UNITS_M)}, "
                             f"not {self.units!r}")
        if self.up_axis is not None and self.up_axis not in UP_AXES:
            raise UsageError(f"--up-axis must be z or y, not {self.up_axis!r}")

    @staticmethod
    def parse_place(text: str | None):
        """``X,Y[,Z][,ROTATION_DEG]`` → (x, y, z or None, rotation_deg); "" for Z keeps the
        ground (``X,Y,,30``)."""
        if text is None:
            return None
        parts = [p.strip() for p in text.split(",")]
        try:
            values = [float(p) if p else None for p in parts]
        except ValueError:
            values = []
        if not (2 <= len(values) <= 4) or values[0] is None or values[1] is None or not all(
                v is None or math.isfinite(v) for v in values):
            raise UsageError(f"--place must be X,Y[,Z][,ROTATION_DEG] (model CRS metres, "
                             f"degrees counter-clockwise), not {text!r}")
        values += [None] * (4 - len(values))
        return values[0], values[1], values[2], values[3] or 0.0

    def up_for(self, path: Path) -> str:
        if self.up_axis is not None:
            return self.up_axis
        return "y" if path.suffix.lower() in (".gltf", ".glb") else "z"


def read_mesh_parts(path: str | Path) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """The geometries of a mesh file, each with its scene-graph transform applied: (name,
    vertices (V, 3) float64, faces (T, 3) int64), in the file's units and axes.

    Raises
    ------
    MeshFileError
        Missing or unreadable file, or no triangle in it.
    """
    import trimesh

    path = Path(path)
    if not path.is_file():
        raise MeshFileError("no such mesh file", path=str(path))
    try:
        scene = trimesh.load(str(path), force="scene", process=False)
        meshes = scene.dump(concatenate=False)
    except Exception as exc:  # noqa: BLE001 - trimesh raises many kinds; its message counts
        raise MeshFileError(f"trimesh cannot read it: {exc}", path=str(path)) from None
    parts = []
    for i, mesh in enumerate(meshes):
        faces = np.asarray(getattr(mesh, "faces", np.zeros((0, 3))), np.int64).reshape(-1, 3)
        if len(faces):
            name = str(mesh.metadata.get("name") or f"part{i}")
            parts.append((name, np.asarray(mesh.vertices, np.float64), faces))
    if not parts:
        raise MeshFileError("the mesh file holds no triangles", path=str(path))
    return parts


def to_model(vertices: np.ndarray, up: str, unit_m: float, place, ground_z=None) -> np.ndarray:
    """File coordinates → model CRS: scaled to metres, Y-up turned to Z-up, rotated about the
    vertical and moved to ``place`` (x, y, z, rotation_deg); ``ground_z`` stands for a
    missing z."""
    v = np.asarray(vertices, np.float64) * unit_m
    if up == "y":
        v = np.column_stack([v[:, 0], -v[:, 2], v[:, 1]])
    if place is None:
        return v
    x, y, z, rot = place
    a = math.radians(rot)
    c, s = math.cos(a), math.sin(a)
    out = np.column_stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1], v[:, 2]])
    return out + [x, y, ground_z if z is None else z]


def outward_faces(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, int]:
    """The faces wound so that each faces the side more directions escape the mesh from
    (ties and faces enclosed on both sides keep their winding); returns (faces, flipped)."""
    from cityshade.accel.kdtree_build import build_kdtree
    from cityshade.trace import occluded, shadow_offset_m

    origin = vertices.mean(axis=0)
    v32 = (vertices - origin).astype(np.float32)
    n_t = len(faces)
    tree = build_kdtree(v32, faces, np.full(n_t, -np.inf), np.full(n_t, np.inf),
                        np.full(n_t, -1, np.int32))
    corners = v32.astype(np.float64)[faces]
    centre = corners.mean(axis=1)
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    dirs = _hemisphere(_SIDE_RAYS)
    escapes = []
    for sign in (1.0, -1.0):
        n = sign * normal
        # A frame (t, b, n) per face: the hemisphere's directions around n.
        t = np.cross(n, np.where(np.abs(n[:, 2:3]) < 0.9, [[0.0, 0.0, 1.0]], [[1.0, 0.0, 0.0]]))
        t /= np.linalg.norm(t, axis=1)[:, None]
        b = np.cross(n, t)
        d = (dirs[None, :, 0:1] * t[:, None] + dirs[None, :, 1:2] * b[:, None]
             + dirs[None, :, 2:3] * n[:, None]).reshape(-1, 3)
        o = centre + n * (shadow_offset_m(centre)[:, None] * 4.0)
        o = np.repeat(o, len(dirs), axis=0)
        escapes.append((~occluded(tree, o, d)).reshape(n_t, -1).sum(axis=1))
    flip = escapes[1] > escapes[0]
    out = faces.copy()
    out[flip] = out[flip][:, ::-1]
    return out, int(flip.sum())


def _hemisphere(n: int) -> np.ndarray:
    """n directions spread over the +z hemisphere (a Fibonacci spiral), (n, 3)."""
    k = np.arange(n) + 0.5
    z = 1.0 - k / n
    r = np.sqrt(1.0 - z * z)
    phi = k * math.pi * (3.0 - math.sqrt(5.0))
    return np.column_stack([r * np.cos(phi), r * np.sin(phi), z])


def classify_faces(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Surface class code of each (outward) face: roof, wall, ground or outer_ceiling."""
    corners = vertices[faces]
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    nz = normal[:, 2] / np.maximum(np.linalg.norm(normal, axis=1), 1e-300)
    low = corners[:, :, 2].max(axis=1) <= vertices[:, 2].min() + 0.01
    out = np.full(len(faces), SURFACE_CODE["wall"], np.uint8)
    out[nz > _ROOF_MIN_NZ] = SURFACE_CODE["roof"]
    down = nz < -_ROOF_MIN_NZ
    out[down & low] = SURFACE_CODE["ground"]
    out[down & ~low] = SURFACE_CODE["outer_ceiling"]
    return out


def _surfaces(name: str, vertices, faces, classes):
    """Polygons of one part: trimesh's facets (coplanar adjacent faces) split by class, each
    other face alone; (face → surface, surface ids, surface classes)."""
    import trimesh

    mesh = trimesh.Trimesh(vertices, faces, process=False)
    face_surface = np.full(len(faces), -1, np.int64)
    n = 0
    for facet in mesh.facets:
        for cls in np.unique(classes[facet]):
            face_surface[facet[classes[facet] == cls]] = n
            n += 1
    alone = np.flatnonzero(face_surface < 0)
    face_surface[alone] = n + np.arange(len(alone))
    n += len(alone)
    first = np.full(n, -1, np.int64)
    first[face_surface[::-1]] = np.arange(len(faces))[::-1]
    surface_class = classes[first]
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    ids = [f"{name}_{SURFACE_CLASSES[c]}_{k}" for k, c in enumerate(surface_class)]
    return face_surface, ids, surface_class


def _far_warning(path: Path, objects, model) -> list[str]:
    """A warning when an unplaced mesh lies nowhere near the model (local coordinates)."""
    v = np.concatenate([ob.vertices_m for ob in objects])
    lo, hi = (np.asarray(b, np.float64) + model.origin_m for b in model.city_box_m())
    gap = np.maximum(np.maximum(lo[:2] - v[:, :2].max(axis=0), v[:, :2].min(axis=0) - hi[:2]), 0)
    if float(np.hypot(*gap)) <= float(np.hypot(*(hi[:2] - lo[:2]))):
        return []
    return [(f"{path.name} lies {np.hypot(*gap):,.0f} m from the model: its coordinates look "
             f"local; give --place X,Y to put its origin in the model")]


def proposal_scene(path: str | Path, model, placement: MeshPlacement | None = None):
    """The scene of a mesh proposal in ``model``'s CRS and origin (module docstring): one
    ``Building`` object per geometry of the file, named ``<file stem>`` (or
    ``<stem>:<geometry>`` when there are several). ``report["warnings"]`` holds what the
    user should know (an open or non-manifold mesh, faces turned outward).

    Raises
    ------
    MeshFileError
        As :func:`read_mesh_parts`.
    """
    import trimesh

    placement = placement or MeshPlacement()
    path = Path(path)
    parts = read_mesh_parts(path)
    up, unit = placement.up_for(path), LENGTH_UNITS_M[placement.units]
    ground_z, ground_from = None, None
    if placement.place is not None and placement.place[2] is None:
        z, ground_from = ground_heights_m(model, [placement.place[:2]])
        ground_z = float(z[0])
    objects, warnings, flipped = [], [], 0
    for name, vertices, faces in parts:
        v = to_model(vertices, up, unit, placement.place, ground_z)
        mesh = trimesh.Trimesh(v, faces, process=True)  # merges repeated vertices
        v, f = np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int64)
        oid = path.stem if len(parts) == 1 else f"{path.stem}:{name}"
        if not mesh.is_watertight:
            warnings.append(f"{path.name}: {oid} is not a closed manifold mesh (open edges "
                            f"or faces sharing an edge 3 times or more); it is used as it is")
        f, n_flip = outward_faces(v, f)
        flipped += n_flip
        classes = classify_faces(v, f)
        face_surface, ids, surface_class = _surfaces(oid, v, f, classes)
        objects.append(MeshObject(oid, "Building", v, f, face_surface, ids, surface_class))
    if placement.place is None:
        warnings += _far_warning(path, objects, model)
    if flipped:
        warnings.append(f"{path.name}: {flipped} faces turned to face outward (the side "
                        f"more directions escape the mesh from)")
    report = {"warnings": warnings, "mesh": {
        "file": str(path.resolve()), "up_axis": up, "units": placement.units,
        "place": list(placement.place) if placement.place else None,
        "ground": ground_from, "ground_z_m": ground_z, "faces_flipped": flipped}}
    return scene_from_objects(objects, model.crs, origin_m=model.origin_m, report=report)
