"""The recipes of docs/design.md work as written: "Adding a vendor" builds the example vendor
from the document's own code block (a folder of one ``__init__.py``), registers it as its line
in ``profiles/registry.py`` would, finds it wherever a vendor appears, and removes it again;
"Adding an analysis" adds the example analysis from its three blocks (schema entries, module,
registry line) without touching ``report.py`` and finds it in the report when asked only."""

from __future__ import annotations

import importlib.util
import re
import sys

import pytest

from conftest import ROOT, SEED_INPUT
import pulab.analyses
from pulab import report
from pulab.analyses import registry as analyses
from pulab.analyses.registry import Analysis, Lazy
from pulab.profiles import header, registry
from pulab.profiles.translate import translate
from pulab.schema.catalog import render
from pulab.schema import fields
from pulab.schema.errors import InputError
from pulab.schema.fields import FIELD, F, Section, schema_json


def _recipe(title: str, nth: int = 0) -> str:
    """The ``nth`` ```python block after the paragraph that starts with ``**title**``."""
    text = (ROOT / "docs" / "design.md").read_text(encoding="utf-8")
    start = text.index(f"**{title}**")
    return re.findall(r"```python\n(.*?)```", text[start:], re.S)[nth]


@pytest.fixture
def acme(tmp_path):
    """The example vendor as a package folder ``acme/`` of pulab.profiles, registered."""
    folder = tmp_path / "acme"
    folder.mkdir()
    (folder / "__init__.py").write_text(_recipe("Adding a vendor"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location("pulab.profiles.acme", folder / "__init__.py",
                                                  submodule_search_locations=[str(folder)])
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    registry.register(module)
    yield module
    registry.unregister("acme")
    del sys.modules[spec.name]


def test_a_new_vendor_is_everywhere_a_vendor_is(acme):
    assert registry.names()[-1] == "acme"
    assert "acme" in FIELD["conventions.firmware"].choices
    assert '"path": "profiles.acme.full_scale_voltage_v"' in schema_json()
    zero = {"profile_name": {"vendor": "acme"}, "name": "K", "format": "Q15", "ideal": 1e-6}
    assert render("warning.profile_zero", zero, "zh").startswith("艾克米 K")

    r = report({**SEED_INPUT, "profiles": {"acme": {"full_scale_voltage_v": 48}}})
    p = r["profiles"]["acme"]
    assert p["inputs"] == {"full_scale_voltage_v": 48.0}
    assert p["bases"]["U_b"] == 48.0 and r["firmware"]["acme"]["representable"]
    assert set(p["constants"]) == {"ACME_KP_D", "ACME_KI_D", "ACME_KP_Q", "ACME_KI_Q"}
    assert "#define ACME_KP_Q" in header(r, "acme")

    kp = p["constants"]["ACME_KP_Q"]["value"]
    ki = p["constants"]["ACME_KI_Q"]["value"]
    t = translate(SEED_INPUT, "acme", "q", {"ACME_KP_Q": kp, "ACME_KI_Q": ki})
    assert [s["profile"] for s in t["chain"]] == ["inovance", "ti", "nxp", "st", "microchip",
                                                  "acme"]
    assert set(t["profiles"]) == set(registry.names())


def test_a_new_vendor_option_is_checked_by_its_field(acme):
    with pytest.raises(Exception) as e:
        report({**SEED_INPUT, "profiles": {"acme": {"full_scale_voltage_v": -1}}})
    assert e.value.field == "profiles.acme.full_scale_voltage_v"
    assert e.value.code == "not_positive"


def test_a_removed_vendor_is_gone(acme):
    registry.unregister("acme")
    try:
        assert "acme" not in registry.names()
        assert "acme" not in FIELD["conventions.firmware"].choices
        assert "profiles.acme" not in schema_json()
        assert "acme" not in report({**SEED_INPUT, "profiles": {}})["profiles"]
    finally:
        registry.register(acme)  # the fixture removes it again


def test_a_vendor_without_a_member_is_refused():
    import types
    with pytest.raises(TypeError, match="lacks"):
        registry.register(types.SimpleNamespace(NAME="half", NAMES=("Half", "半")))
    assert "half" not in registry.names()


@pytest.fixture
def ripple(tmp_path, monkeypatch):
    """The example analysis: its schema entries in the table's index (as the lines in
    ``fields.py`` would put them), its module as ``pulab.analyses.ripple`` (a file found on
    the package's path), its line appended to ``ANALYSES``."""
    entries = eval("(" + _recipe("Adding an analysis", 0) + ")", {"Section": Section, "F": F})
    for e in entries:
        if isinstance(e, Section):
            monkeypatch.setitem(fields.SECTIONS, e.path, e)
        else:
            monkeypatch.setitem(fields.FIELD, e.path, e)
            monkeypatch.setitem(fields._BY_SECTION, e.section, [e])
    (tmp_path / "ripple.py").write_text(_recipe("Adding an analysis", 1), encoding="utf-8")
    monkeypatch.setattr(pulab.analyses, "__path__", [*pulab.analyses.__path__, str(tmp_path)])
    line = eval(_recipe("Adding an analysis", 2).strip().rstrip(","),
                {"Analysis": Analysis, "Lazy": Lazy})
    monkeypatch.setattr(analyses, "ANALYSES", analyses.ANALYSES + (line,))
    yield line
    sys.modules.pop("pulab.analyses.ripple", None)


def test_a_new_analysis_is_in_the_report_when_asked(ripple):
    plain = report(SEED_INPUT)
    assert "ripple" not in plain and "ripple" not in plain["input"]
    assert "pulab.analyses.ripple" not in sys.modules  # imported on first use only

    r = report({**SEED_INPUT, "ripple": {}})
    assert "pulab.analyses.ripple" in sys.modules
    assert r["input"]["ripple"] == {"duty": 0.5}
    # the seed motor: U_dc 24 V, T 100 µs, L_q 0.6 mH; I_b = I_rated = 1.5 A (RMS bases)
    assert r["ripple"]["ripple_a"] == pytest.approx(24 * 0.25 * 1e-4 / 6e-4, rel=1e-12)
    assert r["ripple"]["ripple_pu"] == pytest.approx(1.0 / 1.5, rel=1e-12)
    assert report({**SEED_INPUT, "ripple": {"duty": 0.1}})["ripple"]["ripple_a"] == \
        pytest.approx(24 * 0.09 * 1e-4 / 6e-4, rel=1e-12)
    # asking adds its section and echo only: everything else is the plain report's
    assert {k: v for k, v in r.items() if k != "ripple"} == \
        {**plain, "input": {**plain["input"], "ripple": {"duty": 0.5}}}


@pytest.mark.parametrize("given, field, code", [
    ({"duty": 1.0}, "ripple.duty", "out_of_range"),
    ({"duty": 0}, "ripple.duty", "not_positive"),
    ({"duty": "half"}, "ripple.duty", "not_number"),
    ({"dutty": 0.5}, "ripple.dutty", "unknown_field"),
    (0.5, "ripple", "not_object"),
])
def test_a_new_analysis_input_is_checked_by_its_fields(ripple, given, field, code):
    with pytest.raises(InputError) as e:
        report({**SEED_INPUT, "ripple": given})
    assert (e.value.field, e.value.code) == (field, code)


def test_an_analysis_section_without_its_schema_entry_is_refused():
    with pytest.raises(InputError) as e:
        report({**SEED_INPUT, "ripple": {}})
    assert (e.value.field, e.value.code) == ("ripple", "unknown_section")


@pytest.mark.parametrize("entry", [
    {"stage": "model"},                                   # nothing prepares it
    {"stage": "report"},                                  # nothing runs it
    {"stage": "report", "run": len, "prepare": len},      # prepared after the profiles
    {"stage": "later", "run": len},
])
def test_an_analysis_without_what_its_stage_calls_is_refused(entry):
    with pytest.raises(ValueError, match="analysis half"):
        Analysis("half", "half", **entry)
