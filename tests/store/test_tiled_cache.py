"""The tiled cache (issue 15 point 2): ``build --tile-m`` writes a folder of tile caches and an
index; a view of all tiles is the one-cache scene array for array, and renders (raytrace, izb;
perspective, overview, map; views of some tiles) and batches (plain, --tile-px, surfaces)
of the tiled cache equal those of the one cache bit for bit, ids included."""
from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from click.testing import CliRunner

from conftest import REPO, shared_file

from cityshade.cli.main import cli

SAMPLE = REPO / "sample_data" / "sample_city.gml"
SUN = dict(azimuth=235.0, elevation=28.0)
T_DAYS = 19895.5  # 2024-06-21, every sample building stands


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    from cityshade.build import build_file

    folder = tmp_path_factory.mktemp("tiled")
    one = build_file(SAMPLE, folder / "one.cityshade")[0]
    tiled = build_file(SAMPLE, folder / "tiled.cityshade", tile_m=60.0)[0]
    return one, tiled


def test_index_and_tiles(built):
    from cityshade.store.scenefile import load_scene
    from cityshade.store.tiled import open_tiled

    one, tiled = built
    scene = load_scene(one)
    tc = open_tiled(tiled)
    assert tc.tiles_mapped == []  # opening reads the index only
    index = json.loads((tiled / "index.json").read_text())
    assert len(index["tiles"]) >= 4
    assert index["counts"]["triangles"] == scene.n_triangles == 1386
    assert sum(t["triangles"] for t in index["tiles"]) == scene.n_triangles
    assert sum(t["objects"] for t in index["tiles"]) == len(scene.obj_ids)
    assert np.array_equal(index["origin_m"], scene.origin_m)
    for t in index["tiles"]:
        assert (tiled / t["file"]).stat().st_size == t["size"]
    # Every object, polygon and triangle is in exactly one tile.
    for group, n in (("obj", len(scene.obj_ids)), ("poly", len(scene.poly_ids)),
                     ("tri", scene.n_triangles)):
        ids = np.concatenate([tc.tile_globals(i)[group] for i in range(len(tc.tiles))])
        assert np.array_equal(np.sort(ids), np.arange(n)), group
    # A tile's box holds its triangles; its kd-tree is its own.
    part = tc.tile(0)
    refs = np.asarray(part.kdtree.prim_indices)
    assert np.array_equal(np.unique(refs), np.arange(part.n_triangles))
    lo, hi = np.asarray(index["tiles"][0]["box_m"])
    assert (part.vertices >= lo).all() and (part.vertices <= hi).all()


def test_view_of_all_tiles_is_the_one_cache_scene(built):
    from cityshade.geometry.scene import Scene
    from cityshade.store.scenefile import load_scene
    from cityshade.store.tiled import open_tiled

    one, tiled = built
    scene = load_scene(one)
    view = open_tiled(tiled).view()
    for name in Scene.ARRAY_FIELDS:
        assert np.array_equal(getattr(view, name), getattr(scene, name), equal_nan=True), name
    assert list(view.obj_ids) == list(scene.obj_ids)
    assert list(view.obj_types) == list(scene.obj_types)
    assert list(view.poly_ids) == list(scene.poly_ids)
    assert view.materials == scene.materials and view.textures == scene.textures


def _cameras(scene):
    from cityshade.raster import camera as cams

    close = cams.perspective(np.array([-150.0, -90.0, 29.0]), np.array([-90.0, -30.0, -6.0]),
                             vfov_deg=30.0, width_px=240, height_px=136, scene=scene)
    return {"overview": cams.overview(scene, 240, 136), "map": cams.map_view(scene, 1.0),
            "close": close}


@pytest.mark.parametrize("technique", ["raytrace", "izb"])
def test_render_equals_one_cache(built, technique):
    from cityshade.frame.render import render_frame
    from cityshade.store.scenefile import load_scene, open_scene, scene_for_camera
    from cityshade.geo.sun import sun_from_angles

    one, tiled = built
    scene = load_scene(one)
    tc = open_scene(tiled)
    sun = sun_from_angles(SUN["azimuth"], SUN["elevation"], scene.crs, scene.origin_m)
    cams_one, cams_tiled = _cameras(scene), _cameras(tc)
    partial = 0
    for name, cam in cams_one.items():
        a = render_frame(scene, cam, T_DAYS, sun, technique, ground="auto")
        view = scene_for_camera(tc, cams_tiled[name], technique)
        partial += len(view.tiling.tile_ids) < len(tc.tiles)
        b = render_frame(view, cams_tiled[name], T_DAYS, sun, technique, ground="auto")
        assert np.array_equal(a.lit, b.lit), name
        assert np.array_equal(a.rgb, b.rgb), name
        assert np.array_equal(a.gbuffer.depth, b.gbuffer.depth), name
        assert np.array_equal(a.gbuffer.prim_id, view.global_triangle_ids(b.gbuffer.prim_id))
        assert np.array_equal(a.surfaces.obj_id, view.global_object_ids(b.surfaces.obj_id))
        assert (a.lit > 0).any() and (a.lit == 0).any()  # sun and shadow in every picture
    assert partial >= 1  # the close view draws some tiles only


def test_shadow_rays_skip_tiles_they_cannot_reach(built):
    from cityshade.raster import camera as cams
    from cityshade.frame.render import render_frame
    from cityshade.store.scenefile import load_scene, open_scene, scene_for_camera
    from cityshade.geo.sun import sun_from_angles

    one, tiled = built
    scene = load_scene(one)
    tc = open_scene(tiled)
    # A small map of one corner under a high sun: its shadow rays reach only nearby tiles.
    box = np.array([[-170.0, -110.0], [-120.0, -60.0]])
    sun = sun_from_angles(180.0, 75.0, scene.crs, scene.origin_m)
    cam_t = cams.map_view(tc, 0.5, bbox=box.ravel())
    view = scene_for_camera(tc, cam_t, "raytrace")
    b = render_frame(view, cam_t, T_DAYS, sun, "raytrace")
    assert len(tc.tiles_mapped) < len(tc.tiles)
    a = render_frame(scene, cams.map_view(scene, 0.5, bbox=box.ravel()), T_DAYS, sun, "raytrace")
    assert np.array_equal(a.lit, b.lit) and (a.lit == 0).any() and (a.lit > 0).any()


def _exr(path):
    from cityshade.imageio import read_exr

    return read_exr(path)[0]


def test_cli_batch_and_info(built, tmp_path):
    one, tiled = built
    runner = CliRunner()
    common = ["--date", "2024-06-21", "--from", "08:00", "--to", "18:00", "--every", "3h",
              "--tz", "Europe/Berlin", "--pixel-size", "2", "--surfaces"]
    for extra, technique in (([], "izb"), ([], "raytrace"), (["--tile-px", "32"], "izb")):
        out = {}
        for label, path in (("one", one), ("tiled", tiled)):
            out[label] = tmp_path / f"{label}_{technique}_{len(extra)}"
            r = runner.invoke(cli, ["batch", str(path), *common, *extra, "--shadows",
                                    technique, "-o", str(out[label])])
            assert r.exit_code == 0, r.output
        a, b = _exr(out["one"] / "sun_hours.exr"), _exr(out["tiled"] / "sun_hours.exr")
        assert a.keys() == b.keys()
        for k in a:
            assert np.array_equal(a[k], b[k], equal_nan=True), k
        assert np.nanmax(a["sun_hours"]) > 0
        assert ((out["one"] / "surfaces.csv").read_bytes()
                == (out["tiled"] / "surfaces.csv").read_bytes())
    r = runner.invoke(cli, ["info", str(tiled), "--verify"])
    assert r.exit_code == 0, r.output
    assert "tiled cache" in r.output and "triangles     1,386" in r.output
    assert "all" in r.output and "match their checksums" in r.output
    d = json.loads(runner.invoke(cli, ["info", str(tiled), "--json"]).output)
    assert d["triangles"] == 1386 and d["tiled"]["tiles"] >= 4


def test_batch_in_local_mean_time_opens_a_tiled_cache_like_a_file(built, tmp_path):
    """``--tz local-mean`` takes the model's longitude from the opened scene (once), so a tiled
    folder works as a file does and gives the same sun-hours."""
    one, tiled = built
    out = {}
    for label, path in (("one", one), ("tiled", tiled)):
        out[label] = tmp_path / label
        r = CliRunner().invoke(cli, [
            "batch", str(path), "--date", "1850-06-21", "--from", "09:00", "--to", "15:00",
            "--every", "2h", "--tz", "local-mean", "--pixel-size", "4", "-o", str(out[label])])
        assert r.exit_code == 0, r.output
    a, b = _exr(out["one"] / "sun_hours.exr"), _exr(out["tiled"] / "sun_hours.exr")
    assert np.array_equal(a["sun_hours"], b["sun_hours"], equal_nan=True)
    assert np.nanmax(a["sun_hours"]) > 0


def test_bad_input_one_line(built, tmp_path):
    one, tiled = built
    runner = CliRunner()
    render = ["--camera", "map", "--sun-azimuth", "200", "--sun-elevation", "30"]
    # evaluate and compare read a tiled cache; a folder that is not one is one line.
    (tmp_path / "plain").mkdir()
    for cmd in (["evaluate", str(tmp_path / "plain"), "-o", str(tmp_path / "e")],
                ["compare", str(tmp_path / "plain"), "--before", "1850", "--after", "1990",
                 "--date", "2024-03-21", "--tz", "UTC", "-o", str(tmp_path / "c")]):
        r = runner.invoke(cli, cmd)
        assert r.exit_code != 0 and "not a tiled cache (no index.json" in r.output, cmd
        assert len(r.output.strip().splitlines()) == 1 and "Traceback" not in r.output
    assert not (tmp_path / "e").exists() and not (tmp_path / "c").exists()
    # --crs cannot change a tiled cache's CRS: refused, not ignored.
    r = runner.invoke(cli, ["evaluate", str(tiled), "--crs", "EPSG:25832", "-o",
                            str(tmp_path / "e")])
    assert r.exit_code != 0 and "is a tiled scene folder built with its CRS" in r.output
    assert len(r.output.strip().splitlines()) == 1 and not (tmp_path / "e").exists()
    damaged = tmp_path / "damaged.cityshade"
    shutil.copytree(tiled, damaged)
    (damaged / "index.json").write_text("{not json")
    r = runner.invoke(cli, ["info", str(damaged)])
    assert r.exit_code != 0 and "index.json is damaged" in r.output
    assert "Traceback" not in r.output
    # A tile file replaced by another is refused before use.
    index = json.loads((tiled / "index.json").read_text())
    (damaged / "index.json").write_text(json.dumps(index))
    first, second = index["tiles"][0]["file"], index["tiles"][1]["file"]
    shutil.copy(damaged / second, damaged / first)
    r = runner.invoke(cli, ["render", str(damaged), *render, "-o", str(tmp_path / "y.exr")])
    assert r.exit_code != 0 and "is not the one the index lists" in r.output
    r = runner.invoke(cli, ["build", str(SAMPLE), "-o", str(tmp_path), "--tile-m", "-5"])
    assert r.exit_code != 0 and "--tile-m must be a positive number" in r.output
    # A build onto a folder that is not a tiled cache leaves it alone.
    (tmp_path / "keep").mkdir()
    (tmp_path / "keep" / "mine.txt").write_text("x")
    r = runner.invoke(cli, ["build", str(SAMPLE), "-o", str(tmp_path / "keep"), "--tile-m", "60"])
    assert r.exit_code != 0 and "not a tiled cache" in r.output
    assert (tmp_path / "keep" / "mine.txt").read_text() == "x"


def test_cli_builds_a_tiled_cache_in_a_new_or_empty_folder(tmp_path):
    """The CLI creates the output folder when it checks that it can write there; the tiled
    build then took that empty folder for a foreign one and refused every new -o."""
    runner = CliRunner()
    for out in (tmp_path / "new" / "city", tmp_path / "empty"):
        if out.name == "empty":
            out.mkdir()
        r = runner.invoke(cli, ["build", str(SAMPLE), "-o", str(out), "--tile-m", "150", "-q"])
        assert r.exit_code == 0, r.output
        assert (out / "index.json").is_file()
        assert runner.invoke(cli, ["info", str(out)]).exit_code == 0
        assert not [p.name for p in out.parent.iterdir() if p.name.startswith(".")]


def test_real_file_in_tiles(tmp_path):
    """The TUM campus, read as 3 files with border duplicates, built as a tiled cache of
    100 m tiles, renders the map of the same files built as one cache bit for bit."""
    from citygml_snippets import split_citygml

    from cityshade.build import build_file
    from cityshade.raster import camera as cams
    from cityshade.frame.render import render_frame
    from cityshade.store.scenefile import load_scene, open_scene, scene_for_camera
    from cityshade.geo.sun import sun_from_angles

    tum = shared_file("munich-tum-campus-lod2/TUM Munich.gml")
    files = split_citygml(tum, tmp_path, 3, overlap=2)
    # The same files as one cache (material numbers follow the files' order, test_tiles).
    one = load_scene(build_file(files, tmp_path / "tum.cityshade")[0])
    tc = open_scene(build_file(files, tmp_path / "tum_tiled.cityshade", tile_m=100.0)[0])
    assert len(tc.tiles) >= 4
    sun = sun_from_angles(150.0, 35.0, one.crs, one.origin_m)
    for technique in ("raytrace", "izb"):
        a = render_frame(one, cams.map_view(one, 2.0), 0.0, sun, technique)
        cam = cams.map_view(tc, 2.0)
        b = render_frame(scene_for_camera(tc, cam, technique), cam, 0.0, sun, technique)
        assert np.array_equal(a.lit, b.lit)
        assert np.array_equal(a.rgb, b.rgb, equal_nan=True)  # NaN: no surface
        assert np.array_equal(a.gbuffer.prim_id, b.gbuffer.prim_id)
        assert (a.lit == 0).any() and (a.lit > 0).any()


def _same_tiled(a, b) -> None:
    """Two tiled caches hold the same index (but the build's timings and source) and the same
    tiles, every cache array equal."""
    from cityshade.store.cache import open_cache

    ia, ib = (json.loads((p / "index.json").read_text()) for p in (a, b))
    for index in (ia, ib):
        index["report"].pop("timings")
        for k in ("source", "build_options"):
            index.pop(k)
        for t in index["tiles"]:
            for k in ("size", "header_blake2b"):
                t.pop(k)
            t["kdtree"].pop("build_s")
    assert ia == ib
    for t in ia["tiles"]:
        ca, cb = open_cache(a / t["file"]), open_cache(b / t["file"])
        names = sorted(cb.header["arrays"])
        assert names == sorted(ca.header["arrays"]) and "global/vert" in names
        for n in names:
            assert np.array_equal(ca.array(n), cb.array(n), equal_nan=True), (t["file"], n)


def test_tiles_from_many_files_spilled_equal_the_assembled_city(tmp_path):
    """A tiled build of several files spills each file's objects to their tiles and never
    assembles the city; it equals the tiled cache cut from the assembled city, also where an
    object changes tile after it was spilled: a building part in a later file (the building
    met again there) widens its building's box into another tile, and an object without
    geometry waits for the lowest tile."""
    from citygml_snippets import box_polygons, building, city

    from cityshade.build import build_file, build_scene_from_files
    from cityshade.config import Settings
    from cityshade.build.tiled import save_tiled

    x, y = 690000.0, 5336000.0
    part = building("bp", box_polygons(x + 70, y, 0, 3, 3, 3, "q"), solid_refs=False
                    ).replace("bldg:Building", "bldg:BuildingPart")
    b = box_polygons(x, y, 0, 5, 5, 5, "p")
    (tmp_path / "t1.gml").write_text(city(building("b", b), building(
        "c", box_polygons(x + 40, y + 30, 0, 4, 4, 9, "c")), '<bldg:Building gml:id="empty"/>'))
    (tmp_path / "t2.gml").write_text(city(
        building("b", b, extra=f"<bldg:consistsOfBuildingPart>{part}</bldg:consistsOfBuildingPart>"),
        building("d", box_polygons(x + 10, y + 45, 0, 4, 4, 9, "d"))))
    files = [tmp_path / "t1.gml", tmp_path / "t2.gml"]
    spilled = build_file(files, tmp_path / "spilled.cityshade", tile_m=20.0)[0]
    cut = tmp_path / "cut.cityshade"
    save_tiled(build_scene_from_files(files, Settings(), tree=False), cut, 20.0, Settings(), {}, {})
    _same_tiled(spilled, cut)
    index = json.loads((spilled / "index.json").read_text())
    by_key = {tuple(t["key"]): t["objects"] for t in index["tiles"]}
    # b (0..5 m) with its part (70..73 m) is centred at 36.5 m: tile 34501, not 34500.
    assert by_key == {(34501, 266800): 3, (34502, 266801): 1, (34500, 266802): 1}
    assert not list(tmp_path.glob(".*.tmp"))  # the spill went with the temporary folder

    # The sample city in 3 files with border duplicates, in 60 m tiles.
    from citygml_snippets import split_citygml

    shutil.copy(REPO / "sample_data" / "sample_city_facade.png", tmp_path)
    files = split_citygml(SAMPLE, tmp_path, 3, overlap=2)
    spilled = build_file(files, tmp_path / "s_spilled.cityshade", tile_m=60.0)[0]
    cut = tmp_path / "s_cut.cityshade"
    save_tiled(build_scene_from_files(files, Settings(), tree=False), cut, 60.0, Settings(), {}, {})
    _same_tiled(spilled, cut)


def test_tree_over_tiles_finds_what_the_linear_test_finds():
    """The tree over the tile boxes gives the tiles the test of every box in turn gives: for
    the sun-ward overlap test and the camera frustum's plane test, on random grids of
    tiles (with empty and overlapping boxes) and on the sample city's tiles."""
    from reference import reference_tiles_passing

    from cityshade.raster import culling as cull
    from cityshade.store.tiled import TileTree

    rng = np.random.default_rng(5)
    for n in (0, 1, 3, 5, 40, 200):
        lo = rng.uniform(0, 1000, (n, 3))
        boxes = np.stack([lo, lo + rng.uniform(0, 300, (n, 3))], axis=1)
        boxes[: n // 7, 1] = boxes[: n // 7, 0]  # flat boxes
        tree = TileTree(boxes)
        assert tree.n_nodes <= max(1, 2 * n)
        found = 0
        for _ in range(15):
            a, b = np.sort(rng.uniform(-100, 1100, (2, 3)), axis=0)

            def overlap(lo, hi, a=a, b=b):
                return bool((lo <= b).all() and (hi >= a).all())

            planes = np.concatenate([rng.normal(size=(6, 3)), rng.uniform(-500, 900, (6, 1))],
                                    axis=1)

            def inside(lo, hi, planes=planes):
                return not cull.box_outside(planes, lo, hi, 63)[0]

            for test in (overlap, inside):
                want = reference_tiles_passing(boxes, test)
                assert tree.query(test) == want
                found += len(want)
        assert n == 0 or found > 0


def test_views_use_the_tree(built):
    """The sample city's 17 tiles: the frustum culling of each camera and the sun-ward sweep
    of some receivers, through the tree, against every tile box tested in turn."""
    from reference import reference_tiles_passing

    from cityshade.raster import culling as cull
    from cityshade.store.tiled import open_tiled

    tc = open_tiled(built[1])
    assert tc.tree.n_nodes > 1
    box = np.asarray(tc.index["box_m"])
    pad = cull.FRUSTUM_PAD_REL * max(float(np.max(box[1] - box[0])), 1.0)
    counts = []
    for cam in _cameras(tc).values():
        planes = cull.frustum_planes(cam, pad)
        mask = (1 << planes.shape[0]) - 1
        want = reference_tiles_passing(
            tc.boxes, lambda lo, hi: not cull.box_outside(planes, lo, hi, mask)[0])
        assert tc.tiles_in_view(cam) == want
        counts.append(len(want))
    assert min(counts) < len(tc.tiles) == max(counts)  # the close view draws some tiles
    origins = np.array([[-60.0, -40.0, 0.5], [-50.0, -30.0, 2.0]])
    sun = np.array([0.5, 0.3, 0.81])
    reach = tc.tiles_reaching(origins, sun)
    assert 0 < len(reach) < len(tc.tiles)


def test_map_techniques_evaluate_and_compare_on_a_tiled_cache(built, tmp_path):
    """The map techniques draw their casters from the view of all tiles (a caster outside
    the frustum still shades what is in it), and evaluate and compare read a tiled cache as
    that view: the same pictures, errors and sun-hours as the one cache."""
    import csv

    from cityshade.frame.render import render_frame
    from cityshade.store.scenefile import load_scene, open_scene, scene_for_camera
    from cityshade.geo.sun import sun_from_angles

    one, tiled = built
    scene, tc = load_scene(one), open_scene(tiled)
    sun = sun_from_angles(SUN["azimuth"], SUN["elevation"], scene.crs, scene.origin_m)
    cams_one, cams_tiled = _cameras(scene), _cameras(tc)
    for technique in ("pcf", "csm", "hybrid:shadowmap"):
        for name in ("map", "close"):
            a = render_frame(scene, cams_one[name], T_DAYS, sun, technique)
            view = scene_for_camera(tc, cams_tiled[name], technique)
            assert len(view.tiling.tile_ids) == len(tc.tiles)
            b = render_frame(view, cams_tiled[name], T_DAYS, sun, technique)
            assert np.array_equal(a.lit, b.lit), (technique, name)
            assert np.array_equal(a.rgb, b.rgb), (technique, name)
            assert (a.lit > 0).any() and (a.lit == 0).any()
    runner = CliRunner()
    rows = {}
    for label, path in (("one", one), ("tiled", tiled)):
        out = tmp_path / f"e_{label}"
        r = runner.invoke(cli, ["evaluate", str(path), "--views", "map", "--size", "96x64",
                                "--pixel-size", "2", "--sun", "135,30", "--date", "2024",
                                "--shadows", "shadowmap,izb", "--sizes", "256", "--repeat", "1",
                                "-o", str(out)])
        assert r.exit_code == 0, r.output
        rows[label] = [{k: v for k, v in row.items()
                        if k not in ("model", "stages") and not k.endswith(("_s", "_ms"))}
                       for row in csv.DictReader(open(out / "results.csv"))]
    assert rows["one"] == rows["tiled"] and len(rows["one"]) == 3
    out = {}
    for label, path in (("one", one), ("tiled", tiled)):
        out[label] = tmp_path / f"c_{label}"
        r = runner.invoke(cli, ["compare", str(path), "--before", "1850", "--after", "1990",
                                "--date", "2024-03-21", "--from", "10:00", "--to", "14:00",
                                "--every", "2h", "--tz", "UTC", "--pixel-size", "4",
                                "-o", str(out[label])])
        assert r.exit_code == 0, r.output
    exrs = sorted(p.name for p in out["one"].glob("*.exr"))
    assert exrs and exrs == sorted(p.name for p in out["tiled"].glob("*.exr"))
    for name in exrs:
        a, b = _exr(out["one"] / name), _exr(out["tiled"] / name)
        assert a.keys() == b.keys()
        for k in a:
            assert np.array_equal(a[k], b[k], equal_nan=True), (name, k)
    assert (out["one"] / "surfaces.csv").read_bytes() == (out["tiled"] / "surfaces.csv").read_bytes()
