"""The claims ledger: structure, kinds, the findings as prose, profile-independent statuses, the
report rendered from it (obsbook.report) and the layers it sits in; each Section III status against
recomputed evidence."""

import json
import re

import numpy as np
import pytest

import obslib as ob
from obslib import claims
from obslib.studies import model_and_bound
from obslib.tools.run import NOTEBOOK_DIR, ROOT


@pytest.fixture(scope="module")
def records():
    return {r.id: r for r in claims.evaluate("quick")}


def test_records_are_complete(records):
    assert records, "the ledger is empty"
    for r in records.values():
        assert r.kind in claims.KINDS
        assert r.status in claims.STATUS_WORDS[r.kind]
        for field in ("id", "where", "statement", "paper", "ours", "notebook"):
            assert getattr(r, field).strip(), f"{r.id}: empty {field}"
        assert (NOTEBOOK_DIR / f"{r.notebook}.ipynb").exists(), f"{r.id}: no notebook {r.notebook}"


def test_unknown_profile_and_id_are_rejected():
    with pytest.raises(ValueError, match="unknown profile"):
        claims.evaluate("nope")
    with pytest.raises(ValueError, match="unknown claim"):
        claims.evaluate("quick", ids=["thm99"])


def test_finding_rejects_a_status_outside_the_words():
    with pytest.raises(ValueError, match="status"):
        claims.Finding("mostly", "It holds.")
    with pytest.raises(ValueError, match="table"):
        claims.Finding("reproduced", "It holds.", table=[("a", 1)])


def test_a_summary_is_one_sentence():
    ok = claims.Finding("reproduced", "It holds in all 10 trials (see Fig. 3, e.g. the first).")
    assert ok.ours == ok.summary
    for bad in ("", "No full stop", "One. Two.", "It holds. Mostly it does."):
        with pytest.raises(ValueError, match="summary"):
            claims.Finding("reproduced", bad)
    # a full stop inside math, code or parentheses ends no sentence
    claims.Finding("partly", r"It holds for $x = 1. Y$ and `a. B` (as said. Here).")


def test_every_summary_is_one_sentence_of_prose(records):
    for r in records.values():
        assert r.summary and claims._ledger._sentences(r.summary) == 1, r.id
        assert len(r.summary) < 420, f"{r.id}: the summary is {len(r.summary)} characters"


def test_a_check_is_a_pure_function_of_its_parameters(records):
    """recheck with the profile's parameters gives evaluate's record; a changed parameter
    reaches the check without any profile."""
    from obslib.profiles import params

    p = params("01_model_and_bound", "quick")
    assert claims.recheck("thm1", p, profile="quick") == records["thm1"]
    fewer = claims.recheck("thm1", {**p, "n_scenes": 37}, profile="quick")
    assert fewer.evidence["n_scenes"] == 37 and fewer.status == "reproduced"
    assert claims.resolve("thm1", "quick") == p
    with pytest.raises(ValueError, match="unknown claim"):
        claims.resolve("thm99")


def test_a_caveat_is_attached_only_at_the_base_parameters():
    from obslib.profiles import params

    p = params("01_model_and_bound", "paper")
    cav = {"remark1": "Reproduced at the paper's values; refuted with twice $u_{\\max}$."}
    assert claims.recheck("remark1", p, caveats=cav).caveat == cav["remark1"]
    assert claims.recheck("remark1", {**p, "n_scenes": 50}, caveats=cav).caveat == ""
    (r,) = claims.evaluate("paper", ids=["remark1"], caveats=cav)
    assert r.caveat == cav["remark1"]


def test_model_and_bound_statuses(records):
    expected = {
        "eq4-lie-rows": "reproduced", "sec3-rank-observability": "reproduced",
        "thm2-proof-rank": "reproduced", "sec3-squared-range": "partly",
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
    monkeypatch.setattr(model_and_bound, "lower_bounds",
                        lambda rows, u: ob.bounds.lower_bounds(rows, 0.0))
    p = {**claims.resolve("thm1", "quick"), "seed": 12345}  # a fresh computation, not a cached one
    f = claims.registry()["thm1"].check(p)
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


def test_lie_rows_against_finite_differences():
    """Eq. (4)'s rows by central differences of the Lie derivatives, computed by hand."""
    rng = np.random.default_rng(5)
    for _ in range(20):
        o, p, u = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2)

        def L0(x):
            return 0.5 * np.sum((p - x) ** 2)

        def L1(x):  # the derivative of L0 along the drift u
            return (x - p) @ u

        def L2(x):
            return u @ u  # the derivative of L1 along u does not depend on x

        h = 1e-6
        grad = [np.array([(f(o + h * e) - f(o - h * e)) / (2 * h) for e in np.eye(2)])
                for f in (L0, L1, L2)]
        np.testing.assert_allclose(grad[0], o - p, atol=1e-6)
        np.testing.assert_allclose(grad[1], u, atol=1e-6)
        np.testing.assert_allclose(grad[2], 0, atol=1e-6)
    from obslib.symbolic import lie

    assert lie.rows_match_printed(4)
    det, printed = lie.one_sensor_rank_condition()
    assert (det - printed).expand() == 0


def test_one_sensor_rank_condition_numerically():
    rng = np.random.default_rng(6)
    for _ in range(200):
        o, p, u = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2)
        if _ % 5 == 0:
            u = 2.0 * (o - p)  # a control along the sensor's row (an exact multiple): rank one
        cond = (o[0] - p[0]) * u[1] != (o[1] - p[1]) * u[0]
        rank = np.linalg.matrix_rank(np.vstack([o - p, u]), tol=1e-12)
        assert (rank == 2) == cond


def test_rank_audit_twins_and_stretch(records):
    a = records["sec3-rank-observability"].evidence
    assert a["n_full"] > 0 and a["n_deficient"] > 0
    assert a["min_ratio"] > 0.999 and a["max_twin_gap"] < 1e-12
    # a twin by hand: one sensor, a stationary target, the point turned about the sensor
    p, o = np.array([1.0, 2.0]), np.array([4.0, -1.0])
    c, s = np.cos(0.3), np.sin(0.3)
    twin = p + np.array([[c, -s], [s, c]]) @ (o - p)
    assert np.isclose(np.sum((p - twin) ** 2), np.sum((p - o) ** 2))
    assert ob.inverse_condition_number(p[None], o, [0.0, 0.0]) == 0


def test_squared_range_pairs_recounted_by_brute_force():
    from obslib.studies.model_and_bound import squared_range_audit

    a = squared_range_audit(40, seed=3)
    rng = np.random.default_rng(3)
    targets = rng.uniform(0, 100, size=(40, 2))
    sensors = rng.uniform(0, 100, size=(40, 6, 2))
    differ = 0
    for o, S in zip(targets, sensors):
        def best(unit):
            scores = {}
            for i in range(6):
                for j in range(i + 1, 6):
                    R = np.vstack([o - S[i], o - S[j]])
                    if unit:
                        R = R / np.linalg.norm(R, axis=1, keepdims=True)
                    sv = np.linalg.svd(R, compute_uv=False)
                    scores[(i, j)] = sv[1] / sv[0]
            return max(scores, key=scores.get)
        differ += best(False) != best(True)
    assert a.pair_differs == pytest.approx(differ / 40)




#: ASCII stand-ins for mathematics that the ledger's texts must not contain outside ``$...$``.
ASCII_MATH = re.compile(
    r"\*\*|\bsqrt\(|\bsigma_|\blambda_|\balpha\b|\btheta\b|C\^-1|>=|<=|\+-|-\+|\|\||\bu_max\b|"
    r"\bd_io\b|\bO\^T\b|\btrace\(|\blog det\b|\beps\b|\bomega\("
)


def _outside_math(text):
    return "".join(re.split(r"\$[^$]+\$", text))


def test_ledger_texts_are_myst_with_math_in_dollars(records):
    for r in records.values():
        for field in ("title", "where", "statement", "paper", "summary", "ours", "journal"):
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


# ------------------------------------------------------------------ kinds and status words

def test_beyond_entries_are_findings_never_verdicts_on_the_paper(records):
    beyond = {i for i, r in records.items() if r.kind == "beyond"}
    assert {i for i in records if i.startswith("beyond-")} <= beyond and beyond
    for i in beyond:
        assert records[i].status in claims.BEYOND_STATUSES
        assert records[i].status not in claims.STATUSES
    for r in records.values():
        if r.kind == "paper":
            assert r.status in claims.STATUSES


def test_a_status_word_of_the_other_kind_is_an_error(monkeypatch):
    from obslib.claims import _ledger

    bad = claims.Claim("probe", "nowhere", "a question", "not asked", "10_criteria",
                       lambda p: claims.Finding("refuted", "It fails."), "A question?", "probe",
                       "beyond")
    monkeypatch.setitem(_ledger._REGISTRY, "probe", bad)
    with pytest.raises(ValueError, match="beyond entry takes one of"):
        claims.evaluate("quick", ids=["probe"])
    with pytest.raises(ValueError, match="kind must be one of"):
        claims.claim(id="probe2", where="", statement="", paper="", notebook="", kind="ours")


def test_paper_entries_quote_the_paper(records):
    """Every statement of the paper quotes at least four consecutive words of its source, and
    only statements of the paper are verdicts on it."""
    from obslib.claims import quotes

    for r in records.values():
        if r.kind == "paper":
            assert len(r.quote.split()) >= 4 and quotes.found(r.quote), f"{r.id}: {r.quote!r}"
    kinds = {r.kind for r in records.values()}
    assert kinds <= set(claims.KINDS) and "paper" in kinds


def test_kinds_take_their_own_status_words(records):
    for r in records.values():
        assert r.status in claims.STATUS_WORDS[r.kind], r.id
    assert set(claims.CODE_STATUSES).isdisjoint(claims.STATUSES)


def test_new_entries_exist_with_their_verdicts(records):
    want = {"sec5b-control-ball": "differs", "intro-vs-problem2": "partly",
            "footnote1-two-sensors": "partly", "sec5d-logdet-measure": "differs",
            "code-link": "agrees", "sec5a-umax-speed": "reproduced",
            "sec4-mahalanobis-units": "partly", "problem3-ordered": "differs",
            "published-replay": "differs"}
    assert {i: records[i].status for i in want} == want


@pytest.fixture(scope="module")
def paper_records(paper_ledger):
    """The ledger at the paper's sizes (tests/conftest.py)."""
    return paper_ledger


def test_statuses_do_not_depend_on_the_profile(records, paper_records):
    assert list(records) == list(paper_records)
    differ = {i: (records[i].status, paper_records[i].status) for i in records
              if records[i].status != paper_records[i].status}
    assert not differ, f"status depends on the profile (quick, paper): {differ}"


def test_thm6_tight_rests_on_the_stored_witness(records, paper_records):
    from obslib.claims.greedy_unique_pairs import NEAR_THIRD

    for recs in (records, paper_records):
        ev = recs["thm6-tight"].evidence
        assert ev["near_third"] == NEAR_THIRD and ev["witness_ratio"] <= NEAR_THIRD
    assert records["thm6-tight"].evidence["witness_ratio"] == pytest.approx(
        paper_records["thm6-tight"].evidence["witness_ratio"], rel=1e-12)


# ------------------------------------------------------------------ the command line

def test_json_carries_every_field_and_the_kind(capsys):
    from obslib.claims.__main__ import main

    assert main(["--json", "--id", "thm1", "--id", "beyond-criteria", "--profile", "quick"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert [(d["id"], d["kind"]) for d in out] == [("thm1", "paper"), ("beyond-criteria", "beyond")]
    assert out[0]["table"]["columns"] and out[1]["status"] in claims.BEYOND_STATUSES


def test_cli_write_goes_through_the_safe_writer(tmp_path, capsys):
    from obslib.claims.__main__ import main, parse_args

    path = tmp_path / "ledger.json"
    assert main(["--id", "thm2", "--profile", "quick", "--write", str(path)]) == 0
    assert json.loads(path.read_text())[0]["id"] == "thm2"
    mtime = path.stat().st_mtime_ns
    main(["--id", "thm2", "--profile", "quick", "--write", str(path)])
    assert path.stat().st_mtime_ns == mtime  # unchanged data: the file is left alone
    for bad, msg in ((tmp_path / "missing" / "x.json", "does not exist"),
                     (tmp_path, "is a directory"), (tmp_path / "x.md", "must end in .json")):
        with pytest.raises(SystemExit) as exc:
            parse_args(["--write", str(bad)])
        assert exc.value.code == 2 and msg in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        parse_args(["--id", "erratum-thm4-matrix"])  # former ids are gone
    assert exc.value.code == 2


# ------------------------------------------------------------------ findings a person would write

#: What generated text looks like: Python reprs, machine notation, counts of zero in digits.
MACHINE = re.compile(
    r"\b(True|False|None)\b|\[\s*[-\d.(]|\(\d+, \d+\)|\b\d+(\.\d+)?e[+-]?\d+\b|"
    r"(?<![\d.])0 of\b|\bin 0\b|(?<![\d.])0\.0+(?![\d])|\bnan\b|\binf\b"
)


def _texts(r):
    yield "ours", r.ours
    if r.table is not None:
        yield "caption", r.table.caption
        for row in r.table.rows:
            for cell in row:
                if isinstance(cell, str):
                    yield "cell", cell
    yield "summary", r.summary
    if r.journal:
        yield "journal", r.journal


def test_findings_read_as_prose(records, paper_records):
    for recs in (records, paper_records):
        for r in recs.values():
            for where, text in _texts(r):
                assert not re.search(r"[\x00-\x1f]", text), f"{r.id} {where}: control character"
                assert text.count("$") % 2 == 0, f"{r.id} {where}: unbalanced $"
                plain = _outside_math(text)
                bad = MACHINE.search(plain)
                assert not bad, f"{r.id} {where}: {bad.group(0)!r} in {plain!r}"
            # one or two sentences (three at most where a sentence cites a later fact)
            ends = re.findall(
                r"[.;:]?\.(?=\s+[A-Z(])",
                _outside_math(r.ours)
                .replace("Eq.", "Eq")
                .replace("Fig.", "Fig")
                .replace("Sec.", "Sec")
                .replace("Figs.", "Figs"),
            )
            assert len(ends) <= 2, f"{r.id}: {len(ends) + 1} sentences: {r.ours!r}"
            assert len(r.ours) < 700, f"{r.id}: the finding is {len(r.ours)} characters"


def test_finding_tables_are_small_and_well_formed(records):
    for r in records.values():
        if r.table is None:
            continue
        t = r.table
        assert 1 <= len(t.columns) <= 8 and t.rows, r.id
        assert all(len(row) == len(t.columns) for row in t.rows), r.id
        assert t.caption.endswith("."), f"{r.id}: caption {t.caption!r}"


# ------------------------------------------------------------------ evidence links

def _labels_of(notebook):
    """The MyST targets ``(name)=`` that open a line of a markdown cell of ``notebook``."""
    nb = json.loads((NOTEBOOK_DIR / f"{notebook}.ipynb").read_text())
    return {m for c in nb["cells"] if c["cell_type"] == "markdown"
            for m in re.findall(r"^\(([^()\s]+)\)=$", "".join(c["source"]), re.M)}


def test_every_evidence_link_lands_on_a_label_of_its_notebook(records):
    missing = [f"{r.id}: ({r.label})= in {r.notebook}" for r in records.values()
               if r.label not in _labels_of(r.notebook)]
    assert not missing, "\n".join(missing)


def test_committed_report_links_every_entry_to_its_section():
    committed = (ROOT / "book" / "report.md").read_text()
    for cid, c in claims.registry().items():
        entry = committed.split(f"\n(claim-{cid})=\n", 1)[1].split("\n(claim-", 1)[0]
        assert f"](#{c.label})" in entry, f"{cid}: no link to ({c.label})= in its entry"
    assert "](../notebooks/" not in committed  # no link to the top of a chapter


# ------------------------------------------------------------------ the report

from obsbook import report  # noqa: E402


@pytest.fixture(scope="module")
def stored_robustness():
    from obslib.claims import robustness as rb
    from obslib.claims.robustness import read_json

    return read_json(rb.DATA)


def test_committed_report_is_the_ledger_at_the_paper_profile(paper_records, stored_robustness):
    text = report.render_report(list(paper_records.values()), "paper", robustness=stored_robustness)
    committed = (ROOT / "book" / "report.md").read_text()
    assert committed == text, "book/report.md is stale: run python -m obsbook.report --write ..."


def test_counts_are_of_the_paper_claims_and_add_up(records):
    recs = list(records.values())
    sentence = report.counts_sentence(recs)
    n_paper = sum(r.kind == "paper" for r in recs)
    numbers = [int(x.replace(",", "")) for x in re.findall(r"\d[\d,]*", sentence)]
    assert numbers[0] == n_paper and sum(numbers[1:]) == n_paper, sentence
    for s in claims.BEYOND_STATUSES:
        assert s not in sentence
    text = report.render_report(recs, "quick", targets={}, robustness=None)
    counts = text.split(":name: tab-report-counts", 1)[1].split(":::", 1)[0]
    cells = re.findall(r"^  - ([\d,]+)$", counts, re.M)
    assert int(cells[-1]) == n_paper and sum(map(int, cells[:-1])) == n_paper


def test_report_structure(records):
    recs = list(records.values())
    text = report.render_report(recs, "quick", targets={recs[0].label: (recs[0].notebook, "Sec")})
    for r in recs:
        assert text.count(f"\n(claim-{r.id})=\n") == 1
        assert f"](#claim-{r.id})" in text  # a table links to the entry
    assert f"[Sec](#{recs[0].label})" in text
    assert f"](../notebooks/{recs[1].notebook}.ipynb)" in text  # label unknown: the chapter
    for start, end in report.MARKERS.values():
        assert text.count(start) == 1 and text.count(end) == 1
        assert text.index(start) < text.index(end)
    claims_table = text.split(":name: tab-report-claims", 1)[1].split(":::", 1)[0]
    beyond = [r for r in recs if r.kind == "beyond"]
    assert beyond and not any(f"(#claim-{r.id})" in claims_table for r in beyond)
    assert text.index("## Beyond the paper") > text.index("## The claims one by one")
    names = re.findall(r"^:name: (\S+)$", text, re.M)
    assert len(names) == len(set(names))
    # a table's caption is above it (the directive's argument), never a paragraph below
    for m in re.finditer(r"^:::\{list-table\}(.*)$", text, re.M):
        assert m.group(1).strip(), "a table without caption"
    # no paragraph line that Markdown would read as a list item or a heading by accident
    body = text.split("## The claims one by one", 1)[1]
    for line in body.splitlines():
        if line.startswith(("* - ", "  - ")):
            continue
        assert not re.match(r"^\s*([+*]|-(?!\s\*))\s", line), line


def test_report_never_mentions_how_it_was_made(records):
    text = report.render_report(list(records.values()), "quick", targets={})
    plain = _outside_math(text).lower()
    for words in ("the tests", "unit test", "pytest", "budget", "commit", ".py", "source file",
                  "notebook 1"):
        assert words not in plain, words


def test_intro_includes_the_report_markers():
    committed = (ROOT / "book" / "report.md").read_text()
    intro = (ROOT / "book" / "intro.md").read_text()
    for start, end in report.MARKERS.values():
        assert start in committed and end in committed
    start, end = report.MARKERS["counts"]
    assert f':start-after: "{start}"' in intro and f':end-before: "{end}"' in intro


def test_typeset_numbers_sets_and_long_formulas():
    assert report.typeset("difference < 1e-12.") == "difference $< 10^{-12}$."
    assert (
        report.typeset("ranges over [4.5e-07, 0.99]") == r"ranges over [$4.5 \times 10^{-7}$, 0.99]"
    )
    assert report.typeset("adding s2 to {s1, s3}") == r"adding $s_2$ to $\{s_1, s_3\}$"
    long = r"$\omega(\{s_1,s_2,s_3\}) - \omega(\{s_1,s_2\}) = 0.3310 - 0.5345 = -0.2035$"
    pieces = re.findall(r"\$[^$]+\$", report.typeset(long))
    assert len(pieces) > 2 and pieces[-2:] == ["$= 0.3310 - 0.5345$", "$= -0.2035$"]
    assert all(len(p) < 45 for p in pieces)
    joined = " ".join(p[1:-1].replace("{} ", "") for p in pieces)
    assert joined.split() == long[1:-1].split()  # the pieces put back together are the formula
    frac = r"$\dfrac{a = b}{c}$"
    assert report.typeset(frac) == frac  # never split inside braces or an environment
    assert report.typeset(r"$|x|$ and a | b") == r"$\vert x\vert $ and a \| b"
    assert report.typeset("`s1 < 1e-12` and s1") == "`s1 < 1e-12` and $s_1$"  # code stays code


def test_notebook_targets_read_labels_and_their_sections(tmp_path):
    nb = {
        "cells": [
            {"cell_type": "markdown", "source": ["# The chapter\n"]},
            {
                "cell_type": "markdown",
                "source": ["(thm1-evidence)=\n", "## Audit\n", "text (not)= here\n"],
            },
            {"cell_type": "code", "source": ["(code-label)=\n"]},
            {"cell_type": "markdown", "source": "(a-b)=\n(c)=\n### H $x$\n"},
            {"cell_type": "markdown", "source": "(d)=\n**Misprints** (no heading)\n"},
        ]
    }
    (tmp_path / "x.ipynb").write_text(json.dumps(nb))
    assert report.notebook_targets(tmp_path) == {
        "thm1-evidence": ("x", "Audit"), "a-b": ("x", "H $x$"), "c": ("x", "H $x$"),
        "d": ("x", "The chapter")}


def test_report_command_line_errors_exit_2(tmp_path, capsys):
    for argv, msg in ((["--write", str(tmp_path / "no" / "r.md")], "does not exist"),
                      (["--notebooks", str(tmp_path / "none")], "not a directory"),
                      (["--profile", "nope"], "invalid choice")):
        with pytest.raises(SystemExit) as exc:
            report.main(argv)
        assert exc.value.code == 2 and msg in capsys.readouterr().err
    bad = tmp_path / "r.json"
    bad.write_text("[1]")
    with pytest.raises(SystemExit) as exc:
        report.main(["--robustness", str(bad), "--write", str(tmp_path / "r.md")])
    assert exc.value.code == 2 and "not a robustness data file" in capsys.readouterr().err


def test_list_table_formats_numbers_with_the_book_formatter():
    lines = report.list_table("Numbers.", ["a", "b"], [[12345, 2.5e-7], [0.25, "none"]], name="t")
    assert "* - 12,345" in lines and r"  - $2.50 \times 10^{-7}$" in lines
    assert lines[0] == ":::{list-table} Numbers." and lines[-1] == ":::"


# ------------------------------------------------------------------ layers

def test_claims_sit_above_the_studies_and_below_the_book():
    import ast
    import warnings

    pkg = ROOT / "obslib"
    for path in sorted((pkg / "claims").glob("*.py")):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # an invalid escape such as "\p" in TeX is a bug
            tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                names = [a.name for a in node.names] if isinstance(node, ast.Import) else [
                    ("." * node.level) + (node.module or "")]
                for name in names:
                    assert "tools" not in name.split("."), f"{path.name} imports {name}"
                    assert not name.startswith("obsbook"), f"{path.name} imports {name}"
    for path in sorted(pkg.rglob("*.py")):
        text = path.read_text()
        assert "obsbook" not in re.sub(r"#.*|\"\"\"[\s\S]*?\"\"\"", "", text), \
            f"{path.relative_to(ROOT)} refers to obsbook"
        if path.parent.name == "studies":
            assert not re.search(r"^\s*(from|import) [.\w]*claims", text, re.M), \
                f"{path.name}: the studies must not import the ledger"
