"""Independent oracle for the vendor profiles (docs/contract.md "Vendor profiles").

Written from the contract and the vendors' public files, never importing pulab. The SI gains
and the Inovance integers come from the existing oracle (oracle.py). Fixed-point conversions
are numpy: C casts are np.trunc, then numpy integer types; saturating macros are np.clip;
"nearest" is ties away from zero.

    .venv/bin/python tests/oracle/profiles_oracle.py          # write tests/golden/profiles/
    .venv/bin/python tests/oracle/profiles_oracle.py --check  # exit 1 if stale
"""

from __future__ import annotations

import copy
import json
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import oracle_report  # noqa: E402
from make_golden import IND380, LV48, SEED, SERVO  # noqa: E402

OUT = pathlib.Path(__file__).resolve().parents[1] / "golden" / "profiles"
REL, ABS = 1e-12, 1e-15  # closed-form float64 arithmetic (see golden_files.py)
R2, R3 = np.sqrt(2.0), np.sqrt(3.0)


def trunc(x: float, q: int) -> int:
    """(integer)(x·2^q) as a C cast does (toward zero)."""
    return int(np.trunc(np.float64(x) * np.float64(2.0) ** q))


def nearest(x: float, q: int) -> int:
    y = np.float64(x) * np.float64(2.0) ** q
    return int(np.sign(y) * np.floor(np.abs(y) + 0.5))


def rec(value: int, ideal_real: float, q: int, scale: float) -> dict:
    ideal = float(ideal_real) * 2.0 ** q
    return {"value": int(value), "ideal": ideal, "si": value / 2.0 ** q * scale, "q": q}


def sat(v: int, lo: int, hi: int) -> int:
    return int(np.clip(v, lo, hi))


def profiles(inp: dict, choices: dict | None = None) -> dict:
    """Every profile's constants; ``choices``, when given, receives the shifts, divisors and
    Qs each profile chose ({profile: {name: integer}})."""
    prof_in = inp.get("profiles") or {}
    base = {k: v for k, v in inp.items() if k != "profiles"}
    o = oracle_report(base)
    m, d = base["motor"], base["drive"]
    rs, ld, lq, pp = m["rs_ohm"], m["ld_h"], m["lq_h"], m["pole_pairs"]
    i_r, u_r, f_n, e = m["rated_current_a"], m["rated_voltage_v"], m["rated_freq_hz"], m["bemf_v"]
    udc, ts = d["udc_v"], d["ts_s"]
    f_b = d.get("base_freq_hz", f_n)
    i_fs = 2.0 * R2 * i_r
    gains = {a: (o["current_pi"][a]["kp"], o["current_pi"][a]["ki"]) for a in ("d", "q")}
    psi_pk = R2 * e / (R3 * 2 * np.pi * f_n)
    out = {}

    # Inovance: the existing oracle's integers; gains on U_LL/√3, I_rms
    ub, ib = u_r / R3, i_r
    ino = {k: {"value": v["value"], "ideal": v["ideal"], "si": v["si"]}
           for k, v in o["vendor"].items() if k != "raw"}
    for a in ("d", "q"):
        kp, ki = gains[a]
        ino[f"pm_kp_{a}"] = rec(nearest(kp * ib / ub, 12), kp * ib / ub, 12, ub / ib)
        ino[f"pm_ki_{a}"] = rec(nearest(ki * ts * ib / ub, 16), ki * ts * ib / ub, 16,
                                ub / ib / ts)
    out["inovance"] = ino

    # TI: IQ(global_q) of full-scale per unit, series PI, (long) cast
    t = prof_in.get("ti", {})
    v, i, f = t.get("full_scale_voltage_v", udc), t.get("full_scale_current_a", i_fs), \
        t.get("full_scale_freq_hz", f_b)
    q, imax = t.get("global_q", 24), t.get("max_current_a", R2 * i_r)
    ti = {}
    for a in ("d", "q"):
        kp, ki = gains[a]
        kp_r = rec(trunc(kp * i / v, q), kp * i / v, q, v / i)
        ti[f"Kp_I{a}"] = kp_r
        ti[f"Ki_I{a}"] = rec(trunc(ki * ts / kp, q), ki * ts / kp, q, kp_r["si"] / ts)
    for a, L in (("d", ld), ("q", lq)):
        kp_r = rec(trunc(0.25 * L * i / (ts * v), q), 0.25 * L * i / (ts * v), q, v / i)
        ti[f"Kp_I{a}_default"] = kp_r
        ti[f"Ki_I{a}_default"] = rec(trunc(rs / L * ts, q), rs / L * ts, q, kp_r["si"] / ts)
    ti["Kp_spd_default"] = rec(trunc(0.02 * imax * f / i, q), 0.02 * imax * f / i, q, i / f)
    ti["Ki_spd_default"] = rec(trunc(2 * imax * f * ts / i, q), 2 * imax * f * ts / i, q, 1 / ts)
    ti["Rs_pu"] = rec(trunc(rs * i / v, q), rs * i / v, q, v / i)
    out["ti"] = ti

    # NXP: ACC32 = trunc(x·2^15) clipped to int32; FRAC16 mantissa with shift
    n = prof_in.get("nxp", {})
    um = n.get("udcb_max_v", udc) / n.get("u_max_coeff", R3)
    if n.get("round_u_max", False):
        um = np.floor(um * 10 + 0.5) / 10
    im, k = n.get("i_max_a", i_fs), 2.0 if n.get("trapezoidal", False) else 1.0
    em = n.get("e_max_v", um)
    acc = lambda x: sat(trunc(x, 15), -2 ** 31, 2 ** 31 - 1)  # noqa: E731
    nxp = {}
    for a in ("d", "q"):
        kp, ki = gains[a]
        A = a.upper()
        nxp[f"M1_{A}_KP_GAIN"] = rec(acc(kp * im / um), kp * im / um, 15, um / im)
        nxp[f"M1_{A}_KI_GAIN"] = rec(acc(ki * ts / k * im / um), ki * ts / k * im / um, 15,
                                     um / im * k / ts)
    den, wmax = ld + ts * rs, 2 * np.pi * f_b
    for name, x, sc in (("M1_I_SCALE", ld / den, 1.0), ("M1_U_SCALE", ts / den * um / im, im / um),
                        ("M1_E_SCALE", ts / den * em / im, im / em),
                        ("M1_WI_SCALE", lq * ts / den * wmax, 1 / wmax)):
        nxp[name] = rec(acc(x), x, 15, sc)
    K = ts * wmax / np.pi
    sh = int(np.ceil(np.log2(K))) if K >= 1 else -int(np.ceil(np.log2(1 / K) - 1))
    mant = K * 2.0 ** -sh
    th = rec(sat(trunc(mant, 15), -32768, 32767), mant, 15, 2.0 ** sh * np.pi / ts)
    th["shift"] = sh
    nxp["M1_TO_THETA_GAIN"] = th
    out["nxp"] = nxp

    # ST: digits; int16 gains over power-of-two divisors; C casts for the conversions
    s = prof_in.get("st", {})
    vref, g = s.get("adc_reference_v", 3.3), s.get("amplification_gain", 8.0)
    rsh = s.get("rshunt_ohm", 3.3 / (2 * 8.0 * i_fs))
    vbf = s.get("vbus_partitioning_factor", 3.3 / (2 * udc))
    f1 = s.get("f1", 16384)
    imax_st = vref / (2 * rsh * g)
    r = (udc / R3) / imax_st

    def div(x):
        dd = 16384
        while dd > 1 and np.floor(abs(x) * dd + 0.5) > 32767:
            dd //= 2
        return dd
    kpdiv = s.get("tf_kpdiv") or div(max(abs(gains[a][0]) for a in "dq") / r)
    kidiv = s.get("tf_kidiv") or div(max(abs(gains[a][1]) for a in "dq") * ts / r)
    st = {}
    for a, w in (("d", "FLUX"), ("q", "TORQUE")):
        kp, ki = gains[a]
        qp, qi = int(np.log2(kpdiv)), int(np.log2(kidiv))
        st[f"PID_{w}_KP_DEFAULT"] = rec(sat(nearest(kp / r, qp), -32768, 32767), kp / r, qp, r)
        st[f"PID_{w}_KI_DEFAULT"] = rec(sat(nearest(ki * ts / r, qi), -32768, 32767),
                                        ki * ts / r, qi, r / ts)
    ccf = 65536.0 * rsh * g / vref
    st["CURRENT_CONV_FACTOR"] = rec(int(np.uint16(np.trunc(ccf))), ccf, 0, 1.0)
    mv = (vref / R3) / vbf
    st["MAX_VOLTAGE"] = rec(int(np.int16(np.trunc(mv))), mv, 0, 1.0)
    nom = R2 * i_r * 32767.0 * rsh * g / (vref / 2)
    st["NOMINAL_CURRENT"] = rec(nearest(nom, 0), nom, 0, (vref / 2) / (32767 * rsh * g))
    f_reg = int(np.floor(1 / ts + 0.5))
    c1 = f1 * rs / (lq * f_reg)
    st["C1"] = rec(int(np.trunc(c1)), c1, 0, lq * f_reg / f1)
    rpm = 60 * f_b / pp
    kev = e / (60 * f_n / pp / 1000)
    bemf = rpm * 1.2 * kev * R2 / (1000 * R3)
    st["MAX_BEMF_VOLTAGE"] = rec(int(np.trunc(bemf)), bemf, 0, 1.0)
    dn = lq * imax_st * f_reg
    st["C3"] = rec(int(np.trunc(f1 * st["MAX_BEMF_VOLTAGE"]["value"] / dn)), f1 * bemf / dn, 0,
                   dn / f1)
    st["C5"] = rec(int(np.trunc(f1 * st["MAX_VOLTAGE"]["value"] / dn)), f1 * mv / dn, 0, dn / f1)
    out["st"] = st

    # Microchip: Q-format with bases V_b, I_b, ω_b, Δt; nearest
    c = prof_in.get("microchip", {})
    vb, ibm = c.get("voltage_base_v", udc), c.get("current_base_a", i_fs)
    wb = 2 * np.pi * c.get("velocity_base_hz", f_b)
    z = vb / ibm
    q16 = lambda x, qq, sc: rec(sat(nearest(x, qq), -32768, 32767), x, qq, sc)  # noqa: E731
    mc = {"MCAF_MOTOR_RS": q16(rs / z, 15, z)}
    for A, L in (("D", ld), ("Q", lq)):
        mc[f"MCAF_MOTOR_L{A}_BASE_DT"] = q16(L / (z * ts), 13, z * ts)
        mc[f"MCAF_MOTOR_L{A}_BASE_OMEGA_E"] = q16(L * wb / z, 15, z / wb)
    mc["MCAF_MOTOR_PSI_BASE_OMEGA_E"] = q16(psi_pk * wb / vb, 14, vb / wb)
    mc["MCAF_MOTOR_PSI_BASE_DT"] = q16(psi_pk / (vb * ts), 13, vb * ts)
    mc["MCAF_MOTOR_KE"] = q16(psi_pk * wb / vb, 12, vb * pp / wb)

    def gq(x):
        qq = 15
        while qq > 0 and np.floor(abs(x) * 2.0 ** qq + 0.5) > 32767:
            qq -= 1
        return qq
    kp, ki = gains["q"]
    mc["KIP"] = q16(kp / z, gq(kp / z), z)
    mc["KII"] = q16(ki * ts / z, gq(ki * ts / z), z / ts)
    out["microchip"] = mc
    if choices is not None:
        choices.update(nxp={"M1_TO_THETA_SHIFT": sh}, st={"TF_KPDIV": kpdiv, "TF_KIDIV": kidiv},
                       microchip={"KIP_Q": gq(kp / z), "KII_Q": gq(ki * ts / z)})
        # The real value each constant stores (before its own scaling by 2^q, after the shift).
        choices["real"] = {name: {k: r_["ideal"] / 2.0 ** r_["q"] * 2.0 ** r_.get("shift", 0)
                                  for k, r_ in p.items()} for name, p in out.items()
                           if name != "inovance"}
    return {name: {k: {kk: float(vv) if kk != "value" and kk != "shift" else vv
                       for kk, vv in r_.items() if kk != "q"} for k, r_ in p.items()}
            for name, p in out.items()}


CASES = {
    "seed": SEED, "ind380": IND380, "servo220": SERVO, "lv48": LV48,
    "servo220_options": {**copy.deepcopy(SERVO), "profiles": {
        "ti": {"global_q": 20, "full_scale_voltage_v": 400.0, "full_scale_current_a": 12.0},
        "nxp": {"trapezoidal": True, "round_u_max": True, "udcb_max_v": 433.0},
        "st": {"tf_kpdiv": 256, "tf_kidiv": 8192, "rshunt_ohm": 0.01, "amplification_gain": 5.0},
        "microchip": {"voltage_base_v": 400.0, "current_base_a": 11.0,
                      "velocity_base_hz": 500.0}}},
}


# The C word each constant is stored in and how the vendor rounds into it (vendor-scaling.md
# and the files named there): (min, max, 'trunc' | 'nearest').
_I16, _U16, _I32 = (-2 ** 15, 2 ** 15 - 1), (0, 2 ** 16 - 1), (-2 ** 31, 2 ** 31 - 1)
WORDS = {
    "ti": {k: (*_I32, "trunc") for k in ("Kp_Id", "Ki_Id", "Kp_Iq", "Ki_Iq", "Kp_Id_default",
                                         "Ki_Id_default", "Kp_Iq_default", "Ki_Iq_default",
                                         "Kp_spd_default", "Ki_spd_default", "Rs_pu")},
    "nxp": {**{k: (*_I32, "trunc") for k in ("M1_D_KP_GAIN", "M1_D_KI_GAIN", "M1_Q_KP_GAIN",
                                            "M1_Q_KI_GAIN", "M1_I_SCALE", "M1_U_SCALE",
                                            "M1_E_SCALE", "M1_WI_SCALE")},
            "M1_TO_THETA_GAIN": (*_I16, "trunc")},
    "st": {**{k: (*_I16, "nearest") for k in ("PID_FLUX_KP_DEFAULT", "PID_FLUX_KI_DEFAULT",
                                              "PID_TORQUE_KP_DEFAULT", "PID_TORQUE_KI_DEFAULT",
                                              "NOMINAL_CURRENT")},
           "CURRENT_CONV_FACTOR": (*_U16, "trunc"), "MAX_BEMF_VOLTAGE": (*_U16, "trunc"),
           "MAX_VOLTAGE": (*_I16, "trunc"), "C1": (*_I32, "trunc"), "C3": (*_I32, "trunc"),
           "C5": (*_I32, "trunc")},
    "microchip": {k: (*_I16, "nearest") for k in (
        "MCAF_MOTOR_RS", "MCAF_MOTOR_LD_BASE_DT", "MCAF_MOTOR_LD_BASE_OMEGA_E",
        "MCAF_MOTOR_LQ_BASE_DT", "MCAF_MOTOR_LQ_BASE_OMEGA_E", "MCAF_MOTOR_PSI_BASE_OMEGA_E",
        "MCAF_MOTOR_PSI_BASE_DT", "MCAF_MOTOR_KE", "KIP", "KII")},
}


def fails(profile: str, key: str, rec: dict) -> bool:
    """Whether a constant breaks (docs/contract.md, "Family proof"): the real it stores,
    rounded the vendor's way, is outside its word (a saturating macro clamps it, a C cast is
    undefined), or it stores 0 for a non-zero real (all resolution lost)."""
    lo, hi, how = WORDS[profile][key]
    x = rec["ideal"]
    r = np.trunc(x) if how == "trunc" else np.sign(x) * np.floor(np.abs(x) + 0.5)
    return not lo <= r <= hi or (rec["value"] == 0 and x != 0)


def main(argv: list[str]) -> int:
    files = {f"{name}.json": {"input": inp, "expected": profiles(inp)} for name, inp in CASES.items()}
    return sync(files, golden_dir(argv, OUT), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
