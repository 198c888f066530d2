"""The MkDocs plugin ``pu-lab``: ```` ```pu-lab ```` fences become live panels with their numbers
in the static page.

In ``mkdocs.yml``::

    plugins:
      - pu-lab:
          site: https://intranet/tools/pu-lab/   # absolute, or root-relative (/tools/pu-lab/)

In a page (options after the fence's name; the body is the input JSON, blank for the seed motor)::

    ```pu-lab panel=vendor lang=zh
    {"motor": {"rated_voltage_v": 380, ...}, "drive": {...}}
    ```

A bad option or input stops the build with the page and the field's name.
"""

from __future__ import annotations

import re

from mkdocs.config import config_options
from mkdocs.exceptions import PluginError
from mkdocs.plugins import BasePlugin

from . import EmbedError, render

__all__ = ["PuLabPlugin", "FENCE"]

#: A fence of backticks or tildes named ``pu-lab`` at the start of a line, up to its closing fence.
FENCE = re.compile(r"^(?P<fence>`{3,}|~{3,})[ \t]*pu-lab(?P<opts>[^\n`]*)\n(?P<body>.*?)^(?P=fence)[ \t]*$",
                   re.M | re.S)


def _options(text: str) -> dict:
    opts = {}
    for word in text.split():
        key, eq, value = word.partition("=")
        if not eq:
            raise EmbedError(f"pu-lab: {key}: options are written name=value")
        opts[key] = value.strip("\"'")
    return opts


class PuLabPlugin(BasePlugin):
    config_scheme = (("site", config_options.Type(str, default="")),)

    def on_page_markdown(self, markdown, page, config, files):
        def panel(m):
            try:
                html = render(_options(m["opts"]), m["body"], self.config["site"])
            except EmbedError as e:
                raise PluginError(f"{page.file.src_path}: {e}") from None
            # One block of raw HTML (no blank line inside), which Markdown passes through as is.
            return '<div class="pu-lab-embed">' + html.replace("\n", " ") + "</div>"
        return FENCE.sub(panel, markdown)
