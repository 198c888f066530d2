"""Microchip MCAF / motorBench: Q15 fractions of V_b, I_b, ω_b, and two L bases."""

from .decode import decode_header
from .header import header
from .observer import observer
from .pi import controller
from .scaling import *  # noqa: F403 (OPTIONS, bases, profile, …: see its __all__)

NAME = "microchip"
NAMES = ("Microchip", "Microchip")
HEADER_FILE = "mcaf_params_pulab.h"
