"""Text formatting shared by notebooks and the ledger."""

from __future__ import annotations

__all__ = ["format_small"]


def format_small(x: float, floor: float = 1e-12, fmt: str = ".3g") -> str:
    """``x`` formatted with ``fmt``, or ``"< floor"`` when ``|x| < floor``.

    Rounding-level values differ from one CPU to another; printed as a bound, the text is the
    same on every machine.
    """
    return f"< {floor:.0e}" if abs(x) < floor else format(x, fmt)
