"""ClosureSurfaces are virtual: left out of the scene by default (counted), kept on request."""
from __future__ import annotations

import json

import numpy as np
import pytest
from click.testing import CliRunner
from lxml import etree

from citygml_snippets import box_polygons, building, city
from conftest import shared_file

from cityshade.citygml.namespaces import SURFACE_CODE
from cityshade.citygml.reader import read_citygml
from cityshade.cli.main import cli
from cityshade.config import BuildSettings
from cityshade.errors import ConfigError
from cityshade.geometry.scene import build_scene


def _box_with_closure(tmp_path):
    faces = box_polygons(0, 0, 0, 10, 10, 5)
    # The east wall is a passage closed by a virtual surface.
    faces = [("ClosureSurface" if pid == "pe" else cls, pid, pts) for cls, pid, pts in faces]
    path = tmp_path / "closure.gml"
    path.write_text(city(building("b1", faces)))
    return path


def test_closure_surface_neither_casts_nor_receives_by_default(tmp_path):
    path = _box_with_closure(tmp_path)
    omitted = build_scene(read_citygml(path))
    assert omitted.n_triangles == 10
    assert SURFACE_CODE["closure"] not in set(np.asarray(omitted.tri_class).tolist())
    assert omitted.report["left_out"] == {"closure_polygons": 1, "closure_triangles": 2}
    assert omitted.report["closure_surfaces"] == "omit"
    assert "pe" not in omitted.poly_ids
    kept = build_scene(read_citygml(path), BuildSettings(closure_surfaces="keep"))
    assert kept.n_triangles == 12 and kept.report["left_out"] == {}
    assert (np.asarray(kept.tri_class) == SURFACE_CODE["closure"]).sum() == 2
    with pytest.raises(ConfigError):
        BuildSettings(closure_surfaces="drop")


def test_closure_option_on_the_command_line(tmp_path):
    path = _box_with_closure(tmp_path)
    runner = CliRunner()
    for option, triangles in (([], 10), (["--closure-surfaces", "keep"], 12)):
        out = tmp_path / f"b{triangles}.cityshade"
        result = runner.invoke(cli, ["build", str(path), "-o", str(out), "-q", *option])
        assert result.exit_code == 0, result.output
        d = json.loads(runner.invoke(cli, ["info", str(out), "--json"]).output)
        assert d["triangles"] == triangles
    text = runner.invoke(cli, ["info", str(tmp_path / "b10.cityshade")]).output
    assert "left out    1 ClosureSurface polygons (2 triangles)" in text
    bad = runner.invoke(cli, ["build", str(path), "-o", str(tmp_path / "x.cityshade"),
                              "--closure-surfaces", "drop"])
    assert bad.exit_code == 2 and "Traceback" not in bad.output


@pytest.mark.shared
def test_berlin_buildings_closure_triangles():
    path = shared_file("berlin-lichtenberg-trees/lod2_buildings_berlin_test_area.gml")
    # Independently: the ClosureSurfaces' polygons in the XML.
    root = etree.parse(str(path)).getroot()
    closure_polys = sum(1 for cs in root.iter("{*}ClosureSurface")
                        for _ in cs.iter("{http://www.opengis.net/gml}Polygon"))
    raw = read_citygml(path)
    omitted = build_scene(raw)
    kept = build_scene(read_citygml(path), BuildSettings(closure_surfaces="keep"))
    left = omitted.report["left_out"]
    assert left["closure_polygons"] == closure_polys
    # The figure: 289 ClosureSurface triangles in this file.
    assert left["closure_triangles"] == 289
    assert kept.n_triangles - omitted.n_triangles == 289
    assert (np.asarray(kept.tri_class) == SURFACE_CODE["closure"]).sum() == 289
