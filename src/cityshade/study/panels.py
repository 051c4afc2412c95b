"""The panels of a shadow study: the shadow masks of two city states at each sun, and what each
pixel shows (existing shadow, new shadow, a new building...).

A state's camera pass is made once (:func:`cityshade.frame.pipeline.camera_pass`: the city does
not change during a study); every sun is a :func:`cityshade.frame.pipeline.shadow_pass` on it
and the mask is :func:`cityshade.imageio.mask_from_lit` of its lit fraction, so a panel's
masks are the pixels of ``cityshade render --camera map --mask`` at that time, bit for bit.

What a pixel shows (:func:`categories`) depends on whether its surface is the same in both
states (the same object seen; the ground plane counts as one surface): there the two masks
say existing shadow (shadow in both), new shadow (shadow after, sun before), shadow no longer
cast (shadow before, sun after) or sun; elsewhere a new building stands (drawn in its own
colour) or an old one is gone (the state after is drawn).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from datetime import date, datetime
from typing import Any

import numpy as np

__all__ = [
    "LABELS",
    "NEW_BUILDING",
    "NEW_BUILDING_SHADOW",
    "NEW_SHADOW",
    "NO_SURFACE",
    "PALETTE",
    "ROOF_SHADOW",
    "ROOF_SUN",
    "SHADOW",
    "SHADOW_GONE",
    "SUN",
    "Panel",
    "StudyView",
    "categories",
    "make_panel",
    "panel_rgb",
    "study_camera",
    "study_view",
]

# What a pixel of a panel shows (indices into PALETTE and LABELS).
NO_SURFACE, SUN, ROOF_SUN, SHADOW, ROOF_SHADOW, NEW_SHADOW, SHADOW_GONE, NEW_BUILDING, \
    NEW_BUILDING_SHADOW = range(9)
#: sRGB colours of the categories: paper-white ground, warm grey roofs, neutral grey shadow
#: (darker on roofs, so buildings read in shadow), orange new shadow (the usual colour of
#: planning shadow studies), green where a shadow is no longer cast, blue new buildings.
PALETTE = np.array([
    (255, 255, 255), (250, 249, 244), (222, 215, 202), (160, 160, 160), (122, 122, 122),
    (238, 112, 24), (126, 196, 128), (120, 150, 212), (72, 96, 152)], np.uint8)
LABELS = ("no surface", "sun", "roof in sun", "existing shadow", "existing shadow on a roof",
          "new shadow", "shadow no longer cast", "new building", "new building in shadow")
#: Surface classes that are open ground, not a building or structure: drawn as paper, not
#: outlined.
_GROUND_CLASSES = ("terrain", "traffic", "auxiliary_traffic", "water", "vegetation",
                   "landuse", "marking")


def study_camera(scene, pixel_size_m: float | None, side_px: int, extent=None):
    """The study's map view of ``scene`` (the state after: a proposal lies inside it) or of
    ``extent`` (x0, y0, x1, y1 in model CRS metres), at ``pixel_size_m`` or the "nice" size
    that fits the longer side into ``side_px``."""
    from cityshade.raster.camera import map_view, nice_ceil, scene_box

    bbox = None
    if extent is not None:
        o = scene.origin_m
        bbox = (extent[0] - o[0], extent[1] - o[1], extent[2] - o[0], extent[3] - o[1])
        x0, y0, x1, y1 = bbox
    else:
        box = scene_box(scene)
        x0, y0, x1, y1 = box[0, 0], box[0, 1], box[1, 0], box[1, 1]
    if pixel_size_m is None:
        pixel_size_m = nice_ceil(max(float(x1 - x0), float(y1 - y0), 1e-3) / side_px)
    return map_view(scene, pixel_size_m, bbox=bbox)


@dataclass
class StudyView:
    """The sun-independent part of a study: both states' camera passes on one camera and
    what stands where.

    Attributes
    ----------
    before, after : cityshade.frame.pipeline.CameraPass
    same : (H, W) bool
        The pixel shows the same surface in both states.
    building_after : (H, W) bool
        A building (or other structure) is seen there after.
    new_building : (H, W) bool
        A building seen after that was not seen there before.
    """

    before: Any
    after: Any
    same: np.ndarray
    building_after: np.ndarray
    new_building: np.ndarray

    @property
    def camera(self):
        return self.after.camera


def _buildings(cp) -> np.ndarray:
    """(H, W) bool: a surface of a building or structure (not open ground, not the plane)."""
    from cityshade.citygml.namespaces import SURFACE_CODE

    s = cp.surfaces
    ground = np.isin(np.asarray(s.cls), [SURFACE_CODE[c] for c in _GROUND_CLASSES])
    return np.asarray(s.valid, bool) & (np.asarray(cp.gbuffer.prim_id) >= 0) & ~ground


def study_view(scene_before, t_before_days: float, scene_after, t_after_days: float, camera,
               ground: str | None = "auto") -> StudyView:
    """Both states' camera passes (as ``render`` makes them) and the per-pixel comparison.
    Object ids are the same in both scenes (a proposal's objects come after the model's:
    :func:`cityshade.planning.compare.merge_scenes`)."""
    from cityshade.frame.pipeline import camera_pass

    before = camera_pass(scene_before, camera, t_before_days, ground=ground)
    after = camera_pass(scene_after, camera, t_after_days, ground=ground)
    vb, va = before.valid, after.valid
    same = vb & va & (np.asarray(before.surfaces.obj_id) == np.asarray(after.surfaces.obj_id))
    b_after = _buildings(after)
    return StudyView(before, after, same, b_after, b_after & ~same)


def categories(before_mask: np.ndarray, after_mask: np.ndarray, view: StudyView) -> np.ndarray:
    """(H, W) uint8 category of every pixel (:data:`LABELS`) from the two shadow masks
    (255 sun, 0 shadow, 128 no surface)."""
    from cityshade.imageio import MASK_LIT, MASK_SHADOW

    b_shadow = np.asarray(before_mask) == MASK_SHADOW
    a_shadow = np.asarray(after_mask) == MASK_SHADOW
    a_lit = np.asarray(after_mask) == MASK_LIT
    b_lit = np.asarray(before_mask) == MASK_LIT
    roof = view.building_after
    out = np.full(a_shadow.shape, NO_SURFACE, np.uint8)
    out[a_lit] = SUN
    out[a_lit & roof] = ROOF_SUN
    out[a_shadow] = SHADOW
    out[a_shadow & roof] = ROOF_SHADOW
    same = view.same
    out[same & a_shadow & b_lit] = NEW_SHADOW
    out[same & a_lit & b_shadow] = SHADOW_GONE
    out[view.new_building & a_lit] = NEW_BUILDING
    out[view.new_building & a_shadow] = NEW_BUILDING_SHADOW
    return out


def panel_rgb(cats: np.ndarray) -> np.ndarray:
    """(H, W, 3) uint8 picture of a panel's categories (:data:`PALETTE`)."""
    return PALETTE[np.asarray(cats)]


@dataclass
class Panel:
    """One time of one day: the sun, both masks, the categories and the areas.

    Attributes
    ----------
    day : datetime.date
    local : datetime.datetime
        The panel's local time (aware).
    sun : cityshade.geo.sun.SunPosition
    before, after : (H, W) uint8
        Shadow masks, as ``render --mask`` writes them.
    cats : (H, W) uint8
        :func:`categories`.
    area_m2 : dict
        Plan area (seen from above) in shadow ``before``, ``after``, and of ``new`` shadow
        and shadow ``gone``.
    """

    day: date
    local: datetime
    sun: Any
    before: np.ndarray
    after: np.ndarray
    cats: np.ndarray
    area_m2: dict = field(default_factory=dict)

    @property
    def sun_up(self) -> bool:
        return bool(self.sun.above_horizon)


def make_panel(view: StudyView, day: date, local: datetime, sun, technique, settings=None
               ) -> Panel:
    """Both states' shadow passes for ``sun`` (``technique``: a registry name or its
    :func:`cityshade.shadows.get_technique` instance) and the panel they make."""
    from cityshade.frame.pipeline import shadow_pass
    from cityshade.imageio import MASK_SHADOW, mask_from_lit

    masks = [mask_from_lit(shadow_pass(cp, sun, technique, settings).lit, cp.surfaces.valid)
             for cp in (view.before, view.after)]
    cats = categories(masks[0], masks[1], view)
    px_m2 = float(view.camera.pixel_size_m) ** 2
    area = {"before": int(np.count_nonzero(masks[0] == MASK_SHADOW)) * px_m2,
            "after": int(np.count_nonzero(masks[1] == MASK_SHADOW)) * px_m2,
            "new": int(np.count_nonzero(cats == NEW_SHADOW)) * px_m2,
            "gone": int(np.count_nonzero(cats == SHADOW_GONE)) * px_m2}
    return Panel(day, local, sun, masks[0], masks[1], cats, area)
