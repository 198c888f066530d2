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

import math

from .bases import bases, flux_linkage, per_unit
from .constants import magic_constants
from .gains import current_pi, current_pi_si, gains_from_integers, pll_gains
from .inputs import normalize
from .messages import to_zh
from .vendor import RAW_FIELDS, current_pi_step, raw_from_si, raw_source, vendor_results

__all__ = ["report", "format_text", "input_bases", "input_raw", "current_pi_section"]


def _warnings(inp: dict, raw: dict, vendor: dict, pi: dict, b: dict) -> list:
    w = []
    unit = inp["conventions"]["inductance_unit"]
    if unit == "uH":
        w.append("LD/LQ taken in µH: the vendor code was written for 0.01 mH, so "
                 "gMotorExtPer.LD/LQ are 10× the Q13 per-unit inductance (seed 1.4-6, the '×10' "
                 "puzzle)")
    if inp["conventions"]["base"] == "custom":
        w.append("custom bases: the vendor integers (Rpm, LD, …) always use the Inovance rms "
                 "bases U_LL/√3 and I_rms; the PI integers use the custom bases")
    for name, res in vendor.items():
        for flag, text in (("wrap", "an intermediate result wrapped around"),
                           ("store", "the store into Uint16 changed the value")):
            if flag in res["flags"]:
                w.append(f"{name}: {text}; the firmware value {res['value']} is wrong "
                         f"(ideal {res['ideal']:.6g})")
    for name in RAW_FIELDS:
        if name in inp["raw"]:
            continue
        path, scale = raw_source(name, unit)
        si = inp[path.split(".")[0]][path.split(".")[1]]
        exact = si * scale
        if raw[name] == 0:
            w.append(f"raw.{name} = 0: {path} = {si:g} is below the firmware resolution")
        elif abs(raw[name] - exact) / exact > 0.005:
            w.append(f"raw.{name} = {raw[name]}: rounding {path} = {si:g} to the firmware unit "
                     f"changes it by {100 * (raw[name] - exact) / exact:+.2f} %")
    for axis in ("d", "q"):
        g = pi[axis]
        if g["pm_ki"] == 0:
            w.append(f"current_pi.{axis}.pm_ki rounds to 0: the integral action is lost "
                     f"(ki·Ts is below one Q16 LSB of the per-unit gain)")
        elif abs(g["pm_ki"]) < 16:
            w.append(f"current_pi.{axis}.pm_ki = {g['pm_ki']}: coarse, rounding changes ki by "
                     f"{100 * (g['from_integers']['ki'] - g['ki']) / g['ki']:+.1f} %")
        if 0 < abs(g["pm_kp"]) < 16:
            w.append(f"current_pi.{axis}.pm_kp = {g['pm_kp']}: coarse, rounding changes kp by "
                     f"{100 * (g['from_integers']['kp'] - g['kp']) / g['kp']:+.1f} %")
    wc_ts = 2 * math.pi * inp["current_loop"]["bandwidth_hz"] * inp["drive"]["ts_s"]
    if inp["current_loop"]["method"] in ("bandwidth", "damping") and wc_ts > 0.3:
        w.append(f"current-loop ω_c·Ts = {wc_ts:.2f}: the continuous-time design is far from "
                 f"the discrete loop's behaviour (keep ω_c·Ts ≲ 0.2)")
    if b["f_b"] < inp["motor"]["rated_freq_hz"]:
        w.append("base frequency below rated frequency: FreqPer > 1.0 in Q15")
    return w


def _profile_warnings(prof: dict) -> list:
    """One warning per profile constant the firmware could not store as intended."""
    w = [f"profiles.ti: USER_checkForErrors would set {code} ({why})"
         for code, why in prof["ti"]["checks"]]
    for name, p in prof.items():
        for k, c in p["constants"].items():
            if "out_of_range" in c["flags"] or "saturate" in c["flags"]:
                w.append(f"profiles.{name}.{k}: {c['ideal']:.6g} does not fit {c['format']}; "
                         f"stored {c['value']}")
            elif c["value"] == 0 and c["ideal"] != 0:
                w.append(f"profiles.{name}.{k}: rounds to 0 in {c['format']} "
                         f"(ideal {c['ideal']:.6g})")
    return w


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


def input_raw(n: dict) -> dict:
    """The raw firmware integers (contract ``vendor.raw``) of a normalized input."""
    si = {f"{s}.{k}": v for s in ("motor", "drive") for k, v in n[s].items()}
    return raw_from_si(si, n["conventions"]["inductance_unit"], n["raw"])


def current_pi_section(n: dict, b: dict) -> dict:
    """The current PI gains of both axes (contract ``current_pi`` without ``step_example``)."""
    m, d, cl = n["motor"], n["drive"], n["current_loop"]
    pi = {"method": cl["method"],
          "bandwidth_hz": cl["bandwidth_hz"] if cl["method"] in ("bandwidth", "damping") else None}
    for axis, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        if cl["method"] == "integers":
            kp, ki = gains_from_integers(cl["pm_kp"], cl["pm_ki"], b["U_b"], b["I_b"], d["ts_s"])
        else:
            kp, ki = current_pi_si(cl["method"], m["rs_ohm"], l_h, cl["bandwidth_hz"],
                                   cl["damping"], cl["kp"], cl["ki"])
        pi[axis] = current_pi(kp, ki, l_h, b["U_b"], b["I_b"], d["ts_s"])
    return pi


def report(inp: dict) -> dict:
    """Compute the report for one motor and drive.

    Parameters
    ----------
    inp : dict
        Input per docs/contract.md.

    Returns
    -------
    dict
        ``input`` (normalized), ``base``, ``pu``, ``vendor``, ``current_pi``, ``pll``,
        ``constants``, ``warnings`` and, when asked, ``sim``.

    Raises
    ------
    pulab.InputError
        Naming the field, for any bad input or firmware division by zero.
    """
    n = normalize(inp)
    m, d, c = n["motor"], n["drive"], n["conventions"]
    sim_in = None
    if "sim" in n:
        from . import sim as _sim  # imported only when asked: plain reports stay fast
        sim_in = _sim.validate(n["sim"])
    b = input_bases(n)
    psi = flux_linkage(c["base"], m["bemf_v"], m["rated_freq_hz"])
    pu = per_unit(b, m["rs_ohm"], m["ld_h"], m["lq_h"], psi, d["ts_s"])
    raw = input_raw(n)
    vendor = vendor_results(raw, c["inductance_unit"])
    pi = current_pi_section(n, b)
    pi["step_example"] = _pi_example(pi["d"], vendor)
    prof = None
    if "profiles" in n:  # only when asked: the five profiles cost more than the rest
        from . import profiles as _profiles
        ctx = _profiles.context(n, raw, vendor, pi)
        n["profiles"] = _profiles.options(n["profiles"], ctx)
        prof = _profiles.profiles(ctx, n["profiles"])
    out = {
        "input": {k: v for k, v in n.items() if k != "sim"},
        "base": b,
        "pu": pu,
        "vendor": {"raw": raw, **vendor},
        "current_pi": pi,
        "pll": pll_gains(n["pll"]["bandwidth_hz"], n["pll"]["damping"], b["w_b"],
                         b["theta_b"]),
        "constants": magic_constants(),
        "warnings": _warnings(n, raw, vendor, pi, b),
    }
    if prof is not None:
        out["profiles"] = prof
        out["warnings"] += _profile_warnings(prof)
    out["warnings_zh"] = [to_zh(w) for w in out["warnings"]]
    if sim_in is not None:
        out["sim"] = _sim.simulate(out, sim_in)
    return out


def _table(title: str, rows: list) -> list:
    width = max(len(r[0]) for r in rows)
    return [title, "-" * len(title)] + [f"  {k.ljust(width)}  {v}" for k, v in rows] + [""]


def format_text(r: dict) -> str:
    """Readable tables of a report, for the terminal (``--format text``)."""
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
    for name, prof in r.get("profiles", {}).items():
        lines += _table(f"Profile {name}", [
            (k, f"{c['value']:>11d}  {c['format']:<16} err {c['error_pct']:+.4f} %  = "
                f"{c['si']:.6g} {c['unit']}  {' '.join(c['flags'])}")
            for k, c in prof["constants"].items()])
    if r["warnings"]:
        lines += ["Warnings", "--------"] + [f"  ! {w}" for w in r["warnings"]]
    return "\n".join(lines).rstrip() + "\n"
