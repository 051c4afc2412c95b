"""Exact visibility on a scene: which rays are blocked, which points see the sun.

The engines take one :class:`~cityshade.accel.KdTree` each: :mod:`cityshade.trace` (kd-tree
rays, ``raytrace``) and :mod:`cityshade.lightspace` (``izb``), the same answer on every ray. A
scene is one tree of its own or a tiled cache's view, whose rays go through every tile they can
reach (:meth:`~cityshade.geometry.scene.Scene.any_hit`). This module joins the two, so no engine
knows about tiles and no caller about engines' trees.
"""
from __future__ import annotations

import numpy as np

from cityshade.errors import ContractError


def _engine(name: str):
    """The any-hit function of the exact engine ``name`` (a :class:`TechniqueSpec`'s
    ``engine``): ``(tree, origins, directions, t_days, **options) -> (N,) bool``."""
    if name == "izb":
        from cityshade.lightspace import occluded

        return occluded
    if name == "raytrace":
        from cityshade.trace import occluded

        return occluded
    raise ContractError(f"no exact engine named {name!r}")


def occluded(scene, origins, directions, t_days: float = 0.0, *, engine: str = "raytrace",
             **options) -> np.ndarray:
    """(N,) bool: whether each ray from ``origins`` along ``directions`` is blocked by a
    triangle present at city time ``t_days``.

    Parameters
    ----------
    scene : Scene
        A scene with its own kd-tree or a tiled cache's view.
    origins : (N, 3) float array
        Render-space metres (shadow rays: from
        :func:`cityshade.trace.shadow_rays_from_surface`).
    directions : (3,) or (N, 3) float array
        Unit directions; ``izb`` takes one shared (3,) sun direction.
    t_days : float
        City time, days since 1970-01-01 UTC.
    engine : str
        ``raytrace``, ``izb`` or ``exact`` (:attr:`cityshade.shadows.TechniqueSpec.engine`):
        the cheaper of the two for each tree the rays meet
        (:func:`cityshade.shadows.exact.choose_for_tree`).
    **options
        Passed to the engine: ``tmax`` and ``brick_size`` (``raytrace``), ``stats`` and
        ``cell_m`` (``izb``); for ``exact``, ``calls`` (how many calls of this size share the
        izb set-up: a batch's sun positions) and ``chosen`` (a list that gets each tree's
        :class:`~cityshade.shadows.exact.EngineChoice`).
    """
    origins = np.ascontiguousarray(origins, dtype=np.float64)
    tmax = options.pop("tmax", None)
    calls = options.pop("calls", 1)
    chosen = options.pop("chosen", None)
    shared = np.asarray(directions).shape == (3,)

    def hit(tree, rays):
        d = directions if shared else _take(directions, rays)
        o = _take(origins, rays)
        name, extra = engine, dict(options)
        if engine == "exact":
            from cityshade.shadows.exact import choose_for_tree

            choice = choose_for_tree(tree, len(o), d, calls)
            name = choice.engine
            if chosen is not None:
                chosen.append(choice)
            if name == "raytrace":
                extra.pop("stats", None)
        if tmax is not None:
            extra["tmax"] = _take_per_ray(tmax, rays)
        return _engine(name)(tree, o, d, t_days, **extra)

    return scene.any_hit(origins, directions, hit)


def _take(arr, rays):
    return arr if isinstance(rays, slice) else np.asarray(arr)[rays]


def _take_per_ray(tmax, rays):
    """``tmax`` for the rays ``rays``: a shared value as it is, a per-ray (N,) array's rows."""
    arr = np.asarray(tmax, dtype=np.float64)
    if isinstance(rays, slice) or arr.ndim == 0 or arr.shape == (1,):
        return tmax
    return arr[rays]


def transmission(scene, origins, direction, t_days: float = 0.0, *, engine: str = "raytrace",
                 day_of_year: int | None = None, **options) -> np.ndarray:
    """(N,) float64 in [0, 1]: the fraction of the sun each ray from ``origins`` along the one
    sun ``direction`` (3,) keeps: 0 where an opaque triangle blocks it, else the product of
    the transmissivities of the distinct vegetation crowns it crosses (docs/DESIGN.md §21).

    A scene without vegetation (or a tiled cache's view, whose vegetation is opaque) is
    :func:`occluded` as it is: 1 or 0. ``day_of_year`` (1-366, None: no date) decides leaf on
    or off; ``options`` go to the opaque engine as for :func:`occluded`.
    """
    from cityshade.geometry.vegetation import scene_vegetation, vegetation_settings

    veg = scene_vegetation(scene)
    if veg is None:
        return (~occluded(scene, origins, direction, t_days, engine=engine,
                          **options)).astype(np.float64)
    tau = veg.transmissivity(vegetation_settings(scene), day_of_year)
    return crown_transmission(scene, origins, direction, t_days, (tau,), engine=engine,
                              **options)[1][0]


def crown_transmission(scene, origins, direction, t_days: float, taus, *,
                       engine: str = "raytrace", **options) -> tuple[np.ndarray, list]:
    """The opaque pass once and the crowns' pass once per set of crown transmissivities.

    ``taus``: a sequence of (C,) float64 arrays (:meth:`~cityshade.geometry.vegetation.
    SceneVegetation.transmissivity_in`, e.g. in leaf and leafless) of a scene WITH vegetation
    (:func:`~cityshade.geometry.vegetation.scene_vegetation` not None). Returns ``blocked``
    (N,) bool (an opaque triangle is in the way) and one (N,) float64 transmission per entry
    of ``taus`` (0 where blocked), as :func:`transmission` gives for each.
    """
    from cityshade.geometry.vegetation import scene_vegetation

    veg = scene_vegetation(scene)
    origins = np.ascontiguousarray(origins, dtype=np.float64)
    direction = np.ascontiguousarray(direction, dtype=np.float64).reshape(3)
    blocked = occluded(veg.opaque, origins, direction, t_days, engine=engine, **options)
    return blocked, crowns_pass(veg, origins, direction, t_days, np.flatnonzero(~blocked),
                                taus, engine=engine)


def crowns_pass(veg, origins, direction, t_days: float, rays, taus, *,
                engine: str = "izb") -> list[np.ndarray]:
    """The crowns alone: one (N,) float64 per entry of ``taus`` holding, for the rays ``rays``
    (indices into ``origins``), the product of the transmissivities of the distinct crowns of
    ``veg`` (a :class:`~cityshade.geometry.vegetation.SceneVegetation`) each crosses, and 0 for
    the other rays. ``origins`` (N, 3) float64, ``direction`` (3,) the one sun."""
    # The light-plane grid (izb, and exact: a crowns' pass has no early exit, so the tree's
    # walk visits every leaf along each ray, 4-5x the grid's cost on a map's pixels), or the
    # crowns' kd-tree (raytrace); the same bits either way.
    if engine in ("izb", "exact"):
        from cityshade.lightspace.vegetation import crown_records
        from cityshade.lightspace.vegetation import transmission as grid_crowns

        outs = np.zeros((len(taus), len(origins)), np.float64)
        grid_crowns(crown_records(veg), origins, direction, float(t_days), rays,
                    np.stack([np.asarray(tau, np.float64) for tau in taus]), outs)
        return list(outs)
    _engine(engine)  # an unknown name fails here
    from cityshade.trace.vegetation import transmission as tree_crowns

    outs = []
    for tau in taus:
        out = np.zeros(len(origins), np.float64)
        tree_crowns(veg.tree, origins, direction, float(t_days), rays, veg.tri_crown, tau, out)
        outs.append(out)
    return outs


def with_crowns(run, ctx):
    """``run(ctx)`` (a map technique's or the hybrid's: a
    :class:`~cityshade.shadows.ShadowResult`) with the crowns as partial shade
    (docs/DESIGN.md §21, "Map techniques"): the technique decides the opaque casters alone
    (its maps and rays see the scene without the crowns), then each facing pixel it leaves
    lit, fully or in part, is multiplied by its shadow ray's transmission through the crowns
    (:func:`crowns_pass`, exact). A scene without vegetation is ``run(ctx)`` as it is."""
    import dataclasses
    import time

    from cityshade.geometry.vegetation import (day_of_year, scene_vegetation,
                                               vegetation_settings)

    veg = scene_vegetation(ctx.scene)
    if veg is None:
        return run(ctx)
    # The receivers are the same pixels whatever casts: shared, not gathered again.
    opaque = dataclasses.replace(ctx, scene=veg.opaque, oriented_normal=ctx.normal)
    if not ctx.sun.above_horizon:
        return run(opaque)
    # Those ctx made already; the rest the technique makes on opaque (or in the contexts'
    # shared dict) and the crowns' pass reads from there: an exact technique's origins, a map
    # technique's gathered points and normals.
    for name in ("faces", "facing_points", "facing_normals", "facing_origins"):
        if name in ctx.__dict__:
            opaque.__dict__[name] = ctx.__dict__[name]
    result = run(opaque)
    t0 = time.perf_counter()
    from cityshade.shadows import scatter_pixels

    faces = opaque.faces
    lit = result.lit[faces]
    rays = np.flatnonzero(lit > 0)
    if rays.size:
        direction = np.asarray(ctx.sun.direction, np.float64)
        origins = opaque.facing_origins_of(rays)
        tau = veg.transmissivity(vegetation_settings(ctx.scene), day_of_year(ctx.sun))
        crowns = crowns_pass(veg, origins, direction, ctx.t_days,
                             np.arange(rays.size), (tau,))[0]
        lit[rays] *= crowns
        scatter_pixels(lit, faces, result.lit)
    d = result.diagnostics
    crowns_s = time.perf_counter() - t0
    d.timings_s = {**(d.timings_s or {}), "crowns_s": crowns_s}
    d.shadow_s = (d.shadow_s or 0.0) + crowns_s
    return result


def sunlit(scene, points, normals, sun_direction, t_days: float = 0.0, *,
           engine: str = "raytrace", stats: dict | None = None, **options) -> np.ndarray:
    """(N,) bool: whether each surface point sees the sun, by one shadow ray from the point
    pushed off its surface (:func:`cityshade.trace.shadow_rays_from_surface`).

    ``points``, ``normals``: (N, 3) render-space metres and unit normals on the side facing the
    sun; ``stats`` (``izb``): filled with the engine's profile; ``options``: as
    :func:`occluded`'s (``calls``, ``chosen`` for ``exact``)."""
    from cityshade.trace import shadow_rays_from_surface

    sun = np.asarray(sun_direction, dtype=np.float64)
    origins = shadow_rays_from_surface(points, normals, sun)
    if stats is not None:
        options["stats"] = stats
    return ~occluded(scene, origins, sun, t_days, engine=engine, **options)


def sun_fraction(scene, points, normals, sun, t_days: float = 0.0, *,
                 engine: str = "raytrace", stats: dict | None = None, **options) -> np.ndarray:
    """(N,) float64 in [0, 1]: the fraction of the sun each surface point gets, by one shadow
    ray from the point pushed off its surface (as :func:`sunlit`) through :func:`transmission`
    (1 lit, 0 shadow, between where only vegetation is in the way). ``sun`` is a
    :class:`~cityshade.geo.sun.SunPosition` (its date decides leaf on or off); ``options``
    as :func:`occluded`'s."""
    from cityshade.trace import shadow_rays_from_surface

    origins = shadow_rays_from_surface(points, normals, np.asarray(sun.direction, np.float64))
    return origins_sun_fraction(scene, origins, sun, t_days, engine=engine, stats=stats,
                                **options)


def origins_sun_fraction(scene, origins, sun, t_days: float = 0.0, *, engine: str = "raytrace",
                         stats: dict | None = None, **options) -> np.ndarray:
    """:func:`sun_fraction` of shadow rays whose origins are made already (N, 3)."""
    from cityshade.geometry.vegetation import day_of_year

    if stats is not None:
        options["stats"] = stats
    return transmission(scene, origins, np.asarray(sun.direction, dtype=np.float64), t_days,
                        engine=engine, day_of_year=day_of_year(sun), **options)
