import copy
import json
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# The seed's worked example motor (seed 1.4-1 … 1.4-7: Rs 1.5 Ω, Un 17 V, In 1.5 A, fn 220 Hz,
# Ld 600 µH); bemf, pole pairs, Udc and Ts are plausible choices of ours.
SEED_INPUT = {
    "motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
              "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
    "drive": {"udc_v": 24, "ts_s": 1e-4},
}


@pytest.fixture
def seed_input():
    return copy.deepcopy(SEED_INPUT)


def chinese(text) -> bool:
    """True when ``text`` (a ``message_zh``, ``warnings_zh`` entry …) has Chinese characters."""
    return isinstance(text, str) and any("\u4e00" <= ch <= "\u9fff" for ch in text)
