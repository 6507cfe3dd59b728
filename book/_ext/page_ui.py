"""Sphinx extension: what the pages need to read well on any screen.

1. Every image of a figure is wrapped in a link to the image file (class ``bk-zoom``), so that a
   figure opens full size on click; ``book.js`` shows it in an overlay, and without scripts
   the link opens the file itself.
2. Every cell of a table with three or more columns gets its column's header as a label
   (``<span class="bk-cell-label">``, hidden on wide screens), and the table the class
   ``bk-cards``: on a narrow screen ``book.css`` shows each row as a card of labelled fields
   instead of a table that scrolls sideways (label and value on one line where every cell is
   short, class ``bk-cards-short``). The label is the header's own HTML, so a header with a
   formula shows the formula.
3. The page that holds the bound explorer (an element ``id="bound-explorer"``) loads its script
   and stylesheet; no other page does.
4. A change to a file of ``book/_static`` or ``book/_ext`` rebuilds the book: Sphinx alone sees
   only changed sources, and would neither copy the new static file nor rewrite the pages that
   link it (with a ``?v=`` digest of its content). The digest of those files is a configuration
   value, and a changed configuration value rebuilds everything.
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

from docutils import nodes
from sphinx.util.osutil import relative_uri

EXPLORER_ID = 'id="bound-explorer"'


# ------------------------------------------------------------------------------ figures


def _link_figure_images(app, doctree, docname):
    if app.builder.format != "html":
        return  # in print a figure is a figure
    images = app.env.images
    target = relative_uri(app.builder.get_target_uri(docname), "_images")
    for fig in doctree.findall(nodes.figure):
        for img in list(fig.findall(nodes.image)):
            if isinstance(img.parent, nodes.reference):
                continue
            uri = img["uri"]
            if uri in images:
                href = f"{target}/{images[uri][1]}"
            elif "://" in uri or uri.startswith("data:"):
                continue
            else:
                href = uri
            ref = nodes.reference("", "", internal=True, refuri=href, classes=["bk-zoom"],
                                  reftitle="Open the figure full size")
            img.replace_self(ref)
            ref.append(img)


# ------------------------------------------------------------------------------ tables

#: A table whose cells all have at most this many characters (numbers, short names) shows each
#: field of a card on one line, label and value side by side.
SHORT_CELL = 24

_TABLE = re.compile(r'<table class="table[^"]*">.*?</table>', re.S)
_HEAD = re.compile(r"<thead>(.*?)</thead>", re.S)
_ROW = re.compile(r"(<tr[^>]*>)(.*?)(</tr>)", re.S)
_HEADER_CELL = re.compile(r"<th[^>]*>(.*?)</th>", re.S)
_BODY_CELL = re.compile(r"<(td|th)([^>]*)>")
_PARA = re.compile(r"^\s*<p>(.*)</p>\s*$", re.S)


def _cell_label(cell_html: str) -> str:
    m = _PARA.match(cell_html)
    inner = m.group(1) if m else cell_html
    return re.sub(r'\sid="[^"]*"', "", inner).strip()


def _label_table(table: str) -> str:
    head = _HEAD.search(table)
    if not head or "colspan" in table or "rowspan" in table:
        return table
    header_rows = _ROW.findall(head.group(1))
    if len(header_rows) != 1:
        return table
    labels = [_cell_label(c) for c in _HEADER_CELL.findall(header_rows[0][1])]
    if len(labels) < 3 or not all(re.sub(r"<[^>]+>", "", x).strip() for x in labels):
        return table
    start, end = head.end(), len(table)

    def label_row(m):
        cells = iter(labels)

        def label_cell(c):
            text = next(cells, None)
            if text is None:
                return c.group(0)
            return f'{c.group(0)}<span class="bk-cell-label" aria-hidden="true">{text}</span>'

        return m.group(1) + _BODY_CELL.sub(label_cell, m.group(2)) + m.group(3)

    body = _ROW.sub(label_row, table[start:end])
    cells = [
        re.sub(r"<[^>]+>", "", c)
        for c in re.findall(r"<td[^>]*>(.*?)</td>", table[start:end], re.S)
    ]
    short = all(len(" ".join(c.split())) <= SHORT_CELL for c in cells)
    kind = "bk-cards bk-cards-short" if short else "bk-cards"
    opening = table[: start].replace('<table class="table', f'<table class="table {kind}', 1)
    return opening + body


def _page(app, pagename, templatename, context, doctree):
    body = context.get("body")
    if not body:
        return
    context["body"] = _TABLE.sub(lambda m: _label_table(m.group(0)), body)
    if EXPLORER_ID in body:
        app.add_js_file("bound-explorer.js")
        app.add_css_file("bound-explorer.css")


BOOK = Path(__file__).resolve().parents[1]


def _assets_digest() -> str:
    h = hashlib.sha256()
    for path in sorted([*BOOK.glob("_static/*"), *BOOK.glob("_ext/*.py")]):
        if path.is_file():
            h.update(path.name.encode() + b"\0" + path.read_bytes())
    return h.hexdigest()[:16]


def _set_digest(app, config):
    config.page_ui_assets = _assets_digest()


def setup(app):
    app.add_config_value("page_ui_assets", "", "env")
    app.connect("config-inited", _set_digest)
    app.add_js_file("book.js")
    app.connect("doctree-resolved", _link_figure_images)
    app.connect("html-page-context", _page)
    return {"parallel_read_safe": True, "parallel_write_safe": True}

