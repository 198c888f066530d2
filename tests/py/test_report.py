"""Input validation, conventions and gains through report(); fuzzing for stray exceptions."""
import copy
import json
import math
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

from conftest import ROOT, SEED_INPUT, chinese
from pulab import InputError, report
from pulab.api import call_json


def test_seed_bases_and_per_unit(seed_input):
    r = report(seed_input)
    u_b = 17 / math.sqrt(3)
    assert r["base"]["U_b"] == pytest.approx(u_b, rel=1e-15)
    # Seed 1.4-7 computes L_b with the line value 17 V and gets L_pu = 0.0732; with the phase
    # value U_b = 17/√3 that the seed itself chose as base, L_pu is √3 larger: 0.1268.
    assert r["pu"]["Ld"] == pytest.approx(0.0732 * math.sqrt(3), rel=2e-3)
    assert r["pu"]["Ts"] == pytest.approx(1e-4 * 2 * math.pi * 220, rel=1e-15)
    assert r["base"]["P_b"] == pytest.approx(3 * u_b * 1.5, rel=1e-15)


@pytest.mark.parametrize("conv, u_b, i_b", [
    ({"base": "rms"}, 400 / math.sqrt(3), 10.0),
    ({"base": "peak"}, 400 * math.sqrt(2 / 3), 10 * math.sqrt(2)),
    ({"base": "custom", "base_voltage_v": 300.0, "base_current_a": 25.0}, 300.0, 25.0),
])
def test_conventions(seed_input, conv, u_b, i_b):
    seed_input["motor"].update(rated_voltage_v=400, rated_current_a=10)
    seed_input["conventions"] = conv
    b = report(seed_input)["base"]
    assert (b["U_b"], b["I_b"]) == (pytest.approx(u_b), pytest.approx(i_b))


def test_peak_and_rms_give_the_same_pi_integers(seed_input):
    # I_b/U_b is √3·I/U_LL in both rms and peak conventions (seed 2.2-9).
    a = report(seed_input)["current_pi"]["d"]
    seed_input["conventions"] = {"base": "peak"}
    b = report(seed_input)["current_pi"]["d"]
    assert (a["pm_kp"], a["pm_ki"]) == (b["pm_kp"], b["pm_ki"])


def test_pll_integrator_gain_is_two_fb_for_pi_base(seed_input):
    p = report(seed_input)["pll"]
    assert p["integrator_gain"] == pytest.approx(2 * 220, rel=1e-15)  # seed 3.2-5
    seed_input["conventions"] = {"angle_base": "2pi"}
    assert report(seed_input)["pll"]["integrator_gain"] == pytest.approx(220, rel=1e-15)


def test_bandwidth_design_round_trips_through_the_integers(seed_input):
    seed_input["drive"]["ts_s"] = 1e-5
    seed_input["current_loop"] = {"bandwidth_hz": 300}
    d = report(seed_input)["current_pi"]["d"]
    assert d["from_integers"]["bandwidth_hz"] == pytest.approx(300, rel=1 / d["pm_kp"])


@pytest.mark.parametrize("patch, field", [
    ({"motor": {"rs_ohm": -1}}, "motor.rs_ohm"),
    ({"motor": {"rs_ohm": 0}}, "motor.rs_ohm"),
    ({"motor": {"ld_h": "6e-4"}}, "motor.ld_h"),
    ({"motor": {"pole_pairs": 2.5}}, "motor.pole_pairs"),
    ({"motor": {"bemf_v": True}}, "motor.bemf_v"),
    ({"motor": {"rs_ohms": 1}}, "motor.rs_ohms"),
    ({"drive": {"ts_s": float("nan")}}, "drive.ts_s"),
    ({"conventions": {"base": "custom"}}, "conventions.base_voltage_v"),
    ({"conventions": {"angle_base": "tau"}}, "conventions.angle_base"),
    ({"current_loop": {"method": "manual"}}, "current_loop.kp"),
    ({"raw": {"Voltage": 70000}}, "raw.Voltage"),
    ({"raw": {"Voltage": -1}}, "raw.Voltage"),
    ({"current_loop": {"method": "damping", "bandwidth_hz": 1}}, "current_loop.bandwidth_hz"),
])
def test_bad_input_names_the_field(seed_input, patch, field):
    for sec, vals in patch.items():
        seed_input.setdefault(sec, {}).update(vals)
    with pytest.raises(InputError) as e:
        report(seed_input)
    assert e.value.field == field


@pytest.mark.parametrize("patch, field, missing", [
    # FreqPer = 0 and FluxRotor divides by it: a property of the vendor code
    ({"raw": {"FreqRated01": 0}}, "raw.FreqRated01", ["FluxRotor"]),
    # 700 A needs Current = 70000 (0.01 A): beyond the Uint16 parameter
    ({"motor": {"rated_current_a": 700}}, "raw.Current", ["LD", "LQ", "Rpm"]),
])
def test_firmware_limits_leave_the_physics(seed_input, patch, field, missing):
    for sec, vals in patch.items():
        seed_input.setdefault(sec, {}).update(vals)
    r = report(seed_input)
    st = r["firmware"]["inovance"]
    assert not st["representable"] and st["problems"][0]["field"] == field
    assert st["problems"][0]["results"] == missing
    assert not set(missing) & set(r["vendor"]) and r["base"]["I_b"] > 0
    assert any(f["code"] == "unrepresentable" for f in r["review"]["findings"])
    p = _cli("report", "-", stdin=json.dumps(seed_input))
    assert p.returncode == 0 and json.loads(p.stdout)["firmware"]["inovance"] == st


def test_the_firmware_shipped_is_in_the_plain_report():
    """conventions.firmware = microchip without a profiles section: the report holds that
    profile (the page's answer strip needs no second call), and the review grades what it
    cannot hold as a warning. The 380 V motor's Microchip current base (2·√2·15 A) overflows."""
    inp = json.loads((ROOT / "tests/golden/04_ind380_7k5.json").read_text())["input"]
    plain = report(inp)
    assert set(plain["firmware"]) == {"inovance"} and "profiles" not in plain
    shipped = copy.deepcopy(inp)
    shipped.setdefault("conventions", {})["firmware"] = "microchip"
    r = report(shipped)
    assert set(r["profiles"]) == {"microchip"} and "profiles" not in r["input"]
    assert not r["firmware"]["microchip"]["representable"]
    x = [x for x in r["review"]["findings"] if x["key"] == "firmware.microchip"]
    assert len(x) == 1 and x[0]["severity"] == "warning"
    # the same integers as the five profiles asked for (the vendors panel's request)
    full = report({**shipped, "profiles": {}})
    assert r["profiles"]["microchip"] == full["profiles"]["microchip"]
    assert r["firmware"]["microchip"] == full["firmware"]["microchip"]


def test_missing_field(seed_input):
    del seed_input["motor"]["bemf_v"]
    with pytest.raises(InputError, match="motor.bemf_v: is required"):
        report(seed_input)


def _cli(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "pulab", *args], input=stdin,
                          capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT / "py"), "PATH": "/usr/bin:/bin"})


def test_cli_text_format():
    p = _cli("report", "-", "--format", "text", stdin=json.dumps(SEED_INPUT))
    assert p.returncode == 0 and "15022" in p.stdout and "Rpm" in p.stdout


@pytest.mark.parametrize("stdin, field", [("{", "input"), ('{"motor": 1}', "motor"),
                                          ("[]", "input")])
def test_cli_bad_input_exit_2_one_line(stdin, field):
    p = _cli("report", "-", stdin=stdin)
    assert p.returncode == 2 and p.stdout == ""
    assert len(p.stderr.splitlines()) == 1 and p.stderr.startswith(f"error: {field}:")


json_values = st.recursive(
    st.none() | st.booleans() | st.floats(allow_nan=True) | st.integers(-10 ** 20, 10 ** 20)
    | st.text(max_size=5), lambda c: st.lists(c, max_size=3)
    | st.dictionaries(st.text(max_size=5), c, max_size=3), max_leaves=6)


sim_values = st.dictionaries(
    st.sampled_from(["axis", "step_a", "speed_hz", "duration_s", "delay", "angle_step_deg", "x"]),
    st.floats(-1e6, 1e6) | st.sampled_from(["d", "q", True]), max_size=3)


@settings(max_examples=400, deadline=None)
@given(section=st.sampled_from(["motor", "drive", "conventions", "current_loop", "pll", "raw",
                                "sim"]),
       key=st.sampled_from(["rated_voltage_v", "rs_ohm", "ld_h", "pole_pairs", "udc_v", "ts_s",
                            "base", "method", "kp", "pm_ki", "bandwidth_hz", "Voltage", "LD",
                            "FreqRated01", "base_freq_hz", "uDCFilter", "current", "pll",
                            "junk"]),
       value=json_values | st.floats(1e-9, 1e9) | st.integers(0, 70000) | sim_values)
def test_fuzzed_input_raises_only_input_error(section, key, value):
    """Only InputError, one line, with Chinese text; a report never holds NaN/inf."""
    inp = copy.deepcopy(SEED_INPUT)
    inp.setdefault(section, {})[key] = value
    try:
        r = report(inp)
    except InputError as e:
        assert e.field and "\n" not in e.message
        assert chinese(e.message_zh), e.message
        return
    json.dumps(r, allow_nan=False)
    assert all(chinese(w) for w in r["warnings_zh"]), r["warnings_zh"]


@pytest.mark.parametrize("pm_kp, pm_ki", [(1180, 4720), (1, 1), (123456, 7)])
def test_integers_method_returns_the_integers_and_their_si_gains(seed_input, pm_kp, pm_ki):
    seed_input["current_loop"] = {"method": "integers", "pm_kp": pm_kp, "pm_ki": pm_ki}
    r = report(seed_input)
    z_b = r["base"]["Z_b"]
    for axis in ("d", "q"):
        g = r["current_pi"][axis]
        assert (g["pm_kp"], g["pm_ki"]) == (pm_kp, pm_ki)
        assert g["kp"] == pytest.approx(pm_kp / 4096 * z_b, rel=1e-15)
        assert g["ki"] == pytest.approx(pm_ki / 65536 / 1e-4 * z_b, rel=1e-15)


def test_integers_method_needs_both(seed_input):
    seed_input["current_loop"] = {"method": "integers", "pm_kp": 10}
    with pytest.raises(InputError) as e:
        report(seed_input)
    assert e.value.field == "current_loop.pm_ki"


@pytest.mark.parametrize("req, raw, name", [
    ({"format": "Q15", "value": 0.5}, 16384, "Q0.15"),       # short name: 16-bit word by default
    ({"format": "Q12", "value": 1.0}, 4096, "Q3.12"),
    ({"format": "Q24", "word_bits": 32, "value": 1.0}, 1 << 24, "Q7.24"),
    ({"format": "UQ0.16", "value": -0.1}, 0, "UQ0.16"),
])
def test_qcalc(req, raw, name):
    out = json.loads(call_json("qcalc", json.dumps(req)))
    assert (out["result"]["raw"], out["format"]["name"]) == (raw, name)


@pytest.mark.parametrize("req, field, text", [
    ({"format": "Q24", "value": 1.0}, "qcalc.format", "Q24 does not fit 16 word bits"),
    ({"format": "Qx", "value": 1.0}, "qcalc.format", "not a Q format"),
    ({"format": "Q15", "word_bits": 1.5, "value": 1.0}, "qcalc.word_bits", "must be an integer"),
])
def test_qcalc_errors(req, field, text):
    out = json.loads(call_json("qcalc", json.dumps(req)))
    assert out["ok"] is False and out["field"] == field and out["message"].startswith(text)
