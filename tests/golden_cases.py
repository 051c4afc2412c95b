"""The golden-image cases: small renders of the sample city (shared by the test and the
regeneration command ``python tests/golden/regenerate.py``)."""
from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: name → (date, camera, size or pixel size, sun azimuth, sun elevation, output kind)
CASES = {
    "sample_overview_1990": ("1990", "overview", (256, 160), 135.0, 30.0, "png"),
    "sample_overview_1750": ("1750", "overview", (256, 160), 135.0, 30.0, "png"),
    "sample_map_1990_mask": ("1990", "map", 2.0, 200.0, 25.0, "mask"),
}


def render_case(scene, name: str):
    """8-bit image of one case."""
    from cityshade.citygml.temporal import parse_user_date
    from cityshade.raster import camera as cams
    from cityshade.render import render_frame, shadow_mask
    from cityshade.shading import to_srgb8
    from cityshade.sun import sun_from_angles

    date, kind, size, az, el, out = CASES[name]
    cam = cams.overview(scene, *size) if kind == "overview" else cams.map_view(scene, size)
    sun = sun_from_angles(az, el, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, parse_user_date(date).city_days, sun, "raytrace")
    return to_srgb8(frame.rgb) if out == "png" else shadow_mask(frame)


def sample_scene(tmp_dir: Path):
    from cityshade.build import build_file
    from cityshade.scenefile import load_scene

    out, _, _ = build_file(REPO / "sample_data" / "sample_city.gml", tmp_dir / "sample.cityshade")
    return load_scene(out)


# --- shadow-map techniques (issue 5): cases rendered with a technique other than raytrace ------

#: case name → shadow technique; cases not listed here are rendered with "raytrace".
CASE_TECHNIQUE: dict[str, str] = {}
CASES["lispsm_overview_1990"] = ("1990", "overview", (256, 160), 135.0, 30.0, "png")
CASE_TECHNIQUE["lispsm_overview_1990"] = "lispsm"
CASES["csm_overview_1990"] = ("1990", "overview", (256, 160), 135.0, 30.0, "png")
CASE_TECHNIQUE["csm_overview_1990"] = "csm"


def _render_case_with_technique(scene, name: str, technique: str):
    from cityshade.citygml.temporal import parse_user_date
    from cityshade.raster import camera as cams
    from cityshade.render import render_frame, shadow_mask
    from cityshade.shading import to_srgb8
    from cityshade.sun import sun_from_angles

    date, kind, size, az, el, out = CASES[name]
    cam = cams.overview(scene, *size) if kind == "overview" else cams.map_view(scene, size)
    sun = sun_from_angles(az, el, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, parse_user_date(date).city_days, sun, technique)
    return to_srgb8(frame.rgb) if out == "png" else shadow_mask(frame)


def render_case(scene, name: str):  # noqa: F811 - extends the definition above with techniques
    """8-bit image of one case, with the case's technique (``CASE_TECHNIQUE``, else raytrace)."""
    return _render_case_with_technique(scene, name, CASE_TECHNIQUE.get(name, "raytrace"))
CASES["shadowmap_overview_1990"] = ("1990", "overview", (256, 160), 135.0, 30.0, "png")
CASE_TECHNIQUE["shadowmap_overview_1990"] = "shadowmap"
CASES["vsm_map_1990_mask"] = ("1990", "map", 2.0, 200.0, 25.0, "mask")
CASE_TECHNIQUE["vsm_map_1990_mask"] = "vsm"
