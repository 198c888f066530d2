"""The board: current sensing, bus sensing and the PWM timer, and the scales they set.

In firmware the per-unit current base is not the motor's rated current but what the board can
measure; the bus base is the ADC's full scale through the divider; the PWM period and dead time
are timer counts. This module computes that chain from the schematic's values (vendor-neutral);
each vendor profile reads it its own way.

Current sensing (shunt ``R`` and amplifier gain ``G``, or a sensor's sensitivity ``S = R·G``
in V/A; an ADC of ``n`` bits at reference ``V_ref``):

- full ADC range in amperes: ``V_ref/S`` — what TI's universal lab calls
  ``USER_M1_ADC_FULL_SCALE_CURRENT_A`` (anyway-blows/ti-c2000-motor-control-sdk :
  solutions/universal_motorcontrol_lab/common/include/user_mtr1.h: 47.14285714 A "gain=10"
  on the 7 mΩ BOOSTXL-DRV8323RS; DRV8316: 3.3 V / 0.15 V/A = 22.0 A);
- the largest measurable current: ``±V_ref/(2·S)`` bipolar (offset at mid-rail: ST's
  ``MAX_CURRENT = ADC_REFERENCE_VOLTAGE/(2·RSHUNT·AMPLIFICATION_GAIN)``, dronectl/g431-mcsdk :
  Inc/parameters_conversion.h), ``V_ref/S`` unipolar;
- one count: ``V_ref/(2^n·S)`` A (TI's ``USER_M1_CURRENT_SF`` = full scale/4096).

Bus: ``max_v = V_ref/ratio``, ``ratio = R_bottom/(R_top + R_bottom)`` (ST's
``VBUS_PARTITIONING_FACTOR``; TI's ``USER_M1_ADC_FULL_SCALE_VOLTAGE_V``, 57.52845691 V on the
BOOSTXL-DRV8323RS).

PWM: ``f_clk/f_pwm`` timer ticks per period (ST's ``PWM_PERIOD_CYCLES``); the period register
holds ``f_clk/(2·f_pwm)`` counting up and down (TI's ``USER_M1_PWM_TBPRD_NUM``, cast to an
integer) or ``f_clk/f_pwm − 1`` counting up; the duty cycle has as many steps as the compare
register spans; the dead time is ``t_d·f_clk`` ticks and costs ``U_dc·t_d·f_pwm`` of average
voltage (the error's magnitude, sign following the current).

Examples
--------
>>> b = board({"current": {"shunt_ohm": 0.007, "gain": 10.0, "sensitivity_v_per_a": None,
...            "adc_bits": 12, "adc_ref_v": 3.3, "bipolar": True, "max_a": None}},
...           i_b=1.5, psi_peak=0.01, pole_pairs=4, udc_v=24.0)
>>> round(b["current"]["max_a"], 4), round(b["current"]["full_range_a"], 6)
(23.5714, 47.142857)
>>> round(b["current"]["counts_per_a"], 3)
86.885
"""

from __future__ import annotations

import math

from ..schema.errors import InputError

__all__ = ["board", "current_chain", "bus_chain", "pwm_chain"]


def _either(sec: dict, path: str, one: str, others: tuple) -> None:
    """A value typed directly and the chain it replaces: one of them, never both."""
    given = [k for k in others if sec.get(k) is not None]
    if sec.get(one) is not None and given:
        raise InputError(f"{path}.{one}", code="board_either", other=f"{path}.{given[0]}")


def current_chain(c: dict, i_b: float, psi_peak: float, pole_pairs: int) -> dict | None:
    """The phase-current chain, or None when the board gives no current sensing.

    Parameters
    ----------
    c : dict
        Normalized ``board.current`` (every key present, None when not given).
    i_b : float > 0, A — the report's current base
    psi_peak : float > 0, Wb — peak flux linkage (torque per ampere: 1.5·p·ψ)
    pole_pairs : int

    Returns
    -------
    dict or None
        ``max_a`` (± A), ``full_range_a`` (A over the whole ADC range), ``sensitivity_v_per_a``
        (None when the largest current was typed), ``a_per_count``, ``counts_per_a``,
        ``nm_per_count``, ``pu_per_count``, ``from`` (``chain`` or ``max_a``).
    """
    _either(c, "board.current", "max_a", ("shunt_ohm", "gain", "sensitivity_v_per_a"))
    _either(c, "board.current", "sensitivity_v_per_a", ("shunt_ohm", "gain"))
    if c["gain"] is not None and c["shunt_ohm"] is None:
        raise InputError("board.current.shunt_ohm", code="board_needs", other="board.current.gain")
    span = 1.0 if c["bipolar"] else 0.5      # full ADC range / (2·largest current)
    counts = 2.0 ** c["adc_bits"]
    if c["max_a"] is not None:
        s = None
        full = 2.0 * span * c["max_a"]
        source = "max_a"
    else:
        s = c["sensitivity_v_per_a"]
        if s is None and c["shunt_ohm"] is not None:
            s = c["shunt_ohm"] * (c["gain"] if c["gain"] is not None else 1.0)
        if s is None:
            return None
        full = c["adc_ref_v"] / s
        source = "chain"
    max_a = full / (2.0 * span)
    lsb = full / counts
    return {"max_a": max_a, "full_range_a": full, "sensitivity_v_per_a": s, "a_per_count": lsb,
            "counts_per_a": 1.0 / lsb, "nm_per_count": 1.5 * pole_pairs * psi_peak * lsb,
            "pu_per_count": lsb / i_b, "from": source}


def bus_chain(b: dict) -> dict | None:
    """The DC-bus chain (``max_v``, ``v_per_count``, ``ratio``), or None without bus sensing."""
    _either(b, "board.bus", "max_v", ("r_top_ohm", "r_bottom_ohm", "ratio"))
    _either(b, "board.bus", "ratio", ("r_top_ohm", "r_bottom_ohm"))
    for one, other in (("r_top_ohm", "r_bottom_ohm"), ("r_bottom_ohm", "r_top_ohm")):
        if b[one] is not None and b[other] is None:
            raise InputError(f"board.bus.{other}", code="board_needs", other=f"board.bus.{one}")
    if b["max_v"] is not None:
        ratio, max_v = None, b["max_v"]
    else:
        ratio = b["ratio"]
        if ratio is None and b["r_top_ohm"] is not None:
            ratio = b["r_bottom_ohm"] / (b["r_top_ohm"] + b["r_bottom_ohm"])
        if ratio is None:
            return None
        max_v = b["adc_ref_v"] / ratio
    return {"max_v": max_v, "v_per_count": max_v / 2.0 ** b["adc_bits"], "ratio": ratio,
            "from": "max_v" if ratio is None else "chain"}


def pwm_chain(p: dict, udc_v: float) -> dict | None:
    """The PWM timer: period in ticks and in its register, duty resolution, dead time.

    Values that need the timer clock are None without it; None altogether without a PWM
    frequency.
    """
    f, clk, td = p["freq_hz"], p["clock_hz"], p["deadtime_s"]
    if f is None:
        for k in ("clock_hz", "deadtime_s"):
            if p[k] is not None:
                raise InputError("board.pwm.freq_hz", code="board_needs", other=f"board.pwm.{k}")
        return None
    out = {"control_period_s": p["periods_per_control"] / f, "period_counts": None,
           "period_register": None, "freq_actual_hz": None, "duty_bits": None,
           "deadtime_counts": None,
           "deadtime_error_v": None if td is None else udc_v * td * f}
    if clk is not None:
        ticks = clk / f
        updown = p["mode"] == "updown"
        # the register holds an integer: the C casts (truncates), as TI's (uint16_t)(…/2.0f)
        reg = math.floor(ticks / 2.0) if updown else math.floor(ticks) - 1
        if reg < 1:
            raise InputError("board.pwm.freq_hz", code="board_pwm_ticks", ticks=ticks, clock=clk)
        steps = reg if updown else reg + 1
        out.update(period_counts=ticks, period_register=reg,
                   freq_actual_hz=clk / (2.0 * reg) if updown else clk / (reg + 1),
                   duty_bits=math.log2(steps),
                   deadtime_counts=None if td is None else td * clk)
    return out


def board(sec: dict, i_b: float, psi_peak: float, pole_pairs: int, udc_v: float) -> dict:
    """The ``board`` output: ``current``, ``bus`` and ``pwm``, each None when not given.

    Parameters
    ----------
    sec : dict
        Normalized ``board`` input: ``current``, ``bus``, ``pwm`` each a section with every
        key (absent sections may be missing).
    i_b : float, A ; psi_peak : float, Wb ; pole_pairs : int ; udc_v : float, V

    Raises
    ------
    InputError
        A value typed together with the chain it replaces, a chain missing a piece, or a PWM
        frequency beyond the timer clock.
    """
    out = {"current": None, "bus": None, "pwm": None}
    if sec.get("current") is not None:
        out["current"] = current_chain(sec["current"], i_b, psi_peak, pole_pairs)
    if sec.get("bus") is not None:
        out["bus"] = bus_chain(sec["bus"])
    if sec.get("pwm") is not None:
        out["pwm"] = pwm_chain(sec["pwm"], udc_v)
    return out
