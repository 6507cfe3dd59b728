"""Many targets in closed loop: the authors' later experiment reproduced and judged, and the
same comparison on larger networks.

Computed once here (each function caches its result on its arguments) and shared by the
chapter and the ledger:

* :func:`saved_comparison`: the saved run of each of the authors' two scripts
  (:mod:`obslib.later_experiment`) against ours over many noise seeds: per target, the mean
  error, the mean trace and the steps without a sensor, and where the saved value falls among
  our runs; and the trace after the first update, which does not depend on the noise and must
  equal the saved one;
* :func:`code_treatment`: what the code's evaluation of :math:`\\log\\det(O^T O)` does with the
  first, singular sensor of a team: the first step's teams and second-step traces in each
  arithmetic, and how often the team greedy leaves a target without a sensor;
* :func:`later_comparison`: every assignment of :data:`obslib.tracking.ASSIGNMENTS` on the
  later experiment over many noise seeds, per target and overall, each against the unique-pair
  greedy with chapter 10's paired tests (:func:`obslib.studies.criteria.paired_test`);
* :func:`network_comparison`: the same at ``N = 200`` sensors and ``L = 50`` targets on random
  scenes (:func:`obslib.tracking.network_scene`), one noise seed per scene.

The statistics of a run leave out step 1, whose logged values are the initial ones for every
assignment: a target's *mean error* and *mean trace* are over steps 2 to K; its *steps
without a sensor* count the steps 1 to K at which it had none; its track is *lost* when its
mean error exceeds :data:`obslib.tracking.LOSS_THRESHOLD` (chapter 10's threshold).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .. import tracking
from .._validate import as_int, as_mapping, as_names, as_nonnegative, as_str
from ..later_experiment import RUN_NAMES, saved_run
from .criteria import paired_test, significance

__all__ = [
    "NOTEBOOK",
    "REFERENCE",
    "NETWORK_ASSIGNMENTS",
    "later_runs",
    "run_statistics",
    "saved_comparison",
    "code_treatment",
    "comparison_rows",
    "later_comparison",
    "network_runs",
    "network_comparison",
]

NOTEBOOK = "12_many_targets"

#: The assignment every other is compared with: the unique-pair greedy of the authors' script.
REFERENCE = "unique-pairs"

#: The assignments compared at ``N = 200``, ``L = 50``: all but the exact optimum (beyond
#: enumeration, and a branch and bound per step and run), and of the code's log det only its
#: floating-point greedy with the sensors it picked (the saved script's reading of the teams
#: has the same team sizes, and exact arithmetic gives one target every sensor at any size).
NETWORK_ASSIGNMENTS = ("unique-pairs", "random", "logdet-teams", "logdet-teams-prior",
                       "d-optimal-teams", "a-optimal-teams", "e-optimal-teams")


def _assignments_iv(assignments) -> tuple:
    names = as_names(assignments, "assignments", tracking.ASSIGNMENTS)
    if not names:
        raise ValueError("assignments is empty")
    return tuple(dict.fromkeys(names))


def _seeds_iv(n_seeds, seed) -> tuple:
    n_seeds = as_int(n_seeds, "n_seeds", 2)
    return n_seeds, as_int(seed, "seed", 0)


@lru_cache(maxsize=32)
def _later_run(n_seeds: int, seed: int, assignment: str):
    # one assignment at a time, so that every caller shares each assignment's runs (the runs
    # of an assignment do not depend on the others: the noise is the seeds')
    return tracking.simulate_targets_batch(tracking.LATER_MULTI_TARGET, [assignment],
                                           seeds=range(seed, seed + n_seeds))[assignment]


def _later_runs(n_seeds: int, seed: int, assignments: tuple) -> dict:
    return {name: _later_run(n_seeds, seed, name) for name in assignments}


def later_runs(n_seeds: int = 200, seed: int = 0, assignments=tracking.ASSIGNMENTS) -> dict:
    """The later experiment (:data:`~obslib.tracking.LATER_MULTI_TARGET`) with every
    assignment over the noise seeds ``seed .. seed + n_seeds - 1``, common to all:
    ``{assignment: TargetsBatch}`` (each assignment's runs cached).

    Examples
    --------
    >>> runs = later_runs(3, assignments=("unique-pairs", "random"))
    >>> list(runs), runs["random"].error.shape
    (['unique-pairs', 'random'], (3, 100, 3))
    >>> later_runs(3)["random"] is runs["random"]  # one computation, shared
    True
    """
    n_seeds, seed = _seeds_iv(n_seeds, seed)
    return _later_runs(n_seeds, seed, _assignments_iv(assignments))


def run_statistics(batch, loss_threshold: float = tracking.LOSS_THRESHOLD) -> dict:
    """Per run and target, ``(B, L)``: ``mean_error`` and ``mean_trace`` over the steps after
    the first, ``unobserved`` (steps without a sensor) and ``lost`` (mean error above
    ``loss_threshold``).

    Examples
    --------
    >>> runs = later_runs(3, assignments=("logdet-teams-exact",))
    >>> s = run_statistics(runs["logdet-teams-exact"])
    >>> s["unobserved"].tolist()  # the first target takes every sensor
    [[0, 100, 100], [0, 100, 100], [0, 100, 100]]
    >>> s["lost"].tolist()[0]
    [False, True, True]
    """
    if not isinstance(batch, tracking.TargetsBatch):
        raise ValueError(f"batch must be a TargetsBatch, got {type(batch).__name__}")
    loss_threshold = as_nonnegative(loss_threshold, "loss_threshold")
    err = batch.error[:, 1:].mean(axis=1)
    return {"mean_error": err, "mean_trace": batch.trace_cov[:, 1:].mean(axis=1),
            "unobserved": batch.unobserved.sum(axis=1), "lost": err > loss_threshold}


# --------------------------------------------------------------------------------------------
# The saved runs against ours
# --------------------------------------------------------------------------------------------


@lru_cache(maxsize=4)
def _saved_comparison(n_seeds: int, seed: int) -> dict:
    runs = _later_runs(n_seeds, seed, RUN_NAMES)
    out = {}
    for name in RUN_NAMES:
        saved = saved_run(name)
        b = runs[name]
        ours = {"mean_error": b.error[:, 1:].mean(axis=1),
                "mean_trace": b.trace_cov[:, 1:].mean(axis=1),
                "unobserved": b.unobserved[:, :-1].sum(axis=1)}  # steps 1..99, as read
        theirs = saved.summary()
        rows = []
        for key in ("mean_error", "mean_trace", "unobserved"):
            for l in range(3):
                x = ours[key][:, l]
                v = float(theirs[key][l])
                rows.append({"statistic": key, "target": l + 1, "saved": v,
                             "ours_mean": float(x.mean()), "ours_median": float(np.median(x)),
                             "ours_p05": float(np.percentile(x, 5)),
                             "ours_p95": float(np.percentile(x, 95)),
                             "below": float((x < v).mean()), "above": float((x > v).mean())})
        total = ours["unobserved"].sum(axis=1)
        step2 = b.trace_cov[:, 1]
        out[name] = {
            "rows": rows,
            "step2_saved": saved.trace_cov[1].tolist(),
            "step2_ours": step2[0].tolist(),
            "step2_same_every_seed": bool((step2 == step2[0]).all()),
            "step2_max_rel_diff": float(np.abs(step2[0] / saved.trace_cov[1] - 1).max()),
            "unobserved_total_saved": int(theirs["unobserved"].sum()),
            "unobserved_total_at_least_saved": float((total >= theirs["unobserved"].sum()).mean()),
            "n_runs": int(b.n_runs),
        }
    return out


def saved_comparison(n_seeds: int = 200, seed: int = 0) -> dict:
    """The saved run of each script against ours over ``n_seeds`` noise seeds (cached).

    Returns ``{run name: {...}}`` for the names of :data:`obslib.later_experiment.RUN_NAMES`
    (``"unique-pairs"``, ``"logdet-teams-as-run"``): ``rows``, one per statistic
    (``mean_error``, ``mean_trace``, ``unobserved``: steps ``1 .. 99`` without a sensor, as
    the saved traces show them) and target, with the saved value, our runs' mean, median, 5th
    and 95th percentiles and the fractions of our runs below and above the saved value;
    ``step2_saved`` and ``step2_ours``, the trace after the first update (the same for every
    seed, ``step2_same_every_seed``), and their largest relative difference; the saved total of
    steps without a sensor and the fraction of our runs with at least as many.

    Examples
    --------
    >>> c = saved_comparison(4)
    >>> c["unique-pairs"]["step2_max_rel_diff"] < 5e-6
    True
    >>> row = c["logdet-teams-as-run"]["rows"][-3]
    >>> row["statistic"], row["target"], row["saved"]
    ('unobserved', 1, 33.0)
    """
    return _saved_comparison(*_seeds_iv(n_seeds, seed))


# --------------------------------------------------------------------------------------------
# The code's treatment of the first, singular sensor of a team
# --------------------------------------------------------------------------------------------


def _first_update_traces(setup, labels) -> list:
    """The trace of each target's covariance after the first update with the sensors of
    ``labels`` (target per sensor), from the initial state (independent of the noise)."""
    S = setup.sensor_array
    out = []
    for l, x0 in enumerate(setup.estimate0):
        P = tracking.kalman.predict(setup.cov0, setup.Q)
        team = np.flatnonzero(labels == l)
        if team.size:
            z = tracking.euclidean_range(x0, S[team])  # any z: the covariance does not depend on it
            _, P = tracking.kalman.update(x0, P, S[team], z, setup.R, measurement="range")
        out.append(float(np.trace(P)))
    return out


@lru_cache(maxsize=4)
def _code_treatment(n_seeds: int, seed: int) -> dict:
    su = tracking.LATER_MULTI_TARGET
    first = {}
    for arithmetic in tracking.code_logdet.ARITHMETICS:
        picked, rounds = tracking.code_logdet.logdet_rounds(su.sensors, su.estimate0, arithmetic)
        first[arithmetic] = {
            "picked": [np.flatnonzero(picked == l).tolist() for l in range(3)],
            "rounds": [np.flatnonzero(rounds == l).tolist() for l in range(3)],
            "trace_picked": _first_update_traces(su, picked),
            "trace_rounds": _first_update_traces(su, rounds),
        }
    names = ("logdet-teams", "logdet-teams-as-run", "logdet-teams-exact", "logdet-teams-prior")
    runs = _later_runs(n_seeds, seed, names)
    sizes = {}
    for name in names:
        ts = runs[name].team_sizes  # (B, K, L)
        sizes[name] = {
            "share_none": float((ts == 0).mean()),
            "share_one": float((ts == 1).mean()),
            "mean_size": float(ts.mean()),
            "unobserved_per_target": (ts == 0).sum(axis=1).mean(axis=0).tolist(),
            "longest_without": float(_longest_run(ts == 0).mean()),
        }
    return {"saved_step2": saved_run("logdet-teams-as-run").trace_cov[1].tolist(),
            "first_step": first, "team_sizes": sizes, "n_runs": n_seeds}


def _longest_run(mask) -> np.ndarray:
    """The longest stretch of consecutive steps where ``mask`` ``(B, K, L)`` holds, per run and
    target, ``(B, L)``."""
    B, K, L = mask.shape
    best = np.zeros((B, L), dtype=int)
    cur = np.zeros((B, L), dtype=int)
    for k in range(K):
        cur = np.where(mask[:, k], cur + 1, 0)
        best = np.maximum(best, cur)
    return best


def code_treatment(n_seeds: int = 200, seed: int = 0) -> dict:
    """What the code's evaluation of :math:`\\log\\det(O^T O)` does (cached).

    Returns ``saved_step2`` (the saved team run's trace after the first update),
    ``first_step`` (per arithmetic of :data:`obslib.tracking.code_logdet.ARITHMETICS`: the
    teams picked at the later experiment's initial estimates, the teams by rounds as the script
    reads them, and the trace after the first update with each) and ``team_sizes`` (per log-det
    assignment over the runs: the share of (run, step, target) with no sensor and with one, the
    mean team size, the steps without a sensor per target, and the mean longest stretch of
    steps a target goes without one).

    Examples
    --------
    >>> c = code_treatment(3)
    >>> c["first_step"]["code"]["rounds"]
    [[0, 2], [1, 3, 6], [4, 5, 7]]
    >>> [round(t, 7) for t in c["first_step"]["code"]["trace_rounds"]]
    [0.4431206, 0.0622691, 0.0651809]
    >>> c["team_sizes"]["logdet-teams-exact"]["share_none"] == 2 / 3
    True
    """
    return _code_treatment(*_seeds_iv(n_seeds, seed))


# --------------------------------------------------------------------------------------------
# Every assignment against the unique-pair greedy
# --------------------------------------------------------------------------------------------


_STAT_KEYS = ("mean_error", "mean_trace", "unobserved", "lost")


def _stats_iv(stats, reference: str) -> dict:
    """``{assignment: run_statistics(...)}`` holding ``reference``, every array ``(B, L)`` of
    one shape, at least two runs."""
    stats = as_mapping(stats, "stats")
    if reference not in stats:
        raise ValueError(f"stats must hold the reference {reference!r}, got {list(stats)}")
    shape = None
    out = {}
    for name, st in stats.items():
        st = as_mapping(st, "stats")
        if set(st) != set(_STAT_KEYS):
            raise ValueError(f"stats[{name!r}] must be run_statistics' {_STAT_KEYS}")
        arrays = {k: np.asarray(st[k]) for k in _STAT_KEYS}
        for k, a in arrays.items():
            if a.dtype.kind not in "biuf" or a.ndim != 2 or a.shape[0] < 2 or (
                    shape is not None and a.shape != shape) or not np.isfinite(a).all():
                raise ValueError(f"stats[{name!r}][{k!r}] must be finite (runs, targets), at "
                                 f"least 2 runs, one shape for all, got {a.shape}")
            shape = a.shape
        out[name] = arrays
    return out


def comparison_rows(stats: dict, reference: str = REFERENCE) -> list:
    """One row per assignment and target (``target`` 1..L) and overall (``target`` ``"all"``)
    from per-run statistics ``{assignment: run_statistics(...)}`` (runs paired by index).

    Keys: ``assignment``, ``target``, ``n`` (runs), ``mean_error`` / ``sd_error`` and
    ``mean_trace`` / ``sd_trace`` (over runs of the per-run means; overall, of the means over
    targets), ``unobserved`` (mean steps without a sensor per run; overall, summed over
    targets), ``lost`` (tracks lost over all runs), and the paired tests against
    ``reference`` of the per-run mean error (prefix ``vs_``) and mean trace (prefix
    ``vs_trace_``) with :func:`~obslib.studies.criteria.significance`'s verdicts ``verdict``
    and ``verdict_trace`` (lower is better; empty for the reference).

    Examples
    --------
    >>> runs = later_runs(4, assignments=("unique-pairs", "random"))
    >>> stats = {k: run_statistics(v) for k, v in runs.items()}
    >>> rows = comparison_rows(stats)
    >>> [r["target"] for r in rows if r["assignment"] == "random"]
    [1, 2, 3, 'all']
    >>> rows[-1]["vs_n"], rows[-1]["verdict"] in ("better", "worse", "same")
    (4, True)
    """
    stats = _stats_iv(stats, as_str(reference, "reference"))
    ref = stats[reference]
    rows = []
    for name, s in stats.items():
        L = s["mean_error"].shape[1]
        for target in [*range(1, L + 1), "all"]:
            if target == "all":
                pick = lambda a: a.mean(axis=1)  # noqa: E731
                unobs = s["unobserved"].sum(axis=1)
            else:
                pick = lambda a, t=target: a[:, t - 1]  # noqa: E731
                unobs = s["unobserved"][:, target - 1]
            err, trc = pick(s["mean_error"]), pick(s["mean_trace"])
            lost = s["lost"] if target == "all" else s["lost"][:, target - 1]
            row = {"assignment": name, "target": target, "n": int(err.size),
                   "mean_error": float(err.mean()), "sd_error": float(err.std(ddof=1)),
                   "mean_trace": float(trc.mean()), "sd_trace": float(trc.std(ddof=1)),
                   "unobserved": float(unobs.mean()), "lost": int(np.sum(lost))}
            if name != reference:
                row.update({f"vs_{k}": v for k, v in
                            paired_test(pick(ref["mean_error"]), err).items()})
                row.update({f"vs_trace_{k}": v for k, v in
                            paired_test(pick(ref["mean_trace"]), trc).items()})
                row["verdict"] = significance(row)
                row["verdict_trace"] = significance(
                    {"vs_p_wilcoxon": row["vs_trace_p_wilcoxon"],
                     "vs_median_diff": row["vs_trace_median_diff"]})
            rows.append(row)
    return rows


@lru_cache(maxsize=4)
def _later_comparison(n_seeds: int, seed: int, assignments: tuple) -> list:
    runs = _later_runs(n_seeds, seed, assignments)
    return comparison_rows({k: run_statistics(v) for k, v in runs.items()})


def later_comparison(n_seeds: int = 200, seed: int = 0, assignments=tracking.ASSIGNMENTS) -> list:
    """Every assignment on the later experiment against the unique-pair greedy, per target and
    overall (:func:`comparison_rows` of :func:`later_runs`; cached).

    Examples
    --------
    >>> names = ("unique-pairs", "logdet-teams-exact")
    >>> rows = later_comparison(4, assignments=names)
    >>> exact = [r for r in rows if r["assignment"] == "logdet-teams-exact"]
    >>> [r["unobserved"] for r in exact]
    [0.0, 100.0, 100.0, 200.0]
    """
    n_seeds, seed = _seeds_iv(n_seeds, seed)
    assignments = _assignments_iv(assignments)
    if REFERENCE not in assignments:
        raise ValueError(f"assignments must include the reference {REFERENCE!r}")
    return _later_comparison(n_seeds, seed, assignments)


# --------------------------------------------------------------------------------------------
# Larger networks
# --------------------------------------------------------------------------------------------


@lru_cache(maxsize=4)
def _network_runs(n_sensors, n_targets, n_scenes, steps, seed, assignments) -> dict:
    seeds = range(seed, seed + n_scenes)
    scenes = [tracking.network_scene(n_sensors, n_targets, steps=steps, seed=s) for s in seeds]
    return tracking.simulate_targets_scenes(scenes, list(assignments), seeds=seeds)


def network_runs(n_sensors: int = 200, n_targets: int = 50, n_scenes: int = 10,
                 steps: int = 100, seed: int = 0, assignments=NETWORK_ASSIGNMENTS) -> dict:
    """Every assignment on ``n_scenes`` random scenes (:func:`obslib.tracking.network_scene`
    of seeds ``seed .. seed + n_scenes - 1``), scene ``s`` with the noise of seed ``s``:
    ``{assignment: TargetsBatch}``, one run per scene (cached).

    Examples
    --------
    >>> runs = network_runs(20, 5, n_scenes=2, steps=10,
    ...                     assignments=("unique-pairs",))
    >>> runs["unique-pairs"].error.shape
    (2, 10, 5)
    """
    n_sensors = as_int(n_sensors, "n_sensors", 2)
    n_targets = as_int(n_targets, "n_targets", 1)
    n_scenes = as_int(n_scenes, "n_scenes", 1)
    steps = as_int(steps, "steps", 2)
    seed = as_int(seed, "seed", 0)
    assignments = _assignments_iv(assignments)
    pairs = [a for a in assignments if a in tracking.PAIR_ASSIGNMENTS]
    if pairs and n_sensors < 2 * n_targets:
        raise ValueError(f"assignments {pairs} need two sensors per target: n_sensors >= "
                         f"{2 * n_targets}")
    if "optimal-pairs" in assignments and (
            tracking.assigners.assignment_count(n_sensors, n_targets)
            > tracking.assigners.MAX_ENUMERATED):
        raise ValueError(f"'optimal-pairs' at N = {n_sensors}, L = {n_targets} would solve a "
                         "branch and bound per step and run: leave it out of assignments")
    return _network_runs(n_sensors, n_targets, n_scenes, steps, seed, assignments)


@lru_cache(maxsize=4)
def _network_comparison(n_sensors, n_targets, n_scenes, steps, seed, assignments) -> list:
    runs = _network_runs(n_sensors, n_targets, n_scenes, steps, seed, assignments)
    return comparison_rows({k: run_statistics(v) for k, v in runs.items()})


def network_comparison(n_sensors: int = 200, n_targets: int = 50, n_scenes: int = 10,
                       steps: int = 100, seed: int = 0, assignments=NETWORK_ASSIGNMENTS) -> list:
    """The comparison of :func:`later_comparison` on larger networks (:func:`network_runs`;
    runs paired by scene; :func:`comparison_rows`, cached).

    Examples
    --------
    >>> rows = network_comparison(20, 5, n_scenes=2, steps=10,
    ...                           assignments=("unique-pairs", "d-optimal-teams"))
    >>> last = rows[-1]
    >>> last["assignment"], last["target"], last["n"]
    ('d-optimal-teams', 'all', 2)
    """
    network_runs(n_sensors, n_targets, n_scenes, steps, seed, assignments)  # checks
    assignments = _assignments_iv(assignments)
    if REFERENCE not in assignments:
        raise ValueError(f"assignments must include the reference {REFERENCE!r}")
    return _network_comparison(int(n_sensors), int(n_targets), int(n_scenes), int(steps),
                               int(seed), assignments)
