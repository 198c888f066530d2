"""NXP MCAT's ``m1_pmsm_appconfig.h`` read back (``decode_header``).

Every constant is a fraction of a scale the same file states (``M1_I_MAX``, ``M1_U_MAX`` =
U_DCB,max/√3, ``M1_E_MAX``, ``M1_N_MAX``, ``M1_FREQ_MAX`` = N_max·pp/60, ``M1_U_DCB_MAX``),
stored through RTCESL's ``FRAC16``/``FRAC32``/``ACC32`` (folded by the decoder). The
formulas are those of :mod:`pulab.profiles.nxp.scaling` (MCAT's ``inner_CLoop.js`` and
``inner_PoSpeBemfDQ.js``), read backwards:

- T_s: the MCAT JSON's ``currentLoopSampleTime``, else ``M1_SCALAR_INTEG_GAIN``/(2·f_max)
  (the scalar mode's angle step, in units of π), else ``M1_TO_THETA_GAIN``·2^shift·π/ω_max;
- the motor from the observer scales: with a = T_s/(L_d + T_s·R_s) = U_SCALE·I_max/U_max,
  L_d = I_SCALE·T_s/a, R_s = (1 − I_SCALE)/a, L_q = WI_SCALE/(a·ω_max);
- the current PI: kp = K_p·U_max/I_max [V/A], ki = K_i·U_max/I_max·k/T_s with k = 2 (MCAT's
  trapezoidal integrator; the JSON decides when present), and from them MCAT's own design
  inputs ω0 = √(ki/L), ξ = (kp + R_s)/(2·ω0·L);
- the speed PI (in A per electrical rad/s): kp = K_p·I_max/ω_max, ki = K_i·I_max/ω_max·k/T_speed
  (the same controller as the current loop, so the same k; T_speed from the JSON).

The MCAT JSON in the header's first comment (its inputs) is read and every constant it
determines is computed again from it and compared in LSB (MCAT prints 6 significant digits,
so a FRAC32 may differ by the print's rounding; the bound is stated per macro).

Examples
--------
>>> v = {"M1_I_MAX": 8.0, "M1_U_MAX": 20.9578, "M1_I_SCALE": 28226, "M1_U_SCALE": 22033}
>>> d = decode_header(v, {})
>>> round(d["design"]["a_per_ohm"], 4)  # T_s/(L_d + T_s·R_s) = U_SCALE·I_max/U_max
0.2567
"""

from __future__ import annotations

import math

from ..common import SQRT3
from ...model.mcat import flatten, mcat_json
from ..decoding import check, current_loop, integrator_loop, macro, result
from .appconfig import _encoder

__all__ = ["decode_header"]

_Q15, _Q31 = 32768.0, 2147483648.0
#: name → (scale macro, unit, meaning, Q) for the FRAC16/FRAC32/ACC32 fractions of a scale.
_FRACTIONS = {
    "M1_I_PH_NOM": ("M1_I_MAX", "A", "nominal phase current", _Q15),
    "M1_N_NOM": ("M1_N_MAX", "rpm", "nominal speed", _Q15),
    "M1_U_DCB_TRIP": ("M1_U_DCB_MAX", "V", "brake resistor on above", _Q15),
    "M1_U_DCB_UNDERVOLTAGE": ("M1_U_DCB_MAX", "V", "under-voltage fault", _Q15),
    "M1_U_DCB_OVERVOLTAGE": ("M1_U_DCB_MAX", "V", "over-voltage fault", _Q15),
    "M1_N_OVERSPEED": ("M1_N_MAX", "rpm", "over-speed fault", _Q15),
    "M1_N_MIN": ("M1_N_MAX", "rpm", "minimum speed", _Q15),
    "M1_E_BLOCK_TRH": ("M1_E_MAX", "V", "blocked-rotor back-EMF threshold", _Q15),
    "M1_SCALAR_UQ_MIN": ("M1_U_MAX", "V", "scalar mode minimum voltage", _Q15),
    "M1_ALIGN_VOLTAGE": ("M1_U_MAX", "V", "alignment voltage", _Q15),
    "M1_OL_START_I": ("M1_I_MAX", "A", "open-loop start-up current", _Q15),
    "M1_MERG_SPEED_TRH": ("M1_N_MAX", "rpm", "merging speed", _Q15),
    "M1_SPEED_LOOP_HIGH_LIMIT": ("M1_I_MAX", "A", "speed PI output high limit", _Q15),
    "M1_SPEED_LOOP_LOW_LIMIT": ("M1_I_MAX", "A", "speed PI output low limit", _Q15),
    "M1_CLOOP_LIMIT": (None, "", "current-loop output limit (fraction of U_max)", _Q15),
    "M1_I_SCALE": (None, "", "observer: L_d/(L_d + T_s·R_s)", _Q15),
}
_SCALES = {"M1_I_MAX": ("A", "phase-current scale"), "M1_U_MAX": ("V", "voltage scale"),
           "M1_E_MAX": ("V", "back-EMF scale"), "M1_N_MAX": ("rpm", "speed scale"),
           "M1_FREQ_MAX": ("Hz", "electrical frequency scale"),
           "M1_U_DCB_MAX": ("V", "DC-bus scale"), "M1_MOTOR_PP": ("", "pole pairs"),
           "M1_W_MAX": ("rad/s", "electrical speed scale (pu-lab's header)")}
_GAINS = ("M1_D_KP_GAIN", "M1_D_KI_GAIN", "M1_Q_KP_GAIN", "M1_Q_KI_GAIN")
_OTHER = ("M1_U_SCALE", "M1_E_SCALE", "M1_WI_SCALE", "M1_SCALAR_INTEG_GAIN",
          "M1_TO_THETA_GAIN", "M1_TO_THETA_SHIFT", "M1_TO_KP_GAIN", "M1_TO_KP_SHIFT",
          "M1_TO_KI_GAIN", "M1_TO_KI_SHIFT", "M1_SPEED_PI_PROP_GAIN", "M1_SPEED_PI_INTEG_GAIN",
          "M1_ALIGN_DURATION", "M1_BEMF_DQ_KP_GAIN", "M1_BEMF_DQ_KI_GAIN")
READS = tuple(_SCALES) + tuple(_FRACTIONS) + _GAINS + _OTHER


def _frac16(x: float) -> int:
    return int(max(-1.0, min(x, 32767 / _Q15)) * _Q15)


def _acc32(x: float) -> int:
    return int(x * _Q15)


def _frac32(x: float) -> int:
    return int(max(-1.0, min(x, (_Q31 - 1) / _Q31)) * _Q31)


_STORE = {"FRAC16": (_frac16, _Q15), "FRAC32": (_frac32, 2.0 ** 31), "ACC32": (_acc32, _Q15)}


def _expected(j: dict, k: float, flt: bool) -> dict:
    """Each constant the MCAT inputs determine: name → (ideal value, the macro that stores it
    (None: a float the header prints), LSB per unit); ``flt``: the floating-point variant,
    whose constants are SI (speeds in electrical rad/s)."""
    p, c = j["parameters"], j.get("currentLoop", {})
    sl, sn = j.get("speedLoop", {}), j.get("sensorless", {})
    out: dict = {}
    try:
        # MCAT spells the pole pairs parametersPP in older versions, parametersPp in newer ones
        i_max, udcb = p["parametersImax"], p["parametersUdcbMax"]
        pp = p["parametersPp"] if "parametersPp" in p else p["parametersPP"]
        n_max, e_max = p["parametersNmax"], p.get("parametersEmax")
        rs, ld, lq = p["parametersRs"], p["parametersLd"], p["parametersLq"]
        ts = c["currentLoopSampleTime"]
    except (KeyError, TypeError):
        return out
    u_max = udcb / SQRT3
    w_max = 2.0 * math.pi * n_max * pp / 60.0
    f16 = [("M1_I_PH_NOM", p.get("parametersIphNom"), i_max),
           ("M1_N_NOM", p.get("parametersNnom"), n_max),
           ("M1_U_DCB_TRIP", p.get("parametersUdcbTrip"), udcb),
           ("M1_U_DCB_UNDERVOLTAGE", p.get("parametersUdcbUnder"), udcb),
           ("M1_U_DCB_OVERVOLTAGE", p.get("parametersUdcbOver"), udcb),
           ("M1_N_OVERSPEED", p.get("parametersNover"), n_max),
           ("M1_N_MIN", p.get("parametersNmin"), n_max),
           ("M1_E_BLOCK_TRH", p.get("parametersEblock"), e_max),
           ("M1_SCALAR_UQ_MIN", p.get("parametersScalarUqMin"), u_max),
           ("M1_ALIGN_VOLTAGE", p.get("parametersAlignVoltage"), u_max),
           ("M1_OL_START_I", sn.get("sensorlessStartupCurrent"), i_max),
           ("M1_MERG_SPEED_TRH", sn.get("sensorlessMergingSpeed"), n_max),
           ("M1_SPEED_LOOP_HIGH_LIMIT", sl.get("speedLoopUpperLimit"), i_max),
           ("M1_SPEED_LOOP_LOW_LIMIT", sl.get("speedLoopLowerLimit"), i_max),
           ("M1_CLOOP_LIMIT", c.get("currentLoopOutputLimit"), 100.0)]
    speeds = {"M1_N_NOM", "M1_N_OVERSPEED", "M1_N_MIN", "M1_MERG_SPEED_TRH"}
    for name, x, scale in f16:
        if not isinstance(x, (int, float)) or not isinstance(scale, (int, float)) or not scale:
            continue
        if not flt:
            out[name] = (x / scale, _frac16, _Q15)
        elif name in speeds:
            out[name] = (x * pp * 2.0 * math.pi / 60.0, None, 1.0)
        else:
            out[name] = (x / 100.0 / SQRT3 if name == "M1_CLOOP_LIMIT" else x, None, 1.0)
    f0, ksi = c.get("currentLoopF0"), c.get("currentLoopKsi")
    if isinstance(f0, (int, float)) and isinstance(ksi, (int, float)):
        w0 = 2.0 * math.pi * f0
        g = 1.0 if flt else i_max / u_max
        for axis, l in (("D", ld), ("Q", lq)):
            out[f"M1_{axis}_KP_GAIN"] = ((2.0 * ksi * w0 * l - rs) * g, None if flt else _acc32, _Q15)
            out[f"M1_{axis}_KI_GAIN"] = (w0 * w0 * l * ts / k * g, None if flt else _acc32, _Q15)
    a = ts / (ld + ts * rs)
    f = None if flt else _acc32
    out["M1_I_SCALE"] = (ld / (ld + ts * rs), f, _Q15)
    out["M1_U_SCALE"] = (a if flt else a * u_max / i_max, f, _Q15)
    if flt:
        out["M1_E_SCALE"] = (a, f, _Q15)
    elif isinstance(e_max, (int, float)):
        out["M1_E_SCALE"] = (a * e_max / i_max, f, _Q15)
    out["M1_WI_SCALE"] = (lq * a if flt else lq * a * w_max, f, _Q15)
    out["M1_SCALAR_INTEG_GAIN"] = (2.0 * n_max * pp / 60.0 * ts, _acc32, _Q15)
    if isinstance(p.get("parametersAlignDuration"), (int, float)):
        out["M1_ALIGN_DURATION"] = (p["parametersAlignDuration"] / ts, round, 1.0)
    if sl.get("speedLoopManualConstantTunning") is True and not flt:
        tsp = sl.get("speedLoopSampleTime")
        if isinstance(sl.get("speedLoopSLKp"), (int, float)):
            out["M1_SPEED_PI_PROP_GAIN"] = (sl["speedLoopSLKp"] * w_max / i_max, _acc32, _Q15)
        if isinstance(sl.get("speedLoopSLKi"), (int, float)) and isinstance(tsp, (int, float)):
            out["M1_SPEED_PI_INTEG_GAIN"] = (sl["speedLoopSLKi"] * w_max / i_max * tsp,
                                             _acc32, _Q15)
    if not flt:  # the encoder's macros: the profile's own records (appconfig)
        for name, rec in _encoder(flatten(j), n_max).items():
            store, per = _STORE.get(rec["format"].split(" ")[0], (round, 1.0))
            out[name] = (rec["ideal"] / per, store, per)
    return out


def _observer(v: dict, flt: bool, ts, ts_theta, w_max, i_max, motor: dict) -> dict | None:
    """The back-EMF observer and the tracking observer (:mod:`pulab.profiles.nxp.observer`'s
    formulas read backwards): the BEMF observer's kp = 2ζω0·L_d − R_s [Ω], ki = L_d·ω0² [Ω/s]
    (fractional: ·E_max/I_max/2^15, ki per T_s), so ω0 = √(ki/L_d), ζ = (kp + R_s)/(2ω0·L_d);
    the tracking observer's kp = 2ζω_t, ki = ω_t² (fractional: gain·2^shift/2^15·ω_max, ki per
    T_s): a PLL, :func:`pulab.profiles.decoding.integrator_loop` with k = 1."""
    has = v.keys().__contains__
    out = {}
    if has("M1_TO_THETA_GAIN") and (flt or has("M1_TO_THETA_SHIFT")):
        out["tracking_theta_gain"] = v["M1_TO_THETA_GAIN"] if flt else \
            v["M1_TO_THETA_GAIN"] / _Q15 * 2.0 ** v["M1_TO_THETA_SHIFT"]
        out["ts_from_theta_s"] = ts_theta
    if ts and all(map(has, ("M1_TO_KP_GAIN", "M1_TO_KI_GAIN"))) and (
            flt or (w_max and has("M1_TO_KP_SHIFT") and has("M1_TO_KI_SHIFT"))):
        g = (lambda n: v[f"{n}_GAIN"]) if flt else \
            (lambda n: v[f"{n}_GAIN"] / _Q15 * 2.0 ** v[f"{n}_SHIFT"] * w_max)
        t = integrator_loop(g("M1_TO_KP"), g("M1_TO_KI") / ts, 1.0)
        if t is not None:
            out["tracking"] = {"kp_per_s": g("M1_TO_KP"), "ki_per_s2": g("M1_TO_KI") / ts, **t}
    ld, rs, e_max = motor.get("ld_h"), motor.get("rs_ohm"), v.get("M1_E_MAX")
    if ts and ld and rs is not None and has("M1_BEMF_DQ_KP_GAIN") and has("M1_BEMF_DQ_KI_GAIN") \
            and (flt or (e_max and i_max)):
        g = 1.0 if flt else e_max / i_max / _Q15
        kp, ki = v["M1_BEMF_DQ_KP_GAIN"] * g, v["M1_BEMF_DQ_KI_GAIN"] * g / ts
        if ki > 0:
            w0 = math.sqrt(ki / ld)
            out["bemf"] = {"kp_ohm": kp, "ki_ohm_per_s": ki, "natural_hz": w0 / (2.0 * math.pi),
                           "damping": (kp + rs) / (2.0 * w0 * ld)}
    return out or None


def decode_header(values: dict, notes: dict) -> dict:
    """NXP MCAT macros in SI, the design, the checks against the embedded JSON
    (:mod:`pulab.profiles.decoding`)."""
    v = values
    has = v.keys().__contains__
    # MCAT's floating-point variant stores SI floats (speeds in electrical rad/s)
    flt = isinstance(v.get("M1_I_SCALE", v.get("M1_D_KP_GAIN")), float)
    out = {n: macro(v[n], "rad/s" if flt and u == "rpm" else u, m, n)
           for n, (u, m) in _SCALES.items() if has(n)}
    checks: list = []
    design: dict = {"assumed": []}
    i_max, u_max = v.get("M1_I_MAX"), v.get("M1_U_MAX")
    pp = v.get("M1_MOTOR_PP")
    design["variant"] = "float" if flt else "fractional"
    q15 = 1.0 if flt else _Q15
    for n, (scale, unit, meaning, q) in _FRACTIONS.items():
        if not has(n):
            continue
        if flt:
            out[n] = macro(v[n], "rad/s" if unit == "rpm" else unit,
                           meaning + (" (electrical)" if unit == "rpm" else ""), n)
            continue
        frac = v[n] / q
        if scale is None:
            out[n] = macro(frac, unit, meaning, f"{n}/2^15")
        elif has(scale):
            out[n] = macro(frac * v[scale], unit, meaning, f"{n}/2^15·{scale}")
    w_max = v.get("M1_W_MAX")
    if w_max is None and has("M1_FREQ_MAX"):
        w_max = 2.0 * math.pi * v["M1_FREQ_MAX"]
    elif w_max is None and has("M1_N_MAX") and pp:
        w_max = v["M1_N_MAX"] if flt else 2.0 * math.pi * v["M1_N_MAX"] * pp / 60.0
    j = mcat_json(notes.get("", ()))
    design["mcat_inputs"] = j
    # the sample time: the tool's own input, else two constants that carry it
    ts, ts_from = None, None
    if j is not None and isinstance(j.get("currentLoop", {}).get("currentLoopSampleTime"),
                                    (int, float)):
        ts, ts_from = j["currentLoop"]["currentLoopSampleTime"], "MCAT JSON currentLoopSampleTime"
    f_max = w_max / (2.0 * math.pi) if w_max else None
    ts_integ = v["M1_SCALAR_INTEG_GAIN"] / _Q15 / (2.0 * f_max) \
        if has("M1_SCALAR_INTEG_GAIN") and f_max else None
    if flt:  # TO_THETA_GAIN = T_s/π
        ts_theta = v["M1_TO_THETA_GAIN"] * math.pi if has("M1_TO_THETA_GAIN") else None
    else:
        ts_theta = v["M1_TO_THETA_GAIN"] / _Q15 * 2.0 ** v["M1_TO_THETA_SHIFT"] * math.pi / w_max \
            if has("M1_TO_THETA_GAIN") and has("M1_TO_THETA_SHIFT") and w_max else None
    if ts is None:
        ts, ts_from = (ts_integ, "M1_SCALAR_INTEG_GAIN/(2·f_max)") if ts_integ else \
            (ts_theta, "M1_TO_THETA_GAIN·2^shift·π/ω_max") if ts_theta else (None, None)
    design["ts_s"], design["ts_from"] = ts, ts_from
    if ts_integ and ts_theta and abs(ts_theta / ts_integ - 1.0) > 0.01:
        checks.append(check("warning", "inconsistent", ["M1_SCALAR_INTEG_GAIN", "M1_TO_THETA_GAIN"],
                            what="T_s", a=ts_integ, a_from="M1_SCALAR_INTEG_GAIN",
                            b=ts_theta, b_from="M1_TO_THETA_GAIN",
                            diff=round(100.0 * (ts_theta / ts_integ - 1.0), 2)))
    if has("M1_SCALAR_INTEG_GAIN"):
        out["M1_SCALAR_INTEG_GAIN"] = macro(ts_integ, "s", "scalar mode angle step / (2·f_max)",
                                            "M1_SCALAR_INTEG_GAIN/2^15/(2·f_max)")
    # the motor from the observer scales
    motor: dict = {}
    if flt:
        a = v.get("M1_U_SCALE")
    else:
        a = v["M1_U_SCALE"] / _Q15 * i_max / u_max if has("M1_U_SCALE") and i_max and u_max \
            else None
    design["a_per_ohm"] = a
    if has("M1_I_SCALE") and a and a > 0 and ts:
        i_scale = v["M1_I_SCALE"] / q15
        motor["ld_h"] = i_scale * ts / a
        motor["rs_ohm"] = (1.0 - i_scale) / a
        out["M1_U_SCALE"] = macro(a, "1/Ω", "observer: T_s/(L_d + T_s·R_s)",
                                  "M1_U_SCALE" if flt else "M1_U_SCALE/2^15·I_max/U_max")
        if has("M1_WI_SCALE") and (w_max or flt):
            motor["lq_h"] = v["M1_WI_SCALE"] / a if flt else v["M1_WI_SCALE"] / _Q15 / (a * w_max)
            out["M1_WI_SCALE"] = macro(motor["lq_h"], "H", "observer: L_q·T_s/(L_d + T_s·R_s)"
                                       + ("" if flt else "·ω_max") + " → L_q",
                                       "M1_WI_SCALE/a" if flt else "M1_WI_SCALE/2^15/(a·ω_max)")
        if has("M1_E_SCALE") and (flt or v.get("M1_E_MAX")):
            e = v["M1_E_SCALE"] if flt else v["M1_E_SCALE"] / _Q15 * i_max / v["M1_E_MAX"]
            if abs(e / a - 1.0) > 0.01:
                checks.append(check("warning", "inconsistent", ["M1_E_SCALE", "M1_U_SCALE"],
                                    what="T_s/(L_d + T_s·R_s)", a=a, a_from="M1_U_SCALE",
                                    b=e, b_from="M1_E_SCALE",
                                    diff=round(100.0 * (e / a - 1.0), 2)))
    if pp:
        motor["pole_pairs"] = int(pp)
    # the current PI; MCAT's trapezoidal k = 2 unless its JSON says otherwise
    k = 2.0
    expected = {}
    if j is not None:
        e1, e2 = _expected(j, 1.0, flt), _expected(j, 2.0, flt)
        miss = [sum(abs(v[n] - x) / abs(x) if f is None else abs(v[n] - f(x))
                    for n, (x, f, _) in e.items()
                    if n in ("M1_D_KI_GAIN", "M1_Q_KI_GAIN") and has(n)) for e in (e1, e2)]
        k = 1.0 if miss[0] < miss[1] else 2.0
        expected = e1 if k == 1.0 else e2
    else:
        design["assumed"].append("ki = K_i·U_max/I_max·2/T_s: MCAT's trapezoidal integrator")
    loops = {}
    for axis, l_key in (("d", "ld_h"), ("q", "lq_h")):
        kp_n, ki_n = f"M1_{axis.upper()}_KP_GAIN", f"M1_{axis.upper()}_KI_GAIN"
        if not (has(kp_n) and has(ki_n) and ts and (flt or (i_max and u_max))):
            continue
        g = 1.0 if flt else u_max / i_max / _Q15
        kp, ki = v[kp_n] * g, v[ki_n] * g * k / ts
        scaled = "" if flt else "/2^15·U_max/I_max"
        out[kp_n] = macro(kp, "V/A", f"current PI kp, {axis} axis", f"{kp_n}{scaled}")
        out[ki_n] = macro(ki, "V/(A·s)", f"current PI ki, {axis} axis",
                          f"{ki_n}{scaled}·{k:g}/T_s")
        l = motor.get(l_key)
        c = current_loop(kp, ki, motor["rs_ohm"], l, (kp_n, ki_n)) if l and "rs_ohm" in motor else None
        if c is not None:
            w0 = math.sqrt(ki / l) if ki > 0 else None
            c["mcat_f0_hz"] = w0 / (2.0 * math.pi) if w0 else None
            c["mcat_ksi"] = (kp + motor["rs_ohm"]) / (2.0 * w0 * l) if w0 else None
            # MCAT's design is ω0, not a crossover: its closed loop has ω_n = ω0
            if c["mcat_f0_hz"]:
                c["bandwidth_hz"] = c["mcat_f0_hz"]
            loops[axis] = c
    design["current_loop"] = loops or None
    speed = None
    if has("M1_SPEED_PI_PROP_GAIN") and (flt or (i_max and w_max)):
        g = 1.0 if flt else i_max / w_max / _Q15
        speed = {"kp_a_per_rad_s": v["M1_SPEED_PI_PROP_GAIN"] * g}
        if has("M1_SPEED_PI_INTEG_GAIN"):
            ki_per_sample = v["M1_SPEED_PI_INTEG_GAIN"] * g
            tsp = (j or {}).get("speedLoop", {}).get("speedLoopSampleTime")
            speed["ki_a_per_rad_s_per_sample"] = ki_per_sample
            speed["ki_a_per_rad"] = ki_per_sample * k / tsp if isinstance(tsp, (int, float)) \
                else None
            scaled = "" if flt else "/2^15·I_max/ω_max"
            out["M1_SPEED_PI_INTEG_GAIN"] = (
                macro(speed["ki_a_per_rad"], "A/rad", "speed PI ki (electrical rad)",
                      f"M1_SPEED_PI_INTEG_GAIN{scaled}·{k:g}/T_speed (T_speed: the MCAT JSON)")
                if speed["ki_a_per_rad"] is not None else
                macro(ki_per_sample, "A/(rad/s)", "speed PI ki per speed-loop sample",
                      f"M1_SPEED_PI_INTEG_GAIN{scaled}"))
        out["M1_SPEED_PI_PROP_GAIN"] = macro(speed["kp_a_per_rad_s"], "A/(rad/s)",
                                             "speed PI kp (electrical rad/s)",
                                             "M1_SPEED_PI_PROP_GAIN"
                                             + ("" if flt else "/2^15·I_max/ω_max"))
    design["speed_loop"] = speed
    if speed is not None and speed.get("ki_a_per_rad"):
        # the mechanics only the JSON states: Kt [N·m/A] and J [kg·m²] → el. rad/s² per A
        p = (j or {}).get("parameters", {})
        kt, jm = p.get("parametersKt"), p.get("parametersJ")
        if isinstance(kt, (int, float)) and isinstance(jm, (int, float)) and jm > 0 and pp:
            speed["plant_rad_s2_per_a"] = pp * kt / jm
            speed.update(integrator_loop(speed["kp_a_per_rad_s"], speed["ki_a_per_rad"],
                                         speed["plant_rad_s2_per_a"]) or {})
    design["observer"] = _observer(v, flt, ts, ts_theta, w_max, i_max, motor)
    # the JSON: every constant it determines, again, in LSB (a float: relative, 6 digits printed)
    for n, (x, f, per) in expected.items():
        if not has(n):
            continue
        if f is None:
            rel = (v[n] - x) / x if x else (1.0 if v[n] else 0.0)
            if abs(rel) > 1e-5:
                checks.append(check("warning", "json_float", [n], macro=n, value=v[n],
                                    expected=x, diff=round(100.0 * rel, 4)))
            continue
        want = f(x)
        delta = v[n] - want
        bound = max(1.0, abs(x) * per * 5e-6)  # MCAT prints 6 significant digits
        if abs(delta) > bound:
            checks.append(check("warning", "json", [n], macro=n, value=v[n], expected=want,
                                diff=delta))
    design["json_checked"] = sorted(n for n in expected if has(n))
    for n in _GAINS + ("M1_SPEED_PI_PROP_GAIN", "M1_SPEED_PI_INTEG_GAIN"):
        if not (isinstance(v.get(n), int) and v[n]):
            continue
        if n in expected and expected[n][1] is not None:
            # the JSON's inputs give the value the integer truncates
            x = expected[n][0] * expected[n][2]
            if x and abs(x - v[n]) / abs(x) > 0.01:
                checks.append(check("warning", "rounding", [n], "", macro=n, value=v[n],
                                    ideal=f"{x:.4f}", err=round(100.0 * (v[n] - x) / x, 2)))
        elif 1.0 / abs(v[n]) > 0.01:  # ACC32 truncates: up to 1 LSB lost
            checks.append(check("warning", "rounding", [n], "", macro=n, value=v[n],
                                ideal=f"{n} + [0, 1) LSB", err=round(100.0 / abs(v[n]), 2)))
    drive: dict = {}
    if ts:
        drive["ts_s"] = ts
    if has("M1_U_DCB_MAX"):
        drive["udc_v"] = float(v["M1_U_DCB_MAX"])
        design["assumed"].append("drive.udc_v = M1_U_DCB_MAX (the bus scale)")
    if j is not None:
        p = j["parameters"]
        for key, name in (("rated_current_a", "parametersIphNom"),
                          ("bemf_v", None), ("rated_voltage_v", "parametersUphNom")):
            if name and isinstance(p.get(name), (int, float)):
                motor[key] = float(p[name])
        if isinstance(p.get("parametersNnom"), (int, float)) and pp:
            motor["rated_freq_hz"] = p["parametersNnom"] * pp / 60.0
    design["input"] = {"motor": motor, "drive": drive}
    opt = {}
    if has("M1_U_DCB_MAX"):
        opt["udcb_max_v"] = float(v["M1_U_DCB_MAX"])
    if i_max:
        opt["i_max_a"] = float(i_max)
    if has("M1_E_MAX"):
        opt["e_max_v"] = float(v["M1_E_MAX"])
    opt["trapezoidal"] = k == 2.0
    design["input"]["profiles"] = {"nxp": opt}
    if loops:
        q = loops.get("q") or loops.get("d")
        design["input"]["current_loop"] = {"method": "manual", "kp": q["kp_v_per_a"],
                                           "ki": q["ki_v_per_a_s"]}
    return result(READS, "arm", out, design, checks)
