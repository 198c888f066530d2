"""Audit a vendor's generated parameter header: the design it encodes and what is wrong.

:func:`audit` takes one or more header texts (a whole generated set: ST's four MCSDK files,
TI's ``user_mtr1.h`` with ``user_common.h``, NXP's ``m1_pmsm_appconfig.h`` …):

1. the files are ordered so that a file comes after the given files it ``#include``s (an
   include of another file is listed in ``unresolved``), and run through the tracer's C
   preprocessor (:func:`pulab.ctrace.preprocess.preprocess`: ``#if``, include guards, macros
   built from macros), with the vendor library macros of :data:`LIBRARY` and ``-D``
   definitions first, as on the compiler's command line;
2. every object-like ``#define`` is expanded and folded as the target's compiler folds it
   (:mod:`pulab.analyses.cconst`: casts, integer division, ``f`` singles); a name left after
   expansion is listed in ``unknown``, never guessed;
3. the vendor is the one whose decoder reads the most of the defined macros (or given); its
   ``decode_header`` (:data:`pulab.profiles.vendor.OPTIONAL`) turns the values into SI with
   unit, meaning and formula, recovers the design and checks the constants against each
   other; when it folds on another target (TI's C28x, Microchip's dsPIC: 16-bit ``int``) the
   macros are folded again there;
4. findings (``severity``, ``code``, ``macros``, en/zh ``message``): the vendor's checks, a
   known macro whose value the compiler wraps or truncates out of range (``overflow``), an
   ``#if`` that compares undefined names (``if_undefined``: 0 == 0 picks the first branch).

Examples
--------
>>> text = ("#define RS 0.35\\n#define LS 0.0006\\n#define POLE_PAIR_NUM 2\\n"
...         "#define PWM_FREQUENCY 20000\\n#define REGULATION_EXECUTION_RATE 1\\n")
>>> d = audit([("pmsm_motor_parameters.h", text)])
>>> d["profile"], d["macros"]["RS"]["si"], d["design"]["input"]["drive"]["ts_s"]
('st', 0.35, 5e-05)
"""

from __future__ import annotations

import copy
import math
import re

from ..ctrace.errors import TraceError
from ..ctrace.lexer import tokenize
from ..ctrace.preprocess import STANDARD_HEADERS, preprocess
from ..profiles import registry
from ..profiles.vendor import provided
from ..schema.catalog import render
from ..schema.errors import InputError
from ..schema.validate import shown
from .cconst import NotConstant, evaluate
from .loop.current import STATIC_PLANT, axis_loop
from .prove import PROFILES as PROVABLE
from .prove import prove

__all__ = ["audit", "LIBRARY", "MAX_FILES", "MAX_CHARS"]

#: More files, or more characters in all, are refused.
MAX_FILES = 16
MAX_CHARS = 1_000_000

#: Vendor library macros a generated header uses without defining them, as their libraries
#: define them (written here from their documented meaning). NXP RTCESL mlib_types.h
#: (:data:`pulab.profiles.common.SOURCES` ``nxp_types``): FRAC16(x) = x·2^15 and FRAC32(x) =
#: x·2^31 saturated to [−1, 1), ACC32(x) = x·2^15 in Q16.15, truncated by the cast.
LIBRARY = {
    "FRAC16(x)": "((frac16_t)(((x) < 0.999969482421875) ? (((x) >= -1.0) ? (x)*32768.0 "
                 ": (-32767-1)) : 32767))",
    "FRAC32(x)": "((frac32_t)(((x) < 1.0) ? (((x) >= -1.0) ? (x)*2147483648.0 "
                 ": (-2147483647L-1)) : 2147483647L))",
    "ACC32(x)": "((acc32_t)(((x) < 65535.999969482421875) ? (((x) >= -65536.0) ? (x)*32768.0 "
                ": (-2147483647L-1)) : 2147483647L))",
    # TI C2000Ware libraries/math/include/math.h (the universal lab's user_mtr1.h uses them)
    "MATH_PI": "((float32_t)(3.1415926535897932384626433832f))",
    "MATH_TWO_PI": "((float32_t)(6.283185307179586f))",
}
_LIB_NAMES = {k.split("(")[0] for k in LIBRARY}
_STD_NAMES = {n for h in STANDARD_HEADERS.values() for n in h}
_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)", re.M)
_INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*[<"]([^>"\n]+)[>"]', re.M)
_IF = re.compile(r"^[ \t]*#[ \t]*(?:el)?if\b(.*)$", re.M)
_SENTINEL = "__pulab_audit_"
#: The inputs a report needs that a header may not fix (``design.missing`` names them).
_REQUIRED = (("motor", ("rated_voltage_v", "rated_current_a", "rated_freq_hz", "rs_ohm", "ld_h",
                        "lq_h", "bemf_v", "pole_pairs")), ("drive", ("udc_v", "ts_s")))
#: The delay model of the margins (the report's default: computation and PWM) and the phase
#: margin below which a loop is called under-damped (the report's ``warning.current_low_pm``).
_DELAY = "computation_pwm"
_PM_LOW = 30.0
#: The motor box of the range proof: every motor number of ``design.input`` × (1 ∓ 20 %), and
#: the boxes the family prover may evaluate per constant (it answers ``unknown`` beyond).
SPREAD = 0.2
PROOF_BUDGET = 400
_COMMENT = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|//(?:\\\r?\n|[^\n])*|/\*.*?(?:\*/|\Z)',
                      re.S)


def _blank_comments(text: str) -> str:
    """Comments replaced by a blank (their line breaks kept). The tracer's preprocessor reads a
    ``#`` inside a directive's comment as an operator (``/* … #SPEED_UNIT */`` in ST's
    drive_parameters.h stops it), and the comments are read separately (:func:`_comments`)."""
    return _COMMENT.sub(lambda m: m[0] if m[0][0] in "\"'" else " " + "\n" * m[0].count("\n"),
                        text)


def _check_files(files) -> list:
    if not isinstance(files, (list, tuple)) or not files:
        raise InputError("files", code="audit_no_files")
    if len(files) > MAX_FILES:
        raise InputError("files", code="integer_range", lo=1, hi=MAX_FILES, got=len(files))
    out, total = [], 0
    for k, item in enumerate(files):
        field = f"files[{k}]"
        if not isinstance(item, (list, tuple)) or len(item) != 2:
            raise InputError(field, code="audit_not_text", name=field,
                             why={"code": "audit_why_pair", "params": {}})
        name, text = item
        if not isinstance(name, str) or not name.strip():
            name = f"file{k + 1}"
        if not isinstance(text, str):
            raise InputError(field, code="audit_not_text", name=name,
                             why={"code": "audit_why_type", "params": {}})
        if "\x00" in text:
            raise InputError(field, code="audit_not_text", name=name,
                             why={"code": "audit_why_nul", "params": {}})
        total += len(text)
        if total > MAX_CHARS:
            raise InputError(field, code="json_too_long", limit=MAX_CHARS)
        if not text.strip():
            raise InputError(field, code="audit_empty", name=name)
        out.append((name.strip().replace("\\", "/"), text))
    return out


def _order(files: list) -> list:
    """Files after the given files they include (by base name), otherwise as given."""
    base = {n.rsplit("/", 1)[-1]: k for k, (n, _) in enumerate(files)}
    done, out = set(), []

    def visit(k: int, path: tuple) -> None:
        if k in done or k in path:
            return
        for inc in _INCLUDE.findall(files[k][1]):
            j = base.get(inc.strip().rsplit("/", 1)[-1])
            if j is not None:
                visit(j, path + (k,))
        done.add(k)
        out.append(files[k])

    for k in range(len(files)):
        visit(k, ())
    return out


class _Source:
    """The files joined into one text, with the map back to (file, line)."""

    def __init__(self, files: list) -> None:
        self.names, self.starts, self.raw, parts, line = [], [], [], [], 1
        given = {n.rsplit("/", 1)[-1] for n, _ in files}
        for name, text in files:
            # An include of a given file is satisfied by joining it before; drop the line so
            # the preprocessor does not list it as unresolved (the line count is kept).
            text = _INCLUDE.sub(lambda m: "" if m[1].strip().rsplit("/", 1)[-1] in given
                                else m[0], text)
            if not text.endswith("\n"):
                text += "\n"
            self.names.append(name)
            self.starts.append(line)
            parts.append(_blank_comments(text))
            self.raw.append(text)
            line += text.count("\n")
        self.text = "".join(parts)
        self.lines = line

    def where(self, line: int) -> tuple:
        k = max(i for i, s in enumerate(self.starts) if s <= line)
        return self.names[k], line - self.starts[k] + 1


def _preprocess(src: _Source, text: str, defines: dict, tail: tuple = ((), {})):
    """The tracer's preprocessor on ``text``; an error names the file and line. ``tail``:
    (macro names, their (file, line)) of the expansion line appended to the files, so an error
    there (a macro bomb) names the ``#define`` whose expansion failed."""
    try:
        return preprocess(tokenize(text), {**LIBRARY, **defines})
    except TraceError as e:
        line = getattr(e, "line", None) or 1
        if line < src.lines:
            f, n = src.where(line)
        else:
            names, lines = tail
            k = len(text[len(src.text):len(src.text) + 1 + (e.column or 1)].split(_SENTINEL)) - 2
            f, n = lines.get(names[k], (src.names[-1], 0)) if 0 <= k < len(names) else \
                (src.names[-1], 0)
        raise InputError("files", code="audit_preprocess", file=f, line=n,
                         why=e.reason_error()) from None


def _defines(options) -> dict:
    out = {}
    for d in options or ():
        if not isinstance(d, str):
            raise InputError("defines", code="set_syntax", got=shown(d))
        name, eq, value = d.partition("=")
        name = name.strip()
        if not re.fullmatch(r"[A-Za-z_]\w*", name):
            raise InputError("defines", code="set_syntax", got=repr(d))
        out[name] = value if eq else "1"
    return out


def _comments(text: str) -> dict:
    """Line of each ``#define`` → the comment that starts on its (spliced) line; a
    ``/* … */`` may go on over later lines."""
    out = {}
    for m in _DEFINE.finditer(text):
        i, note = m.end(), None
        while True:
            end = text.find("\n", i)
            end = len(text) if end < 0 else end
            c = re.search(r"//|/\*", text[i:end])
            if c is not None:
                start = i + c.start() + 2
                if c[0] == "//":
                    note = text[start:end]
                else:
                    close = text.find("*/", start)
                    note = text[start:close if close >= 0 else len(text)]
                break
            if not text[i:end].rstrip().endswith("\\") or end == len(text):
                break
            i = end + 1
        if note is not None:
            line = text.count("\n", 0, m.start()) + 1
            note = re.sub(r"^[ \t]*\*+(?!/)", " ", note.replace("!<", " "), flags=re.M)
            out[line] = " ".join(note.split())
    return out


def _undefined_if(src: _Source, macros: dict, folded: dict) -> tuple:
    """(names, accidental): the names an ``#if``/``#elif`` compares with ``==``/``!=`` that no
    file defines, and whether some comparison has both sides 0 through undefined names (a
    name no file defines, or a macro that expands only to such names): 0 == 0 then picks a
    branch by accident. Otherwise such a branch can only never be chosen by its name."""
    names, accidental = [], False

    def undefined_zero(n: str) -> bool:
        f = folded.get(n)
        return n not in macros or (f is not None and bool(f["unknown"]) and not f["value"])

    for m in _IF.finditer(src.text):
        cond = re.sub(r"defined\s*\(?\s*\w+\s*\)?|//.*|/\*.*?\*/", " ", m[1])
        if "==" not in cond and "!=" not in cond:
            continue
        for n in re.findall(r"[A-Za-z_]\w*", cond):
            if n not in macros and n not in names:
                names.append(n)
        for a, b in re.findall(r"([A-Za-z_]\w*)\s*[=!]=\s*([A-Za-z_]\w*)", cond):
            accidental = accidental or (undefined_zero(a) and undefined_zero(b))
    return names, accidental


def _fold_all(src: _Source, names: list, defines: dict, target: str, lines: dict) -> dict:
    """Every macro of ``names`` expanded and folded on ``target``."""
    tail = "\n" + " ".join(f"{_SENTINEL}{k} {n}" for k, n in enumerate(names)) + "\n"
    pre = _preprocess(src, src.text + tail, defines, (names, lines))
    toks = pre.tokens[:-1]
    out, cur, k = {}, None, None
    starts = [i for i, t in enumerate(toks) if t.kind == "name" and t.text.startswith(_SENTINEL)
              and t.line >= src.lines]
    for j, i in enumerate(starts):
        k = int(toks[i].text[len(_SENTINEL):])
        cur = toks[i + 1:starts[j + 1] if j + 1 < len(starts) else len(toks)]
        try:
            v = evaluate(cur, target)
            out[names[k]] = {"value": v.value, "type": v.type, "unknown": v.unknown,
                             "flags": v.flags, "expansion": " ".join(t.text for t in cur)}
        except NotConstant as e:
            out[names[k]] = {"value": None, "type": None, "unknown": [], "flags": [],
                             "expansion": " ".join(t.text for t in cur), "error": e.reason}
    return out


def _decoders() -> dict:
    return {n: f for n in registry.names()
            if (f := provided(registry.get(n), "decode_header")) is not None}


def _finding(severity: str, code: str, macros: list, params: dict, advice: str = "",
             words: str | None = None) -> dict:
    """A finding; ``words``: the catalog entry ``audit.<words>`` when not ``audit.<code>``."""
    key = f"audit.{words or code}"
    return {"severity": severity, "code": code, "macros": macros,
            "message": render(key, params, "en"), "message_zh": render(key, params, "zh"),
            "advice": advice}


def _margins(design: dict) -> list:
    """Each current-loop axis measured as the report measures a loop (the firmware PI, the ZOH
    plant R + sL, one sample of computation and the PWM's half period,
    :func:`pulab.analyses.loop.current.axis_loop`): its ``delay``, ``phase_margin_deg``,
    ``gain_margin_db``, ``crossover_hz`` and ``stable`` are added to the axis; a
    ``loop_margin`` finding when it is unstable (error) or under 30° of phase margin."""
    motor = design.get("input", {}).get("motor", {})
    ts = design.get("input", {}).get("drive", {}).get("ts_s")
    out = []
    for axis, c in design["current_loop"].items():
        r, l = motor.get("rs_ohm"), motor.get("ld_h" if axis == "d" else "lq_h")
        # R·Ts/L beyond STATIC_PLANT: the plant settles within a sample, no loop to measure
        if not (ts and l and r is not None and r * ts / l <= STATIC_PLANT):
            continue
        try:
            m = axis_loop(r, l, ts, c["kp_v_per_a"], c["ki_v_per_a_s"], _DELAY)
        except (ArithmeticError, ValueError):
            continue  # gains the header makes absurd (1e300 V/A): no margin is a number
        if not all(map(math.isfinite, (m["spectral_radius"], *(x for x in (
                m["phase_margin_deg"], m["gain_margin_db"]) if x is not None)))):
            continue
        c.update(delay=_DELAY, phase_margin_deg=m["phase_margin_deg"],
                 gain_margin_db=m["gain_margin_db"], crossover_hz=m["crossover_hz"],
                 stable=m["stable"])
        pm = m["phase_margin_deg"]
        if m["stable"] and (pm is None or pm >= _PM_LOW):
            continue
        out.append(_finding("error" if not m["stable"] else "warning", "loop_margin",
                            list(c.get("macros", ())), {
                                "axis": axis, "pm": "—" if pm is None else round(pm, 1),
                                "gm": "—" if m["gain_margin_db"] is None
                                else round(m["gain_margin_db"], 1),
                                "fc": "—" if m["crossover_hz"] is None
                                else round(m["crossover_hz"], 1),
                                "ts": ts, "stable": {"code": "audit.loop_stable" if m["stable"]
                                                     else "audit.loop_unstable", "params": {}}},
                            "lower the bandwidth (kp) until the phase margin is 30° or more"))
    return out


def _range_proof(vendor: str, design: dict, macros: dict) -> tuple:
    """(``design.range_proof``, findings): the vendor's constants for every motor within
    ± :data:`SPREAD` of the one the files encode, decided by the family prover
    (:func:`pulab.analyses.prove.prove`: interval evaluation of the profile's own code, so
    ``proven`` holds for the whole box and ``violated`` comes with a motor that breaks it). A
    violated constant is an ``overflow`` warning naming the macro and that motor."""
    if design["missing"] or vendor not in PROVABLE:
        return None, []
    motor = design["input"].get("motor", {})
    ranges = {f"motor.{k}": [x * (1.0 - SPREAD), x * (1.0 + SPREAD)] for k, x in motor.items()
              if k != "pole_pairs" and isinstance(x, float) and x > 0}
    if not ranges:
        return None, []
    try:
        r = prove({"input": design["input"], "ranges": ranges, "profile": vendor,
                   "budget": PROOF_BUDGET})
    except InputError as e:
        # a box end the report refuses (e.g. a rated voltage above the bus): no proof, said why
        return {"verdict": None, "spread": SPREAD, "error": e.message,
                "error_zh": e.message_zh}, []
    out = {"verdict": r["verdict"], "spread": SPREAD, "ranges": r["ranges"], "constants": {}}
    found = []
    for name, e in r["integers"].items():
        short = name.rsplit(".", 1)[-1]
        keep = {k: e[k] for k in ("verdict", "range", "word", "kind", "statement",
                                  "counterexample") if k in e}
        out["constants"][short] = keep
        if e["verdict"] != "violated":
            continue
        motor_at = (e.get("counterexample") or {}).get("motor", {})
        at = ", ".join(f"{k} = {motor_at[k]:.6g}" for k in sorted(motor_at)
                       if f"motor.{k}" in ranges)
        found.append(_finding("warning", "overflow", [short] if short in macros else [], {
            "macro": short, "spread": round(100 * SPREAD), "kind": e.get("kind", ""),
            "statement": e.get("statement", ""), "at": at},
            "a wider word, a larger scale or a smaller shift for this constant",
            words="overflow_range"))
    return out, found


def _roundtrip(vendor: str, design: dict, macros: dict) -> tuple:
    """(``regenerated``, ``roundtrip``): pu-lab's header for ``design.input`` (None when the
    files do not fix a whole report input, ``design.missing``) and, per macro the files define
    and pu-lab generates — in its header, or among the profile's constants that the vendor's
    own conversion file computes from the others (ST's ``C1``…``C5``) —, file vs pu-lab
    (``delta_lsb`` for two integers, else ``delta_rel``)."""
    if design["missing"]:
        return None, {}
    from .. import profiles
    from ..report import report
    inp = copy.deepcopy(design["input"])
    inp.setdefault("profiles", {}).setdefault(vendor, {})
    try:
        rep = report(inp)
        text = profiles.header(rep, vendor)
        mine = {n: m["value"] for n, m in
                _read([(f"pulab_{vendor}.h", text)], vendor, None)["macros"].items()}
    except InputError as e:
        return {"header": None, "error": e.message, "error_zh": e.message_zh}, {}
    for n, c in ((rep.get("profiles") or {}).get(vendor) or {}).get("constants", {}).items():
        mine.setdefault(n, c.get("value") if isinstance(c, dict) else None)
    out = {}
    for n, m in macros.items():
        a, b = m["value"], mine.get(n)
        if not isinstance(a, (int, float)) or not isinstance(b, (int, float)) \
                or isinstance(b, bool):
            continue
        if isinstance(a, int) and isinstance(b, int):
            out[n] = {"file": a, "pulab": b, "delta_lsb": a - b}
        else:
            out[n] = {"file": a, "pulab": b, "delta_rel": (a - b) / b if b else None}
    return {"header": text}, out


def audit(files, profile: str | None = None, defines=None) -> dict:
    """The design a set of generated headers encodes, and what is wrong with it.

    Parameters
    ----------
    files : list of (name, text)
        The header files (a name's last path part resolves an ``#include``).
    profile : str, optional
        A vendor name (:func:`pulab.profiles.registry.names`); detected when not given.
    defines : list of str, optional
        ``NAME[=VALUE]`` definitions made before the files (a compiler's ``-D``: TI's board).

    Returns
    -------
    dict
        ``profile`` (the vendor), ``target`` (the compiler whose widths folded the macros), ``files`` (in
        the order read), ``unresolved`` (included files not given), ``macros`` (every macro
        the vendor's decoder knows: ``value`` as the compiler computes it, ``type``, ``si``,
        ``unit``, ``meaning``, ``formula``, ``source`` (file:line), ``expansion``),
        ``other`` (every other object-like macro: ``value``, ``source``), ``unknown`` (macro
        → the names it needs that no file defines), ``design`` (``current_loop`` maps ``d``/``q``
        to the gains the files hold: empty when they hold none), ``findings``, ``regenerated``
        (pu-lab's header for ``design.input``: ``header``, or ``error``/``error_zh`` when the
        report refuses it; None when ``design.missing`` is not empty) and ``roundtrip`` (per
        macro both headers define: ``file``, ``pulab``, ``delta_lsb`` or ``delta_rel``).

    Raises
    ------
    InputError
        No file, an empty or non-text file, a preprocessor error (``#error``, an unclosed
        ``#if``) or a known macro that is no constant expression (each naming file:line),
        no macro of a known vendor, an unknown ``profile``.
    """
    out = _read(files, profile, defines)
    out["design"]["range_proof"], found = _range_proof(out["profile"], out["design"],
                                                       out["macros"])
    out["findings"] += found
    out["regenerated"], out["roundtrip"] = _roundtrip(out["profile"], out["design"], out["macros"])
    return out


def _read(files, vendor: str | None, defines) -> dict:
    files = _check_files(files)
    defs = _defines(defines)
    decoders = _decoders()
    if vendor is not None and (not isinstance(vendor, str) or vendor not in decoders):
        raise InputError("profile", code="not_choice", choices=", ".join(decoders),
                         got=shown(vendor))
    ordered = _order(files)
    src = _Source(ordered)
    pre = _preprocess(src, src.text, defs)
    names = [n for n, m in pre.macros.items() if m.params is None and n not in _STD_NAMES
             and n not in _LIB_NAMES and n not in defs]
    lines = {}
    for n in names:
        body = pre.macros[n].body
        if body and body[0].line < src.lines:
            lines[n] = src.where(body[0].line)
    by_line = {name: _comments(text) for name, text in zip(src.names, src.raw)}
    comments: dict = {n: by_line[f].get(line) for n, (f, line) in lines.items()
                      if by_line[f].get(line)}
    comments[""] = [m[1] for text in src.raw for m in re.finditer(r"/\*(.*?)\*/", text, re.S)]
    folded = _fold_all(src, names, defs, "arm", lines)
    defined = {n for n in names if pre.macros[n].body}
    if vendor is None:
        counts = {v: len(set(f({}, {})["reads"]) & defined) for v, f in decoders.items()}
        best = max(counts.values())
        if best == 0:
            raise InputError("files", code="audit_no_vendor",
                             names=", ".join(n for n, _ in files))
        vendor = next(v for v, c in counts.items() if c == best)
    dec = decoders[vendor]
    target = dec({}, {})["target"]
    if target != "arm":
        folded = _fold_all(src, names, defs, target, lines)
    reads = dec({}, {})["reads"]
    for n in reads:
        f = folded.get(n)
        if f is not None and "error" in f and pre.macros[n].body:
            file, line = lines.get(n, (src.names[-1], 0))
            raise InputError("files", code="audit_define", file=file, line=line, name=n,
                             why=f["error"])
    # a -D value is the decoder's too (ST leaves SPEED_UNIT to its library), not a file's macro
    given = _fold_all(src, list(defs), defs, target, {}) if defs else {}
    values = {n: f["value"] for d in (given, folded) for n, f in d.items()
              if f["value"] is not None}
    try:
        result = dec(values, comments)
    except (ArithmeticError, ValueError) as e:
        # a decoder's formula on numbers that make no motor (a zero scale, a negative root):
        # the header is at fault, and the reply says so rather than a number
        raise InputError("files", code="audit_values", vendor={"vendor": vendor},
                         why=type(e).__name__) from None
    macros = {}
    for n, d in result["macros"].items():
        if n not in folded:
            continue  # given by -D, not by a file
        f = folded[n]
        file, line = lines.get(n, ("", 0))
        macros[n] = {"value": f["value"], "type": f["type"], **d,
                     "source": f"{file}:{line}", "expansion": f["expansion"]}
    findings = [_finding(*c) for c in result["checks"]]
    for n in macros:
        if "conversion" in folded[n]["flags"] or "overflow" in folded[n]["flags"]:
            findings.append(_finding("error", "overflow", [n], {
                "macro": n, "value": folded[n]["value"], "ideal": folded[n]["expansion"],
                "ctype": folded[n]["type"]}))
    design = result["design"]
    design["current_loop"] = design.get("current_loop") or {}
    findings += _margins(design)
    design.setdefault("assumed", [])
    design["missing"] = [f"{sec}.{k}" for sec, keys in _REQUIRED for k in keys
                         if k not in design.get("input", {}).get(sec, {})]
    undefined, accidental = _undefined_if(src, pre.macros, folded)
    if undefined:
        findings.insert(0, _finding("warning" if accidental else "note", "if_undefined", [],
                                    {"names": ", ".join(undefined)},
                                    "give the file that defines them, or -D NAME=VALUE",
                                    words=None if accidental else "if_undefined_unused"))
    other = {n: {"value": f["value"], "source": "{}:{}".format(*lines[n])}
             for n, f in folded.items() if n not in macros and n in lines
             and f["value"] is not None}
    unknown = {n: f["unknown"] for n, f in folded.items() if f["unknown"]}
    return {"profile": vendor, "target": target, "files": [n for n, _ in ordered],
            "unresolved": list(pre.unresolved), "macros": macros, "other": other,
            "unknown": unknown, "design": design, "findings": findings}
