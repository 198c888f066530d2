"""pulab.model.gains: the current and PLL PI gains in SI, per unit and as firmware integers,
checked against the closed loops they must give (complex arithmetic here, no pulab)."""
import math
import random

import pytest

from pulab.model.gains import current_pi, current_pi_si, gains_from_integers, pi_integer_ideals, pll_gains
from pulab.schema.errors import InputError

R, L = 1.5, 6e-4


def closed_loop(kp, ki, s):
    """PI (kp + ki/s) around the winding 1/(R + sL), unity feedback."""
    g = (kp + ki / s) / (R + s * L)
    return g / (1 + g)


def test_bandwidth_design_cancels_the_pole_and_has_its_bandwidth():
    kp, ki = current_pi_si("bandwidth", R, L, 500.0, 0.7)
    assert kp / ki == pytest.approx(L / R, rel=1e-15)  # the PI zero on the plant pole
    w = 2 * math.pi * 500.0
    assert abs(closed_loop(kp, ki, 1j * w)) == pytest.approx(1 / math.sqrt(2), rel=1e-12)
    assert abs(closed_loop(kp, ki, 1j * w * 1e-3)) == pytest.approx(1.0, abs=1e-5)


def test_damping_design_places_the_second_order_poles():
    kp, ki = current_pi_si("damping", R, L, 800.0, 0.5)
    # closed-loop denominator L·s² + (R + kp)·s + ki = L·(s² + 2ζω0·s + ω0²)
    w0 = 2 * math.pi * 800.0
    assert ki / L == pytest.approx(w0 ** 2, rel=1e-12)
    assert (R + kp) / L == pytest.approx(2 * 0.5 * w0, rel=1e-12)
    with pytest.raises(InputError) as e:
        current_pi_si("damping", 100.0, L, 1.0, 0.1)  # 2ζω0·L below R: kp would be ≤ 0
    assert (e.value.field, e.value.code) == ("current_loop.bandwidth_hz", "damping_kp_low")
    assert current_pi_si("manual", R, L, 1.0, 1.0, kp=2, ki=3) == (2.0, 3.0)


def test_the_seed_motor_integers():
    # U_b = 17/√3 V, I_b = 1.5 A: kp_pu = 1.885·1.5/9.81495 = 0.288081 → ×2^12 = 1179.98 → 1180;
    # ki_pu·Ts = 4712.4·1.5/9.81495·1e-4 = 0.0720187 → ×2^16 = 4719.8 → 4720.
    g = current_pi(1.885, 4712.4, L, 17 / math.sqrt(3), 1.5, 1e-4)
    assert (g["pm_kp"], g["pm_ki"]) == (1180, 4720)
    assert pi_integer_ideals(0.5, 100.0, 1e-4) == (2048.0, 655.36)


def test_integers_round_to_nearest_and_come_back_within_half_an_lsb():
    rng = random.Random(3)
    for _ in range(500):
        kp, ki = rng.uniform(0.01, 50), rng.uniform(1, 1e5)
        u_b, i_b, ts = rng.uniform(5, 600), rng.uniform(0.5, 300), rng.choice([5e-5, 1e-4, 2.5e-4])
        g = current_pi(kp, ki, L, u_b, i_b, ts)
        assert abs(g["pm_kp"] - kp * i_b / u_b * 4096) <= 0.5
        assert abs(g["pm_ki"] - ki * i_b / u_b * ts * 65536) <= 0.5
        back_kp, back_ki = gains_from_integers(g["pm_kp"], g["pm_ki"], u_b, i_b, ts)
        assert abs(back_kp - kp) <= 0.5 / 4096 * u_b / i_b * (1 + 1e-12)
        assert abs(back_ki - ki) <= 0.5 / 65536 / ts * u_b / i_b * (1 + 1e-12)
        assert g["from_integers"]["kp"] == back_kp


def test_an_integer_beyond_a_long_is_an_error():
    with pytest.raises(InputError) as e:
        current_pi(1e6, 1.0, L, 1.0, 1.0, 1e-4)  # kp_pu·2^12 = 4.1e9 > 2^31 − 1
    assert (e.value.field, e.value.code) == ("current_loop", "long_overflow")


def test_pll_gains_give_the_asked_natural_frequency_and_damping():
    g = pll_gains(50.0, 0.7, 2 * math.pi * 75.0, math.pi)
    # closed loop (kp·s + ki)/(s² + kp·s + ki): ω_n = √ki, ζ = kp/(2√ki)
    assert math.sqrt(g["ki"]) == pytest.approx(2 * math.pi * 50.0, rel=1e-14)
    assert g["kp"] / (2 * math.sqrt(g["ki"])) == pytest.approx(0.7, rel=1e-14)
    assert g["kp_pu"] == pytest.approx(g["kp"] * math.pi / (2 * math.pi * 75.0), rel=1e-15)
    assert g["integrator_gain"] == pytest.approx(150.0, rel=1e-15)  # ω_b/θ_b = 2π·75/π
