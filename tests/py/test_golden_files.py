"""The oracles' staleness check: numbers within the oracle's tolerance, everything else exact.

A changed oracle output must still be caught: these tests change a copy of the committed
golden files and expect ``--check --dir COPY`` to call it stale.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ORACLE = ROOT / "tests" / "oracle"
sys.path.insert(0, str(ORACLE))
from golden_files import differences  # noqa: E402

REL, ABS = 1e-9, 1e-9


@pytest.mark.parametrize("expected, actual, same", [
    (1.0, 1.0 + 1e-12, True),             # last digits move: not stale
    (1.0, 1.0 + 1e-6, False),              # a real change
    (-2.839402248584555e-05, -2.839402248488122e-05, True),  # near zero: the absolute floor
    (0.0, 2e-9, False),                    # beyond the floor
    (15022, 15023, False),                 # integers exact
    (1, 1.0, False),                       # an int never matches a float
    ("Q13", "Q14", False),
    (True, 1, False),
    (None, 0.0, False),
    ([1.0, 2.0], [1.0], False),
    ({"a": 1.0}, {"a": 1.0, "b": 2}, False),
    ({"a": [1.0, {"b": 3}]}, {"a": [1.0 + 1e-13, {"b": 3}]}, True),
    (float("inf"), float("inf"), True),
])
def test_differences(expected, actual, same):
    assert (differences(expected, actual, REL, ABS) == []) is same


def test_differences_name_the_path():
    diff = differences({"loop": {"d": [0.5, 7]}}, {"loop": {"d": [0.5, 8]}}, REL, ABS)
    assert diff == ["loop.d[1]: 7 != 8"]


def _first_float(obj, path=()):
    if isinstance(obj, float) and abs(obj) >= 1.0:  # well above every absolute floor
        return path
    items = obj.items() if isinstance(obj, dict) else enumerate(obj) if isinstance(obj, list) else ()
    for k, v in items:
        found = _first_float(v, path + (k,))
        if found is not None:
            return found
    return None


def _perturbed_copy(tmp_path, src: Path, name: str, change) -> Path:
    copy = tmp_path / src.name
    shutil.copytree(src, copy, ignore=shutil.ignore_patterns("*.md"))
    case = json.loads((copy / name).read_text(encoding="utf-8"))
    path = _first_float(case["expected"])
    node = case["expected"]
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = change(node[path[-1]])
    (copy / name).write_text(json.dumps(case), encoding="utf-8")
    return copy


@pytest.mark.parametrize("oracle, folder, name", [
    ("make_golden.py", "golden", "01_seed_motor.json"),
    ("loop_oracle.py", "golden/loop", "01_seed_motor.json"),
])
def test_changed_value_is_stale(tmp_path, oracle, folder, name):
    src = ROOT / "tests" / folder
    for factor, stale in ((1 + 1e-6, True), (1 + 1e-14, False)):
        copy = _perturbed_copy(tmp_path / str(factor), src, name, lambda v: v * factor)
        r = subprocess.run([sys.executable, str(ORACLE / oracle), "--check", "--dir", str(copy)],
                           capture_output=True, text=True)
        assert (r.returncode == 1) is stale, r.stderr
        assert (name in r.stderr) is stale, r.stderr
