"""The input schema (pulab.schema.fields), its validator and its error catalog, and everything
derived from the schema: the page's generated field file and the contract's input tables."""
import json
import re

import pytest

from conftest import ROOT
from pulab.schema.catalog import MESSAGES, render
from pulab.schema.errors import InputError
from pulab.schema.fields import FIELD, FIELDS, REQUIRED, SECTIONS, markdown, schema_json
from pulab.schema.validate import read, value


def test_generated_page_schema_is_fresh():
    """web/src/generated/schema.json is what the build writes; a schema edit needs a build."""
    assert (ROOT / "web/src/generated/schema.json").read_text(encoding="utf-8") == schema_json()


def test_every_field_is_well_formed():
    for f in FIELDS:
        assert f.section in SECTIONS, f.path
        assert f.kind in ("number", "integer", "choice", "flag", "name_or_number", "pair", "table",
                          "text", "object"), f.path
        assert f.kind != "text" or f.hi is not None, f.path
        assert (f.kind in ("choice", "name_or_number")) == bool(f.choices), f.path
        assert (f.kind == "table") == bool(f.columns), f.path
        assert f.default is REQUIRED or f.default is None or f.kind != "choice" or f.default in f.choices
        if f.only_with:
            on, want = f.only_with
            assert FIELD[on].section == f.section and want in FIELD[on].choices, f.path
            assert FIELDS.index(FIELD[on]) < FIELDS.index(f), f"{f.path}: its condition comes first"
        if f.kind == "integer":
            assert f.lo is not None and f.hi is not None, f.path


@pytest.mark.parametrize("f", [f for f in FIELDS if f.kind == "number"], ids=lambda f: f.path)
def test_number_fields_refuse_what_is_no_finite_number(f):
    for bad, code in ((True, "not_number"), ("1", "not_number"), ([1], "not_number"),
                      (float("nan"), "not_finite"), (10 ** 400, "not_finite"), (-10 ** 400, "not_finite")):
        with pytest.raises(InputError) as e:
            value(f, bad)
        assert (e.value.field, e.value.code) == (f.path, code)


@pytest.mark.parametrize("f", [f for f in FIELDS if f.kind == "number"], ids=lambda f: f.path)
def test_number_fields_keep_their_range(f):
    lo = f.lo if f.lo is not None else (0.0 if f.sign == ">0" else None)
    if lo is not None:
        with pytest.raises(InputError) as e:
            value(f, lo - max(abs(lo), 1.0))
        assert e.value.code in ("not_positive", "out_of_range", "negative")
    if f.hi is not None:
        with pytest.raises(InputError):
            value(f, f.hi * 2 if f.hi > 0 else 1.0)


def test_every_catalog_text_renders_in_both_languages():
    """Each entry's two texts name the same params, and both render."""
    for code, (en, zh) in MESSAGES.items():
        names = set(re.findall(r"{(\w+)", en))
        assert names == set(re.findall(r"{(\w+)", zh)), code
        params = {k: 1.5 for k in names}
        if "reason" in names:
            params["reason"] = {"code": "not_positive", "params": {"value": -1.0}}
        assert render(code, params, "en") and re.search(r"[\u4e00-\u9fff]", render(code, params, "zh")), code


def test_a_datasheet_error_is_one_sentence_in_each_language():
    from pulab import report
    with pytest.raises(InputError) as e:
        report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rs_ohm": 1.5,
                          "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 1000},
                "drive": {"udc_v": 24, "ts_s": 1e-4}, "datasheet": {"speed_rpm": 1e9}})
    assert e.value.field == "datasheet.speed_rpm" and e.value.code == "derived_invalid"
    assert e.value.message == ("gives motor.rated_freq_hz = 1.66667e+10, which must be between "
                               "1e-09 and 1e+09, got 1.66667e+10")
    assert e.value.message_zh == ("得到 motor.rated_freq_hz = 1.66667e+10，必须在 1e-09 与 1e+09 "
                                  "之间，当前为 1.66667e+10")


def test_read_fills_defaults_and_checks_only_with():
    assert read("current_loop", {"method": "manual", "kp": 1, "ki": 2})["pm_kp"] is None
    with pytest.raises(InputError) as e:
        read("current_loop", {"method": "manual", "kp": 1})
    assert (e.value.field, e.value.code) == ("current_loop.ki", "required")
    with pytest.raises(InputError) as e:
        read("current_loop", {"pm_kp": 1})
    assert (e.value.field, e.value.message) == ("current_loop.pm_kp", "is only used with method = integers")


def _contract_rows():
    text = (ROOT / "docs/contract.md").read_text(encoding="utf-8")
    start, end = text.index("<!-- input-fields:begin -->"), text.index("<!-- input-fields:end -->")
    return text[start:end]


def test_contract_input_tables_are_the_schema():
    """docs/contract.md's input tables are the schema's text; after a schema edit paste the output of
    ``PYTHONPATH=py python3 -c "from pulab.schema.fields import markdown; print(markdown(), end='')"``."""
    assert _contract_rows().split("\n", 1)[1] == markdown()


def test_normalize_fills_every_default_from_the_schema():
    from conftest import SEED_INPUT
    from pulab.schema.inputs import SECTIONS as NORMALIZED, normalize
    out = normalize(SEED_INPUT)
    for sec, keys in NORMALIZED.items():
        for k in keys:
            f = FIELD[f"{sec}.{k}"]
            given = SEED_INPUT.get(sec, {}).get(k)
            if sec == "raw":
                assert k not in out["raw"]  # raw holds only the values given
            elif sec == "motor" and (k == "kind" or f.only_with == ("motor.kind", "acim")):
                assert k not in out["motor"]  # a PMSM's motor: as before motor.kind existed
            elif given is not None:
                assert out[sec][k] == given
            elif f.only_with and out[sec][f.only_with[0].rsplit(".", 1)[1]] != f.only_with[1]:
                assert out[sec][k] is None
            elif f.default is not None and f.default is not REQUIRED:
                assert out[sec][k] == f.default, f.path
    assert out["drive"]["base_freq_hz"] == SEED_INPUT["motor"]["rated_freq_hz"]  # f_b defaults to f_n
    assert normalize({k: v for k, v in out.items() if k != "analysis"}) == out  # its own fixed point


def test_normalize_names_the_field_at_fault():
    from conftest import SEED_INPUT
    from pulab.schema.inputs import normalize
    cases = [
        ([], "input", "not_json_object"),
        ({**SEED_INPUT, "motors": {}}, "motors", "unknown_section"),
        ({**SEED_INPUT, "drive": {"udc_v": 24}}, "drive.ts_s", "required"),
        # a datasheet value whose conversion is out of range is reported where it was typed
        ({"motor": {**{k: v for k, v in SEED_INPUT["motor"].items() if k != "rated_freq_hz"},
                    "pole_pairs": 1000},
          "drive": SEED_INPUT["drive"], "datasheet": {"speed_rpm": 1e9}}, "datasheet.speed_rpm",
         "derived_invalid"),
    ]
    for inp, field, code in cases:
        with pytest.raises(InputError) as e:
            normalize(inp)
        assert (e.value.field, e.value.code) == (field, code)


@pytest.mark.parametrize("lang", ["en", "zh"])
def test_a_finding_prints_physical_values_with_an_si_prefix(lang):
    """The seed-format LQ finding of a 10.6 µH motor: the value as a reader writes it."""
    from pulab.schema.catalog import render
    text = render("finding.raw_rounding", {"name": "LQ", "value": 1, "path": {"label": "motor.lq_h"},
                                           "si": 1.06e-05, "si_unit": "H", "pct": -5.66,
                                           "label": "Unit", "fix": {"code": "fix.inductance_unit", "params": {}}},
                  lang)
    assert "Lq = 10.6 µH" in text and "e-05" not in text
