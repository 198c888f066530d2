"""pulab.analyses.loop.robust: the corners against the python-control oracle
tests/oracle/robust_oracle.py (golden files tests/golden/robust), the inputs, the search, the
Monte Carlo's reproducibility and the CLI."""

from __future__ import annotations

import copy
import json
import math
import os
import pathlib
import subprocess
import sys

import pytest

import pulab
from pulab.api import call_json
from pulab.schema.errors import InputError
from pulab.analyses.loop import robust
from conftest import chinese

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden" / "robust"
CASES = sorted(GOLDEN.glob("*.json"))
REL = 1e-6
SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 1e-4}, "analysis": {"robust": {}}}


def _close(a, e) -> bool:
    return abs(a - e) <= REL * max(abs(a), abs(e)) + 1e-9


def test_golden_files_not_stale():
    r = subprocess.run([sys.executable, str(ROOT / "tests" / "oracle" / "robust_oracle.py"),
                        "--check"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_enough_motors():
    assert len(CASES) >= 10


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_corners_match_python_control(path):
    case = json.loads(path.read_text(encoding="utf-8"))
    got = pulab.report(case["input"])["loop"]["robust"]["cases"]
    expected = case["expected"]["cases"]
    assert [c["kind"] for c in got[:len(expected)]] == ["nominal"] + ["corner"] * 8
    problems = []
    for k, (e, a) in enumerate(zip(expected, got)):
        for key in ("temperature_c", "current_a", "udc_v", "rs_ohm", "ld_h", "lq_h", "psi_wb",
                    "voltage_headroom_pct"):
            if not _close(a[key], e[key]):
                problems.append(f"cases[{k}].{key}: {a[key]} vs {e[key]}")
        for axis in ("d", "q"):
            for key, v in e[axis].items():
                w = a[axis][key]
                if v is None or isinstance(v, bool):
                    ok = w is v
                else:
                    ok = w is not None and _close(w, v)
                if not ok:
                    problems.append(f"cases[{k}].{axis}.{key}: {w} vs {v}")
    assert not problems, "\n".join(problems[:20])


def test_defaults_as_the_contract_states():
    cfg = robust.settings({})
    assert cfg["temperature_c"] == [20.0, 155.0] and cfg["reference_c"] == 20.0
    assert cfg["copper_alpha_per_k"] == 0.00393 and cfg["magnet_pct_per_k"] == -0.12
    assert cfg["inductance_drop_pct"] == 30.0 and cfg["peak_current_a"] is None
    assert cfg["udc_tolerance_pct"] == 10.0 and cfg["samples"] == 0
    assert (cfg["min_phase_margin_deg"], cfg["min_gain_margin_db"]) == (45.0, 6.0)
    r = pulab.report(SEED)["loop"]["robust"]
    assert r["config"]["peak_current_a"] == 3.0
    assert "monte_carlo" not in r


@pytest.mark.parametrize("value, field, code", [
    ({"temperature_c": [155, 20]}, "analysis.robust.temperature_c", "pair_order"),
    ({"temperature_c": 155}, "analysis.robust.temperature_c", "not_pair"),
    ({"temperature_c": [20, 155, 200]}, "analysis.robust.temperature_c", "not_pair"),
    ({"temperature_c": [-273.15, 20]}, "analysis.robust.temperature_c[0]", "out_of_range"),
    ({"temperature_c": [20, 400.5]}, "analysis.robust.temperature_c[1]", "out_of_range"),
    ({"temperature_c": [20, "hot"]}, "analysis.robust.temperature_c[1]", "not_number"),
    ({"magnet": "alnico"}, "analysis.robust.magnet", "not_name_or_number"),
    ({"magnet": True}, "analysis.robust.magnet", "not_number"),
    ({"magnet": -1.5}, "analysis.robust.magnet", "out_of_range"),
    ({"samples": -1}, "analysis.robust.samples", "integer_range"),
    ({"samples": 1.5}, "analysis.robust.samples", "not_integer"),
    ({"samples": 1_000_001}, "analysis.robust.samples", "integer_range"),
    ({"grid": 1}, "analysis.robust.grid", "integer_range"),
    ({"inductance_table": [[0, 1e-3, 1e-3]]}, "analysis.robust.inductance_table", "not_table"),
    ({"inductance_table": [[0, 1e-3, 1e-3], [0, 1e-3, 1e-3]]},
     "analysis.robust.inductance_table[1][0]", "not_increasing"),
    ({"inductance_table": [[0, 1e-3, 1e-3], [1, "x", 1e-3]]},
     "analysis.robust.inductance_table[1][1]", "not_number"),
    ({"inductance_table": [[0, 1e-3, 1e-3], [1, 1e-3]]},
     "analysis.robust.inductance_table[1]", "not_row"),
    ({"inductance_table": [[-1, 1e-3, 1e-3], [1, 1e-3, 1e-3]]},
     "analysis.robust.inductance_table[0][0]", "negative"),
    ({"inductance_table": [[0, 1e-3, 0], [1, 1e-3, 1e-3]]},
     "analysis.robust.inductance_table[0][2]", "not_positive"),
    ({"bus_compensated": 1}, "analysis.robust.bus_compensated", "not_flag"),
    ({"min_phase_margin_deg": 120}, "analysis.robust.min_phase_margin_deg", "out_of_range"),
    ({"peak_current_a": 0}, "analysis.robust.peak_current_a", "not_positive"),
    ({"reference_c": 10 ** 400}, "analysis.robust.reference_c", "not_finite"),
    ({"colour": 1}, "analysis.robust.colour", "unknown_field"),
    ("hot", "analysis.robust", "not_object"),
])
def test_bad_input_names_the_field(value, field, code):
    inp = copy.deepcopy(SEED)
    inp["analysis"]["robust"] = value
    with pytest.raises(InputError) as e:
        pulab.report(inp)
    assert (e.value.field, e.value.code) == (field, code)
    assert chinese(e.value.message_zh) and e.value.message_zh != e.value.message


def test_the_section_as_the_analysis_reads_it():
    """Defaults, a magnet by name or by number, the table's rows as numbers (settings = the
    schema's checked section with the magnet's coefficient)."""
    cfg = robust.settings({})
    assert cfg["temperature_c"] == [20.0, 155.0] and cfg["magnet_pct_per_k"] == -0.12
    assert cfg["grid"] == 7 and cfg["samples"] == 0 and cfg["inductance_table"] is None
    assert "magnet" not in cfg
    assert robust.settings({"magnet": "smco"})["magnet_pct_per_k"] == -0.035
    assert robust.settings({"magnet": -0.5})["magnet_pct_per_k"] == -0.5
    table = robust.settings({"inductance_table": [[0, 1e-3, 2e-3], [10, 8e-4, 1.5e-3]]})
    assert table["inductance_table"] == [[0.0, 1e-3, 2e-3], [10.0, 8e-4, 1.5e-3]]
    assert robust.settings({"temperature_c": [-40, -40]})["temperature_c"] == [-40.0, -40.0]


def test_cli_bad_input_exit_2(tmp_path):
    inp = copy.deepcopy(SEED)
    inp["analysis"]["robust"] = {"magnet": "alnico"}
    path = tmp_path / "in.json"
    path.write_text(json.dumps(inp))
    r = subprocess.run([sys.executable, "-m", "pulab", "robust", str(path)], capture_output=True,
                       text=True, env={"PYTHONPATH": str(ROOT / "py")})
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and "analysis.robust.magnet" in r.stderr


def test_worst_is_no_better_than_any_corner_or_grid_point():
    r = pulab.report(SEED)["loop"]["robust"]
    w = r["worst"][r["worst"]["axis"]]["phase_margin_deg"]
    assert all(c[a]["phase_margin_deg"] >= w for c in r["cases"] for a in ("d", "q"))
    assert all(v >= w - 1e-12 for row in r["map"]["q"]["phase_margin_deg"] for v in row)
    assert r["cases"][r["worst"]["case"]]["q"] == r["worst"]["q"]


def test_search_finds_an_interior_minimum():
    # A table whose inductance dips in the middle of the current range: the worst phase
    # margin is inside the box, not at a corner.
    inp = copy.deepcopy(SEED)
    inp["analysis"]["robust"] = {"inductance_table": [[0, 6e-4, 6e-4], [1.4, 2e-4, 2e-4],
                                                      [3, 6e-4, 6e-4]], "grid": 4}
    r = pulab.report(inp)["loop"]["robust"]
    worst = r["cases"][r["worst"]["case"]]
    assert worst["kind"] == "search"
    assert 0.0 < worst["current_a"] < 3.0
    corner_pm = min(c["q"]["phase_margin_deg"] for c in r["cases"] if c["kind"] == "corner")
    assert worst["q"]["phase_margin_deg"] < corner_pm


def test_safe_band_is_safe_and_its_edges_are_not():
    r = pulab.report(SEED)["loop"]["robust"]
    lo, hi = r["safe_bandwidth_hz"]
    assert 0 < lo < hi < 0.5 / 1e-4
    inp = copy.deepcopy(SEED)
    cfg = robust.settings({})
    base = pulab.report({k: v for k, v in SEED.items() if k != "analysis"})
    from pulab.analyses.loop import current

    def worst_pm(f):
        kp, ki = current.design(1.5, 6e-4, 1e-4, "computation_pwm", "bandwidth", f)
        b = copy.deepcopy(base)
        for a in ("d", "q"):
            b["current_pi"][a]["from_integers"] = {"kp": kp, "ki": ki}
        out = robust.analyze(b, cfg, "computation_pwm", band=False)
        corners = [c for c in out["cases"] if c["kind"] == "corner"]
        return min(c["q"]["phase_margin_deg"] for c in corners), \
            min(c["q"]["gain_margin_db"] for c in corners)
    pm, gm = worst_pm(hi * 0.999)
    assert pm >= 45 and gm >= 6
    pm, gm = worst_pm(hi * 1.01)
    assert pm < 45 or gm < 6
    del inp


def test_hot_saturated_warning_names_the_corner():
    r = pulab.report(SEED)
    w = [x for x in r["warnings"] if x.startswith("loop.robust")]
    assert w and "20 °C, 3 A" in w[0] and "Hz keep it at every corner" in w[0]


IND380 = {"motor": {"rated_voltage_v": 380, "rated_current_a": 14.5, "rated_freq_hz": 50,
                    "rs_ohm": 0.42, "ld_h": 0.0085, "lq_h": 0.0135, "bemf_v": 335.0,
                    "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 0.000125},
          "analysis": {"robust": {}}}


@pytest.mark.parametrize("bandwidth_hz, findings", [(500.0, 2), (300.0, 0)])
def test_review_names_the_bandwidth_and_is_quiet_inside_the_safe_band(bandwidth_hz, findings):
    # Tuned cold at 500 Hz the 7.5 kW motor loses both margins at peak current; designed at
    # 300 Hz (inside the safe band) it keeps them at every corner and the review says nothing.
    inp = copy.deepcopy(IND380)
    inp["current_loop"] = {"bandwidth_hz": bandwidth_hz}
    r = pulab.report(inp)
    f = [x for x in r["review"]["findings"] if x["code"] == "robust_margin"]
    assert len(f) == findings, f
    assert all(x["field"] == "current_loop.bandwidth_hz" and x["severity"] == "warning"
               and x["key"].startswith("loop.robust.worst") for x in f)


def test_monte_carlo_seeded_and_sliceable():
    inp = copy.deepcopy(SEED)
    inp["analysis"]["robust"] = {"samples": 300, "seed": 7}
    a = pulab.report(inp)["loop"]["robust"]["monte_carlo"]
    b = pulab.report(inp)["loop"]["robust"]["monte_carlo"]
    assert a == b and sum(a["phase_margin_deg"]["q"]["counts"]) == 300
    inp["analysis"]["robust"]["seed"] = 8
    c = pulab.report(inp)["loop"]["robust"]["monte_carlo"]
    assert c != a
    base = pulab.report({k: v for k, v in SEED.items() if k != "analysis"})
    cfg = robust.settings({"seed": 7})
    whole = robust.study_row(base, cfg, "computation_pwm", 300, 7, 0)
    parts = [robust.study_row(base, cfg, "computation_pwm", 100, 7, s) for s in (0, 100, 200)]
    assert whole["below"] == sum(p["below"] for p in parts) == a["below"]
    assert whole["min_phase_margin_deg"] == min(p["min_phase_margin_deg"] for p in parts)


def test_resistance_flux_inductance_formulas():
    cfg = robust.settings({})
    assert math.isclose(robust.resistance(1.0, 120.0, cfg), 1.393)
    assert math.isclose(robust.flux(1.0, 120.0, cfg), 0.88)
    assert robust.inductance(1.0, 2.0, 1.5, 3.0, cfg) == pytest.approx((0.85, 1.7))
    cfg = robust.settings({"inductance_table": [[1, 1e-3, 2e-3], [3, 5e-4, 1e-3]]})
    assert robust.inductance(0, 0, 0.0, 3.0, cfg) == (1e-3, 2e-3)
    assert robust.inductance(0, 0, 2.0, 3.0, cfg) == pytest.approx((7.5e-4, 1.5e-3))
    assert robust.inductance(0, 0, 9.0, 3.0, cfg) == (5e-4, 1e-3)


# ---- studies: processes and a Dask cluster give the --jobs 1 numbers ---------------------

def _catalogue(count: int) -> str:
    lines = (ROOT / "tests" / "data" / "motors-1000.csv").read_text(encoding="utf-8").splitlines()
    return "\n".join(lines[:count + 1]) + "\n"


def test_study_jobs_give_the_single_process_numbers():
    from pulab.cli.robust import run_study, study_tasks
    tasks = study_tasks(_catalogue(6), {"robust": {}}, 40, 3)
    one = run_study(tasks, 1, progress=lambda d, t: None)
    two = run_study(tasks, 2, progress=lambda d, t: None)
    assert one == two and len(one) == 6
    assert all("error" in r or r["samples"] == 40 for r in one)


def test_study_on_a_local_dask_cluster_equals_jobs_1():
    try:
        from dask.distributed import LocalCluster
    except ImportError:
        if os.environ.get("CI"):
            raise
        pytest.skip("dask not installed (pip install 'pulab[dask]'); required when CI is set")
    from pulab.cli.robust import run_study, study_tasks
    tasks = study_tasks(_catalogue(8), {"robust": {}}, 40, 5)
    seen = []
    with LocalCluster(n_workers=3, threads_per_worker=1, processes=True,
                      dashboard_address=":0") as cluster:
        rows = run_study(tasks, scheduler=cluster.scheduler_address,
                         progress=lambda d, t: seen.append((d, t)))
    assert rows == run_study(tasks, 1, progress=lambda d, t: None)
    assert seen[-1] == (8, 8) and len(seen) == 8


def test_pulab_imports_without_dask():
    code = ("import sys; sys.modules['dask'] = None; sys.modules['distributed'] = None; "
            "import pulab, pulab.__main__, pulab.cli.robust; print('ok')")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env={"PYTHONPATH": str(ROOT / "py")})
    assert r.stdout.strip() == "ok", r.stderr


def test_cli_study_progress_on_stderr(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text(_catalogue(3))
    r = subprocess.run([sys.executable, "-m", "pulab", "robust", "--catalogue", str(path),
                        "--samples", "10", "--jobs", "1"], capture_output=True, text=True,
                       env={"PYTHONPATH": str(ROOT / "py")})
    assert r.returncode in (0, 1), r.stderr
    rows = json.loads(r.stdout)
    assert [x["row"] for x in rows] == [1, 2, 3] and "3/3" in r.stderr


@pytest.mark.parametrize("value", [{"temperature_c": [155, 20]}, {"temperature_c": 1},
                                   {"inductance_table": [[0, 1e-3, 1e-3]]},
                                   {"inductance_table": [[0, 1e-3, 1e-3], [0, 1e-3, 1e-3]]},
                                   {"inductance_table": [[0, 1e-3, 1e-3], [1, 1e-3]]},
                                   {"inductance_table": [[0, 1e-3, 1e-3], [1, 0, 1e-3]]},
                                   {"magnet": "alnico"}, {"samples": 0.5}, {"magnet": 5},
                                   {"samples": -1}, {"grid": 100}, {"peak_current_a": -1},
                                   {"reference_c": 1000}, {"seed": -1}, "x"])
def test_errors_have_chinese(value):
    inp = copy.deepcopy(SEED)
    inp["analysis"]["robust"] = value
    r = json.loads(call_json("report", json.dumps(inp)))
    assert r["ok"] is False and r["field"].startswith("analysis.robust"), r
    assert any("\u4e00" <= ch <= "\u9fff" for ch in r["message_zh"]), r


def test_warnings_have_chinese():
    def has_chinese(text):
        return any("\u4e00" <= ch <= "\u9fff" for ch in text)
    inp = copy.deepcopy(SEED)
    inp["current_loop"] = {"bandwidth_hz": 1500}      # unstable somewhere: no safe design left?
    for i in (SEED, inp):
        r = pulab.report(i)
        en = [x for x in r["warnings"] if x.startswith("loop.robust")]
        zh = [x for x in r["warnings_zh"] if x.startswith("loop.robust")]
        assert en and len(zh) == len(en) and all(has_chinese(x) for x in zh), (en, zh)


def test_worst_step_fixed_beside_float():
    # 380 V 7.5 kW motor (tests/oracle/make_golden.py IND380): tuned for 500 Hz on the nameplate
    # plant; at the worst case (peak current, L −30 %) the same integers overshoot far more.
    ind = {"motor": {"rated_voltage_v": 380, "rated_current_a": 14.5, "rated_freq_hz": 50,
                     "rs_ohm": 0.42, "ld_h": 0.0085, "lq_h": 0.0135, "bemf_v": 335.0,
                     "pole_pairs": 2}, "drive": {"udc_v": 540, "ts_s": 0.000125},
           "analysis": {"robust": {}}, "sim": {"current": {"axis": "q", "delay": True}}}
    r = pulab.report(ind)
    s = r["loop"]["robust"]["step"]
    assert s["case"] == r["loop"]["robust"]["worst"]["case"] and s["axis"] == "q"
    assert len(s["t"]) == len(s["float"]) == len(s["fixed"]) <= 400
    m = s["metrics"]
    assert abs(m["fixed"]["overshoot_pct"] - m["float"]["overshoot_pct"]) < 1.0
    assert s["fixed_vs_float_max_a"] < 0.01 * s["ref_a"]
    nominal = r["sim"]["current"]["metrics"]["fixed"]["overshoot_pct"]
    assert m["fixed"]["overshoot_pct"] > nominal + 5, (m["fixed"]["overshoot_pct"], nominal)
