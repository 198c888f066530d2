"""The vendor-profile entry points keep the hardening contract (docs/contract.md).

``python -m pulab header`` and ``translate`` on the seeded adversarial inputs of
tests/py/adversarial.py, and the kinds ``vendors.header`` and ``vendors.translate`` of
``pulab.api.call_json`` with hostile ``profiles`` sections and translator values: strict
JSON / a header, or one printable error line naming a field, with Chinese text for every
message.
"""
import contextlib
import io
import json
import random
import sys
from collections import Counter

from adversarial import BASE, _value, cases
from pulab.__main__ import main
from pulab.api import call_json
from conftest import chinese
from test_hardening import _check_cli, _one_line, _strict

FUZZ = 1500


def _cli(args: list, data: bytes) -> tuple:
    stdin = io.TextIOWrapper(io.BytesIO(data), encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    saved = sys.stdin
    sys.stdin = stdin
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main([*args, "-"])
    finally:
        sys.stdin = saved
    return code, out.getvalue(), err.getvalue()


def test_header_and_translate_cli_on_adversarial_inputs():
    seen = Counter()
    for i, data in enumerate(cases(FUZZ, seed=12)):
        args = (["header", "--profile", ("ti", "nxp", "st", "microchip", "inovance")[i % 5]]
                if i % 2 else ["translate", "--from", "inovance", "--kp", "1180", "--ki", "4720"])
        code, out, err = _cli(args, data)
        if code == 0 and args[0] == "header":
            assert err == "" and "#define" in out and out.isprintable() is False  # text with \n
            seen["header"] += 1
            continue
        kind, _ = _check_cli(code, out, err)
        seen[f"{args[0]} {kind}"] += 1
    print(f"\nprofile CLI fuzz: {dict(seen)}")
    assert seen["header"] > 50 and seen["translate ok"] > 50


def test_vendors_kinds_with_hostile_profiles_and_values():
    rng = random.Random(12)
    seen = Counter()
    plain = {k: v for k, v in BASE.items() if k != "sim"}
    names = ["ti", "nxp", "st", "microchip", "inovance", "", "a\nb", "ti.x"]
    keys = ["full_scale_voltage_v", "global_q", "tf_kpdiv", "trapezoidal", "i_max_a",
            "voltage_base_v", "f1", "round_u_max", "\u2028"]
    for _ in range(FUZZ):
        section = rng.choice([_value(rng), {rng.choice(names): _value(rng)},
                              {rng.choice(names): {rng.choice(keys): _value(rng)}}])
        kind, req = rng.choice([
            ("vendors.header", {"input": {**plain, "profiles": section},
                                "profile": rng.choice(names + [_value(rng)])}),
            ("vendors.translate", {"input": {**plain, "profiles": section},
                                   "from": rng.choice(names),
                                   "axis": rng.choice(["d", "q", _value(rng)]),
                                   "values": rng.choice([
                                       _value(rng), {"pm_kp": _value(rng), "pm_ki": 4720},
                                       {"Kp_Iq": rng.choice([1, -1, 2 ** 31, 0.5]), "Ki_Iq": 3}])}),
        ])
        out = _strict(call_json(kind, json.dumps(req)))
        if out["ok"]:
            seen["ok"] += 1
            continue
        assert set(out) == {"ok", "field", "message", "message_zh", "code", "params"}, out
        assert isinstance(out["code"], str) and isinstance(out["params"], dict), out
        assert all(_one_line(out[k]) for k in ("field", "message", "message_zh")), out
        assert chinese(out["message_zh"]), out
        seen["error"] += 1
    print(f"\nvendors fuzz: {dict(seen)}")
    assert seen["error"] > 500


def test_nxp_u_max_rounded_to_zero_is_an_input_error():
    """U_DCB_MAX/UmaxCoeff below 0.05 V rounds to 0 V with MCAT's rounding: a ZeroDivisionError
    traceback before, now the field that caused it."""
    import copy
    import pytest
    import pulab
    from conftest import SEED_INPUT
    inp = copy.deepcopy(SEED_INPUT)
    inp["profiles"] = {"nxp": {"u_max_coeff": 481, "round_u_max": True}}
    with pytest.raises(pulab.InputError) as e:
        pulab.report(inp)
    assert e.value.field == "profiles.nxp.u_max_coeff" and "0.1 V" in e.value.message
    inp["profiles"]["nxp"]["round_u_max"] = False       # unrounded it is tiny but not zero
    assert pulab.report(inp)["profiles"]["nxp"]["inputs"]["u_max_v"] > 0
