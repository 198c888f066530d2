"""Propose each firmware constant's format, in its vendor's own form, for a whole product family.

A family proof (:mod:`pulab.analyses.prove`) decides whether the formats a profile uses now
hold over a box of inputs.  This module asks the reverse: which format gives the finest
resolution such that, for every input of the box, the constant neither overflows its word nor
rounds to zero — and what is then its worst-case quantization error.  Each vendor has its own
form:

``nxp``
    a FRAC16 mantissa and a shift (RTCESL's ``{f16Gain, i16Shift}``): x = m·2^s, |m| < 1, the
    smallest s with max|x| < 2^s; the mantissa truncates (FRAC16()), error ≤ 1 LSB.
``st``
    an int16 gain over a power-of-two divisor (``TF_KPDIV``/``TF_KIDIV``, shared by the two
    axes): the largest D ≤ 16384 with round(max|x|·D) ≤ 32767; then a proof re-run with those
    divisors confirms it (``confirmed``).
``microchip``
    the Q of each int16 constant (MCAF's ``_Q``, Q15 at most; the PI shifts by 15 − Q): the
    largest Q ≤ 15 with round(max|x|·2^Q) ≤ 32767.
``ti``
    one ``GLOBAL_Q`` for every IQ constant: each candidate from 30 down is a whole proof
    (:func:`pulab.analyses.prove.propose_global_q`).
``inovance``
    the seed's code fixes its formats; what applies is each proven integer's headroom (how
    many more fractional bits its word holds over the box) and its worst-case error.

The real value x of every constant is enclosed over the box by the profile's own code run
over intervals (the proof's evaluation, choices such as NXP's shift split exactly), so a
proposal derived from the enclosure holds for every input of the box; it is the finest one
the enclosure allows (the enclosure may be wider than the true range, never narrower).

Examples
--------
>>> seed = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
...     "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
...     "drive": {"udc_v": 24, "ts_s": 1e-4}}
>>> p = propose({"input": seed, "ranges": {"motor.rated_current_a": [1, 40]},
...              "profile": "microchip"})
>>> rs = p["constants"]["MCAF_MOTOR_RS"]
>>> rs["q"], rs["current_q"], rs["range"][1] <= 32767
(12, 15, True)
"""

from __future__ import annotations

import heapq
import math

from ..fixedpoint.boxsearch import search
from ..fixedpoint.interval import Branch, Empty, RInterval, Undecided, forcing
from ..profiles.common import pow2_exponent
from ..schema.errors import InputError
from .prove import (_pi_input, _profile_constants, integer_steps, make_problem, prove,
                    propose_global_q)
from .slices import finish

__all__ = ["propose", "FORMS"]

#: Each profile's form of a proposal.
FORMS = {"inovance": "headroom", "ti": "GLOBAL_Q", "nxp": "FRAC16 · 2^shift",
         "st": "int16 / 2^n", "microchip": "Q(n) in int16"}
_INT16_MAX = 32767


def _real(c: dict):
    """The real value a constant stores (its ideal over 2^q, times 2^shift), as (lo, hi)."""
    x = c["ideal"]
    lo, hi = x.value if isinstance(x, RInterval) else (x, x)
    k = 2.0 ** (c["shift"] - c["q"])
    return lo * k, hi * k


def _evaluate(problem, box: dict, forced: dict):
    """The constants over a box under forced choices: {name: (lo, hi)}; None when no point of
    the box makes the choices or the report refuses the whole box; raises Branch, Undecided.
    Kept per problem: the constants' refinements share their first boxes and probes."""
    memo = problem.__dict__.setdefault("_real_memo", {})
    key = (tuple(sorted(box.items())), tuple(sorted(forced.items())))
    if key not in memo:
        try:
            with forcing(forced):
                cs = _profile_constants(_pi_input(problem, box), problem)
            memo[key] = {k: _real(c) for k, c in cs.items()}
        except (Empty, InputError):  # InputError: every point of the box is refused alike
            memo[key] = None
        except Undecided as e:
            memo[key] = e
    if isinstance(memo[key], Undecided):
        raise memo[key]
    return memo[key]


def _halves(box: dict, full: dict, p: str | None = None) -> list:
    """The box split in two along ``p`` (default: the relatively widest input)."""
    p = p or max(full, key=lambda q: _log_ratio(box[q]) / _log_ratio(full[q]))
    lo, hi = box[p]
    mid = math.sqrt(lo * hi) if lo > 0 and hi > 4 * lo else lo + (hi - lo) / 2
    return [{**box, p: (lo, mid)}, {**box, p: (mid, hi)}]


def _log_ratio(r: tuple) -> float:
    return math.log(r[1] / r[0]) if r[0] > 0 else r[1] - r[0]


def _leaves(problem, full: dict):
    """A partition of the box into pieces that evaluate: [(box, forced, {name: (lo, hi)})];
    None when the budget ran out first."""
    leaves, undecided = [], False

    def visit(neg, box, forced):
        nonlocal undecided
        try:
            cs = _evaluate(problem, box, forced)
        except Branch as b:
            return 1, [(neg / len(b.choices), box, {**forced, b.site: c}) for c in b.choices]
        except Undecided:  # a design comparison differs inside the box: split it
            if not full or -neg < 1e-12:
                undecided = True
                return 1, None
            return 1, [(neg / 2, half, forced) for half in _halves(box, full)]
        if cs is not None:
            leaves.append((box, forced, cs))
        return 1, ()

    _, left = finish(search(dict(full), -1.0, visit, problem.budget, {}))
    return None if left or undecided else leaves


#: Boxes evaluated per constant and end while closing an enclosure's end in on its values.
_REFINE = 12


def _refine(problem, key: str, leaves: list, full: dict, end: int) -> tuple:
    """(bound, witness) of one end of a constant's values (end 1: the largest): a sound
    bound, refined by splitting the boxes that hold it, and the most extreme value seen at a
    box's centre (a real motor of the box)."""
    sign = 1 if end else -1
    heap = [(-sign * cs[key][end], i, box, forced, cs[key]) for i, (box, forced, cs) in
            enumerate(leaves)]
    heapq.heapify(heap)
    order, witness = len(heap), None
    for _ in range(_REFINE):
        neg, _, box, forced, enc = heap[0]
        if witness is not None and abs(-sign * neg - witness) <= 1e-4 * abs(witness):
            break
        heapq.heappop(heap)
        centre = {p: ((lo + hi) / 2,) * 2 for p, (lo, hi) in box.items()}
        try:
            pt = _evaluate(problem, centre, forced)
        except Undecided:
            pt = None
        if pt is not None and (witness is None or sign * pt[key][end] > sign * witness):
            witness = pt[key][end]
        for half in _halves(box, full, _narrowing(problem, key, box, forced, full, end))\
                if full else []:
            try:
                cs = _evaluate(problem, half, forced)
            except Undecided:  # the half's values lie in its parent's enclosure
                cs = {key: enc}
            if cs is not None:
                heapq.heappush(heap, (-sign * cs[key][end], order, half, forced, cs[key]))
                order += 1
        if not full:
            heapq.heappush(heap, (neg, order, box, forced, enc))
            break
    return -sign * heap[0][0], witness


def _narrowing(problem, key: str, box: dict, forced: dict, full: dict, end: int):
    """The input whose fixing (at its midpoint) moves this end of the enclosure in most: the
    one a dependency (L_d twice in L_d/(L_d + T_s·R_s)) over-estimates it by."""
    sign = 1 if end else -1
    best, best_end = None, math.inf
    for q in full:
        if box[q][0] == box[q][1]:
            continue
        mid = (box[q][0] + box[q][1]) / 2
        try:
            cs = _evaluate(problem, {**box, q: (mid, mid)}, forced)
        except Undecided:
            continue
        if cs is not None and sign * cs[key][end] < best_end:
            best, best_end = q, sign * cs[key][end]
    return best


def real_ranges(problem) -> dict:
    """{constant: {"range": (lo, hi), "witnessed": (lo, hi) or None} or None} — every real
    value each constant of the profile takes over the box lies in ``range`` (None when the work
    budget ran out before the whole box was enclosed); ``witnessed`` are values real motors of
    the box take.

    The box is cut into one piece per choice where a shift or divisor differs (as the proof
    does) and split where the design code's comparison differs; each end of each constant's
    enclosure is then closed in on by splitting the boxes that hold it (interval arithmetic
    over-estimates a quantity that appears twice, such as L_d in L_d/(L_d + T_s·R_s))."""
    full = {p: r for p, r in problem.ranges.items() if not p.startswith("raw.") and r[0] != r[1]}
    leaves = _leaves(problem, full)
    if not leaves:
        return {k: None for k in problem.constants}
    out = {}
    for k in problem.constants:
        (lo, w_lo), (hi, w_hi) = (_refine(problem, k, leaves, full, end) for end in (0, 1))
        out[k] = {"range": (lo, hi),
                  "witnessed": (w_lo, w_hi) if w_lo is not None and w_hi is not None else None}
    return out


def _magnitudes(rng) -> tuple:
    """(smallest, largest) |x| over a range (smallest 0 when it holds 0)."""
    lo, hi = rng
    big = max(abs(lo), abs(hi))
    return (0.0 if lo <= 0 <= hi else min(abs(lo), abs(hi))), big


def _fits(rng, frac_bits: int, lsb: float, word_max: int) -> bool:
    """Whether every x of the range stores in the word at these bits, and none as 0."""
    small, big = _magnitudes(rng)
    scale = 2.0 ** frac_bits
    return big * scale < word_max + 1 - (0.5 if lsb == 0.5 else 0) and small * scale >= lsb


def _entry(found: dict, bits_of, lsb: float, word_max: int, **form) -> dict:
    """A proposal for one constant: its integers' range and worst error, or why none holds —
    ``impossible`` true when values real motors of the box take already span more than the
    word can hold (no format of this form exists), false when only the enclosure does."""
    rng = found["range"]
    small, big = _magnitudes(rng)
    frac_bits = bits_of(big)
    scale = 2.0 ** frac_bits
    if not _fits(rng, frac_bits, lsb, word_max):
        w = found["witnessed"]
        # The finest format the witnesses' largest value allows fails for them: so does every
        # other (a finer one overflows on that value, a coarser one loses the smallest).
        impossible = w is not None and not _fits(w, bits_of(_magnitudes(w)[1]), lsb, word_max)
        return {**form, "frac_bits": frac_bits, "range": None, "worst_error_pct": None,
                "real_range": list(rng), "witnessed": list(w) if w else None, "holds": False,
                "impossible": impossible}
    ends = [math.floor(abs(x) * scale + 0.5) if lsb == 0.5 else math.trunc(abs(x) * scale)
            for x in rng]
    lo_i, hi_i = (-ends[0], -ends[1]) if rng[1] < 0 else (ends[0], ends[1])
    return {**form, "frac_bits": frac_bits, "range": [min(lo_i, hi_i), max(lo_i, hi_i)],
            "worst_error_pct": math.nextafter(100.0 * lsb / (small * scale), math.inf),
            "real_range": list(rng), "witnessed": list(found["witnessed"] or []) or None,
            "holds": True}


def _nxp(problem, ranges: dict) -> dict:
    out = {}
    for k, found in ranges.items():
        if found is None:
            out[k] = None
            continue
        s = math.frexp(_magnitudes(found["range"])[1])[1]  # the smallest s with max|x| < 2^s
        out[k] = _entry(found, lambda big: 15 - math.frexp(big)[1], 1.0, _INT16_MAX, shift=s,
                        format=f"FRAC16 · 2^{s}", current=problem.constants[k]["format"])
    return {"constants": out}


def _pow2(problem, ranges: dict, largest: int) -> dict:
    out = {}
    for k, found in ranges.items():
        c = problem.constants[k]
        if found is None or c["word_bits"] != 16 or not c["format"].startswith(("Q", "int16 /")):
            continue  # ST's conversion constants are C casts of fixed formulas: nothing to choose
        n = pow2_exponent(_magnitudes(found["range"])[1], _INT16_MAX, largest)[0]
        out[k] = _entry(found, lambda big: pow2_exponent(big, _INT16_MAX, largest)[0], 0.5,
                        _INT16_MAX, q=n, current_q=c["q"],
                        format=f"Q{n}" if problem.profile == "microchip" else f"int16 / {1 << n}",
                        current=c["format"])
    return {"constants": out}


def _st(problem, ranges: dict, req: dict) -> dict:
    out = _pow2(problem, ranges, 14)
    cs = out["constants"]
    # One divisor per gain kind, shared by the two axes: the coarser of the two.
    divisors = {}
    for opt, kind in (("tf_kpdiv", "KP"), ("tf_kidiv", "KI")):
        ns = [e["q"] for k, e in cs.items() if k.endswith(f"_{kind}_DEFAULT") and e is not None]
        if ns:
            divisors[opt] = 1 << min(ns)
    out["divisors"] = divisors
    if len(divisors) == 2:
        inp = req["input"]
        profiles = {**(inp.get("profiles") or {})}
        profiles["st"] = {**(profiles.get("st") or {}), **divisors}
        # Only the gains: the other constants do not depend on the divisors.
        again = make_problem({**req, "profile": "st", "input": {**inp, "profiles": profiles}})
        gains = {k: finish(integer_steps(again, f"profiles.st.constants.{k}")) for k in cs}
        out["confirmed"] = {f"profiles.st.constants.{k}": e["verdict"] for k, e in gains.items()}
        for k, e in gains.items():
            if e["verdict"] == "proven":
                cs[k]["shared_worst_error_pct"] = e["worst_error_pct"]
    return out


def propose(req, proof: dict | None = None) -> dict:
    """The finest format of each constant in the profile's own form, holding over the box.

    Parameters
    ----------
    req : dict
        A proof request (:func:`pulab.analyses.prove.make_problem`).
    proof : dict, optional
        Its result, when already computed (the Inovance and TI proposals read it).

    Returns
    -------
    dict
        ``profile``, ``form`` (:data:`FORMS`) and per profile:
        ``constants`` {name: {format, frac_bits, range [lo, hi] of the integers (None when no
        format holds), worst_error_pct (a bound over the box), real_range, witnessed, holds,
        impossible (when not holds: the witnessed values alone need more than the word),
        current}}
        (``shift`` for NXP, ``q``/``current_q`` for ST and Microchip); ST adds ``divisors``
        ({tf_kpdiv, tf_kidiv}) and ``confirmed`` (the gains' verdicts re-proven with them);
        TI ``global_q``, ``tried`` and ``worst_error_pct`` {name: bound at that Q};
        Inovance ``integers`` {name: {headroom_bits, worst_error_pct, error_bound}}.
    """
    problem = make_problem(req)
    profile = problem.profile
    out = {"profile": profile, "form": FORMS[profile]}
    if profile == "inovance":
        r = proof or prove(req)
        out["integers"] = {k: {"headroom_bits": e["headroom_bits"],
                               "worst_error_pct": e["worst_error_pct"],
                               "error_bound": e["error_bound"]}
                           for k, e in r["integers"].items() if e["verdict"] == "proven"}
        return out
    if profile == "ti":
        g = propose_global_q(req)
        out.update(g)
        if g["global_q"] is not None:
            inp = req["input"]
            profiles = {**(inp.get("profiles") or {})}
            profiles["ti"] = {**(profiles.get("ti") or {}), "global_q": g["global_q"]}
            r = prove({**req, "profile": "ti", "input": {**inp, "profiles": profiles}})
            out["worst_error_pct"] = {k.split(".")[-1]: e["worst_error_pct"]
                                      for k, e in r["integers"].items()}
        return out
    ranges = real_ranges(problem)
    if profile == "nxp":
        out.update(_nxp(problem, ranges))
    elif profile == "st":
        out.update(_st(problem, ranges, req))
    else:
        out.update(_pow2(problem, ranges, 15))
    return out
