"""Validation and defaults of the report's ``"analysis"`` input section .

The fields, their ranges and defaults are the schema's ``analysis``,
``analysis.speed`` and ``analysis.robust`` sections (:mod:`pulab.schema.fields`),
checked by :func:`pulab.schema.validate.read`.  Defaults that depend on the motor
stay ``None`` here and are resolved by :func:`pulab.analyses.loop.analyze`.

Examples
--------
>>> validate(None)["delay"]
'computation_pwm'
>>> validate({"delay": "pwm"})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: analysis.delay: must be one of computation_pwm, computation, none, got 'pwm'
"""

from __future__ import annotations

from ...schema.fields import section_fields
from ...schema.validate import read
from . import robust as _robust

__all__ = ["validate", "FIELDS", "SPEED_FIELDS"]

FIELDS = tuple(f.key for f in section_fields("analysis")) + ("speed", "robust")
SPEED_FIELDS = tuple(f.key for f in section_fields("analysis.speed"))


def validate(value) -> dict:
    """Check the ``"analysis"`` input and fill in the defaults.

    Raises
    ------
    pulab.InputError
        Naming the JSON path of the first bad field.
    """
    a = read("analysis", value)
    speed, robust, fw = a.get("speed"), a.get("robust"), a.get("fw")
    a["speed"] = None if speed is None else read("analysis.speed", speed)
    a["fw"] = None if fw is None else read("analysis.fw", fw)
    a["robust"] = None if robust is None else _robust.settings(robust)
    return a
