"""The speed loop in per unit: mechanical bases, PI gains in SI, pu and Q format, margins.

Mechanical bases (from the electrical ones of :func:`pulab.model.bases.bases`)::

    ω_mb = ω_b/p                  mechanical rad/s per pu speed (p pole pairs)
    T_mb = P_b/ω_mb               N·m, torque base
    H    = J·ω_mb²/(2·P_b)        s, inertia constant (kinetic energy at base speed / P_b)
    K_t  = (P_b/(U_b·I_b))·p·ψ_r  N·m/A: 3·p·ψ_r for rms bases, 1.5·p·ψ_r for peak/custom

so that T_e/T_mb = ψ_r,pu·i_q,pu and the mechanics J·dω_m/dt = T_e − T_L − B·ω_m
become 2H·dω_pu/dt = ψ_pu·i_q,pu − T_L,pu − B_pu·ω_pu with B_pu = B·ω_mb/T_mb
(the same equation in SI and pu: the seed's point for the electrical model).

Speed PI (the firmware form of :mod:`pulab.analyses.loop.pi`, input ω_m error in rad/s,
output i_q reference in A), designed on K_t/(J·s + B) for a closed loop of
natural frequency ω_n = 2π·bandwidth_hz and damping ζ::

    kp = (2ζω_n·J − B)/K_t [A·s/rad],   ki = ω_n²·J/K_t [A/rad]
    kp_pu = kp·ω_mb/I_b,  ki_pu = ki·ω_mb/I_b [1/s]

Firmware integers, chosen the way the seed chooses the current PI's (2.2-9):
the speed error is Q15 of ω_b (the firmware's speed word, as FreqPer and the
PLL's ω̂ high half), the output is the Q12 current reference (the current
loop's gIMTQ12), so the gains keep the current PI's formats:

    pm_kp_speed = round(kp_pu·2^12)         Q12: out += (e_Q15·pm_kp) >> 15
    pm_ki_speed = round(ki_pu·T_sp·2^16)    Q16, T_sp folded in: I_Q24 += (e_Q15·pm_ki) >> 7

The integral is Q24 (12 bits below the Q12 output, as the current PI's, so an
increment smaller than one output LSB is kept instead of lost); the products
are int64 as IQmath's _IQmpy.  Q12 for kp: kp_pu of speed loops is of order
0.1…1000, which Q12 holds in int32 with a relative step 2^-12/kp_pu; ki·T_sp is
small (≪ 1) and Q16 gives it four more bits, as pm_ki does for the current loop.

Margins, at the speed period T_sp with the inner loop as one T_sp of delay
(the current reference computed at k acts from k + 1; the inner current loop
is assumed settled within one speed period — ``inner_bandwidth_ratio`` tells
how true that is) and the measurement low-pass y_k = y_{k−1} + α·(x_k − y_{k−1}),
α = 1 − e^{−2π·f_f·T_sp}::

    L(z) = C(z) · K_t·γ/(z − φ) · z⁻¹ · α·z/(z − (1 − α))

with φ, γ the exact ZOH of 1/(B + s·J) (:func:`pulab.analyses.sim.plant.zoh`).

Examples
--------
>>> import math
>>> b = mechanical_bases(4, 2 * math.pi * 220, 44.17, 9.815, 1.5, 0.005, 1e-5)
>>> round(b["w_mb"], 4), round(b["torque_nm"], 4), round(b["inertia_constant_s"], 6)
(345.5752, 0.1278, 0.013518)
"""

from __future__ import annotations

import math

from ...schema.errors import InputError
from ...model.gains import INT32_MAX, INT32_MIN
from ..sim.plant import zoh
from ...fixedpoint.qformat import round_half_away
from .discrete import margins
from .pi import pi
from .polynomial import multiply

__all__ = ["mechanical_bases", "design", "integers", "loop", "analyze"]


def mechanical_bases(pole_pairs: int, w_b: float, p_b: float, u_b: float, i_b: float,
                     psi_r: float, inertia: float) -> dict:
    """Mechanical bases and the torque constant.

    Parameters
    ----------
    pole_pairs : int ≥ 1 ; w_b : float > 0, electrical rad/s ; p_b : float > 0, W
    u_b : float > 0, V ; i_b : float > 0, A
    psi_r : float ≥ 0, Wb (in the convention of the bases)
    inertia : float > 0, kg·m²

    Returns
    -------
    dict
        ``w_mb`` (rad/s), ``n_mb_rpm`` (r/min), ``torque_nm`` (T_mb), ``kt_nm_per_a``,
        ``inertia_constant_s`` (H).
    """
    w_mb = w_b / pole_pairs
    return {"w_mb": w_mb, "n_mb_rpm": w_mb * 30.0 / math.pi, "torque_nm": p_b / w_mb,
            "kt_nm_per_a": p_b / (u_b * i_b) * pole_pairs * psi_r,
            "inertia_constant_s": inertia * w_mb * w_mb / (2.0 * p_b)}


def design(kt: float, inertia: float, friction: float, bandwidth_hz: float,
           damping: float) -> tuple:
    """SI speed PI gains (kp [A·s/rad], ki [A/rad]) for ω_n, ζ on K_t/(J·s + B).

    Raises
    ------
    InputError
        ``analysis.speed.bandwidth_hz`` when kp = (2ζω_n·J − B)/K_t ≤ 0.
    """
    wn = 2.0 * math.pi * bandwidth_hz
    kp = (2.0 * damping * wn * inertia - friction) / kt
    if kp <= 0:
        raise InputError("analysis.speed.bandwidth_hz", code="speed_kp_low", kp=kp)
    return kp, wn * wn * inertia / kt


def integers(kp: float, ki: float, w_mb: float, i_b: float, ts: float) -> dict:
    """Per-unit gains and firmware integers (Q12 kp, Q16 ki·T_sp), and back.

    Raises
    ------
    InputError
        ``analysis.speed.bandwidth_hz`` when an integer does not fit int32.
    """
    kp_pu, ki_pu = kp * w_mb / i_b, ki * w_mb / i_b
    pm_kp = round_half_away(kp_pu * 4096.0)
    pm_ki = round_half_away(ki_pu * ts * 65536.0)
    for name, v in (("pm_kp", pm_kp), ("pm_ki", pm_ki)):
        if not INT32_MIN <= v <= INT32_MAX:
            raise InputError("analysis.speed.bandwidth_hz", code="long_overflow", what=f"speed {name}",
                             value=v)
    return {"kp": kp, "ki": ki, "kp_pu": kp_pu, "ki_pu": ki_pu, "pm_kp": pm_kp, "pm_ki": pm_ki,
            "from_integers": {"kp": pm_kp / 4096.0 * i_b / w_mb,
                              "ki": pm_ki / 65536.0 / ts * i_b / w_mb}}


def loop(kp: float, ki: float, kt: float, inertia: float, friction: float, filter_hz: float,
         ts: float) -> tuple:
    """(N, D) of the speed open loop at T_sp (module docstring)."""
    mech = zoh(friction, inertia, inertia, 0.0, 0.0, ts)
    alpha = 1.0 - math.exp(-2.0 * math.pi * filter_hz * ts)
    nc, dc = pi(kp, ki, ts)
    num = multiply(nc, [kt * mech.gamma[0] * alpha, 0.0])
    den = multiply(multiply(dc, [1.0, -mech.phi[0]]), multiply([1.0, 0.0], [1.0, alpha - 1.0]))
    return num, den


def analyze(cfg: dict, kt: float, w_mb: float, i_b: float) -> dict:
    """Design, integers and margins (design gains and rounded integers) of the speed loop.

    Parameters
    ----------
    cfg : dict — the resolved ``analysis.speed`` input (every default filled)
    kt : float > 0, N·m/A ; w_mb : float > 0, rad/s ; i_b : float > 0, A
    """
    j, b, ts = cfg["inertia_kg_m2"], cfg["friction_nm_s"], cfg["ts_s"]
    kp, ki = design(kt, j, b, cfg["bandwidth_hz"], cfg["damping"])
    gains = integers(kp, ki, w_mb, i_b, ts)
    out = {**gains, **margins(*loop(kp, ki, kt, j, b, cfg["filter_hz"], ts), ts)}
    back = gains["from_integers"]
    out["firmware"] = margins(*loop(back["kp"], back["ki"], kt, j, b, cfg["filter_hz"], ts), ts)
    return out
