"""The shared studies of Sections V-A/V-B (obslib.studies.tracking)."""

from __future__ import annotations

import pytest

from obslib import tracking as tr
from obslib.studies import tracking as study

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_partner_study_equals_one_monte_carlo_per_partner():
    setup = CIRCLE.replace(steps=50)
    ps = study.partner_study(setup, 3, first_seed=2)
    assert sorted(ps) == [0, 2, 3, 4, 5]
    for j, d in ps.items():
        r = tr.monte_carlo(setup.replace(fixed_pair=(1, j)), 3, ["fixed-pair"], 2)["fixed-pair"]
        run_err = r.error[:, 1:].mean(axis=1)
        assert d["mean_error"] == pytest.approx(run_err.mean(), rel=1e-12)
        assert d["mean_trace"] == pytest.approx(r.trace_cov[:, 1:].mean(), rel=1e-12)
        assert d["mean_bound"] == pytest.approx(r.bound[:, 1:].mean(), rel=1e-12)
