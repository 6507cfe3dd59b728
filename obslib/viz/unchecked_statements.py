"""Figures of what the paper states but does not check: the derived matrix's worst case over
Theorem 1's bound, the greedy on jittered copies of a near-tight layout, and the published
adversarial run against random noise seeds.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_instance, as_mapping, as_positive, as_real
from ..published_runs import PublishedRun
from ..tracking import BatchResult, TrackingResult
from ._checks import as_series
from .style import GREY, PUBLISHED_STYLE, REPLAY_STYLE, look

__all__ = ["plot_eq4_ratios", "plot_jitter", "plot_typicality"]


def plot_eq4_ratios(lam_max, ratio, u_max: float):
    r"""The worst :math:`C^{-1}` of the matrix as derived (the control row once per sensor) over
    Theorem 1's bound, against :math:`\lambda_{\max} / u_{\max}^2`: the closed form for
    :math:`N = 2, 3, 6` sensors, and random scenes (``lam_max``, ``ratio``: one per scene).

    Examples
    --------
    >>> plot_eq4_ratios([1.0, 10.0], [0.8, 0.95], u_max=1.0).axes[0].get_xscale()
    'log'
    """
    import matplotlib.pyplot as plt

    lam_max = as_series(lam_max, "lam_max")
    ratio = as_series(ratio, "ratio", lam_max.size)
    u_max = as_positive(u_max, "u_max")
    fig, ax = plt.subplots(figsize=(7.5, 3.6))
    t = np.logspace(-2, 3, 200)  # lambda_max / u_max^2
    for n in (2, 3, 6):
        ax.plot(t, np.sqrt((t + 1) / (t + n)), label=f"closed form, $N = {n}$")
    ax.plot(lam_max / u_max**2, ratio, ".", color=GREY, ms=2, label="random scenes")
    ax.set_xscale("log")
    ax.set_xlabel("$\\lambda_{\\max} / u_{\\max}^2$ (dimensionless)")
    ax.set_ylabel("worst $C^{-1}(O_d)$ / bound")
    ax.legend(loc="lower right")
    return fig


def plot_jitter(ratios, fractions):
    """The greedy over the optimum on jittered copies of the near-tight layout: one row of
    ``ratios`` per jitter of ``fractions`` (a fraction of the layout's spread), against the
    guaranteed third.

    Examples
    --------
    >>> fig = plot_jitter([[0.4, 0.5], [0.6, 0.9]], [0.001, 0.1])
    >>> fig.axes[0].get_ylabel()
    'greedy / optimum'
    """
    import matplotlib.pyplot as plt

    from .._validate import as_float_array

    fractions = as_series(fractions, "fractions")
    R = as_float_array(ratios, "ratios")
    if R.ndim != 2 or R.shape[0] != fractions.size or not np.isfinite(R).all():
        raise ValueError(f"ratios must be finite, one row per fraction ({fractions.size}), "
                         f"got shape {R.shape}")
    if (fractions <= 0).any():
        raise ValueError("fractions must be positive")
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    x = np.log10(fractions)
    for a, row in enumerate(R):
        ax.plot(np.full(row.size, x[a]) + np.linspace(-0.15, 0.15, row.size), row, ".",
                ms=3, color=look("greedy").color, alpha=0.5,
                label="a jittered copy" if a == 0 else None)
    ax.axhline(1 / 3, color="k", ls="--", label="guarantee 1/3")
    ax.set_xlabel("jitter, $\\log_{10}$ of the fraction of the spread")
    ax.set_ylabel("greedy / optimum")
    ax.legend(loc="center left")
    return fig


def plot_typicality(published, replay, typical: dict):
    """The published adversarial run: its bound at each step (wide and pale) under its replay
    (thin), and its mean bound among those of runs with random noise seeds (``typical``:
    ``per_run``, the runs' mean bounds, and ``published``, the published run's).

    Examples
    --------
    >>> from obslib.published_runs import published_run
    >>> from obslib.studies.replay import replay
    >>> pub, rep = published_run("adversarial"), replay("adversarial")
    >>> typical = {"per_run": [0.5, 0.6, 0.7], "published": 0.79}
    >>> plot_typicality(pub, rep, typical).axes[1].get_xlabel()
    'mean bound of a run'
    """
    import matplotlib.pyplot as plt

    published = as_instance(published, PublishedRun, "published")
    mine = as_instance(replay, TrackingResult, "replay")
    if isinstance(mine, BatchResult) or mine.steps != published.steps:
        raise ValueError(f"replay must be one run of the published run's {published.steps} steps")
    typical = as_mapping(typical, "typical")
    if not {"per_run", "published"} <= set(typical):
        raise ValueError("typical must hold per_run and published")
    per_run = as_series(typical["per_run"], "typical")
    at = as_real(typical["published"], "typical")
    fig, (a0, a1) = plt.subplots(1, 2, figsize=(7.5, 3.4))
    k = np.arange(1, published.steps + 1)
    colour = look("best-pair").color
    a0.plot(k, published.bound, color=colour, label="published", **PUBLISHED_STYLE)
    a0.plot(k, mine.bound, color=colour, label="replay", **REPLAY_STYLE)
    a0.set_xlabel("step $k$")
    a0.set_ylabel("bound of the chosen pair")
    a0.set_ylim(min(published.bound.min(), mine.bound.min()) - 0.2, 1.02)
    a0.legend(loc="lower center", ncols=2)
    a1.hist(per_run, bins=40, color=GREY, label="random seeds")
    a1.axvline(at, color="k", ls="--", label="published run")
    a1.set_xlabel("mean bound of a run")
    a1.set_ylabel("noise seeds")
    a1.legend(loc="upper left")
    return fig
