"""Shadow-map filters: PCF, separable box/Gaussian, VSM and the depth-aware smoothing, each
against its slow twin in tests/reference.py, plus properties checked on numbers we know."""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from reference import (reference_pcf, reference_separable_filter, reference_smooth_lit,
                       reference_vsm_lookup)

from cityshade.errors import UsageError
from cityshade.shadows import filtering as flt


def test_pcf_matches_twin():
    rng = np.random.default_rng(5)
    depth = rng.uniform(-1, 1, (23, 31)).astype(np.float32)
    depth[rng.random(depth.shape) < 0.1] = np.inf
    n = 400
    u = rng.uniform(-3, 34, n)
    v = rng.uniform(-3, 26, n)
    z = rng.uniform(-1, 1, n)
    for kernel in (1, 3, 5):
        fast = flt.pcf_lookup(depth, u, v, z, kernel)
        slow = reference_pcf(depth, u, v, z, kernel)
        np.testing.assert_allclose(fast, slow, atol=1e-7)


def test_pcf_known_values():
    depth = np.full((5, 5), 0.5, np.float32)   # the receiver's own surface, behind it
    depth[:, :2] = -0.5                      # two columns of casters nearer than the receiver
    # A receiver at z = 0.2 centred on column 2: 3 of its 9 taps (column 1) are occluded.
    assert flt.pcf_lookup(depth, [2.5], [2.5], [0.2], 3)[0] == pytest.approx(6 / 9)
    assert flt.pcf_lookup(depth, [1.5], [2.5], [0.2], 1)[0] == 0.0
    assert flt.pcf_lookup(depth, [-4.0], [2.5], [0.2], 1)[0] == 1.0   # outside: lit
    with pytest.raises(UsageError, match="odd"):
        flt.pcf_lookup(depth, [1.0], [1.0], [0.0], 2)


@pytest.mark.parametrize("weights", [flt.box_weights(2), flt.gaussian_weights(1.3),
                                     flt.gaussian_weights(0.0)])
def test_separable_filter_matches_twin(weights):
    rng = np.random.default_rng(1)
    img = rng.random((17, 12, 2))
    np.testing.assert_allclose(flt.separable_filter(img, weights),
                               reference_separable_filter(img, weights), atol=1e-12)
    flat = img[..., 0]
    np.testing.assert_allclose(flt.separable_filter(flat, weights),
                               reference_separable_filter(flat, weights), atol=1e-12)


def test_filter_weights():
    g = flt.gaussian_weights(2.0)
    assert g.shape == (13,) and g.sum() == pytest.approx(1.0)
    assert g[6] / g[8] == pytest.approx(np.exp(0.5))      # exp(-x²/2σ²) at x = 2, σ = 2
    np.testing.assert_allclose(flt.box_weights(1), [1 / 3] * 3)
    # A constant image stays constant; a box filter of an impulse spreads it evenly.
    assert np.allclose(flt.separable_filter(np.full((6, 7), 0.3), g), 0.3)
    imp = np.zeros((7, 7))
    imp[3, 3] = 9.0
    out = flt.separable_filter(imp, flt.box_weights(1))
    assert np.allclose(out[2:5, 2:5], 1.0) and out.sum() == pytest.approx(9.0)


def test_vsm_matches_twin_and_bounds():
    rng = np.random.default_rng(7)
    depth = rng.uniform(-1, 1, (20, 24)).astype(np.float32)
    moments = flt.vsm_moments(depth, 50.0, flt.gaussian_weights(1.0))
    n = 300
    u = rng.uniform(-1, 25, n)
    v = rng.uniform(-1, 21, n)
    d = rng.uniform(0, 100, n)
    for bleed in (0.0, 0.3):
        fast = flt.vsm_lookup(moments, u, v, d, 1e-3, bleed)
        slow = reference_vsm_lookup(moments, u, v, d, 1e-3, bleed)
        np.testing.assert_allclose(fast, slow, atol=1e-6)


def test_smooth_of_a_binary_picture_matches_twin():
    # Shadow-map output is mostly exactly 0 or 1: the kernel skips the taps where a line holds
    # one value within its radius, so the twin is checked on such pictures too (blocks of 0
    # and 1, a few fractional pixels, invalid pixels and depth steps), and pixels whose whole
    # neighbourhood holds one value keep it exactly.
    rng = np.random.default_rng(11)
    h, w = 80, 100
    lit = np.kron(rng.integers(0, 2, (4, 5)), np.ones((20, 20))).astype(np.float64)
    lit[3:5, 30:33] = 0.5
    lit[20, 7] = 0.25
    depth = np.where(np.arange(w)[None, :] < 47, 10.0, 10.8) * np.ones((h, 1))
    valid = rng.random((h, w)) > 0.03
    for sigma in (0.7, 1.5):
        fast = flt.smooth_lit(lit, _surfaces(depth, valid), MAP, sigma, 0.02)
        slow = reference_smooth_lit(lit, depth, valid, np.where(valid, sigma, 0.0), 0.02)
        np.testing.assert_allclose(fast, slow, atol=1e-6)
        r = int(np.ceil(3.0 * sigma))
        padded = np.pad(lit, r, mode="edge")
        windows = np.lib.stride_tricks.sliding_window_view(padded, (2 * r + 1, 2 * r + 1))
        uniform = (windows.min(axis=(2, 3)) == windows.max(axis=(2, 3))) & np.isin(lit, (0, 1))
        assert uniform.sum() > h * w // 4
        np.testing.assert_array_equal(fast[uniform], lit[uniform].astype(np.float32))
        assert fast.min() >= 0.0 and fast.max() <= 1.0


def test_vsm_moments_equal_the_stacked_moments_filtered():
    """The fused moments pass against its obvious twin: (d, d²) of the depth in metres
    (empty texels at the far plane), stacked, then separable_filter; equal to the bit."""
    rng = np.random.default_rng(3)
    depth = rng.uniform(-1, 1, (17, 23)).astype(np.float32)
    depth[rng.random(depth.shape) < 0.2] = np.inf
    d = (np.minimum(depth.astype(np.float64), 1.0) + 1.0) * 40.0
    stacked = np.stack([d, d * d], axis=-1)
    for weights in (flt.gaussian_weights(1.5), flt.box_weights(2), np.ones(1)):
        want = stacked if weights.shape[0] == 1 else flt.separable_filter(stacked, weights)
        assert np.array_equal(flt.vsm_moments(depth, 40.0, weights), want)
    assert np.array_equal(flt.vsm_moments(depth, 40.0), stacked)


def test_vsm_chebyshev_known_value():
    # Unfiltered constant map: mean 10 m, variance = min_variance 1 m²: a receiver 2 m behind
    # gets 1 / (1 + 4) = 0.2; with bleeding reduction 0.1 → (0.2 - 0.1) / 0.9.
    depth = np.full((4, 4), -0.8, np.float32)    # (z + 1) · 50 = 10 m
    moments = flt.vsm_moments(depth, 50.0)
    np.testing.assert_allclose(flt.vsm_lookup(moments, [2.0], [2.0], [12.0], 1.0, 0.0), [0.2],
                               rtol=1e-6)
    np.testing.assert_allclose(flt.vsm_lookup(moments, [2.0], [2.0], [12.0], 1.0, 0.1),
                               [0.1 / 0.9], rtol=1e-6)
    assert flt.vsm_lookup(moments, [2.0], [2.0], [9.0], 1.0, 0.1)[0] == 1.0


def _surfaces(depth, valid=None):
    depth = np.asarray(depth, np.float32)
    return SimpleNamespace(depth=depth, valid=np.ones(depth.shape, bool) if valid is None
                           else valid)


MAP = SimpleNamespace(kind="map")


def test_smooth_matches_twin():
    rng = np.random.default_rng(3)
    h, w = 24, 30
    depth = np.where(rng.random((h, w)) < 0.2, 10.0, 10.5) + rng.uniform(0, 0.05, (h, w))
    valid = rng.random((h, w)) > 0.05
    lit = rng.random((h, w))
    fast = flt.smooth_lit(lit, _surfaces(depth, valid), MAP, 1.2, 0.02)
    slow = reference_smooth_lit(lit, depth.astype(np.float32).astype(np.float64), valid,
                                np.where(valid, 1.2, 0.0), 0.02)
    np.testing.assert_allclose(fast, slow, atol=1e-6)


def test_smooth_never_crosses_a_discontinuity():
    h, w = 20, 40
    depth = np.full((h, w), 10.0)
    depth[:, 20:] = 11.0                       # a 10 % step between two surfaces
    depth[8:12, 5:15] = 9.0                    # a nearer object inside the left surface
    lit = np.zeros((h, w))
    lit[:, 20:] = 1.0
    lit[8:12, 5:15] = 0.5
    out = flt.smooth_lit(lit, _surfaces(depth), MAP, 3.0, 0.05)
    # Threshold 5 %: nothing mixes; every region keeps its exact value.
    np.testing.assert_array_equal(out, lit.astype(np.float32))
    # Above the step size the same picture is blurred across it.
    out = flt.smooth_lit(lit, _surfaces(depth), MAP, 3.0, 0.2)
    assert 0.05 < out[0, 19] < 0.95 and 0.05 < out[0, 20] < 0.95


def test_smooth_along_a_receding_surface_and_by_distance():
    # A ground plane seen at a grazing angle: depth grows 1.5 % per row; 2 % threshold smooths.
    h, w = 30, 30
    depth = 10.0 * 1.015 ** np.arange(h)[:, None] * np.ones((1, w))
    lit = (np.arange(w)[None, :] >= 15) * np.ones((h, 1))
    cam = SimpleNamespace(kind="perspective")
    out = flt.smooth_lit(lit, _surfaces(depth), cam, 1.5, 0.02)
    assert 0.1 < out[0, 15] < 0.9
    # Nearer rows are blurred more (σ ∝ median depth / depth): the edge is wider at row 0.
    width_near = int(((out[0] > 0.02) & (out[0] < 0.98)).sum())
    width_far = int(((out[-1] > 0.02) & (out[-1] < 0.98)).sum())
    assert width_near > width_far


def test_smooth_validates():
    with pytest.raises(UsageError, match="same"):
        flt.smooth_lit(np.zeros((3, 3)), _surfaces(np.ones((4, 3))), MAP, 1.0, 0.1)
    with pytest.raises(UsageError, match="threshold"):
        flt.smooth_lit(np.zeros((3, 3)), _surfaces(np.ones((3, 3))), MAP, 1.0, 0.0)
