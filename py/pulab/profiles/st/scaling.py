"""ST MCSDK profile: ADC/PWM "digit" units, int16 gains over power-of-two divisors.

Hardware scaling (parameters_conversion.h)::

    CURRENT_CONV_FACTOR = (uint16_t)(65536·R_shunt·G/V_ref)   digits per ampere
    MAX_CURRENT = V_ref/(2·R_shunt·G)                         A at 32768 digits
    MAX_VOLTAGE = (int16_t)((V_ref/√3)/VBUS_PARTITIONING_FACTOR)
    C1 = (int32_t)(F1·RS/(LS·f_reg))
    C3 = (int32_t)(F1·MAX_BEMF_VOLTAGE/(LS·MAX_CURRENT·f_reg))
    C5 = (int32_t)(F1·MAX_VOLTAGE/(LS·MAX_CURRENT·f_reg))

LS is L_q (pmsm_motor_parameters.h: "For I-PMSM it is equal to Lq"); NOMINAL_CURRENT
is I_peak·32767·R_shunt·G/(V_ref/2) (the formula in that file's comment).

Current PI (pid_regulator.c ``PI_Controller``): ``out = (Kp·e >> log2 KPDIV) +
(ΣKi·e >> log2 KIDIV)`` in digits; the FULL_MISRA_C_COMPLIANCY build divides instead, which
rounds negative values toward zero rather than down (one LSB apart). The voltage digit is taken
as (U_dc/√3)/32768 (full SVPWM modulation, phase peak) — an assumption, not read in
a public file; the Workbench's own Kp/Ki rule is not public either, so pulab stores
the report's kp, ki::

    Kp/KPDIV = kp·MAX_CURRENT/(U_dc/√3)      Ki/KIDIV = ki·T·MAX_CURRENT/(U_dc/√3)

Examples
--------
>>> opt = {"rshunt_ohm": 0.003, "amplification_gain": 9.14, "adc_reference_v": 3.3}
>>> round(max_current(opt), 3)
60.175
"""

from __future__ import annotations

import math

from ...fixedpoint.cint import trunc_div
from ...fixedpoint.interval import RInterval
from ..common import SOURCES, SQRT2, SQRT3, derived, fixed, pow2_divisor, pow2_exponent, real
from ..vendor import Option

__all__ = ["OPTIONS", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "bases", "max_current",
           "gain_fields", "gain_range", "gains_to_ints", "ints_to_gains", "pi_first_output",
           "profile", "constants", "board_constants"]

_GAIN = 8.0


def _sensing(c: dict) -> tuple | None:
    """(V_ref, R_shunt, G) of the board's current chain, or None without one. A sensor in
    V/A, or a largest current typed, is R_shunt·G with G = 1: ST's formulas hold only the
    product."""
    b, bi = c.get("board") or {}, (c.get("board_input") or {}).get("current")
    if not b.get("current"):
        return None
    vref = bi["adc_ref_v"]
    if bi["shunt_ohm"] is not None:
        return vref, bi["shunt_ohm"], bi["gain"] if bi["gain"] is not None else 1.0
    return vref, vref / b["current"]["full_range_a"], 1.0


def _vbus_ratio(c: dict) -> float | None:
    """V at the ADC pin per V on the bus: the board's divider, or its ADC reference over a
    typed bus full scale; None without bus sensing."""
    b, bi = (c.get("board") or {}).get("bus"), (c.get("board_input") or {}).get("bus")
    if not b:
        return None
    return b["ratio"] if b["ratio"] is not None else bi["adc_ref_v"] / b["max_v"]


OPTIONS = (
    Option("adc_reference_v", lambda c: (_sensing(c) or (3.3,))[0],
           "ADC_REFERENCE_VOLTAGE; default the board's, else 3.3 V",
           ("ADC reference", "ADC 参考电压")),
    Option("amplification_gain", lambda c: (_sensing(c) or (0, 0, _GAIN))[2],
           "AMPLIFICATION_GAIN; default the board's, else 8",
           ("amplifier gain", "放大倍数")),
    Option("rshunt_ohm", lambda c: (_sensing(c) or (0, 3.3 / (2.0 * _GAIN * c["i_fs"])))[1],
           "RSHUNT; default the board's, else so that MAX_CURRENT = 2·√2·I_rated with the "
           "defaults above",
           ("shunt", "采样电阻")),
    Option("vbus_partitioning_factor",
           lambda c: _vbus_ratio(c) or 3.3 / (2.0 * c["udc"]),
           "VBUS_PARTITIONING_FACTOR; default the board's divider, else puts U_dc at half "
           "the ADC range",
           ("bus voltage divider", "母线分压系数")),
    Option("tf_kpdiv", lambda c: None,
           "TF_KPDIV (power of two); default the largest ≤ 16384 fitting int16",
           ("TF_KPDIV", "TF_KPDIV"), kind="integer", lo=1, hi=32768, power_of_two=True),
    Option("tf_kidiv", lambda c: None, "TF_KIDIV (power of two); default as TF_KPDIV",
           ("TF_KIDIV", "TF_KIDIV"), kind="integer", lo=1, hi=32768, power_of_two=True),
    Option("f1", lambda c: 16384, "observer scaling F1; default 16384",
           ("observer F1", "观测器 F1"), kind="integer", lo=1, hi=32767),
    Option("f2", lambda c: None, "observer scaling F2 (power of two); default the largest ≤ 16384 "
           "keeping GAIN2 in int16 (with an observer section)",
           ("observer F2", "观测器 F2"), kind="integer", lo=1, hi=16384, power_of_two=True),
    Option("observer_design", lambda c: False, "true: GAIN1/GAIN2 and the PLL gains from pulab's "
           "observer design (observer.bemf_*, observer.tracking_*); default the Workbench's rule",
           ("observer gains from pulab's design", "观测器增益按 pu-lab 设计"), kind="flag"),
)
CONVENTIONS = {
    "voltage_base": "U_dc/√3 at 32768 digits (assumed, full modulation)",
    "current_base": "MAX_CURRENT = V_ref/(2·R_shunt·G) at 32768 digits (hardware)",
    "line_or_phase": "phase", "rms_or_peak": "peak (0-to-peak digits)",
    "clarke_k": "2/3 (MCM_Clarke: α = a, β = −(a + 2b)/√3, mc_math.c)",
    "inductance_base": "none: LS in H (float) enters C1..C5",
    "pi_form": "parallel, int16 gain / power-of-two divisor, Ki·T folded in",
    "rounding": "C casts (uint16_t)/(int16_t)/(int32_t): toward zero",
}
CONVENTIONS_ZH = {
    "voltage_base": "U_dc/√3 对应 32768 数字量（假设，满调制）",
    "current_base": "MAX_CURRENT = V_ref/(2·R_shunt·G) 对应 32768 数字量（硬件）",
    "line_or_phase": "相", "rms_or_peak": "峰值（0-峰值数字量）",
    "clarke_k": "2/3（MCM_Clarke：α = a，β = −(a + 2b)/√3，mc_math.c）",
    "inductance_base": "无：LS 以 H 存（浮点），进入 C1..C5",
    "pi_form": "并联，int16 增益 / 2 的幂除数，Ki·T 合并",
    "rounding": "C 强制转换 (uint16_t)/(int16_t)/(int32_t)：向零",
}
#: Where the rounding rule was read; files whose printed numbers the tests reproduce.
FILES = {"rounding": SOURCES["st_conv"], "pi": SOURCES["st_pid"],
         "worked_numbers": [SOURCES["st_drive"]]}


def max_current(opt: dict) -> float:
    """MAX_CURRENT = V_ref/(2·R_shunt·G), A (parameters_conversion.h)."""
    return opt["adc_reference_v"] / (2.0 * opt["rshunt_ohm"] * opt["amplification_gain"])


def _v_over_i(ctx: dict, opt: dict) -> float:
    """Volts per voltage digit over amperes per current digit."""
    return (ctx["udc"] / SQRT3) / max_current(opt)


def bases(ctx: dict, opt: dict) -> tuple:
    """U_dc/√3 (assumed voltage digit scale), MAX_CURRENT; no inductance base (LS in H)."""
    return ctx["udc"] / SQRT3, max_current(opt), None


def gain_fields(axis: str) -> tuple[str, str]:
    """Flux (d) and torque (q) PID defaults."""
    w = "FLUX" if axis == "d" else "TORQUE"
    return f"PID_{w}_KP_DEFAULT", f"PID_{w}_KI_DEFAULT"


def gain_range(axis: str) -> tuple[int, int]:
    """hKpGain, hKiGain are int16_t."""
    return -32768, 32767


def divisors(ctx: dict, opt: dict) -> tuple[int, int]:
    """TF_KPDIV, TF_KIDIV: given, or pulab's choice for the larger of the two axes."""
    return _divisors(ctx, opt)[:2]


def _divisors(ctx: dict, opt: dict) -> tuple:
    """TF_KPDIV, TF_KIDIV and each axis's Kp, Ki per unit ({axis: (kp, ki)}).

    The divisor suits the larger gain of the two axes: the largest D whose gain fits is
    monotone in |gain|, so D for max(|g_d|, |g_q|) is the smaller of the two axes' own D.
    Over intervals (a family proof) each axis's exponent is a choice (``st.TF_KPDIV.d`` …)
    and its gain keeps only the part of its interval that makes it."""
    r, t = _v_over_i(ctx, opt), ctx["ts"]
    per_axis = {a: [ctx["gains"][a][0] / r, ctx["gains"][a][1] * t / r] for a in ("d", "q")}
    divs = []
    for i, (key, site) in enumerate((("tf_kpdiv", "st.TF_KPDIV"), ("tf_kidiv", "st.TF_KIDIV"))):
        if opt[key]:
            divs.append(opt[key])
            continue
        ns = []
        for a in ("d", "q"):
            n, per_axis[a][i] = pow2_exponent(per_axis[a][i], 32767, 14, f"{site}.{a}")
            ns.append(n)
        divs.append(1 << min(ns))
    return divs[0], divs[1], per_axis


def gains_to_ints(kp, ki, ctx: dict, opt: dict, axis: str, per_unit: tuple = None) -> dict:
    """int16 Kp, Ki over TF_KPDIV, TF_KIDIV for SI gains kp [V/A], ki [V/(A·s)];
    ``per_unit`` (from :func:`_divisors`): Kp, Ki per unit already computed."""
    r, t = _v_over_i(ctx, opt), ctx["ts"]
    kpdiv = opt["tf_kpdiv"] or pow2_divisor(kp / r)
    kidiv = opt["tf_kidiv"] or pow2_divisor(ki * t / r)
    x_kp, x_ki = per_unit or (kp / r, ki * t / r)
    kp_name, ki_name = gain_fields(axis)
    src = derived("kp·MAX_CURRENT/(U_dc/√3), the Workbench rule is not public; the PI form "
                  "(int16 gain >> log2 divisor) is MCSDK pid_regulator.c")
    return {kp_name: fixed(kp_name, x_kp, 16, kpdiv.bit_length() - 1, r, "V/A",
                           "kp·MAX_CURRENT/(U_dc/√3)", src, fmt=f"int16 / {kpdiv}"),
            ki_name: fixed(ki_name, x_ki, 16, kidiv.bit_length() - 1, r / t, "V/(A·s)",
                           "ki·T·MAX_CURRENT/(U_dc/√3)", src, fmt=f"int16 / {kidiv}")}


def ints_to_gains(kp_int: int, ki_int: int, ctx: dict, opt: dict, axis: str) -> tuple:
    """SI kp, ki of stored gains (divisors from the profile inputs, or as chosen above)."""
    r, t = _v_over_i(ctx, opt), ctx["ts"]
    kpdiv, kidiv = divisors(ctx, opt)
    return kp_int / kpdiv * r, ki_int / kidiv * r / t


def pi_first_output(kp: int, kpdiv: int, ki: int, kidiv: int, error: int, misra: bool) -> int:
    """The first output of ``PI_Controller`` from a zero integral (pid_regulator.c), digits.

    The default build shifts (an arithmetic shift floors), the FULL_MISRA_C_COMPLIANCY build
    divides (C division truncates toward zero): a negative term differs by one LSB.

    >>> pi_first_output(9456, 16384, 2364, 16384, -33, False)
    -25
    >>> pi_first_output(9456, 16384, 2364, 16384, -33, True)
    -23
    """
    p, i = kp * error, ki * error
    if misra:
        return trunc_div(p, kpdiv) + trunc_div(i, kidiv)
    return (p >> (kpdiv.bit_length() - 1)) + (i >> (kidiv.bit_length() - 1))


def _c_trunc(x: float) -> int:
    return math.trunc(x)


def _carried(per_unit, ideal):
    """|C − ideal| in LSB for C = trunc(F1·N/den) of a truncated integer N (N ≤ x < N + 1):
    below 1 (the cast) + F1/den (the input's truncation, carried) + a few roundings of the
    doubles; over a box (intervals) its largest value, else None (a point needs none)."""
    if not isinstance(per_unit, RInterval):
        return None
    return 1.0 + per_unit.hi * (1 + 1e-12) + 1e-15 * max(abs(ideal.lo), abs(ideal.hi))


def profile(ctx: dict, opt: dict) -> dict:
    """ST constants: PID defaults, current conversion, observer C1, C3, C5."""
    kpdiv, kidiv = divisors(ctx, opt)
    o = {**opt, "tf_kpdiv": kpdiv, "tf_kidiv": kidiv}
    out = constants(ctx, opt)
    imax = max_current(o)
    f_reg = round(1.0 / ctx["ts"])
    max_rpm = 60.0 * ctx["f_base"] / ctx["pp"]
    o.update(max_current_a=imax, pwm_frequency_hz=f_reg, max_application_speed_rpm=max_rpm,
             motor_voltage_constant=_ke(ctx))
    # A ±0.1 % current error through the torque PI: the shift and the MISRA build disagree
    # on the negative side (rounding down vs toward zero).
    e = max(1, round(0.001 * 32768))
    kp_i, ki_i = out["PID_TORQUE_KP_DEFAULT"]["value"], out["PID_TORQUE_KI_DEFAULT"]["value"]
    example = [{"error": err,
                "shift": pi_first_output(kp_i, kpdiv, ki_i, kidiv, err, False),
                "misra": pi_first_output(kp_i, kpdiv, ki_i, kidiv, err, True)}
               for err in (e, -e)]
    board = board_constants(ctx, o)
    out.update(board)
    return {"inputs": o, "constants": out, "board": list(board), "pi_example": example}


def dead_time_counts(clock_hz: float, deadtime_s: float) -> int:
    """DEAD_TIME_COUNTS as parameters_conversion.h encodes it into the timer's DTG field.

    ``DEAD_TIME_COUNTS_1`` = f_clk[MHz]·t_dead[ns]/1000 in integer arithmetic; up to 255 it
    is the count itself, beyond that the coarser DTG ranges (÷2 + 128, ÷8 + 320, ÷16 + 384),
    and 510 beyond 2015 counts.

    >>> dead_time_counts(170e6, 800e-9), dead_time_counts(170e6, 2e-6), dead_time_counts(170e6, 20e-6)
    (136, 298, 510)
    """
    prod = math.floor(round(clock_hz / 1e6, 9) * round(deadtime_s * 1e9, 6))   # MHz · ns
    dt1 = prod // 1000
    for limit, div, off in ((255, 1, 0), (508, 2, 128), (1008, 8, 320), (2015, 16, 384)):
        if dt1 <= limit:
            return prod // div // 1000 + off
    return 510


def board_constants(ctx: dict, opt: dict) -> dict:
    """parameters_conversion.h's board macros, from the board's chains (and the options it set).

    ``MAX_CURRENT`` (MCSDK 6: ``M1_MAX_READABLE_CURRENT``) = V_ref/(2·R_shunt·G), a double;
    ``VBUS_PARTITIONING_FACTOR`` the divider; ``PWM_PERIOD_CYCLES`` = (uint16_t)(f_clk/f_pwm
    & 0xFFFE) timer ticks (the timer counts up and down over half of them);
    ``DEAD_TIME_COUNTS`` by :func:`dead_time_counts`.
    """
    b, bi, out = ctx.get("board") or {}, ctx.get("board_input") or {}, {}
    if b.get("current"):
        for name in ("MAX_CURRENT", "M1_MAX_READABLE_CURRENT"):
            out[name] = real(name, max_current(opt), "A", "ADC_REFERENCE_VOLTAGE/(2·RSHUNT·"
                             "AMPLIFICATION_GAIN)", SOURCES["st_conv"])
    if b.get("bus"):
        out["VBUS_PARTITIONING_FACTOR"] = real(
            "VBUS_PARTITIONING_FACTOR", opt["vbus_partitioning_factor"], "V/V",
            "R_bottom/(R_top + R_bottom)", SOURCES["st_power"])
    p = bi.get("pwm") or {}
    if b.get("pwm") and p.get("clock_hz") is not None:
        clk, f = p["clock_hz"], p["freq_hz"]
        ticks = clk / f
        stored = (math.floor(ticks) & 0xFFFE) & 0xFFFF
        out["PWM_PERIOD_CYCLES"] = fixed(
            "PWM_PERIOD_CYCLES", ticks, 16, 0, 1.0 / clk, "s",
            "(uint16_t)((ADV_TIM_CLK_MHz·10⁶/PWM_FREQUENCY) & 0xFFFE)", SOURCES["st_conv"],
            rounding="zero", signed=False, fmt="uint16_t", value=stored)
        if p.get("deadtime_s") is not None:
            td = p["deadtime_s"]
            code = dead_time_counts(clk, td)
            plain = code <= 255
            out["DEAD_TIME_COUNTS"] = fixed(
                "DEAD_TIME_COUNTS", td * clk if plain else code, 16, 0,
                1.0 / clk if plain else 1.0, "s" if plain else "DTG code",
                "ADV_TIM_CLK_MHz·DEADTIME_NS/1000, DTG-encoded beyond 255", SOURCES["st_conv"],
                rounding="zero", signed=False, fmt="uint16_t", value=code)
    return out


def _ke(ctx: dict):
    """MOTOR_VOLTAGE_CONSTANT, V rms line-to-line per krpm."""
    return ctx["bemf_v"] / (60.0 * ctx["f_rated"] / ctx["pp"] / 1000.0)


def constants(ctx: dict, opt: dict) -> dict:
    """The integers of :func:`profile` (the inputs may be intervals: a family proof)."""
    kpdiv, kidiv, per_axis = _divisors(ctx, opt)
    o = {**opt, "tf_kpdiv": kpdiv, "tf_kidiv": kidiv}
    out = {}
    for axis in ("d", "q"):
        out.update(gains_to_ints(*ctx["gains"][axis], ctx, o, axis, tuple(per_axis[axis])))
    vref, rsh, g = o["adc_reference_v"], o["rshunt_ohm"], o["amplification_gain"]
    imax = max_current(o)
    f_reg = round(1.0 / ctx["ts"])  # PWM_FREQUENCY / REGULATION_EXECUTION_RATE (= 1)
    f1 = o["f1"]
    conv, mot = SOURCES["st_conv"], SOURCES["st_motor"]
    out["CURRENT_CONV_FACTOR"] = fixed("CURRENT_CONV_FACTOR", 65536.0 * rsh * g / vref, 16, 0,
                                       1.0, "digit/A", "65536·RSHUNT·G/V_ref", conv,
                                       rounding="zero", signed=False, fmt="uint16_t")
    mv_exact = (vref / SQRT3) / o["vbus_partitioning_factor"]
    out["MAX_VOLTAGE"] = fixed("MAX_VOLTAGE", mv_exact, 16, 0, 1.0, "V",
                               "(V_ref/√3)/VBUS_PARTITIONING_FACTOR", conv, rounding="zero",
                               fmt="int16_t")
    i_pk = SQRT2 * ctx["i_rated"]
    out["NOMINAL_CURRENT"] = fixed("NOMINAL_CURRENT", i_pk * 32767.0 * rsh * g / (vref / 2.0),
                                   16, 0, (vref / 2.0) / (32767.0 * rsh * g), "A",
                                   "I_peak·32767·RSHUNT·G/(V_ref/2)", mot, fmt="int16_t")
    ls = ctx["lq"]
    out["C1"] = fixed("C1", f1 * ctx["rs"] / (ls * f_reg), 32, 0, ls * f_reg / f1, "Ω",
                      "F1·RS/(LS·f_reg)", conv, rounding="zero", fmt="int32_t")
    max_rpm = 60.0 * ctx["f_base"] / ctx["pp"]
    bemf_exact = max_rpm * 1.2 * _ke(ctx) * SQRT2 / (1000.0 * SQRT3)
    bemf = fixed("MAX_BEMF_VOLTAGE", bemf_exact, 16, 0, 1.0, "V",
                 "MAX_APPLICATION_SPEED_RPM·1.2·MOTOR_VOLTAGE_CONSTANT·√2/(1000·√3)", conv,
                 rounding="zero", signed=False, fmt="uint16_t")
    out["MAX_BEMF_VOLTAGE"] = bemf
    den = ls * imax * f_reg
    out["C3"] = fixed("C3", f1 * bemf_exact / den, 32, 0, den / f1, "V",
                      "F1·MAX_BEMF_VOLTAGE/(LS·MAX_CURRENT·f_reg)", conv, rounding="zero",
                      fmt="int32_t", value=_c_trunc(f1 * bemf["value"] / den),
                      error_lsb=_carried(f1 / den, f1 * bemf_exact / den))
    out["C5"] = fixed("C5", f1 * mv_exact / den, 32, 0, den / f1, "V",
                      "F1·MAX_VOLTAGE/(LS·MAX_CURRENT·f_reg)", conv, rounding="zero",
                      fmt="int32_t", value=_c_trunc(f1 * out["MAX_VOLTAGE"]["value"] / den),
                      error_lsb=_carried(f1 / den, f1 * mv_exact / den))
    return out
