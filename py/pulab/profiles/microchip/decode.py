"""Microchip motorBench / MCAF parameter headers read back (``decode_header``).

motorBench writes each constant as an integer ``NAME`` with ``NAME_Q`` and, in
``motor_params.h``, ``NAME_NORM``, ``NAME_SCALE`` (engineering units per 1.0) and ``NAME_ENG``;
its comment prints the same twice, e.g. (``microchip-pic-avr-solutions/
motorbench-release-collateral : …/motorBench/parameters/motor_params.h``)::

    #define MCAF_MOTOR_RS   4829   // Q15(  0.14737) = +240.99626 mohm = +241.00000 mohm - 0.0015%

the stored value in Q, in SI, the value it was designed for, and the error. ``foc_params.h``
has no ``_SCALE`` for the PI gains: their scale is read from the comment (its printed SI value
over its printed per-unit value, 5 to 6 digits). So each macro decodes to
``NAME/2^Q·SCALE``, is checked against its own comment (``comment_stale``: the integer or its
scale was edited after generation), and a printed error of 1 % or more is a ``rounding``
finding. The design: R, L_d, L_q, ψ (V·s) and pole pairs from ``motor_params.h``; the current
PI kp [V/A] = KIP, ki [V/(A·s)] = KII, and the PWM period Δt = KIP's scale/KII's scale (the
integral gain's base is V_b/(I_b·Δt)); the speed PI KWP [A/(rad/s)], KWI [A/rad].

Examples
--------
>>> d = decode_header({"KIP": 12007, "KIP_Q": 15, "KII": 1770, "KII_Q": 15},
...     {"KIP": "Q15(  0.36642) = +599.22182 mV/A        = +599.22866 mV/A        - 0.0011%",
...      "KII": "Q15(  0.05402) =   +1.76667 kV/A/s      =   +1.76709 kV/A/s      - 0.0236%"})
>>> round(d["macros"]["KIP"]["si"], 5), round(d["design"]["ts_s"] * 1e6, 1)
(0.59923, 50.0)
"""

from __future__ import annotations

import re

from ..decoding import check, current_loop, macro, result

__all__ = ["decode_header"]

_NUM = r"[-+]?\d+(?:\.\d+)?"
_COMMENT = re.compile(rf"Q(\d\d?)\(\s*({_NUM})\)\s*=\s*({_NUM})\s*(\S+)\s*=\s*({_NUM})\s*(\S+)\s*"
                      rf"([-+])\s*(\d+(?:\.\d+)?)%")
_PREFIX = {"m": 1e-3, "u": 1e-6, "µ": 1e-6, "n": 1e-9, "k": 1e3, "M": 1e6}
#: name → (SI unit, meaning) of the constants this decoder reads.
_KNOWN = {
    "MCAF_MOTOR_RS": ("Ω", "stator resistance, line-to-neutral"),
    "MCAF_MOTOR_LD_BASE_DT": ("H", "d-axis inductance (base V_b·Δt/I_b)"),
    "MCAF_MOTOR_LQ_BASE_DT": ("H", "q-axis inductance (base V_b·Δt/I_b)"),
    "MCAF_MOTOR_LS_BASE_DT": ("H", "stator inductance (base V_b·Δt/I_b)"),
    "MCAF_MOTOR_LD_BASE_OMEGA_E": ("H", "d-axis inductance (base V_b/(I_b·ω_b))"),
    "MCAF_MOTOR_LQ_BASE_OMEGA_E": ("H", "q-axis inductance (base V_b/(I_b·ω_b))"),
    "MCAF_MOTOR_KE": ("V/(rad/s)", "back-EMF constant, line-to-neutral 0-pk"),
    "MCAF_MOTOR_PSI_BASE_OMEGA_E": ("V·s", "rotor flux (base V_b/ω_b)"),
    "MCAF_MOTOR_PSI_BASE_DT": ("V·s", "rotor flux (base V_b·Δt)"),
    "KIP": ("V/A", "current PI kp"), "KII": ("V/(A·s)", "current PI ki"),
    "KWP": ("A/(rad/s)", "speed PI kp"), "KWI": ("A/rad", "speed PI ki"),
    "MCAF_CURRENT_CTRL_D_OUT_LIMIT": ("", "d-axis output limit (line-to-line fraction)"),
    "MCAF_CURRENT_CTRL_Q_OUT_LIMIT": ("", "q-axis output limit (line-to-line fraction)"),
}
_PLAIN = {"MOTOR_PARAM_R": ("Ω", "stator resistance, line-to-neutral"),
          "MOTOR_PARAM_L": ("H", "stator inductance, line-to-neutral"),
          "MOTOR_PARAM_KE": ("V/(rad/s)", "back-EMF constant, line-to-neutral 0-pk"),
          "MOTOR_PARAM_J": ("kg·m²", "inertia"),
          "MOTOR_PARAM_POLE_PAIRS": ("", "pole pairs")}
READS = tuple(_KNOWN) + tuple(_PLAIN) + tuple(f"{n}_Q" for n in _KNOWN) + \
    tuple(f"{n}_SCALE" for n in _KNOWN)


def _si_unit(number: str, unit: str) -> tuple:
    """(value in SI, unit without its prefix) of a printed ``+599.22182 mV/A``."""
    x = float(number)
    if len(unit) > 1 and unit[0] in _PREFIX and unit[1:2] not in ("", "/"):
        return x * _PREFIX[unit[0]], unit[1:]
    return x, unit


def _against_comments(v: dict, notes: dict) -> dict:
    """Every integer whose comment prints the value it was designed for, re-derived from it:
    name → the integer minus round(designed/scale·2^Q), the scale being the comment's printed SI
    value (8 digits) over the integer: the generator's own rounding checked (an
    integer edited after generation is ``comment_stale``: its printed Q value no longer
    matches)."""
    out = {}
    for n, note in notes.items():
        c = _COMMENT.search(note) if isinstance(note, str) else None
        if c is None or not isinstance(v.get(n), int) or not v[n]:
            continue
        got, _ = _si_unit(c[3], c[4])
        want, _ = _si_unit(c[5], c[6])
        if got:
            out[n] = v[n] - round(want / got * v[n])
    return out


def decode_header(values: dict, notes: dict) -> dict:
    """Microchip macros in SI, the design and the checks (:mod:`pulab.profiles.decoding`)."""
    v = values
    has = v.keys().__contains__
    out = {n: macro(v[n], u, m, n) for n, (u, m) in _PLAIN.items() if has(n)}
    checks: list = []
    scales: dict = {}
    for n, (unit, meaning) in _KNOWN.items():
        if not has(n):
            continue
        c = _COMMENT.search(notes.get(n, ""))
        q = v.get(f"{n}_Q", int(c[1]) if c else None)
        if not isinstance(q, int) or not 0 <= q <= 62:
            continue
        norm = v[n] / 2.0 ** q
        scale, source = v.get(f"{n}_SCALE"), f"{n}_SCALE"
        if c is not None:
            got, _ = _si_unit(c[3], c[4])
            said_norm = float(c[2])
            if scale is None and said_norm:
                scale, source = got / said_norm, "its comment's SI value / its Q value"
            # the printed Q value has 5 decimals: the integer must round to it
            if abs(norm - said_norm) > 0.6e-5:
                checks.append(check("warning", "comment_stale", [n], macro=n, value=v[n],
                                    got=f"Q{q}({norm:.5f})", said=f"Q{c[1]}({c[2]})"))
            err = float(c[8]) * (1 if c[7] == "+" else -1)
            if abs(err) >= 1.0:
                design_si, _ = _si_unit(c[5], c[6])
                checks.append(check("warning", "rounding", [n], macro=n, value=v[n],
                                    ideal=f"{design_si:.6g} {unit}", err=err))
        if scale is None:
            continue
        scales[n] = scale
        out[n] = macro(norm * scale, unit, meaning, f"{n}/2^{q}·{source}")
    design: dict = {"assumed": [], "comment_checked": _against_comments(v, notes)}
    g = {n: out[n]["si"] for n in out}
    motor: dict = {}
    for key, names in (("rs_ohm", ("MCAF_MOTOR_RS", "MOTOR_PARAM_R")),
                       ("ld_h", ("MCAF_MOTOR_LD_BASE_DT", "MCAF_MOTOR_LD_BASE_OMEGA_E")),
                       ("lq_h", ("MCAF_MOTOR_LQ_BASE_DT", "MCAF_MOTOR_LQ_BASE_OMEGA_E"))):
        x = next((g[n] for n in names if n in g), None)
        if x:
            motor[key] = x
    if has("MOTOR_PARAM_POLE_PAIRS"):
        motor["pole_pairs"] = int(v["MOTOR_PARAM_POLE_PAIRS"])
    psi = next((g[n] for n in ("MCAF_MOTOR_PSI_BASE_OMEGA_E", "MCAF_MOTOR_PSI_BASE_DT",
                               "MCAF_MOTOR_KE", "MOTOR_PARAM_KE") if n in g), None)
    design["psi_wb"] = psi
    ts = scales["KIP"] / scales["KII"] if scales.get("KIP") and scales.get("KII") else None
    design["ts_s"] = ts
    drive = {"ts_s": ts} if ts else {}
    design["input"] = {"motor": motor, "drive": drive}
    loops = {}
    if "KIP" in g and "KII" in g and "rs_ohm" in motor:
        for axis, key in (("d", "ld_h"), ("q", "lq_h")):
            c = current_loop(g["KIP"], g["KII"], motor["rs_ohm"], motor[key], ("KIP", "KII")) \
                if key in motor else None
            if c is not None:
                loops[axis] = c
        design["input"]["current_loop"] = {"method": "manual", "kp": g["KIP"], "ki": g["KII"]}
    design["current_loop"] = loops or None
    design["speed_loop"] = {"kp_a_per_rad_s": g.get("KWP"), "ki_a_per_rad": g.get("KWI")} \
        if "KWP" in g else None
    design["observer"] = None
    return result(READS, "msp430", out, design, checks)
