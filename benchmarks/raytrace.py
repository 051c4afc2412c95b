"""Ray-tracing benchmark: our 4-D kd-tree against Embree 4 and Mitsuba 3 on one synthetic city.

Generates a seeded city of about one million triangles (gabled houses on a jittered grid with
construction and demolition dates, plus a ground plane), builds the kd-tree (seconds per million
triangles), then runs two workloads fixed by seed at the city time 2000-01-01:

* camera: a 1920x1080 perspective view, primary closest hits, then shadow rays from the lit
  hit points (normal facing the sun) towards a sun at elevation 30 deg, azimuth 135 deg;
* map: a 2048x2048 top-down grid of vertical primary rays, then shadow rays to the same sun.

Rays are traced in 16x16-pixel tile order (the same order for every engine). For each workload
it reports Mrays/s of closest-hit and any-hit rays at 1 and 2 threads (median of ``--runs``; the
any-hit and izb runs alternate 1 and 2 threads run by run),
and the exact shadow decisions/s of the light-space engine ``izb`` (``cityshade.lightspace``)
on the same shadow-ray origins, with the number of decisions that differ from the kd-tree's
(must be 0), its first-call time (caster records made once per tree) and its stage profile.
When ``embreex`` and ``mitsuba`` (``llvm_ad_rgb`` variant) are importable, the same triangles
(those present at the city time) and the same float32-rounded rays go through Embree 4
(``rtcOccluded1``/``rtcIntersect1`` via embreex; two threads = two Python threads on two halves,
embreex releases no work to a pool of its own) and Mitsuba 3 (``ray_test`` /
``ray_intersect_preliminary``, drjit thread count set per run); agreement with our results is
checked (>= 99.99 % of rays) and throughput ratios are printed. Prints a table and writes JSON.

With ``--profile`` it also counts the kd-tree any-hit's work per shadow ray (inner nodes, leaves,
records tested, caster-cache hits) with a one-thread measuring twin of the kernel, and prints
izb's phases (project, bin, query) with its cell size and tests per receiver.

Usage: python benchmarks/raytrace.py [--triangles 1000000] [--runs 3] [--json out.json]
       [--no-embree] [--no-mitsuba] [--profile] [--sweep-sah]
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

import numba
import numpy as np

from cityshade.accel import KdTreeSettings, build_kdtree
from cityshade.accel.kdtree_layout import (LEAF_CODE, TIME_AXIS, leaf_first, node_split,
                                           node_word, record_present, word_axis, word_payload)
from cityshade import lightspace
from cityshade.trace import intersect, occluded, shadow_rays_from_surface, tile_order
from cityshade.trace.kernels import (FAR_ONLY, NEAR_ONLY, STACK_SIZE, clip_to_box,
                                     hit_record, ray_shear, split_side)

DAY_2000 = 10957.0   # 2000-01-01 in days since 1970-01-01


def synthetic_city(n_triangles: int = 1_000_000, seed: int = 1):
    """A seeded city of gabled houses on a jittered grid, with a ground plane and dates.

    Each house is 18 triangles: 4 walls (the two gable walls are pentagons: 3 triangles each,
    the eave walls rectangles: 2 each), 2 roof planes (2 each), a floor (2) and two eave
    overhang strips (2 each). Returns (vertices (V, 3) float32, triangles (T, 3) int32,
    t_begin_days, t_end_days (T,) float64, material (T,) int32), T close to ``n_triangles``.
    """
    rng = np.random.default_rng(seed)
    per_house = 18
    n_houses = max(1, (n_triangles - 2) // per_house)
    side = int(np.ceil(np.sqrt(n_houses)))
    pitch_m = 20.0                                   # grid spacing: a block of 20 m
    gx, gy = np.meshgrid(np.arange(side), np.arange(side), indexing="ij")
    gx = gx.ravel()[:n_houses]
    gy = gy.ravel()[:n_houses]
    w = rng.uniform(6.0, 14.0, n_houses)             # footprint along x, metres
    d = rng.uniform(6.0, 14.0, n_houses)             # footprint along y
    h = rng.lognormal(np.log(9.0), 0.5, n_houses).clip(3.0, 80.0)   # eave height
    roof = rng.uniform(1.0, 5.0, n_houses)           # ridge above the eaves
    x0 = gx * pitch_m + rng.uniform(0.5, pitch_m - 14.5, n_houses)
    y0 = gy * pitch_m + rng.uniform(0.5, pitch_m - 14.5, n_houses)
    z0 = rng.normal(0.0, 0.5, n_houses)              # not all on one ground level
    x1 = x0 + w
    y1 = y0 + d
    zt = z0 + h
    ym = 0.5 * (y0 + y1)
    zr = zt + roof
    # Vertices per house: 0-3 floor corners, 4-7 eave corners, 8-9 ridge ends.
    v = np.stack([
        np.stack([x0, y0, z0], 1), np.stack([x1, y0, z0], 1), np.stack([x1, y1, z0], 1),
        np.stack([x0, y1, z0], 1), np.stack([x0, y0, zt], 1), np.stack([x1, y0, zt], 1),
        np.stack([x1, y1, zt], 1), np.stack([x0, y1, zt], 1), np.stack([x0, ym, zr], 1),
        np.stack([x1, ym, zr], 1)], axis=1)                        # (H, 10, 3)
    faces = np.array([
        (0, 2, 1), (0, 3, 2),                 # floor (facing down)
        (0, 1, 5), (0, 5, 4),                 # south wall
        (2, 3, 7), (2, 7, 6),                 # north wall
        (1, 2, 6), (1, 6, 5), (5, 6, 9),      # east gable wall
        (3, 0, 4), (3, 4, 7), (7, 4, 8),      # west gable wall
        (4, 5, 9), (4, 9, 8),                 # south roof
        (6, 7, 8), (6, 8, 9),                 # north roof
        (4, 8, 9), (6, 9, 8),                 # inner ridge triangles (closed attic)
    ], np.int64)
    tris = (faces[None, :, :] + 10 * np.arange(n_houses)[:, None, None]).reshape(-1, 3)
    verts = v.reshape(-1, 3)
    # Ground plane under the whole city, 2 triangles.
    ext = side * pitch_m
    g = np.array([[-10, -10, -2], [ext + 10, -10, -2], [ext + 10, ext + 10, -2],
                  [-10, ext + 10, -2]], np.float64)
    tris = np.concatenate([tris, np.array([[0, 1, 2], [0, 2, 3]]) + verts.shape[0]])
    verts = np.concatenate([verts, g])
    # Centre the city on the origin (render space is relative to the model centre).
    verts -= np.array([ext / 2, ext / 2, 0.0])
    # Construction dates: 70 % dated between 1850 and 2020, 10 % also demolished later.
    begin = np.full(n_houses, -np.inf)
    end = np.full(n_houses, np.inf)
    dated = rng.random(n_houses) < 0.7
    begin[dated] = rng.uniform(-43830.0, 18262.0, dated.sum())
    demolished = dated & (rng.random(n_houses) < 0.1)
    end[demolished] = begin[demolished] + rng.uniform(3650.0, 36500.0, demolished.sum())
    t_begin = np.concatenate([np.repeat(begin, per_house), [-np.inf, -np.inf]])
    t_end = np.concatenate([np.repeat(end, per_house), [np.inf, np.inf]])
    material = np.concatenate([np.tile(np.array([0] * 2 + [1] * 10 + [2] * 6, np.int32),
                                       n_houses), [3, 3]]).astype(np.int32)
    return (verts.astype(np.float32), tris.astype(np.int32), t_begin, t_end, material)


SUN_ELEVATION_DEG = 30.0
SUN_AZIMUTH_DEG = 135.0          # clockwise from north: south-east
CITY_TIME_DAYS = DAY_2000
TILE_PX = 16


def sun_direction(elevation_deg: float, azimuth_deg: float) -> np.ndarray:
    """Unit vector towards the sun in render space (x east, y north, z up)."""
    el = np.radians(elevation_deg)
    az = np.radians(azimuth_deg)
    return np.array([np.sin(az) * np.cos(el), np.cos(az) * np.cos(el), np.sin(el)])


def camera_rays(bounds: np.ndarray, width: int = 1920, height: int = 1080, fov_deg: float = 60.0):
    """Perspective camera over the south-west corner, looking north-east and down 25 deg."""
    lo, hi = bounds[0, :3], bounds[1, :3]
    ext = hi[:2] - lo[:2]
    eye = np.array([lo[0] + 0.15 * ext[0], lo[1] + 0.15 * ext[1], 120.0])
    yaw = np.radians(45.0)
    pitch = np.radians(-25.0)
    fwd = np.array([np.sin(yaw) * np.cos(pitch), np.cos(yaw) * np.cos(pitch), np.sin(pitch)])
    right = np.cross(fwd, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    half_w = np.tan(np.radians(fov_deg) / 2)
    half_h = half_w * height / width
    px = (np.arange(width) + 0.5) / width * 2 - 1
    py = 1 - (np.arange(height) + 0.5) / height * 2
    d = (fwd[None, None, :] + px[None, :, None] * half_w * right[None, None, :]
         + py[:, None, None] * half_h * up[None, None, :]).reshape(-1, 3)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    o = np.broadcast_to(eye, d.shape).copy()
    order = tile_order(height, width, TILE_PX)
    return o[order], d[order]


def map_rays(bounds: np.ndarray, size: int = 2048):
    """Vertical rays from above on a size x size grid over the city."""
    lo, hi = bounds[0, :3], bounds[1, :3]
    xs = lo[0] + (np.arange(size) + 0.5) / size * (hi[0] - lo[0])
    ys = hi[1] - (np.arange(size) + 0.5) / size * (hi[1] - lo[1])
    x, y = np.meshgrid(xs, ys)
    o = np.column_stack([x.ravel(), y.ravel(), np.full(size * size, hi[2] + 10.0)])
    d = np.tile([0.0, 0.0, -1.0], (size * size, 1))
    order = tile_order(size, size, TILE_PX)
    return o[order], d[order]


def shadow_rays(vertices, triangles, origins, directions, dist, tri, sun):
    """Shadow rays from the hit points whose geometric normal (towards the viewer) faces the sun."""
    hit = tri >= 0
    p = origins[hit] + directions[hit] * dist[hit, None]
    v = vertices.astype(np.float64)[triangles[tri[hit]]]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    n *= np.where(np.einsum("ij,ij->i", n, directions[hit]) > 0, -1.0, 1.0)[:, None]
    lit = n @ sun > 0.0
    so = shadow_rays_from_surface(p[lit], n[lit], sun)
    return so, np.ascontiguousarray(np.broadcast_to(sun, so.shape))


#: Counters of :func:`anyhit_counts`, in its output order.
COUNTER_NAMES = ("cache_hits", "inner_nodes", "leaves", "empty_leaves", "records",
                 "records_present", "traversal_hits")


@numba.njit(cache=True)
def anyhit_counts(tree, box_lo, box_hi, origins, direction, t_days, brick_size, out):
    """Work of the kd-tree any-hit per call, one thread, for rays sharing ``direction``: adds
    to ``out`` the counts named by ``COUNTER_NAMES`` (caster-cache hits, inner nodes entered,
    leaves, empty leaves, records looked at, records present at ``t_days`` and tested, rays
    blocked found by traversal). The same decisions, order and cache (reset per brick) as
    ``trace.kernels.trace_range``; a measuring twin, not a fast path."""
    dx, dy, dz = direction[0], direction[1], direction[2]
    kx, ky, kz, sx, sy, sz = ray_shear(dx, dy, dz)
    inv_x = 1.0 / dx if dx != 0.0 else 0.0
    inv_y = 1.0 / dy if dy != 0.0 else 0.0
    inv_z = 1.0 / dz if dz != 0.0 else 0.0
    st_node = np.empty(STACK_SIZE, np.int64)
    st_t0 = np.empty(STACK_SIZE)
    st_t1 = np.empty(STACK_SIZE)
    cache_k = -1
    for i in range(origins.shape[0]):
        if i % brick_size == 0:
            cache_k = -1
        o = origins[i]
        okx, oky, okz = o[kx], o[ky], o[kz]
        if cache_k >= 0 and record_present(tree, cache_k, t_days):
            hit, t, _, _ = hit_record(tree.recs, cache_k, okx, oky, okz, kx, ky, kz, sx, sy, sz)
            if hit and t >= 0.0:
                out[0] += 1
                continue
        seg0, seg1 = clip_to_box(box_lo, box_hi, o[0], o[1], o[2], dx, dy, dz, 0.0, np.inf)
        node, sp, found = 0, 0, False
        while seg0 <= seg1:
            w0 = node_word(tree, node)
            axis = word_axis(w0)
            if axis != LEAF_CODE:
                out[1] += 1
                split = node_split(tree, node)
                right = word_payload(w0)
                if axis == TIME_AXIS:
                    node = node + 1 if t_days < split else right
                    continue
                d = dx if axis == 0 else (dy if axis == 1 else dz)
                near, far = (node + 1, right) if d >= 0.0 else (right, node + 1)
                if d == 0.0:
                    # Parallel: the side of the origin (both sides when in the plane).
                    if o[axis] != split:
                        node = node + 1 if o[axis] < split else right
                    else:
                        st_node[sp], st_t0[sp], st_t1[sp] = right, seg0, seg1
                        sp += 1
                        node = node + 1
                    continue
                t_split = (split - o[axis]) * (inv_x if axis == 0 else
                                               (inv_y if axis == 1 else inv_z))
                side, ts = split_side(t_split, seg0, seg1)
                if side == NEAR_ONLY:
                    node = near
                elif side == FAR_ONLY:
                    node = far
                else:
                    st_node[sp], st_t0[sp], st_t1[sp] = far, ts, seg1
                    sp += 1
                    node = near
                    seg1 = ts
                continue
            out[2] += 1
            first, count = leaf_first(tree, node), word_payload(w0)
            out[3] += count == 0
            for k in range(first, first + count):
                out[4] += 1
                if record_present(tree, k, t_days):
                    out[5] += 1
                    hit, t, _, _ = hit_record(tree.recs, k, okx, oky, okz, kx, ky, kz, sx, sy,
                                              sz)
                    if hit and t >= 0.0:
                        found = True
                        cache_k = k
                        break
            if found or sp == 0:
                break
            sp -= 1
            node, seg0, seg1 = st_node[sp], st_t0[sp], st_t1[sp]
        out[6] += found


def anyhit_profile(tree, origins, direction, t_days, brick_size=256):
    """Per-ray counters of the kd-tree any-hit (``COUNTER_NAMES``), on one thread."""
    from cityshade.trace import BOX_PAD_REL
    lo, hi, scale_m = tree.box_scale_m()
    pad = BOX_PAD_REL * scale_m
    counts = np.zeros(len(COUNTER_NAMES), np.int64)
    anyhit_counts(tree.views, lo - pad, hi + pad, np.ascontiguousarray(origins, np.float64),
                  np.ascontiguousarray(direction, np.float64), t_days, brick_size, counts)
    n = max(len(origins), 1)
    return {name: float(c) / n for name, c in zip(COUNTER_NAMES, counts)}


@numba.njit(parallel=True, cache=True)
def _probe_kernel(n):
    """A trivial parallel loop (64 equal items of pure arithmetic): what 2 threads can give."""
    s = np.zeros(64)
    for j in numba.prange(64):
        acc = 0.0
        for i in range(n):
            acc += np.sqrt(i + j + 1.0)
        s[j] = acc
    return s.sum()


def core_probe(threads_list, runs):
    """Seconds of the trivial parallel loop per thread count: a 2-thread figure below ~1.9x
    of it says the second core was busy with other work during the run."""
    _probe_kernel(10)
    out = {}
    for th in threads_list:
        numba.set_num_threads(th)
        out[th], _ = timed(lambda: _probe_kernel(2_000_000), runs)
    return out


@numba.njit(parallel=True, cache=True)
def _triad_kernel(a, b, c, s):
    """STREAM's triad ``a = b + s c``: 24 bytes of memory traffic per item, no reuse."""
    for i in numba.prange(a.shape[0]):
        a[i] = b[i] + s * c[i]


def memory_probe(threads_list, runs, mb: int = 256):
    """GB/s of the triad over three ``mb`` MB arrays per thread count: what the machine's memory
    gives 1 and 2 threads (a kernel that streams from memory cannot scale past its ratio)."""
    n = (mb << 20) // 8
    a, b, c = np.zeros(n), np.ones(n), np.ones(n)
    _triad_kernel(a, b, c, 2.0)
    out = {}
    for th in threads_list:
        numba.set_num_threads(th)
        sec, _ = timed(lambda: _triad_kernel(a, b, c, 2.0), runs)
        out[th] = 24.0 * n / sec / 1e9
    return out


def timed(fn, runs, clock=time.perf_counter):
    """Median seconds of ``runs`` calls of ``fn`` and its last result."""
    times = []
    out = None
    for _ in range(runs):
        t0 = clock()
        out = fn()
        times.append(clock() - t0)
    return statistics.median(times), out


def timed_threads(fn, threads_list, runs):
    """Median seconds of ``fn(threads)`` per thread count, the counts alternating run by run
    (a burst of other load on a shared machine then falls on both counts, not on the runs of
    one: the 2-thread / 1-thread ratio steadier), and the last result."""
    times = {th: [] for th in threads_list}
    out = None
    for _ in range(runs):
        for th in threads_list:
            numba.set_num_threads(th)
            t0 = time.perf_counter()
            out = fn(th)
            times[th].append(time.perf_counter() - t0)
    return {th: statistics.median(v) for th, v in times.items()}, out


class Embree:
    """Embree 4 through embreex on the triangles present at the city time."""

    name = "embree"

    def __init__(self, tri_vertices):
        from embreex import rtcore_scene
        from embreex.mesh_construction import TriangleMesh
        self.scene = rtcore_scene.EmbreeScene()
        t0 = time.perf_counter()
        TriangleMesh(self.scene, np.ascontiguousarray(tri_vertices, dtype=np.float32))
        self.scene.run(np.zeros((1, 3), np.float32), np.array([[0, 0, 1]], np.float32))
        self.build_s = time.perf_counter() - t0

    def _split(self, fn, o, d, threads):
        if threads == 1:
            return fn(o, d)
        parts = np.array_split(np.arange(len(o)), threads)
        with ThreadPoolExecutor(threads) as pool:
            res = list(pool.map(lambda ix: fn(o[ix], d[ix]), parts))
        return np.concatenate(res) if isinstance(res[0], np.ndarray) else res

    def occluded(self, o, d, threads):
        return self._split(lambda a, b: self.scene.run(a, b, query="OCCLUDED") >= 0, o, d,
                           threads)

    def intersect(self, o, d, threads):
        def one(a, b):
            r = self.scene.run(a, b, output=1)
            return np.column_stack([r["tfar"].astype(np.float64), r["primID"]])
        res = self._split(one, o, d, threads)
        return res[:, 0], res[:, 1].astype(np.int64)


class Mitsuba:
    """Mitsuba 3 (llvm_ad_rgb variant) on the triangles present at the city time."""

    name = "mitsuba"

    def __init__(self, tri_vertices):
        import drjit as dr
        import mitsuba as mi
        mi.set_variant("llvm_ad_rgb")
        self.mi = mi
        self.dr = dr
        n = tri_vertices.shape[0]
        t0 = time.perf_counter()
        mesh = mi.Mesh("city", 3 * n, n)
        params = mi.traverse(mesh)
        params["vertex_positions"] = mi.Float(np.ascontiguousarray(tri_vertices, np.float32).ravel())
        params["faces"] = mi.UInt32(np.arange(3 * n, dtype=np.uint32))
        params.update()
        self.scene = mi.load_dict({"type": "scene", "city": mesh})
        self.build_s = time.perf_counter() - t0

    def _ray(self, o, d):
        mi = self.mi
        return mi.Ray3f(o=mi.Point3f(np.ascontiguousarray(o.T)), d=mi.Vector3f(np.ascontiguousarray(d.T)))

    def occluded(self, o, d, threads):
        self.dr.set_thread_count(threads)
        return np.array(self.scene.ray_test(self._ray(o, d))).astype(bool)

    def intersect(self, o, d, threads):
        self.dr.set_thread_count(threads)
        si = self.scene.ray_intersect_preliminary(self._ray(o, d))
        t = np.array(si.t).astype(np.float64)
        prim = np.array(si.prim_index).astype(np.int64)
        prim[~np.isfinite(t)] = -1
        return t, prim


def run(args):
    numba_threads = numba.get_num_threads()
    verts, tris, t_begin, t_end, material = synthetic_city(args.triangles, seed=1)
    n_tri = tris.shape[0]
    result = {"commit": commit(), "triangles": int(n_tri), "city_time_days": CITY_TIME_DAYS,
              "sun": {"elevation_deg": SUN_ELEVATION_DEG, "azimuth_deg": SUN_AZIMUTH_DEG},
              "runs": args.runs, "workloads": {}}
    # Warm the kernels (compile or load the cache) on a tiny scene before timing the build.
    small = synthetic_city(200, seed=2)
    warm = build_kdtree(*small)
    intersect(warm, np.zeros((4, 3)), np.tile([0, 0, -1.0], (4, 1)))
    occluded(warm, np.zeros((4, 3)), np.tile([0, 0, -1.0], (4, 1)))
    t0 = time.perf_counter()
    tree = build_kdtree(verts, tris, t_begin, t_end, material)
    build_s = time.perf_counter() - t0
    stats = {k: (float(v) if isinstance(v, (np.floating, float)) else v)
             for k, v in tree.stats.items()}
    result["build"] = {"seconds": build_s, "seconds_per_million": build_s / (n_tri / 1e6),
                       "stats": stats}
    print(f"city: {n_tri} triangles; kd-tree build {build_s:.2f} s "
          f"({build_s / (n_tri / 1e6):.2f} s per million), {stats['nodes']} nodes, "
          f"duplication {stats['duplication']:.2f}, SAH {stats['sah_cost']:.1f}, "
          f"{stats['time_splits']} time splits", flush=True)

    present = (t_begin <= CITY_TIME_DAYS) & (CITY_TIME_DAYS < t_end)
    present_ids = np.flatnonzero(present)
    tri_vertices = verts[tris[present_ids]]
    engines = []
    if not args.no_embree:
        try:
            engines.append(Embree(tri_vertices))
        except ImportError as exc:
            print(f"embree skipped: {exc}")
    if not args.no_mitsuba:
        try:
            engines.append(Mitsuba(tri_vertices))
        except (ImportError, AttributeError) as exc:
            print(f"mitsuba skipped: {exc}")
    for e in engines:
        result.setdefault("engine_build_s", {})[e.name] = e.build_s

    sun = sun_direction(SUN_ELEVATION_DEG, SUN_AZIMUTH_DEG)
    threads_list = [t for t in (1, 2) if t <= numba_threads]
    workloads = {"camera": camera_rays(tree.bounds), "map": map_rays(tree.bounds, args.map_size)}
    for wname, (po, pd) in workloads.items():
        wres = {"primary_rays": int(len(po))}
        # Closest-hit primary rays.
        prim = None
        for th in threads_list:
            numba.set_num_threads(th)
            sec, prim = timed(lambda: intersect(tree, po, pd, CITY_TIME_DAYS), args.runs)
            wres[f"closest_mrays_s_{th}t"] = len(po) / sec / 1e6
        dist, tri, _, _ = prim
        so, sd = shadow_rays(verts, tris, po, pd, dist, tri, sun)
        wres["shadow_rays"] = int(len(so))
        secs, occ = timed_threads(lambda th: occluded(tree, so, sd, CITY_TIME_DAYS),
                                  threads_list, args.runs)
        for th in threads_list:
            wres[f"anyhit_mrays_s_{th}t"] = len(so) / secs[th] / 1e6
        wres["shadowed_fraction"] = float(occ.mean())
        if args.profile:
            prof = anyhit_profile(tree, so, sun, CITY_TIME_DAYS)
            twin = round((prof["cache_hits"] + prof["traversal_hits"]) * len(so))
            prof["blocked_differing_from_kernel"] = abs(twin - int(occ.sum()))
            wres["anyhit_per_ray"] = prof
        # The light-space engine (izb) on the same origins and sun: every decision must be
        # the kd-tree's. The first call per tree also makes the caster records (reported).
        for th in threads_list:
            numba.set_num_threads(th)
            t0 = time.perf_counter()
            lightspace.occluded(tree, so, sun, CITY_TIME_DAYS)
            wres[f"izb_first_call_s_{th}t"] = time.perf_counter() - t0
        profiles = {th: {} for th in threads_list}
        secs, izb = timed_threads(lambda th: lightspace.occluded(
            tree, so, sun, CITY_TIME_DAYS, stats=profiles[th]), threads_list, args.runs)
        for th in threads_list:
            wres[f"izb_mrays_s_{th}t"] = len(so) / secs[th] / 1e6
            wres[f"izb_profile_{th}t"] = profiles[th]
        wres["izb_differing_from_ours"] = int((izb != occ).sum())
        # Other engines on the identical float32-rounded rays.
        po32, pd32 = po.astype(np.float32), pd.astype(np.float32)
        so32, sd32 = so.astype(np.float32), sd.astype(np.float32)
        for e in engines:
            er = {}
            for th in threads_list:
                sec, (edist, eprim) = timed(lambda: e.intersect(po32, pd32, th), args.runs)
                er[f"closest_mrays_s_{th}t"] = len(po) / sec / 1e6
                sec, eocc = timed(lambda: e.occluded(so32, sd32, th), args.runs)
                er[f"anyhit_mrays_s_{th}t"] = len(so) / sec / 1e6
            etri = np.where(eprim >= 0, present_ids[np.clip(eprim, 0, None)], -1)
            same_hit = (etri == tri) | ((etri >= 0) & (tri >= 0)
                                        & np.isclose(edist, dist, rtol=1e-4, atol=1e-3))
            er["closest_agreement"] = float(same_hit.mean())
            er["anyhit_agreement"] = float((eocc == occ).mean())
            er["izb_agreement"] = float((eocc == izb).mean())
            for th in threads_list:
                er[f"ratio_izb_to_{e.name}_anyhit_{th}t"] = (wres[f"izb_mrays_s_{th}t"]
                                                            / er[f"anyhit_mrays_s_{th}t"])
            for key in [k for k in er if k.endswith("t") and "mrays" in k]:
                er[f"ratio_ours_to_{e.name}_{key}"] = wres[key] / er[key]
            wres[e.name] = er
        # The trivial parallel loop right after this workload: did 2 threads have 2 cores?
        probe = core_probe(threads_list, args.runs)
        if 2 in probe:
            wres["probe_scaling_2t"] = probe[1] / probe[2]
        result["workloads"][wname] = wres
        print_table(wname, wres, engines, threads_list)
    numba.set_num_threads(numba_threads)
    return result


def print_table(wname, wres, engines, threads_list):
    print(f"\n{wname}: {wres['primary_rays']} primary rays, {wres['shadow_rays']} shadow rays, "
          f"{100 * wres['shadowed_fraction']:.1f} % shadowed")
    cols = [f"{kind} {th}t" for kind in ("closest", "anyhit") for th in threads_list]
    keys = [f"{kind}_mrays_s_{th}t" for kind in ("closest", "anyhit") for th in threads_list]
    if "probe_scaling_2t" in wres:
        print(f"trivial prange loop, 2 threads / 1 thread in this run: "
              f"{wres['probe_scaling_2t']:.2f}x (about 2 when both cores were free)")
    print(f"{'Mrays/s':<12}" + "".join(f"{c:>14}" for c in cols) + f"{'agree hit/occ':>18}")
    print(f"{'cityshade':<12}" + "".join(f"{wres[k]:>14.2f}" for k in keys))
    izb_cols = "".join(f"{wres[f'izb_mrays_s_{th}t']:>14.2f}" for th in threads_list)
    print(f"{'izb':<12}" + " " * 14 * len(threads_list) + izb_cols
          + f"{'differing from kd-tree: ':>26}{wres['izb_differing_from_ours']}")
    if "anyhit_per_ray" in wres:
        c = wres["anyhit_per_ray"]
        blocked = c["cache_hits"] + c["traversal_hits"]
        print(f"kd-tree any-hit per ray (1 thread): {c['inner_nodes']:.1f} inner nodes, "
              f"{c['leaves']:.2f} leaves ({c['empty_leaves']:.2f} empty), {c['records']:.2f} "
              f"records ({c['records_present']:.2f} present, tested); blocked "
              f"{blocked:.3f} ({c['cache_hits']:.3f} by the caster cache); blocked count "
              f"differing from the kernel's: {c['blocked_differing_from_kernel']}")
    for th in threads_list:
        prof = wres.get(f"izb_profile_{th}t", {})
        if prof:
            print(f"izb {th}t phases, ms: " + ", ".join(
                f"{k[:-2]} {1e3 * prof[k]:.1f}" for k in ("sort_s", "project_s", "bin_s",
                                                          "query_s"))
                  + f"; cell {prof['cell_m']:.2f} m, {prof['references'] / wres['shadow_rays']:.3f}"
                  f" references and {prof['tests'] / wres['shadow_rays']:.2f} full tests per "
                  "receiver")
    for e in engines:
        er = wres[e.name]
        print(f"{e.name:<12}" + "".join(f"{er[k]:>14.2f}" for k in keys)
              + f"{100 * er['closest_agreement']:>9.3f}/{100 * er['anyhit_agreement']:.3f}%")
        print(f"{'  ratio':<12}" + "".join(f"{wres[k] / er[k]:>13.2f}x" for k in keys))
        print(f"{'  izb ratio':<12}" + " " * 14 * len(threads_list)
              + "".join(f"{er[f'ratio_izb_to_{e.name}_anyhit_{th}t']:>13.2f}x"
                        for th in threads_list)
              + f"{'izb agreement ':>20}{100 * er['izb_agreement']:.3f}%")
    sys.stdout.flush()


def sweep_sah(args):
    """Measure closest-hit and any-hit speed of the map workload over a grid of SAH constants.

    One thread, timed in process CPU seconds so that other load on a shared machine disturbs
    the comparison less than wall time would.
    """
    verts, tris, t_begin, t_end, material = synthetic_city(args.triangles, seed=1)
    sun = sun_direction(SUN_ELEVATION_DEG, SUN_AZIMUTH_DEG)
    numba.set_num_threads(1)
    rows = []
    for ci in (0.7, 1.0, 1.5, 2.5):
        for bonus in (0.0, 0.2, 0.5):
            settings = KdTreeSettings(intersection_cost=ci, empty_bonus=bonus)
            tree = build_kdtree(verts, tris, t_begin, t_end, material, settings)
            po, pd = map_rays(tree.bounds, 1024)
            dist, tri, _, _ = intersect(tree, po, pd, CITY_TIME_DAYS)
            so, sd = shadow_rays(verts, tris, po, pd, dist, tri, sun)
            sec_c, _ = timed(lambda: intersect(tree, po, pd, CITY_TIME_DAYS), args.runs,
                             time.process_time)
            sec_a, _ = timed(lambda: occluded(tree, so, sd, CITY_TIME_DAYS), args.runs,
                             time.process_time)
            row = {"intersection_cost": ci, "empty_bonus": bonus,
                   "build_s": tree.stats["build_s"], "sah_cost": tree.stats["sah_cost"],
                   "closest_mrays_s": len(po) / sec_c / 1e6, "anyhit_mrays_s": len(so) / sec_a / 1e6}
            rows.append(row)
            print(json.dumps(row), flush=True)
    return {"sah_sweep": rows}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--map-size", type=int, default=2048)
    parser.add_argument("--json", default=None, help="write the results here")
    parser.add_argument("--no-embree", action="store_true")
    parser.add_argument("--no-mitsuba", action="store_true")
    parser.add_argument("--profile", action="store_true",
                        help="also count the kd-tree any-hit's work per ray (nodes, leaves, "
                             "records; one thread, a measuring twin of the kernel)")
    parser.add_argument("--sweep-sah", action="store_true",
                        help="measure the SAH constants instead of the comparison")
    args = parser.parse_args(argv)
    result = sweep_sah(args) if args.sweep_sah else run(args)
    text = json.dumps(result, indent=2)
    if args.json:
        with open(args.json, "w") as fh:
            fh.write(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    main()
