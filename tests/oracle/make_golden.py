"""Write tests/golden/NN_name.json and errors.json from the independent oracle.

    .venv/bin/python tests/oracle/make_golden.py          # (re)write the files
    .venv/bin/python tests/oracle/make_golden.py --check  # exit 1 if any file is stale

Each case file is {"input": ..., "expected": oracle_report(input)}.
"""

from __future__ import annotations

import copy
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import OracleInputError, oracle_report  # noqa: E402

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden"
# Closed-form float64 arithmetic: the same operations give the same bits on every IEEE machine
# that this project runs on, but numpy may vectorise sums differently across versions.
REL, ABS = 1e-12, 1e-15

# The seed's worked motor (seed 1.4-1 … 1.4-7: Rs 1.5 Ω, Un 17 V, In 1.5 A, fn 220 Hz,
# Ld = Lq = 600 µH). bemf 12 V line RMS, 4 pole pairs, Udc 24 V, Ts 100 µs are our choices.
SEED = {
    "motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
              "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12.0,
              "pole_pairs": 4},
    "drive": {"udc_v": 24, "ts_s": 0.0001},
}

# 7.5 kW, 380 V 50 Hz interior PMSM (induction-motor frame size), 1500 rpm, Udc 540 V.
IND380 = {
    "motor": {"rated_voltage_v": 380, "rated_current_a": 14.5, "rated_freq_hz": 50,
              "rs_ohm": 0.42, "ld_h": 0.0085, "lq_h": 0.0135, "bemf_v": 335.0,
              "pole_pairs": 2},
    "drive": {"udc_v": 540, "ts_s": 0.000125},
}

# 400 W, 220 V servo, 4 pole pairs, 3000 rpm rated (200 Hz), 5000 rpm max (base 333.33 Hz).
SERVO = {
    "motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
              "rs_ohm": 2.3, "ld_h": 0.0046, "lq_h": 0.0052, "bemf_v": 104.0,
              "pole_pairs": 4},
    "drive": {"base_freq_hz": 333.33, "udc_v": 310, "ts_s": 0.0000625},
}

# 48 V bus traction motor: 32 V line rated, 120 A, Rs 8 mΩ, tens of µH.
# ld_h 45 µH is 4.5 raw units of 10 µH: an exact binary tie, rounded away from zero to 5.
LV48 = {
    "motor": {"rated_voltage_v": 32, "rated_current_a": 120, "rated_freq_hz": 100,
              "rs_ohm": 0.008, "ld_h": 0.000045, "lq_h": 0.00006, "bemf_v": 27.5,
              "pole_pairs": 5},
    "drive": {"udc_v": 48, "ts_s": 0.00005},
}

# 690 V, 110 kW-class PMSM, Udc 1000 V, drive max 75 Hz.
V690 = {
    "motor": {"rated_voltage_v": 690, "rated_current_a": 112, "rated_freq_hz": 50,
              "rs_ohm": 0.021, "ld_h": 0.0021, "lq_h": 0.0034, "bemf_v": 610.0,
              "pole_pairs": 3},
    "drive": {"base_freq_hz": 75, "udc_v": 1000, "ts_s": 0.00025},
}


def with_(base: dict, **sections) -> dict:
    d = copy.deepcopy(base)
    for k, v in sections.items():
        d.setdefault(k, {}).update(v)
    return d


CASES = [
    ("01_seed_motor", SEED),
    # Seed 1.4-6 … 1.4-15: LD in µH gives 10× the Q13 value (flag unit_uH).
    ("02_seed_uH_puzzle", with_(SEED, conventions={"inductance_unit": "uH"})),
    # Seed 1.4-1/1.4-2 worked numbers through `raw` overrides (SI Rs deliberately different):
    # RsPm 1500, Current 150, Voltage 17 → m_UData 13235, Rpm 15022 vs ideal 15023.6.
    ("03_seed_raw_worked", with_(SEED, motor={"rs_ohm": 2.0},
                                 raw={"RsPm": 1500, "Current": 150, "Voltage": 17})),
    ("04_ind380_7k5", IND380),
    ("05_servo220_400w", SERVO),
    ("06_lv48_tiny_rs", LV48),
    ("07_mv690", V690),
    ("08_seed_peak", with_(SEED, conventions={"base": "peak"})),
    # TI-style full-scale bases: U_b = Udc/√3, I_b = ADC full scale.
    ("09_servo_custom", with_(SERVO, conventions={"base": "custom", "base_voltage_v": 178.98,
                                                  "base_current_a": 10.0})),
    ("10_servo_theta_2pi", with_(SERVO, conventions={"angle_base": "2pi"},
                                 pll={"bandwidth_hz": 30, "damping": 1.0})),
    ("11_ind380_damping", with_(IND380, current_loop={"method": "damping",
                                                      "bandwidth_hz": 300, "damping": 0.8})),
    ("12_servo_manual", with_(SERVO, current_loop={"method": "manual", "kp": 15.0,
                                                   "ki": 7500.0})),
    # 6.6 kV motor: Voltage*10 = 66000 wraps 16-bit int to 464, then m_Ulong<<15 wraps 32
    # bits. A 0.1 V Uint16 cannot hold the MV bus, so uDCFilter is given raw.
    ("13_wrap_6600v", {"motor": {"rated_voltage_v": 6600, "rated_current_a": 52,
                                 "rated_freq_hz": 50, "rs_ohm": 0.35, "ld_h": 0.045,
                                 "lq_h": 0.06, "bemf_v": 6000.0, "pole_pairs": 2},
                       "drive": {"udc_v": 6500, "ts_s": 0.0005},
                       "raw": {"uDCFilter": 65000}}),
    # Voltage 1 (raw): Rpm multiply wraps 2^32 and its Uint16 store changes the value,
    # m_Ulong<<15 wraps, pm_maxout_vol<<12 wraps int32 (maxu negative).
    ("14_wrap_tiny_voltage_raw", with_(SEED, raw={"Voltage": 1, "RsPm": 2000,
                                                  "BemfVolt": 400, "uDCFilter": 3100})),
    # LQ in µH far above what Q13 can hold: m_Ulong/10 > 65535, the Uint16 store wraps.
    ("15_store_lq_uH", with_(SEED, conventions={"inductance_unit": "uH"},
                             raw={"LQ": 7500})),
    # Exact binary ties: 2.125 A → 212.5 → 213, 12.25 V → 122.5 → 123, 310.25 V → 3103
    # (ties away from zero; banker's rounding would give 212, 122, 3102).
    ("16_ties_away", with_(SEED, motor={"rated_current_a": 2.125, "bemf_v": 12.25},
                           drive={"udc_v": 310.25})),
    # f_b below rated (FreqPer > 1 in Q15) and FreqRated01 = 2·FullFreq01 − 1: near the edge.
    ("17_base_below_rated", with_(IND380, drive={"base_freq_hz": 40},
                                  raw={"FreqRated01": 7999})),
    # All raw overrides at once, 380 V motor, custom PLL.
    ("18_ind380_all_raw", with_(IND380, pll={"bandwidth_hz": 20, "damping": 0.9},
                                raw={"Voltage": 380, "Current": 1450, "FullFreq01": 5000,
                                     "FreqRated01": 5000, "RsPm": 420, "LD": 850,
                                     "LQ": 1350, "BemfVolt": 3350, "uDCFilter": 5400})),
    # Beyond the Inovance firmware, physics intact (firmware.inovance lists what it cannot
    # hold or compute; the other results are computed):
    # 7000 V bus → uDCFilter 70000 > Uint16: no pm_maxout_vol/maxu.
    ("19_limit_udc_7000v", with_(SEED, drive={"udc_v": 7000})),
    # FreqPer = (1<<15)/40000 = 0, then FluxRotor divides by it.
    ("20_limit_freqper_zero", with_(SEED, drive={"base_freq_hz": 400}, raw={"FreqRated01": 1})),
    # Voltage*10 = 327680 ≡ 0 (mod 65536): the 16-bit product is zero, FluxRotor divides by it.
    ("21_limit_voltage_32768", with_(SEED, raw={"Voltage": 32768})),
    # Voltage 0: Rpm, the inductances, FluxRotor and the voltage limits all divide by zero.
    ("22_limit_voltage_0", with_(SEED, raw={"Voltage": 0})),
    # A 24 V, 7-pole-pair, 28,000 rpm robot motor: 3266.67 Hz needs FullFreq01 and
    # FreqRated01 = 326667 (0.01 Hz units) > 65535.
    ("23_limit_robot_28krpm", {"motor": {"rated_voltage_v": 24, "rated_current_a": 10,
                                         "rated_freq_hz": 3266.67, "rs_ohm": 0.05,
                                         "ld_h": 2e-5, "lq_h": 2e-5, "bemf_v": 16,
                                         "pole_pairs": 7},
                               "drive": {"udc_v": 24, "ts_s": 2.5e-5}}),
]


def _drop(d: dict, section: str, key: str) -> dict:
    d = copy.deepcopy(d)
    del d[section][key]
    return d


ERRORS = [
    (_drop(SEED, "motor", "rs_ohm"), "motor.rs_ohm"),
    (with_(SEED, motor={"rated_voltage_v": None}), "motor.rated_voltage_v"),
    (with_(SEED, motor={"rated_current_a": "1.5"}), "motor.rated_current_a"),
    (with_(SEED, motor={"ld_h": True}), "motor.ld_h"),
    (with_(SEED, motor={"rs_ohm": -1.5}), "motor.rs_ohm"),
    (with_(SEED, drive={"ts_s": 0}), "drive.ts_s"),
    (with_(SEED, motor={"pole_pairs": 0}), "motor.pole_pairs"),
    (with_(SEED, raw={"LD": 70000}), "raw.LD"),
    (with_(SEED, raw={"Current": -1}), "raw.Current"),
    (with_(SEED, motor={"colour": "red"}), "motor.colour"),
    (with_(SEED, raw={"Rs": 1500}), "raw.Rs"),
    (with_(SEED, conventions={"base": "custom", "base_current_a": 10.0}),
     "conventions.base_voltage_v"),
    (with_(SEED, conventions={"base": "rmss"}), "conventions.base"),
    (with_(SEED, current_loop={"method": "manual", "ki": 100.0}), "current_loop.kp"),
    # damping: kp = 2ζω0·L − Rs ≤ 0 for a 10 Hz loop on this motor
    (with_(SEED, current_loop={"method": "damping", "bandwidth_hz": 10}),
     "current_loop.bandwidth_hz"),
    (with_(SEED, current_loop={"method": "manual", "kp": 1e9, "ki": 100.0}), "current_loop"),
]


def build() -> dict:
    files = {}
    names = set()
    for name, inp in CASES:
        assert name not in names, name
        names.add(name)
        files[f"{name}.json"] = {"input": inp, "expected": oracle_report(inp)}
    errs = []
    for inp, field in ERRORS:
        try:
            oracle_report(inp)
        except OracleInputError as e:
            assert e.field == field, (field, e.field, e.message)
        else:
            raise AssertionError(f"oracle accepted a bad input meant for {field}")
        errs.append({"input": inp, "field": field})
    files["errors.json"] = errs
    return files


def main(argv: list[str]) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
