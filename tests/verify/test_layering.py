"""generator/verify's modules import one another one way (docstrings: tests/test_docstrings.py)."""

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
