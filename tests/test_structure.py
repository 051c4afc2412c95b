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


# --- the import direction between folders (docs/DESIGN.md, the map) -----------------------------

#: The stages of the package from the bottom up: a folder (or top-level module) may import itself
#: and what stands in an earlier tier, nothing in its own tier or later. Declared once, here and in
#: docs/DESIGN.md's map. ``cityshade`` is the package's ``__init__`` (its ``__version__``).
TIERS: list[set[str]] = [
    {"errors"},
    {"util", "runtime", "plotting", "halffloat"},
    {"cityshade"},
    {"geo", "accel"},
    {"config", "imageio"},
    {"citygml"},
    {"cityjson"},
    {"geometry"},
    {"trace"},
    {"raster"},
    {"lightspace"},
    {"shadows"},
    {"store"},
    {"present"},
    {"frame"},
    {"build"},
    {"sunhours"},
    {"light"},
    {"meshes"},
    {"planning"},
    {"study"},
    {"evaluate", "samplegen"},
    {"cli"},
    {"__main__"},
]


def stage_of(module: str) -> str:
    """The tier name of a dotted module (``cityshade.store.tiled`` → ``store``)."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "cityshade"


def package_imports(src: Path = SRC):
    """(importing module, imported module, line) of every import of cityshade in ``src``:
    module-level, function-level and type-checking imports alike."""
    for path in sorted(src.rglob("*.py")):
        rel = path.relative_to(src).with_suffix("")
        parts = ["cityshade", *rel.parts]
        if parts[-1] == "__init__":
            parts.pop()
        here = ".".join(parts)
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0 \
                    and node.module.split(".")[0] == "cityshade":
                for alias in node.names:
                    # ``from cityshade import imageio`` imports the module cityshade.imageio
                    target = node.module
                    if target == "cityshade" and alias.name != "__version__":
                        target = f"cityshade.{alias.name}"
                    yield here, target, node.lineno
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.split(".")[0] == "cityshade":
                        yield here, alias.name, node.lineno


def import_violations(src: Path = SRC) -> list[str]:
    """Every import that runs against :data:`TIERS`, and every module not placed in a tier."""
    rank = {name: i for i, tier in enumerate(TIERS) for name in tier}
    found = []
    for here, target, line in package_imports(src):
        a, b = stage_of(here), stage_of(target)
        for name in (a, b):
            if name not in rank:
                found.append(f"{here}:{line}: {name!r} is in no tier of tests/test_structure.py")
        if a == b or a not in rank or b not in rank:
            continue
        if rank[b] >= rank[a]:
            found.append(f"{here}:{line}: {a} imports {target} ({b} is not below {a})")
    return sorted(set(found))


def test_imports_run_one_way_between_folders():
    """No import cycle between folders: each folder imports only the tiers below it (module-
    and function-level imports counted)."""
    assert import_violations() == []


def test_the_import_rule_catches_an_upward_import(tmp_path):
    """The check fails on a layout that breaks the rule: an engine importing the store."""
    (tmp_path / "trace").mkdir()
    (tmp_path / "store").mkdir()
    (tmp_path / "trace" / "__init__.py").write_text(
        "def f():\n    from cityshade.store.tiled import TiledCache\n", encoding="utf-8")
    (tmp_path / "store" / "tiled.py").write_text("from cityshade.trace import f\n",
                                                  encoding="utf-8")
    (tmp_path / "batch.py").write_text("import cityshade.trace\n", encoding="utf-8")
    found = import_violations(tmp_path)
    assert any("trace imports cityshade.store.tiled" in f for f in found)
    assert any("'batch' is in no tier" in f for f in found)
    assert not any(f.startswith("cityshade.store.tiled") for f in found)


def test_at_most_eight_modules_at_the_top_level():
    top = sorted(p.stem for p in SRC.glob("*.py") if p.stem not in ("__init__", "__main__"))
    assert len(top) <= 8, top


# --- sizes that keep the code readable (issue 36) -------------------------------------------------

def _functions():
    """(path, function node, is a Numba kernel, is a click command) of every function in src."""
    for path in sorted(SRC.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                decorators = [ast.unparse(d) for d in node.decorator_list]
                kernel = any("jit" in d or "vectorize" in d for d in decorators)
                command = any(".command" in d or d.startswith("command") for d in decorators)
                yield path.relative_to(SRC).as_posix(), node, kernel, command


def _parameters(node) -> int:
    a = node.args
    names = [*a.posonlyargs, *a.args, *a.kwonlyargs]
    n = len(names) + (a.vararg is not None) + (a.kwarg is not None)
    return n - (bool(names) and names[0].arg in ("self", "cls"))


def test_no_python_function_over_120_lines():
    long = [f"{path}:{node.lineno} {node.name} {node.end_lineno - node.lineno + 1}"
            for path, node, kernel, _ in _functions()
            if not kernel and node.end_lineno - node.lineno + 1 > 120]
    assert long == []


def test_no_library_function_over_12_parameters():
    many = [f"{path}:{node.lineno} {node.name} {_parameters(node)}"
            for path, node, kernel, _ in _functions()
            if not kernel and not path.startswith("cli/") and _parameters(node) > 12]
    assert many == []


def test_click_command_bodies_are_thin():
    """A command parses, builds the request, calls the library: at most 80 lines of body."""
    thick = [f"{path}:{node.lineno} {node.name} {node.end_lineno - node.body[0].lineno + 1}"
             for path, node, _, command in _functions()
             if command and node.end_lineno - node.body[0].lineno + 1 > 80]
    assert thick == []


def test_every_error_class_lives_in_errors_py():
    """The library's error classes are declared in one place (the CLI's own exit signals
    excepted)."""
    stray = []
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC).as_posix()
        if rel == "errors.py" or rel.startswith("cli/"):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef) and any(
                    ast.unparse(b).split(".")[-1].endswith(("Error", "Exception"))
                    for b in node.bases):
                stray.append(f"{rel}:{node.lineno} {node.name}")
    assert stray == []
