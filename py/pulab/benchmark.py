"""Benchmarks of the core, the same code in CPython and in Pyodide (prints numbers).

``PYTHONPATH=py python3 -m pulab.benchmark [--json]`` times :func:`pulab.report`
on every golden-style motor below (target: under 5 ms per full report
in Pyodide) and the current-loop simulation (:mod:`pulab.analyses.sim.bench`;
target: 20 000 steps of the three variants under 0.5 s in CPython, 1 s in
Pyodide).  The Pyodide runner (``tests/bench/pyodide.bench.ts``) calls
:func:`run` and prints the Pyodide/CPython ratio.
"""

from __future__ import annotations

import json
import sys
import time

from .analyses.exercises import EXAMPLE_ACIM

__all__ = ["run", "report_timing", "loop_timing", "acim_timing", "ACIM", "trace_timing", "board_timing",
           "observer_timing", "audit_timing", "format_run", "MOTORS", "TRACE_SNIPPET", "TRACE_INPUTS"]

#: Motors of different sizes; timing differs little, but one motor would hide outliers.
MOTORS = {
    "seed 17 V": {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                            "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12,
                            "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}},
    "380 V 7.5 kW": {"motor": {"rated_voltage_v": 380, "rated_current_a": 15.5,
                               "rated_freq_hz": 50, "rs_ohm": 0.45, "ld_h": 8e-3,
                               "lq_h": 1.4e-2, "bemf_v": 330, "pole_pairs": 2},
                     "drive": {"udc_v": 540, "ts_s": 1e-4}},
    "690 V": {"motor": {"rated_voltage_v": 690, "rated_current_a": 112, "rated_freq_hz": 50,
                        "rs_ohm": 0.05, "ld_h": 2e-3, "lq_h": 2e-3, "bemf_v": 600,
                        "pole_pairs": 3}, "drive": {"udc_v": 1000, "ts_s": 2e-4}},
}


def report_timing(n: int = 200) -> dict:
    """Mean milliseconds per :func:`pulab.report` call for each motor (n calls each)."""
    from .report import report
    out = {}
    for name, inp in MOTORS.items():
        report(inp)  # warm-up: first call imports lazily
        t0 = time.perf_counter()
        for _ in range(n):
            report(inp)
        out[name] = (time.perf_counter() - t0) / n * 1e3
    return out


def loop_timing(n: int = 30) -> dict:
    """Median milliseconds of the full report with the loop analysis and Bode data.

    ``"analysis": {"bode": true}`` on every motor: margins, poles, bandwidth of the current
    loop (design gains, firmware integers, delay-aware design and the continuous design),
    both PLLs, and 400 points per Bode curve (12 curves).  Target: ≤ 20 ms in Pyodide.
    """
    from .report import report
    out = {}
    for name, inp in MOTORS.items():
        inp = {**inp, "analysis": {"bode": True}}
        report(inp)
        times = []
        for _ in range(n):
            t0 = time.perf_counter()
            report(inp)
            times.append((time.perf_counter() - t0) * 1e3)
        out[name] = sorted(times)[n // 2]
    return out


#: The tracer's benchmark: 30 lines of firmware scaling code (the seed's blocks, one scope).
TRACE_SNIPPET = """\
Uint16 gMotorExtInfo.RsPm, gMotorInfo.Current, gMotorInfo.Voltage, gBasePar.FullFreq01;
Uint16 gMotorExtInfo.LD, gMotorInfo.FreqRated01, gMotorExtInfo.BemfVolt, gUDC.uDCFilter;
Uint16 gMotorExtPer.Rpm, gMotorExtPer.LD, gMotorInfo.FreqPer, gMotorExtPer.FluxRotor;
Ulong m_UData, m_BaseL, m_Ulong;
long data1, pm_maxout_vol, maxu, minu, pm_ud;
long pm_integral_d, pm_error_id, pm_kp_d, pm_ki_d;
m_UData = ((Ulong)gMotorExtInfo.RsPm * (Ulong)gMotorInfo.Current)/gMotorInfo.Voltage;
gMotorExtPer.Rpm = ((Ulong)m_UData * 18597)>>14;
m_BaseL = ((Ulong)gMotorInfo.Voltage * 3678)/gMotorInfo.Current;
m_BaseL = ((Ulong)m_BaseL * 5000)/gBasePar.FullFreq01; //Q15
m_Ulong = ((Ulong)gMotorExtInfo.LD <<14) + (m_BaseL >>1);
m_Ulong = m_Ulong / m_BaseL;
gMotorExtPer.LD = m_Ulong / 10; // Q13
gMotorInfo.FreqPer = ((Ulong)gMotorInfo.FreqRated01<<15)/gBasePar.FullFreq01;
m_Ulong = ((Long)gMotorExtInfo.BemfVolt <<12) / (gMotorInfo.Voltage *10); //Q12
gMotorExtPer.FluxRotor = (m_Ulong << 15) / gMotorInfo.FreqPer; //Q12
data1 = ((long)gUDC.uDCFilter * 2316L)>>15; // Udc/sqrt(2)/10
pm_maxout_vol = (data1<<12)/gMotorInfo.Voltage;
maxu = (long)pm_maxout_vol<<12;
minu = -maxu;
pm_error_id = 410;
pm_kp_d = 1000;
pm_ki_d = 3000;
pm_integral_d = 0;
pm_integral_d = pm_integral_d + (pm_error_id * pm_ki_d >> 4); //Q24,28-4
pm_integral_d = __IQsat(pm_integral_d, maxu, minu);
data1 = (pm_integral_d + pm_error_id * pm_kp_d)>>12;
data1 = __IQsat(data1, pm_maxout_vol, -pm_maxout_vol);
pm_ud = data1;
pm_ud = _IQmpy(pm_ud << 12, 16777216L / 3) >> 12;
"""
#: The seed motor's raw integers (seed 1.4-1 … 1.4-7).
TRACE_INPUTS = {"gMotorExtInfo.RsPm": 1500, "gMotorInfo.Current": 150, "gMotorInfo.Voltage": 17,
                "gBasePar.FullFreq01": 22000, "gMotorExtInfo.LD": 60,
                "gMotorInfo.FreqRated01": 22000, "gMotorExtInfo.BemfVolt": 120,
                "gUDC.uDCFilter": 240}


#: A 60-line translation unit as firmware keeps it: a PI handle typedef, an inline clamp,
#: Clarke/Park with out-parameters, a lookup table walked by a loop, one entry function.
TRACE_UNIT = """#include <stdint.h>
#define ONE_BY_SQRT3_Q15 18919
typedef struct
{
  int16_t kp;
  int16_t ki;
  int32_t integral;
  int32_t upper, lower;
  uint16_t kp_shift, ki_shift;
} pi_t;
typedef struct { int16_t a, b; } ab_t;
typedef struct { int16_t d, q; } dq_t;
static const int16_t sin_tab[8] = {0, 12540, 23170, 30274, 32767, 30274, 23170, 12540};

static inline int32_t clamp32(int32_t v, int32_t lo, int32_t hi)
{
  if (v > hi) return hi;
  if (v < lo) return lo;
  return v;
}

static int16_t pi_run(pi_t *p, int16_t err)
{
  int32_t prop = (int32_t)p->kp * err;
  int32_t step = (int32_t)p->ki * err;
  if (step != 0)
  {
    p->integral = clamp32(p->integral + step, p->lower, p->upper);
  }
  return (int16_t)clamp32((prop >> p->kp_shift) + (p->integral >> p->ki_shift), -32768, 32767);
}

static void clarke(int16_t ia, int16_t ib, ab_t *out)
{
  out->a = ia;
  out->b = (int16_t)((((int32_t)ia + 2 * (int32_t)ib) * ONE_BY_SQRT3_Q15) >> 15);
}

static void park(const ab_t *in, uint16_t angle, dq_t *out)
{
  int16_t s = sin_tab[angle & 7];
  int16_t c = sin_tab[(angle + 2) & 7];
  out->d = (int16_t)(((int32_t)in->a * c + (int32_t)in->b * s) >> 15);
  out->q = (int16_t)(((int32_t)in->b * c - (int32_t)in->a * s) >> 15);
}

int16_t current_loop(pi_t *pid, pi_t *piq, int16_t ia, int16_t ib, uint16_t angle,
                     int16_t id_ref, int16_t iq_ref, int16_t *vd)
{
  ab_t ab;
  dq_t dq;
  uint16_t k;
  int32_t energy = 0;
  clarke(ia, ib, &ab);
  park(&ab, angle, &dq);
  for (k = 0; k < 4; k++)
  {
    energy += ((int32_t)sin_tab[k] * dq.q) >> 15;
  }
  *vd = pi_run(pid, (int16_t)(id_ref - dq.d));
  return pi_run(piq, (int16_t)(iq_ref - dq.q + (int16_t)(energy >> 4)));
}
"""
TRACE_UNIT_INPUTS = {"ia": 1200, "ib": -700, "angle": 5, "id_ref": 0, "iq_ref": 3000,
                     **{f"{p}.{k}": v for p in ("pid", "piq") for k, v in (
                         ("kp", 9000), ("ki", 300), ("integral", -40000), ("upper", 1 << 24),
                         ("lower", -(1 << 24)), ("kp_shift", 12), ("ki_shift", 10))}}


def _timing(n: int, fn) -> dict:
    fn()  # warm-up: imports
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        times.append((time.perf_counter() - t0) * 1e3)
    times.sort()
    return {"median_ms": times[n // 2], "p95_ms": times[int(n * 0.95)], "min_ms": times[0]}


def _sequence_rows(calls: int) -> list:
    """A sequence's per-call inputs for :data:`TRACE_UNIT`: the phase currents and the angle
    of each control period (the PI handles and references are set once, before call 0)."""
    return [{"ia": 1200 - (k * 37) % 2400, "ib": -700 + (k * 53) % 1400, "angle": k % 1024}
            for k in range(calls)]


#: The same periods' inputs generated (:mod:`pulab.ctrace.generate`): two phase currents 120°
#: apart with noise on neither, the angle a ramp.
SEQUENCE_GEN = {"ia": "sine:amp=1200,period=200", "ib": "sine:amp=1200,period=200,phase=-120",
                "angle": "ramp:start=0,slope=1"}


def trace_timing(n: int = 200, calls: int = 1000, runs: int = 5) -> dict:
    """Median, p95 and minimum milliseconds to parse, type and trace :data:`TRACE_SNIPPET`
    (c28x), and ``unit``: the same for :data:`TRACE_UNIT` through its entry function, both
    compiled anew each time; ``unit_again``: the unit traced again with other inputs (the
    compiled program reused, as the page and a sequence do); ``sequence``: median, minimum
    seconds of ``calls`` calls of the unit with per-call inputs (``runs`` runs);
    ``sequence_gen``: the same with the inputs generated (:data:`SEQUENCE_GEN`).  The
    minimum is what the code costs when no other process takes the CPU."""
    from .ctrace import trace, tracing
    from .ctrace.sequence import trace_sequence

    def cold(fn):
        def run():
            tracing._COMPILED.clear()
            fn()
        return run

    out = {"lines": TRACE_SNIPPET.count("\n"),
           **_timing(n, cold(lambda: trace(TRACE_SNIPPET, "c28x", TRACE_INPUTS)))}
    def unit():
        trace(TRACE_UNIT, "c28x", TRACE_UNIT_INPUTS, entry="current_loop")

    out["unit"] = {"lines": TRACE_UNIT.count("\n"), **_timing(n, cold(unit))}
    out["unit_again"] = _timing(n, unit)
    rows = _sequence_rows(calls)
    seq = _timing(runs, lambda: trace_sequence(TRACE_UNIT, "c28x", calls, rows,
                                               TRACE_UNIT_INPUTS, entry="current_loop"))
    out["sequence"] = {"calls": calls, "median_s": seq["median_ms"] / 1e3,
                       "min_s": seq["min_ms"] / 1e3}
    seq = _timing(runs, lambda: trace_sequence(TRACE_UNIT, "c28x", calls, None,
                                               TRACE_UNIT_INPUTS, entry="current_loop",
                                               gen=SEQUENCE_GEN))
    out["sequence_gen"] = {"calls": calls, "median_s": seq["median_ms"] / 1e3,
                           "min_s": seq["min_ms"] / 1e3}
    return out


#: TI's BOOSTXL-DRV8323RS on a 100 MHz F28004x: every chain of the board section.
BOARD = {"current": {"shunt_ohm": 0.007, "gain": 10}, "bus": {"r_top_ohm": 82e3, "r_bottom_ohm": 4.99e3},
         "pwm": {"clock_hz": 100e6, "freq_hz": 1e4, "deadtime_s": 2e-7}}


def _paired(plain: dict, extra: dict, n: int) -> dict:
    """Median milliseconds of ``report(plain)`` and ``report(plain + extra)``, measured
    interleaved (one of each per round, so load hits both alike), and their ratio."""
    from .report import report
    other = {**plain, **extra}
    report(plain), report(other)
    a, b = [], []
    for _ in range(n):
        for inp, out in ((plain, a), (other, b)):
            t0 = time.perf_counter()
            report(inp)
            out.append((time.perf_counter() - t0) * 1e3)
    a.sort(), b.sort()
    return {"without_ms": a[n // 2], "with_ms": b[n // 2], "ratio": b[n // 2] / a[n // 2]}


def board_timing(n: int = 200) -> dict:
    """The seed motor's report with every profile, without and with :data:`BOARD`
    (:func:`_paired`; target ratio ≤ 1.3)."""
    return _paired({**MOTORS["seed 17 V"], "profiles": {}}, {"board": BOARD}, n)


def observer_timing(n: int = 200) -> dict:
    """The seed motor's report with every profile, without and with ``observer: {}`` (design,
    budget and NXP's sensorless integers; :func:`_paired`, target ratio ≤ 1.3)."""
    return _paired({**MOTORS["seed 17 V"], "profiles": {}}, {"observer": {}}, n)


#: An induction motor (ST's public ACIM GUI example), with the loop analysis and a speed loop.
ACIM = {**EXAMPLE_ACIM, "analysis": {"speed": {"inertia_kg_m2": 1e-3}}}


def acim_timing(n: int = 30) -> dict:
    """Median milliseconds of an induction motor's report, plain and with the loop analysis
    (a speed loop and the flux build-up's 10·τ_r of TI's fixed-point model: ≈ 15 000 periods);
    the plain report's target is the PMSM's: under 5 ms in Pyodide."""
    from .report import report
    out = {}
    for name, inp in (("plain", {k: v for k, v in ACIM.items() if k != "analysis"}),
                      ("loop", ACIM)):
        report(inp)
        times = []
        for _ in range(n):
            t0 = time.perf_counter()
            report(inp)
            times.append((time.perf_counter() - t0) * 1e3)
        out[name] = sorted(times)[n // 2]
    return out


def audit_timing(n: int = 20) -> dict:
    """Median and minimum milliseconds to audit a generated ST set (target ≤ 200 ms in CPython,
    ≤ 1 s in Pyodide): pu-lab's own ST header, whose macros match the MCSDK files', repeated
    as four files of 150 macros each (the size of a Workbench set, ~600 macros)."""
    from . import profiles
    from .analyses.audit import audit
    from .report import report
    text = profiles.header(report({**MOTORS["seed 17 V"], "profiles": {}}), "st")
    body = [ln for ln in text.splitlines() if ln.startswith("#define") and "ADC_REF" not in ln]
    files = [(f"st{k}.h", "\n".join(body) + "\n" + "\n".join(
        f"#define EXTRA_{k}_{j} ((int16_t)(RS*{j}/LS) + {j}u)" for j in range(150 - len(body))))
        for k in range(4)]
    out = {"macros": sum(f[1].count("#define") for f in files), **_timing(n, lambda: audit(files))}
    return out


def run(sim_steps: int = 20000) -> dict:
    """All core benchmarks: ``report_ms`` per motor, ``loop_ms``, ``sim`` (see pulab.analyses.sim.bench),
    ``trace``."""
    from .analyses.sim.bench import bench
    return {"python": f"{sys.implementation.name} {sys.version.split()[0]}",
            "platform": sys.platform, "report_ms": report_timing(), "loop_ms": loop_timing(),
            "sim": bench(sim_steps), "trace": trace_timing(), "board": board_timing(),
            "observer": observer_timing(), "acim_ms": acim_timing(), "audit": audit_timing()}


def format_run(r: dict) -> str:
    """Readable lines of :func:`run`'s result."""
    lines = [f"pulab core benchmark in {r['python']} ({r['platform']}):"]
    for name, ms in r["report_ms"].items():
        lines.append(f"  report(), {name:<13} {ms:7.3f} ms per call  (target < 5 ms in Pyodide)")
    for name, ms in r.get("loop_ms", {}).items():
        lines.append(f"  report() + loop analysis + Bode, {name:<13} {ms:7.3f} ms median  "
                     f"(target ≤ 20 ms in Pyodide)")
    if "board" in r:
        b = r["board"]
        lines.append(f"  report() with every profile, seed motor: {b['without_ms']:.3f} ms median, with a "
                     f"board {b['with_ms']:.3f} ms = {b['ratio']:.3f}× (target ≤ 1.3×)")
    if "observer" in r:
        o = r["observer"]
        lines.append(f"  report() with every profile, seed motor, with observer {{}}: "
                     f"{o['with_ms']:.3f} ms median = {o['ratio']:.3f}× (target ≤ 1.3×)")
    if "acim_ms" in r:
        a = r["acim_ms"]
        lines.append(f"  report(), induction motor: {a['plain']:.3f} ms median; with the loop "
                     f"analysis, a speed loop and the flux build-up {a['loop']:.3f} ms "
                     f"(target < 5 ms plain in Pyodide)")
    if "audit" in r:
        d = r["audit"]
        lines.append(f"  audit(): an ST set of {d['macros']} macros in {d['median_ms']:.1f} ms "
                     f"median, {d['min_ms']:.1f} ms min (target ≤ 200 ms CPython, ≤ 1 s Pyodide)")
    s = r["sim"]
    lines.append(f"  sim: {s['steps']} steps × 7 variants (si, pu, fixed; ti, nxp, st, microchip) "
                 f"in {s['total_s']:.3f} s = {s['steps_per_s']:.0f} steps/s (target < 0.5 s "
                 f"CPython, < 1 s Pyodide); fixed variant without memo {s['fixed_no_memo_s']:.3f} s"
                 f", the four vendors {s['vendors_s']:.3f} s")
    if "trace" in r:
        t = r["trace"]
        lines.append(f"  trace(): {t['lines']}-line snippet parsed and traced in "
                     f"{t['median_ms']:.2f} ms median, {t['p95_ms']:.2f} ms p95, "
                     f"{t.get('min_ms', float('nan')):.2f} ms min (target ≤ 5 ms in Pyodide)")
        if "unit" in t:
            u = t["unit"]
            lines.append(f"  trace(): {u['lines']}-line unit (structs, calls, a loop) through its "
                         f"entry in {u['median_ms']:.2f} ms median, {u['p95_ms']:.2f} ms p95, "
                         f"{u['min_ms']:.2f} ms min (target ≤ 5 ms in CPython)")
        if "unit_again" in t:
            a = t["unit_again"]
            lines.append(f"  trace(): the same unit again, compiled program reused, "
                         f"{a['median_ms']:.2f} ms median, {a['p95_ms']:.2f} ms p95, "
                         f"{a['min_ms']:.2f} ms min (target ≤ 5 ms CPython, ≤ 20 ms Pyodide)")
        if "sequence" in t:
            q = t["sequence"]
            lines.append(f"  trace sequence: {q['calls']} calls of the unit with per-call "
                         f"inputs in {q['median_s']:.3f} s median, {q['min_s']:.3f} s min "
                         f"(target ≤ 2 s in CPython)")
        if "sequence_gen" in t:
            q = t["sequence_gen"]
            lines.append(f"  trace sequence, inputs generated (sine, ramp): {q['calls']} calls "
                         f"in {q['median_s']:.3f} s median, {q['min_s']:.3f} s min "
                         f"(target ≤ 2 s in CPython)")
    return "\n".join(lines)


if __name__ == "__main__":
    result = run()
    print(json.dumps(result) if "--json" in sys.argv else format_run(result))
