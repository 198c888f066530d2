"""ST MCSDK's generated parameter set read back (``decode_header``).

The files (Motor Control Workbench output, e.g. ``dronectl/g431-mcsdk : Inc/``):
``pmsm_motor_parameters.h`` (RS, LS, POLE_PAIR_NUM, MOTOR_VOLTAGE_CONSTANT in V rms
line-to-line per krpm, NOMINAL_CURRENT in digits), ``drive_parameters.h`` (PWM_FREQUENCY,
REGULATION_EXECUTION_RATE, the PI integers and their power-of-two divisors, the observer
and PLL gains), ``power_stage_parameters.h`` (RSHUNT, AMPLIFICATION_GAIN,
VBUS_PARTITIONING_FACTOR) and ``parameters_conversion.h`` (CURRENT_CONV_FACTOR, MAX_CURRENT,
C1…C5 computed from the others). Scales as in :mod:`pulab.profiles.st.scaling`: a current
digit is MAX_CURRENT/32768 = (V_ref/2)/(R_shunt·G)/32768 A (the NOMINAL_CURRENT comment's
formula), a voltage digit (U_dc/√3)/32768 V (pulab's assumption: full modulation), the
current PI ``Kp·e/KPDIV + ΣKi·e/KIDIV`` once per FOC period T = REGULATION_EXECUTION_RATE /
PWM_FREQUENCY.

Examples
--------
>>> d = decode_header({"RS": 0.35, "LS": 0.0006, "PWM_FREQUENCY": 20000,
...                    "REGULATION_EXECUTION_RATE": 1, "PID_TORQUE_KP_DEFAULT": 2312,
...                    "PID_TORQUE_KI_DEFAULT": 2158, "TF_KPDIV": 128, "TF_KIDIV": 4096}, {})
>>> round(d["design"]["ki_over_kp_per_sample"], 5), round(0.35 * 5e-5 / 0.0006, 5)
(0.02917, 0.02917)
"""

from __future__ import annotations

import math

from ..common import SQRT2, SQRT3
from ..decoding import check, current_loop, integrator_loop, macro, result

__all__ = ["decode_header"]

#: name → (unit, meaning) for the macros read as they are (an SI number already).
_PLAIN = {
    "RS": ("Ω", "stator resistance, phase"),
    "LS": ("H", "stator inductance (L_q for an IPM)"),
    "POLE_PAIR_NUM": ("", "pole pairs"),
    "MOTOR_VOLTAGE_CONSTANT": ("V/krpm", "back-EMF constant, V rms line-to-line per krpm"),
    "MOTOR_MAX_SPEED_RPM": ("rpm", "motor's maximum rated speed, mechanical"),
    "MAX_APPLICATION_SPEED_RPM": ("rpm", "application's maximum speed, mechanical"),
    "PWM_FREQUENCY": ("Hz", "PWM frequency"),
    "REGULATION_EXECUTION_RATE": ("", "PWM periods per FOC period"),
    "SPEED_LOOP_FREQUENCY_HZ": ("Hz", "speed-loop rate"),
    "RSHUNT": ("Ω", "shunt resistor"),
    "AMPLIFICATION_GAIN": ("V/V", "current amplifier gain"),
    "VBUS_PARTITIONING_FACTOR": ("", "bus divider ratio (V at the ADC / V on the bus)"),
    "NOMINAL_BUS_VOLTAGE_V": ("V", "nominal DC-bus voltage"),
    "ADC_REFERENCE_VOLTAGE": ("V", "ADC reference"),
    "OV_VOLTAGE_THRESHOLD_V": ("V", "over-voltage threshold"),
    "UD_VOLTAGE_THRESHOLD_V": ("V", "under-voltage threshold"),
    "MAX_CURRENT": ("A", "current at 32768 digits: V_ref/(2·R_shunt·G)"),
    "TF_KPDIV": ("", "current PI Kp divisor"), "TF_KIDIV": ("", "current PI Ki divisor"),
    "SP_KPDIV": ("", "speed PI Kp divisor"), "SP_KIDIV": ("", "speed PI Ki divisor"),
    "PLL_KPDIV": ("", "PLL Kp divisor"), "PLL_KIDIV": ("", "PLL Ki divisor"),
    "F1": ("", "observer scaling F1"), "F2": ("", "observer scaling F2"),
    "GAIN1": ("", "observer gain K1 (digits)"), "GAIN2": ("", "observer gain K2 (digits)"),
    "PLL_KP_GAIN": ("", "PLL Kp (digits)"), "PLL_KI_GAIN": ("", "PLL Ki (digits)"),
    "MAX_VOLTAGE": ("V", "bus voltage at full ADC scale over √3: (V_ref/√3)/divider"),
    "MAX_BEMF_VOLTAGE": ("V", "back-EMF peak phase at 1.2 × the maximum speed"),
    "C1": ("", "observer constant F1·RS/(LS·f_reg)"), "C3": ("", "observer constant C3"),
    "C5": ("", "observer constant C5"),
    "TF_REGULATION_RATE": ("Hz", "FOC rate f_reg = PWM_FREQUENCY/REGULATION_EXECUTION_RATE"),
    "CURRENT_CONV_FACTOR": ("digit/A", "(uint16_t)(65536·R_shunt·G/V_ref)"),
    "PWM_PERIOD_CYCLES": ("tick", "PWM period in timer ticks (even)"),
    "ADV_TIM_CLK_MHz": ("MHz", "advanced timer clock"),
    "SW_DEADTIME_NS": ("ns", "dead time the software inserts"),
}
_CURRENTS = ("NOMINAL_CURRENT", "IQMAX", "ID_DEMAG")
_GAINS = ("PID_TORQUE_KP_DEFAULT", "PID_TORQUE_KI_DEFAULT", "PID_FLUX_KP_DEFAULT",
          "PID_FLUX_KI_DEFAULT")
_SPEED = ("PID_SPEED_KP_DEFAULT", "PID_SPEED_KI_DEFAULT")
READS = tuple(_PLAIN) + _CURRENTS + _GAINS + _SPEED


def _speed_loop(v: dict, i_digit: float | None, out: dict) -> dict | None:
    """The speed PI in SI: the error is in 1/``SPEED_UNIT`` Hz of mechanical speed (MCSDK's
    ``mc_stm_types.h``: 10 for 0.1 Hz; the file leaves it to that library, so it must be given,
    ``-D SPEED_UNIT=10``), the output in current digits, Ki once per speed-loop period:
    kp = KP/SP_KPDIV·i_digit·SPEED_UNIT/2π [A/(rad/s)], ki = KI/SP_KIDIV·i_digit·SPEED_UNIT/2π·
    f_speed [A/rad]. The files hold no inertia, so no bandwidth."""
    has = v.keys().__contains__
    if not (all(map(has, _SPEED + ("SPEED_UNIT", "SPEED_LOOP_FREQUENCY_HZ")))
            and v.get("SP_KPDIV") and v.get("SP_KIDIV") and i_digit):
        return None
    per = i_digit * v["SPEED_UNIT"] / (2.0 * math.pi)
    kp = v["PID_SPEED_KP_DEFAULT"] / v["SP_KPDIV"] * per
    ki = v["PID_SPEED_KI_DEFAULT"] / v["SP_KIDIV"] * per * v["SPEED_LOOP_FREQUENCY_HZ"]
    out["PID_SPEED_KP_DEFAULT"] = macro(kp, "A/(rad/s)", "speed PI kp (mechanical rad/s)",
                                        "PID_SPEED_KP_DEFAULT/SP_KPDIV·(V_ref/2)/(32767·R_shunt·G)"
                                        "·SPEED_UNIT/2π")
    out["PID_SPEED_KI_DEFAULT"] = macro(ki, "A/rad", "speed PI ki (mechanical rad)",
                                        "PID_SPEED_KI_DEFAULT/SP_KIDIV·(V_ref/2)/(32767·R_shunt·G)"
                                        "·SPEED_UNIT/2π·SPEED_LOOP_FREQUENCY_HZ")
    return {"kp_a_per_rad_s": kp, "ki_a_per_rad": ki, "zero_rad_s": ki / kp if kp else None,
            "period_s": 1.0 / v["SPEED_LOOP_FREQUENCY_HZ"], "macros": list(_SPEED)}


def decode_header(values: dict, notes: dict) -> dict:
    """ST MCSDK macros in SI, the design, and the checks (:mod:`pulab.profiles.decoding`)."""
    v = values
    out = {n: macro(v[n], u, m, n) for n, (u, m) in _PLAIN.items() if n in v}
    design: dict = {"input": {}, "assumed": []}
    checks: list = []
    has = v.keys().__contains__
    # digits per ampere: the NOMINAL_CURRENT comment's formula (32767 at (V_ref/2)/(R·G))
    i_digit = None
    if all(map(has, ("RSHUNT", "AMPLIFICATION_GAIN", "ADC_REFERENCE_VOLTAGE"))):
        i_max = v["ADC_REFERENCE_VOLTAGE"] / (2.0 * v["RSHUNT"] * v["AMPLIFICATION_GAIN"])
        i_digit = i_max / 32767.0
        design["max_current_a"] = i_max
        for n in _CURRENTS:
            if has(n):
                out[n] = macro(v[n] * i_digit, "A", "current, 0-to-peak (digits)",
                               f"{n}·(V_ref/2)/(32767·R_shunt·G)")
    ts = None
    if has("PWM_FREQUENCY") and has("REGULATION_EXECUTION_RATE"):
        ts = v["REGULATION_EXECUTION_RATE"] / v["PWM_FREQUENCY"]
        design["ts_s"] = ts
    r, l, pp = v.get("RS"), v.get("LS"), v.get("POLE_PAIR_NUM")
    motor: dict = {}
    if r is not None:
        motor["rs_ohm"] = r
    if l is not None:
        motor["ld_h"] = motor["lq_h"] = l
        design["assumed"].append("motor.ld_h = LS (the file gives one inductance)")
    if pp is not None:
        motor["pole_pairs"] = int(pp)
    rpm = v.get("MAX_APPLICATION_SPEED_RPM", v.get("MOTOR_MAX_SPEED_RPM"))
    if pp and rpm:
        motor["rated_freq_hz"] = rpm * pp / 60.0
    ke = v.get("MOTOR_VOLTAGE_CONSTANT")
    if ke and pp:
        # V rms line-to-line per krpm → ψ = E_peak,phase/ω_e
        psi = ke * SQRT2 / SQRT3 / (1000.0 * 2.0 * math.pi / 60.0 * pp)
        design["psi_wb"] = psi
        out["MOTOR_VOLTAGE_CONSTANT"]["formula"] = "ψ = Ke·√2/√3/(1000·2π/60·pp)"
        if rpm:
            motor["bemf_v"] = ke * rpm / 1000.0
            motor["rated_voltage_v"] = motor["bemf_v"]
            design["assumed"].append("motor.rated_voltage_v = the back-EMF at the maximum "
                                     "speed (the files give no rated voltage)")
    if has("NOMINAL_CURRENT") and i_digit:
        motor["rated_current_a"] = v["NOMINAL_CURRENT"] * i_digit / SQRT2
    drive: dict = {}
    if has("NOMINAL_BUS_VOLTAGE_V"):
        drive["udc_v"] = float(v["NOMINAL_BUS_VOLTAGE_V"])
    if ts:
        drive["ts_s"] = ts
    design["input"] = {"motor": motor, "drive": drive}
    board: dict = {}
    if has("RSHUNT") and has("AMPLIFICATION_GAIN"):
        board["current"] = {"shunt_ohm": v["RSHUNT"], "gain": v["AMPLIFICATION_GAIN"]}
        if has("ADC_REFERENCE_VOLTAGE"):
            board["current"]["adc_ref_v"] = v["ADC_REFERENCE_VOLTAGE"]
    if has("VBUS_PARTITIONING_FACTOR"):
        board["bus"] = {"ratio": v["VBUS_PARTITIONING_FACTOR"]}
    if has("PWM_FREQUENCY"):
        board["pwm"] = {"freq_hz": float(v["PWM_FREQUENCY"]),
                        "periods_per_control": int(v.get("REGULATION_EXECUTION_RATE", 1))}
        if has("ADV_TIM_CLK_MHz"):
            board["pwm"]["clock_hz"] = v["ADV_TIM_CLK_MHz"] * 1e6
        if has("SW_DEADTIME_NS"):
            board["pwm"]["deadtime_s"] = v["SW_DEADTIME_NS"] * 1e-9
    if board:
        design["input"]["board"] = board
    opt = {k: v[n] for k, n in (("adc_reference_v", "ADC_REFERENCE_VOLTAGE"),
                                ("amplification_gain", "AMPLIFICATION_GAIN"),
                                ("rshunt_ohm", "RSHUNT"),
                                ("vbus_partitioning_factor", "VBUS_PARTITIONING_FACTOR"),
                                ("tf_kpdiv", "TF_KPDIV"), ("tf_kidiv", "TF_KIDIV"), ("f1", "F1"))
           if has(n)}
    if opt:
        design["input"]["profiles"] = {"st": opt}
    # the current PI: per unit of (voltage digit / current digit), Ki per FOC period
    loops = {}
    for axis, w in (("d", "FLUX"), ("q", "TORQUE")):
        kp_n, ki_n = f"PID_{w}_KP_DEFAULT", f"PID_{w}_KI_DEFAULT"
        if not (has(kp_n) and has(ki_n) and v.get("TF_KPDIV") and v.get("TF_KIDIV")):
            continue
        for n in (kp_n, ki_n):
            if not -32768 <= v[n] <= 32767:
                checks.append(check("error", "overflow", [n], macro=n, value=v[n], ideal=v[n],
                                    ctype="int16_t (hKpGain/hKiGain)"))
            elif v[n] and 0.5 / abs(v[n]) > 0.01:
                checks.append(check("warning", "rounding", [n], macro=n, value=v[n],
                                    ideal=f"{v[n]} ± 0.5", err=round(50.0 / abs(v[n]), 2)))
        kp_pu = v[kp_n] / v["TF_KPDIV"]
        ki_pu = v[ki_n] / v["TF_KIDIV"]
        out[kp_n] = macro(kp_pu, "digit/digit", f"current PI Kp, {axis} axis", f"{kp_n}/TF_KPDIV")
        out[ki_n] = macro(ki_pu, "digit/digit", f"current PI Ki per FOC period, {axis} axis",
                          f"{ki_n}/TF_KIDIV")
        if axis == "q":
            design["ki_over_kp_per_sample"] = ki_pu / kp_pu if kp_pu else None
        if i_digit and ts and has("NOMINAL_BUS_VOLTAGE_V") and r and l:
            v_digit = v["NOMINAL_BUS_VOLTAGE_V"] / SQRT3 / 32768.0
            kp = kp_pu * v_digit / (i_digit * 32767.0 / 32768.0)
            ki = ki_pu * v_digit / (i_digit * 32767.0 / 32768.0) / ts
            out[kp_n].update(si=kp, unit="V/A", formula=f"{kp_n}/TF_KPDIV·(U_dc/√3)/MAX_CURRENT")
            out[ki_n].update(si=ki, unit="V/(A·s)",
                             formula=f"{ki_n}/TF_KIDIV·(U_dc/√3)/MAX_CURRENT/T")
            c = current_loop(kp, ki, r, l, (kp_n, ki_n))
            if c is not None:
                loops[axis] = c
    if r and l and ts and "ki_over_kp_per_sample" in design and design["ki_over_kp_per_sample"]:
        # the Workbench places the PI zero on the plant pole: Ki/Kp (per sample) = R·T/L
        want = r * ts / l
        got = design["ki_over_kp_per_sample"]
        if abs(got / want - 1.0) > 0.01:
            checks.append(check("warning", "inconsistent", _GAINS[:2] + ("RS", "LS"),
                                "regenerate the gains after changing RS or LS",
                                what="PI zero vs plant pole (Ki/Kp per sample)",
                                a=round(got, 6), a_from="PID_TORQUE_KI/KP·KPDIV/KIDIV",
                                b=round(want, 6), b_from="RS·T/LS",
                                diff=round(100.0 * (got / want - 1.0), 2)))
    if loops:
        design["assumed"].append("a voltage digit is (U_dc/√3)/32768 (pu-lab's assumption, not "
                                 "read in a public file): kp, ki and the bandwidth in SI follow "
                                 "it; Ki/Kp per sample does not")
    design["current_loop"] = loops or None
    if loops:
        design["input"]["current_loop"] = {"method": "manual",
                                           "kp": loops["q" if "q" in loops else "d"]["kp_v_per_a"],
                                           "ki": loops["q" if "q" in loops else "d"]["ki_v_per_a_s"]}
    design["speed_loop"] = _speed_loop(v, i_digit, out)
    design["observer"] = _pll(v, ts, rpm)
    return result(READS, "arm", out, design, checks)


def _pll(v: dict, ts: float | None, rpm: float | None) -> dict | None:
    """The state observer's PLL (MCSDK ``sto_pll_speed_pos_fdbk.c``, ``STO_ExecutePLL``): its
    error is e_β·cos θ̂ − e_α·sin θ̂ = E·sin(θ − θ̂) in back-EMF digits (32768 per
    ``MAX_BEMF_VOLTAGE`` volts, the scale ``C3`` gives the observer), its PI
    (Kp·e/PLL_KPDIV + ΣKi·e/PLL_KIDIV) is the speed in angle digits (65536 per turn) per FOC
    period. So the loop gain grows with the back-EMF: at the maximum application speed,
    g = E_digits·2π/65536 and kp = Kp/PLL_KPDIV·g/T [1/s], ki = Ki/PLL_KIDIV·g/T² [1/s²]
    (:func:`pulab.profiles.decoding.integrator_loop`, k = 1); at half the speed, half of both."""
    has = v.keys().__contains__
    if not (has("PLL_KP_GAIN") and has("PLL_KI_GAIN") and v.get("PLL_KPDIV")
            and v.get("PLL_KIDIV")):
        return None
    kp, ki = v["PLL_KP_GAIN"] / v["PLL_KPDIV"], v["PLL_KI_GAIN"] / v["PLL_KIDIV"]
    out = {"pll_kp": kp, "pll_ki": ki}
    ke, e_fs = v.get("MOTOR_VOLTAGE_CONSTANT"), v.get("MAX_BEMF_VOLTAGE")
    if not (ts and rpm and ke and e_fs):
        return out
    # Ke is V rms line-to-line per krpm: the observer's back-EMF is the phase peak
    e_digits = 32768.0 * ke * rpm / 1000.0 * SQRT2 / SQRT3 / e_fs
    g = e_digits * 2.0 * math.pi / 65536.0
    out["tracking"] = {"at_speed_rpm": float(rpm), "bemf_digits": e_digits,
                       "kp_per_s": kp * g / ts, "ki_per_s2": ki * g / ts ** 2,
                       **(integrator_loop(kp * g / ts, ki * g / ts ** 2, 1.0) or {})}
    return out

