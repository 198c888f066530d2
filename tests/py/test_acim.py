"""Induction motors (motor.kind = acim): golden vectors of the independent oracle
(tests/oracle/acim_oracle.py), the vendors' printed constants, bad input, the PMSM untouched."""

from __future__ import annotations

import copy
import json
import pathlib
import re
import struct
import subprocess
import sys

import pytest

import pulab
from pulab.schema.errors import InputError

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "oracle"))
from golden_files import differences  # noqa: E402

GOLDEN = ROOT / "tests" / "golden" / "acim"
CASES = sorted(p for p in GOLDEN.glob("[0-9]*.json"))
ERRORS = json.loads((GOLDEN / "errors.json").read_text(encoding="utf-8"))["cases"]
HEADERS = ROOT / "tests" / "data" / "headers"
REL = 1e-12

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}


def _load(path: pathlib.Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def _case(stem: str) -> dict:
    return _load(GOLDEN / f"{stem}.json")


def _f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


def test_golden_files_are_fresh():
    r = subprocess.run([sys.executable, "acim_oracle.py", "--check"], capture_output=True,
                       text=True, cwd=ROOT / "tests" / "oracle")
    assert r.returncode == 0, r.stdout + r.stderr


def test_three_real_motors_and_a_convention():
    assert len(CASES) >= 4 and len(ERRORS) >= 8


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_golden(path):
    case = _load(path)
    r = pulab.report(case["input"])
    exp = case["expected"]
    got = {"acim": {k: v for k, v in r["acim"].items() if k != "inovance"},
           "current_pi": r["current_pi"],
           "vendor_values": {v: {k: c["value"] for k, c in r["profiles"][v]["constants"].items()}
                             for v in exp["vendor_values"]}}
    if "speed_bases" in exp:
        got["speed_bases"] = r["loop"]["speed"]["bases"]
    if "acim_flux" in exp:
        got["acim_flux"] = {k: v for k, v in r["acim_flux"].items() if k != "trace"}
    assert differences(exp, got, REL, 0.0) == []


def test_the_issue_numbers():
    a = pulab.report(_case("01_st_mez_acim")["input"])["acim"]
    assert a["ls_h"] == pytest.approx(0.0615, rel=1e-15) and a["lr_h"] == pytest.approx(0.0615, rel=1e-15)
    assert a["sigma"] == pytest.approx(0.2712671, abs=5e-8)
    assert a["tau_r_s"] == pytest.approx(0.15375, rel=1e-15)


@pytest.mark.parametrize("case", ERRORS, ids=[c["field"] + str(i) for i, c in enumerate(ERRORS)])
def test_bad_input_names_the_field(case):
    with pytest.raises(InputError) as e:
        pulab.report(case["input"])
    assert e.value.field == case["field"]


def test_cli_exit_2_naming_the_field():
    bad = next(c for c in ERRORS if c["field"] == "motor.rated_speed_rpm")
    r = subprocess.run([sys.executable, "-m", "pulab", "report", "-"], input=json.dumps(bad["input"]),
                       capture_output=True, text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT / "py")})
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.startswith("error: motor.rated_speed_rpm: must be below the synchronous speed")
    assert len(r.stderr.strip().splitlines()) == 1


def test_cli_report_of_an_induction_motor():
    r = subprocess.run([sys.executable, "-m", "pulab", "report", "-"],
                       input=json.dumps(_case("01_st_mez_acim")["input"]), capture_output=True,
                       text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT / "py")})
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["acim"]["tau_r_s"] == 0.15375


def _defines(path: pathlib.Path) -> dict:
    """The header's float constants: name → the printed decimal text."""
    out = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        m = re.match(r"#define\s+(\w+)\s+\(\(float\)\(([-0-9.eE]+)\)\)", line) or \
            re.match(r"#define\s+(\w+)\s+\(([-0-9.eE]+)F\)", line) or \
            re.match(r"#define\s+(\w+)\s+([-0-9.]+)\s", line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


@pytest.mark.parametrize("vendor, header, case", [
    ("nxp", "acim_m1_acim_appconfig_hvpkv58f.h", "02_nxp_hvpkv58f"),
    ("st", "acim_motor_parameters_mez.h", "01_st_mez_acim"),
    ("st", "acim_motor_parameters_lso_g431.h", "04_st_g431_lms"),
])
def test_vendor_header_reproduced(vendor, header, case):
    """Every constant the profile writes that the public header prints: the same decimal text
    at the header's precision, and the same C float."""
    printed = _defines(HEADERS / vendor / header)
    constants = pulab.report(_case(case)["input"])["profiles"][vendor]["constants"]
    shared = sorted(set(printed) & set(constants))
    assert len(shared) >= (10 if vendor == "nxp" else 12), shared
    for name in shared:
        text, c = printed[name], constants[name]
        assert f"{c['ideal']:.{_decimals(text)}f}" == f"{float(text):.{_decimals(text)}f}", name
        assert c["value"] == _f32(float(text)), name
        assert c["format"] == "float32" and c["flags"] == []


def test_vendors_without_acim_say_so():
    p = pulab.report(_case("01_st_mez_acim")["input"])["profiles"]
    assert p["nxp"]["available"] and p["st"]["available"] and p["ti"]["available"]
    assert p["ti"]["constants"]["Kr"]["format"] == "IQ24"
    for name in ("inovance", "microchip"):
        assert p[name] == {"available": False, "reason": "no public induction-motor scaling is "
                                                         "modelled for this vendor in pu-lab",
                           "reason_zh": "pu-lab 未建模该厂商公开的感应电机标定"}
    for name in ("nxp", "st", "ti"):     # what is not computed, said in both languages
        assert p[name]["not_covered"] and p[name]["not_covered_zh"] != p[name]["not_covered"]


def test_loop_is_the_pmsm_loop_on_the_sigma_plant():
    """The loop analysis of an induction motor equals a PMSM's with R = R_σ, L = σ·L_s."""
    inp = copy.deepcopy(_case("01_st_mez_acim")["input"])
    inp["analysis"] = {}
    r = pulab.report(inp)
    a = r["acim"]
    m = inp["motor"]
    pmsm = {"motor": {"rated_voltage_v": m["rated_voltage_v"], "rated_current_a": m["rated_current_a"],
                      "rated_freq_hz": m["rated_freq_hz"], "rs_ohm": a["r_sigma_ohm"],
                      "ld_h": a["sigma_ls_h"], "lq_h": a["sigma_ls_h"], "bemf_v": 30,
                      "pole_pairs": m["pole_pairs"]}, "drive": inp["drive"], "analysis": {}}
    q = pulab.report(pmsm)
    for axis in ("d", "q"):
        for key in ("phase_margin_deg", "gain_margin_db", "crossover_hz", "bandwidth_hz"):
            assert r["loop"]["current"][axis][key] == q["loop"]["current"][axis][key]
        assert r["current_pi"][axis] == q["current_pi"][axis]


def test_review_findings():
    r = pulab.report(_case("01_st_mez_acim")["input"])
    codes = {f["code"]: f for f in r["review"]["findings"]}
    assert codes["acim_rr_drift"]["severity"] == "warning"
    assert "53.1 %" in codes["acim_rr_drift"]["message"]
    assert codes["acim_flux_build"]["severity"] == "note"
    # the ST example's I_m = 0.55 A gives 2.63 Hz of slip where the nameplate says 4.33 Hz
    assert codes["acim_slip_mismatch"]["value"] == pytest.approx(-39.39, abs=0.01)
    estimated = pulab.report(_case("03_krause_3hp_peak")["input"])["review"]["findings"]
    assert "acim_im_estimated" in {f["code"] for f in estimated}
    hi = copy.deepcopy(_case("01_st_mez_acim")["input"])
    hi["motor"]["magnetizing_current_a"] = 1.6
    r = pulab.report(hi)
    assert r["acim"]["torque_current_a"] is None and r["review"]["counts"]["error"] == 1


def test_pmsm_fields_refuse_acim_ones_and_back():
    inp = copy.deepcopy(SEED)
    inp["motor"]["rr_ohm"] = 0.4
    with pytest.raises(InputError, match="motor.rr_ohm: is only used with kind = acim"):
        pulab.report(inp)
    inp = copy.deepcopy(SEED)
    inp["datasheet"] = {"lms_h": 0.035}
    with pytest.raises(InputError, match="datasheet.lms_h"):
        pulab.report(inp)
    bad = copy.deepcopy(_case("01_st_mez_acim")["input"])
    bad["motor"]["kind"] = "dc"
    with pytest.raises(InputError, match="motor.kind"):
        pulab.report(bad)


def test_pmsm_report_holds_no_kind():
    r = pulab.report(copy.deepcopy(SEED))
    assert "kind" not in r["input"]["motor"] and "acim" not in r
    explicit = copy.deepcopy(SEED)
    explicit["motor"]["kind"] = "pmsm"
    assert json.dumps(pulab.report(explicit)) == json.dumps(r)


def test_text_format_and_families_refuse():
    inp = _case("01_st_mez_acim")["input"]
    from pulab.report import format_text
    text = format_text(pulab.report(inp))
    assert "Induction motor (I_m given)" in text and "tau_r_s                0.15375" in text
    assert "Profile microchip: no public induction-motor scaling" in text
    from pulab.analyses.sweep import make_plan
    with pytest.raises(InputError) as e:
        make_plan({"input": inp, "x": {"path": "motor.rated_current_a", "start": 1, "stop": 2}})
    assert e.value.field == "motor.kind"


def test_benchmark_line():
    from pulab.benchmark import ACIM, acim_timing, format_run
    assert pulab.report(ACIM)["loop"]["speed"]["bases"]["kt_nm_per_a"] > 0
    t = acim_timing(1)
    assert set(t) == {"plain", "loop"} and all(x > 0 for x in t.values())
    r = {"python": "cpython", "platform": "test", "report_ms": {}, "acim_ms": t,
         "sim": {"steps": 1, "total_s": 1.0, "steps_per_s": 1.0, "fixed_no_memo_s": 1.0,
                 "vendors_s": 1.0}}
    assert "report(), induction motor:" in format_run(r)


def test_every_api_kind_answers_an_induction_motor():
    """Each kind that takes an input: a report of it, or an error naming a field (never a crash)."""
    from pulab.api import KINDS, call_json
    inp = _case("01_st_mez_acim")["input"]
    valid = {"input": inp, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3},
             "profile": "nxp", "from": "inovance", "axis": "q", "values": {"pm_kp": 1180, "pm_ki": 4720},
             "summaries": [], "start": 0, "count": 1, "ranges": {"motor.rs_ohm": [1, 2]},
             "budget": 20, "name": "vendor.Rpm", "integers": {}, "id": "acim-sigma", "answer": "0.27"}
    replies = {}
    for kind in KINDS:
        if kind.startswith(("trace", "qcalc", "batch", "course.spec", "course.trainees", "audit")):
            continue
        req = inp if kind == "report" else valid
        replies[kind] = json.loads(call_json(kind, json.dumps(req)))
    assert replies["report"]["ok"] is True
    for kind, out in replies.items():
        if kind != "report":
            assert out["ok"] is False and out["field"] in ("motor.kind", "sim"), (kind, out)


def test_flux_buildup_stall_warning():
    """A slow rotor (τ_r = 1.5 s at 100 µs): TI's IQ24 model stops 0.25 % short, a warning."""
    inp = copy.deepcopy(_case("01_st_mez_acim")["input"])
    inp["motor"]["rr_ohm"] = 0.04
    inp["motor"]["rated_speed_rpm"] = 1490
    inp["analysis"] = {}
    r = pulab.report(inp)
    f = r["acim_flux"]
    kr = r["profiles"]["ti"]["constants"]["Kr"]["value"]
    # it can never come closer than its stall point, where Kr·error < 2^24 floors to 0
    assert f["kr"] == kr and (f["stall_lsb"] + 1) * kr >= 2 ** 24
    assert f["stall_pct"] > 0.1 and f["t95_fixed_s"] > 0 and len(f["trace"]["t_s"]) <= 202
    assert "acim_flux_stall" in {x["code"] for x in r["review"]["findings"]}
    assert "acim_flux" not in pulab.report(_case("01_st_mez_acim")["input"])
