"""Transmission of sun rays through vegetation crowns in the sun's light plane (``izb``).

The same idea as the opaque engine (docs/DESIGN.md §7): all rays share the sun direction, so
in the watertight test's sheared frame a ray from o can meet a triangle only where o's
light-plane point lies in the triangle's projection. The crowns' triangles are binned by their
light-plane boxes (widened by :data:`cityshade.lightspace.MARGIN_REL` of the coordinate
magnitude, the same margin and argument as the opaque engine's box) into a grid over the
receivers' points; each receiver tests its cell's triangles with the same watertight test as
``raytrace`` (:func:`cityshade.trace.kernels.hit_triangle`, the same float32 vertices as the
tree's records) at ``t >= 0``, collects the distinct crowns, and multiplies their
transmissivities in ascending crown order (:func:`cityshade.trace.vegetation.crown_product`):
``raytrace``'s answer, bit for bit.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from cityshade.trace.kernels import hit_triangle, on_axes, ray_shear
from cityshade.trace.vegetation import CROWN_SET, add_crown, crown_product, has_crown

#: Target receivers per grid cell, and the largest grid side.
RECEIVERS_PER_CELL = 4
MAX_GRID_SIDE = 2048


@njit(cache=True)
def _project(origins, rays, kx, ky, kz, sx, sy, px, py):
    """The rays' light-plane points ``px``, ``py``; returns their box (x0, x1, y0, y1) and
    the largest coordinate magnitude of their origins (one pass: no gathered copies)."""
    x0 = y0 = np.inf
    x1 = y1 = -np.inf
    magnitude = 0.0
    for j in range(rays.shape[0]):
        i = rays[j]
        okx, oky, okz = on_axes(origins[i, 0], origins[i, 1], origins[i, 2], kx, ky, kz)
        px[j] = okx - sx * okz
        py[j] = oky - sy * okz
        x0 = min(x0, px[j])
        x1 = max(x1, px[j])
        y0 = min(y0, py[j])
        y1 = max(y1, py[j])
        magnitude = max(magnitude, abs(origins[i, 0]), abs(origins[i, 1]), abs(origins[i, 2]))
    return x0, x1, y0, y1, magnitude


@njit(cache=True)
def _triangle_cells(vertices, triangles, t_begin, t_end, t_days, kx, ky, kz, sx, sy, margin,
                    x0, y0, inv_cell, nx, ny, c_lo, c_hi, boxes):
    """Per triangle its widened light-plane box ``boxes`` (xmin, xmax, ymin, ymax) and its
    cell range ``c_lo``/``c_hi`` (ix0, iy0) / (ix1, iy1), empty (lo > hi) when not standing
    or outside the grid."""
    for t in range(triangles.shape[0]):
        c_lo[t, 0] = 1
        c_lo[t, 1] = 1
        c_hi[t, 0] = 0
        c_hi[t, 1] = 0
        if not (t_begin[t] <= t_days < t_end[t]):
            continue
        xmin = np.inf
        xmax = -np.inf
        ymin = np.inf
        ymax = -np.inf
        for c in range(3):
            v = triangles[t, c]
            vx = np.float64(vertices[v, kx])
            vy = np.float64(vertices[v, ky])
            vz = np.float64(vertices[v, kz])
            qx = vx - sx * vz
            qy = vy - sy * vz
            xmin = min(xmin, qx)
            xmax = max(xmax, qx)
            ymin = min(ymin, qy)
            ymax = max(ymax, qy)
        boxes[t, 0] = xmin - margin
        boxes[t, 1] = xmax + margin
        boxes[t, 2] = ymin - margin
        boxes[t, 3] = ymax + margin
        ix0 = math.floor((xmin - margin - x0) * inv_cell)
        ix1 = math.floor((xmax + margin - x0) * inv_cell)
        iy0 = math.floor((ymin - margin - y0) * inv_cell)
        iy1 = math.floor((ymax + margin - y0) * inv_cell)
        if ix1 < 0 or iy1 < 0 or ix0 >= nx or iy0 >= ny:
            continue
        c_lo[t, 0] = max(ix0, 0)
        c_lo[t, 1] = max(iy0, 0)
        c_hi[t, 0] = min(ix1, nx - 1)
        c_hi[t, 1] = min(iy1, ny - 1)


@njit(cache=True)
def _bin(c_lo, c_hi, nx, ny):
    """Cell lists (CSR): ``start`` (nx·ny + 1,), ``items`` the triangles in ascending order."""
    count = np.zeros(nx * ny + 1, np.int64)
    for t in range(c_lo.shape[0]):
        for iy in range(c_lo[t, 1], c_hi[t, 1] + 1):
            for ix in range(c_lo[t, 0], c_hi[t, 0] + 1):
                count[iy * nx + ix + 1] += 1
    for c in range(nx * ny):
        count[c + 1] += count[c]
    items = np.empty(count[nx * ny], np.int32)
    fill = count[:-1].copy()
    for t in range(c_lo.shape[0]):
        for iy in range(c_lo[t, 1], c_hi[t, 1] + 1):
            for ix in range(c_lo[t, 0], c_hi[t, 0] + 1):
                c = iy * nx + ix
                items[fill[c]] = t
                fill[c] += 1
    return count, items


@njit(cache=True, parallel=True)
def _query(vertices, triangles, tri_crown, crown_tau, origins, rays, px, py, x0, y0, inv_cell,
           nx, ny, start, items, boxes, kx, ky, kz, sx, sy, sz, out):
    n = rays.shape[0]
    chunk = 256
    for b in prange((n + chunk - 1) // chunk):
        seen = np.empty(CROWN_SET, np.int32)
        for j in range(b * chunk, min(n, (b + 1) * chunk)):
            i = rays[j]
            okx, oky, okz = on_axes(origins[i, 0], origins[i, 1], origins[i, 2], kx, ky, kz)
            ix = min(max(math.floor((px[j] - x0) * inv_cell), 0), nx - 1)
            iy = min(max(math.floor((py[j] - y0) * inv_cell), 0), ny - 1)
            c = iy * nx + ix
            m = 0
            for e in range(start[c], start[c + 1]):
                t = items[e]
                # Outside the widened box: no hit (the cells' own argument, per triangle).
                if px[j] < boxes[t, 0] or px[j] > boxes[t, 1] or py[j] < boxes[t, 2] or \
                        py[j] > boxes[t, 3]:
                    continue
                crown = tri_crown[t]
                if has_crown(seen, m, crown):
                    continue  # met already: its other triangles cannot change the set
                hit, tt, _, _ = hit_triangle(vertices, triangles, t, okx, oky, okz, kx, ky, kz,
                                             sx, sy, sz)
                if hit and tt >= 0.0:
                    seen, m = add_crown(seen, m, crown)
            out[i] = crown_product(seen, m, crown_tau)


def transmission(vertices, triangles, t_begin_days, t_end_days, tri_crown, crown_tau, origins,
                 direction, t_days, rays, out, margin_rel: float) -> None:
    """Fill ``out[rays]`` with the transmission of those sun rays through the crowns
    ``triangles`` (vertex indices into ``vertices`` (V, 3) float32; validity ``[begin, end)``;
    ``tri_crown`` the crown of each; ``crown_tau`` (C,) the transmissivity of each crown).
    ``origins`` (N, 3) float64, ``direction`` (3,) unit, one for every ray; ``margin_rel``
    the boxes' widening per metre of coordinate magnitude."""
    rays = np.ascontiguousarray(rays, dtype=np.int64)
    if len(rays) == 0:
        return
    kx, ky, kz, sx, sy, sz = ray_shear(*(float(c) for c in direction))
    px = np.empty(len(rays))
    py = np.empty(len(rays))
    x0, x1, y0, y1, ray_magnitude = _project(origins, rays, kx, ky, kz, sx, sy, px, py)
    magnitude = max(ray_magnitude, float(np.abs(vertices).max()) if len(vertices) else 0.0,
                    1.0)
    margin = margin_rel * magnitude * (1.0 + max(abs(sx), abs(sy)))
    side = max(x1 - x0, y1 - y0, 1e-6)
    cells = max(1, min(MAX_GRID_SIDE, int(math.sqrt(len(rays) / RECEIVERS_PER_CELL))))
    cell = side / cells * (1.0 + 1e-9)
    nx = max(1, min(MAX_GRID_SIDE, int((x1 - x0) / cell) + 1))
    ny = max(1, min(MAX_GRID_SIDE, int((y1 - y0) / cell) + 1))
    inv_cell = 1.0 / cell
    c_lo = np.empty((len(triangles), 2), np.int64)
    c_hi = np.empty((len(triangles), 2), np.int64)
    boxes = np.empty((len(triangles), 4))
    _triangle_cells(vertices, triangles, t_begin_days, t_end_days, float(t_days), kx, ky, kz,
                    sx, sy, margin, x0, y0, inv_cell, nx, ny, c_lo, c_hi, boxes)
    start, items = _bin(c_lo, c_hi, nx, ny)
    _query(vertices, triangles, tri_crown, np.ascontiguousarray(crown_tau, np.float64), origins,
           rays, px, py, x0, y0, inv_cell, nx, ny, start, items, boxes, kx, ky, kz, sx, sy, sz, out)
