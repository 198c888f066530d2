"""The Inovance C2000 normalization code of seed 1.4 and 2.2, run as the seed's C.

The code is :data:`pulab.ctrace.examples.EXAMPLES`' C text, the one copy: each result runs
its block through the tracer (:mod:`pulab.ctrace`: parsed and checked once as C2000
code, then compiled into closures, :mod:`pulab.ctrace.compile`), so the integer after
every statement is the one the firmware holds, with the wrap and truncation it suffers.
Each result also carries ``ideal``, the exact real value the code approximates from the
same raw inputs, and ``si``, what the integer means back in SI units for this motor.

Raw inputs are the firmware's Uint16 parameters:

========== ===================================== ==============
name       meaning                               unit
========== ===================================== ==============
Voltage    rated line-to-line RMS voltage        1 V
Current    rated RMS current                     0.01 A
FullFreq01 base (maximum) frequency f_b          0.01 Hz
FreqRated01 rated frequency                      0.01 Hz
RsPm       stator resistance per phase           1 mΩ
LD, LQ     d/q inductance                        0.01 mH (or 1 µH)
BemfVolt   back-EMF line RMS at rated frequency  0.1 V
uDCFilter  DC bus voltage                        0.1 V
========== ===================================== ==============

Examples
--------
>>> raw = {"Voltage": 17, "Current": 150, "RsPm": 1500, "FullFreq01": 22000}
>>> r = rpm(raw)
>>> r["value"], round(r["ideal"], 1)        # seed 1.4-1, 1.4-2
(15022, 15023.6)
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ...ctrace.compile import Stopped, compiled
from ...ctrace.examples import EXAMPLES
from ...ctrace.parser import ExprStmt, Member, Var
from ...ctrace.tracing import compile_code
from ...schema.errors import InputError
from ...schema.fields import RAW_FIELDS
from ...fixedpoint.qformat import round_half_away

__all__ = [
    "RAW_FIELDS", "RAW_SCALE", "INDUCTANCE_SCALE", "raw_source", "raw_value", "raw_split",
    "raw_from_si", "round_half_away", "vendor_split",
    "rpm", "inductance", "freq_per", "flux_rotor", "max_output_voltage",
    "vendor_results", "VENDOR_RESULTS", "VENDOR_READS", "VENDOR_BLOCKS", "block_program",
    "current_pi_step", "PiStep", "to_si",
]

SQRT3 = math.sqrt(3.0)
TWO_PI = 2.0 * math.pi

#: The SI input each raw firmware field (the schema's RAW_FIELDS) comes from, and SI → raw scale.
RAW_SCALE = {
    "Voltage": ("motor.rated_voltage_v", 1.0),
    "Current": ("motor.rated_current_a", 100.0),
    "FullFreq01": ("drive.base_freq_hz", 100.0),
    "FreqRated01": ("motor.rated_freq_hz", 100.0),
    "RsPm": ("motor.rs_ohm", 1000.0),
    "LD": ("motor.ld_h", None),  # depends on the inductance unit
    "LQ": ("motor.lq_h", None),
    "BemfVolt": ("motor.bemf_v", 10.0),
    "uDCFilter": ("drive.udc_v", 10.0),
}
#: SI henry → raw LD/LQ for each inductance unit.
INDUCTANCE_SCALE = {"10uH": 1e5, "uH": 1e6}


def raw_source(name: str, inductance_unit: str) -> tuple[str, float]:
    """The SI input path a raw field comes from and the SI → raw scale factor."""
    path, scale = RAW_SCALE[name]
    return path, scale if scale is not None else INDUCTANCE_SCALE[inductance_unit]


def raw_value(name: str, si_value: float, inductance_unit: str) -> int:
    """The raw integer of field ``name`` for its SI value (before the Uint16 range check).

    >>> raw_value("Current", 69.475, "10uH"), raw_value("Current", 69.47500000000001, "10uH")
    (6947, 6948)
    """
    return round_half_away(float(si_value) * raw_source(name, inductance_unit)[1])


def raw_split(si: dict, inductance_unit: str, given: dict) -> tuple[dict, dict]:
    """Firmware integers from SI inputs, split into those a Uint16 parameter holds and those
    it cannot; values in ``given`` override.

    Parameters
    ----------
    si : dict
        Flat mapping from the SI field path (``motor.rs_ohm`` …) to its value.
    inductance_unit : {'10uH', 'uH'}
    given : dict
        Raw values the user entered directly.

    Returns
    -------
    raw : dict
        name → integer in 0..65535.
    outside : dict
        name → integer the SI value needs but Uint16 cannot hold (a limit of the firmware,
        not of the motor).

    Raises
    ------
    InputError
        Naming ``raw.NAME`` when a value the user typed is outside Uint16.

    Examples
    --------
    >>> raw, outside = raw_split({"drive.base_freq_hz": 3266.67}, "10uH", {})  # doctest: +SKIP
    """
    raw, outside = {}, {}
    for name in RAW_FIELDS:
        path = RAW_SCALE[name][0]
        v = given[name] if name in given else raw_value(name, si[path], inductance_unit)
        if 0 <= v <= 0xFFFF:
            raw[name] = v
        elif name in given:
            raise InputError(f"raw.{name}", code="raw_outside_given", value=v)
        else:
            outside[name] = v
    return raw, outside


def raw_from_si(si: dict, inductance_unit: str, given: dict) -> dict:
    """Firmware integers from SI inputs, every one required to fit (see :func:`raw_split`).

    Raises
    ------
    InputError
        Naming ``raw.NAME`` when a value is outside Uint16 (0..65535).
    """
    raw, outside = raw_split(si, inductance_unit, given)
    for name, v in outside.items():
        raise InputError(f"raw.{name}", code="raw_outside_from", value=v,
                         source=RAW_SCALE[name][0])
    return raw


def _ld_as(axis: str) -> str:
    """The seed's LD block for either axis (the firmware runs the same lines for LQ)."""
    code = EXAMPLES["ld"]["code"]
    return code if axis == "LD" else code.replace(".LD", ".LQ").replace("d-axis", "q-axis")


#: The seed's C of each block, by the name the results below use.
_CODE = {"rpm": EXAMPLES["rpm"]["code"], "LD": _ld_as("LD"), "LQ": _ld_as("LQ"),
         "flux": EXAMPLES["flux"]["code"], "maxu": EXAMPLES["maxu"]["code"],
         "pi": EXAMPLES["pi"]["code"]}

#: What each assignment of a block means, in statement order (notes about the C, shown
#: beside its integers in the report's traces).
_MEANINGS = {
    "rpm": ("R_s[mΩ]·I_b[0.01 A]/U_LL[V] = 10^5/√3 · R_pu", "R_pu·2^16 (Q16)"),
    "L": ("U_LL·3678/I_b[0.01 A]", "≈ 2·10^4·L_b[H]; 3678 ≈ 2·10^4/(√3·π)",
          "{name}·2^14 + m_BaseL/2", "10·L_pu·2^13", "L_pu·2^13 (Q13)"),
    "flux": ("f_n/f_b·2^15 (Q15)", "2π·f_n·ψ_r/U_b·2^12", "ψ_r/ψ_b·2^12 (Q12)"),
    "maxu": ("U_dc/√2 [V] (2316 ≈ 2^15/(10·√2))", "(U_dc/√2)/U_LL·2^12 (Q12)",
             "(U_dc/√2)/U_LL·2^24 (Q24)"),
    "pi": ("", "integral + Δi·ki (Q12·Q16 = Q28, >>4 → Q24)", "∈ [−maxu, maxu]",
           "(Q24 + Q12·Q12) >> 12 → Q12", "∈ [−pm_maxout_vol, pm_maxout_vol]",
           "u_d/U_LL·2^12 (Q12)"),
}
#: The LD/LQ result read in µH where the code expects 0.01 mH (the seed's "×10" puzzle).
_UH_MEANING = "10·L_pu·2^13 (µH ≠ 0.01 mH)"

#: Each division of a block that can meet a zero divisor: the raw field to blame and why, by
#: the assignment's index in the block (the tracer stops there).
_DIVISIONS = {
    "rpm": {0: ("Voltage", "Voltage = 0")},
    "L": {0: ("Current", "Current = 0"), 1: ("FullFreq01", "FullFreq01 = 0"),
          3: (None, "m_BaseL = Voltage·3678/Current·5000/FullFreq01 = 0")},
    "flux": {0: ("FullFreq01", "FullFreq01 = 0"), 1: ("Voltage", "Voltage*10 ≡ 0 (mod 2^16)"),
             2: ("FreqRated01",
                 "FreqPer = 0 (FreqRated01·2^15 < FullFreq01, or ≡ 0 mod 2^16)")},
    "maxu": {0: None, 1: ("Voltage", "Voltage = 0")},
}

#: The tracer's flags as the report names them: a changed value is a wrap (``store`` when
#: it is the store into a Uint16 parameter, see :func:`_trace`).
_FLAG = {"signed_overflow": "wrap", "unsigned_wrap": "wrap", "conversion": "wrap",
         "shift_count": "wrap", "truncation": "truncation", "saturate": "saturate"}


def block_program(block: str):
    """A block's closures (parsed, checked as C2000 code and compiled once; its checked
    program is ``.checked``), by the names of :data:`VENDOR_BLOCKS`."""
    prog = _PROGRAMS.get(block)
    if prog is None:
        prog = _PROGRAMS[block] = compiled(compile_code(_CODE[block], "c28x"))
    return prog


#: The blocks' closures, kept here: the tracer's own cache also serves the page's code.
_PROGRAMS: dict = {}


def _lines(block: str) -> list:
    return _CODE[block].splitlines()


#: The last block runs, by block and inputs (a report asks FreqPer and FluxRotor of one flux
#: run, pm_maxout_vol and maxu of one maxu run; a sweep or proof revisits points).
_RUNS: dict = {}
_RUNS_KEPT = 32


def _run(block: str, raw: dict) -> tuple:
    """Run a block on the raw parameters present in ``raw``: (its assignment steps, the
    index of the assignment it stopped at or None)."""
    prog = block_program(block)
    inputs = {p: raw[p.rpartition(".")[2]] for p in prog.checked.inputs
              if p.rpartition(".")[2] in raw}
    key = (block, *inputs.items())
    hit = _RUNS.get(key)
    if hit is not None:
        return hit
    try:
        steps, stop = prog.run(inputs).steps, None
    except Stopped as e:
        steps = e.steps
        stop = sum(1 for s in e.steps if type(s.stmt) is ExprStmt)
    out = _RUNS[key] = (tuple(s for s in steps if type(s.stmt) is ExprStmt), stop)
    while len(_RUNS) > _RUNS_KEPT:
        del _RUNS[next(iter(_RUNS))]
    return out


def _trace(block: str, steps: list, meanings: tuple, first: int = 0) -> list:
    """The report's trace of assignment steps (``first``: the index of the first in its
    block): the source line, variable, type, value, meaning and flags of each."""
    prog = block_program(block)
    lines = _lines(block)
    out = []
    for i, s in enumerate(steps, first):
        sym = prog.checked.symbols[s.var]
        flags = {_FLAG[f] for f in s.inner}
        if s.stored:  # the firmware silently keeps a Uint16 parameter modulo 65536
            flags.add("store" if sym.spelling == "Uint16" else "wrap")
        out.append({"code": lines[s.stmt.line - 1].strip(), "var": s.var, "type": sym.spelling,
                    "value": s.value, "meaning": meanings[i], "flags": sorted(flags)})
    return out


def _failed(block: str, stop: int, raw: dict, steps: list) -> InputError:
    field, why = _DIVISIONS["L" if block in ("LD", "LQ") else block][stop]
    if field is None:  # m_BaseL truncated to zero: blame the divisor that made it so
        field = "Current" if steps[0].value == 0 else "FullFreq01"
    return InputError(f"raw.{field}", code="firmware_div0", why=why)


def _result(trace: list, q: int, ideal: float, si: float, unit: str) -> dict:
    last = trace[-1]
    value = last["value"]
    return {"value": value, "ideal": ideal, "q": q, "type": last["type"], "si": si,
            "unit": unit, "error_pct": 0.0 if ideal == 0 else 100.0 * (value - ideal) / ideal,
            "flags": sorted({f for s in trace for f in s["flags"]}), "trace": trace}


def _bases(raw: dict) -> tuple[float, float, float]:
    """U_b (phase RMS), I_b and f_b as the firmware's raw values define them (seed 1.4-13);
    NaN for a parameter the firmware does not hold (no result that needs it is computed)."""
    return (raw.get("Voltage", math.nan) / SQRT3, raw.get("Current", math.nan) / 100.0,
            raw.get("FullFreq01", math.nan) / 100.0)


def _complete(block: str, raw: dict, upto: int) -> list:
    """The block's first ``upto`` assignment steps, or the InputError of the division that
    stops it before."""
    steps, stop = _run(block, raw)
    if stop is not None and stop < upto:
        raise _failed(block, stop, raw, steps)
    return list(steps[:upto])


def rpm(raw: dict) -> dict:
    """Stator resistance per unit, Q16 (seed 1.4-1, 1.4-2)."""
    if raw["Current"] == 0:
        # The C code computes 0, but per unit of Z_b = U_b/0 the number means nothing.
        raise InputError("raw.Current", code="firmware_div0", why="Z_b = U_b/I_b with Current = 0")
    trace = _trace("rpm", _complete("rpm", raw, 2), _MEANINGS["rpm"])
    u_b, i_b, _ = _bases(raw)
    z_b = u_b / i_b if i_b else math.inf
    ideal = (raw["RsPm"] / 1000.0) / z_b * 65536.0
    return _result(trace, 16, ideal, trace[-1]["value"] / 65536.0 * z_b, "Ω")


def inductance(raw: dict, axis: str, unit: str = "10uH") -> dict:
    """d- or q-axis inductance per unit, Q13 (seed 1.4-3 … 1.4-15).

    With ``unit='uH'`` the raw value is taken in µH, which is what the seed
    assumed; the code was written for 0.01 mH, so the result is 10× the Q13
    value — the seed's "×10" puzzle — and is flagged ``unit_uH``.
    """
    name = "LD" if axis == "d" else "LQ"
    meanings = tuple(m.format(name=name) for m in _MEANINGS["L"])
    trace = _trace(name, _complete(name, raw, 5), meanings)
    if unit == "uH":
        trace[-1]["meaning"] = _UH_MEANING
        trace[-1]["flags"] = sorted(trace[-1]["flags"] + ["unit_uH"])
    u_b, i_b, f_b = _bases(raw)
    l_b = u_b / (TWO_PI * f_b * i_b) if f_b * i_b else math.inf
    l_si = raw[name] * (1e-6 if unit == "uH" else 1e-5)
    ideal = l_si / l_b * 8192.0
    return _result(trace, 13, ideal, trace[-1]["value"] / 8192.0 * l_b, "H")


def freq_per(raw: dict) -> dict:
    """Rated frequency per unit, Q15 (the first line of the seed's flux block)."""
    trace = _trace("flux", _complete("flux", raw, 1), _MEANINGS["flux"])
    ideal = raw["FreqRated01"] / raw["FullFreq01"] * 32768.0
    return _result(trace, 15, ideal,
                   trace[-1]["value"] / 32768.0 * raw["FullFreq01"] / 100.0, "Hz")


def flux_rotor(raw: dict) -> dict:
    """Permanent-magnet flux per unit, Q12 (seed 1.4-23 … 1.4-25), after FreqPer."""
    trace = _trace("flux", _complete("flux", raw, 3)[1:], _MEANINGS["flux"], 1)
    ideal = (raw["BemfVolt"] / 10.0) / raw["Voltage"] * raw["FullFreq01"] \
        / raw["FreqRated01"] * 4096.0
    u_b, _, f_b = _bases(raw)
    psi_b = u_b / (TWO_PI * f_b)
    return _result(trace, 12, ideal, trace[-1]["value"] / 4096.0 * psi_b, "Wb")


def max_output_voltage(raw: dict) -> tuple[dict, dict]:
    """pm_maxout_vol (Q12) and maxu (Q24), seed 2.2-1, 2.2-2."""
    steps = _complete("maxu", raw, 3)
    vol_trace = _trace("maxu", steps[:2], _MEANINGS["maxu"])
    ideal = (raw["uDCFilter"] / 10.0 / math.sqrt(2.0)) / raw["Voltage"] * 4096.0
    vol = _result(vol_trace, 12, ideal, vol_trace[-1]["value"] / 4096.0 * raw["Voltage"], "V")
    maxu_trace = _trace("maxu", steps[2:], _MEANINGS["maxu"], 2)
    maxu = _result(maxu_trace, 24, ideal * 4096.0,
                   maxu_trace[-1]["value"] / 16777216.0 * raw["Voltage"], "V")
    return vol, maxu


#: Each vendor result of seed 1.4 and 2.2, in report order, computed from the raw integers
#: alone (with the lines it reads, e.g. FluxRotor reads FreqPer), so one can be computed
#: without the others — a sweep bisecting one integer's boundary needs only that one.
VENDOR_RESULTS = {
    "Rpm": lambda raw, unit: rpm(raw),
    "LD": lambda raw, unit: inductance(raw, "d", unit),
    "LQ": lambda raw, unit: inductance(raw, "q", unit),
    "FreqPer": lambda raw, unit: freq_per(raw),
    "FluxRotor": lambda raw, unit: flux_rotor(raw),
    "pm_maxout_vol": lambda raw, unit: max_output_voltage(raw)[0],
    "maxu": lambda raw, unit: max_output_voltage(raw)[1],
}


def _read_paths(node, out: list) -> None:
    if type(node) is Member and node.flat is not None:
        out.append(node.flat.key)
    elif type(node) is Var:
        out.append(node.sym.key)
    else:
        for child in node.children():
            _read_paths(child, out)


def _reads(block: str, own: slice, before: slice = slice(0)) -> tuple:
    """The raw fields a result reads: the inputs its own assignments of the block read, then
    those of the assignments before it that it depends on, in the order the C reads them."""
    prog = block_program(block)
    stmts = [s for s in prog.checked.program.statements if type(s) is ExprStmt]
    paths: list = []
    for s in stmts[own] + stmts[before]:
        _read_paths(s.expr.value, paths)
    return tuple(dict.fromkeys(p.rpartition(".")[2] for p in paths if p in prog.checked.inputs))


#: Each vendor result's block, its own assignments there and the assignments before them
#: that it reads (FluxRotor divides by FreqPer, maxu shifts pm_maxout_vol).
VENDOR_BLOCKS = {
    "Rpm": ("rpm", slice(0, 2), slice(0)),
    "LD": ("LD", slice(0, 5), slice(0)),
    "LQ": ("LQ", slice(0, 5), slice(0)),
    "FreqPer": ("flux", slice(0, 1), slice(0)),
    "FluxRotor": ("flux", slice(1, 3), slice(0, 1)),
    "pm_maxout_vol": ("maxu", slice(0, 2), slice(0)),
    "maxu": ("maxu", slice(2, 3), slice(0, 2)),
}

#: The raw fields each vendor result reads (the C statements of its block and the ones before
#: it that it reads), so a caller may reuse a result while these stay the same.
VENDOR_READS = {name: _reads(*spec) for name, spec in VENDOR_BLOCKS.items()}


def vendor_results(raw: dict, inductance_unit: str) -> dict:
    """Every vendor result of seed 1.4 and 2.2, keyed as in the report contract."""
    return {name: f(raw, inductance_unit) for name, f in VENDOR_RESULTS.items()}


def vendor_split(raw: dict, inductance_unit: str) -> tuple[dict, dict]:
    """The vendor results the firmware can compute from ``raw``, and why the others cannot be.

    A result is left out when a raw field it reads is missing from ``raw`` (it did not fit
    Uint16) or when its C code divides by zero.

    Returns
    -------
    results : dict
        name → result, as :func:`vendor_results`.
    failed : dict
        name → :class:`InputError` (``raw.NAME``, the field that stops it).
    """
    results, failed = {}, {}
    for name, f in VENDOR_RESULTS.items():
        missing = [k for k in VENDOR_READS[name] if k not in raw]
        if missing:
            failed[name] = InputError(f"raw.{missing[0]}", code="raw_missing", name=missing[0])
            continue
        try:
            results[name] = f(raw, inductance_unit)
        except InputError as e:
            failed[name] = e
    return results, failed


def to_si(name: str, value: int, raw: dict, inductance_unit: str = "10uH") -> float:
    """What a firmware integer means in SI for this motor (the inverse of ``ideal``).

    >>> round(to_si("Rpm", 15022, {"Voltage": 17, "Current": 150, "FullFreq01": 22000}), 4)
    1.4998
    """
    u_b, i_b, f_b = _bases(raw)
    if name == "Rpm":
        return value / 65536.0 * u_b / i_b
    if name in ("LD", "LQ"):
        return value / 8192.0 * u_b / (TWO_PI * f_b * i_b)
    if name == "FreqPer":
        return value / 32768.0 * f_b
    if name == "FluxRotor":
        return value / 4096.0 * u_b / (TWO_PI * f_b)
    if name == "pm_maxout_vol":
        return value / 4096.0 * raw["Voltage"]
    if name == "maxu":
        return value / 16777216.0 * raw["Voltage"]
    raise ValueError(f"unknown vendor result {name!r}")


class PiStep(NamedTuple):
    """State after one vendor current-PI update."""

    integral: int
    out: int
    flags: frozenset


_LONG = (-(1 << 31), (1 << 31) - 1)
#: The PI block's inputs, in :func:`current_pi_step`'s argument order.
_PI_INPUTS = ("pm_integral_d", "pm_error_id", "pm_kp_d", "pm_ki_d", "maxu", "pm_maxout_vol")


def current_pi_step(integral: int, error: int, kp: int, ki: int, maxu: int,
                    maxout: int, trace: list | None = None) -> PiStep:
    """One update of the vendor current PI (seed 2.2, the C of its ``pi`` block), all
    arithmetic in 32-bit long.

    Parameters
    ----------
    integral : int, Q24 (per unit of rated line voltage)
    error : int, Q12 current error (per unit of rated current)
    kp : int, Q12 ; ki : int, Q16 (the "new" integral gain, Ts folded in)
    maxu : int, Q24 ; maxout : int, Q12
    trace : list, optional
        When given, one step per C statement of the update is appended (as in vendor
        results; the lower limit ``minu = -maxu`` is the block's first line, not listed).

    Returns
    -------
    PiStep
        New integral (Q24), output voltage (Q12) and the flags raised
        (``wrap``, ``truncation``, ``saturate``).

    Raises
    ------
    ValueError
        An argument outside long.

    Examples
    --------
    >>> current_pi_step(0, 410, 1000, 3000, 1 << 24, 4096)
    PiStep(integral=76875, out=118, flags=frozenset({'truncation'}))
    """
    args = (integral, error, kp, ki, maxu, maxout)
    lo, hi = _LONG
    for v in args:
        if not lo <= v <= hi:
            raise ValueError(f"{v} does not fit long")
    inputs = dict(zip(_PI_INPUTS, args))
    prog = block_program("pi")
    if trace is not None:
        run = prog.run(inputs)
        steps = [s for s in run.steps if type(s.stmt) is ExprStmt]
        for s in steps[1:]:
            trace.append({"code": _lines("pi")[s.stmt.line - 1].strip(), "var": s.var,
                          "type": "long", "value": s.value,
                          "meaning": _MEANINGS["pi"][steps.index(s)],
                          "flags": sorted({_FLAG[f] for f in s.flags})})
        mem, raised = run.values, [f for s in steps for f in s.flags]
    else:
        mem, raised = prog.values(inputs)
    return PiStep(mem["pm_integral_d"], mem["pm_ud"], frozenset([_FLAG[f] for f in raised]))
