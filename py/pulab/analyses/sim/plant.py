"""The PMSM dq current model, discretized exactly for a zero-order-hold input.

Continuous model (seed 1.2-3, the same form in SI and in per unit, seed 1.2-2)::

    di_d/dt = (u_d − R_s·i_d + ω_e·L_q·i_q) / L_d
    di_q/dt = (u_q − R_s·i_q − ω_e·(L_d·i_d + ψ_r)) / L_q

with L_d ≠ L_q allowed, the cross-coupling at a constant electrical speed ω_e
and the back-EMF ω_e·ψ_r.  Written as ẋ = A·x + B·(u + w) with x = (i_d, i_q),
B = diag(1/L_d, 1/L_q) and the constant w = (0, −ω_e·ψ_r).

Discretization: **exact zero-order hold** (not RK4).  Between two controller
samples the inverter holds u constant, so over one period T_s::

    x[k+1] = Φ·x[k] + Γ·(u[k] + w),   Φ = e^{A·T_s},   Γ = ∫₀^{T_s} e^{A·τ} dτ · B

Φ and Γ come from one matrix exponential of the augmented 4×4 matrix
(Van Loan): exp([[A, B], [0, 0]]·T_s) = [[Φ, Γ], [0, I]].  This is exact for
any ω_c·T_s (no second Euler error on top of the controller's, unlike the seed's
1.2-4), and each step costs 8 multiplies.  The eigenvalues p of A map to
e^{p·T_s} of Φ (tests check this and the DC gain).

The per-unit plant is the same function called with per-unit R_s, L_d, L_q,
ψ_r, ω_e and the per-unit period T_s·ω_b (seed 1.2-1: time is normalized by
1/ω_b), which is the seed's point: the model code is unchanged.

Examples
--------
>>> z = zoh(1.5, 6e-4, 6e-4, 0.0, 0.0, 1e-4)           # locked rotor, SI
>>> import math; abs(z.phi[0] - math.exp(-1.5 / 6e-4 * 1e-4)) < 1e-15
True
"""

from __future__ import annotations

from typing import NamedTuple

from .linalg import expm

__all__ = ["Zoh", "zoh", "continuous_matrices"]


class Zoh(NamedTuple):
    """One-period transition of the dq plant (row-major 2×2 matrices).

    Attributes
    ----------
    phi : tuple of 4 floats
        Φ = e^{A·T_s} as (Φ_dd, Φ_dq, Φ_qd, Φ_qq).
    gamma : tuple of 4 floats
        Γ in current per voltage (A/V in SI, pu/pu in per unit), same order.
    bemf : float
        ω_e·ψ_r, the back-EMF on the q axis (V or pu); u_q − bemf drives Γ.
    """

    phi: tuple
    gamma: tuple
    bemf: float


def continuous_matrices(rs: float, ld: float, lq: float, omega: float) -> tuple:
    """A and B of ẋ = A·x + B·(u + w) (seed 1.2-3).

    Parameters
    ----------
    rs : float > 0, Ω or pu ; ld, lq : float > 0, H or pu
    omega : float, electrical rad/s or pu (ω_e/ω_b); any sign, 0 = locked rotor

    Returns
    -------
    (A, B) : 2×2 lists of lists
    """
    a = [[-rs / ld, omega * lq / ld],
         [-omega * ld / lq, -rs / lq]]
    b = [[1.0 / ld, 0.0], [0.0, 1.0 / lq]]
    return a, b


def zoh(rs: float, ld: float, lq: float, psi: float, omega: float, ts: float) -> Zoh:
    """Exact zero-order-hold discretization of the dq plant over one period.

    Parameters
    ----------
    rs : float > 0, Ω (SI) or pu
    ld, lq : float > 0, H (SI) or pu
    psi : float ≥ 0, Wb (SI) or pu — permanent-magnet flux ψ_r
    omega : float, rad/s electrical (SI) or pu — constant speed during the run
    ts : float > 0, s (SI) or pu time (T_s·ω_b)

    Returns
    -------
    Zoh
    """
    a, b = continuous_matrices(rs, ld, lq, omega)
    aug = [[a[0][0] * ts, a[0][1] * ts, b[0][0] * ts, b[0][1] * ts],
           [a[1][0] * ts, a[1][1] * ts, b[1][0] * ts, b[1][1] * ts],
           [0.0, 0.0, 0.0, 0.0],
           [0.0, 0.0, 0.0, 0.0]]
    e = expm(aug)
    return Zoh((e[0][0], e[0][1], e[1][0], e[1][1]),
               (e[0][2], e[0][3], e[1][2], e[1][3]),
               omega * psi)
