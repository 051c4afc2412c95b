"""Trees in the sky: a sky direction through vegetation crowns counts with the product of their
transmissivities (docs/DESIGN.md §18, §21), against a closed form built here: a thin horizontal
disc crown of angular radius θ above a ground point hides a cone of half-angle θ around the
zenith, whose share of the cosine-weighted sky is sin²θ, so SVF = 1 − (1 − τ) sin²θ."""
from __future__ import annotations

import math

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, tree

from cityshade.light import named_sky, sky_view_factor, sky_visibility

#: 4.5 rows of Reinhart MF 2 (rows of 90° / 14.5 from the horizon, a zenith cap of half a row):
#: a border between rows, so the crown hides whole patches and no patch is cut.
THETA_DEG = 4.5 * 90.0 / 14.5
H_M = 10.0          # height of the crown's underside above the receiver
SIDES = 64


def _disc(x, y, z, radius_m, thick_m, prefix):
    """A closed flat prism of SIDES sides around (x, y) from z to z + thick_m, outward faces."""
    ang = np.linspace(0.0, 2 * math.pi, SIDES, endpoint=False)
    ring = [(x + radius_m * math.cos(a), y + radius_m * math.sin(a)) for a in ang]
    top = [(px, py, z + thick_m) for px, py in ring]
    bottom = [(px, py, z) for px, py in reversed(ring)]
    faces = [("RoofSurface", f"{prefix}t", top), ("GroundSurface", f"{prefix}b", bottom)]
    for i in range(SIDES):
        (ax, ay), (bx, by) = ring[i], ring[(i + 1) % SIDES]
        faces.append(("WallSurface", f"{prefix}s{i}", [(ax, ay, z), (bx, by, z),
                                                       (bx, by, z + thick_m), (ax, ay, z + thick_m)]))
    return faces


@pytest.fixture(scope="module")
def disc_scene(tmp_path_factory):
    """One disc crown of angular radius THETA_DEG seen from (0, 0, 0); a 4 m block far east
    (an opaque caster, so the crowns are not the whole scene)."""
    from cityshade.build import build_scene_from_file

    tmp = tmp_path_factory.mktemp("disc")
    radius = H_M * math.tan(math.radians(THETA_DEG))
    path = tmp / "disc.gml"
    path.write_text(city(tree("T", _disc(0.0, 0.0, H_M, radius, 0.2, "t")),
                         building("B", box_polygons(200.0, 0.0, 0.0, 5.0, 5.0, 4.0, "b"))))
    return build_scene_from_file(path)


@pytest.mark.parametrize("engine", ["izb", "raytrace"])
def test_a_disc_crown_lets_its_transmissivity_of_the_cone_through(disc_scene, engine):
    point = -np.asarray(disc_scene.origin_m, np.float64)[None]
    vis = sky_visibility(disc_scene, point, [[0.0, 0.0, 1.0]], named_sky("reinhart577"),
                         engine=engine)
    cone = math.sin(math.radians(THETA_DEG)) ** 2
    assert vis.visible().all()                             # nothing opaque in the way
    # In leaf 3 % (UMEP/SOLWEIG), leafless 50 % (docs/DESIGN.md §21): closed forms.
    assert sky_view_factor(vis)[0] == pytest.approx(1.0 - (1.0 - 0.03) * cone, abs=1e-9)
    assert sky_view_factor(vis, leaf=False)[0] == pytest.approx(1.0 - 0.5 * cone, abs=1e-9)


def test_both_engines_give_the_same_crown_rays(disc_scene):
    pts = -np.asarray(disc_scene.origin_m)[None] + np.array([[0.0, 0.0, 0.0], [3.0, 1.0, 0.0],
                                                              [197.0, 2.0, 2.0], [8.0, 0.0, 0.0]])
    nrm = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.6, 0.0, 0.8]])
    sky = named_sky("reinhart577")
    a = sky_visibility(disc_scene, pts, nrm, sky, engine="izb")
    b = sky_visibility(disc_scene, pts, nrm, sky, engine="raytrace")
    np.testing.assert_array_equal(a.bits, b.bits)
    for field in ("rows", "cols", "leaf_on", "leaf_off"):
        np.testing.assert_array_equal(getattr(a.crowns, field), getattr(b.crowns, field))
    assert len(a.crowns.rows) > 0


def test_a_scene_without_vegetation_builds_no_crowns(tmp_path):
    from cityshade.build import build_scene_from_file

    path = tmp_path / "b.gml"
    path.write_text(city(building("B", box_polygons(0.0, 0.0, 0.0, 5.0, 5.0, 4.0, "b"))))
    scene = build_scene_from_file(path)
    vis = sky_visibility(scene, -np.asarray(scene.origin_m)[None] + [[10.0, 0.0, 0.0]],
                         [[0.0, 0.0, 1.0]], named_sky("tregenza"))
    assert vis.crowns is None


def test_berlin_trees_and_buildings_same_sky_in_both_engines():
    """The Berlin-Lichtenberg buildings with their 288 LiDAR trees (shared data): ``izb`` and
    ``raytrace`` give the same bits and the same crown rays and transmissions on 4 m map
    pixels under the trees."""
    from conftest import shared_file

    from cityshade.build import build_scene_from_files
    from cityshade.frame.pipeline import camera_pass
    from cityshade.light import map_receivers, sky_for_scene
    from cityshade.raster.camera import map_view

    folder = "berlin-lichtenberg-trees/"
    scene = build_scene_from_files([shared_file(folder + "lod2_buildings_berlin_test_area.gml"),
                                    shared_file(folder + "semantic_3D_tree_model_berlin_test_area.gml")])
    points, normals, _ = map_receivers(camera_pass(scene, map_view(scene, 4.0), 0.0))
    rows = np.random.default_rng(2).choice(len(points), min(len(points), 400), replace=False)
    sky = sky_for_scene(scene, "tregenza")
    a = sky_visibility(scene, points[rows], normals[rows], sky, engine="izb")
    b = sky_visibility(scene, points[rows], normals[rows], sky, engine="raytrace")
    np.testing.assert_array_equal(a.bits, b.bits)
    for field in ("rows", "cols", "leaf_on", "leaf_off"):
        np.testing.assert_array_equal(getattr(a.crowns, field), getattr(b.crowns, field))
    assert len(np.unique(a.crowns.rows)) > 20          # many receivers see sky through crowns
    svf_on, svf_off = sky_view_factor(a), sky_view_factor(a, leaf=False)
    assert (svf_on <= svf_off + 1e-12).all() and (svf_on < svf_off - 1e-3).sum() > 20


def test_the_sky_command_takes_the_season_and_no_vegetation(tmp_path):
    """A 0.2 × 0.2 m floor patch under the disc crown: ``surfaces.csv``'s SVF is the closed
    form in leaf (the default), leafless with ``--season leaf-off``, 1 with
    ``--no-vegetation``."""
    import csv

    from click.testing import CliRunner

    from citygml_snippets import ground
    from cityshade.cli.main import cli

    x0, y0 = 690_000.0, 5_336_000.0
    radius = H_M * math.tan(math.radians(THETA_DEG))
    gml = tmp_path / "disc.gml"
    gml.write_text(city(tree("T", _disc(x0, y0, H_M, radius, 0.2, "t")),
                        ground(x0 - 0.1, y0 - 0.1, x0 + 0.1, y0 + 0.1, gid="floor")))
    scene = tmp_path / "disc.cityshade"
    assert CliRunner().invoke(cli, ["build", str(gml), "-o", str(scene)]).exit_code == 0
    cone = math.sin(math.radians(THETA_DEG)) ** 2
    for extra, expected in (([], 1.0 - 0.97 * cone), (["--season", "leaf-off"], 1.0 - 0.5 * cone),
                            (["--no-vegetation"], 1.0)):
        out = tmp_path / f"out{len(extra)}{extra[:1]}"
        result = CliRunner().invoke(cli, ["sky", str(scene), "--no-map", "--surfaces",
                                          "--samples-per-m2", "2", "--sky", "reinhart577",
                                          "--shadows", "raytrace", "--no-gis", "-o", str(out), *extra])
        assert result.exit_code == 0, result.output
        with open(out / "surfaces.csv", newline="") as fh:
            floor = [r for r in csv.DictReader(fh) if r["object_id"] == "floor"]
        assert float(floor[0]["svf"]) == pytest.approx(expected, abs=1e-4)  # 4 decimals written


def test_windows_leave_deciduous_trees_out_as_bre_209_does(disc_scene):
    """``[vegetation] window_trees``: "evergreen" (default) drops deciduous crowns from the
    openings' VSC and sunlight, keeps evergreen ones; "all" keeps every crown; "none" none."""
    import dataclasses

    from cityshade.config import ConfigError, VegetationSettings
    from cityshade.geometry.vegetation import (scene_vegetation, window_light_scene,
                                               with_vegetation)

    def crowns(settings):
        scene = window_light_scene(with_vegetation(disc_scene, settings))
        veg = scene_vegetation(scene)
        return 0 if veg is None else len(veg.crown_object)

    base = VegetationSettings()
    evergreen = dataclasses.replace(base, solitary=dataclasses.replace(base.solitary,
                                                                       evergreen=True))
    assert crowns(base) == 0
    assert crowns(evergreen) == 1
    assert crowns(dataclasses.replace(base, window_trees="all")) == 1
    assert crowns(dataclasses.replace(evergreen, window_trees="none")) == 0
    with_vegetation(disc_scene, base)                   # the fixture's settings back
    with pytest.raises(ConfigError, match="window_trees must be one of evergreen, all, none"):
        VegetationSettings(window_trees="some")


def test_probable_sunlight_under_a_crown_counts_its_transmission_by_season(tmp_path):
    """A ground point under a 5 km wide disc crown 10 m up (every sun above 0.12° crosses
    it), pvlib's Greensboro TMY3: each sunny hour counts 3 % in leaf (UTC days 97 to 300 of
    the hour's middle) and 50 % leafless, counted here from the file's DNI column."""
    import os

    import pvlib

    from cityshade.build import build_scene_from_file
    from cityshade.light import probable_sunlight, read_weather, weather_suns

    x0, y0 = 608_000.0, 3_996_000.0
    gml = tmp_path / "canopy.gml"
    gml.write_text(city(
        tree("T", _disc(x0, y0, H_M, 5000.0, 0.5, "t")),
        building("B", box_polygons(x0 + 6000.0, y0, 0.0, 5.0, 5.0, 4.0, "b"),
                 srs="EPSG:32617")))
    scene = build_scene_from_file(gml)
    weather = read_weather(os.path.join(os.path.dirname(pvlib.__file__), "data",
                                        "723170TYA.CSV"))
    directions, elevation = weather_suns(weather, scene)
    sunny = (weather.dni_w_m2 >= 120.0) & (elevation > 0.0)
    assert elevation[sunny].min() > 0.2   # above atan(10 m / 5 km): every sun meets the crown
    days = np.asarray(weather.sun_times.tz_convert("UTC").dayofyear)
    tau = np.where((days >= 97) & (days <= 300), 0.03, 0.5)
    point = np.array([[x0, y0, 0.0]]) - scene.origin_m
    ps = probable_sunlight(scene, point, [[0.0, 0.0, 1.0]], weather, engine="raytrace")
    assert ps.total_h == sunny.sum()
    assert ps.annual_h[0] == pytest.approx(tau[sunny].sum(), rel=1e-12)
    assert 0.0 < ps.annual_h[0] < 0.5 * sunny.sum()


def test_an_evergreen_crown_keeps_its_leaves_in_the_sky(disc_scene):
    """Evergreen solitary trees: the in-leaf 3 % in both seasons (one crowns' pass)."""
    import dataclasses

    from cityshade.config import VegetationSettings
    from cityshade.geometry.vegetation import with_vegetation

    base = VegetationSettings()
    evergreen = dataclasses.replace(base, solitary=dataclasses.replace(base.solitary,
                                                                       evergreen=True))
    point = -np.asarray(disc_scene.origin_m, np.float64)[None]
    try:
        vis = sky_visibility(with_vegetation(disc_scene, evergreen), point, [[0.0, 0.0, 1.0]],
                             named_sky("reinhart577"), engine="raytrace")
    finally:
        with_vegetation(disc_scene, base)
    cone = math.sin(math.radians(THETA_DEG)) ** 2
    np.testing.assert_array_equal(vis.crowns.leaf_on, vis.crowns.leaf_off)
    assert sky_view_factor(vis, leaf=False)[0] == pytest.approx(1.0 - 0.97 * cone, abs=1e-9)
