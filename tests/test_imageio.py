"""Round trips and failures of cityshade.imageio (the only OpenImageIO user)."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.errors import CityshadeError
from cityshade.imageio import FORMAT_DTYPES, ImageIOError, read_image, write_image


def _pattern(shape, dtype) -> np.ndarray:
    """A pixel pattern in which every pixel and channel differs (catches transposes, shifts)."""
    rng = np.random.default_rng(1234)
    if np.dtype(dtype).kind == "f":
        return rng.uniform(-3.0, 1000.0, size=shape).astype(dtype)
    info = np.iinfo(dtype)
    return rng.integers(0, int(info.max) + 1, size=shape, dtype=np.int64).astype(dtype)


@pytest.mark.parametrize("ext", [e for e in sorted(FORMAT_DTYPES) if e not in (".jpg", ".jpeg")])
def test_every_lossless_format_and_type_round_trips(tmp_path, ext):
    for dtype in FORMAT_DTYPES[ext]:
        for channels in (1, 2, 3, 4):
            pixels = _pattern((7, 11, channels), dtype)  # non-square: catches H/W swaps
            path = tmp_path / f"img_{np.dtype(dtype).name}_{channels}{ext}"
            write_image(path, pixels)
            back, attrs = read_image(path)
            assert back.dtype == pixels.dtype, (ext, dtype, back.dtype)
            assert back.shape == pixels.shape, (ext, dtype, back.shape)
            np.testing.assert_array_equal(back, pixels, err_msg=f"{ext} {dtype} {channels}ch")
            assert len(attrs["channel_names"]) == channels


@pytest.mark.parametrize("ext", [".png", ".tif", ".exr"])
def test_2d_mask_is_written_as_one_channel_with_the_right_pixels(tmp_path, ext):
    # DESIGN §14: OpenImageIO writes wrong pixels from a 2-D array; a checkerboard with an odd
    # width shows any row misalignment.
    dtype = np.float32 if ext == ".exr" else np.uint8
    mask = ((np.arange(9)[:, None] + np.arange(13)[None, :]) % 2 * 255).astype(dtype)
    mask[0, 0] = 128  # the nodata value of 8-bit masks, at a known corner
    path = tmp_path / f"mask{ext}"
    write_image(path, mask)
    back, _ = read_image(path)
    assert back.shape == (9, 13, 1)
    np.testing.assert_array_equal(back[:, :, 0], mask)
    assert back[0, 0, 0] == 128 and back[0, 1, 0] == 255 and back[1, 1, 0] == 0


def test_exr_float_channels_with_custom_names_and_attributes(tmp_path):
    # Names chosen so OpenEXR's alphabetical channel sorting would reorder them.
    lit = np.linspace(0.0, 1.0, 6 * 5, dtype=np.float32).reshape(6, 5)
    depth = np.arange(30, dtype=np.float32).reshape(6, 5) * 10.5 + 1e6
    prim = np.full((6, 5), np.nan, dtype=np.float32)
    prim[2, 3] = 4.0
    pixels = np.stack([lit, depth, prim], axis=-1)
    attrs = {"cityshade:technique": "hybrid", "cityshade:sun_azimuth_deg": 194.34024,
             "cityshade:frames": 3, "cityshade:date": "1850-06-21T15:00+01:00"}
    path = tmp_path / "frame.exr"
    write_image(path, pixels, attributes=attrs, channel_names=("lit", "depth", "prim_id"))
    back, got = read_image(path)
    assert got["channel_names"] == ("lit", "depth", "prim_id")
    np.testing.assert_array_equal(back, pixels)  # NaN compares equal in assert_array_equal
    assert got["cityshade:technique"] == "hybrid"
    assert got["cityshade:date"] == "1850-06-21T15:00+01:00"
    assert got["cityshade:frames"] == 3
    # EXR float attributes are float32.
    assert got["cityshade:sun_azimuth_deg"] == pytest.approx(194.34024, rel=1e-7)


def test_png_string_attribute_and_uint16(tmp_path):
    pixels = _pattern((4, 3, 2), np.uint16)
    path = tmp_path / "a.png"
    write_image(path, pixels, attributes={"ImageDescription": "cityshade mask"})
    back, got = read_image(path)
    np.testing.assert_array_equal(back, pixels)
    assert got["ImageDescription"] == "cityshade mask"


def test_jpeg_round_trips_within_quantisation(tmp_path):
    # JPEG is lossy; flat colour blocks aligned to its 8x8 DCT blocks survive quality 100 without
    # chroma subsampling within a few levels of colour-space rounding.
    pixels = np.zeros((16, 24, 3), np.uint8)
    pixels[:8, :8] = (200, 100, 50)
    pixels[8:, 8:16] = (10, 220, 90)
    path = tmp_path / "a.jpg"
    write_image(path, pixels,
                attributes={"Compression": "jpeg:100", "jpeg:subsampling": "4:4:4"})
    back, _ = read_image(path)
    assert back.shape == pixels.shape and back.dtype == np.uint8
    assert np.abs(back.astype(int) - pixels.astype(int)).max() <= 3


def test_overwrite_replaces_the_file(tmp_path):
    path = tmp_path / "x.png"
    write_image(path, np.zeros((2, 2, 3), np.uint8))
    write_image(path, np.full((3, 1, 1), 7, np.uint8))
    back, _ = read_image(path)
    assert back.shape == (3, 1, 1) and (back == 7).all()
    assert [p.name for p in tmp_path.iterdir()] == ["x.png"]


def test_unwritable_paths_raise_and_leave_no_file(tmp_path):
    pixels = np.zeros((4, 4, 3), np.uint8)
    not_a_folder = tmp_path / "plain.txt"
    not_a_folder.write_text("x")
    a_folder = tmp_path / "taken.png"  # a directory where the image should go: rename fails
    a_folder.mkdir()
    for path in (tmp_path / "missing" / "out.png", not_a_folder / "out.png", a_folder):
        with pytest.raises(ImageIOError) as info:
            write_image(path, pixels)
        assert isinstance(info.value, CityshadeError)
        assert info.value.path == str(path)
        assert "cannot write image" in str(info.value) and str(path) in str(info.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain.txt", "taken.png"]
    assert list(a_folder.iterdir()) == []


@pytest.mark.parametrize("name, pixels, message", [
    ("a.png", np.zeros((2, 2, 3), np.float32), "cannot store float32"),
    ("a.exr", np.zeros((2, 2), np.uint8), "cannot store uint8"),
    ("a.tif", np.zeros((2, 2), np.uint32), "cannot store uint32"),
    ("a.jpg", np.zeros((2, 2, 4), np.uint8), "cannot store 4 channels"),
    ("a.bmp", np.zeros((2, 2, 3), np.uint8), "unsupported image extension"),
    ("a.png", np.zeros((2, 2, 3, 1), np.uint8), "must have shape"),
    ("a.png", np.zeros((0, 2, 3), np.uint8), "empty image"),
])
def test_refused_inputs_name_the_problem_and_write_nothing(tmp_path, name, pixels, message):
    with pytest.raises(ImageIOError, match=message):
        write_image(tmp_path / name, pixels)
    assert list(tmp_path.iterdir()) == []


def test_bad_channel_names_and_attributes(tmp_path):
    pixels = np.zeros((2, 2, 2), np.float32)
    with pytest.raises(ImageIOError, match="channel_names"):
        write_image(tmp_path / "a.exr", pixels, channel_names=("only_one",))
    with pytest.raises(ImageIOError, match="distinct"):
        write_image(tmp_path / "a.exr", pixels, channel_names=("z", "z"))
    with pytest.raises(ImageIOError, match="must be a str, int or float"):
        write_image(tmp_path / "a.exr", pixels, attributes={"bad": [1, 2]})
    assert list(tmp_path.iterdir()) == []


def test_read_errors(tmp_path):
    with pytest.raises(ImageIOError, match="no such file"):
        read_image(tmp_path / "nothing.png")
    junk = tmp_path / "junk.png"
    junk.write_bytes(b"this is not a png")
    with pytest.raises(ImageIOError, match="cannot read image") as info:
        read_image(junk)
    assert info.value.path == str(junk)
