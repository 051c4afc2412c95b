"""Tests of the 4-D SAH kd-tree build and layout (cityshade.accel)."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.accel import KdTree, KdTreeInputError, KdTreeSettings, build_kdtree
from cityshade.errors import ConfigError
from synthetic import box_city
from reference import (reference_event_order, reference_kdtree_leaves_at_point,
                       reference_kdtree_triangles_at_time)

@pytest.fixture(scope="module")
def city():
    return box_city(120, seed=3)


@pytest.fixture(scope="module")
def tree(city):
    return build_kdtree(*city)


def slices(begin, end):
    """Time slices before, at, between and after the dates of a model."""
    dates = np.unique(np.concatenate([begin[np.isfinite(begin)], end[np.isfinite(end)]]))
    mids = 0.5 * (dates[:-1] + dates[1:])
    return np.concatenate([[dates[0] - 1e4, dates[-1] + 1e4], dates, mids[::7]])


def test_every_triangle_reachable_in_every_slice_where_valid(city, tree):
    v, t, begin, end, mat = city
    for t_days in slices(begin, end):
        valid = set(np.flatnonzero((begin <= t_days) & (t_days < end)).tolist())
        reached = reference_kdtree_triangles_at_time(tree, t_days)
        assert valid <= reached, f"t={t_days}: {len(valid - reached)} valid triangles unreachable"


def test_leaf_cells_cover_every_point_of_their_triangles(city, tree):
    """Points on each triangle (vertices, edge points, interior) lie in a leaf that lists it."""
    v, t, begin, end, mat = city
    rng = np.random.default_rng(0)
    axis, child, second = tree.unpack()
    bary = np.vstack([np.eye(3), [[0.5, 0.5, 0], [0, 0.5, 0.5], [0.5, 0, 0.5]],
                      rng.dirichlet([1, 1, 1], 4)])
    for tri in rng.choice(t.shape[0], 150, replace=False):
        times = [begin[tri] if np.isfinite(begin[tri]) else -1e6,
                 np.nextafter(end[tri], -np.inf) if np.isfinite(end[tri]) else 1e6]
        pts = bary @ v[t[tri]].astype(np.float64)
        for t_days in times:
            for p in pts:
                # Barycentric sums round by ~1e-14 m: allow that much off a plane.
                leaves = reference_kdtree_leaves_at_point(tree, p, t_days, tol_m=1e-9)
                listed = any(tri in tree.prim_indices[int(second[n]):int(second[n]) + child[n]]
                             for n in leaves)
                assert listed, f"triangle {tri} point {p} at t={t_days} is in no leaf listing it"


def test_depth_and_leaf_size_settings_are_obeyed(city):
    settings = KdTreeSettings(max_depth=9, min_leaf_triangles=6)
    tree = build_kdtree(*city, settings=settings)
    axis, child, second = tree.unpack()
    # Walk the tree computing depth and the distinct triangles under each node.
    depth = np.zeros(axis.size, int)
    under = [None] * axis.size
    for node in range(axis.size - 1, -1, -1):
        if axis[node] == 4:
            first = int(second[node])
            under[node] = set(tree.prim_indices[first:first + child[node]].tolist())
        else:
            under[node] = under[node + 1] | under[child[node]]
    for node in range(axis.size):
        if axis[node] != 4:
            depth[node + 1] = depth[node] + 1
            depth[child[node]] = depth[node] + 1
            assert len(under[node]) > 6, "a node with <= min_leaf_triangles was split"
    assert depth.max() <= 9
    assert tree.stats["max_depth"] == depth[axis == 4].max()


def test_leaves_sorted_by_material_then_id(city, tree):
    v, t, begin, end, mat = city
    axis, child, second = tree.unpack()
    for node in np.flatnonzero(axis == 4):
        ids = tree.prim_indices[int(second[node]):int(second[node]) + child[node]]
        key = list(zip(mat[ids].tolist(), ids.tolist()))
        assert key == sorted(key)


def test_records_match_triangles(city, tree):
    v, t, begin, end, mat = city
    ids = tree.prim_indices
    np.testing.assert_array_equal(tree.tri_records[:, :9], v[t[ids]].reshape(-1, 9))
    np.testing.assert_array_equal(tree.records_i32[:, 9], ids)
    np.testing.assert_array_equal(tree.records_i32[:, 14], mat[ids])
    np.testing.assert_array_equal(tree.records_f64[:, 5], begin[ids])
    np.testing.assert_array_equal(tree.records_f64[:, 6], end[ids])


def test_stats_are_consistent_with_the_nodes(city, tree):
    v, t, begin, end, mat = city
    s = tree.stats
    axis, child, second = tree.unpack()
    leaves = axis == 4
    assert s["nodes"] == axis.size == tree.nodes.shape[0]
    assert s["leaves"] == leaves.sum() == (axis.size + 1) // 2
    assert s["empty_leaves"] == (leaves & (child == 0)).sum()
    assert s["references"] == child[leaves].sum() == tree.prim_indices.size
    assert s["duplication"] == pytest.approx(tree.prim_indices.size / t.shape[0])
    assert s["time_splits"] == (axis == 3).sum() > 0
    assert s["triangles_in"] == t.shape[0]
    assert s["build_s"] > 0 and s["sah_cost"] > 0
    np.testing.assert_array_equal(tree.bounds[0, :3], v.min(axis=0))
    np.testing.assert_array_equal(tree.bounds[1, :3], v.max(axis=0))


def test_sah_cost_matches_an_independent_walk(city, tree):
    """Recompute the tree's SAH cost from its nodes: sum of C_t P(inner) + C_i N P(leaf)."""
    v, t, begin, end, mat = city
    st = KdTreeSettings()
    axis, child, second = tree.unpack()
    t0, t1 = tree.bounds[:, 3]

    def surface(lo, hi):
        e = hi[:3] - lo[:3]
        area = 2 * (e[0] * e[1] + e[0] * e[2] + e[1] * e[2])
        return area * (min(hi[3], t1) - max(lo[3], t0))

    lo0 = np.append(tree.bounds[0, :3], -np.inf)
    hi0 = np.append(tree.bounds[1, :3], np.inf)
    root = surface(lo0, hi0)
    total = 0.0
    todo = [(0, lo0, hi0)]
    while todo:
        node, lo, hi = todo.pop()
        p = surface(lo, hi) / root
        if axis[node] == 4:
            total += st.intersection_cost * child[node] * p
            continue
        total += st.traversal_cost * p
        a = axis[node]
        hl, lr = hi.copy(), lo.copy()
        hl[a] = lr[a] = second[node]
        todo += [(node + 1, lo, hl), (int(child[node]), lr, hi)]
    assert tree.stats["sah_cost"] == pytest.approx(total, rel=1e-9)


def test_model_without_dates_builds_a_3d_tree():
    v, t, begin, end, mat = box_city(60, seed=1, dated=False)
    tree = build_kdtree(v, t, begin, end, mat)
    axis, _, _ = tree.unpack()
    assert tree.stats["time_splits"] == 0 and not (axis == 3).any()
    assert not tree.has_time and not tree.stats["has_time"]
    assert reference_kdtree_triangles_at_time(tree, 0.0) == set(range(t.shape[0]))


def test_empty_and_never_valid_triangles():
    v, t, begin, end, mat = box_city(3, seed=2, dated=False)
    empty = build_kdtree(v, t[:0], begin[:0], end[:0], mat[:0])
    assert empty.stats["nodes"] == 1 and empty.prim_indices.size == 0
    end = end.copy()
    end[:12] = begin[:12] = 5.0        # [5, 5) is empty: never valid, left out
    tree = build_kdtree(v, t, begin, end, mat)
    assert set(tree.prim_indices.tolist()) == set(range(12, 36))


def test_zero_area_triangles_do_not_break_the_build():
    v, t, begin, end, mat = box_city(5, seed=4, dated=False)
    degenerate = np.array([[0, 0, 0], [1, 1, 1], [2, 2, 2], [0, 1, 2]], np.int32)  # point, line
    degenerate[3] = [0, 1, 0]
    t2 = np.vstack([t, degenerate])
    n = t2.shape[0]
    tree = build_kdtree(v, t2, np.full(n, -np.inf), np.full(n, np.inf), np.zeros(n, np.int32))
    assert reference_kdtree_triangles_at_time(tree, 0.0) == set(range(n))
    assert np.isfinite(tree.stats["sah_cost"])


def test_round_trip_through_read_only_memory_maps(tmp_path, tree):
    arrays = tree.to_arrays()
    for name, arr in arrays.items():
        np.save(tmp_path / f"{name}.npy", arr)
    loaded = {name: np.load(tmp_path / f"{name}.npy", mmap_mode="r") for name in arrays}
    back = KdTree.from_arrays(loaded, tree.stats)
    for name, arr in back.to_arrays().items():
        np.testing.assert_array_equal(arr, arrays[name])
        assert not arr.flags.writeable
    assert back.stats == tree.stats


def test_bad_inputs_raise_typed_errors(city):
    v, t, begin, end, mat = city
    with pytest.raises(KdTreeInputError, match="shape"):
        build_kdtree(v[:, :2], t, begin, end, mat)
    with pytest.raises(KdTreeInputError, match="out of range"):
        build_kdtree(v, t + v.shape[0], begin, end, mat)
    bad = v.copy()
    bad[0, 0] = np.nan
    with pytest.raises(KdTreeInputError, match="NaN"):
        build_kdtree(bad, t, begin, end, mat)
    with pytest.raises(KdTreeInputError, match="NaN"):
        build_kdtree(v, t, np.full_like(begin, np.nan), end, mat)
    with pytest.raises(KdTreeInputError, match="material"):
        build_kdtree(v, t, begin, end, mat[:-1])
    with pytest.raises(ConfigError):
        KdTreeSettings(empty_bonus=1.0)
    with pytest.raises(ConfigError):
        KdTreeSettings(max_depth=99)
    assert KdTreeSettings().depth_cap(2 ** 20) == 34


def test_parallel_subtrees_stitch_into_the_undivided_tree_for_1_and_2_threads(city,
                                                                             monkeypatch):
    """Nodes of at most ``subtree_refs`` references are built apart (from threads, several at
    once) and stitched back: every array equals the build that never divides (the root is
    then the only subtree), for any subtree size and thread count, and the statistics agree."""
    import numba

    from cityshade.accel import kdtree_build as kb
    from cityshade.runtime.interpret import InterpretBudget

    monkeypatch.setattr(kb, "_INTERPRET", InterpretBudget(0))  # compiled: the threads' build

    whole = build_kdtree(*city, settings=KdTreeSettings(subtree_refs=10 ** 9))
    threads = sorted({1, min(2, numba.config.NUMBA_NUM_THREADS)})
    before = numba.get_num_threads()
    try:
        for subtree_refs in (30, 400):
            for n_threads in threads:
                numba.set_num_threads(n_threads)
                split = build_kdtree(*city, settings=KdTreeSettings(subtree_refs=subtree_refs))
                where = f"subtree_refs={subtree_refs}, {n_threads} thread(s)"
                np.testing.assert_array_equal(split.nodes, whole.nodes, err_msg=where)
                np.testing.assert_array_equal(split.prim_indices, whole.prim_indices,
                                              err_msg=where)
                np.testing.assert_array_equal(split.tri_records, whole.tri_records,
                                              err_msg=where)
                for key, value in whole.stats.items():
                    if key == "sah_cost":  # summed in another order: last bits only
                        assert split.stats[key] == pytest.approx(value, rel=1e-12), where
                    elif key != "build_s":
                        assert split.stats[key] == value, f"{key}, {where}"
    finally:
        numba.set_num_threads(before)
    with pytest.raises(ConfigError, match="subtree_refs"):
        KdTreeSettings(subtree_refs=-1)


def slanted_city(n_triangles, seed):
    """Seeded random slanted triangles (most straddle split planes, so perfect splits clip
    them) with random validity intervals."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0, 200, (n_triangles, 1, 3)) + rng.normal(0, 6, (n_triangles, 3, 3))
    verts = centres.reshape(-1, 3).astype(np.float32)
    tris = np.arange(3 * n_triangles, dtype=np.int32).reshape(n_triangles, 3)
    begin = np.where(rng.random(n_triangles) < 0.5, -np.inf,
                     np.round(rng.uniform(-5000, 5000, n_triangles)))
    end = np.where(rng.random(n_triangles) < 0.5, np.inf,
                   np.round(rng.uniform(5001, 9000, n_triangles)))
    return verts, tris, begin, end, rng.integers(-1, 3, n_triangles).astype(np.int32)


@pytest.mark.parametrize("case, nodes, references, sah, digest", [
    ("boxes dated", 2755, 3056, 18.26754664270322, "7e61dcd55851d5c9"),
    ("boxes dateless", 2825, 3690, 25.174818688147997, "ca20d9dc67ec6b45"),
    ("slanted", 7471, 6096, 74.28479046139834, "5044774824b9ecb1"),
    ("slanted mixed", 7543, 6161, 74.25329104037837, "b1427dd100c93bec"),
])
def test_presorted_sweep_builds_the_tree_of_the_per_node_sort(case, nodes, references, sah,
                                                               digest):
    """The exact sweep keeps its events sorted from node to node (straddlers re-sorted and
    merged after clipping); the golden figures are those of the sweep that sorted every
    node's events anew (commit 60376aa): the same planes, so the same tree bit for bit.
    Boxes have many planar and tied events, slanted triangles many clipped straddlers."""
    import hashlib

    data = {"boxes dated": lambda: box_city(120, seed=3),
            "boxes dateless": lambda: box_city(150, seed=5, dated=False),
            "slanted": lambda: slanted_city(3000, 11),
            "slanted mixed": lambda: slanted_city(3000, 11)}[case]()
    settings = (KdTreeSettings(sweep_threshold=300, subtree_refs=500) if case == "slanted mixed"
                else KdTreeSettings(sweep_threshold=10**6))  # every node swept exactly
    built = build_kdtree(*data, settings=settings)
    assert (built.stats["nodes"], built.stats["references"]) == (nodes, references)
    assert built.stats["sah_cost"] == sah
    found = hashlib.sha256(np.ascontiguousarray(built.nodes).tobytes()
                           + np.ascontiguousarray(built.prim_indices).tobytes()).hexdigest()
    assert found[:16] == digest


@pytest.mark.parametrize("n", [1, 2, 31, 700, 2048, 5000])
def test_radix_event_order_is_the_stable_comparison_order(n):
    """The event sort's radix order equals a stable comparison sort, with ties (many equal
    coordinates), -0.0 beside 0.0, infinite validity ends, negatives, and keys of one node
    sharing their high bits (passes skipped); so does its interpreted twin (NumPy's uint32
    bit operations for Numba's) on the same values."""
    from cityshade.accel.kdtree_build import RADIX_BITS, _event_orders, _radix_order
    from cityshade.runtime.interpret import python_twin

    rng = np.random.default_rng(n)
    cases = [
        np.round(rng.normal(0, 50, n), 1),
        rng.choice(np.array([-0.0, 0.0, 1.5, -2.0, np.inf, -np.inf]), n),
        100.0 + rng.uniform(0, 1, n),
        rng.uniform(-1e30, 1e30, n),
    ]
    for values in cases:
        values = values.astype(np.float32)
        for kernel in (_radix_order, python_twin(_radix_order)):
            out = np.empty(n, np.int32)
            kernel(values, out, np.empty(n, np.uint32), np.empty(n, np.uint32),
                   np.empty(n, np.int32), np.empty((3, 1 << RADIX_BITS), np.int64))
            np.testing.assert_array_equal(out, reference_event_order(values))
    lo = rng.normal(0, 20, (n, 4)).astype(np.float32)
    hi = lo + rng.uniform(0, 3, (n, 4)).astype(np.float32)
    orders = _event_orders(lo, hi, 4)
    for q in range(8):
        column = hi[:, q >> 1] if q & 1 else lo[:, q >> 1]
        np.testing.assert_array_equal(orders[q], reference_event_order(column))


def test_an_interrupted_subtree_build_starts_no_queued_subtree(city, monkeypatch):
    """Ctrl-C (or a failure) during the parallel subtree builds ends the build once the
    running subtrees return: the queued ones are cancelled, not all built first (what
    ``Executor.map``'s iterator does when an exception leaves it)."""
    import threading
    import time

    import numba

    from cityshade.accel import kdtree_build as kb
    from cityshade.runtime.interpret import InterpretBudget

    if min(2, numba.config.NUMBA_NUM_THREADS) < 2:
        pytest.skip("needs 2 Numba threads")
    monkeypatch.setattr(kb, "_INTERPRET", InterpretBudget(0))  # compiled: the threads' build
    real = kb._build_kernel
    calls = []
    lock = threading.Lock()

    def kernel(*args):
        with lock:
            calls.append(args[2].shape[0])
            first = len(calls) == 1
        if first:
            raise KeyboardInterrupt
        time.sleep(0.05)
        return real(*args)

    before = numba.get_num_threads()
    numba.set_num_threads(2)
    try:
        monkeypatch.setattr(kb, "_build_kernel", lambda *a: kernel(*a) if a[-1] == 0 else
                            real(*a))
        with pytest.raises(KeyboardInterrupt):
            build_kdtree(*city, settings=KdTreeSettings(subtree_refs=30))
    finally:
        numba.set_num_threads(before)
    # subtree_refs=30 defers dozens of subtrees; one thread was busy for 50 ms at most.
    assert 1 <= len(calls) <= 4, len(calls)


def test_model_time_range_matches_its_twin():
    from cityshade.accel import model_time_range
    from reference import reference_model_time_range

    rng = np.random.default_rng(11)
    begin = np.where(rng.random(500) < 0.3, -np.inf, np.round(rng.uniform(-9e4, 2e4, 500)))
    end = np.where(rng.random(500) < 0.5, np.inf, begin + np.round(rng.uniform(1, 9e3, 500)))
    end[np.isinf(end) & np.isinf(begin)] = np.inf
    valid = begin < end
    assert model_time_range(begin, end, valid) == reference_model_time_range(begin[valid],
                                                                             end[valid])
    assert model_time_range(begin, end) == reference_model_time_range(begin, end)
    assert model_time_range(np.full(3, -np.inf), np.full(3, np.inf)) is None
    assert model_time_range(np.array([5.0]), np.array([np.inf])) == (4.0, 6.0)  # a day each side


def test_pack_nodes_matches_its_twin():
    from cityshade.accel.kdtree_layout import pack_nodes
    from reference import reference_pack_nodes

    rng = np.random.default_rng(2)
    axis = rng.integers(0, 5, 1000)
    child = rng.integers(0, 2 ** 29, 1000)
    first = rng.integers(0, 2 ** 32, 1000)
    split = rng.normal(0, 1e4, 1000).astype(np.float32).astype(np.float64)
    np.testing.assert_array_equal(pack_nodes(axis, child, first, split),
                                  reference_pack_nodes(axis, child, first, split))


@pytest.mark.parametrize("n", [0, 1, 2, 33, 1000])
def test_heapsort_matches_numpy_sort(n):
    """The hand-written heapsort (leaves and clipped straddlers beyond 32 references) sorts
    like numpy, with duplicates, negatives and the int64 extremes."""
    from cityshade.accel.kdtree_build import _heapsort

    rng = np.random.default_rng(n)
    keys = rng.integers(-50, 50, n).astype(np.int64)
    keys[:min(n, 2)] = [np.iinfo(np.int64).max, np.iinfo(np.int64).min][:min(n, 2)]
    tail = np.arange(7, dtype=np.int64)  # past n: must stay as they are
    work = np.concatenate([keys, tail])
    _heapsort(work, n)
    np.testing.assert_array_equal(work, np.concatenate([np.sort(keys), tail]))


def _slivers(n, seed):
    """``n`` long thin triangles across a 300 m box city along x, overlapping in y and z (so
    no y or z plane parts them, and every x plane clips them all)."""
    rng = np.random.default_rng(seed)
    y = rng.uniform(150, 150.2, n)
    z = rng.uniform(10, 10.2, n)
    v = np.stack([np.column_stack([np.zeros(n), y, z]), np.column_stack([np.full(n, 300.0), y, z]),
                  np.column_stack([np.full(n, 150.0), y + 0.5, z + 0.5])], 1).reshape(-1, 3)
    return v, np.arange(3 * n).reshape(n, 3)


def _twin_cases():
    """(name, inputs, settings, paths) of the interpreted build's test: dates (time splits),
    no dates, degenerate and duplicate triangles, huge and far coordinates, and settings that
    reach the binned planes, deferred subtrees, large leaves and many clipped straddlers;
    ``paths``: callee -> (least calls, least size of the first argument) the case must show."""
    dated = box_city(40, seed=5)
    v, t, begin, end, mat = box_city(20, seed=6, dated=False)
    sv, st = _slivers(80, 7)
    degenerate = np.array([[0, 0, 0], [1, 1, 1], [0, 1, 0], [2, 3, 2]], np.int32)
    t_deg = np.vstack([t, t[:40], degenerate, t[::-1][:10]])        # duplicates: same ids too
    n_deg = t_deg.shape[0]
    mixed_v = np.vstack([v, sv]).astype(np.float32)
    mixed_t = np.vstack([t, st + v.shape[0]]).astype(np.int32)
    n_mix = mixed_t.shape[0]
    swept = {"_sweep_axis": (1, 1), "_clipped_box": (1, 1)}
    return [
        ("dated", dated, KdTreeSettings(), swept),
        ("dated binned, subtrees", dated, KdTreeSettings(sweep_threshold=24, bins=7,
                                                         subtree_refs=40),
         {**swept, "_binned_axis": (1, 25), "_build_kernel": (3, 1)}),
        ("dated large leaves", dated, KdTreeSettings(max_depth=3), {"_heapsort": (1, 33)}),
        ("degenerate and duplicate", (v, t_deg, np.full(n_deg, -np.inf), np.full(n_deg, np.inf),
                                      np.zeros(n_deg, np.int32)), KdTreeSettings(), swept),
        ("slivers", (mixed_v, mixed_t, np.full(n_mix, -np.inf), np.full(n_mix, np.inf),
                     np.arange(n_mix, dtype=np.int32) % 3), KdTreeSettings(sweep_threshold=512),
         {**swept, "_sort_by_value": (1, 33)}),
        ("far", (dated[0] + np.float32(3.3e6),) + dated[1:], KdTreeSettings(), swept),
        ("huge", (dated[0] * np.float32(1e30),) + dated[1:],
         KdTreeSettings(sweep_threshold=100, bins=5), {**swept, "_binned_axis": (1, 101)}),
    ]


def _counting(space, name, seen):
    """Wrap the twin's callee ``name`` so the test sees the paths that ran: (calls, largest
    size of the first argument)."""
    inner = space[name]

    def wrapper(*args):
        calls, size = seen.get(name, (0, 0))
        seen[name] = (calls + 1, max(size, int(getattr(args[0], "shape", (1,))[0])))
        return inner(*args)
    return wrapper


@pytest.mark.parametrize("case", range(7))
def test_interpreted_twin_builds_the_compiled_tree(monkeypatch, case):
    """Small builds on first use run the kernels' Python source (runtime.interpret): every
    array of the tree and every statistic but the time equal the compiled build's, bit for
    bit, on inputs that reach the binned and swept planes, time splits, deferred subtrees,
    clipping, the heapsorts and the far and huge coordinates where every step rounds."""
    _assert_twin_builds_the_compiled_tree(monkeypatch, *_twin_cases()[case])


def test_interpreted_twin_builds_the_sample_city_s_compiled_tree(monkeypatch, sample_city_scene):
    """The same on the bundled sample city, from its read-only memory-mapped arrays."""
    s = sample_city_scene
    _assert_twin_builds_the_compiled_tree(
        monkeypatch, "sample city", (s.vertices, s.triangles, s.tri_t_begin_days,
                                     s.tri_t_end_days, s.tri_material), KdTreeSettings(),
        {"_sweep_axis": (1, 1000), "_clipped_box": (1, 1)})


def _assert_twin_builds_the_compiled_tree(monkeypatch, name, inputs, settings, paths):
    import cityshade.accel.kdtree_build as K
    from cityshade.runtime.interpret import InterpretBudget, python_twin

    monkeypatch.setattr(K, "_INTERPRET", InterpretBudget(0))
    compiled = build_kdtree(*inputs, settings=settings)
    space = python_twin(K._build_kernel).__globals__
    seen: dict = {}
    for callee in paths:
        monkeypatch.setitem(space, callee, _counting(space, callee, seen))
    budget = InterpretBudget(10 ** 9)
    monkeypatch.setattr(K, "_INTERPRET", budget)
    twin = build_kdtree(*inputs, settings=settings)
    assert budget.left == 10 ** 9 - inputs[1].shape[0], name  # it ran interpreted
    for array in ("nodes", "prim_indices", "tri_records", "bounds"):
        a, b = getattr(compiled, array), getattr(twin, array)
        assert a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes(), \
            f"{name}: {array}"
    assert {k: v for k, v in compiled.stats.items() if k != "build_s"} == \
        {k: v for k, v in twin.stats.items() if k != "build_s"}, name
    assert compiled.stats["nodes"] > 10, name
    for callee, (calls, size) in paths.items():  # the case reached what it is there for
        got = seen.get(callee, (0, 0))
        assert got[0] >= calls and got[1] >= size, (name, callee, got)
    if inputs[2].size and np.isfinite(inputs[2]).any():
        assert compiled.stats["time_splits"] > 0, name


def test_interpreted_binned_planes_widen_float32_like_numba():
    """The time axis's bins of float32 bounds against a Python float ``t0``: NumPy 2 would
    subtract and compare in float32, Numba in float64. References on every bin boundary and
    its float32 neighbours give the twin the compiled kernel's best plane, bit for bit (the
    unwidened source missed it in most of these trials)."""
    import cityshade.accel.kdtree_build as K
    from cityshade.runtime.interpret import python_twin

    twin = python_twin(K._binned_axis)
    rng = np.random.default_rng(1)
    nbins = 64
    blo, bhi = np.array([0.0, 0.0, 0.0, -np.inf]), np.array([1.0, 1.0, 1.0, np.inf])
    for _ in range(50):
        t0 = float(rng.uniform(-3e4, 0))
        t1 = float(t0 + rng.uniform(1e3, 4e4))
        edges = np.float32(t0 + np.arange(1, nbins) * (t1 - t0) / nbins)
        x = np.concatenate([edges, np.nextafter(edges, np.float32(np.inf)),
                            np.nextafter(edges, np.float32(-np.inf))])
        lo = np.zeros((x.size, 4), np.float32)
        hi = np.ones((x.size, 4), np.float32)
        lo[:, 3] = x
        hi[:, 3] = np.float32(t1 + 5.0)
        found = []
        for kernel in (K._binned_axis, twin):
            best = np.array([np.inf, -1.0, 0.0, 0.0])
            kernel(lo, hi, 3, blo, bhi, t0, t1, 1.0, 0.7, 0.2, nbins, best)
            found.append(best)
        assert found[0][1] == 3.0 and found[0].tobytes() == found[1].tobytes(), (t0, t1)
