"""``report.html``: a report's Markdown as one self-contained page that opens in any browser.

The page is the report's own Markdown (``report.md`` as written) converted by markdown-it-py
(CommonMark with tables; raw HTML in the text is not passed through), with every picture the
Markdown names read from the output folder and embedded as a ``data:image/png;base64`` URI,
pictures made for the page only (a rule's map) inserted after their heading, and inline CSS
that reads on a phone (one column, pictures and tables no wider than the screen, tables
scrolling sideways) and prints (no scrolling boxes, no breaks inside a picture or row). No
external URL: the page loads nothing.
"""
from __future__ import annotations

import base64
import re
from pathlib import Path
from typing import Mapping

import numpy as np

from cityshade.errors import OutputError

__all__ = ["png_bytes", "figure_html", "report_html", "write_report_html", "CSS"]

#: The page's style: system fonts, one readable column, a print layout.
CSS = """
body{font:16px/1.5 system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,sans-serif;
 margin:0 auto;max-width:62rem;padding:.75rem 1rem 2rem;color:#1d1d1d;background:#fff}
h1{font-size:1.55rem;margin:.5rem 0 1rem}
h2{font-size:1.25rem;border-bottom:1px solid #ccc;padding-bottom:.2rem;margin-top:2rem}
h3{font-size:1.08rem;margin-top:1.5rem}
img{max-width:100%;height:auto;display:block;margin:.25rem 0}
figure{margin:1rem 0}figcaption{font-size:.9rem;color:#444}
table{border-collapse:collapse;display:block;overflow-x:auto;max-width:100%;font-size:.88rem;
 margin:.75rem 0}
th,td{border:1px solid #c8c8c8;padding:.2rem .45rem;vertical-align:top}
th{background:#f1f1f1}td img{min-width:9rem}
code{font-size:.88em;background:#f3f3f3;padding:0 .2em;border-radius:3px;
 overflow-wrap:anywhere}
blockquote{border-left:4px solid #d39e00;margin:1rem 0;padding:.2rem .9rem;background:#fff8e1}
.verdict{padding:.05rem .4rem;border-radius:3px}
.verdict.pass{background:#d4edda;color:#0f4d1f}.verdict.fail{background:#f8d7da;color:#6f1720}
.verdict.na{background:#e9e9e9;color:#333}
footer{margin-top:2rem;font-size:.8rem;color:#555}
@media print{body{max-width:none;font-size:10.5pt;padding:0}
 table{display:table;overflow:visible}h2,h3{break-after:avoid}
 img,figure,tr{break-inside:avoid}}
"""

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png_bytes(rgb: np.ndarray) -> bytes:
    """A (H, W, 3) uint8 picture encoded as PNG in memory (matplotlib's writer, the ``[plot]``
    extra)."""
    import io

    from matplotlib.image import imsave

    buf = io.BytesIO()
    imsave(buf, np.asarray(rgb, np.uint8), format="png")
    return buf.getvalue()


def _data_uri(data: bytes) -> str:
    return "data:image/png;base64," + base64.b64encode(data).decode("ascii")


def _escape(text: str) -> str:
    """HTML text as markdown-it-py escapes it (``&``, ``<``, ``>``, ``"``)."""
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))


def figure_html(picture: np.ndarray | bytes, caption: str, alt: str | None = None) -> str:
    """A ``<figure>`` with the picture (an (H, W, 3) uint8 array or PNG bytes) embedded."""
    data = picture if isinstance(picture, bytes) else png_bytes(picture)
    return (f'<figure><img src="{_data_uri(data)}" alt="{_escape(alt or caption)}">'
            f"<figcaption>{_escape(caption)}</figcaption></figure>\n")


def _embed_images(tokens, folder: Path, images: Mapping[str, bytes]) -> None:
    """Every image token's ``src`` → a data URI of the PNG it names (given in ``images``, or
    the file in ``folder``, also one still pending in an output group); a missing or non-PNG
    picture becomes its alt text."""
    from cityshade.util import pending_path

    for token in tokens:
        for child in token.children or ():
            if child.type != "image":
                continue
            src = child.attrGet("src") or ""
            data = images.get(src)
            if data is None and "/" not in src and "\\" not in src and src:
                path = pending_path(folder / src)
                data = path.read_bytes() if path.is_file() else None
            if data is None or not data.startswith(_PNG_SIGNATURE):
                child.type = "text"
                child.content = f"[picture {src} missing]"
                child.children = None
                continue
            child.attrSet("src", _data_uri(data))


def report_html(markdown_text: str, folder, *, title: str,
                images: Mapping[str, bytes] | None = None,
                after_heading: Mapping[str, str] | None = None) -> str:
    """The page of a report.

    Parameters
    ----------
    markdown_text : str
        The report (``report.md``'s text).
    folder : path-like
        Where the pictures it names are.
    title : str
        The page's ``<title>``.
    images : mapping of name → PNG bytes, optional
        Pictures named in the Markdown that are not (yet) files.
    after_heading : mapping of heading text → HTML, optional
        Fragments (:func:`figure_html`) placed right after the first heading with that text.
    """
    from markdown_it import MarkdownIt

    from cityshade import __version__

    md = MarkdownIt("commonmark", {"html": False}).enable("table")
    env: dict = {}
    tokens = md.parse(markdown_text, env)
    _embed_images(tokens, Path(folder), images or {})
    body = md.renderer.render(tokens, md.options, env)
    for heading, fragment in (after_heading or {}).items():
        body = re.sub(rf"(<h[1-6]>{re.escape(_escape(heading))}</h[1-6]>\n)",
                      lambda m: m.group(1) + fragment, body, count=1)
    body = re.sub(r"<strong>Verdict: (PASS|FAIL|NOT ASSESSED)</strong>",
                  lambda m: f'<strong class="verdict {_status_class(m.group(1))}">Verdict: '
                            f"{m.group(1)}</strong>", body)
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<title>{_escape(title)}</title>\n<style>{CSS}</style>\n</head>\n<body>\n"
            f"<main>\n{body}</main>\n<footer>Made by cityshade {_escape(__version__)}; "
            "this page is self-contained (pictures embedded, nothing loaded).</footer>\n"
            "</body>\n</html>\n")


def _status_class(status: str) -> str:
    return {"PASS": "pass", "FAIL": "fail"}.get(status, "na")


def write_report_html(path, markdown_text: str, *, title: str,
                      images: Mapping[str, bytes] | None = None,
                      after_heading: Mapping[str, str] | None = None) -> Path:
    """Write :func:`report_html` of ``markdown_text`` (pictures from ``path``'s folder) to
    ``path`` (atomically; inside an output group, with the group).

    Raises
    ------
    OutputError
        A picture named in ``images`` is not PNG, or the file cannot be written.
    """
    from cityshade.util import write_text_atomic

    path = Path(path)
    for name, data in (images or {}).items():
        if not data.startswith(_PNG_SIGNATURE):
            raise OutputError(f"the picture {name} for the report is not a PNG", path=str(path))
    text = report_html(markdown_text, path.parent, title=title, images=images,
                       after_heading=after_heading)
    return write_text_atomic(path, text, what="the HTML report")
