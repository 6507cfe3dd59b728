"""Fixtures shared by the tests of obslib.tracking."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr

CIRCLE = tr.PAPER_CIRCLE


@pytest.fixture(scope="module")
def runs():
    """The three strategies at the default seed (and the Euclidean variant of each)."""
    out = {(s, "mahalanobis"): tr.simulate(CIRCLE, s, seed=0) for s in tr.STRATEGIES}
    eu = CIRCLE.replace(metric="euclidean")
    out.update({(s, "euclidean"): tr.simulate(eu, s, seed=0) for s in tr.STRATEGIES})
    return out


def _random_states(rng, n, spread=3.0):
    """Estimates around the paper's scene and random SPD covariances."""
    x = rng.normal([2.0, 2.0], spread, size=(n, 2))
    A = rng.normal(size=(n, 2, 2))
    cov = A @ np.swapaxes(A, 1, 2) + 0.05 * np.eye(2)
    return x, cov


@pytest.fixture
def random_states():
    """Estimates around the paper's scene and random SPD covariances: ``random_states(rng, n)``."""
    return _random_states
