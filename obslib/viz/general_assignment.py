"""Figures of general assignment by greedy teams (Section V-D, Fig. 9): the diminishing gains of
a sensor joining a team, the sensors per target, how evenly the greedy spreads them, and the
greedy against the optimum.
"""

from __future__ import annotations

import itertools

import numpy as np

from .._validate import as_float_array, as_instance, as_int, as_mapping
from ..formatting import setting
from ..studies.general_assignment import Evenness
from ._checks import as_series
from .style import OKABE_ITO, SEQUENTIAL, look

__all__ = ["plot_join_gains", "plot_fig9", "plot_evenness", "plot_optimum_ratio"]


def plot_join_gains(gains: dict):
    r"""The median gain in :math:`\log\det(O^T O + \varepsilon I)` of a sensor joining a team,
    against its place in the team, one curve per prior :math:`\varepsilon` (``gains``: prior ->
    the gains of the first, second, ... sensor).

    Examples
    --------
    >>> fig = plot_join_gains({1.0: [2.0, 1.0, 0.5], 100.0: [1.0, 0.8, 0.4]})
    >>> fig.axes[0].get_legend().get_texts()[1].get_text()
    '$\\varepsilon$ = 100'
    """
    import matplotlib as mpl
    import matplotlib.pyplot as plt

    gains = as_mapping(gains, "gains")
    if not gains:
        raise ValueError("gains must hold at least one prior")
    curves = {}
    for e, g in gains.items():
        curves[float(as_float_array(e, "gains"))] = as_series(g, "gains")
    n_join = len(next(iter(curves.values())))
    if any(len(g) != n_join for g in curves.values()):
        raise ValueError("gains must hold the same number of gains for each prior")
    fig, ax = plt.subplots(figsize=(7.5, 3.6))
    k = np.arange(1, n_join + 1)
    colours = mpl.colormaps[SEQUENTIAL](np.linspace(0, 0.85, len(curves)))
    for (e, g), colour, marker in zip(curves.items(), colours, itertools.cycle("osD^v")):
        ax.plot(k, g, color=colour, marker=marker,
                label=rf"$\varepsilon$ = {setting(e, math=False)}")
    ax.set_yscale("log")
    ax.set_xticks(k)
    ax.set_xlabel("the sensor's place in its team (1: the team's first sensor)")
    ax.set_ylabel("gain in log det (nats)")
    ax.legend(title="prior", loc="upper right")
    return fig


def _counts_iv(counts, N_values):
    counts = as_float_array(counts, "counts")
    N = as_series(N_values, "N_values")
    if counts.ndim != 3 or counts.shape[0] != N.size or counts.shape[1] < 2:
        raise ValueError(f"counts must have shape (len(N_values), trials >= 2, L), "
                         f"got {counts.shape}")
    return counts, N


def plot_fig9(counts, N_values):
    """Fig. 9: the sensors the greedy gives each target against :math:`N/L`, target 1's mean
    and standard deviation over the trials (the paper's curve) and the other targets' means.

    ``counts`` has shape ``(len(N_values), trials, L)``
    (:func:`obslib.studies.general_assignment.fig9_sweep`).

    Examples
    --------
    >>> from obslib.studies.general_assignment import fig9_sweep
    >>> counts = fig9_sweep([4, 6], trials=2, seed=0, n_targets=2)
    >>> plot_fig9(counts, [4, 6]).axes[0].get_xlabel()
    '$N/L$ (sensors per target)'
    """
    import matplotlib.pyplot as plt

    counts, N = _counts_iv(counts, N_values)
    n_targets = counts.shape[2]
    fair = N / n_targets
    fig, ax = plt.subplots(figsize=(7.5, 3.8))
    greedy_look = look("logdet")
    for l in range(n_targets):
        m, s = counts[:, :, l].mean(axis=1), counts[:, :, l].std(axis=1, ddof=1)
        if l == 0:
            ax.errorbar(fair, m, yerr=s, capsize=2, color=greedy_look.color,
                        label="target 1, mean and standard deviation (the paper's curve)")
        else:
            ax.plot(fair, m, color=greedy_look.color, alpha=0.35, lw=1,
                    label=f"targets 2 to {n_targets}, means" if l == 1 else None)
    ax.plot(fair, fair, "k--", label="$N/L$")
    ax.set_xlabel("$N/L$ (sensors per target)")
    ax.set_ylabel("sensors given to a target")
    ax.legend(loc="upper left")
    return fig


def plot_evenness(even, N_values, n_targets: int, text=None):
    """How evenly the greedy spreads the sensors: the spread of the counts within a trial
    against :math:`N/L`, for the greedy with the prior, for a uniformly random assignment and,
    when ``text`` is given, for the greedy with the measure the text of Section V-D names (an
    :class:`~obslib.studies.general_assignment.Evenness` of its counts, with the control row).

    Examples
    --------
    >>> from obslib.studies.general_assignment import evenness, fig9_sweep
    >>> counts = fig9_sweep([4, 6], trials=2, seed=0, n_targets=2)
    >>> fig = plot_evenness(evenness(counts, [4, 6], 2), [4, 6], 2)
    >>> fig.axes[0].get_ylabel()
    'spread of the counts in a trial'
    """
    import matplotlib.pyplot as plt

    even = as_instance(even, Evenness, "even")
    N = as_series(N_values, "N_values", len(even.within))
    if text is not None and len(as_instance(text, Evenness, "text").within) != len(N):
        raise ValueError(f"text must have one spread per N ({len(N)}), got {len(text.within)}")
    fair = N / as_int(n_targets, "n_targets", 1)
    fig, ax = plt.subplots(figsize=(7.5, 3.6))
    ax.plot(fair, even.within, **look("logdet").kw(ms=4, label="greedy, log det with prior"))
    if text is not None:
        ax.plot(fair, text.within, **look("logdet").kw(
            color=OKABE_ITO["orange"], marker="v", linestyle="--", ms=4,
            label="greedy, log det with control row"))
    ax.plot(fair, even.baseline, **look("random").kw(ms=4, label="uniformly random assignment"))
    ax.set_xlabel("$N/L$ (sensors per target)")
    ax.set_ylabel("spread of the counts in a trial")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper left")
    return fig


def plot_optimum_ratio(ratio):
    """The greedy team assignment's total over the optimum's on tiny instances, as a histogram
    (log counts), with the guaranteed half.

    Examples
    --------
    >>> plot_optimum_ratio([1.0, 0.9]).axes[0].get_xlabel()
    'greedy total over the optimum (log det sums)'
    """
    import matplotlib.pyplot as plt

    r = as_series(ratio, "ratio")
    fig, ax = plt.subplots(figsize=(7.5, 3.2))
    ax.hist(r, bins=np.linspace(0.5, 1.0, 51), color=look("logdet").color, label="instances")
    ax.axvline(0.5, color="k", ls="--", label="guarantee, 1/2")
    ax.set_xlabel("greedy total over the optimum (log det sums)")
    ax.set_ylabel("instances")
    ax.set_yscale("log")
    ax.legend(loc="upper center")
    return fig
