"""generator/verify's modules import one another one way, and each public name says what it is."""

from __future__ import annotations

import ast
from graphlib import CycleError, TopologicalSorter
from pathlib import Path

import pytest

import generator.verify

FOLDER = Path(generator.verify.__file__).parent
MODULES = {p.stem: ast.parse(p.read_text(encoding="utf-8")) for p in sorted(FOLDER.glob("*.py"))}


def _imported(tree: ast.Module) -> set[str]:
    """The generator.verify modules ``tree`` imports, at module level or inside a function."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module == "generator.verify":
            found |= {alias.name for alias in node.names if alias.name in MODULES}
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("generator.verify."):
            found.add(node.module.split(".")[2])
        elif isinstance(node, ast.Import):
            found |= {a.name.split(".")[2] for a in node.names if a.name.startswith("generator.verify.")}
    return found


def test_verify_modules_import_each_other_one_way():
    graph = {name: _imported(tree) - {name} for name, tree in MODULES.items()}
    try:
        tuple(TopologicalSorter(graph).static_order())
    except CycleError as error:
        pytest.fail(f"import cycle in generator/verify: {' -> '.join(error.args[1])}")


def _public(tree: ast.AST):
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, ast.FunctionDef | ast.ClassDef) and not node.name.startswith("_"):
            yield node
            if isinstance(node, ast.ClassDef):
                yield from _public(node)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_every_public_function_and_class_has_a_docstring(name):
    missing = [node.name for node in _public(MODULES[name]) if ast.get_docstring(node) is None]
    assert not missing, f"generator/verify/{name}.py: no docstring on {', '.join(missing)}"
