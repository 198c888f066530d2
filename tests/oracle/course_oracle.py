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
from loop_oracle import current_loop, measure, pi  # noqa: E402
from acim_oracle import ST_MEZ, expected as acim_expected  # noqa: E402
from acim_sim_oracle import section as acim_sim_section  # noqa: E402

#: Trainee number → the input of the motor a trainee link carries.
TRAINEES = {
    0: {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 0.0001}},
    1: {"motor": {"rated_voltage_v": 36, "rated_current_a": 10, "rated_freq_hz": 200, "rs_ohm": 0.33, "ld_h": 0.00037, "lq_h": 0.00041, "bemf_v": 25.4, "pole_pairs": 4}, "drive": {"udc_v": 60, "ts_s": 5e-05, "base_freq_hz": 300.0}, "pll": {"bandwidth_hz": 50}},
    2: {"motor": {"rated_voltage_v": 200, "rated_current_a": 4.5, "rated_freq_hz": 100, "rs_ohm": 2.485, "ld_h": 0.01494, "lq_h": 0.01816, "bemf_v": 121.8, "pole_pairs": 4}, "drive": {"udc_v": 311, "ts_s": 0.000125, "base_freq_hz": 125.0}, "pll": {"bandwidth_hz": 20}},
    3: {"motor": {"rated_voltage_v": 340, "rated_current_a": 12, "rated_freq_hz": 50, "rs_ohm": 0.571, "ld_h": 0.01084, "lq_h": 0.01437, "bemf_v": 259.7, "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 6.25e-05, "base_freq_hz": 50}, "pll": {"bandwidth_hz": 10}},
    4: {"motor": {"rated_voltage_v": 24, "rated_current_a": 20, "rated_freq_hz": 300, "rs_ohm": 0.12, "ld_h": 0.00013, "lq_h": 0.00019, "bemf_v": 16.0, "pole_pairs": 5}, "drive": {"udc_v": 48, "ts_s": 0.0001, "base_freq_hz": 600}, "pll": {"bandwidth_hz": 5}},
    5: {"motor": {"rated_voltage_v": 340, "rated_current_a": 30, "rated_freq_hz": 150, "rs_ohm": 0.731, "ld_h": 0.00134, "lq_h": 0.0014, "bemf_v": 194.7, "pole_pairs": 4}, "drive": {"udc_v": 540, "ts_s": 5e-05, "base_freq_hz": 187.5}, "pll": {"bandwidth_hz": 50}},
    9: {"motor": {"rated_voltage_v": 340, "rated_current_a": 12, "rated_freq_hz": 50, "rs_ohm": 1.058, "ld_h": 0.00851, "lq_h": 0.01256, "bemf_v": 234.7, "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 5e-05, "base_freq_hz": 50}, "pll": {"bandwidth_hz": 5}},
    14: {"motor": {"rated_voltage_v": 200, "rated_current_a": 4.5, "rated_freq_hz": 100, "rs_ohm": 4.015, "ld_h": 0.01129, "lq_h": 0.01147, "bemf_v": 142.7, "pole_pairs": 4}, "drive": {"udc_v": 311, "ts_s": 0.000125, "base_freq_hz": 150.0}, "pll": {"bandwidth_hz": 5}},
    23: {"motor": {"rated_voltage_v": 340, "rated_current_a": 30, "rated_freq_hz": 150, "rs_ohm": 1.316, "ld_h": 0.0025, "lq_h": 0.00373, "bemf_v": 205.0, "pole_pairs": 4}, "drive": {"udc_v": 540, "ts_s": 0.000125, "base_freq_hz": 300}, "pll": {"bandwidth_hz": 5}},
}


def _wrap16(v: int) -> int:
    """Two's complement of a 16-bit int."""
    v &= 0xFFFF
    return v - 0x10000 if v >= 0x8000 else v


def fb_max(inp: dict, limit_v: float) -> float:
    """The largest base frequency (≥ f_n, ≤ 655.35 Hz, the firmware's 0.01 Hz Uint16) at which the
    motor at rated current (i_d = 0, L_q, RMS flux) needs no more line RMS voltage than the limit:
    the root of |R·jI − ωL_q·I + jωψ|·√3 = limit, a quadratic in ω; 0 when f_n already needs more."""
    m = inp["motor"]
    psi = m["bemf_v"] / math.sqrt(3) / (2 * math.pi * m["rated_freq_hz"])
    R, Lq, I, V = m["rs_ohm"], m["lq_h"], m["rated_current_a"], limit_v / math.sqrt(3)
    a, b, c = (Lq * I) ** 2 + psi ** 2, 2 * R * I * psi, (R * I) ** 2 - V ** 2
    w = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a) if b * b - 4 * a * c >= 0 else -1.0
    f = w / (2 * math.pi)
    return 0.0 if f < m["rated_freq_hz"] else min(f, 655.35)


def fw_answers(inp: dict) -> dict:
    """Above base speed at the current limit √2·I_n and V = U_dc/√3: the MTPA point by a dense
    scan of the current angle, the base speed by bisection on |v| (not pulab's closed forms)."""
    m, udc = inp["motor"], inp["drive"]["udc_v"]
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    r, ld, lq, p = m["rs_ohm"], m["ld_h"], m["lq_h"], m["pole_pairs"]
    i, v = math.sqrt(2) * m["rated_current_a"], udc / math.sqrt(3)
    def t(b):
        return 1.5 * p * (psi * i * math.sin(b) + (ld - lq) * i * math.cos(b) * i * math.sin(b))
    h = math.pi / 20000
    best = max((t(h * k), h * k) for k in range(20001))[1]
    a, b = max(0.0, best - h), min(math.pi, best + h)
    for _ in range(100):  # ternary search on the unimodal torque around the scan's best angle
        m1, m2 = a + (b - a) / 3, b - (b - a) / 3
        a, b = (m1, b) if t(m1) < t(m2) else (a, m2)
    best = (a + b) / 2
    i_d, i_q = i * math.cos(best), i * math.sin(best)

    def vmag(w):
        return math.hypot(r * i_d - w * lq * i_q, r * i_q + w * (ld * i_d + psi))
    lo, hi = 0.0, 1.0
    while vmag(hi) < v:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if vmag(mid) < v else (lo, mid)
    return {"fw-char": psi / ld, "fw-unbounded": "yes" if psi / ld <= i else "no",
            "fw-base": lo * 60 / (2 * math.pi * p)}


def observer_answers(inp: dict) -> dict:
    """The sensorless exercises at every default (docs/contract.md, "Output: observer"): the
    back-EMF observer's kp = 2ζω0·L_d − R (250 Hz, ζ = 1); NXP's M1_TO_KP_SHIFT of
    2ζω_t/ω_max (15 Hz, ζ = 1, ω_max = 2π·f_b), MCAT's rule ceil(log2 k) for k ≥ 1,
    −ceil(log2(1/k) − 1) below; the lowest speed where ψ·ω = ΔR·I + LSB·|R + jωL_q| with
    ΔR = 0.00393·135·R, I = √2·I_n, LSB = 2√2·I_n/4096, solved as a quadratic in ω; Microchip's
    KFILTER_ESDQ, the forward-Euler back-EMF low-pass of MCAF's pll.c at 250 Hz: round(ω·T_s·2^15)."""
    m, d = inp["motor"], inp["drive"]
    r, ld, lq, p = m["rs_ohm"], m["ld_h"], m["lq_h"], m["pole_pairs"]
    f_b = d.get("base_freq_hz", m["rated_freq_hz"])
    k = 2 * 2 * math.pi * 15 / (2 * math.pi * f_b)
    shift = math.ceil(math.log2(k)) if k >= 1 else -math.ceil(math.log2(1 / k) - 1)
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    i = math.sqrt(2) * m["rated_current_a"]
    c0, c1 = r * 0.00393 * 135 * i, 2 * math.sqrt(2) * m["rated_current_a"] / 4096
    qa, qb, qc = psi ** 2 - (c1 * lq) ** 2, -2 * psi * c0, c0 ** 2 - (c1 * r) ** 2
    w = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
    return {"obs-bemf-kp": 2 * 2 * math.pi * 250 * ld - r, "obs-to-kp-shift": shift,
            "obs-lowest": w * 30 / (math.pi * p),
            "obs-mchp-kfilter": math.floor(2 * math.pi * 250 * d["ts_s"] * 32768 + 0.5)}


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
    psi = pu["psi_r"]
    fit = next((f"Q{q}" for q in (16, 15, 14, 13, 12) if round(psi * 2 ** q) <= 0xFFFF), "none")
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
        # the firmware's voltage limit pm_maxout_vol is Q12 of the rated line voltage
        "pi-choose-fb": fb_max(inp, V["pm_maxout_vol"]["value"] / 4096 * raw_v),
        "pll-kp": L["kp"],
        "pll-kp-pu": L["kp_pu"],
        "pll-int-gain": L["integrator_gain"],
        "pll-naive-kts": g_naive * L["kp"] * ts,
        "pll-naive-locks": "yes" if naive["stable"] else "no",
        **fw_answers(inp),
        **observer_answers(inp),
        # TI's BOOSTXL-DRV8323RS: 7 mΩ × 10 on a bipolar 12-bit ADC at 3.3 V
        "board-counts": 4096 * 0.007 * 10 / 3.3,
        "board-pu": 3.3 / (0.007 * 10) / 4096 / B["I_b"],
        "board-gain": 0.8 * 3.3 / (2 * 0.007 * math.sqrt(2) * P["rated_current_a"]),
        # TI's IQ24 Kp with I_FS the largest reading ±V_ref/(2·R·G) and V_FS = U_dc, truncated
        "board-ti-kp": math.trunc(r["current_pi"]["q"]["kp"] * (3.3 / (2 * 0.007 * 10))
                                  / P["udc_v"] * 2 ** 24),
        **AUDIT,
        # the induction motor of every trainee: ST's ACIM GUI example (acim_oracle.ST_MEZ)
        "acim-sigma": ACIM["acim"]["sigma"],
        "acim-tau-r-pu": ACIM["acim"]["pu"]["tau_r_s"],
        "acim-pm-kp": ACIM["current_pi"]["d"]["pm_kp"],
        # its simulated flux build-up (acim_sim_oracle: flux linkages, float PI)
        "acim-flux-95": ACIM_FLUX["metrics"]["si"]["flux_95_s"],
    }


ACIM = acim_expected(ST_MEZ)


def audit_answers() -> dict:
    """The Workbench header of dronectl/g431-mcsdk read back by hand: a current digit is
    (V_ref/2)/(R_shunt·G)/32767 A (NOMINAL_CURRENT's own comment), the PI is Kp·e/KPDIV +
    ΣKi·e/KIDIV once per 1/20 kHz, a voltage digit (U_dc/√3)/32768 V (pu-lab's stated
    assumption), the loop measured by python-control with one sample plus half a PWM period."""
    i_digit = 3.3 / 2 / (0.003 * 9.14) / 32767
    ts = 1 / 20000
    kp_pu, ki_pu = 2312 / 128, 2158 / 4096
    volts_per_amp = 24 / math.sqrt(3) / 32768 / (i_digit * 32767 / 32768)
    kp, ki = kp_pu * volts_per_amp, ki_pu * volts_per_amp / ts
    m = measure(current_loop(0.35, 0.0006, ts, kp, ki, "computation_pwm"), ts)
    return {"audit-st-current": 870 * i_digit, "audit-st-zero": ki_pu / kp_pu / ts,
            "audit-st-pm": m["phase_margin_deg"]}


AUDIT = audit_answers()
ACIM_FLUX = acim_sim_section({**ST_MEZ, "sim": {}}, {}, True, False)
