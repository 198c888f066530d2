"""Benchmark of family proofs: 6-dimensional boxes over the seed's Inovance code and over each
vendor profile's constants (TI, NXP, ST, Microchip), medians printed (numbers, not tests).

    PYTHONPATH=py python3 tests/bench/prove_bench.py

``tests/bench/prove.bench.ts`` runs :func:`prove_timing` of this file in Pyodide/Node.
Target: a 6-dimensional box decided (every integer proven or violated) in ≤ 2 s in CPython
and ≤ 10 s in Pyodide.
"""

from __future__ import annotations

import os
import statistics
import sys
import time

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}
SERVO = {"motor": {"rated_voltage_v": 220, "rated_current_a": 5, "rated_freq_hz": 200,
                   "rs_ohm": 1.5, "ld_h": 6e-3, "lq_h": 6e-3, "bemf_v": 150, "pole_pairs": 4},
         "drive": {"udc_v": 310, "ts_s": 1e-4, "base_freq_hz": 250}}
BOXES = {
    # A 220 V servo range: every integer proven.
    "servo 6-D (V, I, f_n, R, L_d, E)": (SERVO, {
        "motor.rated_voltage_v": [180, 240], "motor.rated_current_a": [1, 10],
        "motor.rated_freq_hz": [100, 250], "motor.rs_ohm": [0.3, 10],
        "motor.ld_h": [2e-3, 40e-3], "motor.bemf_v": [60, 220]}),
    # The seed's 24 V motor widened: FluxRotor breaks only inside the box (f_b just below
    # f_n/2 wraps FreqPer), found by splitting.
    "seed 6-D (V, I, f_b, R, E, U_dc)": (SEED, {
        "motor.rated_voltage_v": [12, 48], "motor.rated_current_a": [0.5, 5],
        "drive.base_freq_hz": [101.9, 348], "motor.rs_ohm": [0.1, 3],
        "motor.bemf_v": [5, 30], "drive.udc_v": [12, 60]}),
    "seed 6-D (V, I, f_b, f_n, E, U_dc)": (SEED, {
        "motor.rated_voltage_v": [12, 48], "motor.rated_current_a": [0.5, 5],
        "drive.base_freq_hz": [100, 348], "motor.rated_freq_hz": [100, 300],
        "motor.bemf_v": [5, 30], "drive.udc_v": [12, 60]}),
}
#: A drive-side box where each profile's shift, divisor or Q changes inside the box (the
#: proof cuts it at each choice): T_s, f_b, L_d, L_q, I and the current-loop bandwidth.
DRIVE_6D = {"drive.ts_s": [2e-5, 2e-4], "drive.base_freq_hz": [50, 1000],
            "motor.ld_h": [1e-4, 1e-2], "motor.lq_h": [1e-4, 1e-2],
            "motor.rated_current_a": [1, 40], "current_loop.bandwidth_hz": [200, 2000]}
#: The 6-D servo range, the widened seed and the drive box through each vendor profile.
PROFILE_BOXES = {
    **{f"{profile} {name.split(' (')[0]}": (*BOXES[name], profile)
       for profile in ("ti", "nxp", "st", "microchip")
       for name in ("servo 6-D (V, I, f_n, R, L_d, E)", "seed 6-D (V, I, f_b, R, E, U_dc)")},
    **{f"{profile} drive 6-D (T_s, f_b, L_d, L_q, I, bandwidth)": (SEED, DRIVE_6D, profile)
       for profile in ("inovance", "ti", "nxp", "st", "microchip")},
}


def prove_timing(repeat: int = 7) -> dict:
    """{name: (wall median s, CPU median s, verdict, decided, boxes)} for :data:`BOXES` (the
    seed's code) and :data:`PROFILE_BOXES`."""
    from pulab.analyses.prove import prove
    out = {}
    boxes = {**{k: (*v, "inovance") for k, v in BOXES.items()}, **PROFILE_BOXES}
    for name, (inp, ranges, profile) in boxes.items():
        req = {"input": inp, "ranges": ranges, "profile": profile}
        r = prove(req)  # warm-up (lazy imports)
        wall, cpu = [], []
        for _ in range(repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            prove(req)
            wall.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        decided = all(e["verdict"] != "unknown" for e in r["integers"].values())
        boxes = sum(e.get("boxes", 0) for e in r["integers"].values())
        out[name] = (statistics.median(wall), statistics.median(cpu), r["verdict"], decided, boxes)
    return out


#: Chapter 04's product family: three 400 V servo datasheets in a 9-D box, the Siemens
#: 1FT7044-AK7 as the base (its datasheet's motor and drive values).
FAMILY_BASE = {"motor": {"rated_voltage_v": 424.26406871192853, "rated_current_a": 2.5,
                         "rated_freq_hz": 300.0, "rs_ohm": 0.61, "ld_h": 0.0042, "lq_h": 0.0042,
                         "bemf_v": 342.0, "pole_pairs": 3},
               "drive": {"udc_v": 600.0, "ts_s": 0.000125}}
FAMILY_RANGES = {"motor.rated_voltage_v": [150, 430], "motor.rated_current_a": [1, 7],
                 "motor.rated_freq_hz": [150, 300], "motor.rs_ohm": [0.5, 4],
                 "motor.ld_h": [4e-3, 7.5e-3], "motor.lq_h": [4e-3, 7.5e-3],
                 "motor.bemf_v": [150, 350], "drive.ts_s": [6.25e-5, 1.25e-4],
                 "drive.udc_v": [540, 600]}


def propose_timing(repeat: int = 3) -> dict:
    """{profile: (wall median s, CPU median s, formats holding / constants)}: ``--propose`` on
    the chapter's 9-D family (no target; the page runs it on demand)."""
    from pulab.analyses.propose import propose
    out = {}
    for profile in ("nxp", "st", "microchip"):
        req = {"input": FAMILY_BASE, "ranges": FAMILY_RANGES, "profile": profile}
        wall, cpu = [], []
        for _ in range(repeat):
            t0, c0 = time.perf_counter(), time.process_time()
            p = propose(req)
            wall.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
        held = sum(bool(e and e["holds"]) for e in p["constants"].values())
        out[profile] = (statistics.median(wall), statistics.median(cpu), held, len(p["constants"]))
    return out


def format_proposals(t: dict) -> str:
    return "\n".join(f"  propose, 9-D servo family, {name}: median {w:.3f} s wall, {c:.3f} s CPU; "
                     f"{h}/{n} formats hold" for name, (w, c, h, n) in t.items())


def format_proofs(t: dict, runtime: str, target: str) -> str:
    # Pyodide's os.getloadavg answers a constant: the machine's load is the CPython run's line.
    load = os.getloadavg() if hasattr(os, "getloadavg") and sys.platform != "emscripten" else None
    lines = [f"  {name}: median {w:.3f} s wall, {c:.3f} s CPU; {v}, "
             f"{'every integer decided' if d else 'SOME UNKNOWN'}, {b} boxes (target {target})"
             for name, (w, c, v, d, b) in t.items()]
    if load is not None:
        lines.append(f"  machine load (1/5/15 min): {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
                     f"on {os.cpu_count()} cores")
    return "\n".join(lines)


if __name__ == "__main__":
    import platform
    runtime = f"CPython {platform.python_version()}"
    print(f"family proof benchmark ({runtime}):")
    print(format_proofs(prove_timing(), runtime, "≤ 2 s"))
    print(format_proposals(propose_timing()))
