"""Sphinx extension: the API reference, one page per part of ``obslib``, and a landing page that
lists every public name with the first sentence of its docstring.

A page of the reference says which modules it documents in a fenced block::

    ```{api-modules}
    obslib.observability
    obslib.tracking
    obslib.tracking.*
    ```

(``pkg.*``: every public submodule of ``pkg``, in alphabetical order). When the page is read, the
block becomes, for each module, a section titled with the module's name, its docstring and an
entry for each of its public names (its ``__all__``). Each object is documented once: a name
that a package in :data:`EXPORTING` offers (``obslib.lower_bound``, ``obslib.claims.evaluate``)
under that package, and not in the module that defines it; a package documents only the names of
its ``__all__`` that no public submodule lists. Every public name is documented, with or without a
docstring; a constant's value is shown when it is short (:data:`MAX_VALUE_CHARS`) and not a path
of the machine that builds the book.

The landing page holds an empty ``{api-summary}`` block. It becomes one table per page of the
reference (in the order of the table of contents): every module of the page with its summary,
then every public name of the module with its summary, each linked to its entry. The names and
summaries are read from the package when the book is built, so the table cannot go stale; a
module's change makes Sphinx read the pages again.
"""

from __future__ import annotations

import importlib
import inspect
import os
import pkgutil
import re
from pathlib import Path

import yaml

PACKAGE = "obslib"
#: The repository the book is built from: no page may show where it is.
CHECKOUT = Path(__file__).resolve().parents[2]
#: Packages whose ``__all__`` names are documented under the package (``obslib.lower_bound``).
EXPORTING = ("obslib", "obslib.claims")

_BLOCK = re.compile(r"^```\{(api-modules|api-summary)\}[^\n]*\n(.*?)^```\s*$", re.M | re.S)


# ------------------------------------------------------------------------------ the package


def public_modules() -> list[str]:
    """Every module of the package whose dotted path has no part starting with ``_``."""
    pkg = importlib.import_module(PACKAGE)
    names = [PACKAGE]
    for info in pkgutil.walk_packages(pkg.__path__, PACKAGE + "."):
        if not any(part.startswith("_") for part in info.name.split(".")):
            names.append(info.name)
    return sorted(names)


def _module(name: str):
    return importlib.import_module(name)


def _is_package(name: str) -> bool:
    return hasattr(_module(name), "__path__")


def _exports(name: str) -> list[str]:
    return list(getattr(_module(name), "__all__", []))


def _submodules(name: str) -> list[str]:
    return [m for m in public_modules() if m.rsplit(".", 1)[0] == name]


def _exported_ids() -> set:
    """``id`` of every object that a package of :data:`EXPORTING` documents itself."""
    out = set()
    for pkg in EXPORTING:
        mod = _module(pkg)
        out |= {id(getattr(mod, n)) for n in _exports(pkg) if not inspect.ismodule(getattr(mod, n))}
    return out


def _own_names(name: str) -> list[str]:
    """The names module ``name`` documents: its ``__all__`` minus modules, minus what an
    exporting package documents, and for a package minus what a public submodule lists."""
    mod = _module(name)
    names = [n for n in _exports(name) if not inspect.ismodule(getattr(mod, n, None))]
    if name in EXPORTING:
        return names
    exported = _exported_ids()
    names = [n for n in names if id(getattr(mod, n)) not in exported]
    if _is_package(name):
        below = {id(getattr(_module(s), n)) for s in _submodules(name) for n in _exports(s)}
        names = [n for n in names if id(getattr(mod, n)) not in below]
    return names


def _expand(lines: list[str]) -> list[str]:
    out = []
    for line in lines:
        line = line.strip()
        if not line:
            continue
        if line.endswith(".*"):
            out += _submodules(line[:-2])
        else:
            _module(line)  # an unknown module fails the build here, with its name
            out.append(line)
    return out


# ------------------------------------------------------------------------------ module pages


def _directive(name: str) -> str:
    """The module's docstring, then an entry for each name it documents, in ``__all__`` order.

    One directive per name rather than ``automodule`` with ``:members:``: autodoc leaves out
    some undocumented constants of a ``:members:`` list even with ``:undoc-members:``.
    """
    mod = _module(name)
    rst = [f".. automodule:: {name}", "   :no-members:", ""]
    for n in _own_names(name):
        obj = getattr(mod, n)
        if inspect.isclass(obj):
            rst += [f".. autoclass:: {name}.{n}", "   :members:", ""]
        elif inspect.isroutine(obj):
            rst += [f".. autofunction:: {name}.{n}", ""]
        else:  # a constant: its ``#:`` comment (autodata would show its type's docstring)
            doc = ["   " + line if line else "" for line in _data_doc(name, n, obj)]
            rst += [f".. py:data:: {n}", f"   :module: {name}", *_value_option(obj), "", *doc, ""]
    return "\n".join(rst)


def _data_doc(name: str, attr: str, obj) -> list[str]:
    """The ``#:`` comment of constant ``attr`` of module ``name``, or of the module that
    defines it (a package's ``__all__`` offers it from there)."""
    if ("", attr) in _attr_docs(name):
        return _attr_docs(name)[("", attr)]
    for other in public_modules():
        if (
            other != name
            and getattr(_module(other), attr, None) is obj
            and ("", attr) in _attr_docs(other)
        ):
            return _attr_docs(other)[("", attr)]
    return []


def _attr_docs(name: str) -> dict:
    """The ``#:`` comments of module ``name``, by ``("", attribute)``."""
    from sphinx.pycode import ModuleAnalyzer

    if name not in _ATTR_DOCS:
        try:
            _ATTR_DOCS[name] = ModuleAnalyzer.for_module(name).find_attr_docs()
        except Exception:  # a module without source: no comments to read
            _ATTR_DOCS[name] = {}
    return _ATTR_DOCS[name]


_ATTR_DOCS: dict = {}


def _value_option(obj) -> list[str]:
    """``:value:`` of a constant, when its repr is short and does not depend on the machine (a
    path in the checkout would show where the book was built)."""
    from sphinx.util.inspect import object_description

    if isinstance(obj, os.PathLike):
        return []
    try:
        text = object_description(obj)
    except Exception:  # a value without a usable repr
        return []
    if len(text) > MAX_VALUE_CHARS or "\n" in text or str(CHECKOUT) in text:
        return []
    return [f"   :value: {text}"]


def _module_sections(names: list[str]) -> str:
    """One ``eval-rst`` block for the modules of a page, a section for each: the sections of
    the modules' docstrings (underlined ``-``) become subsections of it, so that two modules'
    *Conventions* are told apart rather than colliding as targets of the page."""
    rst = []
    for name in names:
        rst += [name, "*" * len(name), "", _directive(name)]
    return "```{eval-rst}\n" + "\n".join(rst) + "```\n"


# ------------------------------------------------------------------------------ landing page


def _summary(obj, modname: str, attr: str) -> str:
    """The first sentence of the object's docstring (or of its ``#:`` comment, for data)."""
    doc = None
    if inspect.ismodule(obj) or inspect.isclass(obj) or inspect.isroutine(obj):
        doc = inspect.getdoc(obj)
    if not doc:
        doc = "\n".join(_data_doc(modname, attr, obj))
    para = re.split(r"\n\s*\n", (doc or "").strip())[0]
    para = " ".join(para.split())
    # the first sentence: up to a full stop followed by a space and a capital, not after an
    # abbreviation (Eq. (5), Fig. 2) and not inside inline markup
    for m in re.finditer(r"(\S*)\.\s+(?=[A-Z])", para):
        first = para[: m.start() + len(m.group(1)) + 1]
        if m.group(1).lower().rstrip(".") in _ABBREVIATIONS or first.count("`") % 2:
            continue
        return first
    return para


_ABBREVIATIONS = {"eq", "eqs", "fig", "figs", "sec", "e.g", "i.e", "cf", "vs", "no", "ref", "al"}


def _documented_path(modname: str, attr: str) -> str:
    """Where ``modname.attr`` is documented (see :func:`_own_names`)."""
    obj = getattr(_module(modname), attr)
    for pkg in EXPORTING:
        mod = _module(pkg)
        if any(getattr(mod, n) is obj for n in _exports(pkg)):
            return f"{pkg}.{attr}"
    return f"{modname}.{attr}"


def _pages(root: Path) -> list[tuple[str, str, list[str]]]:
    """``(docname, title, modules)`` of every block of modules of the reference's pages, in the
    order of the table of contents."""
    toc = yaml.safe_load((root / "_toc.yml").read_text())

    def files(entries):
        for e in entries or []:
            if "file" in e:
                yield e["file"]
            yield from files(e.get("sections"))

    out = []
    for part in toc.get("parts", []):
        for doc in files(part.get("chapters")):
            path = root / f"{doc}.md"
            if not path.exists():
                continue
            text = path.read_text()
            blocks = [m.group(2) for m in _BLOCK.finditer(text) if m.group(1) == "api-modules"]
            if not blocks:
                continue
            title = re.search(r"^# (.+)$", text, re.M).group(1).strip()
            out += [(doc, title, _expand(body.splitlines())) for body in blocks]
    return out


def _summary_tables(app, docname: str) -> str:
    root = Path(app.srcdir)
    pages: dict = {}  # docname -> (title, rows), in the order of the table of contents
    for doc, title, modules in _pages(root):
        rows = pages.setdefault(doc, (title, []))[1]
        for name in modules:
            mod = _module(name)
            if getattr(mod, "__file__", None):
                app.env.note_dependency(mod.__file__)
            rows.append((f":py:mod:`{name}`", _summary(mod, name, "")))
            for n in _own_names(name):
                obj = getattr(mod, n)
                label = n if name == PACKAGE else f"{name.removeprefix(PACKAGE + '.')}.{n}"
                where = obj.__module__ if inspect.isclass(obj) or inspect.isroutine(obj) else name
                rows.append((f":py:obj:`{label} <{_documented_path(name, n)}>`",
                             _summary(obj, where, n)))
    out = []
    here = Path(docname).parent
    for doc, (title, rows) in pages.items():
        link = Path(doc).relative_to(here).as_posix() if Path(doc).parent == here else "/" + doc
        table = [".. list-table::", "   :header-rows: 1", "   :widths: 40 60",
                 "   :class: api-summary", "", "   * - name", "     - summary"]
        for name, summary in rows:
            table += [f"   * - {name}", f"     - {summary}"]
        out.append(f"## {title}\n\nFull entries: {{doc}}`{link}`.\n\n"
                   "```{eval-rst}\n" + "\n".join(table) + "\n```\n")
    return "\n".join(out)


# ------------------------------------------------------------------------------ Sphinx


def _source_read(app, docname, source):
    text = source[0]
    if "```{api-" not in text:
        return

    def replace(m):
        kind, body = m.group(1), m.group(2)
        if kind == "api-summary":
            return _summary_tables(app, docname)
        for name in _expand(body.splitlines()):
            if getattr(_module(name), "__file__", None):
                app.env.note_dependency(_module(name).__file__)
        return _module_sections(_expand(body.splitlines()))

    source[0] = _BLOCK.sub(replace, text)


#: A constant's value is shown after its name up to this many characters (a profile table or a
#: parameter record would fill a screen; its docstring and the source say what it holds).
MAX_VALUE_CHARS = 120


def setup(app):
    app.connect("source-read", _source_read)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
