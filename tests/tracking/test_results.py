"""The result records (obslib.tracking.results): lazily derived quantities."""

from __future__ import annotations

import numpy as np
import pytest

import obslib as ob
from obslib import tracking as tr

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_lazy_icn_of_a_run_equals_the_batch():
    b = tr.simulate_batch(ADV.replace(steps=30), "best-pair", seeds=[0, 1])
    r = b.run(1)
    fresh = tr.TrackingResult(**{
        f: getattr(r, f) for f in r.__dataclass_fields__
    })
    # one run against the batch: the same elementwise closed form over different shapes,
    # equal to rounding (values in [0, 1])
    np.testing.assert_allclose(fresh.true_icn, b.true_icn[1], rtol=0, atol=1e-14)
    np.testing.assert_allclose(fresh.objective, b.objective[1], rtol=0, atol=1e-14)
    s = ADV.sensor_array
    k = 7
    want = ob.inverse_condition_number(s[r.pairs[k]], r.truth[k], r.control[k - 1])
    assert r.true_icn[k] == pytest.approx(want, abs=1e-12)
