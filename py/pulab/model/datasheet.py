"""Datasheet entry: what motor datasheets print, converted into the SI fields of ``motor``.

A datasheet gives speed in rpm, the back-EMF constant per 1000 rpm or per rad/s (line
to line or per phase, RMS or peak), a speed constant Kv in rpm/V, a torque constant per
A RMS or peak, the magnet flux, R and L measured between two terminals or per phase
(star or delta), sometimes only a DC-bus voltage.  The report's ``motor`` section wants the rated frequency, the line
RMS back-EMF at that frequency and per-phase values of the equivalent star.
Each conversion is returned with its formula and result so the reader can check
it by hand.

Conventions (sinusoidal PMSM, three phases)::

    f_n     = n·p/60                               (n in rpm, p pole pairs)
    E_LL    = Ke·n/1000            (Ke in V/krpm, RMS)   or  /√2 when Ke is peak,
                                   ·√3 when Ke is per phase
    E_LL    = n/Kv                 (Kv in rpm/V, RMS)    or  /√2 when Kv is peak
    Ke_SI   = E_LL / ω_m           (V·s/rad, line-to-line RMS per mechanical rad/s)
    kT      = √3·Ke_SI             (N·m per A RMS phase current; T = 3·p·ψ_rms·I)
    ψ_pk    = √2·E_LL/(√3·ω_e)     (Wb, phase flux amplitude; ψ_rms = ψ_pk/√2)
    R_ph    = R_LL/2, L_ph = L_LL/2 (equivalent star; a delta phase is 3·R_LL/2,
                                     which is the same star equivalent)
    R_ph    = R_Δ/3                (a delta phase given per phase: its star equivalent)
    U_LL    = U_dc/√2              (largest line RMS voltage of linear SVPWM)

Examples
--------
>>> motor, conv = apply({"speed_rpm": 3000, "ke_v_per_krpm": 44.38, "ke_measure": "peak",
...     "rs_line_ohm": 2.78, "l_line_h": 0.00506}, {"pole_pairs": 4, "rated_voltage_v": 220,
...     "rated_current_a": 2.8}, {})[:2]
>>> motor["rated_freq_hz"], round(motor["bemf_v"], 4), motor["rs_ohm"], motor["ld_h"]
(200.0, 94.1442, 1.39, 0.00253)
>>> [c["label"] for c in conv][3:]
['d-axis inductance per phase, equivalent star', 'q-axis inductance per phase, equivalent star']
>>> [c["field"] for c in conv]
['motor.rated_freq_hz', 'motor.bemf_v', 'motor.rs_ohm', 'motor.ld_h', 'motor.lq_h']
"""

from __future__ import annotations

import math

from ..schema.errors import InputError
from ..schema.fields import FIELD, section_fields
from ..schema.validate import value

__all__ = ["FIELDS", "KE_FIELDS", "SETS", "apply", "mechanical"]

SQRT2 = math.sqrt(2.0)
SQRT3 = math.sqrt(3.0)

#: Datasheet keys; units in the names (the schema's ``datasheet`` section).
FIELDS = tuple(f.key for f in section_fields("datasheet"))
#: The back-EMF sources, in order of preference (``bemf_from`` picks another).
KE_FIELDS = ("ke_v_per_krpm", "ke_v_s_per_rad", "kv_rpm_per_v", "kt_nm_per_a", "psi_wb")
#: R and L as printed: (key, motor fields it sets, symbol, measured between).
_WINDING = (("rs_line_ohm", ("rs_ohm",), "R", "line"), ("rs_phase_ohm", ("rs_ohm",), "R", "phase"),
            ("l_line_h", ("ld_h", "lq_h"), "L", "line"),
            ("l_phase_h", ("ld_h", "lq_h"), "L", "phase"),
            ("ld_line_h", ("ld_h",), "L_d", "line"), ("ld_phase_h", ("ld_h",), "L_d", "phase"),
            ("lq_line_h", ("lq_h",), "L_q", "line"), ("lq_phase_h", ("lq_h",), "L_q", "phase"))
#: Which motor fields each datasheet value sets (the "both given" error, the required hint).
SETS = {"speed_rpm": ("rated_freq_hz",), **{k: ("bemf_v",) for k in KE_FIELDS},
        **{k: fields for k, fields, _, _ in _WINDING}, "dc_bus_v": ("rated_voltage_v",)}
#: Choices that qualify a value: (choice, the values it is used with).
_QUALIFIERS = (("ke_measure", ("ke_v_per_krpm", "ke_v_s_per_rad")),
               ("ke_between", ("ke_v_per_krpm", "ke_v_s_per_rad")),
               ("kv_measure", ("kv_rpm_per_v",)), ("kt_current", ("kt_nm_per_a",)),
               ("winding", tuple(k for k, _, _, _ in _WINDING)))


def _positive(ds: dict, key: str) -> float:
    return value(FIELD[f"datasheet.{key}"], ds[key])


def _choice(ds: dict, key: str) -> str:
    f = FIELD[f"datasheet.{key}"]
    if key in ds:
        return value(f, ds[key])
    if f.default is None:
        raise InputError(f.path, code="required_choice", choices=", ".join(f.choices))
    return f.default


def both_given(field: str, other: str, target: str) -> InputError:
    """The error for two inputs that set the same motor field: it names both, and
    ``params.other`` is the second path (so a page can mark both)."""
    return InputError(field, code="both_given", this=field, other=other,
                      target={"label": target}, this_label={"label": field},
                      other_label={"label": other})


def _step(field: str, label: str, label_zh: str, formula: str, value: float, unit: str,
          sources: list) -> dict:
    return {"field": field, "label": label, "label_zh": label_zh, "formula": formula,
            "value": value, "unit": unit, "from": sources}


def _g(x: float) -> str:
    return f"{x:.6g}"


def _bemf(ds: dict, src: str, n: float, f_n: float) -> tuple[float, str, list]:
    """The line RMS back-EMF at rated speed ``n`` [rpm] (``f_n`` [Hz]) that datasheet value
    ``src`` implies: (E_LL [V], formula, the datasheet fields used)."""
    x = _positive(ds, src)
    used = [f"datasheet.{src}"]
    if src in ("ke_v_per_krpm", "ke_v_s_per_rad"):
        peak = _choice(ds, "ke_measure") == "peak"
        phase = _choice(ds, "ke_between") == "phase"
        k = (SQRT3 if phase else 1.0) / (SQRT2 if peak else 1.0)
        tail = ("·√3" if phase else "") + ("/√2" if peak else "")
        if src == "ke_v_per_krpm":
            e, formula = x * n / 1000.0 * k, f"E_LL = Ke·n/1000{tail} = {_g(x)}·{_g(n)}/1000{tail}"
        else:
            e = x * 2.0 * math.pi * n / 60.0 * k
            formula = f"E_LL = Ke·2π·n/60{tail} = {_g(x)}·2π·{_g(n)}/60{tail}"
        return e, formula, used + ["datasheet.ke_measure"] + (
            ["datasheet.ke_between"] if "ke_between" in ds else [])
    if src == "kv_rpm_per_v":
        peak = _choice(ds, "kv_measure") == "peak"
        tail = "/√2" if peak else ""
        return (n / x / (SQRT2 if peak else 1.0), f"E_LL = n/Kv{tail} = {_g(n)}/{_g(x)}{tail}",
                used + (["datasheet.kv_measure"] if "kv_measure" in ds else []))
    if src == "kt_nm_per_a":
        k = 1.0 if _choice(ds, "kt_current") == "rms" else SQRT2
        tail = "" if k == 1 else "·√2"
        return (x * k / SQRT3 * 2.0 * math.pi * n / 60.0,
                f"E_LL = kT{tail}/√3·2π·n/60 = {_g(x)}{tail}/√3·2π·{_g(n)}/60",
                used + (["datasheet.kt_current"] if "kt_current" in ds else []))
    return (SQRT3 * 2.0 * math.pi * f_n * x / SQRT2,
            f"E_LL = √3·2π·f_n·ψ/√2 = √3·2π·{_g(f_n)}·{_g(x)}/√2", used)


def _check(ds: dict) -> None:
    """Errors of fields that contradict each other or qualify nothing."""
    for key, values in _QUALIFIERS:
        if key in ds and not set(values) & set(ds):
            if len(values) == 1:
                raise InputError(f"datasheet.{key}", code="used_with", other=f"datasheet.{values[0]}")
            raise InputError(f"datasheet.{key}", code="used_with_either",
                             a=f"datasheet.{values[0]}", b=values[1])
    setters: dict = {}
    for key in FIELDS:
        if key in ds and key in SETS and key not in KE_FIELDS:
            for t in SETS[key]:
                if t in setters:
                    raise both_given(f"datasheet.{key}", f"datasheet.{setters[t]}", f"motor.{t}")
                setters[t] = key
    if "bemf_from" in ds:
        src = _choice(ds, "bemf_from")
        if src not in ds:
            raise InputError("datasheet.bemf_from", code="used_with", other=f"datasheet.{src}")


def apply(ds: dict, motor: dict, drive: dict) -> tuple[dict, list, dict, dict | None]:
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
    (motor, conversions, drive, bemf_check)
        New ``motor``/``drive`` dicts with the derived fields added; one entry per
        conversion: ``field, label, label_zh, formula, value, unit, from``; and, when
        several of Ke, Kv, kT, ψ are given, their cross-check: ``used`` (the datasheet
        path the firmware's back-EMF comes from), ``sources`` (each ``field``,
        ``bemf_v`` line RMS at rated speed, ``formula``, ``deviation_pct`` from the one
        used) and ``spread_pct`` = 100·(max − min)/used.

    Raises
    ------
    InputError
        A datasheet value and the motor field it would set both given, or two datasheet
        values for one motor field (the message names both, ``params.other`` is the
        second path), a bad number or choice.
    """
    motor, drive = dict(motor), dict(drive)
    for key, targets in SETS.items():
        if key in ds:
            for t in targets:
                if t in motor:
                    raise both_given(f"datasheet.{key}", f"motor.{t}", f"motor.{t}")
    _check(ds)
    sources = [k for k in KE_FIELDS if k in ds]
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
    check = None
    if sources:
        if "rated_freq_hz" not in motor:
            raise InputError("datasheet.speed_rpm", code="required_to_convert",
                             source=f"datasheet.{sources[0]}", other="motor.rated_freq_hz")
        # Only the sign here: a value out of range is named where it came from, by normalize.
        f_n = value(FIELD["motor.rated_freq_hz"]._replace(lo=None, hi=None), motor["rated_freq_hz"])
        n = 60.0 * f_n / p  # rpm at rated frequency
        implied = {src: _bemf(ds, src, n, f_n) for src in sources}
        used = _choice(ds, "bemf_from") if "bemf_from" in ds else sources[0]
        e, formula, fields = implied[used]
        motor["bemf_v"] = e
        conv.append(_step("motor.bemf_v", "back-EMF, line RMS at rated frequency",
                          "额定频率下的线反电势（有效值）", formula, e, "V",
                          fields + (["datasheet.speed_rpm"] if "speed_rpm" in ds
                                    else ["motor.rated_freq_hz"]) + ["motor.pole_pairs"]))
        if len(sources) > 1:
            values = [x[0] for x in implied.values()]
            check = {"used": f"datasheet.{used}", "rated_speed_rpm": n,
                     "sources": [{"field": f"datasheet.{src}", "bemf_v": x[0], "formula": x[1],
                                  "deviation_pct": 100.0 * (x[0] - e) / e}
                                 for src, x in implied.items()],
                     "spread_pct": 100.0 * (max(values) - min(values)) / e}
    winding = _choice(ds, "winding")
    for key, fields, sym, between in _WINDING:
        if key not in ds:
            continue
        x = _positive(ds, key)
        if between == "line":
            # a delta phase is 3·X_LL/2 and its star equivalent X_Δ/3: again X_LL/2
            y, formula = x / 2.0, f"{sym} = {sym}_LL/2 = {_g(x)}/2" + (
                "" if winding == "star" else "  (delta: X_Δ = 3·X_LL/2, star equivalent X_Δ/3)")
        elif winding == "star":
            y, formula = x, f"{sym} = {sym}_ph = {_g(x)}"
        else:
            y, formula = x / 3.0, f"{sym} = {sym}_Δ/3 = {_g(x)}/3  (star equivalent of a delta phase)"
        unit = "Ω" if sym == "R" else "H"
        for f in fields:
            motor[f] = y
            axis = f[1]  # "ld_h" → d
            conv.append(_step(f"motor.{f}", "resistance per phase, equivalent star" if sym == "R"
                              else f"{axis}-axis inductance per phase, equivalent star",
                              "每相电阻（等效星形）" if sym == "R"
                              else f"每相 {axis} 轴电感（等效星形）", formula, y, unit,
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
    return motor, conv, drive, check


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
