"""Every message the core can produce has Chinese text (the page shows both languages), and an
error reply's text is its code and params rendered by the one catalog: every error is a catalog
code (the tracer's and the command line's too), none is free text.

Fuzzed inputs are checked for this too, in test_report.py."""
import ast
import io
import json
import random
import re
from collections import Counter

import pytest

from conftest import ROOT, chinese
from pulab import report
from pulab.__main__ import main
from pulab.api import call_json
from pulab.ctrace import TraceError, trace
from pulab.ctrace.examples import EXAMPLES
from pulab.schema.catalog import MESSAGES, render
from pulab.schema.errors import InputError
from test_ctrace import _garbage

ERRORS = json.loads((ROOT / "tests/golden/errors.json").read_text())
GOLDEN = sorted((ROOT / "tests/golden").glob("*.json"))
#: Mutated C snippets the tracer runs (each its tests' snippets once, then random ones).
HOSTILE_CODES = 8000
#: The tokens a mutation inserts: C the tracer refuses or half-accepts, and directives.
C_WORDS = ["int", "Uint16", "long", "*", "&", "(", ")", "{", "}", "[", "]", ";", ",", "=", "+",
           "/", "0", "x", "p", "s", "->", ".", "struct", "typedef", "void", "return", "case",
           "switch", "#define", "#if", "#endif", "_IQ(", "0.5", "// @q x Q15\n", "<<", "64", "?",
           ":", "do", "while", "float", "union", "enum", "static", "const", "'a'", "1.5", "010",
           "a##b", "#include <x.h>\n", "__IQmpy(", "...", "goto", "sizeof"]


@pytest.mark.parametrize("case", ERRORS, ids=lambda c: c["field"])
def test_every_golden_error_has_chinese(case):
    out = json.loads(call_json("report", json.dumps(case["input"])))
    assert out["ok"] is False and chinese(out["message_zh"]), out
    assert out["message"] == render(out["code"], out["params"], "en")
    assert out["message_zh"] == render(out["code"], out["params"], "zh")
    assert out["code"] in MESSAGES, out  # every input error of a report has a catalog code


@pytest.mark.parametrize("path", [p for p in GOLDEN if p.name != "errors.json"], ids=lambda p: p.stem)
def test_every_golden_warning_has_chinese(path):
    r = report(json.loads(path.read_text())["input"])
    assert len(r["warnings_zh"]) == len(r["warnings"])
    for w in r["warnings_zh"]:
        assert chinese(w), w


@pytest.mark.parametrize("req", [
    {"format": "Qx"}, {"format": "Q15", "word_bits": 8}, {"format": "Q40.30"},
    {"format": "Q15", "word_bits": "8"}, {"format": "Q0.15", "value": 2.0, "overflow": "error"},
    {"format": "Q0.15", "raw": 70000}, {"format": "Q0.15", "value": "a"},
    {"format": "Q0.15", "raw": "0xZZ"}, {"format": "Q0.15", "value": "1,500"},
    {"format": "Q0.15", "value": 0.1, "rounding": "up"}, {"format": "Q0.15", "raw": 1.5},
])
def test_qcalc_errors_have_chinese(req):
    out = json.loads(call_json("qcalc", json.dumps(req)))
    assert out["ok"] is False and chinese(out["message_zh"]) and out["code"] in MESSAGES, out


# ---- every error is a catalog code ------------------------------------------------------------

def _literal_codes(node):
    """The codes a source expression can be: string constants, through ``a if c else b``/``or``."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        yield node.value
    elif isinstance(node, ast.IfExp):
        yield from _literal_codes(node.body)
        yield from _literal_codes(node.orelse)
    elif isinstance(node, ast.BoolOp):
        for v in node.values:
            yield from _literal_codes(v)


def _codes_in_source() -> dict:
    """code → the files that raise or render it: ``code=`` arguments, ``TraceError.at(place,
    CODE)``, ``render(CODE, …)`` and nested errors ``{"code": CODE, "params": …}``."""
    found: dict = {}
    for path in sorted((ROOT / "py/pulab").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            exprs = []
            if isinstance(node, ast.Call):
                exprs += [k.value for k in node.keywords if k.arg == "code"]
                f = node.func
                if isinstance(f, ast.Attribute) and f.attr == "at" and len(node.args) > 1 and \
                        isinstance(f.value, ast.Name) and f.value.id == "TraceError":
                    exprs.append(node.args[1])
                if isinstance(f, ast.Name) and f.id == "render" and node.args:
                    exprs.append(node.args[0])
            if isinstance(node, ast.Dict) and {getattr(k, "value", None) for k in node.keys} == \
                    {"code", "params"}:
                exprs.append(node.values[[k.value for k in node.keys].index("code")])
            for e in exprs:
                for code in _literal_codes(e):
                    found.setdefault(code, set()).add(path.relative_to(ROOT).as_posix())
    return found


def test_every_code_the_source_names_is_in_the_catalog_in_both_languages():
    found = _codes_in_source()
    assert len(found) > 250, len(found)  # the scan sees the raises (it would pass vacuously)
    assert {c: f for c, f in found.items() if c not in MESSAGES} == {}
    # both texts (test_schema.py renders each with Chinese characters)
    assert all(MESSAGES[c][0] and MESSAGES[c][1] for c in found)


def _codes_of(error: dict):
    """An error's code and the codes of the errors nested in its params."""
    yield error["code"]
    for v in error["params"].values():
        if isinstance(v, dict) and set(v) == {"code", "params"}:
            yield from _codes_of(v)


def test_every_tracer_error_on_hostile_code_is_a_catalog_code():
    """The C snippets of the tracer's tests and the seed's blocks, mutated token by token, with
    random entries, inputs, defines and options: every error is a TraceError whose code (and
    every nested reason's) is in the catalog, rendered in both languages."""
    snippets = sorted({node.value for path in sorted((ROOT / "tests/py").glob("test_ctrace*.py"))
                       for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
                       if isinstance(node, ast.Constant) and isinstance(node.value, str)
                       and any(c in node.value for c in ";#{")})
    corpus = snippets + [e["code"] for e in EXAMPLES.values()]
    rng = random.Random(30)
    seen: Counter = Counter()
    for k in range(HOSTILE_CODES):
        base = corpus[k] if k < len(corpus) else rng.choice(corpus)
        tokens = re.findall(r"\w+|\S", base) if rng.random() < 0.8 else _garbage(rng).split()
        for _ in range(rng.randrange(0, 3) if k < len(corpus) else rng.randrange(1, 3)):
            at = rng.randrange(len(tokens) + 1)
            if tokens and rng.random() < 0.5:
                del tokens[min(at, len(tokens) - 1)]
            else:
                tokens.insert(at, rng.choice(C_WORDS))
        names = re.findall(r"[A-Za-z_]\w*", base) or ["x"]
        entry = rng.choice([None, None, rng.choice(names), rng.choice(names) + "(int)"])
        sets = {rng.choice(names): rng.choice([1, -1, 2 ** 40, "&x", "0x10", "abc", None])} \
            if rng.random() < 0.4 else {}
        # a bad option now and then (it is refused before the code is read)
        options = rng.choice([(None, None, entry)] * 18 + [(99, None, entry), (None, ["1N"], entry),
                                                          (None, None, "1x")])
        try:
            trace(" ".join(tokens), rng.choice(["arm", "c28x"]), sets, options[0], options[1],
                  options[2], rng.random() < 0.5)
            seen["ok"] += 1
        except TraceError as e:
            codes = list(_codes_of(e.as_dict()))
            assert all(c in MESSAGES for c in codes), (codes, e.message)
            assert chinese(e.message_zh) and e.message == render(e.code, e.params, "en"), e.message
            seen.update(codes)
    print(f"\nhostile code: {HOSTILE_CODES} runs, {seen['ok']} traced, "
          f"{len(seen) - 1} distinct error codes")
    assert len(seen) > 80, seen


@pytest.mark.parametrize("argv, stdin, line", [
    (["robust"], "", "error: input: an input JSON file is required (or --catalogue)"),
    (["robust", "-", "--jobs", "0"], "{}", "error: --jobs: must be ≥ 1, got 0"),
    (["robust", "-"], "[]", "error: input: must be a JSON object"),
    (["robust", "-"], '{"analysis": 3}', "error: analysis: must be an object"),
    (["robust", "--catalogue", "-", "--samples", "-1"], "",
     "error: --samples: must be ≥ 0, got -1"),
])
def test_the_robust_command_errors_are_catalog_codes(argv, stdin, line, monkeypatch, capsys):
    monkeypatch.setattr("sys.stdin", io.TextIOWrapper(io.BytesIO(stdin.encode()), encoding="utf-8"))
    assert main(argv) == 2
    assert capsys.readouterr().err == line + "\n"


def test_the_robust_command_codes_have_chinese():
    for code, params in (("cli_needs_dask", {}), ("cli_input_or_catalogue", {}),
                         ("object_required", {}), ("at_least", {"lo": 1, "got": 0})):
        assert chinese(InputError("x", code=code, **params).message_zh), code
