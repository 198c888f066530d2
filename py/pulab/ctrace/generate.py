"""Generated per-call inputs for sequences: a step, a ramp, a sine, noise.

A spec is ``KIND:PARAM=VALUE,PARAM=VALUE`` (the CLI's ``--gen NAME=SPEC``, the API's
``gen: {NAME: SPEC}``); call ``k`` (from 0) gets

``step:at=K[,before=V0][,after=V1]``
    ``before`` (default 0) for ``k < at``, ``after`` (default 1) from call ``at`` on;
``ramp:start=S,slope=D[,min=LO][,max=HI]``
    ``S + D·k``, kept within ``[LO, HI]`` when given (a ramp that stops at its target);
``sine:amp=A,period=P[,offset=O][,phase=DEG]``
    ``O + A·sin(2π·k/P + DEG·π/180)`` (``P`` in calls, > 0);
``noise:amp=A[,dist=uniform|gauss][,seed=S][,offset=O]``
    ``O`` + uniform in ``[−A, A]`` (default) or Gaussian with standard deviation ``A``, from
    Python's ``random.Random(S)`` (``S`` default 0): the same spec gives the same values on
    every run and machine.

Each value is rounded to the nearest integer (halves away from zero) and held within the
input's C type: a value beyond it becomes the type's limit, and the result says so
(``clamped``, ``first_clamped``) — the firmware's variable could not have held it.

Examples
--------
>>> values(parse_spec("x", "step:at=2,before=-5,after=7"), 4, -32768, 32767)[0]
[-5, -5, 7, 7]
>>> values(parse_spec("x", "ramp:start=0,slope=20000"), 3, -32768, 32767)  # held at 32767
([0, 20000, 32767], 1, 2)
>>> values(parse_spec("x", "sine:amp=1000,period=4"), 4, -32768, 32767)[0]
[0, 1000, 0, -1000]
"""

from __future__ import annotations

import math
import random

from ..fixedpoint.cint import CType
from ..schema.errors import InputError
from ..schema.validate import shown

__all__ = ["KINDS", "parse_spec", "values", "generate"]

#: Each kind's parameters: required, then optional with their defaults.
KINDS = {
    "step": (("at",), {"before": 0.0, "after": 1.0}),
    "ramp": (("start", "slope"), {"min": None, "max": None}),
    "sine": (("amp", "period"), {"offset": 0.0, "phase": 0.0}),
    "noise": (("amp",), {"dist": "uniform", "seed": 0.0, "offset": 0.0}),
}
_WHOLE = ("at", "seed")


def parse_spec(name: str, spec) -> dict:
    """The generator ``spec`` (text, see the module) for input ``name`` as
    ``{"kind", PARAM: value…}``; a bad one is an :class:`InputError` of field ``gen.NAME``.

    >>> parse_spec("e", "noise:amp=50,dist=gauss,seed=7")
    {'kind': 'noise', 'amp': 50.0, 'dist': 'gauss', 'seed': 7, 'offset': 0.0}
    >>> parse_spec("e", "sine:amp=1")
    Traceback (most recent call last):
    ...
    pulab.schema.errors.InputError: gen.e: sine needs period=…
    """
    field = f"gen.{name}"
    if not isinstance(spec, str):
        raise InputError(field, code="trace_gen_kind", got=shown(spec), kinds=", ".join(KINDS))
    kind, _, rest = spec.strip().partition(":")
    kind = kind.strip()
    if kind not in KINDS:
        raise InputError(field, code="trace_gen_kind", got=shown(kind), kinds=", ".join(KINDS))
    required, optional = KINDS[kind]
    out = {"kind": kind}
    for item in filter(None, (p.strip() for p in rest.split(","))):
        key, eq, text = (s.strip() for s in item.partition("="))
        if key not in required and key not in optional:
            raise InputError(field, code="trace_gen_param", kind=kind, got=shown(key),
                             allowed=", ".join((*required, *optional)))
        if not eq or not text:
            raise InputError(field, code="trace_gen_number", param=key, got=shown(item))
        if key == "dist":
            if text not in ("uniform", "gauss"):
                raise InputError(field, code="not_choice", choices="uniform, gauss",
                                 got=shown(text))
            out[key] = text
            continue
        try:
            number = float(text)
        except ValueError:
            number = math.nan
        if not math.isfinite(number):
            raise InputError(field, code="trace_gen_number", param=key, got=shown(text))
        if key in _WHOLE:
            if number != int(number) or number < 0:
                raise InputError(field, code="trace_gen_whole", param=key, got=shown(text))
            number = int(number)
        out[key] = number
    for key in required:
        if key not in out:
            raise InputError(field, code="trace_gen_missing", kind=kind, param=key)
    for key, default in optional.items():
        out.setdefault(key, default)
    if kind == "sine" and out["period"] <= 0:
        raise InputError(field, code="trace_gen_period", got=shown(out["period"]))
    if kind == "ramp" and None not in (out["min"], out["max"]) and out["min"] > out["max"]:
        raise InputError(field, code="trace_gen_order", lo=shown(out["min"]),
                         hi=shown(out["max"]))
    if kind == "noise":
        out["seed"] = int(out["seed"])
    return out


def _raw(spec: dict, calls: int) -> list:
    """The generator's real values for calls 0..calls−1."""
    kind = spec["kind"]
    if kind == "step":
        return [spec["before"] if k < spec["at"] else spec["after"] for k in range(calls)]
    if kind == "ramp":
        lo = -math.inf if spec["min"] is None else spec["min"]
        hi = math.inf if spec["max"] is None else spec["max"]
        return [min(hi, max(lo, spec["start"] + spec["slope"] * k)) for k in range(calls)]
    if kind == "sine":
        w, phase = 2 * math.pi / spec["period"], math.radians(spec["phase"])
        return [spec["offset"] + spec["amp"] * math.sin(w * k + phase) for k in range(calls)]
    rng = random.Random(spec["seed"])
    amp, offset = spec["amp"], spec["offset"]
    if spec["dist"] == "gauss":
        return [offset + rng.gauss(0.0, amp) for _ in range(calls)]
    return [offset + amp * (2.0 * rng.random() - 1.0) for _ in range(calls)]


def values(spec: dict, calls: int, lo: int, hi: int) -> tuple:
    """The integers a parsed ``spec`` gives calls 0..calls−1 in a C type of range
    ``[lo, hi]``, how many were held at a limit, and the first such call (None when none)."""
    out, first, count = [], None, 0
    for k, x in enumerate(_raw(spec, calls)):
        # beyond binary64 (offset 1e308 plus a swing): past either limit anyway
        n = int(math.floor(abs(x) + 0.5)) * (1 if x >= 0 else -1) if math.isfinite(x) else \
            hi + 1 if x > 0 else lo - 1
        if not lo <= n <= hi:
            n = hi if n > hi else lo
            first = k if first is None else first
            count += 1
        out.append(n)
    return out, count, first


def generate(checked, gen: dict, calls: int) -> tuple:
    """Per-call rows (``[{NAME: int}…]``, one per call) for the generators ``gen``
    ({input name: spec text}) of the compiled code ``checked``, and the report of each
    (``{"spec", "type", "values", "clamped", "first_clamped"}``)."""
    if not isinstance(gen, dict):
        raise InputError("gen", code="not_object", got=shown(gen))
    rows = [{} for _ in range(calls)]
    report = {}
    for name, text in gen.items():
        sym = checked.symbols.get(name) if isinstance(name, str) else None
        if sym is None or sym.initialized or not isinstance(sym.ctype, CType):
            raise InputError(f"gen.{name}", code="trace_gen_name", name=shown(name),
                             inputs=", ".join(checked.inputs) or "none")
        spec = parse_spec(name, text)
        got, clamped, first = values(spec, calls, sym.ctype.min, sym.ctype.max)
        for row, v in zip(rows, got):
            row[name] = v
        report[name] = {"spec": text.strip(), "type": sym.spelling, "values": got,
                        "clamped": clamped, "first_clamped": first}
    return rows, report
