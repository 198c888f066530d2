"""pulab.analyses.sim.vendor_loop: each vendor's integer PI closed around the plant.

1. Closed loop, bit for bit: the feedback integers a run recorded are replayed through the C
   oracle (tests/oracle/vendor_pi.c, gcc -m32 -fwrapv, never imports pulab) from the same
   start; its outputs must equal the run's, integer by integer, and its counts of wraps,
   saturations and limits the run's — on the seed motor and on a stressed run that drives
   every controller into its limits.
2. Against float: the fixed-point currents stay within a stated tolerance of a float PI of
   the same structure on the same plant (TI, NXP, ST: the report's ``si`` variant, whose
   order — integral, then output — is theirs; Microchip's CalcPI updates the integral
   after the output, so its float twin is written here).
"""

from __future__ import annotations

import math
import pathlib
import subprocess

import pytest

from ctrace_compilers import require
from pulab import report
from pulab.analyses.sim import current, vendor_loop
from pulab.analyses.sim.plant import zoh
from pulab.analyses.slices import finish

ORACLE = pathlib.Path(__file__).resolve().parents[1] / "oracle" / "vendor_pi.c"
ORDER = {"ti": ("kp", "ki", "out_max", "out_min", "q"),
         "nxp": ("kp", "ki", "upper", "lower", "trapezoidal"),
         "st": ("kp", "ki", "kp_log", "ki_log", "integral_limit"),
         "microchip": ("kp", "ki", "kc", "out_max", "out_min", "kp_shift", "ki_shift")}


@pytest.fixture(scope="module")
def oracle(tmp_path_factory):
    exe = tmp_path_factory.mktemp("vendor_loop") / "vendor_pi"
    subprocess.run(["gcc", "-m32", "-fwrapv", "-O1", "-o", str(exe), str(ORACLE)], check=True)
    return exe


def _run(seed_input, name: str, step_a: float, speed_hz: float, delay: bool, axis: str = "q"):
    """A report with the sim, and the full-rate run of one profile with its controller."""
    r = report(seed_input)
    profiles, _ = vendor_loop.profile_data(r)
    umax_pu, _, _ = current.voltage_limits(r)
    peak = math.sqrt(2.0)
    ctl = vendor_loop.controllers(profiles, umax_pu * r["base"]["U_b"] * peak,
                                  r["input"]["drive"]["udc_v"])[name]
    m, ts = r["input"]["motor"], r["input"]["drive"]["ts_s"]
    z = zoh(m["rs_ohm"], m["ld_h"], m["lq_h"], r["pu"]["psi_r_wb"], 2 * math.pi * speed_hz, ts)
    n = 600
    ref = (0.0, step_a) if axis == "q" else (step_a, 0.0)
    run = finish(vendor_loop.run_profile_steps(z, ctl, peak, *ref, z.bemf, n, delay,
                                               record=True))
    return r, ctl, z, run


def _replay(exe, ctl: dict, axis: str, run: dict, ref: int, state: tuple) -> tuple:
    """The oracle's outputs for one axis, and its event counts (wrap, saturate,
    integral_limit, output_limit)."""
    kw = ctl["steps"][axis].keywords
    args = [int(kw[k]) for k in ORDER[run["name"]]] + list(state)
    text = "".join(f"{ref} {f}\n" for f in run[f"fb_{axis}"])
    res = subprocess.run([str(exe), run["name"]] + [str(a) for a in args], input=text,
                         capture_output=True, text=True, check=True)
    *rows, last = res.stdout.splitlines()
    return [int(line.split()[0]) for line in rows], [int(x) for x in last.split()[1:]]


@pytest.mark.parametrize("name", vendor_loop.names())
@pytest.mark.parametrize("stress", [False, True])
def test_closed_loop_outputs_equal_the_c_oracle(oracle, capsys, seed_input, name, stress):
    require("arm", capsys)
    # Stressed: a step of 2.8 A (2.8·√2 = 3.96 A peak, near every full scale of 4.24 A),
    # at 150 Hz electrical with a one-sample delay — the outputs hit their limits.
    step, speed, delay = (2.8, 150.0, True) if stress else (0.75, 0.0, False)
    _, ctl, z, run = _run(seed_input, name, step, speed, delay)
    run["name"] = name
    peak = math.sqrt(2.0)
    refs = {"d": 0, "q": round(step * peak / ctl["i_lsb"])}
    if name in ("nxp", "st", "microchip"):
        refs["q"] = min(refs["q"], 32767)
    starts = {"d": ctl["start"](0.0), "q": ctl["start"](z.bemf * peak)}
    mismatches = 0
    events = [0, 0, 0, 0]
    for axis in ("d", "q"):
        want, ev = _replay(oracle, ctl, axis, run, refs[axis], starts[axis])
        got = list(run[f"out_{axis}"])
        assert len(want) == len(got) > 400
        mismatches += sum(g != w for g, w in zip(got, want))
        events = [a + b for a, b in zip(events, ev)]
    assert mismatches == 0
    assert events == [run["events"][k] for k in ("wrap", "saturate", "integral_limit",
                                                  "output_limit")]
    if stress:
        assert run["events"]["output_limit"] > 0, run["events"]


def _microchip_float(z, kp: float, ki_ts: float, kc: float, umax: float, ref_q: float,
                     n: int) -> list:
    """CalcPI's order in float (V, A): out = Sum + kp·e, clamp; Sum += ki·Ts·e − kc·(U − out);
    q axis from the back-EMF, d axis from 0 (reference 0)."""
    p0, p1, p2, p3 = z.phi
    g0, g1, g2, g3 = z.gamma
    sums = [0.0, z.bemf]
    xd = xq = 0.0
    iq = []
    for _ in range(n + 1):
        iq.append(xq)
        outs = []
        for a, (x, r) in enumerate(((xd, 0.0), (xq, ref_q))):
            e = r - x
            u = sums[a] + kp * e
            o = max(-umax, min(umax, u))
            sums[a] += ki_ts * e - kc * (u - o)
            outs.append(o)
        vq = outs[1] - z.bemf
        xd, xq = p0 * xd + p1 * xq + g0 * outs[0] + g1 * vq, p2 * xd + p3 * xq + g2 * outs[0] + g3 * vq
    return iq


@pytest.mark.parametrize("name", vendor_loop.names())
def test_fixed_point_stays_near_a_float_pi_of_its_structure(seed_input, name):
    # Tolerance: 2 counts of the vendor's current word (feedback rounding) plus 1e-4 of the
    # step (the stored gains' relative rounding is ≤ 6e-5 on this motor: TI's truncated Kp,
    # NXP's ACC32, ST's int16/16384, Microchip's Q15).
    step = 0.75
    r, ctl, z, run = _run(seed_input, name, step, 0.0, False)
    tol = 2 * run["lsb_a"] + 1e-4 * step
    n = len(run["iq"]) - 1
    if name == "microchip":
        g = r["current_pi"]["q"]
        umax = current.voltage_limits(r)[0] * r["base"]["U_b"]
        ref_iq = _microchip_float(z, g["kp"], g["ki"] * r["input"]["drive"]["ts_s"],
                                  32767 / 32768, umax, step, n)
    else:
        umax_pu, imax_pu, _ = current.voltage_limits(r)
        gd, gq = r["current_pi"]["d"], r["current_pi"]["q"]
        ts, u_b = r["input"]["drive"]["ts_s"], r["base"]["U_b"]
        ref_iq = current.run_float(z, gd["kp"], gd["ki"] * ts, gq["kp"], gq["ki"] * ts,
                                   umax_pu * u_b, imax_pu * u_b, 0.0, step, z.bemf, n,
                                   False)["iq"]
    worst = max(abs(a - b) for a, b in zip(run["iq"], ref_iq))
    assert worst <= tol, (name, worst, tol)
    assert sum(run["events"].values()) == 0, run["events"]


def test_report_metrics_of_every_profile(seed_input):
    # The report's by_profile metrics: each rise time within one period of the float run's
    # and no event on the seed motor's default step; vs_si in counts is vs_si / lsb_a.
    r = report({**seed_input, "sim": {}})
    c = r["sim"]["current"]
    ts = r["input"]["drive"]["ts_s"]
    assert sorted(c["by_profile"]) == sorted(vendor_loop.names())
    for name, b in c["by_profile"].items():
        assert b["ran"] is True
        m = b["metrics"]
        assert abs(m["rise_time_s"] - c["metrics"]["si"]["rise_time_s"]) < ts, name
        assert m["vs_si_max_lsb"] == pytest.approx(m["vs_si_max_abs_a"] / b["lsb_a"], rel=1e-12)
        assert set(b["events"]) == set(vendor_loop.EVENT_NAMES)
        assert len(b["variant"]["iq"]) == len(c["t"])


def test_every_profile_runs_whichever_firmware_is_shipped(seed_input):
    # The report then holds the shipped profile alone; the simulation still runs all of them.
    r = report({**seed_input, "sim": {}, "conventions": {"firmware": "ti"}})
    assert list(r["profiles"]) == ["ti"]
    assert sorted(r["sim"]["current"]["by_profile"]) == sorted(vendor_loop.names())


def test_a_profile_that_cannot_hold_the_gains_does_not_run(seed_input):
    # 500 kHz bandwidth: kp·I_FS/V_FS = 2π·5e5·6e-4·4.243/24 ≈ 333, beyond IQ24's ±128 —
    # TI's Kp does not fit, so TI has no run; it names the fields of firmware.ti.problems.
    inp = {**seed_input, "current_loop": {"bandwidth_hz": 500000}, "sim": {}, "profiles": {}}
    r = report(inp)
    ti = r["sim"]["current"]["by_profile"]["ti"]
    assert ti == {"ran": False, "problems": [{"field": p["field"], "code": p["code"]}
                                             for p in r["firmware"]["ti"]["problems"]]}
    assert [p["field"] for p in ti["problems"]] == ["profiles.ti.Kp_Id", "profiles.ti.Kp_Iq"]
    assert r["sim"]["current"]["by_profile"]["nxp"]["ran"] is True


def test_any_profile_options_run_or_say_why_never_crash(seed_input):
    # Random hardware options over their whole input ranges (full scales from 1e-6 to 1e6,
    # every GLOBAL_Q, every power-of-two divider) and random loops: every profile either runs
    # with finite currents or is marked not representable; the report stays strict JSON.
    import json
    import random
    rng = random.Random(20261126)
    keys = {"ti": ("full_scale_voltage_v", "full_scale_current_a", "global_q"),
            "nxp": ("udcb_max_v", "i_max_a", "u_max_coeff", "trapezoidal"),
            "st": ("rshunt_ohm", "amplification_gain", "adc_reference_v", "tf_kpdiv", "tf_kidiv"),
            "microchip": ("voltage_base_v", "current_base_a")}
    ran = skipped = 0
    for _ in range(40):
        prof = {}
        for v, ks in keys.items():
            prof[v] = {}
            for k in ks:
                if rng.random() < 0.5:
                    continue
                prof[v][k] = (rng.randint(1, 30) if k == "global_q" else
                              1 << rng.randint(0, 15) if k.startswith("tf_") else
                              rng.random() < 0.5 if k == "trapezoidal" else
                              10 ** rng.uniform(-6, 6))
        r = report({**seed_input, "profiles": prof,
                    "current_loop": {"bandwidth_hz": 10 ** rng.uniform(0, 4)},
                    "sim": {"current": {"axis": rng.choice("dq"), "delay": rng.random() < 0.5,
                                        "speed_hz": rng.uniform(-1000, 1000),
                                        "duration_s": 0.01}}})
        json.dumps(r, allow_nan=False)
        for name, b in r["sim"]["current"]["by_profile"].items():
            assert b["ran"] is r["firmware"][name]["representable"]
            if b["ran"]:
                ran += 1
                assert all(math.isfinite(x) for k in ("id", "iq") for x in b["variant"][k])
            else:
                skipped += 1
    assert ran > 40 and skipped > 10, (ran, skipped)


def test_lsb_is_one_count_of_each_vendors_own_current_scale():
    """EMRAX 228 LV (rms bases, TI shipped): one count is the profile's full-scale current (A,
    phase peak) over its word — TI 2·√2·450 A / 2^24, NXP/ST/Microchip 2·√2·450 A / 2^15 — in the
    report's dq scale (÷ √2 for rms bases), so |vendor − SI| in counts is that difference over it."""
    import json
    root = pathlib.Path(__file__).resolve().parents[2]
    inp = json.loads((root / "tests/golden/datasheets/emrax_228_lv.json").read_text())["input"]
    r = report({**inp, "conventions": {"firmware": "ti"}, "sim": {}, "profiles": {}})
    assert r["input"]["conventions"]["base"] == "rms"
    full = 2 * math.sqrt(2) * 450.0  # A peak: twice the rated current's peak (1272.79 A)
    words = {"ti": 2 ** 24, "nxp": 2 ** 15, "st": 2 ** 15, "microchip": 2 ** 15}
    fields = {"ti": "full_scale_current_a", "nxp": "i_max_a", "st": "max_current_a",
              "microchip": "current_base_a"}
    for name, b in r["sim"]["current"]["by_profile"].items():
        assert r["profiles"][name]["inputs"][fields[name]] == pytest.approx(full, rel=1e-12)
        lsb = full / words[name] / math.sqrt(2)
        assert b["lsb_a"] == pytest.approx(lsb, rel=1e-12), name
        m = b["metrics"]
        assert m["vs_si_max_lsb"] == pytest.approx(m["vs_si_max_abs_a"] / lsb, rel=1e-12), name
    # TI: 900 A / 2^24 per count in the rms dq scale is the same count as 1272.79 A / 2^24 peak
    assert r["sim"]["current"]["by_profile"]["ti"]["lsb_a"] == pytest.approx(900.0 / 2 ** 24,
                                                                             rel=1e-12)
