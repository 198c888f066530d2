"""Benchmark of code proofs: a 35-line PI routine (tests/bench/pi_step.c) with six ranged
inputs, on a 16-bit-int and a 32-bit-int target; medians printed (numbers, not tests).

    PYTHONPATH=py python3 tests/bench/code_prove_bench.py

``tests/bench/code-prove.bench.ts`` runs :func:`code_prove_timing` of this file in Pyodide/Node.
"""

from __future__ import annotations

import os
import pathlib
import statistics
import sys
import time

try:
    CODE = (pathlib.Path(__file__).parent / "pi_step.c").read_text()
except NameError:  # run as text in Pyodide: the caller sets CODE
    CODE = None

NOMINAL = {"ref": [-32768, 32767], "fb": [-32768, 32767], "p.kp": [0, 16384],
           "p.ki": [0, 4096], "p.integ": [-32767, 32767], "p.out_max": [1000, 32767]}
# The integrator state over all of int32 and a limit that may be -32768: the sum overflows
# and -hi does not fit int16.
WIDE = {**NOMINAL, "p.integ": [-2 ** 31, 2 ** 31 - 1], "p.out_max": [-32768, 32767]}
CASES = {f"PI {name} on {target}": (target, box) for name, box in (("nominal", NOMINAL),
                                                                  ("wide", WIDE))
         for target in ("c28x", "arm")}
#: A loop whose count is an input: the box is split down to each count (81 boxes).
LOOP = """int32_t acc(int16_t x, int16_t n) {
  int32_t s = 0;
  for (int16_t i = 0; i < n; i++)
    s += x;
  return s;
}"""
LOOP_BOX = {"x": [-1000, 1000], "n": [0, 80]}


def code_prove_timing(code: str | None = None, repeat: int = 7) -> dict:
    """{case: (wall median s, CPU median s, verdict, statements, work)} for :data:`CASES` and
    the loop."""
    from pulab.ctrace.prove import prove_code
    code = code or CODE
    out = {}
    runs = {name: (code, target, "pi_step", box) for name, (target, box) in CASES.items()}
    runs["loop of 0..80 on arm"] = (LOOP, "arm", "acc", LOOP_BOX)
    for name, (src, target, entry, box) in runs.items():
        r = prove_code(src, target, entry, box, budget=4000)  # warm-up
        wall, cpu = [], []
        for _ in range(repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            prove_code(src, target, entry, box, budget=4000)
            wall.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        counts = {}
        for s in r["statements"]:
            counts[s["verdict"]] = counts.get(s["verdict"], 0) + 1
        out[name] = (statistics.median(wall), statistics.median(cpu), r["verdict"], counts,
                     r["work"])
    return out


def format_code_proofs(t: dict) -> str:
    # Pyodide's os.getloadavg answers a constant: the machine's load is the CPython run's line.
    load = os.getloadavg() if hasattr(os, "getloadavg") and sys.platform != "emscripten" else None
    lines = [f"  {name}: median {w * 1000:.1f} ms wall, {c * 1000:.1f} ms CPU; {v} "
             f"({', '.join(f'{n} {k}' for k, n in sorted(counts.items()))}), {work} runs"
             for name, (w, c, v, counts, work) in t.items()]
    if load is not None:
        lines.append(f"  machine load (1/5/15 min): {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
                     f"on {os.cpu_count()} cores")
    return "\n".join(lines)


if __name__ == "__main__":
    import platform
    print(f"code proof benchmark (CPython {platform.python_version()}, 6 ranged inputs):")
    print(format_code_proofs(code_prove_timing()))
