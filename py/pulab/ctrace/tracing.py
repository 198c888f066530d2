"""``trace``: pasted C code, a target and input values in; every intermediate out.

Examples
--------
>>> code = "Uint16 Voltage; Ulong m = (Ulong)Voltage * 10; Uint16 w = Voltage * 10;"
>>> r = trace(code, "c28x", {"Voltage": 6554})
>>> r["vars"]["m"]["value"], r["vars"]["w"]["value"], r["steps"][2]["flags"]
(65540, 4, ['unsigned_wrap'])
>>> trace(code, "arm", {"Voltage": 6554})["steps"][2]["flags"]
['conversion']
"""

from __future__ import annotations

import re

from ..fixedpoint.cint import CType
from .check import ArrT, Checked, PtrT, StructT, check, describe, same_layout
from .evaluate import Evaluator, hex_of
from .errors import TraceError
from .parser import Ptr, parse
from .macro_entry import entry_macros, split_entry, wrapper
from .preprocess import parse_define
from .types import TARGETS
from ..schema.errors import InputError
from ..schema.validate import key_path, shown

__all__ = ["trace", "trace_checked", "compile_code", "run_checked", "rounding_summary",
           "inputs_for", "result_vars", "input_values", "DEFAULT_GLOBAL_Q"]

#: The object a pointer input is given as ``&OBJECT``: a name, its fields and elements.
_OBJECT = re.compile(r"[A-Za-z_]\w*(?:\.[A-Za-z_]\w*|\[\d+\])*")

#: IQmath's GLOBAL_Q when neither the code (``#define GLOBAL_Q``) nor the caller sets one.
DEFAULT_GLOBAL_Q = 24


def _defines(defines) -> dict:
    out = {}
    for i, item in enumerate(defines or ()):
        if not isinstance(item, str):
            raise InputError(f"define[{i}]", code="trace_define_text", got=shown(item))
        try:
            name, value = parse_define(item)
        except TraceError as e:
            reason = e.reason_error()
            raise InputError(f"define[{i}]", code=reason["code"], **reason["params"]) from None
        out[name] = value
    return out


def _undefines(undefines) -> set:
    out = set()
    for i, name in enumerate(undefines or ()):
        if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z_]\w*", name.strip()):
            raise InputError(f"undefine[{i}]", code="trace_undefine_name", got=shown(name))
        out.add(name.strip())
    return out


#: The programs compiled last (see :func:`compile_code`), most recent last.
_COMPILED: dict = {}
#: How many compiled programs are kept.
COMPILED_KEPT = 8


def compile_code(code: str, target: str = "c28x", defines=None,
                 global_q: int | None = None, entry: str | None = None,
                 undefines=None) -> Checked:
    """Parse and type ``code`` for ``target`` (reusable for many input vectors);
    ``defines`` is a list of ``-D`` texts ``NAME[=VALUE]``, made after the target's
    predefined macros (:attr:`~pulab.ctrace.types.Target.predefined`) less the names in
    ``undefines`` (``-U NAME``); ``global_q`` is the Q the
    IQmath conversion macros (``_IQ(0.5)``…) use when the code does not define GLOBAL_Q;
    ``entry`` the function to run (None: the statements outside functions), or a
    function-like macro as ``NAME`` or ``NAME(TYPE, …)`` (see :mod:`~pulab.ctrace.macro_entry`).

    The last :data:`COMPILED_KEPT` programs are kept: the same request again (a page
    re-tracing as the user edits inputs, a sequence's calls) is not parsed or checked again
    (the checked program is never changed by a run).
    """
    try:
        key = (code, target, tuple(defines or ()), tuple(undefines or ()), global_q, entry)
        hash(key)
    except TypeError:  # an unhashable request is refused by _compile
        key = None
    checked = _COMPILED.pop(key, None) if key is not None else None
    if checked is None:
        checked = _compile(code, target, defines, global_q, entry, undefines)
    if key is not None:
        _COMPILED[key] = checked
        while len(_COMPILED) > COMPILED_KEPT:
            del _COMPILED[next(iter(_COMPILED))]
    return checked


def _compile(code, target, defines, global_q, entry, undefines) -> Checked:
    if entry is not None and (not isinstance(entry, str) or split_entry(entry) is None):
        raise InputError("entry", code="trace_entry_name", got=shown(entry))
    if not isinstance(target, str) or target not in TARGETS:
        raise InputError("target", code="not_choice", choices=", ".join(TARGETS), got=shown(target))
    t = TARGETS[target]
    gq = global_q if isinstance(global_q, int) and 1 <= global_q <= 30 else DEFAULT_GLOBAL_Q
    gone = _undefines(undefines)
    defs = {k: v for k, v in t.predefined if k not in gone}
    defs.update(_defines(defines))
    program = parse(code, defines=defs, global_q=gq, target=t)
    if entry is None:
        return check(program, t)
    name = split_entry(entry)[0]
    if name not in program.functions:
        macro = wrapper(program, entry)
        if macro is not None:  # the code again, then the objects and the one invocation
            program = parse(code + macro.text, defines=defs, global_q=gq, target=t)
            f = program.functions.pop(macro.function)
            f.name = name
            program.functions[name] = f
    return check(program, t, name)


def input_values(checked: Checked, inputs: dict, zero_unset: bool = False) -> dict:
    """``inputs`` checked against the code (names, types, ranges; ``&OBJECT`` for a pointer)
    as path → integer (or object path); ``zero_unset`` adds 0 for every input not given.

    >>> checked = compile_code("Uint16 v; Uint16 w; long x = v * w;", "c28x")
    >>> input_values(checked, {"v": "0x10"}, zero_unset=True)
    {'v': 16, 'w': 0}
    """
    out = {}
    for name, value in inputs.items():
        if isinstance(name, str):
            name = name.strip().replace("->", ".")  # p->FIELD names p.FIELD
        field = key_path("set", name)
        sym = checked.symbols.get(name)
        if sym is None and name in checked.pointers:
            out[name] = _pointer_value(checked, field, name, value)
            continue
        if sym is None:
            shown_name = name if field == f"set.{name}" else shown(name)
            raise InputError(field, code="trace_no_variable", name=shown_name)
        if sym.initialized:
            raise InputError(field, code="trace_has_initializer", name=name)
        if isinstance(value, str):
            try:
                value = int(value.strip().replace("_", ""), 0)
            except ValueError:
                raise InputError(field, code="not_integer", got=shown(value)) from None
        if isinstance(value, bool) or not isinstance(value, int):
            raise InputError(field, code="not_integer", got=shown(value))
        t = sym.ctype
        if not t.min <= value <= t.max:
            raise InputError(field, code="trace_value_range", lo=t.min, hi=t.max,
                             type=sym.spelling, got=value)
        out[name] = value
    if zero_unset:  # a pointer has no zero to take: it stays unset (an error where read)
        seeds = {k: v for k, v in out.items() if k in checked.pointers}
        for name in checked.inputs_with(seeds):
            if name not in checked.pointers:
                out.setdefault(name, 0)
    return out


def inputs_for(checked: Checked, inputs: dict) -> list:
    """``checked.inputs`` with the valid pointer inputs among ``inputs`` pointing where
    given (the objects read through them are inputs too): what a page offers fields for,
    also when the run failed."""
    seeds = {}
    for name, value in inputs.items():
        name = name.strip().replace("->", ".") if isinstance(name, str) else name
        if name in checked.pointers:
            try:
                seeds[name] = _pointer_value(checked, "set", name, value)
            except InputError:
                pass
    return checked.inputs_with(seeds)


def _pointer_value(checked: Checked, field: str, name: str, value) -> str:
    """``&OBJECT`` for the pointer input ``name``: the path of an object of the code
    (a global, an entry parameter's object or a field or element of one) whose type is the
    one the pointer points to (any struct or integer for ``void *`` and opaque handles)."""
    ptr, spelling = checked.pointers[name]
    text = "".join(value.split()) if isinstance(value, str) else ""
    path = text[1:].replace("->", ".")
    if not text.startswith("&") or not _OBJECT.fullmatch(path):
        raise InputError(field, code="trace_pointer_syntax", name=name, got=shown(value))
    head = re.match(r"\w+", path)[0]
    params = {p.key for p in checked.entry.params} if checked.entry is not None else set()
    t = None  # a global pointer names no object of its own (a pointer parameter names its)
    if head in checked.heads and (head in params or not isinstance(checked.roots.get(head), PtrT)) \
            and (path in checked.symbols or any(k.startswith((path + ".", path + "["))
                                                for k in checked.symbols)):  # indexes in range
        t = checked.type_at(path)
    if t is None or isinstance(t, PtrT):
        raise InputError(field, code="trace_pointer_no_object", name=name, got=path)
    if isinstance(ptr.to, (CType, StructT)) and not same_layout(t, ptr.to) or \
            isinstance(t, ArrT):
        raise InputError(field, code="trace_pointer_type", name=name, got=path,
                         want=describe(ptr.to), type=describe(t))
    return path


def _meaning(note, value: int) -> dict:
    real = value / 2.0 ** note.q
    d = {"q": note.q, "real": real}
    if note.base is not None:
        d["si"] = real * note.base
        d["unit"] = note.unit
    return d


def run_checked(checked: Checked, inputs: dict, global_q: int | None = None,
                record: bool = True, zero_unset: bool = False) -> Evaluator:
    """Run a compiled program (inputs are validated here; ``zero_unset`` gives the inputs
    not set the value 0); returns the finished :class:`~pulab.ctrace.evaluate.Evaluator`
    (``values``, ``steps``, ``undefined``)."""
    gq = checked.program.global_q or global_q or DEFAULT_GLOBAL_Q
    ev = Evaluator(checked, input_values(checked, inputs or {}, zero_unset), gq, record)
    ev.run()
    return ev


def _pointer_var(program, spelling: str, path: str | None, given: bool) -> dict:
    """A pointer in ``vars``: no integer value, ``points_to`` the object's name (None: null);
    ``type`` the typedef that names the pointer (``PI_Handle``) or the pointee's spelling
    then ``*``."""
    if not isinstance(program.aliases.get(spelling), Ptr):
        spelling += " *"
    return {"type": spelling, "c_type": "pointer", "bits": None, "signed": False,
            "value": None, "hex": None, "input": given, "points_to": path}


def rounding_summary(steps: list) -> dict:
    """Per variable given a statement's result (calls included): how many of its terms
    rounded toward −∞ (``floor``) and toward zero, and the largest ``|lost|`` in LSB.

    >>> r = trace("long x = -5000; long s = x >> 12; long d = x / 4096;", "c28x")
    >>> r["rounding"]["s"], r["rounding"]["d"]["toward_zero"]
    ({'floor': 1, 'toward_zero': 0, 'max_lost': 0.779296875}, 1)
    """
    out: dict = {}

    def walk(items: list) -> None:
        for st in items:
            for t in st.get("terms", ()):
                if "rounding" in t:
                    name = st.get("var") or "(no variable)"
                    d = out.setdefault(name, {"floor": 0, "toward_zero": 0, "max_lost": 0.0})
                    d[t["rounding"]] += 1
                    d["max_lost"] = max(d["max_lost"], abs(t["lost"]))
                if "steps" in t:
                    walk(t["steps"])

    walk(steps)
    return out


def trace(code: str, target: str = "c28x", inputs: dict | None = None,
          global_q: int | None = None, defines=None, entry: str | None = None,
          zero_unset: bool = False, undefines=None) -> dict:
    """Trace C code as ``target``'s compiler computes it.

    Parameters
    ----------
    code : str
        C statements (see :mod:`pulab.ctrace.parser` for the subset).
    target : {'c28x', 'avr', 'msp430', 'arm'}
    inputs : dict, optional
        Variable name → integer (or integer text, ``0x…`` allowed) for variables declared
        without an initializer.
    global_q : int in 1..30, optional
        IQmath's GLOBAL_Q (default 24); ``#define GLOBAL_Q`` in the code wins.
    defines : list of str, optional
        ``NAME[=VALUE]`` definitions made before the code, as a compiler's ``-D`` (after the
        target's predefined macros, :attr:`~pulab.ctrace.types.Target.predefined`).
    undefines : list of str, optional
        Predefined macros to remove, as a compiler's ``-U NAME``.
    entry : str, optional
        The function of the code to run; its integer parameters, the fields of the structs
        its pointer parameters point to (``p.FIELD``), the integers they point to (``*out``)
        and the globals read before written are the inputs.
    zero_unset : bool, optional
        Inputs not given are 0 (else reading one is an error naming every unset input).

    Returns
    -------
    dict
        ``ok``, ``target``, ``global_q``, ``entry``, ``functions`` (those the code defines),
        ``unresolved_includes`` (headers named by
        ``#include`` whose contents are unknown), ``inputs`` (names the code reads before giving
        them a value), ``vars`` (every variable: type, c_type, bits, value, hex, and q,
        real, si, unit when annotated) and ``steps`` (one per executed statement, each
        with ``terms``: every intermediate, in evaluation order).

    Raises
    ------
    TraceError
        Code outside the subset, or a division by zero, naming line and column; a bad
        target, entry, input value or global_q (no position).  It says what the code offers
        instead: ``functions`` and ``macros`` when the entry is at fault and the code parses,
        and ``inputs``, ``functions`` and ``macros`` once the code compiled.
    """
    try:
        checked = compile_code(code, target, defines, global_q, entry, undefines)
    except InputError as e:
        err = TraceError.of(e)
        if e.field == "entry" and isinstance(code, str):
            try:  # the code parses: offer its functions (and macros) so the user can pick one
                program = parse(code)
                err.functions, err.macros = list(program.functions), entry_macros(program)
            except InputError:
                pass
        raise err
    try:
        return trace_checked(checked, inputs, global_q, zero_unset)
    except InputError as e:
        raise run_error(e, checked, inputs) from None


def run_error(e: InputError, checked: Checked, inputs) -> TraceError:
    """A run-time error of checked code, with what the user can set and call beside it."""
    err = TraceError.of(e)
    err.inputs = inputs_for(checked, inputs if isinstance(inputs, dict) else {})
    err.functions = [f for f in checked.functions if f not in checked.program.macros]
    err.macros = entry_macros(checked.program)
    return err


def trace_checked(checked: Checked, inputs: dict | None = None,
                  global_q: int | None = None, zero_unset: bool = False) -> dict:
    """:func:`trace` for code already compiled by :func:`compile_code`."""
    if global_q is not None and (isinstance(global_q, bool) or not isinstance(global_q, int)
                                 or not 1 <= global_q <= 30):
        raise InputError("global_q", code="integer_range", lo=1, hi=30, got=shown(global_q))
    inputs = inputs or {}
    ev = run_checked(checked, inputs, global_q, zero_unset=zero_unset)
    steps = ev.steps
    given = {k.strip().replace("->", ".") if isinstance(k, str) else k for k in inputs}
    if zero_unset:
        given |= set(ev.names)
    gq = checked.program.global_q or global_q or DEFAULT_GLOBAL_Q
    notes = {k: n for k, n in checked.program.notes.items() if n.q is not None}  # not "@q auto"
    for s in steps:
        if s["var"] in notes:
            s.update(_meaning(notes[s["var"]], s["value"]))
    return {"ok": True, "target": checked.target.name, "global_q": gq,
            "entry": checked.entry.name if checked.entry is not None else None,
            "rounding": rounding_summary(steps),
            "functions": [f for f in checked.functions if f not in checked.program.macros],
            "macros": entry_macros(checked.program),
            "unresolved_includes": list(checked.program.unresolved),
            "inputs": ev.names, "vars": result_vars(checked, ev, given), "steps": steps}


def result_vars(checked: Checked, ev: Evaluator, given: set, keep=frozenset()) -> dict:
    """``vars`` of a finished run: every variable the run read, wrote or was given (the
    names in ``given``) or named in ``keep`` (a sequence's state), pointers given and the
    entry's result."""
    values = ev.values
    notes = {k: n for k, n in checked.program.notes.items() if n.q is not None}
    out_vars = {}
    entry = checked.entry
    for name, sym in checked.symbols.items():
        if entry is not None and name not in given and name not in ev.written and \
                name not in checked.inputs and name not in keep:
            continue  # a field the function neither reads nor writes
        v = values[name]
        d = {"type": sym.spelling, "c_type": sym.ctype.name, "bits": sym.ctype.bits,
             "signed": sym.ctype.signed, "value": v,
             "hex": hex_of(v, sym.ctype.bits) if v is not None else None,
             "input": name in given}
        if name in notes and v is not None:
            d.update(_meaning(notes[name], v))
        elif name in checked.program.notes and checked.program.notes[name].q is None:
            # "// @q NAME auto": the code proof proposes its Q
            d["q_auto"] = True
        out_vars[name] = d
    pointers = checked.pointers
    for name in pointers:  # pointer inputs given: what they point to after the call
        if name in given:
            out_vars[name] = _pointer_var(checked.program, pointers[name][1],
                                          values.get(name), True)
    if entry is not None and isinstance(entry.ret, PtrT):
        out_vars["return"] = _pointer_var(checked.program, entry.ret_spelling,
                                        values.get("return"), False)
    if entry is not None and isinstance(entry.ret, CType):
        v = values.get("return")
        out_vars["return"] = {"type": entry.ret_spelling, "c_type": entry.ret.name,
                              "bits": entry.ret.bits, "signed": entry.ret.signed, "value": v,
                              "hex": hex_of(v, entry.ret.bits), "input": False}
    return out_vars
