"""What a vendor provides: the one interface every firmware profile implements.

A vendor is a package ``pulab/profiles/NAME/`` whose ``__init__`` exposes the members of
:class:`Vendor` (its modules hold the code: scaling, header, integer PI …), listed once in
:mod:`pulab.profiles.registry`.  Everything else reads the vendors through the registry:
the input's choices and option fields (:mod:`pulab.schema.vendors`), the report's
``profiles``, the headers, the translator, the review's findings and the fixed-point
simulations (docs/design.md, "Adding a vendor").

The members in :data:`OPTIONAL` may be left out; :func:`provided` gives None for them then,
and the caller skips the vendor (its simulation, its warnings, …) rather than pretend.

Examples
--------
>>> from pulab.profiles import registry
>>> ti = registry.get("ti")
>>> ti.NAMES, ti.gain_fields("q"), provided(registry.get("inovance"), "observer")
(('TI', 'TI'), ('Kp_Iq', 'Ki_Iq'), None)
>>> f = ti.OPTIONS[4].field("ti")
>>> f.path, f.kind, f.lo, f.hi
('profiles.ti.global_q', 'integer', 1, 30)
"""

from __future__ import annotations

from typing import Callable, NamedTuple, Protocol

from ..schema.fields import Field

__all__ = ["Option", "Vendor", "OPTIONAL", "provided"]

#: The unit an option's name ends in (``_v`` volts …), shown beside it on the vendors panel.
_UNITS = (("_v", "V"), ("_a", "A"), ("_hz", "Hz"), ("_ohm", "Ω"))


class Option(NamedTuple):
    """One hardware input of a vendor (``profiles.NAME.KEY``).

    Attributes
    ----------
    key : str
        Its name in the input.
    default : callable
        ``default(ctx)``: its value for this motor and drive when the input does not give it
        (``ctx``: :func:`pulab.profiles.context.context`); None means the vendor's code picks.
    meaning : str
        What it is in the vendor's code, and where its default comes from.
    label : (str, str)
        Its form label, English and Chinese (the vendor's name is prefixed when registered).
    kind : {'number', 'integer', 'flag'}
        A number is > 0 in the input's plausibility range 1e-9..1e9; an integer lies in
        ``lo..hi`` and, with ``power_of_two``, is a power of two.
    """

    key: str
    default: Callable[[dict], object]
    meaning: str
    label: tuple
    kind: str = "number"
    lo: int | None = None
    hi: int | None = None
    power_of_two: bool = False

    def field(self, vendor: str) -> Field:
        """The input field of this option for vendor ``vendor`` (what the schema registers)."""
        unit = next((u for end, u in _UNITS if self.key.endswith(end)), "")
        path = f"profiles.{vendor}.{self.key}"
        if self.kind == "number":
            return Field(path, "number", unit, sign=">0", lo=1e-9, hi=1e9, label=self.label)
        return Field(path, self.kind, unit, lo=self.lo, hi=self.hi, label=self.label)


class Vendor(Protocol):
    """The members of a vendor package (each a module-level name of its ``__init__``).

    Attributes
    ----------
    NAME : str
        Its key: ``profiles.NAME``, ``conventions.firmware``, ``--profile``.
    NAMES : (str, str)
        How texts name it, English and Chinese (``{"vendor": NAME}`` in a message).
    OPTIONS : tuple of :class:`Option`
        Its hardware inputs (empty when its scaling follows the motor alone).
    CONVENTIONS, CONVENTIONS_ZH : dict
        Its base choices in words (``voltage_base``, ``current_base``, ``line_or_phase``,
        ``rms_or_peak``, ``clarke_k``, ``inductance_base``, ``pi_form``, ``rounding``).
    FILES : dict
        The public files its rounding rule and worked numbers were read in
        (:data:`pulab.profiles.common.SOURCES`).
    HEADER_FILE : str
        The name its header is saved under.

    Methods
    -------
    bases(ctx, opt) -> (U_b, I_b, L_b or None)
        Its voltage, current and inductance bases in SI.
    profile(ctx, opt) -> dict
        ``inputs`` (the options used) and ``constants`` (:func:`pulab.profiles.common.fixed`
        records), and whatever else it reports; ``problems``, when given, are the limit
        entries (:mod:`pulab.profiles.limits`) of what its code cannot compute for this motor,
        moved to ``firmware.NAME``.
    gain_fields(axis) -> (str, str)
        The names of its current-loop kp and ki integers on axis ``'d'`` or ``'q'``.
    gain_range(axis) -> (int, int)
        The range of those integers (their C type).
    gains_to_ints(kp, ki, ctx, opt, axis) -> dict
        Its two integers, as constant records, for SI kp [V/A], ki [V/(A·s)].
    ints_to_gains(kp_int, ki_int, ctx, opt, axis) -> (float, float)
        The inverse: the SI kp, ki two stored integers stand for.
    header(p, ctx, r) -> str
        Its C header: ``p`` its profile in the report ``r`` (computed with a ``profiles``
        section), ``ctx`` the SI context; a vendor whose header is the report's own (Inovance)
        reads ``r``.
    """

    NAME: str
    NAMES: tuple
    OPTIONS: tuple
    CONVENTIONS: dict
    CONVENTIONS_ZH: dict
    FILES: dict
    HEADER_FILE: str

    def bases(self, ctx: dict, opt: dict) -> tuple: ...

    def profile(self, ctx: dict, opt: dict) -> dict: ...

    def gain_fields(self, axis: str) -> tuple: ...

    def gain_range(self, axis: str) -> tuple: ...

    def gains_to_ints(self, kp: float, ki: float, ctx: dict, opt: dict, axis: str) -> dict: ...

    def ints_to_gains(self, kp_int: int, ki_int: int, ctx: dict, opt: dict,
                      axis: str) -> tuple: ...

    def header(self, p: dict, ctx: dict, r: dict) -> str: ...


#: Members a vendor may leave out, and what each gives when provided.
OPTIONAL = {
    "constants": "constants(ctx, opt) -> dict: the integers of ``profile`` alone, for inputs "
                 "that may be intervals (a family proof over a box)",
    "controller": "controller(p, umax_peak, udc) -> dict: its integer current PI, bound to its "
                  "profile ``p``, for the fixed-point simulation "
                  "(:func:`pulab.analyses.sim.vendor_loop.controllers` says the keys)",
    "warnings": "warnings(p) -> list: its own warnings about its profile ``p`` in the report, "
                "as (catalog code, params) pairs",
    "decode_header": "decode_header(values, notes) -> dict: its generated header read back "
                     "(:mod:`pulab.profiles.decoding`): ``values`` the folded macros (name → "
                     "int or float as its compiler computes them), ``notes`` the comment on each "
                     "``#define`` line (name → text; key ``''``: every block comment); returns "
                     "``reads`` (the names it knows), ``target`` (its compiler's widths), "
                     "``macros`` (SI, unit, meaning, formula), ``design`` and ``checks``",
    "board_constants": "board_constants(ctx, opt) -> dict: the macros its header holds for "
                       "the board (``ctx['board']``, by its own names); its ``profile`` merges "
                       "them into the constants and lists their names in ``profile['board']``. "
                       "Its options read their defaults from the board (``common.board_value``)",
    "observer": "observer(ctx, opt) -> dict: its sensorless constants (constant records, added "
                "to its profile's) for the settings ``ctx['observer']`` "
                "(:func:`pulab.model.observer.settings`; None when the input has no ``observer``)",
    "acim": "acim(a, n) -> dict: its induction-motor constants from the report's ``acim`` "
            "section ``a`` and the normalized input ``n``: ``constants`` (records as "
            "``profile``'s; :func:`pulab.profiles.common.real` where it stores floats), "
            "``not_covered`` (its ACIM constants not computed here, and why)",
}


def provided(vendor: Vendor, member: str):
    """The optional ``member`` of ``vendor`` (:data:`OPTIONAL`), or None when not provided."""
    if member not in OPTIONAL:
        raise KeyError(f"{member} is not an optional member of a vendor")
    return getattr(vendor, member, None)
