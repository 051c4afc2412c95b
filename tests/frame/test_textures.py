"""Texture loading, mip pyramids, trilinear sampling and mip-level choice (cityshade.frame.textures)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from cityshade.frame import textures as T
from cityshade.imageio import write_image
from reference import reference_mip_reduce, reference_sample_texture

REPO = Path(__file__).parents[2]


def _checkerboard(h, w, cell=1):
    """0/1 checkerboard, (h, w, 4) premultiplied RGBA with alpha 1."""
    board = (((np.arange(h)[:, None] // cell) + (np.arange(w)[None, :] // cell)) % 2)
    out = np.ones((h, w, 4), np.float32)
    out[:, :, :3] = board[:, :, None]
    return out


def _single_texture_set(levels, mode="wrap", border=(0, 0, 0, 0)) -> T.TextureSet:
    offsets, total = [], 0
    for lev in levels:
        offsets.append(total)
        total += lev.shape[0] * lev.shape[1]
    return T.TextureSet(
        texels=np.concatenate([lev.reshape(-1, 4) for lev in levels]).astype(np.float32),
        level_offset=np.array(offsets, np.int64),
        level_width=np.array([lev.shape[1] for lev in levels], np.int64),
        level_height=np.array([lev.shape[0] for lev in levels], np.int64),
        first_level=np.array([0, len(levels)], np.int64),
        wrap=np.array([T.WRAP_MODES.index(mode)], np.int64),
        border=np.array([border], np.float32))


def test_checkerboard_mips_average_to_grey():
    # A 1-texel checkerboard averages to exactly 0.5 at every level below the first (each 2×2
    # box holds two black and two white texels); alpha stays 1.
    levels = T.build_mip_levels(_checkerboard(16, 32))
    assert [lev.shape[:2] for lev in levels] == [(16, 32), (8, 16), (4, 8), (2, 4), (1, 2),
                                                 (1, 1)]
    for lev in levels[1:]:
        np.testing.assert_allclose(lev[:, :, :3], 0.5, atol=1e-7)
        np.testing.assert_allclose(lev[:, :, 3], 1.0, atol=1e-7)
    # A 4-texel checkerboard survives two levels as a checkerboard, then turns grey.
    levels = T.build_mip_levels(_checkerboard(16, 16, cell=4))
    np.testing.assert_array_equal(levels[2][:, :, 0], [[0, 1, 0, 1], [1, 0, 1, 0]] * 2)
    np.testing.assert_allclose(levels[3][:, :, 0], 0.5)


@pytest.mark.parametrize("shape", [(5, 7), (1, 9), (3, 1), (6, 5), (13, 2), (1, 1)])
def test_non_power_of_two_levels_match_the_area_average_twin(shape):
    rng = np.random.default_rng(sum(shape))
    image = rng.uniform(0, 1, size=(*shape, 4)).astype(np.float32)
    levels = T.build_mip_levels(image)
    assert levels[-1].shape[:2] == (1, 1)
    for fine, coarse in zip(levels, levels[1:]):
        assert coarse.shape[:2] == (max(1, fine.shape[0] // 2), max(1, fine.shape[1] // 2))
        np.testing.assert_allclose(coarse, reference_mip_reduce(fine), rtol=1e-5, atol=1e-6)
    # An area average preserves the image mean at every level.
    np.testing.assert_allclose(levels[-1][0, 0], image.reshape(-1, 4).mean(axis=0), rtol=1e-5)


@pytest.mark.parametrize("mode", T.WRAP_MODES)
def test_trilinear_sampling_equals_the_reference_twin(mode):
    rng = np.random.default_rng(T.WRAP_MODES.index(mode))
    image = rng.uniform(0, 1, size=(6, 11, 4)).astype(np.float32)
    levels = T.build_mip_levels(image)
    border = (0.2, 0.1, 0.05, 0.4)
    ts = _single_texture_set(levels, mode, border)
    n = 400
    uv = rng.uniform(-2.5, 3.5, size=(n, 2))
    uv[:50] = rng.uniform(0, 1, size=(50, 2))              # inside, where "none" samples
    uv[50:60] = rng.integers(-1, 2, size=(10, 2))           # exact edges
    lod = rng.uniform(-1.0, len(levels) + 0.5, size=n)
    lod[:20] = np.floor(lod[:20])                            # exact integer levels
    got = T.sample_trilinear(ts, np.zeros(n, np.int64), uv, lod)
    want = np.array([reference_sample_texture(levels, mode, border, u, v, l)
                     for (u, v), l in zip(uv, lod)])
    np.testing.assert_allclose(got, want, rtol=1e-5, atol=1e-6)


def test_texel_centres_and_orientation():
    # 2×2 image, row 0 (top) red/green, row 1 (bottom) blue/white: v = 0 is the bottom.
    img = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], np.uint8)
    ts = _single_texture_set(T.build_mip_levels(T.texels_from_image(img)), "clamp")
    uv = [[0.25, 0.75], [0.75, 0.75], [0.25, 0.25], [0.75, 0.25], [0.5, 0.5]]
    got = T.sample_trilinear(ts, [0] * 5, uv, [0] * 5)
    np.testing.assert_allclose(got[:4, :3], [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]],
                               atol=1e-6)
    np.testing.assert_allclose(got[4, :3], [0.5, 0.5, 0.5], atol=1e-6)


def test_wrap_modes_outside_the_unit_square():
    # 1×2 image: left black, right white (linear 0 and 1).
    img = np.array([[[0, 0, 0], [255, 255, 255]]], np.uint8)
    levels = T.build_mip_levels(T.texels_from_image(img))
    v = 0.5

    def at(mode, u, border=(0, 0, 0, 0)):
        ts = _single_texture_set(levels, mode, border)
        return T.sample_trilinear(ts, [0], [[u, v]], [0])[0]

    assert at("wrap", 1.25)[0] == pytest.approx(0.0)      # = u 0.25: left texel centre
    assert at("wrap", -0.25)[0] == pytest.approx(1.0)     # = u 0.75
    assert at("mirror", 1.25)[0] == pytest.approx(1.0)    # mirrored: 0.75
    assert at("mirror", 2.25)[0] == pytest.approx(0.0)    # period 2
    assert at("clamp", 7.0)[0] == pytest.approx(1.0)
    assert at("clamp", -3.0)[0] == pytest.approx(0.0)
    np.testing.assert_allclose(at("border", 2.0, (0.3, 0.2, 0.1, 1.0)), [0.3, 0.2, 0.1, 1.0])
    # "none": transparent outside [0, 1]² (the material shows), edge-clamped inside.
    np.testing.assert_allclose(at("none", 1.5), [0, 0, 0, 0])
    assert at("none", 1.0)[3] == pytest.approx(1.0)


def test_srgb_decode_and_alpha_premultiplication():
    # Published values of the sRGB curve: code 188 → 0.50289, 0.5 → 0.21404; grey + alpha
    # images premultiply.
    assert T.srgb_to_linear(188 / 255) == pytest.approx(0.50289, abs=2e-5)
    assert T.srgb_to_linear(0.5) == pytest.approx(0.21404, abs=2e-5)
    assert T.srgb_to_linear(1.0) == pytest.approx(1.0)
    grey_alpha = np.array([[[255, 128]]], np.uint8)
    texels = T.texels_from_image(grey_alpha)
    np.testing.assert_allclose(texels[0, 0], [128 / 255] * 4, rtol=1e-6)
    rgb16 = np.array([[[65535, 0, 32768]]], np.uint16)
    np.testing.assert_allclose(T.texels_from_image(rgb16)[0, 0, :3],
                               [1.0, 0.0, T.srgb_to_linear(32768 / 65535)], rtol=1e-6)


def test_texture_files_load_once_and_bad_ones_are_counted(tmp_path):
    T.clear_texture_cache()
    good = tmp_path / "facade.png"
    write_image(good, np.full((4, 6, 3), 255, np.uint8))
    junk = tmp_path / "junk.jpg"
    junk.write_bytes(b"not a jpeg")
    textures = [{"path": str(good), "wrap_mode": "wrap"},
                {"path": str(tmp_path / "missing.png"), "wrap_mode": "none"},
                {"path": str(junk), "wrap_mode": "clamp"},
                {"path": str(good), "wrap_mode": "sideways"}]
    ts = T.load_texture_set(textures)
    assert ts.counters == {"loaded": 2, "failed": 2, "unknown_wrap_modes": 1}
    assert len(ts.warnings) == 3
    assert any("missing.png" in w for w in ts.warnings) and any("junk" in w for w in ts.warnings)
    assert list(np.diff(ts.first_level)) == [3, 0, 0, 3]   # 4×6 → 2×3 → 1×1
    # An unloaded texture samples as transparent (the material colour shows).
    got = T.sample_trilinear(ts, [0, 1, 2], [[0.5, 0.5]] * 3, [0, 0, 0])
    np.testing.assert_allclose(got, [[1, 1, 1, 1], [0, 0, 0, 0], [0, 0, 0, 0]], atol=1e-6)
    # The pyramid is cached per file: a second load returns the same object.
    assert T.load_mip_pyramid(good) is T.load_mip_pyramid(good)


def test_sample_city_facade_texture_loads():
    facade = REPO / "sample_data" / "sample_city_facade.png"
    pyramid = T.load_mip_pyramid(facade)
    top = pyramid.levels[-1]
    assert top.shape == (1, 1, 4)
    # The 1×1 level is the image mean (in linear light).
    mean = pyramid.levels[0].reshape(-1, 4).mean(axis=0, dtype=np.float64)
    np.testing.assert_allclose(top[0, 0], mean, rtol=1e-6)


def test_lod_follows_the_screen_space_uv_rate():
    # A 64×64 texture mapped so that one pixel steps s texels: level log2(s).
    ts = _single_texture_set(T.build_mip_levels(_checkerboard(64, 64)), "wrap")
    h, w = 6, 8
    for step, want in [(0.25, 0.0), (1.0, 0.0), (4.0, 2.0), (8.0, 3.0), (1000.0, 6.0)]:
        cols, rows = np.meshgrid(np.arange(w), np.arange(h))
        uv = np.stack([cols * step / 64.0, rows * step / 64.0], axis=-1)
        tex = np.zeros((h, w), np.int64)
        group = np.zeros((h, w), np.int64)
        normal = np.zeros((h, w, 3))
        normal[..., 2] = 1.0
        lod = T.lod_from_uv_neighbours(uv, tex, group, normal, ts)
        np.testing.assert_allclose(lod, want, atol=1e-5, err_msg=f"step {step}")
    # Anisotropic: the larger axis decides; a uv seam on one side does not.
    uv[:, :, 1] = rows * 2.0 / 64.0
    uv[:, :, 0] = cols * 0.5 / 64.0
    uv[:, 4:, 0] += 0.5  # seam between columns 3 and 4
    lod = T.lod_from_uv_neighbours(uv, tex, group, normal, ts)
    np.testing.assert_allclose(lod, 1.0, atol=1e-5)
    # A pixel with no neighbour on its patch gets the coarsest level (its whole texture).
    group = np.arange(h * w).reshape(h, w)
    lod = T.lod_from_uv_neighbours(uv, tex, group, normal, ts)
    np.testing.assert_allclose(lod, 6.0)
