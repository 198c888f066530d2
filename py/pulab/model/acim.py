"""The induction motor (ACIM) in per unit: T-equivalent circuit, slip, rotor flux.

Per phase, referred to the stator (R_s, R_r, L_ls, L_lr, L_m)::

    L_s = L_ls + L_m,  L_r = L_lr + L_m,  σ = 1 − L_m²/(L_s·L_r)
    τ_r = L_r/R_r,  τ_s = L_s/R_s
    n_s = 60·f_n/p,  s = (n_s − n)/n_s,  f_sl = s·f_n
    I_m given, or the no-load current U_ph/(2π·f_n·L_s) (R_s neglected)
    ψ_r = L_m·I_m (RMS; × √2 in the peak and custom conventions, like the PMSM's ψ_r)
    k_T = 3·p·(L_m²/L_r)·I_m   N·m per A RMS of torque current at rated flux

In rotor-flux orientation the stator current loop sees, on both axes,
u = R_σ·i + σ·L_s·di/dt (rotor flux held), with R_σ = R_s + R_r·(L_m/L_r)²: the same
first-order plant as the PMSM's R_s + s·L, so the same PI design, delays and margins apply
(:mod:`pulab.analyses.loop`).  The current-model observer integrates
τ_r·dψ_r/dt + ψ_r = L_m·i_d (exactly for a held i_d: a = e^{−T_s/τ_r}, b = L_m·(1 − a));
the slip estimator is ω_sl = i_q/(τ_r·i_d).  A vendor's L_ms = 2/3·L_m (the steady-state
per-phase magnetizing inductance of ST's ACIM GUI) is converted by
:func:`circuit`.

Examples
--------
>>> from pulab.model.bases import bases
>>> m = {"rated_voltage_v": 42 * 3 ** 0.5, "rated_current_a": 1.5, "rated_freq_hz": 50.0,
...      "rated_speed_rpm": 1370.0, "pole_pairs": 2, "rs_ohm": 0.6, "rr_ohm": 0.4,
...      "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525, "ls_h": None, "lr_h": None,
...      "magnetizing_current_a": 0.55}
>>> a = model(m, None, bases("rms", m["rated_voltage_v"], 1.5, 50.0), "rms", 1e-4)
>>> round(a["sigma"], 7), a["tau_r_s"], round(a["rated_slip"], 6)
(0.2712671, 0.15375, 0.086667)
"""

from __future__ import annotations

import math

from ..schema.errors import InputError
from .datasheet import both_given

__all__ = ["circuit", "model", "PU_KEYS"]

SQRT2 = math.sqrt(2.0)
SQRT3 = math.sqrt(3.0)
#: ln 20: the rotor flux reaches 95 % of its final value after ln 20·τ_r ≈ 3·τ_r.
LN20 = math.log(20.0)
#: Each per-unit key and the base it is divided by (None: dimensionless, as it is).
PU_KEYS = (("rs_ohm", "Z_b"), ("rr_ohm", "Z_b"), ("r_sigma_ohm", "Z_b"),
           ("lls_h", "L_b"), ("llr_h", "L_b"), ("lm_h", "L_b"), ("lms_h", "L_b"),
           ("ls_h", "L_b"), ("lr_h", "L_b"), ("sigma_ls_h", "L_b"),
           ("tau_r_s", "T_b"), ("tau_s_s", "T_b"), ("tau_sigma_s", "T_b"),
           ("magnetizing_current_a", "I_b"), ("torque_current_a", "I_b"),
           ("rotor_flux_wb", "psi_b"), ("slip_freq_hz", "f_b"),
           ("rated_slip", None), ("sigma", None))


def _leakage(m: dict, own: str, total: str, lm: float) -> float:
    """L_ls (or L_lr) from the field ``own``, or from ``total`` = L_s (L_r) minus L_m."""
    if m[own] is not None and m[total] is not None:
        raise both_given(f"motor.{total}", f"motor.{own}", f"motor.{own}")
    if m[own] is not None:
        return m[own]
    if m[total] is None:
        raise InputError(f"motor.{own}", code="required_or", alternatives=f"motor.{total}")
    if m[total] <= lm:
        raise InputError(f"motor.{total}", code="acim_self_le_lm", lm=lm, value=m[total])
    return m[total] - lm


def circuit(m: dict, lms_h: float | None) -> tuple[float, float, float]:
    """(L_m, L_ls, L_lr) in H from the motor fields and an optional datasheet L_ms.

    Parameters
    ----------
    m : dict — the normalized ``motor`` of an induction motor (``lm_h``, ``lls_h``,
        ``llr_h``, ``ls_h``, ``lr_h``; absent ones None)
    lms_h : float or None, H — ``datasheet.lms_h``: L_m = 1.5·L_ms

    Raises
    ------
    InputError
        Naming the field: L_m given twice or not at all, a leakage given both ways or not
        at all, L_s or L_r not above L_m.

    Examples
    --------
    >>> m = {"lm_h": None, "lls_h": None, "llr_h": 0.009, "ls_h": 0.0615, "lr_h": None}
    >>> [round(x, 6) for x in circuit(m, 0.035)]
    [0.0525, 0.009, 0.009]
    """
    if m["lm_h"] is not None and lms_h is not None:
        raise both_given("datasheet.lms_h", "motor.lm_h", "motor.lm_h")
    if m["lm_h"] is None and lms_h is None:
        raise InputError("motor.lm_h", code="required_or", alternatives="datasheet.lms_h")
    lm = m["lm_h"] if m["lm_h"] is not None else 1.5 * lms_h
    return lm, _leakage(m, "lls_h", "ls_h", lm), _leakage(m, "llr_h", "lr_h", lm)


def model(m: dict, lms_h: float | None, b: dict, base: str, ts_s: float) -> dict:
    """The report's ``acim`` section (docs/contract.md, "Induction motor").

    Parameters
    ----------
    m : dict — normalized ``motor`` with ``kind`` = ``acim`` (SI: V line RMS, A RMS, Hz,
        rpm, Ω, H)
    lms_h : float or None, H — ``datasheet.lms_h``
    b : dict — the bases (:func:`pulab.model.bases.bases`)
    base : {'rms', 'peak', 'custom'} — the convention (the dq scaling of flux and current)
    ts_s : float > 0, s — the control period (the observer's discretization)

    Returns
    -------
    dict
        SI values (see the module docstring and the contract), ``observer``, ``pu``.

    Raises
    ------
    InputError
        ``motor.rated_speed_rpm`` not below the synchronous speed; the inductance errors of
        :func:`circuit`.
    """
    lm, lls, llr = circuit(m, lms_h)
    rs, rr, p, f_n = m["rs_ohm"], m["rr_ohm"], m["pole_pairs"], m["rated_freq_hz"]
    ls, lr = lls + lm, llr + lm
    n_s = 60.0 * f_n / p
    if m["rated_speed_rpm"] >= n_s:
        raise InputError("motor.rated_speed_rpm", code="acim_speed_not_below_sync", sync=n_s,
                         value=m["rated_speed_rpm"])
    slip = (n_s - m["rated_speed_rpm"]) / n_s
    sigma = 1.0 - lm * lm / (ls * lr)
    r_sigma = rs + rr * (lm / lr) ** 2
    tau_r = lr / rr
    given = m["magnetizing_current_a"] is not None
    i_m = m["magnetizing_current_a"] if given else \
        m["rated_voltage_v"] / SQRT3 / (2.0 * math.pi * f_n * ls)
    i_n = m["rated_current_a"]
    i_q = math.sqrt(i_n * i_n - i_m * i_m) if i_m < i_n else None
    dq = 1.0 if base == "rms" else SQRT2     # RMS → the convention's dq magnitude
    kt = 3.0 * p * lm * lm / lr * i_m
    a_zoh = math.exp(-ts_s / tau_r)
    out = {"rs_ohm": rs, "rr_ohm": rr, "lls_h": lls, "llr_h": llr, "lm_h": lm,
           "lms_h": lm / 1.5, "ls_h": ls, "lr_h": lr, "sigma": sigma, "sigma_ls_h": sigma * ls,
           "r_sigma_ohm": r_sigma, "tau_r_s": tau_r, "tau_s_s": ls / rs,
           "tau_sigma_s": sigma * ls / r_sigma, "sync_speed_rpm": n_s, "rated_slip": slip,
           "slip_freq_hz": slip * f_n, "magnetizing_current_a": i_m,
           "magnetizing_from": "given" if given else "no_load_estimate",
           "id_ref_a": dq * i_m, "torque_current_a": i_q,
           "rotor_flux_wb": dq * lm * i_m, "torque_per_amp_nm": kt,
           "rated_torque_nm": None if i_q is None else kt * i_q,
           "slip_freq_model_hz": None if i_q is None else i_q / (2.0 * math.pi * tau_r * i_m),
           "slip_gain_per_s": 1.0 / tau_r, "flux_95_s": LN20 * tau_r,
           "observer": {"a": a_zoh, "b_h": lm * (1.0 - a_zoh),
                        "a_euler": tau_r / (tau_r + ts_s),
                        "b_euler_h": lm * ts_s / (tau_r + ts_s)}}
    # a current in per unit is its dq value (RMS × dq) over I_b, like i_d and i_q
    pu = {k: None if out[k] is None else
          out[k] * (dq if base_key == "I_b" else 1.0) / (b[base_key] if base_key else 1.0)
          for k, base_key in PU_KEYS}
    pu["id_ref_a"] = pu["magnetizing_current_a"]
    pu["slip_gain_per_s"] = out["slip_gain_per_s"] / b["w_b"]
    # torque per unit dq current over T_mb = P_b·p/ω_b (k_T is per A RMS)
    pu["torque_per_amp_nm"] = kt / dq * b["I_b"] / (b["P_b"] * p / b["w_b"])
    pu["observer_b"] = out["observer"]["b_h"] / b["L_b"]
    out["pu"] = pu
    return out
