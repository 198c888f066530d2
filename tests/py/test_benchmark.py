"""pulab.benchmark: the benchmark's motors are valid inputs and a short run yields every number
the printout shows (timings are printed by the benchmark itself, never asserted here)."""
import math

from pulab import report
from pulab.benchmark import MOTORS, TRACE_SNIPPET, format_run, loop_timing, report_timing, trace_timing
from pulab.analyses.sim.bench import bench


def test_every_benchmark_motor_is_a_valid_report_input():
    for name, inp in MOTORS.items():
        r = report(inp)
        assert r["vendor"]["raw"] and r["current_pi"]["d"]["pm_kp"] > 0, name


def test_a_short_run_formats_every_number():
    r = {"python": "cpython", "platform": "test", "report_ms": report_timing(2),
         "loop_ms": loop_timing(1), "sim": bench(200), "trace": trace_timing(2, 3, 1)}
    assert set(r["report_ms"]) == set(MOTORS)
    numbers = [*r["report_ms"].values(), *r["loop_ms"].values(), r["sim"]["total_s"],
               r["trace"]["median_ms"], r["trace"]["p95_ms"], r["trace"]["unit_again"]["median_ms"],
               r["trace"]["sequence"]["median_s"], r["trace"]["sequence_gen"]["median_s"]]
    assert all(math.isfinite(x) and x > 0 for x in numbers), numbers
    assert r["trace"]["lines"] == len(TRACE_SNIPPET.strip().splitlines())
    text = format_run(r)
    assert all(name in text for name in MOTORS) and "nan" not in text
    assert "trace sequence: 3 calls of the unit" in text and "compiled program reused" in text
    assert "inputs generated (sine, ramp): 3 calls" in text
