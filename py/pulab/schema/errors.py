"""The one error that bad input produces."""

__all__ = ["InputError"]


class InputError(ValueError):
    """Invalid input, naming the field at fault.

    Parameters
    ----------
    field : str
        JSON path of the offending input field, e.g. ``motor.rs_ohm``.
    message : str
        What is wrong with it, one line.
    """

    def __init__(self, field: str, message: str) -> None:
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message
