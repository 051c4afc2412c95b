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


def test_a_new_folder_prunes_old_and_surplus_ones(tmp_path):
    day = 86400.0
    now = 1_800_000_000.0
    ages = {"recent1": 1, "recent2": 2, "recent3": 3, "recent4": 4, "stale": 30}
    for name, age_days in ages.items():
        (tmp_path / name).mkdir()
        mark = tmp_path / name / cityshade._USED_MARK
        mark.touch()
        os.utime(mark, (now - age_days * day,) * 2)
    current = tmp_path / "current"
    cityshade._mark_used_and_prune(str(current), now=now)
    assert (current / cityshade._USED_MARK).exists()
    kept = sorted(p.name for p in tmp_path.iterdir() if p.name != "current")
    assert kept == ["recent1", "recent2", "recent3"]    # 30 days unused, and beyond 3 others
    # A folder in use prunes nothing more.
    (tmp_path / "recent9").mkdir()
    cityshade._mark_used_and_prune(str(current), now=now)
    assert (tmp_path / "recent9").exists()
