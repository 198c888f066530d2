"""Every message the core can produce has Chinese text (the page shows both languages), and an
error reply's text is its code and params rendered by the one catalog.

Fuzzed inputs are checked for this too, in test_report.py."""
import json

import pytest

from conftest import ROOT, chinese
from pulab import report
from pulab.api import call_json
from pulab.schema.catalog import render

ERRORS = json.loads((ROOT / "tests/golden/errors.json").read_text())
GOLDEN = sorted((ROOT / "tests/golden").glob("*.json"))


@pytest.mark.parametrize("case", ERRORS, ids=lambda c: c["field"])
def test_every_golden_error_has_chinese(case):
    out = json.loads(call_json("report", json.dumps(case["input"])))
    assert out["ok"] is False and chinese(out["message_zh"]), out
    assert out["message"] == render(out["code"], out["params"], "en")
    assert out["message_zh"] == render(out["code"], out["params"], "zh")
    assert out["code"] != "text", out  # every input error of a report has a catalog code


@pytest.mark.parametrize("path", [p for p in GOLDEN if p.name != "errors.json"], ids=lambda p: p.stem)
def test_every_golden_warning_has_chinese(path):
    r = report(json.loads(path.read_text())["input"])
    assert len(r["warnings_zh"]) == len(r["warnings"])
    for w in r["warnings_zh"]:
        assert chinese(w), w


@pytest.mark.parametrize("req", [
    {"format": "Qx"}, {"format": "Q15", "word_bits": 8}, {"format": "Q40.30"},
    {"format": "Q15", "word_bits": "8"}, {"format": "Q0.15", "value": 2.0, "overflow": "error"},
    {"format": "Q0.15", "raw": 70000}, {"format": "Q0.15", "value": "a"},
    {"format": "Q0.15", "raw": "0xZZ"}, {"format": "Q0.15", "value": "1,500"},
    {"format": "Q0.15", "value": 0.1, "rounding": "up"}, {"format": "Q0.15", "raw": 1.5},
])
def test_qcalc_errors_have_chinese(req):
    out = json.loads(call_json("qcalc", json.dumps(req)))
    assert out["ok"] is False and chinese(out["message_zh"]) and out["code"] != "text", out
