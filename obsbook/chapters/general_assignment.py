r"""The intuition's gains, numbers and tables of the chapter on general assignment by greedy teams
(Section V-D, Fig. 9).

:func:`join_gains` computes what the intuition draws; each ``glue_*`` function formats one result
of :mod:`obslib.studies.general_assignment` and glues it under the names the chapter's prose uses.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from obslib.claims.general_assignment import FIG9_PUBLISHED_STD, direction_words
from obslib.formatting import count, fixed, listing, number, percent, setting, span
from obslib.measures import measure, measure_from_vectors
from obslib.studies import fig9_measure, general_assignment

from ..glue import glue_texts
from ..prose import point, sensor_math
from ..tables import numbered_table, rows_table

__all__ = ["join_gains", "glue_intuition", "glue_fig9", "glue_text_measure", "glue_priors",
           "glue_measures", "glue_optimum", "hand_gains", "glue_exercise_gains",
           "glue_exercise_prior"]

#: The exercise's target and sensors (by hand: rows of lengths 3, 4 and 3, two of them parallel).
HAND_TARGET = (0.0, 0.0)
HAND_SENSORS = ((3.0, 0.0), (0.0, 4.0), (-3.0, 0.0))


def join_gains(seed: int, side: float, eps_values, eps: float, n_join: int = 10,
               n_draws: int = 2000) -> tuple:
    r"""The median gain in :math:`\log\det(O^T O + \varepsilon I)` of each of ``n_join`` sensors
    joining a team in turn, over ``n_draws`` random teams in Fig. 9's square of side ``side``
    (drawn from ``numpy.random.default_rng(seed)``).

    Returns
    -------
    tuple
        ``(gains, base)``: the gains by prior of ``eps_values``, and the gains for ``eps``.
    """
    rng = np.random.default_rng(seed)
    rows = rng.uniform(0, side, (n_draws, 1, 2)) - rng.uniform(0, side, (n_draws, n_join, 2))
    first_k = np.tri(n_join + 1, n_join, -1, dtype=bool)  # row k: the first k sensors

    def median_gains(e):
        return np.median(np.diff(measure_from_vectors(rows, first_k, "logdet", e), axis=1),
                         axis=0)

    gains = {e: median_gains(e) for e in eps_values}
    return gains, gains[eps] if eps in gains else median_gains(eps)


def glue_intuition(base, eps: float, eps_values, gains: dict) -> None:
    """The gains of the first, second, third and last sensor to join a team, at the prior
    ``eps`` and at the largest prior compared, and that prior.

    Parameters
    ----------
    base : ndarray
        The gains at ``eps`` (:func:`join_gains`).
    eps : float
        The chapter's prior.
    eps_values : list of float
        The priors compared.
    gains : dict
        Prior of ``eps_values`` -> its gains (:func:`join_gains`).
    """
    big = gains[max(eps_values)]
    glue_texts(
        p_eps=setting(eps),
        gain_1=number(float(base[0])),
        gain_2=number(float(base[1])),
        gain_3=number(float(base[2])),
        gain_10=number(float(base[-1])),
        eps_big=setting(max(eps_values)),
        big_1=number(float(big[0])),
        big_10=number(float(big[-1])),
        n_join=number(len(base)),
    )


def glue_fig9(counts, N, even, eps: float, trials: int) -> None:
    """Greedy teams on Fig. 9's instances (``tab-08-fig9``): target 1's mean and spread, the
    evenness of every target's counts, and the sizes of the sweep.

    Parameters
    ----------
    counts : ndarray, shape (len(N), trials, L)
        :func:`obslib.studies.general_assignment.fig9_sweep`.
    N : ndarray
        The numbers of sensors.
    even : obslib.studies.general_assignment.Evenness
        :func:`obslib.studies.general_assignment.evenness` of ``counts``.
    eps : float
        The prior.
    trials : int
        The trials per number of sensors.
    """
    n_targets = counts.shape[2]
    fair = N / n_targets
    c1 = counts[:, :, 0]
    sd1 = c1.std(axis=1, ddof=1)
    rows = [
        ("target 1: largest distance of its mean from $N/L$",
         number(float(np.abs(c1.mean(axis=1) - fair).max()))),
        ("target 1: standard deviation over trials", span(sd1.min(), sd1.max())),
        ("any target: largest distance of its mean from $N/L$",
         number(float(even.mean_deviation))),
        ("the same, in standard errors of the mean", number(float(even.z.max()))),
        ("spread within a trial, over a random assignment's",
         span(even.relative.min(), even.relative.max())),
        ("smallest and largest team in any trial",
         f"{number(int(counts.min()))} and {number(int(counts.max()))}"),
    ]
    glue_texts(
        tab_fig9=rows_table(
            rows, f"Greedy teams on Fig. 9's instances, $\\varepsilon =$ {setting(eps)}, "
            f"{count(trials)} trials for each $N$ from {number(int(N[0]))} to "
            f"{number(int(N[-1]))}.", "tab-08-fig9"),
        rel_span=span(even.relative.min(), even.relative.max()),
        cmin=number(int(counts.min())),
        cmax=number(int(counts.max())),
        sd1_span=span(sd1.min(), sd1.max()),
        base_span=span(even.baseline.min(), even.baseline.max()),
        pub_sd=f"{fixed(FIG9_PUBLISHED_STD[0], 1)} to {fixed(FIG9_PUBLISHED_STD[1], 1)}",
        p_L=number(n_targets),
        p_Nmin=number(int(N[0])),
        p_Nmax=number(int(N[-1])),
        p_trials=number(trials),
    )


def _share1(counts) -> float:
    """The share of all sensors given to target 1."""
    return float(counts[..., 0].sum() / counts.sum())


def glue_text_measure(C: dict, even_text: dict, even, N, n_targets: int, eps: float) -> None:
    r"""The greedy with the measure the text names, :math:`\log\det` of
    :math:`\mathbb{O}(o, u_o)` with the control row, in each control direction tried, against
    the code's measure without the row and the book's prior (``tab-08-measure``).

    Parameters
    ----------
    C : dict
        :func:`obslib.studies.fig9_measure.fig9_measure_sweeps`.
    even_text : dict
        Control direction -> :func:`obslib.studies.general_assignment.evenness` of ``C["text"]``
        for it.
    even : obslib.studies.general_assignment.Evenness
        The evenness of ``C["prior"]``.
    N : ndarray
        The numbers of sensors.
    n_targets : int
        The targets.
    eps : float
        The prior.
    """
    code = general_assignment.evenness(C["code"], N, n_targets)
    u = setting(fig9_measure.FIG9_U_MAX)
    rows = [(f"the text's, $\\lVert u_o \\rVert$ = {u}, {direction_words(d)}",
             percent(_share1(C["text"][d])), span(e.relative.min(), e.relative.max()))
            for d, e in even_text.items()]
    rows += [("the code's, $\\log\\det(O^T O)$, undefined gains skipped",
              percent(_share1(C["code"])), span(code.relative.min(), code.relative.max())),
             (f"the book's, $\\log\\det(O^T O + \\varepsilon I)$, $\\varepsilon$ = {setting(eps)}",
              percent(_share1(C["prior"])), span(even.relative.min(), even.relative.max()))]
    worst = max(float(e.relative.max()) for e in even_text.values())
    degrees = [f"{number(int(round(np.degrees(d))))}°" for d in even_text if d is not None]
    glue_texts(
        tab_measure=rows_table(
            rows, "The greedy on Fig. 9's instances with three measures of a team: the text's, "
            "with a control row in each direction tried; the code's; and the book's prior. The "
            "spread of the counts within a trial is given over a random assignment's (below 1: "
            "more even than chance), its range over $N$.", "tab-08-measure",
            headers=("measure", "share of the sensors on target 1",
                     "spread within a trial over random")),
        u_norm=u,
        directions=listing(degrees),
        text_worst=number(worst),
        code_share=percent(_share1(C["code"])),
        code_lo=number(float(code.relative.min())),
    )


def glue_priors(within_eps: dict, compare_N, n_targets: int, compare_trials: int) -> None:
    """The spread of the counts within a trial for each prior and for a uniformly random
    assignment (``tab-08-prior``).

    Parameters
    ----------
    within_eps : dict
        Prior -> the mean spread within a trial, one per number of sensors.
    compare_N : list of int
        The numbers of sensors compared.
    n_targets, compare_trials : int
        The targets, and the trials per number of sensors.
    """
    eps_values = list(within_eps)
    spread = pd.DataFrame(
        {f"$N = {n}$": [number(float(within_eps[e][a])) for e in eps_values]
         + [number(general_assignment.random_spread(int(n), n_targets))]
         for a, n in enumerate(compare_N)},
        index=pd.Index([f"$\\varepsilon =$ {setting(e)}" for e in eps_values]
                       + ["uniformly random"], name="prior"),
    )
    glue_texts(
        tab_eps=numbered_table(
            spread, "Spread of the counts within a trial (mean over "
            f"{count(compare_trials)} trials) for three priors, and for a uniformly random "
            "assignment.", "tab-08-prior"),
        eps_small=setting(min(eps_values)),
    )


def glue_measures(within_m: dict, example: dict, compare_N, eps: float,
                  compare_trials: int) -> None:
    """The spread of the counts within a trial for each measure, and the targets' counts in one
    trial (``tab-08-measures``).

    Parameters
    ----------
    within_m : dict
        Measure -> the mean spread within a trial, one per number of sensors.
    example : dict
        Measure -> the targets' counts in one trial at the largest number of sensors.
    compare_N : list of int
        The numbers of sensors compared.
    eps : float
        The prior of the measures that take one.
    compare_trials : int
        The trials per number of sensors.
    """
    names = {
        "logdet": f"$\\log\\det G$, $\\varepsilon =$ {setting(eps)}",
        "neg_trace_inverse": f"$-\\operatorname{{tr}}(G^{{-1}})$, $\\varepsilon =$ {setting(eps)}",
        "trace": "$\\operatorname{tr}(O^T O)$",
        "rank": "$\\operatorname{rank}(O^T O)$",
    }
    table = pd.DataFrame(
        {f"$N = {n}$": {names[name]: number(float(w[a])) for name, w in within_m.items()}
         for a, n in enumerate(compare_N)}
        | {f"one trial at $N = {compare_N[-1]}$": {names[k]: listing([int(c) for c in v])
                                                   for k, v in example.items()}}
    ).rename_axis("measure")
    # at which sizes each measure spreads the sensors most evenly
    evenest = [min(within_m, key=lambda m: within_m[m][a]) for a in range(len(compare_N))]

    def sizes(name):
        ns = [int(n) for n, m in zip(compare_N, evenest) if m == name]
        return f"$N$ = {listing(ns)}" if ns else "no size compared"

    glue_texts(
        tab_measures=numbered_table(
            table, f"Spread of the counts within a trial (mean over {count(compare_trials)} "
            "trials) for each measure, and the five targets' counts in one trial.",
            "tab-08-measures"),
        evenest_nti=sizes("neg_trace_inverse"),
        evenest_logdet=sizes("logdet"),
    )


def glue_optimum(ratio) -> None:
    """The greedy team assignment against the optimum on tiny instances.

    Parameters
    ----------
    ratio : ndarray
        Greedy over optimum, one per instance.
    """
    glue_texts(
        n_inst=number(int(ratio.size)),
        r_min=number(float(ratio.min())),
        r_med=number(float(np.median(ratio))),
        r_opt=percent(float(np.mean(ratio >= 1 - 1e-12))),
    )


# ---------------------------------------------------------------------------------------------
# Exercises
# ---------------------------------------------------------------------------------------------


def hand_gains(eps: float) -> list:
    r"""The greedy on the exercise's one target and three sensors (:data:`HAND_TARGET`,
    :data:`HAND_SENSORS`) with :math:`\log\det(O^T O + \varepsilon I)`, round by round: the
    gain of each free sensor, and the sensor taken (the largest gain; ties: the smallest index).

    Parameters
    ----------
    eps : float
        The prior.

    Returns
    -------
    list of dict
        Per round, ``gains`` (free sensor -> gain) and ``pick``.

    Examples
    --------
    >>> [r["pick"] for r in hand_gains(1.0)]
    [1, 0, 2]
    """
    S, t = np.array(HAND_SENSORS), np.array(HAND_TARGET)
    team, rounds = [], []

    def value(idx):
        return measure(S[idx], t, "logdet", eps)

    while len(team) < len(S):
        base = value(team)
        gains = {i: value(team + [i]) - base for i in range(len(S)) if i not in team}
        pick = max(gains, key=lambda i: (gains[i], -i))
        rounds.append({"gains": gains, "pick": pick})
        team.append(pick)
    return rounds


def glue_exercise_gains(eps: float) -> list:
    """The numbers of the exercise that runs the greedy by hand on one target
    (:func:`hand_gains`): the positions, and every gain of every round.

    Parameters
    ----------
    eps : float
        The prior.

    Returns
    -------
    list of dict
        :func:`hand_gains`.
    """
    rounds = hand_gains(eps)
    texts = {"exg_target": point(HAND_TARGET), "exg_eps": setting(eps)}
    for k, p in enumerate(HAND_SENSORS):
        texts[f"exg_p{k + 1}"] = point(p)
    for r, rnd in enumerate(rounds, start=1):
        texts[f"exg_pick{r}"] = sensor_math(rnd["pick"])
        for i, g in rnd["gains"].items():
            texts[f"exg_r{r}_s{i + 1}"] = number(g)
    glue_texts(**texts)
    return rounds


def glue_exercise_prior(N, trials: int, seed: int, n_targets: int, side: float, eps: float,
                        even_text: dict, even, factor: float = 1e4) -> object:
    """The numbers of the exercise that reruns Fig. 9 with a prior ``factor`` times the
    chapter's: the spread of the counts within a trial over a random assignment's with that
    prior (:func:`obslib.studies.general_assignment.fig9_sweep`, what a rerun computes), and with
    the text's measure, which takes no prior.

    Parameters
    ----------
    N : ndarray
        The numbers of sensors.
    trials, seed, n_targets : int
        Fig. 9's trials per ``N``, seed and targets.
    side, eps : float
        The square's side and the chapter's prior.
    even_text : dict
        Control direction -> the evenness of the text's measure (no prior).
    even : obslib.studies.general_assignment.Evenness
        The evenness with the chapter's prior.
    factor : float
        How many times the chapter's prior.

    Returns
    -------
    obslib.studies.general_assignment.Evenness
        The evenness with the larger prior.
    """
    counts = general_assignment.fig9_sweep(N, trials, seed, n_targets, "logdet", factor * eps, side)
    big = general_assignment.evenness(counts, N, n_targets)
    worst = max(float(e.relative.max()) for e in even_text.values())
    glue_texts(
        exp_eps=setting(factor * eps),
        exp_factor=setting(factor),
        exp_span=span(big.relative.min(), big.relative.max()),
        exp_above=count(int((big.relative >= 1).sum()), of=len(big.relative)),
        exp_text=number(worst),
        exp_prior=("only what its sentence says of the prior changes"
                   if bool((big.relative < 1).all()) != bool((even.relative < 1).all()) else
                   "and what its sentence says of the prior stays as it is too"),
    )
    return big
