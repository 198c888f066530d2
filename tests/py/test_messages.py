"""Every message the core can produce has Chinese text (the page shows both languages)."""
import copy
import json

import pytest
from hypothesis import given, settings, strategies as st

from conftest import ROOT, SEED_INPUT
from pulab import InputError, report
from pulab.api import qcalc_json, run_json
from pulab.messages import to_zh

ERRORS = json.loads((ROOT / "tests/golden/errors.json").read_text())
GOLDEN = sorted((ROOT / "tests/golden").glob("*.json"))


def _zh_ok(msg: str) -> bool:
    return to_zh(msg) != msg and any("\u4e00" <= ch <= "\u9fff" for ch in to_zh(msg))


@pytest.mark.parametrize("case", ERRORS, ids=lambda c: c["field"])
def test_every_golden_error_has_chinese(case):
    out = json.loads(run_json(json.dumps(case["input"])))
    assert out["ok"] is False and _zh_ok(out["message"]), out
    assert out["message_zh"] == to_zh(out["message"])


@pytest.mark.parametrize("path", [p for p in GOLDEN if p.name != "errors.json"], ids=lambda p: p.stem)
def test_every_golden_warning_has_chinese(path):
    r = report(json.loads(path.read_text())["input"])
    assert len(r["warnings_zh"]) == len(r["warnings"])
    for w in r["warnings"]:
        assert _zh_ok(w), w


@pytest.mark.parametrize("req", [
    {"format": "Qx"}, {"format": "Q15"}, {"format": "Q0.15", "value": 2.0, "overflow": "error"},
    {"format": "Q0.15", "raw": 40000}, {"format": "Q0.15", "value": "a"},
    {"format": "Q0.15", "value": 0.1, "rounding": "up"}, {"format": "Q0.15", "raw": 1.5},
])
def test_qcalc_errors_have_chinese(req):
    out = json.loads(qcalc_json(json.dumps(req)))
    assert out["ok"] is False and _zh_ok(out["message"]), out


@settings(max_examples=300, deadline=None)
@given(section=st.sampled_from(["motor", "drive", "conventions", "current_loop", "pll", "raw",
                                "sim"]),
       key=st.sampled_from(["rated_voltage_v", "rs_ohm", "ld_h", "pole_pairs", "udc_v", "ts_s",
                            "base", "method", "kp", "pm_ki", "bandwidth_hz", "Voltage", "LD",
                            "FreqRated01", "base_freq_hz", "current", "pll", "junk"]),
       value=st.none() | st.booleans() | st.floats(allow_nan=True) | st.text(max_size=3)
       | st.integers(-10, 70000) | st.floats(1e-12, 1e12)
       | st.dictionaries(st.sampled_from(["axis", "step_a", "speed_hz", "duration_s", "delay",
                                          "angle_step_deg", "x"]),
                         st.floats(-1e6, 1e6) | st.sampled_from(["d", "q", True]), max_size=3))
def test_fuzzed_messages_all_have_chinese(section, key, value):
    inp = copy.deepcopy(SEED_INPUT)
    inp.setdefault(section, {})[key] = value
    try:
        r = report(inp)
    except InputError as e:
        assert _zh_ok(e.message), e.message
        return
    for w in r["warnings"]:
        assert _zh_ok(w), w
