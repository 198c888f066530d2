"""Benchmarks of the robustness analysis (prints numbers; no timed test).

    PYTHONPATH=py .venv/bin/python tests/bench/robust_bench.py [--study MOTORS SAMPLES]

1. corners + worst case (and, apart, the safe band) of the seed drive: median of 15 runs;
2. 10 000 Monte Carlo samples on one core;
3. with --study: a MOTORS × SAMPLES catalogue study (tests/data/motors-1000.csv) with
   --jobs 1 and on a local 2-worker Dask cluster; the rows must be equal, the speed-up is printed.
"""

from __future__ import annotations

import os
import pathlib
import statistics
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "py"))

import pulab  # noqa: E402
from pulab.analyses.loop import robust  # noqa: E402
from pulab.cli.robust import run_study, study_tasks  # noqa: E402

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}


def main(argv: list) -> None:
    print(f"load average {os.getloadavg()}")
    r = pulab.report(SEED)
    for band in (False, True):
        times = []
        for _ in range(15):
            t = time.perf_counter()
            robust.analyze(r, robust.validate({}), "computation_pwm", band=band)
            times.append(time.perf_counter() - t)
        label = "corners + worst case + map" + (" + safe band + worst-case step" if band else "")
        print(f"{label}: median {1e3 * statistics.median(times):.1f} ms")
    t = time.perf_counter()
    out = robust.analyze(r, robust.validate({"samples": 10000}), "computation_pwm", band=False)
    print(f"10 000 Monte Carlo samples: {time.perf_counter() - t:.2f} s "
          f"(fraction below threshold {out['monte_carlo']['fraction_below']:.4f})")
    if "--study" in argv:
        k = argv.index("--study")
        motors, samples = int(argv[k + 1]), int(argv[k + 2])
        lines = (ROOT / "tests" / "data" / "motors-1000.csv").read_text().splitlines()
        tasks = study_tasks("\n".join(lines[:motors + 1]) + "\n", {"robust": {}}, samples, 0)
        quiet = lambda d, n: None  # noqa: E731
        t = time.perf_counter()
        one = run_study(tasks, 1, progress=quiet)
        t1 = time.perf_counter() - t
        from dask.distributed import LocalCluster
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                          dashboard_address=":0") as cluster:
            t = time.perf_counter()
            two = run_study(tasks, scheduler=cluster.scheduler_address, progress=quiet)
            t2 = time.perf_counter() - t
        print(f"study {motors} motors × {samples} samples: --jobs 1 {t1:.1f} s, "
              f"2-worker Dask {t2:.1f} s, speed-up {t1 / t2:.2f}×, equal rows: {one == two}, "
              f"rows with errors {sum('error' in x for x in one)}")


if __name__ == "__main__":
    main(sys.argv[1:])
