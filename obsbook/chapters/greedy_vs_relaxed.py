"""The example, numbers and tables of the chapter on the greedy against the relaxed matching
(Section V-C, Fig. 8).

:func:`example` picks the instance the intuition draws; each ``glue_*`` function formats one
result of :mod:`obslib.studies.greedy_vs_relaxed` and glues it under the names the chapter's
prose uses.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from obslib import (
    greedy_pair_assignment,
    optimal_pair_assignment,
    pair_bounds,
    relaxed_pair_assignment,
)
from obslib.formatting import count, fixed, listing, number, percent, setting, small, span
from obslib.studies.greedy_vs_relaxed import fig8_instance, fig8_summary, fig8_sweep
from obslib.studies.published import FIG8_PUBLISHED_L20

from ..glue import glue_texts
from ..prose import pair_math, sensor_math, triple_math
from ..tables import numbered_table, rows_table

__all__ = ["example", "glue_parameters", "glue_example", "glue_fig8", "glue_optimum",
           "glue_problem3", "glue_ordered", "glue_extended", "hand_instance",
           "glue_exercise_hand", "loose_instance", "glue_exercise_loose", "glue_exercise_speed"]


def _two_target_trials(seed: int, side: float, u_max: float, n_trials: int):
    """Fig. 8's first ``n_trials`` trials with two targets: ``(trial, sensors, targets, W,
    assignments)``, the assignments of the greedy, the optimum and the relaxed matching by
    name."""
    for trial in range(n_trials):
        S, T = fig8_instance(2, trial, seed, side)
        W = pair_bounds(S, T, u_max)
        yield trial, S, T, W, {"greedy": greedy_pair_assignment(W),
                               "optimal": optimal_pair_assignment(W),
                               "relaxed": relaxed_pair_assignment(W)}


def _example_trial(seed: int, side: float, u_max: float, n_trials: int) -> tuple:
    """The trial of :func:`example` and its instance."""
    best = None
    for trial, S, T, W, res in _two_target_trials(seed, side, u_max, n_trials):
        margin = min(res["optimal"].value - res["greedy"].value,
                     res["relaxed"].value - res["optimal"].value)
        if best is None or margin > best[0]:
            best = (margin, trial, S, T, W, res)
    return best[1:]


def example(seed: int, side: float, u_max: float, n_trials: int = 30) -> tuple:
    """Of Fig. 8's first ``n_trials`` trials with two targets (seed ``seed``, square of side
    ``side``, pair bounds for ``u_max``), the one where the greedy, the optimum and the relaxed
    value lie farthest apart (the largest of the smaller of the two gaps).

    Returns
    -------
    tuple
        ``(sensors, targets, W, assignments)``: the instance, its pair weights, and the greedy,
        optimal and relaxed assignments by name.
    """
    return _example_trial(seed, side, u_max, n_trials)[1:]


def glue_parameters(L_max: int, trials: int, optimum_max_L: int) -> None:
    """Fig. 8's sizes: the largest number of targets, the trials per size, and the largest
    size whose optimum is computed.

    Parameters
    ----------
    L_max, trials, optimum_max_L : int
        The chapter's parameters.
    """
    glue_texts(p_Lmax=number(L_max), p_trials=number(trials), p_optL=number(optimum_max_L))


def glue_example(W, assignments: dict) -> None:
    """The intuition's instance: the greedy's picks, the three totals, the optimum's pairs and
    the sensors the relaxed matching uses twice.

    Parameters
    ----------
    W : ndarray, shape (N, N, L)
        The instance's pair weights.
    assignments : dict
        The greedy, optimal and relaxed assignments by name (:func:`example`).
    """
    ex = assignments
    n = W.shape[0]
    used = np.bincount([k for i, j, _ in ex["relaxed"].triples for k in (i, j)], minlength=n)
    shared = [sensor_math(k) for k in np.flatnonzero(used > 1)]
    first = ex["greedy"].triples[0]
    glue_texts(
        n_assign=number(float(math.factorial(40) // 2 ** 20)),
        ex_first=triple_math(first),
        ex_first_w=number(float(W[first])),
        ex_second=triple_math(ex["greedy"].triples[1]),
        ex_g=number(ex["greedy"].value),
        ex_o=number(ex["optimal"].value),
        ex_r=number(ex["relaxed"].value),
        ex_opt_pairs=" and ".join(triple_math(t) for t in ex["optimal"].triples),
        ex_shared=" and ".join(shared) if shared else "no sensor",
    )


def glue_fig8(summary, trials: int, optimum_max_L: int) -> None:
    """Fig. 8's mean totals by number of targets (``tab-07-fig8``), the paper's numbers at
    :math:`L = 20` against ours in standard errors, and the range of greedy over relaxed.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The sweep's summary.
    trials, optimum_max_L : int
        The trials per size, and the largest size whose optimum is computed.
    """
    mean, std, L, ratio = summary.mean, summary.std, summary.L, summary.ratio
    has_opt = L <= optimum_max_L
    rows = pd.DataFrame(
        {
            "greedy": [number(x) for x in mean["greedy"]],
            "relaxed": [number(x) for x in mean["relaxed"]],
            "optimum": [number(x) if h else "\u2013" for x, h in zip(mean["optimum"], has_opt)],
            "greedy / relaxed": [number(x) for x in ratio],
            "greedy / optimum": [number(g / o) if h else "\u2013"
                                 for g, o, h in zip(mean["greedy"], mean["optimum"], has_opt)],
        },
        index=pd.Index(L, name="$L$"),
    )
    # the paper's L = 20 means against ours, in standard errors of our means
    i20 = int(np.flatnonzero(L == 20)[0]) if 20 in L else len(L) - 1
    se = {k: std[k][i20] / math.sqrt(trials) for k in ("greedy", "relaxed")}
    z = max(abs(mean[k][i20] - FIG8_PUBLISHED_L20[k]) / se[k] for k in se)
    glue_texts(
        tab_fig8=numbered_table(
            rows, f"Mean totals over {count(trials)} trials for each number of targets $L$ "
            f"($N = 2L$ sensors); the optimum of Problem 1 is computed up to "
            f"$L = {optimum_max_L}$.", "tab-07-fig8"),
        L_cmp=number(int(L[i20])),
        g20=fixed(mean["greedy"][i20], 2),
        r20=fixed(mean["relaxed"][i20], 2),
        p_g20=fixed(FIG8_PUBLISHED_L20["greedy"], 2),
        p_r20=fixed(FIG8_PUBLISHED_L20["relaxed"], 2),
        z20=number(float(z)),
        ratio_span=span(ratio[1:].min(), ratio[1:].max()) if len(L) > 1 else number(1.0),
        third_margin=number(float((3 * ratio).min())),
    )


def glue_optimum(summary, sweep: dict, L_max: int, optimum_max_L: int) -> None:
    """Where the gap lies: the greedy and the relaxed matching against the exact optimum, over
    the sizes where it is computed and trial by trial with two targets.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The sweep's summary.
    sweep : dict
        :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep`.
    L_max, optimum_max_L : int
        The largest number of targets, and the largest whose optimum is computed.
    """
    mean = summary.mean
    k = min(optimum_max_L, L_max)
    texts = {"opt_L": number(int(k))}
    if k >= 2:
        texts["gopt_lo"] = number(float((mean["greedy"][1:k] / mean["optimum"][1:k]).min()))
        texts["ropt_hi"] = number(float((mean["relaxed"][1:k] / mean["optimum"][1:k]).max()))
        # of the distance between the relaxed and the greedy means, the part above the optimum
        loose = ((mean["relaxed"][1:k] - mean["optimum"][1:k])
                 / (mean["relaxed"][1:k] - mean["greedy"][1:k]))
        texts["loose_lo"] = percent(float(loose.min()))
    if L_max >= 2 and optimum_max_L >= 2:  # the trials with two targets, one by one
        g2, o2, r2 = (sweep[key][1] for key in ("greedy", "optimum", "relaxed"))
        texts |= {"n2": number(len(g2)),
                  "n2_greedy_opt": count(int(np.sum(g2 >= o2 - 1e-12)), of=len(g2)),
                  "n2_rel_above": count(int(np.sum(r2 > o2 + 1e-12)), of=len(g2))}
    glue_texts(**texts)


def glue_problem3(upper, matching) -> None:
    """The relaxed matching against Problem 1's optimum and against a 0-1 program of Problem 3
    on the instances where the optimum is computed: the numbers of the ledger's entries
    ``problem3-upper-bound`` and ``problem3-matching``, formatted as they format them.

    Parameters
    ----------
    upper, matching : obslib.claims.Record
        The two entries, evaluated with the chapter's parameters.
    """
    ev = upper.evidence
    n = int(ev.get("n_instances", 0))
    glue_texts(
        p3_n=number(n),
        p3_below=count(int(ev.get("below", 0)), of=n),
        p3_equal=percent(float(ev.get("share_equal", 0.0))),
        p3_excess=percent(float(ev.get("largest_excess", 0.0))),
        p3_diff=small(float(matching.evidence.get("largest_relative_difference", 0.0))),
    )


def glue_ordered(summary, sweep: dict, trials: int) -> None:
    """Problem 3 as printed (unordered pairs) and as the authors' code solves it (ordered
    pairs), at a few sizes (``tab-07-ordered``), and their largest relative gap.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The means of both relaxations, ``relaxed`` and ``relaxed_ordered``.
    sweep : dict
        Both relaxations' values trial by trial, one row per number of targets.
    trials : int
        The trials per size.
    """
    mean, L = summary.mean, summary.L
    sel = [a for a, n in enumerate(L) if n == 2 or n % 5 == 0] or list(range(len(L)))
    rel, ordd = sweep["relaxed"], sweep["relaxed_ordered"]
    rows = pd.DataFrame(
        {
            "Problem 3 (mean)": [number(x, 4) for x in mean["relaxed"][sel]],
            "ordered pairs (mean)": [number(x, 4) for x in mean["relaxed_ordered"][sel]],
            "trials where ordered is larger": [
                count(int(np.sum(ordd[a] > rel[a] + 1e-12)), of=trials) for a in sel],
        },
        index=pd.Index(L[sel], name="$L$"),
    )
    gap = np.max(np.abs(mean["relaxed_ordered"] - mean["relaxed"]) / mean["relaxed"])
    larger = [int(np.sum(ordd[a] > rel[a] + 1e-12)) for a in sel]
    most = int(np.argmax(larger))
    glue_texts(
        ordered_most=count(larger[most], of=trials),
        ordered_most_L=number(int(L[sel][most])),
        tab_ordered=numbered_table(
            rows, "The relaxation as printed (unordered pairs) and as the authors' code solves "
            f"it (ordered pairs), {count(trials)} trials for each $L$.", "tab-07-ordered"),
        ordered_gap=percent(float(gap)),
    )


def glue_extended(ext: dict, trials_extended: int, summary) -> None:
    """The greedy and the relaxed matching on larger instances (``tab-07-extended``).

    Parameters
    ----------
    ext : dict
        :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep` at the larger sizes.
    trials_extended : int
        The trials per size.
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        Fig. 8's summary (its ratio at its largest size).
    """
    g_ext, r_ext = ext["greedy"].mean(axis=1), ext["relaxed"].mean(axis=1)
    rows = pd.DataFrame(
        {"$N$": [number(int(2 * n)) for n in ext["L"]],
         "greedy (mean)": [number(x) for x in g_ext],
         "relaxed (mean)": [number(x) for x in r_ext],
         "greedy / relaxed": [number(x) for x in g_ext / r_ext]},
        index=pd.Index(ext["L"], name="$L$"),
    )
    ratio = g_ext / r_ext
    steady = len(ratio) > 1 and bool(np.all(np.diff(ratio) > 0)) and ratio[0] > summary.ratio[-1]
    glue_texts(
        ext_trend="keeps growing" if steady else "does not grow steadily",
        short_L20=percent(float(1 - summary.ratio[-1])),
        short_last=percent(float(1 - ratio[-1])),
        L20=number(int(summary.L[-1])),
        tab_ext=numbered_table(
            rows, f"The greedy and the relaxed matching on larger instances, "
            f"{count(trials_extended)} trials each.", "tab-07-extended"),
        ext_ratio_last=number(float(g_ext[-1] / r_ext[-1])),
        ext_L_last=number(int(ext["L"][-1])),
        ratio_L20=number(float(summary.ratio[-1])),
    )


# ---------------------------------------------------------------------------------------------
# Exercises
# ---------------------------------------------------------------------------------------------


def hand_instance(seed: int, side: float, u_max: float, n_trials: int = 30) -> tuple:
    """An instance of Fig. 8 with two targets to solve by hand: of the first ``n_trials``
    trials, the first other than :func:`example`'s in which the greedy is not optimal (else the
    first other than it).

    Parameters
    ----------
    seed, side, u_max : as in :func:`example`
        Fig. 8's seed, the side of its square and the speed bound of the pair bounds.
    n_trials : int
        The trials looked at (at least two).

    Returns
    -------
    tuple
        ``(trial, W, assignments)``, as in :func:`example`.
    """
    skip = _example_trial(seed, side, u_max, n_trials)[0]
    first = None
    for trial, _, _, W, res in _two_target_trials(seed, side, u_max, n_trials):
        if trial == skip:
            continue
        if res["greedy"].value < res["optimal"].value * (1 - 1e-12):
            return trial, W, res
        first = first or (trial, W, res)
    if first is None:
        raise ValueError("n_trials must be at least 2")
    return first


def glue_exercise_hand(seed: int, side: float, u_max: float) -> tuple:
    """The numbers of the exercise that solves an instance of :func:`hand_instance` by hand:
    its twelve weights (``tab-07-exercise``), the greedy's two picks, the six assignments of
    Problem 1 and their totals, the optimum and the relaxed matching.

    Parameters
    ----------
    seed, side, u_max : as in :func:`example`
        Fig. 8's seed, the side of its square and the speed bound of the pair bounds.

    Returns
    -------
    tuple
        :func:`hand_instance`, and the six assignments as ``((pair 1, pair 2), total)``.
    """
    trial, W, res = hand_instance(seed, side, u_max)
    pairs = [(i, j) for i in range(4) for j in range(i + 1, 4)]
    weights = [(pair_math(i, j), number(float(W[i, j, 0])), number(float(W[i, j, 1])))
               for i, j in pairs]
    six = []
    for a in pairs:
        b = tuple(k for k in range(4) if k not in a)
        six.append(((a, b), float(W[a[0], a[1], 0] + W[b[0], b[1], 1])))
    g1, g2 = res["greedy"].triples
    shared = set(res["relaxed"].triples[0][:2]) & set(res["relaxed"].triples[1][:2])
    glue_texts(
        tab_ex07=rows_table(
            weights, f"The bounds $\\omega(s_i, s_j, t_l)$ of trial {trial} of Fig. 8 with two "
            "targets, four sensors.", "tab-07-exercise",
            headers=("pair", "target $t_1$", "target $t_2$")),
        exh_six=listing([f"{pair_math(*a)} for $t_1$ with {pair_math(*b)} for $t_2$, {number(v)}"
                         for (a, b), v in six]),
        exh_first=triple_math(g1),
        exh_first_w=number(float(W[g1])),
        exh_second=triple_math(g2),
        exh_second_w=number(float(W[g2])),
        exh_g=number(res["greedy"].value),
        exh_o=number(res["optimal"].value),
        exh_opt=" and ".join(triple_math(t) for t in res["optimal"].triples),
        exh_r=number(res["relaxed"].value),
        exh_rel=" and ".join(triple_math(t) for t in res["relaxed"].triples),
        exh_shared=(f"shares {sensor_math(min(shared))} between the two targets, which Problem 1 "
                    "forbids" if shared else "shares no sensor, so it is also an assignment of "
                    "Problem 1"),
    )
    return (trial, W, res), six


def loose_instance(n_targets: int) -> tuple:
    """Weights on which the relaxed matching is ``n_targets`` times the optimum of Problem 1:
    ``N = 2 L`` sensors, and each target ``l`` values only the pair of sensor 0 with sensor
    ``l + 1`` (weight 1; every other weight 0), so the pairs of Problem 3 can all share sensor 0
    and those of Problem 1 cannot.

    Parameters
    ----------
    n_targets : int
        The number of targets ``L`` (at least 2).

    Returns
    -------
    tuple
        ``(W, assignments)``, the greedy, optimal and relaxed assignments by name.

    Examples
    --------
    >>> W, res = loose_instance(3)
    >>> [round(res[k].value, 12) for k in ("greedy", "optimal", "relaxed")]
    [1.0, 1.0, 3.0]
    """
    if isinstance(n_targets, bool) or not isinstance(n_targets, int) or n_targets < 2:
        raise ValueError(f"n_targets must be an integer of at least 2, got {n_targets!r}")
    W = np.zeros((2 * n_targets, 2 * n_targets, n_targets))
    for l in range(n_targets):
        W[0, l + 1, l] = W[l + 1, 0, l] = 1.0
    return W, {"greedy": greedy_pair_assignment(W), "optimal": optimal_pair_assignment(W),
               "relaxed": relaxed_pair_assignment(W)}


def glue_exercise_loose(sweep: dict, n_targets: int = 4) -> tuple:
    """The numbers of the exercise that looks for a greedy below a third of the relaxed
    matching: the totals on :func:`loose_instance`, and the smallest ratio of the greedy to the
    relaxed matching over Fig. 8's instances.

    Parameters
    ----------
    sweep : dict
        :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep` of the chapter.
    n_targets : int
        The number of targets of the constructed instance.

    Returns
    -------
    tuple
        :func:`loose_instance`, and the smallest ratio on Fig. 8's instances.
    """
    W, res = loose_instance(n_targets)
    ratio = sweep["greedy"] / sweep["relaxed"]
    a, t = np.unravel_index(np.argmin(ratio), ratio.shape)
    glue_texts(
        exl_L=number(n_targets),
        exl_N=number(2 * n_targets),
        exl_last=sensor_math(n_targets),
        exl_g=number(res["greedy"].value),
        exl_o=number(res["optimal"].value),
        exl_r=number(res["relaxed"].value),
        exl_ratio=number(res["greedy"].value / res["relaxed"].value),
        exl_min=number(float(ratio[a, t])),
        exl_min_L=number(int(sweep["L"][a])),
        exl_n=number(int(ratio.size)),
    )
    return (W, res), float(ratio[a, t])


def glue_exercise_speed(summary, L_max: int, trials: int, seed: int, u_max: float, side: float,
                        factor: float = 10.0) -> dict:
    """The numbers of the exercise that reruns Fig. 8 with ``factor`` times the speed bound:
    the greedy over the relaxed matching at ``L = 2`` and at ``L = L_max``, with the chapter's
    speed bound and with the larger one (what a rerun with that value computes at these sizes:
    :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep` gives each size the same instances,
    whichever sizes it is asked for).

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The chapter's Fig. 8.
    L_max, trials, seed, u_max, side : as in the chapter
        Fig. 8's sizes, seed, speed bound and square.
    factor : float
        How many times the speed bound.

    Returns
    -------
    dict
        ``L`` -> (the ratio at the chapter's speed bound, the ratio at the larger one).
    """
    sizes = sorted({2, int(L_max)})
    fast = fig8_summary(fig8_sweep(sizes, trials, seed, factor * u_max, side))
    out = {L: (float(summary.ratio[list(summary.L).index(L)]), float(r))
           for L, r in zip(sizes, fast.ratio)}
    glue_texts(
        exs_u=setting(factor * u_max),
        exs_2=number(out[2][1]),
        exs_20=number(out[2][0]),
        exs_last=number(out[sizes[-1]][1]),
        exs_last0=number(out[sizes[-1]][0]),
        exs_L=number(sizes[-1]),
    )
    return out
