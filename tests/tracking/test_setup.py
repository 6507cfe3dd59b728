"""The parameter record (obslib.tracking.setup): validation, immutability, the paper's values."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


@pytest.mark.parametrize(
    "changes, match",
    [
        ({"sensors": np.zeros((0, 2))}, "no sensors"),
        ({"sensors": []}, "no sensors"),
        ({"sensors": None}, "no sensors"),
        ({"sensors": [[0.0, 0.0]]}, "1 sensor"),
        ({"sensors": [[0.0, 0.0], [np.nan, 1.0]]}, "sensor 1 has a non-finite"),
        ({"sensors": [[0.0, 0.0], [1.0, 1.0], [0.0, 0.0]]}, "sensors 0 and 2 coincide"),
        ({"sensors": [[0.0, 0.0, 1.0]]}, "shape"),
        ({"steps": 0}, "steps must be at least 1"),
        ({"steps": 2.5}, "steps must be an integer"),
        ({"u_max": np.nan}, "u_max must be finite"),
        ({"u_max": -1.0}, "u_max must be non-negative"),
        ({"cov0": [[1.0, 0.0], [0.0, -1.0]]}, "cov0 is not positive definite"),
        ({"cov0": [[1.0, 0.2], [0.0, 1.0]]}, "cov0 is not symmetric"),
        ({"Q": 0.0}, "Q is not positive definite"),
        ({"Q": [[np.nan, 0], [0, 1]]}, "Q has a non-finite"),
        ({"R": [[1.0, 2.0], [2.0, 1.0]]}, "R is not positive definite"),
        ({"R": np.eye(3)}, "R must be a 2x2"),
        ({"estimate0": (np.nan, 0.0)}, "estimate0 has a non-finite"),
        ({"noise_std": -0.1}, "noise_std must be non-negative"),
        ({"motion": "spiral"}, "motion must be one of"),
        ({"motion": "adversarial"}, "needs a start"),
        ({"start": (1.0, 1.0)}, "start is for the adversarial"),
        ({"controls": [[5.0, 0.0]]}, "control 0 has norm"),
        ({"metric": "manhattan"}, "metric must be one of"),
        ({"adversary": "psychic"}, "adversary must be one of"),
        ({"anchor": 6}, "anchor must be a sensor index"),
        ({"fixed_pair": (2, 2)}, "names sensor 2 twice"),
        ({"fixed_pair": (0, 9)}, "fixed_pair must be two sensor indices"),
    ],
)
def test_bad_setups_raise(changes, match):
    with pytest.raises(ValueError, match=match):
        CIRCLE.replace(**changes)


def test_setups_are_frozen_parameter_records():
    import dataclasses

    with pytest.raises(dataclasses.FrozenInstanceError):
        CIRCLE.steps = 3
    assert CIRCLE.replace(Q=0.5, R=0.5, cov0=0.5) == CIRCLE
    assert hash(CIRCLE) == hash(tr.TrackingSetup())
    assert ADV.u_max == 0.1 and ADV.start == (2.0, 2.0) and ADV.estimate0 == (2.5, 1.5)
    second = [2 + 3 * np.cos(0.02), 3 + 3 * np.sin(0.02)]
    np.testing.assert_allclose(tr.circle_truth(CIRCLE)[[0, 1]], [[5, 3], second])


def test_paper_controls():
    c = tr.paper_controls(0.1)
    assert c.shape == (64, 2)
    np.testing.assert_array_equal(c[0], [0, 0])
    np.testing.assert_allclose(np.hypot(*c[1:].T), 0.1)
    np.testing.assert_allclose(np.arctan2(c[-1, 1], c[-1, 0]) % (2 * np.pi), 6.2)


# --------------------------------------------------------------------------------------------
# Named errors for values of the wrong kind or scale
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "changes, match",
    [
        ({"u_max": True}, "u_max must be a real number, got a bool"),
        ({"radius": 1 + 2j}, "radius must be a real number, got a complex"),
        ({"noise_std": "0.5"}, "noise_std must be a real number, got text"),
        ({"sensors": [[0.0, 0.0], [1j, 1.0]]}, "sensors must be real points"),
        ({"cov0": True}, "cov0 must be a real 2x2 matrix"),
        ({"estimate0": (True, 0.0)}, "estimate0 must be a real point"),
    ],
)
def test_values_of_the_wrong_kind_raise_type_errors(changes, match):
    with pytest.raises(TypeError, match=match):
        CIRCLE.replace(**changes)


def test_a_covariance_too_large_for_the_filter_is_named():
    """1e300 I is refused where it is given, not later as "cov of target 0"."""
    with pytest.raises(ValueError, match=r"cov0 has entries of scale 1e\+300"):
        CIRCLE.replace(cov0=1e300)
    with pytest.raises(ValueError, match="Q has entries of scale"):
        CIRCLE.replace(Q=[[1e200, 0.0], [0.0, 1e200]])


def test_a_tiny_positive_definite_covariance_is_accepted():
    """Scale 1e-170: the determinant (1e-340) underflows to 0, yet the matrix is positive
    definite; the checks run on the matrix divided by its largest entry."""
    c = 1e-170 * np.array([[2.0, 0.5], [0.5, 1.0]])
    setup = CIRCLE.replace(cov0=c)
    np.testing.assert_array_equal(np.array(setup.cov0), c)
    with pytest.raises(ValueError, match="cov0 is not positive definite"):
        CIRCLE.replace(cov0=1e-170 * np.array([[1.0, 2.0], [2.0, 1.0]]))
