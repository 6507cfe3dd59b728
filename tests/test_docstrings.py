"""Every public function of obslib has an Examples section with a doctest.

Public functions: the functions among ``obslib.__all__``, and the functions defined in
``obslib.tracking``, ``obslib.symbolic`` and every module of ``obslib.studies`` and ``obslib.viz``
(a module's ``__all__`` where it has one, else its names without a leading underscore). pytest
runs the doctests themselves (``--doctest-modules``); this test finds the functions that have
none.

The API page renders these docstrings, so every doctest line (``>>>`` and ``...`` source and
the expected output) fits in :data:`MAX_DOCTEST_WIDTH` characters, the width of its code
blocks.
"""

import doctest
import importlib
import inspect
import pkgutil

import obslib

PACKAGES = ("obslib.tracking", "obslib.symbolic", "obslib.studies", "obslib.viz")

def _modules():
    yield obslib, list(obslib.__all__)
    for pkg_name in PACKAGES:
        pkg = importlib.import_module(pkg_name)
        yield pkg, None
        for info in pkgutil.iter_modules(pkg.__path__):
            if not info.name.startswith("_"):
                yield importlib.import_module(f"{pkg_name}.{info.name}"), None


def _public_functions():
    seen = {}
    for mod, names in _modules():
        if names is None:
            names = getattr(mod, "__all__", None) or [n for n in vars(mod) if not n.startswith("_")]
        for name in names:
            obj = getattr(mod, name)
            if not inspect.isfunction(inspect.unwrap(obj)):  # functions, also cached ones
                continue
            if names is not getattr(mod, "__all__", None) and mod is not obslib:
                if obj.__module__ != mod.__name__:  # imported, documented where defined
                    continue
            seen.setdefault(f"{obj.__module__}.{obj.__name__}", obj)
    return seen


FUNCTIONS = _public_functions()


def _examples(doc: str) -> str:
    """The text of the docstring's Examples section ('' if there is none)."""
    lines = inspect.cleandoc(doc or "").splitlines()
    for k in range(len(lines) - 1):
        if lines[k].strip() == "Examples" and set(lines[k + 1].strip()) == {"-"}:
            return "\n".join(lines[k + 2:])
    return ""


def test_the_functions_are_found():
    # the collection reaches every package named above, through re-exports and submodules
    for expected in ("obslib.bounds.lower_bound", "obslib.tracking.batch.simulate",
                     "obslib.symbolic.theorem4.theorem4_bound", "obslib.viz.pair_closed_form",
                     "obslib.studies.pair_closed_form"):
        assert any(k.startswith(expected) for k in FUNCTIONS), expected
    assert len(FUNCTIONS) > 150


def test_examples_parser():
    def with_examples():
        """Summary.

        Examples
        --------
        >>> 1 + 1
        2
        """

    def without():
        """Summary, and the word Examples in prose."""

    assert ">>> 1 + 1" in _examples(with_examples.__doc__)
    assert _examples(without.__doc__) == ""


def test_every_public_function_has_examples():
    missing = [k for k, f in sorted(FUNCTIONS.items()) if ">>>" not in _examples(f.__doc__)]
    assert not missing, "public functions without an Examples doctest:\n" + "\n".join(missing)


#: The widest doctest line the API page's code blocks show without scrolling.
MAX_DOCTEST_WIDTH = 79


def _doctest_lines(example) -> list:
    """An example's lines as the page shows them: ``>>>``/``...`` source, then its output."""
    src = example.source.rstrip("\n").split("\n")
    lines = [(">>> " if k == 0 else "... ") + s for k, s in enumerate(src)]
    return lines + (example.want.rstrip("\n").split("\n") if example.want else [])


def _all_doctests():
    finder = doctest.DocTestFinder(exclude_empty=True)
    mods = [obslib] + [importlib.import_module(m.name)
                       for m in pkgutil.walk_packages(obslib.__path__, "obslib.")
                       if not m.name.endswith("__main__")]
    seen = set()
    for mod in mods:
        for test in finder.find(mod, mod.__name__):
            key = (test.filename, test.lineno, test.docstring)
            if key not in seen:  # an object re-exported by another module
                seen.add(key)
                yield test


def _too_wide(tests) -> list:
    return [f"{t.name} ({len(s)} chars): {s}" for t in tests for ex in t.examples
            for s in _doctest_lines(ex) if len(s) > MAX_DOCTEST_WIDTH]


def test_doctest_line_width():
    # ruff checks the width of code lines; doctest output lines are text, so this test does
    too_wide = _too_wide(_all_doctests())
    assert not too_wide, "doctest lines wider than {}:\n{}".format(MAX_DOCTEST_WIDTH,
                                                                 "\n".join(too_wide))


def test_doctest_lines_parser():
    def wide():
        """Summary.

        Examples
        --------
        >>> x = [1,
        ...      2]
        >>> x
        [1, 2]
        """

    (test,) = doctest.DocTestFinder().find(wide, "wide")
    lines = [s for ex in test.examples for s in _doctest_lines(ex)]
    assert lines == [">>> x = [1,", "...      2]", ">>> x", "[1, 2]"]


def _control_characters(doc: str) -> set:
    """Control characters other than the newline: what a ``\\theta`` or ``\\alpha`` of TeX
    becomes in a docstring that is not a raw string (a tab, a bell)."""
    return {hex(ord(c)) for c in doc if ord(c) < 32 and c != "\n"}


def test_docstrings_hold_no_control_characters():
    """The API pages and the PDF typeset the docstrings: a TeX command eaten by a string escape
    shows as a missing letter on the web and stops XeLaTeX."""
    found = []
    for mod in [m for m, _ in _modules()] + [importlib.import_module("obslib.claims"),
                                              importlib.import_module("obslib.formatting")]:
        for name, obj in [(mod.__name__, mod)] + list(vars(mod).items()):
            doc = getattr(obj, "__doc__", None)
            if isinstance(doc, str) and _control_characters(doc):
                found.append(f"{mod.__name__}: {name} {sorted(_control_characters(doc))}")
    assert _control_characters("\theta") == {"0x9"}
    assert not found, "\n".join(found)
