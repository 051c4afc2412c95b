"""The kd-tree build's tunables (TOML table ``[kdtree]``), apart from the builder's kernels
(:mod:`cityshade.accel.kdtree_build`): every command reads its settings, few build a tree."""
from __future__ import annotations

import math
from dataclasses import dataclass

from cityshade.errors import ConfigError

#: Deepest tree the layout and the fixed traversal stack support (the stack holds one entry
#: per level, see ``cityshade.trace.kernels.STACK_SIZE``).
MAX_DEPTH_LIMIT = 60


@dataclass(frozen=True)
class KdTreeSettings:
    """Tunables of the kd-tree build (TOML table ``[kdtree]``).

    The defaults are the values measured fastest for our own traversal on the 1M-triangle
    synthetic city of ``benchmarks/raytrace.py`` (``--sweep-sah`` repeats the measurement;
    CPU time of one thread, camera and map shadow rays and camera closest hits, Nov 2026):
    intersection_cost 0.5-2.5 and empty_bonus 0-0.5 were tried. intersection_cost 0.7-1.5
    with a bonus of 0.1-0.2 are within the ~5 % noise of each other (camera shadow rays
    7.1-7.5 Mrays/s, map 2.1-2.4, closest hits 4.0-4.5); a bonus of 0.5 is 10-20 % slower.
    0.7 / 0.2 builds a third fewer nodes than 1.5 (1.37 M vs 2.04 M for 1 M triangles) at
    the same speed, so it is the default: traversal steps are memory-latency bound here and
    cost more than a ray/triangle test on a cached record.
    """

    #: Cost of one traversal step, relative to ``intersection_cost``.
    traversal_cost: float = 1.0
    #: Cost of one ray/triangle test.
    intersection_cost: float = 0.7
    #: Fraction of a split's cost forgiven when one child is empty: cutting off empty space
    #: lets rays skip it entirely, which the plain SAH under-rates.
    empty_bonus: float = 0.2
    #: Depth cap; 0 means automatic, ``round(8 + 1.3 log2 N)`` (pbrt's rule), never above 60.
    max_depth: int = 0
    #: A node with at most this many triangle references becomes a leaf without a split search.
    min_leaf_triangles: int = 1
    #: Nodes with more references than this choose their plane from ``bins`` bins per axis;
    #: smaller nodes run the exact sorted event sweep.
    sweep_threshold: int = 2048
    #: Number of bins per axis in binned nodes.
    bins: int = 32
    #: Nodes with at most this many references are built as independent subtrees, several
    #: at once (one per Numba thread), and stitched back in depth-first order: the tree is
    #: the one a single-threaded build makes, whatever the thread count. 0 means automatic,
    #: ``max(references / 64, 4096)``: enough subtrees to keep two cores busy to the end,
    #: few enough that the serial top of the tree stays a small part of the build.
    subtree_refs: int = 0

    def __post_init__(self) -> None:
        for name in ("traversal_cost", "intersection_cost"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ConfigError(f"kdtree {name} must be a finite number > 0, not {value}")
        if not (0.0 <= self.empty_bonus < 1.0):
            raise ConfigError(f"kdtree empty_bonus must be in [0, 1), not {self.empty_bonus}")
        if not (0 <= self.max_depth <= MAX_DEPTH_LIMIT):
            raise ConfigError(f"kdtree max_depth must be in [0, {MAX_DEPTH_LIMIT}] "
                              f"(0 = automatic), not {self.max_depth}")
        if self.min_leaf_triangles < 0:
            raise ConfigError("kdtree min_leaf_triangles must be >= 0, "
                              f"not {self.min_leaf_triangles}")
        if self.sweep_threshold < 0:
            raise ConfigError(f"kdtree sweep_threshold must be >= 0, not {self.sweep_threshold}")
        if not (2 <= self.bins <= 4096):
            raise ConfigError(f"kdtree bins must be in [2, 4096], not {self.bins}")
        if self.subtree_refs < 0:
            raise ConfigError(f"kdtree subtree_refs must be >= 0 (0 = automatic), "
                              f"not {self.subtree_refs}")

    def depth_cap(self, n_triangles: int) -> int:
        """Depth cap for ``n_triangles`` triangles (resolves ``max_depth = 0``)."""
        if self.max_depth > 0:
            return self.max_depth
        auto = int(round(8 + 1.3 * math.log2(max(n_triangles, 1))))
        return min(auto, MAX_DEPTH_LIMIT)

    def subtree_cap(self, n_references: int) -> int:
        """Largest node built as an independent subtree (resolves ``subtree_refs = 0``)."""
        if self.subtree_refs > 0:
            return self.subtree_refs
        return max(n_references // 64, 4096)
