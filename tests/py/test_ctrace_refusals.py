"""Valid C the tracer once refused, run as pasted and compared with the compilers.

A tentative ``extern`` array completed later, a ``void *`` argument cast back to
``int16_t *`` (ST MCSDK's ``VSS_CalcElAngle`` shape, written here), floating constant
expressions cast to integers (NuttX's ``ftob16``, Microchip's ``Q15``), ``#`` inside a
comment of a macro body, the messages for a macro of a header not pasted, and the macros
each target's compiler predefines.  The compiled twins run in gcc -m32 and avr-gcc + simavr
(tests/py/ctrace_compilers.py).
"""

from __future__ import annotations

import random

import pytest

from ctrace_compilers import Unit, require, run_unit
from ctrace_gen import random_vector
from pulab.ctrace import TraceError, compile_code, run_checked, trace

TABLE = r"""
#include <stdint.h>
extern const int16_t sin_tab[];
int16_t lookup(uint8_t i) { return sin_tab[i & 7] / 2 + sin_tab[(i + 2) & 7]; }
const int16_t sin_tab[8] = {0, 23170, 32767, 23170, 0, -23170, -32767, -23170};
"""

# The shape of ST MCSDK virtual_speed_sensor.c's VSS_CalcElAngle (written for this test):
# the observed angle comes in through a void * and is read back as int16_t.
VSS = r"""
#include <stdint.h>
typedef struct { int16_t hElAngle; int16_t hElSpeedDpp; uint8_t bTransitionStarted;
                 int16_t hRemainingStep; int16_t hElAngleAccu; } VSS_Handle_t;
int16_t VSS_CalcElAngle(VSS_Handle_t *pHandle, void *pInputVars_str)
{
  int16_t hRetAngle, hAngleDiff, hAngleCorr, hSignCorr = 1;
  int32_t wAux;
  if (pHandle->bTransitionStarted == 1u) {
    if (pHandle->hRemainingStep == 0) {
      hRetAngle = *(int16_t *)pInputVars_str;
    } else {
      pHandle->hRemainingStep--;
      pHandle->hElAngleAccu += pHandle->hElSpeedDpp;
      hAngleDiff = *(int16_t *)pInputVars_str - pHandle->hElAngleAccu;
      if (hAngleDiff < 0) { hAngleDiff = -hAngleDiff; hSignCorr = -1; }
      wAux = (int32_t)hAngleDiff * pHandle->hRemainingStep;
      hAngleCorr = (int16_t)(wAux / 100);
      hAngleCorr *= hSignCorr;
      hRetAngle = pHandle->hElAngleAccu + hAngleCorr;
    }
  } else {
    hRetAngle = pHandle->hElAngle;
  }
  pHandle->hElAngle = hRetAngle;
  return hRetAngle;
}
"""
VSS_CALLER = "int16_t vss_call(VSS_Handle_t *h, int16_t *in) { return VSS_CalcElAngle(h, in); }\n"
VSS_FIELDS = ("hElAngle", "hElSpeedDpp", "bTransitionStarted", "hRemainingStep", "hElAngleAccu")

# Constant floating expressions cast to integers, as firmware writes them: NuttX's
# ftob16 (fixedmath.h: (b16_t)((f)*65536.0f)), Microchip's Q15 (the motor-control
# application notes' macro shape), float against double arithmetic, negative truncation.
FOLD = r"""
#include <stdint.h>
typedef int32_t b16_t;
#define ftob16(f) ((b16_t)((f) * 65536.0f))
#define Q15(X) ((X < 0.0) ? (int16_t)(32768 * (X) - 0.5) : (int16_t)(32767 * (X) + 0.5))
#include <stdbool.h>
int32_t r0, r1, r2, r3, r4, r5, r6, r7, r8, r9, r10, r11, r12, r13;
int16_t tab[(int)(2.5f * 2)];
/* initialized and assigned without a cast: converted as by assignment */
const int16_t coef[3] = {0.25 * 32768, -0.5f * 32768, 1};
bool flag = 0.25;
void fold(void)
{
  r0 = ftob16(0.866025f);
  r1 = Q15(0.5);
  r2 = Q15(-0.25);
  r3 = (int32_t)(0.1f * 3.0f * 10000000.0f);
  r4 = (int32_t)(0.1 * 3.0 * 10000000.0);
  r5 = (int32_t)(1.0f / 3.0f * 100000000.0f);
  r6 = (int32_t)(-2.5f * 1000.3f);
  r7 = (int32_t)(0.7f + 0.1 * 1e8);
  r8 = (int32_t)((0.1f == 0.1) ? 1.0 : 2.0);
  r9 = (uint16_t)(65535.9f);
  r10 = sizeof(tab) / sizeof(tab[0]) == 5;
  r11 = 0.29 * 100;
  r12 = coef[0] + coef[1];
  r13 = flag;
}
"""


def _fold_code() -> str:
    # sizeof is outside the subset: the tracer's copy checks the array size by its index range
    return FOLD.replace("r10 = sizeof(tab) / sizeof(tab[0]) == 5;", "tab[4] = 1; r10 = 1;")


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_tentative_extern_array_takes_its_later_size(target, capsys):
    require(target, capsys)
    checked = compile_code(TABLE, target, entry="lookup")
    assert checked.inputs == ["i"]
    unit = Unit(TABLE, "lookup", [("uint8_t", "i")], [("uint8_t", "i")],
                [("int16_t", "return")])
    vectors = [{"i": i} for i in range(256)]
    expected = [{"return": run_checked(checked, v, None, record=False).values["return"]}
                for v in vectors]
    assert expected == run_unit(unit, vectors, target)
    r = trace(TABLE.replace("[8] =", "[] ="), target, {"i": 3}, entry="lookup")
    assert r["vars"]["return"]["value"] == 23170 // 2 + (-23170)


def test_an_extern_array_never_completed_still_needs_a_size():
    with pytest.raises(TraceError) as e:
        trace("extern short t[]; long x = t[0];", "c28x")
    assert e.value.reason == "an array needs a size or an initializer"


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_void_pointer_read_back_as_int16(target, capsys):
    require(target, capsys)
    checked = compile_code(VSS, target, entry="VSS_CalcElAngle")
    assert "*pInputVars_str" in checked.inputs
    names = [f"pHandle.{f}" for f in VSS_FIELDS] + ["*pInputVars_str"]
    spell = {n: ("uint8_t" if n.endswith("Started") else "int16_t") for n in names}
    c_name = {n: "*in" if n.startswith("*") else "h." + n.split(".")[1] for n in names}
    unit = Unit(VSS + VSS_CALLER, "vss_call", [("VSS_Handle_t *", "h"), ("int16_t *", "in")],
                [(spell[n], c_name[n]) for n in names],
                [("int16_t", "return"), ("int16_t", "h.hElAngle"),
                 ("int16_t", "h.hElAngleAccu"), ("int16_t", "h.hRemainingStep")])
    rng = random.Random(f"vss-{target}")
    vectors, expected = [], []
    for _ in range(200):
        vec = random_vector(rng, unit, target)
        vec["h.bTransitionStarted"] = rng.choice([0, 1, 1, 1, 2])
        vec["h.hRemainingStep"] = rng.choice([0, 1, 50, 100])
        ev = run_checked(checked, {n: vec[c_name[n]] for n in names}, None, record=False)
        vectors.append(vec)
        expected.append({"return": ev.values["return"],
                         **{f"h.{f}": ev.values[f"pHandle.{f}"]
                            for f in ("hElAngle", "hElAngleAccu", "hRemainingStep")}})
    assert expected == run_unit(unit, vectors, target)
    # --set of the pointee, as the CLI names it
    r = trace(VSS, target, {"pHandle.bTransitionStarted": 1, "pHandle.hRemainingStep": 0,
                            "*pInputVars_str": -1234, "pHandle.hElAngle": 0,
                            "pHandle.hElSpeedDpp": 0, "pHandle.hElAngleAccu": 0},
              entry="VSS_CalcElAngle")
    assert r["vars"]["return"]["value"] == -1234
    assert r["vars"]["*pInputVars_str"]["input"] is True


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_constant_float_expressions_fold_as_the_compiler_does(target, capsys):
    require(target, capsys)
    outs = [f"r{k}" for k in range(14)]
    checked = compile_code(_fold_code(), target, entry="fold")
    ev = run_checked(checked, {}, None, record=False)
    expected = {n: ev.values[n] for n in outs}
    unit = Unit(FOLD, "fold", [], [], [("int32_t", n) for n in outs])
    assert [expected] == run_unit(unit, [{}], target)
    # hand-worked: 0.866025f = 0.86602497100830078125, times 65536 = 56755.3…, toward zero
    assert expected["r0"] == 56755 and expected["r1"] == 16384 and expected["r2"] == -8192
    # 0.1f == 0.1 only where double is binary32 (avr-gcc)
    assert (expected["r3"], expected["r6"], expected["r8"], expected["r9"]) == \
        (3000000, -2500, 1 if target == "avr" else 2, 65535)
    # 0.29 * 100 = 28.999999999999996 in binary64, 29.0 in avr-gcc's binary32; bool of 0.25 is 1
    assert (expected["r11"], expected["r12"], expected["r13"]) == \
        (29 if target == "avr" else 28, 8192 - 16384, 1)


def test_a_file_scope_float_the_entry_never_uses_is_refused_where_used():
    code = ("#include <stdint.h>\nint32_t unused = (int32_t)(1.5 * (3 + 4));\n"
            "int32_t f(int32_t x) { return x + 1; }\nint32_t g(void) { return unused; }\n")
    assert trace(code, "arm", {"x": 1}, entry="f")["vars"]["return"]["value"] == 2
    with pytest.raises(TraceError) as e:
        trace(code, "arm", entry="g")
    assert e.value.reason.startswith("unused (at 2:28) is outside the subset: 1.5: only")


def test_float_folding_precision_follows_the_target():
    code = "long a = (long)(0.1 * 3.0 * 10000000.0);"
    # avr-gcc's double is binary32: 0.1*3.0 rounds as floats do
    assert trace(code, "arm")["vars"]["a"]["value"] == 3000000
    assert trace(code, "avr")["vars"]["a"]["value"] == 3000000
    code = "long b = (long)(1.0 / 3.0 * 100000000.0);"
    assert trace(code, "arm")["vars"]["b"]["value"] == 33333333
    assert trace(code, "avr")["vars"]["b"]["value"] == 33333334


@pytest.mark.parametrize("code,reason", [
    ("long x = 7 % 1.5;", "% of a floating constant cannot be folded"),
    ("Uint16 v; long x = (long)(v * 0.5);", "0.5: only integer constants are supported"),
    ("long x = (int)(40000.0);", "40000.0 truncated toward zero is 40000, outside int"),
    ("long x = (long)(1.0 % 2.0);", "% of a floating constant cannot be folded"),
])
def test_floating_constants_not_folded_are_refused(code, reason):
    with pytest.raises(TraceError) as e:
        trace(code, "c28x", {"v": 1})
    assert e.value.reason.startswith(reason)


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_a_hash_inside_a_comment_of_a_macro_body(target, capsys):
    require(target, capsys)
    code = ("#include <stdint.h>\n#define SCALE(v) \\\n  /* profile #1: x2, see note # 3 */ \\\n"
            "  ((int16_t)((v) * 2)) // #2\n"
            "#define TWO 2  /* '#' */\n"
            "int16_t f(int16_t v) { return SCALE(v) + 1; }\n")
    checked = compile_code(code, target, entry="f")
    unit = Unit(code, "f", [("int16_t", "v")], [("int16_t", "v")], [("int16_t", "return")])
    vectors = [{"v": v} for v in (-32768, -1, 0, 1, 16383, 16384, 32767)]
    expected = [{"return": run_checked(checked, v, None, record=False).values["return"]}
                for v in vectors]
    assert expected == run_unit(unit, vectors, target)


def test_a_missing_macro_suggests_minus_d_and_only_missing_headers_are_listed():
    header = "#ifndef __SPEED_H__\n#define __SPEED_H__\n#define SPEED_UNIT 10\n#endif\n"
    code = header + '#include "speed.h"\n#include "drive/other.h"\n' \
        "int f(int x) { return x * SPEED_UNIT * OTHER_K; }\n"
    with pytest.raises(TraceError) as e:
        trace(code, "c28x", {"x": 2}, entry="f")
    assert e.value.reason == ("OTHER_K is not declared: if it is a macro of a header not "
                              "pasted (drive/other.h), paste the header or give it with "
                              "-D OTHER_K=VALUE")
    r = trace(code, "c28x", {"x": 2}, defines=["OTHER_K=3"], entry="f")
    assert r["unresolved_includes"] == ["drive/other.h"]
    assert r["vars"]["return"]["value"] == 60
    with pytest.raises(TraceError) as e:
        trace("long x = GAIN * 2;", "c28x")
    assert e.value.reason.startswith("GAIN is not declared: if it is a macro, give it with "
                                     "-D GAIN=VALUE")
    with pytest.raises(TraceError) as e:
        trace("long x = gain * 2;", "c28x")
    assert e.value.reason.startswith("gain is not declared (declare it with its type")


# What CMSIS's cmsis_compiler.h and vendor headers test before anything else.
WHICH_COMPILER = r"""
#if defined(__TI_COMPILER_VERSION__) && defined(__TMS320C2000__) && defined(__TMS320C28XX__)
  #define COMPILER 28
#elif defined(__GNUC__) && defined(__AVR__)
  #define COMPILER 8
#elif defined(__GNUC__) && defined(__arm__)
  #define COMPILER 32
#elif defined(__GNUC__) && defined(__MSP430__)
  #define COMPILER 430
#else
  #error Unknown compiler
#endif
#ifdef __GNUC__
  #define GCC __GNUC__
#else
  #define GCC 0
#endif
long which(void) { return COMPILER * 100L + GCC; }
"""


@pytest.mark.parametrize("target,value", [("c28x", 2800), ("avr", 805), ("arm", 3213),
                                          ("msp430", 43009)])
def test_each_target_predefines_its_compilers_macros(target, value):
    r = trace(WHICH_COMPILER, target, entry="which")
    assert r["vars"]["return"]["value"] == value


def test_minus_u_removes_a_predefined_macro_and_minus_d_adds_one():
    with pytest.raises(TraceError) as e:
        trace(WHICH_COMPILER, "arm", entry="which", undefines=["__arm__"])
    assert e.value.reason == "#error Unknown compiler"
    r = trace(WHICH_COMPILER, "arm", entry="which", undefines=["__arm__", "__GNUC__"],
              defines=["__TI_COMPILER_VERSION__=1", "__TMS320C2000__", "__TMS320C28XX__"])
    assert r["vars"]["return"]["value"] == 2800
    r = trace(WHICH_COMPILER, "c28x", entry="which", defines=["__GNUC__=4"])
    assert r["vars"]["return"]["value"] == 2804
    with pytest.raises(TraceError) as e:
        trace(WHICH_COMPILER, "arm", entry="which", undefines=["1x"])
    assert e.value.field == "undefine[0]"


def test_avr_gcc_predefines_what_the_avr_target_does(capsys):
    require("avr", capsys)
    checked = compile_code(WHICH_COMPILER, "avr", entry="which")
    expected = run_checked(checked, {}, None, record=False).values["return"]
    unit = Unit(WHICH_COMPILER, "which", [], [], [("int32_t", "return")])
    assert [{"return": expected}] == run_unit(unit, [{}], "avr")


def test_the_cli_takes_minus_u(tmp_path):
    import os
    import subprocess
    import sys

    from conftest import ROOT
    src = tmp_path / "which.c"
    src.write_text(WHICH_COMPILER)
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "py"))
    run = [sys.executable, "-m", "pulab", "trace", str(src), "--entry", "which", "--format", "text"]
    p = subprocess.run(run + ["--target", "avr", "-U", "__GNUC__", "-D", "__GNUC__=7"],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0 and p.stdout.splitlines()[-1] == "return 807 (0x00000327)"
    p = subprocess.run(run + ["--target", "avr", "-U", "__AVR__", "-U", "__GNUC__"],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 2 and p.stderr == "error: code: 11:3: #error Unknown compiler\n"
