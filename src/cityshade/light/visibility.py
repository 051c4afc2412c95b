"""Which sky directions each receiver sees: one bit per receiver and direction, traced once.

A receiver is a point on a surface with its unit normal (a map pixel, a surface sample, an
opening's reference point). For every direction of a :class:`~cityshade.light.sky.Sky` in front
of the receiver's plane (:func:`~cityshade.light.sky.in_front`) one shadow ray leaves the point,
pushed off its surface (:func:`cityshade.trace.shadow_rays_from_surface`), and the exact engine
says whether it is blocked (:func:`cityshade.shadows.visibility.occluded`: ``izb`` or
``raytrace``, the same bits). Directions behind or in the plane are not traced and count as not
visible. The bits are kept packed (``np.packbits`` along the directions), so one tracing serves
the sky view factor, the vertical sky component and every hour of a year (daylight
coefficients): :mod:`cityshade.light.metrics` is arithmetic on them.

Memory: the result holds ``ceil(P / 8)`` bytes per receiver for P directions (19 B for
Tregenza's 145, 73 B for 577, 289 B for 2,305) plus the receivers' float64 normals (24 B).
While tracing, one direction's ray origins and rows (32 B per receiver), a byte holding eight
directions' answers until they go into the packed bits together (:mod:`cityshade.light.kernels`)
and the engine's own work arrays (docs/DESIGN.md §7, §6).

Trees: on a scene with vegetation crowns (docs/DESIGN.md §21) a bit says "no opaque triangle
in the way", and the rays that cross crowns are listed apart (:class:`SkyCrowns`: 24 bytes per
such ray, with the product of the crowns' transmissivities in leaf and leafless); each
direction then costs one opaque pass and two crowns' passes, and holds 17 bytes of results per
receiver besides its origins. A scene without vegetation lists nothing and is traced exactly as
before.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cityshade.errors import UsageError

#: The exact engines a sky can be traced with (:func:`cityshade.shadows.visibility.occluded`).
ENGINES = ("izb", "raytrace")

#: Directions between two progress calls (a multiple of 8: whole bytes); ``raytrace`` on a few
#: receivers (:data:`BATCH_RAYS`) traces a block in one call, unpacked (64 B per receiver).
DEFAULT_BLOCK = 64

#: ``raytrace`` takes a direction per ray: up to this many rays (24 B of origins and 24 B of
#: directions each) go to the engine in one call rather than one call per direction, which
#: costs a few milliseconds each and dominates for a few receivers (a window's reference
#: point). The rays are the same, so the bits are.
BATCH_RAYS = 1 << 20


@dataclass(frozen=True)
class SkyVisibility:
    """The visibility bits of N receivers towards the P directions of a sky.

    Attributes
    ----------
    sky : Sky
        The directions (render space, grid north).
    bits : (N, ceil(P / 8)) uint8
        ``np.packbits(visible, axis=1)`` (big bit order): bit ``p`` of row ``i`` is 1 when
        receiver ``i`` sees direction ``p``; 0 when blocked or behind the receiver's plane.
    normals : (N, 3) float64
        The receivers' unit normals (the metrics weight the directions by them).
    t_days : float
        City time the bits were traced at, days since 1970-01-01 UTC.
    engine : str
        ``izb`` or ``raytrace``.
    """

    sky: object
    bits: np.ndarray
    normals: np.ndarray
    t_days: float
    engine: str
    #: The rays through vegetation crowns (:class:`SkyCrowns`), None for a scene without
    #: vegetation: then the bits are the whole answer.
    crowns: object = None

    @property
    def n_receivers(self) -> int:
        return int(self.bits.shape[0])

    def visible(self, rows=slice(None)) -> np.ndarray:
        """(n, P) bool: the unpacked bits of receivers ``rows`` (index array or slice); it
        costs P bytes per receiver, so unpack a block of rows at a time for large N."""
        return np.unpackbits(self.bits[rows], axis=1, count=self.sky.n).astype(bool)

    def nbytes_per_receiver(self) -> int:
        """Bytes kept per receiver: the packed bits and the normal (and, with crowns, their
        rays' mean share: :attr:`SkyCrowns.NBYTES` per ray through a crown)."""
        extra = 0
        if self.crowns is not None and self.n_receivers:
            extra = -(-len(self.crowns.rows) * SkyCrowns.NBYTES // self.n_receivers)
        return int(self.bits.shape[1]) + 24 + extra


@dataclass(frozen=True)
class SkyCrowns:
    """The (receiver, direction) rays that no opaque triangle blocks but that cross vegetation
    crowns, with the product of the crowns' transmissivities in leaf and leafless
    (docs/DESIGN.md §21): a ray of a :class:`SkyVisibility` counts with its bit × this
    transmission (1 for a ray not listed). Kept sparse: 24 bytes per such ray (:attr:`NBYTES`)
    and nothing for the others.

    Attributes
    ----------
    rows, cols : (K,) int32
        Receiver and direction of each ray.
    leaf_on, leaf_off : (K,) float64
        Its transmission with deciduous crowns in leaf and leafless (evergreen classes in leaf
        in both).
    """

    rows: np.ndarray
    cols: np.ndarray
    leaf_on: np.ndarray
    leaf_off: np.ndarray

    #: Bytes per ray through a crown: two int32 indices and two float64 transmissions.
    NBYTES = 24

    def transmission(self, leaf: bool) -> np.ndarray:
        """(K,) the rays' transmissions in leaf or leafless."""
        return self.leaf_on if leaf else self.leaf_off


def sky_visibility(scene, points, normals, sky, t_days: float = 0.0, *, engine: str = "izb",
                   block: int = DEFAULT_BLOCK, progress=None) -> SkyVisibility:
    """Trace every sky direction in front of every receiver through an exact engine.

    Parameters
    ----------
    scene : Scene
        A scene with its own kd-tree or a tiled cache's view.
    points : (N, 3) float array
        Receivers on surfaces, render-space metres.
    normals : (N, 3) float array
        Their unit normals, on the side the sky is seen from (outward).
    sky : Sky
        The directions (:func:`cityshade.light.sky.sky_for_scene`).
    t_days : float
        City time, days since 1970-01-01 UTC (the objects standing then block).
    engine : str
        ``izb`` (default; one light-space pass per direction) or ``raytrace``; both give the
        same bits.
    block : int
        Directions between progress calls (a multiple of 8); ``raytrace`` on few receivers
        traces a block in one call (``block`` bytes per receiver).
    progress : callable, optional
        Called as ``progress(done, total)`` directions after each block.

    Returns
    -------
    SkyVisibility
        Memory: ``ceil(P / 8) + 24`` bytes per receiver (see the module's docstring).

    Raises
    ------
    UsageError
        An unknown engine, a bad block, or points and normals of different shapes.

    Examples
    --------
    >>> from cityshade.light.sky import named_sky
    >>> vis = sky_visibility(scene, [[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]],
    ...                      named_sky("tregenza"))                    # doctest: +SKIP
    >>> vis.visible().sum()                          # open ground sees all 145 # doctest: +SKIP
    145
    """
    from cityshade.geometry.vegetation import scene_vegetation, vegetation_settings
    from cityshade.light.sky import FRONT_MIN_COS, in_front
    from cityshade.shadows.visibility import crown_transmission, occluded
    from cityshade.light.kernels import front_origins
    from cityshade.trace import (SHADOW_OFFSET_MIN_SCALE_M, SHADOW_OFFSET_REL,
                                 shadow_rays_from_surface)

    if engine == "exact":      # one choice for the whole sky: its directions share the set-up
        from cityshade.shadows.exact import engine_for_run

        engine = engine_for_run(engine, scene, len(np.asarray(points).reshape(-1, 3)),
                                len(sky.directions))
    if engine not in ENGINES:
        raise UsageError(f"sky visibility is traced with {' or '.join(ENGINES)}, not {engine!r}")
    if not (isinstance(block, (int, np.integer)) and block >= 8 and block % 8 == 0):
        raise UsageError(f"the block of directions must be a positive multiple of 8, not {block}")
    pts = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
    nrm = np.ascontiguousarray(normals, dtype=np.float64).reshape(-1, 3)
    if pts.shape != nrm.shape:
        raise UsageError(f"points {pts.shape} and normals {nrm.shape} differ in shape")
    n, p_total = len(pts), sky.n
    bits = np.zeros((n, (p_total + 7) // 8), np.uint8)
    rows_buf, origins_buf = np.empty(n, np.int64), np.empty((n, 3), np.float64)
    answers = _HeldAnswers(bits)
    if n:   # the checks, once, into the buffer the directions' origins reuse
        shadow_rays_from_surface(pts, nrm, sky.directions[0], out=origins_buf)
    veg = scene_vegetation(scene)
    if veg is not None:
        # Both seasons in one tracing: one opaque pass and two crowns' passes per direction.
        settings = vegetation_settings(scene)
        taus = (veg.transmissivity_in(settings, True), veg.transmissivity_in(settings, False))
        # Every crown the same in both seasons (evergreen classes, equal values): one pass.
        same = np.array_equal(taus[0], taus[1])
        crown_parts: list[tuple] = []
    # izb sorts the casters again whenever a direction's key order changes (lightspace.
    # caster_order: 5 orders over a hemisphere, but 22 changes in Tregenza's band order):
    # directions are traced grouped by it, each into its own column, so the bits are the same.
    order = direction_order(sky.directions)
    for start in range(0, p_total, int(block)):
        stop = min(start + int(block), p_total)
        dirs = sky.directions[start:stop]
        if veg is None and engine == "raytrace" and n * len(dirs) <= BATCH_RAYS:
            work = np.zeros((n, stop - start), bool)
            rows, cols = np.nonzero(in_front(nrm, dirs))
            if len(rows):
                d = np.ascontiguousarray(dirs[cols])
                origins = shadow_rays_from_surface(pts[rows], nrm[rows], d)
                work[rows, cols] = ~occluded(scene, origins, d, t_days, engine=engine)
            bits[:, start // 8:(stop + 7) // 8] = np.packbits(work, axis=1)
        else:
            for col in order[start:stop]:
                d = sky.directions[col]
                k = front_origins(pts, nrm, d, FRONT_MIN_COS, SHADOW_OFFSET_REL,
                                  SHADOW_OFFSET_MIN_SCALE_M, rows_buf, origins_buf)
                if not k:
                    continue
                rows, origins = rows_buf[:k], origins_buf[:k]
                if veg is None:
                    blocked = occluded(scene, origins, d, t_days, engine=engine)
                else:
                    blocked, outs = crown_transmission(scene, origins, d, t_days,
                                                       taus[:1] if same else taus,
                                                       engine=engine)
                    on, off = outs[0], outs[-1]
                    part = ~blocked & ((on != 1.0) | (off != 1.0))
                    if part.any():
                        crown_parts.append((rows[part], int(col), on[part], off[part]))
                answers.add(rows, blocked, int(col))
            answers.put()
        if progress is not None:
            progress(stop, p_total)
    return SkyVisibility(sky=sky, bits=bits, normals=nrm, t_days=float(t_days), engine=engine,
                         crowns=None if veg is None else _sky_crowns(crown_parts))


class _HeldAnswers:
    """The answers of up to :data:`~cityshade.light.kernels.HELD_DIRECTIONS` directions held
    in a byte per receiver, then put into the packed bits together."""

    def __init__(self, bits):
        self.bits, self.held, self.columns = bits, np.zeros(bits.shape[0], np.uint8), []

    def add(self, rows, blocked, column: int) -> None:
        """Direction ``column``'s answers for receivers ``rows`` (rays ``blocked`` or not)."""
        from cityshade.light.kernels import HELD_DIRECTIONS, hold_visible

        hold_visible(self.held, rows, blocked, len(self.columns))
        self.columns.append(column)
        if len(self.columns) == HELD_DIRECTIONS:
            self.put()

    def put(self) -> None:
        """The held answers into the bits (before a progress call: its directions are done)."""
        from cityshade.light.kernels import put_held

        if self.columns:
            put_held(self.bits, self.held, self.columns)
            self.columns = []


def _sky_crowns(crown_parts) -> SkyCrowns:
    """The :class:`SkyCrowns` of (rows, direction, leaf-on, leaf-off) parts, direction-major
    (the sky's order, whatever order the directions were traced in)."""
    crown_parts = sorted(crown_parts, key=lambda part: part[1])
    return SkyCrowns(
        rows=np.concatenate([r for r, *_ in crown_parts] or [np.zeros(0)]).astype(np.int32),
        cols=np.concatenate([np.full(len(r), c) for r, c, *_ in crown_parts]
                            or [np.zeros(0)]).astype(np.int32),
        leaf_on=np.concatenate([on for *_, on, _ in crown_parts] or [np.zeros(0)]),
        leaf_off=np.concatenate([off for *_, off in crown_parts] or [np.zeros(0)]))


def direction_order(directions) -> np.ndarray:
    """(P,) int64: the directions' indices grouped by the light-space engine's caster key order
    (:func:`cityshade.lightspace.caster_order`), first appearance first, the sky's order
    inside a group: the order :func:`sky_visibility` traces them in."""
    from cityshade.lightspace import caster_order

    groups: dict = {}
    for i, d in enumerate(np.asarray(directions, np.float64)):
        groups.setdefault(caster_order(d), []).append(i)
    return np.array([i for g in groups.values() for i in g], np.int64)


def map_pixels(camera_pass) -> np.ndarray:
    """(N,) int64 flat indices (``row * W + col``) of the pixels of a map or view that show a
    surface, row-major: the receivers of :func:`map_receivers`."""
    return np.flatnonzero(np.asarray(camera_pass.surfaces.valid).ravel())


def map_receivers(camera_pass) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The receivers of a map or view: its pixels that show a surface.

    Parameters
    ----------
    camera_pass : CameraPass
        :func:`cityshade.frame.pipeline.camera_pass` of the scene and camera.

    Returns
    -------
    points : (N, 3) float64
        Render-space positions of the pixels with a surface, row-major.
    normals : (N, 3) float64
        Their normals turned to the side the camera sees.
    pixels : (N,) int64
        Flat pixel indices (``row * W + col``), to put per-receiver values back in a map.

    Examples
    --------
    >>> cp = camera_pass(scene, map_view(scene, 1.0), t_days)      # doctest: +SKIP
    >>> points, normals, pixels = map_receivers(cp)                # doctest: +SKIP
    """
    surf = camera_pass.surfaces
    pixels = map_pixels(camera_pass)
    points = np.asarray(surf.position_m, np.float64).reshape(-1, 3)[pixels]
    normals = np.asarray(camera_pass.normal, np.float64).reshape(-1, 3)[pixels]
    return points, normals, pixels


def polygon_reference_points(scene, polygon_groups) -> tuple[np.ndarray, np.ndarray]:
    """One receiver per group of polygons (an opening): its area centroid and mean normal.

    BRE 209 takes a window's vertical sky component at the centre of the window on its outer
    face: the area-weighted centroid of the opening's triangles, which lies on the face of a
    flat opening (a group's polygons are coplanar in practice; the centroid of a bent group
    is the mean, off its surfaces by the bend).

    Parameters
    ----------
    scene : Scene
    polygon_groups : sequence of sequences of int
        Polygon indices per receiver (e.g. ``Opening.polygons`` of
        :func:`cityshade.planning.compare.openings_of`).

    Returns
    -------
    points : (G, 3) float64
        Render-space centroids (NaN for a group without triangles).
    normals : (G, 3) float64
        Unit area-weighted normals of the groups' triangles (outward by the winding).

    Examples
    --------
    >>> points, normals = polygon_reference_points(scene, [o.polygons for o in openings_of(scene)])  # doctest: +SKIP
    """
    verts = np.asarray(scene.vertices, np.float64)
    tri = np.asarray(scene.triangles)
    tri_poly = np.asarray(scene.tri_polygon)
    points = np.full((len(polygon_groups), 3), np.nan)
    normals = np.full((len(polygon_groups), 3), np.nan)
    for g, polys in enumerate(polygon_groups):
        t = tri[np.isin(tri_poly, np.asarray(list(polys), np.int64))]
        if not len(t):
            continue
        a, b, c = verts[t[:, 0]], verts[t[:, 1]], verts[t[:, 2]]
        cross = np.cross(b - a, c - a)              # twice the area, along the normal
        area = np.linalg.norm(cross, axis=1)
        if area.sum() <= 0.0:
            continue
        points[g] = ((a + b + c) / 3.0 * area[:, None]).sum(axis=0) / area.sum()
        s = cross.sum(axis=0)
        normals[g] = s / np.linalg.norm(s)
    return points, normals
