"""A large CityGML file read by two processes: the second half in a child, then merged.

The reader's time goes to lxml and the walker, which hold the GIL, so a second thread cannot
help; a second process can. The file is cut before a top-level member near its middle. This
process reads the first part (the bytes before the cut, then the root's end tag); a child
(``python -m cityshade.citygml.split``) reads the rest behind the file's prolog and root start
tag, so it sees the same namespaces, and sends its :class:`~cityshade.citygml.reader.RawModel`
back pickled. :func:`merge` appends it with every index shifted and the first-wins rules of one
read (ids, rings, aggregates), so the model equals that of one read field for field (tested on
every real file of the test data).

Anything unexpected — no safe cut, the first part not closing at the root (the cut was not
between top-level members), a child that fails, a malformed file — returns None, and the
caller reads the file in one pass, which also gives the error its usual message and line. Only
Ctrl-C and the like propagate; the child is killed then.
"""
from __future__ import annotations

import os
import pickle
import re
import signal
import struct
import subprocess
import sys
import threading
from dataclasses import dataclass
from pathlib import Path

#: Files smaller than this are read in one process: the child's start-up (about 1 s of
#: imports) and the model's transfer outweigh what it saves.
MIN_SPLIT_BYTES = 96 << 20
#: Where the cut is sought, as a share of the file. Past the middle: files often end with
#: their appearances (a material target per polygon), which cost more per byte than geometry
#: (10M sample city: the tail read 0.40 s per percent of the file, the head 0.30 s; measured
#: best at 0.60, 0.52 took 2 s longer).
SPLIT_AT = 0.58
#: How far past SPLIT_AT a member start is sought before giving up.
_SEARCH_BYTES = 64 << 20
_PROLOG_BYTES = 65536
_MEMBER_START = re.compile(
    rb"<(?:[A-Za-z_][\w.\-]*:)?(?:cityObjectMember|featureMember|featureMembers|"
    rb"appearanceMember)[\s>/]")
_XML_DECL_ENCODING = re.compile(rb"^<\?xml[^>]*?encoding\s*=\s*[\"']([^\"']+)")
_ASCII_COMPATIBLE = re.compile(r"^(utf-?8|us-ascii|ascii|iso-?8859-\d+|latin-?1|"
                               r"(windows|cp)-?125\d)$", re.IGNORECASE)
_START_TAG = re.compile(rb"<([^\s>/]+)(?:[^>\"']|\"[^\"]*\"|'[^']*')*>")
_ENV_NO_SPLIT = "CITYSHADE_READ_SPLIT"


@dataclass(frozen=True)
class Plan:
    #: The file's bytes up to the end of the root's start tag (prolog included).
    root_end: int
    #: The root element's qualified name, for the first part's end tag.
    root_qname: bytes
    #: Offset of the top-level member the second part starts with.
    cut: int


def _root_start_tag(head: bytes) -> tuple[int, bytes] | None:
    """(end offset, qualified name) of the root's start tag in the prolog, or None where the
    prolog is not one a byte-level cut can copy (another encoding, an internal DTD subset)."""
    if head.startswith((b"\xff\xfe", b"\xfe\xff", b"\x00", b"\x4c\x6f\xa7\x94")):
        return None  # UTF-16/32 or EBCDIC: the tag search below reads bytes as ASCII
    pos = 3 if head.startswith(b"\xef\xbb\xbf") else 0
    decl = _XML_DECL_ENCODING.match(head, pos)
    if decl and not _ASCII_COMPATIBLE.match(decl.group(1).decode("ascii", "replace")):
        return None
    while True:
        pos = head.find(b"<", pos)
        if pos < 0 or pos + 1 >= len(head):
            return None
        if head.startswith(b"<?", pos):
            end = head.find(b"?>", pos)
            if end < 0:
                return None
            pos = end + 2
        elif head.startswith(b"<!--", pos):
            end = head.find(b"-->", pos)
            if end < 0:
                return None
            pos = end + 3
        elif head.startswith(b"<!", pos):
            end = head.find(b">", pos)
            if end < 0 or b"[" in head[pos:end]:
                return None
            pos = end + 1
        else:
            tag = _START_TAG.match(head, pos)
            if tag is None or head[tag.end() - 2:tag.end()] == b"/>":
                return None
            return tag.end(), tag.group(1)


def plan(path: Path, total: int) -> Plan | None:
    """Where to cut ``path`` for a two-process read, or None to read it in one."""
    if total < MIN_SPLIT_BYTES or os.environ.get(_ENV_NO_SPLIT) == "0":
        return None
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not Linux
        cores = os.cpu_count() or 1
    if cores < 2:
        return None
    return find_cut(path, total, SPLIT_AT)


def _next_member(fh, start: int) -> int | None:
    """Offset of the first top-level member start at or after ``start`` (read in 1 MB steps,
    at most :data:`_SEARCH_BYTES`), or None."""
    overlap = 64  # longer than any match, so one cut in two by a step is found in the next
    pos = start
    while pos < start + _SEARCH_BYTES:
        fh.seek(pos)
        window = fh.read(1 << 20)
        found = _MEMBER_START.search(window)
        if found is not None:
            return pos + found.start()
        if len(window) < 1 << 20:
            return None
        pos += len(window) - overlap
    return None


def find_cut(path: Path, total: int, share: float) -> Plan | None:
    """The first top-level member start at or after ``share`` of the file and after the first
    member (whose end is where one read looks at the root's envelope), or None (none within
    :data:`_SEARCH_BYTES`, or a prolog that cannot be copied)."""
    with path.open("rb") as fh:
        root = _root_start_tag(fh.read(_PROLOG_BYTES))
        if root is None:
            return None
        root_end, qname = root
        first = _next_member(fh, root_end)
        if first is None:
            return None
        cut = _next_member(fh, max(int(total * share), first + 1))
    if cut is None or cut >= total:
        return None
    return Plan(root_end, qname, cut)


class _Head:
    """The first part as a stream: the file's bytes before the cut, then the root's end tag."""

    def __init__(self, fh, cut: int, end_tag: bytes):
        self._fh, self._left, self._end_tag = fh, cut, end_tag

    def read(self, n: int = -1) -> bytes:
        if self._left > 0:
            data = self._fh.read(self._left if n < 0 else min(n, self._left))
            self._left -= len(data)
            if data:
                return data
            self._left = 0
        data, self._end_tag = self._end_tag, b""
        return data

    def tell(self) -> int:
        return self._fh.tell()


class _Tail:
    """The second part as a stream: the prolog and root start tag, newlines up to the cut's
    line, then the file from the cut. The newlines (the root's text, which the reader never
    looks at) give every element the line lxml gives it in one read of the file, quirks past
    line 65535 included. ``tell()`` is the offset in the file, as the reader's truncation
    check expects."""

    def __init__(self, fh, head: bytes, newlines: int, cut: int):
        self._fh, self._head, self._newlines = fh, head, newlines
        fh.seek(cut)

    def read(self, n: int = -1) -> bytes:
        if self._head:
            data, self._head = self._head, b""
            return data
        if self._newlines:
            k = min(self._newlines, 1 << 20)
            self._newlines -= k
            return b"\n" * k
        return self._fh.read(n)

    def tell(self) -> int:
        return self._fh.tell()


def _count_lines(fh, end: int) -> int:
    """Newlines in the first ``end`` bytes of ``fh`` (read in reused 16 MB chunks)."""
    buf = bytearray(16 << 20)
    view = memoryview(buf)
    fh.seek(0)
    count, left = 0, end
    while left > 0:
        n = fh.readinto(view[:min(left, len(buf))])
        if not n:
            break
        count += buf.count(b"\n", 0, n)
        left -= n
    return count


def _merge_ids(into: dict, more: dict, shift: int | None) -> int:
    """Add ``more``'s entries (values plus ``shift``) to ``into`` where its key is new, as
    ``setdefault`` in order would; returns how many keys both had. Dict-level operations, not
    a Python loop over the million ids of a large file."""
    shared = more.keys() & into.keys()
    kept = {key: into[key] for key in shared}
    into.update(zip(more, map(shift.__add__, more.values())) if shift else more)
    into.update(kept)  # a key met before keeps its first value (and its place)
    return len(shared)


def merge(a, b) -> None:
    """Append model ``b`` (the records after ``a``'s in the file) to ``a`` in place, as one
    read of both would have recorded them."""
    import numpy as np

    n_obj, n_poly, n_ring, n_ref = len(a.obj_ids), len(a.poly_ids), len(a.ring_points), len(
        a.ref_target)
    a.versions |= b.versions
    a.obj_ids += b.obj_ids
    a.obj_types += b.obj_types
    a.obj_parent += [p + n_obj if p >= 0 else p for p in b.obj_parent]
    a.obj_time += b.obj_time
    a.obj_codes.update({i + n_obj: codes for i, codes in b.obj_codes.items()})
    a.obj_line += b.obj_line
    a.poly_obj = np.concatenate([a.poly_obj, b.poly_obj + n_obj])
    a.poly_cls = np.concatenate([a.poly_cls, b.poly_cls])
    a.poly_lod = np.concatenate([a.poly_lod, b.poly_lod])
    a.poly_flip = np.concatenate([a.poly_flip, b.poly_flip])
    a.poly_ring0 = np.concatenate([a.poly_ring0, b.poly_ring0 + n_ring])
    a.poly_ids += b.poly_ids
    shared = _merge_ids(a.poly_by_id, b.poly_by_id, n_poly)
    if shared:  # one read counts every later polygon of an id met before
        a.counters["duplicate_gml_ids"] += shared
    _merge_ids(a.ring_by_id, b.ring_by_id, n_ring)
    a.xyz = np.concatenate([a.xyz, b.xyz])
    a.ring_points = np.concatenate([a.ring_points, b.ring_points])
    a.ring_bad = np.concatenate([a.ring_bad, b.ring_bad])
    a.ref_obj = np.concatenate([a.ref_obj, b.ref_obj + n_obj])
    a.ref_cls = np.concatenate([a.ref_cls, b.ref_cls])
    a.ref_lod = np.concatenate([a.ref_lod, b.ref_lod])
    a.ref_flip = np.concatenate([a.ref_flip, b.ref_flip])
    a.ref_target += b.ref_target
    _merge_ids(a.aggregates, {agg_id: (p0 + n_poly, p1 + n_poly, r0 + n_ref, r1 + n_ref)
                              for agg_id, (p0, p1, r0, r1) in b.aggregates.items()}, None)
    a.openings += [(oid, p0 + n_poly, p1 + n_poly) for oid, p0, p1 in b.openings]
    app_a, app_b = a.appearance, b.appearance
    app_a.materials += app_b.materials
    app_a.textures += app_b.textures
    app_a.theme_targets.update(app_b.theme_targets)
    app_a.counters.update(app_b.counters)
    a.srs_names.update(b.srs_names)
    a.counters.update(b.counters)
    a.ade_tags |= b.ade_tags
    if a.ade_tags:  # distinct tags, not the sum of the two parts' counts
        a.counters["ade_elements_skipped"] = len(a.ade_tags)
    a.warnings += b.warnings
    from cityshade.citygml.implicit import merge_records

    a.implicit = merge_records(a.implicit, b.implicit, n_obj)


class _Child:
    """The child reading the second part: its progress (bytes) and its pickled model."""

    def __init__(self, path: Path, plan_: Plan, root_ns: str, generic: frozenset):
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "cityshade.citygml.split", str(path), str(plan_.root_end),
             str(plan_.cut), plan_.root_qname.decode("utf-8", "surrogateescape"), root_ns,
             *sorted(generic)],
            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.done_bytes = 0
        self.payload: bytearray | None = None
        self._out = threading.Thread(target=self._read_out, daemon=True)
        self._err = threading.Thread(target=self._read_err, daemon=True)
        self._out.start()
        self._err.start()

    def _read_out(self) -> None:
        stream = self.proc.stdout
        size = stream.read(8)
        if len(size) != 8:
            return
        (n,) = struct.unpack("<Q", size)
        buf = bytearray(n)
        view, got = memoryview(buf), 0
        while got < n:
            k = stream.readinto(view[got:])
            if not k:
                return
            got += k
        self.payload = buf

    def _read_err(self) -> None:
        for line in self.proc.stderr:  # other lines (a failure's) are dropped: one pass follows
            if line.startswith(b"P "):
                self.done_bytes = int(line[2:])

    def result(self, wait) -> object | None:
        """The child's model (None if it failed); ``wait()`` is called while it runs."""
        while self._out.is_alive():
            wait()
            self._out.join(0.25)
        self._err.join()
        if self.proc.wait() != 0 or self.payload is None:
            return None
        payload, self.payload = self.payload, None
        return pickle.loads(payload)

    def kill(self) -> None:
        """Stop the child (if it still runs) and release its pipes."""
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()
        # The pipes end with the child: the threads reading them see their end and stop.
        self._out.join()
        self._err.join()
        self.proc.stdout.close()
        self.proc.stderr.close()


def read_split(path: Path, plan_: Plan, root_ns: str, progress, generic: frozenset):
    """The model of ``path`` read in two processes, or None (read it in one instead)."""
    from cityshade.errors import CityshadeError

    child = _Child(path, plan_, root_ns, generic)
    try:
        def both_parts(done: int, total: int) -> None:
            progress(min(done, plan_.cut) + child.done_bytes, total)

        try:
            first = read_head(path, plan_, root_ns, progress and both_parts, generic)
        except CityshadeError:
            return None  # malformed, or the cut was not between top-level members
        total = path.stat().st_size
        second = child.result(lambda: progress and both_parts(plan_.cut, total))
        if second is None:
            return None
        merge(first, second)
        return first
    finally:
        child.kill()


def read_head(path: Path, plan_: Plan, root_ns: str, progress, generic: frozenset):
    """The model of the part before the cut (raises where the cut was not between top-level
    members: the root's end tag then closes an inner element)."""
    from cityshade.citygml.reader import read_stream

    with path.open("rb") as fh:
        return read_stream(_Head(fh, plan_.cut, b"</" + plan_.root_qname + b">"),
                           path.stat().st_size, path, root_ns, progress, False, generic)


def read_tail(path: Path, plan_: Plan, root_ns: str, progress, generic: frozenset):
    """The model of the part from the cut on (its objects' lines those of the file)."""
    from cityshade.citygml.reader import read_stream

    with path.open("rb") as fh:
        head = fh.read(plan_.root_end)
        newlines = _count_lines(fh, plan_.cut) - head.count(b"\n")
        return read_stream(_Tail(fh, head, newlines, plan_.cut), path.stat().st_size, path,
                           root_ns, progress, False, generic)


def _child_main(argv: list[str]) -> int:
    """``python -m cityshade.citygml.split PATH ROOT_END CUT ROOT_QNAME ROOT_NS [GENERIC…]``:
    read the part of PATH from CUT on and write its model, pickled, to stdout (8 bytes of
    length first); progress lines ``P BYTES`` go to stderr."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent stops this process
    if sys.platform.startswith("linux"):  # and it ends with the parent, however that ends
        import ctypes

        ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    path = Path(argv[0])
    plan_ = Plan(int(argv[1]), argv[3].encode("utf-8", "surrogateescape"), int(argv[2]))
    root_ns = argv[4]
    err = sys.stderr.buffer
    last = [0]

    def progress(done: int, _total: int) -> None:
        if done - last[0] >= 4 << 20:
            last[0] = done
            err.write(b"P %d\n" % (done - plan_.cut))
            err.flush()

    model = read_tail(path, plan_, root_ns, progress, frozenset(argv[5:]))
    payload = pickle.dumps(model, protocol=pickle.HIGHEST_PROTOCOL)
    out = sys.stdout.buffer
    out.write(struct.pack("<Q", len(payload)))
    out.write(payload)
    out.flush()
    return 0


if __name__ == "__main__":
    try:
        sys.exit(_child_main(sys.argv[1:]))
    except BrokenPipeError:  # the parent is gone
        sys.exit(1)
    except Exception as exc:  # the parent reads the file in one pass instead
        sys.stderr.write(f"{type(exc).__name__}: {exc}\n")
        sys.exit(1)
