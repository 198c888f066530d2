"""Generated per-call inputs (step, ramp, sine, noise) for sequences.

A PI controller on a first-order filtered feedback, fed by a generated reference step, a
generated sine feedback and generated Gaussian noise, runs 1,000 calls in the tracer; the
values the generators gave (the result's ``generated`` table) are then fed, call by call, to
the same C compiled by gcc -m32 and avr-gcc + simavr, and every output after every call must
agree.  The generators themselves are checked against their definitions where those are
exact (step, ramp, rounding, clamping) and by bounds and statistics where they are not (sine
within ½ LSB of the formula, noise repeatable by seed, in range, with its stated spread).
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest

from conftest import ROOT
from ctrace_compilers import Unit, require, run_calls
from pulab.api import call_json
from pulab.ctrace import TraceError
from pulab.ctrace.sequence import trace_sequence

CTL = r"""
#include <stdint.h>
typedef struct { int16_t kp, ki; int32_t integ, lim; } Pi;
static int32_t lpf_acc;   /* the filter's state, Q15 * 2^15 */

int16_t ctl(Pi *c, int16_t ref, int16_t fb, int16_t d)
{
  int16_t y, meas;
  int32_t err, out;
  y = (int16_t)(lpf_acc >> 15);
  lpf_acc += (int32_t)6000 * (int16_t)(fb + d - y);
  meas = (int16_t)(lpf_acc >> 15);
  err = (int32_t)ref - meas;
  c->integ += (int32_t)c->ki * err;
  if (c->integ > c->lim) c->integ = c->lim;
  else if (c->integ < -c->lim) c->integ = -c->lim;
  out = (((int32_t)c->kp * err) >> 8) + (c->integ >> 12);
  if (out > 32767) out = 32767;
  else if (out < -32768) out = -32768;
  return (int16_t)out;
}
"""
GEN = {"ref": "step:at=300,before=0,after=12000",
       "fb": "sine:amp=32000,period=200,offset=1000,phase=30",
       "d": "noise:amp=600,dist=gauss,seed=11"}
SETS = {"c.kp": 400, "c.ki": 30, "c.integ": 0, "c.lim": 60_000_000, "lpf_acc": 0}
CALLS = 1000


@pytest.mark.parametrize("target", ["arm", "avr"])
def test_a_pi_and_filter_fed_by_generators_match_the_compiler(target, capsys):
    require(target, capsys)
    r = trace_sequence(CTL, target, CALLS, inputs=SETS, entry="ctl", gen=GEN)
    made = r["generated"]
    assert [made[n]["spec"] for n in GEN] == list(GEN.values())
    rows = [{n: made[n]["values"][k] for n in GEN} for k in range(CALLS)]
    rows[0].update(SETS)
    names = ["c.kp", "c.ki", "c.integ", "c.lim", "lpf_acc", "ref", "fb", "d"]
    spell = {"c.integ": "int32_t", "c.lim": "int32_t", "lpf_acc": "int32_t"}
    unit = Unit(CTL, "ctl", [("Pi *", "c"), ("int16_t", "ref"), ("int16_t", "fb"),
                             ("int16_t", "d")], [(spell.get(n, "int16_t"), n) for n in names],
                [("int16_t", "return"), ("int32_t", "c.integ"), ("int32_t", "lpf_acc")])
    got = run_calls(unit, rows, target)
    assert len(got) == len(r["calls"]) == CALLS
    for k, (call, g) in enumerate(zip(r["calls"], got)):
        mine = {"return": call["return"]["value"], "c.integ": call["vars"]["c.integ"]["value"],
                "lpf_acc": call["vars"]["lpf_acc"]["value"]}
        assert mine == g, f"call {k}: tracer {mine} vs compiler {g}"
    outs = [c["return"]["value"] for c in r["calls"]]
    assert len(set(outs)) > 100  # the loop really moved
    # 1000 + 32000·sin(1.8°·k + 30°) first passes 32767 at k = 30 (84°; 82.2° at k = 29 gives
    # 32704): the int16_t input is held at its limit there, and said so
    assert made["fb"]["first_clamped"] == 30 and made["fb"]["values"][30] == 32767
    assert made["ref"]["clamped"] == made["d"]["clamped"] == 0


def _gen(spec: str, calls: int, ctype: str = "int16_t") -> dict:
    code = f"#include <stdint.h>\n{ctype} s;\nvoid f({ctype} x) {{ s = x; }}\n"
    return trace_sequence(code, "arm", calls, entry="f", gen={"x": spec})["generated"]["x"]


def test_step_and_ramp_give_their_definitions_exactly():
    assert _gen("step:at=3,before=-7,after=9", 6)["values"] == [-7, -7, -7, 9, 9, 9]
    assert _gen("step:at=2", 4)["values"] == [0, 0, 1, 1]
    assert _gen("ramp:start=10,slope=-2.5", 5)["values"] == [10, 8, 5, 3, 0]  # ½ away from 0
    assert _gen("ramp:start=0,slope=7,max=20", 5)["values"] == [0, 7, 14, 20, 20]
    g = _gen("ramp:start=32000,slope=500", 4)
    assert (g["values"], g["clamped"], g["first_clamped"]) == ([32000, 32500, 32767, 32767], 2, 2)
    g = _gen("ramp:start=0,slope=-100", 3, "uint8_t")
    assert (g["values"], g["first_clamped"], g["type"]) == ([0, 0, 0], 1, "uint8_t")


def test_values_beyond_binary64_are_held_at_the_limits():
    g = _gen("ramp:start=1e308,slope=1e308", 3)
    assert (g["values"], g["clamped"]) == ([32767, 32767, 32767], 3)
    g = _gen("noise:amp=1e308,offset=-1e308", 50)
    assert set(g["values"]) <= {-32768, 32767} and g["clamped"] == 50


def test_sine_is_within_half_an_lsb_of_its_formula():
    amp, period, offset, phase = 12345.0, 37.5, -200.0, 45.0
    g = _gen(f"sine:amp={amp},period={period},offset={offset},phase={phase}", 300)
    for k, v in enumerate(g["values"]):
        x = offset + amp * math.sin(2 * math.pi * k / period + math.radians(phase))
        assert abs(v - x) <= 0.5, k
    assert g["clamped"] == 0


def test_noise_repeats_by_seed_and_has_its_stated_spread():
    a = _gen("noise:amp=1000,seed=5", 2000)["values"]
    assert a == _gen("noise:amp=1000,seed=5", 2000)["values"]
    assert a != _gen("noise:amp=1000,seed=6", 2000)["values"]
    assert max(a) <= 1000 and min(a) >= -1000 and max(a) > 950 and min(a) < -950
    g = _gen("noise:amp=300,dist=gauss,offset=5000", 4000)["values"]
    mean = sum(g) / len(g)
    sd = math.sqrt(sum((v - mean) ** 2 for v in g) / (len(g) - 1))
    assert abs(mean - 5000) < 20 and abs(sd - 300) < 15  # 4 000 samples: ~4σ margins


@pytest.mark.parametrize("gen, text", [
    ({"x": "sin:amp=1"}, "gen.x: the generator is 'sin'"),
    ({"x": "sine:amp=1"}, "gen.x: sine needs period="),
    ({"x": "sine:amp=1,period=0"}, "gen.x: period must be > 0"),
    ({"x": "sine:amp=nan,period=3"}, "gen.x: amp: 'nan' is not a finite number"),
    ({"x": "noise:amp=1,seed=-1"}, "gen.x: seed must be a whole number"),
    ({"x": "noise:amp=1,dist=normal"}, "gen.x: "),
    ({"x": "step:at=1,slope=2"}, "gen.x: step has no parameter 'slope'"),
    ({"x": "ramp:start=0,slope=1,min=3,max=2"}, "gen.x: min 3.0 is above max 2.0"),
    ({"y": "step:at=1"}, "gen.y: 'y' is not an integer input"),
    ({"x": 5}, "gen.x: the generator is 5"),
])
def test_bad_generators_name_their_input(gen, text):
    with pytest.raises(TraceError) as e:
        trace_sequence("int s; void f(int x) { s = x; }", "arm", 3, entry="f", gen=gen)
    assert f"{e.value.field}: {e.value.message}".startswith(text)


def test_a_generated_input_cannot_also_be_a_table_column():
    with pytest.raises(TraceError) as e:
        trace_sequence("int s; void f(int x) { s = x; }", "arm", 2, table=[{}, {"x": 1}],
                       entry="f", gen={"x": "step:at=1"})
    assert e.value.field == "gen.x" and "row of call 1" in e.value.message


def test_the_cli_and_the_api_take_the_same_spec(tmp_path):
    src = tmp_path / "f.c"
    src.write_text("int s; int f(int x) { s += x; return s; }\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT / "py")}
    cmd = [sys.executable, "-m", "pulab", "trace", str(src), "--target", "arm", "--entry", "f",
           "--calls", "4", "--set", "s=0", "--gen", "x=ramp:start=1,slope=1"]
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=60)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert [c["return"]["value"] for c in out["calls"]] == [1, 3, 6, 10]
    assert out["generated"]["x"]["values"] == [1, 2, 3, 4]
    bad = subprocess.run(cmd[:-1] + ["x=ramp:start=1"], capture_output=True, text=True, env=env,
                         timeout=60)
    assert bad.returncode == 2 and bad.stderr == "error: gen.x: ramp needs slope=…\n"
    reply = json.loads(call_json("trace", json.dumps({
        "code": src.read_text(), "target": "arm", "entry": "f", "calls": 4,
        "set": {"s": 0}, "gen": {"x": "ramp:start=1,slope=1"}})))
    assert reply["ok"] and reply["generated"] == out["generated"]
    reply = json.loads(call_json("trace", json.dumps({
        "code": src.read_text(), "target": "arm", "entry": "f", "calls": 4,
        "gen": {"x": "ramp:slope=1"}})))
    assert not reply["ok"] and reply["field"] == "gen.x"
