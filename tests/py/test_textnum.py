"""Typed numbers (pulab.schema.textnum) and the Q calculator's readings: hex, register values, IQmath."""
import pytest

from pulab import InputError
from pulab.qcalc import qcalc
from pulab.schema.textnum import parse_int, parse_real, si_text


@pytest.mark.parametrize("text, want", [
    ("１７", 17.0), ("０．５", 0.5), ("０。５", 0.5), ("－２", -2.0), ("−2", -2.0), ("1,5", 1.5),
    ("６ｅ－４", 6e-4), (" 1.5 ", 1.5), (3, 3.0)])
def test_parse_real(text, want):
    assert parse_real(text, "x") == want


@pytest.mark.parametrize("text", ["1,500", "abc", "1.2.3", "1e999", "", True, None, "0x10"])
def test_parse_real_refuses(text):
    with pytest.raises(InputError) as e:
        parse_real(text, "f.x")
    assert e.value.field == "f.x"


@pytest.mark.parametrize("text, want", [
    ("0x8000", 32768), ("0X7fff", 32767), ("０ｘ８０００", 32768), ("40000", 40000), ("-1", -1),
    ("0b1010", 10), (12, 12), (12.0, 12)])
def test_parse_int(text, want):
    assert parse_int(text, "raw") == want


@pytest.mark.parametrize("req, raw, value, flags", [
    ({"format": "Q15", "raw": "0x8000"}, -32768, -1.0, ["unsigned_register"]),
    ({"format": "Q15", "raw": 40000}, 40000 - 65536, (40000 - 65536) / 32768, ["unsigned_register"]),
    ({"format": "Q0.15", "raw": "0x4000"}, 16384, 0.5, []),
    ({"format": "UQ1.15", "raw": 40000}, 40000, 40000 / 32768, []),
    ({"format": "iq24", "raw": "0x01000000"}, 1 << 24, 1.0, []),
    ({"format": "_IQ15", "raw": 32768}, 32768, 1.0, []),  # 32-bit long: no register wrap
    ({"format": "_iq", "raw": 1 << 24}, 1 << 24, 1.0, []),  # GLOBAL_Q = 24
])
def test_qcalc_decode_readings(req, raw, value, flags):
    r = qcalc(req)["result"]
    assert (r["raw"], r["value"], r["flags"]) == (raw, value, flags)


def test_qcalc_iqmath_names_are_32_bit():
    for name in ("iq24", "IQ24", "_IQ24", "_iq24"):
        f = qcalc({"format": name, "value": 1.5})["format"]
        assert (f["name"], f["word_bits"]) == ("Q7.24", 32)


def test_qcalc_full_width_value():
    assert qcalc({"format": "Ｑ０．１５", "value": "０。５"})["result"]["raw"] == 16384


@pytest.mark.parametrize("req, field", [
    ({"format": "Q15", "raw": 65536}, "qcalc.raw"), ({"format": "Q15", "raw": "0xZZ"}, "qcalc.raw"),
    ({"format": "Q15", "raw": "1.5"}, "qcalc.raw"), ({"format": "iqx"}, "qcalc.format"),
    ({"format": "Q15", "value": "1,500"}, "qcalc.value")])
def test_qcalc_errors_name_the_field(req, field):
    with pytest.raises(InputError) as e:
        qcalc(req)
    assert e.value.field == field


@pytest.mark.parametrize("value, unit, sig, text", [
    (1.06e-05, "H", 6, "10.6 µH"),             # the Lq
    (0.0011, "Ω", 6, "1.1 mΩ"),
    (6.25e-05, "s", 6, "62.5 µs"),
    (1.03e-05, "H", 6, "10.3 µH"),
    (0.0002315, "H", 6, "231.5 µH"),
    (113.13708498984761, "V", 6, "113.137 V"),  # 80·√2: six digits, not the double's 17
    (655.35, "Hz", 6, "655.35 Hz"),
    (3266.6666666666665, "Hz", 6, "3.26667 kHz"),
    (999.9996, "V", 6, "1 kV"),                 # rounding carries into the next prefix
    (12345678.0, "Hz", 6, "12.3457 MHz"),
    (100.0, "V", 6, "100 V"),
    (2e-04, "s", 6, "200 µs"),
    (-0.0025, "A", 6, "-2.5 mA"),
    (0.0, "H", 6, "0 H"),
    (-0.0, "H", 6, "0 H"),
    (1e-13, "H", 6, "0.1 pH"),                  # below pico: the smallest prefix
    (2.5e12, "Hz", 6, "2500 GHz"),              # above giga: the largest
    (0.05177344693115979, "Ω", 4, "51.77 mΩ"),
    (1.5, "", 6, "1.5"),                        # no unit: no prefix
    (1500.0, "", 6, "1500"),
    (float("inf"), "V", 6, "inf V"),
])
def test_si_text_writes_a_prefix_the_unit_and_the_shortest_digits(value, unit, sig, text):
    assert si_text(value, unit, sig) == text
