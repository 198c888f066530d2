"""Microchip MCAF's PLL estimator constants (AN1292's estimator as motorBench generates it).

The estimator (microchip-pic-avr-solutions/motorbench-release-collateral :
zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/commutation/pll.c,
``MCAF_EstimatorPllExecute``) runs on Q15 per-unit values at the control period Δt:

- the back-EMF in d-q is low-passed by forward Euler, ``state += K·(Es − Es_filt)``, so
  ``KFILTER_ESDQ`` = ω1·Δt, ω1 the corner (motorBench's ``pll-omega1`` in Hz: 116.5 → 1199);
- the speed ``omegaMr`` = (E_q − sign·E_d)·``keInverse`` is integrated into the angle,
  ``rho += omegaMr·MCAF_PLL_DT_ANGULAR >> 15``; with ω in units of ω_b and the angle in
  units of π, ``MCAF_PLL_DT_ANGULAR`` = ω_b·Δt/π;
- the speed is low-passed the same way: ``KFILTER_VELESTIM`` = Δt/τ (motorBench's
  ``pll-tau``, 2.19 ms → 748), τ = 1/(2π·f) for a corner f;
- ``keInverse`` = ``MCAF_MOTOR_KE_INVERSE`` (motor_params.h, Q12) = 1/K_e in units of
  (ω_b/p)/V_b: V_b/(ψ·ω_b);
- below ``MCAF_PLL_VELOCITY_FILTER_THRESHOLD`` (a speed in units of ω_b) dI/dt is taken
  over 8 samples; motorBench writes ``pll-velocity_filter_threshold`` (1.0) × the nominal
  speed.  ``DECIMATE_BASE_SPEED`` is 0.1 × the nominal speed: read in the three reference
  projects' pll_params.h (tests/data/headers/microchip/README.md), no public file states it.

pulab maps its vendor-neutral settings: ω1 = 2π·``observer.bemf_f0_hz``, f =
``observer.speed_filter_hz``; the nominal speed is the motor's rated frequency.  Rounding:
nearest, Q15 (motorBench, like motor_params.h).  ``D_ILIMIT_HS``/``D_ILIMIT_LS`` (dI/dt
limits) are not computed: their rule is not public and the three headers do not pin it.

Examples
--------
>>> ctx = {"ts": 5e-5, "psi_peak": 9.28229e-3, "f_rated": 16000 / 60,
...        "observer": {"bemf_f0_hz": 116.5, "speed_filter_hz": 72.6735}}
>>> opt = {"voltage_base_v": 71.3, "velocity_base_hz": 400.0}
>>> c = observer(ctx, opt)
>>> [c[k]["value"] for k in ("MCAF_PLL_DT_ANGULAR", "KFILTER_ESDQ", "KFILTER_VELESTIM")]
[1311, 1199, 748]
"""

from __future__ import annotations

import math

from ..common import TWO_PI, derived, fixed

__all__ = ["observer"]

_PARAMS = ("microchip-pic-avr-solutions/motorbench-release-collateral : "
           "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/pll_params.h")
_CODE = ("microchip-pic-avr-solutions/motorbench-release-collateral : "
         "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/commutation/pll.c")
_MOTOR = ("microchip-pic-avr-solutions/motorbench-release-collateral : "
          "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/motor_params.h")
#: motorBench's own constants: the speed below which it decimates, and the dI/dt switch,
#: as fractions of the nominal speed (the same in all three reference projects).
_DECIMATE, _THRESHOLD = 0.1, 1.0


def _q(name, x, n, scale, unit, expr, source):
    return fixed(name, x, 16, n, scale, unit, expr, source, fmt=f"Q{n}")


def observer(ctx: dict, opt: dict) -> dict:
    """MCAF's PLL estimator integers for the settings ``ctx['observer']`` (None: none)."""
    s = ctx.get("observer")
    if s is None:
        return {}
    dt, wb, vb = ctx["ts"], TWO_PI * opt["velocity_base_hz"], opt["voltage_base_v"]
    w1, wf = TWO_PI * s["bemf_f0_hz"], TWO_PI * s["speed_filter_hz"]
    nominal = ctx["f_rated"] / opt["velocity_base_hz"]
    from_code = f"{_PARAMS}; the loop is {_CODE}"
    return {
        "MCAF_PLL_DT_ANGULAR": _q("MCAF_PLL_DT_ANGULAR", wb * dt / math.pi, 15, math.pi / wb,
                                  "s", "ω_b·Δt/π", from_code),
        "KFILTER_ESDQ": _q("KFILTER_ESDQ", w1 * dt, 15, 1.0 / dt, "rad/s",
                           "2π·observer.bemf_f0_hz·Δt", from_code),
        "KFILTER_VELESTIM": _q("KFILTER_VELESTIM", wf * dt, 15, 1.0 / dt, "rad/s",
                               "Δt/τ, τ = 1/(2π·observer.speed_filter_hz)", from_code),
        "DECIMATE_BASE_SPEED": _q("DECIMATE_BASE_SPEED", _DECIMATE * nominal, 15, wb, "rad/s",
                                  "0.1·ω_rated/ω_b",
                                  derived(f"0.1 × the nominal speed, read in three {_PARAMS}")),
        "MCAF_PLL_VELOCITY_FILTER_THRESHOLD": _q(
            "MCAF_PLL_VELOCITY_FILTER_THRESHOLD", _THRESHOLD * nominal, 15, wb, "rad/s",
            "1.0·ω_rated/ω_b (motorBench pll-velocity_filter_threshold)", from_code),
        "MCAF_MOTOR_KE_INVERSE": _q("MCAF_MOTOR_KE_INVERSE", vb / (ctx["psi_peak"] * wb), 12,
                                    wb / vb, "(rad/s)/V", "V_b/(ψ·ω_b): 1/K_e in (ω_b/p)/V_b",
                                    _MOTOR),
    }
