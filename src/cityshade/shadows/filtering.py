"""Shadow-map filtering: depth tests with percentage-closer filtering, variance shadow maps,
separable box / Gaussian filters and the depth-aware screen-space smoothing post-filter.

Conventions: maps are (H, W) row-major, texel ``(col, row)`` with continuous coordinates
``u_px, v_px`` (:func:`cityshade.shadows.shadowmap.project`; texel ``floor(u_px)``, centre at
``+0.5``). Depth maps hold NDC depth (smaller is nearer the sun, ``+inf`` where no caster).
A lookup outside the map is lit (no caster is known there).
"""
from __future__ import annotations

import dataclasses
import math
import time

import numpy as np
from numba import njit, prange

from cityshade.config import SMOOTH_MAX_GAIN
from cityshade.errors import UsageError

#: Gaussian kernels are cut at this many standard deviations (weights beyond 3σ sum to 0.3 %).
GAUSS_CUT_SIGMA = 3.0


# --- depth tests ------------------------------------------------------------------------------

@njit(cache=True, parallel=True)
def _pcf(depth, u_px, v_px, z, radius, out):
    h, w = depth.shape
    taps = (2 * radius + 1) * (2 * radius + 1)
    for i in prange(u_px.shape[0]):
        u = u_px[i]
        v = v_px[i]
        # Non-finite or far outside the map (no int64 conversion of ±1e300): lit.
        if not (-radius - 1.0 <= u < w + radius + 1.0 and -radius - 1.0 <= v < h + radius + 1.0):
            out[i] = 1.0
            continue
        c0 = int(math.floor(u))
        r0 = int(math.floor(v))
        lit = 0
        for dr in range(-radius, radius + 1):
            r = r0 + dr
            for dc in range(-radius, radius + 1):
                c = c0 + dc
                # Outside the map, or the receiver is not behind the stored caster: lit.
                if r < 0 or r >= h or c < 0 or c >= w or z[i] <= depth[r, c]:
                    lit += 1
        out[i] = lit / taps


def pcf_lookup(depth, u_px, v_px, z, kernel: int = 1) -> np.ndarray:
    """Percentage-closer filtering (Reeves et al. 1987): the share of the ``kernel × kernel``
    texels around each receiver's texel whose stored depth is not nearer than the receiver.

    Parameters
    ----------
    depth : (H, W) float32 NDC depth map.
    u_px, v_px, z : (N,) float64 receiver texel coordinates and (biased) NDC depth.
    kernel : odd int; 1 is the plain shadow-map test.

    Returns
    -------
    (N,) float32 lit fraction in [0, 1].
    """
    kernel = int(kernel)
    if kernel < 1 or kernel % 2 == 0:
        raise UsageError(f"the PCF kernel must be an odd number of texels, not {kernel}")
    depth = np.asarray(depth)
    if depth.ndim != 2:
        raise UsageError(f"depth map must be (H, W), not {depth.shape}")
    u, v, zz = (np.ascontiguousarray(a, dtype=np.float64).reshape(-1) for a in (u_px, v_px, z))
    if not u.shape == v.shape == zz.shape:
        raise UsageError("u_px, v_px and z must have the same length")
    out = np.empty(u.shape[0], np.float32)
    _pcf(depth, u, v, zz, kernel // 2, out)
    return out


# --- separable filters ------------------------------------------------------------------------

def gaussian_weights(sigma_px: float, radius_px: int | None = None) -> np.ndarray:
    """Normalised 1-D Gaussian weights (2r + 1,), r = ceil(3σ) unless given."""
    sigma = float(sigma_px)
    if not (math.isfinite(sigma) and sigma >= 0):
        raise UsageError(f"sigma must be a finite number >= 0, not {sigma_px}")
    r = int(math.ceil(GAUSS_CUT_SIGMA * sigma)) if radius_px is None else int(radius_px)
    if sigma == 0.0 or r == 0:
        return np.ones(1)
    x = np.arange(-r, r + 1, dtype=np.float64)
    g = np.exp(-0.5 * (x / sigma) ** 2)
    return g / g.sum()


def box_weights(radius_px: int) -> np.ndarray:
    """Normalised 1-D box weights (2r + 1,)."""
    r = int(radius_px)
    if r < 0:
        raise UsageError(f"box radius must be >= 0, not {radius_px}")
    return np.full(2 * r + 1, 1.0 / (2 * r + 1))


@njit(cache=True, parallel=True)
def _filter_axis(img, weights, along_rows, out):
    """Convolve every row (``along_rows``) or every column of (H, W, C) ``img`` with
    ``weights``; edges clamp to the border."""
    h, w, nc = img.shape
    r = weights.shape[0] // 2
    for y in prange(h):
        for x in range(w):
            for ch in range(nc):
                acc = 0.0
                for k in range(-r, r + 1):
                    if along_rows:
                        acc += weights[k + r] * img[y, min(max(x + k, 0), w - 1), ch]
                    else:
                        acc += weights[k + r] * img[min(max(y + k, 0), h - 1), x, ch]
                out[y, x, ch] = acc


def separable_filter(image, weights) -> np.ndarray:
    """Filter an image with ``weights`` along rows, then along columns (clamp-to-edge).

    Parameters
    ----------
    image : (H, W) or (H, W, C) array
    weights : (2r + 1,) 1-D kernel (see :func:`gaussian_weights`, :func:`box_weights`).

    Returns
    -------
    float64 array of the image's shape.
    """
    img = np.asarray(image, dtype=np.float64)
    flat = img.ndim == 2
    if flat:
        img = img[..., None]
    if img.ndim != 3:
        raise UsageError(f"image must be (H, W) or (H, W, C), not {np.shape(image)}")
    wts = np.ascontiguousarray(weights, dtype=np.float64)
    if wts.ndim != 1 or wts.shape[0] % 2 == 0:
        raise UsageError("filter weights must be 1-D with an odd length")
    tmp = np.empty_like(img)
    out = np.empty_like(img)
    _filter_axis(np.ascontiguousarray(img), wts, True, tmp)
    _filter_axis(tmp, wts, False, out)
    return out[..., 0] if flat else out


# --- variance shadow maps ---------------------------------------------------------------------

def vsm_moments(depth, metres_per_ndc: float, filter_weights=None, work=None) -> np.ndarray:
    """(H, W, 2) float64 moments ``(E[d], E[d²])`` of the depth in metres, filtered.

    Depth is ``(z_ndc + 1) · metres_per_ndc``, i.e. metres from the near plane, so the moments
    stay small; texels without caster count as the far plane (z = 1). float64 because
    ``E[d²] - E[d]²`` cancels: in float32 a 1 km depth range would leave a variance noise of
    0.1 m². ``work`` (a :class:`cityshade.runtime.memory.Scratch`) holds the result and its temporary
    instead of fresh arrays (valid while the caller holds it).
    """
    z = np.asarray(depth)
    if z.ndim != 2:
        raise UsageError(f"depth map must be (H, W), not {z.shape}")
    wts = np.ones(1) if filter_weights is None else np.ascontiguousarray(filter_weights,
                                                                         np.float64)
    if wts.ndim != 1 or wts.shape[0] % 2 == 0:
        raise UsageError("filter weights must be 1-D with an odd length")
    if wts.shape[0] == 1:
        wts = np.ones(1)        # a one-tap kernel leaves the moments unfiltered
    # The row pass reads the depth map itself (no (H, W, 2) moments image before filtering);
    # the arithmetic is separable_filter's on np.stack([d, d * d]), so the values are the same.
    shape = z.shape + (2,)
    rows = np.empty(shape) if work is None else work.get("vsm.rows", shape)
    _moment_rows(np.ascontiguousarray(z), float(metres_per_ndc), wts, rows)
    if wts.shape[0] == 1:
        return rows
    out = np.empty(shape) if work is None else work.get("vsm.moments", shape)
    _filter_axis(rows, wts, False, out)
    return out


@njit(cache=True, parallel=True)
def _moment_rows(depth, scale, weights, out):
    """Depth (metres from the near plane; no caster = the far plane) and its square, filtered
    along every row (clamp-to-edge) into ``out`` (H, W, 2)."""
    h, w = depth.shape
    r = weights.shape[0] // 2
    for y in prange(h):
        for x in range(w):
            m1 = 0.0
            m2 = 0.0
            for k in range(-r, r + 1):
                d = (min(np.float64(depth[y, min(max(x + k, 0), w - 1)]), 1.0) + 1.0) * scale
                m1 += weights[k + r] * d
                m2 += weights[k + r] * (d * d)
            out[y, x, 0] = m1
            out[y, x, 1] = m2


@njit(cache=True, inline="always")
def chebyshev_lit(mean, mean2, d, min_variance, bleed_reduction):
    """Lit fraction bound of a receiver at depth ``d`` against filtered moments: 1 when not
    behind the mean, else Chebyshev's one-tailed bound ``σ² / (σ² + (d - μ)²)`` with
    ``σ² >= min_variance``, then light-bleeding reduction (bounds below ``bleed_reduction`` are
    shadow, the rest is rescaled to [0, 1])."""
    if d <= mean:
        return 1.0
    var = max(mean2 - mean * mean, min_variance)
    diff = d - mean
    p = var / (var + diff * diff)
    if bleed_reduction > 0.0:
        p = min(max((p - bleed_reduction) / (1.0 - bleed_reduction), 0.0), 1.0)
    return p


@njit(cache=True, parallel=True)
def _vsm(moments, u_px, v_px, d, min_variance, bleed_reduction, out):
    h, w = moments.shape[0], moments.shape[1]
    for i in prange(u_px.shape[0]):
        # Clamp far-away coordinates (the border texels are used there anyway) so the integer
        # conversion stays defined; non-finite receivers are lit.
        if not (np.isfinite(u_px[i]) and np.isfinite(v_px[i])):
            out[i] = 1.0
            continue
        u = min(max(u_px[i] - 0.5, -1.0), w + 1.0)
        v = min(max(v_px[i] - 0.5, -1.0), h + 1.0)
        # Bilinear moments of the four nearest texel centres (clamped to the map).
        c0 = int(math.floor(u))
        r0 = int(math.floor(v))
        fu = u - c0
        fv = v - r0
        m1 = 0.0
        m2 = 0.0
        for dr in range(2):
            r = min(max(r0 + dr, 0), h - 1)
            wr = fv if dr == 1 else 1.0 - fv
            for dc in range(2):
                c = min(max(c0 + dc, 0), w - 1)
                wgt = wr * (fu if dc == 1 else 1.0 - fu)
                m1 += wgt * moments[r, c, 0]
                m2 += wgt * moments[r, c, 1]
        out[i] = chebyshev_lit(m1, m2, d[i], min_variance, bleed_reduction)


def vsm_lookup(moments, u_px, v_px, depth_m, min_variance_m2: float,
               bleed_reduction: float) -> np.ndarray:
    """Variance-shadow-map lookup (Donnelly and Lauritzen 2006): bilinear moments at each
    receiver, Chebyshev bound, light-bleeding reduction.

    Parameters
    ----------
    moments : (H, W, 2) float64 from :func:`vsm_moments`.
    u_px, v_px : (N,) texel coordinates; depth_m : (N,) receiver depth in the moments' metres.

    Returns
    -------
    (N,) float32 lit fraction.
    """
    mom = np.asarray(moments, dtype=np.float64)
    if mom.ndim != 3 or mom.shape[2] != 2:
        raise UsageError(f"moments must be (H, W, 2), not {mom.shape}")
    if not 0.0 <= bleed_reduction < 1.0:
        raise UsageError(f"bleed_reduction must be in [0, 1), not {bleed_reduction}")
    u, v, d = (np.ascontiguousarray(a, dtype=np.float64).reshape(-1)
               for a in (u_px, v_px, depth_m))
    out = np.empty(u.shape[0], np.float32)
    _vsm(mom, u, v, d, float(min_variance_m2), float(bleed_reduction), out)
    return out


# --- screen-space smoothing -------------------------------------------------------------------

@njit(cache=True, parallel=True)
def _equal_runs(values, horizontal, before, after):
    """Per pixel, how many pixels in a row along the line (a row when ``horizontal``, else a
    column), itself included, hold exactly its value, counted backwards (``before``) and
    forwards (``after``)."""
    h, w = values.shape
    if horizontal:
        for y in prange(h):
            before[y, 0] = 1
            for x in range(1, w):
                before[y, x] = before[y, x - 1] + 1 if values[y, x] == values[y, x - 1] else 1
            after[y, w - 1] = 1
            for x in range(w - 2, -1, -1):
                after[y, x] = after[y, x + 1] + 1 if values[y, x] == values[y, x + 1] else 1
    else:
        # Blocks of columns, row after row inside each (a row reads the previous one): the
        # inner loop runs along a row, contiguous in memory.
        for b in prange((w + 63) // 64):
            x0, x1 = 64 * b, min(w, 64 * b + 64)
            for x in range(x0, x1):
                before[0, x] = 1
                after[h - 1, x] = 1
            for y in range(1, h):
                for x in range(x0, x1):
                    before[y, x] = (before[y - 1, x] + 1 if values[y, x] == values[y - 1, x]
                                    else 1)
            for y in range(h - 2, -1, -1):
                for x in range(x0, x1):
                    after[y, x] = after[y + 1, x] + 1 if values[y, x] == values[y + 1, x] else 1


@njit(cache=True, parallel=True)
def _smooth_pass(values, depth, ok, sigma, thr_rel, horizontal, before, after, out):
    """One depth-aware 1-D Gaussian pass. From each pixel the kernel walks outward on each
    side and stops at the first pixel that is not ``ok`` or whose depth differs from its
    predecessor's by more than ``thr_rel`` times the predecessor's depth. ``before`` and
    ``after`` are :func:`_equal_runs` of ``values`` along the pass."""
    h, w = values.shape
    for y in prange(h):
        for x in range(w):
            if not ok[y, x] or sigma[y, x] <= 0.0:
                out[y, x] = values[y, x]
                continue
            s = sigma[y, x]
            r = int(math.ceil(GAUSS_CUT_SIGMA * s))
            v0 = values[y, x]
            if v0 == 0.0 or v0 == 1.0:
                # Fully lit or fully shadowed with only the same value within r on its line
                # (most pixels): whatever stops the walk, the sum is v0 * wsum, which is
                # exactly v0 for 0 and 1, so the taps (an exp each) are skipped.
                pos = x if horizontal else y
                end = w if horizontal else h
                if (before[y, x] > min(r, pos) and after[y, x] > min(r, end - 1 - pos)):
                    out[y, x] = v0
                    continue
            inv2 = 0.5 / (s * s)
            acc = v0
            wsum = 1.0
            for side in range(2):
                step = 2 * side - 1
                sx = step if horizontal else 0
                sy = 0 if horizontal else step
                prev = depth[y, x]
                for k in range(1, r + 1):
                    yy = y + sy * k
                    xx = x + sx * k
                    if yy < 0 or yy >= h or xx < 0 or xx >= w or not ok[yy, xx]:
                        break
                    dd = depth[yy, xx]
                    if abs(dd - prev) > thr_rel * abs(prev):
                        break
                    prev = dd
                    wk = math.exp(-k * k * inv2)
                    acc += wk * values[yy, xx]
                    wsum += wk
            out[y, x] = acc / wsum


def smooth_lit(lit, surfaces, camera, sigma_px: float, depth_threshold_rel: float, *,
               mask=None, max_gain: float = SMOOTH_MAX_GAIN) -> np.ndarray:
    """Depth-aware screen-space Gaussian smoothing of a lit-fraction image.

    A separable Gaussian, N×1 then 1×N. Along each line the kernel stops at depth
    discontinuities: a neighbour contributes only when every step between consecutive pixels
    from the centre to it changes the depth by at most ``depth_threshold_rel`` (relative), so
    a value never crosses a discontinuity larger than the threshold (each pass walks straight
    lines; a surface's own slow depth change along the line is not a discontinuity). Pixels
    outside ``mask`` (default: the valid pixels) keep their value and never contribute.

    Strength by distance: for perspective cameras σ at a pixel is ``sigma_px · median depth /
    depth``, clamped to ``[sigma_px / max_gain, sigma_px · max_gain]`` (near surfaces show
    bigger shadow-map steps on screen); map views use ``sigma_px`` everywhere.

    Parameters
    ----------
    lit : (H, W) lit fraction.
    surfaces : Surfaces (its ``depth`` and ``valid``).
    camera : Camera.
    sigma_px : float >= 0, Gaussian σ in pixels at the median depth.
    depth_threshold_rel : float > 0.

    Returns
    -------
    (H, W) float32 in [0, 1].
    """
    values = np.asarray(lit, dtype=np.float64)
    depth = np.asarray(surfaces.depth, dtype=np.float64)
    if values.ndim != 2 or values.shape != depth.shape:
        raise UsageError(f"lit {values.shape} and surfaces {depth.shape} must be the same "
                         f"(H, W)")
    sigma = float(sigma_px)
    thr = float(depth_threshold_rel)
    if not (math.isfinite(sigma) and 0.0 <= sigma <= 64.0):
        raise UsageError(f"smoothing sigma must be in [0, 64] pixels, not {sigma_px}")
    if not (math.isfinite(thr) and thr > 0.0):
        raise UsageError(f"depth threshold must be a finite number > 0, not "
                         f"{depth_threshold_rel}")
    if not (math.isfinite(max_gain) and max_gain >= 1.0):
        raise UsageError(f"max_gain must be >= 1, not {max_gain}")
    ok = np.asarray(surfaces.valid, bool) if mask is None else np.asarray(mask, bool)
    ok = ok & np.isfinite(depth)
    if sigma == 0.0 or not ok.any():
        return np.clip(values, 0.0, 1.0).astype(np.float32)
    sig = np.zeros(values.shape)
    if camera.kind == "map":
        sig[ok] = sigma
    else:
        d = np.maximum(depth[ok], 1e-9)
        sig[ok] = np.clip(sigma * float(np.median(d)) / d, sigma / max_gain, sigma * max_gain)
    values = np.ascontiguousarray(values)
    tmp = np.empty_like(values)
    out = np.empty_like(values)
    before = np.empty(values.shape, np.int32)
    after = np.empty(values.shape, np.int32)
    _equal_runs(values, True, before, after)
    _smooth_pass(values, depth, ok, sig, thr, True, before, after, tmp)
    _equal_runs(tmp, False, before, after)
    _smooth_pass(tmp, depth, ok, sig, thr, False, before, after, out)
    return np.clip(out, 0.0, 1.0).astype(np.float32)


# --- the "+smooth" post-filter ----------------------------------------------------------------

class Smoothed:
    """A technique followed by :func:`smooth_lit` (registered as ``NAME+smooth``).

    Only pixels that face the sun are smoothed, and only with each other: the shared rule
    (pixels facing away are shadow) holds afterwards as before.
    """

    def __init__(self, inner):
        self.inner = inner
        self.name = f"{inner.name}+smooth"

    def run(self, ctx):
        result = self.inner.run(ctx)
        settings = ctx.settings.smooth
        t0 = time.perf_counter()
        faces = ctx.faces
        lit = smooth_lit(result.lit, ctx.surfaces, ctx.camera, settings.sigma_px,
                         settings.depth_threshold_rel, mask=faces, max_gain=settings.max_gain)
        lit[~faces] = 0.0
        smooth_s = time.perf_counter() - t0
        diagnostics = dataclasses.replace(result.diagnostics)
        diagnostics.technique = self.name
        diagnostics.smooth = {"sigma_px": settings.sigma_px,
                              "depth_threshold_rel": settings.depth_threshold_rel,
                              "max_gain": settings.max_gain, "smooth_s": smooth_s}
        diagnostics.shadow_s = float(diagnostics.get("shadow_s", 0.0)) + smooth_s
        # Keep every other field of the inner result (extra channels, maps used, ...).
        return dataclasses.replace(result, lit=lit, diagnostics=diagnostics)
