"""The intuition, numbers and tables of the chapter on many targets in closed loop: the authors'
later experiment, what their team script does, every assignment compared, a larger network.

:func:`intuition` computes the two pictures of the intuition; each ``glue_*`` function formats
one result (of :mod:`obslib.studies.many_targets`, or of a ledger entry's record, so that the
chapter shows the numbers of the entry's own computation) and glues it under the names the
chapter's prose uses.
"""

from __future__ import annotations

import numpy as np

from obslib import tracking
from obslib.bounds import pair_bounds
from obslib.claims.criteria import ALPHA
from obslib.claims.many_targets import ASSIGNMENT_WORDS, target_math, team_math
from obslib.formatting import count, listing, number, percent, setting
from obslib.later_experiment import TRACE_Q
from obslib.studies.many_targets import REFERENCE
from obslib.viz.style import pair_label

from ..glue import glue_texts
from ..prose import point
from ..report import record_table
from ..tables import rows_table
from .criteria import p_text

__all__ = ["SNAPSHOT_STEPS", "intuition", "glue_intuition", "glue_settings",
           "glue_snapshots", "glue_saved", "glue_code", "glue_comparison", "glue_network"]

#: The steps of the authors' saved snapshots of the assignment.
SNAPSHOT_STEPS = (1, 20, 40, 60, 80, 100)


# --------------------------------------------------------------------------------------------
# Intuition
# --------------------------------------------------------------------------------------------


def intuition(setup, target: int = 0, gap: int = 3) -> dict:
    """The two pictures of the intuition for one target of ``setup`` on its true path.

    Parameters
    ----------
    setup : obslib.tracking.TargetsSetup
        The experiment (its sensors, paths, noise and speed bound).
    target : int
        The target (0-based).
    gap : int
        The steps without a sensor in the second picture.

    Returns
    -------
    dict
        ``steps`` (2 to K: the target is on its circle from step 2), ``fixed`` and
        ``rechosen``: Theorem 4's bound at each of them of the pair best at step 2, kept, and of
        the best pair at each step; ``fixed_pair`` and its ``pair_label``; ``covs``: label -> the
        covariance after an update with the best pair (at its steady state) and after each of
        ``gap`` steps without a sensor; ``trace``, ``observed``: the trace after each step of a
        schedule with ``gap`` steps without a sensor, and which steps had one; ``estimate``.
    """
    S = setup.sensor_array
    path = setup.truth_array[1:-1, target]  # steps 2 .. K: on the circle
    W = pair_bounds(S, path, setup.u_max)  # (N, N, K)
    N = S.shape[0]
    flat = W.reshape(N * N, -1)
    i, j = divmod(int(np.argmax(flat[:, 0])), N)
    fixed, rechosen = W[i, j], flat.max(axis=0)
    o = path[0]
    best = S[[i, j]]
    P = np.array(setup.cov0, dtype=float)
    observed = np.array([True] * 6 + [False] * gap + [True] * 3)
    trace, covs = [], {}
    for k, seen in enumerate(observed):
        P = tracking.kalman.predict(P, setup.Q)
        if seen:
            _, P = tracking.kalman.update(o, P, best, tracking.euclidean_range(o, best), setup.R,
                                          measurement="range")
        if k == 5:
            covs["after an update with a pair"] = P
        elif not seen:
            n = k - 5
            covs[f"{n} step{'s' if n > 1 else ''} without a sensor"] = P
        trace.append(float(np.trace(P)))
    return {"steps": np.arange(2, path.shape[0] + 2), "fixed": fixed, "rechosen": rechosen,
            "fixed_pair": (i, j),
            "pair_label": pair_label(i, j), "target": target,
            "covs": covs, "trace": np.array(trace), "observed": observed, "estimate": o,
            "gap": gap}


def glue_intuition(scene: dict) -> None:
    """The intuition's numbers: the kept pair, its lowest bound and when, the lowest bound of
    the pair chosen afresh, and the trace before and after the steps without a sensor.

    Parameters
    ----------
    scene : dict
        :func:`intuition`'s result.
    """
    fixed, rechosen = scene["fixed"], scene["rechosen"]
    k = int(np.argmin(fixed))
    t, seen = scene["trace"], scene["observed"]
    before = int(np.flatnonzero(~seen)[0]) - 1
    last = int(np.flatnonzero(~seen)[-1])
    i, j = scene["fixed_pair"]
    glue_texts(
        i_target=target_math(scene["target"]),
        i_pair=team_math((i, j)),
        i_fixed_first=number(float(fixed[0])),
        i_fixed_min=number(float(fixed.min())),
        i_fixed_min_k=number(int(scene["steps"][k])),
        i_rechosen_min=number(float(rechosen.min())),
        i_gap=number(scene["gap"]),
        i_trace_before=number(t[before]),
        i_trace_after=number(t[last]),
        i_trace_back=number(t[last + 1]),
        i_trace_q=setting(TRACE_Q),
        snap_steps=listing(list(SNAPSHOT_STEPS)),
    )


# --------------------------------------------------------------------------------------------
# The experiment
# --------------------------------------------------------------------------------------------


def glue_settings(setup) -> None:
    """The settings of the later experiment as the authors' code runs it (``tab-12-settings``).

    Parameters
    ----------
    setup : obslib.tracking.TargetsSetup
        :data:`obslib.tracking.LATER_MULTI_TARGET`.
    """
    S, T = setup.sensor_array, setup.truth_array
    centres = T[0]
    turn = np.arctan2(*(T[2] - centres).T[::-1]) - np.arctan2(*(T[1] - centres).T[::-1])
    periods = [int(round(1 / a)) for a in (turn + np.pi) % (2 * np.pi) - np.pi]
    q, p0 = setup.Q[0][0], setup.cov0[0][0]
    rows = [
        ("sensors", ", ".join(f"$s_{{{i + 1}}}$ = {point(p)}" for i, p in enumerate(S))),
        ("targets and their paths",
         "; ".join(f"{target_math(l)} circles {point(c)}" for l, c in enumerate(centres))
         + r"; at step 1 each stands at its centre $c_l$, at step $k + 1$ at "
         r"$c_l + (\cos(k / W_l), \sin(k / W_l))$, with $W$ = "
         + listing([f"${w}$" for w in periods])
         + ": unit circles, the first move a jump from the centre onto the circle"),
        ("initial estimates", "; ".join(f"{target_math(l)}: {point(x)}"
                                        for l, x in enumerate(setup.estimate0))
         + f", each with the covariance {setting(p0)} $I$"),
        ("measurement", r"the range $z_i = \lVert p_i - o \rVert + n_i$ (not the half squared "
         r"range of Section V), $n_i \sim \mathcal N(0, \sigma^2)$, $\sigma$ = "
         f"{setting(setup.noise_std)}; the filter's $R$ = {setting(setup.R)} $I$"),
        ("filters", "one extended Kalman filter per target on its position; random-walk "
         f"prediction with $Q$ = {setting(q)} $I$; Joseph-form update"),
        (r"speed bound $u_{\max}$ in the bound", f"{setting(setup.u_max)}, Euclidean "
         "distances to the estimates"),
        ("steps", f"{number(setup.steps)}; the error and the trace of each target are logged "
         "before the step's update"),
        ("noise across assignments", "common: the draw for step $k$ and sensor $s_i$ is the "
         "same whichever assignment and target it serves"),
    ]
    glue_texts(tab_settings=rows_table(
        rows, "The later experiment as the authors' code runs it.", "tab-12-settings",
        headers=("setting", "value")),
        n_sensors=number(setup.n_sensors), n_targets=number(setup.n_targets),
        n_steps=number(setup.steps), i_q=setting(setup.Q[0][0]), umax=setting(setup.u_max))


def glue_snapshots(pairs, teams) -> None:
    """The first step's teams of the two runs shown, and how often the team run leaves a
    target without a sensor.

    Parameters
    ----------
    pairs, teams : obslib.tracking.TargetsResult
        One run of the unique pairs and one of the teams as the script runs them.
    """
    none = teams.unobserved  # (steps, L)
    glue_texts(
        snap_pairs_1="; ".join(f"{target_math(l)}: {team_math(t)}"
                               for l, t in enumerate(pairs.teams[0])),
        snap_teams_1="; ".join(f"{target_math(l)}: {team_math(t)}"
                               for l, t in enumerate(teams.teams[0])),
        snap_teams_none=count(int(none.any(axis=1).sum()), of=teams.steps),
        snap_teams_longest=number(int(max(
            (len(s) for l in range(none.shape[1])
             for s in "".join("x" if v else "." for v in none[:, l]).split(".")), default=0))),
    )


# --------------------------------------------------------------------------------------------
# The saved runs, the code
# --------------------------------------------------------------------------------------------


def glue_saved(verdicts: dict) -> None:
    """The tables and numbers of the three statements of the later material.

    Parameters
    ----------
    verdicts : dict
        Id -> the entry's record (:func:`obsbook.verdicts.glue_verdicts`), holding the three
        ``later-*`` entries.
    """
    u = verdicts["later-unique-pairs"].evidence
    t = verdicts["later-teams-unobserved"].evidence
    v = verdicts["later-teams-vs-pairs"].evidence
    glue_texts(
        tab_saved_pairs=record_table(verdicts["later-unique-pairs"], "tab-12-saved-pairs"),
        tab_saved_unobserved=record_table(verdicts["later-teams-unobserved"],
                                          "tab-12-saved-unobserved"),
        tab_saved_versus=record_table(verdicts["later-teams-vs-pairs"], "tab-12-saved-versus"),
        saved_step2=", ".join(number(x) for x in u["step2_saved"]),
        saved_like=percent(u["share_like"]),
        saved_tol=percent(u["tolerance"]),
        saved_unobserved=listing([count(int(x)) for x in t["saved"]]),
        saved_unobserved_total=count(t["saved_total"]),
        saved_steps=number(t["steps"]),
        saved_at_least=percent(t["share_runs_at_least_saved_total"]),
        teams_share=listing([percent(x) for x in t["share"]]),
        versus_same=count(v["same_way"]),
        versus_error=number(v["overall"]["mean_error"]),
        versus_trace=number(v["overall"]["mean_trace"]),
    )


def glue_code(verdicts: dict) -> None:
    """The tables and numbers of the findings about the team script.

    Parameters
    ----------
    verdicts : dict
        Id -> the entry's record (:func:`obsbook.verdicts.glue_verdicts`), holding
        ``later-code-rounds`` and ``later-code-singular``.
    """
    r = verdicts["later-code-rounds"].evidence
    s = verdicts["later-code-singular"].evidence
    glue_texts(
        tab_code_singular=record_table(verdicts["later-code-singular"], "tab-12-code-singular"),
        tab_code_rounds=record_table(verdicts["later-code-rounds"], "tab-12-code-rounds"),
        code_none=percent(s["share_none"]["logdet-teams"]),
        code_none_exact=percent(s["share_none"]["logdet-teams-exact"]),
        code_lost=count(s["lost"]["logdet-teams"]),
        code_lost_exact=count(s["lost"]["logdet-teams-exact"]),
        code_gap_rounds=number(r["gap_rounds"]),
        code_error_picked=number(r["picked_mean_error"]),
        code_error_rounds=number(r["as_run_vs_picked"]["mean_error"]),
    )


# --------------------------------------------------------------------------------------------
# Every assignment; the larger network
# --------------------------------------------------------------------------------------------

_VERDICT = {"better": "better", "worse": "worse", "same": "no clear difference"}


def glue_comparison(rows: list, n_seeds: int) -> None:
    """Every assignment on the later experiment against the unique pairs: the table over the
    targets (``tab-12-all``), the table per target (``tab-12-targets``) and the numbers of the
    prose.

    Parameters
    ----------
    rows : list of dict
        :func:`obslib.studies.many_targets.later_comparison`'s rows.
    n_seeds : int
        The runs of each assignment.
    """
    overall = [r for r in rows if r["target"] == "all"]
    table = []
    for r in overall:
        test = ("reference" if "verdict" not in r else
                f"{_VERDICT[r['verdict']]}: lower in "
                f"{count(r['vs_other_better'], of=r['vs_n'])} runs ({p_text(r['vs_p_wilcoxon'])})")
        table.append((ASSIGNMENT_WORDS[r["assignment"]], number(r["mean_error"]),
                      number(r["mean_trace"]), number(r["unobserved"]), count(r["lost"]),
                      test))
    per = {(r["assignment"], r["target"]): r for r in rows if r["target"] != "all"}
    names = [r["assignment"] for r in overall]
    L = max(t for _, t in per)
    targets = []
    for name in names:
        cells = []
        for l in range(1, L + 1):
            r = per[(name, l)]
            mark = "" if "verdict" not in r else f", {_VERDICT[r['verdict']]}"
            cells.append(f"{number(r['mean_error'])}{mark}")
        cells += [number(per[(name, l)]["unobserved"]) for l in range(1, L + 1)]
        table_row = (ASSIGNMENT_WORDS[name], *cells)
        targets.append(table_row)
    by = {r["assignment"]: r for r in overall}
    d, u = by["d-optimal-teams"], by[REFERENCE]
    n = number(n_seeds)
    glue_texts(
        tab_all=rows_table(
            table, f"Every assignment over {n} runs with common noise: the mean error and trace "
            "over steps 2 to 100 and the three targets, the target-steps without a sensor per "
            "run, the tracks lost (a target's mean error above "
            f"{setting(tracking.LOSS_THRESHOLD)}), and the paired comparison of the error with the "
            f"unique pairs (Wilcoxon signed-rank test at {setting(ALPHA)}).", "tab-12-all",
            headers=("assignment", "mean error", r"mean $\operatorname{tr}\Sigma$",
                     "target-steps without a sensor", "tracks lost",
                     "error against unique pairs")),
        tab_targets=rows_table(
            targets, f"Each target's mean error over {n} runs, with the paired comparison with "
            f"the unique pairs (Wilcoxon at {setting(ALPHA)}), and its steps without a sensor "
            "per run.",
            "tab-12-targets",
            headers=("assignment", *(f"error of {target_math(l)}" for l in range(L)),
                     *(f"steps without a sensor, {target_math(l)}" for l in range(L)))),
        all_n=n,
        all_pairs_error=number(u["mean_error"]),
        all_d_error=number(d["mean_error"]),
        all_a_error=number(by["a-optimal-teams"]["mean_error"]),
        all_d_wins=count(d["vs_other_better"], of=d["vs_n"]),
        all_prior_error=number(by["logdet-teams-prior"]["mean_error"]),
        all_prior_p=p_text(by["logdet-teams-prior"]["vs_p_wilcoxon"]),
        all_code_error=number(by["logdet-teams"]["mean_error"]),
        all_code_p=p_text(by["logdet-teams"]["vs_p_wilcoxon"]),
        all_optimal_error=number(by["optimal-pairs"]["mean_error"]),
        all_dpairs_error=number(by["d-optimal-pairs"]["mean_error"]),
        all_random_error=number(by["random"]["mean_error"]),
        all_e_lost=count(by["e-optimal-teams"]["lost"]),
        all_exact_lost=count(by["logdet-teams-exact"]["lost"]),
        all_runs3=count(3 * n_seeds),
    )


def glue_network(record, p: dict) -> None:
    """The comparison on the larger network and the network's sizes.

    Parameters
    ----------
    record : obslib.claims.Record
        The record of ``beyond-many-targets``.
    p : mapping
        The chapter's parameters (``net_sensors``, ``net_targets``, ``net_scenes``,
        ``net_steps``).
    """
    ev = record.evidence
    by = {r["assignment"]: r for r in ev["rows"]}
    glue_texts(
        tab_network=record_table(record, "tab-12-network"),
        net_n=number(p["net_sensors"]), net_l=number(p["net_targets"]),
        net_scenes_n=count(p["net_scenes"]), net_steps_n=number(p["net_steps"]),
        net_pairs_error=number(by[REFERENCE]["mean_error"]),
        net_d_error=number(by["d-optimal-teams"]["mean_error"]),
        net_prior_error=number(by["logdet-teams-prior"]["mean_error"]),
        net_code_error=number(by["logdet-teams"]["mean_error"]),
        net_code_none=number(by["logdet-teams"]["unobserved"]),
        net_random_error=number(by["random"]["mean_error"]),
        net_e_lost=count(by["e-optimal-teams"]["lost"], of=p["net_targets"] * p["net_scenes"]),
    )
