"""Prove a product family's firmware integers in range, or find a motor that breaks one.

A sweep (:mod:`pulab.analyses.sweep`) samples one or two inputs; this module decides
for *every* input in a box (any numeric input paths, each with a range) whether each
firmware integer of the seed's Inovance code stays in range.  Per integer the
verdict is

``proven``
    for every input in the box: no wrap, no store that changes the number, no
    division by zero, no zero where a gain is meant, every raw parameter fits its
    Uint16;
``violated``
    with a counterexample: an input inside the box (a motor the page can open) for
    which :func:`pulab.report` shows the failure, and the C statement that fails;
``unknown``
    the work budget ran out; ``proven_fraction`` of the box is proven.

Soundness by construction: SI inputs map to the firmware's raw integers by a
monotone rounding (``round(x·scale)``), so a range of an input is exactly a range
of raw integers.  The vendor code itself (the seed's C the report runs) is evaluated over
intervals of those integers by the tracer's interval evaluator
(:func:`~pulab.analyses.prove_intervals.interval_steps`, the exact C semantics on
``[lo, hi]``), so its result encloses every value and flag of every point.  A box whose
enclosure raises nothing is proven (and its quantization error bounded by the floors of
its statements, :func:`~pulab.analyses.prove_intervals.error_bound`); otherwise its corners
and centre are run concretely (a failure there is the counterexample), and else it is split
in two along its relatively widest raw input.  A box of one raw point is evaluated
exactly, so the split ends.  Each integer's search is :func:`pulab.fixedpoint.boxsearch.search`,
the code proof's too (:mod:`pulab.ctrace.prove`); this module gives it what a box evaluates to,
which points are run and how a failure is reproduced (through :func:`pulab.report`).

The current-PI integers ``pm_kp``/``pm_ki`` (seed 2.2-9) are designed in floating
point: the report's design code runs over intervals of the ranged inputs themselves
(:class:`~pulab.fixedpoint.interval.RInterval`, rounded outward so that it encloses the
double the code computes), a branch or comparison that differs inside a box splits it,
and the rounding to the integer is monotone.  The vendor profiles' constants (``profile``
``ti``, ``nxp``, ``st``, ``microchip``) run the same way through each profile's own code (its
``constants``, what the report runs): encoding is monotone, so the ends of an interval bound its
integers.  A shift, divisor or Q the code chooses from the motor is a monotone step function of
one quantity (:func:`pulab.fixedpoint.interval.choose`); where it differs across a box the box is
cut into one piece per choice, evaluated with that choice forced and the quantity clipped to the
values that make it, so each choice is treated exactly.  A proven constant's worst quantization
error is then bounded over the box: its rounding's LSB over the smallest ideal of each piece.

Examples
--------
>>> seed = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
...     "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
...     "drive": {"udc_v": 24, "ts_s": 1e-4}}
>>> r = prove({"input": seed, "ranges": {"motor.rated_current_a": [1, 4],
...                                      "motor.rs_ohm": [0.5, 2]}})
>>> r["verdict"], r["integers"]["vendor.LD"]["range"], r["integers"]["vendor.Rpm"]["range"]
('proven', [692, 2808], [3338, 53414])
>>> r = prove({"input": seed, "ranges": {"motor.rated_current_a": [1, 100]}})
>>> ld = r["integers"]["vendor.LD"]
>>> ld["verdict"], ld["kind"], ld["counterexample"]["motor"]["rated_current_a"] >= 69.475
('violated', 'store', True)
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..fixedpoint.boxsearch import halve, headroom_bits, hull, search, volume
from ..fixedpoint.interval import ANY, Branch, Empty, RInterval, Undecided, forcing
from ..model.gains import pi_integer_ideals
from ..profiles import MODULES, context
from ..profiles.inovance.code import (RAW_FIELDS, RAW_SCALE, VENDOR_READS, VENDOR_RESULTS,
                                      raw_source, raw_value)
from ..report import current_pi_section, input_bases, report, require_pmsm
from ..schema.errors import InputError
from ..schema.fields import FIELD
from ..schema.inputs import SECTIONS, normalize
from ..schema.validate import key_path, real, shown
from .integers import profile_name
from .prove_intervals import error_bound, interval_steps
from .slices import finish

__all__ = ["prove", "prove_steps", "make_problem", "Problem", "integer_names", "integer_steps",
           "PROFILES", "propose_global_q",
           "summary", "VERDICTS", "KINDS",
           "DEFAULT_BUDGET", "MAX_BUDGET"]

VERDICTS = ("proven", "violated", "unknown")
#: The profiles a proof covers: the seed's Inovance code and the four vendor profiles' constants.
PROFILES = ("inovance", "ti", "nxp", "st", "microchip")
#: The choices a profile's code makes from the motor (a shift, a divisor, a Q), proven as
#: integers of their own: name → (its sites in :func:`~pulab.fixedpoint.interval.choose`, the
#: constants that use it — the first one's record carries it —, how to read it from that
#: record).  A constant that uses no choice of a site is evaluated with that site at ``ANY``,
#: so its box is not cut where the choice changes.
CHOICES = {
    "nxp": {"shifts.M1_TO_THETA_SHIFT": (("nxp.M1_TO_THETA_SHIFT",), ("M1_TO_THETA_GAIN",),
                                         lambda c: c["shift"])},
    "st": {"divisors.TF_KPDIV": (("st.TF_KPDIV.d", "st.TF_KPDIV.q"),
                                 ("PID_TORQUE_KP_DEFAULT", "PID_FLUX_KP_DEFAULT"),
                                 lambda c: 1 << c["q"]),
           "divisors.TF_KIDIV": (("st.TF_KIDIV.d", "st.TF_KIDIV.q"),
                                 ("PID_TORQUE_KI_DEFAULT", "PID_FLUX_KI_DEFAULT"),
                                 lambda c: 1 << c["q"])},
    "microchip": {"q.KIP_Q": (("microchip.KIP_Q",), ("KIP",), lambda c: c["q"]),
                  "q.KII_Q": (("microchip.KII_Q",), ("KII",), lambda c: c["q"])},
}
#: What breaks an integer: wrapped mid-way (a PI gain: beyond long, which the report refuses),
#: changed by its Uint16 store, divided by zero, zero (all resolution lost), a raw parameter
#: the Uint16 cannot hold, or a PI design the report refuses (damping with kp ≤ 0).
KINDS = ("wrap", "store", "div0", "zero", "outside", "saturate", "invalid")
#: Interval evaluations (boxes) allowed per integer.
DEFAULT_BUDGET = 4000
MAX_BUDGET = 1_000_000
_UINT16_MAX = 0xFFFF
_PI_NAMES = tuple(f"current_pi.{a}.{k}" for a in ("d", "q") for k in ("pm_kp", "pm_ki"))
#: Boxes evaluated between two yields of :func:`prove_steps`.
_SLICE_BOXES = 200


class Problem:
    """A checked proof request: the base input, the raw-integer box, and how to map back.

    Attributes
    ----------
    input : dict — the base input (points outside the box keep its values)
    ranges : dict — path → (lo, hi), as given
    unit : str — the inductance unit
    box : dict — raw field → (lo, hi) raw integers over the whole box (fixed fields: lo = hi)
    sources : dict — raw field → the box path it comes from (SI or ``raw.NAME``)
    ties : dict — raw field → the raw field it always equals (FullFreq01 → FreqRated01 when
        f_b defaults to a ranging f_n); split and sampled with it, never on its own
    budget : int
    """

    def __init__(self, inp: dict, ranges: dict, unit: str, box: dict, sources: dict,
                 ties: dict, budget: int) -> None:
        self.input, self.ranges, self.unit = inp, ranges, unit
        self.box, self.sources, self.ties, self.budget = box, sources, ties, budget
        self.normalized = normalize(inp)


def _numeric_path(path, field: str) -> str:
    section, _, key = path.partition(".") if isinstance(path, str) else ("", "", "")
    if key not in SECTIONS.get(section, ()) or FIELD[path].kind not in ("number", "integer"):
        raise InputError(field, code="not_numeric_path", got=shown(path))
    return path


def _set(inp: dict, path: str, value) -> dict:
    section, _, key = path.partition(".")
    return {**inp, section: {**(inp.get(section) or {}), key: value}}


def make_problem(req) -> Problem:
    """Check a proof request.

    Parameters
    ----------
    req : dict
        ``input`` (a report input), ``ranges`` ({path: [lo, hi]}, numeric input paths,
        lo ≤ hi; a raw path takes integers), optional ``profile`` (``inovance``, the
        default, or its alias ``vendor``; ``ti``, ``nxp``, ``st``, ``microchip``) and
        ``budget`` (boxes per integer, 1..1000000, default 4000).

    Raises
    ------
    pulab.InputError
        Naming ``prove.ranges.PATH`` (or the input field that a range end makes invalid).
    """
    if not isinstance(req, dict):
        raise InputError("prove", code="not_object", got=shown(req))
    inp = req.get("input")
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    require_pmsm(inp)
    inp = {k: v for k, v in inp.items() if k not in ("sim", "analysis", "profiles")}
    profile = req.get("profile")
    if profile is not None and (not isinstance(profile, str)
                                or profile_name(profile) not in PROFILES):
        raise InputError("prove.profile", code="prove_profile", got=shown(profile),
                         choices=", ".join(PROFILES))
    profile = profile_name(profile)
    options = ((req["input"].get("profiles") or {}).get(profile) or {}) \
        if profile != "inovance" and isinstance(req["input"].get("profiles"), dict) else {}
    budget = req.get("budget", DEFAULT_BUDGET)
    if isinstance(budget, bool) or not isinstance(budget, int) or not 1 <= budget <= MAX_BUDGET:
        raise InputError("prove.budget", code="integer_range", lo=1, hi=MAX_BUDGET,
                         got=shown(budget))
    ranges = req.get("ranges")
    if not isinstance(ranges, dict) or not ranges:
        raise InputError("prove.ranges", code="prove_no_ranges")
    checked = {}
    for path, pair in ranges.items():
        # A path as typed names its range; anything unprintable is quoted (one-line errors).
        field = f"prove.ranges.{path}" if isinstance(path, str) and path.isprintable() \
            and path.strip() == path and 0 < len(path) <= 80 else key_path("prove.ranges", path)
        _numeric_path(path, field)
        if not isinstance(pair, (list, tuple)) or len(pair) != 2:
            raise InputError(field, code="prove_pair", got=shown(pair))
        lo, hi = (real(v, field) for v in pair)
        if FIELD[path].kind == "integer":
            if lo != int(lo) or hi != int(hi):
                raise InputError(field, code="prove_pair", got=shown(lo if lo != int(lo) else hi))
            lo, hi = int(lo), int(hi)
        if not lo <= hi:
            raise InputError(field, code="prove_order", lo=lo, hi=hi)
        checked[path] = (lo, hi)
    inp = _explicit(inp)
    # Both ends of every range are real inputs (each field's own limits hold between them).
    n_lo = normalize(_with(inp, checked, 0))
    normalize(_with(inp, checked, 1))
    base = normalize(inp)
    unit = n_lo["conventions"]["inductance_unit"]
    given = n_lo["raw"]
    box, sources, ties = {}, {}, {}
    for name in RAW_FIELDS:
        path = RAW_SCALE[name][0]
        section, _, key = path.partition(".")
        if f"raw.{name}" in checked:
            sources[name] = f"raw.{name}"
            box[name] = checked[f"raw.{name}"]
        elif name in given:
            box[name] = (given[name], given[name])
        elif path in checked:
            sources[name] = path
            lo_si, hi_si = checked[path]
            box[name] = (raw_value(name, lo_si, unit), raw_value(name, hi_si, unit))
        else:
            v = raw_value(name, base[section][key], unit)
            box[name] = (v, v)
    if (sources.get("FreqRated01") == "motor.rated_freq_hz" and "FullFreq01" not in sources
            and "FullFreq01" not in given
            and (inp.get("drive") or {}).get("base_freq_hz") is None):
        # f_b defaults to f_n: the same SI value at the same scale, so the same raw integer.
        ties["FullFreq01"] = "FreqRated01"
        box["FullFreq01"] = box["FreqRated01"]
    problem = Problem(inp, checked, unit, box, sources, ties, budget)
    problem.profile, problem.options, problem.constants = profile, {}, {}
    problem.board = None
    if profile == "inovance":
        problem.names = integer_names()
    else:
        # The report checks the options and names the constants.
        full = report({**inp, "profiles": {profile: options}})
        r = full["profiles"][profile]
        problem.options = {k: r["inputs"][k] for k in options}
        # The board cannot be ranged (its fields are nested), and the vendors read only its
        # own scales from it (full ranges, the divider), which the motor does not change.
        problem.board = full.get("board")
        board = set(r.get("board", ()))
        problem.constants = {k: c for k, c in r["constants"].items() if k not in board}
        problem.names = tuple(f"profiles.{profile}.constants.{k}" for k in problem.constants) + \
            tuple(f"profiles.{profile}.{k}" for k in CHOICES.get(profile, {}))
    return problem


def _explicit(inp: dict) -> dict:
    """The input with a datasheet's conversions made once, at the base input: ranges then
    apply to the motor and drive values it gave."""
    if "datasheet" not in inp:
        return inp
    n = normalize(inp)
    drive = {k: v for k, v in n["drive"].items()
             if v is not None and (k != "base_freq_hz" or (inp.get("drive") or {}).get(k))}
    return {**{k: v for k, v in inp.items() if k != "datasheet"}, "motor": n["motor"],
            "drive": drive}


def _with(inp: dict, ranges: dict, end: int) -> dict:
    for path, pair in ranges.items():
        inp = _set(inp, path, pair[end])
    return inp


def _si_for(problem: Problem, name: str, k: int):
    """An input value in the box whose raw integer is ``k`` (None if none is found)."""
    path = problem.sources[name]
    lo, hi = problem.ranges[path]
    if path.startswith("raw."):
        return k
    unit = problem.unit
    if raw_value(name, lo, unit) == k:
        return lo
    if raw_value(name, hi, unit) == k:
        return hi
    x = k / raw_source(name, unit)[1]
    # k/scale rounds back to k except at a double's edge: step a few doubles either way.
    for step in (math.inf, -math.inf):
        y = x
        for _ in range(64):
            if lo <= y <= hi and raw_value(name, y, unit) == k:
                return y
            y = math.nextafter(y, step)
    return None


def counterexample(problem: Problem, point: dict) -> dict | None:
    """The input JSON for a raw point of the box (None if no input in the box gives it)."""
    inp = problem.input
    for name, path in problem.sources.items():
        v = _si_for(problem, name, point[name])
        if v is None:
            return None
        inp = _set(inp, path, v)
    return inp


def _reproduces(inp: dict, name: str) -> bool:
    """Whether the report of ``inp`` shows integer ``name`` failing (the counterexample check:
    the whole report, what a user sees when opening the input)."""
    try:
        r = report(inp)
    except InputError:
        return False
    section, _, key = name.partition(".")
    if section == "raw":
        return key not in r["vendor"]["raw"]
    v = r["vendor"].get(key)
    return v is None or bool({"wrap", "store"} & set(v["flags"])) or v["value"] == 0


def _point(name: str, pt: dict, unit: str) -> tuple:
    """(kind or None, value, error_pct, statement) of vendor result ``name`` at a raw point."""
    for k in VENDOR_READS[name]:
        if pt[k] > _UINT16_MAX:
            return "outside", None, None, _outside_statement(k, pt[k])
    try:
        r = VENDOR_RESULTS[name](pt, unit)
    except InputError as e:
        return "div0", None, None, e.message
    for s in r["trace"]:
        bad = {"wrap", "store"} & set(s["flags"])
        if bad:
            return sorted(bad)[-1], r["value"], r["error_pct"], s["code"]
    if r["value"] == 0:
        return "zero", 0, r["error_pct"], r["trace"][-1]["code"]
    return None, r["value"], r["error_pct"], None


def _outside_statement(name: str, value: int) -> str:
    return f"gMotorInfo.{name} (Uint16) = {value}: does not fit"


def _enclose(name: str, box: dict, unit: str) -> tuple:
    """(kinds, (lo, hi), word) of vendor result ``name`` over a raw box, by interval evaluation."""
    kinds = {"outside"} if any(box[k][1] > _UINT16_MAX for k in VENDOR_READS[name]) else set()
    if any(box[k][0] > _UINT16_MAX for k in VENDOR_READS[name]):
        return kinds, None, None
    run = interval_steps(name, box)
    if run is None:
        return kinds | {"div0"}, None, None
    own, before = run
    for s in own:
        kinds |= {"wrap", "store", "div0"} & set(s["flags"])
    if any("div0" in s["flags"] for s in before):  # a value that may not exist
        kinds.add("div0")
    lo, hi = own[-1]["value"]
    if lo <= 0 <= hi:
        kinds.add("zero")
    return kinds, (lo, hi), own[-1]["type"]


def _tie(x: dict, ties: dict) -> dict:
    """A point or box with every tied raw field set to its leader's."""
    return {**x, **{f: x[lead] for f, lead in ties.items()}} if ties else x


def _corners(box: dict, dims, ties: dict) -> list:
    pts = [dict(box_lo(box))]
    for k in dims:
        lo, hi = box[k]
        if hi != lo:
            pts += [{**p, k: hi} for p in pts]
    mid = {k: (lo + hi) // 2 for k, (lo, hi) in box.items()}
    return [_tie(p, ties) for p in pts + [mid]]


def box_lo(box: dict) -> dict:
    return {k: lo for k, (lo, _) in box.items()}


def _split(box: dict, dims, ties: dict) -> tuple:
    # Relatively widest first: the code multiplies and divides, so ratios matter.
    k = max((k for k in dims if box[k][1] > box[k][0]),
            key=lambda k: (box[k][1] - box[k][0]) / (box[k][0] + 1))
    return tuple(_tie(half, ties) for half in halve(box, k))


_WORDS = {"Uint16": (0, _UINT16_MAX), "long": (-(1 << 31), (1 << 31) - 1),
          "int16": (-(1 << 15), (1 << 15) - 1),
          "Ulong": (0, (1 << 32) - 1)}


def _prove_vendor(problem: Problem, name: str):
    """Decide one vendor result over the box (a slice generator returning its entry)."""
    unit = problem.unit
    ties = problem.ties
    # A tied field is split and sampled through its leader.
    dims = list(dict.fromkeys(ties.get(k, k) for k in VENDOR_READS[name]
                              if problem.box[k][0] != problem.box[k][1]))
    total = volume(problem.box, dims)
    proven_volume = 0
    rng = rng_proven = None  # hull of every box's enclosure, of the proven boxes' only
    word = None
    worst = None  # (|error_pct|, error_pct, raw point) over the points run
    bound, bounded = 0.0, True  # the worst |error| over the proven boxes, all bounded?
    violated = None  # (kind, statement, raw point, input) reproduced by the report

    def visit(neg_vol, box, _):
        nonlocal proven_volume, rng, rng_proven, word, worst, bound, bounded, violated
        kinds, enc, w = _enclose(name, box, unit)
        word = word or w
        rng = hull(rng, enc)
        if not kinds:
            rng_proven = hull(rng_proven, enc)
            proven_volume += -neg_vol
            if bounded:
                b = error_bound(name, box, unit)
                bounded = b is not None
                bound = max(bound, b or 0.0)
            for pt in (box_lo(box), {k: hi for k, (_, hi) in box.items()}):  # tied: equal ends
                worst = _worse(worst, _point(name, pt, unit), pt)
            return 1, ()
        for pt in _corners(box, dims, ties):
            got = _point(name, pt, unit)
            if got[0] is not None:
                inp = counterexample(problem, pt)
                if inp is not None and _reproduces(inp, name):
                    violated = got[0], got[3], {k: pt[k] for k in VENDOR_READS[name]}, inp
                    return 1, None
            else:
                worst = _worse(worst, got, pt)
        if volume(box, dims) == 1:
            # A single point evaluates exactly: its failure did not reproduce as an input.
            return 1, None
        return 1, [(-volume(half, dims), half, None) for half in _split(box, dims, ties)]

    evaluated, left = yield from search(problem.box, -total, visit, problem.budget,
                                        every=_SLICE_BOXES)
    if violated is not None:
        kind, statement, raw, inp = violated
        return _entry("violated", rng, word, proven_volume / total, worst, boxes=evaluated,
                      kind=kind, statement=statement, raw=raw, counterexample=inp)
    if not left and proven_volume == total:
        entry = _entry("proven", rng_proven, word, 1.0, worst, boxes=evaluated)
        if bounded:
            entry.update(worst_error_pct=bound, worst_error_raw=None, error_bound=True)
        return entry
    return _entry("unknown", rng, word, proven_volume / total, worst, boxes=evaluated)


def _log_width(r: tuple) -> float:
    """How wide a range is for splitting: its ratio for positive ranges, else its width."""
    return math.log(r[1] / r[0]) if r[0] > 0 else r[1] - r[0]


def _worse(worst, got, pt):
    err = got[2]
    if got[0] is not None or err is None or (worst is not None and abs(err) <= worst[0]):
        return worst
    return abs(err), err, dict(pt)


def _entry(verdict: str, rng, word, fraction: float, worst, **extra) -> dict:
    out = {"verdict": verdict, "range": list(rng) if rng else None, "type": word,
           "word": list(_WORDS[word]) if word else None, "proven_fraction": fraction,
           "worst_error_pct": None if worst is None else worst[1],
           "worst_error_raw": None if worst is None else worst[2],
           "headroom_bits": headroom_bits(rng, _WORDS[word])
           if verdict == "proven" and rng and word else None}
    out.update(extra)
    return out


def _prove_raw(problem: Problem, name: str) -> dict:
    """A raw parameter: the range is exact (a monotone rounding), so is the verdict."""
    lo, hi = problem.box[name]
    scale = raw_source(name, problem.unit)[1]
    path = problem.sources.get(problem.ties.get(name, name))
    # |round(x·s) − x·s| ≤ 1/2, so the relative error is worst at the low end.
    worst = None
    if path is not None and not path.startswith("raw."):
        x_lo = problem.ranges[path][0] * scale
        worst = 50.0 / x_lo if x_lo > 0 else None
    if hi <= _UINT16_MAX:
        out = _entry("proven", (lo, hi), "Uint16", 1.0, None)
    else:
        k = max(lo, _UINT16_MAX + 1)
        lead = problem.ties.get(name, name)
        inp = counterexample(problem, {**box_lo(problem.box), lead: k, name: k})
        fraction = max(0, _UINT16_MAX - lo + 1) / (hi - lo + 1)
        out = _entry("violated" if inp is not None else "unknown", (lo, hi), "Uint16",
                     fraction, None, kind="outside", raw={name: k},
                     statement=_outside_statement(name, k))
        if inp is not None:
            out["counterexample"] = inp
    out["worst_error_pct"] = worst
    out["error_bound"] = worst is not None
    return out


def _pi_at(n: dict, name: str):
    """One current-PI integer of a normalized input whose values may be intervals: the
    report's own design code (``current_pi_section``), run once more."""
    _, axis, key = name.split(".")
    return current_pi_section(n, input_bases(n))[axis][key]


def _pi_input(problem: Problem, box: dict) -> dict:
    """The normalized base input with each ranged input an interval (a point where the
    box is flat: a point evaluates exactly)."""
    n = {s: dict(v) if isinstance(v, dict) else v for s, v in problem.normalized.items()}
    for path, (lo, hi) in box.items():
        sec, key = path.split(".")
        n[sec][key] = lo if lo == hi else RInterval(lo, hi)
    if problem.ties:  # f_b follows a ranging f_n
        n["drive"]["base_freq_hz"] = n["motor"]["rated_freq_hz"]
    return n


def _pi_enclose(problem: Problem, name: str, box: dict, forced: dict = None) -> tuple:
    """(kinds, (lo, hi), bound) of a current-PI integer over an SI box; ``undecided`` when a
    branch or comparison of the design code differs inside the box.  ``bound``: the box's
    worst |error_pct| — the integer rounds its ideal to nearest, so |ideal| ≥ min|value| − ½
    and the error is at most ½ over that (None when the range holds 0)."""
    try:
        v = _pi_at(_pi_input(problem, box), name)
    except Undecided:
        return {"undecided"}, None, None
    except InputError as e:  # raised only when every point of the box fails the same way
        return {"wrap" if e.code == "long_overflow" else "invalid"}, None, None
    lo, hi = v.value if isinstance(v, RInterval) else (v, v)
    if lo <= 0 <= hi:
        return {"zero"}, (lo, hi), None
    low = min(abs(lo), abs(hi)) - 0.5
    return set(), (lo, hi), math.nextafter(50.0 / low, math.inf) + 1e-10


def _pi_point(problem: Problem, name: str, pt: dict) -> tuple:
    """(kind or None, value, error_pct, input) of a current-PI integer at an SI point."""
    inp = _with(problem.input, {p: (v, v) for p, v in pt.items()}, 0)
    try:
        n = normalize(inp)
        _, axis, key = name.split(".")
        g = current_pi_section(n, input_bases(n))[axis]
    except InputError as e:
        return ("wrap" if e.code == "long_overflow" else "invalid"), None, None, inp
    ideal = dict(zip(("pm_kp", "pm_ki"), pi_integer_ideals(g["kp_pu"], g["ki_pu"],
                                                           n["drive"]["ts_s"])))[key]
    err = 0.0 if ideal == 0 else 100.0 * (g[key] - ideal) / ideal
    return ("zero" if g[key] == 0 else None), g[key], err, inp


def _pi_reproduces(inp: dict, name: str, kind: str) -> bool:
    _, axis, key = name.split(".")
    try:
        r = report(inp)
    except InputError as e:
        return kind in ("wrap", "invalid") and e.field.startswith("current_loop")
    return kind == "zero" and r["current_pi"][axis][key] == 0


#: Smallest share of the whole box a float box is split down to (about 2^-40 per input).
_MIN_SHARE = 1e-12


def _profile_constants(n: dict, problem: Problem) -> dict:
    """A vendor profile's constants for a normalized input whose values may be intervals:
    the profile's own code (its ``constants``, what its ``profile`` reports), with the
    options the input gives and the others at their defaults for this motor."""
    ctx = context(n, {}, {}, current_pi_section(n, input_bases(n)), (), problem.board)
    mod = MODULES[problem.profile]
    opt = {k: problem.options[k] if k in problem.options else default(ctx)
           for k, default, *_ in mod.OPTIONS}
    return mod.constants(ctx, opt)


def _constant_of(problem: Problem, name: str) -> tuple:
    """(the constant's key, how to read the integer from its record) for a profile name."""
    _, profile, group, key = name.split(".")
    if group == "constants":
        return key, lambda c: c["value"]
    _, users, read = CHOICES[profile][f"{group}.{key}"]
    return users[0], read


def _unused_choices(problem: Problem, key: str) -> dict:
    """The sites constant ``key`` does not use, forced to ``ANY``."""
    return {site: ANY for sites, users, _ in CHOICES.get(problem.profile, {}).values()
            if key not in users for site in sites}


def _profile_enclose(problem: Problem, name: str, box: dict, forced: dict = None) -> tuple:
    """(kinds, (lo, hi), bound) of a profile integer over an SI box under the ``forced``
    choices (see :func:`_pi_enclose`): ``bound`` is the box's worst |error| in percent (None
    when not bounded), kinds ``branch`` with the :class:`Branch` when a choice differs
    across the box, ``empty`` when no point of the box makes the forced choices."""
    key, read = _constant_of(problem, name)
    try:
        with forcing({**_unused_choices(problem, key), **(forced or {})}):
            c = _profile_constants(_pi_input(problem, box), problem)[key]
    except Branch as b:
        return {"branch"}, None, b
    except Empty:
        return {"empty"}, None, None
    except Undecided:
        return {"undecided"}, None, None
    except InputError as e:
        return {"wrap" if e.code == "long_overflow" else "invalid"}, None, None
    v = read(c)
    lo, hi = v.value if isinstance(v, RInterval) else (v, v)
    if key != name.split(".")[-1]:  # a choice: its failures are its constant's; no rounding
        return set(), (lo, hi), None
    kinds = {_PROFILE_FLAGS[f] for f in c["flags"] if f in _PROFILE_FLAGS}
    return kinds | ({"zero"} if lo <= 0 <= hi else set()), (lo, hi), _error_bound(c)


def _error_bound(c: dict):
    """The worst |error_pct| of a constant over a box: |stored − ideal| ≤ error_lsb LSB for
    its rounding, and |ideal| ≥ the low end of its enclosure (None when it may be 0 or the
    integer comes from other rounded integers)."""
    ideal = c["ideal"]
    if not isinstance(ideal, RInterval):
        return abs(c["error_pct"])
    lsb = c.get("error_lsb")
    low = min(abs(ideal.lo), abs(ideal.hi))
    if lsb is None or ideal.lo <= 0 <= ideal.hi or low == 0:
        return None
    return math.nextafter(100.0 * lsb / low, math.inf)


#: A profile constant's flags that break it: the vendor's macro clamped, or C's cast of an
#: out-of-range float (undefined behaviour).
_PROFILE_FLAGS = {"saturate": "saturate", "out_of_range": "outside"}


def _profile_kind(c: dict):
    bad = [_PROFILE_FLAGS[f] for f in c["flags"] if f in _PROFILE_FLAGS]
    return bad[0] if bad else "zero" if c["value"] == 0 and c["ideal"] != 0 else None


def _profile_point(problem: Problem, name: str, pt: dict) -> tuple:
    """(kind or None, value, error_pct, input) of a profile integer at an SI point (the
    input carries this profile's options, so the report gives the same constant)."""
    inp = _with(problem.input, {p: (v, v) for p, v in pt.items()}, 0)
    inp = {**inp, "profiles": {problem.profile: problem.options}}
    key, read = _constant_of(problem, name)
    try:
        c = _profile_constants(normalize(inp), problem)[key]
    except InputError as e:
        return ("wrap" if e.code == "long_overflow" else "invalid"), None, None, inp
    if key != name.split(".")[-1]:
        return None, read(c), None, inp
    return _profile_kind(c), c["value"], c["error_pct"], inp


def _profile_reproduces(inp: dict, name: str, kind: str) -> bool:
    _, profile, group, key = name.split(".")
    try:
        c = report(inp)["profiles"][profile]["constants"][key]
    except InputError as e:
        return kind in ("wrap", "invalid") and e.field.startswith("current_loop")
    return group == "constants" and _profile_kind(c) == kind


class _Float(NamedTuple):
    """How to decide one integer computed in floating point (a PI gain, a profile constant)."""

    enclose: object
    point: object
    reproduces: object
    word: str
    statement: str


def _float_spec(problem: Problem, name: str) -> _Float:
    if name.startswith("current_pi."):
        return _Float(_pi_enclose, _pi_point, _pi_reproduces, "long",
                      f"{name.split('.')[-1]} = round(…) (seed 2.2-9)")
    key, _ = _constant_of(problem, name)
    c = problem.constants[key]
    if key != name.split(".")[-1]:
        return _Float(_profile_enclose, _profile_point, _profile_reproduces,
                      "Uint16" if ".divisors." in name else "int16",
                      f"{name.split('.')[-1]}: chosen from {c['name']} = {c['expression']}")
    word = {16: "Uint16" if c["format"] == "uint16_t" else "int16",
            32: "long"}[c["word_bits"]] if c["format"] else "long"
    return _Float(_profile_enclose, _profile_point, _profile_reproduces, word,
                  f"{c['name']} = {c['format']}({c['expression']})")


def _prove_float(problem: Problem, name: str):
    """Decide one integer computed in floating point over the SI box (a slice generator
    returning its entry).

    The box is split in the ranged inputs themselves; a box's corners (all of them up to 6
    inputs) and centre are run concretely.  Where a choice of the code (a shift, a divisor)
    differs across a box, the box is cut into one *piece* per choice, each evaluated with its
    choice forced (:func:`pulab.fixedpoint.interval.choose`): together they hold every point
    exactly once.  A piece's share of the box is its box's share over its number of choices
    (``proven_fraction`` counts pieces so, an estimate where choices split a box).
    """
    spec = _float_spec(problem, name)
    full = {p: r for p, r in problem.ranges.items()
            if not p.startswith("raw.") and r[0] != r[1]}
    dims = list(full)
    proven_share = 0.0
    rng = rng_proven = worst = None
    bound, bounded = 0.0, True  # the worst |error| over the proven pieces, all bounded?
    corners_run = False
    violated = None  # (kind, value, input) reproduced by the report

    def visit(neg_share, box, data):
        nonlocal dims, proven_share, rng, rng_proven, worst, bound, bounded, corners_run
        nonlocal violated
        forced, box_share = data
        kinds, enc, extra = spec.enclose(problem, name, box, forced)
        if kinds == {"empty"}:
            proven_share += -neg_share
            return 1, ()
        if kinds == {"branch"}:
            return 1, [(neg_share / len(extra.choices), box, ({**forced, extra.site: c},
                                                               box_share))
                       for c in extra.choices]
        rng = hull(rng, enc)
        if enc is not None and box_share == 1.0 and len(dims) > 1:
            # Split only inputs the integer depends on: fixing one it does not leaves the whole
            # box's enclosure as it is.
            moving = [q for q in dims if _fixed(spec, problem, name, box, forced, q) != enc]
            dims = moving or dims
        if not kinds:
            rng_proven = hull(rng_proven, enc)
            proven_share += -neg_share
            bounded = bounded and extra is not None
            bound = max(bound, extra) if extra is not None else bound
            for end in (0, 1):
                pt = {p: r[end] for p, r in box.items()}
                worst = _worse(worst, spec.point(problem, name, pt)[:3], pt)
            return 1, ()
        # Every corner of the whole box (a monotone design breaks at one); the centre of each
        # smaller box, where a break inside the box is closed in on.
        corners = [{}]
        for p in dims if len(dims) <= 6 and not corners_run and box_share == 1.0 else ():
            corners = [{**c, p: e} for c in corners for e in box[p]]
        corners_run = corners_run or box_share == 1.0
        centre = {p: (lo + hi) / 2 for p, (lo, hi) in box.items()}
        for pt in [{**{p: lo for p, (lo, _) in box.items()}, **c} for c in corners] + [centre]:
            kind, value, err, inp = spec.point(problem, name, pt)
            if kind is not None and spec.reproduces(inp, name, kind):
                violated = kind, value, inp
                return 1, None
            worst = _worse(worst, (kind, value, err), pt)
        if box_share < _MIN_SHARE or not dims:
            return 1, ()
        p = _split_dim(spec, problem, name, box, forced, dims, full,
                       round(-math.log2(box_share)))
        lo, hi = box[p]
        # Ratios of inputs (I_max/I_FS …) narrow by the ratio hi/lo: split at the geometric
        # mean while it is large.
        mid = math.sqrt(lo * hi) if lo > 0 and hi > 4 * lo else lo + (hi - lo) / 2
        parts = [(half, (half[1] - half[0]) / (hi - lo)) for half in ((lo, mid), (mid, hi))]
        return 1, [(neg_share * part, {**box, p: half}, (forced, box_share * part))
                   for half, part in parts]

    evaluated, left = yield from search(dict(full), -1.0, visit, problem.budget, ({}, 1.0),
                                        every=_SLICE_BOXES)
    if violated is not None:
        kind, value, inp = violated
        return _entry("violated", rng, spec.word, proven_share, worst, boxes=evaluated,
                      kind=kind, statement=spec.statement, raw={"value": value},
                      counterexample=inp)
    if not left and proven_share >= 1.0 - 1e-9:
        entry = _entry("proven", rng_proven, spec.word, 1.0, worst, boxes=evaluated)
        if ".constants." not in name and not name.startswith("current_pi."):
            entry["headroom_bits"] = None  # a shift or divisor: no fractional bits to add
        if bounded and rng_proven is not None:
            entry["worst_error_pct"], entry["worst_error_raw"] = bound, None
            entry["error_bound"] = True
        return entry
    return _entry("unknown", rng, spec.word, min(proven_share, 1.0), worst, boxes=evaluated)


def _fixed(spec: _Float, problem: Problem, name: str, box: dict, forced: dict, q: str):
    """The enclosure with input ``q`` fixed at its midpoint (None when it does not evaluate)."""
    mid = (box[q][0] + box[q][1]) / 2
    kinds, e, _ = spec.enclose(problem, name, {**box, q: (mid, mid)}, forced)
    return None if kinds & {"branch", "undecided", "empty"} else e


def _split_dim(spec: _Float, problem: Problem, name: str, box: dict, forced: dict, dims,
               full: dict, depth: int) -> str:
    """The input to split a box along, alternating by depth: the relatively widest, and the
    one whose fixing (at its midpoint) narrows the enclosure most — so that an input that
    cancels out of a formula (I in I·R_shunt(I), a dependency interval arithmetic does not
    see) is split too, while the widest-first order still closes in on a curved boundary."""
    widest = max(dims, key=lambda q: _log_width(box[q]) / _log_width(full[q]))
    live = [q for q in dims if box[q][0] < box[q][1]]
    if depth % 2 == 0 or len(live) < 2:
        return widest

    def width(q):
        e = _fixed(spec, problem, name, box, forced, q)
        return math.inf if e is None else e[1] - e[0]

    return min(live, key=width)


def integer_names() -> tuple:
    """The integers a proof decides, in report order (raw parameters, vendor results, then
    the current-PI gains).

    >>> integer_names()[-1]
    'current_pi.q.pm_ki'
    """
    return (tuple(f"raw.{k}" for k in RAW_FIELDS) + tuple(f"vendor.{k}" for k in VENDOR_RESULTS)
            + _PI_NAMES)


def integer_steps(problem: Problem, name: str):
    """Decide one integer (a slice generator returning its entry).

    Raises
    ------
    pulab.InputError
        Naming ``prove.name`` for a name not in :func:`integer_names`.
    """
    if name not in problem.names:
        raise InputError("prove.name", code="not_choice", choices=", ".join(problem.names),
                         got=shown(name))
    section, _, key = name.partition(".")
    if section == "raw":
        return _prove_raw(problem, key)
    if section in ("current_pi", "profiles"):
        entry = yield from _prove_float(problem, name)
    else:
        entry = yield from _prove_vendor(problem, key)
    entry.setdefault("error_bound", False)
    return entry


def summary(problem: Problem, integers: dict) -> dict:
    """The proof result from each integer's entry (see :func:`prove`)."""
    verdicts = {e["verdict"] for e in integers.values()}
    verdict = ("violated" if "violated" in verdicts else
               "unknown" if "unknown" in verdicts else "proven")
    first = next((n for n, e in integers.items() if e["verdict"] == "violated"), None)
    out = {"verdict": verdict, "profile": problem.profile,
           "ranges": {p: list(v) for p, v in problem.ranges.items()},
           "raw_box": {k: list(v) for k, v in problem.box.items()},
           "integers": integers, "not_analysed": []}
    if first is not None:
        out["counterexample"] = integers[first]["counterexample"]
        out["first_violated"] = first
    return out


def prove_steps(req):
    """:func:`prove` in slices: yields None between slices of boxes; closing it cancels."""
    problem = make_problem(req)
    integers = {}
    for name in problem.names:
        integers[name] = yield from integer_steps(problem, name)
    return summary(problem, integers)


def propose_global_q(req) -> dict:
    """TI's GLOBAL_Q with the finest resolution for which every IQ constant is proven over the
    box: each candidate from 30 down is a whole proof (``profiles.ti.global_q`` set).

    Returns
    -------
    dict
        ``global_q`` (None when no Q from 30 to 1 is proven) and ``tried``: {q: verdict}.
    """
    inp = req.get("input") if isinstance(req, dict) else None
    tried = {}
    for q in range(30, 0, -1):
        profiles = {**((inp or {}).get("profiles") or {})}
        profiles["ti"] = {**(profiles.get("ti") or {}), "global_q": q}
        r = prove({**req, "profile": "ti", "input": {**(inp or {}), "profiles": profiles}})
        tried[q] = r["verdict"]
        if r["verdict"] == "proven":
            return {"global_q": q, "tried": tried}
    return {"global_q": None, "tried": tried}


def prove(req) -> dict:
    """Decide every firmware integer over a box of inputs.

    Parameters
    ----------
    req : dict
        See :func:`make_problem`.

    Returns
    -------
    dict
        ``verdict`` (proven | violated | unknown: the worst over the integers),
        ``integers`` {name: {verdict, range [lo, hi] (a sound enclosure of every value over
        the box where the code completes), type and word [min, max] of its C type,
        proven_fraction, worst_error_pct and error_bound (raw parameters and proven
        integers: a bound over the box — for a vendor result only where no floor of its code
        may be 0; else the worst at the points run, error_bound false), and when violated:
        kind (wrap, store, div0, zero, outside, saturate, invalid), statement, raw (the raw point) and counterexample (an input JSON inside
        the box)}}, ``counterexample`` (the first violated integer's),
        ``raw_box`` and ``not_analysed``.
    """
    return finish(prove_steps(req))
