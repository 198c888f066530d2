"""Microchip MCAF / motorBench profile: Q15 fractions of V_b, I_b, ω_b, and two L bases.

From the generated parameter headers (motor_params.h, foc_params.h), where every
constant is listed with its Q format, its normalized value, its scale (the
engineering value of 1.0) and its engineering value::

    R:   scale V_b/I_b (Q15)          L: scale V_b·Δt/I_b (Q13, *_BASE_DT)
                                         and V_b/(I_b·ω_b) (Q15, *_BASE_OMEGA_E)
    ψ:   scale V_b/ω_b (Q14) and V_b·Δt (Q13)
    Ke:  scale V_b/(ω_b/p) per mechanical rad/s (Q12)
    KIP: scale V_b/I_b (Q15)          KII: scale V_b/(I_b·Δt) (Q15)

All quantities line-to-neutral, 0-to-peak (motor_params.h comments).  The stored
integer is the normalized value rounded to nearest.

Examples
--------
>>> opt = {"voltage_base_v": 71.3, "current_base_a": 43.6, "velocity_base_hz": 400.0}
>>> gains_to_ints(0.25374467, 634.829, {"ts": 5e-5}, opt, "q")["KIP"]["value"]
5084
"""

from __future__ import annotations


from ..common import SOURCES, TWO_PI, board_value, fixed, pow2_exponent
from ..vendor import Option

__all__ = ["OPTIONS", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "bases", "gain_q", "gain_fields",
           "gain_range", "gains_to_ints", "ints_to_gains", "profile", "constants", "board_constants"]

OPTIONS = (
    Option("voltage_base_v", lambda c: board_value(c, "bus", "max_v", c["udc"]),
           "V_b, the DC-link voltage full scale; default the board's bus full scale, else U_dc",
           ("voltage base", "电压基值")),
    Option("current_base_a", lambda c: board_value(c, "current", "max_a", c["i_fs"]),
           "I_b, the current full scale; default the board's ± measurable current, else "
           "2·√2·I_rated",
           ("current base", "电流基值")),
    Option("velocity_base_hz", lambda c: c["f_base"],
           "ω_b/2π, electrical velocity base; default f_b",
           ("velocity base", "速度基值")),
)
CONVENTIONS = {
    "voltage_base": "V_b = DC-link full scale (hardware)",
    "current_base": "I_b = current full scale (hardware)", "line_or_phase": "phase",
    "rms_or_peak": "peak (line-to-neutral 0-pk)", "clarke_k": "2/3",
    "inductance_base": "two: V_b·Δt/I_b (Q13) and V_b/(I_b·ω_b) (Q15)",
    "pi_form": "parallel, Ki·Δt folded in (scale V_b/(I_b·Δt))",
    "rounding": "nearest (motorBench)",
}
CONVENTIONS_ZH = {
    "voltage_base": "V_b = 直流母线满量程（硬件）",
    "current_base": "I_b = 电流满量程（硬件）", "line_or_phase": "相",
    "rms_or_peak": "峰值（线-中性点 0-峰值）", "clarke_k": "2/3",
    "inductance_base": "两种：V_b·Δt/I_b（Q13）与 V_b/(I_b·ω_b)（Q15）",
    "pi_form": "并联，Ki·Δt 合并（比例 V_b/(I_b·Δt)）",
    "rounding": "最近（motorBench）",
}
#: Where the rounding rule was read; files whose printed numbers the tests reproduce.
FILES = {"rounding": SOURCES["mchp_motor"],
         "worked_numbers": [SOURCES["mchp_motor"], SOURCES["mchp_foc"]]}


def _bases(ctx: dict, opt: dict) -> tuple[float, float, float, float]:
    v, i = opt["voltage_base_v"], opt["current_base_a"]
    return v, i, TWO_PI * opt["velocity_base_hz"], ctx["ts"]


def bases(ctx: dict, opt: dict) -> tuple:
    """V_b, I_b and the Δt inductance base V_b·Δt/I_b (the ω_b one is V_b/(I_b·ω_b))."""
    v, i, _, dt = _bases(ctx, opt)
    return v, i, v / i * dt


def gain_fields(axis: str) -> tuple[str, str]:
    """MCAF keeps one pair for both axes (DKP = QKP = KIP)."""
    return "KIP", "KII"


def gain_range(axis: str) -> tuple[int, int]:
    """Q15 in int16_t."""
    return -32768, 32767


def _q(name, x, n, scale, unit, expr, source):
    return fixed(name, x, 16, n, scale, unit, expr, source, fmt=f"Q{n}")


def gain_q(x) -> int:
    """KIP_Q/KII_Q: 15, or fewer fractional bits when |x| ≥ 1 (the PI then shifts by
    DKNP = 15 − KIP_Q, foc_params.h); pulab takes the largest Q that fits int16.

    >>> gain_q(0.155), gain_q(2.5)
    (15, 13)
    """
    return pow2_exponent(x, 32767, 15)[0]


def gains_to_ints(kp, ki, ctx: dict, opt: dict, axis: str) -> dict:
    """KIP, KII (Q15, or Q(KIP_Q) when the gain exceeds 1) for SI kp [V/A], ki [V/(A·s)]
    (intervals in a family proof: each Q is then a choice, ``microchip.KIP_Q``/``KII_Q``)."""
    v, i, _, dt = _bases(ctx, opt)
    z = v / i
    q_kp, kp_n = pow2_exponent(kp / z, 32767, 15, "microchip.KIP_Q")
    q_ki, ki_n = pow2_exponent(ki * dt / z, 32767, 15, "microchip.KII_Q")
    return {"KIP": _q("KIP", kp_n, q_kp, z, "V/A", "kp/(V_b/I_b)", SOURCES["mchp_foc"]),
            "KII": _q("KII", ki_n, q_ki, z / dt, "V/(A·s)", "ki/(V_b/(I_b·Δt))",
                      SOURCES["mchp_foc"])}


def ints_to_gains(kp_int: int, ki_int: int, ctx: dict, opt: dict, axis: str) -> tuple:
    """SI kp, ki of stored KIP, KII; their Q (KIP_Q, KII_Q) is the one
    :func:`gain_q` picks for the report's own gains on that axis."""
    v, i, _, dt = _bases(ctx, opt)
    z = v / i
    kp, ki = ctx["gains"][axis]
    return (kp_int / 2.0 ** gain_q(kp / z) * z, ki_int / 2.0 ** gain_q(ki * dt / z) * z / dt)


def profile(ctx: dict, opt: dict) -> dict:
    """MCAF constants: motor parameters in both inductance bases, ψ, Ke, KIP/KII (q axis)."""
    board = board_constants(ctx, opt)
    return {"inputs": opt, "constants": {**constants(ctx, opt), **board}, "board": list(board)}


def board_constants(ctx: dict, opt: dict | None = None) -> dict:
    """hal_params.h's timer counts from the board's PWM: ``HAL_PARAM_PWM_PERIOD_COUNTS`` is
    half the PWM period in timer clocks (center-aligned: the file notes it is one half-period;
    5000 at 200 MHz and 20 kHz on the LVMC), ``HAL_PARAM_DEADTIME_COUNTS`` the dead time
    (200 for 1 µs at 200 MHz), Q0 rounded to nearest.

    The current and voltage bases need no constant of their own: MCAF reads the ADC with a
    nominal gain of 1.0 (adc_params.h: ``CURRENT_KAA`` = 1.0 in Q14, ``MCAF_VDC_SCALING_FACTOR``
    = 1.0), so the ADC's full scale is the base, which the options take from the board.
    """
    b, p = ctx.get("board") or {}, (ctx.get("board_input") or {}).get("pwm") or {}
    if not b.get("pwm") or p.get("clock_hz") is None:
        return {}
    clk, src = p["clock_hz"], SOURCES["mchp_hal"]
    out = {"HAL_PARAM_PWM_PERIOD_COUNTS": fixed(
        "HAL_PARAM_PWM_PERIOD_COUNTS", clk / (2.0 * p["freq_hz"]), 16, 0, 1.0 / clk, "s",
        "f_clk/(2·f_pwm): one half-period, center-aligned", src, signed=False, fmt="Q0")}
    if p.get("deadtime_s") is not None:
        out["HAL_PARAM_DEADTIME_COUNTS"] = fixed(
            "HAL_PARAM_DEADTIME_COUNTS", p["deadtime_s"] * clk, 16, 0, 1.0 / clk, "s",
            "t_dead·f_clk", src, signed=False, fmt="Q0")
    return out


def constants(ctx: dict, opt: dict) -> dict:
    """The Q integers of :func:`profile` (the inputs may be intervals: a family proof)."""
    v, i, wb, dt = _bases(ctx, opt)
    z, src = v / i, SOURCES["mchp_motor"]
    out = {"MCAF_MOTOR_RS": _q("MCAF_MOTOR_RS", ctx["rs"] / z, 15, z, "Ω", "R_s/(V_b/I_b)",
                               src)}
    for axis, l_h in (("D", ctx["ld"]), ("Q", ctx["lq"])):
        out[f"MCAF_MOTOR_L{axis}_BASE_DT"] = _q(f"MCAF_MOTOR_L{axis}_BASE_DT", l_h / (z * dt), 13,
                                                 z * dt, "H", "L/(V_b·Δt/I_b)", src)
        out[f"MCAF_MOTOR_L{axis}_BASE_OMEGA_E"] = _q(f"MCAF_MOTOR_L{axis}_BASE_OMEGA_E",
                                                      l_h / (z / wb), 15, z / wb, "H",
                                                      "L/(V_b/(I_b·ω_b))", src)
    psi = ctx["psi_peak"]
    out["MCAF_MOTOR_PSI_BASE_OMEGA_E"] = _q("MCAF_MOTOR_PSI_BASE_OMEGA_E", psi / (v / wb), 14,
                                            v / wb, "V·s", "ψ/(V_b/ω_b)", src)
    out["MCAF_MOTOR_PSI_BASE_DT"] = _q("MCAF_MOTOR_PSI_BASE_DT", psi / (v * dt), 13, v * dt,
                                       "V·s", "ψ/(V_b·Δt)", src)
    ke_scale = v / (wb / ctx["pp"])
    out["MCAF_MOTOR_KE"] = _q("MCAF_MOTOR_KE", psi * ctx["pp"] / ke_scale, 12, ke_scale,
                              "V/(rad/s)", "p·ψ/(V_b/(ω_b/p)), per mechanical rad/s", src)
    out.update(gains_to_ints(*ctx["gains"]["q"], ctx, opt, "q"))
    return out
