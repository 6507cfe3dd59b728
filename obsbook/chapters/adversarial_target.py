"""The numbers and tables of the chapter on the adversarial target (Section V-B, Fig. 7).

Each ``glue_*`` function formats one result of the chapter (the bound over the plane, a run and
its entrapment, the published run and its replay, the Monte Carlo summaries of
:mod:`obslib.studies.tracking`, the stronger adversaries) and glues it under the names the
chapter's prose uses.
"""

from __future__ import annotations

import numpy as np

from obslib import tracking
from obslib.controls import disc_controls
from obslib.formatting import count, listing, number, percent, setting, small
from obslib.published_runs import published_run
from obslib.studies.adversarial_target import adversary_runs, entrapment_summary
from obslib.studies.experiment_details import control_set_gap
from obslib.studies.published import FIGURE_TOLERANCE, PUBLISHED_ADVERSARIAL
from obslib.viz.adversarial_target import ADVERSARY_LABELS
from obslib.viz.tracking import STRATEGY_LABELS

from ..glue import glue_texts
from ..prose import PUBLISHED_RUNS, point, sensor_math, share
from ..tables import rows_table
from .two_sensors_tracking import replay_gap

__all__ = ["glue_intuition", "glue_settings", "glue_one_run", "glue_replay", "glue_entrapment",
           "glue_monte_carlo", "glue_mechanism", "full_step_share", "glue_strong", "glue_metric",
           "valley_steps", "glue_exercise_valley", "glue_exercise_slow"]

#: The exact :math:`C^{-1}` below which the exercise on the fixed pair's valley counts the target
#: as having reached the valley.
VALLEY_LEVEL = 0.01


def _n_ring(setup) -> int:
    """The target's controls of full speed (all but ``u = 0``)."""
    return int((np.hypot(*setup.control_array.T) > 0).sum())


def glue_intuition(setup, landscapes: dict) -> None:
    """The intuition's speed bound, the number of pairs, and the lowest value of the best pair's
    bound over the plane.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The experiment's setup.
    landscapes : dict
        :func:`obslib.viz.adversarial_target.bound_landscapes`.
    """
    n = setup.n_sensors
    glue_texts(
        u_max=setting(setup.u_max),
        n_pairs=number(n * (n - 1) // 2),
        landscape_min=number(float(landscapes["best"].min())),
    )


def glue_settings(setup) -> None:
    """The settings of the published run of Fig. 7 that differ from Section V-A's
    (``tab-06-settings``), the number of controls and how far the target could go.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The experiment's setup.
    """
    n_ring = _n_ring(setup)
    rows = [
        ("speed bound $u_{\\max}$ (the target's, and in the bound)", setting(setup.u_max)),
        ("the target's start", point(setup.start)),
        ("start of the filter", f"$\\hat o_1$ = {point(setup.estimate0)},"
         f" $\\Sigma_1$ = {setting(setup.cov0[0][0])} $I$"),
        ("time steps", number(setup.steps)),
        ("the target's controls",
         f"$u = 0$ and {number(n_ring)} controls of norm $u_{{\\max}}$ at angles"
         f" {setting(0.0)}, {setting(0.1)}, ..., {setting(0.1 * (n_ring - 1))} rad"
         " (the authors' grid of the ball)"),
        ("distances in the bound", "Mahalanobis lengths, Euclidean angle" if setup.metric ==
         "mahalanobis" else "Euclidean"),
    ]
    glue_texts(
        tab_settings=rows_table(
            rows, "The settings of the published run of Fig. 7 that differ from Section V-A's.",
            "tab-06-settings", headers=("setting", "value")),
        n_controls=number(len(setup.control_array)),
        reach=number(float(setup.steps * setup.u_max)),
        n_moves=number(setup.steps),
        n_transitions=number(setup.steps - 1),
    )


def glue_one_run(e, seed: int) -> None:
    """One run against the adversary, its entrapment ``e`` against the published run's printed
    numbers (``tab-06-one``).

    Parameters
    ----------
    e : obslib.tracking.Entrapment
        :func:`obslib.tracking.entrapment` of the run.
    seed : int
        The run's noise seed.
    """
    rows = [
        ("mean bound", number(e.bound_mean), setting(PUBLISHED_ADVERSARIAL["mean_bound"])),
        ("smallest bound", number(e.bound_min), ""),
        ("mean exact C⁻¹ the sensors face", number(e.icn_mean), ""),
        ("smallest exact C⁻¹", number(e.icn_min), ""),
        (f"pair switches (of {e.transitions})", number(int(e.switches)),
         number(int(PUBLISHED_ADVERSARIAL["switches"]))),
        ("path length of the target (length unit)", number(e.path_length), ""),
        ("farthest from the start (length unit)", number(e.max_from_start), ""),
        ("net displacement (length unit)", number(e.net_displacement), ""),
        ("mean error ε (length unit)", number(e.mean_error), ""),
        ("mean trace Σ (length unit²)", number(e.mean_trace), ""),
    ]
    glue_texts(
        tab_one=rows_table(
            rows, f"The run of seed {seed} against the published run's printed numbers.",
            "tab-06-one", headers=("quantity", f"seed {seed}", "published")),
        one_bound=number(e.bound_mean),
        one_icn_min=number(e.icn_min),
        one_switches=number(int(e.switches)),
        one_far=number(e.max_from_start),
        one_path=number(e.path_length),
        pub_bound=setting(PUBLISHED_ADVERSARIAL["mean_bound"]),
        pub_switches_printed=number(int(PUBLISHED_ADVERSARIAL["switches"])),
    )


def glue_replay(published, replay) -> None:
    """The published run of Fig. 7 and its replay: their largest difference, mean bounds and
    pair switches.

    Parameters
    ----------
    published : obslib.published_runs.PublishedRun
        The published run.
    replay : obslib.tracking.TrackingResult
        Its replay with the published noise.
    """
    fields = ("bound", "error", "trace_cov", "truth", "estimate", "control", "objective")
    gap = replay_gap(published, replay, fields)
    glue_texts(
        replay_gap=small(gap, floor=1e-9),
        pub_bound_log=number(float(published.bound.mean())),
        rep_bound=number(float(replay.bound.mean())),
        pub_switches=number(int(published.switches)),
        rep_switches=number(int(replay.switches)),
    )


def glue_entrapment(ents: dict, seed: int) -> None:
    """The criteria of entrapment, and the adversary against each strategy
    (``tab-06-control``).

    Parameters
    ----------
    ents : dict
        Strategy -> :func:`obslib.tracking.entrapment` of its run.
    seed : int
        The runs' noise seed.
    """
    crit = tracking.ENTRAPMENT_CRITERIA
    rows = [(STRATEGY_LABELS[s], number(float(ee.max_from_start)), number(float(ee.bound_mean)),
             number(float(ee.icn_mean)), small(float(ee.icn_min), floor=1e-4),
             number(int(ee.switches)), number(float(ee.mean_error)),
             "yes" if tracking.is_entrapped(ee) else "no") for s, ee in ents.items()]
    glue_texts(
        reach_share=percent(crit["reach_fraction"]),
        crit_bound=setting(crit["bound_mean"]),
        crit_icn=setting(crit["icn_min"]),
        tab_control=rows_table(
            rows, f"The adversary against each strategy (seed {seed}).", "tab-06-control",
            headers=("sensors use", "farthest from start (length unit)", "mean bound",
                     "mean exact C⁻¹", "smallest exact C⁻¹", "pair switches",
                     "mean error ε (length unit)", "entrapped")),
        ctl_icn_min_3=small(float(ents["fixed-pair"].icn_min), floor=1e-4),
        ctl_icn_min_2=small(float(ents["best-partner"].icn_min), floor=1e-4),
        ctl_icn_min_1=number(float(ents["best-pair"].icn_min)),
        ctl_trace_3=number(float(ents["fixed-pair"].mean_trace)),
        ctl_far=number(float(max(x.max_from_start for x in ents.values()))),
    )


def glue_monte_carlo(batch, summ: dict, ctl: dict, per_run, ends, high, mid, near_mid: int,
                     published) -> None:
    """The adversary over many noise seeds, against the best pair and against the fixed pair
    (``tab-06-mc``), and the numbers the prose reads entrapment with.

    Parameters
    ----------
    batch : obslib.tracking.BatchResult
        The runs against the best pair.
    summ, ctl : dict
        :func:`obslib.studies.adversarial_target.entrapment_summary` against the best and the
        fixed pair.
    per_run : ndarray
        Each run's mean bound.
    ends : ndarray, shape (runs, 2)
        Where each run ends.
    high : ndarray of bool
        The runs whose mean bound is near the published run's.
    mid : ndarray, shape (2,)
        The median end point.
    near_mid : int
        The runs that end near it.
    published : obslib.published_runs.PublishedRun
        The published run.
    """
    n_seeds = batch.n_runs
    lo_b, hi_b = summ["bound_mean_range"]
    sw_span = (number(int(batch.switches.min())), number(int(batch.switches.max())))
    rows = [
        ("runs entrapped", percent(summ["entrapped"]), percent(ctl["entrapped"])),
        ("farthest from the start (length unit)", number(summ["max_from_start"]),
         number(ctl["max_from_start"])),
        ("mean bound of a run", f"{number(lo_b)} to {number(hi_b)}",
         f"{number(ctl['bound_mean_range'][0])} to {number(ctl['bound_mean_range'][1])}"),
        ("smallest exact C⁻¹ over all runs", number(summ["icn_min"]),
         small(ctl["icn_min"], floor=1e-4)),
        (f"pair switches per run (of {batch.steps - 1})", f"{sw_span[0]} to {sw_span[1]}",
         "none"),
    ]
    near_pub = (f"within {percent(FIGURE_TOLERANCE)} of the published"
                f" {setting(PUBLISHED_ADVERSARIAL['mean_bound'])}")
    glue_texts(
        tab_mc=rows_table(
            rows, f"The paper's adversary over {number(n_seeds)} noise seeds, against the best "
            "pair and against the fixed pair.", "tab-06-mc",
            headers=("quantity", "against (1) best pair", "against (3) fixed pair")),
        mc_mid=point(mid, 2),
        mc_near_mid=count(near_mid, of=n_seeds),
        mc_entrapped=share(float(summ["entrapped"]), n_seeds, "runs"),
        mc_ctl_entrapped=share(float(ctl["entrapped"]), n_seeds, "runs"),
        mc_far=number(float(summ["max_from_start"])),
        mc_icn_min=number(float(summ["icn_min"])),
        mc_ctl_icn_min=small(float(ctl["icn_min"]), floor=1e-4),
        mc_bound_span=f"between {number(float(lo_b))} and {number(float(hi_b))}",
        mc_bound_med=number(float(np.median(per_run))),
        mc_high_clause=f"only {count(int(high.sum()))} come {near_pub} (they end at"
        f" {listing([point(x, 2) for x in ends[high]])})" if high.any() else
        f"none comes {near_pub}",
        mc_below_pub=count(int((per_run < published.bound.mean()).sum()), of=n_seeds),
        mc_sw_span=f"between {sw_span[0]} and {sw_span[1]}",
        n_seeds=number(n_seeds),
    )


def _rate(x: float, none: str) -> str:
    """A pooled rate, or what stands in its place when its event never happened."""
    return none if np.isnan(x) else percent(x)


def glue_mechanism(mech: dict, n_seeds: int) -> None:
    """The adversary's moves and the sensors' switches, pooled over the runs (``tab-06-mech``).

    Parameters
    ----------
    mech : dict
        The mechanism's shares and mean gain, pooled over the runs
        (:func:`obslib.studies.adversarial_target.pooled_switch_mechanism`).
    n_seeds : int
        How many runs were pooled.
    """
    sw_closer, raised, gain = mech["switch_if_closer"], mech["raised"], mech["mean_gain"]
    rows = [("transitions where the target moves closer to a sensor of the pair",
             percent(mech["closer_fraction"])),
            ("of those, transitions where the pair then switches",
             _rate(sw_closer, "– (the target never closed in)")),
            ("switches that leave a higher C⁻¹ than the target aimed at",
             _rate(raised, "– (no switch)")),
            ("mean change of C⁻¹ at a switch", "–" if np.isnan(gain) else number(gain))]
    glue_texts(
        tab_mech=rows_table(
            rows, f"The adversary's moves and the sensors' switches, pooled over "
            f"{number(n_seeds)} runs.", "tab-06-mech"),
        mech_closer=percent(mech["closer_fraction"]),
        mech_switch=_rate(sw_closer, "none (the target never closed in)"),
        mech_raised=_rate(raised, "none (there was no switch)"),
    )


def full_step_share(n_radii: int, n_angles: int) -> float:
    r"""Along the published adversarial run, the share of its steps at which the best control of
    a polar grid of the whole disc (the adversary's objective,
    :func:`obslib.tracking.target_objective`, at its smallest; the first such control) is a
    full step, of norm :math:`u_{\max}`.

    Parameters
    ----------
    n_radii, n_angles : int
        The polar grid of the disc (:func:`obslib.controls.disc_controls`).
    """
    run = published_run("adversarial")
    setup = tracking.PAPER_ADVERSARIAL
    grid = disc_controls(setup.u_max, n_radii, n_angles)
    obj = tracking.target_objective(setup.sensor_array[run.pairs], run.truth, grid)
    best = grid[obj.argmin(axis=-1)]
    return float(np.mean(np.isclose(np.hypot(*best.T), setup.u_max, rtol=1e-9)))


def glue_strong(strong: dict, setup, variants: dict, worst: str, lowest: float,
                n_radii: int, n_angles: int) -> None:
    """The stronger adversaries against the best pair (``tab-06-strong``), the worst of them,
    and how much lower the target's objective gets with the whole disc of controls.

    Parameters
    ----------
    strong : dict
        Adversary -> :func:`obslib.studies.adversarial_target.entrapment_summary` of its runs.
    setup : obslib.tracking.TrackingSetup
        The paper's adversarial setup.
    variants : dict
        Adversary -> its setup (:func:`obslib.studies.adversarial_target.adversary_variants`).
    worst : str
        The adversary that drives the exact inverse condition number lowest.
    lowest : float
        The smallest share of runs entrapped by any adversary.
    n_radii, n_angles : int
        The polar grid of the disc of controls.
    """
    n_strong = next(iter(strong.values()))["batch"].n_runs
    # along the published trajectory: how much lower the target's objective gets with the disc
    gap_disc = control_set_gap(n_radii, n_angles)
    rows = [(ADVERSARY_LABELS[name], percent(d["entrapped"]), number(float(d["max_from_start"])),
             number(float(d["bound_mean"])), number(float(d["icn_mean"])),
             number(float(d["icn_min"])), number(float(d["switches"])),
             number(float(d["mean_error"]))) for name, d in strong.items()]
    glue_texts(
        n_ring=number(_n_ring(setup)),
        n_strong=number(n_strong),
        n_disc=number(len(variants["disc"].control_array)),
        strong_worst=ADVERSARY_LABELS[worst],
        strong_icn_min=number(float(strong[worst]["icn_min"])),
        strong_all=share(lowest, n_strong, "runs"),
        disc_entrapped=share(float(strong["disc"]["entrapped"]), n_strong, "runs"),
        disc_gap=small(float(gap_disc["gap"].max()), floor=1e-12),
        disc_full=share(full_step_share(n_radii, n_angles), len(gap_disc["gap"]), "steps"),
        next_icn=number(float(strong["next-pair"]["icn_mean"])),
        paper_icn=number(float(strong["paper"]["icn_mean"])),
        next_switches=number(float(strong["next-pair"]["switches"])),
        tab_strong=rows_table(
            rows, f"The adversaries against the best pair, {number(n_strong)} runs each: means"
            " over the runs; farthest and smallest: over all runs.", "tab-06-strong",
            headers=("adversary", "entrapped", "farthest from start (length unit)", "mean bound",
                     "mean exact C⁻¹", "smallest exact C⁻¹", "pair switches",
                     "mean error ε (length unit)")),
    )


def glue_metric(choices: dict) -> None:
    """At every logged estimate of the published runs: how often the logged pair is the mixed
    score's choice, and how often the consistent scores choose the same pair
    (``tab-06-metric``).

    Parameters
    ----------
    choices : dict
        Published run -> :func:`obslib.studies.experiment_details.metric_choices`.
    """
    rows = [(PUBLISHED_RUNS[name], percent(m["logged_match"]), percent(m["agree_whitened"]),
             percent(m["agree_euclidean"])) for name, m in choices.items()]
    glue_texts(
        tab_metric=rows_table(
            rows, "At every logged estimate of the published runs: how often the logged pair "
            "is the mixed score's choice, and how often the consistent scores choose the same "
            "pair.", "tab-06-metric",
            headers=("run", "logged pair = mixed choice", "whitened choice agrees",
                     "Euclidean choice agrees")),
        agree_w_adv=percent(choices["adversarial"]["agree_whitened"]),
        agree_e_adv=percent(choices["adversarial"]["agree_euclidean"]),
        agree_w_circle=percent(choices["best-pair"]["agree_whitened"]),
        logged_all="every" if all(m["logged_match"] == 1 for m in choices.values())
        else "not every",
    )


# ---------------------------------------------------------------------------------------------
# Exercises
# ---------------------------------------------------------------------------------------------


def valley_steps(setup) -> dict:
    r"""How far the adversarial target starts from the valley of strategy (3)'s pair, the line
    through its two sensors, and how many moves of at most :math:`u_{\max}` it needs at least
    to reach it: the distance :math:`|n^T (o_1 - p)|` of its start :math:`o_1` from the line
    (:math:`n` a unit normal, :math:`p` either sensor), over :math:`u_{\max}`, rounded up.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The adversarial experiment.

    Returns
    -------
    dict
        ``distance``, ``moves`` (the least number of moves) and ``normal``.

    Examples
    --------
    >>> from obslib.tracking import PAPER_ADVERSARIAL
    >>> v = valley_steps(PAPER_ADVERSARIAL)
    >>> round(v["distance"] ** 2, 9), v["moves"]  # (10 / sqrt(13))^2 and 0.1 per move
    (7.692307692, 28)
    """
    s = setup.sensor_array
    a, b = s[setup.fixed_pair[0]], s[setup.fixed_pair[1]]
    d = (b - a) / np.hypot(*(b - a))
    n = np.array([-d[1], d[0]])
    dist = abs(float(n @ (np.array(setup.start) - a)))
    return {"distance": dist, "moves": int(np.ceil(dist / setup.u_max - 1e-12)), "normal": n}


def glue_exercise_valley(setup, run) -> dict:
    """The numbers of the exercise on the fixed pair's valley: the pair and the target's start,
    the least number of moves to the valley (:func:`valley_steps`), and the first step at which
    the exact :math:`C^{-1}` the fixed pair faces in ``run`` falls below :data:`VALLEY_LEVEL`.

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The adversarial experiment.
    run : obslib.tracking.TrackingResult
        The adversary against strategy (3), the fixed pair.

    Returns
    -------
    dict
        :func:`valley_steps`, with ``first`` (the step, 1-based, or ``None``).
    """
    v = valley_steps(setup)
    below = np.flatnonzero(run.true_icn[1:] < VALLEY_LEVEL)
    v["first"] = int(below[0]) + 2 if below.size else None
    i, j = setup.fixed_pair
    s = setup.sensor_array
    glue_texts(
        ex_pair=f"{sensor_math(i)} = {point(s[i])} and {sensor_math(j)} = {point(s[j])}",
        ex_start=point(setup.start),
        ex_u=setting(setup.u_max),
        ex_level=setting(VALLEY_LEVEL),
        ex_normal=point(v["normal"], 3),
        ex_dist=number(v["distance"]),
        ex_moves=number(v["moves"]),
        ex_first=(f"at step {number(v['first'])}" if v["first"] is not None else
                  f"at none of the {number(run.steps)} steps"),
    )
    return v


def glue_exercise_slow(setup, n_seeds: int, seed: int) -> dict:
    """The numbers of the exercise that slows the target to a quarter of its speed: the best
    pair against the paper's adversary at the chapter's speed bound and at a quarter of it,
    over the same noise seeds (:func:`obslib.studies.adversarial_target.adversary_runs`, what a
    rerun with that value computes).

    Parameters
    ----------
    setup : obslib.tracking.TrackingSetup
        The adversarial experiment.
    n_seeds, seed : int
        The noise seeds: ``seed, ..., seed + n_seeds - 1``.

    Returns
    -------
    dict
        Speed bound -> :func:`obslib.studies.adversarial_target.entrapment_summary` of the best
        pair's runs.
    """
    out = {u: entrapment_summary(
        adversary_runs(setup.replace(u_max=u), n_seeds, seed)["best-pair"])
        for u in (setup.u_max, setup.u_max / 4)}
    full, slow = out[setup.u_max], out[setup.u_max / 4]
    frac = tracking.ENTRAPMENT_CRITERIA["reach_fraction"]
    # each condition of entrapment alone (the others switched off: every run meets them)
    alone = {"reach": {"bound_mean": 0.0, "icn_min": 0.0},
             "bound": {"reach_fraction": 1.0, "icn_min": 0.0},
             "icn": {"reach_fraction": 1.0, "bound_mean": 0.0}}
    fails = {k: sum(not tracking.is_entrapped(e, **off) for e in slow["runs"])
             for k, off in alone.items()}
    glue_texts(
        ex_fail_reach=count(fails["reach"], of=n_seeds),
        ex_fail_bound=count(fails["bound"], of=n_seeds),
        ex_fail_icn=count(fails["icn"], of=n_seeds),
        ex_u_slow=setting(setup.u_max / 4),
        ex_entrapped_slow=share(slow["entrapped"], n_seeds, "runs"),
        ex_reach_slow=number(slow["reach"]),
        ex_radius_slow=number(frac * slow["reach"]),
        ex_radius_full=number(frac * full["reach"]),
        ex_far_slow=number(slow["max_from_start"]),
        ex_far_full=number(full["max_from_start"]),
        ex_icn_slow=number(slow["icn_min"]),
        ex_icn_full=number(full["icn_min"]),
        ex_bound_slow=number(slow["bound_mean"]),
        ex_bound_full=number(full["bound_mean"]),
    )
    return out
