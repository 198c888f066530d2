"""The one list of vendors: every profile, header, translation, simulation and input choice
reads the vendors from here.

A vendor is a package with the members of :class:`pulab.profiles.vendor.Vendor`;
:func:`register` checks them and makes the vendor known to the input (its name as a choice
of ``conventions.firmware``, its display name and its option fields:
:mod:`pulab.schema.vendors`).  Adding a vendor is its package and one line below
(docs/design.md, "Adding a vendor").

Examples
--------
>>> names()
('inovance', 'ti', 'nxp', 'st', 'microchip')
>>> get("nxp").HEADER_FILE
'm1_pmsm_appconfig_pulab.h'
"""

from __future__ import annotations

from ..schema import vendors as _schema
from ..schema.errors import InputError
from ..schema.validate import shown
from . import inovance, microchip, nxp, st, ti
from .vendor import Vendor

__all__ = ["VENDORS", "register", "unregister", "names", "get", "vendors"]

#: Every vendor by name, in order (read it; :func:`register` and :func:`unregister` change it).
VENDORS: dict = {}
#: The members :func:`register` checks: those :class:`.vendor.Vendor` declares (the optional
#: ones are :data:`.vendor.OPTIONAL`).
_REQUIRED = tuple(Vendor.__annotations__) + tuple(
    n for n, member in vars(Vendor).items() if callable(member) and not n.startswith("_"))


def register(vendor: Vendor) -> Vendor:
    """Add ``vendor`` (after those registered before it: the report's and the translator's
    order) and make it known to the input.

    Raises
    ------
    TypeError
        When a member of :class:`pulab.profiles.vendor.Vendor` is missing.
    """
    missing = [m for m in _REQUIRED if not hasattr(vendor, m)]
    if missing:
        raise TypeError(f"vendor {getattr(vendor, 'NAME', vendor)!r} lacks {', '.join(missing)}")
    VENDORS[vendor.NAME] = vendor
    _schema.register(vendor.NAME, vendor.NAMES, tuple(o.field(vendor.NAME) for o in vendor.OPTIONS),
                     {a: vendor.gain_fields(a) for a in ("d", "q")}, vendor.HEADER_FILE)
    return vendor


def unregister(name: str) -> None:
    """Remove vendor ``name`` (a test's temporary vendor)."""
    del VENDORS[name]
    _schema.unregister(name)


def names() -> tuple:
    """Every vendor's name, in order."""
    return tuple(VENDORS)


def vendors() -> tuple:
    """Every vendor, in order."""
    return tuple(VENDORS.values())


def get(name, field: str = "profile") -> Vendor:
    """Vendor ``name``.

    Raises
    ------
    InputError
        ``not_choice`` at ``field`` for a name that is no vendor.
    """
    if not isinstance(name, str) or name not in VENDORS:
        raise InputError(field, code="not_choice", choices=", ".join(VENDORS), got=shown(name))
    return VENDORS[name]


# One line per vendor, in the order the report lists them.
register(inovance)
register(ti)
register(nxp)
register(st)
register(microchip)
