"""Front-to-back kd-tree walk for the rasterizer: time filtering, frustum and occlusion culling.

The thesis slides' "Rendering" section: the kd-tree is drawn front to back; nodes outside the
view frustum are skipped (box against the 6 planes), time splits send the walk only into the
child that holds the city time (whole subtrees of demolished or not yet built buildings go at
once), and occlusion culling follows Coherent Hierarchical Culling (Bittner et al. 2004) with
*software* occlusion queries: a node's box is tested against a hierarchical max-depth buffer of
what has been drawn so far, and skipped when every pixel it could cover already holds a surface
strictly nearer than the box's nearest point. Leaves emit their triangles in stored order, which
the kd-tree layout sorts by material ("draw batches").

A subtree that lies entirely inside the frustum and is too small to be queried is emitted by
one linear scan of its references, which the layout keeps contiguous (depth-first order), with
the records' own validity as the time filter. The walk is resumable: :func:`walk` stops after emitting about ``max_out`` triangles, the
caller rasterizes them (which refines the max-depth buffer) and calls it again with the same
stack. Culling never removes a visible triangle: a triangle's visible sample lies in some leaf
cell the frustum test keeps (boxes are padded), and the occlusion test is strict and padded.
"""
from __future__ import annotations

import weakref

import numpy as np
from numba import njit

from cityshade.runtime.interpret import InterpretBudget, twin_if
from cityshade.accel.kdtree_layout import (LEAF_CODE, TIME_AXIS, leaf_first, node_split,
                                           node_word, record_present, word_axis, word_payload)

#: Walk stack entries: the walk pops one node and pushes at most two, so it holds at most one
#: entry per tree level plus one; the build caps the depth at 60.
STACK_SIZE = 128
#: Padding of node boxes in the frustum test, relative to the scene size: float32 vertices and
#: float64 plane evaluation differ by far less, so the test stays conservative.
FRUSTUM_PAD_REL = 1e-5
#: A node box is occluded only when its nearest point is farther than every covering depth by
#: this relative margin (stored depths are float32: 6e-8 relative rounding) ...
OCCLUSION_REL = 1e-5
#: ... plus this absolute margin in metres.
OCCLUSION_ABS_M = 1e-4
#: Queries whose pixel rectangle covers more blocks than this read the coarser tile maxima
#: instead (conservative: a tile's maximum bounds its blocks').
QUERY_MAX_BLOCKS = 64
#: Nodes with fewer triangle references below them than this are drawn without a query: a
#: query (8 corner projections and a rectangle of reads) costs about as much as drawing 2-3
#: small triangles, so small nodes cannot win much; 64 gave the fastest occlusion-culled
#: passes on the 1M-triangle city's views (benchmarks/render.py; 8 and 512 were slower).
QUERY_MIN_REFS = 64

# Indices of the statistics vector filled by :func:`walk`.
ST_NODES_VISITED = 0
ST_LEAVES_DRAWN = 1
ST_TIME_SUBTREES = 2
ST_TIME_REFS = 3
ST_FRUSTUM_NODES = 4
ST_FRUSTUM_REFS = 5
ST_OCCLUSION_QUERIES = 6
ST_OCCLUSION_NODES = 7
ST_OCCLUSION_REFS = 8
ST_DUPLICATE_REFS = 9
ST_EMITTED = 10
N_STATS = 11
#: Names of the statistics; "leaves_drawn" counts leaves and whole in-frustum subtrees scanned.
STAT_NAMES = ("nodes_visited", "leaves_drawn", "time_subtrees_skipped", "time_refs_removed",
              "frustum_nodes_culled", "frustum_refs_removed", "occlusion_queries",
              "occlusion_nodes_culled", "occlusion_refs_removed", "duplicate_refs",
              "triangles_drawn")


@njit(cache=True)
def _subtree_info(tree):
    """Per node: triangle references below it and, when those references form one contiguous
    range of the leaf-ordered records, the range's first index (else -1); and the largest
    leaf's count."""
    m = tree.nodes.shape[0]
    refs = np.zeros(m, np.int64)
    lo = np.empty(m, np.int64)
    hi = np.empty(m, np.int64)
    biggest = 0
    # Children always have larger indices than their parent (left = i + 1), so one backward
    # pass sees both children before the parent.
    for i in range(m - 1, -1, -1):
        w0 = node_word(tree, i)
        if word_axis(w0) == LEAF_CODE:
            count = word_payload(w0)
            refs[i] = count
            biggest = max(biggest, count)
            if count > 0:
                lo[i] = leaf_first(tree, i)
                hi[i] = lo[i] + count
            else:
                lo[i] = np.iinfo(np.int64).max
                hi[i] = -1
        else:
            left = i + 1
            right = word_payload(w0)
            refs[i] = refs[left] + refs[right]
            lo[i] = min(lo[left], lo[right])
            hi[i] = max(hi[left], hi[right])
    first = np.full(m, -1, np.int64)
    for i in range(m):
        if refs[i] > 0 and hi[i] - lo[i] == refs[i]:
            first[i] = lo[i]
    return refs, first, biggest


_TREE_INFO: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def tree_info(tree) -> tuple[np.ndarray, np.ndarray, int]:
    """(subtree reference counts (M,), first index of each subtree's contiguous reference range
    or -1 (M,), largest leaf size) of a KdTree, computed once per tree."""
    info = _TREE_INFO.get(tree)
    if info is None:
        refs, first, biggest = _subtree_info(tree.views)
        info = (refs, first, int(biggest))
        _TREE_INFO[tree] = info
    return info


def frustum_planes(camera, pad_m: float) -> np.ndarray:
    """(6, 4) float64 planes ``(n, d)`` with unit ``n``; inside is ``n . p + d >= -pad``.

    The side planes pass 1.5 pixels outside the image edges, so boxes touching the border
    are kept, and ``pad_m`` metres are added to every ``d`` (the test is conservative).
    """
    right, up, fwd = camera.frame()
    eye = np.asarray(camera.eye_m, np.float64)
    xs, ys = camera.screen_coordinates()
    planes = np.empty((6, 4))
    if camera.kind == "map":
        px = camera.pixel_size_m
        x0, x1 = xs[0] - 1.5 * px, xs[-1] + 1.5 * px
        y1, y0 = ys[0] + 1.5 * px, ys[-1] - 1.5 * px
        normals = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, -1), (0, 0, 1)]
        offsets = [-x0, x1, -y0, y1, eye[2] - camera.near_m, camera.far_m - eye[2]]
        for i in range(6):
            planes[i, :3] = normals[i]
            planes[i, 3] = offsets[i]
    else:
        p = camera.pitch
        x0, x1 = xs[0] - 1.5 * p, xs[-1] + 1.5 * p
        y1, y0 = ys[0] + 1.5 * p, ys[-1] - 1.5 * p
        side = [right - x0 * fwd, -right + x1 * fwd, up - y0 * fwd, -up + y1 * fwd]
        for i, n in enumerate(side):
            n = n / np.linalg.norm(n)
            planes[i, :3] = n
            planes[i, 3] = -n @ eye
        planes[4, :3] = fwd
        planes[4, 3] = -fwd @ eye - camera.near_m
        planes[5, :3] = -fwd
        planes[5, 3] = fwd @ eye + camera.far_m
    planes[:, 3] += pad_m
    return planes


@njit(cache=True)
def box_outside(planes, lo, hi, mask):
    """Test the box ``[lo, hi]`` against the planes whose bit is set in ``mask``.

    Returns ``(outside, mask)``: ``outside`` when the box lies entirely outside one plane;
    the returned mask drops the planes the box lies entirely inside, so the children of a
    node inside the frustum skip those tests (plane masking).
    """
    for i in range(planes.shape[0]):
        if not (mask >> i) & 1:
            continue
        # The box corners farthest along and against the plane normal.
        far = planes[i, 3]
        near = planes[i, 3]
        for a in range(3):
            n = planes[i, a]
            far += n * (hi[a] if n > 0.0 else lo[a])
            near += n * (lo[a] if n > 0.0 else hi[a])
        if far < 0.0:
            return True, mask
        if near >= 0.0:
            mask &= ~(1 << i)
    return False, mask


#: Box tests a process runs through :func:`box_outside`'s Python source from Python (the
#: model's box against a view, a tiled scene's tiles) while it is neither compiled nor cached
#: (:mod:`cityshade.runtime.interpret`): about 10 µs a test against 0.25 s to compile.
_INTERPRET_OUTSIDE = InterpretBudget(20_000, box_outside)


def outside_view(planes, lo, hi, mask):
    """:func:`box_outside` called from Python: its interpreted twin while a first use's tests
    are few (the same operations on doubles and integers: the same answer, tested)."""
    return twin_if(_INTERPRET_OUTSIDE.take(1), box_outside)(planes, lo, hi, mask)


@njit(cache=True)
def box_occluded(lo, hi, cam, hiz_block, hiz_tile, block_px, tile_px):
    """Software occlusion query: is every pixel the box could cover already nearer?

    ``cam`` is the rasterizer's parameter vector (:func:`cityshade.raster.rasterize.camera_params`);
    ``hiz_block`` / ``hiz_tile`` hold the maximum stored depth of each ``block_px`` /
    ``tile_px`` square (``inf`` while any of its pixels is empty).
    """
    w = int(cam[20])
    h = int(cam[21])
    if cam[0] != 0.0:
        # Map: depth is the distance below the camera plane.
        xmin, xmax, ymin, ymax = lo[0], hi[0], lo[1], hi[1]
        dmin = cam[15] - hi[2]
    else:
        # Perspective: the box's nearest point bounds the distance along every pixel ray.
        dd = 0.0
        for a in range(3):
            e = cam[1 + a]
            g = max(lo[a] - e, 0.0, e - hi[a])
            dd += g * g
        dmin = np.sqrt(dd)
        if dmin <= 0.0:
            return False
        xmin = np.inf
        xmax = -np.inf
        ymin = np.inf
        ymax = -np.inf
        for corner in range(8):
            px = hi[0] if corner & 1 else lo[0]
            py = hi[1] if corner & 2 else lo[1]
            pz = hi[2] if corner & 4 else lo[2]
            dx = px - cam[1]
            dy = py - cam[2]
            dz = pz - cam[3]
            z = cam[10] * dx + cam[11] * dy + cam[12] * dz
            if z < cam[13]:
                return False    # the box reaches the near plane: no projection bound
            x = (cam[4] * dx + cam[5] * dy + cam[6] * dz) / z
            y = (cam[7] * dx + cam[8] * dy + cam[9] * dz) / z
            xmin = min(xmin, x)
            xmax = max(xmax, x)
            ymin = min(ymin, y)
            ymax = max(ymax, y)
    # Pixel rectangle (one pixel of slack on each side), clamped to the image.
    c0 = max(np.floor(cam[16] * xmin + cam[17]) - 1.0, 0.0)
    c1 = min(np.ceil(cam[16] * xmax + cam[17]) + 1.0, w - 1.0)
    r0 = max(np.floor(cam[18] * ymax + cam[19]) - 1.0, 0.0)
    r1 = min(np.ceil(cam[18] * ymin + cam[19]) + 1.0, h - 1.0)
    if c0 > c1 or r0 > r1:
        return False        # off screen: the frustum test's business, never cull here
    ic0 = int(c0)
    ic1 = int(c1)
    ir0 = int(r0)
    ir1 = int(r1)
    bx0 = ic0 // block_px
    bx1 = ic1 // block_px
    by0 = ir0 // block_px
    by1 = ir1 // block_px
    if (bx1 - bx0 + 1) * (by1 - by0 + 1) > QUERY_MAX_BLOCKS:
        for ty in range(ir0 // tile_px, ir1 // tile_px + 1):
            for tx in range(ic0 // tile_px, ic1 // tile_px + 1):
                d = np.float64(hiz_tile[ty, tx])
                if d * (1.0 + OCCLUSION_REL) + OCCLUSION_ABS_M >= dmin:
                    return False
        return True
    for by in range(by0, by1 + 1):
        for bx in range(bx0, bx1 + 1):
            d = np.float64(hiz_block[by, bx])
            if d * (1.0 + OCCLUSION_REL) + OCCLUSION_ABS_M >= dmin:
                return False
    return True


@njit(cache=True)
def walk(tree, info, t_days, planes, order_point, occlusion, stack, drawn, out, max_out, stats):
    """Walk the tree front to back and emit the triangles to draw; resumable.

    Parameters
    ----------
    tree : KdViews
        The flat tree (:mod:`cityshade.accel.kdtree_layout`).
    info : (subtree_refs, subtree_first)
        (M,) int64 each, from :func:`tree_info`: reference counts (for the statistics) and
        contiguous reference ranges (a subtree entirely inside the frustum is emitted by one
        linear scan of its range when no occlusion queries are made).
    t_days : float
        City time; a triangle is drawn when ``begin <= t_days < end``.
    planes : (P, 4) float64
        Culling planes (:func:`frustum_planes` or a light view's), inside ``n . p + d >= 0``.
    order_point : (4,) float64
        Homogeneous point that fixes the walk order: ``(x, y, z, 1)``, children nearer the
        point first (a camera's eye); ``(dx, dy, dz, 0)``, children nearer a viewer infinitely
        far along the direction first (a map camera, a light).
    occlusion : None or (query_min_refs, cam, hiz_block, hiz_tile, block_px, tile_px)
        Software occlusion queries (:func:`box_occluded`) of nodes with at least
        ``query_min_refs`` references below them (see ``QUERY_MIN_REFS``); None makes none.
    stack : (st_node (STACK_SIZE,) int64, st_box (STACK_SIZE, 6) float64,
             st_mask (STACK_SIZE,) int64, state (1,) int64)
        The walk stack (node, box, planes still to test) and its pointer, kept by the caller
        between calls (start: the root, its box, all plane bits and ``state[0] = 1``).
    drawn : (T,) uint8
        Triangles already emitted (the tree lists straddling triangles in several leaves).
    out : (max_out + largest leaf,) int32
        Receives the record indices (into ``prim_indices`` / the triangle records) of the
        triangles to draw, in walk order.
    stats : (N_STATS,) int64
        Accumulated counts (``STAT_NAMES``).

    Returns
    -------
    int
        Number of indices written to ``out``; the walk is finished when ``state[0] == 0``.
    """
    subtree_refs, subtree_first = info
    st_node, st_box, st_mask, state = stack
    sp = state[0]
    n_out = 0
    lo = np.empty(3)
    hi = np.empty(3)
    at_infinity = order_point[3] == 0.0
    while sp > 0 and n_out < max_out:
        # Pop the nearest pending node.
        sp -= 1
        node = st_node[sp]
        mask = st_mask[sp]
        for a in range(3):
            lo[a] = st_box[sp, a]
            hi[a] = st_box[sp, 3 + a]
        stats[ST_NODES_VISITED] += 1
        outside, mask = box_outside(planes, lo, hi, mask)
        if outside:
            stats[ST_FRUSTUM_NODES] += 1
            stats[ST_FRUSTUM_REFS] += subtree_refs[node]
            continue
        queried = False
        if occlusion is not None:
            if subtree_refs[node] >= occlusion[0]:
                queried = True
                stats[ST_OCCLUSION_QUERIES] += 1
                if box_occluded(lo, hi, occlusion[1], occlusion[2], occlusion[3], occlusion[4],
                                occlusion[5]):
                    stats[ST_OCCLUSION_NODES] += 1
                    stats[ST_OCCLUSION_REFS] += subtree_refs[node]
                    continue
        w0 = node_word(tree, node)
        axis = word_axis(w0)
        first = -1
        count = 0
        if axis == LEAF_CODE:
            first = leaf_first(tree, node)
            count = word_payload(w0)
        elif (mask == 0 and not queried and subtree_first[node] >= 0
              and subtree_refs[node] <= out.shape[0] - n_out):
            # Inside the frustum and too small for queries: nothing below can be culled but by
            # time, and the records' own validity does that; scan the subtree's range at once.
            first = subtree_first[node]
            count = subtree_refs[node]
        if first >= 0:
            # Emit the triangles present at t_days, each triangle once.
            stats[ST_LEAVES_DRAWN] += 1
            for k in range(first, first + count):
                if not record_present(tree, k, t_days):
                    stats[ST_TIME_REFS] += 1
                    continue
                tri = tree.prim_indices[k]
                if drawn[tri]:
                    stats[ST_DUPLICATE_REFS] += 1
                    continue
                drawn[tri] = 1
                out[n_out] = k
                n_out += 1
            continue
        split = node_split(tree, node)
        right = word_payload(w0)
        if axis == TIME_AXIS:
            # Only the child holding t_days can have triangles present at t_days.
            keep = node + 1 if t_days < split else right
            drop = right if t_days < split else node + 1
            stats[ST_TIME_SUBTREES] += 1
            stats[ST_TIME_REFS] += subtree_refs[drop]
            st_node[sp] = keep
            st_mask[sp] = mask
            for a in range(3):
                st_box[sp, a] = lo[a]
                st_box[sp, 3 + a] = hi[a]
            sp += 1
            continue
        # Spatial split: push the far child first so the near child is walked first.
        if at_infinity:
            left_first = order_point[axis] <= 0.0   # the viewer lies towards -axis (or across)
        else:
            left_first = order_point[axis] < split
        for side in range(2):
            is_left = (side == 1) == left_first
            st_node[sp] = node + 1 if is_left else right
            st_mask[sp] = mask
            for a in range(3):
                st_box[sp, a] = lo[a]
                st_box[sp, 3 + a] = hi[a]
            if is_left:
                st_box[sp, 3 + axis] = split
            else:
                st_box[sp, axis] = split
            sp += 1
    state[0] = sp
    stats[ST_EMITTED] += n_out
    return n_out
