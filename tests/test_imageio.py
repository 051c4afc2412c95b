"""Round trips and failures of cityshade.imageio (the only OpenImageIO user)."""
from __future__ import annotations

import numpy as np
import pytest

from cityshade.errors import CityshadeError
from cityshade.imageio import FORMAT_DTYPES, read_image, write_image
from cityshade.errors import ImageIOError


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


# --- EXR with named channels, PNG, masks, georeferenced rasters --------------------------------

import json  # noqa: E402
import shutil  # noqa: E402
import struct  # noqa: E402
import subprocess  # noqa: E402

from cityshade.imageio import (MASK_NODATA, mask_from_lit, read_exr, world_file_lines,  # noqa: E402
                               write_exr, write_georeferenced, write_mask_png, write_png_rgb)


def _frame_channels(h=5, w=7):
    rng = np.random.default_rng(7)
    prim = rng.integers(-1, 2 ** 24, size=(h, w)).astype(np.int32)
    prim[0, 0] = -1
    prim[0, 1] = 2 ** 24          # the largest id float32 still holds exactly
    normal = rng.normal(size=(h, w, 3)).astype(np.float32)
    return {
        "R": rng.uniform(0, 2, (h, w)).astype(np.float32),
        "G": rng.uniform(0, 2, (h, w)).astype(np.float32),
        "B": np.full((h, w), np.nan, np.float32),
        "shadow": rng.uniform(0, 1, (h, w)).astype(np.float32),
        "Z": np.where(prim >= 0, rng.uniform(1, 1e4, (h, w)), np.inf).astype(np.float32),
        "N.x": normal[..., 0], "N.y": normal[..., 1], "N.z": normal[..., 2],
        "primid": prim, "objid": (prim // 3).astype(np.int32),
    }


def test_exr_round_trip_with_every_channel_and_the_header(tmp_path):
    channels = _frame_channels()
    attrs = {"cityshade:date": "1850-06-21T15:00+01:00", "cityshade:sun_azimuth_true_deg": 194.25,
             "cityshade:technique": "raytrace", "cityshade:crs_epsg": 25832}
    path = tmp_path / "frame.exr"
    write_exr(path, channels, attrs)
    back, got = read_exr(path)
    assert got["channel_names"] == tuple(channels)
    for name, values in channels.items():
        assert back[name].shape == values.shape
        np.testing.assert_array_equal(back[name], values, err_msg=name)
    assert back["primid"].dtype.kind == "i" and back["primid"][0, 0] == -1
    assert back["primid"][0, 1] == 2 ** 24
    assert got["cityshade:date"] == "1850-06-21T15:00+01:00"
    assert got["cityshade:technique"] == "raytrace"
    assert got["cityshade:crs_epsg"] == 25832
    assert got["cityshade:sun_azimuth_true_deg"] == pytest.approx(194.25)
    assert [p.name for p in tmp_path.iterdir()] == ["frame.exr"]


def test_exr_ids_beyond_float32_go_to_a_uint32_part(tmp_path):
    channels = {"R": np.zeros((2, 3), np.float32),
                "primid": np.array([[-1, 0, 2 ** 24 + 1], [4_000_000_000, 7, 123_456_789]])}
    path = tmp_path / "big.exr"
    write_exr(path, channels, {"cityshade:technique": "raytrace"})
    back, got = read_exr(path)
    np.testing.assert_array_equal(back["primid"], channels["primid"])
    np.testing.assert_array_equal(back["R"], 0.0)
    # The plain reader sees the float part (what an EXR viewer shows first).
    pixels, attrs = read_image(path)
    assert attrs["channel_names"] == ("R",)


def test_exr_written_by_strips_equals_one_whole_buffer(tmp_path):
    # 150 rows: two full strips of EXR_STRIP_ROWS and a short one; a lazy channel and an id
    # channel beyond float32 (the uint32 part) are interleaved strip by strip too.
    from cityshade.imageio import EXR_STRIP_ROWS, LazyChannel

    h, w = 2 * EXR_STRIP_ROWS + 22, 9
    rng = np.random.default_rng(3)
    z = np.where(rng.uniform(size=(h, w)) < 0.3, np.inf, rng.uniform(1, 50, (h, w)))
    calls = []

    def z_rows(y0, y1):
        calls.append((y0, y1))
        return z[y0:y1].astype(np.float32)

    big = rng.integers(-1, 2 ** 31, (h, w)).astype(np.int64)
    r = rng.uniform(0, 2, (h, w)).astype(np.float32)
    path = tmp_path / "strips.exr"
    write_exr(path, {"R": r, "Z": LazyChannel((h, w), z_rows), "big": big})
    step = EXR_STRIP_ROWS
    assert calls == [(0, step), (step, 2 * step), (2 * step, h)]
    back, _ = read_exr(path)
    np.testing.assert_array_equal(back["R"], r)
    np.testing.assert_array_equal(back["Z"], z.astype(np.float32))
    np.testing.assert_array_equal(back["big"], big)
    # The float part written in one piece by the plain writer reads back the same.
    whole = tmp_path / "whole.exr"
    write_image(whole, np.dstack([r, z.astype(np.float32)]), channel_names=("R", "Z"))
    pixels, _ = read_image(whole)
    np.testing.assert_array_equal(pixels[..., 1], back["Z"])


@pytest.mark.parametrize("channels, message", [
    ({}, "at least one channel"),
    ({"R": np.zeros((2, 2), np.float32), "G": np.zeros((2, 3), np.float32)}, "shape"),
    ({"R": np.zeros((2, 2, 1), np.float32)}, r"\(H, W\)"),
    ({"id": np.array([[-2, 2 ** 25]])}, "EXR ids must lie"),
    ({"s": np.array([["a", "b"]])}, "type"),
    ({"": np.zeros((1, 1), np.float32)}, "channel names"),
])
def test_exr_refuses_bad_channels_and_writes_nothing(tmp_path, channels, message):
    with pytest.raises(ImageIOError, match=message):
        write_exr(tmp_path / "x.exr", channels)
    assert list(tmp_path.iterdir()) == []


def test_png_rgb_and_mask_values(tmp_path):
    rgb = _pattern((6, 9, 3), np.uint8)
    write_png_rgb(tmp_path / "beauty.png", rgb, {"cityshade:technique": "raytrace"})
    back, _ = read_image(tmp_path / "beauty.png")
    np.testing.assert_array_equal(back, rgb)
    lit = np.array([[0.0, 0.49, 0.5, 1.0], [np.nan, 1.0, 0.2, 0.7]])
    valid = np.array([[True, True, True, True], [True, False, True, True]])
    mask = mask_from_lit(lit, valid)
    np.testing.assert_array_equal(mask, [[0, 0, 255, 255], [128, 128, 0, 255]])
    np.testing.assert_array_equal(mask_from_lit(lit.astype(np.float32), valid), mask)
    # float32 lit against a float64 threshold just above it: compared in float64 (in float32
    # the threshold would round down onto the value and count it as lit).
    x = np.float32(0.3)
    assert mask_from_lit(np.array([[x]]), threshold=float(x) + 1e-12)[0, 0] == 0
    assert mask_from_lit(np.array([[x]]), threshold=float(x))[0, 0] == 255
    write_mask_png(tmp_path / "mask.png", mask)
    back, _ = read_image(tmp_path / "mask.png")
    assert back.shape == (2, 4, 1) and back.dtype == np.uint8
    np.testing.assert_array_equal(back[:, :, 0], mask)
    write_mask_png(tmp_path / "bool.png", np.array([[True, False]]))
    np.testing.assert_array_equal(read_image(tmp_path / "bool.png")[0][:, :, 0], [[255, 0]])
    with pytest.raises(ImageIOError, match="only 255"):
        write_mask_png(tmp_path / "bad.png", np.array([[0, 7]], np.uint8))
    with pytest.raises(ImageIOError, match="mask_from_lit"):
        write_mask_png(tmp_path / "bad.png", lit)
    with pytest.raises(ImageIOError, match=r"\(H, W, 3\) uint8"):
        write_png_rgb(tmp_path / "bad.png", rgb[:, :, :2])
    assert not (tmp_path / "bad.png").exists()


def _tiff_tags(path):
    """{tag: values} of the first IFD of a classic TIFF, parsed here from the TIFF 6.0 layout."""
    data = path.read_bytes()
    order = {b"II": "<", b"MM": ">"}[data[:2]]
    ifd = struct.unpack(order + "I", data[4:8])[0]
    sizes = {2: ("c", 1), 3: ("H", 2), 4: ("I", 4), 12: ("d", 8)}
    tags = {}
    for k in range(struct.unpack(order + "H", data[ifd:ifd + 2])[0]):
        tag, ftype, count = struct.unpack(order + "HHI", data[ifd + 2 + 12 * k: ifd + 10 + 12 * k])
        if ftype not in sizes:
            continue
        fmt, size = sizes[ftype]
        field_at = ifd + 10 + 12 * k
        at = field_at if size * count <= 4 else struct.unpack(order + "I",
                                                                data[field_at:field_at + 4])[0]
        raw = data[at: at + size * count]
        tags[tag] = raw.rstrip(b"\0").decode() if ftype == 2 else struct.unpack(
            order + fmt * count, raw)
    return tags


def test_georeferenced_mask_world_file_prj_and_geotiff_tags(tmp_path):
    # A 3×4 map of 0.5 m pixels whose upper-left CORNER is at (690000, 5336000) in UTM 32N.
    gt = (690000.0, 0.5, 0.0, 5336000.0, 0.0, -0.5)
    mask = np.array([[255, 0, 128, 255], [0, 0, 255, 128], [128, 255, 0, 0]], np.uint8)
    path = tmp_path / "shadow.tif"
    written = write_georeferenced(path, mask, gt, epsg=25832, nodata=MASK_NODATA)
    assert written == [path, tmp_path / "shadow.tfw", tmp_path / "shadow.prj"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["shadow.prj", "shadow.tfw", "shadow.tif"]
    back, _ = read_image(path)
    np.testing.assert_array_equal(back[:, :, 0], mask)
    # World file: pixel size, rotations, then the CENTRE of the upper-left pixel.
    lines = (tmp_path / "shadow.tfw").read_text().split()
    assert [float(v) for v in lines] == [0.5, 0.0, 0.0, -0.5, 690000.25, 5335999.75]
    # Every pixel centre from the world file equals the corner rule + half a pixel.
    a, d, b, e, c, f = (float(v) for v in lines)
    for row in range(3):
        for col in range(4):
            assert a * col + b * row + c == 690000.0 + 0.5 * (col + 0.5)
            assert d * col + e * row + f == 5336000.0 - 0.5 * (row + 0.5)
    prj = (tmp_path / "shadow.prj").read_text()
    assert prj.startswith('PROJCS["ETRS_1989_UTM_Zone_32N"') and "GEOGCS" in prj
    tags = _tiff_tags(path)
    assert tags[33550] == (0.5, 0.5, 0.0)                                 # ModelPixelScale
    assert tags[33922] == (0.0, 0.0, 0.0, 690000.0, 5336000.0, 0.0)       # ModelTiePoint
    keys = tags[34735]
    assert keys[:4] == (1, 1, 0, 3)
    entries = {keys[i]: keys[i + 3] for i in range(4, len(keys), 4)}
    assert entries == {1024: 1, 1025: 1, 3072: 25832}   # projected, PixelIsArea, EPSG:25832
    assert tags[42113] == "128"                          # GDAL_NODATA
    assert tags[256] == (4,) and tags[257] == (3,)       # the image's own tags survive
    if shutil.which("gdalinfo"):   # an independent reader, when GDAL is installed
        info = json.loads(subprocess.run(["gdalinfo", "-json", str(path)], check=True,
                                         capture_output=True, text=True).stdout)
        assert info["geoTransform"] == list(gt)
        assert info["bands"][0]["noDataValue"] == 128
        assert '"EPSG",25832' in info["coordinateSystem"]["wkt"].replace(" ", "")


def test_georeferenced_rotated_float_raster_without_crs(tmp_path):
    gt = (1000.0, 0.8, 0.6, 2000.0, 0.6, -0.8)     # 1 m pixels rotated by ~36.87°
    raster = np.arange(6, dtype=np.float32).reshape(2, 3)
    raster[0, 0] = np.nan
    path = tmp_path / "r.tiff"
    written = write_georeferenced(path, raster, gt)
    assert written == [path, tmp_path / "r.tfw"]                   # no CRS: no .prj
    lines = world_file_lines(gt)
    assert lines == (tmp_path / "r.tfw").read_text().split()
    # Centre of pixel (0, 0) = corner + half a pixel along both rotated pixel axes.
    assert [float(v) for v in lines] == pytest.approx([0.8, 0.6, 0.6, -0.8, 1000.7, 1999.9],
                                                      abs=1e-9)
    tags = _tiff_tags(path)
    assert tags[34264] == (0.8, 0.6, 0.0, 1000.0, 0.6, -0.8, 0.0, 2000.0,
                           0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # ModelTransformation
    assert 33550 not in tags and 42113 not in tags
    back, _ = read_image(path)
    np.testing.assert_array_equal(back[:, :, 0], raster)


def test_georeferenced_refusals_leave_no_files(tmp_path):
    mask = np.zeros((2, 2), np.uint8)
    with pytest.raises(ImageIOError, match="tif"):
        write_georeferenced(tmp_path / "a.png", mask, (0, 1, 0, 0, 0, -1))
    with pytest.raises(ImageIOError, match="singular"):
        write_georeferenced(tmp_path / "a.tif", mask, (0, 0, 0, 0, 0, -1))
    with pytest.raises(ImageIOError, match="6 finite"):
        write_georeferenced(tmp_path / "a.tif", mask, (0, 1, 0, 0, 0))
    with pytest.raises(CityshadeError, match="CRS"):
        write_georeferenced(tmp_path / "a.tif", mask, (0, 1, 0, 0, 0, -1), epsg=999999)
    assert list(tmp_path.iterdir()) == []


def _stored_types(path):
    """Channel name → type stored in the file (half, float, uint), and the compression."""
    import OpenImageIO as oiio

    inp = oiio.ImageInput.open(str(path))
    try:
        spec = inp.spec()
        formats = [str(f) for f in spec.channelformats] or [str(spec.format)] * spec.nchannels
        return dict(zip(spec.channelnames, formats)), spec.get_string_attribute("compression")
    finally:
        inp.close()


@pytest.mark.parametrize("compression", ["none", "zip"])
def test_exr_half_channels_read_back_rounded_as_numpy_rounds_them(tmp_path, compression):
    # 150 x 9 rows (strips of 64, an odd width: the half rows leave the float rows unaligned),
    # a lazy channel, NaN, ±inf, ids up to 2**24, values past the half range.
    from cityshade.imageio import EXR_STRIP_ROWS, LazyChannel

    h = 2 * EXR_STRIP_ROWS + 22
    channels = _frame_channels(h, 9)
    channels["R"][0, :3] = [70000.0, -1e-8, 65519.0]      # → inf, -0, 65504
    z = channels["Z"]
    channels["Z"] = LazyChannel(z.shape, lambda y0, y1: z[y0:y1])
    half = ("R", "G", "B", "N.x", "N.y", "N.z")
    attrs = {"cityshade:technique": "raytrace", "cityshade:crs_epsg": 25832,
             "cityshade:sun_elevation_deg": 30.5, "cityshade:a_name_longer_than_31_bytes": "x"}
    path = tmp_path / "f.exr"
    write_exr(path, channels, attrs, half=half, compression=compression)
    types, stored = _stored_types(path)
    assert stored == compression
    assert types == {n: ("half" if n in half else "float") for n in channels}
    back, got = read_exr(path)
    assert got["channel_names"] == tuple(channels)
    for name, values in channels.items():
        want = z if name == "Z" else values
        if name in half:   # numpy's float32 → float16 rounding, not the writer's
            with np.errstate(over="ignore"):     # 70000 → inf on purpose
                want = values.astype(np.float16).astype(np.float32)
        np.testing.assert_array_equal(back[name], want, err_msg=name)
    assert back["R"][0, :3].tolist() == [np.inf, 0.0, 65504.0]
    assert back["primid"].dtype.kind == "i" and back["primid"][0, 1] == 2 ** 24
    assert (got["cityshade:technique"], got["cityshade:crs_epsg"]) == ("raytrace", 25832)
    assert got["cityshade:sun_elevation_deg"] == 30.5
    assert got["cityshade:a_name_longer_than_31_bytes"] == "x"
    assert [p.name for p in tmp_path.iterdir()] == ["f.exr"]


def test_uncompressed_exr_reads_back_as_the_zip_one(tmp_path):
    # The direct writer and OpenImageIO's: the same channels, values and header for a reader.
    channels = _frame_channels(70, 5)
    attrs = {"cityshade:technique": "izb", "cityshade:n": 3, "cityshade:f": 0.25}
    write_exr(tmp_path / "a.exr", channels, attrs, compression="none")
    write_exr(tmp_path / "b.exr", channels, attrs, compression="zip")
    a, got_a = read_exr(tmp_path / "a.exr")
    b, got_b = read_exr(tmp_path / "b.exr")
    assert list(a) == list(b) == list(channels)
    for name in channels:
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)
    differ = {k for k in set(got_a) | set(got_b) if got_a.get(k) != got_b.get(k)}
    # OpenImageIO adds its write time and chunk height; only those and the compression differ.
    assert differ <= {"compression", "DateTime", "oiio:RowsPerChunk"} and "compression" in differ


def test_exr_with_ids_beyond_float32_keeps_its_half_channels_in_the_zip_parts(tmp_path):
    # No single uncompressed part can hold uint32 ids: the two zip parts, R still half.
    r = np.array([[0.1, 1 / 3, 7.0]], np.float32)
    ids = np.array([[-1, 2 ** 24 + 1, 4_000_000_000]])
    path = tmp_path / "big.exr"
    write_exr(path, {"R": r, "Z": r * 2, "primid": ids}, half=("R",), compression="none")
    types, stored = _stored_types(path)
    assert stored == "zip" and types == {"R": "half", "Z": "float"}
    back, _ = read_exr(path)
    np.testing.assert_array_equal(back["R"], r.astype(np.float16).astype(np.float32))
    np.testing.assert_array_equal(back["Z"], r * 2)
    np.testing.assert_array_equal(back["primid"], ids)


@pytest.mark.parametrize("kwargs, message", [
    ({"compression": "piz"}, "EXR compression must be zip or none, not 'piz'$"),
    ({"half": ("primid",)}, "half channels must be float channels: primid$"),
    ({"half": ("R", "nope")}, "half channels must be float channels: nope$"),
])
def test_exr_refuses_bad_half_or_compression(tmp_path, kwargs, message):
    channels = {"R": np.zeros((2, 2), np.float32), "primid": np.zeros((2, 2), np.int32)}
    with pytest.raises(ImageIOError, match=message):
        write_exr(tmp_path / "x.exr", channels, **kwargs)
    assert list(tmp_path.iterdir()) == []
