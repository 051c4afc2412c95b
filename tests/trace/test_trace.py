"""Tests of the ray-tracing core (cityshade.trace) against brute force and analytic scenes."""
from __future__ import annotations


import numba
import numpy as np
import pytest

from cityshade.accel import build_kdtree
from cityshade.errors import TraceInputError
from cityshade.trace import intersect, occluded, shadow_rays_from_surface, tile_order
from conftest import run_with_and_without_jit, shared_file
from reference import reference_closest_hit, reference_ray_hits
from synthetic import (BOX_FACES, box_city, closed_box_tree, edge_and_vertex_targets,
                       unit)


@pytest.fixture(scope="module")
def city():
    return box_city(150, seed=7, extent_m=250.0)


@pytest.fixture(scope="module")
def tree(city):
    return build_kdtree(*city)


def random_rays(n, seed, lo=(-20, -20, -5), hi=(290, 290, 60)):
    rng = np.random.default_rng(seed)
    origins = rng.uniform(lo, hi, (n, 3))
    directions = unit(rng.normal(size=(n, 3)))
    return origins, directions


@pytest.mark.parametrize("which", ["before", "between", "after"])
def test_random_rays_agree_with_brute_force(city, tree, which):
    v, t, begin, end, mat = city
    dates = np.unique(np.concatenate([begin[np.isfinite(begin)], end[np.isfinite(end)]]))
    t_days = {"before": dates[0] - 100.0, "between": float(np.median(dates)),
              "after": dates[-1] + 100.0}[which]
    origins, directions = random_rays(600, seed={"before": 1, "between": 2, "after": 3}[which])
    tmax = np.where(np.arange(600) % 3 == 0, 40.0, np.inf)    # some finite segments too
    dist, tri, u, w = intersect(tree, origins, directions, t_days, tmax)
    occ = occluded(tree, origins, directions, t_days, tmax)
    n_hits = 0
    for i in range(600):
        t_ref, tri_ref = reference_closest_hit(v, t, begin, end, origins[i], directions[i],
                                               t_days, tmax[i])
        assert occ[i] == (tri_ref >= 0), f"ray {i}: any-hit disagrees with brute force"
        assert (tri[i] >= 0) == (tri_ref >= 0), f"ray {i}: closest hit/miss disagrees"
        if tri_ref >= 0:
            n_hits += 1
            assert dist[i] == pytest.approx(t_ref, rel=1e-9, abs=1e-9), f"ray {i}"
            if tri[i] != tri_ref:   # a tie: both triangles must be hit at that distance
                t_all, ids = reference_ray_hits(v, t, begin, end, origins[i], directions[i],
                                                t_days, tmax[i])
                assert tri[i] in ids and t_all[ids == tri[i]][0] == pytest.approx(t_ref)
            # Barycentrics reproduce the hit point.
            p = origins[i] + dist[i] * directions[i]
            a, b, c = v[t[tri[i]]].astype(np.float64)
            q = (1 - u[i] - w[i]) * a + u[i] * b + w[i] * c
            np.testing.assert_allclose(q, p, atol=1e-3)
        else:
            assert dist[i] == np.inf and tri[i] == -1
    assert n_hits > 60, "the test scene should be hit by a fair share of rays"


def test_results_do_not_depend_on_thread_count_or_brick_size(tree):
    origins, directions = random_rays(3000, seed=11)
    ref = intersect(tree, origins, directions, 0.0)
    occ_ref = occluded(tree, origins, directions, 0.0)
    default = numba.get_num_threads()
    try:
        for threads in {1, default}:
            numba.set_num_threads(threads)
            for brick in (1, 7, 256, 5000):
                got = intersect(tree, origins, directions, 0.0, brick_size=brick)
                for a, b in zip(got, ref):
                    np.testing.assert_array_equal(a, b)
                np.testing.assert_array_equal(
                    occluded(tree, origins, directions, 0.0, brick_size=brick), occ_ref)
    finally:
        numba.set_num_threads(default)


@pytest.mark.parametrize("rotation_seed", [None, 1, 2, 3])
def test_watertight_closed_box(rotation_seed):
    """Rays from inside a closed box aimed at every vertex and edge always hit it; rays from
    outside aimed at them through the box hit it too."""
    verts, tree = closed_box_tree(rotation_seed=rotation_seed)
    targets = edge_and_vertex_targets(verts, BOX_FACES)
    centre = verts.astype(np.float64).mean(axis=0)
    rng = np.random.default_rng(0)
    for inside in [centre] + list(centre + rng.uniform(-0.4, 0.4, (5, 3))):
        dirs = unit(targets - inside)
        origins = np.broadcast_to(inside, dirs.shape)
        dist, tri, _, _ = intersect(tree, origins, dirs)
        assert (tri >= 0).all(), f"{(tri < 0).sum()} rays slipped through the closed box"
        assert occluded(tree, origins, dirs).all()
        # From outside, through the target, towards the box centre: must hit.
        outside = targets + unit(targets - centre) * 7.0
        d2 = unit(inside - outside)
        assert occluded(tree, outside, d2).all()


def fzk_haus_mesh():
    """FZK-Haus LoD2 (CityGML 3.0) rings parsed with lxml and triangulated with earcut."""
    import mapbox_earcut
    from lxml import etree

    path = shared_file("fzk-haus/citygml3.0/FZK-Haus-LoD2-KIT-IAI-KHH-B36-V1__v3.gml")
    gml = "http://www.opengis.net/gml/3.2"
    root = etree.parse(str(path)).getroot()
    verts, tris = [], []
    for ring in root.iter(f"{{{gml}}}LinearRing"):
        pts = np.array([[float(x) for x in p.text.split()] for p in ring.iter(f"{{{gml}}}pos")])
        if len(pts) > 1 and np.allclose(pts[0], pts[-1]):
            pts = pts[:-1]
        # Project on the plane of the ring (Newell normal), then ear-clip in 2-D.
        normal = np.sum(np.cross(pts, np.roll(pts, -1, axis=0)), axis=0)
        drop = int(np.argmax(np.abs(normal)))
        keep = [a for a in range(3) if a != drop]
        flat = pts[:, keep]
        idx = mapbox_earcut.triangulate_float64(flat, np.array([len(pts)], np.uint32))
        tri = idx.reshape(-1, 3)
        # Restore the ring's winding (earcut output orientation is not guaranteed).
        for a, b, c in tri:
            n_tri = np.cross(pts[b] - pts[a], pts[c] - pts[a])
            tris.append((a, b, c) if n_tri @ normal > 0 else (a, c, b))
        tris[-len(tri):] = [tuple(np.array(x) + sum(len(p) for p in verts)) for x in tris[-len(tri):]]
        verts.append(pts)
    verts = np.vstack(verts)
    origin = np.round(verts.mean(axis=0))   # the 10^6-10^7 m offset removed, as the scene does
    return (verts - origin).astype(np.float32), np.array(tris, np.int32)


def test_watertight_fzk_haus():
    verts, tris = fzk_haus_mesh()
    # Merge coincident ring vertices so shared edges share vertex values exactly.
    uniq, inverse = np.unique(verts, axis=0, return_inverse=True)
    verts, tris = uniq, inverse.reshape(-1)[tris].astype(np.int32)
    n = tris.shape[0]
    tree = build_kdtree(verts, tris, np.full(n, -np.inf), np.full(n, np.inf),
                        np.zeros(n, np.int32))
    targets = edge_and_vertex_targets(verts, tris)
    centre = verts.astype(np.float64).mean(axis=0)
    dirs = unit(targets - centre)
    origins = np.broadcast_to(centre, dirs.shape)
    dist, tri, _, _ = intersect(tree, origins, dirs)
    assert (tri >= 0).all(), f"{(tri < 0).sum()} of {len(tri)} rays slipped through FZK-Haus"
    assert occluded(tree, origins, dirs).all()


def test_zero_area_triangles_never_hit_and_never_nan():
    verts = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [5, 5, 5]], np.float32)
    tris = np.array([[0, 1, 2], [4, 4, 4], [0, 0, 1], [0, 1, 3]], np.int32)   # 3 degenerate
    n = 4
    tree = build_kdtree(verts, tris, np.full(n, -np.inf), np.full(n, np.inf),
                        np.zeros(n, np.int32))
    origins = np.array([[0.5, 0.0, 1.0], [5, 5, 6], [0.25, 0.25, 1.0], [1.5, 0, 1]])
    dirs = np.array([[0, 0, -1.0]] * 4)
    dist, tri, u, v = intersect(tree, origins, dirs)
    np.testing.assert_array_equal(tri, [3, -1, 3, -1])
    np.testing.assert_array_equal(dist, [1.0, np.inf, 1.0, np.inf])
    assert np.isfinite(u).all() and np.isfinite(v).all()
    # A ray in the plane z = 0 of every triangle here (and along the degenerate line) hits none.
    d = unit([[1, 0, 0]])
    assert not occluded(tree, [[-1.0, 0.0, 0.0]], d)[0]
    assert intersect(tree, [[-1.0, 0.0, 0.0]], d)[1][0] == -1


def test_axis_parallel_rays_in_a_face_plane_and_along_an_edge():
    """Rays with zero direction components: in the plane of a face they hit the wall across
    at its edge; along an edge they hit the corner; no NaN anywhere."""
    verts, tree = closed_box_tree(lo=(1.0, 2.0, 3.0), size=(4.0, 5.0, 6.0))
    origins = np.array([
        [-3.0, 4.0, 9.0],      # in the plane of the top face (z = 9), towards +x
        [-3.0, 2.0, 9.0],      # along the top edge y = 2, z = 9
        [-3.0, 4.0, 5.0],      # parallel to the top face, through the box
        [3.0, 4.0, 20.0],      # straight down onto the top face
        [-3.0, 1.0, 9.0],      # parallel, just outside the box: miss
    ])
    dirs = np.array([[1, 0, 0], [1, 0, 0], [1, 0, 0], [0, 0, -1], [1, 0, 0]], np.float64)
    dist, tri, u, v = intersect(tree, origins, dirs)
    np.testing.assert_array_equal(dist, [4.0, 4.0, 4.0, 11.0, np.inf])
    assert (tri[:4] >= 0).all() and tri[4] == -1
    np.testing.assert_array_equal(occluded(tree, origins, dirs), [True] * 4 + [False])
    assert np.isfinite(u).all() and np.isfinite(v).all()


@pytest.mark.parametrize("offset_m", [0.0, 1.0e7])
def test_box_shadow_length_and_grazing_rays(offset_m):
    """A box of height h on a ground plane casts a shadow of length h / tan(elevation) (also
    with a 10^7 m coordinate offset removed before float32); 0.1° grazing rays hit the ground
    at height / sin(0.1°)."""
    h = 10.0
    box = np.array([(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0),
                    (0, 0, h), (4, 0, h), (4, 4, h), (0, 4, h)], np.float64)
    ground = np.array([(-500, -500, 0), (500, -500, 0), (500, 500, 0), (-500, 500, 0)],
                      np.float64)
    world = np.vstack([box, ground]) + offset_m                 # georeferenced, float64
    origin = np.round(world.mean(axis=0))                      # the scene's origin shift
    verts = (world - origin).astype(np.float32)
    tris = np.vstack([BOX_FACES, [[8, 9, 10], [8, 10, 11]]]).astype(np.int32)
    n = tris.shape[0]
    tree = build_kdtree(verts, tris, np.full(n, -np.inf), np.full(n, np.inf),
                        np.zeros(n, np.int32))
    elevation = np.radians(30.0)
    sun = np.array([0.0, -np.cos(elevation), np.sin(elevation)])   # sun in the south
    length = h / np.tan(elevation)
    # Ground points north of the box along x = 2: shadowed up to 4 + length.
    ys = np.array([4.5, 10.0, 4 + length - 0.05, 4 + length + 0.05, 40.0])
    pts = np.column_stack([np.full(5, 2.0), ys, np.zeros(5)]) + offset_m - origin
    pts = pts.astype(np.float32).astype(np.float64)
    normals = np.tile([0.0, 0.0, 1.0], (5, 1))
    o = shadow_rays_from_surface(pts, normals, sun)
    np.testing.assert_array_equal(occluded(tree, o, np.tile(sun, (5, 1))),
                                  [True, True, True, False, False])
    grazing = np.radians(0.1)
    d = np.array([[np.cos(grazing), 0.0, -np.sin(grazing)]])
    start = np.array([[-400.0, 100.0, 0.5]]) + (offset_m - origin)   # 0.5 m above ground
    dist, tri, _, _ = intersect(tree, start, d)
    assert tri[0] in (12, 13)
    assert dist[0] == pytest.approx(0.5 / np.sin(grazing), rel=1e-5)


def test_shadow_rays_never_rehit_their_own_surface(city, tree):
    """Seeded property: rays leaving a float32 point of a lit triangle never hit it again."""
    v, t, begin, end, mat = city
    rng = np.random.default_rng(5)
    sun = unit([0.4, -0.5, 0.6])
    tv = v[t].astype(np.float64)
    normals = unit(np.cross(tv[:, 1] - tv[:, 0], tv[:, 2] - tv[:, 0]))
    lit = np.flatnonzero(normals @ sun > 0.05)
    pick = rng.choice(lit, 2000)
    bary = rng.dirichlet([1, 1, 1], 2000)
    pts = np.einsum("ij,ijk->ik", bary, tv[pick]).astype(np.float32).astype(np.float64)
    o = shadow_rays_from_surface(pts, normals[pick], sun)
    dist, tri, _, _ = intersect(tree, o, np.tile(sun, (2000, 1)), t_days=-1e9)
    assert not (tri == pick).any(), f"{(tri == pick).sum()} rays re-hit their own triangle"


def test_read_only_memory_mapped_tree(tmp_path, city, tree):
    from cityshade.accel import KdTree
    for name, arr in tree.to_arrays().items():
        np.save(tmp_path / f"{name}.npy", arr)
    mapped = KdTree.from_arrays({name: np.load(tmp_path / f"{name}.npy", mmap_mode="r")
                                 for name in tree.to_arrays()})
    origins, directions = random_rays(500, seed=2)
    origins.setflags(write=False)
    for a, b in zip(intersect(mapped, origins, directions, 3000.0),
                    intersect(tree, origins, directions, 3000.0)):
        np.testing.assert_array_equal(a, b)


def test_a_scene_traces_through_its_own_tree(tree, sample_city_scene):
    """The engines take one KdTree; a scene hands its own to them
    (:mod:`cityshade.shadows.visibility`), with the engine's answer."""
    import dataclasses

    from cityshade.shadows import visibility

    scene = dataclasses.replace(sample_city_scene, kdtree=tree)
    origins, directions = random_rays(10, seed=3)
    np.testing.assert_array_equal(visibility.occluded(scene, origins, directions),
                                  occluded(tree, origins, directions))
    with pytest.raises(TraceInputError, match="KdTree"):
        occluded(scene, origins, directions)


def test_input_validation(tree):
    o, d = random_rays(4, seed=1)
    with pytest.raises(TraceInputError, match="unit length"):
        occluded(tree, o, d * 2)
    with pytest.raises(TraceInputError, match="shape"):
        intersect(tree, o[:, :2], d[:, :2])
    with pytest.raises(TraceInputError, match="NaN"):
        occluded(tree, np.full((4, 3), np.nan), d)
    with pytest.raises(TraceInputError, match="tmax"):
        occluded(tree, o, d, tmax=-1.0)
    with pytest.raises(TraceInputError, match="KdTree"):
        occluded(object(), o, d)
    with pytest.raises(TraceInputError, match="unit length"):
        shadow_rays_from_surface(o, d, [0, 0, 2.0])
    empty = occluded(tree, np.empty((0, 3)), np.empty((0, 3)))
    assert empty.shape == (0,)
    # A caller's own buffer gets the same origins; one of another shape or type is refused.
    n = d / np.linalg.norm(d, axis=1, keepdims=True)
    buf = np.empty((4, 3))
    assert shadow_rays_from_surface(o, n, [0.0, 0.0, 1.0], out=buf) is buf
    assert np.array_equal(buf, shadow_rays_from_surface(o, n, [0.0, 0.0, 1.0]))
    for bad in (np.empty((3, 3)), np.empty((4, 3), np.float32), np.empty((3, 4)).T):
        with pytest.raises(TraceInputError, match="out must be a C-contiguous float64"):
            shadow_rays_from_surface(o, n, [0.0, 0.0, 1.0], out=bad)


def test_tile_order_is_a_permutation_of_tiles():
    order = tile_order(5, 7, tile_px=2)
    assert sorted(order.tolist()) == list(range(35))
    assert order[:4].tolist() == [0, 1, 7, 8]       # first tile: rows 0-1, columns 0-1


def test_kernels_run_without_jit():
    """NUMBA_DISABLE_JIT=1: the same code as plain Python agrees with the compiled kernels."""
    script = r"""
import json, numpy as np, sys
sys.path.insert(0, sys.argv[1])
from synthetic import box_city
from cityshade.accel import build_kdtree
from cityshade.trace import intersect, occluded
city = box_city(4, seed=9, extent_m=30.0)
tree = build_kdtree(*city)
rng = np.random.default_rng(1)
o = rng.uniform(-5, 40, (40, 3)); d = rng.normal(size=(40, 3))
d /= np.linalg.norm(d, axis=1, keepdims=True)
dist, tri, u, v = intersect(tree, o, d, 0.0)
print(json.dumps({"nodes": tree.nodes.tolist(), "tri": tri.tolist(),
                  "dist": [float(x) for x in dist], "occ": occluded(tree, o, d, 0.0).tolist()}))
"""
    results = run_with_and_without_jit(script)
    assert results[0] == results[1]
    assert any(x >= 0 for x in results[0]["tri"])


@pytest.fixture(scope="module")
def tum_campus():
    """The TUM campus LoD2 model through the project's reader and scene (skipped when absent)."""
    path = shared_file("munich-tum-campus-lod2/TUM Munich.gml")
    reader = pytest.importorskip("cityshade.citygml.reader")
    scene_mod = pytest.importorskip("cityshade.geometry.scene")
    scene = scene_mod.build_scene(reader.read_citygml(path))
    return scene


def test_tum_campus_agrees_with_brute_force_across_dates(tum_campus):
    sc = tum_campus
    v, t = sc.vertices, sc.triangles
    begin, end = sc.tri_t_begin_days, sc.tri_t_end_days
    tree = build_kdtree(v, t, begin, end, sc.tri_material)
    lo, hi = v.min(axis=0).astype(np.float64), v.max(axis=0).astype(np.float64)
    rng = np.random.default_rng(17)
    n = 150
    # Half the rays from above the roofs downwards (like a map), half in random directions.
    origins = rng.uniform(lo, hi, (n, 3))
    origins[: n // 2, 2] = hi[2] + 5.0
    directions = unit(rng.normal(size=(n, 3)))
    directions[: n // 2] = unit(directions[: n // 2] * [0.3, 0.3, 0.0] + [0, 0, -1.0])
    finite = np.concatenate([begin[np.isfinite(begin)], end[np.isfinite(end)]])
    slices = [0.0] if finite.size == 0 else [finite.min() - 1.0, float(np.median(finite)),
                                            finite.max() + 1.0]
    n_hits = 0
    for t_days in slices:
        dist, tri, _, _ = intersect(tree, origins, directions, t_days)
        occ = occluded(tree, origins, directions, t_days)
        for i in range(n):
            t_ref, tri_ref = reference_closest_hit(v, t, begin, end, origins[i], directions[i],
                                                   t_days)
            assert occ[i] == (tri_ref >= 0), f"t={t_days} ray {i}: any-hit disagrees"
            assert (tri[i] >= 0) == (tri_ref >= 0), f"t={t_days} ray {i}: hit/miss disagrees"
            if tri_ref >= 0:
                n_hits += 1
                assert dist[i] == pytest.approx(t_ref, rel=1e-9, abs=1e-9)
    assert n_hits > 50


def test_stripe_interleave_is_a_permutation():
    from cityshade.trace.bricks import stripe_interleave
    for stripes in (1, 8, 64):
        for n_items in (1, 5, stripes, stripes + 1, 1000):
            n_iter = stripes * ((n_items + stripes - 1) // stripes)
            items = [b for b in (stripe_interleave(j, n_items, stripes) for j in range(n_iter))
                     if b >= 0]
            assert sorted(items) == list(range(n_items))


def test_shadow_ray_leaves_the_wall_at_the_foot_of_a_sun_facing_wall():
    """Issue 13 point 12: points exactly on a roof-step edge lie in the plane of the step's
    wall; offset only along the roof normal their shadow rays hit that wall at distance ≈ 0.
    The stress set's case: every foot point of the sun-facing wall is lit, every foot point of
    the wall facing away is in shadow."""
    from cityshade.evaluate.stress import wall_foot_case

    case = wall_foot_case()
    assert case.passed, case.failures
    assert case.numbers["false shadow"] == 0 and case.numbers["false lit"] == 0


def test_sample_pixel_at_a_roof_step_is_lit():
    """The reported pixel: sample city, 1990, sun 135°/30°, map at 1 m, row 99, col 264
    (centre 690244.5, 5336100.5, exactly on a roof-step edge in front of a sun-facing wall)."""
    from conftest import REPO
    from cityshade.build import build_scene_from_file
    from cityshade.geo.temporal import parse_user_date
    from cityshade.raster import camera as cams
    from cityshade.frame.render import render_frame
    from cityshade.geo.sun import sun_from_angles

    scene = build_scene_from_file(REPO / "sample_data" / "sample_city.gml")
    cam = cams.map_view(scene, 1.0)
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, parse_user_date("1990").city_days, sun, "raytrace")
    assert frame.lit[99, 264] == 1.0, "the pixel at the foot of the sun-facing wall is in shadow"


def test_shadow_origins_equal_their_numpy_twin_bit_for_bit():
    from reference import reference_shadow_origins

    rng = np.random.default_rng(11)
    pts = rng.uniform(-3000.0, 3000.0, (5000, 3))
    pts[:50] = rng.uniform(-0.5, 0.5, (50, 3))                # below the 1 m floor of the scale
    pts[50:60] *= 1e4                                           # far from the origin
    normals = unit(rng.normal(size=(5000, 3)))
    sun = unit([0.3, -0.6, 0.7])
    np.testing.assert_array_equal(shadow_rays_from_surface(pts, normals, sun),
                                  reference_shadow_origins(pts, normals, sun))
    suns = unit(rng.normal(size=(5000, 3)))                    # one sun per point
    np.testing.assert_array_equal(shadow_rays_from_surface(pts, normals, suns),
                                  reference_shadow_origins(pts, normals, suns))
    bad = pts.copy()
    bad[3, 1] = np.nan
    with pytest.raises(TraceInputError, match="points contain NaN"):
        shadow_rays_from_surface(bad, normals, sun)
    bad = normals.copy()
    bad[7, 2] = np.inf
    with pytest.raises(TraceInputError, match="normals contain NaN"):
        shadow_rays_from_surface(pts, bad, sun)
    with pytest.raises(TraceInputError, match="normals must be unit length"):
        shadow_rays_from_surface(pts, normals * 1.01, sun)


def test_pixel_shadow_origins_equal_the_gathered_pixels_origins(sample_city_scene):
    """shadow_rays_from_pixels (one pass over a frame's rows) against its twin, the gathered
    pixels' shadow_rays_from_surface (whose own twin is numpy's), bit for bit: a real frame of
    the sample city (its facing pixels, then every valid one), on one and two threads; the
    same errors for a NaN point, a NaN normal and a normal off unit length."""
    from cityshade.frame.pipeline import camera_pass
    from cityshade.geo.sun import sun_from_angles
    from cityshade.raster.camera import map_view
    from cityshade.shadows import gather_pixels
    from cityshade.trace import shadow_rays_from_pixels

    def row_starts(mask):
        return np.concatenate([[0], np.cumsum(mask.sum(axis=1))]).astype(np.int64)

    scene = sample_city_scene
    cp = camera_pass(scene, map_view(scene, 0.5), 7305.0, ground="auto")
    ctx = cp.context(sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m))
    position, normal = cp.surfaces.position_m, ctx.normal
    for mask in (ctx.faces, np.asarray(cp.surfaces.valid)):
        want = shadow_rays_from_surface(gather_pixels(position, mask),
                                        gather_pixels(normal, mask), ctx.sun.direction)
        default = numba.get_num_threads()
        try:
            for threads in {1, default}:
                numba.set_num_threads(threads)
                got = shadow_rays_from_pixels(position, normal, mask, row_starts(mask),
                                              ctx.sun.direction)
                assert got.shape == want.shape and got.tobytes() == want.tobytes()
        finally:
            numba.set_num_threads(default)
    assert ctx.facing_origins.tobytes() == shadow_rays_from_surface(
        ctx.facing_points, ctx.facing_normals, ctx.sun.direction).tobytes()
    mask = np.asarray(cp.surfaces.valid).copy()
    r, c = np.argwhere(mask)[17]
    for image, value, message in ((position, np.nan, "points contain NaN"),
                                  (normal, np.inf, "normals contain NaN"),
                                  (normal, None, "normals must be unit length")):
        bad = np.array(image, copy=True)
        bad[r, c] = bad[r, c] * 1.01 if value is None else value
        args = (bad, normal) if image is position else (position, bad)
        with pytest.raises(TraceInputError, match=message):
            shadow_rays_from_pixels(*args, mask, row_starts(mask), ctx.sun.direction)



def test_facing_origins_of_some_rows_are_the_same_from_either_source(sample_city_scene):
    """ShadowContext.facing_origins_of (the crowns' pass): rows taken from the frame's origins
    when an exact technique made them, else made from those rows of the gathered points and
    normals; both equal the gathered rows' shadow_rays_from_surface bit for bit."""
    from cityshade.frame.pipeline import camera_pass
    from cityshade.geo.sun import sun_from_angles
    from cityshade.raster.camera import map_view

    scene = sample_city_scene
    cp = camera_pass(scene, map_view(scene, 0.5), 7305.0, ground="auto")
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    gathered, made = cp.context(sun), cp.context(sun)
    made.shared = gathered.shared = None           # each its own arrays
    rows = np.arange(0, int(made.faces.sum()), 7)
    want = shadow_rays_from_surface(gathered.facing_points[rows],
                                    gathered.facing_normals[rows], sun.direction)
    assert "facing_origins" not in gathered.__dict__
    assert gathered.facing_origins_of(rows).tobytes() == want.tobytes()
    assert "facing_origins" not in gathered.__dict__      # not made for a few rows
    made.facing_origins
    assert "facing_points" not in made.__dict__
    assert made.facing_origins_of(rows).tobytes() == want.tobytes()
    assert "facing_points" not in made.__dict__           # taken, nothing gathered

def test_shared_direction_shadow_rays_agree_with_brute_force(city, tree):
    """Sun rays (one direction for all, whose terms the kernel computes once) give the
    brute-force answer, and the same as the per-ray path on the same rays."""
    from cityshade.trace.bricks import occluded_bricks
    from cityshade.trace import padded_box

    v, t, begin, end, mat = city
    rng = np.random.default_rng(4)
    origins = rng.uniform((-20, -20, 0), (270, 270, 30), (800, 3))
    sun = unit([0.5, -0.4, 0.35])
    directions = np.tile(sun, (800, 1))
    occ = occluded(tree, origins, directions, 20000.0)
    want = np.array([reference_ray_hits(v, t, begin, end, o, sun, 20000.0)[1].size > 0
                     for o in origins])
    assert 100 < want.sum() < 700
    np.testing.assert_array_equal(occ, want)
    per_ray = np.zeros(800, np.bool_)
    lo, hi = padded_box(tree)
    occluded_bricks(tree.views, lo, hi, origins, directions, 0.0, np.full(800, np.inf), 20000.0,
                    256, per_ray)
    np.testing.assert_array_equal(per_ray, occ)
