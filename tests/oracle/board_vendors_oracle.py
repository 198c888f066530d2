"""Independent oracle for what each vendor's header holds for a board; writes
tests/golden/board-vendors/*.json.

    .venv/bin/python tests/oracle/board_vendors_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/board_vendors_oracle.py --check  # exit 1 if any is stale

Never imports pulab. Each macro is written here from the vendor's own file, with exact
Fractions where the C folds integers and the C's own double or float arithmetic where it
does not (a float literal ``f`` is what a compiler stores: the nearest float):

- TI universal lab user_mtr1.h: USER_M1_ADC_FULL_SCALE_CURRENT_A = V_ref/(R·G) (the whole ADC
  range), USER_M1_CURRENT_SF = that/2^bits, the same for the bus (V_ref·(R_top+R_bot)/R_bot),
  USER_M1_PWM_TBPRD_NUM = (uint16_t)(f_clk/f_pwm/2);
- ST parameters_conversion.h: MAX_CURRENT = ADC_REFERENCE_VOLTAGE/(2*RSHUNT*AMPLIFICATION_GAIN)
  (double; MCSDK 6 names it M1_MAX_READABLE_CURRENT), VBUS_PARTITIONING_FACTOR the divider,
  PWM_PERIOD_CYCLES = (uint16_t)((f_clk/f_pwm) & 0xFFFE) in integers, DEAD_TIME_COUNTS the
  #if chain of DTG ranges;
- NXP m1_pmsm_appconfig.h: M1_I_MAX the ± measurable current, M1_U_DCB_MAX the bus full
  scale, both float literals;
- Microchip hal_params.h: HAL_PARAM_PWM_PERIOD_COUNTS = f_clk/(2·f_pwm) (one half-period),
  HAL_PARAM_DEADTIME_COUNTS = t_dead·f_clk, both rounded to nearest.
"""

from __future__ import annotations

import copy
import struct
import sys
from fractions import Fraction as Fr
from pathlib import Path

from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "board-vendors"
REL, ABS = 0.0, 0.0     # every value is what a compiler stores: exact

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 0.0001}, "profiles": {}}


def f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


def _f(x) -> Fr:
    return Fr(str(x))


def _round(x: Fr) -> int:
    return int(x + Fr(1, 2)) if x >= 0 else -int(-x + Fr(1, 2))


def _dtg(mhz: int, ns: int) -> int:
    p = mhz * ns
    d1 = p // 1000
    if d1 <= 255:
        return d1
    if d1 <= 508:
        return p // 2 // 1000 + 128
    if d1 <= 1008:
        return p // 8 // 1000 + 320
    if d1 <= 2015:
        return p // 16 // 1000 + 384
    return 510


def expected(board: dict) -> dict:
    c, b, p = board.get("current"), board.get("bus"), board.get("pwm")
    ti, st, nxp, mchp = {}, {}, {}, {}
    if c is not None:
        ref, bits = c.get("adc_ref_v", 3.3), c.get("adc_bits", 12)
        rg = _f(c["shunt_ohm"]) * _f(c.get("gain", 1))
        full = _f(ref) / rg
        ti["USER_M1_ADC_FULL_SCALE_CURRENT_A"] = f32(float(full))
        ti["USER_M1_CURRENT_SF"] = f32(float(full / 2 ** bits))
        # the C's double arithmetic, in its order
        st["MAX_CURRENT"] = st["M1_MAX_READABLE_CURRENT"] = \
            ref / (2 * float(c["shunt_ohm"]) * float(c.get("gain", 1)))
        nxp["M1_I_MAX"] = f32(float(full / 2))
    if b is not None:
        ref, bits = b.get("adc_ref_v", 3.3), b.get("adc_bits", 12)
        ratio = _f(b["ratio"]) if "ratio" in b else \
            _f(b["r_bottom_ohm"]) / (_f(b["r_top_ohm"]) + _f(b["r_bottom_ohm"]))
        top = _f(ref) / ratio
        ti["USER_M1_ADC_FULL_SCALE_VOLTAGE_V"] = f32(float(top))
        ti["USER_M1_VOLTAGE_SF"] = f32(float(top / 2 ** bits))
        st["VBUS_PARTITIONING_FACTOR"] = float(ratio) if "ratio" in b else \
            b["r_bottom_ohm"] / (b["r_top_ohm"] + b["r_bottom_ohm"])
        nxp["M1_U_DCB_MAX"] = f32(float(top))
    if p is not None and "clock_hz" in p:
        clk, f = _f(p["clock_hz"]), _f(p["freq_hz"])
        ti["USER_M1_PWM_TBPRD_NUM"] = int(clk / f / 2)
        st["PWM_PERIOD_CYCLES"] = (int(clk / f) & 0xFFFE) & 0xFFFF
        mchp["HAL_PARAM_PWM_PERIOD_COUNTS"] = _round(clk / (2 * f))
        if "deadtime_s" in p:
            td = _f(p["deadtime_s"])
            st["DEAD_TIME_COUNTS"] = _dtg(int(clk / 10 ** 6), int(td * 10 ** 9))
            mchp["HAL_PARAM_DEADTIME_COUNTS"] = _round(td * clk)
    return {"ti": ti, "st": st, "nxp": nxp, "microchip": mchp, "inovance": {}}


CASES = [
    # TI BOOSTXL-DRV8323RS on a F28004x LaunchPad (user_mtr1.h prints 47.14285714, 57.52845691)
    ("01_ti_boostxl_drv8323rs", {"current": {"shunt_ohm": 0.007, "gain": 10},
                                 "bus": {"r_top_ohm": 82000, "r_bottom_ohm": 4990},
                                 "pwm": {"clock_hz": 100e6, "freq_hz": 10000, "deadtime_s": 2e-7}}),
    # ST B-G431B-ESC1 (power_stage_parameters.h), 170 MHz timer, 800 ns dead time
    ("02_st_g431_esc", {"current": {"shunt_ohm": 0.003, "gain": 9.14},
                        "bus": {"ratio": 0.09625565501973242},
                        "pwm": {"clock_hz": 170e6, "freq_hz": 20000, "mode": "up",
                                "deadtime_s": 8e-7}}),
    # Microchip dsPIC33CK LVMC timer (hal_params.h: 5000 and 200), TI BOOSTXL-DRV8301 sensing
    ("03_mchp_lvmc_timer", {"current": {"shunt_ohm": 0.01, "gain": 10},
                            "bus": {"r_top_ohm": 34800, "r_bottom_ohm": 4990},
                            "pwm": {"clock_hz": 200e6, "freq_hz": 20000, "deadtime_s": 1e-6}}),
    # ST's coarser dead-time ranges and a 14-bit ADC at 3.0 V
    ("04_dtg_ranges", {"current": {"shunt_ohm": 0.005, "gain": 20, "adc_bits": 14, "adc_ref_v": 3.0},
                       "pwm": {"clock_hz": 170e6, "freq_hz": 16000, "deadtime_s": 2.5e-6}}),
]


def build() -> dict:
    out = {}
    for name, board in CASES:
        inp = copy.deepcopy(SEED)
        inp["board"] = board
        out[f"{name}.json"] = {"input": inp, "expected": expected(board)}
    return out


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
