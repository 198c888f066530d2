"""``PanelWidget``: a live pu-lab panel in a Jupyter notebook (``pip install 'pulab[jupyter]'``).

The widget loads ``embed.js`` from the pu-lab site as a classic script (so the notebook must reach
that site; no CORS header is needed) and shows one ``<pu-lab-panel>``; every report the panel
shows comes back to Python in ``report``.
For tables that need no site and no widget, :class:`pulab.html.Report` renders in any notebook.

Examples
--------
::

    from pulab_docs.widget import PanelWidget
    w = PanelWidget(site="https://intranet/tools/pu-lab/", panel="vendor",
                    input={"motor": {...}, "drive": {...}})
    w            # the live panel
    w.report     # after it went live: the report the panel shows (w.numbers == "live")
"""

from __future__ import annotations

import pathlib

import anywidget
import traitlets

from pulab.html import PANELS

__all__ = ["PanelWidget"]


class PanelWidget(anywidget.AnyWidget):
    """One live pu-lab panel.

    Parameters
    ----------
    site : str
        The pu-lab site's URL (its directory, ending in ``/``).
    panel : str
        A panel id of :data:`pulab.html.PANELS`; default ``bases``.
    input : dict, optional
        The input (docs/contract.md); empty: the seed's example motor.
    lang : {"", "en", "zh"}
        "": the browser's language.
    """

    _esm = pathlib.Path(__file__).with_name("widget.js")
    site = traitlets.Unicode().tag(sync=True)
    panel = traitlets.Enum(PANELS, default_value="bases").tag(sync=True)
    input = traitlets.Dict().tag(sync=True)
    lang = traitlets.Enum(("", "en", "zh"), default_value="").tag(sync=True)
    #: Set by the browser: the last report the panel showed and how it got it
    #: (``build``, ``cached``, ``live``; docs/contract.md, "Embedding").
    report = traitlets.Dict(read_only=True).tag(sync=True)
    numbers = traitlets.Unicode(read_only=True).tag(sync=True)

    @traitlets.validate("site")
    def _site(self, proposal):
        if not proposal["value"].endswith("/"):
            raise traitlets.TraitError("site: the pu-lab site's directory, ending in '/'")
        return proposal["value"]
