"""The current loop as the firmware runs it: ZOH plant, PI form, delays.

Per axis, on the zero-speed plant G(s) = 1/(R_s + s·L) (L = L_d or L_q; the
cross-coupling ω_e·L vanishes at standstill), discretized exactly for a
zero-order hold (a = e^{−R_s·T_s/L},
b = (1 − a)/R_s).  The firmware PI (seed 2.2, vendor order)::

    I_k = I_{k−1} + ki·T_s·e_k,   u_k = kp·e_k + I_k
    C(z) = ((kp + ki·T_s)·z − kp) / (z − 1)

Delay models (``analysis.delay``), with the plant P(z) = N_p(z)/D_p(z):

``none``
    u_k is applied at once: P = b/(z − a).
``computation``
    u_k is computed from i_k and loaded at the next PWM update, exactly one
    sample later: P = b/(z·(z − a)).
``computation_pwm`` (default)
    one sample, plus the PWM: a centre-aligned PWM realizes its average voltage
    half a period after the update, so the plant sees u_{k−1} from
    t_k + T_s/2 to t_{k+1} + T_s/2.  This is modelled **exactly** as the ZOH of
    the plant with an input delay of T_s/2 (modified z-transform, m = 1/2):
    over [t_k, t_{k+1}) the first half carries u_{k−2}, the second u_{k−1}, so
    i_{k+1} = a·i_k + γ_h·u_{k−1} + φ_h·γ_h·u_{k−2} with φ_h, γ_h the ZOH of
    half a period; P = γ_h·(z + φ_h)/(z²·(z − a)).  Rational, so the margins
    stay exact (no Padé approximation).

Design with the delay accounted for (``analysis.design``): the PI zero is put
on the discrete plant pole, kp/(kp + ki·T_s) = a, i.e. ki·T_s = kp·(1/a − 1)
(discrete pole-zero cancellation); then L = kp·S(z) with S fixed by the plant
and the delay, and

- ``phase_margin``: the θ_c = ω_c·T_s where 180° + arg S = PM target (the first
  from below, bracketed on a 64-point scan and bisected), kp = 1/|S(e^{jθ_c})|;
- ``bandwidth``: |kp·S/(1 + kp·S)| = 1/√2 at the target, which is a quadratic
  in kp: kp = (Re S + √((Re S)² + |S|²))/|S|².

Beside it, the continuous-time design an engineer would do by hand
(kp = ω_c·L, ki = ω_c·R_s, the seed's 2.1): for a bandwidth target
ω_c = 2π·f_target, for a PM target ω_c = (90° − PM)/T_d with the loop delay
taken as dead time T_d = T_s/2 (the hold) + T_s per computation delay
+ T_s/2 for the PWM; its true discrete margins and its error are reported.

Examples
--------
>>> r = axis_loop(1.5, 6e-4, 1e-4, 1.885, 4712.4, "none")   # seed motor, 500 Hz design
>>> round(r["phase_margin_deg"], 3)
83.238
"""

from __future__ import annotations

import cmath
import math
from functools import lru_cache

from ...schema.errors import InputError
from .discrete import margins
from .pi import pi
from .polynomial import multiply

__all__ = ["DELAYS", "plant", "loop", "axis_loop", "design", "dead_time"]

DELAYS = ("none", "computation", "computation_pwm")


@lru_cache(maxsize=64)
def _hold(rs: float, l_h: float, ts: float) -> tuple:
    """(φ, γ) of the scalar plant 1/(R_s + s·L) over ts, in closed form.

    φ = e^{−R_s·ts/L}, γ = (1 − φ)/R_s (expm1 keeps γ exact when R_s·ts/L is tiny); the same
    numbers as :func:`pulab.analyses.sim.plant.zoh` at zero speed, at a quarter of its cost,
    which the robustness analysis pays once per drifted plant."""
    x = -rs * ts / l_h
    return math.exp(x), -math.expm1(x) / rs


def plant(rs: float, l_h: float, ts: float, delay: str) -> tuple:
    """(N_p, D_p) of the zero-speed ZOH plant in A/V, with the delay model.

    Parameters
    ----------
    rs : float > 0, Ω ; l_h : float > 0, H ; ts : float > 0, s
    delay : {'none', 'computation', 'computation_pwm'}

    Examples
    --------
    >>> n, d = plant(1.0, 1.0, 1.0, "computation")
    >>> round(n[0], 12), [round(x, 12) for x in d]
    (0.632120558829, [1.0, -0.367879441171, 0.0])
    """
    a, b = _hold(rs, l_h, ts)
    if delay == "none":
        return [b], [1.0, -a]
    if delay == "computation":
        return [b], [1.0, -a, 0.0]
    phi_h, gamma_h = _hold(rs, l_h, 0.5 * ts)
    return [gamma_h, phi_h * gamma_h], [1.0, -a, 0.0, 0.0]


def loop(kp: float, ki: float, rs: float, l_h: float, ts: float, delay: str) -> tuple:
    """(N, D) of the open loop L = C·P."""
    nc, dc = pi(kp, ki, ts)
    npl, dpl = plant(rs, l_h, ts, delay)
    return multiply(nc, npl), multiply(dc, dpl)


def axis_loop(rs: float, l_h: float, ts: float, kp: float, ki: float, delay: str) -> dict:
    """Margins (:func:`pulab.analyses.loop.discrete.margins`) of one axis with gains kp [Ω], ki [Ω/s]."""
    num, den = loop(kp, ki, rs, l_h, ts, delay)
    return margins(num, den, ts)


def dead_time(ts: float, delay: str) -> float:
    """T_d, seconds: the loop delay as dead time for the continuous-time design."""
    return ts * {"none": 0.5, "computation": 1.5, "computation_pwm": 2.0}[delay]


#: R·Ts/L above which the plant's pole e^(−R·Ts/L) < 2.3e-16 is below double rounding next
#: to 1: the cancelling zero (ki/kp = (1/a − 1)/Ts) would be a number, not a design.
STATIC_PLANT = 36.0


def _shape(rs: float, l_h: float, ts: float, delay: str):
    """S(e^{jθ}) = L/kp with the cancelling zero, and the pole a."""
    a = _hold(rs, l_h, ts)[0]
    num, den = loop(1.0, (1.0 / a - 1.0) / ts, rs, l_h, ts, delay)

    def s(theta: float) -> complex:
        z = cmath.exp(1j * theta)
        acc_n = 0j
        for c in num:
            acc_n = acc_n * z + c
        acc_d = 0j
        for c in den:
            acc_d = acc_d * z + c
        return acc_n / acc_d
    return s, a


def _phase_margin_at(s, theta: float, previous: float | None) -> float:
    """180° + unwrapped arg S(e^{jθ}), degrees."""
    ph = math.degrees(cmath.phase(s(theta)))
    if previous is not None:
        ph -= 360.0 * round((ph - (previous - 180.0)) / 360.0)
    return 180.0 + ph


def design(rs: float, l_h: float, ts: float, delay: str, by: str, target: float) -> tuple:
    """SI gains (kp [Ω], ki [Ω/s]) meeting a phase margin or a bandwidth with the delay.

    Parameters
    ----------
    rs : float > 0, Ω ; l_h : float > 0, H ; ts : float > 0, s
    delay : one of :data:`DELAYS`
    by : {'phase_margin', 'bandwidth'}
    target : float — degrees in (0, 90) or Hz > 0

    Raises
    ------
    InputError
        ``analysis.target_phase_margin_deg`` / ``analysis.target_bandwidth_hz``
        when no gain reaches the target below the Nyquist frequency; ``drive.ts_s`` when
        R·Ts/L exceeds :data:`STATIC_PLANT` (the plant is static at this period).
    """
    x = rs * ts / l_h
    if x > STATIC_PLANT:
        raise InputError("drive.ts_s", code="plant_static", value=ts, tau=l_h / rs, x=x,
                         limit=STATIC_PLANT)
    s, a = _shape(rs, l_h, ts, delay)
    if by == "bandwidth":
        theta = 2.0 * math.pi * target * ts
        if theta >= math.pi:
            raise InputError("analysis.target_bandwidth_hz", code="above_nyquist", value=target,
                             nyquist=0.5 / ts)
        v = s(theta)
        kp = (v.real + math.sqrt(v.real * v.real + abs(v) ** 2)) / abs(v) ** 2
        return kp, kp * (1.0 / a - 1.0) / ts
    steps = 64
    low, pm_low = 1e-9, _phase_margin_at(s, 1e-9, None)
    high = None
    for k in range(1, steps + 1):
        t = math.pi * k / steps
        pm = _phase_margin_at(s, t, pm_low)
        if pm <= target:
            high = t
            break
        low, pm_low = t, pm
    if high is None:
        raise InputError("analysis.target_phase_margin_deg", code="pm_unreachable", value=target)
    for _ in range(48):                       # bracket π/64 → below 1e-16 rad
        mid = 0.5 * (low + high)
        pm_mid = _phase_margin_at(s, mid, pm_low)
        if pm_mid > target:
            low, pm_low = mid, pm_mid
        else:
            high = mid
    kp = 1.0 / abs(s(0.5 * (low + high)))
    return kp, kp * (1.0 / a - 1.0) / ts
