"""``exact``: the cheaper exact engine per call (:mod:`cityshade.shadows.exact`), the answer
of ``raytrace`` on every pixel whichever it takes."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.shadows import exact as E
from cityshade.shadows.exact import (IZB_FIRST_USE_NS_PER_CASTER,
                                     IZB_FIRST_USE_NS_PER_RECEIVER, choose_engine,
                                     choose_for_tree, engine_for_run)

# Workloads measured at cd5487c (issue 41; benchmarks/raytrace.py, whole-process renders):
# the 1M-triangle city's 1 m map (4.10 M shadow rays) and its 1080p overview (1.49 M).
CITY_1M = 999_672


def test_a_single_large_map_in_a_fresh_process_goes_to_raytrace():
    # Whole process: raytrace 2.12 s against izb 2.82 s (the caster sort is paid in the call).
    choice = choose_engine(4_100_000, CITY_1M)
    assert choice.engine == "raytrace" and "caster sort in this call" in choice.reason
    # Session 35 (benchmarks/exact_choice.py, renders without huge pages): izb's whole process
    # took 0.18 and 0.28 s longer on the 1 m map (2,609,871 rays) and 0.19-0.35 s on the
    # overview (1,566,120): its first call's receivers cost about what kd-tree rays do. -v's
    # estimates differ by about that, not by the first model's 0.9-1.0 s.
    for rays in (1_566_120, 2_609_871, 4_100_000):
        one = choose_engine(rays, CITY_1M)
        assert one.engine == "raytrace"
        assert 200 <= one.izb_ms - one.raytrace_ms <= 400


def test_warm_casters_go_to_izb():
    # benchmarks/raytrace.py (warm, 2 threads): izb 18.3 against 8.2 Mrays/s on the map,
    # 36.8 against 13.4 on the overview (a saving worth having over a few frames).
    assert choose_engine(4_100_000, CITY_1M, warm=True).engine == "izb"
    assert choose_engine(1_490_000, CITY_1M, warm=True, calls=10).engine == "izb"


def test_a_day_of_sun_positions_shares_the_sort_and_goes_to_izb(monkeypatch):
    # benchmarks/batch.py: 96 positions over the 2.14 Mpx map, izb 1.55x the kd-tree.
    monkeypatch.setattr(E, "izb_compiled", lambda: True)
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


def test_izb_not_compiled_yet_is_charged_its_compile_once(monkeypatch):
    # The sample city's first batch (a day at 1 m: 685,000 rays, 49 suns) saves seconds with
    # izb, less than izb's kernels take to compile: raytrace, whose kernels a render compiled.
    cold = choose_engine(685_000, 1_386, calls=49, compiled=False)
    assert cold.engine == "raytrace" and "izb not compiled yet" in cold.reason
    assert choose_engine(685_000, 1_386, calls=49).engine == "izb"
    # A year of the 1M city's map (96 suns a day) saves far more than the compile.
    assert choose_engine(2_000_000, CITY_1M, calls=96 * 365, compiled=False).engine == "izb"
    assert choose_engine(2_000_000, CITY_1M, calls=96, compiled=False).engine == "raytrace"
    # The saving against the compile, at the threshold: one more call tips it.
    per_call = choose_engine(1_000_000, 1_386, warm=True)
    saving = per_call.raytrace_ms - per_call.izb_ms
    calls = int((E.IZB_COMPILE_MS + E.IZB_MIN_SAVING_MS) // saving) + 1
    assert choose_engine(1_000_000, 1_386, warm=True, calls=calls, compiled=False).engine == "izb"
    assert choose_engine(1_000_000, 1_386, warm=True, calls=calls - 2,
                         compiled=False).engine == "raytrace"
    # The run-wide choice reads the state of the machine.
    scene = type("S", (), {"n_triangles": 1_386})()
    monkeypatch.setattr(E, "izb_compiled", lambda: False)
    assert engine_for_run("exact", scene, 685_000, 49) == "raytrace"
    monkeypatch.setattr(E, "izb_compiled", lambda: True)
    assert engine_for_run("exact", scene, 685_000, 49) == "izb"


def test_izb_compiled_reads_numba_s_cache(tmp_path):
    import os
    import subprocess
    import sys

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path))
    probe = ("from cityshade.shadows.exact import izb_compiled as c; import numpy as np; "
             "from cityshade.lightspace.kernels import query; print(c())")
    out = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == ["False"]        # an empty cache, nothing run: not compiled


def test_the_first_use_cost_is_shared_by_the_calls():
    cold = choose_engine(1_000_000, CITY_1M, calls=1)
    shared = choose_engine(1_000_000, CITY_1M, calls=10)
    assert cold.izb_ms - shared.izb_ms == pytest.approx(
        (CITY_1M * IZB_FIRST_USE_NS_PER_CASTER + 1_000_000 * IZB_FIRST_USE_NS_PER_RECEIVER)
        * 1e-6 * (1 - 1 / 10))
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
    assert E.izb_compiled()        # izb ran in this process
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


def test_the_choice_waits_for_izb_while_the_command_s_children_compile_it(monkeypatch):
    """``cityshade sky``'s first use: its children compile izb's kernels while the command
    starts; the engine for the whole run is chosen once they have, not on a cache that is
    still being filled (the first sky of the 1M city would go to raytrace: 35 s against 21)."""
    from cityshade.runtime import interpret, prewarm

    cached = []
    waited = []
    monkeypatch.setattr(interpret, "compiled_or_cached", lambda kernel: bool(cached))
    monkeypatch.setattr(prewarm, "pending", lambda name: not cached)
    monkeypatch.setattr(prewarm, "wait", lambda name: (waited.append(name), cached.append(1)))
    assert E.izb_compiled()
    assert waited == ["cityshade.lightspace.kernels:query"]
    cached.clear()
    monkeypatch.setattr(prewarm, "pending", lambda name: False)   # no child has it: no wait
    assert not E.izb_compiled() and len(waited) == 1
