"""The G-buffer of a camera pass and the per-pixel surface attributes derived from it.

The rasterizer (:func:`cityshade.raster.rasterize.rasterize`) writes only what it must: the
triangle id, the perspective-correct barycentrics of the pixel centre and the depth.
:func:`resolve` derives everything else from those and the scene (exact float64 positions on
the triangles, face normals, object, material, texture coordinates, surface class).
:func:`gbuffer_by_raycasting` is the slow, obvious twin: one closest-hit ray per pixel centre.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit

from cityshade.errors import UsageError
from cityshade.runtime.memory import Recycler
from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks


@dataclass(eq=False)
class GBuffer:
    """Result of a camera pass.

    Attributes
    ----------
    camera : Camera
    prim_id : (H, W) int32
        Triangle id, -1 where no surface (sky / nodata).
    bary : (H, W, 2) float32
        Barycentrics ``(u, v)`` of the pixel centre's point on the triangle:
        point = (1 - u - v) v0 + u v1 + v v2.
    depth : (H, W) float32
        Metres from the eye along the pixel's ray (map: below the camera plane); +inf where no
        surface.
    stats : dict
        Culling counts per step, timings (s), tiles, threads.
    """

    camera: object
    prim_id: np.ndarray
    bary: np.ndarray
    depth: np.ndarray
    stats: dict = field(default_factory=dict)


@dataclass(eq=False)
class Surfaces:
    """Per-pixel surface attributes (see :func:`resolve`). Pixels without surface: ``valid``
    False, ``position_m`` NaN, ``normal`` and ``uv`` 0, ids -1, ``cls`` 0."""

    position_m: np.ndarray     # (H, W, 3) float64 render space
    normal: np.ndarray         # (H, W, 3) float32 unit face normal (outward by the winding)
    obj_id: np.ndarray         # (H, W) int32
    material: np.ndarray       # (H, W) int32
    texture: np.ndarray        # (H, W) int32
    uv: np.ndarray             # (H, W, 2) float32
    cls: np.ndarray            # (H, W) uint8 surface class
    valid: np.ndarray          # (H, W) bool
    prim_id: np.ndarray        # (H, W) int32 (the G-buffer's)
    depth: np.ndarray          # (H, W) float32 (the G-buffer's)

    @property
    def class_(self) -> np.ndarray:
        """Alias of ``cls`` (the contract's name ``class`` is a Python keyword)."""
        return self.cls


@njit(cache=True, nogil=True)
def _resolve_kernel(prim, bary, verts, tris, uvs, tri_object, tri_material, tri_texture,
                    tri_class, position, normal, uv, obj_id, material, texture, cls, r0, r1):
    """Fill every pixel's attributes: the no-surface values (NaN position, zero normal and
    texture coordinates, -1 ids, class 0) where ``prim`` is -1, else the triangle's. Every
    value is the same float64 expression, in the same order, as the numpy twin
    ``tests/reference.py: reference_resolve``, so the results are bit-identical. (Numpy's
    fills before the kernel were a serial quarter of the resolve.)"""
    height, width = prim.shape
    has_uv = uvs.shape[0] > 0
    for r in range(r0, r1):
        for c in range(width):
            tri = prim[r, c]
            normal[r, c, 0] = np.float32(0.0)
            normal[r, c, 1] = np.float32(0.0)
            normal[r, c, 2] = np.float32(0.0)
            uv[r, c, 0] = np.float32(0.0)
            uv[r, c, 1] = np.float32(0.0)
            if tri < 0:
                position[r, c, 0] = np.nan
                position[r, c, 1] = np.nan
                position[r, c, 2] = np.nan
                obj_id[r, c] = -1
                material[r, c] = -1
                texture[r, c] = -1
                cls[r, c] = 0
                continue
            bu = np.float64(bary[r, c, 0])
            bv = np.float64(bary[r, c, 1])
            bw = 1.0 - bu - bv
            i0, i1, i2 = tris[tri, 0], tris[tri, 1], tris[tri, 2]
            a0, a1, a2 = (np.float64(verts[i0, 0]), np.float64(verts[i0, 1]),
                          np.float64(verts[i0, 2]))
            b0, b1, b2 = (np.float64(verts[i1, 0]), np.float64(verts[i1, 1]),
                          np.float64(verts[i1, 2]))
            c0, c1, c2 = (np.float64(verts[i2, 0]), np.float64(verts[i2, 1]),
                          np.float64(verts[i2, 2]))
            position[r, c, 0] = bw * a0 + bu * b0 + bv * c0
            position[r, c, 1] = bw * a1 + bu * b1 + bv * c1
            position[r, c, 2] = bw * a2 + bu * b2 + bv * c2
            # Face normal: (v1 - v0) x (v2 - v0), unit, 0 for a degenerate triangle.
            e0, e1, e2 = b0 - a0, b1 - a1, b2 - a2
            f0, f1, f2 = c0 - a0, c1 - a1, c2 - a2
            n0 = e1 * f2 - e2 * f1
            n1 = e2 * f0 - e0 * f2
            n2 = e0 * f1 - e1 * f0
            length = np.sqrt(n0 * n0 + n1 * n1 + n2 * n2)
            if length > 0.0:
                normal[r, c, 0] = np.float32(n0 / length)
                normal[r, c, 1] = np.float32(n1 / length)
                normal[r, c, 2] = np.float32(n2 / length)
            if has_uv:
                for k in range(2):
                    uv[r, c, k] = np.float32(bw * np.float64(uvs[i0, k])
                                             + bu * np.float64(uvs[i1, k])
                                             + bv * np.float64(uvs[i2, k]))
            obj_id[r, c] = tri_object[tri]
            material[r, c] = tri_material[tri]
            texture[r, c] = tri_texture[tri]
            cls[r, c] = tri_class[tri]


#: The resolved surfaces' and oriented normals' memory (eight arrays a frame), used again once
#: nothing refers to it.
_SURFACES = Recycler(keep=16)


def resolve(scene, gbuf: GBuffer) -> Surfaces:
    """Derive per-pixel surface attributes from ``prim_id`` and ``bary``.

    ``position_m`` is the float64 point ``(1-u-v) v0 + u v1 + v v2`` of the triangle's float32
    vertices; ``normal`` the unit cross product ``(v1 - v0) x (v2 - v0)`` (computed in float64;
    zero for a degenerate triangle); ``uv`` interpolates the vertex texture coordinates. One
    parallel pass over the pixels (the numpy twin is ``tests/reference.py``'s
    ``reference_resolve``).
    """
    prim = np.asarray(gbuf.prim_id)
    if prim.ndim != 2 or gbuf.bary.shape != prim.shape + (2,):
        raise UsageError("G-buffer prim_id must be (H, W) and bary (H, W, 2)")
    h, w = prim.shape
    # Every element is written by the kernel; the memory of earlier frames' dropped surfaces
    # is used again (fresh pages: a fault and the kernel's zeroing each).
    position = _SURFACES.empty((h, w, 3), np.float64)
    normal = _SURFACES.empty((h, w, 3), np.float32)
    uv = _SURFACES.empty((h, w, 2), np.float32)
    obj_id = _SURFACES.empty((h, w), np.int32)
    material = _SURFACES.empty((h, w), np.int32)
    texture = _SURFACES.empty((h, w), np.int32)
    cls = _SURFACES.empty((h, w), np.uint8)
    # Rows handed out a few at a time (run_chunks is dynamic): surfaces are uneven over a
    # picture (the 1080p overview of the 1M city has 32 % of its surface pixels in the top half
    # of the rows).
    run_chunks(_resolve_kernel, h, ROW_CHUNK, prim, np.asarray(gbuf.bary),
               np.asarray(scene.vertices), np.asarray(scene.triangles),
               np.asarray(scene.uv).reshape(-1, 2), np.asarray(scene.tri_object),
               np.asarray(scene.tri_material), np.asarray(scene.tri_texture),
               np.asarray(scene.tri_class), position, normal, uv, obj_id, material, texture, cls)
    return Surfaces(position_m=position, normal=normal, obj_id=obj_id, material=material,
                    texture=texture, uv=uv, cls=cls, valid=prim >= 0, prim_id=prim,
                    depth=np.asarray(gbuf.depth))


@njit(cache=True, nogil=True)
def _seen_side_kernel(normal, position, eye, to_viewer, perspective, out, r0, r1):
    height, width = normal.shape[:2]
    for r in range(r0, r1):
        for c in range(width):
            n0 = np.float64(normal[r, c, 0])
            n1 = np.float64(normal[r, c, 1])
            n2 = np.float64(normal[r, c, 2])
            if perspective:
                t0 = eye[0] - position[r, c, 0]
                t1 = eye[1] - position[r, c, 1]
                t2 = eye[2] - position[r, c, 2]
            else:
                t0, t1, t2 = to_viewer[0], to_viewer[1], to_viewer[2]
            if n0 * t0 + n1 * t1 + n2 * t2 < 0.0:
                n0, n1, n2 = -n0, -n1, -n2
            out[r, c, 0] = n0
            out[r, c, 1] = n1
            out[r, c, 2] = n2


def seen_side_normals(surfaces: Surfaces, camera) -> np.ndarray:
    """Unit normals (H, W, 3) float64 turned to the side the camera sees: flipped where the
    normal points away from the viewer (``n . (eye - p) < 0``; maps: ``n . (eye - target)``).

    One parallel pass (:func:`cityshade.shadows.oriented_normals` calls it; the numpy twin is
    ``tests/reference.py``'s ``reference_oriented_normals``).
    """
    normal = np.asarray(surfaces.normal)
    h, w = normal.shape[:2]
    eye = np.asarray(camera.eye_m, np.float64).reshape(3)
    perspective = camera.kind != "map"
    if perspective:
        position = np.asarray(surfaces.position_m, np.float64)
    else:
        position = np.zeros((1, 1, 3))
    to_viewer = eye - np.asarray(camera.target_m, np.float64).reshape(3)
    out = _SURFACES.empty((h, w, 3), np.float64)
    run_chunks(_seen_side_kernel, h, ROW_CHUNK, normal, position, eye, to_viewer, perspective,
               out)  # rows: uneven, as in resolve
    return out


def gbuffer_by_raycasting(scene, camera, t_days: float) -> GBuffer:
    """The slow, obvious twin of the rasterizer: one closest-hit ray per pixel centre.

    Perspective rays start on the near plane (the rasterizer's near clipping) and end at the
    far plane; map rays start on the camera plane and run straight down to ``far_m``. Uses
    :func:`cityshade.trace.intersect`, so it needs the scene's kd-tree.
    """
    from cityshade.trace import intersect

    h, w = camera.shape
    origins, directions = camera.primary_rays()
    if camera.kind == "map":
        start = np.zeros(h * w)
        tmax = np.full(h * w, camera.far_m)
    else:
        # Distance along the unit ray to the near / far plane.
        _, _, fwd = camera.frame()
        cos = directions @ fwd
        start = camera.near_m / cos
        tmax = camera.far_m / cos - start
        origins = origins + directions * start[:, None]
    dist, tri, u, v = intersect(scene.kdtree, origins, directions, t_days, tmax)
    depth = np.where(tri >= 0, dist + start, np.inf).astype(np.float32)
    bary = np.stack([u, v], axis=-1).astype(np.float32).reshape(h, w, 2)
    return GBuffer(camera=camera, prim_id=tri.astype(np.int32).reshape(h, w), bary=bary,
                   depth=depth.reshape(h, w), stats={"method": "raycasting"})
