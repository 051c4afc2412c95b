"""Coordinate text → float64 rings, as one Numba pass over a whole batch of rings.

The reader collects the text of every ring (``gml:posList``, the ``gml:pos`` of a ring joined,
or ``gml:coordinates`` with its separators normalised) and hands a batch of them to
:func:`parse_ring_texts`, which joins them with ``;`` and parses all numbers in one kernel call.
Per-ring Python work is one string append; per-number work runs in machine code.
:class:`RingParser` runs the kernels of each batch on a second thread while the reader goes on
(lxml holds the GIL; the kernels release it).
"""
from __future__ import annotations

import math
import queue
import threading

import numpy as np
from numba import njit

from cityshade.runtime.interpret import InterpretBudget, python_twin

#: Byte that separates rings in a batch (never part of a number or of GML whitespace).
RING_SEPARATOR = ";"

# Exact powers of ten: for a mantissa below 2**53 and |exponent| <= 22, one multiplication or
# division by these is correctly rounded (Clinger's fast path), which covers every coordinate
# written with up to 15 significant digits — all real CityGML we have seen.
_POW10 = np.array([10.0 ** k for k in range(23)], dtype=np.float64)


@njit(cache=True, inline="always")
def _digit_run(buf, i, n, mantissa, n_digits, exponent, fraction):
    """Read the digits from ``buf[i]`` on into the mantissa (at most 19 significant digits,
    exact in uint64): past 19 an integer digit scales by 10 (``exponent`` + 1) and a fraction
    digit is dropped; each taken fraction digit is ``exponent`` − 1. Returns the next index,
    the mantissa, the significant-digit count, the exponent and whether a digit was seen."""
    seen = False
    while i < n and 48 <= buf[i] <= 57:
        seen = True
        if n_digits < 19:
            mantissa = mantissa * np.uint64(10) + np.uint64(buf[i] - 48)
            if mantissa > 0:
                n_digits += 1
            if fraction:
                exponent -= 1
        elif not fraction:
            exponent += 1
        i += 1
    return i, mantissa, n_digits, exponent, seen


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _pow10(exponent):
    """``10.0 ** exponent`` as Numba computes ``float ** int`` (repeated squaring, 1 / r for a
    negative exponent), written out so that the kernel's interpreted twin gets the same bits
    (Python's ``**`` calls C's ``pow``); past 65,536 Numba calls ``pow``, which gives inf or 0."""
    exp = -exponent if exponent < 0 else exponent
    if exp > 0x10000:
        return 0.0 if exponent < 0 else math.inf
    a = 10.0
    r = 1.0
    while exp != 0:
        if exp & 1:
            r *= a
        exp >>= 1
        a *= a
    return 1.0 / r if exponent < 0 else r


@njit(cache=True, nogil=True)
def _parse_kernel(buf, pow10):
    """Parse whitespace/comma separated decimal numbers; ``;`` ends a ring.

    Returns (values, ring_value_end, ring_bad) where ring r owns
    values[ring_value_end[r-1]:ring_value_end[r]] and ring_bad[r] is 1 when the ring held a token
    that is not a finite decimal number (such tokens are dropped).
    """
    n = buf.shape[0]
    # Sized for the worst case (one number per two bytes) without a counting pass: the pages
    # past the numbers actually written are never touched, so they never become resident
    # (measured: peak RSS is the same as with an exact count, and the kernel 10 % faster).
    values = np.empty(n // 2 + 1, dtype=np.float64)
    n_rings = 1
    for i in range(n):
        if buf[i] == 59:  # ';'
            n_rings += 1
    ring_end = np.empty(n_rings, dtype=np.int64)
    ring_bad = np.zeros(n_rings, dtype=np.uint8)
    nv = 0
    ring = 0
    i = 0
    while i < n:
        c = buf[i]
        # Skip separators: space, tab, newline, carriage return, comma.
        if c == 32 or c == 9 or c == 10 or c == 13 or c == 44:
            i += 1
            continue
        if c == 59:
            ring_end[ring] = nv
            ring += 1
            i += 1
            continue
        # Parse one token: [sign] digits [. digits] [e [sign] digits].
        negative = False
        if c == 45 or c == 43:
            negative = c == 45
            i += 1
        mantissa = np.uint64(0)
        n_digits = 0
        exponent = 0
        seen_digit = False
        i, mantissa, n_digits, exponent, seen_digit = _digit_run(
            buf, i, n, mantissa, n_digits, exponent, False)
        if i < n and buf[i] == 46:  # '.'
            i, mantissa, n_digits, exponent, seen_fraction = _digit_run(
                buf, i + 1, n, mantissa, n_digits, exponent, True)
            seen_digit = seen_digit or seen_fraction
        if seen_digit and i < n and (buf[i] == 101 or buf[i] == 69):  # 'e' / 'E'
            j = i + 1
            exp_negative = False
            if j < n and (buf[j] == 45 or buf[j] == 43):
                exp_negative = buf[j] == 45
                j += 1
            if j < n and 48 <= buf[j] <= 57:
                e = 0
                while j < n and 48 <= buf[j] <= 57:
                    if e < 100000:
                        e = e * 10 + (buf[j] - 48)
                    j += 1
                exponent += -e if exp_negative else e
                i = j
        # A token must end at a separator; anything else (letters, 'nan', '1.2.3') is bad.
        if not seen_digit or (i < n and not (buf[i] == 32 or buf[i] == 9 or buf[i] == 10
                                            or buf[i] == 13 or buf[i] == 44 or buf[i] == 59)):
            ring_bad[ring] = 1
            while i < n and not (buf[i] == 32 or buf[i] == 9 or buf[i] == 10 or buf[i] == 13
                                 or buf[i] == 44 or buf[i] == 59):
                i += 1
            continue
        value = float(mantissa)
        if mantissa < np.uint64(9007199254740992) and -22 <= exponent <= 22:
            if exponent >= 0:
                value = value * pow10[exponent]
            else:
                value = value / pow10[-exponent]
        elif exponent != 0:
            value = value * _pow10(exponent)
        if not np.isfinite(value):
            ring_bad[ring] = 1
            continue
        values[nv] = -value if negative else value
        nv += 1
    ring_end[ring] = nv
    return values[:nv], ring_end, ring_bad


@njit(cache=True, nogil=True)
def _rings_to_xyz(values, ring_value_end, ring_dim, ring_bad):
    """Reshape parsed numbers to (N, 3) points per ring; 2-D rings get z = 0.

    A ring whose number count is not a multiple of its dimension is marked bad and gets no points.
    """
    n_rings = ring_value_end.shape[0]
    n_points = 0
    start = 0
    for r in range(n_rings):
        count = ring_value_end[r] - start
        if count % ring_dim[r] != 0:
            ring_bad[r] = 1
        elif ring_bad[r] == 0:
            n_points += count // ring_dim[r]
        start = ring_value_end[r]
    xyz = np.empty((n_points, 3), dtype=np.float64)
    ring_points = np.zeros(n_rings, dtype=np.int64)
    k = 0
    start = 0
    for r in range(n_rings):
        end = ring_value_end[r]
        if ring_bad[r] == 0:
            dim = ring_dim[r]
            m = (end - start) // dim
            for p in range(m):
                base = start + p * dim
                xyz[k, 0] = values[base]
                xyz[k, 1] = values[base + 1]
                xyz[k, 2] = values[base + 2] if dim >= 3 else 0.0
                k += 1
            ring_points[r] = m
        start = end
    return xyz, ring_points


def parse_ring_texts(texts: list[str], dims: list[int]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Parse the coordinate texts of a batch of rings.

    Parameters
    ----------
    texts : list of str
        One whitespace-separated coordinate string per ring (commas count as whitespace).
    dims : list of int
        ``srsDimension`` of each ring: 2 or 3 (other values make the ring bad).

    Returns
    -------
    xyz : (N, 3) float64
        All points of all rings in order (2-D rings get z = 0).
    ring_points : (R,) int64
        Number of points of each ring (0 for a bad ring).
    ring_bad : (R,) uint8
        1 where the ring held text that is not a finite number or a count that does not fit
        its dimension.
    """
    if not texts:
        return np.empty((0, 3)), np.empty(0, np.int64), np.empty(0, np.uint8)
    return _parse_encoded(_encode(texts), dims)


def _encode(texts: list[str]) -> np.ndarray:
    """The rings' texts joined by :data:`RING_SEPARATOR`, as ASCII bytes."""
    joined = RING_SEPARATOR.join(texts)
    # Non-ASCII characters cannot belong to a number: '?' makes the kernel flag the ring.
    return np.frombuffer(joined.encode("ascii", "replace"), dtype=np.uint8)


#: Bytes of coordinate text a process parses with the kernels' Python source while they are
#: neither compiled nor cached (:mod:`cityshade.runtime.interpret`): about 1.7 µs a byte
#: interpreted (the sample city's 114 kB: 0.2 s) against some 2 CPU s of compiling on first use.
INTERPRET_BYTES = 256_000
_INTERPRET = InterpretBudget(INTERPRET_BYTES, _parse_kernel, _rings_to_xyz)


def _parse_encoded(buf: np.ndarray, dims: list[int]):
    parse, to_xyz = _parse_kernel, _rings_to_xyz
    if _INTERPRET.take(buf.shape[0]):
        # A memoryview: its items are Python ints, which the interpreter reads faster.
        parse, to_xyz, buf = python_twin(_parse_kernel), python_twin(_rings_to_xyz), memoryview(buf)
    values, ring_end, ring_bad = parse(buf, _POW10)
    dim_arr = np.asarray(dims, dtype=np.int64)
    valid_dim = (dim_arr == 2) | (dim_arr == 3)
    ring_bad[~valid_dim] = 1
    dim_arr[~valid_dim] = 3
    xyz, ring_points = to_xyz(values, ring_end, dim_arr, ring_bad)
    return xyz, ring_points, ring_bad


class RingParser:
    """:func:`parse_ring_texts` of successive batches on a second thread, results in order.

    The reader spends most of its time in lxml, which holds the GIL; the parse kernels release
    it, so a batch parses on the other core while the next one is read (about 5 s of the 10M
    city's 29 s read). Joining and encoding a batch stay on the caller's thread (they need the
    GIL anyway). At most ``max_pending`` encoded batches wait, which bounds the memory held.
    """

    def __init__(self, max_pending: int = 2):
        self._jobs: queue.Queue = queue.Queue(maxsize=max_pending)
        self._results: list = []
        self._thread: threading.Thread | None = None

    def submit(self, texts: list[str], dims: list[int]) -> None:
        if self._thread is None:
            self._thread = threading.Thread(target=self._run, name="cityshade-ring-parse",
                                            daemon=True)
            self._thread.start()
        self._jobs.put((_encode(texts), dims))

    def _run(self) -> None:
        while (job := self._jobs.get()) is not None:
            try:
                self._results.append(_parse_encoded(*job))
            except BaseException as exc:  # re-raised by results()
                self._results.append(exc)

    def results(self) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """(xyz, ring_points, ring_bad) of every batch submitted, in order."""
        self.close()
        for out in self._results:
            if isinstance(out, BaseException):
                raise out
        results, self._results = self._results, []
        return results

    def close(self) -> None:
        """Wait for the batches submitted (a failed read calls it too, so no thread lingers)."""
        if self._thread is not None:
            self._jobs.put(None)
            self._thread.join()
            self._thread = None
