"""The built book: complete, offline, and working in a real headless browser.

The book is rendered (not re-executed) into ``_build/html`` when it is missing or older than its
sources. The browser test drives Debian's ``chromium`` through ``chromium-driver`` (Selenium, no
downloaded browser) against the book served on 127.0.0.1. Without Chromium it skips with the
reason, except in CI (``CI`` set), where it must run: ``.ci/run`` installs both packages.
Screenshots of every page, 1400 px wide, go to ``_build/screenshots/``, and 390 px wide (a phone)
to ``_build/screenshots/390/``, for review.

What a reader sees is checked page by page (one test per page and check, so that a failure names
both): no glued value shown in quotes, no TeX left raw in the text, no element wider than its
container, every image of a notebook in a figure with a caption, captions at WCAG AA contrast
(4.5:1, in light and dark mode), no dead internal link, and no request leaving the page's origin;
and on a 390 px screen: no page wider than the screen, every control of the animation players on
the screen, and every figure linked to its image file (shown full size in an overlay). The prose
reads as written for a person: no Python reprs, True/False or e-notation, every table numbered
with its caption above, visible code free of imports, helpers and glue, and no words about how
the book was made; the front page opens with its written summary. Every figure has at least two
image pixels per pixel shown (sharp on HiDPI screens), and on a phone each figure of each
chapter, tapped open, shows its smallest text at 10 pt of its own size.

The explorer's section is in its chapter's contents under the label ``explorer``; the index of
theorems, algorithms and remarks names them as their boxes do; the site search lists the
chapters before the API reference; "How to cite" names the commit the book was built from.

The bound explorer on the pair closed-form page is driven through its contract
(``window.boundExplorer.set``, ``.bound-value``, ``.exact-value``, the ``data-`` state) at random
geometries and compared with ``obslib``, and dragged with the mouse.
"""

from __future__ import annotations

import functools
import http.server
import json
import math
import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest
import yaml

from obsbook import edition
from obslib.tools import run
from obslib.tools.run import ROOT

BUILD = ROOT / "_build" / "html"
SHOTS = ROOT / "_build" / "screenshots"
#: The scripts the browser runs on each page, beside this file.
SCRIPTS = Path(__file__).with_name("js")
SOURCES = [
    ROOT / "_config.yml",
    ROOT / "_toc.yml",
    *ROOT.glob("book/*.md"),
    *ROOT.glob("book/*.bib"),
    *ROOT.glob("book/_static/*"),
    *ROOT.glob("book/_ext/*.py"),
    *ROOT.glob("notebooks/*.ipynb"),
    *ROOT.glob("obslib/**/*.py"),
]  # the API pages are the docstrings


def _stale() -> bool:
    index = BUILD / "index.html"
    if not index.exists():
        return True
    built = index.stat().st_mtime
    return any(p.stat().st_mtime > built for p in SOURCES if p.exists())


@pytest.fixture(scope="session")
def book() -> Path:
    """Path of the rendered book, rendering it first (execution off, warnings as errors) if
    needed."""
    from obsbook import front
    from obslib._io import locked

    BUILD.parent.mkdir(exist_ok=True)
    with locked(BUILD.parent / ".render.lock"):  # one render when workers ask at once
        _render(front)
    return BUILD


def _render(front) -> None:
    front.write_figure(front.FIGURE)  # as make book does; unchanged when it holds the picture
    if _stale():
        if not run.EXECUTION_PAGE.exists():
            times = json.loads(run.TIMES_FILE.read_text()) if run.TIMES_FILE.exists() else {}
            run.EXECUTION_PAGE.write_text(run.execution_page(times))
        jb = Path(sys.executable).with_name("jupyter-book")
        proc = subprocess.run(
            [
                str(jb),
                "build",
                str(ROOT),
                "--builder",
                "html",
                "--warningiserror",
                "--nitpick",
                "--keep-going",
            ],
            capture_output=True,
            text=True,
            cwd=ROOT,
        )
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]


def pages(book: Path) -> list[Path]:
    return sorted(
        p for p in book.rglob("*.html")
        if not any(part.startswith(("_", ".")) for part in p.relative_to(book).parts)
    )


def test_every_toc_page_is_built(book):
    for f in toc_pages():
        assert (book / f).exists(), f"{f} was not rendered"


EXTERNAL = re.compile(
    r"""<script[^>]*\ssrc=["'](?:https?:)?//|<link[^>]*\shref=["'](?:https?:)?//[^"']*["'][^>]*>|<iframe[^>]*\ssrc=["'](?:https?:)?//""",
    re.I,
)


def test_no_resource_is_fetched_from_the_network(book):
    """No external script, stylesheet, font or frame in any page or stylesheet of the build."""
    offenders = []
    for page in pages(book):
        for m in EXTERNAL.finditer(page.read_text(errors="replace")):
            tag = m.group(0)
            if tag.lower().startswith("<link") and not re.search(
                r"rel=[\"'](stylesheet|preload|icon|font)", tag, re.I
            ):
                continue  # plain hyperlinks such as canonical or author pages fetch nothing
            offenders.append(f"{page.relative_to(book)}: {tag[:120]}")
    for css in book.rglob("*.css"):
        for m in re.finditer(
            r"(@import\s+url\(|url\()\s*[\"']?(https?:)?//[^)]*\)", css.read_text(errors="replace")
        ):
            offenders.append(f"{css.relative_to(book)}: {m.group(0)[:120]}")
    assert not offenders, "\n".join(offenders)


def test_no_page_shows_where_the_book_was_built(book):
    """No page shows the path of the checkout (a default value or a constant in the API pages
    would print it): the book reads the same wherever it is built."""
    shown = [
        page.relative_to(book).as_posix() for page in pages(book) if str(ROOT) in page.read_text()
    ]
    assert not shown, shown


def test_mathjax_is_served_from_the_build(book):
    page = (book / "notebooks" / "01_model_and_bound.html").read_text()
    src = re.findall(r"<script[^>]*src=\"([^\"]*mathjax[^\"]*)\"", page, re.I)
    assert src and all(not s.startswith(("http", "//")) for s in src), src
    assert (book / "_static" / "mathjax" / "tex-chtml.js").exists()


def test_notebook_download_links_resolve_locally(book):
    for page in (book / "notebooks").glob("*.html"):
        links = re.findall(r"href=\"([^\"]+\.ipynb)\"", page.read_text())
        assert links, f"{page.name}: no notebook download link"
        for link in links:
            assert not link.startswith(("http", "//")), link
            assert (page.parent / link).resolve().exists(), (
                f"{page.name}: {link} is missing from the build"
            )


# ------------------------------------------------------------------------------------- browser


@pytest.fixture(scope="module")
def server(book):
    handler = functools.partial(_QuietHandler, directory=str(book))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def browser():
    chromium, chromedriver = shutil.which("chromium"), shutil.which("chromedriver")
    if not (chromium and chromedriver):
        reason = ("the browser test needs Debian's chromium and chromium-driver "
                  "(apt-get install chromium chromium-driver)")
        if os.environ.get("CI"):
            pytest.fail(f"CI must run the browser test: {reason}")
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    opts = Options()
    opts.binary_location = chromium
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-dev-shm-usage",
        f"--window-size={WIDTH},1600",
    ):
        opts.add_argument(flag)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(chromedriver), options=opts)
    driver.set_page_load_timeout(60)
    yield driver
    driver.quit()


#: Width of the browser window (the screenshots have this width).
WIDTH = 1400


def toc_pages() -> list[str]:
    """The pages of the table of contents (chapters and their sections), as paths of their HTML
    files in the build."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())

    def files(entries):
        for e in entries or []:
            yield e["file"]
            yield from files(e.get("sections"))

    return [
        f"{f}.html"
        for f in [toc["root"], *(f for part in toc["parts"] for f in files(part["chapters"]))]
    ]


#: A promise that the page's formulas are typeset. MathJax loads after the page, and until it has
#: loaded ``MathJax.startup`` does not exist: wait for it (15 s at most) on a page with formulas,
#: then for the typesetting (60 s at most; ``typeset`` says whether it finished).
def script(name: str) -> str:
    """The JavaScript in ``tests/js/<name>``."""
    return (SCRIPTS / name).read_text()


MATH_READY = script("math_ready.js")

#: The callback of an asynchronous script (Selenium's ``execute_async_script``).
DONE = "const done = arguments[arguments.length - 1];\n"

PAGE_CHECK = DONE + MATH_READY + script("page_check.js")


def visit_every_page(book, server, browser, width: int, height: int, check: str, shots: Path,
                     after=None) -> dict:
    """Open every built page in a window ``width`` x ``height`` px, run the asynchronous script
    ``check`` (which returns a dict with the page's ``height``), call ``after(result)`` if given,
    and save a screenshot of the page (down to that height) in ``shots``; the results by page
    path."""
    shots.mkdir(parents=True, exist_ok=True)
    browser.set_script_timeout(120)
    out = {}
    for page in pages(book):
        rel = page.relative_to(book).as_posix()
        browser.set_window_size(width, height)
        browser.get(f"{server}/{rel}")
        result = browser.execute_async_script(check)
        if after is not None:
            after(result)
        browser.set_window_size(width, max(800, result["height"]))
        browser.save_screenshot(str(shots / (rel.replace("/", "__").replace(".html", ".png"))))
        out[rel] = result
    browser.set_window_size(WIDTH, 1600)
    return out


@pytest.fixture(scope="module")
def seen(book, server, browser) -> dict:
    """Every built page as the browser shows it: the results of :data:`PAGE_CHECK` and the
    console errors, by page path; a screenshot of each page goes to ``_build/screenshots/``."""

    def console(result):
        result["errors"] = [
            e["message"] for e in browser.get_log("browser")
            if e["level"] == "SEVERE" and "favicon.ico" not in e["message"]
        ]

    return visit_every_page(book, server, browser, WIDTH, 1600, PAGE_CHECK, SHOTS, after=console)


def test_every_page_renders_in_a_headless_browser(seen):
    problems, n_anims, n_math, n_images = [], 0, 0, 0
    for rel, result in seen.items():
        if result["errors"]:
            problems.append(f"{rel}: console errors {result['errors'][:3]}")
        if result["broken"]:
            problems.append(f"{rel}: images that did not load {result['broken'][:3]}")
        for a in result["anims"]:
            if not a["loaded"] or a["frames"] < 2:
                problems.append(f"{rel}: animation without frames {a}")
        n_anims += len(result["anims"])
        n_math += result["math"]
        n_images += result["images"]
    assert not problems, "\n".join(problems)
    # the checks must have had something to check
    assert n_math > 100 and n_images > 20 and n_anims >= 1, (n_math, n_images, n_anims)


# ------------------------------------------------------------------- what a reader sees, per page

_ID = re.compile(r"""\sid=["']([^"']+)["']""")
_HREF = re.compile(r"""<a\s[^>]*href=["']([^"']+)["']""", re.I)


@functools.cache
def _ids(path: Path) -> frozenset:
    return frozenset(_ID.findall(path.read_text(errors="replace")))


def pdf_not_built(book: Path) -> bool:
    """Whether the PDF edition, which the pages link, is missing from the build where it may be:
    ``make pdf`` has not run on this machine (it needs TeX), and this is not CI, which builds
    it (tests/test_pdf.py then skips with the reason)."""
    return not (book / edition.pdf_name()).exists() and not os.environ.get("CI")


@functools.cache
def dead_links(book: Path, rel: str) -> tuple[str, ...]:
    """Internal links of a page whose file or anchor does not exist in the build (the PDF
    edition aside where :func:`pdf_not_built`)."""
    page = book / rel
    dead = []
    pdf, no_pdf = edition.pdf_name(), pdf_not_built(book)
    for href in _HREF.findall(page.read_text(errors="replace")):
        if href.endswith(pdf) and no_pdf:
            continue
        if re.match(r"^https?://[^/]+\.(md|py|ipynb|txt|json|yml|cfg|toml)/?$", href, re.I):
            dead.append(href)  # a file name that linkify turned into a web address
            continue
        if re.match(r"^[a-z][a-z0-9+.-]*:", href, re.I) or href.startswith("//"):
            continue  # external (http, mailto, ...): a plain hyperlink, fetched only if followed
        target, _, frag = href.partition("#")
        path = (page.parent / target.split("?")[0]).resolve() if target else page
        if path.is_dir():
            path = path / "index.html"
        if not path.exists():
            dead.append(href)
        elif frag and path.suffix == ".html" and frag not in _ids(path):
            dead.append(href)
    return tuple(sorted(set(dead)))


CHECKS = {
    "quoted_glue": "glued values shown as quoted strings",
    "raw_tex": "TeX left raw in the text",
    "too_wide": "elements wider than their container",
    "uncaptioned_images": "images outside a figure with a caption",
    "caption_contrast": "captions below WCAG AA contrast (4.5:1) in light or dark mode",
    "dead_links": "dead internal links",
    "external_requests": "requests to another origin",
    "math_typeset": "formulas that MathJax did not typeset within a minute",
    "machine_notation": "Python reprs, True/False, e-notation, '0 of them' or a stray $ in prose",
    "unnumbered_tables": "tables without a numbered caption above them",
    "bookkeeping_code": "visible code cells with import, def or glue lines",
    "process_words": "words about how the book was made",
    "blurry_figures": "figures with fewer than two image pixels per pixel shown (blurred on "
                      "HiDPI screens and when zoomed)",
}

def _param(check: str, rel: str):
    """One test per check and page, named by both."""
    return pytest.param(check, rel, id=f"{check}-{rel.removesuffix('.html')}")


#: Pages a check does not apply to: the API reference documents the code (its module names,
#: tables of signatures), the execution statistics list the notebooks by file, and "How to
#: cite" gives the commit the book was built from.
EXEMPT = {
    "machine_notation": ("book/api",),
    "unnumbered_tables": ("book/api", "book/execution"),
    "process_words": ("book/api", "book/execution", "book/cite"),
}


@pytest.mark.parametrize("check, rel", [_param(c, p) for c in CHECKS for p in toc_pages()
                                        if not p.startswith(EXEMPT.get(c, ()))])
def test_what_a_reader_sees(check, rel, book, seen):
    result = seen[rel]
    found = {
        "quoted_glue": result["quoted"],
        "raw_tex": result["raw"],
        "too_wide": result["wide"]
        + ([f"... {result['n_wide'] - 12} more"] if result["n_wide"] > 12 else []),
        "uncaptioned_images": result["uncaptioned"],
        "caption_contrast": result["low_contrast"],
        "dead_links": dead_links(book, rel),
        "external_requests": result["external"],
        "math_typeset": [] if result["typeset"] else ["MathJax did not finish"],
        "machine_notation": result["machine"],
        "unnumbered_tables": result["bad_tables"],
        "bookkeeping_code": result["bookkeeping"],
        "process_words": result["process"],
        "blurry_figures": result["blurry"],
    }[check]
    assert not found, f"{rel}: {CHECKS[check]}:\n" + "\n".join(map(str, found))


def test_the_front_page_opens_with_its_summary(seen):
    """At 1400 px the front page is at most about four screens tall, its written summary starts on
    the first screen (900 px), and it holds no long table: the full ledger lives in the report."""
    front = seen["book/intro.html"]
    assert front["height"] <= 5000, front["height"]
    assert front["summary_top"] is not None and front["summary_top"] < 900, front["summary_top"]
    assert front["max_rows"] <= 25, front["max_rows"]


def test_the_front_page_shows_the_bound_at_a_glance(book):
    """The front page shows the idea of the bound in a numbered figure, drawn when the book is
    built (``python -m obsbook.front``), whose caption links the bound explorer by name."""
    from obsbook import front

    html = (book / "book" / "intro.html").read_text()
    fig = re.search(r'<figure[^>]*id="fig-front-bound".*?</figure>', html, re.S)
    assert fig, "the front page shows no picture"
    assert re.search(r'caption-number">Figure \d', fig.group(0))
    assert re.search(r'href="[^"]*02_pair_closed_form\.html#explore-the-bound"[^>]*>.*?'
                     r'the bound explorer',
                     fig.group(0), re.S)
    chapter = (book / "notebooks" / "02_pair_closed_form.html").read_text()
    assert 'id="explore-the-bound"' in chapter
    src = re.search(r'<img[^>]*src="([^"]+)"', fig.group(0)).group(1)
    assert (book / "book" / src).resolve().read_bytes() == front.front_figure()[0]


# ------------------------------------------------------------------- the checks themselves can fail

PNG = bytes.fromhex(
    "89504e470d0a1a0a0000000d49484452000000010000000108060000001f15c489"
    "0000000d49444154789c6360f8cfc0f01f0005fe02fea7d6a4b30000000049454e44ae426082"
)


def _serve(directory: Path):
    handler = functools.partial(_QuietHandler, directory=str(directory))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    return httpd, f"http://127.0.0.1:{httpd.server_address[1]}"


def test_page_check_finds_each_defect_on_a_page_made_to_have_them(tmp_path, browser):
    """A page with one of each defect (and a clean twin of each) must be reported exactly so."""
    (tmp_path / "dot.png").write_bytes(PNG)
    other, other_url = _serve(tmp_path)  # another port is another origin
    page = f"""<!doctype html><html><body><main><article class="bd-article" style="width:600px">
<p>value <span class="output text_plain">'0.4849'</span>,
fine <span class="output text_plain">0.5204</span></p>
<p>raw $\\lambda_{{\\max}}$ here</p>
<pre style="overflow-x:auto">{"x" * 400}</pre>
<div style="width:900px">sticks out</div>
<p><img src="dot.png"></p>
<figure><img src="dot.png"><figcaption>Figure 1. A caption.</figcaption></figure>
<figure><img src="dot.png">
<figcaption style="color:#999">Figure 2. A pale caption.</figcaption></figure>
<figure><img src="dot.png">
<figcaption style="color:#595959">Figure 3. Grey, but 7:1.</figcaption></figure>
<figure style="opacity:0.3"><img src="dot.png">
<figcaption>Figure 4. Black, faded.</figcaption></figure>
<img src="{other_url}/dot.png" alt="">
<p>the check holds: True for (i, j) = [(1, 1)], a gap of 3.0e-04, as the tests show.</p>
<p>clean: in none of 2,000 scenes; a gap of 0.25.</p>
<table><tr><td>no caption</td></tr></table>
<table><caption><span class="caption-number">Table 1 </span>Numbered.</caption>
<tr><td>ok</td></tr></table>
<div class="cell"><div class="cell_input"><pre>import numpy as np
x = 1</pre></div></div>
<details><div class="cell"><div class="cell_input"><pre>def folded(): pass</pre></div></div>
</details>
<div class="cell"><div class="cell_input"><pre>result = run(x)</pre></div></div>
</article></main></body></html>"""
    (tmp_path / "page.html").write_text(page)
    httpd, url = _serve(tmp_path)
    try:
        browser.set_window_size(WIDTH, 1600)
        browser.get(f"{url}/page.html")
        r = browser.execute_async_script(PAGE_CHECK)
    finally:
        httpd.shutdown()
        other.shutdown()
    assert r["quoted"] == ["'0.4849'"]
    assert r["raw"] and all("lambda" in s for s in r["raw"]), r["raw"]
    assert any(w.startswith("pre") and "needs" in w for w in r["wide"]), r["wide"]
    assert any(w.startswith("div") and "ends at" in w for w in r["wide"]), r["wide"]
    assert len(r["uncaptioned"]) == 2, r["uncaptioned"]  # the bare image and the external one
    # #999 on white is 2.85:1; #595959 is 7.0:1 (WCAG's formula), in either mode of a plain page
    # and black at opacity 0.3 on white is rgb(178.5, 178.5, 178.5), 2.11:1
    pale = [c for c in r["low_contrast"] if "A pale caption" in c and "2.85:1" in c]
    faded = [c for c in r["low_contrast"] if "Black, faded" in c and "2.11:1" in c]
    assert len(pale) == len(faded) == 2 and len(r["low_contrast"]) == 4, r["low_contrast"]
    assert [u.split("/")[-1] for u in r["external"]] == ["dot.png"]
    assert r["external"][0].startswith(other_url)
    machine = " | ".join(r["machine"])
    assert all(w in machine for w in ("True", "[(1, 1)", "3.0e-04")), r["machine"]
    assert "2,000" not in machine and "0.25" not in machine, r["machine"]
    assert len(r["bad_tables"]) == 1 and "no caption" in r["bad_tables"][0], r["bad_tables"]
    assert len(r["bookkeeping"]) == 1 and "import numpy" in r["bookkeeping"][0], r["bookkeeping"]
    assert len(r["process"]) == 1 and "the tests" in r["process"][0], r["process"]


def test_dead_links_finds_missing_files_and_anchors(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "b.html").write_text('<h1 id="top">B</h1>')
    (tmp_path / "sub" / "a.html").write_text(
        '<a href="../b.html#top">ok</a> <a href="../b.html#nowhere">bad anchor</a> '
        '<a href="../c.html">missing</a> <a href="#here">bad local</a> <p id="there"></p> '
        '<a href="#there">ok local</a> <a href="https://example.org/x">external</a> '
        '<a href="mailto:a@b.c">mail</a> <a href="http://NOTES.md">a file name made a link</a>'
    )
    _ids.cache_clear()
    assert list(dead_links(tmp_path, "sub/a.html")) == [
        "#here", "../b.html#nowhere", "../c.html", "http://NOTES.md"]


def test_links_to_the_report_read_as_words(book):
    """A link to a claim's entry in the report names the claim in words, never by its ledger id
    (the API reference, which documents the ledger's code, names claims by id)."""
    from obslib.claims import registry

    ids = set(registry())
    link = re.compile(r'<a [^>]*href="[^"]*report\.html#claim-([a-z0-9-]+)"[^>]*>(.*?)</a>', re.S)
    as_id, n = [], 0
    for page in pages(book):
        rel = page.relative_to(book).as_posix()
        if rel == "book/report.html" or rel.startswith("book/api"):
            continue
        for m in link.finditer(page.read_text(errors="replace")):
            n += 1
            text = re.sub(r"<[^>]+>", "", m.group(2)).strip()
            if text in ids or text.startswith("claim-"):
                as_id.append(f"{rel}: {text}")
    assert n > len(ids), f"only {n} links to the report's entries: the check checks nothing"
    assert not as_id, "\n".join(as_id)


# ------------------------------------------------------------------------- on a phone (390 px)

#: Width of a phone's screen (an iPhone 12 to 15 in portrait).
NARROW = 390

NARROW_CHECK = DONE + MATH_READY + script("narrow_check.js")


@pytest.fixture(scope="module")
def seen_narrow(book, server, browser) -> dict:
    """Every built page on a 390 px screen: the results of :data:`NARROW_CHECK`, by page path;
    a screenshot of each page (its first 16,000 px) goes to ``_build/screenshots/390/``."""
    return visit_every_page(book, server, browser, NARROW, 844, NARROW_CHECK, SHOTS / str(NARROW))


NARROW_CHECKS = {
    "phone_overflow": "the page is wider than a 390 px screen",
    "phone_players": "controls of an animation player outside a 390 px screen",
    "figure_zoom": "figures without a working link to their image file",
}


def _narrow_found(check: str, result: dict) -> list:
    if check == "phone_overflow":
        wide = result["scroll_width"] > result["viewport"]
        return [f"scroll width {result['scroll_width']}px, screen {result['viewport']}px",
                *result["sticking"]] if wide else []
    return result[{"phone_players": "players", "figure_zoom": "figures"}[check]]


@pytest.mark.parametrize("check, rel", [
    pytest.param(c, p, id=f"{c}-{p.removesuffix('.html')}") for c in NARROW_CHECKS
    for p in toc_pages()])
def test_what_a_reader_sees_on_a_phone(check, rel, seen_narrow):
    found = _narrow_found(check, seen_narrow[rel])
    assert not found, f"{rel}: {NARROW_CHECKS[check]}:\n" + "\n".join(map(str, found))


def test_the_generated_pages_fit_a_phone(seen_narrow):
    """The index pages Sphinx adds (general index, module index, theorems, search) fit too, and
    the checks above had players and figures to check."""
    toc = set(toc_pages())
    extra = {rel: r for rel, r in seen_narrow.items() if rel not in toc}
    assert {"genindex.html", "search.html"} <= set(extra), sorted(extra)
    wide = [f"{rel}: {_narrow_found('phone_overflow', r)}" for rel, r in extra.items()
            if _narrow_found("phone_overflow", r)]
    assert not wide, "\n".join(wide)
    assert sum(r["n_controls"] for r in seen_narrow.values()) >= 10
    assert sum(r["n_figures"] for r in seen_narrow.values()) > 20


def test_a_figure_opens_full_size_on_a_phone(server, browser):
    """A tap on a figure shows it at its own size (the width its page gives it, not narrowed to
    the screen) in an overlay that scrolls, and the page behind does not widen; Escape closes
    it."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import WebDriverWait

    browser.set_window_size(NARROW, 900)
    try:
        browser.get(f"{server}/notebooks/05_two_sensors_tracking.html")
        link = browser.find_element(By.CSS_SELECTOR, "figure a.bk-zoom")
        browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", link)
        link.click()
        WebDriverWait(browser, 10).until(lambda d: d.execute_script(
            "const i = document.querySelector('.bk-lightbox:not([hidden]) img');"
            "return !!i && i.complete && i.naturalWidth > 0"))
        r = browser.execute_script(
            """
            const box = document.querySelector('.bk-lightbox'), img = box.querySelector('img');
            return {shown: img.getBoundingClientRect().width, natural: img.naturalWidth,
                    own: parseFloat(arguments[0].querySelector('img').style.width),
                    href: arguments[0].getAttribute('href'), src: img.getAttribute('src'),
                    box_scrolls: box.scrollWidth > box.clientWidth,
                    page: document.documentElement.scrollWidth,
                    screen: document.documentElement.clientWidth};
        """,
            link,
        )
        assert r["src"] == r["href"] and r["href"].endswith(".png"), r
        assert r["own"] > 0 and abs(r["shown"] - r["own"]) <= 1, r  # its own size
        assert r["shown"] > NARROW and r["box_scrolls"], r  # wider than the phone: it scrolls
        assert r["page"] <= r["screen"], r
        browser.switch_to.active_element.send_keys(Keys.ESCAPE)
        assert browser.execute_script("return document.querySelector('.bk-lightbox').hidden")

        # the frame a player shows opens the same way
        frame = browser.find_element(By.CSS_SELECTOR, ".animation img.bk-zoom-frame")
        browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", frame)
        frame.click()
        r = browser.execute_script("""
            const box = document.querySelector('.bk-lightbox'), img = box.querySelector('img');
            return {hidden: box.hidden, same: img.src === arguments[0].src,
                    shown: img.getBoundingClientRect().width, natural: img.naturalWidth};
        """, frame)
        assert not r["hidden"] and r["same"] and abs(r["shown"] - r["natural"]) <= 1, r
        browser.switch_to.active_element.send_keys(Keys.ESCAPE)
    finally:
        browser.set_window_size(WIDTH, 1600)


ZOOM_CHECK = DONE + script("zoom_check.js")


@functools.cache
def stored_figures() -> dict:
    """The description of every figure the notebooks store (obsbook.figures), by the name the
    build gives its image: the SHA-256 of the PNG (myst-nb's name for an output's file)."""
    import base64
    import hashlib

    from obsbook import figures

    out = {}
    for path in run.notebooks():
        for cell in json.loads(path.read_text())["cells"]:
            for o in cell.get("outputs", []):
                png = o.get("data", {}).get("image/png")
                meta = o.get("metadata", {}).get("image/png", {}).get(figures.METADATA_KEY)
                if png and meta:
                    digest = hashlib.sha256(base64.b64decode(png)).hexdigest()
                    out[digest] = figures.unpack(meta)
    return out


def test_enlarged_figures_are_legible_and_sharp_on_a_phone(book, server, browser):
    """On a 390 px screen, each figure of each chapter, tapped, shows its smallest text at
    least as large as 10 pt at its own size (10 pt at 100 px per inch: 13.9 px), with at least
    two image pixels per pixel shown, so that it stays sharp on the phone's screen and when
    pinched. The text sizes are those the notebooks store with each figure."""
    from obsbook import figures

    descriptions = stored_figures()
    browser.set_window_size(NARROW, 844)
    bad, n = [], 0
    try:
        for rel in toc_pages():
            if not rel.startswith("notebooks/"):
                continue
            browser.get(f"{server}/{rel}")
            for r in browser.execute_async_script(ZOOM_CHECK):
                n += 1
                d = descriptions.get(Path(r["href"]).stem)
                if d is None:
                    bad.append(f"{rel}: {r['href']}: no stored description of its text")
                    continue
                smallest = min(t["pt"] for t in d["texts"])
                px = smallest * figures.DPI / 72 * r["shown"] / d["size"][0]
                if px < figures.MIN_PT * figures.DPI / 72 - 0.05:
                    bad.append(f"{rel}: {r['id']}: smallest text {px:.1f} px enlarged, "
                               f"{r['shown']:.0f} px of {d['size'][0]} px wide")
                if r["natural"] < 2 * r["shown"] - 1:
                    bad.append(f"{rel}: {r['id']}: {r['natural']} image pixels shown "
                               f"{r['shown']:.0f} px wide")
                if r["screen"] > NARROW:
                    bad.append(f"{rel}: the enlarged view widened the page to {r['screen']} px")
    finally:
        browser.set_window_size(WIDTH, 1600)
    assert n > 40, n
    assert not bad, "\n".join(bad[:20])


# ------------------------------------------------------------------------- the bound explorer

EXPLORER_PAGE = "notebooks/02_pair_closed_form.html"


@pytest.fixture()
def explorer(server, browser):
    """The browser on the page of the bound explorer, 1400 px wide, the explorer in view."""
    from selenium.webdriver.support.ui import WebDriverWait

    browser.set_window_size(WIDTH, 1600)
    browser.get(f"{server}/{EXPLORER_PAGE}")
    WebDriverWait(browser, 20).until(lambda d: d.execute_script(
        "return !!(window.boundExplorer && window.boundExplorer.set)"))
    browser.execute_script(
        "document.getElementById('bound-explorer').scrollIntoView({block: 'start'})")
    return browser


def random_geometries(n: int, seed: int) -> list[dict]:
    """``n`` explorer states: 2-6 sensors, target and sensors in [-5, 5]^2, ``umax`` in [0, 3]
    (0 in every tenth), the control inside the disc of radius ``umax``. Every third geometry is
    nearly collinear: the sensors within 1e-7 to 1e-2 rad of one line through the target, on
    both sides of it, where O(o) is close to rank one."""
    import numpy as np

    rng = np.random.default_rng(seed)
    out = []
    for k in range(n):
        n_sensors = int(rng.integers(2, 7))
        target = rng.uniform(-5, 5, 2)
        if k % 3 == 0:
            spread = 10.0 ** rng.uniform(-7, -2)
            angle = rng.uniform(0, np.pi) + rng.uniform(-spread, spread, n_sensors)
            dist = rng.uniform(0.3, 5, n_sensors) * rng.choice([-1.0, 1.0], n_sensors)
            sensors = target + dist[:, None] * np.c_[np.cos(angle), np.sin(angle)]
        else:
            sensors = rng.uniform(-5, 5, (n_sensors, 2))
        umax = 0.0 if k % 10 == 5 else float(rng.uniform(0, 3))
        radius, phi = 0.999 * umax * np.sqrt(rng.random()), rng.uniform(0, 2 * np.pi)
        out.append({"sensors": sensors.tolist(), "target": target.tolist(),
                    "control": [radius * np.cos(phi), radius * np.sin(phi)], "umax": umax})
    return out


DRIVE = r"""
const root = document.getElementById('bound-explorer'), out = [];
for (const g of arguments[0]) {
  window.boundExplorer.set(g);
  out.push({bound: root.querySelector('.bound-value').textContent,
            exact: root.querySelector('.exact-value').textContent,
            bound_full: root.dataset.bound, exact_full: root.dataset.exact,
            sensors: root.dataset.sensors, target: root.dataset.target,
            control: root.dataset.control, umax: root.dataset.umax});
}
return out;
"""


_SUPERSCRIPTS = "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079"
_FROM_SUPERSCRIPT = str.maketrans(_SUPERSCRIPTS, "-0123456789")


def _six_digits(shown: str, value: float) -> bool:
    """Whether ``shown`` has 6 significant digits and is ``value`` rounded to them (half a unit
    of the last digit, plus 1e-9 of it for a value on a rounding boundary)."""
    m = re.fullmatch(rf"(-?(\d+(?:\.\d*)?))(?:\u00d710([{_SUPERSCRIPTS}]+))?", shown)
    if not m:
        return False
    digits = m.group(2).replace(".", "")
    if len(digits.lstrip("0") or digits[-6:]) != 6:
        return False
    exponent = m.group(3) or ""
    shown_value = float(m.group(1)) * 10.0 ** int(exponent.translate(_FROM_SUPERSCRIPT) or 0)
    if value == 0:
        return shown_value == 0
    unit = 10.0 ** (math.floor(math.log10(abs(value))) - 5)
    return abs(shown_value - value) <= unit * (0.5 + 1e-9)


def test_explorer_agrees_with_obslib_at_random_geometries(explorer):
    """At 200 random geometries (a third nearly collinear) the explorer's bound and exact value
    equal ``obslib.lower_bound`` and ``obslib.inverse_condition_number`` to 1e-6 relative.

    Two readings of each: the full-precision ``data-bound`` and ``data-exact`` attributes against
    obslib at 1e-6 relative (the contract; the largest difference seen is about 2e-10, on nearly
    collinear sensors, where obslib's SVD and the explorer's Cauchy-Binet determinant round
    differently), and the 6 significant digits shown in ``.bound-value`` and ``.exact-value``,
    which must be obslib's value rounded to 6 digits (within half a unit of the last digit).
    """
    import obslib as ob

    geoms = random_geometries(200, seed=23)
    results = explorer.execute_script(DRIVE, geoms)
    bad = []
    for k, (g, r) in enumerate(zip(geoms, results)):
        state = {key: json.loads(r[key]) for key in ("sensors", "target", "control", "umax")}
        assert state == g, f"geometry {k}: the explorer holds {state}, not {g}"
        bound = ob.lower_bound(g["sensors"], g["target"], g["umax"])
        exact = ob.inverse_condition_number(g["sensors"], g["target"], g["control"])
        for what, ours, full, shown in (("bound", bound, r["bound_full"], r["bound"]),
                                        ("exact", exact, r["exact_full"], r["exact"])):
            if not math.isclose(float(full), ours, rel_tol=1e-6, abs_tol=1e-300):
                bad.append(f"geometry {k} {what}: explorer {full}, obslib {ours!r}: {g}")
            if not _six_digits(shown, ours):
                bad.append(f"geometry {k} {what}: shows {shown!r}, obslib {ours!r}")
    assert not bad, "\n".join(bad[:10])


def test_six_digits_check_can_fail():
    assert _six_digits("0.734940", 0.73494031746)
    assert _six_digits("1.00000\u00d710\u207b\u2077", 1.0000001e-7) and _six_digits("0.00000", 0.0)
    assert not _six_digits("1.00000e-7", 1.0000001e-7)  # machine notation is not the book's
    assert not _six_digits("0.734941", 0.73494031746)  # wrong last digit
    assert not _six_digits("0.73494", 0.73494031746)  # five digits
    assert not _six_digits("0.7349403", 0.73494031746)  # seven digits


def test_explorer_formulas_agree_with_obslib(explorer):
    """The explorer's Theorem 4 (polar form, the surface view), its maximiser alpha*, its pair
    polar coordinates (alpha, theta_ji) and its heat map (the bound with one more sensor) against
    obslib at random points."""
    import numpy as np

    import obslib as ob
    from obslib import pair_form as pf

    rng = np.random.default_rng(7)
    alpha, theta, q = (
        rng.uniform(0, 6, 200),
        rng.uniform(-np.pi, np.pi, 200),
        rng.uniform(0, 3, 200),
    )
    theta[:10] = [0, np.pi, -np.pi / 2, np.pi / 2, 1e-9, np.pi - 1e-9, 0.3, -2.0, 1.0, 2.5]
    got = explorer.execute_script(
        "const m = window.boundExplorer.math;"
        "return arguments[0].map((a, k) => [m.pairBoundPolar(a, arguments[1][k], arguments[2][k]),"
        " m.maximisingAlpha(arguments[1][k], arguments[2][k])]);",
        alpha.tolist(), theta.tolist(), q.tolist())
    got = np.array(got)
    np.testing.assert_allclose(
        got[:, 0], ob.pair_bound_polar(alpha, theta, q), rtol=1e-9, atol=1e-15
    )
    ok = np.abs(np.sin(theta)) > 1e-6  # alpha* is defined where the angle is not 0 or pi
    np.testing.assert_allclose(got[ok, 1], pf.maximising_alpha_closed(theta[ok], q[ok]), rtol=1e-9)

    # alpha and theta_ji of a pair, through Theorem 4, give the pair's bound from its geometry
    geoms = random_geometries(60, seed=5)
    polar = explorer.execute_script(
        "const m = window.boundExplorer.math;"
        "return arguments[0].map(g => {"
        " const p = m.pairPolar(g.sensors[0], g.sensors[1], g.target);"
        " return [p.alpha, p.theta, p.di, m.pairBoundPolar(p.alpha, p.theta, g.umax / p.di)]; });",
        geoms,
    )
    for g, (a, th, _di, b) in zip(geoms, polar):
        w = ob.pair_bounds(g["sensors"][:2], [g["target"]], g["umax"])[0, 1, 0]
        assert math.isclose(b, w, rel_tol=1e-6, abs_tol=1e-12), (g, b, w)
        v = np.subtract(g["sensors"], g["target"])
        assert math.isclose(a, np.hypot(*v[1]) / np.hypot(*v[0]), rel_tol=1e-12)
        assert math.isclose(np.cos(th), np.dot(v[0], v[1]) / np.hypot(*v[0]) / np.hypot(*v[1]),
                            rel_tol=1e-9, abs_tol=1e-9)

    # the heat map: the bound with one more sensor at each grid point
    g = geoms[1]
    xs, ys = np.linspace(-6, 6, 9), np.linspace(-5, 5, 7)
    heat = explorer.execute_script(
        "const g = arguments[0], r = window.boundExplorer.math.candidateBounds("
        "g.sensors, g.target, g.umax, arguments[1], arguments[2]);"
        "return [Array.from(r.values), r.bestIndex];", g, xs.tolist(), ys.tolist())
    values = np.array(heat[0]).reshape(len(ys), len(xs))
    want = np.array([[ob.lower_bound(g["sensors"] + [[x, y]], g["target"], g["umax"]) for x in xs]
                     for y in ys])
    np.testing.assert_allclose(values, want, rtol=1e-9, atol=1e-15)
    assert heat[1] == int(np.argmax(want))



def test_dragging_the_explorer_changes_its_state(explorer):
    """Mouse drags on the canvas move the target, a sensor and the tip of the arrow (which stops
    at u_max), and the displayed values follow."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By

    explorer.execute_script("window.boundExplorer.set(arguments[0])",
                            {"sensors": [[-2.5, -1.5], [2.0, -2.0]], "target": [0.5, 1.0],
                             "control": [0.6, 0.3], "umax": 1.0})
    canvas = explorer.find_element(By.CSS_SELECTOR, "#bound-explorer canvas")
    size = canvas.size

    def state():
        return explorer.execute_script(
            "const e = document.getElementById('bound-explorer');"
            "return {sensors: JSON.parse(e.dataset.sensors), target: JSON.parse(e.dataset.target),"
            " control: JSON.parse(e.dataset.control), umax: JSON.parse(e.dataset.umax),"
            " bound: e.querySelector('.bound-value').textContent,"
            " exact: e.querySelector('.exact-value').textContent};")

    def drag(handle, dx, dy):
        x, y = explorer.execute_script("return window.boundExplorer.handle(arguments[0])", handle)
        (
            ActionChains(explorer)
            .move_to_element_with_offset(canvas, x - size["width"] / 2, y - size["height"] / 2)
            .click_and_hold()
            .move_by_offset(dx // 2, dy // 2)
            .move_by_offset(dx - dx // 2, dy - dy // 2)
            .release()
            .perform()
        )
        return explorer.execute_script("return window.boundExplorer.handle(arguments[0])", handle)

    before = state()
    x0, y0 = explorer.execute_script("return window.boundExplorer.handle('target')")
    x1, y1 = drag("target", 40, -30)
    after = state()
    assert abs(x1 - x0 - 40) <= 1.5 and abs(y1 - y0 + 30) <= 1.5, (x0, y0, x1, y1)
    assert after["target"][0] > before["target"][0] and after["target"][1] > before["target"][1]
    assert after["sensors"] == before["sensors"] and after["control"] == before["control"]
    assert after["bound"] != before["bound"] and after["exact"] != before["exact"]

    drag(1, -50, 20)  # the second sensor
    moved = state()
    assert moved["sensors"][0] == after["sensors"][0] and moved["sensors"][1] != after["sensors"][1]

    drag("tip", 300, 0)  # far beyond the disc: the arrow stops at u_max
    tipped = state()
    assert math.isclose(math.hypot(*tipped["control"]), tipped["umax"], rel_tol=1e-9), tipped
    assert tipped["control"][0] > 0.9 * tipped["umax"]

    import obslib as ob
    shown = ob.inverse_condition_number(tipped["sensors"], tipped["target"], tipped["control"])
    assert _six_digits(tipped["exact"], shown)

    # the second view: dragging the point over (alpha, theta_ji) moves sensor j only, to the
    # distance ratio and angle it is dropped at
    explorer.execute_script("window.boundExplorer.setMode('surface')")
    x, y = explorer.execute_script("return window.boundExplorer.explorer.surfacePoint()")
    size = canvas.size
    (ActionChains(explorer)
     .move_to_element_with_offset(canvas, x - size["width"] / 2, y - size["height"] / 2)
     .click_and_hold().move_by_offset(60, 25).release().perform())
    on_surface = state()
    assert (
        on_surface["sensors"][0] == tipped["sensors"][0]
        and on_surface["target"] == tipped["target"]
    )
    assert on_surface["sensors"][1] != tipped["sensors"][1]
    x1, y1 = explorer.execute_script("return window.boundExplorer.explorer.surfacePoint()")
    assert abs(x1 - x - 60) <= 1.5 and abs(y1 - y - 25) <= 1.5, (x, y, x1, y1)
    explorer.execute_script("window.boundExplorer.setMode('map')")


# ------------------------------------------------------------------------- the API reference


def public_names() -> dict[str, list[str]]:
    """Every public module of ``obslib`` (no part of its dotted path starts with ``_``) with the
    names of its ``__all__`` that are not modules."""
    import importlib
    import inspect
    import pkgutil

    import obslib

    out = {}
    for name in ["obslib", *(m.name for m in pkgutil.walk_packages(obslib.__path__, "obslib."))]:
        if any(part.startswith("_") for part in name.split(".")):
            continue
        mod = importlib.import_module(name)
        out[name] = [
            n for n in getattr(mod, "__all__", []) if not inspect.ismodule(getattr(mod, n))
        ]
    return out


def _object_at(path: str):
    import importlib

    parts = path.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attr in parts[cut:]:
            obj = getattr(obj, attr)
        return obj
    raise LookupError(path)


def test_api_landing_lists_every_public_name(book):
    """The landing page of the reference links every public name (and every module with public
    names, and every package) to an entry that exists on a page of the reference."""
    import importlib

    page = (book / "book" / "api.html").read_text()
    links = re.findall(r'<a class="reference internal" href="(api_[a-z]+\.html)#([\w.-]+)"', page)
    assert links, "no links to the pages of the reference"
    linked, modules, dead = set(), set(), []
    for href, anchor in links:
        if anchor not in _ids(book / "book" / href):
            dead.append(f"{href}#{anchor}")
        if anchor.startswith("module-"):
            modules.add(anchor.removeprefix("module-"))
        else:
            linked.add(id(_object_at(anchor)))
    assert not dead, dead
    missing = []
    for modname, names in public_names().items():
        mod = importlib.import_module(modname)
        if (names or hasattr(mod, "__path__")) and modname not in modules:
            missing.append(f"module {modname}")
        missing += [f"{modname}.{n}" for n in names if id(getattr(mod, n)) not in linked]
    assert not missing, "not on the landing page of the API reference:\n" + "\n".join(missing)
    assert len(linked) > 200


CONTENTS_CHECK = script("contents_check.js")


def test_api_pages_contents_do_not_clip(server, browser):
    """On every page of the reference, each entry of the right-hand contents fits its column."""
    api = [p for p in toc_pages() if p.startswith("book/api")]
    assert len(api) >= 8, api
    from selenium.webdriver.support.ui import WebDriverWait

    browser.set_window_size(WIDTH, 1600)
    clipped = []
    for rel in api:
        browser.get(f"{server}/{rel}")
        WebDriverWait(browser, 20).until(
            lambda d: d.execute_script(
                "return document.readyState === 'complete'"
            " && !!document.querySelector('.bd-sidebar-secondary')"
            )
        )
        clipped += [f"{rel}: {c}" for c in browser.execute_script(CONTENTS_CHECK)]
    assert not clipped, "\n".join(clipped[:20])


# ---------------------------------------------------------------- contents, indices and search


def test_the_explorer_is_in_the_contents_of_its_chapter(book, server, browser):
    """The explorer's section is an entry of the chapter's contents (the right-hand column at
    1400 px), and has the stable label ``explore-the-bound``, which any page can link by name
    (``{ref}`the bound explorer <explore-the-bound>```): its anchor is at the section's
    heading, and the section holds the explorer."""
    from selenium.webdriver.support.ui import WebDriverWait
    from sphinx.util.inventory import InventoryFile

    with open(book / "objects.inv", "rb") as fh:
        labels = InventoryFile.load(fh, "", lambda base, uri: uri)["std:label"]
    assert labels["explore-the-bound"][2] == f"{EXPLORER_PAGE}#explore-the-bound", \
        labels["explore-the-bound"]
    assert labels["explore-the-bound"][3] == "Explore the bound"
    browser.set_window_size(WIDTH, 1600)
    browser.get(f"{server}/{EXPLORER_PAGE}")
    WebDriverWait(browser, 20).until(lambda d: d.execute_script(
        "return !!document.querySelector('.bd-sidebar-secondary')"))
    r = browser.execute_script("""
        const a = document.querySelector('.bd-sidebar-secondary a[href="#explore-the-bound"]');
        const label = document.getElementById('explore-the-bound');
        const section = label && label.closest('section');
        return {entry: a ? a.textContent.trim() : null, shown: !!a && a.offsetParent !== null,
                section: section ? section.id : null,
                // the anchor is the section itself, or a label just before its heading
                heading: !!label && (label.tagName === 'SECTION'
                                     ? label.querySelector(':scope > h1, :scope > h2, :scope > h3')
                                     : label.nextElementSibling).tagName,
                holds: !!section && !!section.querySelector('#bound-explorer')};
    """)
    assert r == {"entry": "Explore the bound", "shown": True, "section": "explore-the-bound",
                 "heading": "H2", "holds": True}, r


def test_print_only_cells_stay_out_of_the_pages(book):
    """The explorer's still, which stands for it in print, is not on the web page, nor is the
    sentence that introduces it; the explorer is."""
    html = (book / EXPLORER_PAGE).read_text()
    assert 'id="bound-explorer"' in html and "In the web edition" not in html
    nb = json.loads((ROOT / "notebooks" / "02_pair_closed_form.ipynb").read_text())
    stills = [c for c in nb["cells"] if "print-only" in c.get("metadata", {}).get("tags", [])]
    assert len(stills) == 1 and stills[0]["outputs"], "the still of the explorer is not stored"
    import base64
    import hashlib

    (png,) = [o["data"]["image/png"] for o in stills[0]["outputs"] if "image/png" in o["data"]]
    assert hashlib.sha256(base64.b64decode(png)).hexdigest() not in html


def test_the_statement_index_names_statements_as_the_pages_do(book):
    """The index of theorems, algorithms and remarks shows no internal label (``thm-...``,
    ``stmt-...``) and no file name; each entry is named as its box is ("Theorem 4") and links
    to it."""
    labels = set()
    for path in run.notebooks():
        text = "".join("".join(c["source"]) + "\n" for c in json.loads(path.read_text())["cells"])
        labels |= set(re.findall(r"^```\{prf:\w+\}.*\n:label: ([\w-]+)", text, re.M))
    assert {"thm-lower-bound", "stmt-intro-vs-problem2"} <= labels
    html = (book / "prf-prf.html").read_text()
    body = html[html.index("<article"):html.index("</article>")]
    visible = re.sub(r"<[^>]+>", " ", body)
    shown = sorted(lab for lab in labels if re.search(rf"(?<![\w-]){re.escape(lab)}(?![\w-])",
                                                      visible))
    assert not shown, shown
    assert not re.search(r"notebooks/|\.ipynb|\d\d_[a-z_]+", visible)
    entries = re.findall(r'<a href="([^"#]+)#([^"]+)"><code class="xref">([^<]+)</code>', body)
    assert len(entries) == len(labels), (len(entries), len(labels))
    for href, anchor, name in entries:
        assert re.fullmatch(r"[A-Z][a-z]+ \d+", name), name
        page = (book / href).read_text()
        # the box the entry links to carries the same name
        box = page[page.index(f'id="{anchor}"'):][:600]
        assert f'<span class="caption-number">{name} </span>' in box, (name, href, anchor)


def _search(server, browser, query: str) -> list[str]:
    """The pages the site search lists for ``query``, in its order."""
    from urllib.parse import quote

    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(f"{server}/search.html?q={quote(query)}")
    WebDriverWait(browser, 30).until(lambda d: d.execute_script(
        "const s = document.querySelector('#search-results .search-summary');"
        "return !!s && /Search finished/.test(s.textContent);"))  # every result listed
    return browser.execute_script(
        "return Array.from(document.querySelectorAll('#search-results ul.search li > a'))"
        ".map(a => new URL(a.getAttribute('href'), location.href).pathname.slice(1));")


@pytest.mark.parametrize("query", ["greedy", "Mahalanobis", "lower bound"])
def test_the_search_lists_chapters_before_the_api(server, browser, query):
    """Every page of the book that the search finds comes before every page of the API
    reference, and the search finds both (so that the order is checked)."""
    browser.set_window_size(WIDTH, 1600)
    found = _search(server, browser, query)
    api = [k for k, p in enumerate(found) if p.startswith("book/api")]
    chapters = [k for k, p in enumerate(found) if p.startswith("notebooks/")]
    assert api and chapters, found
    assert max(k for k, p in enumerate(found) if not p.startswith("book/api")) < min(api), found


def test_how_to_cite_gives_the_version_the_book_was_built_from(book):
    """The "How to cite" page names a commit of this repository and its date, in its text and
    in the book's BibTeX entry, and shows the paper's entry of the bibliography."""
    import html as html_module

    page = html_module.unescape(re.sub(r"<[^>]+>", "", (book / "book" / "cite.html").read_text()))
    m = re.search(r"built from commit ([0-9a-f]{12}) of (\d{4}-\d{2}-\d{2})", page)
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        assert "a copy without its version history" in page
        return
    assert m, "no version on the page"
    commit, date = m.groups()
    proc = subprocess.run(["git", "-C", str(ROOT), "log", "-1", "--format=%cs", commit],
                          capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stdout.strip() == date, (commit, date, proc.stderr)
    assert f"note         = {{Version: commit {commit} of {date}" in page
    assert "@misc{zhou2017lower," in page and "eprint        = {1706.00871}" in page
