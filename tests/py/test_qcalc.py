"""pulab.qcalc: the Q calculator's request → reply, checked against exact rational arithmetic
(fractions, no pulab) and the register conventions of 16- and 32-bit words."""
import math
import random
from fractions import Fraction

import pytest

from pulab.qcalc import qcalc
from pulab.schema.errors import InputError


def _nearest(x: Fraction) -> int:
    """Round half away from zero, exactly."""
    n = math.floor(abs(x) + Fraction(1, 2))
    return n if x >= 0 else -n


@pytest.mark.parametrize("name, word, frac, signed", [
    ("Q0.15", 16, 15, True), ("Q3.12", 16, 12, True), ("UQ0.16", 16, 16, False),
    ("Q15", 16, 15, True), ("iq24", 32, 24, True), ("_IQ15", 32, 15, True), ("Q19.12", 32, 12, True),
])
def test_encode_is_exact_rounding_with_saturation(name, word, frac, signed):
    lo, hi = (-(1 << (word - 1)), (1 << (word - 1)) - 1) if signed else (0, (1 << word) - 1)
    rng = random.Random(word * 100 + frac)
    for _ in range(300):
        x = rng.uniform(lo, hi) / (1 << frac) * 1.2
        out = qcalc({"format": name, "value": x})
        want = _nearest(Fraction(x) * (1 << frac))
        clamped = min(max(want, lo), hi)
        assert out["result"]["raw"] == clamped, (name, x)
        assert ("saturate" in out["result"]["flags"]) == (want != clamped)
        assert out["result"]["value"] == clamped / (1 << frac)
        assert out["result"]["hex"] == f"0x{clamped & ((1 << word) - 1):0{word // 4}X}"
    f = out["format"]
    assert (f["word_bits"], f["frac_bits"], f["signed"]) == (word, frac, signed)
    assert (f["min"], f["max"], f["resolution"]) == (lo / (1 << frac), hi / (1 << frac), 2.0 ** -frac)


def test_the_page_default_and_its_decode():
    # 0.229242018648822·2^12 = 938.97 → 939 = 0x03AB; 939/4096 = 0.229248046875
    out = qcalc({"format": "Q3.12", "value": 0.229242018648822})
    assert (out["result"]["raw"], out["result"]["hex"]) == (939, "0x03AB")
    back = qcalc({"format": "Q3.12", "raw": 939})["result"]
    assert (back["value"], back["error"], back["flags"]) == (0.229248046875, 0.0, [])


@pytest.mark.parametrize("raw, value, flags", [
    ("0x8000", -1.0, ["unsigned_register"]),      # a Uint16 register read as Q15: two's complement
    (40000, (40000 - 65536) / 32768, ["unsigned_register"]),
    ("0b0100000000000000", 0.5, []),
    (-32768, -1.0, []),
])
def test_register_readings(raw, value, flags):
    r = qcalc({"format": "Q15", "raw": raw})["result"]
    assert (r["value"], r["flags"]) == (value, flags)


@pytest.mark.parametrize("rounding, x, raw", [
    ("nearest", 2.5 / 4096, 3), ("convergent", 2.5 / 4096, 2), ("floor", -0.5 / 4096, -1),
    ("zero", -0.5 / 4096, 0), ("nearest", -2.5 / 4096, -3), ("convergent", 3.5 / 4096, 4),
])
def test_rounding_rules(rounding, x, raw):
    assert qcalc({"format": "Q3.12", "value": x, "rounding": rounding})["result"]["raw"] == raw


def test_overflow_rules():
    assert qcalc({"format": "Q0.15", "value": 1.0, "overflow": "wrap"})["result"]["raw"] == -32768
    with pytest.raises(InputError) as e:
        qcalc({"format": "Q0.15", "value": 1.0, "overflow": "error"})
    assert (e.value.field, e.value.code) == ("qcalc.value", "q_outside")


@pytest.mark.parametrize("req, field, code", [
    ([], "qcalc", "not_object"),
    ({"format": 15}, "qcalc.format", "not_string"),
    ({"format": "Qx"}, "qcalc.format", "not_q_format"),
    ({"format": "Q40"}, "qcalc.format", "q_too_wide"),
    ({"format": "Q15", "word_bits": True}, "qcalc.word_bits", "not_integer"),
    ({"format": "Q15", "value": 0.5, "rounding": "up"}, "qcalc.rounding", "not_choice"),
    ({"format": "Q15", "value": 0.5, "overflow": ["wrap"]}, "qcalc.overflow", "not_choice"),
    ({"format": "Q15", "raw": 70000}, "qcalc.raw", "raw_range_for"),
    ({"format": "UQ0.16", "raw": -1}, "qcalc.raw", "raw_range_for"),
    ({"format": "Q15"}, "qcalc.value", None),
])
def test_bad_requests_name_the_field(req, field, code):
    with pytest.raises(InputError) as e:
        qcalc(req)
    assert e.value.field == field and (code is None or e.value.code == code), (e.value.field, e.value.code)
