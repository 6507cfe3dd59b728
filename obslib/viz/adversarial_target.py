"""Figures of the adversarial target (Section V-B, Fig. 7): the bound over the plane, one run and
the published run under its replay, the target against each strategy, the runs' mean bounds and
end points, and the stronger adversaries.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_instance, as_int, as_mapping
from ..bounds import pair_bounds
from ..published_runs import PublishedRun
from ..tracking import BatchResult, TrackingSetup
from ._checks import as_run, as_runs, as_series
from .style import look
from .tracking import (
    STRATEGY_LABELS,
    draw_published_overlay,
    draw_sensors,
    draw_switch_overlay,
)

__all__ = ["ADVERSARY_LABELS", "bound_landscapes", "plot_landscapes", "plot_fig7",
           "plot_fig7_replayed", "plot_against_strategies", "plot_run_means",
           "plot_adversaries"]

#: How the chapter names the adversaries of
#: :func:`obslib.studies.adversarial_target.adversary_variants`.
ADVERSARY_LABELS = {"paper": "the paper's", "next-pair": "knowing the next pair",
                    "disc": "the whole disc", "disc, next-pair": "both"}


def bound_landscapes(setup, n: int = 200) -> dict:
    """Theorem 4's bound over the plane (Euclidean distances, the target's ``u_max``) on an
    ``n`` by ``n`` grid of the square from -4.02 to 6.02 (a grid that misses the sensors): of the
    setup's fixed pair, and of the best of all pairs at each point.

    Returns
    -------
    dict
        ``x``, ``y``: the grid; ``fixed``, ``best``: the two bounds on it.

    Examples
    --------
    >>> from obslib import tracking
    >>> land = bound_landscapes(tracking.PAPER_ADVERSARIAL, n=5)
    >>> land["best"].shape, bool((land["best"] >= land["fixed"]).all())
    ((5, 5), True)
    """
    setup = as_instance(setup, TrackingSetup, "setup")
    grid = np.linspace(-4.02, 6.02, as_int(n, "n", 2))
    GX, GY = np.meshgrid(grid, grid)
    W = pair_bounds(setup.sensor_array, np.column_stack([GX.ravel(), GY.ravel()]), setup.u_max)
    return {"x": GX, "y": GY, "fixed": W[setup.fixed_pair].reshape(GX.shape),
            "best": W.max(axis=(0, 1)).reshape(GX.shape)}


def plot_landscapes(setup, landscapes: dict):
    """A target that fights back: the bound over the plane (:func:`bound_landscapes`) of (a) the
    fixed pair and (b) the best of all pairs, with the sensors and the target's start.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL
    >>> fig = plot_landscapes(setup, bound_landscapes(setup, n=20))
    >>> fig.axes[1].get_title()
    '(b) the best of the 15 pairs'
    """
    import matplotlib.pyplot as plt

    setup = as_instance(setup, TrackingSetup, "setup")
    land = as_mapping(landscapes, "landscapes")
    if set(land) != {"x", "y", "fixed", "best"}:
        raise ValueError("landscapes must hold x, y, fixed and best (bound_landscapes)")
    shape = np.shape(land["x"])
    if len(shape) != 2 or any(np.shape(land[k]) != shape for k in ("y", "fixed", "best")):
        raise ValueError("landscapes must hold four arrays of one two-dimensional shape")
    S = setup.sensor_array
    n = setup.n_sensors
    fig, axes = plt.subplots(1, 2, figsize=(7.5, 3.9), sharey=True)
    levels = np.linspace(0, 1, 11)
    titles = ("(a) the fixed pair (s₂, s₁)", f"(b) the best of the {n * (n - 1) // 2} pairs")
    for ax, Z, title in zip(axes, (land["fixed"], land["best"]), titles):
        filled = ax.contourf(land["x"], land["y"], Z, levels=levels, cmap="viridis", alpha=0.85)
        draw_sensors(ax, S, label="sensors")
        ax.plot(*setup.start, **look("start").kw(ms=8, mec="w", label="the target's start"))
        ax.set_aspect("equal")
        ax.set_title(title)
        ax.set_xlabel("x (length unit)")
    axes[0].axline(S[0], S[1], color="w", ls=":", lw=1.2, label="line through s₁ and s₂")
    axes[0].set_ylabel("y (length unit)")
    fig.colorbar(filled, ax=axes, label="bound on C⁻¹")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=3,
               facecolor="0.85")
    return fig


def _legend_below(fig, ax0, ax1, ncol: int) -> None:
    """One legend below the figure with the entries of both axes."""
    h0, l0 = ax0.get_legend_handles_labels()
    h1, l1 = ax1.get_legend_handles_labels()
    fig.legend(h0 + h1, l0 + l1, loc="outside lower center", ncol=ncol)


def plot_fig7(run):
    """Fig. 7: one run against the adversary, (a) the target's and the estimate's paths, (b) the
    sensors' bound and the exact :math:`C^{-1}` they face over time, with the pair switches.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=5)
    >>> fig = plot_fig7(tracking.simulate(setup, "best-pair", seed=0))
    >>> fig.axes[1].get_title()
    '(b) observability over time'
    """
    import matplotlib.pyplot as plt

    adv = as_run(run, "run")
    k = np.arange(1, adv.steps + 1)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 4.0),
                                   gridspec_kw={"width_ratios": [1, 1.5]})
    draw_sensors(ax0, adv.setup.sensor_array)
    ax0.plot(*adv.truth.T, color="k", lw=1, label="target")
    ax0.plot(*adv.estimate.T, color=look("estimate").color, lw=0.6, alpha=0.7,
             label="estimate")
    ax0.plot(*adv.truth[0], **look("start").kw(ms=6))
    ax0.plot(*adv.truth[-1], "ks", ms=6, label="end")
    ax0.set_aspect("equal")
    ax0.set_title("(a) trajectories")
    ax0.set_xlabel("x (length unit)")
    ax0.set_ylabel("y (length unit)")
    ax1.plot(k, adv.bound, lw=1, label="sensors' lower bound on C⁻¹ (at ô)")
    ax1.plot(k[1:], adv.true_icn[1:], lw=1, label="exact C⁻¹(Oᵢⱼ(oₖ, uₖ₋₁))")
    sw = np.flatnonzero(adv.switched) + 2
    ax1.plot(sw, np.full(sw.size, -0.03), "|", color="k", ms=4, label="pair switch")
    ax1.set(ylim=(-0.06, 1.0), xlabel="step k", ylabel="inverse condition number",
            title="(b) observability over time")
    _legend_below(fig, ax0, ax1, 4)
    return fig


def plot_fig7_replayed(published, replay):
    """The published run of Fig. 7 (wide and pale) under its replay (thin): (a) the paths of the
    estimate and the target, (b) the sensors' bound and the pair switches.

    Examples
    --------
    >>> from obslib.published_runs import published_run
    >>> from obslib.studies.replay import replay
    >>> pub, rep = published_run("adversarial"), replay("adversarial")
    >>> fig = plot_fig7_replayed(pub, rep)
    >>> fig.axes[0].get_title()
    '(a) trajectories'
    """
    import matplotlib.pyplot as plt

    pub = as_instance(published, PublishedRun, "published")
    rep = as_run(replay, "replay")
    if rep.steps != pub.steps:
        raise ValueError(f"replay has {rep.steps} steps, the published run {pub.steps}")
    pub_switched = (pub.pairs[1:] != pub.pairs[:-1]).any(axis=1)
    kp = np.arange(1, pub.steps + 1)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 4.2),
                                   gridspec_kw={"width_ratios": [1, 1.5]})
    draw_sensors(ax0, rep.setup.sensor_array)
    draw_published_overlay(ax0, pub.estimate, rep.estimate, color=look("estimate").color,
                           label="estimate")
    draw_published_overlay(ax0, pub.truth, rep.truth, color="k", label="target")
    ax0.set_aspect("equal")
    ax0.set_title("(a) trajectories")
    ax0.set_xlabel("x (length unit)")
    ax0.set_ylabel("y (length unit)")
    draw_published_overlay(ax1, pub.bound, rep.bound, x=kp, color=look("best-pair").color,
                           label="sensors' bound")
    draw_switch_overlay(ax1, pub_switched, rep.switched, y=-0.03)
    ax1.set_ylim(-0.07, 1.05)
    ax1.set_xlabel("step k")
    ax1.set_ylabel("lower bound on C⁻¹")
    ax1.set_title("(b) the sensors' bound and pair switches")
    _legend_below(fig, ax0, ax1, 3)
    return fig


def plot_against_strategies(runs):
    """The adversary against each strategy of ``runs`` (strategy -> one run): the target's paths
    and the exact :math:`C^{-1}` the sensors face (log scale).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=5)
    >>> arms = {s: (setup, s) for s in tracking.STRATEGIES}
    >>> batches = tracking.simulate_many(arms, seeds=[0])
    >>> fig = plot_against_strategies({s: b.run(0) for s, b in batches.items()})
    >>> fig.axes[0].get_title()
    "the target's paths"
    """
    import matplotlib.pyplot as plt

    runs = as_runs(runs, "runs")
    for run in runs.values():
        as_run(run, "runs")
    if not runs:
        raise ValueError("runs must hold at least one strategy")
    first = next(iter(runs.values()))
    k = np.arange(1, first.steps + 1)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.9),
                                   gridspec_kw={"width_ratios": [1, 1.5]})
    draw_sensors(ax0, first.setup.sensor_array)
    for s, run in runs.items():
        color = look(s).color
        ax0.plot(*run.truth.T, lw=1, color=color, label=STRATEGY_LABELS[s])
        ax1.semilogy(k[1:], run.true_icn[1:], lw=0.8, color=color, label=STRATEGY_LABELS[s])
    ax0.plot(*first.setup.start, **look("start").kw(ms=6))
    ax0.set_aspect("equal")
    ax0.set_title("the target's paths")
    ax0.set_xlabel("x (length unit)")
    ax0.set_ylabel("y (length unit)")
    ax1.set_xlabel("step k")
    ax1.set_ylabel("exact C⁻¹ (log scale)")
    ax1.set_title("the exact C⁻¹ the sensors face")
    ax1.yaxis.set_major_formatter(lambda v, _: f"{v:g}")  # plain decimals, no mathtext
    fig.legend(*ax0.get_legend_handles_labels(), loc="outside lower center", ncol=2)
    return fig


def plot_run_means(batch, bound_means):
    """Many runs against the adversary: the histogram of the runs' mean bounds
    (``bound_means``, one per run) against the published run's, and where each run ends,
    coloured by its mean bound.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=5)
    >>> batch = tracking.simulate_batch(setup, "best-pair", seeds=range(3))
    >>> fig = plot_run_means(batch, batch.bound.mean(axis=1))
    >>> fig.axes[0].get_xlabel()
    'mean bound of a run'
    """
    import matplotlib.pyplot as plt

    from ..studies.published import PUBLISHED_ADVERSARIAL

    mcb = as_instance(batch, BatchResult, "batch")
    per_run = as_series(bound_means, "bound_means", mcb.n_runs)
    ends = mcb.truth[:, -1]
    published = PUBLISHED_ADVERSARIAL["mean_bound"]
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.8))
    ax0.hist(per_run, bins=30, color=look("best-pair").color)
    ax0.axvline(published, color="k", ls="--", label="published run")
    ax0.set_xlabel("mean bound of a run")
    ax0.set_ylabel("runs")
    ax0.set_xlim(right=max(per_run.max(), published) + 0.02)
    draw_sensors(ax1, mcb.setup.sensor_array)
    sc = ax1.scatter(*ends.T, c=per_run, s=14, cmap="viridis", label="end of run")
    ax1.plot(*mcb.setup.start, **look("start").kw(ms=6))
    ax1.set_aspect("equal")
    ax1.set_xlabel("x (length unit)")
    ax1.set_ylabel("y (length unit)")
    fig.colorbar(sc, ax=ax1, label="mean bound of the run")
    _legend_below(fig, ax0, ax1, 3)
    return fig


def plot_adversaries(batches):
    """The exact :math:`C^{-1}` the sensors face in the first run against each adversary of
    ``batches`` (a name of :data:`ADVERSARY_LABELS` -> its runs).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=5)
    >>> batch = tracking.simulate_batch(setup, "best-pair", seeds=range(2))
    >>> plot_adversaries({"paper": batch}).axes[0].get_ylabel()
    'exact C⁻¹'
    """
    import matplotlib.pyplot as plt

    batches = as_mapping(batches, "batches")
    for name, b in batches.items():
        if name not in ADVERSARY_LABELS:
            raise ValueError(f"batches: unknown adversary {name!r}; "
                             f"known: {tuple(ADVERSARY_LABELS)}")
        as_instance(b, BatchResult, "batches")
    fig, ax = plt.subplots(figsize=(7.5, 3.4))
    for name, b in batches.items():
        run = b.run(0)
        k = np.arange(1, run.steps + 1)
        ax.plot(k[1:], run.true_icn[1:], lw=0.8, label=ADVERSARY_LABELS[name])
    ax.set_xlabel("step k")
    ax.set_ylabel("exact C⁻¹")
    ax.set_ylim(0, 1)
    fig.legend(loc="outside lower center", ncol=4)
    return fig
