"""Tracking entries of the ledger at the ends of their chapters' parameter ranges, where the
chapters' verdict boxes re-check them: a target that never closes in on a sensor, and runs in
which no strategy's bound correlates with its error."""

from __future__ import annotations

import numpy as np

from obslib import tracking as tr
from obslib.claims import recheck
from obslib.profiles import params


def _moves_closer(run) -> np.ndarray:
    """Per transition, whether the target's move brought it nearer to a sensor of the pair that
    had just measured it (distances before and after the move, computed here)."""
    s = run.setup.sensor_array
    out = []
    for k in range(run.steps - 1):
        pair = s[run.pairs[k]]
        o, o_next = run.truth[k], run.truth[k] + run.control[k]
        out.append(np.linalg.norm(pair - o_next, axis=1).min()
                   < np.linalg.norm(pair - o, axis=1).min())
    return np.array(out)


def test_a_target_that_never_closes_in_leaves_the_mechanism_untestable():
    p = params("06_adversarial_target", "quick") | {"u_max": 10.0, "n_seeds": 2, "steps": 60}
    r = recheck("fig7-switch-mechanism", p)
    runs = [tr.simulate(tr.setup_from_params(tr.PAPER_ADVERSARIAL, p), "best-pair", seed=k)
            for k in range(2)]
    assert not any(_moves_closer(run).any() for run in runs)  # the premise, by hand
    assert r.status == "untestable" and "never moves closer" in r.summary
    assert np.isnan(r.evidence["switch_if_closer"]) and r.evidence["closer_fraction"] == 0
    assert dict(r.table.rows)["of those, transitions where the pair then switches"] == "none"


def test_no_correlating_strategy_is_refuted_not_a_crash():
    p = params("05_two_sensors_tracking", "quick") | {"q": 1e-6, "n_seeds": 3}
    r = recheck("fig6-bound-correlation", p)
    med = r.evidence["median_own"]
    holds = [d["error"] <= -0.1 and d["trace"] <= -0.1 for d in med.values()]
    assert not any(holds) and r.status == "refuted"
    assert "no strategy" in r.summary
