"""The published tracking runs of Figs. 4-7, as data shipped with the package.

The per-step data of the runs drawn in the paper's Figs. 4-7 and the measurement noise they
used, read out of the authors' saved MATLAB workspaces (``obslib/data/published_runs/README.md``
gives the provenance and how the noise was recovered).

>>> from obslib.published_runs import published_noise, published_run
>>> published_noise().shape
(315, 6)
>>> published_run("adversarial").bound.shape
(315,)

Runs are named by the strategy of Section V-A (``"best-pair"``, ``"best-partner"``,
``"fixed-pair"``: strategies (1), (2), (3) on the circle, Figs. 4-6) or ``"adversarial"`` (the
adversarial target against strategy (1), Fig. 7). Steps ``k = 1..315`` sit at index ``k - 1``
and sensors are 0-based (``s1`` is 0), as in :class:`obslib.tracking.TrackingResult`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache, lru_cache
from importlib import resources

import numpy as np

__all__ = ["RUN_NAMES", "STEPS", "N_SENSORS", "PublishedRun", "published_noise", "noise_sources",
           "published_run"]

#: Names accepted by :func:`published_run`.
RUN_NAMES = ("best-pair", "best-partner", "fixed-pair", "adversarial")

#: Steps of every published run and sensors of the experiments (Section V).
STEPS = 315
N_SENSORS = 6

_FILES = {
    "noise": "inferred_measurement_noise.csv",
    "trajectories": "fig4_6_workspace_trajectories.csv",
    "pairs": "fig5_pair_selection_per_step.csv",
    "three": "fig6_three_strategies_per_step.csv",
    "adversarial": "fig7_entrapment_per_step.csv",
}


@dataclass(frozen=True, eq=False)
class PublishedRun:
    """The logged per-step data of one published run (arrays indexed by step ``k - 1``).

    Attributes
    ----------
    name : str
        One of :data:`RUN_NAMES`.
    strategy : str
        The sensors' strategy (``"best-pair"`` for the adversarial run).
    motion : {"circle", "adversarial"}
    bound : (315,)
        The chosen pair's bound at the estimate (the curve ``C^{-1}`` of Figs. 6-7).
    error, trace_cov : (315,)
        ``||xhat_k - o_k||`` and ``trace(Sigma_k)`` before the step's update.
    pairs : (315, 2) int or None
        The chosen pair, 0-based and sorted. Strategy (3)'s pair is ``(s1, s2)`` by definition.
    truth : (315, 2) or None
        The true position ``o_k`` (None for strategy (3), whose truth is the same circle but
        whose filter was not saved).
    estimate, cov : (315, 2), (315, 2, 2) or None
        ``xhat_k`` and ``Sigma_k`` before the step's update (None for strategy (3)).
    estimate_end, cov_end : (2,), (2, 2) or None
        The filter after the last update (logged for the circle runs of strategies 1 and 2).
    control : (315, 2) or None
        The adversarial target's move after step ``k``, ``u_k = o_{k+1} - o_k``.
    objective : (315,) or None
        The adversarial run's logged exact inverse condition number of
        ``[o_{k+1} - p_i; o_{k+1} - p_j; u_k]`` with the pair of step ``k``: the value the
        target reached with its move (:attr:`obslib.tracking.TrackingResult.objective`).
    """

    name: str
    strategy: str
    motion: str
    bound: np.ndarray
    error: np.ndarray
    trace_cov: np.ndarray
    pairs: np.ndarray | None = None
    truth: np.ndarray | None = None
    estimate: np.ndarray | None = None
    cov: np.ndarray | None = None
    estimate_end: np.ndarray | None = None
    cov_end: np.ndarray | None = None
    control: np.ndarray | None = None
    objective: np.ndarray | None = None

    @property
    def steps(self) -> int:
        return int(self.bound.shape[0])

    @property
    def switches(self) -> int | None:
        """Pair changes over the ``steps - 1`` transitions (None when no pair was logged)."""
        if self.pairs is None:
            return None
        return int((self.pairs[1:] != self.pairs[:-1]).any(axis=1).sum())


def _read(key: str) -> tuple[list[str], np.ndarray]:
    """Header and numeric columns of one data file (non-numeric columns become NaN)."""
    path = resources.files("obslib").joinpath("data", "published_runs", _FILES[key])
    lines = path.read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")

    def num(s: str) -> float:
        try:
            return float(s)
        except ValueError:
            return np.nan

    rows = [[num(x) for x in line.split(",")] for line in lines[1:] if line.strip()]
    return header, np.array(rows, dtype=float)


@cache
def _table(key: str) -> dict[str, np.ndarray]:
    header, data = _read(key)
    if data.shape[1] != len(header):
        raise RuntimeError(f"{_FILES[key]}: {data.shape[1]} columns for {len(header)} names")
    k = data[:, 0]
    if not np.array_equal(k, np.arange(1, k.size + 1)):
        raise RuntimeError(f"{_FILES[key]}: steps are not 1, 2, ...")
    return {name: data[:, i] for i, name in enumerate(header)}


def published_noise() -> np.ndarray:
    """The measurement noise of the published runs, ``(315, 6)``; NaN where no run measured.

    Entry ``[k - 1, i]`` is the additive noise ``n_i`` of sensor ``i`` (0-based) at step ``k`` in
    ``z_i = 1/2 ||p_i - o_k||^2 + n_i`` (Section V), recovered from the saved filter updates.
    1240 entries are known: every (step, sensor) that strategy (1), strategy (2) or the
    adversarial run measured. Pass it, with the NaN filled, as ``noise`` to
    :func:`obslib.tracking.simulate`.

    Returns
    -------
    ndarray, shape (315, 6)
        A fresh copy.
    """
    return _noise().copy()


@lru_cache(maxsize=1)
def _noise() -> np.ndarray:
    header, data = _read("noise")
    col = {name: i for i, name in enumerate(header)}
    k = data[:, col["k"]].astype(int)
    s = data[:, col["sensor_id"]].astype(int)
    if k.min() < 1 or k.max() > STEPS or s.min() < 1 or s.max() > N_SENSORS:
        raise RuntimeError("noise table: step or sensor out of range")
    table = np.full((STEPS, N_SENSORS), np.nan)
    if np.unique(k * N_SENSORS + s).size != k.size:
        raise RuntimeError("noise table: an entry is given twice")
    table[k - 1, s - 1] = data[:, col["noise"]]
    table.setflags(write=False)
    return table


#: The noise table's names of the runs an entry was recovered from -> names of :data:`RUN_NAMES`.
_SOURCE_RUNS = {"flex": "best-pair", "partner": "best-partner", "entrap": "adversarial"}


def noise_sources() -> np.ndarray:
    """Which published run each entry of :func:`published_noise` was recovered from.

    Returns
    -------
    ndarray of str, shape (315, 6)
        A name of :data:`RUN_NAMES` (``"best-pair"``, ``"best-partner"`` or ``"adversarial"``),
        or ``""`` where no run measured the sensor at that step.

    Examples
    --------
    >>> from obslib.published_runs import noise_sources, published_noise
    >>> src = noise_sources()
    >>> bool(((src != "") == np.isfinite(published_noise())).all())
    True
    """
    return _sources().copy()


@lru_cache(maxsize=1)
def _sources() -> np.ndarray:
    path = resources.files("obslib").joinpath("data", "published_runs", _FILES["noise"])
    lines = path.read_text(encoding="utf-8").splitlines()
    col = {name: i for i, name in enumerate(lines[0].split(","))}
    out = np.full((STEPS, N_SENSORS), "", dtype=object)
    for line in lines[1:]:
        if line.strip():
            f = line.split(",")
            run = f[col["source_run"]]
            if run not in _SOURCE_RUNS:
                raise RuntimeError(f"noise table: unknown source run {run!r}")
            out[int(f[col["k"]]) - 1, int(f[col["sensor_id"]]) - 1] = _SOURCE_RUNS[run]
    out.setflags(write=False)
    return out


def _pairs(first, second) -> np.ndarray:
    p = np.column_stack([first, second]).astype(int) - 1
    return np.sort(p, axis=1)


def _cov(S11, S12, S22) -> np.ndarray:
    return np.stack([np.stack([S11, S12], -1), np.stack([S12, S22], -1)], -2)


def _build(name: str) -> PublishedRun:
    n = STEPS
    if name == "adversarial":
        t = _table("adversarial")
        xy = lambda a, b: np.column_stack([t[a], t[b]])  # noqa: E731
        return PublishedRun(
            name=name,
            strategy="best-pair",
            motion="adversarial",
            bound=t["sensor_lowerbound"],
            error=t["est_error"],
            trace_cov=t["trace_Sigma"],
            pairs=_pairs(t["pair_first"], t["pair_second"]),
            truth=xy("true_x", "true_y"),
            estimate=xy("est_x", "est_y"),
            control=xy("ux", "uy"),
            objective=t["target_true_invcond"],
        )
    three, traj, sel = _table("three"), _table("trajectories"), _table("pairs")
    p = {"fixed-pair": "fixed_s2s1", "best-pair": "flex"}.get(name, "partner_s2")
    logged = dict(name=name, strategy=name, motion="circle", bound=three[f"{p}_lowerbound"],
                  error=three[f"{p}_est_error"], trace_cov=three[f"{p}_trace_Sigma"])
    if name == "fixed-pair":
        return PublishedRun(**logged, pairs=np.tile([0, 1], (n, 1)))
    w = "flex" if name == "best-pair" else "partner"
    est = np.column_stack([traj[f"{w}_est_x"], traj[f"{w}_est_y"]])
    cov = _cov(traj[f"{w}_S11"], traj[f"{w}_S12"], traj[f"{w}_S22"])
    if name == "best-pair":
        pairs = _pairs(sel["flex_pair_min"], sel["flex_pair_max"])
    else:
        pairs = _pairs(np.full(n, 2), sel["partner_of_s2(black)"])
    return PublishedRun(
        **logged,
        pairs=pairs,
        truth=np.column_stack([traj["true_x"], traj["true_y"]])[:n],
        estimate=est[:n],
        cov=cov[:n],
        estimate_end=est[n],
        cov_end=cov[n],
    )


@cache
def _run(name: str) -> PublishedRun:
    return _build(name)


def published_run(name: str) -> PublishedRun:
    """The logged per-step data of one published run.

    Parameters
    ----------
    name : {"best-pair", "best-partner", "fixed-pair", "adversarial"}
        Strategies (1), (2), (3) of Section V-A on the circle (Figs. 4-6), or the adversarial
        target of Section V-B against strategy (1) (Fig. 7).

    Returns
    -------
    PublishedRun
        Arrays are fresh copies; fields a run did not log are None.
    """
    r = _run(_published_run_iv(name))
    copies = {
        f: (v.copy() if isinstance(v, np.ndarray) else v) for f, v in vars(r).items()
    }
    return PublishedRun(**copies)


def _published_run_iv(name) -> str:
    """One of :data:`RUN_NAMES`."""
    if not isinstance(name, str) or name not in RUN_NAMES:
        raise ValueError(f"unknown published run {name!r}; accepted names: {', '.join(RUN_NAMES)}")
    return name
