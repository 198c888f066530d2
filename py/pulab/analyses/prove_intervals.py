"""The seed's vendor blocks over boxes of raw integers, for the family prover
(:mod:`pulab.analyses.prove`): the same C the report runs (:mod:`pulab.profiles.inovance.code`),
through the tracer's interval evaluator (:class:`~pulab.ctrace.abstract.BoxEvaluator`).

Each assignment gives the hull of the values it stores over the box and the failures some
point may meet, named as the report names them (``wrap``, ``store`` into a Uint16
parameter, ``div0``); :func:`error_bound` bounds the quantization error from the lowest
value of each floor the code takes.

>>> own, before = interval_steps("FreqPer", {"FreqRated01": (100, 200),
...                                          "FullFreq01": (22000, 22000)})
>>> own[0]["value"], own[0]["flags"], own[0]["type"]
((148, 297), [], 'Uint16')
"""

from __future__ import annotations

import math

from ..ctrace.abstract import BoxEvaluator
from ..ctrace.parser import ExprStmt
from ..ctrace.tracing import DEFAULT_GLOBAL_Q
from ..profiles.inovance.code import SQRT3, TWO_PI, VENDOR_BLOCKS, block_program

__all__ = ["interval_steps", "error_bound"]

_UINT16_MAX = 0xFFFF


def interval_steps(name: str, box: dict):
    """The assignments of vendor result ``name`` over ``box`` (raw field → (lo, hi); a field
    the box lacks ranges over Uint16, and each range is cut to what a Uint16 holds), as
    (its own assignments, those before it that it reads): each ``value`` (lo, hi),
    ``flags`` and ``type`` (the variable's spelling).  None when every point of the box
    divides by zero before the result is stored (the concrete code stops there)."""
    block, own, before = VENDOR_BLOCKS[name]
    checked = block_program(block).checked
    ranges = {}
    for path in checked.inputs:
        lo, hi = box.get(path.rpartition(".")[2], (0, _UINT16_MAX))
        ranges[path] = (min(lo, _UINT16_MAX), min(hi, _UINT16_MAX))
    records = BoxEvaluator.over(checked, ranges, DEFAULT_GLOBAL_Q).run_box()
    steps = []
    for s in checked.program.statements:
        if type(s) is not ExprStmt:
            continue
        rec = records.get((s.line, s.column))
        if rec is None or rec["lo"] is None:  # every point stopped at or before it
            break
        spelling = checked.symbols[rec["var"]].spelling
        flags = {"div0" if k == "division_by_zero" else
                 "store" if k == "conversion" and spelling == "Uint16" else "wrap"
                 for k in rec["kinds"]}
        steps.append({"value": (rec["lo"], rec["hi"]), "flags": sorted(flags),
                      "type": spelling})
    if len(steps) < own.stop:
        return None
    return steps[own], steps[before]


def _low(step: dict) -> int:
    return step["value"][0]


def _floor(low: int, exponent: int):
    """floor(y)/y, raised to ``exponent`` (±1), for every real y ≥ ``low`` (a positive
    integer, the floor's lowest value): floor(y)/y ∈ (1 − 1/low, 1].  None when unbounded."""
    if low < 1 or exponent < 0 and low < 2:
        return None
    f = 1.0 - 1.0 / low
    return (f, 1.0) if exponent > 0 else (1.0, 1.0 / f)


def _ld_factors(trace: list, unit: str) -> list:
    """LD/LQ over its ideal (seed 1.4-3 … 1.4-15): with B = m_BaseL, z = L·2^14/B and
    h = floor(B/2)/B ∈ [1/2 − 1/(2B), 1/2], m = floor(z + h) differs from z by
    (−1/2 − 1/(2B), 1/2]; then floor(m/10); B itself is V·3678·5000/(I·F) times two floors."""
    b1, b, _, m, ld = (_low(s) for s in trace)
    z = m - 0.5  # m ≤ z + 1/2
    if z <= 0 or b < 1:
        return [None]
    k = (1e-6 if unit == "uH" else 1e-5) * 8192.0 * TWO_PI * SQRT3 / 1e4
    c = 16384.0 / (10.0 * 3678.0 * 5000.0) / k
    return [(c, c), _floor(b1, -1), _floor(b, -1),
            (1.0 - (0.5 + 0.5 / b) / z, 1.0 + 0.5 / z), _floor(ld, 1)]


def error_bound(name: str, box: dict, unit: str):
    """A bound on |error_pct| of vendor result ``name`` (its integer against ``ideal``) for
    every raw point of ``box`` (raw field → (lo, hi)); None where an assignment it runs
    (FreqPer's too, for FluxRotor) may wrap, change a store or divide by zero, or a floor
    may reach 0.

    Every result is its ideal times a constant (the code's integer constants over the real
    ones: 18597/2^14 for 10^5/(√3·2^16)…) times, per floor of the code, floor(y)/y — in the
    numerator, or in the denominator (FreqPer inside FluxRotor, m_BaseL inside LD) — and, for
    LD/LQ, its rounded division; each floor's lowest value over the box bounds its factor.
    The bound is rounded up by 1e-10 percentage points for the doubles' own rounding.

    >>> from pulab.profiles.inovance.code import freq_per
    >>> raw = {"FreqRated01": 22000, "FullFreq01": 22000}
    >>> error_bound("FreqPer", {k: (v, v) for k, v in raw.items()}, "10uH") \\
    ...     >= abs(freq_per(raw)["error_pct"])
    True
    """
    run = interval_steps(name, box)
    if run is None:
        return None
    own, before = run
    steps = own + before  # a FreqPer that wraps is its own failure, but breaks this bound
    if name in ("LD", "LQ"):
        factors = _ld_factors(own, unit)
    elif name == "FluxRotor":  # m·2^15/FreqPer: FreqPer's floor divides
        factors = [_floor(_low(own[0]), 1), _floor(_low(own[1]), 1),
                   _floor(_low(before[0]), -1)]
    elif name in ("pm_maxout_vol", "maxu"):  # maxu = pm_maxout_vol·2^12 exactly
        c = 2316.0 / 32768.0 * 10.0 * math.sqrt(2.0)
        factors = [(c, c)] + [_floor(_low(s), 1) for s in (before if name == "maxu" else own)]
    else:
        c = 18597.0 / 16384.0 / (SQRT3 * 65536.0 / 1e5) if name == "Rpm" else 1.0
        factors = [(c, c)] + [_floor(_low(s), 1) for s in own]
    if any(f is None for f in factors) or any({"wrap", "store", "div0"} & set(s["flags"])
                                               for s in steps):
        return None
    lo = math.prod(f[0] for f in factors)
    hi = math.prod(f[1] for f in factors)
    return 100.0 * max(1.0 - lo, hi - 1.0, 0.0) + 1e-10
