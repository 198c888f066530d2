"""Q-format encode/decode: names, ranges, rounding rules, overflow modes."""
import math

import pytest
from hypothesis import assume, given, strategies as st

from pulab.fixedpoint.qformat import QFormat, decode, encode, iqsat, parse_format


@pytest.mark.parametrize("fmt, name, lo, hi", [
    (QFormat(16, 15), "Q0.15", -1.0, 1 - 2 ** -15),
    (QFormat(16, 12), "Q3.12", -8.0, 8 - 2 ** -12),
    (QFormat(32, 24), "Q7.24", -128.0, 128 - 2 ** -24),
    (QFormat(16, 16, signed=False), "UQ0.16", 0.0, 1 - 2 ** -16),
    (QFormat(16, 13, signed=False), "UQ3.13", 0.0, 8 - 2 ** -13),
])
def test_names_and_ranges(fmt, name, lo, hi):
    assert (fmt.name, fmt.min_value, fmt.max_value) == (name, lo, hi)
    assert parse_format(name) == fmt


@pytest.mark.parametrize("x, rounding, raw", [
    (2.5, "nearest", 3), (-2.5, "nearest", -3), (2.5, "convergent", 2), (3.5, "convergent", 4),
    (-2.5, "convergent", -2), (2.7, "floor", 2), (-2.2, "floor", -3), (-2.7, "zero", -2),
    (2.7, "zero", 2), (2.4, "nearest", 2),
])
def test_rounding_rules_on_q0(x, rounding, raw):
    assert encode(x, QFormat(16, 0), rounding).raw == raw


@pytest.mark.parametrize("x, overflow, raw, flag", [
    (1.0, "saturate", 32767, "saturate"), (-1.5, "saturate", -32768, "saturate"),
    (1.0, "wrap", -32768, "wrap"), (1.25, "wrap", -24576, "wrap"),
])
def test_overflow_modes_q15(x, overflow, raw, flag):
    e = encode(x, QFormat(16, 15), overflow=overflow)
    assert (e.raw, flag in e.flags) == (raw, True)


def test_overflow_error_raises():
    with pytest.raises(OverflowError):
        encode(2.0, QFormat(16, 15), overflow="error")


fmts = st.builds(lambda w, n, s: QFormat(w, min(n, w - (1 if s else 0)), s),
                 st.integers(2, 40), st.integers(0, 40), st.booleans())


@given(fmt=fmts, u=st.floats(0, 1), rounding=st.sampled_from(["nearest", "convergent"]))
def test_round_trip_within_half_lsb(fmt, u, rounding):
    x = fmt.min_value + u * (fmt.max_value - fmt.min_value)
    e = encode(x, fmt, rounding)
    assert abs(e.value - x) <= fmt.resolution / 2
    assert ("rounded" in e.flags) == (e.value != x)


@given(fmt=fmts, u=st.floats(0, 1), rounding=st.sampled_from(["floor", "zero"]))
def test_directed_rounding_within_one_lsb_and_directed(fmt, u, rounding):
    x = fmt.min_value + u * (fmt.max_value - fmt.min_value)
    v = encode(x, fmt, rounding).value
    assert abs(v - x) < fmt.resolution
    assert v <= x if rounding == "floor" else abs(v) <= abs(x)


@given(fmt=fmts, data=st.data())
def test_decode_encode_is_identity_on_integers(fmt, data):
    raw = data.draw(st.integers(fmt.raw_min, fmt.raw_max))
    assume(abs(raw) < 2 ** 53)
    assert encode(decode(raw, fmt), fmt).raw == raw


def test_iqsat_clamps():
    assert [iqsat(x, 10, -10) for x in (-11, -10, 0, 10, 11)] == [-10, -10, 0, 10, 10]


def test_resolution():
    assert QFormat(32, 24).resolution == math.ldexp(1, -24)
