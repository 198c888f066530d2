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

import math

from ..fixedpoint.counted import wrap
from ..model.acim import SQRT2
from ..profiles import registry
from ..profiles.vendor import provided
from .review import SEVERITIES, _board, _finding

__all__ = ["INOVANCE", "profiles", "loop_view", "review", "NOT_APPLICABLE", "flux_buildup",
           "FLUX_STEPS_MAX", "FLUX_POINTS", "STALL_PCT", "flux_fraction", "hot_rotor", "IM_RATIO",
           "NOLOAD_PCT", "HOT_K", "torque_flux_peak"]

#: The longest flux build-up simulated, in controller periods (10·τ_r/T_s beyond it is cut).
FLUX_STEPS_MAX = 100_000
#: Points of each trace of the build-up (every k-th period).
FLUX_POINTS = 200
#: A fixed-point flux model that stops this far (%) below its reference is a warning.
STALL_PCT = 0.1

#: What of the seed's Inovance code holds for an induction motor, and what does not.
INOVANCE = {
    "applies": ["base (the same bases, seed 1.1)", "current_pi pm_kp (Q12) and pm_ki (Q16, T_s "
                "folded in), seed 2.2-9, on the plant σ·L_s, R_σ", "pll (seed 3)",
                "loop.speed (with analysis.speed)"],
    "not_covered": "the seed's raw parameter block (LD, LQ, BemfVolt …) is a PMSM's; it documents "
                   "no induction-motor block (R_r, L_m, L_σ, I_0), so none of their integers is "
                   "computed",
    "not_covered_zh": "源文档的原始参数块（LD、LQ、BemfVolt …）属于永磁同步电机；它没有感应电机的参数块"
                      "（R_r、L_m、L_σ、I_0），因此这些量的整数都不计算"}
#: Input sections that do not apply to an induction motor yet (each refused, naming it).
NOT_APPLICABLE = ("raw", "sim.current.code", "profiles", "analysis.fw", "analysis.robust",
                  "analysis.speed.response")


def profiles(a: dict, n: dict) -> dict:
    """Each vendor's induction-motor constants, or ``available`` false and why not."""
    out = {}
    for v in registry.vendors():
        own = provided(v, "acim")
        if own is None:
            out[v.NAME] = {"available": False,
                           "reason": "no public induction-motor scaling is modelled for this "
                                     "vendor in pu-lab",
                           "reason_zh": "pu-lab 未建模该厂商公开的感应电机标定"}
        else:
            out[v.NAME] = {"available": True, **own(a, n)}
    return out


def torque_flux_peak(a: dict) -> float:
    """The flux (Wb, peak) whose 1.5·p·ψ is the induction motor's torque per A peak of i_q:
    √2·(L_m²/L_r)·I_m, so the board's ``nm_per_count`` is k_T/√2 per ampere of a count.

    >>> round(torque_flux_peak({"lm_h": 0.0525, "lr_h": 0.0615, "magnetizing_current_a": 0.55}), 7)
    0.0348595
    """
    return SQRT2 * a["lm_h"] ** 2 / a["lr_h"] * a["magnetizing_current_a"]


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


def flux_buildup(a: dict, n: dict, kr: int, q: int = 24) -> dict:
    """The rotor flux built by a step of i_d to I_m: TI's current model in float and in IQ``q``.

    TI's ``CUR_MOD_MACRO`` (controlSUITE ``cur_mod.h``) updates the magnetizing current
    ``IMDs += _IQmpy(Kr, IDs - IMDs)`` every period, ``_IQmpy`` = ``(int64 a·b) >> q`` (floor);
    the float run does the same with the exact Kr = T_s/τ_r.  The fixed-point model stops
    moving once Kr·(IDs − IMDs) < 2^q: it stalls below its reference (``stall_lsb``).

    Parameters
    ----------
    a : dict — the report's ``acim`` section ; n : dict — the normalized input
    kr : int — TI's stored Kr (``profiles.ti.constants.Kr.value``) ; q : int — GLOBAL_Q

    Returns
    -------
    dict
        ``steps`` (periods simulated: 10·τ_r/T_s, at most :data:`FLUX_STEPS_MAX`), ``complete``
        (not cut), ``kr``, ``id_ref`` (IDs, IQ``q`` of the d reference I_m in per unit),
        ``t95_float_s``/``t95_fixed_s`` (first time at 95 %, None if not reached),
        ``final_float_pu``, ``final_fixed`` (IQ``q``), ``final_fixed_pu``, ``stall_lsb``
        (IDs − IMDs at the end), ``stall_pct`` (of IDs), ``events`` (wraps counted) and
        ``trace`` (``t_s``, ``float_pu``, ``fixed_pu``, every ``FLUX_POINTS``-th).

    >>> a = {"tau_r_s": 0.15375, "pu": {"magnetizing_current_a": 0.55 / 1.5}}
    >>> f = flux_buildup(a, {"drive": {"ts_s": 1e-4}}, 10912)
    >>> f["stall_lsb"], round(f["stall_pct"], 4)
    (1537, 0.025)
    """
    ts, tau, i_d = n["drive"]["ts_s"], a["tau_r_s"], a["pu"]["magnetizing_current_a"]
    want = math.ceil(10.0 * tau / ts)
    steps = min(want, FLUX_STEPS_MAX)
    ids, k_real = int(i_d * 2 ** q), ts / tau        # _IQ(x): a C cast, toward zero
    every = max(1, steps // FLUX_POINTS)
    x, imds, ev = 0.0, 0, {}
    t95 = {"float": None, "fixed": None}
    trace = {"t_s": [0.0], "float_pu": [0.0], "fixed_pu": [0.0]}
    for k in range(1, steps + 1):
        x += k_real * (i_d - x)
        imds = wrap(imds + wrap((kr * (ids - imds)) >> q, 32, ev), 32, ev)
        if t95["float"] is None and x >= 0.95 * i_d:
            t95["float"] = k * ts
        if t95["fixed"] is None and 20 * imds >= 19 * ids:
            t95["fixed"] = k * ts
        if k % every == 0 or k == steps:
            trace["t_s"].append(k * ts)
            trace["float_pu"].append(x)
            trace["fixed_pu"].append(imds / 2 ** q)
    return {"steps": steps, "complete": steps == want, "kr": kr, "id_ref": ids,
            "t95_float_s": t95["float"], "t95_fixed_s": t95["fixed"], "final_float_pu": x,
            "final_fixed": imds, "final_fixed_pu": imds / 2 ** q, "stall_lsb": ids - imds,
            "stall_pct": 100.0 * (ids - imds) / ids if ids else 0.0, "events": ev,
            "trace": trace}


#: The magnetizing current's usual share of the rated current, % (small to medium motors).
IM_RATIO = (20.0, 60.0)
#: A given I_m this far (%) from the no-load estimate U_ph/(ω·L_s) is a warning.
NOLOAD_PCT = 25.0
#: The rotor's temperature rise the hot-rotor finding is computed for, K.
HOT_K = 100.0


def flux_fraction(tau_r: float, t: float, sim_flux: dict | None = None) -> float:
    """The share of the final rotor flux built t seconds after i_d steps to I_m: from the
    simulated build-up (its float run) when given, else 1 − e^{−t/τ_r}.

    >>> round(flux_fraction(0.15375, 0.15375), 6)
    0.632121
    """
    if sim_flux is None:
        return 1.0 - math.exp(-t / tau_r)
    t_s, psi = sim_flux["t"], sim_flux["variants"]["si"]["psi_d"]
    k = max((i for i, x in enumerate(t_s) if x <= t), default=0)
    return psi[k] / sim_flux["psi_ref_wb"]


def hot_rotor(a: dict, alpha: float, rise_k: float = HOT_K) -> dict | None:
    """Indirect field orientation with the cold τ_r when the rotor is ``rise_k`` hotter.

    R_r → R_r·(1 + α·ΔT), so the true τ_r is k = 1/(1 + α·ΔT) of the estimate and the slip the
    controller sets is k times what the orientation needs.  In steady state at the rated
    currents (t = I_q/I_m) the rotor flux is ψ = L_m·i/(1 + j·k·t): it leads the controller's
    d axis by atan(t) − atan(k·t), its magnitude by √((1 + t²)/(1 + k²·t²)), the torque per ampere by
    k·(1 + t²)/(1 + k²·t²) (linear magnetics: in a real motor saturation caps the flux rise).

    Returns
    -------
    dict or None (no torque current at rated current) — ``rise_k``, ``rr_pct`` (R_r rise),
    ``slip_pct`` (needed slip over the estimate − 1), ``angle_deg`` (the flux's lead),
    ``flux_pct``,
    ``torque_pct`` (each the error, %)

    >>> h = hot_rotor({"torque_current_a": 1.39553, "magnetizing_current_a": 0.55}, 0.00393)
    >>> round(h["slip_pct"], 3), round(h["angle_deg"], 2), round(h["torque_pct"], 1)
    (39.3, 7.26, 23.7)
    """
    if a["torque_current_a"] is None:
        return None
    k = 1.0 / (1.0 + alpha * rise_k)
    t = a["torque_current_a"] / a["magnetizing_current_a"]
    return {"rise_k": rise_k, "rr_pct": 100.0 * alpha * rise_k, "slip_pct": 100.0 * (1.0 / k - 1.0),
            "angle_deg": math.degrees(math.atan(t) - math.atan(k * t)),
            "flux_pct": 100.0 * (math.sqrt((1.0 + t * t) / (1.0 + k * k * t * t)) - 1.0),
            "torque_pct": 100.0 * (k * (1.0 + t * t) / (1.0 + k * k * t * t) - 1.0)}


def review(n: dict, a: dict, robust_c: tuple = (20.0, 155.0), alpha: float = 0.00393,
           flux: dict | None = None, sim: dict | None = None,
           startup_s: float | None = None, board: dict | None = None) -> dict:
    """The induction motor's findings (the same record as :mod:`pulab.analyses.review`).

    ``robust_c`` and ``alpha``: the winding temperature range and copper coefficient the
    R_r drift is judged over (the robustness view's defaults); ``sim``: the report's
    simulation (its flux build-up, when run); ``startup_s``: when the drive commands torque
    after magnetizing starts (``sim.flux.startup_s``); ``board``: the report's ``board``
    (its findings as for a PMSM, the dead time against the stator flux √2·L_s·I_m).
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
    if startup_s is not None:
        # the flux built at start-up: simulated (current loop included) when run, else 1 − e^{−t/τ_r}
        sim_f = None if sim is None else sim["flux"]
        t95 = a["flux_95_s"] if sim_f is None or sim_f["metrics"]["si"]["flux_95_s"] is None \
            else sim_f["metrics"]["si"]["flux_95_s"]
        built = 100.0 * flux_fraction(a["tau_r_s"], startup_s, sim_f)
        _finding(f, "warning" if startup_s < t95 else None, "acim_torque_before_flux",
                 "sim.flux.metrics.si.flux_95_s" if sim_f else "acim.flux_95_s",
                 "sim.flux.startup_s", startup_s, t=startup_s, t95=t95, pct=built)
    hot = hot_rotor(a, alpha)
    if hot is not None:
        _finding(f, "warning" if abs(hot["angle_deg"]) >= 2.0 else "note", "acim_rr_hot",
                 "acim.slip_gain_per_s", "motor.rr_ohm", hot["angle_deg"], **hot)
    ratio = 100.0 * a["magnetizing_current_a"] / m["rated_current_a"]
    if a["torque_current_a"] is not None:
        _finding(f, "note" if IM_RATIO[0] <= ratio <= IM_RATIO[1] else "warning", "acim_im_ratio",
                 "acim.magnetizing_current_a", "motor.magnetizing_current_a", ratio, pct=ratio,
                 lo=IM_RATIO[0], hi=IM_RATIO[1])
    if a["magnetizing_from"] == "given":
        u_ph = m["rated_voltage_v"] / math.sqrt(3.0)
        noload = u_ph / (2.0 * math.pi * m["rated_freq_hz"] * a["ls_h"])
        off = 100.0 * (a["magnetizing_current_a"] - noload) / noload
        if abs(off) > NOLOAD_PCT:
            _finding(f, "warning", "acim_im_vs_noload", "acim.magnetizing_current_a",
                     "motor.magnetizing_current_a", off, value=a["magnetizing_current_a"],
                     noload=noload, pct=off)
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
    if flux is not None and flux["stall_pct"] >= STALL_PCT:
        _finding(f, "warning", "acim_flux_stall", "acim_flux.stall_pct", "drive.ts_s",
                 flux["stall_pct"], pct=flux["stall_pct"], lsb=flux["stall_lsb"], kr=flux["kr"])
    _board(f, n, board, SQRT2 * a["ls_h"] * a["magnetizing_current_a"])
    f.sort(key=lambda x: SEVERITIES.index(x["severity"]))
    return {"findings": f, "counts": {s: sum(x["severity"] == s for x in f) for s in SEVERITIES}}
