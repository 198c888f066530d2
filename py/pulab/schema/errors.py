"""The one error that bad input produces: a code, the field's JSON path, parameters.

Its text in English and Chinese comes from one catalog (:mod:`.catalog`), so the
CLI, the JSON API and the page show the same words.

Examples
--------
>>> e = InputError("motor.rs_ohm", code="not_positive", value=-1.0)
>>> e.field, e.code, e.params
('motor.rs_ohm', 'not_positive', {'value': -1.0})
>>> e.message, e.message_zh
('must be > 0, got -1', '必须大于 0，当前为 -1')
>>> str(e)
'motor.rs_ohm: must be > 0, got -1'
"""

from .catalog import render

__all__ = ["InputError"]


class InputError(ValueError):
    """Invalid input, naming the field at fault.

    Parameters
    ----------
    field : str
        JSON path of the offending input field, e.g. ``motor.rs_ohm``.
    code : str
        Catalog code (:data:`pulab.schema.catalog.MESSAGES`); ``params`` fill its text.
    """

    def __init__(self, field: str, *, code: str, **params) -> None:
        self.field = field
        self.code = code
        self.params = params
        self.message = render(code, params, "en")
        super().__init__(f"{field}: {self.message}")

    @property
    def message_zh(self) -> str:
        """The Chinese text of :attr:`message`."""
        return render(self.code, self.params, "zh")

    def as_dict(self) -> dict:
        """``{"code", "params"}``: the error as data (nested errors included)."""
        return {"code": self.code, "params": self.params}
