"""The full report: bases, per-unit values, vendor integers, gains (docs/contract.md).

Examples
--------
>>> r = report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> r["vendor"]["Rpm"]["value"], r["vendor"]["LD"]["value"]
(15022, 1045)
"""

from __future__ import annotations

from .model.bases import bases, flux_linkage, per_unit
from .model.board import board
from .profiles.inovance.magic import magic_constants
from .model.datasheet import mechanical
from .model.gains import current_pi, current_pi_si, gains_from_integers, pll_gains
from .schema.inputs import normalize
from .schema.errors import InputError
from .schema.fields import FIELD
from .schema.validate import value
from .model.acim import model as acim_model
from .analyses import acim as _acim
from .schema.catalog import render
from .analyses import registry as _analyses
from .analyses.registry import at, put
from .analyses.review import review
from .analyses.slices import finish
from . import profiles as _profiles
from .profiles import limits, registry
from .profiles.inovance.code import current_pi_step, raw_from_si, raw_split, vendor_split
from .profiles.vendor import provided

__all__ = ["report", "report_steps", "format_text", "input_bases", "input_raw", "input_raw_split",
           "current_pi_section", "require_pmsm"]


def _profile_warnings(prof: dict) -> list:
    """The vendors' own warnings (their optional ``warnings``), then one per profile constant
    the firmware could not store as intended, as ``(catalog code, params)`` pairs."""
    w = []
    for name, p in prof.items():
        own = provided(registry.get(name), "warnings")
        if own:
            w += own(p)
    for name, p in prof.items():
        for k, c in p["constants"].items():
            params = {"path": f"profiles.{name}.{k}", "profile_name": {"vendor": name}, "name": k,
                      "ideal": c["ideal"], "format": c["format"], "value": c["value"]}
            if "out_of_range" in c["flags"] or "saturate" in c["flags"]:
                w.append(("warning.profile_overflow", params))
            elif c["value"] == 0 and c["ideal"] != 0:
                w.append(("warning.profile_zero", params))
    return w


#: The vendor results the firmware's voltage limits come from (the PI's clamps).
_LIMITS = frozenset(("maxu", "pm_maxout_vol"))


def _pi_example(g: dict, vendor: dict) -> dict:
    """The first vendor PI update after a step of 10 % rated current in i_d (seed 2.2)."""
    error = round(0.1 * 4096)
    trace: list = []
    current_pi_step(0, error, g["pm_kp"], g["pm_ki"], vendor["maxu"]["value"],
                    vendor["pm_maxout_vol"]["value"], trace)
    return {"error": error, "integral": 0, "trace": trace}


def input_bases(n: dict) -> dict:
    """The bases (contract ``base``) of a normalized input."""
    m, d, c = n["motor"], n["drive"], n["conventions"]
    return bases(c["base"], m["rated_voltage_v"], m["rated_current_a"], d["base_freq_hz"],
                 c["base_voltage_v"], c["base_current_a"], c["angle_base"])


def require_pmsm(n: dict) -> None:
    """Refuse an induction motor (input ``n``, given or normalized) where only a PMSM's
    firmware integers are computed (the Inovance raw block, sweeps, batches, proofs,
    translation)."""
    motor = n.get("motor")
    if isinstance(motor, dict) and motor.get("kind") == "acim":
        raise InputError("motor.kind", code="acim_not_applicable")


def _si(n: dict) -> dict:
    require_pmsm(n)
    return {f"{s}.{k}": v for s in ("motor", "drive") for k, v in n[s].items()}


def input_raw(n: dict) -> dict:
    """The raw firmware integers (contract ``vendor.raw``) of a normalized input, every one
    required to fit its Uint16 (raises :class:`InputError` naming ``raw.NAME``)."""
    return raw_from_si(_si(n), n["conventions"]["inductance_unit"], n["raw"])


def input_raw_split(n: dict) -> tuple[dict, dict]:
    """The raw firmware integers that fit, and those the firmware cannot hold
    (:func:`pulab.profiles.inovance.code.raw_split`)."""
    return raw_split(_si(n), n["conventions"]["inductance_unit"], n["raw"])


def current_pi_section(n: dict, b: dict, plant: tuple | None = None) -> dict:
    """The current PI gains of both axes (contract ``current_pi`` without ``step_example``);
    ``plant`` = (R [Ω], L_d [H], L_q [H]) of the loop, the motor's R_s, L_d, L_q when None."""
    m, d, cl = n["motor"], n["drive"], n["current_loop"]
    r_ohm, ld_h, lq_h = plant or (m["rs_ohm"], m["ld_h"], m["lq_h"])
    pi = {"method": cl["method"],
          "bandwidth_hz": cl["bandwidth_hz"] if cl["method"] in ("bandwidth", "damping") else None}
    for axis, l_h in (("d", ld_h), ("q", lq_h)):
        if cl["method"] == "integers":
            kp, ki = gains_from_integers(cl["pm_kp"], cl["pm_ki"], b["U_b"], b["I_b"], d["ts_s"])
        else:
            kp, ki = current_pi_si(cl["method"], r_ohm, l_h, cl["bandwidth_hz"],
                                   cl["damping"], cl["kp"], cl["ki"])
        pi[axis] = current_pi(kp, ki, l_h, b["U_b"], b["I_b"], d["ts_s"])
    return pi


def report(inp: dict) -> dict:
    """Compute the report for one motor and drive: :func:`report_steps` run to the end.

    Parameters, result and errors are those of :func:`report_steps`.
    """
    return finish(report_steps(inp))


def report_steps(inp: dict):
    """Compute the report for one motor and drive, in slices.

    Parameters
    ----------
    inp : dict
        Input per docs/contract.md.

    Returns
    -------
    generator — yields None between slices of the simulation (:mod:`pulab.analyses.slices`; none
    without ``sim``), returning a dict:
        ``input`` (normalized), ``base``, ``pu``, ``vendor``, ``current_pi``, ``pll``,
        ``constants``, ``mechanical``, ``review`` (graded findings, :mod:`pulab.analyses.review`),
        ``warnings``/``warnings_zh`` (the review's errors and warnings as text, then the
        profiles' and the loop analysis' warnings), ``datasheet`` (when given: values and
        conversions) and, when asked, the optional sections (``board``, ``observer``,
        ``loop``, ``fw``, ``sim``: :data:`pulab.analyses.registry.ANALYSES`).

    Raises
    ------
    pulab.InputError
        Naming the field, for any bad input or firmware division by zero.
    """
    n = normalize(inp)
    if n["motor"].get("kind") == "acim":
        return (yield from _acim_report(n))
    m, d, c = n["motor"], n["drive"], n["conventions"]
    plan = _analyses.plan(_analyses.ANALYSES)  # read per call: a test may add an entry
    checked = {a.key: a.check(given) for a in plan.checked
               if (given := at(n, a.asked)) is not None}
    b = input_bases(n)
    psi = flux_linkage(c["base"], m["bemf_v"], m["rated_freq_hz"])
    pu = per_unit(b, m["rs_ohm"], m["ld_h"], m["lq_h"], psi, d["ts_s"])
    # The Inovance integers are one firmware's view: what it cannot hold is reported in
    # ``firmware.inovance``, and the physics goes on without it.
    raw, outside = input_raw_split(n)
    vendor, failed = vendor_split(raw, c["inductance_unit"])
    firmware = {"inovance": limits.status(limits.inovance(outside, failed,
                                                          c["inductance_unit"]))}
    pi = current_pi_section(n, b)
    pi["step_example"] = _pi_example(pi["d"], vendor) if _LIMITS <= vendor.keys() else None
    # what the profiles read (the board's scales, the observer's settings), before them
    core = {"input": n, "base": b}
    for a in plan.model:
        if (given := at(n, a.asked)) is not None:
            core[a.key] = a.prepare(core, checked.get(a.key, given))
            if a.echo is not None:
                put(n, a.asked, a.echo(given, core[a.key]))
    prof = None
    shipped = c["firmware"]
    # The five profiles only when asked (they cost more than the rest); the one shipped always,
    # so that one report holds its integers and the review grades what it cannot hold.
    if "profiles" in n or shipped != "inovance":
        ctx = _profiles.context(n, raw, vendor, pi, firmware["inovance"]["problems"],
                                core.get("board"))
        opts = _profiles.options(n.get("profiles"), ctx)
        if "profiles" in n:
            n["profiles"] = opts
        prof = _profiles.profiles(ctx, opts, None if "profiles" in n else (shipped,))
        firmware.update({name: p.pop("status") for name, p in prof.items()})
    out = {
        "input": {k: v for k, v in n.items() if k not in ("sim", "analysis", "datasheet")},
        "base": b,
        "pu": pu,
        "vendor": {"raw": raw, **vendor},
        "current_pi": pi,
        "pll": pll_gains(n["pll"]["bandwidth_hz"], n["pll"]["damping"], b["w_b"],
                         b["theta_b"]),
        "constants": magic_constants(),
        "mechanical": mechanical(m, b, psi, c["base"]),
        "firmware": firmware,
    }
    if "datasheet" in n:
        out["datasheet"] = n["datasheet"]
    for a in plan.model:
        if a.key in core:
            out[a.key] = core[a.key] if a.run is None else a.run(out, core[a.key])
    if prof is not None:
        out["profiles"] = prof
    for a in plan.later:
        # an earlier entry's echo (the checked ``analysis``) is what a later one reads
        head = a.asked.split(".", 1)[0]
        given = at(out["input"] if head in out["input"] else n, a.asked)
        if given is None:
            continue
        value = checked.get(a.key, given)
        if a.stage == "steps":
            out[a.key] = yield from a.run(out, value)
        else:
            out[a.key] = a.run(out, value)
        if a.echo is not None:
            put(out["input"], a.asked, a.echo(given, out[a.key]))
    out["review"] = review(n, raw, vendor, pi, firmware=firmware,
                           **{key: out.get(key) for key in plan.reviewed})
    # The pre-review contract: warnings (and errors) of the review as plain strings.
    serious = [x for x in out["review"]["findings"] if x["severity"] != "note"]
    out["warnings"] = [x["message"] for x in serious]
    out["warnings_zh"] = [x["message_zh"] for x in serious]
    extra = _profile_warnings(prof) if prof is not None else []
    for a in plan.warned:
        if a.key in out:
            extra += a.warnings(out[a.key])
    out["warnings"] += [render(code, params, "en") for code, params in extra]
    out["warnings_zh"] += [render(code, params, "zh") for code, params in extra]
    return out


def _acim_refuse(n: dict) -> None:
    """An induction motor's input: the first section that does not apply, named."""
    given = {"raw": n["raw"] or None,
             "profiles": n.get("profiles"),
             "datasheet.speed_rpm": n.get("datasheet", {}).get("given", {}).get("speed_rpm")}
    analysis = n["analysis"] if isinstance(n["analysis"], dict) else {}
    given.update({f"analysis.{k}": analysis.get(k) for k in ("fw", "robust")})
    speed = analysis.get("speed")
    if isinstance(speed, dict) and speed.get("response"):   # its simulation runs a PMSM
        raise InputError("analysis.speed.response", code="acim_not_applicable")
    for path, v in given.items():
        if path == "datasheet.speed_rpm" and v is not None:
            raise InputError(path, code="only_with", key="kind", value="pmsm")
        if v is not None:
            raise InputError(path, code="acim_not_applicable")


def _acim_report(n: dict):
    """The report of an induction motor (docs/contract.md, "Induction motor"), in slices
    like :func:`report_steps`."""
    _acim_refuse(n)
    sim_in = None
    if "sim" in n:
        from .analyses import sim as _sim
        sim_in = _sim.validate(n["sim"], acim=True)
    m, d, c = n["motor"], n["drive"], n["conventions"]
    b = input_bases(n)
    lms = n.get("datasheet", {}).get("given", {}).get("lms_h")
    a = acim_model(m, None if lms is None else value(FIELD["datasheet.lms_h"], lms), b,
                   c["base"], d["ts_s"])
    a["inovance"] = _acim.INOVANCE
    out = {"input": {k: v for k, v in n.items() if k not in ("sim", "analysis", "datasheet")},
           "base": b, "acim": a,
           "current_pi": current_pi_section(n, b, (a["r_sigma_ohm"], a["sigma_ls_h"],
                                                   a["sigma_ls_h"])),
           "pll": pll_gains(n["pll"]["bandwidth_hz"], n["pll"]["damping"], b["w_b"],
                            b["theta_b"]),
           "profiles": _acim.profiles(a, n)}
    if "datasheet" in n:
        out["datasheet"] = n["datasheet"]
    if "board" in n:
        out["board"] = board(n["board"], b["I_b"], _acim.torque_flux_peak(a), m["pole_pairs"],
                             d["udc_v"])
    extra = []
    if n["analysis"] is not None:
        from .analyses import loop as _loop
        out["loop"] = _loop.analyze(_acim.loop_view(out, a), n["analysis"])
        out["input"]["analysis"] = _loop.validate(n["analysis"])
        extra = _loop.warnings(out["loop"])
        # the flux build-up in TI's fixed point (asked with the analysis: thousands of periods)
        out["acim_flux"] = _acim.flux_buildup(a, n, out["profiles"]["ti"]["constants"]["Kr"]["value"])
    if sim_in is not None:
        from .analyses.sim import induction as _induction
        out["sim"] = yield from _induction.simulate_steps(out, sim_in)
    out["review"] = _acim.review(n, a, flux=out.get("acim_flux"), sim=out.get("sim"),
                                 startup_s=None if sim_in is None else sim_in["flux"]["startup_s"],
                                 board=out.get("board"))
    serious = [x for x in out["review"]["findings"] if x["severity"] != "note"]
    out["warnings"] = [x["message"] for x in serious] + [render(k, p, "en") for k, p in extra]
    out["warnings_zh"] = [x["message_zh"] for x in serious] + [render(k, p, "zh")
                                                               for k, p in extra]
    return out


def _acim_text(r: dict) -> list:
    """The induction motor's tables of :func:`format_text`."""
    a = r["acim"]
    skip = ("pu", "observer", "inovance", "magnetizing_from")
    lines = _table(f"Induction motor (I_m {a['magnetizing_from'].replace('_', ' ')})", [
        (k, "—" if v is None else f"{v:.6g}   pu {a['pu'][k]:.6g}" if a["pu"].get(k) is not None
         else f"{v:.6g}") for k, v in a.items() if k not in skip])
    lines += _table("Current-model observer (ψ_k = a·ψ_k−1 + b·i_d)",
                    [(k, f"{v:.9g}") for k, v in a["observer"].items()])
    for name, p in r["profiles"].items():
        if not p["available"]:
            lines += [f"Profile {name}: {p['reason']}", ""]
            continue
        lines += _table(f"Profile {name} (induction motor)", [
            (k, f"{c['value']!r:>22}  {c['format']}  err {c['error_pct']:+.2e} %  = {c['expression']}")
            for k, c in p["constants"].items()])
    return lines


def _format_acim_text(r: dict) -> str:
    units = {"U_b": "V", "I_b": "A", "f_b": "Hz", "w_b": "rad/s", "Z_b": "Ω", "L_b": "H",
             "psi_b": "Wb", "T_b": "s", "P_b": "W", "theta_b": "rad"}
    lines = _table("Bases", [(k, f"{v:.6g} {units[k]}") for k, v in r["base"].items()])
    lines += _acim_text(r)
    rows = [(f"{axis}-axis", f"kp {g['kp']:.6g} Ω  ki {g['ki']:.6g} Ω/s  pm_kp {g['pm_kp']} (Q12)  "
                             f"pm_ki {g['pm_ki']} (Q16)")
            for axis, g in ((x, r["current_pi"][x]) for x in ("d", "q"))]
    lines += _table(f"Current PI on σ·L_s, R_σ ({r['current_pi']['method']})", rows)
    if "loop" in r:
        lines += _table(f"Loop margins (delay {r['loop']['delay']})", _loop_rows(r["loop"]))
    for name in ("current", "flux"):
        s = r.get("sim", {}).get(name)
        if s is None:
            continue
        runs = dict(s["metrics"])
        if s["by_profile"]["ti"]["ran"]:
            runs["ti"] = s["by_profile"]["ti"]["metrics"]
        keys = ("flux_95_s", "rise_time_s", "overshoot_pct", "vs_si_max_abs_a", "wraps")
        title = f"current step, axis {s['axis']}" if name == "current" else "flux build-up"
        lines += _table(f"Simulation: {title}", [
            (v, "  ".join(f"{k} {m[k]:.6g}" for k in keys if m.get(k) is not None))
            for v, m in runs.items()])
    c = r["review"]["counts"]
    title = f"Design review: {c['error']} error(s), {c['warning']} warning(s), {c['note']} note(s)"
    lines += [title, "-" * len(title)] + [f"  {x['severity'].upper():7s} [{x['key']}] {x['message']}"
                                          for x in r["review"]["findings"]]
    return "\n".join(lines).rstrip() + "\n"


def _table(title: str, rows: list) -> list:
    width = max(len(r[0]) for r in rows)
    return [title, "-" * len(title)] + [f"  {k.ljust(width)}  {v}" for k, v in rows] + [""]


def _loop_rows(loop: dict) -> list:
    """PM/GM/crossover/bandwidth lines of the loop section, 'none' where absent."""
    def fmt(x, unit):
        return "none" if x is None else f"{x:.4g} {unit}"
    cases = [(f"current {a}", loop["current"][a]) for a in ("d", "q")]
    cases += [(f"current {a} integers", loop["current"][a]["firmware"]) for a in ("d", "q")]
    cases += [(f"current {a} designed", loop["current"]["design"][a]) for a in ("d", "q")]
    cases += [("PLL scaled", loop["pll"]["correct"]), ("PLL naive", loop["pll"]["naive"])]
    if loop["speed"] is not None:
        cases.append(("speed", loop["speed"]))
    return [(name, f"PM {fmt(m['phase_margin_deg'], '°')}  GM {fmt(m['gain_margin_db'], 'dB')}  "
                   f"f_c {fmt(m['crossover_hz'], 'Hz')}  f_-3dB {fmt(m['bandwidth_hz'], 'Hz')}  "
                   f"{'stable' if m['stable'] else 'UNSTABLE'}") for name, m in cases]


def format_text(r: dict) -> str:
    """Readable tables of a report, for the terminal (``--format text``)."""
    if "acim" in r:
        return _format_acim_text(r)
    b, pu = r["base"], r["pu"]
    units = {"U_b": "V", "I_b": "A", "f_b": "Hz", "w_b": "rad/s", "Z_b": "Ω", "L_b": "H",
             "psi_b": "Wb", "T_b": "s", "P_b": "W", "theta_b": "rad"}
    lines = _table("Bases", [(k, f"{v:.6g} {units[k]}") for k, v in b.items()])
    lines += _table("Per unit", [(k, f"{v:.6g}") for k, v in pu.items()])
    lines += _table("Raw firmware inputs", [(k, str(v)) for k, v in r["vendor"]["raw"].items()])
    rows = []
    for name, res in r["vendor"].items():
        if name == "raw":
            continue
        rows.append((name, f"{res['value']:>11d}  Q{res['q']:<2d}  ideal {res['ideal']:.6g}  "
                           f"err {res['error_pct']:+.4f} %  = {res['si']:.6g} {res['unit']}  "
                           f"{' '.join(res['flags'])}"))
    lines += _table("Vendor integers", rows)
    rows = []
    for axis in ("d", "q"):
        g = r["current_pi"][axis]
        rows.append((f"{axis}-axis", f"kp {g['kp']:.6g} Ω  ki {g['ki']:.6g} Ω/s  kp_pu "
                     f"{g['kp_pu']:.6g}  ki_pu {g['ki_pu']:.6g}  pm_kp {g['pm_kp']}  "
                     f"pm_ki {g['pm_ki']}  (back: {g['from_integers']['bandwidth_hz']:.4g} Hz)"))
    lines += _table(f"Current PI ({r['current_pi']['method']})", rows)
    p = r["pll"]
    lines += _table("PLL", [(k, f"{p[k]:.6g}") for k in
                            ("kp", "ki", "kp_pu", "ki_pu", "integrator_gain")])
    lines += _table("Magic constants", [(k, f"exact {c['exact']:.6f} = {c['expression']}, "
                                            f"rel. error {100 * c['rel_error']:+.4f} %")
                                        for k, c in r["constants"].items()])
    mech = r["mechanical"]
    lines += _table("Mechanical", [
        ("pole pairs", str(mech["pole_pairs"])),
        ("rated speed", f"{mech['rated_speed_rpm']:.6g} rpm"),
        ("base speed (f_b)", f"{mech['base_speed_rpm']:.6g} rpm"),
        ("torque base T_mb", f"{mech['torque_base_nm']:.6g} N·m"),
        ("kT", f"{mech['kt_nm_per_a']:.6g} N·m/A (RMS)"),
        ("Ke", f"{mech['ke_v_s_per_rad']:.6g} V·s/rad (line RMS)"),
        ("rated torque", f"{mech['rated_torque_nm']:.6g} N·m")])
    if "datasheet" in r:
        lines += _table("Datasheet conversions", [
            (c["field"], f"{c['formula']} = {c['value']:.6g} {c['unit']}")
            for c in r["datasheet"]["conversions"]])
    check = r.get("datasheet", {}).get("bemf_check")
    if check is not None:
        lines += _table(f"Back-EMF cross-check at {check['rated_speed_rpm']:.6g} rpm "
                        f"(spread {check['spread_pct']:.3g} %)", [
            (s["field"] + (" (used)" if s["field"] == check["used"] else ""),
             f"{s['formula']} = {s['bemf_v']:.6g} V  ({s['deviation_pct']:+.3g} %)")
            for s in check["sources"]])
    for name, st in r["firmware"].items():
        if not st["representable"]:
            lines += _table(f"Firmware {name}: cannot hold this motor",
                            [(p["field"], f"{p['message']} → {p['advice']}")
                             for p in st["problems"]])
    h = r["review"]["headroom"]
    lines += _table("Voltage headroom (line RMS)", [
        ("limit (pm_maxout_vol)", f"{h['limit_v']:.6g} V"),
        ("back-EMF at f_b", f"{h['bemf_fb_v']:.6g} V"),
        ("needed, rated I at f_n", f"{h['need_rated_fn_v']:.6g} V"),
        ("needed, rated I at f_b", f"{h['need_rated_fb_v']:.6g} V")])
    findings = r["review"]["findings"]
    if findings:
        c = r["review"]["counts"]
        title = f"Design review: {c['error']} error(s), {c['warning']} warning(s), " \
                f"{c['note']} note(s)"
        lines += [title, "-" * len(title)] + [f"  {x['severity'].upper():7s} [{x['key']}] "
                                               f"{x['message']}" for x in findings]
    for name, prof in r.get("profiles", {}).items():
        lines += _table(f"Profile {name}", [
            (k, f"{c['value']:>11{'.10g' if c.get('real') else 'd'}}  {c['format']:<16} "
                f"err {c['error_pct']:+.4f} %  = {c['si']:.6g} {c['unit']}  {' '.join(c['flags'])}")
            for k, c in prof["constants"].items()])
    if "observer" in r:
        o, low = r["observer"], r["observer"]["budget"]["min_speed_rpm"]
        def pm(x):
            return "none" if x is None else f"{x:.4g}°"
        lines += _table("Sensorless observer", [
            (f"{name} observer", f"kp {o['design'][name][kp]:.6g}, ki {o['design'][name][ki]:.6g}, "
                                 f"PM {pm(o['design'][name]['phase_margin_deg'])}, |pole| max "
                                 f"{o['design'][name]['spectral_radius']:.6g}")
            for name, kp, ki in (("bemf", "kp_v_per_a", "ki_v_per_as"),
                                 ("tracking", "kp_per_s", "ki_per_s2"))] + [
            ("lowest sensorless speed", "none" if low is None else f"{low:.6g} rpm"),
            ("merging / lowest asked", f"{o['settings']['merging_speed_rpm']:.6g} / "
                                       f"{o['settings']['min_speed_rpm']:.6g} rpm")])
    if "loop" in r:
        lines += _table(f"Loop margins (delay {r['loop']['delay']})", _loop_rows(r["loop"]))
    reviewed = {x["message"] for x in r["review"]["findings"]}
    other = [w for w in r["warnings"] if w not in reviewed]
    if other:
        lines += ["Warnings", "--------"] + [f"  ! {w}" for w in other]
    return "\n".join(lines).rstrip() + "\n"
