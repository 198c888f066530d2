"""ST MCSDK: ADC/PWM "digit" units, int16 gains over power-of-two divisors."""

from .decode import decode_header
from .induction import acim
from .header import header
from .observer import observer
from .pi import controller
from .scaling import *  # noqa: F403 (OPTIONS, bases, profile, …: see its __all__)

NAME = "st"
NAMES = ("ST", "ST")
HEADER_FILE = "drive_parameters_pulab.h"
