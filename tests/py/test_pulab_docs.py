"""pulab_docs: real Sphinx and MkDocs builds of tiny projects with pu-lab panels, and the widget.

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
from test_html import Page, _same

CASE = json.loads((ROOT / "tests" / "golden" / "04_ind380_7k5.json").read_text())
SITE = "https://intranet/tools/pu-lab/"


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """A directory holding the installed pulab wheel (pulab, pulab_docs and their metadata)."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"
    for pkg in ("pulab", "pulab_docs"):
        shutil.copytree(ROOT / "py" / pkg, src / "py" / pkg,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, src / name)
    pip = [sys.executable, "-m", "pip", "-q", "--disable-pip-version-check"]
    subprocess.run(pip + ["wheel", "--no-build-isolation", "--no-deps", "--no-index", "-w",
                          str(tmp / "wheels"), str(src)], check=True, capture_output=True)
    (wheel,) = (tmp / "wheels").glob("pulab-*.whl")
    subprocess.run(pip + ["install", "--no-deps", "--no-index", "--target", str(tmp / "site"),
                          str(wheel)], check=True, capture_output=True)
    return tmp / "site"


def _run(installed, args, cwd):
    env = {**os.environ, "PYTHONPATH": str(installed)}
    return subprocess.run([sys.executable, "-m", *args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=300)


def _check_panel(html: str, panel: str, lang: str | None, inp: dict | None):
    """The built page holds the element with its attributes, embed.js and the panel's numbers."""
    page = Page(html)
    els = [a for t, a in page.elements if t == "pu-lab-panel" and a.get("panel") == panel]
    assert len(els) == 1, panel
    assert els[0].get("lang") == lang
    assert (json.loads(els[0]["input"]) if "input" in els[0] else None) == inp
    assert ("script", {"type": "module", "src": SITE + "embed.js"}) in page.elements
    return page.cells


def _check_numbers(cells):
    exp = CASE["expected"]
    for name in ("Rpm", "LD", "LQ", "FreqPer", "FluxRotor", "maxu"):
        assert cells[f"vendor.{name}.value"][0] == str(exp["vendor"][name]["value"]), name
        assert cells[f"vendor.{name}.value"][1] == str(exp["vendor"][name]["value"]), name


def test_sphinx_directive_builds_panels_with_their_numbers(installed, tmp_path):
    (tmp_path / "conf.py").write_text(
        f'project = "motor"\nextensions = ["pulab_docs.sphinx"]\npulab_site = "{SITE}"\n')
    (tmp_path / "index.rst").write_text(
        "Motor\n=====\n\nIts firmware integers:\n\n.. pu-lab::\n   :panel: vendor\n   :lang: zh\n\n"
        f"   {json.dumps(CASE['input'])}\n\nThe seed's bases:\n\n.. pu-lab::\n   :panel: bases\n")
    out = _run(installed, ["sphinx", "-W", "-q", "-b", "html", str(tmp_path), str(tmp_path / "_build")],
               tmp_path)
    assert out.returncode == 0, out.stderr
    html = (tmp_path / "_build" / "index.html").read_text()
    _check_numbers(_check_panel(html, "vendor", "zh", CASE["input"]))
    cells = _check_panel(html, "bases", None, None)
    assert _same(cells["base.Z_b"][0], 6.543303050815759)  # the seed motor, tests/golden/01
    # the search index holds the prerendered numbers (scripts off, search engines)
    index = (tmp_path / "_build" / "searchindex.js").read_text()
    assert str(CASE["expected"]["vendor"]["Rpm"]["value"]) in index


@pytest.mark.parametrize("body, options, message", [
    ('{"motor": {"rated_voltage_v": -1}}', ":panel: bases", "motor.rated_voltage_v"),
    ('{"motor": ', ":panel: bases", "pu-lab: input: not valid JSON"),
    ("", ":panel: nope", "pu-lab: panel: 'nope' is not a pu-lab panel"),
])
def test_sphinx_bad_input_stops_the_build_naming_the_field(installed, tmp_path, body, options,
                                                           message):
    (tmp_path / "conf.py").write_text(f'extensions = ["pulab_docs.sphinx"]\npulab_site = "{SITE}"\n')
    (tmp_path / "index.rst").write_text(f"T\n=\n\n.. pu-lab::\n   {options}\n\n   {body}\n")
    out = _run(installed, ["sphinx", "-W", "-q", "-b", "html", str(tmp_path), str(tmp_path / "_b")],
               tmp_path)
    assert out.returncode != 0
    assert message in out.stderr and "index.rst:4" in out.stderr, out.stderr


def test_sphinx_without_site_says_so(installed, tmp_path):
    (tmp_path / "conf.py").write_text('extensions = ["pulab_docs.sphinx"]\n')
    (tmp_path / "index.rst").write_text("T\n=\n\n.. pu-lab::\n")
    out = _run(installed, ["sphinx", "-W", "-q", "-b", "html", str(tmp_path), str(tmp_path / "_b")],
               tmp_path)
    assert out.returncode != 0 and "pu-lab: site: " in out.stderr


def _mkdocs_site(tmp_path, page: str, site=SITE):
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "index.md").write_text(page)
    (tmp_path / "mkdocs.yml").write_text(
        f"site_name: motor\nplugins:\n  - search\n  - pu-lab:\n      site: {site}\n")


def test_mkdocs_fences_build_panels_with_their_numbers(installed, tmp_path):
    _mkdocs_site(tmp_path, "# Motor\n\nIts firmware integers:\n\n```pu-lab panel=vendor lang=zh\n"
                           f"{json.dumps(CASE['input'], indent=2)}\n```\n\nThe seed's bases:\n\n"
                           "~~~pu-lab\n~~~\n\nA code block stays one:\n\n```python\nx = 1\n```\n")
    out = _run(installed, ["mkdocs", "build", "--strict", "-q"], tmp_path)
    assert out.returncode == 0, out.stderr
    html = (tmp_path / "site" / "index.html").read_text()
    _check_numbers(_check_panel(html, "vendor", "zh", CASE["input"]))
    cells = _check_panel(html, "bases", None, None)
    assert _same(cells["base.Z_b"][0], 6.543303050815759)
    assert "x = 1" in html and "<p><pu-lab-panel" not in html  # raw HTML, not wrapped in <p>
    index = (tmp_path / "site" / "search" / "search_index.json").read_text()
    assert str(CASE["expected"]["vendor"]["Rpm"]["value"]) in index


@pytest.mark.parametrize("fence, message", [
    ('```pu-lab panel=bases\n{"motor": {"rated_voltage_v": -1}}\n```', "motor.rated_voltage_v"),
    ("```pu-lab panel=bases colour=red\n```", "pu-lab: colour: unknown option"),
    ("```pu-lab vendor\n```", "pu-lab: vendor: options are written name=value"),
])
def test_mkdocs_bad_fence_stops_the_build_naming_the_field(installed, tmp_path, fence, message):
    _mkdocs_site(tmp_path, f"# T\n\n{fence}\n")
    out = _run(installed, ["mkdocs", "build", "--strict", "-q"], tmp_path)
    assert out.returncode != 0
    assert f"index.md: {message}" in out.stderr or message in out.stderr, out.stderr
    assert "index.md" in out.stderr


def test_widget_state_and_front_end(installed):
    from pulab_docs.widget import PanelWidget
    import traitlets
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
    shipped = installed / "pulab_docs" / "widget.js"
    assert shipped.read_text() == esm
    node = shutil.which("node")
    assert node, "node is needed (the site's build runs on it)"
    subprocess.run([node, "--check", str(ROOT / "py" / "pulab_docs" / "widget.js")], check=True)


def test_pulab_imports_no_docs_tool():
    code = ("import sys, pulab, pulab.html; bad = {'sphinx', 'mkdocs', 'docutils', 'anywidget', "
            "'traitlets'} & {m.split('.')[0] for m in sys.modules}; print(sorted(bad))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": str(ROOT / "py")})
    assert out.stdout.strip() == "[]", out


def _snippet(heading: str, lang: str) -> str:
    """The first ```lang block after `heading` in docs/deploy.md: the snippet users copy."""
    text = (ROOT / "docs" / "deploy.md").read_text()
    rest = text[text.index(heading):]
    start = rest.index(f"```{lang}\n") + len(lang) + 4
    return rest[start:rest.index("\n```", start)]


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
    site = "http://127.0.0.1:9/tools/pu-lab/"
    (tmp_path / "current_loop.h").write_text(
        _snippet("### Doxygen", "c").replace("https://intranet/tools/pu-lab/", site)
        + "\nint current_loop_period; /**< the loop's period in ticks */\n")
    (tmp_path / "Doxyfile").write_text("INPUT = current_loop.h\nOUTPUT_DIRECTORY = out\n"
                                       "GENERATE_LATEX = NO\nHAVE_DOT = NO\nQUIET = YES\n"
                                       "WARN_AS_ERROR = YES\n")
    out = subprocess.run(["doxygen", "Doxyfile"], cwd=tmp_path, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    page = Page((tmp_path / "out" / "html" / "current__loop_8h.html").read_text())
    assert ("script", {"type": "module", "src": site + "embed.js"}) in page.elements
    (el,) = [a for t, a in page.elements if t == "pu-lab-panel"]
    assert el["panel"] == "vendor" and json.loads(el["input"]) == CASE["input"]
