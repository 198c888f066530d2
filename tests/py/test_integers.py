"""pulab.analyses.integers: every firmware integer of one input with its status — the values and
ideals worked out by hand from the seed's C code (seed 1.4-5, 1.4-6) and per-unit definitions."""
import copy
import math

import pytest

from conftest import SEED_INPUT
from pulab.analyses.integers import INOVANCE_NAMES, evaluate, integer_names, profile_name


def _with(**motor):
    inp = copy.deepcopy(SEED_INPUT)
    inp["motor"].update(motor)
    return inp


def test_the_seed_motor_ld_by_hand():
    e = evaluate(SEED_INPUT)
    # Voltage 17, Current 150 (0.01 A), FullFreq01 22000 (0.01 Hz), LD 60 (0.01 mH):
    # m_BaseL = 17·3678/150 = 416 → 416·5000/22000 = 94; (60<<14 + 94>>1)/94 = 10458 → /10 = 1045
    assert e["intermediates"]["m_BaseL"] == 94
    ld = e["integers"]["vendor.LD"]
    assert (ld["status"], ld["value"]) == ("ok", 1045)
    # ideal: L/L_b·2^13 with L_b = (17/√3/1.5)/(2π·220)
    ideal = 6e-4 / (17 / math.sqrt(3) / 1.5 / (2 * math.pi * 220)) * 8192
    assert ld["ideal"] == pytest.approx(ideal, rel=1e-12)
    assert ld["error_pct"] == pytest.approx(100 * (1045 - ideal) / ideal, rel=1e-12)


def test_a_large_current_makes_the_code_divide_by_zero():
    # Current 13000: 17·3678/13000 = 4 → 4·5000/22000 = 0 = m_BaseL, the divisor of LD and LQ.
    e = evaluate(_with(rated_current_a=130))
    assert e["intermediates"]["m_BaseL"] == 0
    for name in ("vendor.LD", "vendor.LQ"):
        s = e["integers"][name]
        assert (s["status"], s["value"]) == ("div0", None) and "m_BaseL" in s["message"], s


def test_a_gain_that_rounds_to_zero():
    # bandwidth 0.01 Hz: ki = ω·R = 0.0942 Ω/s → ki_pu·Ts·2^16 = 0.0942·1.5/9.815·1e-4·65536 ≈ 0.09 → 0
    inp = copy.deepcopy(SEED_INPUT)
    inp["current_loop"] = {"bandwidth_hz": 0.01}
    s = evaluate(inp)["integers"]["current_pi.d.pm_ki"]
    assert (s["status"], s["value"]) == ("zero", 0)
    assert s["ideal"] == pytest.approx(2 * math.pi * 0.01 * 1.5 * 1.5 / (17 / math.sqrt(3)) * 1e-4 * 65536,
                                       rel=1e-12)


def test_a_design_the_input_refuses_is_invalid_not_a_number():
    # damping design at 10 Hz: kp = 2ζω_0·L − R = 2·0.7071·62.8·6e-4 − 1.5 < 0
    inp = copy.deepcopy(SEED_INPUT)
    inp["current_loop"] = {"method": "damping", "bandwidth_hz": 10}
    e = evaluate(inp)
    for name in ("current_pi.d.pm_kp", "current_pi.q.pm_ki"):
        s = e["integers"][name]
        assert (s["status"], s["value"]) == ("invalid", None)
        assert s["message"].startswith("current_loop.bandwidth_hz: ") and s["message_zh"]
    assert e["integers"]["vendor.LD"]["status"] == "ok"  # the vendor integers do not need the PI


def test_names_and_profiles():
    assert profile_name(None) == profile_name("vendor") == "inovance"
    assert integer_names(SEED_INPUT) == INOVANCE_NAMES
    assert set(evaluate(SEED_INPUT)["integers"]) == set(INOVANCE_NAMES)
    ti = integer_names({**SEED_INPUT, "profiles": {}}, "ti")
    assert ti and all(n.startswith("profiles.ti.constants.") or n.startswith("profiles.ti") for n in ti)
