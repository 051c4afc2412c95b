"""The coordinate parser's interpreted twin (runtime.interpret: small first-use batches) gives
the compiled kernels' bits, and ``_pow10`` is Numba's own ``float ** int``."""
from __future__ import annotations

import numba
import numpy as np
import pytest

import cityshade.citygml.geometry as G
from cityshade.runtime.interpret import InterpretBudget


def _tokens(rng, n):
    """Numbers in every form the kernel reads or refuses: 1-25 digits, fractions, exponents
    from -345 to 289 and past Numba's power cut-off (±65,536), signs, and bad tokens."""
    out = []
    for _ in range(n):
        digits = "".join(rng.choice(list("0123456789"), int(rng.integers(1, 26))))
        cut = int(rng.integers(0, len(digits) + 1))
        text = digits[:cut] + ("." + digits[cut:] if cut < len(digits) else "")
        if rng.random() < 0.2:
            text += f"e{int(rng.integers(-345, 290))}"
        out.append(("-" if rng.random() < 0.3 else "") + text)
    return out + ["1e65536", "1e65537", "1e-65537", "0e70000", "12345678901234567e-70000",
                  "1e999999", "nan", "1.2.3", "+-1", ".5", "5.", "-0", "1e", "1e+", "é1",
                  "179769313486231570000000000000e280", "4.9e-324", "2.4e-324"]


@pytest.mark.parametrize("seed", [0, 1])
def test_interpreted_twin_equals_the_compiled_kernels(monkeypatch, seed):
    rng = np.random.default_rng(seed)
    tokens = _tokens(rng, 3000)
    rings, dims = [], []
    for k in range(0, len(tokens), 12):  # rings of 12 tokens: 3-D, 2-D and some bad counts
        rings.append(" ".join(tokens[k:k + 12]) if k % 5 else ",".join(tokens[k:k + 11]))
        dims.append(3 if k % 3 else 2)
    monkeypatch.setattr(G, "_INTERPRET", InterpretBudget(0))
    compiled = G.parse_ring_texts(rings, dims)
    budget = InterpretBudget(10**9)
    monkeypatch.setattr(G, "_INTERPRET", budget)
    twin = G.parse_ring_texts(rings, dims)
    assert budget.left < 10**9  # it ran interpreted
    assert compiled[0].shape[0] > 1000 and 0 < compiled[2].sum() < len(rings)
    for a, b in zip(compiled, twin):
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True)
        assert a.tobytes() == b.tobytes()  # signs of zeros too


def test_pow10_is_numba_s_float_power():
    """The slow path's power, written out for the twin, is the ``10.0 ** e`` the kernel
    compiled before (Numba: repeated squaring, ``pow`` past 65,536)."""
    power = numba.njit(lambda e: 10.0 ** e)
    written = numba.njit(lambda e: G._pow10(e))
    exps = list(range(-400, 401)) + [65535, 65536, 65537, -65536, -65537, 10**6, -10**6]
    for e in exps:
        assert np.float64(written(e)).tobytes() == np.float64(power(e)).tobytes(), e
