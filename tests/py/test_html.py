"""pulab.html: a panel's prerendered numbers and a notebook's tables carry the report's values.

Expected values are the golden vectors (tests/oracle/, which never import pulab), read back from
the HTML with the standard library's HTML parser by their data-key / data-value attributes.
"""
import json
import math
import re
from html.parser import HTMLParser

import pytest

from conftest import ROOT, SEED_INPUT
from pulab import InputError
from pulab.html import PANELS, Report, panel_html, report_html

GOLDEN = sorted((ROOT / "tests" / "golden").glob("[0-9]*.json"))


class Page(HTMLParser):
    """Elements with their attributes, and the data-key cells (key → (data-value, text))."""

    def __init__(self, text):
        super().__init__()
        self.elements, self.cells, self._key, self.text = [], {}, None, []
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.elements.append((tag, a))
        if "data-key" in a:
            self._key = a["data-key"]
            self.cells[self._key] = [a["data-value"], ""]

    def handle_endtag(self, tag):
        self._key = None

    def handle_data(self, data):
        self.text.append(data)
        if self._key:
            self.cells[self._key][1] += data


def _at(d, path):
    for part in path.split("."):
        d = d[part]
    return d


def _same(shown: str, expected) -> bool:
    if isinstance(expected, int):
        return shown == str(expected)
    return math.isclose(float(shown), expected, rel_tol=1e-12, abs_tol=1e-15)


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: p.stem)
def test_prerendered_numbers_are_the_golden_values(path):
    case = json.loads(path.read_text())
    exp = case["expected"]
    for panel, section in (("bases", "base"), ("vendor", "vendor"), ("current", "current_pi"),
                           ("pll", "pll")):
        if section not in exp:
            continue
        cells = Page(panel_html(panel, case["input"], site="/pu-lab/")).cells
        checked = 0
        for key, (value, text) in cells.items():
            try:
                want = _at(exp, key)
            except (KeyError, TypeError):
                continue  # a value the golden file does not hold (e.g. the vendor's ideal)
            assert _same(value, want), (path.stem, key, value, want)
            assert text.strip(), key  # every number is shown, not only in the attribute
            checked += 1
        assert checked >= 4, (path.stem, panel)
    if "vendor" in exp:  # every golden vendor integer is in the vendor panel
        cells = Page(panel_html("vendor", case["input"], site="/pu-lab/")).cells
        for name, res in exp["vendor"].items():
            if isinstance(res, dict) and "value" in res:
                assert cells[f"vendor.{name}.value"][0] == str(res["value"]), name


def test_element_attributes_carry_the_panel_and_the_input():
    inp = {"motor": {**SEED_INPUT["motor"], "rated_voltage_v": 380}, "drive": SEED_INPUT["drive"]}
    page = Page(panel_html("vendor", inp, site="https://intranet/tools/pu-lab/", lang="zh",
                           theme="dark"))
    (script,) = [a for t, a in page.elements if t == "script"]
    assert script == {"src": "https://intranet/tools/pu-lab/embed.js"}
    (el,) = [a for t, a in page.elements if t == "pu-lab-panel"]
    assert el["panel"] == "vendor" and el["lang"] == "zh" and el["theme"] == "dark"
    assert json.loads(el["input"]) == inp
    # zh titles; the firmware's flags are shown with the number (Rpm truncates in the seed code)
    assert "厂商整数" in "".join(page.text) and "理想值" in "".join(page.text)
    assert re.search(r"Rpm.*\[truncation\]", "".join(page.text))


def test_seed_when_no_input_and_panels_without_numbers():
    page = Page(panel_html("vendor", None, site="/pu-lab/"))
    (el,) = [a for t, a in page.elements if t == "pu-lab-panel"]
    assert "input" not in el and "lang" not in el
    assert page.cells["vendor.Rpm.value"][0] == "15022"  # seed 1.4-7
    page = Page(panel_html("qcalc", None, site="/pu-lab/"))
    assert page.cells == {}
    assert ("a", {"href": "/pu-lab/?embed=qcalc"}) in page.elements


@pytest.mark.parametrize("kw, field", [
    ({"panel": "nope"}, "panel"), ({"lang": "fr"}, "lang"), ({"theme": "blue"}, "theme"),
    ({"site": "https://intranet/pu-lab"}, "site"),
])
def test_bad_options_name_the_option(kw, field):
    args = {"panel": "bases", "site": "/pu-lab/", **kw}
    with pytest.raises(ValueError, match=f"^{field}: "):
        panel_html(args.pop("panel"), SEED_INPUT, **args)


def test_bad_input_names_the_field():
    with pytest.raises(InputError) as e:
        panel_html("bases", {"motor": {**SEED_INPUT["motor"], "rated_voltage_v": -1},
                             "drive": SEED_INPUT["drive"]}, site="/pu-lab/")
    assert e.value.field == "motor.rated_voltage_v"


def test_panel_ids_are_the_sites():
    registry = (ROOT / "web" / "src" / "panels" / "registry.ts").read_text()
    files = dict(re.findall(r"import \{ (\w+)(?:, \w+)? \} from '\./(\w+)'", registry))
    ids = []
    for var in re.findall(r"^  (\w+Panel),", registry, re.M):
        src = (ROOT / "web" / "src" / "panels" / f"{files[var]}.ts").read_text()
        ids.append(re.search(r"\bid: '(\w+)'", src)[1])
    assert tuple(ids) == PANELS


def test_notebook_report_renders_readable_tables():
    case = json.loads((ROOT / "tests" / "golden" / "04_ind380_7k5.json").read_text())
    r = Report(case["input"])
    assert r["vendor"]["Rpm"]["value"] == case["expected"]["vendor"]["Rpm"]["value"]  # still the dict
    page = Page(r._repr_html_())
    captions = [t for t in page.text if t in ("Bases", "Per unit", "Vendor integers", "Current PI",
                                              "PLL", "Mechanical", "Magic constants")]
    assert len(captions) == 7
    for key in ("base.Z_b", "pu.Rs", "vendor.LD.value", "current_pi.q.pm_kp", "pll.kp_pu"):
        assert _same(page.cells[key][0], _at(case["expected"], key)), key
    zh = "".join(Page(Report(case["input"], lang="zh")._repr_html_()).text)
    assert "基值" in zh and "厂商整数" in zh and "提示" in zh  # the 380 V motor's review notes
    with pytest.raises(ValueError, match="^lang: "):
        Report(case["input"], lang="fr")


def test_notebook_report_shows_findings_and_warnings():
    # the seed motor has findings (the vendor constants' quantization notes at least)
    r = Report(SEED_INPUT)
    text = "".join(Page(report_html(r)).text)
    assert r["review"]["findings"] and all(x["message"] in text for x in r["review"]["findings"])
    assert all(w in text for w in r["warnings"])
