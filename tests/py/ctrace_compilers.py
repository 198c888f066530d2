"""Run C cases through real compilers (never imports pulab).

``avr``: avr-gcc -mmcu=atmega2560 (16-bit int, 32-bit long, as C28x and MSP430),
run in simavr; results come back on UART0, which simavr echoes to stderr with
colour codes, '.' before each newline, and a line break every 255 characters.
``arm``: the host gcc -m32 (32-bit int and long, as ARM Cortex-M) with
-funsigned-char (ARM's plain char is unsigned).  Both build with -fwrapv, so a
signed overflow is the two's-complement wrap; the vectors exclude the other
undefined behaviour (shift count out of range, INT_MIN / -1, division by zero).

Each program batches many cases, each with its own input table (at most
~30 KB per AVR table and ~60 KB of tables per program, as pgm_read works in
the first 64 KB of flash).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile

import pytest

from ctrace_gen import TYPE_BITS

__all__ = ["available", "run_cases", "run_unit", "run_calls", "Unit", "PRELUDE", "UNIT_PRELUDE"]

#: Firmware type names and IQmath as TI defines them (DSP28x_Project.h, IQmathLib.h);
#: _IQmpy = (long)(((long long)a * b) >> GLOBAL_Q), __IQsat(x, hi, lo) clamps.
PRELUDE = r"""
#include <stdint.h>
#include <string.h>
typedef uint16_t Uint16; typedef int16_t int16; typedef int16_t Int16;
typedef uint32_t Uint32; typedef int32_t int32; typedef int32_t Int32;
typedef int64_t int64; typedef uint64_t Uint64; typedef long Long; typedef unsigned long Ulong;
typedef unsigned int Uint; typedef int Int; typedef long _iq;
#define GLOBAL_Q 24
static long iq_mpy(long a, long b, int q) { return (long)(((long long)a * (long long)b) >> q); }
static long iq_sat(long x, long hi, long lo) { return x > hi ? hi : (x < lo ? lo : x); }
#define _IQmpy(a, b) iq_mpy((a), (b), GLOBAL_Q)
#define __IQmpy(a, b, q) iq_mpy((a), (b), (q))
#define _IQsat(x, hi, lo) iq_sat((x), (hi), (lo))
#define __IQsat(x, hi, lo) iq_sat((x), (hi), (lo))
""" + "".join(f"#define _IQ{q}mpy(a, b) iq_mpy((a), (b), {q})\n" for q in range(1, 31))

_AVR_IO = r"""
#include <avr/io.h>
#include <avr/interrupt.h>
#include <avr/sleep.h>
#include <avr/pgmspace.h>
static void put(char c) { while (!(UCSR0A & (1 << UDRE0))); UDR0 = c; }
#define LOAD(dst, src) memcpy_P(&(dst), &(src), sizeof(dst))
#define TABLE PROGMEM
"""
_HOST_IO = r"""
#include <stdio.h>
static void put(char c) { putchar(c); }
#define LOAD(dst, src) memcpy(&(dst), &(src), sizeof(dst))
#define TABLE
"""
_PUT_HEX = r"""
static void put_hex(uint64_t v, uint8_t bytes) {
  uint8_t b[8]; memcpy(b, &v, 8);  /* both targets are little-endian */
  while (bytes--) { uint8_t x = b[bytes], h = x >> 4, l = x & 15;
    put(h < 10 ? '0' + h : 'a' + h - 10); put(l < 10 ? '0' + l : 'a' + l - 10); }
}
"""

_TABLE_BYTES = 30000
_PROGRAM_TABLE_BYTES = 60000
_PROGRAM_CASES = 40


def require(target: str, capsys) -> None:
    """Skip the test, with a loud line, when ``target``'s compiler is missing; under CI=true
    fail instead (the cross-check is mandatory there)."""
    missing = available(target)
    if not missing:
        return
    hint = "clang gcc-multilib" if target == "clang" else "gcc-avr avr-libc simavr gcc-multilib"
    msg = (f"SKIPPED: compiler cross-check for {target} needs {', '.join(missing)} "
           f"(apt-get install {hint})")
    if os.environ.get("CI") == "true":
        pytest.fail(msg + " — mandatory under CI=true")
    with capsys.disabled():
        print(f"\n\n{'!' * len(msg)}\n{msg}\n{'!' * len(msg)}\n", file=sys.stderr)
    pytest.skip(msg)


def available(target: str) -> list:
    """The missing tools for ``target`` (empty when it can run): the programs, and a compile
    of an empty program (avr-libc's headers; gcc-multilib's 32-bit libraries; for ``clang``,
    the code proof's sanitizer oracle, its 32-bit sanitizer runtime)."""
    tools = {"avr": ["avr-gcc", "simavr"], "clang": ["clang"]}.get(target, ["gcc"])
    missing = [t for t in tools if shutil.which(t) is None]
    if missing:
        return missing
    with tempfile.TemporaryDirectory() as d:
        src = os.path.join(d, "t.c")
        with open(src, "w") as f:
            f.write("#include <stdint.h>\n" + ("#include <avr/io.h>\n" if target == "avr" else "")
                    + "int main(void) { return 0; }\n")
        cmd = {"avr": ["avr-gcc", "-mmcu=atmega2560"],
               "clang": ["clang", "-m32", "-fsanitize=signed-integer-overflow,implicit-conversion"]
               }.get(target, ["gcc", "-m32"])
        if subprocess.run(cmd + [src, "-o", os.path.join(d, "t")], capture_output=True).returncode:
            return ["avr-libc" if target == "avr" else "gcc-multilib"]  # clang's -m32 uses it too
    return []


def _declare(decls: list) -> str:
    """C declarations for (spelling, name); dotted names become struct members."""
    plain, structs = [], {}
    for spelling, name in decls:
        if "." in name:
            head, _, member = name.partition(".")
            structs.setdefault(head, []).append(f"{spelling} {member};")
        else:
            plain.append(f"{spelling} {name};")
    return " ".join(plain + [f"struct {{ {' '.join(m)} }} {h};" for h, m in structs.items()])


def _case_source(k: int, case, vectors: list, target: str) -> str:
    inputs = case.input_decls()
    fields = " ".join(f"{t} f{i};" for i, (t, _) in enumerate(inputs)) or "char unused;"
    rows = []
    for vec in vectors:
        vals = []
        for spelling, name in inputs:
            bits, _ = TYPE_BITS(spelling, target)
            vals.append(f"({spelling})0x{vec[name] & ((1 << bits) - 1):X}ULL")
        rows.append("{" + ", ".join(vals or ["0"]) + "}")
    load = " ".join(f"{name} = in.f{i};" for i, (_, name) in enumerate(inputs))
    prints = " ".join(f"put(' '); put_hex((uint64_t)({name}), sizeof({name}));"
                      for _, name in case.outputs)
    return f"""
struct in_{k} {{ {fields} }};
static const struct in_{k} tbl_{k}[] TABLE = {{ {", ".join(rows)} }};
static void case_{k}(void) {{
  uint16_t i;
  for (i = 0; i < {len(vectors)}; i++) {{
    struct in_{k} in; LOAD(in, tbl_{k}[i]);
    {{ {_declare(case.decls)} {load}
{case.body}
    put('@'); put_hex({k}, 2); put(' '); put_hex(i, 2); {prints} put('\\n'); }}
  }}
}}
"""


def _program(chunks: list, target: str) -> str:
    io = _AVR_IO if target == "avr" else _HOST_IO
    body = "".join(_case_source(k, c, v, target) for k, (c, v) in enumerate(chunks))
    calls = " ".join(f"case_{k}();" for k in range(len(chunks)))
    init = "UCSR0A = 1 << U2X0; UBRR0 = 0; UCSR0B = 1 << TXEN0;" if target == "avr" else ""
    end = "cli(); sleep_cpu();" if target == "avr" else ""
    return f"{PRELUDE}{io}{_PUT_HEX}{body}\nint main(void) {{ {init} {calls} {end} return 0; }}\n"


def _row_bytes(case, target: str) -> int:
    return sum(TYPE_BITS(t, target)[0] // 8 + 1 for t, _ in case.input_decls()) + 2


def _batches(cases: list, target: str) -> list:
    """Split (case, vectors) pairs into programs of table chunks within the size limits."""
    programs, current, size = [], [], 0
    for case, vectors in cases:
        per = max(1, _TABLE_BYTES // _row_bytes(case, target))
        for start in range(0, len(vectors), per):
            chunk = vectors[start:start + per]
            nbytes = len(chunk) * _row_bytes(case, target)
            if current and (size + nbytes > _PROGRAM_TABLE_BYTES or
                            len(current) >= _PROGRAM_CASES):
                programs.append(current)
                current, size = [], 0
            current.append((case, chunk))
            size += nbytes
    if current:
        programs.append(current)
    return programs


def _compile_and_run(chunks: list, target: str, workdir: str, index: int) -> list:
    return _run_program(_program(chunks, target), chunks, target, workdir, index)


def _run_program(text: str, chunks: list, target: str, workdir: str, index: int,
                 flags: tuple = ()) -> list:
    src = os.path.join(workdir, f"p{index}.c")
    exe = os.path.join(workdir, f"p{index}.{'elf' if target == 'avr' else 'out'}")
    with open(src, "w") as f:
        f.write(text)
    if target == "avr":
        cmd = ["avr-gcc", "-mmcu=atmega2560", "-Os", "-fwrapv", "-std=gnu11", "-w", *flags,
               src, "-o", exe, "-lm"]
    else:
        cmd = ["gcc", "-m32", "-O1", "-fwrapv", "-funsigned-char", "-std=gnu11", "-w", *flags,
               src, "-o", exe, "-lm"]
    cc = subprocess.run(cmd, capture_output=True, text=True)
    if cc.returncode:
        raise RuntimeError(f"{cmd[0]} failed on {src}:\n{cc.stderr[:4000]}")
    if target == "avr":
        run = subprocess.run(["simavr", "-m", "atmega2560", "-f", "16000000", exe],
                             capture_output=True, text=True, timeout=300)
        text = re.sub(r"\x1b\[[0-9;]*m", "", run.stderr)
        text = text.replace(".\n", "\x00").replace("\n", "")
        lines = text.split("\x00")
    else:
        run = subprocess.run([exe], capture_output=True, text=True, timeout=300)
        lines = run.stdout.split("\n")
    results: dict = {}
    for line in lines:
        at = line.find("@")
        if at < 0:
            continue
        parts = line[at + 1:].split()
        results[(int(parts[0], 16), int(parts[1], 16))] = parts[2:]
    out = []
    for k, (case, chunk) in enumerate(chunks):
        for i in range(len(chunk)):
            words = results.get((k, i))
            if words is None or len(words) != len(case.outputs):
                raise RuntimeError(f"program {index}: no complete output for case {k} "
                                   f"vector {i}")
            vals = {}
            for (spelling, name), word in zip(case.outputs, words):
                bits, signed = TYPE_BITS(spelling, target)
                v = int(word, 16) & ((1 << bits) - 1)
                if signed and v >> (bits - 1):
                    v -= 1 << bits
                vals[name] = v
            out.append(vals)
    return out


def run_cases(cases: list, target: str, jobs: int = 2) -> tuple:
    """Final values of every output of every (case, vectors) pair, in order.

    Returns (results, programs): results is a list (per case) of lists (per vector)
    of {name: value}; programs is how many programs were compiled and run.
    """
    from concurrent.futures import ThreadPoolExecutor
    programs = _batches(cases, target)
    with tempfile.TemporaryDirectory(prefix=f"ctrace-{target}-") as d:
        with ThreadPoolExecutor(jobs) as pool:
            outs = list(pool.map(lambda a: _compile_and_run(a[1], target, d, a[0]),
                                 enumerate(programs)))
    flat = [v for o in outs for v in o]
    results, pos = [], 0
    for case, vectors in cases:
        results.append(flat[pos:pos + len(vectors)])
        pos += len(vectors)
    return results, len(programs)


class Unit:
    """A translation unit run through one function, for the compilers.

    ``code`` is pasted at file scope unchanged; ``entry`` is called once per vector with
    ``params`` [(C spelling, name)]: a ``T *`` parameter gets the address of a zeroed local
    ``T`` (``name.FIELD`` or ``*name`` inputs and outputs address it), ``T [N]`` a zeroed
    local array (``name[i]``), any other its value.
    ``inputs``/``outputs`` are [(spelling, name)]; names are ``return``, parameter names,
    ``p.FIELD``, ``*p`` and globals (``return.FIELD`` for a struct result, whose C type is
    ``ret``); ``prelude`` is C placed before the code (the vendor type names and IQmath the
    code expects from headers it does not paste).
    """

    def __init__(self, code: str, entry: str, params: list, inputs: list, outputs: list,
                 prelude: str = "", ret: str = "") -> None:
        self.code, self.entry, self.params = code, entry, params
        self.inputs, self.outputs, self.prelude = inputs, outputs, prelude
        self.ret = ret  # the C type of a struct result (return.FIELD outputs)

    def input_decls(self) -> list:
        return self.inputs


def _unit_c_name(unit: Unit, name: str) -> str:
    """The C expression for an input/output name inside the driver."""
    if name == "return" or name.startswith("return."):
        return "ret" + name[6:]
    pointers = {n for s, n in unit.params if s.rstrip()[-1:] in "*]"}
    scalars = {n for s, n in unit.params if s.rstrip()[-1:] not in "*]"}
    if name.startswith("*") and name[1:] in pointers:
        return f"o_{name[1:]}"
    head = re.match(r"\w+", name)[0]
    rest = name[len(head):]
    if head in pointers:
        return f"o_{head}{rest}"
    if head in scalars:
        return f"v_{head}{rest}"
    return name


def _unit_source(unit: Unit, vectors: list, target: str) -> str:
    fields = " ".join(f"{t} f{i};" for i, (t, _) in enumerate(unit.inputs)) or "char unused;"
    rows = []
    for vec in vectors:
        vals = []
        for spelling, name in unit.inputs:
            bits, _ = TYPE_BITS(spelling, target)
            vals.append(f"({spelling})0x{vec[name] & ((1 << bits) - 1):X}ULL")
        rows.append("{" + ", ".join(vals or ["0"]) + "}")
    decls, args = [], []
    for spelling, name in unit.params:
        if spelling.rstrip().endswith("]"):  # T p[N]: an array of N
            base, _, size = spelling.rstrip()[:-1].rpartition("[")
            decls.append(f"{base} o_{name}[{size}]; memset(o_{name}, 0, sizeof o_{name});")
            args.append(f"o_{name}")
        elif spelling.rstrip().endswith("*"):
            base = spelling.rstrip()[:-1]
            decls.append(f"{base} o_{name}; memset(&o_{name}, 0, sizeof o_{name});")
            args.append(f"&o_{name}")
        else:
            decls.append(f"{spelling} v_{name}; memset(&v_{name}, 0, sizeof v_{name});")
            args.append(f"v_{name}")
    load = " ".join(f"{_unit_c_name(unit, n)} = in.f{i};" for i, (_, n) in enumerate(unit.inputs))
    ret = [unit.ret] if unit.ret else [s for s, n in unit.outputs if n == "return"]
    call = f"{ret[0]} ret = {unit.entry}({', '.join(args)});" if ret else \
        f"{unit.entry}({', '.join(args)});"
    prints = " ".join(f"put(' '); put_hex((uint64_t)({_unit_c_name(unit, n)}), "
                      f"sizeof({_unit_c_name(unit, n)}));" for _, n in unit.outputs)
    return f"""
{unit.prelude}
{unit.code}
struct in_0 {{ {fields} }};
static const struct in_0 tbl_0[] TABLE = {{ {", ".join(rows)} }};
static void case_0(void) {{
  uint16_t i;
  for (i = 0; i < {len(vectors)}; i++) {{
    struct in_0 in; LOAD(in, tbl_0[i]);
    {{ {" ".join(decls)} {load} {call}
    put('@'); put_hex(0, 2); put(' '); put_hex(i, 2); {prints} put('\\n'); }}
  }}
}}
"""


#: What a unit gets before its code: the fixed-width types, TI's type names and the IQmath
#: of TI's IQmathLib.h (fixed-point build: _IQN(A) = (long)(A * 2^N), the multiplies, the
#: Q conversions) that the tracer knows without a header.
UNIT_PRELUDE = r"""
#include <stdint.h>
#include <string.h>
#ifndef GLOBAL_Q
#define GLOBAL_Q 24
#endif
static long iq_mpy(long a, long b, int q) { return (long)(((long long)a * (long long)b) >> q); }
#define _IQmpy(a, b) iq_mpy((a), (b), GLOBAL_Q)
#define __IQmpy(a, b, q) iq_mpy((a), (b), (q))
#define _IQsat(x, hi, lo) ((x) > (hi) ? (hi) : ((x) < (lo) ? (lo) : (x)))
#define _IQabs(A) ((long)(A) < 0 ? -(long)(A) : (long)(A))
#define IQ_CAT(a, b) a##b
#define IQ_OF(q, A) IQ_CAT(_IQ, q)(A)
#define _IQ(A) IQ_OF(GLOBAL_Q, A)
typedef long _iq;
typedef uint16_t Uint16; typedef int16_t int16; typedef uint32_t Uint32; typedef int32_t int32;
""" + "".join(f"#define _IQ{q}mpy(a, b) iq_mpy((a), (b), {q})\n"
              f"#define _IQ{q}(A) ((long)((A) * {float(1 << q)!r}L))\n"
              f"#define _IQtoIQ{q}(A) (GLOBAL_Q >= {q} ? (long)(A) >> (GLOBAL_Q - {q}) : "
              f"(long)(A) << ({q} - GLOBAL_Q))\n"
              f"#define _IQ{q}toIQ(A) (GLOBAL_Q >= {q} ? (long)(A) << (GLOBAL_Q - {q}) : "
              f"(long)(A) >> ({q} - GLOBAL_Q))\n"
              f"typedef long _iq{q};\n" for q in range(1, 31)) + "".join(
    f"#define _IQmpy{k}(A) ((A) << {k.bit_length() - 1})\n#define _IQdiv{k}(A) ((A) >> "
    f"{k.bit_length() - 1})\n" for k in (2, 4, 8, 16, 32, 64))


def run_unit(unit: Unit, vectors: list, target: str, flags: tuple = ()) -> list:
    """Final values of ``unit.outputs`` for each vector: a list of {name: value};
    ``flags`` go to the compiler (``-D``, ``-idirafter`` for headers the code names)."""
    io = _AVR_IO if target == "avr" else _HOST_IO
    init = "UCSR0A = 1 << U2X0; UBRR0 = 0; UCSR0B = 1 << TXEN0;" if target == "avr" else ""
    end = "cli(); sleep_cpu();" if target == "avr" else ""
    out = []
    with tempfile.TemporaryDirectory(prefix=f"ctrace-unit-{target}-") as d:
        per = max(1, _TABLE_BYTES // _row_bytes(unit, target))
        for start in range(0, len(vectors), per):
            chunk = vectors[start:start + per]
            text = (f"{UNIT_PRELUDE}{io}{_PUT_HEX}{_unit_source(unit, chunk, target)}\n"
                    f"int main(void) {{ {init} case_0(); {end} return 0; }}\n")
            out += _run_program(text, [(_UnitOutputs(unit.outputs), chunk)], target, d,
                                start, flags)
    return out


class _UnitOutputs:
    def __init__(self, outputs: list) -> None:
        self.outputs = outputs


def run_calls(unit: Unit, rows: list, target: str) -> list:
    """The firmware's own loop: ``unit.entry`` called once per row, in one program, its
    pointer parameters' objects and the by-value arguments kept from call to call (the
    caller's variables); row k assigns only the inputs it names (a bit mask per row) before
    call k.  Returns ``unit.outputs`` after each call: a list of {name: value}."""
    assert len(unit.inputs) <= 32 and len(rows) < 65536
    io = _AVR_IO if target == "avr" else _HOST_IO
    init = "UCSR0A = 1 << U2X0; UBRR0 = 0; UCSR0B = 1 << TXEN0;" if target == "avr" else ""
    end = "cli(); sleep_cpu();" if target == "avr" else ""
    fields = " ".join(f"{t} f{i};" for i, (t, _) in enumerate(unit.inputs))
    table = []
    for row in rows:
        mask, vals = 0, []
        for i, (spelling, name) in enumerate(unit.inputs):
            bits, _ = TYPE_BITS(spelling, target)
            if name in row:
                mask |= 1 << i
            vals.append(f"({spelling})0x{row.get(name, 0) & ((1 << bits) - 1):X}ULL")
        table.append("{" + ", ".join([f"0x{mask:X}UL", *vals]) + "}")
    decls, args = [], []
    for spelling, name in unit.params:
        if spelling.rstrip().endswith("*"):
            decls.append(f"static {spelling.rstrip()[:-1]} o_{name};")
            args.append(f"&o_{name}")
        else:
            decls.append(f"static {spelling} v_{name};")
            args.append(f"v_{name}")
    load = " ".join(f"if (in.mask & (1UL << {i})) {_unit_c_name(unit, n)} = in.f{i};"
                    for i, (_, n) in enumerate(unit.inputs))
    ret = [s for s, n in unit.outputs if n == "return"]
    call = f"{ret[0]} ret = {unit.entry}({', '.join(args)});" if ret else \
        f"{unit.entry}({', '.join(args)});"
    prints = " ".join(f"put(' '); put_hex((uint64_t)({_unit_c_name(unit, n)}), "
                      f"sizeof({_unit_c_name(unit, n)}));" for _, n in unit.outputs)
    text = f"""{UNIT_PRELUDE}{io}{_PUT_HEX}
{unit.prelude}
{unit.code}
struct in_0 {{ uint32_t mask; {fields} }};
static const struct in_0 tbl_0[] TABLE = {{ {", ".join(table)} }};
{" ".join(decls)}
static void case_0(void) {{
  uint16_t i;
  for (i = 0; i < {len(rows)}; i++) {{
    struct in_0 in; LOAD(in, tbl_0[i]);
    {{ {load} {call}
    put('@'); put_hex(0, 2); put(' '); put_hex(i, 2); {prints} put('\\n'); }}
  }}
}}
int main(void) {{ {init} case_0(); {end} return 0; }}
"""
    with tempfile.TemporaryDirectory(prefix=f"ctrace-calls-{target}-") as d:
        return _run_program(text, [(_UnitOutputs(unit.outputs), rows)], target, d, 0)
