"""How the book is cited: ``CITATION.cff`` is valid Citation File Format 1.2.0 and says what the
book and its bibliography say, and the BibTeX entries of the "How to cite" page are well formed.

The schema is the format's own (``tests/data/cff-schema-1.2.0.json``, with its provenance in
``tests/data/README.md``), applied with jsonschema and its format checks (dates, URLs).
"""

from __future__ import annotations

import copy
import importlib.util
import json
import re

import jsonschema
import pytest
import yaml
from pybtex.database import parse_string

from obsbook import edition

ROOT = edition.ROOT
SCHEMA = json.loads((ROOT / "tests" / "data" / "cff-schema-1.2.0.json").read_text())
BIB = (ROOT / "book" / "references.bib").read_text()
PAPER_KEY = "zhou2017lower"


def _citation_ext():
    """``book/_ext/citation.py``, the Sphinx extension behind the "How to cite" page."""
    spec = importlib.util.spec_from_file_location("citation_ext",
                                                  ROOT / "book" / "_ext" / "citation.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _errors(data) -> list[str]:
    validator = jsonschema.Draft7Validator(SCHEMA, format_checker=jsonschema.FormatChecker())
    return [e.message for e in validator.iter_errors(data)]


@pytest.fixture(scope="module")
def cff() -> dict:
    return yaml.safe_load((ROOT / "CITATION.cff").read_text())


def test_citation_file_is_valid_cff(cff):
    assert SCHEMA["$id"].endswith("/1.2.0/schema.json")
    assert cff["cff-version"] == "1.2.0"
    assert _errors(cff) == []


@pytest.mark.parametrize("change", ["no authors", "unknown key", "bad date", "bad reference"])
def test_the_schema_check_can_fail(cff, change):
    bad = copy.deepcopy(cff)
    if change == "no authors":
        del bad["authors"]
    elif change == "unknown key":
        bad["titel"] = "a misspelt key"
    elif change == "bad date":
        bad["date-released"] = "28 November 2026"
    else:
        bad["references"][0]["type"] = "preprint"  # not a type of the format
    assert _errors(bad)


def test_citation_file_names_the_book_as_its_configuration_does(cff):
    config = edition.book_config()
    assert cff["title"] == config["title"]
    assert [a["name"] for a in cff["authors"]] == [config["author"]]


def test_citation_file_cites_the_paper_as_the_bibliography_does(cff):
    (paper,) = cff["references"]
    entry = parse_string(BIB, "bibtex").entries[PAPER_KEY]
    words = " ".join(entry.fields["title"].split())
    assert " ".join(paper["title"].split()) == words
    assert str(paper["year"]) == entry.fields["year"]
    assert [(a["given-names"], a["family-names"]) for a in paper["authors"]] == [
        (" ".join(p.first_names), " ".join(p.last_names)) for p in entry.persons["author"]]
    arxiv = entry.fields["eprint"]
    assert [i["value"] for i in paper["identifiers"]] == [f"arXiv:{arxiv}"]
    assert paper["url"] == f"https://arxiv.org/abs/{arxiv}"


def test_the_paper_entry_is_shown_as_written_in_the_bibliography():
    ext = _citation_ext()
    shown = ext.bib_entry(PAPER_KEY, BIB)
    assert shown.startswith("@misc{zhou2017lower,") and shown.endswith("}")
    assert shown in BIB
    # one complete entry, which BibTeX reads alone
    assert list(parse_string(shown, "bibtex").entries) == [PAPER_KEY]
    with pytest.raises(KeyError, match="nowhere"):
        ext.bib_entry("nowhere", BIB)


def test_the_book_entry_is_bibtex_with_the_version():
    ext = _citation_ext()
    v = edition.Version("0123456789abcdef0123456789abcdef01234567", "2026-11-28", False)
    config = edition.book_config()
    text = ext.book_bibtex(config["title"], config["author"], v)
    (key, entry), = parse_string(text, "bibtex").entries.items()
    assert entry.type == "misc" and key.endswith("audited")
    assert entry.fields["year"] == "2026"
    assert "commit 0123456789ab of 2026-11-28" in entry.fields["note"]
    assert " ".join(entry.fields["title"].split()).startswith(config["title"] + ":")
    assert max(len(line) for line in text.splitlines()) <= 88  # fits the page's code box


def test_the_version_is_the_commit_git_reports():
    import shutil
    import subprocess

    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    v = edition.version()
    assert v.commit == head and re.fullmatch(r"\d{4}-\d{2}-\d{2}", v.date)
    assert v.describe().startswith(f"commit {head[:12]} of {v.date}")
