"""NXP MCAT / RTCESL profile: fractions of U_max and I_max, ACC32 and FRAC16 + shift.

Scales (inner_CLoop.js, clickCalculateCloop)::

    U_max = U_DCB,max / UmaxCoeff

That JavaScript MCAT rounds U_max to 0.1 V; the 2023 MCAT-generated
m1_pmsm_appconfig.h (motor "linix": M1_U_MAX 35.1029 = 60.8/√3) does not, and its
scales follow the unrounded value — so rounding is an option (``round_u_max``), off
by default.
    Kp = (2·ξ·ω0·L − R_s)·I_max/U_max                  (its own design; pulab stores the
    Ki = ω0²·L·T_s/k · I_max/U_max                      report's kp, ki the same way)

with k = 2 for the trapezoidal discretization.  Gains and the observer scales are
emitted as ``ACC32(x)``: Q16.15 in 32 bits, the macro truncates toward zero and
saturates (mlib_types.h).  Observer scales (inner_PoSpeBemfDQ.js)::

    I_SCALE = L_d/(L_d + T_s·R_s)        U_SCALE = T_s/(L_d + T_s·R_s)·U_max/I_max
    E_SCALE = T_s/(L_d + T_s·R_s)·E_max/I_max    WI_SCALE = L_q·T_s/(L_d + T_s·R_s)·ω_max

The tracking observer's theta gain T_s·ω_max/π is a FRAC16 mantissa with a shift
(:func:`pulab.profiles.common.mantissa_shift`).

Examples
--------
>>> u_max(24.0, 3 ** 0.5)
13.9
"""

from __future__ import annotations

import math

from ...schema.errors import InputError
from ..common import SOURCES, SQRT3, TWO_PI, board_value, fixed, mantissa_shift, real
from ..vendor import Option

__all__ = ["OPTIONS", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "bases", "u_max", "gain_fields",
           "gain_range", "gains_to_ints", "ints_to_gains", "profile", "constants", "board_constants"]

OPTIONS = (
    Option("udcb_max_v", lambda c: board_value(c, "bus", "max_v", c["udc"]),
           "U_DCB_MAX, DC-bus full scale; default the board's bus full scale, else U_dc",
           ("U_DCB max", "母线电压满量程 U_DCB")),
    Option("i_max_a", lambda c: board_value(c, "current", "max_a", c["i_fs"]),
           "I_MAX, phase-current full scale; default the board's ± measurable current, else "
           "2·√2·I_rated",
           ("I max", "电流满量程 I max")),
    Option("u_max_coeff", lambda c: SQRT3, "UmaxCoeff: U_max = U_DCB_MAX/UmaxCoeff; default √3",
           ("UmaxCoeff", "UmaxCoeff")),
    Option("e_max_v", lambda c: None, "E_MAX, back-EMF scale; default U_max",
           ("E max (back-EMF scale)", "反电势满量程 E max")),
    Option("trapezoidal", lambda c: False, "discretization: true halves Ki (k = 2); default false",
           ("trapezoidal discretization", "梯形离散化"), kind="flag"),
    Option("round_u_max", lambda c: False, "round U_max to 0.1 V as the JavaScript MCAT does; "
           "default false",
           ("U_max rounded to 0.1 V", "U_max 取整到 0.1 V"), kind="flag"),
    Option("mcat", lambda c: None, "the JSON object MCAT writes at the top of "
           "m1_pmsm_appconfig.h; fills the motor, drive, current-loop, observer and NXP fields "
           "it implies (pulab.model.mcat), typed fields win",
           ("MCAT inputs (JSON)", "MCAT 输入（JSON）"), kind="object"),
)
CONVENTIONS = {
    "voltage_base": "U_max = U_DCB_MAX/UmaxCoeff (hardware)",
    "current_base": "I_MAX (hardware)", "line_or_phase": "phase", "rms_or_peak": "peak",
    "clarke_k": "2/3 (GMCLIB Clarke; not read in a public file here)",
    "inductance_base": "none: L enters through Kp·I_max/U_max and the observer scales",
    "pi_form": "parallel, Ki·T_s folded in (÷2 trapezoidal)",
    "rounding": "ACC32()/FRAC16() macros: toward zero, saturating",
}
CONVENTIONS_ZH = {
    "voltage_base": "U_max = U_DCB_MAX/UmaxCoeff（硬件）",
    "current_base": "I_MAX（硬件）", "line_or_phase": "相", "rms_or_peak": "峰值",
    "clarke_k": "2/3（GMCLIB Clarke；此处未在公开文件中读到）",
    "inductance_base": "无：L 经 Kp·I_max/U_max 与观测器比例进入",
    "pi_form": "并联，Ki·T_s 合并（梯形离散时 ÷2）",
    "rounding": "ACC32()/FRAC16() 宏：向零，饱和",
}
#: Where the rounding rule was read; files whose printed numbers the tests reproduce.
FILES = {"rounding": SOURCES["nxp_types"], "worked_numbers": [SOURCES["nxp_appconfig"]]}


def u_max(udcb_max_v: float, coeff: float, rounded: bool = True) -> float:
    """U_max = U_DCB,max/coeff; ``rounded``: JavaScript ``Math.round(U/coeff·10)/10``."""
    u = udcb_max_v / coeff
    return math.floor(u * 10.0 + 0.5) / 10.0 if rounded else u


def _scales(opt: dict) -> tuple[float, float]:
    um = u_max(opt["udcb_max_v"], opt["u_max_coeff"], opt["round_u_max"])
    if isinstance(um, float) and um == 0.0:    # (over a box of a family proof: an interval)
        raise InputError("profiles.nxp.u_max_coeff", code="nxp_u_max_zero",
                         value=opt["udcb_max_v"] / opt["u_max_coeff"])
    return um, opt["i_max_a"]


def bases(ctx: dict, opt: dict) -> tuple:
    """U_max, I_max; L enters the observer scales per T_s: effective base U_max·T_s/I_max."""
    um, im = _scales(opt)
    return um, im, um / im * ctx["ts"]


def gain_fields(axis: str) -> tuple[str, str]:
    """``M1_D_KP_GAIN``/``M1_D_KI_GAIN`` or the Q-axis pair."""
    a = axis.upper()
    return f"M1_{a}_KP_GAIN", f"M1_{a}_KI_GAIN"


def gain_range(axis: str) -> tuple[int, int]:
    """acc32_t is a 32-bit long."""
    return -(1 << 31), (1 << 31) - 1


def _acc32(name, x, per_unit, unit, expr, source):
    return fixed(name, x, 32, 15, per_unit, unit, expr, source, rounding="zero", clamps=True,
                 fmt="ACC32 (Q16.15)")


def gains_to_ints(kp: float, ki: float, ctx: dict, opt: dict, axis: str) -> dict:
    """ACC32 Kp and Ki for SI gains kp [V/A], ki [V/(A·s)]."""
    um, im = _scales(opt)
    k = 2.0 if opt["trapezoidal"] else 1.0
    kp_name, ki_name = gain_fields(axis)
    return {kp_name: _acc32(kp_name, kp * im / um, um / im, "V/A", "kp·I_max/U_max",
                            SOURCES["nxp_cloop"]),
            ki_name: _acc32(ki_name, ki * ctx["ts"] / k * im / um, um / im * k / ctx["ts"],
                            "V/(A·s)", "ki·T_s/k·I_max/U_max", SOURCES["nxp_cloop"])}


def ints_to_gains(kp_int: int, ki_int: int, ctx: dict, opt: dict, axis: str) -> tuple:
    """SI kp, ki of stored ACC32 gains."""
    um, im = _scales(opt)
    k = 2.0 if opt["trapezoidal"] else 1.0
    return kp_int / 32768.0 * um / im, ki_int / 32768.0 * um / im * k / ctx["ts"]


def profile(ctx: dict, opt: dict) -> dict:
    """NXP constants: current-loop gains and the back-EMF observer scales."""
    um, im = _scales(opt)
    em = opt["e_max_v"] if opt["e_max_v"] is not None else um
    board = board_constants(ctx, opt)
    return {"inputs": {**opt, "u_max_v": um, "e_max_v": em,
                       "w_max_rad_s": TWO_PI * ctx["f_base"]},
            "constants": {**constants(ctx, opt), **board}, "board": list(board)}


def board_constants(ctx: dict, opt: dict) -> dict:
    """``M1_I_MAX`` and ``M1_U_DCB_MAX`` as the appconfig writes them (float literals, ``F``),
    when the board's current or bus chain sets them: I_MAX is the ± measurable current (the
    FRAC16 full scale of a phase current), U_DCB_MAX the bus ADC full scale."""
    b, out = ctx.get("board") or {}, {}
    if b.get("current"):
        out["M1_I_MAX"] = real("M1_I_MAX", opt["i_max_a"], "A",
                               "V_ref/(2·R_shunt·G): the ± measurable current", SOURCES["nxp_appconfig"],
                               single=True)
    if b.get("bus"):
        out["M1_U_DCB_MAX"] = real("M1_U_DCB_MAX", opt["udcb_max_v"], "V",
                                   "V_ref·(R_top + R_bottom)/R_bottom", SOURCES["nxp_appconfig"],
                                   single=True)
    return out


def constants(ctx: dict, opt: dict) -> dict:
    """The ACC32 and FRAC16 integers of :func:`profile` (the inputs may be intervals: a
    family proof; the theta gain's shift is then a choice, ``nxp.M1_TO_THETA_SHIFT``)."""
    um, im = _scales(opt)
    em = opt["e_max_v"] if opt["e_max_v"] is not None else um
    ts, rs, ld, lq = ctx["ts"], ctx["rs"], ctx["ld"], ctx["lq"]
    w_max = TWO_PI * ctx["f_base"]
    out = {}
    for axis in ("d", "q"):
        out.update(gains_to_ints(*ctx["gains"][axis], ctx, opt, axis))
    den = ld + ts * rs
    src = SOURCES["nxp_bemf"]
    out["M1_I_SCALE"] = _acc32("M1_I_SCALE", ld / den, 1.0, "", "L_d/(L_d + T_s·R_s)", src)
    out["M1_U_SCALE"] = _acc32("M1_U_SCALE", ts / den * um / im, im / um, "A/V",
                               "T_s/(L_d + T_s·R_s)·U_max/I_max", src)
    out["M1_E_SCALE"] = _acc32("M1_E_SCALE", ts / den * em / im, im / em, "A/V",
                               "T_s/(L_d + T_s·R_s)·E_max/I_max", src)
    out["M1_WI_SCALE"] = _acc32("M1_WI_SCALE", lq * ts / den * w_max, 1.0 / w_max, "s",
                                "L_q·T_s/(L_d + T_s·R_s)·ω_max", src)
    mant, shift = mantissa_shift(ts * w_max / math.pi, "nxp.M1_TO_THETA_SHIFT")
    out["M1_TO_THETA_GAIN"] = fixed("M1_TO_THETA_GAIN", mant, 16, 15, math.pi / ts, "rad/s",
                                    "T_s·ω_max/π = mantissa·2^shift", src, rounding="zero",
                                    clamps=True, fmt=f"FRAC16 · 2^{shift}", shift=shift)
    return out
