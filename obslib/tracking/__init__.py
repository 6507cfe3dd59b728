"""Tracking simulations: sensor pairs chosen step by step track a circling target (Figs. 4-6)
or an adversary (Fig. 7) with an extended Kalman filter (Section V), and teams of sensors
re-assigned every step track many targets, one filter per target (the authors' later
experiment and larger networks).

In Section V six stationary range sensors serve one target; at each step a *strategy* picks two
of them, which measure the half squared range :math:`z_i = \\tfrac12 \\lVert p_i - o
\\rVert^2 + n_i` to the target (:mod:`~obslib.tracking.model`), and an extended Kalman filter on
the target's 2-D position fuses the two measurements. With many targets
(:mod:`~obslib.tracking.targets`) an *assignment* gives every target its sensors at every step.
Both run on one engine (:mod:`~obslib.tracking.engine`). The parts:

:mod:`~obslib.tracking.setup`
    the parameter records: :class:`TrackingSetup` with the paper's :data:`PAPER_CIRCLE` and
    :data:`PAPER_ADVERSARIAL`; :class:`TargetsSetup` with the authors' later experiment
    :data:`LATER_MULTI_TARGET` and larger networks (:func:`network_scene`); the common noise
    tables;
:mod:`~obslib.tracking.model`
    the measurement functions and their Jacobians, the circle, the pair bound along a run;
:mod:`~obslib.tracking.choosers`
    the pair choosers: the paper's :data:`STRATEGIES` (``"best-pair"``, ``"best-partner"``,
    ``"fixed-pair"``, by Theorem 4's bound) and, beyond the paper, :data:`CRITERIA`
    (``"d-optimal"``, ``"a-optimal"``, ``"e-optimal"`` on the filter's information,
    ``"exact-icn"`` an oracle knowing the target's control, ``"random"``);
:mod:`~obslib.tracking.adversary`
    the adversarial target's moves (Section V-B);
:mod:`~obslib.tracking.kalman`
    the extended Kalman filter's predict and update, for one filter or many at once
    (filterpy's equations; the tests hold them to filterpy);
:mod:`~obslib.tracking.engine`
    the one step loop of every run, over many filters at once;
:mod:`~obslib.tracking.batch`
    Section V on the engine: :func:`simulate` (one run), :func:`simulate_batch`,
    :func:`simulate_many`, :func:`monte_carlo` (many runs over seeds, strategies and setup
    variants at once);
:mod:`~obslib.tracking.targets`
    many targets on the engine: :func:`simulate_targets` (one run),
    :func:`simulate_targets_batch` (many noise seeds), :func:`simulate_targets_scenes` (many
    scenes), :func:`step_times`;
:mod:`~obslib.tracking.assigners`
    the assignments of sensors to many targets (:data:`ASSIGNMENTS`);
:mod:`~obslib.tracking.code_logdet`
    the authors' team greedy as their code evaluates it in floating point;
:mod:`~obslib.tracking.results`
    :class:`TrackingResult`, :class:`BatchResult`, :class:`TargetsResult` and
    :class:`TargetsBatch`;
:mod:`~obslib.tracking.stats`
    comparisons, correlations, switches, track loss, entrapment.

Noise is common to all strategies and assignments: entry ``[k-1, i]`` of a ``(steps, N)`` table
is sensor ``i``'s noise at step ``k``, whichever strategy asks for it and whatever target it
serves (:func:`noise_table`).

The drawings are in :mod:`obslib.viz.tracking` and the studies of the paper's claims in
:mod:`obslib.studies.two_sensors_tracking` (Section V-A) and
:mod:`obslib.studies.adversarial_target` (Section V-B).
"""

from __future__ import annotations

from .assigners import ASSIGNMENTS, PAIR_ASSIGNMENTS, assign_targets
from .batch import monte_carlo, simulate, simulate_batch, simulate_many
from .choosers import CRITERIA, STRATEGIES, choose_pairs
from .model import (
    circle_truth,
    euclidean_range,
    euclidean_range_jacobian,
    half_squared_range,
    pair_bound_series,
    range_jacobian,
    target_objective,
)
from .results import BatchResult, TargetsBatch, TargetsResult, TrackingResult
from .setup import (
    ADVERSARIES,
    LATER_MULTI_TARGET,
    LATER_SENSORS,
    METRICS,
    MOTIONS,
    PAPER_ADVERSARIAL,
    PAPER_CIRCLE,
    PAPER_SENSORS,
    PARAM_FIELDS,
    TargetsSetup,
    TrackingSetup,
    circle_paths,
    network_scene,
    noise_table,
    paper_controls,
    setup_from_params,
)
from .stats import (
    ENTRAPMENT_CRITERIA,
    LOSS_THRESHOLD,
    TIE_RTOL,
    Entrapment,
    bound_correlation,
    clearly_lower,
    compare_strategies,
    entrapment,
    is_entrapped,
    mirror_point,
    spearman,
    switch_back_fraction,
    switch_rate,
    track_loss,
)
from .targets import (
    simulate_targets,
    simulate_targets_batch,
    simulate_targets_scenes,
    step_times,
)

__all__ = [
    "STRATEGIES",
    "CRITERIA",
    "METRICS",
    "ADVERSARIES",
    "MOTIONS",
    "PARAM_FIELDS",
    "PAPER_SENSORS",
    "TrackingSetup",
    "PAPER_CIRCLE",
    "PAPER_ADVERSARIAL",
    "TIE_RTOL",
    "LOSS_THRESHOLD",
    "clearly_lower",
    "TrackingResult",
    "BatchResult",
    "paper_controls",
    "noise_table",
    "setup_from_params",
    "circle_truth",
    "half_squared_range",
    "range_jacobian",
    "euclidean_range",
    "euclidean_range_jacobian",
    "choose_pairs",
    "pair_bound_series",
    "target_objective",
    "simulate",
    "simulate_batch",
    "simulate_many",
    "monte_carlo",
    "compare_strategies",
    "spearman",
    "Entrapment",
    "entrapment",
    "ENTRAPMENT_CRITERIA",
    "is_entrapped",
    "switch_rate",
    "switch_back_fraction",
    "bound_correlation",
    "mirror_point",
    "track_loss",
    "ASSIGNMENTS",
    "PAIR_ASSIGNMENTS",
    "TargetsSetup",
    "LATER_SENSORS",
    "LATER_MULTI_TARGET",
    "TargetsResult",
    "TargetsBatch",
    "circle_paths",
    "network_scene",
    "assign_targets",
    "simulate_targets",
    "simulate_targets_batch",
    "simulate_targets_scenes",
    "step_times",
]
