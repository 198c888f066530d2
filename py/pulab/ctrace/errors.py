"""The one error the tracer produces: a catalog code, where in the code, and what the code offers.

Examples
--------
>>> e = TraceError(3, 14, code="trace_division_zero")
>>> str(e), e.reason
('code: 3:14: division by zero', 'division by zero')
>>> e.message_zh
'3:14：除以零'
>>> from dataclasses import fields
>>> [f.name for f in fields(TraceError)]
['line', 'column', 'inputs', 'functions', 'macros']
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..schema.errors import InputError

__all__ = ["TraceError"]


@dataclass(init=False, eq=False, repr=False)
class TraceError(InputError):
    """Code the tracer cannot run, or a request it cannot run the code with.

    An :class:`~pulab.schema.errors.InputError` (field, catalog code, params) with the
    fields below: the tracer fills them, each ``None`` where it does not apply, and the API's
    error reply carries those that are set, in this order (docs/contract.md, "API").

    Parameters
    ----------
    line, column : int >= 1, or None
        Where in the pasted code (1-based; ``column`` counts characters).  The error's code
        is then ``trace_at`` with ``line``, ``column`` and the reason (``code`` with
        ``params``) nested as ``reason``.  ``None`` for an error not at a place in the code
        (a bad entry, input value or option): ``code`` and ``params`` are the error's own.
    field : str
        The request field at fault (``code`` unless the code is run with a bad value).
    code : str
        A code of :data:`pulab.schema.catalog.MESSAGES`; ``params`` fill its texts.
    """

    line: int | None = field(default=None, metadata={
        "doc": "the line of the code at fault (1-based); None: not at a place in the code"})
    column: int | None = field(default=None, metadata={
        "doc": "the column of the code at fault (1-based, in characters)"})
    inputs: list | None = field(default=None, metadata={
        "doc": "the names the code reads before giving them a value, once it compiled"})
    functions: list | None = field(default=None, metadata={
        "doc": "the functions the code defines (one can be the entry), once it parsed"})
    macros: list | None = field(default=None, metadata={
        "doc": "the function-like macros that can be the entry, once the code parsed"})

    def __init__(self, line: int | None, column: int | None, field: str = "code", *,
                 code: str, **params) -> None:
        if line is None:
            super().__init__(field, code=code, **params)
        else:
            super().__init__(field, code="trace_at", line=line, column=column,
                             reason={"code": code, "params": params})
        self.line, self.column = line, column

    @classmethod
    def of(cls, e: InputError) -> TraceError:
        """``e`` itself when it is a TraceError, else a TraceError with its field, code and
        params and no position (so the tracer can say what the code offers)."""
        if isinstance(e, cls):
            return e
        return cls(None, None, e.field, code=e.code, **e.params)

    @classmethod
    def at(cls, place, /, code: str, **params) -> TraceError:
        """The error ``code`` at ``place`` (a token or a syntax node: its line and column)."""
        return cls(place.line, place.column, code=code, **params)

    def reason_error(self) -> dict:
        """The reason without the position, as a message parameter (an error of its own,
        rendered in the language of the message it is part of)."""
        return self.params["reason"] if self.line is not None else self.as_dict()

    @property
    def reason(self) -> str:
        """:meth:`reason_error` in English."""
        from ..schema.catalog import render
        reason = self.reason_error()
        return render(reason["code"], reason["params"], "en")
