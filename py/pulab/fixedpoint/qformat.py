"""Fixed-point Q formats: encode, decode, range, resolution and ``__IQsat``.

A format is named the way the fixed-point world does: ``Qm.n`` for a signed
word with m integer bits besides the sign bit and n fractional bits (word =
1 + m + n), ``UQm.n`` for an unsigned word (word = m + n).  The firmware's
"Q12 in a long" is ``Q19.12``; "Q15 in a Uint16" is ``UQ1.15``.

Rounding: ``nearest`` (ties away from zero), ``convergent`` (ties to even),
``floor``, ``zero``.  Overflow: ``saturate``, ``wrap``, ``error``.  Rounding is
done on the exact rational value of the float, so no double rounding occurs.

Examples
--------
>>> f = QFormat(16, 15)
>>> f.name, f.min_value, f.max_value
('Q0.15', -1.0, 0.999969482421875)
>>> encode(0.5, f).raw
16384
>>> encode(1.0, f).raw, encode(1.0, f).flags
(32767, ['saturate'])
>>> encode(1.0, f, overflow="wrap").raw
-32768
>>> decode(16384, f)
0.5
>>> iqsat(70000, 65536, -65536)
65536
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

__all__ = ["QFormat", "QEncoded", "encode", "decode", "iqsat", "round_half_away", "round_rational",
           "parse_format", "ROUNDINGS", "OVERFLOWS"]

ROUNDINGS = ("nearest", "convergent", "floor", "zero")
OVERFLOWS = ("saturate", "wrap", "error")


@dataclass(frozen=True)
class QFormat:
    """A two's-complement or unsigned fixed-point format.

    Parameters
    ----------
    word_bits : int, 2..64
        Width of the stored integer.
    frac_bits : int, 0..word_bits
        Number of fractional bits n; the value is ``raw / 2**n``.
    signed : bool
    """

    word_bits: int
    frac_bits: int
    signed: bool = True

    def __post_init__(self) -> None:
        if not 2 <= self.word_bits <= 64:
            raise ValueError("word_bits must be 2..64")
        if not 0 <= self.frac_bits <= self.word_bits - (1 if self.signed else 0):
            raise ValueError("frac_bits must be 0..word_bits (minus the sign bit)")

    @property
    def int_bits(self) -> int:
        return self.word_bits - self.frac_bits - (1 if self.signed else 0)

    @property
    def name(self) -> str:
        return f"{'' if self.signed else 'U'}Q{self.int_bits}.{self.frac_bits}"

    @property
    def raw_min(self) -> int:
        return -(1 << (self.word_bits - 1)) if self.signed else 0

    @property
    def raw_max(self) -> int:
        return (1 << (self.word_bits - 1 if self.signed else self.word_bits)) - 1

    @property
    def resolution(self) -> float:
        """Value of one LSB, ``2**-n``."""
        return math.ldexp(1.0, -self.frac_bits)

    @property
    def min_value(self) -> float:
        return math.ldexp(self.raw_min, -self.frac_bits)

    @property
    def max_value(self) -> float:
        return math.ldexp(self.raw_max, -self.frac_bits)


def parse_format(name: str, word_bits: int | None = None) -> QFormat:
    """Parse ``Qm.n``, ``UQm.n`` or the short ``Qn`` (needs ``word_bits``).

    >>> parse_format("Q3.12").word_bits
    16
    >>> parse_format("Q24", 32).name
    'Q7.24'
    """
    s = name.strip()
    signed = not s.upper().startswith("UQ")
    body = s[2:] if not signed else s[1:]
    if not s.upper().startswith(("Q", "UQ")) or not body:
        raise ValueError(f"not a Q format name: {name!r}")
    if "." in body:
        m, n = (int(p) for p in body.split(".", 1))
        return QFormat(m + n + (1 if signed else 0), n, signed)
    if word_bits is None:
        raise ValueError("short name Qn needs word_bits")
    return QFormat(word_bits, int(body), signed)


def round_half_away(x) -> int:
    """Round to nearest, ties away from zero (not Python's banker's ``round``): the rounding of
    the firmwares' own float-to-integer code.

    >>> round_half_away(2.5), round_half_away(-2.5), round_half_away(-2.4)
    (3, -3, -2)
    """
    if not isinstance(x, (int, float)):
        return x.round_half_away()  # an interval of reals (pulab.fixedpoint.interval)
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def round_rational(x: Fraction, rounding: str) -> int:
    """Round an exact rational to an integer by the named rule."""
    if rounding == "floor":
        return math.floor(x)
    if rounding == "zero":
        return math.trunc(x)
    lo = math.floor(x)
    rest = x - lo
    if rest > Fraction(1, 2):
        return lo + 1
    if rest < Fraction(1, 2):
        return lo
    if rounding == "nearest":  # ties away from zero
        return lo + 1 if x > 0 else lo
    if rounding == "convergent":  # ties to even
        return lo if lo % 2 == 0 else lo + 1
    raise ValueError(f"unknown rounding {rounding!r}; one of {', '.join(ROUNDINGS)}")


@dataclass(frozen=True)
class QEncoded:
    """Result of :func:`encode`.

    Attributes
    ----------
    raw : int
        The stored integer.
    value : float
        What ``raw`` means, ``raw / 2**n``.
    error : float
        ``value - x``, the quantization (and overflow) error in real units.
    flags : list of str
        ``rounded`` when x was not exactly representable, ``saturate`` or ``wrap``
        when it was out of range.
    """

    raw: int
    value: float
    error: float
    flags: list


def encode(x: float, fmt: QFormat, rounding: str = "nearest",
           overflow: str = "saturate") -> QEncoded:
    """Quantize a real number into ``fmt``.

    Parameters
    ----------
    x : float, finite
    fmt : QFormat
    rounding : {'nearest', 'convergent', 'floor', 'zero'}
    overflow : {'saturate', 'wrap', 'error'}
        ``error`` raises :class:`OverflowError` when x is out of range.
    """
    if rounding not in ROUNDINGS:
        raise ValueError(f"unknown rounding {rounding!r}; one of {', '.join(ROUNDINGS)}")
    if overflow not in OVERFLOWS:
        raise ValueError(f"unknown overflow {overflow!r}; one of {', '.join(OVERFLOWS)}")
    if not math.isfinite(x):
        raise ValueError("value must be finite")
    scaled = Fraction(x) * (1 << fmt.frac_bits)
    r = round_rational(scaled, rounding)
    flags = ["rounded"] if r != scaled else []
    if r > fmt.raw_max or r < fmt.raw_min:
        if overflow == "error":
            raise OverflowError(f"{x} is outside {fmt.name} [{fmt.min_value}, {fmt.max_value}]")
        if overflow == "saturate":
            r = min(max(r, fmt.raw_min), fmt.raw_max)
            flags.append("saturate")
        else:
            span = 1 << fmt.word_bits
            r = (r - fmt.raw_min) % span + fmt.raw_min
            flags.append("wrap")
    value = decode(r, fmt)
    return QEncoded(r, value, value - x, flags)


def decode(raw: int, fmt: QFormat) -> float:
    """The real value of a stored integer, ``raw / 2**n`` (exact for |raw| < 2**53)."""
    if not fmt.raw_min <= raw <= fmt.raw_max:
        raise ValueError(f"{raw} is outside the {fmt.name} integer range")
    return math.ldexp(raw, -fmt.frac_bits)


def iqsat(x: int, max_value: int, min_value: int) -> int:
    """TI IQmath ``__IQsat(x, max, min)``: clamp x into [min, max]."""
    return max_value if x > max_value else min_value if x < min_value else x
