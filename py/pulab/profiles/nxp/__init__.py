"""NXP MCAT / RTCESL: fractions of U_max and I_max, ACC32 and FRAC16 + shift.

One vendor of :mod:`pulab.profiles.registry`, with the members of
:class:`pulab.profiles.vendor.Vendor`: the scaling is :mod:`.scaling`, the header
:mod:`.header`, the integer current PI of its simulation :mod:`.pi`.
"""

from __future__ import annotations

from .header import header
from .pi import controller
from .scaling import (CONVENTIONS, CONVENTIONS_ZH, FILES, OPTIONS, bases, constants, gain_fields,
                      gain_range, gains_to_ints, ints_to_gains, profile)

__all__ = ["NAME", "NAMES", "HEADER_FILE", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "OPTIONS",
           "bases", "constants", "gain_fields", "gain_range", "gains_to_ints", "ints_to_gains",
           "profile", "header", "controller"]

NAME = "nxp"
NAMES = ("NXP", "NXP")
HEADER_FILE = "m1_pmsm_appconfig_pulab.h"
