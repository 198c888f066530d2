"""Batch: a CSV catalogue of motors in, every motor's firmware integers and findings out.

CSV contract (docs/contract.md, "Batch"):

- Input columns are named by input JSON paths (``motor.rated_voltage_v``, ``drive.ts_s``,
  ``raw.LD``, ``datasheet.speed_rpm`` …), optionally with a unit in brackets that is
  converted exactly (``motor.ld_h [mH]``: the decimal text times 10⁻³, rounded once).
  Other columns without a dot (``name``, ``model``) are labels, copied to the output.
  An empty cell is an absent field.  Comma, semicolon or tab separated; UTF-8 (BOM
  allowed).  Completely empty lines are skipped and not counted.
- The output has one row per input row, in order: ``row`` (1-based data row), the label
  columns, ``error`` (``field: message``, empty when the row computed) and ``error_zh``,
  then columns named by report JSON paths (:data:`REPORT_COLUMNS`) and the number of
  review findings per severity (``review.counts.error``, ``review.counts.warning``,
  ``review.counts.note``: the graded review's report path), ``firmware`` (each firmware
  that cannot hold the motor, with the raw fields it cannot hold or compute).
- A bad row is reported in its ``error`` cell and the others are still computed; only an
  unreadable header stops the batch (:class:`pulab.InputError` naming the column).

Examples
--------
>>> text = ("name,motor.rated_voltage_v,motor.rated_current_a,motor.rated_freq_hz,"
...         "motor.rs_ohm,motor.ld_h [mH],motor.lq_h [mH],motor.bemf_v,motor.pole_pairs,"
...         "drive.udc_v,drive.ts_s [us]\\n"
...         "seed,17,1.5,220,1.5,0.6,0.6,12,4,24,100\\n"
...         "broken,17,1.5,220,-1,0.6,0.6,12,4,24,100\\n")
>>> rows = batch_rows(text)
>>> rows[0]["vendor.LD.value"], rows[0]["current_pi.d.pm_kp"], rows[0]["error"]
('1045', '1180', '')
>>> rows[1]["row"], rows[1]["name"], rows[1]["error"]
('2', 'broken', 'motor.rs_ohm: must be > 0, got -1')
"""

from __future__ import annotations

import csv
import io
import re
from decimal import Decimal, InvalidOperation

from ..schema.errors import InputError
from ..schema.fields import FIELD
from ..schema.validate import shown
from ..report import report, require_pmsm
from ..profiles.inovance.code import RAW_FIELDS, VENDOR_RESULTS

__all__ = ["read_table", "batch_rows", "batch_csv", "to_csv", "output_columns", "findings_counts",
           "UNITS", "REPORT_COLUMNS", "SEVERITIES"]

#: Units a bracket may give, by the unit the field name ends in (``_h``, ``_ohm`` …):
#: each as the power of ten it scales the decimal text by.
UNITS = {
    "h": {"H": 0, "mH": -3, "uH": -6, "µH": -6, "μH": -6},
    "ohm": {"Ω": 0, "ohm": 0, "Ohm": 0, "mΩ": -3, "mohm": -3, "mOhm": -3, "kΩ": 3, "kohm": 3},
    "v": {"V": 0, "mV": -3, "kV": 3},
    "a": {"A": 0, "mA": -3, "kA": 3},
    "hz": {"Hz": 0, "kHz": 3},
    "s": {"s": 0, "ms": -3, "us": -6, "µs": -6, "μs": -6, "ns": -9},
    "wb": {"Wb": 0, "mWb": -3},
    "rpm": {"rpm": 0, "krpm": 3},
}
#: Report columns, by report JSON path: the firmware integers and their errors.
REPORT_COLUMNS = (
    tuple(f"vendor.raw.{name}" for name in RAW_FIELDS)
    + tuple(f"vendor.{name}.{key}" for name in VENDOR_RESULTS
            for key in ("value", "error_pct", "flags"))
    + tuple(f"current_pi.{axis}.{key}" for axis in ("d", "q") for key in ("pm_kp", "pm_ki"))
)
SEVERITIES = ("error", "warning", "note")
_HEADER = re.compile(r"\s*([^\[\]]*?)\s*(?:\[\s*([^\[\]]*?)\s*\])?\s*")
_INT = re.compile(r"[+-]?\d+")


def _column(cell: str, k: int) -> tuple:
    """(name, power of ten) of a header cell ``path [unit]``; a label has no dot."""
    m = _HEADER.fullmatch(cell)
    name, unit = (m[1], m[2]) if m else (cell.strip(), None)
    where = f"csv.header.{k + 1}"
    if not name:
        raise InputError(where, code="empty_column", got=shown(cell))
    if unit is None:
        return name, 0
    if "." not in name:
        raise InputError(where, code="unit_not_path", got=shown(name))
    field = FIELD.get(name)
    if field is not None and unit == field.unit:
        return name, 0  # the unit the schema gives, as it spells it (V/krpm, rpm/V, N·m/A …)
    # a compound unit (ke_v_per_krpm, kt_nm_per_a) is not the unit its name ends in
    dim = "" if "_per_" in name else name.rsplit("_", 1)[-1]
    table = UNITS.get(dim, {})
    if unit not in table:
        if not table:
            raise InputError(where, code="unit_none", unit=unit, name=name)
        raise InputError(where, code="unit_unknown", unit=unit, name=name, allowed=", ".join(table))
    return name, table[unit]


def _delimiter(first_line: str) -> str:
    return max(",;\t", key=first_line.count)


_LAST: list = [None, None]  # the last text parsed and its table: a page asks chunk by chunk


def read_table(text: str) -> tuple:
    """Parse a motor CSV: (columns, rows).

    Returns
    -------
    tuple
        ``columns``: list of (name, power of ten); ``rows``: list of lists of cell text,
        one per non-empty data row, padded with "" to the header's length (a row with more
        cells than the header is kept longer and reported by :func:`batch_rows`).

    Raises
    ------
    pulab.InputError
        ``csv`` when there is no header, ``csv.header.K`` for a bad column K (1-based).
    """
    if not isinstance(text, str):
        raise InputError("csv", code="not_string", got=shown(text))
    if _LAST[0] == text:
        return _LAST[1]
    table = _parse(text)
    _LAST[:] = [text, table]
    return table


def _parse(text: str) -> tuple:
    text = text.lstrip("\ufeff")
    first = text.split("\n", 1)[0]
    reader = csv.reader(io.StringIO(text), delimiter=_delimiter(first))
    try:
        table = [r for r in reader if any(c.strip() for c in r)]
    except csv.Error as e:
        raise InputError("csv", code="csv_unreadable", detail=str(e)) from None
    if not table:
        raise InputError("csv", code="no_header")
    columns = [_column(c, k) for k, c in enumerate(table[0])]
    seen: dict = {}
    for k, (name, _) in enumerate(columns):
        if name in seen:
            raise InputError(f"csv.header.{k + 1}", code="duplicate_column", name=name,
                             other=seen[name] + 1)
        seen[name] = k
    width = len(columns)
    rows = [r + [""] * (width - len(r)) for r in table[1:]]
    return columns, rows


#: Longer integer cells are read as decimals (int() refuses over 4300 digits; no field needs 400).
_INT_DIGITS = 400


def _number(text: str, power: int, field: str):
    """A cell as a number: integers stay int, decimals become the nearest double."""
    if power == 0 and _INT.fullmatch(text) and len(text) <= _INT_DIGITS:
        return int(text)
    try:
        d = Decimal(text)
    except InvalidOperation:
        if power:
            raise InputError(field, code="not_number", got=shown(text)) from None
        return text  # a choice (conventions.base …) or a mistake normalize will name
    if not d.is_finite():
        raise InputError(field, code="not_finite")
    return float(d.scaleb(power))


def _row_input(columns: list, cells: list) -> dict:
    if len(cells) > len(columns):
        raise InputError("row", code="ragged_row", cells=len(cells), columns=len(columns))
    inp: dict = {}
    for (name, power), cell in zip(columns, cells):
        cell = cell.strip()
        if "." not in name or not cell:
            continue
        section, key = name.split(".", 1)
        inp.setdefault(section, {})[key] = _number(cell, power, name)
    return inp


def findings_counts(r: dict) -> dict:
    """Review findings per severity (``error``, ``warning``, ``note``) of a report.

    The graded review gives ``review.counts`` (or at least ``review.findings``
    with a ``severity`` each); a report without one counts its ``warnings``, all of them
    warnings.
    """
    counts = dict.fromkeys(SEVERITIES, 0)
    review = r.get("review")
    if isinstance(review, dict) and isinstance(review.get("counts"), dict):
        return {s: int(review["counts"].get(s, 0)) for s in SEVERITIES}
    if review is None:
        counts["warning"] = len(r["warnings"])
        return counts
    findings = review.get("findings", ()) if isinstance(review, dict) else review
    for f in findings:
        counts[f["severity"]] = counts.get(f["severity"], 0) + 1
    return counts


def _cell(v) -> str:
    if v is None:
        return ""
    if isinstance(v, float):
        return repr(v)  # shortest round-trip text: the CLI and the page print the same
    if isinstance(v, list):
        return " ".join(v)
    return str(v)


def _report_cells(r: dict) -> dict:
    out = {}
    for path in REPORT_COLUMNS:
        v = r
        for part in path.split("."):
            # an integer the firmware cannot compute for this motor: empty (firmware.*)
            v = v.get(part) if isinstance(v, dict) else None
        out[path] = _cell(v)
    for sev, n in findings_counts(r).items():
        out[f"review.counts.{sev}"] = str(n)
    out["firmware"] = "; ".join(f"{name}: {' '.join(p['field'] for p in st['problems'])}"
                                for name, st in r.get("firmware", {}).items()
                                if not st["representable"])
    return out


def output_columns(columns: list) -> list:
    """The output header for an input header (see the module docstring)."""
    labels = [name for name, _ in columns if "." not in name]
    return (["row"] + labels + ["error", "error_zh"] + list(REPORT_COLUMNS)
            + [f"review.counts.{s}" for s in SEVERITIES] + ["firmware"])


def batch_rows(text: str, start: int = 0, count: int | None = None) -> list:
    """Output rows (dicts of cell text) for data rows ``start`` … ``start+count−1``.

    Raises
    ------
    pulab.InputError
        Only for the file as a whole (no header, bad column); a bad row is reported in its
        ``error`` cell.
    """
    columns, rows = read_table(text)
    stop = len(rows) if count is None else min(len(rows), start + count)
    out = []
    for k in range(start, stop):
        cells = rows[k]
        rec = {"row": str(k + 1)}
        for (name, _), cell in zip(columns, cells):
            if "." not in name:
                rec[name] = cell
        try:
            r = report(_row_input(columns, cells))
            require_pmsm(r["input"])
            rec.update(_report_cells(r), error="", error_zh="")
        except InputError as e:
            rec.update(error=f"{e.field}: {e.message}", error_zh=f"{e.field}: {e.message_zh}")
        out.append(rec)
    return out


#: First characters that make a spreadsheet read a cell as a formula (OWASP, CSV injection).
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_PLAIN_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def spreadsheet_safe(cell) -> str:
    """A CSV cell a spreadsheet shows as text, never runs as a formula.

    A cell starting with ``= + - @``, tab or carriage return gets a leading ``'``
    (the OWASP rule), unless the whole cell is a plain decimal number such as
    ``-0.5`` or ``-1e-3``, which stays a number.

    Examples
    --------
    >>> for cell in ['=HYPERLINK("http://x","a")', "-1.5e-3", "-1+2", "@SUM(A1)", "seed"]:
    ...     print(spreadsheet_safe(cell))
    '=HYPERLINK("http://x","a")
    -1.5e-3
    '-1+2
    '@SUM(A1)
    seed
    """
    text = str(cell)
    if text.startswith(FORMULA_START) and not _PLAIN_NUMBER.fullmatch(text):
        return "'" + text
    return text


def to_csv(names: list, rows: list, header: bool = True) -> str:
    """CSV text of output rows (dicts) in the column order ``names``, header first if asked.

    Every cell, the header's included, goes through :func:`spreadsheet_safe`.
    """
    lines = [[spreadsheet_safe(n) for n in names]] if header else []
    lines += [[spreadsheet_safe(r.get(n, "")) for n in names] for r in rows]
    return "".join(",".join(_quoted(c) for c in line) + "\n" for line in lines)


def _quoted(cell: str) -> str:
    # The csv module leaves a lone CR unquoted when the line ends in LF; readers then split there.
    if any(c in cell for c in ',"\r\n'):
        return '"' + cell.replace('"', '""') + '"'
    return cell


def batch_csv(text: str) -> str:
    """The whole output CSV of a motor CSV (what ``pulab batch FILE`` prints)."""
    return to_csv(output_columns(read_table(text)[0]), batch_rows(text))
