"""An induction motor's current step and flux build-up, float beside integers.

The loops, PI steps and metrics are those of the PMSM (:mod:`.current`, :mod:`.vendor_loop`,
:mod:`.metrics`); only the plant differs: :func:`.plant.acim_zoh`, the induction motor's dq
model with its rotor flux, exact ZOH.  The controller is indirect rotor-flux-oriented: the
frame turns at ω_e = ω_r + ω_sl* with the slip of the references,
ω_sl* = i_q*/(τ_r·i_d*) (:mod:`pulab.model.acim`), held from t = 0.

``current``
    The motor is magnetized (i_d = I_m in the dq scale, ψ_rd = L_m·I_m, zero slip) and turns
    at ``sim.current.speed_hz`` (the rotor's electrical speed); at t = 0 the reference steps
    by ``step_a`` on ``axis``: d → i_d* = I_m + step, q → i_q* = step.  The PI integrals
    start at the voltages that held the magnetized state: u_d = R_s·I_m, u_q = ω_r·L_s·I_m.
``flux``
    Magnetizing at standstill: everything at zero, then i_d* = I_m.  The current follows
    within the current loop's time; the rotor flux ψ_rd rises with τ_r (95 % after
    ln 20·τ_r ≈ 3·τ_r behind the current).

Variants: ``si`` and ``pu`` (float PI, SI and per unit), ``fixed`` (the seed's Inovance PI,
pm_kp Q12, pm_ki Q16, its voltage limits pm_maxout_vol and maxu from the rated line voltage
and U_dc as the firmware computes them, seed 2.2-1/2) and ``by_profile.ti`` (TI's IQ PI,
``pi.h``, with Kp/Ki of the TI profile's default full scales, U_dc and 2·√2·I_rated, as its
universal lab's ACIM build runs the same controller).  NXP's ACIM PI is a float controller
(MCAT's ``M1_D_KP_GAIN``), ST's ACIM integers are not modelled here (each listed with why in
``by_profile``).

Examples
--------
>>> from pulab import report
>>> r = report({"motor": {"kind": "acim", "rated_voltage_v": 72.746, "rated_current_a": 1.5,
...     "rated_freq_hz": 50, "rated_speed_rpm": 1370, "pole_pairs": 2, "rs_ohm": 0.6,
...     "rr_ohm": 0.4, "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525,
...     "magnetizing_current_a": 0.55}, "drive": {"udc_v": 150, "ts_s": 1e-4},
...     "sim": {"current": {"axis": "q"}}})
>>> f = r["sim"]["flux"]["metrics"]
>>> round(r["acim"]["flux_95_s"], 5), round(f["si"]["flux_95_s"], 5), f["fixed"]["wraps"]
(0.46059, 0.4606, 0)
"""

from __future__ import annotations

import math
from array import array

from ...schema.errors import InputError
from ...fixedpoint.qformat import round_half_away
from ...profiles.inovance import code as inovance_code
from ...profiles.ti import pi as ti_pi
from ...profiles.ti import scaling as ti_scaling
from ..slices import finish
from .current import Q12_CURRENT_LIMIT_PU, run_fixed_steps, run_float_steps
from .inputs import periods
from .metrics import step_metrics
from .plant import acim_zoh
from .vendor_loop import run_profile_steps

__all__ = ["simulate_steps", "simulate", "voltage_limits", "NOT_RUN", "MAX_PERIODS"]

#: The longest run of each section, in controller periods: the flux build-up keeps the integer
#: PI's state moving (no step repeats, so no memo helps), and four runs of two sections at this
#: cap take ≈ 1.6 s in CPython, the PMSM's worst case.  A default duration beyond it is cut
#: (``complete`` false); a duration typed beyond it is an error naming the field.
MAX_PERIODS = 50_000

#: Vendors with no integer ACIM current PI here, and why (en, zh).
NOT_RUN = {
    "nxp": ("MCAT's ACIM application runs a float PI (GFLIB_CtrlPIpAW_FLT) with its own gains "
            "(profiles.nxp.constants.M1_D_KP_GAIN): no integers to simulate",
            "MCAT 的异步电机应用使用浮点 PI（GFLIB_CtrlPIpAW_FLT）及其自己的增益"
            "（profiles.nxp.constants.M1_D_KP_GAIN）：没有可仿真的整数"),
    "st": ("ST's ACIM current PI integers are not modelled in pu-lab",
           "pu-lab 未建模 ST 异步电机电流 PI 的整数"),
    "microchip": ("no public induction-motor scaling is modelled for this vendor in pu-lab",
                  "pu-lab 未建模该厂商公开的感应电机标定"),
}


def voltage_limits(n: dict) -> tuple[float, float, tuple[int, int] | None]:
    """As :func:`.current.voltage_limits` for an induction motor's normalized input ``n``:
    the seed's pm_maxout_vol and maxu from its raw ``Voltage`` (V) and ``uDCFilter`` (0.1 V),
    which do not depend on the motor kind; None when those do not fit their Uint16."""
    m, d = n["motor"], n["drive"]
    unit = n["conventions"]["inductance_unit"]
    raw = {k: inovance_code.raw_value(k, v, unit)
           for k, v in (("Voltage", m["rated_voltage_v"]), ("uDCFilter", d["udc_v"]))}
    if all(1 <= v <= 0xFFFF for v in raw.values()):
        vol, maxu = inovance_code.max_output_voltage(raw)
        return vol["value"] / 4096.0, maxu["value"] / 16777216.0, (vol["value"], maxu["value"])
    ratio = d["udc_v"] / math.sqrt(2.0) / m["rated_voltage_v"]
    return ratio, ratio, None


def _ti_controller(report: dict, umax_peak: float) -> dict:
    """TI's IQ PI (:func:`pulab.profiles.ti.pi.controller`) with the TI profile's default
    options and its gains of the report's ``current_pi``."""
    n = report["input"]
    ctx = {"udc": n["drive"]["udc_v"], "i_fs": 2.0 * math.sqrt(2.0) * n["motor"]["rated_current_a"],
           "f_base": n["drive"]["base_freq_hz"], "i_rated": n["motor"]["rated_current_a"],
           "ts": n["drive"]["ts_s"], "board": None}
    opt = {o.key: o.default(ctx) for o in ti_scaling.OPTIONS}
    consts = {}
    for axis in ("d", "q"):
        g = report["current_pi"][axis]
        consts.update(ti_scaling.gains_to_ints(g["kp"], g["ki"], ctx, opt, axis))
    return ti_pi.controller({"inputs": opt, "constants": consts}, umax_peak, ctx["udc"])


def _setup(report: dict, cfg: dict, flux: bool) -> dict:
    """Plants, references and starts of one run (:func:`_runs`)."""
    n, a, b = report["input"], report["acim"], report["base"]
    ts, i_b, w_b = n["drive"]["ts_s"], b["I_b"], b["w_b"]
    i_m = a["id_ref_a"]
    if flux:
        ref_d, ref_q, w_r, i0 = i_m, 0.0, 0.0, 0.0
    else:
        step = cfg["step_a"] if cfg["step_a"] is not None else 0.5 * i_b
        ref_d, ref_q = (i_m + step, 0.0) if cfg["axis"] == "d" else (i_m, step)
        for ref in (ref_d, ref_q):
            if abs(ref / i_b) >= Q12_CURRENT_LIMIT_PU:
                raise InputError("sim.current.step_a", code="step_q12", value=step,
                                 pu=ref / i_b, limit=8 * i_b)
        if ref_d <= 0.0:
            raise InputError("sim.current.step_a", code="acim_flux_ref", value=step, im=i_m)
        w_r, i0 = 2.0 * math.pi * cfg["speed_hz"], i_m
    w_e = w_r + ref_q / (a["tau_r_s"] * ref_d)
    if abs(w_e) * ts >= math.pi:
        # the frame's angle step beyond π: the sampled dq model means nothing there
        raise InputError("sim.current.speed_hz", code="speed_nyquist",
                         value=abs(w_e) / (2.0 * math.pi), nyquist=0.5 / ts)
    p = a["pu"]
    si = (a["rs_ohm"], a["rr_ohm"], a["ls_h"], a["lr_h"], a["lm_h"])
    pu = tuple(p[k] for k in ("rs_ohm", "rr_ohm", "ls_h", "lr_h", "lm_h"))
    return {"ts": ts, "ref_d": ref_d, "ref_q": ref_q, "w_e": w_e, "w_r": w_r,
            "z_si": lambda: acim_zoh(*si, w_e, w_r, ts, (i0, 0.0, a["lm_h"] * i0, 0.0)),
            "z_pu": lambda: acim_zoh(*pu, w_e / w_b, w_r / w_b, ts * w_b,
                                     (i0 / i_b, 0.0, p["lm_h"] * i0 / i_b, 0.0)),
            # the voltages that held the magnetized state before the step (0 for the flux)
            "hold": (a["rs_ohm"] * i0, w_r * a["ls_h"] * i0)}


def _runs(report: dict, n_steps: int, s: dict, delay: bool):
    """Every variant of one run: currents, voltages, saturation, flux (SI)."""
    b, pi = report["base"], report["current_pi"]
    i_b, u_b, psi_b = b["I_b"], b["U_b"], b["psi_b"]
    gd, gq = pi["d"], pi["q"]
    ts = s["ts"]
    umax_pu, imax_pu, ints = voltage_limits(report["input"])
    hd, hq = s["hold"]
    out, by_profile = {}, {}
    z = s["z_si"]()
    out["si"] = yield from run_float_steps(z, gd["kp"], gd["ki"] * ts, gq["kp"], gq["ki"] * ts,
                                           umax_pu * u_b, imax_pu * u_b, s["ref_d"], s["ref_q"],
                                           hq, n_steps, delay, integ_d0=hd)
    out["si"]["psi_d"], out["si"]["psi_q"] = z.flux[0]
    z = s["z_pu"]()
    p = yield from run_float_steps(z, gd["kp_pu"], gd["ki_pu"] * ts, gq["kp_pu"],
                                   gq["ki_pu"] * ts, umax_pu, imax_pu, s["ref_d"] / i_b,
                                   s["ref_q"] / i_b, hq / u_b, n_steps, delay,
                                   integ_d0=hd / u_b)
    out["pu"] = {"id": [x * i_b for x in p["id"]], "iq": [x * i_b for x in p["iq"]],
                 "ud": [x * u_b for x in p["ud"]], "uq": [x * u_b for x in p["uq"]],
                 "sat": p["sat"], "psi_d": [x * psi_b for x in z.flux[0][0]],
                 "psi_q": [x * psi_b for x in z.flux[0][1]]}
    yield
    if ints is not None:
        maxout, maxu = ints
        z = s["z_si"]()
        f = yield from run_fixed_steps(
            z, i_b, u_b, gd["pm_kp"], gd["pm_ki"], gq["pm_kp"], gq["pm_ki"], maxu, maxout,
            round_half_away(s["ref_d"] / i_b * 4096.0), round_half_away(s["ref_q"] / i_b * 4096.0),
            round_half_away(hq / u_b * 16777216.0), n_steps, delay,
            integ_d0=round_half_away(hd / u_b * 16777216.0))
        f["psi_d"], f["psi_q"] = z.flux[0]
        out["fixed"] = f
    peak = math.sqrt(2.0) if report["input"]["conventions"]["base"] == "rms" else 1.0
    z = s["z_si"]()
    ti = yield from run_profile_steps(z, _ti_controller(report, umax_pu * u_b * peak), peak,
                                      s["ref_d"], s["ref_q"], hq, n_steps, delay, hold_d_v=hd)
    ti["psi_d"], ti["psi_q"] = z.flux[0]
    by_profile["ti"] = ti
    return out, by_profile, ints


def _flux95(t, psi: list, target: float) -> float | None:
    for k, x in enumerate(psi):
        if x >= 0.95 * target:
            return t[k]
    return None


def _max_diff(a: dict, b: dict, keys: tuple) -> float:
    return max(max(abs(x - y) for x, y in zip(a[k], b[k])) for k in keys)


def _section(report: dict, cfg: dict, flux: bool, delay: bool):
    """One run (``current`` or ``flux``) as the report shows it."""
    from . import decimate_indices
    a = report["acim"]
    ts = report["input"]["drive"]["ts_s"]
    s = _setup(report, cfg, flux)
    field = "sim.flux.duration_s" if flux else "sim.current.duration_s"
    if cfg["duration_s"] is not None:
        n_steps = periods(cfg["duration_s"], ts, MAX_PERIODS, field)
        complete = True
    else:
        # flux: 5·τ_r (99.3 %); current: as the PMSM's, 30 closed-loop time constants on σ·L_s
        want = 5.0 * a["tau_r_s"] if flux else \
            30.0 * a["sigma_ls_h"] / report["current_pi"][cfg["axis"]]["kp"]
        n_want = max(200, int(round(want / ts)))
        n_steps, complete = min(n_want, MAX_PERIODS), n_want <= MAX_PERIODS
    runs, by_profile, ints = yield from _runs(report, n_steps, s, delay)
    t = array("d", (k * ts for k in range(n_steps + 1)))
    idx = decimate_indices(len(t))
    keys = ("id", "iq", "ud", "uq", "psi_d", "psi_q")
    axis = "d" if flux else cfg["axis"]
    ref = s["ref_d"] if axis == "d" else s["ref_q"]
    # the step's own size: the d step starts from I_m, so its metrics are of i_d − I_m
    base = 0.0 if flux or axis == "q" else a["id_ref_a"]
    psi_ref = a["lm_h"] * s["ref_d"]
    si = runs["si"]
    variants, metrics = {}, {}
    for name, v in list(runs.items()) + [("ti", by_profile["ti"])]:
        y = [x - base for x in v["id" if axis == "d" else "iq"]]
        m = step_metrics(t, y, ref - base, v["sat"], ts)
        if flux:
            m["flux_95_s"] = _flux95(t, v["psi_d"], psi_ref)
        m["psi_final_wb"] = v["psi_d"][-1]
        if name != "si":
            m["vs_si_max_abs_a"] = _max_diff(v, si, ("id", "iq"))
            m["vs_si_max_psi_wb"] = _max_diff(v, si, ("psi_d",))
        row = {k: [v[k][i] for i in idx] for k in keys}
        if name == "ti":
            m["vs_si_max_lsb"] = m["vs_si_max_abs_a"] / v["lsb_a"]
            by_profile["ti"] = {"ran": True, "lsb_a": v["lsb_a"], "events": v["events"],
                                "variant": row, "metrics": m}
        else:
            variants[name] = row
            metrics[name] = m
        yield
    if "fixed" in runs:
        metrics["fixed"]["vs_si_max_lsb"] = metrics["fixed"]["vs_si_max_abs_a"] / (
            report["base"]["I_b"] / 4096.0)
        metrics["fixed"]["wraps"] = runs["fixed"]["wraps"]
    for name, (en, zh) in NOT_RUN.items():
        by_profile[name] = {"ran": False, "reason": en, "reason_zh": zh}
    out = {"t": [t[i] for i in idx], "complete": complete, "axis": axis, "ref_d_a": s["ref_d"],
           "ref_q_a": s["ref_q"], "omega_e_rad_s": s["w_e"], "omega_r_rad_s": s["w_r"], "psi_ref_wb": psi_ref,
           "variants": variants, "metrics": metrics, "by_profile": by_profile,
           "fixed": None if ints is None else {"pm_maxout_vol": ints[0], "maxu": ints[1]}}
    if flux:
        out["flux_95_model_s"] = a["flux_95_s"]
    return out


def simulate_steps(report: dict, cfg: dict):
    """The ``sim`` section of an induction motor's report (docs/contract.md, "Induction
    motor: simulation"): ``current`` and ``flux`` (module docstring).

    Parameters
    ----------
    report : dict — the induction motor's report (``input``, ``base``, ``acim``, ``current_pi``)
    cfg : dict — the validated ``sim`` (:func:`pulab.analyses.sim.validate`, ``acim`` true)

    Returns
    -------
    generator — yields between slices, returns ``{"current": …, "flux": …, "pll": …}`` (the
    PLL as for a PMSM: it tracks an angle, whatever the motor)

    Raises
    ------
    InputError
        ``sim.current.step_a`` (beyond Q12, or an i_d* at or below 0),
        ``sim.current.speed_hz`` (the frame's step beyond half a turn a period),
        ``sim.current.duration_s``/``sim.flux.duration_s`` (too many periods).
    """
    from . import _pll_section
    delay = cfg["current"]["delay"]
    current = yield from _section(report, cfg["current"], False, delay)
    flux = yield from _section(report, cfg["flux"], True, delay)
    pll = yield from _pll_section(report, cfg["pll"])
    return {"current": current, "flux": flux, "pll": pll}


def simulate(report: dict, cfg: dict) -> dict:
    """:func:`simulate_steps` run to the end."""
    return finish(simulate_steps(report, cfg))

