"""The float32 → half kernel of the EXR writer against numpy's conversion."""
from __future__ import annotations

import numpy as np

from cityshade.halffloat import float32_to_half_bits


def test_half_bits_equal_numpy_on_random_and_edge_values():
    rng = np.random.default_rng(11)
    random_bits = rng.integers(0, 2 ** 32, 2_000_000, dtype=np.uint64).astype(np.uint32)
    # Every half value, and float32 values at and one ulp around the midpoints between halves
    # (ties to even), through normals, subnormals, 0, the overflow edge and inf.
    halves = np.arange(2 ** 16, dtype=np.uint32).astype(np.uint16).view(np.float16)
    near = halves.astype(np.float32).view(np.uint32).astype(np.int64)[:, None] + \
        np.array([-4097, -4096, -4095, -1, 0, 1, 4095, 4096, 4097])[None, :]
    edges = np.array([0x477FEFFF, 0x477FF000, 0x477FF001, 0x47800000, 0x33000000, 0x33000001,
                      0x32FFFFFF, 0x387FFFFF, 0x38800000, 0x7F800000, 0xFF800000, 0x80000000],
                     np.uint32)
    bits = np.concatenate([random_bits, near.ravel().astype(np.uint32), edges])
    src = bits.view(np.float32).reshape(2, -1)
    out = np.zeros(src.shape, np.uint16)
    float32_to_half_bits(np.ascontiguousarray(src), out)
    with np.errstate(over="ignore", invalid="ignore"):
        want = src.astype(np.float16)
    nan = np.isnan(src)
    np.testing.assert_array_equal(out[~nan], want.view(np.uint16)[~nan])
    assert np.isnan(out.view(np.float16)[nan]).all() and nan.any()


def test_half_bits_into_a_strided_column_slice():
    src = np.arange(12, dtype=np.float32).reshape(3, 4) / 3
    strip = np.zeros((3, 20), np.uint8)
    float32_to_half_bits(src, strip[:, 6:14].view("<u2"))
    np.testing.assert_array_equal(strip[:, 6:14].view(np.float16), src.astype(np.float16))
    assert not strip[:, :6].any() and not strip[:, 14:].any()
