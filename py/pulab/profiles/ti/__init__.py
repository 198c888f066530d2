"""TI MotorWare / InstaSPIN: per unit of the hardware full scale, IQ24."""

from .decode import decode_header
from .header import header
from .induction import acim
from .observer import observer
from .pi import controller
from .scaling import *  # noqa: F403 (OPTIONS, bases, profile, …: see its __all__)

NAME = "ti"
NAMES = ("TI", "TI")
HEADER_FILE = "user_mtr1_pulab.h"
