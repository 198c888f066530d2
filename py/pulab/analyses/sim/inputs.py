"""Validation and defaults of the report's ``"sim"`` input section.

Rules as for the rest of the input (docs/contract.md): JSON ``null`` equals an
absent field, booleans are not numbers, unknown keys are errors, and every
error is an :class:`pulab.schema.errors.InputError` naming the JSON path
(``sim.current.step_a``).

The fields, their ranges and defaults are the schema's ``sim.current`` and
``sim.pll`` sections (:mod:`pulab.schema.fields`), checked by
:func:`pulab.schema.validate.read`.  Defaults that depend on the motor stay
``None`` here and are resolved by :func:`pulab.analyses.sim.simulate`.

Examples
--------
>>> validate({"current": {"axis": "q", "step_a": 1.0}})["current"]
{'axis': 'q', 'step_a': 1.0, 'duration_s': None, 'speed_hz': 0.0, 'delay': False}
>>> validate({"current": {"delay": 1}})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: sim.current.delay: must be true or false, got 1
"""

from __future__ import annotations


from ...schema.errors import InputError
from ...schema.fields import section_fields
from ...schema.validate import read

__all__ = ["validate", "periods", "FIELDS"]

#: Allowed keys per subsection.
FIELDS = {name: tuple(f.key for f in section_fields(f"sim.{name}"))
          for name in ("current", "current.code", "pll", "flux")}


def periods(duration: float, ts: float, cap: int, field: str) -> int:
    """Control periods in ``duration``: ``round(duration/ts)``, 1..cap.

    Checked against the cap before anything is rounded or allocated: a
    finite duration over a tiny ``ts`` can exceed the float range.

    Parameters
    ----------
    duration : float > 0, seconds ; ts : float > 0, seconds
    cap : int, even (so ``q ≤ cap + ½`` is exactly ``round(q) ≤ cap``)
    field : str, the JSON path named when the run is too long

    Examples
    --------
    >>> periods(0.02, 1e-4, 200_000, "sim.current.duration_s")
    200
    >>> periods(1e300, 1e-9, 200_000, "sim.current.duration_s")
    Traceback (most recent call last):
    ...
    pulab.schema.errors.InputError: sim.current.duration_s: 1e+300 s is >1.8e308 control periods; at most 200000
    """
    q = duration / ts
    if not q <= cap + 0.5:  # also catches q = inf
        count = f"{q:.4g}" if q < float("inf") else ">1.8e308"
        raise InputError(field, code="too_many_periods", value=duration, count=count, limit=cap)
    return max(int(round(q)), 1)


def validate(sim_input, acim: bool = False) -> dict:
    """Check the ``"sim"`` input section and fill in the defaults.

    Parameters
    ----------
    sim_input : dict
        The value of the report input's ``"sim"`` key.
    acim : bool
        An induction motor's: also ``flux`` (:mod:`.induction`); its ``sim.current.code``
        is refused.

    Returns
    -------
    dict
        ``{"current": {...}, "pll": {...}}`` with every field of :data:`FIELDS`
        present (motor-dependent defaults as ``None``).  Both simulations always
        run; a missing subsection means "all defaults".

    Raises
    ------
    pulab.InputError
        Naming the JSON path of the first bad field.
    """
    sim = read("sim", sim_input)
    if not acim and sim.get("flux") is not None:
        raise InputError("sim.flux", code="only_with", key="kind", value="acim")
    current = read("sim.current", sim.get("current"))
    if "code" in current:  # the user's routine as the controller (:mod:`.code_loop`)
        if acim:
            raise InputError("sim.current.code", code="acim_not_applicable")
        current["code"] = read("sim.current.code", current["code"])
    out = {"current": current, "pll": read("sim.pll", sim.get("pll"))}
    if acim:
        out["flux"] = read("sim.flux", sim.get("flux"))
    return out
