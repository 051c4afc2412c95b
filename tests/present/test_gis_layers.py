"""results.gpkg: read back with pyogrio, in the model's CRS, with the values of surfaces.csv and
openings.csv; outlines with their holes; footprints; GeoJSON in longitude/latitude."""
from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, wall_with_window

pyogrio = pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")

X0, Y0 = 690000.0, 5336000.0  # EPSG:25832, near Munich


def _window_house():
    """A south wall at y = Y0 with a 1 m x 0.2 m window (gml:id WIN) in a hole of it."""
    return wall_with_window(lambda pts: [(X0 + x, Y0 + y, z) for x, y, z in pts])


@pytest.fixture(scope="module")
def comparison(tmp_path_factory):
    """A house with a window, a block 6 m south of it, and a small box built in 2030 right in
    front of the window, compared 2025 against 2031 under four explicit suns; the tables and
    the layers written."""
    from datetime import date, datetime, timedelta, timezone

    from cityshade.build import build_scene_from_file
    from cityshade.geo.sun import sun_from_angles
    from cityshade.planning.compare import Receivers, compare_states, write_comparison
    from cityshade.planning.gis import compare_layers
    from cityshade.present.gis import write_gis
    from cityshade.raster.camera import map_view
    from cityshade.sunhours.plan import Step

    tmp = tmp_path_factory.mktemp("gis")
    block = building("BLOCK", box_polygons(X0 - 20.0, Y0 - 12.0, 0.0, 40.0, 6.0, 8.0, "b"))
    new = building("NEW", box_polygons(X0 - 2.0, Y0 - 4.0, 0.0, 4.0, 1.0, 3.0, "n"),
                   extra="<bldg:yearOfConstruction>2030</bldg:yearOfConstruction>")
    gml = tmp / "m.gml"
    gml.write_text(city(_window_house(), block, new))
    scene = build_scene_from_file(gml)
    t0 = datetime(2025, 3, 21, 8, tzinfo=timezone.utc)
    steps = [Step(i, t0 + timedelta(hours=i), t0 + timedelta(hours=i + 1)) for i in range(4)]
    suns = [sun_from_angles(az, el, scene.crs, scene.origin_m)
            for az, el in ((120, 20), (160, 35), (200, 35), (240, 20))]
    t_a, t_b = ((date(y, 6, 1) - date(1970, 1, 1)).days for y in (2025, 2031))
    comp = compare_states(scene, t_a, scene, t_b, map_view(scene, 1.0), steps,
                          Receivers(samples_per_m2=2.0), suns=suns)
    out = tmp / "out"
    out.mkdir()
    write_comparison(out, comp, {"cityshade:kind": "compare"})
    written = write_gis(out, compare_layers(comp), scene.crs)
    return comp, scene, out, written


def _csv(path):
    with path.open() as fh:
        return list(csv.DictReader(fh))


def _close(a, text, digits=4):
    if text == "":
        return a is None or (isinstance(a, float) and math.isnan(a))
    return a is not None and abs(float(a) - float(text)) <= 0.6 * 10 ** -digits


def test_the_geopackage_reads_back_with_the_crs_and_the_csv_values(comparison):
    import pyproj

    comp, scene, out, written = comparison
    gpkg = out / "results.gpkg"
    assert gpkg in written
    # layer_styles: the shipped QGIS styles (tests/present/test_qgis_styles.py).
    layers = {name for name, _ in pyogrio.list_layers(gpkg)} - {"layer_styles"}
    assert layers == {"surfaces", "openings", "buildings"}
    for layer in layers:
        info = pyogrio.read_info(gpkg, layer=layer)
        assert pyproj.CRS(info["crs"]).to_epsg() == 25832
    meta, _, geoms, values = pyogrio.raw.read(gpkg, layer="surfaces")
    fields = list(meta["fields"])
    rows = _csv(out / "surfaces.csv")
    assert len(rows) == len(geoms) == 2 + 6  # the wall, the window and the block's faces
    for k, row in enumerate(rows):
        got = {name: values[i][k] for i, name in enumerate(fields)}
        for col in ("object_id", "polygon_id", "surface_class"):
            assert str(got[col]) == row[col]
        assert int(got["polygon_index"]) == int(row["polygon_index"])
        assert int(got["samples"]) == int(row["samples"])
        assert _close(got["area_m2"], row["area_m2"], 3)
        for col in ("hours_before", "hours_after", "loss_h", "loss_pct", "longest_before_h",
                    "longest_after_h"):
            v = got[col]
            assert _close(None if v is None or (isinstance(v, float) and math.isnan(v))
                          else v, row[col]), (col, v, row[col])
    meta, _, geoms, values = pyogrio.raw.read(gpkg, layer="openings")
    fields = list(meta["fields"])
    (row,) = _csv(out / "openings.csv")
    got = {name: values[i][0] for i, name in enumerate(fields)}
    assert got["opening_id"] == row["opening_id"] == "WIN"
    for col in ("hours_before", "hours_after", "loss_h", "ref_hours_before", "ref_hours_after",
                "facing_deg"):
        assert _close(got[col], row[col], 1 if col == "facing_deg" else 4), col
    # The window is its 1 m × 0.2 m rectangle in the wall's plane, at y = Y0.
    win = shapely.from_wkb(geoms[0])
    coords = np.array([c for p in win.geoms for c in p.exterior.coords])
    assert np.allclose(coords[:, 1], Y0, atol=1e-3)
    assert coords[:, 0].min() == pytest.approx(X0 - 0.5, abs=1e-3)
    assert coords[:, 2].max() == pytest.approx(1.2, abs=1e-3)


def test_outlines_keep_holes_and_buildings_get_footprints(comparison):
    comp, scene, out, _ = comparison
    gpkg = out / "results.gpkg"
    meta, _, geoms, values = pyogrio.raw.read(gpkg, layer="surfaces")
    ids = list(values[list(meta["fields"]).index("polygon_id")])
    wall = shapely.from_wkb(geoms[ids.index("WALLPOLY")])
    (part,) = wall.geoms
    assert len(part.interiors) == 1  # the window's hole, back from the triangles
    roof = shapely.from_wkb(geoms[ids.index("br")])
    # A flat roof seen from above: its 40 m × 6 m area.
    assert shapely.area(shapely.force_2d(roof)) == pytest.approx(240.0, rel=1e-6)
    meta, _, geoms, values = pyogrio.raw.read(gpkg, layer="buildings")
    fields = list(meta["fields"])
    objs = list(values[fields.index("object_id")])
    block = shapely.from_wkb(geoms[objs.index("BLOCK")])
    assert block.area == pytest.approx(240.0, rel=1e-6)
    assert values[fields.index("footprint_source")][objs.index("BLOCK")] == "ground"
    # The house is one wall: no ground surface, nothing facing down; a convex hull of a
    # vertical wall has no area.
    assert "HOUSE" not in objs or values[fields.index("footprint_source")][
        objs.index("HOUSE")] in ("convex_hull", "none")


def test_geojson_is_longitude_latitude(comparison):
    import pyproj

    comp, scene, out, written = comparison
    path = out / "results_buildings.geojson"
    assert path in written
    doc = json.loads(path.read_text())
    assert doc["type"] == "FeatureCollection" and "crs" not in doc  # RFC 7946: WGS 84 only
    feature = next(f for f in doc["features"] if f["properties"]["object_id"] == "BLOCK")
    ring = np.array(feature["geometry"]["coordinates"][0][0])
    lon, lat = pyproj.Transformer.from_crs(25832, 4326, always_xy=True).transform(X0, Y0)
    assert np.abs(ring[:, 0] - lon).max() < 0.001 and np.abs(ring[:, 1] - lat).max() < 0.001
