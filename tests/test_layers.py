"""The direction of the imports: core -> tracking -> studies -> claims -> tools, the drawings
beside them, the book's helpers on top, and no circle.

Read from the source with :mod:`ast` (no module is imported), module by module, counting imports
inside functions too: an import deferred to a call is still a dependency.

- A module imports only modules of its own layer or of the layers below it.
- ``obslib.viz`` may import the core, ``tracking`` and ``studies``; nothing in ``obslib`` imports
  ``viz`` (the notebooks and ``obsbook`` draw with it).
- ``obsbook`` sits on top: ``obslib`` never imports it.
- No circle of imports, within a layer or across.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SOURCES = sorted([*(ROOT / "obslib").rglob("*.py"), *(ROOT / "obsbook").rglob("*.py")])

#: The layers from the bottom; a module belongs to the first prefix it matches. ``obslib`` (the
#: package's namespace) offers the core and ``obslib.tracking`` at the top level.
LAYERS = {
    "obslib": 0,  # every module not in a subpackage below: the paper's numerics, profiles
    "obslib.tracking": 1,
    "obslib.studies": 2,
    "obslib.viz": 2.5,
    "obslib.claims": 3,
    "obslib.tools": 4,
    "obslib.run": 4,
    "obslib.bench": 4,
    "obsbook": 5,
}

#: What each layer may import besides itself and the layers below it.
EXTRA = {"obslib": {"obslib.tracking"}}  # the package namespace: ``ob.tracking.simulate``


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def is_module(name: str) -> bool:
    p = ROOT.joinpath(*name.split("."))
    return p.with_suffix(".py").is_file() or (p / "__init__.py").is_file()


def imports(path: Path, source: str | None = None) -> set[str]:
    """The modules of obslib and obsbook that the file ``path`` (or ``source`` as if it were that
    file) imports, at any depth of its code: ``from pkg import name`` counts as ``pkg.name``
    when that is a module, else as ``pkg``."""
    tree = ast.parse(path.read_text() if source is None else source)
    package = module_name(path).split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - (node.level - 1)]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            for a in node.names:
                found.add(f"{mod}.{a.name}" if is_module(f"{mod}.{a.name}") else mod)
    return {m for m in found if m.split(".")[0] in ("obslib", "obsbook")}


def layer(module: str) -> tuple[str, float]:
    best = max((p for p in LAYERS if module == p or module.startswith(p + ".")), key=len)
    return best, LAYERS[best]


GRAPH = {module_name(p): imports(p) for p in SOURCES}


def test_the_import_reader():
    probe = ROOT / "obslib" / "studies" / "probe.py"
    src = ("from .. import tracking\nfrom ..bounds import pair_bounds\n"
           "def f():\n    from ..viz import tracking as v\n    import obsbook.report\n")
    assert imports(probe, src) == {"obslib.tracking", "obslib.bounds", "obslib.viz.tracking",
                                   "obsbook.report"}
    assert layer("obslib.studies.two_sensors_tracking") == ("obslib.studies", 2)
    assert layer("obslib._validate") == ("obslib", 0)
    assert len(GRAPH) > 80 and GRAPH["obslib.claims.two_sensors_tracking"]


def test_imports_point_down():
    wrong = []
    for mod, deps in GRAPH.items():
        name, rank = layer(mod)
        for dep in deps:
            dep_name, dep_rank = layer(dep)
            if dep_name == "obslib.viz" and name not in ("obslib.viz", "obsbook"):
                wrong.append(f"{mod} -> {dep} (only obsbook and the notebooks draw)")
            elif dep_rank > rank and dep_name not in EXTRA.get(name, ()):
                wrong.append(f"{mod} ({name}) -> {dep} ({dep_name})")
    assert not wrong, "imports against the layers:\n" + "\n".join(sorted(wrong))


def circles(graph: dict) -> list:
    """The circles of ``graph`` (module -> imported modules): its strongly connected components
    of two or more modules, and the modules that import themselves (Tarjan's algorithm)."""
    index, low, stack, on, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1 or v in graph[v]:
                found.append(sorted(comp))

    for v in graph:
        if v not in index:
            visit(v)
    return found


def test_circles_are_found():
    assert circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert circles({"a": {"a"}, "b": set()}) == [["a"]]
    assert circles({"a": {"b"}, "b": set()}) == []


def test_no_circle_of_imports():
    assert not circles(GRAPH), f"circles of imports: {circles(GRAPH)}"
