"""Maps with context: the scale bar against the pixel size, the north arrow against pyproj's
meridian convergence, and the map's own pixels untouched by the decoration."""
from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("matplotlib")

UTM32 = "EPSG:25832"


def _map(h=180, w=260, seed=1):
    return np.random.default_rng(seed).integers(0, 256, (h, w, 3), dtype=np.uint8)


def _ctx(x_ul, y_ul, px, crs=UTM32, **kw):
    from cityshade.geo.crs import parse_srs_name
    from cityshade.present.maps import MapContext

    return MapContext((x_ul, px, 0.0, y_ul, 0.0, -px), parse_srs_name(crs), **kw)


def _black_run(row: np.ndarray, start: int) -> int:
    """Length of the run of black pixels in ``row`` (W, 3) from ``start``."""
    black = (row < 40).all(axis=1)
    n = 0
    while start + n < len(black) and black[start + n]:
        n += 1
    return n


@pytest.mark.parametrize("px_m, w", [(0.5, 260), (4.0, 333), (0.37, 700), (25.0, 90)])
def test_the_scale_bar_is_as_long_in_pixels_as_its_metres_at_the_pixel_size(px_m, w):
    from cityshade.present.maps import decorate_map

    d = decorate_map(_map(150, w), _ctx(690000.0, 5336400.0, px_m))
    mantissa = d.scale_bar_m / 10 ** math.floor(math.log10(d.scale_bar_m))
    assert round(mantissa, 9) in (1.0, 2.0, 5.0)
    # About a fifth of the width: within the rounding to 1-2-5 (a factor of 2.5 at worst).
    assert 0.2 / 2.5 <= d.scale_bar_m / (w * px_m) <= 0.2 * 2.5
    assert d.scale_bar_px == d.scale_bar_m / px_m
    drawn = _black_run(d.image[d.scale_bar_row], d.scale_bar_col)
    assert abs(drawn - d.scale_bar_px) <= 1.0, (drawn, d.scale_bar_px)
    # The bar is black where it is drawn, and nothing black continues past it.
    assert drawn >= 3


@pytest.mark.parametrize("x_ul, y_ul", [(690000.0, 5336400.0), (310000.0, 6100000.0),
                                        (499900.0, 5000100.0)])
def test_the_north_arrow_turns_by_the_meridian_convergence_at_the_map_centre(x_ul, y_ul):
    import pyproj

    from cityshade.present.maps import TRUE_NORTH_MIN_DEG, decorate_map

    h, w, px = 150, 260, 2.0
    d = decorate_map(_map(h, w), _ctx(x_ul, y_ul, px))
    # Independently: PROJ's factors at the centre of the map.
    proj = pyproj.Proj(UTM32)
    lon, lat = proj(x_ul + 0.5 * w * px, y_ul - 0.5 * h * px, inverse=True)
    gamma = proj.get_factors(lon, lat).meridian_convergence
    assert d.convergence_deg == pytest.approx(gamma, abs=0.1)
    if abs(gamma) > TRUE_NORTH_MIN_DEG:
        # True north lies γ anticlockwise of grid north (grid north is γ east of true north).
        assert d.true_north_cw_deg == pytest.approx(-gamma, abs=0.1)
    else:
        assert d.true_north_cw_deg is None
    if x_ul == 690000.0:  # ~2.6° east of 9° E at 48° N: γ ≈ +1.9°, the second arrow drawn
        assert 1.5 < gamma < 2.5 and d.true_north_cw_deg is not None


def test_a_local_crs_gets_grid_north_only():
    from cityshade.geo.crs import unknown_crs
    from cityshade.present.maps import MapContext, decorate_map

    d = decorate_map(_map(), MapContext((0.0, 1.0, 0.0, 100.0, 0.0, -1.0), unknown_crs("x")))
    assert d.convergence_deg is None and d.true_north_cw_deg is None


@pytest.mark.parametrize("legend", ["none", "bar", "categories"])
def test_the_map_pixels_are_unchanged_inside_the_decoration(legend):
    from cityshade.present.maps import Categories, ColourBar, decorate_map

    rgb = _map(173, 311, seed=7)
    leg = {"none": None,
           "bar": ColourBar(np.array([[0, 0, 0], [255, 255, 0]], np.uint8), 0.0, 12.0,
                            "sun-hours (h)"),
           "categories": Categories((((255, 255, 255), "sun"), ((0, 0, 0), "shadow")))}[legend]
    d = decorate_map(rgb, _ctx(690000.0, 5336400.0, 0.5, title="A title", legend=leg))
    h, w = rgb.shape[:2]
    inside = d.image[d.map_row:d.map_row + h, d.map_col:d.map_col + w]
    assert np.array_equal(inside, rgb)
    assert d.image.shape[0] > h + 40 and d.image.shape[1] >= w
    # Something is drawn around it (the frame, the bar, the text).
    assert (d.image[d.map_row + h:] < 100).any()


def test_a_tiny_map_and_a_rotated_geotransform():
    from cityshade.errors import UsageError
    from cityshade.geo.crs import parse_srs_name
    from cityshade.present.maps import MapContext, decorate_map

    rgb = _map(3, 5)
    d = decorate_map(rgb, _ctx(690000.0, 5336400.0, 1.0))
    assert np.array_equal(d.image[d.map_row:d.map_row + 3, d.map_col:d.map_col + 5], rgb)
    with pytest.raises(UsageError, match="north-up"):
        decorate_map(rgb, MapContext((0.0, 1.0, 0.2, 0.0, 0.0, -1.0), parse_srs_name(UTM32)))


def test_render_decorate_keeps_the_mask_pixels_and_the_geotiff(sample_city_scene, tmp_path):
    from cityshade.errors import UsageError
    from cityshade.frame.render import render_frame, write_frame
    from cityshade.geo.sun import sun_from_angles
    from cityshade.imageio import read_image
    from cityshade.raster.camera import map_view, overview

    scene = sample_city_scene
    cam = map_view(scene, pixel_size_m=4.0)
    sun = sun_from_angles(135.0, 30.0, scene.crs, scene.origin_m)
    frame = render_frame(scene, cam, 7305.0, sun, "raytrace")
    plain = write_frame(frame, scene, "2000", mask=tmp_path / "m.png", georef=tmp_path / "m.tif")
    fancy = write_frame(frame, scene, "2000", mask=tmp_path / "d.png", png=tmp_path / "p.png",
                        georef=tmp_path / "d.tif", decorate=True)
    assert len(plain) and len(fancy)
    mask, _ = read_image(tmp_path / "m.png")
    deco, _ = read_image(tmp_path / "d.png")
    h, w = mask.shape[:2]
    assert deco.shape[2] == 3 and deco.shape[0] > h and deco.shape[1] >= w
    grey = np.repeat(mask[..., :1], 3, axis=2)
    found = [(r, c) for r in range(deco.shape[0] - h + 1) for c in range(deco.shape[1] - w + 1)
             if np.array_equal(deco[r, c:c + w], grey[0])
             and np.array_equal(deco[r:r + h, c:c + w], grey)]
    assert len(found) == 1
    assert np.array_equal(read_image(tmp_path / "m.tif")[0], read_image(tmp_path / "d.tif")[0])
    persp = render_frame(scene, overview(scene, 64, 48), 7305.0, sun, "raytrace")
    with pytest.raises(UsageError, match="map view"):
        write_frame(persp, scene, "2000", png=tmp_path / "x.png", decorate=True)
