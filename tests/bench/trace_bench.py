"""The tracer on its 60-line unit (pulab.benchmark.TRACE_UNIT) in CPython, with the load.

    PYTHONPATH=py .venv/bin/python tests/bench/trace_bench.py [--before REV] [--rounds N]

Each round runs a batch of traces in a fresh interpreter per build (this tree, and with
``--before`` the ``py/`` of git revision REV), alternating, so both builds meet the same load
on a shared machine; prints each build's median, p95 and minimum over all rounds with the
1-minute load average before and after.
"""

from __future__ import annotations

import argparse
import io
import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

_BATCH = r"""
import json, sys, time
from pulab.benchmark import TRACE_UNIT, TRACE_UNIT_INPUTS
from pulab.ctrace import trace
run = lambda: trace(TRACE_UNIT, "c28x", TRACE_UNIT_INPUTS, entry="current_loop")
run()
times = []
for _ in range(int(sys.argv[1])):
    t0 = time.perf_counter()
    run()
    times.append((time.perf_counter() - t0) * 1e3)
print(json.dumps(times))
"""


def _batch(py_dir: str, n: int) -> list:
    out = subprocess.run([sys.executable, "-c", _BATCH, str(n)], capture_output=True,
                         text=True, check=True, env={**os.environ, "PYTHONPATH": py_dir})
    return json.loads(out.stdout)


def _export(rev: str, into: str) -> str:
    """The ``py/`` tree of ``rev`` under ``into``."""
    data = subprocess.run(["git", "archive", rev, "py"], cwd=ROOT, capture_output=True,
                          check=True).stdout
    with tarfile.open(fileobj=io.BytesIO(data)) as tar:
        tar.extractall(into, filter="data")
    return os.path.join(into, "py")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--before", help="a git revision to compare with (its py/)")
    ap.add_argument("--rounds", type=int, default=10)
    ap.add_argument("--batch", type=int, default=30)
    args = ap.parse_args()
    builds = {"this tree": str(ROOT / "py")}
    with tempfile.TemporaryDirectory() as tmp:
        if args.before:
            builds = {f"before ({args.before})": _export(args.before, tmp), **builds}
        load0 = os.getloadavg()[0]
        times: dict = {name: [] for name in builds}
        for _ in range(args.rounds):
            for name, path in builds.items():
                times[name] += _batch(path, args.batch)
        load1 = os.getloadavg()[0]
    print(f"trace() of the 60-line unit (c28x, entry current_loop), CPython "
          f"{sys.version.split()[0]}, {args.rounds} × {args.batch} runs per build, "
          f"load average {load0:.1f} → {load1:.1f}:")
    for name, ts in times.items():
        ts.sort()
        print(f"  {name:<28} median {statistics.median(ts):6.2f} ms   p95 "
              f"{ts[int(len(ts) * 0.95)]:6.2f} ms   min {ts[0]:6.2f} ms   (target ≤ 5 ms median)")


if __name__ == "__main__":
    main()
