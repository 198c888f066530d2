"""TI IQmath library calls in the tracer, against C written here from TI's descriptions.

The reference C below is this test's own: each function is written from what TI's public
sources state (see py/pulab/ctrace/iqmath.py for the files), never from the tracer's Python.
The exact operations (mpy, rmpy, rsmpy, int, frac, sat, abs) must agree bit for bit, call by
call, with gcc -m32 and avr-gcc + simavr running that C; the operations whose last bits TI's
closed library decides (div, sqrt, mag, sin, cos, atan2 and their PU forms) must equal the
correctly rounded value the C computes (integer arithmetic for div, sqrt, mag; the C library's
binary64 functions and lround for the trig ones) and carry the flag ``not_bit_exact``.
"""

from __future__ import annotations

import math
import random

import pytest

from ctrace_compilers import Unit, require, run_calls
from pulab.ctrace import TraceError, compile_code, trace
from pulab.ctrace.sequence import run_sequence

REFERENCE = r"""
#include <limits.h>
#include <math.h>
static long ref_wrap(long long v) { return (long)(unsigned long)(unsigned long long)v; }
static long ref_clamp(long long v) { return v > LONG_MAX ? LONG_MAX : v < LONG_MIN ? LONG_MIN : (long)v; }
static long ref_rmpy(long a, long b, int q) { return ref_wrap(((long long)a * b + (1LL << (q - 1))) >> q); }
static long ref_rsmpy(long a, long b, int q) { return ref_clamp(((long long)a * b + (1LL << (q - 1))) >> q); }
/* C28x ABSTC under overflow mode: |LONG_MIN| is LONG_MAX */
static long ref_sabs(long a) { return a == LONG_MIN ? LONG_MAX : a < 0 ? -a : a; }
static long ref_int(long a, int q) { long m = ref_sabs(a) >> q; return a < 0 ? -m : m; }
static long ref_frac(long a, int q) { long m = ref_sabs(a) & ((1L << q) - 1); return a < 0 ? -m : m; }
static unsigned long long ref_isqrt(unsigned long long n) {  /* floor(sqrt(n)), bit by bit */
  unsigned long long r = 0, bit = 1ULL << 62;
  while (bit > n) bit >>= 2;
  while (bit) { if (n >= r + bit) { n -= r + bit; r = (r >> 1) + bit; } else r >>= 1; bit >>= 2; }
  return r;
}
static unsigned long long ref_sqrt_nearest(unsigned long long n) {
  unsigned long long r = ref_isqrt(n);
  return n - r * r > r ? r + 1 : r;
}
static long ref_div(long a, long b, int q) {
  long long num, den, quo;
  if (b == 0) return a >= 0 ? LONG_MAX : LONG_MIN;
  num = (long long)a * (1LL << q); den = b;
  if (den < 0) { num = -num; den = -den; }
  quo = ((num < 0 ? -num : num) * 2 + den) / (2 * den);  /* halves away from zero */
  return ref_clamp(num < 0 ? -quo : quo);
}
static long ref_sqrt(long a, int q) { return a <= 0 ? 0 : (long)ref_sqrt_nearest((unsigned long long)a << q); }
static long ref_mag(long a, long b) {
  unsigned long long s = (unsigned long long)((long long)a * a) + (unsigned long long)((long long)b * b);
  return ref_clamp((long long)ref_sqrt_nearest(s));
}
static long ref_trig(double x, int q) { return ref_clamp(lround(ldexp(x, q))); }
static const double ref_pi = 3.14159265358979323846;
static long ref_atan2pu(long a, long b, int q) {
  double t = atan2((double)a, (double)b) / (2 * ref_pi);
  return ref_trig(t < 0 ? t + 1.0 : t, q);
}
#define _IQrmpy(a, b) ref_rmpy((a), (b), GLOBAL_Q)
#define _IQ15rmpy(a, b) ref_rmpy((a), (b), 15)
#define _IQrsmpy(a, b) ref_rsmpy((a), (b), GLOBAL_Q)
#define _IQ30rsmpy(a, b) ref_rsmpy((a), (b), 30)
#define _IQint(a) ref_int((a), GLOBAL_Q)
#define _IQ1int(a) ref_int((a), 1)
#define _IQfrac(a) ref_frac((a), GLOBAL_Q)
#define _IQ29frac(a) ref_frac((a), 29)
#define _IQdiv(a, b) ref_div((a), (b), GLOBAL_Q)
#define _IQ15div(a, b) ref_div((a), (b), 15)
#define _IQsqrt(a) ref_sqrt((a), GLOBAL_Q)
#define _IQ30sqrt(a) ref_sqrt((a), 30)
#define _IQmag(a, b) ref_mag((a), (b))
#define _IQsin(a) ref_trig(sin(ldexp((a), -GLOBAL_Q)), GLOBAL_Q)
#define _IQcos(a) ref_trig(cos(ldexp((a), -GLOBAL_Q)), GLOBAL_Q)
#define _IQ29sin(a) ref_trig(sin(ldexp((a), -29)), 29)
#define _IQsinPU(a) ref_trig(sin(2 * ref_pi * ldexp((a), -GLOBAL_Q)), GLOBAL_Q)
#define _IQcosPU(a) ref_trig(cos(2 * ref_pi * ldexp((a), -GLOBAL_Q)), GLOBAL_Q)
#define _IQatan2(a, b) ref_trig(atan2((double)(a), (double)(b)), GLOBAL_Q)
#define _IQatan2PU(a, b) ref_atan2pu((a), (b), GLOBAL_Q)
"""

EXACT = r"""
long r_mpy, r_rmpy, r_rmpy15, r_rsmpy, r_rsmpy30, r_int, r_int1, r_frac, r_frac29, r_sat, r_abs;
void iq_exact(long a, long b)
{
  r_mpy = _IQmpy(a, b);
  r_rmpy = _IQrmpy(a, b);
  r_rmpy15 = _IQ15rmpy(a, b);
  r_rsmpy = _IQrsmpy(a, b);
  r_rsmpy30 = _IQ30rsmpy(a, b);
  r_int = _IQint(a);
  r_int1 = _IQ1int(b);
  r_frac = _IQfrac(a);
  r_frac29 = _IQ29frac(b);
  r_sat = _IQsat(a, b, -b);
  r_abs = _IQabs(a);
}
"""

ROUNDED = r"""
long r_div, r_div15, r_sqrt, r_sqrt30, r_mag, r_sin, r_cos, r_sin29, r_sinpu, r_cospu, r_atan2, r_atan2pu;
void iq_rounded(long a, long b)
{
  r_div = _IQdiv(a, b);
  r_div15 = _IQ15div(a, b);
  r_sqrt = _IQsqrt(a);
  r_sqrt30 = _IQ30sqrt(b);
  r_mag = _IQmag(a, b);
  r_sin = _IQsin(a);
  r_cos = _IQcos(b);
  r_sin29 = _IQ29sin(a >> 2);
  r_sinpu = _IQsinPU(a);
  r_cospu = _IQcosPU(b);
  r_atan2 = _IQatan2(a, b);
  r_atan2pu = _IQatan2PU(a, b);
}
"""

LIMITS = [0, 1, -1, 2, -2, (1 << 23) - 1, 1 << 24, -(1 << 24), 3 << 23, -(3 << 23), 1 << 30,
          -(1 << 30), 2147483647, -2147483648, 2147483646, -2147483647, 46341, -46341]


def _rows(seed: str, n: int) -> list:
    rng = random.Random(seed)
    pool = LIMITS + [rng.randrange(-(1 << 31), 1 << 31) for _ in range(40)]
    rows = [{"a": a, "b": b} for a in LIMITS for b in LIMITS[:8]]
    while len(rows) < n:
        pick = rng.random()
        a = rng.choice(pool) if pick < 0.2 else rng.randrange(-(1 << 31), 1 << 31) \
            if pick < 0.5 else rng.randrange(-(1 << 26), 1 << 26)
        b = rng.randrange(-(1 << 31), 1 << 31) if rng.random() < 0.4 else \
            rng.randrange(-(1 << 25), 1 << 25)
        rows.append({"a": a, "b": b})
    return rows[:n]


def _agree(code, entry, outputs, rows, target):
    traced = run_sequence(compile_code(code, target, entry=entry), len(rows), rows)
    unit = Unit(code, entry, [("long", "a"), ("long", "b")], [("long", "a"), ("long", "b")],
                [("long", n) for n in outputs], prelude=REFERENCE)
    got = run_calls(unit, rows, target)
    assert len(got) == len(traced["calls"]) == len(rows)
    for k, (call, g) in enumerate(zip(traced["calls"], got)):
        mine = {n: call["vars"][n]["value"] for n in outputs}
        assert mine == g, f"call {k} {rows[k]}: tracer {mine} vs compiler {g}"
    return traced


@pytest.mark.parametrize("target", ["arm", "avr"])
def test_exact_iqmath_calls_agree_bit_for_bit_with_the_compiled_reference(target, capsys):
    require(target, capsys)
    outputs = ["r_mpy", "r_rmpy", "r_rmpy15", "r_rsmpy", "r_rsmpy30", "r_int", "r_int1",
               "r_frac", "r_frac29", "r_sat", "r_abs"]
    traced = _agree(EXACT, "iq_exact", outputs, _rows(f"exact-{target}", 1000), target)
    flags = set().union(*(c["flags"] for c in traced["calls"]))
    # the vectors reach the saturation of _IQrsmpy, the wrap of _IQrmpy, labs(LONG_MIN)
    assert {"saturate", "conversion", "truncation", "signed_overflow"} <= flags
    assert "not_bit_exact" not in flags


@pytest.mark.parametrize("target", ["arm"])
def test_rounded_iqmath_calls_equal_the_correctly_rounded_value_and_are_flagged(target, capsys):
    require(target, capsys)
    outputs = ["r_div", "r_div15", "r_sqrt", "r_sqrt30", "r_mag", "r_sin", "r_cos", "r_sin29",
               "r_sinpu", "r_cospu", "r_atan2", "r_atan2pu"]
    traced = _agree(ROUNDED, "iq_rounded", outputs, _rows(f"rounded-{target}", 1000), target)
    assert all("not_bit_exact" in c["flags"] for c in traced["calls"])


def _one(code: str, name: str, **inputs) -> dict:
    r = trace(code, "c28x", inputs=inputs)
    return next(t for s in r["steps"] for t in s["terms"] if t["expr"].startswith(name))


@pytest.mark.parametrize("expr, a, b, value", [
    # TI's readme examples: _IQint(-2.3456) = -2, _IQfrac(-2.3456) = -0.3456 (Q24)
    ("_IQint(a)", -round(2.3456 * 2 ** 24), 0, -2),
    ("_IQfrac(a)", -round(2.3456 * 2 ** 24), 0, 2 * 2 ** 24 - round(2.3456 * 2 ** 24)),
    ("_IQint(a)", -(2 ** 31), 0, -127),          # |LONG_MIN| saturated, then >> 24
    ("_IQrsmpy(a, b)", 1 << 30, 1 << 30, 2 ** 31 - 1),
    ("_IQrmpy(a, b)", 3 << 22, 1, 1),             # 0.75 LSB rounds up; _IQmpy gives 0
    ("_IQdiv(a, b)", 1 << 24, 0, 2 ** 31 - 1),    # saturates by the sign of a
    ("_IQdiv(a, b)", -(1 << 24), 0, -(2 ** 31)),
    ("_IQdiv(a, b)", 1, 1 << 25, 1),            # exactly ½ LSB: halves away from zero
    ("_IQdiv(a, b)", -1, 1 << 25, -1),
    ("_IQsqrt(a)", -5, 0, 0),
    ("_IQatan2PU(a, b)", -(1 << 24), 0, 3 << 22),  # −90° is 0.75 of a turn
])
def test_documented_edge_values(expr, a, b, value):
    t = _one(f"long a, b; long y = {expr};", expr.split("(")[0], a=a, b=b)
    assert t["value"] == value, t["expr"]


def test_flags_name_each_effect_and_the_term_carries_its_q():
    t = _one("long a, b; long y = _IQ20sinPU(a);", "_IQ20sinPU", a=1 << 18, b=0)
    assert (t["value"], t["flags"], t["q"]) == (1 << 20, ["not_bit_exact"], 20)
    t = _one("long a, b; long y = _IQrsmpy(a, b);", "_IQrsmpy", a=1 << 30, b=1 << 30)
    assert t["flags"] == ["saturate"]
    r = trace("#define GLOBAL_Q 15\nlong a; long y = _IQsin(a);", "c28x", inputs={"a": 51472})
    assert r["vars"]["y"]["value"] == round(math.sin(51472 / 2 ** 15) * 2 ** 15)  # π/2 in Q15


@pytest.mark.parametrize("code, text", [
    ("long a; long y = _IQdiv(a);", "_IQdiv() takes 2 arguments, got 1"),
    ("long a; long y = _IQ24sqrt(a, a);", "_IQ24sqrt() takes 1 arguments, got 2"),
    ("long a; long y = _IQtoF(a);", "_IQtoF() returns a float"),
])
def test_bad_iqmath_calls_are_refused(code, text):
    with pytest.raises(TraceError) as e:
        trace(code, "c28x", inputs={"a": 1})
    assert text in str(e.value)
