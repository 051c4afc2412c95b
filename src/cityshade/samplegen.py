"""A seeded, deterministic generator of synthetic CityGML 2.0 cities.

The generated city imitates the German LoD2 files cityshade is made for (the TUM campus file of
the Bavarian survey office): buildings on a street grid with gaps, gabled, hipped and flat roofs,
dormers, set-back upper storeys, a courtyard block, a building with a ``bldg:BuildingPart``,
thematic boundary surfaces whose polygons are referenced by ``xlink:href`` from a ``gml:Solid``,
a TIN terrain the buildings stand on, X3D materials and one procedurally drawn facade texture.
Buildings carry ``yearOfConstruction`` (1700–2000) and some ``yearOfDemolition``, so the city
changes over the centuries.

It serves three purposes: the small committed sample in ``sample_data/``, test scenes of known
content, and the ~1-million-triangle benchmark city (``target_triangles``), which it writes piece
by piece so memory stays small whatever the size.

Determinism: the same arguments give the same bytes on every platform. All randomness comes
from :class:`random.Random` (Mersenne Twister, whose ``random()`` sequence Python guarantees
across versions and platforms) through ``random()`` only; geometry uses only ``+ - * /`` and
``round`` (correctly rounded in IEEE-754 double, unlike ``sin``/``cos`` whose last bit depends on
the C library), buildings are axis-aligned, and every number is formatted explicitly (``%.3f``
for coordinates, millimetres like real files; ``%.4f`` for texture coordinates).

Conventions: coordinates are EPSG:25832 (UTM 32N, x east, y north, metres) with heights in
EPSG:5783 (DHHN2016), written as the compound ``urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783``.
Rings are closed (first point repeated) and counter-clockwise seen from outside the building
(outward normals); interior rings run the other way.
"""
from __future__ import annotations

import argparse
import math
import os
import random
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from cityshade.errors import CityshadeError, SampleGenError, UsageError
from cityshade.util import atomic_write

__all__ = ["CityInfo", "SampleCitySettings", "SampleGenError", "generate_city",
           "facade_texture", "main"]

SRS_NAME = "urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783"

NS_CORE = "http://www.opengis.net/citygml/2.0"
NS_BLDG = "http://www.opengis.net/citygml/building/2.0"
NS_DEM = "http://www.opengis.net/citygml/relief/2.0"
NS_APP = "http://www.opengis.net/citygml/appearance/2.0"
NS_GEN = "http://www.opengis.net/citygml/generics/2.0"
NS_GML = "http://www.opengis.net/gml"
NS_XLINK = "http://www.w3.org/1999/xlink"
NS_XSI = "http://www.w3.org/2001/XMLSchema-instance"

#: AdV roof type codes (bldg:roofType), as used by the German LoD2 data.
_ROOF_TYPE_CODE = {"flat": "1000", "gabled": "3100", "hipped": "3200"}

#: Materials of the global appearance, in the order they are written (fixed: determinism).
#: diffuseColor is linear RGB 0..1: red clay tiles, dark slate, grey gravel of flat roofs, beige
#: plaster, red-brown brick, dark blue-grey glass.
_MATERIALS = (
    ("roof_tiles", "0.560 0.180 0.120"),
    ("roof_slate", "0.220 0.230 0.260"),
    ("roof_flat", "0.450 0.440 0.420"),
    ("wall_plaster", "0.850 0.780 0.640"),
    ("wall_brick", "0.580 0.300 0.220"),
    ("window_glass", "0.150 0.200 0.260"),
)
_TEXTURE_KEY = "facade_texture"


@dataclass(frozen=True)
class SampleCitySettings:
    """Layout of the generated city (lengths in metres).

    The defaults give a central-European block city: 60 m × 48 m blocks of four lots between
    16 m streets, 3 m storeys and window bays, terrain sampled every 20 m.
    """

    #: Block size east-west and north-south; a block holds 2 × 2 lots of 30 m × 24 m.
    block_x_m: float = 60.0
    block_y_m: float = 48.0
    #: Street width between blocks.
    street_m: float = 16.0
    #: Probability that a lot stays empty ("a street grid with gaps").
    gap_probability: float = 0.15
    #: Probability that a block (after the first) is one perimeter block with a courtyard.
    courtyard_probability: float = 0.06
    #: Probability that a house gets a tower as a bldg:BuildingPart (the first one always does).
    part_probability: float = 0.05
    #: Probability that a building is demolished before 2000 (the city changes over time).
    demolition_probability: float = 0.2
    #: Probability that a building's walls carry the facade texture instead of a material.
    texture_probability: float = 0.25
    #: Storey height; also the height of one window row of the facade texture.
    storey_m: float = 3.0
    #: Width of one window bay when facades are split into panels (detail >= 1).
    bay_m: float = 3.0
    #: Size of the facade texture on the wall: 2 bays × 2 storeys (it repeats: wrapMode wrap).
    texture_tile_m: float = 6.0
    #: Terrain grid spacing; the TIN has two triangles per cell.
    terrain_cell_m: float = 20.0
    #: Terrain reaches this far beyond the outermost blocks.
    terrain_margin_m: float = 20.0
    #: Terrain height at the south-west corner; the surface rises gently by up to 10 m (DESIGN
    #: brief: heights around 515–525 m, like Munich).
    terrain_base_m: float = 515.0

    def __post_init__(self) -> None:
        for name in ("block_x_m", "block_y_m", "street_m", "storey_m", "bay_m",
                     "texture_tile_m", "terrain_cell_m"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise UsageError(f"{name} must be a positive number, not {value}")
        if self.block_x_m < 46.0 or self.block_y_m < 36.0:
            # Half a block must hold a 12 m × 10 m house, 3 m margins and a 5 m tower; a block
            # must hold a courtyard ring of two 14 m wings around a courtyard.
            raise UsageError("blocks must be at least 46 m × 36 m")
        for name in ("gap_probability", "courtyard_probability", "part_probability",
                     "demolition_probability", "texture_probability"):
            value = getattr(self, name)
            if not 0.0 <= value <= 1.0:
                raise UsageError(f"{name} must be between 0 and 1, not {value}")


@dataclass(frozen=True)
class CityInfo:
    """What :func:`generate_city` wrote.

    Attributes
    ----------
    path, texture_path : Path
        The GML file and its facade texture (None when written without texture).
    buildings, building_parts : int
        ``bldg:Building`` and ``bldg:BuildingPart`` elements.
    polygons : int
        ``gml:Polygon`` elements (building surfaces).
    interior_rings : int
        ``gml:interior`` rings of those polygons (courtyards, dormer holes, windows).
    terrain_triangles : int
        ``gml:Triangle`` patches of the TIN.
    building_triangles, triangles : int
        Triangles a correct triangulation yields: per polygon, vertices of all its rings − 2 +
        2 × holes; ``triangles`` adds the terrain triangles.
    textured_polygons : int
        Polygons that carry the facade texture (one ``app:textureCoordinates`` each).
    demolished : int
        Buildings with a ``yearOfDemolition``.
    year_range : tuple of int
        Smallest and largest year written (construction and demolition).
    detail : int
        Facade detail level used (0 whole walls, 1 storey × bay panels, 2 panels with windows).
    size_bytes : int
        Size of the GML file.
    """

    path: Path
    texture_path: Path | None
    buildings: int
    building_parts: int
    polygons: int
    interior_rings: int
    terrain_triangles: int
    building_triangles: int
    triangles: int
    textured_polygons: int
    demolished: int
    year_range: tuple[int, int]
    detail: int
    size_bytes: int


# ---------------------------------------------------------------------------------------------
# Plan: the city as a list of small building descriptions (cheap; geometry comes later)
# ---------------------------------------------------------------------------------------------

@dataclass
class _Plan:
    """One building or building part, axis-aligned, before its geometry is made."""

    gml_id: str
    lot: int
    x0: float
    y0: float
    x1: float
    y1: float
    roof: str                      # "flat" | "gabled" | "hipped"
    ridge_along_x: bool
    storeys: int
    roof_height_m: float
    ground_z: float = 0.0
    dormers: int = 0
    step_storeys: int = 0          # > 0: the top storeys are set back (terrace roof)
    step_inset_m: float = 0.0
    courtyard: tuple[float, float, float, float] | None = None
    textured: bool = False
    roof_material: str = "roof_tiles"
    wall_material: str = "wall_plaster"
    year_built: int = 1900
    year_demolished: int | None = None
    part: "_Plan | None" = None

    def eave_z(self, storey_m: float) -> float:
        return self.ground_z + self.storeys * storey_m

    def top_z(self, storey_m: float) -> float:
        top = self.eave_z(storey_m) + (self.roof_height_m if self.roof != "flat" else 0.0)
        if self.part is not None:
            top = max(top, self.part.top_z(storey_m))
        return top


class _Random:
    """Seeded draws through ``random.Random.random()`` only (stable across Python versions)."""

    def __init__(self, seed: int):
        self._rng = random.Random(seed)

    def uniform(self, low: float, high: float) -> float:
        return low + (high - low) * self._rng.random()

    def chance(self, probability: float) -> bool:
        return self._rng.random() < probability

    def integer(self, low: int, high: int) -> int:
        """Integer in [low, high] inclusive."""
        return min(high, low + int(self._rng.random() * (high - low + 1)))

    def decimetres(self, low: float, high: float) -> float:
        """A length in [low, high] on a 0.1 m grid (like surveyed dimensions)."""
        steps = int(round((high - low) * 10.0))
        return low + self.integer(0, steps) / 10.0


def _mm(value: float) -> float:
    """Round to millimetres: coordinates are written, and shared, at this precision."""
    return round(value * 1000.0) / 1000.0


class _Terrain:
    """A regular-grid TIN: height = base + 6 m east-west ramp + 4 m quadratic north rise."""

    def __init__(self, x0: float, y0: float, nx: int, ny: int, cell_m: float, base_m: float):
        self.x0, self.y0, self.nx, self.ny, self.cell_m = x0, y0, nx, ny, cell_m
        # Heights on the grid, rounded to mm so the file and the buildings agree exactly.
        self.z = [[_mm(base_m + 6.0 * i / nx + 4.0 * (j / ny) * (j / ny)) for i in range(nx + 1)]
                  for j in range(ny + 1)]

    @property
    def triangles(self) -> int:
        return 2 * self.nx * self.ny

    def height(self, x: float, y: float) -> float:
        """Height of the TIN at (x, y) (clamped to the grid), by linear interpolation."""
        fx = (x - self.x0) / self.cell_m
        fy = (y - self.y0) / self.cell_m
        i = min(max(int(math.floor(fx)), 0), self.nx - 1)
        j = min(max(int(math.floor(fy)), 0), self.ny - 1)
        u = min(max(fx - i, 0.0), 1.0)
        v = min(max(fy - j, 0.0), 1.0)
        z00, z10 = self.z[j][i], self.z[j][i + 1]
        z01, z11 = self.z[j + 1][i], self.z[j + 1][i + 1]
        # Cells are split along the diagonal (i, j)-(i+1, j+1), as written in _terrain_xml.
        if u >= v:
            return z00 + u * (z10 - z00) + v * (z11 - z10)
        return z00 + v * (z01 - z00) + u * (z11 - z01)


def _grid_columns(n_buildings: int) -> int:
    # About 3.2 buildings per block (4 lots, 15 % gaps, some courtyard blocks): a square city.
    return max(1, int(math.ceil(math.sqrt(n_buildings / 3.2))))


def _plan_city(n_buildings: int, seed: int, texture: bool, s: SampleCitySettings
               ) -> tuple[list[_Plan], _Terrain]:
    """Lay out ``n_buildings`` buildings block by block and the terrain under them."""
    rng = _Random(seed)
    columns = _grid_columns(n_buildings)
    pitch_x = s.block_x_m + s.street_m
    pitch_y = s.block_y_m + s.street_m
    lot_x = s.block_x_m / 2.0
    lot_y = s.block_y_m / 2.0
    plans: list[_Plan] = []
    lot = 0
    block = 0
    need_part = True
    need_texture = texture
    while len(plans) < n_buildings:
        bx0 = (block % columns) * pitch_x
        by0 = (block // columns) * pitch_y
        # The first block is always a courtyard block so every city has one.
        if block == 0 or rng.chance(s.courtyard_probability):
            plans.append(_courtyard_plan(rng, len(plans), lot, bx0, by0, s))
            lot += 4
            block += 1
            continue
        for row in range(2):
            for col in range(2):
                lot += 1
                if len(plans) >= n_buildings:
                    break
                if rng.chance(s.gap_probability) and not need_part:
                    continue
                lx0 = bx0 + col * lot_x
                ly0 = by0 + row * lot_y
                # The first house always has a tower part, later ones now and then.
                with_part = rng.chance(s.part_probability) or need_part
                plan = _house_plan(rng, len(plans), lot, lx0, ly0, lot_x, lot_y, row, with_part,
                                   s)
                # The first house gets the textured walls if texture is on, so every city
                # with texture has at least one textured facade. The draw happens either way:
                # the layout does not depend on ``texture``.
                textured = rng.chance(s.texture_probability)
                plan.textured = texture and (need_texture or textured)
                need_texture = False
                need_part = False
                plans.append(plan)
        block += 1

    # Terrain over all blocks plus a margin, on whole cells.
    rows = (block + columns - 1) // columns
    width_m = (min(block, columns) * pitch_x - s.street_m) + 2.0 * s.terrain_margin_m
    height_m = (rows * pitch_y - s.street_m) + 2.0 * s.terrain_margin_m
    nx = max(1, int(math.ceil(width_m / s.terrain_cell_m)))
    ny = max(1, int(math.ceil(height_m / s.terrain_cell_m)))
    terrain = _Terrain(-s.terrain_margin_m, -s.terrain_margin_m, nx, ny, s.terrain_cell_m,
                       s.terrain_base_m)
    for plan in plans:
        _set_ground(plan, terrain)
    return plans, terrain


def _set_ground(plan: _Plan, terrain: _Terrain) -> None:
    # Lowest terrain point under the footprint: the building never floats above the terrain
    # (on the uphill side the terrain covers the foot of the walls, as in real data).
    corners = [(plan.x0, plan.y0), (plan.x1, plan.y0), (plan.x1, plan.y1), (plan.x0, plan.y1)]
    plan.ground_z = _mm(min(terrain.height(x, y) for x, y in corners))
    if plan.part is not None:
        _set_ground(plan.part, terrain)


def _years(rng: _Random, s: SampleCitySettings, may_demolish: bool) -> tuple[int, int | None]:
    built = rng.integer(1700, 2000)
    demolished = None
    if rng.chance(s.demolition_probability) and may_demolish and built < 2000:
        demolished = rng.integer(max(built + 1, 1750), 2000)
    return built, demolished


def _courtyard_plan(rng: _Random, index: int, lot: int, bx0: float, by0: float,
                    s: SampleCitySettings) -> _Plan:
    """A perimeter block: one flat-roofed ring of houses around a courtyard."""
    depth_m = rng.decimetres(10.0, 14.0)
    x0, y0 = bx0 + 2.0, by0 + 2.0
    x1, y1 = bx0 + s.block_x_m - 2.0, by0 + s.block_y_m - 2.0
    built, demolished = _years(rng, s, may_demolish=True)
    return _Plan(gml_id=f"SC_B{index + 1:06d}", lot=lot + 1, x0=x0, y0=y0, x1=x1, y1=y1,
                 roof="flat", ridge_along_x=True, storeys=rng.integer(4, 6), roof_height_m=0.0,
                 courtyard=(x0 + depth_m, y0 + depth_m, x1 - depth_m, y1 - depth_m),
                 roof_material="roof_flat",
                 wall_material="wall_brick" if rng.chance(0.5) else "wall_plaster",
                 year_built=built, year_demolished=demolished)


def _house_plan(rng: _Random, index: int, lot: int, lx0: float, ly0: float, lot_x: float,
                lot_y: float, row: int, with_part: bool, s: SampleCitySettings) -> _Plan:
    """One house on a lot, near the street side of the lot; optionally with a tower part."""
    margin_m = 3.0  # keeps 6 m between neighbours: no shared walls between buildings
    tower_m = 5.0 if with_part else 0.0
    width_m = rng.decimetres(12.0, lot_x - 2.0 * margin_m - tower_m)
    depth_m = rng.decimetres(10.0, min(18.0, lot_y - 2.0 * margin_m))
    x0 = lx0 + margin_m + rng.decimetres(0.0, lot_x - 2.0 * margin_m - tower_m - width_m)
    # Houses of the south row face the southern street, those of the north row the northern.
    y0 = ly0 + margin_m if row == 0 else ly0 + lot_y - margin_m - depth_m
    x1, y1 = x0 + width_m, y0 + depth_m

    draw = rng.uniform(0.0, 1.0)
    roof = "gabled" if draw < 0.5 else ("hipped" if draw < 0.7 else "flat")
    long_x = width_m >= depth_m
    if roof == "hipped" and abs(width_m - depth_m) < 1.0:
        roof = "gabled"  # a hip roof needs a ridge of positive length
    span_m = depth_m if long_x else width_m
    length_m = width_m if long_x else depth_m
    plan = _Plan(gml_id=f"SC_B{index + 1:06d}", lot=lot, x0=x0, y0=y0, x1=x1, y1=y1, roof=roof,
                 ridge_along_x=long_x, storeys=0, roof_height_m=0.0)
    if roof == "flat":
        plan.storeys = rng.integer(3, 7)
        plan.roof_material = "roof_flat"
        if plan.storeys >= 4 and rng.chance(0.4):
            plan.step_storeys = rng.integer(1, 2)
            plan.step_inset_m = 2.0
    else:
        plan.storeys = rng.integer(2, 5)
        # Roof pitch between 27° and 45°: height = half span × tan(pitch) ∈ [0.5, 1.0] × half.
        plan.roof_height_m = round(span_m / 2.0 * rng.uniform(0.5, 1.0), 1)
        plan.roof_material = "roof_tiles" if rng.chance(0.7) else "roof_slate"
        if roof == "gabled" and length_m >= 9.0 and plan.roof_height_m >= 2.5:
            plan.dormers = rng.integer(0, 3)
    plan.wall_material = "wall_brick" if rng.chance(0.3) else "wall_plaster"
    plan.year_built, plan.year_demolished = _years(rng, s, may_demolish=not with_part)
    if with_part:
        # A tower added later at the east gable, standing against the main body's wall.
        cy = y0 + depth_m / 2.0
        part_built = rng.integer(plan.year_built, 2000)
        plan.part = _Plan(gml_id=f"{plan.gml_id}_part1", lot=lot, x0=x1, y0=_mm(cy - 2.5),
                          x1=x1 + tower_m, y1=_mm(cy + 2.5), roof="flat", ridge_along_x=True,
                          storeys=plan.storeys + rng.integer(2, 4), roof_height_m=0.0,
                          roof_material="roof_slate", wall_material="wall_brick",
                          year_built=part_built)
    return plan


# ---------------------------------------------------------------------------------------------
# Geometry: polygons of one building (float64, then rounded to mm on output)
# ---------------------------------------------------------------------------------------------

Point = tuple[float, float, float]


@dataclass
class _Poly:
    """A planar polygon: exterior CCW seen from outside (open: no repeated point)."""

    exterior: list[Point]
    interiors: list[list[Point]] = field(default_factory=list)
    material: str = ""
    tex: list[tuple[float, float]] | None = None   # per exterior point, for the facade texture

    @property
    def triangles(self) -> int:
        points = len(self.exterior) + sum(len(r) for r in self.interiors)
        return points - 2 + 2 * len(self.interiors)


@dataclass
class _Surface:
    """A thematic surface: ``kind`` is RoofSurface, WallSurface or GroundSurface."""

    kind: str
    polys: list[_Poly]


def _lerp(p: tuple[float, float], q: tuple[float, float], t: float) -> tuple[float, float]:
    # (1 - t) p + t q gives p and q exactly at t = 0 and 1: shared corners stay identical.
    return (p[0] * (1.0 - t) + q[0] * t, p[1] * (1.0 - t) + q[1] * t)


def _wall(p: tuple[float, float], q: tuple[float, float], bottom_z: float, top: list[Point],
          ground_z: float, material: str, detail: int, textured: bool,
          s: SampleCitySettings) -> list[_Poly]:
    """Polygons of the wall under footprint edge p → q (building to the left of p → q).

    ``top`` is the upper outline from q back to p (two points at the eave, or eave–ridge–eave
    for a gable). Seen from outside, p is bottom left: the ring p, q, top is CCW from outside.
    """
    if textured or detail == 0:
        ring = [(p[0], p[1], bottom_z), (q[0], q[1], bottom_z)] + top
        tex = None
        if textured:
            # u along the wall, v up from the building's ground; one tile = texture_tile_m.
            # Walls are axis-aligned, so |dx| + |dy| is the distance along the wall.
            tex = [((abs(x - p[0]) + abs(y - p[1])) / s.texture_tile_m,
                    (z - ground_z) / s.texture_tile_m) for x, y, z in ring]
        return [_Poly(ring, material=_TEXTURE_KEY if textured else material, tex=tex)]

    # Split the rectangle below the eave into storey × bay panels (detail 1) with a window hole
    # and a window polygon each (detail 2); the gable above the eave stays one polygon.
    eave_z = top[0][2]
    length_m = abs(q[0] - p[0]) + abs(q[1] - p[1])
    bays = max(1, int(round(length_m / s.bay_m)))
    rows = max(1, int(round((eave_z - bottom_z) / s.storey_m)))
    xy = [p] + [_lerp(p, q, k / bays) for k in range(1, bays)] + [q]
    zs = [bottom_z] + [bottom_z + (eave_z - bottom_z) * j / rows for j in range(1, rows)] + [eave_z]
    polys = []
    for j in range(rows):
        za, zb = zs[j], zs[j + 1]
        for k in range(bays):
            a, b = xy[k], xy[k + 1]
            panel = _Poly([(a[0], a[1], za), (b[0], b[1], za), (b[0], b[1], zb),
                           (a[0], a[1], zb)], material=material)
            panel_w = length_m / bays
            if detail >= 2 and panel_w >= 1.5 and zb - za >= 2.2:
                # A window of at most 1.4 m × 1.5 m, sill 0.9 m above the storey floor.
                half_w = min(1.4, 0.5 * panel_w) / 2.0 / panel_w
                wa = _lerp(a, b, 0.5 - half_w)
                wb = _lerp(a, b, 0.5 + half_w)
                w_lo = za + 0.9
                w_hi = w_lo + min(1.5, 0.55 * (zb - za))
                # Hole: clockwise seen from outside; the window itself: counter-clockwise.
                panel.interiors.append([(wa[0], wa[1], w_lo), (wa[0], wa[1], w_hi),
                                        (wb[0], wb[1], w_hi), (wb[0], wb[1], w_lo)])
                polys.append(panel)
                polys.append(_Poly([(wa[0], wa[1], w_lo), (wb[0], wb[1], w_lo),
                                    (wb[0], wb[1], w_hi), (wa[0], wa[1], w_hi)],
                                   material="window_glass"))
            else:
                polys.append(panel)
    if len(top) > 2:
        polys.append(_Poly([(p[0], p[1], eave_z), (q[0], q[1], eave_z)] + top[1:-1],
                           material=material))
    return polys


def _rect(x0: float, y0: float, x1: float, y1: float) -> list[tuple[float, float]]:
    """Axis-aligned rectangle, counter-clockwise seen from above."""
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def _at(ring: Sequence[tuple[float, float]], z: float) -> list[Point]:
    return [(x, y, z) for x, y in ring]


def _box_walls(ring: list[tuple[float, float]], bottom_z: float, top_z: float, plan: _Plan,
               detail: int, s: SampleCitySettings) -> list[_Surface]:
    """One WallSurface per edge of ``ring`` (CCW: outward walls; CW: walls facing a hole)."""
    surfaces = []
    for i in range(len(ring)):
        p, q = ring[i], ring[(i + 1) % len(ring)]
        top = [(q[0], q[1], top_z), (p[0], p[1], top_z)]
        surfaces.append(_Surface("WallSurface", _wall(p, q, bottom_z, top, plan.ground_z,
                                                      plan.wall_material, detail,
                                                      plan.textured, s)))
    return surfaces


def _flat_building(plan: _Plan, detail: int, s: SampleCitySettings) -> list[_Surface]:
    zg = plan.ground_z
    top_z = plan.eave_z(s.storey_m)
    outer = _rect(plan.x0, plan.y0, plan.x1, plan.y1)
    surfaces: list[_Surface] = []
    if plan.courtyard is not None:
        inner_ccw = _rect(*plan.courtyard)
        inner_cw = inner_ccw[::-1]
        surfaces.append(_Surface("RoofSurface", [_Poly(_at(outer, top_z), [_at(inner_cw, top_z)],
                                                       material=plan.roof_material)]))
        surfaces += _box_walls(outer, zg, top_z, plan, detail, s)
        surfaces += _box_walls(inner_cw, zg, top_z, plan, detail, s)
        surfaces.append(_Surface("GroundSurface", [_Poly(_at(outer[::-1], zg),
                                                         [_at(inner_ccw, zg)])]))
        return surfaces
    if plan.step_storeys > 0:
        # Lower box with a terrace roof around the set-back upper box.
        step_z = zg + (plan.storeys - plan.step_storeys) * s.storey_m
        d = plan.step_inset_m
        upper = _rect(plan.x0 + d, plan.y0 + d, plan.x1 - d, plan.y1 - d)
        surfaces.append(_Surface("RoofSurface", [_Poly(_at(outer, step_z),
                                                       [_at(upper[::-1], step_z)],
                                                       material=plan.roof_material)]))
        surfaces.append(_Surface("RoofSurface", [_Poly(_at(upper, top_z),
                                                       material=plan.roof_material)]))
        surfaces += _box_walls(outer, zg, step_z, plan, detail, s)
        surfaces += _box_walls(upper, step_z, top_z, plan, detail, s)
    else:
        surfaces.append(_Surface("RoofSurface", [_Poly(_at(outer, top_z),
                                                       material=plan.roof_material)]))
        surfaces += _box_walls(outer, zg, top_z, plan, detail, s)
    surfaces.append(_Surface("GroundSurface", [_Poly(_at(outer[::-1], zg))]))
    return surfaces


def _pitched_building(plan: _Plan, detail: int, s: SampleCitySettings) -> list[_Surface]:
    """Gabled or hipped roof, built in a local frame: u along the ridge, v across it."""
    zg = plan.ground_z
    ze = plan.eave_z(s.storey_m)
    zr = ze + plan.roof_height_m
    if plan.ridge_along_x:
        lu, lv = plan.x1 - plan.x0, plan.y1 - plan.y0

        def world(u: float, v: float) -> tuple[float, float]:
            return (plan.x0 + u, plan.y0 + v)
    else:
        lu, lv = plan.y1 - plan.y0, plan.x1 - plan.x0

        def world(u: float, v: float) -> tuple[float, float]:
            # A quarter turn (u, v) → (−v, u): a rotation keeps counter-clockwise rings so.
            return (plan.x1 - v, plan.y0 + u)

    def pt(u: float, v: float, z: float) -> Point:
        x, y = world(u, v)
        return (x, y, z)

    vm = lv / 2.0
    c0, c1, c2, c3 = world(0.0, 0.0), world(lu, 0.0), world(lu, lv), world(0.0, lv)
    roof_mat = plan.roof_material
    surfaces: list[_Surface] = []
    if plan.roof == "gabled":
        front = _Poly([pt(0.0, 0.0, ze), pt(lu, 0.0, ze), pt(lu, vm, zr), pt(0.0, vm, zr)],
                      material=roof_mat)
        back = _Poly([pt(lu, lv, ze), pt(0.0, lv, ze), pt(0.0, vm, zr), pt(lu, vm, zr)],
                     material=roof_mat)
        surfaces.append(_Surface("RoofSurface", [front]))
        surfaces.append(_Surface("RoofSurface", [back]))
        surfaces += _dormers(plan, front, pt, lu, vm, ze, zr)
        tops = [[pt(lu, 0.0, ze), pt(0.0, 0.0, ze)],
                [pt(lu, lv, ze), pt(lu, vm, zr), pt(lu, 0.0, ze)],
                [pt(0.0, lv, ze), pt(lu, lv, ze)],
                [pt(0.0, 0.0, ze), pt(0.0, vm, zr), pt(0.0, lv, ze)]]
    else:
        h = vm  # hips at 45° in plan: the ridge ends half a span from the gable walls
        surfaces.append(_Surface("RoofSurface", [_Poly(
            [pt(0.0, 0.0, ze), pt(lu, 0.0, ze), pt(lu - h, vm, zr), pt(h, vm, zr)],
            material=roof_mat)]))
        surfaces.append(_Surface("RoofSurface", [_Poly(
            [pt(lu, lv, ze), pt(0.0, lv, ze), pt(h, vm, zr), pt(lu - h, vm, zr)],
            material=roof_mat)]))
        surfaces.append(_Surface("RoofSurface", [_Poly(
            [pt(lu, 0.0, ze), pt(lu, lv, ze), pt(lu - h, vm, zr)], material=roof_mat)]))
        surfaces.append(_Surface("RoofSurface", [_Poly(
            [pt(0.0, lv, ze), pt(0.0, 0.0, ze), pt(h, vm, zr)], material=roof_mat)]))
        tops = [[pt(lu, 0.0, ze), pt(0.0, 0.0, ze)], [pt(lu, lv, ze), pt(lu, 0.0, ze)],
                [pt(0.0, lv, ze), pt(lu, lv, ze)], [pt(0.0, 0.0, ze), pt(0.0, lv, ze)]]
    corners = [c0, c1, c2, c3]
    for i in range(4):
        surfaces.append(_Surface("WallSurface", _wall(
            corners[i], corners[(i + 1) % 4], zg, tops[i], zg, plan.wall_material, detail,
            plan.textured, s)))
    surfaces.append(_Surface("GroundSurface", [_Poly(_at(corners[::-1], zg))]))
    return surfaces


def _dormers(plan: _Plan, front: _Poly, pt: Callable[[float, float, float], Point], lu: float,
             vm: float, ze: float, zr: float) -> list[_Surface]:
    """Flat-roofed dormers on the front slope: a hole in the slope, a front wall, two cheeks."""
    surfaces = []
    width_m = 2.0

    def slope_z(v: float) -> float:
        return ze + (zr - ze) * v / vm

    for i in range(plan.dormers):
        # From about 20 % to 70 % of the way up the slope, staggered by 2 % per dormer: holes
        # whose corners line up make ear-clipping triangulators merge collinear points and
        # return fewer triangles than vertices − 2 + 2 × holes.
        v1, v2 = (0.2 + 0.02 * i) * vm, (0.7 - 0.02 * i) * vm
        z1, zd = slope_z(v1), slope_z(v2)
        centre = lu * (i + 0.5) / plan.dormers
        a, b = centre - width_m / 2.0, centre + width_m / 2.0
        # Slope hole, clockwise seen from above (the slope's exterior is counter-clockwise).
        front.interiors.append([pt(a, v1, z1), pt(a, v2, zd), pt(b, v2, zd), pt(b, v1, z1)])
        walls = [
            _Poly([pt(a, v1, z1), pt(b, v1, z1), pt(b, v1, zd), pt(a, v1, zd)],
                  material=plan.wall_material),
            _Poly([pt(b, v1, z1), pt(b, v2, zd), pt(b, v1, zd)], material=plan.wall_material),
            _Poly([pt(a, v1, z1), pt(a, v1, zd), pt(a, v2, zd)], material=plan.wall_material),
        ]
        roof = _Poly([pt(a, v1, zd), pt(b, v1, zd), pt(b, v2, zd), pt(a, v2, zd)],
                     material=plan.roof_material)
        surfaces.append(_Surface("WallSurface", walls))
        surfaces.append(_Surface("RoofSurface", [roof]))
    return surfaces


def _building_surfaces(plan: _Plan, detail: int, s: SampleCitySettings) -> list[_Surface]:
    if plan.roof == "flat":
        return _flat_building(plan, detail, s)
    return _pitched_building(plan, detail, s)


# ---------------------------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------------------------

def _fmt(value: float) -> str:
    text = f"{value:.3f}"
    return "0.000" if text == "-0.000" else text


def _pos_list(ring: list[Point]) -> str:
    closed = ring + ring[:1]
    return " ".join(f"{_fmt(x)} {_fmt(y)} {_fmt(z)}" for x, y, z in closed)


_IND = "  "  # two spaces per level, like the 3DCityDB exporter that wrote the TUM file


def _ring_xml(tag: str, ring: list[Point], depth: int, ring_id: str | None) -> str:
    i = _IND * depth
    rid = f' gml:id="{ring_id}"' if ring_id else ""
    return (f"{i}<gml:{tag}>\n{i}{_IND}<gml:LinearRing{rid}>\n"
            f'{i}{_IND * 2}<gml:posList srsDimension="3">{_pos_list(ring)}</gml:posList>\n'
            f"{i}{_IND}</gml:LinearRing>\n{i}</gml:{tag}>\n")


def _envelope_xml(lo: Point, hi: Point, depth: int) -> str:
    i = _IND * depth
    return (f"{i}<gml:boundedBy>\n"
            f'{i}{_IND}<gml:Envelope srsName="{SRS_NAME}" srsDimension="3">\n'
            f"{i}{_IND * 2}<gml:lowerCorner>{_fmt(lo[0])} {_fmt(lo[1])} {_fmt(lo[2])}"
            f"</gml:lowerCorner>\n"
            f"{i}{_IND * 2}<gml:upperCorner>{_fmt(hi[0])} {_fmt(hi[1])} {_fmt(hi[2])}"
            f"</gml:upperCorner>\n"
            f"{i}{_IND}</gml:Envelope>\n{i}</gml:boundedBy>\n")


@dataclass
class _Counts:
    buildings: int = 0
    parts: int = 0
    polygons: int = 0
    interiors: int = 0
    triangles: int = 0
    textured: int = 0
    demolished: int = 0
    year_min: int = 10_000
    year_max: int = -10_000


class _AppearanceSink:
    """Collects appearance targets in temporary files while buildings stream out."""

    def __init__(self, folder: Path, texture: bool):
        keys = [m for m, _ in _MATERIALS] + ([_TEXTURE_KEY] if texture else [])
        self.files = {k: tempfile.TemporaryFile("w+", encoding="utf-8", dir=folder)
                      for k in keys}
        self.used = {k: False for k in keys}

    def add(self, material: str, poly_id: str, poly: _Poly, ring_id: str | None) -> None:
        if material not in self.files:
            return
        self.used[material] = True
        if material == _TEXTURE_KEY:
            i = _IND * 5
            coords = poly.tex + poly.tex[:1]
            uv = " ".join(f"{u:.4f} {v:.4f}" for u, v in coords)
            self.files[material].write(
                f'{i}<app:target uri="#{poly_id}">\n{i}{_IND}<app:TexCoordList>\n'
                f'{i}{_IND * 2}<app:textureCoordinates ring="#{ring_id}">{uv}'
                f"</app:textureCoordinates>\n{i}{_IND}</app:TexCoordList>\n{i}</app:target>\n")
        else:
            self.files[material].write(f"{_IND * 5}<app:target>#{poly_id}</app:target>\n")

    def write(self, out, texture_uri: str | None) -> None:
        i = _IND * 3
        out.write(f"{_IND}<app:appearanceMember>\n"
                  f'{_IND * 2}<app:Appearance gml:id="SC_appearance">\n'
                  f"{i}<app:theme>rgbTexture</app:theme>\n")
        for key, colour in _MATERIALS:
            if not self.used[key]:
                continue
            out.write(f"{i}<app:surfaceDataMember>\n"
                      f'{i}{_IND}<app:X3DMaterial gml:id="SC_mat_{key}">\n'
                      f"{i}{_IND * 2}<app:diffuseColor>{colour}</app:diffuseColor>\n")
            self._copy(key, out)
            out.write(f"{i}{_IND}</app:X3DMaterial>\n{i}</app:surfaceDataMember>\n")
        if texture_uri is not None and self.used.get(_TEXTURE_KEY):
            out.write(f"{i}<app:surfaceDataMember>\n"
                      f'{i}{_IND}<app:ParameterizedTexture gml:id="SC_tex_facade">\n'
                      f"{i}{_IND * 2}<app:imageURI>{texture_uri}</app:imageURI>\n"
                      f"{i}{_IND * 2}<app:mimeType>image/png</app:mimeType>\n"
                      f"{i}{_IND * 2}<app:wrapMode>wrap</app:wrapMode>\n")
            self._copy(_TEXTURE_KEY, out)
            out.write(f"{i}{_IND}</app:ParameterizedTexture>\n{i}</app:surfaceDataMember>\n")
        out.write(f"{_IND * 2}</app:Appearance>\n{_IND}</app:appearanceMember>\n")

    def _copy(self, key: str, out) -> None:
        handle = self.files[key]
        handle.seek(0)
        shutil.copyfileobj(handle, out, 1 << 20)

    def close(self) -> None:
        for handle in self.files.values():
            handle.close()


def _object_xml(plan: _Plan, tag: str, detail: int, s: SampleCitySettings, counts: _Counts,
                sink: _AppearanceSink, depth: int) -> tuple[list[str], Point, Point]:
    """XML of one Building or BuildingPart (with its parts), its envelope corners."""
    surfaces = _building_surfaces(plan, detail, s)
    ids: list[str] = []
    body: list[str] = []
    n_poly = 0
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    i = _IND * depth
    for n_surf, surface in enumerate(surfaces, start=1):
        body.append(f"{i}{_IND}<bldg:boundedBy>\n"
                    f'{i}{_IND * 2}<bldg:{surface.kind} gml:id="{plan.gml_id}_s{n_surf}">\n'
                    f"{i}{_IND * 3}<bldg:lod2MultiSurface>\n{i}{_IND * 4}<gml:MultiSurface>\n")
        for poly in surface.polys:
            n_poly += 1
            pid = f"{plan.gml_id}_p{n_poly}"
            rid = f"{pid}_r0" if poly.tex is not None else None
            ids.append(pid)
            d = depth + 5
            body.append(f"{_IND * d}<gml:surfaceMember>\n"
                        f'{_IND * (d + 1)}<gml:Polygon gml:id="{pid}">\n')
            body.append(_ring_xml("exterior", poly.exterior, d + 2, rid))
            for hole in poly.interiors:
                body.append(_ring_xml("interior", hole, d + 2, None))
            body.append(f"{_IND * (d + 1)}</gml:Polygon>\n{_IND * d}</gml:surfaceMember>\n")
            for ring in [poly.exterior] + poly.interiors:
                for point in ring:
                    for k in range(3):
                        lo[k] = min(lo[k], point[k])
                        hi[k] = max(hi[k], point[k])
            counts.polygons += 1
            counts.interiors += len(poly.interiors)
            counts.triangles += poly.triangles
            counts.textured += poly.tex is not None
            sink.add(poly.material, pid, poly, rid)
        body.append(f"{i}{_IND * 4}</gml:MultiSurface>\n{i}{_IND * 3}</bldg:lod2MultiSurface>\n"
                    f"{i}{_IND * 2}</bldg:{surface.kind}>\n{i}{_IND}</bldg:boundedBy>\n")

    part_xml: list[str] = []
    if plan.part is not None:
        part_body, plo, phi = _object_xml(plan.part, "BuildingPart", detail, s, counts, sink,
                                          depth + 2)
        counts.parts += 1
        lo = [min(a, b) for a, b in zip(lo, plo)]
        hi = [max(a, b) for a, b in zip(hi, phi)]
        part_xml = [f"{i}{_IND}<bldg:consistsOfBuildingPart>\n"] + part_body + \
                   [f"{i}{_IND}</bldg:consistsOfBuildingPart>\n"]

    years = [plan.year_built] + ([plan.year_demolished] if plan.year_demolished else [])
    counts.year_min = min(counts.year_min, *years)
    counts.year_max = max(counts.year_max, *years)
    counts.demolished += plan.year_demolished is not None
    # Height of this object alone (a taller tower part has its own measuredHeight).
    height_m = plan.eave_z(s.storey_m) + plan.roof_height_m - plan.ground_z

    j = i + _IND
    head = [f'{i}<bldg:{tag} gml:id="{plan.gml_id}">\n',
            f"{j}<gml:name>{plan.gml_id}</gml:name>\n",
            _envelope_xml(tuple(lo), tuple(hi), depth + 1),
            f'{j}<gen:intAttribute name="Parzelle">\n{j}{_IND}<gen:value>{plan.lot}</gen:value>\n'
            f"{j}</gen:intAttribute>\n",
            f'{j}<gen:doubleAttribute name="HoeheGrund">\n{j}{_IND}<gen:value>'
            f"{_fmt(plan.ground_z)}</gen:value>\n{j}</gen:doubleAttribute>\n",
            f"{j}<bldg:function>{'1010' if tag == 'BuildingPart' else '1000'}</bldg:function>\n",
            f"{j}<bldg:yearOfConstruction>{plan.year_built}</bldg:yearOfConstruction>\n"]
    if plan.year_demolished is not None:
        head.append(f"{j}<bldg:yearOfDemolition>{plan.year_demolished}</bldg:yearOfDemolition>\n")
    head += [f"{j}<bldg:roofType>{_ROOF_TYPE_CODE[plan.roof]}</bldg:roofType>\n",
             f'{j}<bldg:measuredHeight uom="urn:adv:uom:m">{_fmt(height_m)}'
             f"</bldg:measuredHeight>\n",
             f"{j}<bldg:storeysAboveGround>{plan.storeys}</bldg:storeysAboveGround>\n",
             f"{j}<bldg:lod2Solid>\n{j}{_IND}<gml:Solid gml:id=\"{plan.gml_id}_solid\">\n"
             f"{j}{_IND * 2}<gml:exterior>\n"
             f'{j}{_IND * 3}<gml:CompositeSurface gml:id="{plan.gml_id}_cs">\n']
    k = j + _IND * 4
    head += [f'{k}<gml:surfaceMember xlink:href="#{pid}"/>\n' for pid in ids]
    head.append(f"{j}{_IND * 3}</gml:CompositeSurface>\n{j}{_IND * 2}</gml:exterior>\n"
                f"{j}{_IND}</gml:Solid>\n{j}</bldg:lod2Solid>\n")
    return head + body + part_xml + [f"{i}</bldg:{tag}>\n"], tuple(lo), tuple(hi)


def _terrain_xml(out, terrain: _Terrain, ox: float, oy: float) -> None:
    """Write the TIN: two triangles per cell, counter-clockwise seen from above (up normals)."""
    d = _IND * 8
    out.write(f"{_IND}<cityObjectMember>\n"
              f'{_IND * 2}<dem:ReliefFeature gml:id="SC_DEM">\n'
              f"{_IND * 3}<gml:name>Terrain</gml:name>\n"
              f"{_IND * 3}<dem:lod>2</dem:lod>\n{_IND * 3}<dem:reliefComponent>\n"
              f'{_IND * 4}<dem:TINRelief gml:id="SC_DEM_tin">\n{_IND * 5}<dem:lod>2</dem:lod>\n'
              f'{_IND * 5}<dem:tin>\n{_IND * 6}<gml:TriangulatedSurface gml:id="SC_DEM_surface">\n'
              f"{_IND * 7}<gml:trianglePatches>\n")
    c = terrain.cell_m

    def p(i: int, j: int) -> Point:
        return (ox + terrain.x0 + i * c, oy + terrain.y0 + j * c, terrain.z[j][i])

    for j in range(terrain.ny):
        chunk = []
        for i in range(terrain.nx):
            for tri in ((p(i, j), p(i + 1, j), p(i + 1, j + 1)),
                        (p(i, j), p(i + 1, j + 1), p(i, j + 1))):
                chunk.append(f"{d}<gml:Triangle>\n{_ring_xml('exterior', list(tri), 9, None)}"
                             f"{d}</gml:Triangle>\n")
        out.write("".join(chunk))
    out.write(f"{_IND * 7}</gml:trianglePatches>\n{_IND * 6}</gml:TriangulatedSurface>\n"
              f"{_IND * 5}</dem:tin>\n{_IND * 4}</dem:TINRelief>\n"
              f"{_IND * 3}</dem:reliefComponent>\n{_IND * 2}</dem:ReliefFeature>\n"
              f"{_IND}</cityObjectMember>\n")


def _shifted(plan: _Plan, ox: float, oy: float) -> None:
    """Move a plan from city-local to world coordinates (after terrain heights are set)."""
    plan.x0, plan.y0, plan.x1, plan.y1 = (_mm(plan.x0 + ox), _mm(plan.y0 + oy),
                                          _mm(plan.x1 + ox), _mm(plan.y1 + oy))
    if plan.courtyard is not None:
        cx0, cy0, cx1, cy1 = plan.courtyard
        plan.courtyard = (_mm(cx0 + ox), _mm(cy0 + oy), _mm(cx1 + ox), _mm(cy1 + oy))
    if plan.part is not None:
        _shifted(plan.part, ox, oy)


def facade_texture(size_px: int = 256) -> np.ndarray:
    """The procedural facade texture: 2 × 2 windows on plaster, for 2 bays × 2 storeys.

    Parameters
    ----------
    size_px : int
        Width and height in pixels (a multiple of 8).

    Returns
    -------
    numpy.ndarray, shape (size_px, size_px, 3), uint8
        sRGB pixels, row 0 at the top (texture coordinate v = 1). Integer arithmetic only, so
        the picture is identical everywhere.
    """
    if size_px < 32 or size_px % 8:
        raise UsageError(f"texture size must be a multiple of 8 and at least 32, not {size_px}")
    n = size_px
    row = np.arange(n, dtype=np.int64)[:, None]
    col = np.arange(n, dtype=np.int64)[None, :]
    # Plaster: warm off-white with a hashed grain of ±6 levels (integer hash: no float noise).
    grain = ((row * 73856093) ^ (col * 19349663)) % 13 - 6
    img = np.empty((n, n, 3), np.int64)
    img[..., 0] = 226 + grain
    img[..., 1] = 212 + grain
    img[..., 2] = 184 + grain
    cell = n // 2
    r, c = row % cell, col % cell
    # Window in each cell (one bay × one storey): frame, glass with a darker lower half, a
    # mullion and a transom, and a stone sill under it. Fractions of the cell, in eighths/64ths.
    left, right = cell * 18 // 64, cell * 46 // 64
    top, bottom = cell * 14 // 64, cell * 50 // 64
    frame = max(1, cell // 32)
    bar = frame // 2 + 1                                   # half width of mullion and transom
    transom_row = top + (bottom - top) * 2 // 5
    window = (r >= top) & (r < bottom) & (c >= left) & (c < right)
    glass = (r >= top + frame) & (r < bottom - frame) & (c >= left + frame) & (c < right - frame)
    bars = glass & ((np.abs(2 * c - (left + right)) < 2 * bar) | (np.abs(r - transom_row) < bar))
    frame_px = (window & ~glass) | bars
    glass_px = glass & ~bars
    sill = (r >= bottom) & (r < bottom + max(2, cell // 24)) & (c >= left - frame) & \
        (c < right + frame)
    shade = np.broadcast_to((r - top) * 40 // max(1, bottom - top), (n, n))  # darker below
    for k, (frame_level, glass_level, sill_level) in enumerate(
            ((244, 70, 190), (242, 92, 184), (236, 112, 172))):
        channel = img[..., k]
        channel[frame_px] = frame_level
        channel[glass_px] = glass_level - shade[glass_px]
        channel[sill] = sill_level
    return np.clip(img, 0, 255).astype(np.uint8)


def _validate(n_buildings: int, seed: int, target_triangles: int | None,
              detail: int | None) -> None:
    if isinstance(n_buildings, bool) or not isinstance(n_buildings, int) or n_buildings < 1:
        raise UsageError(f"n_buildings must be a positive integer, not {n_buildings!r}")
    if n_buildings > 1_000_000:
        raise UsageError(f"n_buildings must be at most 1000000, not {n_buildings}")
    if isinstance(seed, bool) or not isinstance(seed, int):
        raise UsageError(f"seed must be an integer, not {seed!r}")
    if target_triangles is not None and (
            isinstance(target_triangles, bool) or not isinstance(target_triangles, int)
            or not 100 <= target_triangles <= 100_000_000):
        raise UsageError("target_triangles must be an integer between 100 and 100000000, "
                         f"not {target_triangles!r}")
    if detail is not None and detail not in (0, 1, 2):
        raise UsageError(f"detail must be 0, 1 or 2, not {detail!r}")


def _count_triangles(plans: list[_Plan], detail: int, s: SampleCitySettings) -> int:
    total = 0
    for plan in plans:
        while plan is not None:
            total += sum(p.triangles for sf in _building_surfaces(plan, detail, s)
                         for p in sf.polys)
            plan = plan.part
    return total


def _choose_size(target: int, seed: int, texture: bool, terrain: bool, detail: int | None,
                 s: SampleCitySettings) -> tuple[int, int]:
    """(n_buildings, detail) whose city has about ``target`` triangles."""
    if detail is None:
        # Whole walls for small cities; panels, then windows, as the target grows, so large
        # cities get more detailed buildings as well as more of them.
        detail = 0 if target < 20_000 else (1 if target < 150_000 else 2)
    n = 40
    # Fixed-point iteration on the measured triangles per building (three rounds reach ±2 %).
    for _ in range(3):
        plans, tin = _plan_city(n, seed, texture, s)
        per_building = _count_triangles(plans, detail, s) / n
        terrain_tris = tin.triangles if terrain else 0
        n = max(1, int(round((target - terrain_tris) / per_building)))
    return n, detail


def generate_city(path: str | os.PathLike, *, n_buildings: int = 40, seed: int = 7,
                  origin_xy_m: tuple[float, float] = (690_000.0, 5_336_000.0),
                  texture: bool = True, terrain: bool = True,
                  target_triangles: int | None = None, detail: int | None = None,
                  settings: SampleCitySettings | None = None,
                  output_format: str = "citygml") -> CityInfo:
    """Write a synthetic CityGML 2.0 (or CityJSON 2.0) city, deterministically from ``seed``.

    Parameters
    ----------
    path : str or path-like
        The ``.gml`` file to write (replaced atomically). The facade texture is written next to
        it as ``<stem>_facade.png``.
    n_buildings : int
        Number of ``bldg:Building`` elements (ignored when ``target_triangles`` is given).
    seed : int
        Seed of the layout; the same arguments give the same bytes on every platform.
    origin_xy_m : (float, float)
        South-west corner of the first block, EPSG:25832 metres (default: Munich, tile 690_5336).
    texture, terrain : bool
        Write the facade texture (and texture some facades) / the TIN terrain.
    target_triangles : int, optional
        Choose ``n_buildings`` and ``detail`` so the city has about this many triangles
        (within a few per cent).
    detail : {0, 1, 2}, optional
        Facade detail: 0 one polygon per wall, 1 storey × bay panels, 2 panels with window
        holes and window polygons. Default 0, or chosen from ``target_triangles``.
    settings : SampleCitySettings, optional
        Layout parameters.
    output_format : {"citygml", "cityjson", "cityjsonseq"}
        The same city as CityGML 2.0, as one CityJSON 2.0 document, or as CityJSONSeq (a
        header line, then one CityJSONFeature line per building with its part).

    Returns
    -------
    CityInfo
        Counts of what was written.

    Raises
    ------
    UsageError
        Arguments out of range.
    SampleGenError
        The file cannot be written.
    """
    _validate(n_buildings, seed, target_triangles, detail)
    if output_format not in OUTPUT_FORMATS:
        raise UsageError(f"output_format must be one of {', '.join(OUTPUT_FORMATS)}, "
                         f"not {output_format!r}")
    s = settings or SampleCitySettings()
    ox, oy = (float(v) for v in origin_xy_m)
    if not (math.isfinite(ox) and math.isfinite(oy)):
        raise UsageError(f"origin_xy_m must be finite, not {origin_xy_m!r}")
    if target_triangles is not None:
        n_buildings, detail = _choose_size(target_triangles, seed, texture, terrain, detail, s)
    detail = 0 if detail is None else detail

    path = Path(path)
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise SampleGenError(f"cannot write sample city: folder {folder} does not exist",
                             path=str(path))
    plans, tin = _plan_city(n_buildings, seed, texture, s)
    for plan in plans:
        _shifted(plan, ox, oy)

    texture_path = None
    texture_uri = None
    if texture:
        from cityshade.errors import ImageIOError
        from cityshade.imageio import write_image
        texture_path = path.with_name(f"{path.stem}_facade.png")
        texture_uri = texture_path.name
        try:
            write_image(texture_path, facade_texture(256))
        except ImageIOError as exc:
            raise SampleGenError(f"cannot write the facade texture: {exc.message}",
                                 path=str(texture_path)) from None

    counts = _Counts()
    sink = _AppearanceSink(folder, texture)
    try:
        with atomic_write(path, newline="\n", buffering=1 << 20, error=SampleGenError,
                          what="sample city") as out:
            if output_format == "citygml":
                _write_city(out, plans, tin, terrain, ox, oy, detail, seed, s, counts, sink,
                            texture_uri)
            else:
                _write_cityjson(out, plans, tin, terrain, ox, oy, detail, seed, s, counts,
                                texture_uri, seq=output_format == "cityjsonseq")
    finally:
        sink.close()

    terrain_tris = tin.triangles if terrain else 0
    return CityInfo(path=path, texture_path=texture_path, buildings=counts.buildings,
                    building_parts=counts.parts, polygons=counts.polygons,
                    interior_rings=counts.interiors, terrain_triangles=terrain_tris,
                    building_triangles=counts.triangles,
                    triangles=counts.triangles + terrain_tris,
                    textured_polygons=counts.textured, demolished=counts.demolished,
                    year_range=(counts.year_min, counts.year_max), detail=detail,
                    size_bytes=path.stat().st_size)


def _write_city(out, plans: list[_Plan], tin: _Terrain, terrain: bool, ox: float, oy: float,
                detail: int, seed: int, s: SampleCitySettings, counts: _Counts,
                sink: _AppearanceSink, texture_uri: str | None) -> None:
    # City envelope: the terrain (or the buildings) in x/y, lowest ground to highest roof in z.
    if terrain:
        lo_xy = (ox + tin.x0, oy + tin.y0)
        hi_xy = (ox + tin.x0 + tin.nx * tin.cell_m, oy + tin.y0 + tin.ny * tin.cell_m)
        z_lo = min(min(row) for row in tin.z)
    else:
        lo_xy = (min(p.x0 for p in plans), min(p.y0 for p in plans))
        hi_xy = (max(p.part.x1 if p.part else p.x1 for p in plans), max(p.y1 for p in plans))
        z_lo = min(p.ground_z for p in plans)
    z_hi = max(p.top_z(s.storey_m) for p in plans)
    out.write('<?xml version="1.0" encoding="UTF-8"?>\n'
              f"<!-- Synthetic city written by cityshade.samplegen (seed {seed}, "
              f"{len(plans)} buildings, detail {detail}). Not real data. -->\n"
              f'<CityModel xmlns="{NS_CORE}" xmlns:gml="{NS_GML}" xmlns:xlink="{NS_XLINK}" '
              f'xmlns:bldg="{NS_BLDG}" xmlns:dem="{NS_DEM}" xmlns:app="{NS_APP}" '
              f'xmlns:gen="{NS_GEN}" xmlns:xsi="{NS_XSI}" xsi:schemaLocation="'
              f"{NS_BLDG} http://schemas.opengis.net/citygml/building/2.0/building.xsd "
              f"{NS_DEM} http://schemas.opengis.net/citygml/relief/2.0/relief.xsd "
              f"{NS_APP} http://schemas.opengis.net/citygml/appearance/2.0/appearance.xsd "
              f'{NS_GEN} http://schemas.opengis.net/citygml/generics/2.0/generics.xsd">\n'
              f"{_IND}<gml:name>cityshade sample city, seed {seed}</gml:name>\n")
    out.write(_envelope_xml((lo_xy[0], lo_xy[1], z_lo), (hi_xy[0], hi_xy[1], z_hi), 1))
    if terrain:
        _terrain_xml(out, tin, ox, oy)
    for plan in plans:
        parts, _, _ = _object_xml(plan, "Building", detail, s, counts, sink, 2)
        counts.buildings += 1
        out.write(f"{_IND}<cityObjectMember>\n")
        out.write("".join(parts))
        out.write(f"{_IND}</cityObjectMember>\n")
    sink.write(out, texture_uri)
    out.write("</CityModel>\n")


OUTPUT_FORMATS = ("citygml", "cityjson", "cityjsonseq")


class _CityJSONSink:
    """Vertices (integer millimetres, deduplicated), texture coordinates and appearance
    indices of one CityJSON document or CityJSONSeq feature."""

    def __init__(self, ox: float, oy: float):
        self.ox, self.oy = ox, oy
        self.index: dict[tuple[int, int, int], int] = {}
        self.vertices: list[tuple[int, int, int]] = []
        self.uv: list[tuple[float, float]] = []
        self.materials_used: dict[str, int] = {}

    def vertex(self, p: Point) -> int:
        key = (round((p[0] - self.ox) * 1000.0), round((p[1] - self.oy) * 1000.0),
               round(p[2] * 1000.0))
        i = self.index.get(key)
        if i is None:
            i = self.index[key] = len(self.vertices)
            self.vertices.append(key)
        return i

    def material(self, key: str) -> int | None:
        if key not in dict(_MATERIALS):
            return None
        return self.materials_used.setdefault(key, len(self.materials_used))

    def vertices_json(self) -> str:
        return "[" + ",".join(f"[{x},{y},{z}]" for x, y, z in self.vertices) + "]"

    def appearance(self, texture_uri: str | None) -> dict:
        colours = dict(_MATERIALS)
        app: dict = {"materials": [
            {"name": key, "diffuseColor": [float(c) for c in colours[key].split()]}
            for key in self.materials_used]}
        if texture_uri is not None and self.uv:
            app["textures"] = [{"type": "PNG", "image": texture_uri, "wrapMode": "wrap"}]
            app["vertices-texture"] = self.uv
        return app


def _cityjson_objects(plan: _Plan, obj_type: str, detail: int, s: SampleCitySettings,
                      counts: _Counts, sink: _CityJSONSink, textured: bool,
                      parent: str | None) -> dict[str, dict]:
    """The CityObjects of one Building (or BuildingPart) and its parts: one lod 2 MultiSurface
    with semantics, materials and the facade texture, attributes as in the CityGML writer."""
    boundaries, sem_values, mat_values, tex_values = [], [], [], []
    kinds: dict[str, int] = {}
    for surface in _building_surfaces(plan, detail, s):
        sem = kinds.setdefault(surface.kind, len(kinds))
        for poly in surface.polys:
            rings = [[sink.vertex(p) for p in ring] for ring in [poly.exterior] + poly.interiors]
            boundaries.append(rings)
            sem_values.append(sem)
            mat_values.append(sink.material(poly.material))
            if poly.tex is not None and textured:
                first = len(sink.uv)
                sink.uv.extend([round(u, 4), round(v, 4)] for u, v in poly.tex)
                tex_values.append([[0] + list(range(first, first + len(poly.tex)))] +
                                  [[None]] * len(poly.interiors))
            else:
                tex_values.append([[None]] * (1 + len(poly.interiors)))
            counts.polygons += 1
            counts.interiors += len(poly.interiors)
            counts.triangles += poly.triangles
            counts.textured += poly.tex is not None
    geometry = {"type": "MultiSurface", "lod": "2", "boundaries": boundaries,
                "semantics": {"surfaces": [{"type": k} for k in kinds], "values": sem_values},
                "material": {"rgbTexture": {"values": mat_values}}}
    if any(v != [[None]] * len(v) for v in tex_values):
        geometry["texture"] = {"rgbTexture": {"values": tex_values}}
    years = [plan.year_built] + ([plan.year_demolished] if plan.year_demolished else [])
    counts.year_min = min(counts.year_min, *years)
    counts.year_max = max(counts.year_max, *years)
    counts.demolished += plan.year_demolished is not None
    attributes = {"Parzelle": plan.lot, "HoeheGrund": plan.ground_z,
                  "function": "1010" if obj_type == "BuildingPart" else "1000",
                  "yearOfConstruction": plan.year_built, "roofType": _ROOF_TYPE_CODE[plan.roof],
                  "measuredHeight": round(plan.eave_z(s.storey_m) + plan.roof_height_m
                                          - plan.ground_z, 3),
                  "storeysAboveGround": plan.storeys}
    if plan.year_demolished is not None:
        attributes["yearOfDemolition"] = plan.year_demolished
    obj: dict = {"type": obj_type, "attributes": attributes, "geometry": [geometry]}
    if parent is not None:
        obj["parents"] = [parent]
    objects = {plan.gml_id: obj}
    if plan.part is not None:
        counts.parts += 1
        obj["children"] = [plan.part.gml_id]
        objects.update(_cityjson_objects(plan.part, "BuildingPart", detail, s, counts, sink,
                                         textured, plan.gml_id))
    return objects


def _terrain_cityjson(tin: _Terrain, ox: float, oy: float, sink: _CityJSONSink) -> dict:
    c = tin.cell_m
    boundaries = []
    for j in range(tin.ny):
        for i in range(tin.nx):
            p = [sink.vertex((ox + tin.x0 + (i + di) * c, oy + tin.y0 + (j + dj) * c,
                              tin.z[j + dj][i + di])) for di, dj in ((0, 0), (1, 0), (1, 1),
                                                                       (0, 1))]
            boundaries += [[[p[0], p[1], p[2]]], [[p[0], p[2], p[3]]]]
    return {"SC_DEM": {"type": "TINRelief", "geometry": [
        {"type": "CompositeSurface", "lod": "2", "boundaries": boundaries}]}}


def _write_cityjson(out, plans: list[_Plan], tin: _Terrain, terrain: bool, ox: float,
                    oy: float, detail: int, seed: int, s: SampleCitySettings, counts: _Counts,
                    texture_uri: str | None, seq: bool) -> None:
    """The city as CityJSON 2.0 (one document) or CityJSONSeq (one feature per building)."""
    import json

    header = {"type": "CityJSON", "version": "2.0",
              "transform": {"scale": [0.001, 0.001, 0.001], "translate": [ox, oy, 0.0]},
              "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/25832",
                           "title": f"cityshade sample city, seed {seed} (synthetic, not "
                                    f"real data)"}}
    dumps = json.JSONEncoder(separators=(",", ":")).encode
    textured = texture_uri is not None
    if seq:
        out.write(dumps({**header, "CityObjects": {}, "vertices": []}) + "\n")

        def feature(fid: str, objects: dict, sink: _CityJSONSink) -> None:
            out.write('{"type":"CityJSONFeature","id":' + dumps(fid) + ',"CityObjects":'
                      + dumps(objects) + ',"vertices":' + sink.vertices_json()
                      + ',"appearance":' + dumps(sink.appearance(texture_uri)) + "}\n")

        if terrain:
            sink = _CityJSONSink(ox, oy)
            feature("SC_DEM", _terrain_cityjson(tin, ox, oy, sink), sink)
        for plan in plans:
            sink = _CityJSONSink(ox, oy)
            objects = _cityjson_objects(plan, "Building", detail, s, counts, sink, textured,
                                        None)
            counts.buildings += 1
            feature(plan.gml_id, objects, sink)
        return
    sink = _CityJSONSink(ox, oy)
    out.write(dumps(header)[:-1] + ',"CityObjects":{')
    first = True
    objects = _terrain_cityjson(tin, ox, oy, sink) if terrain else {}
    for plan in [None] + plans:
        if plan is not None:
            objects = _cityjson_objects(plan, "Building", detail, s, counts, sink, textured,
                                        None)
            counts.buildings += 1
        for oid, obj in objects.items():
            out.write(("" if first else ",") + dumps(oid) + ":" + dumps(obj))
            first = False
    out.write('},"vertices":' + sink.vertices_json() + ',"appearance":'
              + dumps(sink.appearance(texture_uri)) + "}\n")


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m cityshade.samplegen OUT.gml [--buildings N | --triangles N] [--seed S]``."""
    parser = argparse.ArgumentParser(
        prog="python -m cityshade.samplegen",
        description="Write a deterministic synthetic CityGML 2.0 or CityJSON 2.0 city (and its "
                    "facade PNG).")
    parser.add_argument("out", type=Path, help="GML file to write")
    size = parser.add_mutually_exclusive_group()
    size.add_argument("--buildings", type=int, default=40, help="number of buildings (40)")
    size.add_argument("--triangles", type=int, default=None,
                      help="about this many triangles (chooses buildings and detail)")
    parser.add_argument("--seed", type=int, default=7, help="layout seed (7)")
    parser.add_argument("--detail", type=int, choices=(0, 1, 2), default=None,
                        help="facade detail: 0 walls, 1 panels, 2 panels with windows")
    parser.add_argument("--origin", type=float, nargs=2, default=(690_000.0, 5_336_000.0),
                        metavar=("X", "Y"), help="south-west corner, EPSG:25832 metres")
    parser.add_argument("--no-texture", action="store_true", help="no facade texture")
    parser.add_argument("--no-terrain", action="store_true", help="no TIN terrain")
    parser.add_argument("--format", choices=OUTPUT_FORMATS, default="citygml",
                        help="citygml (default), cityjson (one 2.0 document) or cityjsonseq")
    args = parser.parse_args(argv)
    try:
        info = generate_city(args.out, n_buildings=args.buildings, seed=args.seed,
                             origin_xy_m=tuple(args.origin), texture=not args.no_texture,
                             terrain=not args.no_terrain, target_triangles=args.triangles,
                             detail=args.detail, output_format=args.format)
    except CityshadeError as exc:
        parser.exit(2 if isinstance(exc, UsageError) else 1, f"error: {exc}\n")
    print(f"{info.path}: {info.buildings} buildings, {info.building_parts} parts, "
          f"{info.polygons} polygons, {info.terrain_triangles} terrain triangles, "
          f"{info.triangles} triangles, {info.size_bytes / 1e6:.1f} MB, years "
          f"{info.year_range[0]}-{info.year_range[1]}, detail {info.detail}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
