"""accel stage of cityshade: the 4-D (x, y, z, time) SAH kd-tree and its flat layout."""
from cityshade.errors import KdTreeInputError
from cityshade.accel.kdtree_layout import KdTree
from cityshade.accel.settings import KdTreeSettings

__all__ = ["KdTree", "KdTreeInputError", "KdTreeSettings", "build_kdtree", "model_time_range"]

#: The builder's functions, imported on first use: a command that only loads a tree (a render)
#: skips the builder's module and the set-up of its kernels (about 15 ms).
_BUILD_NAMES = ("build_kdtree", "model_time_range")


def __getattr__(name: str):
    if name in _BUILD_NAMES:
        from cityshade.accel import kdtree_build

        return getattr(kdtree_build, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
