"""Repository tooling behind ``make book``: the notebook runner and the benchmarks.

They work on the checkout that obslib is installed from (the notebooks, ``book/``, ``_build/``);
the library's modules never import them. ``python -m obslib.run`` and ``python -m obslib.bench``
are their command lines.
"""

from pathlib import Path

#: The checkout obslib is installed from (editable): notebooks/, book/ and _build/ live here.
ROOT = Path(__file__).resolve().parents[2]
