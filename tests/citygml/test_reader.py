"""Reader and scene assembly on small hand-written documents, and every kind of bad input."""
from __future__ import annotations

import numpy as np
import pytest

from citygml_snippets import CG2, box_polygons, building, city, polygon

from cityshade.citygml.reader import read_citygml
from cityshade.config import BuildSettings
from cityshade.errors import EmptyModelError, InputError, NotCityGMLError, XMLSyntaxError
from cityshade.geometry.scene import build_scene

BASE = (690_000.0, 5_336_000.0, 500.0)


def write(tmp_path, text, name="city.gml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def scene_of(tmp_path, text, **settings):
    return build_scene(read_citygml(write(tmp_path, text)), BuildSettings(**settings))


def signed_volume(scene) -> float:
    v = scene.vertices.astype(np.float64)
    t = scene.triangles
    return float(np.einsum("ij,ij->i", v[t[:, 0]], np.cross(v[t[:, 1]], v[t[:, 2]])).sum() / 6)


def test_box_with_forward_references_is_closed_and_outward(tmp_path):
    faces = box_polygons(*BASE, 10, 8, 6)
    scene = scene_of(tmp_path, city(building("b1", faces)))
    assert scene.n_triangles == 12
    assert scene.report["polygons"] == {"read": 6, "drawn": 6, "skipped": 0, "not_selected_lod": 0,
                                       "left_out": 0}
    # Outward winding: the enclosed volume is positive and equals 10 * 8 * 6.
    assert signed_volume(scene) == pytest.approx(480.0, rel=1e-6)
    assert scene.crs.horizontal_epsg == 25832
    np.testing.assert_allclose(scene.origin_m, [690_005, 5_336_004, 503])


@pytest.mark.parametrize("namespace", [
    CG2,
    CG2.replace("http://www.opengis.net/citygml/2.0", "http://www.opengis.net/citygml/1.0")
       .replace("building/2.0", "building/1.0"),
    CG2.replace('xmlns="http://www.opengis.net/citygml/2.0" ', 'xmlns:x="urn:unused" '),
    CG2.replace("http://www.opengis.net/citygml/2.0", "http://www.citygml.org/citygml/1/0/0"),
])
def test_namespaces_old_and_missing(tmp_path, namespace):
    """CityGML 2.0, 1.0, a CityModel without namespace and the pre-standard namespace."""
    faces = box_polygons(*BASE, 4, 4, 4)
    scene = scene_of(tmp_path, city(building("b1", faces), ns=namespace))
    assert scene.n_triangles == 12 and scene.obj_types == ["Building"]


def test_coordinates_pos_and_gml_coordinates(tmp_path):
    sq = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)]
    pos = "".join(f"<gml:pos>{x} {y} {z}</gml:pos>" for x, y, z in sq + sq[:1])
    coords = " ".join(f"{x},{y},{z}" for x, y, z in sq + sq[:1])
    doc = city(
        '<bldg:Building gml:id="b"><bldg:lod2MultiSurface><gml:MultiSurface>'
        f'<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing>{pos}'
        '</gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>'
        f'<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:coordinates>{coords}'
        '</gml:coordinates></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>'
        '</gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building>')
    scene = scene_of(tmp_path, doc)
    assert scene.n_triangles == 4
    np.testing.assert_allclose(scene.poly_area_m2, [4.0, 4.0])


def test_orientable_surface_minus_flips(tmp_path):
    sq = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)]  # counter-clockwise seen from +z
    doc = city(
        '<bldg:Building gml:id="b"><bldg:lod2MultiSurface><gml:MultiSurface>'
        f'<gml:surfaceMember>{polygon(sq, "up")}</gml:surfaceMember>'
        '<gml:surfaceMember><gml:OrientableSurface orientation="-"><gml:baseSurface>'
        f'{polygon([(x, y, 5) for x, y, _ in sq], "down")}</gml:baseSurface></gml:OrientableSurface>'
        '</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building>')
    scene = scene_of(tmp_path, doc)
    up, down = scene.poly_ids.index("up"), scene.poly_ids.index("down")
    assert scene.poly_normal[up][2] == pytest.approx(1.0)
    assert scene.poly_normal[down][2] == pytest.approx(-1.0)
    v = scene.vertices.astype(float)
    for p, sign in ((up, 1), (down, -1)):
        t = scene.triangles[scene.tri_polygon == p]
        n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
        assert (np.sign(n[:, 2]) == sign).all()


def test_lod_selection_highest_and_requested(tmp_path):
    sq = [(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0)]
    doc = city(
        '<bldg:Building gml:id="b">'
        f'<bldg:lod0FootPrint><gml:MultiSurface><gml:surfaceMember>{polygon(sq, "fp")}'
        '</gml:surfaceMember></gml:MultiSurface></bldg:lod0FootPrint>'
        + building("x", box_polygons(0, 0, 0, 4, 4, 3))[len('<bldg:Building gml:id="x">'):])
    default = scene_of(tmp_path, doc)
    assert default.report["lods_drawn"] == {"2": 1} and default.n_triangles == 12
    lod0 = scene_of(tmp_path, doc, lod=0)
    assert lod0.n_triangles == 2 and lod0.poly_ids == ["fp"]
    with pytest.raises(EmptyModelError, match="LoD 3"):
        scene_of(tmp_path, doc, lod=3)


def test_time_attributes_and_parts_inherit(tmp_path):
    part = building("part", box_polygons(20, 0, 0, 3, 3, 3, "q"), solid_refs=False)
    part = part.replace("bldg:Building", "bldg:BuildingPart")
    extra = ("<bldg:yearOfConstruction>1850</bldg:yearOfConstruction>"
             "<bldg:yearOfDemolition>1950</bldg:yearOfDemolition>"
             f"<bldg:consistsOfBuildingPart>{part}</bldg:consistsOfBuildingPart>")
    doc = city(building("b", box_polygons(0, 0, 0, 5, 5, 5), extra=extra))
    scene = scene_of(tmp_path, doc)
    from cityshade.geo.temporal import parse_xsd_datetime_days as days
    assert scene.obj_types == ["Building", "BuildingPart"]
    assert scene.obj_parent.tolist() == [-1, 0]
    for i in (0, 1):
        assert scene.obj_t_begin_days[i] == days("1850-01-01")
        assert scene.obj_t_end_days[i] == days("1950-01-01")
    assert scene.report["time_sources_used"] == {"construction": 1, "inherited": 1}
    assert np.isin(scene.tri_object, [0, 1]).all() and (scene.tri_object == 1).sum() == 12


def test_ade_elements_skipped(tmp_path):
    ns = CG2 + ' xmlns:noise="http://www.citygml.org/ade/noise_de/2.0"'
    extra = (f"<noise:buildingReflection><noise:geom><gml:MultiSurface><gml:surfaceMember>"
             f"{polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0)])}</gml:surfaceMember></gml:MultiSurface>"
             f"</noise:geom></noise:buildingReflection>")
    scene = scene_of(tmp_path, city(building("b", box_polygons(0, 0, 0, 2, 2, 2), extra=extra), ns=ns))
    assert scene.n_triangles == 12
    assert scene.report["counters"]["ade_elements_skipped"] >= 1


def test_material_theme_and_texture_paths(tmp_path):
    (tmp_path / "tex").mkdir()
    from cityshade.imageio import write_image
    write_image(tmp_path / "tex" / "wall.png", np.full((4, 4, 3), 200, np.uint8))
    faces = box_polygons(0, 0, 0, 4, 4, 4)
    south = faces[2]
    faces[2] = (south[0], south[1], south[2])
    doc_faces = building("b", faces).replace(
        f'<gml:Polygon gml:id="{south[1]}"><gml:exterior><gml:LinearRing>',
        f'<gml:Polygon gml:id="{south[1]}"><gml:exterior><gml:LinearRing gml:id="ring_s">')
    appearance = (
        "<app:Appearance><app:theme>summer</app:theme>"
        "<app:surfaceDataMember><app:X3DMaterial><app:diffuseColor>0.8 0.1 0.1</app:diffuseColor>"
        "<app:target>#pr</app:target></app:X3DMaterial></app:surfaceDataMember>"
        "<app:surfaceDataMember><app:ParameterizedTexture><app:imageURI>tex\\wall.png</app:imageURI>"
        '<app:target uri="#ps"><app:TexCoordList><app:textureCoordinates ring="#ring_s">'
        "0 0 1 0 1 1 0 1 0 0</app:textureCoordinates></app:TexCoordList></app:target>"
        "</app:ParameterizedTexture></app:surfaceDataMember>"
        "<app:surfaceDataMember><app:ParameterizedTexture>"
        "<app:imageURI>../outside.png</app:imageURI><app:target uri=\"#pe\"/>"
        "</app:ParameterizedTexture></app:surfaceDataMember>"
        "<app:surfaceDataMember><app:ParameterizedTexture>"
        "<app:imageURI>http://example.org/x.png</app:imageURI><app:target uri=\"#pn\"/>"
        "</app:ParameterizedTexture></app:surfaceDataMember>"
        "</app:Appearance>")
    scene = scene_of(tmp_path, city(doc_faces, appearance=appearance))
    assert scene.report["theme"] == "summer"
    assert scene.materials[0]["diffuse"] == [0.8, 0.1, 0.1]
    roof = scene.poly_ids.index("pr")
    assert (scene.tri_material[scene.tri_polygon == roof] == 0).all()
    wall = scene.poly_ids.index("ps")
    assert len(scene.textures) == 1 and scene.textures[0]["path"].endswith("wall.png")
    assert (scene.tri_texture[scene.tri_polygon == wall] == 0).all()
    uv = scene.uv[np.unique(scene.triangles[scene.tri_polygon == wall])]
    assert sorted(map(tuple, uv.tolist())) == [(0, 0), (0, 1), (1, 0), (1, 1)]
    warnings = " ".join(scene.report["warnings"])
    assert "outside the dataset folder" in warnings and "is a URL" in warnings
    assert scene.report["counters"]["textures_refused"] == 2


def test_material_targets_an_aggregate_a_polygon_and_nothing(tmp_path):
    """A material naming a solid covers all its faces; a later one naming a face wins there;
    one naming only unknown ids is not listed."""
    doc = building("b", box_polygons(0, 0, 0, 4, 4, 4)).replace(
        "<gml:Solid ", '<gml:Solid gml:id="solid_b" ')

    def material(rgb, *targets):
        return ("<app:surfaceDataMember><app:X3DMaterial>"
                f"<app:diffuseColor>{rgb}</app:diffuseColor>"
                + "".join(f"<app:target>#{t}</app:target>" for t in targets)
                + "</app:X3DMaterial></app:surfaceDataMember>")

    appearance = ("<app:Appearance><app:theme>t</app:theme>"
                  + material("0.5 0.5 0.5", "solid_b") + material("1 0 0", "nope", "pr")
                  + material("0 0 1", "nope") + "</app:Appearance>")
    scene = scene_of(tmp_path, city(doc, appearance=appearance))
    assert [m["diffuse"] for m in scene.materials] == [[0.5, 0.5, 0.5], [1.0, 0.0, 0.0]]
    roof = scene.poly_ids.index("pr")
    assert (scene.tri_material[scene.tri_polygon == roof] == 1).all()
    assert (scene.tri_material[scene.tri_polygon != roof] == 0).sum() == 10


def test_scene_assembly_kernels_match_their_twins():
    from cityshade.geometry.scene import _expand_ranges, _render_vertices
    from reference import reference_expand_ranges, reference_render_vertices

    rng = np.random.default_rng(5)
    starts = rng.integers(0, 10**9, 200)
    lengths = rng.integers(0, 6, 200)  # empty ranges among them
    np.testing.assert_array_equal(_expand_ranges(starts, lengths),
                                  reference_expand_ranges(starts, lengths))
    assert _expand_ranges(starts[:0], lengths[:0]).shape == (0,)
    points = rng.uniform(-1, 1, (500, 3)) * 10.0 ** rng.integers(0, 8, (500, 1))
    index = np.sort(rng.choice(500, 300, replace=False))
    origin = np.array([1234567.0, -7654321.0, 500.0])
    got = _render_vertices(points, index, origin)
    assert got.dtype == np.float32
    np.testing.assert_array_equal(got, reference_render_vertices(points, index, origin))


def test_scene_assembly_twins_equal_the_compiled_kernels():
    """Small scenes on first use run these kernels' Python source (runtime.interpret): the
    same bits as the compiled kernels, far from the origin and with NaN coordinates."""
    from cityshade.geometry.bounds import used_vertex_box
    from cityshade.geometry.scene import _expand_ranges_kernel, _render_vertices
    from cityshade.runtime.interpret import python_twin

    rng = np.random.default_rng(6)
    starts = rng.integers(0, 10**9, 200)
    lengths = rng.integers(0, 6, 200)
    points = rng.uniform(-1, 1, (500, 3)) * 10.0 ** rng.integers(0, 8, (500, 1)) + 3.3e6
    index = np.sort(rng.choice(500, 300, replace=False))
    origin = np.array([1234567.0, -7654321.0, 500.0])
    tris = rng.integers(0, 500, (400, 3))
    with_nan = points.astype(np.float32)
    with_nan[tris[7, 1], 2] = np.nan
    cases = [(_expand_ranges_kernel, lambda: (starts, lengths, np.empty(lengths.sum(), np.int64))),
             (_render_vertices, lambda: (points, index, origin)),
             (used_vertex_box, lambda: (tris, points, np.empty((2, 3)))),
             (used_vertex_box, lambda: (tris, with_nan, np.empty((2, 3))))]
    for kernel, args in cases:
        a, b = args(), args()
        got = [kernel(*a), python_twin(kernel)(*b)]
        if got[0] is None:  # results written into the last argument
            got = [a[-1], b[-1]]
        assert got[0].dtype == got[1].dtype and got[0].tobytes() == got[1].tobytes(), kernel
    assert np.isnan(b[-1][:, 2]).all() and np.isfinite(b[-1][:, :2]).all()


def test_precision_offset_1e7(tmp_path):
    """The same building 10^7 m away gives the same local geometry to 1 mm."""
    near = scene_of(tmp_path, city(building("b", box_polygons(1234.567, 2345.678, 10.0, 12.3, 7.9, 15.1))))
    far = scene_of(tmp_path, city(building("b", box_polygons(1e7 + 1234.567, 1e7 + 2345.678, 10.0,
                                                              12.3, 7.9, 15.1))))
    np.testing.assert_array_equal(near.triangles, far.triangles)
    np.testing.assert_allclose(far.vertices, near.vertices + (near.origin_m - far.origin_m + 1e7 * np.array([1, 1, 0])),
                               atol=1e-3)
    assert np.abs(far.vertices).max() < 20


# -- bad input ---------------------------------------------------------------------------------
def test_malformed_xml_reports_line(tmp_path):
    doc = city(building("b", box_polygons(0, 0, 0, 1, 1, 1))).replace("</bldg:Building>", "</bldg:Buildin>")
    with pytest.raises(XMLSyntaxError) as info:
        read_citygml(write(tmp_path, doc))
    assert "malformed XML" in str(info.value) and ":2:" in str(info.value)


def test_truncated_file(tmp_path):
    doc = city(building("b", box_polygons(0, 0, 0, 1, 1, 1)), building("c", box_polygons(5, 0, 0, 1, 1, 1)))
    with pytest.raises(XMLSyntaxError, match="truncated"):
        read_citygml(write(tmp_path, doc[: len(doc) // 2]))


def test_not_citygml(tmp_path):
    with pytest.raises(NotCityGMLError, match="root element is html"):
        read_citygml(write(tmp_path, "<html><body>hi</body></html>"))


def test_empty_model_and_empty_file(tmp_path):
    with pytest.raises(EmptyModelError, match="no city objects"):
        read_citygml(write(tmp_path, city()))
    with pytest.raises(InputError, match="empty"):
        read_citygml(write(tmp_path, ""))
    with pytest.raises(InputError, match="no such file"):
        read_citygml(tmp_path / "missing.gml")


def test_billion_laughs_refused(tmp_path):
    entities = '<!ENTITY lol "lol">' + "".join(
        f'<!ENTITY lol{i} "{("&lol%s;" % (i - 1 if i > 1 else "")) * 10}">' for i in range(1, 10))
    doc = f'<?xml version="1.0"?>\n<!DOCTYPE CityModel [{entities}]>\n<CityModel {CG2}>&lol9;</CityModel>'
    with pytest.raises(XMLSyntaxError, match="entities"):
        read_citygml(write(tmp_path, doc))


def test_external_entity_and_dtd_refused(tmp_path):
    doc = ('<?xml version="1.0"?>\n<!DOCTYPE CityModel SYSTEM "http://example.org/x.dtd">\n'
           f"<CityModel {CG2}></CityModel>")
    with pytest.raises(XMLSyntaxError, match="external DTD"):
        read_citygml(write(tmp_path, doc))
    doc = ('<?xml version="1.0"?>\n<!DOCTYPE CityModel [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n'
           f"<CityModel {CG2}>&x;</CityModel>")
    with pytest.raises(XMLSyntaxError, match="entities"):
        read_citygml(write(tmp_path, doc))


def test_invalid_geometry_is_skipped_and_counted(tmp_path):
    bow_tie = [(0, 0, 0), (2, 2, 0), (2, 0, 0), (0, 2, 0)]
    line = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
    good = [(5, 5, 0), (6, 5, 0), (6, 6, 0)]
    bad_text = ('<gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>1 2 3 4 5 x 7 8 9 1 2 3'
                '</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>')
    members = "".join(f"<gml:surfaceMember>{polygon(p)}</gml:surfaceMember>" for p in (bow_tie, line, good))
    doc = city('<bldg:Building gml:id="b"><bldg:lod2MultiSurface><gml:MultiSurface>'
               f"{members}<gml:surfaceMember>{bad_text}</gml:surfaceMember>"
               "</gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building>")
    scene = scene_of(tmp_path, doc)
    assert scene.n_triangles == 1
    assert scene.report["skipped"] == {"all_collinear": 1, "bad_coordinates": 1, "self_intersecting": 1}
    with pytest.raises(EmptyModelError, match="no polygon could be triangulated"):
        scene_of(tmp_path, city('<bldg:Building gml:id="b"><bldg:lod2MultiSurface><gml:MultiSurface>'
                                f"<gml:surfaceMember>{polygon(line)}</gml:surfaceMember>"
                                "</gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building>"))


def test_empty_or_xlinked_exterior_is_skipped(tmp_path):
    good = polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0)])
    doc = city('<bldg:Building gml:id="b"><bldg:lod2MultiSurface><gml:MultiSurface>'
               f"<gml:surfaceMember>{good}</gml:surfaceMember>"
               "<gml:surfaceMember><gml:Polygon><gml:exterior/></gml:Polygon></gml:surfaceMember>"
               '<gml:surfaceMember><gml:Polygon><gml:exterior xlink:href="#r1"/></gml:Polygon>'
               "</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building>")
    scene = scene_of(tmp_path, doc)
    assert scene.n_triangles == 1
    assert scene.report["polygons"]["read"] == 3
    assert scene.report["skipped"] == {"too_few_points": 2}


def test_consumed_model_builds_the_same_scene():
    """``consume_raw`` frees the read model's coordinates on the way (the one-file build): the
    scene is the one built from a model that is kept, array for array (textured sample city)."""
    from pathlib import Path

    from cityshade.geometry.scene import Scene

    path = Path(__file__).resolve().parents[2] / "sample_data" / "sample_city.gml"
    kept = build_scene(read_citygml(path))
    raw = read_citygml(path)
    consumed = build_scene(raw, consume_raw=True)
    assert raw.xyz is None
    for name in Scene.ARRAY_FIELDS:
        a, b = getattr(kept, name), getattr(consumed, name)
        assert a.dtype == b.dtype and np.array_equal(a, b), name
    assert kept.poly_ids == consumed.poly_ids and kept.materials == consumed.materials
    assert kept.textures == consumed.textures and kept.report == consumed.report


@pytest.mark.parametrize("batch_chars", [1, 5_000])
def test_batches_parsed_on_a_second_thread_give_the_same_model(tmp_path, monkeypatch, batch_chars):
    """Coordinate batches flushed during the read parse on the ring parser's thread, in order:
    with batches of one ring or a few hundred, the model equals the one of a single batch (the
    sample city, whose xlinked rings are numbered across batches, and a file with bad rings)."""
    from pathlib import Path

    import cityshade.citygml.reader as reader

    bad_ring = ('<bldg:Building gml:id="B2"><bldg:lod2MultiSurface><gml:MultiSurface>'
                '<gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing><gml:posList>'
                '1 2 3 4 5 x 7 8 9 1 2 3</gml:posList></gml:LinearRing></gml:exterior>'
                '</gml:Polygon></gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface>'
                '</bldg:Building>')
    bad = city(building("B1", box_polygons(0, 0, 0, 10, 10, 5)), bad_ring,
               building("B3", box_polygons(20, 0, 0, 5, 5, 5, prefix="q")))
    bad_path = tmp_path / "bad.gml"
    bad_path.write_text(bad)
    sample = Path(__file__).resolve().parents[2] / "sample_data" / "sample_city.gml"
    for path in (sample, bad_path):
        whole = read_citygml(path)
        monkeypatch.setattr(reader, "_PARSE_BATCH_CHARS", batch_chars)
        batched = read_citygml(path)
        monkeypatch.undo()
        for name in ("xyz", "ring_points", "ring_bad", "poly_obj", "poly_ring0", "ref_obj"):
            a, b = getattr(whole, name), getattr(batched, name)
            assert a.dtype == b.dtype and np.array_equal(a, b), (path.name, name)
        assert whole.ring_by_id == batched.ring_by_id and whole.counters == batched.counters
    assert whole.ring_bad.sum() == 1


def test_a_failed_read_leaves_no_parser_thread(tmp_path, monkeypatch):
    """A file that fails after batches were flushed stops the ring parser's thread."""
    import threading

    import cityshade.citygml.reader as reader

    doc = city(*(building(f"B{i}", box_polygons(10 * i, 0, 0, 5, 5, 5, prefix=f"p{i}"))
                 for i in range(3)))
    path = tmp_path / "cut.gml"
    path.write_text(doc[: len(doc) - 200])
    monkeypatch.setattr(reader, "_PARSE_BATCH_CHARS", 1)
    with pytest.raises(XMLSyntaxError):
        read_citygml(path)
    assert not any(t.name == "cityshade-ring-parse" for t in threading.enumerate())
