"""Notebook conventions (DESIGN.md): tagged parameters equal to the profile, executed, in the toc."""

import ast
import json

import pytest
import yaml

from obslib.profiles import PROFILES, params
from obslib.run import NOTEBOOK_DIR, ROOT, notebooks

NOTEBOOKS = notebooks()


def code_cells(path):
    return [c for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "code"]


def literal_assignments(source):
    out = {}
    for node in ast.parse(source).body:
        assert isinstance(node, ast.Assign) and len(node.targets) == 1, "parameters cell: only NAME = literal"
        out[node.targets[0].id] = ast.literal_eval(node.value)
    return out


def test_there_are_notebooks():
    assert NOTEBOOKS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_parameters_cell_equals_paper_profile(path):
    first = code_cells(path)[0]
    assert "parameters" in first["metadata"].get("tags", [])
    assert literal_assignments("".join(first["source"])) == params(path.stem, "paper")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_committed_with_outputs_and_no_errors(path):
    for i, cell in enumerate(code_cells(path)):
        tags = cell["metadata"].get("tags", [])
        assert "injected-parameters" not in tags, f"cell {i}: papermill-injected parameters"
        assert cell["execution_count"] is not None, f"cell {i} never executed"
        assert all(o["output_type"] != "error" for o in cell["outputs"]), f"cell {i} stores an error"
    meta = json.loads(path.read_text())["metadata"]
    assert "papermill" not in meta and "version" not in meta.get("language_info", {})


def test_profiles_only_override_known_parameters():
    for name, table in PROFILES.items():
        for stem, values in table.items():
            assert stem in PROFILES["paper"], f"profile {name}: unknown notebook {stem}"
            assert set(values) <= set(PROFILES["paper"][stem]), f"profile {name}/{stem}: unknown parameter"
    assert {p.stem for p in NOTEBOOKS} == set(PROFILES["paper"])


def test_toc_lists_every_notebook_and_every_entry_exists():
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]] + [ch["file"] for part in toc["parts"] for ch in part["chapters"]]
    for f in files:
        assert any((ROOT / f"{f}{ext}").exists() for ext in (".md", ".ipynb")), f"toc entry {f} missing"
    for nb in NOTEBOOKS:
        assert f"notebooks/{nb.stem}" in files, f"{nb.name} is not in _toc.yml"
    assert NOTEBOOK_DIR.exists()
