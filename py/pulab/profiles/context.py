"""Everything a vendor profile needs from the input and the report, in SI (``ctx``).

Examples
--------
>>> from pulab import report
>>> r = report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> ctx = context_of(r)
>>> ctx["udc"], round(ctx["i_fs"], 4)
(24.0, 4.2426)
"""

from __future__ import annotations

from ..model.bases import flux_linkage
from .common import SQRT2

__all__ = ["context", "context_of"]


def context(n: dict, raw: dict, vendor: dict, pi: dict, problems: list = (),
            board: dict | None = None) -> dict:
    """Everything a profile needs from the normalized input and the report, in SI.

    Parameters
    ----------
    n : dict
        The normalized input (:func:`pulab.schema.inputs.normalize`).
    raw, vendor : dict
        The Inovance raw integers and results (:mod:`pulab.profiles.inovance.code`).
    pi : dict
        The report's ``current_pi``; its SI kp [V/A], ki [V/(A·s)] per axis are the
        gains every profile stores (a V/A ratio is the same in peak and RMS).
    problems : list
        What the Inovance firmware cannot hold (``firmware.inovance.problems``).
    board : dict, optional
        The report's ``board`` (:func:`pulab.model.board.board`): each vendor reads its
        hardware scales from it by its own convention; ``board_input`` is the normalized
        ``board`` input (ADC reference, bits) beside it.
    """
    m, d = n["motor"], n["drive"]
    return {"rs": m["rs_ohm"], "ld": m["ld_h"], "lq": m["lq_h"], "pp": m["pole_pairs"],
            "i_rated": m["rated_current_a"], "u_rated": m["rated_voltage_v"],
            "f_rated": m["rated_freq_hz"], "bemf_v": m["bemf_v"], "f_base": d["base_freq_hz"],
            "udc": d["udc_v"], "ts": d["ts_s"], "i_fs": 2.0 * SQRT2 * m["rated_current_a"],
            "psi_peak": flux_linkage("peak", m["bemf_v"], m["rated_freq_hz"]),
            "psi_rms": flux_linkage("rms", m["bemf_v"], m["rated_freq_hz"]),
            "u_limit": d["udc_v"] / SQRT2,
            "gains": {a: (pi[a]["kp"], pi[a]["ki"]) for a in ("d", "q")},
            "vendor": vendor, "raw": raw, "inductance_unit": n["conventions"]["inductance_unit"],
            "firmware_problems": list(problems), "board": board, "board_input": n.get("board"),
            # the sensorless settings (pulab.model.observer), None when not asked
            "observer": n.get("observer")}


def context_of(r: dict) -> dict:
    """:func:`context` rebuilt from a finished report (which carries every piece of it)."""
    return context(r["input"], r["vendor"]["raw"],
                   {k: v for k, v in r["vendor"].items() if k != "raw"}, r["current_pi"],
                   r["firmware"]["inovance"]["problems"], r.get("board"))
