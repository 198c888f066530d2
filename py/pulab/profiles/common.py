"""The constant record every vendor profile reports, and the shared SI context.

A *constant* is one integer a vendor's firmware stores, with what it should
have been and what it means (docs/contract.md, "Vendor profiles")::

    value      the stored integer
    ideal      the exact real value on the same integer scale (real · 2^n)
    error_pct  100·(value − ideal)/ideal  (0 when ideal = 0)
    format     e.g. "IQ24", "Q15", "ACC32 (Q16.15)", "int16 / 128", "FRAC16 · 2^3"
    si         what the stored integer means back in SI, in ``unit``
    scale      SI value of 1.0 in the format (MCAF's ``_SCALE``): si = value/2^q · scale
    source     the public file the formula follows ("repository : path"), or
               "derived: …" when no public file was found that states it
    flags      'truncation' (a C cast dropped a fraction), 'saturate' (the vendor's
               macro clamped), 'out_of_range' (the value does not fit and the vendor's
               conversion does not clamp: C leaves the cast undefined)

Examples
--------
>>> c = fixed("Kp", 0.3, 32, 24, 2.0, "V/A", "x", "TI", rounding="zero", fmt="IQ24")
>>> c["value"], c["flags"], round(c["si"], 6)
(5033164, ['truncation'], 0.6)
"""

from __future__ import annotations

import math
import struct
from fractions import Fraction

from ..fixedpoint.interval import RInterval, choose
from ..fixedpoint.qformat import QEncoded, QFormat, encode

__all__ = ["fixed", "real", "board_value", "mantissa_shift", "SQRT2", "SQRT3", "TWO_PI", "pow2_divisor", "pow2_exponent",
           "within", "SOURCES", "derived"]

SQRT2 = math.sqrt(2.0)
SQRT3 = math.sqrt(3.0)
TWO_PI = 2.0 * math.pi


def fixed(name: str, ideal: float, word_bits: int, frac_bits: int, si_per_unit: float,
          unit: str, expression: str, source: str, *, rounding: str = "nearest",
          clamps: bool = False, fmt: str | None = None, signed: bool = True,
          shift: int = 0, value: int | None = None, error_lsb=None) -> dict:
    """One stored integer: the real ``ideal`` quantized into a ``word_bits`` word.

    Parameters
    ----------
    name : str
        The vendor's name of the constant (``Kp_Iq``, ``KIP`` …).
    ideal : float, finite
        The real value the integer represents (per unit, or the vendor's scaled unit).
    word_bits : int in {16, 32}; frac_bits : int >= 0
        The integer is ideal·2^frac_bits rounded by ``rounding``.
    si_per_unit : float
        SI value of ideal = 1.0 (so si = value/2^frac_bits · 2^shift · si_per_unit).
    rounding : {'nearest', 'zero', 'floor'}
        'zero' is a C cast of a float; the vendor's macro decides.
    clamps : bool
        True when the vendor's conversion saturates (NXP FRAC16/ACC32 macros).
    shift : int
        A power-of-two scale kept beside a FRAC16 mantissa (NXP).
    value : int, optional
        The stored integer when the firmware computes it from other rounded integers
        (ST's C5 uses the truncated MAX_VOLTAGE); ``ideal`` stays the exact value.
    error_lsb : float, optional
        With ``value`` over a box (a family proof): a bound on |value − ideal·2^n| in LSB
        over the box, when the caller can give one (else the constant has no error bound).
    """
    q = QFormat(word_bits, frac_bits, signed)
    if isinstance(ideal, RInterval):
        # Over a box of inputs (pulab.analyses.prove): encoding is monotone, so the ends'
        # integers bound every point's, and the ends alone can saturate.
        ends = [encode(x, q, rounding, "saturate") for x in ideal.value]
        e = QEncoded(RInterval(ends[0].raw, ends[1].raw), None, None,
                     sorted({f for end in ends for f in end.flags}))
    else:
        e = encode(ideal, q, rounding, "saturate")
    exact = ideal * 2.0 ** frac_bits
    raw = e.raw if value is None else value
    inexact = "rounded" in e.flags if value is None else \
        isinstance(raw, RInterval) or Fraction(raw) != Fraction(ideal) * (1 << frac_bits)
    flags = []
    if rounding != "nearest" and inexact and "saturate" not in e.flags:
        flags.append("truncation")
    if "saturate" in e.flags:
        flags.append("saturate" if clamps else "out_of_range")
    si = raw / 2.0 ** frac_bits * 2.0 ** shift * si_per_unit
    return {"name": name, "value": raw, "ideal": exact,
            "error_pct": 0.0 if exact == 0 else 100.0 * (raw - exact) / exact,
            "format": fmt or q.name, "q": frac_bits, "word_bits": word_bits, "shift": shift,
            "si": si, "si_ideal": ideal * 2.0 ** shift * si_per_unit, "unit": unit,
            "scale": 2.0 ** shift * si_per_unit,
            "expression": expression, "source": source, "flags": flags,
            **({"error_lsb": _ERROR_LSB[rounding] if value is None else error_lsb}
               if isinstance(ideal, RInterval) else {})}


#: |stored − ideal·2^n| in LSB at most, for each rounding of one real (a family proof's
#: worst-error bound, :mod:`pulab.analyses.prove`; a value computed from other rounded
#: integers has none).
_ERROR_LSB = {"nearest": 0.5, "zero": 1.0, "floor": 1.0}


def _shift_of(k: float) -> int:
    """The shift of :func:`mantissa_shift`, exactly: the mantissa lands in [0.5, 1] (k ≥ 1,
    where 1.0 saturates FRAC16) or [0.5, 1) (k < 1).  ``frexp`` is exact where ``log2`` may
    round across an integer within an ulp of a power of two; this rule is monotone in k."""
    m, e = math.frexp(k)
    return e - 1 if k >= 1.0 and m == 0.5 else e


def mantissa_shift(k, site: str = "shift") -> tuple:
    """NXP MCAT's FRAC16 mantissa and shift for a positive constant K.

    shift = ceil(log2 K) for K ≥ 1, −ceil(log2(1/K) − 1) for K < 1; mantissa = K·2^−shift
    (Masmiseim36/nxpSDK : middleware/motor_control/freemaster/pmsm_frac/mcat/src/
    JS_functions/inner_PoSpeBemfDQ.js, tracking-observer and theta gains).  The shift is
    computed exactly (:func:`_shift_of`); K may be an interval (a family proof), the shift
    then a choice (:func:`pulab.fixedpoint.interval.choose`) named ``site``.

    >>> mantissa_shift(3.0), mantissa_shift(0.1)
    ((0.75, 2), (0.8, -3))
    """
    s, k = choose(site, k, _shift_of, lambda s: (2.0 ** (s - 1), 2.0 ** s if s >= 0
                                                  else math.nextafter(2.0 ** s, 0.0)))
    if isinstance(k, RInterval):  # scaling by 2^-s is exact: no outward rounding
        return RInterval(math.ldexp(k.lo, -s), math.ldexp(k.hi, -s)), s
    return k * 2.0 ** -s, s


def pow2_exponent(k, limit: int = 32767, largest: int = 14, site: str = "divisor") -> tuple:
    """The largest n ≤ ``largest`` with round(|k|·2^n) ≤ ``limit`` (0 when none), and k.

    k may be an interval (a family proof): n is then a choice named ``site``
    (:func:`pulab.fixedpoint.interval.choose`) and the k returned keeps only the part of the
    interval that makes it.

    >>> pow2_exponent(18.06)[0], pow2_exponent(0.001)[0]
    (10, 14)
    """
    def pick(a: float) -> int:
        n = largest
        while n > 0 and math.floor(a * 2.0 ** n + 0.5) > limit:  # nearest, ties away
            n -= 1
        return n

    def region(n: int) -> tuple:
        # |k|·2^n is exact and so is adding 1/2 below 2^52: round(|k|·2^n) ≤ limit exactly
        # when |k|·2^n < limit + 1/2.
        edge = limit + 0.5
        lo = 0.0 if n == largest else edge / 2.0 ** (n + 1)
        return lo, math.inf if n == 0 else math.nextafter(edge / 2.0 ** n, 0.0)

    n, a = choose(site, abs(k), pick, region)
    return n, within(k, a, exact=True)


def within(k, bound, exact: bool = False):
    """k where |k| ≤ bound (an interval's part that a choice on |k| keeps); ``exact``: where
    |k| lies in bound (when bound is |k| itself, not a larger quantity)."""
    if not isinstance(k, RInterval):
        return k
    if exact and k.lo >= 0:
        return k.clip(bound.lo, bound.hi)
    if exact and k.hi <= 0:
        return k.clip(-bound.hi, -bound.lo)
    return k.clip(-bound.hi, bound.hi)


def pow2_divisor(k, limit: int = 32767, largest: int = 16384, site: str = "divisor") -> int:
    """The largest power-of-two divisor D ≤ ``largest`` with round(|k|·D) ≤ ``limit``.

    pulab's choice for ST's ``TF_KPDIV``/``TF_KIDIV`` when none is given (the Motor
    Control Workbench's own rule is not public).

    >>> pow2_divisor(18.06), pow2_divisor(0.001)
    (1024, 16384)
    """
    return 1 << pow2_exponent(k, limit, largest.bit_length() - 1, site)[0]


#: Public files each profile's formulas were read in ("repository : path").
SOURCES = {
    "seed": "seed 1.4, 2.2 (Inovance C2000 code quoted in the seed document)",
    "ti_ctrl": "PBLSys/motorware_1_01_00_18_PB2 : sw/modules/ctrl/src/32b/ctrl.c (CTRL_setParams)",
    "ti_pigains": "TI MotorWare calcPIgains() (public lab copies, e.g. gdgly/EV_28069M; "
                  "exact-string match, file path not pinned)",
    "ti_iqmath": "TI IQmathLib.h _IQ24(A) = (long)((A)*16777216.0L) (public copies)",
    "ti_pi": "TI MotorWare pi.h PI_run_series: Ui += _IQmpy(Ki, Up) (public copy, path not pinned)",
    "ti_user": "gdgly/EV_28069M : sw/modules/user/src/32b/user.c",
    "nxp_cloop": "Masmiseim36/nxpSDK : middleware/motor_control/freemaster/pmsm_frac/mcat/src/"
                 "JS_functions/inner_CLoop.js",
    "nxp_bemf": "Masmiseim36/nxpSDK : middleware/motor_control/freemaster/pmsm_frac/mcat/src/"
                "JS_functions/inner_PoSpeBemfDQ.js",
    "nxp_types": "NXP RTCESL mlib_types.h ACC32(x)/FRAC16(x) macros (public copies)",
    "nxp_appconfig": "NXP MCAT-generated m1_pmsm_appconfig.h, 'FILE NAME: pmsm_frac/mcat/"
                     "m1_pmsm_appconfig.h, DATE: Mon Nov 27 2023' (motor 'linix'; public copy "
                     "found by exact-string search, repository not named by the search tool)",
    "st_conv": "dronectl/g431-mcsdk : Inc/parameters_conversion.h",
    "st_motor": "dronectl/g431-mcsdk : Inc/pmsm_motor_parameters.h",
    "st_drive": "dronectl/g431-mcsdk : Inc/drive_parameters.h",
    "st_pid": "ST MCSDK pid_regulator.c PI_Controller and mc_math.c MCM_Clarke (public copies "
              "found by exact-string search; path not pinned)",
    "mchp_motor": "microchip-pic-avr-solutions/motorbench-release-collateral : "
                  "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/"
                  "motor_params.h",
    "mchp_foc": "microchip-pic-avr-solutions/motorbench-release-collateral : "
                "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/"
                "foc_params.h",
    "mchp_hal": "microchip-pic-avr-solutions/motorbench-release-collateral : "
                "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/"
                "hal_params.h",
    "mchp_adc": "microchip-pic-avr-solutions/motorbench-release-collateral : "
                "zsmt-reference-actblf02-lvmc.X/mcc_generated_files/motorBench/parameters/"
                "adc_params.h",
    "ti_umcl": "anyway-blows/ti-c2000-motor-control-sdk : solutions/universal_motorcontrol_lab/"
               "common/include/user_mtr1.h",
    "ti_user_h": "scottmcdaid/instaspin-labs : sw/solutions/instaspin_foc/boards/"
                 "boostxldrv8301_revB/f28x/f2806xF/src/user_j1.h",
    "st_power": "dronectl/g431-mcsdk : Inc/power_stage_parameters.h",
}


def real(name: str, ideal: float, unit: str, expression: str, source: str, *,
         single: bool = False, decimals: int | None = None) -> dict:
    """One real number a vendor's header keeps as a C floating constant (no Q format).

    The record has the keys of :func:`fixed` (``q`` 0, ``shift`` 0, ``scale`` 1) and
    ``real`` True; ``value`` is the number the compiler stores: ``ideal`` itself for a
    ``double``, or the nearest IEEE binary32 for a ``float`` literal (``single``; flag
    ``out_of_range`` beyond its range), ``error_pct`` being that rounding. ``decimals``: the
    generator prints ``ideal`` with that many decimals first, and the compiler rounds the text.

    >>> c = real("USER_M1_ADC_FULL_SCALE_CURRENT_A", 3.3 / 0.07, "A", "V_ref/(R·G)", "TI",
    ...          single=True)
    >>> c["value"], c["format"], f"{c['error_pct']:.1e}"
    (47.14285659790039, 'float32', '-1.2e-06')
    >>> c = real("SIGMA", 0.27126710291, "", "1 − L_m²/(L_s·L_r)", "ST", single=True, decimals=7)
    >>> c["value"], round(c["error_pct"], 6)
    (0.2712670862674713, -6e-06)
    """
    printed = float(ideal) if decimals is None else float(f"{ideal:.{decimals}f}")
    flags = []
    if not single:
        value = printed
    else:
        try:
            value = struct.unpack("<f", struct.pack("<f", printed))[0]
        except OverflowError:
            value, flags = math.copysign(math.inf, ideal), ["out_of_range"]
    return {"name": name, "value": value, "ideal": float(ideal),
            "error_pct": 0.0 if ideal == 0 or flags else 100.0 * (value - ideal) / ideal,
            "format": "float32" if single else "double", "q": 0, "word_bits": 32 if single else 64,
            "shift": 0, "si": value, "si_ideal": float(ideal), "unit": unit, "scale": 1.0,
            "expression": expression, "source": source, "flags": flags, "real": True}


def board_value(ctx: dict, chain: str, key: str, default):
    """``ctx["board"][chain][key]`` when the board gives that chain, else ``default``: a vendor
    option that the board decides unless typed (:mod:`pulab.model.board`)."""
    b = (ctx.get("board") or {}).get(chain)
    return default if b is None or b.get(key) is None else b[key]


def derived(why: str) -> str:
    """``source`` text for a formula no public file was found to state."""
    return f"derived (not found in a public file): {why}"
