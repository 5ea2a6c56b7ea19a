"""Every public function, method and class of generator/ says in a docstring what it is or does.

Each module is read with ast. Public: a function or class, at module level or in a class's
body (a private class's included: its methods are its interface), whose name has no leading
underscore. Functions defined inside functions are not.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "generator"
MODULES = sorted(p.relative_to(PACKAGE.parent).as_posix() for p in PACKAGE.rglob("*.py"))

Definition = ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef


def public(tree: ast.AST, prefix: str = "") -> Iterator[tuple[str, Definition]]:
    """The public definitions directly in ``tree`` and in the bodies of its classes: qualified name, node."""
    for node in ast.iter_child_nodes(tree):
        if not isinstance(node, Definition):
            continue
        name = f"{prefix}{node.name}"
        if not node.name.startswith("_"):
            yield name, node
        if isinstance(node, ast.ClassDef):
            yield from public(node, f"{name}.")


def undocumented(path: Path) -> list[str]:
    """``line name`` of each public definition in the module at ``path`` without a docstring."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return [f"{node.lineno} {name}" for name, node in public(tree) if ast.get_docstring(node) is None]


@pytest.mark.parametrize("module", MODULES)
def test_every_public_function_method_and_class_has_a_docstring(module):
    missing = undocumented(PACKAGE.parent / module)
    assert not missing, f"{module}: no docstring on " + ", ".join(missing)


def test_the_check_names_what_lacks_a_docstring(tmp_path):
    source = tmp_path / "sample.py"
    source.write_text(
        'def shown():\n    """Said."""\n\n\ndef bare():\n    pass\n\n\ndef _private():\n    pass\n\n\n'
        "class Record:\n    def method(self):\n        def inner():\n            pass\n\n    def _hidden(self):\n        pass\n\n\n"
        'class _Private:\n    """Said."""\n\n    def read(self):\n        pass\n',
        encoding="utf-8",
    )
    assert undocumented(source) == ["5 bare", "13 Record", "14 Record.method", "25 _Private.read"]
