"""The batch engine: many tracking runs at once (noise seeds, strategies, setup variants), with
the equations of :func:`~obslib.tracking.simulate` written as NumPy operations over runs.

Per step, in the order of :func:`~obslib.tracking.simulate`: choose and log, predict, measure
the true position with the chosen pair, update (the batched EKF of :mod:`~obslib.tracking.kalman`,
filterpy's equations for many filters at once), choose the next pair, move the target.
A run does not depend on the other runs of its pass; the tests hold every run to the filterpy
engine's run of the same seed.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable

import numpy as np

from .._validate import (
    ArgumentTypeError,
    as_choice,
    as_float_array,
    as_int,
    as_names,
    as_noise_table,
)
from . import kalman
from .adversary import adversary_moves, control_basis
from .choosers import NAMES, PairChooser, candidates, fixed_pair_bound, pair_draws
from .ekf import singular_update_message
from .model import circle_truth, pair_index
from .results import BatchResult, TrackingResult, derived_arrays
from .setup import TrackingSetup, noise_table

__all__ = ["simulate_many", "simulate_batch", "monte_carlo"]

#: Setup fields that may differ between the rows of one batched pass (see :func:`simulate_many`).
_ROW_FIELDS = ("metric", "anchor", "fixed_pair", "adversary", "controls")


class _Filters:
    """The states of ``R`` extended Kalman filters (estimate ``xx, xy``, covariance entries
    ``p00, p01, p10, p11``) and their step: ``kalman.predict``, then
    ``kalman.update``."""

    def __init__(self, setup: TrackingSetup, R_: int):
        self.xx = np.full(R_, float(setup.estimate0[0]))
        self.xy = np.full(R_, float(setup.estimate0[1]))
        (c00, c01), (c10, c11) = setup.cov0
        self.p00, self.p01, self.p10, self.p11 = (np.full(R_, float(c)) for c in
                                                  (c00, c01, c10, c11))
        self.Q, self.R = setup.Q, setup.R

    def covariance(self):
        return self.p00, self.p01, self.p10, self.p11

    def step(self, s0x, s0y, s1x, s1y, z0, z1, k: int) -> None:
        """Predict, then update with the measurements ``z0, z1`` of the sensors
        ``(s0x, s0y)``, ``(s1x, s1y)`` (one per run) at step ``k`` (0-based)."""
        P = kalman.predict(self.covariance(), self.Q)
        try:
            (self.xx, self.xy), P = kalman.update((self.xx, self.xy), P, (s0x, s0y), (s1x, s1y),
                                                  (z0, z1), self.R)
        except kalman.SingularInnovation as e:
            self._singular(e.ok, k, s0x, s0y, s1x, s1y)
        self.p00, self.p01, self.p10, self.p11 = P

    def _singular(self, ok, k, s0x, s0y, s1x, s1y):
        r = int(np.flatnonzero(~ok)[0])
        pick = lambda a: a[r] if np.ndim(a) else a  # noqa: E731
        x = np.array([self.xx[r], self.xy[r]])
        ps = np.array([[pick(s0x), pick(s0y)], [pick(s1x), pick(s1y)]])
        raise ValueError(singular_update_message(x, ps, k, run=r)) from None


def _measure(sx, sy, i0, i1, ox, oy, noise_k, cols):
    """Half squared ranges of the true positions from the chosen sensors plus the noise entries
    ``noise_k[cols + i]`` (run ``r``'s table row at offset ``cols[r]``)."""
    d0x, d0y, d1x, d1y = sx[i0] - ox, sy[i0] - oy, sx[i1] - ox, sy[i1] - oy
    z0 = 0.5 * (d0x * d0x + d0y * d0y) + noise_k.take(cols + i0)
    z1 = 0.5 * (d1x * d1x + d1y * d1y) + noise_k.take(cols + i1)
    return z0, z1


class _Adversaries:
    """The adversarial targets of ``R`` runs: positions over time and their moves.

    Runs with different control sets (``barred``: each run's own set is a contiguous block of
    ``controls``) are screened block by block, each against its own controls only: the pick
    within a block is the one ``adversary.adversary_moves`` makes with the
    other blocks barred, without evaluating them (notebook 06's stronger adversaries: 20 runs
    with 9 controls next to 20 with 1801; 0.3 s against 1.7 s for their 315 moves)."""

    def __init__(self, setup, R_, nextpair, controls, barred):
        self.truth = np.empty((setup.steps + 1, R_, 2))
        self.truth[0] = setup.start
        self.controls = setup.control_array if controls is None else controls
        self.nextpair = nextpair
        self.anynext = bool(nextpair.any())
        if barred is None:
            self.blocks = [(None, 0, self.controls, control_basis(self.controls))]
        else:
            allowed = np.asarray(barred) == 0
            lo = allowed.argmax(axis=1)
            hi = allowed.shape[1] - allowed[:, ::-1].argmax(axis=1)
            if not (allowed.sum(axis=1) == hi - lo).all() or not allowed.any(axis=1).all():
                raise ValueError("each run's controls must be one contiguous block")
            self.blocks = []
            for a, b in sorted(set(zip(lo.tolist(), hi.tolist()))):
                c = self.controls[a:b]
                self.blocks.append((np.flatnonzero((lo == a) & (hi == b)), a, c,
                                    control_basis(c)))

    def move(self, k, pair_ps, next_ps):
        """Move every target after step ``k`` against its pair's sensors ``pair_ps``
        ``(R, 2, 2)`` (or those of the sensors' next pair, ``next_ps``)."""
        eval_ps = pair_ps
        if self.anynext:
            eval_ps = np.where(self.nextpair[:, None, None], next_ps, eval_ps)
        o = self.truth[k]
        if self.blocks[0][0] is None:
            _, _, c, basis = self.blocks[0]
            pick = adversary_moves(eval_ps, o, c, basis)
        else:
            pick = np.empty(o.shape[0], dtype=int)
            for rows, a, c, basis in self.blocks:
                pick[rows] = a + adversary_moves(eval_ps[rows], o[rows], c, basis)
        self.truth[k + 1] = o + self.controls[pick]


def _run_rows(setup: TrackingSetup, cand, maha, nextpair, tables, controls=None,
              barred=None, kinds=None, draws=None) -> dict:
    """``R`` runs of one shared setup, each with its own pair candidates (``cand``, ``(R, P)``),
    metric (``maha``), adversary (``nextpair``), chooser (``kinds`` and ``draws`` of
    :class:`~obslib.tracking.choosers.PairChooser`) and noise table: run ``r`` uses
    ``tables[r % B]``. An adversary's controls are ``controls`` (default: the setup's) less each
    run's ``barred`` ones (see ``adversary.adversary_moves``).

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
    filters = _Filters(setup, R_)
    circle = setup.motion == "circle"
    if circle:
        path = circle_truth(setup)  # (steps + 1, 2), the same for every run
    else:
        adv = _Adversaries(setup, R_, nextpair, controls, barred)

    best_log = np.empty((steps, R_), dtype=int)
    bound = np.empty((steps, R_))
    est = np.empty((steps, 2, R_))
    cov = np.empty((steps, 4, R_))
    chooser = PairChooser(s, cand, maha, setup.u_max**2, kinds, setup.Q, setup.R, draws)
    oracle = kinds is not None and bool((np.asarray(kinds, object) == "exact-icn").any())
    if oracle and nextpair.any():
        raise ValueError("an exact-icn run cannot face a next-pair adversary: each needs the "
                         "other's next move first")
    zero = np.zeros((R_, 2))
    pair_ps = s[np.stack([ii, jj], axis=1)]  # (P, 2, 2): the sensors of each pair
    best, b = chooser(filters.xx, filters.xy, *filters.covariance(), zero, 0)
    for k in range(steps):
        best_log[k], bound[k] = best, b
        est[k] = filters.xx, filters.xy
        cov[k] = filters.covariance()
        i0, i1 = ii[best], jj[best]
        ox, oy = path[k] if circle else (adv.truth[k, :, 0], adv.truth[k, :, 1])
        z0, z1 = _measure(sx, sy, i0, i1, ox, oy, noise[k], cols)
        filters.step(sx[i0], sy[i0], sx[i1], sy[i1], z0, z1, k)
        cur = best
        if oracle:  # move first: the oracle knows the control that brings the target to o_{k+1}
            if not circle:
                adv.move(k, pair_ps[cur], None)
            control = (path[k + 1] - path[k]) if circle else adv.truth[k + 1] - adv.truth[k]
            best, b = chooser(filters.xx, filters.xy, *filters.covariance(),
                              np.broadcast_to(control, (R_, 2)), k + 1)
            continue
        # the next choice depends only on the posterior (a "next-pair" adversary may know it)
        best, b = chooser(filters.xx, filters.xy, *filters.covariance(), zero, k + 1)
        if not circle:
            adv.move(k, pair_ps[cur], pair_ps[best] if adv.anynext else None)
    truth = path[None] if circle else np.ascontiguousarray(adv.truth.transpose(1, 0, 2))
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


def _seeds_iv(seeds, noise):
    if (seeds is None) == (noise is None):
        raise ValueError("give either seeds or noise tables")
    if noise is not None:
        given = as_float_array(noise, "noise")
        if given.ndim != 3:
            raise ValueError(f"noise must have shape (B, steps, N), got {given.shape}")
        return (), given
    if isinstance(seeds, (str, bytes)) or not isinstance(seeds, Iterable):
        raise ArgumentTypeError(
            f"seeds must be an iterable of non-negative integers, got {seeds!r}")
    seeds = tuple(as_int(x, "each seed", 0) for x in seeds)
    if not seeds:
        raise ValueError("seeds is empty")
    return seeds, None


def _kind(strategy: str) -> str:
    """The chooser kind of a strategy: ``"bound"`` for the paper's, else the criterion."""
    return "bound" if strategy in ("best-pair", "best-partner", "fixed-pair") else strategy


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
    seeds, given = _seeds_iv(seeds, noise)
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
    strategies: Iterable[str] = ("best-pair", "best-partner", "fixed-pair"),
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
