"""Tests for cityshade.geometry.triangulate: areas, orientation, repairs, skips, real data."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.errors import InputError
from cityshade.geometry.triangulate import REPAIR_COLLINEAR_POINTS, REPAIR_DUPLICATE_POINTS, REPAIR_HOLE_DROPPED, REPAIR_NONPLANAR, REPAIR_UNCLOSED_RING, SKIP_ALL_COLLINEAR, SKIP_INVALID_HOLES, SKIP_NAN_COORDINATES, SKIP_REASONS, SKIP_SELF_INTERSECTING, SKIP_TOO_FEW_POINTS, SKIP_ZERO_AREA, TRIANGULATED, triangulate_polygons
from cityshade.errors import TriangulationInputError
from conftest import shared_file
from reference import reference_triangulate_polygon


# ---------------------------------------------------------------------------------------------
# Helpers: batches from nested lists, 2-D polygons embedded in 3-D, independent area/coverage.

def make_batch(polygons):
    """Flat (coords, ring_offsets, polygon_ring_offsets) from a list of polygons (lists of rings)."""
    rings = [np.asarray(r, dtype=np.float64).reshape(-1, 3) for poly in polygons for r in poly]
    coords = np.concatenate(rings) if rings else np.zeros((0, 3))
    ring_offsets = np.concatenate([[0], np.cumsum([len(r) for r in rings])]).astype(np.int64)
    polygon_ring_offsets = np.concatenate(
        [[0], np.cumsum([len(poly) for poly in polygons])]).astype(np.int64)
    return coords, ring_offsets, polygon_ring_offsets


def run(polygons, **kwargs):
    coords, ring_offsets, polygon_ring_offsets = make_batch(polygons)
    return coords, triangulate_polygons(coords, ring_offsets, polygon_ring_offsets, **kwargs)


def closed(xy, z=0.0):
    """3-D closed ring (last point = first) from 2-D points at height z."""
    xy = np.asarray(xy, dtype=np.float64)
    pts = np.column_stack([xy, np.full(len(xy), z)])
    return np.vstack([pts, pts[:1]])


def shoelace(xy):
    """Signed area of a 2-D ring (counter-clockwise positive), computed independently."""
    x, y = np.asarray(xy, dtype=np.float64).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def triangle_vectors(coords, triangles):
    """Right-hand (a, b, c) cross products of triangles: direction = normal, length = 2 area."""
    p = coords[triangles]
    return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q *= np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def star_polygon(rng, n, convex):
    """Random simple polygon, counter-clockwise: sorted angles, radius constant if convex."""
    angles = np.sort(rng.uniform(0.0, 2.0 * np.pi, n))
    # Keep angular gaps below π so the points on a circle form a convex, non-degenerate ring.
    angles = np.sort(np.concatenate([angles, np.arange(4) * np.pi / 2 + 0.1]))
    radii = np.full(len(angles), 5.0) if convex else rng.uniform(1.0, 5.0, len(angles))
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def coverage(tri_xy, points):
    """How many triangles (T, 3, 2), counter-clockwise or not, contain each point (S, 2)."""
    a, b, c = tri_xy[:, 0][:, None], tri_xy[:, 1][:, None], tri_xy[:, 2][:, None]
    p = points[None]

    def side(u, w):
        return (w[..., 0] - u[..., 0]) * (p[..., 1] - u[..., 1]) \
            - (w[..., 1] - u[..., 1]) * (p[..., 0] - u[..., 0])

    s1, s2, s3 = side(a, b), side(b, c), side(c, a)
    inside = ((s1 > 0) & (s2 > 0) & (s3 > 0)) | ((s1 < 0) & (s2 < 0) & (s3 < 0))
    return inside.sum(axis=0)


def point_in_rings(rings_xy, points):
    """Even-odd membership of points (S, 2) in a polygon given by 2-D rings (crossing number)."""
    inside = np.zeros(len(points), dtype=bool)
    x, y = points[:, 0], points[:, 1]
    for ring in rings_xy:
        ring = np.asarray(ring, dtype=np.float64)
        x0, y0 = ring[:, 0], ring[:, 1]
        x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
        for i in range(len(ring)):
            straddle = (y0[i] > y) != (y1[i] > y)
            with np.errstate(divide="ignore", invalid="ignore"):
                x_cross = x0[i] + (y - y0[i]) * (x1[i] - x0[i]) / (y1[i] - y0[i])
            inside ^= straddle & (x < x_cross)
    return inside


# ---------------------------------------------------------------------------------------------
# Orientation and normals.

def test_ccw_square_gives_up_normal_and_up_triangles():
    square = closed([(0, 0), (1, 0), (1, 1), (0, 1)])
    coords, res = run([[square], [square[::-1]]])
    assert res.status.tolist() == [TRIANGULATED, TRIANGULATED]
    np.testing.assert_allclose(res.normal, [[0, 0, 1], [0, 0, -1]], atol=1e-15)
    np.testing.assert_allclose(res.area_m2, [1.0, 1.0], rtol=1e-15)
    tri_n = triangle_vectors(coords, res.triangles)
    up = res.tri_polygon == 0
    assert np.all(tri_n[up, 2] > 0) and np.all(tri_n[~up, 2] < 0)
    assert np.count_nonzero(up) == 2 and np.count_nonzero(~up) == 2
    assert res.repairs.tolist() == [0, 0]  # the closing point is no repair


def test_vertical_walls_and_box_at_real_world_coordinates():
    # A 10 × 6 × 7 m box at UTM-like coordinates, faces wound outwards.
    x0, y0, z0 = 4.5e6 + 0.125, 5.3e6 + 0.375, 519.5
    dx, dy, dz = 10.0, 6.0, 7.0
    c = np.array([[x0, y0, z0], [x0 + dx, y0, z0], [x0 + dx, y0 + dy, z0], [x0, y0 + dy, z0]])
    top = c + [0, 0, dz]
    faces = [c[[0, 3, 2, 1]], top, np.array([c[0], c[1], top[1], top[0]]),
             np.array([c[1], c[2], top[2], top[1]]), np.array([c[2], c[3], top[3], top[2]]),
             np.array([c[3], c[0], top[0], top[3]])]
    coords, res = run([[np.vstack([f, f[:1]])] for f in faces])
    assert np.all(res.status == TRIANGULATED)
    expected_normals = [[0, 0, -1], [0, 0, 1], [0, -1, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0]]
    np.testing.assert_allclose(res.normal, expected_normals, atol=1e-12)
    np.testing.assert_allclose(res.area_m2, [60, 60, 70, 42, 70, 42], rtol=1e-9)
    tri_n = triangle_vectors(coords, res.triangles)
    areas = 0.5 * np.linalg.norm(tri_n, axis=1)
    np.testing.assert_allclose(np.bincount(res.tri_polygon, areas), [60, 60, 70, 42, 70, 42],
                               rtol=1e-9)
    # Each triangle's right-hand normal is its face's outward normal.
    unit = tri_n / np.linalg.norm(tri_n, axis=1)[:, None]
    np.testing.assert_allclose(unit, np.asarray(expected_normals, float)[res.tri_polygon],
                               atol=1e-9)
    # Divergence theorem: the outward-wound triangles enclose the box volume.
    p = coords[res.triangles] - coords.mean(axis=0)
    volume = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0
    assert volume == pytest.approx(dx * dy * dz, rel=1e-9)


# ---------------------------------------------------------------------------------------------
# Areas of random and holed polygons.

@pytest.mark.parametrize("convex", [True, False])
def test_random_polygons_area_and_normal(convex):
    rng = np.random.default_rng(1234 if convex else 4321)
    polygons, truth = [], []
    for _ in range(150):
        xy = star_polygon(rng, int(rng.integers(3, 40)), convex)
        rot = random_rotation(rng)
        offset = rng.uniform(-1e3, 1e3, 3) + [4.5e6, 5.3e6, 0.0]
        pts = offset + np.column_stack([xy, np.zeros(len(xy))]) @ rot.T
        polygons.append([np.vstack([pts, pts[:1]])])
        truth.append((shoelace(xy), rot[:, 2], len(xy)))
    coords, res = run(polygons)
    assert np.all(res.status == TRIANGULATED), SKIP_REASONS
    assert np.all(res.repairs == 0)
    tri_n = triangle_vectors(coords, res.triangles)
    tri_area = np.bincount(res.tri_polygon, 0.5 * np.linalg.norm(tri_n, axis=1),
                           minlength=len(polygons))
    area, normal, n_points = (np.array(t) for t in zip(*truth))
    np.testing.assert_allclose(tri_area, area, rtol=1e-9)
    np.testing.assert_allclose(res.area_m2, area, rtol=1e-9)
    np.testing.assert_allclose(res.normal, np.stack(normal), atol=1e-9)
    assert np.array_equal(np.bincount(res.tri_polygon, minlength=len(polygons)), n_points - 2)
    # Every triangle faces like its polygon.
    assert np.all(np.einsum("ij,ij->i", tri_n, res.normal[res.tri_polygon]) > 0)


def regular(n, r, cx=0.0, cy=0.0, phase=0.0):
    t = phase + 2 * np.pi * np.arange(n) / n
    return np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])


def square(x0, y0, x1, y1):
    return np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], dtype=np.float64)


HOLED = {
    # name: (exterior 2-D, [holes 2-D], analytic area)
    "l_shape": (np.array([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]), [], 3.0),
    "square_annulus": (square(0, 0, 10, 10), [square(3, 3, 7, 7)], 84.0),
    "round_annulus": (regular(32, 2.0), [regular(16, 1.0, phase=0.1)],
                      16 * np.sin(2 * np.pi / 32) * 4 - 8 * np.sin(2 * np.pi / 16)),
    "two_holes": (square(0, 0, 10, 4), [square(1, 1, 3, 3), square(6, 1, 9, 3)[::-1]], 40.0 - 4 - 6),
    "three_holes_in_l": (np.array([(0, 0), (6, 0), (6, 2), (2, 2), (2, 6), (0, 6)]),
                         [square(0.5, 0.5, 1.5, 1.5), square(3, 0.5, 5, 1.5),
                          square(0.5, 3, 1.5, 5)], 20.0 - 1 - 2 - 2),
    "holes_sharing_x": (square(0, 0, 4, 4), [square(1, 0.5, 3, 1.5), square(1, 2.5, 3, 3.5)], 12.0),
}


@pytest.mark.parametrize("name", sorted(HOLED))
def test_polygons_with_holes(name):
    ext, holes, area = HOLED[name]
    rng = np.random.default_rng(7)
    rot = random_rotation(rng)
    offset = np.array([4.5e6, 5.3e6, 35.0])
    rings_xy = [ext] + holes
    rings = []
    for xy in rings_xy:
        pts = offset + np.column_stack([xy, np.zeros(len(xy))]) @ rot.T
        rings.append(np.vstack([pts, pts[:1]]))
    coords, res = run([rings])
    assert res.status[0] == TRIANGULATED, SKIP_REASONS.get(int(res.status[0]))
    assert res.repairs[0] == 0
    assert shoelace(ext) - sum(abs(shoelace(h)) for h in holes) == pytest.approx(area, rel=1e-12)
    tri_n = triangle_vectors(coords, res.triangles)
    assert 0.5 * np.linalg.norm(tri_n, axis=1).sum() == pytest.approx(area, rel=1e-9)
    assert res.area_m2[0] == pytest.approx(area, rel=1e-9)
    assert len(res.triangles) == sum(len(r) for r in rings_xy) + 2 * len(holes) - 2
    assert np.all(tri_n @ rot[:, 2] > 0)
    # The triangles cover the polygon exactly once and the holes not at all.
    tri_xy = (coords[res.triangles] - offset) @ rot[:, :2]
    lo, hi = ext.min(axis=0), ext.max(axis=0)
    samples = np.random.default_rng(11).uniform(lo - 0.5, hi + 0.5, (4000, 2))
    assert np.array_equal(coverage(tri_xy, samples), point_in_rings(rings_xy, samples))


# ---------------------------------------------------------------------------------------------
# Repairs and skips on hand-made polygons.

def figure_eight(n):
    """Large self-crossing ring: a figure eight whose right lobe is twice as wide as its left,
    with more points than the exact edge test takes, so only the area check can find it."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    x = np.sin(t)
    return np.column_stack([np.where(x > 0, 2 * x, x), np.sin(t) * np.cos(t)])


UNIT = [(0, 0), (1, 0), (1, 1), (0, 1)]
DEGENERATE = {
    # name: (rings, expected status, expected repair bits; skipped polygons report none)
    "bow_tie_symmetric": ([closed([(0, 0), (0, 1), (1, 0), (1, 1)])], SKIP_SELF_INTERSECTING, 0),
    "bow_tie_unequal": ([closed([(0, 0), (2, 2), (2, 0), (0, 1)])], SKIP_SELF_INTERSECTING, 0),
    "pentagram": ([closed(regular(5, 1.0)[[0, 2, 4, 1, 3]])], SKIP_SELF_INTERSECTING, 0),
    # The chain passes through (2, 1), a point inside the edge (3, 0) → (1, 2): no proper
    # crossing, but a crossing through a vertex.
    "crossing_through_vertex": ([closed([(0, 0), (2, 1), (4, 3), (3, 0), (1, 2), (0, 2)])],
                                SKIP_SELF_INTERSECTING, 0),
    # Two counter-clockwise lobes touching at (2, 1): weakly simple, triangulated (area 8).
    "lobes_touching_at_vertex": ([closed([(0, 0), (2, 1), (4, 0), (4, 4), (2, 1), (0, 4)])],
                                 TRIANGULATED, 0),
    "large_figure_eight": ([closed(figure_eight(600))], SKIP_SELF_INTERSECTING, 0),
    "collinear_only": ([closed([(0, 0), (1, 0), (2, 0), (3, 0)])], SKIP_ALL_COLLINEAR, 0),
    "two_points": ([closed([(0, 0), (0, 1)])], SKIP_TOO_FEW_POINTS, 0),
    "one_point_repeated": ([closed([(2, 2), (2, 2), (2, 2)])], SKIP_TOO_FEW_POINTS, 0),
    "empty_ring": ([np.zeros((0, 3))], SKIP_TOO_FEW_POINTS, 0),
    "repeated_points": ([closed([(0, 0), (1, 0), (1, 0), (1, 1), (1, 1), (1, 1), (0, 1)])],
                        TRIANGULATED, REPAIR_DUPLICATE_POINTS),
    "unclosed": ([closed(UNIT)[:-1]], TRIANGULATED, REPAIR_UNCLOSED_RING),
    "point_on_edge": ([closed([(0, 0), (0.5, 0), (1, 0), (1, 1), (0, 1)])], TRIANGULATED,
                      REPAIR_COLLINEAR_POINTS),
    "spike": ([closed([(0, 0), (1, 0), (1, 1), (1.5, 1.5), (1, 1), (0, 1)])], TRIANGULATED,
              REPAIR_COLLINEAR_POINTS | REPAIR_DUPLICATE_POINTS),
    "traced_back": ([closed([(0, 0), (1, 0), (0, 1), (1, 0)])], SKIP_ZERO_AREA, 0),
    "nan": ([closed([(0, 0), (1, 0), (np.nan, 1), (0, 1)])], SKIP_NAN_COORDINATES, 0),
    "inf_in_hole": ([closed(square(0, 0, 4, 4)), closed([(1, 1), (1, 2), (np.inf, 2)])],
                    SKIP_NAN_COORDINATES, 0),
    "hole_outside": ([closed(square(0, 0, 4, 4)), closed(square(5, 1, 6, 2))],
                     SKIP_INVALID_HOLES, 0),
    "hole_outside_left": ([closed(square(0, 0, 4, 4)), closed(square(-3, 1, -2, 2))],
                          SKIP_INVALID_HOLES, 0),
    "hole_crossing_exterior": ([closed(square(0, 0, 4, 4)), closed(square(3, 1, 5, 2))],
                               SKIP_INVALID_HOLES, 0),
    "nested_holes": ([closed(square(0, 0, 4, 4)), closed(square(1, 1, 3, 3)),
                      closed(square(1.5, 1.5, 2.5, 2.5))], SKIP_INVALID_HOLES, 0),
    "overlapping_holes": ([closed(square(0, 0, 4, 4)), closed(square(1, 1, 2.5, 2.5)),
                           closed(square(2, 2, 3, 3))], SKIP_INVALID_HOLES, 0),
    "duplicated_hole": ([closed(square(0, 0, 4, 4)), closed(square(1, 1, 2, 2)),
                         closed(square(1, 1, 2, 2))], SKIP_INVALID_HOLES, 0),
    "hole_as_big_as_exterior": ([closed(square(0, 0, 4, 4)), closed(square(0, 0, 4, 4))],
                                SKIP_INVALID_HOLES, 0),
    "hole_two_points": ([closed(square(0, 0, 4, 4)), closed([(1, 1), (2, 2)])],
                        TRIANGULATED, REPAIR_HOLE_DROPPED),
    "hole_collapsed_to_line": ([closed(square(0, 0, 4, 4)), closed([(1, 1), (2, 2), (3, 3)])],
                               TRIANGULATED, REPAIR_HOLE_DROPPED | REPAIR_COLLINEAR_POINTS),
    "nonplanar": ([np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0.1), (0, 1, 0), (0, 0, 0)])],
                  TRIANGULATED, REPAIR_NONPLANAR),
    "sliver": ([closed([(0, 0), (1, 0), (0.5, 1e-14)])], SKIP_ALL_COLLINEAR, 0),
}


@pytest.mark.parametrize("name", sorted(DEGENERATE))
def test_degenerate_polygon_table(name):
    rings, expected_status, expected_repairs = DEGENERATE[name]
    coords, res = run([rings])
    got = SKIP_REASONS.get(int(res.status[0]), "triangulated")
    want = SKIP_REASONS.get(expected_status, "triangulated")
    assert got == want
    assert int(res.repairs[0]) == expected_repairs
    assert np.all(np.isfinite(res.normal)) and np.all(np.isfinite(res.area_m2))
    if expected_status != TRIANGULATED:
        assert len(res.triangles) == 0 and res.area_m2[0] == 0.0
    else:
        tri = res.triangles
        assert len(tri) > 0
        # No repeated index and no two corners at the same point.
        assert np.all((tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 2] != tri[:, 0]))
        assert np.all(np.linalg.norm(triangle_vectors(coords, tri), axis=1) > 0)


def test_repairs_keep_the_area():
    names = ("repeated_points", "unclosed", "point_on_edge", "spike", "hole_two_points",
             "lobes_touching_at_vertex")
    coords, res = run([DEGENERATE[n][0] for n in names])
    np.testing.assert_allclose(res.area_m2, [1, 1, 1, 1, 16, 8], rtol=1e-12)
    tri_area = 0.5 * np.linalg.norm(triangle_vectors(coords, res.triangles), axis=1)
    np.testing.assert_allclose(np.bincount(res.tri_polygon, tri_area), [1, 1, 1, 1, 16, 8],
                               rtol=1e-12)
    assert np.bincount(res.tri_polygon).tolist() == [2, 2, 2, 2, 2, 2]


def test_polygon_without_rings_and_mixed_batch():
    # Polygon 1 has no ring at all; the others must not be disturbed by it.
    sq = closed(UNIT)
    coords = np.vstack([sq, sq + [0, 0, 1]])
    res = triangulate_polygons(coords, np.array([0, 5, 10]), np.array([0, 1, 1, 2]))
    assert res.status.tolist() == [TRIANGULATED, SKIP_TOO_FEW_POINTS, TRIANGULATED]
    assert res.tri_polygon.tolist() == [0, 0, 2, 2]
    assert res.skip_counts() == {"too_few_points": 1}
    assert res.repair_counts() == {}


# ---------------------------------------------------------------------------------------------
# Precision at large offsets; agreement with the slow twin.

def test_offset_by_1e7_gives_same_triangles():
    rng = np.random.default_rng(99)
    polygons = []
    for _ in range(40):
        xy = star_polygon(rng, int(rng.integers(5, 30)), convex=False)
        polygons.append([closed(xy, z=float(rng.uniform(0, 50)))])
    coords, res = run(polygons)
    shifted = [[ring + [1e7, 1e7, 0.0] for ring in poly] for poly in polygons]
    coords_s, res_s = run(shifted)
    assert np.all(res.status == TRIANGULATED) and np.all(res_s.status == TRIANGULATED)
    assert np.array_equal(res.triangles, res_s.triangles)
    np.testing.assert_allclose(res_s.area_m2, res.area_m2, rtol=1e-9)
    np.testing.assert_allclose(res_s.normal, res.normal, atol=1e-9)


def test_agrees_with_reference_twin():
    rng = np.random.default_rng(2024)
    cases = []
    for i in range(60):
        xy = star_polygon(rng, int(rng.integers(4, 25)), convex=False)
        holes = []
        if i % 3 == 0:
            # Star radii are at least 1: a small hole around the centre lies inside.
            holes.append(regular(int(rng.integers(3, 7)), 0.4, phase=float(rng.uniform(0, 1))))
        if i % 6 == 0:
            holes[0] = holes[0] + [0.35, 0.0]
            holes.append(regular(4, 0.15, cx=-0.5, cy=0.0)[::-1])
        cases.append((xy, holes))
    rot = random_rotation(rng)
    offset = np.array([4.5e6, 5.3e6, 10.0])
    polygons = []
    for xy, holes in cases:
        polygons.append([offset + np.column_stack([r, np.zeros(len(r))]) @ rot.T
                         for r in [xy] + holes])  # rings left unclosed on purpose
    coords, res = run(polygons)
    assert np.all(res.status == TRIANGULATED)
    assert np.all(res.repairs == REPAIR_UNCLOSED_RING)
    samples_all = np.random.default_rng(5).uniform(-5.5, 5.5, (3000, 2))
    ring_base = 0
    for p, (xy, holes) in enumerate(cases):
        rings = polygons[p]
        ref = reference_triangulate_polygon(rings) + ring_base
        ring_base += sum(len(r) for r in rings)
        fast = res.triangles[res.tri_polygon == p]
        fast_xy = (coords[fast] - offset) @ rot[:, :2]
        ref_xy = (coords[ref] - offset) @ rot[:, :2]
        area = shoelace(xy) - sum(abs(shoelace(h)) for h in holes)
        for tri_xy in (fast_xy, ref_xy):
            e1, e2 = tri_xy[:, 1] - tri_xy[:, 0], tri_xy[:, 2] - tri_xy[:, 0]
            tri_area = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]).sum()
            assert tri_area == pytest.approx(area, rel=1e-9)
        assert len(fast) == len(ref)
        cov_fast = coverage(fast_xy, samples_all)
        cov_ref = coverage(ref_xy, samples_all)
        assert np.array_equal(cov_fast, cov_ref)
        assert np.array_equal(cov_fast, point_in_rings([xy] + holes, samples_all))


# ---------------------------------------------------------------------------------------------
# API edge: validation, read-only input, determinism.

def test_read_only_input_and_determinism():
    rings = [closed(square(0, 0, 4, 4)), closed(square(1, 1, 2, 2))]
    coords, ring_offsets, polygon_ring_offsets = make_batch([rings, [closed(HOLED["l_shape"][0])]])
    for array in (coords, ring_offsets, polygon_ring_offsets):
        array.setflags(write=False)
    first = triangulate_polygons(coords, ring_offsets, polygon_ring_offsets)
    second = triangulate_polygons(coords, ring_offsets, polygon_ring_offsets)
    for name in ("triangles", "tri_polygon", "status", "repairs", "normal", "area_m2"):
        assert np.array_equal(getattr(first, name), getattr(second, name))
    assert first.triangles.dtype == np.int64 and first.status.dtype == np.uint8
    assert first.repairs.dtype == np.uint16 and first.normal.shape == (2, 3)


@pytest.mark.parametrize("args, message", [
    ((np.zeros((4, 2)), [0, 4], [0, 1]), "shape"),
    ((np.zeros((4, 3)), [0, 5], [0, 1]), "within"),
    ((np.zeros((4, 3)), [0, 4, 2], [0, 2]), "non-decreasing"),
    ((np.zeros((4, 3)), [0, 4], [0, 2]), "within"),
    ((np.zeros((4, 3)), [0.0, 4.0], [0, 1]), "integers"),
    ((np.zeros((4, 3)), [], [0]), "at least one"),
])
def test_invalid_arrays_raise_typed_error(args, message):
    with pytest.raises(TriangulationInputError, match=message) as info:
        triangulate_polygons(*args)
    assert isinstance(info.value, InputError)


def test_negative_tolerance_raises():
    with pytest.raises(TriangulationInputError, match="area_rel_tol"):
        triangulate_polygons(np.zeros((0, 3)), [0], [0], area_rel_tol=-1.0)


def test_empty_batch():
    res = triangulate_polygons(np.zeros((0, 3)), np.array([0]), np.array([0]))
    assert res.triangles.shape == (0, 3) and res.status.shape == (0,)


# ---------------------------------------------------------------------------------------------
# Real data: the QIE unit-test solids (tudelft3d/CityGML-QIE-3Dvalidation).

GML_NS = "{http://www.opengis.net/gml}"


def read_qie_polygons(path):
    """Polygons of a QIE file as lists of (n, 3) rings, parsed with a small lxml walk."""
    from lxml import etree

    polygons = []
    for polygon in etree.parse(str(path)).iter(GML_NS + "Polygon"):
        rings = []
        for boundary in ("exterior", "interior"):
            for element in polygon.findall(GML_NS + boundary):
                ring = next(element.iter(GML_NS + "LinearRing"))
                values = [float(v) for pos in ring.iter(GML_NS + "pos") for v in pos.text.split()]
                rings.append(np.array(values).reshape(-1, 3))
        polygons.append(rings)
    return polygons


def signed_volume(coords, triangles):
    p = coords[triangles] - coords.mean(axis=0)
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0


@pytest.mark.shared
@pytest.mark.parametrize("name", ["v001", "v004", "v005"])
def test_qie_valid_unit_cubes(name):
    # v004/v005 are the unit cube at coordinates ≈ 1e8 and ≈ 3.3e12.
    path = shared_file(f"invalid-qie-unittests/{name}.gml")
    coords, res = run(read_qie_polygons(path))
    assert np.all(res.status == TRIANGULATED) and np.all(res.repairs == 0)
    assert len(res.triangles) == 12
    np.testing.assert_allclose(res.area_m2, 1.0, rtol=1e-9)
    assert signed_volume(coords, res.triangles) == pytest.approx(1.0, rel=1e-6)
    # Outward normals: each face normal points away from the cube's centre.
    centre = coords.mean(axis=0)
    for p in range(len(res.status)):
        face_centre = coords[res.triangles[res.tri_polygon == p]].reshape(-1, 3).mean(axis=0)
        assert np.dot(res.normal[p], face_centre - centre) > 0.4


@pytest.mark.shared
@pytest.mark.parametrize("name, polygon, status, repairs", [
    ("i101_1", 0, SKIP_TOO_FEW_POINTS, 0),
    ("i102_1", 2, TRIANGULATED, REPAIR_DUPLICATE_POINTS),
    ("i103_1", 0, TRIANGULATED, REPAIR_UNCLOSED_RING),
    ("i104_1", 0, SKIP_SELF_INTERSECTING, 0),
    ("i105_1", 0, TRIANGULATED, REPAIR_HOLE_DROPPED | REPAIR_COLLINEAR_POINTS),
    ("i201_1", 0, SKIP_INVALID_HOLES, 0),
    ("i202_1", 0, SKIP_INVALID_HOLES, 0),
    ("i206_1", 4, SKIP_INVALID_HOLES, 0),
    ("i207_1", 0, SKIP_INVALID_HOLES, 0),
    ("t203_1", 1, TRIANGULATED, REPAIR_NONPLANAR),
])
def test_qie_invalid_files(name, polygon, status, repairs):
    path = shared_file(f"invalid-qie-unittests/{name}.gml")
    polygons = read_qie_polygons(path)
    coords, res = run(polygons)
    assert int(res.status[polygon]) == status
    assert int(res.repairs[polygon]) == repairs
    # Only the polygon carrying the file's error is affected.
    others = np.arange(len(polygons)) != polygon
    assert np.all(res.status[others] == TRIANGULATED) and np.all(res.repairs[others] == 0)


@pytest.mark.shared
def test_qie_wrong_orientation_keeps_the_given_winding():
    # i308_1: all polygons wound inwards; triangles follow the rings, so the volume is −1.
    coords, res = run(read_qie_polygons(shared_file("invalid-qie-unittests/i308_1.gml")))
    assert np.all(res.status == TRIANGULATED)
    assert signed_volume(coords, res.triangles) == pytest.approx(-1.0, rel=1e-9)


def mixed_polygons():
    """900 polygons mixing the degenerate table's skips and repairs, holes, random stars and
    polygons without rings."""
    rng = np.random.default_rng(11)
    polygons = []
    for i in range(900):
        kind = i % 4
        if kind == 0:
            polygons.append(DEGENERATE[sorted(DEGENERATE)[(i // 4) % len(DEGENERATE)]][0])
        elif kind == 1:
            ext, holes, _area = HOLED[sorted(HOLED)[(i // 4) % len(HOLED)]]
            polygons.append([closed(ext)] + [closed(h) for h in holes])
        elif kind == 2:
            polygons.append([closed(star_polygon(rng, int(rng.integers(3, 40)), convex=i % 8 == 2))])
        else:
            polygons.append([] if i % 12 == 3 else [closed(regular(int(rng.integers(3, 9)), 2.0))])
    return polygons


@pytest.mark.parametrize("threads", [1, 2])
def test_parallel_chunks_equal_the_one_thread_kernel(monkeypatch, threads):
    """Chunks of polygons triangulated on the threads, each into its own rows, then moved
    together: every output equals the one-thread kernel's, row for row, on a batch that mixes
    the degenerate table's skips and repairs, holes, random stars and polygons without rings
    (chunk edges then fall on every kind), and the bound each chunk is given holds."""
    import numba

    import cityshade.geometry.triangulate as T

    polygons = mixed_polygons()
    coords, ring_offsets, poly_rings = make_batch(polygons)
    monkeypatch.setattr(T, "PARALLEL_MIN_POLYGONS", 10**9)
    one = triangulate_polygons(coords, ring_offsets, poly_rings)
    monkeypatch.setattr(T, "PARALLEL_MIN_POLYGONS", 0)
    calls = []
    real = T._triangulate_parallel
    monkeypatch.setattr(T, "_triangulate_parallel", lambda *a: calls.append(real(*a)) or calls[-1])
    old = numba.get_num_threads()
    numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
    try:
        many = triangulate_polygons(coords, ring_offsets, poly_rings)
    finally:
        numba.set_num_threads(old)
    assert calls == ([len(one.triangles)] if numba.config.NUMBA_NUM_THREADS > 1 and threads > 1
                     else [])
    assert 0 < len(one.triangles) and len(set(one.status.tolist())) > 5
    for name in ("triangles", "tri_polygon", "status", "repairs", "normal", "area_m2"):
        a, b = getattr(one, name), getattr(many, name)
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True), name
    poly_start, out_start = T._chunk_bounds(ring_offsets, poly_rings, 16)
    counts = np.bincount(one.tri_polygon, minlength=len(polygons))
    for c in range(16):  # each chunk's triangles fit before the next chunk's first row
        used = counts[poly_start[c]:poly_start[c + 1]].sum()
        assert out_start[c] + used <= out_start[c + 1]
    assert poly_start[0] == 0 and poly_start[-1] == len(polygons)


@pytest.mark.parametrize("offset_m", [0.0, 3.3e6 + 0.123])
def test_interpreted_twin_equals_the_compiled_kernel(monkeypatch, offset_m):
    """Small first-use batches run the kernel's own Python source (runtime.interpret): every
    output equals the compiled kernel's, bit for bit, on the mixed batch (and far from the
    origin, where every step rounds)."""
    import cityshade.geometry.triangulate as T
    from cityshade.runtime.interpret import InterpretBudget

    coords, ring_offsets, poly_rings = make_batch(mixed_polygons())
    coords = coords + offset_m
    coords.setflags(write=False)
    monkeypatch.setattr(T, "_INTERPRET", InterpretBudget(0))
    compiled = triangulate_polygons(coords, ring_offsets, poly_rings)
    budget = InterpretBudget(10**9)
    monkeypatch.setattr(T, "_INTERPRET", budget)
    twin = triangulate_polygons(coords, ring_offsets, poly_rings)
    assert budget.left == 10**9 - len(coords)  # it ran interpreted
    assert len(compiled.triangles) > 1000 and len(set(compiled.status.tolist())) > 5
    for name in ("triangles", "tri_polygon", "status", "repairs", "normal", "area_m2"):
        a, b = getattr(compiled, name), getattr(twin, name)
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=True), name
