"""ImplicitGeometry (CityGML 2.0 and 3.0): prototypes placed by matrix and reference point.

The expected positions are written out by hand (a rotation by 90° about z with scales, a
translation in the matrix, a mirror), and the Berlin tree file is checked against its own
``veg:height``, ``veg:crownDiameter`` and reference points read here with lxml.
"""
from __future__ import annotations

import numpy as np
import pytest
from lxml import etree

from citygml_snippets import CG2, city
from conftest import shared_file

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.citygml.reader import read_citygml
from cityshade.errors import InputError
from cityshade.geometry.scene import build_scene

VEG2 = ""  # citygml_snippets.CG2 declares the vegetation namespace itself
#: The prototype: one triangle, (0,0,0) (1,0,0) (0,1,1), its ring closed.
PROTO_POLYGON = ('<gml:Polygon><gml:exterior><gml:LinearRing><gml:posList srsDimension="3">'
                 '0 0 0 1 0 0 0 1 1 0 0 0</gml:posList></gml:LinearRing></gml:exterior>'
                 '</gml:Polygon>')


def _tree(tid: str, matrix: str, ref: str, geometry: str, lod: int = 2,
          prefix: str = "veg", rel: str = "relativeGMLGeometry") -> str:
    return (f'<{prefix}:SolitaryVegetationObject gml:id="{tid}">'
            f'<{prefix}:lod{lod}ImplicitRepresentation><ImplicitGeometry>'
            f'<mimeType>model/obj</mimeType>'
            f'<transformationMatrix>{matrix}</transformationMatrix>'
            f'<{rel}{geometry}'
            f'<referencePoint><gml:Point srsName="EPSG:25832"><gml:pos>{ref}</gml:pos>'
            f'</gml:Point></referencePoint></ImplicitGeometry>'
            f'</{prefix}:lod{lod}ImplicitRepresentation></{prefix}:SolitaryVegetationObject>')


def _inline(gid: str, rel: str = "relativeGMLGeometry") -> str:
    return (f'><gml:MultiSurface gml:id="{gid}"><gml:surfaceMember>{PROTO_POLYGON}'
            f'</gml:surfaceMember></gml:MultiSurface></{rel}>')


def _link(gid: str) -> str:
    return f' xlink:href="#{gid}"/>'


# x' = -2 y, y' = 2 x, z' = 3 z (90° about z, scale 2 in plan, 3 in height).
ROTATE_SCALE = "0 -2 0 0  2 0 0 0  0 0 3 0  0 0 0 1"
# The identity with a translation of 5 m east in the matrix.
SHIFT = "1 0 0 5  0 1 0 0  0 0 1 0  0 0 0 1"
# A mirror in x: the winding must be reversed.
MIRROR = "-1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1"


def _snippet_file(tmp_path, doc: str):
    path = tmp_path / "trees.gml"
    path.write_text(doc)
    return path


def _placed_rings(raw) -> dict[int, np.ndarray]:
    """Object → its polygon's ring points (the one ring of each placed triangle)."""
    starts = np.concatenate([[0], np.cumsum(raw.ring_points)])
    out = {}
    for p in range(raw.n_polygons):
        r = raw.poly_ring0[p]
        out[int(raw.poly_obj[p])] = raw.xyz[starts[r]:starts[r + 1]]
    return out


def test_inline_and_xlinked_prototypes_are_placed_exactly(tmp_path):
    doc = city(
        # A forward reference: the prototype is defined by the next tree.
        _tree("t0", SHIFT, "50 60 0", _link("proto")),
        _tree("t1", ROTATE_SCALE, "100 200 10", _inline("proto")),
        _tree("t2", MIRROR, "10 20 30", _link("proto")),
        ns=CG2 + " " + VEG2)
    raw = read_citygml(_snippet_file(tmp_path, doc))
    assert raw.counters["implicit_prototypes"] == 1
    assert raw.counters["implicit_instances"] == 3
    assert raw.n_polygons == 3 and list(raw.poly_lod) == [2, 2, 2]
    rings = _placed_rings(raw)
    expected = {
        0: [(55, 60, 0), (56, 60, 0), (55, 61, 1), (55, 60, 0)],
        1: [(100, 200, 10), (100, 202, 10), (98, 200, 13), (100, 200, 10)],
        2: [(10, 20, 30), (9, 20, 30), (10, 21, 31), (10, 20, 30)],
    }
    for obj, pts in expected.items():
        np.testing.assert_array_equal(rings[obj], np.array(pts, float))
    # The mirror reverses the winding; the rotation and the shift do not.
    flips = {int(o): int(f) for o, f in zip(raw.poly_obj, raw.poly_flip)}
    assert flips == {0: 0, 1: 0, 2: 1}
    # The trees are vegetation, and they build like explicit geometry.
    scene = build_scene(raw)
    assert scene.obj_types == ["SolitaryVegetationObject"] * 3
    assert scene.n_triangles == 3 and scene.report["lods_drawn"] == {"2": 3}
    world = np.asarray(scene.vertices, np.float64) + scene.origin_m
    want = np.array([p for pts in expected.values() for p in pts[:3]], float)
    d = np.abs(world[:, None, :] - want[None, :, :]).max(axis=2)
    assert d.min(axis=1).max() < 1e-4 and d.min(axis=0).max() < 1e-4
    classes = set(np.asarray(scene.tri_class).tolist())
    assert classes == {SURFACE_CODE["vegetation"]}
    # The mirrored tree's normal is the mirror image of the shifted one's, (0, -1, 1)/√2 (its
    # ring read as written would face the other way, (0, 1, -1)/√2).
    normals = np.asarray(scene.poly_normal, np.float64)
    by_obj = {int(o): normals[i] for i, o in enumerate(np.asarray(scene.poly_object))}
    np.testing.assert_allclose(by_obj[0], np.array([0, -1, 1]) / np.sqrt(2), atol=1e-6)
    np.testing.assert_allclose(by_obj[2], by_obj[0] * [-1, 1, 1], atol=1e-6)


def test_citygml3_relative_geometry(tmp_path):
    ns3 = ('xmlns="http://www.opengis.net/citygml/3.0" xmlns:gml="http://www.opengis.net/gml/3.2" '
           'xmlns:veg="http://www.opengis.net/citygml/vegetation/3.0" '
           'xmlns:xlink="http://www.w3.org/1999/xlink"')
    doc = city(_tree("a", ROTATE_SCALE, "100 200 10", _inline("p3", "relativeGeometry"),
                     rel="relativeGeometry"),
               _tree("b", SHIFT, "50 60 0", _link("p3"), rel="relativeGeometry"), ns=ns3)
    raw = read_citygml(_snippet_file(tmp_path, doc))
    rings = _placed_rings(raw)
    np.testing.assert_array_equal(rings[0][:3], [(100, 200, 10), (100, 202, 10), (98, 200, 13)])
    np.testing.assert_array_equal(rings[1][:3], [(55, 60, 0), (56, 60, 0), (55, 61, 1)])
    assert "3.0" in raw.versions


def test_unresolved_reference_is_counted_and_bad_matrix_is_one_line(tmp_path):
    doc = city(_tree("t1", ROTATE_SCALE, "100 200 10", _inline("proto")),
               _tree("t2", SHIFT, "1 2 3", _link("nowhere")), ns=CG2 + " " + VEG2)
    raw = read_citygml(_snippet_file(tmp_path, doc))
    assert raw.counters["implicit_references_unresolved"] == 1
    assert raw.counters["implicit_instances"] == 1
    bad = city(_tree("t1", "1 0 0", "100 200 10", _inline("proto")), ns=CG2 + " " + VEG2)
    with pytest.raises(InputError) as info:
        read_citygml(_snippet_file(tmp_path, bad))
    assert "transformationMatrix" in str(info.value) and "\n" not in str(info.value)
    assert info.value.gml_id == "t1"


# -- the Berlin trees ------------------------------------------------------------------------

TREES = "berlin-lichtenberg-trees/semantic_3D_tree_model_berlin_test_area.gml"
G = "{http://www.opengis.net/gml}"
VEG = "{http://www.opengis.net/citygml/vegetation/2.0}"
CORE = "{http://www.opengis.net/citygml/2.0}"
XLINK = "{http://www.w3.org/1999/xlink}href"


def _berlin_trees(path):
    """Per tree, straight from the XML: height, crown diameter, reference point, matrix and
    the prototype's points (its gml:id resolved here)."""
    root = etree.parse(str(path)).getroot()
    protos = {mg.get(G + "id"): np.array(
        [float(v) for pl in mg.iter(G + "posList") for v in pl.text.split()]).reshape(-1, 3)
        for mg in root.iter(G + "MultiGeometry") if mg.get(G + "id")}
    trees = []
    for tree in root.iter(VEG + "SolitaryVegetationObject"):
        geom = next(tree.iter(CORE + "ImplicitGeometry"))
        rel = geom.find(CORE + "relativeGMLGeometry")
        proto_id = rel.get(XLINK, "").lstrip("#") or rel[0].get(G + "id")
        trees.append({
            "height": float(tree.find(VEG + "height").text),
            "crown": float(tree.find(VEG + "crownDiameter").text),
            "ref": np.array(next(geom.find(CORE + "referencePoint").iter(G + "pos"))
                            .text.split(), float),
            "matrix": np.array(geom.find(CORE + "transformationMatrix").text.split(),
                               float).reshape(4, 4),
            "proto": protos[proto_id]})
    return trees


@pytest.fixture(scope="module")
def berlin():
    path = shared_file(TREES)
    return _berlin_trees(path), build_scene(read_citygml(path))


def _tree_vertices(scene, k: int) -> np.ndarray:
    tri = np.asarray(scene.triangles)[np.asarray(scene.tri_object) == k]
    return np.asarray(scene.vertices, np.float64)[np.unique(tri)] + scene.origin_m


@pytest.mark.shared
def test_berlin_trees_stand_where_their_attributes_say(berlin):
    trees, scene = berlin
    assert len(trees) == 288
    assert scene.obj_types == ["SolitaryVegetationObject"] * 288
    rep = scene.report
    assert rep["counters"]["implicit_prototypes"] == 10
    assert rep["counters"]["implicit_instances"] == 288
    assert rep["lods_drawn"] == {"2": 288}
    for k, t in enumerate(trees):
        v = _tree_vertices(scene, k)
        assert len(v), f"tree {k} has no triangles"
        lo, hi = v.min(axis=0), v.max(axis=0)
        # Standing on its reference point, crown up to veg:height (the prototypes reach
        # z = -0.004 of the unit height at most; the file rounds to 1 cm).
        assert lo[2] == pytest.approx(t["ref"][2], abs=0.005 * t["height"] + 0.01), k
        assert hi[2] == pytest.approx(t["ref"][2] + t["height"], abs=0.01), k
        # Centred on the reference point in plan.
        centre = (lo[:2] + hi[:2]) / 2
        assert np.abs(centre - t["ref"][:2]).max() < 0.05 * t["crown"] + 0.01, k
        # The crown's two diameters (extents along its principal axes, taken from the
        # placed points) average to veg:crownDiameter.
        xy = v[:, :2] - v[:, :2].mean(axis=0)
        _, axes = np.linalg.eigh(xy.T @ xy)
        proj = xy @ axes
        extents = proj.max(axis=0) - proj.min(axis=0)
        assert extents.mean() == pytest.approx(t["crown"], rel=0.03, abs=0.02), k


@pytest.mark.shared
@pytest.mark.parametrize("k", [0, 1, 2, 3, 100, 287])
def test_berlin_tree_equals_its_prototype_placed_by_hand(berlin, k):
    trees, scene = berlin
    t = trees[k]
    m = t["matrix"]
    by_hand = np.array([m[:3, :3] @ p + m[:3, 3] for p in t["proto"]]) + t["ref"]
    got = _tree_vertices(scene, k)
    # float32 render space near the origin: well under 1e-4 m.
    d = np.abs(got[:, None, :] - by_hand[None, :, :]).max(axis=2)
    assert d.min(axis=1).max() < 1e-4  # every drawn vertex is a placed prototype point
    assert d.min(axis=0).max() < 1e-4  # every prototype point is drawn
