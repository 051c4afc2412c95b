"""A proposal drawn as a mesh (``compare --with block.obj``): the same verdicts and hours as
the same block written as CityGML; the real Topologic massing (Y up, faces wound either way,
internal floor slabs) placed, stood up and turned outward."""
from __future__ import annotations

import csv
import re

import numpy as np
import pytest
import trimesh
from citygml_snippets import box_polygons, building, city, ground
from click.testing import CliRunner
from conftest import REPO

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.cli.main import cli
from cityshade.meshes.proposal import MeshPlacement, proposal_scene

X0, Y0 = 690_000.0, 5_336_000.0
#: The proposed block: 30 m east-west, 4 m deep, 30 m high, south of the house's garden.
BX, BY, W, D, H = X0 - 10.0, Y0 - 14.0, 30.0, 4.0, 30.0


def _obj_box(path, reversed_faces=(1, 4)):
    """The block as an OBJ in Y-up axes (x east, y up, z south), its origin at the centre of
    its footprint, as quads; the faces named are wound inward (exporters do that)."""
    hx, hz = W / 2, D / 2
    # Model (east, north, up) corners of the block around its footprint centre.
    c = [(-hx, -hz, 0), (hx, -hz, 0), (hx, hz, 0), (-hx, hz, 0),
         (-hx, -hz, H), (hx, -hz, H), (hx, hz, H), (-hx, hz, H)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    lines = [f"v {e} {u} {-n}" for e, n, u in c]  # Y up: file (x, y, z) = (east, up, -north)
    for k, q in enumerate(quads):
        q = q[::-1] if k in reversed_faces else q
        lines.append("f " + " ".join(str(i + 1) for i in q))
    path.write_text("\n".join(lines) + "\n")


@pytest.fixture
def model(tmp_path):
    from cityshade.build import build_file

    gml = tmp_path / "city.gml"
    gml.write_text(city(building("HOUSE", box_polygons(X0, Y0, 0.0, 10.0, 8.0, 6.0, "h")),
                        ground(X0 - 30, Y0 - 30, X0 + 40, Y0 + 20)))
    out, _, _ = build_file(gml, tmp_path / "city.cityshade")
    block = tmp_path / "block.gml"
    block.write_text(city(building("NEW", box_polygons(BX, BY, 0.0, W, D, H, "n"))))
    obj = tmp_path / "block.obj"
    _obj_box(obj)
    return out, block, obj


def _compare(model_path, outdir, *extra):
    args = ["compare", model_path, *extra, "--date", "2025-03-21", "--tz", "Europe/Berlin",
            "--every", "1h", "--pixel-size", "1", "--rules", "bre209",
            "--area", f"{X0},{Y0 - 9},{X0 + 10},{Y0 - 1}", "--no-gis", "-o", outdir]
    result = CliRunner().invoke(cli, [str(a) for a in args])
    assert result.exit_code == 0, result.output
    with open(outdir / "surfaces.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    return result.output.splitlines(), rows


def test_a_study_takes_a_placed_mesh_like_the_citygml_block(model, tmp_path):
    """``study --with block.obj --up-axis y --place X,Y`` draws the same panels as the same
    block written in CityGML (the GeoTIFF masks of both states, pixel for pixel)."""
    from cityshade.imageio import read_image

    city_model, block, obj = model
    outs = []
    for name, extra in (("gml", ["--with", block]),
                        ("obj", ["--with", obj, "--up-axis", "y", "--place",
                                 f"{BX + W / 2},{BY + D / 2}"])):
        out = tmp_path / name
        args = ["study", city_model, *extra, "--days", "2025-03-21", "--times", "09:00,15:00",
                "--tz", "Europe/Berlin", "--pixel-size", "1", "-o", out]
        result = CliRunner().invoke(cli, [str(a) for a in args])
        assert result.exit_code == 0, result.output
        outs.append(out)
    tifs = sorted(p.name for p in (outs[0] / "panels").glob("*.tif"))
    assert len(tifs) == 4
    for name in tifs:
        a, _ = read_image(outs[0] / "panels" / name)
        b, _ = read_image(outs[1] / "panels" / name)
        np.testing.assert_array_equal(a, b, err_msg=name)
    assert (np.asarray(read_image(outs[1] / "panels" / tifs[1])[0]) == 0).any()


def test_obj_block_gives_the_citygml_blocks_verdicts_and_hours(model, tmp_path):
    city_model, block, obj = model
    lines_gml, rows_gml = _compare(city_model, tmp_path / "gml", "--with", block)
    lines_obj, rows_obj = _compare(city_model, tmp_path / "obj", "--with", obj, "--up-axis", "y",
                                   "--place", f"{BX + W / 2},{BY + D / 2}")
    verdicts = [ln for ln in lines_gml if ln.startswith("bre209")]
    assert verdicts and verdicts == [ln for ln in lines_obj if ln.startswith("bre209")]
    assert "cityshade: warning: block.obj: 4 faces turned to face outward" in " ".join(lines_obj)
    existing_gml = [r for r in rows_gml if r["object_id"] == "HOUSE"]
    existing_obj = [r for r in rows_obj if r["object_id"] == "HOUSE"]
    assert existing_gml == existing_obj and len(existing_gml) == 6
    assert any(float(r["loss_h"]) > 0 for r in existing_gml)

    def proposal(rows, oid):
        mine = [r for r in rows if r["object_id"] == oid]
        assert all(r["hours_before"] == "" for r in mine)
        return sorted((r["surface_class"], float(r["area_m2"]), float(r["hours_after"]))
                      for r in mine)

    got, want = proposal(rows_obj, "block"), proposal(rows_gml, "NEW")
    assert [g[:2] for g in got] == [w[:2] for w in want]
    assert [g[0] for g in got] == ["ground", "roof", "wall", "wall", "wall", "wall"]
    np.testing.assert_allclose([g[2] for g in got], [w[2] for w in want], atol=1e-9)
    assert max(g[2] for g in got) > 10.0  # the roof: the whole day


def test_proposal_surfaces_in_the_gis_layers_and_the_report(model, tmp_path):
    """The proposal's own surfaces reach the GeoPackage (layer ``proposal_surfaces``, outlines
    from the scene after) and the report with the values ``surfaces.csv`` gives them; its roof,
    30 m above a 6 m house, has the sun at every step with the sun up."""
    import pyogrio
    import shapely

    city_model, block, _ = model
    out = tmp_path / "gis"
    args = ["compare", city_model, "--with", block, "--date", "2025-03-21", "--tz",
            "Europe/Berlin", "--every", "1h", "--pixel-size", "1", "-o", out]
    result = CliRunner().invoke(cli, [str(a) for a in args])
    assert result.exit_code == 0, result.output
    with open(out / "surfaces.csv", newline="") as fh:
        mine = [r for r in csv.DictReader(fh) if r["object_id"] == "NEW"]
    meta, _, geoms, values = pyogrio.raw.read(out / "results.gpkg", layer="proposal_surfaces")
    got = dict(zip(meta["fields"], values))
    assert sorted(got["polygon_id"]) == sorted(r["polygon_id"] for r in mine)
    by_id = {r["polygon_id"]: float(r["hours_after"]) for r in mine}
    # surfaces.csv writes 4 decimals; the layer keeps the float64.
    np.testing.assert_allclose(got["hours_after"], [by_id[p] for p in got["polygon_id"]],
                               rtol=0, atol=5e-5)
    assert all(v is None or np.isnan(v) for v in got["hours_before"])
    # Outlines where the block stands: its footprint's box, in the model CRS.
    bounds = shapely.total_bounds(shapely.from_wkb(geoms))
    np.testing.assert_allclose(bounds, (BX, BY, BX + W, BY + D), atol=1e-6)
    report = (out / "report.md").read_text()
    roof = [r for r in mine if r["surface_class"] == "roof"]
    sun_up = float(re.search(r"([\d.]+) h with the sun up", report).group(1))
    assert len(roof) == 1 and float(roof[0]["hours_after"]) == pytest.approx(sun_up, abs=0.005)
    row = next(ln for ln in report.splitlines() if ln.startswith("| roof |"))
    assert row.split("|")[2:5] == [" 1 ", f" {W * D:.1f} ", f" {sun_up:.2f} "]


def test_mesh_options_are_checked(model, tmp_path):
    city_model, block, obj = model
    result = CliRunner().invoke(cli, ["compare", str(city_model), "--with", str(obj), "--place",
                                      "1,x", "--date", "2025-03-21", "--tz", "UTC", "-o", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert result.output.strip() == ("cityshade: error: --place must be X,Y[,Z][,ROTATION_DEG] "
                                     "(model CRS metres, degrees counter-clockwise), not '1,x'")
    result = CliRunner().invoke(cli, ["compare", str(city_model), "--with", str(block),
                                      "--up-axis", "y", "--date", "2025-03-21", "--tz", "UTC", "-o",
                                      str(tmp_path / "o")])
    assert result.exit_code == 2
    assert result.output.strip() == ("cityshade: error: --mesh-units, --up-axis and --place are "
                                     "for a mesh proposal: --with FILE.obj|.glb|.gltf|.ply|.stl")


TOPOLOGIC = REPO.parent / "shared" / "data" / "meshes" / "TopologicBuilding.obj"


@pytest.mark.shared
def test_topologic_massing_stands_up_turned_outward(model):
    if not TOPOLOGIC.exists():
        pytest.skip(f"real data not available: {TOPOLOGIC}")
    from cityshade.store.scenefile import load_scene

    scene = load_scene(model[0])
    place = MeshPlacement(up_axis="y", place=MeshPlacement.parse_place(f"{X0 + 40},{Y0},,30"))
    prop = proposal_scene(TOPOLOGIC, scene, place)
    warnings = prop.report["warnings"]
    assert warnings[0] == ("TopologicBuilding.obj: TopologicBuilding is not a closed manifold "
                           "mesh (open edges or faces sharing an edge 3 times or more); it is "
                           "used as it is")
    v = np.asarray(prop.vertices, np.float64) + prop.origin_m
    assert v[:, 2].min() == pytest.approx(0.0, abs=1e-4)  # the ground plane of the model
    assert v[:, 2].max() == pytest.approx(18.0, abs=1e-4)
    # Turned 30° about its origin: the footprint's corners lie 3√2 m from (X0 + 40, Y0).
    r = np.hypot(v[:, 0] - X0 - 40, v[:, 1] - Y0)
    assert r.max() == pytest.approx(3 * 2 ** 0.5, abs=1e-4)
    tri = np.asarray(prop.triangles)
    c = v[tri]
    n = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
    centre = c.mean(axis=1)
    radial = centre[:, :2] - [X0 + 40, Y0]
    outer_wall = (np.abs(n[:, 2]) < 1e-6) & (np.linalg.norm(radial, axis=1) > 2.0) & (
        np.abs(np.einsum("ij,ij->i", n[:, :2], radial)) > 1e-6 * np.linalg.norm(n, axis=1))
    # Every outer wall faces out, the top faces up, the bottom down.
    assert outer_wall.sum() >= 48
    assert (np.einsum("ij,ij->i", n[outer_wall, :2], radial[outer_wall]) > 0).all()
    top, bottom = centre[:, 2] > 17.99, centre[:, 2] < 0.01
    assert (n[top, 2] > 0).all() and (n[bottom, 2] < 0).all()
    cls = np.asarray(prop.tri_class)
    assert (cls[top] == SURFACE_CODE["roof"]).all() and (cls[bottom] == SURFACE_CODE["ground"]).all()
    assert len(tri) == 204  # every face kept, the internal slabs too


def test_glb_is_y_up_by_default_and_equals_the_obj(model, tmp_path):
    """The same Y-up block as binary glTF (written by trimesh): no --up-axis needed, and the
    placed triangles are the OBJ's with --up-axis y."""
    from cityshade.store.scenefile import load_scene

    city_model, _, obj = model
    scene = load_scene(city_model)
    mesh = trimesh.load(str(obj), force="mesh", process=False)
    glb = tmp_path / "block.glb"
    glb.write_bytes(trimesh.exchange.gltf.export_glb(trimesh.Scene(mesh)))
    place = MeshPlacement.parse_place(f"{BX + W / 2},{BY + D / 2},2.5")
    a = proposal_scene(glb, scene, MeshPlacement(place=place))
    b = proposal_scene(obj, scene, MeshPlacement(up_axis="y", place=place))
    assert a.report["mesh"]["up_axis"] == "y" and b.report["mesh"]["up_axis"] == "y"
    va = np.asarray(a.vertices)[np.asarray(a.triangles)]
    vb = np.asarray(b.vertices)[np.asarray(b.triangles)]
    np.testing.assert_allclose(np.sort(va.reshape(-1, 9), axis=0), np.sort(vb.reshape(-1, 9), axis=0),
                               atol=1e-5)
    world = np.asarray(a.vertices, np.float64) + a.origin_m
    np.testing.assert_allclose(world.min(axis=0), [BX, BY, 2.5], atol=1e-4)
    np.testing.assert_allclose(world.max(axis=0), [BX + W, BY + D, 2.5 + H], atol=1e-4)


def test_place_stands_on_the_terrain_under_it(tmp_path):
    """Z of --place defaults to the terrain (a TIN sloping 10 % east) under X, Y."""
    from cityshade.build import build_scene_from_file

    dem = 'xmlns:dem="http://www.opengis.net/citygml/relief/2.0"'
    pts = [(X0 - 50, Y0 - 50), (X0 + 50, Y0 - 50), (X0 + 50, Y0 + 50), (X0 - 50, Y0 + 50)]
    z = {p: 0.1 * (p[0] - X0) + 40.0 for p in pts}

    def tri(a, b, c):
        ring = " ".join(f"{x} {y} {z[(x, y)]}" for x, y in (a, b, c, a))
        return (f"<gml:Triangle><gml:exterior><gml:LinearRing><gml:posList srsDimension=\"3\">"
                f"{ring}</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>")

    relief = (f'<dem:ReliefFeature gml:id="R"><dem:lod>2</dem:lod><dem:reliefComponent>'
              f'<dem:TINRelief gml:id="T"><dem:lod>2</dem:lod><dem:tin><gml:TriangulatedSurface '
              f'srsName="EPSG:25832"><gml:trianglePatches>{tri(pts[0], pts[1], pts[2])}'
              f'{tri(pts[0], pts[2], pts[3])}</gml:trianglePatches></gml:TriangulatedSurface>'
              f'</dem:tin></dem:TINRelief></dem:reliefComponent></dem:ReliefFeature>')
    from citygml_snippets import CG2

    gml = tmp_path / "terrain.gml"
    gml.write_text(city(building("HOUSE", box_polygons(X0, Y0, 40.0, 10.0, 8.0, 6.0, "h")),
                        relief, ns=f"{CG2} {dem}"))
    scene = build_scene_from_file(gml)
    assert (np.asarray(scene.tri_class) == SURFACE_CODE["terrain"]).sum() == 2
    obj = tmp_path / "b.obj"
    _obj_box(obj)
    prop = proposal_scene(obj, scene, MeshPlacement(
        up_axis="y", place=MeshPlacement.parse_place(f"{X0 + 20},{Y0 - 20}")))
    assert prop.report["mesh"]["ground"] == "terrain"
    assert prop.report["mesh"]["ground_z_m"] == pytest.approx(42.0, abs=1e-4)
    world = np.asarray(prop.vertices, np.float64) + prop.origin_m
    assert world[:, 2].min() == pytest.approx(42.0, abs=1e-4)
