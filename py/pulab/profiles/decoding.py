"""What every vendor's ``decode_header`` shares: the record of a decoded macro, the current
loop a pair of SI gains implies, and the checks' common shapes.

A vendor's ``decode_header(values, notes)`` (:data:`pulab.profiles.vendor.OPTIONAL`) gets the
folded macros (name → int or float, as the compiler computes them; a macro that does not fold
is absent) and the comment on each ``#define`` line, and returns :func:`result`: the names it
reads, its compiler (``target``), the decoded macros, the design and its checks. Called with
two empty dicts it still gives ``reads`` and ``target`` (the detection and the fold need them).

Examples
--------
>>> c = current_loop(1.8, 3150.0, 0.35, 0.0006)
>>> round(c["bandwidth_hz"], 1), round(c["zero_rad_s"], 1), c["cancels_plant"]
(531.1, 1750.0, False)
"""

from __future__ import annotations

import math
import re

__all__ = ["macro", "result", "current_loop", "integrator_loop", "check", "near", "numbers_in"]


def macro(si, unit: str | None, meaning: str, formula: str) -> dict:
    """One decoded macro: its value in SI (None when it has none; a float even when whole, as
    the output promises), unit, meaning, formula."""
    return {"si": None if si is None else float(si), "unit": unit, "meaning": meaning, "formula": formula}


def result(reads, target: str, macros: dict, design: dict, checks: list) -> dict:
    """What ``decode_header`` returns."""
    return {"reads": list(reads), "target": target, "macros": macros, "design": design,
            "checks": checks}


def current_loop(kp: float, ki: float, r: float, l: float, macros=()) -> dict | None:
    """The current loop of a parallel PI ``kp + ki/s`` [V/A, V/(A·s)] on the plant ``1/(Ls+R)``;
    ``macros``: the names that store its gains (kept as ``macros``).

    ``zero_rad_s`` = ki/kp; ``cancels_plant`` when it is R/L within 1 %; ``bandwidth_hz`` the
    crossover of the continuous open loop, |kp + ki/(jω)| = |jωL + R|, i.e. the positive root
    x = ω² of L²x² + (R² − kp²)x − ki² = 0 (kp/L when the zero cancels the plant pole).
    None when L ≤ 0 or R < 0 (a header whose numbers make no motor)."""
    if not (l > 0 and r >= 0 and math.isfinite(kp) and math.isfinite(ki)):
        return None  # no plant to speak of: the header's numbers make no motor
    zero = ki / kp if kp else None
    pole = r / l
    b = r * r - kp * kp
    x = (-b + math.sqrt(b * b + 4.0 * l * l * ki * ki)) / (2.0 * l * l)
    return {"kp_v_per_a": kp, "ki_v_per_a_s": ki, "bandwidth_hz": math.sqrt(x) / (2.0 * math.pi),
            "zero_rad_s": zero, "plant_pole_rad_s": pole,
            "cancels_plant": zero is not None and abs(zero / pole - 1.0) <= 0.01,
            "macros": list(macros)}


def integrator_loop(kp: float, ki: float, k: float) -> dict | None:
    """A PI ``kp + ki/s`` around an integrating plant ``k/s`` (a speed loop: current to speed,
    ``k`` = (speed unit/s) per A; a PLL: ``k`` = 1, gains in rad/s per rad and rad/s² per rad).

    Closed loop s² + k·kp·s + k·ki = 0: ``natural_hz`` = √(k·ki)/2π, ``damping`` ζ =
    k·kp/(2·√(k·ki)); ``bandwidth_hz`` the open loop's crossover, |k·(kp + ki/jω)/jω| = 1,
    i.e. ω² = (k²kp² + √(k⁴kp⁴ + 4k²ki²))/2; ``zero_rad_s`` = ki/kp. None when a gain or ``k``
    is not positive (no loop to speak of).

    >>> c = integrator_loop(2 * 0.7 * 100.0, 100.0 ** 2, 1.0)
    >>> round(c["natural_hz"] * 2 * math.pi, 6), round(c["damping"], 6)
    (100.0, 0.7)
    """
    if not (kp > 0 and ki > 0 and k > 0 and math.isfinite(kp * ki * k)):
        return None
    wn = math.sqrt(k * ki)
    a = (k * kp) ** 2
    wc = math.sqrt((a + math.sqrt(a * a + 4.0 * k * k * ki * ki)) / 2.0)
    return {"bandwidth_hz": wc / (2.0 * math.pi), "natural_hz": wn / (2.0 * math.pi),
            "damping": k * kp / (2.0 * wn), "zero_rad_s": ki / kp}


def check(severity: str, code: str, macros: list, advice: str = "", **params) -> tuple:
    """A finding of the vendor's: (severity, code, macros, params, advice); the words are the
    catalog's ``audit.<code>``."""
    return severity, code, macros, params, advice


def near(a: float, b: float, rel: float) -> bool:
    """|a − b| ≤ rel·|b|."""
    return abs(a - b) <= rel * abs(b)


_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def numbers_in(note: str, unit: str) -> list:
    """The numbers written right before ``unit`` in a comment (``4.11V/krpm`` → [4.11]).

    >>> numbers_in("// 4.11V/krpm, 2.9 V/krpm", "V/krpm")
    [4.11, 2.9]
    """
    return [float(m[1]) for m in re.finditer(r"(" + _NUMBER.pattern + r")\s*" + re.escape(unit),
                                            note or "")]
