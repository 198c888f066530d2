"""The graded design review (the datasheet conversions: test_datasheet.py).

Golden vectors: tests/golden/review, written by tests/oracle/review_oracle.py (pulab-free)
for three real motors' datasheets and the issue's contract example."""
import copy
import json
import math
import re
import subprocess
import sys

import pytest

from conftest import ROOT, chinese
from pulab import InputError, report
from pulab.analyses.review import THRESHOLDS, grade

GOLDEN = sorted((ROOT / "tests" / "golden" / "review").glob("*.json"))
REL = 1e-12


def _close(a, b):
    if b is None or a is None:
        return a is b
    return abs(a - b) <= REL * max(abs(a), abs(b))


def test_review_golden_files_are_fresh():
    r = subprocess.run([sys.executable, str(ROOT / "tests/oracle/review_oracle.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: p.stem)
def test_real_motor_datasheets(path):
    case = json.loads(path.read_text())
    exp = case["expected"]
    r = report(case["input"])
    motor = r["input"]["motor"]
    for k, v in exp["mechanical"].items():
        assert _close(r["mechanical"][k], v), k
    for k, v in exp["review.headroom"].items():
        assert _close(r["review"]["headroom"][k], v), k
    got = sorted(((x["severity"], x["code"], x["key"]) for x in r["review"]["findings"]),
                 key=lambda x: (("error", "warning", "note").index(x[0]), x[1], x[2]))
    assert got == [tuple(x) for x in exp["review.findings"]]
    for k, v in exp["input.motor"].items():
        assert _close(float(motor[k]), float(v)), (k, motor[k], v)


def _seed(**drive):
    return {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                      "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
            "drive": {"udc_v": 24, "ts_s": 1e-4, **drive}, "current_loop": {"bandwidth_hz": 300}}


def _codes(r, severity=None):
    return {(x["code"], x["key"]) for x in r["review"]["findings"]
            if severity is None or x["severity"] == severity}


@pytest.mark.parametrize("value, severity", [
    (0.099, None), (0.1, "note"), (-0.99, "note"), (1.0, "warning"), (-4.99, "warning"),
    (5.0, "error"), (-200.0, "error")])
def test_quantization_grades(value, severity):
    assert grade(value, THRESHOLDS["quantization_pct"]) == severity


def test_24v_bus_truncation_of_pm_maxout_vol_is_a_vendor_cost_not_an_input_error():
    # data1 = (240·2316)>>15 = 16 V instead of 16.97 V: −5.7 %, a property of the vendor code;
    # the seed example as the seed prints it opens with notes only.
    r = report(_seed())
    f = {x["key"]: x for x in r["review"]["findings"]}
    pmv = f["vendor.pm_maxout_vol.value"]
    assert pmv["severity"] == "note" and pmv["field"] == "drive.udc_v"
    assert "property of the vendor's code" in pmv["message"] and "厂商代码的性质" in pmv["message_zh"]
    assert r["vendor"]["pm_maxout_vol"]["error_pct"] == pytest.approx(-5.72, abs=0.01)
    seed = json.loads((ROOT / "tests/golden/01_seed_motor.json").read_text())["input"]
    assert {x["severity"] for x in report(seed)["review"]["findings"]} == {"note"}


def test_findings_name_the_form_label_in_both_languages():
    inp = _seed(base_freq_hz=100)
    inp["motor"]["rated_freq_hz"] = 300
    f = next(x for x in report(inp)["review"]["findings"] if x["code"] == "base_below_rated")
    assert f["label"] == "Base frequency f_b (drive max.)" and f["label"] in f["message"]
    assert f["label_zh"] in f["message_zh"] and "drive.base_freq_hz" not in f["message"]


def test_base_100hz_on_300hz_motor_flags_freqper_and_fluxrotor():
    inp = _seed(base_freq_hz=100)
    inp["motor"]["rated_freq_hz"] = 300
    r = report(inp)
    errors = _codes(r, "error")
    assert ("constant_wrap", "vendor.FreqPer.value") in errors
    assert ("constant_error", "vendor.FluxRotor.value") in errors
    assert r["vendor"]["FluxRotor"]["error_pct"] == pytest.approx(200, rel=1e-3)
    assert ("base_below_rated", "vendor.FreqPer.value") in _codes(r, "warning")


@pytest.mark.parametrize("bandwidth_hz, severity", [(500, None), (700, "warning"), (800, "warning"),
                                                   (1000, "error")])
def test_phase_margin_rule_is_the_loop_panels(bandwidth_hz, severity):
    # One delay-aware rule: the review grades the margin of the discrete loop the Loop design
    # panel analyses (computation + PWM delay), and its advice is that panel's 60° design.
    from pulab.analyses.loop import current as loop_current
    inp = _seed()
    inp["current_loop"] = {"bandwidth_hz": bandwidth_hz}
    r = report(inp)
    f = [x for x in r["review"]["findings"] if x["code"] == "phase_margin"]
    g = r["current_pi"]["d"]["from_integers"]
    pm = loop_current.axis_loop(1.5, 6e-4, 1e-4, g["kp"], g["ki"], "computation_pwm")
    if severity is None:
        assert f == [] and pm["phase_margin_deg"] >= 45
        return
    assert f[0]["severity"] == severity
    inp["analysis"] = {}
    design = report(inp)["loop"]["current"]["design"]["d"]
    ok_hz = design["kp"] / (2 * math.pi * 6e-4)
    assert f"{ok_hz:.6g} Hz" in f[0]["message"] and "Bandwidth" in f[0]["message"]
    inp["current_loop"] = {"bandwidth_hz": ok_hz}
    assert not [x for x in report(inp)["review"]["findings"] if x["code"] == "phase_margin"]


def test_base_equal_rated_compared_on_integers():
    inp = _seed(base_freq_hz=633.33)
    inp["motor"]["rated_freq_hz"] = 633.333
    r = report(inp)
    assert r["vendor"]["raw"]["FullFreq01"] == r["vendor"]["raw"]["FreqRated01"] == 63333
    assert not [x for x in r["review"]["findings"] if x["code"] == "base_below_rated"]


def test_voltage_headroom_needs_field_weakening():
    # 400 V servo whose back-EMF at f_b is 1.28 pu against a ≈0.95 pu limit
    inp = {"motor": {"rated_voltage_v": 400, "rated_current_a": 10, "rated_freq_hz": 250,
                     "rs_ohm": 0.5, "ld_h": 0.008, "lq_h": 0.008, "bemf_v": 320,
                     "pole_pairs": 5},
           "drive": {"base_freq_hz": 400, "udc_v": 540, "ts_s": 1e-4},
           "current_loop": {"bandwidth_hz": 300}}
    r = report(inp)
    assert r["pu"]["psi_r"] == pytest.approx(1.28, rel=1e-9)
    h = r["review"]["headroom"]
    assert h["limit_v"] / 400 == pytest.approx(0.95, abs=0.01)
    assert h["field_weakening"] is True
    assert h["field_weakening_from_hz"] == pytest.approx(h["limit_v"] / 320 * 250)
    assert ("voltage_bemf", "review.headroom.bemf_fb_v") in _codes(r)


def test_well_designed_drive_is_quiet():
    case = json.loads((ROOT / "tests/golden/review/issue9_contract_example.json").read_text())
    r = report(case["input"])
    assert r["warnings"] == [] and r["review"]["counts"]["error"] == 0
    assert r["review"]["counts"]["warning"] == 0


def test_pll_steady_angle_error_beside_the_transient():
    inp = _seed()
    inp["sim"] = {"pll": {}}
    m = report(inp)["sim"]["pll"]["metrics"]["q15"]
    assert m["locked"]
    assert m["steady_angle_error_deg"] < 2.0 < m["max_angle_error_deg"]


def test_every_finding_has_chinese_and_names_a_field():
    inp = _seed(base_freq_hz=100)
    inp["motor"]["rated_freq_hz"] = 300
    inp["conventions"] = {"inductance_unit": "uH"}
    inp["current_loop"] = {"bandwidth_hz": 5000}
    inp["sim"] = {"pll": {}}
    r = report(inp)
    assert {"error", "warning", "note"} == {x["severity"] for x in r["review"]["findings"]}
    for x in r["review"]["findings"]:
        assert chinese(x["message_zh"]), x["message"]
        # a design choice (never a motor's property such as its resistance)
        assert x["field"].split(".")[0] in ("drive", "conventions", "current_loop", "pll",
                                            "profiles", "datasheet"), x
    assert r["warnings_zh"] == [x["message_zh"] for x in r["review"]["findings"]
                                if x["severity"] != "note"]


def test_cli_text_shows_the_review_and_the_conversions(tmp_path):
    case = json.loads((ROOT / "tests/golden/review/heidenhain_srp5000.json").read_text())
    p = tmp_path / "in.json"
    p.write_text(json.dumps(case["input"]))
    out = subprocess.run([sys.executable, "-m", "pulab", "report", str(p), "--format", "text"],
                         capture_output=True, text=True, env={"PYTHONPATH": str(ROOT / "py")})
    assert out.returncode == 0, out.stderr
    assert "Design review: 0 error(s), 0 warning(s)" in out.stdout
    assert "E_LL = Ke·2π·n/60 = 0.397·2π·300/60" in out.stdout
    assert "NOTE    [vendor.pm_maxout_vol.value]" in out.stdout


def test_cli_both_given_exits_2_naming_the_field(tmp_path):
    inp = copy.deepcopy(_seed())
    inp["datasheet"] = {"speed_rpm": 3000}
    p = tmp_path / "in.json"
    p.write_text(json.dumps(inp))
    out = subprocess.run([sys.executable, "-m", "pulab", "report", str(p)],
                         capture_output=True, text=True, env={"PYTHONPATH": str(ROOT / "py")})
    assert out.returncode == 2
    assert out.stderr == ("error: datasheet.speed_rpm: Rated speed (datasheet.speed_rpm) and Rated "
                          "frequency (motor.rated_freq_hz) both set the motor's Rated frequency: "
                          "give only one of them.\n")


@pytest.mark.parametrize("path", sorted((ROOT / "tests/golden").glob("[0-9]*.json")),
                         ids=lambda p: p.stem)
def test_no_finding_asks_to_change_the_motor(path):
    """Every golden motor: each finding points at a design choice, with its form label."""
    r = report(json.loads(path.read_text())["input"])
    for x in r["review"]["findings"]:
        assert not x["field"].startswith("motor."), x
        assert x["label"] != x["field"] and chinese(x["label_zh"]), x


def test_the_firmware_shipped_grades_the_others_limits_as_notes():
    """The 28,000 rpm robot motor: a warning while Inovance is shipped; with TI shipped a note,
    and the voltage headroom is the physical U_dc/√2, not Inovance's whole-volt limit."""
    inp = json.loads((ROOT / "tests/golden/23_limit_robot_28krpm.json").read_text())["input"]
    sev = {x["code"]: x["severity"] for x in report(inp)["review"]["findings"]}
    assert sev["unrepresentable"] == "warning"
    r = report({**inp, "conventions": {"firmware": "ti"}})
    x = [x for x in r["review"]["findings"] if x["code"] == "unrepresentable"]
    assert x[0]["severity"] == "note" and x[0]["field"] == "conventions.firmware"
    assert x[0]["label"] == "Firmware you ship" and x[0]["label_zh"] == "所用固件"
    assert r["review"]["headroom"]["limit_v"] == 24 / math.sqrt(2)


def test_a_firmware_that_cannot_hold_the_motor_is_named_as_the_reader_knows_it():
    """The finding names the profile as the picker does (Inovance, 汇川), not by its id."""
    inp = json.loads((ROOT / "tests/golden/23_limit_robot_28krpm.json").read_text())["input"]
    x = [x for x in report(inp)["review"]["findings"] if x["code"] == "unrepresentable"][0]
    assert x["message"].startswith("the Inovance firmware cannot hold this motor (FullFreq01")
    assert x["message_zh"].startswith("汇川固件无法表示这台电机（FullFreq01")
    assert x["key"] == "firmware.inovance"


def test_the_shipped_firmwares_integer_pi_wraps_are_an_error():
    # 20 kHz bandwidth: Microchip's KIP needs Q11 (gain > 1), the DKNP shift then overflows
    # int32 in the step (the C oracle counts the same wraps, test_vendor_loop).  Shipping
    # Microchip: an error naming the count and the bandwidth; shipping Inovance: no such finding.
    inp = _seed()
    inp["current_loop"] = {"bandwidth_hz": 20000}
    inp["sim"] = {"current": {}}
    inp["conventions"] = {"firmware": "microchip"}
    r = report(inp)
    wraps = r["sim"]["current"]["by_profile"]["microchip"]["events"]["wrap"]
    assert wraps > 0
    hit = [x for x in r["review"]["findings"] if x["code"] == "pi_wrap"]
    assert len(hit) == 1 and hit[0]["severity"] == "error"
    assert hit[0]["key"] == "sim.current.by_profile.microchip.events.wrap"
    assert hit[0]["value"] == wraps and hit[0]["field"] == "current_loop.bandwidth_hz"
    assert f"wrapped {wraps} times" in hit[0]["message"] and "Microchip" in hit[0]["message"]
    assert chinese(hit[0]["message_zh"])
    inp["conventions"] = {"firmware": "inovance"}
    assert not [x for x in report(inp)["review"]["findings"] if x["code"].startswith("pi_")]


#: A JSON path of an input or of a firmware integer in a text (the firmware's own parameter and
#: constant names — RsPm, FullFreq01, MCAF_MOTOR_PSI_BASE_DT — are the vendor's identifiers and stay).
_PATH = re.compile(r"\b(?:profiles|motor|drive|raw|vendor|current_pi|datasheet|conventions|"
                   r"current_loop|pll|sim|analysis)\.[A-Za-z_]")
_DATASHEETS = sorted((ROOT / "tests/golden/datasheets").glob("*.json"))


@pytest.mark.parametrize("firmware", ["inovance", "ti", "nxp", "st", "microchip"])
def test_findings_name_inputs_by_their_labels_not_json_paths(firmware):
    """Six datasheet motors and the seed, each firmware shipped: no finding's text and no
    firmware problem's text or advice, in either language, names an input by its JSON path."""
    inputs = [json.loads(p.read_text())["input"] for p in _DATASHEETS]
    inputs.append(json.loads((ROOT / "tests/golden/01_seed_motor.json").read_text())["input"])
    texts = 0
    for inp in inputs:
        r = report({**inp, "conventions": {**inp.get("conventions", {}), "firmware": firmware},
                    "profiles": {}})
        problems = [x for st in r["firmware"].values() for x in st["problems"]]
        for x in r["review"]["findings"] + problems:
            for k in ("message", "message_zh", "advice", "advice_zh"):
                if k in x:
                    texts += 1
                    assert not _PATH.search(x[k]), (x["field"], x[k])
    assert texts > 20  # the texts checked exist


def test_a_constant_too_big_names_the_profiles_options_by_their_labels_and_links_to_one():
    """Rexroth MHP112A, Microchip shipped: MCAF_MOTOR_PSI_BASE_DT needs Q12; the advice names
    the three bases as the vendors panel labels them, and the finding opens the first."""
    inp = json.loads((ROOT / "tests/golden/datasheets/rexroth_mhp112a_024.json").read_text())["input"]
    r = report({**inp, "conventions": {"firmware": "microchip"}})
    x = [x for x in r["review"]["findings"] if x["key"] == "firmware.microchip"][0]
    assert x["field"] == "profiles.microchip.voltage_base_v"
    assert (x["label"], x["label_zh"]) == ("Microchip · voltage base", "Microchip · 电压基值")
    assert ("(Microchip · voltage base, Microchip · current base, Microchip · velocity base)"
            in x["message"])
    assert "（Microchip · 电压基值、Microchip · 电流基值、Microchip · 速度基值）" in x["message_zh"]


def test_every_profile_option_has_a_label_in_both_languages():
    from pulab.profiles import MODULES
    from pulab.schema import vendors
    keys = {f"profiles.{n}.{o[0]}" for n, m in MODULES.items() for o in m.OPTIONS}
    labels = {f.path: f.label for f in vendors.option_fields()}
    assert set(labels) == keys and len(keys) == 24
    for en, zh in labels.values():
        assert en and zh and " · " in en and " · " in zh


def test_a_finding_prints_the_value_with_an_si_prefix_and_keeps_it_exact():
    """EMRAX 228 LV (Lq = 10.6 µH): the texts say 10.6 µH and 1.1 mΩ, `value` stays the double."""
    inp = json.loads((ROOT / "tests/golden/datasheets/emrax_228_lv.json").read_text())["input"]
    f = {x["key"]: x for x in report(inp)["review"]["findings"]}
    lq, rs = f["vendor.raw.LQ"], f["vendor.raw.RsPm"]
    assert "Lq = 10.6 µH to the firmware unit" in lq["message"] and "Lq = 10.6 µH 取整" in lq["message_zh"]
    assert "= 1.1 mΩ to the firmware unit" in rs["message"] and "= 1.1 mΩ 取整" in rs["message_zh"]
    assert lq["value"] == 100.0 * (1 - 1.06e-05 * 1e5) / (1.06e-05 * 1e5)


@pytest.mark.parametrize("firmware", ["inovance", "ti", "nxp", "st", "microchip"])
def test_inovance_parameter_rounding_counts_only_when_inovance_is_shipped(firmware):
    """EMRAX 228 LV: RsPm = 1 for 1.1 mΩ (−9.09 %), LQ = 1 for 10.6 µH (−5.66 %) are errors of
    Inovance's parameter table; with another firmware shipped they are notes naming Inovance."""
    inp = json.loads((ROOT / "tests/golden/datasheets/emrax_228_lv.json").read_text())["input"]
    r = report({**inp, "conventions": {**inp.get("conventions", {}), "firmware": firmware}})
    rows = {x["key"]: x for x in r["review"]["findings"] if x["code"] == "raw_rounding"}
    rs, lq = rows["vendor.raw.RsPm"], rows["vendor.raw.LQ"]
    assert round(rs["value"], 2) == -9.09 and round(lq["value"], 2) == -5.66
    if firmware == "inovance":
        assert rs["severity"] == lq["severity"] == "error"
        assert rows["vendor.raw.LD"]["severity"] == "warning"
    else:
        assert {x["severity"] for x in rows.values()} == {"note"}
        assert all("Inovance's parameter table" in x["message"] and "汇川参数表" in x["message_zh"]
                   and x["field"] == "conventions.firmware" for x in rows.values())
        assert not any(x["code"] in ("raw_rounding", "raw_zero") and x["severity"] != "note"
                       for x in r["review"]["findings"])
