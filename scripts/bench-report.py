"""CPython side of `npm run bench`: pulab.report() per call, and pulab.sim.bench when present.

Prints one JSON line: {"report_ms": ..., "sim": {...}|null}. Shared with the Pyodide runner
(scripts/bench-pyodide.mjs runs the same code inside Pyodide).
"""
import json
import time

from pulab.api import run_json

SEED = json.dumps({
    "motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220, "rs_ohm": 1.5,
              "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
    "drive": {"udc_v": 24, "ts_s": 1e-4},
})


def bench_report(n=300):
    run_json(SEED)
    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        for _ in range(n):
            run_json(SEED)
        best = min(best, (time.perf_counter() - t0) / n)
    return best * 1e3


def main():
    out = {"report_ms": bench_report(), "sim": None}
    try:
        from pulab.sim.bench import bench
        out["sim"] = bench(20000, 2)
    except ImportError:
        pass
    return json.dumps(out)


if __name__ == "__main__":
    print(main())
