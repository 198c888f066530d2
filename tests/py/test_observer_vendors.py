"""Microchip's and TI's sensorless constants: motorBench's printed pll_params.h reproduced from
each reference project's stated motor and board; TI's eSMO floats against the float32 oracle."""

from __future__ import annotations

import json
import math
import pathlib
import re
import struct
import subprocess
import sys

import pytest

import pulab

HERE = pathlib.Path(__file__).resolve().parents[1]
MCHP = HERE / "data" / "headers" / "microchip"
GOLDEN = HERE / "golden" / "observer" / "ti_esmo.json"

#: The three motorBench 2.50 reference projects (motor_params.h comments and data-model-dump.yaml
#: of each): pole pairs, nominal speed (rpm), K_e (V/(rad/s) mechanical, line-neutral peak).
#: LVMC board: V_b 71.3 V, I_b 43.6 A, Δt 50 µs; velocity base = 1.5 × nominal
#: (operation-fullscale_base_ratio); pll-omega1 116.5 Hz, pll-tau 2.19 ms.
PROJECTS = {"actblf02": (4, 4000.0, 3.712916167e-02), "elra": (2, 3000.0, 3.146130776e-02),
            "linix": (2, 4000.0, 2.836246446e-02)}
MCHP_MACROS = ("MCAF_PLL_DT_ANGULAR", "KFILTER_ESDQ", "KFILTER_VELESTIM", "DECIMATE_BASE_SPEED",
               "MCAF_PLL_VELOCITY_FILTER_THRESHOLD")


def _mchp_input(project: str) -> dict:
    pp, rpm, ke = PROJECTS[project]
    f_nom = pp * rpm / 60.0
    psi = ke / pp
    return {"motor": {"rated_voltage_v": 24.0, "rated_current_a": 5.0, "rated_freq_hz": f_nom,
                      "rs_ohm": 0.3, "ld_h": 3e-4, "lq_h": 3e-4, "pole_pairs": pp,
                      "bemf_v": psi * 2 * math.pi * f_nom * math.sqrt(3) / math.sqrt(2)},
            "drive": {"udc_v": 24.0, "ts_s": 5e-5, "base_freq_hz": f_nom},
            "profiles": {"microchip": {"voltage_base_v": 71.3, "current_base_a": 43.6,
                                       "velocity_base_hz": 1.5 * f_nom}},
            "observer": {"bemf_f0_hz": 116.5, "speed_filter_hz": 1.0 / (2 * math.pi * 2.19e-3)}}


def _printed(path: pathlib.Path) -> dict:
    """name → (integer, ideal engineering number) of each Q15 line of a pll_params.h."""
    out = {}
    line = r"#define (\w+)\s+(-?\d+)\s+// Q\d+\(\s*\S+\) = \s*\S+ \S+\s+= \s*([+-][\d.]+)"
    for m in re.finditer(line, path.read_text(encoding="utf-8")):
        out[m.group(1)] = (int(m.group(2)), float(m.group(3)))
    return out


@pytest.mark.parametrize("project", sorted(PROJECTS))
def test_microchip_pll_params_reproduce_motorbench(project):
    printed = _printed(MCHP / f"pll_params_{project}.h")
    c = pulab.report(_mchp_input(project))["profiles"]["microchip"]["constants"]
    assert {k: c[k]["value"] for k in MCHP_MACROS} == {k: printed[k][0] for k in MCHP_MACROS}


def test_microchip_ke_inverse_reproduces_motor_params():
    """MCAF_MOTOR_KE_INVERSE of the three motor_params.h (12519, 19698, 16388; Q12)."""
    got = {p: pulab.report(_mchp_input(p))["profiles"]["microchip"]["constants"]
           ["MCAF_MOTOR_KE_INVERSE"]["value"] for p in PROJECTS}
    assert got == {"actblf02": 12519, "elra": 19698, "linix": 16388}


def test_microchip_engineering_values_match_the_printed_column():
    """The header's ideal column (µs, rad/s, RPM) against pulab's SI ideal (si_ideal)."""
    printed = _printed(MCHP / "pll_params_actblf02.h")
    c = pulab.report(_mchp_input("actblf02"))["profiles"]["microchip"]["constants"]
    dt_us = printed["MCAF_PLL_DT_ANGULAR"][1]
    assert c["MCAF_PLL_DT_ANGULAR"]["si_ideal"] == pytest.approx(dt_us * 1e-6, rel=1e-6)
    for k in ("KFILTER_ESDQ", "KFILTER_VELESTIM"):
        assert c[k]["si_ideal"] == pytest.approx(printed[k][1], rel=1e-6)
    rpm = c["DECIMATE_BASE_SPEED"]["si_ideal"] * 30 / math.pi / 4
    assert rpm == pytest.approx(printed["DECIMATE_BASE_SPEED"][1], rel=1e-9)


def test_microchip_observer_constants_listed_only_with_an_observer():
    inp = _mchp_input("linix")
    p = pulab.report(inp)["profiles"]["microchip"]
    assert p["observer_constants"] == list(MCHP_MACROS) + ["MCAF_MOTOR_KE_INVERSE"]
    del inp["observer"]
    assert "observer_constants" not in pulab.report(inp)["profiles"]["microchip"]


def test_microchip_filter_beyond_q15_is_flagged():
    """A back-EMF corner above 1/(2π·Δt) (3.18 kHz at 50 µs) leaves Q15: shown, not wrapped."""
    inp = _mchp_input("linix")
    inp["observer"]["bemf_f0_hz"] = 4000.0
    c = pulab.report(inp)["profiles"]["microchip"]["constants"]["KFILTER_ESDQ"]
    assert c["value"] == 32767 and "out_of_range" in c["flags"]


# Golden vectors of tests/oracle/observer_vendors_oracle.py (motorBench's printed integers; TI's
# esmo.c re-run in numpy float32; never imports pulab); the same files go through Pyodide in
# tests/web/golden-observer-vendors.test.ts.
VENDOR_GOLDEN = sorted((HERE / "golden" / "observer-vendors").glob("*.json"))


def test_observer_vendor_golden_files_are_fresh():
    assert {p.name[:2] for p in VENDOR_GOLDEN} == {"mc", "ti"}
    r = subprocess.run([sys.executable, "observer_vendors_oracle.py", "--check"],
                       capture_output=True, text=True, cwd=HERE / "oracle")
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("path", VENDOR_GOLDEN, ids=[p.stem for p in VENDOR_GOLDEN])
def test_observer_vendor_golden(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    got, tol = pulab.report(case["input"]), case["tolerance"]
    for key, want in case["expected"].items():
        have = got
        for k in key.split("."):
            have = have[k]
        if isinstance(want, int):
            assert have == want, key
        else:
            assert have == pytest.approx(want, rel=tol["rel"], abs=tol["abs"]), key


def test_ti_esmo_values_are_float32():
    """Each eSMO field is the binary32 the C2000 holds (``float32_t``), not a double."""
    case = json.loads((HERE / "golden" / "observer-vendors" / "ti_teknic_m2310pln04k.json")
                      .read_text(encoding="utf-8"))
    c = pulab.report(case["input"])["profiles"]["ti"]["constants"]
    for k in ("Fdsmopos", "Gdsmopos", "Kslf", "lpf_a1", "thetaDelta", "pll_Kp"):
        assert c[k]["format"] == "float32"
        assert struct.unpack("<f", struct.pack("<f", c[k]["value"]))[0] == c[k]["value"], k


def test_ti_pll_kp_crosses_over_at_the_tracking_bandwidth():
    """The proportional PLL θ += Kp·(Δθ/2π)·f_max·T_s: its loop gain per period is
    Kp·f_max·T_s, a crossover at Kp·f_max rad/s = 2π·tracking_f0_hz (15 Hz, f_max 400 Hz)."""
    case = json.loads((HERE / "golden" / "observer-vendors" / "ti_teknic_m2310pln04k.json")
                      .read_text(encoding="utf-8"))
    inp = {**case["input"], "observer": {**case["input"]["observer"], "tracking_f0_hz": 15.0}}
    kp = pulab.report(inp)["profiles"]["ti"]["constants"]["pll_Kp"]["value"]
    assert kp * 400.0 == pytest.approx(2 * math.pi * 15.0, rel=1e-6)


def test_ti_header_prints_the_esmo_macros_and_the_fields_as_a_comment():
    """user_mtr1.h holds only the USER_MOTOR1_ macros; the eSMO fields are computed at run time,
    so the header shows them in a comment, not as _IQ integers."""
    case = json.loads((HERE / "golden" / "observer-vendors" / "ti_teknic_m2310pln04k.json")
                      .read_text(encoding="utf-8"))
    from pulab.profiles import header
    text = header(pulab.report(case["input"]), "ti")
    assert re.search(r"#define USER_MOTOR1_BEMF_KSLF_FC_Hz\s+\(2\.0f\)", text)
    assert re.search(r"#define USER_MOTOR1_SPEED_LPF_FC_Hz\s+\(200\.0f\)", text)
    assert re.search(r"^ \*   Fdsmopos = 0\.97793\d+", text, re.M)
    assert "FDSMOPOS" not in text and "KSLF_IQ" not in text
