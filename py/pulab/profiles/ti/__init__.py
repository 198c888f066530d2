"""TI MotorWare / InstaSPIN: per unit of the hardware full scale, IQ24.

One vendor of :mod:`pulab.profiles.registry`, with the members of
:class:`pulab.profiles.vendor.Vendor`: the scaling is :mod:`.scaling`, the header
:mod:`.header`, the integer current PI of its simulation :mod:`.pi`.
"""

from __future__ import annotations

from .header import header
from .pi import controller
from .scaling import (CONVENTIONS, CONVENTIONS_ZH, FILES, OPTIONS, bases, constants, gain_fields,
                      gain_range, gains_to_ints, ints_to_gains, profile, warnings)

__all__ = ["NAME", "NAMES", "HEADER_FILE", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "OPTIONS",
           "bases", "constants", "gain_fields", "gain_range", "gains_to_ints", "ints_to_gains",
           "profile", "header", "controller", "warnings"]

NAME = "ti"
NAMES = ("TI", "TI")
HEADER_FILE = "user_mtr1_pulab.h"
