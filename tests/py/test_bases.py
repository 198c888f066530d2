"""pulab.model.bases: base values and per-unit parameters, checked against the textbook relations
they must satisfy (three-phase apparent power, E = ω·ψ), computed here without pulab."""
import math

import pytest

from pulab.model.bases import bases, flux_linkage, per_unit

SEED = dict(rated_voltage_v=17.0, rated_current_a=1.5, base_freq_hz=220.0)


@pytest.mark.parametrize("base", ["rms", "peak"])
def test_power_base_is_the_rated_apparent_power_in_both_conventions(base):
    # S = √3·U_LL·I_rms for a balanced three-phase machine, whatever the dq scaling.
    b = bases(base, **SEED)
    assert b["P_b"] == pytest.approx(math.sqrt(3) * 17.0 * 1.5, rel=1e-12)


def test_rms_convention_bases():
    b = bases("rms", **SEED)
    u_b = 17.0 / math.sqrt(3)
    w_b = 2 * math.pi * 220.0
    assert b["U_b"] == pytest.approx(u_b, rel=1e-15) and b["I_b"] == 1.5
    assert b["Z_b"] == pytest.approx(u_b / 1.5, rel=1e-15)
    assert b["L_b"] == pytest.approx(u_b / 1.5 / w_b, rel=1e-15)
    assert b["psi_b"] == pytest.approx(u_b / w_b, rel=1e-15)
    assert b["T_b"] == pytest.approx(1 / w_b, rel=1e-15)
    assert b["theta_b"] == math.pi


def test_peak_and_custom_conventions():
    p = bases("peak", **SEED, angle_base="2pi")
    assert p["U_b"] == pytest.approx(17.0 * math.sqrt(2 / 3), rel=1e-15)
    assert p["I_b"] == pytest.approx(1.5 * math.sqrt(2), rel=1e-15)
    assert p["theta_b"] == 2 * math.pi
    c = bases("custom", **SEED, base_voltage_v=12.0, base_current_a=4.0)
    assert (c["U_b"], c["I_b"], c["P_b"]) == (12.0, 4.0, 72.0)
    with pytest.raises(ValueError):
        bases("line", **SEED)


def test_every_base_is_consistent_with_the_others():
    for base in ("rms", "peak"):
        b = bases(base, **SEED)
        assert b["L_b"] * b["I_b"] == pytest.approx(b["psi_b"], rel=1e-14)  # ψ = L·i
        assert b["w_b"] * b["psi_b"] == pytest.approx(b["U_b"], rel=1e-14)  # u = ω·ψ


def test_flux_linkage_from_the_back_emf():
    # E_LL = √3·ω·ψ_phase,rms: 610 V at 50 Hz is 1.12103542 Wb (the 690 V golden motor).
    assert flux_linkage("rms", 610.0, 50.0) == pytest.approx(610 / (math.sqrt(3) * 2 * math.pi * 50),
                                                             rel=1e-15)
    assert flux_linkage("rms", 610.0, 50.0) == pytest.approx(1.1210354206909772, rel=1e-12)
    # amplitude-invariant dq: the peak of the phase flux
    assert flux_linkage("peak", 610.0, 50.0) == pytest.approx(math.sqrt(2) * 1.1210354206909772,
                                                              rel=1e-12)


def test_per_unit_values():
    b = bases("rms", **SEED)
    pu = per_unit(b, rs_ohm=1.5, ld_h=6e-4, lq_h=9e-4, psi_r_wb=0.0071, ts_s=1e-4)
    assert pu["Rs"] * b["Z_b"] == pytest.approx(1.5, rel=1e-15)
    assert pu["Lq"] / pu["Ld"] == pytest.approx(1.5, rel=1e-15)
    assert pu["Ts"] == pytest.approx(1e-4 * 2 * math.pi * 220.0, rel=1e-15)
    assert pu["psi_r"] * b["psi_b"] == pytest.approx(0.0071, rel=1e-15) and pu["psi_r_wb"] == 0.0071
