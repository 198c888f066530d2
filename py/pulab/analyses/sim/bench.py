"""Benchmark of the current-loop simulation (prints numbers; not a timed test).

``PYTHONPATH=py python3 -m pulab.analyses.sim.bench [STEPS]`` runs STEPS controller
periods (default 20 000) of each current-loop variant on the seed's motor with a
step at t = 0 (so the run is mostly steady state, as a real step response is)
and prints seconds and steps per second.  Target: every variant (si, pu, fixed and
the four other vendors' integer PIs of ``by_profile``) together under 0.5 s in CPython,
under 1 s in Pyodide.  :func:`bench` returns the
numbers, so a Pyodide runner can call it and compute the Pyodide/CPython ratio.
"""

from __future__ import annotations

import sys
import time

__all__ = ["bench", "main", "SEED_INPUT"]

#: The seed's example motor (seed 1.4-1 … 1.4-7) with a plausible drive.
SEED_INPUT = {
    "motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
              "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
    "drive": {"udc_v": 24, "ts_s": 1e-4},
}


def bench(steps: int = 20000, repeat: int = 3) -> dict:
    """Time ``steps`` controller periods of each current-loop variant.

    Parameters
    ----------
    steps : int ≥ 1, controller periods per variant
    repeat : int ≥ 1, the best of this many runs is kept

    Returns
    -------
    dict
        ``steps``, ``total_s`` and ``steps_per_s`` (steps of all variants together per
        second, :func:`pulab.analyses.sim.current.run`), and single-variant times
        ``float_variant_s``, ``fixed_variant_s``, ``fixed_no_memo_s`` (the worst case,
        every step a call of :func:`pulab.profiles.inovance.code.current_pi_step`) and
        ``vendors_s`` (TI, NXP, ST and Microchip together, :mod:`.vendor_loop`).
    """
    from ... import report
    from ..slices import finish
    from . import current, validate

    rep = report(SEED_INPUT)
    # n periods give n + 1 samples (controller steps): ask for steps − 1 periods.
    cfg = validate({"current": {"speed_hz": 50.0, "duration_s": (steps - 1) * 1e-4}})["current"]
    best = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        r = current.run(rep, cfg)
        t1 = time.perf_counter()
        if best is None or t1 - t0 < best:
            best = t1 - t0
    # Split the total by variant with separate timed calls of the inner loops.
    inp, b, pu, vendor, pi = rep["input"], rep["base"], rep["pu"], rep["vendor"], rep["current_pi"]
    ts = inp["drive"]["ts_s"]
    z = current.zoh(inp["motor"]["rs_ohm"], inp["motor"]["ld_h"], inp["motor"]["lq_h"],
                    pu["psi_r_wb"], 2 * 3.141592653589793 * 50.0, ts)
    umax = vendor["pm_maxout_vol"]["value"] / 4096.0 * b["U_b"]
    per = {}
    t0 = time.perf_counter()
    current.run_float(z, pi["d"]["kp"], pi["d"]["ki"] * ts, pi["q"]["kp"], pi["q"]["ki"] * ts,
                      umax, umax, 0.75, 0.0, z.bemf, steps - 1, False)
    per["float_variant_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    current.run_fixed(z, b["I_b"], b["U_b"], pi["d"]["pm_kp"], pi["d"]["pm_ki"],
                      pi["q"]["pm_kp"], pi["q"]["pm_ki"], vendor["maxu"]["value"],
                      vendor["pm_maxout_vol"]["value"], 2048, 0, 0, steps - 1, False)
    per["fixed_variant_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    current.run_fixed(z, b["I_b"], b["U_b"], pi["d"]["pm_kp"], pi["d"]["pm_ki"],
                      pi["q"]["pm_kp"], pi["q"]["pm_ki"], vendor["maxu"]["value"],
                      vendor["pm_maxout_vol"]["value"], 2048, 0, 0, steps - 1, False, memo=False)
    per["fixed_no_memo_s"] = time.perf_counter() - t0
    from . import vendor_loop
    ctls = vendor_loop.controllers(vendor_loop.profile_data(rep)[0], umax * 2 ** 0.5,
                                   inp["drive"]["udc_v"])
    t0 = time.perf_counter()
    for name in vendor_loop.names():
        finish(vendor_loop.run_profile_steps(z, ctls[name], 2 ** 0.5, 0.75, 0.0, z.bemf,
                                             steps - 1, False))
    per["vendors_s"] = time.perf_counter() - t0
    return {"steps": r["n"] + 1, "total_s": best, "steps_per_s": (r["n"] + 1) / best, **per}


def main(argv: list | None = None) -> int:
    """Command-line entry: print the numbers of :func:`bench`."""
    argv = sys.argv[1:] if argv is None else argv
    steps = int(argv[0]) if argv else 20000
    r = bench(steps)
    print(f"pulab.analyses.sim current loop, {r['steps']} controller steps × 7 variants "
          f"(si, pu, fixed; ti, nxp, st, microchip) in {sys.implementation.name} "
          f"{sys.version.split()[0]}:")
    print(f"  total {r['total_s']:.3f} s  →  {r['steps_per_s']:.0f} steps/s "
          f"(all variants per step; target < 0.5 s)")
    print(f"  one float variant {r['float_variant_s']:.3f} s, fixed variant "
          f"{r['fixed_variant_s']:.3f} s (without the current_pi_step memo, i.e. every "
          f"step a new integer state: {r['fixed_no_memo_s']:.3f} s); TI, NXP, ST and "
          f"Microchip together {r['vendors_s']:.3f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
