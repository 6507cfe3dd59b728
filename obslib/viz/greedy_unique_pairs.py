"""Figures of greedy unique pairs (Section IV-A, Algorithm 1 and Theorem 6): maps of the greedy's
and the optimum's pairs side by side, the greedy's ratio to the optimum on random instances, and
the greedy's picks by the number of optimal triples charged to them (Theorem 6's proof).
"""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_instance, as_points
from ..assignment import PairAssignment
from ..formatting import number
from ._checks import as_series
from .style import as_figsize, look, sensor_label, target_label

__all__ = ["plot_greedy_and_optimum", "plot_ratio_histogram", "plot_charges_per_pick"]


def _place_labels(ax, P, labels, dist=10):
    """Each label beside its point, on the side away from the nearest other point."""
    for k, (p, text) in enumerate(zip(P, labels)):
        d = np.linalg.norm(P - p, axis=1)
        d[k] = np.inf
        away = (p - P[np.argmin(d)]) / d.min()
        ax.annotate(text, p, textcoords="offset points", xytext=tuple(dist * away),
                    ha="left" if away[0] > 0.3 else "right" if away[0] < -0.3 else "center",
                    va="bottom" if away[1] > 0.3 else "top" if away[1] < -0.3 else "center")


def _draw_assignment(ax, S, T, triples, name, W=None):
    """Sensors, targets and a line from each sensor of a pair to its target, in the look of
    the assignment ``name``; with ``W``, each pair's value written beside its target."""
    line = look(name).kw(marker="", label=None)
    for i, j, l in triples:
        for s in (i, j):
            ax.plot(*np.array([S[s], T[l]]).T, lw=2, zorder=1, **line)
        if W is not None:
            # the value sits on the side of the target away from its two sensors
            away = -sum((S[s] - T[l]) / np.linalg.norm(S[s] - T[l]) for s in (i, j))
            away = away / max(np.linalg.norm(away), 1e-9)
            ax.annotate(f"ω = {number(W[i, j, l], math=False)}", T[l], ha="center",
                        va="center", textcoords="offset points", xytext=tuple(40 * away),
                        color=line["color"])
    ax.plot(*S.T, **look("sensor").kw(ms=9, zorder=3))
    ax.plot(*T.T, **look("target").kw(ms=14, zorder=3))
    _place_labels(ax, np.vstack([S, T]), [sensor_label(i) for i in range(len(S))]
                  + [target_label(l) for l in range(len(T))])
    ax.set_aspect("equal", adjustable="box")
    ax.margins(0.15)
    ax.set_xlabel("x (length unit)")


def _assignment_iv(result, name, n, n_targets):
    """An assignment whose triples index ``n`` sensors and ``n_targets`` targets."""
    as_instance(result, PairAssignment, name)
    for i, j, l in result.triples:
        if not (0 <= i < n and 0 <= j < n and 0 <= l < n_targets):
            raise ValueError(f"{name}: the triple {(i, j, l)} is outside {n} sensors and "
                             f"{n_targets} targets")
    return result


def plot_greedy_and_optimum(sensors, targets, greedy, optimum, W=None, figsize=(7.5, 4.2)):
    """Two maps side by side: the greedy's pairs (left) and the optimum's (right), each line
    from a sensor of a pair to its target, the titles giving the totals; with the weights ``W``
    ``(N, N, L)``, each pair's bound written beside its target.

    Examples
    --------
    >>> import obslib as ob
    >>> S = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [4.0, 4.0]]
    >>> T = [[2.0, 1.0], [2.0, 3.0]]
    >>> W = ob.pair_bounds(S, T, 1.0)
    >>> g, o = ob.greedy_pair_assignment(W), ob.optimal_pair_assignment(W)
    >>> fig = plot_greedy_and_optimum(S, T, g, o, W)
    >>> [ax.get_title().split(":")[0] for ax in fig.axes]
    ['greedy', 'optimum']
    """
    import matplotlib.pyplot as plt

    S = as_points(sensors, "sensors")
    T = as_points(targets, "targets")
    greedy = _assignment_iv(greedy, "greedy", len(S), len(T))
    optimum = _assignment_iv(optimum, "optimum", len(S), len(T))
    if W is not None:
        W = as_float_array(W, "W")
        if W.shape != (len(S), len(S), len(T)):
            raise ValueError(f"W must have shape {(len(S), len(S), len(T))}, got {W.shape}")
    figsize = as_figsize(figsize)
    fig, axes = plt.subplots(1, 2, figsize=figsize, sharex=True, sharey=True)
    for ax, res, name, title in ((axes[0], greedy, "greedy", "greedy"),
                                 (axes[1], optimum, "optimal", "optimum")):
        _draw_assignment(ax, S, T, res.triples, name, W)
        ax.set_title(f"{title}: total {number(res.value, math=False)}")
    axes[0].set_ylabel("y (length unit)")
    return fig


def plot_ratio_histogram(ratio):
    """The greedy's total over the optimum's on random instances, as a histogram (log counts),
    with Theorem 6's guarantee of a third.

    Examples
    --------
    >>> fig = plot_ratio_histogram([1.0, 0.9, 0.95])
    >>> fig.axes[0].get_xlabel()
    'greedy / optimum (ratio of the totals)'
    """
    import matplotlib.pyplot as plt

    ratio = as_series(ratio, "ratio")
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    ax.hist(ratio, bins=np.linspace(0.3, 1.0, 71), color=look("greedy").color)
    ax.axvline(1 / 3, color="k", ls="--", label="Theorem 6: 1/3")
    ax.set_xlabel("greedy / optimum (ratio of the totals)")
    ax.set_ylabel("instances (log scale)")
    ax.set_yscale("log")
    ax.legend(loc="upper left")
    return fig


def plot_charges_per_pick(charges):
    """The greedy's picks on random instances by the number of optimal triples charged to them
    in Theorem 6's charging argument, ``charges[k]`` picks with ``k`` triples (``k`` = 0 to 3),
    as bars with their counts.

    Examples
    --------
    >>> fig = plot_charges_per_pick([10, 30, 8, 2])
    >>> [t.get_text() for t in fig.axes[0].get_xticklabels()]
    ['0', '1', '2', '3']
    """
    import matplotlib.pyplot as plt

    charges = as_series(charges, "charges", 4)
    if (charges < 0).any():
        raise ValueError("charges must be counts >= 0")
    fig, ax = plt.subplots(figsize=(7.5, 3.2))
    bars = ax.bar(range(4), charges, color=look("greedy").color, width=0.6)
    ax.bar_label(bars, labels=[number(int(c), math=False) for c in charges], padding=2)
    ax.set_xticks(range(4), [str(k) for k in range(4)])
    ax.set_xlabel("optimal triples charged to the pick")
    ax.set_ylabel("greedy picks")
    ax.set_ylim(0, 1.15 * max(float(charges.max()), 1.0))
    return fig
