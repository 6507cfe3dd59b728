"""Notebook conventions: a tagged parameters cell first, folded after the chapter's opening; no
code shown before the first section; hidden cells that only call the chapter's modules (no
function defined in a notebook, at most :data:`MAX_HIDDEN_LINES` lines of hidden code in all);
executed, in the toc."""

import ast
import json
import re

import pytest
import yaml

from obslib.profiles import PROFILES, RANGES, params
from obslib.tools.run import NOTEBOOK_DIR, ROOT, notebooks

NOTEBOOKS = notebooks()


def code_cells(path):
    return [c for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "code"]


def literal_assignments(source):
    out = {}
    for node in ast.parse(source).body:
        assert isinstance(node, ast.Assign) and len(node.targets) == 1, (
            "parameters cell: only NAME = literal"
        )
        out[node.targets[0].id] = ast.literal_eval(node.value)
    return out


def test_there_are_notebooks():
    assert NOTEBOOKS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_first_code_cell_is_the_parameters_cell_of_literals(path):
    # the one source of the paper's values, read by obslib.profiles.params
    first = code_cells(path)[0]
    assert "parameters" in first["metadata"].get("tags", [])
    assert literal_assignments("".join(first["source"])) == params(path.stem, "paper")


def cells_of(path):
    return json.loads(path.read_text())["cells"]


def is_hidden(cell) -> bool:
    """Whether a code cell's code is kept off the page (folded or removed)."""
    return bool(HIDDEN & set(cell["metadata"].get("tags", [])))


#: Where to change the values, said in the sentence before the folded parameters cell.
WHERE_TO_CHANGE = "set in the folded cell below: change them there, or rerun the chapter"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_parameters_are_folded_after_a_sentence_saying_where_to_change_them(path):
    # the chapter opens with its question, not with code: the parameters are folded away
    cells = cells_of(path)
    k = next(i for i, c in enumerate(cells) if "parameters" in c["metadata"].get("tags", []))
    assert "hide-input" in cells[k]["metadata"]["tags"], f"{path.name}: parameters not folded"
    prompt = cells[k]["metadata"].get("mystnb", {}).get("code_prompt_show", "")
    assert "parameters" in prompt, f"{path.name}: the fold's button does not name the parameters"
    before = cells[k - 1]
    assert before["cell_type"] == "markdown" and WHERE_TO_CHANGE in "".join(before["source"]), (
        f"{path.name}: no sentence before the parameters cell says where to change them")
    assert cells[0]["cell_type"] == "markdown" and "".join(cells[0]["source"]).startswith("# ")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_no_code_is_shown_before_the_first_section(path):
    # the title, the opening paragraph and (where the chapter has one) the intuition come first
    shown = []
    for i, cell in enumerate(cells_of(path)):
        if cell["cell_type"] == "markdown" and re.search(r"^## ", "".join(cell["source"]), re.M):
            break
        if cell["cell_type"] == "code" and not is_hidden(cell):
            shown.append(i)
    else:
        pytest.fail(f"{path.name} has no section")
    assert not shown, f"{path.name}: cells {shown} show code before the first section"


#: The most lines of hidden code (not blank) all notebooks together may hold: hidden cells are
#: calls into the chapters' modules (obsbook.chapters, obslib.viz), imports and the parameters.
MAX_HIDDEN_LINES = 800


def hidden_lines(cells) -> int:
    """The lines of code, not blank, in the cells ``cells`` whose code is hidden."""
    return sum(1 for c in cells if c["cell_type"] == "code" and is_hidden(c)
               for line in "".join(c["source"]).splitlines() if line.strip())


def test_hidden_lines_are_counted():
    cells = [{"cell_type": "code", "metadata": {"tags": ["remove-input"]}, "source": "a = 1\n\nb"},
             {"cell_type": "code", "metadata": {"tags": ["hide-input"]}, "source": ["c = 2\n"]},
             {"cell_type": "code", "metadata": {}, "source": "d = 3"},
             {"cell_type": "markdown", "metadata": {"tags": ["remove-cell"]}, "source": "text"}]
    assert hidden_lines(cells) == 3


def test_hidden_code_stays_small():
    counts = {p.stem: hidden_lines(cells_of(p)) for p in NOTEBOOKS}
    assert sum(counts.values()) <= MAX_HIDDEN_LINES, (
        f"{sum(counts.values())} lines of hidden code (at most {MAX_HIDDEN_LINES}): {counts}")


def definitions(source: str) -> list:
    """The functions, lambdas and classes a cell's code defines, as ``(kind, line)``."""
    kinds = {ast.FunctionDef: "def", ast.AsyncFunctionDef: "def", ast.Lambda: "lambda",
             ast.ClassDef: "class"}
    return sorted((kinds[type(n)], n.lineno) for n in ast.walk(ast.parse(source))
                  if type(n) in kinds)


def test_definitions_are_found():
    assert definitions("f = lambda x: x\nclass A:\n    def g(self):\n        pass\n") == [
        ("class", 2), ("def", 3), ("lambda", 1)]
    assert definitions("y = sorted(x, key=abs)") == []


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_no_function_or_class_is_defined_in_a_notebook(path):
    # a chapter's helpers live in obsbook.chapters and its drawings in obslib.viz, linted and
    # documented: a hidden cell only calls them (not even a lambda), and a visible cell, which
    # teaches, defines no helper for hidden cells to call (a key function is teaching code)
    found = [(i, kind, line) for i, c in enumerate(code_cells(path))
             for kind, line in definitions("".join(c["source"]))
             if is_hidden(c) or kind != "lambda"]
    assert not found, f"{path.name}: (code cell, kind, line) of definitions: {found}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_figures_set_up_before_the_first_figure(path):
    # obsbook.setup in the import cell (the one after the parameters), so every figure is drawn
    # once and the same way
    sources = ["".join(c["source"]) for c in code_cells(path)]
    calls = [k for k, s in enumerate(sources) if "obsbook.setup()" in s]
    assert calls == [1], f"{path.name}: obsbook.setup() must be called once, in the import cell"
    assert "set_matplotlib_formats" not in "".join(sources)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_committed_with_outputs_and_no_errors(path):
    for i, cell in enumerate(code_cells(path)):
        tags = cell["metadata"].get("tags", [])
        assert "injected-parameters" not in tags, f"cell {i}: papermill-injected parameters"
        assert cell["execution_count"] is not None, f"cell {i} never executed"
        assert all(o["output_type"] != "error" for o in cell["outputs"]), (
            f"cell {i} stores an error"
        )
    meta = json.loads(path.read_text())["metadata"]
    assert "papermill" not in meta and "version" not in meta.get("language_info", {})


#: Widest code line a reader sees without scrolling sideways in the book's column.
VISIBLE_WIDTH = 88
#: Cell tags that keep a cell's code off the page (hidden behind a toggle, or removed).
HIDDEN = {"remove-input", "hide-input", "remove-cell"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_visible_code_fits_the_column(path):
    # shown or folded (a reader may unfold a cell tagged hide-input)
    wide = [(i, len(line)) for i, c in enumerate(code_cells(path))
            if not {"remove-input", "remove-cell"} & set(c["metadata"].get("tags", []))
            for line in "".join(c["source"]).splitlines() if len(line) > VISIBLE_WIDTH]
    assert not wide, f"{path.name}: (code cell, characters) of lines over {VISIBLE_WIDTH}: {wide}"


def test_profiles_only_override_known_parameters():
    for name, table in PROFILES.items():
        for stem, values in table.items():
            assert stem in RANGES, f"profile {name}: unknown notebook {stem}"
            assert set(values) <= set(params(stem)), f"profile {name}/{stem}: unknown parameter"
    assert {p.stem for p in NOTEBOOKS} == set(RANGES) == set(PROFILES["paper"])


def test_toc_lists_every_notebook_and_every_entry_exists():
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]] + [ch["file"] for part in toc["parts"] for ch in part["chapters"]]
    generated = {"book/execution"}  # written by make book (obslib.run), not committed
    for f in files:
        if f in generated:
            continue
        assert any((ROOT / f"{f}{ext}").exists() for ext in (".md", ".ipynb")), (
            f"toc entry {f} missing"
        )
    for nb in NOTEBOOKS:
        assert f"notebooks/{nb.stem}" in files, f"{nb.name} is not in _toc.yml"
    assert NOTEBOOK_DIR.exists()


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_papermill_sees_every_parameter(path):
    """papermill cannot parse a parameter line whose comment holds '=' or quotes; -p would then
    fail."""
    import papermill as pm

    assert set(pm.inspect_notebook(str(path))) == set(params(path.stem, "paper"))


def glued_verdicts():
    """Every verdict box the notebooks glue: (notebook, claim id, its MyST text)."""
    out = []
    for path in NOTEBOOKS:
        for cell in json.loads(path.read_text())["cells"]:
            for o in cell.get("outputs", []):
                name = o.get("metadata", {}).get("scrapbook", {}).get("name", "")
                if name.startswith("verdict_"):
                    text = o["data"]["application/papermill.record/text/markdown"]
                    m = re.search(r"\(#claim-([a-z0-9-]+)\)\n```$", text)
                    out.append((path.stem, m.group(1) if m else name, text))
    return out


def test_every_verdict_box_is_the_ledger_s_statement(paper_ledger):
    """A chapter never types a verdict: each box is glued from the ledger, and at the paper's
    parameters it is the very text the report states (status, one sentence, caveat)."""
    from obsbook.verdicts import box

    wrong = [f"{nb}: the box of {cid} differs from the ledger's" for nb, cid, text
             in glued_verdicts() if cid not in paper_ledger or text != box(paper_ledger[cid])]
    assert not wrong, "\n".join(wrong)


def test_every_entry_has_a_box_in_its_chapter_and_no_box_is_typed(paper_ledger):
    boxed = {(nb, cid) for nb, cid, _ in glued_verdicts()}
    missing = [f"{r.id} in {r.notebook}" for r in paper_ledger.values()
               if (r.notebook, r.id) not in boxed]
    assert not missing, "entries without a verdict box in their chapter: " + ", ".join(missing)
    for path in NOTEBOOKS:
        glued = {f"verdict_{cid.replace('-', '_')}" for nb, cid, _ in glued_verdicts()
                 if nb == path.stem}
        for cell in json.loads(path.read_text())["cells"]:
            if cell["cell_type"] != "markdown":
                continue
            src = "".join(cell["source"])
            assert "{admonition} Verdict" not in src, f"{path.name}: a typed verdict box"
            for key in re.findall(r"\{glue:md\} (verdict_\w+)", src):
                assert key in glued, f"{path.name}: shows {key}, which it does not glue"
