"""pulab.profiles.inovance.code: the vendor code of seed 1.4 and 2.2, against the seed's own
numbers and hand arithmetic."""
import math

import pytest

from pulab import InputError
from pulab.profiles.inovance.code import (current_pi_step, flux_rotor, freq_per, inductance,
                          max_output_voltage, raw_from_si, round_half_away, rpm, to_si)

SEED_RAW = {"Voltage": 17, "Current": 150, "FullFreq01": 22000, "FreqRated01": 22000,
            "RsPm": 1500, "LD": 60, "LQ": 60, "BemfVolt": 120, "uDCFilter": 240}


def test_rpm_seed_1_4_1_worked_number():
    # Seed 1.4-1/1.4-2: RsPm 1500, Current 150, Voltage 17 → m_UData = 13235 → Rpm = 15022,
    # against the ideal 1.5/(17/√3/1.5)·2^16 = 15023.6.
    r = rpm(SEED_RAW)
    assert [s["value"] for s in r["trace"]] == [13235, 15022]
    assert r["value"] == 15022
    assert r["ideal"] == pytest.approx(1.5 / (17 / math.sqrt(3) / 1.5) * 65536, rel=1e-15)
    assert round(r["ideal"], 1) == 15023.6
    assert r["flags"] == ["truncation"] and r["q"] == 16


def test_inductance_q13_and_the_x10_puzzle():
    # LD in 0.01 mH: m_BaseL = 17·3678/150 = 416, ·5000/22000 = 94; (60<<14 + 47)/94 = 10458;
    # /10 = 1045 ≈ L/L_b·2^13 = 1038.4 (seed 1.4-8).  Hand arithmetic, step by step.
    r = inductance(SEED_RAW, "d", "10uH")
    assert [s["value"] for s in r["trace"]] == [416, 94, 60 * 16384 + 47, 10458, 1045]
    assert r["ideal"] == pytest.approx(6e-4 / ((17 / math.sqrt(3)) / (2 * math.pi * 220 * 1.5))
                                       * 8192, rel=1e-12)
    # The same motor with LD in µH (600) — the seed's reading — gives 10× (seed 1.4-6, 1.4-9).
    u = inductance({**SEED_RAW, "LD": 600}, "d", "uH")
    assert u["value"] == (600 * 16384 + 47) // 94 // 10 == 10457 and "unit_uH" in u["flags"]
    assert u["value"] / u["ideal"] == pytest.approx(10, rel=0.01)


def test_freq_per_and_flux_rotor_q12():
    fp = freq_per({**SEED_RAW, "FullFreq01": 44000})
    assert fp["value"] == 16384
    fr = flux_rotor(SEED_RAW)
    # (120<<12)/(17*10) = 2891; (2891<<15)/32768 = 2891
    assert [s["value"] for s in fr["trace"]] == [2891, 2891]
    assert fr["ideal"] == pytest.approx(12 / 17 * 4096, rel=1e-15)


def test_voltage_times_ten_wraps_in_16_bits():
    # Voltage 6600 → Voltage*10 = 66000 → 464 in 16-bit arithmetic: FluxRotor is garbage.
    raw = {**SEED_RAW, "Voltage": 6600, "BemfVolt": 60000}
    fr = flux_rotor(raw)
    assert fr["trace"][0]["value"] == (60000 << 12) // 464
    assert "wrap" in fr["flags"]


def test_uint16_store_is_flagged():
    # Rated above base frequency ×2: FreqPer = 3·2^15 does not fit Uint16.
    fp = freq_per({**SEED_RAW, "FreqRated01": 30000, "FullFreq01": 10000})
    assert fp["value"] == (3 << 15) % 65536 and "store" in fp["flags"]


def test_max_output_voltage_seed_2_2_2():
    vol, maxu = max_output_voltage({**SEED_RAW, "uDCFilter": 5400, "Voltage": 380})
    assert vol["trace"][0]["value"] == 5400 * 2316 >> 15          # 381 V ≈ 540/√2
    assert vol["value"] == (381 << 12) // 380
    assert maxu["value"] == vol["value"] << 12
    assert vol["ideal"] == pytest.approx(540 / math.sqrt(2) / 380 * 4096, rel=1e-15)


def test_maxu_wraps_for_a_tiny_voltage():
    vol, maxu = max_output_voltage({**SEED_RAW, "uDCFilter": 65535, "Voltage": 1})
    assert "wrap" in maxu["flags"] and maxu["value"] != vol["value"] * 4096


@pytest.mark.parametrize("name, value, expected", [
    ("Rpm", 15022, 15022 / 65536 * (17 / math.sqrt(3)) / 1.5),
    ("FreqPer", 16384, 110.0),
    ("pm_maxout_vol", 4096, 17.0),
])
def test_reverse_to_si(name, value, expected):
    assert to_si(name, value, SEED_RAW) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize("x, n", [(0.5, 1), (1.5, 2), (-0.5, -1), (2.4999, 2), (59.99999999, 60)])
def test_round_half_away(x, n):
    assert round_half_away(x) == n


def test_raw_out_of_uint16_names_the_raw_field():
    si = {"motor.rated_voltage_v": 17, "motor.rated_current_a": 700, "drive.base_freq_hz": 220,
          "motor.rated_freq_hz": 220, "motor.rs_ohm": 1.5, "motor.ld_h": 6e-4,
          "motor.lq_h": 6e-4, "motor.bemf_v": 12, "drive.udc_v": 24}
    with pytest.raises(InputError) as e:
        raw_from_si(si, "10uH", {})
    assert e.value.field == "raw.Current"


def test_division_by_zero_is_an_input_error():
    with pytest.raises(InputError) as e:
        rpm({**SEED_RAW, "Voltage": 0})
    assert e.value.field == "raw.Voltage"


@pytest.mark.parametrize("integral, error, kp, ki, maxu, maxout, out, integ, flags", [
    # integral += (e·ki)>>4 ; out = (integral + e·kp)>>12  (seed 2.2)
    (0, 4096, 1180, 4720, 1 << 26, 1 << 14, (1208320 + 4096 * 1180) >> 12, 1208320, set()),
    (0, -4096, 1180, 4720, 1 << 26, 1 << 14, (-1208320 - 4096 * 1180) >> 12, -1208320, set()),
    # clamps: integral to maxu, output to maxout
    (1 << 20, 4096, 4096, 65536, 1 << 20, 100, 100, 1 << 20, {"saturate"}),
    # e·kp overflows 32 bits: the firmware wraps
    (0, 1 << 20, 1 << 12, 0, 1 << 24, 1 << 30, ((1 << 32) >> 12) - (1 << 20), 0, {"wrap"}),
])
def test_current_pi_step(integral, error, kp, ki, maxu, maxout, out, integ, flags):
    s = current_pi_step(integral, error, kp, ki, maxu, maxout)
    if "wrap" in flags:
        assert "wrap" in s.flags
    else:
        assert (s.integral, s.out) == (integ, out)
        assert flags <= set(s.flags)


def test_current_pi_step_at_the_long_edges_against_gcc(tmp_path):
    """The PI update at every edge of its long words (maxu wrapped to −2^31 by its own shift,
    integral −2^31, products that wrap) against the seed's C compiled by gcc -m32 -fwrapv
    (C2000 wraps): the integers equal and never a Python error."""
    import itertools
    import subprocess
    from ctrace_compilers import PRELUDE, available
    if available("gcc"):
        pytest.skip(f"missing {available('gcc')}")
    edges = (-(1 << 31), -(1 << 31) + 1, -4096, -1, 0, 1, 1 << 24, (1 << 31) - 1)
    cases = list(itertools.product(edges, (-32768, -1, 0, 1, 32767), (0, 1180, (1 << 31) - 1),
                                   (0, 4720, (1 << 31) - 1), edges[::2], (-(1 << 31), 0, 4096)))
    rows = ",\n".join("{%d, %d, %d, %d, %d, %d}" % c for c in cases)
    src = tmp_path / "pi.c"
    src.write_text(PRELUDE + f"""
#include <stdio.h>
static const long long CASES[][6] = {{{rows}}};
int main(void) {{
    for (unsigned k = 0; k < sizeof CASES / sizeof CASES[0]; k++) {{
        long pm_integral_d = CASES[k][0], pm_error_id = CASES[k][1], pm_kp_d = CASES[k][2];
        long pm_ki_d = CASES[k][3], maxu = CASES[k][4], pm_maxout_vol = CASES[k][5];
        long minu, data1, pm_ud;
        minu = -maxu;
        pm_integral_d = pm_integral_d + (pm_error_id * pm_ki_d >> 4);
        pm_integral_d = __IQsat(pm_integral_d, maxu, minu);
        data1 = (pm_integral_d + pm_error_id * pm_kp_d)>>12;
        data1 = __IQsat(data1, pm_maxout_vol, -pm_maxout_vol);
        pm_ud = data1;
        printf("%ld %ld\\n", pm_integral_d, pm_ud);
    }}
    return 0;
}}
""")
    exe = tmp_path / "pi"
    subprocess.run(["gcc", "-m32", "-fwrapv", "-O0", str(src), "-o", str(exe)], check=True)
    got = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout.split("\n")
    wrapped_minu = 0
    for c, line in zip(cases, got):
        s = current_pi_step(c[0], c[1], c[2], c[3], c[4], c[5])
        assert f"{s.integral} {s.out}" == line, c
        if c[4] == -(1 << 31):
            wrapped_minu += 1
            assert "wrap" in s.flags, c
    assert len(got) == len(cases) + 1 and wrapped_minu > 0
