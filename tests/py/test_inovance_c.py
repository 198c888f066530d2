"""The Inovance results are the seed's C (pulab.ctrace.examples) run by the tracer.

The report's vendor traces are lines of that C and their values the tracer's evaluator's; the
family proof's enclosure of a box (pulab.analyses.prove_intervals, the tracer's interval
evaluator over the same C) holds every point of the box, with every failure a point meets.
"""

from __future__ import annotations

import random

import pytest

from pulab.analyses.prove_intervals import interval_steps
from pulab.ctrace import compile_code, run_checked
from pulab.ctrace.examples import EXAMPLES
from pulab.profiles.inovance.code import VENDOR_READS, VENDOR_RESULTS, current_pi_step
from pulab.schema.errors import InputError

SEED = 20261129
RAW = {"Voltage": 380, "Current": 1550, "FullFreq01": 5000, "FreqRated01": 5000, "RsPm": 450,
       "LD": 800, "LQ": 1400, "BemfVolt": 3300, "uDCFilter": 5400}
BLOCK = {"Rpm": "rpm", "LD": "ld", "FreqPer": "flux", "FluxRotor": "flux",
         "pm_maxout_vol": "maxu", "maxu": "maxu"}


@pytest.mark.parametrize("name", list(BLOCK))
def test_a_result_is_its_block_run_by_the_evaluator(name):
    """Each trace step is a line of the example's C, with the evaluator's value."""
    code = EXAMPLES[BLOCK[name]]["code"]
    checked = compile_code(code, "c28x")
    rng = random.Random(f"{SEED}-{name}")
    for _ in range(200):
        raw = {k: rng.randrange(1, 65536) if rng.random() < 0.5 else v for k, v in RAW.items()}
        try:
            r = VENDOR_RESULTS[name](raw, "10uH")
        except InputError:
            continue
        values = run_checked(checked, {p: raw[p.rpartition(".")[2]] for p in checked.inputs},
                             record=False).values
        lines = code.splitlines()
        for step in r["trace"]:
            assert step["code"] in lines
        assert r["value"] == values[r["trace"][-1]["var"]]


def test_the_pi_update_is_the_pi_block():
    checked = compile_code(EXAMPLES["pi"]["code"], "c28x")
    rng = random.Random(SEED)
    for _ in range(300):
        maxout = rng.randrange(1, 8192)
        args = (rng.randrange(-(maxout << 12), (maxout << 12) + 1), rng.randrange(-32768, 32768),
                rng.randrange(0, 32768), rng.randrange(0, 65536), maxout << 12, maxout)
        step = current_pi_step(*args)
        v = run_checked(checked, dict(zip(("pm_integral_d", "pm_error_id", "pm_kp_d", "pm_ki_d",
                                           "maxu", "pm_maxout_vol"), args)),
                        record=False).values
        assert (step.integral, step.out) == (v["pm_integral_d"], v["pm_ud"])


def _box(rng: random.Random) -> dict:
    box = {}
    for k, v in RAW.items():
        lo = max(0, int(v * rng.uniform(0.0, 1.5)) - rng.randrange(0, 3))
        box[k] = (lo, min(65535, lo + rng.choice([0, 1, 5, 50, 2000, 40000])))
    return box


@pytest.mark.parametrize("name", list(VENDOR_READS))
def test_the_enclosure_holds_every_point(name):
    rng = random.Random(f"{SEED}-box-{name}")
    checked_points = 0
    for _ in range(60):
        box = _box(rng)
        run = interval_steps(name, box)
        for _ in range(20):
            pt = {k: rng.randint(lo, hi) for k, (lo, hi) in box.items()}
            try:
                r = VENDOR_RESULTS[name](pt, "10uH")
            except InputError:  # the point divides by zero: so may the box
                assert run is None or any("div0" in s["flags"] for s in run[0] + run[1])
                continue
            assert run is not None
            own = run[0]
            lo, hi = own[-1]["value"]
            assert lo <= r["value"] <= hi
            for s, t in zip(own, r["trace"]):
                assert s["value"][0] <= t["value"] <= s["value"][1]
                assert set(t["flags"]) & {"wrap", "store"} <= set(s["flags"])
            checked_points += 1
    assert checked_points >= 300
