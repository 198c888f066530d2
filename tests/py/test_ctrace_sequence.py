"""Sequences: the entry called every control period with the firmware's memory kept.

Three routines written for these tests in the shapes public motor-control firmware gives
them — a PI with integral clamping and back-calculation on a handle passed by pointer, a
speed ramp with a ``static`` delay counter and a global tick count, a Q15 first-order
filter on a file-scope accumulator — run 1,000 calls with per-call inputs from a table
(sparse rows: a cell left out keeps the carried value) and are compared, after every call,
with the same routine compiled by gcc -m32 and avr-gcc + simavr and called the same way
by a C loop (tests/py/ctrace_compilers.py ``run_calls``).
"""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys

import pytest

from conftest import ROOT
from ctrace_compilers import Unit, require, run_calls
from pulab.api import call_json
from pulab.ctrace import TraceError, compile_code, trace
from pulab.ctrace.sequence import read_table, run_sequence, trace_sequence

PI = r"""
#include <stdint.h>
typedef struct {
  int16_t kp, ki;            /* gains, scaled by 2^kp_shift and 2^ki_shift */
  uint16_t kp_shift, ki_shift;
  int32_t integ;             /* the integrator, kept between periods */
  int32_t integ_hi, integ_lo;
  int16_t out_hi, out_lo;
} PiCtl;

int16_t pi_step(PiCtl *c, int32_t err)
{
  int32_t p = c->kp * err;
  int32_t i = c->ki * err;
  int32_t sum = c->integ + i;
  int32_t out, back = 0;
  /* the sum wrapped: keep the sign the two terms agreed on */
  if (sum < 0 && c->integ > 0 && i > 0) sum = INT32_MAX;
  else if (sum > 0 && c->integ < 0 && i < 0) sum = -INT32_MAX;
  if (sum > c->integ_hi) sum = c->integ_hi;
  else if (sum < c->integ_lo) sum = c->integ_lo;
  c->integ = sum;
  out = (p >> c->kp_shift) + (c->integ >> c->ki_shift);
  if (out > c->out_hi) { back = c->out_hi - out; out = c->out_hi; }
  else if (out < c->out_lo) { back = c->out_lo - out; out = c->out_lo; }
  c->integ += back;          /* back-calculation: the integrator gives up what was clipped */
  return (int16_t)out;
}
"""

RAMP = r"""
#include <stdint.h>
typedef struct { int32_t target; int32_t out; int32_t step; uint16_t every; uint8_t done; } Ramp;
uint16_t ramp_ticks;

void ramp_run(Ramp *r)
{
  static uint16_t wait;
  ramp_ticks++;
  if (++wait < r->every) return;
  wait = 0;
  if (r->target - r->out > r->step) { r->out += r->step; r->done = 0; }
  else if (r->out - r->target > r->step) { r->out -= r->step; r->done = 0; }
  else { r->out = r->target; r->done = 1; }
}
"""

LPF = r"""
#include <stdint.h>
static int32_t lpf_acc = 0;  /* Q15 state * 2^15 */

int16_t lpf_q15(int16_t x, int16_t alpha)
{
  int16_t y = (int16_t)(lpf_acc >> 15);
  lpf_acc += (int32_t)alpha * (int16_t)(x - y);
  return (int16_t)(lpf_acc >> 15);
}
"""

CALLS = 1000


def _compare(code, entry, params, inputs, outputs, rows, target):
    """Trace ``rows`` as a sequence and run them through the compiled loop; every output
    after every call must agree.  ``inputs`` (spelling, tracer name) are the table's
    columns; a tracer name is the C driver's name with the parameter's pointer made a
    field path (``c.kp``), as ``run_calls`` names them."""
    checked = compile_code(code, target, entry=entry)
    traced = run_sequence(checked, len(rows), rows)
    got = run_calls(Unit(code, entry, params, inputs, outputs), rows, target)
    assert len(got) == len(traced["calls"]) == len(rows)
    for k, (call, g) in enumerate(zip(traced["calls"], got)):
        mine = {n: (call["return"]["value"] if n == "return" else call["vars"][n]["value"])
                for _, n in outputs}
        assert mine == g, f"call {k}: tracer {mine} vs compiler {g}"
    return traced


def _pi_rows(rng: random.Random, n: int) -> list:
    rows = [{"c.kp": 300, "c.ki": 40, "c.kp_shift": 8, "c.ki_shift": 10, "c.integ": 0,
             "c.integ_hi": 20_000_000, "c.integ_lo": -20_000_000, "c.out_hi": 30000,
             "c.out_lo": -30000, "err": 0}]
    for k in range(1, n):
        row = {}
        r = rng.random()
        if r < 0.8:  # a new error this period (else the caller passes the last one again)
            row["err"] = rng.choice([rng.randrange(-2000, 2000), rng.randrange(-60000, 60000),
                                     70000, -70000, 0])
        if r > 0.97:  # gains retuned on the fly
            row["c.ki"] = rng.randrange(0, 400)
        if r > 0.995:
            row["c.integ"] = rng.randrange(-1000, 1000)
        rows.append(row)
    return rows


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_pi_over_1000_periods_matches_the_compiler(target, capsys):
    require(target, capsys)
    rows = _pi_rows(random.Random(f"pi-{target}"), CALLS)
    names = ["c.kp", "c.ki", "c.kp_shift", "c.ki_shift", "c.integ", "c.integ_hi", "c.integ_lo",
             "c.out_hi", "c.out_lo", "err"]
    spell = {"c.kp_shift": "uint16_t", "c.ki_shift": "uint16_t", "c.integ": "int32_t",
             "c.integ_hi": "int32_t", "c.integ_lo": "int32_t", "err": "int32_t"}
    traced = _compare(PI, "pi_step", [("PiCtl *", "c"), ("int32_t", "err")],
                      [(spell.get(n, "int16_t"), n) for n in names],
                      [("int16_t", "return"), ("int32_t", "c.integ")], rows, target)
    # the loop saturated (the clamp is the code's own, not an intrinsic) and wound back
    outs = [c["return"]["value"] for c in traced["calls"]]
    assert 30000 in outs and -30000 in outs


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_ramp_with_a_static_counter_matches_the_compiler(target, capsys):
    require(target, capsys)
    rng = random.Random(f"ramp-{target}")
    rows = [{"r.target": 0, "r.out": 0, "r.step": 37, "r.every": 3, "r.done": 0,
             "ramp_ticks": 65530}]
    for k in range(1, CALLS):
        rows.append({"r.target": rng.randrange(-100000, 100000)} if rng.random() < 0.01 else
                    {"r.every": rng.randrange(1, 5)} if rng.random() < 0.005 else {})
    code_inputs = [("int32_t", "r.target"), ("int32_t", "r.out"), ("int32_t", "r.step"),
                   ("uint16_t", "r.every"), ("uint8_t", "r.done"), ("uint16_t", "ramp_ticks")]
    traced = _compare(RAMP, "ramp_run", [("Ramp *", "r")], code_inputs,
                      [("int32_t", "r.out"), ("uint8_t", "r.done"), ("uint16_t", "ramp_ticks")],
                      rows, target)
    # the global tick count wrapped at call 5: the first event (16-bit unsigned int arithmetic
    # on avr; on arm ramp_ticks promotes to int, and the store back converts)
    assert traced["first_event"] == {"call": 5, "line": 9, "name": "ramp_ticks",
                                     "kind": "unsigned_wrap" if target == "avr" else "conversion"}
    assert any(c["vars"]["r.done"]["value"] == 1 for c in traced["calls"])


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_q15_filter_on_a_file_scope_state_matches_the_compiler(target, capsys):
    require(target, capsys)
    rng = random.Random(f"lpf-{target}")
    rows = [{"x": 0, "alpha": 3000}]
    for k in range(1, CALLS):
        step = 32767 if (k // 150) % 2 else -32768
        rows.append({"x": step + rng.randrange(-200, 200) if abs(step) < 32700 else
                     max(-32768, min(32767, step + rng.randrange(-200, 200)))}
                    if rng.random() < 0.9 else {"alpha": rng.randrange(100, 20000)})
    traced = _compare(LPF, "lpf_q15", [("int16_t", "x"), ("int16_t", "alpha")],
                      [("int16_t", "x"), ("int16_t", "alpha")],
                      [("int16_t", "return"), ("int32_t", "lpf_acc")], rows, target)
    # x - y leaves 16 bits when a full-scale step reverses: the first event is that wrap
    e = traced["first_event"]
    assert e is not None and e["line"] == 8 and e["name"] == "lpf_acc"


def test_state_is_carried_and_by_value_parameters_are_the_callers_copy():
    code = ("int total; int f(int e) { static int n; n++; e = e * 2; total += e; "
            "return n; }")
    r = trace_sequence(code, "c28x", 4, [{"e": 1}, {}, {"e": 10, "total": 0}, {}],
                       {"total": 100}, entry="f")
    assert [c["return"]["value"] for c in r["calls"]] == [1, 2, 3, 4]  # static n counts
    # e doubled inside the call; the caller passes its own 1 again (C passes by value)
    assert [c["vars"]["total"]["value"] for c in r["calls"]] == [102, 104, 20, 40]
    assert [c["vars"]["e"]["input"] for c in r["calls"]] == [True, True, True, True]
    assert r["first_event"] is None
    assert [c["flags"] for c in r["calls"]] == [[], [], [], []]


def test_first_event_is_the_first_clamp_wrap_or_overflow():
    code = ("long f(long x) { long y = _IQsat(x, 100, -100); Uint16 u = x; return y + u; }")
    r = trace_sequence(code, "c28x", 3, [{"x": 5}, {"x": 70000}, {"x": 200}], entry="f")
    assert r["first_event"] == {"call": 1, "line": 1, "kind": "saturate", "name": "y"}
    assert r["calls"][1]["flags"] == ["conversion", "saturate"]
    assert r["calls"][2]["flags"] == ["saturate"]


@pytest.mark.parametrize("calls,table,code,text", [
    (3, [{}, {}], "trace_table_rows", "the input table has 2 rows for 3 calls"),
    (0, None, "integer_range", None),
    (2, [{"e": 1}, {"nope": 2}], "trace_table_cell", "the row of call 1: "),
    (2, [{"e": 1}, {"e": 40000}], "trace_table_cell", "the row of call 1: "),
])
def test_bad_sequences_are_refused(calls, table, code, text):
    with pytest.raises(TraceError) as e:
        trace_sequence("int f(int e) { return e; }", "c28x", calls, table, entry="f")
    assert e.value.code == code
    if text:
        assert e.value.message.startswith(text)
    with pytest.raises(TraceError) as e:
        trace_sequence("int x = 1;", "c28x", 2)
    assert e.value.code == "trace_calls_entry"


def test_a_sequence_has_a_statement_budget(monkeypatch):
    import pulab.ctrace.sequence as sequence
    monkeypatch.setattr(sequence, "MAX_SEQUENCE_STEPS", 50)
    code = "int f(int n) { int k, s = 0; for (k = 0; k < n; k++) s += k; return s; }"
    assert len(trace_sequence(code, "c28x", 2, None, {"n": 10}, entry="f")["calls"]) == 2
    with pytest.raises(TraceError) as e:
        trace_sequence(code, "c28x", 3, None, {"n": 10}, entry="f")
    assert e.value.field == "calls" and e.value.message.startswith(
        "call 2 reaches 50 statements executed over the sequence")


def test_a_run_time_error_names_its_call():
    with pytest.raises(TraceError) as e:
        trace_sequence("int f(int d) { return 100 / d; }", "c28x", 3,
                       [{"d": 5}, {"d": 0}, {"d": 1}], entry="f")
    assert e.value.message == "1:29: in call 1: division by zero"


def test_tables_read_csv_and_json_lines():
    assert read_table("err,c.kp\r\n5,0x10\r\n,\r\n-3,\n", "csv") == \
        [{"err": "5", "c.kp": "0x10"}, {}, {"err": "-3"}]
    assert read_table('{"err": 5}\r\n{"c.kp": "0x10", "err": null}\n', "jsonl") == \
        [{"err": 5}, {"c.kp": "0x10"}]
    for text, kind in (("", "csv"), ("a,,b\n1,2,3\n", "csv"), ("a\n1,2\n", "csv"),
                       ("[1]\n", "jsonl"), ("{\n", "jsonl")):
        with pytest.raises(Exception) as e:
            read_table(text, kind)
        assert e.value.code.startswith("trace_table")


def _cli(args, **kw):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "py"))
    return subprocess.run([sys.executable, "-m", "pulab", "trace", *args], capture_output=True,
                          text=True, env=env, **kw)


def test_the_cli_runs_a_table(tmp_path):
    src = tmp_path / "pi.c"
    src.write_text(PI)
    table = tmp_path / "errs.csv"
    table.write_bytes(b"err,c.ki\r\n100,\r\n,0x50\r\n-100,\r\n")
    sets = ["--set", "c.kp=300", "--set", "c.ki=40", "--set", "c.kp_shift=8", "--set",
            "c.ki_shift=10", "--set", "c.integ=0", "--set", "c.integ_hi=1000000", "--set",
            "c.integ_lo=-1000000", "--set", "c.out_hi=200", "--set", "c.out_lo=-200"]
    p = _cli([str(src), "--target", "arm", "--entry", "pi_step", "--inputs", str(table), *sets])
    assert p.returncode == 0, p.stderr
    r = json.loads(p.stdout)
    # err 100: p = 30000 >> 8 = 117, integ 4000 >> 10 = 3 → 120; then ki = 80 with err kept:
    # integ 12000 >> 10 = 11 → 128; err -100: -30000 >> 8 = -118 (floor), 4000 >> 10 = 3
    assert [c["return"]["value"] for c in r["calls"]] == [120, 128, -115]
    assert [c["vars"]["c.integ"]["value"] for c in r["calls"]] == [4000, 12000, 4000]
    assert r["first_event"] is None
    jl = tmp_path / "errs.jsonl"
    jl.write_text('{"err": 100}\n{"c.ki": "0x50"}\n{"err": -100}\n')
    p2 = _cli([str(src), "--target", "arm", "--entry", "pi_step", "--inputs", str(jl),
               "--calls", "3", *sets])
    assert json.loads(p2.stdout)["calls"] == r["calls"]
    p3 = _cli([str(src), "--target", "arm", "--entry", "pi_step", "--inputs", str(jl),
               "--calls", "4", *sets])
    assert p3.returncode == 2 and p3.stderr == "error: inputs: the input table has 3 rows " \
                                               "for 4 calls\n"
    p4 = _cli([str(src), "--target", "arm", "--entry", "pi_step", "--calls", "2", "--set",
               "err=5", *sets, "--format", "text"])
    # 300 * 5 >> 8 = 5; the integrator's 200 and 400 are 0 after >> 10
    assert p4.returncode == 0 and p4.stdout.splitlines()[1:] == [
        "call 0  return 5 (0x0005)  truncation", "call 1  return 5 (0x0005)  truncation",
        "first event: none"]


def test_the_api_runs_a_sequence():
    r = json.loads(call_json("trace", json.dumps({
        "code": "int a; int f(int e) { a += e; return a; }", "target": "c28x", "entry": "f",
        "set": {"a": 0}, "table": [{"e": 30000}, {"e": 30000}]})))
    assert r["ok"] and [c["return"]["value"] for c in r["calls"]] == [30000, -5536]
    assert r["first_event"] == {"call": 1, "line": 1, "kind": "signed_overflow", "name": "a"}


def _recorded(steps: list, flags: set, found: list) -> None:
    """The flags and first event read off a recorded trace: steps in order, a call's inner
    steps before the call term's own flags."""
    kinds = ("signed_overflow", "unsigned_wrap", "conversion", "saturate")
    for s in steps:
        for t in s["terms"]:
            if "steps" in t:
                _recorded(t["steps"], flags, found)
            hit = [f for f in t["flags"] if f in kinds]
            if hit and not found:
                found.append((t["line"], hit[0], s["var"] or t["expr"]))
        flags.update(s["flags"])
        hit = [f for f in s["flags"] if f in kinds]
        if hit and not found:
            found.append((s["line"], hit[0], s["var"] or s["code"]))


@pytest.mark.parametrize("target", ["c28x", "arm"])
def test_a_sequence_sees_the_flags_and_event_a_recorded_trace_shows(target):
    from pulab.benchmark import TRACE_UNIT
    rng = random.Random(f"watch-{target}")
    code = TRACE_UNIT + PI.replace("#include <stdint.h>", "")
    events = 0
    for _ in range(150):
        inputs = {"ia": rng.randrange(-32768, 32768), "ib": rng.randrange(-32768, 32768),
                  "angle": rng.randrange(0, 65536), "id_ref": rng.randrange(-32768, 32768),
                  "iq_ref": rng.randrange(-32768, 32768),
                  **{f"{p}.{k}": v for p in ("pid", "piq") for k, v in (
                      ("kp", rng.randrange(-32768, 32768)), ("ki", rng.randrange(-32768, 32768)),
                      ("integral", rng.randrange(-1 << 31, 1 << 31)),
                      ("upper", rng.randrange(0, 1 << 31)), ("lower", -rng.randrange(0, 1 << 31)),
                      ("kp_shift", rng.randrange(0, 16)), ("ki_shift", rng.randrange(0, 16)))}}
        r = trace(code, target, inputs, entry="current_loop")
        flags, found = set(), []
        _recorded(r["steps"], flags, found)
        s = trace_sequence(code, target, 1, None, inputs, entry="current_loop")
        assert set(s["calls"][0]["flags"]) == flags
        e = s["first_event"]
        assert (None if e is None else (e["line"], e["kind"], e["name"])) == \
            (found[0] if found else None)
        assert s["calls"][0]["vars"] == r["vars"]
        events += bool(found)
    assert events > 50


def test_a_static_local_of_a_helper_keeps_its_value_between_its_calls():
    code = ("static int tick(void) { static int n = 10; int t = 1; n += t; return n; }\n"
            "static int down(void) { static int z; z--; return z; }\n"
            "int f(void) { return tick() + tick(); }\nint g(void) { return down() * 10; }")
    # within one trace: 11 + 12 (its initializer runs once, C99 6.2.4p3)
    assert trace(code, "c28x", entry="f")["vars"]["return"]["value"] == 23
    r = trace_sequence(code, "c28x", 3, entry="f")
    assert [c["return"]["value"] for c in r["calls"]] == [23, 27, 31]
    # z without an initializer starts at 0 (static storage)
    r = trace_sequence(code, "c28x", 3, entry="g")
    assert [c["return"]["value"] for c in r["calls"]] == [-10, -20, -30]


def test_fuzzed_sequence_requests_give_only_error_replies():
    from conftest import chinese
    rng = random.Random(12)
    values = [None, True, 0, -1, 3, 2**70, 1.5, "", "f", "2", "0x10", [], {}, [1], [{}],
              [{"e": 1}, {"e": "x"}], [{"e": 1}, None], [{"a": 1}, {"e": 40000}],
              {"e": 1}, "int a; int f(int e) { a += e; return a; }"]
    for _ in range(1500):
        req = {k: rng.choice(values) for k in rng.sample(
            ["code", "target", "set", "entry", "calls", "table", "undefine", "zero_unset"],
            rng.randrange(0, 8))}
        req.setdefault("code", "int a; int f(int e) { a += e; return a; }")
        req.setdefault("calls" if rng.random() < 0.5 else "table", rng.choice(values))
        if rng.random() < 0.5:
            req["entry"] = "f"
        r = json.loads(call_json("trace", json.dumps(req)))
        assert r["ok"] is True or (r["field"] and chinese(r["message_zh"])), (req, r)
