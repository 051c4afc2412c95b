"""Image regression: small renders of the sample city against committed goldens.

Tolerance: at most 0.1 % of pixels may differ by more than 2/255. On failure the rendered,
reference and difference images are written to test_output/ (paths in the message).
Regenerate after an intended change with ``python tests/golden/regenerate.py``.
"""
from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from golden_cases import CASES, REPO, render_case
from imagediff import assert_matches_golden


@pytest.fixture(scope="module")
def scene(sample_city_scene):
    return sample_city_scene


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_golden(scene, name):
    assert_matches_golden(name, render_case(scene, name))


def test_identical_run_to_run_and_across_thread_counts(scene, tmp_path):
    """The same picture with 1 and 2 Numba threads (in fresh processes)."""
    code = ("import sys, numpy as np; sys.path.insert(0, 'tests');"
            "from pathlib import Path; from golden_cases import render_case, sample_scene;"
            "s = sample_scene(Path(sys.argv[1])); np.save(sys.argv[2], render_case(s, 'sample_overview_1990'))")
    images = []
    for threads in ("1", "2"):
        out = tmp_path / f"t{threads}.npy"
        (tmp_path / threads).mkdir()
        env = dict(os.environ, NUMBA_NUM_THREADS=threads)
        subprocess.run([sys.executable, "-c", code, str(tmp_path / threads), str(out)], cwd=REPO,
                       env=env, check=True)
        images.append(np.load(out))
    assert np.array_equal(images[0], images[1])
    assert np.array_equal(images[0], render_case(scene, "sample_overview_1990"))
