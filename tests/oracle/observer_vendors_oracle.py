"""Independent oracle for Microchip's and TI's sensorless constants; writes
tests/golden/observer-vendors/*.json.

    .venv/bin/python tests/oracle/observer_vendors_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/observer_vendors_oracle.py --check  # exit 1 if any is stale

Never imports pulab.

- Microchip: the expected integers are the ones motorBench printed in the reference projects'
  pll_params.h (tests/data/headers/microchip/, read here as text), the input the project's
  stated motor (motor_params.h comments, data-model-dump.yaml).  Exact integers.
- TI: ESMO_setParams/ESMO_updateFilterParams (anyway-blows/ti-c2000-motor-control-sdk :
  libraries/observers/esmo/source/esmo.c) re-run in numpy float32, operation by operation as
  the C2000's FPU does, for two motors of user_mtr1.h (Teknic_M2310PLN04K, Estun_EMJ_04APB22_A)
  on the BSXL8320RS_REVA board at 15 kHz (PGA gain 12: 42.856 A; 57.528 V).  Its float32
  rounding per operation, against pulab's one rounding of a double, is the stated tolerance.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np

from golden_files import golden_dir, sync

HERE = Path(__file__).resolve().parents[1]
GOLDEN = HERE / "golden" / "observer-vendors"
MCHP = HERE / "data" / "headers" / "microchip"
REL, ABS = 1e-12, 0.0
F = np.float32

#: pole pairs, nominal rpm, K_e [V/(rad/s) mechanical] of each motorBench reference project
PROJECTS = {"actblf02": (4, 4000.0, 3.712916167e-02), "elra": (2, 3000.0, 3.146130776e-02),
            "linix": (2, 4000.0, 2.836246446e-02)}
#: user_mtr1.h: Rs, Ls_d, Ls_q, FREQ_MAX_HZ, BEMF_KSLF_FC_Hz, SPEED_LPF_FC_Hz
TI_MOTORS = {"teknic_m2310pln04k": (2.98774099, 0.008926632, 0.008926632, 400.0, 2.0, 200.0),
             "estun_emj_04apb22_a": (2.62655902, 0.00860825367, 0.00860825367, 400.0, 2.0, 200.0)}
V_ADC, I_ADC, PWM_KHZ = 57.528, 42.856, 15.0


def _printed(path: Path) -> dict:
    text = path.read_text(encoding="utf-8")
    return {m.group(1): int(m.group(2))
            for m in re.finditer(r"#define (\w+)\s+(-?\d+)\s+// Q15", text)}


def microchip(project: str) -> dict:
    pp, rpm, ke = PROJECTS[project]
    f_nom = pp * rpm / 60.0
    psi = ke / pp
    printed = _printed(MCHP / f"pll_params_{project}.h")
    keys = ("MCAF_PLL_DT_ANGULAR", "KFILTER_ESDQ", "KFILTER_VELESTIM", "DECIMATE_BASE_SPEED",
            "MCAF_PLL_VELOCITY_FILTER_THRESHOLD")
    inp = {"motor": {"rated_voltage_v": 24.0, "rated_current_a": 5.0, "rated_freq_hz": f_nom,
                     "rs_ohm": 0.3, "ld_h": 3e-4, "lq_h": 3e-4, "pole_pairs": pp,
                     "bemf_v": psi * 2 * math.pi * f_nom * math.sqrt(3) / math.sqrt(2)},
           "drive": {"udc_v": 24.0, "ts_s": 5e-5, "base_freq_hz": f_nom},
           "profiles": {"microchip": {"voltage_base_v": 71.3, "current_base_a": 43.6,
                                      "velocity_base_hz": 1.5 * f_nom}},
           "observer": {"bemf_f0_hz": 116.5, "speed_filter_hz": 1.0 / (2 * math.pi * 2.19e-3)}}
    return {"input": inp,
            "expected": {f"profiles.microchip.constants.{k}.value": printed[k] for k in keys},
            "tolerance": {"rel": 0.0, "abs": 0.0}}


def ti(motor: str) -> dict:
    rs, ld, lq, f_max, kslf_fc, lpf_fc = TI_MOTORS[motor]
    # user_mtr1.h: period in µs as float32, then seconds
    ts = F(F(F(1000.0) / F(PWM_KHZ)) / F(1000000.0))
    v_sf, i_sf = F(V_ADC) / F(4096.0), F(I_ADC) / F(4096.0)
    base_vi = F(F(v_sf / i_sf) * F(2.0))
    rs32 = F(rs)
    two_pi = F(2.0 * math.pi)
    out = {}
    for axis, l_h in (("d", ld), ("q", lq)):
        f = np.exp(F(-F(rs32 / F(l_h)) * ts), dtype=np.float32)
        out[f"F{axis}smopos"] = float(f)
        out[f"G{axis}smopos"] = float(F(base_vi / rs32) * F(F(1.0) - f))
    base_wts = F(ts * F(f_max))
    out["Kslf"] = float(F(F(F(kslf_fc) * two_pi) * base_wts))
    t = F(F(F(lpf_fc) * two_pi) * ts)
    a1 = F(F(1.0) / F(F(1.0) + t))
    out["lpf_a1"], out["lpf_b0"] = float(a1), float(F(F(1.0) - a1))
    out["thetaDelta"] = float(F(F(f_max) * ts))
    inp = {"motor": {"rated_voltage_v": 200.0, "rated_current_a": 2.0, "rated_freq_hz": 200.0,
                     "rs_ohm": rs, "ld_h": ld, "lq_h": lq, "pole_pairs": 4, "bemf_v": 100.0},
           "drive": {"udc_v": 48.0, "ts_s": 1.0 / (PWM_KHZ * 1000.0), "base_freq_hz": f_max},
           "profiles": {"ti": {"full_scale_voltage_v": V_ADC, "full_scale_current_a": I_ADC / 2,
                               "full_scale_freq_hz": f_max}},
           # TI's corner macros: FC·f_max Hz for the back-EMF filter, the speed filter's own
           "observer": {"bemf_f0_hz": kslf_fc * f_max, "speed_filter_hz": lpf_fc}}
    exp = {f"profiles.ti.constants.{k}.value": v for k, v in out.items()}
    exp["profiles.ti.constants.USER_MOTOR1_BEMF_KSLF_FC_Hz.value"] = float(F(kslf_fc))
    exp["profiles.ti.constants.USER_MOTOR1_SPEED_LPF_FC_Hz.value"] = float(F(lpf_fc))
    # (1 − F) in float32 loses up to 2⁻²⁴/(1 − F) relative: 3e-6 at F = 0.978
    return {"input": inp, "expected": exp, "tolerance": {"rel": 1e-5, "abs": 0.0}}


def build() -> dict:
    files = {f"mchp_{p}.json": microchip(p) for p in PROJECTS}
    files.update({f"ti_{m}.json": ti(m) for m in TI_MOTORS})
    return files


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
