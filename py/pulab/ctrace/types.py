"""C integer types of each target, the firmware's type names, and C's conversions.

A type is a :class:`pulab.fixedpoint.cint.CType` named by its canonical C spelling
(``unsigned long``); its conversion rank (C99 6.3.1.1) is looked up from
that name.  Widths per target:

======= ==== ===== ==== ===== =========
target  char short int  long  long long
======= ==== ===== ==== ===== =========
c28x    16   16    16   32    64
avr     8    16    16   32    64
msp430  8    16    16   32    64
arm     8    16    32   32    64
======= ==== ===== ==== ===== =========

Examples
--------
>>> c28x, arm = TARGETS["c28x"], TARGETS["arm"]
>>> c28x.type_named("Uint16").name, arm.type_named("Uint16").name
('unsigned int', 'unsigned short')
>>> common_type(c28x, c28x.type_named("Uint16"), c28x.type_named("int")).name
'unsigned int'
>>> common_type(arm, arm.type_named("Uint16"), arm.type_named("int")).name
'int'
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..fixedpoint.cint import CType

__all__ = ["Target", "TARGETS", "rank", "promote", "common_type", "BASE_TYPE_WORDS"]

_RANK = {"_Bool": 0, "char": 1, "short": 2, "int": 3, "long": 4, "long long": 5}

#: Words that may make up a base type spelling (``unsigned long long int``).
BASE_TYPE_WORDS = frozenset({"signed", "unsigned", "char", "short", "int", "long"})


def rank(t: CType) -> int:
    """Integer conversion rank: char 1 < short 2 < int 3 < long 4 < long long 5."""
    name = t.name
    if name.startswith("unsigned "):
        name = name[9:]
    elif name.startswith("signed "):
        name = name[7:]
    return _RANK[name]


@dataclass(frozen=True)
class Target:
    """A compiler's integer model.

    Parameters
    ----------
    name : str
    char_bits, int_bits : int in {8, 16, 32}
    char_signed : bool
        Whether plain ``char`` is signed.
    double_bits : {64, 32}
        The width of ``double`` (avr-gcc's is 32 bits): the precision ``_IQ(…)`` folds in.
    predefined : tuple of (name, body)
        The macros the target's compiler defines before any code (``-U`` removes one).
    """

    name: str
    char_bits: int
    int_bits: int
    char_signed: bool
    double_bits: int = 64
    predefined: tuple = ()
    types: dict = field(init=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        bits = {"char": self.char_bits, "short": 16, "int": self.int_bits, "long": 32,
                "long long": 64}
        names = {"char": CType("char", self.char_bits, self.char_signed),
                 "signed char": CType("signed char", self.char_bits, True),
                 # C99 6.3.1.2: converting to _Bool gives 1 for any non-zero value
                 "_Bool": CType("_Bool", self.char_bits, False)}
        for base, b in bits.items():
            if base != "char":
                names[base] = CType(base, b, True)
            names["unsigned " + base] = CType("unsigned " + base, b, False)
        # The exact-width names as each compiler's <stdint.h> defines them.
        exact = {8: "signed char", 16: "int" if self.int_bits == 16 else "short",
                 32: "int" if self.int_bits == 32 else "long", 64: "long long"}
        for b, signed_name in exact.items():
            if b == 8 and self.char_bits != 8:
                continue  # C28x has no 8-bit type: int8_t does not exist there
            names[f"int{b}_t"] = names[signed_name]
            names[f"uint{b}_t"] = names["unsigned " + signed_name.replace("signed ", "")]
        # The least- and fast-width names: least = exact width (int16 for 8 on C28x);
        # fast as avr-gcc, TI C2000 and gcc -m32/arm-none-eabi define them (int for 16).
        small = "signed char" if self.char_bits == 8 else "int"
        fast = {8: small, 16: "int", 32: "long" if self.int_bits == 16 else "int",
                64: "long long"}
        for b in (8, 16, 32, 64):
            least = exact[b] if b > 8 else small
            for kind, name in (("least", least), ("fast", fast[b])):
                names[f"int_{kind}{b}_t"] = names[name]
                names[f"uint_{kind}{b}_t"] = names["unsigned " + name.replace("signed ", "")]
        names["intmax_t"], names["uintmax_t"] = names["long long"], names["unsigned long long"]
        # Firmware spellings (TI's DSP28x_Project.h, Inovance's typedefs).
        firmware = {"int16": "int16_t", "Int16": "int16_t", "Uint16": "uint16_t",
                    "int32": "int32_t", "Int32": "int32_t", "Uint32": "uint32_t",
                    "int64": "int64_t", "Int64": "int64_t", "Uint64": "uint64_t",
                    "Long": "long", "Ulong": "unsigned long", "ULong": "unsigned long",
                    "Uint": "unsigned int", "Int": "int", "_iq": "long",
                    # Simulink Embedded Coder's rtwtypes.h and NXP RTCESL's mlib_types.h
                    "int16_T": "int16_t", "uint16_T": "uint16_t", "int32_T": "int32_t",
                    "uint32_T": "uint32_t", "boolean_T": "unsigned char",
                    "frac16_t": "int16_t", "frac32_t": "int32_t", "acc16_t": "int16_t",
                    "acc32_t": "int32_t"}
        for alias, real in firmware.items():
            names[alias] = names[real]
        for q in range(1, 31):
            names[f"_iq{q}"] = names["long"]
        object.__setattr__(self, "types", names)

    def limits(self) -> dict:
        """``<limits.h>`` on this target: macro name → body text, as the headers write them
        (a minimum is ``-MAX - 1`` so that it keeps a signed type)."""
        t = self.types
        out = {"CHAR_BIT": str(self.char_bits), "MB_LEN_MAX": "1"}
        for prefix, name, suffix in (("SCHAR", "signed char", ""), ("SHRT", "short", ""),
                                     ("INT", "int", ""), ("LONG", "long", "L"),
                                     ("LLONG", "long long", "LL")):
            mx = t[name].max
            out[f"{prefix}_MAX"] = f"{mx}{suffix}"
            out[f"{prefix}_MIN"] = f"(-{mx}{suffix} - 1)"
        for prefix, name, suffix in (("UCHAR", "unsigned char", ""), ("USHRT", "unsigned short", ""),
                                     ("UINT", "unsigned int", "U"), ("ULONG", "unsigned long", "UL"),
                                     ("ULLONG", "unsigned long long", "ULL")):
            out[f"{prefix}_MAX"] = f"{t[name].max}{suffix}"
        c = t["char"]
        out["CHAR_MAX"], out["CHAR_MIN"] = (out["SCHAR_MAX"], out["SCHAR_MIN"]) if c.signed \
            else (out["UCHAR_MAX"], "0")
        return out

    def type_named(self, name: str) -> CType:
        """The type a spelling denotes; ``KeyError`` when unknown on this target."""
        return self.types[name]


TARGETS = {
    # TI cl2000 22.6.0.LTS (its version as MMMmmmppp), no __GNUC__
    "c28x": Target("c28x", 16, 16, True, predefined=(
        ("__TMS320C2000__", "1"), ("__TMS320C28XX__", "1"),
        ("__TI_COMPILER_VERSION__", "22006000"))),
    # avr-gcc 5.4.0 (Debian/Ubuntu's gcc-avr, the cross-check's compiler)
    "avr": Target("avr", 8, 16, True, double_bits=32, predefined=(
        ("__AVR__", "1"), ("__GNUC__", "5"))),
    # TI's MSP430-GCC 9.3.1
    "msp430": Target("msp430", 8, 16, True, predefined=(("__MSP430__", "1"), ("__GNUC__", "9"))),
    # Arm GNU Toolchain 13 (arm-none-eabi-gcc)
    "arm": Target("arm", 8, 32, False, predefined=(("__arm__", "1"), ("__GNUC__", "13"))),
}


def promote(target: Target, t: CType) -> CType:
    """Integer promotions (C99 6.3.1.1): below ``int`` rank to ``int`` if it holds every value."""
    if rank(t) >= 3:
        return t
    if t.bits < target.int_bits or (t.signed and t.bits == target.int_bits):
        return target.types["int"]
    return target.types["unsigned int"]


def common_type(target: Target, a: CType, b: CType) -> CType:
    """The usual arithmetic conversions (C99 6.3.1.8) for two integer types."""
    a, b = promote(target, a), promote(target, b)
    if a == b:
        return a
    if a.signed == b.signed:
        return a if rank(a) >= rank(b) else b
    u, s = (a, b) if not a.signed else (b, a)
    if rank(u) >= rank(s):
        return u
    if s.bits > u.bits:
        return s
    return target.types["unsigned " + s.name]
