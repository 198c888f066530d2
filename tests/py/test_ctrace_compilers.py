"""pulab.ctrace against real compilers: avr-gcc + simavr (16-bit int, as C28x)
and gcc -m32 (32-bit int and long, as ARM).

Random snippets (tests/py/ctrace_gen.py: expression trees over every supported operator
and type, seeded) and random inputs are compiled and run; every final variable must equal
the tracer's.  Built with -fwrapv: signed overflow is compared as the two's-complement
wrap; vectors that meet other undefined behaviour (shift count out of range, INT_MIN/-1,
division by zero) are excluded and counted.  The seed's own Inovance blocks run over
1,100 random motors the same way (the report's vendor integers are these blocks,
pulab.profiles.inovance.code).

Missing tools: SKIPPED loudly; with CI=true the missing tools fail the test.
"""

from __future__ import annotations

import random

import pytest

from ctrace_compilers import require, run_cases
from ctrace_gen import Case, generate_case, random_vector
from pulab.ctrace import TraceError, compile_code, run_checked
from pulab.ctrace.examples import EXAMPLES
from pulab.ctrace.parser import Decl

SEED = 20261122
SNIPPETS = 300
VECTORS_PER_SNIPPET = 42
MIN_PAIRS = 10_000
MOTORS = 1_100
# The tracer's target for each compiler: AVR's widths are C28x's (char aside; the generator's
# char types are checked as avr, the seed blocks as c28x).
TARGETS = {"avr": "avr", "arm": "arm"}


def _vectors(checked, rng, case, target: str, n: int) -> tuple:
    """Up to n input vectors without excluded UB, their traced values, the exclusions, and how
    many kept vectors overflow a signed type (compared as the -fwrapv wrap)."""
    vectors, expected, excluded, wraps = [], [], 0, 0
    for _ in range(n):
        for _attempt in range(6):
            vec = random_vector(rng, case, target)
            try:
                ev = run_checked(checked, vec, None, record=False)
            except TraceError:  # division or remainder by zero
                excluded += 1
                continue
            if ev.undefined & {"shift_count", "division_overflow"}:
                excluded += 1
                continue
            vectors.append(vec)
            expected.append(dict(ev.values))
            wraps += "signed_overflow" in ev.undefined
            break
    return vectors, expected, excluded, wraps


def _compare(cases: list, expected: list, results: list) -> tuple:
    pairs, mismatches = 0, []
    for (case, vectors), exp, got in zip(cases, expected, results):
        for vec, e, g in zip(vectors, exp, got):
            pairs += 1
            bad = {n: (e[n], g[n]) for n in g if e[n] != g[n]}
            if bad:
                mismatches.append((case.code(), vec, bad))
    return pairs, mismatches


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_random_snippets_match_the_compiler(target, capsys):
    require(target, capsys)
    rng = random.Random(f"{SEED}-{target}")
    cases, expected, excluded, wraps = [], [], 0, 0
    for i in range(SNIPPETS):
        case = generate_case(rng, i)
        checked = compile_code(case.code(), TARGETS[target])
        vectors, exp, ex, w = _vectors(checked, rng, case, target, VECTORS_PER_SNIPPET)
        excluded += ex
        wraps += w
        cases.append((case, vectors))
        expected.append(exp)
    results, programs = run_cases(cases, target)
    pairs, mismatches = _compare(cases, expected, results)
    with capsys.disabled():
        print(f"\nctrace vs {'avr-gcc+simavr' if target == 'avr' else 'gcc -m32'} "
              f"(seed {SEED}): {SNIPPETS} snippets, {pairs} snippet-vector pairs, "
              f"{len(mismatches)} mismatches ({wraps} pairs with a signed overflow, compared "
              f"as the -fwrapv wrap), {excluded} vectors excluded as UB or ÷0, "
              f"{programs} programs")
    assert not mismatches, "first mismatches:\n" + "\n".join(
        f"{code}inputs {vec}: tracer vs compiler {bad}" for code, vec, bad in mismatches[:5])
    assert pairs >= MIN_PAIRS


def _motor(rng: random.Random) -> dict:
    """Raw firmware integers of a random plausible motor and one PI state."""
    full = rng.randrange(1000, 60001)
    voltage = rng.randrange(12, 691)
    maxout = rng.randrange(1, 8192)
    maxu = maxout << 12
    return {
        "gMotorInfo.Voltage": voltage, "gMotorInfo.Current": rng.randrange(10, 60001),
        "gMotorExtInfo.RsPm": rng.randrange(1, 60001), "gBasePar.FullFreq01": full,
        "gMotorInfo.FreqRated01": rng.randrange(full // 4, full + 1),
        "gMotorExtInfo.LD": rng.randrange(1, 60001),
        "gMotorExtInfo.BemfVolt": rng.randrange(10, min(65535, voltage * 12)),
        "gUDC.uDCFilter": rng.randrange(100, 65536),
        "pm_integral_d": rng.randrange(-maxu, maxu + 1), "pm_error_id": rng.randrange(-32768, 32768),
        "pm_kp_d": rng.randrange(0, 32768), "pm_ki_d": rng.randrange(0, 65536),
        "maxu": maxu, "minu": -maxu, "pm_maxout_vol": maxout,
    }


def _seed_case(name: str, target: str) -> tuple:
    """A seed block as a Case: its uninitialized declarations go to the C harness."""
    code = EXAMPLES[name]["code"]
    checked = compile_code(code, target)
    decls = [(s.spelling, s.name) for s in checked.symbols.values() if not s.initialized]
    body = code
    for stmt in checked.program.statements:  # the harness declares these (dotted → struct)
        if isinstance(stmt, Decl) and all(item[1] is None for item in stmt.items):
            body = body.replace(code[stmt.start:stmt.end], "", 1)
    return Case(decls, body, decls, checked.inputs), checked


@pytest.mark.parametrize("target", ["avr", "arm"])
def test_seed_statements_match_the_compiler_over_motors(target, capsys):
    require(target, capsys)
    rng = random.Random(f"{SEED}-motors")
    motors = [_motor(rng) for _ in range(MOTORS)]
    tracer_target = "c28x" if target == "avr" else "arm"
    cases, expected, excluded = [], [], 0
    for name in ("rpm", "ld", "flux", "maxu", "pi"):
        case, checked = _seed_case(name, tracer_target)
        vectors, exp = [], []
        for m in motors:
            v = {k: m[k] for k in case.inputs}
            try:
                exp.append(dict(run_checked(checked, v, None, record=False).values))
            except TraceError:  # the firmware divides by zero (e.g. m_BaseL = 0)
                excluded += 1
                continue
            vectors.append(v)
        cases.append((case, vectors))
        expected.append(exp)
    results, programs = run_cases(cases, target)
    pairs, mismatches = _compare(cases, expected, results)
    with capsys.disabled():
        print(f"\nseed blocks as {tracer_target} vs "
              f"{'avr-gcc+simavr' if target == 'avr' else 'gcc -m32'}: {MOTORS} motors × "
              f"{len(cases)} blocks = {pairs} pairs ({excluded} excluded: the firmware "
              f"divides by zero), {len(mismatches)} mismatches")
    assert not mismatches, mismatches[:3]
    assert pairs + excluded == MOTORS * len(cases) and pairs >= 1000 * len(cases)
