"""Benchmarks of the family view, medians printed (numbers, not tests).

    PYTHONPATH=py python3 tests/bench/family_bench.py     # CPython: sweep and 10,000-row batch

``tests/bench/family.bench.ts`` runs :func:`sweep_timing` of this file in Pyodide/Node.
Targets: a 1,000-point sweep ≤ 1 s in Pyodide; a 10,000-row batch ≤ 10 s in CPython.
"""

from __future__ import annotations

import statistics
import time

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}
SWEEPS = {
    "1-D current 1–200 A, 1000 points": {
        "x": {"path": "motor.rated_current_a", "start": 1, "stop": 200, "n": 1000}},
    "1-D voltage 0.1–1000 V log, 1000 points": {
        "x": {"path": "motor.rated_voltage_v", "start": 0.1, "stop": 1000, "n": 1000,
              "scale": "log"}},
    "2-D voltage × current 40 × 25 log": {
        "x": {"path": "motor.rated_voltage_v", "start": 1, "stop": 400, "n": 40, "scale": "log"},
        "y": {"path": "motor.rated_current_a", "start": 0.5, "stop": 300, "n": 25,
              "scale": "log"}},
}


def _median(f, repeat: int) -> tuple:
    """(wall, CPU) medians in seconds; on a shared machine the CPU time is the fairer number."""
    from pulab.analyses import integers
    f()  # warm-up (lazy imports)
    wall, cpu = [], []
    for _ in range(repeat):
        integers._MEMO.clear()  # each run as the first sweep of its motor, not a repeat
        t0, c0 = time.perf_counter(), time.process_time()
        f()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return statistics.median(wall), statistics.median(cpu)


def sweep_timing(repeat: int = 5) -> dict:
    """(wall, CPU) median seconds of each sweep in :data:`SWEEPS` (whole, with boundaries)."""
    from pulab.analyses.sweep import sweep
    return {name: _median(lambda req=req: sweep({"input": SEED, **req}), repeat)
            for name, req in SWEEPS.items()}


def batch_timing(rows: int = 10_000, repeat: int = 3) -> tuple:
    """(wall, CPU) median seconds of ``pulab batch`` on ``rows`` synthetic motors (text → CSV)."""
    import pathlib
    import sys
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "data"))
    from make_catalogue import synthetic, to_csv
    from pulab.analyses.batch import batch_csv
    text = to_csv(synthetic(rows))
    return _median(lambda: batch_csv(text), repeat)


def format_sweeps(t: dict, runtime: str) -> str:
    return "\n".join(f"  sweep in {runtime}, {name}: median {w:.3f} s wall, {c:.3f} s CPU "
                     "(target ≤ 1 s in Pyodide)" for name, (w, c) in t.items())


if __name__ == "__main__":
    import platform
    runtime = f"CPython {platform.python_version()}"
    print(f"family view benchmark ({runtime}):")
    print(format_sweeps(sweep_timing(), runtime))
    w, c = batch_timing()
    print(f"  batch in {runtime}, 10,000 rows: median {w:.2f} s wall, {c:.2f} s CPU (target ≤ 10 s)")
