"""TI MotorWare / InstaSPIN profile: per unit of the hardware full scale, IQ24.

Bases are the board's full-scale values, not the motor's ratings:
``USER_IQ_FULL_SCALE_VOLTAGE_V`` (V_FS), ``USER_IQ_FULL_SCALE_CURRENT_A`` (I_FS),
``USER_IQ_FULL_SCALE_FREQ_Hz`` (F_FS) (gdgly/EV_28069M : sw/modules/user/src/32b/user.c).
Every constant is ``_IQ(A) = (long)(A·2^GLOBAL_Q)`` — a C cast, so it truncates
toward zero (IQmathLib.h).

Current PI, series form (pi.h ``PI_run_series``: Up = Kp·e, Ui += Ki·Up)::

    Kp_pu = kp·I_FS/V_FS              ki = kp·Ki_pu/T  ⇒  Ki_pu = ki·T/kp

MotorWare's own defaults (calcPIgains, and ctrl.c ``CTRL_setParams``)::

    Kp_pu = 0.25·L·I_FS/(T·V_FS)   Ki_pu = (R/L)·T           (current, per axis)
    Kp_spd = 0.02·I_max·F_FS/I_FS   Ki_spd = 2·I_max·F_FS·T/I_FS  (speed)

Examples
--------
>>> ctx = {"ts": 1e-4}
>>> opt = {"full_scale_voltage_v": 24.0, "full_scale_current_a": 10.0, "global_q": 24}
>>> g = gains_to_ints(1.2, 3000.0, ctx, opt, "q")
>>> g["Kp_Iq"]["value"], g["Ki_Iq"]["value"]
(8388608, 4194304)
"""

from __future__ import annotations

from ..common import SOURCES, SQRT2, board_value, derived, fixed, real
from ..vendor import Option

__all__ = ["OPTIONS", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "bases", "gain_fields",
           "gain_range", "gains_to_ints", "ints_to_gains", "check_for_errors", "warnings", "profile",
           "constants", "board_constants"]

#: Its hardware inputs (:class:`pulab.profiles.vendor.Option`).
OPTIONS = (
    Option("full_scale_voltage_v", lambda c: c["udc"], "USER_IQ_FULL_SCALE_VOLTAGE_V; default U_dc",
           ("full-scale voltage", "满量程电压")),
    Option("full_scale_current_a", lambda c: board_value(c, "current", "max_a", c["i_fs"]),
           "USER_IQ_FULL_SCALE_CURRENT_A; default the board's largest reading (half of "
           "USER_ADC_FULL_SCALE_CURRENT_A: TI requires it above every reading), else 2·√2·I_rated",
           ("full-scale current", "满量程电流")),
    Option("full_scale_freq_hz", lambda c: c["f_base"], "USER_IQ_FULL_SCALE_FREQ_Hz; default f_b",
           ("full-scale frequency", "满量程频率")),
    Option("max_current_a", lambda c: SQRT2 * c["i_rated"],
           "USER_MOTOR_MAX_CURRENT (peak); default √2·I_rated",
           ("max. motor current", "电机最大电流")),
    Option("global_q", lambda c: 24, "GLOBAL_Q; default 24",
           ("GLOBAL_Q", "GLOBAL_Q"), kind="integer", lo=1, hi=30),
)
CONVENTIONS = {
    "voltage_base": "USER_IQ_FULL_SCALE_VOLTAGE_V (hardware)",
    "current_base": "USER_IQ_FULL_SCALE_CURRENT_A (hardware)",
    "line_or_phase": "phase", "rms_or_peak": "peak",
    "clarke_k": "2/3 (CTRL_setupClarke_I: 1/3, 1/√3 scale factors)",
    "inductance_base": "none: L stays in H (float); Kp_pu = 0.25·L·I_FS/(T·V_FS)",
    "pi_form": "series: Ui += Ki·(Kp·e)", "rounding": "_IQ(): (long) cast, toward zero",
}
CONVENTIONS_ZH = {
    "voltage_base": "USER_IQ_FULL_SCALE_VOLTAGE_V（硬件）",
    "current_base": "USER_IQ_FULL_SCALE_CURRENT_A（硬件）",
    "line_or_phase": "相", "rms_or_peak": "峰值",
    "clarke_k": "2/3（CTRL_setupClarke_I：比例系数 1/3、1/√3）",
    "inductance_base": "无：L 以 H 存（浮点）；Kp_pu = 0.25·L·I_FS/(T·V_FS)",
    "pi_form": "串联：Ui += Ki·(Kp·e)", "rounding": "_IQ()：(long) 强制转换，向零",
}
#: Where the rounding rule was read; files whose printed numbers the tests reproduce.
FILES = {"rounding": SOURCES["ti_iqmath"], "checks": SOURCES["ti_user"], "worked_numbers": []}


def bases(ctx: dict, opt: dict) -> tuple:
    """V_FS, I_FS; L enters Kp_pu as L·I_FS/(T·V_FS), so its effective base is V_FS·T/I_FS."""
    v, i = opt["full_scale_voltage_v"], opt["full_scale_current_a"]
    return v, i, v / i * ctx["ts"]


def gain_fields(axis: str) -> tuple[str, str]:
    """``Kp_Id``/``Ki_Id`` or ``Kp_Iq``/``Ki_Iq``."""
    return f"Kp_I{axis}", f"Ki_I{axis}"


def gain_range(axis: str) -> tuple[int, int]:
    """_iq is a 32-bit long."""
    return -(1 << 31), (1 << 31) - 1


def _iq(name, x, opt, si_per_unit, unit, expr, source):
    q = opt["global_q"]
    return fixed(name, x, 32, q, si_per_unit, unit, expr, source, rounding="zero",
                 fmt=f"IQ{q}")


def gains_to_ints(kp: float, ki: float, ctx: dict, opt: dict, axis: str) -> dict:
    """Kp (IQ) and the series Ki (IQ) for SI gains kp [V/A], ki [V/(A·s)]."""
    v, i, t = opt["full_scale_voltage_v"], opt["full_scale_current_a"], ctx["ts"]
    kp_name, ki_name = gain_fields(axis)
    kp_rec = _iq(kp_name, kp * i / v, opt, v / i, "V/A", "kp·I_FS/V_FS", SOURCES["ti_pigains"])
    ki_rec = _iq(ki_name, ki * t / kp, opt, kp_rec["si"] / t, "V/(A·s)",
                 "ki·T/kp (series: integral gain multiplies Up = Kp·e)", SOURCES["ti_pi"])
    return {kp_name: kp_rec, ki_name: ki_rec}


def ints_to_gains(kp_int: int, ki_int: int, ctx: dict, opt: dict, axis: str) -> tuple:
    """SI kp, ki of stored Kp, Ki (IQ): kp = Kp/2^q·V_FS/I_FS, ki = kp·Ki/2^q/T."""
    q = opt["global_q"]
    kp = kp_int / 2.0 ** q * opt["full_scale_voltage_v"] / opt["full_scale_current_a"]
    return kp, kp * ki_int / 2.0 ** q / ctx["ts"]


def check_for_errors(ctx: dict, opt: dict) -> list:
    """The conditions of MotorWare's ``USER_checkForErrors`` (user.c) that these inputs decide.

    Each is ``[error code, condition]`` — the firmware would stop with that code. The checks
    keep the speed gains and frequencies inside IQ24's ±128 (the 128 in each condition).

    >>> hits = check_for_errors({"ts": 1e-4, "pp": 4}, {"full_scale_voltage_v": 24.0,
    ...     "full_scale_current_a": 1.0, "full_scale_freq_hz": 20.0, "max_current_a": 2.0})
    >>> [why for _, why in hits]
    ['I_FS < USER_MOTOR_MAX_CURRENT', 'F_FS < 50 Hz']
    """
    i, f, imax, t = (opt["full_scale_current_a"], opt["full_scale_freq_hz"],
                     opt["max_current_a"], ctx["ts"])
    rules = (
        ("USER_ErrorCode_iqFullScaleCurrent_A_Low",
         i <= 0.02 * imax * f / 128.0, "I_FS <= 0.02·I_max·F_FS/128"),
        ("USER_ErrorCode_iqFullScaleCurrent_A_Low",
         i <= 2.0 * imax * f * t / 128.0, "I_FS <= 2·I_max·F_FS·T/128"),
        ("USER_ErrorCode_iqFullScaleCurrent_A_Low", i < imax, "I_FS < USER_MOTOR_MAX_CURRENT"),
        ("USER_ErrorCode_iqFullScaleFreq_Hz_High",
         f >= 128.0 * i / (0.02 * imax), "F_FS >= 128·I_FS/(0.02·I_max)"),
        ("USER_ErrorCode_iqFullScaleFreq_Hz_High",
         f >= 128.0 * i / (2.0 * imax * t), "F_FS >= 128·I_FS/(2·I_max·T)"),
        ("USER_ErrorCode_iqFullScaleFreq_Hz_High",
         f >= 128.0 * ctx["pp"] * 1000.0 / 60.0, "F_FS >= 128·p·1000/60"),
        ("USER_ErrorCode_iqFullScaleFreq_Hz_Low", f < 50.0, "F_FS < 50 Hz"),
    )
    return [[code, why] for code, hit, why in rules if hit]


def warnings(p: dict) -> list:
    """One ``warning.ti_check`` per condition of :func:`check_for_errors` this profile ``p``
    hits, as ``(catalog code, params)``."""
    return [("warning.ti_check", {"code": code, "why": why}) for code, why in p["checks"]]


def profile(ctx: dict, opt: dict) -> dict:
    """TI constants for this motor: the user's current PI, MotorWare's defaults, Rs_pu."""
    board = board_constants(ctx, opt)
    return {"inputs": opt, "constants": {**constants(ctx, opt), **board}, "board": list(board),
            "checks": check_for_errors(ctx, opt)}


def board_constants(ctx: dict, opt: dict | None = None) -> dict:
    """The universal lab's board macros (user_mtr1.h), from the board's chains.

    ``USER_M1_ADC_FULL_SCALE_CURRENT_A`` is V_ref/(R·G), the whole ADC range (TI prints
    47.14285714 for 7 mΩ × 10), ``USER_M1_CURRENT_SF`` that over 2^bits (A per count);
    the same for the bus; ``USER_M1_PWM_TBPRD_NUM`` = (uint16_t)(f_clk/f_pwm/2), an
    up-down count.

    >>> b = {"current": {"full_range_a": 3.3 / 0.07, "a_per_count": 3.3 / 0.07 / 4096},
    ...      "bus": None, "pwm": None}
    >>> c = board_constants({"board": b, "board_input": {"current": {"adc_bits": 12}}})
    >>> c["USER_M1_ADC_FULL_SCALE_CURRENT_A"]["value"], c["USER_M1_CURRENT_SF"]["format"]
    (47.14285659790039, 'float32')
    """
    b, bi, out = ctx.get("board") or {}, ctx.get("board_input") or {}, {}
    # (chain, its full scale and one count in the board output, the macro names, unit, formula)
    for chain, full, lsb, name, sf, unit, expr in (
            ("current", "full_range_a", "a_per_count", "USER_M1_ADC_FULL_SCALE_CURRENT_A",
             "USER_M1_CURRENT_SF", "A", "V_ref/(R_shunt·G): the whole ADC range"),
            ("bus", "max_v", "v_per_count", "USER_M1_ADC_FULL_SCALE_VOLTAGE_V",
             "USER_M1_VOLTAGE_SF", "V", "V_ref·(R_top + R_bottom)/R_bottom")):
        if b.get(chain):
            bits = bi[chain]["adc_bits"]
            out[name] = real(name, b[chain][full], unit, expr, SOURCES["ti_umcl"], single=True)
            out[sf] = real(sf, b[chain][lsb], f"{unit}/count", f"{name}/{2 ** bits}",
                           SOURCES["ti_umcl"], single=True)
    p = bi.get("pwm") or {}
    if b.get("pwm") and p.get("clock_hz") is not None:
        clk = p["clock_hz"]
        out["USER_M1_PWM_TBPRD_NUM"] = fixed(
            "USER_M1_PWM_TBPRD_NUM", clk / p["freq_hz"] / 2.0, 16, 0, 1.0 / clk, "s (half period)",
            "(uint16_t)(SYSTEM_FREQ_MHz·1000/PWM_FREQ_kHz/2): half the period, up-down",
            SOURCES["ti_umcl"], rounding="zero", signed=False, fmt="uint16_t")
    return out


def constants(ctx: dict, opt: dict) -> dict:
    """The IQ integers of :func:`profile` alone (without MotorWare's error checks)."""
    v, i, f, t = (opt["full_scale_voltage_v"], opt["full_scale_current_a"],
                  opt["full_scale_freq_hz"], ctx["ts"])
    out = {}
    for axis in ("d", "q"):
        out.update(gains_to_ints(*ctx["gains"][axis], ctx, opt, axis))
    for axis, l_h in (("d", ctx["ld"]), ("q", ctx["lq"])):
        kp = _iq(f"Kp_I{axis}_default", 0.25 * l_h * i / (t * v), opt, v / i, "V/A",
                 "0.25·L·I_FS/(T·V_FS)", SOURCES["ti_pigains"])
        out[kp["name"]] = kp
        ki = _iq(f"Ki_I{axis}_default", ctx["rs"] / l_h * t, opt, kp["si"] / t, "V/(A·s)",
                 "(R/L)·T", SOURCES["ti_pigains"])
        out[ki["name"]] = ki
    imax = opt["max_current_a"]
    out["Kp_spd_default"] = _iq("Kp_spd_default", 0.02 * imax * f / i, opt, i / f, "A/Hz",
                                "0.02·I_max·F_FS/I_FS", SOURCES["ti_ctrl"])
    out["Ki_spd_default"] = _iq("Ki_spd_default", 2.0 * imax * f * t / i, opt, 1.0 / t, "1/s",
                                "2·I_max·F_FS·T/I_FS (series)", SOURCES["ti_ctrl"])
    out["Rs_pu"] = _iq("Rs_pu", ctx["rs"] * i / v, opt, v / i, "Ω", "R_s·I_FS/V_FS",
                       derived("TI per unit of V_FS/I_FS; MotorWare keeps USER_MOTOR_Rs in Ω"))
    return out
