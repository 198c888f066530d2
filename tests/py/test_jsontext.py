"""pulab.schema.jsontext: JSON text with the contract's limits — nesting counted over brackets
outside strings only, every failure an InputError naming the field, never a Python exception."""
import json

import pytest

from pulab.schema.errors import InputError
from pulab.schema.jsontext import MAX_DEPTH, parse


def _code(text, field="input"):
    with pytest.raises(InputError) as e:
        parse(text, field)
    assert e.value.field == field
    return e.value.code


@pytest.mark.parametrize("open_, close", [("[", "]"), ('{"k":', "}")])
def test_depth_limit_is_exact(open_, close):
    ok = open_ * MAX_DEPTH + "1" + close * MAX_DEPTH
    assert parse(ok) == json.loads(ok)
    assert _code(open_ * (MAX_DEPTH + 1) + "1" + close * (MAX_DEPTH + 1)) == "json_too_deep"


def test_brackets_inside_strings_do_not_count():
    text = json.dumps({"a": "[[[[{{{{" * 100, "b": '\\"[' * 50, "c": ["]]]]"]})
    assert parse(text) == json.loads(text)


def test_every_failure_is_an_input_error_naming_the_field():
    assert _code('{"a": 1,}', "qcalc") == "json_invalid"
    assert _code('"unterminated [[[[', "sweep") == "json_invalid"
    assert _code("1" * 5000) == "json_invalid"          # beyond Python's int-from-text limit
    assert _code(None) == "json_not_text" and _code(b"{}") == "json_not_text"
    assert _code("[" * 100_000) == "json_too_deep"
    assert parse("NaN") != parse("NaN")                   # parsed; the field checks refuse it


def test_hostile_strings_end_in_an_error():
    # an unterminated string of escaped quotes (a backtracking scan would not return)
    assert _code('"' + '\\"' * 200_000) == "json_invalid"
    assert _code('["' + "\\" * 100_001) == "json_invalid"
