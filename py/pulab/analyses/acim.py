"""The induction motor's report parts beyond the model: vendors, loop view, review.

The current loop of an induction motor in rotor-flux orientation is the PMSM's plant with
R_σ for R_s and σ·L_s for L_d = L_q (:mod:`pulab.model.acim`), so :func:`loop_view` hands
:func:`pulab.analyses.loop.analyze` a report whose motor is that plant and whose flux is
the one that gives the induction motor's torque constant: the same design methods, delays,
margins and speed loop, computed by the same code.

Examples
--------
>>> from pulab import report
>>> r = report({"motor": {"kind": "acim", "rated_voltage_v": 72.746, "rated_current_a": 1.5,
...     "rated_freq_hz": 50, "rated_speed_rpm": 1370, "pole_pairs": 2, "rs_ohm": 0.6,
...     "rr_ohm": 0.4, "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525},
...     "drive": {"udc_v": 150, "ts_s": 1e-4}})
>>> round(r["acim"]["sigma"], 7), r["profiles"]["microchip"]["available"]
(0.2712671, False)
"""

from __future__ import annotations

from ..profiles import registry
from ..profiles.vendor import provided
from .review import SEVERITIES, _finding

__all__ = ["INOVANCE", "profiles", "loop_view", "review", "NOT_APPLICABLE"]

#: What of the seed's Inovance code holds for an induction motor, and what does not.
INOVANCE = {
    "applies": ["base (the same bases, seed 1.1)", "current_pi pm_kp (Q12) and pm_ki (Q16, T_s "
                "folded in), seed 2.2-9, on the plant σ·L_s, R_σ", "pll (seed 3)",
                "loop.speed (with analysis.speed)"],
    "not_covered": "the seed's raw parameter block (LD, LQ, BemfVolt …) is a PMSM's; it documents "
                   "no induction-motor block (R_r, L_m, L_σ, I_0), so none of their integers is "
                   "computed"}
#: Input sections that do not apply to an induction motor yet (each refused, naming it).
NOT_APPLICABLE = ("raw", "board", "sim", "profiles", "analysis.fw", "analysis.robust",
                  "analysis.speed.response")


def profiles(a: dict, n: dict) -> dict:
    """Each vendor's induction-motor constants, or ``available`` false and why not."""
    out = {}
    for v in registry.vendors():
        own = provided(v, "acim")
        if own is None:
            out[v.NAME] = {"available": False,
                           "reason": "no public induction-motor scaling is modelled for this "
                                     "vendor in pu-lab"}
        else:
            out[v.NAME] = {"available": True, **own(a, n)}
    return out


def loop_view(out: dict, a: dict) -> dict:
    """The report :func:`pulab.analyses.loop.analyze` reads, with the induction motor's plant.

    ``input.motor``: R_σ as ``rs_ohm``, σ·L_s as ``ld_h`` and ``lq_h``; ``pu.psi_r_wb`` the
    flux (L_m/L_r)·ψ_r that gives k_T = 3·p·(L_m²/L_r)·I_m (rms convention).
    """
    n = out["input"]
    plant = {"rs_ohm": a["r_sigma_ohm"], "ld_h": a["sigma_ls_h"], "lq_h": a["sigma_ls_h"],
             "pole_pairs": n["motor"]["pole_pairs"]}
    return {**out, "input": {**n, "motor": plant},
            "pu": {"psi_r_wb": a["lm_h"] / a["lr_h"] * a["rotor_flux_wb"]}}


def review(n: dict, a: dict, robust_c: tuple = (20.0, 155.0), alpha: float = 0.00393) -> dict:
    """The induction motor's findings (the same record as :mod:`pulab.analyses.review`).

    ``robust_c`` and ``alpha``: the winding temperature range and copper coefficient the
    R_r drift is judged over (the robustness view's defaults).
    """
    f: list = []
    m = n["motor"]
    if a["torque_current_a"] is None:
        _finding(f, "error", "acim_im_ge_rated", "acim.magnetizing_current_a",
                 "motor.magnetizing_current_a", a["magnetizing_current_a"],
                 value=a["magnetizing_current_a"], rated=m["rated_current_a"])
    if a["magnetizing_from"] == "no_load_estimate":
        _finding(f, "note", "acim_im_estimated", "acim.magnetizing_current_a",
                 "motor.magnetizing_current_a", a["magnetizing_current_a"],
                 value=a["magnetizing_current_a"])
    _finding(f, "note", "acim_flux_build", "acim.flux_95_s", "motor.rr_ohm", a["flux_95_s"],
             t95=a["flux_95_s"], tau=a["tau_r_s"])
    pct = 100.0 * alpha * (robust_c[1] - robust_c[0])
    _finding(f, "warning", "acim_rr_drift", "acim.slip_gain_per_s", "motor.rr_ohm", pct,
             t_lo=robust_c[0], t_hi=robust_c[1], pct=pct, alpha=alpha)
    model_hz = a["slip_freq_model_hz"]
    if model_hz is not None:
        off = 100.0 * (model_hz - a["slip_freq_hz"]) / a["slip_freq_hz"]
        if abs(off) > 20.0:
            _finding(f, "warning", "acim_slip_mismatch", "acim.slip_freq_model_hz",
                     "motor.rated_speed_rpm", off, model=model_hz, plate=a["slip_freq_hz"],
                     pct=off)
    f.sort(key=lambda x: SEVERITIES.index(x["severity"]))
    return {"findings": f, "counts": {s: sum(x["severity"] == s for x in f) for s in SEVERITIES}}
