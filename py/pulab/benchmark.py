"""Benchmarks of the core, the same code in CPython and in Pyodide (prints numbers).

``PYTHONPATH=py python3 -m pulab.benchmark [--json]`` times :func:`pulab.report`
on every golden-style motor below (issue 2's target: under 5 ms per full report
in Pyodide) and the current-loop simulation (:mod:`pulab.sim.bench`; issue 3's
target: 20 000 steps of the three variants under 0.5 s in CPython, 1 s in
Pyodide).  The Pyodide runner (``tests/bench/pyodide.bench.ts``) calls
:func:`run` and prints the Pyodide/CPython ratio.
"""

from __future__ import annotations

import json
import sys
import time

__all__ = ["run", "report_timing", "loop_timing", "format_run", "MOTORS"]

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
    """Median milliseconds of the full report with the loop analysis and Bode data (issue 11).

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


def run(sim_steps: int = 20000) -> dict:
    """All core benchmarks: ``report_ms`` per motor, ``loop_ms`` and ``sim`` (pulab.sim.bench)."""
    from .sim.bench import bench
    return {"python": f"{sys.implementation.name} {sys.version.split()[0]}",
            "platform": sys.platform, "report_ms": report_timing(), "loop_ms": loop_timing(),
            "sim": bench(sim_steps)}


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
    return "\n".join(lines)


if __name__ == "__main__":
    result = run()
    print(json.dumps(result) if "--json" in sys.argv else format_run(result))
