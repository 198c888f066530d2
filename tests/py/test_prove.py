"""Family proofs: verdicts at the seed motor's known boundaries, counterexamples that reproduce,
budgets and bad requests.  (Soundness against an enumeration that does not import pulab:
tests/py/test_prove_oracle.py.)"""
import json
import os
import subprocess
import sys

import pytest

from pulab import report
from pulab.api import call_json
from pulab.analyses.prove import prove
from pulab.schema.errors import InputError

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}}


def _prove(ranges, **kw):
    return prove({"input": SEED, "ranges": ranges, **kw})


def test_ld_boundary_of_the_seed_motor_is_where_the_sweep_found_it():
    # The sweep's bisection (pulab.analyses.sweep docs): LD's store wraps from raw Current
    # 6948, i.e. from 69.47500000000001 A; 69.47 A is still Current 6947.
    below = _prove({"motor.rated_current_a": [1, 69.47]})["integers"]["vendor.LD"]
    assert below["verdict"] == "proven" and below["proven_fraction"] == 1.0
    above = _prove({"motor.rated_current_a": [1, 69.48]})["integers"]["vendor.LD"]
    assert above["verdict"] == "violated" and above["kind"] == "store"
    ce = above["counterexample"]
    assert 69.475 < ce["motor"]["rated_current_a"] <= 69.48
    r = report(ce)
    assert "store" in r["vendor"]["LD"]["flags"]
    assert above["statement"] == "gMotorExtPer.LD = m_Ulong / 10; // Q13"


def test_every_counterexample_reproduces_and_lies_in_the_box():
    ranges = {"motor.rated_current_a": [0.5, 130], "motor.rated_voltage_v": [5, 400],
              "drive.base_freq_hz": [50, 1000], "motor.rated_freq_hz": [50, 1000],
              "motor.bemf_v": [1, 400], "drive.udc_v": [12, 800]}
    r = _prove(ranges)
    assert r["verdict"] == "violated"
    seen = 0
    for name, e in r["integers"].items():
        if e["verdict"] != "violated":
            continue
        seen += 1
        ce = e["counterexample"]
        for path, (lo, hi) in ranges.items():
            sec, key = path.split(".")
            assert lo <= ce[sec][key] <= hi, (name, path)
        out = report(ce)
        field = name.split(".")[1]
        if name.startswith("raw."):
            assert field not in out["vendor"]["raw"]
        else:
            v = out["vendor"].get(field)
            assert v is None or v["value"] == 0 or {"wrap", "store"} & set(v["flags"]), name
    assert seen >= 3


def test_a_small_family_is_proven_with_exact_end_values():
    r = _prove({"motor.rated_current_a": [1, 4], "motor.rs_ohm": [0.5, 2]})
    assert r["verdict"] == "proven" and "counterexample" not in r
    rpm = r["integers"]["vendor.Rpm"]
    # Ends by hand from seed 1.4-1: (500·100/17 = 2941)·18597 >> 14 = 3338 and
    # (2000·400/17 = 47058)·18597 >> 14 = 53414.
    assert rpm["range"] == [3338, 53414] and rpm["word"] == [0, 65535]
    assert r["integers"]["raw.Current"]["range"] == [100, 400]
    # |round(x) − x| ≤ 1/2 of raw Current 100 (1 A): 0.5 %.
    assert r["integers"]["raw.Current"]["worst_error_pct"] == pytest.approx(0.5, abs=1e-12)


def test_a_raw_parameter_beyond_uint16_is_violated_at_65536():
    e = _prove({"motor.rated_current_a": [600, 700]})["integers"]["raw.Current"]
    assert e["verdict"] == "violated" and e["kind"] == "outside" and e["raw"] == {"Current": 65536}
    assert e["counterexample"]["motor"]["rated_current_a"] == pytest.approx(655.36)
    assert "Current" not in report(e["counterexample"])["vendor"]["raw"]


def test_a_violation_inside_the_box_is_found_by_splitting_and_a_tiny_budget_says_unknown():
    # f_b ≤ 110 Hz makes FreqPer = f_n/f_b·2^15 ≥ 2^16 for the seed's f_n = 220 Hz: its Uint16
    # store wraps to a small number and FluxRotor, divided by it, overflows — but only just
    # below 110 Hz: at 101.9 Hz FreqPer wraps to 5207 and FluxRotor still fits (18192).
    ranges = {"drive.base_freq_hz": [101.9, 348]}
    flux = _prove(ranges)["integers"]["vendor.FluxRotor"]
    assert flux["verdict"] == "violated" and flux["kind"] == "store"
    f_b = flux["counterexample"]["drive"]["base_freq_hz"]
    assert 101.9 < f_b <= 110
    assert "store" in report(flux["counterexample"])["vendor"]["FluxRotor"]["flags"]
    short = _prove(ranges, budget=1)["integers"]["vendor.FluxRotor"]
    assert short["verdict"] == "unknown" and short["proven_fraction"] == 0.0


def test_division_by_zero_is_a_counterexample():
    # FullFreq01 = 0 from f_b < 0.005 Hz is refused by the input checks, so divide by a
    # Voltage·10 that wraps to 0 in 16-bit unsigned int: 32768·10 = 5·65536 ≡ 0.
    r = _prove({"motor.rated_voltage_v": [32768, 32768]})
    flux = r["integers"]["vendor.FluxRotor"]
    assert flux["verdict"] == "violated" and flux["kind"] == "div0"
    assert "FluxRotor" not in report(flux["counterexample"])["vendor"]


@pytest.mark.parametrize("req, field", [
    ({"input": SEED}, "prove.ranges"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [2, 1]}}, "prove.ranges.motor.rs_ohm"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [1]}}, "prove.ranges.motor.rs_ohm"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [1, "x"]}}, "prove.ranges.motor.rs_ohm"),
    ({"input": SEED, "ranges": {"motor.name": [1, 2]}}, "prove.ranges.motor.name"),
    ({"input": SEED, "ranges": {"raw.Current": [1.5, 2]}}, "prove.ranges.raw.Current"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [-1, 2]}}, "motor.rs_ohm"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [1, 2]}, "profile": "renesas"}, "prove.profile"),
    ({"input": SEED, "ranges": {"motor.rs_ohm": [1, 2]}, "budget": 0}, "prove.budget"),
    ({"ranges": {"motor.rs_ohm": [1, 2]}}, "input"),
    ([], "prove"),
])
def test_bad_requests_name_the_field(req, field):
    with pytest.raises(InputError) as e:
        prove(req)
    assert e.value.field == field


def _cli(tmp_path, *args):
    f = tmp_path / "seed.json"
    f.write_text(json.dumps(SEED))
    return subprocess.run([sys.executable, "-m", "pulab", "prove", str(f), *args],
                          capture_output=True, text=True, env={**os.environ, "PYTHONPATH": "py"})


def test_cli_exit_status_is_the_verdict(tmp_path):
    ok = _cli(tmp_path, "--range", "motor.rated_current_a=1:4", "--range", "motor.rs_ohm=0.5:2")
    assert ok.returncode == 0 and json.loads(ok.stdout)["verdict"] == "proven"
    bad = _cli(tmp_path, "--range", "motor.rated_current_a=1:100", "--format", "text")
    assert bad.returncode == 1 and "vendor.LD              violated" in bad.stdout
    unknown = _cli(tmp_path, "--range", "drive.base_freq_hz=101.9:348", "--budget", "1")
    assert unknown.returncode == 1
    assert json.loads(unknown.stdout)["integers"]["vendor.FluxRotor"]["verdict"] == "unknown"


@pytest.mark.parametrize("args, line", [
    (("--range", "motor.rs_ohm=1"), "error: prove.ranges: expected PATH=LO:HI, got 'motor.rs_ohm=1'"),
    (("--range", "motor.rs_ohm=2:1"), "error: prove.ranges.motor.rs_ohm: lo must be ≤ hi, got 2 > 1"),
    # the end that is not whole is quoted, not "a list"
    (("--range", "motor.pole_pairs=1.5:3"), "error: prove.ranges.motor.pole_pairs: must be [lo, hi] "
     "(integers for a raw or integer input), got 1.5"),
    ((), "error: prove.ranges: give at least one input range (PATH=LO:HI)"),
    (("--range", "motor.rs_ohm=1:2", "--profile", "renesas"),
     "error: prove.profile: a proof covers the profiles inovance, ti, nxp, st, microchip, "
     "got 'renesas'"),
])
def test_cli_bad_request_is_one_line_and_exit_2(tmp_path, args, line):
    r = _cli(tmp_path, *args)
    assert r.returncode == 2 and r.stderr == line + "\n" and r.stdout == ""


def test_api_by_integer_then_summary_equals_the_whole_proof():
    req = {"input": SEED, "ranges": {"motor.rated_current_a": [1, 100]}}
    whole = json.loads(call_json("prove", json.dumps(req)))["proof"]
    plan = json.loads(call_json("prove.plan", json.dumps(req)))["plan"]
    entries = {n: json.loads(call_json("prove.integer", json.dumps({**req, "name": n})))["integer"]
               for n in plan["names"]}
    merged = json.loads(call_json("prove.summary", json.dumps({**req, "integers": entries})))
    assert merged["proof"] == whole
    err = json.loads(call_json("prove.integer", json.dumps({**req, "name": "vendor.X"})))
    assert err["ok"] is False and err["field"] == "prove.name"


@pytest.mark.parametrize("profile, ranges, key, flag", [
    ("nxp", {"motor.ld_h": [1e-3, 1], "motor.rated_current_a": [5, 200]}, "M1_D_KP_GAIN",
     "saturate"),
    ("st", {"motor.rated_current_a": [0.01, 2]}, "CURRENT_CONV_FACTOR", "out_of_range"),
    ("microchip", {"motor.rated_current_a": [1, 40]}, "MCAF_MOTOR_RS", "out_of_range"),
])
def test_vendor_counterexamples_reproduce_in_the_report(profile, ranges, key, flag):
    r = _prove(ranges, profile=profile)
    e = r["integers"][f"profiles.{profile}.constants.{key}"]
    assert r["verdict"] == "violated" and e["verdict"] == "violated"
    c = report(e["counterexample"])["profiles"][profile]["constants"][key]
    assert flag in c["flags"]


def test_shifts_and_divisors_are_integers_of_the_proof():
    ranges = {"drive.ts_s": [1e-5, 2e-4], "drive.base_freq_hz": [50, 2000]}
    shift = _prove(ranges, profile="nxp")["integers"]["profiles.nxp.shifts.M1_TO_THETA_SHIFT"]
    # T_s·ω_max/π = 2·T_s·f_b spans [1e-3, 0.8]: mantissa in [0.5, 1) with shifts −9 … 0.
    assert shift["verdict"] == "proven" and shift["range"] == [-9, 0]
    st = _prove({"motor.ld_h": [1e-4, 1e-2]}, profile="st")["integers"]
    # Kp grows with L_d, so the divisor falls: its ends are the oracle's at the box's ends.
    from conftest import ROOT
    sys.path.insert(0, str(ROOT / "tests/oracle"))
    import profiles_oracle
    ends = []
    for ld in (1e-2, 1e-4):
        chosen = {}
        profiles_oracle.profiles({**SEED, "motor": {**SEED["motor"], "ld_h": ld},
                                  "profiles": {"st": {}}}, chosen)
        ends.append(chosen["st"]["TF_KPDIV"])
    assert st["profiles.st.divisors.TF_KPDIV"]["range"] == ends and ends[0] < ends[1]
    assert st["profiles.st.constants.PID_FLUX_KP_DEFAULT"]["error_bound"] is True


def test_cli_propose_for_a_vendor_profile(tmp_path):
    r = _cli(tmp_path, "--range", "motor.rated_current_a=1:40", "--profile", "microchip",
             "--propose")
    out = json.loads(r.stdout)
    assert r.returncode == 1  # Q15 does not hold R_s/(V_b/I_b) up to 7
    rs = out["proposal"]["constants"]["MCAF_MOTOR_RS"]
    assert rs["format"] == "Q12" and rs["holds"] and rs["current"] == "Q15"
