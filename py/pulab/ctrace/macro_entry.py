"""A function-like macro run as the entry, as the firmware invokes it.

TI's math blocks are macros over a struct object (``#define CLARKE_MACRO(v) v.Alpha = v.As;
…``), invoked as ``CLARKE_MACRO(clarke1);``.  Run as the entry, each macro parameter becomes
an object of that name at file scope and one call ``NAME(v, …);`` is the entry's body, so the
fields the expansion reads are inputs named ``v.FIELD`` and ``vars`` holds them after.

A parameter's type is the struct the pasted code defines whose fields cover every
``v.FIELD`` (or ``v->FIELD``, then the macro is given ``&v``) the macro's own text uses;
``NAME(TYPE, …)`` names the types instead (one per parameter, ``-`` to infer that one).

Examples
--------
>>> from pulab.ctrace.parser import parse
>>> code = "typedef struct { int a; int b; } AB;\\n#define SWAP(v) v.a = v.b;"
>>> print(wrapper(parse(code), "SWAP").text.strip())
AB v; void __entry_SWAP(void) { SWAP(v); }
>>> wrapper(parse(code), "SWAP(long)").params
[('v', 'long', False)]
"""

from __future__ import annotations

import re

from ..schema.errors import InputError
from .parser import Decl, Program, StructDef

__all__ = ["wrapper", "entry_macros", "split_entry", "MacroEntry"]

_ENTRY = re.compile(r"\s*([A-Za-z_]\w*)\s*(?:\(([^()]*)\))?\s*\Z")
_TYPE = re.compile(r"(?:struct\s+)?[A-Za-z_]\w*|-\Z")
_ASSIGN = frozenset({"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=",
                     "++", "--"})


class MacroEntry:
    """The text that runs macro ``name`` (appended to the code), the function it defines
    (``function``) and per parameter (name, type spelling, passed by address)."""

    __slots__ = ("name", "function", "text", "params")

    def __init__(self, name: str, function: str, text: str, params: list) -> None:
        self.name, self.function, self.text, self.params = name, function, text, params


def split_entry(entry: str) -> tuple:
    """``"M"`` → ``("M", None)``; ``"M(T1, -)"`` → ``("M", ["T1", "-"])``; None if malformed.

    >>> split_entry(" CLARKE_MACRO ( CLARKE ) "), split_entry("f"), split_entry("f(")
    (('CLARKE_MACRO', ['CLARKE']), ('f', None), None)
    """
    m = _ENTRY.match(entry)
    if m is None:
        return None
    if m[2] is None:
        return m[1], None
    types = [" ".join(t.split()) for t in m[2].split(",")]
    if not all(_TYPE.fullmatch(t) for t in types):
        return None
    return m[1], types


def entry_macros(program: Program) -> list:
    """The function-like macros of ``program`` that can run as an entry: those with
    parameters whose text assigns something (a statement macro, not an expression helper)."""
    return [name for name, mac in program.macros.items()
            if mac.params and any(t.kind == "op" and t.text in _ASSIGN for t in mac.body)]


def _struct_types(program: Program) -> dict:
    """Struct types the code defines: spelling → field names (one spelling per struct, the
    first typedef name, else ``struct TAG``)."""
    seen: dict = {}
    for name, desc in program.aliases.items():
        if isinstance(desc, StructDef) and desc.fields is not None and id(desc) not in seen:
            seen[id(desc)] = (name, desc)
    return {name: {f[0] for f in desc.fields} for name, desc in seen.values()}


def _uses(mac, param: str) -> tuple:
    """The fields ``param.FIELD`` / ``param->FIELD`` the macro's text uses, and whether any
    use is through ``->``."""
    fields, arrow, other = set(), False, False
    body = mac.body
    for i, t in enumerate(body):
        if t.kind != "name" or t.text != param:
            continue
        if i + 2 < len(body) and body[i + 1].text in (".", "->") and body[i + 2].kind == "name":
            fields.add(body[i + 2].text)
            arrow = arrow or body[i + 1].text == "->"
        else:
            other = True
    return fields, arrow, other


def wrapper(program: Program, entry: str) -> MacroEntry | None:
    """The text that runs the function-like macro ``entry`` names (``NAME`` or
    ``NAME(TYPE, …)``), or None when ``entry`` names no function-like macro of ``program``.

    Raises
    ------
    InputError
        Field ``entry``: a parameter's type cannot be inferred (none or several structs fit,
        or the macro does not use it as ``v.FIELD``), the types given do not match the
        parameters, or a parameter's name is already a file-scope name of the code.
    """
    parts = split_entry(entry)
    if parts is None:
        return None
    name, given = parts
    mac = program.macros.get(name)
    if mac is None or mac.params is None or name in program.functions:
        return None
    params = [p for p in mac.params if p != "__VA_ARGS__"]
    if given is not None and len(given) != len(params):
        raise InputError("entry", code="trace_macro_arity", name=name, n=len(params),
                         given=len(given), params=", ".join(params))
    structs = _struct_types(program)
    taken = {var.name for s in program.statements if isinstance(s, Decl)
             for var, _, _ in s.items} | set(program.functions)
    out = []
    for k, p in enumerate(params):
        if p in taken:
            raise InputError("entry", code="trace_macro_param_taken", name=name, param=p)
        fields, arrow, other = _uses(mac, p)
        t = given[k] if given is not None else "-"
        if t == "-":
            example = f"{name}({', '.join('TYPE' if j == k else '-' for j in range(len(params)))})"
            if not fields:
                raise InputError("entry", code="trace_macro_untyped", name=name, param=p,
                                 example=example)
            fit = [s for s, have in structs.items() if fields <= have]
            if len(fit) != 1:
                raise InputError("entry", code="trace_macro_no_type" if not fit else
                                 "trace_macro_many_types", name=name, param=p,
                                 fields=", ".join(f"{p}.{f}" for f in sorted(fields)),
                                 known=", ".join(fit or structs) or "none", example=example)
            t = fit[0]
        out.append((p, t, arrow and not other))
    function = f"__entry_{name}"
    decls = " ".join(f"{t} {p};" for p, t, _ in out)
    args = ", ".join(("&" if by_address else "") + p for p, _, by_address in out)
    text = f"\n{decls} void {function}(void) {{ {name}({args}); }}\n"
    return MacroEntry(name, function, text, out)
