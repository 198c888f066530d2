"""Validation and defaults of the report's ``"sim"`` input section.

Rules as for the rest of the input (docs/contract.md): JSON ``null`` equals an
absent field, booleans are not numbers, unknown keys are errors, and every
error is an :class:`pulab.schema.errors.InputError` naming the JSON path
(``sim.current.step_a``).

Fields (defaults marked *motor* are resolved by :func:`pulab.analyses.sim.simulate`
from the report, so they stay ``None`` here):

======================== ======================================== ==================
field                    unit, range                              default
======================== ======================================== ==================
current.axis             ``"d"`` or ``"q"``: the stepped reference ``"d"``
current.step_a           A (dq scale of ``conventions.base``),    *motor*: 0.5·I_b
                         finite, ≠ 0, |step| < 8·I_b (Q12 int16)
current.duration_s       s, > 0, at most 200 000 periods          *motor*: 30/ω_c,
                                                                  ≥ 200 periods
current.speed_hz         electrical Hz, finite (0 = locked rotor) 0
current.delay            bool: one-sample computation delay       false
pll.speed_hz             electrical Hz of the input angle, finite *motor*: rated_freq_hz
pll.angle_step_deg       deg, −180..180: θ(0) while θ̂(0) = 0      30
pll.ramp_hz_per_s        Hz/s, finite: speed ramp of the input    0
pll.duration_s           s, > 0, at most 500 000 periods          *motor*: 60/(ζω_n),
                                                                  ≥ 2000 periods
======================== ======================================== ==================

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
from ...schema.inputs import object_fields, real, shown

__all__ = ["validate", "periods", "FIELDS"]

#: Allowed keys per subsection.
FIELDS = {
    "current": ("axis", "step_a", "duration_s", "speed_hz", "delay"),
    "pll": ("speed_hz", "angle_step_deg", "ramp_hz_per_s", "duration_s"),
}


def _section(sim: dict, name: str) -> dict:
    return object_fields(sim.get(name), f"sim.{name}", FIELDS[name])


def _num(sec: dict, path: str, key: str, default, positive: bool = False,
         nonzero: bool = False, lo: float | None = None, hi: float | None = None):
    if key not in sec:
        return default
    full = f"{path}.{key}"
    v = real(sec[key], full)
    if positive and v <= 0:
        raise InputError(full, f"must be > 0, got {v:g}")
    if nonzero and v == 0:
        raise InputError(full, "must not be 0")
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        raise InputError(full, f"must be {lo:g}..{hi:g}, got {v:g}")
    return v


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
        raise InputError(field, f"{duration:g} s is {count} control periods; at most {cap}")
    return max(int(round(q)), 1)


def validate(sim_input) -> dict:
    """Check the ``"sim"`` input section and fill in the defaults.

    Parameters
    ----------
    sim_input : dict
        The value of the report input's ``"sim"`` key.

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
    sim = object_fields(sim_input, "sim", FIELDS)
    c = _section(sim, "current")
    p = _section(sim, "pll")
    axis = c.get("axis", "d")
    if axis not in ("d", "q"):
        raise InputError("sim.current.axis", f"must be one of d, q, got {shown(axis)}")
    delay = c.get("delay", False)
    if not isinstance(delay, bool):
        raise InputError("sim.current.delay", f"must be true or false, got {shown(delay)}")
    cur = {"axis": axis,
           "step_a": _num(c, "sim.current", "step_a", None, nonzero=True),
           "duration_s": _num(c, "sim.current", "duration_s", None, positive=True),
           "speed_hz": _num(c, "sim.current", "speed_hz", 0.0),
           "delay": delay}
    pll = {"speed_hz": _num(p, "sim.pll", "speed_hz", None),
           "angle_step_deg": _num(p, "sim.pll", "angle_step_deg", 30.0, lo=-180.0, hi=180.0),
           "ramp_hz_per_s": _num(p, "sim.pll", "ramp_hz_per_s", 0.0),
           "duration_s": _num(p, "sim.pll", "duration_s", None, positive=True)}
    return {"current": cur, "pll": pll}
