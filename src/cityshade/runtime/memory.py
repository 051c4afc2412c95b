"""Process memory: pages handed back to the OS, and work arrays kept between frames.

A leaf module: it imports nothing of cityshade.
"""
from __future__ import annotations

import math
import sys
import threading
import weakref

import numpy as np


def release_pages(*arrays) -> int:
    """Drop this process's resident pages of read-only memory-mapped arrays (views into a
    :func:`open_cache` map); other arrays are left alone. Returns the bytes released.

    The pages are clean file pages: they stay in the OS page cache and the next touch maps
    them back unchanged, so the data read is the same, only the resident set shrinks (a whole
    10^7-triangle city read strip by strip otherwise keeps most of its 2.1 GB file resident).
    """
    import mmap

    released = 0
    if not hasattr(mmap, "MADV_DONTNEED"):  # not Linux/BSD: the pages stay, as before
        return released
    for a in arrays:
        if not isinstance(a, np.ndarray) or a.nbytes == 0:
            continue
        root = a
        while isinstance(root.base, np.ndarray):
            root = root.base
        # np.memmap(mode="r") maps with ACCESS_READ: nothing can have written to its pages.
        if not (isinstance(root.base, mmap.mmap) and getattr(root, "mode", None) == "r"):
            continue
        mm = root.base
        base = root.ctypes.data - (root.offset % mmap.ALLOCATIONGRANULARITY)
        # A view's span: strided too (a channel of an (H, W, 3) map spans its whole rows).
        lo = hi = a.ctypes.data - base
        for n, step in zip(a.shape, a.strides):
            lo, hi = (lo + (n - 1) * step, hi) if step < 0 else (lo, hi + (n - 1) * step)
        hi += a.itemsize
        lo -= lo % mmap.PAGESIZE
        hi = min(len(mm), hi + (-hi) % mmap.PAGESIZE)
        if hi > lo:
            mm.madvise(mmap.MADV_DONTNEED, lo, hi - lo)
            released += hi - lo
    return released


def release_freed_memory() -> None:
    """Hand the free pages of the C heap back to the operating system (glibc; elsewhere a no-op).

    The reader's records (hundreds of thousands of small strings and tuples), the scene's
    temporaries and the kd-tree kernel's per-node arrays leave the heap fragmented once freed,
    so without this each build stage would start from the last one's high-water mark
    (measured on the 1M-triangle city: 190 MB of resident memory returned after reading, in
    about 20 ms).
    """
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):  # not glibc (musl has no malloc_trim)
        pass


#: Every :class:`Scratch` and :class:`Recycler` of the process (:func:`release_kept_memory`).
_KEPT: "weakref.WeakSet" = weakref.WeakSet()


def release_kept_memory() -> None:
    """Drop the buffers every :class:`Scratch` and :class:`Recycler` keeps for the next frame
    (arrays in use stay valid: they hold their memory themselves) and trim the C heap, for a
    process done with the work they serve (a one-frame render before it shades and writes:
    the kd-tree's shadow-ray origins, the rasterizer's triangle set-up)."""
    for kept in list(_KEPT):
        kept.clear()
    release_freed_memory()


#: A :class:`Scratch` buffer outgrown is replaced by one 1 / REGROW_SPARE (an eighth) larger
#: than asked for; a first request gets exactly its size (a one-frame render's peak is
#: unchanged).
REGROW_SPARE = 8


class Scratch:
    """Grow-only work arrays kept between calls, for per-frame temporaries of the same sizes.

    A fresh large array is page-faulted in on first touch, and the kernel zeroes every page:
    under load that cost tens to hundreds of ms per frame, and it depended on what ran before
    (which frees left pages the allocator could hand out again). Arrays taken from here are
    touched once and reused. One caller at a time holds a Scratch (:meth:`take`); a concurrent
    call gets a fresh private one, so results never depend on who else runs. The arrays are
    uninitialised and only valid until the holder gives the Scratch back.
    """

    def __init__(self):
        self._arrays: dict = {}
        self._lock = threading.Lock()
        _KEPT.add(self)

    def take(self) -> "Scratch":
        """``self`` when free (release with :meth:`give_back`), else a fresh private one."""
        return self if self._lock.acquire(blocking=False) else Scratch()

    def give_back(self) -> None:
        if self._lock.locked():
            self._lock.release()

    def get(self, name: str, shape, dtype=None):
        """An uninitialised C-contiguous array of ``shape`` (default dtype float64): the first
        bytes of a kept byte buffer of that name that only grows. One name may serve arrays of
        other types one after the other (a caller reuses the memory of an array it is done
        with: every earlier array of the name then sees the new one's values)."""
        import numpy as np

        dtype = np.dtype(np.float64 if dtype is None else dtype)
        shape = tuple(int(x) for x in (shape if isinstance(shape, tuple) else (shape,)))
        nbytes = math.prod(shape) * dtype.itemsize
        buf = self._arrays.get(name)
        if buf is None or buf.size < nbytes:
            # A buffer outgrown is replaced with room to spare: calls of slowly varying sizes
            # (a sky's directions face 2.04-2.14 M of a map's receivers) grew its arrays by
            # 1.1 GB of fresh pages over 145 calls when each took exactly what it asked for.
            size = nbytes if buf is None else nbytes + nbytes // REGROW_SPARE
            self._arrays[name] = None      # the old buffer goes before the new one comes
            buf = self._arrays[name] = np.empty(max(size, 1), np.uint8)
        return buf[:nbytes].view(dtype).reshape(shape)

    def drop(self, *names: str) -> None:
        """Drop the kept buffers of these names (their memory, once arrays made from them are
        gone too), for a caller that will not need them again before it returns."""
        for name in names:
            self._arrays.pop(name, None)

    def clear(self) -> None:
        """Drop the kept arrays (their memory)."""
        self._arrays.clear()


class Recycler:
    """Output arrays whose memory is handed out again once nothing refers to it any more.

    For large per-frame results that a caller keeps as long as it likes (a 4096² depth map and
    its triangle ids: 128 MB; a map frame's 3.4 M shadow-ray origins: 81 MB): :meth:`empty`
    returns the front of a kept buffer of that dtype, at least as large and at most twice, when
    no array made from it is alive (CPython's reference count says so; every view or slice of
    it holds a reference), else a fresh one it keeps instead of the least recently used. Fresh
    pages cost a fault and the kernel's zeroing each (24 ms of a 4096² depth map of the
    1M-triangle city at one thread, 15-150 ms for the origins on a loaded machine). Results
    never depend on it: the arrays are uninitialised either way.
    """

    def __init__(self, keep: int = 4):
        self._keep = int(keep)
        self._buffers: list = []
        self._lock = threading.Lock()
        _KEPT.add(self)

    def empty(self, shape, dtype):
        """An uninitialised C-contiguous array of ``shape`` and ``dtype``."""
        import numpy as np

        dtype = np.dtype(dtype)
        shape = tuple(int(x) for x in (shape if isinstance(shape, tuple) else (shape,)))
        size = max(math.prod(shape), 1)
        with self._lock:
            for i in range(len(self._buffers)):
                buf = self._buffers[i]
                # References: the list, ``buf`` and getrefcount's argument.
                if (buf.dtype == dtype and size <= buf.size <= 2 * size
                        and sys.getrefcount(buf) == 3):
                    self._buffers.append(self._buffers.pop(i))      # most recently used last
                    return buf[:math.prod(shape)].reshape(shape)
            buf = np.empty(size, dtype)
            self._buffers.append(buf)
            if len(self._buffers) > self._keep:
                self._buffers.pop(0)
            return buf[:math.prod(shape)].reshape(shape)

    def clear(self) -> None:
        """Drop the kept buffers (their memory, once their users let go too)."""
        with self._lock:
            self._buffers.clear()
