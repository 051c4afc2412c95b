"""Golden-image comparison for regression tests (DESIGN §13.4).

A test renders a small image and calls :func:`assert_matches_golden`. The metric is the share of
pixels where any channel differs by more than ``tolerance_levels`` (out of 255); it must not
exceed ``max_fraction``. On failure the rendered, reference and difference images are written
to ``test_output/`` and their paths are in the assertion message. Goldens change only through
the documented command::

    python tests/golden/regenerate.py
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

GOLDEN_DIR = Path(__file__).resolve().parent / "golden"
OUTPUT_DIR = Path(__file__).resolve().parents[1] / "test_output"


def difference_image(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Amplified absolute difference (×8, clipped), grey where equal, red where different."""
    diff = np.abs(a.astype(np.int16) - b.astype(np.int16)).max(axis=-1)
    out = np.full(a.shape[:2] + (3,), 40, np.uint8)
    hot = diff > 0
    out[hot, 0] = np.clip(64 + diff[hot] * 8, 0, 255).astype(np.uint8)
    out[hot, 1] = 0
    out[hot, 2] = 0
    return out


def assert_matches_golden(name: str, rendered: np.ndarray, tolerance_levels: int = 2,
                          max_fraction: float = 0.001) -> None:
    """Compare an 8-bit (H, W, C) image with ``tests/golden/<name>.png``."""
    from cityshade.imageio import read_image, write_image

    golden_path = GOLDEN_DIR / f"{name}.png"
    if not golden_path.exists():
        raise AssertionError(f"golden image {golden_path} is missing; create it with "
                             f"`python tests/golden/regenerate.py`")
    reference, _ = read_image(golden_path)
    rendered = np.asarray(rendered)
    if rendered.ndim == 2:
        rendered = rendered[..., None]
    if reference.shape != rendered.shape:
        raise AssertionError(f"{name}: rendered shape {rendered.shape} != golden {reference.shape}")
    diff = np.abs(reference.astype(np.int16) - rendered.astype(np.int16)).max(axis=-1)
    fraction = float((diff > tolerance_levels).mean())
    if fraction > max_fraction:
        OUTPUT_DIR.mkdir(exist_ok=True)
        paths = {kind: OUTPUT_DIR / f"{name}_{kind}.png" for kind in ("rendered", "reference", "diff")}
        write_image(paths["rendered"], rendered)
        write_image(paths["reference"], reference)
        rgb_r = rendered if rendered.shape[-1] >= 3 else np.repeat(rendered, 3, axis=-1)
        rgb_g = reference if reference.shape[-1] >= 3 else np.repeat(reference, 3, axis=-1)
        write_image(paths["diff"], difference_image(rgb_r[..., :3], rgb_g[..., :3]))
        raise AssertionError(
            f"{name}: {100 * fraction:.3f} % of pixels differ by more than {tolerance_levels}/255 "
            f"(allowed {100 * max_fraction:.3f} %); images: "
            + ", ".join(str(p) for p in paths.values()))
