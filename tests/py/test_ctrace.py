"""pulab.ctrace: the C tracer's semantics by hand-checked cases (C99 6.3, 6.4.4.1, 6.5),
its CLI/API contract, and fuzzing (bad code gives only the documented error).

The values here follow from the C standard and each target's widths, worked out by hand
in the comments; test_ctrace_compilers.py checks the same engine against real compilers.
"""

import json
import random
import subprocess
import sys

import pytest

from conftest import ROOT, chinese
from pulab.api import call_json
from pulab.ctrace import TraceError, trace
from pulab.ctrace.examples import EXAMPLES
from pulab.ctrace.parser import Node, NodeVisitor, Stmt, parse
from pulab.schema.errors import InputError


def value(code, name, target="c28x", **inputs):
    return trace(code, target, inputs)["vars"][name]["value"]


def last_flags(code, target="c28x", **inputs):
    return trace(code, target, inputs)["steps"][-1]["flags"]


# (code, target, inputs, variable, expected value, expected flags of the last statement)
CASES = [
    # the example: Uint16 * int is unsigned int arithmetic, 16 bits on C28x
    ("Uint16 v; long x = v * 10;", "c28x", {"v": 6554}, "x", 4, ["unsigned_wrap"]),
    # ... but uint16_t promotes to a 32-bit int on ARM: no wrap
    ("Uint16 v; long x = v * 10;", "arm", {"v": 6554}, "x", 65540, []),
    # >> rounds toward -inf, / toward zero (C99 6.5.5p6): one LSB apart for -5000
    ("long x = -5000; long s = x >> 12;", "c28x", {}, "s", -2, ["truncation"]),
    ("long x = -5000; long d = x / 4096;", "c28x", {}, "d", -1, ["truncation"]),
    # 32767 + 1 in 16-bit int: signed overflow, shown as the wrap
    ("int a = 32767; int b = a + 1;", "c28x", {}, "b", -32768, ["signed_overflow"]),
    ("int a = 32767; int b = a + 1;", "arm", {}, "b", 32768, []),
    # 65535 is a long on C28x (decimal: int, long, long long), 0xFFFF an unsigned int
    ("long a = 65535 + 1;", "c28x", {}, "a", 65536, []),
    ("long a = 0xFFFF + 1;", "c28x", {}, "a", 0, ["unsigned_wrap"]),
    # -1 < 0U: -1 converts to unsigned int, so the comparison is false on both
    ("int r = -1 < 0U;", "c28x", {}, "r", 0, ["conversion"]),
    # -1L < 0U: long holds every 16-bit unsigned on C28x (true), not on ARM (unsigned long)
    ("int r = -1L < 0U;", "c28x", {}, "r", 1, []),
    ("int r = -1L < 0U;", "arm", {}, "r", 0, ["conversion"]),
    # truncating assignment and cast
    ("Uint16 u = 70000;", "c28x", {}, "u", 4464, ["conversion"]),
    ("int s = (int)40000L;", "c28x", {}, "s", -25536, ["conversion"]),
    # % truncates toward zero too; the sign follows the dividend
    ("int r = -7 % 3;", "c28x", {}, "r", -1, []),
    # shift count out of range: flagged; the value of a full shift
    ("int r = 1 << 16;", "c28x", {}, "r", 0, ["shift_count"]),
    ("long r = 1L << 16;", "c28x", {}, "r", 65536, []),
    # TI IQmath: 64-bit product >> GLOBAL_Q, floor
    ("long r = _IQmpy(-3, 5);", "c28x", {}, "r", -1, ["truncation"]),
    ("long r = _IQmpy(3L << 24, 1L << 23);", "c28x", {}, "r", 3 << 23, []),
    ("long r = __IQmpy(-3, 5, 1);", "arm", {}, "r", -8, ["truncation"]),
    ("long r = _IQ12mpy(4096, -4096);", "c28x", {}, "r", -4096, []),
    ("#define GLOBAL_Q 1\nlong r = _IQmpy(-3, 5);", "c28x", {}, "r", -8, ["truncation"]),
    ("long r = _IQsat(5000, 4096, -4096);", "c28x", {}, "r", 4096, ["saturate"]),
    ("long r = __IQsat(-5000, 4096, -4096);", "c28x", {}, "r", -4096, ["saturate"]),
    # compound assignment converts back: Uint16 += 1 from 65535 wraps to 0 on both
    ("Uint16 u = 65535; u += 1;", "c28x", {}, "u", 0, ["unsigned_wrap"]),
    ("Uint16 u = 65535; u += 1;", "arm", {}, "u", 0, ["conversion"]),
    ("Uint16 u = 0; u--;", "c28x", {}, "u", 65535, ["unsigned_wrap"]),
    # ternary: the common type of both branches even when one is not evaluated
    ("int c = 1; long r = c ? -1 : 0U;", "c28x", {}, "r", 65535, ["conversion"]),
    # bitwise and logical operators
    ("int r = ~0x00FF & 0x0FF0;", "c28x", {}, "r", 0x0F00, []),
    ("int r = (3 ^ 5) | 8;", "c28x", {}, "r", 14, []),
    ("int r = !0 + (2 && 0) + (0 || 7);", "c28x", {}, "r", 2, []),
    # #define constants, dotted names, hex input, char on C28x is 16 bits
    ("#define K (1 << 4)\nUint16 g.v; long r = g.v * K;", "c28x", {"g.v": "0x1000"}, "r", 0,
     ["unsigned_wrap"]),
    ("char c = 300;", "c28x", {}, "c", 300, []),
    ("char c = 200;", "arm", {}, "c", 200, []),
    ("char c = 200;", "avr", {}, "c", -56, ["conversion"]),
    # if / else
    ("int a = 3; int r = 0; if (a > 2) r = 1; else r = 2;", "c28x", {}, "r", 1, []),
    ("long long big = 0x7FFFFFFFFFFFFFFF; big = big + 1;", "arm", {}, "big", -(1 << 63),
     ["signed_overflow"]),
]


@pytest.mark.parametrize("code,target,inputs,name,expected,flags", CASES,
                         ids=[f"{c[1]}: {c[0][:40]}" for c in CASES])
def test_values_and_flags(code, target, inputs, name, expected, flags):
    r = trace(code, target, inputs)
    assert r["vars"][name]["value"] == expected
    assert r["steps"][-1]["flags"] == flags


def test_types_after_the_usual_arithmetic_conversions():
    terms = trace("Uint16 v; Ulong m; long x = (v * 10) + m;", "c28x",
                  {"v": 1, "m": 2})["steps"][-1]["terms"]
    assert [(t["expr"], t["type"]) for t in terms] == [
        ("(v * 10)", "unsigned int"), ("(v * 10) + m", "unsigned long")]
    assert terms[0]["hex"] == "0x000A" and terms[1]["hex"] == "0x0000000C"


def test_every_variable_and_inputs_are_reported():
    r = trace("Uint16 a; Ulong b; long c = a; b = c;", "c28x", {"a": 3})
    assert r["inputs"] == ["a"]
    assert {k: (v["type"], v["c_type"], v["value"]) for k, v in r["vars"].items()} == {
        "a": ("Uint16", "unsigned int", 3), "b": ("Ulong", "unsigned long", 3),
        "c": ("long", "long", 3)}


def test_q_annotation_gives_real_and_si():
    r = trace("Uint16 x = 6144; // @q x Q12 base=5.5 V", "c28x")
    assert r["vars"]["x"]["real"] == 1.5 and r["vars"]["x"]["si"] == 8.25
    assert r["vars"]["x"]["unit"] == "V" and r["steps"][0]["q"] == 12


def test_flux_lines_differ_between_c28x_and_arm():
    """The seed's flux lines, c28x vs arm: the tracer's first acceptance case."""
    raw = {"gMotorInfo.FreqRated01": 22000, "gBasePar.FullFreq01": 22000,
           "gMotorExtInfo.BemfVolt": 120, "gMotorInfo.Voltage": 6554}
    c28x = trace(EXAMPLES["flux"]["code"], "c28x", raw)["vars"]
    arm = trace(EXAMPLES["flux"]["code"], "arm", raw)["vars"]
    # Voltage*10 = 65540 wraps to 4 on C28x: BemfVolt<<12 / 4 = 122880
    assert c28x["m_Ulong"]["value"] == 122880 and arm["m_Ulong"]["value"] == 7


@pytest.mark.parametrize("code,line,column,text", [
    ("long a = 1;\nlong b = a / 0;", 2, 14, "division by zero"),
    ("long a = 1;\nlong b = a % (a - 1);", 2, 14, "remainder by zero"),
    ("x = 1;", 1, 1, "x is not declared"),
    ("long a = 1 +;", 1, 13, "expected a value"),
    ("for (;;) {}", 1, 1, "more than 10000 statements executed"),
    ("goto out;", 1, 1, "'goto' is not supported"),
    ("int8_t a = 1;", 1, 1, "int8_t does not exist on c28x"),
    ("long b; long a = b + 1.5;", 1, 22, "only integer constants"),
    ("long a = 99999999999999999999;", 1, 10, "too large"),
    ("long a = foo(1);", 1, 10, "unknown function foo()"),
    ("#if 1\nlong a;", 1, 1, "#if without #endif"),
    ("long a; // @q b Q12", 1, 9, "the annotation names b"),
    ("long a = b;", 1, 10, "b is not declared"),
    ("long a;\nlong c = a;", 2, 10, "a is read before it has a value"),
    ("long a = 1; long a = 2;", 1, 18, "a is already declared at 1:6"),
    ("/* open", 1, 1, "comment not closed"),
    ("long a = `;", 1, 10, "unexpected character '`'"),
])
def test_bad_code_names_line_and_column(code, line, column, text):
    with pytest.raises(TraceError) as e:
        trace(code, "c28x")
    assert (e.value.line, e.value.column) == (line, column), str(e.value)
    assert text in e.value.reason and chinese(e.value.message_zh), e.value.message


def test_bad_inputs_name_the_field():
    code = "Uint16 v; long x = 1;"
    for inputs, field in [({"w": 1}, "set.w"), ({"v": 70000}, "set.v"), ({"v": "1.5"}, "set.v"),
                          ({"x": 1}, "set.x")]:
        with pytest.raises(InputError) as e:
            trace(code, "c28x", inputs)
        assert e.value.field == field and chinese(e.value.message_zh), e.value.message
    with pytest.raises(InputError) as e:
        trace(code, "z80")
    assert e.value.field == "target"


def _garbage(rng):
    alphabet = "abxyzUL0123456789_.;,=+-*/%<>&|^!~?:(){}[]#@ \n\t\"'\\`$" + "中Ω"
    words = ["Uint16", "long", "int", "unsigned", "if", "else", "_IQmpy", "__IQsat", "#define",
             "// @q", "0x", "<<=", ">>", "(Ulong)", "for", "a", "b.c", "1", "65535UL", "/*"]
    if rng.random() < 0.5:
        return "".join(rng.choice(alphabet) for _ in range(rng.randrange(0, 60)))
    return " ".join(rng.choice(words) for _ in range(rng.randrange(0, 25)))


def test_fuzzed_code_gives_only_the_documented_error():
    rng = random.Random(10)
    results = {"ok": 0, "error": 0}
    for _ in range(4000):
        code = _garbage(rng)
        target = rng.choice(["c28x", "arm"])
        try:
            trace(code, target, {})
            results["ok"] += 1
        except TraceError as e:
            assert e.line >= 1 and e.column >= 1 and chinese(e.message_zh), (code, e.message)
            results["error"] += 1
        except InputError as e:  # only a read-before-value names set.NAME
            assert e.field.startswith("set."), (code, e)
            results["error"] += 1
    assert results["error"] > 3000


@pytest.mark.parametrize("code", ["(" * 5000, "-" * 5000 + "1", "{" * 5000,
                                  "long a = 1 << 0x7FFFFFFFFFFFFFFF;",
                                  "long a = " + "+1" * 20000 + ";"])
def test_pathological_code_never_crashes(code):
    try:
        trace(code, "c28x")
    except TraceError as e:
        assert chinese(e.message_zh)


def test_a_qualifier_after_a_typedef_star_is_read():
    # `typedef int * const P;` looped for ever: the qualifier after the '*' was never taken
    assert trace("typedef int * const P; int x = 1;", "arm")["vars"]["x"]["value"] == 1
    with pytest.raises(TraceError, match="pq is a pointer type"):
        trace("typedef int16_t * static pq; pq p;", "arm")


def _slot_nodes(node) -> list:
    """The sub-nodes of ``node`` found by reading every slot (lists and tuples included)."""
    out = []
    for name in node.__slots__:
        value = getattr(node, name, None)
        for item in value if isinstance(value, list) else [value]:
            out += [x for x in (item if isinstance(item, tuple) else (item,))
                    if isinstance(x, (Node, Stmt))]
    return out


@pytest.mark.parametrize("example", sorted(EXAMPLES))
def test_children_are_every_sub_node_and_the_visitor_walks_them(example):
    program = parse(EXAMPLES[example]["code"])

    class Count(NodeVisitor):
        def __init__(self):
            self.seen = []

        def generic_visit(self, node):
            self.seen.append(node)
            assert sorted(map(id, node.children())) == sorted(map(id, _slot_nodes(node)))
            super().generic_visit(node)

    walk = Count()
    for s in program.statements + [f for f in program.functions.values()]:
        walk.visit(s)
    assert len(walk.seen) > 20 and len(set(map(id, walk.seen))) == len(walk.seen)


def test_api_trace_error_reply_has_position_and_inputs():
    r = json.loads(call_json("trace", json.dumps({"code": "Uint16 v;\nlong x = v / 0;",
                                          "set": {"v": 1}})))
    assert r["ok"] is False and (r["line"], r["column"]) == (2, 14)
    assert r["field"] == "code" and r["inputs"] == ["v"] and "除以零" in r["message_zh"]
    ok = json.loads(call_json("trace", json.dumps({"code": "Uint16 v; long x = v * 10;",
                                           "target": "arm", "set": {"v": 6554}})))
    assert ok["ok"] and ok["vars"]["x"] == {"type": "long", "c_type": "long", "bits": 32,
                                            "signed": True, "value": 65540,
                                            "hex": "0x00010004", "input": False}


def _cli(*args, stdin=""):
    return subprocess.run([sys.executable, "-m", "pulab", "trace", *args], input=stdin,
                          capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT / "py")})


def test_cli_contract(tmp_path):
    f = tmp_path / "flux.c"
    f.write_text(EXAMPLES["flux"]["code"])
    p = _cli(str(f), "--target", "c28x", "--set", "gMotorInfo.FreqRated01=22000",
             "--set", "gBasePar.FullFreq01=22000", "--set", "gMotorExtInfo.BemfVolt=120",
             "--set", "gMotorInfo.Voltage=0x199A")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["ok"] is True and out["target"] == "c28x"
    assert out["vars"]["m_Ulong"]["value"] == 122880 and out["vars"]["m_Ulong"]["type"] == "Ulong"
    assert isinstance(out["steps"], list) and out["steps"][-1]["var"] == "gMotorExtPer.FluxRotor"


@pytest.mark.parametrize("args,stdin,prefix", [
    (["-"], "long a = 1;\nlong b = a / 0;", "error: code: 2:14: division by zero"),
    (["-"], "long a = ;", "error: code: 1:10: expected a value"),
    (["-", "--set", "zz=1"], "long a;", "error: set.zz: "),
    (["-", "--set", "novalue"], "long a;", "error: set: "),
    (["-", "--target", "pdp11"], "long a;", "error: target: "),
    (["-", "--global-q", "31"], "long a;", "error: global_q: "),
    (["/nonexistent.c"], "", "error: code: cannot read"),
])
def test_cli_bad_input_exits_2_with_one_line(args, stdin, prefix):
    p = _cli(*args, stdin=stdin)
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr.startswith(prefix) and p.stderr.count("\n") == 1, p.stderr


def test_cli_reads_latin1_comments_and_refuses_such_bytes_outside_them(tmp_path):
    f = tmp_path / "gbk.c"
    f.write_bytes(b"/* Rule\xa011.4 */ long a = 3; // e\xba\xcd\nlong b = a * 2;\n")
    p = subprocess.run([sys.executable, "-m", "pulab", "trace", str(f), "--format", "text"],
                       capture_output=True, text=True, cwd=ROOT,
                       env={"PYTHONPATH": str(ROOT / "py")})
    assert p.returncode == 0 and "b = 6" in p.stdout, p.stderr
    f.write_bytes(b"long a = 3;\nlong b = a \xd7 2;\n")
    p = subprocess.run([sys.executable, "-m", "pulab", "trace", str(f)], capture_output=True,
                       text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT / "py")})
    assert p.returncode == 2 and p.stderr.startswith("error: code: 2:12: unexpected character")


def test_fuzzed_api_requests_give_only_error_replies():
    rng = random.Random(11)
    values = [None, True, 0, -1, 2**70, 1.5, "", "c28x", "arm", "0x10", [], {}, [1], {"a": 1},
              "long a = 1;", "Uint16 v; long x = v * 10;"]
    for _ in range(2000):
        req = {k: rng.choice(values) for k in rng.sample(["code", "target", "set", "global_q",
                                                          "extra"], rng.randrange(0, 5))}
        if rng.random() < 0.3:
            req["set"] = {rng.choice(["v", "a", "x"]): rng.choice(values)}
        text = json.dumps(req) if rng.random() < 0.9 else rng.choice(["", "[", "nul", "1"])
        r = json.loads(call_json("trace", text))
        assert r["ok"] is True or (r["field"] and chinese(r["message_zh"])), (req, r)


def test_cli_text_format_is_one_line_per_statement(tmp_path):
    import subprocess
    import sys
    src = tmp_path / "pi.c"
    src.write_text("int16_t e;\nint32_t acc = 0;\nacc += (int32_t)e * 3 >> 2;\n"
                   "if (acc > 100) acc = 100;\n")
    run = subprocess.run([sys.executable, "-m", "pulab", "trace", str(src), "--target", "arm",
                          "--set", "e=-7", "--format", "text"],
                         capture_output=True, text=True, env={"PYTHONPATH": "py"})
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == "target arm, GLOBAL_Q 24; inputs: e"
    # e, acc, acc += …, the if (not taken): 4 statements, 4 lines
    assert len(lines) == 6
    assert "acc = -6 (0xFFFFFFFA)" in lines[3] and "truncation at 3:8" in lines[3]
    assert lines[4].endswith("-> none")
    # >> rounds toward -inf: -21 >> 2 = -6 loses 0.75 LSB (-21/4 = -5.25)
    assert "(floor, 0.75 LSB lost)" in lines[3]
    assert lines[5] == "rounding acc: 1 toward -inf, 0 toward zero, at most 0.75 LSB"


@pytest.mark.parametrize("code,where,reason,text", [
    ("int f(int x) {\n  int g(int y) { return y; }\n  return x;\n}", "2:7", "trace_nested_function",
     "a function g(…) can only be declared at file scope (a function definition is not "
     "supported inside a function)"),
    ("union u { int a; };", "1:1", "trace_not_supported", "'union' is not supported"),
    ("long y; long x = y * 1.5;", "1:22", "trace_float_constant", "1.5: only integer constants"),
    ("int f(int x, ...) { return x; }", "1:14", "trace_variadic",
     "variadic functions are not supported"),
    ("struct s { int a : 3; };", "1:18", "trace_bitfield", "bit-fields are not supported"),
    ("int f(int x) { return x, 1; }", "1:24", "trace_comma", "the comma operator"),
    ("long x = 3 @ 4;", "1:12", "trace_character", "unexpected character '@'"),
    ("int f(int x) { goto out; }", "1:16", "trace_not_supported", "'goto' is not supported"),
])
def test_parser_errors_are_catalog_codes_naming_the_construct(code, where, reason, text):
    with pytest.raises(TraceError) as e:
        trace(code, "arm", entry=None)
    err = e.value
    assert err.code == "trace_at" and err.params["reason"]["code"] == reason, err.params
    assert f"{err.line}:{err.column}" == where and text in err.message, err.message
    assert chinese(err.message_zh)
