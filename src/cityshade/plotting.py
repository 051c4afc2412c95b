"""matplotlib, the optional ``[plot]`` extra: whether it is there and an Agg canvas to draw on.

A leaf module: nothing of cityshade is imported; matplotlib only inside the functions.
"""
from __future__ import annotations

from typing import Any

#: Why a plot or legend is missing when matplotlib is not installed.
NO_MATPLOTLIB = "plot skipped: matplotlib is not installed (pip install 'cityshade[plot]')"


def have_matplotlib() -> bool:
    """Whether the ``[plot]`` extra (matplotlib) is installed."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return False
    return True


def agg_canvas(width_px: int, height_px: int):
    """(Figure, FigureCanvasAgg) of ``width_px`` × ``height_px`` pixels: matplotlib's object API
    on an Agg canvas (no pyplot, no global backend state). Needs :func:`have_matplotlib`."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width_px / 100.0, height_px / 100.0), dpi=100)
    return fig, FigureCanvasAgg(fig)


def canvas_pixels(canvas) -> Any:
    """(H, W, 3) uint8 RGB of a drawn :func:`agg_canvas`."""
    import numpy as np

    canvas.draw()
    return np.array(canvas.buffer_rgba())[..., :3].copy()


