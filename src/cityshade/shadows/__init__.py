"""Shadow techniques: one registry, one signature, one output.

Every technique takes a :class:`ShadowContext` (scene, resolved G-buffer surfaces, camera, sun,
city time, :class:`~cityshade.config.ShadowSettings`) and returns a :class:`ShadowResult`: the
per-pixel lit fraction (0 = shadow, 1 = sun; NaN never) and its own diagnostics. Techniques are
chosen by name with :func:`get_technique`; unknown names raise a
:class:`~cityshade.errors.UsageError` listing the valid ones.

The registry is the one place that knows the names. The grammar::

    NAME        := [hybrid:]TECHNIQUE[+smooth]
    TECHNIQUE   := EXACT | PLANNER[/LOOKUP] | ALIAS
    EXACT       := raytrace | ... (:data:`TECHNIQUES`: one "module:Class" entry each)
    PLANNER     := shadowmap | psm | lispsm | xpsm | csm[:WARP]     (WARP: psm | lispsm | xpsm)
    LOOKUP      := hard | pcf | vsm                                 (default hard)
    ALIAS       := pcf (shadowmap/pcf) | vsm (shadowmap/vsm)

A map technique is a light-view planner (:mod:`cityshade.shadows.planners`) plus a lookup
(:mod:`cityshade.shadows.lookups`), every planner with every lookup; ``+smooth`` adds the
screen-space post-filter to any technique; ``hybrid:`` refines any map technique with exact rays.

Shared rule (docs/DESIGN.md §9): a surface facing away from the sun (N·L ≤ 0, with N turned towards
the viewer) is in shadow without any test, in every technique, so techniques agree there. It is
computed once per frame and sun (:attr:`ShadowContext.faces`).
"""
from __future__ import annotations

import dataclasses
import functools
import importlib
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numba import njit

from cityshade.config import ShadowSettings
from cityshade.errors import ContractError, UsageError
from cityshade.runtime.memory import Recycler
from cityshade.runtime.threadpool import ROW_CHUNK, run_chunks

if TYPE_CHECKING:
    from cityshade.geometry.scene import Scene
    from cityshade.raster.camera import Camera
    from cityshade.raster.gbuffer import Surfaces
    from cityshade.geo.sun import SunPosition

#: Techniques that are not map techniques: name → "module:Class" (registering one is one line).
TECHNIQUES: dict[str, str] = {
    "raytrace": "cityshade.shadows.raytraced:RayTraced",
    "izb": "cityshade.shadows.izb:LightSpace",
    "exact": "cityshade.shadows.exact:Exact",
}
#: Light-view planners of the map techniques (:mod:`cityshade.shadows.planners`); ``csm`` takes
#: an optional ``:WARP`` (one of the other planners but ``shadowmap``).
PLANNERS = ("shadowmap", "psm", "lispsm", "xpsm", "csm")
#: Lookups of the map techniques (:mod:`cityshade.shadows.lookups`).
LOOKUPS = ("hard", "pcf", "vsm")
#: Short names kept from the thesis slides: the uniform map with a filtered lookup.
ALIASES = {"pcf": "shadowmap/pcf", "vsm": "shadowmap/vsm"}


@dataclass(eq=False)
class ShadowContext:
    """Everything a technique may use for one frame and one sun.

    ``normal`` (oriented to the viewer) comes from the camera pass when the pipeline built the
    context, and ``faces`` is computed at most once, however many techniques (a base, a
    smoothing, a hybrid) read it. ``measure`` asks map techniques for their per-frame measures
    (texel footprint, aliasing m: ``render -v``, ``evaluate``); they cost as much as a lookup,
    so a plain frame leaves them out.
    """

    scene: "Scene"
    surfaces: "Surfaces"
    camera: "Camera"
    sun: "SunPosition"
    t_days: float
    settings: ShadowSettings = field(default_factory=ShadowSettings)
    oriented_normal: np.ndarray | None = None
    measure: bool = False
    #: The sun-dependent arrays below (``faces``, ``facing_points``, ``facing_normals``,
    #: ``facing_origins``) kept across the contexts of one camera pass and sun
    #: (:meth:`CameraPass.context`), so the techniques of ``evaluate`` and their timed runs
    #: gather them once.
    shared: dict | None = field(default=None, repr=False)

    def _shared(self, name: str, make):
        if self.shared is None:
            return make()
        value = self.shared.get(name)
        if value is None:
            value = self.shared[name] = make()
        return value

    @functools.cached_property
    def normal(self) -> np.ndarray:
        """(H, W, 3) float64 unit normals turned to the seen side (:func:`oriented_normals`)."""
        if self.oriented_normal is not None:
            return self.oriented_normal
        return oriented_normals(self.surfaces, self.camera)

    @functools.cached_property
    def faces(self) -> np.ndarray:
        """(H, W) bool: surface pixels facing the sun (the shared rule)."""
        return self._shared("faces", lambda: facing_mask(self.normal, self.surfaces.valid,
                                                         self.sun.direction))

    @functools.cached_property
    def facing_points(self) -> np.ndarray:
        """(N, 3) float64 surface points of the :attr:`faces` pixels (row-major order),
        gathered once for the planner, the lookup and the rays."""
        return self._shared("facing_points",
                            lambda: gather_pixels(self.surfaces.position_m, self.faces))

    @functools.cached_property
    def facing_normals(self) -> np.ndarray:
        """(N, 3) float64 oriented normals of the :attr:`faces` pixels."""
        return self._shared("facing_normals", lambda: gather_pixels(self.normal, self.faces))

    @functools.cached_property
    def facing_origins(self) -> np.ndarray:
        """(N, 3) float64 shadow-ray origins of the :attr:`faces` pixels (row-major order):
        ``shadow_rays_from_surface(facing_points, facing_normals, sun)``, made straight from
        the frame's points and oriented normals (an exact technique needs no gathered copy)."""
        from cityshade.trace import shadow_rays_from_pixels

        return self._shared("facing_origins", lambda: shadow_rays_from_pixels(
            self.surfaces.position_m, self.normal, self.faces, _row_starts(self.faces),
            self.sun.direction))

    def facing_origins_of(self, rows: np.ndarray) -> np.ndarray:
        """(len(rows), 3) shadow-ray origins of the facing pixels ``rows`` (indices in the
        :attr:`faces` order): taken from :attr:`facing_origins` when an exact technique made
        them, else made from those rows of the gathered points and normals (a map technique's
        planner gathered them). The same values either way."""
        if "facing_origins" in self.__dict__ or "facing_origins" in (self.shared or {}):
            return take_pixels(self.facing_origins, rows)
        from cityshade.trace import shadow_rays_from_surface

        return shadow_rays_from_surface(take_pixels(self.facing_points, rows),
                                        take_pixels(self.facing_normals, rows),
                                        np.asarray(self.sun.direction, np.float64))

    def receivers(self, pixels: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(points, oriented normals) of the pixels of mask ``pixels`` (the gathered facing
        ones when ``pixels`` is :attr:`faces` itself)."""
        if pixels is self.faces:
            return self.facing_points, self.facing_normals
        return gather_pixels(self.surfaces.position_m, pixels), gather_pixels(self.normal, pixels)


@dataclass
class MapUse:
    """A depth map a map technique used, and for which pixels (what ``hybrid`` classifies with)."""

    depth_map: Any              # cityshade.shadows.shadowmap.DepthMap
    pixels: np.ndarray          # (H, W) bool: the facing pixels looked up in this map
    filter_radius_px: int       # texels around the lookup the technique's filter reads


class _Reported:
    """The behaviour of :class:`TechniqueDiagnostics` (its fields are declared below)."""

    def update(self, other: "TechniqueDiagnostics | dict[str, Any] | None" = None,
               **fields: Any) -> "TechniqueDiagnostics":
        """Set the reported fields of ``other`` and the keywords; returns self. A name that is
        not a field, or a value of the wrong type, is a :class:`ContractError`."""
        items = dict(other.items() if isinstance(other, _Reported) else other or {})
        items.update(fields)
        for name, value in items.items():
            kind = _DIAGNOSTIC_TYPES.get(name)
            if kind is None:
                raise ContractError(f"technique diagnostics have no field {name!r}")
            if value is not None and not isinstance(value, kind):
                raise ContractError(f"technique diagnostics: {name} must be {kind}, "
                                    f"not {type(value).__name__}")
            setattr(self, name, value)
        return self

    def as_dict(self) -> dict[str, Any]:
        """The reported fields as a plain dict (``base`` nested likewise)."""
        return {k: (v.as_dict() if isinstance(v, _Reported) else v) for k, v in self.items()}

    def items(self) -> list[tuple[str, Any]]:
        return [(k, v) for k in _DIAGNOSTIC_TYPES if (v := getattr(self, k)) is not None]

    def keys(self) -> list[str]:
        return [k for k, _ in self.items()]

    def get(self, key: str, default: Any = None) -> Any:
        value = getattr(self, key) if key in _DIAGNOSTIC_TYPES else None
        return default if value is None else value

    def __getitem__(self, key: str) -> Any:
        value = self.get(key)
        if value is None:
            raise KeyError(key)
        return value

    def __contains__(self, key: object) -> bool:
        return isinstance(key, str) and self.get(key) is not None


_NUMBER = (int, float)
#: The fields of :class:`TechniqueDiagnostics` by family, name → type; the names are those
#: ``render -v`` and ``evaluate`` print. Every field defaults to None: "not reported".
_DIAGNOSTIC_FAMILIES: dict[str, dict[str, Any]] = {
    # every technique; timings_s holds the stage times (fit_s, depth_s, lookup_s, rays_s...)
    "common": dict(technique=str, note=str, self_shadowed_px=int, shadow_s=_NUMBER,
                   timings_s=dict),
    # exact techniques: rays (or light-space queries) decided; izb's engine statistics
    "exact": dict(rays=int, engine=dict),
    # map techniques: lookup mode, (W, H) of each map, the warp's name (cascades) or what
    # warps.warp_matrix chose, a single map's DepthMap.stats, texel footprint on the receivers
    # and light-space texel size (metres), perspective aliasing {max, mean[, pixels]} (metres)
    "map": dict(lookup=str, map_px=list, warp=(str, dict), depth_map=dict, texel_m=_NUMBER,
                texel_light_m=_NUMBER, aliasing_m=dict),
    "cascades": dict(cascades=int, cascades_rendered=int, cascades_skipped=list,
                     splits_m=list, per_cascade=list),
    # hybrid: its base technique's diagnostics and what the rays refined
    # (refined_with: the exact engine(s) that traced, "raytrace" and/or "izb"; proven_px: the
    # uncertain pixels whose ray hit a caster of the map's window, decided without a trace)
    "hybrid": dict(base=_Reported, classifier=str, uncertain_px=int, proven_px=int,
                   boundary_px=int,
                   boundary_passes=int, traced_px=int, traced_share=_NUMBER, facing_px=int,
                   refined_with=str),
    # +smooth: its settings and time
    "smooth": dict(smooth=dict),
}
_DIAGNOSTIC_TYPES: dict[str, Any] = {name: kind for family in _DIAGNOSTIC_FAMILIES.values()
                                     for name, kind in family.items()}

TechniqueDiagnostics = dataclasses.make_dataclass(
    "TechniqueDiagnostics",
    [(name, Any, field(default=None)) for name in _DIAGNOSTIC_TYPES],
    bases=(_Reported,), namespace={"__module__": __name__, "__doc__": """What one technique run did.

    A dataclass whose fields are :data:`_DIAGNOSTIC_FAMILIES`, each None until the technique
    reports it; :meth:`as_dict` leaves the unreported ones out. Written through the fields or
    :meth:`update` (which checks names and types); read like a mapping too
    (``d["traced_px"]``, ``d.get("note")``, ``"rays" in d``).
    """})


@dataclass
class ShadowResult:
    """Per-pixel lit fraction and diagnostics of one technique run."""

    lit: np.ndarray                       # (H, W) float32 in [0, 1]; 0 where no surface
    diagnostics: TechniqueDiagnostics = field(default_factory=TechniqueDiagnostics)
    extra_channels: dict[str, np.ndarray] = field(default_factory=dict)
    #: Map techniques list the depth maps they used (empty for ``raytrace``).
    maps: list[MapUse] = field(default_factory=list)
    #: Map techniques: everything their planner drew (views, the cascades' texture array).
    prepared: Any = None


class Technique(Protocol):
    name: str

    def run(self, ctx: ShadowContext) -> ShadowResult: ...


def technique_names() -> list[str]:
    """The names of the product (docs/DESIGN.md §9), each usable with ``hybrid:`` and ``+smooth``;
    any planner also takes ``/pcf`` or ``/vsm`` (the module docstring's grammar)."""
    return [*TECHNIQUES, *map_technique_names()]


def exact_technique_names() -> list[str]:
    """The exact techniques (:data:`TECHNIQUES`): no map, the same answer as ``raytrace``."""
    return list(TECHNIQUES)


#: The exact technique that is no engine of its own: it picks one per call
#: (:mod:`cityshade.shadows.exact`); the default of every command.
DEFAULT_EXACT = "exact"


def exact_engine_names() -> list[str]:
    """The exact engines (``raytrace``, ``izb``): :func:`exact_technique_names` but the chooser
    :data:`DEFAULT_EXACT`, e.g. the techniques ``evaluate --shadows all`` times."""
    return [n for n in TECHNIQUES if n != DEFAULT_EXACT]


def map_technique_names() -> list[str]:
    """The map techniques of the product: every planner with its classic lookup."""
    return ["shadowmap", *ALIASES, "psm", "lispsm", "xpsm", "csm",
            *(f"csm:{w}" for w in PLANNERS[1:4])]


def names_help() -> str:
    """One line for ``--help`` and error messages: the names and the grammar."""
    return (f"{', '.join(technique_names())}; any map technique as PLANNER/LOOKUP "
            f"(planners {', '.join(PLANNERS)}, csm:WARP; lookups {', '.join(LOOKUPS)}); "
            f"hybrid[:MAP] (default base vsm); each also as NAME+smooth")


def _unknown(name: str, why: str = "") -> UsageError:
    return UsageError(f"unknown shadow technique {name!r}{why}; valid: {names_help()}")


@dataclass(frozen=True)
class TechniqueSpec:
    """A technique name parsed once by the grammar of the module docstring.

    ``family`` is ``"exact"`` (an engine of :data:`TECHNIQUES`: no map, the same answer as
    ``raytrace``), ``"map"`` (a planner and a lookup) or ``"hybrid"`` (a map technique whose
    uncertain pixels exact rays decide). ``+smooth`` keeps the family of what it smooths.
    """

    name: str                  # the name as given
    family: str                # "exact" | "map" | "hybrid"
    engine: str | None = None  # exact: the engine's name (a key of TECHNIQUES)
    planner: str | None = None  # map and hybrid: shadowmap | psm | lispsm | xpsm | csm
    warp: str | None = None     # csm:WARP's warp
    lookup: str | None = None   # map and hybrid: hard | pcf | vsm
    base: str | None = None     # hybrid: its map technique's name; +smooth: the unsmoothed name
    smooth: bool = False

    @property
    def exact(self) -> bool:
        """An exact engine alone (``raytrace``, ``izb``; not smoothed): no depth map, answers
        equal to ``raytrace``'s on every receiver, runs on a tiled scene view and on batch
        receivers."""
        return self.family == "exact" and not self.smooth

    @property
    def tileable(self) -> bool:
        """Runs tile by tile over a tiled cache's view (shadow rays per tile, ORed)."""
        return self.exact

    def maps_per_frame(self, settings: ShadowSettings | None = None) -> int:
        """Depth maps a frame draws: 0 for an exact engine, the cascades' count for ``csm``,
        else 1."""
        if self.family == "exact":
            return 0
        if self.planner == "csm":
            return (settings or ShadowSettings()).cascades.count
        return 1


def describe(name: "str | TechniqueSpec") -> TechniqueSpec:
    """The :class:`TechniqueSpec` of ``name``: the one parser of technique names (a spec is
    returned as it is, so functions take either at their public edge). Unknown names raise a
    :class:`UsageError` listing the valid ones."""
    if isinstance(name, TechniqueSpec):
        return name
    return _describe(name)


@functools.lru_cache(maxsize=256)
def _describe(name: str) -> TechniqueSpec:
    base, plus, suffix = name.partition("+")
    if plus:
        if suffix != "smooth":
            raise _unknown(name, f" (unknown suffix +{suffix})")
        return dataclasses.replace(_describe(base), name=name, base=base, smooth=True)
    if name == "hybrid" or name.startswith("hybrid:"):
        inner_name = name.partition(":")[2] or "vsm"
        return dataclasses.replace(hybrid_base(inner_name), name=name, family="hybrid",
                                   base=inner_name)
    if name in TECHNIQUES:
        return TechniqueSpec(name=name, family="exact", engine=name)
    spec = ALIASES.get(name, name)
    planner_name, slash, lookup_name = spec.partition("/")
    if slash and lookup_name not in LOOKUPS:
        raise _unknown(name, f" (unknown lookup {lookup_name!r})")
    head, colon, warp = planner_name.partition(":")
    if head not in PLANNERS or (colon and (head != "csm" or warp not in PLANNERS[1:4])):
        if head == "csm" and colon:
            raise _unknown(name, f" (unknown warp {warp!r}; valid: {', '.join(PLANNERS[1:4])})")
        raise _unknown(name)
    return TechniqueSpec(name=name, family="map", planner=head, warp=warp or None,
                         lookup=lookup_name or "hard")


def hybrid_base(name: str) -> TechniqueSpec:
    """The :class:`TechniqueSpec` of ``name`` as the base of ``hybrid:NAME``: a map technique
    (not smoothed, not itself a hybrid); a :class:`UsageError` for anything else."""
    if name.startswith("hybrid") or name in TECHNIQUES or "+" in name:
        raise UsageError(f"hybrid needs a shadow-map base technique, not {name!r}; "
                         "valid: " + ", ".join(map_technique_names()) + " (or PLANNER/LOOKUP)")
    return _describe(name)


def get_technique(name: "str | TechniqueSpec") -> Technique:
    """The technique registered under ``name`` (an instance ready to run), by the grammar of
    the module docstring."""
    spec = describe(name)
    if spec.smooth:
        from cityshade.shadows.filtering import Smoothed

        return Smoothed(get_technique(spec.base))
    if spec.family == "hybrid":
        from cityshade.shadows.hybrid import Hybrid

        return Hybrid(spec.base)
    if spec.family == "exact":
        module, cls = TECHNIQUES[spec.engine].split(":")
        return getattr(importlib.import_module(module), cls)()
    return get_map_technique(spec.name)


def get_map_technique(name: str):
    """The :class:`~cityshade.shadows.planners.MapTechnique` of ``PLANNER[/LOOKUP]`` or an
    alias; a :class:`UsageError` for anything else."""
    from cityshade.shadows import lookups, planners

    spec = describe(name)
    if spec.family != "map" or spec.smooth:
        raise _unknown(name)
    planner = planners.make_planner(spec.planner, spec.warp)
    return planners.MapTechnique(name, planner, lookups.make_lookup(spec.lookup))


def oriented_normals(surfaces: "Surfaces", camera: "Camera") -> np.ndarray:
    """Unit normals (H, W, 3) float64 turned to the side the camera sees.

    A pixel may show the back of a triangle (an open model, a wall seen from inside); its
    surface for shading and shadows is the side that is seen.
    """
    from cityshade.raster.gbuffer import seen_side_normals

    return seen_side_normals(surfaces, camera)


# Serial kernels over rows ``[r0, r1)`` run on ``run_chunks`` (see runtime.threadpool): as
# ``prange`` kernels the three made 1.7-2.0 CPU s of a first render's compiling, serial 0.4-0.9.

@njit(cache=True, nogil=True)
def _row_counts(mask, counts, r0, r1):
    for r in range(r0, r1):
        k = 0
        for c in range(mask.shape[1]):
            if mask[r, c]:
                k += 1
        counts[r + 1] = k


@njit(cache=True, nogil=True)
def _gather_kernel(image, mask, starts, out, r0, r1):
    # Rows handed out in chunks, each from its prefix-sum start: row-major order, the first
    # touch of the fresh output's pages shared by the threads.
    for r in range(r0, r1):
        k = starts[r]
        for c in range(mask.shape[1]):
            if mask[r, c]:
                for j in range(image.shape[2]):
                    out[k, j] = image[r, c, j]
                k += 1


def _row_starts(mask) -> np.ndarray:
    """(H + 1,) int64: where each row's pixels of an (H, W) bool mask start in its row-major
    gather (the last entry is the count), for the gather's rows in parallel."""
    starts = np.zeros(mask.shape[0] + 1, np.int64)
    if mask.size:
        run_chunks(_row_counts, mask.shape[0], ROW_CHUNK, mask, starts)
    np.cumsum(starts, out=starts)
    return starts


#: The gathered receivers' memory (a map frame's points and normals: 81 MB each), used again
#: once nothing refers to it.
_GATHERED = Recycler(keep=4)


def gather_pixels(image, mask) -> np.ndarray:
    """(N, C) float64 ``image[mask]`` of an (H, W, C) image and an (H, W) bool mask, in
    row-major order (numpy's boolean gather of a 3-D image is several times slower)."""
    image = np.asarray(image)
    mask = np.ascontiguousarray(mask, bool)
    starts = _row_starts(mask)
    out = _GATHERED.empty((int(starts[-1]), image.shape[2]), np.float64)
    if out.shape[0]:
        run_chunks(_gather_kernel, mask.shape[0], ROW_CHUNK, image, mask, starts, out)
    return out


@njit(cache=True, nogil=True)
def _scatter_kernel(values, mask, starts, out, r0, r1):
    for r in range(r0, r1):
        k = starts[r]
        for c in range(mask.shape[1]):
            if mask[r, c]:
                out[r, c] = values[k]
                k += 1


def scatter_pixels(values, mask, out) -> None:
    """``out[mask] = values``: (N,) values of an (H, W) bool mask's pixels in row-major order
    (:func:`gather_pixels`'s order) written into the (H, W) image ``out``, rows in parallel
    (numpy's boolean assignment took 11-13 ms for 3.4 M of 4.2 M pixels)."""
    mask = np.ascontiguousarray(mask, bool)
    starts = _row_starts(mask)
    if int(starts[-1]) != len(values):
        raise ContractError(f"{len(values)} values for {int(starts[-1])} pixels")
    if len(values):
        run_chunks(_scatter_kernel, mask.shape[0], ROW_CHUNK, values, mask, starts, out)


def take_pixels(image, at) -> np.ndarray:
    """(N, C) float64 rows of an (H, W, C) image (or of an (M, C) array) at flat pixel (row)
    indices ``at``: the gather of a mask's few pixels (``gather_pixels(image, mask)`` equals
    it with ``at`` the mask's ``np.flatnonzero``) without a pass over the whole frame, in
    parallel by :func:`cityshade.lightspace.kernels.gather_rows` (numpy's fancy index of
    2-D rows: 1.15 ms for 81k rows of 3, this 0.12)."""
    from cityshade.lightspace.kernels import gather_rows

    image = np.asarray(image)
    flat = image.reshape(-1, image.shape[-1])
    at = np.asarray(at, np.int64)
    if at.size and not (0 <= int(at.min()) and int(at.max()) < flat.shape[0]):
        raise ContractError(f"pixel indices outside 0..{flat.shape[0] - 1}")
    out = np.empty((at.shape[0], flat.shape[1]), np.float64)
    if at.size:
        gather_rows(flat, at, out)
    return out


@njit(cache=True, nogil=True)
def _facing_kernel(normal, valid, sx, sy, sz, out, i0, i1):
    # N·L summed left to right in float64 (no fused multiply-add: the same bits anywhere).
    every = valid.shape[0] == 0
    for i in range(i0, i1):
        cos = normal[i, 0] * sx + normal[i, 1] * sy + normal[i, 2] * sz
        out[i] = (cos > 0.0) & (every or valid[i])


#: Pixels per work item of :func:`facing_mask`.
FACING_CHUNK = 1 << 16


def facing_mask(normal, valid, sun_direction) -> np.ndarray:
    """(H, W) bool: valid pixels whose oriented normal faces the sun: N·L > 0, with N·L
    ``(nx sx + ny sy) + nz sz`` in float64 (numpy's ``normal @ sun`` took 12 ms for a 1080p
    frame, every technique's and every batch step's, and its rounding depends on the BLAS
    kernel the machine picks). ``normal`` (..., 3); ``valid`` bool of its leading shape, or
    True."""
    normal = np.asarray(normal, np.float64)
    shape = normal.shape[:-1]
    flat = np.ascontiguousarray(normal).reshape(-1, 3)
    s = np.asarray(sun_direction, dtype=np.float64).reshape(3)
    valid = np.asarray(valid, bool)
    if valid.ndim == 0 and bool(valid):
        valid = np.empty(0, bool)       # every pixel
    else:
        valid = np.ascontiguousarray(np.broadcast_to(valid, shape)).reshape(-1)
    valid.flags.writeable = False       # one kernel type for both (a broadcast is read-only)
    out = np.empty(flat.shape[0], bool)
    run_chunks(_facing_kernel, flat.shape[0], FACING_CHUNK, flat, valid, float(s[0]),
               float(s[1]), float(s[2]), out)
    return out.reshape(shape)


def facing_sun(surfaces: "Surfaces", camera: "Camera", sun_direction
               ) -> tuple[np.ndarray, np.ndarray]:
    """(oriented normals, mask of surface pixels that face the sun): the shared rule."""
    normal = oriented_normals(surfaces, camera)
    return normal, facing_mask(normal, surfaces.valid, sun_direction)
