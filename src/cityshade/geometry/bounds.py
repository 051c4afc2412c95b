"""Bounding boxes of the triangles a scene uses (kernels over the flat arrays)."""
from __future__ import annotations

import numpy as np
from numba import njit

from cityshade.runtime.interpret import InterpretBudget, twin_if


@njit(cache=True, inline="always")
def _take(out, v, a):
    """Widen ``out``'s axis ``a`` to the value ``v`` (a NaN bound sticks, as numpy's min/max:
    no comparison with it is true)."""
    if v < out[0, a] or v != v:
        out[0, a] = v
    if v > out[1, a] or v != v:
        out[1, a] = v


@njit(cache=True)
def used_vertex_box(triangles, vertices, out):
    """``out`` (2, 3) float64: min and max of the vertices the triangles use (NaN where one
    is NaN, as numpy's min/max). One pass over the index array: no sorted copy of it, no
    float64 copy of the vertices (``np.unique`` of the 10^7-triangle city's 30 M indices took
    21 s and left 0.4 GB of freed heap resident)."""
    for a in range(3):
        out[0, a] = np.inf
        out[1, a] = -np.inf
    for t in range(triangles.shape[0]):
        for c in range(3):
            i = triangles[t, c]
            for a in range(3):
                _take(out, np.float64(vertices[i, a]), a)


@njit(cache=True)
def all_vertex_box(vertices, out):
    """``out`` (2, 3) float64: min and max of every vertex (NaN where one is NaN, as numpy's
    min/max), in one pass: numpy's per-column min and max over the memory-mapped (V, 3) array
    took 32 ms each on the 1M-triangle city (1.2 M vertices), a tenth of its map's camera
    pass."""
    for a in range(3):
        out[0, a] = np.inf
        out[1, a] = -np.inf
    for i in range(vertices.shape[0]):
        for a in range(3):
            _take(out, np.float64(vertices[i, a]), a)


#: Triangles a process boxes through the kernel's Python source while it is neither compiled
#: nor cached (:mod:`cityshade.runtime.interpret`): 6.6 µs a triangle interpreted against
#: 0.17-0.25 s to compile (Dec 2026, 10^5 random triangles).
INTERPRET_BOX = InterpretBudget(30_000, used_vertex_box)
#: The same for :func:`all_vertex_box`, in vertices (a third of a triangle's reads).
INTERPRET_ALL_BOX = InterpretBudget(90_000, all_vertex_box)


def vertex_box(triangles, vertices) -> np.ndarray:
    """(2, 3) float64 min and max of the vertices ``triangles`` use (:func:`used_vertex_box`,
    interpreted while the work of a first use is small)."""
    box = np.empty((2, 3))
    twin_if(INTERPRET_BOX.take(len(triangles)), used_vertex_box)(triangles, vertices, box)
    return box


def all_vertices_box(vertices) -> np.ndarray:
    """(2, 3) float64 min and max of every vertex (:func:`all_vertex_box`, interpreted while
    the work of a first use is small)."""
    box = np.empty((2, 3))
    twin_if(INTERPRET_ALL_BOX.take(len(vertices)), all_vertex_box)(vertices, box)
    return box
