"""``cityshade export``: the .glb and .ply read back by trimesh hold the vertices, colours and
``_VALUE`` written, equal to surfaces.csv's values per polygon."""
from __future__ import annotations

import csv
import json
import struct

import numpy as np
import pytest
import trimesh
from citygml_snippets import box_polygons, building, city, ground
from click.testing import CliRunner

from cityshade.cli.main import cli
from cityshade.sunhours.outputs import viridis_rgb

X0, Y0 = 690_000.0, 5_336_000.0


@pytest.fixture(scope="module")
def batch_run(tmp_path_factory):
    """A house, a taller block south of it and a ground square; batch --surfaces for a day."""
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("export")
    gml = tmp / "city.gml"
    gml.write_text(city(building("HOUSE", box_polygons(X0, Y0, 0.0, 10.0, 8.0, 6.0, "h")),
                        building("TALL", box_polygons(X0, Y0 - 12, 0.0, 10.0, 4.0, 20.0, "t")),
                        ground(X0 - 30, Y0 - 30, X0 + 40, Y0 + 20)))
    out, _, _ = build_file(gml, tmp / "city.cityshade")
    result = CliRunner().invoke(cli, ["batch", str(out), "--date", "2025-03-21", "--tz",
                                      "Europe/Berlin", "--every", "2h", "--pixel-size", "4",
                                      "--surfaces", "--no-gis", "-o", str(tmp / "batch")])
    assert result.exit_code == 0, result.output
    with open(tmp / "batch" / "surfaces.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    return tmp, out, load_scene(out), rows


def _glb_json(path) -> dict:
    data = path.read_bytes()
    (length,) = struct.unpack("<I", data[12:16])
    return json.loads(data[20:20 + length])


def test_glb_and_ply_round_trip_equal_surfaces_csv(batch_run):
    tmp, scene_path, scene, rows = batch_run
    glb, ply = tmp / "sun.glb", tmp / "sun.ply"
    result = CliRunner().invoke(cli, ["export", str(scene_path), str(tmp / "batch" / "surfaces.csv"),
                                      "-o", str(glb), "--ply", str(ply)])
    assert result.exit_code == 0, result.output
    value = {int(r["polygon_index"]): float(r["mean_sun_hours"]) for r in rows}
    top = max(value.values())
    assert result.output.strip() == (f"{glb}: {len(value)} polygons coloured by mean_sun_hours "
                                     f"(0 to {top:g} h), 0 without a value in grey; {ply}")
    # What should be there, from the scene and the table: each triangle of a valued polygon,
    # its three corners, in triangle order; glTF axes (x, z, -y).
    tri = np.asarray(scene.triangles)
    tri_value = np.array([value.get(int(p), np.nan) for p in scene.tri_polygon])
    keep = np.isfinite(tri_value)
    corners = np.asarray(scene.vertices, np.float64)[tri[keep]].reshape(-1, 3)
    want_value = np.repeat(tri_value[keep], 3).astype(np.float32)
    want_rgb = viridis_rgb(want_value.astype(np.float64) / top)

    loaded = trimesh.load(str(glb), process=False)
    mesh = loaded.geometry["result"]
    assert len(mesh.vertices) == len(corners) == 3 * int(keep.sum())
    np.testing.assert_allclose(mesh.vertices, np.column_stack(
        [corners[:, 0], corners[:, 2], -corners[:, 1]]), atol=1e-6)
    np.testing.assert_array_equal(np.asarray(mesh.vertex_attributes["_VALUE"]).ravel(), want_value)
    np.testing.assert_array_equal(mesh.visual.vertex_colors[:, :3], want_rgb)
    assert (mesh.visual.vertex_colors[:, 3] == 255).all()
    extras = _glb_json(glb)["asset"]["extras"]["cityshade"]
    assert extras == loaded.metadata["cityshade"]
    assert extras["legend"] == {"column": "mean_sun_hours", "unit": "h", "colour_map": "viridis",
                                "range": [0.0, top], "no_value_rgba": [200, 200, 200, 255],
                                "value_attribute": "_VALUE"}
    assert extras["origin_m"] == list(scene.origin_m) and extras["crs"]["epsg"] == 25832
    assert extras["units"] == "m"
    # Every vertex of a polygon carries the table's value of that polygon.
    got_poly = np.asarray(scene.tri_polygon)[keep].repeat(3)
    for p, v in value.items():
        got = np.unique(np.asarray(mesh.vertex_attributes["_VALUE"]).ravel()[got_poly == p])
        assert got.tolist() == [np.float32(v)]

    back = trimesh.load(str(ply), process=False)
    raw = back.metadata["_ply_raw"]["vertex"]["data"]
    n = len(corners)
    np.testing.assert_allclose(np.asarray(back.vertices)[:n], corners + scene.origin_m, atol=1e-6)
    np.testing.assert_array_equal(raw["_VALUE"][:n], want_value)
    np.testing.assert_array_equal(back.visual.vertex_colors[:n, :3], want_rgb)


def test_loss_column_of_another_scene_is_refused(batch_run, tmp_path):
    _, scene_path, _, _ = batch_run
    bad = tmp_path / "s.csv"
    with open(bad, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["object_id", "polygon_id", "polygon_index", "loss_h"])
        w.writerow(["X", "someone_else", 0, "1.5"])
    result = CliRunner().invoke(cli, ["export", str(scene_path), str(bad), "--column", "loss_h",
                                      "-o", str(tmp_path / "x.glb")])
    assert result.exit_code == 1
    assert result.output.strip() == (
        f"cityshade: error: {bad}:2: polygon 0 is 'hg' in the scene but 'someone_else' here: "
        f"the table is of another scene")
    assert not (tmp_path / "x.glb").exists()
    result = CliRunner().invoke(cli, ["export", str(scene_path), str(bad), "--column", "nope",
                                      "-o", str(tmp_path / "x.glb")])
    assert result.exit_code == 2
    assert result.output.strip() == ("cityshade: error: --column nope: the table's columns are "
                                     "object_id, polygon_id, polygon_index, loss_h")
