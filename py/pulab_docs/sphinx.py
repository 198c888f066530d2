"""The Sphinx directive ``.. pu-lab::``: a live pu-lab panel with its numbers in the static page.

In ``conf.py``::

    extensions = ["pulab_docs.sphinx"]
    pulab_site = "https://intranet/tools/pu-lab/"   # absolute, or root-relative ("/tools/pu-lab/")

In a page::

    .. pu-lab::
       :panel: vendor
       :lang: zh

       {"motor": {"rated_voltage_v": 380, "rated_current_a": 12.5, ...}, "drive": {...}}

A bad option or input stops the build with the field's name (an error at the directive's line).
"""

from __future__ import annotations

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.util.docutils import SphinxDirective

from pulab import __version__
from . import EmbedError, render

__all__ = ["PuLabDirective", "setup"]


class PuLabDirective(SphinxDirective):
    """``.. pu-lab::`` with ``:panel:``, ``:lang:``, ``:theme:`` and the input JSON as content."""

    has_content = True
    option_spec = {"panel": directives.unchanged_required, "lang": directives.unchanged,
                   "theme": directives.unchanged}

    def run(self):
        try:
            html = render(dict(self.options), "\n".join(self.content), self.config.pulab_site)
        except EmbedError as e:
            raise self.error(str(e)) from None
        return [nodes.raw("", html, format="html")]


def setup(app):
    app.add_config_value("pulab_site", None, "html", str)
    app.add_directive("pu-lab", PuLabDirective)
    return {"version": __version__, "parallel_read_safe": True, "parallel_write_safe": True}
