"""Inovance C2000 (the seed's code): per unit of the motor's rated values, Q12/Q16 integers.

Its scaling is a view of :mod:`pulab.profiles.inovance.code` (the report's own integers) and its
header the report's; its simulation is the report's fixed-point variant
(:mod:`pulab.analyses.sim.current`), so it provides no ``controller``.
"""

from .decode import decode_header
from .header import header
from .scaling import *  # noqa: F403 (OPTIONS, bases, profile, …: see its __all__)

NAME = "inovance"
NAMES = ("Inovance", "汇川")
HEADER_FILE = "pulab_params.h"
