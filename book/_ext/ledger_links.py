"""Sphinx extension: every ledger id written as inline code links to its entry in the report.

A page that names a claim of the ledger as ```thm1``` (inline code whose whole text is a claim
id) gets that code wrapped in a link to the claim's entry in the reproduction report (anchor
``claim-<id>``). Code already inside a link, code blocks, and the report itself are left alone.
"""

from docutils import nodes

REPORT = "book/report"


def _ids() -> frozenset:
    from obslib.claims import registry

    return frozenset(registry())


def _link_ids(app, doctree, docname):
    if docname == REPORT or REPORT not in app.env.all_docs:
        return
    ids = _IDS or _ids()
    for lit in list(doctree.findall(nodes.literal)):
        text = lit.astext()
        if text not in ids or isinstance(lit.parent, (nodes.reference, nodes.literal_block)):
            continue
        if any(isinstance(a, nodes.reference) for a in _ancestors(lit)):
            continue
        uri = app.builder.get_relative_uri(docname, REPORT) + f"#claim-{text}"
        ref = nodes.reference("", "", internal=True, refuri=uri, reftitle=f"ledger entry {text}")
        lit.replace_self(ref)
        ref.append(lit)


def _ancestors(node):
    p = node.parent
    while p is not None:
        yield p
        p = p.parent


_IDS: frozenset = frozenset()


def _load(app):
    global _IDS
    _IDS = _ids()


def setup(app):
    app.connect("builder-inited", _load)
    app.connect("doctree-resolved", _link_ids)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
