"""pulab.api: one entry point and one dispatch key (``kind``) for every request
(docs/contract.md, "API")."""

import json

import pytest

import pulab.api
from pulab.api import KINDS, call_json, call_json_steps

from conftest import SEED_INPUT

AXIS = {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3}
SIM = {**SEED_INPUT, "sim": {"current": {"duration_s": 0.005}}}


def reply(kind, req):
    out = json.loads(call_json(kind, json.dumps(req)))
    assert isinstance(out, dict) and isinstance(out["ok"], bool)
    return out


def test_kinds_are_the_documented_ones():
    assert sorted(KINDS) == sorted([
        "report", "qcalc", "export.header", "export.csv_current", "export.csv_pll", "sweep",
        "sweep.plan", "sweep.chunk", "sweep.merge", "batch", "trace", "trace.examples",
        "trace.prove", "vendors.header", "vendors.translate", "prove", "prove.plan", "prove.integer",
        "prove.summary", "prove.propose",
        "course.check", "course.answers", "course.spec",
        "course.trainees", "audit"])


# Each kind on a request with a known answer (values checked elsewhere against oracles; here
# that each kind reaches its own computation).
@pytest.mark.parametrize("kind, req, check", [
    ("report", SEED_INPUT, lambda r: r["report"]["vendor"]["Rpm"]["value"] > 0),
    ("qcalc", {"value": 0.5, "format": "Q0.15"},
     lambda r: (r["result"]["raw"], r["result"]["hex"]) == (16384, "0x4000")),
    ("export.header", {"input": SEED_INPUT}, lambda r: "#define PULAB_RPM" in r["text"]),
    ("export.csv_current", {"input": SIM}, lambda r: r["text"].splitlines()[0].startswith("t_s")),
    ("sweep.plan", {"input": SEED_INPUT, "x": AXIS},
     lambda r: r["plan"]["x"]["values"] == [1.0, 1.5, 2.0] and r["plan"]["total"] == 3),
    ("sweep.chunk", {"input": SEED_INPUT, "x": AXIS, "start": 1, "count": 2},
     lambda r: r["chunk"]["points"]["x"] == [1.5, 2.0]),
    ("sweep", {"input": SEED_INPUT, "x": AXIS}, lambda r: r["sweep"]["points"]["x"] == [1.0, 1.5, 2.0]),
    ("batch", {"csv": "name,motor.rated_voltage_v\na,17\n"}, lambda r: r["total"] == 1),
    # C28x int is 16 bits: 6554·10 = 65540 is computed as an unsigned int and wraps to 4
    ("trace", {"code": "Uint16 v; long x = v*10;", "set": {"v": 6554}},
     lambda r: r["vars"]["x"]["value"] == 4),
    ("trace.examples", {}, lambda r: "c28x" in r["targets"] and r["examples"][0]["code"]),
    # arm: a·2 is an int; 20000·2 = 40000 does not fit the int16 b
    ("trace.prove", {"code": "int16_t f(int16_t a) { int16_t b = a * 2; return b; }",
                     "target": "arm", "entry": "f", "range": {"a": [0, 20000]}},
     lambda r: r["proof"]["verdict"] == "violated" and r["proof"]["counterexample"]["a"] > 16383),
    ("vendors.header", {"input": SEED_INPUT, "profile": "ti"},
     lambda r: "#define USER_MTR1_KP_IQ_IQ" in r["text"]),
    ("vendors.translate", {"input": SEED_INPUT, "from": "inovance", "axis": "q",
                           "values": {"pm_kp": 1180, "pm_ki": 4720}},
     lambda r: r["translation"]["round_trip"]["values"] == {"pm_kp": 1180, "pm_ki": 4720}),
    # 16384·0.35/(0.0006·20000) = 477.87: the (int32_t) cast truncates to 477
    ("audit", {"files": [{"name": "a.h", "text": "#define RS 0.35\n#define LS 0.0006\n"
                           "#define F1 16384\n#define PWM_FREQUENCY 20000\n"
                           "#define C1 (int32_t)((((int16_t)F1)*RS)/(LS*PWM_FREQUENCY))\n"}]},
     lambda r: r["audit"]["profile"] == "st" and r["audit"]["macros"]["C1"]["value"] == 477),
])
def test_every_kind_answers(kind, req, check):
    out = reply(kind, req)
    assert out["ok"] is True, out
    assert check(out)


def test_sweep_merge_of_the_chunks_is_the_whole_sweep_summary():
    req = {"input": SEED_INPUT, "x": AXIS}
    parts = [reply("sweep.chunk", {**req, "start": s, "count": c})["chunk"]["summary"]
             for s, c in ((0, 2), (2, 1))]
    merged = reply("sweep.merge", {**req, "summaries": parts})["summary"]
    assert merged == reply("sweep", req)["sweep"]["summary"]


def test_an_unknown_kind_is_an_error_naming_kind():
    for kind in ("nope", "", "sweep.", "Report", None, 3):
        out = json.loads(call_json(kind, "{}"))
        assert out["ok"] is False and out["field"] == "kind" and out["code"] == "not_choice", out


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_every_kind_has_the_parser_limits(kind):
    field = KINDS[kind][0]
    deep = json.loads(call_json(kind, "[" * 40 + "]" * 40))
    assert (deep["ok"], deep["field"], deep["code"]) == (False, field, "json_too_deep")
    bad = json.loads(call_json(kind, '{"a": 1,}'))
    assert (bad["ok"], bad["field"], bad["code"]) == (False, field, "json_invalid")
    none = json.loads(call_json(kind, None))
    assert (none["ok"], none["field"], none["code"]) == (False, field, "json_not_text")


def test_the_one_kind_entry_points_are_gone():
    assert pulab.api.__all__ == ["KINDS", "call_json", "call_json_steps"]
    assert not [name for name in vars(pulab.api) if name.endswith("_json") and name != "call_json"]


def test_the_tracer_error_says_where_and_which_inputs():
    out = reply("trace", {"code": "x = 1 +;"})
    assert (out["ok"], out["field"], out["line"], out["column"]) == (False, "code", 1, 8)
    out = reply("trace", {"code": "Uint16 v; long x = v;", "set": {"v": "0x1FFFF"}})
    assert out["ok"] is False and out["field"].startswith("set") and out["inputs"] == ["v"], out


def test_report_in_slices_is_the_same_text_and_cancellable():
    text = json.dumps(SIM)
    gen = call_json_steps("report", text)
    slices = 0
    try:
        while True:
            next(gen)
            slices += 1
    except StopIteration as done:
        assert done.value == call_json("report", text)
    assert slices >= 2
    gen = call_json_steps("report", text)
    next(gen)
    gen.close()  # cancelled between two slices: nothing raised


def test_other_kinds_in_slices_answer_at_once():
    gen = call_json_steps("qcalc", '{"value": 0.5, "format": "Q0.15"}')
    with pytest.raises(StopIteration) as done:
        next(gen)
    assert json.loads(done.value.value)["result"]["raw"] == 16384
