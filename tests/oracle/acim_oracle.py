"""Independent oracle for the induction motor's report (``acim``, ``current_pi``, vendor floats).

    .venv/bin/python tests/oracle/acim_oracle.py          # (re)write tests/golden/acim/*.json
    .venv/bin/python tests/oracle/acim_oracle.py --check  # exit 1 if any file is stale

Never imports pulab. Written from the textbook equations of the T-equivalent circuit
(Krause, *Analysis of Electric Machinery*, ch. 6; Novotny & Lipo, *Vector Control*, ch. 5),
with numpy, by routes of its own where there is one:

- σ from the leakage factors σ_s = L_ls/L_m, σ_r = L_lr/L_m: σ = 1 − 1/((1 + σ_s)(1 + σ_r));
- the torque at rated current from the steady-state circuit in complex phasors: the rotor
  current of the T-circuit at the slip frequency ω_sl, T = 3·p·|I_r|²·R_r/ω_sl (air-gap
  power over synchronous speed), so k_T = T/I_q checks 3·p·(L_m²/L_r)·I_m; the rotor flux
  |L_m·I_s + L_r·I_r| checks L_m·I_m;
- the current-model observer from the matrix exponential of its 1×1 state equation
  (scaling and squaring of a Taylor series) and its backward-Euler form;
- vendor floats: numpy.float32 of the vendors' formulas (NXP MCAT, ST ACIM GUI).

Cases: three real motors and one vendor convention (README of tests/golden/acim).
"""

from __future__ import annotations

import copy
import math
import sys
from pathlib import Path

import numpy as np

from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "acim"
REL, ABS = 1e-12, 0.0

ST_MEZ = {"motor": {"kind": "acim", "rated_voltage_v": 42 * math.sqrt(3.0), "rated_current_a": 1.5,
                    "rated_freq_hz": 50, "rated_speed_rpm": 1370, "pole_pairs": 2, "rs_ohm": 0.6,
                    "rr_ohm": 0.4, "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525,
                    "magnetizing_current_a": 0.55},
          "drive": {"udc_v": 150, "ts_s": 1e-4}}
NXP_KV58 = {"motor": {"kind": "acim", "rated_voltage_v": 230, "rated_current_a": 0.9,
                      "rated_freq_hz": 50, "rated_speed_rpm": 1380, "pole_pairs": 2,
                      "rs_ohm": 25.223, "rr_ohm": 23.004, "ls_h": 0.534, "lr_h": 0.534,
                      "lm_h": 0.487},
            "drive": {"udc_v": 325, "ts_s": 1e-4},
            "current_loop": {"bandwidth_hz": 150, "damping": 1}, "analysis": {}}
# Krause, Analysis of Electric Machinery (3-hp, 220 V, 4-pole, 60 Hz): r_s 0.435 Ω, X_ls = X'_lr
# 0.754 Ω, X_M 26.13 Ω, r'_r 0.816 Ω at 60 Hz; rated 5.8 A, 1710 rpm.
KRAUSE_3HP = {"motor": {"kind": "acim", "rated_voltage_v": 220, "rated_current_a": 5.8,
                        "rated_freq_hz": 60, "rated_speed_rpm": 1710, "pole_pairs": 2,
                        "rs_ohm": 0.435, "rr_ohm": 0.816, "lls_h": 0.754 / (120 * math.pi),
                        "llr_h": 0.754 / (120 * math.pi), "lm_h": 26.13 / (120 * math.pi)},
              "drive": {"udc_v": 311, "ts_s": 1e-4}, "conventions": {"base": "peak"},
              "analysis": {"speed": {"inertia_kg_m2": 0.089}}}
# ST's GUI convention: L_ms = 2/3·L_m typed as datasheet.lms_h
ST_G431 = {"motor": {"kind": "acim", "rated_voltage_v": 115 * math.sqrt(3.0), "rated_current_a": 3,
                     "rated_freq_hz": 157, "rated_speed_rpm": 9000, "pole_pairs": 1,
                     "rs_ohm": 2.2, "rr_ohm": 0.7, "lls_h": 0.003, "llr_h": 0.003,
                     "magnetizing_current_a": 1.64},
           "datasheet": {"lms_h": 0.099},
           "drive": {"udc_v": 320, "ts_s": 6.25e-5}, "current_loop": {"method": "damping",
                                                                    "bandwidth_hz": 400}}
CASES = [("01_st_mez_acim", ST_MEZ), ("02_nxp_hvpkv58f", NXP_KV58), ("03_krause_3hp_peak", KRAUSE_3HP),
         ("04_st_g431_lms", ST_G431)]
ERRORS = [
    (ST_MEZ, ("motor", "lm_h"), -0.01, "motor.lm_h"),
    (ST_MEZ, ("motor", "rated_speed_rpm"), 1500, "motor.rated_speed_rpm"),
    (ST_MEZ, ("motor", "rated_speed_rpm"), 1600, "motor.rated_speed_rpm"),
    (ST_MEZ, ("motor", "ld_h"), 0.01, "motor.ld_h"),
    (NXP_KV58, ("motor", "ls_h"), 0.487, "motor.ls_h"),
    (NXP_KV58, ("motor", "lls_h"), 0.047, "motor.ls_h"),
    (ST_G431, ("motor", "lm_h"), 0.1485, "datasheet.lms_h"),
    (ST_MEZ, ("sim", "current", "code"), {"text": "int u;", "output": "u"}, "sim.current.code"),
]


def _expm_1x1(x: float) -> float:
    """e^x by scaling and squaring a 12-term Taylor series (the observer's 1×1 transition)."""
    k = max(0, int(math.ceil(math.log2(abs(x) + 1e-300))) + 4)
    y = x / 2 ** k
    s = np.sum([y ** j / math.factorial(j) for j in range(12)])
    for _ in range(k):
        s = s * s
    return float(s)


def _round_away(x: float) -> int:
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def _get(inp: dict, sec: str, key: str, default=None):
    return inp.get(sec, {}).get(key, default)


def expected(inp: dict) -> dict:
    m = inp["motor"]
    base = _get(inp, "conventions", "base", "rms")
    u_ll, i_n, f_n, p = m["rated_voltage_v"], m["rated_current_a"], m["rated_freq_hz"], m["pole_pairs"]
    lm = m["lm_h"] if "lm_h" in m else 1.5 * inp["datasheet"]["lms_h"]
    lls = m["lls_h"] if "lls_h" in m else m["ls_h"] - lm
    llr = m["llr_h"] if "llr_h" in m else m["lr_h"] - lm
    rs, rr, ts = m["rs_ohm"], m["rr_ohm"], inp["drive"]["ts_s"]
    ls, lr = lm + lls, lm + llr
    # bases (the report's; f_b = f_n here)
    if base == "rms":
        u_b, i_b, pk, dq = u_ll / math.sqrt(3.0), i_n, 3.0, 1.0
    else:
        u_b, i_b, pk, dq = u_ll * math.sqrt(2.0 / 3.0), math.sqrt(2.0) * i_n, 1.5, math.sqrt(2.0)
    w_b = 2 * math.pi * f_n
    z_b, l_b, psi_b, p_b = u_b / i_b, u_b / i_b / w_b, u_b / w_b, pk * u_b * i_b
    sigma = 1.0 - 1.0 / ((1.0 + lls / lm) * (1.0 + llr / lm))
    tau_r = lr / rr
    n_s = 120.0 * f_n / (2 * p)
    slip = 1.0 - m["rated_speed_rpm"] / n_s
    given = "magnetizing_current_a" in m
    i_m = m["magnetizing_current_a"] if given else u_ll / math.sqrt(3.0) / (w_b * ls)
    i_q = math.sqrt(i_n ** 2 - i_m ** 2)
    # steady state in the T-circuit at the field-oriented slip frequency (complex phasors)
    w_sl = i_q / (tau_r * i_m)
    i_s = complex(i_m, i_q)
    i_r = -i_s * 1j * lm / (rr / w_sl + 1j * lr)
    torque = 3.0 * p * abs(i_r) ** 2 * rr / w_sl
    psi_r = abs(lm * i_s + lr * i_r)
    a_zoh = _expm_1x1(-ts / tau_r)
    l_sig = (ls * lr - lm * lm) / lr
    r_sig = rs + rr * lm * lm / (lr * lr)
    a = {"rs_ohm": rs, "rr_ohm": rr, "lls_h": lls, "llr_h": llr, "lm_h": lm, "lms_h": 2 * lm / 3,
         "ls_h": ls, "lr_h": lr, "sigma": sigma, "sigma_ls_h": l_sig, "r_sigma_ohm": r_sig,
         "tau_r_s": tau_r, "tau_s_s": ls / rs, "tau_sigma_s": l_sig / r_sig,
         "sync_speed_rpm": n_s, "rated_slip": slip, "slip_freq_hz": slip * f_n,
         "magnetizing_current_a": i_m, "magnetizing_from": "given" if given else "no_load_estimate",
         "id_ref_a": dq * i_m, "torque_current_a": i_q, "rotor_flux_wb": dq * psi_r,
         "torque_per_amp_nm": torque / i_q, "rated_torque_nm": torque,
         "slip_freq_model_hz": w_sl / (2 * math.pi), "slip_gain_per_s": rr / lr,
         "flux_95_s": tau_r * math.log(20.0),
         "observer": {"a": a_zoh, "b_h": lm * (1 - a_zoh), "a_euler": 1 / (1 + ts / tau_r),
                      "b_euler_h": lm * ts / (tau_r + ts)}}
    t_mb = p_b * p / w_b
    a["pu"] = {"rs_ohm": rs / z_b, "rr_ohm": rr / z_b, "r_sigma_ohm": r_sig / z_b,
               "lls_h": lls / l_b, "llr_h": llr / l_b, "lm_h": lm / l_b, "lms_h": 2 * lm / 3 / l_b,
               "ls_h": ls / l_b, "lr_h": lr / l_b, "sigma_ls_h": l_sig / l_b,
               "tau_r_s": tau_r * w_b, "tau_s_s": ls / rs * w_b, "tau_sigma_s": l_sig / r_sig * w_b,
               "magnetizing_current_a": dq * i_m / i_b, "torque_current_a": dq * i_q / i_b,
               "rotor_flux_wb": dq * psi_r / psi_b, "slip_freq_hz": slip, "rated_slip": slip,
               "sigma": sigma, "id_ref_a": dq * i_m / i_b, "slip_gain_per_s": rr / lr / w_b,
               "torque_per_amp_nm": torque / (dq * i_q / i_b) / t_mb,
               "observer_b": lm * (1 - a_zoh) / l_b}
    # the current PI on σ·L_s, R_σ (the report's methods; Inovance Q12 and Q16 integers)
    cl = inp.get("current_loop", {})
    method, bw, zeta = cl.get("method", "bandwidth"), cl.get("bandwidth_hz", 500.0), \
        cl.get("damping", math.sqrt(0.5))
    w = 2 * math.pi * bw
    kp, ki = (w * l_sig, w * r_sig) if method == "bandwidth" else \
        (2 * zeta * w * l_sig - r_sig, w * w * l_sig)
    pm_kp, pm_ki = _round_away(kp * i_b / u_b * 4096), _round_away(ki * i_b / u_b * ts * 65536)
    kp_back, ki_back = pm_kp / 4096 * u_b / i_b, pm_ki / 65536 / ts * u_b / i_b
    axis = {"kp": kp, "ki": ki, "kp_pu": kp * i_b / u_b, "ki_pu": ki * i_b / u_b,
            "pm_kp": pm_kp, "pm_ki": pm_ki,
            "from_integers": {"kp": kp_back, "ki": ki_back,
                              "bandwidth_hz": kp_back / (2 * math.pi * l_sig)}}
    pi = {"method": method, "bandwidth_hz": float(bw), "d": axis, "q": copy.deepcopy(axis)}
    # the vendors' floats
    # the generators print 12 (MCAT) and 7 (ST GUI) decimals; the compiler rounds that text
    def f32(x: float, decimals: int) -> float:
        printed = np.format_float_positional(x, precision=decimals, unique=False)
        return float(np.float32(float(printed)))
    w0, z0 = 2 * math.pi * bw, zeta
    nxp_kp, nxp_ki = 2 * z0 * w0 * l_sig - rs, w0 * w0 * l_sig * ts
    vendors = {
        "nxp": {"M1_RFO_KR_INV_GAIN": f32(lr / lm, 12), "M1_RFO_LS_TOT_LEAK_GAIN": f32(l_sig * lr / lm, 12),
                "M1_RFO_PSI_RA1_GAIN": f32(tau_r / (tau_r + ts), 12),
                "M1_RFO_PSI_RB1_GAIN": f32(lm * ts / (tau_r + ts), 12),
                "M1_RFO_TRQ_CNST": f32(1.5 * p * lm / lr, 12), "M1_MRAS_SPDCNST": f32(30 / (math.pi * p), 12),
                "M1_D_KP_GAIN": f32(nxp_kp, 12), "M1_D_KI_GAIN": f32(nxp_ki, 12),
                "M1_Q_KP_GAIN": f32(nxp_kp, 12), "M1_Q_KI_GAIN": f32(nxp_ki, 12)},
        "st": {"RS": f32(rs, 7), "RR": f32(rr, 7), "LLS": f32(lls, 7), "LLR": f32(llr, 7), "LMS": f32(2 * lm / 3, 7),
               "LM": f32(lm, 7), "LR": f32(lr, 7), "LS": f32(ls, 7), "TAU_R": f32(tau_r, 7),
               "TAU_S": f32(ls / rs, 7), "SIGMA": f32(sigma, 7), "IMAGN_A": f32(math.sqrt(2) * i_m, 7),
               "NOMINAL_PHASE_VOLTAGE": f32(u_ll / math.sqrt(3), 7), "NOMINAL_FREQ": f32(f_n, 7)}}
    # TI's CUR_CONST_MACRO in C float (Kt through double: PI is a double literal), then
    # (long)(x·2^24) of each float
    s32 = np.float32
    tr32 = s32(lr) / s32(rr)
    f_b = _get(inp, "drive", "base_freq_hz", f_n)
    kt32 = s32(1.0 / (float(tr32 * s32(2)) * 3.14159265358979 * float(s32(f_b))))
    vendors["ti"] = {"Kr": int(float(s32(ts) / tr32) * 2 ** 24), "Kt": int(float(kt32) * 2 ** 24),
                     "K": int(float(s32(ts) * s32(f_b)) * 2 ** 24)}
    out = {"acim": a, "current_pi": pi, "vendor_values": vendors}
    if "analysis" in inp:
        out["acim_flux"] = _flux(ts, tau_r, a["pu"]["magnetizing_current_a"], vendors["ti"]["Kr"])
    if "speed" in inp.get("analysis", {}):
        j = inp["analysis"]["speed"]["inertia_kg_m2"]
        out["speed_bases"] = {"w_mb": w_b / p, "n_mb_rpm": 60 * f_n / p, "torque_nm": t_mb,
                              "kt_nm_per_a": torque / (dq * i_q),
                              "inertia_constant_s": j * (w_b / p) ** 2 / (2 * p_b)}
    return out


def _flux(ts: float, tau_r: float, i_d: float, kr: int) -> dict:
    """TI's CUR_MOD update IMDs += (Kr·(IDs − IMDs)) >> 24 in Python integers, beside the same
    update in float with Kr = T_s/τ_r, over 10·τ_r: the first periods at 95 % and the end."""
    steps = math.ceil(10.0 * tau_r / ts)
    ids = math.trunc(i_d * (1 << 24))
    x, m, t95f, t95i = 0.0, 0, None, None
    for k in range(1, steps + 1):
        x = x + ts / tau_r * (i_d - x)
        m = m + (kr * (ids - m) >> 24)
        if t95f is None and x >= 0.95 * i_d:
            t95f = k * ts
        if t95i is None and m * 20 >= ids * 19:
            t95i = k * ts
    return {"steps": steps, "complete": True, "kr": kr, "id_ref": ids, "t95_float_s": t95f,
            "t95_fixed_s": t95i, "final_float_pu": x, "final_fixed": m,
            "final_fixed_pu": m / (1 << 24), "stall_lsb": ids - m, "stall_pct": 100.0 * (ids - m) / ids,
            "events": {}}


def _error_case(inp: dict, where: tuple, value, field: str) -> dict:
    inp = copy.deepcopy(inp)
    node = inp
    for k in where[:-1]:
        node = node.setdefault(k, {})
    node[where[-1]] = value
    return {"input": inp, "field": field}


def build() -> dict:
    files = {f"{name}.json": {"input": inp, "expected": expected(inp)} for name, inp in CASES}
    files["errors.json"] = {"cases": [_error_case(*e) for e in ERRORS]}
    return files


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
