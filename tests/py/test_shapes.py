"""pulab.schema.shapes: the declared shapes of the report and of the API's replies are the ones
pulab really returns, and the page's generated TypeScript is what the build writes from them.

Real outputs only: the report of every golden vector's input (every ``tests/golden/**`` file with
an ``input``) and each API kind's reply on the seed motor.  A report is checked whole: every
declared key present (unless optional) with its declared JSON type.  Keys the declaration does
not name are allowed (the TypeScript declares what the page reads) and listed by
``PULAB_SHAPES_EXTRA=1 pytest -s tests/py/test_shapes.py``.
"""

import json
import os
import re

import pytest

from conftest import ROOT, SEED_INPUT
from pulab.api import KINDS, call_json
from pulab.ctrace.examples import EXAMPLES
from pulab.profiles.inovance.header import _NAMES
from pulab.report import report
from pulab.schema.api_shapes import API
from pulab.schema.report_shapes import REPORT
from pulab.schema.shapes import EXTRA, STR, Rec, Ref, names_of, problems
from pulab.schema.typings import typescript_files

NAMES = names_of(REPORT, API)
GOLDEN = sorted(p for p in (ROOT / "tests/golden").rglob("*.json")
                if isinstance(d := json.loads(p.read_text(encoding="utf-8")), dict) and "input" in d)
#: What an induction motor's report leaves out (the Report declaration's own comment on `acim`),
#: and its profiles: each an AcimProfile, not a ProfileReport.
ACIM_ABSENT = ["$: missing pu", "$: missing vendor", "$: missing constants", "$: missing mechanical",
               "$: missing firmware", "$.review: missing thresholds", "$.review: missing headroom"]


def _errors(value, t):
    """The type problems (extra keys left out)."""
    return [p for p in problems(json.loads(json.dumps(value)), t, NAMES) if EXTRA not in p]


def test_generated_types_are_fresh():
    """web/src/generated/*.ts is what the build writes; a shape edit needs a build."""
    for path, text in typescript_files().items():
        assert (ROOT / path).read_text(encoding="utf-8") == text, path


def test_every_name_a_shape_refers_to_is_declared():
    text = "".join(typescript_files().values())
    imported = {n.strip() for line in re.findall(r"import type \{(.*)\}", text) for n in line.split(",")}
    body = re.sub(r"/\*\*.*?\*/|//.*|'[^']*'|import .*", "", text)
    used = set(re.findall(r"\b([A-Z]\w+)\b(?!\s*[:(])", body))
    assert imported == {"Input", "Json", "Plan", "Chunk", "Points", "Summary", "Report"}
    assert used - set(NAMES) - imported - {"Record", "Partial"} == set()


def test_vendor_names_are_the_inovance_header_names():
    (const,) = [s for s in REPORT if s.name == "VENDOR_NAMES"]
    assert tuple(const.values) == _NAMES


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: str(p.relative_to(ROOT / "tests/golden")))
def test_every_golden_report_has_the_declared_shape(path):
    rep = report(json.loads(path.read_text(encoding="utf-8"))["input"])
    found = _errors(rep, Ref("Report"))
    if "acim" in rep:
        assert sorted(p for p in found if not p.startswith("$.profiles.")) == sorted(ACIM_ABSENT)
        assert _errors(rep.get("profiles", {}), Rec(STR, Ref("AcimProfile"))) == []
    else:
        assert found == []


def test_the_golden_reports_cover_every_optional_section():
    """Each optional part of the report appears in some golden report, so the test above checks it."""
    seen = set()
    for path in GOLDEN:
        rep = report(json.loads(path.read_text(encoding="utf-8"))["input"])
        seen |= {k for k in rep if k not in ("input",)}
        seen |= {f"sim.{k}" for k in rep.get("sim", {})}
        seen |= {f"loop.{k}" for k in rep.get("loop", {})}
    assert {"sim.current", "sim.pll", "datasheet", "fw", "observer", "board", "loop", "loop.robust",
            "loop.bode", "profiles", "acim"} <= seen


def test_a_wrong_report_is_caught():
    """The check fails on each kind of mistake (a type, a missing key, a member of no union)."""
    rep = json.loads(json.dumps(report(SEED_INPUT)))
    rep["warnings"] = "x"
    del rep["review"]["counts"]
    rep["review"]["findings"].append({"severity": "fatal"})
    found = _errors(rep, Ref("Report"))
    assert "$.warnings: expected array, got string" in found
    assert "$.review: missing counts" in found
    assert any(p.startswith("$.review.findings[") and "'error' | 'warning' | 'note'" in p for p in found)


SIM = {**SEED_INPUT, "sim": {"current": {"duration_s": 0.005}, "pll": {}}}
#: The seed's PI block (pulab.ctrace.examples) in the current loop, the speed loop's step
#: response and the robustness Monte Carlo: the report's parts no golden input asks for.
RICH = {**SEED_INPUT,
        "sim": {"current": {"duration_s": 0.002, "axis": "q", "code": {
            "text": EXAMPLES["pi"]["code"], "error": "pm_error_id", "output": "pm_ud",
            "integral": "pm_integral_d", "integral_shift": 12,
            "set": {"pm_kp_d": {"d": "current_pi.d.pm_kp", "q": "current_pi.q.pm_kp"},
                    "pm_ki_d": {"d": "current_pi.d.pm_ki", "q": "current_pi.q.pm_ki"},
                    "maxu": "vendor.maxu", "pm_maxout_vol": "vendor.pm_maxout_vol"}}}},
        "analysis": {"speed": {"inertia_kg_m2": 1e-5, "response": True}, "robust": {"samples": 20}}}
#: ST Motor Control Workbench's generated headers (tests/data/headers/st/README names their source).
ST = [{"name": n, "text": (ROOT / "tests/data/headers/st" / n).read_text(encoding="utf-8", errors="replace")}
      for n in ("pmsm_motor_parameters.h", "drive_parameters.h", "power_stage_parameters.h",
                "parameters_conversion.h", "parameters_conversion_g4xx.h")]
RANGES = {"input": SEED_INPUT, "ranges": {"motor.rs_ohm": [1, 2]}}
SEQUENCE = {"code": "int16_t acc; int16_t f(int16_t x) { acc += x; return acc; }", "target": "arm",
            "entry": "f", "calls": 4, "zero_unset": True, "gen": {"x": "ramp:start=0,slope=10000"}}
AUTO = """int16_t gain(int16_t x, int16_t k) { // @q k auto
  int32_t p = (int32_t)x * k; // @q p auto
  return (int16_t)(p >> 12);
}"""
#: A call, a branch, a pointer store, division's rounding and a Q annotation in one trace.
CALLS = """int16_t half(int16_t a) { return a / 2; }
int16_t f(int16_t x) { // @q x Q12 base=10 V
  int16_t y;
  int16_t *p = &y;
  if (x > 0) { y = half(x); } else { y = half(-x); }
  *p = (y >> 1) + (x / 3);
  return y;
}"""
HEADER = {"files": [{"name": "a.h", "text": "#define RS 0.35\n#define LS 0.0006\n#define F1 16384\n"
                     "#define PWM_FREQUENCY 20000\n"
                     "#define C1 (int32_t)((((int16_t)F1)*RS)/(LS*PWM_FREQUENCY))\n"}]}
AXIS = {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3, "scale": "linear"}
#: Each kind's body type, from the declaration (ReplyBody[kind]).
REPLY = NAMES["ReplyBody"].obj.fields(NAMES)[0]
REQUEST = NAMES["Request"].obj.fields(NAMES)[0]


def _reply(kind, req):
    out = json.loads(call_json(kind, json.dumps(req)))
    assert out.pop("ok") is True, out
    return out


def _cases():
    """(kind, request[, the reply body's type when not ReplyBody[kind]]) on the seed motor, each
    kind at least once."""
    integer = _reply("prove.plan", RANGES)["plan"]["names"][0]
    entries = _reply("prove", RANGES)["proof"]["integers"]
    ti = _reply("vendors.header", {"input": SEED_INPUT, "profile": "ti"})["text"]
    sweep = {"input": SEED_INPUT, "x": AXIS}
    return [
        ("report", SEED_INPUT), ("report", SIM), ("report", RICH),
        ("qcalc", {"value": 0.5, "format": "Q0.15"}), ("qcalc", {"raw": "0x8000", "format": "Q0.15"}),
        ("export.header", {"input": SEED_INPUT}),
        ("export.csv_current", {"input": SIM}),
        ("export.csv_pll", {"input": SIM}),
        ("sweep", sweep), ("sweep.plan", sweep), ("sweep.chunk", {**sweep, "start": 1, "count": 2}),
        ("sweep.merge", {**sweep, "summaries": []}),
        ("batch", {"csv": "name,motor.rated_voltage_v\na,17\nb,x\n"}),
        ("trace", {"code": "Uint16 v; long x = v*10; long *p = &x;", "set": {"v": 6554}}),
        ("trace", {"code": CALLS, "entry": "f", "target": "arm", "set": {"x": -5}}),
        # ReplyBody says Trace for every trace; with `calls` the reply is a TraceSequence (the
        # request's own doc says so; the code panel casts to it)
        ("trace", SEQUENCE, Ref("TraceSequence")),
        ("trace.examples", {}),
        ("trace.prove", {"code": AUTO, "target": "arm", "entry": "gain",
                         "range": {"x": [-4096, 4096], "k": ["-1.5", "2.0"]}}),
        ("trace.prove", {"code": "int16_t f(int16_t a) { int16_t b = a * 2; return b; }", "target": "arm",
                         "entry": "f", "range": {"a": [0, 20000]}}),
        ("vendors.header", {"input": SEED_INPUT, "profile": "ti"}),
        ("vendors.translate", {"input": SEED_INPUT, "from": "inovance", "axis": "q",
                               "values": {"pm_kp": 1180, "pm_ki": 4720}}),
        ("prove", RANGES), ("prove", {**RANGES, "ranges": {"drive.udc_v": [24, 7000]}}),
        ("prove.plan", RANGES),
        ("prove.integer", {**RANGES, "name": integer}),
        ("prove.summary", {**RANGES, "integers": entries}),
        *[("prove.propose", {**RANGES, "profile": p}) for p in ("inovance", "ti", "nxp", "st", "microchip")],
        ("course.spec", {}),
        ("course.check", {"input": SEED_INPUT, "id": "warmup-current", "answer": "1"}),
        ("course.answers", {"input": SEED_INPUT}),
        ("course.trainees", {"start": 1, "count": 2}),
        ("audit", HEADER), ("audit", {"files": [{"name": "user.h", "text": ti}], "profile": "ti"}),
        ("audit", {"files": ST, "profile": "st"}),
    ]


def test_the_request_and_reply_kinds_are_the_api_kinds():
    assert set(REQUEST) == set(REPLY) == set(KINDS)


def test_each_kind_replies_in_its_declared_shape():
    cases = _cases()
    assert {kind for kind, *_ in cases} == set(KINDS)
    for kind, req, *t in cases:
        assert _errors(_reply(kind, req), t[0] if t else REPLY[kind][0]) == [], kind


def test_each_request_sent_has_its_declared_shape():
    """The requests above (each answered, so each one pulab reads) are Request[kind], top-level
    extra keys included: a request field the declaration lacks is one the page cannot send (deeper
    down, echoed data such as prove.summary's entries keeps the reply's extra keys)."""
    for kind, req, *_ in _cases():
        found = problems(req, REQUEST[kind][0], NAMES)
        assert [p for p in found if EXTRA not in p or p.startswith("$: ")] == [], kind


def test_extra_keys_are_listed_on_request():
    """Not a check: with PULAB_SHAPES_EXTRA=1, print the keys the declarations leave out."""
    if not os.environ.get("PULAB_SHAPES_EXTRA"):
        pytest.skip("set PULAB_SHAPES_EXTRA=1 to list them")
    extra = set()
    for path in GOLDEN:
        rep = report(json.loads(path.read_text(encoding="utf-8"))["input"])
        extra |= {re.sub(r"\[\d+\]", "[]", p) for p in problems(json.loads(json.dumps(rep)), Ref("Report"), NAMES)
                  if EXTRA in p}
    for kind, req, *t in _cases():
        found = problems(_reply(kind, req), t[0] if t else REPLY[kind][0], NAMES)
        extra |= {f"{kind} " + re.sub(r"\[\d+\]", "[]", p) for p in found if EXTRA in p}
    print("\n".join(sorted(extra)))
