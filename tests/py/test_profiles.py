"""Vendor profiles, their headers (compiled with gcc) and the translator .

Expected integers come from the vendors' own published files where one exists
(Microchip motor_params.h/foc_params.h, NXP m1_pmsm_appconfig.h, ST drive_parameters.h),
from gcc evaluating the vendors' C expressions, or from the independent oracle
(tests/oracle/profiles_oracle.py, via tests/golden/profiles.json) — never from pulab.
"""
from __future__ import annotations

import copy
import json
import math
import re
import shutil
import subprocess
import sys

import pytest

from conftest import ROOT, SEED_INPUT, chinese
from pulab import report
from pulab.api import call_json
from pulab.profiles import header, registry
from pulab.profiles.common import mantissa_shift
from pulab.profiles.translate import translate

NAMES = registry.names()

GOLDEN = json.loads((ROOT / "tests/golden/04_ind380_7k5.json").read_text())["input"]
SERVO = json.loads((ROOT / "tests/golden/05_servo220_400w.json").read_text())["input"]
MOTORS = {"seed": SEED_INPUT, "ind380": GOLDEN, "servo220": SERVO}
GCC = shutil.which("gcc")


def _with_profiles(inp, profiles=None):
    out = copy.deepcopy(inp)
    out["profiles"] = profiles or {}
    return out


# ---------------------------------------------------------------------------------------
# Contract: every profile, every constant, three motors

@pytest.mark.parametrize("motor", MOTORS)
def test_every_constant_carries_the_contract_fields(motor):
    r = report(_with_profiles(MOTORS[motor]))
    assert sorted(r["profiles"]) == sorted(NAMES)
    for name, p in r["profiles"].items():
        assert len(p["constants"]) >= 2, name
        for k, c in p["constants"].items():
            where = f"{name}.{k}"
            assert type(c["value"]) is int, where
            for key in ("ideal", "error_pct", "si"):
                assert math.isfinite(c[key]), where
            assert c["format"] and c["source"] and c["unit"] is not None, where
            if c["ideal"]:
                assert c["error_pct"] == pytest.approx(100 * (c["value"] - c["ideal"]) / c["ideal"],
                                                       rel=1e-12, abs=1e-12), where
            # si is the stored integer read back through the format's scale
            assert c["si"] == pytest.approx(c["value"] / 2.0 ** c["q"] * c["scale"], rel=1e-12), where


def test_profiles_only_when_asked(seed_input):
    assert "profiles" not in report(seed_input)
    assert "profiles" in report(_with_profiles(seed_input))


@pytest.mark.parametrize("field,value,message", [
    ("profiles.ti.global_q", 31, "must be 1..30, got 31"),
    ("profiles.ti.global_q", 1.5, "must be an integer, got 1.5"),
    ("profiles.st.tf_kpdiv", 100, "must be a power of two, got 100"),
    ("profiles.nxp.trapezoidal", 1, "must be true or false, got 1"),
    ("profiles.microchip.voltage_base_v", -3, "must be > 0, got -3"),
    ("profiles.ti.bogus", 1, None),
])
def test_bad_profile_inputs_name_the_field(seed_input, field, value, message):
    _, name, key = field.split(".")
    out = json.loads(call_json("report", json.dumps(_with_profiles(seed_input, {name: {key: value}}))))
    assert out["ok"] is False and out["field"] == field
    if message:
        assert out["message"] == message
    assert chinese(out["message_zh"]), out


def test_unknown_profile_name_is_refused(seed_input):
    out = json.loads(call_json("report", json.dumps(_with_profiles(seed_input, {"infineon": {}}))))
    assert out["field"] == "profiles.infineon"


# ---------------------------------------------------------------------------------------
# Vendors' worked numbers

def _mcaf_input():
    """Microchip ACT57BLF02 (motor_params.h, foc_params.h in
    microchip-pic-avr-solutions/motorbench-release-collateral, zsmt-reference-actblf02-lvmc.X)."""
    pp, psi = 4, 9.28229e-3                         # Wb, "Rotor flux: 9.282 mVs"
    f_n = 16000.0 / 60.0                             # 16 kRPM electrical
    bemf_ll_rms = psi * 2 * math.pi * f_n * math.sqrt(3) / math.sqrt(2)
    return {"motor": {"rated_voltage_v": 26.938, "rated_current_a": 9.01, "rated_freq_hz": f_n,
                      "rs_ohm": 0.241, "ld_h": 102e-6, "lq_h": 132.5e-6, "bemf_v": bemf_ll_rms,
                      "pole_pairs": pp},
            "drive": {"udc_v": 24, "ts_s": 5e-5},
            # KIP_ENG/KII_ENG "ideal" columns of foc_params.h: 253.74467 mV/A, 634.82900 V/A/s
            "current_loop": {"method": "manual", "kp": 0.25374467, "ki": 634.829},
            "profiles": {"microchip": {"voltage_base_v": 71.3, "current_base_a": 43.6,
                                       "velocity_base_hz": 400.0}}}


@pytest.mark.parametrize("name,expected", [
    ("MCAF_MOTOR_RS", 4829), ("MCAF_MOTOR_LD_BASE_DT", 10219), ("MCAF_MOTOR_LQ_BASE_DT", 13275),
    ("MCAF_MOTOR_LD_BASE_OMEGA_E", 5137), ("MCAF_MOTOR_LQ_BASE_OMEGA_E", 6673),
    ("MCAF_MOTOR_PSI_BASE_OMEGA_E", 5361), ("MCAF_MOTOR_PSI_BASE_DT", 21330),
    ("MCAF_MOTOR_KE", 1340), ("KIP", 5084), ("KII", 636),
])
def test_microchip_reproduces_motorbench_integers(name, expected):
    c = report(_mcaf_input())["profiles"]["microchip"]["constants"][name]
    assert c["value"] == expected


@pytest.mark.parametrize("name,scale", [  # the _SCALE column of the same headers
    ("MCAF_MOTOR_RS", 1.6353211009), ("MCAF_MOTOR_LD_BASE_DT", 8.176606e-05),
    ("MCAF_MOTOR_LD_BASE_OMEGA_E", 0.0006506736), ("MCAF_MOTOR_PSI_BASE_OMEGA_E", 0.0283693686),
    ("MCAF_MOTOR_PSI_BASE_DT", 0.0035650000), ("MCAF_MOTOR_KE", 0.1134774744),
    ("KIP", 1.6353211009), ("KII", 3.270642e+04),
])
def test_microchip_scales_match_motorbench(name, scale):
    c = report(_mcaf_input())["profiles"]["microchip"]["constants"][name]
    assert c["scale"] == pytest.approx(scale, rel=2e-7)


def _nxp_input():
    """NXP MCAT 2023 m1_pmsm_appconfig.h, motor "linix": Rs 0.55, Ld 403 µH, Lq 512 µH, pp 2,
    N_max 4400 rpm (f = 146.667 Hz), I_max 8.25 A, U_DCB_MAX 60.8 V, E_max 15.1 V,
    Ts 100 µs, current loop f0 288 Hz, ξ = 1 (trapezoidal: Ki halved)."""
    return {"motor": {"rated_voltage_v": 26.0, "rated_current_a": 2.0, "rated_freq_hz": 133.33,
                      "rs_ohm": 0.55, "ld_h": 0.000403, "lq_h": 0.000512, "bemf_v": 9.0,
                      "pole_pairs": 2},
            "drive": {"udc_v": 24, "ts_s": 1e-4, "base_freq_hz": 2 * 4400 / 60},
            "current_loop": {"method": "damping", "bandwidth_hz": 288, "damping": 1},
            "profiles": {"nxp": {"udcb_max_v": 60.8, "i_max_a": 8.25, "e_max_v": 15.1,
                                 "trapezoidal": True}}}


@pytest.mark.parametrize("name,printed", [  # ACC32(x) arguments printed in that header
    ("M1_D_KP_GAIN", 0.213519), ("M1_D_KI_GAIN", 0.0155071), ("M1_Q_KP_GAIN", 0.306232),
    ("M1_Q_KI_GAIN", 0.0197013), ("M1_I_SCALE", 0.879913), ("M1_U_SCALE", 0.929017),
    ("M1_E_SCALE", 0.399629), ("M1_WI_SCALE", 0.103019),
])
def test_nxp_reproduces_mcat_appconfig(name, printed):
    c = report(_nxp_input())["profiles"]["nxp"]["constants"][name]
    assert c["ideal"] / 32768 == pytest.approx(printed, rel=6e-6)   # 6 printed digits
    assert abs(c["value"] - math.trunc(printed * 32768)) <= 1


def test_nxp_theta_gain_shift_matches_mcat_appconfig():
    c = report(_nxp_input())["profiles"]["nxp"]["constants"]["M1_TO_THETA_GAIN"]
    assert c["shift"] == -5 and c["value"] / 32768 == pytest.approx(0.938667, rel=2e-5)


@pytest.mark.parametrize("mantissa,shift", [(0.545455, -1), (0.877361, -9), (0.938667, -5),
                                             (0.61359375, -11), (0.61685, -6)])
def test_nxp_mantissa_shift_rule_on_published_pairs(mantissa, shift):
    """TO_KP/TO_KI/TO_THETA and POSPE_TO_KP/KI pairs of that header: the rule gives them back."""
    m, s = mantissa_shift(mantissa * 2.0 ** shift)
    assert s == shift and m == pytest.approx(mantissa, rel=1e-12)


def test_st_decodes_workbench_gains_to_r_over_l():
    """dronectl/g431-mcsdk: RS 0.35 Ω, LS 0.6 mH, 20 kHz, PID_TORQUE_KP/KI_DEFAULT 2312/2158 over
    TF_KPDIV/TF_KIDIV 128/4096: the Workbench cancels the pole, so ki/kp = R/L."""
    inp = {"motor": {"rated_voltage_v": 24, "rated_current_a": 5, "rated_freq_hz": 133.33,
                     "rs_ohm": 0.35, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 2},
           "drive": {"udc_v": 24, "ts_s": 5e-5},
           "profiles": {"st": {"rshunt_ohm": 0.003, "amplification_gain": 9.14,
                               "tf_kpdiv": 128, "tf_kidiv": 4096}}}
    t = translate(inp, "st", "q", {"PID_TORQUE_KP_DEFAULT": 2312, "PID_TORQUE_KI_DEFAULT": 2158})
    assert t["si"]["ki"] / t["si"]["kp"] == pytest.approx(0.35 / 6e-4, rel=5e-4)
    c = report(inp)["profiles"]["st"]["constants"]
    # parameters_conversion.h formulas on that board's numbers (checked by gcc below too)
    assert c["CURRENT_CONV_FACTOR"]["value"] == 544      # 65536·0.003·9.14/3.3 = 544.55
    assert c["C1"]["value"] == 477                       # 16384·0.35/(0.0006·20000) = 477.87


# ---------------------------------------------------------------------------------------
# Headers: gcc compiles each and a C file that uses every constant

def _defines(text: str) -> list[str]:
    names = re.findall(r"^#define\s+(\w+)\s+\S", text, re.M)
    return [n for n in names if not n.endswith("_H")]


def _compile_and_run(tmp_path, header_text: str, main_body: str) -> str:
    (tmp_path / "profile.h").write_text(header_text)
    (tmp_path / "use.c").write_text(
        '#include <stdio.h>\n#include <stdint.h>\n#include "profile.h"\n'
        "int main(void) {\n" + main_body + "return 0;\n}\n")
    exe = tmp_path / "use"
    subprocess.run([GCC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-o", str(exe),
                    str(tmp_path / "use.c"), "-lm"], check=True, capture_output=True, text=True)
    return subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout


@pytest.mark.skipif(GCC is None, reason="gcc not installed")
@pytest.mark.parametrize("motor", MOTORS)
@pytest.mark.parametrize("name", NAMES)
def test_header_compiles_and_every_constant_is_usable(tmp_path, motor, name):
    r = report(_with_profiles(MOTORS[motor]))
    text = header(r, name)
    names = _defines(text)
    assert len(names) >= 4
    body = "".join(f'printf("%s %.17g\\n", "{n}", (double)({n}));\n' for n in names)
    out = _compile_and_run(tmp_path, text, body)
    printed = dict(line.split() for line in out.splitlines())
    consts = r["profiles"][name]["constants"]
    for n, v in printed.items():  # every integer the header carries is the report's integer
        for k, c in consts.items():
            if n in (k, f"USER_MTR1_{k.upper()}_IQ"):
                assert float(v) == c["value"], n


@pytest.mark.skipif(GCC is None, reason="gcc not installed")
@pytest.mark.parametrize("motor", MOTORS)
def test_st_parameters_conversion_evaluated_by_gcc(tmp_path, motor):
    """gcc evaluates parameters_conversion.h's expressions (dronectl/g431-mcsdk) on the
    generated header; pulab's integers must be what the C casts give."""
    r = report(_with_profiles(MOTORS[motor]))
    c = r["profiles"]["st"]["constants"]
    body = """
    double sqrt_2 = 1.4142135623730951, sqrt_3 = 1.7320508075688772;
    uint32_t f_reg = (uint32_t)PWM_FREQUENCY / REGULATION_EXECUTION_RATE;
    uint16_t ccf = (uint16_t)((65536.0 * RSHUNT * AMPLIFICATION_GAIN) / ADC_REFERENCE_VOLTAGE);
    int16_t mv = (int16_t)((ADC_REFERENCE_VOLTAGE / sqrt_3) / VBUS_PARTITIONING_FACTOR);
    double max_i = ADC_REFERENCE_VOLTAGE / (2 * RSHUNT * AMPLIFICATION_GAIN);
    uint16_t bemf = (uint16_t)((MAX_APPLICATION_SPEED_RPM * 1.2 * MOTOR_VOLTAGE_CONSTANT * sqrt_2)
                               / (1000u * sqrt_3));
    int32_t c1 = (int32_t)((((int16_t)F1) * RS) / (LS * f_reg));
    int32_t c3 = (int32_t)((((int16_t)F1) * bemf) / (LS * max_i * f_reg));
    int32_t c5 = (int32_t)((((int16_t)F1) * mv) / (LS * max_i * f_reg));
    printf("%u %d %u %ld %ld %ld\\n", ccf, mv, bemf, (long)c1, (long)c3, (long)c5);
    """
    out = _compile_and_run(tmp_path, header(r, "st"), body).split()
    ours = [c[k]["value"] for k in ("CURRENT_CONV_FACTOR", "MAX_VOLTAGE", "MAX_BEMF_VOLTAGE",
                                    "C1", "C3", "C5")]
    assert [int(x) for x in out] == ours


@pytest.mark.skipif(GCC is None, reason="gcc not installed")
@pytest.mark.parametrize("motor", MOTORS)
def test_ti_default_gains_evaluated_by_gcc(tmp_path, motor):
    """MotorWare's calcPIgains formula and _IQ() truncation, evaluated by gcc on the header."""
    r = report(_with_profiles(MOTORS[motor]))
    c = r["profiles"]["ti"]["constants"]
    body = """
    long kp = (long)(((0.25 * USER_MOTOR_Ls_q * USER_IQ_FULL_SCALE_CURRENT_A)
                      / (USER_CTRL_PERIOD_sec * USER_IQ_FULL_SCALE_VOLTAGE_V)) * 16777216.0L);
    long ki = (long)(((USER_MOTOR_Rs / USER_MOTOR_Ls_q) * USER_CTRL_PERIOD_sec) * 16777216.0L);
    printf("%ld %ld\\n", kp, ki);
    """
    kp, ki = map(int, _compile_and_run(tmp_path, header(r, "ti"), body).split())
    assert (kp, ki) == (c["Kp_Iq_default"]["value"], c["Ki_Iq_default"]["value"])


def _cli(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "pulab", *args], capture_output=True, text=True,
                          input=stdin, env={"PYTHONPATH": str(ROOT / "py")})


@pytest.mark.parametrize("name", NAMES)
def test_cli_header(tmp_path, name):
    path = tmp_path / "in.json"
    path.write_text(json.dumps(SEED_INPUT))
    p = _cli("header", "--profile", name, str(path))
    assert p.returncode == 0 and "#define" in p.stdout and p.stderr == ""


@pytest.mark.parametrize("args,field", [
    (["header", "--profile", "infineon"], "profile"),
    (["header"], "profile"),
    (["translate", "--from", "ti", "--kp", "12x", "--ki", "3"], "translate.values.Kp_Iq"),
    (["translate", "--from", "st", "--kp", "40000", "--ki", "3"],
     "translate.values.PID_TORQUE_KP_DEFAULT"),
    (["translate", "--from", "inovance", "--kp", "1180"], "translate.values.pm_ki"),
    (["translate", "--kp", "1", "--ki", "1"], "translate.from"),
    (["translate", "--from", "ti", "--axis", "x", "--kp", "1", "--ki", "1"], "translate.axis"),
])
def test_cli_bad_input_exit_2_one_line(tmp_path, args, field):
    path = tmp_path / "in.json"
    path.write_text(json.dumps(SEED_INPUT))
    p = _cli(*args, str(path))
    assert p.returncode == 2 and p.stdout == ""
    lines = p.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}: "), p.stderr


def test_cli_bad_json_for_header(tmp_path):
    path = tmp_path / "in.json"
    path.write_text("{not json")
    p = _cli("header", "--profile", "ti", str(path))
    assert p.returncode == 2 and len(p.stderr.splitlines()) == 1


# ---------------------------------------------------------------------------------------
# Translator

@pytest.mark.parametrize("motor", MOTORS)
@pytest.mark.parametrize("axis", ["d", "q"])
def test_round_trip_inovance_ti_nxp_st_microchip_inovance(motor, axis):
    inp = MOTORS[motor]
    g = report(inp)["current_pi"][axis]
    t = translate(inp, "inovance", axis, {"pm_kp": g["pm_kp"], "pm_ki": g["pm_ki"]})
    assert [s["profile"] for s in t["chain"]] == ["ti", "nxp", "st", "microchip", "inovance"]
    prev = t["si"]
    budget = {"kp": 0.0, "ki": 0.0}
    for step in t["chain"]:  # each step moves a gain by at most its format's LSB
        dkp = abs(step["si"]["kp"] - prev["kp"])
        assert dkp <= step["lsb"]["kp"] * (1 + 1e-9), step["profile"]
        dki = abs(step["si"]["ki"] - prev["ki"])
        assert dki <= step["lsb"]["ki"] + prev["ki"] * dkp / prev["kp"] + 1e-12 * prev["ki"], \
            step["profile"]
        budget["kp"] += dkp
        budget["ki"] += dki
        prev = step["si"]
    # back in Inovance: the integers differ by no more than the drift the chain stated, in LSBs
    last = t["chain"][-1]
    for k, f in (("kp", "pm_kp"), ("ki", "pm_ki")):
        allowed = 0.5 + budget[k] / last["lsb"][k]
        assert abs(t["round_trip"]["delta"][f]) <= allowed
    assert abs(t["round_trip"]["delta"]["pm_kp"]) <= 1 and abs(t["round_trip"]["delta"]["pm_ki"]) <= 1


@pytest.mark.parametrize("motor", MOTORS)
@pytest.mark.parametrize("source", NAMES)
def test_round_trip_from_every_profile_stays_within_the_chain_budget(motor, source):
    """Back at the source, the integers move by no more than the summed per-step LSBs."""
    inp = MOTORS[motor]
    r = report(_with_profiles(inp))
    from pulab.profiles import MODULES
    kp_name, ki_name = MODULES[source].gain_fields("q")
    key = (lambda k: f"{k}_q") if source == "inovance" else (lambda k: k)
    consts = r["profiles"][source]["constants"]
    given = {kp_name: consts[key(kp_name)]["value"], ki_name: consts[key(ki_name)]["value"]}
    t = translate(inp, source, "q", given)
    prev, budget = t["si"], {"kp": 0.0, "ki": 0.0}
    for step in t["chain"]:
        budget["kp"] += abs(step["si"]["kp"] - prev["kp"])
        budget["ki"] += abs(step["si"]["ki"] - prev["ki"])
        prev = step["si"]
    last = t["chain"][-1]
    assert last["profile"] == source
    for k, f in (("kp", kp_name), ("ki", ki_name)):
        assert abs(t["round_trip"]["delta"][f]) <= 0.5 + budget[k] / last["lsb"][k] + 1e-9


@pytest.mark.parametrize("source", NAMES)
def test_translate_from_every_profile_reproduces_its_own_integers(source, seed_input):
    r = report(_with_profiles(seed_input))
    consts = r["profiles"][source]["constants"]
    from pulab.profiles import MODULES
    kp_name, ki_name = MODULES[source].gain_fields("q")
    key = (lambda k: f"{k}_q") if source == "inovance" else (lambda k: k)
    given = {kp_name: consts[key(kp_name)]["value"], ki_name: consts[key(ki_name)]["value"]}
    t = translate(seed_input, source, "q", given)
    assert t["profiles"][source]["values"] == given


@pytest.mark.parametrize("values,field,message", [
    ({"Kp_Iq": 1.5, "Ki_Iq": 1}, "translate.values.Kp_Iq", "must be an integer, got 1.5"),
    ({"Kp_Iq": 2 ** 31, "Ki_Iq": 1}, "translate.values.Kp_Iq",
     "must be -2147483648..2147483647, got 2147483648"),
    ({"Kp_Iq": 0, "Ki_Iq": 1}, "translate.values.Kp_Iq", "must not be 0"),
    ({"Kp_Iq": 1}, "translate.values.Ki_Iq", "is required"),
    ({"Kp_Iq": 1, "Ki_Iq": 1, "Kd": 0}, "translate.values.Kd", None),
    ([1, 2], "translate.values", None),
])
def test_translate_errors_name_the_field(seed_input, values, field, message):
    from pulab.schema.errors import InputError
    with pytest.raises(InputError) as e:
        translate(seed_input, "ti", "q", values)
    assert e.value.field == field
    if message:
        assert e.value.message == message
    assert chinese(e.value.message_zh)


# ---------------------------------------------------------------------------------------
# Golden vectors from the independent oracle (tests/oracle/profiles_oracle.py)

PROFILE_GOLDEN = sorted((ROOT / "tests/golden/profiles").glob("*.json"))


@pytest.mark.parametrize("path", PROFILE_GOLDEN, ids=lambda p: p.stem)
def test_profiles_match_the_oracle(path):
    case = json.loads(path.read_text())
    inp = copy.deepcopy(case["input"])
    inp.setdefault("profiles", {})
    got = report(inp)["profiles"]
    problems = []
    for name, consts in case["expected"].items():
        for k, exp in consts.items():
            c = got[name]["constants"].get(k)
            if c is None:
                problems.append(f"{name}.{k}: missing")
                continue
            if c["value"] != exp["value"] or type(c["value"]) is not int:
                problems.append(f"{name}.{k}: value {c['value']!r} != {exp['value']}")
            for key in ("ideal", "si"):  # float formulas in another order: 1e-9 relative
                if c[key] != pytest.approx(exp[key], rel=1e-9, abs=1e-300):
                    problems.append(f"{name}.{k}.{key}: {c[key]!r} != {exp[key]!r}")
            if "shift" in exp and c["shift"] != exp["shift"]:
                problems.append(f"{name}.{k}.shift")
        assert sorted(got[name]["constants"]) == sorted(consts), name
    assert not problems, "\n".join(problems)


def test_profile_golden_files_are_fresh():
    p = subprocess.run([sys.executable, str(ROOT / "tests/oracle/profiles_oracle.py"), "--check"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr


# ---------------------------------------------------------------------------------------
# Warnings and fuzzing: every message in Chinese, only InputError

def test_out_of_range_and_zero_constants_warn_in_both_languages(seed_input):
    inp = _with_profiles(seed_input, {"ti": {"full_scale_current_a": 5000.0, "global_q": 28},
                                      "microchip": {"current_base_a": 1e-6}})
    r = report(inp)
    ti = r["profiles"]["ti"]["constants"]["Kp_Iq"]
    assert "out_of_range" in ti["flags"] and ti["value"] == 2 ** 31 - 1
    # a constant is named by its vendor and its own name, not by a JSON path
    hits = [w for w in r["warnings"] if w.split(" ")[0] in ("TI", "Microchip")]
    assert any(w.startswith("TI Kp_Iq: ") for w in hits)
    assert not any("profiles." in w for w in r["warnings"] + r["warnings_zh"])
    assert any("rounds to 0" in w for w in hits)
    for w in r["warnings_zh"][-len(hits):]:
        assert chinese(w), w


from hypothesis import given, settings, strategies as st  # noqa: E402

_VALUES = st.one_of(st.none(), st.booleans(), st.integers(-5, 70000),
                    st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=3))
_KEYS = {"ti": ["full_scale_voltage_v", "full_scale_current_a", "global_q", "max_current_a"],
         "nxp": ["udcb_max_v", "i_max_a", "trapezoidal", "round_u_max", "u_max_coeff"],
         "st": ["rshunt_ohm", "tf_kpdiv", "tf_kidiv", "f1", "amplification_gain"],
         "microchip": ["voltage_base_v", "current_base_a", "velocity_base_hz"]}


@settings(max_examples=150, deadline=None)
@given(st.dictionaries(st.sampled_from(sorted(_KEYS)),
                       st.dictionaries(st.sampled_from(sum(_KEYS.values(), [])), _VALUES,
                                       max_size=3), max_size=3))
def test_fuzzed_profile_inputs_give_a_report_or_a_chinese_error(section):
    out = json.loads(call_json("report", json.dumps({**SEED_INPUT, "profiles": section})))
    if out["ok"]:
        for w in out["report"]["warnings_zh"]:
            assert chinese(w), w
    else:
        assert out["field"].startswith("profiles") and chinese(out["message_zh"]), out


@pytest.mark.parametrize("name", NAMES)
def test_conventions_in_both_languages(name):
    from pulab.profiles import MODULES
    en, zh = MODULES[name].CONVENTIONS, MODULES[name].CONVENTIONS_ZH
    assert list(en) == list(zh)
    assert all(any("\u4e00" <= ch <= "\u9fff" for ch in zh[k]) for k in zh
               if k not in ("clarke_k", "inductance_base")), zh


@pytest.mark.skipif(GCC is None, reason="gcc not installed")
@pytest.mark.parametrize("motor", MOTORS)
def test_st_pi_example_shift_and_misra_builds_by_gcc(tmp_path, motor):
    """pid_regulator.c's output line in both builds, compiled: >> floors, / truncates."""
    st_p = report(_with_profiles(MOTORS[motor]))["profiles"]["st"]
    body = "int32_t e;\n"
    for ex in st_p["pi_example"]:
        body += (f"e = {ex['error']};\n"
                 "printf(\"%ld %ld\\n\", (long)(((int32_t)PID_TORQUE_KP_DEFAULT * e >> TF_KPDIV_LOG)"
                 " + ((int32_t)PID_TORQUE_KI_DEFAULT * e >> TF_KIDIV_LOG)),"
                 " (long)(((int32_t)PID_TORQUE_KP_DEFAULT * e / (int32_t)TF_KPDIV)"
                 " + ((int32_t)PID_TORQUE_KI_DEFAULT * e / (int32_t)TF_KIDIV)));\n")
    out = _compile_and_run(tmp_path, header(report(_with_profiles(MOTORS[motor])), "st"), body)
    got = [tuple(map(int, line.split())) for line in out.splitlines()]
    assert got == [(ex["shift"], ex["misra"]) for ex in st_p["pi_example"]]


def test_cli_text_format_lists_profiles(tmp_path):
    path = tmp_path / "in.json"
    path.write_text(json.dumps(_with_profiles(SEED_INPUT)))
    p = _cli("report", "--format", "text", str(path))
    assert p.returncode == 0 and "Profile microchip" in p.stdout and "KIP" in p.stdout


@pytest.mark.parametrize("ti,codes", [
    ({}, []),
    ({"full_scale_current_a": 1.0}, ["USER_ErrorCode_iqFullScaleCurrent_A_Low"]),
    ({"full_scale_freq_hz": 40.0}, ["USER_ErrorCode_iqFullScaleFreq_Hz_Low"]),
    ({"full_scale_freq_hz": 9000.0}, ["USER_ErrorCode_iqFullScaleFreq_Hz_High"]),
])
def test_ti_user_check_for_errors(seed_input, ti, codes):
    """user.c USER_checkForErrors conditions (gdgly/EV_28069M): seed motor, 4 pole pairs,
    I_FS = 2·√2·1.5 A, I_max = √2·1.5 A; 9000 Hz ≥ 128·4·1000/60 = 8533 Hz."""
    r = report(_with_profiles(seed_input, {"ti": ti}))
    assert sorted({c for c, _ in r["profiles"]["ti"]["checks"]}) == codes
    ws = [z for w, z in zip(r["warnings"], r["warnings_zh"]) if "USER_checkForErrors" in w]
    assert len(ws) == len(r["profiles"]["ti"]["checks"])
    assert all(chinese(w) for w in ws)


AVR_GCC = shutil.which("avr-gcc")


@pytest.mark.skipif(AVR_GCC is None, reason="avr-gcc not installed")
@pytest.mark.parametrize("name", NAMES)
def test_header_compiles_where_int_is_16_bits(tmp_path, name):
    """C2000 and dsPIC have a 16-bit int, like AVR: every constant still fits its C type."""
    r = report(_with_profiles(SERVO))
    text = header(r, name)
    (tmp_path / "profile.h").write_text(text)
    names = _defines(text)
    uses = "".join(f"  ({n}),\n" for n in names)
    (tmp_path / "use.c").write_text('#include <stdint.h>\n#include "profile.h"\n'
                                    "const double used[] = {\n" + uses + "};\n")
    p = subprocess.run([AVR_GCC, "-mmcu=atmega328p", "-std=c99", "-Wall", "-Wextra", "-Werror",
                        "-Woverflow", "-c", "-o", str(tmp_path / "use.o"), str(tmp_path / "use.c")],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr


@pytest.mark.parametrize("name", ["ti", "nxp", "st", "microchip"])
def test_the_family_sweep_reads_each_profile(seed_input, name):
    """pulab.analyses.integers looks integers up in profiles.NAME.constants."""
    from pulab.analyses.integers import evaluate
    e = evaluate(seed_input, name)
    consts = report(_with_profiles(seed_input))["profiles"][name]["constants"]
    assert sorted(e["integers"]) == sorted(f"profiles.{name}.constants.{k}" for k in consts)
    for k, c in consts.items():
        assert e["integers"][f"profiles.{name}.constants.{k}"]["value"] == c["value"]


def test_a_constant_beyond_its_word_says_how_much_to_rescale():
    """The 7.5 kW motor in Microchip's scaling: MCAF_MOTOR_LD_BASE_DT needs 1.29× Q13's range;
    the advice gives the Q format with enough integer bits and the options that scale it."""
    r = report({**GOLDEN, "profiles": {}})
    p = r["firmware"]["microchip"]["problems"][0]
    c = r["profiles"]["microchip"]["constants"]["MCAF_MOTOR_LD_BASE_DT"]
    assert p["field"] == "profiles.microchip.MCAF_MOTOR_LD_BASE_DT" and p["stored"] == 32767
    factor = c["ideal"] / 32767
    assert p["params"]["factor"] == pytest.approx(factor, rel=1e-15)
    assert 2 ** (p["params"]["bits"] - 1) < factor <= 2 ** p["params"]["bits"]
    assert f"Q{c['q'] - p['params']['bits']}" in p["advice"]
    assert "Microchip · current base" in p["advice"] and "Microchip · 电流基值" in p["advice_zh"]
    f = [x for x in r["review"]["findings"] if x["key"] == "firmware.microchip"][0]
    assert f["severity"] == "note" and "keep the largest integer" in f["message"]
