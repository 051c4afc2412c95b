"""Shading (cityshade.frame.shading): Lambert + sky ambient, albedo sources, back faces, sky, sRGB."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from cityshade.citygml.namespaces import SURFACE_CLASSES, SURFACE_CODE
from cityshade.frame.shading import DEFAULT_PALETTE_SRGB8, ShadingSettings, shade, to_srgb8
from cityshade.errors import ShadingError

REPO = Path(__file__).parents[2]
FACADE = REPO / "sample_data" / "sample_city_facade.png"


def _decode(code8: float) -> float:
    """sRGB 8-bit code → linear, straight from IEC 61966-2-1."""
    c = code8 / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


@dataclass
class FakeSurfaces:
    """The fields of cityshade.raster.gbuffer.Surfaces, filled by hand."""

    valid: np.ndarray
    normal: np.ndarray
    position_m: np.ndarray
    material: np.ndarray
    texture: np.ndarray
    uv: np.ndarray
    cls: np.ndarray
    obj_id: np.ndarray
    prim_id: np.ndarray | None = None


def _surfaces(h, w, *, normal=(0.0, 0.0, 1.0), cls="roof", material=-1, texture=-1):
    return FakeSurfaces(
        valid=np.ones((h, w), bool),
        normal=np.broadcast_to(np.asarray(normal, np.float32), (h, w, 3)).copy(),
        position_m=np.zeros((h, w, 3)),
        material=np.full((h, w), material, np.int32),
        texture=np.full((h, w), texture, np.int32),
        uv=np.zeros((h, w, 2), np.float32),
        cls=np.full((h, w), SURFACE_CODE[cls], np.uint8),
        obj_id=np.zeros((h, w), np.int32))


@dataclass
class FakeScene:
    materials: list = field(default_factory=list)
    textures: list = field(default_factory=list)


@dataclass
class FakeCamera:
    kind: str
    eye_m: np.ndarray
    target_m: np.ndarray
    #: The pixel rays of a 2x2 picture, ``xs[c] right + ys[r] up + forward`` as a real camera
    #: makes them: rays (0, 1, 0), (0, 0, 1) on the top row, (0, 0.6, -0.8) bottom left.
    sky_frame: tuple = ((0.0, -1.0, 1.0), (0.0, -0.4, -0.8), (0.0, 1.0, 0.0))

    def screen_coordinates(self):
        return np.array([0.0, 1.0]), np.array([0.0, 1.0])

    def frame(self):
        return tuple(np.array(v) for v in self.sky_frame)


MAP = FakeCamera("map", np.array([0.0, 0.0, 100.0]), np.array([0.0, 0.0, 0.0]))
SETTINGS = ShadingSettings()


def _ambient(nz: float) -> np.ndarray:
    up = 0.5 * (1.0 + nz)
    return (np.array(SETTINGS.ground_ambient_rgb)
            + (np.array(SETTINGS.sky_ambient_rgb) - np.array(SETTINGS.ground_ambient_rgb)) * up)


def test_flat_roof_in_sun_and_shadow_differs_by_the_lambert_term():
    sun = np.array([0.0, -0.6, 0.8])           # 53.13° elevation from the south: N·L = 0.8
    surf = _surfaces(2, 3)
    lit = shade(FakeScene(), surf, MAP, np.ones((2, 3), np.float32), sun)
    dark = shade(FakeScene(), surf, MAP, np.zeros((2, 3), np.float32), sun)
    albedo = np.array([_decode(c) for c in DEFAULT_PALETTE_SRGB8["roof"]])
    np.testing.assert_allclose(lit - dark, np.broadcast_to(
        albedo * np.array(SETTINGS.sun_rgb) * 0.8, (2, 3, 3)), rtol=1e-5)
    np.testing.assert_allclose(dark, np.broadcast_to(albedo * _ambient(1.0), (2, 3, 3)),
                               rtol=1e-5)
    # Half lit is halfway; the sun direction need not be unit length.
    half = shade(FakeScene(), surf, MAP, np.full((2, 3), 0.5, np.float32), sun * 7.0)
    np.testing.assert_allclose(half, 0.5 * (lit + dark), rtol=1e-5)


def test_surfaces_facing_away_from_the_sun_get_ambient_only():
    sun = np.array([0.0, -0.6, 0.8])
    wall = _surfaces(1, 1, normal=(0.0, 1.0, 0.0), cls="wall")  # faces north, sun in the south
    wall.position_m[:] = (0.0, 10.0, 0.0)
    camera = FakeCamera("perspective", np.array([0.0, 50.0, 10.0]), np.zeros(3))
    rgb = shade(FakeScene(), wall, camera, np.ones((1, 1), np.float32), sun)
    albedo = np.array([_decode(c) for c in DEFAULT_PALETTE_SRGB8["wall"]])
    np.testing.assert_allclose(rgb[0, 0], albedo * _ambient(0.0), rtol=1e-5)


def test_back_faces_are_shaded_with_the_flipped_normal():
    sun = np.array([0.3, -0.6, 0.5])
    camera = FakeCamera("perspective", np.array([0.0, -50.0, 5.0]), np.zeros(3))
    front = _surfaces(1, 1, normal=(0.0, -1.0, 0.0), cls="wall")   # faces the camera
    back = _surfaces(1, 1, normal=(0.0, 1.0, 0.0), cls="wall")     # same wall, wound inward
    ones = np.ones((1, 1), np.float32)
    np.testing.assert_array_equal(shade(FakeScene(), back, camera, ones, sun),
                                  shade(FakeScene(), front, camera, ones, sun))
    # A roof seen from below (map camera looks down, so a downward normal is a back face).
    under = _surfaces(1, 1, normal=(0.0, 0.0, -1.0))
    over = _surfaces(1, 1, normal=(0.0, 0.0, 1.0))
    np.testing.assert_array_equal(shade(FakeScene(), under, MAP, ones, sun),
                                  shade(FakeScene(), over, MAP, ones, sun))


def test_albedo_priority_palette_material_texture():
    sun = np.array([0.0, 0.0, 1.0])
    ones = np.ones((1, 4), np.float32)
    scene = FakeScene(materials=[{"diffuse": [0.2, 0.4, 0.6]}, {"diffuse": None}],
                      textures=[{"path": str(FACADE), "wrap_mode": "wrap"}])
    surf = _surfaces(1, 4, cls="traffic")
    surf.material[0] = (-1, 0, 1, 0)       # none, a material, an unusable one, material+texture
    surf.texture[0, 3] = 0
    surf.uv[0, 3] = (0.37, 0.61)
    rgb = shade(scene, surf, MAP, ones, sun)
    light = np.array(SETTINGS.sun_rgb) + _ambient(1.0)
    road = np.array([_decode(c) for c in DEFAULT_PALETTE_SRGB8["traffic"]])
    np.testing.assert_allclose(rgb[0, 0], road * light, rtol=1e-5)      # default palette
    np.testing.assert_allclose(rgb[0, 2], road * light, rtol=1e-5)      # unusable material
    material = np.array([_decode(255 * c) for c in (0.2, 0.4, 0.6)])
    np.testing.assert_allclose(rgb[0, 1], material * light, rtol=1e-5)  # X3DMaterial
    # The textured pixel is neither the palette nor the material colour.
    assert np.abs(rgb[0, 3] - rgb[0, 1]).max() > 0.05
    assert np.abs(rgb[0, 3] - rgb[0, 0]).max() > 0.05
    # Textures switched off: the material colour again.
    plain = shade(scene, surf, MAP, ones, sun, settings=ShadingSettings(textures=False))
    np.testing.assert_allclose(plain[0, 3], material * light, rtol=1e-5)


def test_a_missing_texture_falls_back_to_the_material_with_a_counted_warning(tmp_path):
    scene = FakeScene(materials=[{"diffuse": [0.5, 0.5, 0.5]}],
                      textures=[{"path": str(tmp_path / "gone.jpg"), "wrap_mode": "none"}])
    surf = _surfaces(2, 2, material=0, texture=0)
    report = {}
    rgb = shade(scene, surf, MAP, np.ones((2, 2), np.float32), np.array([0, 0, 1.0]),
                report=report)
    want = _decode(127.5) * (np.array(SETTINGS.sun_rgb) + _ambient(1.0))
    np.testing.assert_allclose(rgb, np.broadcast_to(want, (2, 2, 3)), rtol=1e-5)
    assert report["texture_counts"]["failed"] == 1
    assert "gone.jpg" in report["texture_warnings"][0]


def test_every_surface_class_has_a_distinct_default_colour():
    assert list(DEFAULT_PALETTE_SRGB8) == list(SURFACE_CLASSES)
    key = ("roof", "wall", "terrain", "traffic", "water", "vegetation")
    colours = {tuple(DEFAULT_PALETTE_SRGB8[k]) for k in key}
    assert len(colours) == len(key)
    r, g, b = DEFAULT_PALETTE_SRGB8["water"]
    assert b > r and b > g
    r, g, b = DEFAULT_PALETTE_SRGB8["vegetation"]
    assert g > r and g > b
    r, g, b = DEFAULT_PALETTE_SRGB8["roof"]
    assert r > g > b


def test_background_sky_for_perspective_nodata_for_maps():
    camera = FakeCamera("perspective", np.array([0.0, 0.0, 10.0]), np.array([0.0, 1.0, 10.0]))
    surf = _surfaces(2, 2)
    surf.valid[:] = False
    surf.valid[1, 1] = True
    lit = np.zeros((2, 2), np.float32)
    sun = np.array([0.0, 0.0, 1.0])
    rgb = shade(FakeScene(), surf, camera, lit, sun)
    np.testing.assert_allclose(rgb[0, 0], SETTINGS.sky_horizon_rgb, rtol=1e-6)
    np.testing.assert_allclose(rgb[0, 1], SETTINGS.sky_zenith_rgb, rtol=1e-6)
    np.testing.assert_allclose(rgb[1, 0], SETTINGS.sky_below_rgb, rtol=1e-6)
    assert np.isfinite(rgb).all()
    no_sky = shade(FakeScene(), surf, camera, lit, sun, sky=False)
    assert np.isnan(no_sky[~surf.valid]).all() and np.isfinite(no_sky[1, 1]).all()
    as_map = shade(FakeScene(), surf, MAP, lit, sun)
    assert np.isnan(as_map[~surf.valid]).all()
    np.testing.assert_array_equal(to_srgb8(as_map)[0, 0], [0, 0, 0])


def test_srgb_encode_known_values():
    rgb = np.array([[[0.5, 0.0, 1.0], [0.22, 0.0031308, 0.00015]],
                    [[2.0, -1.0, 0.18], [np.nan, 0.5, 0.5]]], np.float32)
    out = to_srgb8(rgb, nodata_srgb8=(1, 2, 3))
    assert out.dtype == np.uint8
    # 0.5 → 0.73536 → 187.52 → 188; 0.22 → 0.50639 → 129.13 → 129; 0.0031308 → 0.04045 → 10.3;
    # 0.00015 → 12.92·0.00015·255 = 0.49 → 0; 0.18 (mid grey) → 117.65 → 118.
    np.testing.assert_array_equal(out[0], [[188, 0, 255], [129, 10, 0]])
    np.testing.assert_array_equal(out[1, 0], [255, 0, 118])
    np.testing.assert_array_equal(out[1, 1], [1, 2, 3])


def test_bad_inputs_raise_shading_errors():
    surf = _surfaces(2, 2)
    ones = np.ones((2, 2), np.float32)
    sun = np.array([0.0, 0.0, 1.0])
    with pytest.raises(ShadingError, match="NaN"):
        shade(FakeScene(), surf, MAP, np.full((2, 2), np.nan, np.float32), sun)
    with pytest.raises(ShadingError, match="shape"):
        shade(FakeScene(), surf, MAP, np.ones((3, 2), np.float32), sun)
    with pytest.raises(ShadingError, match="sun direction"):
        shade(FakeScene(), surf, MAP, ones, np.zeros(3))
    with pytest.raises(ShadingError, match="camera kind"):
        shade(FakeScene(), surf, FakeCamera("fisheye", np.zeros(3), np.ones(3)), ones, sun)
    with pytest.raises(ShadingError, match="unknown surface classes"):
        ShadingSettings(palette_srgb8={"unclassified": (1, 2, 3), "spaceship": (1, 2, 3)})
    with pytest.raises(ShadingError, match="sun_rgb"):
        ShadingSettings(sun_rgb=(1.0, -1.0, 1.0))


# --- the sample city through the real G-buffer ------------------------------------------------

@pytest.fixture(scope="module")
def sample_scene(sample_city_scene):
    return sample_city_scene


def test_sample_city_overview_is_textured_and_deterministic(sample_scene):
    raster = pytest.importorskip("cityshade.raster.rasterize")
    from cityshade.raster.camera import overview
    from cityshade.raster.gbuffer import resolve

    scene = sample_scene
    camera = overview(scene, 160, 100)
    gbuf = raster.rasterize(scene, camera, 1e9)   # far future: every open-ended building
    surf = resolve(scene, gbuf)
    textured = surf.valid & (surf.texture >= 0)
    assert textured.sum() > 20, "the overview should see textured facades"
    lit = np.where(surf.valid, 1.0, 0.0).astype(np.float32)
    sun = np.array([0.4, -0.5, 0.7])
    rgb = shade(scene, surf, camera, lit, sun)
    again = shade(scene, surf, camera, lit, sun)
    np.testing.assert_array_equal(rgb, again)
    assert np.isfinite(rgb).all()                   # perspective: sky behind everything
    # Textured pixels are not the colour the same pixel gets without textures.
    plain = shade(scene, surf, camera, lit, sun, settings=ShadingSettings(textures=False))
    differs = np.abs(rgb - plain).max(axis=2) > 0.02
    assert differs[textured].mean() > 0.8
    np.testing.assert_array_equal(rgb[~textured], plain[~textured])
    srgb = to_srgb8(rgb)
    assert srgb.shape == (100, 160, 3) and len(np.unique(srgb.reshape(-1, 3), axis=0)) > 50


def test_texture_composite_equals_the_gather_twin(tmp_path):
    """The one-pass texture kernels against the gather/sample/scatter twin, bit for bit: a
    half-transparent texture over material colours, uv patches by triangle and by polygon,
    pixels without surface or outside the texture list, and no ids at all."""
    from reference import reference_albedo

    from cityshade import imageio
    from cityshade.frame.shading import albedo_of_surfaces

    rng = np.random.default_rng(5)
    rgba = rng.integers(0, 256, (16, 24, 4), dtype=np.uint8)
    rgba[..., 3] = rng.choice([0, 90, 255], (16, 24))
    imageio.write_image(tmp_path / "t.png", rgba)
    scene = FakeScene(materials=[{"diffuse": [0.2, 0.4, 0.6]}],
                      textures=[{"path": str(tmp_path / "t.png"), "wrap_mode": "wrap"},
                                {"path": str(FACADE), "wrap_mode": "mirror"}])
    h, w = 37, 41
    surf = _surfaces(h, w, material=0)
    surf.texture[:] = rng.integers(-1, 3, (h, w))          # 2: beyond the list
    surf.valid[rng.random((h, w)) < 0.1] = False
    yy, xx = np.mgrid[0:h, 0:w]
    surf.uv[..., 0] = xx * rng.choice([0.01, 0.3], (h, w)) # smooth and jumpy patches
    surf.uv[..., 1] = yy * 0.05
    surf.prim_id = np.where(surf.valid, (xx // 7 + 10 * (yy // 9)).astype(np.int32), -1)
    scene.tri_polygon = (np.arange(60) // 3).astype(np.int32)
    fast = albedo_of_surfaces(scene, surf, prim_id=surf.prim_id)
    assert fast.tobytes() == reference_albedo(scene, surf, surf.prim_id).tobytes()
    assert np.abs(fast - albedo_of_surfaces(scene, surf, settings=ShadingSettings(
        textures=False))).max() > 0.1                      # the textures show
    del scene.tri_polygon                                   # patches by triangle
    assert (albedo_of_surfaces(scene, surf, prim_id=surf.prim_id).tobytes()
            == reference_albedo(scene, surf, surf.prim_id).tobytes())
    surf.prim_id = None                                     # one patch
    assert albedo_of_surfaces(scene, surf).tobytes() == reference_albedo(scene, surf).tobytes()
