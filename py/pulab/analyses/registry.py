"""The report's optional sections (analyses), listed once: :data:`ANALYSES`.

Each :class:`Analysis` says which input path asks for it, when it runs relative to the others,
the functions that compute it (a :class:`Lazy` one imports its module on first use, so a plain
report never loads the loop or simulation code) and what it gives the review and the warnings.
:func:`pulab.report.report_steps` runs the asked ones in this order:

1. every ``check`` (the input checked before anything is computed: a bad ``sim`` is named
   before any firmware problem);
2. the report's core (bases, per-unit values, vendor integers, current PI);
3. every ``prepare`` of the ``"model"`` stage: what the vendor profiles read (the board's
   scales, the observer's settings), each seeing those before it;
4. the vendor profiles (:mod:`pulab.profiles`, not listed here: the shipped firmware's profile
   runs even when no profile is asked);
5. the ``"model"`` entries' sections (``run`` over the report so far, else what ``prepare``
   gave), then the profiles' section, then the ``"report"`` and ``"steps"`` entries in the
   tuple's order (a ``"steps"`` entry's ``run`` is a generator of slices,
   :mod:`pulab.analyses.slices`: the simulation, listed last);
6. the review, given each ``reviewed`` section under its key; the warnings, each entry's
   ``warnings`` after the profiles' own.

Adding an analysis is one entry here (docs/design.md, "Adding an analysis").

Examples
--------
>>> [a.key for a in ANALYSES]
['board', 'observer', 'loop', 'fw', 'sim']
>>> at({"analysis": {"fw": {}}}, "analysis.fw"), at({"analysis": None}, "analysis.fw")
({}, None)
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Callable, Literal, NamedTuple, Optional

from ..model.bases import flux_linkage
from ..model.board import board
from ..model.observer import settings

__all__ = ["Analysis", "Lazy", "ANALYSES", "Plan", "plan", "at", "put"]


@dataclass(frozen=True)
class Lazy:
    """A function ``name`` of module ``module`` (dotted, absolute), imported on its first call."""

    module: str
    name: str

    def __call__(self, *args):
        return getattr(importlib.import_module(self.module), self.name)(*args)


@dataclass(frozen=True)
class Analysis:
    """One optional section of the report.

    Attributes
    ----------
    key : str
        Its report key (``report[key]``), and its keyword of
        :func:`pulab.analyses.review.review` when ``reviewed``.
    asked : str
        The input path that asks for it (dotted): it runs when the value there is not None.
        A ``"report"`` or ``"steps"`` entry reads it in the report's input echo when that
        holds its top-level section (``analysis.fw`` once the loop's entry echoed ``analysis``
        checked), else in the normalized input.
    stage : str
        ``"model"`` (``prepare`` runs before the vendor profiles, the section is placed before
        theirs), ``"report"`` (after them) or ``"steps"`` (``run`` is a generator of slices;
        listed last). Entries of one stage run in the order of :data:`ANALYSES`.
    check : callable, optional
        ``check(given) -> checked``, run before anything is computed; ``prepare`` or ``run``
        get the checked value.
    prepare : callable, optional
        ``prepare(core, given) -> value``, required of a ``"model"`` entry (and only there):
        ``core`` holds ``input`` (the normalized input), ``base`` and the values prepared
        before it, under their keys.
    run : callable, optional
        ``run(report, value) -> section`` over the report so far; ``value`` is what
        ``prepare`` gave, else the (checked) input. Without it the section is ``prepare``'s.
    echo : callable, optional
        ``echo(given, value) -> input``: what the input holds at ``asked`` from then on — the
        normalized input's for a ``"model"`` entry (the profiles and the report's ``input``
        read it), else the report's ``input`` echo (default: the input as normalized; ``sim``
        and ``analysis`` are not echoed unless an entry does).
    warnings : callable, optional
        ``warnings(section) -> [(catalog code, params), ...]``, appended to the report's
        warnings.
    reviewed : bool
        Whether :func:`pulab.analyses.review.review` grades the section.
    """

    key: str
    asked: str
    stage: Literal["model", "report", "steps"] = "report"
    check: Optional[Callable] = None
    prepare: Optional[Callable] = None
    run: Optional[Callable] = None
    echo: Optional[Callable] = None
    warnings: Optional[Callable] = None
    reviewed: bool = False

    def __post_init__(self):
        # what report_steps calls at each stage must be there (an entry is checked once, here)
        if self.stage not in ("model", "report", "steps"):
            raise ValueError(f"analysis {self.key}: unknown stage {self.stage!r}")
        if (self.prepare is not None) != (self.stage == "model"):
            raise ValueError(f"analysis {self.key}: prepare belongs to (and only to) the "
                             "model stage")
        if self.run is None and self.stage != "model":
            raise ValueError(f"analysis {self.key}: a {self.stage} stage entry runs")


class Plan(NamedTuple):
    """A tuple of analyses split by what :func:`pulab.report.report_steps` does with each."""

    checked: tuple   # entries with a ``check``
    model: tuple     # ``"model"`` entries
    later: tuple     # ``"report"`` and ``"steps"`` entries, in order
    reviewed: tuple  # keys of the reviewed sections
    warned: tuple    # entries with ``warnings``


_LAST: list = [None, None]  # the last tuple planned and its plan: every report reads one


def plan(analyses: tuple) -> Plan:
    """The :class:`Plan` of ``analyses`` (kept for the last tuple asked: a report reads it
    once, so it costs a few attribute reads per entry once, not per report).

    Examples
    --------
    >>> p = plan(ANALYSES)
    >>> [a.key for a in p.model], [a.key for a in p.later], p.reviewed
    (['board', 'observer'], ['loop', 'fw', 'sim'], ('board', 'observer', 'loop', 'fw', 'sim'))
    """
    if _LAST[0] is not analyses:
        _LAST[:] = [analyses, Plan(tuple(a for a in analyses if a.check is not None),
                                   tuple(a for a in analyses if a.stage == "model"),
                                   tuple(a for a in analyses if a.stage != "model"),
                                   tuple(a.key for a in analyses if a.reviewed),
                                   tuple(a for a in analyses if a.warnings is not None))]
    return _LAST[1]


def at(tree: dict, path: str):
    """The value at dotted ``path`` of nested dicts, None where any step is missing."""
    if "." not in path:  # most entries: read on every report, so kept short
        return tree.get(path)
    for part in path.split("."):
        if not isinstance(tree, dict):
            return None
        tree = tree.get(part)
    return tree


def put(tree: dict, path: str, value) -> None:
    """Set dotted ``path`` of nested dicts (its parents exist) to ``value``."""
    *parents, last = path.split(".")
    for part in parents:
        tree = tree[part]
    tree[last] = value


def _board(core: dict, given: dict) -> dict:
    """The board's scales (:func:`pulab.model.board.board`); each vendor reads them."""
    m, d = core["input"]["motor"], core["input"]["drive"]
    return board(given, core["base"]["I_b"], flux_linkage("peak", m["bemf_v"], m["rated_freq_hz"]),
                 m["pole_pairs"], d["udc_v"])


def _observer(core: dict, given: dict) -> dict:
    """The observer's settings, derived defaults filled (:func:`pulab.model.observer.settings`);
    the vendors' observer integers read them."""
    n = core["input"]
    return settings(given, n["motor"], n["drive"], core.get("board"),
                    (n["analysis"] or {}).get("robust"))


def _given_keys(given: dict, value: dict) -> dict:
    """The input echo of a section whose derived defaults were filled: the given keys' values."""
    return {k: value[k] for k in given}


_LOOP = "pulab.analyses.loop"
_loop_input = Lazy(_LOOP, "validate")


def _analysis_echo(given: dict, loop: dict) -> dict:
    """The echo of ``analysis``: every default filled (:func:`pulab.analyses.loop.validate`)."""
    return _loop_input(given)


#: The optional sections, in the order they run (see the module docstring).
ANALYSES: tuple = (
    Analysis("board", "board", "model", prepare=_board, reviewed=True),
    Analysis("observer", "observer", "model", prepare=_observer,
             run=Lazy("pulab.analyses.observer", "analyze"), echo=_given_keys, reviewed=True),
    Analysis("loop", "analysis", run=Lazy(_LOOP, "analyze"), echo=_analysis_echo,
             warnings=Lazy(_LOOP, "warnings"), reviewed=True),
    Analysis("fw", "analysis.fw", run=Lazy("pulab.analyses.fwtables", "analyze"), reviewed=True),
    Analysis("sim", "sim", "steps", check=Lazy("pulab.analyses.sim", "validate"),
             run=Lazy("pulab.analyses.sim", "simulate_steps"), reviewed=True),
)
