"""Trees from a register (``build --trees``): the same triangles as the tree written by hand as
CityGML ImplicitGeometry (trimesh's own unit shapes, placed by a matrix and a reference
point), the Berlin register's 288 trees with their buildings, CRS and bad input."""
from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import trimesh
from citygml_snippets import CG2, box_polygons, building, city
from click.testing import CliRunner
from conftest import shared_file

from cityshade.build import build_scene_from_file
from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.cli.main import cli
from cityshade.config import TreeSettings
from cityshade.errors import TreeRegisterError
from cityshade.meshes.trees import add_trees, read_register

VEG2 = ""  # citygml_snippets.CG2 declares the vegetation namespace itself
X0, Y0 = 690_000.0, 5_336_000.0
#: One tree: position, height, crown diameter, trunk height (metres).
TREE = {"x": X0 + 30.0, "y": Y0 + 12.0, "h": 11.0, "d": 6.0, "ht": 4.0}


def _multisurface(mesh) -> str:
    polys = "".join(
        '<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList '
        'srsDimension="3">' + " ".join(repr(float(c)) for i in (*f, f[0]) for c in mesh.vertices[i])
        + "</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>"
        for f in mesh.faces)
    return f"<gml:MultiSurface>{polys}</gml:MultiSurface>"


def _implicit(tid: str, mesh, scale, ref) -> str:
    sx, sy, sz = scale
    matrix = f"{sx!r} 0 0 0  0 {sy!r} 0 0  0 0 {sz!r} 0  0 0 0 1"
    return (f'<veg:SolitaryVegetationObject gml:id="{tid}"><veg:lod2ImplicitRepresentation>'
            f'<ImplicitGeometry><transformationMatrix>{matrix}</transformationMatrix>'
            f'<relativeGMLGeometry>{_multisurface(mesh)}</relativeGMLGeometry>'
            f'<referencePoint><gml:Point srsName="EPSG:25832"><gml:pos>'
            f'{ref[0]!r} {ref[1]!r} {ref[2]!r}</gml:pos></gml:Point></referencePoint>'
            f'</ImplicitGeometry></veg:lod2ImplicitRepresentation></veg:SolitaryVegetationObject>')


def _block() -> str:
    return building("b1", box_polygons(X0, Y0, 0.0, 10.0, 8.0, 6.0))


def _hand_written_tree() -> str:
    """The register's tree as CityGML: trimesh's unit icosphere scaled to the crown and its
    unit cylinder (z from -0.5 to 0.5) scaled to the trunk, standing on z = 0 (the block's
    ground: the ground plane's height)."""
    t, s = TREE, TreeSettings()
    crown_h = t["h"] - t["ht"]
    crown = trimesh.creation.icosphere(subdivisions=s.crown_subdivisions)
    trunk = trimesh.creation.cylinder(radius=1.0, height=1.0, sections=s.trunk_sections)
    r = s.trunk_diameter_m / 2
    return (_implicit("crown", crown, (t["d"] / 2, t["d"] / 2, crown_h / 2),
                      (t["x"], t["y"], t["ht"] + crown_h / 2))
            + _implicit("trunk", trunk, (r, r, t["ht"]), (t["x"], t["y"], t["ht"] / 2)))


@pytest.fixture
def files(tmp_path):
    gml = tmp_path / "city.gml"
    gml.write_text(city(_block(), ns=f"{CG2} {VEG2}"))
    twin = tmp_path / "twin.gml"
    twin.write_text(city(_block(), _hand_written_tree(), ns=f"{CG2} {VEG2}"))
    register = tmp_path / "trees.csv"
    t = TREE
    register.write_text("treeID_tile;X;Y;h_tree;d_crown;h_trunk\n"
                        f"oak1;{t['x']};{t['y']};{t['h']};{t['d']};{t['ht']}\n")
    return gml, twin, register


def _vegetation_triangles(scene) -> np.ndarray:
    """(T, 3, 3) model-CRS corners of the vegetation triangles, each rotated so its smallest
    corner comes first (the winding kept), sorted."""
    keep = np.asarray(scene.tri_class) == SURFACE_CODE["vegetation"]
    corners = (np.asarray(scene.vertices, np.float64)[np.asarray(scene.triangles)[keep]]
               + scene.origin_m)
    key = np.round(corners, 3)
    first = np.array([min(range(3), key=lambda i: tuple(k[i])) for k in key])
    corners = np.stack([np.roll(c, -f, axis=0) for c, f in zip(corners, first)])
    order = np.lexsort(np.round(corners.reshape(-1, 9), 3).T[::-1])
    return corners[order]


def test_register_tree_equals_the_tree_written_as_implicit_geometry(files):
    gml, twin, register = files
    scene = build_scene_from_file(gml, tree=False,
                                  extend=functools.partial(add_trees, path=register))
    hand = build_scene_from_file(twin, tree=False)
    got, want = _vegetation_triangles(scene), _vegetation_triangles(hand)
    assert got.shape == want.shape == (320 + 32, 3, 3)
    assert np.abs(got - want).max() < 1e-4  # float32 render space around different origins
    i = scene.obj_ids.index("oak1")
    assert scene.obj_types[i] == hand.obj_types[-1] == "SolitaryVegetationObject"
    assert scene.report["trees"]["ground"] == "plane"
    lo = got.reshape(-1, 3).min(axis=0)
    hi = got.reshape(-1, 3).max(axis=0)
    np.testing.assert_allclose(hi - lo, [TREE["d"], TREE["d"], TREE["h"]], atol=1e-4)


def test_build_trees_command_line(files, tmp_path):
    gml, _, register = files
    out = tmp_path / "city.cityshade"
    result = CliRunner().invoke(cli, ["build", str(gml), "--trees", str(register), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[-1] == ("1 trees from trees.csv (ETRS89 / UTM zone 32N; "
                                              "standing on the plane)")
    bad = tmp_path / "bad.csv"
    bad.write_text("X,Y,height\n1,2,3\n")
    result = CliRunner().invoke(cli, ["build", str(gml), "--trees", str(bad), "-o", str(out)])
    assert result.exit_code == 1
    assert result.output.strip().splitlines()[-1] == (
        f"cityshade: error: {bad}: the register has no column 'h_tree' ([trees] height); "
        f"name it in [trees] of --config")


def test_geojson_register_in_longitude_latitude_is_projected(tmp_path, files):
    """A GeoJSON in CRS84 (longitude first): its points land where pyproj projects them."""
    from pyproj import Transformer

    gml = files[0]
    to_ll = Transformer.from_crs("EPSG:25832", "EPSG:4326", always_xy=True)
    lon, lat = to_ll.transform(TREE["x"], TREE["y"])
    doc = {"type": "FeatureCollection",
           "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:OGC:1.3:CRS84"}},
           "features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": [lon, lat]},
                         "properties": {"h_tree": 800, "d_crown": 400, "h_trunk": 300,
                                        "planted": "2030"}}]}
    path = tmp_path / "trees.geojson"
    path.write_text(json.dumps(doc))
    settings = TreeSettings(units="cm", planted="planted")
    scene = build_scene_from_file(gml, tree=False, extend=functools.partial(
        add_trees, path=path, settings=settings))
    i = scene.obj_ids.index("tree_1")
    v = (np.asarray(scene.vertices, np.float64)[np.unique(np.asarray(scene.triangles)[
        np.asarray(scene.tri_object) == i])] + scene.origin_m)
    centre = (v.min(axis=0) + v.max(axis=0)) / 2
    np.testing.assert_allclose(centre[:2], [TREE["x"], TREE["y"]], atol=1e-3)
    np.testing.assert_allclose(v.max(axis=0) - v.min(axis=0), [4.0, 4.0, 8.0], atol=1e-4)
    assert scene.obj_t_begin_days[i] == pytest.approx((np.datetime64("2030-01-01")
                                                       - np.datetime64("1970-01-01")).astype(int))


def test_bad_rows_are_counted_and_an_empty_register_refused(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("X,Y,h_tree,d_crown,h_trunk\n1,2,10,4,3\n1,2,,4,3\n1,2,10,4,12\n,2,10,4,3\n")
    reg = read_register(path)
    assert reg.ids == ["tree_1"]
    assert reg.skipped == {"no_position": 1, "no_height_or_crown": 1, "trunk_not_below_top": 1}
    path.write_text("X,Y,h_tree,d_crown,h_trunk\n1,2,0,4,3\n")
    with pytest.raises(TreeRegisterError, match="no usable tree among 1 rows"):
        read_register(path)


BERLIN = "berlin-lichtenberg-trees/"


@pytest.mark.shared
def test_berlin_register_builds_with_its_buildings():
    gml = shared_file(BERLIN + "lod2_buildings_berlin_test_area.gml")
    register = shared_file(BERLIN + "tree_positions_parameterized.geojson")
    feats = json.loads(register.read_text())["features"]
    scene = build_scene_from_file(gml, tree=False,
                                  extend=functools.partial(add_trees, path=register))
    assert scene.report["trees"]["trees"] == len(feats) == 288
    assert scene.report["objects_by_type"]["SolitaryVegetationObject"] == 288
    assert scene.report["polygons"]["drawn"] == 648 + 2 * 288  # buildings + crowns and trunks
    from cityshade.geometry.ground import ground_height_m

    n_build = len(scene.obj_ids) - 288
    plane = ground_height_m(scene, "auto") + scene.origin_m[2]
    tri_obj = np.asarray(scene.tri_object)
    vertices = np.asarray(scene.vertices, np.float64) + scene.origin_m
    for k, f in enumerate(feats):
        p = f["properties"]
        i = n_build + k
        assert scene.obj_ids[i] == p["treeID_tile"]
        v = vertices[np.unique(np.asarray(scene.triangles)[tri_obj == i])]
        lo, hi = v.min(axis=0), v.max(axis=0)
        assert lo[2] == pytest.approx(plane, abs=1e-4)
        assert hi[2] - lo[2] == pytest.approx(p["h_tree"], abs=1e-3)
        assert hi[0] - lo[0] == pytest.approx(p["d_crown"], abs=1e-3)
        assert hi[1] - lo[1] == pytest.approx(p["d_crown"], abs=1e-3)
        np.testing.assert_allclose((lo[:2] + hi[:2]) / 2, f["geometry"]["coordinates"], atol=1e-3)
