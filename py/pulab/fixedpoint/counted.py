"""C integer operations that count what they do to a value: a wrap, a saturation, a limit.

The vendors' integer PI steps (:mod:`pulab.profiles`, each vendor's ``pi`` module) are written
with these, so a simulation can say how often the firmware's arithmetic wrapped or clipped.
Each takes ``ev``, a dict of event name → count, and adds to it:

``wrap``
    a C integer operation overflowed and wrapped (two's complement, as the targets do);
``saturate``
    a saturating operation (a library call, an overflow guard) clipped its result;
``integral_limit``, ``output_limit``
    the integral or the output was held at the limit the code is given.

Examples
--------
>>> ev = {}
>>> wrap(1 << 15, 16, ev), saturate(1 << 15, 16, ev), limit(7, -5, 5, ev, "output_limit"), ev
(-32768, 32767, 5, {'wrap': 1, 'saturate': 1, 'output_limit': 1})
"""

from __future__ import annotations

__all__ = ["EVENTS", "count", "wrap", "saturate", "limit"]

#: Event names, in the order they are reported.
EVENTS = ("wrap", "saturate", "integral_limit", "output_limit")


def count(ev: dict, name: str) -> None:
    """One more ``name`` event in ``ev``."""
    ev[name] = ev.get(name, 0) + 1


def wrap(x: int, bits: int, ev: dict) -> int:
    """x kept in a signed ``bits`` word (two's complement); a change counts as a ``wrap``."""
    half = 1 << (bits - 1)
    y = ((x + half) & ((half << 1) - 1)) - half
    if y != x:
        count(ev, "wrap")
    return y


def saturate(x: int, bits: int, ev: dict) -> int:
    """x clipped to a signed ``bits`` word; a clip counts as a ``saturate``."""
    hi = (1 << (bits - 1)) - 1
    if x > hi or x < -hi - 1:
        count(ev, "saturate")
        return hi if x > hi else -hi - 1
    return x


def limit(x: int, lo: int, hi: int, ev: dict, name: str) -> int:
    """x held within [lo, hi]; holding it counts as event ``name``."""
    if x > hi:
        count(ev, name)
        return hi
    if x < lo:
        count(ev, name)
        return lo
    return x
