"""The book's helpers (obsbook): tables and glued numbers; the figures have tests/test_figures.py.

A numbered table is checked by parsing its MyST with the parser the book uses: one list-table
directive, its caption, its name, and the cells in order, with no row for the index's name.
"""

import ast

import pandas as pd
import pytest

import obsbook
import obslib
from obsbook import tables


def _list_table(text: str):
    """(caption, options, rows) of the one ``{list-table}`` in ``text``, read by markdown-it
    (MyST's parser) and the directive's own list syntax."""
    from markdown_it import MarkdownIt
    from mdit_py_plugins.colon_fence import colon_fence_plugin

    tokens = MarkdownIt("commonmark").use(colon_fence_plugin).parse(text)
    fences = [t for t in tokens if t.type == "fence"]
    assert len(fences) == 1 and fences[0].info.startswith("{list-table}")
    caption = fences[0].info[len("{list-table}"):].strip()
    lines = fences[0].content.splitlines()
    options = dict(line[1:].split(": ", 1) for line in lines if line.startswith(":"))
    body = MarkdownIt("commonmark").parse("\n".join(lines[len(options):]))
    rows, depth, cell = [], 0, None
    for t in body:
        if t.type == "bullet_list_open":
            depth += 1
            if depth == 2:
                rows.append([])
        elif t.type == "bullet_list_close":
            depth -= 1
        elif t.type == "list_item_open" and depth == 2:
            cell = ""
            rows[-1].append(cell)
        elif t.type == "inline" and depth == 2:
            rows[-1][-1] = t.content
    return caption, options, rows


def test_a_dataframe_becomes_a_numbered_table_with_caption_above():
    t = pd.DataFrame({"N": ["10", "20"], "time (s)": ["0.12", "0.50"]})
    caption, options, rows = _list_table(tables.numbered_table(t, "Time per size.", "tab-time"))
    assert caption == "Time per size."
    assert options == {"header-rows": "1", "name": "tab-time", "widths": "auto"}
    assert rows == [["N", "time (s)"], ["10", "0.12"], ["20", "0.50"]]


def test_a_named_index_is_the_first_column_without_a_row_of_its_own():
    t = pd.DataFrame({"mean": ["1.00", "2.00"]}, index=pd.Index(["greedy", "relaxed"], name="rule"))
    _, _, rows = _list_table(tables.numbered_table(t, "Means.", "tab-means"))
    assert rows == [["rule", "mean"], ["greedy", "1.00"], ["relaxed", "2.00"]]
    _, _, rows = _list_table(tables.numbered_table(t, "Means.", "tab-means", index=False))
    assert rows == [["mean"], ["1.00"], ["2.00"]]


def test_rows_are_formatted_by_their_columns():
    rows = [{"s": "a", "v": 1.2345}, {"s": "b", "v": 2.0}]
    cols = {"name": ("s", "s"), "value": ("v", ".2f"), "upper": (None, lambda r: r["s"].upper())}
    _, _, got = _list_table(tables.numbered_table(rows, "Rows.", "tab-rows", columns=cols))
    assert got == [["name", "value", "upper"], ["a", "1.23", "A"], ["b", "2.00", "B"]]
    # the same cells as the Markdown table of the same rows
    md = tables.markdown_table(rows, cols).splitlines()
    assert [[c.strip() for c in line.strip("|").split("|")] for line in md[2:]] == got[1:]


def test_bad_tables_are_refused():
    t = pd.DataFrame({"a": [1]})
    with pytest.raises(ValueError, match="caption"):
        tables.numbered_table(t, "two\nlines", "tab-a")
    with pytest.raises(ValueError, match="name"):
        tables.numbered_table(t, "A.", "tab a")
    with pytest.raises(ValueError, match="columns"):
        tables.numbered_table([{"a": 1}], "A.", "tab-a")
    with pytest.raises(ValueError, match="formats name columns"):
        tables.formatted_table(t, formats={"b": "{}"})


def test_glued_numbers_read_as_the_formatter_writes_them(monkeypatch):
    glued = {}
    import myst_nb

    monkeypatch.setattr(myst_nb, "glue", lambda name, value, display: glued.update({name: value}))
    for x in (10000, 0.48488, 1.234e-5, 3.0):
        g = obsbook.glue_number("x", x)
        assert glued["x"] is g
        assert g._repr_markdown_() == obslib.formatting.number(x)
        assert repr(g) == obslib.formatting.number(x, math=False)
        assert not repr(g).startswith(("'", '"'))  # shown without quotes by {glue:text}
    obsbook.glue_text("n", obslib.formatting.count(0))
    assert repr(glued["n"]) == "none"
    with pytest.raises(ValueError, match="str"):
        obsbook.glue_text("n", 3)
    with pytest.raises(ValueError, match="identifier"):
        obsbook.glue_text("a name", "3")


def test_obslib_never_imports_obsbook():
    from pathlib import Path

    root = Path(obslib.__file__).parent
    found = []
    for path in root.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            found += [f"{path.relative_to(root)}: {n}" for n in names
                      if n.split(".")[0] == "obsbook"]
    assert not found, found


def _helpers():
    """Every function in the ``__all__`` of obsbook's modules and of each chapter's module."""
    import importlib
    import inspect
    import pkgutil

    import obsbook.chapters

    names = ["obsbook.glue", "obsbook.tables", "obsbook.prose"] + [
        f"obsbook.chapters.{m.name}" for m in pkgutil.iter_modules(obsbook.chapters.__path__)]
    for name in names:
        mod = importlib.import_module(name)
        for attr in mod.__all__:
            obj = getattr(mod, attr)
            if inspect.isfunction(obj) and obj.__module__ == name:
                yield f"{name}.{attr}", obj


def test_the_chapter_modules_are_found():
    found = dict(_helpers())
    assert "obsbook.chapters.model_and_bound.glue_theorem1" in found
    assert "obsbook.prose.share" in found and len(found) > 100


def test_every_helper_is_documented():
    # NumPy style: a summary line, then every parameter named (in a Parameters section or in
    # the text); the chapters' notebooks call these, so a reader looks them up here
    import inspect
    import re

    missing = []
    for qualname, fn in _helpers():
        doc = inspect.getdoc(fn) or ""
        if not doc.strip():
            missing.append(f"{qualname}: no docstring")
            continue
        for p in inspect.signature(fn).parameters:
            if not re.search(rf"(?<![A-Za-z_]){re.escape(p)}(?![A-Za-z_])", doc):
                missing.append(f"{qualname}: parameter {p} not described")
    assert not missing, "\n".join(missing)


def test_published_runs_are_named_for_runs_that_exist():
    from obsbook.prose import PUBLISHED_RUNS
    from obslib.published_runs import RUN_NAMES

    assert set(PUBLISHED_RUNS) <= set(RUN_NAMES)
