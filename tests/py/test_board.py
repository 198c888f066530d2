"""The board input: the current, bus and PWM chains against the numbers vendors' public files
print, and the review's findings on them.

Sources (read, numbers reproduced here):
- TI MotorControl SDK universal lab, anyway-blows/ti-c2000-motor-control-sdk :
  solutions/universal_motorcontrol_lab/common/include/user_mtr1.h — BOOSTXL-DRV8323RS
  ``USER_M1_ADC_FULL_SCALE_CURRENT_A (47.14285714f) // gain=10`` (7 mΩ shunts) and
  ``USER_M1_ADC_FULL_SCALE_VOLTAGE_V (57.52845691f)``; DRV8316 ``3.3V / 0.15V/A = 22.0A``;
  BOOSTXL-3PHGANINV ``(33.0f) // gain=20`` (5 mΩ); ``USER_M1_PWM_TBPRD_NUM`` =
  (uint16_t)(SYSTEM_FREQ_MHz·1000/PWM_FREQ_kHz/2).
- ST MCSDK, dronectl/g431-mcsdk : Inc/power_stage_parameters.h (RSHUNT 0.003,
  AMPLIFICATION_GAIN 9.14, VBUS_PARTITIONING_FACTOR 0.09625565501973242) and
  Inc/parameters_conversion.h (MAX_CURRENT, CURRENT_CONV_FACTOR, PWM_PERIOD_CYCLES), evaluated
  by gcc as the firmware's compiler would.
The BOOSTXL-DRV8323RS divider (82 kΩ over 4.99 kΩ) is the reconstruction that reproduces TI's
57.52845691 V to ten digits; TI's header prints only the result.
"""
import copy
import json
import pathlib
import subprocess
import sys

import pytest

import pulab
from conftest import SEED_INPUT
from ctrace_compilers import available
from pulab import InputError

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "oracle"))
from golden_files import differences  # noqa: E402 - the oracles' own tolerance rule


def _report(board, **sections):
    inp = copy.deepcopy(SEED_INPUT)
    inp["board"] = board
    for k, v in sections.items():
        inp.setdefault(k, {}).update(v)
    return pulab.report(inp)


def test_ti_boostxl_drv8323rs_full_scales():
    r = _report({"current": {"shunt_ohm": 0.007, "gain": 10},
                 "bus": {"r_top_ohm": 82e3, "r_bottom_ohm": 4.99e3}})["board"]
    # TI prints the full ADC range (both signs); the ± measurable current is half of it
    assert r["current"]["full_range_a"] == pytest.approx(47.14285714, rel=1e-9)
    assert r["current"]["max_a"] == pytest.approx(47.14285714 / 2, rel=1e-9)
    # USER_M1_CURRENT_SF = full scale / 4096
    assert r["current"]["a_per_count"] == pytest.approx(47.14285714 / 4096, rel=1e-9)
    assert r["bus"]["max_v"] == pytest.approx(57.52845691, rel=1e-9)
    assert r["bus"]["v_per_count"] == pytest.approx(57.52845691 / 4096, rel=1e-9)


@pytest.mark.parametrize("current, full", [
    ({"sensitivity_v_per_a": 0.15}, 22.0),           # DRV8316: 3.3 V / 0.15 V/A
    ({"shunt_ohm": 0.005, "gain": 20}, 33.0),        # BOOSTXL-3PHGANINV
])
def test_ti_full_scales_of_other_boosterpacks(current, full):
    assert _report({"current": current})["board"]["current"]["full_range_a"] == \
        pytest.approx(full, rel=1e-12)


def test_ti_period_register_as_the_header_casts_it():
    # 100 MHz system clock (f28004x), 10 kHz, up-down: (uint16_t)(100·1000/10/2) = 5000
    p = _report({"pwm": {"clock_hz": 100e6, "freq_hz": 10e3}})["board"]["pwm"]
    assert (p["period_counts"], p["period_register"], p["freq_actual_hz"]) == (1e4, 5000, 1e4)
    # 15 kHz does not divide: the cast truncates 3333.33 to 3333, the timer runs at 15001.5 Hz
    p = _report({"pwm": {"clock_hz": 100e6, "freq_hz": 15e3}})["board"]["pwm"]
    assert p["period_register"] == 3333 and p["freq_actual_hz"] == pytest.approx(1e8 / 6666)


def test_st_g431_macros_evaluated_by_gcc(tmp_path):
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    src = tmp_path / "st.c"
    src.write_text("""#include <stdio.h>
#include <stdint.h>
#define ADC_REFERENCE_VOLTAGE 3.3
#define RSHUNT 0.003
#define AMPLIFICATION_GAIN 9.14
#define VBUS_PARTITIONING_FACTOR 0.09625565501973242
#define ADV_TIM_CLK_MHz 170
#define PWM_FREQUENCY 20000
#define MAX_CURRENT (ADC_REFERENCE_VOLTAGE/(2*RSHUNT*AMPLIFICATION_GAIN))
#define CURRENT_CONV_FACTOR_EXACT ((65536.0 * RSHUNT * AMPLIFICATION_GAIN)/ADC_REFERENCE_VOLTAGE)
#define PWM_PERIOD_CYCLES (uint16_t)((ADV_TIM_CLK_MHz*(uint32_t)1000000u/((uint32_t)(PWM_FREQUENCY)))& ( uint16_t )0xFFFE)
int main(void) {
    printf("%.17g %.17g %.17g %u\\n", MAX_CURRENT, CURRENT_CONV_FACTOR_EXACT,
           ADC_REFERENCE_VOLTAGE / VBUS_PARTITIONING_FACTOR, (unsigned)PWM_PERIOD_CYCLES);
    return 0;
}
""")
    exe = tmp_path / "st"
    subprocess.run(["gcc", str(src), "-o", str(exe)], check=True)
    max_current, conv, vbus, cycles = subprocess.run([str(exe)], check=True, capture_output=True,
                                                     text=True).stdout.split()
    r = _report({"current": {"shunt_ohm": 0.003, "gain": 9.14},
                 "bus": {"ratio": 0.09625565501973242},
                 "pwm": {"clock_hz": 170e6, "freq_hz": 20e3, "mode": "up"}})["board"]
    assert r["current"]["max_a"] == pytest.approx(float(max_current), rel=1e-15)
    # ST's CURRENT_CONV_FACTOR is counts per ampere of the left-aligned 16-bit reading
    st16 = _report({"current": {"shunt_ohm": 0.003, "gain": 9.14, "adc_bits": 16}})["board"]
    assert st16["current"]["counts_per_a"] == pytest.approx(float(conv), rel=1e-15)
    assert r["bus"]["max_v"] == pytest.approx(float(vbus), rel=1e-15)
    assert r["pwm"]["period_counts"] == int(cycles) == 8500


def test_hoverboard_counts_per_ampere():
    # 3.5 mΩ × 11 on a 12-bit 3.3 V ADC: 47.8 counts per ampere (hoverboard firmware thread)
    c = _report({"current": {"shunt_ohm": 0.0035, "gain": 11}})["board"]["current"]
    assert round(c["counts_per_a"], 1) == 47.8


def test_unipolar_and_typed_max_current():
    uni = _report({"current": {"shunt_ohm": 0.01, "gain": 20, "bipolar": False}})["board"]["current"]
    assert uni["max_a"] == pytest.approx(3.3 / 0.2) and uni["a_per_count"] == pytest.approx(16.5 / 4096)
    typed = _report({"current": {"max_a": 16.5, "bipolar": False}})["board"]["current"]
    assert typed["a_per_count"] == pytest.approx(uni["a_per_count"], rel=1e-15)
    assert typed["sensitivity_v_per_a"] is None and typed["from"] == "max_a"


def test_torque_and_per_unit_of_one_count():
    r = _report({"current": {"shunt_ohm": 0.007, "gain": 10}})
    c, m = r["board"]["current"], r["input"]["motor"]
    psi_peak = m["bemf_v"] * (2 / 3) ** 0.5 / (2 * 3.141592653589793 * m["rated_freq_hz"])
    assert c["nm_per_count"] == pytest.approx(1.5 * m["pole_pairs"] * psi_peak * c["a_per_count"],
                                              rel=1e-14)
    assert c["pu_per_count"] == pytest.approx(c["a_per_count"] / r["base"]["I_b"], rel=1e-15)


def test_dead_time_counts_and_voltage():
    p = _report({"pwm": {"clock_hz": 170e6, "freq_hz": 20e3, "deadtime_s": 800e-9}})["board"]["pwm"]
    assert p["deadtime_counts"] == pytest.approx(136.0)
    assert p["deadtime_error_v"] == pytest.approx(24 * 800e-9 * 20e3)


@pytest.mark.parametrize("board, field", [
    ({"current": {"max_a": 10, "shunt_ohm": 0.01}}, "board.current.max_a"),
    ({"current": {"sensitivity_v_per_a": 0.1, "gain": 5}}, "board.current.sensitivity_v_per_a"),
    ({"current": {"gain": 5}}, "board.current.shunt_ohm"),
    ({"bus": {"r_top_ohm": 1e5}}, "board.bus.r_bottom_ohm"),
    ({"bus": {"max_v": 50, "ratio": 0.1}}, "board.bus.max_v"),
    ({"pwm": {"clock_hz": 1e8}}, "board.pwm.freq_hz"),
    ({"pwm": {"clock_hz": 1e3, "freq_hz": 1e3}}, "board.pwm.freq_hz"),
    ({"current": {"shunt_ohm": -1}}, "board.current.shunt_ohm"),
    ({"pwm": {"mode": "down"}}, "board.pwm.mode"),
    ({"bus": {"ratio": 2}}, "board.bus.ratio"),
    ({"current": {"adc_bits": 0}}, "board.current.adc_bits"),
    ({"current": {"bipolar": "yes"}}, "board.current.bipolar"),
    ({"cpu": {}}, "board.cpu"),
    ([], "board"),
])
def test_bad_boards_name_the_field(board, field):
    with pytest.raises(InputError) as e:
        _report(board)
    assert e.value.field == field
    assert e.value.message and e.value.message_zh != e.value.message


def _codes(r):
    return {x["code"]: x for x in r["review"]["findings"]}


def test_findings_a_user_can_act_on():
    # 1.5 A rated (2.12 A peak) on a ±23.6 A chain: 9 % of the range, a gain that fits
    f = _codes(_report({"current": {"shunt_ohm": 0.007, "gain": 10}}))["board_adc_low"]
    assert f["field"] == "board.current.gain" and f["severity"] == "warning"
    assert "10 → 88.89 V/V" in f["message"] and "V/V" in f["message_zh"]
    # the rated peak beyond the ADC: it clips
    f = _codes(_report({"current": {"max_a": 2.0}}))["board_adc_clip"]
    assert (f["severity"], f["field"]) == ("error", "board.current.max_a")
    # a 6-bit duty, a dead time that eats the low-speed voltage, a PWM that is not Ts
    codes = _codes(_report({"pwm": {"clock_hz": 1.28e6, "freq_hz": 1e4, "deadtime_s": 5e-6,
                                    "periods_per_control": 2}}))
    assert {"board_duty_bits", "board_deadtime", "board_ts"} <= set(codes)
    assert codes["board_ts"]["field"] == "board.pwm.periods_per_control"
    # none of them on a board that fits
    fine = _report({"current": {"max_a": 3.0}, "pwm": {"clock_hz": 1e8, "freq_hz": 1e4,
                                                       "deadtime_s": 1e-7}})
    assert not [c for c in _codes(fine) if c.startswith("board")]
    assert fine["review"]["thresholds"]["board"]["adc_use"] == {"warning": 0.25, "error": 1.0}


def test_no_board_changes_nothing():
    r = pulab.report(copy.deepcopy(SEED_INPUT))
    assert "board" not in r and "board" not in r["input"] and "board" not in r["review"]["thresholds"]


# Golden vectors of the independent oracle (tests/oracle/board_oracle.py, Fractions, never
# imports pulab); the same files go through Pyodide in tests/web/golden-board.test.ts.
GOLDEN = sorted((pathlib.Path(__file__).resolve().parents[1] / "golden" / "board").glob("*.json"))


def test_board_golden_files_are_fresh():
    assert len(GOLDEN) >= 4
    r = subprocess.run([sys.executable, "board_oracle.py", "--check"], capture_output=True,
                       text=True, cwd=pathlib.Path(__file__).resolve().parents[1] / "oracle")
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_board_golden(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    got = pulab.report(case["input"])["board"]
    assert differences(case["expected"], got, 1e-12, 0.0) == []
