r"""The numbers and tables of the chapter on what the paper states but does not check, what the
authors' code does, and one question of the book.

Each ``glue_*`` function formats the result of one check of the chapter (the studies of
:mod:`obslib.studies.unchecked_statements`, :mod:`obslib.studies.eq4`, :mod:`obslib.studies.replay`,
:mod:`obslib.studies.hardness` and others, called with the arguments the ledger's checks use, so
that the chapter and the ledger share one computation) and glues it under the names the chapter's
prose uses.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from obslib.claims.general_assignment import direction_words
from obslib.claims.greedy_unique_pairs import NEAR_THIRD
from obslib.claims.misprints import MISPRINTS
from obslib.claims.unchecked_statements import N_SPREAD
from obslib.formatting import count, listing, number, percent, setting, small, span
from obslib.profiles import params
from obslib.studies import general_assignment, greedy_tightness, greedy_vs_relaxed
from obslib.studies.fig9_measure import FIG9_U_MAX
from obslib.studies.published import (
    CODE_ACCOUNT_PRINTED,
    CODE_REPOSITORY,
    CODE_URL_PRINTED,
    FIGURE_TOLERANCE,
)
from obslib.studies.replay import compare_replay

from ..glue import glue_texts
from ..prose import PUBLISHED_RUNS, pair_math
from ..tables import numbered_table, rows_table

__all__ = ["glue_team_constraint", "glue_one_sensor", "glue_misprints", "glue_typos",
           "glue_eq4_example", "glue_eq4", "glue_units", "glue_metric", "glue_jitter",
           "glue_code_link", "glue_replays", "glue_typicality", "glue_control_ball",
           "glue_reduction", "glue_reach", "glue_problem3", "glue_fig9_measures"]


def glue_team_constraint(constraint: dict, fig9: dict) -> None:
    """Greedy teams on Fig. 9's instances with the constraint of Problem 2 and with every sensor
    on every target (``tab-team-constraint``).

    Parameters
    ----------
    constraint : dict
        :func:`obslib.studies.unchecked_statements.team_constraint`.
    fig9 : dict
        Fig. 9's parameters (``compare_N``, ``compare_trials``, ``n_targets``).
    """
    rows = [{
        "$N$": number(int(n)),
        "most targets per sensor": number(int(constraint["targets_per_sensor"][k])),
        "team sizes": f"{constraint['team_min'][k]} to {constraint['team_max'][k]}",
        "total, Problem 2 (mean)": number(float(constraint["constrained"][k])),
        "total, every sensor on every target (mean)":
            number(float(constraint["unconstrained"][k])),
    } for k, n in enumerate(fig9["compare_N"])]
    glue_texts(
        tab_team_constraint=numbered_table(
            pd.DataFrame(rows), f"Greedy teams on Fig. 9's instances "
            f"($L = {fig9['n_targets']}$, {number(fig9['compare_trials'])} trials per $N$): the "
            "constraint of Problem 2 against every sensor on every target; totals of "
            "$\\log\\det(O^T O + \\varepsilon I)$ over the targets.", "tab-team-constraint"),
        tc_most=number(int(max(constraint["targets_per_sensor"]))),
    )


def glue_one_sensor(one: dict, n_geometries: int) -> None:
    """One sensor with a known control: how well it observes the target.

    Parameters
    ----------
    one : dict
        :func:`obslib.studies.unchecked_statements.one_sensor_conditioning`.
    n_geometries : int
        The random scenes, each with a control drawn in the disc.
    """
    glue_texts(
        one_n=number(n_geometries),
        one_max=number(float(one["exact"].max())),
        one_half=percent(float(one["share_above_half"])),
        one_best=percent(float(np.mean(one["best"] >= 1))),
    )


def glue_misprints() -> None:
    """The paper's misprints, as printed and as the book reads them, in the order of the paper
    (``tab-paper-typos``, the rows of :data:`obslib.claims.misprints.MISPRINTS`), and how many
    there are."""
    glue_texts(
        tab_paper_typos=rows_table(
            MISPRINTS, "The misprints of notation, indexing and wording, in the order of the "
            "paper, and how the book reads them.", "tab-paper-typos",
            headers=("printed", "read as")),
        typo_count=number(len(MISPRINTS)),
    )


def glue_typos(chosen) -> None:
    """Algorithm 1's pairs on an instance with a sensor too many, target by target.

    Parameters
    ----------
    chosen : obslib.PairAssignment
        The greedy's assignment.
    """
    glue_texts(
        typo_pairs=" ".join(f"$t_{{{l + 1}}}$ gets {pair_math(i, j)};" for i, j, l in
                            sorted(chosen.triples, key=lambda t: t[2]))[:-1],
    )


def glue_eq4_example(printed: float, derived: float, worst: float) -> None:
    """The matrix as derived (Eq. (4)) against Eq. (5) on two perpendicular sensors: Theorem 1's
    bound,
    the derived matrix's worst case in closed form and on a grid of the disc.

    Parameters
    ----------
    printed, derived, worst : float
        The three values.
    """
    glue_texts(eq4_printed=number(float(printed)), eq4_derived=number(float(derived)),
               eq4_grid=number(float(worst)))


def glue_eq4(audit: dict, below: int, n_geometries: int, n_refine: int, u_max: float) -> None:
    """The derived matrix's worst case over Theorem 1's bound in random scenes, by size of the
    scene (``tab-eq4``).

    Parameters
    ----------
    audit : dict
        Side of the scene -> the ratios (:func:`obslib.studies.eq4.random_scene_audit`).
    below : int
        The refined scenes where the grid falls below the closed form.
    n_geometries, n_refine : int
        The scenes per side, and the scenes refined.
    u_max : float
        The speed bound.
    """
    rows = [{
        "side of the scene (length units)": number(int(side)),
        "median ratio": number(float(np.median(r))),
        "smallest ratio": number(float(r.min())),
    } for side, r in audit.items()]
    glue_texts(
        tab_eq4=numbered_table(
            pd.DataFrame(rows), f"The derived matrix's worst case over the disc divided by "
            f"Theorem 1's bound, in {number(n_geometries)} random scenes of 2 to 6 sensors per "
            f"side ($u_{{\\max}} =$ {setting(u_max)}).", "tab-eq4"),
        eq4_below=count(int(below), of=n_refine),
        eq4_min1=number(float(audit[1.0].min())),
        eq4_med100=number(float(np.median(audit[100.0]))),
    )


def glue_units(u: dict) -> None:
    """The experiments' bound in two units of length (``tab-units``): at step 1 of the published
    circle run, and the share of its logged steps whose best pair changes with the unit.

    Parameters
    ----------
    u : dict
        :func:`obslib.studies.experiment_details.unit_dependence`.
    """
    f = setting(u["factor"])

    def pair(p):
        return f"$(s_{{{p[0] + 1}}}, s_{{{p[1] + 1}}})$"

    rows = [
        ("best pair's bound at step 1, lengths as logged", number(u["first_bound"])),
        (f"the same, every length multiplied by {f}", number(u["first_bound_scaled"])),
        ("best pair at step 1, lengths as logged and multiplied",
         f"{pair(u['first_pair'])} and {pair(u['first_pair_scaled'])}"),
        ("logged steps whose best pair changes with the unit", percent(u["changed"])),
        ("largest change of a Euclidean bound with the unit", small(u["euclidean_gap"], 1e-12)),
    ]
    glue_texts(
        tab_units=rows_table(
            rows, "The experiments' bound (Mahalanobis lengths) at the logged estimates of the "
            f"published circle run of strategy (1), as logged and with the sensors, the "
            f"estimates and $u_{{\\max}}$ multiplied by {f} and the covariances by "
            f"{setting(u['factor'] ** 2)}: the same scene in another unit of length.",
            "tab-units"),
        units_factor=f,
        units_first=number(u["first_bound"]),
        units_first_scaled=number(u["first_bound_scaled"]),
        units_changed=percent(u["changed"]),
    )


def glue_metric(choices: dict) -> None:
    """Where the published runs follow the mixed score, and where Theorem 4 in consistent
    coordinates chooses the same pair (``tab-metric``).

    Parameters
    ----------
    choices : dict
        Published run -> :func:`obslib.studies.experiment_details.metric_choices`.
    """
    rows = [{
        "run": PUBLISHED_RUNS[name],
        "logged pair is the mixed score's choice": percent(m["logged_match"]),
        "whitened (Mahalanobis) choice agrees": percent(m["agree_whitened"]),
        "Euclidean choice agrees": percent(m["agree_euclidean"]),
    } for name, m in choices.items()]
    glue_texts(
        tab_metric=numbered_table(
            pd.DataFrame(rows), "Share of the logged steps of the published runs where the "
            "logged pair is the mixed score's choice, and where Theorem 4 in consistent "
            "coordinates chooses the same pair.", "tab-metric"),
        metric_logged=percent(choices["best-pair"]["logged_match"]),
        metric_white=percent(choices["best-pair"]["agree_whitened"]),
        metric_white_adv=percent(choices["adversarial"]["agree_whitened"]),
    )


def glue_jitter(ratios, fractions, margin: dict, n_jitter: int) -> None:
    """The greedy over the optimum on jittered copies of the near-tight layout, by size of the
    jitter (``tab-jitter``), and the layout's own ratio and margin.

    Parameters
    ----------
    ratios : ndarray
        One row of ratios per jitter (:func:`obslib.studies.greedy_tightness.jitter_ratios`).
    fractions : list of float
        The jitters, fractions of the layout's spread.
    margin : dict
        :func:`obslib.studies.greedy_tightness.first_pick_margin` of the layout.
    n_jitter : int
        The copies per jitter.
    """
    jitter = greedy_tightness.jitter_summary(ratios, fractions)
    # the smallest jitter that lifts the greedy above half the optimum in most copies
    lifted = next((r for r in jitter if r["below_half"] < 0.5), jitter[-1])
    rows = [{
        "jitter (fraction of the spread)": setting(r["fraction"]),
        "median greedy / optimum": number(r["median"]),
        "5th percentile": number(r["q05"]),
        "95th percentile": number(r["q95"]),
        "copies below 1/2": percent(r["below_half"]),
    } for r in jitter]
    glue_texts(
        tab_jitter=numbered_table(
            pd.DataFrame(rows), f"Greedy over optimum for {number(n_jitter)} jittered copies of "
            "the near-tight layout at each size of the jitter.", "tab-jitter"),
        t6_ratio=number(float(margin["ratio"])),
        t6_near=setting(NEAR_THIRD),
        t6_margin=number(float(margin["relative_margin"])),
        t6_small=setting(fractions[0]),
        t6_pct_jitter=percent(lifted["fraction"]),
        t6_pct_below=percent(lifted["below_half"]),
    )


def glue_code_link(commits) -> None:
    """Every change recorded in the history of the repository that holds the code and the saved
    runs today (its commits), with its date and author (``tab-code-link``), and the two
    addresses.

    Parameters
    ----------
    commits : tuple
        :func:`obslib.studies.published.code_commits`, newest first.
    """
    rows = [(date[:10], f"`{commit[:7]}`", f"`{author}`")
            for commit, date, author in reversed(commits)]
    glue_texts(
        tab_code_link=rows_table(
            rows, "The changes recorded in the history of the repository that holds the code "
            "and the saved runs today, oldest first, with their authors.", "tab-code-link",
            headers=("date", "identifier", "author")),
        code_printed=f"`{CODE_URL_PRINTED}`",
        code_account=f"`{CODE_ACCOUNT_PRINTED}`",
        code_found=f"`{CODE_REPOSITORY}`",
    )


def glue_replays(comparison: dict, checks: dict) -> None:
    """What the replay of each published run checks beyond the noise it was given
    (``tab-replay``), and the largest difference from the logs.

    Parameters
    ----------
    comparison : dict
        Run -> :func:`obslib.studies.replay.compare_replay`.
    checks : dict
        Run -> :func:`obslib.studies.replay.independent_checks`.
    """
    runs = {"best-pair": "strategy (1), best pair", "best-partner": "strategy (2), best partner",
            "adversarial": "the adversarial run"}
    rows = [{
        "run": runs[name],
        "steps (pairs compared)": number(checks[name]["pairs"]),
        "bounds": number(checks[name]["bounds"]),
        "covariance entries": number(checks[name]["covariances"]),
        "target positions and moves": count(checks[name]["target"]),
        "noise entries read from another run": (f"{count(checks[name]['shared_noise'])} of "
                                                f"{number(checks[name]['read_noise'])}"),
        "largest difference": small(c.largest, 1e-10),
    } for name, c in comparison.items()]
    caption = ("What the replay of each published run checks beyond the noise it was given: the "
               "logged numbers compared, the noise entries recovered from another run's log, and "
               "the largest difference from the log.")
    glue_texts(
        tab_replay=numbered_table(pd.DataFrame(rows), caption, "tab-replay"),
        replay_fixed_steps=number(compare_replay("fixed-pair").steps),
        replay_largest=small(max(c.largest for c in comparison.values()), 1e-10),
    )


def glue_typicality(typical: dict, mine, n_seeds: int) -> None:
    """Where the published adversarial run's mean bound falls among runs with random noise, and
    its replay's pair switches.

    Parameters
    ----------
    typical : dict
        :func:`obslib.studies.replay.seed_typicality`.
    mine : obslib.tracking.TrackingResult
        The replay of the published run.
    n_seeds : int
        The random seeds.
    """
    glue_texts(
        typ_pub=number(float(typical["published"])),
        typ_median=number(float(typical["quantiles"][50])),
        typ_pct=number(float(typical["percentile"])),
        typ_near=percent(float(typical["within_tolerance"])),
        typ_tol=percent(float(FIGURE_TOLERANCE)),
        typ_n=number(n_seeds),
        typ_switches=number(int(mine.switches)),
    )


def glue_control_ball(gap: float, entrapment: dict, n_seeds: int, n_radii: int,
                      n_angles: int) -> None:
    """The adversary's controls: how much lower a fine grid of the disc gets the target's
    objective, and the entrapment with each set of controls.

    Parameters
    ----------
    gap : float
        The largest lowering of the objective per step.
    entrapment : dict
        Control set -> :func:`obslib.studies.experiment_details.control_set_entrapment`.
    n_seeds, n_radii, n_angles : int
        The runs, and the polar grid of the disc.
    """
    each = {}
    for name, d in entrapment.items():
        each[f"ball_trap_{name}"] = count(round(d["entrapped"] * n_seeds), of=n_seeds)
        each[f"ball_bound_{name}"] = number(float(d["bound_mean"]))
    glue_texts(
        ball_gap=small(float(gap), 1e-12),
        ball_n=number(n_seeds),
        **each,
        ball_grid=f"{number(n_radii)} radii and {number(n_angles)} angles",
    )


def glue_reduction(reduction: dict) -> None:
    """The reduction from 3-dimensional matching against brute force.

    Parameters
    ----------
    reduction : dict
        :func:`obslib.studies.hardness.reduction_check`.
    """
    glue_texts(red_agree=count(reduction["agree"], of=reduction["n"]),
               red_matching=count(reduction["with_matching"]))


def glue_reach(exact: dict, time_budget: float) -> None:
    """The exact optimum of Problem 1 by size, within the time budget (``tab-reach``), and what
    it says of Fig. 8.

    Parameters
    ----------
    exact : dict
        :func:`obslib.studies.hardness.exact_optimum_study`.
    time_budget : float
        The seconds the solver may take on one instance.
    """
    reach, spread, top = exact["reach"], exact["spread"], exact["largest_solved"]
    rows = [{
        "$L$": number(r["L"]),
        "$N$": number(r["N"]),
        f"solved within {setting(time_budget)} s": "yes" if r["solved"] else "no",
        "greedy": number(r["greedy"]) if r["solved"] else "–",
        "optimum": number(r["optimum"]) if r["solved"] else "–",
        "relaxed (Problem 3)": number(r["relaxed"]) if r["solved"] else "–",
    } for r in reach]
    fig8_L = params(greedy_vs_relaxed.NOTEBOOK)["L_max"]
    within = f"within {setting(time_budget)} s"
    if all(r["solved"] for r in reach) and top >= fig8_L:
        reach_text = (f"The optimum is found {within} at every size of Fig. 8, which could have"
                      " plotted it instead of the relaxed bound.")
    elif top:
        reach_text = f"The optimum is found {within} up to $L$ = {number(top)}."
    else:
        reach_text = f"The optimum is not found {within} at any size tried."
    done = np.isfinite(spread)
    if done.any():
        reach_text += (f" At $L$ = {number(top)}, over {count(int(done.sum()), of=N_SPREAD)}"
                       f" instances solved, the greedy collects"
                       f" {span(float(spread[done].min()), float(spread[done].max()))} of the"
                       f" optimum, {number(float(spread[done].mean()))} on average.")
    glue_texts(
        tab_reach=numbered_table(
            pd.DataFrame(rows), "The exact optimum of Problem 1 on one random Fig. 8 instance "
            "per size, with the greedy's value and the relaxed upper bound Fig. 8 plots.",
            "tab-reach"),
        np_reach=reach_text,
    )


def glue_problem3(sweep: dict, unordered: float, ordered: float, trials: int) -> None:
    """Problem 3 as printed and as solved: the two relaxations on Fig. 8's instances
    (``tab-problem3``) and on a small example.

    Parameters
    ----------
    sweep : dict
        :func:`obslib.studies.unchecked_statements.problem3_relaxations`.
    unordered, ordered : float
        The example's two relaxed values.
    trials : int
        The instances per size.
    """
    excess = sweep["excess"]
    means, means_ordered = sweep["relaxed"].mean(axis=1), sweep["relaxed_ordered"].mean(axis=1)
    shift = float(np.abs(means_ordered - means).max())  # what Fig. 8 plots: the means per L
    rows = [{
        "$L$": number(int(L)),
        "Problem 3 (mean)": number(float(sweep["relaxed"][a].mean())),
        "ordered pairs (mean)": number(float(sweep["relaxed_ordered"][a].mean())),
        "trials where ordered is larger": percent(float(np.mean(excess[a] > 1e-12))),
        "largest excess": percent(float(excess[a].max())),
    } for a, L in enumerate(sweep["L"])]
    glue_texts(
        tab_problem3=numbered_table(
            pd.DataFrame(rows), f"The two relaxations on {number(trials)} Fig. 8 instances per "
            "$L$ ($N = 2L$).", "tab-problem3"),
        p3_unordered=number(float(unordered)),
        p3_ordered=number(float(ordered)),
        p3_excess_top=percent(float(excess[-1].max())),
        p3_shift=number(shift),
        p3_shift_pct=percent(shift / float(means.max())),
        p3_L_top=number(int(sweep["L"][-1])),
    )


def glue_fig9_measures(sweeps: dict, fig9: dict) -> None:
    """Greedy teams on Fig. 9's instances with every measure compared: the text's with a
    control row in each direction tried, the code's with each rule for undefined gains, and the
    book's prior; the share of the sensors on target 1 and the evenness of the counts
    (``tab-fig9-measures``).

    Parameters
    ----------
    sweeps : dict
        :func:`obslib.studies.fig9_measure.fig9_measure_sweeps`.
    fig9 : dict
        Fig. 9's parameters.
    """
    N, L = range(fig9["N_min"], fig9["N_max"] + 1), fig9["n_targets"]
    u = setting(FIG9_U_MAX)
    measures = [(rf"the text's, $\log\det(O^T O + u_o u_o^T)$, $\lVert u_o \rVert = {u}$, "
                 f"{direction_words(d)}", C) for d, C in sweeps["text"].items()]
    measures += [
        (r"the code's, $\log\det(O^T O)$, undefined gains skipped", sweeps["code"]),
        (r"the code's, $\log\det(O^T O)$, the first undefined gain taken",
         sweeps["code-first"]),
        (rf"the book's, $\log\det(O^T O + \varepsilon I)$, "
         rf"$\varepsilon = {setting(fig9['eps'])}$", sweeps["prior"]),
    ]

    def spread(C):
        return general_assignment.evenness(C, N, L).relative

    def share(C):
        return float(C[..., 0].sum() / C.sum())

    rows = [(name, percent(share(C)), span(float(spread(C).min()), float(spread(C).max())))
            for name, C in measures]
    text_max = max(float(spread(C).max()) for C in sweeps["text"].values())
    code = spread(sweeps["code"])
    glue_texts(
        tab_fig9_measures=rows_table(
            rows, f"Greedy teams on Fig. 9's instances ($L = {L}$, $N$ from {fig9['N_min']} to "
            f"{fig9['N_max']}, {number(fig9['trials'])} trials each) with each measure; the "
            f"spread is the standard deviation of the {number(L)} counts within a trial over "
            "that of a uniformly random assignment (below 1: more even than chance).",
            "tab-fig9-measures",
            headers=("measure", "share of the sensors on target 1",
                     "spread within a trial over random")),
        f9_u=u,
        f9_dirs=listing([f"{number(int(round(np.degrees(d))))}°" for d in sweeps["text"]
                         if d is not None]),
        f9_lit_share=percent(share(sweeps["code"])),
        f9_text_max=number(text_max),
        f9_code_spread=span(float(code.min()), float(code.max())),
    )
