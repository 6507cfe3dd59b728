"""The book's reproduction report (``book/report.md``), rendered from the claims ledger.

``python -m obsbook.report --profile paper --write book/report.md`` evaluates
:func:`obslib.claims.evaluate` and writes the page: a header explaining the verdicts, the counts
of the paper's claims by verdict, the table of the paper's claims, the claims that do not hold as
printed, one entry per claim (the paper's words, the claim, our finding in one sentence with its
caveat, the fuller finding and the table under it, the link to the section of the book that shows
the evidence), the findings about the authors' code, the statements of their later material and
the book's own questions apart, and how robust the verdicts are (from
``obslib/data/robustness.json``, written by ``python -m obslib.claims --robustness --write ...``).
Every verdict carries the caveat of the robustness study where a change of one parameter changes
it.

Parts of the page sit between marker comments (:data:`MARKERS`) so that another page can include
them with MyST's ``{include}`` directive (``start-after`` / ``end-before``): the sentence counting
the paper's claims by verdict, and the table of those that do not hold as printed.
"""

from __future__ import annotations

import argparse
import json
import re
from collections import Counter
from pathlib import Path

from obslib._io import command
from obslib.claims import REQUIRED_IDS, STATUSES
from obslib.formatting import count, number
from obslib.tools import ROOT

__all__ = ["MARKERS", "SECTIONS", "PAPER_LABELS", "render_report", "notebook_targets",
           "typeset", "list_table", "counts_sentence", "quote_myst", "verdict_line",
           "statement_of", "exceptions_table", "record_table", "render_front",
           "render_code_notes", "main"]

#: Marker comments around the parts of the report that other pages may include.
MARKERS = {
    "counts": ("% counts: start", "% counts: end"),
    "exceptions": ("% exceptions: start", "% exceptions: end"),
}

HEADER = """\
# Reproduction report

This page is the referee's report of the book: every statement the paper prints, what we found
when we recomputed it, and the verdict, each with a link to the section of the book that shows
the evidence. All checks were run at {parameters}; the parameters of every experiment are on
the {{doc}}`experimental setup <setup>` page. A verdict says what the evidence gives, whatever we
expected:

- **reproduced**: the statement holds as printed. Where the authors' code departs from the text
  in a way that changes no conclusion the statement draws, the departure is reported apart, among
  the findings about the code, and not held against the statement;
- **partly**: it holds only with a correction (a condition added, a quantifier or a number
  changed), or only for part of what it says; the entry says which part;
- **refuted**: the evidence contradicts the statement as printed;
- **untestable**: nothing we can compute decides it.

For a statement about a printed formula or a step of a proof, the statement is what the paper
prints, so *refuted* means that the printed formula is wrong, not necessarily the theorem. Each
entry quotes the paper's own words. Where changing one parameter of an experiment changes a
verdict (see [How robust are the verdicts?](#report-robustness)), the verdict says so wherever it
is stated.

Three other kinds of entry are reported apart and never counted as verdicts on the paper: the
findings about the authors' code and saved runs ([The authors' code](#report-code)), the
statements of the authors' later material, which the paper never published
([The authors' later experiment](#report-later)), and the questions this book asks beyond the
paper ([Beyond the paper](#report-beyond)). Every check can be rerun from the command line,
`python -m obslib.claims --profile {profile}`, or one entry with
`python -m obslib.claims --id thm1`.
"""

#: Per kind other than ``paper``: the section's anchor, heading and introduction, the word for
#: its status and the caption of its table.
SECTIONS = {
    "code": (
        "report-code", "The authors' code and saved runs",
        "What the authors' code does and what their saved runs hold, against what the paper's "
        "text says. **agrees**: the code or the runs are what the text describes, or follow "
        "from it; **differs**: they depart from the text, and the finding says how and how much "
        "it matters. These are findings about the code, not verdicts on the paper.",
        "Finding", "The findings about the authors' code and saved runs.",
    ),
    "later": (
        "report-later", "The authors' later experiment",
        "The authors' code repository holds an experiment the paper never published: several "
        "targets tracked in closed loop, the sensors reassigned at every step. Its statements "
        "are judged like the paper's, with the saved data as evidence; they are verdicts on that "
        "later material, never on the paper, and are not counted with the paper's claims.",
        "Verdict on the later material", "The statements of the authors' later experiment.",
    ),
    "beyond": (
        "report-beyond", "Beyond the paper: the book's own questions",
        "The paper does not ask these questions; the book does, because a reader deciding "
        "whether to use the bound asks them. Each is reported as a finding: **answered** when "
        "the evidence settles the question (the finding says how), **open** when it does not. "
        "They are not verdicts on the paper.",
        "Status", "The book's own questions and their status.",
    ),
}

#: Kind -> the heading of an entry's ``paper`` field: what its source offers for it.
SUPPORT = {"paper": "The paper's support", "later": "The later material"}

ROBUSTNESS_INTRO = """\
Every claim of the paper that is partly reproduced or refuted, and every claim of the tracking
experiments, is checked again with one parameter of its experiment changed at a time: the speed
bound $u_{{\\max}}$ and the measurement noise $\\sigma$ scaled by 0.25, 0.5, 2 and 4, the
distances of the pair bound computed with the other metric (Euclidean instead of Mahalanobis),
and the number of noise seeds, instances or trials halved and doubled. The reruns start from
{start} and change one of them at a time. A cell reads *holds* when the verdict is the same at
every value tried, *unchanged finding* when not even the numbers change (the check does not use
that parameter of its experiment), names the verdict where it changes, and reads *n/a* when the
experiment has no such parameter. The numbers of a published run are not varied in the
parameters that run was made with. Where a verdict changes, its entry above and every page that
states it say so. Rerun with `python -m obslib.claims --robustness`.
"""

_MATH = re.compile(r"(\$\$.*?\$\$|\$[^$]+\$|`[^`]*`)", re.S)
_SCI = re.compile(r"(?<![\w.$])(<\s*)?(\d+(?:\.\d+)?)e([+-]?)0*(\d+)\b")
_SET = re.compile(r"\{(s\d(?:\s*,\s*s\d)*)\}")
_SENSOR = re.compile(r"(?<![\w$\\{])s(\d)\b")


def _sci(m: re.Match) -> str:
    rel, mant, sign, exp = m.group(1), m.group(2), m.group(3), m.group(4)
    power = f"10^{{{'-' if sign == '-' else ''}{exp}}}"
    body = power if float(mant) == 1 else f"{mant} \\times {power}"
    return f"${'< ' if rel else ''}{body}$"


def _set(m: re.Match) -> str:
    members = ", ".join(f"s_{x.strip()[1:]}" for x in m.group(1).split(","))
    return f"$\\{{{members}\\}}$"


#: Inline formulas longer than this (in characters of TeX) are split at their top-level relations.
SPLIT_AT = 36
_REL = re.compile(r"(?<!\\)(:=|(?<!:)=|<|>|\\le\b|\\ge\b|\\ne\b|\\Rightarrow\b)")


def _cuts(body: str, at) -> list:
    """Positions in ``body`` where ``at(i)`` holds, outside braces, brackets and parentheses."""
    depth, cuts = 0, []
    for i, ch in enumerate(body):
        if ch in "{([":
            depth += 1
        elif ch in "})]":
            depth -= 1
        elif depth == 0 and i > 0 and body[i - 1] != "\\" and at(i):
            cuts.append(i)
    return cuts


def _binary(body: str, i: int) -> bool:
    """Whether ``body[i]`` is a binary ``+`` or ``-`` (its left neighbour ends an operand)."""
    if body[i] not in "+-":
        return False
    left = body[:i].rstrip()
    return bool(left) and (left[-1].isalnum() or left[-1] in ")}'")


def _pieces(body: str, cuts: list) -> list:
    return [p for p in (body[a:b].strip() for a, b in zip([0] + cuts, cuts + [len(body)])) if p]


def _split_math(tex: str) -> str:
    """``$a = b = c$`` as ``$a$ $= b$ $= c$`` when it is long, so that a line can break there.

    Splits only at relations outside braces, brackets and parentheses, and never inside an
    environment or a ``\\left ... \\right`` pair, so each piece is valid TeX.
    """
    body = tex[1:-1]
    if len(body) <= SPLIT_AT or "\\begin" in body or "\\left" in body:
        return tex
    out = []
    for piece in _pieces(body, _cuts(body, lambda i: _REL.match(body, i))):
        if len(piece) > SPLIT_AT:  # still long: also break before binary + and -
            sub = _pieces(piece, _cuts(piece, lambda i: _binary(piece, i)))
            out += [sub[0]] + [f"{{}} {s}" for s in sub[1:]]
        else:
            out.append(piece)
    return " ".join(f"${p}$" for p in out)


def typeset(text: str) -> str:
    """Ledger text as one line of MyST, long inline formulas split where a line may break.

    Outside ``$...$`` a number in machine notation (``< 1e-12``, ``4.5e-07``) is typeset as a
    power of ten, and sensor sets ``{s1, s3}`` and names ``s1`` as :math:`\\{s_1, s_3\\}` and
    :math:`s_1` (the ledger's own texts do not need it; quoted text may). A ``|`` outside math is
    escaped (it would split a Markdown table row); inside math it becomes ``\\vert``.

    Examples
    --------
    >>> typeset("difference < 1e-12 for s1")
    'difference $< 10^{-12}$ for $s_1$'
    """
    parts = _MATH.split(" ".join(str(text).split()))
    out = []
    for i, part in enumerate(parts):
        if i % 2 and part.startswith("`"):  # inline code, verbatim
            out.append(part.replace("|", r"\|"))
        elif i % 2:  # math
            part = part.replace("|", r"\vert ")
            out.append(part if part.startswith("$$") else _split_math(part))
        else:
            part = _SCI.sub(_sci, part)
            part = _SET.sub(_set, part)
            part = _SENSOR.sub(lambda m: f"$s_{m.group(1)}$", part)
            out.append(part.replace("|", r"\|"))
    return "".join(out)


_LABEL = re.compile(r"^\(([^()\s]+)\)=\s*$")
_HEADING = re.compile(r"^(#{1,6})\s+(.*\S)\s*$")


def notebook_targets(notebooks=None) -> dict:
    """The MyST targets ``(name)=`` of the notebooks' markdown cells: name -> (notebook, title).

    ``notebook`` is the notebook's stem; ``title`` the heading that follows the target (the
    section it names), or the notebook's title when no heading follows in the same cell.

    Examples
    --------
    >>> t = notebook_targets()
    >>> t["thm1-evidence"][0]
    '01_model_and_bound'
    """
    notebooks = Path(ROOT / "notebooks" if notebooks is None else notebooks)
    out = {}
    for path in sorted(notebooks.glob("*.ipynb")):
        cells = [c for c in json.loads(path.read_text()).get("cells", [])
                 if c.get("cell_type") == "markdown"]
        lines_of = ["".join(c.get("source", [])).splitlines() for c in cells]
        title = next((m.group(2) for lines in lines_of for line in lines
                      if (m := _HEADING.match(line)) and len(m.group(1)) == 1), path.stem)
        for lines in lines_of:
            pending = []
            for line in lines:
                m = _LABEL.match(line)
                if m:
                    pending.append(m.group(1))
                    continue
                h = _HEADING.match(line)
                if pending and (h or line.strip()):
                    for name in pending:
                        out[name] = (path.stem, h.group(2) if h else title)
                    pending = []
            for name in pending:
                out[name] = (path.stem, title)
    return out


def _cell(value) -> str:
    return value if isinstance(value, str) else number(value)


def list_table(caption: str, columns, rows, name: str | None = None, widths=None) -> list:
    """Lines of a MyST ``{list-table}``: caption above, one header row, ``name`` for a number.

    Cells are MyST text (used as given) or real numbers (:func:`obslib.formatting.number`).

    Examples
    --------
    >>> print("\\n".join(list_table("Two rows.", ["$L$", "ratio"], [[2, 0.951], [3, "none"]],
    ...                             name="tab-x")))
    :::{list-table} Two rows.
    :header-rows: 1
    :name: tab-x
    <BLANKLINE>
    * - $L$
      - ratio
    * - 2
      - 0.951
    * - 3
      - none
    :::
    """
    lines = [f":::{{list-table}} {' '.join(caption.split())}", ":header-rows: 1"]
    if name:
        lines.append(f":name: {name}")
    if widths:
        lines.append(f":widths: {' '.join(str(w) for w in widths)}")
    lines.append("")
    for row in [list(columns)] + [list(r) for r in rows]:
        lines.append(f"* - {_cell(row[0])}")
        lines += [f"  - {_cell(c)}" for c in row[1:]]
    lines.append(":::")
    return lines


_WORDS = {"partly": "partly reproduced"}


def counts_sentence(records) -> str:
    """The sentence counting the paper's claims by verdict (the book's own questions apart).

    Examples
    --------
    >>> from obslib.claims import Record
    >>> rs = [Record(str(i), "", "", "", "", s, "", {}) for i, s in
    ...       enumerate(["reproduced", "reproduced", "refuted"])]
    >>> print(counts_sentence(rs))  # doctest: +NORMALIZE_WHITESPACE
    Of the 3 claims of the paper in the ledger, 2 are reproduced and 1 refuted; none is partly
    reproduced or untestable.
    """
    paper = [r for r in records if r.kind == "paper"]
    c = Counter(r.status for r in paper)
    have = [s for s in STATUSES if c.get(s)]
    parts = [f"{number(c[s])} {_WORDS.get(s, s)}" for s in have]
    if not parts:
        return "The ledger holds no claim of the paper yet."
    parts[0] = parts[0].replace(" ", " is " if c[have[0]] == 1 else " are ", 1)
    tally = parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]
    absent = [_WORDS.get(s, s) for s in STATUSES if not c.get(s)]
    none = f"; none is {' or '.join(absent)}" if absent else ""
    return f"Of the {number(len(paper))} claims of the paper in the ledger, {tally}{none}."


#: The paper's labels that quotes may refer to (``\ref{...}``), with the numbers the paper
#: prints for them.
PAPER_LABELS = {
    "prob:unique": "1", "prob:general": "2", "prob:perfect": "3",
    "thm:lower_bound": "1", "thm:sensor_n_1": "2", "thm:sensor_n_gre2": "3",
    "thm:lower_bound_ijo": "4", "thm:$ij_pair_extreme$": "5", "thm:lem_optimal_fin": "6",
    "Them:invcond_not_sub": "7", "thm:submodular_observability_measure": "8",
    "algorithm:unique_pair_assignment": "1", "remark:rem2": "2",
    "eqn:multi_sensor_target_system": "(3)", "observability_multi_sensor_target": "(4)",
    "eqn:new_multi_sensor_target": "(5)", "eqn:lower_bound_i_j_o": "(9)",
    "eqn:assumption_singular_condition": "(27)", "eqn:conslusion_singular_condition": "(28)",
    "eqn:maximum_unkown_extreme": "(34)",
    "fig:lower_bound_surf_contour": "2", "fig:position_cond_test_nonsubmodular": "3",
    "fig:flexible_best_pairing": "4", "fig:best_fixed_selection": "5",
    "fig:compare_pair_threecase": "6", "fig:target_entrap": "7",
    "fig:comparsion_perfect_unique": "8", "fig:trial_submodular_obs.eps": "9",
}  # fmt: skip

_LATEX_TEXT = [
    (re.compile(r"``(.*?)''", re.S), r"“\1”"),
    (re.compile(r"\\emph\{([^{}]*)\}"), r"*\1*"),
    (re.compile(r"\\textbf\{([^{}]*)\}"), r"**\1**"),
    (re.compile(r"~?\\cite\{[^{}]*\}"), ""),
    (re.compile(r"(?<!\\)--"), "–"),
    (re.compile(r"(?<!\\)~"), " "),
]


def quote_myst(quote: str) -> str:
    r"""The paper's words (LaTeX as printed) as MyST: math kept (a long formula split where a
    line may break, as :func:`typeset` splits it), ``\emph``, quotes, ties, dashes and
    citations of the text converted, ``\ref`` replaced by the number the paper prints
    (:data:`PAPER_LABELS`).

    Examples
    --------
    >>> print(quote_myst(r"solve Problem~\ref{prob:unique} for any $\omega(\cdot)$"))
    solve Problem 1 for any $\omega(\cdot)$
    >>> print(quote_myst(r"is ``trapped'' by the \emph{sensors}~\cite{x}."))
    is “trapped” by the *sensors*.
    """
    parts = re.split(r"(\$[^$]*\$)", " ".join(str(quote).split()))
    out = []
    for i, part in enumerate(parts):
        if i % 2:
            out.append(_split_math(part))
            continue

        def ref(m):
            if m.group(1) not in PAPER_LABELS:
                raise ValueError(f"quote refers to the label {m.group(1)!r}, which "
                                 "PAPER_LABELS does not number")
            return PAPER_LABELS[m.group(1)]

        part = re.sub(r"\\ref\{([^{}]*)\}", ref, part)
        for pattern, repl in _LATEX_TEXT:
            part = pattern.sub(repl, part)
        out.append(part)
    return "".join(out)


def _verdict(status: str) -> str:
    return f"**{status}**"


def verdict_line(r) -> str:
    """The verdict as the book states it: the status in bold, and its caveat when the
    robustness study changes it.

    Examples
    --------
    >>> from obslib.claims import Record
    >>> r = Record("x", "", "", "", "", "partly", "", {}, caveat="Partly at the paper's values; "
    ...            "refuted with half the noise seeds.")
    >>> print(verdict_line(r))
    **partly** (partly at the paper's values; refuted with half the noise seeds)
    """
    if not r.caveat:
        return _verdict(r.status)
    return f"{_verdict(r.status)} ({r.caveat[0].lower()}{r.caveat[1:].rstrip('.')})"


def statement_of(r) -> str:
    """The entry's one sentence as every summary states it: its summary, then its caveat."""
    return typeset(r.summary + (f" {r.caveat}" if r.caveat else ""))


def _entry(r, evidence: str, label: str) -> list:
    lines = [
        f"(claim-{r.id})=",
        f"### {typeset(r.title).rstrip('.')}",
        "",
        f"*Where:* {typeset(r.where)}. *{label}:* {verdict_line(r)}. "
        f"*Evidence:* {evidence}. *Rerun:* `python -m obslib.claims --id {r.id}`.",
        "",
    ]
    if r.quote:
        lines += ["**The paper's words.**", "", f"> {quote_myst(r.quote)}", ""]
    lines += [
        f"**The claim.** {typeset(r.statement)}",
        "",
        f"**{SUPPORT.get(r.kind, SUPPORT['paper'])}.** {typeset(r.paper)}",
        "",
    ]
    if r.journal:
        lines += [f"**The later version.** {typeset(r.journal)}", ""]
    lines += [f"**In one sentence.** {statement_of(r)}", ""]
    if r.ours != r.summary:
        lines += [f"**In detail.** {typeset(r.ours)}", ""]
    if r.table is not None:
        lines += [record_table(r, f"tab-claim-{r.id}"), ""]
    return lines


def record_table(record, name: str) -> str:
    """The table of an evaluated ledger entry (its :class:`obslib.claims.Table`) as a numbered
    MyST table: the report's and a chapter's (under its own ``name``) show the same cells.

    Parameters
    ----------
    record : obslib.claims.Record
        The evaluated entry (from :func:`obslib.claims.evaluate` or
        :func:`obsbook.verdicts.glue_verdicts`).
    name : str
        The table's label (``tab-NN-...`` in a chapter).

    Examples
    --------
    >>> from obslib.claims import Record, Table
    >>> r = Record("x", "", "", "", "", "reproduced", "", {}, summary="It holds.",
    ...            table=Table("Two rows.", ("$L$", "ratio"), [(2, 0.951), (3, "s1")]))
    >>> print(record_table(r, "tab-x").splitlines()[-2])
      - $s_1$
    """
    t = record.table
    if t is None:
        raise ValueError(f"the entry {record.id!r} has no table")

    def cell(c):
        return typeset(c) if isinstance(c, str) else c

    return "\n".join(list_table(typeset(t.caption), [cell(c) for c in t.columns],
                                [[cell(c) for c in row] for row in t.rows], name=name))


def robustness_section(records, robustness: dict) -> list:
    """Lines of the section "How robust are the verdicts?" from the stored robustness data."""
    from obslib.claims.robustness import DIMENSIONS, HEADERS, describe

    have = {r.id: r for r in records if r.kind == "paper"}
    rows = [row for row in robustness["rows"] if row["id"] in have]
    if not rows:
        return []
    start = ("the paper's parameters" if robustness["base"] == "paper" else
             f"the parameters of the profile `{robustness['base']}` (the paper's, with smaller "
             "Monte Carlo sizes)")
    intro = ROBUSTNESS_INTRO.format(start=start)
    body = []
    for row in rows:
        r = have[row["id"]]
        verdict, cells = describe(row, r.status)
        body.append([f"[{typeset(r.title)}](#claim-{r.id})", verdict] + cells)
    return (["(report-robustness)=", "## How robust are the verdicts?", "",
             " ".join(intro.split()), ""]
            + list_table("Each verdict with one parameter of its experiment changed at a time.",
                         ["claim", "verdict"] + [HEADERS[d] for d in DIMENSIONS], body,
                         name="tab-report-robustness") + [""])


def exceptions_table(records) -> list:
    """Lines of the table of the paper's claims that do not hold as printed: the claim, its
    verdict (with its caveat) and its one sentence."""
    paper = [r for r in records if r.kind == "paper"]
    bad = [r for s in ("refuted", "partly") for r in paper if r.status == s]
    if not bad:
        return ["Every claim of the paper holds as printed."]
    return list_table("The paper's claims that do not hold as printed, refuted first.",
                      ["claim", "verdict", "what we found"],
                      [[f"[{typeset(r.title)}](#claim-{r.id})", verdict_line(r), statement_of(r)]
                       for r in bad], widths=(3, 2, 5))


def render_code_notes(records) -> str:
    """MyST of the findings about the authors' code: one bullet per entry of kind ``code``, in
    the ledger's order, with its title linking to its entry of the report, its status (with its
    caveat), its one sentence and the link to the section that shows its evidence; between the
    markers of :data:`obsbook.front.CODE_MARKERS`.

    Examples
    --------
    >>> from obslib.claims import Record
    >>> r = Record("c", "", "", "", "", "differs", "", {}, title="The code does X.",
    ...            label="c-evidence", kind="code", summary="It does Y.")
    >>> print(render_code_notes([r]))
    % code: start
    - [The code does X](#claim-c): **differs**. It does Y. ([evidence](#c-evidence))
    % code: end
    <BLANKLINE>
    """
    from .front import CODE_MARKERS

    lines = [CODE_MARKERS[0]]
    code = [r for r in records if r.kind == "code"]
    lines += [f"- [{typeset(r.title).rstrip('.')}](#claim-{r.id}): {verdict_line(r)}. "
              f"{statement_of(r)} ([evidence](#{r.label}))" for r in code]
    if not code:
        lines.append("The book records no finding about the authors' code.")
    lines.append(CODE_MARKERS[1])
    return "\n".join(lines) + "\n"


def render_front(records, headlines=None) -> str:
    """MyST of the front page's generated parts (:mod:`obsbook.front`): the findings, one bullet
    per headline stating its entries' one sentences with a link to their evidence, and the table
    of the paper's claims that do not hold as printed.

    Raises
    ------
    ValueError
        When a headline asserts a status its entry does not have, or states an unknown entry.
    """
    from . import front

    headlines = front.HEADLINES if headlines is None else headlines
    by_id = front.check_headlines(records, headlines)
    lines = [front.MARKERS["findings"][0]]
    for h in headlines:
        said = " ".join(statement_of(by_id[cid]) for cid in h.states)
        links = ", ".join(f"[{typeset(by_id[cid].title).rstrip('.')}](#{by_id[cid].label})"
                          for cid in h.statuses)
        lines.append(f"- **{typeset(h.lead)}** {said} (The evidence: {links}.)")
    lines += [front.MARKERS["findings"][1], "", front.MARKERS["exceptions"][0]]
    paper = [r for r in records if r.kind == "paper"]
    refuted = [r for r in paper if r.status == "refuted"]
    partly = [r for r in paper if r.status == "partly"]
    if refuted:
        lines += list_table(
            "The paper's claims that the evidence refutes as printed.",
            ["the paper says", "what we found"],
            [[f"[{typeset(r.title).rstrip('.')}](#claim-{r.id})", statement_of(r)]
             for r in refuted],
            name="table-intro-exceptions", widths=(2, 5))
    if partly:
        lines += ["", f"{count(len(partly)).capitalize()} more "
                  + ("claim holds" if len(partly) == 1 else "claims hold")
                  + " only in part: the [report](#report-exceptions) lists them with what holds "
                  "instead."]
    if not refuted and not partly:
        lines.append("Every claim of the paper holds as printed.")
    lines.append(front.MARKERS["exceptions"][1])
    return "\n".join(lines) + "\n\n" + render_code_notes(records)


def render_report(records, profile: str = "paper", targets=None, robustness=None) -> str:
    """MyST Markdown for the report page (see the module docstring).

    Parameters
    ----------
    records : list of obslib.claims.Record
        The evaluated ledger (:func:`obslib.claims.evaluate`, with the caveats of the
        robustness study).
    profile : str
        The profile the records were evaluated at (named on the page).
    targets : dict, optional
        The MyST targets of the notebooks (:func:`notebook_targets`; default: read from
        ``notebooks/``). A claim's evidence links to its ``label`` when its notebook defines that
        target, else to the top of its notebook.
    robustness : dict, optional
        The stored robustness of the verdicts (:func:`obslib.claims.robustness.read_json`);
        when given, the section "How robust are the verdicts?" ends the page.
    """
    targets = notebook_targets() if targets is None else targets

    def evidence(r) -> str:
        nb, heading = targets.get(r.label, (None, None))
        if nb == r.notebook:
            return f"[{typeset(heading)}](#{r.label})"
        return f"[the chapter](../notebooks/{r.notebook}.ipynb)"

    def title(r) -> str:
        return f"[{typeset(r.title)}](#claim-{r.id})"

    paper = [r for r in records if r.kind == "paper"]
    tally = Counter(r.status for r in paper)
    parameters = ("the paper's parameters (profile `paper`)" if profile == "paper" else
                  f"the parameters of the profile `{profile}`")
    lines = [
        HEADER.format(profile=profile, parameters=parameters),
        "## The verdicts in numbers",
        "",
        MARKERS["counts"][0],
        counts_sentence(records),
        MARKERS["counts"][1],
        "",
    ]
    others = [(kind, [r for r in records if r.kind == kind]) for kind in SECTIONS]
    others = [(kind, rs) for kind, rs in others if rs]
    if others:
        lines += ["Reported apart: " + "; ".join(
            f"[{SECTIONS[kind][1][0].lower()}{SECTIONS[kind][1][1:]}](#{SECTIONS[kind][0]}) "
            f"({number(len(rs))} {'entry' if len(rs) == 1 else 'entries'})"
            for kind, rs in others) + ".", ""]
    lines += list_table("The paper's claims by verdict.", ["verdict", "claims"],
                        [[s, tally.get(s, 0)] for s in STATUSES] + [["total", len(paper)]],
                        name="tab-report-counts") + [""]
    lines += ["## The paper's claims", "",
              "Each claim links to its entry below, which quotes the paper, states the claim and "
              "says what we found; the last column links to the section of the book that shows "
              "the evidence.", ""]
    lines += list_table("Every claim of the paper, its verdict and the evidence.",
                        ["claim", "verdict", "evidence"],
                        [[title(r), verdict_line(r), evidence(r)] for r in paper],
                        name="tab-report-claims", widths=(5, 2, 3)) + [""]
    lines += ["(report-exceptions)=", "## What does not hold as printed", "",
              MARKERS["exceptions"][0]]
    lines += exceptions_table(records)
    lines += [MARKERS["exceptions"][1], "", "## The claims one by one", ""]
    for r in paper:
        lines += _entry(r, evidence(r), "Verdict")
    for kind, rs in others:
        anchor, heading, intro, label, caption = SECTIONS[kind]
        lines += [f"({anchor})=", f"## {heading}", "", intro, ""]
        lines += list_table(caption, ["entry", "status", "evidence"],
                            [[title(r), verdict_line(r), evidence(r)] for r in rs],
                            name=f"tab-{anchor}", widths=(5, 2, 3)) + [""]
        for r in rs:
            lines += _entry(r, evidence(r), label)
    if robustness:
        lines += robustness_section(records, robustness)
    missing = [i for i in REQUIRED_IDS if i not in {r.id for r in records}]
    if missing:
        lines += ["## Not yet audited", "",
                  f"{count(len(missing))} claims have no check yet, so the book makes no "
                  "statement about them: " + ", ".join(f"`{i}`" for i in missing) + ".", ""]
    return "\n".join(lines).rstrip() + "\n"


@command("python -m obsbook.report")
def main(argv=None) -> int:
    """``python -m obsbook.report [--profile P] [--write FILE] [--front FILE]
    [--robustness FILE] [--notebooks DIR]``: render the report (and with ``--front`` the front
    page's generated parts, :mod:`obsbook.front`), print it or store it (exit status 2 for a bad
    profile or path, or a missing robustness file; 1, after one line, if a write fails)."""
    from obslib._io import OutputPathError, as_input_file, as_output_path, write_or_report
    from obslib.claims import evaluate, robustness
    from obslib.profiles import profile_names

    ap = argparse.ArgumentParser(prog="python -m obsbook.report",
                                 description="Render the reproduction report from the ledger.")
    ap.add_argument("--profile", default="paper", choices=profile_names())
    ap.add_argument("--write", help="store the page here (default: print it)")
    ap.add_argument("--front", help="also store the front page's generated parts here")
    ap.add_argument("--robustness", default=str(robustness.DATA),
                    help="the stored robustness data (default: obslib/data/robustness.json)")
    ap.add_argument("--notebooks", default=str(ROOT / "notebooks"),
                    help="the notebooks whose section labels the evidence links go to")
    args = ap.parse_args(argv)
    for name in ("write", "front"):
        if getattr(args, name) is not None:
            try:
                setattr(args, name, as_output_path(getattr(args, name)))
            except OutputPathError as exc:
                ap.error(f"--{name} {exc}")
    if not Path(args.notebooks).is_dir():
        ap.error(f"--notebooks {args.notebooks}: not a directory")
    try:
        stored = robustness.read_json(as_input_file(args.robustness))
    except ValueError as exc:  # missing, not a regular file, or not robustness data
        ap.error(f"--robustness {exc}")
    caveats = robustness.caveats(stored) if args.profile == "paper" else {}
    records = evaluate(args.profile, caveats=caveats)
    text = render_report(records, args.profile, notebook_targets(args.notebooks), stored)
    if args.write is None:
        print(text, end="")
    elif not write_or_report("python -m obsbook.report", args.write, text):
        return 1
    else:
        print(f"{args.write}: {len(records)} entries")
    if args.front is not None:
        if not write_or_report("python -m obsbook.report", args.front, render_front(records)):
            return 1
        print(f"{args.front}: the front page's findings")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
