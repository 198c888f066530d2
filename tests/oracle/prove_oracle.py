"""Exhaustive oracle for family proofs: every raw point of a box through the seed's C code.

Never imports pulab.  The seed's normalization code (seed 1.4 and 2.2, as printed in
/work/shared/seeds/000_e1cf52bc344b3aa9.txt, with FreqPer = (FreqRated01<<15)/FullFreq01)
is written out once more over numpy int64 arrays — one array element per raw point of the
box — with the C2000 types checked by hand at every operation: exact in int64 (no product
here exceeds 2^48), then reduced modulo the C type, a change being a wrap.  An integer
*fails* at a point (docs/contract.md, "Family proof") when a raw parameter it reads is
beyond Uint16, when its code divides by zero, when a step wraps or its Uint16 store changes
the number, or when its result is 0.

SI inputs map to raw integers with :func:`oracle.parse` (independent of pulab as well).
"""

from __future__ import annotations

import numpy as np

from oracle import RAW_NAMES, READS, parse

M16, M32 = 0xFFFF, 0xFFFFFFFF
S32_MIN, S32_MAX = -(1 << 31), (1 << 31) - 1

class _Run:
    """One C block over arrays: ``fail`` collects every point that wraps or divides by 0."""

    def __init__(self, shape):
        self.fail = np.zeros(shape, dtype=bool)

    def ulong(self, x):
        self.fail |= (x < 0) | (x > M32)
        return x & M32

    def long(self, x):
        self.fail |= (x < S32_MIN) | (x > S32_MAX)
        return ((x - S32_MIN) & M32) + S32_MIN

    def uint(self, x):
        """16-bit unsigned ``int`` arithmetic (C2000) and the Uint16 store alike."""
        self.fail |= (x < 0) | (x > M16)
        return x & M16

    def div(self, a, b):
        """C ``/`` of non-negative operands (all of them here); b = 0 fails the point."""
        self.fail |= b == 0
        return a // np.where(b == 0, 1, b)


def _freqper(r: _Run, fr, ff):
    return r.uint(r.div(r.ulong(fr << 15), ff))


def block(name: str, raw: dict):
    """(value, fail) arrays of one result; ``raw`` maps each read parameter to an int64 array."""
    shape = np.broadcast(*[raw[k] for k in READS[name]]).shape
    r = _Run(shape)
    V = raw.get("Voltage")
    if name == "Rpm":
        m = r.div(r.ulong(raw["RsPm"] * raw["Current"]), V)
        value = r.uint(r.ulong(m * 18597) >> 14)
    elif name in ("LD", "LQ"):
        base = r.div(r.ulong(V * 3678), raw["Current"])
        base = r.div(r.ulong(base * 5000), raw["FullFreq01"])
        m = r.div(r.ulong((raw[name] << 14) + (base >> 1)), base)
        value = r.uint(m // 10)
    elif name == "FreqPer":
        value = _freqper(r, raw["FreqRated01"], raw["FullFreq01"])
    elif name == "FluxRotor":
        v10 = r.uint(V * 10)                      # Uint16 * 10 in 16-bit unsigned int
        m = r.div(raw["BemfVolt"] << 12, v10)     # long / (unsigned int → long)
        # FreqPer is its own result: its wrapped store is its failure, not FluxRotor's,
        # but its division by zero stops FluxRotor's code as well.
        fp_run = _Run(shape)
        fp = _freqper(fp_run, raw["FreqRated01"], raw["FullFreq01"])
        r.fail |= raw["FullFreq01"] == 0
        value = r.uint(r.div(r.ulong(m << 15), fp))
    elif name in ("pm_maxout_vol", "maxu"):
        data1 = r.long(raw["uDCFilter"] * 2316) >> 15
        pmv = r.div(r.long(data1 << 12), V)
        if name == "maxu":
            r = _Run(shape)                       # maxu's own statement only...
            r.fail |= V == 0                      # ...after pm_maxout_vol's division
            value = r.long(pmv << 12)
        else:
            value = pmv
    else:
        raise KeyError(name)
    outside = np.zeros(shape, dtype=bool)
    for k in READS[name]:
        outside |= raw[k] > M16
    return value, r.fail | outside | (value == 0)


def ideal(name: str, raw: dict):
    """The real value each result's integer stands for, from the per-unit bases of the same raw
    parameters (seed 1.4-13: U_b = U_LL/√3, I_b, f_b; inductance raw in 0.01 mH), as float64
    arrays: R_s/Z_b·2^16, L/L_b·2^13, f_n/f_b·2^15, ψ_r/ψ_b·2^12 (ψ_r from the line back-EMF at
    f_n), (U_dc/√2)/U_LL·2^12 and ·2^24."""
    f = {k: np.asarray(v, dtype=np.float64) for k, v in raw.items()}
    u_b = f.get("Voltage", np.nan) / np.sqrt(3.0)
    i_b, f_b = f.get("Current", np.nan) / 100.0, f.get("FullFreq01", np.nan) / 100.0
    w_b = 2.0 * np.pi * f_b
    if name == "Rpm":
        return f["RsPm"] / 1000.0 / (u_b / i_b) * 2.0 ** 16
    if name in ("LD", "LQ"):
        return f[name] * 1e-5 / (u_b / (w_b * i_b)) * 2.0 ** 13
    if name == "FreqPer":
        return f["FreqRated01"] / 100.0 / f_b * 2.0 ** 15
    if name == "FluxRotor":
        psi = f["BemfVolt"] / 10.0 / np.sqrt(3.0) / (2.0 * np.pi * f["FreqRated01"] / 100.0)
        return psi / (u_b / w_b) * 2.0 ** 12
    q = 12 if name == "pm_maxout_vol" else 24
    return f["uDCFilter"] / 10.0 / np.sqrt(2.0) / f["Voltage"] * 2.0 ** q


def raw_box(inp: dict, ranges: dict) -> dict:
    """raw name → (lo, hi): the oracle's own SI → raw map at both ends of every range."""
    lo, hi = _raw_at(inp, ranges, 0), _raw_at(inp, ranges, 1)
    return {k: (min(lo[k], hi[k]), max(lo[k], hi[k])) for k in RAW_NAMES}


def _raw_at(inp: dict, ranges: dict, end: int) -> dict:
    x = {s: dict(v) if isinstance(v, dict) else v for s, v in inp.items()}
    for path, pair in ranges.items():
        sec, key = path.split(".")
        x.setdefault(sec, {})[key] = pair[end]
    return raw_point(x)


def dimensions(inp: dict, ranges: dict) -> list:
    """For each ranged input, the raw fields it moves (found by moving it alone).

    One input can move two fields: f_b defaults to f_n, so a ranging f_n moves FreqRated01
    and FullFreq01 together (same value, same ×100, so the same integer at every point).
    """
    base = _raw_at(inp, {p: (lo, lo) for p, (lo, _) in ranges.items()}, 0)
    dims = []
    for path, (lo, hi) in ranges.items():
        moved = _raw_at(inp, {**{p: (a, a) for p, (a, _) in ranges.items()}, path: (hi, hi)}, 0)
        fields = [k for k in RAW_NAMES if moved[k] != base[k]]
        if fields:
            dims.append(fields)
    return dims


def raw_point(inp: dict) -> dict:
    """The raw integers of one input (beyond-Uint16 values kept as they are)."""
    p = parse(inp)
    return {**p["raw"], **p["outside"]}


def enumerate_box(name: str, box: dict, dims: list) -> dict:
    """Every raw point of the box for result ``name``; ``dims`` as :func:`dimensions` (the
    fields of one dimension take the same integer).

    Returns
    -------
    dict
        ``points`` (how many), ``fails`` (how many fail), ``first_fail`` (a failing raw
        point or None), ``min``/``max`` of the value over the points that do not fail and
        ``max_error_pct``, the largest |value − ideal|/ideal there, in percent.
    """
    keys = READS[name]
    used = [d for d in dims if set(d) & set(keys)]
    for d in used:
        assert len({box[k] for k in d}) == 1, d  # tied fields share one range
    grids = np.meshgrid(*[np.arange(box[d[0]][0], box[d[0]][1] + 1, dtype=np.int64)
                          for d in used], indexing="ij")
    n = grids[0].size if grids else 1
    raw = {k: np.full(n, box[k][0], dtype=np.int64) for k in keys}
    for d, g in zip(used, grids):
        for k in d:
            if k in raw:
                raw[k] = g.ravel()
    value, fail = block(name, raw)
    ok = ~fail
    first = None
    if fail.any():
        i = int(np.argmax(fail))
        first = {k: int(raw[k][i]) for k in keys}
    with np.errstate(divide="ignore", invalid="ignore"):
        err = np.abs(100.0 * (value - ideal(name, raw)) / ideal(name, raw))
    return {"points": int(fail.size), "fails": int(fail.sum()), "first_fail": first,
            "min": int(value[ok].min()) if ok.any() else None,
            "max": int(value[ok].max()) if ok.any() else None,
            "max_error_pct": float(err[ok].max()) if ok.any() else None}


def fails_at(name: str, point: dict) -> bool:
    """Whether result ``name`` fails at one raw point."""
    _, fail = block(name, {k: np.array([point[k]], dtype=np.int64) for k in READS[name]})
    return bool(fail[0])


__all__ = ["READS", "block", "ideal", "raw_box", "raw_point", "dimensions", "enumerate_box", "fails_at"]
