"""Golden vectors (tests/golden, written by the independent oracle tests/oracle) against pulab.

Integers, strings and flags exactly; floats to 1e-12 relative (see tests/golden/README.md).
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import subprocess
import sys

import pytest

import pulab

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden"
CASES = sorted(p for p in GOLDEN.glob("[0-9]*.json"))
ERRORS = json.loads((GOLDEN / "errors.json").read_text(encoding="utf-8"))
REL, ABS = 1e-12, 1e-300


def _load(path: pathlib.Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def _compare(expected, actual, path: str, problems: list[str]) -> None:
    """Every key of `expected` must exist in `actual` and match; extra keys are fine."""
    if isinstance(expected, dict):
        if not isinstance(actual, dict):
            problems.append(f"{path}: expected an object, got {actual!r}")
            return
        for k, v in expected.items():
            if k not in actual:
                problems.append(f"{path}.{k}: missing")
            else:
                _compare(v, actual[k], f"{path}.{k}", problems)
    elif isinstance(expected, list):
        if not isinstance(actual, list) or len(actual) != len(expected):
            problems.append(f"{path}: expected {expected!r}, got {actual!r}")
            return
        for i, (e, a) in enumerate(zip(expected, actual)):
            _compare(e, a, f"{path}[{i}]", problems)
    elif isinstance(expected, bool) or isinstance(expected, str) or expected is None:
        if actual != expected or type(actual) is not type(expected):
            problems.append(f"{path}: expected {expected!r}, got {actual!r}")
    elif isinstance(expected, int):
        # Firmware integers are exact: an int, never a float or bool.
        if type(actual) is not int or actual != expected:
            problems.append(f"{path}: expected int {expected!r}, got {actual!r}")
    elif isinstance(expected, float):
        if isinstance(actual, bool) or not isinstance(actual, (int, float)):
            problems.append(f"{path}: expected float {expected!r}, got {actual!r}")
            return
        a = float(actual)
        if not math.isfinite(a) or abs(a - expected) > max(REL * max(abs(a), abs(expected)), ABS):
            problems.append(f"{path}: expected {expected!r}, got {a!r}")
    else:  # pragma: no cover - the generator writes only JSON types
        problems.append(f"{path}: unexpected type in golden file: {expected!r}")


def test_golden_files_not_stale():
    r = subprocess.run([sys.executable, str(ROOT / "tests" / "oracle" / "make_golden.py"),
                        "--check"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_enough_cases():
    assert len(CASES) >= 16
    assert len(ERRORS) >= 8


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_golden_case(path):
    case = _load(path)
    report = pulab.report(case["input"])
    problems: list[str] = []
    _compare(case["expected"], report, path.stem, problems)
    assert not problems, "\n".join(problems[:40])


@pytest.mark.parametrize("case", ERRORS, ids=lambda c: c["field"])
def test_golden_error(case):
    with pytest.raises(pulab.InputError) as ei:
        pulab.report(case["input"])
    assert ei.value.field == case["field"], ei.value.message
    assert isinstance(ei.value.message, str) and ei.value.message


def _cli(tmp_path, inp: dict):
    f = tmp_path / "input.json"
    f.write_text(json.dumps(inp), encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=str(ROOT / "py"))
    return subprocess.run([sys.executable, "-m", "pulab", "report", str(f)],
                          capture_output=True, text=True, env=env, cwd=ROOT)


@pytest.mark.parametrize("name", ["01_seed_motor", "13_wrap_6600v", "15_store_lq_uH",
                                  "23_limit_robot_28krpm"])
def test_cli_report(tmp_path, name):
    inp = _load(GOLDEN / f"{name}.json")["input"]
    r = _cli(tmp_path, inp)
    assert r.returncode == 0, r.stderr
    # Equal to the in-process report (JSON round trip: floats survive repr exactly).
    assert json.loads(r.stdout) == json.loads(json.dumps(pulab.report(inp)))


@pytest.mark.parametrize("idx", [0, 7, -1])
def test_cli_error(tmp_path, idx):
    case = ERRORS[idx]
    r = _cli(tmp_path, case["input"])
    assert r.returncode == 2, (r.stdout, r.stderr)
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert lines[0].startswith(f"error: {case['field']}:"), lines[0]


def test_seed_worked_numbers():
    inp = _load(GOLDEN / "03_seed_raw_worked.json")["input"]
    rep = pulab.report(inp)
    rpm = rep["vendor"]["Rpm"]
    # Seed 1.4-1/1.4-2: RsPm 1500 mΩ, Current 150 (0.01 A), Voltage 17 V:
    # m_UData = 225000/17 = 13235, Rpm = 13235·18597 >> 14 = 15022, against the exact Q16
    # value 1.5/((17/√3)/1.5)·2^16 = 15023.6.
    assert rpm["value"] == 15022
    assert rpm["ideal"] == pytest.approx(15023.6, abs=0.01)
    assert rpm["trace"][0]["value"] == 13235

    # Seed 1.4-7 gives L_pu = 0.0732 for Ld 600 µH, but it computes L_b with U_b = 17 V, the
    # line value; the seed itself (1.4-1, 1.4-13) takes U_b = U_LL/√3, the phase value. With
    # that, L_b = (17/√3)/(2π·220·1.5) = 4.734 mH and L_pu = 0.1268 = √3 × the seed's 0.0732.
    seed = _load(GOLDEN / "01_seed_motor.json")["input"]
    ld_pu = pulab.report(seed)["pu"]["Ld"]
    assert ld_pu == pytest.approx(6e-4 / ((17 / math.sqrt(3)) / (2 * math.pi * 220 * 1.5)),
                                  rel=1e-12)
    assert ld_pu == pytest.approx(0.0732 * math.sqrt(3), rel=2e-3)
    assert ld_pu != pytest.approx(0.0732, rel=0.1)
