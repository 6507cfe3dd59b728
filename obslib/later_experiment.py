"""The authors' later multi-target run, as data shipped with the package.

The per-step estimation error and trace of the covariance of the three targets of the closed-loop
experiment the authors saved in their code repository and never published, for its two
assignments (``obslib/data/later_experiment/README.md`` gives the provenance). The setup is
:data:`obslib.tracking.LATER_MULTI_TARGET`.

>>> from obslib.later_experiment import saved_run
>>> r = saved_run("logdet-teams-as-run")
>>> r.error.shape, r.trace_cov[0].tolist()
((100, 3), [1.0, 1.0, 1.0])

Runs are named by the assignment of :mod:`obslib.tracking.assigners` that the saved script ran:
``"unique-pairs"`` (the unique-pair script) and ``"logdet-teams-as-run"`` (the general-team
script, whose filters measure with the sensors numbered by the greedy's rounds). Step ``k``
sits at index ``k - 1`` and target ``l`` (1-based in the scripts) at index ``l - 1``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources

import numpy as np

from ._validate import as_choice, as_nonnegative

__all__ = ["RUN_NAMES", "STEPS", "N_TARGETS", "TRACE_Q", "SavedLaterRun", "saved_run"]

#: Names accepted by :func:`saved_run`, and the scripts' prefixes in the data file.
RUN_NAMES = ("unique-pairs", "logdet-teams-as-run")
_PREFIX = {"unique-pairs": "uni", "logdet-teams-as-run": "gen"}

#: Steps of the saved runs and their targets.
STEPS = 100
N_TARGETS = 3

#: :math:`\operatorname{tr} Q` of the experiment's filters: the growth of the trace over a step
#: at which a target receives no sensor.
TRACE_Q = 0.4

_FILE = "per_step_error_and_trace.csv"


@dataclass(frozen=True, eq=False)
class SavedLaterRun:
    """The logged per-step data of one saved run (arrays ``(100, 3)``, step ``k`` at index
    ``k - 1``, target ``l`` at ``l - 1``).

    Attributes
    ----------
    name : str
        One of :data:`RUN_NAMES`.
    error : (100, 3)
        :math:`\\lVert \\hat x_{l,k} - o_{l,k} \\rVert` before the step's update.
    trace_cov : (100, 3)
        :math:`\\operatorname{tr} \\Sigma_{l,k}` before the step's update.
    """

    name: str
    error: np.ndarray
    trace_cov: np.ndarray

    def unobserved(self, atol: float = 1e-5) -> np.ndarray:
        """``(99, 3)`` bool: the target got no sensor at step ``k`` (``k = 1 .. 99``), read from
        the trace, which then grows by exactly :data:`TRACE_Q` to step ``k + 1`` (within
        ``atol``: the file holds six significant digits).

        Examples
        --------
        >>> saved_run("logdet-teams-as-run").unobserved().sum(axis=0).tolist()
        [33, 22, 19]
        >>> int(saved_run("unique-pairs").unobserved().sum())
        0
        """
        atol = as_nonnegative(atol, "atol")
        return np.abs(np.diff(self.trace_cov, axis=0) - TRACE_Q) <= atol

    def summary(self) -> dict:
        """Per-target means over the steps after the first (which logs the initial values),
        and the steps without a sensor (:meth:`unobserved`).

        Examples
        --------
        >>> s = saved_run("unique-pairs").summary()
        >>> s["mean_error"].round(3).tolist()
        [0.25, 0.257, 0.206]
        """
        return {"mean_error": self.error[1:].mean(axis=0),
                "mean_trace": self.trace_cov[1:].mean(axis=0),
                "unobserved": self.unobserved().sum(axis=0)}


@cache
def _columns() -> dict:
    path = resources.files("obslib").joinpath("data", "later_experiment", _FILE)
    lines = path.read_text(encoding="utf-8").splitlines()
    header = lines[0].strip().split(",")
    data = np.array([[float(x) for x in line.split(",")] for line in lines[1:] if line.strip()])
    if data.shape != (STEPS, len(header)) or not np.array_equal(data[:, 0],
                                                                 np.arange(1, STEPS + 1)):
        raise RuntimeError(f"{_FILE}: expected steps 1..{STEPS} in {len(header)} columns")
    return {name: data[:, i] for i, name in enumerate(header)}


def saved_run(name: str) -> SavedLaterRun:
    """The saved run of one assignment (:data:`RUN_NAMES`), fresh arrays.

    Examples
    --------
    >>> r = saved_run("unique-pairs")
    >>> r.error[0].round(4).tolist(), r.trace_cov[1].round(7).tolist()
    ([0.7071, 2.1213, 0.7071], [0.0778002, 0.0756757, 0.0798803])
    """
    as_choice(name, RUN_NAMES, "run name")
    col = _columns()
    p = _PREFIX[name]
    error = np.stack([col[f"{p}_tar_mean_error_{l}"] for l in range(1, N_TARGETS + 1)], axis=1)
    trace = np.stack([col[f"{p}_tar_tra_cova_{l}"] for l in range(1, N_TARGETS + 1)], axis=1)
    return SavedLaterRun(name=name, error=error, trace_cov=trace)
