"""The front page's findings, the report's verdict lines and the chapters' verdict boxes are
the ledger's one sentences (obsbook.front, obsbook.report, obsbook.verdicts)."""

import re

import pytest

from obsbook import front, report, verdicts
from obslib import claims
from obslib.tools.run import ROOT


def _record(id, status, kind="paper", summary="It holds.", caveat="", label=None):
    return claims.Record(id, "", "", "", summary, status, "01_model_and_bound", {},
                         title=f"Claim {id}.", label=label or f"{id}-evidence", kind=kind,
                         summary=summary, caveat=caveat)


def test_a_headline_must_agree_with_the_ledger():
    recs = [_record("a", "reproduced"), _record("b", "refuted", summary="It fails.")]
    ok = front.Headline("A holds, B does not.", {"a": "reproduced", "b": "refuted"})
    text = report.render_front(recs, (ok,))
    assert ("- **A holds, B does not.** It holds. It fails. (The evidence: [Claim a](#a-evidence), "
            "[Claim b](#b-evidence).)") in text
    one = front.Headline("B does not hold.", {"a": "reproduced", "b": "refuted"}, ("b",))
    assert "- **B does not hold.** It fails. (The evidence: [Claim a]" in report.render_front(
        recs, (one,))
    with pytest.raises(ValueError, match="states an entry it asserts nothing of"):
        front.Headline("C.", {"a": "reproduced"}, ("c",))
    wrong = front.Headline("Both hold.", {"a": "reproduced", "b": "reproduced"})
    with pytest.raises(ValueError, match="asserts 'b' is reproduced, but the ledger finds it"):
        report.render_front(recs, (wrong,))
    with pytest.raises(ValueError, match="does not hold"):
        report.render_front(recs, (front.Headline("C.", {"c": "reproduced"}),))


def test_the_front_lists_the_refuted_claims_and_counts_the_partly_ones():
    recs = [_record("a", "partly", summary="Only in part.",
                    caveat="Partly at the paper's values; refuted with twice $u_{\\max}$."),
            _record("b", "refuted", summary="It fails."), _record("c", "reproduced"),
            _record("d", "differs", kind="code", summary="The code differs."),
            _record("e", "partly", summary="Also in part.")]
    text = report.render_front(recs, ())
    start, end = front.MARKERS["exceptions"]
    part = text.split(start)[1].split(end)[0]
    assert "[Claim b](#claim-b)" in part and "It fails." in part
    assert "claim-a" not in part and "claim-c" not in part and "claim-d" not in part
    assert "2 more claims hold only in part" in part and "(#report-exceptions)" in part
    # the report itself tabulates every claim that does not hold, with its caveat
    table = "\n".join(report.exceptions_table(recs))
    assert table.index("claim-b") < table.index("claim-a")
    assert "**partly** (partly at the paper's values; refuted with twice $u_{\\max}$)" in table


def test_a_box_is_the_entry_s_sentence_with_its_caveat_and_link():
    r = _record("x-1", "partly", summary="Only in part.", caveat="Partly at the paper's "
                "values; refuted with half the noise seeds.")
    text = verdicts.box(r)
    assert text.startswith("```{admonition} Verdict: partly\n:class: verdict verdict-partly\n")
    assert ("Only in part. Partly at the paper's values; refuted with half the noise seeds. "
            "[The report's entry](#claim-x-1)") in text
    code = verdicts.box(_record("y", "differs", kind="code", summary="It differs."))
    assert code.startswith("```{admonition} The authors' code: differs")
    assert verdicts.glue_name("x-1") == "verdict_x_1"


def test_quotes_render_as_myst():
    assert report.quote_myst(r"the target is ``trapped'' by the sensors") == \
        "the target is “trapped” by the sensors"
    assert report.quote_myst(r"Theorem~\ref{thm:lower_bound} and $a~b$") == "Theorem 1 and $a~b$"
    with pytest.raises(ValueError, match="does not number"):
        report.quote_myst(r"Equation~\ref{eqn:nope}")
    # a long formula of the paper breaks at its relations, and a piece still longer than
    # SPLIT_AT before its binary minus, as the ledger's own texts do
    long = r"$\omega(\{s_1,s_2,s_3\})-\omega(\{s_1,s_2\})=0.3310-0.5345=-0.2035<0.8765-0.9258$"
    assert report.quote_myst(long) == (r"$\omega(\{s_1,s_2,s_3\})$ ${} -\omega(\{s_1,s_2\})$ "
                                       r"$=0.3310-0.5345$ $=-0.2035$ $<0.8765-0.9258$")
    # a definition := is one relation
    defn = r"$\mathbb{O}(o,u_o):=O^{T}(o,u_o)O(o,u_o)$"
    assert report.quote_myst(defn) == r"$\mathbb{O}(o,u_o)$ $:=O^{T}(o,u_o)O(o,u_o)$"


def test_every_quote_of_the_ledger_renders():
    for c in claims.registry().values():
        if c.quote:
            text = report.quote_myst(c.quote)
            assert "\\ref" not in text and "\\cite" not in text and "~" not in re.sub(
                r"\$[^$]*\$", "", text), c.id


def test_committed_front_fragment_is_the_ledger_at_the_paper_profile(paper_ledger):
    recs = list(paper_ledger.values())
    assert (ROOT / "book" / "_front.md").read_text() == report.render_front(recs), (
        "book/_front.md is stale: run python -m obsbook.report --front book/_front.md")


def test_the_front_page_states_no_claim_of_its_own():
    """Outside its generated parts the front page names no verdict and links no entry: every
    statement about an entry comes from the ledger."""
    text = (ROOT / "book" / "intro.md").read_text()
    own = re.sub(r"```\{include\}.*?```", "", text, flags=re.S)
    assert "claim-" not in own and "-evidence" not in own
    for word in ("reproduced", "refuted", "partly"):
        assert not re.search(rf"\b{word}\b", own), word
    for start, end in front.MARKERS.values():
        assert f'"{start}"' in text and f'"{end}"' in text


def test_the_code_notes_state_each_code_entry_through_its_sentence():
    recs = [_record("a", "reproduced"),
            _record("b", "differs", kind="code", summary="The code does less.",
                    caveat="Differs at the paper's values; agrees with half the seeds."),
            _record("c", "agrees", kind="code", summary="The code does it.")]
    text = report.render_code_notes(recs)
    start, end = front.CODE_MARKERS
    assert text.startswith(start + "\n") and text.endswith(end + "\n")
    bullets = text.splitlines()[1:-1]
    assert bullets == [
        "- [Claim b](#claim-b): **differs** (differs at the paper's values; agrees with half the "
        "seeds). The code does less. Differs at the paper's values; agrees with half the seeds. "
        "([evidence](#b-evidence))",
        "- [Claim c](#claim-c): **agrees**. The code does it. ([evidence](#c-evidence))"]
    assert "claim-a" not in text  # a claim of the paper is not a finding about the code
    assert text in report.render_front(recs, ())


def test_committed_code_notes_are_the_ledger_s_code_entries(paper_ledger):
    recs = list(paper_ledger.values())
    start, end = front.CODE_MARKERS
    committed = (ROOT / "book" / "_front.md").read_text()
    part = committed[committed.index(start):committed.index(end) + len(end)] + "\n"
    assert part == report.render_code_notes(recs), (
        "book/_front.md is stale: run python -m obsbook.report --front book/_front.md")
    code = [r for r in recs if r.kind == "code"]
    assert code and all(f"(#claim-{r.id}): " in part and report.statement_of(r) in part
                        for r in code)


def test_the_notes_on_the_code_state_no_finding_of_their_own():
    """Outside the included findings, the notes on the original code give settings only: no
    status word and no share or count the ledger computes."""
    text = (ROOT / "book" / "original_code.md").read_text()
    start, end = front.CODE_MARKERS
    assert f'"{start}"' in text and f'"{end}"' in text
    own = re.sub(r"```\{include\}.*?```", "", text, flags=re.S)
    for word in ("agrees", "differs", "reproduced", "refuted", "partly"):
        assert not re.search(rf"\b{word}\b", own), word
    assert not re.search(r"\d\s*(%|per ?cent)", own)
