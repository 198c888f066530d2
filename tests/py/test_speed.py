"""pulab.analyses.loop.speed: the speed loop's bases, design, integers and margins — the design
against the closed-loop polynomial it must give, the margins against python-control on the same
discrete loop built independently (c2d of K_t/(J·s + B), the firmware PI, one period of delay,
the speed filter)."""
import math

import pytest

from pulab.analyses.loop.speed import analyze, design, integers, mechanical_bases
from pulab.model.bases import bases
from pulab.schema.errors import InputError

control = pytest.importorskip("control")

KT, J, B, TS = 0.0531, 1e-5, 2e-6, 1e-3


def test_mechanical_bases_of_rms_bases():
    b = bases("rms", 17.0, 1.5, 220.0)
    m = mechanical_bases(4, b["w_b"], b["P_b"], b["U_b"], b["I_b"], 0.0071, 1e-5)
    assert m["w_mb"] == pytest.approx(2 * math.pi * 220 / 4, rel=1e-15)
    assert m["torque_nm"] * m["w_mb"] == pytest.approx(b["P_b"], rel=1e-14)  # T_mb·ω_mb = P_b
    assert m["kt_nm_per_a"] == pytest.approx(3 * 4 * 0.0071, rel=1e-14)    # T = 3·p·ψ_rms·I
    assert m["inertia_constant_s"] == pytest.approx(0.5 * 1e-5 * m["w_mb"] ** 2 / b["P_b"], rel=1e-14)
    assert m["n_mb_rpm"] == pytest.approx(220 * 60 / 4, rel=1e-14)


def test_design_places_the_closed_loop_poles():
    kp, ki = design(KT, J, B, 20.0, 0.8)
    # J·s² + (B + K_t·kp)·s + K_t·ki = J·(s² + 2ζω_n·s + ω_n²)
    wn = 2 * math.pi * 20.0
    assert KT * ki / J == pytest.approx(wn ** 2, rel=1e-13)
    assert (B + KT * kp) / J == pytest.approx(2 * 0.8 * wn, rel=1e-13)
    with pytest.raises(InputError) as e:
        design(KT, J, 1.0, 20.0, 0.8)  # friction alone exceeds 2ζω_n·J: kp ≤ 0
    assert (e.value.field, e.value.code) == ("analysis.speed.bandwidth_hz", "speed_kp_low")


def test_integers_round_half_away_and_overflow_is_an_error():
    g = integers(0.25, 30.0, 345.6, 1.5, TS)
    assert g["kp_pu"] == pytest.approx(0.25 * 345.6 / 1.5, rel=1e-15)
    assert abs(g["pm_kp"] - g["kp_pu"] * 4096) <= 0.5 and abs(g["pm_ki"] - g["ki_pu"] * TS * 65536) <= 0.5
    assert g["from_integers"]["kp"] == pytest.approx(g["pm_kp"] / 4096 * 1.5 / 345.6, rel=1e-15)
    with pytest.raises(InputError) as e:
        integers(1e6, 1.0, 345.6, 1.5, TS)
    assert e.value.code == "long_overflow"


@pytest.mark.parametrize("bandwidth_hz, filter_hz", [(20.0, 100.0), (50.0, 250.0), (8.0, 400.0)])
def test_margins_agree_with_python_control(bandwidth_hz, filter_hz):
    cfg = {"inertia_kg_m2": J, "friction_nm_s": B, "ts_s": TS, "bandwidth_hz": bandwidth_hz,
           "damping": 0.7071, "filter_hz": filter_hz}
    out = analyze(cfg, KT, 345.6, 1.5)
    kp, ki = out["kp"], out["ki"]
    alpha = 1 - math.exp(-2 * math.pi * filter_hz * TS)
    plant = control.c2d(control.tf([KT], [J, B]), TS, "zoh")
    pi = control.tf([kp + ki * TS, -kp], [1, -1], TS)          # I_k = I_k−1 + ki·T·e_k; u = kp·e + I
    delay = control.tf([1], [1, 0], TS)                           # the current reference acts one T later
    lowpass = control.tf([alpha, 0], [1, alpha - 1], TS)          # y_k = y_k−1 + α(x_k − y_k−1)
    gm, pm, wcg, wcp = control.margin(pi * plant * delay * lowpass)
    assert out["phase_margin_deg"] == pytest.approx(pm, abs=1e-6)
    assert out["crossover_hz"] == pytest.approx(wcp / (2 * math.pi), rel=1e-6)
    assert out["gain_margin_db"] == pytest.approx(20 * math.log10(gm), abs=1e-6)
    assert out["phase_crossover_hz"] == pytest.approx(wcg / (2 * math.pi), rel=1e-6)
