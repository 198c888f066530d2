"""Vendor headers read back (pulab.analyses.audit): real generated headers, each decoded value
checked against a number the header itself prints (a comment, the MCAT JSON) or the vendor's
formula worked by hand here; pu-lab's own headers decoded back to the report's design.

Fixtures: tests/data/headers/<vendor>/ (README there names each repository, path and commit).
"""

from __future__ import annotations

import copy
import json
import math
import subprocess
import sys

import pytest

from conftest import ROOT, SEED_INPUT, chinese
from pulab import profiles
from pulab.analyses.audit import audit
from pulab.report import report
from pulab.schema.errors import InputError

HEADERS = ROOT / "tests" / "data" / "headers"
ST_SET = ("pmsm_motor_parameters.h", "drive_parameters.h", "power_stage_parameters.h",
          "parameters_conversion.h", "parameters_conversion_g4xx.h")


def _files(vendor: str, names) -> list:
    return [(n, (HEADERS / vendor / n).read_text(encoding="utf-8", errors="replace"))
            for n in names]


@pytest.fixture(scope="module")
def st():
    return audit(_files("st", ST_SET))


@pytest.fixture(scope="module")
def nxp():
    return audit(_files("nxp", ["m1_pmsm_appconfig.h"]))


@pytest.fixture(scope="module")
def ti():
    return audit(_files("ti", ["user_mtr1.h", "user_common.h"]), defines=["BSXL8323RS_REVA"])


# -- ST MCSDK (dronectl/g431-mcsdk : Inc/) -------------------------------------------------

def test_st_set_is_detected_and_ordered_by_its_includes(st):
    assert st["profile"] == "st" and st["target"] == "arm"
    # parameters_conversion.h includes the other four: it is read last
    assert st["files"][-1] == "parameters_conversion.h"
    assert st["unresolved"] == ["mc_math.h"]


def test_st_parameters_conversion_values_as_the_compiler_folds_them(st):
    m = st["macros"]
    # (uint16_t)((65536.0·RSHUNT·AMPLIFICATION_GAIN)/ADC_REFERENCE_VOLTAGE):
    # 65536·0.003 = 196.608; ·9.14 = 1797.01; /3.3 = 544.55 → 544
    assert m["CURRENT_CONV_FACTOR"]["value"] == 544
    # V_ref/(2·R·G) = 3.3/(2·0.003·9.14) = 3.3/0.05484
    assert m["MAX_CURRENT"]["value"] == pytest.approx(3.3 / 0.05484, rel=1e-12)
    # (int32_t)((((int16_t)F1)·RS)/(LS·TF_REGULATION_RATE)) = 5734.4/12 = 477.87 → 477
    assert m["C1"]["value"] == 477
    # (170·1000000/20000) & 0xFFFE = 8500
    assert m["PWM_PERIOD_CYCLES"]["value"] == 8500
    # DEAD_TIME_COUNTS_1 = 170·1·750/1000 = 127 ≤ 255: the first #if branch
    assert st["other"]["DEAD_TIME_COUNTS"]["value"] == 127
    assert m["C1"]["source"] == "parameters_conversion.h:71"


def test_st_nominal_current_by_the_formula_its_comment_prints(st):
    # pmsm_motor_parameters.h: int16 = I·32767·Rshunt·G/(V_ref/2) → I = 870·1.65/(32767·0.02742)
    i = 870 * 1.65 / (32767 * 0.003 * 9.14)
    assert st["macros"]["NOMINAL_CURRENT"]["si"] == pytest.approx(i, rel=1e-12)
    assert st["macros"]["NOMINAL_CURRENT"]["unit"] == "A"


def test_st_pi_zero_sits_on_the_plant_pole(st):
    # Ki/Kp per sample = (2158/4096)/(2312/128) = 0.029168…; RS·T/LS = 0.35·(1/20000)/0.0006
    # = 0.029166…: the Workbench's pole-zero cancellation, 0.01 % apart
    d = st["design"]
    assert d["ki_over_kp_per_sample"] == pytest.approx((2158 / 4096) / (2312 / 128), rel=1e-12)
    assert d["current_loop"]["q"]["cancels_plant"] is True
    assert d["current_loop"]["q"]["zero_rad_s"] == pytest.approx(0.35 / 0.0006, rel=1e-3)
    assert not [f for f in st["findings"] if f["code"] == "inconsistent"]


def test_st_unknown_macros_are_listed_not_guessed(st):
    # SQRT_3 and LOG2 come from mc_math.h, which is not given
    assert st["unknown"]["MAX_VOLTAGE"] == ["SQRT_3"]
    assert st["unknown"]["TF_KPDIV_LOG"] == ["LOG2"]
    assert "MAX_VOLTAGE" not in st["macros"]


def test_st_a_definition_supplies_what_a_missing_include_defines():
    d = audit(_files("st", ST_SET), defines=["SQRT_3=1.732051"])
    # (int16_t)((3.3/1.732051)/0.09625565501973242) = 1.905256/0.0962557 = 19.79 → 19
    assert d["macros"]["MAX_VOLTAGE"]["value"] == 19


def test_st_design_input_is_a_report_input(st):
    inp = copy.deepcopy(st["design"]["input"])
    assert st["design"]["missing"] == []
    r = report(inp)
    assert r["input"]["motor"]["rs_ohm"] == 0.35


def test_st_round_trip_regenerates_the_workbench_integers(st):
    # pu-lab's ST header for the decoded design: every integer the Workbench wrote comes back
    rt = st["roundtrip"]
    ints = {n: m for n, m in rt.items() if "delta_lsb" in m}
    assert {"PID_TORQUE_KP_DEFAULT", "PID_TORQUE_KI_DEFAULT", "NOMINAL_CURRENT", "TF_KPDIV",
            "POLE_PAIR_NUM", "PWM_FREQUENCY"} <= set(ints)
    assert all(m["delta_lsb"] == 0 for m in ints.values()), ints
    assert rt["PID_TORQUE_KP_DEFAULT"]["file"] == 2312
    assert "#define PID_TORQUE_KP_DEFAULT" in st["regenerated"]["header"]


def test_st_conversion_constants_come_back_to_the_lsb():
    # with MCSDK 5.x's mc_math.h (SQRT_2 1.4142, SQRT_3 1.732) every integer the Workbench set
    # holds or its conversion file computes is the one pu-lab computes from the decoded design
    d = audit(_files("st", ST_SET), defines=["SQRT_2=1.4142", "SQRT_3=1.732"])
    ints = {n: r["delta_lsb"] for n, r in d["roundtrip"].items() if "delta_lsb" in r}
    assert {"C1", "C3", "C5", "MAX_BEMF_VOLTAGE", "MAX_VOLTAGE", "CURRENT_CONV_FACTOR",
            "PWM_PERIOD_CYCLES", "NOMINAL_CURRENT", "PID_TORQUE_KP_DEFAULT",
            "PID_TORQUE_KI_DEFAULT", "PID_FLUX_KP_DEFAULT", "PID_FLUX_KI_DEFAULT"} <= set(ints)
    assert all(v == 0 for v in ints.values()), ints


def test_st_speed_pi_in_si_once_speed_unit_is_given():
    # MCSDK's mc_stm_types.h: SPEED_UNIT = U_01HZ = 10, so the error is in 0.1 Hz (mechanical)
    d = audit(_files("st", ST_SET), defines=["SQRT_3=1.732", "SPEED_UNIT=10"])
    sp = d["design"]["speed_loop"]
    i_digit = 3.3 / 2 / (0.003 * 9.14) / 32767
    assert sp["kp_a_per_rad_s"] == pytest.approx(3144 / 1024 * i_digit / (2 * math.pi * 0.1))
    assert sp["ki_a_per_rad"] == pytest.approx(141 / 16384 * i_digit / (2 * math.pi * 0.1) * 1000)
    assert "SPEED_UNIT" not in d["macros"]  # a -D value, not one of the files' macros
    assert audit(_files("st", ST_SET))["design"]["speed_loop"] is None


def test_st_pll_bandwidth_and_damping_at_the_maximum_speed():
    # STO_ExecutePLL: error E·sin(θ − θ̂) in back-EMF digits (32768 per MAX_BEMF_VOLTAGE = 15 V,
    # the integer C3 uses), PI output in angle digits (65536 per turn) per 50 µs period
    d = audit(_files("st", ST_SET), defines=["SQRT_2=1.4142", "SQRT_3=1.732"])
    tr = d["design"]["observer"]["tracking"]
    e = 32768 * 4.0 * 4000 / 1000 * math.sqrt(2 / 3) / 15
    g = e * 2 * math.pi / 65536
    kp, ki = 213 / 16384 * g / 5e-5, 8 / 65535 * g / 5e-5 ** 2
    assert tr["natural_hz"] == pytest.approx(math.sqrt(ki) / (2 * math.pi), rel=1e-9)
    assert tr["damping"] == pytest.approx(kp / (2 * math.sqrt(ki)), rel=1e-9)
    assert 0.95 < tr["damping"] < 1.0 and 55 < tr["natural_hz"] < 60
    # without MAX_BEMF_VOLTAGE (SQRT_2 unknown) only the gains
    assert "tracking" not in audit(_files("st", ST_SET))["design"]["observer"]


def test_nxp_round_trip_needs_the_back_emf(nxp):
    assert nxp["design"]["missing"] == ["motor.bemf_v"] and nxp["regenerated"] is None \
        and nxp["roundtrip"] == {}


def test_st_edited_resistance_breaks_the_cancellation():
    files = [(n, t.replace("#define RS                     0.35", "#define RS 0.5"))
             for n, t in _files("st", ST_SET)]
    d = audit(files)
    f = [f for f in d["findings"] if f["code"] == "inconsistent"]
    assert len(f) == 1 and "RS" in f[0]["macros"] and chinese(f[0]["message_zh"])


def test_st_loop_margin_is_the_reports_delay_aware_margin(st):
    # ω_c·Ts = 0.35 here, yet with the report's delay model the loop keeps 50° of phase margin
    inp = copy.deepcopy(st["design"]["input"])
    inp["analysis"] = {}
    want = report(inp)["loop"]["current"]
    for axis in ("d", "q"):
        got = st["design"]["current_loop"][axis]
        assert got["delay"] == "computation_pwm" and got["stable"] is True
        assert got["phase_margin_deg"] == pytest.approx(want[axis]["phase_margin_deg"], abs=1e-9)
        assert got["gain_margin_db"] == pytest.approx(want[axis]["gain_margin_db"], abs=1e-9)
        assert 50.0 < got["phase_margin_deg"] < 50.5
    assert not [f for f in st["findings"] if f["code"] == "loop_margin"]


@pytest.mark.parametrize("kp, severity", [(5000, "warning"), (9000, "error")])
def test_st_gains_raised_by_hand_lose_their_margin(kp, severity):
    files = [(n, t.replace("#define PID_TORQUE_KP_DEFAULT         2312",
                           f"#define PID_TORQUE_KP_DEFAULT         {kp}"))
             for n, t in _files("st", ST_SET)]
    d = audit(files)
    q = d["design"]["current_loop"]["q"]
    inp = copy.deepcopy(d["design"]["input"])
    inp["analysis"] = {}
    want = report(inp)["loop"]["current"]["q"]
    assert q["stable"] is want["stable"] and q["stable"] is (severity == "warning")
    f = [f for f in d["findings"] if f["code"] == "loop_margin"]
    assert [x["severity"] for x in f] == [severity]
    assert f[0]["macros"] == ["PID_TORQUE_KP_DEFAULT", "PID_TORQUE_KI_DEFAULT"]
    assert chinese(f[0]["message_zh"]) and "30°" in f[0]["message"]
    if q["stable"]:
        assert q["phase_margin_deg"] < 30.0


def test_st_constants_proven_for_every_motor_within_20_percent(st):
    rp = st["design"]["range_proof"]
    assert rp["verdict"] == "proven" and rp["spread"] == 0.2
    assert rp["ranges"]["motor.rs_ohm"] == pytest.approx([0.28, 0.42])
    lo, hi = rp["constants"]["NOMINAL_CURRENT"]["range"]
    assert lo <= 870 <= hi and hi <= 32767
    assert not [f for f in st["findings"] if f["code"] == "overflow"]


def test_st_current_near_the_word_overflows_for_a_motor_20_percent_larger():
    files = [(n, t.replace("#define NOMINAL_CURRENT         870",
                           "#define NOMINAL_CURRENT         30000"))
             for n, t in _files("st", ST_SET)]
    d = audit(files)
    f = [f for f in d["findings"] if f["code"] == "overflow"]
    assert [x["macros"] for x in f] == [["NOMINAL_CURRENT"]] and f[0]["severity"] == "warning"
    assert "20 %" in f[0]["message"] and chinese(f[0]["message_zh"])
    c = d["design"]["range_proof"]["constants"]["NOMINAL_CURRENT"]
    assert c["verdict"] == "violated"
    # the counterexample's peak current in ST's digits (32767 at (V_ref/2)/(R_shunt·G)) is
    # beyond int16, and the motor is inside the box
    i_rated = c["counterexample"]["motor"]["rated_current_a"]
    assert i_rated <= 1.2 * d["design"]["input"]["motor"]["rated_current_a"] * (1 + 1e-12)
    assert i_rated * math.sqrt(2) * 32767 * 0.003 * 9.14 / (3.3 / 2) > 32767


def test_no_range_proof_without_a_whole_report_input(mchp):
    assert mchp["design"]["missing"] and mchp["design"]["range_proof"] is None


@pytest.mark.parametrize("kp", ["1e300", "2312e30"])
def test_st_absurd_gains_give_no_margin_and_no_crash(kp):
    files = [(n, t.replace("#define PID_TORQUE_KP_DEFAULT         2312",
                           f"#define PID_TORQUE_KP_DEFAULT         {kp}"))
             for n, t in _files("st", ST_SET)]
    try:
        d = audit(files)
    except InputError as e:
        assert e.field.startswith("files")
        return
    q = d["design"]["current_loop"].get("q", {})
    assert "phase_margin_deg" not in q or q["stable"] is False or q["phase_margin_deg"] is None \
        or math.isfinite(q["phase_margin_deg"])


# -- NXP MCAT (nxp-mcuxpresso/mcuxsdk-examples : …/twrmc56f8200/…/m1_pmsm_appconfig.h) --------

def test_nxp_fractions_are_the_printed_decimals(nxp):
    m = nxp["macros"]
    assert nxp["profile"] == "nxp"
    # ACC32(0.257498) = (acc32_t)(0.257498·32768) = (acc32_t)8437.69 → 8437
    assert m["M1_D_KP_GAIN"]["value"] == 8437
    # FRAC16(0.909091) = 29789.09 → 29789; ·N_MAX 4400 rpm
    assert m["M1_N_NOM"]["value"] == 29789
    assert m["M1_N_NOM"]["si"] == pytest.approx(29789 / 32768 * 4400, rel=1e-6)
    # FRAC16(-0.375) = -12288 → −3 A of I_MAX 8 A
    assert m["M1_SPEED_LOOP_LOW_LIMIT"]["si"] == pytest.approx(-3.0, rel=1e-12)


def test_nxp_motor_recovered_from_the_observer_scales_matches_its_json(nxp):
    # JSON: Rs 0.54 Ω, Ld 0.3356 mH, Lq 0.218 mH, PP 4; the header's integers carry them
    mot = nxp["design"]["input"]["motor"]
    assert mot["rs_ohm"] == pytest.approx(0.54, rel=1e-3)
    assert mot["ld_h"] == pytest.approx(0.0003356, rel=1e-3)
    assert mot["lq_h"] == pytest.approx(0.000218, rel=1e-3)
    assert mot["pole_pairs"] == 4


def test_nxp_current_loop_design_inputs_come_back(nxp):
    # JSON currentLoopF0 288 Hz, ξ 1: Kp = (2ξω0·L − R)·I/U, Ki = ω0²·L·Ts/2·I/U
    for axis in ("d", "q"):
        c = nxp["design"]["current_loop"][axis]
        assert c["mcat_f0_hz"] == pytest.approx(288.0, rel=2e-3)
        assert c["mcat_ksi"] == pytest.approx(1.0, rel=2e-3)
        assert c["cancels_plant"] is False


def test_nxp_every_constant_agrees_with_its_json(nxp):
    assert len(nxp["design"]["json_checked"]) >= 25
    assert not [f for f in nxp["findings"] if f["code"] == "json"]
    # by hand for one: (2·1·2π·288·0.0003356 − 0.54)·8/(36.3/√3) = 0.674575·0.381719 = 0.257497
    kp = (2 * 2 * math.pi * 288 * 0.0003356 - 0.54) * 8 / (36.3 / math.sqrt(3))
    assert int(kp * 32768) == nxp["macros"]["M1_D_KP_GAIN"]["value"]


def test_nxp_a_constant_edited_by_hand_disagrees_with_the_json():
    (n, t), = _files("nxp", ["m1_pmsm_appconfig.h"])
    d = audit([(n, t.replace("ACC32(0.257498)", "ACC32(0.27)"))])
    f = [f for f in d["findings"] if f["code"] == "json"]
    # 0.27·32768 = 8847 against 8437: 410 LSB
    assert [x["macros"] for x in f] == [["M1_D_KP_GAIN"]] and "410" in f[0]["message"]


def test_nxp_encoder_macros_checked_against_the_json_flag_the_linix_hand_edit():
    """The encoder's macros join the JSON check: the BSD pmsm_enc header agrees in all 11; the
    linix file (its numbers, mcat_linix.json, rebuilt as MCAT lays a header out) disagrees in
    exactly the six tracking-observer lines edited by hand (README of the fixtures)."""
    twin = audit(_files("nxp", ["mcat_enc_mc56f83000evk_m1_pmsm_appconfig.h"]))
    enc = [n for n in twin["design"]["json_checked"] if n.startswith(("M1_POSPE_", "M1_POS_P_"))]
    assert len(enc) == 11 and not [f for f in twin["findings"] if f["code"] == "json"]
    d = json.loads((HEADERS / "nxp" / "mcat_linix.json").read_text(encoding="utf-8"))
    text = "/*\n" + json.dumps(d["mcat"], indent=4) + "\n*/\n" + "".join(
        f"#define {k} {v}\n" for k, v in d["printed"].items())
    f = [f for f in audit([("m1_pmsm_appconfig.h", text)])["findings"] if f["code"] == "json"]
    assert sorted(x["macros"][0] for x in f) == sorted(
        f"M1_POSPE_TO_{g}_{k}" for g in ("KP", "KI", "THETA") for k in ("GAIN", "SHIFT"))
    # 0.0000318310·2^15 stores 1 where MCAT's T·ω_mech/π = 0.938667·2^-6 stores 30758
    theta = next(x for x in f if x["macros"] == ["M1_POSPE_TO_THETA_GAIN"])
    assert "= 1," in theta["message"] and "30758" in theta["message"]


def test_nxp_sample_time_without_the_json(nxp):
    (n, t), = _files("nxp", ["m1_pmsm_appconfig.h"])
    start = t.index("/*\n{")
    d = audit([(n, t[:start] + t[t.index("*/", start) + 2:])])
    # M1_SCALAR_INTEG_GAIN = ACC32(0.0586667) = 1922; /2^15/(2·293.333 Hz) = 9.998e-5 s
    assert d["design"]["ts_s"] == pytest.approx(1922 / 32768 / (2 * 293.333), rel=1e-6)
    assert d["design"]["mcat_inputs"] is None


def test_nxp_speed_integral_gain_loses_one_lsb_in_67(nxp):
    # the JSON's Ki 0.009 A/rad: 0.009·ω_max/I_max·T_speed·2^15 = 67.94, which ACC32 truncates
    # to 67 (−1.39 %)
    f = [f for f in nxp["findings"] if f["code"] == "rounding"]
    assert [x["macros"] for x in f] == [["M1_SPEED_PI_INTEG_GAIN"]]
    w_max = 2 * math.pi * 4400 * 4 / 60
    ideal = 0.009 * w_max / 8 * 0.001 * 32768
    assert f"{ideal:.4f}" in f[0]["message"] and f"{100 * (67 - ideal) / ideal:.2f} %" in f[0]["message"]
    # ω_max from the header's printed M1_FREQ_MAX (6 digits)
    assert nxp["macros"]["M1_SPEED_PI_INTEG_GAIN"]["si"] == pytest.approx(67 / 32768 * 8 / w_max * 2 / 0.001,
                                                                         rel=1e-5)


# -- NXP MCAT, floating-point variant (nxp-appcodehub/an-mc-pmsm-mcxe31b : source/…) --------

@pytest.fixture(scope="module")
def nxp_float():
    return audit(_files("nxp", ["m1_pmsm_appconfig_float.h"]))


def test_nxp_float_variant_is_si(nxp_float):
    d = nxp_float
    assert d["profile"] == "nxp" and d["design"]["variant"] == "float"
    # JSON: Rs 0.45 Ω, Ld 0.375 mH, Lq 0.429 mH, Ts 62.5 µs; the observer floats carry them
    mot = d["design"]["input"]["motor"]
    assert mot["rs_ohm"] == pytest.approx(0.45, rel=1e-4)
    assert mot["ld_h"] == pytest.approx(0.000375, rel=1e-4)
    assert mot["lq_h"] == pytest.approx(0.000429, rel=1e-4)
    # M1_D_KP_GAIN (1.24646F) = 2·1·2π·360·0.000375 − 0.45 V/A
    kp = 2 * 2 * math.pi * 360 * 0.000375 - 0.45
    assert d["macros"]["M1_D_KP_GAIN"]["si"] == pytest.approx(kp, rel=1e-5)
    # M1_N_NOM (837.758F) rad/s = 4000 rpm · 2 pole pairs · 2π/60
    assert d["macros"]["M1_N_NOM"]["si"] == pytest.approx(4000 * 2 * 2 * math.pi / 60, rel=1e-6)
    assert d["macros"]["M1_N_NOM"]["unit"] == "rad/s"


def test_nxp_float_startup_current_disagrees_with_its_json(nxp_float):
    # #define M1_OL_START_I (0.6F) while the JSON says sensorlessStartupCurrent 0.35 A: the one
    # constant of this file that its own inputs do not give
    f = [(x["code"], x["macros"]) for x in nxp_float["findings"]]
    assert f == [("json_float", ["M1_OL_START_I"])]
    assert len(nxp_float["design"]["json_checked"]) >= 20


def test_nxp_float_sample_time_without_the_json():
    (n, t), = _files("nxp", ["m1_pmsm_appconfig_float.h"])
    start = t.index("/*\n{")
    d = audit([(n, t[:start] + t[t.index("*/", start) + 2:])])
    # ACC32(0.0183333) = 600 (600.75 truncated): 600/2^15/(2·146.667 Hz) = 62.42 µs, 0.12 % low
    assert d["design"]["ts_s"] == pytest.approx(600 / 32768 / (2 * 146.667), rel=1e-6)
    # TO_THETA_GAIN (0.0000198944F) = T_s/π
    assert d["design"]["observer"]["ts_from_theta_s"] == pytest.approx(0.0000198944 * math.pi,
                                                                       rel=1e-6)


# -- TI universal lab (anyway-blows/ti-c2000-motor-control-sdk) ------------------------------

def test_ti_selected_motor_and_board(ti):
    m = ti["macros"]
    assert ti["profile"] == "ti" and ti["target"] == "c28x"
    # USER_MOTOR1 == Teknic_M2310PLN04K (122 in user_common.h): 4 pole pairs, 0.38157931f
    assert m["USER_MOTOR1_NUM_POLE_PAIRS"]["value"] == 4
    assert m["USER_MOTOR1_Rs_Ohm"]["value"] == pytest.approx(0.38157931, rel=1e-7)
    # BSXL8323RS_REVA: 47.14285714f A over the whole ADC range
    assert ti["design"]["input"]["board"]["current"]["max_a"] == pytest.approx(47.14285714 / 2,
                                                                               rel=1e-7)
    # (float32_t)USER_M1_CTRL_PERIOD_usec/(float32_t)1000000.0 with 1000/15 µs
    assert m["USER_M1_CTRL_PERIOD_sec"]["value"] == pytest.approx(1 / 15000, rel=1e-7)
    assert not ti["findings"]


def test_ti_current_and_speed_pi_as_the_lab_computes_them_at_run_time(ti):
    # motor_common.c setupControllers (MotorControl SDK v3.03): Kp = L·BWc, Ki = 0.25·R/L·T
    # (series: ki = Kp·Ki/T), speed Kp = BWc/(δ·Kctrl), Ki = BWc·T_spd/δ², Kctrl = 3·pp·ψ/(2J)
    bwc, t = 2.0 * math.pi * 400.0, 1.0 / 15000.0
    r, l, pp = 0.38157931, 1.8829548e-4, 4
    psi, j = 0.03966425 / (2.0 * math.pi), 7.06154e-06
    for axis in ("d", "q"):
        c = ti["design"]["current_loop"][axis]
        assert c["kp_v_per_a"] == pytest.approx(l * bwc, rel=1e-6)
        assert c["ki_v_per_a_s"] == pytest.approx(l * bwc * 0.25 * r / l * t / t, rel=1e-6)
        assert c["zero_rad_s"] == pytest.approx(0.25 * r / l, rel=1e-6)
        assert c["cancels_plant"] is False and c["stable"] is True
    sp = ti["design"]["speed_loop"]
    kctrl = 3.0 * pp * psi / (2.0 * j)
    assert sp["kp_a_per_hz"] == pytest.approx(bwc / (10.0 * kctrl), rel=1e-6)
    assert sp["ki_series"] == pytest.approx(bwc * 10.0 * t / 100.0, rel=1e-6)
    # closed loop s² + k·kp·s + k·ki with k = 1.5·pp²·ψ/(2πJ) (A → electrical Hz/s)
    k = 1.5 * pp * pp * psi / (2.0 * math.pi * j)
    wn = math.sqrt(k * sp["ki_a_per_hz_s"])
    assert sp["natural_hz"] == pytest.approx(wn / (2.0 * math.pi), rel=1e-6)
    assert sp["damping"] == pytest.approx(k * sp["kp_a_per_hz"] / (2.0 * wn), rel=1e-6)
    assert ti["design"]["input"]["current_loop"]["kp"] == pytest.approx(l * bwc, rel=1e-6)
    assert ti["regenerated"]["header"]


def test_nxp_observers_come_back_to_their_json_design(nxp):
    s = nxp["design"]["mcat_inputs"]["sensorless"]
    ob = nxp["design"]["observer"]
    assert ob["tracking"]["natural_hz"] == pytest.approx(s["sensorlessTrackObsrvF0"], rel=1e-4)
    assert ob["tracking"]["damping"] == pytest.approx(s["sensorlessTrackObsrvKsi"], rel=1e-4)
    assert ob["bemf"]["natural_hz"] == pytest.approx(s["sensorlessBemfObsrvF0"], rel=1e-4)
    assert ob["bemf"]["damping"] == pytest.approx(s["sensorlessBemfObsrvKsi"], rel=1e-4)


def test_nxp_float_observers_come_back_to_their_json_design(nxp_float):
    s = nxp_float["design"]["mcat_inputs"]["sensorless"]
    ob = nxp_float["design"]["observer"]
    assert ob["tracking"]["natural_hz"] == pytest.approx(s["sensorlessTrackObsrvF0"], rel=1e-5)
    assert ob["bemf"]["natural_hz"] == pytest.approx(s["sensorlessBemfObsrvF0"], rel=1e-5)
    assert ob["bemf"]["damping"] == pytest.approx(s["sensorlessBemfObsrvKsi"], rel=1e-5)


def test_nxp_speed_loop_from_its_manual_gains_and_the_json_mechanics(nxp):
    p = nxp["design"]["mcat_inputs"]["parameters"]
    sl = nxp["design"]["speed_loop"]
    k = p["parametersPP"] * p["parametersKt"] / p["parametersJ"]
    # the JSON's manual Kp = 0.003 A/(rad/s) and Ki 0.009 stored as 0.009·T_speed per sample,
    # which the trapezoidal PI (e_k + e_k−1) integrates twice: ki = 0.018 A/rad
    ki = 2 * 0.009
    assert sl["ki_a_per_rad"] == pytest.approx(ki, rel=0.02)  # 67 of 67.94 LSB
    wn = math.sqrt(k * ki)
    assert sl["natural_hz"] == pytest.approx(wn / (2.0 * math.pi), rel=0.01)
    assert sl["damping"] == pytest.approx(k * 0.003 / (2.0 * wn), rel=0.02)


def test_ti_am26x_lab_estun_servo_on_the_high_voltage_kit():
    # TexasInstruments/motor-control-sdk (AM26x), HVMTRPFC_REV1P1 selects the Estun EMJ-04APB22
    files = [(f"am263x/{n}", (HEADERS / "ti" / "am263x" / n).read_text(encoding="utf-8"))
             for n in ("user_mtr1.h", "user_common.h")]
    d = audit(files, defines=["HVMTRPFC_REV1P1"])
    m = d["design"]["input"]["motor"]
    assert (m["rs_ohm"], m["ld_h"], m["pole_pairs"]) == pytest.approx((2.3679111, 0.00836551283, 4))
    assert d["design"]["input"]["drive"]["udc_v"] == 220.0
    assert d["design"]["input"]["board"]["bus"]["max_v"] == pytest.approx(409.90)
    # this SDK's user_mtr1.c: BWc = 2π·200 rad/s, δ = 20 (the C2000 lab: 2π·400, 10)
    q = d["design"]["current_loop"]["q"]
    assert q["runtime"]["sdk"] == "AM26x motor-control-sdk"
    assert q["kp_v_per_a"] == pytest.approx(0.00836551283 * 2 * math.pi * 200, rel=1e-6)
    assert q["zero_rad_s"] == pytest.approx(0.25 * 2.3679111 / 0.00836551283, rel=1e-6)
    assert d["design"]["speed_loop"]["delta"] == 20.0
    # the file names no rated speed: no round trip, said so
    assert set(d["design"]["missing"]) == {"motor.rated_freq_hz", "motor.bemf_v"}
    # it compares an id user_common.h never defines, but its own choice does not depend on it
    f = [f for f in d["findings"] if f["code"] == "if_undefined"]
    assert [(x["severity"], "Regal_Beloit_5SME39DL0756" in x["message"]) for x in f] == [("note", True)]


def test_ti_without_user_common_every_motor_id_is_zero():
    d = audit(_files("ti", ["user_mtr1.h"]), defines=["BSXL8323RS_REVA"])
    f = d["findings"][0]
    assert f["code"] == "if_undefined" and "Teknic_M2310PLN04K" in f["message"]
    # 0 == 0: the first motor (Estun_EMJ_04APB22_A) is read, not the one selected
    assert d["macros"]["USER_MOTOR1_Rs_Ohm"]["value"] != pytest.approx(0.38157931)


def test_ti_flux_comment_matches_no_reading():
    files = [(n, t.replace("#define USER_MOTOR1 Teknic_M2310PLN04K",
                           "#define USER_MOTOR1 Anaheim_BLWS235D"))
             for n, t in _files("ti", ["user_mtr1.h", "user_common.h"])]
    d = audit(files, defines=["BSXL8323RS_REVA"])
    f = [f for f in d["findings"] if f["code"] == "comment_value"]
    assert len(f) == 1 and "4.11 V/krpm" in f[0]["message"]
    # 0.560590863 V/Hz at 2 pole pairs: 0.560590863·2·1000/60 = 18.69 V phase peak per krpm,
    # 32.4 line peak, 22.9 line rms, 13.2 phase rms — none is 4.11
    assert "phase peak 18.7" in f[0]["message"] and "line rms 22.9" in f[0]["message"]


def test_ti_without_a_board_the_files_own_error_names_its_line():
    with pytest.raises(InputError) as e:
        audit(_files("ti", ["user_mtr1.h", "user_common.h"]))
    assert "user_mtr1.h:571" in e.value.message and "#error" in e.value.message


# -- Microchip motorBench (microchip-pic-avr-solutions/motorbench-release-collateral) --------

@pytest.fixture(scope="module")
def mchp():
    return audit(_files("microchip", ["motor_params.h", "foc_params.h"]))


def test_microchip_constants_are_their_printed_si_values(mchp):
    m = mchp["macros"]
    assert mchp["profile"] == "microchip"
    # no _SCALE macros in this version: the scale is the comment's SI value over its Q value,
    # both printed with 5–6 digits (relative error ≤ 0.5e-5/0.14737 = 3.4e-5)
    assert m["MCAF_MOTOR_RS"]["si"] == pytest.approx(0.24099626, rel=4e-5)  # +240.99626 mohm
    assert m["KIP"]["si"] == pytest.approx(0.59922182, rel=2e-5)  # +599.22182 mV/A
    assert m["KII"]["si"] == pytest.approx(1766.67, rel=1e-4)  # +1.76667 kV/A/s
    assert m["MCAF_MOTOR_LQ_BASE_DT"]["si"] == pytest.approx(132.50053e-6, rel=1e-5)
    assert mchp["design"]["input"]["motor"]["pole_pairs"] == 4


def test_microchip_every_integer_rederived_from_its_printed_design_value(mchp):
    # motorBench prints the value each integer was designed for: all 28 round to the integer
    checked = mchp["design"]["comment_checked"]
    assert len(checked) == 28 and set(checked.values()) == {0}
    assert {"KIP", "KII", "KWP", "KWI", "MCAF_MOTOR_RS", "MCAF_MOTOR_LD_BASE_DT"} <= set(checked)


def test_microchip_pwm_period_from_the_two_pi_scales(mchp):
    # KII's base is KIP's over Δt: (0.59922182/0.36642)/(1766.67/0.05402) = 1.63534/32704 = 50 µs
    assert mchp["design"]["ts_s"] == pytest.approx(50e-6, rel=2e-4)


def test_microchip_speed_integral_gain_is_the_rounding_it_prints(mchp):
    # KWI 8 // … = +16.94130 mA/rad = +17.14283 mA/rad - 1.1756%
    f = [f for f in mchp["findings"] if f["code"] == "rounding"]
    assert [x["macros"] for x in f] == [["KWI"]] and "-1.1756" in f[0]["message"]


def test_microchip_integer_edited_after_generation():
    files = [(n, t.replace("#define KIP                                 12007",
                           "#define KIP                                 13007"))
             for n, t in _files("microchip", ["motor_params.h", "foc_params.h"])]
    f = [f for f in audit(files)["findings"] if f["code"] == "comment_stale"]
    assert [x["macros"] for x in f] == [["KIP"]] and "Q15(0.36642)" in f[0]["message"]


# -- pu-lab's own headers, decoded back -----------------------------------------------------

def _own(vendor: str, extra: dict | None = None) -> tuple:
    inp = copy.deepcopy(SEED_INPUT)
    inp["profiles"] = extra or {}
    r = report(inp)
    text = profiles.header(r, vendor)
    return r, audit([(f"{vendor}.h", text)])


@pytest.mark.parametrize("vendor, extra, kp_name", [
    ("st", None, "PID_TORQUE_KP_DEFAULT"),
    ("ti", None, "USER_MTR1_KP_IQ_IQ"),
    ("nxp", {"nxp": {"trapezoidal": True}}, "M1_Q_KP_GAIN"),
    ("microchip", None, "KIP"),
])
def test_own_header_round_trip(vendor, extra, kp_name):
    r, d = _own(vendor, extra)
    assert d["profile"] == vendor
    pi = r["current_pi"]["q"]
    c = d["design"]["current_loop"]["q"]
    # the integers' quantization: below 0.1 % for these gains at this motor
    assert c["kp_v_per_a"] == pytest.approx(pi["kp"], rel=1e-3)
    assert c["ki_v_per_a_s"] == pytest.approx(pi["ki"], rel=1e-3)
    mot = d["design"]["input"]["motor"]
    if vendor in ("st", "ti"):  # pu-lab's NXP and Microchip blocks have no pole pairs
        assert mot["pole_pairs"] == 4
    # NXP's R and L come back through its Q15 observer scales, Microchip's through Q15/Q13
    rel = {"nxp": 2e-3, "microchip": 1e-4}.get(vendor, 1e-12)
    assert mot["rs_ohm"] == pytest.approx(1.5, rel=rel)
    assert mot["lq_h"] == pytest.approx(6e-4, rel=rel)
    assert d["design"]["input"]["drive"]["ts_s"] == pytest.approx(1e-4, rel=2e-3)


def test_own_inovance_block_round_trip():
    r, d = _own("inovance")
    m = d["macros"]
    # the raw table back in SI: the seed motor (17 V, 1.5 A, 220 Hz, 1.5 Ω, 0.6 mH)
    assert d["design"]["input"]["motor"] == {k: pytest.approx(SEED_INPUT["motor"][k], rel=1e-12)
                                             for k in d["design"]["input"]["motor"]}
    assert m["PULAB_RPM"]["value"] == 15022  # seed 1.4-1
    assert m["PULAB_PM_KP_Q"]["si"] == pytest.approx(r["current_pi"]["q"]["from_integers"]["kp"],
                                                     rel=1e-12)
    assert not d["findings"]
    assert d["design"]["missing"] == ["motor.pole_pairs", "drive.ts_s"]


def test_inovance_integer_edited_after_the_raw_table():
    r = report({**copy.deepcopy(SEED_INPUT), "profiles": {}})
    text = profiles.header(r, "inovance").replace("PULAB_RPM                    15022",
                                                   "PULAB_RPM                    15100")
    f = audit([("p.h", text)])["findings"]
    assert [x["code"] for x in f] == ["inconsistent"] and "15022" in f[0]["message"]


# -- bad input ------------------------------------------------------------------------------

@pytest.mark.parametrize("files, field, words", [
    ([], "files", "at least one"),
    ([("a.h", "  \n")], "files[0]", "empty"),
    ([("a.h", "#define FOO 1\n")], "files", "no #define of a known vendor"),
    ([("a.h", "#define RS (0.35\n#define LS 1e-3\n")], "files", "a.h:1: #define RS"),
    ([("a.h", "#define RS 0.35\n#if 1\n")], "files", "a.h:2"),
    ([("a.h", "#define RS 1\x00\n")], "files[0]", "NUL"),
    # a macro bomb: M0 expands to 3^20 tokens; the error names M0's #define (line 2)
    ([("a.h", "#define RS 0.35\n" + "".join(f"#define M{i} (M{i+1} M{i+1} M{i+1})\n"
                                             for i in range(20)) + "#define M20 1\n")],
     "files", "a.h:2: macro"),
])
def test_bad_input_names_the_file(files, field, words):
    with pytest.raises(InputError) as e:
        audit(files)
    assert e.value.field == field and words in e.value.message


def test_cli_exit_codes(tmp_path):
    ok = subprocess.run([sys.executable, "-m", "pulab", "audit",
                         *(str(HEADERS / "st" / n) for n in ST_SET)],
                        capture_output=True, text=True, cwd=ROOT, env={"PYTHONPATH": "py"})
    assert ok.returncode == 0 and json.loads(ok.stdout)["profile"] == "st"
    empty = tmp_path / "empty.h"
    empty.write_text("")
    bad = subprocess.run([sys.executable, "-m", "pulab", "audit", str(empty)],
                         capture_output=True, text=True, cwd=ROOT, env={"PYTHONPATH": "py"})
    assert bad.returncode == 2 and bad.stdout == ""
    assert bad.stderr.count("\n") == 1 and bad.stderr.startswith("error: files[0]: ")


def test_mutated_headers_end_in_a_result_or_one_input_error():
    """500 seeded mutations of the real headers (characters deleted, doubled, swapped for C
    punctuation): each is audited or raises InputError, nothing else."""
    import random
    rng = random.Random(32)
    texts = [t for v, names in (("st", ST_SET[:2]), ("nxp", ["m1_pmsm_appconfig.h"]),
                                ("microchip", ["foc_params.h"]))
             for _, t in _files(v, names)]
    seen = {"ok": 0, "error": 0}
    for _ in range(500):
        t = list(rng.choice(texts))
        for _ in range(rng.randint(1, 8)):
            k = rng.randrange(len(t))
            op = rng.random()
            if op < 0.4:
                del t[k]
            elif op < 0.7:
                t[k] = rng.choice("()#/*\\\n\"'?:-+~!0123456789.efUL,")
            else:
                t.insert(k, t[k] * rng.randint(1, 50))
        try:
            audit([("m.h", "".join(t))])
            seen["ok"] += 1
        except InputError:
            seen["error"] += 1
    assert seen["ok"] > 100 and seen["error"] > 10, seen


# -- the contract outside tests rely on: keys, shapes, exit codes -----------------------------

_MACRO_KEYS = {"value", "si", "unit", "meaning", "formula", "source"}
_LOOP_KEYS = {"kp_v_per_a", "ki_v_per_a_s", "bandwidth_hz", "zero_rad_s", "cancels_plant"}
_FINDING_KEYS = {"severity", "code", "macros", "message", "message_zh", "advice"}
_DESIGN_INPUTS = (("motor", "rs_ohm"), ("motor", "ld_h"), ("motor", "lq_h"), ("motor", "pole_pairs"),
                  ("drive", "ts_s"), ("drive", "udc_v"))


def _cli(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "pulab", *map(str, args)], input=stdin,
                          capture_output=True, text=True, cwd=ROOT, env={"PYTHONPATH": "py"})


def _check_contract_shape(out: dict, profile: str) -> None:
    assert out["profile"] == profile
    assert out["macros"]
    for name, m in out["macros"].items():
        assert _MACRO_KEYS <= set(m), name
        assert isinstance(m["value"], (int, float)) and not isinstance(m["value"], bool), name
        assert m["si"] is None or isinstance(m["si"], float), name
        assert m["unit"] is None or isinstance(m["unit"], str), name
        assert all(isinstance(m[k], str) for k in ("meaning", "formula", "source")), name
    d = out["design"]
    assert {"input", "current_loop", "speed_loop", "observer"} <= set(d)
    # each of these is in design.input, or named in design.missing when the files do not fix it
    for sec, key in _DESIGN_INPUTS:
        v = d["input"].get(sec, {}).get(key)
        assert isinstance(v, (int, float)) or f"{sec}.{key}" in d["missing"], (sec, key)
    assert set(d["current_loop"]) <= {"d", "q"}
    for axis, c in d["current_loop"].items():
        assert _LOOP_KEYS <= set(c), axis
        assert isinstance(c["cancels_plant"], bool)
        assert all(isinstance(c[k], float) for k in ("kp_v_per_a", "ki_v_per_a_s", "bandwidth_hz"))
    assert d["speed_loop"] is None or isinstance(d["speed_loop"], dict)
    assert d["observer"] is None or isinstance(d["observer"], dict)
    for f in out["findings"]:
        assert set(f) == _FINDING_KEYS
        assert isinstance(f["macros"], list) and all(isinstance(n, str) for n in f["macros"])
        assert chinese(f["message_zh"])


def test_cli_output_has_every_key_and_shape_of_the_contract():
    p = _cli("audit", *(HEADERS / "st" / n for n in ST_SET), "--profile", "st",
             "-D", "SQRT_3=1.732051")
    assert p.returncode == 0 and p.stderr == "", p.stderr
    out = json.loads(p.stdout)
    _check_contract_shape(out, "st")
    assert out["design"]["missing"] == []
    assert all(isinstance(out["design"]["input"][s][k], (int, float)) for s, k in _DESIGN_INPUTS)
    assert set(out["design"]["current_loop"]) == {"d", "q"}
    # roundtrip.NAME for every macro with a value in both the file set and pu-lab's header, or
    # among the constants pu-lab's profile computes (ST's conversion file derives C1…C5 itself)
    mine = {n: m["value"] for n, m in
            audit([("pulab_st.h", out["regenerated"]["header"])], "st")["macros"].items()}
    inp = copy.deepcopy(out["design"]["input"])
    for n, c in report(inp)["profiles"]["st"]["constants"].items():
        mine.setdefault(n, c["value"])
    both = {n for n, m in out["macros"].items() if n in mine}
    assert {"C1", "C5", "CURRENT_CONV_FACTOR", "PID_TORQUE_KP_DEFAULT"} <= both
    assert set(out["roundtrip"]) == both
    for n, r in out["roundtrip"].items():
        a, b = out["macros"][n]["value"], mine[n]
        assert (r["file"], r["pulab"]) == (a, b), n
        if isinstance(a, int) and isinstance(b, int):
            assert set(r) == {"file", "pulab", "delta_lsb"} and r["delta_lsb"] == a - b, n
        else:
            assert set(r) == {"file", "pulab", "delta_rel"}, n
    # design.input is a valid `pulab report` input
    rep = _cli("report", "-", stdin=json.dumps(out["design"]["input"]))
    assert rep.returncode == 0 and json.loads(rep.stdout)["input"]["motor"]["rs_ohm"] == 0.35


@pytest.mark.parametrize("vendor, names, defines", [
    ("nxp", ["m1_pmsm_appconfig.h"], []),
    ("ti", ["user_mtr1.h", "user_common.h"], ["BSXL8323RS_REVA"]),
    ("microchip", ["motor_params.h", "foc_params.h"], []),
])
def test_api_reply_has_the_contract_shape_and_equals_the_cli(vendor, names, defines):
    from pulab.api import call_json
    # named as the CLI names them (its path), so that ``source`` and ``files`` agree too
    files = [{"name": str(HEADERS / vendor / n), "text": t} for n, t in _files(vendor, names)]
    out = json.loads(call_json("audit", json.dumps({"files": files, "define": defines})))
    assert out["ok"] is True and set(out) == {"ok", "audit"}
    r = out["audit"]
    assert isinstance(r["roundtrip"], dict)
    for m in r["roundtrip"].values():
        assert {"file", "pulab"} < set(m) and ("delta_lsb" in m) != ("delta_rel" in m)
    _check_contract_shape(r, vendor)
    given = json.loads(call_json("audit", json.dumps({"files": files, "profile": vendor,
                                                      "define": defines})))
    assert given == out
    p = _cli("audit", *(HEADERS / vendor / n for n in names), *(a for d in defines for a in ("-D", d)))
    assert p.returncode == 0 and json.loads(p.stdout) == r


def _one_error_line(p, field: str) -> None:
    assert p.returncode == 2 and p.stdout == "", p
    assert p.stderr.count("\n") == 1 and p.stderr.startswith(f"error: {field}: "), p.stderr


def test_cli_bad_input_is_one_line_and_exit_2(tmp_path):
    binary = tmp_path / "firmware.bin"
    binary.write_bytes(b"\x7fELF\x02\x01\x01\x00" + bytes(range(256)) * 4)
    _one_error_line(_cli("audit", binary), "files[0]")
    bomb = tmp_path / "bomb.h"
    bomb.write_text("#define RS 0.35\n" + "".join(f"#define M{i} (M{i+1} M{i+1} M{i+1})\n"
                                                 for i in range(20)) + "#define M20 1\n")
    p = _cli("audit", bomb)
    _one_error_line(p, "files")
    assert "bomb.h:2" in p.stderr  # the #define of M0, 3^20 tokens
    big = tmp_path / "big.h"
    with open(big, "w") as f:  # 10 MB of valid #defines
        f.write("#define RS 0.35\n" + "#define X 1\n" * 900_000)
    assert big.stat().st_size > 10_000_000
    _one_error_line(_cli("audit", big), "files[0]")
    _one_error_line(_cli("audit", "-", stdin="#define RS 0.35\n" + "#define X 1\n" * 900_000),
                    "files[0]")
    other = tmp_path / "config.h"
    other.write_text("#define LED_PIN 13\n#define BAUD 115200\n")
    p = _cli("audit", other)
    _one_error_line(p, "files")
    assert "no #define of a known vendor" in p.stderr
    _one_error_line(_cli("audit", HEADERS / "nxp" / "m1_pmsm_appconfig.h", "--profile", "abb"),
                    "profile")
    _one_error_line(_cli("audit", tmp_path / "missing.h"), "files[0]")


@pytest.mark.parametrize("req, field", [
    ({"files": [{"name": "big.h", "text": "#define RS 0.35\n" + "#define X 1\n" * 900_000}]},
     "files[0]"),
    ({"files": [{"name": "b.h", "text": "#define RS 0.35\n" + "".join(
        f"#define M{i} (M{i+1} M{i+1} M{i+1})\n" for i in range(20)) + "#define M20 1\n"}]}, "files"),
    ({"files": [{"name": "a.bin", "text": "\x7fELF\x00\x01"}]}, "files[0]"),
    ({"files": [{"name": "c.h", "text": "#define LED_PIN 13\n"}]}, "files"),
    ({"files": [{"name": "a.h", "text": "#define RS 0.35\n"}], "profile": "abb"}, "profile"),
    ({"files": [], "profile": "st"}, "files"),
    ({"files": [{"name": "a.h", "text": "#define RS 0.35\n"}], "vendor": "st"}, "vendor"),
])
def test_api_bad_input_names_its_field(req, field):
    from pulab.api import call_json
    out = json.loads(call_json("audit", json.dumps(req)))
    assert out["ok"] is False and out["field"] == field, out
    assert out["message"] and chinese(out["message_zh"])


def test_nxp_newer_mcat_spelling_of_the_pole_pairs_is_checked_too():
    """MCAT's newer headers spell the pole pairs parametersPp: their constants are checked
    against the JSON as the older ones' are."""
    name = "mcat_enc_mc56f81000evk_2025_m1_pmsm_appconfig.h"
    text = (HEADERS / "nxp" / name).read_text(encoding="utf-8")
    assert '"parametersPp"' in text and '"parametersPP"' not in text
    d = audit([(name, text)])
    assert len(d["design"]["json_checked"]) >= 25
    assert not [f for f in d["findings"] if f["code"] == "json"]
