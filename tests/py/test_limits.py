"""pulab.profiles.limits: what a firmware cannot hold, entry by entry — a Uint16 raw parameter
too small for the motor (what it needs, what 16 bits keep, the largest SI value it holds), a
division by zero in the vendor code, a profile constant that overflows its word."""
import pytest

from conftest import SEED_INPUT, chinese
from pulab import report
from pulab.profiles.limits import constant_problem, error_problem, inovance, raw_problem, status
from pulab.schema.errors import InputError


def test_a_raw_parameter_beyond_uint16():
    # 3266.67 Hz in 0.01 Hz is 326667 counts; 16 bits keep 326667 mod 65536 = 64523.
    p = raw_problem("FullFreq01", 326667, ["LQ", "LD"])
    assert (p["field"], p["code"], p["value"], p["stored"]) == ("raw.FullFreq01", "limit.uint16", 326667, 64523)
    assert p["max_si"] == 655.35 and p["results"] == ["LD", "LQ"]
    assert p["params"]["si"] == pytest.approx(3266.67, rel=1e-12)
    assert p["params"]["stored_si"] == pytest.approx(645.23, rel=1e-12)
    assert chinese(p["message_zh"]) and chinese(p["advice_zh"]) and "FullFreq01" in p["message"]
    # the SI field it comes from by its form label, in each language (the path stays in params)
    assert "and Base frequency f_b (drive max.) = 3.26667 kHz needs 326667" in p["message"]
    assert "频率基值 f_b（最大频率） = 3.26667 kHz 需要 326667" in p["message_zh"]
    assert p["params"]["source"] == "drive.base_freq_hz"


@pytest.mark.parametrize("unit, counts_per_h, shown", [("10uH", 1e5, "0.01 mH"), ("uH", 1e6, "1 µH")])
def test_the_inductance_unit_sets_the_count(unit, counts_per_h, shown):
    p = raw_problem("LD", 70000, [], unit)
    assert p["max_si"] == pytest.approx(65535 / counts_per_h, rel=1e-12)
    assert p["params"]["unit"] == shown and p["params"]["results"] == "—"


def test_a_division_by_zero_and_an_overflowing_constant():
    err = InputError("raw.Current", code="not_positive", value=0.0)
    e = error_problem(err, ["Rpm", "LD"])
    assert (e["field"], e["code"], e["results"], e["value"]) == ("raw.Current", "limit.code", ["LD", "Rpm"], None)
    assert e["params"]["reason"] == {"code": "not_positive", "params": {"value": 0.0}}
    c = constant_problem("ti", {"name": "Kp_Iq", "ideal": 70000.0, "format": "Q15", "value": 32767,
                                "q": 15}, ("full_scale_current_a",))
    assert (c["field"], c["value"], c["stored"]) == ("profiles.ti.Kp_Iq", 70000.0, 32767)
    # 70000/32767 = 2.14: two fractional bits fewer (Q13 keeps 70000/4 = 17500 ≤ 32767)
    assert (c["params"]["bits"], c["params"]["q_new"]) == (2, 13)
    assert c["params"]["factor"] == pytest.approx(70000 / 32767, rel=1e-15)
    assert c["params"]["options"] == "profiles.ti.full_scale_current_a"
    assert c["params"]["option_labels"] == [{"label": "profiles.ti.full_scale_current_a"}]
    assert "(TI · full-scale current)" in c["advice"] and "（TI · 满量程电流）" in c["advice_zh"]
    assert c["message"] == "TI Kp_Iq: 70000 does not fit Q15; stored 32767"


def test_one_entry_per_field_with_the_results_it_stops():
    err = InputError("raw.FullFreq01", code="not_positive", value=0.0)
    out = inovance({"FullFreq01": 326667}, {"LD": err, "LQ": err,
                                            "Rpm": InputError("raw.RsPm", code="zero")}, "10uH")
    assert [(p["field"], p["code"], p["results"]) for p in out] == [
        ("raw.FullFreq01", "limit.uint16", ["LD", "LQ"]), ("raw.RsPm", "limit.code", ["Rpm"])]
    assert status(out)["representable"] is False and status([]) == {"representable": True, "problems": []}


def test_the_report_says_so_and_keeps_the_physics():
    # 28,000 rpm with 4 pole pairs → 1866.7 Hz: FreqRated01 needs 186667 counts of 0.01 Hz.
    inp = {**SEED_INPUT, "motor": {**SEED_INPUT["motor"], "rated_freq_hz": 28000 * 4 / 60}}
    r = report(inp)
    fw = r["firmware"]["inovance"]
    assert fw["representable"] is False
    assert any(p["field"] == "raw.FreqRated01" and p["value"] == 186667 for p in fw["problems"])
    assert r["base"]["f_b"] > 0 and r["current_pi"]["d"]["kp"] > 0
