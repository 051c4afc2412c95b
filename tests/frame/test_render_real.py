"""Real data renders: TUM campus LoD2 (no terrain: with a ground plane) and textured files."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import shared_file

from cityshade.build import build_file
from cityshade.store.scenefile import load_scene
from cityshade.geo.sun import sun_from_angles


def _scene(path, tmp_path):
    out, _, _ = build_file(path, tmp_path / "s.cityshade")
    return load_scene(out)


def test_tum_campus_with_ground(tmp_path):
    from cityshade.raster.camera import map_view, overview
    from cityshade.frame.render import render_frame, shadow_mask

    scene = _scene(shared_file("munich-tum-campus-lod2/TUM Munich.gml"), tmp_path)
    sun = sun_from_angles(200.0, 35.0, scene.crs, scene.origin_m)
    view = render_frame(scene, overview(scene, 320, 200), 20000.0, sun, ground="auto")
    assert np.isfinite(view.rgb).all() and view.surfaces.valid.mean() > 0.5
    building = view.gbuffer.prim_id >= 0
    ground = view.surfaces.valid & ~building
    # Walls and roofs away from the sun, and courtyards, are dark; the rest is lit.
    assert 0.1 < view.lit[building].mean() < 0.9
    # The ground plane receives the buildings' shadows.
    assert (view.lit[ground] == 0).sum() > 100
    m = render_frame(scene, map_view(scene, 2.0), 20000.0, sun)
    mask = shadow_mask(m)
    # Without terrain most of a map is "no surface" (DESIGN §14) — marked nodata, not lit.
    assert 0.5 < (mask == 128).mean() < 0.9
    with_ground = shadow_mask(render_frame(scene, map_view(scene, 2.0), 20000.0, sun, ground="min"))
    assert (with_ground == 128).mean() == 0.0 and (with_ground == 0).mean() > (mask == 0).mean()


@pytest.mark.parametrize("relative", [
    "plateau-tokyo-meiji-gallery/53394517_bldg_6697_2_op_CityGML3.gml",
    "citygml4j-samples/lod3_building_v2.gml",
])
def test_textured_model_shows_its_textures(relative, tmp_path):
    from cityshade.raster.camera import overview
    from cityshade.frame.render import render_frame
    from cityshade.frame.shading import albedo_of_surfaces

    scene = _scene(shared_file(relative), tmp_path)
    assert scene.textures, "the model should carry textures"
    frame = render_frame(scene, overview(scene, 256, 192), 20000.0,
                         sun_from_angles(160.0, 40.0, scene.crs, scene.origin_m))
    textured = frame.surfaces.valid & (frame.surfaces.texture >= 0)
    assert textured.mean() > 0.05
    # Textured pixels do not have the flat palette/material colour: their albedo varies.
    albedo = albedo_of_surfaces(scene, frame.surfaces)
    assert np.asarray(albedo)[textured][:, :3].std(axis=0).max() > 0.02
