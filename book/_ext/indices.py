"""Sphinx extension: the book's indices read as words.

1. The index of theorems, algorithms and remarks (sphinx-proof's "Proof Index") names each
   statement as the pages do, "Theorem 4" with its title if it has one, groups them by kind and
   gives the chapter each is in; sphinx-proof lists the internal labels (``thm-lower-bound``,
   ``stmt-...``) and the notebooks' file names instead.
2. The site search ranks the chapters and every other page above the API reference: a result
   from a page of the reference keeps its order among those, after all others
   (``search_scorer.js`` beside this file).
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from docutils import nodes
from sphinx_proof.domain import ProofIndex

#: The kinds of statement in the order the index shows them, by sphinx-proof's ``realtype``.
KINDS = ("theorem", "proposition", "algorithm", "definition", "observation", "remark")


def _collect(app, doctree):
    """Record, for each statement of the page read, its title and kind."""
    env = app.env
    found = getattr(env, "bk_statements", {})
    for node in doctree.findall(lambda n: isinstance(n, nodes.Element) and n.get("realtype")
                                and n.get("label")):
        title = node.children[0].astext().strip() if node.children else ""
        if title.startswith("(") and title.endswith(")"):  # sphinx-proof's "(%t)"
            title = title[1:-1]
        found[node["label"]] = {"docname": env.docname, "title": title}
    env.bk_statements = found


def _purge(app, env, docname):
    found = getattr(env, "bk_statements", {})
    env.bk_statements = {k: v for k, v in found.items() if v["docname"] != docname}


def _merge(app, env, docnames, other):
    env.bk_statements = {**getattr(env, "bk_statements", {}),
                         **getattr(other, "bk_statements", {})}


class StatementIndex(ProofIndex):
    """sphinx-proof's index, each entry named in words (see the module docstring)."""

    localname = "Index of theorems, algorithms and remarks"
    shortname = "statements"

    def generate(self, docnames=None):
        env = self.domain.env
        statements = getattr(env, "bk_statements", {})
        groups = defaultdict(list)
        for label, values in getattr(env, "proof_list", {}).items():
            if docnames is not None and values["docname"] not in docnames:
                continue
            info = statements.get(label, {})
            kind = values["realtype"]
            number = ""
            if not values["nonumber"]:
                numbers = env.toc_fignumbers.get(values["docname"], {})
                found = numbers.get(values["countertype"], {}).get(label)
                number = ".".join(map(str, found)) if found else ""
            name = " ".join(x for x in (kind.title(), number) if x)
            chapter = env.titles[values["docname"]].astext() if values["docname"] in env.titles \
                else ""
            title = info.get("title", "")
            sort = (int(number) if number.isdigit() else 0, name)
            groups[kind].append((sort, (name, 0, values["docname"], values["ids"][0], title, "",
                                        chapter)))
        order = {k: i for i, k in enumerate(KINDS)}
        content = [(f"{kind.title()}s", [entry for _, entry in sorted(entries)])
                   for kind, entries in sorted(groups.items(),
                                               key=lambda kv: (order.get(kv[0], 99), kv[0]))]
        return content, False


def _use_statement_index(app):
    domain = app.env.domains["prf"]
    domain.indices = [StatementIndex if cls is ProofIndex else cls for cls in domain.indices]


def _scorer(app, config):
    config.html_search_scorer = str(Path(__file__).with_name("search_scorer.js"))


def setup(app):
    app.connect("doctree-read", _collect)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("builder-inited", _use_statement_index)
    app.connect("config-inited", _scorer)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
