"""The rest of MCAT's ``m1_pmsm_appconfig.h``, from MCAT's own inputs (``profiles.nxp.mcat``).

With the JSON MCAT wrote, the NXP profile also computes the application macros of the same
header: scales, fault thresholds, durations, the bus-voltage filter, the scalar (V/Hz) mode, the
current-loop limit and the speed loop.  Formulas of MCAT's JavaScript (Masmiseim36/nxpSDK :
middleware/motor_control/freemaster/pmsm_frac/mcat/src/JS_functions/inner_Parameters.js
``clickCalculateParam``, inner_SLoop.js ``clickCalculateSloop``), with ω_max = 2π·p·N_max/60,
U_max = U_DCB,max/UmaxCoeff, T = currentLoopSampleTime, T_w = speedLoopSampleTime::

    M1_I_PH_NOM = IphNom/I_max        M1_N_NOM = Nnom/N_max        M1_N_OVERSPEED = Nover/N_max
    M1_U_DCB_TRIP, _UNDERVOLTAGE, _OVERVOLTAGE = UdcbTrip, UdcbUnder, UdcbOver / U_DCB,max
    M1_SCALAR_UQ_MIN = ScalarUqMin/U_max        M1_ALIGN_VOLTAGE = AlignVoltage/U_max
    M1_E_BLOCK_PER = EblockPer (integer)        M1_ALIGN_DURATION = AlignDuration/T
    M1_CALIB_DURATION, M1_FAULT_DURATION, M1_FREEWHEEL_DURATION = … Duration/T_w (rounded)
    M1_UDCB_IIR_B0 = B1 = x/(2 + x)/2, M1_UDCB_IIR_A1 = (2 − x)/(2 + x)/2,  x = 2π·UdcbIIRf0·T
    M1_SCALAR_VHZ_FACTOR = UphNom·(ScalarVHzRatio/100)/U_max·N_max/Nnom (FRAC16 + shift;
        below one the factor itself with shift 0)
    M1_SCALAR_INTEG_GAIN = 2·f_max·T (ACC32),   f_max = p·N_max/60
    M1_SCALAR_RAMP_UP/DOWN = speedLoopIncUp/IncDown / N_max·T (FRAC32)
    M1_CLOOP_LIMIT = currentLoopOutputLimit/100
    M1_SPEED_RAMP_UP/DOWN = speedLoopIncUp/IncDown / N_max·T_w (FRAC32)
    M1_SPEED_LOOP_HIGH_LIMIT, _LOW_LIMIT = speedLoopUpperLimit, LowerLimit / I_max
    M1_SPEED_PI_PROP_GAIN = Kp·ω_max/I_max,  M1_SPEED_PI_INTEG_GAIN = Ki·T_w·ω_max/I_max (ACC32)
        Kp, Ki = speedLoopSLKp, speedLoopSLKi with speedLoopManualConstantTunning, else
        Kp = 2ξ·ω0·J/Kt, Ki = ω0²·J/Kt (ω0 = 2π·speedLoopF0, ξ = speedLoopKsi, J, Kt of
        parameters)
    M1_SPEED_IIR_B0 = B1 = y/(2 + y)/2, M1_SPEED_IIR_A1 = (2 − y)/(2 + y)/2,  y = 2π·fc·T_w

The encoder (MCAT's SENSORS section; its bundled JavaScript, nxp-mcuxpresso/mcux-motor_control :
freemaster/pmsm_frac/mcat/js/mcat.js, SENSORS ``calculateParams``), ω_mech = 2π·N_max/60::

    M1_POSPE_ENC_PULSES, _DIRECTION = sensorEncPulseNumber, sensorEncDir
    M1_POSPE_ENC_N_MIN = sensorEncNmin/N_max (FRAC32),  M1_POS_P_PROP_GAIN = positionLoopPLKp
    M1_POSPE_MECH_POS_GAIN = 2^15/(4·N_enc/2) (ACC32: a revolution is 2^16 position LSBs)
    M1_POSPE_TO_KP, _KI, _THETA = the tracking observer of the sensorless one
        (:func:`pulab.profiles.nxp.observer.tracking`) on the mechanical angle: ω_mech for
        ω_max, ω0 = 2π·sensorObsrvParF0, ζ = sensorObsrvParKsi, T = sensorObsrvParSampleTime

Read in the MCAT-generated headers rather than the JavaScript (which is older than the
generator): U_max and f_max unrounded, the scalar minimum voltage over U_max (not U_DCB,max),
the bus filter at ``parametersUdcbIIRf0`` (not a fixed 100 Hz), the V/Hz factor (no JavaScript
read states it; it reproduces the three headers of tests/data/headers/nxp/observer_README.md).

Examples
--------
>>> m = {"parametersNmax": 4400, "parametersUdcbMax": 36.3, "parametersUdcbTrip": 29}
>>> c = constants(m, {"ts": 1e-4, "pp": 4}, {"udcb_max_v": 36.3, "i_max_a": 8.0,
...               "u_max_coeff": 1.73205, "round_u_max": False, "e_max_v": 15.1})
>>> round(c["M1_U_DCB_TRIP"]["ideal"] / 32768, 6)
0.798898
"""

from __future__ import annotations


from ...model.mcat import flatten
from ..common import TWO_PI, fixed, real
from . import scaling
from .observer import _frac, _gain_shift, tracking
from .scaling import _acc32, _scales

__all__ = ["constants", "profile"]

_JS = ("Masmiseim36/nxpSDK : middleware/motor_control/freemaster/pmsm_frac/mcat/src/"
       "JS_functions/inner_Parameters.js, inner_SLoop.js")
_ENC = ("nxp-mcuxpresso/mcux-motor_control : freemaster/pmsm_frac/mcat/js/mcat.js (MCAT's "
        "SENSORS calculateParams)")
_HDR = "MCAT-generated m1_pmsm_appconfig.h headers (tests/data/headers/nxp/observer_README.md)"


def _n(m: dict, key: str):
    v = m.get(key)
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _int(name: str, x: float, expr: str, source: str) -> dict:
    return fixed(name, x, 32, 0, 1.0, "", expr, source, fmt="int")


def _iir(prefix: str, fc: float, ts: float, what: str) -> dict:
    """Bilinear first-order low-pass at fc: FRAC32 of b0/2, b1/2, −a1/2 (MCAT's halving)."""
    x = TWO_PI * fc * ts
    b, a = x / (2.0 + x) / 2.0, (2.0 - x) / (2.0 + x) / 2.0
    return {f"{prefix}_B0": _frac(f"{prefix}_B0", b, 32, 2.0, "", f"b0/2, {what}", _JS),
            f"{prefix}_B1": _frac(f"{prefix}_B1", b, 32, 2.0, "", f"b1/2, {what}", _JS),
            f"{prefix}_A1": _frac(f"{prefix}_A1", a, 32, 2.0, "", f"−a1/2, {what}", _JS)}


def constants(m: dict, ctx: dict, opt: dict) -> dict:
    """MCAT's application macros for its flattened inputs ``m`` (keys MCAT did not write are
    skipped, with the macros that need them)."""
    um, im = _scales(opt)
    pp, ts = ctx["pp"], ctx["ts"]
    n_max, udcb = _n(m, "parametersNmax"), opt["udcb_max_v"]
    tw = _n(m, "speedLoopSampleTime")
    out = {}
    if n_max:
        f_max = pp * n_max / 60.0
        out["M1_N_MAX"] = real("M1_N_MAX", n_max, "rpm", "parametersNmax", _JS, single=True)
        out["M1_FREQ_MAX"] = real("M1_FREQ_MAX", f_max, "Hz", "p·N_max/60", _HDR, single=True)
    out["M1_I_MAX"] = real("M1_I_MAX", im, "A", "parametersImax", _JS, single=True)
    out["M1_U_MAX"] = real("M1_U_MAX", um, "V", "U_DCB,max/UmaxCoeff", _HDR, single=True)
    out["M1_E_MAX"] = real("M1_E_MAX", opt["e_max_v"] if opt["e_max_v"] is not None else um,
                           "V", "parametersEmax", _JS, single=True)
    out["M1_MOTOR_PP"] = _int("M1_MOTOR_PP", pp, "pole pairs", _JS)
    out["M1_U_DCB_MAX"] = real("M1_U_DCB_MAX", udcb, "V", "parametersUdcbMax", _JS, single=True)
    frac16 = [("M1_I_PH_NOM", "parametersIphNom", im, "A", "IphNom/I_max"),
              ("M1_N_NOM", "parametersNnom", n_max, "rpm", "Nnom/N_max"),
              ("M1_U_DCB_TRIP", "parametersUdcbTrip", udcb, "V", "UdcbTrip/U_DCB,max"),
              ("M1_U_DCB_UNDERVOLTAGE", "parametersUdcbUnder", udcb, "V", "UdcbUnder/U_DCB,max"),
              ("M1_U_DCB_OVERVOLTAGE", "parametersUdcbOver", udcb, "V", "UdcbOver/U_DCB,max"),
              ("M1_N_OVERSPEED", "parametersNover", n_max, "rpm", "Nover/N_max"),
              ("M1_SCALAR_UQ_MIN", "parametersScalarUqMin", um, "V", "ScalarUqMin/U_max"),
              ("M1_ALIGN_VOLTAGE", "parametersAlignVoltage", um, "V", "AlignVoltage/U_max"),
              ("M1_CLOOP_LIMIT", "currentLoopOutputLimit", 100.0, "%", "OutputLimit/100"),
              ("M1_SPEED_LOOP_HIGH_LIMIT", "speedLoopUpperLimit", im, "A", "UpperLimit/I_max"),
              ("M1_SPEED_LOOP_LOW_LIMIT", "speedLoopLowerLimit", im, "A", "LowerLimit/I_max")]
    for name, key, scale, unit, expr in frac16:
        x = _n(m, key)
        if x is not None and scale:
            out[name] = _frac(name, x / scale, 16, scale, unit, expr, _JS)
    if _n(m, "parametersEblockPer") is not None:
        out["M1_E_BLOCK_PER"] = _int("M1_E_BLOCK_PER", m["parametersEblockPer"],
                                     "parametersEblockPer", _JS)
    for name, key, t, expr in (("M1_CALIB_DURATION", "parametersCalibDuration", tw, "/T_w"),
                               ("M1_FAULT_DURATION", "parametersFaultDuration", tw, "/T_w"),
                               ("M1_FREEWHEEL_DURATION", "parametersFreewheelDuration", tw,
                                "/T_w"),
                               ("M1_ALIGN_DURATION", "parametersAlignDuration", ts, "/T")):
        x = _n(m, key)
        if x is not None and t:
            out[name] = _int(name, x / t, key + expr, _JS)
    f_iir = _n(m, "parametersUdcbIIRf0")
    if f_iir:
        out.update(_iir("M1_UDCB_IIR", f_iir, ts, "bus-voltage low-pass at UdcbIIRf0"))
    u_nom, ratio, n_nom = (_n(m, k) for k in ("parametersUphNom", "parametersScalarVHzRatio",
                                              "parametersNnom"))
    if u_nom and ratio and n_nom and n_max:
        k = u_nom * ratio / 100.0 / um * n_max / n_nom
        expr = "UphNom·VHzRatio/100/U_max·N_max/Nnom"
        if k < 1.0:  # below one MCAT keeps the factor itself, shift 0 (the linix header)
            out["M1_SCALAR_VHZ_FACTOR_GAIN"] = _frac("M1_SCALAR_VHZ_FACTOR_GAIN", k, 16, um, "V",
                                                     expr, _HDR)
            out["M1_SCALAR_VHZ_FACTOR_SHIFT"] = fixed("M1_SCALAR_VHZ_FACTOR_SHIFT", 0, 16, 0, 1.0,
                                                      "", f"shift of {expr}", _HDR, fmt="int16")
        else:
            out.update(_gain_shift("M1_SCALAR_VHZ_FACTOR", k, um, "V", expr, _HDR))
    if n_max:
        out["M1_SCALAR_INTEG_GAIN"] = _acc32("M1_SCALAR_INTEG_GAIN", 2.0 * f_max * ts,
                                             1.0 / (2.0 * ts), "Hz", "2·f_max·T", _JS)
    for which, key in (("UP", "speedLoopIncUp"), ("DOWN", "speedLoopIncDown")):
        x = _n(m, key)
        if x is None or not n_max:
            continue
        for name, t, expr in ((f"M1_SCALAR_RAMP_{which}", ts, "·T"),
                              (f"M1_SPEED_RAMP_{which}", tw, "·T_w")):
            if t:
                out[name] = _frac(name, x / n_max * t, 32, n_max / t, "rpm/s",
                                  f"{key}/N_max{expr}", _JS)
    w_max = TWO_PI * pp * n_max / 60.0 if n_max else None
    kp, ki = _speed_pi(m)
    if kp is not None and w_max:
        out["M1_SPEED_PI_PROP_GAIN"] = _acc32("M1_SPEED_PI_PROP_GAIN", kp * w_max / im,
                                              im / w_max, "A/(rad/s)", "Kp·ω_max/I_max", _JS)
        if ki is not None and tw:
            out["M1_SPEED_PI_INTEG_GAIN"] = _acc32("M1_SPEED_PI_INTEG_GAIN", ki * tw * w_max / im,
                                                   im / w_max / tw, "A/rad",
                                                   "Ki·T_w·ω_max/I_max", _JS)
    fc = _n(m, "speedLoopCutOffFreq")
    if fc and tw:
        out.update(_iir("M1_SPEED_IIR", fc, tw, "speed low-pass at speedLoopCutOffFreq"))
    out.update(_encoder(m, n_max))
    return out


def _encoder(m: dict, n_max) -> dict:
    """The quadrature encoder's macros (MCAT's SENSORS section), from the JSON's ``sensors``."""
    out = {}
    pulses = _n(m, "sensorEncPulseNumber")
    if pulses:
        out["M1_POSPE_ENC_PULSES"] = _int("M1_POSPE_ENC_PULSES", pulses, "sensorEncPulseNumber",
                                          _ENC)
        # 4·N counts a revolution, and a revolution is 2^16 LSBs of the 16-bit position
        out["M1_POSPE_MECH_POS_GAIN"] = _acc32("M1_POSPE_MECH_POS_GAIN", 32768.0 / (2.0 * pulses),
                                               1.0, "LSB/count", "2^15/(4·N_enc/2)", _ENC)
    if _n(m, "sensorEncDir") is not None:
        out["M1_POSPE_ENC_DIRECTION"] = _int("M1_POSPE_ENC_DIRECTION", m["sensorEncDir"],
                                             "sensorEncDir", _ENC)
    n_min = _n(m, "sensorEncNmin")
    if n_min is not None and n_max:
        out["M1_POSPE_ENC_N_MIN"] = _frac("M1_POSPE_ENC_N_MIN", n_min / n_max, 32, n_max, "rpm",
                                          "sensorEncNmin/N_max", _ENC)
    kp = _n(m, "positionLoopPLKp")
    if kp is not None:
        out["M1_POS_P_PROP_GAIN"] = _frac("M1_POS_P_PROP_GAIN", kp, 16, 1.0, "",
                                          "positionLoopPLKp", _ENC)
    f0, ksi, t = (_n(m, k) for k in ("sensorObsrvParF0", "sensorObsrvParKsi",
                                      "sensorObsrvParSampleTime"))
    if f0 and ksi and t and n_max:  # the observer tracks the mechanical angle
        out.update(tracking("M1_POSPE_TO", ksi, TWO_PI * f0, t, TWO_PI * n_max / 60.0, _ENC))
    return out


def profile(ctx: dict, opt: dict) -> dict:
    """The NXP profile (:func:`pulab.profiles.nxp.scaling.profile`) and, with
    ``profiles.nxp.mcat``, the application macros of :func:`constants` beside its constants."""
    p = scaling.profile(ctx, opt)
    if opt.get("mcat"):
        p["constants"].update(constants(flatten(opt["mcat"]), ctx, opt))
    return p


def _speed_pi(m: dict) -> tuple:
    """MCAT's speed PI (Kp in A per electrical rad/s, Ki per second): typed, or designed."""
    if m.get("speedLoopManualConstantTunning") is True:
        return _n(m, "speedLoopSLKp"), _n(m, "speedLoopSLKi")
    f0, ksi, j, kt = (_n(m, k) for k in ("speedLoopF0", "speedLoopKsi", "parametersJ",
                                         "parametersKt"))
    if not (f0 and ksi and j and kt):
        return None, None
    w0 = TWO_PI * f0
    return 2.0 * ksi * w0 * j / kt, w0 * w0 * j / kt
