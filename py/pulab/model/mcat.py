"""NXP MCAT's own inputs (``profiles.nxp.mcat``) turned into pulab's input fields.

MCAT writes its inputs as a JSON object in the first comment of a fixed-point
``m1_pmsm_appconfig.h``: sections ``parameters``, ``currentLoop``, ``speedLoop``, ``sensors``,
``sensorless`` (a flat object with the same keys is accepted too), or the text a reader pastes:
that JSON, or the whole header (:func:`from_text` finds the object).  :func:`expand` fills every
motor, drive, current-loop, observer and NXP-profile field the object implies; a field typed in
the input wins.  It runs before the input is checked (like the datasheet), so it lives here and
not in :mod:`pulab.profiles.nxp`.

The conversions (MCAT's quantities are amplitudes compared with its own scales: I_max is a
phase-current amplitude, U_max = U_DCB,max/√3 a phase-voltage amplitude)::

    motor.rs_ohm, ld_h, lq_h  = parametersRs, parametersLd, parametersLq
    motor.pole_pairs          = parametersPP (older MCAT) or parametersPp (newer)
    motor.rated_current_a     = parametersIphNom/√2            (amplitude → RMS)
    motor.rated_voltage_v     = parametersUphNom·√3/√2         (phase amplitude → line RMS)
    motor.rated_freq_hz       = parametersNnom·p/60
    motor.bemf_v              = parametersKe·(2π·Nnom/60)/√2   (Ke read as line-to-line peak
                                volts per mechanical rad/s: then E(N_max) phase peak ≈ E_max)
    drive.udc_v               = parametersUdcbMax (MCAT has no nominal bus voltage)
    drive.ts_s                = currentLoopSampleTime
    drive.base_freq_hz        = parametersNmax·p/60
    current_loop              = method "damping", bandwidth_hz = currentLoopF0,
                                damping = currentLoopKsi (MCAT's kp = 2ξω0L − R, ki = ω0²L)
    profiles.nxp              = udcb_max_v = parametersUdcbMax, i_max_a = parametersImax,
                                e_max_v = parametersEmax, trapezoidal = true (MCAT's
                                fixed-point headers store Ki·T/2), u_max_coeff = 1.73205
                                (MCAT's own √3: its 6th printed digit follows it)
    observer                  = sensorlessBemfObsrvF0/Ksi → bemf_f0_hz/bemf_damping,
                                sensorlessTrackObsrvF0/Ksi → tracking_f0_hz/tracking_damping,
                                sensorlessTrackObsrvIIRSpeedCutOff → speed_filter_hz,
                                sensorlessStartupRamp → startup_ramp_rpm_per_s,
                                sensorlessStartupCurrent → startup_current_a,
                                sensorlessMergingSpeed → merging_speed_rpm,
                                sensorlessMergingCoeff → merging_coeff_pct,
                                parametersNmin → min_speed_rpm, parametersEblock → e_block_v

A key MCAT did not write leaves its field to the input (or its default); a key with a value
that is not a number is left out and reported by the field's own check when required.

Examples
--------
>>> m = {"parametersRs": 0.54, "parametersLd": 3.356e-4, "parametersLq": 2.18e-4,
...      "parametersPp": 4, "parametersNmax": 4400, "currentLoopSampleTime": 1e-4}
>>> out = expand({"profiles": {"nxp": {"mcat": m}}})
>>> out["motor"]["pole_pairs"], out["drive"]["base_freq_hz"]
(4, 293.3333333333333)
>>> from_text('/* generated */ /* {"parameters": {"parametersPp": 4}} */')
{'parameters': {'parametersPp': 4}}
"""

from __future__ import annotations

import copy
import json
import math
import re

from ..schema.errors import InputError
from ..schema.validate import shown

__all__ = ["expand", "flatten", "from_text", "mcat_json", "SECTIONS"]

#: The sections MCAT writes.
SECTIONS = ("parameters", "currentLoop", "speedLoop", "sensors", "sensorless")

_OBSERVER = (("sensorlessBemfObsrvF0", "bemf_f0_hz"), ("sensorlessBemfObsrvKsi", "bemf_damping"),
             ("sensorlessTrackObsrvF0", "tracking_f0_hz"),
             ("sensorlessTrackObsrvKsi", "tracking_damping"),
             ("sensorlessTrackObsrvIIRSpeedCutOff", "speed_filter_hz"),
             ("sensorlessStartupRamp", "startup_ramp_rpm_per_s"),
             ("sensorlessStartupCurrent", "startup_current_a"),
             ("sensorlessMergingSpeed", "merging_speed_rpm"),
             ("sensorlessMergingCoeff", "merging_coeff_pct"),
             ("parametersNmin", "min_speed_rpm"), ("parametersEblock", "e_block_v"))


def flatten(m: dict) -> dict:
    """MCAT's keys in one object: the sections merged (a flat object as it is)."""
    out = {k: v for k, v in m.items() if k not in SECTIONS}
    for s in SECTIONS:
        if s in m:
            if not isinstance(m[s], dict):
                raise InputError(f"profiles.nxp.mcat.{s}", code="not_object", got=shown(m[s]))
            out.update(m[s])
    return out


def _num(m: dict, key: str):
    v = m.get(key)
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _implied(m: dict) -> dict:
    """The sections and fields the MCAT keys imply (module docstring)."""
    pp = m.get("parametersPp", m.get("parametersPP"))
    pp = pp if isinstance(pp, int) and not isinstance(pp, bool) else None
    rs, ld, lq = (_num(m, k) for k in ("parametersRs", "parametersLd", "parametersLq"))
    n_nom, n_max, i_nom = (_num(m, k) for k in ("parametersNnom", "parametersNmax",
                                                "parametersIphNom"))
    u_nom, ke, udcb = (_num(m, k) for k in ("parametersUphNom", "parametersKe",
                                            "parametersUdcbMax"))
    motor = {"rs_ohm": rs, "ld_h": ld, "lq_h": lq, "pole_pairs": pp,
             "rated_current_a": i_nom / math.sqrt(2.0) if i_nom else None,
             "rated_voltage_v": u_nom * math.sqrt(1.5) if u_nom else None,
             "rated_freq_hz": n_nom * pp / 60.0 if n_nom and pp else None,
             "bemf_v": ke * 2.0 * math.pi * n_nom / 60.0 / math.sqrt(2.0) if ke and n_nom
             else None}
    drive = {"udc_v": udcb, "ts_s": _num(m, "currentLoopSampleTime"),
             "base_freq_hz": n_max * pp / 60.0 if n_max and pp else None}
    loop = {"method": "damping", "bandwidth_hz": _num(m, "currentLoopF0"),
            "damping": _num(m, "currentLoopKsi")}
    if loop["bandwidth_hz"] is None or loop["damping"] is None:
        loop = {}
    nxp = {"udcb_max_v": udcb, "i_max_a": _num(m, "parametersImax"),
           "e_max_v": _num(m, "parametersEmax"), "trapezoidal": True, "u_max_coeff": 1.73205}
    out = {"motor": motor, "drive": drive, "current_loop": loop, "nxp": nxp}
    if any(k.startswith("sensorless") for k in m):
        out["observer"] = {ours: _num(m, key) for key, ours in _OBSERVER}
    return out


def _fill(given, implied: dict) -> dict:
    """``given`` (a section of the input, or None) with the implied values it does not type."""
    out = dict(given) if isinstance(given, dict) else {}
    for k, v in implied.items():
        if v is not None and k not in out:
            out[k] = v
    return out


_BLOCK = re.compile(r"/\*(.*?)\*/", re.S)


def mcat_json(blocks) -> dict | None:
    """MCAT's inputs among a header's comments: the first that is a JSON object with a
    ``parameters`` object (``blocks``: the comments' texts, in order)."""
    for b in blocks or ():
        text = b.strip()
        if not text.startswith("{"):
            continue
        try:
            d = json.loads(text)
        except ValueError:
            continue
        if isinstance(d, dict) and isinstance(d.get("parameters"), dict):
            return d
    return None


def from_text(text: str) -> dict | None:
    """The JSON object MCAT writes, in pasted text: the text itself when it is a JSON object,
    else the first ``/* … */`` comment of a pasted ``m1_pmsm_appconfig.h`` that is one with a
    ``parameters`` object (:func:`mcat_json`); None when there is neither."""
    try:
        d = json.loads(text)
    except ValueError:
        d = None
    if isinstance(d, dict):
        return d
    return mcat_json(m[1] for m in _BLOCK.finditer(text))


def expand(inp: dict) -> dict:
    """The input with what ``profiles.nxp.mcat`` implies filled in (typed fields win).

    Parameters
    ----------
    inp : dict
        The report input; unchanged (a copy is returned) when it has no ``profiles.nxp.mcat``.
        ``mcat`` may be the pasted text (the JSON, or the whole header): :func:`from_text`.

    Returns
    -------
    dict
        The input with ``motor``, ``drive``, ``current_loop``, ``observer`` (when MCAT wrote
        sensorless keys) and ``profiles.nxp`` completed; ``profiles.nxp.mcat`` kept.

    Raises
    ------
    InputError
        ``profiles.nxp.mcat`` (or one of its sections) is not a JSON object; pasted text in
        which no MCAT object is found (``mcat_not_found``).
    """
    nxp = (inp.get("profiles") or {}).get("nxp") if isinstance(inp.get("profiles"), dict) else None
    if not isinstance(nxp, dict) or nxp.get("mcat") is None:
        return inp
    if isinstance(nxp["mcat"], str):
        found = from_text(nxp["mcat"])
        if found is None:
            raise InputError("profiles.nxp.mcat", code="mcat_not_found")
        nxp = {**nxp, "mcat": found}
        inp = {**inp, "profiles": {**inp["profiles"], "nxp": nxp}}
    if not isinstance(nxp["mcat"], dict):
        raise InputError("profiles.nxp.mcat", code="not_object", got=shown(nxp["mcat"]))
    imp = _implied(flatten(nxp["mcat"]))
    out = copy.copy(inp)
    for sec in ("motor", "drive", "current_loop", "observer"):
        if sec in imp and (imp[sec] or sec in inp):
            out[sec] = _fill(inp.get(sec), imp[sec])
    out["profiles"] = {**inp["profiles"], "nxp": _fill(nxp, imp["nxp"])}
    return out
