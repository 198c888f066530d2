"""Oracle for the course's exercises: every expected answer, recomputed without pulab.

For each trainee motor below (the inputs pulab's ``trainee_input(n)`` hands out; the test pins
them, so a link a trainer already gave out keeps its motor) the answers come from the
independent report oracle (``oracle.py``: bases, per unit, the Inovance integers, PI and PLL
gains, the constants' exact expressions), python-control for the naive PLL's closed-loop
poles (``loop_oracle.py``), and plain integer arithmetic with the C2000's 16-bit ``int`` for the
buggy routine and the int16 wrap.  Never imports pulab.
"""

from __future__ import annotations

import math
import pathlib
import sys

import control

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from oracle import oracle_report, parse  # noqa: E402
from loop_oracle import measure, pi  # noqa: E402

#: Trainee number → the input of the motor a trainee link carries.
TRAINEES = {
    0: {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 0.0001}},
    1: {"motor": {"rated_voltage_v": 48, "rated_current_a": 10, "rated_freq_hz": 200, "rs_ohm": 0.44, "ld_h": 0.00175, "lq_h": 0.00198, "bemf_v": 37.7, "pole_pairs": 4}, "drive": {"udc_v": 60, "ts_s": 5e-05, "base_freq_hz": 300.0}, "pll": {"bandwidth_hz": 50}},
    2: {"motor": {"rated_voltage_v": 220, "rated_current_a": 4.5, "rated_freq_hz": 100, "rs_ohm": 2.734, "ld_h": 0.06781, "lq_h": 0.08536, "bemf_v": 147.5, "pole_pairs": 4}, "drive": {"udc_v": 311, "ts_s": 0.000125, "base_freq_hz": 125.0}, "pll": {"bandwidth_hz": 20}},
    3: {"motor": {"rated_voltage_v": 380, "rated_current_a": 12, "rated_freq_hz": 50, "rs_ohm": 0.638, "ld_h": 0.04197, "lq_h": 0.05836, "bemf_v": 325.5, "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 6.25e-05, "base_freq_hz": 50}, "pll": {"bandwidth_hz": 10}},
    4: {"motor": {"rated_voltage_v": 36, "rated_current_a": 20, "rated_freq_hz": 300, "rs_ohm": 0.181, "ld_h": 0.00079, "lq_h": 0.0012, "bemf_v": 26.7, "pole_pairs": 5}, "drive": {"udc_v": 48, "ts_s": 0.0001, "base_freq_hz": 600}, "pll": {"bandwidth_hz": 5}},
    5: {"motor": {"rated_voltage_v": 380, "rated_current_a": 30, "rated_freq_hz": 150, "rs_ohm": 0.817, "ld_h": 0.005, "lq_h": 0.00525, "bemf_v": 238.3, "pole_pairs": 4}, "drive": {"udc_v": 540, "ts_s": 5e-05, "base_freq_hz": 187.5}, "pll": {"bandwidth_hz": 50}},
    9: {"motor": {"rated_voltage_v": 380, "rated_current_a": 12, "rated_freq_hz": 50, "rs_ohm": 1.183, "ld_h": 0.02896, "lq_h": 0.04552, "bemf_v": 291.9, "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 5e-05, "base_freq_hz": 50}, "pll": {"bandwidth_hz": 5}},
    14: {"motor": {"rated_voltage_v": 220, "rated_current_a": 4.5, "rated_freq_hz": 100, "rs_ohm": 4.417, "ld_h": 0.04772, "lq_h": 0.04862, "bemf_v": 175.2, "pole_pairs": 4}, "drive": {"udc_v": 311, "ts_s": 0.000125, "base_freq_hz": 150.0}, "pll": {"bandwidth_hz": 5}},
    23: {"motor": {"rated_voltage_v": 380, "rated_current_a": 30, "rated_freq_hz": 150, "rs_ohm": 1.471, "ld_h": 0.01148, "lq_h": 0.01826, "bemf_v": 252.1, "pole_pairs": 4}, "drive": {"udc_v": 540, "ts_s": 0.000125, "base_freq_hz": 300}, "pll": {"bandwidth_hz": 5}},
}


def _wrap16(v: int) -> int:
    """Two's complement of a 16-bit int."""
    v &= 0xFFFF
    return v - 0x10000 if v >= 0x8000 else v


def expected(inp: dict) -> dict:
    """Exercise id → expected answer for one motor."""
    P = parse(inp)
    r = oracle_report(inp)
    B, pu, V, C, L = r["base"], r["pu"], r["vendor"], r["current_pi"]["d"], r["pll"]
    raw_v = round(P["rated_voltage_v"])
    raw_i = round(P["rated_current_a"] * 100)
    raw_rs = round(P["rs_ohm"] * 1000)
    # the buggy Rpm: Uint16 m_UData * int 18597 is a 16-bit unsigned product on the C2000
    m_udata = raw_rs * raw_i // raw_v
    buggy = ((m_udata * 18597) & 0xFFFF) >> 14
    ld = pu["Ld"]
    fit = next((f"Q{q}" for q in (16, 15, 14, 13, 12) if round(ld * 2 ** q) <= 0xFFFF), "none")
    ts = P["ts_s"]
    g_naive = B["w_b"] / B["theta_b"]
    naive = measure(pi(L["kp"], L["ki"], ts) * control.tf([g_naive * ts], [1.0, -1.0], ts), ts)
    ts_half = dict(inp, drive=dict(inp["drive"], ts_s=ts / 2))
    ratio = oracle_report(ts_half)["current_pi"]["d"]["pm_ki"] / C["pm_ki"]
    return {
        "warmup-current": 2.0 / B["I_b"],
        "warmup-ub": P["rated_voltage_v"] / math.sqrt(3),
        "warmup-peak": math.sqrt(2) * P["rated_current_a"],
        "warmup-zb": B["Z_b"],
        "warmup-rs": P["rs_ohm"] / B["Z_b"],
        "warmup-lb": B["Z_b"] / (2 * math.pi * P["base_freq_hz"]) * 1e3,
        "q-current": round(2.0 / B["I_b"] * 4096),
        "q-data1": V["pm_maxout_vol"]["trace"][0]["value"],
        "q-maxout": V["pm_maxout_vol"]["value"],
        "q-wrap": _wrap16(round(8.5 * 4096)),
        "q-fit": fit,
        "vendor-mudata": m_udata,
        "vendor-rpm": V["Rpm"]["value"],
        "vendor-basel": V["LD"]["trace"][1]["value"],
        "vendor-ld": V["LD"]["value"],
        "vendor-bug": buggy,
        "vendor-flux": V["FluxRotor"]["value"],
        "const-18597": 2 ** 30 * math.sqrt(3) / 1e5,
        "const-3678": 2e4 / (math.sqrt(3) * math.pi),
        "const-2316": 2 ** 15 / (10 * math.sqrt(2)),
        "const-ld-error": (V["LD"]["value"] - pu["Ld"] * 2 ** 13) / (pu["Ld"] * 2 ** 13) * 100,
        "const-freqper": V["FreqPer"]["value"],
        "pi-kp-pu": C["kp_pu"],
        "pi-pm-kp": C["pm_kp"],
        "pi-pm-ki": C["pm_ki"],
        "pi-line-trap": round(C["kp"] * B["I_b"] / P["rated_voltage_v"] * 4096),
        "pi-ts-half": "halves" if abs(ratio - 0.5) < 0.05 else "doubles" if abs(ratio - 2) < 0.2 else "same",
        "pll-kp": L["kp"],
        "pll-kp-pu": L["kp_pu"],
        "pll-int-gain": L["integrator_gain"],
        "pll-naive-kts": g_naive * L["kp"] * ts,
        "pll-naive-locks": "yes" if naive["stable"] else "no",
    }
