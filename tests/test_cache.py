"""The .cityshade file: bit-identical round trip; other versions, truncation, tampering refused."""
from __future__ import annotations

import struct

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city

from cityshade.build import build_file
from cityshade.cache import FORMAT_VERSION, open_cache, write_cache
from cityshade.errors import CacheCorruptError, CacheError, CacheVersionError
from cityshade.geometry.scene import Scene
from cityshade.scenefile import load_scene


@pytest.fixture
def built(tmp_path):
    faces = box_polygons(690_000, 5_336_000, 500, 10, 8, 6) + box_polygons(690_020, 5_336_000, 500, 4, 4, 9, "q")
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    src = tmp_path / "city.gml"
    src.write_text(city(building("b1", faces[:6], extra=extra), building("b2", faces[6:])))
    out, scene, size = build_file(src, tmp_path / "city.cityshade")
    return out, scene, size


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
    import cityshade.cache as cache_mod

    target = tmp_path / "out.cityshade"

    def interrupted(fd):
        raise KeyboardInterrupt

    monkeypatch.setattr(cache_mod.os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write_cache(target, {"kind": "x"}, {"a": np.arange(1000)})
    assert list(tmp_path.iterdir()) == []
