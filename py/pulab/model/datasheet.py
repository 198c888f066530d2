"""Datasheet entry: what motor datasheets print, converted into the SI fields of ``motor``.

A datasheet gives speed in rpm, the back-EMF constant per 1000 rpm (line to line,
RMS or peak), R and L measured between two terminals, sometimes only a DC-bus
voltage.  The report's ``motor`` section wants the rated frequency, the line
RMS back-EMF at that frequency and per-phase values of the equivalent star.
Each conversion is returned with its formula and result so the reader can check
it by hand.

Conventions (sinusoidal PMSM, three phases)::

    f_n     = n·p/60                               (n in rpm, p pole pairs)
    E_LL    = Ke·n/1000            (Ke in V/krpm, RMS)   or  /√2 when Ke is peak
    Ke_SI   = E_LL / ω_m           (V·s/rad, line-to-line RMS per mechanical rad/s)
    kT      = √3·Ke_SI             (N·m per A RMS phase current; T = 3·p·ψ_rms·I)
    ψ_pk    = √2·E_LL/(√3·ω_e)     (Wb, phase flux amplitude; ψ_rms = ψ_pk/√2)
    R_ph    = R_LL/2, L_ph = L_LL/2 (equivalent star; a delta phase is 3·R_LL/2,
                                     which is the same star equivalent)
    U_LL    = U_dc/√2              (largest line RMS voltage of linear SVPWM)

Examples
--------
>>> motor, conv = apply({"speed_rpm": 3000, "ke_v_per_krpm": 44.38, "ke_measure": "peak",
...     "rs_line_ohm": 2.78, "l_line_h": 0.00506}, {"pole_pairs": 4, "rated_voltage_v": 220,
...     "rated_current_a": 2.8}, {})[:2]
>>> motor["rated_freq_hz"], round(motor["bemf_v"], 4), motor["rs_ohm"], motor["ld_h"]
(200.0, 94.1442, 1.39, 0.00253)
>>> [c["field"] for c in conv]
['motor.rated_freq_hz', 'motor.bemf_v', 'motor.rs_ohm', 'motor.ld_h', 'motor.lq_h']
"""

from __future__ import annotations

import math

from ..schema.errors import InputError
from ..schema.fields import FIELD, section_fields
from ..schema.validate import value

__all__ = ["FIELDS", "KE_FIELDS", "apply", "mechanical"]

SQRT2 = math.sqrt(2.0)
SQRT3 = math.sqrt(3.0)

#: Datasheet keys; units in the names (the schema's ``datasheet`` section).
FIELDS = tuple(f.key for f in section_fields("datasheet"))
#: The back-EMF sources, in order of preference; more than one is an error.
KE_FIELDS = ("ke_v_per_krpm", "ke_v_s_per_rad", "kt_nm_per_a", "psi_wb")
#: Which motor field each datasheet value sets (for the "both given" error).
_SETS = {"speed_rpm": ("rated_freq_hz",), "ke_v_per_krpm": ("bemf_v",),
         "ke_v_s_per_rad": ("bemf_v",), "kt_nm_per_a": ("bemf_v",), "psi_wb": ("bemf_v",),
         "rs_line_ohm": ("rs_ohm",), "l_line_h": ("ld_h", "lq_h"), "ld_line_h": ("ld_h",),
         "lq_line_h": ("lq_h",), "dc_bus_v": ("rated_voltage_v",)}


def _positive(ds: dict, key: str) -> float:
    return value(FIELD[f"datasheet.{key}"], ds[key])


def _choice(ds: dict, key: str) -> str:
    f = FIELD[f"datasheet.{key}"]
    if key in ds:
        return value(f, ds[key])
    if f.default is None:
        raise InputError(f.path, code="required_choice", choices=", ".join(f.choices))
    return f.default


def _step(field: str, label: str, label_zh: str, formula: str, value: float, unit: str,
          sources: list) -> dict:
    return {"field": field, "label": label, "label_zh": label_zh, "formula": formula,
            "value": value, "unit": unit, "from": sources}


def _g(x: float) -> str:
    return f"{x:.6g}"


def apply(ds: dict, motor: dict, drive: dict) -> tuple[dict, list, dict]:
    """Fill ``motor`` (and a missing ``drive.udc_v``) from the datasheet section.

    Parameters
    ----------
    ds : dict
        The ``datasheet`` section, unknown keys already rejected, nulls dropped.
    motor, drive : dict
        The raw ``motor`` and ``drive`` sections as given (not yet validated);
        ``motor.pole_pairs`` must be a valid integer when speed is converted.

    Returns
    -------
    (motor, conversions, drive) : (dict, list of dict, dict)
        New ``motor``/``drive`` dicts with the derived fields added, and one entry per
        conversion: ``field, label, label_zh, formula, value, unit, from``.

    Raises
    ------
    InputError
        A datasheet value and the motor field it would set both given (the message
        names both), two back-EMF sources, a bad number or choice.
    """
    motor, drive = dict(motor), dict(drive)
    for key, targets in _SETS.items():
        if key in ds:
            for t in targets:
                if t in motor:
                    raise InputError(f"datasheet.{key}", code="both_given", other=f"motor.{t}")
    sources = [k for k in KE_FIELDS if k in ds]
    if len(sources) > 1:
        raise InputError(f"datasheet.{sources[1]}", code="both_bemf", other=f"datasheet.{sources[0]}")
    if "ke_measure" in ds and not {"ke_v_per_krpm", "ke_v_s_per_rad"} & set(ds):
        raise InputError("datasheet.ke_measure", code="used_with_either",
                         a="datasheet.ke_v_per_krpm", b="ke_v_s_per_rad")
    if "kt_current" in ds and "kt_nm_per_a" not in ds:
        raise InputError("datasheet.kt_current", code="used_with", other="datasheet.kt_nm_per_a")
    conv: list = []
    p = motor.get("pole_pairs")
    if "speed_rpm" in ds or sources:
        if p is None:
            raise InputError("motor.pole_pairs", code="required")
        p = value(FIELD["motor.pole_pairs"], p)
    if "speed_rpm" in ds:
        n = _positive(ds, "speed_rpm")
        motor["rated_freq_hz"] = n * p / 60.0
        conv.append(_step("motor.rated_freq_hz", "rated frequency", "额定频率",
                          f"f_n = n·p/60 = {_g(n)}·{p}/60", motor["rated_freq_hz"], "Hz",
                          ["datasheet.speed_rpm", "motor.pole_pairs"]))
    if sources:
        if "rated_freq_hz" not in motor:
            raise InputError("datasheet.speed_rpm", code="required_to_convert",
                             source=f"datasheet.{sources[0]}", other="motor.rated_freq_hz")
        # Only the sign here: a value out of range is named where it came from, by normalize.
        f_n = value(FIELD["motor.rated_freq_hz"]._replace(lo=None, hi=None), motor["rated_freq_hz"])
        n = 60.0 * f_n / p  # rpm at rated frequency
        w_m = 2.0 * math.pi * n / 60.0
        src = sources[0]
        x = _positive(ds, src)
        if src in ("ke_v_per_krpm", "ke_v_s_per_rad"):
            measure = _choice(ds, "ke_measure")
            k = 1.0 if measure == "rms" else 1.0 / SQRT2
            if src == "ke_v_per_krpm":
                e = x * n / 1000.0 * k
                formula = f"E_LL = Ke·n/1000{'' if k == 1 else '/√2'} = {_g(x)}·{_g(n)}/1000" \
                          + ("" if k == 1 else "/√2")
            else:
                e = x * w_m * k
                formula = f"E_LL = Ke·2π·n/60{'' if k == 1 else '/√2'} = {_g(x)}·2π·{_g(n)}/60" \
                          + ("" if k == 1 else "/√2")
            sources_used = [f"datasheet.{src}", "datasheet.ke_measure"]
        elif src == "kt_nm_per_a":
            k = 1.0 if _choice(ds, "kt_current") == "rms" else SQRT2
            e = x * k / SQRT3 * w_m
            formula = f"E_LL = kT{'' if k == 1 else '·√2'}/√3·2π·n/60 = {_g(x)}" \
                      f"{'' if k == 1 else '·√2'}/√3·2π·{_g(n)}/60"
            sources_used = ["datasheet.kt_nm_per_a", "datasheet.kt_current"]
        else:
            e = SQRT3 * 2.0 * math.pi * f_n * x / SQRT2
            formula = f"E_LL = √3·2π·f_n·ψ/√2 = √3·2π·{_g(f_n)}·{_g(x)}/√2"
            sources_used = ["datasheet.psi_wb"]
        motor["bemf_v"] = e
        conv.append(_step("motor.bemf_v", "back-EMF, line RMS at rated frequency",
                          "额定频率下的线反电势（有效值）", formula, e, "V",
                          sources_used + (["datasheet.speed_rpm"] if "speed_rpm" in ds
                                          else ["motor.rated_freq_hz"]) + ["motor.pole_pairs"]))
    winding = _choice(ds, "winding")
    if "winding" in ds and not {"rs_line_ohm", "l_line_h", "ld_line_h", "lq_line_h"} & set(ds):
        raise InputError("datasheet.winding", code="used_with_either", a="datasheet.rs_line_ohm",
                         b="l_line_h")
    if "l_line_h" in ds and ({"ld_line_h", "lq_line_h"} & set(ds)):
        other = "ld_line_h" if "ld_line_h" in ds else "lq_line_h"
        raise InputError(f"datasheet.{other}", code="both_given", other="datasheet.l_line_h")
    delta = "" if winding == "star" else "  (delta: R_Δ = 3·R_LL/2, star equivalent R_Δ/3)"
    for key, fields, sym in (("rs_line_ohm", ("rs_ohm",), "R"), ("l_line_h", ("ld_h", "lq_h"), "L"),
                             ("ld_line_h", ("ld_h",), "L_d"), ("lq_line_h", ("lq_h",), "L_q")):
        if key not in ds:
            continue
        x = _positive(ds, key)
        for f in fields:
            motor[f] = x / 2.0
            unit = "Ω" if sym == "R" else "H"
            conv.append(_step(f"motor.{f}", "resistance per phase, equivalent star" if sym == "R"
                              else f"{f[0].upper()}-axis inductance per phase, equivalent star",
                              "每相电阻（等效星形）" if sym == "R"
                              else f"每相 {f[0]} 轴电感（等效星形）",
                              f"{sym}_ph = {sym}_LL/2 = {_g(x)}/2{delta}", x / 2.0, unit,
                              [f"datasheet.{key}"] + (["datasheet.winding"] if "winding" in ds
                                                      else [])))
    if "dc_bus_v" in ds:
        u = _positive(ds, "dc_bus_v")
        motor["rated_voltage_v"] = u / SQRT2
        conv.append(_step("motor.rated_voltage_v", "rated line voltage (RMS) from the DC bus",
                          "由直流母线电压得到的额定线电压（有效值）",
                          f"U_LL = U_dc/√2 = {_g(u)}/√2", u / SQRT2, "V", ["datasheet.dc_bus_v"]))
        if "udc_v" not in drive:
            drive["udc_v"] = u
            conv.append(_step("drive.udc_v", "DC bus (drive.udc_v not given)",
                              "直流母线（未给出 drive.udc_v）", "U_dc = datasheet.dc_bus_v", u, "V",
                              ["datasheet.dc_bus_v"]))
    return motor, conv, drive


def mechanical(motor: dict, base: dict, psi_r_wb: float, convention: str) -> dict:
    """Mechanical quantities that the pole pairs give: speeds, torque base, kT, Ke.

    Parameters
    ----------
    motor : dict — normalized motor section (SI)
    base : dict — :func:`pulab.model.bases.bases` output
    psi_r_wb : float > 0, Wb — ψ_r in the report's convention
    convention : {'rms', 'peak', 'custom'}

    Returns
    -------
    dict
        ``pole_pairs``; ``rated_speed_rpm`` = 60·f_n/p, ``base_speed_rpm`` = 60·f_b/p;
        ``w_mech_b`` = ω_b/p (rad/s); ``torque_base_nm`` T_b = P_b/(ω_b/p);
        ``psi_pk_wb`` (phase flux amplitude); ``ke_v_s_per_rad`` (line RMS per mechanical
        rad/s); ``kt_nm_per_a`` (per A RMS, = √3·Ke); ``rated_torque_nm`` = kT·I_n;
        ``rated_torque_pu`` = T_n/T_b.

    Examples
    --------
    >>> from pulab.model.bases import bases
    >>> b = bases("rms", 220.0, 2.8, 200.0)
    >>> m = mechanical({"pole_pairs": 4, "rated_freq_hz": 200.0, "rated_current_a": 2.8,
    ...                 "bemf_v": 100.0}, b, 100.0 / (3 ** 0.5 * 2 * 3.141592653589793 * 200), "rms")
    >>> round(m["rated_speed_rpm"], 6), round(m["ke_v_s_per_rad"], 6), round(m["kt_nm_per_a"], 6)
    (3000.0, 0.31831, 0.551329)
    """
    p = motor["pole_pairs"]
    psi_rms = psi_r_wb if convention == "rms" else psi_r_wb / SQRT2
    w_mb = base["w_b"] / p
    kt = 3.0 * p * psi_rms
    t_b = base["P_b"] / w_mb
    torque = kt * motor["rated_current_a"]
    return {"pole_pairs": p, "rated_speed_rpm": 60.0 * motor["rated_freq_hz"] / p,
            "base_speed_rpm": 60.0 * base["f_b"] / p, "w_mech_b": w_mb, "torque_base_nm": t_b,
            "psi_pk_wb": SQRT2 * psi_rms, "ke_v_s_per_rad": kt / SQRT3, "kt_nm_per_a": kt,
            "rated_torque_nm": torque, "rated_torque_pu": torque / t_b}
