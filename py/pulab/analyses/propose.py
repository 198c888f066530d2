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

from ..fixedpoint.interval import Branch, Empty, RInterval, Undecided, forcing
from ..profiles.common import pow2_exponent
from ..schema.errors import InputError
from .prove import _pi_input, _profile_constants, make_problem, prove, propose_global_q

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


def real_ranges(problem) -> dict:
    """{constant: (lo, hi) or None} — every real value each constant of the profile takes over
    the box; None when the work budget ran out before the whole box was enclosed.

    The box is cut into one piece per choice where a shift or divisor differs (as the proof
    does) and split where the design code's comparison differs."""
    full = {p: r for p, r in problem.ranges.items() if not p.startswith("raw.") and r[0] != r[1]}
    heap = [(-1.0, 0, dict(full), {})]
    order, evaluated, hull = 1, 0, {}
    while heap:
        if evaluated >= problem.budget:
            return {k: None for k in problem.constants}
        neg, _, box, forced = heapq.heappop(heap)
        evaluated += 1
        try:
            with forcing(forced):
                cs = _profile_constants(_pi_input(problem, box), problem)
        except Branch as b:
            for c in b.choices:
                heapq.heappush(heap, (neg / len(b.choices), order, box, {**forced, b.site: c}))
                order += 1
            continue
        except Empty:
            continue
        except (Undecided, InputError):
            # A design comparison differs (split), or the report refuses part of the box
            # (its points have no constants; the rest are still enclosed).
            if not full or -neg < 1e-12:
                continue
            p = max(full, key=lambda q: (box[q][1] - box[q][0]) / (full[q][1] - full[q][0]))
            lo, hi = box[p]
            mid = math.sqrt(lo * hi) if lo > 0 and hi > 4 * lo else lo + (hi - lo) / 2
            for half in ((lo, mid), (mid, hi)):
                heapq.heappush(heap, (neg / 2, order, {**box, p: half}, forced))
                order += 1
            continue
        for k, c in cs.items():
            lo, hi = _real(c)
            h = hull.get(k)
            hull[k] = (lo, hi) if h is None else (min(h[0], lo), max(h[1], hi))
    return {k: hull.get(k) for k in problem.constants}


def _magnitudes(rng) -> tuple:
    """(smallest, largest) |x| over a range (smallest 0 when it holds 0)."""
    lo, hi = rng
    big = max(abs(lo), abs(hi))
    return (0.0 if lo <= 0 <= hi else min(abs(lo), abs(hi))), big


def _entry(rng, frac_bits: int, lsb: float, word_max: int, **form) -> dict:
    """A proposal for one constant: its integers' range and worst error, or why none holds."""
    small, big = _magnitudes(rng)
    scale = 2.0 ** frac_bits
    # Beyond the word even at the coarsest form, or so small that it may store 0.
    if big * scale >= word_max + 1 - (0.5 if lsb == 0.5 else 0) or small * scale < lsb:
        return {**form, "frac_bits": frac_bits, "range": None, "worst_error_pct": None,
                "real_range": list(rng), "holds": False}
    ends = [math.floor(abs(x) * scale + 0.5) if lsb == 0.5 else math.trunc(abs(x) * scale)
            for x in rng]
    lo_i, hi_i = (-ends[0], -ends[1]) if rng[1] < 0 else (ends[0], ends[1])
    return {**form, "frac_bits": frac_bits, "range": [min(lo_i, hi_i), max(lo_i, hi_i)],
            "worst_error_pct": math.nextafter(100.0 * lsb / (small * scale), math.inf),
            "real_range": list(rng), "holds": True}


def _nxp(problem, ranges: dict) -> dict:
    out = {}
    for k, rng in ranges.items():
        c = problem.constants[k]
        if rng is None:
            out[k] = None
            continue
        s = math.frexp(_magnitudes(rng)[1])[1]  # the smallest s with max|x| < 2^s
        out[k] = _entry(rng, 15 - s, 1.0, _INT16_MAX, shift=s, format=f"FRAC16 · 2^{s}",
                        current=c["format"])
    return {"constants": out}


def _pow2(problem, ranges: dict, largest: int) -> dict:
    out = {}
    for k, rng in ranges.items():
        c = problem.constants[k]
        if rng is None or c["word_bits"] != 16 or not c["format"].startswith(("Q", "int16 /")):
            continue  # ST's conversion constants are C casts of fixed formulas: nothing to choose
        n = pow2_exponent(_magnitudes(rng)[1], _INT16_MAX, largest)[0]
        out[k] = _entry(rng, n, 0.5, _INT16_MAX, q=n, current_q=c["q"],
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
        r = prove({**req, "profile": "st", "input": {**inp, "profiles": profiles}})
        out["confirmed"] = {k: e["verdict"] for k, e in r["integers"].items()
                            if "_KP_" in k or "_KI_" in k}
        for k, e in r["integers"].items():
            key = k.split(".")[-1]
            if key in cs and e["verdict"] == "proven":
                cs[key]["shared_worst_error_pct"] = e["worst_error_pct"]
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
        format holds), worst_error_pct (a bound over the box), real_range, holds, current}}
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
