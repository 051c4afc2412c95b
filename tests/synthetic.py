"""Seeded synthetic geometry shared by the tests of several packages."""
from __future__ import annotations

import numpy as np

from cityshade.accel import build_kdtree

BOX_FACES = np.array([(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
                      (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)])


def box_city(n_boxes, seed=0, dated=True, extent_m=300.0):
    """Seeded random boxes (12 triangles each, outward winding) with random validity intervals.

    Returns vertices (V, 3) float32, triangles (T, 3) int32, begin, end (T,) float64 days,
    material (T,) int32. About a third of the boxes have an open begin, 60 % an open end.
    """
    rng = np.random.default_rng(seed)
    corners = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                        (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], np.float64)
    lo = np.column_stack([rng.uniform(0, extent_m, (n_boxes, 2)), rng.normal(0, 1, n_boxes)])
    size = np.column_stack([rng.uniform(3, 20, (n_boxes, 2)), rng.uniform(3, 40, n_boxes)])
    verts = (lo[:, None, :] + corners[None] * size[:, None, :]).reshape(-1, 3)
    tris = (BOX_FACES[None] + 8 * np.arange(n_boxes)[:, None, None]).reshape(-1, 3)
    begin = np.full(n_boxes, -np.inf)
    end = np.full(n_boxes, np.inf)
    if dated:
        has_begin = rng.random(n_boxes) > 0.33
        begin[has_begin] = np.round(rng.uniform(-20000, 20000, has_begin.sum()))
        has_end = rng.random(n_boxes) > 0.6
        end[has_end] = np.where(np.isfinite(begin[has_end]), begin[has_end], -20000) \
            + np.round(rng.uniform(100, 20000, has_end.sum()))
    material = rng.integers(-1, 4, n_boxes)
    return (verts.astype(np.float32), tris.astype(np.int32), np.repeat(begin, 12),
            np.repeat(end, 12), np.repeat(material, 12).astype(np.int32))


def unit(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def closed_box_tree(lo=(1.0, 2.0, 3.0), size=(4.0, 5.0, 6.0), rotation_seed=None):
    corners = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                        (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], np.float64)
    verts = np.asarray(lo) + corners * np.asarray(size)
    if rotation_seed is not None:
        q, _ = np.linalg.qr(np.random.default_rng(rotation_seed).normal(size=(3, 3)))
        verts = verts @ q.T * 3.7 + 1234.5
    verts = verts.astype(np.float32)
    n = 12
    tree = build_kdtree(verts, BOX_FACES.astype(np.int32), np.full(n, -np.inf),
                        np.full(n, np.inf), np.zeros(n, np.int32))
    return verts, tree


def edge_and_vertex_targets(verts, triangles, fractions=(0.5, 0.25, 1 / 3, 0.9)):
    """Every vertex and points on every edge of a mesh (float64)."""
    v = verts.astype(np.float64)
    targets = [v]
    for a, b, c in triangles:
        for i, j in ((a, b), (b, c), (c, a)):
            for f in fractions:
                targets.append([(1 - f) * v[i] + f * v[j]])
    return np.vstack(targets)
