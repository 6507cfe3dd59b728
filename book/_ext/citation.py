"""Sphinx extension: how to cite the book, with the version it was built from.

1. The version, the commit of the checkout and its date (:func:`obsbook.edition.version`), is
   the substitution ``{{ book_version }}`` of every page, and the version and date on the PDF's
   title page. A new commit changes the configuration, so every page is read again.
2. ``{book-bibtex}`` shows the book's BibTeX entry, with that version, its title and authors
   from ``_config.yml``.
3. ``{bibtex-source} key`` shows the entry ``key`` of the book's bibliography
   (``book/references.bib``) exactly as it is written there: the paper's own entry is the one
   the book cites.
"""

from __future__ import annotations

import re
from pathlib import Path

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

from obsbook import edition

BIB = Path(__file__).resolve().parents[1] / "references.bib"


def bib_entry(key: str, text: str) -> str:
    """The entry ``key`` of the BibTeX ``text``, from its ``@`` to its closing brace.

    Examples
    --------
    >>> bib_entry("b", "@misc{a, title = {A}}\\n@article{b,\\n  title = {B {C}}\\n}\\n")
    '@article{b,\\n  title = {B {C}}\\n}'
    """
    m = re.search(r"@\w+\s*\{\s*" + re.escape(key) + r"\s*,", text)
    if m is None:
        raise KeyError(f"no entry {key!r} in the bibliography")
    depth = 0
    for k in range(text.index("{", m.start()), len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0:
            return text[m.start():k + 1]
    raise ValueError(f"the entry {key!r} of the bibliography is not closed")


def book_bibtex(title: str, author: str, version: edition.Version) -> str:
    """The book's BibTeX entry at ``version``, no line longer than 88 characters.

    Examples
    --------
    >>> v = edition.Version("0123456789abcdef0123456789abcdef01234567", "2026-11-28", False)
    >>> print(book_bibtex("A book", "The authors", v))
    @misc{obslib2026audited,
      author       = {{The authors}},
      title        = {A book: an executable companion
                      to the paper of {Zhou} and {Tokekar}},
      year         = {2026},
      howpublished = {Executable book},
      note         = {Version: commit 0123456789ab of 2026-11-28}
    }
    """
    year = version.date[:4] if version.date else "n.d."
    return "\n".join([
        f"@misc{{obslib{year}audited,",
        f"  author       = {{{{{author}}}}},",
        f"  title        = {{{title}: an executable companion",
        "                  to the paper of {Zhou} and {Tokekar}},",
        f"  year         = {{{year}}},",
        "  howpublished = {Executable book},",
        f"  note         = {{Version: {version.describe()}}}",
        "}",
    ])


def _bibtex_block(text: str) -> nodes.literal_block:
    block = nodes.literal_block(text, text, language="bibtex")
    block["classes"].append("bk-bibtex")
    return block


class BookBibtex(SphinxDirective):
    """``{book-bibtex}``: the book's BibTeX entry (:func:`book_bibtex`)."""

    def run(self):
        cfg = edition.book_config()
        text = book_bibtex(cfg["title"], cfg["author"], self.env.app.book_version)
        return [_bibtex_block(text)]


class BibtexSource(SphinxDirective):
    """``{bibtex-source} key``: an entry of the book's bibliography as written there."""

    required_arguments = 1

    def run(self):
        self.env.note_dependency(str(BIB))
        return [_bibtex_block(bib_entry(self.arguments[0], BIB.read_text()))]


def _version(app, config):
    v = edition.version()
    app.book_version = v
    config.myst_substitutions = {**config.myst_substitutions, "book_version": v.describe()}
    if v.commit is not None:
        config.version = config.release = v.short
        config.today = v.date


def setup(app):
    app.connect("config-inited", _version)
    app.add_directive("book-bibtex", BookBibtex)
    app.add_directive("bibtex-source", BibtexSource)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
