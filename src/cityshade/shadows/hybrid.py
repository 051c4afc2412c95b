"""``hybrid[:BASE]``: a shadow map for the rough answer, exact rays for the uncertain pixels.

The thesis' central idea (slides "Shadows"): shadow maps are fast but alias; ray tracing is
exact. Use the map to classify every visible pixel as surely lit, surely in shadow, or
uncertain, and trace shadow rays only for the uncertain ones. Writes the "refine image" (which
pixels were traced) as the EXR channel ``refined``.

Classifiers (``[shadows.hybrid] classifier``):

``bracket`` (default)
    For each receiver, look at the base's depth-map texels within one texel of its true surface
    point. Surely lit: no texel there holds a caster in front of the point (casters of its own
    polygon aside), also in a second map of the triangles thinner than two texels in light
    space (walls edge-on to a low sun fall between texel centres of a point-sampled map).
    Surely in shadow: every texel holds a caster in front and all come from one polygon. A
    planar polygon whose depth lies in front of the receiver's plane at the texel centres
    around the receiver covers the receiver's light-space point (it lies within the centres'
    hull) in front of it, so no light passes there; two polygons side by side, even of one
    building, may leave a gap narrower than a texel between them, which no texel centre
    sees (a lit channel between two building parts). Everything else — casters in front and
    clear texels (a shadow edge), or several casters (a possible gap) — is uncertain. This is
    the slides' "better shadow edge detection": it looks at the map's depth discontinuities
    and caster changes, not at the filtered answer.
``vsm``
    The slides' original: uncertain where the base's filtered lit fraction lies strictly
    between ``low`` and ``high``. Kept to measure how many edge pixels it misses.

Either way, a final boundary pass traces every not-yet-traced pixel that touches a pixel of
the other class (4-neighbourhood), repeatedly, until no boundary pixel is untraced (bounded by
``max_boundary_passes``): every shadow boundary in the result is verified by rays on both sides.

Pixels facing away from the sun are shadow by the shared rule and never traced.
What remains wrong can only be a mistaken region that touches no verified boundary: a gap or a
caster narrower than a texel, inside a region the map calls sure; a caster that the
receiver's own polygon hides at the texel centres (on real LoD2 files, 12 suns at 4
elevations, two maps and an overview: 11 pixels of the Lyon opera's 288 frames, none of the
Munich CityGML 3.0 tile's, TUM campus's or PLATEAU roads'). Receivers almost along the sun's
rays (:data:`GRAZING_COS`) are traced. ``cityshade evaluate`` counts those misses against
``raytrace``.
"""
from __future__ import annotations

import math
import time

import numba
import numpy as np
from numba import njit, prange

from cityshade.shadows import (ShadowContext, ShadowResult, TechniqueDiagnostics, hybrid_base,
                               take_pixels)
from cityshade.shadows.shadowmap import clip_point, plane_depth_gradient
from cityshade.trace.kernels import hit_triangle, on_axes, ray_shear
from cityshade.runtime.memory import Recycler, Scratch

#: Receiver states of the classifiers. PROVEN_SHADOW: uncertain by the map, but its shadow ray
#: hits one of the casters the map holds around it (the tracer's own watertight test of those
#: few triangles): shadow, exactly as a traced ray finds it, without the traversal.
SURE_LIT, SURE_SHADOW, UNCERTAIN, PROVEN_SHADOW = 0, 1, 2, 3


#: Triangles whose light-space height (2·area / longest edge) is below this many texels can fall
#: between texel centres and vanish from a point-sampled depth map: they go into the thin-caster
#: map too (2 leaves a texel of margin over the 1-texel worst case).
THIN_TEXELS = 2.0
#: Slivers, whose longest edge exceeds this many times their light-space height (longest² >
#: ratio · 2·area), go into the thin map too, however high: near their acute tip they are
#: thinner than a texel for several texels (a roof sliver 85 texels long and 3 high on the
#: Munich CityGML 3.0 tile, map at 1/400 of its side, sun 90°/3°, shaded one pixel between
#: texel centres: the one miss of the bracket classifier found on the shared files).
SLIVER_RATIO = 8.0
#: A thin triangle is splatted on every texel whose square comes within this many texels of
#: it (a margin for the rounding of its projection and of the receivers').
THIN_MARGIN_TEXELS = 1e-3


@njit(cache=True, parallel=True)
def _project_vertices(vertices, m, width, height, out):
    """(V, 4) ``out``: each vertex's column, row and NDC depth in the light view of clip matrix
    ``m`` (16,), and its clip W (the point is in front of the light where W > 0). Once per
    vertex for every triangle that uses it (the 1M city: 1.23 M vertices against 3 M corners),
    in a loop that vectorises."""
    for q in prange(vertices.shape[0]):
        x = np.float64(vertices[q, 0])
        y = np.float64(vertices[q, 1])
        z = np.float64(vertices[q, 2])
        cw = m[12] * x + m[13] * y + m[14] * z + m[15]
        out[q, 0] = ((m[0] * x + m[1] * y + m[2] * z + m[3]) / cw + 1.0) * 0.5 * width
        out[q, 1] = (1.0 - (m[4] * x + m[5] * y + m[6] * z + m[7]) / cw) * 0.5 * height
        out[q, 2] = (m[8] * x + m[9] * y + m[10] * z + m[11]) / cw
        out[q, 3] = cw


@njit(cache=True, parallel=True)
def _thin_boxes(light, triangles, t_begin, t_end, t_days, width, height, blocks, limit, box,
                zmin):
    """Every triangle present at ``t_days`` (``t_begin <= t_days < t_end``) in the light view
    (its vertices' ``light``: :func:`_project_vertices`); for the thin ones, the texels their
    bounding box touches, within :data:`THIN_MARGIN_TEXELS` (``box`` col0, col1, row0, row1;
    col0 > col1 for the others, for boxes off the map, for boxes that reach no block of
    :func:`_needed_blocks`'s ``blocks`` and, when ``limit`` (H, W) is not empty, for
    triangles not in front of the limit at any texel of their box), and their nearest
    depth."""
    limited = limit.shape[0] > 0
    for i in prange(triangles.shape[0]):
        box[i, 0] = 1
        box[i, 1] = 0
        if not (t_begin[i] <= t_days and t_days < t_end[i]):
            continue
        q0, q1, q2 = triangles[i, 0], triangles[i, 1], triangles[i, 2]
        if not (light[q0, 3] > 0.0 and light[q1, 3] > 0.0 and light[q2, 3] > 0.0):
            continue
        u0, v0, z0 = light[q0, 0], light[q0, 1], light[q0, 2]
        u1, v1, z1 = light[q1, 0], light[q1, 1], light[q1, 2]
        u2, v2, z2 = light[q2, 0], light[q2, 1], light[q2, 2]
        # Light-space height in texels: 2·area / longest edge.
        e1u, e1v = u1 - u0, v1 - v0
        e2u, e2v = u2 - u0, v2 - v0
        e3u, e3v = u2 - u1, v2 - v1
        area2 = abs(e1u * e2v - e2u * e1v)
        longest = math.sqrt(max(e1u * e1u + e1v * e1v, e2u * e2u + e2v * e2v,
                                e3u * e3u + e3v * e3v))
        # Thin, or a sliver: its acute tip is thinner than a texel for several texels.
        if longest > 0.0 and area2 / longest >= THIN_TEXELS and (
                longest * longest < SLIVER_RATIO * area2):
            continue
        z = min(z0, z1, z2)
        if not z <= 1.0:
            continue
        c0 = max(int(math.floor(min(u0, u1, u2) - THIN_MARGIN_TEXELS)), 0)
        c1 = min(int(math.floor(max(u0, u1, u2) + THIN_MARGIN_TEXELS)), width - 1)
        r0 = max(int(math.floor(min(v0, v1, v2) - THIN_MARGIN_TEXELS)), 0)
        r1 = min(int(math.floor(max(v0, v1, v2) + THIN_MARGIN_TEXELS)), height - 1)
        if c0 > c1 or r0 > r1:
            continue
        # No needed texel near the box: nothing to splat (the splat tests each texel).
        if not _reaches_a_block(blocks, c0, c1, r0, r1):
            continue
        # The least depth the splat can write for it is its nearest vertex's as float32.
        if limited and not _in_front_somewhere(limit, c0, c1, r0, r1, np.float32(z)):
            continue
        box[i, 0], box[i, 1], box[i, 2], box[i, 3] = c0, c1, r0, r1
        zmin[i] = z


#: Row bands of the thin-caster splat: each band applies, in id order, the splats that touch
#: it, so every texel sees the serial order and the map is the same for any thread count.
THIN_BANDS = 64


@njit(cache=True, parallel=True)
def _thin_splat(light, triangles, box, zmin, poly, band_start, band_items, needed, d1, p1, d2,
                p2):
    """Splat the thin triangles over the texels whose squares they touch (a conservative
    rasterization: every edge's half-plane reaches the square, within the margin), each texel
    getting a lower bound of the triangle's depth over its square (the depth plane's minimum
    there less a margin that covers float32 rounding, at least the nearest vertex's depth as
    float32), in id order (the lowest id wins ties); per
    texel the nearest polygon (d1, p1) and the nearest of every other polygon (d2, p2).
    Parallel over row bands (:func:`_band_lists`: each band's triangles in id order)."""
    h, w = d1.shape
    bands = band_start.size - 1
    for b in prange(bands):
        b0 = b * h // bands
        b1 = (b + 1) * h // bands
        # Each band clears its own rows: the fresh map's pages are first touched in parallel.
        d1[b0:b1] = np.inf
        p1[b0:b1] = -1
        d2[b0:b1] = np.inf
        p2[b0:b1] = -1
        edges = np.empty((3, 7))
        for j in range(band_start[b], band_start[b + 1]):
            i = band_items[j]
            q0, q1, q2 = triangles[i, 0], triangles[i, 1], triangles[i, 2]
            u0, v0, z0 = light[q0, 0], light[q0, 1], light[q0, 2]
            u1, v1, z1 = light[q1, 0], light[q1, 1], light[q1, 2]
            u2, v2, z2 = light[q2, 0], light[q2, 1], light[q2, 2]
            # Depth is affine in texel coordinates over a planar triangle (also under a
            # perspective warp): z = z0 + a (u - u0) + b (v - v0), unless it is seen edge-on.
            e1u, e1v, e2u, e2v = u1 - u0, v1 - v0, u2 - u0, v2 - v0
            det = e1u * e2v - e2u * e1v
            flat = abs(det) <= 1e-9 * (abs(e1u * e2v) + abs(e2u * e1v))
            a = bb = 0.0
            if not flat:
                a = ((z1 - z0) * e2v - (z2 - z0) * e1v) / det
                bb = ((z2 - z0) * e1u - (z1 - z0) * e2u) / det
                flat = not (np.isfinite(a) and np.isfinite(bb))
            _thin_edges(u0, v0, u1, v1, u2, v2, 1.0 if det > 0.0 else -1.0, flat, edges)
            # Lowest plane depth over a square is its centre's minus half the slopes; the
            # margin: 1 % of a texel's depth change and the float32 depth's rounding.
            half = 0.5 * (abs(a) + abs(bb)) + 0.01 * (abs(a) + abs(bb)) + 1e-6
            q = poly[i]
            for r in range(max(box[i, 2], b0), min(box[i, 3] + 1, b1)):
                for c in range(box[i, 0], box[i, 1] + 1):
                    if not needed[r, c]:
                        continue
                    inside = True
                    for k in range(3):
                        # The inner-side edge function at the square's most inward corner.
                        f = (edges[k, 2] * (c + edges[k, 4] - edges[k, 0])
                             + edges[k, 3] * (r + edges[k, 5] - edges[k, 1]))
                        if f < edges[k, 6]:
                            inside = False
                            break
                    if not inside:
                        continue
                    z = zmin[i]
                    if not flat:
                        zc = z0 + a * (c + 0.5 - u0) + bb * (r + 0.5 - v0) - half
                        if zc > z:
                            z = zc
                    z32 = np.float32(z)
                    if q == p1[r, c]:
                        if z32 < d1[r, c]:
                            d1[r, c] = z32
                    elif q == p2[r, c]:
                        if z32 < d2[r, c]:
                            d2[r, c] = z32
                            if z32 < d1[r, c]:
                                d1[r, c], d2[r, c] = d2[r, c], d1[r, c]
                                p1[r, c], p2[r, c] = p2[r, c], p1[r, c]
                    elif z32 < d1[r, c]:
                        d2[r, c], p2[r, c] = d1[r, c], p1[r, c]
                        d1[r, c], p1[r, c] = z32, q
                    elif z32 < d2[r, c]:
                        d2[r, c], p2[r, c] = z32, q


#: Side in texels of the blocks of the needed-texel mask that lets :func:`_thin_boxes` skip a
#: triangle with no needed texel near it (a small table, where a per-texel summed-area table of
#: a 2048² map was 33 MB of fresh pages per frame).
NEEDED_BLOCK_TEXELS = 8


@njit(cache=True, parallel=True)
def _needed_blocks(needed):
    """(ceil(H / B), ceil(W / B)) bool: whether block (r // B, c // B) of
    :data:`NEEDED_BLOCK_TEXELS` holds a needed texel."""
    h, w = needed.shape
    side = NEEDED_BLOCK_TEXELS
    out = np.zeros(((h + side - 1) // side, (w + side - 1) // side), np.bool_)
    for br in prange(out.shape[0]):
        for r in range(br * side, min((br + 1) * side, h)):
            for c in range(w):
                if needed[r, c]:
                    out[br, c // side] = True
    return out


@njit(cache=True, inline="always")
def _reaches_a_block(blocks, c0, c1, r0, r1):
    side = NEEDED_BLOCK_TEXELS
    for br in range(r0 // side, r1 // side + 1):
        for bc in range(c0 // side, c1 // side + 1):
            if blocks[br, bc]:
                return True
    return False


@njit(cache=True, inline="always")
def _in_front_somewhere(limit, c0, c1, r0, r1, z):
    for r in range(r0, r1 + 1):
        # A whole row at a time, without an exit per texel: the row loop vectorises.
        front = False
        for c in range(c0, c1 + 1):
            front |= z < limit[r, c]
        if front:
            return True
    return False


@njit(cache=True, parallel=True)
def _fill_rows(a, value):
    for r in prange(a.shape[0]):
        a[r, :] = value


@njit(cache=True, parallel=True)
def _raise_limits(own_texel, z_limit, n_parts, limit):
    # Part p raises only the texels of its own share of the map (each part reads every
    # receiver): two threads raising one texel would race for the maximum.
    flat = limit.reshape(-1)
    share = (flat.size + n_parts - 1) // n_parts
    for p in prange(n_parts):
        k0 = p * share
        k1 = k0 + share
        for i in range(own_texel.shape[0]):
            k = own_texel[i]
            if k0 <= k < k1:
                z = np.float32(z_limit[i])
                if z < z_limit[i]:
                    z = np.nextafter(z, np.float32(np.inf))
                if z > flat[k]:
                    flat[k] = z


def texel_limits(own_texel, z_limit, limit) -> None:
    """``limit`` (H, W) float32: at each receiver's texel ``own_texel`` (flat, -1 for none) the
    largest ``z_limit`` of the receivers there, rounded up to float32 (a caster's float32 depth
    is below it when it is below the receiver's), elsewhere -inf (no caster matters there)."""
    _fill_rows(limit, np.float32(-np.inf))
    _raise_limits(own_texel, z_limit, numba.get_num_threads(), limit)


@njit(cache=True)
def _band_lists(box, h, bands):
    """(starts (bands + 1,), items): per row band (rows b h // bands to (b + 1) h // bands) the
    triangles whose box reaches it, in id order (a counting sort), so that each band reads
    only its own."""
    band_of = np.empty(h, np.int64)
    for b in range(bands):
        band_of[b * h // bands:(b + 1) * h // bands] = b
    counts = np.zeros(bands + 1, np.int64)
    for i in range(box.shape[0]):
        if box[i, 0] <= box[i, 1]:
            for b in range(band_of[box[i, 2]], band_of[box[i, 3]] + 1):
                counts[b + 1] += 1
    for b in range(bands):
        counts[b + 1] += counts[b]
    items = np.empty(counts[bands], np.int32)
    fill = counts[:bands].copy()
    for i in range(box.shape[0]):
        if box[i, 0] <= box[i, 1]:
            for b in range(band_of[box[i, 2]], band_of[box[i, 3]] + 1):
                items[fill[b]] = i
                fill[b] += 1
    return counts, items


@njit(cache=True, inline="always")
def _set_edge(edges, k, pu, pv, qu, qv, sgn):
    """Row k: edge p→q's start, inner normal (inner side ``sgn``), the offsets of the texel
    square's corner that maximises the inner edge function, and the margin (negative)."""
    eu, ev = qu - pu, qv - pv
    nu, nv = -sgn * ev, sgn * eu
    edges[k, 0], edges[k, 1], edges[k, 2], edges[k, 3] = pu, pv, nu, nv
    edges[k, 4] = 1.0 if nu > 0.0 else 0.0
    edges[k, 5] = 1.0 if nv > 0.0 else 0.0
    edges[k, 6] = -THIN_MARGIN_TEXELS * math.sqrt(eu * eu + ev * ev)


@njit(cache=True, inline="always")
def _thin_edges(u0, v0, u1, v1, u2, v2, sgn, flat, edges):
    """The three half-planes of a projected triangle's conservative coverage; a triangle seen
    edge-on (``flat``) is its longest edge, a segment: both sides of its line, and no third."""
    if flat:
        l01 = (u1 - u0) ** 2 + (v1 - v0) ** 2
        l02 = (u2 - u0) ** 2 + (v2 - v0) ** 2
        l12 = (u2 - u1) ** 2 + (v2 - v1) ** 2
        if l01 >= l02 and l01 >= l12:
            pu, pv, qu, qv = u0, v0, u1, v1
        elif l02 >= l12:
            pu, pv, qu, qv = u0, v0, u2, v2
        else:
            pu, pv, qu, qv = u1, v1, u2, v2
        _set_edge(edges, 0, pu, pv, qu, qv, 1.0)
        _set_edge(edges, 1, pu, pv, qu, qv, -1.0)
        _set_edge(edges, 2, pu, pv, pu, pv, 1.0)    # zero edge: always reached
    else:
        _set_edge(edges, 0, u0, v0, u1, v1, sgn)
        _set_edge(edges, 1, u1, v1, u2, v2, sgn)
        _set_edge(edges, 2, u2, v2, u0, v0, sgn)


#: The thin-caster maps' and texel polygons' memory (used again once the caller drops them) and
#: the per-triangle temporaries of :func:`thin_caster_map`.
_THIN_MAPS = Recycler(keep=6)
_THIN_SCRATCH = Scratch()
#: :func:`bracket_states`'s per-receiver temporaries.
_BRACKET_SCRATCH = Scratch()


def thin_caster_map(scene, view, t_days: float, needed=None,
                    limit=None) -> tuple[np.ndarray, ...]:
    """(depth, polygon, second depth, second polygon), each (H, W) (float32, int32), of the
    triangles present at ``t_days`` that are thinner than :data:`THIN_TEXELS` in the light
    view or slivers (:data:`SLIVER_RATIO`) — the casters a point-sampled depth map may miss entirely (walls seen edge-on by a
    low sun). Per texel: the nearest polygon, and the nearest of all other polygons (+inf,
    -1 where none), so that a receiver whose own polygon is the nearest still sees another's
    thin caster under it (a 2-cm step between two roof polygons of the Munich CityGML 3.0
    tile, sun 240°/10°, hid behind a sliver of the receiver's own roof).

    ``needed`` (H, W) bool: make it only there (other texels stay empty); triangles whose box
    reaches no block of :data:`NEEDED_BLOCK_TEXELS` with a needed texel are skipped whole.
    ``limit`` (H, W) float32: only casters nearer than it matter (:func:`texel_limits` of the
    lit receivers' depths; -inf where none), so a triangle whose nearest depth (as float32)
    is not in front of the limit at any texel of its box is left out (on the 1M
    city's 1080p overview, three in four thin triangles; on its 2049² map, nine in ten). A
    needed texel then holds every caster nearer than its limit, and maybe some others: the
    nearest polygon of the others in front of the limit is the full map's."""
    h, w = view.height_px, view.width_px
    needed = (np.ones((h, w), np.bool_) if needed is None
              else np.ascontiguousarray(needed, np.bool_))
    blocks = _needed_blocks(needed)
    thin = (_THIN_MAPS.empty((h, w), np.float32), _THIN_MAPS.empty((h, w), np.int32),
            _THIN_MAPS.empty((h, w), np.float32), _THIN_MAPS.empty((h, w), np.int32))
    n = scene.triangles.shape[0]
    m = np.ascontiguousarray(view.clip_from_world.reshape(16), np.float64)
    # Per-triangle and per-vertex temporaries of every frame (a 1M-triangle city: 24 + 39 MB),
    # kept: fresh pages were faulted in anew each time.
    work = _THIN_SCRATCH.take()
    try:
        box = work.get("box", (n, 4), np.int32)
        zmin = work.get("zmin", n)
        light = work.get("light", (scene.vertices.shape[0], 4))
        _project_vertices(scene.vertices, m, float(w), float(h), light)
        _thin_boxes(light, scene.triangles, np.asarray(scene.tri_t_begin_days, np.float64),
                    np.asarray(scene.tri_t_end_days, np.float64), float(t_days), w, h, blocks,
                    np.zeros((0, 0), np.float32) if limit is None else limit, box, zmin)
        band_start, band_items = _band_lists(box, h, min(THIN_BANDS, h))
        _thin_splat(light, scene.triangles, box, zmin, classifier_polygons(scene), band_start,
                    band_items, needed, *thin)
    finally:
        work.give_back()
    return thin


@njit(cache=True, parallel=True)
def _bracket_kernel(m, width, height, depth, prim, texel_poly, points, normals, sun,
                    offset_rel, min_scale_m, own_poly, radius, vertices, triangles, state,
                    own_texel, z_limit, needed):
    """Classify receivers from the depth-map texels around their true surface points, in one
    pass per receiver: its shadow-ray origin (:func:`cityshade.trace.shadow_rays_from_surface`'s
    offset, the arithmetic of :func:`cityshade.trace.bricks.shadow_origins`), its projection
    (:func:`~cityshade.shadows.shadowmap.project`'s), its tangent plane's depth gradient (that
    of :func:`~cityshade.shadows.shadowmap.receiver_plane_gradient`), then the texels, until
    the answer is known.

    A texel occludes a receiver when its caster lies in front of the receiver's tangent plane
    at that texel (``z_surface + dz_du Δu + dz_dv Δv - tol``) and belongs to another polygon.
    Surfaces in the receiver's own plane (its polygon, coplanar neighbours on a roof slope)
    therefore never count, while anything rising above the plane does. Surely lit: no texel
    within ``radius`` occludes (and, decided by :func:`_thin_kernel` afterwards, no thin caster
    covers the receiver's point: ``own_texel``, its texel's flat index or -1 off the map, and
    ``z_limit``, its depth less the tolerance, are kept for that, and ``needed``, (H·W,) bool
    all False on entry, marks those texels: the thin map is made only there). Surely in shadow:
    every texel within ``radius`` occludes and all come from one polygon (no gap between
    casters, however narrow, can let light through). Else uncertain. No bias is involved: the
    decision is about the exact surface point, within the map's one-texel position accuracy.

    An uncertain receiver with occluding texels then tests its shadow ray (origin and
    direction as traced) against their triangles with the tracer's watertight test: a hit
    makes it PROVEN_SHADOW, the answer every exact engine gives (any hit occludes).
    """
    h, w = depth.shape
    kx, ky, kz, sx, sy, sz = ray_shear(sun[0], sun[1], sun[2])
    for i in prange(points.shape[0]):
        px, py, pz = points[i, 0], points[i, 1], points[i, 2]
        nx, ny, nz = normals[i, 0], normals[i, 1], normals[i, 2]
        offset = offset_rel * max(max(max(abs(px), abs(py)), abs(pz)), min_scale_m)
        px = px + (nx + sun[0]) * offset
        py = py + (ny + sun[1]) * offset
        pz = pz + (nz + sun[2]) * offset
        u_s, v_s, z_s = clip_point(m, px, py, pz, width, height)
        # A non-finite lookup cannot be decided from the map, nor a surface almost along the
        # sun's rays (its plane's tolerance grows as 1 / N·L).
        own_texel[i] = -1
        if not (np.isfinite(u_s) and np.isfinite(v_s) and np.isfinite(z_s)) or (
                normals[i, 0] * sun[0] + normals[i, 1] * sun[1] + normals[i, 2] * sun[2]
                < GRAZING_COS):
            state[i] = UNCERTAIN
            continue
        # Two tangents of the receiver's plane, 1 cm long (receiver_plane_gradient's helper
        # axis z, or x for a nearly vertical normal).
        if abs(nz) < 0.9:
            ax, ay, az = ny, -nx, 0.0
        else:
            ax, ay, az = 0.0, nz, -ny
        la = math.sqrt(ax * ax + ay * ay + az * az)
        ax, ay, az = ax / la, ay / la, az / la
        bx, by, bz = ny * az - nz * ay, nz * ax - nx * az, nx * ay - ny * ax
        # A plane holding the light's rays (seen edge-on) gets no gradient: the own-polygon
        # rule alone decides.
        dz_du, dz_dv = plane_depth_gradient(m, width, height, px, py, pz, u_s, v_s, z_s,
                                            ax, ay, az, bx, by, bz)
        tol = _PLANE_TOL_NDC + _PLANE_TOL_SLOPE * (abs(dz_du) + abs(dz_dv))
        own = own_poly[i]
        cu = int(np.floor(u_s))
        cv = int(np.floor(v_s))
        occluding = 0
        clear = 0
        near = 0
        first_poly = -2
        mixed = False
        decided = False
        # Another polygon's caster less than the plane's change across the window behind the
        # plane at a texel centre may still cover the receiver's point in front of it.
        band = (radius + 0.5) * (abs(dz_du) + abs(dz_dv))
        for dv in range(-radius, radius + 1):
            row = cv + dv
            if decided:
                break
            for du in range(-radius, radius + 1):
                # Occluded somewhere and clear (or a second caster) somewhere: uncertain,
                # whatever the other texels hold.
                if occluding > 0 and (clear > 0 or mixed):
                    decided = True
                    break
                col = cu + du
                # Outside the map nothing was drawn: empty, i.e. no caster there.
                if row < 0 or row >= h or col < 0 or col >= w:
                    clear += 1
                    continue
                # The receiver's plane at this texel's centre.
                plane = (z_s + dz_du * (col + 0.5 - u_s) + dz_dv * (row + 0.5 - v_s) - tol)
                tp = texel_poly[row, col]
                if depth[row, col] < plane and tp != own:
                    occluding += 1
                    if first_poly == -2:
                        first_poly = tp
                    elif tp != first_poly:
                        mixed = True
                else:
                    clear += 1
                    if tp != own and depth[row, col] < min(plane + band, z_s):
                        near += 1
        if occluding == 0 and near > 0 and _hits_a_window_caster(
                depth, prim, texel_poly, vertices, triangles, cu, cv, radius, u_s, v_s, z_s,
                dz_du, dz_dv, tol, own, band, z_s, px, py, pz, kx, ky, kz, sx, sy, sz):
            # Lit at every texel centre, but the ray hits one of those casters: near the line
            # where a steep receiver's plane meets another polygon's (a roof at the corner of
            # two others on the TUM campus and the Munich CityGML 3.0 tile).
            state[i] = PROVEN_SHADOW
        elif occluding == 0:
            # Lit unless a thin caster covers its light-space point: the second pass reads
            # its own texel of the thin map, against its own depth.
            state[i] = SURE_LIT
            if 0 <= cv < h and 0 <= cu < w:
                own_texel[i] = cv * w + cu
                z_limit[i] = z_s - tol
                needed[cv * w + cu] = True      # every thread writes the same True
        elif clear == 0 and not mixed:
            state[i] = SURE_SHADOW
        else:
            state[i] = UNCERTAIN
            if _hits_a_window_caster(
                    depth, prim, texel_poly, vertices, triangles, cu, cv, radius, u_s, v_s,
                    z_s, dz_du, dz_dv, tol, own, 0.0, np.inf, px, py, pz, kx, ky, kz, sx, sy,
                    sz):
                state[i] = PROVEN_SHADOW


@njit(cache=True, parallel=True)
def _thin_kernel(thin_depth, thin_poly, thin_depth2, own_poly, own_texel, z_limit, state):
    """Second pass: a lit receiver becomes uncertain when a thin caster of another polygon may
    cover its light-space point (the map's lower bound of its depth over the receiver's texel
    lies in front of the receiver). The nearest thin caster of another polygon: the nearest
    one, or the nearest of the others when that is the receiver's own."""
    depth1 = thin_depth.reshape(-1)
    poly1 = thin_poly.reshape(-1)
    depth2 = thin_depth2.reshape(-1)
    for i in prange(own_texel.shape[0]):
        k = own_texel[i]
        if k < 0:
            continue
        other = depth1[k] if poly1[k] != own_poly[i] else depth2[k]
        if other < z_limit[i]:
            state[i] = UNCERTAIN


@njit(cache=True, inline="always")
def _occluder_hit(depth, prim, texel_poly, vertices, triangles, row, col, u_s, v_s, z_s,
                  dz_du, dz_dv, tol, own, band, z_max, last, okx, oky, okz, kx, ky, kz, sx, sy,
                  sz):
    """(triangle tested or ``last``, hit): the watertight test of texel (row, col)'s triangle
    when it is another polygon's caster less than ``band`` behind the receiver's plane (0: in
    front of it, an occluding texel) and in front of ``z_max``, and is not ``last``, the one
    tested just before."""
    t = prim[row, col]
    if t < 0 or t == last or texel_poly[row, col] == own:
        return last, False
    plane = (z_s + dz_du * (col + 0.5 - u_s) + dz_dv * (row + 0.5 - v_s) - tol)
    if not depth[row, col] < min(plane + band, z_max):
        return last, False
    hit, t_hit, _, _ = hit_triangle(vertices, triangles, t, okx, oky, okz, kx, ky, kz,
                                    sx, sy, sz)
    return t, hit and t_hit >= 0.0


@njit(cache=True, inline="always")
def _hits_a_window_caster(depth, prim, texel_poly, vertices, triangles, cu, cv, radius, u_s,
                          v_s, z_s, dz_du, dz_dv, tol, own, band, z_max, ox, oy, oz, kx, ky, kz,
                          sx, sy, sz):
    """Whether the shadow ray from ``o`` hits (t >= 0) the triangle of a window texel holding
    another polygon's caster less than ``band`` behind the receiver's plane and in front of
    ``z_max`` (0 and inf: the bracket test's occluding texels; a run of texels of one triangle
    is tested once). The receiver's own texel first: its caster is the likeliest hit."""
    h, w = depth.shape
    okx, oky, okz = on_axes(ox, oy, oz, kx, ky, kz)
    last = -1
    if 0 <= cv < h and 0 <= cu < w:
        last, hit = _occluder_hit(depth, prim, texel_poly, vertices, triangles, cv, cu, u_s, v_s,
                                  z_s, dz_du, dz_dv, tol, own, band, z_max, last, okx, oky, okz,
                                  kx, ky, kz, sx, sy, sz)
        if hit:
            return True
    for row in range(max(cv - radius, 0), min(cv + radius + 1, h)):
        for col in range(max(cu - radius, 0), min(cu + radius + 1, w)):
            if row == cv and col == cu:
                continue
            last, hit = _occluder_hit(depth, prim, texel_poly, vertices, triangles, row, col,
                                      u_s, v_s, z_s, dz_du, dz_dv, tol, own, band, z_max, last,
                                      okx, oky, okz, kx, ky, kz, sx, sy, sz)
            if hit:
                return True
    return False


#: A polygon with a triangle (of at least :data:`FOLD_MIN_AREA_M2`) whose normal is more than
#: this many radians off the polygon's normal is folded: the own-polygon exception assumes a
#: plane, and a ray from one triangle of a folded polygon can hit another (PLATEAU's road
#: polygons, draped over the terrain, fold by 0.03-0.3 rad: 555 pixels of one tile's overview
#: were wrongly lit). The classifier gives each triangle of a folded polygon its own id.
FOLD_RAD = 1e-3
#: Smaller triangles are left out of the fold test (their float32 normals are rounding).
FOLD_MIN_AREA_M2 = 1e-4


@njit(cache=True)
def _classifier_ids(vertices, triangles, tri_polygon, poly_normal, cos_fold, min_area2, out):
    folded = np.zeros(poly_normal.shape[0], np.bool_)
    for t in range(triangles.shape[0]):
        q0, q1, q2 = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        ax = np.float64(vertices[q1, 0]) - vertices[q0, 0]
        ay = np.float64(vertices[q1, 1]) - vertices[q0, 1]
        az = np.float64(vertices[q1, 2]) - vertices[q0, 2]
        bx = np.float64(vertices[q2, 0]) - vertices[q0, 0]
        by = np.float64(vertices[q2, 1]) - vertices[q0, 1]
        bz = np.float64(vertices[q2, 2]) - vertices[q0, 2]
        nx, ny, nz = ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx
        norm = math.sqrt(nx * nx + ny * ny + nz * nz)
        if norm < min_area2:
            continue
        p = tri_polygon[t]
        pn = poly_normal[p]
        if abs(nx * pn[0] + ny * pn[1] + nz * pn[2]) < cos_fold * norm:
            folded[p] = True
    n_poly = poly_normal.shape[0]
    for t in range(triangles.shape[0]):
        p = tri_polygon[t]
        out[t] = n_poly + t if folded[p] else p


_CLASSIFIER_IDS: dict = {}


def classifier_polygons(scene) -> np.ndarray:
    """(T,) int32: each triangle's polygon for the classifier's own-polygon and one-polygon
    rules, or, for a triangle of a folded polygon (:data:`FOLD_RAD`), an id of its own
    (polygon count + triangle). Made once per scene (its numpy twin is ``tests/reference.py``'s
    ``reference_classifier_polygons``)."""
    import weakref

    held = _CLASSIFIER_IDS.get(id(scene))
    if held is not None and held[0]() is scene:
        return held[1]
    for key in [k for k, (ref, _) in _CLASSIFIER_IDS.items() if ref() is None]:
        del _CLASSIFIER_IDS[key]
    out = np.empty(scene.triangles.shape[0], np.int32)
    _classifier_ids(scene.vertices, scene.triangles, np.asarray(scene.tri_polygon),
                    np.ascontiguousarray(scene.poly_normal, np.float64),
                    math.cos(FOLD_RAD), 2.0 * FOLD_MIN_AREA_M2, out)
    _CLASSIFIER_IDS[id(scene)] = (weakref.ref(scene), out)
    return out


@njit(cache=True, parallel=True)
def _texel_polygons_kernel(prim, tri_polygon, out):
    for r in prange(prim.shape[0]):
        for c in range(prim.shape[1]):
            t = prim[r, c]
            out[r, c] = tri_polygon[t] if t >= 0 else -1


def texel_polygons(prim_id, tri_polygon) -> np.ndarray:
    """(H, W) int32 polygon of each depth-map texel's triangle (-1 where empty): looked up once
    per texel instead of once per receiver and window texel."""
    prim = np.asarray(prim_id)
    out = _THIN_MAPS.empty(prim.shape, np.int32)
    _texel_polygons_kernel(prim, np.asarray(tri_polygon), out)
    return out


#: Depth tolerance of the coplanarity test: the float32 depth map's rounding (≈ 1.2e-7 per NDC
#: unit near 1) with margin, plus 1 % of the plane's depth change per texel (texel centres and
#: the tangent-plane fit are exact only to that).
_PLANE_TOL_NDC = 1e-6
_PLANE_TOL_SLOPE = 0.01
#: Receivers whose N·L is below this (within 0.06° of the sun's rays) are left to the rays: a
#: roof of the Munich CityGML 3.0 tile at N·L 0.0002 (sun 157°/12°) had a tolerance larger
#: than the depth gap to the sliver that shades it. On that frame 0.8 % of the facing pixels
#: have N·L below 0.01.
GRAZING_COS = 1e-3


def bracket_states(depth_map, scene, points_m, normals, own_poly, sun_direction,
                   radius_texels: int, t_days: float, thin_map=None) -> np.ndarray:
    """(N,) uint8 receiver states from one depth map (its numpy twin is ``tests/reference.py``'s
    ``reference_bracket_states``).

    ``own_poly`` (N,) are the receivers' :func:`classifier_polygons` (-1 for the ground plane,
    which has no triangle); the surface
    point is the shadow-ray origin (pushed off its surface by the tracer's tiny offset). The
    thin-caster map (:func:`thin_caster_map` of the same view at ``t_days``) is made only on
    the texels of the receivers the depth map calls lit, the only ones it can change; or pass
    a whole one as ``thin_map``.
    """
    points = np.ascontiguousarray(points_m, np.float64).reshape(-1, 3)
    normals = np.ascontiguousarray(normals, np.float64).reshape(-1, 3)
    own_poly = np.ascontiguousarray(own_poly, np.int32)
    n = points.shape[0]
    state = np.empty(n, np.uint8)
    if not n:
        return state
    work = _BRACKET_SCRATCH.take()
    try:
        return _bracket_states(depth_map, scene, points, normals, own_poly, sun_direction,
                               radius_texels, t_days, thin_map, state, work)
    finally:
        work.give_back()


def _bracket_states(depth_map, scene, points, normals, own_poly, sun_direction, radius_texels,
                    t_days, thin_map, state, work):
    """:func:`bracket_states` on checked arrays, its per-receiver temporaries in ``work``."""
    from cityshade.trace import SHADOW_OFFSET_MIN_SCALE_M, SHADOW_OFFSET_REL

    view = depth_map.view
    n = points.shape[0]
    own_texel = work.get("own_texel", n, np.int32)   # MAX_MAP_PX² < 2^31
    z_limit = work.get("z_limit", n)
    needed = np.zeros(view.height_px * view.width_px, np.bool_)
    _bracket_kernel(np.ascontiguousarray(view.clip_from_world.reshape(16), np.float64),
                    float(view.width_px), float(view.height_px),
                    np.asarray(depth_map.depth), np.asarray(depth_map.prim_id),
                    texel_polygons(depth_map.prim_id, classifier_polygons(scene)), points,
                    normals,
                    np.ascontiguousarray(sun_direction, np.float64).reshape(3),
                    SHADOW_OFFSET_REL, SHADOW_OFFSET_MIN_SCALE_M, own_poly, int(radius_texels),
                    scene.vertices, scene.triangles, state, own_texel, z_limit, needed)
    if thin_map is None:
        shape = (view.height_px, view.width_px)
        limit = work.get("limit", shape, np.float32)
        texel_limits(own_texel, z_limit, limit)
        thin_map = thin_caster_map(scene, view, t_days, needed.reshape(shape), limit)
    _thin_kernel(thin_map[0], thin_map[1], thin_map[2], own_poly, own_texel, z_limit, state)
    return state


#: Uncertain pixels from which the light-space engine (``izb``) refines them instead of the
#: kd-tree's shadow rays: both give the same answer, bit for bit, but izb pays a per-call setup
#: (projecting and binning every caster over the receivers' light-plane box, which for pixels
#: scattered over a whole view is the whole city) that only many receivers repay. Measured on
#: the 1M-triangle city, sun 135°/30°, CPU time at one thread, random facing pixels of the
#: 1080p overview / the 2049² map (kd-tree against izb, ms): 100k 40 / 44 against 112 / 114;
#: 400k 108 / 123 against 137 / 142; map 800k 206 against 175, 1.6M 346 against 227.
IZB_REFINE_MIN_RAYS = 600_000


def refine_engine(n_rays: int):
    """(name, sunlit function) of the exact engine that refines ``n_rays`` uncertain pixels:
    ``izb`` from :data:`IZB_REFINE_MIN_RAYS` on, else ``raytrace``
    (:func:`cityshade.shadows.visibility.sunlit`: the same answer either way)."""
    import functools

    from cityshade.shadows.visibility import sunlit

    name = "izb" if n_rays >= IZB_REFINE_MIN_RAYS else "raytrace"
    return name, functools.partial(sunlit, engine=name)


@njit(cache=True, inline="always")
def _is_boundary(lit, valid, faces, refined, r, c):
    """Pixel (r, c) is facing, valid, not yet refined and has a valid 4-neighbour of the other
    class (lit >= 0.5 or not)."""
    h, w = lit.shape
    if not (valid[r, c] and faces[r, c]) or refined[r, c]:
        return False
    b = lit[r, c] >= 0.5
    if r > 0 and valid[r - 1, c] and (lit[r - 1, c] >= 0.5) != b:
        return True
    if r + 1 < h and valid[r + 1, c] and (lit[r + 1, c] >= 0.5) != b:
        return True
    if c > 0 and valid[r, c - 1] and (lit[r, c - 1] >= 0.5) != b:
        return True
    return c + 1 < w and valid[r, c + 1] and (lit[r, c + 1] >= 0.5) != b


@njit(cache=True, parallel=True)
def _boundary_kernel(lit, valid, faces, refined, out):
    """``out``: the untraced facing pixels with a valid 4-neighbour of the other class."""
    for r in prange(lit.shape[0]):
        for c in range(lit.shape[1]):
            out[r, c] = _is_boundary(lit, valid, faces, refined, r, c)


@njit(cache=True)
def _boundary_near_kernel(lit, valid, faces, refined, traced):
    """Flat indices (ascending) of the boundary pixels among the 4-neighbours of ``traced``."""
    h, w = lit.shape
    seen = np.zeros(h * w, np.uint8)
    out = np.empty(4 * traced.shape[0], np.int64)
    n = 0
    for i in range(traced.shape[0]):
        r0, c0 = traced[i] // w, traced[i] % w
        for k in range(4):
            r = r0 - 1 if k == 0 else (r0 + 1 if k == 1 else r0)
            c = c0 - 1 if k == 2 else (c0 + 1 if k == 3 else c0)
            if r < 0 or r >= h or c < 0 or c >= w:
                continue
            q = r * w + c
            if seen[q]:
                continue
            seen[q] = 1
            if _is_boundary(lit, valid, faces, refined, r, c):
                out[n] = q
                n += 1
    return np.sort(out[:n])


def boundary_todo(lit, valid, faces, refined, near=None) -> np.ndarray:
    """(N,) int64 flat indices, ascending, of the facing, valid, not yet refined pixels next to
    a valid pixel of the other class (4-neighbourhood; its numpy twin is
    ``tests/reference.py``'s ``reference_boundary``).

    ``near``: the flat indices traced since the last call, whose 4-neighbours are then the only
    pixels looked at. The same answer as the whole frame: a pixel that was no boundary pixel
    (and is not traced) can only become one when a neighbour's class changed, i.e. was traced.
    """
    args = (np.ascontiguousarray(lit), np.ascontiguousarray(valid, np.bool_),
            np.ascontiguousarray(faces, np.bool_), np.ascontiguousarray(refined, np.bool_))
    if near is not None:
        return _boundary_near_kernel(*args, np.ascontiguousarray(near, np.int64))
    out = np.empty(lit.shape, np.bool_)
    _boundary_kernel(*args, out)
    return np.flatnonzero(out)


@njit(cache=True, parallel=True)
def _receiver_polygons(prim, at, polygon_of, out):
    """``out[i]``: the classifier polygon of the triangle pixel ``at[i]`` shows (-1 where none)."""
    for i in prange(at.shape[0]):
        t = prim[at[i]]
        out[i] = polygon_of[t] if t >= 0 else -1


@njit(cache=True, parallel=True)
def _scatter_states(at, states, lit, refined, uncertain):
    """The states of the pixels at flat indices ``at`` into the flat images: lit = 1 where surely
    lit, refined where proven shadow, uncertain where uncertain (each pixel's three set anew)."""
    for i in prange(at.shape[0]):
        k = at[i]
        lit[k] = np.float32(1.0) if states[i] == SURE_LIT else np.float32(0.0)
        refined[k] = states[i] == PROVEN_SHADOW
        uncertain[k] = states[i] == UNCERTAIN


def _apply_states(at, states, lit, refined, uncertain) -> None:
    """:func:`_scatter_states` on the (H, W) images."""
    _scatter_states(np.ascontiguousarray(at, np.int64), np.ascontiguousarray(states, np.uint8),
                    lit.reshape(-1), refined.reshape(-1), uncertain.reshape(-1))


class Hybrid:
    """``hybrid:BASE``: BASE's map(s) classify, exact rays decide the uncertain pixels."""

    def __init__(self, base: str = "vsm"):
        from cityshade.shadows import get_map_technique

        hybrid_base(base)  # the registry refuses a base that is not a map technique
        self.base_name = base
        self.base = get_map_technique(base)
        self.name = f"hybrid:{base}"

    def run(self, ctx: ShadowContext) -> ShadowResult:
        """The base's maps and the rays decide the opaque casters; crowns as partial shade on
        top (:func:`~cityshade.shadows.visibility.with_crowns`)."""
        from cityshade.shadows.visibility import with_crowns

        return with_crowns(self._run, ctx)

    def _run(self, ctx: ShadowContext) -> ShadowResult:
        settings = ctx.settings.hybrid
        t0 = time.perf_counter()
        # The bracket classifier needs the base's map(s) only, not its filtered answer.
        if settings.classifier == "bracket":
            prepared = self.base.prepare(ctx)
            base_diagnostics = TechniqueDiagnostics(technique=self.base.name).update(
                prepared.diagnostics)
            maps = prepared.maps
            base_lit = None
        else:
            base = self.base.run(ctx)
            base_diagnostics, maps, base_lit = base.diagnostics, base.maps, base.lit
        t1 = time.perf_counter()
        surfaces = ctx.surfaces
        shape = surfaces.valid.shape
        lit = np.zeros(shape, np.float32)
        refined = np.zeros(shape, bool)
        diagnostics = TechniqueDiagnostics(technique=self.name, base=base_diagnostics,
                                           classifier=settings.classifier)
        if not ctx.sun.above_horizon:
            diagnostics.update(traced_px=0, traced_share=0.0, note="sun below the horizon")
            return ShadowResult(lit=lit, diagnostics=diagnostics,
                                extra_channels={"refined": refined.astype(np.float32)})
        faces = ctx.faces
        # 1. Classify facing pixels (facing pixels no map covers stay shadow, untraced):
        # surely lit ones get lit = 1, proven shadow ones are refined, uncertain ones traced.
        uncertain = np.zeros(shape, bool)
        # The uncertain pixels' receivers, when one map classified every facing pixel: taken
        # from the gathered ones (no second pass over the frame).
        todo_rays = None
        if settings.classifier == "bracket" and maps:
            prim = np.ascontiguousarray(surfaces.prim_id, np.int32).reshape(-1)
            for use in maps:
                # A single map serves the facing pixels themselves: their gathered receivers.
                mask = faces if use.pixels is faces else use.pixels & faces
                at = np.flatnonzero(mask)
                if at.size:
                    points, normals = ctx.receivers(mask)
                    own_poly = np.empty(at.shape[0], np.int32)
                    _receiver_polygons(prim, at, classifier_polygons(ctx.scene), own_poly)
                    states = bracket_states(
                        use.depth_map, ctx.scene, points, normals, own_poly, ctx.sun.direction,
                        settings.extra_texels, ctx.t_days)
                    _apply_states(at, states, lit, refined, uncertain)
                    if len(maps) == 1:
                        sel = np.flatnonzero(states == UNCERTAIN)
                        todo_rays = (at[sel], take_pixels(points, sel),
                                     take_pixels(normals, sel))
            classifier_used = "bracket"
        else:
            b = self.base.look_up(ctx, prepared) if base_lit is None else base_lit
            bf = b[faces]
            _apply_states(np.flatnonzero(faces), np.where(
                bf >= settings.high, SURE_LIT,
                np.where(bf <= settings.low, SURE_SHADOW, UNCERTAIN)).astype(np.uint8),
                lit, refined, uncertain)
            classifier_used = "vsm" if settings.classifier == "vsm" else "vsm (base exposes no map)"
        diagnostics.classifier = classifier_used
        t2 = time.perf_counter()

        engines: list[str] = []

        def trace(at: np.ndarray, points=None, normals=None) -> int:
            # Pixels at flat indices ``at`` (ascending), their receivers taken when not given.
            if points is None:
                points = take_pixels(surfaces.position_m, at)
                normals = take_pixels(ctx.normal, at)
            if not len(points):
                return 0
            engine, sunlit = refine_engine(len(points))
            engines.append(engine)
            lit.reshape(-1)[at] = sunlit(ctx.scene, points, normals, ctx.sun.direction,
                                         ctx.t_days)
            refined.reshape(-1)[at] = True
            return len(points)

        # 2. Exact rays for the uncertain pixels (the proven ones are decided: shadow).
        n_proven = int(np.count_nonzero(refined))
        n_uncertain = int(np.count_nonzero(uncertain))
        rays = trace(*(todo_rays or (np.flatnonzero(uncertain),)))
        # 3. Follow the boundaries: trace untraced pixels next to the other class until stable
        # (after the first pass only the neighbours of the pixels just traced can change).
        passes = 0
        boundary_rays = 0
        valid = np.asarray(surfaces.valid, bool)
        near = None
        while passes < settings.max_boundary_passes:
            todo = boundary_todo(lit, valid, faces, refined, near)
            if not todo.size:
                break
            boundary_rays += trace(todo)
            near = todo
            passes += 1
        t3 = time.perf_counter()
        n_facing = int(faces.sum())
        diagnostics.update(
            uncertain_px=n_uncertain + n_proven,
            proven_px=n_proven,
            boundary_px=boundary_rays, boundary_passes=passes,
            traced_px=rays + boundary_rays,
            traced_share=(rays + boundary_rays) / max(int(valid.sum()), 1),
            facing_px=n_facing,
            refined_with="+".join(dict.fromkeys(engines)) or None,
            map_px=base_diagnostics.map_px,
            texel_m=base_diagnostics.texel_m,
            aliasing_m=base_diagnostics.aliasing_m,
            shadow_s=t3 - t0,
            timings_s={"base_s": t1 - t0, "classify_s": t2 - t1, "rays_s": t3 - t2},
        )
        return ShadowResult(lit=lit, diagnostics=diagnostics,
                            extra_channels={"refined": refined.astype(np.float32)})
