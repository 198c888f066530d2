"""The current loop closed through each vendor's own integer PI (TI, NXP, ST, Microchip).

Each vendor that provides a ``controller`` (:class:`pulab.profiles.vendor.Vendor`; its
``pi`` module, e.g. :mod:`pulab.profiles.ti.pi`) runs on that profile's integers from the
report (``profiles.NAME.constants`` and ``inputs``; the defaults when the input has no
``profiles``) and drives the same plant as the float variants (:mod:`.plant`, exact ZOH).

Scaling, per sample (the plant is in the dq scale of ``conventions.base``; every vendor
counts phase *peak* amperes and volts, so rms bases are multiplied by √2 on the way in
and divided on the way out):

- feedback: the plant current rounded to the nearest count of the vendor's current
  scale and clipped to its word — an ideal ADC reading in that word; clipping counts as
  ``feedback_saturate``.  (TI: IQ(GLOBAL_Q) of I_FS; NXP: frac16 of I_MAX; ST: digits of
  MAX_CURRENT/32768; Microchip: Q15 of I_b.)  The reference is the same rounding of the
  step.
- output: the controller's integer times the vendor's voltage scale (TI V_FS/2^q, NXP
  U_max/2^15, ST (U_dc/√3)/2^15 — pulab's assumption, :mod:`pulab.profiles.st` —,
  Microchip V_b/2^15).
- limits: the float variants' output limit (the report's U_dc/√3 phase peak,
  :func:`.current.voltage_limits`) in each vendor's integer, as its application code
  sets it (TI ``_IQ()`` and NXP ``FRAC16()`` toward zero, Microchip nearest); ST keeps
  MCSDK's own ±INT16_MAX (``mc_config.c``), which is the same voltage.  Microchip's
  anti-windup gain Kc is Q15(0.99999) = 32767 as in AN1078.
- start: the q integral holds the back-EMF (as for the float runs), in each vendor's
  integral format (TI _iq, NXP f16 << 16 as ``GFLIB_CtrlPIpAWInit_F16``, ST digits·KIDIV
  as ``PID_SetIntegralTerm``, Microchip Q15 << 15).

Not modelled: the ADC's own resolution below the word, MCSDK's circle limitation and
NXP's stop-integration flag (both act only when the voltage vector is limited).
"""

from __future__ import annotations

from array import array

from ... import profiles as _profiles
from ...fixedpoint.counted import EVENTS
from ...fixedpoint.qformat import round_half_away
from ...profiles import registry
from ...profiles.vendor import provided
from ..slices import SLICE_STEPS

__all__ = ["names", "EVENT_NAMES", "profile_data", "controllers", "run_profile_steps"]


def names() -> tuple:
    """The vendors with a fixed-point simulation here: those that provide a ``controller``
    (Inovance's run is the report's own, :mod:`.current`)."""
    return tuple(v.NAME for v in registry.vendors() if provided(v, "controller"))


#: Event counts reported per run.
EVENT_NAMES = ("feedback_saturate",) + EVENTS


def profile_data(report: dict) -> tuple[dict, dict]:
    """The report's ``profiles`` and each one's ``firmware`` status; when the input asked for
    no profiles, every profile with its default options (the page's sim request has none).

    Returns
    -------
    (profiles, status) — NAME → profile section, NAME → {representable, problems}
    """
    # all five only when the input asked (a report without them holds the shipped one alone)
    if "profiles" in report["input"]:
        return report["profiles"], report["firmware"]
    ctx = _profiles.context_of(report)
    prof = _profiles.profiles(ctx, _profiles.options({}, ctx))
    return prof, {name: p["status"] for name, p in prof.items()}


def controllers(profiles: dict, umax_peak: float, udc: float) -> dict:
    """Each profile's controller: scales, limits and its two bound step functions.

    Parameters
    ----------
    profiles : dict — ``profiles`` of a report (constants and inputs per vendor)
    umax_peak : float > 0, V — the output limit, phase peak
    udc : float > 0, V — the DC bus (ST's voltage digit)

    Returns
    -------
    dict NAME → ``i_lsb`` (A peak per feedback count), ``fb_bits``, ``u_lsb`` (V peak per
    output count), ``out_limit`` (int), ``steps`` ({'d', 'q'} → step(state, ref, fb, ev)),
    ``start`` (V peak → initial state), ``held`` (state → the output its integral alone
    gives: what a one-sample delay holds at t = 0)
    """
    return {name: registry.get(name).controller(profiles[name], umax_peak, udc)
            for name in names()}


def _quantize(x: float, bits: int, ev: dict) -> int:
    v = round_half_away(x)
    hi = (1 << (bits - 1)) - 1
    if v > hi or v < -hi - 1:
        ev["feedback_saturate"] += 1
        return hi if v > hi else -hi - 1
    return v


def _memo_step(memo: dict, step, state: tuple, ref: int, fb: int, ev: dict) -> tuple:
    key = (state, fb)
    hit = memo.get(key)
    if hit is None:
        if len(memo) > 4096:
            memo.clear()
        own: dict = {}
        new, out = step(state, ref, fb, ev=own)
        hit = memo[key] = (new, out, tuple(own.items()))
    if hit[2]:
        for name, count in hit[2]:
            ev[name] += count
    return hit[0], hit[1]


def run_profile_steps(z, ctl: dict, peak: float, ref_d: float, ref_q: float, bemf_v: float,
                      n: int, delay: bool, record: bool = False, hold_d_v: float = 0.0):
    """One vendor's integer PI on the SI plant for n+1 samples.

    Parameters
    ----------
    z : Zoh — SI plant transition (A, V in the dq scale of the report's bases)
    ctl : dict — one entry of :func:`controllers`
    peak : float — √2 for rms bases, 1 otherwise (dq scale → phase peak)
    ref_d, ref_q : float, A — references (dq scale)
    bemf_v : float, V — the q integral's start (dq scale)
    n : int ≥ 1 ; delay : bool — one-sample computation delay
    record : bool — also return the integers ``fb_d, fb_q, out_d, out_q`` (for the oracle)
    hold_d_v : float, V — the d integral's start (an induction motor's magnetized start)

    Returns
    -------
    generator — yields None every SLICE_STEPS periods, returns a dict
        ``id, iq, ud, uq`` (A, V in the dq scale), ``sat`` (0/1), with ``record`` the
        integers ``fb_d, fb_q, out_d, out_q``, ``events`` (:data:`EVENT_NAMES` → count) and
        ``lsb_a`` (one feedback count in A, dq scale).
    """
    plant = z.advance()
    ev = dict.fromkeys(EVENT_NAMES, 0)
    to_count = peak / ctl["i_lsb"]
    to_volt = ctl["u_lsb"] / peak
    bits, lim = ctl["fb_bits"], ctl["out_limit"]
    step_d, step_q = ctl["steps"]["d"], ctl["steps"]["q"]
    r_d = _quantize(ref_d * to_count, bits, ev)
    r_q = _quantize(ref_q * to_count, bits, ev)
    st_d = ctl["start"](hold_d_v * peak)
    st_q = ctl["start"](bemf_v * peak)
    xd, xq = z.x0
    prev_d, prev_q = ctl["held"](st_d) * to_volt, ctl["held"](st_q) * to_volt
    # The steps are pure functions of (state, reference, feedback): in steady state the same
    # pairs recur (limit cycles of a count or two), so a memo saves most calls (as the
    # Inovance run's does); each entry keeps the events of its call, counted again on reuse.
    memo_d: dict = {}
    memo_q: dict = {}
    cols = {k: array("d") for k in ("id", "iq", "ud", "uq")}
    ints = {k: array("l") for k in ("fb_d", "fb_q", "out_d", "out_q")}
    sats = array("b")
    put_id, put_iq, put_ud, put_uq = (cols[k].append for k in ("id", "iq", "ud", "uq"))
    put_fd, put_fq, put_od, put_oq = (ints[k].append for k in ("fb_d", "fb_q", "out_d", "out_q"))
    hi = (1 << (bits - 1)) - 1
    lo = -hi - 1
    for k in range(n + 1):
        if k and not k % SLICE_STEPS:
            yield
        put_id(xd)
        put_iq(xq)
        # The feedback: nearest count (ties away from zero), clipped to the word.
        v = xd * to_count
        fd = int(v + 0.5) if v >= 0 else -int(0.5 - v)
        if fd > hi or fd < lo:
            ev["feedback_saturate"] += 1
            fd = hi if fd > hi else lo
        v = xq * to_count
        fq = int(v + 0.5) if v >= 0 else -int(0.5 - v)
        if fq > hi or fq < lo:
            ev["feedback_saturate"] += 1
            fq = hi if fq > hi else lo
        hit = memo_d.get((st_d, fd))
        if hit is None or hit[2]:
            st_d, od = _memo_step(memo_d, step_d, st_d, r_d, fd, ev)
        else:
            st_d, od = hit[0], hit[1]
        hit = memo_q.get((st_q, fq))
        if hit is None or hit[2]:
            st_q, oq = _memo_step(memo_q, step_q, st_q, r_q, fq, ev)
        else:
            st_q, oq = hit[0], hit[1]
        if record:
            put_fd(fd)
            put_fq(fq)
            put_od(od)
            put_oq(oq)
        sats.append(od >= lim or od <= -lim or oq >= lim or oq <= -lim)
        od_v, oq_v = od * to_volt, oq * to_volt
        if delay:
            ad, aq, prev_d, prev_q = prev_d, prev_q, od_v, oq_v
        else:
            ad, aq = od_v, oq_v
        put_ud(ad)
        put_uq(aq)
        xd, xq = plant(xd, xq, ad, aq)
    return {**cols, "sat": sats, **(ints if record else {}), "events": ev,
            "lsb_a": ctl["i_lsb"] / peak}
