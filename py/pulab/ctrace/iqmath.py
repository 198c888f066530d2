"""TI IQmath library calls as the tracer computes them (32-bit ``long`` arguments and result).

Exact (TI's source states the integer operations; checked bit for bit against gcc -m32 running
C written from these descriptions, tests/py/test_ctrace_iqmath.py):

``mpy``   ``(long)((long long)a * b >> q)``: floor, the low 32 bits kept (C28x ``__IQmpy``).
``rmpy``  ``((long long)a * b + 2**(q-1)) >> q``, low 32 bits kept: rounds half up, no
          saturation (TexasInstruments/mspm0-sdk : source/ti/iqmath/_IQNfunctions/_IQNrmpy.c).
``rsmpy`` the same sum, then clamped to ``[LONG_MIN, LONG_MAX]`` (``_IQNrsmpy.c`` beside it).
``int``   C28x IQmath 1.4d ``IQNint.asm``: ``|a|`` with overflow mode on (``|LONG_MIN|`` saturates
          to ``LONG_MAX``), ``>> q``, the sign put back: toward zero (TI's readme example
          ``_IQint(-2.3456)`` = −2).
``frac``  C28x ``IQNfrac.asm``: the low ``q`` bits of that saturated ``|a|``, the sign put back
          (``_IQfrac(-2.3456)`` = −0.3456).  MSPM0's ``_IQNfrac.c`` differs (``a & (2**q-1)``,
          never negative): the tracer follows C28x, the target IQmath is most used on.
``sat``   clamp to ``[lo, hi]``; ``abs`` is ``labs``.

Not bit-exact (TI computes them in closed code from ROM tables and iterations; their readme
gives the accuracy: ~30 bits for sin/cos, ~28 bits for div, sqrt, atan2, mag): the tracer gives
the correctly rounded value of the exact result (the nearest integer; ``div`` saturated as TI
documents) and the flag ``not_bit_exact``:

``div``   ``a * 2**q / b``; ``b`` = 0 saturates by the sign of ``a``.
``sqrt``  ``sqrt(a * 2**q)``; ``a`` < 0 gives 0.
``sin``, ``cos`` of ``a / 2**q`` radians; ``sinPU``, ``cosPU`` of ``2π a / 2**q``.
``atan2`` ``atan2(a, b)`` radians; ``atan2PU`` the same / 2π, in ``[0, 1)`` (readme: a negative
          angle + 1.0).
``mag``   ``sqrt(a² + b²)``, clamped to ``LONG_MAX``.

The trig values are rounded from binary64 ``math`` functions (error < 2⁻⁵² relative, far below
one LSB at Q ≤ 30 except exactly at a tie); ``div``, ``sqrt`` and ``mag`` use integer arithmetic.

Examples
--------
>>> iq_value("rmpy", [3 << 22, 1], 24, 32)    # 0.75 LSB rounds to 1 (_IQmpy gives 0)
(1, ['truncation'])
>>> iq_value("int", [-39352381], 24, 32), iq_value("frac", [-39352381], 24, 32)  # −2.3456
((-2, []), (-5797949, []))
>>> iq_value("sinPU", [1 << 22], 24, 32)      # sin(π/2) in Q24
(16777216, ['not_bit_exact'])
"""

from __future__ import annotations

import math
import re

__all__ = ["ARITY", "IQ_CALL", "INEXACT", "iq_value"]

#: The operations and their argument counts; ``sat`` and ``abs`` have no Q.
ARITY = {"mpy": 2, "rmpy": 2, "rsmpy": 2, "div": 2, "sqrt": 1, "sin": 1, "cos": 1, "sinPU": 1,
         "cosPU": 1, "atan2": 2, "atan2PU": 2, "mag": 2, "int": 1, "frac": 1, "toF": 1,
         "sat": 3, "abs": 1}
#: ``_IQop`` (GLOBAL_Q) or ``_IQNop`` (Q = N, 1..30); ``_IQsat`` and ``_IQabs`` only as such.
IQ_CALL = re.compile(r"_IQ(?P<n>[1-9]|[12][0-9]|30)?(?P<op>rsmpy|rmpy|mpy|div|sqrt|sinPU|cosPU"
                     r"|sin|cos|atan2PU|atan2|mag|int|frac|toF)\Z|_IQ(?P<plain>sat|abs)\Z")
#: The operations whose last bits TI's closed library decides.
INEXACT = frozenset({"div", "sqrt", "sin", "cos", "sinPU", "cosPU", "atan2", "atan2PU", "mag"})


def _nearest(num: int, den: int) -> int:
    """``num / den`` (den > 0) rounded to the nearest integer, halves away from zero."""
    q, r = divmod(abs(num), den)
    q += 2 * r >= den
    return q if num >= 0 else -q


def _isqrt_nearest(n: int) -> int:
    """``sqrt(n)`` rounded to the nearest integer (no ties: a square root is never k + ½)."""
    r = math.isqrt(n)
    return r + (n - r * r > r)


def iq_value(op: str, args: list, q: int, bits: int) -> tuple:
    """The value of ``_IQ<op>`` on ``args`` (already ``long``) in Q ``q`` for a ``long`` of
    ``bits`` bits, and its flags (``truncation`` bits dropped by a multiply's shift,
    ``conversion`` the 64-bit result's upper bits dropped, ``saturate`` clamped,
    ``signed_overflow`` ``labs(LONG_MIN)``, ``not_bit_exact``).  ``sat`` and ``abs`` ignore ``q``.

    >>> iq_value("rsmpy", [1 << 30, 1 << 30], 24, 32)
    (2147483647, ['saturate'])
    >>> iq_value("div", [1 << 24, 3 << 24], 24, 32)
    (5592405, ['not_bit_exact'])
    """
    hi, lo = (1 << (bits - 1)) - 1, -(1 << (bits - 1))
    flags: list = []

    def wrap(v: int) -> int:
        w = (v - lo) % (1 << bits) + lo
        if w != v:
            flags.append("conversion")
        return w

    def clamp(v: int) -> int:
        c = hi if v > hi else lo if v < lo else v
        if c != v:
            flags.append("saturate")
        return c

    a = args[0]
    if op == "sat":  # _IQsat(x, top, bottom): top when above it, else bottom when below it
        top, bottom = args[1], args[2]
        v = top if a > top else bottom if a < bottom else a
        return v, (["saturate"] if v != a else [])
    if op == "abs":
        v = (abs(a) - lo) % (1 << bits) + lo
        if v != abs(a):
            flags.append("signed_overflow")
        return v, flags
    if op in ("mpy", "rmpy", "rsmpy"):
        product = a * args[1]
        total = product if op == "mpy" else product + (1 << (q - 1))
        shifted = total >> q
        if shifted << q != product:
            flags.append("truncation")
        return (clamp if op == "rsmpy" else wrap)(shifted), flags
    if op in ("int", "frac"):
        mag = min(abs(a), hi)  # C28x ABSTC with overflow mode: |LONG_MIN| saturates
        part = mag >> q if op == "int" else mag & ((1 << q) - 1)
        return (-part if a < 0 else part), flags
    if op in INEXACT:
        flags.append("not_bit_exact")
    one = 1 << q
    if op == "div":
        b = args[1]
        if b == 0:
            flags.append("saturate")
            return (hi if a >= 0 else lo), flags
        num, den = (a << q, b) if b > 0 else (-(a << q), -b)
        return clamp(_nearest(num, den)), flags
    if op == "sqrt":
        return (_isqrt_nearest(a << q) if a > 0 else 0), flags
    if op == "mag":
        return clamp(_isqrt_nearest(a * a + args[1] * args[1])), flags
    if op in ("atan2", "atan2PU"):
        angle = math.atan2(a, args[1])
        if op == "atan2PU":
            angle = angle / (2 * math.pi)
            angle += angle < 0
        return clamp(round(angle * one)), flags
    x = a / one * (2 * math.pi if op.endswith("PU") else 1.0)
    f = math.sin if op.startswith("sin") else math.cos
    return clamp(round(f(x) * one)), flags

