"""Interval C arithmetic encloses every concrete result (exhaustive on small intervals)."""
import itertools
import random

import pytest

from pulab.fixedpoint.cint import INT16, INT32, UINT16, UINT32, CDivisionByZero, CInt
from pulab.fixedpoint.interval import ICInt, RInterval, Undecided

TYPES = (INT16, UINT16, INT32, UINT32)
OPS = {"*": lambda a, b: a * b, "+": lambda a, b: a + b, "-": lambda a, b: a - b,
       "/": lambda a, b: a // b}


def _interval(rng, t):
    centre = rng.choice([0, 1, 7, 100, 255, 1 << 14, t.max, t.min, t.max // 3, 65535, 40000])
    centre = min(max(centre, t.min), t.max)
    lo = max(t.min, centre - rng.choice([0, 1, 2, 5]))
    return lo, min(t.max, lo + rng.choice([0, 1, 3, 6]))


def _check(got, values, flags):
    assert got.lo <= min(values) and max(values) <= got.hi
    assert flags <= got.flags


@pytest.mark.parametrize("op", sorted(OPS))
def test_binary_ops_enclose_every_point(op):
    rng = random.Random(op)
    for _ in range(400):
        ta, tb = rng.choice(TYPES), rng.choice(TYPES)
        (alo, ahi), (blo, bhi) = _interval(rng, ta), _interval(rng, tb)
        values, flags, div0 = [], set(), False
        for a, b in itertools.product(range(alo, ahi + 1), range(blo, bhi + 1)):
            try:
                c = OPS[op](CInt(a, ta), CInt(b, tb))
            except CDivisionByZero:
                div0 = True
                continue
            values.append(c.value)
            flags |= c.flags
        x, y = ICInt(alo, ahi, ta), ICInt(blo, bhi, tb)
        if not values:  # every divisor is 0: the interval code stops as the concrete one
            with pytest.raises(CDivisionByZero):
                OPS[op](x, y)
            continue
        _check(OPS[op](x, y), values, flags | ({"div0"} if div0 else set()))
        # A point on the left of an interval: the subclass's reflected operator takes over.
        if alo == ahi:
            _check(OPS[op](CInt(alo, ta), y), values, flags | ({"div0"} if div0 else set()))


@pytest.mark.parametrize("t", TYPES, ids=lambda t: t.name)
def test_shifts_casts_and_negation_enclose_every_point(t):
    rng = random.Random(t.name)
    for _ in range(300):
        lo, hi = _interval(rng, t)
        x = ICInt(lo, hi, t)
        n = rng.choice([0, 1, 4, 12, 15])
        target = rng.choice(TYPES)
        for f in (lambda v: v << n, lambda v: v >> n, lambda v: -v, lambda v: v.cast(target)):
            pts = [f(CInt(v, t)) for v in range(lo, hi + 1)]
            _check(f(x), [p.value for p in pts], set().union(*(p.flags for p in pts)))


def test_wrap_across_the_seam_gives_the_whole_word():
    # 65530..65540 in Uint16 is two pieces: only the whole word encloses both.
    x = ICInt(65530, 65535, UINT16) + CInt(5, UINT16)
    assert x.value == (0, 65535) and "wrap" in x.flags
    # 70000..70003 wraps without crossing the seam: one piece, exact.
    y = ICInt(35000, 35001, UINT32).cast(UINT16) * CInt(2, UINT32)
    assert y.value == (70000, 70002)
    assert (ICInt(35000, 35001, UINT16) * CInt(2, UINT16)).value == (4464, 4466)


def test_read_back_keeps_only_a_possible_division_by_zero():
    q = ICInt(10, 20, UINT16) // ICInt(0, 2, UINT16)
    assert q.flags == {"div0", "truncation"} and q.clean().flags == {"div0"}
    assert CInt(3, UINT16).clean().flags == frozenset()


def test_real_intervals_enclose_the_doubles_the_concrete_code_computes():
    rng = random.Random(7)
    ops = {"+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b,
           "/": lambda a, b: a / b}
    for _ in range(2000):
        a0 = rng.uniform(-1e3, 1e3)
        b0 = rng.uniform(0.1, 1e3) * rng.choice([-1, 1])
        a = RInterval(a0, a0 + abs(a0) * rng.choice([0, 1e-15, 1e-3, 1.0]))
        b = RInterval(b0, b0 + abs(b0) * rng.choice([0, 1e-15, 1e-3, 0.5]))
        for op, f in ops.items():
            got = f(a, b)
            for x in (a.lo, a.hi, (a.lo + a.hi) / 2):
                for y in (b.lo, b.hi, (b.lo + b.hi) / 2):
                    assert got.lo <= f(x, y) <= got.hi, (op, a, b, x, y)
    assert (3.0 * RInterval(1.0, 2.0) - 1.0) > 1.9
    with pytest.raises(Undecided):
        RInterval(-1.0, 1.0) > 0
    with pytest.raises(Undecided):
        bool(RInterval(0.0, 1.0))
    with pytest.raises(Undecided):
        RInterval(1.0, 2.0) / RInterval(-1.0, 1.0)
    assert RInterval(-2.5, 2.5).round_half_away().value == (-3, 3)
