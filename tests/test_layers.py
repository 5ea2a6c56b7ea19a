"""Imports follow the package's layers one way, and no modules import each other.

Every module of generator/ is read with ast, imports inside functions included (a lazy
import is an edge all the same). A module may import from its own layer or a lower one;
an import from a higher layer, or any cycle between modules, fails naming the edge.
"""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "generator"

#: Layers from the bottom: a module imports from its layer and those before it, never after.
LAYERS = (
    # small top-level modules every layer may use; the package's __init__ fixes numpy's kernels
    (
        "generator",
        "generator.tolerances",
        "generator.files",
        "generator.leftovers",
        "generator.backends",
        "generator.colour_science",
        "generator.heap",
        "generator.avx_state",
    ),
    ("generator.colorimetry",),  # the colour-space library, matrices, CATs, curves, spectra
    ("generator.gamut", "generator.rendering"),  # gamut mapping; ACES output transforms (float64)
    ("generator.spec",),  # the frozen description, checked against the library
    ("generator.reference", "generator.metrics", "generator.looks"),  # the float64 evaluation; errors
    ("generator.luts",),  # lattices, fits, LUT files
    ("generator.ocio",),  # PyOpenColorIO objects: the config, view LUTs as it runs them
    ("generator.verify",),  # probes, engines, checks, report
    ("generator.convert",),  # image conversion through a config, verified
    ("generator.cli", "generator.__main__"),  # one module per command
)


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def layer(module: str) -> int | None:
    """The layer of ``module``: that of the longest name a layer gives it or a package holding
    it (the package itself, ``generator``, holds nothing but its ``__init__``), or None."""
    names = [name for names in LAYERS for name in names if module == name or module.startswith(name + ".")]
    names = [name for name in names if name != "generator" or module == "generator"]
    if not names:
        return None
    return next(i for i, layer_names in enumerate(LAYERS) if max(names, key=len) in layer_names)


def resolve(name: str) -> str | None:
    """The module of generator ``name`` (a module, or a name inside one)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def imports(module: str) -> dict[str, int]:
    """The generator modules ``module`` imports (at any depth), each with a line that does."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found: dict[str, int] = {}
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, *([base] if base else [])])
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in MODULES else base for a in node.names]
        else:
            continue
        for target in targets:
            if target.split(".")[0] == "generator" and (resolved := resolve(target)) and resolved != module:
                found.setdefault(resolved, node.lineno)
    return found


GRAPH = {module: imports(module) for module in MODULES}


def test_every_module_has_a_layer():
    assert not [module for module in MODULES if layer(module) is None], "add them to LAYERS"


def test_no_import_from_a_higher_layer():
    upward = [
        f"{module}:{line} imports {target} ({' '.join(LAYERS[layer(target)])} is above {' '.join(LAYERS[layer(module)])})"
        for module, targets in GRAPH.items()
        for target, line in targets.items()
        if None not in (layer(target), layer(module)) and layer(target) > layer(module)
    ]
    assert not upward, "\n".join(upward)


def cycles(graph: dict[str, dict[str, int]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(graph[root]))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(graph[child])))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_no_import_cycle():
    named = [
        " <-> ".join(component)
        + ": "
        + "; ".join(f"{a}:{GRAPH[a][b]} imports {b}" for a in component for b in component if b in GRAPH[a])
        for component in cycles(GRAPH)
    ]
    assert not named, "\n".join(named)


def test_the_checks_find_an_upward_edge_and_a_cycle():
    """The walk sees a lazy import, and the two checks name what they find."""
    assert layer("generator.luts.view") > layer("generator.reference") > layer("generator.spec.load")
    assert cycles({"a": {"b": 1}, "b": {"c": 2}, "c": {"a": 3}, "d": {"a": 4}}) == [["a", "b", "c"]]
    lazy = ast.parse("def f():\n    from generator.verify import report\n")
    assert any(isinstance(node, ast.ImportFrom) for node in ast.walk(lazy))
