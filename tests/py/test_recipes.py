"""The recipes of docs/design.md work as written: "Adding a vendor" builds the example vendor
from the document's own code block (a folder of one ``__init__.py``), registers it as its line
in ``profiles/registry.py`` would, finds it wherever a vendor appears, and removes it again."""

from __future__ import annotations

import importlib.util
import re
import sys

import pytest

from conftest import ROOT, SEED_INPUT
from pulab import report
from pulab.profiles import header, registry
from pulab.profiles.translate import translate
from pulab.schema.catalog import render
from pulab.schema.fields import FIELD, schema_json


def _recipe(title: str) -> str:
    """The first ```python block after the paragraph that starts with ``**title**``."""
    text = (ROOT / "docs" / "design.md").read_text(encoding="utf-8")
    start = text.index(f"**{title}**")
    return re.search(r"```python\n(.*?)```", text[start:], re.S)[1]


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
