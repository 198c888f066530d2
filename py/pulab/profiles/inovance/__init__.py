"""Inovance C2000 (the seed's code): per unit of the motor's rated values, Q12/Q16 integers.

One vendor of :mod:`pulab.profiles.registry`, with the members of
:class:`pulab.profiles.vendor.Vendor`.  The scaling is :mod:`.scaling` (a view of
:mod:`pulab.profiles.inovance_code`, the report's own integers), the header :mod:`.header`
(the report's); its simulation is the report's fixed-point variant
(:mod:`pulab.analyses.sim.current`), so it provides no ``controller`` here.
"""

from __future__ import annotations

from .header import header
from .scaling import (CONVENTIONS, CONVENTIONS_ZH, FILES, OPTIONS, bases, gain_fields, gain_range,
                      gains_to_ints, ints_to_gains, profile)

__all__ = ["NAME", "NAMES", "HEADER_FILE", "CONVENTIONS", "CONVENTIONS_ZH", "FILES", "OPTIONS",
           "bases", "gain_fields", "gain_range", "gains_to_ints", "ints_to_gains", "profile",
           "header"]

NAME = "inovance"
NAMES = ("Inovance", "汇川")
HEADER_FILE = "pulab_params.h"
