"""pulab.ctrace.preprocess: the preprocessor as compilers run it.

Routines written for these tests in the constructs real firmware uses (function-like
macros with #/##, variadic macros, #if/#elif/#else with defined(), include guards,
<stdint.h> limits, line splices, a splice continuing a // comment) are traced and also
compiled by gcc -m32 and avr-gcc + simavr (tests/py/ctrace_compilers.py): every final
variable must agree over random and extreme inputs.
"""

from __future__ import annotations

import random
import time

import pytest

from ctrace_compilers import Unit, require, run_cases, run_unit
from ctrace_gen import Case, random_vector
from pulab.ctrace import TraceError, compile_code, run_checked, trace
from pulab.ctrace.lexer import tokenize
from pulab.ctrace.preprocess import MAX_EXPANDED_TOKENS, MAX_IF_DEPTH, preprocess
from conftest import chinese

VECTORS = 300

# A PI step: the macros, conditionals and splices are the point, the arithmetic is ordinary.
PI_MACROS = Case(
    [("int16_t", "ref"), ("int16_t", "fb"), ("int16_t", "kp"), ("int16_t", "ki"),
     ("int32_t", "acc"), ("int16_t", "e"), ("int16_t", "out")],
    r"""
#include <stdint.h>
#define PI_SAT(v, lo, hi) ((v) > (hi) ? (hi) : \
                           ((v) < (lo) ? (lo) : (v)))
#define PI_Q 15
#define PI_MUL(a, b) (((int32_t)(a) * (b)) >> PI_Q)
#if defined(PI_USE_HALF) || PI_Q < 12
e = (int16_t)((ref - fb) / 2);
#elif PI_Q == 15
e = (int16_t)(ref - fb);
#else
#error unreachable
#endif
acc = acc + PI_MUL(ki, e);   // integrator \
acc = 0;
acc = PI_SAT(acc, INT16_MIN * 4096L, INT16_MAX * 4096L);
out = (int16_t)PI_SAT(PI_MUL(kp, e) + (acc >> 12), INT16_MIN, INT16_MAX);
""", inputs=["ref", "fb", "kp", "ki", "acc"])
PI_MACROS.outputs = PI_MACROS.decls

# Token pasting builds names; a macro passed as an argument is expanded after substitution.
PASTE = Case(
    [("int16_t", "gain_a"), ("int16_t", "gain_b"), ("int16_t", "u"), ("int32_t", "y")],
    r"""
#define PASTE_FIELD(n) gain_##n
#define PASTE_APPLY(n, x) ((int32_t)PASTE_FIELD(n) * (x) >> 8)
#define PASTE_TWICE(f, x) f(f(x))
#define PASTE_HALF(x) ((x) >> 1)
y = PASTE_APPLY(a, u) + PASTE_APPLY(b, PASTE_TWICE(PASTE_HALF, u));
""", inputs=["gain_a", "gain_b", "u"])
PASTE.outputs = PASTE.decls

# An include guard around variadic macros; nested #if with !defined and shifts.
GUARD = Case(
    [("uint16_t", "x"), ("uint16_t", "z"), ("int32_t", "w"), ("uint16_t", "r")],
    r"""
#include <stdint.h>
#ifndef GUARD_CASE_H
#define GUARD_CASE_H
#define GUARD_SUB(b, c) ((b) - (c))
#define GUARD_ADD(a, ...) ((a) + GUARD_SUB(__VA_ARGS__))
#ifdef GUARD_CASE_H
#if (3 * 4 >> 1) == 6 && !defined GUARD_NOT_THERE && -1 < 0
r = GUARD_ADD(x, z, 7u);
#endif
#endif
#endif
#ifndef GUARD_CASE_H
r = 0;
#endif
#if UINT16_MAX == 65535 && INT32_MIN < 0
w = (int32_t)r - INT16_MAX;
#endif
""", inputs=["x", "z"])
GUARD.outputs = GUARD.decls

CASES = {"pi": PI_MACROS, "paste": PASTE, "guard": GUARD}


def _traced(case: Case, target: str, rng: random.Random) -> tuple:
    checked = compile_code(case.code(), target)
    vectors, expected = [], []
    while len(vectors) < VECTORS:
        vec = random_vector(rng, case, target)
        ev = run_checked(checked, vec, None, record=False)
        if ev.undefined & {"shift_count", "division_overflow"}:
            continue
        vectors.append(vec)
        expected.append({n: ev.values[n] for _, n in case.outputs})
    return vectors, expected


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_macro_routines_match_the_compiler(target, capsys):
    require(target, capsys)
    rng = random.Random(f"20261125-{target}")
    cases, expected = [], []
    for case in CASES.values():
        vectors, exp = _traced(case, target, rng)
        cases.append((case, vectors))
        expected.append(exp)
    results, _ = run_cases(cases, target)
    pairs = 0
    for (case, vectors), exp, got in zip(cases, expected, results):
        for vec, e, g in zip(vectors, exp, got):
            pairs += 1
            assert e == g, f"{case.body}\ninputs {vec}: tracer {e} vs compiler {g}"
    assert pairs == VECTORS * len(CASES)


def test_the_pi_takes_the_branch_the_compiler_takes():
    v = trace(PI_MACROS.code(), "arm", {"ref": 100, "fb": 40, "kp": 16384, "ki": 0,
                                         "acc": 0})["vars"]
    # PI_Q == 15: e = ref - fb, and the // comment ended by a splice swallowed "acc = 0;"
    assert (v["e"]["value"], v["out"]["value"]) == (60, 30)
    half = trace(PI_MACROS.code(), "arm", {"ref": 100, "fb": 40, "kp": 16384, "ki": 0,
                                            "acc": 0}, defines=["PI_USE_HALF"])["vars"]
    assert half["e"]["value"] == 30


def test_minus_d_is_a_define_before_the_code():
    code = "long a;\n#ifdef K\na = K * 2;\n#else\na = -1;\n#endif"
    assert trace(code, "c28x", defines=["K=21"])["vars"]["a"]["value"] == 42
    assert trace(code, "c28x", defines=["K"])["vars"]["a"]["value"] == 2
    assert trace(code, "c28x")["vars"]["a"]["value"] == -1
    assert trace("#define K 21\n" + code, "c28x")["vars"]["a"]["value"] == 42
    assert trace(code, "c28x", defines=["GLOBAL_Q=20"])["global_q"] == 20


def test_bom_splices_and_positions():
    r = trace("\ufefflong a = 1 + \\\n 2;\nlong b = a\\\n;", "c28x")
    assert (r["vars"]["a"]["value"], r["vars"]["b"]["value"]) == (3, 3)
    with pytest.raises(TraceError) as e:
        trace("#define TWICE(x) ((x) + (x))\nlong a;\nlong b = TWICE(a);", "c28x")
    assert (e.value.line, e.value.column) == (3, 10)  # the macro use, not the #define


def test_stringize_and_unresolved_includes():
    pre = preprocess(tokenize("#define S(x) #x\nS(a  +  b)"))
    assert [t.text for t in pre.tokens[:-1]] == ['"a + b"']
    r = trace('#include "motor_cfg.h"\n#include <stdint.h>\nlong a = INT16_MIN;', "c28x")
    assert r["unresolved_includes"] == ["motor_cfg.h"] and r["vars"]["a"]["value"] == -32768


@pytest.mark.parametrize("code,line,text", [
    ("#if 1\nlong a;", 1, "#if without #endif"),
    ("#endif", 1, "#endif without #if"),
    ("#if 1\n#else\n#elif 1\n#endif", 3, "#elif after #else"),
    ("#define F(a, b) a\nlong x = F(1);", 2, "macro F() takes 2 arguments, got 1"),
    ("#define F(a) a\nlong x = F(1;", 2, "macro F(: ')' missing"),
    ("#if 1 +\n#endif", 1, "#if: expression ends early"),
    ("#if 1 / 0\n#endif", 1, "#if: division by zero"),
    ("#error stop here", 1, "#error stop here"),
    ("#frobnicate", 1, "#frobnicate is not a preprocessor directive"),
    ("#define P(a, b) a ## b\nlong x = P(+, /);", 2, "'##' pasting '+' and '/'"),
    ("#define G(a, a) a", 1, "a parameter is named twice"),
])
def test_bad_directives_name_line_and_construct(code, line, text):
    with pytest.raises(TraceError) as e:
        trace(code, "c28x")
    assert e.value.line == line and text in e.value.reason, e.value.message
    assert chinese(e.value.message_zh), e.value.message


def test_expansion_and_nesting_are_bounded():
    # Each level doubles: 2**40 tokens if nothing stopped it.
    bomb = "".join(f"#define M{i} M{i + 1} M{i + 1}\n" for i in range(40)) + "long a = M0;"
    t0 = time.perf_counter()
    with pytest.raises(TraceError) as e:
        trace(bomb, "c28x")
    assert f"more than {MAX_EXPANDED_TOKENS} tokens" in e.value.reason
    assert time.perf_counter() - t0 < 30  # a hang guard, not a speed target
    deep = "#if 1\n" * (MAX_IF_DEPTH + 1) + "#endif\n" * (MAX_IF_DEPTH + 1)
    with pytest.raises(TraceError) as e:
        trace(deep, "c28x")
    assert "nested deeper" in e.value.reason
    # A self-referencing macro stops, as C says, instead of recursing.
    assert trace("long a = 5;\n#define a (a + 1)\nlong b = a;", "c28x")["vars"]["b"]["value"] == 6


def test_typedefs_and_vendor_type_names():
    code = ("typedef signed short int16_T;\ntypedef int16_T myq15, myq15b;\n"
            "#define MAX_int32_T ((int32_T)(2147483647))\n"
            "myq15 a;\nint32_T y = (int32_T)a * 3 + MAX_int32_T;\nfrac16_t f = (frac16_t)a;")
    v = trace(code, "arm", {"a": -5})["vars"]
    assert (v["a"]["c_type"], v["y"]["value"], v["f"]["c_type"]) == ("short", 2147483632, "short")


@pytest.mark.parametrize("code,column,text", [
    ("int16_t f(int16_t x)\n{ goto out; }", 3, "'goto' is not supported"),
    ("typedef union { int a; } S;", 9, "'union' is not supported"),
])
def test_unsupported_constructs_are_named(code, column, text):
    with pytest.raises(TraceError) as e:
        trace(code, "arm")
    assert e.value.column == column and text in e.value.reason and chinese(e.value.message_zh)


IQ_CONSTANTS = ["0.1", "-0.57735026918963", "0.1f", "0.99999999", "1.0e-3", "-1", "0.5L",
                "1.7320508075688772", "-0.00001"]


def test_iq_constants_fold_as_gcc_m32_folds_them(tmp_path):
    """_IQ(A) = (long)((A) * 2**Q L) (TI IQmathLib.h, fixed-point build), folded by gcc -m32."""
    import shutil
    import subprocess
    if shutil.which("gcc") is None:
        pytest.skip("needs gcc")
    qs = (24, 15, 30, 1)
    lines = [f'printf("%ld\\n", (long)(({c}) * {float(2 ** q)!r}L));' for q in qs
             for c in IQ_CONSTANTS]
    src = tmp_path / "iq.c"
    src.write_text("#include <stdio.h>\nint main(void) {\n" + "\n".join(lines) + "\nreturn 0; }\n")
    exe = tmp_path / "iq"
    subprocess.run(["gcc", "-m32", "-o", str(exe), str(src)], check=True)
    want = [int(x) for x in subprocess.run([str(exe)], capture_output=True, text=True,
                                           check=True).stdout.split()]
    code = "".join(f"_iq v{q}_{i} = _IQ{q}({c});\n" for q in qs for i, c in enumerate(IQ_CONSTANTS))
    got = trace(code, "c28x")["vars"]
    assert [got[f"v{q}_{i}"]["value"] for q in qs for i in range(len(IQ_CONSTANTS))] == want
    # _IQ follows GLOBAL_Q: the code's #define, else the caller's, else 24.
    assert trace("_iq a = _IQ(0.5);", "c28x")["vars"]["a"]["value"] == 1 << 23
    assert trace("_iq a = _IQ(0.5);", "c28x", global_q=15)["vars"]["a"]["value"] == 1 << 14
    assert trace("#define GLOBAL_Q 20\n_iq a = _IQ(0.5);", "c28x")["vars"]["a"]["value"] == 1 << 19


@pytest.mark.parametrize("expr,value", [
    ("_IQ15toIQ(x)", 3 << 9), ("_IQtoIQ21(x)", 3 >> 3), ("_IQtoIQ30(x)", 3 << 6),
    ("_IQ30toIQ(x)", 0), ("_Q15toIQ(x)", 3 << 9), ("_IQmpy2(x)", 6), ("_IQdiv2(x)", 1),
    ("_IQmpy64(x)", 192), ("_IQdiv64(x)", 0),
])
def test_iq_conversion_macros_shift_as_iqmathlib(expr, value):
    # GLOBAL_Q 24: IQ15 -> IQ shifts left by 9, IQ -> IQ21 right by 3, IQ -> IQ30 left by 6.
    assert trace(f"_iq x = 3;\n_iq y = {expr};", "c28x")["vars"]["y"]["value"] == value


def test_iq_of_a_variable_is_refused_by_name():
    with pytest.raises(TraceError) as e:
        trace("_iq x = 3;\n_iq y = _IQ(x);", "c28x")
    assert "_IQ(…) needs a floating constant" in e.value.reason and chinese(e.value.message_zh)


def test_api_and_cli_take_defines(tmp_path):
    import json
    import subprocess
    import sys
    from pulab.api import call_json
    code = "long a;\n#if MODE == 2\na = 20;\n#else\na = 10;\n#endif"
    r = json.loads(call_json("trace", json.dumps({"code": code, "define": ["MODE=2"]})))
    assert r["vars"]["a"]["value"] == 20
    bad = json.loads(call_json("trace", json.dumps({"code": code, "define": "MODE=2"})))
    assert bad["field"] == "define" and not bad["ok"]
    bad = json.loads(call_json("trace", json.dumps({"code": code, "define": ["2MODE"]})))
    assert bad["field"] == "define[0]"
    src = tmp_path / "m.c"
    src.write_text(code)
    run = subprocess.run([sys.executable, "-m", "pulab", "trace", str(src), "-D", "MODE=2"],
                         capture_output=True, text=True, env={"PYTHONPATH": "py"})
    assert run.returncode == 0 and json.loads(run.stdout)["vars"]["a"]["value"] == 20
    run = subprocess.run([sys.executable, "-m", "pulab", "trace", str(src), "-D", "=1"],
                         capture_output=True, text=True, env={"PYTHONPATH": "py"})
    assert run.returncode == 2 and run.stderr.startswith("error: define[0]: ")
    assert len(run.stderr.strip().splitlines()) == 1


def test_floating_typedefs_wait_until_used():
    code = "typedef float real32_T;\ntypedef double real_T;\nint16_T a = 1;\n"
    assert trace("typedef void * pointer_T;\nlong a = 2;", "arm")["vars"]["a"]["value"] == 2
    with pytest.raises(TraceError) as e:
        trace("typedef int16_t *pq;\npq p;", "arm")
    assert "pq is a pointer type (typedef at 1:18)" in e.value.reason
    assert trace(code, "arm")["vars"]["a"]["value"] == 1
    with pytest.raises(TraceError) as e:
        trace(code + "real32_T f;", "arm")
    assert (e.value.line, e.value.column) == (4, 1) and "typedef at 1:15" in e.value.reason
    assert chinese(e.value.message_zh)
    # static and inline are qualifiers of a function definition
    r = trace("static inline int16_t f(int16_t x) { return x; }", "arm", {"x": 3}, entry="f")
    assert r["vars"]["return"]["value"] == 3


@pytest.mark.parametrize("arg,value", [
    ("4.0/3.0", 22369621),        # floor(2^24 * 4/3), folded in binary64
    ("4/3", 1 << 24),             # integer division first, as C
    ("-(1.0/3.0)", -5592405),     # toward zero
    ("2.0*(1.5-0.25)", 41943040),
])
def test_iq_of_a_constant_expression_folds_as_the_compiler(arg, value):
    assert trace(f"long x = _IQ({arg});", "c28x")["vars"]["x"]["value"] == value


def test_iq_of_a_variable_or_float_suffix_expression_is_refused():
    for code in ("long y; long x = _IQ(y / 3.0);", "long x = _IQ(1.0f / 3.0f);"):
        with pytest.raises(TraceError) as e:
            trace(code, "c28x")
        assert "needs a floating constant" in str(e.value)


IQ_CONSTANTS = ["240.0/360.0", "300.0/360.0", "0.57735026918963", "4.0/3.0", "1.0/3*2", "0.1",
                "-(2.0/3.0)", "0.8660254038"]


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_iq_constants_fold_in_the_targets_double(target, capsys):
    """avr-gcc's double is binary32, gcc -m32's binary64: _IQ(240.0/360.0) differs by one LSB
    between them, and the tracer gives each compiler's value."""
    require(target, capsys)
    code = "".join(f"long k{i};\n" for i in range(len(IQ_CONSTANTS))) + "void f(void)\n{\n" + \
        "".join(f"  k{i} = _IQ({c});\n" for i, c in enumerate(IQ_CONSTANTS)) + "}\n"
    outs = [("int32_t", f"k{i}") for i in range(len(IQ_CONSTANTS))]
    got = run_unit(Unit(code, "f", [], [], outs), [{}], target)[0]
    r = trace(code, target, entry="f")
    assert {n: r["vars"][n]["value"] for _, n in outs} == got
    assert got["k0"] == (11184811 if target == "avr" else 11184810)


def test_iqmathlib_include_defines_global_q_as_the_header_does():
    code = '#include "IQmathLib.h"\nlong q = GLOBAL_Q;\nlong x = _IQ(0.5);'
    r = trace(code, "c28x")
    assert (r["vars"]["q"]["value"], r["vars"]["x"]["value"]) == (24, 1 << 23)
    assert r["unresolved_includes"] == []
    r = trace(code, "c28x", global_q=20)
    assert (r["vars"]["q"]["value"], r["vars"]["x"]["value"]) == (20, 1 << 19)
    r = trace("#define GLOBAL_Q 15\n" + code, "c28x")  # the code's own GLOBAL_Q wins
    assert (r["vars"]["q"]["value"], r["vars"]["x"]["value"]) == (15, 1 << 14)
