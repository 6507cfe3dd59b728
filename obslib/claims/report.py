"""Render the ledger as the book's reproduction report (MyST Markdown).

The report page holds, between marker comments, the verdict table and the list of the claims
that do not hold as printed; the book's introduction includes both from the report with MyST's
``{include}`` directive (``start-after`` / ``end-before``), so the two pages are written by the
same command and cannot disagree.
"""

from __future__ import annotations

import json
import re
from collections import Counter
from pathlib import Path

from ..tools import ROOT
from ._ledger import ALIASES, REQUIRED_IDS, STATUSES, Record

__all__ = ["render_report", "notebook_labels", "typeset", "MARKERS", "ROBUSTNESS_FILE"]

#: Marker comments around the parts of the report that the introduction includes.
MARKERS = {
    "summary": ("% summary: start", "% summary: end"),
    "verdicts": ("% verdicts: start", "% verdicts: end"),
    "exceptions": ("% exceptions: start", "% exceptions: end"),
}

NOTEBOOKS = ROOT / "notebooks"

#: The stored robustness of the verdicts (``python -m obslib.claims --robustness --write ...``).
ROBUSTNESS_FILE = ROOT / "book" / "data" / "robustness.json"

ROBUSTNESS_INTRO = """\
Every claim that is partly reproduced or refuted, and every claim of the tracking experiments, is
checked again with one parameter of its experiment changed at a time: the speed bound
$u_{{\\max}}$ and the measurement noise $\\sigma$ scaled by 0.25, 0.5, 2 and 4, the distances of
the pair bound computed with the other metric (Euclidean instead of Mahalanobis), and the number
of noise seeds, instances or trials halved and doubled. The reruns keep the paper's other
parameters but start from the smaller Monte Carlo sizes of the profile `{base}`; the verdict
column is the verdict above, at the paper's sizes, and names the one at the smaller sizes where
they differ. A cell reads *holds* when the verdict is the same at every value tried, *unchanged
finding* when not even the numbers change (the check does not use that parameter of its
experiment), names the verdict where it changes, and reads *n/a* when the experiment has no such
parameter. The numbers of a published run are not varied in the parameters that run was made
with. Rerun with `python -m obslib.claims --robustness`.
"""

HEADER = """\
# Reproduction report

This page is the book's *ledger*: the list of the paper's claims, each with where the paper makes
it, what it states, and a function of `obslib.claims` that re-checks it. Every check was run at
the paper's parameters (profile `{profile}`); for each claim, *the paper* is what the paper
states, *ours* what we measured, and the *verdict* what the evidence gives:

- **reproduced**: the claim holds as stated;
- **partly**: it holds with a correction, or only in part;
- **refuted**: the evidence contradicts the statement as printed;
- **untestable**: nothing we can compute decides it.

A verdict is a finding, not a target. For a claim about a printed formula or a step of a proof
(the ids containing `proof`), the statement is what the paper prints, so *refuted* means that
the printed formula is wrong. The parameters of every experiment are on the
{{doc}}`experimental setup <setup>` page. Rerun every check with
`python -m obslib.claims --profile {profile}`, or one claim with
`python -m obslib.claims --id thm1`.
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
_REL = re.compile(r"(?<!\\)(=|<|>|\\le\b|\\ge\b|\\ne\b|\\Rightarrow\b)")


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
    """Ledger text as one line of MyST, with the plain-text numbers of the checks typeset.

    Outside ``$...$``: ``< 1e-12`` becomes :math:`< 10^{-12}`, ``4.5e-07`` becomes
    :math:`4.5 \\times 10^{-7}`, sensor sets ``{s1, s3}`` and names ``s1`` become
    :math:`\\{s_1, s_3\\}` and :math:`s_1`. A ``|`` outside math is escaped (it would split a
    table row); inside math it becomes ``\\vert``.
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


def notebook_labels(notebooks: Path = NOTEBOOKS) -> set:
    """The MyST targets ``(name)=`` defined in the markdown cells of the notebooks."""
    labels = set()
    for path in sorted(Path(notebooks).glob("*.ipynb")):
        nb = json.loads(path.read_text())
        for cell in nb.get("cells", []):
            if cell.get("cell_type") == "markdown":
                src = "".join(cell.get("source", []))
                labels.update(re.findall(r"^\(([^()\s]+)\)=\s*$", src, re.M))
    return labels


def _first_sentence(text: str) -> str:
    """The first sentence of ``text`` (abbreviations such as ``Eq.`` and ``Fig.`` do not end one)."""
    for m in re.finditer(r"[.:;](?=\s+[A-Z$(])", text):
        before = text[: m.start()].rsplit(None, 1)[-1] if text[: m.start()].strip() else ""
        if before in {"Eq", "Eqs", "Fig", "Figs", "Sec", "e.g", "i.e", "cf", "vs"}:
            continue
        if m.group(0) != ".":
            continue
        return text[: m.end()]
    return text


def _verdict(r: Record) -> str:
    return f"**{r.status}**" if r.status != "reproduced" else r.status


def robustness_section(records: list[Record], robustness: dict) -> list:
    """Lines of the section "How robust are the verdicts?" from the stored robustness data."""
    from ..studies.robustness import robustness_table

    have = {r.id: r.status for r in records}
    rows = [r for r in robustness["rows"] if r["id"] in have]
    if not rows:
        return []
    intro = ROBUSTNESS_INTRO.format(base=robustness["base"], n=len(rows))
    table = robustness_table(rows, link=lambda i: f"[`{i}`](#claim-{i})", statuses=have)
    return ["## How robust are the verdicts?", "", " ".join(intro.split()), "",
            table.rstrip("\n"), ""]


def render_report(records: list[Record], profile: str = "paper", labels=None,
                  robustness=None) -> str:
    """MyST Markdown for the report page.

    A summary by verdict, the verdict table (one line per claim: its one-line statement, what
    the paper states, the first sentence of what we found, the verdict and a link to the
    evidence), the claims that do not hold as printed, one section per claim with its own anchor
    ``claim-<id>`` (plus one per former id), and the required ids not yet audited.

    Parameters
    ----------
    records : list of Record
        The evaluated ledger (:func:`obslib.claims.evaluate`).
    profile : str
        The profile the records were evaluated at (named on the page).
    labels : set of str, optional
        The MyST targets that exist in the notebooks (default: read from ``notebooks/``). The
        evidence link of a claim goes to its ``label`` when that target exists, else to the top
        of its notebook.
    robustness : dict, optional
        The stored robustness of the verdicts (:func:`obslib.studies.robustness.read_json`);
        when given, the section "How robust are the verdicts?" follows the claims that do not
        hold as printed.
    """
    if labels is None:
        labels = notebook_labels()
    aliases = {}
    for old, new in ALIASES.items():
        aliases.setdefault(new, []).append(old)

    def evidence(r: Record, text: str) -> str:
        if r.label and r.label in labels:
            return f"[{text}](#{r.label})"
        return f"[{text}](../notebooks/{r.notebook}.ipynb)"

    def title(r: Record) -> str:
        return typeset(r.title or r.statement)

    counts = Counter(r.status for r in records)
    words = {"partly": "partly reproduced"}
    parts = [f"{counts[s]} {words.get(s, s)}" for s in STATUSES if counts.get(s)]
    if parts:
        first = next(s for s in STATUSES if counts.get(s))
        parts[0] = parts[0].replace(" ", " is " if counts[first] == 1 else " are ", 1)
    tally = ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1] if parts else "none"
    lines = [HEADER.format(profile=profile), "## Summary", "", MARKERS["summary"][0],
             f"Of the {len(records)} claims of the ledger, {tally}.", MARKERS["summary"][1], ""]
    lines += ["| verdict | claims |", "| --- | --- |"]
    lines += [f"| {s} | {counts.get(s, 0)} |" for s in STATUSES]
    lines += [f"| total | {len(records)} |", "", "## Verdicts at a glance", ""]
    lines += [
        "Each claim links to its entry below, where the paper makes it links to the section of "
        "the book that shows the evidence.",
        "",
        MARKERS["verdicts"][0],
        "| claim | the paper | we found | verdict |",
        "| --- | --- | --- | --- |",
    ]
    for r in records:
        lines.append(
            f"| [{title(r)}](#claim-{r.id}) ({evidence(r, typeset(r.where))}) | "
            f"{typeset(r.paper)} | {typeset(_first_sentence(' '.join(r.ours.split())))} | "
            f"{_verdict(r)} |"
        )
    lines += [MARKERS["verdicts"][1], ""]

    lines += ["## What does not hold as printed", "", MARKERS["exceptions"][0]]
    bad = [r for r in records if r.status in ("refuted", "partly")]
    for status in ("refuted", "partly"):
        for r in (r for r in bad if r.status == status):
            lines.append(
                f"- *{r.status.capitalize()}*: {title(r)} "
                f"{typeset(_first_sentence(' '.join(r.ours.split())))} "
                f"([entry](#claim-{r.id}))"
            )
    if not bad:
        lines.append("Every claim holds as stated.")
    lines += [MARKERS["exceptions"][1], ""]
    if robustness:
        lines += robustness_section(records, robustness)
    lines += ["## Claims in detail", ""]

    for r in records:
        lines += [f"(claim-{old})=" for old in aliases.get(r.id, [])]
        lines += [
            f"(claim-{r.id})=",
            f"### {title(r).rstrip('.')}",
            "",
            f"*Id:* `{r.id}`. *Where:* {typeset(r.where)}. *Verdict:* {_verdict(r)}. "
            f"*Evidence:* {evidence(r, 'the section of the book that shows it')}.",
            "",
            f"**Claim.** {typeset(r.statement)}",
            "",
            f"**The paper.** {typeset(r.paper)}",
            "",
            f"**Ours.** {typeset(r.ours)}",
            "",
        ]
    have = {r.id for r in records}
    missing = [i for i in REQUIRED_IDS if i not in have]
    if missing:
        lines += [
            "## Not yet audited",
            "",
            "These claims have no check yet, so the book makes no statement about them: "
            + ", ".join(f"`{i}`" for i in missing)
            + ".",
        ]
    return "\n".join(lines).rstrip() + "\n"

