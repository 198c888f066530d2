"""Validation and defaults for the report input (docs/contract.md).

Bad input never becomes a number: every problem raises
:class:`pulab.schema.errors.InputError` naming the JSON path of the field.

Examples
--------
>>> inp = normalize({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> inp["drive"]["base_freq_hz"], inp["conventions"]["base"], inp["current_loop"]["method"]
(220.0, 'rms', 'bandwidth')
>>> normalize({"motor": {}})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: motor.rated_voltage_v: is required (or give datasheet.dc_bus_v)
"""

from __future__ import annotations

from ..model import datasheet as _datasheet
from ..model import mcat as _mcat
from .errors import InputError
from .fields import FIELD, section_fields
from .validate import children, key_path, object_fields, read, real, shown, value

__all__ = ["normalize", "object_fields", "real", "shown", "key_path",
           "DEFAULT_CURRENT_BANDWIDTH_HZ",
           "DEFAULT_PLL_BANDWIDTH_HZ", "DEFAULT_DAMPING", "SECTIONS"]

DEFAULT_CURRENT_BANDWIDTH_HZ = FIELD["current_loop.bandwidth_hz"].default
DEFAULT_PLL_BANDWIDTH_HZ = FIELD["pll.bandwidth_hz"].default
DEFAULT_DAMPING = FIELD["pll.damping"].default

#: The top-level sections :func:`normalize` reads itself (any other one is read by its fields).
_READ_ABOVE = frozenset(("motor", "drive", "conventions", "current_loop", "pll", "raw",
                         "datasheet", "board", "sim", "profiles", "observer", "analysis"))

#: Keys of each section that :func:`normalize` returns with its defaults (from the schema).
SECTIONS = {name: tuple(f.key for f in section_fields(name))
            for name in ("motor", "drive", "conventions", "current_loop", "pll", "raw")}


def normalize(inp: dict) -> dict:
    """Check the input and return it with every default filled in.

    Parameters
    ----------
    inp : dict
        The report input (contract "Input").

    Returns
    -------
    dict
        Same layout; every optional field present; numbers as float (pole
        pairs and raw values as int); ``raw`` holds only the values given.
        ``motor`` holds the values derived from a ``datasheet`` section, and
        ``datasheet`` (when given) its values and conversions
        (:func:`pulab.model.datasheet.apply`).
    """
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    inp = _mcat.expand(inp)  # profiles.nxp.mcat: MCAT's own inputs fill the fields they imply
    for key in inp:
        if key not in children(""):
            raise InputError(key_path("", key), code="unknown_section",
                             expected=", ".join(children("")))
    ds = object_fields(inp.get("datasheet"), "datasheet", _datasheet.FIELDS)
    motor_in = object_fields(inp.get("motor"), "motor", SECTIONS["motor"])
    drive_in = object_fields(inp.get("drive"), "drive", SECTIONS["drive"])
    m, conversions, d, bemf_check = _datasheet.apply(ds, motor_in, drive_in)
    derived = {c["field"]: c["from"][0] for c in conversions}
    kind = value(FIELD["motor.kind"], m["kind"]) if "kind" in m else "pmsm"
    # A PMSM's normalized motor holds no kind and no induction-motor key (its reports stay
    # byte for byte those from before the kind existed); an induction motor's holds both.
    motor = {} if kind == "pmsm" else {"kind": kind}
    for f in section_fields("motor"):
        if f.key == "kind":
            continue
        if f.only_with and f.only_with[1] != kind:
            if f.key in m:
                raise InputError(derived.get(f.path, f.path), code="only_with", key="kind",
                                 value=f.only_with[1])
            continue
        if f.key not in m and f.default is None:
            motor[f.key] = None
            continue
        if f.key not in m:
            alt = [f"datasheet.{k}" for k, sets in _datasheet.SETS.items() if f.key in sets]
            if alt:  # a datasheet start: say what else fills this field
                raise InputError(f.path, code="required_or", alternatives=", ".join(alt))
            raise InputError(f.path, code="required")
        try:
            motor[f.key] = value(f, m[f.key])
        except InputError as e:
            if f.path not in derived:
                raise
            # The value came from the datasheet: the error belongs at what the user typed.
            raise InputError(derived[f.path], code="derived_invalid", target=f.path,
                             value=m[f.key], reason=e.as_dict()) from None

    drive = read("drive", d)
    if drive["base_freq_hz"] is None:
        drive["base_freq_hz"] = motor["rated_freq_hz"]
    conv = read("conventions", inp.get("conventions"))
    loop = read("current_loop", inp.get("current_loop"))
    pll = read("pll", inp.get("pll"))
    raw = {k: v for k, v in read("raw", inp.get("raw")).items() if v is not None}

    out = {"motor": motor, "drive": drive, "conventions": conv, "current_loop": loop,
           "pll": pll, "raw": raw}
    if ds.get("lms_h") is not None and kind != "acim":
        raise InputError("datasheet.lms_h", code="only_with", key="kind", value="acim")
    if ds:
        # Not part of the echoed input (report.input.motor already holds the derived values).
        out["datasheet"] = {"given": ds, "conversions": conversions}
        if bemf_check is not None:
            out["datasheet"]["bemf_check"] = bemf_check
    if inp.get("board") is not None:
        given = object_fields(inp["board"], "board", children("board"))
        out["board"] = {k: read(f"board.{k}", given[k]) for k in children("board") if k in given}
    if inp.get("observer") is not None:
        out["observer"] = read("observer", inp["observer"])
    if inp.get("sim") is not None:
        out["sim"] = inp["sim"]
    if "profiles" in inp:  # checked in pulab.profiles.options: its defaults need the motor
        out["profiles"] = inp["profiles"]
    out["analysis"] = inp.get("analysis")
    # the section of an analysis added later (docs/design.md, "Adding an analysis"): its fields
    for key in inp:
        if key not in _READ_ABOVE and inp[key] is not None:
            out[key] = read(key, inp[key])
    return out
