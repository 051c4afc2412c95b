"""Error of a technique against the exact reference on the same pixels (docs/DESIGN.md §13).

- misclassified pixels in % of the pixels that show a surface, split into false-lit (the
  technique says sun, the reference shadow) and false-shadow; a pixel counts as lit when its
  lit fraction is ≥ :data:`LIT_THRESHOLD` (filtered techniques return fractions);
- the mean absolute difference of the lit fraction (what a soft technique gets wrong on top);
- the shadow-edge displacement in metres: for each wrong pixel, the distance in render space
  from its surface point to the surface point of the nearest pixel (in the image) that truly
  has the class the technique gave it, i.e. how far the true edge would have to move to make
  the pixel right; mean, 95th percentile and maximum;
- the Pareto front of error against time.
"""
from __future__ import annotations

import math
import statistics
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np
from numba import njit, prange

from cityshade.errors import UsageError

#: Pixels whose lit fraction is at least this count as lit (filtered techniques return
#: fractions; 0.5 is the unbiased threshold of a fraction).
LIT_THRESHOLD = 0.5


@njit(cache=True, parallel=True)
def _nearest_feature_kernel(feature, near_row, near_col):
    """Exact Euclidean feature transform: for every pixel, the nearest ``feature`` pixel.

    Two separable passes (Felzenszwalb & Huttenlocher 2012): per column the nearest feature
    row, then per row the lower envelope of the parabolas ``(x - q)² + (y - row(q))²``.
    ``near_row``/``near_col`` (H, W) int64 get -1 when the image has no feature pixel.
    """
    h, w = feature.shape
    col_row = np.empty((h, w), np.int64)
    # Scan each column down and up for the nearest feature row.
    for x in prange(w):
        last = -1
        for y in range(h):
            if feature[y, x]:
                last = y
            col_row[y, x] = last
        nxt = -1
        for y in range(h - 1, -1, -1):
            if feature[y, x]:
                nxt = y
            if nxt >= 0 and (col_row[y, x] < 0 or nxt - y < y - col_row[y, x]):
                col_row[y, x] = nxt
    # Lower envelope of the columns' parabolas along each row.
    for y in prange(h):
        v = np.empty(w, np.int64)
        z = np.empty(w + 1, np.float64)
        k = -1
        for q in range(w):
            if col_row[y, q] < 0:
                continue
            fq = float((y - col_row[y, q]) ** 2)
            if k < 0:
                k = 0
                v[0] = q
                z[0] = -np.inf
                z[1] = np.inf
                continue
            while True:
                p = v[k]
                fp = float((y - col_row[y, p]) ** 2)
                s = ((fq + q * q) - (fp + p * p)) / (2.0 * (q - p))
                if s <= z[k]:
                    k -= 1   # z[0] = -inf stops this before k < 0
                else:
                    break
            k += 1
            v[k] = q
            z[k] = s
            z[k + 1] = np.inf
        if k < 0:
            for x in range(w):
                near_row[y, x] = -1
                near_col[y, x] = -1
            continue
        j = 0
        for x in range(w):
            while z[j + 1] < x:
                j += 1
            near_col[y, x] = v[j]
            near_row[y, x] = col_row[y, v[j]]


def nearest_feature(feature: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row and column of the nearest ``True`` pixel of ``feature`` for every pixel.

    Parameters
    ----------
    feature : (H, W) bool

    Returns
    -------
    near_row, near_col : (H, W) int64
        Nearest feature pixel by Euclidean distance in pixel units (ties: any of them); -1
        everywhere when ``feature`` has no ``True`` pixel.
    """
    feature = np.ascontiguousarray(feature, dtype=np.bool_)
    if feature.ndim != 2:
        raise UsageError(f"feature must be (H, W), not {feature.shape}")
    near_row = np.empty(feature.shape, np.int64)
    near_col = np.empty(feature.shape, np.int64)
    if feature.size:
        _nearest_feature_kernel(feature, near_row, near_col)
    return near_row, near_col


@dataclass
class Reference:
    """The exact answer of one view and sun, prepared for comparisons."""

    lit: np.ndarray           # (H, W) bool: raytrace says sun
    valid: np.ndarray         # (H, W) bool: a surface is seen
    position_m: np.ndarray    # (H, W, 3) float64 render space
    #: Nearest truly lit / truly shadowed valid pixel of every pixel ((row, col), -1 if none).
    near_lit: tuple[np.ndarray, np.ndarray]
    near_shadow: tuple[np.ndarray, np.ndarray]


def make_reference(ref_lit: np.ndarray, valid: np.ndarray, position_m: np.ndarray) -> Reference:
    """Prepare the reference of one frame (two feature transforms, shared by all comparisons)."""
    valid = np.asarray(valid, bool)
    lit = (np.asarray(ref_lit) >= LIT_THRESHOLD) & valid
    return Reference(lit=lit, valid=valid, position_m=np.asarray(position_m, np.float64),
                     near_lit=nearest_feature(lit), near_shadow=nearest_feature(valid & ~lit))


def _displacement_m(ref: Reference, wrong: np.ndarray, near) -> np.ndarray:
    """Render-space distance from each wrong pixel to its nearest pixel of the other class."""
    rows, cols = np.nonzero(wrong)
    nr, nc = near[0][rows, cols], near[1][rows, cols]
    ok = nr >= 0
    d = ref.position_m[nr[ok], nc[ok]] - ref.position_m[rows[ok], cols[ok]]
    return np.sqrt(np.einsum("ij,ij->i", d, d))


def compare(lit: np.ndarray, ref: Reference, percentile: float = 95.0) -> dict[str, Any]:
    """Error of one technique's lit fraction against the reference on the same pixels.

    Returns
    -------
    dict
        ``valid_px``, ``wrong_px``, ``misclassified_pct``, ``false_lit_pct``,
        ``false_shadow_pct`` (of the valid pixels), ``lit_mae`` (mean |lit − reference| over
        valid pixels), ``edge_mean_m``, ``edge_p95_m``, ``edge_max_m`` (None when no wrong
        pixel has a pixel of the other class in the image), ``false_lit`` and
        ``false_shadow`` (H, W) bool masks.
    """
    lit = np.asarray(lit, np.float32)
    if lit.shape != ref.valid.shape:
        raise UsageError(f"lit fraction {lit.shape} and reference {ref.valid.shape} differ")
    says_lit = lit >= LIT_THRESHOLD
    false_lit = ref.valid & says_lit & ~ref.lit
    false_shadow = ref.valid & ~says_lit & ref.lit
    n_valid = int(ref.valid.sum())
    share = 100.0 / max(n_valid, 1)
    dist = np.concatenate([_displacement_m(ref, false_lit, ref.near_lit),
                           _displacement_m(ref, false_shadow, ref.near_shadow)])
    diff = np.abs(np.nan_to_num(lit, nan=0.0) - ref.lit.astype(np.float32))
    out = {
        "valid_px": n_valid,
        "wrong_px": int(false_lit.sum() + false_shadow.sum()),
        "false_lit_pct": float(false_lit.sum() * share),
        "false_shadow_pct": float(false_shadow.sum() * share),
        "lit_mae": float(diff[ref.valid].mean()) if n_valid else 0.0,
        "edge_mean_m": float(dist.mean()) if dist.size else None,
        "edge_p95_m": float(np.percentile(dist, percentile)) if dist.size else None,
        "edge_max_m": float(dist.max()) if dist.size else None,
        "false_lit": false_lit, "false_shadow": false_shadow,
    }
    out["misclassified_pct"] = out["false_lit_pct"] + out["false_shadow_pct"]
    if out["wrong_px"] == 0:
        out.update(edge_mean_m=0.0, edge_p95_m=0.0, edge_max_m=0.0)
    return out


def pareto_front(times: Sequence[float], errors: Sequence[float]) -> list[int]:
    """Indices of the points no other point beats in both time and error, by time.

    A point is dominated when another is at most as slow and at most as wrong, and strictly
    better in one of the two.
    """
    order = sorted(range(len(times)), key=lambda i: (times[i], errors[i]))
    front, best = [], math.inf
    for i in order:
        if errors[i] < best:
            front.append(i)
            best = errors[i]
    return front


def median_s(values: Sequence[float]) -> float:
    """Median of run times (0 for none): what every reported time is."""
    return float(statistics.median(values)) if values else 0.0


def finite_check(result) -> str | None:
    """Why a technique's result is not a valid answer (NaN, out of [0, 1]), or None."""
    lit = np.asarray(result.lit)
    if not np.isfinite(lit).all():
        return "lit fraction has NaN or infinity"
    if lit.size and (lit.min() < 0.0 or lit.max() > 1.0):
        return "lit fraction outside [0, 1]"
    for name, ch in result.extra_channels.items():
        if not np.isfinite(np.asarray(ch, np.float64)).all():
            return f"extra channel {name} has NaN or infinity"
    return None
