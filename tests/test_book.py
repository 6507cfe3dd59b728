"""The built book: complete, offline, and working in a real headless browser.

The book is rendered (not re-executed) into ``_build/html`` when it is missing or older than its
sources. The browser test drives Debian's ``chromium`` through ``chromium-driver`` (Selenium, no
downloaded browser) against the book served on 127.0.0.1. Without Chromium it skips with the
reason, except in CI (``CI`` set), where it must run: ``.ci/run`` installs both packages.
Screenshots of every page go to ``_build/screenshots/`` for review.
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from obslib import run
from obslib.run import ROOT

BUILD = ROOT / "_build" / "html"
SHOTS = ROOT / "_build" / "screenshots"
SOURCES = [ROOT / "_config.yml", ROOT / "_toc.yml", *ROOT.glob("book/*.md"), *ROOT.glob("book/*.bib"),
           *ROOT.glob("notebooks/*.ipynb")]


def _stale() -> bool:
    index = BUILD / "index.html"
    if not index.exists():
        return True
    built = index.stat().st_mtime
    return any(p.stat().st_mtime > built for p in SOURCES if p.exists())


@pytest.fixture(scope="session")
def book() -> Path:
    """Path of the rendered book, rendering it first (execution off, warnings as errors) if needed."""
    if _stale():
        if not run.EXECUTION_PAGE.exists():
            times = json.loads(run.TIMES_FILE.read_text()) if run.TIMES_FILE.exists() else {}
            run.EXECUTION_PAGE.write_text(run.execution_page(times))
        jb = Path(sys.executable).with_name("jupyter-book")
        proc = subprocess.run(
            [str(jb), "build", str(ROOT), "--builder", "html", "--warningiserror", "--nitpick", "--keep-going"],
            capture_output=True, text=True, cwd=ROOT,
        )
        assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return BUILD


def pages(book: Path) -> list[Path]:
    return sorted(
        p for p in book.rglob("*.html")
        if not any(part.startswith(("_", ".")) for part in p.relative_to(book).parts)
    )


def test_every_toc_page_is_built(book):
    import yaml

    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    files = [toc["root"]] + [ch["file"] for part in toc["parts"] for ch in part["chapters"]]
    for f in files:
        assert (book / f"{f}.html").exists(), f"{f} was not rendered"


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
            if tag.lower().startswith("<link") and not re.search(r"rel=[\"'](stylesheet|preload|icon|font)", tag, re.I):
                continue  # plain hyperlinks such as canonical or author pages fetch nothing
            offenders.append(f"{page.relative_to(book)}: {tag[:120]}")
    for css in book.rglob("*.css"):
        for m in re.finditer(r"(@import\s+url\(|url\()\s*[\"']?(https?:)?//[^)]*\)", css.read_text(errors="replace")):
            offenders.append(f"{css.relative_to(book)}: {m.group(0)[:120]}")
    assert not offenders, "\n".join(offenders)


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
            assert (page.parent / link).resolve().exists(), f"{page.name}: {link} is missing from the build"


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
        reason = "the browser test needs Debian's chromium and chromium-driver (apt-get install chromium chromium-driver)"
        if os.environ.get("CI"):
            pytest.fail(f"CI must run the browser test: {reason}")
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    opts = Options()
    opts.binary_location = chromium
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--disable-dev-shm-usage", "--window-size=1280,1600"):
        opts.add_argument(flag)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(chromedriver), options=opts)
    driver.set_page_load_timeout(60)
    yield driver
    driver.quit()


PAGE_CHECK = r"""
const done = arguments[arguments.length - 1];
const ready = (window.MathJax && MathJax.startup && MathJax.startup.promise) ? MathJax.startup.promise : Promise.resolve();
ready.then(() => new Promise(r => setTimeout(r, 300))).then(() => {
  const body = document.querySelector('main') || document.body;
  const clone = body.cloneNode(true);
  clone.querySelectorAll('pre, code, script, style, .highlight, mjx-container').forEach(e => e.remove());
  const text = clone.innerText;
  const raw = (text.match(/\\\(|\\\[|\$\$|\\begin\{/g) || []).length;
  const images = Array.from(document.images);
  const broken = images.filter(i => !i.complete || i.naturalWidth === 0).map(i => (i.src || '').slice(0, 80));
  const anims = Array.from(document.querySelectorAll('.animation')).map(a => {
    const img = a.querySelector('img');
    const slider = a.querySelector('input[type=range]');
    return {loaded: !!img && img.naturalWidth > 0, frames: slider ? Number(slider.max) + 1 : 0};
  });
  done({raw: raw, images: images.length, broken: broken, anims: anims,
        math: document.querySelectorAll('mjx-container').length,
        height: Math.min(document.documentElement.scrollHeight, 12000)});
});
"""


def test_every_page_renders_in_a_headless_browser(book, server, browser):
    SHOTS.mkdir(parents=True, exist_ok=True)
    problems, n_anims, n_math, n_images = [], 0, 0, 0
    browser.set_script_timeout(60)
    for page in pages(book):
        rel = page.relative_to(book).as_posix()
        browser.get(f"{server}/{rel}")
        result = browser.execute_async_script(PAGE_CHECK)
        errors = [
            e["message"] for e in browser.get_log("browser")
            if e["level"] == "SEVERE" and "favicon.ico" not in e["message"]
        ]
        if errors:
            problems.append(f"{rel}: console errors {errors[:3]}")
        if result["broken"]:
            problems.append(f"{rel}: images that did not load {result['broken'][:3]}")
        if result["raw"]:
            problems.append(f"{rel}: {result['raw']} pieces of math left as raw TeX")
        for a in result["anims"]:
            if not a["loaded"] or a["frames"] < 2:
                problems.append(f"{rel}: animation without frames {a}")
        n_anims += len(result["anims"])
        n_math += result["math"]
        n_images += result["images"]
        browser.set_window_size(1280, max(800, result["height"]))
        browser.save_screenshot(str(SHOTS / (rel.replace("/", "__").replace(".html", ".png"))))
        browser.set_window_size(1280, 1600)
    assert not problems, "\n".join(problems)
    # the checks above must have had something to check
    assert n_math > 100 and n_images > 20 and n_anims >= 1, (n_math, n_images, n_anims)
