"""The authors' saved multi-target run (obslib.later_experiment): the file read as the setup
says it must be."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr
from obslib.later_experiment import RUN_NAMES, TRACE_Q, saved_run


@pytest.mark.parametrize("name", RUN_NAMES)
def test_the_first_step_logs_the_initial_state(name):
    """Step 1 logs the initial estimates' errors and the trace of the initial covariance."""
    su = tr.LATER_MULTI_TARGET
    r = saved_run(name)
    assert r.error.shape == r.trace_cov.shape == (100, 3)
    want = np.hypot(*(np.array(su.estimate0) - su.truth_array[0]).T)
    np.testing.assert_allclose(r.error[0], want, rtol=1e-6)
    np.testing.assert_allclose(r.trace_cov[0], np.trace(np.array(su.cov0)), rtol=1e-6)
    assert TRACE_Q == pytest.approx(np.trace(np.array(su.Q)))


def test_steps_without_a_sensor_are_read_from_the_trace():
    """The counts the data's provenance gives: the team greedy leaves the targets without a
    sensor at 33, 22 and 19 of the 99 transitions, the unique pairs never."""
    gen, uni = saved_run("logdet-teams-as-run"), saved_run("unique-pairs")
    assert gen.unobserved().sum(axis=0).tolist() == [33, 22, 19]
    assert not uni.unobserved().any()
    # a tolerance ten times wider finds the same steps: the growths are 0.4 or far from it
    np.testing.assert_array_equal(gen.unobserved(atol=1e-4), gen.unobserved())


def test_arrays_are_fresh_and_names_checked():
    a = saved_run("unique-pairs")
    a.error[0, 0] = 99.0
    assert saved_run("unique-pairs").error[0, 0] != 99.0
    with pytest.raises(ValueError, match="unknown run name"):
        saved_run("gen")
