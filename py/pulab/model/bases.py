"""Base values and per-unit motor parameters (seed 1.1–1.3).

Three conventions for the voltage and current bases:

``rms`` (Inovance, default)
    U_b = U_LL/√3, I_b = I_rms; dq magnitudes are RMS (Clarke k = √2/3);
    P_b = 3·U_b·I_b (seed 3.79).
``peak``
    U_b = √(2/3)·U_LL, I_b = √2·I_rms; amplitude-invariant Clarke k = 2/3;
    P_b = 1.5·U_b·I_b (seed 3.80–3.82).
``custom``
    U_b and I_b given (e.g. the full-scale values TI uses); P_b = 1.5·U_b·I_b.

Every other base follows from U_b, I_b and f_b (seed 1.1-1):
Z_b = U_b/I_b, ω_b = 2π·f_b, L_b = Z_b/ω_b, ψ_b = U_b/ω_b, T_b = 1/ω_b (seed 1.2).

Examples
--------
>>> b = bases("rms", 17.0, 1.5, 220.0)
>>> round(b["Z_b"], 4), round(b["L_b"] * 1e3, 4)      # Ω, mH
(6.5433, 4.7336)
"""

from __future__ import annotations

import math

__all__ = ["bases", "per_unit", "flux_linkage"]

SQRT3 = math.sqrt(3.0)
SQRT2 = math.sqrt(2.0)


def bases(base: str, rated_voltage_v: float, rated_current_a: float, base_freq_hz: float,
          base_voltage_v: float | None = None, base_current_a: float | None = None,
          angle_base: str = "pi") -> dict:
    """Base values in SI.

    Parameters
    ----------
    base : {'rms', 'peak', 'custom'}
    rated_voltage_v : float > 0, volts, line-to-line RMS
    rated_current_a : float > 0, amperes RMS
    base_freq_hz : float > 0, hertz (f_b, the drive's maximum frequency)
    base_voltage_v, base_current_a : float > 0, only for ``custom``
    angle_base : {'pi', '2pi'}
        θ_b; seed section 3 uses π, seed 1.1-1 writes 2π.

    Returns
    -------
    dict
        ``U_b, I_b, f_b, w_b, Z_b, L_b, psi_b, T_b, P_b, theta_b`` in V, A, Hz,
        rad/s, Ω, H, Wb, s, W, rad.
    """
    if base == "rms":
        u_b, i_b, p_k = rated_voltage_v / SQRT3, rated_current_a, 3.0
    elif base == "peak":
        u_b, i_b, p_k = rated_voltage_v * math.sqrt(2.0 / 3.0), SQRT2 * rated_current_a, 1.5
    elif base == "custom":
        u_b, i_b, p_k = base_voltage_v, base_current_a, 1.5
    else:
        raise ValueError(f"unknown base convention {base!r}")
    w_b = 2.0 * math.pi * base_freq_hz
    z_b = u_b / i_b
    return {"U_b": u_b, "I_b": i_b, "f_b": base_freq_hz, "w_b": w_b, "Z_b": z_b,
            "L_b": z_b / w_b, "psi_b": u_b / w_b, "T_b": 1.0 / w_b, "P_b": p_k * u_b * i_b,
            "theta_b": math.pi if angle_base == "pi" else 2.0 * math.pi}


def flux_linkage(base: str, bemf_v: float, rated_freq_hz: float) -> float:
    """Permanent-magnet flux ψ_r in Wb from the line RMS back-EMF at rated frequency.

    In the rms convention ψ_r = E_LL/(√3·2π·f_n) (seed 1.4-22, k = √2/3); the
    peak and custom conventions use amplitude-invariant dq, so ψ_r is √2 larger
    (seed 1.3-2 with k = 2/3).

    >>> round(flux_linkage("rms", 17.0, 220.0), 6)
    0.0071
    """
    psi = bemf_v / (SQRT3 * 2.0 * math.pi * rated_freq_hz)
    return psi if base == "rms" else SQRT2 * psi


def per_unit(b: dict, rs_ohm: float, ld_h: float, lq_h: float, psi_r_wb: float,
             ts_s: float) -> dict:
    """Per-unit Rs, Ld, Lq, ψ_r and Ts (seed 1.1-6, 1.2-1: Ts_pu = Ts·ω_b)."""
    return {"Rs": rs_ohm / b["Z_b"], "Ld": ld_h / b["L_b"], "Lq": lq_h / b["L_b"],
            "psi_r": psi_r_wb / b["psi_b"], "psi_r_wb": psi_r_wb, "Ts": ts_s * b["w_b"]}
