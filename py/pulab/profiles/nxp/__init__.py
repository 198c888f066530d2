"""NXP MCAT / RTCESL: fractions of U_max and I_max, ACC32 and FRAC16 + shift."""

from .decode import decode_header
from .induction import acim
from .header import header
from .observer import observer
from .pi import controller
from .scaling import *  # noqa: F403 (OPTIONS, bases, …: see its __all__)
from .appconfig import profile  # scaling.profile and, with MCAT's inputs, its whole header

NAME = "nxp"
NAMES = ("NXP", "NXP")
HEADER_FILE = "m1_pmsm_appconfig_pulab.h"
