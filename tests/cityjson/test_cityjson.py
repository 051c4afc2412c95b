"""CityJSON and CityJSONSeq input: real files against plain ``json.load`` counts, the same city
from both formats, templates, refined LoDs, a sequence written here, and bad input.

The independent counts walk the documents with the standard ``json`` module (not the reader's
msgspec path): objects are the members of ``CityObjects``; polygons are the surfaces of every
MultiSurface/CompositeSurface/Solid/MultiSolid/CompositeSolid (inner shells included, as the
report counts cavities as read), GeometryInstances counting their template's surfaces; ring
points are the indices of every non-empty ring plus one (the reader closes rings as GML does).
"""
from __future__ import annotations

import json

import numpy as np
import pytest
from click.testing import CliRunner

from conftest import SHARED_DATA, shared_file

from cityshade.build import read_model
from cityshade.cityjson.reader import detect_format, read_cityjson
from cityshade.cli.main import cli
from cityshade.config import BuildSettings
from cityshade.errors import EmptyModelError, InputError, UsageError
from cityshade.geometry.scene import build_scene, lod_request_range

#: CityJSON files that must fail, with a fragment of their one-line message.
EXPECTED_FAILURES = {
    "val3dity-testdata/cityjson/completely_empty.json": "the file is empty",
    "val3dity-testdata/cityjson/invalid_json_cityjson.json": ":3: malformed JSON",
    "val3dity-testdata/cityjson/with-errors.json": ":1934: malformed JSON",
}

_DEPTH = {"MultiSurface": 1, "CompositeSurface": 1, "Solid": 2, "MultiSolid": 3,
          "CompositeSolid": 3}


def _cityjson_files():
    if not SHARED_DATA.is_dir():
        return []
    return sorted(p for p in SHARED_DATA.rglob("*") if p.suffix in (".json", ".jsonl")
                  and p.is_file())


def _surfaces(geom: dict, outer_only: bool = False) -> list:
    """Every surface (list of rings) of a geometry, inner shells included unless outer_only."""
    depth = _DEPTH.get(geom.get("type"))
    if depth is None:
        return []
    b = geom["boundaries"]
    if depth == 1:
        return list(b)
    solids = b if depth == 3 else [b]
    return [surface for solid in solids for shell in (solid[:1] if outer_only else solid)
            for surface in shell]


def _independent_counts(doc: dict) -> dict:
    templates = (doc.get("geometry-templates") or {}).get("templates", [])
    n_tv = len((doc.get("geometry-templates") or {}).get("vertices-templates", []))
    polygons = ring_points = instance_vertices = 0
    for obj in doc["CityObjects"].values():
        for geom in obj.get("geometry", []):
            if geom["type"] == "GeometryInstance":
                geom = templates[geom["template"]]
                instance_vertices += n_tv
            polygons += len(_surfaces(geom))
            # Inner shells (cavities) are counted as read but their rings are not kept.
            ring_points += sum(len(r) + 1 for s in _surfaces(geom, True) for r in s if r)
    return {"objects": len(doc["CityObjects"]), "polygons": polygons,
            "vertices": len(doc.get("vertices", [])) + instance_vertices,
            "ring_points": ring_points}


@pytest.mark.shared
@pytest.mark.parametrize("path", _cityjson_files(), ids=lambda p: str(p.relative_to(SHARED_DATA)))
def test_every_cityjson_file_builds_or_fails_cleanly(path):
    rel = str(path.relative_to(SHARED_DATA))
    if rel in EXPECTED_FAILURES:
        with pytest.raises(InputError) as info:
            build_scene(read_model(path))
        assert EXPECTED_FAILURES[rel] in str(info.value), str(info.value)
        assert "\n" not in str(info.value)
        return
    assert detect_format(path) == "cityjson"
    with open(path, encoding="utf-8") as fh:
        doc = json.load(fh)
    expected = _independent_counts(doc)
    raw = read_cityjson(path)
    scene = build_scene(raw)
    assert len(scene.obj_ids) == expected["objects"]
    assert set(scene.obj_ids) == set(doc["CityObjects"])
    assert scene.report["polygons"]["read"] == expected["polygons"]
    assert raw.xyz.shape == (expected["vertices"], 3)
    assert int(raw.ring_points.sum()) == expected["ring_points"] == len(raw.point_vertex)
    assert scene.report["format"] == "CityJSON"
    assert scene.report["versions"] == [doc["version"][:3]]
    assert np.isfinite(scene.vertices).all() and scene.n_triangles > 0
    # Parents precede their children, and every child names its parent.
    for i, p in enumerate(scene.obj_parent):
        if p >= 0:
            assert p < i
            assert doc["CityObjects"][scene.obj_ids[i]]["parents"][0] == scene.obj_ids[p]


def _scene_with_tree(path, tmp_path, name):
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    out, _, _ = build_file(path, tmp_path / f"{name}.cityshade")
    return load_scene(out)


@pytest.mark.shared
def test_same_buildings_from_cityjson_and_citygml3(tmp_path):
    """lod2_buildings_v2.json and lod2_buildings_v3.gml are the same 100 buildings."""
    from cityshade.raster.camera import map_view
    from cityshade.frame.render import render_frame, shadow_mask
    from cityshade.geo.sun import sun_from_angles

    cj = _scene_with_tree(shared_file("citygml4j-samples/lod2_buildings_v2.json"), tmp_path, "j")
    gml = _scene_with_tree(shared_file("citygml4j-samples/lod2_buildings_v3.gml"), tmp_path, "g")
    assert len(cj.obj_ids) == len(gml.obj_ids) == 100
    assert sorted(cj.obj_ids) == sorted(gml.obj_ids)
    assert cj.report["format"] == "CityJSON" and gml.report["format"] == "CityGML"
    assert np.array_equal(np.bincount(cj.poly_class, minlength=32),
                          np.bincount(gml.poly_class, minlength=32))
    assert cj.report["time_range"] == gml.report["time_range"]

    def area_per_object(s):
        v = np.asarray(s.vertices, np.float64)[np.asarray(s.triangles)]
        a = 0.5 * np.linalg.norm(np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), axis=1)
        per = np.bincount(np.asarray(s.tri_object), a, len(s.obj_ids))
        return dict(zip(s.obj_ids, per))

    a_cj, a_gml = area_per_object(cj), area_per_object(gml)
    for oid, area in a_gml.items():
        assert abs(a_cj[oid] - area) <= 1e-6 * area, (oid, a_cj[oid], area)
    sun_cj = sun_from_angles(135.0, 30.0, cj.crs, cj.origin_m)
    sun_gml = sun_from_angles(135.0, 30.0, gml.crs, gml.origin_m)
    m_cj = shadow_mask(render_frame(cj, map_view(cj, 0.5), 20000.0, sun_cj))
    m_gml = shadow_mask(render_frame(gml, map_view(gml, 0.5), 20000.0, sun_gml))
    assert m_cj.shape == m_gml.shape and (m_cj == 0).sum() > 1000
    assert np.array_equal(m_cj, m_gml), f"{(m_cj != m_gml).sum()} of {m_cj.size} pixels differ"


def _placed_template_vertices(doc: dict, geom: dict) -> np.ndarray:
    """World coordinates of an instance's template vertices, straight from the spec text:
    the row-major 4 × 4 matrix applied to the template vertex, plus the reference point."""
    t = doc["transform"]
    ref = np.array(doc["vertices"][geom["boundaries"][0]], float) * t["scale"] + t["translate"]
    m = np.array(geom["transformationMatrix"], float).reshape(4, 4)
    out = []
    for v in doc["geometry-templates"]["vertices-templates"]:
        h = m @ np.array([*v, 1.0])
        out.append(h[:3] / h[3] + ref)
    return np.array(out)


@pytest.mark.shared
@pytest.mark.parametrize("relative", ["cityjson-cjio-samples/dummy/dummy.json",
                                      "val3dity-testdata/cityjson/geomtemplate_2.json"])
def test_geometry_templates_are_placed_by_their_matrix(relative):
    path = shared_file(relative)
    doc = json.loads(path.read_text())
    scene = build_scene(read_cityjson(path))
    for oid, obj in doc["CityObjects"].items():
        for geom in obj.get("geometry", []):
            if geom["type"] != "GeometryInstance":
                continue
            expected = _placed_template_vertices(doc, geom)
            used = {i for s in _surfaces(doc["geometry-templates"]["templates"][geom["template"]])
                    for r in s for i in r}
            expected = expected[sorted(used)]
            o = scene.obj_ids.index(oid)
            tri = np.asarray(scene.triangles)[np.asarray(scene.tri_object) == o]
            world = np.asarray(scene.vertices, np.float64)[np.unique(tri)] + scene.origin_m
            # Every drawn vertex is a placed template vertex (float32 render space: 1 mm)...
            d = np.abs(world[:, None, :] - expected[None, :, :]).max(axis=2).min(axis=1)
            assert d.max() < 1e-3, d.max()
            if scene.report["skipped"]:
                continue  # dummy.json's template has degenerate polygons, skipped
            # ... and the drawn geometry spans them all.
            assert np.allclose(world.min(axis=0), expected.min(axis=0), atol=1e-3)
            assert np.allclose(world.max(axis=0), expected.max(axis=0), atol=1e-3)


@pytest.mark.shared
def test_multi_lod_selection():
    path = shared_file("cityjson-cjio-samples/multi_lod.json")
    doc = json.loads(path.read_text())
    per_lod: dict[str, int] = {}
    for obj in doc["CityObjects"].values():
        for geom in obj["geometry"]:
            per_lod[geom["lod"]] = per_lod.get(geom["lod"], 0) + len(_surfaces(geom))
    raw = read_cityjson(path)
    assert set(per_lod) == {"1.2", "1.3", "2.2"}
    for lod in ("1.2", "1.3", "2.2"):
        scene = build_scene(raw, BuildSettings(lod=float(lod)))
        assert scene.report["polygons"]["drawn"] + sum(scene.report["skipped"].values()) \
            == per_lod[lod]
        assert scene.report["lods_drawn"] == {lod: 10}
    default = build_scene(raw)
    assert default.report["lods_drawn"] == {"2.2": 10}
    assert default.report["lods"] == {"1.2": 10, "1.3": 10, "2.2": 10}
    assert np.array_equal(default.triangles, build_scene(raw, BuildSettings(lod=2.2)).triangles)
    # A whole LoD takes the highest refinement of it each object has.
    assert build_scene(raw, BuildSettings(lod=1)).report["lods_drawn"] == {"1.3": 10}
    with pytest.raises(EmptyModelError, match="at LoD 3"):
        build_scene(raw, BuildSettings(lod=3))


def test_lod_setting_from_toml_and_cli_values():
    from cityshade.config import settings_from_mapping
    from cityshade.errors import ConfigError

    assert settings_from_mapping({"build": {"lod": 2.2}}).build.lod == 2.2
    with pytest.raises(ConfigError, match="one decimal"):
        BuildSettings(lod=2.25)
    with pytest.raises(ConfigError, match="one decimal"):
        BuildSettings(lod=5.0)


def test_lod_request_range():
    assert lod_request_range(None, 10) is None
    assert lod_request_range(2, 1) == (2, 2)
    assert lod_request_range("2.0", 1) == (2, 2)
    assert lod_request_range("2.2", 10) == (22, 22)
    assert lod_request_range(2, 10) == (20, 29)
    with pytest.raises(UsageError, match="CityJSON only"):
        lod_request_range("2.2", 1)
    with pytest.raises(UsageError):
        lod_request_range("5", 10)


def _as_sequence(doc: dict) -> str:
    """A CityJSONSeq of a CityJSON document, written plainly: a header line, then one feature
    per top-level object with its descendants, each with its own (re-indexed) vertices and a
    copy of the appearance."""
    objects = doc["CityObjects"]
    header = {k: v for k, v in doc.items() if k not in ("CityObjects", "vertices", "appearance")}
    lines = [json.dumps({**header, "CityObjects": {}, "vertices": []})]

    def family(oid):
        out = [oid]
        for child in objects[oid].get("children", []):
            out += family(child)
        return out

    for oid, obj in objects.items():
        if obj.get("parents"):
            continue
        members = {k: json.loads(json.dumps(objects[k])) for k in family(oid)}
        local: dict[int, int] = {}

        def renumber(b):
            if isinstance(b, list):
                return [renumber(x) for x in b]
            return local.setdefault(b, len(local))

        for member in members.values():
            for geom in member.get("geometry", []):
                geom["boundaries"] = renumber(geom["boundaries"])
        vertices = [doc["vertices"][i] for i in sorted(local, key=local.get)]
        feature = {"type": "CityJSONFeature", "id": oid, "CityObjects": members,
                   "vertices": vertices}
        if "appearance" in doc:
            feature["appearance"] = doc["appearance"]
        lines.append(json.dumps(feature))
    return "\n".join(lines) + "\n"


@pytest.mark.shared
@pytest.mark.parametrize("relative", ["cityjson-cjio-samples/DH_01_subs.city.json",
                                      "cityjson-cjio-samples/zurich/zurich_subset_lod2.json"])
def test_sequence_builds_to_the_same_scene(relative, tmp_path):
    path = shared_file(relative)
    doc = json.loads(path.read_text())
    seq = tmp_path / "city.jsonl"
    seq.write_text(_as_sequence(doc))
    assert detect_format(seq) == "cityjsonseq"
    a = build_scene(read_model(path))
    b = build_scene(read_model(seq))
    assert b.report["format"] == "CityJSONSeq"
    assert sorted(a.obj_ids) == sorted(b.obj_ids)
    assert np.array_equal(a.origin_m, b.origin_m) and a.n_triangles == b.n_triangles

    def per_object(s):
        """Object id → its triangles (corner coordinates), classes, materials, uv, parent."""
        out = {}
        corners = np.asarray(s.vertices)[np.asarray(s.triangles)]
        uv = np.asarray(s.uv)[np.asarray(s.triangles)]
        for o, oid in enumerate(s.obj_ids):
            sel = np.asarray(s.tri_object) == o
            parent = s.obj_ids[s.obj_parent[o]] if s.obj_parent[o] >= 0 else None
            material = [json.dumps(s.materials[m]) if m >= 0 else None
                        for m in s.tri_material[sel]]
            out[oid] = (corners[sel], s.tri_class[sel], material, uv[sel], parent,
                        s.obj_t_begin_days[o])
        return out

    pa, pb = per_object(a), per_object(b)
    for oid, fields in pa.items():
        for x, y in zip(fields, pb[oid]):
            assert np.array_equal(x, y), oid


def test_sample_city_is_the_same_in_all_three_formats(tmp_path):
    """The generator's CityJSON and CityJSONSeq give the CityGML city's triangles bit for bit
    (the GML's ReliefFeature wrapper is the one object CityJSON does not have)."""
    from cityshade.samplegen import generate_city

    scenes = {}
    for fmt, name in (("citygml", "c.gml"), ("cityjson", "c.json"), ("cityjsonseq", "c.jsonl")):
        generate_city(tmp_path / name, n_buildings=6, seed=3, output_format=fmt)
        scenes[fmt] = build_scene(read_model(tmp_path / name))
    gml, cj, seq = scenes["citygml"], scenes["cityjson"], scenes["cityjsonseq"]
    assert seq.report["format"] == "CityJSONSeq" and cj.report["format"] == "CityJSON"
    assert len(cj.obj_ids) == len(gml.obj_ids) - 1
    for other in (cj, seq):
        for name in ("vertices", "triangles", "tri_class", "tri_texture", "uv",
                     "tri_t_begin_days", "tri_t_end_days"):
            assert np.array_equal(getattr(gml, name), getattr(other, name)), name
        # Areas are float64 from float64 coordinates: millimetre integers × 0.001 + translate
        # and the GML's decimal text round to doubles a few ulps apart.
        assert np.allclose(gml.poly_area_m2, other.poly_area_m2, rtol=1e-12, atol=0)
        diffuse = [np.array([m["diffuse"] for m in s.materials])[s.tri_material]
                   for s in (gml, other)]
        assert np.array_equal(*diffuse)
    assert cj.report["time_range"] == gml.report["time_range"]


# --- bad input through the CLI ----------------------------------------------------------------

def _run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def _one_line_error(result, fragment, code=1):
    assert result.exit_code == code, result.output
    assert "Traceback" not in result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("cityshade: error: "), result.output
    assert fragment in lines[0], lines[0]


_CUBE = {"type": "CityJSON", "version": "2.0",
         "transform": {"scale": [0.01, 0.01, 0.01], "translate": [100000.0, 400000.0, 0.0]},
         "metadata": {"referenceSystem": "urn:ogc:def:crs:EPSG::7415"},
         "CityObjects": {"b1": {"type": "Building", "attributes": {"yearOfConstruction": 1931},
                                "geometry": [{"type": "Solid", "lod": "1.2", "boundaries": [[
                                    [[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]],
                                    [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]],
                                    "semantics": {"surfaces": [{"type": "GroundSurface"},
                                                               {"type": "RoofSurface"},
                                                               {"type": "WallSurface"}],
                                                  "values": [[0, 1, 2, 2, 2, 2]]}}]}},
         "vertices": [[0, 0, 0], [1000, 0, 0], [1000, 1000, 0], [0, 1000, 0],
                      [0, 0, 1000], [1000, 0, 1000], [1000, 1000, 1000], [0, 1000, 1000]]}


def _write(tmp_path, doc, name="city.json"):
    path = tmp_path / name
    path.write_text(doc if isinstance(doc, str) else json.dumps(doc))
    return path


def test_small_cube_builds_with_classes_time_and_crs(tmp_path):
    out = tmp_path / "cube.cityshade"
    result = _run("build", _write(tmp_path, _CUBE), "-o", out)
    assert result.exit_code == 0, result.output
    info = _run("info", out, "--json")
    d = json.loads(info.output)
    assert d["input_format"] == "CityJSON" and d["citygml_versions"] == ["2.0"]
    assert d["triangles"] == 12 and d["surface_classes"] == {"roof": 2, "wall": 8, "ground": 2}
    assert d["time_range"][0] == "1931-01-01" and d["crs"]["horizontal_epsg"] == 28992
    assert d["lods_drawn"] == {"1.2": 1}
    text = _run("info", _write(tmp_path, _CUBE, "again.json"))
    assert text.exit_code == 0 and "CityJSON      2.0" in text.output
    assert _run("build", tmp_path / "again.json", "-o", out, "--lod", "1.2").exit_code == 0
    _one_line_error(_run("build", tmp_path / "again.json", "-o", tmp_path / "x.cityshade",
                         "--lod", "2.2"), "at LoD 2.2")


@pytest.mark.parametrize("content, fragment", [
    ("", "the file is empty"),
    ("{\n  \"type\": \"CityJSON\",\n  \"version\": \"2.0\"\n  \"x\": 1}", ":4: malformed JSON"),
    ('{"type": "CityJSON", "version": "2.0", "CityObjects": {}, "vertices": [[1, 2, 3]',
     "malformed JSON: the file is truncated"),
    ('[1, 2, 3]', "not a CityJSON file"),
    ('{"type": "FeatureCollection", "features": []}', "not a CityJSON file: type 'FeatureCollection'"),
    (json.dumps({**_CUBE, "version": "3.0"}), "CityJSON version 3.0 is not supported"),
    (json.dumps({**_CUBE, "CityObjects": {}}), "no city objects"),
    (json.dumps({**_CUBE, "vertices": _CUBE["vertices"][:7]}), "vertex index 7 is out of range"),
    (json.dumps({**_CUBE, "vertices": [[0, 0, "a"]] + _CUBE["vertices"][1:]}),
     "not all [x, y, z] numbers"),
    (json.dumps({**_CUBE, "CityObjects": {"b1": {"type": "Building", "geometry": [
        {"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, None]]]}]}}}),
     "not arrays of vertex indices"),
])
def test_bad_cityjson_fails_with_one_line_and_writes_nothing(tmp_path, content, fragment):
    path = _write(tmp_path, content)
    out = tmp_path / "out.cityshade"
    _one_line_error(_run("build", path, "-o", out), fragment)
    assert not out.exists() and [p.name for p in tmp_path.iterdir()] == ["city.json"]


def test_format_is_told_from_the_content(tmp_path):
    """A CityJSON named .gml (with a UTF-8 BOM), and a CityJSONSeq named .json, build."""
    odd = tmp_path / "cube.gml"
    odd.write_bytes(b"\xef\xbb\xbf" + json.dumps(_CUBE, indent=1).encode())
    assert detect_format(odd) == "cityjson"
    assert build_scene(read_model(odd)).n_triangles == 12
    header = {k: v for k, v in _CUBE.items() if k != "CityObjects"}
    feature = {"type": "CityJSONFeature", "id": "b1", "CityObjects": _CUBE["CityObjects"],
               "vertices": _CUBE["vertices"]}
    seq = _write(tmp_path, json.dumps({**header, "CityObjects": {}, "vertices": []}) + "\n"
                 + json.dumps(feature) + "\n", "seq.json")
    assert detect_format(seq) == "cityjsonseq"
    assert build_scene(read_model(seq)).report["format"] == "CityJSONSeq"


def test_bad_sequence_line(tmp_path):
    header = {k: v for k, v in _CUBE.items() if k != "CityObjects"}
    feature = {"type": "CityJSONFeature", "id": "b1", "CityObjects": _CUBE["CityObjects"],
               "vertices": _CUBE["vertices"]}
    good = json.dumps({**header, "CityObjects": {}, "vertices": []}) + "\n" + json.dumps(feature)
    path = _write(tmp_path, good + "\n", "city.jsonl")
    assert build_scene(read_model(path)).n_triangles == 12
    _write(tmp_path, good + "\n" + json.dumps({**feature, "type": "Feature"}) + "\n", "city.jsonl")
    _one_line_error(_run("build", path, "-o", tmp_path / "o.cityshade"),
                    "line 3 of the CityJSONSeq is not a CityJSONFeature")
    _write(tmp_path, good + "\n" + json.dumps(feature)[:-9] + "\n", "city.jsonl")
    _one_line_error(_run("build", path, "-o", tmp_path / "o.cityshade"), ":3: malformed JSON")


def test_time_attribute_and_creation_dates_follow_the_citygml_rules(tmp_path):
    """``--time-attribute`` reads a producer's own attribute (3D BAG's construction year), and
    ``creationDate`` (a database time) is used only with ``--time-source creation``."""
    obj = dict(_CUBE["CityObjects"]["b1"])
    obj["attributes"] = {"oorspronkelijkbouwjaar": 1905, "creationDate": "2015-12-14"}
    path = _write(tmp_path, {**_CUBE, "CityObjects": {"b1": obj}})
    out = tmp_path / "t.cityshade"
    for args, first_day in ((("--time-attribute", "begin=oorspronkelijkbouwjaar"), "1905-01-01"),
                            (("--time-source", "creation"), "2015-12-14")):
        result = _run("build", path, "-o", out, *args)
        assert result.exit_code == 0, result.output
        assert json.loads(_run("info", out, "--json").output)["time_range"][0] == first_day
    result = _run("build", path, "-o", out)
    assert result.exit_code == 0 and "creationDate" in result.output  # the warning
    assert json.loads(_run("info", out, "--json").output)["time_range"] is None


def test_index_globalizing_twin_equals_the_compiled_kernel():
    """Small documents on first use globalize their vertex indices with the kernel's Python
    source (runtime.interpret): the same indices, and the same first bad position."""
    from cityshade.cityjson.reader import _globalize_indices
    from cityshade.runtime.interpret import python_twin

    rng = np.random.default_rng(4)
    counts = rng.integers(1, 50, 40)
    sizes = rng.integers(0, 30, 40)
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    bases = np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64)
    flat = np.concatenate([rng.integers(0, c, s) for c, s in zip(counts, sizes)]).astype(np.int64)
    bad = flat.copy()
    bad[int(starts[30]) + 1 if sizes[30] > 1 else -1] = 10**6
    for indices in (flat, bad):
        got = []
        for kernel in (_globalize_indices, python_twin(_globalize_indices)):
            out = indices.copy()
            got.append((int(kernel(out, starts, bases, counts.astype(np.int64))), out))
        assert got[0][0] == got[1][0] and got[0][1].tobytes() == got[1][1].tobytes()
    assert got[0][0] > 0                      # the bad case stopped at its first bad index
