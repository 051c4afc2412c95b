"""A report page's checks, shared by the tests of every command that writes ``report.html``."""
from __future__ import annotations

import base64
import re
from pathlib import Path

import numpy as np


def check_page(path: Path, tmp_path: Path) -> list[np.ndarray]:
    """Parse ``path`` strictly, refuse external URLs, decode every picture; returns them."""
    import html5lib

    from cityshade.imageio import read_image

    text = path.read_text(encoding="utf-8")
    tree = html5lib.HTMLParser(strict=True, namespaceHTMLElements=False).parse(text)
    for el in tree.iter():
        for attr in ("src", "href"):
            value = el.get(attr) or ""
            assert not re.match(r"\s*(https?:)?//", value, re.I), (el.tag, value)
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*https?://""", text, re.I)
    pictures = []
    for k, img in enumerate(tree.iter("img")):
        src = img.get("src")
        assert src.startswith("data:image/png;base64,"), src[:40]
        data = base64.b64decode(src.split(",", 1)[1], validate=True)
        assert data.startswith(b"\x89PNG\r\n\x1a\n")
        png = tmp_path / f"img{k}.png"
        png.write_bytes(data)
        pixels, _ = read_image(png)
        assert pixels.ndim == 3 and pixels.shape[0] > 0 and pixels.shape[1] > 0
        pictures.append(pixels)
    return pictures
