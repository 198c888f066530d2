"""Physical values written as a reader writes them: an SI prefix, the unit, the shortest digits.

A leaf of :mod:`pulab.schema`: the error catalog formats its numbers with it, and it imports
nothing of pulab.

Examples
--------
>>> si_text(1.06e-05, "H"), si_text(0.0011, "Ω"), si_text(6.25e-05, "s")
('10.6 µH', '1.1 mΩ', '62.5 µs')
"""

from __future__ import annotations

import math
from decimal import Decimal

__all__ = ["si_text"]

#: Engineering exponent → SI prefix (pico to giga: the range of a drive's quantities).
_PREFIXES = {-12: "p", -9: "n", -6: "µ", -3: "m", 0: "", 3: "k", 6: "M", 9: "G"}


def si_text(value: float, unit: str, sig: int = 6) -> str:
    """A physical value as a reader writes it: an SI prefix, the unit, and the shortest
    decimal that gives the value to ``sig`` significant digits (1.06e-05 H is ``10.6 µH``).

    Parameters
    ----------
    value : float — in the SI unit ``unit``
    unit : str — ``'H'``, ``'Ω'``, ``'V'`` …; empty: the number alone, without a prefix
    sig : int — significant digits at most, 1..17 (a finding's text; the JSON keeps the value)
    """
    if not math.isfinite(value):
        return f"{value} {unit}".rstrip()
    # the decimal is cut first and shifted exactly, so no binary digits reappear (10.6, not
    # 10.600000000000001)
    d = Decimal(f"{value:.{sig}g}") or Decimal(0)  # no "-0"
    exp = 0 if d == 0 or not unit else min(9, max(-12, d.adjusted() // 3 * 3))
    digits = format(d.scaleb(-exp).normalize(), "f")
    return f"{digits} {_PREFIXES[exp]}{unit}".rstrip()
