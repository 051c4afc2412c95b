"""The ``.cityshade`` file: one versioned, checksummed, memory-mappable file per model.

Layout (little-endian)::

    0   8 bytes   magic b"CITYSHD\\n"
    8   uint32    format version (FORMAT_VERSION)
    12  uint32    reserved (0)
    16  uint64    header length H in bytes
    24  16 bytes  BLAKE2b-128 of the header
    40  H bytes   header: UTF-8 JSON (metadata, tables, array directory)
    ... arrays, each starting at a multiple of 64 bytes (cache-line aligned for the kernels)

The header's ``arrays`` directory gives each array's dtype, shape, offset and BLAKE2b-128
checksum; ``file_size`` is the whole file's size (a truncated file is detected before any
array is touched). Loading memory-maps the file read-only; arrays are views into the map.
Files are written to a temporary name in the same folder and renamed, so an interrupted build
never leaves a half file under the final name.

Verification (docs/SCALE.md): every load checks magic, version, the header's checksum and the
file size. The arrays' checksums (a pass over the whole file: seconds for gigabytes) are
checked once per version of the file: after a full check — while the build writes the file,
or on a load without a trusted stamp, or on ``cityshade info --verify`` — a *verified stamp*
(the file's device, inode, size, mtime and ctime in nanoseconds and its header checksum) is
kept in the user's cache folder. A load whose file still matches its stamp skips the pass;
any write to the file changes its mtime/ctime, so the next load checks every array again
before anything is computed from it. A stamp written within :data:`RACY_S` of the file's
last change is not trusted (a write in the same clock tick would keep the mtime: git's
"racy" rule), so such a file is checked once more on its next load; a large file's build
waits out that window before stamping, so its first load is fast too.
"""
from __future__ import annotations

import functools
import hashlib
import json
import os
import struct
import sys
import threading
import time
from pathlib import Path
from collections.abc import Sequence
from typing import Any, Mapping

import numpy as np

from cityshade.errors import (CacheCorruptError, CacheError, CacheVersionError, ContractError,
                              InputError, OutputError)
from cityshade.util import atomic_write, make_folder

MAGIC = b"CITYSHD\n"
#: Bump on any change of layout or meaning of a stored array; old files are refused.
FORMAT_VERSION = 1
_PREFIX = struct.Struct("<8sIIQ16s")
_ALIGN = 64
_REBUILD = "rebuild it with `cityshade build`"


#: A stamp written sooner than this after the file's last change is not trusted: file times
#: have a clock-tick granularity (Linux's coarse clock: 1-10 ms), and a later write in the
#: same tick would leave them unchanged. Filesystems with coarser times (FAT: 2 s) need
#: ``info --verify`` after a change made within that window.
RACY_S = 0.05
#: Files at least this large wait out :data:`RACY_S` after their rename, so the build's own
#: stamp is trusted and the first load skips the checksum pass (seconds per gigabyte);
#: smaller files are checked once more on their first load, which costs less than the wait.
STAMP_WAIT_BYTES = 256 << 20


def _stamp_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "cityshade" / "verified"


def _stamp_path(path: Path) -> Path:
    key = hashlib.blake2b(str(path.resolve()).encode("utf-8"), digest_size=16).hexdigest()
    return _stamp_dir() / f"{key}.json"


def _file_key(path: Path, header_digest: str) -> dict:
    st = path.stat()
    return {"path": str(path.resolve()), "dev": st.st_dev, "ino": st.st_ino,
            "size": st.st_size, "mtime_ns": st.st_mtime_ns, "ctime_ns": st.st_ctime_ns,
            "header": header_digest}


def write_verified_stamp(path: str | os.PathLike, header_digest: str) -> None:
    """Record that ``path``, as it is now, matches all its checksums (best effort: an
    unwritable cache folder only means the next load checks again)."""
    path = Path(path)
    try:
        key = _file_key(path, header_digest)
        key["stamped_ns"] = time.time_ns()
        stamp = _stamp_path(path)
        stamp.parent.mkdir(parents=True, exist_ok=True)
        tmp = stamp.with_name(f"{stamp.name}.{os.getpid()}.tmp")
        tmp.write_text(json.dumps(key))
        os.replace(tmp, stamp)
    except OSError:
        pass


def _stamp_trusted(path: Path, header_digest: str) -> bool:
    try:
        stamp = json.loads(_stamp_path(path).read_text())
        key = _file_key(path, header_digest)
    except (OSError, ValueError):
        return False
    if not isinstance(stamp, dict) or any(stamp.get(k) != v for k, v in key.items()):
        return False
    stamped = stamp.get("stamped_ns")
    return isinstance(stamped, int) and stamped - max(key["mtime_ns"], key["ctime_ns"]) > RACY_S * 1e9


def _byte_view(a: np.ndarray) -> memoryview:
    """A contiguous array's bytes as a flat memoryview (also of an empty (0, 3) array, which
    ``memoryview.cast`` refuses)."""
    return memoryview(a.reshape(-1).view(np.uint8))


def _digest(data) -> str:
    return hashlib.blake2b(data, digest_size=16).hexdigest()


#: Piece of an array hashed, written (and, consuming, handed back) at a time by
#: :func:`_write_pieces`.
_CONSUME_PIECE_BYTES = 32 << 20


@functools.cache
def _page_releaser():
    """``release(start, lo, hi)``: drop the whole pages of an anonymous memory range
    (``madvise(MADV_DONTNEED)``: they read as zeros after), or None where that is not known."""
    import ctypes
    import mmap

    if not sys.platform.startswith("linux") or not hasattr(mmap, "MADV_DONTNEED"):
        return None
    madvise = ctypes.CDLL(None, use_errno=True).madvise
    madvise.argtypes = (ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int)
    page = mmap.PAGESIZE

    def release(start: int, lo: int, hi: int) -> int:
        """Drop the whole pages from ``lo`` (a page boundary, or ``start``) to ``hi`` of a range
        that starts at ``start``: none before its first whole page (a heap chunk's header) or
        past ``hi`` (its neighbour). Returns where the next call starts."""
        lo = max(lo, -(-start // page) * page)
        hi = hi // page * page
        if hi > lo:
            madvise(lo, hi - lo, mmap.MADV_DONTNEED)
        return max(lo, hi)

    return release


def _anonymous(a: np.ndarray) -> bool:
    """Whether ``a``'s memory is the process's own (not a file map, which would drop file
    pages): a writeable array whose base chain ends in an ndarray or nothing."""
    import mmap

    root = a
    while isinstance(root.base, np.ndarray):
        root = root.base
    return a.flags.writeable and not isinstance(root, np.memmap) and (
        root.base is None or not isinstance(root.base, mmap.mmap))


def _write_pieces(fh, arrays: list, buffers: list, offsets: list, consume: bool) -> list[str]:
    """Hash and write ``buffers`` (of ``arrays``) at ``offsets`` of ``fh`` piece by piece;
    returns the digests, in order. With ``consume``, each piece's pages are handed back once it
    is hashed and written.

    Two threads hash (the arrays split into two groups of about equal bytes, each hashed piece
    by piece in order; hashlib releases the GIL); this thread writes each piece once it is
    hashed. Writing a large file first makes the OS find new page-cache pages; on the virtual
    machines measured here that costs about 2.5 s per GB (10M city: 5.7 s of a 2.1 GB file),
    while pages this process has just freed are reused at memory speed: hence ``consume``.
    Arrays that share memory with another, or are not anonymous memory, are never dropped.
    """
    import queue

    release = _page_releaser() if consume else None
    n = len(buffers)
    droppable = [release is not None and arrays[i].nbytes >= _CONSUME_PIECE_BYTES
                 and _anonymous(arrays[i])
                 and not any(np.may_share_memory(arrays[i], arrays[j]) for j in range(n) if j != i)
                 for i in range(n)]
    groups: list[list[int]] = [[], []]
    loads = [0, 0]
    for i in sorted(range(n), key=lambda i: -buffers[i].nbytes):
        g = 0 if loads[0] <= loads[1] else 1
        groups[g].append(i)
        loads[g] += buffers[i].nbytes
    digests = [""] * n
    freed = [0] * n
    pieces: queue.Queue = queue.Queue(maxsize=8)
    failed: list[BaseException] = []
    stop = threading.Event()

    def hash_group(indices: list[int]) -> None:
        try:
            for i in indices:
                h = hashlib.blake2b(digest_size=16)
                buf = buffers[i]
                for lo in range(0, buf.nbytes, _CONSUME_PIECE_BYTES):
                    if stop.is_set():
                        return
                    piece = buf[lo:lo + _CONSUME_PIECE_BYTES]
                    h.update(piece)
                    pieces.put((i, lo, piece))
                digests[i] = h.hexdigest()
        except BaseException as exc:  # re-raised by the writer
            failed.append(exc)
        finally:
            pieces.put(None)

    threads = [threading.Thread(target=hash_group, args=(g,), daemon=True,
                                name="cityshade-cache-digests") for g in groups]
    for t in threads:
        t.start()
    fd = fh.fileno()
    try:
        done = 0
        while done < len(threads):
            item = pieces.get()
            if item is None:
                done += 1
                continue
            i, lo, piece = item
            written = 0
            while written < piece.nbytes:
                written += os.pwrite(fd, piece[written:], offsets[i] + lo + written)
            if droppable[i]:  # pieces of an array come in order: drop up to this one's end
                address = arrays[i].ctypes.data
                freed[i] = release(address, freed[i] or address, address + lo + piece.nbytes)
    finally:
        stop.set()
        while any(t.is_alive() for t in threads):  # unblock and join the hashers
            try:
                pieces.get(timeout=0.05)
            except queue.Empty:
                pass
        for t in threads:
            t.join()
    if failed:
        raise failed[0]
    return digests


def pack_strings(values: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """Strings → (UTF-8 blob uint8, offsets int64 of length n+1)."""
    if isinstance(values, PackedStrings) and values.packed_whole():
        return values._blob, np.asarray(values._offsets, np.int64)  # packed already
    offsets = np.zeros(len(values) + 1, np.int64)
    data = "".join(values).encode("utf-8")
    lengths = np.fromiter(map(len, values), np.int64, len(values))
    if len(data) != lengths.sum():
        # Not all ASCII (a character is one byte exactly then): the byte length of each.
        # Else one join: no bytes object per string (millions of polygon ids at write time).
        lengths = np.fromiter((len(v.encode("utf-8")) for v in values), np.int64, len(values))
    np.cumsum(lengths, out=offsets[1:])
    return np.frombuffer(data, dtype=np.uint8), offsets


def unpack_strings(blob: np.ndarray, offsets: np.ndarray) -> list[str]:
    """The strings of a :func:`pack_strings` blob, all decoded at once (a tiled build's
    spilled records); :class:`PackedStrings` decodes on access instead."""
    data = bytes(blob)
    return [data[offsets[i]:offsets[i + 1]].decode("utf-8") for i in range(len(offsets) - 1)]


class PackedStrings(Sequence):
    """A read-only list of strings over a :func:`pack_strings` blob, decoded on access.

    A loaded scene's gml:id tables (millions of polygons in a 10^7-triangle city) would take
    most of a load's time to decode as a list, and most commands never read them.
    """

    def __init__(self, blob: np.ndarray, offsets: np.ndarray):
        self._blob = blob
        self._offsets = offsets

    def __len__(self) -> int:
        return len(self._offsets) - 1

    def packed_whole(self) -> bool:
        """True when the blob is exactly the strings, as :func:`pack_strings` makes it."""
        return (self._offsets.size > 0 and int(self._offsets[0]) == 0
                and int(self._offsets[-1]) == self._blob.size)

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        n = len(self)
        i = int(index)
        if i < 0:
            i += n
        if not 0 <= i < n:
            raise IndexError("string index out of range")
        return bytes(self._blob[self._offsets[i]:self._offsets[i + 1]]).decode("utf-8")

    def __iter__(self):
        data = bytes(self._blob)
        offsets = self._offsets.tolist()
        for i in range(len(offsets) - 1):
            yield data[offsets[i]:offsets[i + 1]].decode("utf-8")

    def __eq__(self, other) -> bool:
        if isinstance(other, (list, tuple, PackedStrings)):
            return len(self) == len(other) and all(a == b for a, b in zip(self, other))
        return NotImplemented

    def __repr__(self) -> str:
        return f"PackedStrings({len(self)} strings)"


def write_cache(path: str | os.PathLike, header: Mapping[str, Any],
                arrays: Mapping[str, np.ndarray], consume: bool = False) -> int:
    """Write arrays and a JSON header atomically; returns the file size in bytes.

    Parameters
    ----------
    path : path-like
        Final file name (written as a temporary file in the same folder, then renamed).
    header : mapping
        JSON-serialisable metadata (must not contain the keys ``arrays``/``file_size``).
    arrays : mapping of str to ndarray
        Arrays to store; stored C-contiguous, little-endian, with their dtype and shape.
    consume : bool
        The arrays are not read again: each piece's memory is handed back to the OS as soon as
        it is hashed and written (they then read as zeros), so the file's new page-cache pages
        reuse it instead of pages the OS must first get (:func:`_write_pieces`).
    """
    path = Path(path)
    directory: dict[str, dict] = {}
    prepared = {}
    offset = 0
    for name, array in arrays.items():
        a = np.ascontiguousarray(array)
        if a.dtype.byteorder == ">":
            a = a.astype(a.dtype.newbyteorder("<"))
        prepared[name] = a
    # Digests have one length, so the header's length is known before they are: the arrays are
    # written behind it piece by piece as two threads hash them (_write_pieces), then the
    # header.
    placeholder = _digest(b"")
    for name, a in prepared.items():
        directory[name] = {"dtype": a.dtype.str, "shape": list(a.shape), "offset": offset,
                           "nbytes": int(a.nbytes), "blake2b": placeholder}
        offset += -(-a.nbytes // _ALIGN) * _ALIGN
    full_header = dict(header)
    full_header["arrays"] = directory
    # The data offset depends on the header length, which contains the file size: iterate
    # until the padded header length is stable (twice at most).
    data_start = 0
    for _ in range(4):
        full_header["data_start"] = data_start
        full_header["file_size"] = data_start + offset
        blob = json.dumps(full_header, sort_keys=True, separators=(",", ":")).encode("utf-8")
        needed = -(-(_PREFIX.size + len(blob)) // _ALIGN) * _ALIGN
        if needed == data_start:
            break
        data_start = needed
    if path.parent.exists() and not path.parent.is_dir():
        raise OutputError(f"cannot write here: {path.parent} is not a folder", path=str(path))
    # Recorded, so that a command that fails afterwards removes the folders it made.
    make_folder(path.parent, "folder")
    with atomic_write(path, "wb", fsync=True, what="here") as fh:
        digests = _write_pieces(fh, list(prepared.values()),
                                [_byte_view(a) for a in prepared.values()],
                                [e["offset"] + data_start for e in directory.values()], consume)
        os.ftruncate(fh.fileno(), data_start + offset)  # the last array's padding
        for entry, digest in zip(directory.values(), digests):
            entry["blake2b"] = digest
        final = json.dumps(full_header, sort_keys=True, separators=(",", ":")).encode("utf-8")
        if len(final) != len(blob):
            raise ContractError("a cache header changed its length with its digests")
        blob = final
        fh.seek(0)  # the data went in by pwrite, which leaves the file position alone
        fh.write(_PREFIX.pack(MAGIC, FORMAT_VERSION, 0, len(blob),
                              hashlib.blake2b(blob, digest_size=16).digest()))
        fh.write(blob)
        fh.write(b"\0" * (data_start - _PREFIX.size - len(blob)))
    # The checksums were computed from the very arrays written (and fsynced). The rename set
    # the file's ctime just now: wait out the racy window so the stamp can be trusted.
    if data_start + offset >= STAMP_WAIT_BYTES:
        time.sleep(RACY_S * 1.2)
    write_verified_stamp(path, hashlib.blake2b(blob, digest_size=16).hexdigest())
    return data_start + offset


def is_cache_file(path: str | os.PathLike) -> bool:
    """Whether ``path`` is a cityshade cache file (by its magic bytes, not its name)."""
    try:
        with open(path, "rb") as fh:
            return fh.read(len(MAGIC)) == MAGIC
    except OSError:
        return False


class CacheFile:
    """A loaded cache: :attr:`header` (dict) and :meth:`array` views into a read-only map."""

    def __init__(self, path: Path, header: dict, mm: np.ndarray, header_digest: str = ""):
        self.path = path
        self.header = header
        self._mm = mm
        self.header_digest = header_digest
        #: How the arrays were checked on opening: "full", "stamp" (a trusted verified stamp)
        #: or "none" (``verify=False``).
        self.verified = "none"

    def names(self) -> list[str]:
        return list(self.header["arrays"])

    def array(self, name: str) -> np.ndarray:
        entry = self.header["arrays"].get(name)
        if entry is None:
            raise CacheCorruptError(f"the cache has no array {name!r}; {_REBUILD}",
                                    path=str(self.path))
        start = self.header["data_start"] + entry["offset"]
        raw = self._mm[start:start + entry["nbytes"]]
        return raw.view(np.dtype(entry["dtype"])).reshape(entry["shape"])

    def verify(self) -> None:
        """Check every array against its checksum (one streaming pass over the file), then
        record the verified stamp."""
        for name, entry in self.header["arrays"].items():
            if _digest(_byte_view(np.ascontiguousarray(self.array(name)))) != entry["blake2b"]:
                raise CacheCorruptError(f"array {name!r} does not match its checksum: the file "
                                        f"was modified or damaged; {_REBUILD}", path=str(self.path))
        self.verified = "full"
        if self.header_digest:
            write_verified_stamp(self.path, self.header_digest)


def open_cache(path: str | os.PathLike, verify: bool | str = "auto") -> CacheFile:
    """Open a cache file read-only (memory-mapped).

    Parameters
    ----------
    verify : "auto", True or False
        "auto": check every array's checksum unless a trusted verified stamp says this very
        file was checked (module docstring); True: check them always (``info --verify``);
        False: only the header and the size.

    Raises
    ------
    InputError
        Missing file.
    CacheVersionError
        Written by another format version.
    CacheCorruptError
        Not a cityshade file, truncated, or a checksum mismatch.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("no such file", path=str(path))
    size = path.stat().st_size
    with path.open("rb") as fh:
        prefix = fh.read(_PREFIX.size)
        if len(prefix) < _PREFIX.size or not prefix.startswith(MAGIC):
            if len(prefix) >= 5 and (prefix.lstrip().startswith(b"<") or b"<?xml" in prefix):
                raise CacheError("this is an XML file, not a .cityshade cache; run "
                                 "`cityshade build` on it first", path=str(path))
            raise CacheCorruptError(f"not a .cityshade file (bad magic); {_REBUILD}",
                                    path=str(path))
        _magic, version, _reserved, header_len, header_digest = _PREFIX.unpack(prefix)
        if version != FORMAT_VERSION:
            raise CacheVersionError(f"cache format version {version}, this cityshade reads "
                                    f"version {FORMAT_VERSION}; {_REBUILD}", path=str(path))
        blob = fh.read(header_len)
    if len(blob) != header_len or hashlib.blake2b(blob, digest_size=16).digest() != header_digest:
        raise CacheCorruptError(f"the cache header is truncated or damaged; {_REBUILD}",
                                path=str(path))
    header = json.loads(blob.decode("utf-8"))
    if header.get("file_size") != size:
        raise CacheCorruptError(f"the cache is truncated or has extra bytes (size {size}, "
                                f"expected {header.get('file_size')}); {_REBUILD}", path=str(path))
    mm = np.memmap(path, dtype=np.uint8, mode="r") if size else np.zeros(0, np.uint8)
    cache = CacheFile(path, header, mm, header_digest.hex())
    if verify == "auto" and _stamp_trusted(path, cache.header_digest):
        cache.verified = "stamp"
    elif verify:
        cache.verify()
    return cache
