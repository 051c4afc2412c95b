"""``exact``: the exact answer by whichever engine is cheaper for the call at hand.

``raytrace`` (kd-tree rays) and ``izb`` (the light-space engine) give the same decision on every
ray, so the choice is only about time, made per call and per kd-tree from a cost model:

- ``raytrace`` costs about the same per ray whatever the rest of the call;
- ``izb`` pays per sun for every caster it projects and bins, then little per receiver; and
  once per process and tree it gathers the casters and sorts them for the sun's dominant axis
  (:class:`cityshade.lightspace.Casters`), which a batch of many suns shares.

- ``izb``'s kernels are compiled once per machine (Numba's cache keeps them): until they are,
  a call that would take ``izb`` pays that compile too, so small runs on a fresh install (the
  sample city's first batch) stay with ``raytrace``, whose kernels every render compiles.

So ``izb`` wins on many receivers with a warm caster copy (a batch, the later frames of an
``evaluate``), ``raytrace`` on few receivers or a single frame of a large city in a fresh
process (the 1M-triangle city's 1 m map: 1.74 s by ``raytrace`` against 2.02 s by ``izb`` as
whole processes in session 35, though ``izb``'s warm query is faster).

The constants are nanoseconds at two threads, from ``benchmarks/raytrace.py`` and the
whole-process renders of the 1M-triangle city (cd5487c; the first use's, session 35;
docs/DESIGN.md §9, "exact");
``python benchmarks/exact_choice.py`` reruns the workloads, times both engines and prints
what the model chose against the faster one.
"""
from __future__ import annotations

from dataclasses import dataclass

from cityshade.shadows.raytraced import RayTraced

#: kd-tree shadow ray, per ray (map 122 ns, 1080p overview 75 ns).
RAYTRACE_NS_PER_RAY = 100.0
#: izb per sun: projecting and binning a caster (map: 31 + 49 ms for the 1M city's casters).
IZB_NS_PER_CASTER = 80.0
#: izb per receiver: the query (map 142 ms for 4.1 M receivers, overview 20 ms for 1.49 M).
IZB_NS_PER_RECEIVER = 30.0
#: izb once per process, tree and dominant sun axis: gathering and sorting the casters and
#: faulting in their pages; and per receiver its work arrays' fresh pages, which later calls
#: reuse (a first call's receiver costs about what a kd-tree ray does). Fitted to
#: ``benchmarks/exact_choice.py`` on the 1M-triangle city (session 35, renders without huge
#: pages): whole processes by izb took 0.18 and 0.28 s longer than by raytrace on the 1 m map
#: (2.61 M rays, two runs) and 0.19-0.35 s on the 1080p overview (1.57 M, four runs); the
#: model says 0.28 s for both. (1000 ns a caster and nothing per receiver, fitted at cd5487c with
#: huge pages, said 0.9-1.0 s.)
IZB_FIRST_USE_NS_PER_CASTER = 200.0
IZB_FIRST_USE_NS_PER_RECEIVER = 70.0
#: izb is taken only when it saves at least this much over all the calls: below it nobody
#: notices, while izb holds its sorted copy and work arrays (issue 41: +236 MB on the 1M map)
#: and, on a fresh install, compiles its own kernels on top of the kd-tree's.
IZB_MIN_SAVING_MS = 200.0
#: izb's kernels compiling in one process (``lightspace.kernels``: 19.2 CPU s, exclusive, in the
#: sample city's first ``batch`` with an empty cache, session 27); charged once to a run that
#: would take izb while they are neither compiled nor in Numba's cache.
IZB_COMPILE_MS = 19_000.0


@dataclass(frozen=True)
class EngineChoice:
    """Which exact engine a call used and why (``render -v`` prints :attr:`reason`)."""

    engine: str          # "izb" | "raytrace"
    reason: str
    izb_ms: float
    raytrace_ms: float


def izb_compiled() -> bool:
    """Whether izb's kernels are compiled in this process or in Numba's cache (its query stands
    for them: they compile together). While the command's first-use children are compiling
    them (``cityshade sky``'s do), it waits for them: the answer decides a whole run."""
    from cityshade.lightspace.kernels import query
    from cityshade.runtime import prewarm
    from cityshade.runtime.interpret import compiled_or_cached

    if compiled_or_cached(query):
        return True
    name = f"{query.py_func.__module__}:{query.py_func.__qualname__}"
    if prewarm.pending(name):
        prewarm.wait(name)
    return compiled_or_cached(query)


def choose_engine(n_rays: int, n_casters: int, *, shared_direction: bool = True,
                  warm: bool = False, calls: int = 1, compiled: bool = True) -> EngineChoice:
    """The cheaper exact engine for ``n_rays`` rays against a tree of ``n_casters`` triangles.

    ``shared_direction``: all rays go toward one sun (``izb`` needs it); ``warm``: the tree's
    casters are already sorted for this sun's axis in this process; ``calls``: how many calls
    of this size will share the first-use cost (a batch's sun positions); ``compiled``: izb's
    kernels are compiled or cached (:func:`izb_compiled`), else their compile is charged once.
    """
    n, m = max(int(n_rays), 0), max(int(n_casters), 0)
    rt_ms = n * RAYTRACE_NS_PER_RAY * 1e-6
    if not shared_direction:
        return EngineChoice("raytrace", "rays in many directions (izb needs one sun)", float("inf"),
                            rt_ms)
    first = 0.0 if warm else (m * IZB_FIRST_USE_NS_PER_CASTER
                              + n * IZB_FIRST_USE_NS_PER_RECEIVER) / max(int(calls), 1)
    izb_ms = (m * IZB_NS_PER_CASTER + n * IZB_NS_PER_RECEIVER + first) * 1e-6
    saving_ms = (rt_ms - izb_ms) * max(int(calls), 1) - (0.0 if compiled else IZB_COMPILE_MS)
    engine = "izb" if saving_ms >= IZB_MIN_SAVING_MS else "raytrace"
    setup = "casters ready" if warm else (
        f"caster sort shared by {calls} calls" if calls > 1 else "caster sort in this call")
    if not compiled:
        setup += f", izb not compiled yet (about {IZB_COMPILE_MS / 1000:.0f} s once)"
    reason = (f"{n:,} rays, {m:,} casters, {setup}: estimated izb {izb_ms:.3g} ms, "
              f"raytrace {rt_ms:.3g} ms")
    return EngineChoice(engine, reason, izb_ms, rt_ms)


def choose_for_tree(tree, n_rays: int, directions, calls: int = 1) -> EngineChoice:
    """:func:`choose_engine` for one kd-tree (a scene's or a tile's) and the rays' directions
    ((3,) shared, or (N, 3))."""
    import numpy as np

    from cityshade.lightspace import caster_order, casters_ready

    d = np.asarray(directions, np.float64)
    shared = d.shape == (3,) or (d.ndim == 2 and len(d) > 0 and bool((d == d[0]).all()))
    sun = d if d.shape == (3,) else (d[0] if shared else None)
    warm = shared and casters_ready(tree, *caster_order(sun))
    from cityshade.trace import tree_of

    kd = tree_of(tree)
    n_casters = int(kd.stats.get("triangles_valid", kd.tri_records.shape[0]))
    return choose_engine(n_rays, n_casters, shared_direction=shared, warm=warm, calls=calls,
                         compiled=not shared or izb_compiled())


class Exact(RayTraced):
    """The ``exact`` technique: a frame's shadow rays by the engine :func:`choose_engine`
    prefers for each kd-tree they meet (``raytrace``'s answer either way); the diagnostics
    say which and why."""

    name = "exact"

    def sunlit(self, scene, origins, sun, t_days, diagnostics):
        from cityshade.shadows.visibility import origins_sun_fraction

        chosen: list[EngineChoice] = []
        lit = origins_sun_fraction(scene, origins, sun, t_days, engine="exact", chosen=chosen)
        if chosen:
            diagnostics.note = describe_choices(chosen, "tiles")
        return lit


def describe_choices(chosen: list[EngineChoice], over: str) -> str:
    """What ``exact`` took, for ``-v``: the engine and why, or over several trees or calls
    (``over``: "tiles", "sun positions") the engines taken and the first choice's reason."""
    names = ", ".join(sorted({c.engine for c in chosen}))
    if len(chosen) == 1:
        return f"exact engine {names}: {chosen[0].reason}"
    return f"exact engine {names} over {len(chosen)} {over}; the first: {chosen[0].reason}"


def run_choice(scene, n_rays: int, calls: int) -> EngineChoice:
    """:func:`choose_engine` for a whole run of ``calls`` calls of about ``n_rays`` rays each
    against ``scene``'s triangles (see :func:`engine_for_run`)."""
    return choose_engine(n_rays, scene.n_triangles, calls=calls, compiled=izb_compiled())


def engine_for_run(engine: str, scene, n_rays: int, calls: int) -> str:
    """``engine`` as it is, or for ``exact`` the engine of a whole run of ``calls`` calls of
    about ``n_rays`` rays each (a tiled or distributed batch: its tasks share one set-up per
    worker, which a per-call choice in a fresh worker would never see as warm)."""
    if engine != "exact":
        return engine
    return run_choice(scene, n_rays, calls).engine
