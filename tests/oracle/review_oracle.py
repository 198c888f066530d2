"""Independent oracle for datasheet entry and the design review; never imports pulab.

Datasheet conversions are written here from the physics, not from pulab's code: a
datasheet's line-to-line Ke is turned into the phase flux amplitude first and the
line RMS back-EMF is computed from the flux (pulab goes the other way), so a slip in
either shows.  The firmware numbers come from tests/oracle/oracle.py (also
pulab-free).  The review's expected findings are the thresholds of docs/contract.md
("Design review") applied to those numbers; the voltage headroom uses complex phasors.

Three real motors, numbers as printed in public datasheets:

- maxon EC 45 flat 70 W, 24 V, part 411812 (maxongroup.com product page, as copied in a
  public design note): 8 pole pairs, torque constant 36.9 mN·m/A (= Ke 0.0369 V·s/rad,
  block commutation: line-to-line peak), terminal resistance phase to phase 0.608 Ω,
  terminal inductance phase to phase 0.463 mH, nominal current 3.21 A, no-load speed
  6110 rpm at 24 V (taken as the rated speed: the speed the 24 V bus allows; 815 Hz
  electrical does not fit the Inovance firmware's FullFreq01 in 0.01 Hz, so its review
  has the ``unrepresentable`` finding and no FreqPer/FluxRotor/LD/LQ checks);
- HEIDENHAIN SRP 5000 torque motor (Betriebsanleitung 5/2017, 11.2 "Motor
  characteristics"): DC 48 V, 20 poles (10 pole pairs), back-EMF constant
  0.397 V_rms/(rad/s), torque constant 0.668 N·m/A_rms, R20 9.06 Ω, L1 2.42 mH (taken as
  terminal to terminal), rated current 0.688 A_rms, maximum speed 300 rpm;
- a 310 V DC-bus brushless servo (the motor table quoted under "torque constant" in the
  Free Dictionary encyclopedia): 4600 rpm, 4 poles, Ke 51 V/krpm, Kt 0.49 N·m/A (so Ke is
  line-to-line peak: Kt ≈ Ke·60/(2π·1000)), ph/ph resistance 3.07 Ω, ph/ph inductance
  6.57 mH, stall current 4.52 A.

Run ``python tests/oracle/review_oracle.py`` to write tests/golden/review/*.json,
``--check`` to verify they are fresh.
"""

from __future__ import annotations

import json
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import oracle_report  # noqa: E402  (pulab-free)
from loop_oracle import current_loop, measure  # noqa: E402  (python-control, pulab-free)

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "review"
REL, ABS = 1e-12, 1e-15  # closed-form float64 arithmetic (see golden_files.py)
TWO_PI = 2.0 * math.pi

# docs/contract.md "Design review"
Q_NOTE, Q_WARN, Q_ERR = 0.1, 1.0, 5.0
C_NOTE, C_WARN, C_ERR = 0.1, 10.0, 50.0   # a firmware constant against its exact value, %
PM_WARN, PM_ERR = 45.0, 20.0               # current-loop phase margin with the PWM delay, degrees


def motor_from_datasheet(ds: dict, motor: dict) -> dict:
    """SI motor fields from datasheet values (physics written out, not pulab's algebra)."""
    m = dict(motor)
    p = m["pole_pairs"]
    if "speed_rpm" in ds:
        m["rated_freq_hz"] = ds["speed_rpm"] / 60.0 * p  # electrical Hz = mech rev/s · p
    w_mech = TWO_PI * m["rated_freq_hz"] / p  # rad/s
    w_el = TWO_PI * m["rated_freq_hz"]
    # line-to-line voltage amplitude per mechanical rad/s …
    if "ke_v_per_krpm" in ds:
        k = ds["ke_v_per_krpm"] / (1000.0 * TWO_PI / 60.0)
    elif "ke_v_s_per_rad" in ds:
        k = ds["ke_v_s_per_rad"]
    else:
        k = None
    if k is not None:
        ll_peak = k if ds["ke_measure"] == "peak" else k * math.sqrt(2.0)
        # … phase amplitude = line amplitude/√3; flux amplitude ψ = phase amplitude/ω_el·ω_mech
        psi_pk = ll_peak / math.sqrt(3.0) / p
        m["bemf_v"] = psi_pk * w_el * math.sqrt(3.0) / math.sqrt(2.0)
        assert abs(psi_pk * p * w_mech - ll_peak * w_mech / math.sqrt(3.0)) < 1e-9
    if "rs_line_ohm" in ds:
        m["rs_ohm"] = ds["rs_line_ohm"] * 0.5  # two star phases in series
    if "l_line_h" in ds:
        m["ld_h"] = m["lq_h"] = ds["l_line_h"] * 0.5
    if "dc_bus_v" in ds:
        # linear SVPWM: phase amplitude U_dc/√3, line amplitude U_dc, line RMS U_dc/√2
        m["rated_voltage_v"] = ds["dc_bus_v"] / math.sqrt(2.0)
    return m


def headroom(m: dict, d: dict, limit_v: float) -> dict:
    """Line RMS voltage needed at rated current (i_d = 0), as complex phasors."""
    psi_rms = m["bemf_v"] / math.sqrt(3.0) / (TWO_PI * m["rated_freq_hz"])

    def need(f):
        # d axis real, q axis imaginary: i on q, back-EMF jωψ on q, jωL·i on −d
        w = TWO_PI * f
        i = 1j * m["rated_current_a"]
        u = m["rs_ohm"] * i + 1j * w * m["lq_h"] * i + 1j * w * psi_rms
        return math.sqrt(3.0) * abs(u)

    f_b = d.get("base_freq_hz", m["rated_freq_hz"])
    e_fb = math.sqrt(3.0) * TWO_PI * f_b * psi_rms
    f_fw = limit_v / (math.sqrt(3.0) * TWO_PI * psi_rms)
    return {"limit_v": limit_v, "bemf_fb_v": e_fb, "need_rated_fn_v": need(m["rated_freq_hz"]),
            "need_rated_fb_v": need(f_b), "field_weakening_from_hz": f_fw if f_fw < f_b else None}


def _q(pct: float):
    a = abs(pct)
    return "error" if a >= Q_ERR else "warning" if a >= Q_WARN else "note" if a >= Q_NOTE else None


def findings(inp: dict) -> tuple[list, dict]:
    """Expected (severity, code, key) of every finding, and the headroom numbers."""
    r = oracle_report(inp)
    m, d = inp["motor"], inp["drive"]
    out = []
    for name, res in r["vendor"].items():
        if name == "raw":
            continue
        if {"wrap", "store"} & set(res["flags"]):
            out.append(("error", "constant_wrap", f"vendor.{name}.value"))
        else:
            a = abs(res["error_pct"])
            sev = "error" if a >= C_ERR else "warning" if a >= C_WARN else \
                "note" if a >= C_NOTE else None
            if sev:
                out.append((sev, "constant_error", f"vendor.{name}.value"))
    scale = {"Voltage": ("rated_voltage_v", 1), "Current": ("rated_current_a", 100),
             "FullFreq01": ("base_freq_hz", 100), "FreqRated01": ("rated_freq_hz", 100),
             "RsPm": ("rs_ohm", 1000), "LD": ("ld_h", 1e5), "LQ": ("lq_h", 1e5),
             "BemfVolt": ("bemf_v", 10), "uDCFilter": ("udc_v", 10)}
    raw = {}
    for name, (key, k) in scale.items():
        si = m.get(key, d.get(key, m["rated_freq_hz"] if key == "base_freq_hz" else None))
        x = si * k
        raw[name] = int(math.floor(x + 0.5))
        if raw[name] > 65535:
            continue  # the firmware cannot be given it: firmware.inovance, not a rounding
        if raw[name] == 0:
            out.append(("error", "raw_zero", f"vendor.raw.{name}"))
        elif _q(100 * (raw[name] - x) / x):
            out.append((_q(100 * (raw[name] - x) / x), "raw_rounding", f"vendor.raw.{name}"))
    for axis in ("d", "q"):
        g = r["current_pi"][axis]
        if g["pm_ki"] == 0:
            out.append(("error", "pi_zero", f"current_pi.{axis}.pm_ki"))
        for k in ("kp", "ki"):
            if g[f"pm_{k}"] and _q(100 * (g["from_integers"][k] - g[k]) / g[k]):
                out.append((_q(100 * (g["from_integers"][k] - g[k]) / g[k]), "pi_rounding",
                            f"current_pi.{axis}.pm_{k}"))
    # The firmware gains' discrete loop with the computation and PWM delay (python-control).
    worst = None
    for axis, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        g = r["current_pi"][axis]["from_integers"]
        mg = measure(current_loop(m["rs_ohm"], l_h, d["ts_s"], g["kp"], g["ki"],
                                  "computation_pwm"), d["ts_s"])
        pm = mg["phase_margin_deg"] if mg["stable"] else -math.inf
        if worst is None or pm < worst[1]:
            worst = (axis, pm)
    if worst[1] < PM_WARN:
        out.append(("error" if worst[1] < PM_ERR else "warning", "phase_margin",
                    f"current_pi.{worst[0]}.pm_kp"))
    if raw["FullFreq01"] <= 65535 and raw["FullFreq01"] < raw["FreqRated01"] <= 65535:
        out.append(("warning", "base_below_rated", "vendor.FreqPer.value"))
    if not r["firmware"]["inovance"]["representable"]:
        out.append(("warning", "unrepresentable", "firmware.inovance"))
    # the firmware's voltage limit, pm_maxout_vol (Q12 of the rated line voltage); the
    # physical U_dc/√2 when the firmware cannot compute it
    limit = (r["vendor"]["pm_maxout_vol"]["value"] / 4096.0 * raw["Voltage"]
             if "pm_maxout_vol" in r["vendor"] else d["udc_v"] / math.sqrt(2.0))
    h = headroom(m, d, limit)
    if h["need_rated_fn_v"] > limit:
        # beyond U_dc/√2 a warning; beyond only the firmware's truncated limit a note
        sev = "warning" if h["need_rated_fn_v"] > d["udc_v"] / math.sqrt(2.0) else "note"
        out.append((sev, "voltage_rated", "review.headroom.need_rated_fn_v"))
    if h["field_weakening_from_hz"] is not None:
        sev = "warning" if h["field_weakening_from_hz"] < m["rated_freq_hz"] else "note"
        out.append((sev, "voltage_bemf", "review.headroom.bemf_fb_v"))
    elif h["need_rated_fb_v"] > limit:
        out.append(("note", "voltage_fb", "review.headroom.need_rated_fb_v"))
    order = {"error": 0, "warning": 1, "note": 2}
    return sorted(out, key=lambda x: (order[x[0]], x[1], x[2])), h


def mechanical(m: dict) -> dict:
    p = m["pole_pairs"]
    w_mech = TWO_PI * m["rated_freq_hz"] / p
    ke = m["bemf_v"] / w_mech  # line RMS per mechanical rad/s
    # T = P/ω_mech with P = 3·E_ph·I (i_d = 0): kT = 3·(E_LL/√3)/ω_mech = √3·Ke
    return {"rated_speed_rpm": m["rated_freq_hz"] * 60.0 / p, "ke_v_s_per_rad": ke,
            "kt_nm_per_a": 3.0 * (m["bemf_v"] / math.sqrt(3.0)) / w_mech}


MOTORS = [
    ("maxon_ec45flat_411812",
     {"datasheet": {"speed_rpm": 6110, "ke_v_s_per_rad": 0.0369, "ke_measure": "peak",
                    "rs_line_ohm": 0.608, "l_line_h": 0.000463, "dc_bus_v": 24},
      "motor": {"rated_current_a": 3.21, "pole_pairs": 8},
      "drive": {"ts_s": 0.00005}, "current_loop": {"bandwidth_hz": 600}}),
    ("heidenhain_srp5000",
     {"datasheet": {"speed_rpm": 300, "ke_v_s_per_rad": 0.397, "ke_measure": "rms",
                    "rs_line_ohm": 9.06, "l_line_h": 0.00242, "dc_bus_v": 48},
      "motor": {"rated_current_a": 0.688, "pole_pairs": 10},
      "drive": {"ts_s": 0.0000625}, "current_loop": {"bandwidth_hz": 500}}),
    ("servo_310vdc_51v_krpm",
     {"datasheet": {"speed_rpm": 4600, "ke_v_per_krpm": 51, "ke_measure": "peak",
                    "rs_line_ohm": 3.07, "l_line_h": 0.00657, "dc_bus_v": 310},
      "motor": {"rated_current_a": 4.52, "pole_pairs": 2},
      "drive": {"ts_s": 0.0001}, "current_loop": {"bandwidth_hz": 300}}),
    ("issue9_contract_example",
     {"datasheet": {"speed_rpm": 3000, "ke_v_per_krpm": 44.38, "ke_measure": "peak",
                    "rs_line_ohm": 2.78, "l_line_h": 0.00506},
      "motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "pole_pairs": 4},
      "drive": {"udc_v": 311, "ts_s": 0.0000625}, "current_loop": {"bandwidth_hz": 500}}),
]


def case(inp: dict) -> dict:
    m = motor_from_datasheet(inp["datasheet"], inp["motor"])
    d = dict(inp["drive"])
    d.setdefault("udc_v", inp["datasheet"].get("dc_bus_v"))
    plain = {"motor": m, "drive": d, "current_loop": inp["current_loop"]}
    out = {"input.motor": m, "mechanical": mechanical(m)}
    f, h = findings(plain)
    return {**out, "review.headroom": h, "review.findings": [list(x) for x in f]}


def build() -> dict:
    return {f"{name}.json": {"input": inp, "expected": case(inp)} for name, inp in MOTORS}


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
