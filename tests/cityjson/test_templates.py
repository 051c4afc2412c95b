"""CityJSON GeometryInstance with "geometry-templates": exact positions of a hand-written case,
the counts ``info`` reports, and ClosureSurface semantics left out like CityGML's."""
from __future__ import annotations

import json

import numpy as np
from click.testing import CliRunner

from cityshade.cityjson.reader import read_cityjson
from cityshade.cli.main import cli
from cityshade.config import BuildSettings
from cityshade.geometry.scene import build_scene

#: One template, a triangle (0,0,0) (1,0,0) (0,1,1); two trees: a rotation by 90° about z
#: with scales (2 in plan, 3 up) at (100, 200, 10), and a shift of 5 m east in the matrix at
#: (50, 60, 0). Vertices are stored with a transform (scale 0.01), templates are not.
_TREES = {
    "type": "CityJSON", "version": "2.0",
    "transform": {"scale": [0.01, 0.01, 0.01], "translate": [0.0, 0.0, 0.0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/25832"},
    "vertices": [[10000, 20000, 1000], [5000, 6000, 0]],
    "geometry-templates": {
        "templates": [{"type": "MultiSurface", "lod": "2", "boundaries": [[[0, 1, 2]]]}],
        "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 1]]},
    "CityObjects": {
        "tree1": {"type": "SolitaryVegetationObject", "geometry": [{
            "type": "GeometryInstance", "template": 0, "boundaries": [0],
            "transformationMatrix": [0, -2, 0, 0, 2, 0, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1]}]},
        "tree2": {"type": "SolitaryVegetationObject", "geometry": [{
            "type": "GeometryInstance", "template": 0, "boundaries": [1],
            "transformationMatrix": [1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]},
    },
}


def test_template_instances_are_placed_exactly(tmp_path):
    path = tmp_path / "trees.json"
    path.write_text(json.dumps(_TREES))
    raw = read_cityjson(path)
    assert raw.counters["implicit_prototypes"] == 1 and raw.counters["implicit_instances"] == 2
    scene = build_scene(raw)
    want = {"tree1": [(100, 200, 10), (100, 202, 10), (98, 200, 13)],
            "tree2": [(55, 60, 0), (56, 60, 0), (55, 61, 1)]}
    tri = np.asarray(scene.triangles)
    world = np.asarray(scene.vertices, np.float64) + scene.origin_m
    for oid, pts in want.items():
        k = scene.obj_ids.index(oid)
        got = world[tri[np.asarray(scene.tri_object) == k][0]]
        # The triangle keeps the template's winding from its first vertex on (up to a
        # rotation of the three corners).
        d = np.abs(got[:, None, :] - np.array(pts, float)[None, :, :]).max(axis=2)
        assert d.min(axis=1).max() < 1e-4 and d.min(axis=0).max() < 1e-4
    result = CliRunner().invoke(cli, ["info", str(path), "--json"])
    assert result.exit_code == 0, result.output
    d = json.loads(result.output)
    assert d["implicit"] == {"prototypes": 1, "instances": 2, "references_unresolved": 0}
    text = CliRunner().invoke(cli, ["info", str(path)])
    assert "implicit      1 prototypes, 2 instances placed" in text.output


_BOX = {
    "type": "CityJSON", "version": "2.0",
    "transform": {"scale": [1, 1, 1], "translate": [0, 0, 0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/25832"},
    "vertices": [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0],
                 [0, 0, 5], [10, 0, 5], [10, 10, 5], [0, 10, 5]],
    "CityObjects": {"b": {"type": "Building", "geometry": [{
        "type": "Solid", "lod": "2",
        "boundaries": [[[[0, 3, 2, 1]], [[4, 5, 6, 7]], [[0, 1, 5, 4]], [[1, 2, 6, 5]],
                        [[2, 3, 7, 6]], [[3, 0, 4, 7]]]],
        "semantics": {"surfaces": [{"type": "GroundSurface"}, {"type": "RoofSurface"},
                                   {"type": "WallSurface"}, {"type": "ClosureSurface"}],
                      "values": [[0, 1, 2, 3, 2, 2]]}}]}},
}


def test_cityjson_closure_surface_is_left_out_unless_kept(tmp_path):
    path = tmp_path / "box.json"
    path.write_text(json.dumps(_BOX))
    omitted = build_scene(read_cityjson(path))
    assert omitted.n_triangles == 10
    assert omitted.report["left_out"] == {"closure_polygons": 1, "closure_triangles": 2}
    kept = build_scene(read_cityjson(path), BuildSettings(closure_surfaces="keep"))
    assert kept.n_triangles == 12 and kept.report["left_out"] == {}
