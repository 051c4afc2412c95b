"""Fixtures of the CLI tests."""
from __future__ import annotations

import pytest

from citygml_snippets import box_polygons, building, city

#: The corner of the dated box of :func:`scene_file` (model CRS metres).
BOX_X0, BOX_Y0, BOX_Z0 = 690_000.0, 5_336_000.0, 500.0


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    """One 10 × 8 × 6 m box built in 1900 (so absent in 1850), on the default ground plane,
    built once per module (a module may define its own ``scene_file``)."""
    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("box")
    src = tmp / "box.gml"
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    src.write_text(city(building("b1", box_polygons(BOX_X0, BOX_Y0, BOX_Z0, 10, 8, 6),
                                 extra=extra)))
    out, _, _ = build_file(src, tmp / "box.cityshade")
    return out
