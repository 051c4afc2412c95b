"""``exact``: the cheaper exact engine per call (:mod:`cityshade.shadows.exact`), the answer
of ``raytrace`` on every pixel whichever it takes."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.shadows.exact import (IZB_FIRST_USE_NS_PER_CASTER, choose_engine,
                                     choose_for_tree, engine_for_run)

# Workloads measured at cd5487c (issue 41; benchmarks/raytrace.py, whole-process renders):
# the 1M-triangle city's 1 m map (4.10 M shadow rays) and its 1080p overview (1.49 M).
CITY_1M = 999_672


def test_a_single_large_map_in_a_fresh_process_goes_to_raytrace():
    # Whole process: raytrace 2.12 s against izb 2.82 s (the caster sort is paid in the call).
    choice = choose_engine(4_100_000, CITY_1M)
    assert choice.engine == "raytrace" and "caster sort in this call" in choice.reason


def test_warm_casters_go_to_izb():
    # benchmarks/raytrace.py (warm, 2 threads): izb 18.3 against 8.2 Mrays/s on the map,
    # 36.8 against 13.4 on the overview (a saving worth having over a few frames).
    assert choose_engine(4_100_000, CITY_1M, warm=True).engine == "izb"
    assert choose_engine(1_490_000, CITY_1M, warm=True, calls=10).engine == "izb"


def test_a_day_of_sun_positions_shares_the_sort_and_goes_to_izb():
    # benchmarks/batch.py: 96 positions over the 2.14 Mpx map, izb 1.55x the kd-tree.
    assert choose_engine(2_000_000, CITY_1M, calls=96).engine == "izb"
    assert engine_for_run("exact", type("S", (), {"n_triangles": CITY_1M})(), 2_000_000,
                          96) == "izb"
    assert engine_for_run("raytrace", None, 2_000_000, 96) == "raytrace"


def test_few_rays_and_many_directions_go_to_raytrace():
    assert choose_engine(13, CITY_1M, warm=True).engine == "raytrace"      # window points
    many = choose_engine(1_000_000, 1_386, shared_direction=False)
    assert many.engine == "raytrace" and "one sun" in many.reason


def test_a_saving_nobody_notices_stays_with_raytrace():
    # The sample city's 1080p overview: izb would save ~45 ms once; a day of 96 suns, seconds.
    assert choose_engine(685_000, 1_386).engine == "raytrace"
    assert choose_engine(685_000, 1_386, calls=96).engine == "izb"


def test_the_first_use_cost_is_shared_by_the_calls():
    cold = choose_engine(1_000_000, CITY_1M, calls=1)
    shared = choose_engine(1_000_000, CITY_1M, calls=10)
    assert cold.izb_ms - shared.izb_ms == pytest.approx(
        CITY_1M * IZB_FIRST_USE_NS_PER_CASTER * 1e-6 * (1 - 1 / 10))
    assert cold.raytrace_ms == shared.raytrace_ms


def test_warmth_is_read_from_the_engine(sample_city_scene):
    from cityshade.lightspace import caster_order, casters_ready, forget_casters
    from cityshade.lightspace import occluded as izb_occluded

    scene = sample_city_scene
    sun = np.array([0.5, -0.5, np.sqrt(0.5)])
    forget_casters(scene.kdtree)
    assert not casters_ready(scene.kdtree, *caster_order(sun))
    assert "caster sort in this call" in choose_for_tree(scene.kdtree, 10, sun).reason
    izb_occluded(scene.kdtree, np.zeros((1, 3)), sun)
    assert casters_ready(scene.kdtree, *caster_order(sun))
    assert "casters ready" in choose_for_tree(scene.kdtree, 10, sun).reason
    other_axis = np.array([0.0, -0.99, np.sqrt(1 - 0.99 ** 2)])
    assert not casters_ready(scene.kdtree, *caster_order(other_axis))


@pytest.mark.parametrize("camera", ["overview", "map"])
def test_exact_render_equals_raytrace_and_says_which_engine(sample_city_scene, camera):
    from cityshade.frame.render import render_frame
    from cityshade.geo.sun import sun_from_angles
    from cityshade.geo.temporal import parse_user_date
    from cityshade.raster import camera as cams

    scene = sample_city_scene
    cam = cams.overview(scene, 160, 90) if camera == "overview" else cams.map_view(scene, 2.0)
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    t = parse_user_date("1750").city_days
    exact = render_frame(scene, cam, t, sun, "exact")
    ref = render_frame(scene, cam, t, sun, "raytrace")
    np.testing.assert_array_equal(exact.lit, ref.lit)
    note = exact.diagnostics.shadow["note"]
    assert note.startswith(("exact engine izb: ", "exact engine raytrace: ")), note
