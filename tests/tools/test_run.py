"""The papermill runner: notebook lookup, parameter checks, clean in-place-safe output."""

import json

import nbformat
import pytest
from nbformat.v4 import new_code_cell, new_notebook

from obslib.tools import run


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


# --------------------------------------------------------------------------- parameters checked first


@pytest.mark.parametrize("value, expected", [
    ("abc", "an integer >= 1"), ("-5", "an integer >= 1"), ("2.5", "an integer >= 1"),
    ("True", "an integer >= 1"), ("None", "an integer >= 1"), ("0", "an integer >= 1"),
])
def test_bad_parameter_value_fails_before_any_notebook_runs(value, expected, monkeypatch, capsys):
    ran = []
    monkeypatch.setattr(run, "execute", lambda *a, **k: ran.append(a))
    with pytest.raises(SystemExit) as exc:
        run.main(["-p", "n_seeds", value, "05"])
    assert exc.value.code == 2 and not ran
    err = capsys.readouterr().err
    assert "n_seeds" in err and "05_two_sensors_tracking" in err and expected in err


def test_unknown_parameter_of_the_second_notebook_fails_before_the_first(monkeypatch, capsys):
    ran = []
    monkeypatch.setattr(run, "execute", lambda *a, **k: ran.append(a))
    with pytest.raises(SystemExit) as exc:
        run.main(["-p", "n_seeds", "5", "05", "01"])
    assert exc.value.code == 2 and not ran
    assert "01_model_and_bound has no parameter(s) ['n_seeds']" in capsys.readouterr().err


def test_parameter_checks_accept_good_values_and_convert_numbers():
    from obslib.profiles import check_parameters

    d = {"u_max": 3.0, "n_seeds": 200, "metric": "mahalanobis", "eps_values": [1e-6, 1.0]}
    assert check_parameters("nb", {"u_max": 2, "n_seeds": 3}, d) == {"u_max": 2.0, "n_seeds": 3}
    assert check_parameters("nb", {"eps_values": [1, 0.5]}, d) == {"eps_values": [1.0, 0.5]}
    for bad in ({"metric": "no"}, {"u_max": -1.0}, {"u_max": float("nan")}, {"eps_values": [0.0]},
                {"eps_values": []}, {"eps_values": 1.0}, {"n_seeds": 5.0}):
        with pytest.raises(ValueError, match=f"parameter {next(iter(bad))}"):
            check_parameters("nb", bad, d)
    with pytest.raises(ValueError, match="N_min <= N_max"):
        check_parameters("nb", {"N_min": 60}, {"N_min": 20, "N_max": 50})


@pytest.mark.parametrize("profile", ["paper", "quick"])
def test_every_profile_passes_the_parameter_checks(profile):
    # the profiles' values are legal for the notebooks that declare them (the defaults too)
    from obslib.profiles import PROFILES, check_parameters, params

    for nb in run.notebooks():
        if nb.stem in PROFILES["paper"]:
            declared = run.declared_parameters(nb)
            check_parameters(nb.stem, params(nb.stem, profile), declared)
            check_parameters(nb.stem, declared, declared)


@pytest.mark.parametrize("argv, message", [
    (["--id", "nosuch"], "unknown claim id"),
    (["--profile", "nosuch"], "invalid choice"),
    (["--write", "/nonexistent-dir/report.md"], "does not exist"),
    (["--write", "."], "is a directory"),
])
def test_claims_cli_errors_are_argparse_errors(argv, message, capsys):
    from obslib.claims.__main__ import parse_args

    with pytest.raises(SystemExit) as exc:
        parse_args(argv)
    assert exc.value.code == 2 and message in capsys.readouterr().err


@pytest.mark.parametrize("argv, message", [
    (["book", "--profile", "nosuch"], "invalid choice"),
    (["nosuch"], "invalid choice"),
    (["book", "--write", "x.json"], "scaling and criteria benchmarks only"),
    (["scaling", "--write", "."], "give a file name"),
])
def test_bench_cli_errors_are_argparse_errors(argv, message, capsys):
    from obslib.tools.bench import parse_args

    with pytest.raises(SystemExit) as exc:
        parse_args(argv)
    assert exc.value.code == 2 and message in capsys.readouterr().err
