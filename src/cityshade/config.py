"""All tunables and tolerances in one place, loadable from TOML.

Each stage has a frozen dataclass of settings with documented defaults; :class:`Settings` is
the one tree of them. A TOML file holds one table per stage (``[build]``, ``[kdtree]``,
``[shadows]`` with its sub-tables ``[shadows.map]``, ``[shadows.bias]``, ..., ``[sun]``,
``[batch]``, ``[evaluate]``, ``[stress]``); unknown tables or keys and values of the wrong type
or range are errors (:class:`~cityshade.errors.ConfigError` naming the key and the file), never
silently ignored. The library takes these objects, never dicts of options; the CLI loads a file
with ``--config`` and lets its flags override single values.
"""
from __future__ import annotations

import dataclasses
import math
import numbers
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from cityshade.errors import ConfigError, UsageError

#: The vegetation code attributes a reader keeps and ``[vegetation]`` may name (CityGML 1.0-3.0
#: ``veg:`` elements, CityJSON attributes; cityshade.citygml.namespaces).
VEGETATION_CODE_NAMES = ("class", "function", "usage", "species")

TIME_SOURCES = ("auto", "valid", "construction", "attribute", "creation")
AXIS_ORDERS = ("lonlat", "latlon")
#: What a build does with ClosureSurfaces (virtual surfaces closing a solid): leave them out
#: (they neither cast nor receive) or keep them as walls of their building.
CLOSURE_SURFACES = ("omit", "keep")

#: A LoD as text: whole (CityGML and CityJSON) or refined (CityJSON "2.2").
_LOD_TEXT = re.compile(r"^[0-4](\.[0-9])?$")


@dataclass(frozen=True)
class BuildSettings:
    """Reading and triangulating a CityGML file."""

    #: LoD to take from every object: 0–4, or for CityJSON a refined LoD such as 2.2 (then 2
    #: takes the highest 2.x each object has); None takes the highest LoD each object has.
    lod: int | float | None = None
    #: Appearance theme; None takes the theme with the most targeted surfaces.
    theme: str | None = None
    #: Override of the file's CRS, e.g. "EPSG:25832" (needed for files without srsName).
    crs: str | None = None
    #: Axis order of geographic coordinates, "lonlat" or "latlon"; None decides from the
    #: values, the footprints' right angles and the srsName spelling (docs/DESIGN.md §1).
    axis_order: str | None = None
    #: Where validity intervals come from (docs/DESIGN.md §1); "auto" takes the first available of
    #: valid → construction → attribute per object (database creation dates only with
    #: "creation").
    time_source: str = "auto"
    #: Generic attribute(s) holding years or dates, "begin=NAME[,end=NAME]" (``--time-attribute``).
    time_attribute: str | None = None
    #: Points closer than this (metres) are one point; below GML files' usual mm precision.
    merge_distance_m: float = 1e-6
    #: A point farther than this from the line of its neighbours, relative to the polygon size,
    #: is not collinear (relative so 10^7 m offsets behave the same as local coordinates).
    collinear_rel_tol: float = 1e-9
    #: Triangulated area must match the polygon's (with holes) to this relative tolerance,
    #: otherwise the polygon is self-intersecting or its holes are invalid and it is skipped.
    area_rel_tol: float = 1e-6
    #: Polygons whose area relative to its bounding square is below this are zero-area slivers.
    min_rel_area: float = 1e-12
    #: Distance (relative to polygon size) beyond which a polygon counts as non-planar in the
    #: report; it is still triangulated (the triangles keep the true 3-D vertices).
    nonplanar_rel_tol: float = 1e-3
    #: "omit": ClosureSurfaces (CityGML bldg:/con:ClosureSurface, WaterClosureSurface,
    #: HoleSurface, CityJSON "ClosureSurface"; surface class "closure") are virtual and left
    #: out of the scene, counted in the report; "keep": drawn like walls (the old behaviour).
    closure_surfaces: str = "omit"

    def __post_init__(self) -> None:
        _one_of("closure_surfaces", self.closure_surfaces, CLOSURE_SURFACES)
        _one_of("time_source", self.time_source, TIME_SOURCES)
        if self.axis_order is not None:
            _one_of("axis_order", self.axis_order, AXIS_ORDERS)
        if self.time_attribute is not None:
            from cityshade.geo.temporal import parse_time_attribute
            from cityshade.errors import UsageError

            try:
                parse_time_attribute(self.time_attribute)
            except UsageError as exc:
                raise ConfigError(str(exc)) from None
        if self.lod is not None and (
                isinstance(self.lod, bool) or not isinstance(self.lod, (int, float, str))
                or (isinstance(self.lod, int) and not 0 <= self.lod <= 4)
                or (not isinstance(self.lod, int) and not _LOD_TEXT.match(str(self.lod)))):
            raise ConfigError(f"lod must be between 0 and 4 (or a CityJSON LoD with one "
                              f"decimal such as 2.2), not {self.lod!r}")
        for name in ("merge_distance_m", "collinear_rel_tol", "area_rel_tol", "min_rel_area",
                     "nonplanar_rel_tol"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0):
                raise ConfigError(f"{name} must be a finite number >= 0, not {value}")


def _kdtree_settings():
    # The kd-tree's tunables, in a module without kernels (a render loads no builder).
    from cityshade.accel.settings import KdTreeSettings

    return KdTreeSettings()


def _sun_settings():
    # Next to the SPA code (sun.py), for the same reason as the kd-tree's.
    from cityshade.geo.sun import SpaSettings

    return SpaSettings()


def _is_int(value) -> bool:
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def _one_of(key: str, value, choices) -> None:
    """A :class:`ConfigError` naming ``key`` unless ``value`` is one of ``choices``."""
    if value not in choices:
        raise ConfigError(f"{key} must be one of {', '.join(choices)}, not {value!r}")


def _is_number(value) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


# --- shadows ------------------------------------------------------------------------------------

#: Largest shadow-map side: 16384² float32 depth + int32 ids is 2 GiB.
MAX_MAP_PX = 16384


@dataclass(frozen=True)
class MapSettings:
    """``[shadows.map]``: the shadow map itself."""

    #: Side of the shadow map in texels (square; per cascade for csm).
    px: int = 2048
    #: Texels of margin around the receivers in a fitted uniform view, so that filter kernels
    #: and offset lookups at the border stay inside the map (the lookup adds its filter radius,
    #: and the margin shrinks to less than half of a tiny map).
    fit_pad_px: int = 4

    def __post_init__(self) -> None:
        if not (_is_int(self.px) and 1 <= self.px <= MAX_MAP_PX):
            raise ConfigError(f"px (map_px) must be an integer in [1, {MAX_MAP_PX}], not {self.px!r}")
        if not (_is_int(self.fit_pad_px) and 0 <= self.fit_pad_px <= 64):
            raise ConfigError(f"fit_pad_px must be an integer in [0, 64], "
                              f"not {self.fit_pad_px!r}")


@dataclass(frozen=True)
class BiasSettings:
    """``[shadows.bias]``: the receiver-side bias of every map lookup (shadows/shadowmap.py).

    The defaults keep acne and peter-panning low on the sample city and on a box at 3° sun
    elevation (tests/shadows/test_shadowmap.py).
    """

    #: Constant offset of receivers toward the sun, metres: covers float32 rounding of the
    #: vertices and the depth (a few 1e-4 m at km coordinates) with a wide margin, and stays
    #: far below a texel so no shadow detaches from its caster.
    constant_m: float = 0.02
    #: Normal offset in light-space texels times sinθ: ≥ 0.71 removes acne, 1.5 leaves room
    #: for the depth's float32 rounding and non-square texels.
    slope: float = 1.5
    #: Largest normal offset, metres: with very coarse maps an unbounded offset would lift
    #: receivers over real occluders (light leaks).
    max_m: float = 1.0

    def __post_init__(self) -> None:
        for name, flag in (("constant_m", "bias"), ("slope", "slope_bias"),
                           ("max_m", "max_bias")):
            value = getattr(self, name)
            if not (_is_number(value) and math.isfinite(value) and value >= 0):
                raise ConfigError(f"{name} ({flag}) must be a finite number >= 0, not {value!r}")


@dataclass(frozen=True)
class PcfSettings:
    """``[shadows.pcf]``: percentage-closer filtering."""

    #: Taps per side (odd): 3 gives a 3×3 box of texels around the receiver.
    kernel: int = 3

    def __post_init__(self) -> None:
        if not (_is_int(self.kernel) and 1 <= self.kernel <= 63 and self.kernel % 2 == 1):
            raise ConfigError(f"kernel (pcf_kernel) must be an odd integer in [1, 63], "
                              f"not {self.kernel!r}")


@dataclass(frozen=True)
class VsmSettings:
    """``[shadows.vsm]``: variance shadow maps."""

    #: Filter radius in texels (0: no filter).
    blur_px: int = 2
    #: "gaussian" (σ = radius / 2) or "box".
    filter: str = "gaussian"
    #: Variance floor of the Chebyshev bound, m²: larger than the float rounding of the
    #: moments (float64 here) and than a plane's in-texel depth spread would need; the normal
    #: offset handles slopes, so a small value keeps contact shadows dark.
    min_variance_m2: float = 1e-4
    #: Light-bleeding reduction: bounds below this are shadow and the rest is rescaled to
    #: [0, 1] (Lauritzen); 0 disables.
    bleed_reduction: float = 0.2

    def __post_init__(self) -> None:
        if not (_is_int(self.blur_px) and 0 <= self.blur_px <= 64):
            raise ConfigError(f"blur_px (vsm_blur) must be an integer in [0, 64], not {self.blur_px!r}")
        if self.filter not in ("gaussian", "box"):
            raise ConfigError(f"filter (vsm_filter) must be 'gaussian' or 'box', not {self.filter!r}")
        if not (_is_number(self.min_variance_m2) and math.isfinite(self.min_variance_m2)
                and self.min_variance_m2 >= 0):
            raise ConfigError(f"min_variance_m2 (min_variance) must be a finite number >= 0, "
                              f"not {self.min_variance_m2!r}")
        if not (_is_number(self.bleed_reduction) and 0.0 <= self.bleed_reduction < 1.0):
            raise ConfigError(f"bleed_reduction must be in [0, 1), not {self.bleed_reduction!r}")


@dataclass(frozen=True)
class CascadeSettings:
    """``[shadows.cascades]``: cascaded shadow maps (shadows/planners.py)."""

    #: Number of view-depth slices: 4 is the usual choice (Zhang et al. 2006 show diminishing
    #: returns beyond 4 at common depth ranges).
    count: int = 4
    #: λ of the practical split scheme: 0.5 is the even blend Zhang et al. recommend; 1 is
    #: logarithmic, 0 uniform.
    split_lambda: float = 0.5

    def __post_init__(self) -> None:
        if not (_is_int(self.count) and 1 <= self.count <= 16):
            raise ConfigError(f"count (cascades) must be an integer in [1, 16], not {self.count!r}")
        if not (_is_number(self.split_lambda) and 0.0 <= self.split_lambda <= 1.0):
            raise ConfigError(f"split_lambda must be in [0, 1], not {self.split_lambda!r}")


@dataclass(frozen=True)
class WarpSettings:
    """``[shadows.warp]``: the perspective warps (shadows/warps.py)."""

    #: PSM: smallest near/far ratio of the virtual camera. Kozlov's slide-back: a tiny near
    #: plane concentrates the whole map on the first metres; 0.05 keeps a 20:1 density ratio.
    psm_min_near_far: float = 0.05
    #: PSM: |w| of the sun in post-perspective space, relative to its length, below which
    #: the light stays directional there (the sun parallel to the view plane).
    psm_directional_eps: float = 1e-9
    #: LiSPSM: beyond this many body depths the projection centre is so far that the warp
    #: changes texel sizes by < 1e-4 relative: use the uniform map itself.
    lispsm_max_n_rel: float = 1e4
    #: XPSM: cap of the warp ratio w_far / w_near (Zhang's bound on the warping strength: a
    #: stronger warp starves the far part of the map).
    xpsm_max_warp: float = 100.0
    #: Margin added on each side of the fitted x, y range, relative to the range, so that
    #: receivers on the border stay inside the map after float32 rounding.
    fit_margin_rel: float = 1e-3

    def __post_init__(self) -> None:
        if not 0.0 < self.psm_min_near_far < 1.0:
            raise ConfigError(f"psm_min_near_far must be in (0, 1), not {self.psm_min_near_far}")
        if not (self.psm_directional_eps >= 0.0 and self.lispsm_max_n_rel > 1.0
                and self.xpsm_max_warp > 1.0 and 0.0 <= self.fit_margin_rel < 0.5):
            raise ConfigError("warp settings out of range (psm_directional_eps >= 0, "
                              "lispsm_max_n_rel > 1, xpsm_max_warp > 1, 0 <= fit_margin_rel < 0.5)")


@dataclass(frozen=True)
class HybridSettings:
    """``[shadows.hybrid]``: the map-classifies, rays-decide technique (shadows/hybrid.py)."""

    #: "bracket" (map depth neighbourhood) or "vsm" (filtered value thresholds).
    classifier: str = "bracket"
    #: "vsm" classifier thresholds on the base's lit fraction.
    low: float = 0.02
    high: float = 0.98
    #: Radius (texels) of the bracket neighbourhood around the surface point: one texel covers
    #: point sampling's position error of up to one texel on either side.
    extra_texels: int = 1
    #: Bound on the boundary-following passes (each traces one layer).
    max_boundary_passes: int = 64

    def __post_init__(self) -> None:
        if self.classifier not in ("bracket", "vsm"):
            raise ConfigError(f"hybrid classifier must be bracket or vsm, "
                              f"not {self.classifier!r}")
        if not 0.0 <= self.low < self.high <= 1.0:
            raise ConfigError("hybrid thresholds need 0 <= low < high <= 1")
        if not (_is_int(self.extra_texels) and 0 <= self.extra_texels <= 16):
            raise ConfigError(f"extra_texels must be an integer in [0, 16], "
                              f"not {self.extra_texels!r}")
        if not (_is_int(self.max_boundary_passes) and self.max_boundary_passes >= 0):
            raise ConfigError(f"max_boundary_passes must be an integer >= 0, "
                              f"not {self.max_boundary_passes!r}")


#: Largest gain of the smoothing radius for surfaces nearer than the median depth (and smallest
#: for farther ones, as 1 / gain): a shadow-map texel near the eye covers many pixels, far away
#: a fraction of one.
SMOOTH_MAX_GAIN = 4.0


@dataclass(frozen=True)
class SmoothSettings:
    """``[shadows.smooth]``: the ``NAME+smooth`` post-filter (shadows/filtering.py)."""

    #: Gaussian σ in pixels at the median depth: 1.5 px softens the one-texel steps of a 2048²
    #: map seen at 1080p without blurring real shadow edges away.
    sigma_px: float = 1.5
    #: Relative depth step that ends the kernel: 2 % separates a building from the street
    #: behind it at any distance, while a ground plane seen at 5° (depth step between pixels
    #: about 1.5 % at 1080p, 40° fov) still smooths along itself.
    depth_threshold_rel: float = 0.02
    #: See :data:`SMOOTH_MAX_GAIN`.
    max_gain: float = SMOOTH_MAX_GAIN


def _table(cls: type) -> Any:
    """A sub-table field whose default is ``cls()``."""
    return field(default_factory=cls)


@dataclass(frozen=True)
class ShadowSettings:
    """``[shadows]``: the technique and the tunables of every technique.

    ``technique`` is a name of the registry (:func:`cityshade.shadows.get_technique`); the
    sub-tables hold what each part of a technique reads. :meth:`override` applies the CLI's
    flat option names (``map_px``, ``pcf_kernel``, ...).
    """

    #: Technique name (registry grammar; ``cityshade render --help`` lists it). None: the
    #: command's default (raytrace).
    technique: str | None = None
    map: MapSettings = _table(MapSettings)
    bias: BiasSettings = _table(BiasSettings)
    pcf: PcfSettings = _table(PcfSettings)
    vsm: VsmSettings = _table(VsmSettings)
    cascades: CascadeSettings = _table(CascadeSettings)
    warp: WarpSettings = _table(WarpSettings)
    hybrid: HybridSettings = _table(HybridSettings)
    smooth: SmoothSettings = _table(SmoothSettings)

    def override(self, **values: Any) -> "ShadowSettings":
        """A copy with the CLI's flat option names applied (:data:`SHADOW_OPTIONS`); None
        values are left alone, unknown names are a :class:`ConfigError`."""
        unknown = sorted(set(values) - set(SHADOW_OPTIONS))
        if unknown:
            raise ConfigError(f"unknown shadow option(s): {', '.join(unknown)} "
                              f"(valid: {', '.join(sorted(SHADOW_OPTIONS))})")
        tables: dict[str, dict[str, Any]] = {}
        for name, value in values.items():
            if value is not None:
                table, key = SHADOW_OPTIONS[name]
                tables.setdefault(table, {})[key] = value
        changes = {table: dataclasses.replace(getattr(self, table), **kv)
                   for table, kv in tables.items()}
        return dataclasses.replace(self, **changes)


#: Flat option name (CLI flag without dashes) → (sub-table, field) of :class:`ShadowSettings`.
SHADOW_OPTIONS: dict[str, tuple[str, str]] = {
    "map_px": ("map", "px"), "fit_pad_px": ("map", "fit_pad_px"),
    "bias": ("bias", "constant_m"), "slope_bias": ("bias", "slope"),
    "max_bias": ("bias", "max_m"), "pcf_kernel": ("pcf", "kernel"),
    "vsm_blur": ("vsm", "blur_px"), "vsm_filter": ("vsm", "filter"),
    "min_variance": ("vsm", "min_variance_m2"), "bleed_reduction": ("vsm", "bleed_reduction"),
    "cascades": ("cascades", "count"), "split_lambda": ("cascades", "split_lambda"),
    "classifier": ("hybrid", "classifier"), "low": ("hybrid", "low"),
    "high": ("hybrid", "high"), "extra_texels": ("hybrid", "extra_texels"),
    "max_boundary_passes": ("hybrid", "max_boundary_passes"),
    "smooth_sigma": ("smooth", "sigma_px"), "smooth_depth_rel": ("smooth", "depth_threshold_rel"),
    "smooth_max_gain": ("smooth", "max_gain"),
}


# --- trees from a register -----------------------------------------------------------------------

#: Length units of a register's or a mesh's numbers, in metres (``[trees] units``,
#: ``compare --mesh-units``).
LENGTH_UNITS_M = {"m": 1.0, "cm": 0.01, "mm": 0.001, "ft": 0.3048, "in": 0.0254}
#: Where a register tree stands: "model" = the model's terrain under it, else the ground plane
#: (``render --ground auto``'s height); "register" = the register's own ground height column.
TREE_GROUNDS = ("model", "register")


@dataclass(frozen=True)
class TreeSettings:
    """``[trees]``: a tree register read by ``build --trees`` (GeoJSON points or CSV rows).

    Column names are the register's property (GeoJSON) or header (CSV) names; the defaults are
    those of the Berlin-Lichtenberg register (``tree_positions_parameterized.geojson``). An
    empty name means the register has no such column.
    """

    #: Easting and northing columns (CSV; a GeoJSON Point's own coordinates win).
    x: str = "X"
    y: str = "Y"
    #: Ground height column (used with ``ground = "register"``).
    z: str = "Z"
    #: Whole tree height, crown diameter and trunk height (ground to the crown's base).
    height: str = "h_tree"
    crown_diameter: str = "d_crown"
    trunk_height: str = "h_trunk"
    #: Trunk diameter column ("" : every trunk is ``trunk_diameter_m``).
    trunk_diameter: str = ""
    #: The tree's id ("" or an empty value: ``tree_<row>``).
    id: str = "treeID_tile"
    #: Planting and felling dates or years ("" : none): the tree's validity interval.
    planted: str = ""
    felled: str = ""
    #: Unit of the height, diameter and ground-height columns (m, cm, mm, ft, in).
    units: str = "m"
    #: Trunk diameter when the register has none (metres).
    trunk_diameter_m: float = 0.3
    #: Crown ellipsoid: an icosphere of this many subdivisions (2: 320 triangles) scaled to the
    #: crown's diameter and height; trunk: a cylinder of this many sides.
    crown_subdivisions: int = 2
    trunk_sections: int = 8
    #: Where a tree stands (TREE_GROUNDS).
    ground: str = "model"

    def __post_init__(self) -> None:
        _one_of("units", self.units, LENGTH_UNITS_M)
        _one_of("ground", self.ground, TREE_GROUNDS)
        if not (_is_number(self.trunk_diameter_m) and 0.0 < self.trunk_diameter_m <= 10.0):
            raise ConfigError(f"trunk_diameter_m must be in (0, 10], not {self.trunk_diameter_m}")
        if not (_is_int(self.crown_subdivisions) and 1 <= self.crown_subdivisions <= 5):
            raise ConfigError(f"crown_subdivisions must be an integer in [1, 5], "
                              f"not {self.crown_subdivisions!r}")
        if not (_is_int(self.trunk_sections) and 3 <= self.trunk_sections <= 64):
            raise ConfigError(f"trunk_sections must be an integer in [3, 64], "
                              f"not {self.trunk_sections!r}")
        for name in ("x", "y", "height", "crown_diameter"):
            if not getattr(self, name):
                raise ConfigError(f"{name} must name a column")


# --- batch, evaluate, stress --------------------------------------------------------------------

@dataclass(frozen=True)
class BatchSettings:
    """``[batch]``: sun-hour runs (batch.py)."""

    #: Density of the surface sample points (``--samples-per-m2``): 1 per m² resolves the
    #: shadow of a chimney-sized object on a roof.
    samples_per_m2: float = 1.0
    #: For ``raytrace``: compute the shadow-ray origins once with the camera pass and only
    #: select the sun-facing pixels per step (identical results, tested).
    reuse_rays: bool = True

    def __post_init__(self) -> None:
        if not (_is_number(self.samples_per_m2) and math.isfinite(self.samples_per_m2)
                and 0.0 < self.samples_per_m2 <= 10_000.0):
            raise ConfigError(f"samples per m² (samples_per_m2) must be in (0, 10000], "
                              f"not {self.samples_per_m2}")


@dataclass(frozen=True)
class EvaluateSettings:
    """``[evaluate]``: tunables of ``cityshade evaluate``.

    Attributes
    ----------
    repeat : int
        Timed runs per technique and size after the warm-up run; the median is reported.
        3 keeps the median robust to one disturbed run on a shared 2-core machine.
    sizes : tuple of int
        Shadow-map sides in texels (``map_px``; per cascade for ``csm``).
    worst_cases : int
        Difference images written per view (the techniques and sizes with the most wrong
        pixels).
    edge_percentile : float
        Percentile of the edge displacement reported next to its mean.
    """

    repeat: int = 3
    sizes: tuple[int, ...] = (1024, 2048, 4096)
    worst_cases: int = 3
    edge_percentile: float = 95.0

    def __post_init__(self) -> None:
        if not (_is_int(self.repeat) and 1 <= self.repeat <= 100):
            raise ConfigError(f"repeat must be an integer in [1, 100], not {self.repeat!r}")
        sizes = tuple(self.sizes)
        if not sizes or not all(_is_int(s) and 16 <= s <= 16384 for s in sizes):
            raise ConfigError(f"map sizes must be integers in [16, 16384], not {self.sizes!r}")
        object.__setattr__(self, "sizes", sizes)
        if not (_is_int(self.worst_cases) and 0 <= self.worst_cases <= 100):
            raise ConfigError(f"worst_cases must be an integer in [0, 100], "
                              f"not {self.worst_cases!r}")
        if not 0.0 < self.edge_percentile <= 100.0:
            raise ConfigError(f"edge_percentile must be in (0, 100], not {self.edge_percentile}")


@dataclass(frozen=True)
class StressSettings:
    """``[stress]``: sizes and technique lists of the stress set (``quick`` for CI)."""

    quick: bool = False
    #: Perspective view size (W, H) and map-view pixel size of the model's cases.
    view_px: tuple[int, ...] = (480, 270)
    map_side_px: int = 400
    #: Map sizes of the elevation and geometry cases.
    map_sizes: tuple[int, ...] = (1024, 2048)
    #: Map sizes of the size sweep (shadowmap and pcf).
    sweep_sizes: tuple[int, ...] = (256, 512, 1024, 2048, 4096, 8192)
    cascades: tuple[int, ...] = (1, 2, 3, 4, 5, 6, 7, 8)
    techniques: tuple[str, ...] = ("shadowmap", "pcf", "vsm", "psm", "lispsm", "xpsm", "csm",
                                   "pcf+smooth", "hybrid:shadowmap", "hybrid:vsm",
                                   "hybrid:csm")
    elevations_deg: tuple[float, ...] = (0.1, 1.0, 3.0, 45.0, 89.9, 90.0, -5.0)
    #: Dates of the time-slice case (0: every date of the model).
    max_dates: int = 0
    #: Ground plane of every frame ("min", "auto" or a height; None: none), as
    #: ``render --ground``: the set checks the pipeline users run.
    ground: str | None = None

    @classmethod
    def quick_set(cls) -> "StressSettings":
        """The CI set: small views and maps, fewer techniques and dates, no 8192² map."""
        return cls(quick=True, view_px=(192, 108), map_side_px=160, map_sizes=(1024,),
                   sweep_sizes=(256, 1024, 2048), cascades=(1, 2, 8),
                   techniques=("shadowmap", "pcf", "vsm", "lispsm", "csm", "hybrid:shadowmap",
                               "hybrid:vsm"),
                   max_dates=2)


#: What decides whether vegetation is in leaf at a sun position (docs/DESIGN.md §21).
SEASONS = ("auto", "leaf_on", "leaf_off")
#: ``[vegetation] window_trees``: the crowns of the openings' daylight and sunlight.
WINDOW_TREES = ("evergreen", "all", "none")


def _fraction(value, what: str) -> None:
    if not (_is_number(value) and 0.0 <= value <= 1.0):
        raise ConfigError(f"{what} must be in [0, 1], not {value}")


@dataclass(frozen=True)
class VegetationClassSettings:
    """Light transmissivity of one class of vegetation (``[vegetation.solitary]``: CityGML
    SolitaryVegetationObject, ``[vegetation.plant_cover]``: PlantCover): the fraction of the
    direct sun a ray keeps after crossing one crown (docs/DESIGN.md §21)."""

    #: In leaf: UMEP/SOLWEIG's default TRANS_VEG, 3 % (Lindberg & Grimmond 2011, Theor. Appl.
    #: Climatol. 105; UMEP-dev/UMEP#825 names the parameter).
    leaf_on_transmissivity: float = 0.03
    #: Leaf off: 50 %, what the UMEP developers set for winter (UMEP-dev/UMEP#411: "we usually
    #: set the transmissivity to 50%").
    leaf_off_transmissivity: float = 0.5
    #: Evergreen: in leaf all year (the leaf-on transmissivity at every date).
    evergreen: bool = False

    def __post_init__(self) -> None:
        _fraction(self.leaf_on_transmissivity, "leaf_on_transmissivity")
        _fraction(self.leaf_off_transmissivity, "leaf_off_transmissivity")


@dataclass(frozen=True)
class VegetationSettings:
    """``[vegetation]``: vegetation objects as casters that let part of the sun through
    (docs/DESIGN.md §21), in every technique: the exact engines trace the crowns, the map
    techniques and the hybrid map the opaque casters and take the crowns from the exact
    crowns' pass."""

    #: False: vegetation neither casts nor receives (``--no-vegetation``): its triangles are
    #: left out of the scene.
    enabled: bool = True
    #: First and last day of the year (1-366, UTC date of the sun position) in leaf: UMEP's
    #: SOLWEIG defaults LEAF_START 97 and LEAF_END 300 (UMEP-dev/UMEP#441, #478), northern
    #: hemisphere; swap them (first > last) for the southern one: in leaf from first to last
    #: across the new year.
    leaf_on_day: int = 97
    leaf_off_day: int = 300
    #: "auto": in leaf by the sun position's date (a sun given by angles has none: in leaf);
    #: "leaf_on" / "leaf_off": that season at every date.
    season: str = "auto"
    #: The crowns in the openings' daylight and sunlight (compare's VSC and probable sunlight
    #: hours, BRE 209): "evergreen" (BRE 209's practice: deciduous trees left out, evergreen
    #: ones counted with their transmissivity), "all" (every crown: in leaf for the VSC, each
    #: hour's leaf state for the sunlight), "none".
    window_trees: str = "evergreen"
    #: Values of a vegetation object's ``class``, ``function``, ``usage`` or ``species`` in
    #: the data (CityGML ``veg:`` elements, CityJSON attributes of those names) that make its
    #: crown evergreen (its in-leaf transmissivity all year), compared whole, without case.
    #: The defaults are the plain words of English and German data; numeric codes go in
    #: :attr:`evergreen_codes` (a number means something else in another code list).
    evergreen_values: tuple[str, ...] = ("evergreen", "conifer", "coniferous", "needleleaf",
                                         "needle-leaved", "immergrün", "nadelbaum",
                                         "nadelgehölz", "konifere")
    #: Codes of a code list that make a crown evergreen, as ``NAME=CODE`` (NAME: ``class``,
    #: ``function``, ``usage`` or ``species``): the code counts under that name only, since
    #: code lists reuse numbers. Defaults: PLATEAU's (Japan's MLIT 3D city models) code list
    #: ``SolitaryVegetationObject_function.xml``, shipped in every dataset's ``codelists/``
    #: (e.g. Kawasaki's), whose product specification defines veg:function as evergreen or
    #: deciduous and needle or broad leaf: 11 常緑/針葉 (evergreen, needleleaf), 12 常緑/広葉
    #: (evergreen, broadleaf); 21 and 22 are the deciduous ones, 0 unknown. Its
    #: SolitaryVegetationObject_class (1-3: tree height classes) and PlantCover_class codes
    #: say nothing of the leaves. The SIG3D code lists of CityGML 2.0 are not among the
    #: defaults: their values were not at hand to cite; add a file's codes here.
    evergreen_codes: tuple[str, ...] = ("function=11", "function=12")
    solitary: VegetationClassSettings = _table(VegetationClassSettings)
    plant_cover: VegetationClassSettings = _table(VegetationClassSettings)

    def __post_init__(self) -> None:
        for name in ("leaf_on_day", "leaf_off_day"):
            value = getattr(self, name)
            if not (_is_int(value) and 1 <= value <= 366):
                raise ConfigError(f"{name} must be a day of the year in 1..366, not {value}")
        _one_of("season", self.season, SEASONS)
        _one_of("window_trees", self.window_trees, WINDOW_TREES)
        for entry in self.evergreen_codes:
            name, eq, code = str(entry).partition("=")
            if not eq or name.strip() not in VEGETATION_CODE_NAMES or not code.strip():
                raise ConfigError(f"evergreen_codes entries are NAME=CODE with NAME one of "
                                  f"{', '.join(VEGETATION_CODE_NAMES)}, not {entry!r}")

    def is_evergreen(self, codes: dict) -> bool:
        """Whether an object's codes (name → list of values, as the reader keeps them) hold
        one of :attr:`evergreen_values` (under any name) or of :attr:`evergreen_codes` (under
        its name)."""
        wanted = {v.strip().casefold() for v in self.evergreen_values}
        pairs = {(n.strip(), c.strip().casefold())
                 for n, _, c in (str(e).partition("=") for e in self.evergreen_codes)}
        return any(str(v).strip().casefold() in wanted
                   or (name, str(v).strip().casefold()) in pairs
                   for name, values in codes.items() for v in values)

    def in_leaf(self, day_of_year: int | None) -> bool:
        """Whether deciduous vegetation is in leaf on ``day_of_year`` (None: no date)."""
        if self.season != "auto":
            return self.season == "leaf_on"
        if day_of_year is None:
            return True
        first, last = self.leaf_on_day, self.leaf_off_day
        if first <= last:
            return first <= day_of_year <= last
        return day_of_year >= first or day_of_year <= last

    def with_transmissivity(self, leaf_on: float) -> "VegetationSettings":
        """These settings with every class's in-leaf transmissivity set to ``leaf_on``
        (``--tree-transmissivity``)."""
        return dataclasses.replace(
            self, solitary=dataclasses.replace(self.solitary, leaf_on_transmissivity=leaf_on),
            plant_cover=dataclasses.replace(self.plant_cover, leaf_on_transmissivity=leaf_on))


@dataclass(frozen=True)
class Settings:
    """All settings, one field per TOML table."""

    #: ``[build]``: reading and triangulating (``cityshade build``).
    build: BuildSettings = field(default_factory=BuildSettings)
    #: ``[kdtree]``: the SAH build (:class:`cityshade.accel.settings.KdTreeSettings`).
    kdtree: Any = field(default_factory=_kdtree_settings)
    #: ``[shadows]`` and its sub-tables: the technique and its tunables.
    shadows: ShadowSettings = field(default_factory=ShadowSettings)
    #: ``[sun]``: SPA (:class:`cityshade.geo.sun.SpaSettings`).
    sun: Any = field(default_factory=_sun_settings)
    #: ``[batch]``, ``[evaluate]``, ``[stress]``: the commands of the same names.
    batch: BatchSettings = field(default_factory=BatchSettings)
    evaluate: EvaluateSettings = field(default_factory=EvaluateSettings)
    stress: StressSettings = field(default_factory=StressSettings)
    #: ``[trees]``: a tree register (``build --trees``).
    trees: TreeSettings = field(default_factory=TreeSettings)
    #: ``[vegetation]``: transmissivity of vegetation per class and season.
    vegetation: VegetationSettings = field(default_factory=VegetationSettings)


_TOML_TYPES = {"int": int, "float": float, "str": str, "bool": bool}


def _coerce(cls: type, table: Mapping[str, Any], where: str) -> Any:
    """Build dataclass ``cls`` from a TOML table, rejecting unknown keys and wrong types."""
    if not isinstance(table, Mapping):
        raise ConfigError(f"{where} must be a table")
    fields = {f.name: f for f in dataclasses.fields(cls)}
    unknown = sorted(set(table) - set(fields))
    if unknown:
        raise ConfigError(f"unknown key(s) in {where}: {', '.join(unknown)} "
                          f"(valid: {', '.join(sorted(fields))})")
    kwargs = {}
    for key, value in table.items():
        default = getattr(cls(), key)
        if dataclasses.is_dataclass(default):
            kwargs[key] = _coerce(type(default), value, f"{where}.{key}")
            continue
        if isinstance(default, bool) and not isinstance(value, bool):
            raise ConfigError(f"{where}.{key} must be true or false")
        if isinstance(default, tuple):
            kwargs[key] = _coerce_list(default, value, f"{where}.{key}")
            continue
        if isinstance(default, float) and isinstance(value, int) and not isinstance(value, bool):
            value = float(value)
        if default is not None:
            allowed: tuple[type, ...] = (type(default),)
        else:  # an optional setting: its annotation names the type, e.g. "int | None"
            names = str(fields[key].type).replace(" ", "").split("|")
            allowed = tuple(_TOML_TYPES[n] for n in names if n in _TOML_TYPES)
        if allowed and not isinstance(value, allowed):
            raise ConfigError(f"{where}.{key} must be of type "
                              f"{' or '.join(t.__name__ for t in allowed)}")
        kwargs[key] = value
    try:
        return cls(**kwargs)
    except UsageError as exc:
        if exc.path or where == "config":
            raise
        raise ConfigError(f"{where}: {exc.message}") from None


def _coerce_list(default: tuple, value: Any, where: str) -> tuple:
    """A TOML array as a tuple whose items have the type of the default's items."""
    if not isinstance(value, list):
        raise ConfigError(f"{where} must be an array")
    kind = type(default[0]) if default else None
    out = []
    for item in value:
        if kind is float and isinstance(item, int) and not isinstance(item, bool):
            item = float(item)
        if kind is not None and (not isinstance(item, kind) or isinstance(item, bool)):
            raise ConfigError(f"{where} must hold values of type {kind.__name__}")
        out.append(item)
    return tuple(out)


def settings_from_mapping(data: Mapping[str, Any], where: str = "config") -> Settings:
    """Validate a parsed TOML document into :class:`Settings`."""
    return _coerce(Settings, data, where)


def load_settings(path: str | Path) -> Settings:
    """Read a TOML configuration file; unknown keys are a :class:`ConfigError`."""
    from cityshade.util import read_toml

    return settings_from_mapping(read_toml(path, "config"), where=str(path))
