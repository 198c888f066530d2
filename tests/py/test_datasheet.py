"""pulab.model.datasheet: datasheet values (rpm, Ke per krpm, kT, ψ, line-to-line R and L, the
DC bus) converted into the motor's SI fields; each error names the datasheet field it came from.
The expected values are the textbook relations, written out here."""
import math

import pytest

from conftest import SEED_INPUT, chinese
from pulab import InputError, report
from pulab.model.datasheet import apply, mechanical


def _seed(**drive):
    return {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                      "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
            "drive": {"udc_v": 24, "ts_s": 1e-4, **drive}, "current_loop": {"bandwidth_hz": 300}}


@pytest.mark.parametrize("ds, motor_key, field", [
    ({"speed_rpm": 3000}, "rated_freq_hz", "datasheet.speed_rpm"),
    ({"ke_v_per_krpm": 40, "ke_measure": "rms"}, "bemf_v", "datasheet.ke_v_per_krpm"),
    ({"rs_line_ohm": 2}, "rs_ohm", "datasheet.rs_line_ohm"),
    ({"l_line_h": 0.004}, "ld_h", "datasheet.l_line_h"),
    ({"dc_bus_v": 48}, "rated_voltage_v", "datasheet.dc_bus_v"),
])
def test_datasheet_and_motor_field_both_given_names_both(ds, motor_key, field):
    inp = _seed()
    inp["datasheet"] = ds
    with pytest.raises(InputError) as e:
        report(inp)
    assert e.value.field == field and f"motor.{motor_key}" in e.value.message
    assert chinese(e.value.message_zh)


FULL = {"speed_rpm": 3000, "ke_v_per_krpm": 30, "ke_measure": "rms", "rs_line_ohm": 3,
        "l_line_h": 1e-3}


def _without(*keys, **extra):
    d = {k: v for k, v in FULL.items() if k not in keys}
    d.update(extra)
    return d


@pytest.mark.parametrize("ds, field", [
    (_without("ke_measure"), "datasheet.ke_measure"),
    (_without(ke_measure="avg"), "datasheet.ke_measure"),
    (_without(psi_wb=0.1), "datasheet.psi_wb"),
    (_without("ke_v_per_krpm", psi_wb=0.1), "datasheet.ke_measure"),
    (_without(kt_current="rms"), "datasheet.kt_current"),
    (_without(winding="wye"), "datasheet.winding"),
    (_without(speed_rpm=-1), "datasheet.speed_rpm"),
    (_without(speed_rpm="3000"), "datasheet.speed_rpm"),
    (_without(rpm=3000), "datasheet.rpm"),
    (_without(ld_line_h=1e-3), "datasheet.ld_line_h"),
    (_without("speed_rpm"), "datasheet.speed_rpm"),
    # a derived value out of range is reported at the datasheet value it came from
    (_without(speed_rpm=1e-8), "datasheet.speed_rpm"),
])
def test_datasheet_errors_name_the_field(ds, field):
    inp = _seed()
    for k in ("rated_freq_hz", "bemf_v", "rs_ohm", "ld_h", "lq_h"):
        inp["motor"].pop(k)
    inp["datasheet"] = ds
    with pytest.raises(InputError) as e:
        report(inp)
    assert e.value.field == field
    assert chinese(e.value.message_zh), e.value.message


@pytest.mark.parametrize("extra, bemf", [
    # E_LL = Ke_rms·ω_m: 0.2 V·s/rad at 3000 rpm = 62.83 V
    ({"ke_v_s_per_rad": 0.2, "ke_measure": "rms"}, 0.2 * 100 * math.pi),
    # kT = √3·Ke (per A RMS), so E_LL = kT/√3·ω_m
    ({"kt_nm_per_a": 0.2 * math.sqrt(3)}, 0.2 * 100 * math.pi),
    ({"kt_nm_per_a": 0.2 * math.sqrt(3) / math.sqrt(2), "kt_current": "peak"}, 0.2 * 100 * math.pi),
    # ψ amplitude: E_LL = √3·ω_e·ψ/√2, ω_e = 2π·200 Hz
    ({"psi_wb": 0.1}, math.sqrt(3) * 2 * math.pi * 200 * 0.1 / math.sqrt(2)),
])
def test_other_back_emf_sources(extra, bemf):
    inp = _seed()
    for k in ("rated_freq_hz", "bemf_v"):
        inp["motor"].pop(k)
    inp["datasheet"] = {"speed_rpm": 3000, **extra}
    r = report(inp)
    assert r["input"]["motor"]["bemf_v"] == pytest.approx(bemf, rel=1e-12)
    assert r["datasheet"]["conversions"][1]["field"] == "motor.bemf_v"


def test_delta_winding_has_the_same_star_equivalent():
    inp = _seed()
    for k in ("rs_ohm", "ld_h", "lq_h"):
        inp["motor"].pop(k)
    inp["datasheet"] = {"rs_line_ohm": 3.0, "l_line_h": 0.002, "winding": "delta"}
    r = report(inp)
    assert r["input"]["motor"]["rs_ohm"] == 1.5 and r["input"]["motor"]["lq_h"] == 0.001
    assert "delta" in r["datasheet"]["conversions"][0]["formula"]
    assert "datasheet" not in r["input"]  # the echoed input can be fed back as it is
    assert report(r["input"])["vendor"]["raw"] == r["vendor"]["raw"]


def test_the_docstring_motor_by_hand():
    # 3000 rpm, 4 pole pairs: f = 3000·4/60 = 200 Hz; Ke 44.38 V/krpm peak → E_LL = 44.38·3/√2;
    # star equivalent of a line-to-line measurement: half of it.
    motor, conv, _ = apply({"speed_rpm": 3000, "ke_v_per_krpm": 44.38, "ke_measure": "peak",
                            "rs_line_ohm": 2.78, "l_line_h": 0.00506},
                           {"pole_pairs": 4, "rated_voltage_v": 220, "rated_current_a": 2.8}, {})
    assert motor["rated_freq_hz"] == 200.0
    assert motor["bemf_v"] == pytest.approx(44.38 * 3 / math.sqrt(2), rel=1e-12)
    assert (motor["rs_ohm"], motor["ld_h"], motor["lq_h"]) == (1.39, 0.00253, 0.00253)
    assert all(c["formula"] and math.isfinite(c["value"]) for c in conv)


def test_dc_bus_gives_the_largest_linear_svpwm_voltage():
    motor, conv, _ = apply({"dc_bus_v": 48}, {"pole_pairs": 4}, {})
    assert motor["rated_voltage_v"] == pytest.approx(48 / math.sqrt(2), rel=1e-12)
    assert conv[0]["field"] == "motor.rated_voltage_v"


def test_mechanical_quantities():
    r = report(SEED_INPUT)
    m, b, motor = r["mechanical"], r["base"], r["input"]["motor"]
    p = motor["pole_pairs"]
    assert m["rated_speed_rpm"] == pytest.approx(60 * motor["rated_freq_hz"] / p, rel=1e-12)
    assert m["w_mech_b"] == pytest.approx(b["w_b"] / p, rel=1e-12)
    assert m["torque_base_nm"] == pytest.approx(b["P_b"] * p / b["w_b"], rel=1e-12)
    # T = 3·p·ψ_rms·I (rms convention) = kT·I, and kT = √3·Ke
    assert m["kt_nm_per_a"] == pytest.approx(math.sqrt(3) * m["ke_v_s_per_rad"], rel=1e-12)
    assert m["kt_nm_per_a"] == pytest.approx(3 * p * r["pu"]["psi_r_wb"], rel=1e-12)
    assert mechanical(motor, b, r["pu"]["psi_r_wb"], "rms") == m
