"""C2000 integer semantics checked against numpy's fixed-width integers."""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from pulab.fixedpoint.cint import INT16, INT32, UINT16, UINT32, CDivisionByZero, CInt, trunc_div

i32 = st.integers(-(1 << 31), (1 << 31) - 1)
u32 = st.integers(0, (1 << 32) - 1)
u16 = st.integers(0, 0xFFFF)
NP = {INT32: np.int32, UINT32: np.uint32, UINT16: np.uint16, INT16: np.int16}


@pytest.mark.parametrize("a, b, q", [(7, 2, 3), (-7, 2, -3), (7, -2, -3), (-7, -2, 3),
                                     (6, 3, 2), (0, 5, 0)])
def test_trunc_div_rounds_toward_zero(a, b, q):
    assert trunc_div(a, b) == q


@pytest.mark.parametrize("ta, tb, t", [(UINT16, INT16, UINT16), (UINT16, INT32, INT32),
                                       (UINT32, INT32, UINT32), (INT16, INT32, INT32),
                                       (UINT16, UINT32, UINT32)])
def test_usual_arithmetic_conversions_with_16_bit_int(ta, tb, t):
    assert (CInt(1, ta) * CInt(1, tb)).ctype == t


def test_uint16_times_int_is_16_bit_on_c2000():
    # FluxRotor's Voltage*10 (seed 1.4 code): unsigned int arithmetic, wraps at 65536.
    r = CInt(7000, UINT16) * CInt(10, UINT16)
    assert (r.value, r.ctype, r.flags) == (70000 % 65536, UINT16, frozenset({"wrap"}))


def _np_op(t, a, b, op):
    with np.errstate(over="ignore"):
        x = np.array([a], dtype=NP[t])
        y = np.array([b], dtype=NP[t])
        if op == "mul":
            return int((x * y)[0])
        if op == "add":
            return int((x + y)[0])
        if op == "div":  # C quotient from numpy's C-style remainder
            return int(((x - np.fmod(x, y)) // y)[0])


@given(a=i32, b=i32, op=st.sampled_from(["mul", "add"]))
def test_long_mul_add_equal_numpy_and_flag_every_wrap(a, b, op):
    r = CInt(a, INT32) * CInt(b, INT32) if op == "mul" else CInt(a, INT32) + CInt(b, INT32)
    assert r.value == _np_op(INT32, a, b, op)
    exact = a * b if op == "mul" else a + b
    assert ("wrap" in r.flags) == (exact != r.value)


@given(a=u32, b=u32, op=st.sampled_from(["mul", "add"]))
def test_ulong_mul_add_equal_numpy_and_flag_every_wrap(a, b, op):
    r = CInt(a, UINT32) * CInt(b, UINT32) if op == "mul" else CInt(a, UINT32) + CInt(b, UINT32)
    assert r.value == _np_op(UINT32, a, b, op)
    assert ("wrap" in r.flags) == ((a * b if op == "mul" else a + b) != r.value)


@given(a=i32, b=i32.filter(lambda b: b != 0))
def test_long_division_equals_numpy_c_quotient(a, b):
    r = CInt(a, INT32) // CInt(b, INT32)
    assert r.value == _np_op(INT32, a, b, "div")
    assert ("truncation" in r.flags) == (a % b != 0)


@given(a=u32, b=u32.filter(lambda b: b != 0))
def test_ulong_division_equals_numpy(a, b):
    assert (CInt(a, UINT32) // CInt(b, UINT32)).value == int(np.uint32(a) // np.uint32(b))


@given(a=i32, n=st.integers(0, 31))
def test_long_shifts_equal_numpy(a, n):
    with np.errstate(over="ignore"):
        left = int(np.left_shift(np.array([a], np.int32), n)[0])
        right = int(np.right_shift(np.array([a], np.int32), n)[0])  # arithmetic, as C2000 ASR
    sl, sr = CInt(a, INT32) << n, CInt(a, INT32) >> n
    assert (sl.value, sr.value) == (left, right)
    assert ("wrap" in sl.flags) == ((a << n) != left)
    assert ("truncation" in sr.flags) == ((a & ((1 << n) - 1)) != 0)


@given(a=u32, n=st.integers(0, 31))
def test_ulong_shifts_equal_numpy(a, n):
    assert (CInt(a, UINT32) << n).value == int(np.left_shift(np.array([a], np.uint32), n)[0])
    assert (CInt(a, UINT32) >> n).value == a >> n


@given(v=st.integers(-(1 << 40), 1 << 40))
def test_store_to_uint16_is_modulo_65536_like_numpy(v):
    r = CInt.of(v, UINT16)
    assert r.value == int(np.array([v & 0xFFFFFFFFFF], np.int64).astype(np.uint16)[0])
    assert ("wrap" in r.flags) == (v != r.value)


def test_division_by_zero_raises():
    with pytest.raises(CDivisionByZero):
        CInt(1, UINT32) // CInt(0, UINT16)


def test_flags_accumulate_through_an_expression():
    r = ((CInt(1 << 30, UINT32) << 3) + CInt(1, UINT32)) // CInt(2, UINT32)
    assert r.flags == frozenset({"wrap", "truncation"})
    assert r.clean().flags == frozenset()
