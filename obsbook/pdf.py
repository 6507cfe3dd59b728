"""``make pdf`` (``python -m obsbook.pdf``): the PDF edition of the book.

Jupyter Book's LaTeX builder renders the executed notebooks as they are stored (nothing is run
again) into ``_build/latex/``, and XeLaTeX, through latexmk, makes the PDF there
(:func:`obsbook.edition.pdf_name`); it is then copied beside the HTML pages, which link it. The
build needs Debian's TeX Live packages :data:`TEX_PACKAGES` (about 380 MB installed); without
them it stops before any work and names them. The LaTeX configuration (Sphinx's own class,
XeLaTeX with GNU FreeFont, every glyph checked) is in ``_config.yml`` and
``book/_ext/pdf_edition.py``.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .edition import HTML_DIR, LATEX_DIR, ROOT, pdf_name

__all__ = ["TEX_PACKAGES", "NEEDS", "missing", "install_hint", "copy_to_html", "main"]

#: Debian's packages the PDF needs (``apt-get install`` them).
TEX_PACKAGES = ("texlive-xetex", "texlive-latex-recommended", "texlive-latex-extra",
                "texlive-fonts-recommended", "fonts-freefont-otf", "latexmk", "xindy")

#: What the build uses, how to find it (a program on the PATH, or a file TeX finds) and the
#: package that brings it.
NEEDS = (
    ("xelatex", "program", "texlive-xetex"),
    ("latexmk", "program", "latexmk"),
    ("xindy", "program", "xindy"),
    ("kpsewhich", "program", "texlive-xetex"),
    ("fontspec.sty", "file", "texlive-latex-recommended"),
    ("fncychap.sty", "file", "texlive-latex-extra"),
    ("FreeSerif.otf", "file", "fonts-freefont-otf"),
)


def missing() -> list[tuple[str, str]]:
    """``(what, package)`` for each entry of :data:`NEEDS` that this machine lacks."""
    out = []
    kpsewhich = shutil.which("kpsewhich")
    for what, kind, package in NEEDS:
        if kind == "program":
            found = shutil.which(what) is not None
        else:
            found = kpsewhich is not None and subprocess.run(
                [kpsewhich, what], capture_output=True, text=True).stdout.strip() != ""
        if not found:
            out.append((what, package))
    return out


def install_hint(lacking) -> str:
    """The one message :func:`main` prints when something is missing.

    Examples
    --------
    >>> print(install_hint([("xelatex", "texlive-xetex")]))  # doctest: +NORMALIZE_WHITESPACE
    make pdf needs Debian's TeX Live (missing: xelatex). Install it with
      sudo apt-get install texlive-xetex texlive-latex-recommended texlive-latex-extra
      texlive-fonts-recommended fonts-freefont-otf latexmk xindy
    """
    names = ", ".join(what for what, _ in lacking)
    return (f"make pdf needs Debian's TeX Live (missing: {names}). Install it with\n"
            f"  sudo apt-get install {' '.join(TEX_PACKAGES[:3])}\n"
            f"  {' '.join(TEX_PACKAGES[3:])}")


def _copy(src: Path, dst: Path) -> None:
    """Copy ``src`` to ``dst`` through a temporary file beside it (never half a PDF)."""
    fd, tmp = tempfile.mkstemp(prefix=f".{dst.name}.", suffix=".tmp", dir=dst.parent)
    os.close(fd)
    try:
        shutil.copyfile(src, tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # as a file written plainly; mkstemp's is private
        os.replace(tmp, dst)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def copy_to_html(latex_dir: Path = LATEX_DIR, html_dir: Path = HTML_DIR) -> Path | None:
    """Copy the built PDF to the top folder of the HTML book, where its pages link it; the path
    of the copy, or None when the PDF or the HTML book is not built."""
    pdf = Path(latex_dir) / pdf_name()
    if not pdf.is_file() or not Path(html_dir).is_dir():
        return None
    dst = Path(html_dir) / pdf.name
    if not dst.exists() or dst.read_bytes() != pdf.read_bytes():
        _copy(pdf, dst)
    return dst


def _execution_page() -> None:
    """The execution statistics page, from the last ``make book``, if ``make book`` has not
    written it (it is not committed)."""
    from obslib.tools import run

    if not run.EXECUTION_PAGE.exists():
        import json

        from obslib._io import write_output

        times = json.loads(run.TIMES_FILE.read_text()) if run.TIMES_FILE.exists() else {}
        write_output(run.EXECUTION_PAGE, run.execution_page(times))


def _latex_errors(log: Path) -> str:
    """The error lines of a LaTeX log, with the two lines after each."""
    if not log.exists():
        return ""
    lines = log.read_text(errors="replace").splitlines()
    picked = []
    for k, line in enumerate(lines):
        if line.startswith("! ") or "Missing character" in line:
            picked += lines[k:k + 3]
    return "\n".join(picked[:60])


def main(argv=None) -> int:
    """``python -m obsbook.pdf``: build the PDF edition (see the module docstring); exit status
    1 when TeX is missing or the build fails, with what went wrong."""
    ap = argparse.ArgumentParser(prog="python -m obsbook.pdf",
                                 description="Build the PDF edition into _build/latex/.")
    ap.parse_args(argv)
    lacking = missing()
    if lacking:
        print(install_hint(lacking), file=sys.stderr)
        return 1
    t0 = time.perf_counter()
    _execution_page()
    from .front import write_figure

    write_figure()  # the front page's picture, drawn as make book draws it (not committed)
    jb = Path(sys.executable).with_name("jupyter-book")
    proc = subprocess.run([str(jb), "build", str(ROOT), "--builder", "latex", "--warningiserror",
                           "--nitpick", "--keep-going"], capture_output=True, text=True, cwd=ROOT)
    if proc.returncode != 0:
        print(proc.stdout[-3000:] + proc.stderr[-3000:], file=sys.stderr)
        print("python -m obsbook.pdf: the LaTeX build failed", file=sys.stderr)
        return 1
    tex = LATEX_DIR / Path(pdf_name()).with_suffix(".tex").name
    pdf = tex.with_suffix(".pdf")
    pdf.unlink(missing_ok=True)
    env = {**os.environ, "XINDYOPTS": "-L english -C utf8 -M sphinx.xdy", "LATEXOPTS": ""}
    proc = subprocess.run(["latexmk", "-xelatex", "-interaction=nonstopmode", "-halt-on-error",
                           "-file-line-error", tex.name], capture_output=True, text=True,
                          cwd=LATEX_DIR, env=env)
    if proc.returncode != 0 or not pdf.is_file():
        errors = _latex_errors(tex.with_suffix(".log")) or proc.stdout[-3000:]
        print(errors, file=sys.stderr)
        print(f"python -m obsbook.pdf: XeLaTeX failed; see {tex.with_suffix('.log')}",
              file=sys.stderr)
        return 1
    copied = copy_to_html()
    pages = re.search(r"Output written on \S+ \((\d+) pages", proc.stdout + proc.stderr)
    size = pdf.stat().st_size / 2**20
    print(f"{pdf.relative_to(ROOT)}: {pages.group(1) + ' pages, ' if pages else ''}"
          f"{size:.1f} MB, {time.perf_counter() - t0:.0f} s"
          + (f"; linked from the HTML book as {copied.relative_to(ROOT)}" if copied else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
