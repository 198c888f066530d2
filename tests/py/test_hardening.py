"""The CLI and pulab.api keep their contract for every input.

Contract (docs/contract.md): exit 0 with strict JSON on stdout, or exit 2 with
exactly one stderr line ``error: FIELD: MESSAGE``; the api returns
``{"ok": false, "field", "message", "message_zh"}``, each one printable line.
The fuzz run sends 10,000 seeded adversarial inputs (tests/py/adversarial.py)
through both ``call_json("report", …)`` and the CLI entry ``main`` in-process, checks that
both name the same field, and prints the count; a handful go through real
subprocesses too.
"""
import contextlib
import io
import json
import subprocess
import sys
from collections import Counter

import pytest

from adversarial import BASE, cases, robust_cases
from conftest import ROOT
from pulab.__main__ import main
from pulab.api import call_json
from pulab.analyses.loop import validate as check_analysis
from pulab.schema.errors import InputError
from pulab.schema.jsontext import MAX_DEPTH, parse

FUZZ_CASES = 10_000


def _strict(text: str):
    def refuse(name):
        raise AssertionError(f"non-strict JSON constant {name}")
    return json.loads(text, parse_constant=refuse)


def _one_line(s) -> bool:
    return isinstance(s, str) and s != "" and s.isprintable()


def _api(text: str) -> tuple:
    out = _strict(call_json("report", text))
    if out["ok"]:
        assert set(out) == {"ok", "report"} and isinstance(out["report"], dict)
        return "ok", None
    assert set(out) == {"ok", "field", "message", "message_zh", "code", "params"}, out
    assert isinstance(out["code"], str) and isinstance(out["params"], dict), out
    assert all(_one_line(out[k]) for k in ("field", "message", "message_zh")), out
    assert out["message_zh"] != out["message"] or out["message"].isascii() is False, out
    return "error", out["field"]


def _cli(data: bytes) -> tuple:
    stdin = io.TextIOWrapper(io.BytesIO(data), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    saved = sys.stdin
    sys.stdin = stdin
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(["report", "-"])
    finally:
        sys.stdin = saved
    return code, out.getvalue(), err.getvalue()


def _check_cli(code: int, stdout: str, stderr: str):
    if code == 0:
        assert stderr == ""
        _strict(stdout)
        return "ok", None
    assert code == 2 and stdout == "", (code, stdout[:200])
    line = stderr[:-1]
    assert stderr.endswith("\n") and _one_line(line) and line.startswith("error: "), repr(stderr)
    return "error", line[len("error: "):].split(": ", 1)[0]


def test_fuzzed_inputs_keep_the_contract_in_the_api_and_the_cli():
    seen = Counter()
    for data in cases(FUZZ_CASES):
        cli = _check_cli(*_cli(data))
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            assert cli[0] == "error" and cli[1] == "input"
            seen["not utf-8"] += 1
            continue
        api = _api(text)
        assert api == cli, (data[:300], api, cli)
        seen[api[0]] += 1
    print(f"\nfuzzed inputs: {sum(seen.values())} through call_json and the CLI entry "
          f"({dict(seen)})")
    assert sum(seen.values()) == FUZZ_CASES
    # The generator must reach valid reports and many distinct errors, or it tests little.
    assert seen["ok"] > 100 and seen["error"] > 5000


ROBUST_CASES = 2_000
#: Valid robustness sections computed in full (≈ 0.5 s each); the others are only validated.
ROBUST_FULL_RUNS = 8


def _robust_valid(text: str):
    """The checked robustness settings of a case, or None when its input is not a valid one."""
    try:
        obj = parse(text)
        return check_analysis(obj["analysis"])["robust"] if isinstance(obj, dict) and \
            isinstance(obj.get("analysis"), dict) else None
    except InputError:
        return None


def test_fuzzed_robust_sections_keep_the_contract():
    """``analysis.robust`` under hostile input: every field of the schema's section mutated.
    A case with an invalid section goes through call_json and the CLI (the same field named);
    valid ones are checked by the validator, and a few cheap ones computed in full."""
    seen = Counter()
    for data in robust_cases(ROBUST_CASES):
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            assert _check_cli(*_cli(data)) == ("error", "input")
            seen["not utf-8"] += 1
            continue
        cfg = _robust_valid(text)
        if cfg is not None:
            cheap = cfg["samples"] <= 10 and cfg["grid"] <= 7
            if not cheap or seen["valid, computed"] >= ROBUST_FULL_RUNS:
                seen["valid, validated"] += 1
                continue
        api = _api(text)
        assert api == _check_cli(*_cli(data)), (data[:300], api)
        seen[api if api[0] == "error" else "valid, computed" if cfg is not None else "ok"] += 1
    fields = {k[1] for k in seen if isinstance(k, tuple)}
    print(f"\nfuzzed robustness sections: {sum(v for k, v in seen.items() if isinstance(k, tuple))} "
          f"errors naming {len(fields)} fields, {seen['valid, computed']} computed, "
          f"{seen['valid, validated']} validated only, {seen['not utf-8']} not UTF-8")
    assert seen["valid, computed"] == ROBUST_FULL_RUNS and seen["valid, validated"] > 50, seen
    # Every field of the section is named by some error.
    assert {f for f in fields if f.startswith("analysis.robust.")} >= {
        "analysis.robust." + k for k in ("temperature_c", "reference_c", "copper_alpha_per_k", "magnet",
                                         "peak_current_a", "inductance_drop_pct", "udc_tolerance_pct",
                                         "bus_compensated", "tolerance_rs_pct", "samples", "seed", "grid",
                                         "min_phase_margin_deg", "min_gain_margin_db")}, sorted(fields)


@pytest.mark.parametrize("data, field", [
    (b"[" * 100000, "input"),
    (json.dumps({**BASE, "motor": {**BASE["motor"], "rs_ohm": int("9" * 309)}}).encode(),
     "motor.rs_ohm"),
    (json.dumps({**BASE, "motor": {**BASE["motor"], "a\nb\u2028": 1}}).encode(),
     "motor['a\\nb\\u2028']"),
    (json.dumps({**BASE, "sim": {"pll": {"duration_s": 1e300}}}).encode(), "sim.pll.duration_s"),
    (b"\xff{}", "input"),
])
def test_real_cli_processes(tmp_path, data, field):
    """A handful of real ``python -m pulab`` runs, the file and stdin paths both."""
    path = tmp_path / "in.json"
    path.write_bytes(data)
    for args, stdin in ((["report", str(path)], None), (["report", "-"], data)):
        p = subprocess.run([sys.executable, "-m", "pulab", *args], input=stdin,
                           capture_output=True, cwd=ROOT / "py", timeout=60)
        assert (p.returncode, p.stdout) == (2, b""), p
        assert p.stderr.decode().startswith(f"error: {field}: ") and p.stderr.count(b"\n") == 1, p


def test_a_valid_input_through_a_real_process_is_strict_json():
    p = subprocess.run([sys.executable, "-m", "pulab", "report", "-"],
                       input=json.dumps(BASE).encode(), capture_output=True, cwd=ROOT / "py",
                       timeout=60)
    assert p.returncode == 0 and p.stderr == b""
    assert "sim" in _strict(p.stdout.decode())


@pytest.mark.parametrize("depth, ok", [(MAX_DEPTH, True), (MAX_DEPTH + 1, False)])
def test_depth_cap(depth, ok):
    text = "[" * depth + "]" * depth
    if ok:
        assert parse(text) is not None
    else:
        with pytest.raises(ValueError, match="nested deeper"):
            parse(text)


@pytest.mark.parametrize("kind, text, field", [
    ("qcalc", '{"format": [[["Q15"]]]}', "qcalc.format"),
    ("qcalc", '{"format": "Q0.15", "value": 1' + "0" * 400 + "}", "qcalc.value"),
    ("qcalc", "[" * 5000, "qcalc"),
    ("export.header", "{" * 5000, "input"),
    ("export.csv_pll", '{"input": null}', "input"),
])
def test_other_api_kinds_name_the_field(kind, text, field):
    out = _strict(call_json(kind, text))
    assert out["ok"] is False and out["field"] == field and _one_line(out["message"]), out


def test_fuzzed_qcalc_and_export_requests_keep_the_contract():
    """The other api kinds: 1,000 seeded requests each, built from the same hostile values."""
    import random
    from adversarial import NASTY_TEXT, NUMBER_LITERALS, _value
    rng = random.Random(15)
    count = 0
    plain = {k: v for k, v in BASE.items() if k != "sim"}
    for _ in range(1000):
        req = {"format": rng.choice(["Q0.15", "Q15", "UQ8.8", "Q3.12", *NASTY_TEXT[:8]]),
               rng.choice(["value", "raw", "word_bits", "rounding", "overflow", "format"]): "@@x@@"}
        text = json.dumps(req).replace('"@@x@@"', rng.choice(NUMBER_LITERALS) if rng.random() < 0.5
                                       else json.dumps(_value(rng)))
        export = rng.choice(["export.header", "export.csv_current", "export.csv_pll", *NASTY_TEXT[:8]])
        for kind, body in (("qcalc", text), (export, json.dumps({"input": plain}))):
            out = _strict(call_json(kind, body))
            assert out["ok"] is True or all(_one_line(out[k]) for k in ("field", "message", "message_zh")), out
            count += 1
    print(f"\nfuzzed qcalc/export requests: {count}")
