"""The ``oembed`` subcommand: static oEmbed descriptions of the panels, written into ``dist/``.

::

    pulab oembed SITE_URL DIST                       # every panel, the seed motor
    pulab oembed SITE_URL DIST --input motor.json --name compressor [--panel vendor ...]

writes ``DIST/oembed/NAME/PANEL.json`` (the oEmbed 1.0 response) and ``DIST/oembed/NAME/PANEL.html``
(the URL to paste into a wiki: its discovery link points at the JSON). Run it where the site is
deployed: the descriptions hold the site's absolute URL, which the build cannot know.

Exit status: 0; 2 with one line ``error: FIELD: MESSAGE`` on stderr (``site``, ``name``,
``panel``, ``dist`` or the input's field).
"""

from __future__ import annotations

import json
import pathlib
import re
import sys

from ..html import PANELS, oembed, oembed_page
from ..schema.errors import InputError
from .family import read_json

__all__ = ["add_oembed_parser"]


def add_oembed_parser(sub) -> None:
    p = sub.add_parser("oembed", help="write the panels' oEmbed descriptions into the site")
    p.add_argument("site", help="the site's absolute URL, ending in / (https://intranet/pu-lab/)")
    p.add_argument("dist", help="the deployed site's directory (dist/)")
    p.add_argument("--input", help="input JSON file ('-' = stdin); default: the seed motor")
    p.add_argument("--name", help="the motor's name in the URLs (a-z, 0-9, -); default: seed")
    p.add_argument("--panel", action="append", help="a panel (repeatable); default: all")
    p.set_defaults(run=run)


def _fail(field: str, message: str) -> int:
    print(f"error: {field}: {message}", file=sys.stderr)
    return 2


def run(args) -> int:
    name = args.name or ("seed" if args.input is None else None)
    if name is None:
        return _fail("name", "required with --input (it names the motor in the URLs)")
    if not re.fullmatch(r"[a-z0-9][a-z0-9-]{0,63}", name):
        return _fail("name", f"{name!r} is not a-z, 0-9 and '-' (at most 64)")
    dist = pathlib.Path(args.dist)
    if not (dist / "embed.js").is_file():
        return _fail("dist", f"{str(dist)!r} holds no embed.js: not a built pu-lab site")
    panels = args.panel or list(PANELS)
    try:
        inp = None if args.input is None else read_json(args.input)
        docs = {p: oembed(args.site, p, inp, None if name == "seed" else f"pu-lab: {p} ({name})")
                for p in panels}
    except InputError as e:
        return _fail(e.field, e.message)
    except ValueError as e:
        field, _, message = str(e).partition(": ")
        return _fail(field, message)
    out = dist / "oembed" / name
    out.mkdir(parents=True, exist_ok=True)
    base = f"{args.site}oembed/{name}/"
    for panel, doc in docs.items():
        (out / f"{panel}.json").write_text(json.dumps(doc, ensure_ascii=False, indent=1) + "\n")
        (out / f"{panel}.html").write_text(
            oembed_page(args.site, panel, f"{base}{panel}.json", inp, doc["title"]))
        print(f"{base}{panel}.html")
    return 0
