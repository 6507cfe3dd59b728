"""The claims ledger: structure, and each Section III status against recomputed evidence."""

import re

import numpy as np
import pytest

import obslib as ob
import obslib.studies.section3 as bc
from obslib import claims
from obslib.tools.run import NOTEBOOK_DIR, ROOT


@pytest.fixture(scope="module")
def records():
    return {r.id: r for r in claims.evaluate("quick")}


def test_records_are_complete(records):
    assert records, "the ledger is empty"
    for r in records.values():
        assert r.status in claims.STATUSES
        for field in ("id", "where", "statement", "paper", "ours", "notebook"):
            assert getattr(r, field).strip(), f"{r.id}: empty {field}"
        assert (NOTEBOOK_DIR / f"{r.notebook}.ipynb").exists(), f"{r.id}: no notebook {r.notebook}"


def test_unknown_profile_and_id_are_rejected():
    with pytest.raises(ValueError, match="unknown profile"):
        claims.evaluate("nope")
    with pytest.raises(ValueError, match="unknown claim"):
        claims.evaluate("quick", ids=["thm99"])


def test_finding_rejects_a_status_outside_the_four():
    with pytest.raises(ValueError, match="status"):
        claims.Finding("mostly", "x")


def test_section3_statuses(records):
    expected = {
        "thm1": "reproduced", "thm1-tight": "reproduced", "thm2": "reproduced",
        "thm3": "reproduced", "thm3-proof-condition": "partly",
        "remark1": "reproduced", "remark2": "reproduced",
    }  # fmt: skip
    assert {k: records[k].status for k in expected} == expected


def test_thm1_evidence_recomputed(records):
    ev = records["thm1"].evidence
    assert ev["n_violations"] == 0 and ev["worst_excess"] <= 1e-12
    # independently: the exact value over a fine circle of controls never dips below the bound
    rng = np.random.default_rng(99)
    phi = np.linspace(0, 2 * np.pi, 2001)
    for _ in range(100):
        s = rng.uniform(-10, 10, size=(3, 2))
        o = rng.uniform(-10, 10, size=2)
        u_max = rng.uniform(0.1, 5)
        O = o - s
        lam = np.linalg.eigvalsh(O.T @ O)
        bound = np.sqrt(lam[0] / (lam[1] + u_max**2))
        for u in u_max * np.column_stack([np.cos(phi), np.sin(phi)])[::50]:
            M = np.vstack([O, u])
            sv = np.linalg.svd(M, compute_uv=False)
            assert sv[-1] / sv[0] >= bound - 1e-12


def test_thm1_check_can_fail(monkeypatch):
    """A wrong bound (ignoring u_max) must make the check report 'refuted'."""
    monkeypatch.setattr(bc, "lower_bounds", lambda rows, u: ob.bounds.lower_bounds(rows, 0.0))
    f = claims.registry()["thm1"].check("quick")
    assert f.status == "refuted" and f.evidence["n_violations"] > 0


def test_thm3_witnesses_recomputed(records):
    w = records["thm3"].evidence["witnesses"]["ratio only"]
    before, after = np.array(w["before"]), np.array(w["after"])
    o = np.zeros(2)

    def eig(s):
        O = o - s
        return np.linalg.eigvalsh(O.T @ O)

    lb, la = eig(before), eig(after)
    assert la[0] / la[1] >= lb[0] / lb[1]  # ratio up
    assert la[0] < lb[0]  # sigma_min down
    assert ob.lower_bound(after, o, w["u"]) < ob.lower_bound(before, o, w["u"])
    n, bad = records["thm3"].evidence["counts"]["stated"]
    assert n > 0 and bad == 0


def test_proof_condition_is_stronger_than_stated(records):
    counts = records["thm3-proof-condition"].evidence["counts"]
    assert 0 < counts["printed"][0] < counts["stated"][0]


def test_report_lists_every_claim(records):
    text = claims.render_report(list(records.values()), "quick")
    committed = (ROOT / "book" / "report.md").read_text()
    for cid in records:
        assert f"`{cid}`" in text
        assert f"`{cid}`" in committed, f"book/report.md is stale: no {cid} (run make book)"
    for cid in claims.REQUIRED_IDS:
        assert f"`{cid}`" in committed, f"required id {cid} neither in the table nor listed as missing"


# ------------------------------------------------------------------ the report as a reader sees it

from obslib.claims import report as rep  # noqa: E402
from obslib.claims._ledger import ALIASES  # noqa: E402

#: ASCII stand-ins for mathematics that the ledger's texts must not contain outside ``$...$``.
ASCII_MATH = re.compile(
    r"\*\*|\bsqrt\(|\bsigma_|\blambda_|\balpha\b|\btheta\b|C\^-1|>=|<=|\+-|-\+|\|\||\bu_max\b|"
    r"\bd_io\b|\bO\^T\b|\btrace\(|\blog det\b|\beps\b|\bomega\("
)


def _outside_math(text):
    return "".join(re.split(r"\$[^$]+\$", text))


def test_ledger_texts_are_myst_with_math_in_dollars(records):
    for r in records.values():
        for field in ("title", "where", "statement", "paper", "ours"):
            text = getattr(r, field)
            assert text.count("$") % 2 == 0, f"{r.id}.{field}: unbalanced $ in {text!r}"
            plain = _outside_math(text)
            bad = ASCII_MATH.search(plain)
            assert not bad, f"{r.id}.{field}: ASCII math {bad.group(0)!r} in {plain!r}"
            assert "|" not in plain, f"{r.id}.{field}: a bare | would split a table row"
            # no file outside the book (an upper-case notes file such as NOTES.md) is cited
            assert not re.search(r"\b[A-Z_]+\.md\b", text), f"{r.id}.{field}: {text!r}"


def test_every_claim_has_a_one_line_title_and_an_evidence_label(records):
    labels = [r.label for r in records.values()]
    assert len(set(labels)) == len(labels)
    for r in records.values():
        assert r.title and "\n" not in r.title and len(_outside_math(r.title)) < 120, r.id
        assert re.fullmatch(r"[a-z0-9-]+", r.label), r.label


def test_typeset_numbers_sets_and_long_formulas():
    assert rep.typeset("difference < 1e-12.") == "difference $< 10^{-12}$."
    assert rep.typeset("ranges over [4.5e-07, 0.99]") == r"ranges over [$4.5 \times 10^{-7}$, 0.99]"
    assert rep.typeset("adding s2 to {s1, s3}") == r"adding $s_2$ to $\{s_1, s_3\}$"
    long = r"$\omega(\{s_1,s_2,s_3\}) - \omega(\{s_1,s_2\}) = 0.3310 - 0.5345 = -0.2035$"
    pieces = re.findall(r"\$[^$]+\$", rep.typeset(long))
    assert len(pieces) > 2 and pieces[-2:] == ["$= 0.3310 - 0.5345$", "$= -0.2035$"]
    assert all(len(p) < 45 for p in pieces)
    # the pieces put back together are the formula
    joined = " ".join(p[1:-1].replace("{} ", "") for p in pieces)
    assert joined.split() == long[1:-1].split()
    # never split inside braces or an environment
    frac = r"$\dfrac{a = b}{c}$"
    assert rep.typeset(frac) == frac
    assert rep.typeset(r"$|x|$ and a | b") == r"$\vert x\vert $ and a \| b"
    assert rep.typeset("`s1 < 1e-12` and s1") == "`s1 < 1e-12` and $s_1$"  # code stays code


def test_committed_report_links_to_every_label_the_notebooks_define(records):
    committed = (ROOT / "book" / "report.md").read_text()
    defined = rep.notebook_labels()
    for r in records.values():
        if r.label in defined:
            assert f"](#{r.label})" in committed, f"book/report.md is stale for {r.label}"
        else:
            assert f"](../notebooks/{r.notebook}.ipynb)" in committed


def test_report_anchors_links_and_markers(records):
    recs = list(records.values())
    some = recs[0]
    text = claims.render_report(recs, "quick", labels={some.label})
    for r in recs:
        assert f"\n(claim-{r.id})=\n" in text
        assert f"](#claim-{r.id})" in text  # the table links to the entry
    for old in ALIASES:
        assert f"\n(claim-{old})=\n" in text, "a renamed id keeps its anchor"
    # the evidence goes to the label when the notebook defines it, else to the notebook
    assert f"](#{some.label})" in text
    other = recs[1]
    assert f"](#{other.label})" not in text
    assert f"](../notebooks/{other.notebook}.ipynb)" in text
    for start, end in rep.MARKERS.values():
        assert text.count(start) == 1 and text.count(end) == 1
        assert text.index(start) < text.index(end)
    # no paragraph line that Markdown would read as a list item, a heading or bold by accident
    body = text.split("## Claims in detail", 1)[1]
    for line in body.splitlines():
        assert not re.match(r"^\s*([+*]|-(?!\s\*))\s", line), line
        assert "**" not in _outside_math(line).replace("**Claim.**", "").replace(
            "**The paper.**", "").replace("**Ours.**", "").replace(f"**{'partly'}**", "").replace(
            "**refuted**", "").replace("**untestable**", ""), line


def test_aliases_resolve_to_the_renamed_claims():
    for old, new in ALIASES.items():
        assert [r.id for r in claims.evaluate("quick", ids=[old])] == [new]


def test_committed_report_is_the_paper_profile_and_the_intro_includes_it():
    committed = (ROOT / "book" / "report.md").read_text()
    assert "(profile `paper`)" in committed
    intro = (ROOT / "book" / "intro.md").read_text()
    for start, end in rep.MARKERS.values():
        assert start in committed and end in committed
        assert f':start-after: "{start}"' in intro and f':end-before: "{end}"' in intro


def test_notebook_labels_reads_myst_targets_of_markdown_cells(tmp_path):
    import json

    nb = {"cells": [
        {"cell_type": "markdown", "source": ["(thm1-evidence)=\n", "## Audit\n", "text (not)= here\n"]},
        {"cell_type": "code", "source": ["(code-label)=\n"]},
        {"cell_type": "markdown", "source": "(a-b)=\n(c)=\n### H"},
    ]}
    (tmp_path / "x.ipynb").write_text(json.dumps(nb))
    assert rep.notebook_labels(tmp_path) == {"thm1-evidence", "a-b", "c"}
