"""Sphinx extension: resolve the API page's references to obslib objects the way Python would.

Docstrings refer to names relative to the module that defines them (``:func:`subset_masks```
in :mod:`obslib.measures`), while the API page documents the public functions under the package
(``obslib.measure_table``), so Sphinx looks for ``obslib.subset_masks`` and finds nothing. This
handler tries the name in every loaded ``obslib`` module: where the page documents the object,
the reference becomes a link to it; where the object exists but the page does not list it (a
private helper, a SymPy derivation), it is set as code. A name that exists nowhere still warns,
except a word of a type field (napoleon's ``:vartype:`` for an *Attributes* entry such as
``noise : (steps, N)`` or ``motion : {"circle", "adversarial"}``): Sphinx makes every word of
such a type a class reference, but a shape or a set of strings names no object, so those words
are set as plain text.

The landing page of the reference quotes the first sentence of each docstring in a table, with no
module around it; there every name is looked up in every ``obslib`` module the same way.
"""

import importlib
import sys

from docutils import nodes
from sphinx.util.nodes import make_refnode

#: The pages of the API reference: their summary tables quote docstrings outside their modules.
API_PAGES = "book/api"


def _lookup(path: str):
    """The object at dotted ``path`` (a module or an attribute of one), or None."""
    parts = path.split(".")
    for cut in range(len(parts), 0, -1):
        name = ".".join(parts[:cut])
        try:
            obj = importlib.import_module(name)
        except ImportError:
            continue
        for attr in parts[cut:]:
            if not hasattr(obj, attr):
                return None
            obj = getattr(obj, attr)
        return obj
    return None


def _candidates(target: str, module: str | None):
    yield target
    if module:
        yield f"{module}.{target}"
    for name in sorted(sys.modules):
        if name.startswith("obslib.") or name == "obslib":
            yield f"{name}.{target}"


def _resolve(app, env, node, contnode):
    if node.get("refdomain") != "py":
        return None
    target = node["reftarget"].lstrip("~.")
    module = node.get("py:module")
    on_api_page = node.get("refdoc", "").startswith(API_PAGES)
    if not (target.startswith("obslib") or (module or "").startswith("obslib") or on_api_page):
        return None
    objects = env.get_domain("py").objects
    for cand in _candidates(target, module):
        if cand in objects:
            entry = objects[cand]
            return make_refnode(app.builder, node["refdoc"], entry.docname, entry.node_id,
                                contnode, cand)
    for cand in _candidates(target, module):
        if cand.startswith("obslib") and _lookup(cand) is not None:
            return nodes.literal(contnode.astext(), contnode.astext())
    if _is_type_word(node):
        return nodes.Text(contnode.astext())
    return None


def _is_type_word(node) -> bool:
    """Whether ``node`` is a word of a docstring's type field rather than a written role.

    Sphinx's type fields mark their references ``refspecific`` with the target as written;
    a written ``:class:`` role is ``refspecific`` only when its target starts with a dot.
    """
    return (node.get("reftype") == "class" and bool(node.get("refspecific"))
            and not node["reftarget"].startswith("."))


def setup(app):
    app.connect("missing-reference", _resolve)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
