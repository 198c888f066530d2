"""Your C routine as the current controller: called every control period against the plant.

The routine of ``sim.current.code`` (pasted C, run by the tracer :mod:`pulab.ctrace`) takes
the place of pulab's PI on both axes: one instance per axis, each with its own memory kept
between its calls (globals, ``static`` locals, what the entry's pointer parameters point
to), as firmware keeps one PI object per axis.  Each period, per axis:

1. the plant current is read as the chosen firmware reads it (``scale``: Inovance's Q12 of
   I_b in int16, as :func:`.current.run_fixed_steps`; TI's, NXP's, ST's or Microchip's
   feedback word, as :mod:`.vendor_loop`): nearest count, ties away from zero, clipped to
   the word (``feedback_saturate``);
2. the bound inputs are given: ``reference`` (the step in the same counts), ``feedback``,
   ``error`` = reference − feedback (computed exactly, as a ``long`` subtraction);
3. the entry is called (without an entry the statements outside functions run: a variable
   declared without an initializer keeps its value, as a global);
4. ``output`` (a variable, a struct field ``p.FIELD`` or ``return``) is read and applied as
   that firmware's voltage count (Inovance: ×U_b/2^12, phase), held one period with
   ``delay``.  pulab does not clamp it: a routine without its own limit drives the plant
   beyond the drive's voltage (counted as ``beyond_limit``).

Before the first call: ``set`` (C name → integer, a report path such as
``current_pi.d.pm_kp``, ``&OBJECT`` for a pointer, or ``{"d": …, "q": …}`` per axis) and
``integral`` preloaded with the back-EMF (q axis; ``integral_shift`` = the integrator's
fraction bits over the output's, e.g. 12 for Inovance's Q24 integral of a Q12 output).
Every other input the code reads starts at 0, as C's static storage does; they are listed
(``zeroed``) so a forgotten gain is visible.

Examples
--------
>>> code = "long e, x, u; x = x + e; u = x >> 4;"
>>> b = bind({"text": code, "target": "c28x", "entry": None, "reference": None,
...           "feedback": None, "error": "e", "output": "u", "set": None,
...           "integral": None, "integral_shift": 0}, {})
>>> r = b.instances["d"]
>>> [r.call(0, {"e": 100}) for _ in range(3)], b.zeroed
([6, 12, 18], ['x'])
"""

from __future__ import annotations

import math
from array import array

from ...ctrace.check import PtrT
from ...ctrace.evaluate import Evaluator
from ...ctrace.sequence import EVENT_KINDS
from ...ctrace.tracing import DEFAULT_GLOBAL_Q, compile_code, input_values
from ...fixedpoint.cint import CType
from ...schema.errors import InputError
from ...schema.validate import key_path, shown
from ..slices import finish
from . import vendor_loop

__all__ = ["bind", "scale", "run_code_steps", "run_code", "MAX_PERIODS", "MAX_STATEMENTS",
           "SLICE_PERIODS"]

#: A run with a routine has at most this many periods (each is two interpreted calls).
MAX_PERIODS = 20_000
#: Statements the routine may execute over the whole run (both axes).
MAX_STATEMENTS = 2_000_000
#: The run yields every this many periods (an interpreted period costs ≈ 0.5 ms).
SLICE_PERIODS = 256

_F = "sim.current.code."


def _renamed(e: InputError) -> InputError:
    """A tracer error as the error of the ``sim.current.code`` field at fault."""
    field = e.field or "code"
    if field == "code":
        field = "text"
    return InputError(_F + field, code=e.code, **e.params)


def _name(v: str) -> str:
    return v.strip().replace("->", ".")


class Routine:
    """One axis's instance of the routine: its own evaluator and memory.

    Parameters
    ----------
    checked : Checked — the compiled code
    first : dict — validated values given before call 0 (``set``, zeros, preload)
    params : dict — the by-value parameters' values among ``first`` (the caller's copies,
        given again every call)
    ranges : dict — bound input name → (min, max) of its C type
    output : str — the output's path, or ``return``
    fields : dict — bound input name → its ``sim.current.code`` field (named in errors)
    """

    def __init__(self, checked, first: dict, params: dict, ranges: dict, output: str,
                 fields: dict) -> None:
        self.checked = checked
        self.gq = checked.program.global_q or DEFAULT_GLOBAL_Q
        self.first, self.params, self.ranges = first, params, ranges
        self.output, self.fields = output, fields
        self.ev: Evaluator | None = None
        self.statements = 0
        #: flags met over all calls, and the first wrap/overflow/clamp (call, line, kind, name)
        self.flags: set = set()
        self.event: tuple | None = None

    def call(self, k: int, given: dict) -> int:
        """Call ``k`` (from 0) with the bound inputs ``given``; returns the output integer.

        Raises
        ------
        InputError
            The bound field when a value does not fit its variable's type; ``set.NAME`` or
            ``text`` for an error in the call (``sim_code_in_call``); ``output`` when the call
            left no value there.
        """
        for name, v in given.items():
            lo, hi = self.ranges[name]
            if not lo <= v <= hi:
                raise InputError(self.fields[name], code="sim_code_fit", name=name, value=v,
                                 lo=lo, hi=hi, call=k)
        try:
            if self.ev is None:
                ev = self.ev = Evaluator(self.checked, {**self.first, **given}, self.gq,
                                         record=False)
                ev.watch = EVENT_KINDS
                ev.run()
            else:
                ev = self.ev
                ev.again({**self.params, **given})
        except InputError as e:  # the tracer's errors (TraceError) and a value it refused
            field = _F + e.field if e.field.startswith("set.") else _F + "text"
            raise InputError(field, code="sim_code_in_call", call=k, reason=e.as_dict()) \
                from None
        self.statements += ev.count
        self.flags |= ev.seen
        if ev.event is not None and self.event is None:
            self.event = (k, *ev.event)
        out = ev.values.get("return") if self.output == "return" else ev.mem.get(self.output)
        if not isinstance(out, int):
            raise InputError(_F + "output", code="sim_code_no_output", name=self.output, call=k)
        return out


class Binding:
    """The compiled routine and its two instances (``instances['d']``, ``['q']``)."""

    def __init__(self, instances: dict, names: dict, zeroed: list) -> None:
        self.instances = instances
        #: the bound C names: ``reference``, ``feedback``, ``error`` (None when not bound)
        self.names = names
        #: the inputs neither bound nor set: 0 before call 0
        self.zeroed = zeroed


def _lookup(report: dict, path: str, field: str) -> int:
    """The integer at report path ``path`` (a ``{"value": …}`` result gives its value)."""
    node = report
    if path.split(".")[0] == "profiles" and "profiles" not in report.get("input", {}):
        node = {"profiles": vendor_loop.profile_data(report)[0]}
    for part in path.split("."):
        node = node.get(part) if isinstance(node, dict) else None
    if isinstance(node, dict):
        node = node.get("value")
    if isinstance(node, bool) or not isinstance(node, int):
        raise InputError(field, code="sim_code_path", got=shown(path))
    return node


def _set_value(report: dict, v, field: str):
    if isinstance(v, str) and v.strip()[:1].isalpha():
        return _lookup(report, v.strip(), field)
    if isinstance(v, (int, str)) and not isinstance(v, bool):
        return v  # an integer, integer text or &OBJECT: the tracer checks it
    raise InputError(field, code="sim_code_set_value", got=shown(v))


def _axis_sets(report: dict, given: dict) -> dict:
    """``set`` resolved per axis: {'d': {name: value}, 'q': {…}}."""
    out: dict = {"d": {}, "q": {}}
    for name, v in given.items():
        if v is None:  # null is absent, as everywhere in the input
            continue
        field = key_path(_F + "set", name)
        if isinstance(v, dict):
            if set(v) != {"d", "q"}:
                raise InputError(field, code="sim_code_set_value", got=shown(v))
            for axis in ("d", "q"):
                out[axis][name] = _set_value(report, v[axis], f"{field}.{axis}")
        else:
            value = _set_value(report, v, field)
            out["d"][name] = out["q"][name] = value
    return out


def _checked_values(checked, values: dict, zero: bool) -> dict:
    try:
        return input_values(checked, values, zero)
    except InputError as e:
        raise _renamed(e) from None


def bind(cfg: dict, report: dict, preload: int = 0) -> Binding:
    """Compile ``sim.current.code`` and check its binding against the code.

    Parameters
    ----------
    cfg : dict — normalized ``sim.current.code`` (:func:`pulab.analyses.sim.validate`)
    report : dict — the report the ``set`` paths are read from
    preload : int — the q integrator's start (``integral``), in its own units

    Returns
    -------
    Binding

    Raises
    ------
    InputError
        Naming the field: ``text`` (code that does not compile), ``entry``, ``reference`` /
        ``feedback`` / ``error`` (no such variable, not an integer input the code reads),
        ``output`` (no such integer, ``return`` of an entry that returns none), ``set.NAME``
        (no such input, a value out of its type, a report path that names no integer).
    """
    try:
        checked = compile_code(cfg["text"], cfg["target"], entry=cfg["entry"])
    except InputError as e:
        raise _renamed(e) from None
    if cfg["feedback"] is None and cfg["error"] is None:
        raise InputError(_F + "feedback", code="sim_code_feedback")
    sets = _axis_sets(report, cfg["set"] or {})
    names = {k: _name(cfg[k]) if cfg[k] is not None else None
             for k in ("reference", "feedback", "error")}
    bound = {v: _F + k for k, v in names.items() if v is not None}
    integral = _name(cfg["integral"]) if cfg["integral"] is not None else None
    # the names exist, are integers and take a value; then that the code reads them
    probe = {n: 0 for n in bound}
    for n, field in bound.items():
        try:
            input_values(checked, {n: 0})
        except InputError as e:
            raise InputError(field, code=e.code, **e.params) from None
    if integral is not None:
        try:  # the preload fits the integrator (the d axis starts at 0)
            input_values(checked, {integral: preload})
        except InputError as e:
            raise InputError(_F + "integral", code=e.code, **e.params) from None
    output = _name(cfg["output"])
    f = checked.entry
    if output == "return":
        if f is None or not isinstance(f.ret, CType):
            raise InputError(_F + "output", code="sim_code_return")
    elif output not in checked.symbols:
        plain = output.isidentifier() or output.replace(".", "_").isidentifier()
        raise InputError(_F + "output", code="trace_no_variable",
                         name=output if plain and len(output) <= 40 else shown(output))
    params = {p.key for p in f.params if not isinstance(p.ctype, PtrT)} if f is not None else set()
    instances, zeroed = {}, []
    for axis in ("d", "q"):
        given = dict(sets[axis])
        if integral is not None:
            given[integral] = preload if axis == "q" else 0
        first = _checked_values(checked, {**given, **probe}, True)
        pointers = {k: v for k, v in first.items() if k in checked.pointers}
        reads = set(checked.inputs_with(pointers))
        for n, field in bound.items():
            if n not in reads:
                raise InputError(field, code="sim_code_unread", name=n)
        named = {_name(k) for k in given if isinstance(k, str)}
        zeroed = sorted(k for k in first if k not in named and k not in probe)
        ranges = {n: (checked.symbols[n].ctype.min, checked.symbols[n].ctype.max) for n in bound}
        instances[axis] = Routine(checked, {k: v for k, v in first.items() if k not in probe},
                                  {k: v for k, v in first.items() if k in params and k not in probe},
                                  ranges, output, bound)
    return Binding(instances, names, zeroed)


def scale(report: dict, name: str, umax_pu: float, maxout: int | None) -> dict:
    """The integer units of firmware ``name`` on this report's plant.

    Parameters
    ----------
    report : dict
    name : str — ``inovance`` or a vendor of :func:`.vendor_loop.names`
    umax_pu : float — the output limit in per unit of U_b (:func:`.current.voltage_limits`)
    maxout : int or None — Inovance's pm_maxout_vol (None: that firmware cannot run this drive)

    Returns
    -------
    dict — ``to_count`` (A in the report's dq scale → count), ``to_volt`` (count → V, dq
    scale), ``bits`` (the feedback word), ``out_limit`` (the voltage limit in counts),
    ``lsb_a`` (A per count)

    Raises
    ------
    InputError — ``sim.current.code.scale`` when that firmware cannot represent the drive
    """
    b = report["base"]
    if name == "inovance":
        if maxout is None:
            problems = report["firmware"]["inovance"]["problems"]
            raise InputError(_F + "scale", code="sim_code_scale", vendor={"vendor": name},
                             problems=", ".join(p["code"] for p in problems) or "—")
        return {"to_count": 4096.0 / b["I_b"], "to_volt": b["U_b"] / 4096.0, "bits": 16,
                "out_limit": maxout, "lsb_a": b["I_b"] / 4096.0}
    if name not in vendor_loop.names():
        raise InputError(_F + "scale", code="not_choice",
                         choices=", ".join(("inovance",) + vendor_loop.names()), got=shown(name))
    profiles, status = vendor_loop.profile_data(report)
    if not status[name]["representable"]:
        raise InputError(_F + "scale", code="sim_code_scale", vendor={"vendor": name},
                         problems=", ".join(p["code"] for p in status[name]["problems"]))
    inp = report["input"]
    peak = math.sqrt(2.0) if inp["conventions"]["base"] == "rms" else 1.0
    ctl = vendor_loop.controllers(profiles, umax_pu * b["U_b"] * peak, inp["drive"]["udc_v"])[name]
    return {"to_count": peak / ctl["i_lsb"], "to_volt": ctl["u_lsb"] / peak,
            "bits": ctl["fb_bits"], "out_limit": ctl["out_limit"], "lsb_a": ctl["i_lsb"] / peak}


def run_code_steps(z, binding: Binding, sc: dict, ref_d: float, ref_q: float, held_q: int,
                   n: int, delay: bool):
    """The routine's two instances on the SI plant for n+1 samples.

    Parameters
    ----------
    z : Zoh — SI plant transition (A, V in the report's dq scale)
    binding : Binding ; sc : dict — :func:`scale`
    ref_d, ref_q : float, A — references
    held_q : int — the q output a one-sample delay holds at t = 0 (counts)
    n : int ≥ 1 ; delay : bool

    Returns
    -------
    generator — yields every :data:`SLICE_PERIODS` periods, returns a dict ``id, iq, ud, uq``
    (A, V), ``sat`` (0/1: an output at or beyond the voltage limit), the integers ``fb_d,
    fb_q, out_d, out_q``, ``events`` (``feedback_saturate``, ``beyond_limit``), ``flags``
    (the tracer's flags met), ``first_event`` ({axis, call, line, kind, name} or None).
    """
    plant = z.advance()
    to_count, to_volt, lim = sc["to_count"], sc["to_volt"], sc["out_limit"]
    hi = (1 << (sc["bits"] - 1)) - 1
    lo = -hi - 1
    ev = {"feedback_saturate": 0, "beyond_limit": 0}

    def count(x: float) -> int:
        v = x * to_count
        c = int(v + 0.5) if v >= 0 else -int(0.5 - v)
        if c > hi or c < lo:
            ev["feedback_saturate"] += 1
            c = hi if c > hi else lo
        return c

    r_d, r_q = count(ref_d), count(ref_q)
    names = binding.names
    inst = binding.instances
    xd, xq = z.x0
    prev_d, prev_q = 0.0, max(-lim, min(lim, held_q)) * to_volt
    cols = {k: array("d") for k in ("id", "iq", "ud", "uq")}
    ints = {k: array("q") for k in ("fb_d", "fb_q", "out_d", "out_q")}
    sats = array("b")
    for k in range(n + 1):
        if k and not k % SLICE_PERIODS:
            yield
        cols["id"].append(xd)
        cols["iq"].append(xq)
        outs = []
        for axis, x, r in (("d", xd, r_d), ("q", xq, r_q)):
            fb = count(x)
            given = {}
            if names["reference"] is not None:
                given[names["reference"]] = r
            if names["feedback"] is not None:
                given[names["feedback"]] = fb
            if names["error"] is not None:
                given[names["error"]] = r - fb
            o = inst[axis].call(k, given)
            ints["fb_" + axis].append(fb)
            ints["out_" + axis].append(o)
            if o > lim or o < -lim:
                ev["beyond_limit"] += 1
            outs.append(o)
        if inst["d"].statements + inst["q"].statements > MAX_STATEMENTS:
            raise InputError("sim.current.duration_s", code="sim_code_steps", call=k,
                             limit=MAX_STATEMENTS)
        od, oq = outs
        sats.append(od >= lim or od <= -lim or oq >= lim or oq <= -lim)
        od_v, oq_v = od * to_volt, oq * to_volt
        if delay:
            ad, aq, prev_d, prev_q = prev_d, prev_q, od_v, oq_v
        else:
            ad, aq = od_v, oq_v
        cols["ud"].append(ad)
        cols["uq"].append(aq)
        xd, xq = plant(xd, xq, ad, aq)
    first = None
    for axis in ("d", "q"):
        e = inst[axis].event
        if e is not None and (first is None or e[0] < first["call"]):
            first = {"axis": axis, "call": e[0], "line": e[1], "kind": e[2], "name": e[3]}
    flags = sorted(inst["d"].flags | inst["q"].flags)
    return {**cols, "sat": sats, **ints, "events": ev, "flags": flags, "first_event": first}


def run_code(*args, **kwargs):
    """:func:`run_code_steps` run to the end: the same arguments, the same result."""
    return finish(run_code_steps(*args, **kwargs))
