"""Shared test fixtures: where the real CityGML data lives, and a skip when it is absent."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]

#: Source for a probe process: ``compiled`` gets the name of every kernel Numba compiles.
COMPILE_EVENTS = """
from numba.core import event
compiled = []
class L(event.Listener):
    def on_start(self, ev): compiled.append(ev.data["dispatcher"].py_func.__name__)
    def on_end(self, ev): pass
event.register("numba:compile", L())
"""
SHARED_DATA = REPO.parent / "shared" / "data" / "citygml"

# The commands' parallel first compile (cityshade.runtime.prewarm) is off in the tests (the
# test workers use the cores already); tests/runtime/test_prewarm.py turns it on where it tests it.
os.environ["CITYSHADE_PREWARM"] = "0"


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


@pytest.fixture(scope="session")
def dated_box_file(tmp_path_factory):
    """A scene file of one 10 × 8 × 6 m box built in 1900 (so absent in 1850), on the default
    ground plane, built once per session (the CLI tests of messages and conventions)."""
    from citygml_snippets import box_polygons, building, city

    from cityshade.build import build_file

    tmp = tmp_path_factory.mktemp("dated_box")
    src = tmp / "box.gml"
    extra = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>"
    src.write_text(city(building("b1", box_polygons(690_000.0, 5_336_000.0, 500.0, 10, 8, 6),
                                 extra=extra)))
    out, _, _ = build_file(src, tmp / "box.cityshade")
    return out


def run_with_and_without_jit(script: str) -> list:
    """Run ``script`` (``python -c``, the tests folder as ``sys.argv[1]``) with
    ``NUMBA_DISABLE_JIT=1`` and ``=0``; returns the JSON of each run's last output line."""
    import json
    import os
    import subprocess
    import sys

    results = []
    for disable in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=disable)
        out = subprocess.run([sys.executable, "-c", script, str(Path(__file__).parent)],
                             env=env, capture_output=True, text=True, timeout=300)
        assert out.returncode == 0, out.stderr[-2000:]
        results.append(json.loads(out.stdout.strip().splitlines()[-1]))
    return results


@pytest.fixture
def stop_batch_after(monkeypatch):
    """``stop_batch_after(n)``: the next ``cityshade batch`` in this process stops with a
    Ctrl-C once ``n`` sun positions are done (its state saved, as after a real one);
    ``stop_batch_after(None)`` lets the batches run through again."""
    from cityshade.cli import batch as batch_cli

    step = batch_cli.Progress.step

    def stop(n):
        def stopping(self, done, total, unit):
            step(self, done, total, unit)
            if done == n:
                raise KeyboardInterrupt

        monkeypatch.setattr(batch_cli.Progress, "step", step if n is None else stopping)

    return stop
