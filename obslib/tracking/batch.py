"""Section V's tracking runs on the engine (:mod:`~obslib.tracking.engine`): one run
(:func:`simulate`), many runs of one strategy (:func:`simulate_batch`), several arms over common
noise (:func:`simulate_many`) and Monte Carlo (:func:`monte_carlo`).

One target per run, one pair of sensors per step chosen by a strategy or criterion
(:class:`~obslib.tracking.choosers.PairChooser`), half squared ranges, and the target on the
circle of Section V-A or the adversary of Section V-B. All runs of a pass (noise seeds,
strategies, setup variants) advance together; :func:`simulate` is the pass of one run.
filterpy's ``ExtendedKalmanFilter`` is the independent reference the tests hold the engine to,
step by step.

Order within step :math:`k`: (1) choose the pair from the current estimate and covariance and
log its bound; (2) log the error :math:`\\lVert \\hat x_k - o_k \\rVert` and
:math:`\\operatorname{tr} \\Sigma_k`, the values *before* this step's update (step 1 logs
0.7071 and 1.0 for the paper's circle); (3) predict, measure the true :math:`o_k` with the chosen
pair and update; (4) choose the next pair from the posterior and move the target to
:math:`o_{k+1}` (the ``"exact-icn"`` oracle's target moves first).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable

import numpy as np

from .._validate import (
    ArgumentTypeError,
    as_choice,
    as_instance,
    as_int,
    as_names,
    as_noise_table,
)
from . import kalman
from .choosers import NAMES, STRATEGIES, PairChooser, candidates, fixed_pair_bound, pair_draws
from .engine import Adversaries, FilterBank, run_steps, singular_update_message
from .model import circle_truth, pair_index
from .results import BatchResult, TrackingResult, derived_arrays
from .setup import TrackingSetup, noise_table, run_table, seeds_or_noise

__all__ = ["simulate", "simulate_many", "simulate_batch", "monte_carlo"]

#: Setup fields that may differ between the rows of one batched pass (see :func:`simulate_many`).
_ROW_FIELDS = ("metric", "anchor", "fixed_pair", "adversary", "controls")


def _measure(sx, sy, i0, i1, ox, oy, noise_k, cols):
    """Half squared ranges of the true positions from the chosen sensors plus the noise entries
    ``noise_k[cols + i]`` (run ``r``'s table row at offset ``cols[r]``)."""
    d0x, d0y, d1x, d1y = sx[i0] - ox, sy[i0] - oy, sx[i1] - ox, sy[i1] - oy
    z0 = 0.5 * (d0x * d0x + d0y * d0y) + noise_k.take(cols + i0)
    z1 = 0.5 * (d1x * d1x + d1y * d1y) + noise_k.take(cols + i1)
    return z0, z1


class _Circle:
    """The circling target of Section V-A: one path for every run."""

    def __init__(self, setup):
        self.path = circle_truth(setup)  # (steps + 1, 2)

    def position(self, k):
        return self.path[k]

    def control(self, k):
        return self.path[k + 1] - self.path[k]

    def move(self, k, choice, nxt):
        pass


def _run_rows(setup: TrackingSetup, cand, maha, nextpair, tables, controls=None,
              barred=None, kinds=None, draws=None, single=False) -> dict:
    """``R`` runs of one shared setup, each with its own pair candidates (``cand``, ``(R, P)``),
    metric (``maha``), adversary (``nextpair``), chooser (``kinds`` and ``draws`` of
    :class:`~obslib.tracking.choosers.PairChooser`) and noise table: run ``r`` uses
    ``tables[r % B]``. An adversary's controls are ``controls`` (default: the setup's) less each
    run's ``barred`` ones (see ``adversary.adversary_moves``). ``single``: one run, whose errors
    need not name it.

    With an ``"exact-icn"`` run in the pass, the target moves before the next choice (the
    oracle needs the control that brings it to its next position; no run of such a pass may
    have a ``"next-pair"`` adversary, which needs the choice first). The other runs of the pass
    are the same either way: their next choice depends only on the posterior, and their target
    (on the circle, or facing the current pair) not on that choice."""
    R_ = cand.shape[0]
    B, steps, n = tables.shape
    s = setup.sensor_array
    sx, sy = s[:, 0].copy(), s[:, 1].copy()
    ii, jj = pair_index(n)
    # the logs are kept step-major ((steps, R) rows written contiguously), transposed at the end
    noise = np.ascontiguousarray(tables.transpose(1, 0, 2)).reshape(steps, B * n)
    cols = (np.arange(R_) % B) * n
    filters = FilterBank(np.broadcast_to(setup.estimate0, (R_, 2)),
                         np.broadcast_to(setup.cov0, (R_, 2, 2)), setup.Q)
    pair_ps = s[np.stack([ii, jj], axis=1)]  # (P, 2, 2): the sensors of each pair
    if setup.motion == "circle":
        motion = _Circle(setup)
    else:
        motion = Adversaries(setup, R_, nextpair, controls, barred,
                             lambda choice: pair_ps[choice[0]])
    chooser = PairChooser(s, cand, maha, setup.u_max**2, kinds, setup.Q, setup.R, draws)
    oracle = kinds is not None and bool((np.asarray(kinds, object) == "exact-icn").any())
    if oracle and nextpair.any():
        raise ValueError("an exact-icn run cannot face a next-pair adversary: each needs the "
                         "other's next move first")
    best_log = np.empty((steps, R_), dtype=int)
    bound = np.empty((steps, R_))
    est = np.empty((steps, 2, R_))
    cov = np.empty((steps, 4, R_))
    zero = np.zeros((R_, 2))

    def choose(k, control):
        u = zero if control is None else np.broadcast_to(control, (R_, 2))
        return chooser(filters.xx, filters.xy, *filters.covariance(), u, k)

    def record(k, choice):
        best_log[k], bound[k] = choice
        est[k] = filters.xx, filters.xy
        cov[k] = filters.covariance()

    def update(k, choice, position):
        best = choice[0]
        i0, i1 = ii[best], jj[best]
        ox, oy = position
        z0, z1 = _measure(sx, sy, i0, i1, ox, oy, noise[k], cols)
        P = filters.predict()
        try:
            filters.update_pairs(P, sx[i0], sy[i0], sx[i1], sy[i1], z0, z1, setup.R)
        except kalman.SingularInnovation as e:
            r = int(np.flatnonzero(~e.ok)[0])
            x = np.array([filters.xx[r], filters.xy[r]])
            ps = np.array([[sx[i0[r]], sy[i0[r]]], [sx[i1[r]], sy[i1[r]]]])
            raise ValueError(singular_update_message(x, ps, k, None if single else r)) from None

    best, _ = run_steps(steps, update, choose, motion, record, move_first=oracle)
    if setup.motion == "circle":
        truth = motion.path[None]
    else:
        truth = np.ascontiguousarray(motion.truth.transpose(1, 0, 2))
    return _collect(chooser, best_log, bound, est, cov, best, truth)


def _collect(chooser, best_log, bound, est, cov, best, truth) -> dict:
    """The logs of :func:`_run_rows` as run-major arrays, the fixed pairs' bounds filled in."""
    ii, jj = chooser.ii, chooser.jj
    steps, R_ = best_log.shape
    pairs = np.stack([ii, jj], axis=1)[best_log.T]  # (R, steps, 2)
    est = np.ascontiguousarray(est.transpose(2, 0, 1))
    cov = np.ascontiguousarray(cov.transpose(2, 0, 1)).reshape(R_, steps, 2, 2)
    bound = np.ascontiguousarray(bound.T)
    if chooser.deferred.size:
        bound[chooser.deferred] = chooser.deferred_bounds(best_log.T[chooser.deferred], est, cov)
    next_pair = np.stack([ii[best], jj[best]], axis=1)
    d = derived_arrays(est, cov, truth)
    if truth.shape[0] == 1 < R_:  # one path for every run (the circle): read-only views
        for name in ("truth", "control", "truth_end"):
            d[name] = np.broadcast_to(d[name], (R_,) + d[name].shape[1:])
    return dict(pairs=pairs, bound=bound, estimate=est, cov=cov, next_pair=next_pair, **d)


# --------------------------------------------------------------------------------------------
# Arms: validation, grouping into passes, common noise
# --------------------------------------------------------------------------------------------


def _arms_iv(arms) -> dict:
    try:
        arms = dict(arms)
    except (TypeError, ValueError):
        raise ValueError("arms must be a mapping {name: (setup, strategy)}") from None
    if not arms:
        raise ValueError("no arms to run")
    for name, arm in arms.items():
        try:
            setup, strategy = arm
        except (TypeError, ValueError):
            raise ValueError(f"arm {name!r} must be a (setup, strategy) pair") from None
        if not isinstance(setup, TrackingSetup):
            raise ValueError(
                f"arm {name!r}: setup must be a TrackingSetup, got {type(setup).__name__}"
            )
        as_choice(strategy, NAMES, "strategy")
    return arms


def _kind(strategy: str) -> str:
    """The chooser kind of a strategy: ``"bound"`` for the paper's, else the criterion."""
    return "bound" if strategy in STRATEGIES else strategy


def _run_key(arm):
    """Arms with equal keys are the same runs: the run of a fixed pair or of a criterion does not
    depend on the metric, only its logged bound does."""
    setup, strategy = arm
    if _kind(strategy) != "bound" or strategy == "fixed-pair":
        return setup.replace(metric="mahalanobis"), strategy
    return arm


def _control_union(setups, B):
    """The union of the setups' control sets (one contiguous block per distinct set) and each
    run's barred controls, or ``(None, None)`` when all share one set."""
    sets, block = [], []
    for su in setups:
        c = su.control_array
        hit = [b for b, x in enumerate(sets) if np.array_equal(x, c)]
        if not hit:
            sets.append(c)
        block.append(hit[0] if hit else len(sets) - 1)
    if len(sets) == 1:
        return None, None
    controls = np.concatenate(sets)
    edges = np.cumsum([0] + [len(x) for x in sets])
    barred = np.full((len(setups) * B, len(controls)), np.inf)
    for g, b in enumerate(block):
        barred[g * B : (g + 1) * B, edges[b] : edges[b + 1]] = 0.0
    return controls, barred


def _with_metric(setup: TrackingSetup, r: BatchResult) -> BatchResult:
    """The runs ``r`` (of a fixed pair or a criterion) with their bound logged in ``setup``'s
    metric."""
    pairs = r.pairs.reshape(-1, 2)
    M = r.bound.size
    s = setup.sensor_array
    bound = fixed_pair_bound(
        s[:, 0].copy(), s[:, 1].copy(), pairs[:, 0], pairs[:, 1], setup.u_max**2,
        r.estimate.reshape(-1, 2), r.cov.reshape(-1, 2, 2),
        np.full(M, setup.metric == "mahalanobis"),
    ).reshape(r.bound.shape)
    return dataclasses.replace(r, setup=setup, bound=bound)


def simulate(setup: TrackingSetup, strategy: str, noise=None, seed: int = 0) -> TrackingResult:
    """One tracking run of Section V (Figs. 4-7): the engine's pass of one run.

    Parameters
    ----------
    setup : TrackingSetup
        E.g. :data:`~obslib.tracking.PAPER_CIRCLE` (Figs. 4-6) or
        :data:`~obslib.tracking.PAPER_ADVERSARIAL` (Fig. 7).
    strategy : str
        ``"best-pair"``, ``"best-partner"``, ``"fixed-pair"``: strategies (1), (2), (3) of
        Section V-A (:data:`~obslib.tracking.STRATEGIES`); or a criterion beyond the paper,
        ``"d-optimal"``, ``"a-optimal"``, ``"e-optimal"``, ``"exact-icn"``, ``"random"``
        (:data:`~obslib.tracking.CRITERIA`, see :mod:`~obslib.tracking.choosers`). The logged
        ``bound`` is always the paper's pair bound of the chosen pair.
    noise : array_like, shape (steps, N), optional
        Explicit measurement noise, entry ``[k-1, i]`` for sensor ``i`` at step ``k`` (exact
        replay). Default: :func:`~obslib.tracking.noise_table` of ``seed``.
    seed : int
        Seed of the noise table when ``noise`` is not given, and of the ``"random"`` chooser's
        draws (``choosers.pair_draws``, a separate stream) in any case.

    Returns
    -------
    TrackingResult
        Equal to run ``b`` of :func:`simulate_batch` with ``seeds[b] = seed`` (the same pass
        with one run).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> r.pairs[:2].tolist(), round(float(r.bound[0]), 4), r.error.shape
    ([[3, 5], [3, 5]], 0.8736, (20,))
    """
    as_instance(setup, TrackingSetup, "setup")
    as_choice(strategy, NAMES, "strategy")
    table, used_seed = run_table(setup, noise, seed, strategy == "random")
    cand = candidates(setup, strategy)[None]
    draws = pair_draws(seed, setup.steps, cand.shape[1])[None] if strategy == "random" else None
    nxt = np.array([setup.motion == "adversarial" and setup.adversary == "next-pair"])
    res = _run_rows(setup, cand, np.array([setup.metric == "mahalanobis"]), nxt, table[None],
                    kinds=np.array([_kind(strategy)], dtype=object), draws=draws, single=True)
    return TrackingResult(setup=setup, strategy=strategy, seed=used_seed, noise=table,
                          **{k: np.array(v[0]) for k, v in res.items()})


def simulate_many(arms, seeds=None, noise=None) -> dict:
    """Several (setup, strategy) arms over the same noise realisations, batched together.

    Every arm runs once per seed (or noise table), with common noise: run ``b`` of every arm
    uses ``noise_table(setup, seeds[b])``, so it equals ``simulate(setup, strategy,
    seed=seeds[b])`` (the tests check this to rounding). Arms whose setups differ only in
    ``metric``, ``anchor``, ``fixed_pair``, ``adversary`` and ``controls`` share one pass of the
    batch engine; a run does not depend on the other runs of its pass. Identical arms are run
    once and share their result; so are arms of a fixed pair or a criterion that differ only in
    the metric, whose runs are the same (only the logged bound is evaluated with each metric).

    Parameters
    ----------
    arms : mapping
        ``{name: (setup, strategy)}``, ``strategy`` any name of
        :data:`~obslib.tracking.STRATEGIES` or :data:`~obslib.tracking.CRITERIA` (``"random"``
        needs ``seeds``; in a pass with an ``"exact-icn"`` arm the target moves before the next
        choice, so such arms run in a pass of their own when others face a ``"next-pair"``
        adversary).
    seeds : iterable of int, optional
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.

    Returns
    -------
    dict
        ``{name: BatchResult}`` in the order of ``arms``.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=30)
    >>> eu = setup.replace(metric="euclidean")
    >>> arms = {"bound": (setup, "best-pair"), "eu": (eu, "best-pair"),
    ...         "d": (setup, "d-optimal")}
    >>> runs = tracking.simulate_many(arms, seeds=[0, 1, 2])
    >>> runs["eu"].pairs.shape, runs["eu"].seeds
    ((3, 30, 2), (0, 1, 2))
    """
    arms = _arms_iv(arms)
    seeds, given = seeds_or_noise(seeds, noise)
    first: dict = {}
    for name, arm in arms.items():
        first.setdefault(_run_key(arm), name)
    groups: dict = {}
    for name in first.values():
        setup = arms[name][0]
        key = tuple(getattr(setup, f.name) for f in dataclasses.fields(setup)
                    if f.name not in _ROW_FIELDS)
        groups.setdefault(key, []).append(name)
    passes = []  # exact-icn arms join the others' pass unless one of them needs the choice first
    for names in groups.values():
        icn = [n for n in names if arms[n][1] == "exact-icn"]
        if icn and any(arms[n][0].adversary == "next-pair" for n in names if n not in icn):
            passes += [[n for n in names if n not in icn], icn]
        else:
            passes.append(names)
    drawn: dict = {}
    out = {}
    for names in passes:
        base = arms[names[0]][0]
        if seeds:
            tkey = (base.steps, base.n_sensors, base.noise_std)
            if tkey not in drawn:
                drawn[tkey] = np.stack([noise_table(base, x) for x in seeds])
            tables = drawn[tkey]
        else:
            tables = np.stack([as_noise_table(t, (base.steps, base.n_sensors)) for t in given])
        B = tables.shape[0]
        cand = np.concatenate([np.tile(candidates(*arms[n]), (B, 1)) for n in names])
        maha = np.repeat([arms[n][0].metric == "mahalanobis" for n in names], B)
        nxt = np.repeat([arms[n][0].adversary == "next-pair" for n in names], B)
        controls = barred = None
        if base.motion == "adversarial":
            controls, barred = _control_union([arms[n][0] for n in names], B)
        kinds = np.repeat([_kind(arms[n][1]) for n in names], B).astype(object)
        draws = None
        if any(arms[n][1] == "random" for n in names):
            if not seeds:
                raise ValueError("the random strategy draws its pairs from the run's seed: "
                                 "give seeds, not noise tables")
            P = cand.shape[1]
            one = np.stack([pair_draws(x, base.steps, P) for x in seeds])
            draws = np.tile(one, (len(names), 1))
        res = _run_rows(base, cand, maha, nxt, tables, controls, barred, kinds, draws)
        for g, n in enumerate(names):
            sl = slice(g * B, (g + 1) * B)
            setup, strategy = arms[n]
            out[n] = BatchResult(
                setup=setup, strategy=strategy, seed=None, seeds=seeds, noise=tables,
                **{k: v[sl] for k, v in res.items()},
            )
    result = {}
    for n, arm in arms.items():
        ref = first[_run_key(arm)]
        result[n] = out[ref] if arm == arms[ref] else _with_metric(arm[0], out[ref])
    return result


def simulate_batch(setup: TrackingSetup, strategy: str, seeds=None, noise=None) -> BatchResult:
    """Many runs of one strategy at once: :func:`~obslib.tracking.simulate` vectorised over
    noise realisations.

    The same equations as filterpy's ``predict`` and ``update`` (Joseph form) in the same order,
    written as NumPy array operations over runs (:func:`simulate_many`), so a run equals
    ``simulate(setup, strategy, seed=s)`` to rounding (checked in the tests).

    Parameters
    ----------
    seeds : iterable of int, optional
        One run per seed with ``noise_table(setup, seed)``.
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> b = tracking.simulate_batch(setup, "best-pair", seeds=[0, 1])
    >>> b.n_runs, b.run(0).pairs[:2].tolist()
    (2, [[3, 5], [3, 5]])
    """
    as_choice(strategy, NAMES, "strategy")
    return simulate_many({strategy: (setup, strategy)}, seeds=seeds, noise=noise)[strategy]


def monte_carlo(
    setup: TrackingSetup,
    n_seeds: int = 100,
    strategies: Iterable[str] = STRATEGIES,
    first_seed: int = 0,
    batch: int = 1000,
) -> dict[str, BatchResult]:
    """The strategies over ``n_seeds`` noise realisations, seeds ``first_seed, first_seed + 1, ..``.

    Trial ``t`` uses ``noise_table(setup, first_seed + t)`` for every strategy (common random
    numbers), so trial ``t`` of a strategy equals ``simulate(setup, strategy,
    seed=first_seed + t)``. All strategies run together (:func:`simulate_many`), ``batch``
    seeds at a time. ``strategies`` may name any of :data:`~obslib.tracking.STRATEGIES` and
    :data:`~obslib.tracking.CRITERIA`, e.g. ``STRATEGIES + CRITERIA``.

    Returns
    -------
    dict
        ``{strategy: BatchResult}`` with arrays of leading size ``n_seeds``.

    Examples
    --------
    >>> from obslib import tracking
    >>> mc = tracking.monte_carlo(tracking.PAPER_CIRCLE.replace(steps=30), 4,
    ...                           ["best-pair", "d-optimal", "random"])
    >>> {name: r.pairs.shape for name, r in mc.items()}
    {'best-pair': (4, 30, 2), 'd-optimal': (4, 30, 2), 'random': (4, 30, 2)}
    >>> # common random numbers
    >>> bool((mc["random"].noise == mc["best-pair"].noise).all())
    True
    """
    n_seeds = as_int(n_seeds, "n_seeds", 1)
    batch = as_int(batch, "batch", 1)
    first_seed = as_int(first_seed, "first_seed", 0)
    if isinstance(strategies, str):
        raise ArgumentTypeError(f"strategies must be a list of names, got the string "
                                f"{strategies!r}; write [{strategies!r}]")
    strategies = list(as_names(strategies, "strategies", NAMES))
    if not strategies:
        return {}
    seeds = list(range(first_seed, first_seed + n_seeds))
    arms = {s: (setup, s) for s in strategies}
    parts = [simulate_many(arms, seeds=seeds[i : i + batch]) for i in range(0, len(seeds), batch)]
    if len(parts) == 1:
        return parts[0]
    return {
        s: BatchResult(
            setup=setup,
            strategy=s,
            seed=None,
            seeds=tuple(seeds),
            **{
                f.name: np.concatenate([getattr(p[s], f.name) for p in parts])
                for f in dataclasses.fields(TrackingResult)
                if f.name not in ("setup", "strategy", "seed")
            },
        )
        for s in strategies
    }
