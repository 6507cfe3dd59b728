r"""The numbers, sentences and tables of the chapter on general assignment and submodularity
(Section IV-B, Theorems 7 and 8).

:func:`neg_trace_inverse_exact` is the one computation the chapter does by hand, in the visible
cell that checks a counterexample in exact rationals; each ``glue_*`` function formats the
result of one audit of :mod:`obslib.studies.submodularity` and glues it under the names the
chapter's prose uses.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pandas as pd

from obslib.formatting import count, fixed, number, setting

from ..glue import glue_texts
from ..prose import sensor_math, set_math
from ..report import record_table
from ..tables import numbered_table

__all__ = ["MEASURE_NAMES", "neg_trace_inverse_exact", "monotone_text", "submodular_text",
           "value_table", "glue_intuition", "glue_case1", "glue_case2", "glue_witnesses",
           "glue_lower_bound", "glue_measures", "glue_theorem8", "glue_by_hand", "glue_teams",
           "glue_logdet", "glue_record_tables", "EXERCISE_ROWS", "EXERCISE_THIRDS",
           "EXERCISE_N_SENSORS", "exercise_numbers", "glue_exercises"]

#: Theorem 8's measures, in words.
MEASURE_NAMES = {"trace": "trace", "logdet": "log det", "rank": "rank",
                 "trace_inverse": "trace of the inverse",
                 "neg_trace_inverse": "minus the trace of the inverse"}


def neg_trace_inverse_exact(*rows) -> Fraction:
    r""":math:`-\operatorname{tr} G^{-1}` for :math:`G = I + \sum_k r_k r_k^T`, in exact
    rationals (for 2 x 2 matrices :math:`\operatorname{tr} G^{-1} = \operatorname{tr} G /
    \det G`).

    Parameters
    ----------
    *rows : tuple of int
        The rows :math:`r_k = o - p_k`, each ``(x, y)``.

    Examples
    --------
    >>> neg_trace_inverse_exact((1, 1))
    Fraction(-4, 3)
    """
    g11 = 1 + sum(Fraction(x * x) for x, _ in rows)
    g22 = 1 + sum(Fraction(y * y) for _, y in rows)
    g12 = sum(Fraction(x * y) for x, y in rows)
    return -(g11 + g22) / (g11 * g22 - g12 * g12)


def monotone_text(w: dict) -> str:
    """A witness of non-monotonicity in words.

    Parameters
    ----------
    w : dict
        The witness: the set ``A``, the sensor ``x`` added, the values ``f_A`` and ``f_Ax``.
    """
    return (f"adding {sensor_math(w['x'])} to {set_math(w['A'])} lowers the bound from "
            f"{fixed(w['f_A'], 4)} to {fixed(w['f_Ax'], 4)}")


def submodular_text(w: dict) -> str:
    """A witness against diminishing returns in words.

    Parameters
    ----------
    w : dict
        The witness: the sets ``A`` and ``B`` (``A`` in ``B``), the sensor ``x`` and its gains
        ``gain_A`` and ``gain_B``.
    """
    return (f"the gain of {sensor_math(w['x'])} is {fixed(w['gain_A'], 4)} at "
            f"{set_math(w['A'])} but {fixed(w['gain_B'], 4)} at the larger {set_math(w['B'])}")


def value_table(case, caption: str, name: str) -> str:
    r"""The bound :math:`\omega` of every set of at least two sensors of a case of Fig. 3,
    recomputed, beside the printed value, as a numbered table.

    Parameters
    ----------
    case : obslib.studies.submodularity.CaseAudit
        The case's audit.
    caption, name : str
        The table's caption and label.
    """
    rows = []
    for idx, v in case.values.items():
        if len(idx) < 2:
            continue
        printed = case.printed.get(idx)
        rows.append({"set $S$": set_math(idx), "$\\omega(S)$ recomputed": fixed(v, 4),
                     "printed": "–" if printed is None else fixed(printed, 4),
                     "the same": "–" if printed is None else
                     ("yes" if case.matches[idx] else "no")})
    return numbered_table(pd.DataFrame(rows), caption, name)


def glue_intuition(logdet: dict, icn: dict, eps: float) -> None:
    r"""The intuition's gains in log det of :math:`s_3` joining a small and a large team, and the
    inverse condition numbers of the two teams.

    Parameters
    ----------
    logdet, icn : dict
        :math:`\log\det` and :math:`C^{-1}` by team (tuples of sensor indices).
    eps : float
        The prior.
    """
    glue_texts(
        i_eps=setting(eps),
        i_gain_small=number(logdet[(0, 2)] - logdet[(0,)]),
        i_gain_large=number(logdet[(0, 1, 2)] - logdet[(0, 1)]),
        i_icn_2=number(icn[(0, 1)]),
        i_icn_3=number(icn[(0, 1, 2)]),
    )


def glue_case1(case1, w13: float, w123: float) -> None:
    r"""Case 1 of Fig. 3: the table of the bound of every set (``tab-04-case1``) and the two
    values the paper compares.

    Parameters
    ----------
    case1 : obslib.studies.submodularity.CaseAudit
        The case's audit.
    w13, w123 : float
        :math:`\omega(\{s_1, s_3\})` and :math:`\omega(\{s_1, s_2, s_3\})`.
    """
    glue_texts(
        tab_04_case1=value_table(
            case1, "Case 1: the bound of every set of at least two sensors, recomputed, beside "
            "the printed values.", "tab-04-case1"),
        c1_13=fixed(w13, 4),
        c1_123=fixed(w123, 4),
        c1_matches="both printed values are right" if case1.all_match else
        "a printed value is wrong",
    )


def glue_case2(case2, gain_A: float, gain_B: float) -> None:
    """Case 2 of Fig. 3: the table of the bound of every set (``tab-04-case2``), the printed
    values that are right, and the two gains the paper compares.

    Parameters
    ----------
    case2 : obslib.studies.submodularity.CaseAudit
        The case's audit.
    gain_A, gain_B : float
        The gains of :math:`s_3` at the smaller and at the larger set.
    """
    wrong = [k for k in case2.printed if not case2.matches[k]]
    glue_texts(
        tab_04_case2=value_table(
            case2, "Case 2: the bound of every set of at least two sensors, recomputed, beside "
            "the printed values.", "tab-04-case2"),
        c2_n_right=count(len(case2.printed) - len(wrong), of=len(case2.printed)),
        c2_123=fixed(case2.values[(0, 1, 2)], 4),
        c2_13=fixed(case2.values[(0, 2)], 4),
        c2_gain_a=fixed(gain_A, 4),
        c2_gain_b=fixed(gain_B, 4),
    )


def glue_witnesses(geometry_audits: dict, case1, case2, min_size: int) -> None:
    """Every addition and nested triple in the two geometries of Fig. 3 (``tab-04-witnesses``),
    and the smallest witnesses against monotonicity and diminishing returns, in words.

    Parameters
    ----------
    geometry_audits : dict
        ``(case name, smallest set size) -> audit`` (:func:`obslib.audit_set_function`).
    case1, case2 : obslib.studies.submodularity.CaseAudit
        The two cases' audits.
    min_size : int
        The smallest set compared for the witnesses.
    """
    rows = [{"geometry": case, "sets compared": "all" if m == 0 else f"at least {m} sensors",
             "additions": count(a.n_additions), "lowering $\\omega$": count(a.n_decreases),
             "nested triples": count(a.n_triples),
             "against diminishing returns": count(a.n_submodular_violations)}
            for (case, m), a in geometry_audits.items()]
    w1 = case1.audits[min_size].monotone_witness
    w2 = case2.audits[min_size].submodular_witness
    w2m = case2.audits[min_size].monotone_witness
    glue_texts(
        tab_04_witnesses=numbered_table(
            pd.DataFrame(rows), "Every addition of a sensor and every nested triple in the two "
            "geometries of Fig. 3: how many lower the bound, and how many break diminishing "
            "returns.", "tab-04-witnesses"),
        w1_text=monotone_text(w1.as_dict()) if w1 else "no addition lowers it",
        w2_text=submodular_text(w2.as_dict()) if w2 else "no triple breaks them",
        w2m_text=monotone_text(w2m.as_dict()) if w2m else "no addition lowers it",
        w2_ga=fixed(w2.gain_A, 4) if w2 else "–",
        w2_gb=fixed(w2.gain_B, 4) if w2 else "–",
    )


def glue_lower_bound(lb, lb0, n_sensors: int, min_size: int) -> None:
    """The bound on random instances, with the speed bound and without it (the exact inverse
    condition number): how often it fails to be monotone or submodular.

    Parameters
    ----------
    lb, lb0 : obslib.studies.submodularity.LowerBoundAudit
        The audits with the speed bound and with :math:`u_{\\max} = 0`.
    n_sensors, min_size : int
        The sensors per instance and the smallest set compared.
    """
    glue_texts(
        lb_sensors=number(n_sensors),
        lb_min=number(min_size),
        lb_n=number(lb.n_instances),
        lb_mono=count(lb.n_not_increasing, of=lb.n_instances),
        lb_sub=count(lb.n_not_submodular, of=lb.n_instances),
        lb0_mono=count(lb0.n_not_increasing, of=lb0.n_instances),
        lb0_sub=count(lb0.n_not_submodular, of=lb0.n_instances),
        lb0_example=submodular_text(lb0.witness) if lb0.witness else "none",
    )


def glue_measures(values: dict, teams, eps: float) -> None:
    r"""The measures of :math:`G = O^T O + \varepsilon I` on teams of Case 2's geometry
    (``tab-04-measures-case2``).

    Parameters
    ----------
    values : dict
        ``team -> {measure name: value}``.
    teams : list of tuple
        The teams, in the table's order.
    eps : float
        The prior.
    """
    shown = ("trace", "logdet", "rank", "trace_inverse")
    table = pd.DataFrame([[set_math(t)] + [number(values[t][m]) for m in shown] for t in teams],
                         columns=["team"] + [MEASURE_NAMES[m] for m in shown])
    glue_texts(tab_04_measures_case2=numbered_table(
        table, f"The measures of $G = O^T O + \\varepsilon I$, $\\varepsilon = {setting(eps)}$, "
        "on teams of Case 2's geometry (no control row).", "tab-04-measures-case2"))


def glue_theorem8(rows) -> None:
    """Theorem 8's measures on random teams: the table of the instances in which a measure
    falls or rises with a sensor, or breaks diminishing or increasing returns
    (``tab-04-theorem8``), the pattern over the configurations, and the counts by measure.

    Parameters
    ----------
    rows : list
        :func:`obslib.studies.submodularity.theorem8_audit`, one row per measure and
        configuration.
    """
    totals = {}
    for r in rows:
        t = totals.setdefault(r.measure, dict(n=0, dec=0, inc=0, sub=0, sup=0))
        for key, v in (("n", r.n_instances), ("dec", r.n_not_increasing),
                       ("inc", r.n_not_decreasing), ("sub", r.n_not_submodular),
                       ("sup", r.n_not_supermodular)):
            t[key] += v
    audit = pd.DataFrame([{"measure": MEASURE_NAMES[m], "instances": number(t["n"]),
                           "lowered by an addition": count(t["dec"]),
                           "raised by an addition": count(t["inc"]),
                           "against diminishing returns": count(t["sub"]),
                           "against increasing returns": count(t["sup"])}
                          for m, t in totals.items()])
    holds = all(r.n_not_increasing == 0 and r.n_not_submodular == 0 for r in rows
                if r.measure in ("trace", "logdet", "rank"))
    fails = all(r.n_not_submodular > 0 for r in rows if r.measure == "neg_trace_inverse")
    by_measure = {}
    for m, t in totals.items():
        by_measure |= {f"th8_{m}_n": number(t["n"]), f"th8_{m}_dec": count(t["dec"], of=t["n"]),
                       f"th8_{m}_sub": count(t["sub"], of=t["n"]),
                       f"th8_{m}_sup": count(t["sup"], of=t["n"])}
    glue_texts(
        tab_04_theorem8=numbered_table(
            audit, "Theorem 8's measures on random teams: instances in which adding a sensor "
            "lowers or raises the measure, and in which some triple breaks diminishing returns "
            "(submodularity) or increasing returns (supermodularity).", "tab-04-theorem8"),
        th8_pattern="No: in each of the three configurations the trace, the log-determinant "
        "and the rank hold, and the trace of the inverse fails" if holds and fails else
        "Yes: the configurations of the check give different results",
        **by_measure,
    )


def glue_by_hand(gain_at_a: Fraction, gain_at_ab: Fraction, hand) -> None:
    """The counterexample worked by hand, and whether the exhaustive audit finds the same.

    Parameters
    ----------
    gain_at_a, gain_at_ab : fractions.Fraction
        The gains of the third sensor at the smaller and at the larger team.
    hand : obslib.submodularity.SetFunctionAudit
        The exhaustive audit of the three sensors.
    """
    w = hand.submodular_witness
    found = (w is not None and list(w.A) == [0] and list(w.B) == [0, 1] and w.x == 2
             and abs(w.gain_A - float(gain_at_a)) < 1e-12
             and abs(w.gain_B - float(gain_at_ab)) < 1e-12)
    glue_texts(
        hand_ga=f"${gain_at_a.numerator}/{gain_at_a.denominator}$",
        hand_gb=f"${gain_at_ab.numerator}/{gain_at_ab.denominator}$",
        hand_found="finds the same counterexample, and none smaller" if found else
        "finds a different smallest counterexample",
    )


def glue_teams(half) -> None:
    """The greedy team assignment against the optimum on tiny instances.

    Parameters
    ----------
    half : ndarray
        Greedy over optimum, one ratio per instance.
    """
    glue_texts(
        half_n=number(half.size),
        half_min=number(float(half.min())),
        half_median=number(float(np.median(half))),
        half_optimal=count(int(np.sum(half >= 1 - 1e-12)), of=half.size),
    )


def glue_logdet(domains, record) -> None:
    """Theorem 8's log determinant on its four matrices
    (:func:`obslib.studies.submodularity.logdet_domain_audit`): the number of exhaustive checks,
    and the ledger entry's table of the teams where it is ``-inf`` (``tab-04-logdet``).

    Parameters
    ----------
    domains : tuple of obslib.studies.submodularity.LogdetDomain
        The audit's result, one per matrix.
    record : obslib.claims.Record
        The entry ``thm8-logdet``, evaluated on the same audit.
    """
    glue_texts(
        ld_checks=number(sum(d.audit.n_instances for d in domains)),
        ld_matrices=number(len(domains)),
        tab_04_logdet=record_table(record, "tab-04-logdet"),
    )


def glue_record_tables(verdicts: dict) -> None:
    """The tables of the entries ``thm8-proof-similar`` (``tab-04-similar``) and
    ``conclusion-constant-factor`` (``tab-04-guarantees``), from the chapter's evaluated
    entries (:func:`obsbook.verdicts.glue_verdicts`)."""
    glue_texts(
        tab_04_similar=record_table(verdicts["thm8-proof-similar"], "tab-04-similar"),
        tab_04_guarantees=record_table(verdicts["conclusion-constant-factor"],
                                       "tab-04-guarantees"),
    )


#: Exercise 1: the rows ``o - p`` of three sensors ``a``, ``b``, ``c`` (the target at 0).
EXERCISE_ROWS = {"a": (1.0, 0.0), "b": (0.0, 1.0), "c": (1.0, 1.0)}
#: Exercise 3: third sensors added to the perfect cross of the intuition's first two sensors.
EXERCISE_THIRDS = ((5.0, 0.0), (-2.0, -2.0), (0.0, -1.0))
#: Exercise 2: the number of sensors per random instance of the rerun.
EXERCISE_N_SENSORS = 4


def exercise_numbers(P, o, eps: float, u_max: float, n_instances: int, seed: int,
                     min_size: int) -> dict:
    r"""The numbers of the chapter's exercises.

    Returns
    -------
    dict
        ``"by_hand"``: the gains of ``c`` (:data:`EXERCISE_ROWS`) at ``{a}`` and ``{a, b}`` in
        :math:`\log\det(O^T O + \varepsilon I)` and in the trace; ``"rerun"``: the lower bound
        audit with :data:`EXERCISE_N_SENSORS` sensors (instances not monotone, not
        submodular); ``"cross"``: :math:`\omega` of the intuition's pair ``P[:2]`` and with each
        sensor of :data:`EXERCISE_THIRDS` added.

    Parameters
    ----------
    P, o : ndarray
        The intuition's sensors and target.
    eps : float
        The prior of the log determinant.
    u_max : float
        The speed bound of the bound :math:`\omega`.
    n_instances, seed, min_size : int
        The random instances of the rerun exercise, their seed and the smallest team compared.
    """
    from obslib import lower_bound, measures
    from obslib.studies.submodularity import lower_bound_audit

    rows = {k: np.asarray(v) for k, v in EXERCISE_ROWS.items()}
    target = np.zeros(2)

    def f(names, m):
        return float(measures.measure(np.array([target - rows[k] for k in names]), target, m,
                                      eps=eps))

    by_hand = {m: {"at_a": f("ac", m) - f("a", m), "at_ab": f("abc", m) - f("ab", m)}
               for m in ("logdet", "trace")}
    lb = lower_bound_audit(n_instances, EXERCISE_N_SENSORS, seed, u_max, min_size)
    pair = np.asarray(P, dtype=float)[:2]
    cross = {"pair": float(lower_bound(pair, o, u_max)),
             "with": [float(lower_bound(np.vstack([pair, t]), o, u_max))
                      for t in EXERCISE_THIRDS]}
    return {"by_hand": by_hand,
            "rerun": {"n": lb.n_instances, "not_monotone": lb.n_not_increasing,
                      "not_submodular": lb.n_not_submodular},
            "cross": cross}


def glue_exercises(P, o, eps: float, u_max: float, n_instances: int, seed: int,
                   min_size: int) -> dict:
    r"""Glue the numbers of the chapter's exercises (:func:`exercise_numbers`); returns them.

    ``P``, ``o``, ``eps``, ``u_max``, ``n_instances``, ``seed`` and ``min_size`` are those of
    :func:`exercise_numbers`.
    """
    x = exercise_numbers(P, o, eps, u_max, n_instances, seed, min_size)
    h, r, c = x["by_hand"], x["rerun"], x["cross"]

    def vec(v):
        return "$(" + ", ".join(setting(float(t)) for t in v) + ")$"

    glue_texts(
        x1_a=vec(EXERCISE_ROWS["a"]), x1_b=vec(EXERCISE_ROWS["b"]), x1_c=vec(EXERCISE_ROWS["c"]),
        x1_eps=setting(eps),
        x1_ld_a=number(h["logdet"]["at_a"]), x1_ld_ab=number(h["logdet"]["at_ab"]),
        x1_tr_a=number(h["trace"]["at_a"]), x1_tr_ab=number(h["trace"]["at_ab"]),
        x2_n=setting(EXERCISE_N_SENSORS),
        x2_mono=count(r["not_monotone"], of=r["n"]),
        x2_sub=count(r["not_submodular"], of=r["n"]),
        x3_pair=number(c["pair"]), x3_u=setting(u_max),
        x3_thirds=", ".join(vec(t) for t in EXERCISE_THIRDS),
        x3_with=", ".join(number(v) for v in c["with"]),
    )
    return x
