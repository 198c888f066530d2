"""Seeded generator of adversarial report inputs (issue 14), as JSON text or raw bytes.

Each case starts from a valid input (the seed motor, with a short simulation so
valid cases stay fast) and applies one or two mutations from four families:
structural (wrong shapes, deep nesting, missing and unknown sections), type (a
field replaced by a value of another JSON type), numeric edge (signed zero,
subnormals, the float range's ends, integer literals of 309+ digits, NaN and
Infinity literals, the period caps of the simulations) and unicode (keys and
strings with newline, NUL, U+2028, lone surrogates, the empty key). A few cases
are text-level: truncated, bracket bombs, invalid UTF-8 (bytes, CLI only).

``analysis.robust`` has its own cases (:func:`robust_cases`): a valid robustness
section costs about 0.5 s of computation, so its fields are mutated on their own,
with counts (``samples``, ``grid``) drawn from edges that stay cheap when valid.
"""
from __future__ import annotations

import copy
import json
import random

from conftest import SEED_INPUT
from pulab.profiles import MODULES
from pulab.schema.fields import FIELDS as SCHEMA_FIELDS

__all__ = ["cases", "robust_cases", "FIELDS", "ROBUST_FIELDS"]

BASE = copy.deepcopy(SEED_INPUT)
# A short run keeps valid cases cheap; mutations of these two reach the caps.
BASE["sim"] = {"current": {"duration_s": 2e-3}, "pll": {"duration_s": 2e-3}}

#: Every field path of the input: the schema's fields (every section) and each vendor profile's
#: options; the robustness section's apart (ROBUST_FIELDS).
FIELDS = [tuple(f.path.split(".")) for f in SCHEMA_FIELDS if not f.path.startswith("analysis.robust.")] + [
    ("profiles", name, opt[0]) for name, mod in MODULES.items() for opt in mod.OPTIONS]
ROBUST_FIELDS = [tuple(f.path.split(".")) for f in SCHEMA_FIELDS if f.path.startswith("analysis.robust.")]

NASTY_TEXT = ["", " ", "\n", "a\nb", "\r", "\x00", "\u2028", "\u2029", "\ud800", "\udfff",
              "\u202e", "\ufeff", "😀", "电机", "'", '"', "\\", "motor.rs_ohm", "[0]", "toString",
              "__proto__", "constructor", "x" * 5000, "\t", "\x1b[31m", "NaN", "1e999", "rms ",
              "d", "q", "custom", "integers"]

# Literal JSON number texts: the parser sees these exactly as written.
NUMBER_LITERALS = ["0", "-0", "-0.0", "1e-324", "5e-324", "2.2250738585072014e-308",
                   "1.7976931348623157e308", "-1.7976931348623157e308", "1e308", "1e309",
                   "-1e309", "1" + "0" * 308, "9" * 309, "-" + "9" * 309, "9" * 4000,
                   "1" + "0" * 4400, "NaN", "Infinity", "-Infinity", "2147483647",
                   "2147483648", "-2147483648", "9223372036854775808", "18446744073709551616",
                   "1e-9", "9.99e-10", "1", "1.0", "1.5", "-1", "65535", "65536", "1e9",
                   "1000000001", "1e-3", "1e3", "0.5", "100", "200000", "500000", "1e300",
                   "4.9e-324", "123456789012345678901234567890"]

# Simulation lengths: tiny, invalid, or beyond the caps (200 000 / 500 000 periods at Ts = 1e-4 s),
# never a long valid run (that would only cost time).
# Counts of the robustness analysis: edges of their ranges, none that is valid and slow.
COUNT_LITERALS = ["0", "-0", "-1", "1", "2", "3", "1.5", "2.0", "42", "1000001", "2e6", "1e7",
                  "9223372036854775807", "9223372036854775808", "1e309", "9" * 309, "NaN", "1e-9"]
DURATION_LITERALS = ["0", "-0", "-1", "1e-9", "1e-300", "5e-324", "2e-3", "1e-3", "20.0001", "50.0001",
                     "20000", "1e300", "1e309", "1" + "0" * 308, "9" * 309, "NaN", "Infinity", "1e9"]

def _value(rng: random.Random, depth: int = 0):
    """A random JSON value (as a Python object) of any type."""
    kind = rng.randrange(9 if depth < 3 else 6)
    if kind == 0:
        return None
    if kind == 1:
        return rng.choice([True, False])
    if kind == 2:
        return rng.choice([0, -1, 1, 2 ** 31 - 1, 2 ** 31, -2 ** 63, 2 ** 64, 10 ** 20])
    if kind == 3:
        return rng.choice([0.0, -0.0, 1e-300, 1e300, -1e308, 5e-324, 0.1, 1e9, 1.0000001e9])
    if kind in (4, 5):
        return rng.choice(NASTY_TEXT)
    if kind == 6:
        return [_value(rng, depth + 1) for _ in range(rng.randrange(3))]
    if kind == 7:
        return {rng.choice(NASTY_TEXT): _value(rng, depth + 1) for _ in range(rng.randrange(3))}
    return {"toString": 1} if rng.random() < 0.5 else {"valueOf": [1]}


def _get_parent(inp: dict, path: tuple) -> dict:
    node = inp
    for k in path[:-1]:
        if not isinstance(node.get(k), dict):
            node[k] = {}
        node = node[k]
    return node


def _mutate(rng: random.Random, inp: dict, fields: list = FIELDS) -> tuple:
    """Apply one mutation to one of ``fields``; returns (object, literal substitutions
    {marker: text})."""
    lits = {}
    family = rng.randrange(5)
    path = rng.choice(fields)
    if family == 0:  # structural
        choice = rng.randrange(8)
        if choice == 0:
            return _value(rng), lits
        if choice == 1:
            inp.pop(rng.choice(list(inp)), None)
        elif choice == 2:
            inp[rng.choice(NASTY_TEXT)] = _value(rng)
        elif choice == 3:
            _get_parent(inp, path)[rng.choice(NASTY_TEXT)] = _value(rng)
        elif choice == 4:
            # Written as text: json.dumps itself would recurse too deep.
            depth = rng.choice([10, 28, 29, 30, 31, 100, 1000, 5000])
            marker = f"@@{rng.randrange(10 ** 9)}@@"
            lits[marker] = ("[" * depth + "1" + "]" * depth if rng.random() < 0.5 else
                            '{"k":' * depth + "1" + "}" * depth)
            _get_parent(inp, path)[path[-1]] = marker
        elif choice == 5:
            sec = path[0]
            inp[sec] = _value(rng)
        elif choice == 6:
            _get_parent(inp, path).pop(path[-1], None)
        else:
            inp["sim"] = rng.choice([None, {}, [], {"current": None}, {"pll": []}, "sim"])
    elif family == 1:  # type
        _get_parent(inp, path)[path[-1]] = _value(rng)
    elif family == 2:  # numeric edge, written as a literal
        marker = f"@@{rng.randrange(10 ** 9)}@@"
        lits[marker] = rng.choice(DURATION_LITERALS if path[-1] == "duration_s" else
                                  COUNT_LITERALS if path[-1] in ("samples", "grid") else NUMBER_LITERALS)
        _get_parent(inp, path)[path[-1]] = marker
    elif family == 3:  # coherent combinations that reach deeper code
        marker, other = f"@@{rng.randrange(10 ** 9)}@@", f"@@{rng.randrange(10 ** 9)}@@"
        lits[marker], lits[other] = rng.choice(NUMBER_LITERALS), rng.choice(NUMBER_LITERALS)
        duration = f"@@{rng.randrange(10 ** 9)}@@"
        lits[duration] = rng.choice(DURATION_LITERALS)
        section, value = rng.choice([
            ("current_loop", {"method": "integers", "pm_kp": marker, "pm_ki": other}),
            ("current_loop", {"method": "manual", "kp": marker, "ki": other}),
            ("conventions", {"base": "custom", "base_voltage_v": marker, "base_current_a": other}),
            ("sim", {"current": {"duration_s": duration, "step_a": other}, "pll": {"duration_s": duration}}),
            ("sim", {"pll": {"duration_s": 1e-3, "ramp_hz_per_s": marker, "speed_hz": other}}),
            ("drive", {"udc_v": marker, "ts_s": other}),
            ("datasheet", {"speed_rpm": marker, "ke_v_per_krpm": other, "ke_measure": "peak"}),
            ("datasheet", {"kt_nm_per_a": marker, "rs_line_ohm": other, "winding": "delta"}),
            ("analysis", {"speed": {"inertia_kg_m2": marker, "ts_s": other, "response": True}}),
            ("analysis", {"design": "bandwidth", "target_bandwidth_hz": marker, "bode": True}),
            ("profiles", {rng.choice(list(MODULES)): {rng.choice(FIELDS)[-1]: marker}}),
        ])
        if section == "datasheet" and isinstance(inp.get("motor"), dict):
            for k in ("rated_freq_hz", "bemf_v", "rs_ohm", "ld_h", "lq_h"):  # the datasheet's to fill
                inp["motor"].pop(k, None)
        inp[section] = value
    else:  # unicode in keys and strings
        if rng.random() < 0.5:
            _get_parent(inp, path)[rng.choice(NASTY_TEXT)] = rng.choice([1, "x", None])
        else:
            _get_parent(inp, path)[path[-1]] = rng.choice(NASTY_TEXT)
    return inp, lits


def _text(obj, lits: dict, ascii_only: bool) -> str:
    text = json.dumps(obj, ensure_ascii=ascii_only)
    for marker, literal in lits.items():
        text = text.replace(json.dumps(marker), literal)
    return text


def cases(n: int, seed: int = 14):
    """``n`` adversarial inputs: yields ``bytes`` (UTF-8 unless deliberately not)."""
    rng = random.Random(seed)
    for i in range(n):
        r = rng.random()
        if r < 0.02:  # text-level: broken JSON, bracket bombs, bad encodings
            yield rng.choice([b"", b"{", b"[" * 100000, b"{\"motor\":" * 50000, b"\xff\xfe{}",
                              b"{\"motor\": \xc3}", b"\"\\ud800\"", b"nul", b"{} {}",
                              b"{\"a\":1,}", b"\x00", json.dumps(BASE).encode()[:rng.randrange(200)]])
            continue
        inp = copy.deepcopy(BASE)
        if rng.random() < 0.2:  # no simulation asked for
            inp.pop("sim")
        lits = {}
        for _ in range(1 + (rng.random() < 0.3)):
            obj, more = _mutate(rng, inp)
            lits.update(more)
            if not isinstance(obj, dict):
                inp = obj
                break
        # An untouched simulation costs time and tests nothing new: keep it in one of twenty.
        if isinstance(inp, dict) and inp.get("sim") == BASE["sim"] and rng.random() < 0.95:
            del inp["sim"]
        try:
            yield _text(inp, lits, rng.random() < 0.5).encode("utf-8", "surrogatepass")
        except ValueError:
            yield json.dumps(inp).encode()


#: Robustness sections the mutations start from: every default, and one with every field given.
ROBUST_BASES = [{}, {"temperature_c": [-20, 120], "reference_c": 25, "copper_alpha_per_k": 0.004,
                     "magnet": -0.1, "peak_current_a": 4, "inductance_table": [[0, 6e-4, 6e-4], [3, 5e-4, 5e-4]],
                     "udc_tolerance_pct": 5, "bus_compensated": False, "tolerance_rs_pct": 2,
                     "tolerance_l_pct": 2, "tolerance_psi_pct": 2, "samples": 3, "seed": 9,
                     "min_phase_margin_deg": 30, "min_gain_margin_db": 3, "grid": 2}]


def robust_cases(n: int, seed: int = 15):
    """``n`` report inputs (UTF-8 JSON bytes) whose ``analysis.robust`` has one or two mutations."""
    rng = random.Random(seed)
    for _ in range(n):
        inp = copy.deepcopy({k: v for k, v in BASE.items() if k != "sim"})
        inp["analysis"] = {"robust": copy.deepcopy(rng.choice(ROBUST_BASES))}
        lits = {}
        for _ in range(1 + (rng.random() < 0.3)):
            obj, more = _mutate(rng, inp, ROBUST_FIELDS)
            lits.update(more)
            if not isinstance(obj, dict):
                inp = obj
                break
        try:
            yield _text(inp, lits, rng.random() < 0.5).encode("utf-8", "surrogatepass")
        except ValueError:
            yield json.dumps(inp).encode()
