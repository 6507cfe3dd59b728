"""What a tracking run returns: :class:`TrackingResult` (one run of Section V),
:class:`BatchResult` (many runs of one strategy), :class:`TargetsResult` and
:class:`TargetsBatch` (runs of many targets), and the quantities they derive from the logged
states.

Per-step arrays hold step ``k`` at index ``k - 1``; a batch adds a leading run axis.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .model import inverse_condition
from .setup import TrackingSetup

__all__ = ["TrackingResult", "BatchResult", "TargetsResult", "TargetsBatch"]


def derived_arrays(est, cov, truth_ext) -> dict:
    """Arrays every run logs, for any leading shape: errors, traces, truth, controls.

    ``truth_ext`` holds ``o_1 .. o_{steps+1}`` (the last is where the target moves after the
    last step).

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.tracking.results import derived_arrays
    >>> truth_ext = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    >>> est = np.array([[0.0, 0.0], [1.0, 2.0]])
    >>> d = derived_arrays(est, np.stack([0.5 * np.eye(2)] * 2), truth_ext)
    >>> d["error"].tolist(), d["trace_cov"].tolist(), d["control"].tolist()
    ([0.0, 2.0], [1.0, 1.0], [[1.0, 0.0], [0.0, 1.0]])
    """
    control = truth_ext[..., 1:, :] - truth_ext[..., :-1, :]
    cur = truth_ext[..., :-1, :]
    diff = est - cur
    return {
        "error": np.hypot(diff[..., 0], diff[..., 1]),
        "trace_cov": cov[..., 0, 0] + cov[..., 1, 1],
        "truth": cur,
        "control": control,
        "truth_end": truth_ext[..., -1, :].copy(),
    }



@dataclass(frozen=True, eq=False)
class TrackingResult:
    """One tracking run (:func:`simulate`); per-step arrays, step ``k`` at index ``k - 1``.

    Attributes
    ----------
    setup : TrackingSetup
        The parameters of the run.
    strategy : str
        The pair chooser.
    seed : int or None
        The noise seed (None when an explicit noise table was given).
    noise : (steps, N)
        The noise table used.
    pairs : (steps, 2) int
        The chosen pair, 0-based, ``pairs[:, 0] < pairs[:, 1]``.
    bound : (steps,)
        The chosen pair's bound at the estimate (the setup's metric).
    error : (steps,)
        :math:`\\lVert \\hat x_k - o_k \\rVert` before the step's update.
    trace_cov : (steps,)
        :math:`\\operatorname{tr} \\Sigma_k` before the step's update.
    truth : (steps, 2)
        :math:`o_k`.
    estimate : (steps, 2)
        :math:`\\hat x_k` (before the update).
    cov : (steps, 2, 2)
        :math:`\\Sigma_k` before the update.
    control : (steps, 2)
        The target's move after step :math:`k`: :math:`u_k = o_{k+1} - o_k`.
    truth_end : (2,)
        :math:`o_{\\text{steps}+1}`, where the target is after its last move.
    next_pair : (2,) int
        The pair the sensors would choose after the last step.
    objective : (steps,)
        :math:`C^{-1}([o_{k+1} - p_i; o_{k+1} - p_j; u_k])` with the pair of step :math:`k`: the
        value the adversary of Section V-B minimises (computed on first access).
    true_icn : (steps,)
        The exact :math:`C^{-1}([o_k - p_i; o_k - p_j; u_{k-1}])` the sensors face at step
        :math:`k` with the pair they chose (:math:`u_0 = 0`; computed on first access).
    """

    setup: TrackingSetup
    strategy: str
    seed: int | None
    noise: np.ndarray
    pairs: np.ndarray
    bound: np.ndarray
    error: np.ndarray
    trace_cov: np.ndarray
    truth: np.ndarray
    estimate: np.ndarray
    cov: np.ndarray
    control: np.ndarray
    truth_end: np.ndarray
    next_pair: np.ndarray

    @cached_property
    def objective(self) -> np.ndarray:
        ps = self.setup.sensor_array[self.pairs]  # (..., steps, 2, 2)
        nxt = np.concatenate([self.truth[..., 1:, :], self.truth_end[..., None, :]], axis=-2)
        return inverse_condition(
            np.concatenate([nxt[..., None, :] - ps, self.control[..., None, :]], axis=-2)
        )

    @cached_property
    def true_icn(self) -> np.ndarray:
        ps = self.setup.sensor_array[self.pairs]
        c = self.control
        prev = np.concatenate([np.zeros_like(c[..., :1, :]), c[..., :-1, :]], axis=-2)
        return inverse_condition(
            np.concatenate([self.truth[..., None, :] - ps, prev[..., None, :]], axis=-2)
        )

    @property
    def steps(self) -> int:
        return self.pairs.shape[-2]

    @property
    def switched(self) -> np.ndarray:
        """``(steps - 1,)`` bool: the pair at step ``k + 1`` differs from the pair at step ``k``."""
        return (self.pairs[..., 1:, :] != self.pairs[..., :-1, :]).any(axis=-1)

    @property
    def switches(self):
        """Number of pair changes over the ``steps - 1`` transitions."""
        return int(self.switched.sum())

    def summary(self) -> dict:
        """The run's headline numbers: switches, transitions, mean bound, error and trace."""
        return {
            "switches": self.switches,
            "transitions": self.steps - 1,
            "mean_bound": float(self.bound.mean()),
            "mean_error": float(self.error.mean()),
            "mean_trace": float(self.trace_cov.mean()),
        }


@dataclass(frozen=True, eq=False)
class BatchResult(TrackingResult):
    """Many runs of one strategy (:func:`simulate_batch`): the arrays of :class:`TrackingResult`
    with a leading run axis ``(B, ...)``; ``seeds`` replaces ``seed``. ``run(b)`` gives one run."""

    seeds: tuple = ()

    @property
    def n_runs(self) -> int:
        return self.pairs.shape[0]

    @property
    def switches(self) -> np.ndarray:
        """Pair changes per run, ``(B,)``."""
        return self.switched.sum(axis=-1)

    def run(self, b: int) -> TrackingResult:
        """Run ``b`` as a :class:`TrackingResult`."""
        arrays = {
            f.name: getattr(self, f.name)[b]
            for f in dataclasses.fields(TrackingResult)
            if f.name not in ("setup", "strategy", "seed")
        }
        seed = self.seeds[b] if self.seeds else None
        r = TrackingResult(setup=self.setup, strategy=self.strategy, seed=seed, **arrays)
        for name in ("objective", "true_icn"):  # if already computed for the whole batch
            if name in self.__dict__:
                r.__dict__[name] = self.__dict__[name][b]
        return r


@dataclass(frozen=True, eq=False)
class TargetsResult:
    """One run of many targets (:func:`~obslib.tracking.simulate_targets`); per-step arrays,
    step ``k`` at index ``k - 1``, target ``l`` at index ``l``.

    Attributes
    ----------
    setup : TargetsSetup
        The parameters of the run.
    assignment : str
        The assignment (:data:`~obslib.tracking.ASSIGNMENTS`).
    seed : int or None
        The noise seed (None when an explicit noise table was given).
    noise : (steps, N)
        The noise table used.
    labels : (steps, N) int
        The target each sensor measured at each step (-1: none).
    error : (steps, L)
        :math:`\\lVert \\hat x_{l,k} - o_{l,k} \\rVert` before the step's update.
    trace_cov : (steps, L)
        :math:`\\operatorname{tr} \\Sigma_{l,k}` before the step's update.
    truth, estimate : (steps, L, 2)
        :math:`o_{l,k}` and :math:`\\hat x_{l,k}` (before the update).
    cov : (steps, L, 2, 2)
        :math:`\\Sigma_{l,k}` before the update.
    estimate_end, cov_end : (L, 2), (L, 2, 2)
        The filters after the last update.
    teams : tuple
        Per step, per target, the sorted sensors that measured it (computed on first access).
    """

    setup: object
    assignment: str
    seed: int | None
    noise: np.ndarray
    labels: np.ndarray
    error: np.ndarray
    trace_cov: np.ndarray
    truth: np.ndarray
    estimate: np.ndarray
    cov: np.ndarray
    estimate_end: np.ndarray
    cov_end: np.ndarray

    @property
    def steps(self) -> int:
        return self.labels.shape[-2]

    @property
    def n_targets(self) -> int:
        return self.error.shape[-1]

    @property
    def team_sizes(self) -> np.ndarray:
        """Sensors per target and step, ``(..., steps, L)``."""
        L = self.n_targets
        lab = self.labels
        return (lab[..., None] == np.arange(L)).sum(axis=-2)

    @property
    def unobserved(self) -> np.ndarray:
        """``(..., steps, L)`` bool: the target got no sensor at the step (its covariance grew
        by :math:`Q` alone)."""
        return self.team_sizes == 0

    @cached_property
    def teams(self) -> tuple:
        lab = np.asarray(self.labels)
        if lab.ndim != 2:
            raise ValueError("teams are listed per run: take run(b) of a batch first")
        return tuple(tuple(tuple(int(i) for i in np.flatnonzero(row == l))
                           for l in range(self.n_targets)) for row in lab)

    def summary(self) -> dict:
        """Per-target means over the steps after the first (the first logs the initial
        values, the same for every assignment): error, trace, and the steps without a sensor.

        Examples
        --------
        >>> from obslib import tracking
        >>> su = tracking.LATER_MULTI_TARGET.first(10)
        >>> s = tracking.simulate_targets(su, "unique-pairs").summary()
        >>> sorted(s), s["unobserved"].tolist()
        (['mean_error', 'mean_trace', 'unobserved'], [0, 0, 0])
        """
        sl = slice(1, None) if self.steps > 1 else slice(None)
        return {"mean_error": self.error[..., sl, :].mean(axis=-2),
                "mean_trace": self.trace_cov[..., sl, :].mean(axis=-2),
                "unobserved": self.unobserved.sum(axis=-2)}


@dataclass(frozen=True, eq=False)
class TargetsBatch(TargetsResult):
    """Many runs of one assignment (:func:`~obslib.tracking.simulate_targets_batch`,
    :func:`~obslib.tracking.simulate_targets_scenes`): the arrays of :class:`TargetsResult`
    with a leading run axis ``(B, ...)``; ``seeds`` replaces ``seed``; ``scenes`` holds each
    run's setup where they differ (``setup`` is then the first). ``run(b)`` gives one run."""

    seeds: tuple = ()
    scenes: tuple = ()

    @property
    def n_runs(self) -> int:
        return self.labels.shape[0]

    def run(self, b: int) -> TargetsResult:
        """Run ``b`` as a :class:`TargetsResult`."""
        arrays = {f.name: getattr(self, f.name)[b] for f in dataclasses.fields(TargetsResult)
                  if f.name not in ("setup", "assignment", "seed")}
        seed = self.seeds[b] if self.seeds else None
        setup = self.scenes[b] if self.scenes else self.setup
        return TargetsResult(setup=setup, assignment=self.assignment, seed=seed, **arrays)
