"""Independent oracle for the report's "board" section; writes tests/golden/board/*.json.

    .venv/bin/python tests/oracle/board_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/board_oracle.py --check  # exit 1 if any file is stale

Never imports pulab. Written from the contract (docs/contract.md, "Output: board") and the
vendors' own definitions, with Fractions wherever the inputs are decimal, so that a formula
slip in pulab (a factor 2 of bipolar sensing, the up-down period register, the per-unit base)
shows as a difference:

- current: full ADC range V_ref/(R·G) (TI USER_M1_ADC_FULL_SCALE_CURRENT_A), ± largest
  V_ref/(2·R·G) bipolar (ST MAX_CURRENT) or V_ref/(R·G) unipolar, one count = full range/2^n;
- bus: V_ref·(R_top + R_bottom)/R_bottom;
- PWM: f_clk/f_pwm ticks; up-down register trunc(f_clk/(2·f_pwm)), up trunc(f_clk/f_pwm) − 1.
The per-unit current base is the report's I_b: RMS rated current (conventions.base "rms") or
√2 times it ("peak"); ψ peak = √(2/3)·E_LL/(2π·f_n).
"""

from __future__ import annotations

import copy
import math
import sys
from fractions import Fraction as Fr
from pathlib import Path

from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "board"
REL, ABS = 1e-12, 0.0

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 0.0001}}
SERVO = {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
                   "rs_ohm": 2.3, "ld_h": 0.0046, "lq_h": 0.0052, "bemf_v": 104.0,
                   "pole_pairs": 4},
         "drive": {"udc_v": 310, "ts_s": 0.0000625}, "conventions": {"base": "peak"}}


def _f(x) -> Fr:
    return Fr(str(x))


def current(c: dict, motor: dict, base: str) -> dict | None:
    ref, bits = _f(c.get("adc_ref_v", 3.3)), c.get("adc_bits", 12)
    bipolar = c.get("bipolar", True)
    if "max_a" in c:
        full = _f(c["max_a"]) * (2 if bipolar else 1)
        s, src = None, "max_a"
    else:
        s = _f(c["sensitivity_v_per_a"]) if "sensitivity_v_per_a" in c else \
            _f(c["shunt_ohm"]) * _f(c.get("gain", 1))
        full, src = ref / s, "chain"
    lsb = full / 2 ** bits
    i_b = float(_f(motor["rated_current_a"])) * (math.sqrt(2.0) if base == "peak" else 1.0)
    psi = math.sqrt(2.0 / 3.0) * motor["bemf_v"] / (2.0 * math.pi * motor["rated_freq_hz"])
    return {"max_a": float(full / 2 if bipolar else full), "full_range_a": float(full),
            "sensitivity_v_per_a": None if s is None else float(s), "a_per_count": float(lsb),
            "counts_per_a": float(1 / lsb), "nm_per_count": 1.5 * motor["pole_pairs"] * psi * float(lsb),
            "pu_per_count": float(lsb) / i_b, "from": src}


def bus(b: dict) -> dict:
    ref, bits = _f(b.get("adc_ref_v", 3.3)), b.get("adc_bits", 12)
    if "max_v" in b:
        ratio, top = None, _f(b["max_v"])
    else:
        ratio = _f(b["ratio"]) if "ratio" in b else \
            _f(b["r_bottom_ohm"]) / (_f(b["r_top_ohm"]) + _f(b["r_bottom_ohm"]))
        top = ref / ratio
    return {"max_v": float(top), "v_per_count": float(top / 2 ** bits),
            "ratio": None if ratio is None else float(ratio), "from": "max_v" if ratio is None else "chain"}


def pwm(p: dict, udc) -> dict:
    f = _f(p["freq_hz"])
    out = {"control_period_s": float(p.get("periods_per_control", 1) / f), "period_counts": None,
           "period_register": None, "freq_actual_hz": None, "duty_bits": None,
           "deadtime_counts": None,
           "deadtime_error_v": float(_f(udc) * _f(p["deadtime_s"]) * f) if "deadtime_s" in p else None}
    if "clock_hz" in p:
        clk = _f(p["clock_hz"])
        ticks = clk / f
        if p.get("mode", "updown") == "updown":
            reg = math.floor(ticks / 2)
            actual, steps = clk / (2 * reg), reg
        else:
            reg = math.floor(ticks) - 1
            actual, steps = clk / (reg + 1), reg + 1
        out.update(period_counts=float(ticks), period_register=reg, freq_actual_hz=float(actual),
                   duty_bits=math.log2(steps),
                   deadtime_counts=float(_f(p["deadtime_s"]) * clk) if "deadtime_s" in p else None)
    return out


def expected(inp: dict) -> dict:
    b, m = inp["board"], inp["motor"]
    base = inp.get("conventions", {}).get("base", "rms")
    return {"current": current(b["current"], m, base) if "current" in b else None,
            "bus": bus(b["bus"]) if "bus" in b else None,
            "pwm": pwm(b["pwm"], inp["drive"]["udc_v"]) if "pwm" in b else None}


def with_board(motor: dict, board: dict) -> dict:
    d = copy.deepcopy(motor)
    d["board"] = board
    return d


CASES = [
    # TI BOOSTXL-DRV8323RS on a F28004x LaunchPad (user_mtr1.h: 47.14285714 A, 57.52845691 V)
    ("01_ti_boostxl_drv8323rs", with_board(SEED, {
        "current": {"shunt_ohm": 0.007, "gain": 10},
        "bus": {"r_top_ohm": 82000, "r_bottom_ohm": 4990},
        "pwm": {"clock_hz": 100e6, "freq_hz": 10000, "deadtime_s": 2e-7}})),
    # ST B-G431B-ESC1 (power_stage_parameters.h: 3 mΩ, ×9.14, VBUS_PARTITIONING_FACTOR), 170 MHz up
    ("02_st_g431_esc", with_board(SEED, {
        "current": {"shunt_ohm": 0.003, "gain": 9.14},
        "bus": {"ratio": 0.09625565501973242},
        "pwm": {"clock_hz": 170e6, "freq_hz": 20000, "mode": "up", "deadtime_s": 8e-7}})),
    # a DRV8316-style sensor in V/A, a unipolar 14-bit ADC, a typed bus full scale, peak bases
    ("03_sensor_unipolar_peak", with_board(SERVO, {
        "current": {"sensitivity_v_per_a": 0.15, "bipolar": False, "adc_bits": 14, "adc_ref_v": 3.0},
        "bus": {"max_v": 44.28, "adc_bits": 16},
        "pwm": {"clock_hz": 150e6, "freq_hz": 16000, "periods_per_control": 1}})),
    # the largest current typed, a PWM frequency only (no clock: no counts)
    ("04_typed_max_no_clock", with_board(SEED, {
        "current": {"max_a": 16.5, "adc_bits": 12},
        "pwm": {"freq_hz": 20000, "periods_per_control": 2, "deadtime_s": 1e-6}})),
]


def build() -> dict:
    return {f"{name}.json": {"input": inp, "expected": expected(inp)} for name, inp in CASES}


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
