"""Command line ``python -m obslib.run``: the notebook runner of :mod:`obslib.tools.run`."""

from .tools.run import main

if __name__ == "__main__":
    raise SystemExit(main())
