"""pulab.ctrace.compile: the closures against the tracer's evaluator they replace.

Every program runs both ways on the same inputs; the values of every variable, each step's
variable, value and flags, the undefined behaviour met and where a run stops (the
evaluator's error) must be equal.  Programs: the seed's blocks and TI line of
ctrace/examples.py over random motors and edge values, the tracer's own doctest snippets,
and 600 random snippets of the compiler cross-check generator (tests/py/ctrace_gen.py:
every operator, type, cast, compound assignment, ++/--, ?:, if/else and IQmath call).
"""

from __future__ import annotations

import random

import pytest

from ctrace_gen import generate_case, random_vector
from pulab.ctrace import TraceError, compile_code, run_checked
from pulab.ctrace.compile import Stopped, Uncompilable, compiled, run_compiled
from pulab.ctrace.examples import EXAMPLES
from pulab.ctrace.iqmath import ARITY

SEED = 20261129


def _both(checked, inputs: dict):
    """(evaluator outcome, closures outcome): values, steps and undefined, or the error."""
    try:
        ev = run_checked(checked, inputs, None, record=True)
        want = ("ok", dict(ev.values),
                [(s["var"], s["value"], tuple(s["flags"])) for s in ev.steps], ev.undefined)
    except TraceError as e:
        want = ("error", str(e), None, None)
    try:
        run = run_compiled(checked, inputs)
        got = ("ok", run.values, [(s.var, s.value, s.flags) for s in run.steps], run.undefined)
    except TraceError as e:
        got = ("error", str(e), None, None)
    return want, got


def _value(rng: random.Random, lo: int, hi: int) -> int:
    r = rng.random()
    if r < 0.3:
        return rng.choice([lo, hi, 0 if lo <= 0 <= hi else lo, min(hi, lo + 1), max(lo, hi - 1)])
    return rng.randrange(lo, hi + 1)


@pytest.mark.parametrize("name", list(EXAMPLES))
@pytest.mark.parametrize("target", ["c28x", "arm"])
def test_examples_run_the_same(name, target):
    checked = compile_code(EXAMPLES[name]["code"], target)
    rng = random.Random(f"{SEED}-{name}-{target}")
    errors = 0
    for _ in range(400):
        inputs = {k: _value(rng, checked.symbols[k].ctype.min, checked.symbols[k].ctype.max)
                  for k in checked.inputs}
        want, got = _both(checked, inputs)
        assert got == want, (name, inputs)
        errors += want[0] == "error"
    assert errors < 400


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_random_snippets_run_the_same(target):
    rng = random.Random(f"{SEED}-{target}")
    pairs = stops = 0
    for i in range(300):
        case = generate_case(rng, i)
        checked = compile_code(case.code(), target)
        for _ in range(12):
            vec = random_vector(rng, case, target)
            want, got = _both(checked, vec)
            assert got == want, (case.code(), vec)
            pairs += 1
            stops += want[0] == "error"
    assert pairs == 3600 and 0 < stops < pairs // 4


@pytest.mark.parametrize("code, inputs", [
    ("Uint16 v; long x = v * 10;", {"v": 6554}),
    ("long x = -5000; long s = x >> 12; long d = x / 4096;", {}),
    ("Uint16 v; Uint16 w; long x = v * w;", {"v": 3}),            # w unset: stops
    ("long a; long b = a % 0;", {"a": 5}),
    ("long a; long b = _IQabs(a);", {"a": -(1 << 31)}),
    ("long a; a++; ++a; a--; long b = a-- + 1;", {"a": (1 << 31) - 1}),
    ("int a; _Bool b = a; _Bool c = (_Bool)2;", {"a": 7}),
    ("long a; if (a > 3) a = a << 31; else a = -a;", {"a": 4}),
    ("long a; if (a > 3) a = a << 31; else a = -a;", {"a": -(1 << 31)}),
    ("#define GLOBAL_Q 12\nlong a; long b = _IQmpy(a, a);", {"a": 4097}),
    ("long a; long b = (a && 0) || a ? 1 : 2;", {"a": 0}),
])
def test_snippets_run_the_same(code, inputs):
    for target in ("c28x", "arm"):
        want, got = _both(compile_code(code, target), inputs)
        assert got == want


@pytest.mark.parametrize("op", sorted(op for op in ARITY if op != "toF"))
def test_iqmath_calls_run_the_same(op):
    """Every IQmath call the tracer knows, compiled and interpreted, on limits and random longs."""
    n = ARITY[op]
    name = f"_IQ{op}" if op in ("sat", "abs") else f"_IQ20{op}"
    params = ", ".join(f"a{i}" for i in range(n))
    code = f"long {'; long '.join(f'a{i}' for i in range(n))}; long r = {name}({params});"
    rng = random.Random(f"{SEED}-{op}")
    for target in ("c28x", "arm"):
        checked = compile_code(code, target)
        for _ in range(200):
            inputs = {f"a{i}": _value(rng, -(1 << 31), (1 << 31) - 1) for i in range(n)}
            want, got = _both(checked, inputs)
            assert got == want, (code, inputs)


def test_stopped_gives_the_statements_run_before():
    checked = compile_code(EXAMPLES["flux"]["code"], "c28x")
    inputs = {"gMotorInfo.FreqRated01": 100, "gBasePar.FullFreq01": 22000,
              "gMotorExtInfo.BemfVolt": 120, "gMotorInfo.Voltage": 17}
    with pytest.raises(Stopped) as e:  # FreqPer = 0, then FluxRotor divides by it
        compiled(checked).run({**inputs, "gMotorInfo.FreqRated01": 0})
    done = {s.var: s.value for s in e.value.steps}
    assert done["gMotorInfo.FreqPer"] == 0 and done["m_Ulong"] == (120 << 12) // 170
    assert checked.program.statements[e.value.index].start == \
        EXAMPLES["flux"]["code"].index("gMotorExtPer.FluxRotor =")
    assert compiled(checked).run(inputs).values["gMotorInfo.FreqPer"] == 148


def test_what_does_not_compile_is_refused():
    with pytest.raises(Uncompilable):
        compiled(compile_code("long f(long a) { return a + 1; }", "c28x", entry="f"))
    for code in ("long a[2]; a[0] = 1;", "long i; long s = 0; for (i = 0; i < 3; i++) s += i;"):
        with pytest.raises(Uncompilable):
            compiled(compile_code(code, "c28x"))
