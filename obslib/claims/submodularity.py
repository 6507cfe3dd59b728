"""Claims of Section IV-B: Theorem 7 (Cases 1 and 2, Fig. 3) and Theorem 8 (notebook 04).

Each check re-decides its claim from numbers: the Fig. 3 geometries recomputed with
:func:`obslib.lower_bound` (SVD), the exhaustive witness finder of
:mod:`obslib.submodularity`, and the Theorem 8 measures of :mod:`obslib.measures` on seeded
random instances whose sizes come from the profile.
"""

from __future__ import annotations

from functools import lru_cache

from ..studies import submodularity as sm
from ..studies.published import THEOREM7_PRINTED_WITNESS
from ..profiles import params
from ._ledger import Finding, claim

NB = "04_submodularity"

LABELS = ("s1", "s2", "s3", "s4")


def _set(idx) -> str:
    return "{" + ",".join(LABELS[i] for i in idx) + "}"


def _case_evidence(ca: sm.CaseAudit) -> dict:
    return {
        "values": {_set(k): v for k, v in ca.values.items()},
        "printed": {_set(k): v for k, v in ca.printed.items()},
        "matches": {_set(k): v for k, v in ca.matches.items()},
        "printed_sides": list(ca.printed_sides),
        "our_sides": list(ca.our_sides),
        "shows_with_printed": ca.shows_with_printed,
        "shows_with_ours": ca.shows_with_ours,
        "audits": {str(m): a.as_dict() for m, a in ca.audits.items()},
    }


@lru_cache(maxsize=8)
def _case(case: str, u_max: float, min_size: int) -> sm.CaseAudit:
    return sm.case_audit(case, min_sizes=tuple(sorted({0, min_size})), u_max=u_max)


@claim(
    id="thm7-case1",
    where="Theorem 7, Case 1 (Sec. IV-B, Fig. 3(a))",
    title=r"Fig. 3(a): adding $s_2$ to $\{s_1, s_3\}$ lowers the bound (not monotone).",
    statement=r"With $s_1 = (0,0)$, $s_2 = (2\sqrt3,-9)$, $s_3 = (\sqrt3,3)$, target "
    r"$t_1 = (\sqrt3,1)$ and $u_{\max} = 1$, $\omega(\{s_1,s_3\}) > \omega(\{s_1,s_2,s_3\})$: "
    "the lower bound is not monotone increasing.",
    paper=r"$\omega(\{s_1,s_3\}) = 0.5345 > \omega(\{s_1,s_2,s_3\}) = 0.1823$.",
    notebook=NB,
)
def _thm7_case1(profile: str) -> Finding:
    p = params(NB, profile)
    ca = _case("case1", p["u_max"], p["min_size"])
    a, b = ca.our_sides
    match = "both printed values match" if ca.all_match else "the printed values do NOT all match"
    shows = ("adding s2 lowers the bound, so it is not monotone" if ca.shows_with_ours
             else "adding s2 does not lower the bound: no counter-example")
    w = ca.audits[p["min_size"]].monotone_witness
    smallest = ""
    printed = THEOREM7_PRINTED_WITNESS["case1"]
    if w is not None and (w.A, w.x) != (printed["A"], printed["x"]):
        smallest = (" The smallest witness of the exhaustive search is a different addition: "
                    f"{w.describe(LABELS)}.")
    return Finding(
        ca.verdict,
        rf"$\omega(\{{s_1,s_3\}})$ = {a:.4f} and $\omega(\{{s_1,s_2,s_3\}})$ = {b:.4f} (SVD); "
        f"{match} to 4 decimals; {shows} (change {b - a:+.4f}).{smallest}",
        _case_evidence(ca),
    )


@claim(
    id="thm7-case2",
    where="Theorem 7, Case 2 (Sec. IV-B, Fig. 3(b))",
    title=r"Fig. 3(b): the gain of $s_3$ is smaller at $\{s_1,s_2\}$ than at "
    r"$\{s_1,s_2,s_4\}$ (not submodular).",
    statement=r"With $s_1 = (0,0)$, $s_2 = (2\sqrt3,0)$, $s_3 = (\sqrt3,0.1)$, "
    r"$s_4 = (\sqrt3,3)$, $t_1 = (\sqrt3,1)$ and $u_{\max} = 1$, the gain of $s_3$ at "
    r"$\{s_1,s_2\}$ is smaller than at $\{s_1,s_2,s_4\}$: the lower bound is not submodular.",
    paper=r"$\omega(\{s_1,s_2,s_3\}) - \omega(\{s_1,s_2\}) = 0.3310 - 0.5345 = -0.2035 < "
    r"\omega(\{s_1,s_2,s_4,s_3\}) - \omega(\{s_1,s_2,s_4\}) = 0.8765 - 0.9258 = -0.0493$.",
    notebook=NB,
)
def _thm7_case2(profile: str) -> Finding:
    p = params(NB, profile)
    ca = _case("case2", p["u_max"], p["min_size"])
    gA, gB = ca.our_sides
    wrong = [rf"$\omega$({_set(k)}) = {ca.values[k]:.4f} (printed {v:.4f})"
             for k, v in ca.printed.items() if not ca.matches[k]]
    right = [_set(k) for k, v in ca.printed.items() if ca.matches[k]]
    same = [_set(k) for k, v in ca.values.items()
            if any(not ca.matches[q] and abs(v - ca.printed[q]) <= 0.5e-4 for q in ca.printed)]
    text = f"Wrong: {'; '.join(wrong) or 'none'}"
    text += f" (the printed value is that of {', '.join(same)}). " if same else ". "
    text += f"Reproduced to 4 decimals: {', '.join(right) or 'none'}. "
    text += f"With our values the printed comparison reads {gA:+.4f} against {gB:+.4f}: "
    if ca.shows_with_ours:
        text += "the gain at the smaller set is still the smaller one, a counter-example."
    else:
        text += ("the gain at the smaller set is the larger one (diminishing returns hold), so "
                 "the printed triple is not a counter-example.")
    w = ca.audits[p["min_size"]].submodular_witness
    if w is not None:
        text += (f" Smallest witness in the same geometry (sets of at least {p['min_size']} "
                 f"sensors): {w.describe(LABELS)}.")
    else:
        text += f" The geometry has no witness among sets of at least {p['min_size']} sensors."
    return Finding(ca.verdict, text, _case_evidence(ca))


@claim(
    id="thm7",
    where="Theorem 7 (Sec. IV-B)",
    title=r"The lower bound $\omega$ is neither monotone nor submodular.",
    statement=r"The lower bound $\omega(\cdot)$ of the inverse condition number is neither "
    "monotone increasing nor submodular.",
    paper="Proved by the two counter-examples of Cases 1 and 2.",
    notebook=NB,
)
def _thm7(profile: str) -> Finding:
    p = params(NB, profile)
    m = p["min_size"]
    cases = {c: _case(c, p["u_max"], m) for c in sm.FIG3_CASES}
    mono = {c: ca.audits[m].monotone_witness for c, ca in cases.items()}
    sub = {c: ca.audits[m].submodular_witness for c, ca in cases.items()}
    lb = sm.lower_bound_audit(p["n_instances"], p["n_sensors"], p["seed"], p["u_max"], m)
    not_mono = any(w is not None for w in mono.values()) or lb.n_not_increasing > 0
    not_sub = any(w is not None for w in sub.values()) or lb.n_not_submodular > 0
    if not_mono and not_sub:
        status = "reproduced"
    else:
        status = "partly" if (not_mono or not_sub) else "refuted"
    parts = []
    for c, w in mono.items():
        if w is not None:
            parts.append(f"not monotone in {c.replace('case', 'Case ')}: {w.describe(LABELS)}")
            break
    for c, w in sub.items():
        if w is not None:
            parts.append(f"not submodular in {c.replace('case', 'Case ')}: {w.describe(LABELS)}")
            break
    found = "; ".join(parts) if parts else "no witness in either geometry"
    return Finding(
        status,
        f"On {lb.n_instances} random instances of {lb.n_sensors} sensors, checked exhaustively "
        f"among sets of at least {m} sensors (where Theorem 1 applies), the bound is non-monotone "
        f"in {lb.n_not_increasing} and non-submodular in {lb.n_not_submodular}. Fig. 3 "
        f"geometries: {found}.",
        {
            "min_size": m,
            "case_monotone_witness": {c: (w.as_dict() if w else None) for c, w in mono.items()},
            "case_submodular_witness": {c: (w.as_dict() if w else None) for c, w in sub.items()},
            "random": lb.as_dict(),
        },
    )


@claim(
    id="thm7-exact",
    where="Abstract and Sec. I",
    title=r"The exact $C^{-1}$ itself is neither monotone nor submodular.",
    statement=r"The inverse of the condition number itself (stationary target, $u_o = 0$) is "
    "neither monotone nor submodular.",
    paper="'we show that the inverse of the condition number is neither monotone nor "
    "submodular' (the proof treats only the lower bound).",
    notebook=NB,
)
def _thm7_exact(profile: str) -> Finding:
    p = params(NB, profile)
    m = p["min_size"]
    lb = sm.lower_bound_audit(p["n_instances"], p["n_sensors"], p["seed"], 0.0, m)
    ok_m, ok_s = lb.n_not_increasing > 0, lb.n_not_submodular > 0
    status = "reproduced" if (ok_m and ok_s) else ("partly" if (ok_m or ok_s) else "refuted")
    w = lb.witness
    wtxt = (f" Smallest witness of non-submodularity (instance {w['instance']}): the gain of "
            f"$s_{w['x'] + 1}$ is {w['gain_A']:.4f} at "
            f"$\\{{{', '.join(f's_{i + 1}' for i in w['A'])}\\}}$ but {w['gain_B']:.4f} at "
            f"$\\{{{', '.join(f's_{i + 1}' for i in w['B'])}\\}}$."
            if w else "")
    return Finding(
        status,
        r"$C^{-1}(O(o)) = \sigma_{\min}/\sigma_{\max}$ (Theorem 1's bound at $u_{\max} = 0$, "
        f"Remark 1), checked over all subsets of at least {m} sensors of {lb.n_instances} random "
        f"instances of {lb.n_sensors}: "
        f"non-monotone in {lb.n_not_increasing}, non-submodular in {lb.n_not_submodular}.{wtxt}",
        lb.as_dict(),
    )


def _thm8_rows(profile: str):
    p = params(NB, profile)
    return sm.theorem8_audit(p["n_instances"], p["n_sensors"], p["seed"], float(p["eps"]),
                             float(p["u_max"]))


def _thm8(profile: str) -> dict:
    return {(r.measure, r.config): r for r in _thm8_rows(profile)}


def _counts(rows, name):
    sel = [r for (mname, _), r in rows.items() if mname == name]
    return sel, sum(r.n_instances for r in sel)


def _holds(rows, name):
    sel, n = _counts(rows, name)
    return (all(r.increasing for r in sel), all(r.submodular for r in sel), n,
            {r.config: r.as_dict() for r in sel})


def _simple_thm8(name: str, profile: str, extra: str) -> Finding:
    rows = _thm8(profile)
    _, _, n, ev = _holds(rows, name)
    status = sm.theorem8_verdicts(_thm8_rows(profile))[name]
    sel, _ = _counts(rows, name)
    dec = sum(r.n_not_increasing for r in sel)
    nsub = sum(r.n_not_submodular for r in sel)
    p = params(NB, profile)
    return Finding(
        status,
        f"{n} exhaustive checks of random instances of {p['n_sensors']} sensors ({p['n_instances']} "
        rf"per instance kind and configuration; configurations: a prior $\varepsilon I$ with "
        rf"$\varepsilon$ = {p['eps']:g} with and without a row for $u_o$ of norm {p['u_max']:g}, "
        r"and $\varepsilon = 0$ on sets of at least 2 sensors), every "
        f"nested pair of subsets compared: {dec} instances with a decrease, {nsub} with a "
        f"violation of submodularity. {extra}",
        ev,
    )


_TH8 = "Theorem 8 (Sec. IV-B)"
_TH8_PAPER = ("'its trace, log determinant, rank and the trace of its inverse are submodular and "
              "monotone increasing'")


@claim(
    id="thm8-trace",
    where=_TH8,
    title=r"$\operatorname{tr}(O^T O)$ is monotone and submodular.",
    statement=r"$\operatorname{tr}(O^T O)$ is monotone increasing and submodular in the set of "
    "sensors.",
    paper=_TH8_PAPER,
    notebook=NB,
)
def _thm8_trace(profile: str) -> Finding:
    rows = _thm8(profile)
    sel, _ = _counts(rows, "trace")
    modular = all(r.n_not_supermodular == 0 for r in sel)
    return _simple_thm8("trace", profile, "It is in fact modular (no violation of supermodularity "
                        "either: " + ("none found" if modular else "SOME FOUND") + "): each sensor "
                        r"adds $\lVert o - p_i\rVert^2$ whatever the set.")


@claim(
    id="thm8-logdet",
    where=_TH8,
    title=r"$\log\det(O^T O)$ is monotone and submodular.",
    statement=r"$\log\det(O^T O)$ is monotone increasing and submodular in the set of sensors.",
    paper=_TH8_PAPER,
    notebook=NB,
)
def _thm8_logdet(profile: str) -> Finding:
    return _simple_thm8("logdet", profile, r"It is $-\infty$ for fewer than two independent rows, "
                        r"so it needs a prior $\varepsilon I$ (or sets of at least 2 sensors in "
                        "general position).")


@claim(
    id="thm8-rank",
    where=_TH8,
    title=r"$\operatorname{rank}(O^T O)$ is monotone and submodular.",
    statement=r"$\operatorname{rank}(O^T O)$ is monotone increasing and submodular in the set of "
    "sensors.",
    paper=_TH8_PAPER,
    notebook=NB,
)
def _thm8_rank(profile: str) -> Finding:
    return _simple_thm8("rank", profile, "It is the rank function of the linear matroid of the rows "
                        "(instances with sensors on lines through the target included); with 2 "
                        "columns it takes only the values $0, 1, 2$.")


@claim(
    id="thm8-trace-inverse",
    where=_TH8,
    title=r"$\operatorname{tr}((O^T O)^{-1})$ is monotone and submodular.",
    statement=r"$\operatorname{tr}((O^T O)^{-1})$ is monotone increasing and submodular in the "
    "set of sensors.",
    paper=_TH8_PAPER,
    notebook=NB,
)
def _thm8_trace_inverse(profile: str) -> Finding:
    rows = _thm8(profile)
    _, _, n, ev = _holds(rows, "trace_inverse")
    ninc, _, _, nev = _holds(rows, "neg_trace_inverse")
    sel, _ = _counts(rows, "trace_inverse")
    nsel, _ = _counts(rows, "neg_trace_inverse")
    n_dec = sum(r.n_not_increasing for r in sel)
    n_not_dec = sum(r.n_not_decreasing for r in sel)
    n_neg_sub = sum(r.n_not_submodular for r in nsel)
    status = sm.theorem8_verdicts(_thm8_rows(profile))["trace_inverse"]
    hit = next((r for r in nsel if r.witness is not None), None)
    wtxt = ""
    if hit is not None:
        w = hit.witness
        conf = (hit.config.replace("eps I", r"$\varepsilon I$").replace("eps = 0", r"$\varepsilon = 0$")
                .replace("u row", "row for $u_o$").replace("|S| >= 2", r"$\lvert S\rvert \ge 2$"))
        wtxt = (f" Smallest witness (configuration “{conf}”, instance {w['instance']}): the "
                rf"gain of $-\operatorname{{tr}}(G^{{-1}})$ from adding $s_{w['x'] + 1}$ is "
                f"{w['gain_A']:.4f} at $\\{{{', '.join(f's_{i + 1}' for i in w['A'])}\\}}$ but "
                f"{w['gain_B']:.4f} at the larger "
                f"$\\{{{', '.join(f's_{i + 1}' for i in w['B'])}\\}}$.")
    return Finding(
        status,
        r"As printed it fails: $\operatorname{tr}(G^{-1})$, $G = O^T O + \varepsilon I$, can only "
        f"decrease when a sensor is added (a strict decrease in {n_dec} of {n} instances, an "
        rf"increase in {n_not_dec}). Its negative $-\operatorname{{tr}}(G^{{-1}})$ is monotone "
        f"increasing ({sum(r.n_not_increasing for r in nsel)} instances with a decrease) but "
        f"*not* submodular: violated in {n_neg_sub} of {n} instances.{wtxt}",
        {"trace_inverse": ev, "neg_trace_inverse": nev, "n_instances": n,
         "n_decreasing_instances": n_dec},
    )
