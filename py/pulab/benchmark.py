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

__all__ = ["run", "report_timing", "loop_timing", "trace_timing", "format_run", "MOTORS",
           "TRACE_SNIPPET", "TRACE_INPUTS"]

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


def trace_timing(n: int = 200) -> dict:
    """Median, p95 and minimum milliseconds to parse, type and trace :data:`TRACE_SNIPPET`
    (c28x); the minimum is what the code costs when no other process takes the CPU."""
    from .ctrace import trace
    trace(TRACE_SNIPPET, "c28x", TRACE_INPUTS)  # warm-up: imports
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        trace(TRACE_SNIPPET, "c28x", TRACE_INPUTS)
        times.append((time.perf_counter() - t0) * 1e3)
    times.sort()
    return {"lines": TRACE_SNIPPET.count("\n"), "median_ms": times[n // 2],
            "p95_ms": times[int(n * 0.95)], "min_ms": times[0]}


def run(sim_steps: int = 20000) -> dict:
    """All core benchmarks: ``report_ms`` per motor, ``loop_ms``, ``sim`` (see pulab.analyses.sim.bench),
    ``trace``."""
    from .analyses.sim.bench import bench
    return {"python": f"{sys.implementation.name} {sys.version.split()[0]}",
            "platform": sys.platform, "report_ms": report_timing(), "loop_ms": loop_timing(),
            "sim": bench(sim_steps), "trace": trace_timing()}


def format_run(r: dict) -> str:
    """Readable lines of :func:`run`'s result."""
    lines = [f"pulab core benchmark in {r['python']} ({r['platform']}):"]
    for name, ms in r["report_ms"].items():
        lines.append(f"  report(), {name:<13} {ms:7.3f} ms per call  (target < 5 ms in Pyodide)")
    for name, ms in r.get("loop_ms", {}).items():
        lines.append(f"  report() + loop analysis + Bode, {name:<13} {ms:7.3f} ms median  "
                     f"(target ≤ 20 ms in Pyodide)")
    s = r["sim"]
    lines.append(f"  sim: {s['steps']} steps × 3 variants in {s['total_s']:.3f} s = "
                 f"{s['steps_per_s']:.0f} steps/s (target < 0.5 s CPython, < 1 s Pyodide); "
                 f"fixed variant without memo {s['fixed_no_memo_s']:.3f} s")
    if "trace" in r:
        t = r["trace"]
        lines.append(f"  trace(): {t['lines']}-line snippet parsed and traced in "
                     f"{t['median_ms']:.2f} ms median, {t['p95_ms']:.2f} ms p95, "
                     f"{t.get('min_ms', float('nan')):.2f} ms min (target ≤ 5 ms in Pyodide)")
    return "\n".join(lines)


if __name__ == "__main__":
    result = run()
    print(json.dumps(result) if "--json" in sys.argv else format_run(result))
