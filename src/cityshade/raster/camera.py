"""Cameras: perspective views, the automatic overview, named presets and georeferenced maps.

Conventions
-----------
* Render space (docs/DESIGN.md §1): x east, y north, z up, metres, relative to the scene origin.
* Pixel ``(col, row)`` has its centre at ``col + 0.5``, ``row + 0.5``; row 0 is the top of the
  image (north for maps). Images are row-major, ``(H, W)``.
* Perspective: the camera frame is ``right``, ``up`` (true up, orthogonal to the view) and
  ``forward`` (unit, eye → target). A pixel centre lies on the plane one metre in front of the
  eye at screen coordinates ``xs = (col + 0.5 - W/2) * pitch``, ``ys = (H/2 - row - 0.5) *
  pitch`` with ``pitch = 2 tan(vfov/2) / H``; its ray is ``xs right + ys up + forward``.
* Map (orthographic, top-down, north up): pixel centres are at render-space
  ``x = x_left_m + (col + 0.5) px``, ``y = y_top_m - (row + 0.5) px``; rays point straight
  down from the camera plane ``z = eye_m[2]``. The grid corners are aligned to multiples of the
  pixel size in the scene CRS, so maps of one model at one pixel size always share a grid.
  A strip of a map (:meth:`Camera.strip`) keeps the whole map's ``y_top_m`` and counts its
  rows from ``row0_px``: ``y = y_top_m - (row0_px + row + 0.5) px``, so its pixel centres are
  the whole map's, bit for bit.
* ``near_m``/``far_m`` bound the view depth (perspective: distance along ``forward``; map:
  distance below the camera plane). The rasterizer clips at them.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from cityshade.errors import UnknownPresetError, UsageError
from cityshade.raster.presets import PRESETS_RESOURCE, load_presets  # noqa: F401 (re-exported)

#: Fraction of the image the fitted model box may fill (a thin border around the city).
FIT_FILL = 0.95
#: Default image side of a map view when no pixel size is given (the CLI's "fits 2048 px").
DEFAULT_MAP_SIDE_PX = 2048
#: Largest map side in pixels: 16384² float32 depth alone is 1 GiB.
DEFAULT_MAX_MAP_PX = 16384
#: Smallest near plane relative to the far plane when the eye is inside the model box; the
#: rasterizer works in float64 homogeneous coordinates, so this costs no depth precision.
NEAR_FAR_RATIO = 1e-6
#: Absolute floor of the near plane, metres.
MIN_NEAR_M = 1e-3
#: Margin of the map camera plane above the highest point, relative to the model size (plus
#: one metre), so that no surface lies on the camera plane.
MAP_EYE_MARGIN_REL = 0.01


@dataclass(frozen=True, eq=False)
class Camera:
    """A perspective or top-down map camera (see the module docstring for conventions).

    Attributes
    ----------
    kind : str
        ``"perspective"`` or ``"map"``.
    width_px, height_px : int
        Image size.
    eye_m, target_m, up : (3,) float64
        Render-space eye and target (metres) and the approximate up direction.
    vfov_deg : float
        Vertical field of view (perspective only).
    near_m, far_m : float
        View-depth range (metres).
    pixel_size_m, x_left_m, y_top_m : float
        Map only: pixel size and the render-space x of the left edge / y of the top edge.
    row0_px : int
        Map only: the first row of this camera in the whole map (a strip, :meth:`strip`); 0
        for a whole map.
    """

    kind: str
    width_px: int
    height_px: int
    eye_m: np.ndarray
    target_m: np.ndarray
    up: np.ndarray
    vfov_deg: float
    near_m: float
    far_m: float
    pixel_size_m: float = 0.0
    x_left_m: float = 0.0
    y_top_m: float = 0.0
    name: str = field(default="", compare=False)
    row0_px: int = 0

    def __post_init__(self) -> None:
        if self.kind not in ("perspective", "map"):
            raise UsageError(f"camera kind must be 'perspective' or 'map', not {self.kind!r}")
        if not (isinstance(self.width_px, (int, np.integer)) and self.width_px >= 1 and
                isinstance(self.height_px, (int, np.integer)) and self.height_px >= 1):
            raise UsageError(f"image size must be at least 1x1 pixels, not "
                             f"{self.width_px}x{self.height_px}")
        for name in ("eye_m", "target_m", "up"):
            value = np.asarray(getattr(self, name), dtype=np.float64).reshape(-1)
            if value.shape != (3,) or not np.isfinite(value).all():
                raise UsageError(f"camera {name} must be 3 finite numbers")
            value.setflags(write=False)
            object.__setattr__(self, name, value)
        if not (math.isfinite(self.near_m) and math.isfinite(self.far_m)
                and 0.0 <= self.near_m < self.far_m):
            raise UsageError(f"camera needs 0 <= near < far, not near {self.near_m}, "
                             f"far {self.far_m}")
        if self.kind == "perspective":
            if not 0.0 < self.vfov_deg < 180.0:
                raise UsageError(f"vertical field of view must be in (0, 180) degrees, "
                                 f"not {self.vfov_deg}")
            if self.near_m <= 0.0:
                raise UsageError("a perspective camera needs near > 0")
            if np.linalg.norm(self.target_m - self.eye_m) == 0.0:
                raise UsageError("camera eye and target coincide")
        elif not (math.isfinite(self.pixel_size_m) and self.pixel_size_m > 0.0):
            raise UsageError(f"map pixel size must be > 0 metres, not {self.pixel_size_m}")
        if not (isinstance(self.row0_px, (int, np.integer)) and self.row0_px >= 0):
            raise UsageError(f"camera row0_px must be an integer >= 0, not {self.row0_px!r}")
        if self.row0_px and self.kind != "map":
            raise UsageError("only a map camera has strips (row0_px)")

    # -- frame -----------------------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, int]:
        """(H, W)."""
        return int(self.height_px), int(self.width_px)

    def frame(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Unit (right, up, forward) of the camera, render space, float64."""
        if self.kind == "map":
            return (np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]),
                    np.array([0.0, 0.0, -1.0]))
        return _look_frame(self.eye_m, self.target_m, self.up)

    @property
    def pitch(self) -> float:
        """Perspective: pixel spacing on the plane one metre in front of the eye."""
        return 2.0 * math.tan(math.radians(self.vfov_deg) / 2.0) / self.height_px

    def screen_coordinates(self) -> tuple[np.ndarray, np.ndarray]:
        """Screen coordinates of pixel centres: ``xs`` (W,) per column, ``ys`` (H,) per row.

        Perspective: on the plane one metre in front of the eye (camera frame). Map:
        render-space x and y. Every kernel uses these same arrays, so ties are decided the
        same way everywhere.
        """
        col = np.arange(self.width_px, dtype=np.float64) + 0.5
        row = np.arange(self.row0_px, self.row0_px + self.height_px, dtype=np.float64) + 0.5
        if self.kind == "map":
            return self.x_left_m + col * self.pixel_size_m, self.y_top_m - row * self.pixel_size_m
        p = self.pitch
        return (col - self.width_px / 2.0) * p, (self.height_px / 2.0 - row) * p

    def primary_rays(self) -> tuple[np.ndarray, np.ndarray]:
        """Rays through the pixel centres, row-major, row 0 at the top.

        Returns
        -------
        origins, directions : (H*W, 3) float64
            Perspective: the eye and unit directions. Map: points on the camera plane
            ``z = eye_m[2]`` and ``(0, 0, -1)``.
        """
        xs, ys = self.screen_coordinates()
        h, w = self.shape
        if self.kind == "map":
            origins = np.empty((h, w, 3))
            origins[..., 0] = xs[None, :]
            origins[..., 1] = ys[:, None]
            origins[..., 2] = self.eye_m[2]
            directions = np.zeros((h * w, 3))
            directions[:, 2] = -1.0
            return origins.reshape(-1, 3), directions
        right, up, fwd = self.frame()
        d = (xs[None, :, None] * right + ys[:, None, None] * up + fwd).reshape(-1, 3)
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        return np.broadcast_to(self.eye_m, d.shape).copy(), d

    # -- matrices --------------------------------------------------------------------------
    def view_from_world(self) -> np.ndarray:
        """(4, 4) float64 OpenGL-style view matrix (camera looks down its -z axis)."""
        right, up, fwd = self.frame()
        m = np.eye(4)
        m[0, :3], m[1, :3], m[2, :3] = right, up, -fwd
        m[:3, 3] = -m[:3, :3] @ self.eye_m
        return m

    def clip_from_world(self) -> np.ndarray:
        """(4, 4) float64 OpenGL-style clip-space matrix (projection @ view).

        After the divide by w, x and y in [-1, 1] span the image (x right, y up: y = 1 is the
        top edge of row 0) and z in [-1, 1] spans [near, far].
        """
        n, f = self.near_m, self.far_m
        proj = np.zeros((4, 4))
        if self.kind == "map":
            h, w = self.shape
            left = self.x_left_m - self.eye_m[0]
            right = left + w * self.pixel_size_m
            top = self.y_top_m - self.row0_px * self.pixel_size_m - self.eye_m[1]
            bottom = top - h * self.pixel_size_m
            proj[0, 0] = 2.0 / (right - left)
            proj[0, 3] = -(right + left) / (right - left)
            proj[1, 1] = 2.0 / (top - bottom)
            proj[1, 3] = -(top + bottom) / (top - bottom)
            proj[2, 2] = -2.0 / (f - n)
            proj[2, 3] = -(f + n) / (f - n)
            proj[3, 3] = 1.0
        else:
            cot = 1.0 / math.tan(math.radians(self.vfov_deg) / 2.0)
            proj[0, 0] = cot * self.height_px / self.width_px
            proj[1, 1] = cot
            proj[2, 2] = (f + n) / (n - f)
            proj[2, 3] = 2.0 * f * n / (n - f)
            proj[3, 2] = -1.0
        return proj @ self.view_from_world()

    def strip(self, row0: int, row1: int) -> "Camera":
        """Map: the camera of rows ``[row0, row1)`` of this one, whose pixel centres are this
        camera's bit for bit (same ``y_top_m``, rows counted from ``row0_px``)."""
        self._require_map("strip")
        row0, row1 = int(row0), int(row1)
        if not 0 <= row0 < row1 <= self.height_px:
            raise UsageError(f"strip rows [{row0}, {row1}) outside the map's {self.height_px}")
        return dataclasses.replace(self, height_px=row1 - row0, row0_px=self.row0_px + row0)

    # -- georeference (maps) ---------------------------------------------------------------
    def _require_map(self, what: str) -> None:
        if self.kind != "map":
            raise UsageError(f"{what} exists only for map cameras, not {self.kind}")

    def pixel_centres_world(self, origin_m) -> np.ndarray:
        """Map: (H, W, 2) float64 CRS coordinates (x, y) of the pixel centres."""
        self._require_map("pixel_centres_world")
        origin = np.asarray(origin_m, dtype=np.float64)
        xs, ys = self.screen_coordinates()
        out = np.empty(self.shape + (2,))
        out[..., 0] = (origin[0] + xs)[None, :]
        out[..., 1] = (origin[1] + ys)[:, None]
        return out

    def geotransform(self, origin_m) -> tuple[float, ...]:
        """Map: GDAL geotransform ``(x_ul, px, 0, y_ul, 0, -px)`` of the upper-left CORNER."""
        self._require_map("geotransform")
        origin = np.asarray(origin_m, dtype=np.float64)
        px = float(self.pixel_size_m)
        return (float(origin[0] + self.x_left_m), px, 0.0,
                float(origin[1] + self.y_top_m - self.row0_px * px), 0.0, -px)

    def pixel_of_world(self, xy_crs, origin_m) -> np.ndarray:
        """Map: (N, 2) int (col, row) of the pixels containing CRS points (N, 2)."""
        self._require_map("pixel_of_world")
        xy = np.atleast_2d(np.asarray(xy_crs, dtype=np.float64))
        origin = np.asarray(origin_m, dtype=np.float64)
        col = np.floor((xy[:, 0] - origin[0] - self.x_left_m) / self.pixel_size_m)
        row = np.floor((self.y_top_m - (xy[:, 1] - origin[1])) / self.pixel_size_m) - self.row0_px
        return np.column_stack([col, row]).astype(np.int64)


# ---------------------------------------------------------------------------------------------
def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v)


def _look_frame(eye, target, up) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    fwd = _unit(np.asarray(target, np.float64) - np.asarray(eye, np.float64))
    side = np.cross(fwd, np.asarray(up, np.float64))
    if np.linalg.norm(side) < 1e-9:
        # Looking along `up` (straight down, say): take north as the image's up instead.
        alt = np.array([0.0, 1.0, 0.0]) if abs(fwd[1]) < 0.9 else np.array([1.0, 0.0, 0.0])
        side = np.cross(fwd, alt)
    right = _unit(side)
    return right, np.cross(right, fwd), fwd


def scene_box(scene, t_days: float | None = None) -> np.ndarray:
    """(2, 3) float64 render-space bounding box of the triangles (present at ``t_days``).

    Raises
    ------
    UsageError
        When no triangle is present.
    """
    from cityshade.geometry.bounds import vertex_box
    from cityshade.geometry.scene import Scene

    tris = np.asarray(scene.triangles)
    if t_days is not None:
        t = float(t_days)
        present = (np.asarray(scene.tri_t_begin_days) <= t) & (t < np.asarray(scene.tri_t_end_days))
        tris = tris[present]
    if tris.shape[0] == 0:
        when = "" if t_days is None else f" at t = {t_days} days"
        raise UsageError(f"the scene has no triangles{when} to frame")
    if t_days is None and isinstance(scene, Scene):   # asked for by extent, margin, camera
        return scene.derived("box_m", lambda: vertex_box(np.ascontiguousarray(tris),
                                                         np.asarray(scene.vertices)))
    return vertex_box(np.ascontiguousarray(tris), np.asarray(scene.vertices))


def _near_far(eye, fwd, box) -> tuple[float, float]:
    corners = np.array([[box[i, 0], box[j, 1], box[k, 2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    z = (corners - eye) @ fwd
    dist = np.linalg.norm(corners - eye, axis=1)
    far = float(dist.max()) * 1.01 + 1.0   # 1 % + 1 m: the farthest corner is never clipped
    if z.min() > 0.0:
        near = 0.5 * float(z.min())          # the whole box lies beyond: clip nothing
    else:
        near = far * NEAR_FAR_RATIO
    return max(near, MIN_NEAR_M), far


def perspective(eye, target, up=(0.0, 0.0, 1.0), vfov_deg: float = 45.0, width_px: int = 1280,
                height_px: int = 720, *, near_m: float | None = None, far_m: float | None = None,
                scene=None, box=None, name: str = "") -> Camera:
    """A perspective camera at render-space ``eye`` looking at ``target``.

    Parameters
    ----------
    eye, target : (3,) float
        Render-space metres.
    up : (3,) float
        Approximate up direction; north is used when it is parallel to the view.
    vfov_deg : float
        Vertical field of view, degrees.
    near_m, far_m : float, optional
        View-depth range; by default derived from ``box`` (or the scene's triangles) so that
        nothing in front of the eye is clipped.
    scene, box : optional
        Where the automatic near/far come from (``box`` is (2, 3) render-space min/max).
    """
    eye = np.asarray(eye, np.float64)
    target = np.asarray(target, np.float64)
    if near_m is None or far_m is None:
        if box is None:
            if scene is None:
                raise UsageError("perspective() needs near_m and far_m, or a scene or box")
            box = scene_box(scene)
        if not (np.isfinite(eye).all() and np.isfinite(target).all()) or \
                np.array_equal(eye, target):
            raise UsageError("camera eye and target must be distinct finite points")
        _, _, fwd = _look_frame(eye, target, up)
        auto_near, auto_far = _near_far(eye, fwd, np.asarray(box, np.float64))
        near_m = auto_near if near_m is None else near_m
        far_m = auto_far if far_m is None else far_m
    return Camera(kind="perspective", width_px=int(width_px), height_px=int(height_px),
                  eye_m=eye, target_m=target, up=np.asarray(up, np.float64),
                  vfov_deg=float(vfov_deg), near_m=float(near_m), far_m=float(far_m), name=name)


def fitted(box, azimuth_deg: float, elevation_deg: float, width_px: int, height_px: int,
           vfov_deg: float = 40.0, zoom: float = 1.0, name: str = "") -> Camera:
    """A perspective camera that frames the box ``(2, 3)`` from a direction.

    Parameters
    ----------
    azimuth_deg : float
        Where the camera stands, seen from the box centre: degrees clockwise from grid north
        (render +y); 225 is south-west.
    elevation_deg : float
        How far the camera looks down, degrees (0 horizontal, 90 straight down).
    zoom : float
        1 fits the whole box (``FIT_FILL`` of the image); 2 goes twice as close.
    """
    box = np.asarray(box, np.float64)
    if not (np.isfinite(azimuth_deg) and -90.0 < elevation_deg <= 90.0 and zoom > 0.0):
        raise UsageError(f"bad camera placement: azimuth {azimuth_deg}, elevation "
                         f"{elevation_deg}, zoom {zoom}")
    a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
    to_eye = np.array([math.sin(a) * math.cos(e), math.cos(a) * math.cos(e), math.sin(e)])
    centre = box.mean(axis=0)
    right, up, fwd = _look_frame(centre + to_eye, centre, (0.0, 0.0, 1.0))
    corners = np.array([[box[i, 0], box[j, 1], box[k, 2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)]) - centre
    ty = math.tan(math.radians(vfov_deg) / 2.0) * FIT_FILL
    tx = ty * width_px / height_px
    x, y, z = corners @ right, corners @ up, corners @ fwd
    # Distance from the centre at which every corner projects inside the image.
    dist = float(max(np.max(np.abs(x) / tx - z), np.max(np.abs(y) / ty - z)))
    size = float(np.linalg.norm(box[1] - box[0]))
    dist = max(dist, 0.01 * size, 1.0) / zoom
    eye = centre - dist * fwd
    return perspective(eye, centre, (0.0, 0.0, 1.0), vfov_deg, width_px, height_px, box=box,
                       name=name)


def overview(scene, width_px: int = 1280, height_px: int = 720, *, t_days: float | None = None,
             vfov_deg: float = 40.0) -> Camera:
    """The whole model seen from the south-west, 35° down, fitted to its triangles' box.

    ``t_days`` fits the box of the triangles present at that city time (default: all).
    """
    return fitted(scene_box(scene, t_days), 225.0, 35.0, width_px, height_px, vfov_deg,
                  name="overview")


def nice_ceil(x: float) -> float:
    """Smallest of 1, 2, 2.5, 5 × 10^k that is >= x (pixel sizes a GIS user would choose)."""
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10.0 ** k >= x * (1 - 1e-12):
            return m * 10.0 ** k
    return 10.0 ** (k + 1)


#: The default map view's margin around the model's box, in model heights: shadows that fall
#: past the box's edge stay in the picture for a sun at least atan(1/2) = 26.6° high.
DEFAULT_MAP_MARGIN_HEIGHTS = 2.0


def default_map_margin_m(scene) -> float:
    """The margin of a whole-model map view: :data:`DEFAULT_MAP_MARGIN_HEIGHTS` times the
    height of the model's box (the longest shadow kept, in metres), at most 0.9 of the ground
    plane's reach (:data:`cityshade.geometry.ground.GROUND_MARGIN_REL` of the box's
    horizontal diagonal): past it a map would show no surface, not a shadow."""
    from cityshade.geometry.ground import GROUND_MARGIN_REL

    box3 = scene_box(scene)
    diagonal = math.hypot(float(box3[1, 0] - box3[0, 0]), float(box3[1, 1] - box3[0, 1]))
    # 0.9: the map's extent is rounded up to whole pixels, which must stay on the plane too.
    return min(DEFAULT_MAP_MARGIN_HEIGHTS * float(box3[1, 2] - box3[0, 2]),
               0.9 * GROUND_MARGIN_REL * diagonal)


def map_extent(scene, bbox_crs=None, margin_m: float = 0.0) -> tuple[float, float, float, float]:
    """Render-space ``(x0, y0, x1, y1)`` of a map view (:func:`map_view`'s ``bbox``): the box
    ``bbox_crs`` given in model CRS coordinates (default: the model's box), grown by
    ``margin_m`` on every side. Only the receivers are cropped: every technique still takes
    its casters from the whole model.

    Raises
    ------
    UsageError
        A box with x0 >= x1 or y0 >= y1, not finite, or a negative margin.
    """
    margin = float(margin_m)
    if not (math.isfinite(margin) and margin >= 0.0):
        raise UsageError(f"the map margin must be a number of metres >= 0, not {margin_m}")
    if bbox_crs is None:
        box3 = scene_box(scene)
        x0, y0, x1, y1 = box3[0, 0], box3[0, 1], box3[1, 0], box3[1, 1]
    else:
        x0, y0, x1, y1 = (float(v) for v in bbox_crs)
        if not (np.isfinite([x0, y0, x1, y1]).all() and x1 > x0 and y1 > y0):
            raise UsageError(f"the map box must be x0,y0,x1,y1 with x0 < x1 and y0 < y1, not "
                             f"{x0:.10g},{y0:.10g},{x1:.10g},{y1:.10g}")
        ox, oy = float(scene.origin_m[0]), float(scene.origin_m[1])
        x0, y0, x1, y1 = x0 - ox, y0 - oy, x1 - ox, y1 - oy
    return (float(x0) - margin, float(y0) - margin, float(x1) + margin, float(y1) + margin)


def map_view(scene, pixel_size_m: float | None = None, bbox=None,
             max_px: int = DEFAULT_MAX_MAP_PX) -> Camera:
    """A georeferenced top-down orthographic map of the model (north up).

    Parameters
    ----------
    scene : Scene
        Its triangles' box gives the default extent and the height of the camera plane.
    pixel_size_m : float, optional
        Metres per pixel; default: the "nice" size (1, 2, 2.5, 5 × 10^k) that fits the
        longer side of the extent into ``DEFAULT_MAP_SIDE_PX`` pixels.
    bbox : (x0, y0, x1, y1), optional
        Render-space extent; default the model's box.
    max_px : int
        Largest allowed image side.

    The grid corners are aligned to multiples of the pixel size in the CRS, so the map covers
    the extent with at most one extra pixel on each side.
    """
    box3 = scene_box(scene)
    if bbox is None:
        x0, y0, x1, y1 = box3[0, 0], box3[0, 1], box3[1, 0], box3[1, 1]
    else:
        try:
            x0, y0, x1, y1 = (float(v) for v in bbox)
        except (TypeError, ValueError):
            raise UsageError("map bbox must be four numbers x0, y0, x1, y1") from None
        if not (np.isfinite([x0, y0, x1, y1]).all() and x1 > x0 and y1 > y0):
            raise UsageError(f"map bbox must have x0 < x1 and y0 < y1, not {bbox}")
    if pixel_size_m is None:
        pixel_size_m = nice_ceil(max(x1 - x0, y1 - y0, 1e-3) / DEFAULT_MAP_SIDE_PX)
    px = float(pixel_size_m)
    if not (math.isfinite(px) and px > 0.0):
        raise UsageError(f"map pixel size must be > 0 metres, not {pixel_size_m}")
    origin = np.asarray(scene.origin_m, np.float64)
    x_ul = math.floor((origin[0] + x0) / px) * px
    y_ul = math.ceil((origin[1] + y1) / px) * px
    width = max(1, math.ceil((origin[0] + x1 - x_ul) / px))
    height = max(1, math.ceil((y_ul - (origin[1] + y0)) / px))
    if max(width, height) > max_px:
        raise UsageError(f"a map of {width}x{height} pixels exceeds the limit of {max_px} per "
                         f"side; choose a pixel size of at least "
                         f"{max(x1 - x0, y1 - y0) / max_px:.3g} m")
    size = float(np.max(box3[1] - box3[0]))
    eye_z = box3[1, 2] + MAP_EYE_MARGIN_REL * size + 1.0
    far = eye_z - box3[0, 2] + MAP_EYE_MARGIN_REL * size + 1.0
    x_left = x_ul - origin[0]
    y_top = y_ul - origin[1]
    centre = np.array([x_left + 0.5 * width * px, y_top - 0.5 * height * px])
    return Camera(kind="map", width_px=int(width), height_px=int(height),
                  eye_m=np.array([centre[0], centre[1], eye_z]),
                  target_m=np.array([centre[0], centre[1], box3[0, 2]]),
                  up=np.array([0.0, 1.0, 0.0]), vfov_deg=0.0, near_m=0.0, far_m=float(far),
                  pixel_size_m=px, x_left_m=float(x_left), y_top_m=float(y_top), name="map")


# ---------------------------------------------------------------------------------------------
def preset(name: str, scene, width_px: int = 1280, height_px: int = 720, *,
           path: str | Path | None = None, extra: str | Path | None = None,
           t_days: float | None = None) -> Camera:
    """The named preset of the shipped presets (or of ``path``), or of the user's preset
    file ``extra`` (``--cameras``; its presets win), fitted to the scene's box.

    Raises
    ------
    UnknownPresetError
        When ``name`` is not a preset; the message lists the valid names.
    """
    presets = load_presets(path)
    if extra is not None:
        presets.update(load_presets(extra))
    if name not in presets:
        raise UnknownPresetError(f"unknown camera {name!r}; valid: map, "
                                 f"{', '.join(sorted(presets))}")
    p = presets[name]
    return fitted(scene_box(scene, t_days), p["azimuth_deg"], p["elevation_deg"], width_px,
                  height_px, p["vfov_deg"], p["zoom"], name=name)
