"""The Numba cache folder: keyed by the sources' content (a reinstall of the same code reuses
it, any change starts afresh) and old folders pruned."""
from __future__ import annotations

import os
import shutil
from pathlib import Path

import cityshade


def _copy_sources(dst: Path) -> Path:
    src = Path(cityshade.__file__).parent
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns("__pycache__"))
    return dst


def test_key_ignores_modification_times_and_follows_content(tmp_path):
    root = _copy_sources(tmp_path / "a")
    key = cityshade._sources_key(str(root))
    assert key == cityshade._sources_key(str(Path(cityshade.__file__).parent))
    for path in root.rglob("*.py"):          # a reinstall: same bytes, new times
        os.utime(path, (1_000_000, 1_000_000))
    (root / "__pycache__").mkdir()
    (root / "__pycache__" / "x.py").write_text("compiled elsewhere")
    assert cityshade._sources_key(str(root)) == key
    helper = root / "util.py"
    helper.write_bytes(helper.read_bytes() + b"\n# changed\n")
    assert cityshade._sources_key(str(root)) != key


NOW_S = 1_800_000_000.0


def _folders_used(parent, ages_days: dict) -> None:
    """A cache folder per name whose used-mark is that many days older than ``NOW_S``."""
    for name, age_days in ages_days.items():
        (parent / name).mkdir()
        mark = parent / name / cityshade._USED_MARK
        mark.touch()
        os.utime(mark, (NOW_S - age_days * 86400.0,) * 2)


def test_a_new_folder_prunes_old_and_surplus_ones(tmp_path):
    now = NOW_S
    _folders_used(tmp_path, {"recent1": 1, "recent2": 2, "recent3": 3, "recent4": 4,
                             "stale": 30})
    current = tmp_path / "current"
    cityshade._mark_used_and_prune(str(current), now=now)
    assert (current / cityshade._USED_MARK).exists()
    kept = sorted(p.name for p in tmp_path.iterdir() if p.name != "current")
    assert kept == ["recent1", "recent2", "recent3"]    # 30 days unused, and beyond 3 others
    # A folder in use prunes nothing more.
    (tmp_path / "recent9").mkdir()
    cityshade._mark_used_and_prune(str(current), now=now)
    assert (tmp_path / "recent9").exists()


def test_folders_in_use_are_never_pruned_however_many(tmp_path):
    """Four checkouts of other sources used within the day (their marks refreshed daily) and
    a new one: none of the four goes, though they are beyond the three others kept; a folder
    unused for five days beyond them does."""
    _folders_used(tmp_path, {"busy1": 0.1, "busy2": 0.2, "busy3": 0.3, "busy4": 1.5, "idle": 5})
    cityshade._mark_used_and_prune(str(tmp_path / "current"), now=NOW_S)
    kept = sorted(p.name for p in tmp_path.iterdir() if p.name != "current")
    assert kept == ["busy1", "busy2", "busy3", "busy4"]


_COMPILE_ONE_KERNEL = """
import cityshade  # first: it points Numba's cache at the sources' folder
import numba.core.event as ev
import numpy as np
compiled = []
class Listener(ev.Listener):
    def on_start(self, event):
        pass
    def on_end(self, event):
        compiled.append(event.data["dispatcher"].py_func.__qualname__)
ev.register("numba:compile", Listener())
from cityshade.geometry.bounds import used_vertex_box
used_vertex_box(np.zeros((2, 3), np.int64), np.zeros((3, 3)), np.zeros((2, 3)))
print(",".join(compiled))
"""


def test_a_reinstall_of_the_same_code_compiles_nothing(tmp_path):
    """The same sources written again at the same place (what ``pip install .`` does: new
    modification times) reuse the machine code: the folder is keyed by content, and so are
    Numba's own stamps of each file."""
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(XDG_CACHE_HOME=str(tmp_path / "cache"), PYTHONPATH=str(tmp_path / "site"))
    runs = []
    for install in range(2):
        shutil.rmtree(tmp_path / "site", ignore_errors=True)
        pkg = _copy_sources(tmp_path / "site" / "cityshade")
        for path in pkg.rglob("*.py"):
            os.utime(path, (1_000_000 + install, 1_000_000 + install))
        out = subprocess.run([sys.executable, "-c", _COMPILE_ONE_KERNEL], env=env,
                             capture_output=True, text=True, check=True)
        runs.append(out.stdout.strip())
    assert runs == ["used_vertex_box", ""]
