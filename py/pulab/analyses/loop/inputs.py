"""Validation and defaults of the report's ``"analysis"`` input section (issue 11).

Same rules as the rest of the input (docs/contract.md): ``null`` = absent,
booleans are not numbers, unknown keys are errors naming their JSON path.

============================== ============================================ =====================
field                          unit, range                                  default
============================== ============================================ =====================
delay                          ``none``, ``computation``, ``computation_pwm`` ``computation_pwm``
design                         ``phase_margin``, ``bandwidth``              ``phase_margin``
target_phase_margin_deg        deg, 0 < x < 90                              60
target_bandwidth_hz            Hz > 0                                       current_loop.bandwidth_hz
bode                           bool: add the Bode data (``loop.bode``)      false
speed                          object or null: the speed loop               null (not analysed)
speed.inertia_kg_m2            J, kg·m² > 0                                 required
speed.friction_nm_s            B, N·m·s/rad ≥ 0                             0
speed.bandwidth_hz             ω_n/2π of the speed loop, Hz > 0             20
speed.damping                  ζ > 0                                        1/√2
speed.filter_hz                speed-measurement low-pass corner, Hz > 0    5·speed.bandwidth_hz
speed.ts_s                     speed-loop period, s, an integer multiple    10·drive.ts_s
                               (1..1000) of drive.ts_s
speed.current_limit_a          |i_q| limit of the speed PI output, A > 0,   2·I_b
                               < 8·I_b (Q12 int16)
speed.response                 bool: add the step/load-step responses       false
speed.step_pu                  speed step, pu of ω_b, 0 < |x| ≤ 1           0.1
speed.load_pu                  load-torque step, pu of T_b (finite)         0.5
robust                         object or null: drift, saturation and        null (not analysed)
                               tolerances (:mod:`.robust`)
============================== ============================================ =====================

Defaults that depend on the motor stay ``None`` here and are resolved by
:func:`pulab.analyses.loop.analyze`.

Examples
--------
>>> validate(None)["delay"]
'computation_pwm'
>>> validate({"delay": "pwm"})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: analysis.delay: must be one of none, computation, computation_pwm, got 'pwm'
"""

from __future__ import annotations

import math

from ...schema.errors import InputError
from ...schema.inputs import object_fields, real
from . import robust as _robust

__all__ = ["validate", "FIELDS", "SPEED_FIELDS"]

FIELDS = ("delay", "design", "target_phase_margin_deg", "target_bandwidth_hz", "bode", "speed",
          "robust")
SPEED_FIELDS = ("inertia_kg_m2", "friction_nm_s", "bandwidth_hz", "damping", "filter_hz", "ts_s",
                "current_limit_a", "response", "step_pu", "load_pu")
_CHOICES = {"delay": ("none", "computation", "computation_pwm"),
            "design": ("phase_margin", "bandwidth")}


def _choice(sec: dict, key: str, default: str) -> str:
    v = sec.get(key, default)
    if v not in _CHOICES[key]:
        raise InputError(f"analysis.{key}", f"must be one of {', '.join(_CHOICES[key])}, got {v!r}")
    return v


def _flag(sec: dict, path: str, key: str) -> bool:
    v = sec.get(key, False)
    if not isinstance(v, bool):
        raise InputError(f"{path}.{key}", f"must be true or false, got {v!r}")
    return v


def _positive(sec: dict, path: str, key: str, default, zero_ok: bool = False):
    if key not in sec:
        return default
    v = real(sec[key], f"{path}.{key}")
    if v < 0 or (v == 0 and not zero_ok):
        raise InputError(f"{path}.{key}", f"must be > 0, got {v:g}" if not zero_ok else
                         f"must be ≥ 0, got {v:g}")
    return v


def _speed(value) -> dict | None:
    if value is None:
        return None
    path = "analysis.speed"
    s = object_fields(value, path, SPEED_FIELDS)
    if "inertia_kg_m2" not in s:
        raise InputError(f"{path}.inertia_kg_m2", "is required")
    out = {"inertia_kg_m2": _positive(s, path, "inertia_kg_m2", None),
           "friction_nm_s": _positive(s, path, "friction_nm_s", 0.0, zero_ok=True),
           "bandwidth_hz": _positive(s, path, "bandwidth_hz", 20.0),
           "damping": _positive(s, path, "damping", math.sqrt(0.5)),
           "filter_hz": _positive(s, path, "filter_hz", None),
           "ts_s": _positive(s, path, "ts_s", None),
           "current_limit_a": _positive(s, path, "current_limit_a", None),
           "response": _flag(s, path, "response"),
           "step_pu": 0.1 if "step_pu" not in s else real(s["step_pu"], f"{path}.step_pu"),
           "load_pu": 0.5 if "load_pu" not in s else real(s["load_pu"], f"{path}.load_pu")}
    if not 0 < abs(out["step_pu"]) <= 1:
        raise InputError(f"{path}.step_pu", f"must be between -1 and 1 and not 0, got "
                         f"{out['step_pu']:g}")
    if not 1e-3 <= out["damping"] <= 100:
        raise InputError(f"{path}.damping", f"must be between 0.001 and 100, got "
                         f"{out['damping']:g}")
    return out


def validate(value) -> dict:
    """Check the ``"analysis"`` input and fill in the defaults.

    Raises
    ------
    pulab.InputError
        Naming the JSON path of the first bad field.
    """
    path = "analysis"
    a = object_fields(value, path, FIELDS)
    pm = _positive(a, path, "target_phase_margin_deg", 60.0)
    if not pm < 90.0:
        raise InputError(f"{path}.target_phase_margin_deg", f"must be between 0 and 90, got "
                         f"{pm:g}")
    return {"delay": _choice(a, "delay", "computation_pwm"),
            "design": _choice(a, "design", "phase_margin"),
            "target_phase_margin_deg": pm,
            "target_bandwidth_hz": _positive(a, path, "target_bandwidth_hz", None),
            "bode": _flag(a, path, "bode"),
            "speed": _speed(a.get("speed")),
            "robust": None if a.get("robust") is None else _robust.validate(a["robust"])}
