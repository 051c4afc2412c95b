"""Per-surface results: sample points on every drawn polygon, shadow rays from them, means.

A camera sees only part of a city; per-surface sun-hours (roofs AND walls, courtyards, the far
side of a block) need points on the surfaces themselves. Each triangle of a polygon standing at
the city time is split into ``m²`` congruent sub-triangles (``m = max(1, round(sqrt(area ·
density)))``: the midpoint subdivision), and the centroid of each is a sample carrying
``area / m²`` of the triangle. This is stratified (one point per stratum of equal area), so
every polygon gets at least one point per triangle and the area-weighted mean of a constant is
exact. A sample is lit when its outward normal (the polygon's winding, CityGML's convention)
faces the sun and its shadow ray through the kd-tree is free: the same facing rule and ray
offset as the per-pixel techniques (docs/DESIGN.md §9).
"""
from __future__ import annotations

import csv
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit

from cityshade.errors import UsageError

__all__ = ["SurfaceSamples", "SampleSettings", "sample_surfaces", "samples_lit",
           "polygon_means", "surface_rows", "write_surface_csv", "CSV_COLUMNS"]


@dataclass(frozen=True)
class SampleSettings:
    """Tunables of the per-surface sampling.

    Attributes
    ----------
    samples_per_m2 : float
        Target density of sample points; 1 per m² resolves the shadow of a chimney-sized
        object on a roof and keeps a 1M-triangle city at a few million points.
    max_samples : int
        Refuse more points than this in total (memory: 56 bytes per point, plus one shadow
        ray per point and step): 50 M points ≈ 2.8 GB.
    """

    samples_per_m2: float = 1.0
    max_samples: int = 50_000_000

    def __post_init__(self) -> None:
        if not (math.isfinite(self.samples_per_m2) and 0.0 < self.samples_per_m2 <= 10_000.0):
            raise UsageError(f"samples per m² must be in (0, 10000], not {self.samples_per_m2}")
        if self.max_samples < 1:
            raise UsageError(f"max_samples must be >= 1, not {self.max_samples}")


@dataclass(eq=False)
class SurfaceSamples:
    """Sample points on the drawn polygons of a scene.

    Attributes
    ----------
    points_m : (N, 3) float64
        Render-space points on the triangles.
    normals : (N, 3) float64
        Unit outward normals of their triangles.
    weight_m2 : (N,) float64
        Area each point stands for (the triangle's area / m²).
    polygon : (N,) int32
        Index into the scene's polygon table.
    sampled : (P,) bool
        Polygons with at least one sample (standing at the city time, non-zero area).
    samples_per_m2 : float
        Density asked for.
    """

    points_m: np.ndarray
    normals: np.ndarray
    weight_m2: np.ndarray
    polygon: np.ndarray
    sampled: np.ndarray
    samples_per_m2: float

    @property
    def n(self) -> int:
        return int(self.points_m.shape[0])


@njit(cache=True)
def _subdivision_centroids(v0, e1, e2, m, first, points_out):
    """Centroids of the m² midpoint sub-triangles of each triangle.

    v0, e1, e2 : (T, 3) float64 — first vertex and edges v1 − v0, v2 − v0.
    m : (T,) int64 subdivisions per edge; first : (T,) int64 offset of each triangle's points.
    """
    for t in range(v0.shape[0]):
        k = first[t]
        mt = m[t]
        inv = 1.0 / mt
        # Upright sub-triangles (i, j), (i+1, j), (i, j+1): centroid at (i + 1/3, j + 1/3) / m.
        for i in range(mt):
            for j in range(mt - i):
                a = (i + 1.0 / 3.0) * inv
                b = (j + 1.0 / 3.0) * inv
                for c in range(3):
                    points_out[k, c] = v0[t, c] + a * e1[t, c] + b * e2[t, c]
                k += 1
        # Inverted sub-triangles (i+1, j), (i, j+1), (i+1, j+1): centroid at (i + 2/3, j + 2/3) / m.
        for i in range(mt - 1):
            for j in range(mt - 1 - i):
                a = (i + 2.0 / 3.0) * inv
                b = (j + 2.0 / 3.0) * inv
                for c in range(3):
                    points_out[k, c] = v0[t, c] + a * e1[t, c] + b * e2[t, c]
                k += 1


def sample_surfaces(scene, samples_per_m2: float = 1.0, t_days: float = 0.0,
                    settings: SampleSettings | None = None,
                    polygon_density: np.ndarray | None = None) -> SurfaceSamples:
    """Stratified sample points on every polygon standing at city time ``t_days``.

    Parameters
    ----------
    scene : Scene
    samples_per_m2 : float
        Target density (at least one point per triangle regardless).
    t_days : float
        City time, days since 1970-01-01 UTC (objects standing then are sampled).
    settings : SampleSettings, optional
        Limits; its density is replaced by ``samples_per_m2``.
    polygon_density : (P,) float, optional
        Density per polygon instead of ``samples_per_m2`` (0: not sampled), e.g. denser on
        windows.

    Returns
    -------
    SurfaceSamples

    Raises
    ------
    UsageError
        Bad density, NaN time, or more points than ``settings.max_samples``.
    """
    settings = SampleSettings(samples_per_m2=float(samples_per_m2),
                              max_samples=(settings or SampleSettings()).max_samples)
    t = float(t_days)
    if math.isnan(t):
        raise UsageError("t_days must be a number of days, not NaN")
    tri = np.asarray(scene.triangles)
    verts = np.asarray(scene.vertices, dtype=np.float64)
    present = (np.asarray(scene.tri_t_begin_days) <= t) & (t < np.asarray(scene.tri_t_end_days))
    v0 = verts[tri[:, 0]]
    e1 = verts[tri[:, 1]] - v0
    e2 = verts[tri[:, 2]] - v0
    cross = np.cross(e1, e2)
    twice_area = np.linalg.norm(cross, axis=1)
    # Degenerate triangles carry no area and have no normal: they get no points.
    density = settings.samples_per_m2
    if polygon_density is not None:
        dens_p = np.asarray(polygon_density, np.float64)
        if dens_p.shape != (len(scene.poly_ids),) or not (np.isfinite(dens_p).all()
                                                         and (dens_p >= 0.0).all()):
            raise UsageError("polygon_density must be (P,) finite densities >= 0")
        density = dens_p[np.asarray(scene.tri_polygon)]
        present &= density > 0.0
    keep = np.flatnonzero(present & (twice_area > 0.0))
    area = 0.5 * twice_area[keep]
    if polygon_density is not None:
        density = density[keep]
    m = np.maximum(1, np.rint(np.sqrt(area * density))).astype(np.int64)
    counts = m * m
    total = int(counts.sum())
    if total > settings.max_samples:
        raise UsageError(f"{total} surface sample points exceed the limit of "
                         f"{settings.max_samples}; lower --samples-per-m2")
    first = np.zeros(len(keep), np.int64)
    if len(keep):
        first[1:] = np.cumsum(counts)[:-1]
    points = np.empty((total, 3), np.float64)
    _subdivision_centroids(np.ascontiguousarray(v0[keep]), np.ascontiguousarray(e1[keep]),
                           np.ascontiguousarray(e2[keep]), m, first, points)
    normal_t = cross[keep] / twice_area[keep, None]
    polygon_t = np.asarray(scene.tri_polygon)[keep].astype(np.int32)
    sampled = np.zeros(len(scene.poly_ids), bool)
    sampled[polygon_t] = True
    return SurfaceSamples(points_m=points, normals=np.repeat(normal_t, counts, axis=0),
                          weight_m2=np.repeat(area / counts, counts),
                          polygon=np.repeat(polygon_t, counts), sampled=sampled,
                          samples_per_m2=settings.samples_per_m2)


def samples_lit(scene, samples: SurfaceSamples, sun, t_days: float,
                engine: str = "exact") -> np.ndarray:
    """(N,) float64: the fraction of the sun each sample gets: 0 facing away (N·L <= 0) or
    blocked, 1 lit, between where only vegetation is in the way (docs/DESIGN.md §21).

    A sun at or below the horizon lights nothing. ``engine`` decides the shadow rays:
    ``izb`` (:mod:`cityshade.lightspace`) or ``raytrace`` (:mod:`cityshade.trace`), the same
    answer.
    """
    from cityshade.shadows import facing_mask, take_pixels
    from cityshade.shadows.visibility import sun_fraction

    lit = np.zeros(samples.n, np.float64)
    if not sun.above_horizon or samples.n == 0:
        return lit
    direction = np.asarray(sun.direction, dtype=np.float64)
    # The shared facing rule (a frame's, a batch's): numpy's ``normals @ direction`` rounds
    # as the machine's BLAS kernel does.
    faces = np.flatnonzero(facing_mask(samples.normals, True, direction))
    if len(faces):
        lit[faces] = sun_fraction(scene, take_pixels(samples.points_m, faces),
                                  take_pixels(samples.normals, faces), sun, t_days,
                                  engine=engine)
    return lit


def polygon_means(samples: SurfaceSamples, values: np.ndarray) -> np.ndarray:
    """Area-weighted mean of per-sample ``values`` (N,) per polygon: (P,) float64, NaN where a
    polygon has no sample."""
    values = np.asarray(values, dtype=np.float64)
    if values.shape != (samples.n,):
        raise UsageError(f"values must have shape ({samples.n},), not {values.shape}")
    n_poly = samples.sampled.shape[0]
    weight = np.bincount(samples.polygon, weights=samples.weight_m2, minlength=n_poly)
    total = np.bincount(samples.polygon, weights=samples.weight_m2 * values, minlength=n_poly)
    return np.divide(total, weight, out=np.full(n_poly, np.nan), where=weight > 0.0)


#: Columns of the per-surface CSV.
CSV_COLUMNS = ("object_id", "polygon_id", "polygon_index", "surface_class", "area_m2",
               "samples", "mean_sun_hours")


def polygon_rows(scene, samples: SurfaceSamples):
    """The first six columns of :data:`CSV_COLUMNS` (object and polygon gml:id, polygon index,
    surface class, area in m², samples) of every sampled polygon, numbers unformatted."""
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    counts = np.bincount(samples.polygon, minlength=samples.sampled.shape[0])
    for p in np.flatnonzero(samples.sampled):
        cls = int(scene.poly_class[p])
        yield (scene.obj_ids[int(scene.poly_object[p])], scene.poly_ids[p], int(p),
               SURFACE_CLASSES[cls] if cls < len(SURFACE_CLASSES) else cls,
               float(scene.poly_area_m2[p]), int(counts[p]))


def surface_rows(scene, samples: SurfaceSamples, polygon_hours: np.ndarray):
    """Rows of ``surfaces.csv`` (:data:`CSV_COLUMNS`) as tuples, numbers unformatted: one per
    sampled polygon."""
    for row in polygon_rows(scene, samples):
        yield (*row, float(polygon_hours[row[2]]))


def write_surface_csv(path: str | os.PathLike, scene, samples: SurfaceSamples,
                      polygon_hours: np.ndarray) -> Path:
    """Write one row per sampled polygon: object and polygon gml:id, surface class, area in m²
    (the polygon's, holes removed), number of samples and mean sun-hours. Written to a
    temporary name and renamed."""
    from cityshade.util import atomic_write

    path = Path(path)
    with atomic_write(path, newline="", what="the surface table") as fh:
        writer = csv.writer(fh)
        writer.writerow(CSV_COLUMNS)
        for row in surface_rows(scene, samples, polygon_hours):
            writer.writerow([*row[:4], f"{row[4]:.3f}", row[5], f"{row[6]:.4f}"])
    return path
