"""C integer arithmetic over intervals: every value an expression takes for a box of inputs.

:class:`ICInt` is a :class:`~pulab.fixedpoint.cint.CInt` whose value is an interval
``[lo, hi]`` of its C type.  It implements the same operators with the same C
semantics (usual arithmetic conversions, modulo wrap, truncating division,
arithmetic right shift), so code written for ``CInt`` — the vendor profiles —
runs unchanged over a whole box of inputs.  The result is sound: every value
the concrete code computes for a point of the box lies in ``[lo, hi]``, and every
flag it raises (``wrap``, ``truncation``) is in ``flags``.  Flags here mean
"some point may raise it".  A division whose divisor interval holds 0 but is
not {0} adds ``div0`` and bounds the quotient over the non-zero divisors; a
divisor that is exactly {0} raises :class:`CDivisionByZero` as the concrete code
does, since then every point divides by zero.

As a subclass, an ``ICInt`` on the right of a ``CInt`` operator takes over
(Python tries a subclass's reflected method first), so ``CInt(5000, ...) * x``
works too.

Examples
--------
>>> from pulab.fixedpoint.cint import UINT16, INT16
>>> v = ICInt(17, 7000, UINT16)
>>> p = v * CInt(10, INT16)          # Uint16 arithmetic on C2000: may wrap
>>> p.value, sorted(p.flags)
((0, 65535), ['wrap'])
>>> q = ICInt(100, 200, UINT16) // ICInt(0, 3, UINT16)
>>> q.value, sorted(q.flags)
((33, 200), ['div0', 'truncation'])
"""

from __future__ import annotations

import math

from .cint import CDivisionByZero, CInt, CType, _common, trunc_div, wrap_to

__all__ = ["ICInt", "lift", "DIV0", "RInterval", "Undecided", "Branch", "Empty", "choose",
           "forcing", "maximum", "ANY"]

_NO_FLAGS = frozenset()
_WRAP = frozenset({"wrap"})
_TRUNC = frozenset({"truncation"})
#: The flag of a division whose divisor may be zero (the concrete code raises there).
DIV0 = frozenset({"div0"})


def _fit(lo: int, hi: int, t: CType, flags: frozenset) -> "ICInt":
    """The exact interval [lo, hi] stored in ``t``: unchanged, or wrapped and flagged."""
    if t.min <= lo and hi <= t.max:
        return ICInt(lo, hi, t, flags)
    flags = flags | _WRAP
    if hi - lo + 1 >= 1 << t.bits:
        return ICInt(t.min, t.max, t, flags)
    wl, wh = wrap_to(lo, t), wrap_to(hi, t)
    # Shorter than 2^bits: the image is one piece exactly when it does not cross the seam.
    return ICInt(wl, wh, t, flags) if wl <= wh else ICInt(t.min, t.max, t, flags)


def lift(x: CInt) -> "ICInt":
    """``x`` as an interval (a point for a plain :class:`CInt`)."""
    return x if isinstance(x, ICInt) else ICInt(x.value, x.value, x.ctype, x.flags)


def _convert(x: "ICInt", t: CType) -> "ICInt":
    """An operand converted to the common type; as in :class:`CInt`, this adds no flag."""
    if x.ctype is t or (t.min <= x.lo and x.hi <= t.max):
        return x
    y = _fit(x.lo, x.hi, t, x.flags)
    return ICInt(y.lo, y.hi, t, x.flags)


class ICInt(CInt):
    """Every value of a C integer expression over a box: ``[lo, hi]`` in ``ctype``.

    Parameters
    ----------
    lo, hi : int, ctype.min ≤ lo ≤ hi ≤ ctype.max
    ctype : CType
    flags : frozenset of str
        Flags some point of the box may raise (``wrap``, ``truncation``, ``div0``).

    Notes
    -----
    ``value`` is the pair ``(lo, hi)``: code that compares a ``CInt``'s value to a
    number sees "not certainly that number", and a store that changes any value is
    seen as a change.
    """

    __slots__ = ("lo", "hi")

    def __init__(self, lo: int, hi: int, ctype: CType, flags: frozenset = _NO_FLAGS) -> None:
        if not ctype.min <= lo <= hi <= ctype.max:
            raise ValueError(f"[{lo}, {hi}] is not an interval of {ctype.name}")
        self.lo, self.hi = lo, hi
        self.value = (lo, hi)
        self.ctype = ctype
        self.flags = flags

    def __repr__(self) -> str:
        return f"ICInt({self.lo}, {self.hi}, {self.ctype.name}, {sorted(self.flags)})"

    def cast(self, ctype: CType) -> "ICInt":
        return _fit(self.lo, self.hi, ctype, self.flags)

    def clean(self) -> "ICInt":
        """Read back from a variable: only ``div0`` stays, since a value that may come from a
        division by zero (where the concrete code stops) may not exist at all."""
        return ICInt(self.lo, self.hi, self.ctype, self.flags & DIV0)

    def _arith(self, other: CInt, op: str) -> "ICInt":
        o = lift(other)
        t = self.ctype if self.ctype is o.ctype else _common(self.ctype, o.ctype)
        a, b = _convert(self, t), _convert(o, t)
        flags = a.flags | b.flags
        if op == "*":
            c = (a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi)
            return _fit(min(c), max(c), t, flags)
        if op == "+":
            return _fit(a.lo + b.lo, a.hi + b.hi, t, flags)
        if op == "-":
            return _fit(a.lo - b.hi, a.hi - b.lo, t, flags)
        return _divide(a, b, t, flags)

    def _rarith(self, other: CInt, op: str) -> "ICInt":
        return lift(other)._arith(self, op)

    def __rmul__(self, other: CInt) -> "ICInt":
        return self._rarith(other, "*")

    def __radd__(self, other: CInt) -> "ICInt":
        return self._rarith(other, "+")

    def __rsub__(self, other: CInt) -> "ICInt":
        return self._rarith(other, "-")

    def __rfloordiv__(self, other: CInt) -> "ICInt":
        return self._rarith(other, "/")

    def __neg__(self) -> "ICInt":
        return _fit(-self.hi, -self.lo, self.ctype, self.flags)

    def __lshift__(self, n: int) -> "ICInt":
        return _fit(self.lo << n, self.hi << n, self.ctype, self.flags)

    def __rshift__(self, n: int) -> "ICInt":
        exact = self.lo == self.hi and not self.lo & ((1 << n) - 1)
        return ICInt(self.lo >> n, self.hi >> n, self.ctype,
                     self.flags if exact or n == 0 else self.flags | _TRUNC)

    def __int__(self) -> int:
        raise TypeError("an interval has no single integer value")


def _divide(a: ICInt, b: ICInt, t: CType, flags: frozenset) -> ICInt:
    """C ``/`` over intervals: trunc(x/y) is monotone in x and, on each sign of y, in y,
    so its extremes over a rectangle are at the corners of each non-zero piece of b."""
    if b.lo == b.hi == 0:
        raise CDivisionByZero("integer division by zero")
    pieces = []
    if b.lo < 0:
        pieces.append((b.lo, min(b.hi, -1)))
    if b.hi > 0:
        pieces.append((max(b.lo, 1), b.hi))
    if b.lo <= 0 <= b.hi:
        flags = flags | DIV0
    q = [trunc_div(x, y) for lo, hi in pieces for x in (a.lo, a.hi) for y in (lo, hi)]
    point = a.lo == a.hi and b.lo == b.hi
    if not (point and q[0] * b.lo == a.lo) and not (b.lo == b.hi == 1):
        flags = flags | _TRUNC
    return _fit(min(q), max(q), t, flags)


class Undecided(ArithmeticError):
    """A comparison or branch whose answer differs across a box: split the box and ask again."""


def _down(x: float) -> float:
    return math.nextafter(x, -math.inf)


def _up(x: float) -> float:
    return math.nextafter(x, math.inf)


def _real(x) -> "RInterval":
    return x if isinstance(x, RInterval) else RInterval(x, x)


class RInterval:
    """Every value a floating-point expression takes over a box: ``[lo, hi]``, rounded outward.

    Each operation widens its result by one unit in the last place each way, so it holds the
    exact real result and the correctly rounded double the concrete code computes (IEEE
    arithmetic is monotone in each operand).  Constants (``math.pi``, ``SQRT3``) enter as
    the same doubles the concrete code uses.  A comparison answers only when every point of
    the box gives the same answer, and raises :class:`Undecided` otherwise; so does ``bool``.

    Examples
    --------
    >>> x = RInterval(1.0, 2.0) * 3.0 + 1.0
    >>> x.lo < 4.0 and x.hi > 7.0, x > 3.0
    (True, True)
    >>> RInterval(0.4, 0.6).round_half_away().value
    (0, 1)
    """

    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi) -> None:
        if not lo <= hi:
            raise ValueError(f"[{lo}, {hi}] is not an interval")
        self.lo, self.hi = lo, hi

    def __repr__(self) -> str:
        return f"RInterval({self.lo!r}, {self.hi!r})"

    @property
    def value(self) -> tuple:
        return self.lo, self.hi

    def _out(self, lo: float, hi: float) -> "RInterval":
        return RInterval(_down(lo), _up(hi))

    def __add__(self, o) -> "RInterval":
        o = _real(o)
        return self._out(self.lo + o.lo, self.hi + o.hi)

    __radd__ = __add__

    def __sub__(self, o) -> "RInterval":
        o = _real(o)
        return self._out(self.lo - o.hi, self.hi - o.lo)

    def __rsub__(self, o) -> "RInterval":
        return _real(o) - self

    def __neg__(self) -> "RInterval":
        return RInterval(-self.hi, -self.lo)

    def __mul__(self, o) -> "RInterval":
        o = _real(o)
        c = (self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi)
        return self._out(min(c), max(c))

    __rmul__ = __mul__

    def __truediv__(self, o) -> "RInterval":
        o = _real(o)
        if o.lo <= 0 <= o.hi:
            if o.lo == o.hi:
                raise ZeroDivisionError("float division by zero")
            raise Undecided("the divisor may be 0")
        c = (self.lo / o.lo, self.lo / o.hi, self.hi / o.lo, self.hi / o.hi)
        return self._out(min(c), max(c))

    def __rtruediv__(self, o) -> "RInterval":
        return _real(o) / self

    def _compare(self, o, certainly_true: bool, certainly_false: bool) -> bool:
        if certainly_true:
            return True
        if certainly_false:
            return False
        raise Undecided(f"{self!r} compared with {o!r}")

    def __lt__(self, o) -> bool:
        o = _real(o)
        return self._compare(o, self.hi < o.lo, self.lo >= o.hi)

    def __le__(self, o) -> bool:
        o = _real(o)
        return self._compare(o, self.hi <= o.lo, self.lo > o.hi)

    def __gt__(self, o) -> bool:
        return _real(o) < self

    def __ge__(self, o) -> bool:
        return _real(o) <= self

    def __bool__(self) -> bool:
        return self._compare(0, self.lo > 0 or self.hi < 0, self.lo == self.hi == 0)

    def __abs__(self) -> "RInterval":
        if self.lo >= 0:
            return self
        if self.hi <= 0:
            return -self
        return RInterval(0.0, max(-self.lo, self.hi))

    # floor, trunc and round are monotone: the ends' integers bound every point's.
    def __floor__(self) -> "RInterval":
        return RInterval(math.floor(self.lo), math.floor(self.hi))

    def __trunc__(self) -> "RInterval":
        return RInterval(math.trunc(self.lo), math.trunc(self.hi))

    def __round__(self) -> "RInterval":
        return RInterval(round(self.lo), round(self.hi))

    def clip(self, lo: float, hi: float) -> "RInterval":
        """The part of the interval inside [lo, hi]; :class:`Empty` when there is none."""
        a, b = max(self.lo, lo), min(self.hi, hi)
        if a > b:
            raise Empty(f"{self!r} misses [{lo}, {hi}]")
        return RInterval(a, b)

    def round_half_away(self) -> "RInterval":
        """The integers ``round(x)`` (ties away from zero) takes: monotone, so the ends'."""
        def r(x: float) -> int:
            return int(math.copysign(math.floor(abs(x) + 0.5), x))
        return RInterval(r(self.lo), r(self.hi))


def maximum(*xs):
    """``max`` of numbers some of which may be intervals (Python's ``max`` would compare them).

    >>> maximum(RInterval(1.0, 3.0), 2.0).value
    (2.0, 3.0)
    """
    if not any(isinstance(x, RInterval) for x in xs):
        return max(xs)
    rs = [_real(x) for x in xs]
    return RInterval(max(r.lo for r in rs), max(r.hi for r in rs))


class Branch(Undecided):
    """A choice the code makes (a shift, a divisor) differs across a box.

    Attributes
    ----------
    site : str — which choice (e.g. ``st.TF_KPDIV``)
    choices : list of int — every choice some point of the box may make
    """

    def __init__(self, site: str, choices: list) -> None:
        super().__init__(f"{site} takes {choices} over the box")
        self.site, self.choices = site, choices


class Empty(ArithmeticError):
    """No point of a box makes the forced choice: that piece of the box is empty."""


#: A forced choice that takes any one choice and keeps the whole interval: for evaluating what
#: does not depend on that choice, without cutting the box at it.
ANY = "any"

#: The choices forced for the evaluation under way (see :func:`forcing`).
_FORCED: dict = {}


class forcing:
    """Evaluate with these choices forced: ``with forcing({"st.TF_KPDIV": 10}): …``.

    Under a forced choice, :func:`choose` keeps only the part of its quantity where the
    choice is made; the evaluation then covers exactly the points of the box that make it.
    """

    def __init__(self, forced: dict) -> None:
        self.forced, self.saved = forced, None

    def __enter__(self) -> None:
        global _FORCED
        self.saved, _FORCED = _FORCED, self.forced

    def __exit__(self, *exc) -> None:
        global _FORCED
        _FORCED = self.saved


def choose(site: str, x, pick, region):
    """A choice made from a quantity: ``(pick(x), x)`` for a number; over an interval, the
    choice every point makes and the interval, or (under :class:`forcing`) the forced choice
    and the part of ``x`` inside ``region(choice)`` (the whole of ``x`` and its low end's
    choice when forced to :data:`ANY`).

    Parameters
    ----------
    site : str
        The choice's name (the key :class:`forcing` uses).
    x : float or RInterval
    pick : callable float → int
        The concrete rule, monotone in ``x`` (either way): the choices of an interval are the
        integers between its ends' choices.
    region : callable int → (lo, hi)
        A closed interval holding every ``x`` that ``pick`` maps to the choice.

    Raises
    ------
    Branch
        When the ends choose differently and the choice is not forced.
    Empty
        When no point of ``x`` makes the forced choice.
    """
    if not isinstance(x, RInterval):
        return pick(x), x
    if site in _FORCED:
        c = _FORCED[site]
        if c is ANY:
            return pick(x.lo), x
        return c, x.clip(*region(c))
    a, b = pick(x.lo), pick(x.hi)
    if a == b:
        return a, x
    raise Branch(site, list(range(min(a, b), max(a, b) + 1)))
