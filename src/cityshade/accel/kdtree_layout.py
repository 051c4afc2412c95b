"""Flat layout of the 4-D kd-tree: 8-byte nodes, leaf-ordered primitive list, triangle records.

Node layout (``nodes``, shape (M, 2), uint32), after the thesis slides' "flat kd-tree with
8 bytes/node":

* word 0: bits 0-2 hold the axis (0 x, 1 y, 2 z, 3 time) or 4 for a leaf; bits 3-31 hold, for
  an inner node, the index of its right child (the left child is always the next node, i + 1),
  and for a leaf, its number of triangle references.
* word 1: for an inner node, the float32 bits of the split position (metres, or days since
  1970-01-01 UTC for a time split: rays at time ``t < split`` go left); for a leaf, the index of
  its first entry in ``prim_indices`` / ``tri_records``.

Triangle records (``tri_records``, shape (K, 16), float32; one 64-byte cache line each) are
stored in leaf order so traversal never chases vertex indices:

* columns 0-8: the three vertices (v0 x, y, z, v1 x, y, z, v2 x, y, z), float32, render space;
* column 9: the triangle id (int32 bits);
* columns 10-11 and 12-13: validity begin and end (float64 bits, days; -inf/+inf for open);
* column 14: material (int32 bits); column 15: zero padding.

This module is the one place that knows the layout: the constants and the inline decoders
below are what the build, the tracing kernels and the rasterizer's walk use, and
:attr:`KdTree.views` hands the kernels the tree as one :class:`KdViews` tuple.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from numba import njit

from cityshade.errors import KdTreeLayoutError
from cityshade.runtime.interpret import run_range, twin_if

#: Number of float32 words of one triangle record (64 bytes: one cache line).
RECORD_WORDS = 16
#: Column of the triangle id in the int32 view of the records.
REC_ID = 9
#: Columns of validity begin / end in the float64 view (byte offsets 40 and 48).
REC_T_BEGIN64 = 5
REC_T_END64 = 6
#: Column of the material in the int32 view.
REC_MATERIAL = 14
#: Axis code of a time split in word 0 of a node (0, 1, 2 are x, y, z).
TIME_AXIS = 3
#: Axis code of a leaf in word 0 of a node.
LEAF_CODE = 4
#: Bits of word 0 that hold the axis code.
AXIS_BITS = 3
#: Mask of those bits.
AXIS_MASK = (1 << AXIS_BITS) - 1
#: Arrays written to and read from the cache, in this order.
ARRAY_NAMES = ("kdtree_nodes", "kdtree_prim_indices", "kdtree_tri_records", "kdtree_bounds")


class KdViews(NamedTuple):
    """The flat tree as the kernels take it: views of the same memory, no copies."""

    #: (M, 2) uint32 node words.
    nodes: np.ndarray
    #: (M, 2) float32 view of ``nodes`` (column 1: split of inner nodes).
    splits: np.ndarray
    #: (K,) int32 triangle ids in leaf order.
    prim_indices: np.ndarray
    #: (K, 16) float32 triangle records.
    recs: np.ndarray
    #: (K, 8) float64 view of the records (validity).
    recs_f64: np.ndarray
    #: (K, 16) int32 view of the records (triangle id, material).
    recs_i32: np.ndarray


# --- inline decoders for the kernels (word 0 is read as int64 so shifts stay unsigned) -------

@njit(cache=True, inline="always")
def node_word(tree, node):
    """Word 0 of ``node`` as int64 (axis code and payload)."""
    return np.int64(tree.nodes[node, 0])


@njit(cache=True, inline="always")
def word_axis(w0):
    """Axis code of a node word: 0-2 x, y, z, ``TIME_AXIS``, or ``LEAF_CODE``."""
    return w0 & AXIS_MASK


@njit(cache=True, inline="always")
def word_payload(w0):
    """Right child of an inner node, or the reference count of a leaf."""
    return w0 >> AXIS_BITS


@njit(cache=True, inline="always")
def leaf_first(tree, node):
    """Index of a leaf's first entry in ``prim_indices`` / the records."""
    return np.int64(tree.nodes[node, 1])


@njit(cache=True, inline="always")
def node_split(tree, node):
    """Split position of an inner node (metres, or days for a time split)."""
    return np.float64(tree.splits[node, 1])


@njit(cache=True, inline="always")
def record_present(tree, k, t_days):
    """Whether the triangle of record ``k`` stands at ``t_days`` (``begin <= t < end``)."""
    return tree.recs_f64[k, REC_T_BEGIN64] <= t_days < tree.recs_f64[k, REC_T_END64]


@njit(cache=True, inline="always")
def record_id(tree, k):
    """Triangle id of record ``k``."""
    return tree.recs_i32[k, REC_ID]


def pack_nodes(axis, child, first, split, interpret=False):
    """Pack raw build output into (M, 2) uint32 nodes (see the module docstring).

    Parameters
    ----------
    axis : (M,) int array
        0-3 for inner nodes (x, y, z, time), 4 for leaves.
    child : (M,) int array
        Right-child index of inner nodes; reference count of leaves.
    first : (M,) int array
        First primitive index of leaves (ignored for inner nodes).
    split : (M,) float array
        Split position of inner nodes, exactly float32-representable.
    interpret : bool
        Run the kernel's Python source (a small build on first use, runtime/interpret.py).
    """
    axis = np.asarray(axis, dtype=np.int64)
    child = np.asarray(child, dtype=np.int64)
    if child.size and child.max() >= 2 ** (32 - AXIS_BITS):
        raise KdTreeLayoutError("kd-tree too large for the 8-byte node layout")
    nodes = np.empty((axis.size, 2), np.uint32)
    split_bits = np.ascontiguousarray(split, dtype=np.float32).view(np.uint32)
    twin_if(interpret, _pack_kernel)(axis, child, np.asarray(first, dtype=np.int64), split_bits,
                                     nodes)
    return nodes


@njit(cache=True)
def _pack_kernel(axis, child, first, split_bits, nodes):
    # One pass (numpy's shifted, cast and selected temporaries took 0.76 s for 10.5 M nodes).
    for i in range(axis.shape[0]):
        nodes[i, 0] = np.uint32((child[i] << AXIS_BITS) | axis[i])
        nodes[i, 1] = np.uint32(first[i]) if axis[i] == LEAF_CODE else split_bits[i]


#: Records per call of :func:`_fill_records` (some 0.5-1 ms of work per chunk).
RECORD_CHUNK = 1 << 16


@njit(cache=True, nogil=True)
def _fill_records(vertices, triangles, t_begin_days, t_end_days, material, prim_indices, recs,
                  recs_i32, recs_f64, k0, k1):
    """Every word of the records ``k0 .. k1`` of ``prim_indices`` (three views of one array,
    disjoint words); one pass, no gathered temporaries. A serial kernel over chunks on the
    thread pool, not a ``prange`` one: that took 2-3x longer to compile on first use."""
    for k in range(np.uint64(k0), np.uint64(k1)):  # unsigned: no negative-index wraparound
        t = prim_indices[k]
        for i in range(3):
            v = triangles[t, i]
            for c in range(3):
                recs[k, 3 * i + c] = vertices[v, c]
        recs_i32[k, REC_ID] = t
        recs_f64[k, REC_T_BEGIN64] = t_begin_days[t]
        recs_f64[k, REC_T_END64] = t_end_days[t]
        recs_i32[k, REC_MATERIAL] = material[t]
        recs_i32[k, RECORD_WORDS - 1] = 0


def triangle_records(vertices, triangles, t_begin_days, t_end_days, material, prim_indices,
                     interpret=False):
    """Leaf-ordered (K, 16) float32 intersection records for ``prim_indices`` (``interpret``:
    the kernel's Python source, see :func:`pack_nodes`)."""
    records = np.empty((prim_indices.size, RECORD_WORDS), np.float32)
    run_range(_fill_records, interpret, prim_indices.size, RECORD_CHUNK,
              np.ascontiguousarray(vertices, dtype=np.float32), triangles, t_begin_days,
              t_end_days, material, prim_indices, records, records.view(np.int32),
              records.view(np.float64))
    return records


@dataclass(frozen=True, eq=False)
class KdTree:
    """A built 4-D kd-tree in its flat layout; the arrays may be read-only memory maps.

    Attributes
    ----------
    nodes : (M, 2) uint32
        Packed nodes; node 0 is the root (layout in the module docstring).
    prim_indices : (K,) int32
        Triangle ids in leaf order; inside each leaf sorted by material, then id.
    tri_records : (K, 16) float32
        Intersection records in the same order (layout in the module docstring).
    bounds : (2, 4) float64
        Scene box: rows min, max; columns x, y, z (metres) and t (days, the finite time range
        used by the heuristic; ``[0, 0]`` for a model without dates).
    stats : dict
        Build statistics: ``triangles_in``, ``triangles_valid``, ``references``, ``duplication``,
        ``nodes``, ``leaves``, ``empty_leaves``, ``max_depth``, ``mean_depth``,
        ``mean_leaf_triangles``, ``sah_cost``, ``time_splits``, ``has_time``, ``depth_cap``,
        ``build_s``.
    """

    nodes: np.ndarray
    prim_indices: np.ndarray
    tri_records: np.ndarray
    bounds: np.ndarray
    stats: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        nodes = self.nodes
        if nodes.ndim != 2 or nodes.shape[1] != 2 or nodes.dtype != np.uint32 or nodes.shape[0] < 1:
            raise KdTreeLayoutError(f"kd-tree nodes must be (M >= 1, 2) uint32, not {nodes.shape} "
                             f"{nodes.dtype}")
        recs = self.tri_records
        if recs.ndim != 2 or recs.shape[1] != RECORD_WORDS or recs.dtype != np.float32:
            raise KdTreeLayoutError(f"kd-tree records must be (K, {RECORD_WORDS}) float32")
        if self.prim_indices.shape != (recs.shape[0],):
            raise KdTreeLayoutError("kd-tree prim_indices and records differ in length")
        if self.bounds.shape != (2, 4):
            raise KdTreeLayoutError("kd-tree bounds must have shape (2, 4)")
        for name in ("nodes", "tri_records"):
            if not getattr(self, name).flags.c_contiguous:
                object.__setattr__(self, name, np.ascontiguousarray(getattr(self, name)))

    # Views of the same memory for the kernels (no copies; fine on read-only memory maps).
    @property
    def node_words(self) -> np.ndarray:
        """(M, 2) uint32 node words."""
        return self.nodes

    @property
    def node_splits(self) -> np.ndarray:
        """(M, 2) float32 view of the nodes; column 1 is the split of inner nodes."""
        return self.nodes.view(np.float32)

    @property
    def records_f64(self) -> np.ndarray:
        """(K, 8) float64 view of the records (columns 5, 6: validity begin, end)."""
        return self.tri_records.view(np.float64)

    @property
    def records_i32(self) -> np.ndarray:
        """(K, 16) int32 view of the records (column 9: triangle id, 14: material)."""
        return self.tri_records.view(np.int32)

    @property
    def views(self) -> KdViews:
        """The tree as the kernels take it (one tuple of views)."""
        return KdViews(self.nodes, self.node_splits, self.prim_indices, self.tri_records,
                       self.records_f64, self.records_i32)

    def box_scale_m(self) -> tuple[np.ndarray, np.ndarray, float]:
        """(box min (3,), box max (3,), scale) in metres, float64: the scale is the larger of the
        box's longest side and its largest coordinate magnitude (at least 1 m), the size that
        float32 rounding errors are relative to (paddings of culling and ray boxes)."""
        lo = np.asarray(self.bounds[0, :3], np.float64)
        hi = np.asarray(self.bounds[1, :3], np.float64)
        return lo, hi, max(float(np.max(hi - lo)), float(np.max(np.abs(np.r_[lo, hi]))), 1.0)

    @property
    def has_time(self) -> bool:
        """Whether the model has any finite validity date."""
        return bool(self.bounds[1, 3] > self.bounds[0, 3])

    def to_arrays(self) -> dict[str, np.ndarray]:
        """The arrays to store in the cache file, by name (see ``ARRAY_NAMES``)."""
        return dict(zip(ARRAY_NAMES, (self.nodes, self.prim_indices, self.tri_records,
                                      self.bounds)))

    @classmethod
    def from_arrays(cls, arrays, stats: dict | None = None) -> "KdTree":
        """Rebuild a tree from ``to_arrays()`` output (arrays may be read-only memory maps)."""
        missing = [name for name in ARRAY_NAMES if name not in arrays]
        if missing:
            raise KdTreeLayoutError(f"kd-tree arrays missing: {', '.join(missing)}")
        return cls(nodes=arrays["kdtree_nodes"], prim_indices=arrays["kdtree_prim_indices"],
                   tri_records=arrays["kdtree_tri_records"], bounds=arrays["kdtree_bounds"],
                   stats=dict(stats or {}))

    def unpack(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Decoded nodes: (axis (M,) int, child-or-count (M,) int, split-or-first (M,)).

        ``split-or-first`` is float64: the split of inner nodes, the first index of leaves.
        """
        w0 = self.nodes[:, 0].astype(np.int64)
        axis = w0 & AXIS_MASK
        child = w0 >> AXIS_BITS
        second = np.where(axis == LEAF_CODE, self.nodes[:, 1].astype(np.float64),
                          self.node_splits[:, 1].astype(np.float64))
        return axis, child, second
