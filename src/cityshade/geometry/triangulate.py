"""Polygon triangulation in float64, with sure repairs and counted skips (docs/DESIGN.md §3, §14).

The CityGML reader hands over every polygon of a batch as flat arrays (points, ring offsets,
polygon → ring offsets); :func:`triangulate_polygons` triangulates the whole batch in one Numba
kernel call and reports, per polygon, whether it was triangulated (``status == 0``) or skipped
(a ``SKIP_*`` code, named in :data:`SKIP_REASONS`), which sure repairs were applied (``REPAIR_*``
bits, named in :data:`REPAIR_NAMES`), its unit Newell normal and its area.

Conventions
-----------
* Points are metres in any CRS magnitude (real files reach 3.3e12). Every polygon is processed
  relative to its first exterior point, so precision follows the polygon's own size.
* The polygon plane is the Newell plane of the exterior ring (Newell's method, see e.g.
  Sutherland, Sproull & Schumacker 1974; Tampieri, "Newell's method for computing the plane
  equation of a polygon", Graphics Gems III). Points are projected on the orthonormal basis
  (u, v) of Duff et al., "Building an orthonormal basis, revisited" (JCGT 2017), which has
  u × v = n, so the exterior comes out counter-clockwise in 2-D when seen against n.
* Output triangles are wound like the exterior ring: their right-hand normals agree with the
  Newell normal (outward when the GML is well oriented). Holes may be given in either
  orientation. Triangle vertices are row indices into the input ``coords``; they keep the true
  3-D points, also for non-planar polygons.
* Holes are joined to the exterior by bridges found as in Eberly, "Triangulation by ear
  clipping" (Geometric Tools, 2002-2015): holes by decreasing maximum x, each bridged from its
  rightmost vertex to a mutually visible vertex of the outer chain. The joined chain is then
  ear-clipped.
* The generic guard: the triangles of a polygon are a sum of ear triangles of one closed chain,
  so the coverage count of their union equals the chain's winding number at every point. When
  every triangle is positive (the sum of |triangle areas| equals |exterior| − Σ|holes|), the
  coverage is exactly the polygon with its holes; otherwise the chain crosses itself or its
  holes are invalid and the polygon is skipped. Self-overlaps of winding two (a pentagram) keep
  positive triangles, so polygons of up to ``SEGMENT_TEST_MAX_POINTS`` points also get an
  O(n²) edge-crossing test (proper crossings and crossings through a vertex).
* Known limit: a ring that runs back along its own edges (collinear overlaps, found only on
  coarse grids in testing) can pass both tests; its triangles then cover the overlap twice,
  as its winding number says. Shadows are unaffected; the area counts the overlap twice.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numba
from numba import njit

from cityshade.errors import TriangulationInputError
from cityshade.runtime.interpret import InterpretBudget, python_twin

# ---------------------------------------------------------------------------------------------
# Status codes (one per polygon) and repair bits.

#: Status of a polygon that was triangulated.
TRIANGULATED = 0
#: Fewer than 3 distinct points in the exterior ring (or no exterior ring at all).
SKIP_TOO_FEW_POINTS = 1
#: A coordinate of one of the polygon's rings is NaN or infinite.
SKIP_NAN_COORDINATES = 2
#: Area below ``min_rel_area`` × size² although the points are not all on one line.
SKIP_ZERO_AREA = 3
#: Three or more distinct points, all on one line.
SKIP_ALL_COLLINEAR = 4
#: The exterior ring crosses itself (edge-crossing test or area check).
SKIP_SELF_INTERSECTING = 5
#: A hole lies outside the exterior, crosses it, is nested in or overlaps another hole.
SKIP_INVALID_HOLES = 6
#: The ring passed the exact simplicity test, yet the ear clipper's triangles fail the area
#: check (numerical breakdown on nearly degenerate input).
SKIP_TRIANGULATION_FAILED = 7

#: Name of every skip code, for build reports.
SKIP_REASONS = {
    SKIP_TOO_FEW_POINTS: "too_few_points",
    SKIP_NAN_COORDINATES: "nan_coordinates",
    SKIP_ZERO_AREA: "zero_area",
    SKIP_ALL_COLLINEAR: "all_collinear",
    SKIP_SELF_INTERSECTING: "self_intersecting",
    SKIP_INVALID_HOLES: "invalid_holes",
    SKIP_TRIANGULATION_FAILED: "triangulation_failed",
}

#: What a skip reason says of its polygons, for messages: (one polygon, several polygons).
SKIP_PHRASES = {
    "too_few_points": ("has too few points", "have too few points"),
    "nan_coordinates": ("has coordinates that are not numbers", "have coordinates that are "
                        "not numbers"),
    "zero_area": ("has no area", "have no area"),
    "all_collinear": ("has all its points on one line", "have all their points on one line"),
    "self_intersecting": ("crosses itself", "cross themselves"),
    "invalid_holes": ("has holes outside it or overlapping", "have holes outside them or "
                      "overlapping"),
    "triangulation_failed": ("is too degenerate to triangulate", "are too degenerate to "
                             "triangulate"),
    "bad_coordinates": ("has unreadable coordinates", "have unreadable coordinates"),
    "solid_cavity_shell": ("is a solid's inner (cavity) shell", "are solids' inner (cavity) "
                           "shells"),
}


def describe_skips(skipped: dict[str, int]) -> str:
    """``{'too_few_points': 1, 'zero_area': 2}`` → ``1 polygon has too few points, 2 polygons
    have no area``: the skip counts of a build as a reader would say them."""
    from cityshade.util import plural

    parts = []
    for reason, count in skipped.items():
        if count:
            one, many = SKIP_PHRASES.get(reason, (f"skipped ({reason.replace('_', ' ')})",) * 2)
            parts.append(f"{plural(count, 'polygon')} {one if count == 1 else many}")
    return ", ".join(parts) or "no polygon was read"


#: A ring whose last point differs from its first was closed implicitly.
REPAIR_UNCLOSED_RING = 1
#: Consecutive points within ``merge_distance_m`` were merged into one.
REPAIR_DUPLICATE_POINTS = 2
#: Points on the line of their neighbours (including zero-width spikes) were removed.
REPAIR_COLLINEAR_POINTS = 4
#: A point lies farther than ``nonplanar_rel_tol`` × size from the Newell plane; the polygon is
#: triangulated anyway with its true 3-D points.
REPAIR_NONPLANAR = 8
#: A degenerate hole (fewer than 3 points or zero area) was dropped, the exterior kept.
REPAIR_HOLE_DROPPED = 16

#: Name of every repair bit, for build reports.
REPAIR_NAMES = {
    REPAIR_UNCLOSED_RING: "unclosed_ring",
    REPAIR_DUPLICATE_POINTS: "duplicate_points",
    REPAIR_COLLINEAR_POINTS: "collinear_points",
    REPAIR_NONPLANAR: "nonplanar",
    REPAIR_HOLE_DROPPED: "hole_dropped",
}

#: Polygons with at most this many points (all rings together, after cleaning) get the exact
#: O(n²) edge-crossing test: 256 points are 32 640 edge pairs, well under a millisecond, and
#: real CityGML polygons above that size are rare enough to rely on the area check alone.
SEGMENT_TEST_MAX_POINTS = 256


@dataclass(frozen=True)
class TriangulationResult:
    """Triangles of a batch of polygons, with the fate of every polygon.

    Attributes
    ----------
    triangles : ndarray, shape (T, 3), int64
        Row indices into the input ``coords``; wound like the polygon's exterior ring.
    tri_polygon : ndarray, shape (T,), int64
        Polygon each triangle came from; non-decreasing (triangles are grouped by polygon).
    status : ndarray, shape (P,), uint8
        ``TRIANGULATED`` (0) or a ``SKIP_*`` code (see :data:`SKIP_REASONS`).
    repairs : ndarray, shape (P,), uint16
        Bitmask of ``REPAIR_*`` applied to a triangulated polygon (0 = none, and 0 for every
        skipped polygon, so report counts never mix repairs and skips).
    normal : ndarray, shape (P, 3), float64
        Unit Newell normal of the exterior ring as given (not re-oriented); zeros when the
        polygon has no defined normal (too few points, NaN, all collinear, zero area).
    area_m2 : ndarray, shape (P,), float64
        Area of the polygon in its Newell plane with holes removed, m²; 0 when skipped.
    """

    triangles: np.ndarray
    tri_polygon: np.ndarray
    status: np.ndarray
    repairs: np.ndarray
    normal: np.ndarray
    area_m2: np.ndarray

    def skip_counts(self) -> dict[str, int]:
        """Number of skipped polygons per skip name (only names that occur)."""
        codes, counts = np.unique(self.status[self.status != TRIANGULATED], return_counts=True)
        return {SKIP_REASONS[int(c)]: int(n) for c, n in zip(codes, counts)}

    def repair_counts(self) -> dict[str, int]:
        """Number of polygons per repair name (only names that occur)."""
        out = {}
        for bit, name in REPAIR_NAMES.items():
            n = int(np.count_nonzero(self.repairs & bit))
            if n:
                out[name] = n
        return out


# ---------------------------------------------------------------------------------------------
# Small geometric helpers (LLVM inlines them into the kernel).

#: The helpers are called only from the kernel, never from Python: without the CPython and
#: cfunc entry points each compiles faster (the sample city's triangulation 10.1 -> 8.5 CPU s
#: on first use), and the kernel runs the same.
_njit_helper = njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)


@_njit_helper
def _orient2(ax, ay, bx, by, cx, cy):
    """Twice the signed area of 2-D triangle (a, b, c); positive when counter-clockwise."""
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


@_njit_helper
def _xy3(x2, y2, a, b, c):
    """The 2-D coordinates of points a, b and c: ``(ax, ay, bx, by, cx, cy)``."""
    return x2[a], y2[a], x2[b], y2[b], x2[c], y2[c]


@_njit_helper
def _dist2_to_slot(loc, k, px, py, pz):
    """Squared distance from point p to scratch point ``loc[k]``."""
    dx = loc[k, 0] - px
    dy = loc[k, 1] - py
    dz = loc[k, 2] - pz
    return dx * dx + dy * dy + dz * dz


@_njit_helper
def _collinear3(ax, ay, az, bx, by, bz, cx, cy, cz, tol_m):
    """Whether b lies within ``tol_m`` of a line through a and c (3-D).

    The height is taken over the longest side, so a zero-width spike (c back on a) counts as
    collinear too: removing its tip is a sure repair.
    """
    ux = bx - ax
    uy = by - ay
    uz = bz - az
    wx = cx - ax
    wy = cy - ay
    wz = cz - az
    crx = uy * wz - uz * wy
    cry = uz * wx - ux * wz
    crz = ux * wy - uy * wx
    cross2 = crx * crx + cry * cry + crz * crz
    l_ab = ux * ux + uy * uy + uz * uz
    l_ac = wx * wx + wy * wy + wz * wz
    l_bc = (cx - bx) ** 2 + (cy - by) ** 2 + (cz - bz) ** 2
    longest2 = max(l_ab, max(l_ac, l_bc))
    # height over the longest side = |cross| / longest; compare squares to avoid sqrt.
    return cross2 <= tol_m * tol_m * longest2


@_njit_helper
def _collinear_slots(loc, i, j, k, tol_m):
    return _collinear3(loc[i, 0], loc[i, 1], loc[i, 2], loc[j, 0], loc[j, 1], loc[j, 2],
                       loc[k, 0], loc[k, 1], loc[k, 2], tol_m)


@_njit_helper
def _clean_ring(coords, a, b, ox, oy, oz, merge2_m2, col_tol_m, idx, loc, k0):
    """Append ring ``coords[a:b]`` to the scratch at ``k0``, cleaned; return (k_end, bits).

    Drops the closing point (not a repair when it equals the first point exactly, else the ring
    was unclosed), merges consecutive points within the merge distance and removes collinear
    points and spikes, cyclically. ``loc`` receives points relative to origin (ox, oy, oz) and
    ``idx`` their input rows.
    """
    bits = 0
    last = b - 1
    if b - a >= 2:
        if (coords[last, 0] == coords[a, 0] and coords[last, 1] == coords[a, 1]
                and coords[last, 2] == coords[a, 2]):
            last -= 1
        else:
            bits |= REPAIR_UNCLOSED_RING
    k = k0
    for i in range(a, last + 1):
        px = coords[i, 0] - ox
        py = coords[i, 1] - oy
        pz = coords[i, 2] - oz
        # Merge a point into the previous kept one when they are within the merge distance.
        if k > k0 and _dist2_to_slot(loc, k - 1, px, py, pz) <= merge2_m2:
            bits |= REPAIR_DUPLICATE_POINTS
            continue
        # Pop kept points that lie on the line from their predecessor to this point.
        while k - k0 >= 2 and _dist2_to_slot(loc, k - 1, px, py, pz) > merge2_m2 \
                and _collinear3(loc[k - 2, 0], loc[k - 2, 1], loc[k - 2, 2],
                                loc[k - 1, 0], loc[k - 1, 1], loc[k - 1, 2],
                                px, py, pz, col_tol_m):
            k -= 1
            bits |= REPAIR_COLLINEAR_POINTS
        # Removing a spike tip can bring this point next to its own duplicate.
        if k > k0 and _dist2_to_slot(loc, k - 1, px, py, pz) <= merge2_m2:
            bits |= REPAIR_DUPLICATE_POINTS
            continue
        loc[k, 0] = px
        loc[k, 1] = py
        loc[k, 2] = pz
        idx[k] = i
        k += 1
    # Apply the same rules across the seam between the last and the first point.
    while True:
        m = k - k0
        if m >= 2 and _dist2_to_slot(loc, k - 1, loc[k0, 0], loc[k0, 1], loc[k0, 2]) <= merge2_m2:
            k -= 1
            bits |= REPAIR_DUPLICATE_POINTS
        elif m >= 3 and _collinear_slots(loc, k - 2, k - 1, k0, col_tol_m):
            k -= 1
            bits |= REPAIR_COLLINEAR_POINTS
        elif m >= 3 and _collinear_slots(loc, k - 1, k0, k0 + 1, col_tol_m):
            for j in range(k0, k - 1):
                loc[j, 0] = loc[j + 1, 0]
                loc[j, 1] = loc[j + 1, 1]
                loc[j, 2] = loc[j + 1, 2]
                idx[j] = idx[j + 1]
            k -= 1
            bits |= REPAIR_COLLINEAR_POINTS
        else:
            break
    return k, bits


@_njit_helper
def _degenerate_reason(coords, a, b, merge_m, col_tol_m):
    """Classify a raw ring with no usable area: too few points, all collinear, or neither (0).

    Also returns the index of the farthest point from the first and of the point farthest from
    their line, which span a fallback plane when the Newell normal vanishes (a symmetric bow
    tie has zero Newell area).
    """
    ax = coords[a, 0]
    ay = coords[a, 1]
    az = coords[a, 2]
    far = a
    far_d2 = 0.0
    for i in range(a, b):
        d2 = (coords[i, 0] - ax) ** 2 + (coords[i, 1] - ay) ** 2 + (coords[i, 2] - az) ** 2
        if d2 > far_d2:
            far_d2 = d2
            far = i
    merge2 = merge_m * merge_m
    if far_d2 <= merge2:
        return SKIP_TOO_FEW_POINTS, a, a
    ex = coords[far, 0] - ax
    ey = coords[far, 1] - ay
    ez = coords[far, 2] - az
    length = np.sqrt(far_d2)
    third = False
    h_max = 0.0
    h_arg = a
    for i in range(a, b):
        px = coords[i, 0] - ax
        py = coords[i, 1] - ay
        pz = coords[i, 2] - az
        d2_a = px * px + py * py + pz * pz
        d2_f = (px - ex) ** 2 + (py - ey) ** 2 + (pz - ez) ** 2
        if d2_a > merge2 and d2_f > merge2:
            third = True
        crx = py * ez - pz * ey
        cry = pz * ex - px * ez
        crz = px * ey - py * ex
        h = np.sqrt(crx * crx + cry * cry + crz * crz) / length
        if h > h_max:
            h_max = h
            h_arg = i
    if not third:
        return SKIP_TOO_FEW_POINTS, far, h_arg
    if h_max <= col_tol_m:
        return SKIP_ALL_COLLINEAR, far, h_arg
    return 0, far, h_arg


@_njit_helper
def _basis(nx, ny, nz):
    """Orthonormal u, v with u × v = n for unit n (Duff et al. 2017, branchless)."""
    sign = 1.0 if nz >= 0.0 else -1.0
    a = -1.0 / (sign + nz)
    b = nx * ny * a
    return (1.0 + sign * nx * nx * a, sign * b, -sign * nx,
            b, sign + ny * ny * a, -ny)


@_njit_helper
def _project(loc, x2, y2, k0, k1, ux, uy, uz, vx, vy, vz):
    for j in range(k0, k1):
        x2[j] = loc[j, 0] * ux + loc[j, 1] * uy + loc[j, 2] * uz
        y2[j] = loc[j, 0] * vx + loc[j, 1] * vy + loc[j, 2] * vz


@_njit_helper
def _shoelace(x2, y2, k0, k1):
    """Signed area of the 2-D ring in slots k0..k1-1 (positive when counter-clockwise)."""
    s = 0.0
    # Relative to the ring's first point, so large offsets cancel before the products.
    x0 = x2[k0]
    y0 = y2[k0]
    for j in range(k0 + 1, k1 - 1):
        s += (x2[j] - x0) * (y2[j + 1] - y0) - (x2[j + 1] - x0) * (y2[j] - y0)
    return 0.5 * s


@_njit_helper
def _is_convex(x2, y2, m):
    """Whether the 2-D ring in slots 0..m-1 is strictly convex, counter-clockwise and simple.

    All left turns alone allow a ring that winds twice (a pentagram); with all left turns the
    edge direction turns monotonically by 2πk, and dx changes sign 2k times, so exactly two
    sign changes of dx prove k = 1.
    """
    changes = 0
    prev_sign = 0
    first_sign = 0
    for j in range(m):
        i = j - 1 if j > 0 else m - 1
        n = j + 1 if j + 1 < m else 0
        if _orient2(x2[i], y2[i], x2[j], y2[j], x2[n], y2[n]) <= 0.0:
            return False
        dx = x2[n] - x2[j]
        s = 1 if dx > 0.0 else (-1 if dx < 0.0 else 0)
        if s != 0:
            if prev_sign != 0 and s != prev_sign:
                changes += 1
            if first_sign == 0:
                first_sign = s
            prev_sign = s
    if prev_sign != first_sign:
        changes += 1
    return changes == 2


@_njit_helper
def _wedge_holds(ax, ay, px, py, bx, by, qx, qy, eps):
    """Side of point q against the wedge a → p → b (interior on the left).

    Returns 1 inside, -1 outside, 0 when q lies on one of the two rays (undecided).
    """
    o_in = _orient2(ax, ay, px, py, qx, qy)
    o_out = _orient2(px, py, bx, by, qx, qy)
    if abs(o_in) <= eps or abs(o_out) <= eps:
        return 0
    if _orient2(ax, ay, px, py, bx, by) > 0.0:
        return 1 if (o_in > 0.0 and o_out > 0.0) else -1
    return 1 if (o_in > 0.0 or o_out > 0.0) else -1


@_njit_helper
def _vertex_contact(x2, y2, v, v_prev, v_next, c, d, c_prev, eps):
    """Contact of vertex v (between v_prev and v_next) with edge c → d of another chain part.

    Returns 2 when the chain crosses the edge's chain at v, 1 for a touch (contact that is
    not a crossing, or undecidable within eps), 0 for no contact. When v coincides with c, the
    two corners (v_prev, v, v_next) and (c_prev, c, d) cross when c's neighbours lie on
    different sides of v's wedge.
    """
    vx, vy, cx, cy, dx, dy = _xy3(x2, y2, v, c, d)
    if vx == cx and vy == cy:
        side_prev = _wedge_holds(x2[v_prev], y2[v_prev], vx, vy, x2[v_next], y2[v_next],
                                 x2[c_prev], y2[c_prev], eps)
        side_next = _wedge_holds(x2[v_prev], y2[v_prev], vx, vy, x2[v_next], y2[v_next],
                                 dx, dy, eps)
        if side_prev * side_next < 0:
            return 2
        return 1
    if vx == dx and vy == dy:
        return 0  # handled as the start point of the next edge
    if abs(_orient2(cx, cy, dx, dy, vx, vy)) > eps:
        return 0
    # v on the line of c → d: a contact only when it lies between c and d.
    t = (vx - cx) * (dx - cx) + (vy - cy) * (dy - cy)
    if t <= 0.0 or t >= (dx - cx) ** 2 + (dy - cy) ** 2:
        return 0
    o_prev = _orient2(cx, cy, dx, dy, x2[v_prev], y2[v_prev])
    o_next = _orient2(cx, cy, dx, dy, x2[v_next], y2[v_next])
    if (o_prev > eps and o_next < -eps) or (o_prev < -eps and o_next > eps):
        return 2
    return 1


@_njit_helper
def _crossing_code(x2, y2, ring_start, n_rings, eps):
    """Exact O(n²) crossing test over all ring edges.

    Finds proper crossings of two edges and crossings through a vertex (a vertex on another
    edge, or two corners at one point, whose chains pass through each other). Returns
    (code, touched): code is 0 when nothing crosses, ``SKIP_SELF_INTERSECTING`` when the
    exterior crosses itself, ``SKIP_INVALID_HOLES`` when a crossing involves a hole; touched
    says whether two non-adjacent parts of the rings touch without crossing.
    """
    total = ring_start[n_rings]
    touched = False
    for r in range(n_rings):
        r0 = ring_start[r]
        r1 = ring_start[r + 1]
        for i in range(r0, r1):
            i1 = i + 1 if i + 1 < r1 else r0
            i_prev = i - 1 if i > r0 else r1 - 1
            ax = x2[i]
            ay = y2[i]
            bx = x2[i1]
            by = y2[i1]
            lo_x = min(ax, bx)
            hi_x = max(ax, bx)
            lo_y = min(ay, by)
            hi_y = max(ay, by)
            # Pair each edge only with later edges; skip the two neighbours in its own ring.
            s = r
            j0 = i + 1
            while j0 < total:
                while j0 >= ring_start[s + 1]:
                    s += 1
                s0 = ring_start[s]
                s1 = ring_start[s + 1]
                j1 = j0 + 1 if j0 + 1 < s1 else s0
                adjacent = s == r and (j0 == i1 or j1 == i)
                if not adjacent:
                    cx = x2[j0]
                    cy = y2[j0]
                    dx = x2[j1]
                    dy = y2[j1]
                    if not (max(cx, dx) < lo_x or min(cx, dx) > hi_x
                            or max(cy, dy) < lo_y or min(cy, dy) > hi_y):
                        contact = 0
                        o1 = _orient2(ax, ay, bx, by, cx, cy)
                        o2 = _orient2(ax, ay, bx, by, dx, dy)
                        o3 = _orient2(cx, cy, dx, dy, ax, ay)
                        o4 = _orient2(cx, cy, dx, dy, bx, by)
                        if ((o1 > eps and o2 > eps) or (o1 < -eps and o2 < -eps)
                                or (o3 > eps and o4 > eps) or (o3 < -eps and o4 < -eps)):
                            contact = 0  # both ends of one edge strictly on one side
                        elif (abs(o1) > eps and abs(o2) > eps
                              and abs(o3) > eps and abs(o4) > eps):
                            contact = 2  # proper crossing
                        else:
                            j_prev = j0 - 1 if j0 > s0 else s1 - 1
                            contact = max(
                                _vertex_contact(x2, y2, i, i_prev, i1, j0, j1, j_prev, eps),
                                _vertex_contact(x2, y2, j0, j_prev, j1, i, i1, i_prev, eps))
                        if contact == 2:
                            if r == 0 and s == 0:
                                return SKIP_SELF_INTERSECTING, touched
                            return SKIP_INVALID_HOLES, touched
                        if contact == 1:
                            touched = True
                j0 += 1
    return 0, touched


# ---------------------------------------------------------------------------------------------
# Hole bridging and ear clipping over a linked list of chain nodes (node → scratch slot).

@_njit_helper
def _in_sector(x2, y2, nslot, prv, nxt, q, px, py):
    """Whether point p lies in the interior wedge of the chain at node q (interior on the left)."""
    a = nslot[prv[q]]
    s = nslot[q]
    b = nslot[nxt[q]]
    left_in = _orient2(x2[a], y2[a], x2[s], y2[s], px, py) > 0.0
    left_out = _orient2(x2[s], y2[s], x2[b], y2[b], px, py) > 0.0
    if _orient2(x2[a], y2[a], x2[s], y2[s], x2[b], y2[b]) > 0.0:
        return left_in and left_out
    return left_in or left_out


@_njit_helper
def _pick_copy(x2, y2, nslot, prv, nxt, n_nodes, node, px, py):
    """Among the chain nodes at the same point as ``node``, the one whose wedge holds p.

    Bridges duplicate points, so a point can occur several times in the chain; a new bridge
    must leave from the occurrence that faces the hole.
    """
    tx = x2[nslot[node]]
    ty = y2[nslot[node]]
    for q in range(n_nodes):
        s = nslot[q]
        if x2[s] == tx and y2[s] == ty and _in_sector(x2, y2, nslot, prv, nxt, q, px, py):
            return q
    return node


@_njit_helper
def _find_bridge(x2, y2, nslot, prv, nxt, n_nodes, ms):
    """Chain node visible from hole point ``ms`` (its rightmost point), or -1 (Eberly §3)."""
    mx = x2[ms]
    my = y2[ms]
    best_x = np.inf
    best_a = -1
    # Cast a ray towards +x; the first edge it leaves the polygon through goes upwards
    # (interior on the left of every chain edge).
    for a in range(n_nodes):
        sa = nslot[a]
        sb = nslot[nxt[a]]
        ay = y2[sa]
        by = y2[sb]
        if ay < by and ay <= my <= by:
            ax = x2[sa]
            bx = x2[sb]
            x = ax + (my - ay) * (bx - ax) / (by - ay)
            if mx <= x < best_x:
                best_x = x
                best_a = a
    if best_a < 0:
        return -1
    sa = nslot[best_a]
    b_node = nxt[best_a]
    sb = nslot[b_node]
    p_node = best_a if x2[sa] >= x2[sb] else b_node
    sp = nslot[p_node]
    px = x2[sp]
    py = y2[sp]
    if px == best_x and py == my:
        return _pick_copy(x2, y2, nslot, prv, nxt, n_nodes, p_node, mx, my)
    # Points inside triangle (M, I, P) may hide P; the one at the smallest angle to the ray
    # (nearest on ties) is visible from M.
    ix = best_x
    iy = my
    sgn = 1.0 if _orient2(mx, my, ix, iy, px, py) > 0.0 else -1.0
    best_node = p_node
    best_dx = px - mx
    best_dy = abs(py - my)
    for q in range(n_nodes):
        s = nslot[q]
        qx = x2[s]
        qy = y2[s]
        if s == sp or (qx == px and qy == py):
            continue
        if (sgn * _orient2(mx, my, ix, iy, qx, qy) >= 0.0
                and sgn * _orient2(ix, iy, px, py, qx, qy) >= 0.0
                and sgn * _orient2(px, py, mx, my, qx, qy) >= 0.0):
            dx = qx - mx
            dy = abs(qy - my)
            if dx <= 0.0:
                if dy == 0.0:
                    # The hole touches the chain at M: a zero-length bridge is the best one.
                    return _pick_copy(x2, y2, nslot, prv, nxt, n_nodes, q, mx, my)
                continue
            # Compare angles dy/dx without division; nearest wins a tie.
            lhs = dy * best_dx
            rhs = best_dy * dx
            if lhs < rhs or (lhs == rhs and dx * dx + dy * dy < best_dx * best_dx + best_dy * best_dy):
                best_node = q
                best_dx = dx
                best_dy = dy
    return _pick_copy(x2, y2, nslot, prv, nxt, n_nodes, best_node, mx, my)


@_njit_helper
def _enters_corner(xx, xy, yx, yy, zx, zy, px, py):
    """Whether point p lies strictly inside the angle at corner x from x→y counter-clockwise
    to x→z of a counter-clockwise triangle (x, y, z)."""
    return _orient2(xx, xy, yx, yy, px, py) > 0.0 and _orient2(xx, xy, zx, zy, px, py) < 0.0


@_njit_helper
def _copy_enters(x2, y2, nslot, prv, nxt, q, xx, xy, yx, yy, zx, zy):
    """Whether the chain at node q (a copy of corner x) runs into the triangle's angle at x."""
    sp = nslot[prv[q]]
    sn = nslot[nxt[q]]
    return (_enters_corner(xx, xy, yx, yy, zx, zy, x2[sp], y2[sp])
            or _enters_corner(xx, xy, yx, yy, zx, zy, x2[sn], y2[sn]))


@_njit_helper
def _is_ear(x2, y2, nslot, prv, nxt, a, b, c):
    """Whether chain node b is a convex ear: no other chain point in or on triangle (a, b, c).

    A point at the same place as a corner (a bridge end, or a ring touching itself) blocks the
    ear only when the chain through it runs into the triangle.
    """
    sa = nslot[a]
    sb = nslot[b]
    sc = nslot[c]
    ax, ay, bx, by, cx, cy = _xy3(x2, y2, sa, sb, sc)
    if _orient2(ax, ay, bx, by, cx, cy) <= 0.0:
        return False
    lo_x = min(ax, min(bx, cx))
    hi_x = max(ax, max(bx, cx))
    lo_y = min(ay, min(by, cy))
    hi_y = max(ay, max(by, cy))
    q = nxt[c]
    while q != a:
        s = nslot[q]
        px = x2[s]
        py = y2[s]
        if lo_x <= px <= hi_x and lo_y <= py <= hi_y:
            if px == ax and py == ay:
                if _copy_enters(x2, y2, nslot, prv, nxt, q, ax, ay, bx, by, cx, cy):
                    return False
            elif px == bx and py == by:
                if _copy_enters(x2, y2, nslot, prv, nxt, q, bx, by, cx, cy, ax, ay):
                    return False
            elif px == cx and py == cy:
                if _copy_enters(x2, y2, nslot, prv, nxt, q, cx, cy, ax, ay, bx, by):
                    return False
            elif (_orient2(ax, ay, bx, by, px, py) >= 0.0
                    and _orient2(bx, by, cx, cy, px, py) >= 0.0
                    and _orient2(cx, cy, ax, ay, px, py) >= 0.0):
                return False
        q = nxt[q]
    return True


@_njit_helper
def _emit(x2, y2, loc, idx, sa, sb, sc, poly, tri_out, tri_poly, n_out):
    """Write triangle of slots (sa, sb, sc) unless two corners coincide; return (n_out, area)."""
    area = 0.5 * _orient2(x2[sa], y2[sa], x2[sb], y2[sb], x2[sc], y2[sc])
    same_ab = loc[sa, 0] == loc[sb, 0] and loc[sa, 1] == loc[sb, 1] and loc[sa, 2] == loc[sb, 2]
    same_bc = loc[sb, 0] == loc[sc, 0] and loc[sb, 1] == loc[sc, 1] and loc[sb, 2] == loc[sc, 2]
    same_ca = loc[sc, 0] == loc[sa, 0] and loc[sc, 1] == loc[sa, 1] and loc[sc, 2] == loc[sa, 2]
    if not (same_ab or same_bc or same_ca):
        tri_out[n_out, 0] = idx[sa]
        tri_out[n_out, 1] = idx[sb]
        tri_out[n_out, 2] = idx[sc]
        tri_poly[n_out] = poly
        n_out += 1
    return n_out, area


@_njit_helper
def _earclip_with_holes(x2, y2, loc, idx, ring_start, n_holes, nslot, nxt, prv, hole_key,
                        hole_slot, poly, tri_out, tri_poly, n_out):
    """Bridge the holes into the exterior and ear-clip the chain.

    Returns (n_out, sum of |triangle areas|, ok); ok is False when a hole has no bridge (it is
    not inside the exterior).
    """
    m_ext = ring_start[1]
    for j in range(m_ext):
        nslot[j] = j
        nxt[j] = j + 1
        prv[j] = j - 1
    nxt[m_ext - 1] = 0
    prv[0] = m_ext - 1
    n_nodes = m_ext
    # Order holes by decreasing maximum x (insertion sort: deterministic, holes are few).
    for h in range(n_holes):
        h0 = ring_start[h + 1]
        h1 = ring_start[h + 2]
        best = h0
        for j in range(h0 + 1, h1):
            if x2[j] > x2[best]:
                best = j
        hole_key[h] = h
        hole_slot[h] = best
    for h in range(1, n_holes):
        key = hole_key[h]
        slot = hole_slot[h]
        g = h - 1
        while g >= 0 and x2[hole_slot[g]] < x2[slot]:
            hole_key[g + 1] = hole_key[g]
            hole_slot[g + 1] = hole_slot[g]
            g -= 1
        hole_key[g + 1] = key
        hole_slot[g + 1] = slot
    # Splice every hole into the chain: P → M … (hole) … M' → P' → next(P).
    for t in range(n_holes):
        h = hole_key[t]
        ms = hole_slot[t]
        bridge = _find_bridge(x2, y2, nslot, prv, nxt, n_nodes, ms)
        if bridge < 0:
            return n_out, 0.0, False
        h0 = ring_start[h + 1]
        h1 = ring_start[h + 2]
        cnt = h1 - h0
        first_new = n_nodes
        for j in range(cnt + 1):
            nslot[n_nodes] = h0 + (ms - h0 + j) % cnt
            n_nodes += 1
        nslot[n_nodes] = nslot[bridge]
        n_nodes += 1
        after = nxt[bridge]
        for q in range(first_new, n_nodes - 1):
            nxt[q] = q + 1
            prv[q + 1] = q
        nxt[bridge] = first_new
        prv[first_new] = bridge
        nxt[n_nodes - 1] = after
        prv[after] = n_nodes - 1
    # Clip ears until a triangle is left.
    abs_sum = 0.0
    count = n_nodes
    cur = np.int64(0)  # not a literal: one compile of _is_ear
    misses = 0
    while count > 3:
        a = prv[cur]
        c = nxt[cur]
        sa = nslot[a]
        sb = nslot[cur]
        sc = nslot[c]
        # A point repeated at once, or the tip of an out-and-back spike, encloses nothing:
        # drop it first (bridges and rings touching themselves leave such pieces behind).
        spike = (x2[sa] == x2[sc] and y2[sa] == y2[sc]) or (x2[sb] == x2[sc] and y2[sb] == y2[sc])
        if spike or _is_ear(x2, y2, nslot, prv, nxt, a, cur, c):
            clip = cur
        else:
            cur = c
            misses += 1
            if misses < count:
                continue
            # No ear in a whole round (only on nearly degenerate or non-simple chains): clip
            # the most convex corner anyway; the area check judges the result.
            clip = cur
            best_o = -np.inf
            q = cur
            for _ in range(count):
                sa = nslot[prv[q]]
                sb = nslot[q]
                sc = nslot[nxt[q]]
                o = _orient2(x2[sa], y2[sa], x2[sb], y2[sb], x2[sc], y2[sc])
                if o > best_o:
                    best_o = o
                    clip = q
                q = nxt[q]
        # Clip the corner: emit its triangle and unlink it from the chain.
        a = prv[clip]
        c = nxt[clip]
        n_out, area = _emit(x2, y2, loc, idx, nslot[a], nslot[clip], nslot[c], poly,
                            tri_out, tri_poly, n_out)
        abs_sum += abs(area)
        nxt[a] = c
        prv[c] = a
        count -= 1
        cur = c
        misses = 0
    n_out, area = _emit(x2, y2, loc, idx, nslot[prv[cur]], nslot[cur], nslot[nxt[cur]], poly,
                        tri_out, tri_poly, n_out)
    abs_sum += abs(area)
    return n_out, abs_sum, True


# ---------------------------------------------------------------------------------------------
# The batch kernel.

@njit(cache=True, nogil=True)
def _triangulate_range(coords, ring_offsets, polygon_ring_offsets, p_begin, p_end, out_begin,
                       merge_distance_m, collinear_rel_tol, area_rel_tol, min_rel_area,
                       nonplanar_rel_tol, tri_out, tri_poly, status, repairs, normal, area_m2):
    """Triangulate polygons p_begin … p_end - 1, their triangles written from row out_begin
    on; fill the per-polygon arrays, return the row after the last triangle."""
    # Size the scratch for the largest polygon: its points plus two bridge copies per hole.
    cap = 3
    max_rings = 1
    for p in range(p_begin, p_end):
        r0 = polygon_ring_offsets[p]
        r1 = polygon_ring_offsets[p + 1]
        if r1 > r0:
            n_pts = ring_offsets[r1] - ring_offsets[r0]
            cap = max(cap, n_pts + 2 * (r1 - r0) + 3)
            max_rings = max(max_rings, r1 - r0)
    idx = np.empty(cap, np.int64)
    loc = np.empty((cap, 3), np.float64)
    x2 = np.empty(cap, np.float64)
    y2 = np.empty(cap, np.float64)
    nslot = np.empty(cap, np.int64)
    nxt = np.empty(cap, np.int64)
    prv = np.empty(cap, np.int64)
    ring_start = np.empty(max_rings + 1, np.int64)
    hole_key = np.empty(max_rings, np.int64)
    hole_slot = np.empty(max_rings, np.int64)
    merge2_m2 = merge_distance_m * merge_distance_m
    n_out = out_begin
    for p in range(p_begin, p_end):
        status[p] = TRIANGULATED
        repairs[p] = 0
        normal[p, 0] = 0.0
        normal[p, 1] = 0.0
        normal[p, 2] = 0.0
        area_m2[p] = 0.0
        r0 = polygon_ring_offsets[p]
        r1 = polygon_ring_offsets[p + 1]
        if r1 <= r0 or ring_offsets[r0 + 1] <= ring_offsets[r0]:
            status[p] = SKIP_TOO_FEW_POINTS
            continue
        a = ring_offsets[r0]
        b = ring_offsets[r0 + 1]
        # Refuse any non-finite coordinate in any ring of the polygon.
        finite = True
        for i in range(ring_offsets[r0], ring_offsets[r1]):
            if not (np.isfinite(coords[i, 0]) and np.isfinite(coords[i, 1])
                    and np.isfinite(coords[i, 2])):
                finite = False
                break
        if not finite:
            status[p] = SKIP_NAN_COORDINATES
            continue
        # Work relative to the first exterior point; size = bounding-box diagonal.
        ox = coords[a, 0]
        oy = coords[a, 1]
        oz = coords[a, 2]
        lo0 = hi0 = lo1 = hi1 = lo2 = hi2 = 0.0
        for i in range(a + 1, b):
            d0 = coords[i, 0] - ox
            d1 = coords[i, 1] - oy
            d2 = coords[i, 2] - oz
            lo0 = min(lo0, d0)
            hi0 = max(hi0, d0)
            lo1 = min(lo1, d1)
            hi1 = max(hi1, d1)
            lo2 = min(lo2, d2)
            hi2 = max(hi2, d2)
        size_m = np.sqrt((hi0 - lo0) ** 2 + (hi1 - lo1) ** 2 + (hi2 - lo2) ** 2)
        col_tol_m = collinear_rel_tol * size_m
        min_area_m2 = min_rel_area * size_m * size_m
        # np.int64, not a literal 0: one compile of _clean_ring and its callees for both calls
        m_ext, bits = _clean_ring(coords, a, b, ox, oy, oz, merge2_m2, col_tol_m, idx, loc,
                                  np.int64(0))
        # Newell normal of the cleaned exterior (equal to the raw ring's: merged and collinear
        # points add nothing), as the sum of cross products of consecutive local points.
        nx = 0.0
        ny = 0.0
        nz = 0.0
        for j in range(m_ext):
            j1 = j + 1 if j + 1 < m_ext else 0
            nx += loc[j, 1] * loc[j1, 2] - loc[j, 2] * loc[j1, 1]
            ny += loc[j, 2] * loc[j1, 0] - loc[j, 0] * loc[j1, 2]
            nz += loc[j, 0] * loc[j1, 1] - loc[j, 1] * loc[j1, 0]
        n_len = np.sqrt(nx * nx + ny * ny + nz * nz)
        if m_ext < 3 or 0.5 * n_len <= min_area_m2:
            reason, far, third = _degenerate_reason(coords, a, b, merge_distance_m, col_tol_m)
            if reason == 0:
                reason = SKIP_ZERO_AREA
                if 3 < m_ext <= SEGMENT_TEST_MAX_POINTS:
                    # Zero net area from lobes of opposite turn (a bow tie): find the crossing
                    # in the plane of three spanning points.
                    ex = coords[far, 0] - ox
                    ey = coords[far, 1] - oy
                    ez = coords[far, 2] - oz
                    tx = coords[third, 0] - ox
                    ty = coords[third, 1] - oy
                    tz = coords[third, 2] - oz
                    fx = ey * tz - ez * ty
                    fy = ez * tx - ex * tz
                    fz = ex * ty - ey * tx
                    f_len = np.sqrt(fx * fx + fy * fy + fz * fz)
                    ux, uy, uz, vx, vy, vz = _basis(fx / f_len, fy / f_len, fz / f_len)
                    _project(loc, x2, y2, np.int64(0), m_ext, ux, uy, uz, vx, vy, vz)
                    ring_start[0] = 0
                    ring_start[1] = m_ext
                    code, _ = _crossing_code(x2, y2, ring_start, np.int64(1), col_tol_m * size_m)
                    if code != 0:
                        reason = SKIP_SELF_INTERSECTING
            if n_len > 0.0 and reason != SKIP_ALL_COLLINEAR and reason != SKIP_TOO_FEW_POINTS:
                normal[p, 0] = nx / n_len
                normal[p, 1] = ny / n_len
                normal[p, 2] = nz / n_len
            status[p] = reason
            continue
        nx /= n_len
        ny /= n_len
        nz /= n_len
        normal[p, 0] = nx
        normal[p, 1] = ny
        normal[p, 2] = nz
        ux, uy, uz, vx, vy, vz = _basis(nx, ny, nz)
        _project(loc, x2, y2, np.int64(0), m_ext, ux, uy, uz, vx, vy, vz)
        ext_area_m2 = _shoelace(x2, y2, np.int64(0), m_ext)
        # Clean, project and orient the holes clockwise; drop the degenerate ones.
        ring_start[0] = 0
        ring_start[1] = m_ext
        k = m_ext
        n_holes = np.int64(0)  # not a literal: one compile of _earclip_with_holes
        holes_area_m2 = 0.0
        for r in range(r0 + 1, r1):
            k1, hole_bits = _clean_ring(coords, ring_offsets[r], ring_offsets[r + 1], ox, oy, oz,
                                        merge2_m2, col_tol_m, idx, loc, k)
            bits |= hole_bits
            if k1 - k < 3:
                bits |= REPAIR_HOLE_DROPPED
                continue
            _project(loc, x2, y2, k, k1, ux, uy, uz, vx, vy, vz)
            hole_area_m2 = _shoelace(x2, y2, k, k1)
            if abs(hole_area_m2) <= min_area_m2:
                bits |= REPAIR_HOLE_DROPPED
                continue
            if hole_area_m2 > 0.0:
                lo = k
                hi = k1 - 1
                while lo < hi:
                    for c in range(3):
                        tmp = loc[lo, c]
                        loc[lo, c] = loc[hi, c]
                        loc[hi, c] = tmp
                    ti = idx[lo]
                    idx[lo] = idx[hi]
                    idx[hi] = ti
                    tmp = x2[lo]
                    x2[lo] = x2[hi]
                    x2[hi] = tmp
                    tmp = y2[lo]
                    y2[lo] = y2[hi]
                    y2[hi] = tmp
                    lo += 1
                    hi -= 1
            holes_area_m2 += abs(hole_area_m2)
            n_holes += 1
            ring_start[n_holes + 1] = k1
            k = k1
        total = k
        # Flag points off the Newell plane (through the exterior's centroid).
        cx = 0.0
        cy = 0.0
        cz = 0.0
        for j in range(m_ext):
            cx += loc[j, 0]
            cy += loc[j, 1]
            cz += loc[j, 2]
        cx /= m_ext
        cy /= m_ext
        cz /= m_ext
        off_max = 0.0
        for j in range(total):
            off = abs((loc[j, 0] - cx) * nx + (loc[j, 1] - cy) * ny + (loc[j, 2] - cz) * nz)
            off_max = max(off_max, off)
        if off_max > nonplanar_rel_tol * size_m:
            bits |= REPAIR_NONPLANAR
        expected_m2 = ext_area_m2 - holes_area_m2
        if expected_m2 <= min_area_m2:
            status[p] = SKIP_INVALID_HOLES if n_holes > 0 else SKIP_ZERO_AREA
            continue
        # Fast paths: a triangle, a convex ring without holes (fan from the first point).
        if n_holes == 0 and (m_ext == 3 or _is_convex(x2, y2, m_ext)):
            for j in range(1, m_ext - 1):
                tri_out[n_out, 0] = idx[0]
                tri_out[n_out, 1] = idx[j]
                tri_out[n_out, 2] = idx[j + 1]
                tri_poly[n_out] = p
                n_out += 1
            area_m2[p] = expected_m2
            repairs[p] = bits
            continue
        # General path: exact crossing test when small, then bridges, ear clipping, area check.
        proven_simple = False
        if total <= SEGMENT_TEST_MAX_POINTS:
            code, touched = _crossing_code(x2, y2, ring_start, n_holes + 1, col_tol_m * size_m)
            if code != 0:
                status[p] = code
                continue
            proven_simple = not touched
        first_tri = n_out
        n_out, abs_sum, ok = _earclip_with_holes(x2, y2, loc, idx, ring_start, n_holes, nslot,
                                                 nxt, prv, hole_key, hole_slot, p, tri_out,
                                                 tri_poly, n_out)
        if not ok or n_out == first_tri or abs(abs_sum - expected_m2) > area_rel_tol * expected_m2:
            n_out = first_tri
            if n_holes > 0:
                status[p] = SKIP_INVALID_HOLES
            elif proven_simple:
                status[p] = SKIP_TRIANGULATION_FAILED
            else:
                status[p] = SKIP_SELF_INTERSECTING
            continue
        area_m2[p] = expected_m2
        repairs[p] = bits
    return n_out


@njit(cache=True)
def _chunk_bounds(ring_offsets, polygon_ring_offsets, n_chunks):
    """Chunks of consecutive polygons with about equal point counts, and the row each chunk's
    triangles may start at: the sum of the earlier polygons' bounds, n - 2 + 2h triangles for
    n points and h holes (ear clipping after the holes' bridges; cleaning only drops points)."""
    n_poly = polygon_ring_offsets.shape[0] - 1
    first_point = ring_offsets[polygon_ring_offsets[0]]
    points = ring_offsets[polygon_ring_offsets[n_poly]] - first_point
    poly_start = np.empty(n_chunks + 1, np.int64)
    out_start = np.empty(n_chunks + 1, np.int64)
    poly_start[0] = 0
    out_start[0] = 0
    c = 1
    rows = 0
    for p in range(n_poly):
        r0 = polygon_ring_offsets[p]
        r1 = polygon_ring_offsets[p + 1]
        if r1 > r0:
            rows += max(0, ring_offsets[r1] - ring_offsets[r0] + 2 * (r1 - r0 - 1) - 2)
        while c < n_chunks and (ring_offsets[r1] - first_point) * n_chunks >= c * points:
            poly_start[c] = p + 1
            out_start[c] = rows
            c += 1
    while c <= n_chunks:
        poly_start[c] = n_poly
        out_start[c] = rows
        c += 1
    return poly_start, out_start


def _triangulate_parallel(inputs, poly_start, out_start, tol, outputs):
    """:func:`_triangulate_range` over chunks of polygons on the thread pool
    (:func:`cityshade.runtime.threadpool.run_chunks`: a serial ``nogil`` kernel compiles in a
    fraction of a ``prange`` one's time and serves the one-thread call too), each chunk's
    triangles written in its own rows, then moved down behind the previous chunk's: the same
    rows in the same order. ``inputs``, ``tol`` and ``outputs`` are the kernel's arguments
    before, between and after the chunk's bounds. Returns the triangle count, or -1 when a
    chunk's bound did not hold (never seen: the caller then redoes it serially)."""
    from cityshade.runtime.threadpool import run_chunks

    n_chunks = poly_start.shape[0] - 1
    out_end = np.empty(n_chunks, np.int64)
    tri_out, tri_poly = outputs[:2]

    def chunks(c0, c1):
        for c in range(c0, c1):
            out_end[c] = _triangulate_range(*inputs, poly_start[c], poly_start[c + 1],
                                            out_start[c], *tol, *outputs)

    run_chunks(chunks, n_chunks, 1)
    if np.any(out_end > out_start[1:]):
        return -1
    n_out = int(out_end[0])
    for c in range(1, n_chunks):  # forward moves: numpy copies overlapping rows correctly
        rows = int(out_end[c] - out_start[c])
        tri_out[n_out:n_out + rows] = tri_out[out_start[c]:out_end[c]]
        tri_poly[n_out:n_out + rows] = tri_poly[out_start[c]:out_end[c]]
        n_out += rows
    return n_out


#: Polygons below which one thread triangulates (the threads' start costs more than it saves).
PARALLEL_MIN_POLYGONS = 20_000

#: Points a process triangulates with the kernel's Python source while the kernel is neither
#: compiled nor cached (:mod:`cityshade.runtime.interpret`): about 25 µs a point interpreted
#: (the sample city's 3,662 points: 0.09 s) against some 8 CPU s of compiling on first use.
INTERPRET_POINTS = 20_000
_INTERPRET = InterpretBudget(INTERPRET_POINTS, _triangulate_range)


def _as_offsets(name: str, array, upper: int) -> np.ndarray:
    """Validate an offsets array: 1-D integers, non-decreasing, within [0, upper]."""
    arr = np.asarray(array)
    if arr.ndim != 1 or arr.shape[0] < 1:
        raise TriangulationInputError(f"{name} must be a 1-D array with at least one entry, "
                                      f"got shape {arr.shape}")
    if arr.dtype.kind not in "iu":
        raise TriangulationInputError(f"{name} must hold integers, got dtype {arr.dtype}")
    arr = arr.astype(np.int64, copy=False)
    if arr[0] < 0 or arr[-1] > upper:
        raise TriangulationInputError(f"{name} must lie within [0, {upper}], "
                                      f"got {arr[0]} … {arr[-1]}")
    if arr.shape[0] > 1 and np.any(arr[1:] < arr[:-1]):
        raise TriangulationInputError(f"{name} must be non-decreasing")
    return arr


def triangulate_polygons(coords: np.ndarray, ring_offsets: np.ndarray,
                         polygon_ring_offsets: np.ndarray, *, merge_distance_m: float = 1e-6,
                         collinear_rel_tol: float = 1e-9, area_rel_tol: float = 1e-6,
                         min_rel_area: float = 1e-12, nonplanar_rel_tol: float = 1e-3
                         ) -> TriangulationResult:
    """Triangulate a batch of polygons with holes, repairing what is sure and skipping the rest.

    Parameters
    ----------
    coords : ndarray, shape (N, 3), float64
        Points in metres, any magnitude; may be read-only (memory-mapped).
    ring_offsets : ndarray, shape (R + 1,), int64
        Ring r is ``coords[ring_offsets[r]:ring_offsets[r + 1]]`` exactly as written in the GML
        (usually closed with a last point equal to the first; unclosed rings are closed).
    polygon_ring_offsets : ndarray, shape (P + 1,), int64
        Polygon p has rings ``polygon_ring_offsets[p] … polygon_ring_offsets[p + 1] - 1``; the
        first is the exterior, the others are holes.
    merge_distance_m : float
        Consecutive points closer than this (metres) are merged.
    collinear_rel_tol : float
        A point within this fraction of the polygon size (bounding-box diagonal of the exterior)
        from the line of its neighbours is removed; also the zero tolerance of the crossing test.
    area_rel_tol : float
        The summed |triangle areas| must equal |exterior| − Σ|holes| to this relative tolerance.
    min_rel_area : float
        Polygons (and holes) with area below this × size² have zero area.
    nonplanar_rel_tol : float
        Points farther than this × size from the Newell plane flag ``REPAIR_NONPLANAR``.

    Returns
    -------
    TriangulationResult
        Triangles (row indices into ``coords``, wound like the exterior ring, grouped by
        polygon), and per polygon the status, repair bits, unit Newell normal and area.

    Raises
    ------
    TriangulationInputError
        When the arrays do not describe polygons (shape, dtype, offsets out of range or
        decreasing) or a tolerance is negative or not finite. Bad geometry never raises.
    """
    coords = np.asarray(coords)
    if coords.ndim != 2 or coords.shape[1] != 3:
        raise TriangulationInputError(f"coords must have shape (N, 3), got {coords.shape}")
    if coords.dtype.kind not in "fiu":
        raise TriangulationInputError(f"coords must be real numbers, got dtype {coords.dtype}")
    coords = coords.astype(np.float64, copy=False)
    ring_offsets = _as_offsets("ring_offsets", ring_offsets, coords.shape[0])
    polygon_ring_offsets = _as_offsets("polygon_ring_offsets", polygon_ring_offsets,
                                       ring_offsets.shape[0] - 1)
    tolerances = {"merge_distance_m": merge_distance_m, "collinear_rel_tol": collinear_rel_tol,
                  "area_rel_tol": area_rel_tol, "min_rel_area": min_rel_area,
                  "nonplanar_rel_tol": nonplanar_rel_tol}
    for name, value in tolerances.items():
        if not (np.isfinite(value) and value >= 0):
            raise TriangulationInputError(f"{name} must be a finite number >= 0, not {value}")
    n_poly = polygon_ring_offsets.shape[0] - 1
    # Upper bound of the triangle count: a polygon with n points and h holes gives n - 2 + 2h.
    used_points = int(ring_offsets[-1] - ring_offsets[0])
    used_rings = ring_offsets.shape[0] - 1
    capacity = used_points + 2 * used_rings + 1
    # np.empty pages are only committed when written, so the loose bound costs no memory.
    tri_out = np.empty((capacity, 3), np.int64)
    tri_poly = np.empty(capacity, np.int64)
    status = np.empty(n_poly, np.uint8)
    repairs = np.empty(n_poly, np.uint16)
    normal = np.empty((n_poly, 3), np.float64)
    area = np.empty(n_poly, np.float64)
    tol = (float(merge_distance_m), float(collinear_rel_tol), float(area_rel_tol),
           float(min_rel_area), float(nonplanar_rel_tol))
    n_tri = -1
    threads = numba.get_num_threads()
    if threads > 1 and n_poly >= PARALLEL_MIN_POLYGONS:
        # Eight chunks a thread: the polygons' costs vary, and a thread that is done early
        # takes the next chunk.
        poly_start, out_start = _chunk_bounds(ring_offsets, polygon_ring_offsets, 8 * threads)
        n_tri = _triangulate_parallel((coords, ring_offsets, polygon_ring_offsets), poly_start,
                                      out_start, tol, (tri_out, tri_poly, status, repairs,
                                                       normal, area))
    if n_tri < 0:
        kernel = _triangulate_range
        if _INTERPRET.take(used_points):
            kernel = python_twin(_triangulate_range)
        n_tri = kernel(coords, ring_offsets, polygon_ring_offsets, 0, n_poly, 0, *tol, tri_out,
                       tri_poly, status, repairs, normal, area)
    # Views, not copies: the rows past n_tri were never written, so they hold no memory, and a
    # copy would double the largest arrays of the build at its peak.
    return TriangulationResult(triangles=tri_out[:n_tri], tri_polygon=tri_poly[:n_tri],
                               status=status,
                               repairs=repairs, normal=normal, area_m2=area)
