"""pulab.ctrace on whole translation units: functions, structs, pointers, arrays, loops.

The routines here are written for these tests in the shapes real motor-control code takes
(a PI handle passed by pointer with its integrator written in one branch, Clarke/Park with
out-parameters and a helper function, a FIR over a global ring buffer and a const table, an
integer square root with while loops).  Hand-worked cases pin the semantics; the compiler
cross-check runs the same units through gcc -m32 and avr-gcc + simavr
(tests/py/ctrace_compilers.py, which never imports pulab) and requires every output equal.
"""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys

import pytest

from conftest import ROOT, chinese
from ctrace_compilers import Unit, require, run_unit
from ctrace_gen import random_vector
from pulab.api import call_json
from pulab.ctrace import TraceError, compile_code, run_checked, trace
from pulab.schema.errors import InputError

PI = r"""
#include <stdint.h>
typedef struct
{
  int16_t kp_gain;
  int16_t ki_gain;
  int32_t integral;
  int32_t upper_integral, lower_integral;
  int16_t upper_out;
  int16_t lower_out;
  uint16_t kp_shift;
  uint16_t ki_shift;
} PiState;

static inline int32_t clamp32(int32_t v, int32_t lo, int32_t hi)
{
  return v < lo ? lo : (v > hi ? hi : v);
}

__attribute__((noinline)) int16_t pi_step(PiState *s, int16_t err)
{
  int32_t p_term, i_term, out;
  p_term = (int32_t)s->kp_gain * err;
  i_term = (int32_t)(*s).ki_gain * err;
  if (i_term != 0)
  {
    s->integral = clamp32(s->integral + i_term, s->lower_integral, s->upper_integral);
  }
  out = (p_term >> s->kp_shift) + (s->integral >> s->ki_shift);
  if (out > s->upper_out) out = s->upper_out;
  else if (out < s->lower_out) out = s->lower_out;
  return (int16_t)out;
}
"""

PARK = r"""
#include <stdint.h>
typedef struct { int16_t a; int16_t b; } ab_t;
typedef struct dq_tag { int16_t d, q; } dq_t;
#define ONE_BY_SQRT3_Q15 18919

static void clarke(int16_t ia, int16_t ib, ab_t *out)
{
  int32_t t;
  out->a = ia;
  t = ((int32_t)ia + 2 * (int32_t)ib) * ONE_BY_SQRT3_Q15;
  out->b = (int16_t)(t >> 15);
}

void park(int16_t ia, int16_t ib, int16_t sin_q15, int16_t cos_q15, struct dq_tag *dq,
          int16_t *mag_sq)
{
  ab_t ab;
  clarke(ia, ib, &ab);
  dq->d = (int16_t)(((int32_t)ab.a * cos_q15 + (int32_t)ab.b * sin_q15) >> 15);
  dq->q = (int16_t)(((int32_t)ab.b * cos_q15 - (int32_t)ab.a * sin_q15) >> 15);
  *mag_sq = (int16_t)(((int32_t)dq->d * dq->d + (int32_t)dq->q * dq->q) >> 16);
}
"""

FIR = r"""
#include <stdint.h>
#define TAPS 5
static const int16_t coeff[TAPS] = {2048, 8192, 12288, 8192, 2048};
int16_t history[TAPS];
uint16_t head;

int16_t fir_push(int16_t x)
{
  int32_t acc = 0;
  uint16_t k, idx;
  history[head] = x;
  idx = head;
  for (k = 0; k < TAPS; k++)
  {
    acc += (int32_t)coeff[k] * history[idx];
    if (idx == 0) idx = TAPS - 1; else idx--;
  }
  head = (uint16_t)(head + 1 == TAPS ? 0 : head + 1);
  return (int16_t)(acc >> 15);
}
"""

SVM = r"""
#include <stdint.h>
typedef struct { int16_t alpha, beta; uint16_t ta, tb, tc; uint8_t sector; } svm_t;
#define SQRT3_BY_2_Q15 28378

void svm(svm_t *s)
{
  int32_t x = s->beta;
  int32_t y = (((int32_t)SQRT3_BY_2_Q15 * s->alpha) >> 15) - (x >> 1);
  int32_t z = -(((int32_t)SQRT3_BY_2_Q15 * s->alpha) >> 15) - (x >> 1);
  uint8_t sec = 0;
  if (x > 0) sec |= 1;
  if (y > 0) sec |= 2;
  if (z > 0) sec |= 4;
  s->sector = sec;
  switch (sec)
  {
    case 3:
      s->ta = (uint16_t)(16384 + (y >> 1));
      s->tb = (uint16_t)(16384 + (x >> 1));
      break;
    case 1:
    case 5:
      s->ta = (uint16_t)(16384 - (z >> 1));
      s->tb = (uint16_t)_IQabs(x);
      break;
    case 6:
      s->tc = 1;
    default:
      s->ta = s->tb = s->tc = 16384;
  }
}
"""

BYVALUE = r"""
#include <stdint.h>
typedef struct { int16_t a; int16_t b; } phase_t;
typedef struct { int16_t alpha; int16_t beta; } albe_t;

static albe_t to_albe(phase_t in)
{
  albe_t out;
  int32_t t = ((int32_t)in.a + 2 * (int32_t)in.b) * 18919;
  out.alpha = in.a;
  out.beta = (int16_t)(t >> 15);
  return out;
}

albe_t scaled(phase_t x, int16_t gain_q12)
{
  albe_t r = to_albe(x);
  r.alpha = (int16_t)(((int32_t)r.alpha * gain_q12) >> 12);
  r.beta = (int16_t)(((int32_t)r.beta * gain_q12) / 4096);
  return r;
}
"""

HANDLE = r"""
#include <stdint.h>
typedef struct _Lim_ { int32_t gain; int32_t state; int32_t hi; int32_t lo; } Lim;
typedef struct _Lim_ *LimHandle;
typedef struct { int32_t gain; int32_t state; int32_t hi; int32_t lo; } LimView;

static inline int32_t lim_run(LimHandle handle, const int32_t x)
{
  Lim *obj = (Lim *)handle;
  void *raw = (void *)obj;
  const LimView *view = (const LimView *)raw;
  int32_t y = (int32_t)(((int64_t)obj->gain * x) >> 12) + view->state;
  obj->state = y >> 4;
  return y > obj->hi ? obj->hi : (y < obj->lo ? obj->lo : y);
}

int32_t lim_step(Lim *lim, int32_t x)
{
  return lim_run((LimHandle)lim, x);
}
"""

ISQRT = r"""
#include <stdint.h>
uint16_t isqrt32(uint32_t v)
{
  uint32_t res = 0;
  uint32_t bit = (uint32_t)1 << 30;
  while (bit > v) bit >>= 2;
  do {
    if (bit == 0) break;
    if (v >= res + bit) { v -= res + bit; res = (res >> 1) + bit; }
    else res >>= 1;
    bit >>= 2;
  } while (1);
  return (uint16_t)res;
}
"""


def test_pi_through_a_pointer_with_a_helper():
    sets = {"err": 100, "s.kp_gain": 300, "s->ki_gain": 20, "s.integral": 1000,
            "s.upper_integral": 2000, "s.lower_integral": -2000, "s.upper_out": 500,
            "s.lower_out": -500, "s.kp_shift": 4, "s.ki_shift": 2}
    r = trace(PI, "c28x", sets, entry="pi_step")
    v = r["vars"]
    # i_term = 2000; the integral 1000 + 2000 = 3000 clamps to 2000;
    # out = (300·100 >> 4) + (2000 >> 2) = 1875 + 500 = 2375 → clamped to 500
    assert (v["s.integral"]["value"], v["return"]["value"]) == (2000, 500)
    assert v["s.ki_gain"]["input"] and v["return"]["type"] == "int16_t"
    # the integrator state is an input although it is written only inside the if
    assert r["inputs"] == ["err", "s.kp_gain", "s.ki_gain", "s.integral", "s.lower_integral",
                           "s.upper_integral", "s.kp_shift", "s.ki_shift", "s.upper_out",
                           "s.lower_out"]
    call = next(t for s in r["steps"] for t in s["terms"] if t.get("call") == "clamp32")
    assert call["value"] == 2000 and call["steps"][-1]["var"] == "return"


def test_integrator_written_in_one_branch_and_read_on_another_path_is_an_input():
    code = ("int32_t integ;\nint16_t step(int16_t e, int16_t run) {\n"
            "  if (run) integ = integ + e; else integ = 0;\n  return (int16_t)integ; }\n"
            "int16_t other(int16_t e) { if (e > 0) integ = e; return (int16_t)integ; }")
    assert compile_code(code, "arm", entry="step").inputs == ["e", "run", "integ"]
    # written on every path before the read: not an input
    assert compile_code(code.replace("integ + e", "e"), "arm", entry="step").inputs == \
        ["e", "run"]
    # written on one path, read after the if: an input
    assert compile_code(code, "arm", entry="other").inputs == ["e", "integ"]


def test_out_parameters_and_local_structs():
    r = trace(PARK, "avr", {"ia": 1000, "ib": -500, "sin_q15": 0, "cos_q15": 32767},
              entry="park")
    v = r["vars"]
    # beta = (1000 - 1000)·18919 >> 15 = 0; d = 1000·32767 >> 15 = 999 (floor), q = 0
    assert (v["ab.a"]["value"], v["ab.b"]["value"]) == (1000, 0)
    assert (v["dq.d"]["value"], v["dq.q"]["value"], v["*mag_sq"]["value"]) == (999, 0, 15)
    assert "return" not in v and r["inputs"] == ["ia", "ib", "sin_q15", "cos_q15"]
    # the call's statements are under the call, with the caller's object names
    call = r["steps"][4]["terms"][0]
    assert call["call"] == "clarke" and [s["var"] for s in call["steps"]] == \
        ["ab.a", "clarke:t", "ab.b"]


def test_loops_tables_and_globals():
    sets = {"x": 1000, "head": 4, **{f"history[{i}]": 100 * i for i in range(5)}}
    r = trace(FIR, "arm", sets, entry="fir_push")
    v = r["vars"]
    # history = [0, 100, 200, 300, 1000]; taps from idx 4 down: 2048·1000 + 8192·300 +
    # 12288·200 + 8192·100 + 2048·0 = 7782400; >> 15 = 237 (floor of 237.5)
    assert v["return"]["value"] == 237 and v["head"]["value"] == 0
    assert v["history[4]"]["value"] == 1000
    loops = [s["branch"] for s in r["steps"] if s.get("branch") in ("loop", "exit")]
    assert loops == ["loop"] * 5 + ["exit"]
    assert trace(ISQRT, "avr", {"v": 4000000000}, entry="isqrt32")["vars"]["return"][
        "value"] == 63245  # floor(sqrt(4e9)) = 63245.55…


def test_structs_by_value_in_and_out():
    r = trace(BYVALUE, "avr", {"x.a": -1000, "x.b": 0, "gain_q12": 3000}, entry="scaled")
    v = r["vars"]
    # beta = -1000·18919 >> 15 = -578 (floor of -577.36); alpha·3000 >> 12 = floor(-732.42)
    # = -733, beta·3000 / 4096 = trunc(-423.34) = -423: the same scaling rounds two ways
    assert (v["return.alpha"]["value"], v["return.beta"]["value"]) == (-733, -423)
    rounding = r["rounding"]
    assert rounding["r.alpha"] == {"floor": 1, "toward_zero": 0, "max_lost": 2368 / 4096}
    assert rounding["r.beta"] == {"floor": 0, "toward_zero": 1, "max_lost": 1392 / 4096}
    assert rounding["to_albe:out.beta"]["floor"] == 1  # inside the call


def test_switch_falls_through_to_the_next_label():
    r = trace(SVM, "arm", {"s.alpha": 0, "s.beta": -100}, entry="svm")
    v = r["vars"]
    # x = -100, y = 50, z = 50: sector 6 sets tc = 1, then falls into default: all 16384
    assert v["s.sector"]["value"] == 6 and [v[f"s.t{c}"]["value"] for c in "abc"] == [16384] * 3
    assert next(s for s in r["steps"] if s["code"].startswith("switch"))["branch"] == "case 6"
    r = trace(SVM, "arm", {"s.alpha": 0, "s.beta": 100}, entry="svm")
    # x = 100, y = z = -50: sector 1 shares case 5's statements; _IQabs(100) = 100
    assert (r["vars"]["s.ta"]["value"], r["vars"]["s.tb"]["value"]) == (16409, 100)
    assert "s.tc" not in r["vars"]  # never written, never read


def test_unset_inputs_error_names_them_or_read_as_zero():
    with pytest.raises(InputError) as e:
        trace(PI, "arm", {"err": 1}, entry="pi_step")
    assert e.value.field == "set.s.kp_gain" and "s.ki_gain" in e.value.reason
    assert chinese(e.value.message_zh)
    r = trace(PI, "arm", {"err": 1, "s.ki_gain": 4}, entry="pi_step", zero_unset=True)
    assert r["vars"]["s.integral"]["value"] == 0 and r["vars"]["s.kp_gain"]["input"]


@pytest.mark.parametrize("code,entry,sets,field,text", [
    (PI, "nope", {}, "entry", "no function nope in the code (functions: clamp32, pi_step)"),
    (PI, None, {}, "entry", "choose the function to run (functions: clamp32, pi_step)"),
    ("int f(int x) { return f(x); }", "f", {"x": 1}, "code", "f() calls itself"),
    ("int f(int x) { if (x) return 1; }", "f", {"x": 0}, "code", "f() ends without 'return'"),
    ("int t[3]; int f(int i) { return t[i]; }", "f", {"i": 3}, "code",
     "index 3 is outside t[0..2]"),
    ("int f(int x) { while (x) { x = 1; } return x; }", "f", {"x": 1}, "code",
     "more than 10000 statements executed"),
    ("struct s; int f(struct s *p) { return 0; }", "f", {}, "code",
     "p is a handle to an object of unknown type: the entry casts it to none"),
    ("struct s; int f(struct s x) { return 0; }", "f", {}, "code",
     "struct s is declared but its fields are not pasted"),
    ("typedef struct { int a; } S; int f(S *p) { return p->b; }", "f", {}, "code",
     "struct S has no field b"),
    ("int f(int x) { return g(x); }", "f", {"x": 1}, "code", "unknown function g()"),
    ("int f(int x) { int y; return y; }", "f", {"x": 1}, "code",
     "y is read before it has a value"),
    ("int f(int x) { return x; }", "f", {"q": 1}, "set.q", "no variable q is declared"),
    ("#include <stdint.h>\nint16_t f(int32_t *p) {\n  return *(int16_t *)p; }", "f", {}, "code",
     "3:11: (int16_t *)p would read int * as short *"),
    ("typedef struct { int a; } A; typedef struct { int b; } B;\n"
     "int f(A *p) { void *v = p; B *q = (B *)v; return q->b; }", "f", {}, "code",
     "2:35: (B *)v would read struct A * as struct B * (a different memory layout"),
    ("int f(int x) { return *(int *)x; }", "f", {}, "code",
     "(int *)x: a pointer cast needs a pointer, not int"),
])
def test_errors_name_the_construct(code, entry, sets, field, text):
    with pytest.raises(InputError) as e:
        trace(code, "arm", sets, entry=entry, zero_unset=True)
    assert e.value.field == field and text in e.value.message, e.value.message
    assert chinese(e.value.message_zh) and isinstance(e.value, TraceError)
    if field == "code":  # the code at fault: the error says where
        assert e.value.line >= 1 and e.value.column >= 1
    elif field == "entry":  # the code's functions come with it, to choose one
        assert e.value.line is None and e.value.functions == ["clamp32", "pi_step"]
    else:  # a bad input value: the code compiled, its inputs come with it
        assert e.value.line is None and e.value.inputs == ["x"]


def test_api_offers_the_functions_and_takes_entry():
    r = json.loads(call_json("trace", json.dumps({"code": PI})))
    assert r["ok"] is False and r["field"] == "entry" and r["functions"] == ["clamp32",
                                                                             "pi_step"]
    r = json.loads(call_json("trace", json.dumps({"code": PARK, "entry": "park", "target": "arm",
                                          "set": {"ia": 1, "ib": 2}, "zero_unset": True})))
    assert r["ok"] and r["entry"] == "park" and r["vars"]["dq.d"]["value"] == 0


def test_cli_entry_and_text_shows_calls_nested(tmp_path):
    f = tmp_path / "park.c"
    f.write_text(PARK)
    cmd = [sys.executable, "-m", "pulab", "trace", str(f), "--target", "arm", "--entry", "park",
           "--set", "ia=1000", "--set", "ib=-500", "--zero-unset", "--format", "text"]
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT,
                       env={**os.environ, "PYTHONPATH": str(ROOT / "py")})
    assert p.returncode == 0, p.stderr
    lines = p.stdout.splitlines()
    assert lines[0].startswith("target arm, GLOBAL_Q 24; entry park; inputs: ia, ib")
    at = next(i for i, l in enumerate(lines) if l.strip().startswith("call clarke()"))
    assert lines[at + 1].startswith("    ") and "ab.a = 1000" in lines[at + 1]
    p = subprocess.run(cmd[:-3], capture_output=True, text=True, cwd=ROOT,
                       env={**os.environ, "PYTHONPATH": str(ROOT / "py")})
    # the first unset input read is the field; the message names every unset input
    assert p.returncode == 2 and p.stderr.startswith("error: set.cos_q15: 20:38: ")
    assert "(unset inputs: sin_q15, cos_q15;" in p.stderr
    assert len(p.stderr.strip().splitlines()) == 1


UNITS = {
    "pi": (Unit(PI, "pi_step", [("PiState *", "s"), ("int16_t", "err")],
                [("int16_t", "err"), ("int16_t", "s.kp_gain"), ("int16_t", "s.ki_gain"),
                 ("int32_t", "s.integral"), ("int32_t", "s.upper_integral"),
                 ("int32_t", "s.lower_integral"), ("int16_t", "s.upper_out"),
                 ("int16_t", "s.lower_out"), ("uint16_t", "s.kp_shift"),
                 ("uint16_t", "s.ki_shift")],
                [("int16_t", "return"), ("int32_t", "s.integral")]),
           {"s.kp_shift": (0, 15), "s.ki_shift": (0, 31)}),
    "park": (Unit(PARK, "park", [("int16_t", "ia"), ("int16_t", "ib"), ("int16_t", "sin_q15"),
                                 ("int16_t", "cos_q15"), ("struct dq_tag *", "dq"),
                                 ("int16_t *", "mag_sq")],
                  [("int16_t", "ia"), ("int16_t", "ib"), ("int16_t", "sin_q15"),
                   ("int16_t", "cos_q15")],
                  [("int16_t", "dq.d"), ("int16_t", "dq.q"), ("int16_t", "*mag_sq")]), {}),
    "fir": (Unit(FIR, "fir_push", [("int16_t", "x")],
                 [("int16_t", "x"), ("uint16_t", "head")] +
                 [("int16_t", f"history[{i}]") for i in range(5)],
                 [("int16_t", "return"), ("uint16_t", "head")] +
                 [("int16_t", f"history[{i}]") for i in range(5)]), {"head": (0, 4)}),
    "svm": (Unit(SVM, "svm", [("svm_t *", "s")], [("int16_t", "s.alpha"), ("int16_t", "s.beta")],
                 [("uint16_t", "s.ta"), ("uint16_t", "s.tb"), ("uint16_t", "s.tc"),
                  ("uint8_t", "s.sector")]), {}),
    "byvalue": (Unit(BYVALUE, "scaled", [("phase_t", "x"), ("int16_t", "gain_q12")],
                     [("int16_t", "x.a"), ("int16_t", "x.b"), ("int16_t", "gain_q12")],
                     [("int16_t", "return.alpha"), ("int16_t", "return.beta")], ret="albe_t"),
                {}),
    "handle": (Unit(HANDLE, "lim_step", [("Lim *", "lim"), ("int32_t", "x")],
                    [("int32_t", "x"), ("int32_t", "lim.gain"), ("int32_t", "lim.state"),
                     ("int32_t", "lim.hi"), ("int32_t", "lim.lo")],
                    [("int32_t", "return"), ("int32_t", "lim.state")]), {}),
    "isqrt": (Unit(ISQRT, "isqrt32", [("uint32_t", "v")], [("uint32_t", "v")],
                   [("uint16_t", "return")]), {}),
}
VECTORS = 150


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_units_match_the_compilers(target, capsys):
    require(target, capsys)
    rng = random.Random(f"units-{target}")
    pairs = 0
    for name, (unit, ranges) in UNITS.items():
        checked = compile_code(unit.code, target, entry=unit.entry)
        assert sorted(checked.inputs) == sorted(n for _, n in unit.inputs), name
        vectors, expected = [], []
        while len(vectors) < VECTORS:
            vec = random_vector(rng, unit, target)
            for k, (lo, hi) in ranges.items():
                vec[k] = lo + vec[k] % (hi - lo + 1)
            ev = run_checked(checked, vec, None, record=False)
            if ev.undefined & {"shift_count", "division_overflow"}:
                continue
            vectors.append(vec)
            # a field the code leaves alone keeps the driver's zero (its objects are memset)
            expected.append({n: 0 if ev.values[n] is None else ev.values[n]
                             for _, n in unit.outputs})
        for vec, e, g in zip(vectors, expected, run_unit(unit, vectors, target)):
            pairs += 1
            assert e == g, f"{name} inputs {vec}: tracer {e} vs compiler {g}"
    print(f"\nunits vs {target}: {pairs} vectors, 0 mismatches")
    assert pairs == VECTORS * len(UNITS)


MODEL = r"""
#include <stdint.h>
typedef struct { int16_t gain; uint16_t shift; } Cfg;
typedef struct { int32_t acc; int16_t out; int16_t hist[2]; } State;
typedef struct tag_M Model;
struct tag_M { const Cfg *cfg; State *st; int16_t in; };

static void push(int16_t y[2], int16_t v)
{
  y[1] = y[0];
  y[0] = v;
}

static State *model_state(const Model *m)
{
  return m->st;
}

void model_step(Model *const m)
{
  const Cfg *c = (const Cfg *)m->cfg;
  State *s = ((State *) m->st);
  s->acc += (int32_t)m->in * c->gain;
  s->out = (int16_t)(s->acc >> (c->shift & 15U));
  push(model_state(m)->hist, s->out);
}
"""


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_pointer_fields_of_the_entry_object_are_objects_of_their_own(target, capsys):
    """As a generated model's step(RT_MODEL *const rtM): each pointer field points to an
    object named after it (m.cfg.gain), also when a getter returns it; the compilers get the
    objects from a caller this test writes."""
    require(target, capsys)
    # the tracer's name -> the C expression: the objects themselves (the driver loads the
    # inputs before the caller points m's fields at them)
    c_name = {"m.in": "m.in", "m.cfg.gain": "m_cfg.gain", "m.cfg.shift": "m_cfg.shift",
              "m.st.acc": "m_st.acc", "m.st.out": "m_st.out", "m.st.hist[0]": "m_st.hist[0]",
              "m.st.hist[1]": "m_st.hist[1]"}
    outs = ("m.st.acc", "m.st.out", "m.st.hist[0]", "m.st.hist[1]")
    checked = compile_code(MODEL, target, entry="model_step")
    assert sorted(checked.inputs) == ["m.cfg.gain", "m.cfg.shift", "m.in", "m.st.acc",
                                      "m.st.hist[0]"]
    caller = "Cfg m_cfg; State m_st; Model m;\nvoid run_model(void) " \
        "{ m.cfg = &m_cfg; m.st = &m_st; model_step(&m); }\n"
    spell = {n: checked.symbols[n].spelling for n in c_name}
    unit = Unit(MODEL + caller, "run_model", [],
                [(spell[n], c_name[n]) for n in checked.inputs],
                [(spell[n], c_name[n]) for n in outs])
    rng = random.Random(f"model-{target}")
    vectors = [random_vector(rng, unit, target) for _ in range(100)]
    expected = []
    for vec in vectors:
        ev = run_checked(checked, {n: vec[c_name[n]] for n in checked.inputs}, None,
                         record=False)
        expected.append({c_name[n]: ev.values[n] for n in outs})
    assert expected == run_unit(unit, vectors, target)


CHAIN = "".join(f"int f{i}(int x) {{ return f{i + 1}(x); }}\n" for i in range(40)) + \
    "int f40(int x) { return x; } int f(int x) { return f0(x); }"
TREE = "".join(f"int f{i}(int x) {{ return f{i + 1}(x) + f{i + 1}(x); }}\n" for i in range(24)) + \
    "int f24(int x) { return x; } int f(int x) { return f0(x); }"


@pytest.mark.parametrize("code,text", [
    ("int t[5000]; int f(int x) { return t[x]; }",
     "array of 5000 elements: at most 4096 integers per object"),
    (CHAIN, "calls nested more than 32 deep"),
    (TREE, "the calls reach more than 200000 expressions: too large to trace"),
    ("int f(int x) { int i; for (i = 0; i < 30000; i++) x++; return x; }",
     "more than 10000 statements executed (a loop that does not end?)"),
])
def test_each_limit_is_a_one_line_error(code, text):
    with pytest.raises(TraceError) as e:
        trace(code, "arm", {"x": 1}, entry="f")
    assert text in e.value.message and "\n" not in e.value.message
    assert chinese(e.value.message_zh)


def test_a_header_extern_then_the_definition_is_one_object():
    code = "typedef struct { short a[2]; } C;\nextern const C tab;\nextern int k;\n" \
        "const C tab = { { 3, 4 } };\nint f(void) { return tab.a[1] + k; }"
    r = trace(code, "arm", {"k": 10}, entry="f")
    assert r["inputs"] == ["k"] and r["vars"]["return"]["value"] == 14
    with pytest.raises(TraceError) as e:
        trace("int k = 1;\nint k = 2;", "arm")
    assert "2:5: k is already declared at 1:5" in str(e.value)


def test_what_was_written_before_a_call_stays_written_after_it():
    code = "typedef struct { int a; int b; } S;\nstatic int one(void) { return 1; }\n" \
        "int f(S *p) { p->a = 2; p->b = one(); return p->a + p->b; }"
    r = trace(code, "arm", {}, entry="f")
    assert r["inputs"] == [] and r["vars"]["return"]["value"] == 3


OPAQUE = r"""
#include <stdint.h>
typedef struct _LPF_ { int32_t b0; int32_t a1; int32_t y1; } LPF_Obj;
typedef struct _LPF_Obj_ *LPF_Handle;   /* a tag never defined, as TI's modules have it */
#define LPF_B0_DEFAULT _IQ(1.0/3.0)

static inline int32_t LPF_run(LPF_Handle handle, const int32_t x)
{
  LPF_Obj *obj = (LPF_Obj *)handle;
  int32_t y0 = _IQmpy(obj->b0, x) - _IQmpy(obj->a1, obj->y1);
  obj->y1 = y0;
  return y0;
}

int32_t LPF_default(LPF_Handle handle, const int32_t x)
{
  LPF_Obj *obj = (LPF_Obj *)handle;
  obj->b0 = LPF_B0_DEFAULT;
  return LPF_run(handle, x);
}
"""


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_an_opaque_handle_is_the_object_the_entry_casts_it_to(target, capsys):
    """A handle typedef'd to a struct tag that is never defined points to the object its
    casts name; _IQ of a constant expression folds as the compiler folds it."""
    require(target, capsys)
    checked = compile_code(OPAQUE, target, entry="LPF_default")
    assert checked.inputs == ["x", "handle.a1", "handle.y1"]
    unit = Unit(OPAQUE, "LPF_default", [("struct _LPF_ *", "handle"), ("int32_t", "x")],
                [("int32_t", "x"), ("int32_t", "handle.a1"), ("int32_t", "handle.y1")],
                [("int32_t", "return"), ("int32_t", "handle.b0"), ("int32_t", "handle.y1")])
    rng = random.Random(f"opaque-{target}")
    vectors = [random_vector(rng, unit, target) for _ in range(100)]
    expected = [{n: run_checked(checked, v, None, record=False).values[n]
                 for _, n in unit.outputs} for v in vectors]
    assert expected == run_unit(unit, vectors, target)
    assert expected[0]["handle.b0"] == 5592405  # (long)(1.0/3.0 * 2^24)


def test_a_float_field_is_refused_only_where_it_is_used():
    code = "#include <stdint.h>\ntypedef float float_t;\n" \
        "typedef struct { int16_t avg; float_t conv; } Pow;\n" \
        "void run(Pow *p, int16_t x) { p->avg += (int16_t)((x - p->avg) / 16); }\n" \
        "int16_t scaled(Pow *p) { return (int16_t)p->conv; }"
    r = trace(code, "arm", {"p.avg": 32, "x": 0}, entry="run")
    assert r["vars"]["p.avg"]["value"] == 30 and "p.conv" not in r["vars"]
    with pytest.raises(TraceError) as e:
        trace(code, "arm", {}, entry="scaled", zero_unset=True)
    assert "5:42: field conv of struct Pow: float_t is a floating-point type (typedef at 2:15)" \
        in str(e.value)
    assert chinese(e.value.message_zh)


TRIM = r"""
#include <stdint.h>
typedef struct _AVG_ { int32_t k; int32_t y1; } AVG_Obj;
typedef struct _AVG_Obj_ *AVG_Handle;   /* never defined: an opaque handle */
typedef struct _TRIM_
{
  int32_t level;
  int32_t bias;
  AVG_Obj avg;
  AVG_Handle avgHandle;      /* an init function would point it at avg */
  const int32_t *pLimit;     /* at one element of a table */
} TRIM_Obj;
typedef struct _TRIM_Obj_ *TRIM_Handle;
int32_t limits[3];

static inline int32_t AVG_step(AVG_Handle h, const int32_t x)
{
  AVG_Obj *a = (AVG_Obj *)h;
  a->y1 += _IQmpy(a->k, x - a->y1);
  return a->y1;
}

static inline void TRIM_run(TRIM_Handle handle, const int32_t x)
{
  TRIM_Obj *obj = (TRIM_Obj *)handle;
  obj->level = AVG_step(obj->avgHandle, x + obj->bias);
  if (obj->level > *obj->pLimit)
    obj->level = *obj->pLimit;
}

const int32_t *TRIM_pick(TRIM_Handle handle, const int32_t x)
{
  TRIM_Obj *obj = (TRIM_Obj *)handle;
  if (x > obj->level)
    return obj->pLimit;
  if (x < 0)
    return &obj->bias;
  return &obj->avg.y1;
}
"""
#: what the tests' caller does before the call, as an init function would
TRIM_CALLER = r"""
TRIM_Obj t;
int16_t pick_id;
void run_trim(int32_t x)
{
  t.avgHandle = (AVG_Handle)&t.avg;
  t.pLimit = &limits[1];
  TRIM_run((TRIM_Handle)&t, x);
}
void run_pick(int32_t x)
{
  const int32_t *r;
  t.pLimit = &limits[1];
  r = TRIM_pick((TRIM_Handle)&t, x);
  pick_id = r == &limits[1] ? 1 : r == &t.bias ? 2 : r == &t.avg.y1 ? 3 : 0;
}
"""
TRIM_POINTERS = {"handle.avgHandle": "&handle.avg", "handle->pLimit": "&limits[1]"}


def _trim_c_name(name: str) -> str:
    return "t" + name[6:] if name.startswith("handle.") else name


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_pointer_input_points_at_an_object_of_the_code(target, capsys):
    """A handle field an init function sets (`obj->avgHandle = &obj->avg`) is given as
    `--set handle.avgHandle=&handle.avg`; the objects read through it become inputs; the
    compilers get the same pointers from a caller this test writes."""
    require(target, capsys)
    checked = compile_code(TRIM, target, entry="TRIM_run")
    # pLimit has an object of its own unless given; avgHandle, opaque, has none
    assert checked.inputs == ["x", "handle.avgHandle", "handle.bias", "*handle.pLimit"]
    r = trace(TRIM, target, {"x": 1, **TRIM_POINTERS}, entry="TRIM_run", zero_unset=True)
    assert r["inputs"] == ["x", "handle.avgHandle", "handle.bias", "handle.avg.y1",
                           "handle.avg.k", "limits[1]"]
    assert r["vars"]["handle.avgHandle"] == {
        "type": "AVG_Handle", "c_type": "pointer", "bits": None, "signed": False,
        "value": None, "hex": None, "input": True, "points_to": "handle.avg"}
    names = [n for n in r["inputs"] if n not in ("handle.avgHandle",)]
    spell = {n: r["vars"][n]["type"] for n in names}
    outs = ("handle.level", "handle.avg.y1")
    unit = Unit(TRIM + TRIM_CALLER, "run_trim", [("int32_t", "x")],
                [(spell[n], _trim_c_name(n)) for n in names],
                [("int32_t", _trim_c_name(n)) for n in outs])
    rng = random.Random(f"trim-{target}")
    vectors = [random_vector(rng, unit, target) for _ in range(100)]
    expected = []
    for vec in vectors:
        given = {n: vec[_trim_c_name(n)] for n in names}
        ev = run_checked(checked, {**given, **TRIM_POINTERS}, None, record=False)
        expected.append({_trim_c_name(n): ev.values[n] for n in outs})
    assert expected == run_unit(unit, vectors, target)


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_an_entry_returning_a_pointer_names_its_object(target, capsys):
    require(target, capsys)
    checked = compile_code(TRIM, target, entry="TRIM_pick")
    assert checked.inputs == ["x", "handle.level"]
    ids = {"limits[1]": 1, "handle.bias": 2, "handle.avg.y1": 3}
    unit = Unit(TRIM + TRIM_CALLER, "run_pick", [("int32_t", "x")],
                [("int32_t", "x"), ("int32_t", "t.level")], [("int16_t", "pick_id")])
    rng = random.Random(f"pick-{target}")
    vectors = [random_vector(rng, unit, target) for _ in range(60)]
    expected, seen = [], set()
    for vec in vectors:
        given = {"x": vec["x"], "handle.level": vec["t.level"],
                 "handle.pLimit": "&limits[1]"}
        r = call_json("trace", json.dumps({"code": TRIM, "target": target, "entry": "TRIM_pick",
                                   "set": given}))
        ret = json.loads(r)["vars"]["return"]
        assert ret["c_type"] == "pointer" and ret["type"] == "int32_t *"
        seen.add(ret["points_to"])
        expected.append({"pick_id": ids[ret["points_to"]]})
    assert seen == set(ids)  # every branch taken
    assert expected == run_unit(unit, vectors, target)
    # without a value of its own pLimit points to its own object, named after it
    r = trace(TRIM, target, {"x": 1, "handle.level": 0}, entry="TRIM_pick")
    assert r["vars"]["return"]["points_to"] == "*handle.pLimit"


@pytest.mark.parametrize("value,text", [
    ("handle.avg", "handle.avgHandle is a pointer: its value is &OBJECT (a global, an entry "
                   "parameter's object, a field or element of one), got 'handle.avg'"),
    ("5", "its value is &OBJECT"),
    ("&handle.nothing", "handle.avgHandle cannot point to handle.nothing: no such object"),
    ("&obj", "handle.avgHandle cannot point to obj: no such object"),  # an entry local
    ("&handle.avgHandle", "cannot point to handle.avgHandle"),  # a pointer to a pointer
    ("&limits[3]", "handle.avgHandle cannot point to limits[3]: no such object"),
])
def test_a_bad_pointer_value_names_the_input(value, text):
    with pytest.raises(InputError) as e:
        trace(TRIM, "arm", {"x": 1, "handle.avgHandle": value}, entry="TRIM_run")
    assert text in e.value.message and chinese(e.value.message_zh)
    assert "avgHandle" in e.value.field
    with pytest.raises(InputError) as e:
        trace(TRIM, "arm", {"x": 1, "handle.pLimit": "&handle.avg"}, entry="TRIM_run")
    assert "handle.pLimit points to int, but handle.avg is struct _AVG_" in e.value.message
    code = "int *gp; int a; int f(void) { return *gp; }"
    assert trace(code, "arm", {"gp": "&a", "a": 7}, entry="f")["vars"]["return"]["value"] == 7
    with pytest.raises(InputError) as e:  # a global pointer is no object of its own
        trace(code, "arm", {"gp": "&gp"}, entry="f")
    assert "gp cannot point to gp: no such object" in e.value.message


def test_an_unset_pointer_input_stays_unset_and_its_error_says_how_to_give_it():
    with pytest.raises(TraceError) as e:
        trace(TRIM, "arm", {"x": 1}, entry="TRIM_run", zero_unset=True)
    assert e.value.field == "set.handle.avgHandle"
    assert "handle.avgHandle is a pointer read before it has a value: give it the address " \
        "of an object of the code (set handle.avgHandle=&OBJECT)" in e.value.message
    with pytest.raises(InputError) as e:
        from pulab.ctrace.prove import prove_code
        prove_code(TRIM, "arm", "TRIM_run", {"handle.avgHandle": [0, 1]})
    assert "not an input of the code (inputs: x, handle.bias, *handle.pLimit)" in \
        e.value.message


def test_a_proof_ranges_the_fields_read_through_a_pointer_input():
    from pulab.ctrace.prove import prove_code
    sets = {"handle.avgHandle": "&handle.avg", "handle.pLimit": "&limits[1]", "limits[1]": 0,
            "handle.bias": 0, "handle.avg.y1": 0}
    r = prove_code(TRIM, "arm", "TRIM_run", {"x": [0, 1000], "handle.avg.k": [0, 1 << 24]},
                   sets)
    assert r["inputs"] == ["x", "handle.avgHandle", "handle.bias", "handle.avg.y1",
                           "handle.avg.k", "limits[1]"]
    # y1 = k·x >> 24 with k ≤ 1.0: no statement can fail
    assert r["verdict"] == "proven"


def test_an_entry_returning_a_local_address_is_an_error():
    code = "int *f(int x) { int y = x; return &y; }\nint g; int *h(void) { return &g; }"
    with pytest.raises(TraceError) as e:
        trace(code, "arm", {"x": 1}, entry="f")
    assert "f() returns the address of y, which ends with the call (a local)" in str(e.value)
    assert trace(code, "arm", {}, entry="h")["vars"]["return"]["points_to"] == "g"


def test_an_error_reply_offers_the_inputs_read_through_the_pointers_given():
    """The page learns its fields from the replies: a run that stops at an unset field read
    through a pointer input still names that field (a bad pointer value adds nothing)."""
    req = {"code": TRIM, "target": "arm", "entry": "TRIM_run",
           "set": {"x": 1, "handle->avgHandle": "&handle.avg"}}
    r = json.loads(call_json("trace", json.dumps(req)))
    assert r["ok"] is False and r["field"] == "set.handle.bias"
    assert r["inputs"] == ["x", "handle.avgHandle", "handle.bias", "handle.avg.y1",
                           "handle.avg.k", "*handle.pLimit"]
    req["set"]["handle->avgHandle"] = "handle.avg"
    r = json.loads(call_json("trace", json.dumps(req)))
    assert r["inputs"] == ["x", "handle.avgHandle", "handle.bias", "*handle.pLimit"]
