"""The sensorless settings: the ``observer`` input with every derived default resolved.

Vendor-neutral numbers in SI (phase peak), read by the design (:mod:`pulab.analyses.observer`)
and by each vendor's ``observer`` member (its integers).  Derived defaults:

- ``startup_ramp_rpm_per_s``: the maximum speed N_max = 60·f_base/p per second;
- ``startup_current_a``: √2·I_rated (the rated current, phase peak);
- ``merging_speed_rpm``: ceil(0.1·N_max), MCAT's basic mode (Masmiseim36/nxpSDK :
  middleware/motor_control/freemaster/pmsm_frac/mcat/src/JS_functions/inner_PoSpeBemfDQ.js,
  ``basicModeCalcPoSpeBEMF``);
- ``min_speed_rpm``: the merging speed (MCAT requires merging ≥ minimum);
- ``e_block_v``: half the back-EMF at the minimum speed, ψ·ω_min/2;
- ``r_error_pct``: α·(T_high − T_ref)·100 of ``analysis.robust`` (copper from 20 to 155 °C: 53 %);
- ``current_lsb_a``: the board's A per count, else 2·√2·I_rated/4096 (a 12-bit ADC over ±√2·2·I);
- ``deadtime_v``: the fundamental of the dead-time error, (4/π)·U_dc·t_d·f_pwm from the
  board's PWM, 0 without one (compensated or unknown).

Examples
--------
>>> m = {"rated_current_a": 1.5, "pole_pairs": 4, "bemf_v": 12.0, "rated_freq_hz": 220.0}
>>> s = settings({"min_speed_rpm": None, "merging_speed_rpm": None, "startup_ramp_rpm_per_s": None,
...               "startup_current_a": None, "e_block_v": None, "r_error_pct": None,
...               "current_lsb_a": None}, m, {"base_freq_hz": 220.0}, None, None)
>>> s["merging_speed_rpm"], s["min_speed_rpm"], round(s["r_error_pct"], 3)
(330.0, 330.0, 53.055)
"""

from __future__ import annotations

import math

from ..schema.fields import FIELD
from .bases import flux_linkage

__all__ = ["settings", "max_speed_rpm"]


def max_speed_rpm(motor: dict, drive: dict) -> float:
    """N_max = 60·f_base/p, rpm (the speed at the drive's base frequency)."""
    return 60.0 * drive["base_freq_hz"] / motor["pole_pairs"]


def _r_error_pct(robust) -> float:
    """The largest R(T)/R − 1 over the robustness range, %: α·max|T − T_ref|·100."""
    r = robust or {}
    def pick(key):
        return r.get(key, FIELD[f"analysis.robust.{key}"].default)
    low, high = pick("temperature_c")
    t_ref, alpha = pick("reference_c"), pick("copper_alpha_per_k")
    return 100.0 * alpha * max(abs(high - t_ref), abs(low - t_ref))


def settings(cfg: dict, motor: dict, drive: dict, board: dict | None, robust) -> dict:
    """The normalized ``observer`` section with its derived defaults filled in.

    Parameters
    ----------
    cfg : dict
        ``observer`` as :func:`pulab.schema.validate.read` returns it (None = derived).
    motor, drive : dict
        Normalized ``motor`` and ``drive``.
    board : dict or None
        The report's ``board`` output (:func:`pulab.model.board.board`), when given.
    robust : dict or None
        ``analysis.robust`` as typed (its temperature range sets the R error).

    Returns
    -------
    dict
        Every field a number, plus ``max_speed_rpm``, ``psi_peak`` [V·s/rad] and
        ``deadtime_v`` [V, phase peak].
    """
    s = dict(cfg)
    n_max = max_speed_rpm(motor, drive)
    psi = flux_linkage("peak", motor["bemf_v"], motor["rated_freq_hz"])
    if s.get("startup_ramp_rpm_per_s") is None:
        s["startup_ramp_rpm_per_s"] = n_max
    if s.get("startup_current_a") is None:
        s["startup_current_a"] = math.sqrt(2.0) * motor["rated_current_a"]
    if s.get("merging_speed_rpm") is None:
        s["merging_speed_rpm"] = float(math.ceil(0.1 * n_max))
    if s.get("min_speed_rpm") is None:
        s["min_speed_rpm"] = s["merging_speed_rpm"]
    if s.get("e_block_v") is None:
        s["e_block_v"] = 0.5 * psi * s["min_speed_rpm"] * motor["pole_pairs"] * math.pi / 30.0
    if s.get("r_error_pct") is None:
        s["r_error_pct"] = _r_error_pct(robust)
    cur = (board or {}).get("current")
    if s.get("current_lsb_a") is None:
        s["current_lsb_a"] = cur["a_per_count"] if cur else \
            2.0 * math.sqrt(2.0) * motor["rated_current_a"] / 4096.0
    pwm = (board or {}).get("pwm")
    err = pwm.get("deadtime_error_v") if pwm else None
    s["deadtime_v"] = 0.0 if err is None else 4.0 / math.pi * err
    s["max_speed_rpm"] = n_max
    s["psi_peak"] = psi
    return s
