"""accel stage of cityshade: the 4-D (x, y, z, time) SAH kd-tree and its flat layout."""
from cityshade.errors import KdTreeInputError
from cityshade.accel.kdtree_build import KdTreeSettings, build_kdtree, model_time_range
from cityshade.accel.kdtree_layout import KdTree

__all__ = ["KdTree", "KdTreeInputError", "KdTreeSettings", "build_kdtree", "model_time_range"]
