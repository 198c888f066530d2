"""The Inovance C2000 parameter block read back (``decode_header``): pu-lab's header of the
seed's code (``PULAB_RAW_*``, the normalized integers, the current PI), the only ``#define``
form of the source document's parameter table.

The raw Uint16 parameters decode to SI by their firmware units (:mod:`pulab.profiles.inovance.code`:
1 V, 0.01 A, 0.01 Hz, 1 mΩ, 0.01 mH, 0.1 V); every normalized integer is computed again from
them with the seed's own integer code, bit-exact, and a stored value that differs is an
``inconsistent`` finding (the raw table was edited after the block was generated). The
current PI: kp = pm_kp/2^12·U_b/I_b [V/A] and ki·T = pm_ki/2^16·U_b/I_b (seed 2.2-9), with
U_b = Voltage/√3 and I_b = Current; the block does not state T, so ki in V/(A·s) needs
``drive.ts_s`` (``design.missing``).

Examples
--------
>>> raw = {"PULAB_RAW_VOLTAGE": 17, "PULAB_RAW_CURRENT": 150, "PULAB_RAW_FULLFREQ01": 22000,
...        "PULAB_RAW_RSPM": 1500, "PULAB_RPM": 15000}
>>> d = decode_header(raw, {})
>>> d["checks"][0][1], d["checks"][0][3]["b"]   # the seed's code gives 15022
('inconsistent', 15022)
"""

from __future__ import annotations

from ...schema.fields import RAW_FIELDS
from ..common import SQRT3
from ..decoding import check, macro, result
from .code import RAW_SCALE, VENDOR_READS, VENDOR_RESULTS, to_si

__all__ = ["decode_header"]

#: header name → the seed's result name.
_RESULTS = {"PULAB_RPM": "Rpm", "PULAB_LD": "LD", "PULAB_LQ": "LQ", "PULAB_FREQPER": "FreqPer",
            "PULAB_FLUXROTOR": "FluxRotor", "PULAB_PM_MAXOUT_VOL": "pm_maxout_vol",
            "PULAB_MAXU": "maxu"}
_UNITS = {"Rpm": "Ω", "LD": "H", "LQ": "H", "FreqPer": "Hz", "FluxRotor": "Wb",
          "pm_maxout_vol": "V", "maxu": "V"}
_RAW = {f"PULAB_RAW_{n.upper()}": n for n in RAW_FIELDS}
_SI_UNIT = {"motor.rated_voltage_v": "V", "motor.rated_current_a": "A", "drive.base_freq_hz": "Hz",
            "motor.rated_freq_hz": "Hz", "motor.rs_ohm": "Ω", "motor.ld_h": "H",
            "motor.lq_h": "H", "motor.bemf_v": "V", "drive.udc_v": "V"}
_GAINS = ("PULAB_PM_KP_D", "PULAB_PM_KI_D", "PULAB_PM_KP_Q", "PULAB_PM_KI_Q")
READS = tuple(_RAW) + tuple(_RESULTS) + _GAINS


def decode_header(values: dict, notes: dict) -> dict:
    """Inovance macros in SI, the design and the checks (:mod:`pulab.profiles.decoding`)."""
    v = values
    out: dict = {}
    raw = {n: int(v[h]) for h, n in _RAW.items() if isinstance(v.get(h), int)}
    inp: dict = {"motor": {}, "drive": {}}
    for h, n in _RAW.items():
        if n not in raw:
            continue
        path, scale = RAW_SCALE[n]
        scale = scale if scale is not None else 1e5  # LD/LQ in 0.01 mH (pu-lab's default unit)
        sec, key = path.split(".")
        inp[sec][key] = raw[n] / scale
        out[h] = macro(raw[n] / scale, _SI_UNIT[path], f"raw {n} → {path}", f"{h}/{scale:g}")
    checks: list = []
    for h, name in _RESULTS.items():
        if h not in v or not all(k in raw for k in VENDOR_READS[name]):
            continue
        try:
            want = VENDOR_RESULTS[name](raw, "10uH")["value"]
            si = to_si(name, int(v[h]), raw)
        except (ValueError, ArithmeticError):
            continue
        out[h] = macro(si, _UNITS[name], f"the seed's {name}", f"{name} → SI (seed 1.4)")
        if want != v[h]:
            checks.append(check("error", "inconsistent", [h] + [f"PULAB_RAW_{k.upper()}"
                                                                for k in VENDOR_READS[name]],
                                "regenerate the block from the raw table",
                                what=name, a=v[h], a_from=h, b=want,
                                b_from="the seed's code on the raw table",
                                diff=round(100.0 * (v[h] / want - 1.0), 3) if want else "∞"))
    gains = {}
    if "Voltage" in raw and "Current" in raw and raw["Current"]:
        z = raw["Voltage"] / SQRT3 / (raw["Current"] / 100.0)
        for axis in ("d", "q"):
            kp_n, ki_n = f"PULAB_PM_KP_{axis.upper()}", f"PULAB_PM_KI_{axis.upper()}"
            if kp_n in v and ki_n in v:
                kp, ki_t = v[kp_n] / 4096.0 * z, v[ki_n] / 65536.0 * z
                out[kp_n] = macro(kp, "V/A", f"current PI kp, {axis} axis", f"{kp_n}/2^12·U_b/I_b")
                out[ki_n] = macro(ki_t, "V/A", f"current PI ki·T, {axis} axis",
                                  f"{ki_n}/2^16·U_b/I_b")
                gains[axis] = {"kp_v_per_a": kp, "ki_t_v_per_a": ki_t}
    design = {"input": inp, "assumed": ["LD, LQ in 0.01 mH (conventions.inductance_unit 10uH)"],
              "current_loop": None, "gains": gains or None, "speed_loop": None,
              "observer": None}
    return result(READS, "c28x", out, design, checks)
