"""Write or check an oracle's golden files: numbers within a stated tolerance, all else exact.

Every oracle in this folder hands its files here as ``{name: JSON object}``.  ``--check``
compares the parsed JSON, not the bytes: a float may move in its last digits when numpy,
scipy or python-control change version, or when the BLAS picks another kernel on another CPU,
and a byte comparison then calls an unchanged oracle "stale".  Integers, strings, booleans,
null, keys and list lengths stay exact, and an int never matches a float.

A float matches when ``|a - b| <= rel * max(|a|, |b|) + abs_`` (an absolute floor for values
that are zero up to rounding, such as a Bode magnitude of -2.8e-5 dB).  Each oracle states the
tolerance it can honestly promise; the differences actually seen between library versions
are in tests/golden/README.md.

Never imports pulab.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path


def differences(expected, actual, rel: float, abs_: float, path: str = "") -> list[str]:
    """Where ``actual`` differs from ``expected`` beyond the tolerance, one line each."""
    here = path or "(top)"
    if isinstance(expected, bool) or isinstance(actual, bool) or expected is None or actual is None:
        return [] if expected is actual else [f"{here}: {expected!r} != {actual!r}"]
    if isinstance(expected, float) and isinstance(actual, float):
        if math.isfinite(expected) and math.isfinite(actual):
            if abs(expected - actual) <= rel * max(abs(expected), abs(actual)) + abs_:
                return []
        elif expected == actual:
            return []
        return [f"{here}: {expected!r} != {actual!r}"]
    if type(expected) is not type(actual):
        return [f"{here}: {type(expected).__name__} {expected!r} != {type(actual).__name__} {actual!r}"]
    if isinstance(expected, dict):
        if expected.keys() != actual.keys():
            return [f"{here}: keys {sorted(expected)} != {sorted(actual)}"]
        out = []
        for k in expected:
            out += differences(expected[k], actual[k], rel, abs_, f"{path}.{k}" if path else k)
        return out
    if isinstance(expected, list):
        if len(expected) != len(actual):
            return [f"{here}: {len(expected)} items != {len(actual)}"]
        out = []
        for i, (e, a) in enumerate(zip(expected, actual)):
            out += differences(e, a, rel, abs_, f"{path}[{i}]")
        return out
    return [] if expected == actual else [f"{here}: {expected!r} != {actual!r}"]


def dumps(obj) -> str:
    """The files' one text form (sorted keys, one space indent, no NaN)."""
    return json.dumps(obj, indent=1, sort_keys=True, ensure_ascii=False, allow_nan=False) + "\n"


def sync(files: dict, directory: Path, check: bool, rel: float, abs_: float) -> int:
    """Check (``check``) or write ``files`` into ``directory``; 1 if checking found a stale file.

    Writing leaves a file alone when it already matches within the tolerance, so that
    regenerating on another machine does not churn the repository.
    """
    directory.mkdir(parents=True, exist_ok=True)
    stale = {}
    for name, obj in files.items():
        path = directory / name
        obj = json.loads(dumps(obj))  # the JSON types the file holds (tuples → lists)
        if not path.exists():
            stale[name] = ["missing"]
            continue
        diff = differences(json.loads(path.read_text(encoding="utf-8")), obj, rel, abs_)
        if diff:
            stale[name] = diff
    extra = sorted(p.name for p in directory.glob("*.json") if p.name not in files)
    if check:
        for name, diff in stale.items():
            more = f" (+{len(diff) - 3} more)" if len(diff) > 3 else ""
            print(f"stale: {directory / name}: {'; '.join(diff[:3])}{more}", file=sys.stderr)
        for name in extra:
            print(f"not written by the oracle: {directory / name}", file=sys.stderr)
        return 1 if stale or extra else 0
    for name in stale:
        (directory / name).write_text(dumps(files[name]), encoding="utf-8")
    for name in extra:
        (directory / name).unlink()
    print(f"{directory}: {len(files)} files, {len(stale)} written, {len(extra)} removed")
    return 0


def golden_dir(argv: list[str], default: Path) -> Path:
    """``--dir PATH`` checks or writes another copy of the files (the staleness test uses it)."""
    if "--dir" in argv:
        return Path(argv[argv.index("--dir") + 1])
    return default
