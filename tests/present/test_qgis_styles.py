"""The shipped QGIS styles (issue 39 point 4): each ``.qml`` is XML that colours a field the
layers of ``results.gpkg`` really have, and ``write_gis`` puts it into the GeoPackage's
``layer_styles`` table (QGIS's schema) as the layer's default style."""
from __future__ import annotations

import itertools
import sqlite3
import xml.etree.ElementTree as ET
from importlib.resources import files

import numpy as np
import pytest


def _qml(name: str) -> ET.Element:
    return ET.fromstring(files("cityshade.present").joinpath("styles", name).read_text(
        encoding="utf-8"))


def test_every_style_parses_and_colours_a_real_field_in_contiguous_classes():
    from cityshade.planning.compare import OPENING_COLUMNS, SURFACE_COLUMNS
    from cityshade.present.gis import STYLE_BY_FIELD
    from cityshade.sunhours.surfaces import CSV_COLUMNS

    # The fields of the layers: compare's surfaces and openings, batch's surfaces, and the
    # buildings' largest loss (planning/gis.py: building_layer(..., {"max_loss_h": ...})).
    real = set(SURFACE_COLUMNS) | set(OPENING_COLUMNS) | set(CSV_COLUMNS) | {"max_loss_h"}
    assert [f for f, _ in STYLE_BY_FIELD] == ["max_loss_h", "loss_h", "mean_sun_hours"]
    for field, name in STYLE_BY_FIELD:
        root = _qml(name)
        assert root.tag == "qgis"
        renderer = root.find("renderer-v2")
        assert renderer.get("type") == "graduatedSymbol" and renderer.get("attr") == field
        assert field in real
        ranges = renderer.findall("ranges/range")
        symbols = renderer.findall("symbols/symbol")
        assert len(ranges) >= 5 and sorted(s.get("name") for s in symbols) == sorted(
            r.get("symbol") for r in ranges)
        bounds = [(float(r.get("lower")), float(r.get("upper"))) for r in ranges]
        assert all(a[1] == b[0] for a, b in itertools.pairwise(bounds))  # no gap, no overlap


def test_write_gis_stores_the_styles_in_layer_styles_as_the_default(tmp_path):
    pyogrio = pytest.importorskip("pyogrio")
    import shapely

    from cityshade.geo.crs import parse_srs_name
    from cityshade.present.gis import Layer, write_gis

    square = shapely.MultiPolygon([shapely.Polygon([(0, 0, 1), (1, 0, 1), (1, 1, 1)])])
    layers = [Layer("surfaces", [square], {"polygon_id": ["a"], "loss_h": [1.5]}),
              Layer("buildings", [square], {"max_loss_h": [1.5]}),
              Layer("rules", [square], {"rule": ["x"]}, geometry_type="MultiPolygon")]
    write_gis(tmp_path, layers, parse_srs_name("EPSG:25832"), geojson=False)
    gpkg = tmp_path / "results.gpkg"
    # GDAL lists the styles' table beside the results (as in a GeoPackage QGIS has styled).
    assert {n for n, _ in pyogrio.list_layers(gpkg)} == {"surfaces", "buildings", "rules",
                                                          "layer_styles"}
    meta, _, _, _ = pyogrio.raw.read(gpkg, layer="layer_styles", read_geometry=False)
    assert "styleQML" in list(meta["fields"])
    with sqlite3.connect(gpkg) as db:
        rows = db.execute("SELECT f_table_name, f_geometry_column, styleName, useAsDefault, "
                          "styleQML FROM layer_styles ORDER BY id").fetchall()
        geometry_column = db.execute("SELECT column_name FROM gpkg_geometry_columns WHERE "
                                     "table_name = 'surfaces'").fetchone()[0]
    assert [r[:4] for r in rows] == [("surfaces", geometry_column, "cityshade loss", 1),
                                     ("buildings", geometry_column, "cityshade building_loss", 1)]
    assert ET.fromstring(rows[0][4]).find("renderer-v2").get("attr") == "loss_h"


@pytest.mark.parametrize("field,values,unit", [
    ("svf", [0.1, 0.95], ""), ("irradiance_kwh_m2", [12.0, 1033.5, float("nan")], " kWh/m²")])
def test_the_sky_layers_get_a_graduated_style_made_for_their_values(field, values, unit):
    """The sky's fields: seven contiguous classes of the template's ramp on the field, the
    first from 0, the last open above and starting at or below the largest value."""
    from cityshade.present.gis import Layer, layer_style

    name, qml = layer_style(Layer("surfaces", [None] * len(values), {"polygon_id": ["a"] *
                                                                    len(values), field: values}))
    assert name == f"{field}.qml"
    renderer = ET.fromstring(qml).find("renderer-v2")
    assert renderer.get("type") == "graduatedSymbol" and renderer.get("attr") == field
    ranges = renderer.findall("ranges/range")
    bounds = [(float(r.get("lower")), float(r.get("upper"))) for r in ranges]
    assert len(bounds) == 7 and bounds[0][0] == 0.0 and bounds[-1][1] >= 1e9
    assert all(a[1] == b[0] and a[0] < a[1] for a, b in itertools.pairwise(bounds))
    assert bounds[-1][0] <= np.nanmax(values) or field == "svf"
    assert ranges[-1].get("label").endswith(f"{unit} or more")
    assert sorted(s.get("name") for s in renderer.findall("symbols/symbol")) == sorted(
        r.get("symbol") for r in ranges)
