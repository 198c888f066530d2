"""An induction motor's simulation (pulab.analyses.sim.induction) and its review findings.

1. Golden trajectories: tests/oracle/acim_sim_oracle.py (flux-linkage ODE discretized with
   scipy, float PI and the seed's PI in np.int32; never imports pulab).  The ``pu`` variant
   is compared with the oracle's ``si``.
2. The integer PIs in C: the feedback a run recorded replayed through gcc -m32 -fwrapv builds of
   the seed's PI (tests/oracle/seed_pi.c) and TI's (tests/oracle/vendor_pi.c), output for output.
3. Refusals name their field; the review's hot-rotor numbers against a time-domain run.
"""

from __future__ import annotations

import copy
import json
import math
import pathlib
import subprocess
import sys

import pytest

import pulab
from ctrace_compilers import require
from pulab.analyses import acim as acim_review
from pulab.analyses.sim import induction
from pulab.analyses.sim.current import run_fixed_steps as _fixed_steps, run_float
from pulab.analyses.sim.plant import acim_zoh
from pulab.analyses.sim.vendor_loop import run_profile_steps
from pulab.analyses.slices import finish
from pulab.schema.errors import InputError
from test_sim import _compare
from test_vendor_loop import _replay, oracle  # noqa: F401 (the compiled C oracle fixture)

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = sorted((ROOT / "tests/golden/acim-sim").glob("*.json"))
MEZ = {"motor": {"kind": "acim", "rated_voltage_v": 42 * math.sqrt(3.0), "rated_current_a": 1.5,
                 "rated_freq_hz": 50, "rated_speed_rpm": 1370, "pole_pairs": 2, "rs_ohm": 0.6,
                 "rr_ohm": 0.4, "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525,
                 "magnetizing_current_a": 0.55},
       "drive": {"udc_v": 150, "ts_s": 1e-4}}


def test_golden_files_exist_and_are_fresh():
    assert len(GOLDEN) >= 3
    r = subprocess.run([sys.executable, str(ROOT / "tests/oracle/acim_sim_oracle.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def _project(got: dict, exp: dict) -> dict:
    """pulab's section reduced to the oracle's keys (a key pulab lacks fails as KeyError)."""
    out = {k: got[k] for k in exp if k not in ("variants", "metrics")}
    out["variants"] = {k: {kk: got["variants"][k][kk] for kk in exp["variants"][k]}
                       for k in exp["variants"]}
    out["metrics"] = {k: {kk: got["metrics"][k][kk] for kk in exp["metrics"][k]}
                      for k in exp["metrics"]}
    return out


@pytest.mark.parametrize("path", GOLDEN, ids=[p.stem for p in GOLDEN])
def test_golden_trajectory(path):
    case = json.loads(path.read_text())
    sim = pulab.report(case["input"])["sim"]
    bad = []
    for sec in ("current", "flux"):
        exp = case["expected"][sec]
        _compare(_project(sim[sec], exp), exp, sec, case["compare"], bad)
        # the per-unit float run is the SI one in other units
        pu = {k: sim[sec]["variants"]["pu"][k] for k in exp["variants"]["si"]}
        _compare(pu, exp["variants"]["si"], f"{sec}.variants.pu", case["compare"], bad)
    assert not bad, "\n".join(bad[:20])


def test_seed_like_flux_numbers():
    r = pulab.report({**MEZ, "sim": {"current": {"axis": "q", "speed_hz": 20.0}}})
    f = r["sim"]["flux"]["metrics"]
    # ln 20·τ_r = 0.46059 s; the current loop (500 Hz) adds well under a millisecond
    assert r["acim"]["flux_95_s"] == pytest.approx(0.4605938, rel=1e-6)
    assert 0.0 <= f["si"]["flux_95_s"] - r["acim"]["flux_95_s"] < 1e-3
    assert f["fixed"]["wraps"] == 0 and f["fixed"]["vs_si_max_lsb"] < 2.0
    ti = r["sim"]["flux"]["by_profile"]["ti"]
    assert ti["ran"] and ti["events"]["wrap"] == 0 and ti["metrics"]["vs_si_max_abs_a"] < 1e-3
    assert r["sim"]["flux"]["by_profile"]["nxp"]["ran"] is False


@pytest.mark.parametrize("axis, speed, delay", [("q", 20.0, False), ("d", 0.0, True)])
def test_ti_closed_loop_equals_the_c_oracle(oracle, capsys, axis, speed, delay):  # noqa: F811
    require("arm", capsys)
    r = pulab.report(MEZ)
    s = induction._setup(r, {"axis": axis, "step_a": 0.6, "speed_hz": speed}, False)
    peak = math.sqrt(2.0)
    umax_pu = induction.voltage_limits(r["input"])[0]
    ctl = induction._ti_controller(r, umax_pu * r["base"]["U_b"] * peak)
    hd, hq = s["hold"]
    run = finish(run_profile_steps(s["z_si"](), ctl, peak, s["ref_d"], s["ref_q"], hq, 600,
                                   delay, record=True, hold_d_v=hd))
    run["name"] = "ti"
    for ax, ref, hold in (("d", s["ref_d"], hd), ("q", s["ref_q"], hq)):
        want, _ = _replay(oracle, ctl, ax, run, round(ref * peak / ctl["i_lsb"]),
                          ctl["start"](hold * peak))
        assert want == list(run[f"out_{ax}"])


def test_hot_rotor_angle_matches_a_time_domain_run():
    """Indirect FOC with the cold τ_r on a rotor whose R_r is 39.3 % higher, the currents held
    at their rated values by the float PI: the rotor flux's angle and size after 20·τ_r
    against :func:`pulab.analyses.acim.hot_rotor`."""
    r = pulab.report(MEZ)
    a, g = r["acim"], r["current_pi"]
    h = acim_review.hot_rotor(a, 0.00393)
    i_d, i_q = a["magnetizing_current_a"], a["torque_current_a"]
    w_sl = i_q / (a["tau_r_s"] * i_d)                       # the cold estimate
    ts = 1e-4
    z = acim_zoh(a["rs_ohm"], a["rr_ohm"] * 1.393, a["ls_h"], a["lr_h"], a["lm_h"], w_sl, 0.0,
                 ts)
    run = run_float(z, g["d"]["kp"], g["d"]["ki"] * ts, g["q"]["kp"], g["q"]["ki"] * ts, 1e3,
                    1e3, i_d, i_q, 0.0, int(20 * a["tau_r_s"] / ts), False)
    assert run["iq"][-1] == pytest.approx(i_q, rel=1e-9)
    psi_d, psi_q = z.flux[0][0][-1], z.flux[0][1][-1]
    assert math.degrees(math.atan2(psi_q, psi_d)) == pytest.approx(h["angle_deg"], abs=1e-6)
    psi_abs = math.hypot(psi_d, psi_q) / (a["lm_h"] * i_d)
    assert 100.0 * (psi_abs - 1.0) == pytest.approx(h["flux_pct"], abs=1e-6)


def test_review_torque_before_flux():
    slow = pulab.report({**MEZ, "sim": {"flux": {"startup_s": 0.2}}})["review"]["findings"]
    hit = [x for x in slow if x["code"] == "acim_torque_before_flux"]
    assert len(hit) == 1 and hit[0]["field"] == "sim.flux.startup_s"
    assert "72.5 %" in hit[0]["message"] and "72.5 %" in hit[0]["message_zh"]
    fine = pulab.report({**MEZ, "sim": {"flux": {"startup_s": 0.5}}})["review"]["findings"]
    assert not [x for x in fine if x["code"] == "acim_torque_before_flux"]


@pytest.mark.parametrize("sim, field", [
    ({"current": {"code": {"text": "int u;", "output": "u"}}}, "sim.current.code"),
    ({"current": {"axis": "d", "step_a": -1.0}}, "sim.current.step_a"),
    ({"current": {"speed_hz": 6000.0}}, "sim.current.speed_hz"),
    ({"flux": {"duration_s": 1e6}}, "sim.flux.duration_s"),
    ({"flux": {"startup_s": -1}}, "sim.flux.startup_s"),
])
def test_bad_sim_input_names_the_field(sim, field):
    with pytest.raises(InputError) as e:
        pulab.report({**MEZ, "sim": sim})
    assert e.value.field == field


def test_flux_section_is_an_induction_motors():
    pmsm = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                      "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
            "drive": {"udc_v": 24, "ts_s": 1e-4}, "sim": {"flux": {}}}
    with pytest.raises(InputError) as e:
        pulab.report(copy.deepcopy(pmsm))
    assert e.value.field == "sim.flux"


def test_board_for_an_induction_motor():
    """The board's chains do not depend on the motor; its torque per count is k_T per A peak
    (3·p·(L_m²/L_r)·I_m/√2 per A), and the dead time is judged against
    R_s·Î + 0.1·ω_n·√2·L_s·I_m."""
    board = {"current": {"shunt_ohm": 0.01, "gain": 20, "adc_bits": 12, "adc_ref_v": 3.3},
             "pwm": {"freq_hz": 10000, "deadtime_s": 1e-6, "clock_hz": 100e6}}
    r = pulab.report({**MEZ, "board": board})
    lsb = 3.3 / (0.01 * 20) / 4096                   # A per count, the whole ADC range
    c = r["board"]["current"]
    assert c["a_per_count"] == pytest.approx(lsb, rel=1e-15)
    kt_peak = 3 * 2 * 0.0525 ** 2 / 0.0615 * 0.55 / math.sqrt(2.0)
    assert c["nm_per_count"] == pytest.approx(kt_peak * lsb, rel=1e-12)
    dead = [x for x in r["review"]["findings"] if x["code"] == "board_deadtime"]
    need = 0.6 * 1.5 * math.sqrt(2.0) + 0.1 * 2 * math.pi * 50 * math.sqrt(2.0) * 0.0615 * 0.55
    assert len(dead) == 1 and dead[0]["value"] == pytest.approx(1.5 / need, rel=1e-9)


def test_csv_export_of_an_induction_motors_current_step():
    from pulab import api
    out = json.loads(api.call_json("export.csv_current",
                                   json.dumps({"input": {**MEZ, "sim": {"current": {"axis": "q"}}}})))
    assert out["ok"], out
    head, first = out["text"].splitlines()[:2]
    cols = head.split(",")
    assert {"si.psi_d_Wb", "fixed.iq_A", "ti.psi_q_Wb"} <= set(cols)
    assert float(first.split(",")[cols.index("si.psi_d_Wb")]) == pytest.approx(0.0525 * 0.55, rel=1e-12)


def test_text_report_lists_both_simulations(tmp_path):
    f = tmp_path / "acim.json"
    f.write_text(json.dumps({**MEZ, "sim": {"current": {"axis": "q"}}}))
    out = subprocess.run([sys.executable, "-m", "pulab", "report", str(f), "--format", "text"],
                         capture_output=True, text=True, env={"PYTHONPATH": str(ROOT / "py")})
    assert out.returncode == 0, out.stderr
    assert "Simulation: current step, axis q" in out.stdout
    assert "Simulation: flux build-up" in out.stdout and "flux_95_s 0.4606" in out.stdout


def test_default_flux_run_is_cut_at_the_cap_not_refused():
    """A rotor with τ_r = 4 s: 5·τ_r is 200 000 periods; the default run stops at the cap and says
    so, while the same length typed is refused naming the field."""
    slow = copy.deepcopy(MEZ)
    slow["motor"]["rr_ohm"] = 0.0615 / 4.0
    f = pulab.report({**slow, "sim": {}})["sim"]["flux"]
    assert f["complete"] is False and f["t"][-1] == pytest.approx(induction.MAX_PERIODS * 1e-4)
    assert f["metrics"]["si"]["flux_95_s"] is None          # 3·τ_r = 12 s is beyond 5 s
    with pytest.raises(InputError) as e:
        pulab.report({**slow, "sim": {"flux": {"duration_s": 20.0}}})
    assert e.value.field == "sim.flux.duration_s"


@pytest.mark.parametrize("axis, speed, delay, flux", [("q", 20.0, False, False),
                                                      ("d", 30.0, True, False),
                                                      ("d", 0.0, False, True)])
def test_seed_pi_closed_loop_equals_its_c(tmp_path, capsys, axis, speed, delay, flux):
    """The Inovance run's outputs (its applied voltages over U_b/2^12) against the seed's PI in C
    fed the run's own Q12 feedback: current steps and the flux build-up."""
    require("arm", capsys)
    exe = tmp_path / "seed_pi"
    subprocess.run(["gcc", "-m32", "-fwrapv", "-O1", "-o", str(exe),
                    str(ROOT / "tests/oracle/seed_pi.c")], check=True)
    r = pulab.report(MEZ)
    s = induction._setup(r, {"axis": axis, "step_a": 0.6, "speed_hz": speed}, flux)
    maxout, maxu = induction.voltage_limits(r["input"])[2]
    b, g = r["base"], r["current_pi"]
    hd, hq = s["hold"]
    q24 = [round(h / b["U_b"] * 2 ** 24) for h in (hd, hq)]
    refs = [round(x / b["I_b"] * 4096) for x in (s["ref_d"], s["ref_q"])]
    n = 3000
    run = finish(_fixed_steps(s["z_si"](), b["I_b"], b["U_b"], g["d"]["pm_kp"], g["d"]["pm_ki"],
                           g["q"]["pm_kp"], g["q"]["pm_ki"], maxu, maxout, *refs, q24[1], n, delay,
                           integ_d0=q24[0]))
    for k, ax in enumerate("dq"):
        text = "".join(f"{refs[k]} {f}\n" for f in run[f"fb_{ax}"])
        out = subprocess.run([str(exe), str(g[ax]["pm_kp"]), str(g[ax]["pm_ki"]), str(maxu),
                              str(maxout), str(q24[k])], input=text, capture_output=True,
                             text=True, check=True).stdout.split()
        want = [int(x) for x in out[0::2]]
        applied = [round(v / (b["U_b"] / 4096.0)) for v in run["u" + ax]]
        got = applied[1:] + [None] if delay else applied
        assert got[:n] == want[:n], ax


def test_voltage_saturation_is_flagged_in_every_run():
    """A 10 A step on a 1.5 A motor asks kp·10 A ≈ 524 V of a 61 V limit: every run saturates,
    the seed's PI counts it in its time at the limit, TI's in its events."""
    c = pulab.report({**MEZ, "sim": {"current": {"axis": "q", "step_a": 10.0,
                                                  "duration_s": 0.02}}})["sim"]["current"]
    for name in ("si", "pu", "fixed"):
        assert c["metrics"][name]["saturation_time_s"] > 0.0, name
    ti = c["by_profile"]["ti"]
    assert ti["metrics"]["saturation_time_s"] > 0.0 and ti["events"]["output_limit"] > 0
    assert c["metrics"]["fixed"]["wraps"] == 0
