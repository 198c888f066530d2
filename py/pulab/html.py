"""A report as HTML: readable tables for a notebook, and the numbers of one embedded panel.

:class:`Report` is the report dict of :func:`pulab.report` that a Jupyter notebook shows as
tables (``_repr_html_``).  :func:`panel_html` is what the docs integrations (:mod:`pulab_docs`:
the Sphinx directive, the MkDocs plugin) write into a static page: a ``<pu-lab-panel>`` element
that goes live in the browser, holding the panel's numbers computed here at docs build time, so
the page reads correctly with scripts off and in search indexes (docs/contract.md, "Embedding").
Every number carries ``data-key`` (its JSON path in the report) and ``data-value`` (full
precision), as on the site.

Examples
--------
>>> inp = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
...     "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
...     "drive": {"udc_v": 24, "ts_s": 1e-4}}
>>> '<td data-key="vendor.Rpm.value" data-value="15022">15022</td>' in panel_html("vendor", inp, site="/pu-lab/")
True
>>> "<table" in Report(inp)._repr_html_()
True
"""

from __future__ import annotations

import json
import re
from html import escape
from urllib.parse import quote

from .report import report

__all__ = ["PANELS", "Report", "report_html", "panel_html", "panel_tables", "oembed",
           "oembed_page", "OEMBED_HEIGHT"]

#: The panel ids of ``?embed=`` and ``<pu-lab-panel panel>`` (web/src/panels/registry.ts).
PANELS = ("review", "datasheet", "acim", "bases", "pu", "vendor", "constants", "current", "pll",
          "loop", "qcalc", "code", "conventions", "sweep", "prove", "batch", "vendors", "board", "fw",
          "observer", "audit", "docs")

_BASE_UNITS = {"U_b": "V", "I_b": "A", "f_b": "Hz", "w_b": "rad/s", "Z_b": "Ω", "L_b": "H",
               "psi_b": "Wb", "T_b": "s", "P_b": "W", "theta_b": "rad"}

_TITLES = {
    "review": ("Design review", "设计检查"), "base": ("Bases", "基值"),
    "pu": ("Per unit", "标幺值"), "raw": ("Raw firmware inputs", "固件原始输入"),
    "vendor": ("Vendor integers", "厂商整数"), "constants": ("Magic constants", "魔数常量"),
    "current_pi": ("Current PI", "电流环 PI"), "pll": ("PLL", "锁相环"),
    "mechanical": ("Mechanical", "机械量"), "warnings": ("Warnings", "警告"),
}
_HEAD = {"en": ("quantity", "value", "details"), "zh": ("量", "值", "说明")}
_WORDS = {("ideal", "en"): "ideal", ("ideal", "zh"): "理想值", ("err", "en"): "err",
          ("err", "zh"): "误差", ("exact", "en"): "exact", ("exact", "zh"): "精确值",
          ("rel", "en"): "rel. error", ("rel", "zh"): "相对误差",
          ("note", "en"): "note", ("note", "zh"): "提示", ("warning", "en"): "warning",
          ("warning", "zh"): "警告", ("error", "en"): "error", ("error", "zh"): "错误"}


def _num(x) -> str:
    return str(x) if isinstance(x, int) else f"{x:.6g}"


def _cell(key: str, value, text: str | None = None) -> tuple:
    """A number cell: its report path, full-precision value and shown text."""
    return (key, value, _num(value) if text is None else text)


def _rows_base(r, lang):
    return [(k, _cell(f"base.{k}", v), _BASE_UNITS[k]) for k, v in r["base"].items()]


def _rows_pu(r, lang):
    return [(k, _cell(f"pu.{k}", v), "") for k, v in r["pu"].items()]


def _rows_raw(r, lang):
    return [(k, _cell(f"vendor.raw.{k}", v), "") for k, v in r["vendor"]["raw"].items()]


def _rows_vendor(r, lang):
    rows = []
    for name, res in r["vendor"].items():
        if name == "raw":
            continue
        flags = " ".join(res["flags"])  # truncation, overflow, wrap: always shown
        ideal, err = _WORDS["ideal", lang], _WORDS["err", lang]
        rows.append((name, _cell(f"vendor.{name}.value", res["value"]),
                     f"{res['type']} Q{res['q']}, {ideal} {res['ideal']:.6g}, "
                     f"{err} {res['error_pct']:+.4f} %, = {res['si']:.6g} {res['unit']}"
                     + (f" [{flags}]" if flags else "")))
    return rows


def _rows_constants(r, lang):
    exact, rel = _WORDS["exact", lang], _WORDS["rel", lang]
    return [(k, _cell(f"constants.{k}.value", c["value"]),
             f"{exact} {c['exact']:.6f} = {c['expression']}, {rel} {100 * c['rel_error']:+.4f} %")
            for k, c in r["constants"].items()]


def _rows_current(r, lang):
    rows = []
    for axis in ("d", "q"):
        g = r["current_pi"][axis]
        for k, unit in (("kp", "Ω"), ("ki", "Ω/s"), ("kp_pu", ""), ("ki_pu", ""), ("pm_kp", ""),
                        ("pm_ki", "")):
            rows.append((f"{axis}.{k}", _cell(f"current_pi.{axis}.{k}", g[k]), unit))
    return rows


def _rows_pll(r, lang):
    return [(k, _cell(f"pll.{k}", r["pll"][k]), "")
            for k in ("kp", "ki", "kp_pu", "ki_pu", "integrator_gain")]


def _rows_mechanical(r, lang):
    units = {"rated_speed_rpm": "rpm", "base_speed_rpm": "rpm", "torque_base_nm": "N·m",
             "kt_nm_per_a": "N·m/A (RMS)", "ke_v_s_per_rad": "V·s/rad (line RMS)",
             "rated_torque_nm": "N·m"}
    return [(k, _cell(f"mechanical.{k}", r["mechanical"][k]), u) for k, u in units.items()]


def _rows_review(r, lang):
    msg = "message_zh" if lang == "zh" else "message"
    return [(_WORDS[x["severity"], lang], _cell(x["key"], x["value"]), x[msg])
            for x in r["review"]["findings"] if x.get("value") is not None]


#: The report sections each panel shows; panels without one (the Q calculator, the code
#: tracer, the chapters…) have no numbers of the report to prerender.
_PANEL_SECTIONS = {
    "review": ("review",), "bases": ("base",), "pu": ("pu",), "vendor": ("raw", "vendor"),
    "constants": ("constants",), "current": ("current_pi",), "pll": ("pll",),
}
_ROWS = {"review": _rows_review, "base": _rows_base, "pu": _rows_pu, "raw": _rows_raw, "vendor": _rows_vendor,
         "constants": _rows_constants, "current_pi": _rows_current, "pll": _rows_pll,
         "mechanical": _rows_mechanical}


def _section(name: str, r: dict, lang: str) -> str:
    rows = _ROWS[name](r, lang)
    title = _TITLES[name][lang == "zh"]
    head = "".join(f"<th>{h}</th>" for h in _HEAD[lang])
    body = "".join(
        f'<tr><th scope="row">{escape(label)}</th><td data-key="{escape(key)}" '
        f'data-value="{escape(repr(value))}">{escape(text)}</td><td>{escape(extra)}</td></tr>'
        for label, (key, value, text), extra in rows)
    return (f'<table class="pu-lab-table"><caption>{escape(title)}</caption>'
            f"<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>")


def panel_tables(panel: str, r: dict, lang: str = "en") -> str:
    """The numbers of one panel as HTML tables ("" for a panel without report numbers).

    Parameters
    ----------
    panel : str
        A panel id of :data:`PANELS`.
    r : dict
        A report of :func:`pulab.report`.
    lang : {"en", "zh"}
    """
    return "".join(_section(s, r, lang) for s in _PANEL_SECTIONS.get(panel, ()))


def report_html(r: dict, lang: str = "en") -> str:
    """A whole report as HTML tables: bases, per unit, vendor integers, gains, review, warnings.

    Parameters
    ----------
    r : dict
        A report of :func:`pulab.report`.
    lang : {"en", "zh"}
        Language of titles, review findings and warnings.
    """
    parts = [_section(s, r, lang) for s in ("base", "pu", "raw", "vendor", "current_pi", "pll",
                                            "mechanical", "constants")]
    findings = r["review"]["findings"]
    if findings:
        msg = "message_zh" if lang == "zh" else "message"
        parts.insert(0, f'<table class="pu-lab-table"><caption>{_TITLES["review"][lang == "zh"]}'
                        "</caption><tbody>" + "".join(
                            f'<tr><th scope="row">{_WORDS[x["severity"], lang]}</th>'
                            f"<td>{escape(x[msg])}</td></tr>" for x in findings)
                        + "</tbody></table>")
    warnings = r["warnings_zh" if lang == "zh" else "warnings"]
    reviewed = {x["message_zh" if lang == "zh" else "message"] for x in findings}
    other = [w for w in warnings if w not in reviewed]
    if other:
        parts.append(f"<p><strong>{_TITLES['warnings'][lang == 'zh']}</strong></p><ul>"
                     + "".join(f"<li>{escape(w)}</li>" for w in other) + "</ul>")
    return '<div class="pu-lab-report">' + "".join(parts) + "</div>"


class Report(dict):
    """The report of one motor and drive (the dict of :func:`pulab.report`) that a notebook
    shows as readable tables.

    Parameters
    ----------
    inp : dict
        Input per docs/contract.md.
    lang : {"en", "zh"}, optional
        Language of the tables' titles and findings.

    Raises
    ------
    pulab.InputError
        Naming the field, as :func:`pulab.report`.
    """

    def __init__(self, inp: dict, lang: str = "en"):
        if lang not in ("en", "zh"):
            raise ValueError(f"lang: {lang!r} is not 'en' or 'zh'")
        super().__init__(report(inp))
        self.lang = lang

    def _repr_html_(self) -> str:
        return report_html(self, self.lang)


def panel_html(panel: str, inp: dict | None, *, site: str, lang: str | None = None,
               theme: str | None = None) -> str:
    """A ``<pu-lab-panel>`` with its numbers prerendered inside, and the ``embed.js`` tag.

    The element shows the prerendered tables until its live frame has painted (docs/contract.md,
    "Embedding"); with scripts off, or to a search engine, the tables are the panel.

    Parameters
    ----------
    panel : str
        A panel id of :data:`PANELS`.
    inp : dict or None
        The input (docs/contract.md); None: the seed's example motor.
    site : str
        The URL of the pu-lab site (its directory, ending in ``/``), absolute or relative to the
        docs page.
    lang : {"en", "zh"} or None
        The panel's language; None: the reader's browser language (tables in English).
    theme : {"light", "dark"} or None
        None: follow the host page's scheme.

    Raises
    ------
    ValueError
        For an unknown panel, language, theme or a site not ending in ``/`` (message starts with
        the option's name).
    pulab.InputError
        For a bad input, naming the field.
    """
    if panel not in PANELS:
        raise ValueError(f"panel: {panel!r} is not a pu-lab panel ({', '.join(PANELS)})")
    if lang not in (None, "en", "zh"):
        raise ValueError(f"lang: {lang!r} is not 'en' or 'zh'")
    if theme not in (None, "light", "dark"):
        raise ValueError(f"theme: {theme!r} is not 'light' or 'dark'")
    if not site.endswith("/"):
        raise ValueError(f"site: {site!r} must be the site's directory, ending in '/'")
    attrs = {"panel": panel, "lang": lang, "theme": theme,
             "input": None if inp is None else json.dumps(inp, ensure_ascii=False)}
    attr_text = "".join(f' {k}="{escape(v)}"' for k, v in attrs.items() if v is not None)
    tables = ""
    if panel in _PANEL_SECTIONS:
        if inp is None:
            from .analyses.sim.bench import SEED_INPUT as inp  # what the element shows then
        tables = panel_tables(panel, report(inp), lang or "en")
    link = (f'<p class="pu-lab-link"><a href="{escape(site)}?embed={escape(panel)}">'
            f"pu-lab: {escape(panel)}</a></p>")
    return (f'<script src="{escape(site)}embed.js"></script>'
            f"<pu-lab-panel{attr_text}>{tables}{link}</pu-lab-panel>")


#: The height (CSS px) an oEmbed consumer gives the frame; the frame itself reports its real
#: height by postMessage (docs/contract.md, "Embedding") to consumers that listen.
OEMBED_HEIGHT = 640


def _frame_url(site: str, panel: str, inp: dict | None) -> str:
    url = f"{site}?embed={panel}"
    return url if inp is None else url + "#in=" + quote(json.dumps(inp, ensure_ascii=False),
                                                        safe="")


def _check_site(site: str) -> None:
    if not re.fullmatch(r"https?://[^/?#\s]+/([^?#\s]*/)?", site):
        raise ValueError(f"site: {site!r} must be the site's absolute URL, ending in '/'")


def oembed(site: str, panel: str, inp: dict | None = None, title: str | None = None) -> dict:
    """The oEmbed 1.0 response (type ``rich``) of one panel: an iframe of ``?embed=PANEL``.

    Parameters
    ----------
    site : str
        The pu-lab site's absolute URL, ending in ``/`` (the consumer inserts the HTML into
        another page).
    panel : str
        A panel id of :data:`PANELS`.
    inp : dict or None
        The input; None: the seed's example motor.
    title : str or None
        Shown by consumers; default ``pu-lab: PANEL``.

    Raises
    ------
    ValueError
        ``site: …`` or ``panel: …``.
    pulab.InputError
        For a bad input, naming the field.
    """
    _check_site(site)
    if panel not in PANELS:
        raise ValueError(f"panel: {panel!r} is not a pu-lab panel ({', '.join(PANELS)})")
    if inp is not None:
        report(inp)  # a bad input is refused here, naming its field, not shown in a frame later
    title = title or f"pu-lab: {panel}"
    frame = (f'<iframe src="{escape(_frame_url(site, panel, inp))}" width="100%" '
             f'height="{OEMBED_HEIGHT}" style="border:0" scrolling="no" '
             f'title="{escape(title)}"></iframe>')
    return {"version": "1.0", "type": "rich", "provider_name": "pu-lab", "provider_url": site,
            "title": title, "html": frame, "width": 900, "height": OEMBED_HEIGHT}


def oembed_page(site: str, panel: str, json_url: str, inp: dict | None = None,
                title: str | None = None) -> str:
    """The page a wiki is given the URL of: its oEmbed discovery link, and for a reader who
    opens it, a link (and a redirect) to the panel."""
    title = title or f"pu-lab: {panel}"
    target = escape(_frame_url(site, panel, inp))
    return ('<!doctype html><html><head><meta charset="utf-8">'
            f"<title>{escape(title)}</title>"
            f'<link rel="alternate" type="application/json+oembed" href="{escape(json_url)}" '
            f'title="{escape(title)}">'
            f'<meta http-equiv="refresh" content="0; url={target}"></head>'
            f'<body><p><a href="{target}">{escape(title)}</a></p></body></html>')
