"""The PDF edition (``make pdf``), read as the browser test reads the pages.

``make pdf`` needs Debian's TeX Live and takes about a minute, so it is not part of this run:
these tests read the PDF it left in ``_build/latex/`` (with poppler's ``pdftotext``,
``pdfimages`` and ``pdffonts``). Without a PDF as new as the book's sources they skip with the
reason, except in CI (``CI`` set), where ``.ci/run`` builds it first and they must run.

What is checked: every chapter and section of the table of contents is in the PDF; no text of
the machinery (reprs of display objects, MyST or TeX left raw, unresolved references, hidden
code) and nothing only a browser shows; every figure and table has the number and caption it has
on the web, and every numbered statement (theorem, algorithm, remark, ...) its number; every
figure has its picture, the explorer's still and the animation's last frame included; every
font is embedded and no character fell out of them; the title page gives the version; and the
HTML book links this PDF.
"""

from __future__ import annotations

import functools
import json
import os
import re
import shutil
import subprocess

import pytest
from test_book import book, toc_pages  # noqa: F401  (the built HTML book, the table of contents)

from obsbook import edition
from obsbook.pdf import TEX_PACKAGES

ROOT = edition.ROOT
PDF = edition.LATEX_DIR / edition.pdf_name()
SOURCES = [
    ROOT / "_config.yml", ROOT / "_toc.yml", *ROOT.glob("book/*.md"), *ROOT.glob("book/*.bib"),
    *ROOT.glob("book/_ext/*.py"), *ROOT.glob("notebooks/*.ipynb"),
]


def _why_not_built() -> str | None:
    if not PDF.exists():
        return "no PDF edition has been built"
    built = PDF.stat().st_mtime
    newer = [p.relative_to(ROOT).as_posix() for p in SOURCES if p.stat().st_mtime > built]
    if newer:
        return f"the PDF edition is older than {', '.join(newer[:3])}"
    return None


@pytest.fixture(scope="module")
def pdf():
    """The built PDF, as new as its sources; skipped (failed in CI) otherwise."""
    reason = _why_not_built()
    if reason is None and shutil.which("pdftotext") is None:
        reason = "poppler's pdftotext is missing (apt-get install poppler-utils)"
    if reason is not None:
        reason += (f": make pdf builds it, with Debian's TeX Live "
                   f"(apt-get install {' '.join(TEX_PACKAGES)})")
        if os.environ.get("CI"):
            pytest.fail(f"CI must test the PDF edition, and {reason}")
        pytest.skip(reason)
    return PDF


@functools.cache
def _text(path, layout: bool = False) -> list[str]:
    """The text of each page of the PDF."""
    args = ["pdftotext", "-enc", "UTF-8", *(["-layout"] if layout else []), str(path), "-"]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    return out.split("\f")


@pytest.fixture(scope="module")
def pages(pdf) -> list[str]:
    return _text(pdf)


def _squash(text: str) -> str:
    """Text without whitespace and with typographic quotes and dashes made plain, to compare
    code lines with what pdftotext reads."""
    table = str.maketrans({"\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"',
                           "\u2212": "-", "\u2013": "-"})
    return re.sub(r"\s+", "", text.translate(table))


def _api_start(pages: list[str]) -> int:
    """Index of the page where the API reference begins (its pages document the code)."""
    starts = [k for k, p in enumerate(pages) if k > 10 and re.search(
        r"^\s*API REFERENCE\s*$", p, re.M) and "CHAPTER" in p.upper()]
    assert starts, "no chapter 'API reference' in the PDF"
    return starts[0]


# ------------------------------------------------------------------------- make pdf itself

def test_make_pdf_names_the_packages_when_tex_is_missing(monkeypatch, capsys):
    from obsbook import pdf as build

    monkeypatch.setattr(build.shutil, "which", lambda name: None)
    assert {package for _, package in build.missing()} >= {"texlive-xetex", "latexmk", "xindy"}
    assert build.main([]) == 1
    err = capsys.readouterr().err
    assert "missing: xelatex, latexmk, xindy" in err
    assert all(package in err for package in TEX_PACKAGES)


def test_make_pdf_refuses_unknown_arguments(capsys):
    from obsbook import pdf as build

    with pytest.raises(SystemExit) as exc:
        build.main(["--fast"])
    assert exc.value.code == 2 and "--fast" in capsys.readouterr().err


def test_the_pdf_is_copied_beside_the_pages_whole_and_readable(tmp_path):
    from obsbook import pdf as build

    latex, html = tmp_path / "latex", tmp_path / "html"
    latex.mkdir()
    assert build.copy_to_html(latex, html) is None  # nothing built
    (latex / edition.pdf_name()).write_bytes(b"%PDF-1.5 a book")
    assert build.copy_to_html(latex, html) is None  # no pages to put it beside
    html.mkdir()
    umask = os.umask(0o022)
    try:
        copy = build.copy_to_html(latex, html)
    finally:
        os.umask(umask)
    assert copy == html / edition.pdf_name() and copy.read_bytes() == b"%PDF-1.5 a book"
    assert copy.stat().st_mode & 0o777 == 0o644  # as any file written under that umask
    assert [p.name for p in html.iterdir()] == [copy.name]  # no temporary file left


# ------------------------------------------------------------------------------------- contents

def _title(source) -> str:
    """The first heading of a page of the book, as its text reads."""
    if source.suffix == ".ipynb":
        text = "".join("".join(c["source"]) + "\n" for c in json.loads(source.read_text())["cells"]
                       if c["cell_type"] == "markdown")
    else:
        text = source.read_text()
    title = re.search(r"^# (.+)$", text, re.M).group(1)
    return re.sub(r"\$[^$]*\$", "", title).strip()


def test_every_chapter_of_the_table_of_contents_is_in_the_pdf(pages):
    contents = _squash(" ".join(pages[:12])).casefold()
    body = _squash(" ".join(pages)).casefold()
    missing = []
    for rel in toc_pages()[1:]:  # the front page opens the book, without a heading of its own
        stem = rel.removesuffix(".html")
        source = next(p for p in (ROOT / f"{stem}.ipynb", ROOT / f"{stem}.md") if p.exists())
        title = _squash(_title(source)).casefold()
        if title not in contents or title not in body:
            missing.append(f"{stem}: {_title(source)!r}")
    assert not missing, "chapters missing from the PDF's contents:\n" + "\n".join(missing)
    front = _squash(" ".join(pages[:16]))
    assert _squash("What this book found") in front  # the front page's findings open the book


def test_the_title_page_gives_the_version(pages):
    v = edition.version()
    if v.commit is None:
        pytest.skip("not a git checkout: the PDF has no version to give")
    # the PDF may be from another commit than the checkout's HEAD; it must name one
    m = re.search(r"Version ([0-9a-f]{12})\b", pages[0])
    assert m and re.search(r"\d{4}-\d{2}-\d{2}", pages[0]), pages[0][:300]


# ------------------------------------------------------------------------- nothing of the machinery

#: Text that only the machinery writes, anywhere in the PDF.
MACHINERY = {
    "a display object's repr": (r"<IPython\.[\w.]+ object>|<Figure size \d+x\d+"
                                r"|object at 0x[0-9a-f]+"),
    "MyST left raw": r"\{(?:glue|glue:\w+|prf:\w+|numref|doc|ref|cite|only|figure)\}|```|^:::",
    "an unresolved reference": r"\?\?|\[\?\]",
    "a notebook's cell tags or buttons": r"remove-input|hide-input|print-only|Show code cell",
    "what only a browser shows": r"needs JavaScript|Drag the sensors",
}
#: Text of the machinery that the API reference may show, since it documents the code (its
#: examples show errors; code cells elsewhere may hold TeX in strings, never between dollars).
MACHINERY_OUTSIDE_API = {
    "TeX left raw": r"\$\\[A-Za-z]+|\\\(|\\\[|\$\$",
    "a traceback": r"Traceback \(most recent call last\)",
    "a glued value's record": r"scrapbook|application/papermill",
}


def test_no_text_of_the_machinery(pages):
    api = _api_start(pages)
    found = []
    for k, page in enumerate(pages):
        checks = {**MACHINERY, **(MACHINERY_OUTSIDE_API if k < api else {})}
        for what, pattern in checks.items():
            for m in re.finditer(pattern, page, re.M):
                found.append(f"page {k + 1}: {what}: {page[max(0, m.start() - 40):m.end() + 40]!r}")
    assert not found, "\n".join(found[:20])


def test_the_checks_for_machinery_can_fail():
    page = "x <IPython.core.display.HTML object> y {glue:md}`a` ?? $\\frac{1}{2}$ scrapbook"
    hits = {what for what, p in {**MACHINERY, **MACHINERY_OUTSIDE_API}.items()
            if re.search(p, page, re.M)}
    assert hits == {"a display object's repr", "MyST left raw", "an unresolved reference",
                    "TeX left raw", "a glued value's record"}


def _code_lines():
    """(hidden, shown): the long lines of the notebooks' hidden and visible code cells."""
    hidden, shown = set(), set()
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        for cell in json.loads(path.read_text())["cells"]:
            if cell["cell_type"] != "code":
                continue
            tags = cell.get("metadata", {}).get("tags", [])
            bucket = hidden if {"remove-input", "hide-input", "remove-cell"} & set(tags) else shown
            for line in "".join(cell["source"]).splitlines():
                if len(_squash(line)) >= 40 and not line.lstrip().startswith("#"):
                    bucket.add(_squash(line))
    return hidden - shown, shown


def test_no_hidden_code(pages):
    """No line of a hidden code cell is printed, while the visible cells' lines are found by
    the same comparison (so that it can find one)."""
    text = _squash("".join(pages[:_api_start(pages)]))  # the API reference quotes the library
    hidden, shown = _code_lines()
    leaked = sorted(line for line in hidden if line in text)
    assert not leaked, "hidden code in the PDF:\n" + "\n".join(leaked[:10])
    found = sum(line in text for line in shown)
    assert len(shown) > 50 and found >= 0.8 * len(shown), (found, len(shown))


# ------------------------------------------------------------------------- numbered as on the web

def _web_numbers(book) -> dict:  # noqa: F811 (the fixture's name)
    """``(kind, number) -> the first words of the caption`` of every figure and table of the
    HTML book, and the numbered statements in the order of the pages."""
    captions, statements = {}, []
    for rel in toc_pages():
        html = (book / rel).read_text()
        for m in re.finditer(r'<span class="caption-number">(Figure|Table) (\d+) </span>'
                             r'<span class="caption-text">(.*?)</span>', html, re.S):
            captions[(m.group(1), int(m.group(2)))] = _words(m.group(3))
        statements += [f"{kind} {n}" for kind, n in re.findall(
            r'<p class="admonition-title"><span class="caption-number">([A-Z][a-z]+) (\d+) ',
            html)]
    return {"captions": captions, "statements": statements}


def _words(text: str) -> str:
    """The first words of a caption before any formula, letters only."""
    text = re.sub(r"<[^>]+>", " ", text)
    text = re.split(r"\\\(|\$|[\U0001D400-\U0001D7FF]", text)[0]  # MathJax's or math italics
    return "".join(re.findall(r"[A-Za-z]", text))[:24]


def test_figures_tables_and_statements_are_numbered_as_on_the_web(pages, book):  # noqa: F811
    web = _web_numbers(book)
    text = "\n".join(pages)
    printed = {}
    for kind, n, caption in re.findall(r"^(Figure|Table) (\d+): (.*(?:\n.*){0,2})", text, re.M):
        printed.setdefault((kind, int(n)), _words(caption))
    assert len(web["captions"]) > 150
    assert set(printed) == set(web["captions"]), (
        sorted(set(web["captions"]) ^ set(printed))[:20])
    wrong = []
    for key in sorted(printed):
        a, b = printed[key], web["captions"][key]
        if a[:min(len(a), len(b))] != b[:min(len(a), len(b))]:
            wrong.append(f"{key[0]} {key[1]}: on the web {b!r}, in print {a!r}")
    assert not wrong, "\n".join(wrong[:20])
    # the statements' boxes, in the order of the pages (the prose names them too, so the web's
    # sequence must be found in order among the printed lines that start with a name)
    kinds = "Theorem|Algorithm|Remark|Definition|Observation|Proposition|Exercise"
    heads = iter(re.findall(rf"^((?:{kinds}) \d+)(?: \(.*)?$", text, re.M))
    missing = [s for s in web["statements"] if not any(h == s for h in heads)]
    assert len(web["statements"]) > 30 and not missing, missing


# ------------------------------------------------------------------------- pictures and fonts

@pytest.fixture(scope="module")
def images(pdf) -> dict:
    """Page number -> the sizes (px) of the pictures on it."""
    out = subprocess.run(["pdfimages", "-list", str(pdf)], capture_output=True, text=True,
                         check=True).stdout
    found: dict = {}
    for line in out.splitlines()[2:]:
        cols = line.split()
        if len(cols) > 4 and cols[2] == "image":
            found.setdefault(int(cols[0]), []).append((int(cols[3]), int(cols[4])))
    return found


def test_every_figure_has_its_picture(pages, images):
    empty = [f"page {k + 1}: {m.group(0)}" for k, page in enumerate(pages)
             for m in re.finditer(r"^Figure \d+:", page, re.M) if not images.get(k + 1)]
    assert not empty, "figures without a picture:\n" + "\n".join(empty)


def test_the_explorer_is_a_still_and_a_sentence(pages, images):
    (k,) = [k for k, p in enumerate(pages) if "Explorer: where should the next sensor go?" in p
            and "CONTENTS" not in p.upper()[:200]]
    after = " ".join(pages[k:k + 2])
    assert "In the web edition of this book a live explorer stands here" in " ".join(after.split())
    # the still is the print-only cell's figure, drawn at 200 px per inch: 7.5 in by 5.4 in
    stills = [(p, size) for p in (k + 1, k + 2) for size in images.get(p, [])
              if size == (1500, 1080)]
    assert stills, images.get(k + 1, []) + images.get(k + 2, [])


def test_the_animation_is_its_last_frame(pages, images):
    (k,) = [k for k, p in enumerate(pages) if re.search(r"Figure \d+: The run of Fig\. 4", p)]
    assert images.get(k + 1), "the animation's figure has no picture"
    assert "in print the last frame shows the whole run" in " ".join(pages[k].split())


def test_every_font_is_embedded_and_holds_every_character(pdf):
    out = subprocess.run(["pdffonts", str(pdf)], capture_output=True, text=True,
                         check=True).stdout.splitlines()[2:]
    assert out and all(line.split()[-5] == "yes" for line in out), "\n".join(out)
    log = pdf.with_suffix(".log").read_text(errors="replace")
    assert "Missing character" not in log


# ------------------------------------------------------------------------- linked from the web

def test_the_html_book_links_the_pdf(pdf, book):  # noqa: F811
    copy = book / pdf.name
    assert copy.is_file() and copy.read_bytes() == pdf.read_bytes()
    for rel in ("book/intro.html", "book/cite.html"):
        hrefs = re.findall(r'href="([^"]+\.pdf)"', (book / rel).read_text())
        assert hrefs and all((book / rel).parent.joinpath(h).resolve() == copy.resolve()
                             for h in hrefs), (rel, hrefs)
