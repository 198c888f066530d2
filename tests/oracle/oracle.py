"""Independent oracle for the pu-lab report (docs/contract.md, seed document).

Written from the contract and the seed only; it never imports pulab, so that the golden
vectors it produces are a second opinion, not a recording of pulab's output.

C integer arithmetic of the TI C2000 (int = 16 bit, long = 32 bit) is done with numpy
fixed-width scalars, which wrap by themselves; flags are found by comparing each numpy
result with the exact Python-int result (wrap) and by remainders (truncation).
Everything else is plain float formulas.
"""

from __future__ import annotations

import math

import numpy as np

SQRT2 = math.sqrt(2.0)
SQRT3 = math.sqrt(3.0)
INV_SQRT2 = 0.7071067811865476  # the contract's default ζ = 1/√2


class OracleInputError(Exception):
    """Bad input; `field` is what pulab.InputError.field must equal."""

    def __init__(self, field: str, message: str):
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message


# ----------------------------------------------------------------------------------------
# Input validation and defaults (contract "Input")

_SCHEMA = {
    "motor": {"rated_voltage_v", "rated_current_a", "rated_freq_hz", "rs_ohm", "ld_h",
              "lq_h", "bemf_v", "pole_pairs"},
    "drive": {"base_freq_hz", "udc_v", "ts_s"},
    "conventions": {"base", "base_voltage_v", "base_current_a", "angle_base",
                    "inductance_unit"},
    "current_loop": {"method", "bandwidth_hz", "damping", "kp", "ki"},
    "pll": {"bandwidth_hz", "damping"},
    "raw": {"Voltage", "Current", "FullFreq01", "FreqRated01", "RsPm", "LD", "LQ",
            "BemfVolt", "uDCFilter"},
}
RAW_NAMES = ["Voltage", "Current", "FullFreq01", "FreqRated01", "RsPm", "LD", "LQ",
             "BemfVolt", "uDCFilter"]


def _is_number(v) -> bool:
    # JSON booleans are Python bools, which are ints: the contract says they are not numbers.
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _section(inp: dict, name: str) -> dict:
    sec = inp.get(name)
    if sec is None:
        return {}
    if not isinstance(sec, dict):
        raise OracleInputError(name, "must be an object")
    for k in sec:
        if k not in _SCHEMA[name]:
            raise OracleInputError(f"{name}.{k}", "unknown key")
    return sec


def _positive(sec: dict, sname: str, key: str, default=None, required=True) -> float | None:
    field = f"{sname}.{key}"
    v = sec.get(key)
    if v is None:
        if default is not None:
            return float(default)
        if required:
            raise OracleInputError(field, "missing")
        return None
    if not _is_number(v):
        raise OracleInputError(field, "not a number")
    v = float(v)
    if not math.isfinite(v) or v <= 0:
        raise OracleInputError(field, "must be > 0")
    return v


def _choice(sec: dict, sname: str, key: str, allowed: tuple, default: str) -> str:
    v = sec.get(key)
    if v is None:
        return default
    if v not in allowed:
        raise OracleInputError(f"{sname}.{key}", f"must be one of {allowed}")
    return v


def _round_half_away(x: float) -> int:
    # Contract: sign(x)·floor(|x| + 0.5) — ties away from zero (not Python's banker's round).
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def parse(inp: dict) -> dict:
    if not isinstance(inp, dict):
        raise OracleInputError("input", "must be an object")
    for k in inp:
        if k not in _SCHEMA:
            raise OracleInputError(k, "unknown key")
    m = _section(inp, "motor")
    d = _section(inp, "drive")
    c = _section(inp, "conventions")
    cl = _section(inp, "current_loop")
    p = _section(inp, "pll")
    r = _section(inp, "raw")

    P = {}
    for key in ("rated_voltage_v", "rated_current_a", "rated_freq_hz", "rs_ohm", "ld_h",
                "lq_h", "bemf_v"):
        P[key] = _positive(m, "motor", key)
    pp = m.get("pole_pairs")
    if pp is None:
        raise OracleInputError("motor.pole_pairs", "missing")
    if not _is_number(pp):
        raise OracleInputError("motor.pole_pairs", "not a number")
    if pp != int(pp) or pp < 1:
        raise OracleInputError("motor.pole_pairs", "must be an integer >= 1")
    P["pole_pairs"] = int(pp)

    P["base_freq_hz"] = _positive(d, "drive", "base_freq_hz", default=P["rated_freq_hz"])
    P["udc_v"] = _positive(d, "drive", "udc_v")
    P["ts_s"] = _positive(d, "drive", "ts_s")

    P["base"] = _choice(c, "conventions", "base", ("rms", "peak", "custom"), "rms")
    P["angle_base"] = _choice(c, "conventions", "angle_base", ("pi", "2pi"), "pi")
    P["inductance_unit"] = _choice(c, "conventions", "inductance_unit", ("10uH", "uH"), "10uH")
    custom = P["base"] == "custom"
    P["base_voltage_v"] = _positive(c, "conventions", "base_voltage_v", required=custom)
    P["base_current_a"] = _positive(c, "conventions", "base_current_a", required=custom)

    P["method"] = _choice(cl, "current_loop", "method", ("bandwidth", "damping", "manual"),
                          "bandwidth")
    P["cl_bandwidth_hz"] = _positive(cl, "current_loop", "bandwidth_hz", default=500.0)
    P["cl_damping"] = _positive(cl, "current_loop", "damping", default=INV_SQRT2)
    manual = P["method"] == "manual"
    P["kp"] = _positive(cl, "current_loop", "kp", required=manual)
    P["ki"] = _positive(cl, "current_loop", "ki", required=manual)

    P["pll_bandwidth_hz"] = _positive(p, "pll", "bandwidth_hz", default=50.0)
    P["pll_damping"] = _positive(p, "pll", "damping", default=INV_SQRT2)

    # Raw firmware integers: SI · unit scale (one double multiply), rounded ties-away,
    # unless given in `raw` (contract "Raw firmware inputs").
    l_scale = 1e5 if P["inductance_unit"] == "10uH" else 1e6
    si = {
        "Voltage": (P["rated_voltage_v"], 1.0),
        "Current": (P["rated_current_a"], 100.0),
        "FullFreq01": (P["base_freq_hz"], 100.0),
        "FreqRated01": (P["rated_freq_hz"], 100.0),
        "RsPm": (P["rs_ohm"], 1000.0),
        "LD": (P["ld_h"], l_scale),
        "LQ": (P["lq_h"], l_scale),
        "BemfVolt": (P["bemf_v"], 10.0),
        "uDCFilter": (P["udc_v"], 10.0),
    }
    raw, outside = {}, {}
    for name in RAW_NAMES:
        v = r.get(name)
        if v is None:
            v = _round_half_away(float(si[name][0]) * si[name][1])
            if not 0 <= v <= 65535:
                # A value the motor needs but the firmware's Uint16 cannot hold: a limit of
                # that firmware, reported in firmware.inovance, not an input error.
                outside[name] = v
                continue
        else:
            if not _is_number(v):
                raise OracleInputError(f"raw.{name}", "not a number")
            if v != int(v):
                raise OracleInputError(f"raw.{name}", "must be an integer")
            v = int(v)
        if not 0 <= v <= 65535:
            raise OracleInputError(f"raw.{name}", "outside Uint16 0..65535")
        raw[name] = v
    P["raw"], P["outside"] = raw, outside
    return P


# ----------------------------------------------------------------------------------------
# C integer helpers (numpy scalars wrap; Python ints are the exact reference)

def _np_type(ctype: str):
    return {"Uint16": np.uint16, "Ulong": np.uint32, "long": np.int32}[ctype]


class Step:
    """Accumulates the flags of one C statement."""

    def __init__(self):
        self.flags: set[str] = set()

    def mul(self, a, b):
        with np.errstate(over="ignore"):
            r = a * b
        if int(r) != int(a) * int(b):
            self.flags.add("wrap")
        return r

    def add(self, a, b):
        with np.errstate(over="ignore"):
            r = a + b
        if int(r) != int(a) + int(b):
            self.flags.add("wrap")
        return r

    def shl(self, a, n: int):
        with np.errstate(over="ignore"):
            r = a << type(a)(n)
        if int(r) != int(a) * (1 << n):
            self.flags.add("wrap")
        return r

    def shr(self, a, n: int):
        r = a >> type(a)(n)  # arithmetic for signed numpy types; all operands here are >= 0
        if int(a) & ((1 << n) - 1):
            self.flags.add("truncation")
        return r

    def div(self, a, b, field: str):
        ia, ib = int(a), int(b)
        if ib == 0:
            raise OracleInputError(field, "division by zero in the firmware path")
        q = abs(ia) // abs(ib)
        if (ia < 0) != (ib < 0):
            q = -q  # C division truncates toward zero
        if q * ib != ia:
            self.flags.add("truncation")
        # The quotient of same-typed operands has that type; it always fits (|q| <= |a|).
        return type(a)(q)

    def store(self, a, ctype: str):
        """Assignment: C conversion, modulo 2^N (Uint16 for gMotorExtPer.* and FreqPer)."""
        r = np.array(a).astype(_np_type(ctype))[()]
        if int(r) != int(a):
            self.flags.add("store" if ctype == "Uint16" else "wrap")
        return r


def _trace(var: str, ctype: str, value, step: Step, extra=()) -> dict:
    # var: the destination as the seed's code names it (gMotorExtPer.*, gMotorInfo.FreqPer,
    # m_UData, m_BaseL, m_Ulong, data1, pm_maxout_vol, maxu); the contract leaves it open.
    return {"var": var, "type": ctype, "value": int(value),
            "flags": sorted(step.flags | set(extra))}


def _result(value, ideal: float, q: int, ctype: str, si: float, trace: list) -> dict:
    flags = sorted(set().union(*[set(t["flags"]) for t in trace]))
    # A zero raw numerator (e.g. RsPm 0) makes ideal and value 0; the contract forbids NaN,
    # so 0/0 is reported as 0 % (not covered by the golden cases: the contract is silent).
    err = 0.0 if ideal == 0 else 100.0 * (int(value) - ideal) / ideal
    return {"value": int(value), "ideal": float(ideal), "q": q, "type": ctype,
            "si": float(si), "error_pct": err,
            "flags": flags, "trace": trace}


U32, I32, U16 = np.uint32, np.int32, np.uint16


#: The raw parameters each vendor block below reads (from its C statements).
READS = {"Rpm": ("RsPm", "Current", "Voltage"),
         "LD": ("Voltage", "Current", "FullFreq01", "LD"),
         "LQ": ("Voltage", "Current", "FullFreq01", "LQ"),
         "FreqPer": ("FreqRated01", "FullFreq01"),
         "FluxRotor": ("BemfVolt", "Voltage", "FreqRated01", "FullFreq01"),
         "pm_maxout_vol": ("uDCFilter", "Voltage"), "maxu": ("uDCFilter", "Voltage")}


def _rpm(P: dict) -> dict:
    raw = P["raw"]
    V, I = raw["Voltage"], raw["Current"]
    Zb = (V / SQRT3) / (I / 100.0)
    # --- Rpm (seed 1.4-1, 1.4-2): Q16 ---
    s1 = Step()
    m_UData = s1.div(s1.mul(U32(raw["RsPm"]), U32(I)), U32(V), "raw.Voltage")
    s2 = Step()
    rpm = s2.store(s2.shr(s2.mul(U32(m_UData), U32(18597)), 14), "Uint16")
    ideal = (raw["RsPm"] / 1000.0) / ((V / SQRT3) / (I / 100.0)) * 2.0 ** 16
    return _result(rpm, ideal, 16, "Uint16", int(rpm) / 2.0 ** 16 * Zb, [
        _trace("m_UData", "Ulong", m_UData, s1), _trace("gMotorExtPer.Rpm", "Uint16", rpm, s2)])


def _inductance(P: dict, name: str) -> dict:
    raw = P["raw"]
    V, I, FF = raw["Voltage"], raw["Current"], raw["FullFreq01"]
    Lb = (V / SQRT3) / (2.0 * math.pi * (FF / 100.0) * (I / 100.0))
    # --- LD, LQ (seed 1.4-3 … 1.4-15): Q13, ×10 when the raw unit is µH ---
    a = Step()
    baseL1 = a.div(a.mul(U32(V), U32(3678)), U32(I), "raw.Current")
    b = Step()
    # m_BaseL == 0 after this would only surface at the next division; name FullFreq01
    # when it is this step that zeroed it, Current when the first step already did.
    baseL2 = b.div(b.mul(U32(baseL1), U32(5000)), U32(FF), "raw.FullFreq01")
    c = Step()
    m1 = c.add(c.shl(U32(raw[name]), 14), c.shr(U32(baseL2), 1))
    d = Step()
    zero_field = "raw.Current" if int(baseL1) == 0 else "raw.FullFreq01"
    m2 = d.div(U32(m1), U32(baseL2), zero_field)
    e = Step()
    res = e.store(e.div(U32(m2), U32(10), name), "Uint16")
    extra = ("unit_uH",) if P["inductance_unit"] == "uH" else ()
    L = raw[name] * (1e-5 if P["inductance_unit"] == "10uH" else 1e-6)
    ideal = L / Lb * 2.0 ** 13
    return _result(res, ideal, 13, "Uint16", int(res) / 2.0 ** 13 * Lb, [
        _trace("m_BaseL", "Ulong", baseL1, a), _trace("m_BaseL", "Ulong", baseL2, b),
        _trace("m_Ulong", "Ulong", m1, c), _trace("m_Ulong", "Ulong", m2, d),
        # unit_uH rides on the store step, so result flags stay the union of step flags.
        _trace(f"gMotorExtPer.{name}", "Uint16", res, e, extra)])


def _freqper_int(P: dict):
    raw = P["raw"]
    s = Step()
    return s.store(s.div(s.shl(U32(raw["FreqRated01"]), 15), U32(raw["FullFreq01"]),
                         "raw.FullFreq01"), "Uint16"), s


def _freqper(P: dict) -> dict:
    FR, FF = P["raw"]["FreqRated01"], P["raw"]["FullFreq01"]
    # --- FreqPer: Q15 ---
    freqper, s = _freqper_int(P)
    return _result(freqper, FR / FF * 2.0 ** 15, 15, "Uint16", int(freqper) / 2.0 ** 15 * FF / 100.0,
                   [_trace("gMotorInfo.FreqPer", "Uint16", freqper, s)])


def _flux(P: dict) -> dict:
    raw = P["raw"]
    V, FF, FR = raw["Voltage"], raw["FullFreq01"], raw["FreqRated01"]
    psib = (V / SQRT3) / (2.0 * math.pi * FF / 100.0)
    # --- FluxRotor (seed 1.4-23 … 1.4-25): Q12 ---
    s1 = Step()
    with np.errstate(over="ignore"):
        v10 = U16(V) * U16(10)  # `int` arithmetic on C2000 is 16-bit unsigned here
    if int(v10) != V * 10:
        s1.flags.add("wrap")
    num = s1.shl(I32(raw["BemfVolt"]), 12)
    q = s1.div(num, I32(int(v10)), "raw.Voltage")  # unsigned int promoted to long
    m_Ulong = s1.store(q, "Ulong")
    freqper, _ = _freqper_int(P)
    s2 = Step()
    flux = s2.store(s2.div(s2.shl(U32(m_Ulong), 15), U32(int(freqper)), "raw.FreqRated01"),
                    "Uint16")
    ideal = (raw["BemfVolt"] / 10.0) / V * FF / FR * 2.0 ** 12
    return _result(flux, ideal, 12, "Uint16", int(flux) / 2.0 ** 12 * psib, [
        _trace("m_Ulong", "Ulong", m_Ulong, s1),
        _trace("gMotorExtPer.FluxRotor", "Uint16", flux, s2)])


def _limits(P: dict) -> tuple[dict, dict]:
    raw = P["raw"]
    V = raw["Voltage"]
    # --- pm_maxout_vol, maxu (seed 2.2-2): Q12, Q24, long ---
    s1 = Step()
    data1 = s1.shr(s1.mul(I32(raw["uDCFilter"]), I32(2316)), 15)
    s2 = Step()
    pmv = s2.div(s2.shl(I32(data1), 12), I32(V), "raw.Voltage")
    ideal = (raw["uDCFilter"] / 10.0 / SQRT2) / V * 2.0 ** 12
    out = _result(pmv, ideal, 12, "long", int(pmv) / 2.0 ** 12 * V, [
        _trace("data1", "long", data1, s1), _trace("pm_maxout_vol", "long", pmv, s2)])
    s3 = Step()
    maxu = s3.shl(I32(pmv), 12)
    return out, _result(maxu, ideal * 2.0 ** 12, 24, "long", int(maxu) / 2.0 ** 24 * V,
                        [_trace("maxu", "long", maxu, s3)])


BLOCKS = {"Rpm": _rpm, "LD": lambda P: _inductance(P, "LD"),
          "LQ": lambda P: _inductance(P, "LQ"), "FreqPer": _freqper, "FluxRotor": _flux,
          "pm_maxout_vol": lambda P: _limits(P)[0], "maxu": lambda P: _limits(P)[1]}


def vendor(P: dict) -> tuple[dict, dict]:
    """The vendor results the firmware computes, and the firmware's own limit entries:
    each block runs alone; one that reads a raw parameter beyond Uint16 or divides by zero
    is not computed and its field is listed (docs/contract.md "Firmware limits")."""
    out = {"raw": dict(P["raw"])}
    failed: dict = {}
    for name, block in BLOCKS.items():
        missing = [k for k in READS[name] if k in P["outside"]]
        if missing:
            failed.setdefault(f"raw.{missing[0]}", []).append(name)
            continue
        try:
            out[name] = block(P)
        except OracleInputError as e:
            failed.setdefault(e.field, []).append(name)
    problems = []
    for name, value in P["outside"].items():
        problems.append({"field": f"raw.{name}", "value": value, "stored": value % 65536,
                         "results": sorted(failed.pop(f"raw.{name}", []))})
    problems += [{"field": f, "value": None, "stored": None, "results": sorted(r)}
                 for f, r in failed.items()]
    return out, {"representable": not problems, "problems": problems}


# ----------------------------------------------------------------------------------------
# Floats: bases, per unit, PI, PLL, constants

def bases(P: dict) -> dict:
    if P["base"] == "rms":
        Ub, Ib = P["rated_voltage_v"] / SQRT3, P["rated_current_a"]
    elif P["base"] == "peak":
        Ub, Ib = P["rated_voltage_v"] * math.sqrt(2.0 / 3.0), SQRT2 * P["rated_current_a"]
    else:
        Ub, Ib = P["base_voltage_v"], P["base_current_a"]
    fb = P["base_freq_hz"]
    wb = 2.0 * math.pi * fb
    Zb = Ub / Ib
    return {"U_b": Ub, "I_b": Ib, "f_b": fb, "w_b": wb, "Z_b": Zb, "L_b": Zb / wb,
            "psi_b": Ub / wb, "T_b": 1.0 / wb,
            "P_b": (3.0 if P["base"] == "rms" else 1.5) * Ub * Ib,  # seed 3.79/3.82
            "theta_b": math.pi if P["angle_base"] == "pi" else 2.0 * math.pi}


def per_unit(P: dict, B: dict) -> dict:
    # ψ_r from the line back-EMF (seed 1.3-2, 1.4-22): RMS flux, ×√2 for amplitude-invariant.
    psi = P["bemf_v"] / (SQRT3 * 2.0 * math.pi * P["rated_freq_hz"])
    if P["base"] != "rms":
        psi *= SQRT2
    return {"Rs": P["rs_ohm"] / B["Z_b"], "Ld": P["ld_h"] / B["L_b"],
            "Lq": P["lq_h"] / B["L_b"], "psi_r": psi / B["psi_b"], "psi_r_wb": psi,
            "Ts": P["ts_s"] * B["w_b"]}


def current_pi(P: dict, B: dict) -> dict:
    Ub, Ib, ts = B["U_b"], B["I_b"], P["ts_s"]
    out = {"method": P["method"]}
    for axis, L in (("d", P["ld_h"]), ("q", P["lq_h"])):
        if P["method"] == "bandwidth":
            wc = 2.0 * math.pi * P["cl_bandwidth_hz"]
            kp, ki = wc * L, wc * P["rs_ohm"]
        elif P["method"] == "damping":
            w0 = 2.0 * math.pi * P["cl_bandwidth_hz"]
            kp = 2.0 * P["cl_damping"] * w0 * L - P["rs_ohm"]
            ki = w0 ** 2 * L
            if kp <= 0:
                raise OracleInputError("current_loop.bandwidth_hz", "kp <= 0")
        else:
            kp, ki = P["kp"], P["ki"]
        kp_pu, ki_pu = kp * Ib / Ub, ki * Ib / Ub  # seed 2.1-4
        pm_kp = _round_half_away(kp_pu * 2.0 ** 12)  # seed 2.2-9, Q12
        pm_ki = _round_half_away(ki_pu * ts * 2.0 ** 16)  # seed 2.2-9, Q16 with Ts inside
        for v in (pm_kp, pm_ki):
            if not -2 ** 31 <= v < 2 ** 31:
                raise OracleInputError("current_loop", "gain integer outside int32")
        fkp = pm_kp / 2.0 ** 12 * Ub / Ib
        fki = pm_ki / 2.0 ** 16 / ts * Ub / Ib
        out[axis] = {"kp": kp, "ki": ki, "kp_pu": kp_pu, "ki_pu": ki_pu, "pm_kp": pm_kp,
                     "pm_ki": pm_ki,
                     "from_integers": {"kp": fkp, "ki": fki,
                                       "bandwidth_hz": fkp / (2.0 * math.pi * L)}}
    return out


def pll(P: dict, B: dict) -> dict:
    wn = 2.0 * math.pi * P["pll_bandwidth_hz"]
    kp, ki = 2.0 * P["pll_damping"] * wn, wn ** 2
    th, wb = B["theta_b"], B["w_b"]
    # seed 3.1-6 (k/(2 f_b) for θ_b = π) and 3.2-5 (integrator gain 2 f_b)
    return {"kp": kp, "ki": ki, "kp_pu": kp * th / wb, "ki_pu": ki * th / wb,
            "integrator_gain": wb / th}


def constants() -> dict:
    exact = {"18597": 2.0 ** 30 * SQRT3 / 1e5,  # seed 1.4-2
             "3678": 2e4 / (SQRT3 * math.pi),  # seed 1.4-4/1.4-5 (10 µH units → Q13)
             "2316": 2.0 ** 15 / (10.0 * SQRT2)}  # seed 2.2-1/2.2-2
    return {k: {"value": int(k), "exact": e, "rel_error": (int(k) - e) / e}
            for k, e in exact.items()}


def oracle_report(inp: dict) -> dict:
    """The compared fields of pulab.report(inp); raises OracleInputError on bad input."""
    P = parse(inp)
    B = bases(P)
    V, F = vendor(P)
    C = current_pi(P, B)
    return {"base": B, "pu": per_unit(P, B), "vendor": V, "current_pi": C,
            "pll": pll(P, B), "constants": constants(), "firmware": {"inovance": F}}
