"""float32 → IEEE half bits, rounded to nearest (ties to even), for the EXR writer.

Written by hand because numpy's ``astype(np.float16)`` converts one value at a time through a
scalar routine (about 4 ns a value here: 52 ms for the six half channels of a 1080p frame);
this kernel is branch-light integer arithmetic that LLVM vectorises. It gives the same bits
as numpy for every non-NaN input and keeps NaN a NaN (tests/test_halffloat.py).
"""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def _half_bits(bits: np.uint32) -> np.uint16:
    sign = (bits >> np.uint32(16)) & np.uint32(0x8000)
    f = bits & np.uint32(0x7FFFFFFF)
    if f >= np.uint32(0x47800000):            # ≥ 65536, inf or NaN
        if f > np.uint32(0x7F800000):         # NaN: numpy's payload (top mantissa bits)
            h = np.uint32(0x7C00) + ((f & np.uint32(0x7FFFFF)) >> np.uint32(13))
            if h == np.uint32(0x7C00):
                h = np.uint32(0x7C01)
        else:
            h = np.uint32(0x7C00)
    elif f < np.uint32(0x38800000):           # below the smallest normal half: subnormal or 0
        # Shift the mantissa, with its implicit 1, into place and round to nearest even.
        e = f >> np.uint32(23)
        if e < np.uint32(102):                # below half the smallest subnormal: ±0
            h = np.uint32(0)
        else:
            m = (f & np.uint32(0x7FFFFF)) | np.uint32(0x800000)
            shift = np.uint32(126) - e         # 14 … 24
            h = m >> shift
            rest = m & ((np.uint32(1) << shift) - np.uint32(1))
            halfway = np.uint32(1) << (shift - np.uint32(1))
            if rest > halfway or (rest == halfway and (h & np.uint32(1))):
                h += np.uint32(1)
    else:
        # Normal: rebias the exponent, round the 13 dropped bits to nearest even (a carry
        # into the exponent is right, up to 0x7C00 = inf for 65520 ≤ |x| < 65536).
        h = (f - np.uint32(0x38000000) + np.uint32(0xFFF)
             + ((f >> np.uint32(13)) & np.uint32(1))) >> np.uint32(13)
    return np.uint16(sign | h)


def float32_to_half_bits(src: np.ndarray, out: np.ndarray) -> None:
    """Write the half bits of the C-contiguous (H, W) float32 ``src`` into the (H, W) uint16
    ``out`` (any strides: a column slice of an EXR strip)."""
    # The uint32 view taken here, not in the kernel: numpy's ``view`` inside a kernel compiles
    # an overload of its own (0.4 CPU s of a first render).
    _half_rows(src.view(np.uint32), out)


@njit(cache=True, nogil=True)
def _half_rows(bits: np.ndarray, out: np.ndarray) -> None:
    for y in range(bits.shape[0]):
        for x in range(bits.shape[1]):
            out[y, x] = _half_bits(bits[y, x])
