"""Figures of many targets in closed loop (the authors' later experiment and larger networks):
why a pair chosen afresh beats one kept, what a step without a sensor does to a covariance,
snapshots of the assignment as the authors' figures show them, the saved runs against ours, the
per-run means of every assignment, and an animation of two runs side by side.

Runs are :class:`obslib.tracking.TargetsResult` (one run) or :class:`obslib.tracking.TargetsBatch`
(many); assignments are named by their looks in :mod:`obslib.viz.style`, targets by
:func:`~obslib.viz.style.target_label` and drawn in the colours of :data:`TARGET_COLOURS`.
"""

from __future__ import annotations

import numpy as np

from .._validate import (
    as_float_array,
    as_instance,
    as_int,
    as_ints,
    as_mapping,
    as_positive,
    as_str,
)
from ..later_experiment import SavedLaterRun
from ..tracking import TargetsBatch, TargetsResult
from ._checks import as_series
from .style import OKABE_ITO, as_axes, as_figsize, look, target_label
from .tracking import RunAnimation, cov_ellipse, draw_sensors

__all__ = ["TARGET_COLOURS", "assignment_label", "plot_fixed_against_rechosen",
           "plot_unobserved_growth", "draw_targets", "plot_assignment_snapshots",
           "plot_saved_runs", "plot_run_means", "animate_targets"]

#: The colours of the targets on a map (the authors' figures colour each target apart).
TARGET_COLOURS = (OKABE_ITO["blue"], OKABE_ITO["vermillion"], OKABE_ITO["bluish green"],
                  OKABE_ITO["reddish purple"], OKABE_ITO["orange"], OKABE_ITO["sky blue"])


def _colour(l: int) -> str:
    return TARGET_COLOURS[l % len(TARGET_COLOURS)]


def assignment_label(name: str) -> str:
    """The legend label of an assignment (its look's).

    Examples
    --------
    >>> assignment_label("unique-pairs")
    'unique pairs (Algorithm 1)'
    """
    return look(as_str(name, "name")).label


def _one_run(run, name: str) -> TargetsResult:
    as_instance(run, TargetsResult, name)
    if isinstance(run, TargetsBatch):
        raise ValueError(f"{name} must be one run, not a batch of runs (take .run(b))")
    return run


# --------------------------------------------------------------------------------------------
# Intuition
# --------------------------------------------------------------------------------------------


def plot_fixed_against_rechosen(steps, fixed, rechosen, fixed_label: str, target: int = 0):
    """The bound of a pair kept from the first of ``steps`` (``fixed``) and of the best pair
    chosen afresh at every step (``rechosen``) along one target's path. Returns the figure.

    Examples
    --------
    >>> fig = plot_fixed_against_rechosen([2, 3], [0.5, 0.2], [0.5, 0.4],
    ...                                   "(s₁, s₈)")
    >>> [line.get_label() for line in fig.axes[0].get_lines()]
    ['pair (s₁, s₈) kept from step 2', 'best pair chosen at every step']
    """
    import matplotlib.pyplot as plt

    k = as_series(steps, "steps")
    fixed = as_series(fixed, "fixed", k.size)
    rechosen = as_series(rechosen, "rechosen", k.size)
    as_str(fixed_label, "fixed_label")
    target = as_int(target, "target", 0)
    fig, ax = plt.subplots(figsize=(7.5, 3.0), layout="constrained")
    ax.plot(k, fixed, color=look("fixed-pair").color, lw=1.5,
            label=f"pair {fixed_label} kept from step {k[0]:g}")
    ax.plot(k, rechosen, color=look("unique-pairs").color, lw=1.5,
            label="best pair chosen at every step")
    ax.set_xlabel("step k")
    ax.set_ylabel("lower bound on C\u207b\u00b9")
    ax.set_ylim(0, 1.05 * max(float(rechosen.max()), float(fixed.max()), 0.1))
    ax.set_title(f"target {target_label(target)} on its circle")
    ax.legend(loc="lower left", fontsize=10)
    return fig


def plot_unobserved_growth(estimate, covs: dict, trace, observed):
    """What steps without a sensor do to a target's covariance: left, its 99.73 % ellipses
    about ``estimate`` (``covs``: label -> 2 x 2 covariance, drawn from the smallest to the
    largest); right, the trace of the covariance at each step of a schedule (``trace``), with
    the steps at which the target had no sensor (``observed`` false) marked. Returns the
    figure.

    Examples
    --------
    >>> import numpy as np
    >>> covs = {"after an update": 0.03 * np.eye(2),
    ...         "one step without": 0.23 * np.eye(2)}
    >>> fig = plot_unobserved_growth([0.0, 0.0], covs, [0.07, 0.47, 0.07],
    ...                              [True, False, True])
    >>> len(fig.axes), fig.axes[1].get_xlabel()
    (2, 'step k')
    """
    import matplotlib.pyplot as plt

    estimate = np.asarray(as_float_array(estimate, "estimate"), dtype=float)
    if estimate.shape != (2,) or not np.isfinite(estimate).all():
        raise ValueError(f"estimate must be a finite point (x, y), got shape {estimate.shape}")
    covs = as_mapping(covs, "covs")
    if not covs:
        raise ValueError("covs is empty")
    trace = as_series(trace, "trace")
    observed = np.asarray(observed)
    if observed.shape != trace.shape or observed.dtype != bool:
        raise ValueError("observed must be one bool per step of trace")
    fig, (ax, axt) = plt.subplots(1, 2, figsize=(7.5, 3.4), layout="constrained",
                                  gridspec_kw={"width_ratios": [1, 1.3]})
    shades = plt.get_cmap("viridis")(np.linspace(0.0, 0.85, len(covs)))
    for (label, cov), shade in zip(covs.items(), shades):
        ax.plot(*cov_ellipse(estimate, np.asarray(cov, dtype=float)).T, color=shade, lw=1.5,
                label=str(label))
    ax.plot(*estimate, **look("estimate").kw(ms=7, label="estimate"))
    ax.set_aspect("equal")
    ax.set_xlabel("x (length unit)")
    ax.set_ylabel("y (length unit)")
    ax.set_title("99.73 % ellipses")
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", fontsize=10, ncol=3)
    k = np.arange(1, trace.size + 1)
    axt.plot(k, trace, "-", color="0.5", lw=1.0)
    axt.plot(k[observed], trace[observed], "o", color=look("unique-pairs").color, ms=5,
             label="with a pair")
    axt.plot(k[~observed], trace[~observed], "o", mfc="none", color=look("e-optimal").color,
             ms=6, label="without a sensor")
    axt.set_ylim(0, 1.1 * float(trace.max()))
    axt.set_xlabel("step k")
    axt.set_ylabel("trace Σ (length unit²)")
    axt.set_title("trace after each step")
    axt.legend(loc="upper left", fontsize=10)
    return fig


# --------------------------------------------------------------------------------------------
# Maps: the assignment at a step
# --------------------------------------------------------------------------------------------


class _TargetArtists:
    """The moving artists of one map: per target its path so far, true position, estimate,
    99.73 % ellipse and the lines from its estimate to its sensors."""

    def __init__(self, ax, n_targets: int):
        self.lines = []
        for l in range(n_targets):
            c = _colour(l)
            path, = ax.plot([], [], ":", color=c, lw=1.2)
            true, = ax.plot([], [], "*", color=c, ms=10, mec="k", mew=0.5)
            est, = ax.plot([], [], "s", color=c, ms=5)
            ell, = ax.plot([], [], "-", color=c, lw=1.0)
            team, = ax.plot([], [], "-", color=c, lw=1.2, alpha=0.8)
            self.lines.append((path, true, est, ell, team))
        self.title = ax.set_title(" ", fontsize=10)

    @property
    def artists(self) -> tuple:
        return (*(a for t in self.lines for a in t), self.title)

    def update(self, run, k: int, title: str = "") -> None:
        i = k - 1
        S = run.setup.sensor_array
        for l, (path, true, est, ell, team) in enumerate(self.lines):
            e = run.estimate[i, l]
            path.set_data(*run.truth[: i + 1, l].T)
            true.set_data([run.truth[i, l, 0]], [run.truth[i, l, 1]])
            est.set_data([e[0]], [e[1]])
            ell.set_data(*cov_ellipse(e, run.cov[i, l]).T)
            members = np.flatnonzero(run.labels[i] == l)
            xs = [v for s in members for v in (e[0], S[s, 0], np.nan)]
            ys = [v for s in members for v in (e[1], S[s, 1], np.nan)]
            team.set_data(xs, ys)
        none = [target_label(l) for l in range(len(self.lines))
                if not (run.labels[i] == l).any()]
        text = f"{title}k = {k}" + (f", no sensor: {', '.join(none)}" if none else "")
        self.title.set_text(text)


def _map_limits(ax, runs, margin: float = 0.8) -> None:
    """Limits that hold every sensor, path and estimate, with room above for the sensors'
    names."""
    pts = np.vstack([np.vstack([r.setup.sensor_array, r.truth.reshape(-1, 2),
                                r.estimate.reshape(-1, 2)]) for r in runs])
    lo, hi = pts.min(axis=0) - margin, pts.max(axis=0) + margin
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1] + 0.6 * margin)
    ax.set_aspect("equal")


def _legend_handles(n_targets: int) -> list:
    from matplotlib.lines import Line2D

    handles = [Line2D([], [], ls="none", marker="*", color=_colour(l), mec="k", mew=0.5,
                      ms=10, label=f"target {target_label(l)}") for l in range(n_targets)]
    handles += [Line2D([], [], ls="none", marker="s", color="0.3", ms=5, label="estimate"),
                Line2D([], [], color="0.3", lw=1.2, label="to its sensors"),
                Line2D([], [], **look("sensor").kw(ms=8, label="sensors"))]
    return handles


def draw_targets(ax, run, k: int, *, title: str = ""):
    """Step ``k`` (1-based) of a run of many targets on ``ax``, as the authors' snapshots draw
    it: the sensors, each target's path so far, its true position (a star) and its estimate (a
    square) with the 99.73 % ellipse, and lines from the estimate to each sensor measuring it,
    in the target's colour; the title names the step and the targets without a sensor. Returns
    the axes.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET.first(5)
    >>> ax = Figure().add_subplot()
    >>> run = tracking.simulate_targets(su, "logdet-teams-exact")
    >>> _ = draw_targets(ax, run, 2)
    >>> ax.get_title()
    'k = 2, no sensor: t₂, t₃'
    """
    as_axes(ax)
    run = _one_run(run, "run")
    k = as_int(k, "k", 1)
    if k > run.steps:
        raise ValueError(f"k must be a step of the run, 1..{run.steps}, got {k}")
    as_str(title, "title")
    draw_sensors(ax, run.setup.sensor_array, ms=7)
    art = _TargetArtists(ax, run.n_targets)
    art.update(run, k, title)
    return ax


def plot_assignment_snapshots(run, steps):
    """The assignment of a run at six steps (the 1-based ``steps``, at most six), as the
    authors' snapshots show it (:func:`draw_targets`), on common axes. Returns the figure.

    Examples
    --------
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET.first(5)
    >>> run = tracking.simulate_targets(su, "unique-pairs")
    >>> fig = plot_assignment_snapshots(run, [1, 5])
    >>> sum(ax.axison for ax in fig.axes)
    2
    """
    import matplotlib.pyplot as plt

    run = _one_run(run, "run")
    steps = as_ints(steps, "steps", 1)
    if not steps or len(steps) > 6 or max(steps) > run.steps:
        raise ValueError(f"steps must be one to six steps of the run's {run.steps}, got {steps}")
    fig, axes = plt.subplots(2, 3, figsize=(7.5, 5.6), layout="constrained", sharex=True,
                             sharey=True)
    for n, ax in enumerate(axes.flat):
        if n >= len(steps):
            ax.axis("off")
            continue
        draw_targets(ax, run, steps[n])
        _map_limits(ax, [run])
        ax.set_xlabel("x (length unit)" if n >= 3 else "")
        ax.set_ylabel("y (length unit)" if n % 3 == 0 else "")
    fig.legend(handles=_legend_handles(run.n_targets), loc="outside lower center", ncol=3,
               fontsize=10)
    return fig


# --------------------------------------------------------------------------------------------
# The saved runs against ours
# --------------------------------------------------------------------------------------------


def plot_saved_runs(saved: dict, ours: dict):
    """The authors' saved runs (``saved``: assignment -> :class:`SavedLaterRun`) drawn over the
    middle 90 % of our runs of the same assignment (``ours``: assignment ->
    :class:`~obslib.tracking.TargetsBatch`): each target's error (top) and trace of the
    covariance (bottom, log scale) at every step, one column per assignment. Returns the
    figure.

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.later_experiment import saved_run
    >>> su = tracking.LATER_MULTI_TARGET
    >>> b = tracking.simulate_targets_batch(su, ["unique-pairs"], seeds=[0, 1])
    >>> fig = plot_saved_runs({"unique-pairs": saved_run("unique-pairs")}, b)
    >>> len(fig.axes)
    2
    """
    import matplotlib.pyplot as plt

    saved, ours = as_mapping(saved, "saved"), as_mapping(ours, "ours")
    if not saved or set(saved) != set(ours):
        raise ValueError(f"saved and ours must hold the same assignments, got {list(saved)} "
                         f"and {list(ours)}")
    for name in saved:
        as_instance(saved[name], SavedLaterRun, "saved")
        as_instance(ours[name], TargetsBatch, "ours")
        if ours[name].error.shape[1:] != saved[name].error.shape:
            raise ValueError(f"ours[{name!r}] must have the saved run's steps and targets")
    names = list(saved)
    fig, axes = plt.subplots(2, len(names), figsize=(7.5, 5.4), layout="constrained",
                             squeeze=False, sharex=True, sharey="row")
    for c, name in enumerate(names):
        s, b = saved[name], ours[name]
        k = np.arange(1, s.error.shape[0] + 1)
        for r, (qs, qb) in enumerate(((s.error, b.error), (s.trace_cov, b.trace_cov))):
            ax = axes[r, c]
            for l in range(qs.shape[1]):
                lo, hi = np.percentile(qb[:, :, l], [5, 95], axis=0)
                ax.fill_between(k, lo, hi, color=_colour(l), alpha=0.15, lw=0)
                ax.plot(k, qs[:, l], color=_colour(l), lw=1.0,
                        label=f"target {target_label(l)}, saved")
            if r == 1:
                ax.set_yscale("log")
                ax.set_xlabel("step k")
        axes[0, c].set_title(assignment_label(name))
    axes[0, 0].set_ylabel("error ε (length unit)")
    axes[1, 0].set_ylabel("trace Σ (length unit²)")
    from matplotlib.patches import Patch

    handles, _ = axes[0, 0].get_legend_handles_labels()
    handles.append(Patch(color="0.5", alpha=0.3, label="our runs, 5th to 95th percentile"))
    fig.legend(handles=handles, loc="outside lower center", ncol=2, fontsize=10)
    return fig


# --------------------------------------------------------------------------------------------
# Every assignment: the per-run means
# --------------------------------------------------------------------------------------------


def _hboxes(ax, data, names) -> None:
    """Horizontal box plots (whiskers at the 5th and 95th percentiles), one per assignment,
    filled in its look's colour, the first at the top."""
    from matplotlib.colors import to_rgba
    from matplotlib.ticker import FormatStrFormatter

    pos = np.arange(len(names), 0, -1)
    parts = ax.boxplot(data, positions=pos, orientation="horizontal", whis=(5, 95),
                       patch_artist=True, flierprops={"ms": 2}, medianprops={"color": "k"},
                       widths=0.6)
    for box, flier, name in zip(parts["boxes"], parts["fliers"], names):
        color = look(name).color
        box.set_facecolor(to_rgba(color, 0.45))
        box.set_edgecolor(color)
        flier.set_markeredgecolor(color)
    ax.set_yticks(pos, [assignment_label(n) for n in names])
    ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.grid(axis="x", alpha=0.3)


def plot_run_means(stats: dict, title: str = ""):
    """Per run, each assignment's error and trace of the covariance averaged over the steps
    after the first and over the targets (``stats``: assignment ->
    :func:`obslib.studies.many_targets.run_statistics`), as box plots: a box spans
    the middle half of the runs, its line is the median, the whiskers reach the 5th and 95th
    percentiles. Returns the figure.

    Examples
    --------
    >>> import numpy as np
    >>> s = {"mean_error": np.array([[0.2, 0.3], [0.25, 0.2]]),
    ...      "mean_trace": np.array([[0.07, 0.08], [0.07, 0.09]])}
    >>> fig = plot_run_means({"unique-pairs": s, "random": s})
    >>> [t.get_text() for t in fig.axes[0].get_yticklabels()]
    ['unique pairs (Algorithm 1)', 'random']
    """
    import matplotlib.pyplot as plt

    stats = as_mapping(stats, "stats")
    if not stats:
        raise ValueError("stats is empty")
    as_str(title, "title")
    names = list(stats)
    data = {}
    for key in ("mean_error", "mean_trace"):
        data[key] = []
        for n in names:
            a = as_float_array(as_mapping(stats[n], "stats")[key], f"stats[{n!r}][{key!r}]")
            if a.ndim != 2 or not np.isfinite(a).all() or (a <= 0).any():
                raise ValueError(f"stats[{n!r}][{key!r}] must be positive (runs, targets)")
            data[key].append(a.mean(axis=1))
    fig, (ax, axt) = plt.subplots(1, 2, figsize=(7.5, 0.38 * len(names) + 1.6),
                                  layout="constrained", sharey=True)
    _hboxes(ax, data["mean_error"], names)
    _hboxes(axt, data["mean_trace"], names)
    ax.set_xlabel("mean error ε (length unit)")
    axt.set_xlabel("mean trace Σ (length unit²)")
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


# --------------------------------------------------------------------------------------------
# Animation
# --------------------------------------------------------------------------------------------


def animate_targets(runs: dict, every: int = 2, dpi: int = 100, figsize=(7.5, 4.2),
                    interval=150):
    """An animation (:class:`obslib.viz.tracking.RunAnimation`) of runs of many targets side by
    side (``runs``: title -> one run, at most three, of the same targets and steps), every
    ``every``-th step and the last: each map as :func:`draw_targets` draws it. Show it with
    ``IPython.display.HTML(animation_html(anim))``.

    Examples
    --------
    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET.first(5)
    >>> run = tracking.simulate_targets(su, "unique-pairs")
    >>> animate_targets({"unique pairs": run}, every=2, dpi=30).frames
    [1, 3, 5]
    """
    import matplotlib.pyplot as plt

    runs = as_mapping(runs, "runs")
    if not 1 <= len(runs) <= 3:
        raise ValueError(f"runs must hold one to three runs, got {len(runs)}")
    runs = {as_str(t, "title"): _one_run(r, "runs") for t, r in runs.items()}
    shapes = {(r.steps, r.n_targets) for r in runs.values()}
    if len(shapes) != 1:
        raise ValueError("runs must have the same steps and targets")
    every = as_int(every, "every", 1)
    dpi = as_positive(dpi, "dpi")
    figsize = as_figsize(figsize)
    interval = as_positive(interval, "interval")
    fig, axes = plt.subplots(1, len(runs), figsize=figsize, dpi=dpi, layout="constrained",
                             squeeze=False, sharex=True, sharey=True)
    arts = []
    for ax, (title, run) in zip(axes[0], runs.items()):
        draw_sensors(ax, run.setup.sensor_array, ms=7)
        _map_limits(ax, list(runs.values()))
        ax.set_xlabel("x (length unit)")
        arts.append((_TargetArtists(ax, run.n_targets), run, title))
    axes[0, 0].set_ylabel("y (length unit)")
    steps, n_targets = shapes.pop()
    fig.legend(handles=_legend_handles(n_targets), loc="outside lower center", ncol=3,
               fontsize=10)
    frames = list(range(1, steps + 1, every))
    if frames[-1] != steps:
        frames.append(steps)

    def frame(k):
        for art, run, title in arts:
            art.update(run, k, f"{title}: ")

    plt.close(fig)
    artists = tuple(a for art, _, _ in arts for a in art.artists)
    return RunAnimation(fig, frame, artists, frames, interval)

