"""Evergreen crowns from the data (issue 38): veg:class / veg:function / veg:usage /
veg:species (CityJSON: the attributes of those names) kept per vegetation object and matched
against ``[vegetation] evergreen_values``."""
from __future__ import annotations

import json

from click.testing import CliRunner
from citygml_snippets import box_polygons, building, city, ground, tree

from cityshade.build import build_file
from cityshade.cli.main import cli
from cityshade.config import VegetationSettings
from cityshade.geometry.vegetation import (evergreen_objects, object_codes, scene_vegetation,
                                           window_light_scene)
from cityshade.store.scenefile import load_scene


def _trees_file(path):
    """Four crowns: A a "Nadelbaum" (German free text), B an oak with a numeric function code,
    C without codes, D a PlantCover whose class says "Evergreen"; and a house."""
    path.write_text(city(
        ground(-50, -50, 50, 50),
        tree("A", box_polygons(-5, -5, 5, 4, 4, 6, "a"), codes=[("class", "Nadelbaum")]),
        tree("B", box_polygons(5, -5, 5, 4, 4, 6, "b"),
             codes=[("function", "1010"), ("species", "Quercus robur")]),
        tree("C", box_polygons(15, -5, 5, 4, 4, 6, "c")),
        tree("D", box_polygons(25, -5, 5, 4, 4, 6, "d"), kind="PlantCover",
             codes=[("class", " Evergreen ")]),
        building("H", box_polygons(-30, -30, 0, 10, 10, 10, "h"))))
    return path


def test_codes_are_kept_and_decide_which_crowns_stay_in_leaf(tmp_path):
    out, _, _ = build_file(_trees_file(tmp_path / "trees.gml"), tmp_path / "trees.cityshade")
    scene = load_scene(out)
    ids = {scene.obj_ids[i]: codes for i, codes in object_codes(scene).items()}
    assert ids == {"A": {"class": ["Nadelbaum"]},
                   "B": {"function": ["1010"], "species": ["Quercus robur"]},
                   "D": {"class": ["Evergreen"]}}
    settings = VegetationSettings()
    veg = scene_vegetation(scene)
    assert [scene.obj_ids[o] for o in veg.crown_object] == ["A", "B", "C", "D"]
    assert veg.evergreen(settings).tolist() == [True, False, False, True]
    # Leafless: the evergreen crowns keep their in-leaf 3 %, the others let half through.
    assert veg.transmissivity(settings, 20).tolist() == [0.03, 0.5, 0.5, 0.03]
    assert veg.transmissivity(settings, 180).tolist() == [0.03] * 4
    # A file's own code list: function 1010 named evergreen in the settings.
    by_code = VegetationSettings(evergreen_values=("1010",))
    assert veg.transmissivity(by_code, 20).tolist() == [0.5, 0.03, 0.5, 0.5]
    objects = evergreen_objects(scene, settings)
    assert sorted(scene.obj_ids[i] for i in objects.nonzero()[0]) == ["A", "D"]
    # compare's windows (BRE 209): the deciduous crowns B and C leave, A and D stay.
    kept = window_light_scene(scene)
    assert sorted({kept.obj_ids[o] for o in kept.tri_object}) == ["A", "D", "H", "ground"]


def test_codes_survive_a_many_file_build(tmp_path):
    """Objects are renumbered when files are merged: the codes follow their objects."""
    house = tmp_path / "house.gml"
    house.write_text(city(building("H", box_polygons(-30, -30, 0, 10, 10, 10, "h"))))
    trees = _trees_file(tmp_path / "trees.gml")
    out, _, _ = build_file([house, trees], tmp_path / "both.cityshade")
    scene = load_scene(out)
    ids = {scene.obj_ids[i]: codes["class"] for i, codes in object_codes(scene).items()
           if "class" in codes}
    assert ids == {"A": ["Nadelbaum"], "D": ["Evergreen"]}


def test_cityjson_attributes(tmp_path):
    tree_obj = {"type": "SolitaryVegetationObject",
                "attributes": {"species": "Conifer", "function": ["x", "evergreen"]},
                "geometry": [{"type": "MultiSurface", "lod": "2", "boundaries": [
                    [[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]],
                    [[2, 3, 7, 6]], [[3, 0, 4, 7]]]}]}
    doc = {"type": "CityJSON", "version": "2.0",
           "transform": {"scale": [0.01, 0.01, 0.01], "translate": [100000.0, 400000.0, 0.0]},
           "metadata": {"referenceSystem": "urn:ogc:def:crs:EPSG::7415"},
           "CityObjects": {"t1": tree_obj},
           "vertices": [[0, 0, 500], [400, 0, 500], [400, 400, 500], [0, 400, 500],
                        [0, 0, 1000], [400, 0, 1000], [400, 400, 1000], [0, 400, 1000]]}
    src = tmp_path / "tree.json"
    src.write_text(json.dumps(doc))
    out, _, _ = build_file(src, tmp_path / "tree.cityshade")
    scene = load_scene(out)
    assert object_codes(scene) == {0: {"function": ["x", "evergreen"], "species": ["Conifer"]}}
    assert evergreen_objects(scene, VegetationSettings()).tolist() == [True]


def test_info_says_how_many_crowns_are_evergreen(tmp_path):
    src = _trees_file(tmp_path / "trees.gml")
    result = CliRunner().invoke(cli, ["info", str(src)])
    assert result.exit_code == 0, result.output
    assert ("vegetation    4 crowns, 2 evergreen; 3 with class/function/usage/species codes"
            in result.output.splitlines())
    d = json.loads(CliRunner().invoke(cli, ["info", str(src), "--json"]).output)
    assert d["vegetation"] == {"crowns": 4, "evergreen": 2, "with_codes": 3}


def test_numeric_codes_count_under_their_own_name(tmp_path):
    """PLATEAU's SolitaryVegetationObject_function codes 11 (evergreen, needleleaf) and 12
    (evergreen, broadleaf) are evergreen by default, 21/22 (deciduous) are not; the same
    number as a class (PLATEAU's class 1-3 are tree heights; another list's 11 means
    something else) is not; a settings entry NAME=CODE adds a file's own code."""
    path = tmp_path / "plateau.gml"
    path.write_text(city(*(
        tree(tid, box_polygons(10 * k, 0, 5, 4, 4, 6, tid.lower()), codes=codes)
        for k, (tid, codes) in enumerate([
            ("N", [("class", "1"), ("function", "11")]),
            ("B", [("function", " 12 ")]),
            ("DN", [("function", "21")]),
            ("DB", [("class", "1"), ("function", "22")]),
            ("C", [("class", "11")]),
            ("S", [("class", "1070")])]))))
    out, _, _ = build_file(path, tmp_path / "plateau.cityshade")
    veg = scene_vegetation(load_scene(out))
    assert veg.evergreen(VegetationSettings()).tolist() == [True, True, False, False, False,
                                                            False]
    own = VegetationSettings(evergreen_codes=("class=1070",))
    assert veg.evergreen(own).tolist() == [False, False, False, False, False, True]
    assert veg.transmissivity(VegetationSettings(), 20).tolist() == [0.03, 0.03, 0.5, 0.5,
                                                                     0.5, 0.5]


def test_a_bad_evergreen_code_entry_is_one_clear_line():
    import pytest

    from cityshade.config import ConfigError

    for entry in ("11", "colour=11", "function="):
        with pytest.raises(ConfigError) as err:
            VegetationSettings(evergreen_codes=(entry,))
        assert str(err.value) == ("evergreen_codes entries are NAME=CODE with NAME one of "
                                  f"class, function, usage, species, not {entry!r}")
