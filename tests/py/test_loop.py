"""pulab.analyses.loop: discrete margins, delays, design, PLL, speed loop — against the
python-control oracle tests/oracle/loop_oracle.py (golden files tests/golden/loop) and by
properties that follow from the mathematics."""

from __future__ import annotations

import cmath
import copy
import json
import math
import pathlib
import subprocess
import sys

import pytest

import pulab
from pulab.schema.errors import InputError
from pulab.analyses.loop import current, discrete, pll, polynomial
from conftest import chinese

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden" / "loop"
CASES = sorted(GOLDEN.glob("*.json"))
REL = 1e-6
SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}, "analysis": {}}


def _close(a, e) -> bool:
    return abs(a - e) <= REL * max(abs(a), abs(e)) + 1e-9


def _poles_match(actual: list, expected: list) -> bool:
    """Every expected pole has a distinct actual pole within 1e-6 relative (complex)."""
    left = [complex(*p) for p in actual]
    if len(left) != len(expected):
        return False
    for re, im in expected:
        e = complex(re, im)
        k = min(range(len(left)), key=lambda i: abs(left[i] - e))
        if abs(left[k] - e) > REL * max(abs(e), 1.0):
            return False
        left.pop(k)
    return True


def _bode_match(actual: dict, expected: dict, problems: list, path: str) -> None:
    for k, i in enumerate(expected["index"]):
        a = 10 ** (actual["magnitude_db"][i] / 20) * cmath.exp(1j * math.radians(
            actual["phase_deg"][i]))
        e = 10 ** (expected["magnitude_db"][k] / 20) * cmath.exp(1j * math.radians(
            expected["phase_deg"][k]))
        if abs(a - e) > REL * abs(e):
            problems.append(f"{path}[{i}]: {a} vs {e}")


def _compare(expected, actual, path: str, problems: list) -> None:
    if isinstance(expected, dict):
        if "index" in expected:
            _bode_match(actual, expected, problems, path)
            return
        for k, v in expected.items():
            if not isinstance(actual, dict) or k not in actual:
                problems.append(f"{path}.{k}: missing")
            elif k == "poles":
                if not _poles_match(actual[k], v):
                    problems.append(f"{path}.poles: {actual[k]} vs {v}")
            elif k == "f_hz":
                idx = list(range(0, len(actual[k]), 10)) + [len(actual[k]) - 1]
                if len(actual[k]) != 400 or not all(_close(actual[k][i], f)
                                                    for i, f in zip(idx, v)):
                    problems.append(f"{path}.f_hz differs")
            else:
                _compare(v, actual[k], f"{path}.{k}", problems)
    elif expected is None or isinstance(expected, (bool, str)):
        if actual != expected:
            problems.append(f"{path}: expected {expected!r}, got {actual!r}")
    elif isinstance(expected, int):
        if type(actual) is not int or actual != expected:
            problems.append(f"{path}: expected int {expected}, got {actual!r}")
    elif actual is None or not _close(actual, expected):
        problems.append(f"{path}: expected {expected!r}, got {actual!r}")


def test_golden_files_not_stale():
    r = subprocess.run([sys.executable, str(ROOT / "tests" / "oracle" / "loop_oracle.py"),
                        "--check"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_enough_motors():
    assert len(CASES) >= 20


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_golden_loop(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    problems: list = []
    _compare(case["expected"]["loop"], pulab.report(case["input"])["loop"], "loop", problems)
    assert not problems, "\n".join(problems[:20])


# ---- properties -------------------------------------------------------------------------

@pytest.mark.parametrize("coefficients, expected", [
    ([1.0, -3.0, 2.0], [1.0, 2.0]),
    ([2.0, 0.0, -8.0, 0.0], [-2.0, 0.0, 2.0]),
    ([1.0, -1.5, 0.75, -0.125], [0.5, 0.5, 0.5]),     # triple root: ~ε^(1/3)
])
def test_roots_real(coefficients, expected):
    got = sorted(r.real for r in polynomial.roots(coefficients))
    assert all(abs(g - e) < 1e-4 for g, e in zip(got, expected))


def test_roots_conjugate_pairs_exact():
    rs = polynomial.roots([1.0, -1.2, 0.85, -0.1])
    upper = sorted((r for r in rs if r.imag > 0), key=lambda r: r.real)
    lower = sorted((r for r in rs if r.imag < 0), key=lambda r: r.real)
    assert [r.conjugate() for r in upper] == lower


@pytest.mark.parametrize("delay", current.DELAYS)
def test_pwm_plant_is_the_half_period_hold(delay):
    """The modelled plant reproduces a brute-force simulation of the delayed ZOH input."""
    rs, l_h, ts = 1.5, 6e-4, 1e-4
    num, den = current.plant(rs, l_h, ts, delay)
    # impulse response of num/den by long division
    n = polynomial.pad(num, len(den))
    h, state = [], n[:]
    for _ in range(8):
        c = state[0] / den[0]
        h.append(c)
        state = [x - c * d for x, d in zip(state, den)][1:] + [0.0]
    # direct: a unit pulse u_0 = 1 applied over [t0 + D, t0 + D + Ts), D = 0, Ts, 1.5·Ts
    lag = {"none": 0.0, "computation": 1.0, "computation_pwm": 1.5}[delay] * ts
    tau = l_h / rs

    def i_at(t):
        on = min(max(t - lag, 0.0), ts)
        return (1 - math.exp(-on / tau)) * math.exp(-max(t - lag - ts, 0.0) / tau) / rs
    direct = [i_at(k * ts) for k in range(8)]
    # h[k] is the response at sample k (the transfer function's first coefficient is z⁰ lead)
    assert all(abs(a - b) < 1e-12 for a, b in zip(h, direct))


@pytest.mark.parametrize("delay", current.DELAYS)
@pytest.mark.parametrize("target", [30.0, 45.0, 60.0, 75.0])
def test_design_meets_phase_margin(delay, target):
    kp, ki = current.design(0.42, 0.0085, 1.25e-4, delay, "phase_margin", target)
    assert abs(current.axis_loop(0.42, 0.0085, 1.25e-4, kp, ki, delay)["phase_margin_deg"]
               - target) < 1e-6


@pytest.mark.parametrize("delay", current.DELAYS)
def test_design_meets_bandwidth(delay):
    kp, ki = current.design(1.5, 6e-4, 1e-4, delay, "bandwidth", 400.0)
    assert abs(current.axis_loop(1.5, 6e-4, 1e-4, kp, ki, delay)["bandwidth_hz"] - 400) < 1e-6


def test_loop_only_when_asked():
    plain = {k: v for k, v in SEED.items() if k != "analysis"}
    assert "loop" not in pulab.report(plain)
    assert pulab.report(SEED)["loop"]["delay"] == "computation_pwm"


def test_more_delay_less_margin():
    pms = [current.axis_loop(1.5, 6e-4, 1e-4, 1.885, 4712.4, d)["phase_margin_deg"]
           for d in current.DELAYS]
    assert pms[0] > pms[1] > pms[2]


def test_seed_default_design_with_realistic_delay():
    r = pulab.report(SEED)["loop"]
    d = r["current"]["d"]
    assert r["delay"] == "computation_pwm"
    assert 50 < d["phase_margin_deg"] < 60 and d["stable"]
    assert d["firmware"]["pm_kp"] == 1180 and d["firmware"]["pm_ki"] == 4720
    assert r["current"]["design"]["d"]["phase_margin_deg"] == pytest.approx(60, abs=1e-9)


def test_pll_naive_is_unstable_and_boundary_matches_jury():
    r = pulab.report(SEED)["loop"]["pll"]
    assert r["correct"]["stable"] and r["correct"]["phase_margin_deg"] > 0
    assert not r["naive"]["stable"] and r["naive"]["gain_margin_db"] < 0
    # the boundary is where the gain margin of the scaled loop runs out
    k = 10 ** (r["correct"]["gain_margin_db"] / 20)
    assert r["boundary_kp_ts_gain"] == pytest.approx(k * r["correct"]["kp_ts_gain"], rel=1e-9)
    for x, stable in ((0.99, True), (1.01, False)):
        num, den = pll.loop(1.0, 0.01, 1.0, x * r["boundary_kp_ts_gain"] / 1.0)
        assert discrete.margins(num, den, 1.0)["stable"] is stable


def test_speed_loop_units():
    inp = copy.deepcopy(SEED)
    inp["analysis"] = {"speed": {"inertia_kg_m2": 1e-5, "response": True}}
    r = pulab.report(inp)
    sp = r["loop"]["speed"]
    b = r["base"]
    assert sp["bases"]["w_mb"] == pytest.approx(b["w_b"] / 4)
    # T_e/T_mb = ψ_pu·i_pu: K_t·I_b/T_mb = ψ_r/ψ_b
    assert sp["bases"]["kt_nm_per_a"] * b["I_b"] / sp["bases"]["torque_nm"] == \
        pytest.approx(r["pu"]["psi_r"], rel=1e-12)
    assert sp["pm_kp"] == round(sp["kp_pu"] * 4096)
    assert sp["stable"] and sp["firmware"]["stable"]
    res = sp["response"]
    for name in ("float", "fixed"):
        rpm = res["variants"][name]["speed_rpm"]
        assert abs(rpm[-1] - res["reference_rpm"]) < 0.01 * res["reference_rpm"]
        assert res["metrics"][name]["load_dip_rpm"] > 0
    # the fixed point differs from float by quantization only: within 1 % of the step
    assert res["fixed_vs_float_max_rpm"] < 0.01 * res["reference_rpm"]


@pytest.mark.parametrize("delay", current.DELAYS)
def test_speed_response_delay_costs_overshoot(delay):
    inp = copy.deepcopy(SEED)
    inp["analysis"] = {"delay": delay, "speed": {"inertia_kg_m2": 1e-5, "response": True,
                                                 "load_pu": 0}}
    m = pulab.report(inp)["loop"]["speed"]["response"]["metrics"]
    assert m["float"]["overshoot_pct"] == pytest.approx(m["fixed"]["overshoot_pct"], abs=0.5)


@pytest.mark.parametrize("analysis, field", [
    ({"delay": "pwm"}, "analysis.delay"),
    ({"design": "lqr"}, "analysis.design"),
    ({"target_phase_margin_deg": 95}, "analysis.target_phase_margin_deg"),
    ({"target_phase_margin_deg": 0}, "analysis.target_phase_margin_deg"),
    ({"design": "bandwidth", "target_bandwidth_hz": 6000}, "analysis.target_bandwidth_hz"),
    ({"bode": 1}, "analysis.bode"),
    ({"speed": {}}, "analysis.speed.inertia_kg_m2"),
    ({"speed": {"inertia_kg_m2": -1}}, "analysis.speed.inertia_kg_m2"),
    ({"speed": {"inertia_kg_m2": 1e-5, "ts_s": 1.5e-4}}, "analysis.speed.ts_s"),
    ({"speed": {"inertia_kg_m2": 1e-5, "friction_nm_s": 1.0}}, "analysis.speed.bandwidth_hz"),
    ({"speed": {"inertia_kg_m2": 1e-5, "current_limit_a": 20}},
     "analysis.speed.current_limit_a"),
    ({"speed": {"inertia_kg_m2": 1e-5, "step_pu": 0}}, "analysis.speed.step_pu"),
    ({"speed": {"inertia_kg_m2": 1e-5, "colour": 1}}, "analysis.speed.colour"),
    ({"deley": "none"}, "analysis.deley"),
])
def test_bad_analysis_names_the_field_in_both_languages(analysis, field):
    inp = copy.deepcopy(SEED)
    inp["analysis"] = analysis
    with pytest.raises(InputError) as e:
        pulab.report(inp)
    assert e.value.field == field
    assert chinese(e.value.message_zh), e.value.message


def test_warnings_have_chinese():
    inp = copy.deepcopy(SEED)
    inp["current_loop"] = {"bandwidth_hz": 1500}
    inp["analysis"] = {"speed": {"inertia_kg_m2": 1e-7, "bandwidth_hz": 200}}
    r = pulab.report(inp)
    loop_warnings = [z for w, z in zip(r["warnings"], r["warnings_zh"]) if w.startswith("loop.")]
    assert loop_warnings
    assert all(chinese(w) for w in loop_warnings)


def test_text_format_lists_the_margins():
    from pulab.report import format_text
    text = format_text(pulab.report(SEED))
    assert "Loop margins (delay computation_pwm)" in text
    assert "PLL naive           PM none" in text and "UNSTABLE" in text
