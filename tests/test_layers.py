"""The runtime's folders are its pipeline, model → free → forced → maps → identify → report →
cli, and imports flow that way only: no module imports from a folder after its own (read from the
source's import statements, lazy ones inside functions included).  ``errors``, ``io``, ``_interrupt``,
``_pool`` (local worker processes, for the maps and a curve's multi-start), ``budgets`` (the forced computations' work budgets, which the command line reads without
importing the forced package), ``export`` and the generated kernels serve every folder and import
none of them.

Inside forced/ the same holds for its folders, engine → (forced/'s own modules) → orbits → loads:
the compiled engine imports nothing that checks or analyses its runs, the orbits nothing of the
sampled loads."""

from __future__ import annotations

import ast
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "src" / "symimpact"
LAYERS = ["model", "free", "forced", "maps", "identify", "report", "cli"]
SHARED = {
    "errors",
    "_compiled",
    "io",
    "_interrupt",
    "_notices",
    "_pool",
    "_progress",
    "_threads",
    "budgets",
    "export",
    "generated",
}


#: forced/'s folders in their order; "" is forced/'s own modules (the forcing, the contact laws,
#: the checked simulations on the engine).
FORCED = ["engine", "", "orbits", "loads"]


def _rank(part: str) -> int:
    return -1 if part in SHARED else LAYERS.index(part)


def _imports(path: Path):
    """(line, the top-level part of symimpact imported) of every relative import in ``path``."""
    rel = path.relative_to(PKG).parts
    package = list(rel[:-1])
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.level > 0:
            base = package[: len(package) - (node.level - 1)]
            target = base + (node.module.split(".") if node.module else [])
            for alias in node.names:
                full = target if target else [alias.name]
                yield node.lineno, full[0]
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("symimpact."):
            yield node.lineno, node.module.split(".")[1]


def _layer(path: Path) -> str:
    rel = path.relative_to(PKG).parts
    return rel[0] if len(rel) > 1 else Path(rel[0]).stem


MODULES = sorted(
    p for p in PKG.rglob("*.py") if "generated" not in p.parts and p != PKG / "__init__.py"
)


def _forced_imports(path: Path):
    """(line, forced/'s folder imported, "" for its own modules) of every import of a module of
    forced/ in ``path``, relative or absolute."""
    rel = path.relative_to(PKG).parts
    package = ["symimpact", *rel[:-1]]
    for node in ast.walk(ast.parse(path.read_text())):
        if not isinstance(node, ast.ImportFrom):
            continue
        if node.level > 0:
            base = package[: len(package) - (node.level - 1)]
            target = base + (node.module.split(".") if node.module else [])
        else:
            target = (node.module or "").split(".")
        if target[:2] != ["symimpact", "forced"]:
            continue
        for alias in node.names:
            full = target[2:] if len(target) > 2 else [alias.name]
            yield node.lineno, full[0] if full[0] in FORCED else ""


def _forced_folder(path: Path) -> str:
    rel = path.relative_to(PKG / "forced").parts
    return rel[0] if len(rel) > 1 else ""


FORCED_MODULES = [p for p in MODULES if p.is_relative_to(PKG / "forced")]


@pytest.mark.parametrize("path", FORCED_MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_forced_imports_flow_down_its_folders(path):
    folder = _forced_folder(path)
    for line, part in _forced_imports(path):
        assert FORCED.index(part) <= FORCED.index(folder), (
            f"{path.relative_to(PKG)}:{line} imports from forced/{part or '(its own modules)'}, "
            f"which comes after forced/{folder or '(its own modules)'}"
        )


def test_the_forced_checker_sees_an_upward_import(monkeypatch):
    """The check above can fail: the engine importing the continuation is caught, and so is a
    relative import of forced/'s own modules from the engine."""
    fake = PKG / "forced" / "engine" / "_modal.py"
    text = "from ..orbits import continuation\nfrom ..simulation import Steady\n"
    monkeypatch.setattr(Path, "read_text", lambda self, *a, **k: text)
    assert [part for _, part in _forced_imports(fake)] == ["orbits", ""]
    assert _forced_folder(fake) == "engine"


def test_no_module_of_forced_is_over_its_size():
    """forced/ shows its pipeline in modules of readable size: none over 1 500 lines (issue 79;
    the N-mode engine, 3 066 lines, is four modules: its flight, searches, ledger and run)."""
    over = {
        p.relative_to(PKG).as_posix(): len(p.read_text().splitlines())
        for p in FORCED_MODULES
        if len(p.read_text().splitlines()) > 1500
    }
    assert not over, over


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_imports_flow_one_way(path):
    layer = _layer(path)
    assert layer in SHARED or layer in LAYERS, f"{path.name} is in no folder of the pipeline"
    for line, part in _imports(path):
        if part not in SHARED and part not in LAYERS:
            continue  # a module of the same folder (a relative import within it)
        assert _rank(part) <= _rank(layer), (
            f"{path.relative_to(PKG)}:{line} imports from {part}/, which comes after {layer}/"
        )


def test_the_checker_sees_an_upward_import(tmp_path, monkeypatch):
    """The check above can fail: a model module importing from forced/ is caught."""
    fake = PKG / "model" / "units.py"
    text = "from ..forced import budgets\n"
    monkeypatch.setattr(Path, "read_text", lambda self, *a, **k: text)
    found = [part for _, part in _imports(fake)]
    assert found == ["forced"] and _rank("forced") > _rank(_layer(fake))


def test_every_folder_ships():
    """Each folder of the runtime is a package that pyproject.toml installs."""
    listed = set(
        tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"]
    )
    folders = {
        "symimpact." + p.parent.relative_to(PKG).as_posix().replace("/", ".")
        for p in PKG.rglob("__init__.py")
        if p.parent != PKG
    }
    assert folders <= listed, f"not installed: {sorted(folders - listed)}"
