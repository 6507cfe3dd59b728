"""The papermill runner: lookup, parameter checks first, rerun names, parallel runs, progress."""

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


def write_notebook(path, params_source, code):
    nb = new_notebook()
    p = new_code_cell(params_source)
    p.metadata["tags"] = ["parameters"]
    nb.cells = [p] + [new_code_cell(c) for c in code]
    for k, c in enumerate(nb.cells):
        c.id = f"c{k}"
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    nbformat.write(nb, path)
    return path


@pytest.fixture
def tiny_notebook(tmp_path):
    return write_notebook(tmp_path / "00_tiny.ipynb", "n = 2", ["print(n * 21)"])


@pytest.fixture
def runs_dir(tmp_path, monkeypatch):
    d = tmp_path / "runs"
    monkeypatch.setattr(run, "RUNS_DIR", d)
    return d


def test_unknown_parameter_is_an_error(tiny_notebook, tmp_path):
    with pytest.raises(ValueError, match="has no parameter"):
        run.execute(tiny_notebook, tmp_path / "out.ipynb", {"m": 3})


def test_execute_injects_parameters_and_strips_run_metadata(tiny_notebook, tmp_path, capfd):
    out = tmp_path / "runs" / "out.ipynb"
    run.execute(tiny_notebook, out, {"n": 5})
    nb = json.loads(out.read_text())
    assert "papermill" not in nb["metadata"]
    assert all(
        "papermill" not in c["metadata"] and "execution" not in c["metadata"] for c in nb["cells"]
    )
    outputs = [o for c in nb["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
    assert any("".join(o.get("text", "")) == "105\n" for o in outputs)
    assert json.loads(tiny_notebook.read_text())["cells"][1]["outputs"] == []  # source untouched
    # the kernel talks over Unix sockets, so it does not warn about TCP (its stderr is ours)
    assert "without encryption" not in capfd.readouterr().err


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
    from obslib.tools._papermill import merge_streams

    merged = merge_streams(outs)
    assert [o.get("text") for o in merged] == ["a\nb\n", "w\n", None, "c\n"]


# --------------------------------------------------------------------------- parameters checked
# first


def refused(argv, monkeypatch, capsys) -> str:
    """The command's error message; fails if it is not a command-line error before any run."""
    ran = []
    monkeypatch.setattr(run, "execute", lambda *a, **k: ran.append(a))
    with pytest.raises(SystemExit) as exc:
        run.main(argv)
    assert exc.value.code == 2 and not ran
    return capsys.readouterr().err


@pytest.mark.parametrize("value, expected", [
    ("abc", "an integer >= 1"), ("-5", "an integer >= 1"), ("2.5", "an integer >= 1"),
    ("True", "an integer >= 1"), ("None", "an integer >= 1"), ("0", "an integer >= 1"),
])
def test_bad_parameter_value_fails_before_any_notebook_runs(value, expected, monkeypatch, capsys):
    err = refused(["-p", "n_seeds", value, "05"], monkeypatch, capsys)
    assert "n_seeds" in err and "05_two_sensors_tracking" in err and expected in err


@pytest.mark.parametrize(
    "argv, expected",
    [
        # values that would crash a notebook halfway lie outside the declared range
        (
            ["-p", "n_sensors", "1", "04"],
            "n_sensors = 1 is not accepted; expected an integer in [2, 10]",
        ),
        (
            ["-p", "n_sensors", "30", "04"],
            "n_sensors = 30 is not accepted; expected an integer in [2, 10]",
        ),
        (["-p", "L_max", "1", "07"], "L_max = 1 is not accepted; expected an integer in [2, 200]"),
        (
            ["-p", "steps", "1", "05"],
            "steps = 1 is not accepted; expected an integer in [71, 10000]",
        ),
        (
            ["-p", "alpha_max", "1e-9", "02"],
            "alpha_max = 1e-09 is not accepted; expected a number in [1, 100]",
        ),
        (
            ["-p", "eps", "1e-300", "04"],
            "eps = 1e-300 is not accepted; expected a number in [1e-06, 1e+06]",
        ),
        # dependencies between parameters
        (
            ["-p", "targets_min", "5", "03"],
            "targets_min = 5, targets_max = 4 are not accepted; "
            "expected targets_min <= targets_max",
        ),
        (["-p", "search_targets", "4", "03"], "expected 2 * search_targets <= search_sensors"),
        (["-p", "N_min", "60", "08"], "expected N_min <= N_max"),
        (["-p", "contour_levels", "[0.5, 0.2]", "02"], "contour levels increase"),
        (["-p", "metric", "'manhattan'", "05"], "one of 'mahalanobis', 'euclidean'"),
        (["-p", "times_file", "'nosuch.json'", "09"], "the path of an existing file"),
        # a name given twice
        (
            ["--profile", "quick", "-p", "n_scenes", "1", "-p", "n_scenes", "2", "01"],
            "n_scenes given more than once",
        ),
    ],
)
def test_values_outside_the_declared_ranges_are_command_line_errors(argv, expected, monkeypatch,
                                                                    capsys):
    err = refused(["--profile", "quick"] + argv if "--profile" not in argv else argv,
                  monkeypatch, capsys)
    assert expected in err, err


def test_unknown_parameter_of_the_second_notebook_fails_before_the_first(monkeypatch, capsys):
    err = refused(["-p", "n_seeds", "5", "05", "01"], monkeypatch, capsys)
    assert "01_model_and_bound has no parameter(s) ['n_seeds']" in err


def test_parameter_checks_accept_good_values_and_convert_numbers():
    from obslib.profiles import validated_parameters

    nb = "05_two_sensors_tracking"
    assert validated_parameters(nb, {"u_max": 2, "n_seeds": 3}) == {"u_max": 2.0, "n_seeds": 3}
    assert validated_parameters("08_general_assignment", {"eps_values": [1, 0.5]}) == {
        "eps_values": [1.0, 0.5]}
    for bad in ({"metric": "no"}, {"u_max": -1.0}, {"u_max": float("nan")}, {"n_seeds": 5.0}):
        with pytest.raises(ValueError, match=f"parameter {next(iter(bad))}"):
            validated_parameters(nb, bad)
    for bad in ({"eps_values": [0.0]}, {"eps_values": []}, {"eps_values": 1.0}):
        with pytest.raises(ValueError, match="expected a non-empty list, each entry number in"):
            validated_parameters("08_general_assignment", bad)


def test_every_parameter_has_a_declared_range():
    from obslib.profiles import RANGES, defaults

    for nb in run.notebooks():
        assert set(RANGES[nb.stem]) == set(defaults(nb.stem)), nb.stem


@pytest.mark.parametrize("profile", ["paper", "quick"])
def test_every_profile_passes_the_parameter_checks(profile):
    # the profiles' values and the notebooks' own defaults lie in the declared ranges
    from obslib.profiles import PROFILES, defaults, validated_parameters

    for nb in run.notebooks():
        declared = defaults(nb.stem)
        validated_parameters(nb.stem, PROFILES[profile][nb.stem], declared)
        validated_parameters(nb.stem, declared, declared)


# --------------------------------------------------------------------------- reruns


def test_reruns_with_different_parameters_never_share_a_file(monkeypatch, runs_dir, capsys):
    monkeypatch.setattr(run, "precompile", lambda: None)
    monkeypatch.setattr(run, "execute", lambda src, dst, parameters, progress=False: 0.5)
    for argv in (["-p", "seed", "1", "01"], ["-p", "seed", "2", "01"], ["--profile", "quick", "01"],
                 ["--profile", "quick", "-p", "seed", "1", "01"], ["-p", "seed", "1", "01"]):
        assert run.main(argv + ["--jobs", "1"]) == 0
    index = json.loads((runs_dir / "index.json").read_text())["runs"]
    outputs = [e["output"] for e in index]
    assert len(outputs) == len(set(outputs)) == 4  # the repeated command replaced its own entry
    for e in index:
        beside = json.loads((runs_dir / e["output"]).with_suffix(".json").read_text())
        assert beside == e and e["notebook"] == "01_model_and_bound" and e["seconds"] == 0.5
        assert e["parameters"] == {**e["parameters"], **e["injected"]}
        assert e["output"].startswith(e["profile"])
    quick = {e["output"]: e for e in index}["quick/01_model_and_bound.ipynb"]
    assert quick["overrides"] == {} and quick["injected"]["n_scenes"] == 200


# --------------------------------------------------------------------------- several at a time


def test_parallel_run_gives_the_outputs_of_a_serial_run(tmp_path, monkeypatch):
    import os

    cwd = os.getcwd()
    monkeypatch.setattr(run, "RUNS_DIR", tmp_path / "serial")
    assert run.main(["--profile", "quick", "--jobs", "1", "03", "07"]) == 0
    monkeypatch.setattr(run, "RUNS_DIR", tmp_path / "parallel")
    assert run.main(["--profile", "quick", "--jobs", "2", "03", "07"]) == 0
    for name in ("03_greedy_unique_pairs.ipynb", "07_greedy_vs_relaxed.ipynb"):
        a, b = (nbformat.read(tmp_path / d / "quick" / name, as_version=4)
                for d in ("serial", "parallel"))
        assert [c.get("outputs") for c in a.cells] == [c.get("outputs") for c in b.cells]
    assert os.getcwd() == cwd  # kernels start in the notebooks' folder; this process stays


def test_first_error_fails_the_command_naming_the_notebook(tmp_path, runs_dir, capfd):
    bad = write_notebook(tmp_path / "00_bad.ipynb", "n = 1", ["raise RuntimeError('boom')"])
    good = write_notebook(tmp_path / "00_good.ipynb", "n = 1", ["print(n)"])
    assert run.main(["--profile", "quick", "--jobs", "2", str(bad), str(good)]) == 1
    out, err = capfd.readouterr()
    assert "00_bad.ipynb" in out and "FAILED" in out
    assert "notebook 00_bad failed" in err and "boom" in err
    with pytest.raises(run.RunFailed, match="00_bad"):
        run.execute_all(run.plan([bad], "quick", {}, False, tmp_path), jobs=1)


def test_progress_of_notebooks_and_cells_goes_to_stderr(tiny_notebook, tmp_path, capfd):
    runs = run.plan([tiny_notebook, tiny_notebook], "quick", {}, False, tmp_path)
    runs = [runs[0], runs[1]._replace(dst=tmp_path / "second.ipynb")]
    seen = []
    times = run.execute_all(runs, jobs=2, progress=True, on_done=lambda r, dt: seen.append(r))
    out, err = capfd.readouterr()
    assert len(seen) == 2 and set(times) == {"00_tiny.ipynb"}
    assert "notebooks: 100%" in err and "cell/s" in err and out == ""
    assert "without encryption" not in err


def test_a_kernel_that_does_not_start_is_started_again_once(tiny_notebook, tmp_path, monkeypatch,
                                                            capsys):
    import shutil

    import papermill

    calls = []

    def flaky(src, dst, **kw):
        calls.append(src)
        if len(calls) == 1:
            raise RuntimeError("Kernel died before replying to kernel_info")
        shutil.copy(src, dst)

    monkeypatch.setattr(papermill, "execute_notebook", flaky)
    run.execute(tiny_notebook, tmp_path / "out.ipynb")
    assert len(calls) == 2 and "did not start" in capsys.readouterr().err

    def broken(src, dst, **kw):
        calls.append(src)
        raise RuntimeError("something else")

    monkeypatch.setattr(papermill, "execute_notebook", broken)
    with pytest.raises(RuntimeError, match="something else"):
        run.execute(tiny_notebook, tmp_path / "out.ipynb")
    assert len(calls) == 3  # not started again
