"""Shared test fixtures: where the real CityGML data lives, and a skip when it is absent."""
from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SHARED_DATA = REPO.parent / "shared" / "data" / "citygml"


def shared_file(relative: str) -> Path:
    """Path of a file in ``../shared/data/citygml``; skips the test when it is not there."""
    path = SHARED_DATA / relative
    if not path.exists():
        pytest.skip(f"real data not available: {path} (../shared/data/citygml is absent)")
    return path


@pytest.fixture
def shared_data() -> Path:
    if not SHARED_DATA.is_dir():
        pytest.skip(f"real data not available: {SHARED_DATA} is absent")
    return SHARED_DATA


@pytest.fixture(scope="session")
def sample_city_scene(tmp_path_factory):
    """``sample_data/sample_city.gml`` built once per test session and loaded back (read-only
    memory-mapped arrays); the modules that render the sample city share it."""
    from golden_cases import sample_scene

    return sample_scene(tmp_path_factory.mktemp("sample_city"))
