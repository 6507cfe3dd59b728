"""Many targets in closed loop: at every step an assignment gives each target its sensors, and
one extended Kalman filter per target fuses their measurements.

The paper's experiments track one target (Figs. 4-7) or assign sensors once, without tracking
(Figs. 8-9). Its authors closed the loop afterwards, in an experiment of their code repository
the paper never published: eight range sensors, three targets on circles, one filter per
target, the sensors re-assigned every step. :data:`LATER_MULTI_TARGET` holds that experiment's
parameters as its code runs it, :func:`network_scene` draws larger networks of the same kind,
and :func:`simulate_targets` and :func:`simulate_targets_batch` run them with any assignment of
:data:`~obslib.tracking.ASSIGNMENTS` on the tracking engine (:mod:`~obslib.tracking.engine`).

Order within step :math:`k` (the authors' and Section V's): assign the sensors from the
current estimates and covariances; log each target's error :math:`\\lVert \\hat x_{l,k} -
o_{l,k} \\rVert` and :math:`\\operatorname{tr} \\Sigma_{l,k}` before the update; predict every
filter (:math:`\\Sigma \\leftarrow \\Sigma + Q`); each sensor measures its target's true
position, entry ``[k - 1, i]`` of the run's noise table added to sensor ``i``'s measurement
whatever target it serves; update every filter with its team's measurements (Joseph form; a
target without a sensor keeps its prediction, so its trace grows by exactly
:math:`\\operatorname{tr} Q`). The targets' paths are known in advance.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Iterable

import numpy as np

from .._validate import (
    ArgumentTypeError,
    as_float_array,
    as_instance,
    as_int,
    as_names,
    as_noise_table,
)
from . import kalman
from .assigners import ASSIGNMENTS, TeamChooser, check_assignment
from .engine import FilterBank, FixedPaths, run_steps, singular_update_message
from .results import TargetsBatch, TargetsResult
from .setup import TargetsSetup, noise_table, run_table, seeds_or_noise

__all__ = [
    "simulate_targets",
    "simulate_targets_batch",
    "simulate_targets_scenes",
    "SCENE_FIELDS",
    "step_times",
]

# --------------------------------------------------------------------------------------------
# The engine's pass
# --------------------------------------------------------------------------------------------


def _assignments_iv(setup, assignments) -> list:
    """A list of distinct names of :data:`ASSIGNMENTS` that ``setup`` can run."""
    if isinstance(assignments, str):
        raise ArgumentTypeError(f"assignments must be a list of names, got the string "
                                f"{assignments!r}; write [{assignments!r}]")
    names = list(dict.fromkeys(as_names(assignments, "assignments", ASSIGNMENTS)))
    if not names:
        raise ValueError("assignments is empty")
    for name in names:
        check_assignment(setup, name)
    return names


def _pass(setups, kinds, tables, seeds, single: bool = False,
          clock: list | None = None, draws=None) -> dict:
    """``R = len(kinds)`` runs at once: row ``r`` follows the assignment ``kinds[r]`` with the
    noise table ``tables[r % B]``, the scene ``setups[r % len(setups)]`` (one setup, or one per
    table: setups that differ only in ``sensors``, ``truth`` and ``estimate0``) and the seed
    ``seeds[r]`` (for ``"random"``, unless ``draws[r % B]`` gives its permutations). Returns the
    logs as run-major arrays; ``clock`` (a list) receives the ``time.perf_counter()`` at the
    start of every step."""
    setup = setups[0]
    R_ = len(kinds)
    B, steps, N = tables.shape
    C = len(setups)
    L = setup.n_targets
    S = np.stack([su.sensor_array for su in setups])  # (C, N, 2)
    truth = np.stack([su.truth_array for su in setups])  # (C, steps + 1, L, 2)
    x0 = np.stack([np.array(su.estimate0) for su in setups])  # (C, L, 2)
    scene = np.arange(R_) % C
    F = R_ * L
    filters = FilterBank(x0[scene].reshape(F, 2), np.broadcast_to(setup.cov0, (F, 2, 2)),
                         setup.Q)
    chooser = TeamChooser(setup, kinds, seeds, S, draws)
    labels_log = np.empty((steps, R_, N), dtype=np.int16 if L < 2**15 else np.int64)
    est = np.empty((steps, F, 2))
    cov = np.empty((steps, F, 2, 2))

    def choose(k, control):
        if k == steps:
            return None  # no step follows the last
        return chooser(filters.estimates().reshape(R_, L, 2),
                       filters.covariances().reshape(R_, L, 2, 2), k)

    def record(k, labels):
        if clock is not None:
            clock.append(time.perf_counter())
        labels_log[k] = labels
        est[k] = filters.estimates()
        cov[k] = filters.covariances()

    def update(k, labels, position):
        P = filters.predict()
        rr, ii = np.nonzero(labels >= 0)  # runs, then sensors, ascending
        owner = rr * L + labels[rr, ii]
        order = np.argsort(owner, kind="stable")
        rr, ii, owner = rr[order], ii[order], owner[order]
        try:
            filters.update_teams(P, owner, S[scene[rr], ii], position[scene[rr], owner % L],
                                 tables[rr % B, k, ii], setup.R, setup.measurement)
        except kalman.SingularInnovation as e:
            f = int(np.flatnonzero(~e.ok)[0])
            r, l = divmod(f, L)
            x = np.array([filters.xx[f], filters.xy[f]])
            ps = S[scene[r], ii[owner == f]]
            raise ValueError(singular_update_message(x, ps, k, None if single else r, l)) from None

    run_steps(steps, update, choose, FixedPaths(truth), record)
    est_r = est.reshape(steps, R_, L, 2).transpose(1, 0, 2, 3)
    cov_r = cov.reshape(steps, R_, L, 2, 2).transpose(1, 0, 2, 3, 4)
    tru = truth[scene, :steps] if C > 1 else np.broadcast_to(truth[:, :steps], (R_, steps, L, 2))
    diff = est_r - tru
    return {
        "labels": np.ascontiguousarray(labels_log.transpose(1, 0, 2)),
        "error": np.hypot(diff[..., 0], diff[..., 1]),
        "trace_cov": cov_r[..., 0, 0] + cov_r[..., 1, 1],
        "truth": tru,
        "estimate": np.ascontiguousarray(est_r),
        "cov": np.ascontiguousarray(cov_r),
        "estimate_end": filters.estimates().reshape(R_, L, 2),
        "cov_end": filters.covariances().reshape(R_, L, 2, 2),
    }


def simulate_targets(setup: TargetsSetup, assignment: str, noise=None,
                     seed: int = 0) -> TargetsResult:
    """One run of many targets in closed loop (the module docstring gives the order of a step).

    Parameters
    ----------
    setup : TargetsSetup
        E.g. :data:`LATER_MULTI_TARGET` or a :func:`network_scene`.
    assignment : str
        A name of :data:`~obslib.tracking.ASSIGNMENTS` (see
        :mod:`~obslib.tracking.assigners`).
    noise : array_like, shape (steps, N), optional
        Entry ``[k-1, i]`` is added to sensor ``i``'s measurement at step ``k``, the same for
        every assignment. Default: :func:`~obslib.tracking.noise_table` of ``seed``.
    seed : int
        Seed of the noise table when ``noise`` is not given, and of the ``"random"``
        assignment's draws in any case.

    Returns
    -------
    TargetsResult
        Per-step arrays: ``teams`` (each target's sorted sensors), ``labels``, ``error``,
        ``trace_cov`` (logged before each step's update), ``truth``, ``estimate``, ``cov``.

    Examples
    --------
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET
    >>> r = tracking.simulate_targets(su, "unique-pairs", seed=0)
    >>> r.teams[0]
    ((0, 6), (3, 7), (1, 4))
    >>> r.error.shape, r.error[0].round(4).tolist()
    ((100, 3), [0.7071, 2.1213, 0.7071])
    >>> r.trace_cov[1].round(4).tolist()
    [0.0778, 0.0757, 0.0799]
    """
    as_instance(setup, TargetsSetup, "setup")
    check_assignment(setup, assignment)
    table, used = run_table(setup, noise, seed, assignment == "random")
    res = _pass((setup,), [assignment], table[None], [seed], single=True)
    return TargetsResult(setup=setup, assignment=assignment, seed=used, noise=table,
                         **{k: np.array(v[0]) for k, v in res.items()})


def simulate_targets_batch(setup: TargetsSetup, assignments, seeds=None, noise=None) -> dict:
    """Several assignments over many noise realisations at once, with common noise.

    Run ``b`` of every assignment uses ``noise_table(setup, seeds[b])`` (or
    ``noise[b]``), so it equals ``simulate_targets(setup, assignment, seed=seeds[b])``; all
    runs of all assignments advance together on the engine.

    Parameters
    ----------
    setup : TargetsSetup
    assignments : list of str
        Names of :data:`~obslib.tracking.ASSIGNMENTS`.
    seeds : iterable of int, optional
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds (not with ``"random"``, which draws from the
        seed).

    Returns
    -------
    dict
        ``{assignment: TargetsBatch}`` in the order given.

    Examples
    --------
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET.first(20)
    >>> names = ["unique-pairs", "logdet-teams"]
    >>> runs = tracking.simulate_targets_batch(su, names, seeds=[0, 1, 2])
    >>> runs["logdet-teams"].labels.shape
    (3, 20, 8)
    >>> runs["unique-pairs"].team_sizes[0, 0].tolist()
    [2, 2, 2]
    """
    as_instance(setup, TargetsSetup, "setup")
    names = _assignments_iv(setup, assignments)
    seeds, given = seeds_or_noise(seeds, noise)
    if given is not None:
        if "random" in names:
            raise ValueError("the random assignment draws from the run's seed: give seeds, "
                             "not noise tables")
        tables = np.stack([as_noise_table(t, (setup.steps, setup.n_sensors)) for t in given])
    else:
        tables = np.stack([noise_table(setup, x) for x in seeds])
    B = tables.shape[0]
    kinds = np.repeat(names, B)
    row_seeds = list(seeds) * len(names) if seeds else [0] * (B * len(names))
    res = _pass((setup,), kinds, tables, row_seeds)
    out = {}
    for g, name in enumerate(names):
        sl = slice(g * B, (g + 1) * B)
        out[name] = TargetsBatch(setup=setup, assignment=name, seed=None, noise=tables,
                                 seeds=seeds, **{k: v[sl] for k, v in res.items()})
    return out


#: Fields in which the scenes of :func:`simulate_targets_scenes` may differ.
SCENE_FIELDS = ("sensors", "truth", "estimate0")


def simulate_targets_scenes(setups, assignments, seeds=None, noise=None, draws=None) -> dict:
    """Several assignments on several scenes at once, one run per scene: scene ``b``
    (``setups[b]``) with the noise of ``seeds[b]`` (or the table ``noise[b]``), for every
    assignment.

    Run ``b`` of every assignment equals ``simulate_targets(setups[b], assignment,
    seed=seeds[b])``. The setups must agree in everything but :data:`SCENE_FIELDS` and have
    the same numbers of sensors, targets and steps (e.g. :func:`network_scene` of several
    seeds); all runs advance together on the engine.

    Parameters
    ----------
    setups : list of TargetsSetup
    assignments : list of str
        Names of :data:`~obslib.tracking.ASSIGNMENTS`.
    seeds : iterable of int, optional
        One per scene: its noise table (:func:`~obslib.tracking.noise_table`) and its ``"random"``
        draws.
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.
    draws : array_like of int, shape (B, steps, N), optional
        Explicit permutations of the sensors for ``"random"`` (row ``k - 1`` for step ``k``),
        instead of the seeds' draws.

    Returns
    -------
    dict
        ``{assignment: TargetsBatch}`` with the scenes in ``scenes``.

    Examples
    --------
    >>> from obslib import tracking
    >>> scenes = [tracking.network_scene(12, 3, steps=10, seed=s) for s in (0, 1)]
    >>> runs = tracking.simulate_targets_scenes(scenes, ["unique-pairs"],
    ...                                         seeds=[0, 1])
    >>> b = runs["unique-pairs"]
    >>> b.error.shape, b.run(1).setup is scenes[1]
    ((2, 10, 3), True)
    """
    if isinstance(setups, TargetsSetup) or not isinstance(setups, (list, tuple)):
        raise ArgumentTypeError(f"setups must be a list of TargetsSetup, got {setups!r}")
    setups = tuple(as_instance(su, TargetsSetup, "each of setups") for su in setups)
    if not setups:
        raise ValueError("setups is empty")
    first = setups[0]
    B = len(setups)
    for b, su in enumerate(setups):
        for f in dataclasses.fields(TargetsSetup):
            if f.name not in SCENE_FIELDS and getattr(su, f.name) != getattr(first, f.name):
                raise ValueError(f"setups {b} and 0 differ in {f.name}: scenes may differ only "
                                 f"in {SCENE_FIELDS}")
        if (su.n_sensors, su.n_targets, su.steps) != (first.n_sensors, first.n_targets,
                                                      first.steps):
            raise ValueError(f"setups {b} and 0 differ in their numbers of sensors, targets or "
                             "steps")
    names = _assignments_iv(first, assignments)
    shape = (first.steps, first.n_sensors)
    if seeds is not None:
        if isinstance(seeds, (str, bytes)) or not isinstance(seeds, Iterable):
            raise ArgumentTypeError(f"seeds must be an iterable of non-negative integers, got "
                                    f"{seeds!r}")
        seeds = tuple(as_int(x, "each seed", 0) for x in seeds)
        if len(seeds) != B:
            raise ValueError(f"seeds must give one seed per scene ({B}), got {len(seeds)}")
    if noise is not None:
        given = as_float_array(noise, "noise")
        if given.ndim != 3 or given.shape[0] != B:
            raise ValueError(f"noise must have shape ({B}, steps, N), one table per scene, got "
                             f"{given.shape}")
        tables = np.stack([as_noise_table(t, shape) for t in given])
    elif seeds is not None:
        tables = np.stack([noise_table(su, x) for su, x in zip(setups, seeds)])
    else:
        raise ValueError("give seeds or noise tables")
    if draws is not None:
        draws = np.asarray(draws)
        n = first.n_sensors
        if (draws.ndim != 3 or draws.shape[0] != B or draws.shape[1] < first.steps
                or draws.shape[2] != n or not np.issubdtype(draws.dtype, np.integer)
                or not (np.sort(draws, axis=-1) == np.arange(n)).all()):
            raise ValueError(f"draws must hold a permutation of the {first.n_sensors} sensors "
                             f"per scene and step, shape ({B}, {first.steps}, "
                             f"{first.n_sensors}), got {draws.shape}")
    elif "random" in names and seeds is None:
        raise ValueError("the random assignment draws from the run's seed: give seeds or draws")
    row_seeds = list(seeds) * len(names) if seeds is not None else [0] * (B * len(names))
    res = _pass(setups, np.repeat(names, B), tables, row_seeds, draws=draws)
    out = {}
    for g, name in enumerate(names):
        sl = slice(g * B, (g + 1) * B)
        out[name] = TargetsBatch(setup=first, assignment=name, seed=None, noise=tables,
                                 seeds=seeds or (), scenes=setups,
                                 **{k: v[sl] for k, v in res.items()})
    return out


def step_times(setup: TargetsSetup, assignment: str, seed: int = 0) -> tuple:
    """The wall time of each step of one run of :func:`simulate_targets`: from the start of
    step ``k`` to the start of step ``k + 1``, that is every filter's predict and update and the
    assignment for the next step (steps ``1 .. steps - 1``; the last step makes no assignment).

    Returns
    -------
    times : ndarray, shape (steps - 1,)
        Seconds.
    run : TargetsResult
        The run (its estimates are what each step's assignment was made from).

    Examples
    --------
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET.first(5)
    >>> t, run = tracking.step_times(su, "unique-pairs")
    >>> t.shape, bool((t > 0).all()), run.steps
    ((4,), True, 5)
    """
    as_instance(setup, TargetsSetup, "setup")
    check_assignment(setup, assignment)
    seed = as_int(seed, "seed", 0)
    table = noise_table(setup, seed)
    clock: list = []
    res = _pass((setup,), [assignment], table[None], [seed], single=True, clock=clock)
    run = TargetsResult(setup=setup, assignment=assignment, seed=seed, noise=table,
                        **{k: np.array(v[0]) for k, v in res.items()})
    return np.diff(np.array(clock)), run
