"""The package's dependencies run one way: cli → api → output/benchmarks → checks → scenes → solvers →
units/errors. Every import of every module (function-level ones included) is parsed and an import
from a higher layer fails the test, so the rule in docs/architecture.md stays true.
Inside ``solvers`` the problems (crank, platform) do not import each other, and the shared
``numerics``, ``soil`` and ``supports`` packages import neither problem."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "foundation_calc"

#: Rank of each layer: a module may import modules of its own rank or lower.
LAYER_RANK = {
    "version": 0,
    "_version": 0,
    "units": 0,
    "errors": 0,
    "references": 0,
    "solvers": 1,
    "scenes": 2,
    "checks": 3,
    "output": 4,
    "benchmarks": 4,
    "validation": 4,
    "api": 5,
    "cli": 6,
    "__main__": 7,
}
#: Solver packages that may be imported only by themselves and layers above ``solvers``.
PROBLEMS = {"crank", "platform"}
SHARED_SOLVERS = {"numerics", "soil", "supports", "constants"}


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _import_statements(path: Path, module: str | None = None) -> list[tuple[int, str, tuple[str, ...]]]:
    """``(line, absolute module name, names imported from it)`` of every foundation_calc import in
    the file at ``path``, whose own dotted name is ``module`` (derived from the path inside the
    package by default); the names are empty for ``import x``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    module = module or _module_name(path)
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name, ()) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")
                anchor = anchor[: len(anchor) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            found.append((node.lineno, base, tuple(alias.name for alias in node.names)))
    return [(line, name, names) for line, name, names in found if name.split(".")[0] == "foundation_calc"]


def _imports(path: Path, module: str | None = None) -> list[tuple[int, str]]:
    """``(line, absolute module name)`` of every foundation_calc import in the file at ``path``."""
    return [(line, name) for line, name, _ in _import_statements(path, module)]


def _layer(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else None


MODULES = sorted(PACKAGE.rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_upward_import(path: Path) -> None:
    here = _layer(_module_name(path))
    if here is None:  # foundation_calc/__init__.py: its version and the API's names, on first use
        imported = {name for _, name in _imports(path)}
        assert imported <= {"foundation_calc.version"}, "the package root must not import its layers"
        return
    assert here in LAYER_RANK, f"{path}: module outside every layer; add it to LAYER_RANK"
    for line, target in _imports(path):
        there = _layer(target)
        if there is None:
            continue
        assert there in LAYER_RANK, f"{path}:{line} imports {target}, outside every layer"
        assert LAYER_RANK[there] <= LAYER_RANK[here], (
            f"{path.relative_to(PACKAGE)}:{line} ({here}) imports {target} ({there}), a layer above it"
        )


@pytest.mark.parametrize(
    "path", sorted((PACKAGE / "solvers").rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE))
)
def test_solver_problems_stay_apart(path: Path) -> None:
    parts = _module_name(path).split(".")
    own = parts[2] if len(parts) > 2 else None
    for line, target in _imports(path):
        tparts = target.split(".")
        if len(tparts) < 3 or tparts[1] != "solvers":
            continue
        other = tparts[2]
        if other in PROBLEMS and other != own:
            assert own not in SHARED_SOLVERS | PROBLEMS, (
                f"{path.relative_to(PACKAGE)}:{line} imports {target}: the problems and the "
                "shared solver packages must not depend on another problem"
            )


def test_layers_cover_the_package() -> None:
    """Every top-level module or package of foundation_calc sits in a layer."""
    names = {p.stem for p in PACKAGE.glob("*.py")} | {p.name for p in PACKAGE.iterdir() if p.is_dir()}
    names -= {"__init__", "__pycache__", "py.typed"}
    assert names <= set(LAYER_RANK), f"outside every layer: {sorted(names - set(LAYER_RANK))}"


def test_an_upward_import_is_caught(tmp_path: Path) -> None:
    """The parser sees a function-level import (the way the CLI defers heavy modules)."""
    module = tmp_path / "m.py"
    module.write_text("def f():\n    from foundation_calc.output.console import x\n")
    assert _imports(module, "foundation_calc.solvers.m") == [(2, "foundation_calc.output.console")]
    module.write_text("from ..output import console\n")
    assert _imports(module, "foundation_calc.solvers.m") == [(1, "foundation_calc.output")]


def _import_graph() -> dict[str, set[str]]:
    """Module -> the package's modules it imports (``from package import module`` counts as the
    module, function-level imports included)."""
    modules = {_module_name(path): path for path in MODULES}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        targets = set()
        for _, base, names in _import_statements(path, name):
            submodules = {f"{base}.{n}" for n in names} & modules.keys()
            targets |= submodules or ({base} & modules.keys())
        graph[name] = targets - {name}
    return graph


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
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
                    work.append((child, iter(sorted(graph.get(child, ())))))
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


def test_no_import_circles() -> None:
    """No two modules import each other, directly or through others (a deferred import that
    breaks a circle at run time still counts): each module can be read and tested from below."""
    assert _circles(_import_graph()) == []


def test_an_import_circle_is_caught() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"e"}}
    assert _circles(graph) == [["a", "b", "c"]]


#: The scene modules of a block's supports and the crank foundation's scene: they read, validate and
#: carry the keys of ``[soil]`` and ``[piles]``; the springs and dashpots are computed in ``solvers/supports``.
SUPPORT_SCENES = ("scenes/block_soil.py", "scenes/block_piles.py", "scenes/crank.py")
#: What computes a support's springs and dashpots (the soil methods, the pile group under its cap).
SUPPORT_PHYSICS = ("foundation_calc.solvers.soil", "foundation_calc.solvers.piles.cap", "foundation_calc.solvers.piles.group")


@pytest.mark.parametrize("name", SUPPORT_SCENES)
def test_a_supports_scene_computes_no_springs(name: str) -> None:
    """A new support is one solver module plus its scene keys: the scene's tables call no soil
    method and no pile group (the physics lives in ``solvers/supports``)."""
    found = [(line, module) for line, module in _imports(PACKAGE / name) if module.startswith(SUPPORT_PHYSICS)]
    assert not found, f"{name} computes a support's springs: {found}"
