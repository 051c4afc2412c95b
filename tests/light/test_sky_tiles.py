"""A sky run in tiles (issue 37 point 7): the tiled answer equals the untiled one bit for bit
(the sample city with irradiance and instants, the Berlin trees), an interrupted run resumes
to the same bits and says so, other parameters are refused, a finished run leaves only its
outputs and is not computed again, Dask workers give the same bits, and the memory estimate
counts the rays through crowns."""
from __future__ import annotations

import dataclasses
import datetime as dt
from pathlib import Path

import numpy as np
import pytest

from conftest import shared_file

from cityshade.errors import UsageError

SAMPLE = Path(__file__).resolve().parents[2] / "sample_data" / "sample_city.gml"


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    """The sample city built to a file (Dask workers map it), loaded back."""
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    path = tmp_path_factory.mktemp("sky_tiles") / "city.cityshade"
    build_file(SAMPLE, path)
    return path, load_scene(path)


def _request(scene, pixel_m=4.0, bbox=None, **kw):
    from cityshade.light.run import SkyRequest
    from cityshade.raster.camera import map_view

    base = dict(camera=map_view(scene, pixel_m, bbox), samples_per_m2=0.05, sky="tregenza", vsc=True,
                t_days=20_000.0, provenance={"case": "tiles"})
    return SkyRequest(**{**base, **kw})


def _same(a, b):
    """Every number of two sky results equal, bit for bit (NaN where both are NaN)."""
    np.testing.assert_array_equal(a.svf, b.svf)
    np.testing.assert_array_equal(a.pixels, b.pixels)
    for name in ("vsc", "instants_w_m2"):
        x, y = getattr(a, name), getattr(b, name)
        assert (x is None) == (y is None), name
        if x is not None:
            np.testing.assert_array_equal(x, y)
    if a.irradiation is not None or b.irradiation is not None:
        for c in ("direct_kwh_m2", "diffuse_kwh_m2", "reflected_kwh_m2"):
            np.testing.assert_array_equal(getattr(a.irradiation, c), getattr(b.irradiation, c))
        assert a.irradiation.hours == b.irradiation.hours


def test_tiled_sky_with_irradiance_and_instants_equals_untiled_bit_for_bit(sample):
    """Map pixels and surface samples, SVF, VSC, a day of pvlib's TMY3 year's irradiance
    and two instants: 24 px tiles (and one tile per sample square) give the untiled numbers."""
    import os

    import pvlib

    from cityshade.light import read_weather
    from cityshade.light.irradiance import hours_between
    from cityshade.light.run import compute_sky

    _, scene = sample
    weather = read_weather(os.path.join(os.path.dirname(pvlib.__file__), "data",
                                        "723170TYA.CSV"))
    zone = dt.timezone(dt.timedelta(hours=weather.location.utc_offset_h))
    instants = (dt.datetime(2025, 6, 21, 9, 0, tzinfo=zone),
                dt.datetime(2025, 6, 21, 15, 30, tzinfo=zone))
    request = _request(scene, pixel_m=6.0, weather=weather,
                       hours=hours_between(weather, "06-21", "06-21"), instants=instants,
                       instant_labels=("0900", "1530"))
    plain = compute_sky(scene, request)
    tiled = compute_sky(scene, dataclasses.replace(request, tile_px=24))
    assert plain.tiles["tiles"] == 1 and tiled.tiles["tiles"] > 5
    assert 10 < plain.irradiation.hours <= 24 and plain.irradiation.total_kwh_m2.max() > 1.0
    assert (plain.svf < 0.9).sum() > 100 and plain.svf.max() == pytest.approx(1.0)
    _same(plain, tiled)


def test_tiled_sky_with_the_berlin_trees_equals_untiled_bit_for_bit():
    """The Berlin-Lichtenberg buildings and their 288 trees (shared data), 3 m map pixels of
    a 90 m square among the trees: the rays through crowns of each tile give the untiled view
    factors in leaf and the VSC."""
    from cityshade.build import build_scene_from_files
    from cityshade.geometry.vegetation import vegetation_mask
    from cityshade.light.run import compute_sky

    folder = "berlin-lichtenberg-trees/"
    scene = build_scene_from_files([shared_file(folder + "lod2_buildings_berlin_test_area.gml"),
                                    shared_file(folder + "semantic_3D_tree_model_berlin_test_area.gml")])
    crowns = np.asarray(scene.triangles)[vegetation_mask(scene)].ravel()
    x, y = np.median(np.asarray(scene.vertices, np.float64)[crowns, :2], axis=0)
    request = _request(scene, pixel_m=3.0, bbox=(x - 45, y - 45, x + 45, y + 45),
                       samples_per_m2=None)
    plain = compute_sky(scene, request)
    tiled = compute_sky(scene, dataclasses.replace(request, tile_px=8))
    assert tiled.tiles["tiles"] > 9 and plain.tiles["crown_rays"] > 1000
    assert tiled.tiles["crown_rays"] == plain.tiles["crown_rays"]
    _same(plain, tiled)


class Stop(Exception):
    pass


def test_an_interrupted_sky_run_resumes_to_the_same_bits(sample, tmp_path):
    """Stopped after 5 of its tiles, the same run again says it resumes, computes only the
    others and writes what an uninterrupted run writes; other parameters are refused (named),
    ``overwrite`` starts over; a finished run leaves its outputs and manifest only and is not
    computed again."""
    from cityshade.light.run import run_sky

    _, scene = sample
    request = _request(scene, pixel_m=6.0, samples_per_m2=None, tile_px=8, gis=False,
                       decorate=False)
    straight = run_sky(tmp_path / "straight", scene, request).result
    out = tmp_path / "out"
    notes, computed = [], []

    def stop_after(done, total):
        computed.append(done)
        if len(computed) == 5:
            raise Stop

    with pytest.raises(Stop):
        run_sky(out, scene, request, on_tile=stop_after)
    assert sorted(p.name for p in out.iterdir()) == ["manifest.json", "state.npz"]
    with pytest.raises(UsageError, match=r"holds a run with other parameters \(differs in: "
                                         r"sky\); use --overwrite or another -o folder"):
        run_sky(out, scene, dataclasses.replace(request, sky="uniform30"))
    again = run_sky(out, scene, request, on_note=notes.append, on_tile=lambda d, t: None)
    total = straight.tiles["tiles"]
    assert notes == [f"resuming the run in {out}: 5 of {total} tiles were done before"]
    assert again.result.tiles["tiles_resumed"] == 5
    _same(straight, again.result)
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(p.name for p in (tmp_path / "straight").iterdir())
    assert "state.npz" not in names and "receivers.npy" not in names and "manifest.json" in names
    done = run_sky(out, scene, request)
    assert done.already_complete and done.result is None
    over = run_sky(out, scene, dataclasses.replace(request, sky="uniform30"), overwrite=True)
    assert over.result.sky.n == len(over.result.sky.directions) != 145


def test_sky_tiles_on_dask_workers_equal_the_plain_run(sample, tmp_path):
    """Two local Dask worker processes (batch's executor) trace the tiles: the same bits."""
    pytest.importorskip("dask.distributed")
    from cityshade.light.run import compute_sky, run_sky
    from cityshade.sunhours.distributed import DaskExecutor

    path, scene = sample
    request = _request(scene, tile_px=24, gis=False, decorate=False, scene_path=path)
    plain = compute_sky(scene, dataclasses.replace(request, tile_px=None))
    sha = (scene.header or {}).get("source", {}).get("sha256", "")
    executor = DaskExecutor("local:2", path, sha, threads_per_worker=1)
    run = run_sky(tmp_path / "dask", scene, dataclasses.replace(request, scheduler=executor))
    assert run.result.tiles["workers"] == 2
    _same(plain, run.result)
    assert not (tmp_path / "dask" / "receivers.npy").exists()


def test_the_memory_estimate_counts_crown_rays_and_a_tile(sample, monkeypatch):
    """With vegetation a receiver counts :data:`CROWN_RAY_SHARE` of its directions at 24 B a
    ray (and 17 B of a direction's results); a tiled run counts what it keeps of every
    receiver and one tile's work."""
    import math

    import cityshade.frame.pipeline as pipeline
    from cityshade.light.run import CROWN_RAY_SHARE, sky_bytes_per_receiver

    plain = sky_bytes_per_receiver(145, False)
    assert plain == 140
    assert sky_bytes_per_receiver(145, False, crowns=True) == \
        140 + 17 + math.ceil(24 * CROWN_RAY_SHARE * 145)
    assert sky_bytes_per_receiver(2305, True, crowns=True) == \
        sky_bytes_per_receiver(2305, True) + 17 + math.ceil(24 * CROWN_RAY_SHARE * 2305)
    from cityshade.light.run import compute_sky

    _, scene = sample
    monkeypatch.setattr(pipeline, "available_memory_bytes", lambda: 1000)
    request = _request(scene, pixel_m=0.05, samples_per_m2=None, vsc=False, tile_px=256)
    cam = request.camera
    n = cam.width_px * cam.height_px
    frame = pipeline.frame_bytes(cam, batch=True)[0]
    need = frame + n * (48 + 16 + 8) + 256 * 256 * 140
    with pytest.raises(UsageError) as err:
        compute_sky(scene, request)
    assert str(err.value) == (
        f"{n:,} receivers need about {need / 1e9:.1f} GB (72 bytes each kept and 140 each of "
        f"a tile's 65,536 while it is traced besides the camera's {frame / 1e9:.1f} GB) but "
        f"0.0 GB are available: use a larger --pixel-size, fewer --samples-per-m2, a smaller "
        f"--tile-px or a coarser --sky")


def _resident_kb(path) -> int:
    """Resident kB of this process's mappings of ``path`` (``/proc/self/smaps``)."""
    total, mine = 0, False
    with open("/proc/self/smaps", encoding="ascii", errors="replace") as fh:
        for line in fh:
            head = line.split()
            if head and "-" in head[0] and not head[0].endswith(":"):
                mine = head[-1] == str(path)
            elif mine and head and head[0] == "Rss:":
                total += int(head[1])
    return total


def test_a_tiled_sky_run_lets_the_scene_file_pages_go_after_each_tile(sample, monkeypatch):
    """The scene's mapped pages a tile read leave the resident set after it (and after the
    camera pass): one release per tile and one after the camera pass, and the run ends with
    no array page of the scene that a release would drop (the 10^7-triangle city's tiles
    otherwise kept 1.9 of its 2.1 GB file resident); the numbers are the untiled run's."""
    import os

    import cityshade.store.scenefile as scenefile
    from cityshade.light.run import compute_sky

    if not os.path.exists("/proc/self/smaps"):
        pytest.skip("no /proc/self/smaps here (not Linux)")
    path, scene = sample
    real, calls = scenefile.release_scene_pages, []
    monkeypatch.setattr(scenefile, "release_scene_pages",
                        lambda s: calls.append(s) or real(s))
    request = _request(scene, samples_per_m2=None, vsc=False, tile_px=24)
    plain = compute_sky(scene, dataclasses.replace(request, tile_px=None))
    calls.clear()
    tiled = compute_sky(scene, request)
    assert tiled.tiles["tiles"] > 5
    assert len(calls) == tiled.tiles["tiles"] + 1 and all(s is scene for s in calls)
    left = _resident_kb(path)
    real(scene)
    assert left == _resident_kb(path) < path.stat().st_size / 1024
    _same(plain, tiled)
