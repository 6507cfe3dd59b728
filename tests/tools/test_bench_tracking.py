"""The closed-loop benchmark (python -m obslib.bench tracking): what it times and its command
line."""

import json

import pytest

from obslib import tracking
from obslib.tools.bench import main, parse_args
from obslib.tools.bench_tracking import bench_tracking


def test_the_benchmark_times_the_loop_and_the_greedy_of_the_same_run():
    r = bench_tracking(24, 6, steps=5, repeat=2)
    assert r["steps"] == 2 * 4  # the last step makes no assignment: not timed
    assert r["step_over_greedy"] == pytest.approx(r["step_ms"] / r["greedy_ms"], rel=1e-2)
    assert r["steps_per_s"] == pytest.approx(1e3 / r["step_ms"], rel=1e-2)


def test_step_times_cover_every_step_but_the_last():
    su = tracking.LATER_MULTI_TARGET.first(6)
    t, run = tracking.step_times(su, "unique-pairs", seed=1)
    assert t.shape == (5,) and (t > 0).all()
    one = tracking.simulate_targets(su, "unique-pairs", seed=1)
    assert run.teams == one.teams


def test_command_line_defaults_and_refusals(capsys):
    args = parse_args(["tracking"])
    assert (args.sensors, args.targets) == (1000, 100)
    assert parse_args(["tracking", "--targets", "7"]).sensors == 1000
    with pytest.raises(SystemExit) as err:
        parse_args(["tracking", "--sensors", "10", "--targets", "6"])
    assert err.value.code == 2
    assert "two sensors per target" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        parse_args(["criteria", "--sensors", "10"])


def test_command_line_prints_the_json_line_last(capsys):
    assert main(["tracking", "--sensors", "20", "--targets", "5"]) == 0
    last = capsys.readouterr().out.strip().splitlines()[-1]
    out = json.loads(last)
    assert {"step_ms", "step_over_greedy", "steps_per_s"} <= set(out)
