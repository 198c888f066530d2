"""Every other entry point under hostile input: the CLI subcommands sweep, batch, trace, header
and translate, and every request kind of the worker's ``pulab.api.call_json``.

``report`` and its kind get the 10,000 cases of test_hardening.py; qcalc, export and vendors
requests their own fuzz there and in test_profiles_hardening.py. The contract is the same
everywhere: exit 0 with strict JSON (or the asked-for text), ``batch`` exit 1 with one stderr
line per bad row, or exit 2 with one line ``error: FIELD: MESSAGE``; an API reply is strict JSON,
``ok`` true or a printable one-line ``field``/``message``/``message_zh`` with ``code`` and
``params``.
"""
import contextlib
import io
import json
import random
import sys
from collections import Counter

from adversarial import BASE, FIELDS, NASTY_TEXT, NUMBER_LITERALS, _value, cases
from pulab.__main__ import main
from pulab.api import KINDS, call_json
from pulab.profiles import registry
from pulab.schema.fields import FIELDS as SCHEMA_FIELDS
from test_hardening import _one_line, _strict

NAMES = registry.names()

PER_COMMAND = 600
PLAIN = {k: v for k, v in BASE.items() if k != "sim"}
CODE = ["Uint16 v; long x = v*10;", "int a = 1; a = a / 0;", "long y = 0x7fffffffL + 1;",
        "#define K 3\nUint16 v; Uint16 w = v * K;", "x = 1 +;", "{" * 500, "(" * 5000 + "1",
        "Uint16 v; // @q 15\n", "#define A A\nint x = A;", "int x = 1" + " + 1" * 3000 + ";",
        "long q = _IQmpy(1, 2);", "Uint16 v; if (v) { v = v >> 1; } else v = 0;", "",
        # whole files through an entry function, at each limit of the tracer
        "int f(int x) { return f(x); }", "int f(int x) { for (;;) {} return x; }",
        "int t[5000]; int f(int x) { return t[x]; }",
        "typedef struct { int a; } S; int f(S *p, int x) { return p->a / x; }",
        "int f(int x) { switch (x) { case 1: return 1; default: x++; } return x; }",
        "int f(int *p) { while (*p) (*p)--; return 1; }",
        "float h(float x) { return x; } int f(int x) { return h(x); }",
        "".join(f"int f{i}(int x) {{ return f{i + 1}(x) + f{i + 1}(x); }}\n" for i in range(24))
        + "int f24(int x) { return x; } int f(int x) { return f0(x); }",
        "".join(f"int f{i}(int x) {{ return f{i + 1}(x); }}\n" for i in range(40))
        + "int f40(int x) { return x; } int f(int x) { return f0(x); }"]


def _run(argv: list, stdin: bytes) -> tuple:
    saved = sys.stdin
    sys.stdin = io.TextIOWrapper(io.BytesIO(stdin), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(argv)
    finally:
        sys.stdin = saved
    return code, out.getvalue(), err.getvalue()


def _check(command: str, code: int, stdout: str, stderr: str, json_out: bool) -> str:
    if code == 0:
        assert stderr == "", (command, stderr[:300])
        if json_out:
            _strict(stdout)
        return "ok"
    if code == 1 and command == "batch":
        lines = stderr.splitlines()
        assert lines and all(_one_line(x) and x.startswith("row ") for x in lines), stderr[:300]
        return "rows"
    assert code == 2 and stdout == "", (command, code, stdout[:200])
    line = stderr[:-1]
    assert stderr.endswith("\n") and _one_line(line) and line.startswith("error: "), \
        (command, repr(stderr[:300]))
    return "error"


def _number(rng) -> str:
    return rng.choice(NUMBER_LITERALS + ["1", "2", "10", "0.5", "1e-3"])


def _text(rng) -> str:
    return rng.choice(NASTY_TEXT + NUMBER_LITERALS + ['=HYPERLINK("http://x","a")', "+1", "@a"])


def _argv(rng, command: str) -> tuple:
    """argv and stdin bytes of one hostile invocation of ``command``."""
    inputs = cases(1, seed=rng.randrange(10 ** 9))
    data = next(inputs) if rng.random() < 0.5 else json.dumps(PLAIN).encode()
    if command == "sweep":
        path = ".".join(rng.choice(FIELDS)) if rng.random() < 0.8 else _text(rng)
        axis = f"{path}={_number(rng)}:{_number(rng)}:{rng.choice(['2', '5', '0', '-1', 'x', '20000'])}"
        argv = ["sweep", "-", f"--x={axis}", f"--format={rng.choice(['json', 'csv', 'text'])}"]
        if rng.random() < 0.3:
            argv.append(f"--y={'.'.join(rng.choice(FIELDS))}={_number(rng)}:{_number(rng)}:3")
        if rng.random() < 0.3:
            argv.append(f"--profile={rng.choice(list(NAMES) + [_text(rng)])}")
        return argv, data
    if command == "batch":
        cols = ["name"] + [rng.choice(SCHEMA_FIELDS).path for _ in range(rng.randrange(1, 6))]
        if rng.random() < 0.2:
            cols.append(_text(rng))
        rows = [",".join(json.dumps(_text(rng)) if rng.random() < 0.3 else _number(rng)
                         for _ in cols) for _ in range(rng.randrange(0, 4))]
        sep = rng.choice([",", ";", "\t"])
        return ["batch", "-"], (sep.join(cols) + "\n" + "\n".join(r.replace(",", sep) for r in rows)
                                ).encode("utf-8", "surrogatepass")
    if command == "trace":
        argv = ["trace", "-", f"--target={rng.choice(['c28x', 'c28x', 'arm', _text(rng)])}"]
        for _ in range(rng.randrange(3)):
            argv.append(f"--set={rng.choice(['v', 'w', 'x', _text(rng)])}={_text(rng)}")
        if rng.random() < 0.2:
            argv.append(f"--global-q={_text(rng)}")
        if rng.random() < 0.5:
            argv.append(f"--entry={rng.choice(['f', 'f', 'g', _text(rng)])}")
        if rng.random() < 0.3:
            argv.append("--zero-unset")
        return argv, rng.choice(CODE + [_text(rng)]).encode("utf-8", "surrogatepass")
    if command == "header":
        return ["header", f"--profile={rng.choice(list(NAMES) + [_text(rng)])}", "-"], data
    return (["translate", f"--from={rng.choice(list(NAMES) + [_text(rng)])}",
             f"--axis={rng.choice(['d', 'q', _text(rng)])}", f"--kp={_number(rng)}",
             f"--ki={_number(rng)}", "-"], data)


def test_fuzzed_subcommands_keep_the_cli_contract():
    rng = random.Random(19)
    seen = Counter()
    for command in ("sweep", "batch", "trace", "header", "translate"):
        for _ in range(PER_COMMAND):
            argv, stdin = _argv(rng, command)
            json_out = command in ("trace", "translate") or "--format=json" in argv
            seen[command, _check(command, *_run(argv, stdin), json_out)] += 1
    print(f"\nsubcommand fuzz: {dict(seen)}")
    for command in ("sweep", "batch", "trace", "header", "translate"):
        # Each must reach both outcomes, or the generator tests little.
        assert seen[command, "ok"] + seen[command, "rows"] > 0 and seen[command, "error"] > 0, seen


def _api_reply(text: str) -> str:
    out = _strict(text)
    if out["ok"] is True:
        return "ok"
    assert _one_line(out["field"]) and _one_line(out["message"]) and _one_line(out["message_zh"]), out
    assert isinstance(out["code"], str) and isinstance(out["params"], dict), out
    return "error"


def test_fuzzed_worker_requests_keep_the_api_contract():
    rng = random.Random(20)
    seen = Counter()
    for _ in range(PER_COMMAND):
        path = ".".join(rng.choice(FIELDS))
        sweep = {"input": rng.choice([PLAIN, _value(rng)]),
                 "x": rng.choice([{"path": path, "start": 1, "stop": 2, "n": 3}, _value(rng)]),
                 rng.choice(["start", "count", "summaries", "profile", "y"]): _value(rng)}
        kind = rng.choice(["sweep", "sweep.plan", "sweep.chunk", "sweep.merge", _text(rng)])
        seen["sweep", _api_reply(call_json(kind, json.dumps(sweep)))] += 1
        csv = f"name,{path}\n{_text(rng)},{_number(rng)}\n"
        batch = {"csv": rng.choice([csv, _value(rng)]), "start": rng.choice([0, 1, -1, _value(rng)]),
                 "count": rng.choice([1, 5, _value(rng)])}
        seen["batch", _api_reply(call_json("batch", json.dumps(batch)))] += 1
        trace = {"code": rng.choice(CODE + [_value(rng)]), "target": rng.choice(["c28x", _value(rng)]),
                 "set": rng.choice([{"v": _value(rng)}, _value(rng)]),
                 "global_q": rng.choice([None, 15, _value(rng)]),
                 "entry": rng.choice([None, "f", _value(rng)]),
                 "zero_unset": rng.choice([True, False, _value(rng)])}
        text = json.dumps(trace)
        if rng.random() < 0.1:
            text = '{"set": ' + "[" * 5000 + "]" * 5000 + "}"
        seen["trace", _api_reply(call_json("trace", text))] += 1
    print(f"\nworker request fuzz: {dict(seen)}")
    assert all(seen[k, "error"] > 0 for k in ("sweep", "batch", "trace")), seen


#: The keys each kind reads (anything else is ignored or refused by the kind).
KIND_KEYS = {"report": list(PLAIN), "qcalc": ["format", "word_bits", "value", "raw", "rounding", "overflow"],
             "export.header": ["input"], "export.csv_current": ["input"], "export.csv_pll": ["input"],
             "sweep": ["input", "x", "y", "profile"], "sweep.plan": ["input", "x", "y", "profile"],
             "sweep.chunk": ["input", "x", "start", "count"], "sweep.merge": ["input", "x", "summaries"],
             "batch": ["csv", "start", "count"], "trace": ["code", "target", "set", "global_q", "define", "entry", "zero_unset"],
             "trace.examples": ["x"],
             "trace.prove": ["code", "target", "range", "budget", "define", "entry", "zero_unset"],
             "vendors.header": ["input", "profile"],
             "vendors.translate": ["input", "from", "axis", "values"],
             "prove": ["input", "ranges", "budget"], "prove.plan": ["input", "ranges"],
             "prove.integer": ["input", "ranges", "name"],
             "prove.summary": ["input", "ranges", "integers"],
             "prove.propose": ["input", "ranges", "profile"],
             "course.check": ["input", "id", "answer"], "course.answers": ["input"], "course.spec": ["x"],
             "course.trainees": ["start", "count"], "audit": ["files", "profile", "define"]}


def test_fuzzed_kinds_keep_the_api_contract():
    """Every kind of call_json (and unknown kinds) on a valid request with one key made hostile,
    a request that is not an object, or a text that is not JSON."""
    assert sorted(KIND_KEYS) == sorted(KINDS)
    rng = random.Random(21)
    valid = {"input": PLAIN, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3},
             "format": "Q3.12", "value": 0.5, "csv": "name,motor.rs_ohm\na,1\n", "code": CODE[0],
             "set": {"v": 6554},
             "profile": "ti", "from": "inovance", "axis": "q", "values": {"pm_kp": 1180, "pm_ki": 4720},
             "summaries": [], "start": 0, "count": 1, "ranges": {"motor.rs_ohm": [1, 2]},
             "budget": 20, "name": "vendor.Rpm", "integers": {}, "range": {"v": [0, 7000]},
             "id": "vendor-rpm", "answer": "1",
             "files": [{"name": "a.h", "text": "#define RS 0.35\n#define LS 0.0006\n"}]}
    seen = Counter()
    for _ in range(60):
        for kind in list(KINDS) + [_text(rng)]:
            keys = KIND_KEYS.get(kind, ["input"])
            req = PLAIN if kind == "report" else {k: valid[k] for k in keys if k in valid}
            if kind.startswith("export.csv"):
                req = {"input": BASE}
            r = rng.random()
            if r < 0.2:
                text = json.dumps(req)
            elif r < 0.7:
                req = {**req, rng.choice(keys): _value(rng)}
                text = json.dumps(req)
            elif r < 0.85:
                text = json.dumps(_value(rng))
            else:
                text = rng.choice(["", "{", "[" * 5000, '{"a": 1,}', "nul", json.dumps(req)[:20]])
            seen[kind if kind in KINDS else "?", _api_reply(call_json(kind, text))] += 1
    print(f"\nkind fuzz: {dict(seen)}")
    assert all(seen[k, "error"] > 0 for k in list(KINDS) + ["?"]), seen
    assert all(seen[k, "ok"] > 0 for k in KINDS), seen
