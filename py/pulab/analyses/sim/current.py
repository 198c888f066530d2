"""Current-loop step response: SI float, per-unit float and vendor fixed point.

All three variants drive the same plant (:mod:`pulab.analyses.sim.plant`, exact ZOH)
with the same reference, limits and timing, so their differences are only
those of the number representation:

``si``
    Float parallel PI in volts and amperes (seed 2.2-3, written as the vendor's
    order of operations: integral first, clamp, then add the proportional part).
``pu``
    The same PI in per unit (kp_pu, ki_pu; seed 2.1-4) on the per-unit plant
    (seed 1.2-2) with the per-unit period T_s·ω_b.  Results are multiplied by
    I_b and U_b only for output; they agree with ``si`` to ~1e-14.
``fixed``
    The vendor code: the plant current quantized to Q12 (round to nearest, ties
    away, int16 saturation ±8 pu, i.e. the ADC reading ``gIMTQ12``), the exact
    integer update :func:`pulab.profiles.inovance.code.current_pi_step` (Q12 error, Q24
    integral, pm_kp Q12, pm_ki Q16, clamps ±maxu and ±pm_maxout_vol), and the
    Q12 output turned into plant voltage.
``by_profile``
    TI's, NXP's, ST's and Microchip's own integer PI on the same plant
    (:mod:`pulab.analyses.sim.vendor_loop`).

Line or phase voltage (seed 1.3, 2.2)
-------------------------------------
The seed reads the PI output ``pm_ud`` as a per-unit *line* voltage (base: the
rated line voltage ``Voltage``) produced by line-valued gains; the plant
(seed 1.2-3) needs *phase* voltage, hence the seed's "divide by √3".  The
contract's gains are phase gains (kp in Ω per phase) and
pm_kp = kp·I_b/U_b·2^12 with the phase base U_b.  Then
``out = Δi/I_b·2^12 · kp·I_b/U_b·2^12 / 2^12 = kp·Δi/U_b·2^12``, so
**out/2^12·U_b is the phase voltage** kp·Δi.  With line gains
kp_LL = √3·kp and base √3·U_b = ``Voltage`` the integers are identical and
out/2^12·Voltage is the line voltage; dividing by √3 gives the same phase
voltage.  The two readings are one number.

Voltage limit: ``pm_maxout_vol`` = (U_dc/√2)/Voltage·2^12 is the SVPWM linear
limit (line RMS U_dc/√2, seed 2.2-2) per unit of the rated line voltage, which
is the same ratio as the phase limit U_dc/√6 to U_b (rms convention) or
U_dc/√3 to √(2/3)·U_LL (peak).  The float variants use exactly the firmware
limits: ±pm_maxout_vol/2^12·U_b on the output and ±maxu/2^24·U_b on the
integral (the vendor's anti-windup clamp), each axis clamped separately as the
vendor code does.  (With ``custom`` bases the firmware limit is still per unit
of the rated voltage while the PI uses the custom U_b; the simulation applies
the firmware's number, as the firmware would.)

Timing: the current is sampled at t_k = k·T_s, the PI runs, and its output
is held over [t_k, t_k+1) — or, with ``delay``, over [t_k+1, t_k+2) (one-sample
computation delay).  At t = 0 the drive runs at the given speed with zero
current: the q integral is preloaded with the back-EMF ω_e·ψ_r (clamped), which
is the steady state for i = 0, so the step response is not mixed with a
back-EMF start-up transient.  The reference steps at t = 0.
"""

from __future__ import annotations

import math
from array import array

from ...schema.errors import InputError
from ..slices import SLICE_STEPS, finish
from ...fixedpoint.cint import INT32, wrap_to
from ...fixedpoint.qformat import iqsat, round_half_away
from ...profiles.inovance.code import current_pi_step
from .inputs import periods
from .plant import zoh
from . import code_loop, vendor_loop

__all__ = ["voltage_limits", "run_float", "run_fixed", "run", "run_float_steps", "run_fixed_steps", "run_steps",
           "MAX_STEPS", "Q12_CURRENT_LIMIT_PU"]

#: Upper bound on the number of controller periods of one run (keeps a typo in
#: ``duration_s`` from hanging the browser).
MAX_STEPS = 200_000

#: gIMTQ12 is an int16 in Q12: |i| < 8 pu.
Q12_CURRENT_LIMIT_PU = 32767 / 4096.0


def run_float_steps(z, kp_d: float, ki_ts_d: float, kp_q: float, ki_ts_q: float, umax: float,
                    imax: float, ref_d: float, ref_q: float, integ_q0: float, n: int,
                    delay: bool, integ_d0: float = 0.0):
    """Float PI + ZOH plant for n+1 samples (SI or per unit, same code).

    Parameters
    ----------
    z : Zoh
        Plant transition in the units of the run.
    kp_d, kp_q : float > 0, V/A or pu ; ki_ts_d, ki_ts_q : float > 0
        Proportional gain and integral gain times T_s (the increment per period).
    umax, imax : float > 0, V or pu — output and integral clamps
    ref_d, ref_q : float, A or pu — references from t = 0
    integ_q0 : float — initial q integral (back-EMF preload)
    n : int ≥ 1 — number of periods; samples k = 0..n
    delay : bool — one-sample computation delay
    integ_d0 : float — initial d integral (an induction motor's magnetized start)

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returns a dict
        ``id, iq, ud, uq`` (arrays of n+1 floats: current at t_k, voltage applied
        from t_k) and ``sat`` (array of 0/1: an output was at its limit at t_k).
        Arrays, not lists: 8 bytes a sample instead of 32 at the 200 000-period cap.
    """
    plant = z.advance()
    xd, xq = z.x0
    integ_d = max(-imax, min(imax, integ_d0))
    integ_q = max(-imax, min(imax, integ_q0))
    prev_d, prev_q = max(-umax, min(umax, integ_d)), max(-umax, min(umax, integ_q))
    ids, iqs, uds, uqs, sats = array("d"), array("d"), array("d"), array("d"), array("b")
    for k in range(n + 1):
        if k and not k % SLICE_STEPS:
            yield
        ids.append(xd)
        iqs.append(xq)
        ed = ref_d - xd
        eq = ref_q - xq
        # Vendor order (seed 2.2): integral += Δi·ki·Ts, clamp, then out = integral + Δi·kp, clamp.
        integ_d += ki_ts_d * ed
        if integ_d > imax:
            integ_d = imax
        elif integ_d < -imax:
            integ_d = -imax
        integ_q += ki_ts_q * eq
        if integ_q > imax:
            integ_q = imax
        elif integ_q < -imax:
            integ_q = -imax
        od = integ_d + kp_d * ed
        oq = integ_q + kp_q * eq
        sat = False
        if od >= umax:
            od, sat = umax, True
        elif od <= -umax:
            od, sat = -umax, True
        if oq >= umax:
            oq, sat = umax, True
        elif oq <= -umax:
            oq, sat = -umax, True
        sats.append(sat)
        if delay:
            ad, aq, prev_d, prev_q = prev_d, prev_q, od, oq
        else:
            ad, aq = od, oq
        uds.append(ad)
        uqs.append(aq)
        xd, xq = plant(xd, xq, ad, aq)
    return {"id": ids, "iq": iqs, "ud": uds, "uq": uqs, "sat": sats}


def run_float(*args, **kwargs):
    """:func:`run_float_steps` run to the end: the same arguments, the same result."""
    return finish(run_float_steps(*args, **kwargs))


def run_fixed_steps(z, i_b: float, u_b: float, pm_kp_d: int, pm_ki_d: int, pm_kp_q: int,
                    pm_ki_q: int, maxu: int, maxout: int, ref_d: int, ref_q: int,
                    integ_q0: int, n: int, delay: bool, memo: bool = True, integ_d0: int = 0):
    """Vendor fixed-point PI (seed 2.2, :func:`pulab.profiles.inovance.code.current_pi_step`) on the SI plant.

    Parameters
    ----------
    z : Zoh — SI plant transition (A, V)
    i_b, u_b : float > 0, A and V — current and phase-voltage bases
    pm_kp_d, pm_kp_q : int, Q12 ; pm_ki_d, pm_ki_q : int, Q16 (T_s folded in)
    maxu : int, Q24 ; maxout : int, Q12 (pm_maxout_vol)
    ref_d, ref_q : int, Q12 references (pm_ref_id, pm_ref_iq)
    integ_q0 : int, Q24 — initial q integral (back-EMF preload)
    n : int ≥ 1 ; delay : bool
    integ_d0 : int, Q24 — initial d integral (an induction motor's magnetized start)
    memo : bool
        Memoize current_pi_step (a pure function) per axis; False only for the
        benchmark's worst case and the test that the memo changes nothing.

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returns a dict
        As :func:`run_float`, in A and V (phase), plus ``fb_d, fb_q``: the Q12
        feedback integers, and ``wraps``: the PI updates (both axes) whose long
        arithmetic wrapped — what the firmware computes then, not an error.
    """
    plant = z.advance()
    to_q12 = 4096.0 / i_b
    to_volt = u_b / 4096.0
    xd, xq = z.x0
    # a preload as the PI clamps it (minu = -maxu); no d preload is the reset state, 0
    integ_d = iqsat(integ_d0, maxu, wrap_to(-maxu, INT32)) if integ_d0 else 0
    integ_q = iqsat(integ_q0, maxu, wrap_to(-maxu, INT32))
    prev_d = max(-maxout, min(maxout, integ_d >> 12)) * to_volt
    prev_q = max(-maxout, min(maxout, integ_q >> 12)) * to_volt
    ids, iqs, uds, uqs, sats = array("d"), array("d"), array("d"), array("d"), array("b")
    fbd, fbq = array("l"), array("l")
    # current_pi_step is a pure function of its integer arguments; within one run
    # only (integral, error) change, and in steady state the same pairs recur
    # (limit cycles of one LSB), so a memo saves most of its CInt bookkeeping
    # without re-implementing the vendor arithmetic.
    memo_d: dict = {}
    memo_q: dict = {}
    wraps = 0
    for k in range(n + 1):
        if k and not k % SLICE_STEPS:
            yield
        ids.append(xd)
        iqs.append(xq)
        # ADC reading: round to nearest Q12, ties away from zero, saturate to int16.
        v = xd * to_q12
        fd = int(v + 0.5) if v >= 0 else -int(0.5 - v)
        fd = 32767 if fd > 32767 else -32768 if fd < -32768 else fd
        v = xq * to_q12
        fq = int(v + 0.5) if v >= 0 else -int(0.5 - v)
        fq = 32767 if fq > 32767 else -32768 if fq < -32768 else fq
        fbd.append(fd)
        fbq.append(fq)
        key = (integ_d, ref_d - fd)
        r = memo_d.get(key)
        if r is None:
            r = memo_d[key] = current_pi_step(integ_d, ref_d - fd, pm_kp_d, pm_ki_d, maxu, maxout)
        integ_d, od = r[0], r[1]
        wraps += "wrap" in r[2]
        key = (integ_q, ref_q - fq)
        r = memo_q.get(key)
        if r is None:
            r = memo_q[key] = current_pi_step(integ_q, ref_q - fq, pm_kp_q, pm_ki_q, maxu, maxout)
        integ_q, oq = r[0], r[1]
        wraps += "wrap" in r[2]
        if len(memo_d) > 4096 or not memo:
            memo_d.clear()
        if len(memo_q) > 4096 or not memo:
            memo_q.clear()
        sats.append(od == maxout or od == -maxout or oq == maxout or oq == -maxout)
        # Q12 output × U_b = phase voltage (module docstring: line vs phase).
        od_v = od * to_volt
        oq_v = oq * to_volt
        if delay:
            ad, aq, prev_d, prev_q = prev_d, prev_q, od_v, oq_v
        else:
            ad, aq = od_v, oq_v
        uds.append(ad)
        uqs.append(aq)
        xd, xq = plant(xd, xq, ad, aq)
    return {"id": ids, "iq": iqs, "ud": uds, "uq": uqs, "sat": sats, "fb_d": fbd, "fb_q": fbq,
            "wraps": wraps}


def run_fixed(*args, **kwargs):
    """:func:`run_fixed_steps` run to the end: the same arguments, the same result."""
    return finish(run_fixed_steps(*args, **kwargs))


def default_duration(report: dict, axis: str) -> float:
    """Default run length: 30 closed-loop time constants 1/ω_c, at least 200 periods.

    Parameters
    ----------
    report : dict — the report (needs current_pi, input)
    axis : {'d', 'q'}

    Returns
    -------
    float, seconds
    """
    ts = report["input"]["drive"]["ts_s"]
    l_h = report["input"]["motor"]["ld_h" if axis == "d" else "lq_h"]
    # kp = ω_c·L for the bandwidth design; for the others kp/L is still the
    # crossover frequency of the open loop, the relevant time scale.
    w_c = report["current_pi"][axis]["kp"] / l_h
    return max(200 * ts, 30.0 / w_c)


def voltage_limits(report: dict) -> tuple[float, float, tuple[int, int] | None]:
    """The current PI's output and integral limits in per unit of U_b, and the firmware's
    integers (pm_maxout_vol Q12, maxu Q24) they come from.

    When the Inovance firmware cannot compute them for this drive (``firmware.inovance``)
    the integers are None — there is no fixed-point run — and the limits are the physical
    U_dc/√2 (line RMS) over the rated line voltage, the same ratio without the firmware's
    whole-volt truncation.
    """
    vendor = report["vendor"]
    if "pm_maxout_vol" in vendor and "maxu" in vendor:
        maxout, maxu = vendor["pm_maxout_vol"]["value"], vendor["maxu"]["value"]
        return maxout / 4096.0, maxu / 16777216.0, (maxout, maxu)
    inp = report["input"]
    ratio = inp["drive"]["udc_v"] / math.sqrt(2.0) / inp["motor"]["rated_voltage_v"]
    return ratio, ratio, None


def run_steps(report: dict, cfg: dict):
    """Run the three variants for one reference step.

    Parameters
    ----------
    report : dict
        The report (``input``, ``base``, ``pu``, ``vendor``, ``current_pi``).
    cfg : dict
        Normalized ``sim.current`` (:func:`pulab.analyses.sim.validate`).

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returns a dict
        ``t`` (s), ``ts``, ``n``, ``axis``, ``ref_a`` (A), and ``variants``:
        ``si``/``pu``/``fixed`` → ``id, iq, ud, uq`` in A and V (phase) plus ``sat``;
        no ``fixed`` when the Inovance firmware cannot compute its voltage limits;
        ``by_profile``: TI, NXP, ST, Microchip (:func:`_profile_runs`); with
        ``sim.current.code``, ``code``: the user's routine (:func:`.code_loop.run_code_steps`,
        plus ``lsb_a``, ``scale`` and ``zeroed``).

    Raises
    ------
    InputError
        ``sim.current.duration_s`` for too many periods, ``sim.current.step_a``
        for a reference outside the Q12 int16 range, ``sim.current.speed_hz`` at or
        above half the control frequency; ``sim.current.code.*`` for a routine that does
        not compile or a binding the code does not have (:func:`.code_loop.bind`).
    """
    inp, b, pu, vendor, pi = (report["input"], report["base"], report["pu"], report["vendor"],
                              report["current_pi"])
    m = inp["motor"]
    ts = inp["drive"]["ts_s"]
    u_b, i_b, w_b = b["U_b"], b["I_b"], b["w_b"]
    axis = cfg["axis"]
    duration = cfg["duration_s"] if cfg["duration_s"] is not None else \
        default_duration(report, axis)
    code = cfg.get("code")
    n = periods(duration, ts, MAX_STEPS if code is None else code_loop.MAX_PERIODS,
                "sim.current.duration_s")
    step = cfg["step_a"] if cfg["step_a"] is not None else 0.5 * i_b
    if abs(step / i_b) >= Q12_CURRENT_LIMIT_PU:
        raise InputError("sim.current.step_a", code="step_q12", value=step, pu=step / i_b,
                         limit=8 * i_b)
    ref_d, ref_q = (step, 0.0) if axis == "d" else (0.0, step)
    if abs(cfg["speed_hz"]) * ts >= 0.5:
        # Beyond Nyquist the sampled dq model is meaningless (and ω_e·Ts is unbounded).
        raise InputError("sim.current.speed_hz", code="speed_nyquist", value=abs(cfg["speed_hz"]),
                         nyquist=0.5 / ts)
    omega = 2.0 * math.pi * cfg["speed_hz"]
    umax_pu, imax_pu, ints = voltage_limits(report)
    fixed = ints is not None
    if fixed:
        maxout, maxu = ints
    gd, gq = pi["d"], pi["q"]

    z_si = zoh(m["rs_ohm"], m["ld_h"], m["lq_h"], pu["psi_r_wb"], omega, ts)
    if code is not None:  # bound first: a binding error costs no simulation
        sc = code_loop.scale(report, code["scale"], umax_pu, maxout if fixed else None)
        shift = code["integral_shift"]
        # the back-EMF within the voltage limit, as every run here clamps its preload
        top = sc["out_limit"] << shift
        preload = 0 if code["integral"] is None else \
            max(-top, min(top, round_half_away(z_si.bemf / sc["to_volt"] * 2.0 ** shift)))
        binding = code_loop.bind(code, report, preload)
    si = yield from run_float_steps(z_si, gd["kp"], gd["ki"] * ts, gq["kp"], gq["ki"] * ts,
                                    umax_pu * u_b, imax_pu * u_b, ref_d, ref_q, z_si.bemf, n,
                                    cfg["delay"])

    z_pu = zoh(pu["Rs"], pu["Ld"], pu["Lq"], pu["psi_r"], omega / w_b, pu["Ts"])
    # The per-unit PI integrates in seconds like the firmware (pm_ki = ki_pu·Ts·2^16).
    p = yield from run_float_steps(z_pu, gd["kp_pu"], gd["ki_pu"] * ts, gq["kp_pu"],
                                   gq["ki_pu"] * ts, umax_pu, imax_pu, ref_d / i_b, ref_q / i_b,
                                   z_pu.bemf, n, cfg["delay"])
    p = {"id": [x * i_b for x in p["id"]], "iq": [x * i_b for x in p["iq"]],
         "ud": [x * u_b for x in p["ud"]], "uq": [x * u_b for x in p["uq"]], "sat": p["sat"]}
    yield  # the unit conversions are a slice of their own
    variants = {"si": si, "pu": p}
    by_profile = yield from _profile_runs(report, z_si, umax_pu * u_b, ref_d, ref_q, n,
                                          cfg["delay"])
    out = {"t": array("d", (k * ts for k in range(n + 1))), "ts": ts, "n": n, "axis": axis,
           "ref_a": step, "variants": variants, "by_profile": by_profile}
    if code is not None:
        run = yield from code_loop.run_code_steps(z_si, binding, sc, ref_d, ref_q,
                                                  preload >> shift, n, cfg["delay"])
        out["code"] = {**run, "lsb_a": sc["lsb_a"], "scale": code["scale"],
                       "zeroed": binding.zeroed}
    if not fixed:
        return out
    variants["fixed"] = yield from run_fixed_steps(z_si, i_b, u_b, gd["pm_kp"], gd["pm_ki"], gq["pm_kp"],
                                    gq["pm_ki"], maxu, maxout,
                                    round_half_away(ref_d / i_b * 4096.0),
                                    round_half_away(ref_q / i_b * 4096.0),
                                    round_half_away(z_pu.bemf * 16777216.0), n, cfg["delay"])
    return out


def _profile_runs(report: dict, z, umax_v: float, ref_d: float, ref_q: float, n: int,
                  delay: bool):
    """TI's, NXP's, ST's and Microchip's integer PI on the plant (:mod:`.vendor_loop`).

    Returns (through the generator) NAME → the run, or → ``{"problems": [...]}`` (the
    codes and fields of ``firmware.NAME.problems``) when that firmware cannot represent
    the motor.
    """
    profiles, status = vendor_loop.profile_data(report)
    peak = math.sqrt(2.0) if report["input"]["conventions"]["base"] == "rms" else 1.0
    ctls = None
    out = {}
    for name in vendor_loop.names():
        st = status[name]
        if not st["representable"]:
            out[name] = {"problems": [{"field": x["field"], "code": x["code"]}
                                      for x in st["problems"]]}
            continue
        if ctls is None:
            ctls = vendor_loop.controllers(profiles, umax_v * peak,
                                           report["input"]["drive"]["udc_v"])
        out[name] = yield from vendor_loop.run_profile_steps(z, ctls[name], peak, ref_d, ref_q,
                                                             z.bemf, n, delay)
    return out


def run(*args, **kwargs):
    """:func:`run_steps` run to the end: the same arguments, the same result."""
    return finish(run_steps(*args, **kwargs))
