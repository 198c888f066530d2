"""pulab.analyses.sim: plant discretization, the three current-loop variants, the PLL
variants, metrics, validation, and the golden trajectories of tests/oracle/sim_oracle.py."""

import cmath
import copy
import fnmatch
import json
import math
import pathlib
import subprocess
import sys

import pytest
from hypothesis import given, settings, strategies as st

import pulab
from pulab.analyses import sim
from pulab.schema.errors import InputError
from pulab.analyses.sim import current, metrics, plant
from pulab.analyses.sim.linalg import expm, matmul
from pulab.profiles.inovance.code import current_pi_step

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden" / "sim"

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}
V690 = {"motor": {"rated_voltage_v": 690, "rated_current_a": 112, "rated_freq_hz": 50,
                  "rs_ohm": 0.021, "ld_h": 0.0021, "lq_h": 0.0034, "bemf_v": 610.0,
                  "pole_pairs": 3},
        "drive": {"base_freq_hz": 75, "udc_v": 1000, "ts_s": 0.00025},
        "current_loop": {"bandwidth_hz": 150}}
IND380 = {"motor": {"rated_voltage_v": 380, "rated_current_a": 14.5, "rated_freq_hz": 50,
                    "rs_ohm": 0.42, "ld_h": 0.0085, "lq_h": 0.0135, "bemf_v": 335.0,
                    "pole_pairs": 2},
          "drive": {"udc_v": 540, "ts_s": 0.000125}}
SERVO = {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
                   "rs_ohm": 2.3, "ld_h": 0.0046, "lq_h": 0.0052, "bemf_v": 104.0,
                   "pole_pairs": 4},
         "drive": {"base_freq_hz": 333.33, "udc_v": 310, "ts_s": 0.0000625}}
LV48 = {"motor": {"rated_voltage_v": 32, "rated_current_a": 120, "rated_freq_hz": 100,
                  "rs_ohm": 0.008, "ld_h": 0.000045, "lq_h": 0.00006, "bemf_v": 27.5,
                  "pole_pairs": 5},
        "drive": {"udc_v": 48, "ts_s": 0.00005}}
MOTORS = {"seed": SEED, "mv690": V690, "ind380": IND380, "servo": SERVO, "lv48": LV48}


def with_(base, **sections):
    d = copy.deepcopy(base)
    for k, v in sections.items():
        d.setdefault(k, {}).update(v)
    return d


def run_sim(base, current_cfg=None, pll_cfg=None, **sections):
    inp = with_(base, **sections)
    inp["sim"] = {"current": current_cfg or {}, "pll": pll_cfg or {}}
    return pulab.report(inp)


# ------------------------------------------------------------------------------------------
# Matrix exponential and the ZOH plant (seed 1.2-3)

def test_expm_matches_series_and_inverse():
    m = [[-3.0, 1.5, 0.2], [-0.7, -2.0, 1.0], [0.0, 0.3, -0.1]]
    e = expm(m)
    # exp(M)·exp(−M) = I
    inv = expm([[-v for v in row] for row in m])
    prod = matmul(e, inv)
    for i in range(3):
        for j in range(3):
            assert prod[i][j] == pytest.approx(1.0 if i == j else 0.0, abs=1e-13)
    # against a long unscaled Taylor series at a small norm
    small = [[v / 64 for v in row] for row in m]
    term = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    total = [row[:] for row in term]
    for k in range(1, 40):
        term = [[v / k for v in row] for row in matmul(term, small)]
        total = [[a + b for a, b in zip(ra, rb)] for ra, rb in zip(total, term)]
    es = expm(small)
    for i in range(3):
        for j in range(3):
            assert es[i][j] == pytest.approx(total[i][j], rel=1e-14, abs=1e-16)


def _eig2(a, b, c, d):
    tr, det = a + d, a * d - b * c
    r = cmath.sqrt(tr * tr / 4 - det)
    return sorted([tr / 2 + r, tr / 2 - r], key=lambda z: (z.real, z.imag))


@pytest.mark.parametrize("ld,lq,w", [(6e-4, 6e-4, 0.0), (2e-3, 3e-3, 0.0),
                                     (2e-3, 3e-3, 2 * math.pi * 50), (6e-4, 6e-4, 3000.0)])
def test_zoh_pole_mapping(ld, lq, w):
    """Eigenvalues of Φ are exp(p·Ts) for the eigenvalues p of A (exact ZOH)."""
    rs, ts = 0.5, 2e-4
    a, _ = plant.continuous_matrices(rs, ld, lq, w)
    z = plant.zoh(rs, ld, lq, 0.0, w, ts)
    poles = _eig2(a[0][0], a[0][1], a[1][0], a[1][1])
    want = sorted((cmath.exp(p * ts) for p in poles), key=lambda q: (q.real, q.imag))
    got = _eig2(*z.phi)
    for g, x in zip(got, want):
        assert abs(g - x) < 1e-13


@pytest.mark.parametrize("w", [0.0, 400.0])
def test_zoh_dc_gain(w):
    """Held u gives the steady state (I − Φ)⁻¹Γ·u = −A⁻¹B·u; at standstill u/R."""
    rs, ld, lq, ts = 1.5, 6e-4, 9e-4, 1e-4
    z = plant.zoh(rs, ld, lq, 0.0, w, ts)
    p0, p1, p2, p3 = z.phi
    g0, g1, g2, g3 = z.gamma
    ud, uq = 3.0, -2.0
    x = [0.0, 0.0]
    for _ in range(20000):
        x = [p0 * x[0] + p1 * x[1] + g0 * ud + g1 * uq, p2 * x[0] + p3 * x[1] + g2 * ud + g3 * uq]
    # steady state of the continuous model: R·id − ω·Lq·iq = ud, R·iq + ω·Ld·id = uq
    det = rs * rs + w * w * ld * lq
    want = [(rs * ud + w * lq * uq) / det, (rs * uq - w * ld * ud) / det]
    assert x[0] == pytest.approx(want[0], rel=1e-11)
    assert x[1] == pytest.approx(want[1], rel=1e-11)
    if w == 0.0:
        assert x[0] == pytest.approx(ud / rs, rel=1e-11)


def test_zoh_back_emf_is_a_q_voltage():
    z = plant.zoh(1.0, 1e-3, 1e-3, 0.05, 300.0, 1e-4)
    assert z.bemf == pytest.approx(15.0)


# ------------------------------------------------------------------------------------------
# Current loop

def _max_rel(a, b):
    scale = max(abs(v) for v in a) or 1.0
    return max(abs(x - y) for x, y in zip(a, b)) / scale


@pytest.mark.parametrize("motor", sorted(MOTORS))
@pytest.mark.parametrize("axis,speed,delay", [("d", 0.0, False), ("q", 40.0, True),
                                              ("d", 80.0, False)])
def test_si_and_pu_agree(motor, axis, speed, delay):
    """Acceptance (a)/(b): per unit × bases equals SI to 1e-9 at every sample (full rate)."""
    rep = pulab.report(MOTORS[motor])
    cfg = sim.validate({"current": {"axis": axis, "speed_hz": speed, "delay": delay}})
    r = current.run(rep, cfg["current"])
    si, pu = r["variants"]["si"], r["variants"]["pu"]
    for k in ("id", "iq", "ud", "uq"):
        assert _max_rel(si[k], pu[k]) < 1e-9, k
    assert si["sat"] == pu["sat"]


@pytest.mark.parametrize("conv", [{"base": "peak"}, {"angle_base": "2pi"},
                                  {"base": "custom", "base_voltage_v": 400,
                                   "base_current_a": 30}])
def test_si_and_pu_agree_other_conventions(conv):
    rep = run_sim(IND380, {"axis": "q", "step_a": 20.0, "speed_hz": 50.0}, conventions=conv)
    v = rep["sim"]["current"]["variants"]
    for k in ("id", "iq", "ud", "uq"):
        assert _max_rel(v["si"][k], v["pu"][k]) < 1e-9


def test_si_and_pu_agree_in_saturation():
    rep = run_sim(IND380, {"axis": "q", "step_a": 29.0, "speed_hz": 50.0, "duration_s": 0.03})
    m = rep["sim"]["current"]["metrics"]
    assert m["si"]["saturation_time_s"] > 0.01
    assert m["si"]["saturation_time_s"] == m["pu"]["saturation_time_s"]
    v = rep["sim"]["current"]["variants"]
    for k in ("id", "iq", "ud", "uq"):
        assert _max_rel(v["si"][k], v["pu"][k]) < 1e-9


@pytest.mark.parametrize("motor,sections", [
    ("seed", {"drive": {"ts_s": 1e-5}}),                          # ω_c·Ts = 0.031
    ("seed", {"current_loop": {"bandwidth_hz": 79}}),             # 0.0496
    ("mv690", {"current_loop": {"bandwidth_hz": 30}}),            # 0.047
    ("ind380", {"drive": {"ts_s": 2.5e-5}, "current_loop": {"bandwidth_hz": 300}}),  # 0.047
    ("servo", {"current_loop": {"bandwidth_hz": 120}}),           # 0.047
])
def test_rise_time_first_order(motor, sections):
    """Acceptance: bandwidth design, no delay, no saturation, ω_c·Ts ≤ 0.05 → within 6 %."""
    rep = run_sim(with_(MOTORS[motor], **sections), {"axis": "d"})
    m = rep["sim"]["current"]["metrics"]
    assert m["wc_ts"] <= 0.05 + 1e-12
    assert m["si"]["saturation_time_s"] == 0.0
    first = 2.2 / (2 * math.pi * rep["input"]["current_loop"]["bandwidth_hz"])
    assert m["first_order_rise_time_s"] == pytest.approx(first)
    assert abs(m["si"]["rise_time_s"] - first) / first < 0.06
    assert m["rise_time_deviation_pct"] == pytest.approx(
        100 * (m["si"]["rise_time_s"] - first) / first)
    assert m["si"]["overshoot_pct"] < 0.5


def test_rise_time_deviation_grows_with_wc_ts():
    """At larger ω_c·Ts the discrete loop is faster; about −30 % near ω_c·Ts ≈ 0.6."""
    devs = []
    for ts in (1e-5, 5e-5, 1e-4, 1.9e-4):
        m = run_sim(SEED, {"axis": "d"}, drive={"ts_s": ts})["sim"]["current"]["metrics"]
        devs.append((m["wc_ts"], m["rise_time_deviation_pct"]))
    assert all(d2 < d1 for (_, d1), (_, d2) in zip(devs, devs[1:]))
    assert devs[-1][0] == pytest.approx(0.597, abs=1e-3)
    assert -40.0 < devs[-1][1] < -25.0


def _steady_lsb(rep):
    r = current.run(rep, sim.validate(rep["input"].get("sim") or {})["current"])
    si, fx = r["variants"]["si"], r["variants"]["fixed"]
    n = len(si["id"])
    tail = range(int(0.9 * n), n)
    lsb = rep["base"]["I_b"] / 4096
    return max(max(abs(fx["id"][k] - si["id"][k]), abs(fx["iq"][k] - si["iq"][k]))
               for k in tail) / lsb


@pytest.mark.parametrize("motor", sorted(MOTORS))
@pytest.mark.parametrize("axis,speed", [("d", 0.0), ("q", 30.0)])
def test_fixed_within_a_few_lsb_of_si(motor, axis, speed):
    """Acceptance (c): steady state within a few Q12 LSB of the SI float loop."""
    rep = pulab.report(MOTORS[motor])
    rep["input"]["sim"] = {"current": {"axis": axis, "speed_hz": speed,
                                       "step_a": 0.3 * rep["base"]["I_b"]}}
    assert _steady_lsb(rep) < 3.0
    whole = run_sim(MOTORS[motor], rep["input"]["sim"]["current"])
    assert whole["sim"]["current"]["metrics"]["fixed_vs_si_max_lsb"] < 4.0


def test_fixed_first_step_is_the_vendor_update_in_phase_volts():
    """Q12 output × U_b is the phase voltage kp·Δi (line/phase, seed 2.2 vs contract)."""
    rep = pulab.report(SEED)
    cfg = sim.validate({"current": {"axis": "d", "step_a": 0.75}})["current"]
    r = current.run(rep, cfg)
    g, v = rep["current_pi"]["d"], rep["vendor"]
    ref = round(0.75 / rep["base"]["I_b"] * 4096)
    step = current_pi_step(0, ref, g["pm_kp"], g["pm_ki"], v["maxu"]["value"],
                           v["pm_maxout_vol"]["value"])
    u0 = r["variants"]["fixed"]["ud"][0]
    assert u0 == step.out * rep["base"]["U_b"] / 4096
    # ≈ the SI first output kp·Δi + ki·Ts·Δi (phase volts) to the integer resolution
    si0 = r["variants"]["si"]["ud"][0]
    assert abs(u0 - si0) < 3 * rep["base"]["U_b"] / 4096
    # the same number read the seed's way: line voltage (base Voltage) / √3
    line = step.out / 4096 * rep["input"]["motor"]["rated_voltage_v"]
    assert u0 == pytest.approx(line / math.sqrt(3), rel=1e-12)


def test_fixed_memo_changes_nothing():
    rep = pulab.report(IND380)
    b, g, v = rep["base"], rep["current_pi"], rep["vendor"]
    z = plant.zoh(0.42, 0.0085, 0.0135, rep["pu"]["psi_r_wb"], 2 * math.pi * 50, 0.000125)
    args = (z, b["I_b"], b["U_b"], g["d"]["pm_kp"], g["d"]["pm_ki"], g["q"]["pm_kp"],
            g["q"]["pm_ki"], v["maxu"]["value"], v["pm_maxout_vol"]["value"], 0, 8000,
            round(z.bemf / b["U_b"] * 2 ** 24), 400, True)
    assert current.run_fixed(*args, memo=True) == current.run_fixed(*args, memo=False)


def test_delay_shifts_the_applied_voltage_by_one_sample():
    a = run_sim(SEED, {"axis": "d", "duration_s": 0.002, "delay": False})
    b = run_sim(SEED, {"axis": "d", "duration_s": 0.002, "delay": True})
    ua, ub = a["sim"]["current"]["variants"]["si"]["ud"], b["sim"]["current"]["variants"]["si"]["ud"]
    assert ub[0] == 0.0 and ua[0] > 0 and ub[1] == pytest.approx(ua[0])


def test_back_emf_preload_is_steady_state():
    """At speed with zero current the q integral holds ω·ψ: no start-up transient."""
    rep = run_sim(SEED, {"axis": "d", "step_a": 1e-9, "speed_hz": 200.0, "duration_s": 0.002})
    v = rep["sim"]["current"]["variants"]["si"]
    assert max(abs(x) for x in v["iq"]) < 1e-6
    w = 2 * math.pi * 200.0
    assert v["uq"][0] == pytest.approx(w * rep["pu"]["psi_r_wb"], rel=1e-12)


# ------------------------------------------------------------------------------------------
# PLL (seed 3)

@pytest.mark.parametrize("bw", [20.0, 50.0, 100.0, 200.0])
def test_pll_correct_scaling_locks_naive_does_not(bw):
    rep = run_sim(SEED, pll_cfg={}, pll={"bandwidth_hz": bw})
    m = rep["sim"]["pll"]["metrics"]
    for name in ("si", "pu", "q15"):
        assert m[name]["locked"], name
        assert m[name]["lock_time_s"] is not None
        assert abs(m[name]["speed_error_hz"]) < 0.01
    assert not m["naive"]["locked"]
    assert m["naive"]["lock_time_s"] is None


@pytest.mark.parametrize("motor", ["mv690", "ind380", "servo"])
def test_pll_locks_other_motors(motor):
    m = run_sim(MOTORS[motor], pll_cfg={"angle_step_deg": -170.0})["sim"]["pll"]["metrics"]
    assert m["si"]["locked"] and m["pu"]["locked"] and m["q15"]["locked"]
    assert not m["naive"]["locked"]


def test_pll_si_and_pu_agree():
    rep = run_sim(SEED, pll_cfg={"ramp_hz_per_s": 300.0, "speed_hz": 80.0})
    v = rep["sim"]["pll"]["variants"]
    for a, b in zip(v["si"]["theta_hat"], v["pu"]["theta_hat"]):
        assert abs(math.remainder(a - b, 2 * math.pi)) < 1e-9
    assert _max_rel(v["si"]["omega_hat"], v["pu"]["omega_hat"]) < 1e-9
    m = rep["sim"]["pll"]["metrics"]
    assert m["si"]["lock_time_s"] == m["pu"]["lock_time_s"]


def test_pll_q15_angle_is_int16_of_pi():
    from pulab.analyses.sim import pll
    g = pll.q15_gains(444.0, 98696.0, 2 * math.pi * 220, 220.0, 1e-4)
    assert g["g"] == round(2 * 220 * 1e-4 * 2 ** 23)
    th_in, th_hat, w = pll.run_q15([math.pi * 0.999, -math.pi * 0.999, math.pi], g)
    assert all(-32768 <= x <= 32767 for x in th_in + th_hat)
    assert th_in[2] == -32768                                    # +π wraps to −π
    assert all(-2 ** 31 <= x < 2 ** 31 for x in w)


def test_pll_q15_tracks_si_closely():
    rep = run_sim(SEED, pll_cfg={"speed_hz": 150.0})
    v = rep["sim"]["pll"]["variants"]
    err = max(abs(math.remainder(a - b, 2 * math.pi))
              for a, b in zip(v["si"]["theta_hat"][-50:], v["q15"]["theta_hat"][-50:]))
    assert err < 5 * math.pi / 32768


# ------------------------------------------------------------------------------------------
# Metrics

def test_metrics_first_order_exact():
    tau = 1e-3
    t = [k * 1e-5 for k in range(2001)]
    y = [2.0 * (1 - math.exp(-x / tau)) for x in t]
    assert metrics.rise_time(t, y, 2.0) == pytest.approx(math.log(9) * tau, rel=1e-4)
    assert metrics.settling_time(t, y, 2.0) == pytest.approx(-math.log(0.02) * tau, rel=1e-4)
    assert metrics.overshoot_pct(y, 2.0) == 0.0
    neg = [-v for v in y]
    assert metrics.rise_time(t, neg, -2.0) == pytest.approx(math.log(9) * tau, rel=1e-4)


def test_metrics_not_reached_is_none():
    t = [0.0, 1.0, 2.0]
    assert metrics.rise_time(t, [0.0, 0.2, 0.5], 1.0) is None
    assert metrics.settling_time(t, [0.0, 0.2, 0.5], 1.0) is None


def test_pll_metrics_lock_window():
    t = [k * 0.01 for k in range(100)]
    th = [0.0] * 100
    hat = [0.5 if k < 30 else 0.01 for k in range(100)]
    m = metrics.pll_metrics(t, th, [1.0] * 100, hat, [1.0] * 100)
    assert m["locked"] and m["lock_time_s"] == pytest.approx(0.30)
    assert m["max_angle_error_deg"] == pytest.approx(math.degrees(0.5))
    hat[95] = 0.1
    assert not metrics.pll_metrics(t, th, [1.0] * 100, hat, [1.0] * 100)["locked"]


# ------------------------------------------------------------------------------------------
# Output shape, validation

def test_output_keys_and_decimation():
    rep = run_sim(SEED, {"duration_s": 0.5}, {"duration_s": 0.5})
    s = rep["sim"]
    c, p = s["current"], s["pll"]
    assert set(c) == {"t", "variants", "metrics", "by_profile"}
    assert set(p) == {"t", "variants", "metrics"}
    assert set(c["variants"]) == {"si", "pu", "fixed"}
    assert set(c["by_profile"]) == {"ti", "nxp", "st", "microchip"}
    for b in c["by_profile"].values():
        assert set(b) == {"ran", "lsb_a", "events", "variant", "metrics"}
        assert all(len(x) == len(c["t"]) for x in b["variant"].values())
    assert set(p["variants"]) == {"si", "pu", "q15", "naive"}
    for v in c["variants"].values():
        assert set(v) == {"id", "iq", "ud", "uq"}
        assert all(len(x) == len(c["t"]) for x in v.values())
    for v in p["variants"].values():
        assert set(v) == {"theta", "theta_hat", "omega_hat"}
    assert set(c["metrics"]["si"]) >= {"rise_time_s", "overshoot_pct", "settling_time_s",
                                       "steady_state_error_a"}
    assert {"fixed_vs_si_max_abs_a", "fixed_vs_si_max_lsb"} <= set(c["metrics"])
    assert set(p["metrics"]["q15"]) == {"locked", "lock_time_s", "speed_error_hz",
                                        "max_angle_error_deg", "steady_angle_error_deg"}
    assert 300 <= len(c["t"]) <= sim.MAX_POINTS and len(p["t"]) <= sim.MAX_POINTS
    assert c["t"][-1] == pytest.approx(0.5)
    json.dumps(s, allow_nan=False)


def test_no_sim_section_unless_asked():
    assert "sim" not in pulab.report(SEED)
    assert "sim" in pulab.report(with_(SEED, sim={}))


def test_decimate_indices():
    assert sim.decimate_indices(5) == [0, 1, 2, 3, 4]
    idx = sim.decimate_indices(100001)
    assert idx[0] == 0 and idx[-1] == 100000 and len(idx) <= sim.MAX_POINTS


def test_validate_defaults_and_idempotence():
    v = sim.validate({})
    assert v == {"current": {"axis": "d", "step_a": None, "duration_s": None, "speed_hz": 0.0,
                             "delay": False},
                 "pll": {"speed_hz": None, "angle_step_deg": 30.0, "ramp_hz_per_s": 0.0,
                         "duration_s": None}}
    assert sim.validate(v) == v
    assert sim.validate(None) == v
    assert sim.validate({"current": None, "pll": {"speed_hz": None}}) == v


@pytest.mark.parametrize("bad,field", [
    ({"foo": {}}, "sim.foo"),
    ([], "sim"),
    ({"current": 3}, "sim.current"),
    ({"current": {"stepa": 1}}, "sim.current.stepa"),
    ({"current": {"step_a": True}}, "sim.current.step_a"),
    ({"current": {"step_a": "1"}}, "sim.current.step_a"),
    ({"current": {"step_a": 0}}, "sim.current.step_a"),
    ({"current": {"step_a": float("nan")}}, "sim.current.step_a"),
    ({"current": {"axis": "x"}}, "sim.current.axis"),
    ({"current": {"delay": 1}}, "sim.current.delay"),
    ({"current": {"delay": "true"}}, "sim.current.delay"),
    ({"current": {"duration_s": 0}}, "sim.current.duration_s"),
    ({"current": {"duration_s": -1}}, "sim.current.duration_s"),
    ({"current": {"speed_hz": float("inf")}}, "sim.current.speed_hz"),
    ({"current": {"speed_hz": False}}, "sim.current.speed_hz"),
    ({"pll": {"angle_step_deg": 181}}, "sim.pll.angle_step_deg"),
    ({"pll": {"duration_s": 0}}, "sim.pll.duration_s"),
    ({"pll": {"speed": 1}}, "sim.pll.speed"),
    ({"pll": {"ramp_hz_per_s": [1]}}, "sim.pll.ramp_hz_per_s"),
])
def test_validate_errors(bad, field):
    with pytest.raises(InputError) as e:
        sim.validate(bad)
    assert e.value.field == field
    with pytest.raises(InputError) as e:       # and through the report entry point
        pulab.report(with_(SEED, sim=bad) if isinstance(bad, dict) else {**SEED, "sim": bad})
    assert e.value.field == field


@pytest.mark.parametrize("cfg,field", [
    ({"current": {"step_a": 13.0}}, "sim.current.step_a"),        # 8.7 pu > Q12 int16
    ({"current": {"duration_s": 100.0}}, "sim.current.duration_s"),
    ({"pll": {"duration_s": 1000.0}}, "sim.pll.duration_s"),
    ({"current": {"speed_hz": 5000.0}}, "sim.current.speed_hz"),     # Nyquist at Ts = 100 µs
    ({"pll": {"speed_hz": -5000.0}}, "sim.pll.speed_hz"),
    ({"pll": {"speed_hz": 100.0, "ramp_hz_per_s": 1e5, "duration_s": 0.1}},
     "sim.pll.ramp_hz_per_s"),
])
def test_simulate_errors(cfg, field):
    with pytest.raises(InputError) as e:
        pulab.report(with_(SEED, sim=cfg))
    assert e.value.field == field


_num = st.one_of(st.none(), st.booleans(), st.text(max_size=3),
                 st.floats(allow_nan=True, allow_infinity=True),
                 st.floats(min_value=-1e4, max_value=1e4), st.integers(-10 ** 6, 10 ** 6))


@settings(max_examples=150, deadline=None)
@given(cur=st.fixed_dictionaries({}, optional={
           "axis": st.one_of(st.sampled_from(["d", "q", "x"]), _num),
           "step_a": _num, "duration_s": st.one_of(_num, st.floats(1e-6, 0.02)),
           "speed_hz": _num, "delay": st.one_of(st.booleans(), _num)}),
       pll=st.fixed_dictionaries({}, optional={
           "speed_hz": _num, "angle_step_deg": _num, "ramp_hz_per_s": _num,
           "duration_s": st.one_of(_num, st.floats(1e-6, 0.05))}))
def test_fuzzed_sim_input_gives_output_or_input_error(cur, pll):
    """Nothing but InputError, and never NaN or infinity in the output."""
    try:
        rep = pulab.report(with_(SEED, sim={"current": cur, "pll": pll}))
    except InputError as e:
        assert e.field.startswith("sim.")
        return
    json.dumps(rep["sim"], allow_nan=False)


def test_bench_runs():
    from pulab.analyses.sim.bench import bench
    r = bench(500, repeat=1)
    assert r["steps"] == 500 and r["steps_per_s"] > 0


# ------------------------------------------------------------------------------------------
# Golden trajectories (tests/oracle/sim_oracle.py, independent numpy oracle)

GOLDEN_FILES = sorted(GOLDEN.glob("*.json"))


def test_golden_files_exist_and_are_fresh():
    assert len(GOLDEN_FILES) >= 4
    r = subprocess.run([sys.executable, str(ROOT / "tests" / "oracle" / "sim_oracle.py"),
                        "--check"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def _match(path, patterns):
    return any(fnmatch.fnmatchcase(path, p) for p in patterns)


def _compare(got, exp, path, rules, bad):
    if _match(path, rules["skip"]):
        return
    if isinstance(exp, dict):
        if set(got) != set(exp):
            bad.append(f"{path}: keys {sorted(set(got) ^ set(exp))}")
            return
        for k in exp:
            _compare(got[k], exp[k], f"{path}.{k}" if path else k, rules, bad)
    elif isinstance(exp, list):
        if len(got) != len(exp):
            bad.append(f"{path}: length {len(got)} != {len(exp)}")
            return
        scale = max((abs(x) for x in exp), default=0.0) or 1.0
        if _match(path, rules["wrapped"]):
            d = max(abs(math.remainder(a - b, 2 * math.pi)) for a, b in zip(got, exp))
        else:
            d = max(abs(a - b) for a, b in zip(got, exp))
        if d > rules["rel"] * scale:
            bad.append(f"{path}: max |Δ| {d:g} > {rules['rel']}·{scale:g}")
    elif isinstance(exp, float) and isinstance(got, (int, float)) and \
            not isinstance(got, bool):
        floor = max([v for p, v in rules["abs"].items() if fnmatch.fnmatchcase(path, p)],
                    default=0.0)
        if abs(got - exp) > rules["rel"] * max(abs(got), abs(exp)) + floor:
            bad.append(f"{path}: {got!r} != {exp!r}")
    elif got != exp or type(got) is not type(exp):
        bad.append(f"{path}: {got!r} != {exp!r}")


@pytest.mark.parametrize("path", GOLDEN_FILES, ids=[p.stem for p in GOLDEN_FILES])
def test_golden_trajectory(path):
    case = json.loads(path.read_text())
    assert set(case) == {"input", "expected", "compare"}
    got = pulab.report(case["input"])["sim"]
    # The four vendors' integer PIs have their own C oracle (test_vendor_pi, test_vendor_loop).
    del got["current"]["by_profile"]
    bad = []
    _compare(got, case["expected"], "", case["compare"], bad)
    assert not bad, "\n".join(bad[:20])
    # the naive PLL: only 'locked' is compared, and it must be false
    assert case["expected"]["pll"]["metrics"]["naive"]["locked"] is False


@pytest.mark.parametrize("name", ["19_limit_udc_7000v", "22_limit_voltage_0"])
def test_a_drive_inovance_cannot_hold_still_simulates_in_float(name):
    """No pm_maxout_vol/maxu (firmware.inovance): the float runs clamp at U_dc/√2, the
    firmware's fixed-point runs are absent, the differences to them null — no crash."""
    inp = json.loads((ROOT / "tests/golden" / f"{name}.json").read_text())["input"]
    inp["sim"] = {}
    inp["analysis"] = {"speed": {"inertia_kg_m2": 1e-4, "response": True}, "robust": {}}
    r = pulab.report(inp)
    assert "maxu" not in r["vendor"] and not r["firmware"]["inovance"]["representable"]
    cur = r["sim"]["current"]
    assert set(cur["variants"]) == {"si", "pu"} and cur["metrics"]["fixed_vs_si_max_lsb"] is None
    assert cur["metrics"]["si"]["rise_time_s"] is not None
    speed = r["loop"]["speed"]["response"]
    assert set(speed["variants"]) == {"float"} and speed["fixed_vs_float_max_rpm"] is None
    step = r["loop"]["robust"].get("step")
    assert step is None or (step["fixed"] is None and step["metrics"]["fixed"] is None)


def test_a_wrapped_maxu_is_simulated_and_flagged_not_a_traceback():
    # Udc 4890.3 V over a 27 V motor: pm_maxout_vol = 3456·4096/27 = 524288 = 2^19, so
    # maxu = pm_maxout_vol << 12 = 2^31 wraps to −2^31 and minu = -maxu wraps with it; the
    # integral is then pinned at −2^31 and the PI's sums wrap (seed 2.2 in 32-bit long).
    rep = run_sim(with_(SEED, motor={"rated_voltage_v": 27}, drive={"udc_v": 4890.3}))
    assert rep["vendor"]["maxu"]["value"] == -(1 << 31)
    m = rep["sim"]["current"]["metrics"]
    assert m["fixed_wraps"] > 0
    wraps = [x for x in rep["review"]["findings"] if x["code"] == "pi_wrap"]
    assert [(x["key"], x["field"], x["value"]) for x in wraps] == \
        [("sim.current.metrics.fixed_wraps", "drive.udc_v", m["fixed_wraps"])]
    assert run_sim(SEED)["sim"]["current"]["metrics"]["fixed_wraps"] == 0
