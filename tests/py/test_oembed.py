"""pulab oembed (pulab.cli.oembed, pulab.html.oembed): static oEmbed 1.0 descriptions of the panels.

The fields required of a `rich` response are those of the oEmbed 1.0 specification (section 2.3.4:
version, type, html, width, height); the discovery link is its section 4 (`<link rel="alternate"
type="application/json+oembed">`). The e2e suite `docs-tools` plays the consumer in Chromium.
"""
import json
import subprocess
import sys
from urllib.parse import unquote, urlsplit

import pytest

from conftest import ROOT
from test_html import Page

SITE = "https://intranet/tools/pu-lab/"
CASE = json.loads((ROOT / "tests" / "golden" / "04_ind380_7k5.json").read_text())


def _pulab(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "pulab", *args], capture_output=True, text=True,
                          input=stdin, env={"PYTHONPATH": str(ROOT / "py")})


@pytest.fixture
def dist(tmp_path):
    (tmp_path / "embed.js").write_text("")  # what marks a built site
    return tmp_path


def test_every_panel_gets_a_description_and_a_discovery_page(dist):
    out = _pulab("oembed", SITE, str(dist))
    assert out.returncode == 0, out.stderr
    from pulab.html import PANELS
    assert out.stdout.split() == [f"{SITE}oembed/seed/{p}.html" for p in PANELS]
    for panel in PANELS:
        doc = json.loads((dist / "oembed" / "seed" / f"{panel}.json").read_text())
        assert doc["version"] == "1.0" and doc["type"] == "rich"
        assert isinstance(doc["width"], int) and isinstance(doc["height"], int)
        assert doc["provider_name"] == "pu-lab" and doc["provider_url"] == SITE
        (frame,) = [a for t, a in Page(doc["html"]).elements if t == "iframe"]
        assert frame["src"] == f"{SITE}?embed={panel}" and frame["title"] == f"pu-lab: {panel}"
        page = Page((dist / "oembed" / "seed" / f"{panel}.html").read_text())
        links = [a for t, a in page.elements
                 if t == "link" and a.get("type") == "application/json+oembed"]
        assert [a["href"] for a in links] == [f"{SITE}oembed/seed/{panel}.json"]
        assert ("a", {"href": frame["src"]}) in page.elements


def test_a_named_motor_carries_its_input_in_the_frame(dist):
    out = _pulab("oembed", SITE, str(dist), "--input", "-", "--name", "compressor-7k5",
                 "--panel", "vendor", stdin=json.dumps(CASE["input"]))
    assert out.returncode == 0, out.stderr
    doc = json.loads((dist / "oembed" / "compressor-7k5" / "vendor.json").read_text())
    assert doc["title"] == "pu-lab: vendor (compressor-7k5)"
    (frame,) = [a for t, a in Page(doc["html"]).elements if t == "iframe"]
    url = urlsplit(frame["src"])
    assert url.query == "embed=vendor" and url.fragment.startswith("in=")
    # the site reads #in= with decodeURIComponent (web/src/state.ts): percent-decoding
    assert json.loads(unquote(url.fragment[3:])) == CASE["input"]
    assert not (dist / "oembed" / "compressor-7k5" / "bases.json").exists()


@pytest.mark.parametrize("args, line", [
    (["intranet/pu-lab/", "DIST"], "error: site: 'intranet/pu-lab/' must be the site's absolute URL, ending in '/'"),
    ([SITE, "DIST", "--panel", "nope"], "error: panel: 'nope' is not a pu-lab panel"),
    ([SITE, "DIST", "--name", "Big Motor"], "error: name: 'Big Motor' is not a-z, 0-9 and '-'"),
    ([SITE, "DIST", "--input", "-"], "error: name: required with --input"),
    ([SITE, "DIST", "--input", "-", "--name", "m"], "error: motor.rated_voltage_v: "),
    ([SITE, "NOWHERE"], "error: dist: "),
])
def test_bad_arguments_exit_2_naming_the_field(dist, args, line):
    args = [str(dist) if a == "DIST" else str(dist / "none") if a == "NOWHERE" else a for a in args]
    out = _pulab("oembed", *args, stdin='{"motor": {"rated_voltage_v": -1}}')
    assert out.returncode == 2
    assert out.stderr.startswith(line) and out.stderr.count("\n") == 1, out.stderr
    assert not (dist / "oembed").exists()
