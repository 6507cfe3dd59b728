"""The papermill runner: notebook lookup, parameter checks, clean in-place-safe output."""

import json

import nbformat
import pytest
from nbformat.v4 import new_code_cell, new_notebook

from obslib import run


def test_resolve_by_number_and_stem():
    first = run.notebooks()[0]
    assert run.resolve([first.stem[:2]]) == [first]
    assert run.resolve([first.stem]) == [first]
    with pytest.raises(ValueError, match="no single notebook"):
        run.resolve(["99"])


def test_literal_values():
    assert run._literal("3") == 3 and run._literal("0.5") == 0.5
    assert run._literal("[1, 2]") == [1, 2] and run._literal("quick") == "quick"


@pytest.fixture
def tiny_notebook(tmp_path):
    nb = new_notebook()
    p = new_code_cell("n = 2")
    p.metadata["tags"] = ["parameters"]
    nb.cells = [p, new_code_cell("print(n * 21)")]
    for k, c in enumerate(nb.cells):
        c.id = f"c{k}"
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path = tmp_path / "00_tiny.ipynb"
    nbformat.write(nb, path)
    return path


def test_unknown_parameter_is_an_error(tiny_notebook, tmp_path):
    with pytest.raises(ValueError, match="has no parameter"):
        run.execute(tiny_notebook, tmp_path / "out.ipynb", {"m": 3})


def test_execute_injects_parameters_and_strips_run_metadata(tiny_notebook, tmp_path):
    out = tmp_path / "runs" / "out.ipynb"
    run.execute(tiny_notebook, out, {"n": 5})
    nb = json.loads(out.read_text())
    assert "papermill" not in nb["metadata"]
    assert all("papermill" not in c["metadata"] and "execution" not in c["metadata"] for c in nb["cells"])
    outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
    assert any("".join(o.get("text", "")) == "105\n" for o in outputs)
    assert json.loads(tiny_notebook.read_text())["cells"][1]["outputs"] == []  # source untouched


def test_cli_refuses_in_place_with_parameters():
    with pytest.raises(SystemExit):
        run.main(["--in-place", "-p", "seed", "1"])


def test_stream_chunks_are_merged():
    outs = [
        {"output_type": "stream", "name": "stdout", "text": "a\n"},
        {"output_type": "stream", "name": "stdout", "text": "b\n"},
        {"output_type": "stream", "name": "stderr", "text": "w\n"},
        {"output_type": "display_data", "data": {}, "metadata": {}},
        {"output_type": "stream", "name": "stdout", "text": "c"},
        {"output_type": "stream", "name": "stdout", "text": "\n"},
    ]
    merged = run._merge_streams(outs)
    assert [o.get("text") for o in merged] == ["a\nb\n", "w\n", None, "c\n"]
