"""Vegetation crowns that let part of the sun through: the transmission of a sun ray is the
product over the distinct crowns it crosses, 0 behind anything opaque; ``raytrace`` and ``izb``
give the same value on every ray, the brute-force twin too; sun-hours weight the hours by it."""
from __future__ import annotations

from datetime import datetime, timedelta, timezone

import numba
import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground, tree
from conftest import shared_file
from reference import reference_transmission

from cityshade.build import build_file
from cityshade.config import ConfigError, VegetationSettings
from cityshade.geo.sun import sun_from_angles
from cityshade.geometry.vegetation import (scene_vegetation, vegetation_mask, with_vegetation,
                                           without_vegetation)
from cityshade.shadows.visibility import transmission
from cityshade.store.scenefile import load_scene

TAU = 0.03  # the default in-leaf transmissivity (UMEP/SOLWEIG)
UP = np.array([0.0, 0.0, 1.0])


@pytest.fixture(scope="module")
def crowns(tmp_path_factory):
    """Ground 100 × 100 m; crowns A (z 5-11) and B (z 15-21) stacked over (-5..5, -5..5);
    crown C alone over (10..16, -5..5); a 10 m building at (20..30, -5..5) under crown D."""
    tmp = tmp_path_factory.mktemp("veg")
    src = tmp / "veg.gml"
    src.write_text(city(ground(-50, -50, 50, 50),
                        tree("A", box_polygons(-5, -5, 5, 10, 10, 6, "a")),
                        tree("B", box_polygons(-5, -5, 15, 10, 10, 6, "b")),
                        tree("C", box_polygons(10, -5, 5, 6, 10, 6, "c")),
                        tree("D", box_polygons(20, -5, 12, 10, 10, 6, "d"), kind="PlantCover"),
                        building("H", box_polygons(20, -5, 0, 10, 10, 10, "h"))))
    out, _, _ = build_file(src, tmp / "veg.cityshade")
    return load_scene(out)


def _rays(scene, points_m):
    return np.asarray(points_m, np.float64) - scene.origin_m


@pytest.mark.parametrize("engine", ["raytrace", "izb"])
def test_crowns_multiply_and_buildings_stop_the_sun(crowns, engine):
    origins = _rays(crowns, [(13, 0, 0.01),    # under C alone: enters and leaves it once
                             (0, 0, 0.01),     # under A and B: two crowns
                             (0, 0, 12.0),     # above A, under B
                             (25, 0, -0.5),    # under the building and crown D: opaque
                             (40, 0, 0.01)])   # open sky
    got = transmission(crowns, origins, UP, 0.0, engine=engine)
    np.testing.assert_array_equal(got, [TAU, TAU * TAU, TAU, 0.0, 1.0])


def test_vegetation_is_found_by_object_type(crowns):
    mask = vegetation_mask(crowns)
    assert mask.sum() == 4 * 12       # four boxes of 12 triangles
    veg = scene_vegetation(crowns)
    assert [crowns.obj_ids[o] for o in veg.crown_object] == ["A", "B", "C", "D"]
    assert veg.crown_class.tolist() == [0, 0, 0, 1]   # solitary ×3, plant cover


def test_per_class_and_season_transmissivity(crowns):
    settings = VegetationSettings()
    veg = scene_vegetation(crowns)
    assert veg.transmissivity(settings, 180).tolist() == [0.03] * 4
    assert veg.transmissivity(settings, 20).tolist() == [0.5] * 4
    evergreen = VegetationSettings(plant_cover=VegetationSettings().plant_cover.__class__(
        evergreen=True, leaf_on_transmissivity=0.1))
    assert veg.transmissivity(evergreen, 20).tolist() == [0.5, 0.5, 0.5, 0.1]
    south = VegetationSettings(leaf_on_day=280, leaf_off_day=100)
    assert south.in_leaf(20) and not south.in_leaf(180)
    with pytest.raises(ConfigError, match="leaf_on_day must be a day of the year"):
        VegetationSettings(leaf_on_day=0)


def test_engines_equal_each_other_and_the_brute_force_twin(crowns):
    veg = scene_vegetation(crowns)
    tri_crown = np.full(crowns.n_triangles, -1, np.int64)
    tri_crown[veg.tri] = veg.tri_crown
    rng = np.random.default_rng(7)
    origins = rng.uniform((-30, -30, -1), (40, 30, 22), (400, 3)) - crowns.origin_m
    settings = VegetationSettings(
        solitary=VegetationSettings().solitary.__class__(leaf_on_transmissivity=0.2))
    scene = with_vegetation(crowns, settings)
    for az, el in ((0, 90), (135, 40), (250, 12), (90, 60)):
        d = sun_from_angles(az, el).direction
        a = transmission(scene, origins, d, 0.0, engine="raytrace")
        b = transmission(scene, origins, d, 0.0, engine="izb")
        np.testing.assert_array_equal(a, b)
        assert 0 < ((a > 0) & (a < 1)).sum() and (a == 0).any() and (a == 1).any()
        crown_tau = veg.transmissivity(settings, None)
        want = [reference_transmission(crowns.vertices, crowns.triangles,
                                       crowns.tri_t_begin_days, crowns.tri_t_end_days,
                                       tri_crown, crown_tau, o, d) for o in origins[:60]]
        np.testing.assert_array_equal(a[:60], want)
    scene.__dict__.pop("vegetation_settings")


def test_without_vegetation_trees_neither_cast_nor_receive(crowns):
    bare = without_vegetation(crowns)
    assert bare.n_triangles == crowns.n_triangles - 48
    assert scene_vegetation(bare) is None
    origins = _rays(crowns, [(0, 0, 0.01), (25, 0, -0.5)])
    np.testing.assert_array_equal(transmission(bare, origins, UP, 0.0, engine="izb"), [1, 0])


def test_the_auto_ground_plane_leaves_the_trees_out(crowns):
    """The median of the objects' lowest points counted the crowns (bases 5-15 m here: 5 m
    with them, 0 m without), so a run with trees and one with --no-vegetation drew their
    ground planes apart; both now stand at the buildings' and terrain's 0 m."""
    from cityshade.geometry.ground import ground_height_m

    zero_m = 0.0 - float(crowns.origin_m[2])
    assert ground_height_m(crowns, "auto") == zero_m
    assert ground_height_m(without_vegetation(crowns), "auto") == zero_m


def test_sun_hours_with_trees_lose_exactly_the_crowns_share(crowns):
    from cityshade.sunhours.accumulate import sun_hours

    t0 = datetime(2024, 6, 21, 10, tzinfo=timezone.utc)
    instants = [t0, t0 + timedelta(hours=1)]
    suns = [sun_from_angles(0.0, 90.0), sun_from_angles(180.0, 30.0)]
    runs = {name: sun_hours(scene, None, instants, 0.0, suns=suns, weights_h=[1.0, 2.0],
                            technique="izb", samples_per_m2=1.0)
            for name, scene in (("with", crowns), ("without", without_vegetation(crowns)))}
    # The ground polygon's samples, the same points in both scenes.
    keep = {}
    for name, run in runs.items():
        pts = run.samples.points_m + crowns.origin_m
        ground_pts = np.abs(pts[:, 2]) < 1e-3
        keep[name] = (pts[ground_pts], run.sample_hours[ground_pts])
    np.testing.assert_array_equal(keep["with"][0], keep["without"][0])
    pts, with_h = keep["with"]
    without_h = keep["without"][1]
    assert (with_h <= without_h).all() and (with_h < without_h).any()
    # Samples under crown C (not under the building's shadow): the vertical sun reaches them
    # through C only; the low sun from the south passes south of C (at C's height, 5-11 m, the
    # ray is 8.7-19 m north of a point with y < 0, beyond C's y = 5 m): 1 h × τ + 2 h × 1.
    under_c = (pts[:, 0] > 10.5) & (pts[:, 0] < 15.5) & (pts[:, 1] > -4.5) & (pts[:, 1] < -1)
    assert under_c.sum() >= 5
    assert (without_h[under_c] == 3.0).all()
    assert (with_h[under_c] == 1.0 * TAU + 2.0).all()


#: Every technique family: the exact engines, each planner with each lookup, the hybrid on
#: two bases and with its other classifier's base, a smoothed map.
EVERY_TECHNIQUE = ["raytrace", "izb", "exact", "shadowmap", "pcf", "vsm", "psm", "lispsm",
                   "xpsm", "csm", "csm:lispsm", "lispsm/pcf", "csm/vsm", "hybrid",
                   "hybrid:shadowmap", "hybrid:csm/pcf"]


@pytest.mark.parametrize("technique", EVERY_TECHNIQUE)
def test_every_technique_gives_the_crowns_shade_tau_not_zero(crowns, technique):
    """Sun from the south at 60°: a point on the ground at z = 0 is shadowed by a box at
    heights z0..z1 over y0..y1 when its y lies in [y0 + z0/tan 60°, y1 + z1/tan 60°] (and its
    x in the box's). The ground north of each box, away from the shadows' edges: under crown
    C alone τ, under A and B τ², under B alone τ, under the building 0, under crown D alone
    (a PlantCover) τ, open ground 1."""
    from cityshade.frame.render import render_frame, shadow_mask
    from cityshade.raster.camera import map_view

    frame = render_frame(crowns, map_view(crowns, 1.0), 0.0, sun_from_angles(180.0, 60.0),
                         technique)
    world = frame.surfaces.position_m + crowns.origin_m
    on_ground = frame.surfaces.valid & (np.abs(world[..., 2]) < 1e-3)
    x, y = world[..., 0], world[..., 1]
    # (x0, x1, y0, y1): the regions, each 1 m inside its closed-form bounds.
    regions = {TAU: [(11, 15, 6, 10.3),           # C: y 5 (its north face) .. 11.35
                     (-4, 4, 12.4, 16.1),         # B alone: 11.35 .. 17.1 (A ends at 11.35)
                     (21, 29, 11.8, 14.4)],       # D alone: the building ends at 10.77
               TAU * TAU: [(-4, 4, 6, 10.3)],     # A and B
               0.0: [(21, 29, 6, 9.7)],           # the building (y 5 .. 10.77)
               1.0: [(35, 45, -40, 40)]}
    for want, boxes in regions.items():
        for x0, x1, y0, y1 in boxes:
            px = on_ground & (x > x0) & (x < x1) & (y > y0) & (y < y1)
            assert px.sum() >= 10, (technique, want, (x0, x1, y0, y1))
            np.testing.assert_array_equal(frame.lit[px], np.float32(want),
                                          err_msg=f"{technique} {(x0, x1, y0, y1)}")
    # The 8-bit mask is a grey level too: round(254 τ) (below 128: no shift).
    mask = shadow_mask(frame, crowns)
    assert set(np.unique(mask[frame.lit == np.float32(TAU)]).tolist()) == {round(254 * TAU)}


@pytest.mark.parametrize("technique", ["vsm", "csm/pcf", "hybrid"])
def test_map_techniques_take_the_leaf_state_and_the_settings(crowns, technique):
    """Leafless (a sun in January) the crowns let 0.5 through, and a crown set to 0.2 in
    leaf gives 0.2: the map techniques take the crowns' settings as the exact engines do."""
    import dataclasses

    from cityshade.frame.render import render_frame
    from cityshade.raster.camera import map_view

    cam = map_view(crowns, 1.0)
    january, june = (dataclasses.replace(sun_from_angles(200.0, 50.0), instant_utc=day)
                     for day in ("2024-01-15T12:00:00+00:00", "2024-06-21T12:00:00+00:00"))
    for sun, settings in ((january, VegetationSettings()), (june, VegetationSettings(
            solitary=VegetationSettings().solitary.__class__(leaf_on_transmissivity=0.2)))):
        scene = with_vegetation(crowns, settings)
        try:
            a = render_frame(scene, cam, 0.0, sun, "raytrace").lit
            b = render_frame(scene, cam, 0.0, sun, technique).lit
        finally:
            scene.__dict__.pop("vegetation_settings")
        inside = a == _interior(a)
        tau = 0.5 if sun is january else 0.2
        assert (b[inside & (a == np.float32(tau))] == np.float32(tau)).sum() >= 10
        np.testing.assert_array_equal(b[inside], a[inside])


def _interior(lit):
    """``lit`` where a pixel equals its four neighbours (away from the shadows' edges, where
    a map technique may differ from the rays), else NaN."""
    out = np.full(lit.shape, np.nan, np.float32)
    c = lit[1:-1, 1:-1]
    same = ((c == lit[:-2, 1:-1]) & (c == lit[2:, 1:-1]) & (c == lit[1:-1, :-2])
            & (c == lit[1:-1, 2:]))
    out[1:-1, 1:-1] = np.where(same, c, np.nan)
    return out


@pytest.fixture(scope="module")
def berlin(tmp_path_factory):
    folder = "berlin-lichtenberg-trees/"
    files = [shared_file(folder + "lod2_buildings_berlin_test_area.gml"),
             shared_file(folder + "semantic_3D_tree_model_berlin_test_area.gml")]
    out, _, _ = build_file(files, tmp_path_factory.mktemp("berlin") / "berlin.cityshade")
    return load_scene(out)


def test_berlin_trees_raytrace_and_izb_equal_on_every_pixel(berlin):
    from cityshade.frame.render import render_frame
    from cityshade.raster.camera import map_view

    assert scene_vegetation(berlin).crown_object.size == 288
    cam = map_view(berlin, 2.0)
    for az, el in ((135.0, 35.0), (250.0, 12.0), (60.0, 3.0)):
        sun = sun_from_angles(az, el)
        a = render_frame(berlin, cam, 0.0, sun, "raytrace").lit
        b = render_frame(berlin, cam, 0.0, sun, "izb").lit
        np.testing.assert_array_equal(a, b)
        assert ((a > 0) & (a < 1)).sum() > 50   # pixels lit only through crowns
    # The crowns' pass splits its cells over the threads: one thread gives the same bits.
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        np.testing.assert_array_equal(render_frame(berlin, cam, 0.0, sun, "izb").lit, a)
    finally:
        numba.set_num_threads(threads)


def _fresh_load(path, keep_stored: bool):
    scene = load_scene(path)
    if not keep_stored:
        scene.__dict__.pop("stored_vegetation_kdtrees")
    return scene


def test_stored_crown_trees_give_the_same_bits_as_trees_built_per_process(crowns, tmp_path):
    """The build stores the opaque triangles' and the crowns' kd-trees; a process that loads
    them builds neither, and every engine answers as with trees built in the process."""
    path = tmp_path / "again.cityshade"
    from cityshade.store.scenefile import save_scene

    save_scene(crowns, path, crowns.header["source"], crowns.header["build_options"])
    stored, built = _fresh_load(path, True), _fresh_load(path, False)
    assert set(stored.header["vegetation_kdtree_stats"]) == {"opaque", "crowns"}
    veg_stored, veg_built = scene_vegetation(stored), scene_vegetation(built)
    trees = stored.__dict__["stored_vegetation_kdtrees"]
    assert veg_stored.tree is trees["crowns"] and veg_stored.opaque.kdtree is trees["opaque"]
    assert without_vegetation(stored).kdtree is trees["opaque"]   # --no-vegetation builds none
    for part, built_tree in (("crowns", veg_built.tree), ("opaque", veg_built.opaque.kdtree)):
        for name, value in built_tree.to_arrays().items():
            np.testing.assert_array_equal(trees[part].to_arrays()[name], value)
    rng = np.random.default_rng(11)
    origins = rng.uniform((-30, -30, -1), (40, 30, 22), (300, 3)) - crowns.origin_m
    for az, el in ((0, 90), (135, 40), (250, 12)):
        d = sun_from_angles(az, el).direction
        want = transmission(built, origins, d, 0.0, engine="raytrace")
        assert 0 < ((want > 0) & (want < 1)).sum() and (want == 0).any()
        for engine in ("raytrace", "izb", "exact"):
            np.testing.assert_array_equal(transmission(stored, origins, d, 0.0, engine=engine),
                                          want)


def test_a_scene_file_without_stored_crown_trees_still_works(crowns, tmp_path):
    """A file written before the crowns' trees were stored (or a tile's) has none: the
    process builds them, with the same answers."""
    from cityshade.store.scenefile import save_scene

    path = tmp_path / "old.cityshade"
    save_scene(crowns, path, crowns.header["source"], crowns.header["build_options"],
               vegetation_trees=False)
    old = load_scene(path)
    assert old.header["vegetation_kdtree_stats"] is None
    assert "stored_vegetation_kdtrees" not in old.__dict__
    origins = _rays(old, [(13, 0, 0.01), (0, 0, 0.01), (0, 0, 12.0), (25, 0, -0.5),
                          (40, 0, 0.01)])
    for engine in ("raytrace", "izb", "exact"):
        np.testing.assert_array_equal(transmission(old, origins, UP, 0.0, engine=engine),
                                      [TAU, TAU * TAU, TAU, 0.0, 1.0])
    assert without_vegetation(old).n_triangles == old.n_triangles - 48
