"""Tiny docs projects with pu-lab panels, built with the real tools: Sphinx, MkDocs, Doxygen, and a
Confluence user macro rendered as Confluence would (the template of docs/deploy.md).

Used by tests/py/test_pulab_docs.py and, to serve the built pages from another origin in Chromium,
by the e2e suite `docs-tools`:

    python tests/py/docs_samples.py OUT SITE     # SITE: the pu-lab site's URL, ending in /

pulab is installed from a wheel built here (offline), so the builds find the Sphinx extension and
the MkDocs plugin (by its entry point) as `pip install 'pulab[docs]'` gives them.
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import urllib.parse

ROOT = pathlib.Path(__file__).resolve().parents[2]
#: The 7.5 kW 380 V motor of tests/golden/04_ind380_7k5.json, and its oracle's numbers.
CASE = json.loads((ROOT / "tests" / "golden" / "04_ind380_7k5.json").read_text())
DOC_SITE = "https://intranet/tools/pu-lab/"  # the site URL in docs/deploy.md's snippets


def install_wheel(tmp: pathlib.Path) -> pathlib.Path:
    """pulab's wheel built from the work tree and installed into ``tmp/site``; returns that path."""
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


def run(site_packages: pathlib.Path, args: list, cwd: pathlib.Path):
    """``python -m ARGS`` with the installed wheel on the path."""
    env = {**os.environ, "PYTHONPATH": str(site_packages)}
    return subprocess.run([sys.executable, "-m", *args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=300)


def snippet(heading: str, lang: str, fence: str = "```") -> str:
    """The first block fenced ``fence + lang`` after `heading` in docs/deploy.md: the snippet
    users copy."""
    text = (ROOT / "docs" / "deploy.md").read_text()
    rest = text[text.index(heading):]
    start = rest.index(f"{fence}{lang}\n") + len(fence) + len(lang) + 1
    return rest[start:rest.index(f"\n{fence}\n", start)]


def sphinx_project(d: pathlib.Path, site: str) -> pathlib.Path:
    d.mkdir(parents=True, exist_ok=True)
    (d / "conf.py").write_text('project = "Motor notes"\nextensions = ["pulab_docs.sphinx"]\n'
                               f'pulab_site = "{site}"\n')
    (d / "index.rst").write_text(
        "Motor notes\n===========\n\nThe 7.5 kW compressor motor's firmware integers:\n\n"
        + snippet("### Sphinx and MkDocs", "rst") + "\n\nThe seed motor's bases:\n\n.. pu-lab::\n   :panel: bases\n"
        "   :lang: en\n")
    return d


def mkdocs_project(d: pathlib.Path, site: str) -> pathlib.Path:
    (d / "docs").mkdir(parents=True, exist_ok=True)
    # highlightjs off: the theme would fetch it from a CDN (this docs site works offline)
    (d / "mkdocs.yml").write_text("site_name: Motor notes\ntheme:\n  name: mkdocs\n  highlightjs: false\n"
                                  + snippet("### Sphinx and MkDocs", "yaml").replace(DOC_SITE, site) + "\n")
    fence = snippet("### Sphinx and MkDocs", "markdown", "````")
    (d / "docs" / "index.md").write_text(
        "# Motor notes\n\nThe 7.5 kW compressor motor's firmware integers:\n\n" + fence
        + "\n\nThe seed motor's bases:\n\n```pu-lab panel=bases lang=en\n```\n")
    return d


def doxygen_project(d: pathlib.Path, site: str) -> pathlib.Path:
    d.mkdir(parents=True, exist_ok=True)
    (d / "current_loop.h").write_text(
        snippet("### Doxygen", "c").replace(DOC_SITE, site)
        + "\nint current_loop_period; /**< the loop's period in ticks */\n")
    (d / "Doxyfile").write_text("PROJECT_NAME = \"Motor firmware\"\nINPUT = current_loop.h\n"
                                "OUTPUT_DIRECTORY = out\nGENERATE_LATEX = NO\nHAVE_DOT = NO\n"
                                "QUIET = YES\nWARN_AS_ERROR = YES\n")
    return d


def _url_encode(text: str) -> str:
    """Java's URLEncoder.encode(text, "UTF-8") (Confluence's $generalUtil.urlEncode)."""
    return urllib.parse.quote_plus(text, safe="*-._")


def confluence_macro(site: str, params: dict) -> str:
    """The user macro of docs/deploy.md rendered for ``params`` (Panel, Lang, Input): the subset
    of Velocity the template uses (## comments, $paramX, #if("$!paramX" != "")…#end,
    urlEncode().replace)."""
    origin = urllib.parse.urlsplit(site)
    tpl = snippet("### Confluence", "velocity").replace(DOC_SITE, site).replace(
        "'https://intranet'", f"'{origin.scheme}://{origin.netloc}'")
    tpl = "\n".join(line for line in tpl.splitlines() if not line.startswith("##"))
    tpl = re.sub(r'#if\("\$!param(\w+)" != ""\)(.*?)#end',
                 lambda m: m[2] if params.get(m[1]) else "", tpl, flags=re.S)
    tpl = re.sub(r'\$generalUtil\.urlEncode\(\$param(\w+)\)\.replace\("\+", "%20"\)',
                 lambda m: _url_encode(params[m[1]]).replace("+", "%20"), tpl)
    return re.sub(r"\$param(\w+)", lambda m: params.get(m[1], ""), tpl)


def confluence_page(d: pathlib.Path, site: str) -> pathlib.Path:
    d.mkdir(parents=True, exist_ok=True)
    body = (
        "<h1>Motor notes</h1><p>The 7.5 kW compressor motor's firmware integers:</p>"
        + confluence_macro(site, {"Panel": "vendor", "Lang": "zh",
                                  "Input": json.dumps(CASE["input"])})
        + "<p>The seed motor's bases:</p>"
        + confluence_macro(site, {"Panel": "bases", "Lang": "en", "Input": ""}))
    (d / "index.html").write_text(
        '<!doctype html><html><head><meta charset="utf-8"><title>Motor notes - Confluence</title>'
        '<meta name="viewport" content="width=device-width"><style>body{font-family:sans-serif;'
        "max-width:900px;margin:auto;padding:8px}</style></head><body>" + body + "</body></html>")
    return d


def build_all(out: pathlib.Path, site: str) -> dict:
    """Every sample built under ``out``; returns {tool: the built page's path}."""
    pkgs = install_wheel(out / "wheel")
    sx = sphinx_project(out / "sphinx", site)
    r = run(pkgs, ["sphinx", "-W", "-q", "-b", "html", str(sx), str(sx / "_build")], sx)
    assert r.returncode == 0, r.stderr
    mk = mkdocs_project(out / "mkdocs", site)
    r = run(pkgs, ["mkdocs", "build", "--strict", "-q"], mk)
    assert r.returncode == 0, r.stderr
    pages = {"sphinx": sx / "_build" / "index.html", "mkdocs": mk / "site" / "index.html",
             "confluence": confluence_page(out / "confluence", site) / "index.html"}
    if shutil.which("doxygen"):
        dx = doxygen_project(out / "doxygen", site)
        r = subprocess.run(["doxygen", "Doxyfile"], cwd=dx, capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        pages["doxygen"] = dx / "out" / "html" / "current__loop_8h.html"
    return pages


if __name__ == "__main__":
    built = build_all(pathlib.Path(sys.argv[1]), sys.argv[2])
    print(json.dumps({k: str(v) for k, v in built.items()}))
