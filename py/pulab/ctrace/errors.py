"""The one error bad C code produces: a message naming line and column."""

from __future__ import annotations

from ..schema.errors import InputError

__all__ = ["TraceError"]


class TraceError(InputError):
    """Code the interpreter cannot run, at a source position.

    Parameters
    ----------
    line, column : int >= 1
        Where in the pasted code (1-based; ``column`` counts characters).
    message : str, optional
        What is wrong there, one line, without the position (free text).
    code : str, optional
        Instead of ``message``: a code of :data:`pulab.schema.catalog.MESSAGES` whose
        ``params`` fill its English and Chinese text.

    Examples
    --------
    >>> str(TraceError(3, 14, "division by zero"))
    'code: 3:14: division by zero'
    """

    def __init__(self, line: int, column: int, message: str | None = None, field: str = "code",
                 *, code: str | None = None, **params) -> None:
        if code is None:  # free text, its Chinese from pulab.schema.messages
            super().__init__(field, f"{line}:{column}: {message}")
            self.reason = message
        else:  # a catalog code: the position, then the reason in either language
            from ..schema.catalog import render
            super().__init__(field, code="trace_at", line=line, column=column,
                             reason={"code": code, "params": params})
            self.reason = render(code, params, "en")
        self.line = line
        self.column = column

    def reason_error(self) -> dict:
        """The reason without the position, as a message parameter (an error of its own,
        rendered in the language of the message it is part of)."""
        if self.code == "trace_at":
            return self.params["reason"]
        return {"code": "text", "params": {"text": self.reason}}
