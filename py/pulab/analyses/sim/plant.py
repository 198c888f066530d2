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

from array import array
from typing import NamedTuple

from .linalg import expm

__all__ = ["Zoh", "zoh", "continuous_matrices", "AcimZoh", "acim_zoh"]


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

    @property
    def x0(self) -> tuple:
        """The currents (i_d, i_q) at t = 0: none."""
        return 0.0, 0.0

    def advance(self):
        """A function (i_d, i_q, u_d, u_q) → (i_d, i_q) one period later, for the loops of
        :mod:`.current` and :mod:`.vendor_loop` (an induction motor's carries its rotor flux,
        :class:`AcimZoh`)."""
        p0, p1, p2, p3 = self.phi
        g0, g1, g2, g3 = self.gamma
        bemf = self.bemf

        def step(xd, xq, ad, aq):
            vq = aq - bemf
            return p0 * xd + p1 * xq + g0 * ad + g1 * vq, p2 * xd + p3 * xq + g2 * ad + g3 * vq
        return step


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


class AcimZoh(NamedTuple):
    """One-period transition of the induction motor's dq model (:func:`acim_zoh`).

    Attributes
    ----------
    phi : tuple of 16 floats — Φ (4×4, row-major) over (i_d, i_q, ψ_rd, ψ_rq)
    gamma : tuple of 8 floats — Γ (4×2, row-major), the voltages (u_d, u_q) in
    start : tuple of 4 floats — the state at t = 0
    flux : list — each :meth:`advance` appends its ψ_rd and ψ_rq records (arrays, one
        sample per call, the flux at the sample the currents are read)
    """

    phi: tuple
    gamma: tuple
    start: tuple
    flux: list

    @property
    def x0(self) -> tuple:
        """The currents (i_d, i_q) at t = 0."""
        return self.start[0], self.start[1]

    def advance(self):
        """As :meth:`Zoh.advance`; the rotor flux is the closure's own state, recorded."""
        (a0, a1, a2, a3, b0, b1, b2, b3, c0, c1, c2, c3, d0, d1, d2, d3) = self.phi
        g0, g1, g2, g3, g4, g5, g6, g7 = self.gamma
        rec_d, rec_q = array("d"), array("d")
        self.flux.append((rec_d, rec_q))
        put_d, put_q = rec_d.append, rec_q.append
        fd, fq = self.start[2], self.start[3]

        def step(xd, xq, ad, aq):
            nonlocal fd, fq
            put_d(fd)
            put_q(fq)
            yd = a0 * xd + a1 * xq + a2 * fd + a3 * fq + g0 * ad + g1 * aq
            yq = b0 * xd + b1 * xq + b2 * fd + b3 * fq + g2 * ad + g3 * aq
            fd, fq = (c0 * xd + c1 * xq + c2 * fd + c3 * fq + g4 * ad + g5 * aq,
                      d0 * xd + d1 * xq + d2 * fd + d3 * fq + g6 * ad + g7 * aq)
            return yd, yq
        return step


def acim_zoh(rs: float, rr: float, ls: float, lr: float, lm: float, omega_e: float,
             omega_r: float, ts: float, start: tuple = (0.0, 0.0, 0.0, 0.0)) -> AcimZoh:
    """Exact zero-order-hold discretization of the induction motor in a frame turning at ω_e.

    Stator current i and rotor flux ψ (per phase, referred to the stator) as complex
    vectors in a frame turning at ω_e, the rotor turning at ω_r (electrical)::

        σL_s·di/dt = u − R_σ·i − jω_e·σL_s·i + (L_m/L_r)·(1/τ_r − jω_r)·ψ
            dψ/dt  = (L_m/τ_r)·i − ψ/τ_r − j(ω_e − ω_r)·ψ

    with σ = 1 − L_m²/(L_s·L_r), τ_r = L_r/R_r, R_σ = R_s + R_r·(L_m/L_r)².  Linear for
    constant ω_e and ω_r, so Φ and Γ come from one 6×6 matrix exponential as for the PMSM.
    In rotor-flux orientation (ψ_rq = 0) with ψ_rd held, the current sees the first-order
    plant R_σ + s·σL_s (:mod:`pulab.model.acim`); ψ_rd follows i_d with τ_r.  The same
    function takes SI (Ω, H, rad/s, s; Wb) or per-unit values.

    Parameters
    ----------
    rs, rr : float > 0, Ω ; ls, lr, lm : float > 0, H, with L_m² < L_s·L_r
    omega_e, omega_r : float, rad/s electrical — the frame's and the rotor's speed
    ts : float > 0, s ; start : (i_d, i_q, ψ_rd, ψ_rq) at t = 0, A and Wb

    Returns
    -------
    AcimZoh

    Examples
    --------
    Held i_d: the rotor flux settles at L_m·i_d, and u_d = R_s·i_d then keeps i_d.

    >>> z = acim_zoh(0.6, 0.4, 0.0615, 0.0615, 0.0525, 0.0, 0.0, 1e-4, (1.0, 0.0, 0.0525, 0.0))
    >>> step = z.advance()
    >>> [round(x, 12) for x in step(1.0, 0.0, 0.6, 0.0)]
    [1.0, 0.0]
    """
    s_ls = ls - lm * lm / lr
    kr, tr = lm / lr, lr / rr
    r_sig = rs + rr * kr * kr
    w_sl = omega_e - omega_r
    a = [[-r_sig / s_ls, omega_e, kr / (tr * s_ls), kr * omega_r / s_ls],
         [-omega_e, -r_sig / s_ls, -kr * omega_r / s_ls, kr / (tr * s_ls)],
         [lm / tr, 0.0, -1.0 / tr, w_sl],
         [0.0, lm / tr, -w_sl, -1.0 / tr]]
    aug = [[x * ts for x in row] + [(1.0 / s_ls if i == j else 0.0) * ts for j in range(2)]
           if i < 2 else [x * ts for x in row] + [0.0, 0.0] for i, row in enumerate(a)]
    aug += [[0.0] * 6, [0.0] * 6]
    e = expm(aug)
    return AcimZoh(tuple(e[i][j] for i in range(4) for j in range(4)),
                   tuple(e[i][4 + j] for i in range(4) for j in range(2)),
                   tuple(float(x) for x in start), [])
