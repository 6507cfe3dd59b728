"""The library's layout rules, checked on the source tree (AST, no import of the modules).

- No module imports another module's private name (``from .bounds import _x`` or ``bounds._x``);
  private modules (``obslib/_kernels.py``, ``obslib/_validate.py``, ...) are shared inside the
  package and may be imported freely.
- Every module is at most :data:`MAX_LINES` lines and opens with a one-sentence docstring (line
  widths and the rest of the code style are ruff's, in ``tests/test_lint.py``).
- Only ``obslib/viz`` imports matplotlib (the notebooks' figure settings are the book's own,
  in ``obsbook``).
- Nothing in the repository refers to files outside it.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "obslib"
MODULES = sorted(PACKAGE.rglob("*.py"))
MAX_LINES = 700

#: Modules allowed to import matplotlib besides obslib/viz: none.
MATPLOTLIB_OUTSIDE_VIZ: set = set()

def rel(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def resolve(path: Path, node: ast.ImportFrom) -> str:
    """Absolute module of ``from <module> import ...`` in the file ``path``."""
    if not node.level:
        return node.module or ""
    package = module_name(path).split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    base = package[: len(package) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def is_module(name: str) -> bool:
    p = ROOT.joinpath(*name.split("."))
    return p.with_suffix(".py").is_file() or (p / "__init__.py").is_file()


def private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def private_imports(path: Path, source: str | None = None) -> list[str]:
    """``from M import _x`` and ``M._x`` with ``M`` a public module, in the file ``path`` (or in
    ``source`` as if it were that file)."""
    tree = ast.parse(path.read_text() if source is None else source)
    found, modules = [], {}  # local name -> absolute module, for attribute access
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.asname:
                    modules[a.asname] = a.name
        elif isinstance(node, ast.ImportFrom):
            mod = resolve(path, node)
            for a in node.names:
                full = f"{mod}.{a.name}"
                if is_module(full):  # a submodule: private ones are shared inside the package
                    modules[a.asname or a.name] = full
                elif private(a.name) and not private(mod.split(".")[-1]):
                    found.append(f"{rel(path)}:{node.lineno}: from {mod} import {a.name}")
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and private(node.attr)
            and node.value.id in modules
            and not private(modules[node.value.id].split(".")[-1])
        ):
            found.append(f"{rel(path)}:{node.lineno}: {modules[node.value.id]}.{node.attr}")
    return found


def test_the_import_resolution_of_this_test():
    # the checks below are only as good as resolve(): spot checks on known files
    node = ast.parse("from ..bounds import pair_bounds").body[0]
    assert resolve(PACKAGE / "studies" / "teams.py", node) == "obslib.bounds"
    node = ast.parse("from . import tracking").body[0]
    assert resolve(PACKAGE / "__init__.py", node) == "obslib"
    assert (
        is_module("obslib._kernels")
        and is_module("obslib.studies")
        and not is_module("obslib.bounds.pair_bounds")
    )
    probe = PACKAGE / "studies" / "probe.py"
    assert private_imports(probe, "from ..bounds import _x\n") == [
        "obslib/studies/probe.py:1: from obslib.bounds import _x"
    ]
    assert (
        private_imports(probe, "from .._kernels import pair_kernel, _y\nfrom .. import _kernels\n")
        == []
    )
    assert private_imports(probe, "import obslib.bounds as b\nb._y\n") == [
        "obslib/studies/probe.py:2: obslib.bounds._y"
    ]
    assert private_imports(probe, "from .. import bounds\nbounds._z\n") == [
        "obslib/studies/probe.py:2: obslib.bounds._z"
    ]


def test_no_module_imports_a_private_name_of_another():
    found = [line for p in MODULES for line in private_imports(p)]
    assert not found, "private names imported across modules:\n" + "\n".join(found)


def test_module_length():
    long = [f"{rel(p)}: {n} lines" for p in MODULES
            if (n := len(p.read_text().splitlines())) > MAX_LINES]
    assert not long, f"modules over {MAX_LINES} lines:\n" + "\n".join(long)


#: Abbreviations whose period does not end a sentence.
ABBREVIATIONS = re.compile(r"\b(Figs?|Eqs?|Secs?|Thms?|al|cf|e\.g|i\.e|vs|etc)\.")


def _opening_sentence_problem(path: Path) -> str | None:
    doc = ast.get_docstring(ast.parse(path.read_text()))
    if not (doc and doc.strip()):
        return f"{rel(path)} has no module docstring"
    first = " ".join(doc.strip().split("\n\n")[0].split())
    text = ABBREVIATIONS.sub("", first)
    breaks = re.findall(r"[.?!]\s+(?=[A-Z])", text)  # a sentence ends and the next begins
    if not text.endswith((".", "?")) or breaks:
        return f"{rel(path)}: {first!r}"
    return None


def test_every_module_opens_with_a_one_sentence_docstring():
    # the opening paragraph says in one sentence what the module is for
    found = [m for p in MODULES if (m := _opening_sentence_problem(p))]
    assert not found, "opening paragraphs that are not one sentence:\n" + "\n".join(found)


def test_matplotlib_only_in_viz():
    found = []
    for p in MODULES:
        if rel(p).startswith("obslib/viz/") or rel(p) in MATPLOTLIB_OUTSIDE_VIZ:
            continue
        for node in ast.walk(ast.parse(p.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            found += [
                f"{rel(p)}:{node.lineno}: {n}"
                for n in names
                if n.split(".")[0].startswith("matplotlib")
            ]
    assert not found, "matplotlib imported outside obslib/viz:\n" + "\n".join(found)


#: Text that would point outside the repository (spelled in pieces so this file does not match).
OUTSIDE = ("../" + "shared", "/work/" + "shared", "EXPERIMENTS" + ".md", "DESIGN" + ".md")


def repository_files():
    yield from MODULES
    for sub, pattern in (
        ("tests", "*"),
        ("notebooks", "*.ipynb"),
        (".ci", "*"),
        ("book/_ext", "*.py"),
    ):
        yield from (
            p
            for p in sorted((ROOT / sub).rglob(pattern))
            if p.is_file() and "__pycache__" not in p.parts
        )
    yield from sorted((ROOT / "book").glob("*.md"))
    for name in (
        "README.md",
        "Makefile",
        "_config.yml",
        "_toc.yml",
        "pyproject.toml",
        "requirements.txt",
    ):
        if (ROOT / name).is_file():
            yield ROOT / name


def test_nothing_refers_to_files_outside_the_repository():
    found = []
    files = list(repository_files())
    assert len(files) > 50 and ROOT / "README.md" in files
    for p in files:
        text = p.read_text(errors="replace")
        found += [f"{rel(p)}: {s}" for s in OUTSIDE if s in text]
    assert not found, "references to files outside the repository:\n" + "\n".join(found)
