"""The firmware vendors as the input sees them: names, display names and option fields.

The schema lies below the vendor profiles, so it does not import them: each vendor is
registered here by the one registry of vendors (:mod:`pulab.profiles.registry`) when that
loads, with its name, its display name (en, zh), the fields of its options
(``profiles.NAME.KEY``, labelled with the vendor's name first), the names of its current-loop
integers (``translate.values``) and its header's file name.  ``conventions.firmware`` offers
:data:`NAMES`, error texts name a vendor and its options from here (:mod:`.catalog`), and
``schema.json`` lists the vendors and their options for the page (:func:`page`).

Examples
--------
>>> from pulab.schema.fields import Field
>>> register("acme", ("Acme", "艾克米"), (Field("profiles.acme.gain", "number",
...     label=("gain", "增益")),), {"d": ("KP", "KI"), "q": ("KP", "KI")}, "acme.h")
>>> "acme" in NAMES, display("acme", "zh"), option_field("profiles.acme.gain").label
(True, '艾克米', ('Acme · gain', '艾克米 · 增益'))
>>> unregister("acme"); "acme" in NAMES
False
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["NAMES", "register", "unregister", "display", "option_field", "option_fields", "page"]

#: name → (display name (en, zh), option fields, gain fields, header file), in order.
_VENDORS: dict = {}


class _Names(Sequence):
    """The registered vendors' names, in order, as they are now (a live view: the choices of
    ``conventions.firmware`` follow registration)."""

    def __getitem__(self, i):
        return tuple(_VENDORS)[i]

    def __len__(self) -> int:
        return len(_VENDORS)

    def __repr__(self) -> str:
        return repr(tuple(_VENDORS))


#: Every registered vendor's name.
NAMES = _Names()


def register(name: str, names: tuple, options: tuple, gain_fields: dict,
             header_file: str) -> None:
    """Make vendor ``name`` known to the input.

    Parameters
    ----------
    name : str
        The key of the vendor (``profiles.NAME``, ``conventions.firmware``).
    names : (str, str)
        How a text names the vendor, in English and Chinese.
    options : tuple of :class:`pulab.schema.fields.Field`
        Its options, paths ``profiles.NAME.KEY``, labels without the vendor's name (it is
        prefixed here: the vendors panel and the messages show ``TI · GLOBAL_Q``).
    gain_fields : dict
        Axis ``'d'``/``'q'`` → the names of its current-loop kp and ki integers.
    header_file : str
        The name its header is saved under.
    """
    labelled = tuple(f._replace(label=tuple(f"{v} · {w}" for v, w in zip(names, f.label)))
                     for f in options)
    _VENDORS[name] = (tuple(names), labelled, gain_fields, header_file)


def unregister(name: str) -> None:
    """Forget vendor ``name`` (a test's temporary vendor)."""
    del _VENDORS[name]


def display(name: str, lang: str) -> str | None:
    """The vendor's name in ``lang`` (``'en'`` or ``'zh'``); None for an unknown vendor."""
    entry = _VENDORS.get(name)
    return entry[0][0 if lang == "en" else 1] if entry else None


def option_fields() -> list:
    """Every registered vendor's option fields, vendor by vendor."""
    return [f for entry in _VENDORS.values() for f in entry[1]]


def option_field(path: str):
    """The option field at ``path`` (``profiles.NAME.KEY``), or None."""
    parts = path.split(".")
    if len(parts) != 3 or parts[0] != "profiles" or parts[1] not in _VENDORS:
        return None
    return next((f for f in _VENDORS[parts[1]][1] if f.path == path), None)


def page() -> list:
    """The vendors as ``schema.json`` gives them to the page: ``name``, ``label`` (en, zh),
    ``gain_fields`` ({axis: [kp, ki]}) and ``header_file``, in order."""
    return [{"name": name, "label": list(names),
             "gain_fields": {a: list(g) for a, g in gains.items()}, "header_file": header}
            for name, (names, _, gains, header) in _VENDORS.items()]
