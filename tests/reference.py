"""Slow, obvious twins of cityshade's fast paths (DESIGN §13.2).

Each function here does the same job as a fast kernel of the package in the plainest way we can
write it, so that a test can check that both agree. Speed does not matter here; clarity does.
"""
from __future__ import annotations

import numpy as np


# --- geometry.triangulate ---------------------------------------------------------------------

def _ref_area2(p, q, r):
    """Twice the signed area of 2-D triangle (p, q, r)."""
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def _ref_segments_cross(a, b, c, d):
    """Whether segments ab and cd cross at a point interior to both (plain sign test)."""
    return (_ref_area2(a, b, c) * _ref_area2(a, b, d) < 0
            and _ref_area2(c, d, a) * _ref_area2(c, d, b) < 0)


def reference_triangulate_polygon(rings):
    """Triangulate one clean polygon with holes by plain O(n³) ear clipping.

    Twin of :func:`cityshade.geometry.triangulate.triangulate_polygons` for valid polygons
    (no repairs, no skips): it shares no code and uses another bridge rule (the nearest
    chain vertex whose bridge crosses no edge).

    Parameters
    ----------
    rings : list of array_like, each (n_i, 3)
        Exterior ring first, then holes, in metres; a closing point equal to the first is
        ignored. Points must be distinct and the polygon valid.

    Returns
    -------
    ndarray, shape (T, 3), int64
        Row indices into ``np.concatenate(rings)``, counter-clockwise seen against the Newell
        normal of the exterior ring.
    """
    rings = [np.asarray(r, dtype=np.float64) for r in rings]
    all_points = np.concatenate(rings)
    ring_rows = []
    base = 0
    for ring in rings:
        n = len(ring)
        if n > 1 and np.array_equal(ring[0], ring[-1]):
            n -= 1
        ring_rows.append(list(range(base, base + n)))
        base += len(ring)
    origin = all_points[ring_rows[0][0]]
    # Newell normal of the exterior, then any orthonormal u, v with u × v = normal.
    normal = np.zeros(3)
    ext = [all_points[i] - origin for i in ring_rows[0]]
    for i in range(len(ext)):
        normal += np.cross(ext[i], ext[(i + 1) % len(ext)])
    normal /= np.linalg.norm(normal)
    helper = np.eye(3)[np.argmin(np.abs(normal))]
    u = np.cross(helper, normal)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    flat = {row: ((all_points[row] - origin) @ u, (all_points[row] - origin) @ v)
            for rows in ring_rows for row in rows}

    def ring_area2(rows):
        return sum(flat[rows[i]][0] * flat[rows[(i + 1) % len(rows)]][1]
                   - flat[rows[(i + 1) % len(rows)]][0] * flat[rows[i]][1]
                   for i in range(len(rows)))

    holes = []
    for rows in ring_rows[1:]:
        holes.append(rows[::-1] if ring_area2(rows) > 0 else rows)  # holes clockwise
    holes.sort(key=lambda rows: -max(flat[r][0] for r in rows))
    chain = list(ring_rows[0])
    for k, hole in enumerate(holes):
        m_pos = max(range(len(hole)), key=lambda i: flat[hole[i]][0])
        m = flat[hole[m_pos]]
        edges = [(chain[i], chain[(i + 1) % len(chain)]) for i in range(len(chain))]
        for other in holes[k:]:
            edges += [(other[i], other[(i + 1) % len(other)]) for i in range(len(other))]
        order = sorted(range(len(chain)),
                       key=lambda i: (flat[chain[i]][0] - m[0]) ** 2 + (flat[chain[i]][1] - m[1]) ** 2)
        for i in order:
            w = flat[chain[i]]
            prev_pt = flat[chain[i - 1]]
            next_pt = flat[chain[(i + 1) % len(chain)]]
            # The bridge must leave the chain vertex into the polygon's interior …
            if _ref_area2(prev_pt, w, next_pt) > 0:
                inside = _ref_area2(prev_pt, w, m) > 0 and _ref_area2(w, next_pt, m) > 0
            else:
                inside = _ref_area2(prev_pt, w, m) > 0 or _ref_area2(w, next_pt, m) > 0
            # … and cross no edge of the chain or of the holes.
            if inside and not any(_ref_segments_cross(m, w, flat[e0], flat[e1])
                                  for e0, e1 in edges):
                break
        else:
            raise ValueError("no bridge for a hole: the polygon is not valid")
        chain = chain[:i + 1] + hole[m_pos:] + hole[:m_pos + 1] + chain[i:]
    triangles = []
    while len(chain) > 3:
        for i in range(len(chain)):
            a, b, c = chain[i - 1], chain[i], chain[(i + 1) % len(chain)]
            pa, pb, pc = flat[a], flat[b], flat[c]
            if _ref_area2(pa, pb, pc) <= 0:
                continue
            corners = {pa, pb, pc}
            blocked = any(flat[q] not in corners
                          and _ref_area2(pa, pb, flat[q]) >= 0
                          and _ref_area2(pb, pc, flat[q]) >= 0
                          and _ref_area2(pc, pa, flat[q]) >= 0 for q in chain)
            if not blocked:
                triangles.append((a, b, c))
                del chain[i]
                break
        else:
            raise ValueError("no ear found: the polygon is not valid")
    triangles.append(tuple(chain))
    # Bridge copies give triangles with a repeated point; they have no area.
    triangles = [t for t in triangles if len({flat[r] for r in t}) == 3]
    return np.array(triangles, dtype=np.int64).reshape(-1, 3)


# --- ray tracing (twins of cityshade.trace and cityshade.accel) ---------------------------------

def reference_ray_hits(vertices, triangles, t_begin_days, t_end_days, origin, direction,
                       t_days=0.0, tmax=np.inf):
    """All hits of one ray, by Moller-Trumbore in float64 over every triangle (no tree).

    Returns (t (H,), triangle ids (H,)) of the triangles valid at ``t_days``
    (``begin <= t_days < end``) hit at ``0 <= t <= tmax``; edges count as inside.
    """
    v = np.asarray(vertices, dtype=np.float64)[np.asarray(triangles)]
    o = np.asarray(origin, dtype=np.float64)
    d = np.asarray(direction, dtype=np.float64)
    e1 = v[:, 1] - v[:, 0]
    e2 = v[:, 2] - v[:, 0]
    p = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, p)
    s = o - v[:, 0]
    q = np.cross(s, e1)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.einsum("ij,ij->i", s, p) / det
        w = (q @ d) / det
        t = np.einsum("ij,ij->i", e2, q) / det
        valid = (np.asarray(t_begin_days) <= t_days) & (t_days < np.asarray(t_end_days))
        ok = (det != 0) & (u >= 0) & (w >= 0) & (u + w <= 1) & (t >= 0) & (t <= tmax) & valid
    ids = np.flatnonzero(ok)
    return t[ids], ids


def reference_closest_hit(vertices, triangles, t_begin_days, t_end_days, origin, direction,
                          t_days=0.0, tmax=np.inf):
    """(t, triangle id) of the nearest hit of one ray by brute force; (inf, -1) on a miss."""
    t, ids = reference_ray_hits(vertices, triangles, t_begin_days, t_end_days, origin,
                                direction, t_days, tmax)
    if t.size == 0:
        return np.inf, -1
    i = int(np.argmin(t))
    return float(t[i]), int(ids[i])


def reference_kdtree_leaves_at_point(tree, point, t_days, tol_m=0.0):
    """Leaf indices of a KdTree whose closed 4-D cell contains (point, t_days), walking the
    unpacked nodes one at a time (a point within ``tol_m`` of a split plane goes to both
    sides)."""
    axis, child, second = tree.unpack()
    leaves = []
    todo = [0]
    while todo:
        node = todo.pop()
        if axis[node] == 4:
            leaves.append(node)
            continue
        s = second[node]
        if axis[node] == 3:
            todo.append(node + 1 if t_days < s else int(child[node]))
            continue
        c = point[axis[node]]
        if c <= s + tol_m:
            todo.append(node + 1)
        if c >= s - tol_m:
            todo.append(int(child[node]))
    return leaves


def reference_kdtree_triangles_at_time(tree, t_days):
    """Set of triangle ids in the leaves reachable at city time ``t_days`` (all space)."""
    axis, child, second = tree.unpack()
    found = set()
    todo = [0]
    while todo:
        node = todo.pop()
        if axis[node] == 4:
            first = int(second[node])
            found.update(int(i) for i in tree.prim_indices[first:first + int(child[node])])
        elif axis[node] == 3:
            todo.append(node + 1 if t_days < second[node] else int(child[node]))
        else:
            todo.extend([node + 1, int(child[node])])
    return found


# --- textures (mip pyramid, trilinear sampling) -----------------------------------------------

def reference_mip_reduce(image):
    """Next mip level of ``image`` (h, w, c) by exact area averaging, done by upsampling.

    Twin of ``cityshade.frame.textures._reduce_level``. Each source texel is repeated ``nw`` times
    along x and ``nh`` times along y; then every output texel covers a whole block of
    ``w × h`` upsampled texels, and its value is that block's plain mean.
    """
    image = np.asarray(image, dtype=np.float64)
    h, w, c = image.shape
    nh, nw = max(1, h // 2), max(1, w // 2)
    big = np.repeat(np.repeat(image, nh, axis=0), nw, axis=1)  # (h*nh, w*nw, c)
    return big.reshape(nh, h, nw, w, c).mean(axis=(1, 3))


def reference_sample_texture(levels, wrap_mode, border_rgba, u, v, lod):
    """One trilinear texture sample, written out texel by texel.

    Twin of ``cityshade.frame.textures.sample_trilinear`` for a single texture.

    Parameters
    ----------
    levels : list of ndarray (h_l, w_l, 4)
        Mip pyramid, finest first, row 0 at the top.
    wrap_mode : str
        "none", "wrap", "mirror", "clamp" or "border".
    border_rgba : sequence of 4 float
    u, v, lod : float
        v = 0 is the BOTTOM of the image; lod 0 is the finest level.
    """
    if wrap_mode == "none" and not (-1e-5 <= u <= 1 + 1e-5 and -1e-5 <= v <= 1 + 1e-5):
        return np.zeros(4)
    lod = min(max(lod, 0.0), len(levels) - 1.0)

    def texel(level, i, j):
        h, w, _ = level.shape
        if wrap_mode == "wrap":
            i, j = i % w, j % h
        elif wrap_mode == "mirror":
            i = i % (2 * w)
            i = i if i < w else 2 * w - 1 - i
            j = j % (2 * h)
            j = j if j < h else 2 * h - 1 - j
        elif wrap_mode == "border":
            if not (0 <= i < w and 0 <= j < h):
                return np.asarray(border_rgba, dtype=np.float64)
        else:  # clamp, none
            i, j = min(max(i, 0), w - 1), min(max(j, 0), h - 1)
        return level[j, i].astype(np.float64)

    def bilinear(level):
        h, w, _ = level.shape
        x = u * w - 0.5           # texel centres at integer x
        y = (1.0 - v) * h - 0.5   # rows count downward from the top
        i, j = int(np.floor(x)), int(np.floor(y))
        fx, fy = x - i, y - j
        return ((1 - fx) * (1 - fy) * texel(level, i, j) + fx * (1 - fy) * texel(level, i + 1, j)
                + (1 - fx) * fy * texel(level, i, j + 1) + fx * fy * texel(level, i + 1, j + 1))

    lo = int(np.floor(lod))
    t = lod - lo
    if t == 0.0:
        return bilinear(levels[lo])
    return (1 - t) * bilinear(levels[lo]) + t * bilinear(levels[lo + 1])


# --- rasterizer (twin of cityshade.raster.rasterize) -------------------------------------------

def reference_rasterize(vertices, triangles, t_begin_days, t_end_days, camera, t_days=0.0):
    """Brute-force G-buffer: every pixel-centre ray against every triangle (Moller-Trumbore).

    Keeps, per pixel, the nearest hit whose view depth lies in [near, far] (perspective: along
    the camera's forward axis; map: below the camera plane); exact depth ties go to the lower
    id. Edges count as inside (no fill rule), so results may differ from the rasterizer only on
    triangle edges. Returns (prim_id (H, W) int, depth (H, W) float64 along the ray).
    """
    h, w = camera.height_px, camera.width_px
    xs = np.arange(w) + 0.5
    ys = np.arange(h) + 0.5
    if camera.kind == "map":
        px = camera.pixel_size_m
        gx, gy = np.meshgrid(camera.x_left_m + xs * px, camera.y_top_m - ys * px)
        origins = np.stack([gx, gy, np.full_like(gx, camera.eye_m[2])], -1).reshape(-1, 3)
        dirs = np.tile([0.0, 0.0, -1.0], (h * w, 1))
        cos = np.ones(h * w)
    else:
        fwd = np.asarray(camera.target_m, float) - camera.eye_m
        fwd /= np.linalg.norm(fwd)
        right = np.cross(fwd, camera.up)
        if np.linalg.norm(right) < 1e-9:
            right = np.cross(fwd, [0.0, 1.0, 0.0])
        right /= np.linalg.norm(right)
        up = np.cross(right, fwd)
        pitch = 2.0 * np.tan(np.radians(camera.vfov_deg) / 2.0) / h
        gx, gy = np.meshgrid((xs - w / 2.0) * pitch, (h / 2.0 - ys) * pitch)
        dirs = (gx[..., None] * right + gy[..., None] * up + fwd).reshape(-1, 3)
        dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
        origins = np.tile(np.asarray(camera.eye_m, float), (h * w, 1))
        cos = dirs @ fwd
    prim = np.full(h * w, -1)
    best = np.full(h * w, np.inf)
    v = np.asarray(vertices, np.float64)
    for tri in range(len(triangles)):
        if not (t_begin_days[tri] <= t_days < t_end_days[tri]):
            continue
        a, b, c = v[np.asarray(triangles[tri])]
        e1, e2 = b - a, c - a
        p = np.cross(dirs, e2)
        det = p @ e1
        with np.errstate(divide="ignore", invalid="ignore"):
            s = origins - a
            uu = np.einsum("ij,ij->i", s, p) / det
            q = np.cross(s, e1)
            vv = np.einsum("ij,ij->i", q, dirs) / det
            t = (q @ e2) / det
        z = t * cos
        ok = ((det != 0) & (uu >= 0) & (vv >= 0) & (uu + vv <= 1) & (z >= camera.near_m)
              & (z <= camera.far_m))
        better = ok & ((t < best) | ((t == best) & (tri < prim)))
        prim[better] = tri
        best[better] = t[better]
    return prim.reshape(h, w), best.reshape(h, w)


# --- sun-hours (twin of cityshade.sunhours.run / cityshade.sunhours.surfaces) ------------------------------------

def reference_sun_hours(vertices, triangles, points, normals, sun_directions, weights_h,
                        offset_m=1e-4):
    """Sun-hours of each point by brute force: for every step, a point facing the sun
    (normal · sun > 0) whose ray towards the sun, started ``offset_m`` off the surface along
    the normal, hits no triangle, gains the step's weight. Steps with the sun at or below the
    horizon (direction z <= 0) give nothing."""
    points = np.asarray(points, dtype=np.float64)
    normals = np.asarray(normals, dtype=np.float64)
    n_tri = len(triangles)
    begin, end = np.full(n_tri, -np.inf), np.full(n_tri, np.inf)
    hours = np.zeros(len(points))
    for d, w in zip(np.asarray(sun_directions, dtype=np.float64), weights_h):
        if d[2] <= 0.0:
            continue
        for i, (p, n) in enumerate(zip(points, normals)):
            if n @ d <= 0.0:
                continue
            t, _ = reference_ray_hits(vertices, triangles, begin, end,
                                      p + offset_m * (n + d), d)
            if t.size == 0:
                hours[i] += w
    return hours


# --- 2-D convex hull (twin of cityshade.shadows.warps.convex_hull_2d) ---------------------------

def reference_convex_hull(points_xy):
    """Vertices of the convex hull of 2-D points by brute force: a point is a hull vertex when
    some pair (it, another point) has every point on one side (or on the line, then within
    the segment) and it is not strictly between two other collinear extreme points. O(n³)."""
    p = np.unique(np.asarray(points_xy, dtype=np.float64), axis=0)
    n = len(p)
    if n < 3:
        return p
    corners = set()
    for i in range(n):
        for j in range(n):
            if i == j:
                continue
            a, b = p[i], p[j]
            cross = (b[0] - a[0]) * (p[:, 1] - a[1]) - (b[1] - a[1]) * (p[:, 0] - a[0])
            if (cross >= 0).all():
                # a-b lies on the hull boundary; its extreme points along the line are corners.
                on = p[cross == 0]
                t = (on - a) @ (b - a)
                corners.add(tuple(on[np.argmin(t)]))
                corners.add(tuple(on[np.argmax(t)]))
    return np.array(sorted(corners))


def reference_tile_lists(bbox, tile_px, tiles_x, tiles_y):
    """Twin of ``raster.triangles.bin_triangles``: per tile, the triangles whose pixel box
    (col0, col1, row0, row1 inclusive; col0 > col1 for none) meets it, in drawing order."""
    lists = [[] for _ in range(tiles_x * tiles_y)]
    for j, (c0, c1, r0, r1) in enumerate(bbox.tolist()):
        if c0 > c1:
            continue
        for ty in range(r0 // tile_px, r1 // tile_px + 1):
            for tx in range(c0 // tile_px, c1 // tile_px + 1):
                lists[ty * tiles_x + tx].append(j)
    return lists


# --- shadow maps (twins of cityshade.raster.depthpass / shadows.shadowmap / filtering) --------------

def reference_depth_map(vertices, triangles, t_begin_days, t_end_days, clip_from_world,
                        width_px, height_px, t_days=0.0):
    """Light-space depth map by ray casting: for every texel centre, the world segment between
    its NDC points z = -1 and z = +1 (through the inverse matrix) is intersected with every
    triangle valid at ``t_days`` (Moller-Trumbore); the nearest hit's NDC depth z/w is kept
    (ties to the lower triangle id). Casters nearer than the near plane are not seen (the
    fast path clamps them to -1; test scenes keep casters inside the depth range).

    Returns (depth (H, W) float64, +inf where empty; prim (H, W) int64, -1 where empty).
    """
    m = np.asarray(clip_from_world, dtype=np.float64)
    inv = np.linalg.inv(m)
    depth = np.full((height_px, width_px), np.inf)
    prim = np.full((height_px, width_px), -1, np.int64)
    for row in range(height_px):
        y = 1.0 - 2.0 * (row + 0.5) / height_px
        for col in range(width_px):
            x = 2.0 * (col + 0.5) / width_px - 1.0
            a = inv @ np.array([x, y, -1.0, 1.0])
            b = inv @ np.array([x, y, 1.0, 1.0])
            a, b = a[:3] / a[3], b[:3] / b[3]
            ts, ids = reference_ray_hits(vertices, triangles, t_begin_days, t_end_days, a, b - a,
                                         t_days, 1.0)
            for t, tri in sorted(zip(ts, ids), key=lambda h: (h[0], h[1])):
                p = a + t * (b - a)
                c = m @ np.r_[p, 1.0]
                z = c[2] / c[3]
                if z < depth[row, col] or (z == depth[row, col] and tri < prim[row, col]):
                    depth[row, col] = z
                    prim[row, col] = tri
    return depth, prim


def reference_pcf(depth, u_px, v_px, z, kernel):
    """Percentage-closer filtering with plain loops: share of the kernel × kernel texels around
    texel (floor u, floor v) that are outside the map or not nearer than ``z``."""
    depth = np.asarray(depth)
    h, w = depth.shape
    r = kernel // 2
    out = []
    for u, v, zz in zip(u_px, v_px, z):
        c0, r0 = int(np.floor(u)), int(np.floor(v))
        lit = 0
        for rr in range(r0 - r, r0 + r + 1):
            for cc in range(c0 - r, c0 + r + 1):
                inside = 0 <= rr < h and 0 <= cc < w
                lit += (not inside) or zz <= depth[rr, cc]
        out.append(lit / kernel ** 2)
    return np.array(out)


def reference_separable_filter(image, weights):
    """Rows then columns convolved with ``weights`` (odd length), borders clamped: np.convolve
    on edge-padded lines."""
    img = np.asarray(image, dtype=np.float64)
    flat = img.ndim == 2
    if flat:
        img = img[..., None]
    k = np.asarray(weights, dtype=np.float64)
    r = len(k) // 2

    def line(a):
        return np.convolve(np.pad(a, r, mode="edge"), k[::-1], mode="valid")

    rows = np.apply_along_axis(line, 1, img)
    out = np.apply_along_axis(line, 0, rows)
    return out[..., 0] if flat else out


def reference_vsm_lookup(moments, u_px, v_px, depth_m, min_variance, bleed_reduction):
    """VSM with plain arithmetic: bilinear moments at (u - 0.5, v - 0.5) (indices clamped),
    Chebyshev's bound for receivers behind the mean, then (p - a) / (1 - a) clipped."""
    mom = np.asarray(moments, dtype=np.float64)
    h, w = mom.shape[:2]
    out = []
    for u, v, d in zip(u_px, v_px, depth_m):
        x, y = u - 0.5, v - 0.5
        c0, r0 = int(np.floor(x)), int(np.floor(y))
        fx, fy = x - c0, y - r0
        m = np.zeros(2)
        for rr, wy in ((r0, 1 - fy), (r0 + 1, fy)):
            for cc, wx in ((c0, 1 - fx), (c0 + 1, fx)):
                m += wy * wx * mom[min(max(rr, 0), h - 1), min(max(cc, 0), w - 1)]
        if d <= m[0]:
            out.append(1.0)
            continue
        var = max(m[1] - m[0] ** 2, min_variance)
        p = var / (var + (d - m[0]) ** 2)
        if bleed_reduction > 0:
            p = min(max((p - bleed_reduction) / (1 - bleed_reduction), 0.0), 1.0)
        out.append(p)
    return np.array(out)


def reference_smooth_lit(lit, depth, ok, sigma_px, threshold_rel):
    """Depth-aware separable Gaussian with plain loops (per-pixel σ ``sigma_px`` (H, W)):
    along each row, then each column, a neighbour k steps away contributes exp(-k²/2σ²) when
    every pixel from the centre to it is ``ok`` and each consecutive depth step is at most
    ``threshold_rel`` times the previous depth; pixels that are not ``ok`` keep their value."""
    lit = np.asarray(lit, dtype=np.float64)
    h, w = lit.shape

    def one_pass(values, horizontal):
        out = values.copy()
        for y in range(h):
            for x in range(w):
                s = sigma_px[y, x]
                if not ok[y, x] or s <= 0:
                    continue
                r = int(np.ceil(3.0 * s))
                num, den = values[y, x], 1.0
                for step in (-1, 1):
                    prev = depth[y, x]
                    for k in range(1, r + 1):
                        yy, xx = (y, x + step * k) if horizontal else (y + step * k, x)
                        if not (0 <= yy < h and 0 <= xx < w) or not ok[yy, xx]:
                            break
                        if abs(depth[yy, xx] - prev) > threshold_rel * abs(prev):
                            break
                        prev = depth[yy, xx]
                        g = np.exp(-k * k / (2 * s * s))
                        num += g * values[yy, xx]
                        den += g
                out[y, x] = num / den
        return out

    return np.clip(one_pass(one_pass(lit, True), False), 0, 1)


def _reference_tangents(n):
    n = np.asarray(n, dtype=np.float64)
    n = n / np.linalg.norm(n)
    helper = np.array([0.0, 0.0, 1.0]) if abs(n[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    t1 = np.cross(n, helper)
    t1 /= np.linalg.norm(t1)
    return t1, np.cross(n, t1)


def _reference_image_jacobian(clip_from_world, width_px, height_px, p, t1, t2, h=1e-3):
    """2×2 derivatives of (column, row) along two tangents by central differences."""
    m = np.asarray(clip_from_world, dtype=np.float64)

    def pixel(q):
        c = m @ np.r_[q, 1.0]
        return np.array([(c[0] / c[3] + 1) * width_px / 2, (1 - c[1] / c[3]) * height_px / 2])

    cols = [(pixel(p + h * t) - pixel(p - h * t)) / (2 * h) for t in (t1, t2)]
    return np.column_stack(cols)


def reference_texel_footprint_m(clip_from_world, width_px, height_px, points, normals):
    """Longer edge (metres) of the texel mapped onto each point's plane, by finite differences:
    the texel's edges are the columns of the inverse of the tangent-plane Jacobian."""
    out = []
    for p, n in zip(np.asarray(points, np.float64), np.asarray(normals, np.float64)):
        t1, t2 = _reference_tangents(n)
        inv = np.linalg.inv(_reference_image_jacobian(clip_from_world, width_px, height_px, p,
                                                      t1, t2))
        out.append(np.linalg.norm(inv, axis=0).max())
    return np.array(out)


def reference_aliasing_px(light_clip, light_w, light_h, camera_clip, camera_w, camera_h,
                          points, normals):
    """Screen pixels spanned by the longer texel edge at each point (finite differences):
    columns of J_screen @ inv(J_light) on the tangent plane."""
    out = []
    for p, n in zip(np.asarray(points, np.float64), np.asarray(normals, np.float64)):
        t1, t2 = _reference_tangents(n)
        jl = _reference_image_jacobian(light_clip, light_w, light_h, p, t1, t2)
        js = _reference_image_jacobian(camera_clip, camera_w, camera_h, p, t1, t2)
        out.append(np.linalg.norm(js @ np.linalg.inv(jl), axis=0).max())
    return np.array(out)


def reference_nearest_feature_distance2(feature):
    """Squared pixel distance from every pixel to the nearest True pixel of ``feature`` by brute
    force over all feature pixels (-1 everywhere when there is none); twin of
    :func:`cityshade.evaluate.nearest_feature`."""
    feature = np.asarray(feature, bool)
    h, w = feature.shape
    fr, fc = np.nonzero(feature)
    if fr.size == 0:
        return np.full((h, w), -1, np.int64)
    rows, cols = np.mgrid[0:h, 0:w]
    d2 = (rows[..., None] - fr) ** 2 + (cols[..., None] - fc) ** 2
    return d2.min(axis=-1).astype(np.int64)


# --- runs (continuous sunshine) ---------------------------------------------------------------

def reference_stretches(lit_steps, starts_s, ends_s, min_stretch_h=0.0):
    """Longest stretch and hours in stretches >= ``min_stretch_h`` per receiver, by listing the
    stretches: maximal runs of lit steps, each step starting where the previous one ended.

    lit_steps : (S, N) bool in time order; starts_s, ends_s : (S,) seconds.
    """
    lit_steps = np.asarray(lit_steps, bool)
    n_steps, n = lit_steps.shape
    longest = np.zeros(n)
    qualified = np.zeros(n)
    for r in range(n):
        stretches = []
        for s in range(n_steps):
            if not lit_steps[s, r]:
                continue
            w = (ends_s[s] - starts_s[s]) / 3600.0
            continues = s > 0 and lit_steps[s - 1, r] and starts_s[s] == ends_s[s - 1]
            if continues:
                stretches[-1] += w
            else:
                stretches.append(w)
        longest[r] = max(stretches, default=0.0)
        qualified[r] = sum(x for x in stretches if x >= min_stretch_h)
    return longest, qualified


def reference_resolve(scene, prim, bary):
    """Per-pixel surface attributes of a G-buffer in plain numpy (twin of
    ``cityshade.raster.gbuffer.resolve``): a dict of the Surfaces fields."""
    prim = np.asarray(prim)
    valid = prim >= 0
    h, w = prim.shape
    ids = prim[valid]
    bu = bary[valid, 0].astype(np.float64)[:, None]
    bv = bary[valid, 1].astype(np.float64)[:, None]
    bw = 1.0 - bu - bv
    corners = np.asarray(scene.triangles)[ids]
    verts = np.asarray(scene.vertices)
    v0 = verts[corners[:, 0]].astype(np.float64)
    v1 = verts[corners[:, 1]].astype(np.float64)
    v2 = verts[corners[:, 2]].astype(np.float64)
    position = np.full((h, w, 3), np.nan)
    position[valid] = bw * v0 + bu * v1 + bv * v2
    n = np.cross(v1 - v0, v2 - v0)
    length = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.divide(n, length, out=np.zeros_like(n), where=length > 0.0)
    normal = np.zeros((h, w, 3), np.float32)
    normal[valid] = n
    uvs = np.asarray(scene.uv)
    uv = np.zeros((h, w, 2), np.float32)
    if uvs.size:
        uv[valid] = (bw * uvs[corners[:, 0]] + bu * uvs[corners[:, 1]]
                     + bv * uvs[corners[:, 2]]).astype(np.float32)

    def per_pixel(values, fill, dtype):
        out = np.full((h, w), fill, dtype)
        out[valid] = np.asarray(values)[ids]
        return out

    return {"position_m": position, "normal": normal, "uv": uv, "valid": valid,
            "obj_id": per_pixel(scene.tri_object, -1, np.int32),
            "material": per_pixel(scene.tri_material, -1, np.int32),
            "texture": per_pixel(scene.tri_texture, -1, np.int32),
            "cls": per_pixel(scene.tri_class, 0, np.uint8)}


def reference_add_ground_plane(camera, surfaces, z_m, box_m):
    """The ground plane in plain numpy over whole-frame arrays (twin of
    ``cityshade.geometry.ground.add_ground_plane``): a dict of the changed Surfaces fields
    and the number of pixels filled."""
    from cityshade.geometry.ground import GROUND_MARGIN_REL, TERRAIN_CODE

    valid = np.asarray(surfaces.valid)
    h, w = valid.shape
    origins, directions = camera.primary_rays()
    origins = origins.reshape(h, w, 3)
    directions = directions.reshape(h, w, 3)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (z_m - origins[..., 2]) / directions[..., 2]
    point = origins + t[..., None] * directions
    lo, hi = box_m
    margin = GROUND_MARGIN_REL * float(np.hypot(hi[0] - lo[0], hi[1] - lo[1]))
    inside = ((point[..., 0] >= lo[0] - margin) & (point[..., 0] <= hi[0] + margin)
              & (point[..., 1] >= lo[1] - margin) & (point[..., 1] <= hi[1] + margin))
    fill = ~valid & np.isfinite(t) & (t > 0) & inside
    position = np.array(surfaces.position_m, dtype=np.float64, copy=True)
    position[fill] = point[fill]
    position[fill, 2] = z_m
    normal = np.array(surfaces.normal, copy=True)
    normal[fill] = (0.0, 0.0, 1.0)
    cls = np.array(surfaces.cls, copy=True)
    cls[fill] = TERRAIN_CODE
    depth = np.array(surfaces.depth, copy=True)
    depth[fill] = ((origins[..., 2] - z_m) if camera.kind == "map" else t)[fill]
    return ({"position_m": position, "normal": normal, "cls": cls, "valid": valid | fill,
             "depth": depth}, int(fill.sum()))


def reference_oriented_normals(surfaces, camera):
    """Normals turned to the seen side in plain numpy (twin of
    ``cityshade.shadows.oriented_normals``)."""
    normal = np.asarray(surfaces.normal, dtype=np.float64)
    if camera.kind == "map":
        to_viewer = np.asarray(camera.eye_m, np.float64) - np.asarray(camera.target_m, np.float64)
        to_viewer = np.broadcast_to(to_viewer, normal.shape)
    else:
        to_viewer = np.asarray(camera.eye_m, np.float64) - surfaces.position_m
    seen_from_back = np.einsum("ijk,ijk->ij", normal, to_viewer) < 0
    return np.where(seen_from_back[..., None], -normal, normal)


def reference_facing_mask(normal, valid, sun_dir):
    """N·L > 0 summed left to right, element by element (numpy's elementwise products and
    sums: no fused multiply-add), and valid."""
    n = np.asarray(normal, np.float64)
    s = np.asarray(sun_dir, np.float64)
    return ((n[..., 0] * s[0] + n[..., 1] * s[1]) + n[..., 2] * s[2] > 0.0) & np.asarray(
        valid, bool)


def reference_shadow_origins(points, normals, sun_dir):
    """Shadow-ray origins in plain numpy (twin of ``cityshade.trace.shadow_rays_from_surface``):
    ``p + (n + sun) * 2^-18 * max(|p|_inf, 1 m)``."""
    points = np.asarray(points, np.float64)
    scale = np.maximum(np.abs(points).max(axis=1), 1.0)
    return points + (np.asarray(normals, np.float64) + sun_dir) * (2.0 ** -18 * scale)[:, None]


def reference_bracket_states(depth_map, scene, points, normals, own_poly, sun_dir, radius,
                             thin_map, counts=None):
    """The bracket classifier's receiver states in plain numpy (twin of
    ``cityshade.shadows.hybrid.bracket_states``): origins, projection and receiver-plane
    gradient step by step, then every texel of the (2 radius + 1)² window. ``counts``, a
    dict, gets ``near_proven``: the receivers clear at every texel centre whose ray hits a
    caster near the plane."""
    from cityshade.shadows.shadowmap import project, receiver_plane_gradient

    origins = reference_shadow_origins(points, normals, np.asarray(sun_dir, np.float64))
    view = depth_map.view
    u, v, z = project(view, origins)
    gu, gv = receiver_plane_gradient(view, origins, np.asarray(normals, np.float64), u, v, z)
    tol = 1e-6 + 0.01 * (np.abs(gu) + np.abs(gv))
    prim = np.asarray(depth_map.prim_id)
    ids = reference_classifier_polygons(scene)
    texel_poly = np.where(prim >= 0, ids[np.maximum(prim, 0)], -1)
    depth = np.asarray(depth_map.depth)
    h, w = depth.shape
    ok = np.isfinite(u) & np.isfinite(v) & np.isfinite(z)
    # A receiver almost along the sun's rays is left to the rays.
    nrm, s = np.asarray(normals, np.float64), np.asarray(sun_dir, np.float64)
    grazing = (nrm[:, 0] * s[0] + nrm[:, 1] * s[1]) + nrm[:, 2] * s[2] < 1e-3
    ok &= ~grazing
    cu = np.floor(np.where(ok, u, 0.0)).astype(np.int64)
    cv = np.floor(np.where(ok, v, 0.0)).astype(np.int64)
    n = len(u)
    occluding = np.zeros(n, np.int64)
    thin_occluding = np.zeros(n, np.int64)
    clear = np.zeros(n, np.int64)
    first = np.full(n, -2, np.int64)
    mixed = np.zeros(n, bool)
    # Another polygon's caster behind the plane at a texel centre by less than the plane's
    # change across the window, and in front of the receiver's own depth: a proof is tried.
    band = (radius + 0.5) * (np.abs(gu) + np.abs(gv))
    near_texels = [[] for _ in range(n)]
    # A thin caster counts in the receiver's own texel, against its own depth.
    inside = (cv >= 0) & (cv < h) & (cu >= 0) & (cu < w)
    r, c = np.clip(cv, 0, h - 1), np.clip(cu, 0, w - 1)
    other = np.where(thin_map[1][r, c] != own_poly, thin_map[0][r, c], thin_map[2][r, c])
    thin_occluding += inside & (other < z - tol)
    occluding_texels = [[] for _ in range(n)]
    for dv in range(-radius, radius + 1):
        for du in range(-radius, radius + 1):
            row, col = cv + dv, cu + du
            inside = (row >= 0) & (row < h) & (col >= 0) & (col < w)
            r, c = np.clip(row, 0, h - 1), np.clip(col, 0, w - 1)
            plane = z + gu * (col + 0.5 - u) + gv * (row + 0.5 - v) - tol
            occ = inside & (depth[r, c] < plane) & (texel_poly[r, c] != own_poly)
            poly = texel_poly[r, c]
            mixed |= occ & (first != -2) & (poly != first)
            first = np.where(occ & (first == -2), poly, first)
            occluding += occ
            clear += ~occ
            for i in np.flatnonzero(occ):
                occluding_texels[i].append(int(prim[r[i], c[i]]))
            near = (inside & ~occ & (texel_poly[r, c] != own_poly)
                    & (depth[r, c] < np.minimum(plane + band, z)))
            for i in np.flatnonzero(near):
                near_texels[i].append(int(prim[r[i], c[i]]))
    state = np.where((occluding == 0) & (thin_occluding == 0), 0,
                     np.where((clear == 0) & ~mixed, 1, 2)).astype(np.uint8)
    state[~ok] = 2
    # Uncertain with occluding texels: shadow proven when the ray hits one of their triangles
    # by the tracer's watertight rule (an edge shared with a triangle outside the window may
    # belong to that one: Moller-Trumbore's inclusive edges would prove more).
    tri = np.asarray(scene.triangles)
    for i in np.flatnonzero((state == 2) & ok & (occluding > 0)):
        ids = sorted(set(occluding_texels[i]))
        if reference_watertight_hits(scene.vertices, tri[ids], origins[i], sun_dir).any():
            state[i] = 3
    # Clear at every texel centre, but near another polygon's caster: a hit proves shadow
    # (a steep receiver at the corner of another polygon), before the thin casters count.
    near_proven = 0
    for i in np.flatnonzero(ok & (occluding == 0)):
        ids = sorted(set(near_texels[i]))
        if ids and reference_watertight_hits(scene.vertices, tri[ids], origins[i],
                                             sun_dir).any():
            state[i] = 3
            near_proven += 1
    if counts is not None:
        counts["near_proven"] = near_proven
    return state


def reference_watertight_hits(vertices, triangles, origin, direction):
    """(T,) bool: whether the ray hits each triangle at t >= 0 by the watertight test (Woop,
    Benthin and Wald 2013) in numpy float64: permute so the largest direction axis is z
    (swapping x, y when it is negative), shear, then the signs of the 2-D edge functions."""
    d = np.asarray(direction, np.float64)
    ad = np.abs(d)
    kz = 0 if ad[0] > ad[1] and ad[0] > ad[2] else (1 if ad[1] > ad[2] else 2)
    kx, ky = (kz + 1) % 3, (kz + 2) % 3
    if d[kz] < 0:
        kx, ky = ky, kx
    sx, sy, sz = d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]
    v = np.asarray(vertices, np.float32)[np.asarray(triangles)].astype(np.float64)
    o = np.asarray(origin, np.float64)
    rel = v - o                                    # (T, 3 vertices, 3 axes)
    z = rel[..., kz]
    x = rel[..., kx] - sx * z
    y = rel[..., ky] - sy * z
    a, b, c = 0, 1, 2
    e_u = x[:, c] * y[:, b] - y[:, c] * x[:, b]
    e_v = x[:, a] * y[:, c] - y[:, a] * x[:, c]
    e_w = x[:, b] * y[:, a] - y[:, b] * x[:, a]
    e = np.stack([e_u, e_v, e_w], axis=1)
    inside = ~((e < 0).any(axis=1) & (e > 0).any(axis=1))
    det = e_u + e_v + e_w
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (e_u * z[:, a] + e_v * z[:, b] + e_w * z[:, c]) * sz * (1.0 / det)
    return inside & (det != 0) & (t >= 0)


def reference_transmission(vertices, triangles, t_begin_days, t_end_days, tri_crown,
                           crown_tau, origin, direction, t_days=0.0):
    """Transmission of one sun ray (twin of :func:`cityshade.shadows.visibility.transmission`):
    per triangle standing at ``t_days`` the watertight test (:func:`reference_watertight_hits`);
    0 if an opaque triangle (``tri_crown`` -1) is hit, else the product of ``crown_tau`` over
    the distinct crowns hit, multiplied in ascending crown order."""
    hit = reference_watertight_hits(vertices, triangles, origin, direction)
    hit &= (np.asarray(t_begin_days) <= t_days) & (t_days < np.asarray(t_end_days))
    crowns = np.asarray(tri_crown)[hit]
    if (crowns < 0).any():
        return 0.0
    tau = 1.0
    for c in sorted(set(crowns.tolist())):
        tau *= float(crown_tau[c])
    return tau


def _reference_square_meets_triangle(c, r, pu, pv, margin):
    """Separating-axis test of texel square [c, c+1] x [r, r+1] and a 2-D triangle (or, when it
    has no area, its longest edge): no edge normal separates them by more than ``margin``
    times the edge length (the square's own axes are the caller's box)."""
    def cross(e, p):
        return e[0] * p[..., 1] - e[1] * p[..., 0]

    corners = np.array([[c, r], [c + 1, r], [c, r + 1], [c + 1, r + 1]], np.float64)
    pts = np.stack([pu, pv], axis=1)
    edges = [(0, 1), (1, 2), (2, 0)]
    area2 = cross(pts[1] - pts[0], pts[2] - pts[0])
    flat = abs(area2) <= 1e-9 * (abs((pu[1] - pu[0]) * (pv[2] - pv[0]))
                                 + abs((pu[2] - pu[0]) * (pv[1] - pv[0])))
    if flat:
        a, b = max(edges, key=lambda e: np.hypot(*(pts[e[1]] - pts[e[0]])))
        for sign in (1.0, -1.0):
            e = pts[b] - pts[a]
            inner = sign * cross(e, corners - pts[a])
            if inner.max() < -margin * np.hypot(*e):
                return False
        return True
    for a, b in edges:
        e = pts[b] - pts[a]
        inner = np.sign(area2) * cross(e, corners - pts[a])
        if inner.max() < -margin * np.hypot(*e):
            return False
    return True


def reference_thin_caster_map(scene, view, t_days, thin_texels=2.0, margin=1e-3,
                              sliver_ratio=8.0):
    """The hybrid's thin-caster map in plain numpy (twin of
    ``cityshade.shadows.hybrid.thin_caster_map``): every thin triangle (light-space height
    below ``thin_texels``, or a sliver: longest edge² at least ``sliver_ratio`` times twice its
    area) on the texels whose squares it meets (separating axes, within
    ``margin`` texels), with a lower bound of its depth there (its depth plane, solved, at the
    square's lowest corner, less 1 % of the slopes and 1e-6, at least its nearest vertex;
    as float32); per texel each polygon's nearest, then the nearest polygon and
    the nearest of the others (lowest polygon id on ties)."""
    h, w = view.height_px, view.width_px
    v = np.asarray(scene.vertices, np.float64)
    tri = np.asarray(scene.triangles)
    m = view.clip_from_world
    clip = v @ m[:, :3].T + m[:, 3]
    cw = clip[:, 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        u = (clip[:, 0] / cw + 1.0) * 0.5 * w
        r = (1.0 - clip[:, 1] / cw) * 0.5 * h
        z = clip[:, 2] / cw
    best = {}    # (row, col) -> {polygon: nearest depth}
    ids = reference_classifier_polygons(scene)
    present = ((np.asarray(scene.tri_t_begin_days) <= t_days)
               & (t_days < np.asarray(scene.tri_t_end_days)))
    for i in np.nonzero(present)[0]:
        q = tri[i]
        if not (cw[q] > 0).all():
            continue
        pu, pv, pz = u[q], r[q], z[q]
        area2 = abs((pu[1] - pu[0]) * (pv[2] - pv[0]) - (pu[2] - pu[0]) * (pv[1] - pv[0]))
        longest = max(np.hypot(pu[a] - pu[b], pv[a] - pv[b]) for a, b in ((0, 1), (0, 2), (1, 2)))
        if longest > 0 and area2 / longest >= thin_texels and longest ** 2 < sliver_ratio * area2:
            continue
        zmin = pz.min()
        if not zmin <= 1.0:
            continue
        c0 = max(int(np.floor(pu.min() - margin)), 0)
        c1 = min(int(np.floor(pu.max() + margin)), w - 1)
        r0 = max(int(np.floor(pv.min() - margin)), 0)
        r1 = min(int(np.floor(pv.max() + margin)), h - 1)
        try:
            with np.errstate(all="ignore"):
                za, zb, z0 = np.linalg.solve(np.stack([pu, pv, np.ones(3)], axis=1), pz)
            plane = np.isfinite(za) and np.isfinite(zb)
        except np.linalg.LinAlgError:
            plane = False
        poly = int(ids[i])
        for row in range(r0, r1 + 1):
            for col in range(c0, c1 + 1):
                if not _reference_square_meets_triangle(col, row, pu, pv, margin):
                    continue
                d = zmin
                if plane:
                    lowest = (z0 + za * (col + (za < 0)) + zb * (row + (zb < 0))
                              - 0.01 * (abs(za) + abs(zb)) - 1e-6)
                    d = max(d, lowest)
                d32 = np.float32(d)
                per = best.setdefault((row, col), {})
                per[poly] = min(per.get(poly, np.float32(np.inf)), d32)
    out = (np.full((h, w), np.inf, np.float32), np.full((h, w), -1, np.int32),
           np.full((h, w), np.inf, np.float32), np.full((h, w), -1, np.int32))
    for (row, col), per in best.items():
        ranked = sorted(per.items(), key=lambda kv: (kv[1], kv[0]))
        out[0][row, col], out[1][row, col] = ranked[0][1], ranked[0][0]
        if len(ranked) > 1:
            out[2][row, col], out[3][row, col] = ranked[1][1], ranked[1][0]
    return out


# --- tiledcache -------------------------------------------------------------------------------

def reference_tiles_passing(boxes, passes):
    """Twin of :meth:`cityshade.store.tiled.TileTree.query`: every tile box tested in turn."""
    return [i for i in range(len(boxes)) if passes(boxes[i][0], boxes[i][1])]


# --- shading: textures over the base colour -------------------------------------------------

def reference_albedo(scene, surfaces, prim_id=None, settings=None):
    """``shading.albedo_of_surfaces`` by gathering the textured pixels, sampling them one array
    at a time and scattering the composite back (the numpy path it replaced)."""
    import dataclasses

    from cityshade.frame.shading import ShadingSettings, albedo_of_surfaces
    from cityshade.frame.textures import load_texture_set, lod_from_uv_neighbours, sample_trilinear

    settings = settings or ShadingSettings()
    albedo = albedo_of_surfaces(scene, surfaces, settings=dataclasses.replace(settings,
                                                                              textures=False))
    textures = list(getattr(scene, "textures", []) or [])
    if not (settings.textures and textures):
        return albedo
    valid = np.asarray(surfaces.valid, bool)
    texture = np.asarray(surfaces.texture, np.int64)
    textured = valid & (texture >= 0) & (texture < len(textures))
    if not textured.any():
        return albedo
    used = np.zeros(len(textures), bool)
    used[np.unique(texture[textured])] = True
    tex_set = load_texture_set(textures, used)
    if prim_id is None:
        prim_id = getattr(surfaces, "prim_id", None)
    if prim_id is not None and getattr(scene, "tri_polygon", None) is not None:
        prim = np.asarray(prim_id, np.int64)
        group = np.where(prim >= 0, np.asarray(scene.tri_polygon)[np.maximum(prim, 0)], -1)
    elif prim_id is not None:
        group = np.asarray(prim_id, np.int64)
    else:
        group = np.zeros(valid.shape, np.int64)
    tex_ids = np.where(textured, texture, -1)
    lod = lod_from_uv_neighbours(surfaces.uv, tex_ids, group, surfaces.normal, tex_set,
                                 bias=settings.mip_bias)
    rows, cols = np.nonzero(textured)
    rgba = sample_trilinear(tex_set, tex_ids[rows, cols], surfaces.uv[rows, cols],
                            lod[rows, cols])
    albedo[rows, cols] = rgba[:, :3] + (1.0 - rgba[:, 3:4]) * albedo[rows, cols]
    return albedo


# --- tiles: the driver's sums ---------------------------------------------------------------

def reference_accumulate(sums, slots, weights_h, lit):
    """A tiled run's sums after one sun position, numpy's way: for each row with a weight,
    ``sums[row, slots] += weight · lit`` (the fancy-indexed add that
    :func:`cityshade.sunhours.tiled.add_lit` does in one pass)."""
    sums = np.array(sums, dtype=np.float64)
    lit64 = np.asarray(lit).astype(np.float64)
    for row in np.flatnonzero(np.asarray(weights_h) > 0.0):
        sums[row, slots] += weights_h[row] * lit64
    return sums


def reference_event_order(values):
    """Stable increasing order of float32 ``values`` (-0.0 ties with 0.0): the comparison
    twin of ``kdtree_build._radix_order``."""
    return np.argsort(np.asarray(values, np.float32), kind="stable").astype(np.int32)


def reference_boxes_holding_a_point(boxes, xs, ys):
    """Twin of :func:`cityshade.lightspace.kernels.cull_unoccupied`: for each box (x0, x1, y0,
    y1; NaN x0: already culled) whether some point (xs, ys) lies in it, tested one by one."""
    out = np.zeros(len(boxes), bool)
    for j, (x0, x1, y0, y1) in enumerate(boxes):
        if not np.isnan(x0):
            out[j] = bool(np.any((xs >= x0) & (xs <= x1) & (ys >= y0) & (ys <= y1)))
    return out


def reference_used_vertex_box(vertices, triangles):
    """Twin of :func:`cityshade.geometry.bounds.used_vertex_box`: (2, 3) float64 min and max of
    the vertices the triangles use, through the sorted set of used indices."""
    used = np.unique(np.asarray(triangles).reshape(-1))
    pts = np.asarray(vertices)[used].astype(np.float64)
    return np.stack([pts.min(axis=0), pts.max(axis=0)])


def reference_expand_ranges(starts, lengths):
    """Twin of :func:`cityshade.geometry.scene._expand_ranges`: the ranges one by one."""
    out = []
    for s, n in zip(np.asarray(starts).tolist(), np.asarray(lengths).tolist()):
        out.extend(range(s, s + n))
    return np.array(out, np.int64)


def reference_render_vertices(points, index, origin):
    """Twin of :func:`cityshade.geometry.scene._render_vertices`: gather, subtract in float64,
    round to float32."""
    return (np.asarray(points, np.float64)[index] - origin).astype(np.float32)


def reference_model_time_range(t_begin_days, t_end_days):
    """Twin of :func:`cityshade.accel.kdtree_build.model_time_range`: the finite values
    gathered, their min and max, padded by 1 % (at least a day)."""
    finite = [float(v) for v in list(t_begin_days) + list(t_end_days) if np.isfinite(v)]
    if not finite:
        return None
    pad = max(1.0, 0.01 * (max(finite) - min(finite)))
    return min(finite) - pad, max(finite) + pad


def reference_pack_nodes(axis, child, first, split):
    """Twin of :func:`cityshade.accel.kdtree_layout.pack_nodes`: the two words with numpy
    (child shifted over the axis; a leaf's first index, else the split's float32 bits)."""
    from cityshade.accel.kdtree_layout import AXIS_BITS, LEAF_CODE

    axis, child = np.asarray(axis, np.int64), np.asarray(child, np.int64)
    split_bits = np.asarray(split, np.float32).view(np.uint32)
    return np.stack([((child << AXIS_BITS) | axis).astype(np.uint32),
                     np.where(axis == LEAF_CODE, np.asarray(first, np.int64).astype(np.uint32),
                              split_bits)], axis=1)


def reference_cache_bytes(header, arrays):
    """The bytes of a cache file, as :func:`cityshade.store.cache.write_cache` lays it out, written
    the obvious way: every checksum first, then prefix, header, padding and arrays in order."""
    import hashlib
    import json

    from cityshade.store.cache import _ALIGN, _PREFIX, FORMAT_VERSION, MAGIC

    arrays = {k: np.ascontiguousarray(v) for k, v in arrays.items()}
    directory, offset = {}, 0
    for name, a in arrays.items():
        directory[name] = {"dtype": a.dtype.str, "shape": list(a.shape), "offset": offset,
                           "nbytes": int(a.nbytes),
                           "blake2b": hashlib.blake2b(a.tobytes(), digest_size=16).hexdigest()}
        offset += -(-a.nbytes // _ALIGN) * _ALIGN
    full = dict(header, arrays=directory)
    data_start = 0
    while True:
        full["data_start"], full["file_size"] = data_start, data_start + offset
        blob = json.dumps(full, sort_keys=True, separators=(",", ":")).encode("utf-8")
        needed = -(-(_PREFIX.size + len(blob)) // _ALIGN) * _ALIGN
        if needed == data_start:
            break
        data_start = needed
    out = bytearray(_PREFIX.pack(MAGIC, FORMAT_VERSION, 0, len(blob),
                                 hashlib.blake2b(blob, digest_size=16).digest()) + blob)
    out += b"\0" * (data_start - len(out))
    for a in arrays.values():
        out += a.tobytes() + b"\0" * (-a.nbytes % _ALIGN)
    return bytes(out)


def reference_ndc_bounds(matrix, points):
    """(smallest w, lo (3,), hi (3,)) of the NDC coordinates of ``points`` (N, 3) under a (4, 4)
    matrix, with numpy, in the kernel's sum order (``warps.ndc_bounds``' twin)."""
    m = np.asarray(matrix, np.float64)
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    w = x * m[3, 0] + y * m[3, 1] + z * m[3, 2] + m[3, 3]
    c = np.stack([(x * m[k, 0] + y * m[k, 1] + z * m[k, 2] + m[k, 3]) / w for k in range(3)],
                 axis=1)
    return float(w.min()), c.min(axis=0), c.max(axis=0)


def reference_boundary(lit, valid, faces, refined):
    """Twin of ``cityshade.shadows.hybrid.boundary_todo``: valid candidates with a valid
    4-neighbour of the other class, by shifted copies (no wrap-around), then the facing and
    not yet refined ones."""
    binary = np.asarray(lit) >= 0.5
    valid = np.asarray(valid, bool)
    out = np.zeros_like(valid)
    h, w = valid.shape
    for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
        nb_bin = np.zeros_like(binary)
        nb_ok = np.zeros_like(valid)
        rs, rd = (slice(0, h - dr), slice(dr, h)) if dr >= 0 else (slice(-dr, h), slice(0, h + dr))
        cs, cd = (slice(0, w - dc), slice(dc, w)) if dc >= 0 else (slice(-dc, w), slice(0, w + dc))
        nb_bin[rd, cd] = binary[rs, cs]
        nb_ok[rd, cd] = valid[rs, cs]
        out |= valid & nb_ok & (nb_bin != binary)
    return out & np.asarray(faces, bool) & ~np.asarray(refined, bool)


def reference_classifier_polygons(scene, fold_rad=1e-3, min_area_m2=1e-4):
    """Twin of ``cityshade.shadows.hybrid.classifier_polygons``: a polygon is folded when one
    of its triangles of at least ``min_area_m2`` has a normal more than ``fold_rad`` off the
    polygon's; triangles of folded polygons get ids of their own (polygon count + index)."""
    v = np.asarray(scene.vertices, np.float64)
    tri = np.asarray(scene.triangles)
    poly = np.asarray(scene.tri_polygon)
    n = np.cross(v[tri[:, 1]] - v[tri[:, 0]], v[tri[:, 2]] - v[tri[:, 0]])
    length = np.linalg.norm(n, axis=1)
    pn = np.asarray(scene.poly_normal, np.float64)[poly]
    off = np.abs((n * pn).sum(axis=1)) < np.cos(fold_rad) * length
    folded = np.zeros(len(scene.poly_normal), bool)
    folded[poly[(length >= 2 * min_area_m2) & off]] = True
    return np.where(folded[poly], len(scene.poly_normal) + np.arange(len(tri)), poly)


def reference_sky_bits(scene, points, normals, sky, t_days, engine):
    """Packed sky visibility bits, the obvious way: per direction, the receivers in front of it
    gathered, their shadow rays traced, the answers in an unpacked (N, P) table, packed."""
    from cityshade.light.sky import in_front
    from cityshade.shadows.visibility import occluded
    from cityshade.trace import shadow_rays_from_surface

    points = np.asarray(points, np.float64)
    normals = np.asarray(normals, np.float64)
    seen = np.zeros((len(points), sky.n), bool)
    front = in_front(normals, sky.directions)
    for j, d in enumerate(sky.directions):
        rows = np.flatnonzero(front[:, j])
        if len(rows):
            origins = shadow_rays_from_surface(points[rows], normals[rows], d)
            seen[rows, j] = ~occluded(scene, origins, d, t_days, engine=engine)
    return np.packbits(seen, axis=1)


def reference_patch_weights(sky, unit_normals, k, luminance):
    """Twin of :func:`cityshade.light.kernels.patch_weight_rows` (via
    :func:`cityshade.light.metrics.patch_weights`), by the definition: every subsample of every
    patch, ``max(0, n · d) L(d) dΩ``, into its own patch when the patch's centre is in front,
    else into the front centre nearest the subsample, the first of those within
    ``NEAREST_TIE`` of the nearest (no shortcut for whole patches)."""
    from cityshade.light.kernels import NEAREST_TIE
    from cityshade.light.sky import in_front

    d, w = sky.subsamples(k)
    lw = w * luminance(d)
    centres = np.asarray(sky.directions, np.float64)
    unit = np.asarray(unit_normals, np.float64)
    front = in_front(unit, centres)
    out = np.zeros((len(unit), sky.n))
    for u, n in enumerate(unit):
        cand = np.flatnonzero(front[u])
        for p in range(sky.n):
            for s in range(d.shape[1]):
                f = max(float(d[p, s] @ n), 0.0) * lw[p, s]
                if front[u, p]:
                    out[u, p] += f
                elif f > 0.0 and len(cand):
                    dots = [float(d[p, s] @ centres[c]) for c in cand]
                    near = [c for c, dot in zip(cand, dots) if dot >= max(dots) - NEAREST_TIE]
                    out[u, near[0]] += f
    return out


def reference_visible_weight_sums(bits, inverse, weights):
    """Twin of :func:`cityshade.light.kernels.visible_weight_sums`: the bits unpacked, then per
    receiver a plain loop adding the visible directions' weights in order."""
    seen = np.unpackbits(np.asarray(bits), axis=1, count=weights.shape[1]).astype(bool)
    out = np.zeros(len(seen))
    for i, row in enumerate(seen):
        s = 0.0
        for p in np.flatnonzero(row):
            s += float(weights[inverse[i], p])
        out[i] = s
    return out


def reference_tile_order(ranges, tile, ntx):
    """Twin of :func:`cityshade.lightspace.kernels.tile_order`: each caster's row when the
    casters are stably sorted by the tile (``tile`` cells square, ``ntx`` tiles per row) of
    their range's first cell (ix0 = ranges[:, 0], iy0 = ranges[:, 2])."""
    ranges = np.asarray(ranges)
    first = (ranges[:, 2] // tile) * ntx + ranges[:, 0] // tile
    order = np.argsort(first, kind="stable")
    dest = np.empty(len(first), np.int64)
    dest[order] = np.arange(len(first))
    return dest


def reference_refs_per_size(boxes, sizes):
    """Twin of :func:`cityshade.lightspace.refs_per_size` of the density grid's box sums: the
    sum over the boxes (x0, x1, y0, y1; NaN x0: culled) of (w / s + 1) (h / s + 1), box by box
    and size by size."""
    out = []
    for s in sizes:
        total = 0.0
        for x0, x1, y0, y1 in boxes:
            if not np.isnan(x0):
                total += ((x1 - x0) / s + 1.0) * ((y1 - y0) / s + 1.0)
        out.append(total)
    return np.array(out)


def reference_all_vertex_box(vertices):
    """Twin of :func:`cityshade.geometry.bounds.all_vertex_box`: numpy's min and max of each
    column, as float64."""
    v = np.asarray(vertices)
    return np.stack([v.min(axis=0), v.max(axis=0)]).astype(np.float64)
