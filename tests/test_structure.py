"""Module boundaries of the package (DESIGN §13): no private names imported across modules,
and the evaluate package used only by itself and its CLI command."""
import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "cityshade"


def _imports():
    for path in sorted(SRC.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and \
                    node.module.startswith("cityshade"):
                yield path.relative_to(SRC).as_posix(), node


def test_no_private_name_is_imported_across_modules():
    found = [f"{path}: from {node.module} import {alias.name}"
             for path, node in _imports() for alias in node.names
             if alias.name.startswith("_") and not alias.name.startswith("__")]
    assert found == []


def test_evaluate_is_imported_only_by_itself_and_its_command():
    found = [f"{path}: from {node.module}" for path, node in _imports()
             if node.module.split(".")[:2] == ["cityshade", "evaluate"]
             and not path.startswith("evaluate/") and path != "cli/evaluate.py"]
    assert found == []
