"""The vendors' integer PI steps (pulab.profiles.NAME.pi) against a C oracle
(tests/oracle/vendor_pi.c, gcc -m32 -fwrapv).

The oracle is our own C of each vendor's PI step, written in the constructs of the vendor's
public code and compiled by a real compiler; it never imports pulab.  Both are fed the same
integer sequences — random errors over the whole word, including values that wrap and
saturate — and every output and state integer, and the count of each event, must agree.
Event counts are also checked on cases worked by hand.

Missing gcc-multilib: SKIPPED loudly; with CI=true the missing tools fail the test.
"""

from __future__ import annotations

import pathlib
import random
import subprocess

import pytest

from ctrace_compilers import require
from pulab.profiles.microchip.pi import step as microchip_step
from pulab.profiles.nxp.pi import step as nxp_step
from pulab.profiles.st.pi import step as st_step
from pulab.profiles.ti.pi import step as ti_step

ORACLE = pathlib.Path(__file__).resolve().parents[1] / "oracle" / "vendor_pi.c"
SEED = 20261126
STEPS = 3000


@pytest.fixture(scope="module")
def oracle(tmp_path_factory):
    exe = tmp_path_factory.mktemp("vendor_pi") / "vendor_pi"
    subprocess.run(["gcc", "-m32", "-fwrapv", "-O1", "-o", str(exe), str(ORACLE)], check=True)
    return exe


def run_oracle(exe, args: list, pairs: list) -> tuple:
    """The oracle's lines for one vendor, [[out, state...], ...], and its event counts."""
    text = "".join(f"{r} {f}\n" for r, f in pairs)
    res = subprocess.run([str(exe)] + [str(a) for a in args], input=text, capture_output=True,
                         text=True, check=True)
    *rows, last = res.stdout.splitlines()
    head, *counts = last.split()
    assert head == "events"
    names = ("wrap", "saturate", "integral_limit", "output_limit")
    return ([[int(x) for x in line.split()] for line in rows],
            {k: int(c) for k, c in zip(names, counts) if int(c)})


def run_pulab(step, state: tuple, pairs: list, ev: dict) -> list:
    rows = []
    for r, f in pairs:
        state, out = step(state, r, f, ev=ev)
        rows.append([out, *state])
    return rows


def _pairs(rng, lo: int, hi: int, near: int) -> list:
    """Errors of every size: small ones around a reference (a loop near steady state) and
    values over the whole word (wraps and saturations)."""
    out = []
    for k in range(STEPS):
        if k % 3:
            r = rng.randint(-near, near)
            out.append((r, r + rng.randint(-near // 8 - 1, near // 8 + 1)))
        else:
            out.append((rng.randint(lo, hi), rng.randint(lo, hi)))
    return out


CASES = [
    # name, oracle args (gains, limits, format), pulab step, initial state
    ("ti", [5590440, 4194304, 11744051, -11744051, 24, 0],
     lambda s, r, f, ev: ti_step(s, r, f, 5590440, 4194304, 11744051, -11744051, 24, ev), (0,)),
    ("ti", [1 << 30, 1 << 29, (1 << 31) - 1, -(1 << 31), 20, 123456],
     lambda s, r, f, ev: ti_step(s, r, f, 1 << 30, 1 << 29, (1 << 31) - 1, -(1 << 31), 20, ev),
     (123456,)),
    ("nxp", [18911, 4727, 18918, -18918, 0, 0, 0],
     lambda s, r, f, ev: nxp_step(s, r, f, 18911, 4727, 18918, -18918, False, ev), (0, 0)),
    ("nxp", [2000000, 900000, 32767, -32768, 1, 5 << 16, 7],
     lambda s, r, f, ev: nxp_step(s, r, f, 2000000, 900000, 32767, -32768, True, ev), (5 << 16, 7)),
    ("st", [9456, 2364, 14, 14, 32767 * 16384, 0],
     lambda s, r, f, ev: st_step(s, r, f, 9456, 2364, 14, 14, 32767 * 16384, ev), (0,)),
    ("st", [32767, 32767, 3, 0, 32767, -5],
     lambda s, r, f, ev: st_step(s, r, f, 32767, 32767, 3, 0, 32767, ev), (-5,)),
    ("st", [-32768, 0, 10, 10, 32767 * 1024, 0],
     lambda s, r, f, ev: st_step(s, r, f, -32768, 0, 10, 10, 32767 * 1024, ev), (0,)),
    ("microchip", [10919, 2730, 32767, 18918, -18918, 0, 0, 0],
     lambda s, r, f, ev: microchip_step(s, r, f, 10919, 2730, 32767, 18918, -18918, 0, 0, ev),
     (0,)),
    ("microchip", [30000, 20000, 32767, 32767, -32768, 4, 2, 1 << 20],
     lambda s, r, f, ev: microchip_step(s, r, f, 30000, 20000, 32767, 32767, -32768, 4, 2, ev),
     (1 << 20,)),
]
WORDS = {"ti": (-(1 << 31), (1 << 31) - 1, 1 << 22), "nxp": (-32768, 32767, 4000),
         "st": (-32768, 32767, 4000), "microchip": (-32768, 32767, 4000)}


@pytest.mark.parametrize("k", range(len(CASES)))
def test_equals_the_c_oracle_integer_by_integer(oracle, capsys, k):
    require("arm", capsys)
    name, args, step, state = CASES[k]
    pairs = _pairs(random.Random(SEED + k), *WORDS[name])
    ev: dict = {}
    got = run_pulab(step, state, pairs, ev)
    want, want_ev = run_oracle(oracle, [name] + args, pairs)
    assert len(want) == len(pairs)
    mismatches = [(i, g, w) for i, (g, w) in enumerate(zip(got, want)) if g != w]
    assert mismatches == [], f"{len(mismatches)} mismatches, first {mismatches[:3]}"
    # Every wrap, saturation and limit counted as the compiled C counts it; whole-word inputs
    # must have driven each controller into some.
    assert ev == want_ev
    assert sum(ev.values()) > 0


def test_ti_counts_the_iqmpy_wrap():
    # Kp = 64.0 in IQ24 times an error of 64.0: 4096.0 does not fit IQ24's ±128 — one wrap
    # in _IQmpy (2^36 mod 2^32 = 0), then Up + Ui is 0: no other event.
    ev: dict = {}
    state, out = ti_step((0,), 64 << 24, 0, 64 << 24, 0, 1 << 30, -(1 << 30), 24, ev)
    assert (state, out, ev) == ((0,), 0, {"wrap": 1})


def test_st_counts_the_overflow_guard_and_the_limits():
    # Integral 2^31 − 100 plus Ki·e = 1000: the sum wraps negative, the guard puts it at
    # INT32_MAX (saturate), the limit then holds it at INT16_MAX·KIDIV (integral_limit);
    # the output (Kp = 0) is INT32_MAX·… >> 14 = 32767 exactly: within ±INT16_MAX.
    ev: dict = {}
    state, out = st_step(((1 << 31) - 100,), 1000, 0, 0, 1, 14, 14, 32767 * 16384, ev)
    assert state == (32767 * 16384,) and out == 32767
    assert ev == {"saturate": 1, "integral_limit": 1}


def test_microchip_counts_the_int16_error_wrap_and_output_limit():
    # qInRef − qInMeas = 32767 − (−32768) = 65535 → int16 −1 (wrap); Kp·(−1) >> 15 = −1,
    # inside ±100: no limit.  Then a big sum drives the output to its limit.
    ev: dict = {}
    (s,), out = microchip_step((0,), 32767, -32768, 32767, 0, 32767, 100, -100, 0, 0, ev)
    assert (s, out, ev) == (0, -1, {"wrap": 1})
    ev = {}
    (s,), out = microchip_step((1000 << 15,), 0, 0, 32767, 0, 32767, 100, -100, 0, 0, ev)
    # Exc = 1000 − 100 = 900; Sum −= 900·32767
    assert (s, out, ev) == ((1000 << 15) - 900 * 32767, 100, {"output_limit": 1})


def test_nxp_saturates_the_error_and_holds_the_accumulator():
    # 32767 − (−32768) saturates to 32767; Kp·e·2 and Ki·e·2 in frac32 saturate; the
    # accumulator is held at the upper limit 100·2^16; P + accumulator saturates again
    # (four saturations); the output is held at 100.
    ev: dict = {}
    (acc, e), out = nxp_step((0, 0), 32767, -32768, 1 << 20, 1 << 20, 100, -100, False, ev)
    assert (acc, e, out) == (100 << 16, 32767, 100)
    assert ev == {"saturate": 4, "integral_limit": 1, "output_limit": 1}
