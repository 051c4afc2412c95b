"""The .cityshade file: bit-identical round trip; other versions, truncation, tampering refused."""
from __future__ import annotations

import struct

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city

from cityshade.build import build_file, build_scene_from_file
from cityshade.store.cache import (FORMAT_VERSION, PackedStrings, open_cache, pack_strings,
                             unpack_strings, write_cache)
from cityshade.errors import CacheCorruptError, CacheError, CacheVersionError
from cityshade.geometry.scene import Scene
from cityshade.store.scenefile import load_scene


@pytest.fixture
def built(tmp_path):
    faces = box_polygons(690_000, 5_336_000, 500, 10, 8, 6) + box_polygons(690_020, 5_336_000, 500, 4, 4, 9, "q")
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    src = tmp_path / "city.gml"
    src.write_text(city(building("b1", faces[:6], extra=extra), building("b2", faces[6:])))
    # build_file writes consuming its scene and returns the file's: the scene to compare
    # with is built again, in memory.
    out, _, size = build_file(src, tmp_path / "city.cityshade")
    return out, build_scene_from_file(src, pack_ids=True), size


def test_round_trip_is_bit_identical(built):
    out, scene, size = built
    assert out.stat().st_size == size
    loaded = load_scene(out)
    for name in Scene.ARRAY_FIELDS:
        a, b = getattr(scene, name), getattr(loaded, name)
        assert a.dtype == b.dtype and a.shape == b.shape, name
        assert a.tobytes() == b.tobytes(), name
    assert loaded.obj_ids == scene.obj_ids and loaded.poly_ids == scene.poly_ids
    assert loaded.obj_types == scene.obj_types and loaded.crs == scene.crs
    assert not loaded.vertices.flags.writeable  # a read-only memory map
    if scene.kdtree is not None:
        for name, a in scene.kdtree.to_arrays().items():
            assert a.tobytes() == loaded.kdtree.to_arrays()[name].tobytes(), name


def test_written_bytes_equal_the_obvious_layout(tmp_path, monkeypatch):
    """write_cache hashes on two threads while it writes the arrays behind a header of the
    final length: the file is the one written checksums first, byte for byte (arrays in one
    piece each, and in pieces of 64 bytes)."""
    from reference import reference_cache_bytes

    import cityshade.store.cache as cache

    rng = np.random.default_rng(3)
    arrays = {"xyz": rng.random((1001, 3)), "ids": np.arange(77, dtype=np.int32),
              "empty": np.zeros(0, np.uint8), "flags": rng.integers(0, 2, 9, dtype=np.uint8)}
    header = {"kind": "test", "note": "ünïcode", "n": 5}
    for threshold in (cache._CONSUME_PIECE_BYTES, 64):
        monkeypatch.setattr(cache, "_CONSUME_PIECE_BYTES", threshold)
        path = tmp_path / f"t{threshold}.cache"
        size = cache.write_cache(path, header, arrays)
        data = path.read_bytes()
        assert size == len(data) and data == reference_cache_bytes(header, arrays)


def test_released_pages_of_a_loaded_scene_read_back_the_same(built):
    """release_scene_pages drops the mapped pages of a loaded scene (and nothing of arrays in
    memory); the arrays read afterwards are the same bytes."""
    from cityshade.runtime.memory import release_pages
    from cityshade.store.scenefile import release_scene_pages

    out, scene, _ = built
    loaded = load_scene(out)
    before = {name: getattr(loaded, name).tobytes() for name in Scene.ARRAY_FIELDS}
    assert release_scene_pages(loaded) >= loaded.vertices.nbytes
    assert release_scene_pages(scene) == 0 and release_pages(np.ones(9), None) == 0
    for name in Scene.ARRAY_FIELDS:
        assert getattr(loaded, name).tobytes() == before[name], name


@pytest.mark.parametrize("values", [[], [""], ["B1", "", "B1_p0_r0"],
                                    ["Gebäude", "x", "建物_1", "", "\U0001f3e0"]])
def test_packed_strings_round_trip(values):
    """ASCII ids take the one-join path, others the per-string lengths: both the UTF-8 blob."""
    blob, offsets = pack_strings(values)
    assert bytes(blob) == "".join(values).encode("utf-8")
    assert offsets.tolist() == [0] + np.cumsum([len(v.encode()) for v in values]).tolist()
    assert unpack_strings(blob, offsets) == values
    assert list(PackedStrings(blob, offsets)) == values
    again = pack_strings(PackedStrings(blob, offsets))  # a packed table is written as it is
    assert bytes(again[0]) == bytes(blob) and again[1].tolist() == offsets.tolist()


def test_arrays_are_aligned(built):
    cache = open_cache(built[0])
    for name in cache.names():
        assert (cache.header["data_start"] + cache.header["arrays"][name]["offset"]) % 64 == 0


def test_truncated_file_refused(built):
    out = built[0]
    data = out.read_bytes()
    out.write_bytes(data[:-100])
    with pytest.raises(CacheCorruptError, match="truncated.*rebuild"):
        load_scene(out)
    out.write_bytes(data[:30])
    with pytest.raises(CacheCorruptError, match="rebuild"):
        load_scene(out)


def test_tampered_array_refused(built):
    out = built[0]
    cache = open_cache(out)
    start = cache.header["data_start"] + cache.header["arrays"]["vertices"]["offset"]
    data = bytearray(out.read_bytes())
    data[start + 5] ^= 0xFF
    out.write_bytes(bytes(data))
    with pytest.raises(CacheCorruptError, match="checksum.*rebuild"):
        load_scene(out)


def test_tampered_header_refused(built):
    out = built[0]
    data = bytearray(out.read_bytes())
    i = data.index(b'"cityshade-scene"')
    data[i + 1] = ord("C")
    out.write_bytes(bytes(data))
    with pytest.raises(CacheCorruptError, match="header.*rebuild"):
        load_scene(out)


def test_other_version_refused(built):
    out = built[0]
    data = bytearray(out.read_bytes())
    struct.pack_into("<I", data, 8, FORMAT_VERSION + 1)
    out.write_bytes(bytes(data))
    with pytest.raises(CacheVersionError, match=f"version {FORMAT_VERSION + 1}.*rebuild"):
        load_scene(out)


def test_xml_given_as_cache(tmp_path):
    p = tmp_path / "x.cityshade"
    p.write_text("<?xml version='1.0'?><CityModel/>")
    with pytest.raises(CacheError, match="cityshade build"):
        load_scene(p)


def test_interrupted_write_leaves_no_file(tmp_path, monkeypatch):
    """A write interrupted after the data went out (at fsync) leaves neither file nor temp."""
    import cityshade.store.cache as cache_mod

    target = tmp_path / "out.cityshade"

    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(cache_mod.os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write_cache(target, {"kind": "x"}, {"a": np.arange(1000)})
    assert list(tmp_path.iterdir()) == []


def _age(path, seconds: float = 5.0) -> None:
    """Move the file's times into the past, as if it had been written a while ago (mtime by
    utime; ctime cannot be set, so the stamp is re-made by a full check)."""
    import os

    st = path.stat()
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns - int(seconds * 1e9)))


def test_verified_stamp_skips_the_checksum_pass(built, tmp_path, monkeypatch):
    """A load after a full check trusts the stamp (no pass over the arrays); a file changed
    afterwards is checked again on its next load and its damage is caught."""
    import time

    import cityshade.store.cache as cache_mod

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setattr(cache_mod, "RACY_S", 0.05)
    out = built[0]
    time.sleep(0.1)
    assert open_cache(out, verify=True).verified == "full"  # writes a trusted stamp
    assert open_cache(out).verified == "stamp"
    # Damage the file in place: its times change, so the stamp no longer vouches for it.
    cache = open_cache(out, verify=False)
    start = cache.header["data_start"] + cache.header["arrays"]["triangles"]["offset"]
    data = bytearray(out.read_bytes())
    data[start] ^= 0x01
    out.write_bytes(bytes(data))
    with pytest.raises(CacheCorruptError, match="checksum"):
        open_cache(out)
    with pytest.raises(CacheCorruptError, match="checksum"):
        load_scene(out)


def test_stamp_racy_and_unwritable(built, tmp_path, monkeypatch):
    """A stamp made right after the file's last change is not trusted (a write in the same
    clock tick keeps the times); without a writable cache folder every load checks."""
    import cityshade.store.cache as cache_mod

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    out = built[0]
    assert open_cache(out).verified == "full"  # the build's stamp went to another folder
    # Racy: stamped within RACY_S of the file's last change (ctime: the rename of the build).
    monkeypatch.setattr(cache_mod, "RACY_S", 60.0)
    assert open_cache(out).verified == "full"
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocker))
    assert open_cache(out).verified == "full" and open_cache(out).verified == "full"


def test_info_verify(built, tmp_path, monkeypatch):
    """`info --verify` checks every array even when a stamp vouches for the file."""
    import os

    from click.testing import CliRunner

    import cityshade.store.cache as cache_mod
    from cityshade.cli.main import cli

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setattr(cache_mod, "RACY_S", 0.0)
    out = built[0]
    result = CliRunner().invoke(cli, ["info", str(out), "--verify"])
    assert result.exit_code == 0 and "verified      all" in result.output, result.output
    assert open_cache(out).verified == "stamp"
    # Damage that keeps the size and the mtime (ctime cannot be kept): --verify catches it.
    st = out.stat()
    cache = open_cache(out, verify=False)
    start = cache.header["data_start"] + cache.header["arrays"]["vertices"]["offset"]
    with open(out, "r+b") as fh:
        fh.seek(start)
        byte = fh.read(1)
        fh.seek(start)
        fh.write(bytes([byte[0] ^ 0x10]))
    os.utime(out, ns=(st.st_atime_ns, st.st_mtime_ns))
    result = CliRunner().invoke(cli, ["info", str(out), "--verify"])
    assert result.exit_code == 1 and "checksum" in result.output, result.output


def test_large_build_stamp_is_trusted(tmp_path, monkeypatch):
    """A build of a large file waits out the racy window, so its first load needs no pass."""
    import cityshade.store.cache as cache_mod

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setattr(cache_mod, "STAMP_WAIT_BYTES", 0)
    out = tmp_path / "big.cityshade"
    write_cache(out, {"kind": "x"}, {"a": np.arange(1000)})
    assert open_cache(out).verified == "stamp"


def test_a_consuming_write_gives_the_same_bytes_and_hands_memory_back(tmp_path, monkeypatch):
    """write_cache(consume=True) hashes and writes piece by piece on threads and drops each
    written piece's pages: the file is the obvious layout's, byte for byte; an array it owned
    alone reads as zeros afterwards (its pages went back), while a view sharing memory with
    another array, a read-only array and small arrays are left as they were."""
    from reference import reference_cache_bytes

    import cityshade.store.cache as cache

    monkeypatch.setattr(cache, "_CONSUME_PIECE_BYTES", 1 << 20)
    rng = np.random.default_rng(5)
    big = rng.integers(1, 9, 3_000_000, dtype=np.int64)  # 24 MB: 23 pieces
    shared = rng.random(400_000)
    frozen = rng.random(300_000)
    frozen.flags.writeable = False
    arrays = {"big": big, "shared": shared, "shared_view": shared[100_000:300_000],
              "frozen": frozen, "small": np.arange(5, dtype=np.int16),
              "empty": np.zeros((0, 3), np.float32)}
    expected = reference_cache_bytes({"kind": "t"}, arrays)
    kept = {k: v.copy() for k, v in arrays.items()}
    path = tmp_path / "c.cache"
    size = cache.write_cache(path, {"kind": "t"}, arrays, consume=True)
    data = path.read_bytes()
    assert size == len(data) and data == expected
    if cache._page_releaser() is not None:  # every whole page inside the array: zeros
        lo = (-(-big.ctypes.data // 4096) * 4096 - big.ctypes.data) // 8
        hi = ((big.ctypes.data + big.nbytes) // 4096 * 4096 - big.ctypes.data) // 8
        assert hi - lo > 2_900_000 and not big[lo:hi].any() and big[hi:].all()
    for name in ("shared", "shared_view", "frozen", "small"):
        assert np.array_equal(arrays[name], kept[name]), name
    loaded = open_cache(path, verify=True)
    assert np.array_equal(loaded.array("big"), kept["big"])
