"""The course's exercises: each answer is read from this package's own report (or its C tracer).

A trainee's answer is checked here, never in the page: :func:`check` computes the report of the
trainee's motor, takes the expected value an exercise names, and compares with the stated
tolerance (:data:`EXERCISES`); the worker asks through ``pulab.api.call_json("course.check", …)``. :func:`answers` gives every expected value (the trainer's answer
sheet); :func:`trainee_input` makes the different, deterministic motor a trainer hands to trainee
``n`` (``n = 0`` is the source document's motor).

Examples
--------
>>> inp = trainee_input(0)
>>> check(inp, "vendor-rpm", "15022")["state"]
'correct'
>>> check(inp, "vendor-rpm", 15023)["state"]
'wrong'
>>> answers(inp)["pi-pm-kp"]["expected"]
1180
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

from ..schema.errors import InputError
from ..schema.textnum import parse_int, parse_real
from ..schema.validate import shown

__all__ = ["EXERCISES", "EXAMPLE_ACIM", "EXAMPLE_HEADER", "BUGGY_RPM", "check", "answers", "trainee_input", "spec"]

#: The "find the bug" routine: the Rpm statement of the vendor code without its ``(Ulong)``
#: cast, so the product is computed in the 16-bit ``unsigned int`` of the C2000 and wraps.
BUGGY_RPM = """Uint16 Voltage, Current, RsPm;   // your motor's raw inputs
Uint16 m_UData, Rpm;
m_UData = ((Ulong)RsPm * (Ulong)Current)/Voltage;
Rpm = (m_UData * 18597)>>14;
"""


class _Ctx:
    """The report of one input, with the loop analysis and the tracer computed only when asked."""

    def __init__(self, inp: dict):
        from ..report import report, require_pmsm
        self.input = inp
        self.r = report(inp)
        require_pmsm(self.r["input"])  # a trainee's motor is a PMSM (the exercises read its firmware)
        self._loop = None
        self._trace = None
        self.fw = None
        self.obs = None
        self.acim = None
        self.audit = None

    def loop(self) -> dict:
        if self._loop is None:
            from ..report import report
            self._loop = report({**self.input, "analysis": {}})["loop"]
        return self._loop

    def trace(self) -> dict:
        if self._trace is None:
            from ..ctrace import trace
            raw = self.r["vendor"]["raw"]
            self._trace = trace(BUGGY_RPM, "c28x", {k: raw[k] for k in ("Voltage", "Current", "RsPm")})
        return self._trace


@dataclass(frozen=True)
class Exercise:
    """One exercise.

    ``kind``: ``int`` (an integer, within ``tol`` counts), ``real`` (within ``tol`` relative),
    ``choice`` (one of ``choices``), ``base`` (a base frequency the review accepts: any f_b from the
    rated frequency up to ``expected``, or 0 when none does). ``expected(ctx)`` reads the report;
    ``unit`` is shown.
    """
    id: str
    chapter: str
    kind: str
    expected: Callable[[_Ctx], object]
    tol: float = 0.0
    unit: str = ""
    choices: tuple = field(default=())


def _path(*keys) -> Callable[[_Ctx], object]:
    def get(c: _Ctx):
        v = c.r
        for k in keys:
            v = v[k]
        return v
    return get


def _first_fit(c: _Ctx) -> str:
    """The Uint16 Q format with the most fraction bits that holds ψ_r* (Q16 … Q12)."""
    psi = c.r["pu"]["psi_r"]
    return next((f"Q{q}" for q in (16, 15, 14, 13, 12) if round(psi * 2 ** q) <= 0xFFFF), "none")


#: The review's findings about the voltage at the base frequency (chapter 2's exercise removes them).
_FB_FINDINGS = ("voltage_fb", "voltage_bemf")
#: The largest base frequency the firmware's 0.01 Hz Uint16 FullFreq01 holds.
_FB_TOP = 655.35


def _fb_ok(c: _Ctx, f_b: float) -> bool:
    """Whether the review raises no voltage finding at base frequency ``f_b`` (its own report)."""
    from ..report import report
    r = report({**c.input, "drive": {**c.input.get("drive", {}), "base_freq_hz": f_b}})
    return not any(x["code"] in _FB_FINDINGS for x in r["review"]["findings"])


def _fb_max(c: _Ctx) -> float:
    """The largest base frequency ≥ f_n without a voltage finding (bisection on the review), or 0
    when even f_b = f_n has one (the motor needs more voltage at its rated point than the limit)."""
    lo = c.r["input"]["motor"]["rated_freq_hz"]
    if not _fb_ok(c, lo):
        return 0.0
    hi = _FB_TOP
    if _fb_ok(c, hi):
        return hi
    while hi - lo > 1e-9 * hi:
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if _fb_ok(c, mid) else (lo, mid)
    return lo


def _q12_int16(c: _Ctx) -> int:
    """A fault current of 8.5 p.u. stored as Q12 in an int16: the two's-complement wrap."""
    from ..fixedpoint.cint import INT16, wrap_to
    return wrap_to(round(8.5 * 4096), INT16)


def _ts_halved(c: _Ctx) -> str:
    """What pm_ki does when the control period is halved, read from two reports."""
    from ..report import report
    d = c.r["input"]["drive"]
    half = report({**c.input, "drive": {**c.input.get("drive", {}), "ts_s": d["ts_s"] / 2}})
    ratio = half["current_pi"]["d"]["pm_ki"] / c.r["current_pi"]["d"]["pm_ki"]
    return "halves" if abs(ratio - 0.5) < 0.05 else "doubles" if abs(ratio - 2) < 0.2 else "same"


def _line_trap(c: _Ctx) -> int:
    """pm_kp with the rated *line* voltage wrongly taken as U_b in eq. 2.2-9."""
    g, i_b = c.r["current_pi"]["d"], c.r["base"]["I_b"]
    return round(g["kp"] * i_b / c.r["input"]["motor"]["rated_voltage_v"] * 4096)


#: The board of the board exercises: TI's BOOSTXL-DRV8323RS current sensing (7 mΩ shunts, gain 10,
#: a bipolar 12-bit ADC at 3.3 V; its header prints 47.14285714 A full scale).
EXAMPLE_BOARD = {"current": {"shunt_ohm": 0.007, "gain": 10}}


def _board(c: _Ctx) -> dict:
    """The report's board chain of the trainee's motor on :data:`EXAMPLE_BOARD`."""
    from ..report import report
    return report({**c.input, "board": EXAMPLE_BOARD})["board"]["current"]


def _board_gain(c: _Ctx) -> float:
    """The gain that puts the rated peak current at 80 % of the example board's measurable range."""
    peak = math.sqrt(2.0) * c.r["input"]["motor"]["rated_current_a"]
    return EXAMPLE_BOARD["current"]["gain"] * 0.8 * _board(c)["max_a"] / peak


def _board_ti_kp(c: _Ctx) -> int:
    """TI's Kp_Iq when its per-unit current full scale is the example board's largest reading."""
    from ..report import report
    r = report({**c.input, "board": EXAMPLE_BOARD, "profiles": {}})
    return r["profiles"]["ti"]["constants"]["Kp_Iq"]["value"]


def _fw(c: _Ctx) -> dict:
    """The trainee motor's field-weakening section at the defaults (current limit √2·I_n, SVPWM),
    computed once per context (three exercises read it)."""
    if c.fw is None:
        from ..report import report
        c.fw = report({**c.input, "analysis": {"fw": {"points": 2, "table_points": 2}}})["fw"]
    return c.fw


def _obs(c: _Ctx) -> dict:
    """The trainee motor's report with ``observer: {}`` and the NXP and Microchip profiles (every
    default), computed once per context (four exercises read it)."""
    if c.obs is None:
        from ..report import report
        c.obs = report({**c.input, "observer": {}, "profiles": {"nxp": {}, "microchip": {}}})
    return c.obs


#: The induction motor of the induction-motor exercises: ST's public ACIM GUI example
#: (novaksta/MEZ-ACIM-FOC : Inc/acim_motor_parameters.h), 42 V phase, 1.5 A, 50 Hz, 1370 rpm.
EXAMPLE_ACIM = {"motor": {"kind": "acim", "rated_voltage_v": 42 * math.sqrt(3.0),
                          "rated_current_a": 1.5, "rated_freq_hz": 50, "rated_speed_rpm": 1370,
                          "pole_pairs": 2, "rs_ohm": 0.6, "rr_ohm": 0.4, "lls_h": 0.009,
                          "llr_h": 0.009, "lm_h": 0.0525, "magnetizing_current_a": 0.55},
                "drive": {"udc_v": 150, "ts_s": 1e-4}}


def _acim(*keys) -> Callable[[_Ctx], object]:
    """A value of :data:`EXAMPLE_ACIM`'s report with its simulation (every default; the same
    motor for every trainee)."""
    def get(c: _Ctx):
        if c.acim is None:
            from ..report import report
            c.acim = report({**EXAMPLE_ACIM, "sim": {}})
        v = c.acim
        for k in keys:
            v = v[k]
        return v
    return get


#: The numbers of a real generated header set: ST Motor Control Workbench's output for a
#: B-G431B-ESC1 drone drive (dronectl/g431-mcsdk : Inc/pmsm_motor_parameters.h,
#: drive_parameters.h, power_stage_parameters.h), written out as plain ``#define``s; the audit
#: exercises read them back (the same header for every trainee).
EXAMPLE_HEADER = (("st_workbench.h", "\n".join(f"#define {n} {v}" for n, v in (
    ("RS", 0.35), ("LS", 0.0006), ("POLE_PAIR_NUM", 2), ("MOTOR_VOLTAGE_CONSTANT", 4.0),
    ("MAX_APPLICATION_SPEED_RPM", 4000), ("NOMINAL_CURRENT", 870), ("PWM_FREQUENCY", 20000),
    ("REGULATION_EXECUTION_RATE", 1), ("RSHUNT", 0.003), ("AMPLIFICATION_GAIN", 9.14),
    ("ADC_REFERENCE_VOLTAGE", 3.3), ("NOMINAL_BUS_VOLTAGE_V", 24),
    ("PID_TORQUE_KP_DEFAULT", 2312), ("PID_TORQUE_KI_DEFAULT", 2158),
    ("PID_FLUX_KP_DEFAULT", 2312), ("PID_FLUX_KI_DEFAULT", 2158),
    ("TF_KPDIV", 128), ("TF_KIDIV", 4096))) + "\n"),)


def _audit(*keys) -> Callable[[_Ctx], object]:
    """A value of the audit of :data:`EXAMPLE_HEADER` (:func:`pulab.analyses.audit.audit`)."""
    def get(c: _Ctx):
        if c.audit is None:
            from .audit import audit
            c.audit = audit(list(EXAMPLE_HEADER))
        v = c.audit
        for k in keys:
            v = v[k]
        return v
    return get


EXERCISES: tuple[Exercise, ...] = (
    # day one, step 1: per-unit intuition
    Exercise("warmup-current", "00-warm-up", "real", lambda c: 2.0 / c.r["base"]["I_b"], 0.01),
    Exercise("warmup-ub", "00-warm-up", "real", _path("base", "U_b"), 0.01, "V"),
    Exercise("warmup-peak", "00-warm-up", "real", lambda c: math.sqrt(2) * c.r["base"]["I_b"], 0.01, "A"),
    Exercise("warmup-zb", "00-warm-up", "real", _path("base", "Z_b"), 0.01, "Ω"),
    Exercise("warmup-rs", "00-warm-up", "real", _path("pu", "Rs"), 0.01),
    Exercise("warmup-lb", "00-warm-up", "real", lambda c: c.r["base"]["L_b"] * 1e3, 0.01, "mH"),
    # step 2: Q formats and the C2000 integer rules
    Exercise("q-current", "04-q-format", "int", lambda c: round(2.0 / c.r["base"]["I_b"] * 4096), 1),
    Exercise("q-data1", "04-q-format", "int", _path("vendor", "pm_maxout_vol", "trace", 0, "value")),
    Exercise("q-maxout", "04-q-format", "int", _path("vendor", "pm_maxout_vol", "value")),
    Exercise("q-wrap", "04-q-format", "int", _q12_int16),
    Exercise("q-fit", "04-q-format", "choice", _first_fit,
             choices=("Q16", "Q15", "Q14", "Q13", "Q12", "none")),
    # step 3: the vendor code and its constants
    Exercise("vendor-mudata", "01-per-unit", "int", _path("vendor", "Rpm", "trace", 0, "value")),
    Exercise("vendor-rpm", "01-per-unit", "int", _path("vendor", "Rpm", "value")),
    Exercise("vendor-basel", "01-per-unit", "int", _path("vendor", "LD", "trace", 1, "value")),
    Exercise("vendor-ld", "01-per-unit", "int", _path("vendor", "LD", "value")),
    Exercise("vendor-bug", "01-per-unit", "int", lambda c: c.trace()["vars"]["Rpm"]["value"]),
    Exercise("vendor-flux", "01-per-unit", "int", _path("vendor", "FluxRotor", "value")),
    Exercise("const-18597", "05-constants", "real", _path("constants", "18597", "exact"), 1e-4),
    Exercise("const-3678", "05-constants", "real", _path("constants", "3678", "exact"), 1e-4),
    Exercise("const-2316", "05-constants", "real", _path("constants", "2316", "exact"), 1e-4),
    Exercise("const-ld-error", "05-constants", "real", _path("vendor", "LD", "error_pct"), 0.05, "%"),
    Exercise("const-freqper", "05-constants", "int", _path("vendor", "FreqPer", "value")),
    # step 4: the current PI
    Exercise("pi-kp-pu", "02-current-pi", "real", _path("current_pi", "d", "kp_pu"), 0.01),
    Exercise("pi-pm-kp", "02-current-pi", "int", _path("current_pi", "d", "pm_kp"), 1),
    Exercise("pi-pm-ki", "02-current-pi", "int", _path("current_pi", "d", "pm_ki"), 1),
    Exercise("pi-line-trap", "02-current-pi", "int", _line_trap, 1),
    Exercise("pi-ts-half", "02-current-pi", "choice", _ts_halved, choices=("halves", "same", "doubles")),
    Exercise("pi-choose-fb", "02-current-pi", "base", _fb_max, unit="Hz"),
    # step 5: the PLL
    Exercise("pll-kp", "03-pll", "real", _path("pll", "kp"), 0.01, "1/s"),
    Exercise("pll-kp-pu", "03-pll", "real", _path("pll", "kp_pu"), 0.01),
    Exercise("pll-int-gain", "03-pll", "real", _path("pll", "integrator_gain"), 0.01, "1/s"),
    Exercise("pll-naive-kts", "03-pll", "real",
             lambda c: c.r["pll"]["integrator_gain"] * c.r["pll"]["kp"] * c.r["input"]["drive"]["ts_s"], 0.01),
    Exercise("pll-naive-locks", "03-pll", "choice",
             lambda c: "yes" if c.loop()["pll"]["naive"]["stable"] else "no", choices=("yes", "no")),
    # reference: above base speed
    Exercise("fw-char", "08-loop-design", "real", lambda c: _fw(c)["characteristic_current_a"], 0.01, "A"),
    Exercise("fw-unbounded", "08-loop-design", "choice",
             lambda c: "yes" if _fw(c)["max_speed_rpm"] is None else "no", choices=("yes", "no")),
    Exercise("fw-base", "08-loop-design", "real", lambda c: _fw(c)["base_speed_rpm"], 0.01, "rpm"),
    # reference: sensorless, the observer and the lowest speed
    Exercise("obs-bemf-kp", "08-loop-design", "real",
             lambda c: _obs(c)["observer"]["design"]["bemf"]["kp_v_per_a"], 0.01, "V/A"),
    Exercise("obs-to-kp-shift", "08-loop-design", "int",
             lambda c: _obs(c)["profiles"]["nxp"]["constants"]["M1_TO_KP_SHIFT"]["value"]),
    Exercise("obs-mchp-kfilter", "08-loop-design", "int",
             lambda c: _obs(c)["profiles"]["microchip"]["constants"]["KFILTER_ESDQ"]["value"]),
    Exercise("obs-lowest", "08-loop-design", "real",
             lambda c: _obs(c)["observer"]["budget"]["min_speed_rpm"], 0.01, "rpm"),
    # reference: the board sets the scales
    Exercise("board-counts", "09-vendors", "real", lambda c: _board(c)["counts_per_a"], 0.01,
             "counts/A"),
    Exercise("board-pu", "09-vendors", "real", lambda c: _board(c)["pu_per_count"], 0.01),
    Exercise("board-gain", "09-vendors", "real", _board_gain, 0.01, "V/V"),
    Exercise("board-ti-kp", "09-vendors", "int", _board_ti_kp),
    # reference: a real generated header read back (EXAMPLE_HEADER, the same for every trainee)
    Exercise("audit-st-current", "09-vendors", "real", _audit("macros", "NOMINAL_CURRENT", "si"),
             0.01, "A"),
    Exercise("audit-st-zero", "09-vendors", "real",
             _audit("design", "current_loop", "q", "zero_rad_s"), 0.01, "rad/s"),
    Exercise("audit-st-pm", "09-vendors", "real",
             _audit("design", "current_loop", "q", "phase_margin_deg"), 0.01, "°"),
    # reference: induction motors, the same bases (the example motor EXAMPLE_ACIM)
    Exercise("acim-sigma", "06-conventions", "real", _acim("acim", "sigma"), 0.01),
    Exercise("acim-tau-r-pu", "06-conventions", "real", _acim("acim", "pu", "tau_r_s"), 0.01),
    Exercise("acim-pm-kp", "06-conventions", "int", _acim("current_pi", "d", "pm_kp"), 1),
    Exercise("acim-flux-95", "06-conventions", "real",
             _acim("sim", "flux", "metrics", "si", "flux_95_s"), 0.01, "s"),
)
_BY_ID = {e.id: e for e in EXERCISES}


def _tolerance(e: Exercise) -> dict:
    """The stated tolerance, as data and as text in both languages."""
    if e.kind == "choice":
        return {"kind": "exact", "en": "one choice", "zh": "单选"}
    if e.kind == "base":
        return {"kind": "range", "en": "any f_b from the rated frequency up to the largest (0 if none)",
                "zh": "从额定频率到最大值之间的任一 f_b（都不行时填 0）"}
    if e.kind == "int":
        if e.tol == 0:
            return {"kind": "exact", "value": 0, "en": "exact integer", "zh": "整数，须完全一致"}
        return {"kind": "abs", "value": e.tol, "en": f"integer, ±{e.tol:g}", "zh": f"整数，允许 ±{e.tol:g}"}
    if e.unit == "%":
        return {"kind": "abs", "value": e.tol, "en": f"±{e.tol:g} percentage points",
                "zh": f"允许 ±{e.tol:g} 个百分点"}
    return {"kind": "rel", "value": e.tol, "en": f"±{e.tol * 100:g} %", "zh": f"允许 ±{e.tol * 100:g} %"}


def spec() -> list:
    """Every exercise's id, chapter, kind, unit, choices and tolerance (for the page)."""
    return [{"id": e.id, "chapter": e.chapter, "kind": e.kind, "unit": e.unit,
             "choices": list(e.choices), "tolerance": _tolerance(e)} for e in EXERCISES]


def _exercise(ex_id) -> Exercise:
    e = _BY_ID.get(ex_id) if isinstance(ex_id, str) else None
    if e is None:
        raise InputError("id", code="unknown_exercise", got=shown(ex_id))
    return e


def _judge(e: Exercise, c: _Ctx, expected, answer) -> bool:
    field_ = f"exercise.{e.id}"
    if e.kind == "choice":
        if answer not in e.choices:
            raise InputError(field_, code="not_choice", choices=", ".join(e.choices), got=shown(answer))
        return answer == expected
    if answer is None or (isinstance(answer, str) and not answer.strip()):
        raise InputError(field_, code="required")
    if e.kind == "int":
        return abs(parse_int(answer, field_) - expected) <= e.tol
    a = parse_real(answer, field_)
    if e.kind == "base":
        if expected == 0:
            return a == 0
        return c.r["input"]["motor"]["rated_freq_hz"] <= a <= _FB_TOP and _fb_ok(c, a)
    if _tolerance(e)["kind"] == "abs":
        return abs(a - expected) <= e.tol
    return abs(a - expected) <= e.tol * abs(expected)


def check(inp: dict, ex_id: str, answer) -> dict:
    """Check one answer for the motor ``inp``.

    Parameters
    ----------
    inp : dict
        The report input (docs/contract.md) of the trainee's motor.
    ex_id : str
        An id of :data:`EXERCISES`.
    answer : str or number
        What the trainee typed (numbers as text are read like the form's fields) or chose.

    Returns
    -------
    dict
        ``id``, ``state`` (``correct`` | ``wrong``), ``expected`` (the report's value),
        ``tolerance`` (see :func:`spec`).

    Raises
    ------
    pulab.InputError
        ``exercise.ID`` for an unreadable answer, ``id`` for an unknown exercise, an input
        field for a bad motor.
    """
    e = _exercise(ex_id)
    c = _Ctx(inp)
    expected = e.expected(c)
    ok = _judge(e, c, expected, answer)
    return {"id": e.id, "state": "correct" if ok else "wrong", "expected": expected,
            "tolerance": _tolerance(e)}


def answers(inp: dict) -> dict:
    """Every exercise's expected answer for the motor ``inp``: ``{id: {chapter, expected, unit,
    tolerance}}`` (the trainer's answer sheet)."""
    c = _Ctx(inp)
    return {e.id: {"chapter": e.chapter, "expected": e.expected(c), "unit": e.unit,
                   "tolerance": _tolerance(e)} for e in EXERCISES}


#: Motor families a trainee can get: (rated line V, rated A, rated Hz, pole pairs, U_dc V).
_FAMILIES = ((17, 1.5, 220, 4, 24), (36, 10, 200, 4, 60), (200, 4.5, 100, 4, 311),
             (340, 12, 50, 2, 540), (24, 20, 300, 5, 48), (340, 30, 150, 4, 540))


def trainee_input(n: int) -> dict:
    """The motor of trainee ``n`` (0 … 9999): deterministic, in the firmware's own units (R in mΩ,
    L in 10 µH, I in 10 mA, E in 0.1 V), so a hand computation from the raw values is exact.

    ``n = 0`` is the source document's motor; others vary R_s*, L*, ψ* and T_s over realistic
    ranges around one of six families, with the drive's maximum frequency 1 … 2 times the rated one
    and a PLL bandwidth of 5 … 50 Hz.
    """
    if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= 9999:
        raise InputError("trainee", code="integer_range", lo=0, hi=9999, got=shown(n))
    if n == 0:
        return {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                          "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
                "drive": {"udc_v": 24, "ts_s": 0.0001}}
    u, i, f, p, udc = _FAMILIES[n % len(_FAMILIES)]
    # A small deterministic sequence (Knuth's multiplicative hash): the same n, the same motor.
    h = (n * 2654435761) % 2 ** 32
    frac = [((h >> s) & 0xFF) / 255 for s in (0, 8, 16, 24)]
    z_b = u / math.sqrt(3) / i
    w_b = 2 * math.pi * f
    rs = round(z_b * (0.02 + 0.2 * frac[0]), 3) or 0.001
    ld = round(z_b / w_b * (0.08 + 0.3 * frac[1]), 5) or 1e-5
    lq = round(ld * (1 + 0.5 * frac[2]), 5)
    bemf = round(u * (0.55 + 0.25 * frac[3]), 1)
    ts = (0.0001, 0.0000625, 0.000125, 0.00005)[(h >> 4) % 4]
    f_b = f * (1, 1.25, 1.5, 2)[(h >> 6) % 4]
    pll_hz = (50, 20, 10, 5)[(h >> 9) % 4]
    return {"motor": {"rated_voltage_v": u, "rated_current_a": i, "rated_freq_hz": f, "rs_ohm": rs,
                      "ld_h": ld, "lq_h": lq, "bemf_v": bemf, "pole_pairs": p},
            "drive": {"udc_v": udc, "ts_s": ts, "base_freq_hz": f_b},
            "pll": {"bandwidth_hz": pll_hz}}
