"""Whether a quote is the paper's own words, without a copy of the paper in the package.

The package carries no text of the paper. It carries, as data, a fingerprint of the paper's
LaTeX source (``obslib/data/paper_source/word_chain.txt``): the source with its comments
removed, split at white space into words, and for every position ``i`` the first eight hex
digits of the SHA-256 of words ``i`` to ``i + 3`` joined by single spaces. A quote of ``n >= 4``
words is the paper's when some position ``i`` has the fingerprints of all ``n - 3`` of its
four-word windows at ``i, i + 1, ...``: the words, in order and contiguous. A quote is therefore
whole words of the source as printed there (LaTeX included, ``$\\alpha=1$``), punctuation as
attached to them; spacing does not matter.

The fingerprint is made from the source by ``python -m obslib.claims.quotes SOURCE.tex``, which
writes the data file (its provenance is in the file's header).

Examples
--------
>>> found("the inverse of the condition number is lower bounded by")
True
>>> found("the inverse of the condition number is upper bounded by")
False
"""

from __future__ import annotations

import hashlib
import re
import sys
from functools import lru_cache
from pathlib import Path

from .._io import write_output
from .._validate import as_path, as_str

__all__ = ["DATA", "MIN_WORDS", "words", "fingerprint", "found", "main"]

#: The fingerprint of the paper's source.
DATA = Path(__file__).resolve().parents[1] / "data" / "paper_source" / "word_chain.txt"

#: A quote has at least this many words (one window).
MIN_WORDS = 4

_COMMENT = re.compile(r"(?<!\\)%.*$", re.M)

HEADER = """\
# Fingerprint of the LaTeX source of Zhou and Tokekar, "A Lower Bound on Observability for
# Target Tracking with Range Sensors and its Application to Sensor Assignment" (arXiv:1706.00871),
# the source the book audits. Comments removed, the text split at white space into words; the
# i-th line after these comments (from 0) holds the first 8 hex digits of the SHA-256 of words
# i .. i + 3 joined by one space. Made by: python -m obslib.claims.quotes SOURCE.tex ({n} words).
"""


def words(text: str, latex: bool = False) -> list[str]:
    """``text`` split at white space; with ``latex`` the source's comments removed first.

    Examples
    --------
    >>> words("a % comment\\nb  c\\\\%d", latex=True)
    ['a', 'b', 'c\\\\%d']
    """
    text = as_str(text, "text")
    return (_COMMENT.sub("", text) if latex else text).split()


def _window(ws) -> str:
    return hashlib.sha256(" ".join(ws).encode()).hexdigest()[:8]


def fingerprint(source: str) -> list[str]:
    """The fingerprint of a LaTeX ``source``: one hash per four-word window, in order.

    Examples
    --------
    >>> len(fingerprint("one two three four five")), fingerprint("")
    (2, [])
    """
    ws = words(as_str(source, "source"), latex=True)
    return [_window(ws[i:i + MIN_WORDS]) for i in range(len(ws) - MIN_WORDS + 1)]


@lru_cache(maxsize=1)
def _chain() -> tuple[tuple[str, ...], dict]:
    lines = [ln.strip() for ln in DATA.read_text().splitlines()]
    chain = tuple(ln for ln in lines if ln and not ln.startswith("#"))
    where: dict = {}
    for i, h in enumerate(chain):
        where.setdefault(h, []).append(i)
    return chain, where


def found(quote: str) -> bool:
    """Whether ``quote`` (at least :data:`MIN_WORDS` words) is words of the paper's source, in
    order and contiguous.

    Raises
    ------
    ValueError
        For fewer than :data:`MIN_WORDS` words.
    """
    ws = words(as_str(quote, "quote"))
    if len(ws) < MIN_WORDS:
        raise ValueError(f"quote must have at least {MIN_WORDS} words, got {quote!r}")
    chain, where = _chain()
    hashes = [_window(ws[k:k + MIN_WORDS]) for k in range(len(ws) - MIN_WORDS + 1)]
    for i in where.get(hashes[0], ()):
        if i + len(hashes) <= len(chain) and all(chain[i + k] == h for k, h in enumerate(hashes)):
            return True
    return False


def main(argv=None) -> int:
    """``python -m obslib.claims.quotes SOURCE.tex``: write the fingerprint of ``SOURCE.tex``."""
    argv = sys.argv[1:] if argv is None else list(argv)
    if len(argv) != 1:
        print("usage: python -m obslib.claims.quotes SOURCE.tex", file=sys.stderr)
        return 2
    source = as_path(argv[0], "SOURCE", exists=True).read_text()
    chain = fingerprint(source)
    header = HEADER.format(n=len(words(source, latex=True)))
    write_output(DATA, header + "\n".join(chain) + "\n")
    _chain.cache_clear()
    print(f"{DATA}: {len(chain)} windows")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
