"""Valid inputs at the far ends of their ranges, where the other fuzzers mutate one field into
something invalid: a report must still be a report or one input error, never a traceback.

The report fuzz draws several fields at once log-uniformly over the schema's whole range, with
raw firmware integers at Uint16 edges, a fixed-point simulation and the loop analysis; the
tracer gets integer literals longer than Python converts (4300 digits) in every place a
literal can stand. Both go through the CLI's ``main`` in-process, so the check is the exit code
and the one stderr line.
"""
import contextlib
import copy
import io
import json
import math
import random
import sys

import pytest

import pulab
from conftest import SEED_INPUT
from pulab.__main__ import main
from pulab.schema.errors import InputError
from pulab.schema.fields import FIELDS, RAW_FIELDS

CASES = 1500
UINT16_EDGES = (0, 1, 2, 3, 10, 27, 255, 256, 4095, 4096, 32767, 32768, 48903, 65534, 65535)
NUMBERS = [f for f in FIELDS if f.kind == "number" and f.lo is not None and f.hi is not None
           and not f.path.startswith(("analysis.", "sim.", "datasheet.", "board."))]
#: The board's chains drawn whole (a shunt with its gain, a divider's two resistors), so that the
#: draw reaches reports rather than "give one or the other".
BOARD_DRAWS = {"current.shunt_ohm": (1e-6, 10.0), "current.gain": (1e-3, 1e3),
               "bus.r_top_ohm": (1.0, 1e9), "bus.r_bottom_ohm": (1.0, 1e9),
               "pwm.clock_hz": (1e5, 1e10), "pwm.freq_hz": (10.0, 1e6), "pwm.deadtime_s": (1e-9, 1e-4)}


def _extreme(rng: random.Random) -> dict:
    inp = copy.deepcopy(SEED_INPUT)
    for f in rng.sample(NUMBERS, rng.randrange(1, 5)):
        lo, hi = max(f.lo, 1e-6), min(f.hi, 1e6)
        v = math.exp(rng.uniform(math.log(lo), math.log(hi))) if lo > 0 else rng.uniform(lo, hi)
        section, key = f.path.split(".", 1)
        inp.setdefault(section, {})[key] = v
    if rng.random() < 0.5:
        inp["raw"] = {k: rng.choice(UINT16_EDGES) if rng.random() < 0.5 else rng.randrange(65536)
                      for k in rng.sample(RAW_FIELDS, rng.randrange(1, 4))}
    if rng.random() < 0.3:
        inp["current_loop"] = {"method": rng.choice(["bandwidth", "damping"]),
                               "bandwidth_hz": 10 ** rng.uniform(0, 5),
                               "damping": 10 ** rng.uniform(-3, 2)}
    inp["sim"] = {"current": {"duration_s": 2e-3}, "pll": {"duration_s": 2e-3}}
    if rng.random() < 0.3:
        board: dict = {}
        for path, (lo, hi) in BOARD_DRAWS.items():
            section, key = path.split(".")
            board.setdefault(section, {})[key] = math.exp(rng.uniform(math.log(lo), math.log(hi)))
        inp["board"] = board
    if rng.random() < 0.4:
        inp["analysis"] = {}
        if rng.random() < 0.3:
            inp["analysis"]["fw"] = {"points": 5, "table_points": 4,
                                     "modulation": rng.choice(["svpwm", "spwm", 0.05, 1.0])}
    if rng.random() < 0.3:
        inp["profiles"] = {}
    return inp


def test_valid_extremes_give_a_report_or_one_input_error():
    rng = random.Random(20261129)
    seen = {"report": 0, "input error": 0}
    tracebacks = []
    for _ in range(CASES):
        inp = _extreme(rng)
        try:
            pulab.report(inp)
            seen["report"] += 1
        except InputError:
            seen["input error"] += 1
        except Exception as e:  # noqa: BLE001 - what the test is looking for
            tracebacks.append(f"{type(e).__name__}: {e} for {json.dumps(inp)}")
    print(f"\nvalid extremes: {CASES} inputs, {seen['report']} reports, "
          f"{seen['input error']} input errors, {len(tracebacks)} tracebacks")
    assert not tracebacks, "\n".join(tracebacks[:5])
    assert seen["report"] > CASES // 5  # the draw reaches valid reports, not only errors


# The seed's maxu wrap, found by an outside fuzzer: raw.Current 0, uDCFilter 48903.
def test_the_wrapped_maxu_reported_from_outside_runs():
    inp = {**copy.deepcopy(SEED_INPUT), "raw": {"Current": 0, "uDCFilter": 48903, "Voltage": 27},
           "sim": {"current": {"duration_s": 2e-3}}}
    r = pulab.report(inp)
    assert r["vendor"]["maxu"]["value"] == -(1 << 31)
    assert r["sim"]["current"]["metrics"]["fixed_wraps"] > 0


def _trace(code: str) -> tuple:
    saved = sys.stdin
    sys.stdin = io.TextIOWrapper(io.BytesIO(code.encode()), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = main(["trace", "-", "--entry", "f"])
    finally:
        sys.stdin = saved
    return status, out.getvalue(), err.getvalue()


BIG = "9" * 5000
HUGE_LITERALS = [
    (f"long f(void) {{ return {BIG}; }}", "1:23", "9999999999999999…99999999 (5000 characters)"),
    (f"long f(void) {{ return 0x{'f' * 5000}; }}", "1:23", "(5002 characters)"),
    (f"long f(void) {{ return 0{'7' * 5000}; }}", "1:23", "(5001 characters)"),
    (f"long f(void) {{ return {BIG}UL; }}", "1:23", "(5002 characters)"),
    (f"#define X {BIG}\nlong f(void) {{ return X; }}", "2:23", "(5000 characters)"),
    (f"#if {BIG}\nlong f(void) {{ return 1; }}\n#endif", "1:1", "intmax_t"),
    (f"#define GLOBAL_Q {BIG}\nlong f(void) {{ return 1; }}", "1:1", "GLOBAL_Q"),
    (f"long f(void) {{ return _IQ({BIG}); }}", "1:23", "inf"),
    ("long f(void) { return _IQ(1e400); }", "1:23", "inf"),
    (f"long f(void) {{ return 1.{BIG}e5; }}", "1:23", "(5004 characters)"),
    # the limits: the largest 64-bit values still convert
    ("long f(void) { return 18446744073709551616ULL > 0; }", "1:23", "too large"),
]


@pytest.mark.parametrize("code, where, shown", HUGE_LITERALS,
                         ids=[f"case{i}" for i in range(len(HUGE_LITERALS))])
def test_huge_literals_are_one_line_naming_line_and_column(code, where, shown):
    status, out, err = _trace(code)
    assert (status, out) == (2, ""), err
    line = err[:-1]
    assert err.endswith("\n") and "\n" not in line and len(line) < 400, err[:500]
    assert line.startswith(f"error: code: {where}: ") and shown in line, line


def test_the_largest_64_bit_literals_still_trace():
    status, out, err = _trace("unsigned long long f(void) { return 18446744073709551615ULL - "
                              "0xFFFFFFFFFFFFFFFFULL + 0000000000000000000000001777777777777777777777ULL; }")
    assert status == 0, err
    assert json.loads(out)["vars"]["return"]["value"] == (1 << 64) - 1
