"""The firmware PI as a discrete transfer function (seed 2.2, vendor order).

The vendor code adds the integral first, then the proportional part::

    I_k = I_{k−1} + ki·T_s·e_k,   u_k = kp·e_k + I_k

so C(z) = U/E = kp + ki·T_s·z/(z − 1) = ((kp + ki·T_s)·z − kp)/(z − 1): the
integral acts in the same sample (backward Euler).  The current PI, the PLL PI
(:mod:`pulab.analyses.sim.pll`) and the speed PI all have this form.

Examples
--------
>>> pi(2.0, 100.0, 0.01)
([3.0, -2.0], [1.0, -1.0])
"""

from __future__ import annotations

__all__ = ["pi"]


def pi(kp: float, ki: float, ts: float) -> tuple:
    """(N_c, D_c) of the firmware PI.

    Parameters
    ----------
    kp : float, output unit per error unit ; ki : float, per second
    ts : float > 0, seconds — the PI's sample time
    """
    return [kp + ki * ts, -kp], [1.0, -1.0]
