"""Interval C arithmetic encloses every concrete result (exhaustive on small intervals)."""
import itertools
import math
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


# Choices (a shift, a divisor) over intervals: pulab.fixedpoint.interval.choose.
def test_choose_splits_where_the_choice_differs_and_clips_each_piece():
    from pulab.fixedpoint.interval import ANY, Branch, Empty, RInterval, choose, forcing
    pick = lambda x: int(x >= 2.0) + int(x >= 4.0)  # noqa: E731
    region = lambda c: [(0.0, 2.0), (2.0, 4.0), (4.0, 8.0)][c]  # noqa: E731
    assert choose("s", RInterval(2.5, 3.5), pick, region)[0] == 1
    with pytest.raises(Branch) as b:
        choose("s", RInterval(1.0, 5.0), pick, region)
    assert b.value.site == "s" and b.value.choices == [0, 1, 2]
    with forcing({"s": 1}):
        c, x = choose("s", RInterval(1.0, 5.0), pick, region)
        assert c == 1 and x.value == (2.0, 4.0)
    with forcing({"s": 2}), pytest.raises(Empty):
        choose("s", RInterval(1.0, 3.0), pick, region)
    with forcing({"s": ANY}):
        c, x = choose("s", RInterval(1.0, 5.0), pick, region)
        assert c == 0 and x.value == (1.0, 5.0)
    assert choose("s", 4.5, pick, region) == (2, 4.5)


def _neighbours(x, n=3):
    out = [x]
    for step in (math.inf, -math.inf):
        y = x
        for _ in range(n):
            y = math.nextafter(y, step)
            out.append(y)
    return out


def test_choice_regions_hold_every_double_the_rule_maps_there():
    """For each shift/exponent the rule picks at doubles next to every boundary, the forced
    region of that choice holds the double (the proof clips to it, so it must)."""
    from pulab.fixedpoint.interval import RInterval, forcing
    from pulab.profiles.common import mantissa_shift, pow2_exponent
    xs = [y for e in range(-20, 6) for y in _neighbours(2.0 ** e)]
    xs += [y for n in range(0, 16) for y in _neighbours(32767.5 / 2.0 ** n)]
    for x in xs:
        m, s = mantissa_shift(x)
        with forcing({"t": s}):
            mi, si = mantissa_shift(RInterval(x, x), "t")
        assert si == s and mi.lo <= m <= mi.hi, x
        for largest in (14, 15):
            n, _ = pow2_exponent(x, 32767, largest)
            with forcing({"d": n}):
                _, k = pow2_exponent(RInterval(x, x), 32767, largest, "d")
            assert k.lo <= x <= k.hi, (x, n)


def test_interval_abs_floor_trunc_round_and_maximum():
    from pulab.fixedpoint.interval import RInterval, maximum
    assert abs(RInterval(-3.0, 2.0)).value == (0.0, 3.0)
    assert abs(RInterval(-3.0, -2.0)).value == (2.0, 3.0)
    assert math.floor(RInterval(-1.5, 2.5)).value == (-2, 2)
    assert math.trunc(RInterval(-1.5, 2.5)).value == (-1, 2)
    assert round(RInterval(0.5, 2.5)).value == (0, 2)  # Python rounds half to even, as the code
    assert maximum(RInterval(1.0, 3.0), RInterval(2.0, 2.5)).value == (2.0, 3.0)
    assert maximum(1.0, 2.0) == 2.0
