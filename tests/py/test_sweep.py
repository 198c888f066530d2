"""The family sweep (pulab.analyses.sweep): boundaries against an independent oracle, chunks, errors.

The expected boundaries come from tests/oracle/sweep_oracle.py, which never imports pulab:
it scans the firmware's raw integers with plain Python ints (seed 1.4-3 … 1.4-6) and walks
doubles with math.nextafter, where pulab bisects.  Per-point values are checked against
the golden-vector oracle (tests/oracle/oracle.py, numpy fixed-width integers).
"""
import copy
import json
import math
import sys

import pytest

from conftest import ROOT, SEED_INPUT, chinese
from pulab import InputError
from pulab.api import call_json
from pulab.analyses.sweep import chunk, make_plan, merge, sweep

sys.path.insert(0, str(ROOT / "tests/oracle"))
import oracle  # noqa: E402  (the golden-vector oracle)
import sweep_oracle as so  # noqa: E402

# The seed motor: 17 V, f_b = 220 Hz → FullFreq01 = 22000; LD = 60 (0.6 mH in 0.01 mH).
F01, LD = 22000, 60


def _seed(**motor):
    inp = copy.deepcopy(SEED_INPUT)
    inp["motor"].update(motor)
    return inp


def _bounds(s, name):
    return [b for b in s["summary"]["boundaries"] if b["name"] == name]


def test_seed_current_sweep_ld_wrap_and_m_base_l_zero_match_the_oracle():
    s = sweep({"input": _seed(), "x": {"path": "motor.rated_current_a", "start": 1,
                                       "stop": 200, "n": 1000}})
    expected = []
    lo = so.raw_of(1, 100)
    while True:
        change = so.first_status_change(lambda c: so.ld_status(LD, 17, c, F01), lo,
                                        so.raw_of(200, 100))
        if change is None:
            break
        expected.append(change)
        lo = change[0]
    assert [(k, a, b) for k, a, b in expected] == [(6948, "ok", "store"),
                                                   (12506, "store", "div0")]
    got = _bounds(s, "vendor.LD")
    assert [(b["from"], b["to"]) for b in got] == [(a, b) for _, a, b in expected]
    for b, (k, _, _) in zip(got, expected):
        at = so.first_double(k, 100.0)
        assert b["at"] == at and b["before"] == math.nextafter(at, -math.inf)
        assert b["raw"] == {"Current": [k - 1, k]}
    # m_BaseL is what reaches 0: 1 → 0 across the second boundary (seed 1.4-3).
    assert got[1]["intermediates"]["m_BaseL"] == [so.m_base_l(17, 12505, F01), 0] == [1, 0]
    assert got[0]["intermediates"]["m_BaseL"] == [2, 1]
    # Regions run from boundary to boundary and end at the axis ends.
    assert s["summary"]["regions"]["vendor.LD"] == [
        {"status": "ok", "from": 1.0, "to": got[0]["before"]},
        {"status": "store", "from": got[0]["at"], "to": got[1]["before"]},
        {"status": "div0", "from": got[1]["at"], "to": 200.0}]


def test_voltage_sweep_at_30_a_ld_wrap_and_m_base_l_zero_match_the_oracle():
    # At 30 A (Current = 3000) the seed's inductance code divides by zero below 4.5 V and
    # wraps LD up to 7.5 V: the voltage boundaries of both.
    s = sweep({"input": _seed(rated_current_a=30), "x": {
        "path": "motor.rated_voltage_v", "start": 1, "stop": 100, "n": 300, "scale": "log"}})
    lo, expected = 1, []
    while (change := so.first_status_change(lambda v: so.ld_status(LD, v, 3000, F01), lo,
                                            100)) is not None:
        expected.append(change)
        lo = change[0]
    assert [(a, b) for _, a, b in expected] == [("div0", "store"), ("store", "ok")]
    got = _bounds(s, "vendor.LD")
    assert [(b["from"], b["to"]) for b in got] == [(a, b) for _, a, b in expected]
    for b, (k, _, _) in zip(got, expected):
        assert b["at"] == so.first_double(k, 1.0)
        assert b["raw"] == {"Voltage": [k - 1, k]}
    assert got[0]["intermediates"]["m_BaseL"][0] == 0


def test_ld_resolution_collapses_at_low_voltage():
    # Same motor, same L: the LD error is the m_BaseL quantization (seed 1.4-15), which
    # grows as the voltage (and so m_BaseL ∝ U/(I·f_b)) goes down.
    s = sweep({"input": _seed(), "x": {"path": "motor.rated_voltage_v", "start": 1,
                                       "stop": 400, "n": 400, "scale": "log"}})
    pts = s["points"]
    err = pts["integers"]["vendor.LD"]["error_pct"]
    base_l = pts["intermediates"]["m_BaseL"]
    for k in range(0, 400, 37):
        v = so.raw_of(pts["x"][k], 1.0)
        assert base_l[k] == so.m_base_l(v, 150, F01)
    low = [abs(e) for x, e in zip(pts["x"], err) if x < 5]
    mid = [abs(e) for x, e in zip(pts["x"], err) if 50 <= x <= 200]
    assert max(low) > 5 and max(mid) < 1


def test_point_values_match_the_golden_oracle():
    s = sweep({"input": _seed(), "x": {"path": "motor.rated_current_a", "start": 0.5,
                                       "stop": 60, "n": 40}})
    for k in range(0, 40, 3):
        ref = oracle.oracle_report(_seed(rated_current_a=s["points"]["x"][k]))
        for name in ("Rpm", "LD", "FluxRotor", "pm_maxout_vol"):
            col = s["points"]["integers"][f"vendor.{name}"]
            assert col["value"][k] == ref["vendor"][name]["value"]
            assert col["error_pct"][k] == pytest.approx(ref["vendor"][name]["error_pct"],
                                                        rel=1e-9, abs=1e-12)
        for key in ("pm_kp", "pm_ki"):
            assert s["points"]["integers"][f"current_pi.d.{key}"]["value"][k] == \
                ref["current_pi"]["d"][key]


def test_pm_ki_rounds_to_zero_below_a_control_period_found_to_adjacent_doubles():
    s = sweep({"input": _seed(), "x": {"path": "drive.ts_s", "start": 1e-4, "stop": 1e-8,
                                       "n": 50, "scale": "log"}})
    (b,) = _bounds(s, "current_pi.d.pm_ki")
    assert (b["from"], b["to"]) == ("ok", "zero")
    assert b["at"] == math.nextafter(b["before"], -math.inf)  # decreasing axis
    assert so.pm_ki(1.5, 17, 1.5, b["before"]) == 1 and so.pm_ki(1.5, 17, 1.5, b["at"]) == 0


def test_raw_integer_axis_steps_through_integers():
    s = sweep({"input": _seed(rated_current_a=60), "x": {"path": "raw.LD", "start": 1,
                                                         "stop": 2000, "n": 100}})
    assert all(isinstance(v, int) for v in s["x"]["values"])
    (b,) = _bounds(s, "vendor.LD")
    k = so.first_status_change(lambda ld: so.ld_status(ld, 17, 6000, F01), 1, 2000)[0]
    assert (b["from"], b["to"], b["before"], b["at"]) == ("ok", "store", k - 1, k)


def test_the_end_of_uint16_is_an_invalid_region_naming_the_field():
    s = sweep({"input": _seed(), "x": {"path": "motor.rated_current_a", "start": 600,
                                       "stop": 700, "n": 11}})
    b = _bounds(s, "vendor.FreqPer")[0]
    assert (b["from"], b["to"]) == ("ok", "invalid")
    assert b["at"] == so.first_double(65536, 100.0)
    assert b["message"].startswith("raw.Current: 65536 (from motor.rated_current_a) is outside")
    assert chinese(b["message_zh"]) and "超出" in b["message_zh"]
    assert s["points"]["error"][-1].startswith("raw.Current:")


@pytest.mark.parametrize("req", [
    {"input": SEED_INPUT, "x": {"path": "motor.rated_voltage_v", "start": 1, "stop": 300,
                                "n": 37, "scale": "log"},
     "y": {"path": "motor.rated_current_a", "start": 0.5, "stop": 200, "n": 23, "scale": "log"}},
    {"input": SEED_INPUT, "x": {"path": "motor.rated_current_a", "start": 1, "stop": 200,
                                "n": 401}},
], ids=["2d", "1d"])
def test_chunks_merged_equal_the_whole_sweep(req):
    whole = sweep(req)
    plan = make_plan(json.loads(json.dumps(req)))
    parts = [chunk(plan, a, min(53, plan.total - a)) for a in range(0, plan.total, 53)]
    merged = merge(plan, [json.loads(json.dumps(p["summary"])) for p in parts])
    assert json.dumps(merged, sort_keys=True) == json.dumps(whole["summary"], sort_keys=True)
    for key in ("x", "error"):
        assert sum((p["points"][key] for p in parts), []) == whole["points"][key]


def test_2d_boundaries_along_x_match_the_oracle_on_every_row():
    s = sweep({"input": SEED_INPUT,
               "x": {"path": "motor.rated_voltage_v", "start": 1, "stop": 60, "n": 30},
               "y": {"path": "motor.rated_current_a", "start": 10, "stop": 100, "n": 7}})
    rows = {}
    for b in _bounds(s, "vendor.LD"):
        if b["axis"] == "x":
            rows.setdefault(b["other"], []).append(b)
    assert rows
    for amps, got in rows.items():
        c = so.raw_of(amps, 100.0)
        lo, expected = 1, []
        while (ch := so.first_status_change(lambda v: so.ld_status(LD, v, c, F01), lo, 60)):
            expected.append(ch)
            lo = ch[0]
        # A grid can only miss a region that starts and ends between two of its points;
        # here every row's boundaries are all the oracle's, at the same doubles.
        assert [(so.raw_of(b["at"], 1.0), b["from"], b["to"]) for b in got] == expected
        for b in got:
            assert b["at"] == so.first_double(so.raw_of(b["at"], 1.0), 1.0)


@pytest.mark.parametrize("req, field", [
    ({"x": {"path": "motor.rs_ohm", "start": 1, "stop": 2}}, "input"),
    ({"input": {}, "x": {"path": "motor.nope", "start": 1, "stop": 2}}, "sweep.x.path"),
    ({"input": {}, "x": {"path": "conventions.base", "start": 1, "stop": 2}}, "sweep.x.path"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 0, "stop": 2, "scale": "log"}},
     "sweep.x.start"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 1}}, "sweep.x.n"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": "a", "stop": 2}}, "sweep.x.start"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "step": 1}},
     "sweep.x.step"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2},
      "y": {"path": "motor.rs_ohm", "start": 1, "stop": 2}}, "sweep.y.path"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 1000},
      "y": {"path": "motor.ld_h", "start": 1, "stop": 2, "n": 1000}}, "sweep"),
    ({"input": SEED_INPUT, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2},
      "profile": "infineon"}, "sweep.profile"),  # nxp is a profile
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2}, "start": 500,
      "kind": "sweep.chunk"}, "sweep.chunk.start"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2},
      "summaries": [{"boundaries": [1]}], "kind": "sweep.merge"}, "sweep.summaries"),
    ({"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2}, "kind": "sweep.fly"},
     "kind"),
])
def test_bad_requests_name_the_field_in_both_languages(req, field):
    req = dict(req)
    out = json.loads(call_json(req.pop("kind", "sweep"), json.dumps(req)))
    assert out["ok"] is False and out["field"] == field, out
    assert chinese(out["message_zh"]), out["message"]


def test_api_chunks_report_progress_and_merge():
    req = {"input": SEED_INPUT, "x": {"path": "motor.rated_current_a", "start": 1,
                                      "stop": 200, "n": 100}}
    plan = json.loads(call_json("sweep.plan", json.dumps(req)))["plan"]
    assert plan["total"] == 100 and plan["names"][1] == "vendor.LD"
    parts = [json.loads(call_json("sweep.chunk", json.dumps({**req, "start": a, "count": 25})))
             ["chunk"] for a in range(0, 100, 25)]
    merged = json.loads(call_json("sweep.merge", json.dumps(
        {**req, "summaries": [p["summary"] for p in parts]})))["summary"]
    whole = json.loads(call_json("sweep", json.dumps(req)))["sweep"]["summary"]
    assert merged == whole
    # The worst case of LD opens as a motor: its input gives the report's state.
    w = next(w for w in whole["worst"] if w["name"] == "vendor.LD")
    assert w["status"] == "div0" and w["input"]["motor"]["rated_current_a"] == w["x"]
    # The report opens it and says which integers the firmware cannot compute there.
    from pulab import report
    problems = report(w["input"])["firmware"]["inovance"]["problems"]
    assert "LD" in problems[0]["results"] and "divides by zero" in problems[0]["message"]


def test_cli_sweep_text_and_csv(tmp_path):
    import subprocess
    f = tmp_path / "seed.json"
    f.write_text(json.dumps(SEED_INPUT))
    env = {"PYTHONPATH": str(ROOT / "py")}
    out = subprocess.run([sys.executable, "-m", "pulab", "sweep", str(f), "--x",
                          "motor.rated_current_a=1:200:200"], capture_output=True, text=True,
                         env=env)
    assert out.returncode == 0, out.stderr
    assert "vendor.LD" in out.stdout and "69.47500000000001" in out.stdout
    csv_out = subprocess.run([sys.executable, "-m", "pulab", "sweep", str(f), "--x",
                              "motor.rated_current_a=1:200:5", "--format", "csv"],
                             capture_output=True, text=True, env=env)
    lines = csv_out.stdout.splitlines()
    assert lines[0].startswith("motor.rated_current_a,error,vendor.Rpm.value,") and len(lines) == 6
    bad = subprocess.run([sys.executable, "-m", "pulab", "sweep", str(f), "--x", "motor.rs_ohm"],
                         capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and bad.stderr.startswith("error: sweep.x: ")
    assert len(bad.stderr.strip().splitlines()) == 1


def test_vendor_reads_lists_every_raw_field_a_result_depends_on():
    # The sweep reuses a vendor result while the raw fields VENDOR_READS names repeat; changing
    # any other field must leave the result as it is (value, flags and whole trace).
    import random
    from pulab.profiles.inovance.code import RAW_FIELDS, VENDOR_READS, VENDOR_RESULTS
    rng = random.Random(3)
    for _ in range(200):
        raw = {k: rng.choice((1, 2, 7, 150, 1500, 22000, 65535, rng.randrange(65536)))
               for k in RAW_FIELDS}
        for name, f in VENDOR_RESULTS.items():
            other = dict(raw)
            for k in RAW_FIELDS:
                if k not in VENDOR_READS[name]:
                    other[k] = rng.randrange(65536)
            try:
                a = f(raw, "10uH")
            except InputError as e:
                with pytest.raises(InputError, match=e.message[:20]):
                    f(other, "10uH")
                continue
            assert f(other, "10uH") == a, name


def test_another_profile_is_swept_through_the_report(monkeypatch):
    # A report wrapped with one synthetic profile checks the lookup through
    # report["profiles"][NAME]["constants"], independent of the real profiles' numbers.
    from pulab.analyses import integers
    from pulab.report import report as real_report

    def with_profile(inp):
        r = real_report(inp)
        rpm = r["vendor"]["Rpm"]
        r["profiles"] = {"toy": {"constants": {"RS": {"value": rpm["value"], "ideal": rpm["ideal"],
                                                     "error_pct": rpm["error_pct"],
                                                     "flags": rpm["flags"]}}}}
        return r

    monkeypatch.setattr(integers, "report", with_profile)
    s = sweep({"input": _seed(), "profile": "toy",
               "x": {"path": "motor.rated_current_a", "start": 1, "stop": 30, "n": 30}})
    assert s["names"] == ["profiles.toy.constants.RS"]
    (a, b) = _bounds(s, "profiles.toy.constants.RS")
    assert (a["from"], a["to"], b["to"]) == ("ok", "store", "wrap")
    ref = sweep({"input": _seed(), "x": {"path": "motor.rated_current_a", "start": 1, "stop": 30,
                                         "n": 30}})
    assert [x["at"] for x in (a, b)] == [x["at"] for x in _bounds(ref, "vendor.Rpm")]


@pytest.mark.parametrize("inp", [{"motor": 5}, {"motor": None}, {"raw": []}, {"drive": "x"},
                                 {"motor": {"rated_current_a": "abc"}}, {"sim": 3}, {"x": {}}])
def test_hostile_inputs_become_invalid_points_never_exceptions(inp):
    for kind in ("sweep", "sweep.chunk"):
        out = json.loads(call_json(kind, json.dumps({"input": inp, "x": {
            "path": "motor.rated_current_a", "start": 1, "stop": 2, "n": 3}})))
        assert out["ok"] is True
        pts = (out.get("sweep") or out["chunk"])["points"]
        assert all(e for e in pts["error"]) and all(chinese(e)
                                                    for e in pts["error_zh"]), pts["error"]
