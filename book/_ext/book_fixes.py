"""Sphinx extension: two fixes to the HTML of jupyter-book 1.0.4 that show as console errors.

1. Each inline script of sphinx-thebe and sphinx-togglebutton is registered twice (once with
   ``filename=None``, once with ``filename=''``); the second ``const THEBE_JS_URL`` is a
   ``SyntaxError``. The first of any identical script is kept.
2. sphinx-book-theme leaves the pydata theme's ``default_mode`` empty, and the theme logs
   "Got invalid theme mode" on a first visit; it is set to ``auto`` (follow the system), the
   theme's own fallback.
"""


def _fix_page(app, pagename, templatename, context, doctree):
    scripts = context.get("script_files")
    if scripts:
        seen, kept = set(), []
        for js in scripts:
            name = js.filename if hasattr(js, "filename") else str(js)
            key = (name or "", tuple(sorted(getattr(js, "attributes", {}).items())))
            if key not in seen:
                seen.add(key)
                kept.append(js)
        context["script_files"] = kept
    if not context.get("default_mode"):
        context["default_mode"] = "auto"


def setup(app):
    app.connect("html-page-context", _fix_page, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
