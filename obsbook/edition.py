"""The book's editions and its version: what a reader cites and where the PDF lives.

The version of a built book is the commit of the checkout it was built from and that commit's
date (:func:`version`); the "How to cite" page and the PDF's title page show it. The PDF edition
is built by ``make pdf`` (:mod:`obsbook.pdf`) into ``_build/latex/`` under the name
:func:`pdf_name` gives, and copied beside the HTML pages so that every page can link it.
"""

from __future__ import annotations

import subprocess
from dataclasses import dataclass
from pathlib import Path

import yaml

from obslib.tools import ROOT

__all__ = ["Version", "version", "pdf_name", "LATEX_DIR", "HTML_DIR", "book_config"]

#: Where Jupyter Book's LaTeX builder writes, and XeLaTeX the PDF.
LATEX_DIR = ROOT / "_build" / "latex"
#: The HTML book; the PDF is copied to its top folder.
HTML_DIR = ROOT / "_build" / "html"


@dataclass(frozen=True)
class Version:
    """The commit a book is built from: ``commit`` (40 hex digits), ``date`` (the commit's, as
    YYYY-MM-DD) and ``changed`` (whether tracked files differ from it); all None outside a git
    checkout."""

    commit: str | None
    date: str | None
    changed: bool | None

    @property
    def short(self) -> str | None:
        """The first 12 digits of the commit."""
        return None if self.commit is None else self.commit[:12]

    def describe(self) -> str:
        """The version in words.

        Examples
        --------
        >>> Version("0123456789abcdef0123456789abcdef01234567", "2026-11-28", False).describe()
        'commit 0123456789ab of 2026-11-28'
        >>> Version("0123456789abcdef0123456789abcdef01234567", "2026-11-28", True).describe()
        'commit 0123456789ab of 2026-11-28, with local changes'
        >>> Version(None, None, None).describe()
        'a copy without its version history'
        """
        if self.commit is None:
            return "a copy without its version history"
        return f"commit {self.short} of {self.date}" + (", with local changes" * bool(self.changed))


def _git(root: Path, *args: str) -> str | None:
    try:
        out = subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True,
                             timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    return out.stdout.strip() if out.returncode == 0 else None


def version(root: Path = ROOT) -> Version:
    """The :class:`Version` of the checkout at ``root`` (git's HEAD, its commit date, and
    whether ``git status`` shows changed tracked files).

    Examples
    --------
    >>> v = version()
    >>> v.commit is None or (len(v.commit) == 40 and len(v.date) == 10)
    True
    """
    commit = _git(Path(root), "rev-parse", "--verify", "HEAD")
    if not commit:
        return Version(None, None, None)
    date = _git(Path(root), "log", "-1", "--format=%cs", commit)
    status = _git(Path(root), "status", "--porcelain", "--untracked-files=no")
    return Version(commit, date, None if status is None else bool(status))


def book_config(root: Path = ROOT) -> dict:
    """The book's ``_config.yml``."""
    return yaml.safe_load((Path(root) / "_config.yml").read_text())


def pdf_name(root: Path = ROOT) -> str:
    """The PDF's file name: the ``targetname`` of ``latex.latex_documents`` in ``_config.yml``,
    with ``.pdf`` for ``.tex``.

    Examples
    --------
    >>> pdf_name()
    'observability-lower-bounds-audited.pdf'
    """
    target = book_config(root)["latex"]["latex_documents"]["targetname"]
    return str(Path(target).with_suffix(".pdf"))
