"""The shapes of pulab's JSON output, declared once: the TypeScript the page reads and a checker.

The report (:mod:`.report_shapes`) and the API's replies (:mod:`.api_shapes`) are declared as
lists of named shapes built from the small type language below.  From them the build writes
``web/src/generated/report-types.ts`` and ``web/src/generated/api-types.ts`` (:func:`typescript`),
and the tests check real outputs against them (:func:`problems`), so the page's types cannot
drift from what pulab returns.

The type language mirrors the TypeScript it writes: :data:`NUM`, :data:`STR`, :data:`BOOL`,
:data:`NULL`, :data:`UNKNOWN`, :class:`Lit` (string or ``true`` literals), :class:`Arr`,
:class:`Tup`, :class:`Rec` (``Record<K, V>``), :class:`Or`, :class:`And`, :class:`Obj` (an
object; a field name ending in ``?`` is optional) and :class:`Ref` (a declared or imported
name).  A named shape is an :class:`Interface`, an :class:`Alias` or a :class:`Const`.

Examples
--------
>>> point = Interface("Point", [("x", NUM), ("y?", Or(NUM, NULL))], doc="A point.")
>>> print(point.ts())
/** A point. */
export interface Point {
  x: number;
  y?: number | null;
}
>>> problems({"x": 1, "y": "a", "z": 0}, Ref("Point"), {"Point": point})
['$.y: expected number | null, got string', '$: extra key z']
"""

from __future__ import annotations

import json

#: The longest line an inline object is written on before it is broken into one member a line.
WIDTH = 110

#: A problem's kind that is not a type error: a key the declaration does not name.
EXTRA = "extra key"


class Type:
    """A type expression: its TypeScript text and a structural check of a JSON value."""

    #: Whether :meth:`ts` needs parentheses inside an array or an intersection.
    compound = False

    def ts(self, indent: str = "") -> str:
        """The TypeScript text of the type (``indent``: that of the line it starts on)."""
        raise NotImplementedError

    def check(self, value, path: str, names: dict, out: list) -> None:
        """Append to ``out`` every problem of ``value`` (at JSON path ``path``) against the type;
        ``names`` maps each declared name to its shape."""
        raise NotImplementedError

    def fields(self, names: dict):
        """The object fields the type declares (name → (type, optional)) and its type for other
        keys (None: none allowed; ``UNKNOWN`` when open), or None when it is not an object."""
        return None

    def wrapped(self, indent: str = "") -> str:
        """:meth:`ts` in parentheses when it is a union."""
        return f"({self.ts(indent)})" if self.compound else self.ts(indent)


def _kind(value) -> str:
    """The JSON type name of a parsed value."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "boolean"
    if isinstance(value, (int, float)):
        return "number"
    if isinstance(value, str):
        return "string"
    return "array" if isinstance(value, list) else "object"


class Prim(Type):
    """A JSON primitive (``number``, ``string``, ``boolean``, ``null``) or ``unknown``."""

    def __init__(self, name: str):
        self.name = name

    def ts(self, indent=""):
        return self.name

    def check(self, value, path, names, out):
        if self.name != "unknown" and _kind(value) != self.name:
            out.append(f"{path}: expected {self.name}, got {_kind(value)}")


NUM, STR, BOOL, NULL, UNKNOWN = (Prim(n) for n in ("number", "string", "boolean", "null", "unknown"))


class Never(Type):
    """TypeScript's ``never`` (``Record<string, never>``: an empty object) or ``undefined`` (a
    field that is never present)."""

    def __init__(self, name: str = "never"):
        self.name = name

    def ts(self, indent=""):
        return self.name

    def check(self, value, path, names, out):
        out.append(f"{path}: expected {self.name}, got {_kind(value)}")


class Lit(Type):
    """One of the literal values (strings, ``True`` or ``False``)."""

    def __init__(self, *values):
        self.values = values
        self.compound = len(values) > 1

    def ts(self, indent=""):
        return " | ".join(json.dumps(v) if isinstance(v, bool) else f"'{v}'" for v in self.values)

    def check(self, value, path, names, out):
        if not any(value is v if isinstance(v, bool) else value == v for v in self.values):
            out.append(f"{path}: expected {self.ts()}, got {json.dumps(value)[:40]}")


class Arr(Type):
    """An array of one type."""

    def __init__(self, item: Type):
        self.item = item

    def ts(self, indent=""):
        return self.item.wrapped(indent) + "[]"

    def check(self, value, path, names, out):
        if not isinstance(value, list):
            out.append(f"{path}: expected array, got {_kind(value)}")
            return
        for i, v in enumerate(value):
            self.item.check(v, f"{path}[{i}]", names, out)


class Tup(Type):
    """A fixed-length array (a TypeScript tuple)."""

    def __init__(self, *items: Type):
        self.items = items

    def ts(self, indent=""):
        return "[" + ", ".join(t.ts(indent) for t in self.items) + "]"

    def check(self, value, path, names, out):
        if not isinstance(value, list) or len(value) != len(self.items):
            out.append(f"{path}: expected a {len(self.items)}-tuple, got {_kind(value)}")
            return
        for i, (t, v) in enumerate(zip(self.items, value)):
            t.check(v, f"{path}[{i}]", names, out)


class Rec(Type):
    """``Record<K, V>``: an object whose keys are ``K`` (:data:`STR` or literals) and values ``V``;
    ``partial``: ``Partial<Record<K, V>>``."""

    def __init__(self, key: Type, value: Type, partial: bool = False):
        self.key, self.value, self.partial = key, value, partial

    def ts(self, indent=""):
        text = f"Record<{self.key.ts()}, {self.value.ts(indent)}>"
        return f"Partial<{text}>" if self.partial else text

    def fields(self, names):
        key = _resolve(self.key, names)
        if isinstance(key, Lit):
            return {k: (self.value, self.partial) for k in key.values}, None
        return {}, self.value

    def check(self, value, path, names, out):
        _check_object(value, path, names, out, *self.fields(names))


class Obj(Type):
    """An object type: ``(name, type)`` or ``(name, type, doc)`` fields (``name?``: optional)
    and, with ``index``, the type of any other key (``[k: string]: T``)."""

    def __init__(self, *fields, index: Type | None = None):
        self.items = [(f[0].rstrip("?"), f[1], f[0].endswith("?"), f[2] if len(f) > 2 else None)
                      for f in fields]
        self.index = index

    def members(self, indent: str) -> list:
        """The TypeScript lines of the members (a doc comment on a line of its own), at
        ``indent``."""
        lines = [f"[k: string]: {self.index.ts(indent)};"] if self.index else []
        for n, t, opt, doc in self.items:
            lines += [f"/** {doc} */"] if doc else []
            lines.append(f"{_key(n)}{'?' if opt else ''}: {t.ts(indent)};")
        return lines

    def ts(self, indent=""):
        flat = "{ " + " ".join(self.members(indent)).rstrip(";") + " }"
        if len(indent) + len(flat) <= WIDTH and not any(doc for *_, doc in self.items):
            return flat
        inner = indent + "  "
        return "{\n" + "".join(f"{inner}{m}\n" for m in self.members(inner)) + indent + "}"

    def fields(self, names):
        return {n: (t, opt) for n, t, opt, _ in self.items}, self.index

    def check(self, value, path, names, out):
        _check_object(value, path, names, out, *self.fields(names))


def _key(name: str) -> str:
    """A property name as TypeScript writes it (quoted unless an identifier)."""
    return name if name.replace("_", "a").isalnum() and not name[0].isdigit() else f"'{name}'"


class Or(Type):
    """A union: the value is one of the types."""

    compound = True

    def __init__(self, *types: Type):
        self.types = types

    def ts(self, indent=""):
        return " | ".join(t.wrapped(indent) if isinstance(t, And) else t.ts(indent) for t in self.types)

    def check(self, value, path, names, out):
        tries = []
        for t in self.types:
            found = []
            t.check(value, path, names, found)
            if not [p for p in found if EXTRA not in p]:  # a member's extra keys do not rule it out
                out.extend(found)
                return
            tries.append(found)
        if all(p.endswith(f"got {_kind(value)}") and p.startswith(path + ":") for f in tries for p in f):
            out.append(f"{path}: expected {self.ts()}, got {_kind(value)}")
        else:  # an object of the wrong member: the member that came closest says why
            out.extend(min(tries, key=len))


class And(Type):
    """An intersection of object types: every member's fields; a ``Record<string, V>`` member
    (or an index signature) types the keys no member names."""

    compound = True

    def __init__(self, *types: Type):
        self.types = types

    def ts(self, indent=""):
        return " & ".join(t.wrapped(indent) for t in self.types)

    def fields(self, names):
        named, other = {}, None
        for t in self.types:
            # a member that is not an object here (a type the page declares) leaves it open
            f, idx = _resolve(t, names).fields(names) or ({}, UNKNOWN)
            named.update(f)
            other = other or idx
        return named, other

    def check(self, value, path, names, out):
        _check_object(value, path, names, out, *self.fields(names))


class Ref(Type):
    """A name: a shape declared in the same lists, or (``module`` given) one imported from a
    module of the page, checked as ``like``."""

    def __init__(self, name: str, module: str | None = None, like: Type = UNKNOWN):
        self.name, self.module, self.like = name, module, like

    def ts(self, indent=""):
        return self.name

    def check(self, value, path, names, out):
        _resolve(self, names).check(value, path, names, out)

    def fields(self, names):
        return _resolve(self, names).fields(names)


def _resolve(t: Type, names: dict) -> Type:
    """The type a :class:`Ref` names (other types: themselves)."""
    while isinstance(t, Ref):
        t = t.like if t.module else names[t.name].type
    return t


def _check_object(value, path, names, out, named: dict, other) -> None:
    """Check an object: each required field present, each present field of its type, other keys
    of ``other``'s type (or reported as :data:`EXTRA` when ``other`` is None)."""
    if not isinstance(value, dict):
        out.append(f"{path}: expected object, got {_kind(value)}")
        return
    for name, (t, optional) in named.items():
        if name in value:
            t.check(value[name], f"{path}.{name}", names, out)
        elif not optional:
            out.append(f"{path}: missing {name}")
    for name in value:
        if name not in named:
            if other is None:
                out.append(f"{path}: {EXTRA} {name}")
            else:
                other.check(value[name], f"{path}.{name}", names, out)


class Shape:
    """A named, exported declaration (``doc``: its comment, one sentence or more)."""

    type: Type

    def __init__(self, name: str, doc: str | None = None):
        self.name, self.doc = name, doc

    def comment(self) -> str:
        """The declaration's doc comment line(s), or nothing."""
        return f"/** {self.doc} */\n" if self.doc else ""


class Interface(Shape):
    """``export interface NAME [extends BASE] { fields }``; ``index``: the type of other keys."""

    def __init__(self, name, fields, doc=None, extends=None, index=None):
        super().__init__(name, doc)
        self.obj = Obj(*fields, index=index)
        self.extends = extends
        self.type = And(Ref(extends), self.obj) if extends else self.obj

    def ts(self, indent=""):
        base = f" extends {self.extends}" if self.extends else ""
        body = "".join(f"  {m}\n" for m in self.obj.members("  "))
        return f"{self.comment()}export interface {self.name}{base} {{\n{body}}}"


class Alias(Shape):
    """``export type NAME = type``."""

    def __init__(self, name, type_, doc=None):
        super().__init__(name, doc)
        self.type = type_

    def ts(self, indent=""):
        return f"{self.comment()}export type {self.name} = {self.type.ts()};"


class Const(Shape):
    """``export const NAME = [...] as const``: a list of strings the page iterates over."""

    type = UNKNOWN

    def __init__(self, name, values, doc=None):
        super().__init__(name, doc)
        self.values = values

    def ts(self, indent=""):
        items = ", ".join(f"'{v}'" for v in self.values)
        return f"{self.comment()}export const {self.name} = [{items}] as const;"


def _refs(t, seen: list) -> None:
    """Collect the imported :class:`Ref` of a type (depth first)."""
    if isinstance(t, Ref) and t.module and t not in seen:
        seen.append(t)
    for attr in ("item", "key", "value", "index", "type", "obj"):
        sub = getattr(t, attr, None)
        if isinstance(sub, (Type, Shape)):
            _refs(sub, seen)
    for sub in getattr(t, "items", ()) or ():
        _refs(sub[1] if isinstance(sub, tuple) else sub, seen)
    for sub in getattr(t, "types", ()):
        _refs(sub, seen)


def typescript(shapes: list, header: str) -> str:
    """The TypeScript module declaring ``shapes`` (with the imports their :class:`Ref` name).

    Parameters
    ----------
    shapes : list of Shape
        The declarations, in the order to write them.
    header : str
        The module's opening comment (what it is), without comment markers.

    Returns
    -------
    str
        The module's text, ending in a newline.

    Examples
    --------
    >>> print(typescript([Alias("Pair", Tup(NUM, NUM))], "Two numbers."), end="")
    // Generated by pulab.schema.shapes from py/pulab/schema: do not edit (npm run build rewrites it).
    // Two numbers.
    export type Pair = [number, number];
    """
    imports: list = []
    for s in shapes:
        _refs(s, imports)
    by_module: dict = {}
    for r in imports:
        by_module.setdefault(r.module, set()).add(r.name)
    lines = ["// Generated by pulab.schema.shapes from py/pulab/schema: do not edit (npm run build rewrites it)."]
    lines += [f"// {line}" for line in header.splitlines()]
    lines += [f"import type {{ {', '.join(sorted(n))} }} from '{m}';" for m, n in sorted(by_module.items())]
    return "\n".join(lines + [s.ts() for s in shapes]) + "\n"


def problems(value, t: Type, names: dict, path: str = "$") -> list:
    """Every way a parsed JSON value differs from a declared type.

    Parameters
    ----------
    value : object
        The parsed JSON (dict, list, str, int, float, bool or None).
    t : Type
        The type to check against (a :class:`Ref` to a declared shape, usually).
    names : dict
        Declared name → :class:`Shape` (:func:`names_of`).
    path : str, optional
        The JSON path of ``value`` in the messages.

    Returns
    -------
    list of str
        ``"PATH: expected T, got K"``, ``"PATH: missing KEY"`` or ``"PATH: extra key KEY"`` (a key
        of a closed object that the declaration does not name); empty when it conforms.

    Examples
    --------
    >>> problems([1, None], Arr(NUM), {})
    ['$[1]: expected number, got null']
    """
    out: list = []
    t.check(value, path, names, out)
    return out


def names_of(*lists) -> dict:
    """Declared name → shape over declaration lists (:func:`problems` resolves through it).

    Examples
    --------
    >>> sorted(names_of([Alias("A", NUM)], [Alias("B", STR)]))
    ['A', 'B']
    """
    return {s.name: s for lst in lists for s in lst}
