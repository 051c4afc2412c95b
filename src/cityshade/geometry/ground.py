"""An optional flat ground plane for models without terrain (docs/DESIGN.md §10).

Most real files have no terrain: a map of the TUM campus is mostly empty pixels, and shadows
fall on nothing. ``--ground`` adds a horizontal plane that receives shadows (it casts none and
never hides the model's own surfaces: it only fills pixels where no surface was drawn).

Modes
-----
``min``  the lowest point of the model — safe, but buildings standing higher get shadows that are
         too long (their real ground is higher);
``auto`` the median over objects of each object's lowest point — the typical ground level;
a number: the plane's height in the model CRS (metres).
The mode and the height used go into every output's metadata.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.errors import UsageError

#: The plane extends this fraction of the model's horizontal diagonal beyond its bounding box:
#: enough for the shadows of the edge buildings at moderate sun, without painting the horizon.
GROUND_MARGIN_REL = 0.5


def ground_height_m(scene, mode: str) -> float:
    """Render-space z of the ground plane for ``mode`` ("min", "auto" or a CRS height)."""
    if scene.is_tiled and mode in ("min", "auto"):  # a view of some tiles: the whole city's
        return float(scene.tiling.source.ground_m[mode])
    # float32 heights: their minima cast to float64 are the same numbers, without the float64
    # copies of every vertex and triangle corner (1.0 GB for the 10^7-triangle city).
    z = np.asarray(scene.vertices)[:, 2]
    if mode == "min":
        return float(z.min())
    if mode == "auto":
        tris = np.asarray(scene.triangles)
        tri_z = np.minimum(np.minimum(z[tris[:, 0]], z[tris[:, 1]]), z[tris[:, 2]])
        tri_z = tri_z.astype(np.float64)
        tri_object = np.asarray(scene.tri_object)
        # Trees left out (when anything else is there): the plane is the same with and
        # without vegetation (--no-vegetation), so the two runs compare the same pixels.
        from cityshade.geometry.vegetation import vegetation_mask

        crowns = vegetation_mask(scene)
        if crowns.any() and not crowns.all():
            tri_z, tri_object = tri_z[~crowns], tri_object[~crowns]
        lowest = np.full(len(scene.obj_ids), np.inf)
        np.minimum.at(lowest, tri_object, tri_z)
        return float(np.median(lowest[np.isfinite(lowest)]))
    try:
        return float(mode) - float(scene.origin_m[2])
    except ValueError:
        raise UsageError(f"--ground must be min, auto or a height in metres, not {mode!r}") from None


def ground_box_m(scene) -> tuple[np.ndarray, np.ndarray]:
    """(lo (3,), hi (3,)) float64: the box the ground plane is limited to (the whole city's for
    a view of some tiles)."""
    return scene.city_box_m()


def add_ground_plane(scene, camera, surfaces, z_m: float, box_m=None):
    """Fill the pixels without surface where the view ray meets the plane ``z = z_m``.

    ``box_m`` is :func:`ground_box_m` when already known (the strips of one frame compute it
    once: a pass over every vertex was 0.75 s per strip of the 10^7-triangle city's map).
    Returns a new Surfaces object (the input is not modified) and the number of pixels filled.
    Ground pixels have class ``terrain``, normal +z, object/primitive/material/texture -1.
    """
    valid = np.asarray(surfaces.valid)
    h, w = valid.shape
    origins, directions = camera.primary_rays()
    origins = origins.reshape(h, w, 3)
    directions = directions.reshape(h, w, 3)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (z_m - origins[..., 2]) / directions[..., 2]
    point = origins + t[..., None] * directions
    lo, hi = ground_box_m(scene) if box_m is None else box_m
    margin = GROUND_MARGIN_REL * float(np.hypot(hi[0] - lo[0], hi[1] - lo[1]))
    inside = ((point[..., 0] >= lo[0] - margin) & (point[..., 0] <= hi[0] + margin)
              & (point[..., 1] >= lo[1] - margin) & (point[..., 1] <= hi[1] + margin))
    fill = ~valid & np.isfinite(t) & (t > 0) & inside
    position = np.array(surfaces.position_m, dtype=np.float64, copy=True)
    position[fill] = point[fill]
    position[fill, 2] = z_m  # exactly on the plane
    normal = np.array(surfaces.normal, copy=True)
    normal[fill] = (0.0, 0.0, 1.0)
    cls = np.array(surfaces.cls, copy=True)
    cls[fill] = SURFACE_CODE["terrain"]
    depth = np.array(surfaces.depth, copy=True)
    if camera.kind == "map":
        depth[fill] = (origins[..., 2] - z_m)[fill]
    else:
        depth[fill] = t[fill]
    new = dataclasses.replace(surfaces, position_m=position, normal=normal, cls=cls,
                              valid=valid | fill, depth=depth)
    return new, int(fill.sum())
