"""Figures of the greedy against the relaxed matching (Section V-C, Fig. 8): the three
assignments of one instance, Fig. 8's mean totals, and the relaxed matching against Problem 1's
optimum instance by instance.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_instance, as_int, as_mapping, as_points, as_positive
from ..assignment import PairAssignment
from ..formatting import number
from ..studies.greedy_vs_relaxed import Fig8Summary, Problem3Audit
from .style import look

__all__ = ["plot_three_assignments", "plot_fig8", "plot_problem3"]

_KEYS = ("greedy", "optimal", "relaxed")


def plot_three_assignments(sensors, targets, assignments: dict, side: float):
    """One instance of Fig. 8 (points in the square ``[0, side]``) and its three assignments,
    ``assignments`` by name: the greedy, the exact optimum and the relaxed matching, each line
    from a sensor of a pair to its target; the titles give the totals. Each point's label
    stands on the side away from its nearest neighbour.

    Examples
    --------
    >>> import obslib as ob
    >>> from obslib.studies.greedy_vs_relaxed import fig8_instance
    >>> S, T = fig8_instance(n_targets=2, trial=0, seed=0, side=40.0)
    >>> W = ob.pair_bounds(S, T, 1.0)
    >>> res = {"greedy": ob.greedy_pair_assignment(W),
    ...        "optimal": ob.optimal_pair_assignment(W),
    ...        "relaxed": ob.relaxed_pair_assignment(W)}
    >>> fig = plot_three_assignments(S, T, res, side=40.0)
    >>> [ax.get_title().splitlines()[0] for ax in fig.axes]
    ['greedy', 'exact optimum', 'relaxed matching']
    """
    import matplotlib.pyplot as plt

    S = as_points(sensors, "sensors", min_count=1)
    T = as_points(targets, "targets", min_count=1)
    assignments = as_mapping(assignments, "assignments")
    if set(assignments) != set(_KEYS):
        raise ValueError(f"assignments must hold {_KEYS}, got {sorted(assignments)}")
    for res in assignments.values():
        as_instance(res, PairAssignment, "assignments")
        for i, j, l in res.triples:
            if not (0 <= i < len(S) and 0 <= j < len(S) and 0 <= l < len(T)):
                raise ValueError(f"assignments: the triple {(i, j, l)} is outside the instance")
    side = as_positive(side, "side")
    # labels on the side away from each point's nearest neighbour, so close points keep apart
    points = np.vstack([S, T])
    dist = np.linalg.norm(points[:, None] - points[None], axis=2) + np.diag(
        [np.inf] * len(points))
    away = np.sign(points[:, 0] - points[dist.argmin(axis=1), 0])
    label_side = np.where(away < 0, -1, 1)  # -1: label left of the point, 1: right
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.1), sharex=True, sharey=True)
    for ax, key in zip(axes, _KEYS):
        for i, j, l in assignments[key].triples:
            for k in (i, j):  # a line from each sensor of the pair to its target
                ax.plot(*zip(S[k], T[l]), color=look(key).color, lw=2)
        ax.plot(*S.T, **look("sensor").kw(ms=9))
        ax.plot(*T.T, **look("target").kw(ms=13))
        names = [f"$s_{k + 1}$" for k in range(len(S))] + [f"$t_{k + 1}$" for k in range(len(T))]
        for text, p, side_ in zip(names, points, label_side):
            ax.annotate(text, p, xytext=(7 * side_, 4), textcoords="offset points",
                        ha="left" if side_ > 0 else "right")
        total = number(assignments[key].value, math=False)
        ax.set_title(f"{look(key).label.split(' (')[0]}\ntotal {total}")
        ax.set_xlabel("x (m)")
        ax.set_xlim(-5, side + 15)
        ax.set_ylim(-5, side + 15)
        ax.set_aspect("equal")
    axes[0].set_ylabel("y (m)")
    return fig


def plot_fig8(summary, optimum_max_L: int):
    """Fig. 8: the mean total bound of the relaxed matching and of the greedy, with their
    spreads, against the number of targets; a third of the relaxed matching, and the exact
    optimum where it is computed (up to ``optimum_max_L`` targets).

    Examples
    --------
    >>> from obslib.studies.greedy_vs_relaxed import fig8_summary, fig8_sweep
    >>> sweep = fig8_sweep([1, 2], trials=3, seed=0, optimum_max_L=2)
    >>> summary = fig8_summary(sweep)
    >>> fig = plot_fig8(summary, optimum_max_L=2)
    >>> fig.axes[0].get_legend().get_texts()[0].get_text()
    'relaxed matching (Problem 3)'
    """
    import matplotlib.pyplot as plt

    summary = as_instance(summary, Fig8Summary, "summary")
    optimum_max_L = as_int(optimum_max_L, "optimum_max_L", 0)
    mean, std, L = summary.mean, summary.std, summary.L
    fig, ax = plt.subplots(figsize=(7.5, 4.4))
    for key, name in (("relaxed", "relaxed"), ("greedy", "greedy")):
        ax.errorbar(L, mean[key], yerr=std[key], capsize=2, ms=4, **look(name).kw())
    ax.plot(L, mean["relaxed"] / 3, **look("relaxed").kw(
        marker="", linestyle="--", label="a third of the relaxed matching"))
    has_opt = L <= optimum_max_L
    ax.plot(L[has_opt], mean["optimum"][has_opt], **look("optimal").kw(
        linestyle="none", ms=6, label="exact optimum (Problem 1)"))
    ax.set_xlabel("number of targets $L$ ($N = 2L$ sensors)")
    ax.set_ylabel("total bound of the pairs")
    ax.set_xticks(L[1::2] if len(L) > 10 else L)
    h, lab = ax.get_legend_handles_labels()
    order = (2, 3, 1, 0)  # relaxed, greedy, optimum, a third
    ax.legend([h[k] for k in order], [lab[k] for k in order], loc="upper left")
    return fig


def plot_problem3(audit):
    """The relaxed matching over Problem 1's exact optimum, instance by instance, one box per
    number of targets ``L`` of a :class:`~obslib.studies.greedy_vs_relaxed.Problem3Audit`, with
    the line of equality: a box below it would be an instance where the relaxation is no upper
    bound.

    Examples
    --------
    >>> from obslib.studies.greedy_vs_relaxed import problem3_audit
    >>> fig = plot_problem3(problem3_audit(3, trials=4, seed=0, optimum_max_L=3))
    >>> fig.axes[0].get_ylabel()
    'relaxed matching / optimum'
    """
    import matplotlib.pyplot as plt

    audit = as_instance(audit, Problem3Audit, "audit")
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    ax.axhline(1.0, **look("optimal").kw(marker="", lw=1, linestyle="--",
                                          label="equal to the optimum"))
    if audit.matching.size:
        ratio = audit.matching / audit.optimum
        ax.boxplot(list(ratio), positions=audit.L, widths=0.5,
                   medianprops={"color": look("relaxed").color},
                   flierprops={"marker": look("relaxed").marker, "markersize": 4})
        ax.set_xticks(audit.L, [str(int(L)) for L in audit.L])
    ax.set_xlabel("number of targets $L$ ($N = 2L$ sensors)")
    ax.set_ylabel("relaxed matching / optimum")
    ax.legend(loc="upper left")
    return fig
