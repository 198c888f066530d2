"""pulab.ctrace.prove: the code proof, against exhaustive enumeration under clang's sanitizers
(tests/oracle/code_prove_oracle.py, never imports pulab) and on hand-checked cases.

Soundness: over random small boxes of six fixed-point routines (tests/oracle/prove_units/),
no statement proven is the first failure of any point in the compiled enumeration, and every
counterexample fails under the compiled program at the line of a statement the tracer also
flags there.  Missing clang: SKIPPED loudly; with CI=true it fails.
"""

from __future__ import annotations

import json
import random
import subprocess
import sys

import pytest

from conftest import ROOT
from ctrace_compilers import require
from pulab.ctrace import trace
from pulab.ctrace.prove import prove_code

sys.path.insert(0, str(ROOT / "tests/oracle"))
import code_prove_oracle as cpo  # noqa: E402

SEED = 20261126


def _window(rng, lo, hi, width, centres):
    """A window of at most ``width`` values of [lo, hi], around a random centre (or anywhere)."""
    c = rng.choice(centres + [rng.randint(lo, hi)])
    w = rng.randint(0, width - 1)
    a = max(lo, min(hi - w, c - rng.randint(0, w)))
    return [a, a + w]


I16 = (-32768, 32767)
BOXES = {
    "q15_multiply": lambda r: {n: _window(r, *I16, 24, [-32768, 32767, 0, -181, 181])
                               for n in ("a", "b")},
    "pi_saturated": lambda r: {"e": _window(r, *I16, 5, [32767, -32768, 4000]),
                               "kp": _window(r, *I16, 4, [4096, 32767, -32768]),
                               "ki": _window(r, *I16, 4, [1024, 32767]),
                               "*integ": _window(r, -2 ** 31, 2 ** 31 - 1, 5,
                                                 [32767, -32768, 0, 2 ** 31 - 1])},
    "sum_store": lambda r: {n: _window(r, *I16, 7, [32767, -32768, 16384, -16384])
                            for n in ("a", "b", "c")},
    "variable_shift": lambda r: {"x": _window(r, 0, 2 ** 31 - 1, 20, [0, 1, 65535, 2 ** 30]),
                                 "n": _window(r, -3, 35, 5, [-1, 0, 15, 16, 31, 32])},
    "gain_table": lambda r: {"num": _window(r, *I16, 6, [32767, -32768, 0]),
                             "den": _window(r, *I16, 5, [0, 1, -1, 3]),
                             "k": _window(r, -2, 5, 3, [0, 3, 4, -1])},
    "sector_switch": lambda r: {n: _window(r, *I16, 12, [0, 1, -1, -1000, -4096, 32767])
                                for n in ("a", "b")},
}
PER_UNIT = 6


def _flagged_lines(code: str, entry: str, point: dict) -> set:
    """Lines where the concrete tracer flags a failure at ``point`` (or stops with an error)."""
    try:
        r = trace(code, "arm", point, entry=entry)
    except Exception as e:  # a run-time error (zero divisor, index): its line
        return {e.line}
    keep = {"signed_overflow", "unsigned_wrap", "conversion", "shift_count"}
    return {s["line"] for s in r["steps"] if keep & set(s["flags"])}


def test_no_proven_statement_fails_in_the_compiled_enumeration(tmp_path, capsys):
    require("clang", capsys)
    rng = random.Random(SEED)
    tally = {"proven": 0, "violated": 0, "unknown": 0, "points": 0, "failing_points": 0}
    for unit, make in BOXES.items():
        oracle = cpo.Oracle(unit, str(tmp_path))
        code = cpo.source(unit)
        entry = cpo.UNITS[unit][0]
        for case in range(PER_UNIT):
            box = make(rng)
            # every other box with a small budget: the parts left undecided must stay sound
            r = prove_code(code, "arm", entry, box, budget=400 if case % 2 else 12)
            failures = oracle.first_failures(box)
            n = 1
            for lo, hi in box.values():
                n *= hi - lo + 1
            tally["points"] += n
            tally["failing_points"] += len(failures)
            failing_lines = {line for line, _ in failures.values()}
            for s in r["statements"]:
                tally[s["verdict"]] += 1
                if s["verdict"] == "proven":
                    assert s["line"] not in failing_lines, (unit, box, s, [
                        (oracle.point_of(box, k), w) for k, w in failures.items()][:3])
                if s["verdict"] == "violated":
                    pt = s["counterexample"]
                    one = {k: [pt[k], pt[k]] for k in box}
                    got = oracle.first_failures(one)
                    assert got, (unit, s, "the counterexample does not fail when compiled")
                    line, what = got[0]
                    assert line in _flagged_lines(code, entry, pt), (unit, s, line, what)
                    assert s["line"] in _flagged_lines(code, entry, pt), (unit, s)
            if r["verdict"] == "proven":
                assert not failures, (unit, box)
    print(json.dumps(tally))
    # The cases must exercise both answers, or the test proves nothing.
    assert tally["proven"] >= 40 and tally["violated"] >= 10 and tally["unknown"] >= 1, tally
    assert tally["failing_points"] >= 100, tally


def test_pi_routine_is_proven_where_the_clamp_bounds_it():
    code = cpo.source("pi_saturated")
    box = {"e": [-4096, 4096], "kp": [0, 8192], "ki": [0, 1024], "*integ": [-32768, 32767]}
    r = prove_code(code, "arm", "pi_saturated", box)
    by_code = {s["code"]: s for s in r["statements"]}
    # |e·kp| ≤ 2^25, >> 12 → [-8192, 8192]; the clamp keeps i in int16; u = up + i can reach
    # 8192 + 32767 > 32767: the int16 store is violated, with a point that shows it.
    assert by_code["int32_t up = ((int32_t)e * kp) >> 12;"]["range"] == [-8192, 8192]
    assert by_code["*integ = i;"]["range"] == [-32768, 32767]
    assert by_code["*integ = i;"]["verdict"] == "proven"
    out = by_code["int16_t out = u;"]
    assert out["verdict"] == "violated" and out["kind"] == "conversion"
    # up ∈ [-8192, 8192] plus the clamped i ∈ [-32768, 32767], before the int16 store
    assert out["computed"] == [-40960, 40959] and out["range"] == [-32768, 32767]
    cx = out["counterexample"]
    e, kp, ki, integ = cx["e"], cx["kp"], cx["ki"], cx["*integ"]
    i = max(-32768, min(32767, integ + ((e * ki) >> 10)))
    assert not -32768 <= ((e * kp) >> 12) + i <= 32767
    assert r["verdict"] == "violated" and r["counterexample"] == cx


def test_unknown_when_the_budget_is_too_small_and_bad_ranges_name_the_field():
    code = cpo.source("variable_shift")
    r = prove_code(code, "arm", "variable_shift", {"x": [0, 2 ** 20], "n": [0, 20]}, budget=3)
    assert r["verdict"] in ("unknown", "violated")
    assert all(0 <= s["proven_fraction"] <= 1 for s in r["statements"])
    with pytest.raises(Exception) as e:
        prove_code(code, "arm", "variable_shift", {"y": [0, 1]})
    assert e.value.field == "range.y"
    with pytest.raises(Exception) as e:
        prove_code(code, "arm", "variable_shift", {"n": [5, 1]})
    assert e.value.field == "range.n"
    with pytest.raises(Exception) as e:
        prove_code(code, "arm", "variable_shift", {"n": [0, 40000]})
    assert e.value.field == "range.n"


def test_cli_exit_status_and_json(tmp_path):
    f = tmp_path / "q.c"
    f.write_text(cpo.source("q15_multiply"))
    base = [sys.executable, "-m", "pulab", "trace", str(f), "--target", "arm",
            "--entry", "q15_multiply", "--prove"]
    env = {"PYTHONPATH": str(ROOT / "py")}
    ok = subprocess.run(base + ["--range", "a=-100:100", "--range", "b=-32768:32767"],
                        capture_output=True, text=True, env=env)
    assert ok.returncode == 0, ok.stderr
    assert json.loads(ok.stdout)["verdict"] == "proven"
    bad = subprocess.run(base + ["--range", "a=-32768:-32760", "--range", "b=-32768:-32767"],
                         capture_output=True, text=True, env=env)
    assert bad.returncode == 1
    r = json.loads(bad.stdout)
    assert r["verdict"] == "violated" and r["counterexample"] == {"a": -32768, "b": -32768}
    wrong = subprocess.run(base + ["--range", "a=1:x"], capture_output=True, text=True, env=env)
    assert wrong.returncode == 2 and wrong.stderr.count("\n") == 1
    assert wrong.stderr.startswith("error: range.a:")


GAIN = """int16_t gain(int16_t x, int16_t k) { // @q k auto
  int32_t p = (int32_t)x * k;
  int16_t y = p >> 12;
  return y;
}"""


def test_q_auto_proposes_the_finest_format_the_proof_allows():
    # k ∈ [-1.5, 2.0] in Qn is round(k·2^n): 2.0·2^14 = 32768 does not fit int16, so at most
    # Q13; with |x| ≤ 4096 every store fits at Q13 (4096·16384 >> 12 = 16384).
    r = prove_code(GAIN, "arm", "gain", {"x": [-4096, 4096], "k": ["-1.5", "2.0"]})
    p = r["proposals"]["k"]
    assert (p["q"], p["raw_range"], p["max_error"]) == (13, [-12288, 16384], 2.0 ** -14)
    assert r["verdict"] == "proven" and r["box"]["k"] == [-12288, 16384]
    # With x over all of int16, y = x·k >> 12 fits only while k·2^n ≤ 4096: Q11
    # (32767·4096 >> 12 = 32767; at Q12 32767·8192 >> 12 = 65534 does not fit).
    r = prove_code(GAIN, "arm", "gain", {"x": [-32768, 32767], "k": [-1.5, 2.0]})
    p = r["proposals"]["k"]
    assert p["q"] == 11 and p["tried"]["12"] == "violated" and p["tried"]["13"] == "violated"
    assert p["max_error_pct"] == pytest.approx(100 * 2.0 ** -12 / 2.0, rel=1e-12)
    with pytest.raises(Exception) as e:
        prove_code(GAIN, "arm", "gain", {"x": [0, 1]})
    assert e.value.field == "range.k"


def test_the_api_kind_runs_in_slices_and_can_be_cancelled():
    from pulab.api import call_json_steps
    # a loop count the box does not decide: the box splits down to each count
    code = """int32_t acc(int16_t x, int16_t n) {
  int32_t s = 0;
  for (int16_t i = 0; i < n; i++)
    s += x;
  return s;
}"""
    req = {"code": code, "target": "arm", "entry": "acc",
           "range": {"x": [-1000, 1000], "n": [0, 80]}, "budget": 4000}
    g = call_json_steps("trace.prove", json.dumps(req))
    slices = 0
    try:
        while True:
            next(g)
            slices += 1
    except StopIteration as done:
        r = json.loads(done.value)
    assert slices >= 2 and r["ok"] and r["proof"]["verdict"] == "proven", (slices, r)
    by_code = {s["code"]: s for s in r["proof"]["statements"]}
    assert by_code["s += x;"]["range"] == [-80000, 80000]
    g = call_json_steps("trace.prove", json.dumps(req))
    next(g)
    g.close()  # the page's Cancel: no exception, nothing left running


def _agrees_with_the_tracer(unit: str, box: dict) -> int:
    """Every point of ``box`` traced concretely: each statement run there is listed by the
    proof (unless it is unknown overall) and each proven range holds its value; the number of
    points traced."""
    import itertools
    from pulab.ctrace import compile_code, run_checked
    code, entry = cpo.source(unit), cpo.UNITS[unit][0]
    checked = compile_code(code, "arm", entry=entry)
    r = prove_code(code, "arm", entry, box)
    ranges = {(s["line"], s["column"]): s["range"] for s in r["statements"]
              if s["verdict"] == "proven" and s["range"] is not None}
    listed = {(s["line"], s["column"]) for s in r["statements"]}
    names, n = list(box), 0
    for values in itertools.product(*(range(lo, hi + 1) for lo, hi in box.values())):
        try:
            ev = run_checked(checked, dict(zip(names, values)), 24)
        except Exception:
            continue  # a run-time error: its statement is not proven
        n += 1
        for s in ev.steps:
            if s.get("input"):
                continue
            key = (s["line"], s["column"])
            assert r["verdict"] == "unknown" or key in listed, (unit, box, values, s["code"])
            rg = ranges.get(key)
            if rg is not None and s["value"] is not None:
                assert rg[0] <= s["value"] <= rg[1], (unit, box, s["code"], s["value"], rg)
    return n


def test_every_range_encloses_every_traced_value():
    # Against the concrete tracer at every point of the box (the tracer's values are themselves
    # checked against gcc and avr-gcc in test_ctrace_compilers.py).
    rng = random.Random(SEED + 1)
    points = sum(_agrees_with_the_tracer(unit, make(rng))
                 for unit, make in BOXES.items() for _ in range(4))
    # a sector switch whose value covers labelled cases and the default, with a return in one
    points += _agrees_with_the_tracer("sector_switch", {"a": [-1005, 5], "b": [-5, 5]})
    assert points > 1000, points


def test_random_snippets_agree_with_the_concrete_tracer_at_every_point():
    # The compiler cross-check's snippet generator (every operator and type, seeded) on small
    # random boxes, c28x and arm: at every point the concrete tracer flags no statement proven
    # and every value lies in its proven range. (Found: `!(65536)` on c28x tests the long
    # constant, not its 16-bit int conversion.)
    import itertools
    from ctrace_gen import generate_case
    from pulab.ctrace import compile_code, run_checked
    from pulab.schema.errors import InputError
    rng = random.Random(SEED + 2)
    fails = {"signed_overflow", "unsigned_wrap", "conversion", "shift_count"}
    proofs = points = 0
    for i in range(200):
        code = generate_case(rng, i).code()
        for target in ("c28x", "arm"):
            try:
                checked = compile_code(code, target)
            except InputError:
                continue
            box = {}
            for n in checked.inputs[:3]:
                t = checked.symbols[n].ctype
                lo = rng.randint(t.min, t.max)
                box[n] = [lo, min(t.max, lo + rng.choice([0, 1, 3, 7]))]
            if not box:
                continue
            r = prove_code(code, target, None, box, zero_unset=True, budget=200)
            proofs += 1
            proven = {(s["line"], s["column"]): s for s in r["statements"]
                      if s["verdict"] == "proven"}
            for s in r["statements"]:  # every counterexample shows its failure when traced
                if s["verdict"] == "violated":
                    try:
                        ev = run_checked(checked, s["counterexample"], 24, zero_unset=True)
                    except InputError as e:  # a run-time error, on that statement's line
                        assert e.line == s["line"], (target, code, s)
                        continue
                    assert any((t["line"], t["column"]) == (s["line"], s["column"]) and
                               fails & set(t["flags"]) for t in ev.steps), (target, code, s)
            for values in itertools.product(*(range(lo, hi + 1) for lo, hi in box.values())):
                try:
                    ev = run_checked(checked, dict(zip(box, values)), 24, zero_unset=True)
                except InputError:
                    continue
                points += 1
                for s in ev.steps:
                    p = proven.get((s["line"], s["column"]))
                    if p is None or s.get("input"):
                        continue
                    assert not fails & set(s["flags"]), (target, code, box, values, s["code"])
                    if p["range"] is not None and s["value"] is not None:
                        assert p["range"][0] <= s["value"] <= p["range"][1], \
                            (target, code, box, values, s["code"], s["value"], p["range"])
    assert proofs > 300 and points > 3000, (proofs, points)


def test_not_of_a_long_constant_on_a_16_bit_int_target():
    # 65536 is a long on c28x; !65536 is 0 (C99 6.5.3.3p5: the operand compared with 0 as it is)
    r = prove_code("uint16_t a; uint16_t b = a + !(65536);", "c28x", None, {"a": [100, 200]})
    assert r["statements"][0]["range"] == [100, 200] and r["verdict"] == "proven"


def test_the_trace_marks_q_auto_inputs():
    r = trace(GAIN, "arm", {"x": 1, "k": 2}, entry="gain")
    assert r["vars"]["k"].get("q_auto") is True and "q_auto" not in r["vars"]["x"]
    r = trace("int16_t k; // @q k Q12\nint16_t y = k;", "arm", {"k": 4096})
    assert "q_auto" not in r["vars"]["k"] and r["vars"]["k"]["real"] == 1.0


LOCALS = """int16_t gain(int16_t x, int16_t k) {
  int32_t p = (int32_t)x * k; // @q p auto
  int16_t y = p >> 12; // @q y auto
  y += 3;
  return y;
}"""


def _best_shift(values, lo, hi) -> int:
    """The largest s with every value in [lo, hi] carrying s more fractional bits (s ≥ 0:
    v·2^s … (v+1)·2^s − 1), or after dropping −s of them (s < 0: v >> −s)."""
    for s in range(62, -64, -1):
        if all(lo <= (v << s if s >= 0 else v >> -s) and
               (((v + 1) << s) - 1 if s >= 0 else v >> -s) <= hi for v in values):
            return s
    raise AssertionError("no shift fits")


@pytest.mark.parametrize("box", [{"x": [30000, 30010], "k": [8190, 8200]},
                                 {"x": [-100, 100], "k": [32700, 32767]},
                                 {"x": [-32768, -32760], "k": [-32768, -32765]}])
def test_q_auto_on_a_local_proposes_the_shift_its_stores_allow(box):
    # Exhaustive enumeration of the stores' values before conversion (C's >> of a negative
    # int32: arithmetic on every target the tracer models, as Python's >>).
    stores = {"p": set(), "y": set()}
    for x in range(box["x"][0], box["x"][1] + 1):
        for k in range(box["k"][0], box["k"][1] + 1):
            p = x * k
            y = ((p + 2 ** 31) % 2 ** 32 - 2 ** 31) >> 12  # p as int32 holds it
            stores["p"].add(p)
            stores["y"] |= {y, (y + 2 ** 15) % 2 ** 16 - 2 ** 15 + 3}
    r = prove_code(LOCALS, "arm", "gain", box, budget=4000)
    for name, word in (("p", (-2 ** 31, 2 ** 31 - 1)), ("y", (-2 ** 15, 2 ** 15 - 1))):
        got = r["proposals"][name]
        v = stores[name]
        assert got["computed"] == [min(v), max(v)], (name, got)
        assert got["shift"] == _best_shift(v, *word), (name, got)
        assert got["max_error_lsb"] == (2 ** -got["shift"] - 1 if got["shift"] < 0 else 0)
    assert set(r["proposals"]) == {"p", "y"}  # the inputs are not auto: no proposal
    from pulab.cli.trace import format_prove_text
    text = format_prove_text(r)
    want = f"@q y auto (local): its stores compute {r['proposals']['y']['computed']}"
    assert want in text and (("value >> 1" in text) == (r["proposals"]["y"]["shift"] == -1))
