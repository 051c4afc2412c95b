"""The golden-image cases: small renders of the sample city (shared by the test and the
regeneration command ``python tests/golden/regenerate.py``)."""
from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: name → (date, camera, (width, height) or map pixel size in m, sun azimuth °, sun elevation °,
#: output: "png" picture or "mask", shadow technique)
CASES = {
    "sample_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png", "raytrace"),
    "sample_overview_1750": ("1750", "overview", (256, 160), 135.0, 30.0, "png", "raytrace"),
    "sample_map_1990_mask": ("1990", "map", 2.0, 200.0, 25.0, "mask", "raytrace"),
    "shadowmap_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png", "shadowmap"),
    "vsm_map_1990_mask": ("1990", "map", 2.0, 200.0, 25.0, "mask", "vsm"),
    "lispsm_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png", "lispsm"),
    "csm_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png", "csm"),
    "hybrid_vsm_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png", "hybrid:vsm"),
}


def render_case(scene, name: str):
    """8-bit image of one case."""
    from cityshade.geo.temporal import parse_user_date
    from cityshade.raster import camera as cams
    from cityshade.frame.render import render_frame, shadow_mask
    from cityshade.frame.shading import to_srgb8
    from cityshade.geo.sun import sun_from_angles

    date, kind, size, az, el, out, technique = CASES[name]
    cam = cams.overview(scene, *size) if kind == "overview" else cams.map_view(scene, size)
    sun = sun_from_angles(az, el, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, parse_user_date(date).city_days, sun, technique)
    return to_srgb8(frame.rgb) if out == "png" else shadow_mask(frame)


def sample_scene(tmp_dir: Path):
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    out, _, _ = build_file(REPO / "sample_data" / "sample_city.gml", tmp_dir / "sample.cityshade")
    return load_scene(out)
