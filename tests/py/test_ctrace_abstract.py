"""pulab.ctrace.abstract: the narrowing of a branch's variables, at the boundary of every
comparison, against the concrete tracer run at every point of the box.

For ``if (L OP R)`` with ``OP`` each of ``< <= > >= == !=``, the operands a variable and a
constant in both orders or two variables, of signed and unsigned 16- and 32-bit types on a 32-bit and a 16-bit `int`, each
box a few values either side of the comparison's boundary: every value a branch's copy
statement stores at some point lies in its proven range (soundness), and where the
comparison's operands keep their values in its type (the narrowing applies) the proven range
*is* the hull of those values, and a side no point takes is not run (exactness).  An
off-by-one in any narrowing rule breaks one of the two.
"""

from __future__ import annotations

import itertools
import random

import pytest

from pulab.ctrace import compile_code, run_checked
from pulab.ctrace.prove import prove_code

OPS = ("<", "<=", ">", ">=", "==", "!=")
#: C type → (lo, hi).
TYPES = {"int16_t": (-32768, 32767), "uint16_t": (0, 65535),
         "int32_t": (-2 ** 31, 2 ** 31 - 1), "uint32_t": (0, 2 ** 32 - 1)}
SEED = 20261127


def _operand_range(target: str, tx: str, ty: str) -> tuple:
    """The range of the type both operands convert to (C99 6.3.1.8). arm (32-bit int): 16-bit
    types promote to int, int32 with uint32 is unsigned. c28x (16-bit int): uint16 is unsigned
    int, int32 is long (which holds every unsigned int), uint32 unsigned long."""
    if "uint32_t" in (tx, ty):
        return 0, 2 ** 32 - 1
    if target == "arm" or "int32_t" in (tx, ty):
        return -2 ** 31, 2 ** 31 - 1
    return (0, 65535) if "uint16_t" in (tx, ty) else (-32768, 32767)


def _near(rng, t: str, centre: int, width: int) -> list:
    lo, hi = TYPES[t]
    a = max(lo, min(hi - width, centre - rng.randint(0, width)))
    return [a, a + width]


def _case(rng, target: str):
    """(code, box, whether the narrowing applies): one comparison at its boundary."""
    op = rng.choice(OPS)
    form = rng.choice(("x_c", "c_x", "x_y"))
    tx, ty = rng.choice(list(TYPES)), rng.choice(list(TYPES))
    lo, hi = TYPES[tx]
    c = rng.choice([lo, hi, 0, 1, -1 if lo < 0 else 2, rng.randint(lo, hi)])
    c = max(lo, min(hi, c))
    box = {"x": _near(rng, tx, c, rng.randint(0, 5))}
    if form == "x_y":
        box["y"] = _near(rng, ty, c + rng.randint(-3, 3), rng.randint(0, 5))
        test, ranges = "x OP y", [box["x"], box["y"]]
    else:
        # the literal has the type of x (a suffix or a cast where the target's int differs)
        ty = tx
        lit = f"({tx}){c}" if c != -2 ** 31 else "(int32_t)(-2147483647 - 1)"
        box["y"] = [0, 0]
        test = f"x OP {lit}" if form == "x_c" else f"{lit} OP x"
        ranges = [box["x"], [c, c]]
    code = f"""void f({tx} x, {ty} y) {{
  if ({test.replace("OP", op)}) {{
    {tx} tx = x;
    {ty} ty = y;
  }} else {{
    {tx} ex = x;
    {ty} ey = y;
  }}
}}"""
    olo, ohi = _operand_range(target, tx, ty)
    narrows = all(olo <= v <= ohi for r in ranges for v in r)
    return code, box, narrows


@pytest.mark.parametrize("target", ["arm", "c28x"])
def test_branch_ranges_are_the_hulls_of_the_traced_values_at_every_boundary(target):
    rng = random.Random(SEED)
    tally = {"cases": 0, "exact": 0, "points": 0, "dead_sides": 0}
    for _ in range(800):
        code, box, narrows = _case(rng, target)
        checked = compile_code(code, target, entry="f")
        r = prove_code(code, target, "f", box)
        ranges = {(s["line"], s["column"]): s["range"] for s in r["statements"]
                  if s["range"] is not None and s["line"] >= 3 and s["code"] != "} else {"}
        hulls: dict = {}
        for x, y in itertools.product(range(box["x"][0], box["x"][1] + 1),
                                      range(box["y"][0], box["y"][1] + 1)):
            ev = run_checked(checked, {"x": x, "y": y}, 24)
            tally["points"] += 1
            for s in ev.steps:
                if s.get("input") or s["line"] < 3:
                    continue
                key = (s["line"], s["column"])
                lo, hi = hulls.get(key, (s["value"], s["value"]))
                hulls[key] = (min(lo, s["value"]), max(hi, s["value"]))
        where = (code, box)
        for key, (lo, hi) in hulls.items():  # sound: every stored value in the range
            assert key in ranges, (where, key)
            assert ranges[key][0] <= lo and hi <= ranges[key][1], (where, key, ranges[key])
        tally["cases"] += 1
        if narrows:  # exact: no value more, no side no point takes
            tally["exact"] += 1
            tally["dead_sides"] += len(hulls) < 4
            assert {k: tuple(v) for k, v in ranges.items()} == hulls, where
    print(tally)
    # Both kinds of case, and sides that no point takes, must occur or the test shows nothing.
    assert tally["exact"] >= 600 and tally["cases"] - tally["exact"] >= 15, tally
    assert tally["dead_sides"] >= 150, tally
