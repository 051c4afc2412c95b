"""report.html: valid HTML5, nothing loaded from outside, every picture a PNG that reads back,
and (where Chromium is installed) a page that renders."""
from __future__ import annotations

import re
import subprocess
from datetime import date
from pathlib import Path

import numpy as np
import pytest

html5lib = pytest.importorskip("html5lib")
pytest.importorskip("matplotlib")

CHROMIUM = "/usr/bin/chromium"
AREA = (690110.0, 5336122.0, 690140.0, 5336131.0)

from htmlcheck import check_page  # noqa: E402


def test_a_page_from_markdown_embeds_its_pictures_and_parses(tmp_path):
    from cityshade import imageio
    from cityshade.present.html import figure_html, write_report_html

    rgb = np.zeros((20, 30, 3), np.uint8)
    rgb[:, :15] = (200, 30, 30)
    imageio.write_png_rgb(tmp_path / "map.png", rgb)
    md = ("# Title & more\n\nText with `code <x>` and **Verdict: FAIL** — a <b>tag</b>.\n\n"
          "![map](map.png)\n\n![gone](missing.png)\n\n## Rule A\n\n| a | b |\n|---|---:|\n"
          "| 1 | 2 |\n\n> Warning: see http://example.org/x\n")
    fig = figure_html(rgb[::-1], "an inserted map")
    out = write_report_html(tmp_path / "report.html", md, title="T",
                            after_heading={"Rule A": fig})
    pictures = check_page(out, tmp_path)
    assert len(pictures) == 2
    assert np.array_equal(pictures[0][..., :3], rgb)
    text = out.read_text()
    assert "&lt;b&gt;tag&lt;/b&gt;" in text and "<table>" in text  # raw HTML is text
    assert 'class="verdict fail"' in text and "[picture missing.png missing]" in text
    assert text.index("<h2>Rule A</h2>") < text.index("an inserted map")


@pytest.fixture(scope="module")
def compared(sample_city_scene, tmp_path_factory):
    """``compare`` of the sample city, 1750 against 1990, with BRE 209 and a garden area,
    every output written (decorated maps, report.html, results.gpkg)."""
    from cityshade.planning.rules import load_rules
    from cityshade.planning.run import CompareRequest, CompareStates, TimePlan, run_compare
    from cityshade.raster.camera import map_view

    out = tmp_path_factory.mktemp("compare")
    request = CompareRequest(
        sample_city_scene, TimePlan(date(2024, 3, 21), from_s=8 * 3600, to_s=16 * 3600,
                                    every_s=7200.0, tz="Europe/Berlin"),
        CompareStates(before="1750", after="1990"), camera=lambda s: map_view(s, 4.0),
        rules=load_rules("bre209"), area=AREA, outdir=out)
    return run_compare(request), out


def test_the_compare_report_html_is_valid_and_self_contained(compared, tmp_path):
    result, out = compared
    page = out / "report.html"
    assert page in result.written and (out / "report.md").is_file()
    pictures = check_page(page, tmp_path)
    # before, after, loss, worst (if any surface loses), and the garden rule's map.
    names = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", (out / "report.md").read_text())
    assert len(pictures) >= len(names) + 1
    text = page.read_text()
    garden = next(v for v in result.verdicts if v.rule.receivers == "area")
    assert f"{garden.rule.name}: {garden.status.upper()}" in text
    assert 'name="viewport"' in text and "@media print" in text


def test_decorated_compare_maps_hold_the_geotiff_values(compared):
    from cityshade.imageio import read_image
    from cityshade.sunhours.outputs import colour_mapped

    result, out = compared
    comp = result.comparison
    tif, _ = read_image(out / "before_h.tif")
    assert np.array_equal(np.nan_to_num(tif[..., 0], nan=-1),
                          np.nan_to_num(comp.before.hours, nan=-1))
    png, _ = read_image(out / "before.png")
    h, w = comp.before.hours.shape
    assert png.shape[0] > h and png.shape[1] >= w  # a margin around the map
    finite = np.concatenate([x[np.isfinite(x)] for x in (comp.before.hours, comp.after.hours)])
    rgb, _ = colour_mapped(comp.before.hours, max(1.0, float(np.ceil(finite.max()))))
    # The map is in the picture, pixel for pixel (found at its offset).
    hits = np.argwhere((png[:, :, :3] == rgb[0, 0]).all(axis=2))
    assert any(np.array_equal(png[r:r + h, c:c + w, :3], rgb) for r, c in hits[:2000]
               if r + h <= png.shape[0] and c + w <= png.shape[1])


@pytest.mark.skipif(not Path(CHROMIUM).exists(),
                    reason=f"{CHROMIUM} is not installed (Debian: apt-get install chromium)")
def test_chromium_renders_the_report(compared, tmp_path):
    from cityshade.imageio import read_image

    _, out = compared
    shot = tmp_path / "shot.png"
    subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                    f"--screenshot={shot}", "--window-size=900,1600",
                    (out / "report.html").resolve().as_uri()],
                   check=True, capture_output=True, timeout=120)
    pixels, _ = read_image(shot)
    grey = pixels[..., :3].astype(float).mean(axis=2)
    assert grey.std() > 10.0  # text and maps, not a blank page
    # Colour: the viridis maps are drawn (not only black text on white).
    sat = pixels[..., :3].max(axis=2).astype(int) - pixels[..., :3].min(axis=2)
    assert (sat > 80).mean() > 0.01

