"""Exhaustive enumeration of small C routines under clang's sanitizers (never imports pulab).

Each unit of ``prove_units/`` is compiled with ``clang -m32 -funsigned-char`` (32-bit int and
long, unsigned plain char: the tracer's ``arm`` target) and
``-fsanitize=signed-integer-overflow,unsigned-integer-overflow,implicit-conversion,shift,
integer-divide-by-zero,bounds`` with no recovery, so a run stops at the first failure.  The
harness calls the routine for every point of a box in order, printing the point's index
before each call; when a run stops, the failure is the last index's, and the next run starts
after it.  So each point's *first* failing line is known (after a failure C and the tracer
may differ: x86 masks a shift count, a zero divisor traps).

``left shift of negative value`` is not counted: ISO C leaves it undefined but every target
the tracer models shifts the two's-complement bits, and the tracer flags only a result that
does not fit.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

UNITS_DIR = Path(__file__).parent / "prove_units"

#: unit → (entry, [(input name as the tracer names it, C type, by pointer)])
UNITS = {
    "q15_multiply": ("q15_multiply", [("a", "int16_t", False), ("b", "int16_t", False)]),
    "pi_saturated": ("pi_saturated", [("e", "int16_t", False), ("kp", "int16_t", False),
                                      ("ki", "int16_t", False), ("*integ", "int32_t", True)]),
    "sum_store": ("sum_store", [("a", "int16_t", False), ("b", "int16_t", False),
                                ("c", "int16_t", False)]),
    "variable_shift": ("variable_shift", [("x", "int32_t", False), ("n", "int16_t", False)]),
    "gain_table": ("gain_table", [("num", "int16_t", False), ("den", "int16_t", False),
                                  ("k", "int16_t", False)]),
    "sector_switch": ("sector_switch", [("a", "int16_t", False), ("b", "int16_t", False)]),
}

SANITIZE = ("signed-integer-overflow,unsigned-integer-overflow,implicit-conversion,shift,"
            "integer-divide-by-zero,bounds")
_ERROR = re.compile(r"^(?P<file>[^:\n]+\.c):(?P<line>\d+):(?P<col>\d+): "
                    r"runtime error: (?P<what>.*)$", re.M)


def source(unit: str) -> str:
    return (UNITS_DIR / f"{unit}.c").read_text()


def _harness(unit: str) -> str:
    entry, params = UNITS[unit]
    n = len(params)
    decl = "".join(f"  {t} v{i} = ({t})(lo[{i}] + (long long)(k / stride[{i}] % span[{i}]));\n"
                   for i, (_, t, _) in enumerate(params))
    args = ", ".join(f"&v{i}" if ptr else f"v{i}" for i, (_, _, ptr) in enumerate(params))
    return f"""#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "{UNITS_DIR / unit}.c"
int main(int argc, char **argv) {{
  long long lo[{n}], span[{n}], stride[{n}], total = 1;
  for (int i = {n - 1}; i >= 0; i--) {{
    lo[i] = atoll(argv[1 + 2 * i]);
    span[i] = atoll(argv[2 + 2 * i]) - lo[i] + 1;
    stride[i] = total;
    total *= span[i];
  }}
  for (long long k = atoll(argv[{1 + 2 * n}]); k < total; k++) {{
    printf("P %lld\\n", k);
    fflush(stdout);
{decl}    {entry}({args});
  }}
  return 0;
}}
"""


class Oracle:
    """A compiled unit; :meth:`first_failures` enumerates a box."""

    def __init__(self, unit: str, workdir: str) -> None:
        self.unit = unit
        self.params = UNITS[unit][1]
        src = os.path.join(workdir, f"{unit}_harness.c")
        Path(src).write_text(_harness(unit))
        self.exe = os.path.join(workdir, unit)
        subprocess.run(["clang", "-m32", "-funsigned-char", "-O0", "-g", "-w",
                        f"-fsanitize={SANITIZE}", "-fno-sanitize-recover=all", src, "-o",
                        self.exe], check=True, capture_output=True)

    def first_failures(self, box: dict) -> dict:
        """Point index → (line, what) of its first failure, for every failing point of ``box``
        (input name → (lo, hi)), enumerated with the last input varying fastest."""
        bounds = [str(v) for name, _, _ in self.params for v in box[name]]
        total = 1
        for name, _, _ in self.params:
            total *= box[name][1] - box[name][0] + 1
        out, start = {}, 0
        while start < total:
            r = subprocess.run([self.exe, *bounds, str(start)], capture_output=True, text=True,
                               env={**os.environ, "UBSAN_OPTIONS": "print_stacktrace=0"})
            errors = [m for m in _ERROR.finditer(r.stderr)
                      if "left shift of negative value" not in m["what"]]
            marks = re.findall(r"^P (\d+)$", r.stdout, re.M)
            if r.returncode == 0 and not errors:
                break
            last = int(marks[-1]) if marks else start
            if errors:
                m = errors[0]
                out[last] = (int(m["line"]), m["what"])
            elif r.returncode == 0:
                break
            elif "left shift of negative value" not in r.stderr:
                raise RuntimeError(f"{self.unit} stopped without a report: {r.stderr[-400:]}")
            start = last + 1
        return out

    def point_of(self, box: dict, k: int) -> dict:
        """The input values of point index ``k`` of ``box``."""
        out = {}
        for name, _, _ in reversed(self.params):
            lo, hi = box[name]
            k, r = divmod(k, hi - lo + 1)
            out[name] = lo + r
        return out
