"""Independent oracle for the corners of the report's "loop.robust" section; writes
tests/golden/robust/*.json.

    .venv/bin/python tests/oracle/robust_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/robust_oracle.py --check  # exit 1 if any file is stale

Never imports pulab.  The firmware gains come from the report oracle (oracle.py:
``current_pi.*.from_integers``); the drifted plants are written here from the contract's
formulas (docs/contract.md, "Robustness"): R(T) = R·(1 + α·(T − T_ref)),
ψ(T) = ψ·(1 + β·(T − T_ref)), L linear to (1 − drop)·L at I_peak or a table, U_dc·(1 ± tol),
loop gain scaled by U_dc/U_dc,nom without bus compensation; the voltage headroom at rated
frequency (i_d = 0, i_q = the case's current, against U_dc/√2); each loop is built and measured
with python-control along loop_oracle.py's route (control.c2d, lifting for the PWM half
period, control.stability_margins, feedback poles, a brentq bandwidth).

The cases are listed in the contract's order: nominal (T_ref, 0 A, nominal bus), then the
corners T_lo/T_hi × 0/I_peak × U_dc low/high.
"""

from __future__ import annotations

import copy
import itertools
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from loop_oracle import EXTRA, current_loop, measure  # noqa: E402
from make_golden import CASES as REPORT_CASES  # noqa: E402
from oracle import oracle_report  # noqa: E402

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "robust"
REL, ABS = 1e-9, 1e-9      # as loop_oracle.py; the pulab test compares at 1e-6
MAGNETS = {"ndfeb": -0.12, "smco": -0.035, "ferrite": -0.20}


def inductance(ld, lq, i, peak, rob):
    table = rob.get("inductance_table")
    if table is None:
        f = 1.0 - rob.get("inductance_drop_pct", 30.0) / 100.0 * min(i / peak, 1.0)
        return ld * f, lq * f
    xs = [p[0] for p in table]
    return (float(np.interp(i, xs, [p[1] for p in table])),
            float(np.interp(i, xs, [p[2] for p in table])))


def expected(inp):
    rep = oracle_report({k: v for k, v in inp.items() if k != "analysis"})
    a = inp["analysis"]
    rob = a["robust"]
    delay = a.get("delay", "computation_pwm")
    m, d = inp["motor"], inp["drive"]
    ts, udc = d["ts_s"], d["udc_v"]
    t_lo, t_hi = rob.get("temperature_c", [20.0, 155.0])
    t_ref = rob.get("reference_c", 20.0)
    alpha = rob.get("copper_alpha_per_k", 0.00393)
    magnet = rob.get("magnet", "ndfeb")
    beta = (MAGNETS[magnet] if isinstance(magnet, str) else magnet) / 100.0
    peak = rob.get("peak_current_a") or 2.0 * m["rated_current_a"]
    tol = rob.get("udc_tolerance_pct", 10.0) / 100.0
    psi = m["bemf_v"] / (math.sqrt(3.0) * 2.0 * math.pi * m["rated_freq_hz"])
    comp = rob.get("bus_compensated", True)
    points = [(t_ref, 0.0, udc)] + list(itertools.product(
        (t_lo, t_hi), (0.0, peak), (udc * (1 - tol), udc * (1 + tol))))
    cases = []
    for t, i, u in points:
        ld, lq = inductance(m["ld_h"], m["lq_h"], i, peak, rob)
        c = {"temperature_c": float(t), "current_a": float(i), "udc_v": float(u),
             "rs_ohm": m["rs_ohm"] * (1 + alpha * (t - t_ref)), "ld_h": ld, "lq_h": lq,
             "psi_wb": psi * (1 + beta * (t - t_ref))}
        # voltage need at rated frequency, i_d = 0, i_q = i (RMS), against U_dc/√2 (line RMS)
        w = 2.0 * math.pi * m["rated_freq_hz"]
        need = math.sqrt(3.0) * abs(complex(c["rs_ohm"] * i + w * c["psi_wb"], -w * lq * i))
        c["voltage_headroom_pct"] = 100.0 * (1.0 - need / (u / math.sqrt(2.0)))
        k = 1.0 if comp else u / udc
        for axis, L in (("d", ld), ("q", lq)):
            g = rep["current_pi"][axis]["from_integers"]
            r = measure(current_loop(c["rs_ohm"], L, ts, k * g["kp"], k * g["ki"], delay), ts)
            c[axis] = {key: r[key] for key in ("phase_margin_deg", "gain_margin_db",
                                               "crossover_hz", "bandwidth_hz", "stable")}
        cases.append(c)
    return cases


ROBUST = [{}, {"temperature_c": [-20, 120], "magnet": "smco", "inductance_drop_pct": 45,
               "udc_tolerance_pct": 15, "bus_compensated": False},
          {"peak_current_a": 5.0, "magnet": -0.09, "copper_alpha_per_k": 0.0039}]


def cases():
    out = {}
    base = [(n[3:], inp) for n, inp in REPORT_CASES[:8]] + list(EXTRA.items())
    delays = ("computation_pwm", "computation", "none")
    for k, (name, inp) in enumerate(base):
        inp = copy.deepcopy(inp)
        rob = copy.deepcopy(ROBUST[k % len(ROBUST)])
        if "peak_current_a" in rob:
            rob["peak_current_a"] = 2.5 * inp["motor"]["rated_current_a"]
        if k == 4:          # a datasheet/FEA table of (current, Ld, Lq)
            i_n, ld, lq = inp["motor"]["rated_current_a"], inp["motor"]["ld_h"], inp["motor"]["lq_h"]
            rob["inductance_table"] = [[0.0, ld, lq], [i_n, 0.95 * ld, 0.9 * lq],
                                       [3 * i_n, 0.7 * ld, 0.55 * lq]]
        inp["analysis"] = {"delay": delays[k % 3], "robust": rob}
        out[f"{k + 1:02d}_{name}"] = inp
    return out


def main(argv: list[str]) -> int:
    files = {f"{name}.json": {"input": inp, "expected": {"cases": expected(inp)}}
             for name, inp in cases().items()}
    return sync(files, golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
