"""Datasheet entry (pulab.model.datasheet): every printed convention, the back-EMF cross-check,
conflicts naming both fields, a start with no motor values; and five real motors from public
datasheets against the pulab-free oracle (tests/oracle/datasheet_oracle.py →
tests/golden/datasheets, floats to 1e-12 relative, integers exactly).
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest

import pulab
from conftest import ROOT, SEED_INPUT, chinese
from pulab import InputError, report
from pulab.model.datasheet import apply, mechanical
from test_golden import _compare

GOLDEN = sorted((ROOT / "tests/golden/datasheets").glob("*.json"))
R2, R3 = math.sqrt(2.0), math.sqrt(3.0)


def _at(r: dict, dotted: str):
    for part in dotted.split("."):
        r = r[part]
    return r


def _run(*args):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "py"))
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env,
                          cwd=ROOT)


def test_golden_datasheets_not_stale():
    r = _run(str(ROOT / "tests/oracle/datasheet_oracle.py"), "--check")
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: p.stem)
def test_real_motor_equals_the_hand_calculation(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    r = report({**case["input"], "profiles": {}})
    problems: list[str] = []
    for key, expected in case["expected"].items():
        if key == "profiles":
            for name, consts in expected.items():
                _compare(consts, r["profiles"][name]["constants"], f"profiles.{name}", problems)
        else:
            _compare(expected, _at(r, key), key, problems)
    assert not problems, "\n".join(problems[:40])


def test_two_real_motors_are_beyond_inovance_and_the_rest_holds_them(tmp_path):
    """The physics and the other firmware: exit 0, the Inovance limit at its own section."""
    outside = []
    for path in GOLDEN:
        case = json.loads(path.read_text(encoding="utf-8"))
        r = report({**case["input"], "profiles": {}})
        if r["firmware"]["inovance"]["representable"]:
            continue
        outside.append(path.stem)
        assert [x["field"] for x in r["firmware"]["inovance"]["problems"]] == [
            "raw.FullFreq01", "raw.FreqRated01"]
        assert all(r["firmware"][n]["representable"] for n in ("ti", "nxp", "st", "microchip"))
        f = tmp_path / f"{path.stem}.json"
        f.write_text(json.dumps(case["input"]), encoding="utf-8")
        assert _run("-m", "pulab", "report", str(f)).returncode == 0
        for name in ("ti", "nxp", "st", "microchip"):
            out = _run("-m", "pulab", "header", "--profile", name, str(f))
            assert out.returncode == 0 and out.stdout.startswith("/*"), out.stderr
        out = _run("-m", "pulab", "header", "--profile", "inovance", str(f))
        assert out.returncode == 2 and "FullFreq01" in out.stderr
    assert len(outside) >= 2, outside


def test_rexroth_ke_and_kt_spread_is_shown_and_graded():
    """The issue's numbers: Ke gives 152.8 V, kT (per A crest) 143.6 V at 4000 rpm."""
    case = json.loads((ROOT / "tests/golden/datasheets/rexroth_mhd041a_144.json").read_text())
    r = report(case["input"])
    check = r["datasheet"]["bemf_check"]
    assert [round(s["bemf_v"], 1) for s in check["sources"]] == [152.8, 143.6]
    f = [x for x in r["review"]["findings"] if x["code"] == "bemf_spread"]
    assert len(f) == 1 and f[0]["severity"] == "note" and f[0]["field"] == "datasheet.bemf_from"
    assert "Ke 152.8 V, kT 143.6 V" in f[0]["message"] and chinese(f[0]["message_zh"])
    # the firmware may take kT's instead
    r2 = report({**case["input"], "datasheet": {**case["input"]["datasheet"],
                                                "bemf_from": "kt_nm_per_a"}})
    assert r2["input"]["motor"]["bemf_v"] == pytest.approx(143.6, abs=0.05)
    assert r2["datasheet"]["bemf_check"]["used"] == "datasheet.kt_nm_per_a"


def _blank(**ds):
    """A datasheet start: only what the datasheet does not give is in the motor section."""
    return {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "pole_pairs": 4},
            "drive": {"udc_v": 311, "ts_s": 1e-4},
            "datasheet": {"speed_rpm": 3000, "ke_v_per_krpm": 40, "ke_measure": "rms",
                          "rs_line_ohm": 2.0, "l_line_h": 0.004, **ds}}


def test_a_datasheet_start_needs_no_seed_values():
    r = report(_blank())
    m = r["input"]["motor"]
    assert (m["rated_freq_hz"], m["bemf_v"], m["rs_ohm"], m["ld_h"]) == (200.0, 120.0, 1.0, 0.002)


@pytest.mark.parametrize("missing, alternatives", [
    ("speed_rpm", "datasheet.speed_rpm"),
    ("rs_line_ohm", "datasheet.rs_line_ohm, datasheet.rs_phase_ohm"),
])
def test_a_missing_motor_value_names_the_datasheet_values_that_fill_it(missing, alternatives):
    inp = _blank()
    del inp["datasheet"][missing]
    if missing == "speed_rpm":
        del inp["datasheet"]["ke_v_per_krpm"], inp["datasheet"]["ke_measure"]
    with pytest.raises(InputError) as e:
        report(inp)
    assert e.value.code == "required_or" and alternatives in e.value.message
    assert chinese(e.value.message_zh)


@pytest.mark.parametrize("extra, field, other", [
    ({"rs_phase_ohm": 1.0}, "datasheet.rs_phase_ohm", "datasheet.rs_line_ohm"),
    ({"ld_phase_h": 0.002}, "datasheet.ld_phase_h", "datasheet.l_line_h"),
])
def test_two_datasheet_values_for_one_motor_field(extra, field, other):
    with pytest.raises(InputError) as e:
        report(_blank(**extra))
    assert e.value.field == field and e.value.params["other"] == other
    # one sentence naming both, by label and path, in either language
    assert field in e.value.message and other in e.value.message
    assert e.value.message.endswith(".") and field in e.value.message_zh


def test_conflict_with_a_typed_motor_value_names_both_labels():
    inp = _blank()
    inp["motor"]["rs_ohm"] = 1.0
    with pytest.raises(InputError) as e:
        report(inp)
    assert e.value.params["other"] == "motor.rs_ohm"
    assert e.value.message == ("Resistance, terminal to terminal (datasheet.rs_line_ohm) and Stator "
                               "resistance Rs (phase) (motor.rs_ohm) both set the motor's Stator "
                               "resistance Rs (phase): give only one of them.")
    assert "定子电阻" in e.value.message_zh


@pytest.mark.parametrize("ds, key, value", [
    # per phase of a star: the phase; of a delta: its star equivalent, a third
    ({"rs_phase_ohm": 0.9}, "rs_ohm", 0.9),
    ({"rs_phase_ohm": 0.9, "winding": "delta"}, "rs_ohm", 0.3),
    ({"lq_phase_h": 0.006, "ld_phase_h": 0.003, "winding": "delta"}, "lq_h", 0.002),
    # a delta's terminal value has the same star equivalent as a star's
    ({"l_line_h": 0.006, "winding": "delta"}, "ld_h", 0.003),
])
def test_per_phase_and_delta(ds, key, value):
    inp = _blank()
    for k in ("rs_line_ohm", "l_line_h"):
        del inp["datasheet"][k]
    inp["datasheet"].update(ds)
    if "rs_phase_ohm" not in ds:
        inp["datasheet"]["rs_line_ohm"] = 2.0
    if not {"l_line_h", "ld_phase_h"} & set(ds):
        inp["datasheet"]["l_line_h"] = 0.004
    r = report(inp)
    assert r["input"]["motor"][key] == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize("ds, bemf", [
    # Ke per phase, RMS: the line value is √3 times
    ({"ke_v_per_krpm": 40, "ke_measure": "rms", "ke_between": "phase"}, 120.0 * R3),
    # Kv in rpm/V on the line amplitude (the default): E_LL = n/Kv/√2
    ({"kv_rpm_per_v": 25}, 3000 / 25 / R2),
    ({"kv_rpm_per_v": 25, "kv_measure": "rms"}, 3000 / 25),
    # kT per A amplitude: ×√2 of the per-A-RMS value
    ({"kt_nm_per_a": 1.0, "kt_current": "peak"}, R2 / R3 * 100 * math.pi),
    # ψ in Wb = V·s, phase amplitude
    ({"psi_wb": 0.1}, R3 * 2 * math.pi * 200 * 0.1 / R2),
])
def test_every_back_emf_convention(ds, bemf):
    inp = _blank()
    del inp["datasheet"]["ke_v_per_krpm"], inp["datasheet"]["ke_measure"]
    inp["datasheet"].update(ds)
    assert report(inp)["input"]["motor"]["bemf_v"] == pytest.approx(bemf, rel=1e-14)


def test_a_mixed_up_convention_is_an_error_finding():
    """Ke entered as RMS while the kT says it was peak: 29 % apart, a convention slip."""
    inp = _blank(kt_nm_per_a=40 / 1000 * 60 / (2 * math.pi) * R3 / R2)
    r = report(inp)
    assert r["datasheet"]["bemf_check"]["spread_pct"] == pytest.approx(100 * (1 - 1 / R2), rel=1e-12)
    f = [x for x in r["review"]["findings"] if x["code"] == "bemf_spread"]
    assert f[0]["severity"] == "error" and "RMS and peak" in f[0]["message"]


def test_bemf_from_must_name_a_given_value():
    with pytest.raises(InputError) as e:
        report(_blank(bemf_from="psi_wb"))
    assert e.value.field == "datasheet.bemf_from" and "datasheet.psi_wb" in e.value.message


def test_conversion_labels_name_each_axis():
    r = report(_blank())
    labels = {c["field"]: (c["label"], c["label_zh"]) for c in r["datasheet"]["conversions"]}
    assert labels["motor.ld_h"][0].startswith("d-axis") and "d 轴" in labels["motor.ld_h"][1]
    assert labels["motor.lq_h"][0].startswith("q-axis") and "q 轴" in labels["motor.lq_h"][1]


def test_the_input_echo_feeds_back():
    r = report(_blank(kt_nm_per_a=0.66))
    assert "datasheet" not in r["input"]
    assert pulab.report(r["input"])["vendor"]["raw"] == r["vendor"]["raw"]


def test_cli_text_shows_the_cross_check_and_what_a_firmware_cannot_hold(tmp_path):
    for name, want in (("rexroth_mhd041a_144", ["Back-EMF cross-check at 4000 rpm (spread 5.99 %)",
                                                "datasheet.ke_v_per_krpm (used)",
                                                "= 143.646 V  (-5.99 %)"]),
                       ("maxon_ec45flat_50w_24v", ["Firmware inovance: cannot hold this motor",
                                                   "a 16-bit parameter would keep 3397"])):
        f = tmp_path / f"{name}.json"
        f.write_text(json.dumps(json.loads((ROOT / f"tests/golden/datasheets/{name}.json")
                                           .read_text())["input"]), encoding="utf-8")
        out = _run("-m", "pulab", "report", str(f), "--format", "text")
        assert out.returncode == 0, out.stderr
        for text in want:
            assert text in out.stdout, text


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
    (_without(bemf_from="psi_wb"), "datasheet.bemf_from"),
    (_without(rs_phase_ohm=1.5), "datasheet.rs_phase_ohm"),
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


def _seed(**drive):
    return {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                      "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
            "drive": {"udc_v": 24, "ts_s": 1e-4, **drive}, "current_loop": {"bandwidth_hz": 300}}


def test_the_docstring_motor_by_hand():
    # 3000 rpm, 4 pole pairs: f = 3000·4/60 = 200 Hz; Ke 44.38 V/krpm peak → E_LL = 44.38·3/√2;
    # star equivalent of a line-to-line measurement: half of it.
    motor, conv, _, _ = apply({"speed_rpm": 3000, "ke_v_per_krpm": 44.38, "ke_measure": "peak",
                            "rs_line_ohm": 2.78, "l_line_h": 0.00506},
                           {"pole_pairs": 4, "rated_voltage_v": 220, "rated_current_a": 2.8}, {})
    assert motor["rated_freq_hz"] == 200.0
    assert motor["bemf_v"] == pytest.approx(44.38 * 3 / math.sqrt(2), rel=1e-12)
    assert (motor["rs_ohm"], motor["ld_h"], motor["lq_h"]) == (1.39, 0.00253, 0.00253)
    assert all(c["formula"] and math.isfinite(c["value"]) for c in conv)


def test_dc_bus_gives_the_largest_linear_svpwm_voltage():
    motor, conv, _, _ = apply({"dc_bus_v": 48}, {"pole_pairs": 4}, {})
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
