"""pulab.ctrace.macro_entry: a function-like macro over a struct object run as the entry.

The macros here are written for these tests in the shape of TI's math-block headers (a
typedef'd struct of IQ fields, a ``#define NAME(v)`` whose lines assign ``v.FIELD`` with
line splices, IQmath and a saturation).  The compiler cross-check invokes each macro as the
firmware does (``NAME(obj);`` on a file-scope object) through gcc -m32 and avr-gcc + simavr
(tests/py/ctrace_compilers.py, which never imports pulab) and requires every field equal.
"""

from __future__ import annotations

import json
import random
import subprocess
import sys

import pytest

from conftest import ROOT, chinese
from ctrace_compilers import Unit, require, run_unit
from ctrace_gen import random_vector
from pulab.api import call_json
from pulab.ctrace import compile_code, run_checked, trace
from pulab.schema.errors import InputError

ALBE = r"""
#ifndef ALBE_H
#define ALBE_H
typedef struct {  int32_t  ia;      // phase a (IQ24)
                  int32_t  ib;      // phase b
                  int32_t  al;      // alpha out
                  int32_t  be;      // beta out
               } ALBE;
#define ALBE_DEFAULTS { 0, 0, 0, 0 }
#define ALBE_RUN(w)                                      \
    w.al = w.ia;                                         \
    w.be = _IQmpy((w.ia + (w.ib << 1)), _IQ(0.57735026918963));
#endif
"""

PIM = r"""
typedef struct { int32_t ref; int32_t fbk; int32_t kp; int32_t ki;
                 int32_t ui; int32_t out; int32_t hi; int32_t lo; int16_t sat; } PIM;
typedef struct { int32_t gain; int32_t y; } SCALE;
#define PIM_RUN(c, s)                                                    \
do {                                                                     \
    int32_t up = _IQmpy(c.kp, c.ref - c.fbk);                            \
    if (c.sat == 0) c.ui = c.ui + _IQmpy(c.ki, up);                      \
    c.out = _IQsat(up + c.ui, c.hi, c.lo);                               \
    c.sat = (c.out != up + c.ui);                                        \
    s.y = (int32_t)(((int64_t)c.out * s.gain) >> 16);                    \
} while (0)
"""


def test_a_macro_runs_as_the_entry_with_its_fields_as_inputs():
    r = trace(ALBE, "c28x", {"w.ia": 1 << 24, "w.ib": -(1 << 23)}, entry="ALBE_RUN")
    assert r["entry"] == "ALBE_RUN" and r["functions"] == [] and r["macros"] == ["ALBE_RUN"]
    assert r["inputs"] == ["w.ia", "w.ib"]
    # (2^24 + 2*(-2^23)) = 0: beta 0; alpha copies ia
    assert {k: v["value"] for k, v in r["vars"].items()} == \
        {"w.ia": 1 << 24, "w.ib": -(1 << 23), "w.al": 1 << 24, "w.be": 0}


def test_type_named_explicitly_or_inferred_per_parameter():
    code = ALBE + "typedef struct { int32_t ia, ib, al, be, extra; } ALBE2;"
    with pytest.raises(InputError) as e:
        compile_code(code, "arm", entry="ALBE_RUN")
    assert e.value.field == "entry"
    assert "several structs have every field of w.al, w.be, w.ia, w.ib" in e.value.message
    assert "(ALBE, ALBE2); name one: ALBE_RUN(TYPE)" in e.value.message
    c = compile_code(code, "arm", entry="ALBE_RUN(ALBE2)")
    assert c.symbols["w.extra"].ctype.bits == 32
    c = compile_code(PIM, "avr", entry="PIM_RUN( - , SCALE )")
    assert "s.gain" in c.inputs and "c.kp" in c.inputs


@pytest.mark.parametrize("code,entry,text", [
    ("typedef struct { int a; } A;\n#define M(v) v.b = 1;", "M",
     "macro M: no struct of the code has every field of v.b (structs: A); name the type: M(TYPE)"),
    ("#define SAT(x, lo) x = x < lo ? lo : x", "SAT",
     "macro SAT: parameter x is not used as x.FIELD; name its type: SAT(TYPE, -)"),
    ("#define SAT(x, lo) x = x < lo ? lo : x", "SAT(int)",
     "macro SAT(x, lo) has 2 parameters, 1 types given"),
    ("typedef struct { int a; } A; A v;\n#define M(v) v.a = 1;", "M",
     "macro M: its parameter v is already a name of the code"),
    ("typedef struct { int a; } A;\n#define M(v) v.a = 1;", "M(",
     "must be a function name or MACRO(TYPE, …), got 'M('"),
    ("typedef struct { int a; } A;\n#define M(v) v.a = 1;", "N",
     "no function N in the code (functions: M(…))"),
])
def test_macro_entry_errors_name_the_macro_and_how_to_fix(code, entry, text):
    with pytest.raises(InputError) as e:
        trace(code, "arm", entry=entry, zero_unset=True)
    assert e.value.field == "entry" and text in e.value.message
    assert chinese(e.value.message_zh)


def test_a_file_of_macros_asks_for_an_entry_and_the_api_offers_them():
    reply = json.loads(call_json("trace", json.dumps({"code": PIM, "target": "arm"})))
    assert reply["ok"] is False and reply["field"] == "entry"
    assert "PIM_RUN(…)" in reply["message"] and reply["macros"] == ["PIM_RUN"]
    reply = json.loads(call_json("trace", json.dumps({"code": ALBE, "target": "arm", "entry": "ALBE_RUN",
                                              "set": {"w.ia": 5, "w->ib": 7}})))
    assert reply["ok"] is True and reply["vars"]["w.be"]["input"] is False


def test_cli_runs_a_macro_entry(tmp_path):
    f = tmp_path / "albe.h"
    f.write_text(ALBE)
    p = subprocess.run([sys.executable, "-m", "pulab", "trace", str(f), "--entry", "ALBE_RUN",
                        "--target", "arm", "--set", "w.ia=100", "--set", "w.ib=-50",
                        "--format", "text"], capture_output=True, text=True, cwd=ROOT,
                       env={"PYTHONPATH": str(ROOT / "py")})
    assert p.returncode == 0, p.stderr
    assert "entry ALBE_RUN; inputs: w.ia, w.ib" in p.stdout
    assert "w.be = 0 (0x00000000)" in p.stdout


UNITS = {
    "albe": (ALBE, "ALBE_RUN", "ALBE w;", "ALBE_RUN(w);"),
    "pim": (PIM, "PIM_RUN", "PIM c; SCALE s;", "PIM_RUN(c, s);"),
}


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_macro_entries_match_the_compilers(target, capsys):
    """The tracer runs the macro pasted as it is; the compilers run it invoked on file-scope
    objects by a function this test writes (the firmware's own call)."""
    require(target, capsys)
    rng = random.Random(f"macro-{target}")
    for name, (code, entry, objects, call) in UNITS.items():
        checked = compile_code(code, target, entry=entry)
        spell = {n: s.spelling for n, s in checked.symbols.items()}
        ints = {"int32_t", "int16_t"}
        assert set(spell.values()) <= ints
        inputs = [(spell[n], n) for n in checked.inputs]
        unit = Unit(code + f"\n{objects}\nvoid run_macro(void) {{ {call} }}\n", "run_macro",
                    [], inputs, [])
        vectors, expected = [], []
        while len(vectors) < 120:
            vec = random_vector(rng, unit, target)
            ev = run_checked(checked, vec, None, record=False)
            vectors.append(vec)
            expected.append(ev.values)
        # the objects' fields (the macro's block locals are the tracer's alone)
        outs = sorted(n for n in checked.symbols if "." in n and
                      (n in ev.written or n in checked.inputs))
        unit.outputs = [(spell[n], n) for n in outs]
        for vec, e, g in zip(vectors, expected, run_unit(unit, vectors, target)):
            assert {n: e[n] for n in outs} == g, f"{name} inputs {vec}"
