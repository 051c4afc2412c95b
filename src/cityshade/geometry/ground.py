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
from numba import njit

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.errors import UsageError
from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks

#: The plane extends this fraction of the model's horizontal diagonal beyond its bounding box:
#: enough for the shadows of the edge buildings at moderate sun, without painting the horizon.
GROUND_MARGIN_REL = 0.5
TERRAIN_CODE = SURFACE_CODE["terrain"]


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
    Returns a Surfaces object and the number of pixels filled; the input's ``position_m``,
    ``normal`` and ``cls`` are filled in place (the camera pass's own arrays) and its ``valid``
    and ``depth`` (the G-buffer's) are left as they were. Ground pixels have class
    ``terrain``, normal +z, object/primitive/material/texture -1. One pass over the rows (the
    numpy twin is ``tests/reference.py``'s ``reference_add_ground_plane``): the numpy form made
    seven full-frame arrays, 0.19 s of a 1M city's 2.1 Mpx map render.
    """
    valid = np.asarray(surfaces.valid)
    h, w = valid.shape
    lo, hi = ground_box_m(scene) if box_m is None else box_m
    margin = GROUND_MARGIN_REL * float(np.hypot(hi[0] - lo[0], hi[1] - lo[1]))
    limits = np.array([lo[0] - margin, hi[0] + margin, lo[1] - margin, hi[1] + margin,
                       float(z_m)])
    xs, ys = camera.screen_coordinates()
    right, up, fwd = camera.frame()
    frame = np.stack([right, up, fwd, np.asarray(camera.eye_m, np.float64)])
    new_valid = valid.copy()
    depth = np.array(surfaces.depth, copy=True)
    position = np.asarray(surfaces.position_m)
    normal = np.asarray(surfaces.normal)
    cls = np.asarray(surfaces.cls)
    run_chunks(_ground_rows, h, ROW_CHUNK, xs, ys, frame, limits, camera.kind != "map",
               new_valid, position, normal, cls, depth)
    new = dataclasses.replace(surfaces, position_m=position, normal=normal, cls=cls,
                              valid=new_valid, depth=depth)
    return new, int(np.count_nonzero(new_valid)) - int(np.count_nonzero(valid))


@njit(cache=True, nogil=True)
def _ground_rows(xs, ys, frame, limits, perspective, valid, position, normal, cls, depth,
                 r0, r1):
    # The float operations of the numpy form, in its order (the twin agrees bit for bit):
    # d = (x right + y up) + fwd, divided by sqrt((d0² + d1²) + d2²); t = (z - o_z) / d_z;
    # the point o + t d. A map's rays start at (x, y, eye z) and run along -z.
    terrain = np.uint8(TERRAIN_CODE)
    eye_z = frame[3, 2]
    z_m = limits[4]
    for r in range(r0, r1):
        for c in range(valid.shape[1]):
            if valid[r, c]:
                continue
            if perspective:
                d0 = xs[c] * frame[0, 0] + ys[r] * frame[1, 0] + frame[2, 0]
                d1 = xs[c] * frame[0, 1] + ys[r] * frame[1, 1] + frame[2, 1]
                d2 = xs[c] * frame[0, 2] + ys[r] * frame[1, 2] + frame[2, 2]
                norm = np.sqrt((d0 * d0 + d1 * d1) + d2 * d2)
                d0, d1, d2 = d0 / norm, d1 / norm, d2 / norm
                o0, o1 = frame[3, 0], frame[3, 1]
            else:
                d0, d1, d2 = 0.0, 0.0, -1.0
                o0, o1 = xs[c], ys[r]
            t = (z_m - eye_z) / d2
            if not (np.isfinite(t) and t > 0.0):
                continue
            p0 = o0 + t * d0
            p1 = o1 + t * d1
            if not (p0 >= limits[0] and p0 <= limits[1] and p1 >= limits[2]
                    and p1 <= limits[3]):
                continue
            valid[r, c] = True
            position[r, c, 0] = p0
            position[r, c, 1] = p1
            position[r, c, 2] = z_m  # exactly on the plane
            normal[r, c, 0] = 0.0
            normal[r, c, 1] = 0.0
            normal[r, c, 2] = 1.0
            cls[r, c] = terrain
            depth[r, c] = t if perspective else eye_z - z_m
