"""pulab_docs and the docs snippets: real Sphinx, MkDocs and Doxygen builds of tiny projects with
pu-lab panels (tests/py/docs_samples.py, from the snippets of docs/deploy.md), and the widget.

pulab is built into a wheel (offline, like test_packaging) and installed into a throw-away
directory, so the builds find the Sphinx extension and the MkDocs plugin the way a user's
`pip install 'pulab[docs]'` does (the MkDocs plugin through its entry point). The numbers in the
built pages are compared with the golden vectors (tests/oracle/, which never import pulab).
"""
import json
import os
import shutil
import subprocess
import sys

import pytest

from conftest import ROOT
from docs_samples import (CASE, DOC_SITE, confluence_macro, doxygen_project, install_wheel,
                          mkdocs_project, run, snippet, sphinx_project)
from test_html import Page, _same

SITE = "http://127.0.0.1:9/tools/pu-lab/"
SEED_Z_B = 6.543303050815759  # tests/golden/01_seed_motor.json


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    return install_wheel(tmp_path_factory.mktemp("wheel"))


def _check_panel(html: str, panel: str, lang: str | None, inp: dict | None):
    """The built page holds the element with its attributes, embed.js and the panel's numbers."""
    page = Page(html)
    els = [a for t, a in page.elements if t == "pu-lab-panel" and a.get("panel") == panel]
    assert len(els) == 1, panel
    assert els[0].get("lang") == lang
    assert (json.loads(els[0]["input"]) if "input" in els[0] else None) == inp
    assert ("script", {"src": SITE + "embed.js"}) in page.elements
    return page.cells


def _check_numbers(cells):
    exp = CASE["expected"]
    for name in ("Rpm", "LD", "LQ", "FreqPer", "FluxRotor", "maxu"):
        assert cells[f"vendor.{name}.value"][0] == str(exp["vendor"][name]["value"]), name
        assert cells[f"vendor.{name}.value"][1] == str(exp["vendor"][name]["value"]), name


def test_sphinx_directive_builds_panels_with_their_numbers(installed, tmp_path):
    sx = sphinx_project(tmp_path, SITE)
    out = run(installed, ["sphinx", "-W", "-q", "-b", "html", str(sx), str(sx / "_build")], sx)
    assert out.returncode == 0, out.stderr
    html = (sx / "_build" / "index.html").read_text()
    _check_numbers(_check_panel(html, "vendor", "zh", CASE["input"]))
    assert _same(_check_panel(html, "bases", "en", None)["base.Z_b"][0], SEED_Z_B)
    # the search index holds the prerendered numbers (scripts off, search engines)
    index = (sx / "_build" / "searchindex.js").read_text()
    assert str(CASE["expected"]["vendor"]["Rpm"]["value"]) in index


def _sphinx_fails(installed, tmp_path, conf: str, body: str):
    (tmp_path / "conf.py").write_text(conf)
    (tmp_path / "index.rst").write_text(f"T\n=\n\n{body}")
    out = run(installed, ["sphinx", "-W", "-q", "-b", "html", str(tmp_path), str(tmp_path / "_b")],
              tmp_path)
    assert out.returncode != 0
    return out.stderr


@pytest.mark.parametrize("body, options, message", [
    ('{"motor": {"rated_voltage_v": -1}}', ":panel: bases", "pu-lab: motor.rated_voltage_v: "),
    ('{"motor": ', ":panel: bases", "pu-lab: input: not valid JSON"),
    ("", ":panel: nope", "pu-lab: panel: 'nope' is not a pu-lab panel"),
    ("", ":lang: fr", "pu-lab: lang: 'fr' is not 'en' or 'zh'"),
])
def test_sphinx_bad_input_stops_the_build_naming_the_field(installed, tmp_path, body, options,
                                                           message):
    err = _sphinx_fails(installed, tmp_path,
                        f'extensions = ["pulab_docs.sphinx"]\npulab_site = "{SITE}"\n',
                        f".. pu-lab::\n   {options}\n\n   {body}\n")
    assert message in err and "index.rst:4" in err, err


def test_sphinx_without_site_says_so(installed, tmp_path):
    err = _sphinx_fails(installed, tmp_path, 'extensions = ["pulab_docs.sphinx"]\n', ".. pu-lab::\n")
    assert "pu-lab: site: " in err, err


def test_mkdocs_fences_build_panels_with_their_numbers(installed, tmp_path):
    mk = mkdocs_project(tmp_path, SITE)
    with (mk / "docs" / "index.md").open("a") as f:
        f.write("\nA code block stays one:\n\n```python\nx = 1\n```\n")
    out = run(installed, ["mkdocs", "build", "--strict", "-q"], mk)
    assert out.returncode == 0, out.stderr
    html = (mk / "site" / "index.html").read_text()
    _check_numbers(_check_panel(html, "vendor", "zh", CASE["input"]))
    assert _same(_check_panel(html, "bases", "en", None)["base.Z_b"][0], SEED_Z_B)
    assert "x = 1" in html and "<p><pu-lab-panel" not in html  # raw HTML, not wrapped in <p>
    index = (mk / "site" / "search" / "search_index.json").read_text()
    assert str(CASE["expected"]["vendor"]["Rpm"]["value"]) in index


@pytest.mark.parametrize("fence, message", [
    ('```pu-lab panel=bases\n{"motor": {"rated_voltage_v": -1}}\n```', "pu-lab: motor.rated_voltage_v: "),
    ("```pu-lab panel=bases colour=red\n```", "pu-lab: colour: unknown option"),
    ("```pu-lab vendor\n```", "pu-lab: vendor: options are written name=value"),
])
def test_mkdocs_bad_fence_stops_the_build_naming_the_field(installed, tmp_path, fence, message):
    mk = mkdocs_project(tmp_path, SITE)
    (mk / "docs" / "index.md").write_text(f"# T\n\n{fence}\n")
    out = run(installed, ["mkdocs", "build", "--strict", "-q"], mk)
    assert out.returncode != 0
    assert f"index.md: {message}" in out.stderr, out.stderr


def _require(tool: str, capsys):
    if shutil.which(tool):
        return
    msg = f"SKIPPED: the {tool} snippet is built with {tool} (apt-get install {tool})"
    if os.environ.get("CI") == "true":
        pytest.fail(msg + " — mandatory under CI=true")
    with capsys.disabled():
        print(f"\n\n{'!' * len(msg)}\n{msg}\n{'!' * len(msg)}\n", file=sys.stderr)
    pytest.skip(msg)


def test_doxygen_snippet_builds_a_page_with_the_panel(tmp_path, capsys):
    _require("doxygen", capsys)
    dx = doxygen_project(tmp_path, SITE)
    out = subprocess.run(["doxygen", "Doxyfile"], cwd=dx, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    page = Page((dx / "out" / "html" / "current__loop_8h.html").read_text())
    assert ("script", {"src": SITE + "embed.js"}) in page.elements
    (el,) = [a for t, a in page.elements if t == "pu-lab-panel"]
    assert el["panel"] == "vendor" and json.loads(el["input"]) == CASE["input"]


def test_confluence_macro_renders_an_iframe_of_the_panel():
    from urllib.parse import unquote, urlsplit
    html = confluence_macro(SITE, {"Panel": "vendor", "Lang": "zh",
                                   "Input": json.dumps({"motor": {"rs_ohm": "1 + 2"}})})
    assert "$" not in html and "#if" not in html and "#end" not in html  # all of it rendered
    page = Page(html)
    (frame,) = [a for t, a in page.elements if t == "iframe"]
    url = urlsplit(frame["src"])
    assert url.query == "embed=vendor&lang=zh"
    # what the site's hash parser (decodeURIComponent) reads: the JSON text, '+' and spaces intact
    assert json.loads(unquote(url.fragment.removeprefix("in="))) == {"motor": {"rs_ohm": "1 + 2"}}
    seed = Page(confluence_macro(SITE, {"Panel": "bases", "Lang": "en", "Input": ""}))
    assert [a["src"] for t, a in seed.elements if t == "iframe"] == [SITE + "?embed=bases&lang=en"]
    assert DOC_SITE in snippet("### Confluence", "velocity")


def test_widget_state_and_front_end(installed):
    import traitlets
    from pulab_docs.widget import PanelWidget
    w = PanelWidget(site=SITE, panel="vendor", input=CASE["input"], lang="zh")
    state = w.get_state()
    assert (state["site"], state["panel"], state["input"], state["lang"]) == \
        (SITE, "vendor", CASE["input"], "zh")
    esm = state["_esm"]
    assert "new URL('embed.js', model.get('site'))" in esm and "pu-lab-report" in esm
    # what the browser sends back when the panel goes live
    w.set_state({"report": {"vendor": {"Rpm": {"value": 7}}}, "numbers": "live"})
    assert w.report["vendor"]["Rpm"]["value"] == 7 and w.numbers == "live"
    with pytest.raises(traitlets.TraitError):
        w.report = {}  # only the browser sets it
    with pytest.raises(traitlets.TraitError, match="site: "):
        PanelWidget(site="https://intranet/pu-lab")
    with pytest.raises(traitlets.TraitError):
        PanelWidget(site=SITE, panel="nope")
    # the ESM file ships in the wheel and is valid JavaScript
    assert (installed / "pulab_docs" / "widget.js").read_text() == esm
    node = shutil.which("node")
    assert node, "node is needed (the site's build runs on it)"
    subprocess.run([node, "--check", str(ROOT / "py" / "pulab_docs" / "widget.js")], check=True)


def test_pulab_imports_no_docs_tool():
    code = ("import sys, pulab, pulab.html; bad = {'sphinx', 'mkdocs', 'docutils', 'anywidget', "
            "'traitlets'} & {m.split('.')[0] for m in sys.modules}; print(sorted(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": str(ROOT / "py")})
    assert out.stdout.strip() == "[]", out
