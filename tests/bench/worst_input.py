"""The work bomb: the worst input the contract allows, timed and measured.

Both simulations at their period caps (200 000 current-loop and 500 000 PLL
periods), ``pm_kp = pm_ki = 2^31 − 1``.  Each run is a fresh process so its
peak resident memory is its own; prints the median time and the peak.

``python3 tests/bench/worst_input.py [runs]`` (from the repository root).
"""
import json
import pathlib
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
WORST = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                   "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
         "drive": {"udc_v": 24, "ts_s": 1e-4},
         "current_loop": {"method": "integers", "pm_kp": 2 ** 31 - 1, "pm_ki": 2 ** 31 - 1},
         "sim": {"current": {"duration_s": 200_000 * 1e-4}, "pll": {"duration_s": 500_000 * 1e-4}}}

CHILD = """
import json, resource, sys, time
from pulab.api import call_json
text = sys.stdin.read()
t0 = time.perf_counter()
out = json.loads(call_json("report", text))
assert out["ok"], out
print(json.dumps({"s": time.perf_counter() - t0,
                  "mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def main(runs: int = 3) -> None:
    results = []
    for _ in range(runs):
        p = subprocess.run([sys.executable, "-c", CHILD], input=json.dumps(WORST), text=True,
                           capture_output=True, check=True, env={"PYTHONPATH": str(ROOT / "py")})
        results.append(json.loads(p.stdout))
    print(f"worst allowed input (sim caps, pm_kp = pm_ki = 2^31-1) in {sys.implementation.name} "
          f"{sys.version.split()[0]}: median {statistics.median(r['s'] for r in results):.2f} s, "
          f"peak {max(r['mb'] for r in results):.0f} MB (max RSS), {runs} runs")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
