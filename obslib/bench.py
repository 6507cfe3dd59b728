"""Command line ``python -m obslib.bench``: the benchmarks of :mod:`obslib.tools.bench`."""

from .tools.bench import main

if __name__ == "__main__":
    raise SystemExit(main())
