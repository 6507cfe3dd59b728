"""Figures of two sensors tracking a target (Section V-A, Figs. 4-6): the rings two range sensors
leave, snapshots of a run, the pair chosen at each step, bound, error and trace over time, the
published runs under their replays, the Monte Carlo means, a lost run and the switching rate.

Runs are :class:`obslib.tracking.TrackingResult` (one run) or :class:`obslib.tracking.BatchResult`
(many), keyed by strategy where a figure shows several; each strategy is named by
:data:`obslib.viz.tracking.STRATEGY_LABELS` and drawn in its look of :mod:`obslib.viz.style`.
"""

from __future__ import annotations

import numpy as np

from .._validate import (
    as_instance,
    as_int,
    as_int_range,
    as_ints,
    as_mapping,
    as_nonnegative,
    as_positive,
)
from ..bounds import lower_bound
from ..formatting import number
from ..published_runs import PublishedRun
from ..tracking import STRATEGIES, BatchResult, TrackingResult, mirror_point, switch_rate
from ._checks import as_run, as_runs, as_series
from .style import look, pair_label, sensor_label
from .tracking import (
    STRATEGY_LABELS,
    cov_ellipse,
    draw_pair_overlay,
    draw_published_overlay,
    draw_sensors,
    draw_snapshot,
)

__all__ = ["RING_SCENES", "plot_ring_overlap", "plot_snapshots", "plot_replayed_paths",
           "plot_fig5", "plot_fig5_replayed", "plot_fig6", "plot_fig6_replayed",
           "plot_monte_carlo", "plot_lost_run", "plot_switch_rate"]

#: The intuition's two pairs, seen from a target at the origin: rows at a right angle, and rows
#: almost parallel (the target nearly on the line through the sensors).
RING_SCENES = {"(a) directions at a right angle": [[-3.0, 0.0], [0.0, -3.0]],
               "(b) directions almost parallel": [[-3.0, 0.0], [3.0, 0.8]]}

_QUANTITIES = {"bound": "lower bound on C⁻¹", "error": "error ε (length unit)",
               "trace_cov": "trace Σ (length unit²)"}


def _pair_index(pairs, n: int) -> np.ndarray:
    """Each step's pair as its index among the pairs ``(i, j)``, ``i < j``, of ``n`` sensors
    (the y value of Fig. 5(a))."""
    all_pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    return np.array([all_pairs.index(tuple(p)) for p in pairs])


def _partner(pairs, anchor: int) -> np.ndarray:
    """Each step's partner of the fixed sensor ``anchor``, 1-based (the y value of Fig. 5(b))."""
    return np.where(pairs[:, 0] == anchor, pairs[:, 1], pairs[:, 0]) + 1


def plot_ring_overlap(noise_std: float, u_max: float = 1.0):
    r"""Which pair sees the target best: for each pair of :data:`RING_SCENES`, the two range
    circles through the target, the grid points where both measured ranges agree with the
    target's within two standard deviations (range noise ``noise_std`` on the half-squared
    range, divided by the range), the baseline through the sensors and the target's mirror
    image across it. The titles give the pair's bound for ``u_max``.

    Examples
    --------
    >>> fig = plot_ring_overlap(noise_std=0.5)
    >>> fig.axes[0].get_title().splitlines()[0]
    '(a) directions at a right angle'
    """
    import matplotlib.pyplot as plt

    noise = as_nonnegative(noise_std, "noise_std")
    u_max = as_positive(u_max, "u_max")
    o = np.zeros(2)
    grid = np.linspace(-4.5, 4.5, 601)
    GX, GY = np.meshgrid(grid, grid)
    fig, axes = plt.subplots(1, 2, figsize=(7.5, 4.2))
    t = np.linspace(0, 2 * np.pi, 400)
    for ax, (title, P) in zip(axes, RING_SCENES.items()):
        P = np.array(P)
        overlap = np.ones(GX.shape, dtype=bool)
        for p in P:
            d = np.linalg.norm(o - p)
            overlap &= np.abs(np.hypot(GX - p[0], GY - p[1]) - d) <= 2 * noise / d
        mirror = mirror_point(o[None], P[0], P[1])[0]
        for n, p in enumerate(P):
            rad = np.linalg.norm(o - p)
            ax.plot(p[0] + rad * np.cos(t), p[1] + rad * np.sin(t), color="0.45", lw=0.8,
                    label="range circle" if n == 0 else None)
        ax.contourf(GX, GY, overlap.astype(float), levels=[0.5, 1.5],
                    colors=[look("ellipse").color], alpha=0.55)
        ax.fill([], [], color=look("ellipse").color, alpha=0.55, label="both rings agree")
        ax.axline(P[0], P[1], color="0.45", ls=":", lw=1, label="baseline")
        draw_sensors(ax, P, label="sensors")
        ax.plot(*o, **look("target").kw(ms=7))
        ax.plot(*mirror, marker="*", ms=7, mfc="none", mec="k", ls="none",
                label="mirror image")
        bound = lower_bound(P, o, u_max)
        ax.set_title(f"{title}\nbound {number(bound, math=False)}")
        ax.set_aspect("equal")
        ax.set_xlim(-4.5, 4.5)
        ax.set_ylim(-4.5, 4.5)
        ax.set_xlabel("x (length unit)")
    axes[0].set_ylabel("y (length unit)")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=3)
    return fig


def plot_snapshots(run, steps):
    """Fig. 4: six moments of a run (the 1-based ``steps``, at most six), each the sensors, the
    path so far, the estimate with its 99.73 % ellipse and the chosen pair
    (:func:`obslib.viz.tracking.draw_snapshot`), on common axes that hold every snapshot.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> run = tracking.simulate(setup, "best-pair", seed=0)
    >>> fig = plot_snapshots(run, [1, 5])
    >>> sum(ax.axison for ax in fig.axes)
    2
    """
    import matplotlib.pyplot as plt

    r1 = as_run(run, "run")
    steps = as_ints(steps, "steps", 1)
    if len(steps) > 6 or max(steps) > r1.steps:
        raise ValueError(f"steps must be at most six steps of the run's {r1.steps}, got {steps}")
    S = r1.setup.sensor_array
    fig, axes = plt.subplots(2, 3, figsize=(7.5, 4.9))
    # limits that hold every snapshot's path, estimate and whole 99.73 % ellipse
    ells = [cov_ellipse(r1.estimate[k - 1], r1.cov[k - 1]) for k in steps]
    pts = np.vstack([S, r1.truth, r1.estimate, *ells])
    lo, hi = pts.min(axis=0) - 0.5, pts.max(axis=0) + 0.5
    for ax, k in zip(axes.flat, steps):
        draw_snapshot(ax, r1, k, legend=False)
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
    for ax in list(axes.flat)[len(steps):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("x (length unit)")
    for ax in axes[:, 0]:
        ax.set_ylabel("y (length unit)")
    fig.legend(*axes.flat[0].get_legend_handles_labels(), loc="outside lower center", ncol=5)
    return fig


def _published_iv(published, replays, n_published: int | None = None):
    published = as_runs(published, "published", PublishedRun, n_published)
    replays = as_runs(replays, "replays", TrackingResult)
    missing = set(replays) - set(published)
    if missing:
        raise ValueError(f"replays has strategies the published runs do not: {sorted(missing)}")
    return published, replays


def plot_replayed_paths(published, replays):
    """The published paths of strategies (1) and (2) (wide and pale) under their replays with
    the published noise (thin): the target and the estimate, one panel per strategy.

    ``published`` and ``replays`` map strategies to the published runs
    (:func:`obslib.published_runs.published_run`) and to their replays
    (:func:`obslib.studies.replay.replay`); each replay is drawn over its published run.

    Examples
    --------
    >>> from obslib.published_runs import published_run
    >>> from obslib.studies.replay import replay
    >>> names = ("best-pair", "best-partner")
    >>> pub = {s: published_run(s) for s in names}
    >>> fig = plot_replayed_paths(pub, {s: replay(s) for s in names})
    >>> [ax.get_title() for ax in fig.axes]
    ['(1) best pair', '(2) best partner of s₂']
    """
    import matplotlib.pyplot as plt

    pub, rep = _published_iv(published, replays)
    if len(rep) != 2:
        raise ValueError(f"replays must hold two strategies, got {len(rep)}")
    fig, axes = plt.subplots(1, 2, figsize=(7.5, 4.3))
    for ax, (s, run) in zip(axes, rep.items()):
        draw_sensors(ax, run.setup.sensor_array)
        draw_published_overlay(ax, pub[s].truth, run.truth, color="0.35", label="target")
        draw_published_overlay(ax, pub[s].estimate, run.estimate, color=look(s).color,
                               label=f"estimate {STRATEGY_LABELS[s][:3]}")
        ax.set_aspect("equal")
        ax.set_title(STRATEGY_LABELS[s])
        ax.set_xlabel("x (length unit)")
    axes[0].set_ylabel("y (length unit)")
    h0, l0 = axes[0].get_legend_handles_labels()
    h1, l1 = axes[1].get_legend_handles_labels()
    fig.legend(h0 + h1[2:], l0 + l1[2:], loc="outside lower center", ncol=3)
    return fig


def _partner_ticks(ax, setup) -> None:
    """The y ticks of Fig. 5(b): every sensor but the fixed one."""
    others = [j for j in range(setup.n_sensors) if j != setup.anchor]
    ax.set_yticks([j + 1 for j in others], [sensor_label(j) for j in others])
    ax.set_xlabel("step k")
    ax.set_ylabel("partner of s₂")
    ax.set_title("(b) strategy 2: partner of s₂")


def plot_fig5(best_pair, best_partner):
    """Fig. 5: (a) the pair strategy (1) takes at each step (one run, ``best_pair``), (b) the
    partner strategy (2) gives the fixed sensor (``best_partner``).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> r1 = tracking.simulate(setup, "best-pair", seed=0)
    >>> r2 = tracking.simulate(setup, "best-partner", seed=0)
    >>> [ax.get_ylabel() for ax in plot_fig5(r1, r2).axes]
    ['chosen pair', 'partner of s₂']
    """
    import matplotlib.pyplot as plt

    r1, r2 = as_run(best_pair, "best_pair"), as_run(best_partner, "best_partner")
    k = np.arange(1, r1.steps + 1)
    idx = _pair_index(r1.pairs, r1.setup.n_sensors)
    used = sorted(set(idx))
    partner = _partner(r2.pairs, r2.setup.anchor)
    all_pairs = [(i, j) for i in range(r1.setup.n_sensors)
                 for j in range(i + 1, r1.setup.n_sensors)]
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.8))
    ax0.plot(k, idx, ".", ms=3)
    ax0.set_yticks(used, [pair_label(*all_pairs[u]) for u in used])
    ax0.set_xlabel("step k")
    ax0.set_ylabel("chosen pair")
    ax0.set_title("(a) strategy 1: best pair")
    ax1.plot(np.arange(1, r2.steps + 1), partner, ".", ms=3, color=look("best-partner").color)
    _partner_ticks(ax1, r2.setup)
    return fig


def plot_fig5_replayed(published, replays):
    """Fig. 5 of the published runs (large pale circles) under their replays (small dots):
    (a) strategy (1)'s pair, (b) strategy (2)'s partner of the fixed sensor.

    ``published`` and ``replays`` map ``"best-pair"`` and ``"best-partner"`` to the published
    runs and to their replays.

    Examples
    --------
    >>> from obslib import published_runs
    >>> from obslib.studies import replay
    >>> names = ("best-pair", "best-partner")
    >>> logs = {s: published_runs.published_run(s) for s in names}
    >>> fig = plot_fig5_replayed(logs, {s: replay.replay(s) for s in names})
    >>> fig.axes[0].get_title()
    '(a) strategy 1: best pair'
    """
    import matplotlib.pyplot as plt

    pub, rep = _published_iv(published, replays)
    s1, s2 = "best-pair", "best-partner"
    if set(rep) != {s1, s2}:
        raise ValueError(f"replays must hold {s1!r} and {s2!r}, got {sorted(rep)}")
    n = rep[s1].setup.n_sensors
    all_pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
    anchor = rep[s2].setup.anchor
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 4.0))
    draw_pair_overlay(ax0, _pair_index(pub[s1].pairs, n), _pair_index(rep[s1].pairs, n),
                      color=look(s1).color, label="(a) pair")
    used = sorted(set(_pair_index(pub[s1].pairs, n)))
    ax0.set_yticks(used, [pair_label(*all_pairs[u]) for u in used])
    ax0.set_xlabel("step k")
    ax0.set_ylabel("chosen pair")
    ax0.set_title("(a) strategy 1: best pair")
    draw_pair_overlay(ax1, _partner(pub[s2].pairs, anchor), _partner(rep[s2].pairs, anchor),
                      color=look(s2).color, label="(b) partner")
    _partner_ticks(ax1, rep[s2].setup)
    for ax in (ax0, ax1):
        ax.margins(x=0.02, y=0.08)
    h0, l0 = ax0.get_legend_handles_labels()
    h1, l1 = ax1.get_legend_handles_labels()
    fig.legend(h0 + h1, l0 + l1, loc="outside lower center", ncol=2)
    return fig


def _fig6_axes(fig, axes, strategies, ncol: int) -> None:
    """Fig. 6's panels: one strategy each (its name above), steps along, values from 0 to 1.05,
    and one legend below."""
    for ax, s in zip(axes, strategies):
        ax.set_title(STRATEGY_LABELS[s])
        ax.set_xlabel("step k")
        ax.set_ylim(0, 1.05)
    axes[0].set_ylabel("value")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=ncol)


def plot_fig6(runs):
    """Fig. 6: the bound, the error and the trace of the covariance over time, one panel per
    strategy of ``runs`` (strategy -> one run).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> runs = {s: tracking.simulate(setup, s, seed=0)
    ...         for s in tracking.STRATEGIES}
    >>> [ax.get_title() for ax in plot_fig6(runs).axes][:1]
    ['(1) best pair']
    """
    import matplotlib.pyplot as plt

    runs = as_runs(runs, "runs", n=3)
    for run in runs.values():
        as_run(run, "runs")
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.4), sharey=True)
    for ax, run in zip(axes, runs.values()):
        k = np.arange(1, run.steps + 1)
        for f, name in _QUANTITIES.items():
            ax.plot(k, getattr(run, f), label=name)
    _fig6_axes(fig, axes, runs, ncol=3)
    return fig


def plot_fig6_replayed(published, replays):
    """Fig. 6 of the published runs (wide and pale) under their replays (thin), one panel per
    strategy; strategy (3), which has no replay, shows its log only.

    ``published`` maps the three strategies to their published runs, ``replays`` those
    replayed to their replays.

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.published_runs import published_run
    >>> from obslib.studies.replay import replay
    >>> pub = {s: published_run(s) for s in tracking.STRATEGIES}
    >>> fig = plot_fig6_replayed(pub, {"best-pair": replay("best-pair")})
    >>> fig.axes[2].get_title()
    '(3) fixed pair (s₂, s₁)'
    """
    import matplotlib.pyplot as plt

    pub, rep = _published_iv(published, replays, n_published=3)
    kp = np.arange(1, pub["best-pair"].steps + 1)
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.8), sharey=True)
    for ax, s in zip(axes, STRATEGIES):
        colors = ("C0", "C1", "C2")  # the palette
        for (f, name), c in zip(_QUANTITIES.items(), colors):
            ours = getattr(rep[s], f) if s in rep else None  # strategy 3: log only
            draw_published_overlay(ax, getattr(pub[s], f), ours, x=kp, color=c, label=name)
    _fig6_axes(fig, axes, STRATEGIES, ncol=2)
    return fig


def plot_monte_carlo(stats, steps: int):
    """The strategies over many noise seeds: the mean over the seeds at each step of the bound,
    the error and the trace, with a band of one standard deviation.

    ``stats`` maps each strategy to its statistics (the ``"strategies"`` of
    :func:`obslib.tracking.compare_strategies`): ``step_mean_<q>`` and ``step_sd_<q>`` for
    ``q`` in bound, error, trace, each with ``steps`` values.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> mc = tracking.monte_carlo(setup, n_seeds=3)
    >>> stats = tracking.compare_strategies(mc)["strategies"]
    >>> [ax.get_ylabel() for ax in plot_monte_carlo(stats, 5).axes][:1]
    ['lower bound on C⁻¹']
    """
    import matplotlib.pyplot as plt

    stats = as_mapping(stats, "stats")
    steps = as_int(steps, "steps", 1)
    series = {}
    for s, d in stats.items():
        if s not in STRATEGIES:
            raise ValueError(f"stats: unknown strategy {s!r}; known: {STRATEGIES}")
        d = as_mapping(d, "stats")
        for key in ("bound", "error", "trace"):
            for stat in ("mean", "sd"):
                name = f"step_{stat}_{key}"
                if name not in d:
                    raise ValueError(f"stats of {s!r} have no {name!r}")
                series[s, stat, key] = as_series(d[name], "stats", steps)
    k = np.arange(1, steps + 1)
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.4))
    for s in (s for s in STRATEGIES if s in stats):
        color = look(s).color
        for ax, key in zip(axes, ("bound", "error", "trace")):
            m, sd = series[s, "mean", key], series[s, "sd", key]
            ax.plot(k, m, color=color, label=STRATEGY_LABELS[s], lw=1.2)
            lo_band = np.maximum(m - sd, 0)
            ax.fill_between(k, lo_band, m + sd, color=color, alpha=0.15, lw=0)
    ylabels = ("lower bound on C⁻¹", "error ε (length unit)", "trace Σ (length unit²)")
    for ax, ylabel in zip(axes, ylabels):
        ax.set_ylabel(ylabel)
        ax.set_xlabel("step k")
    axes[1].set_ylim(0, 2.5)
    axes[2].set_ylim(0, 0.6)
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=3)
    return fig


def plot_lost_run(batch, lost):
    """Strategy (3)'s lost runs: the histogram of the runs' mean errors (left), and the first
    lost run's path, estimate and mirror image across the fixed pair's baseline (right).

    ``batch`` holds the runs of the fixed pair, ``lost`` marks the lost ones (a bool per run,
    :func:`obslib.tracking.track_loss`).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> batch = tracking.simulate_batch(setup, "fixed-pair", seeds=range(3))
    >>> fig = plot_lost_run(batch, [False, True, False])
    >>> fig.axes[1].get_legend_handles_labels()[1][1]
    'estimate (seed 1)'
    """
    import matplotlib.pyplot as plt

    f3 = as_instance(batch, BatchResult, "batch")
    if isinstance(lost, (list, tuple)):
        lost = np.array(lost)
    if not isinstance(lost, np.ndarray) or lost.dtype != bool or lost.shape != (f3.n_runs,):
        raise ValueError(f"lost must be one bool per run ({f3.n_runs}), got {lost!r}")
    S = f3.setup.sensor_array
    a, b = S[0], S[1]
    run_err = f3.error.mean(axis=1)
    color = look("fixed-pair").color
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.6),
                                   gridspec_kw={"width_ratios": [1, 1.1]})
    ax0.hist(run_err, bins=40, color=color)
    ax0.set_xlabel("run-mean error of\nstrategy 3 (length unit)")
    ax0.set_ylabel("runs")
    if lost.any():
        i = int(np.flatnonzero(lost)[0])
        ax1.plot(*f3.truth[i].T, **look("truth").kw())
        ax1.plot(*f3.estimate[i].T, color=look("estimate").color, lw=0.8,
                 label=f"estimate (seed {f3.seeds[i]})")
        ax1.plot(*mirror_point(f3.truth[i], a, b).T, "k:", lw=0.8,
                 label="mirror image of the path")
    ax1.axline(a, b, color=color, lw=0.8, label="baseline s₁s₂")
    draw_sensors(ax1, S[:2])
    ax1.set_aspect("equal")
    ax1.set_xlabel("x (length unit)")
    ax1.set_ylabel("y (length unit)")
    fig.legend(*ax1.get_legend_handles_labels(), loc="outside right center")
    return fig


def plot_switch_rate(batch, run, window):
    """How often strategy (1) changes pair: at each transition :math:`k \\to k+1` the fraction
    of the runs of ``batch`` that switch, the 9-step running mean of one ``run``'s switches, and
    the transitions of ``window`` ``(first, last)`` shaded.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> batch = tracking.simulate_batch(setup, "best-pair", seeds=range(3))
    >>> fig = plot_switch_rate(batch, batch.run(0), (5, 10))
    >>> fig.axes[0].get_xlabel()
    'transition k → k+1'
    """
    import matplotlib.pyplot as plt

    mc = as_instance(batch, BatchResult, "batch")
    r1 = as_run(run, "run")
    lo_k, hi_k = as_int_range(window, "window", 1)
    if r1.steps != mc.steps:
        raise ValueError(f"run has {r1.steps} steps, batch {mc.steps}")
    rate = switch_rate(mc)
    one = r1.switched
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    kt = np.arange(1, mc.steps)
    ax.plot(kt, rate, lw=1, color=look("best-pair").color,
            label=f"fraction of {mc.n_runs} runs switching")
    smooth = np.convolve(one, np.ones(9) / 9, mode="same")
    ax.plot(kt, smooth, lw=1, color="k", alpha=0.6, label=f"seed {r1.seed}: 9-step running mean")
    ax.axvspan(lo_k, hi_k, color=look("estimate").color, alpha=0.1,
               label=f"k = {lo_k} to {hi_k}")
    ax.set_xlabel("transition k → k+1")
    ax.set_ylabel("switch rate (per transition)")
    fig.legend(loc="outside lower center", ncol=3)
    return fig
