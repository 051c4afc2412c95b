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

from cityshade.errors import UsageError


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


def resolve(scene, gbuf: GBuffer) -> Surfaces:
    """Derive per-pixel surface attributes from ``prim_id`` and ``bary``.

    ``position_m`` is the float64 point ``(1-u-v) v0 + u v1 + v v2`` of the triangle's float32
    vertices; ``normal`` the unit cross product ``(v1 - v0) x (v2 - v0)`` (computed in float64;
    zero for a degenerate triangle); ``uv`` interpolates the vertex texture coordinates.
    """
    prim = np.asarray(gbuf.prim_id)
    if prim.ndim != 2 or gbuf.bary.shape != prim.shape + (2,):
        raise UsageError("G-buffer prim_id must be (H, W) and bary (H, W, 2)")
    valid = prim >= 0
    h, w = prim.shape
    ids = prim[valid]
    bu = gbuf.bary[valid, 0].astype(np.float64)[:, None]
    bv = gbuf.bary[valid, 1].astype(np.float64)[:, None]
    bw = 1.0 - bu - bv
    corners = np.asarray(scene.triangles)[ids]
    verts = np.asarray(scene.vertices)
    v0 = verts[corners[:, 0]].astype(np.float64)
    v1 = verts[corners[:, 1]].astype(np.float64)
    v2 = verts[corners[:, 2]].astype(np.float64)
    position = np.full((h, w, 3), np.nan)
    position[valid] = bw * v0 + bu * v1 + bv * v2
    n = np.cross(v1 - v0, v2 - v0)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.divide(n, length, out=np.zeros_like(n), where=length > 0.0)
    normal = np.zeros((h, w, 3), np.float32)
    normal[valid] = n
    uvs = np.asarray(scene.uv)
    uv = np.zeros((h, w, 2), np.float32)
    if uvs.size:
        uv[valid] = (bw * uvs[corners[:, 0]] + bu * uvs[corners[:, 1]]
                     + bv * uvs[corners[:, 2]]).astype(np.float32)

    def per_pixel(values, fill, dtype):
        out = np.full((h, w), fill, dtype)
        out[valid] = np.asarray(values)[ids]
        return out

    return Surfaces(position_m=position, normal=normal,
                    obj_id=per_pixel(scene.tri_object, -1, np.int32),
                    material=per_pixel(scene.tri_material, -1, np.int32),
                    texture=per_pixel(scene.tri_texture, -1, np.int32), uv=uv,
                    cls=per_pixel(scene.tri_class, 0, np.uint8), valid=valid,
                    prim_id=prim, depth=np.asarray(gbuf.depth))


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
    dist, tri, u, v = intersect(scene, origins, directions, t_days, tmax)
    depth = np.where(tri >= 0, dist + start, np.inf).astype(np.float32)
    bary = np.stack([u, v], axis=-1).astype(np.float32).reshape(h, w, 2)
    return GBuffer(camera=camera, prim_id=tri.astype(np.int32).reshape(h, w), bary=bary,
                   depth=depth.reshape(h, w), stats={"method": "raycasting"})
