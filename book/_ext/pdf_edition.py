"""Sphinx extension: the PDF edition (``make pdf``, Sphinx's LaTeX builder and XeLaTeX).

1. Sphinx's own LaTeX class (``manual``) rather than Jupyter Book's ``jupyterBook``, which loads
   ``bbm`` and with it Debian's texlive-fonts-extra (1.4 GB installed). What Jupyter Book's class
   adds that the book uses, the boxes of code cells and their outputs, is defined in the
   preamble of ``_config.yml``. Jupyter Book's other LaTeX transforms stay: parts from the
   table of contents, the front page as the opening pages, hidden code left out.
2. Every Unicode subscript and superscript typeset as its letter lowered or raised
   (:func:`script_map`), since each face of GNU FreeFont lacks some; any other character that
   no font holds stops the build (``\\tracinglostchars=3`` in ``_config.yml``).
3. Figures, tables and theorems numbered through the whole book, as on the web
   (``numfig_secnum_depth = 0``; Jupyter Book numbers them within chapters in print).
4. What only a browser can show is left out of print. In a builder other than HTML, a notebook
   output that offers only HTML and the text IPython prints for a display object
   (``<IPython.core.display.HTML object>``) is dropped, and an animation player becomes the
   last of its frames, the whole run; the page says in its own words what stands in the
   browser's place (``{only}`` blocks).
5. A notebook cell tagged ``print-only`` (a still figure that stands for what only a browser
   shows) is left out of the web pages.
6. No image converter (Jupyter Book loads ``sphinx.ext.imgconverter``, which wants
   ImageMagick): every image of the book is a PNG, which XeLaTeX reads as it is.
7. The web pages link the PDF: the role ``{pdf-edition}`text``` is a link to it (in the PDF
   itself, the text alone), and an HTML build copies the PDF that ``make pdf`` made to the top
   folder of the pages (:func:`obsbook.pdf.copy_to_html`; ``make pdf`` does the same when the
   pages are built first).
"""

from __future__ import annotations

import base64
import hashlib
import re
from pathlib import Path

from docutils import nodes
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util.osutil import relative_uri

from obsbook import edition

#: The text IPython shows for a display object that has no text of its own.
DISPLAY_REPR = re.compile(r"^<IPython\.(?:core\.)?display\.\w+ object>$")
#: A frame of matplotlib's animation player (``Animation.to_jshtml``): its number and PNG.
FRAME = re.compile(r'frames\[(\d+)\]\s*=\s*"data:image/png;base64,([A-Za-z0-9+/=\s\\]+)"')


def _latex_config(app, config):
    config.latex_theme = "manual"
    config.jblatex_load_imgconverter = False
    elements = dict(config.latex_elements)
    elements["preamble"] = elements.get("preamble", "") + script_map()
    config.latex_elements = elements


#: The Unicode blocks of subscript and superscript letters and digits.
SCRIPT_CHARS = [*range(0x2070, 0x20A0), *range(0x1D2C, 0x1D6B), 0x2C7C]


def script_map() -> str:
    """LaTeX that typesets every Unicode subscript and superscript (``ₖ``, ``ⱼ``, ``ᵢ``,
    ``⁻``, ...) as its letter, digit or sign lowered or raised in the font around it: each face
    of GNU FreeFont lacks some of them (the serif has no ``ₖ``, the italic no ``ᵢ``).

    Examples
    --------
    >>> print(*[line for line in script_map().splitlines() if "{k}" in line], sep="\\n")
    \\newunicodechar{ₖ}{\\textsubscript{k}}
    \\newunicodechar{ᵏ}{\\textsuperscript{k}}
    """
    import unicodedata

    lines = [r"\usepackage{newunicodechar}"]
    for code in SCRIPT_CHARS:
        parts = unicodedata.decomposition(chr(code)).split()
        if len(parts) == 2 and parts[0] in ("<sub>", "<super>"):
            how = "textsubscript" if parts[0] == "<sub>" else "textsuperscript"
            lines.append(rf"\newunicodechar{{{chr(code)}}}{{\{how}{{{chr(int(parts[1], 16))}}}}}")
    return "\n" + "\n".join(lines) + "\n"


def _numbering(app):
    app.config.numfig_secnum_depth = 0


def last_frame(html: str) -> bytes | None:
    """The PNG of the last frame of an animation player's HTML, or None if it has no frames.

    Examples
    --------
    >>> png = base64.b64encode(b"\\x89PNG...").decode()
    >>> last_frame(f'frames[0] = "data:image/png;base64,AAAA"; frames[1] = '
    ...            f'"data:image/png;base64,{png}";')
    b'\\x89PNG...'
    >>> last_frame("<p>no player</p>") is None
    True
    """
    frames = {int(m.group(1)): m.group(2) for m in FRAME.finditer(html)}
    if not frames:
        return None
    data = re.sub(r"[\s\\]", "", frames[max(frames)])
    return base64.b64decode(data)


class BrowserOnlyOutputs(SphinxPostTransform):
    """In print, drop the outputs only a browser can show, and show an animation's last frame.

    Runs before myst-nb picks one type of each output for the builder (``SelectMimeType``,
    priority 4), so that the text IPython prints for an HTML display is never that pick."""

    default_priority = 3

    def run(self, **kwargs) -> None:
        if self.app.builder.format == "html":
            return
        for bundle in list(self.document.findall(_is_bundle)):
            by_type = {child["mime_type"]: child for child in bundle.children}
            if "text/html" not in by_type or not _only_a_repr(by_type.get("text/plain")):
                continue
            png = last_frame(by_type["text/html"].astext())
            if png is None:
                bundle.parent.remove(bundle)
            else:
                bundle.replace_self(self._image(png))

    def _image(self, png: bytes) -> nodes.image:
        """An image node of ``png``, written beside the LaTeX sources (where XeLaTeX runs)."""
        name = f"frame-{hashlib.sha256(png).hexdigest()[:16]}.png"
        out = Path(self.app.builder.outdir)
        out.mkdir(parents=True, exist_ok=True)
        path = out / name
        if not path.exists():
            tmp = path.with_suffix(".tmp")
            tmp.write_bytes(png)
            tmp.replace(path)
        return nodes.image(uri=name, candidates={"*": name})


class PrintOnlyCells(SphinxPostTransform):
    """On the web, drop the notebook cells tagged ``print-only``."""

    default_priority = 3

    def run(self, **kwargs) -> None:
        if self.app.builder.format != "html":
            return
        for cell in list(self.document.findall(_is_print_only)):
            cell.parent.remove(cell)


def _is_print_only(node) -> bool:
    return isinstance(node, nodes.container) and "tag_print-only" in node.get("classes", ())


def _is_bundle(node) -> bool:
    return isinstance(node, nodes.container) and node.get("nb_element") == "mime_bundle"


def _only_a_repr(node) -> bool:
    return node is None or bool(DISPLAY_REPR.match(node.astext().strip()))


class PdfLink(SphinxPostTransform):
    """Resolve ``{pdf-edition}`` links: to the PDF beside the HTML pages, or plain text."""

    default_priority = 5

    def run(self, **kwargs) -> None:
        for node in list(self.document.findall(_PdfLinkNode)):
            text = nodes.Text(node["pdf_text"])
            if self.app.builder.format == "html":
                here = self.app.builder.get_target_uri(self.env.docname)
                uri = relative_uri(here, edition.pdf_name())
                ref = nodes.reference("", "", text, refuri=uri, internal=True,
                                      classes=["bk-pdf-edition"])
                node.replace_self(ref)
            else:
                node.replace_self(text)


class _PdfLinkNode(nodes.Inline, nodes.TextElement):
    pass


def pdf_edition_role(name, rawtext, text, lineno, inliner, options=None, content=None):
    """``{pdf-edition}`the PDF edition``` : a link to the PDF (see the module docstring)."""
    return [_PdfLinkNode(rawtext, "", pdf_text=text)], []


def _copy_pdf(app, exception):
    if exception is None and app.builder.format == "html":
        from obsbook.pdf import copy_to_html

        copy_to_html(html_dir=Path(app.outdir))


def _same_name(text: str) -> str:
    """A title or section name as one key: lower case, typographic apostrophes and quotes
    plain, white space single."""
    plain = text.translate(str.maketrans({"\u2019": "'", "\u2018": "'", "\u201c": '"',
                                          "\u201d": '"'}))
    return " ".join(plain.lower().split())


def _find_chapter(env, node, parent_tag):
    """The document of the chapter that holds ``node``, for sphinx-proof's LaTeX numbering.

    sphinx-proof finds it as the section whose names hold the chapter's title, compared as
    typed; a title with an apostrophe is typeset with a typographic one, so the two never
    match, and the statement loses its number and its label. This compares them as one
    :func:`_same_name`.
    """
    while node is not None:
        node = node.parent
        if node is None:
            return None
        docname = node.attributes.get("docname")
        if docname and docname in env.titles:
            title = _same_name(env.titles[docname].astext())
            if title in {_same_name(n) for n in node.attributes.get("names", ())}:
                return docname
    return None


def setup(app):
    import sphinx_proof.nodes

    sphinx_proof.nodes.find_parent = _find_chapter  # looked up when each statement is written
    # after sphinx_jupyterbook_latex, which sets its own class and numbering
    app.connect("config-inited", _latex_config, priority=900)
    app.connect("builder-inited", _numbering, priority=900)
    app.add_post_transform(BrowserOnlyOutputs)
    app.add_post_transform(PrintOnlyCells)
    app.add_role("pdf-edition", pdf_edition_role)
    app.add_node(_PdfLinkNode)
    app.add_post_transform(PdfLink)
    app.connect("build-finished", _copy_pdf)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
