"""Inovance-style C2000 scaling (the seed's code) — a view of :mod:`pulab.profiles.inovance.code`.

The motor constants are :func:`pulab.profiles.inovance.code.vendor_results` (bit-exact C2000
statements); the current-loop integers are :func:`pulab.model.gains.current_pi` with
Inovance's own bases U_b = U_LL/√3, I_b = I_rms (seed 1.4-13), whatever the
report's ``conventions.base`` says:

    pm_kp = round(kp·I_b/U_b·2^12)   (Q12, seed 2.2-9)
    pm_ki = round(ki·Ts·I_b/U_b·2^16) (Q16, Ts folded in)

Its header is the report's own (:func:`pulab.profiles.inovance.header.c_header`).

Examples
--------
>>> ctx = {"u_rated": 17.0, "i_rated": 1.5, "ts": 1e-4}
>>> gains_to_ints(1.885, 4712.4, ctx, {}, "d")["pm_kp"]["value"]
1180
"""

from __future__ import annotations

from ...model.gains import current_pi, gains_from_integers
from ..common import SOURCES, SQRT3, TWO_PI, fixed
from .code import to_si

__all__ = ["OPTIONS", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "bases", "gain_fields",
           "gain_range", "gains_to_ints", "ints_to_gains", "profile"]

OPTIONS: tuple = ()
CONVENTIONS = {
    "voltage_base": "U_LL/√3 (rated, phase RMS)", "current_base": "I_rated (RMS)",
    "line_or_phase": "phase", "rms_or_peak": "RMS", "clarke_k": "√2/3",
    "inductance_base": "L_b = U_b/(I_b·2π·f_b)", "pi_form": "parallel, ki·Ts folded in (Q16)",
    "rounding": "C2000 integer statements (truncating /, >>)",
}
CONVENTIONS_ZH = {
    "voltage_base": "U_LL/√3（额定，相有效值）", "current_base": "I_rated（有效值）",
    "line_or_phase": "相", "rms_or_peak": "有效值", "clarke_k": "√2/3",
    "inductance_base": "L_b = U_b/(I_b·2π·f_b)", "pi_form": "并联，ki·Ts 合并（Q16）",
    "rounding": "C2000 整数语句（/ 与 >> 截断）",
}
#: Where the rounding rule was read; files whose printed numbers the tests reproduce.
FILES = {"rounding": SOURCES["seed"], "worked_numbers": [SOURCES["seed"]]}
_VENDOR = {  # report vendor result -> (SI input it stands for, unit, what the integer is)
    "Rpm": ("rs", "R_s/Z_b·2^16"), "LD": ("ld", "L_d/L_b·2^13"), "LQ": ("lq", "L_q/L_b·2^13"),
    "FreqPer": ("f_rated", "f_n/f_b·2^15"), "FluxRotor": ("psi_rms", "ψ_r/ψ_b·2^12"),
    "pm_maxout_vol": ("u_limit", "(U_dc/√2)/U_LL·2^12"),
    "maxu": ("u_limit", "(U_dc/√2)/U_LL·2^24"),
}


def _bases(ctx: dict) -> tuple[float, float]:
    return ctx["u_rated"] / SQRT3, ctx["i_rated"]


def bases(ctx: dict, opt: dict) -> tuple:
    """U_b = U_LL/√3, I_b = I_rms, L_b = U_b/(I_b·2π·f_b) (seed 1.4-13)."""
    u, i = _bases(ctx)
    return u, i, u / i / (TWO_PI * ctx["f_base"])


def gain_fields(axis: str) -> tuple[str, str]:
    """Names of the current-loop kp and ki integers (the same for both axes)."""
    return "pm_kp", "pm_ki"


def gain_range(axis: str) -> tuple[int, int]:
    """Integer range of pm_kp/pm_ki (long)."""
    return -(1 << 31), (1 << 31) - 1


def gains_to_ints(kp: float, ki: float, ctx: dict, opt: dict, axis: str) -> dict:
    """pm_kp (Q12) and pm_ki (Q16) for SI gains kp [V/A], ki [V/(A·s)]."""
    u_b, i_b = _bases(ctx)
    g = current_pi(kp, ki, 1.0, u_b, i_b, ctx["ts"])
    return {
        "pm_kp": fixed("pm_kp", g["kp_pu"], 32, 12, u_b / i_b, "V/A",
                       "kp·I_b/U_b·2^12", SOURCES["seed"] + " 2.2-9", value=g["pm_kp"],
                       fmt="Q12 (long)"),
        "pm_ki": fixed("pm_ki", g["ki_pu"] * ctx["ts"], 32, 16, u_b / i_b / ctx["ts"],
                       "V/(A·s)", "ki·Ts·I_b/U_b·2^16", SOURCES["seed"] + " 2.2-9",
                       value=g["pm_ki"], fmt="Q16 (long)"),
    }


def ints_to_gains(kp_int: int, ki_int: int, ctx: dict, opt: dict, axis: str) -> tuple:
    """SI kp, ki that pm_kp, pm_ki stand for (the inverse of seed 2.2-9)."""
    u_b, i_b = _bases(ctx)
    return gains_from_integers(kp_int, ki_int, u_b, i_b, ctx["ts"])


def profile(ctx: dict, opt: dict) -> dict:
    """The seed's integers for this motor, as profile constants, and the problems of its code."""
    out = {}
    for name, (si_key, expr) in _VENDOR.items():
        if name not in ctx["vendor"]:
            continue  # the firmware cannot compute it for this motor: firmware.inovance
        r = ctx["vendor"][name]
        out[name] = {"name": name, "value": r["value"], "ideal": r["ideal"],
                     "error_pct": r["error_pct"], "format": f"Q{r['q']} ({r['type']})",
                     "q": r["q"], "word_bits": 16 if r["type"] == "Uint16" else 32, "shift": 0,
                     "si": r["si"], "si_ideal": ctx[si_key], "unit": r["unit"],
                     "scale": to_si(name, 1 << r["q"], ctx["raw"], ctx["inductance_unit"]),
                     "expression": expr, "source": SOURCES["seed"], "flags": r["flags"]}
    for axis in ("d", "q"):
        kp, ki = ctx["gains"][axis]
        for k, rec in gains_to_ints(kp, ki, ctx, opt, axis).items():
            rec["name"] = f"{k}_{axis}"
            out[rec["name"]] = rec
    # what its C code cannot compute for this motor (the report's firmware.inovance)
    return {"inputs": {}, "constants": out, "problems": ctx["firmware_problems"]}

