"""Exports of a report: a C header of the firmware integers (the Inovance profile's,
:func:`pulab.profiles.inovance.header.c_header`), CSV of simulation traces.

Examples
--------
>>> import json
>>> from pulab.report import report
>>> r = report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> print(next(x for x in c_header(r).splitlines() if "PULAB_RPM " in x))
#define PULAB_RPM                    15022  /* Q16 = 0.229218 (ideal 0.229242, -0.0107 %) -> 1.49984 Ω; truncation */
"""

from __future__ import annotations

from .profiles.inovance.header import c_header

__all__ = ["c_header", "sim_csv"]

#: Unit of each simulated signal (pulab.analyses.sim output is SI), as a column-name suffix.
_CSV_UNITS = {"id": "A", "iq": "A", "ud": "V", "uq": "V", "theta": "rad", "theta_hat": "rad",
              "omega_hat": "rad_per_s", "psi_d": "Wb", "psi_q": "Wb"}


def sim_csv(r: dict, which: str) -> str:
    """CSV of a simulation's time series (``which`` = ``current`` or ``pll``), SI units.

    One column per variant and signal, its unit in the name: ``t_s``, ``si.id_A``,
    ``fixed.uq_V`` (phase voltage), ``q15.theta_hat_rad``, ``pu.omega_hat_rad_per_s``
    (electrical); then, for the current loop, each other firmware's run that exists
    (``ti.id_A``, …, ``microchip.uq_V``, ``sim.current.by_profile``); an induction motor's
    runs add its rotor flux (``si.psi_d_Wb``, ``si.psi_q_Wb``).
    """
    s = r.get("sim", {}).get(which)
    if s is None:
        raise ValueError(f"the report has no {which} simulation")
    cols, names = [s["t"]], ["t_s"]
    runs = {name: run["variant"] for name, run in s.get("by_profile", {}).items() if run["ran"]}
    for variant, series in [*s["variants"].items(), *runs.items()]:
        for sig, vals in series.items():
            cols.append(vals)
            names.append(f"{variant}.{sig}_{_CSV_UNITS[sig]}")
    rows = [",".join(names)]
    rows += [",".join(repr(float(c[i])) for c in cols) for i in range(len(s["t"]))]
    return "\n".join(rows) + "\n"
