"""TI's ``user_mtr1.h`` (C2000Ware Motor Control SDK, universal motor control lab) and
MotorWare's ``user.h`` read back (``decode_header``).

The universal lab keeps the motor in SI floats (``USER_MOTOR1_Rs_Ohm``, ``…_Ls_d_H``,
``…_RATED_FLUX_VpHz``: the peak phase back-EMF per electrical Hz, so ψ = flux/(2π)) and the
board as ADC full scales (``USER_M1_ADC_FULL_SCALE_CURRENT_A``: the whole ADC range, ±half
of it; ``…_VOLTAGE_V``). Its PIs are computed at run time from these macros, and the design
reproduces that computation (``anyway-blows/ti-c2000-motor-control-sdk :
solutions/universal_motorcontrol_lab/common/source/motor_common.c``, ``setupControllers``, and
``…/user_mtr1.c``, ``USER_setMotor1Params``, with ``flag_bypassMotorId = true`` as
``…/sys_main.c`` sets it): BW_c = 2π·400 rad/s and δ = 10 — the AM26x SDK's copy of the lab
(``TexasInstruments/motor-control-sdk : examples/tidm_02018_universal_motorcontrol/
universal_motorcontrol/src_board/user_mtr1.c``; told apart by its speed-gain schedule macros
``USER_MOTOR1_KP_SPD_HIGH_SF``) sets 2π·200 rad/s and δ = 20 —, the current PI (series form of
``libraries/control/pi/include/pi.h``: U_i += Ki·Kp·e, so ki = Kp·Ki/T)

    Kp = L·BW_c [V/A],  Ki = 0.25·(R/L)·T_cur,  i.e. ki = 0.25·R·BW_c [V/(A·s)]

(T_cur = ``USER_M1_NUM_ISR_TICKS_PER_CURRENT_TICK``/``USER_M1_ISR_FREQ_Hz``: the zero sits at a
quarter of the plant pole, on purpose), and the speed PI (speed in electrical Hz, current in A)

    K_ctrl = 3·pp·ψ/(2·J),  Kp = BW_c/(δ·K_ctrl) [A/Hz],  Ki = BW_c·T_spd/δ²

(T_spd = ``…_PER_SPEED_TICK``/``USER_M1_ISR_FREQ_Hz``; when K_ctrl ≤ 0.01 the lab uses
Kp = 2.5·I_max/f_max, Ki = 5·I_max·T instead). MotorWare's ``user.h`` stores IQ24 gains
(series form: kp = Kp/2^Q·V_FS/I_FS, ki = kp·Ki/2^Q/T;
:func:`pulab.profiles.ti.scaling.ints_to_gains`), read as they are.

The files select the board and the motor with ``#if``: the board by a compiler ``-D``
(``BSXL8323RS_REVA`` …), the motor by ``USER_MOTOR1`` compared with ids that
``user_common.h`` defines — without that file every id is 0 and the first motor is read.

A flux comment in V/krpm is checked against every reading of the flux at the file's pole
pairs (phase or line, peak or rms; ψ or ψ·2π): ``comment_value`` when none is within 2 %.

Examples
--------
>>> d = decode_header({"USER_MOTOR1_NUM_POLE_PAIRS": 2, "USER_MOTOR1_RATED_FLUX_VpHz": 0.560590863},
...                   {"USER_MOTOR1_RATED_FLUX_VpHz": "4.11V/krpm"})
>>> d["checks"][0][1], round(d["design"]["psi_wb"], 6)
('comment_value', 0.089221)
"""

from __future__ import annotations

import math

from ..common import SQRT2, SQRT3
from ..decoding import check, current_loop, integrator_loop, macro, numbers_in, result

__all__ = ["decode_header"]

_PLAIN = {
    "USER_MOTOR1_NUM_POLE_PAIRS": ("", "pole pairs"),
    "USER_MOTOR1_Rs_Ohm": ("Ω", "stator resistance, phase"),
    "USER_MOTOR1_Ls_d_H": ("H", "d-axis inductance"),
    "USER_MOTOR1_Ls_q_H": ("H", "q-axis inductance"),
    "USER_MOTOR1_RATED_FLUX_VpHz": ("V/Hz", "rated flux: peak phase back-EMF per electrical Hz"),
    "USER_MOTOR1_MAX_CURRENT_A": ("A", "maximum current, peak"),
    "USER_MOTOR1_RATED_VOLTAGE_V": ("V", "rated voltage"),
    "USER_MOTOR1_RATED_SPEED_KRPM": ("krpm", "rated speed"),
    "USER_MOTOR1_FREQ_MAX_HZ": ("Hz", "maximum electrical frequency"),
    "USER_MOTOR1_FREQ_MAX_Hz": ("Hz", "maximum electrical frequency (AM26x SDK's spelling)"),
    "USER_MOTOR1_INERTIA_Kgm2": ("kg·m²", "inertia"),
    "USER_M1_NOMINAL_DC_BUS_VOLTAGE_V": ("V", "nominal DC bus"),
    "USER_M1_ADC_FULL_SCALE_VOLTAGE_V": ("V", "voltage at the full ADC range"),
    "USER_M1_ADC_FULL_SCALE_CURRENT_A": ("A", "current over the full ADC range (±half)"),
    "USER_M1_PWM_FREQ_kHz": ("kHz", "PWM frequency"),
    "USER_M1_NUM_PWM_TICKS_PER_ISR_TICK": ("", "PWM periods per interrupt"),
    "USER_M1_CTRL_PERIOD_sec": ("s", "control period"),
    "USER_M1_ISR_FREQ_Hz": ("Hz", "interrupt (control) rate"),
    "USER_M1_CURRENT_SF": ("A/count", "ADC_FULL_SCALE_CURRENT_A/4096"),
    "USER_M1_VOLTAGE_SF": ("V/count", "ADC_FULL_SCALE_VOLTAGE_V/4096"),
    "USER_M1_MAX_VS_MAG_PU": ("", "voltage vector limit, per unit of the bus"),
    "USER_M1_PWM_TBPRD_NUM": ("tick", "PWM period register (up-down)"),
    # MotorWare user.h, and pu-lab's TI header
    "USER_IQ_FULL_SCALE_VOLTAGE_V": ("V", "per-unit voltage base"),
    "USER_IQ_FULL_SCALE_CURRENT_A": ("A", "per-unit current base"),
    "USER_IQ_FULL_SCALE_FREQ_Hz": ("Hz", "per-unit frequency base"),
    "USER_CTRL_PERIOD_sec": ("s", "control period"),
    "GLOBAL_Q": ("", "IQmath Q"),
    "USER_MOTOR_NUM_POLE_PAIRS": ("", "pole pairs"),
    "USER_MOTOR_Rs": ("Ω", "stator resistance"), "USER_MOTOR_Ls_d": ("H", "d-axis inductance"),
    "USER_MOTOR_Ls_q": ("H", "q-axis inductance"),
    "USER_MOTOR_RATED_FLUX": ("V/Hz", "rated flux"),
    "USER_MOTOR_MAX_CURRENT": ("A", "maximum current, peak"),
}
#: The same quantity under the universal lab's name and MotorWare's (pu-lab's header).
_ALIASES = {"pp": ("USER_MOTOR1_NUM_POLE_PAIRS", "USER_MOTOR_NUM_POLE_PAIRS"),
            "rs": ("USER_MOTOR1_Rs_Ohm", "USER_MOTOR_Rs"),
            "ld": ("USER_MOTOR1_Ls_d_H", "USER_MOTOR_Ls_d"),
            "lq": ("USER_MOTOR1_Ls_q_H", "USER_MOTOR_Ls_q"),
            "flux": ("USER_MOTOR1_RATED_FLUX_VpHz", "USER_MOTOR_RATED_FLUX"),
            "imax": ("USER_MOTOR1_MAX_CURRENT_A", "USER_MOTOR_MAX_CURRENT"),
            "ts": ("USER_M1_CTRL_PERIOD_sec", "USER_CTRL_PERIOD_sec")}
_GAINS = {"d": ("USER_MTR1_KP_ID_IQ", "USER_MTR1_KI_ID_IQ"),
          "q": ("USER_MTR1_KP_IQ_IQ", "USER_MTR1_KI_IQ_IQ")}
READS = tuple(_PLAIN) + tuple(n for pair in _GAINS.values() for n in pair) + (
    "USER_M1_NUM_ISR_TICKS_PER_CURRENT_TICK", "USER_M1_NUM_ISR_TICKS_PER_SPEED_TICK")
#: The universal lab's run-time design with the motor from the header (user_mtr1.c:
#: flag_bypassMotorId true): SDK → (the current bandwidth BW_c [rad/s], the speed loop's δ, the
#: macro that marks that SDK's user_mtr1.h or None).
RUNTIME = {"C2000 MotorControl SDK": (2.0 * math.pi * 400.0, 10.0, None),
           "AM26x motor-control-sdk": (2.0 * math.pi * 200.0, 20.0, "USER_MOTOR1_KP_SPD_HIGH_SF")}


def _runtime(v: dict, motor: dict, psi: float | None) -> tuple:
    """(current loops, speed loop) the universal lab computes at run time from the header."""
    f = v.get("USER_M1_ISR_FREQ_Hz")
    if not f or "rs_ohm" not in motor:
        return {}, None
    sdk = next((k for k, (_, _, mark) in RUNTIME.items() if mark and mark in v),
               "C2000 MotorControl SDK")
    bwc, delta, _ = RUNTIME[sdk]
    t_cur = v.get("USER_M1_NUM_ISR_TICKS_PER_CURRENT_TICK", 1) / f
    names = ["USER_MOTOR1_Rs_Ohm", "USER_M1_ISR_FREQ_Hz"]
    loops = {}
    for axis, key, name in (("d", "ld_h", "USER_MOTOR1_Ls_d_H"), ("q", "lq_h", "USER_MOTOR1_Ls_q_H")):
        if key not in motor:
            continue
        l = motor[key]
        kp = l * bwc
        ki_series = 0.25 * motor["rs_ohm"] / l * t_cur
        c = current_loop(kp, kp * ki_series / t_cur, motor["rs_ohm"], l, [name] + names)
        if c is not None:
            c["runtime"] = {"sdk": sdk, "bwc_rad_s": bwc, "kp": kp, "ki_series": ki_series,
                            "period_s": t_cur}
            loops[axis] = c
    j, pp = v.get("USER_MOTOR1_INERTIA_Kgm2"), motor.get("pole_pairs")
    t_spd = v.get("USER_M1_NUM_ISR_TICKS_PER_SPEED_TICK", 1) / f
    if not (j and j > 0 and pp and psi):
        return loops, None
    k_ctrl = 3.0 * pp * psi / (2.0 * j)
    f_max = v.get("USER_MOTOR1_FREQ_MAX_HZ", v.get("USER_MOTOR1_FREQ_MAX_Hz"))
    if k_ctrl <= 0.01 and f_max and v.get("USER_MOTOR1_MAX_CURRENT_A"):
        kp = 2.5 * v["USER_MOTOR1_MAX_CURRENT_A"] / f_max
        ki_series = 5.0 * v["USER_MOTOR1_MAX_CURRENT_A"] / f
    else:
        kp = bwc / (delta * k_ctrl)
        ki_series = bwc * t_spd / delta ** 2
    # the plant from A to electrical Hz: dω_m/dt = 1.5·pp·ψ·i/J, f_e = pp·ω_m/2π
    plant = 1.5 * pp * pp * psi / (j * 2.0 * math.pi)
    speed = {"sdk": sdk, "bwc_rad_s": bwc, "delta": delta, "kp_a_per_hz": kp, "ki_a_per_hz_s": kp * ki_series / t_spd, "ki_series": ki_series,
             "period_s": t_spd, "k_ctrl": k_ctrl, "plant_hz_per_a_s": plant,
             "macros": ["USER_MOTOR1_INERTIA_Kgm2", "USER_MOTOR1_RATED_FLUX_VpHz",
                        "USER_MOTOR1_NUM_POLE_PAIRS", "USER_M1_NUM_ISR_TICKS_PER_SPEED_TICK"]}
    speed.update(integrator_loop(speed["kp_a_per_hz"], speed["ki_a_per_hz_s"], plant) or {})
    return loops, speed

#: The readings of a V/krpm figure from the flux in V/Hz at pp pole pairs: name → factor
#: on flux·pp·1000/60 (the peak phase back-EMF at 1000 rpm).
_READINGS = {"phase peak": 1.0, "line peak": SQRT3, "line rms": SQRT3 / SQRT2,
             "phase rms": 1.0 / SQRT2, "phase peak with ψ = flux (no 2π)": 2.0 * math.pi,
             "phase peak with ψ/2π": 1.0 / (2.0 * math.pi)}


def _first(v: dict, key: str):
    return next((v[n] for n in _ALIASES[key] if n in v), None)


def decode_header(values: dict, notes: dict) -> dict:
    """TI macros in SI, the design and the checks (:mod:`pulab.profiles.decoding`)."""
    v = values
    has = v.keys().__contains__
    out = {n: macro(v[n], u, m, n) for n, (u, m) in _PLAIN.items() if has(n)}
    checks: list = []
    design: dict = {"assumed": []}
    pp, rs, ld, lq = (_first(v, k) for k in ("pp", "rs", "ld", "lq"))
    flux, imax, ts = _first(v, "flux"), _first(v, "imax"), _first(v, "ts")
    motor: dict = {}
    for key, x in (("rs_ohm", rs), ("ld_h", ld), ("lq_h", lq)):
        if isinstance(x, (int, float)) and x > 0:
            motor[key] = float(x)
    if pp:
        motor["pole_pairs"] = int(pp)
    if flux:
        design["psi_wb"] = flux / (2.0 * math.pi)
        name = next(n for n in _ALIASES["flux"] if has(n))
        out[name]["formula"] = "ψ = flux/(2π)"
        for said in numbers_in(notes.get(name, ""), "V/krpm"):
            if not pp:
                break
            base = flux * pp * 1000.0 / 60.0
            got = {k: base * f for k, f in _READINGS.items()}
            if not any(abs(x / said - 1.0) <= 0.02 for x in got.values()):
                k = min(got, key=lambda r: abs(got[r] / said - 1.0))
                checks.append(check("warning", "comment_value", [name],
                                    "measure Ke again, or correct the comment",
                                    macro=name, value=flux, comment=f"{said:g} V/krpm",
                                    readings=", ".join(f"{r} {x:.3g}" for r, x in got.items()),
                                    nearest=f"{got[k]:.3g} ({k})"))
    if has("USER_MOTOR1_RATED_SPEED_KRPM") and pp:
        motor["rated_freq_hz"] = v["USER_MOTOR1_RATED_SPEED_KRPM"] * 1000.0 * pp / 60.0
        if flux:
            motor["bemf_v"] = flux * motor["rated_freq_hz"] * SQRT3 / SQRT2
    if has("USER_MOTOR1_RATED_VOLTAGE_V"):
        motor["rated_voltage_v"] = float(v["USER_MOTOR1_RATED_VOLTAGE_V"])
    if imax:
        motor["rated_current_a"] = imax / SQRT2
        design["assumed"].append("motor.rated_current_a = USER_MOTOR1_MAX_CURRENT_A/√2")
    drive: dict = {}
    udc = v.get("USER_M1_NOMINAL_DC_BUS_VOLTAGE_V", v.get("USER_IQ_FULL_SCALE_VOLTAGE_V"))
    if udc:
        drive["udc_v"] = float(udc)
    if ts:
        drive["ts_s"] = float(ts)
        design["ts_s"] = float(ts)
    design["input"] = {"motor": motor, "drive": drive}
    board: dict = {}
    fs_i = v.get("USER_M1_ADC_FULL_SCALE_CURRENT_A")
    if fs_i:
        board["current"] = {"max_a": fs_i / 2.0}
        if imax and imax > fs_i / 2.0:
            checks.append(check("error", "inconsistent",
                                ["USER_MOTOR1_MAX_CURRENT_A", "USER_M1_ADC_FULL_SCALE_CURRENT_A"],
                                "a larger current range (lower gain or shunt)",
                                what="measurable current", a=imax, a_from="USER_MOTOR1_MAX_CURRENT_A",
                                b=fs_i / 2.0, b_from="USER_M1_ADC_FULL_SCALE_CURRENT_A/2",
                                diff=round(100.0 * (imax / (fs_i / 2.0) - 1.0), 2)))
    if has("USER_M1_ADC_FULL_SCALE_VOLTAGE_V"):
        board["bus"] = {"max_v": float(v["USER_M1_ADC_FULL_SCALE_VOLTAGE_V"])}
    if has("USER_M1_PWM_FREQ_kHz"):
        board["pwm"] = {"freq_hz": v["USER_M1_PWM_FREQ_kHz"] * 1000.0,
                        "periods_per_control": int(v.get("USER_M1_NUM_PWM_TICKS_PER_ISR_TICK", 1))}
    if board:
        design["input"]["board"] = board
    if has("USER_M1_PWM_FREQ_kHz") and ts:
        t_pwm = v.get("USER_M1_NUM_PWM_TICKS_PER_ISR_TICK", 1) / (v["USER_M1_PWM_FREQ_kHz"] * 1e3)
        if abs(t_pwm / ts - 1.0) > 1e-3:
            checks.append(check("warning", "inconsistent", ["USER_M1_CTRL_PERIOD_sec",
                                                            "USER_M1_PWM_FREQ_kHz"],
                                what="control period", a=ts, a_from="USER_M1_CTRL_PERIOD_sec",
                                b=t_pwm, b_from="USER_M1_NUM_PWM_TICKS_PER_ISR_TICK/PWM_FREQ",
                                diff=round(100.0 * (ts / t_pwm - 1.0), 4)))
    opt = {k: float(v[n]) for k, n in (("full_scale_voltage_v", "USER_IQ_FULL_SCALE_VOLTAGE_V"),
                                       ("full_scale_current_a", "USER_IQ_FULL_SCALE_CURRENT_A"),
                                       ("full_scale_freq_hz", "USER_IQ_FULL_SCALE_FREQ_Hz"))
           if has(n)}
    if imax:
        opt["max_current_a"] = float(imax)
    if has("GLOBAL_Q"):
        opt["global_q"] = int(v["GLOBAL_Q"])
    if opt:
        design["input"]["profiles"] = {"ti": opt}
    loops = {}
    q = int(v.get("GLOBAL_Q", 24))
    for axis, (kp_n, ki_n) in _GAINS.items():
        if not (has(kp_n) and has(ki_n) and ts and "full_scale_voltage_v" in opt
                and "full_scale_current_a" in opt):
            continue
        kp = v[kp_n] / 2.0 ** q * opt["full_scale_voltage_v"] / opt["full_scale_current_a"]
        ki = kp * v[ki_n] / 2.0 ** q / ts
        out[kp_n] = macro(kp, "V/A", f"current PI Kp (series), {axis} axis",
                          f"{kp_n}/2^{q}·V_FS/I_FS")
        out[ki_n] = macro(ki, "V/(A·s)", f"current PI ki = kp·Ki/T, {axis} axis",
                          f"kp·{ki_n}/2^{q}/T")
        l = motor.get("ld_h" if axis == "d" else "lq_h")
        if l and "rs_ohm" in motor:
            c = current_loop(kp, ki, motor["rs_ohm"], l, (kp_n, ki_n))
            if c is not None:
                loops[axis] = c
    speed = None
    if not loops and has("USER_MOTOR1_Rs_Ohm"):
        loops, speed = _runtime(v, motor, design.get("psi_wb"))
        if loops:
            c = next(iter(loops.values()))["runtime"]
            design["assumed"].append(
                f"the current and speed PIs as the universal lab of the {c['sdk']} computes "
                f"them at run time (motor_common.c setupControllers, BW_c = "
                f"{c['bwc_rad_s']:.6g} rad/s), the speed PI's speed in electrical Hz")
    design["current_loop"] = loops or None
    if loops:
        c = loops.get("q") or loops["d"]
        design["input"]["current_loop"] = {"method": "manual", "kp": c["kp_v_per_a"],
                                           "ki": c["ki_v_per_a_s"]}
    design["speed_loop"] = speed
    design["observer"] = None
    return result(READS, "c28x", out, design, checks)
