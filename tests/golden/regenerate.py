"""Regenerate the golden images after an intended change of the pictures.

    python tests/golden/regenerate.py

Look at every image it writes before committing them.
"""
from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from golden_cases import CASES, render_case, sample_scene  # noqa: E402

from cityshade.imageio import write_image  # noqa: E402


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        scene = sample_scene(Path(tmp))
        for name in CASES:
            path = Path(__file__).resolve().parent / f"{name}.png"
            write_image(path, render_case(scene, name))
            print(path)


if __name__ == "__main__":
    main()
