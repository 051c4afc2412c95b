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

Trees (docs/DESIGN.md §21) are drawn apart: a crown seen from above in green, the ground or
roof under the shade of crowns only (part of the sun through the leaves: a lit fraction
strictly between 0 and 1, which the exact techniques of a study give nowhere else) as tree
shade, and as new tree shade where that surface had the whole sun before. The masks of a
scene with trees are grey levels, as ``render --mask`` writes them
(:func:`cityshade.imageio.grey_mask_from_lit`); sun and shadow are still told apart at half
the sun, as sun-hours count them.
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
    "TREE_CROWN",
    "TREE_SHADE",
    "NEW_TREE_SHADE",
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
    NEW_BUILDING_SHADOW, TREE_CROWN, TREE_SHADE, NEW_TREE_SHADE = range(12)
#: sRGB colours of the categories: paper-white ground, warm grey roofs, neutral grey shadow
#: (darker on roofs, so buildings read in shadow), orange new shadow (the usual colour of
#: planning shadow studies), green where a shadow is no longer cast, blue new buildings;
#: dark green crowns, a greyish sage for the partial shade of trees, a light orange for new
#: tree shade.
PALETTE = np.array([
    (255, 255, 255), (250, 249, 244), (222, 215, 202), (160, 160, 160), (122, 122, 122),
    (238, 112, 24), (126, 196, 128), (120, 150, 212), (72, 96, 152), (62, 118, 66),
    (184, 196, 170), (248, 190, 128)], np.uint8)
LABELS = ("no surface", "sun", "roof in sun", "existing shadow", "existing shadow on a roof",
          "new shadow", "shadow no longer cast", "new building", "new building in shadow",
          "tree crown", "tree shade (sun partly through leaves)",
          "new tree shade (full sun before)")
#: The lit fraction from which a pixel counts as in sun (:func:`cityshade.imageio.mask_from_lit`).
LIT_THRESHOLD = 0.5
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
    crown_after : (H, W) bool
        A tree crown is seen there after.
    trees : bool
        Either state has tree crowns: the masks are grey levels and tree shade is drawn.
    """

    before: Any
    after: Any
    same: np.ndarray
    building_after: np.ndarray
    new_building: np.ndarray
    crown_after: np.ndarray | None = None
    trees: bool = False

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
    """Both states' camera passes (as ``render`` makes them; the ground plane at the height
    ``ground`` gives for ``scene_before``) and the per-pixel comparison.
    Object ids are the same in both scenes (a proposal's objects come after the model's:
    :func:`cityshade.planning.compare.merge_scenes`)."""
    from cityshade.citygml.namespaces import SURFACE_CODE
    from cityshade.frame.pipeline import camera_pass
    from cityshade.geometry.vegetation import scene_vegetation

    if ground is not None:
        from cityshade.geometry.ground import ground_height_m

        # One plane for both states, as compare's: a proposal standing lower than the model's
        # typical ground must not move it (6 cm moved every shadow edge on the ground).
        ground = repr(ground_height_m(scene_before, ground) + float(scene_before.origin_m[2]))
    before = camera_pass(scene_before, camera, t_before_days, ground=ground)
    after = camera_pass(scene_after, camera, t_after_days, ground=ground)
    vb, va = before.valid, after.valid
    same = vb & va & (np.asarray(before.surfaces.obj_id) == np.asarray(after.surfaces.obj_id))
    b_after = _buildings(after)
    trees = any(scene_vegetation(s) is not None for s in (scene_before, scene_after))
    crown = (np.asarray(after.surfaces.valid, bool) & (np.asarray(after.gbuffer.prim_id) >= 0)
             & (np.asarray(after.surfaces.cls) == SURFACE_CODE["vegetation"]))
    return StudyView(before, after, same, b_after, b_after & ~same, crown & trees, trees)


def categories(before_mask: np.ndarray, after_mask: np.ndarray, view: StudyView,
               before_lit: np.ndarray | None = None, after_lit: np.ndarray | None = None
               ) -> np.ndarray:
    """(H, W) uint8 category of every pixel (:data:`LABELS`) from the two shadow masks
    (255 sun, 0 shadow, 128 no surface; grey levels between: sun through crowns) and, on a
    scene with trees, the lit fractions they were made of (``before_lit``, ``after_lit``)."""
    from cityshade.imageio import MASK_NODATA

    b_valid = np.asarray(before_mask) != MASK_NODATA
    a_valid = np.asarray(after_mask) != MASK_NODATA
    # Half the sun or more is sun, as sun-hours and mask_from_lit count it (a grey mask's
    # levels are rounded: the fractions decide when given).
    b_lit = b_valid & (np.asarray(before_mask) > MASK_NODATA if before_lit is None
                       else np.asarray(before_lit) >= LIT_THRESHOLD)
    a_lit = a_valid & (np.asarray(after_mask) > MASK_NODATA if after_lit is None
                       else np.asarray(after_lit) >= LIT_THRESHOLD)
    b_shadow = b_valid & ~b_lit
    a_shadow = a_valid & ~a_lit
    roof = view.building_after
    out = np.full(a_shadow.shape, NO_SURFACE, np.uint8)
    out[a_lit] = SUN
    out[a_lit & roof] = ROOF_SUN
    out[a_shadow] = SHADOW
    out[a_shadow & roof] = ROOF_SHADOW
    same = view.same
    out[same & a_shadow & b_lit] = NEW_SHADOW
    out[same & a_lit & b_shadow] = SHADOW_GONE
    if after_lit is not None:
        la = np.asarray(after_lit)
        partial = a_valid & (la > 0.0) & (la < 1.0)
        out[partial] = TREE_SHADE
        if before_lit is not None:
            out[same & partial & (np.asarray(before_lit) == 1.0)] = NEW_TREE_SHADE
        if view.crown_after is not None:
            out[view.crown_after] = TREE_CROWN
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
        Plan area (seen from above) in shadow ``before``, ``after`` (less than half the sun),
        of ``new`` shadow and shadow ``gone``, in ``tree_shade`` after (part of the sun
        through crowns) and of it ``new_tree_shade``.
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
    from cityshade.imageio import MASK_SHADOW, grey_mask_from_lit, mask_from_lit

    lits = [shadow_pass(cp, sun, technique, settings).lit for cp in (view.before, view.after)]
    # The pixels of ``render --mask`` (cityshade.frame.render.shadow_mask): grey with trees.
    to_mask = grey_mask_from_lit if view.trees else mask_from_lit
    masks = [to_mask(lit, cp.surfaces.valid) for lit, cp in zip(lits, (view.before, view.after))]
    cats = categories(masks[0], masks[1], view, *(lits if view.trees else (None, None)))
    px_m2 = float(view.camera.pixel_size_m) ** 2
    shadow = [np.count_nonzero(c == MASK_SHADOW) if not view.trees else
              np.count_nonzero(cp.surfaces.valid & (lit < LIT_THRESHOLD))
              for c, lit, cp in zip(masks, lits, (view.before, view.after))]
    area = {"before": int(shadow[0]) * px_m2, "after": int(shadow[1]) * px_m2,
            "new": int(np.count_nonzero(cats == NEW_SHADOW)) * px_m2,
            "gone": int(np.count_nonzero(cats == SHADOW_GONE)) * px_m2,
            "tree_shade": int(np.count_nonzero((cats == TREE_SHADE)
                                               | (cats == NEW_TREE_SHADE))) * px_m2,
            "new_tree_shade": int(np.count_nonzero(cats == NEW_TREE_SHADE)) * px_m2}
    return Panel(day, local, sun, masks[0], masks[1], cats, area)
