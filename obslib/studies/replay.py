"""The published tracking runs of Figs. 4-7 replayed with their own measurement noise.

The saved runs (:mod:`obslib.published_runs`) let us recover the noise each measurement carried;
fed to :func:`obslib.tracking.simulate` with the experiments' parameters
(:data:`obslib.tracking.PAPER_CIRCLE`, :data:`obslib.tracking.PAPER_ADVERSARIAL`), it should
reproduce every logged number of a run. :func:`compare_replay` measures how closely, and checks
that the table's unknown entries (NaN, sensors no run measured at that step) were never used:
the replay is run with two different fills of those entries and must give identical results,
and every entry the replay's pairs read must be known.

:func:`seed_typicality` places the published adversarial run among runs with random noise.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache, lru_cache

import numpy as np

from .. import tracking
from ..published_runs import RUN_NAMES, noise_sources, published_noise, published_run
from .published import FIGURE_TOLERANCE

__all__ = [
    "REPLAY_FILLS",
    "LOG_TOLERANCE",
    "ReplayComparison",
    "replay_setup",
    "replay",
    "compare_replay",
    "independent_checks",
    "seed_typicality",
]

#: Two fills of the unknown noise entries; a replay that never reads them gives the same run.
REPLAY_FILLS = (0.0, 10.0)

#: The log is printed to 12 significant digits and its numbers are at most about 10: a replayed
#: number within this of the logged one is the same number.
LOG_TOLERANCE = 1e-9


def _run_name_iv(name) -> str:
    if not isinstance(name, str) or name not in RUN_NAMES:
        raise ValueError(f"unknown published run {name!r}; accepted names: {', '.join(RUN_NAMES)}")
    return name


def replay_setup(name: str) -> tracking.TrackingSetup:
    """The experiments' setup of a published run (Sec. V-A: the circle; Sec. V-B: the adversary).

    Examples
    --------
    >>> from obslib.tracking import PAPER_ADVERSARIAL
    >>> from obslib.studies.replay import replay_setup
    >>> replay_setup("adversarial") is PAPER_ADVERSARIAL
    True
    >>> replay_setup("spiral")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: unknown published run 'spiral'; accepted names: ...
    """
    name = _run_name_iv(name)
    return tracking.PAPER_ADVERSARIAL if name == "adversarial" else tracking.PAPER_CIRCLE


def _strategy(name: str) -> str:
    return "best-pair" if name == "adversarial" else name


def _table(steps: int, fill: float) -> np.ndarray:
    """The published noise, unknown entries set to ``fill``, cut or padded to ``steps`` rows."""
    t = np.nan_to_num(published_noise(), nan=fill)
    if steps > t.shape[0]:
        t = np.vstack([t, np.full((steps - t.shape[0], t.shape[1]), fill)])
    return t[:steps]


def _replayable_steps(name: str) -> int:
    """Steps whose logged values the table determines.

    Values logged at step ``k`` come before that step's update, so they need the noise of steps
    ``1..k-1`` on the run's pairs. Strategy (3) always measures s1 and s2; the table lacks s1 at
    step 1, so only step 1 of that run can be replayed. The other runs: all 315 steps.
    """
    if name != "fixed-pair":
        return published_run(name).steps
    known = np.isfinite(published_noise()[:, list(tracking.PAPER_CIRCLE.fixed_pair)]).all(axis=1)
    missing = np.flatnonzero(~known)
    return int(missing[0]) + 1 if missing.size else known.size


#: Runs of one setup that share a batched pass: the circle's strategies (1) and (2).
_SAME_PASS = {"best-pair": ("best-pair", "best-partner"),
              "best-partner": ("best-pair", "best-partner")}


@lru_cache(maxsize=16)
def _replay_pass(names: tuple, fills: tuple, steps: int) -> dict:
    # The batch engine (the filter's equations as array operations, equal to the filterpy
    # engine of tracking.simulate to rounding), without importing filterpy and SciPy, which
    # cost notebooks 05 and 06 about 0.7 s each. The runs of the fills (and of the circle's
    # two strategies) share one batched pass, a run not depending on the others of its pass:
    # compare_replay of three runs 0.5 s -> 0.15 s.
    setup = replay_setup(names[0]).replace(steps=steps)
    tables = np.stack([_table(steps, f) for f in fills])
    runs = tracking.simulate_many({n: (setup, _strategy(n)) for n in names}, noise=tables)
    return {n: tuple(runs[n].run(i) for i in range(len(fills))) for n in names}


def _replay(name: str, fill: float, steps: int) -> tracking.TrackingResult:
    fills = REPLAY_FILLS if fill in REPLAY_FILLS else (fill,)  # compare_replay needs both
    return _replay_pass(_SAME_PASS.get(name, (name,)), fills, steps)[name][fills.index(fill)]


def replay(name: str, fill: float = REPLAY_FILLS[0]) -> tracking.TrackingResult:
    """A published run re-simulated with the published noise (Sec. V, Figs. 4-7).

    Parameters
    ----------
    name : {"best-pair", "best-partner", "fixed-pair", "adversarial"}
        See :func:`obslib.published_runs.published_run`.
    fill : float
        Value given to the noise entries no published run measured (they should not matter:
        :func:`compare_replay` checks it).

    Returns
    -------
    TrackingResult
        315 steps; for ``"fixed-pair"`` only the first steps are determined by the table
        (``compare_replay(name).steps`` of them).

    Examples
    --------
    The replayed pairs are the logged ones:

    >>> from obslib.published_runs import published_run
    >>> from obslib.studies.replay import replay
    >>> r = replay("best-pair")
    >>> r.steps, bool((r.pairs == published_run("best-pair").pairs).all())
    (315, True)
    """
    name = _run_name_iv(name)
    try:
        fill = float(fill)
    except (TypeError, ValueError):
        raise ValueError(f"fill must be a finite number, got {fill!r}") from None
    if not np.isfinite(fill):
        raise ValueError(f"fill must be a finite number, got {fill!r}")
    return _replay(name, fill, published_run(name).steps)


@dataclass(frozen=True)
class ReplayComparison:
    """How a replay compares with the logged run (:func:`compare_replay`).

    Attributes
    ----------
    name : str
    steps : int
        Logged steps compared (all 315, or the replayable prefix of strategy (3)).
    max_abs_diff : dict
        Per logged quantity, the largest absolute difference replay minus log.
    n_values : dict
        Per logged quantity, how many numbers were compared.
    pair_mismatches : int
        Steps whose chosen pair differs from the log.
    fills_agree : bool
        The replays with the two :data:`REPLAY_FILLS` of the unknown entries are identical.
    unknown_reads : int
        Noise entries the replay read (its pairs at the compared steps but the last) that the
        table does not know.
    """

    name: str
    steps: int
    max_abs_diff: dict
    n_values: dict
    pair_mismatches: int
    fills_agree: bool
    unknown_reads: int

    @property
    def largest(self) -> float:
        """The largest difference over every compared number."""
        return max(self.max_abs_diff.values())

    @property
    def total_values(self) -> int:
        return int(sum(self.n_values.values()))

    @property
    def exact(self) -> bool:
        """Same pairs, never an unknown entry, fills agree (numbers are compared separately)."""
        return self.pair_mismatches == 0 and self.fills_agree and self.unknown_reads == 0

    @property
    def matches(self) -> bool:
        """:attr:`exact` and every compared number within :data:`LOG_TOLERANCE` of the log."""
        return self.exact and self.largest <= LOG_TOLERANCE


_FIELDS = ("bound", "error", "trace_cov", "truth", "estimate", "cov", "control", "objective")


def compare_replay(name: str) -> ReplayComparison:
    """Replay a published run and compare it with every number it logged.

    The circle runs of strategies (1) and (2) also logged the filter after the last update; the
    replay gets it by running one step more (the extra step's noise is never read for it).

    Parameters
    ----------
    name : {"best-pair", "best-partner", "fixed-pair", "adversarial"}

    Returns
    -------
    ReplayComparison
        Computed once per run and kept (the ledger's claims and the notebooks share it).

    Examples
    --------
    >>> from obslib.studies.replay import compare_replay
    >>> c = compare_replay("adversarial")
    >>> c.pair_mismatches, c.fills_agree
    (0, True)
    """
    return _compare_replay(_run_name_iv(name))


@cache
def _compare_replay(name: str) -> ReplayComparison:
    pub = published_run(name)
    n = _replayable_steps(name)
    extra = pub.estimate_end is not None
    runs = [_replay(name, f, n + extra) for f in REPLAY_FILLS]
    r = runs[0]
    fields = ("pairs", "bound", "error", "trace_cov", "truth", "estimate", "cov", "control")
    agree = all(np.array_equal(getattr(runs[0], f), getattr(runs[1], f)) for f in fields)
    diff, count = {}, {}
    for f in _FIELDS:
        logged = getattr(pub, f)
        if logged is None:
            continue
        ours = getattr(r, f)[:n]
        d = np.abs(ours - logged[:n])
        diff[f], count[f] = float(d.max()), int(d.size)
    if extra:
        for f, g in (("estimate_end", "estimate"), ("cov_end", "cov")):
            d = np.abs(getattr(r, g)[n] - getattr(pub, f))
            diff[f], count[f] = float(d.max()), int(d.size)
    mism = int((r.pairs[:n] != pub.pairs[:n]).any(axis=1).sum())
    noise = published_noise()
    used = noise[np.arange(n - 1)[:, None], r.pairs[: n - 1]]
    diff = {k: float(v) for k, v in diff.items()}
    return ReplayComparison(
        name=name,
        steps=n,
        max_abs_diff=diff,
        n_values=count,
        pair_mismatches=mism,
        fills_agree=bool(agree),
        unknown_reads=int((~np.isfinite(used)).sum()),
    )


#: Logged quantities by what their agreement with the replay tests. The noise was recovered from
#: each run's own estimates, so the estimates (and the errors computed from them) agree by
#: construction; the rest is computed by the replay from the model alone.
CHECK_GROUPS = {
    "bounds": ("bound", "objective"),
    "covariances": ("trace_cov", "cov", "cov_end"),
    "target": ("truth", "control"),
    "by construction": ("estimate", "estimate_end", "error"),
}


def independent_checks(name: str) -> dict:
    """What the replay of a published run tests beyond the noise it was given.

    The noise of a step was solved from that run's own update (two measurements from two
    equations), so the replayed estimates agree with the logged ones by construction. What
    the model has to get right by itself: the pair chosen at every step, the logged bounds (and,
    for the adversarial run, the exact :math:`C^{-1}` the target faced), the covariances, the
    target's positions and moves, and the noise entries the run reads that were recovered from
    another run's log (two runs measuring the same sensor at the same step must agree).

    Returns
    -------
    dict
        ``pairs`` (steps compared), the number of logged numbers compared per group of
        :data:`CHECK_GROUPS` (``bounds``, ``covariances``, ``target``, ``by construction``),
        ``shared_noise`` (noise entries read that another run's log gave) and ``read_noise``
        (all noise entries read).

    Examples
    --------
    >>> from obslib.studies.replay import independent_checks
    >>> c = independent_checks("best-partner")
    >>> c["pairs"], c["bounds"], c["shared_noise"] > 0
    (315, 315, True)
    """
    c = compare_replay(name)
    out = {"pairs": c.steps}
    for group, fields in CHECK_GROUPS.items():
        out[group] = int(sum(c.n_values.get(f, 0) for f in fields))
    r = replay(name)
    n = c.steps
    read = (np.arange(n - 1)[:, None], r.pairs[: n - 1])
    src = noise_sources()[read]
    out["read_noise"] = int(src.size)
    out["shared_noise"] = int(((src != "") & (src != name)).sum())
    return out


def seed_typicality(n_seeds: int, first_seed: int = 0) -> dict:
    """Where the published adversarial run's mean bound falls among runs with random noise.

    Runs the adversarial experiment (Sec. V-B) with ``n_seeds`` noise seeds
    (:func:`obslib.tracking.simulate_batch`) and compares each run's mean bound with the
    published run's (0.788). Computed once per ``(n_seeds, first_seed)`` and kept: the claims
    ``published-replay`` and ``fig7-figure-data`` and notebook 11 share it.

    Returns
    -------
    dict
        ``published`` (the logged mean bound), ``per_run`` (the seeds' mean bounds, read-only),
        ``percentile`` (share of seeds below the published value, in percent),
        ``at_least`` (share of seeds at or above it), ``within_tolerance`` (share of seeds within
        :data:`~obslib.studies.published.FIGURE_TOLERANCE`, relative, of the published value),
        ``quantiles`` (5, 25, 50, 75, 95 %), ``switches`` (per seed, read-only).

    Examples
    --------
    >>> from obslib.studies.replay import seed_typicality
    >>> s = seed_typicality(3)
    >>> (round(s["published"], 3), len(s["per_run"]),
    ...  0.0 <= s["percentile"] <= 100.0)
    (0.788, 3, True)
    """
    if isinstance(n_seeds, bool) or not isinstance(n_seeds, (int, np.integer)) or n_seeds < 1:
        raise ValueError(f"n_seeds must be a positive integer, got {n_seeds!r}")
    if (isinstance(first_seed, bool) or not isinstance(first_seed, (int, np.integer))
            or first_seed < 0):
        raise ValueError(f"first_seed must be a non-negative integer, got {first_seed!r}")
    out = _seed_typicality(int(n_seeds), int(first_seed))
    return dict(out, quantiles=dict(out["quantiles"]))


@lru_cache(maxsize=4)
def _seed_typicality(n_seeds: int, first_seed: int) -> dict:
    pub = float(published_run("adversarial").bound.mean())
    seeds = range(first_seed, first_seed + n_seeds)
    b = tracking.simulate_batch(tracking.PAPER_ADVERSARIAL, "best-pair", seeds=seeds)
    m = b.bound.mean(axis=1)
    sw = np.array(b.switches)
    m.flags.writeable = sw.flags.writeable = False
    return {
        "published": pub,
        "per_run": m,
        "percentile": float(100 * np.mean(m < pub)),
        "at_least": float(np.mean(m >= pub)),
        "within_tolerance": float(np.mean(np.abs(m - pub) <= FIGURE_TOLERANCE * pub)),
        "quantiles": {q: float(np.quantile(m, q / 100)) for q in (5, 25, 50, 75, 95)},
        "switches": sw,
    }
