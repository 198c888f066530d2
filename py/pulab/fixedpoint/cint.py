"""C integer arithmetic as the TI C2000 compiler performs it.

On C2000 ``int`` is 16 bit and ``long`` is 32 bit, so the familiar PC rules
give wrong answers: ``Voltage*10`` with ``Uint16 Voltage`` is computed in 16
bits.  Every operation here returns a :class:`CInt` that carries the C type of
its result and the flags the firmware would silently suffer:

``wrap``
    the exact result did not fit the C type and was reduced modulo 2**bits;
``truncation``
    a division or right shift discarded non-zero bits.

Flags accumulate through an expression, so the flags of a statement are the
flags of its final value.  Division by zero raises :class:`CDivisionByZero`.

Examples
--------
>>> v = CInt(17, UINT16)
>>> (v * CInt(10, INT16)).value, (v * CInt(10, INT16)).ctype.name
(170, 'Uint16')
>>> big = CInt(7000, UINT16) * CInt(10, INT16)
>>> big.value, sorted(big.flags)
(4464, ['wrap'])
>>> q = CInt(-7, INT32) // CInt(2, INT32)
>>> q.value, sorted(q.flags)
(-3, ['truncation'])
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = [
    "CType", "CInt", "CDivisionByZero",
    "INT16", "UINT16", "INT32", "UINT32", "INT64",
    "C2000_TYPES", "wrap_to", "convert", "fits", "trunc_div",
]


@dataclass(frozen=True)
class CType:
    """A fixed-width C integer type.

    Parameters
    ----------
    name : str
        The C2000 spelling (``int``, ``Uint16``, ``long``, ``Ulong``, ``int64``).
    bits : int in {16, 32, 64}
    signed : bool
    """

    name: str
    bits: int
    signed: bool
    min: int = field(init=False, compare=False)
    max: int = field(init=False, compare=False)

    def __post_init__(self) -> None:
        # Precomputed: range checks run in the simulation's inner loop.
        object.__setattr__(self, "min", -(1 << (self.bits - 1)) if self.signed else 0)
        object.__setattr__(self, "max", (1 << (self.bits - 1)) - 1 if self.signed
                           else (1 << self.bits) - 1)

    def unsigned(self) -> "CType":
        return {16: UINT16, 32: UINT32, 64: UINT64}[self.bits]


INT16 = CType("int", 16, True)
UINT16 = CType("Uint16", 16, False)
INT32 = CType("long", 32, True)
UINT32 = CType("Ulong", 32, False)
INT64 = CType("int64", 64, True)
UINT64 = CType("Uint64", 64, False)

#: The C2000 names used in the vendor code, mapped to their types.
C2000_TYPES = {t.name: t for t in (INT16, UINT16, INT32, UINT32, INT64, UINT64)}


def wrap_to(value: int, ctype: CType) -> int:
    """Reduce an exact integer modulo 2**bits into the range of ``ctype``."""
    v = value & ((1 << ctype.bits) - 1)
    if ctype.signed and v > ctype.max:
        v -= 1 << ctype.bits
    return v


def convert(value: int, ctype: CType) -> int:
    """``value`` converted to ``ctype`` as C converts (C99 6.3.1.2-3): modulo 2**bits, except
    that ``_Bool`` is 1 for any non-zero value.

    >>> convert(70000, UINT16), convert(2, CType("_Bool", 8, False))
    (4464, 1)
    """
    if ctype.name == "_Bool":
        return int(value != 0)
    return wrap_to(value, ctype)


def fits(value: int, ctype: CType) -> bool:
    """True when ``value`` is representable in ``ctype``."""
    return ctype.min <= value <= ctype.max


def trunc_div(a: int, b: int) -> int:
    """Integer quotient truncated toward zero, as C99 ``/`` does (exact, no float)."""
    q = abs(a) // abs(b)
    return q if (a >= 0) == (b > 0) else -q


class CDivisionByZero(ArithmeticError):
    """An integer division by zero in emulated C code."""


def _common(a: CType, b: CType) -> CType:
    """C's usual arithmetic conversions for two integer types (C99 6.3.1.8)."""
    if a == b:
        return a
    if a.signed == b.signed:
        return a if a.bits >= b.bits else b
    u, s = (a, b) if not a.signed else (b, a)
    if u.bits >= s.bits:
        return u
    # The signed type is wider, so it holds every value of the unsigned one.
    return s


_NO_FLAGS = frozenset()
_WRAP = frozenset({"wrap"})
_TRUNC = frozenset({"truncation"})


class CInt:
    """An integer value of a C type, with the flags its computation raised.

    Immutable by convention; a plain ``__slots__`` class because the
    simulation runs it in its inner loop (a frozen dataclass costs 3× more).

    Parameters
    ----------
    value : int
        Must lie in the range of ``ctype`` (use :meth:`of` to convert).
    ctype : CType
    flags : frozenset of str
    """

    __slots__ = ("value", "ctype", "flags")

    def __init__(self, value: int, ctype: CType, flags: frozenset = _NO_FLAGS) -> None:
        if not ctype.min <= value <= ctype.max:
            raise ValueError(f"{value} does not fit {ctype.name}")
        self.value = value
        self.ctype = ctype
        self.flags = flags

    def __repr__(self) -> str:
        return f"CInt({self.value}, {self.ctype.name}, {sorted(self.flags)})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, CInt) and (self.value, self.ctype, self.flags) == \
            (other.value, other.ctype, other.flags)

    def __hash__(self) -> int:
        return hash((self.value, self.ctype, self.flags))

    @classmethod
    def of(cls, value: int, ctype: CType) -> "CInt":
        """Convert an exact integer to ``ctype`` as a C cast does, flagging a changed value."""
        w = wrap_to(value, ctype)
        return cls(w, ctype, _WRAP if w != value else _NO_FLAGS)

    def cast(self, ctype: CType) -> "CInt":
        """``(ctype)self``: modulo conversion; a changed value is flagged ``wrap``."""
        w = wrap_to(self.value, ctype)
        return CInt(w, ctype, self.flags | _WRAP if w != self.value else self.flags)

    def _arith(self, other: "CInt", op: str) -> "CInt":
        t = self.ctype if self.ctype is other.ctype else _common(self.ctype, other.ctype)
        a, b = self.value, other.value
        if not (t.min <= a <= t.max and t.min <= b <= t.max):
            # Converting a negative operand to an unsigned common type is itself a wrap.
            a, b = wrap_to(a, t), wrap_to(b, t)
        flags = self.flags | other.flags
        if op == "*":
            exact = a * b
        elif op == "+":
            exact = a + b
        elif op == "-":
            exact = a - b
        else:
            if b == 0:
                raise CDivisionByZero("integer division by zero")
            exact = trunc_div(a, b)
            if exact * b != a:
                flags = flags | _TRUNC
        if not t.min <= exact <= t.max:
            exact = wrap_to(exact, t)
            flags = flags | _WRAP
        return CInt(exact, t, flags)

    def __mul__(self, other: "CInt") -> "CInt":
        return self._arith(other, "*")

    def __add__(self, other: "CInt") -> "CInt":
        return self._arith(other, "+")

    def __sub__(self, other: "CInt") -> "CInt":
        return self._arith(other, "-")

    def __floordiv__(self, other: "CInt") -> "CInt":
        """C ``/``: truncates toward zero (not Python's floor division)."""
        return self._arith(other, "/")

    def __neg__(self) -> "CInt":
        n = CInt.of(-self.value, self.ctype)
        return CInt(n.value, n.ctype, self.flags | n.flags)

    def __lshift__(self, n: int) -> "CInt":
        """C ``<<``; a signed overflow (undefined in ISO C) wraps as C2000 does, flagged."""
        exact = self.value << n
        t = self.ctype
        if t.min <= exact <= t.max:
            return CInt(exact, t, self.flags)
        return CInt(wrap_to(exact, t), t, self.flags | _WRAP)

    def __rshift__(self, n: int) -> "CInt":
        """C ``>>``: arithmetic for signed types (C2000 ``ASR``), logical for unsigned."""
        lost = self.value & ((1 << n) - 1)
        return CInt(self.value >> n, self.ctype, self.flags | _TRUNC if lost else self.flags)

    def clean(self) -> "CInt":
        """The same value read back from a variable: flags belong to the statement that made it."""
        return CInt(self.value, self.ctype)

    def __int__(self) -> int:
        return self.value
