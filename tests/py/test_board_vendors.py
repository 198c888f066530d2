"""Each vendor reads the board its own way: the constants its header holds, from the board's
schematic values, against the numbers vendors' public files print.

Files read (numbers reproduced below):
- TI universal lab, anyway-blows/ti-c2000-motor-control-sdk :
  solutions/universal_motorcontrol_lab/common/include/user_mtr1.h — BOOSTXL-DRV8323RS
  ``USER_M1_ADC_FULL_SCALE_CURRENT_A (47.14285714f)`` (7 mΩ, gain 10),
  ``USER_M1_ADC_FULL_SCALE_VOLTAGE_V (57.52845691f)``, ``USER_M1_CURRENT_SF`` = full scale/4096,
  ``USER_M1_PWM_TBPRD_NUM`` = (uint16_t)(SYSTEM_FREQ_MHz·1000/PWM_FREQ_kHz/2).
- TI MotorWare, scottmcdaid/instaspin-labs : sw/solutions/instaspin_foc/boards/
  boostxldrv8301_revB/f28x/f2806xF/src/user_j1.h — BOOSTXL-DRV8301 revB
  ``USER_ADC_FULL_SCALE_CURRENT_A (33.0)`` (10 mΩ, gain 10), ``USER_ADC_FULL_SCALE_VOLTAGE_V
  (26.314)`` (34.8 kΩ over 4.99 kΩ), ``USER_IQ_FULL_SCALE_CURRENT_A (20.0)`` with TI's warning
  that it "MUST be larger than the maximum current readings".
- ST MCSDK, dronectl/g431-mcsdk : Inc/power_stage_parameters.h (RSHUNT 0.003,
  AMPLIFICATION_GAIN 9.14, VBUS_PARTITIONING_FACTOR 0.09625565501973242, HW_DEAD_TIME_NS 800)
  and Inc/parameters_conversion.h (MAX_CURRENT, CURRENT_CONV_FACTOR, PWM_PERIOD_CYCLES,
  DEAD_TIME_COUNTS with its DTG ranges) — the macros written out here and compiled by gcc.
- Microchip MCAF, microchip-pic-avr-solutions/motorbench-release-collateral :
  zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/hal_params.h —
  ``HAL_PARAM_PWM_PERIOD_COUNTS 5000`` (25 µs at 5 ns, "one half-period" center-aligned) and
  ``HAL_PARAM_DEADTIME_COUNTS 200`` (1 µs).
"""
import copy
import json
import pathlib
import struct
import subprocess
import sys

import pytest

import pulab
from conftest import SEED_INPUT
from ctrace_compilers import available
from pulab.profiles import header


def f32(x: float) -> float:
    """What a C compiler stores for the literal ``x f``."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def _report(board, profiles=None):
    inp = copy.deepcopy(SEED_INPUT)
    inp["board"] = board
    inp["profiles"] = profiles or {}
    return pulab.report(inp)


def test_ti_universal_lab_boostxl_drv8323rs():
    r = _report({"current": {"shunt_ohm": 0.007, "gain": 10},
                 "bus": {"r_top_ohm": 82e3, "r_bottom_ohm": 4.99e3},
                 "pwm": {"clock_hz": 100e6, "freq_hz": 10e3}})
    c = r["profiles"]["ti"]["constants"]
    # the literals TI prints, as the compiler stores them
    assert c["USER_M1_ADC_FULL_SCALE_CURRENT_A"]["value"] == f32(47.14285714)
    assert c["USER_M1_ADC_FULL_SCALE_VOLTAGE_V"]["value"] == f32(57.52845691)
    assert c["USER_M1_CURRENT_SF"]["value"] == f32(47.14285714 / 4096.0)
    assert c["USER_M1_VOLTAGE_SF"]["value"] == f32(57.52845691 / 4096.0)
    assert c["USER_M1_PWM_TBPRD_NUM"]["value"] == 100 * 1000 // 10 // 2
    assert c["USER_M1_CURRENT_SF"]["format"] == "float32" and c["USER_M1_CURRENT_SF"]["real"]
    # the header carries them by their own names, as float literals the compiler reads back
    h = header(r, "ti")
    assert "#define USER_M1_ADC_FULL_SCALE_CURRENT_A (47.142857f)" in h
    assert f32(47.142857) == f32(47.14285714)


def test_ti_motorware_boostxl_drv8301_revb():
    r = _report({"current": {"shunt_ohm": 0.010, "gain": 10},
                 "bus": {"r_top_ohm": 34.8e3, "r_bottom_ohm": 4.99e3}})
    p = r["profiles"]["ti"]
    assert p["constants"]["USER_M1_ADC_FULL_SCALE_CURRENT_A"]["value"] == f32(33.0)
    assert round(p["constants"]["USER_M1_ADC_FULL_SCALE_VOLTAGE_V"]["value"], 3) == 26.314
    # the per-unit full scale defaults to the largest reading (±16.5 A): TI's example picks
    # 20 A, above every reading as its warning demands; pulab's default is the least such
    assert p["inputs"]["full_scale_current_a"] == pytest.approx(16.5, rel=1e-15)
    assert p["inputs"]["full_scale_current_a"] <= 20.0
    # and with it every IQ integer of the profile is on the board's scale
    assert p["bases"]["I_b"] == pytest.approx(16.5, rel=1e-15)
    typed = _report({"current": {"shunt_ohm": 0.010, "gain": 10}}, {"ti": {"full_scale_current_a": 16.5}})
    assert p["constants"]["Kp_Iq"]["value"] == typed["profiles"]["ti"]["constants"]["Kp_Iq"]["value"]


def test_a_typed_option_wins_over_the_board():
    r = _report({"current": {"shunt_ohm": 0.010, "gain": 10}},
                {"ti": {"full_scale_current_a": 20.0}, "st": {"amplification_gain": 5.0}})
    assert r["profiles"]["ti"]["inputs"]["full_scale_current_a"] == 20.0
    st = r["profiles"]["st"]["inputs"]
    assert (st["amplification_gain"], st["rshunt_ohm"]) == (5.0, 0.010)


_ST_C = r"""#include <stdio.h>
#include <stdint.h>
#define ADC_REFERENCE_VOLTAGE 3.3
#define RSHUNT 0.003
#define AMPLIFICATION_GAIN 9.14
#define ADV_TIM_CLK_MHz %(mhz)d
#define TIM_CLOCK_DIVIDER 1
#define PWM_FREQUENCY %(freq)d
#define DEADTIME_NS %(ns)d
#define MAX_CURRENT (ADC_REFERENCE_VOLTAGE/(2*RSHUNT*AMPLIFICATION_GAIN))
#define CURRENT_CONV_FACTOR (uint16_t)((65536.0 * RSHUNT * AMPLIFICATION_GAIN)/ADC_REFERENCE_VOLTAGE)
#define PWM_PERIOD_CYCLES (uint16_t)((ADV_TIM_CLK_MHz*(uint32_t)1000000u/((uint32_t)(PWM_FREQUENCY)))& ( uint16_t )0xFFFE)
#define DEAD_TIME_ADV_TIM_CLK_MHz (ADV_TIM_CLK_MHz * TIM_CLOCK_DIVIDER)
#define DEAD_TIME_COUNTS_1  (DEAD_TIME_ADV_TIM_CLK_MHz * DEADTIME_NS/1000uL)
#if (DEAD_TIME_COUNTS_1 <= 255)
#define DEAD_TIME_COUNTS (uint16_t) DEAD_TIME_COUNTS_1
#elif (DEAD_TIME_COUNTS_1 <= 508)
#define DEAD_TIME_COUNTS (uint16_t)(((DEAD_TIME_ADV_TIM_CLK_MHz * DEADTIME_NS/2) /1000uL) + 128)
#elif (DEAD_TIME_COUNTS_1 <= 1008)
#define DEAD_TIME_COUNTS (uint16_t)(((DEAD_TIME_ADV_TIM_CLK_MHz * DEADTIME_NS/8) /1000uL) + 320)
#elif (DEAD_TIME_COUNTS_1 <= 2015)
#define DEAD_TIME_COUNTS (uint16_t)(((DEAD_TIME_ADV_TIM_CLK_MHz * DEADTIME_NS/16) /1000uL) + 384)
#else
#define DEAD_TIME_COUNTS 510
#endif
int main(void) {
    printf("%%.17g %%u %%u %%u\n", MAX_CURRENT, (unsigned)CURRENT_CONV_FACTOR,
           (unsigned)PWM_PERIOD_CYCLES, (unsigned)DEAD_TIME_COUNTS);
    return 0;
}
"""


@pytest.mark.parametrize("mhz, freq, ns", [
    (170, 20000, 800),      # B-G431B-ESC1 as its files set it
    (170, 30000, 2000),     # the DTG's ÷2 range
    (170, 16000, 5000),     # ÷8
    (72, 10000, 25000),     # ÷16
    (170, 10000, 20000),    # beyond the DTG: 510
    (170, 2000, 100),       # 85000 ticks: the uint16_t cast wraps
])
def test_st_board_macros_as_gcc_evaluates_them(tmp_path, mhz, freq, ns):
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    src, exe = tmp_path / "st.c", tmp_path / "st"
    src.write_text(_ST_C % {"mhz": mhz, "freq": freq, "ns": ns})
    subprocess.run(["gcc", str(src), "-o", str(exe)], check=True)
    max_current, conv, cycles, dead = subprocess.run(
        [str(exe)], check=True, capture_output=True, text=True).stdout.split()
    r = _report({"current": {"shunt_ohm": 0.003, "gain": 9.14},
                 "bus": {"ratio": 0.09625565501973242},
                 "pwm": {"clock_hz": mhz * 1e6, "freq_hz": freq, "mode": "up",
                         "deadtime_s": ns * 1e-9}})
    c = r["profiles"]["st"]["constants"]
    assert c["MAX_CURRENT"]["value"] == float(max_current)
    assert c["M1_MAX_READABLE_CURRENT"]["value"] == float(max_current)
    assert c["CURRENT_CONV_FACTOR"]["value"] == int(conv)
    assert c["PWM_PERIOD_CYCLES"]["value"] == int(cycles)
    assert c["DEAD_TIME_COUNTS"]["value"] == int(dead)
    assert c["VBUS_PARTITIONING_FACTOR"]["value"] == 0.09625565501973242
    # a period beyond 16 bits is what the firmware would hold, flagged
    assert ("out_of_range" in c["PWM_PERIOD_CYCLES"]["flags"]) == (mhz * 1e6 / freq > 65535)


def test_st_options_follow_the_board():
    st = _report({"current": {"shunt_ohm": 0.003, "gain": 9.14, "adc_ref_v": 3.0},
                  "bus": {"max_v": 60.0, "adc_ref_v": 3.0}})["profiles"]["st"]["inputs"]
    assert (st["rshunt_ohm"], st["amplification_gain"], st["adc_reference_v"]) == (0.003, 9.14, 3.0)
    assert st["vbus_partitioning_factor"] == 3.0 / 60.0
    # a Hall sensor in V/A: ST's formulas hold only R·G
    hall = _report({"current": {"sensitivity_v_per_a": 0.15}})["profiles"]["st"]
    assert hall["constants"]["MAX_CURRENT"]["value"] == pytest.approx(3.3 / 0.3, rel=1e-15)


def test_nxp_and_microchip_bases_are_the_board_full_scales():
    r = _report({"current": {"shunt_ohm": 0.02, "gain": 10}, "bus": {"max_v": 60.8}})
    nxp, mchp = r["profiles"]["nxp"], r["profiles"]["microchip"]
    assert nxp["inputs"]["i_max_a"] == pytest.approx(8.25, rel=1e-15)    # 3.3/(2·0.02·10)
    assert nxp["constants"]["M1_I_MAX"]["value"] == f32(8.25)
    assert nxp["constants"]["M1_U_DCB_MAX"]["value"] == f32(60.8)
    assert (mchp["inputs"]["current_base_a"], mchp["inputs"]["voltage_base_v"]) == \
        (nxp["inputs"]["i_max_a"], 60.8)


def test_microchip_lvmc_timer_counts():
    # 200 MHz PWM clock (5 ns), 20 kHz center-aligned, 1 µs dead time: 5000 and 200
    c = _report({"pwm": {"clock_hz": 200e6, "freq_hz": 20e3, "deadtime_s": 1e-6}})
    c = c["profiles"]["microchip"]["constants"]
    assert c["HAL_PARAM_PWM_PERIOD_COUNTS"]["value"] == 5000
    assert c["HAL_PARAM_PWM_PERIOD_COUNTS"]["si"] == pytest.approx(25e-6, rel=1e-15)
    assert c["HAL_PARAM_DEADTIME_COUNTS"]["value"] == 200


def test_no_board_no_board_constants():
    r = pulab.report({**copy.deepcopy(SEED_INPUT), "profiles": {}})
    for p in r["profiles"].values():
        assert not [c for c in p["constants"].values() if c.get("real")]
    assert "PWM_PERIOD_CYCLES" not in r["profiles"]["st"]["constants"]


def test_the_fixed_point_simulations_use_the_board_scales():
    from pulab.analyses.sim import vendor_loop
    r = _report({"current": {"shunt_ohm": 0.010, "gain": 10}})
    del r["input"]["profiles"]      # the page's simulation request asks for no profiles
    prof, _ = vendor_loop.profile_data(r)
    assert prof["ti"]["inputs"]["full_scale_current_a"] == pytest.approx(16.5, rel=1e-15)
    assert prof["nxp"]["inputs"]["i_max_a"] == pytest.approx(16.5, rel=1e-15)


# Golden vectors of the independent oracle (tests/oracle/board_vendors_oracle.py, never imports
# pulab); the same files go through Pyodide in tests/web/golden-board-vendors.test.ts.
_ORACLE = pathlib.Path(__file__).resolve().parents[1] / "oracle"
GOLDEN = sorted((_ORACLE.parent / "golden" / "board-vendors").glob("*.json"))


def test_board_vendor_golden_files_are_fresh():
    assert len(GOLDEN) >= 4
    r = subprocess.run([sys.executable, "board_vendors_oracle.py", "--check"],
                       capture_output=True, text=True, cwd=_ORACLE)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_board_vendor_golden(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    prof = pulab.report(case["input"])["profiles"]
    for vendor, want in case["expected"].items():
        assert sorted(prof[vendor].get("board", [])) == sorted(want), vendor
        assert {k: prof[vendor]["constants"][k]["value"] for k in want} == want, vendor


@pytest.mark.parametrize("vendor", ["ti", "nxp", "st", "microchip"])
def test_a_family_proof_uses_the_board_scales(vendor):
    from pulab.api import call_json
    inp = {**copy.deepcopy(SEED_INPUT), "board": {"current": {"shunt_ohm": 0.01, "gain": 10},
                                                  "bus": {"max_v": 60.0},
                                                  "pwm": {"clock_hz": 1e8, "freq_hz": 1e4}}}
    out = json.loads(call_json("prove", json.dumps({
        "input": inp, "ranges": {"motor.rated_current_a": [1.5, 1.5]}, "profile": vendor,
        "budget": 3000})))
    assert out["ok"], out
    consts = pulab.report({**inp, "profiles": {}})["profiles"][vendor]["constants"]
    ints = {k.rsplit(".", 1)[1]: e for k, e in out["proof"]["integers"].items()
            if ".constants." in k}
    assert ints and not [k for k in ints if consts[k].get("real")]
    for k, e in ints.items():
        assert e["range"] == [consts[k]["value"]] * 2, k
