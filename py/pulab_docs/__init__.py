"""pu-lab panels in documentation builds: the optional extras of the pulab package.

``pip install 'pulab[docs]'`` brings the tools these adapters plug into; :mod:`pulab` itself never
imports them (it stays standard-library only, for a bare Pyodide).

- :mod:`pulab_docs.sphinx` — the Sphinx directive ``.. pu-lab::`` (``extensions = ["pulab_docs.sphinx"]``);
- :mod:`pulab_docs.mkdocs` — the MkDocs plugin ``pu-lab`` for ```` ```pu-lab ```` fences;
- :mod:`pulab_docs.widget` — ``PanelWidget``, a live panel in a Jupyter notebook (``pulab[jupyter]``).

Each writes :func:`pulab.html.panel_html`: the ``<pu-lab-panel>`` element with the panel's numbers
computed at docs build time inside it (docs/contract.md, "Embedding").
"""

from __future__ import annotations

from pulab import InputError
from pulab.html import panel_html
from pulab.schema.jsontext import parse

__all__ = ["EmbedError", "render"]


class EmbedError(ValueError):
    """A panel that cannot be rendered; the message is one line naming the option or input field."""


def render(options: dict, body: str, site: str | None) -> str:
    """The HTML of one panel from a directive's or fence's options and body.

    Parameters
    ----------
    options : dict
        ``panel`` (default ``bases``), ``lang`` and ``theme`` (optional), as text.
    body : str
        The input as JSON text (docs/contract.md); blank: the seed's example motor.
    site : str or None
        The pu-lab site's URL (its directory, ending in ``/``), from the docs tool's configuration.

    Raises
    ------
    EmbedError
        ``pu-lab: FIELD: message`` for an unknown option, a bad option value, a missing site or a bad
        input (the input field's JSON path, e.g. ``motor.rated_voltage_v``).
    """
    unknown = sorted(set(options) - {"panel", "lang", "theme"})
    if unknown:
        raise EmbedError(f"pu-lab: {unknown[0]}: unknown option (panel, lang, theme)")
    if not site:
        raise EmbedError("pu-lab: site: the pu-lab site's URL is not configured")
    try:
        inp = parse(body) if body.strip() else None
        return panel_html(options.get("panel") or "bases", inp, site=site,
                          lang=options.get("lang") or None, theme=options.get("theme") or None)
    except InputError as e:
        raise EmbedError(f"pu-lab: {e.field}: {e.message}") from None
    except ValueError as e:
        raise EmbedError(f"pu-lab: {e}") from None
