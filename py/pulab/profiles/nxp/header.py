"""NXP MCAT / RTCESL-style C header of the NXP profile (its constants as ``#define`` lines)."""

from __future__ import annotations

from decimal import Decimal

from ..headers import define, define_float, guard

__all__ = ["header"]

#: MCAT's order of the macros in a fixed-point m1_pmsm_appconfig.h, by its section comments.
MCAT_ORDER = (
    ("PARAMETERS", ("M1_N_MAX", "M1_FREQ_MAX", "M1_I_MAX", "M1_U_MAX", "M1_E_MAX", "M1_MOTOR_PP",
                    "M1_I_PH_NOM", "M1_N_NOM", "M1_U_DCB_MAX", "M1_U_DCB_TRIP",
                    "M1_U_DCB_UNDERVOLTAGE", "M1_U_DCB_OVERVOLTAGE", "M1_N_OVERSPEED", "M1_N_MIN",
                    "M1_E_BLOCK_TRH", "M1_E_BLOCK_PER", "M1_CALIB_DURATION", "M1_FAULT_DURATION",
                    "M1_FREEWHEEL_DURATION", "M1_SCALAR_UQ_MIN", "M1_ALIGN_VOLTAGE",
                    "M1_ALIGN_DURATION", "M1_UDCB_IIR_B0", "M1_UDCB_IIR_B1", "M1_UDCB_IIR_A1",
                    "M1_SCALAR_VHZ_FACTOR_GAIN", "M1_SCALAR_VHZ_FACTOR_SHIFT",
                    "M1_SCALAR_INTEG_GAIN", "M1_SCALAR_RAMP_UP", "M1_SCALAR_RAMP_DOWN")),
    ("CURRENTLOOP", ("M1_D_KP_GAIN", "M1_D_KI_GAIN", "M1_Q_KP_GAIN", "M1_Q_KI_GAIN",
                     "M1_CLOOP_LIMIT")),
    ("SPEEDLOOP", ("M1_SPEED_RAMP_UP", "M1_SPEED_RAMP_DOWN", "M1_SPEED_LOOP_HIGH_LIMIT",
                   "M1_SPEED_LOOP_LOW_LIMIT", "M1_SPEED_PI_PROP_GAIN", "M1_SPEED_PI_INTEG_GAIN",
                   "M1_SPEED_IIR_B0", "M1_SPEED_IIR_B1", "M1_SPEED_IIR_A1")),
    ("SENSORS", ("M1_POSPE_ENC_PULSES", "M1_POSPE_ENC_DIRECTION", "M1_POSPE_ENC_N_MIN",
                 "M1_POSPE_MECH_POS_GAIN", "M1_POS_P_PROP_GAIN", "M1_POSPE_TO_KP_SHIFT",
                 "M1_POSPE_TO_KP_GAIN", "M1_POSPE_TO_KI_SHIFT", "M1_POSPE_TO_KI_GAIN",
                 "M1_POSPE_TO_THETA_SHIFT", "M1_POSPE_TO_THETA_GAIN")),
    ("SENSORLESS", ("M1_OL_START_RAMP_INC", "M1_OL_START_I", "M1_MERG_SPEED_TRH",
                    "M1_MERG_COEFF", "M1_I_SCALE", "M1_U_SCALE", "M1_E_SCALE", "M1_WI_SCALE",
                    "M1_BEMF_DQ_KP_GAIN", "M1_BEMF_DQ_KI_GAIN", "M1_TO_KP_SHIFT", "M1_TO_KP_GAIN",
                    "M1_TO_KI_SHIFT", "M1_TO_KI_GAIN", "M1_TO_THETA_SHIFT", "M1_TO_THETA_GAIN",
                    "M1_TO_SPEED_IIR_B0", "M1_TO_SPEED_IIR_B1", "M1_TO_SPEED_IIR_A1")))
_Q = {"FRAC16": 15, "FRAC32": 31, "ACC32": 15}


def _six(x: float) -> str:
    """x as MCAT prints a number (its mcat.js, nxp-mcuxpresso/mcux-motor_control :
    freemaster/pmsm_frac/mcat/js/mcat.js): an integer with ".0"; a number JavaScript writes
    with fewer than 6 decimals as JavaScript writes it (0.0025, 16.384); any other to 6
    significant digits with their trailing zeros (0.0209740, 0.00156250), positional.

    >>> _six(4400.0), _six(0.0025), _six(0.0015625), _six(2 / 3 * 1e-4)
    ('4400.0', '0.0025', '0.00156250', '0.0000666667')
    """
    if x == int(x):
        return f"{int(x)}.0"
    short = format(Decimal(repr(x)), "f")  # JavaScript's and Python's shortest digits agree
    if len(short.split(".")[1]) < 6:
        return short
    return format(Decimal(f"{x:#.6g}"), "f")


def mcat_define(name: str, c: dict) -> str:
    """One line as MCAT prints it: ``FRAC16(x)``/``FRAC32(x)``/``ACC32(x)`` with the argument
    as MCAT prints a number (:func:`_six`), ``(n)`` for an integer, ``(xF)`` for a float.

    >>> from pulab.profiles.common import fixed
    >>> c = fixed("M1_N_MIN", 300 / 4400, 16, 15, 4400.0, "rpm", "", "", fmt="FRAC16")
    >>> mcat_define("M1_N_MIN", c)
    '#define M1_N_MIN FRAC16(0.0681818)'
    """
    if c.get("real"):
        return f"#define {name} ({_six(c['ideal'])}F)"
    wrap = c["format"].split(" ")[0]
    if wrap in _Q:
        return f"#define {name} {wrap}({_six(c['ideal'] / 2 ** _Q[wrap])})"
    return f"#define {name} ({c['value']})"


def _mcat_header(c: dict) -> str:
    """MCAT's layout (its section comments and order); macros the profile has not are left out."""
    out = ["#ifndef __M1_PMSM_APPCONFIG_H ", "#define __M1_PMSM_APPCONFIG_H ", ""]
    for section, names in MCAT_ORDER:  # a section without macros has no comment (MCAT's)
        lines = [mcat_define(n, c[n]) for n in names if n in c]
        out += [f"/* {section}*/"] + lines if lines else []
    return "\n".join(out + ["#endif /* __M1_PMSM_APPCONFIG_H */", ""])


def header(p: dict, ctx: dict, r: dict) -> str:
    """An ``m1_pmsm_appconfig.h``-style block (integers in place of ACC32()/FRAC16()); with
    ``profiles.nxp.mcat``, MCAT's own layout, order and wrappers (:func:`mcat_define`)."""
    o, c = p["inputs"], p["constants"]
    if o.get("mcat"):
        return _mcat_header(c)
    body = ["/* Application scales */",
            define_float("M1_I_MAX", o["i_max_a"], "A"),
            define_float("M1_U_DCB_MAX", o["udcb_max_v"], "V"),
            define_float("M1_U_MAX", o["u_max_v"], "V = U_DCB_MAX/UmaxCoeff"),
            define_float("M1_E_MAX", o["e_max_v"], "V"),
            define_float("M1_W_MAX", o["w_max_rad_s"], "rad/s electrical"),
            "", "/* Current loop (parallel PI) and back-EMF observer, ACC32 = Q16.15 */"]
    for k, r in c.items():
        if r.get("real"):
            continue    # M1_I_MAX, M1_U_DCB_MAX: the scales above
        if k == "M1_TO_THETA_GAIN":
            body.append(define(k, r, "int16_t"))
            if "M1_TO_THETA_SHIFT" not in c:  # a constant of its own with an observer section
                body.append(f"#define {'M1_TO_THETA_SHIFT':<30} {r['shift']:>7}")
        else:  # FRAC16 (and the sensorless shifts) are 16-bit words, ACC32/FRAC32 32-bit
            body.append(define(k, r, "int16_t" if r["word_bits"] == 16 else "int32_t"))
    return guard("M1_PMSM_APPCONFIG_PULAB_H",
                 ["NXP MCAT-style m1_pmsm_appconfig.h block generated by pu-lab.",
                  "Integers are what ACC32(x)/FRAC16(x) store: x*2^15 toward zero, saturated."],
                 body)
