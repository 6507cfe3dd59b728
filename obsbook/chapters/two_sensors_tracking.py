"""The numbers and tables of the chapter on two sensors tracking a target (Section V-A,
Figs. 4-6).

Each ``glue_*`` function formats one result of the chapter (a run, the published runs and their
replays, the Monte Carlo comparison of :func:`obslib.tracking.compare_strategies`, the studies
of :mod:`obslib.studies.two_sensors_tracking`) and glues it under the names the chapter's prose
uses. Runs are keyed by strategy and named by :data:`obslib.viz.tracking.STRATEGY_LABELS`.
"""

from __future__ import annotations

import numpy as np

from obslib import tracking
from obslib.claims.two_sensors_tracking import printed_number
from obslib.formatting import count, fixed, listing, number, percent, setting, small
from obslib.studies.published import FIGURE_TOLERANCE, PUBLISHED_CIRCLE
from obslib.studies.two_sensors_tracking import (
    K50_WINDOW,
    circle_runs,
    circle_speed,
    fixed_pair_typicality,
    hot_windows,
    least_run_wins,
    stretches,
    window_rates,
)
from obslib.viz.style import pair_label
from obslib.viz.tracking import STRATEGY_LABELS

from ..glue import glue_texts
from ..prose import point, sensor_math, share
from ..report import record_table
from ..tables import numbered_table, rows_table

__all__ = ["replay_gap", "glue_settings", "glue_first_steps",
           "glue_replay", "glue_switches", "glue_largest", "glue_vs_paper", "glue_typicality",
           "glue_monte_carlo", "glue_wins", "glue_monte_carlo_claims", "glue_lost",
           "glue_correlations", "glue_k50", "glue_partners", "glue_speed", "glue_metric",
           "baseline_approach", "glue_exercise_baseline", "glue_exercise_noise"]

#: The strategies' short names in the glued names: s1, s2, s3.
SHORT = dict(zip(tracking.STRATEGIES, ("s1", "s2", "s3")))


def glue_settings(setup) -> None:
    """The settings of the published runs (``tab-05-settings``), the target's speed and the
    number of pairs.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The experiment's setup.
    """
    c, rad, rate = np.array(setup.center), setup.radius, setup.rate
    start = c + rad * np.array([1.0, 0.0])
    q_, r_, p0_ = (setting(m[0][0]) for m in (setup.Q, setup.R, setup.cov0))
    maha = setup.metric == "mahalanobis"
    rows = [
        ("sensors", ", ".join(f"{sensor_math(i)} = {point(p)}"
                              for i, p in enumerate(setup.sensor_array))),
        ("the target's path",
         rf"$o_k = c + \rho\,(\cos \omega (k - 1), \sin \omega (k - 1))$, $k = 1, \dots,$"
         f" {number(setup.steps)}: a circle of radius $\\rho$ = {setting(rad)} about"
         f" $c$ = {point(c)}, from {point(start)}, $\\omega$ = {setting(rate)} rad per step"),
        (r"speed bound $u_{\max}$ in the bound", setting(setup.u_max)),
        ("range noise",
         rf"$n_i \sim \mathcal N(0, \sigma^2)$, $\sigma$ = {setting(setup.noise_std)}"),
        ("filter", "extended Kalman filter on the position; random-walk prediction with"
         f" $Q$ = {q_} $I$; $R$ = {r_} $I$; Jacobian rows $(\\hat o - p_i)^T$; Joseph-form"
         " covariance update"),
        ("start of the filter",
         f"$\\hat o_1$ = {point(setup.estimate0)}, $\\Sigma_1$ = {p0_} $I$"),
        ("distances in the bound",
         r"Mahalanobis, $d_i = \sqrt{(p_i - \hat o)^T \Sigma^{-1} (p_i - \hat o)}$, in $\alpha$"
         r" and $u_{\max}^2 / d_{io}^2$; the angle $\theta_{ji}$ stays Euclidean" if maha else
         "Euclidean, as in Theorem 4"),
        ("order within step $k$",
         r"choose the pair from $(\hat o_k, \Sigma_k)$ and log its bound; log $\epsilon_k$ and"
         r" $\operatorname{tr}\Sigma_k$; predict, measure the true $o_k$, update; move the"
         " target"),
        ("noise across strategies", "common: the draw for step $k$ and sensor $s_i$ is the same"
         " whichever strategy asks for it"),
    ]
    glue_texts(
        n_pairs=number(setup.n_sensors * (setup.n_sensors - 1) // 2),
        speed=number(circle_speed(setup)),
        rate=setting(rate),
        tab_settings=rows_table(rows, "The settings of the published runs of Figs. 4-6.",
                                "tab-05-settings", headers=("setting", "value")),
    )


def glue_first_steps(runs: dict, seed: int) -> None:
    """The first steps of one run of each strategy (``tab-05-first``), and strategy (1)'s error
    and trace at step 1.

    Parameters
    ----------
    runs : dict
        Strategy -> one run (:class:`obslib.tracking.TrackingResult`).
    seed : int
        The runs' noise seed.
    """
    r1 = runs["best-pair"]
    first = [k for k in (1, 2, 50) if k <= r1.steps]
    rows = [{"k": number(k), "strategy": STRATEGY_LABELS[s], "pair": pair_label(*run.pairs[k - 1]),
             "bound": number(run.bound[k - 1]), "error": number(run.error[k - 1]),
             "trace": number(run.trace_cov[k - 1])}
            for k in first for s, run in runs.items()]
    glue_texts(
        tab_first=numbered_table(
            rows, f"The first steps of the run of seed {seed}: the pair each strategy chooses, "
            "its bound, the error and the trace of the covariance.", "tab-05-first",
            columns={"step k": ("k", "s"), "strategy": ("strategy", "s"), "pair": ("pair", "s"),
                     "bound": ("bound", "s"), "error ε (length unit)": ("error", "s"),
                     "trace Σ (length unit²)": ("trace", "s")}),
        err1=number(r1.error[0]),
        tr1=number(r1.trace_cov[0]),
    )


def replay_gap(published, replay, fields) -> float:
    """The largest difference between a published run and its replay over the logged
    ``fields``; an error if the replay does not give the log (a difference of
    :math:`10^{-9}` or more, or another pair at some step).

    Parameters
    ----------
    published : obslib.published_runs.PublishedRun
        The published run.
    replay : obslib.tracking.TrackingResult
        Its replay with the published noise (:func:`obslib.studies.replay.replay`).
    fields : tuple of str
        The logged quantities compared.
    """
    gap = max(float(np.abs(getattr(replay, f) - getattr(published, f)).max()) for f in fields)
    if not (gap < 1e-9 and (replay.pairs == published.pairs).all()):
        raise RuntimeError(f"the replay does not give the published run (gap {gap:.3g})")
    return gap


def glue_replay(published: dict, replays: dict) -> None:
    """The largest difference between the published runs and their replays, and the steps
    replayed.

    Parameters
    ----------
    published, replays : dict
        Strategy -> published run, and strategy -> its replay.
    """
    fields = ("bound", "error", "trace_cov", "truth", "estimate", "cov")
    gap = max(replay_gap(published[s], replays[s], fields) for s in replays)
    steps = int(published["best-pair"].steps)
    glue_texts(replay_gap=small(gap, floor=1e-9), replay_steps=count(steps, of=steps))


def glue_switches(runs: dict, published: dict) -> None:
    """How often strategies (1) and (2) change pair in one run and in the published runs, and
    how many pairs strategy (1) uses.

    Parameters
    ----------
    runs : dict
        Strategy -> one run.
    published : dict
        Strategy -> published run.
    """
    r1, r2 = runs["best-pair"], runs["best-partner"]
    glue_texts(
        n_transitions=number(r1.steps - 1),
        s1_changes=number(int(r1.switches)),
        s1_distinct=number(len({tuple(p) for p in r1.pairs})),
        s2_changes=number(int(r2.switches)),
        pub_s1_changes=number(int(published["best-pair"].switches)),
        pub_s2_changes=number(int(published["best-partner"].switches)),
    )


def glue_largest(runs: dict, seed: int) -> None:
    """The largest error and trace of each run, above the cut of Fig. 6's axis
    (``tab-05-largest``).

    Parameters
    ----------
    runs : dict
        Strategy -> one run.
    seed : int
        The runs' noise seed.
    """
    rows = [(STRATEGY_LABELS[s], number(run.error.max()), number(run.trace_cov[1:].max()))
            for s, run in runs.items()]
    glue_texts(tab_largest=rows_table(
        rows, f"The largest values of the run of seed {seed}, above the cut of the figure's axis.",
        "tab-05-largest", headers=("strategy", "largest error ε (length unit)",
                                   "largest trace Σ after step 1 (length unit²)")))


def glue_vs_paper(runs: dict, seed: int) -> None:
    """One run of each strategy against the published run (``tab-05-vs-paper``), and each
    number of the table on its own.

    Parameters
    ----------
    runs : dict
        The three strategies' runs (:class:`obslib.tracking.TrackingResult`), by strategy.
    seed : int
        Their noise seed, named in the caption.
    """
    summ = {s: run.summary() for s, run in runs.items()}
    steps = runs["best-pair"].steps
    quantities = {"switches": f"pair changes (of {steps - 1})", "mean_bound": "mean bound",
                  "mean_error": "mean error ε (length unit)",
                  "mean_trace": "mean trace Σ (length unit²)"}
    rows = []
    for key, text in quantities.items():
        row = {"q": text}
        for s in tracking.STRATEGIES:
            v = summ[s][key]
            row[f"{s} ours"] = number(int(v)) if key == "switches" else number(v)
            row[f"{s} paper"] = printed_number(key, PUBLISHED_CIRCLE[s][key])
        rows.append(row)
    cols = {"quantity": ("q", "s")}
    for s, n in zip(tracking.STRATEGIES, ("(1)", "(2)", "(3)")):
        cols[f"{n} ours"] = (f"{s} ours", "s")
        cols[f"{n} paper"] = (f"{s} paper", "s")
    each = {}
    for s, name in SHORT.items():
        for key in ("mean_bound", "mean_error", "mean_trace"):
            each[f"one_{name}_{key}"] = number(summ[s][key])
            each[f"pub_{name}_{key}"] = printed_number(key, PUBLISHED_CIRCLE[s][key])
        each[f"one_{name}_switches"] = number(int(summ[s]["switches"]))
        each[f"pub_{name}_switches"] = printed_number("switches", PUBLISHED_CIRCLE[s]["switches"])
    glue_texts(
        tab_vs_paper=numbered_table(
            rows, f"Our run of seed {seed} against the published run, strategies (1), (2) and "
            "(3).", "tab-05-vs-paper", columns=cols),
        **each,
    )


def glue_typicality(batch) -> None:
    """How the published run of strategy (3), which cannot be replayed, sits among our runs of
    it (:func:`obslib.studies.two_sensors_tracking.fixed_pair_typicality`): the share of runs like
    it, and the shares of runs with a higher mean error and trace than it.

    Parameters
    ----------
    batch : obslib.tracking.BatchResult
        Strategy (3)'s runs over the noise seeds.
    """
    t = fixed_pair_typicality(batch)
    pct = t["percentile"]  # the percentage of our runs below the published run's value
    glue_texts(
        like3=percent(t["share_like"]),
        fig_tol=percent(FIGURE_TOLERANCE),
        pub3_below_error=percent(1 - pct["mean_error"] / 100),
        pub3_below_trace=percent(1 - pct["mean_trace"] / 100),
        n_seeds=number(batch.n_runs),
    )


def glue_monte_carlo(stats: dict, n_seeds: int, steps: int) -> None:
    """The strategies over many noise seeds (``tab-05-mc``): means and standard deviations of
    the bound, the error and the trace, and the pair changes per run.

    Parameters
    ----------
    stats : dict
        Strategy -> its statistics (the ``"strategies"`` of
        :func:`obslib.tracking.compare_strategies`).
    n_seeds, steps : int
        The noise seeds and the steps of each run.
    """
    rows = [{"s": STRATEGY_LABELS[s],
             **{f"{q}_{stat}": number(float(stats[s][f"{stat}_{q}"]))
                for q in ("bound", "error", "trace") for stat in ("mean", "sd")},
             "sw": number(float(stats[s]["switches"]))} for s in tracking.STRATEGIES]
    glue_texts(tab_mc=numbered_table(
        rows, f"The three strategies over {number(n_seeds)} noise seeds: means over steps 2 to"
        f" {number(steps)} and over the seeds; sd is the standard deviation of the run means over"
        " the seeds.", "tab-05-mc",
        columns={"strategy": ("s", "s"), "bound": ("bound_mean", "s"),
                 "bound sd": ("bound_sd", "s"), "error ε (length unit)": ("error_mean", "s"),
                 "error sd": ("error_sd", "s"), "trace Σ (length unit²)": ("trace_mean", "s"),
                 "trace sd": ("trace_sd", "s"), "pair changes per run": ("sw", "s")}))


def glue_wins(cmp: dict) -> None:
    """How often strategy (1) has the lower error and trace than each other strategy, read three
    ways (``tab-05-wins``).

    Parameters
    ----------
    cmp : dict
        :func:`obslib.tracking.compare_strategies`.
    """
    ways = {"stepmean": "steps of the mean", "pointwise": "steps of single runs", "run": "runs"}
    rows = []
    for o, w in cmp["wins"].items():
        row = {"o": STRATEGY_LABELS[o]}
        for q in ("error", "trace"):
            for way in ways:
                field = f"run_{q}" if way == "run" else f"{q}_{way}"
                row[f"{q}_{way}"] = percent(float(w[field]))
        rows.append(row)
    cols = {"(1) lower than": ("o", "s")}
    for q in ("error", "trace"):
        for way, text in ways.items():
            cols[f"{q}: {text}"] = (f"{q}_{way}", "s")
    glue_texts(tab_wins=numbered_table(
        rows, "How often strategy (1) has the lower error and trace than each other strategy.",
        "tab-05-wins", columns=cols))


def glue_monte_carlo_claims(cmp: dict, mc: dict, n_seeds: int) -> None:
    """The Monte Carlo numbers the prose reads the paper's observations with: the shares of
    steps and runs strategy (1) wins, the stretches where strategy (2)'s trace is not clearly
    above, the means and the steps with a higher mean bound.

    Parameters
    ----------
    cmp : dict
        :func:`obslib.tracking.compare_strategies` of ``mc``.
    mc : dict
        Strategy -> its runs (:class:`obslib.tracking.BatchResult`).
    n_seeds : int
        The noise seeds.
    """
    stats = cmp["strategies"]
    steps = mc["best-pair"].steps
    w2, w3 = cmp["wins"]["best-partner"], cmp["wins"]["fixed-pair"]
    texts = {}
    for key in ("error_stepmean", "trace_stepmean", "error_pointwise", "trace_pointwise"):
        texts[f"w2_{key}"] = percent(float(w2[key]))
        texts[f"w3_{key}"] = percent(float(w3[key]))
    # stretches of at least 5 steps where strategy 2's mean trace is not clearly above strategy 1's
    t1, t2 = stats["best-pair"]["step_mean_trace"], stats["best-partner"]["step_mean_trace"]
    not_above = ~tracking.clearly_lower(t1[1:], t2[1:])  # steps 2..
    spans = [f"{a} to {b}" for a, b in stretches(not_above, first=2, min_length=5)]
    for s, name in SHORT.items():
        texts[f"mc_{name}_error"] = number(float(stats[s]["mean_error"]))
        texts[f"mc_{name}_trace"] = number(float(stats[s]["mean_trace"]))
    # the bound: at how many steps strategy (1)'s mean over the seeds is higher
    b1 = mc["best-pair"].bound[:, 1:]
    higher = {o: float(tracking.clearly_lower(mc[o].bound[:, 1:].mean(0), b1.mean(0)).mean())
              for o in tracking.STRATEGIES[1:]}
    glue_texts(
        **texts,
        run_wins=share(float(least_run_wins(cmp)), n_seeds, "runs"),
        tie_rtol=setting(tracking.TIE_RTOL),
        s2_spans=listing(spans) if spans else "none",
        higher_2=share(higher["best-partner"], steps - 1, "steps"),
        higher_3=share(higher["fixed-pair"], steps - 1, "steps"),
    )


def _flip_span(loss: dict) -> str:
    """Where the lost runs of :func:`obslib.tracking.track_loss` flip, in words."""
    fs = loss["flip_step"][loss["lost"]]
    return (f"between {number(int(fs.min()))} and {number(int(fs.max()))}" if fs.size else
            "nowhere")


def glue_lost(batch, loss: dict, lost_above: float, dist, kmin: int, run, figure_data) -> None:
    """Strategy (3)'s lost runs: how many, how many end at the mirror image, where the estimate
    flips, the geometry where the target passes closest to the fixed pair's baseline, and the
    median run's mean error over all its steps, as the figure data average a run (the number
    of the ledger's entry on the published run's figure data, formatted as it formats it).

    Parameters
    ----------
    batch : obslib.tracking.BatchResult
        The runs of strategy (3).
    loss : dict
        :func:`obslib.tracking.track_loss` of ``batch``.
    lost_above : float
        The run-mean error above which a run is lost.
    dist : ndarray
        The distance of the true path to the baseline at each step.
    kmin : int
        The step where it is smallest (1-based).
    run : obslib.tracking.TrackingResult
        Strategy (3)'s single run.
    figure_data : obslib.claims.Record
        The ledger's entry ``fig6-figure-data``, evaluated with the chapter's parameters.
    """
    lost = loss["lost"]
    frac_m = float(loss["mirrored"][lost].mean()) if lost.any() else 0.0
    glue_texts(
        n_lost=count(int(lost.sum()), of=batch.n_runs),
        mirrored="all of them" if frac_m == 1 else f"{percent(frac_m)} of them",
        flip_span=_flip_span(loss),
        lost_above=setting(lost_above),
        k_closest=number(kmin),
        dist_closest=number(float(dist.min())),
        bound_closest=number(float(batch.bound[:, kmin - 1].mean())),
        bound_avg3=number(float(batch.bound.mean())),
        s3_median_error=number(figure_data.evidence["fixed_pair"]["median"]["mean_error"]),
        n_steps=number(batch.steps),
        pub_s3_error=printed_number("mean_error", PUBLISHED_CIRCLE["fixed-pair"]["mean_error"]),
        one_s3_error=number(float(run.error.mean())),
    )


def glue_correlations(corrs: dict, steps: int) -> None:
    """The rank correlation over time of the bound with the error and with the trace
    (``tab-05-corr``), per strategy and pooled over the strategies.

    Parameters
    ----------
    corrs : dict
        :func:`obslib.studies.two_sensors_tracking.correlations`.
    steps : int
        The steps of each run.
    """
    corr, pooled = corrs["own"], corrs["pooled"]
    rows = [(STRATEGY_LABELS[s], number(float(corr[s]["error"])), number(float(corr[s]["trace"])),
             number(float(corrs["euclidean"][s]["error"])),
             number(float(corrs["euclidean"][s]["trace"]))) for s in tracking.STRATEGIES]
    each = {}
    for s, name in SHORT.items():
        each[f"corr_{name}_error"] = number(float(corr[s]["error"]))
        each[f"corr_{name}_trace"] = number(float(corr[s]["trace"]))
    glue_texts(
        tab_corr=rows_table(
            rows, f"Spearman correlation over time (steps 2 to {number(steps)}) of the bound with"
            " the error and with the trace, median over the seeds: the bound as logged, and the"
            " Euclidean bound of the same pairs.", "tab-05-corr",
            headers=("strategy", "logged bound, with ε", "logged bound, with trace Σ",
                     "Euclidean bound, with ε", "Euclidean bound, with trace Σ")),
        **each,
        pooled_error=number(float(pooled["error"])),
        pooled_trace=number(float(pooled["trace"])),
    )


def glue_k50(rate, one, back: float, n_seeds: int, seed: int) -> None:
    """How often strategy (1) changes pair around :math:`k = 50` and elsewhere
    (``tab-05-k50``), over the seeds and in one run, how often it switches back, and the other
    windows where it switches as often.

    Parameters
    ----------
    rate : ndarray
        The fraction of the runs switching at each transition.
    one : ndarray of bool
        One run's switches.
    back : float
        The share of switches back to the previous pair.
    n_seeds, seed : int
        The noise seeds, and the seed of the one run.
    """
    lo_k, hi_k = K50_WINDOW
    rate_in, rate_out = window_rates(rate, K50_WINDOW)
    one_in, one_out = window_rates(one, K50_WINDOW)
    hot = hot_windows(rate, K50_WINDOW, rate_in)
    rows = [(f"$k$ = {lo_k} to {hi_k}", percent(float(rate_in)), percent(float(one_in))),
            ("elsewhere", percent(float(rate_out)), percent(float(one_out)))]
    glue_texts(
        tab_k50=rows_table(
            rows, "Share of the transitions at which strategy (1) changes pair.", "tab-05-k50",
            headers=("transitions", f"mean over {number(n_seeds)} seeds", f"run of seed {seed}")),
        k50_rate=percent(float(rate_in)),
        k50_rest=percent(float(rate_out)),
        switch_back=percent(float(back)),
        hot_windows=listing([f"{a}" if a == b else f"{a} to {b}" for a, b in hot])
        if hot else "none",
    )


def glue_partners(ps: dict, best: dict, best_bound: int, n_seeds: int, steps: int,
                  lost_above: float) -> None:
    """Strategy (3) with each partner of the fixed sensor (``tab-05-partner``), and the partners
    that are best by each measure.

    Parameters
    ----------
    ps : dict
        Partner -> its summary (:func:`obslib.studies.two_sensors_tracking.partner_summary`).
    best : dict
        Measure -> the best partner (:func:`obslib.studies.two_sensors_tracking.best_partners`),
        without the mean bound.
    best_bound : int
        The partner with the highest mean bound.
    n_seeds, steps : int
        The noise seeds, and the steps of each run.
    lost_above : float
        The run-mean error above which a run is lost (:func:`obslib.tracking.track_loss`).
    """
    rows = [(sensor_math(j), number(float(d["mean_bound"])), number(float(d["mean_trace"])),
             number(float(d["mean_error"])), number(float(d["median_error"])),
             percent(float(d["lost"]))) for j, d in ps.items()]
    measure = {"mean_trace": "mean trace", "mean_error": "mean error",
               "median_error": "median error", "lost": "share of lost runs"}
    s1_best = [measure[key] for key, j in best.items() if j == 0]
    caption = (f"Strategy (3) with each partner of $s_2$, over {number(n_seeds)} noise seeds, "
               f"steps 2 to {number(steps)}. Mean error: the mean over the runs of the run-mean "
               "error; median: that of the median run; lost: the share of runs whose mean error "
               f"over all steps exceeds {setting(lost_above)}.")
    glue_texts(
        tab_partner=rows_table(
            rows, caption, "tab-05-partner",
            headers=("partner of s₂", "mean bound", "mean trace Σ (length unit²)",
                     "mean error ε (length unit)", "median error (length unit)", "runs lost")),
        s1_best_by=listing(s1_best) if s1_best else "no measure",
        s1_best_n=count(len(s1_best), of=len(measure)),
        partner_best_error=sensor_math(best["mean_error"]),
        partner_best_bound=sensor_math(best_bound),
    )


def glue_speed(mc: dict, at_speed: dict, record) -> None:
    """The comparison of the strategies with the paper's speed bound and with the target's own
    speed in the sensors' bound (``tab-05-speed``, the ledger's table of ``sec5a-umax-speed``),
    how loose the paper's bound is, and how often strategy (1) chooses the same pair with both.

    Parameters
    ----------
    mc, at_speed : dict
        Strategy -> its runs (:class:`obslib.tracking.BatchResult`) with the paper's speed
        bound, and with the target's speed, over the same noise seeds.
    record : obslib.claims.Record
        The ledger's entry ``sec5a-umax-speed``, evaluated with the chapter's parameters.
    """
    ev = record.evidence
    same = (mc["best-pair"].pairs == at_speed["best-pair"].pairs).all(axis=-1)
    glue_texts(
        tab_speed=record_table(record, "tab-05-speed"),
        speed_ratio=number(ev["ratio"]),
        speed_same_pairs=percent(float(same.mean())),
        speed_bound_paper=number(ev["paper_u_max"]["mean_bound"]["best-pair"]),
        speed_bound_true=number(ev["true_speed"]["mean_bound"]["best-pair"]),
    )


def glue_metric(by_metric: dict, agree: float, least_wins: float, back: dict,
                n_seeds: int) -> None:
    """Strategies (1) and (2) with each kind of distance in the bound (``tab-05-metric``), how
    often the two kinds choose the same pair, and the least share of runs strategy (1) wins with
    the other kind.

    Parameters
    ----------
    by_metric : dict
        Metric -> the strategies' statistics (as in :func:`glue_monte_carlo`).
    agree : float
        The share of steps where the two metrics choose the same pair.
    least_wins : float
        The least share of runs strategy (1) wins with the other metric.
    back : dict
        Metric -> the share of switches back to the previous pair.
    n_seeds : int
        The noise seeds.
    """
    rows = [(f"{STRATEGY_LABELS[s]}, {m.capitalize()}", number(float(src[s]["switches"])),
             number(float(src[s]["mean_error"])), number(float(src[s]["mean_trace"])))
            for m, src in by_metric.items() for s in tracking.STRATEGIES[:2]]
    each = {}
    for name, m in (("maha", "mahalanobis"), ("eucl", "euclidean")):
        src = by_metric[m]["best-pair"]
        each |= {f"{name}_switches": number(float(src["switches"])),
                 f"{name}_error": number(float(src["mean_error"])),
                 f"{name}_trace": number(float(src["mean_trace"])),
                 f"{name}_back": percent(float(back[m]))}
    glue_texts(
        tab_metric=rows_table(
            rows, f"Strategies (1) and (2) with each kind of distance in the bound, over"
            f" {number(n_seeds)} noise seeds.", "tab-05-metric",
            headers=("strategy, distance", "pair changes per run", "mean error ε (length unit)",
                     "mean trace Σ (length unit²)")),
        metric_agree=percent(float(agree)),
        other_wins=share(float(least_wins), n_seeds, "runs"),
        **each,
    )


# ---------------------------------------------------------------------------------------------
# Exercises
# ---------------------------------------------------------------------------------------------


def baseline_approach(setup) -> dict:
    r"""Where the circle of the experiment comes closest to the baseline of strategy (3)'s pair,
    the line through its two sensors, by hand: with :math:`n` a unit normal of the baseline and
    :math:`h = n^T (c - p_a)` the signed distance of the circle's centre :math:`c`, the circle
    comes within :math:`|h| - \rho` of the line, at the point :math:`c - \rho\,\mathrm{sign}(h)\,n`,
    reached at the angle :math:`\varphi` of :math:`-\mathrm{sign}(h)\,n` from the start, so at
    step :math:`k = 1 + \varphi / \omega` (the nearer of the two steps around it).

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        A circle experiment whose circle does not cross the baseline.

    Returns
    -------
    dict
        ``center_distance`` (:math:`|h|`), ``closest`` (:math:`|h| - \rho`), ``angle``
        (:math:`\varphi`, rad, in :math:`[0, 2\pi)`), ``step`` (1-based) and ``normal``.

    Examples
    --------
    >>> from obslib.tracking import PAPER_CIRCLE
    >>> a = baseline_approach(PAPER_CIRCLE)
    >>> round(a["center_distance"] ** 2, 9), round(a["closest"], 3), a["step"]
    (13.0, 0.606, 207)
    """
    s = setup.sensor_array
    a, b = s[setup.fixed_pair[0]], s[setup.fixed_pair[1]]
    d = (b - a) / np.hypot(*(b - a))
    n = np.array([-d[1], d[0]])
    c, rho, omega = np.array(setup.center), setup.radius, setup.rate
    h = float(n @ (c - a))
    if abs(h) <= rho:
        raise ValueError("the circle crosses the baseline of the fixed pair")
    toward = -np.sign(h) * n
    angle = float(np.arctan2(toward[1], toward[0]) % (2 * np.pi))
    ks = np.array([np.floor(angle / omega), np.ceil(angle / omega)]) + 1
    pts = c + rho * np.column_stack([np.cos(omega * (ks - 1)), np.sin(omega * (ks - 1))])
    step = int(ks[np.argmin(np.abs((pts - a) @ n))])
    return {"center_distance": abs(h), "closest": abs(h) - rho, "angle": angle, "step": step,
            "normal": n}


def glue_exercise_baseline(setup, loss: dict) -> dict:
    """The numbers of the exercise on the fixed pair's baseline (:func:`baseline_approach`):
    the pair's sensors, the distances, the angle and the step.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The circle experiment.
    loss : dict
        :func:`obslib.tracking.track_loss` of strategy (3)'s runs (where they flip).

    Returns
    -------
    dict
        :func:`baseline_approach`.
    """
    a = baseline_approach(setup)
    i, j = setup.fixed_pair
    s = setup.sensor_array
    k = a["step"]
    glue_texts(
        ex_pair=f"{sensor_math(i)} = {point(s[i])} and {sensor_math(j)} = {point(s[j])}",
        ex_center=point(setup.center),
        ex_radius=setting(setup.radius),
        ex_normal=point(a["normal"], 3),
        ex_hdist=number(a["center_distance"]),
        ex_closest=number(a["closest"]),
        ex_angle=number(a["angle"]),
        ex_step=number(k),
        ex_step_real=fixed(1 + a["angle"] / setup.rate, 1),
        ex_when=(f"the lost runs of strategy (3) flip {_flip_span(loss)}, around that step"
                 if k <= setup.steps else
                 f"after the last of this run's {number(setup.steps)} steps, so this run never "
                 "gets there"),
    )
    return a


def glue_exercise_noise(setup, n_seeds: int, seed: int, lost_above: float) -> dict:
    """The numbers of the exercise that halves the range noise: strategy (3)'s lost runs and
    the strategies' mean errors with the chapter's noise and with half of it, over the same
    seeds (:func:`obslib.studies.two_sensors_tracking.circle_runs`, what a rerun with half the noise
    computes).

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The circle experiment.
    n_seeds, seed : int
        The noise seeds: ``seed, ..., seed + n_seeds - 1``.
    lost_above : float
        The run-mean error above which a run is lost.

    Returns
    -------
    dict
        Noise level -> ``{"lost", "mean_error", "run_wins"}`` (lost runs of strategy (3), the
        strategies' mean errors, strategy (1)'s least share of runs won).
    """
    out = {}
    for sd in (setup.noise_std, setup.noise_std / 2):
        mc = circle_runs(setup.replace(noise_std=sd), n_seeds, seed)["mc"]
        cmp = tracking.compare_strategies(mc)
        out[sd] = {"lost": int(tracking.track_loss(mc["fixed-pair"], lost_above)["lost"].sum()),
                   "mean_error": {s: float(d["mean_error"]) for s, d in
                                  cmp["strategies"].items()},
                   "run_wins": float(least_run_wins(cmp))}
    full, half = out[setup.noise_std], out[setup.noise_std / 2]
    glue_texts(
        ex_noise=setting(setup.noise_std),
        ex_half=setting(setup.noise_std / 2),
        ex_lost=count(full["lost"], of=n_seeds),
        ex_lost_half=count(half["lost"], of=n_seeds),
        ex_err1=number(full["mean_error"]["best-pair"]),
        ex_err1_half=number(half["mean_error"]["best-pair"]),
        ex_err3=number(full["mean_error"]["fixed-pair"]),
        ex_err3_half=number(half["mean_error"]["fixed-pair"]),
        ex_wins_half=share(half["run_wins"], n_seeds, "runs"),
    )
    return out
