"""Misprints of the paper (notebook 11): its notation, indexing and wording, read off the text, and
the work its citation of the greedy's 1/2 guarantee points to.

Nothing is computed here: each entry fixes its verdict in its docstring and states the evidence
read off the paper's source. Registered after the other statements the paper does not check,
in the order of the paper.
"""

from __future__ import annotations

from ..formatting import number
from ..studies.unchecked_statements import NOTEBOOK
from ._ledger import Finding, Table, claim


@claim(
    id="greedy-half-citation",
    where="Sec. I, II and IV-B (citation)",
    title="The greedy team assignment's $1/2$ guarantee, and the work it is cited from.",
    statement="For monotone submodular measures the greedy team assignment is a "
    "$1/2$-approximation, as shown in the work the paper cites as `nemhauser1978analysis`.",
    paper="\"a greedy algorithm gives a $1/2$-approximation\", citing the key "
    "`nemhauser1978analysis`.",
    quote=r"However, for the specific class of submodular functions, there exists a "
    r"$1/2$--approximation by a greedy",
    notebook=NOTEBOOK,
)
def _half_citation(p: dict) -> Finding:
    """A bibliographic check (nothing to compute; the result itself is ``greedy-half``). The
    paper's source holds only the citation key, not its bibliography, so which work is meant is
    inferred from the key: ``nemhauser1978analysis`` names Nemhauser as first author, as part I
    (Math. Programming 14, 1978) has it; part II, where the 1/2 bound of the greedy over a
    matroid is proved, has Fisher first. partly: right result, the work the key points to is
    not the one that proves it."""
    return Finding(
        "partly",
        summary="The $1/2$ guarantee is right, but the work the citation points to, Nemhauser, "
        r"Wolsey and Fisher's part I, proves $1 - 1/e$ under a cardinality constraint; the $1/2$ "
        "for Problem 2's constraint, a partition matroid, is proved in their part II.",
        ours="The guarantee is right, but the work the citation points to is, as far as its key "
        "shows (the paper's bibliography is not available), Nemhauser, Wolsey and Fisher's part "
        r"I, which proves $1 - 1/e$ under a cardinality constraint; the $1/2$ of the greedy over "
        "a partition matroid, Problem 2's constraint, is proved in Fisher, Nemhauser and "
        "Wolsey's part II {cite}`fisher1978analysis`.",
        evidence={"key": "nemhauser1978analysis",
                  "inferred": "Nemhauser, Wolsey, Fisher 1978, part I",
                  "should_cite": "Fisher, Nemhauser, Wolsey 1978, part II, Math. Programming "
                                 "Study 8: 73-87"},
    )


#: The misprints of notation, indexing and wording, as printed and as the book reads them, in
#: the order of the paper.
MISPRINTS = (
    (r"Problems 1 and 2: $\sum_{i=1}^{L}$ of terms indexed by $l$", r"$\sum_{l=1}^{L}$"),
    (r"Problems 1-3: $\mathcal{S} := \{s_0, \ldots, s_N\}$, $\mathcal{T} := \{t_0, \ldots, "
     r"t_L\}$: $N + 1$ sensors and $L + 1$ targets",
     r"$s_1, \dots, s_N$ and $t_1, \dots, t_L$, as the constraints $i = 1, \dots, N$ have them"),
    ("Sec. III: the sensors “can improve the lower bound on the condition number”",
     "the lower bound on the inverse of the condition number"),
    (r"Theorem 3: “the smallest singular number” of $O(o)$", "its smallest singular value"),
    (r"Sec. IV: the Mahalanobis distance for $i\in\{1,,...,N\}$", r"$i \in \{1, \dots, N\}$"),
    ("Sec. IV-A: “We can use the inverse of the condition number” (Eq. (9)) as the weight",
     "its lower bound, Eq. (9), which the experiments use"),
    ("Algorithm 1: “while true”, no stopping rule",
     r"stop when every target has its pair, which comes first since $N \ge 2L$"),
    (r"Algorithm 1: “Remove $\{s_i,s_j\}$ from union sensor $S$”, after selecting "
     r"$(\sigma_1(l), \sigma_2(l), t_l)$",
     r"remove $\sigma_1(l)$ and $\sigma_2(l)$ from the sensor set $\mathcal{S}$"),
    ("Sec. IV-A: “We present the following lemmas”, followed by Theorem 6 and no lemma",
     "the following theorem"),
    (r"Proof of Theorem 6: the value charged is “at most twice of $(s_i,s_j,t_l)$”",
     r"at most twice $\omega(s_i,s_j,t_l)$"),
    (r"Sec. IV-B: the submodular welfare problem over “independent sets $\{S_i \mid S_i\in S, "
     r"~i=\{1,2,...n\}\}$”",
     r"disjoint sets $S_i \subseteq \mathcal{S}$, $i \in \{1, \dots, n\}$: $S_i \in S$ would "
     "make each team a single sensor"),
    (r"Secs. V-C and V-D: positions “within $[0,100]\times [0,100]\in\mathbb{R}^{2}$”",
     r"$[0, 100] \times [0, 100] \subset \mathbb{R}^2$"),
)


@claim(
    id="paper-typos",
    where="Problems 1-3, Algorithm 1, Theorems 3 and 6, Secs. III to V",
    statement="Algorithm 1, Problems 1-3, the sets $\\mathcal{S}$ and $\\mathcal{T}$ and the "
    "notation of Sections III to V are stated correctly.",
    title="Algorithm 1, Problems 1-3 and the notation, as printed.",
    paper="Algorithm 1: \"while true\"; Problem 1: maximise $\\sum_{i=1}^L \\omega(\\sigma_1(l), "
    "\\sigma_2(l), t_l)$; $\\mathcal{S} := \\{s_0, \\ldots, s_N\\}$, $\\mathcal{T} := \\{t_0, "
    "\\ldots, t_L\\}$; and the other lines of the table.",
    quote=r"Given a set of sensor positions, $\mathcal{S} := \{s_0,\ldots,s_N\}$",
    notebook=NOTEBOOK,
)
def _typos(p: dict) -> Finding:
    """Misprints of notation, indexing and wording, read off the text (nothing to compute):
    partly, since each has an obvious intended reading that the book implements
    (:data:`MISPRINTS`)."""
    n = len(MISPRINTS)
    return Finding(
        "partly",
        summary=f"The paper has {number(n)} misprints of notation, indexing and wording, each "
        "with an obvious intended reading, which the book follows.",
        evidence={"misprints": [printed for printed, _ in MISPRINTS]},
        table=Table("The misprints and their reading.", ("printed", "read as"), MISPRINTS),
    )
