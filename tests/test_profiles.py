"""Parameters: read from each notebook's parameters cell, overridden by profiles, checked."""

import json
import shutil

import pytest

from obslib import profiles as pr


@pytest.fixture
def notebook_copy(tmp_path, monkeypatch):
    """A copy of the notebooks folder, named by OBSLIB_NOTEBOOKS."""
    folder = tmp_path / "notebooks"
    shutil.copytree(pr.notebook_dir(), folder)
    monkeypatch.setenv(pr.NOTEBOOKS_ENV, str(folder))
    return folder


def set_cell(path, old, new):
    nb = json.loads(path.read_text())
    cell = next(c for c in nb["cells"] if "parameters" in c["metadata"].get("tags", []))
    source = "".join(cell["source"])
    assert old in source
    cell["source"] = source.replace(old, new)
    path.write_text(json.dumps(nb))


def test_the_cell_is_the_one_source_of_the_paper_values(notebook_copy):
    nb = "05_two_sensors_tracking"
    assert pr.params(nb)["n_seeds"] == 200 and pr.params(nb, "quick")["n_seeds"] == 20
    set_cell(notebook_copy / f"{nb}.ipynb", "n_seeds = 200", "n_seeds = 123")
    assert pr.params(nb)["n_seeds"] == 123  # read again once the file changed
    assert pr.params(nb, "quick")["n_seeds"] == 20  # the profile overrides the cell
    assert pr.params(nb, "quick")["steps"] == pr.params(nb)["steps"] == 315


def test_a_missing_notebooks_folder_says_where_to_find_it(tmp_path, monkeypatch):
    monkeypatch.setenv(pr.NOTEBOOKS_ENV, str(tmp_path / "nowhere"))
    with pytest.raises(FileNotFoundError, match="OBSLIB_NOTEBOOKS.*notebooks/ folder"):
        pr.params("01_model_and_bound")


def test_the_cell_holds_only_literal_assignments(notebook_copy):
    nb = "04_submodularity"
    set_cell(notebook_copy / f"{nb}.ipynb", "eps = 1.0", "eps = 2 * 0.5")
    with pytest.raises(ValueError, match="only NAME = literal lines"):
        pr.params(nb)


def test_unknown_notebook_and_profile():
    with pytest.raises(ValueError, match="no parameters for notebook"):
        pr.params("99_nothing")
    with pytest.raises(ValueError, match="unknown profile 'nosuch'"):
        pr.params("01_model_and_bound", "nosuch")


def test_constraints_name_their_parameters_in_order():
    c = pr.Constraint("2 * search_targets <= search_sensors and len(xs) > min(ys)")
    assert c.names() == ["search_targets", "search_sensors", "xs", "ys"]
    assert c.holds({"search_targets": 3, "search_sensors": 6, "xs": [1, 2], "ys": [1]})
    assert not c.holds({"search_targets": 4, "search_sensors": 6, "xs": [1, 2], "ys": [1]})


def test_range_messages_say_why():
    with pytest.raises(ValueError, match=r"n_sensors = 11 is not accepted; expected an integer in "
                                         r"\[2, 10\] \(all 2\^N subsets"):
        pr.validated_parameters("04_submodularity", {"n_sensors": 11})
    with pytest.raises(ValueError, match="n_instances = 5000, n_sensors = 10 are not accepted"):
        pr.validated_parameters("04_submodularity", {"n_sensors": 10, "n_instances": 5000})
