"""hybrid[:BASE]: exact shadows from a map classification plus rays for the uncertain pixels."""
from __future__ import annotations

import numpy as np
import pytest


from cityshade.citygml.temporal import parse_user_date
from cityshade.config import ShadowSettings
from cityshade.errors import UsageError
from cityshade.raster.camera import map_view, overview, preset
from cityshade.render import render_frame
from cityshade.shadows import get_technique
from cityshade.sun import sun_from_angles

BASES = ["shadowmap", "pcf", "vsm", "psm", "lispsm", "xpsm", "csm", "csm:lispsm"]


@pytest.fixture(scope="module")
def scene(sample_city_scene):
    return sample_city_scene


@pytest.fixture(scope="module")
def references(scene):
    """raytrace frames per (view, elevation), rendered once."""
    t = parse_user_date("1990").city_days
    cams = {"overview": overview(scene, 320, 200), "map": map_view(scene, 1.0),
            "south": preset("south", scene, 320, 200)}
    out = {}
    for name, cam in cams.items():
        for el in (5.0, 30.0, 70.0):
            sun = sun_from_angles(135.0, el, scene.crs, scene.origin_m)
            out[name, el] = (cam, sun, render_frame(scene, cam, t, sun, "raytrace"))
    return t, out


@pytest.mark.parametrize("base", BASES)
def test_hybrid_agrees_with_raytrace(scene, references, base):
    t, refs = references
    for (view, el), (cam, sun, ref) in refs.items():
        frame = render_frame(scene, cam, t, sun, f"hybrid:{base}")
        valid = ref.surfaces.valid
        wrong = ((frame.lit >= 0.5) != (ref.lit >= 0.5)) & valid
        agree = 1.0 - wrong.sum() / valid.sum()
        assert agree >= 0.9999, f"{view} sun {el}°: {wrong.sum()} pixels differ ({100 * agree:.4f} %)"
        d = frame.diagnostics.shadow
        assert 0.0 < d["traced_share"] < 0.5, d["traced_share"]
        refined = frame.extra_channels["refined"]
        assert refined.shape == valid.shape and set(np.unique(refined)) <= {0.0, 1.0}
        # Every traced pixel is a surface facing the sun; none is outside the surfaces.
        assert not (refined.astype(bool) & ~valid).any()


def test_bracket_classifier_misses_no_more_than_the_slides_vsm_classifier(scene, references):
    t, refs = references
    misses = {"bracket": 0, "vsm": 0}
    traced = {"bracket": 0, "vsm": 0}
    for (view, el), (cam, sun, ref) in refs.items():
        for clf in misses:
            f = render_frame(scene, cam, t, sun, "hybrid:vsm",
                             ShadowSettings().override(classifier=clf))
            misses[clf] += int((((f.lit >= 0.5) != (ref.lit >= 0.5)) & ref.surfaces.valid).sum())
            traced[clf] += f.diagnostics.shadow["traced_px"]
    assert misses["bracket"] == 0, misses
    assert misses["bracket"] <= misses["vsm"], misses


def test_names_and_errors():
    assert get_technique("hybrid").name == "hybrid:vsm"
    assert get_technique("hybrid:csm:lispsm").name == "hybrid:csm:lispsm"
    with pytest.raises(UsageError, match="shadow-map base"):
        get_technique("hybrid:raytrace")
    with pytest.raises(UsageError, match="unknown shadow technique 'magic'"):
        get_technique("hybrid:magic")


def test_night_traces_nothing(scene, references):
    t, refs = references
    cam, _, _ = refs["map", 30.0]
    frame = render_frame(scene, cam, t, sun_from_angles(0.0, -3.0), "hybrid:shadowmap")
    assert (frame.lit == 0).all() and frame.diagnostics.shadow["traced_px"] == 0
