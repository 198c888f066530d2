"""Independent oracle for six real motors entered as their datasheets print them; never imports pulab.

Each motor's printed values (tests/golden/datasheets/README.md names the documents) are
turned into the SI motor by the physics written out here, through the magnet flux
amplitude ψ (pulab goes from a back-EMF at rated speed, so a slip in either shows):

- a back-EMF constant Ke (line to line or per phase, RMS or peak) is a voltage per speed,
  so ψ = Ke_LL,peak/(√3·p) per mechanical rad/s;
- a speed constant Kv [rpm/V] is the inverse of a line-to-line peak (maxon: on the DC
  terminals) voltage per rpm;
- a torque constant kT: T = 3/2·p·ψ·Î = 3·p·(ψ/√2)·I_rms, so ψ = kT_peak/(1.5·p) or
  √2·kT_rms/(3·p);
- resistance and inductance between two terminals of a star are two phases in series;
  a per-phase value of a star is the phase itself.

The back-EMF each constant implies at rated speed, E_LL = √3·ω_e·ψ/√2, is the cross-check
(``datasheet.bemf_check``); the firmware integers, bases, per-unit values and gains of the
resulting SI motor come from oracle.py, and the other vendors' constants from
profiles_oracle.py (both pulab-free).

Run ``python tests/oracle/datasheet_oracle.py`` to write tests/golden/datasheets/*.json,
``--check`` to verify they are fresh.
"""

from __future__ import annotations

import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import oracle_report  # noqa: E402  (pulab-free)
from profiles_oracle import profiles  # noqa: E402  (pulab-free)

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "datasheets"
REL, ABS = 1e-12, 1e-15  # closed-form float64 arithmetic (see golden_files.py)
R2, R3, TWO_PI = math.sqrt(2.0), math.sqrt(3.0), 2.0 * math.pi

# name: (values as printed, with their units in the keys; the pulab input typing them in)
MOTORS = {
    "siemens_1ft7044_ak7": (
        {"rated speed n_N [rpm]": 6000, "number of poles 2p": 6, "rated current I_N [A]": 2.5,
         "torque constant k_T [Nm/A] (RMS, 100 K)": 0.88,
         "voltage constant k_E [V/1000 rpm] (RMS, phase to phase)": 57,
         "winding resistance R_ph [Ω] (star, 20 °C)": 0.61,
         "rotating field inductance L_D [mH]": 4.2},
        {"datasheet": {"speed_rpm": 6000, "ke_v_per_krpm": 57, "ke_measure": "rms",
                       "kt_nm_per_a": 0.88, "rs_phase_ohm": 0.61, "l_phase_h": 0.0042,
                       "dc_bus_v": 600},
         "motor": {"rated_current_a": 2.5, "pole_pairs": 3},
         "drive": {"ts_s": 0.000125}, "current_loop": {"bandwidth_hz": 250}}),
    "rexroth_mhd041a_144": (
        {"rated speed n_N [1/min]": 4000, "torque constant K_m [Nm/A] (crest value)": 0.42,
         "voltage constant K_E(eff) [V/1000 min^-1]": 38.2,
         "winding resistance R12 [Ω]": 7.0, "winding inductivity L12 [mH]": 13.5,
         "number of pole pairs p": 3, "rated current I_N [A] (60 K)": 1.29,
         "rated voltage U_N [V]": 163, "rated frequency f_N [Hz]": 200},
        {"datasheet": {"speed_rpm": 4000, "ke_v_per_krpm": 38.2, "ke_measure": "rms",
                       "kt_nm_per_a": 0.42, "kt_current": "peak", "rs_line_ohm": 7.0,
                       "l_line_h": 0.0135},
         "motor": {"rated_voltage_v": 163, "rated_current_a": 1.29, "pole_pairs": 3},
         "drive": {"udc_v": 540, "ts_s": 0.0000625}, "current_loop": {"bandwidth_hz": 500}}),
    "rexroth_mhp112a_024": (
        {"base speed n_N [min^-1]": 2500, "nominal motor voltage U_N(eff) [V]": 313,
         "nominal motor current I_N(eff) [A]": 6.2, "torque constant K_mE [Nm/A]": 1.89,
         "voltage constant K_Eeff [V/1000 min^-1]": 116.4,
         "windings resistance R12 [Ω]": 1.45, "windings inductance L12 [mH]": 14.0,
         "number of pole pairs": 4, "nominal frequency f_N [Hz]": 167,
         "equivalent circuit: windings resistance R1 [Ω]": 0.73,
         "equivalent circuit: rotary field inductance L1-D [mH]": 7.0},
        {"datasheet": {"speed_rpm": 2500, "ke_v_per_krpm": 116.4, "ke_measure": "rms",
                       "kt_nm_per_a": 1.89, "rs_phase_ohm": 0.73, "l_phase_h": 0.007},
         "motor": {"rated_voltage_v": 313, "rated_current_a": 6.2, "pole_pairs": 4},
         "drive": {"udc_v": 540, "ts_s": 0.0000625}, "current_loop": {"bandwidth_hz": 500}}),
    "maxon_ec45flat_50w_24v": (
        {"nominal voltage [V]": 24, "nominal speed [rpm]": 5170, "nominal current [A]": 2.52,
         "terminal resistance phase to phase [Ω]": 0.942,
         "terminal inductance phase to phase [mH]": 0.363, "speed constant [rpm/V]": 265,
         "number of pole pairs": 8},
        {"datasheet": {"speed_rpm": 5170, "kv_rpm_per_v": 265, "rs_line_ohm": 0.942,
                       "l_line_h": 0.000363, "dc_bus_v": 24},
         "motor": {"rated_current_a": 2.52, "pole_pairs": 8},
         "drive": {"ts_s": 0.00005}, "current_loop": {"bandwidth_hz": 600}}),
    "maxon_ec45flat_70w_411812": (
        {"nominal voltage [V]": 24, "no load speed [rpm]": 6110, "nominal current [A]": 3.21,
         "torque constant [mNm/A]": 36.9, "terminal resistance phase to phase [Ω]": 0.608,
         "terminal inductance phase to phase [mH]": 0.463, "number of pole pairs": 8},
        {"datasheet": {"speed_rpm": 6110, "ke_v_s_per_rad": 0.0369, "ke_measure": "peak",
                       "rs_line_ohm": 0.608, "l_line_h": 0.000463, "dc_bus_v": 24},
         "motor": {"rated_current_a": 3.21, "pole_pairs": 8},
         "drive": {"ts_s": 0.00005}, "current_loop": {"bandwidth_hz": 600}}),
    "emrax_228_lv": (
        {"maximal battery voltage [Vdc] (max load RPM)": "160 (5500)",
         "continuous motor current [Arms]": 450, "maximal motor current [Arms]": 900,
         "number of pole pairs": 10, "internal phase resistance at 25 °C [mΩ]": "1,1",
         "wire connection": "star", "induction in Ld/Lq [µH] of 1 phase": "10,3/10,6",
         "AC voltage between two phases [Vrms/1RPM]": "0,0176",
         "torque / motor current [Nm/1Aph rms]": "0,27", "magnetic flux – axial [Vs]": "0,0131"},
        {"datasheet": {"speed_rpm": 5500, "ke_v_per_krpm": 17.6, "ke_measure": "rms",
                       "kt_nm_per_a": 0.27, "psi_wb": 0.0131, "rs_phase_ohm": 0.0011,
                       "ld_phase_h": 0.0000103, "lq_phase_h": 0.0000106, "dc_bus_v": 160},
         "motor": {"rated_current_a": 450, "pole_pairs": 10},
         "drive": {"ts_s": 0.0000625}, "current_loop": {"bandwidth_hz": 800}}),
}


def flux(ds: dict, src: str, p: int) -> float:
    """ψ (phase flux amplitude, Wb) from one datasheet constant."""
    x = ds[src]
    if src in ("ke_v_per_krpm", "ke_v_s_per_rad"):
        per_rad = x / (1000.0 * TWO_PI / 60.0) if src == "ke_v_per_krpm" else x
        ll_peak = per_rad * (1.0 if ds["ke_measure"] == "peak" else R2)
        if ds.get("ke_between") == "phase":
            ll_peak *= R3
        return ll_peak / R3 / p
    if src == "kv_rpm_per_v":
        volts_per_rpm = 1.0 / x * (1.0 if ds.get("kv_measure", "peak") == "peak" else R2)
        return volts_per_rpm * 60.0 / TWO_PI / R3 / p
    if src == "kt_nm_per_a":
        return x / (1.5 * p) if ds.get("kt_current") == "peak" else R2 * x / (3.0 * p)
    return x  # psi_wb


def motor_si(inp: dict) -> tuple[dict, dict, dict | None]:
    """The SI motor and drive, and the back-EMF cross-check, from the datasheet input."""
    ds, d = inp["datasheet"], dict(inp["drive"])
    # numbers as the report echoes them: floats, the pole pairs an integer
    m = {k: v if k == "pole_pairs" else float(v) for k, v in inp["motor"].items()}
    p = m["pole_pairs"]
    m["rated_freq_hz"] = ds["speed_rpm"] / 60.0 * p
    w_e = TWO_PI * m["rated_freq_hz"]
    srcs = [k for k in ("ke_v_per_krpm", "ke_v_s_per_rad", "kv_rpm_per_v", "kt_nm_per_a",
                        "psi_wb") if k in ds]
    bemf = {s: R3 * w_e * flux(ds, s, p) / R2 for s in srcs}
    used = ds.get("bemf_from", srcs[0])
    m["bemf_v"] = bemf[used]
    delta = ds.get("winding") == "delta"
    for key, fields in (("rs", ("rs_ohm",)), ("l", ("ld_h", "lq_h"))):
        unit = "ohm" if key == "rs" else "h"
        for f in fields:
            # an axis-specific value (Ld, Lq) wins over one L for both axes
            axis = f"{f[:2]}_" if key == "l" and any(k.startswith(f[:2] + "_") for k in ds) else f"{key}_"
            line, phase = ds.get(f"{axis}line_{unit}"), ds.get(f"{axis}phase_{unit}")
            # a star's terminals see two phases in series; a delta phase's star equivalent is a third
            m[f] = line / 2.0 if line is not None else phase / 3.0 if delta else phase
    if "dc_bus_v" in ds:
        m["rated_voltage_v"] = ds["dc_bus_v"] / R2  # linear SVPWM: line amplitude = U_dc
        d.setdefault("udc_v", ds["dc_bus_v"])
    check = None
    if len(srcs) > 1:
        e = bemf[used]
        check = {"used": f"datasheet.{used}",
                 "sources": [{"field": f"datasheet.{s}", "bemf_v": bemf[s],
                              "deviation_pct": 100.0 * (bemf[s] - e) / e} for s in srcs],
                 "spread_pct": 100.0 * (max(bemf.values()) - min(bemf.values())) / e}
    return m, d, check


def case(printed: dict, inp: dict) -> dict:
    m, d, check = motor_si(inp)
    plain = {"motor": m, "drive": d, "current_loop": inp["current_loop"]}
    o = oracle_report(plain)
    prof = profiles(plain)
    expected = {"input.motor": m, "base": o["base"], "pu": o["pu"],
                "vendor": o["vendor"], "current_pi": {a: {k: o["current_pi"][a][k] for k in (
                    "kp", "ki", "pm_kp", "pm_ki")} for a in ("d", "q")},
                "firmware.inovance": o["firmware"]["inovance"],
                "profiles": {name: {k: {"value": c["value"]} for k, c in prof[name].items()}
                             for name in ("ti", "nxp", "st", "microchip")}}
    if check is not None:
        expected["datasheet.bemf_check"] = check
    return {"printed": printed, "input": inp, "expected": expected}


def build() -> dict:
    return {f"{name}.json": case(printed, inp) for name, (printed, inp) in MOTORS.items()}


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
