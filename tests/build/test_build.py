"""Many files into one city (issue 15 point 1): the sample city split into tiles builds the
scene of the one file; duplicates across tile borders are kept once and counted; CityGML and
CityJSON tiles mix; mixed CRSs are refused unless --crs names the target."""
from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from click.testing import CliRunner

from citygml_snippets import box_polygons, building, city, split_citygml
from conftest import REPO, shared_file

from cityshade.cli.main import cli

SAMPLE = REPO / "sample_data" / "sample_city.gml"


@pytest.fixture(scope="module")
def sample_tiles(tmp_path_factory):
    folder = tmp_path_factory.mktemp("tiles")
    shutil.copy(REPO / "sample_data" / "sample_city_facade.png", folder)
    return split_citygml(SAMPLE, folder, 3, overlap=2)


def _same_scene(a, b) -> None:
    """Equal arrays, ids, tables and kd-tree; materials and textures compared by what they
    are (a tiled build numbers them in the order the tiles introduce them)."""
    from cityshade.accel.kdtree_layout import REC_MATERIAL
    from cityshade.geometry.scene import Scene

    for name in Scene.ARRAY_FIELDS:
        if name in ("tri_material", "tri_texture"):
            continue
        assert np.array_equal(getattr(a, name), getattr(b, name), equal_nan=True), name
    assert a.obj_ids == b.obj_ids and a.obj_types == b.obj_types and a.poly_ids == b.poly_ids
    for codes, table, key in (("tri_material", "materials", lambda m: m),
                              ("tri_texture", "textures", lambda t: t["uri"])):
        per_tri = [[key(getattr(s, table)[c]) if c >= 0 else None for c in getattr(s, codes)]
                   for s in (a, b)]
        assert per_tri[0] == per_tri[1], codes
    ta, tb = a.kdtree.to_arrays(), b.kdtree.to_arrays()
    assert ta.keys() == tb.keys()
    for name in ta:
        x, y = np.asarray(ta[name]), np.asarray(tb[name])
        if name.endswith("tri_records"):
            cols = [c for c in range(x.view(np.int32).shape[1]) if c != REC_MATERIAL]
            x, y = x.view(np.int32)[:, cols], y.view(np.int32)[:, cols]
        assert np.array_equal(x, y), name


def test_tiles_build_the_one_file_scene(sample_tiles, sample_city_scene, tmp_path):
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    out, scene, _ = build_file(list(sample_tiles), tmp_path / "tiled.cityshade")
    tiled = load_scene(out)
    _same_scene(sample_city_scene, tiled)
    tiles = tiled.report["tiles"]
    # 2 members repeated at each of the 2 inner borders; each is one object (no parts).
    assert tiles["files"] == 3 and tiles["duplicate_objects"] == 4
    assert [f["duplicates"] for f in tiles["per_file"]] == [0, 2, 2]
    assert len(tiled.obj_ids) == len(set(tiled.obj_ids)) == 36


def test_cli_folder_progress_and_info(sample_tiles, tmp_path):
    out = tmp_path / "city.cityshade"
    result = CliRunner().invoke(cli, ["build", str(sample_tiles[0].parent), "-o", str(out)])
    assert result.exit_code == 0, result.output
    # Not a terminal: one progress line per file.
    assert [l for l in result.output.splitlines() if l.startswith("cityshade: reading")] == [
        f"cityshade: reading {i + 1}/3 tile_{i}.gml" for i in range(3)]
    assert "3 files; 4 objects met again" in result.output
    info = CliRunner().invoke(cli, ["info", str(out)])
    assert info.exit_code == 0 and "tiles         3 files; 4 objects met again" in info.output


def _two_tiles(tmp_path, srs_b="EPSG:25832"):
    a = tmp_path / "a.gml"
    a.write_text(city(building("b1", box_polygons(690_000, 5_336_000, 500, 10, 8, 6))))
    b = tmp_path / "b.gml"
    b.write_text(city(building("b2", box_polygons(690_030, 5_336_000, 500, 5, 5, 20, "q"),
                               srs=srs_b)))
    return a, b


def _one_line_error(result, fragment, code=1):
    assert result.exit_code == code, result.output
    lines = [l for l in result.output.splitlines() if l.strip()
             and not l.startswith("cityshade: reading")]
    assert len(lines) == 1 and lines[0].startswith("cityshade: error: "), result.output
    assert fragment in lines[0], lines[0]


def test_mixed_crs_refused_unless_crs_names_the_target(tmp_path):
    from pyproj import Transformer

    from cityshade.store.scenefile import load_scene

    a, b = _two_tiles(tmp_path, srs_b="EPSG:25833")
    out = tmp_path / "mixed.cityshade"
    _one_line_error(CliRunner().invoke(cli, ["build", str(a), str(b), "-o", str(out)]),
                    "different CRSs")
    assert not out.exists() and list(tmp_path.glob("*.cityshade*")) == []
    result = CliRunner().invoke(cli, ["build", str(a), str(b), "-o", str(out), "--crs",
                                      "EPSG:25832", "-q"])
    assert result.exit_code == 0, result.output
    scene = load_scene(out)
    assert scene.crs.horizontal_epsg == 25832
    # b's corners were read as UTM 33N and projected to 32N by PROJ (independent numbers).
    world = scene.world_from_render(scene.vertices[scene.triangles[scene.tri_object == 1]]
                                    .reshape(-1, 3))
    east, north = Transformer.from_crs(25833, 25832, always_xy=True).transform(690_030.0,
                                                                               5_336_000.0)
    assert abs(east - 690_030) > 1000  # the projection moved it
    assert np.isclose(world[:, 0], east, atol=0.01).any()
    assert np.isclose(world[:, 1], north, atol=0.01).any()


def test_bad_inputs_one_line(tmp_path):
    a, b = _two_tiles(tmp_path)
    _one_line_error(CliRunner().invoke(cli, ["build", str(a), str(b)]), "need -o", code=2)
    empty = tmp_path / "empty"
    empty.mkdir()
    _one_line_error(CliRunner().invoke(cli, ["build", str(empty), "-o", str(tmp_path / "x")]),
                    "no model file")
    _one_line_error(CliRunner().invoke(cli, ["build", str(a), str(tmp_path / "nope.gml"), "-o",
                                             str(tmp_path / "x.cityshade")]), "no such file")
    _one_line_error(CliRunner().invoke(cli, ["build", str(a), str(b), "-o", str(tmp_path / "x"),
                                             "--crs", "EPSG:4326"]), "projected CRS", code=2)


def test_citygml_and_cityjson_tiles_mix(sample_tiles, sample_city_scene, tmp_path):
    """The first tile as CityGML, then the whole city as CityJSON: its objects of the first
    tile are duplicates, the rest fill the city, and the triangles are the one file's."""
    from cityshade.build import build_file
    from cityshade.samplegen import main as samplegen

    cj = tmp_path / "city.city.json"
    samplegen([str(cj), "--format", "cityjson", "--buildings", "30", "--seed", "7"])
    _, scene, _ = build_file([sample_tiles[0], cj], tmp_path / "mixed.cityshade")
    n_first = scene.report["tiles"]["per_file"][0]["objects"]
    in_json = set(json.loads(cj.read_text())["CityObjects"])
    # CityJSON folds the TINRelief into its ReliefFeature: 12 of the first tile's 13 objects.
    assert scene.report["tiles"]["duplicate_objects"] == len(
        in_json & set(sample_city_scene.obj_ids[:n_first])) == 12
    assert scene.report["format"] == "CityGML, CityJSON"
    assert scene.obj_ids == sample_city_scene.obj_ids
    assert np.array_equal(scene.vertices, sample_city_scene.vertices)
    # The same triangles (a CityJSON ring may start at another corner, so one quad of the
    # terrain takes the other diagonal): the polygons' areas agree.
    assert scene.n_triangles == sample_city_scene.n_triangles
    assert np.allclose(scene.poly_area_m2, sample_city_scene.poly_area_m2, rtol=1e-12)


def test_real_tiles(tmp_path):
    """Real data: the TUM campus split into 4 tiles with border duplicates builds the scene
    of the file; the two Lyon district tiles build one city of both."""
    from cityshade.build import build_file

    tum = shared_file("munich-tum-campus-lod2/TUM Munich.gml")
    _, whole, _ = build_file(tum, tmp_path / "tum.cityshade")
    tiles = split_citygml(tum, tmp_path, 4, overlap=3)
    _, tiled, _ = build_file(tiles, tmp_path / "tum_tiled.cityshade")
    _same_scene(whole, tiled)
    assert tiled.report["tiles"]["duplicate_objects"] >= 9
    lyon = shared_file("lyon-small-houses-textured")
    _, scene, _ = build_file([lyon], tmp_path / "lyon.cityshade")
    assert scene.report["tiles"]["files"] == 2 and len(scene.textures) == 2
