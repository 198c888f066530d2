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
    message : str
        What is wrong there, one line, without the position.

    Examples
    --------
    >>> str(TraceError(3, 14, "division by zero"))
    'code: 3:14: division by zero'
    """

    def __init__(self, line: int, column: int, message: str, field: str = "code") -> None:
        super().__init__(field, f"{line}:{column}: {message}")
        self.line = line
        self.column = column
        self.reason = message
