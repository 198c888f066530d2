"""Static typing of a parsed program for one target (C99 6.3, 6.5), and its inputs.

Every expression node gets ``ctype``: the C type of its value after the integer
promotions and the usual arithmetic conversions (a :class:`~pulab.fixedpoint.cint.CType`
for integers, or a :class:`StructT`, :class:`PtrT`, :class:`ArrT`, :data:`VOID`);
binary operators that convert their operands first also get ``operand_type``.  Types are
known before any value, so ``c ? a : b`` has its type even when a branch is never
evaluated.

Every object has a *path*: its name for the code's globals and the entry function's
parameters and locals (``p.hKpGain`` for a field of the struct ``p`` points to, ``*out``
for the integer ``out`` points to, ``tab[2]`` for an element), ``f:x`` for a local of
another function ``f``.  The *inputs* are the paths the code may read before giving them
a value on some path through it (definite assignment: an ``if`` assigns what both
branches assign), following pointers from the entry function's parameters into calls.

Examples
--------
>>> from .parser import parse
>>> from .types import TARGETS
>>> prog = parse("Uint16 v; long x = v * 10;")
>>> checked = check(prog, TARGETS["c28x"])
>>> checked.inputs, prog.statements[1].items[0][1].ctype.name
(['v'], 'unsigned int')
>>> code = "typedef struct { int k; long i; } PI; int f(PI *p, int e) { if (e > 0) p->i = e; " \\
...        "return p->i + p->k; }"
>>> check(parse(code), TARGETS["c28x"], "f").inputs
['e', 'p.i', 'p.k']
"""

from __future__ import annotations

import re

from ..fixedpoint.cint import CType
from .errors import TraceError
from .lexer import quoted
from .macro_entry import entry_macros
from .parser import (Arr, Assign, Binary, Block, Call, Cast, Cond, Decl, ExprStmt, FNum, FuncDef,
                     If, IncDec, Index, InitList, Jump, Label, Logical, Loop, Member, Num,
                     NodeVisitor, Program, Ptr, Return, StructDef, Switch, Unary, Unsupported,
                     Var, constant_value, float_to_int)
from ..schema.errors import InputError
from .types import Target, common_type, promote

__all__ = ["check", "Checked", "Symbol", "StructT", "PtrT", "ArrT", "VOID", "leaves", "pointee",
           "MAX_ELEMENTS", "MAX_ANALYSIS"]

#: A name spelled as C macros are (upper case, digits, underscores).
_MACRO_NAME = re.compile(r"_*[A-Z][A-Z0-9_]*")
#: Larger arrays (and objects with more integers) are refused.
MAX_ELEMENTS = 4096
#: The inputs analysis follows calls into their bodies; beyond this many visited nodes the
#: code is refused (a call tree that would take too long to trace anyway).
MAX_ANALYSIS = 200_000


class StructT:
    """A struct type: ``fields`` maps a name to (type, spelling)."""

    __slots__ = ("name", "fields")

    def __init__(self, name: str) -> None:
        self.name, self.fields = name, {}


class PtrT:
    """Pointer to ``to``; ``n`` the length of the array a parameter ``T p[N]`` points into."""

    __slots__ = ("to", "n")

    def __init__(self, to, n: int | None = None) -> None:
        self.to, self.n = to, n

    def __eq__(self, other) -> bool:
        return isinstance(other, PtrT) and _same(self.to, other.to)

    def __hash__(self) -> int:
        return 1


class ArrT:
    __slots__ = ("of", "n")

    def __init__(self, of, n: int) -> None:
        self.of, self.n = of, n


class _Void:
    name = "void"

    def __repr__(self) -> str:
        return "void"


VOID = _Void()


def _same(a, b) -> bool:
    if isinstance(a, CType) and isinstance(b, CType):
        return a.bits == b.bits and a.signed == b.signed
    if isinstance(a, PtrT) and isinstance(b, PtrT):
        return _same(a.to, b.to)
    if isinstance(a, ArrT) and isinstance(b, ArrT):
        return _same(a.of, b.of)
    return a is b


def same_layout(a, b) -> bool:
    """Whether objects of types ``a`` and ``b`` are the same memory read the same way: equal
    integer types, and structs, arrays and pointers whose parts match field by field in order,
    names included (a pointer cast between them views the same object by the same paths)."""
    if a is b:
        return True
    if isinstance(a, StructT) and isinstance(b, StructT):
        fa, fb = list(a.fields.items()), list(b.fields.items())
        return len(fa) == len(fb) and all(x[0] == y[0] and same_layout(x[1][0], y[1][0])
                                          for x, y in zip(fa, fb))
    if isinstance(a, ArrT) and isinstance(b, ArrT):
        return a.n == b.n and same_layout(a.of, b.of)
    if isinstance(a, PtrT) and isinstance(b, PtrT):
        return a.to is VOID or b.to is VOID or same_layout(a.to, b.to)
    return _same(a, b)


def describe(t) -> str:
    """A type as C spells it, for messages."""
    if isinstance(t, StructT):
        return f"struct {t.name}"
    if isinstance(t, PtrT):
        return describe(t.to) + " *"
    if isinstance(t, ArrT):
        return f"{describe(t.of)}[{t.n}]"
    return t.name


def _accepts(t, vt) -> bool:
    """Whether a value of type ``vt`` may initialize an object of type ``t`` or be passed
    for a parameter of it: any integer for an integer, else the same type (arrays decay)."""
    if isinstance(t, PtrT) and t.to is VOID and t.n is None:  # any object pointer to void *
        return isinstance(_decay(vt), PtrT)
    return isinstance(vt, CType) if isinstance(t, CType) else _same(t, _decay(vt))


def leaves(path: str, t, spelling: str = "") -> list:
    """The integers (and pointers) an object of type ``t`` at ``path`` holds:
    a list of (path, type, spelling)."""
    if isinstance(t, StructT):
        return [leaf for name, (ft, sp) in t.fields.items()
                for leaf in leaves(f"{path}.{name}", ft, sp)]
    if isinstance(t, ArrT):
        return [leaf for i in range(t.n) for leaf in leaves(f"{path}[{i}]", t.of, spelling)]
    return [(path, t, spelling)]


class Symbol:
    """A declared object: its spelling, type, whether it has an initializer, and its path
    (``key``)."""

    __slots__ = ("name", "spelling", "ctype", "initialized", "line", "column", "key")

    def __init__(self, name, spelling, ctype, initialized, line, column, key=None) -> None:
        self.name, self.spelling, self.ctype, self.initialized = name, spelling, ctype, \
            initialized
        self.line, self.column = line, column
        self.key = name if key is None else key


class Function:
    """A checked function: its FuncDef, parameter symbols, return type."""

    __slots__ = ("name", "node", "params", "ret", "ret_spelling", "prefix", "scope", "calls")

    def __init__(self, node: FuncDef, prefix: str) -> None:
        self.name, self.node, self.prefix = node.name, node, prefix
        self.params: list = []
        self.ret = VOID
        self.ret_spelling = node.ret_spelling
        self.calls: set = set()  # names of the functions of the code it calls


class Checked:
    """A typed program: ``symbols`` (path → Symbol of every integer the user can name, in
    declaration order), ``inputs``, ``functions`` (name → Function), ``entry`` (Function or
    None)."""

    __slots__ = ("program", "target", "symbols", "inputs", "functions", "entry", "objects",
                 "roots", "pointees", "pointers", "heads", "analyse", "_seeded")

    def __init__(self, program: Program, target: Target, symbols: dict, inputs: list,
                 functions: dict | None = None, entry=None, objects: dict | None = None
                 ) -> None:
        self.program, self.target, self.symbols, self.inputs = program, target, symbols, inputs
        self.functions, self.entry = functions or {}, entry
        #: path of every array object -> its length (pointer arithmetic stays inside it)
        self.objects = objects or {}
        #: key of every declared object -> its type (a pointer parameter: what it points to)
        self.roots: dict = {}
        #: pointer field of the entry's objects -> the object it points to (see :func:`linked`)
        self.pointees: dict = {}
        #: pointer the user may set (a field of the entry's objects, a global without
        #: initializer) -> (its type, its spelling)
        self.pointers: dict = {}
        #: keys of the objects a pointer input may point into: globals, entry parameters
        self.heads: set = set()
        #: pointer inputs' paths -> the inputs as they read (see :meth:`inputs_with`)
        self.analyse = lambda seeds: self.inputs
        self._seeded: dict = {}

    def inputs_with(self, seeds: dict) -> list:
        """The inputs when the pointer inputs ``seeds`` (path -> the object's path) point
        where given: the objects read through them become inputs too."""
        key = tuple(sorted(seeds.items()))
        if not key:
            return self.inputs
        if key not in self._seeded:
            self._seeded[key] = self.analyse(seeds)
        return self._seeded[key]

    def type_at(self, path: str):
        """The type of the object at ``path`` (``obj.f[2].g``), or None if unknown."""
        head = re.match(r"[^.\[]+", path)[0]
        t = self.roots.get(head)
        if isinstance(t, PtrT):
            t = t.to if t.n is None else ArrT(t.to, t.n)
        elif t is None and head.startswith("*"):  # the integer a pointer parameter points to
            t = self.roots.get(head[1:])
            t = t.to if isinstance(t, PtrT) and t.n is None else None
        for part in re.findall(r"\.(\w+)|\[(\d+)\]", path[len(head):]):
            if isinstance(t, PtrT):  # a pointer field's own object (see linked)
                t = t.to
            if part[0] and isinstance(t, StructT) and part[0] in t.fields:
                t = t.fields[part[0]][0]
            elif part[1] and isinstance(t, ArrT):
                t = t.of
            else:
                return None
        return t


def _type_of(target: Target, spelling: str, node) -> object:
    try:
        return target.type_named(spelling)
    except KeyError:
        raise TraceError(node.line, node.column, code="trace_no_type_on_target", name=spelling,
                         target=target.name) from None


def _flat_name(e) -> str | None:
    """``a.b->c`` as one dotted name, when ``e`` is a chain of names and fields."""
    if isinstance(e, Var):
        return e.name
    if isinstance(e, Member):
        base = _flat_name(e.base)
        return None if base is None else base + ("->" if e.arrow else ".") + e.field
    return None


class _Checker(NodeVisitor):
    def __init__(self, program: Program, target: Target) -> None:
        self.program = program
        self.target = target
        self.int = target.types["int"]
        self.long = target.types["long"]
        self.scopes: list = [{}]
        self.used_keys: set = set()
        self.function: Function | None = None
        self.functions: dict = {}
        self.broken: dict = {}  # function name -> the TraceError its definition raised
        self.arrays: dict = {}
        self.roots: dict = {}  # key -> type of every object declared

    # -- names and types
    def lookup(self, name: str) -> Symbol | None:
        for scope in reversed(self.scopes):
            sym = scope.get(name)
            if sym is not None:
                return sym
        return None

    def refused(self, name: str, node) -> None:
        """Raise the error of a definition outside the subset, at its use."""
        found = self.program.refused.get(name)
        if found is not None:
            err = found[0]
            raise TraceError(node.line, node.column, code="trace_refused_use", name=name,
                             at=f"{err.line}:{err.column}", reason=err.reason_error())

    def symbol(self, var: Var) -> Symbol:
        sym = self.lookup(var.name)
        if sym is None:
            self.refused(var.name, var)
            if _MACRO_NAME.fullmatch(var.name):  # spelled as a macro: -D can give it
                if self.program.unresolved:
                    raise TraceError(var.line, var.column, code="trace_undeclared_macro",
                                     name=var.name, headers=", ".join(self.program.unresolved))
                raise TraceError(var.line, var.column, code="trace_undeclared_define",
                                 name=var.name)
            raise TraceError(var.line, var.column, code="trace_undeclared", name=var.name)
        return sym

    def resolve(self, desc, node) -> object:
        """A parser type descriptor as a type of this target."""
        if isinstance(desc, str):
            return VOID if desc == "void" else _type_of(self.target, desc, node)
        if isinstance(desc, Ptr):
            if isinstance(desc.to, StructDef) and desc.to.fields is None and desc.size is None:
                # a handle to a struct never defined (TI's `struct _PI_Obj_ *PI_Handle` beside
                # `typedef struct _PI_ {…} PI_Obj`): opaque as void *, its casts checked
                return PtrT(VOID)
            to = self.resolve(desc.to, node)
            if isinstance(to, PtrT):
                raise TraceError(node.line, node.column, code="trace_pointer_pointer")
            n = None
            if desc.size is not None:
                n = constant_value(desc.size, "trace_const_array_size")
                if not 1 <= n <= MAX_ELEMENTS:
                    raise TraceError(desc.size.line, desc.size.column, code="trace_array_size",
                                     n=n, limit=MAX_ELEMENTS)
            return PtrT(to, n)
        if isinstance(desc, Unsupported):
            return desc  # refused where the field is used
        if isinstance(desc, Arr):
            if desc.size is None:
                raise TraceError(node.line, node.column, code="trace_array_no_size")
            n = constant_value(desc.size, "trace_const_array_size")
            of = self.resolve(desc.of, node)
            if not 1 <= n <= MAX_ELEMENTS or n * max(1, len(leaves("", of))) > MAX_ELEMENTS:
                raise TraceError(desc.size.line, desc.size.column, code="trace_array_size", n=n,
                                 limit=MAX_ELEMENTS)
            return ArrT(of, n)
        return self.struct(desc, node)

    def struct(self, sdef: StructDef, node) -> StructT:
        st = sdef.resolved.get(self.target.name)
        if st is not None:
            return st
        if sdef.fields is None:
            raise TraceError(node.line, node.column, code="trace_struct_incomplete",
                             name=sdef.name)
        st = sdef.resolved[self.target.name] = StructT(sdef.name)
        for name, desc, spelling in sdef.fields:
            ft = self.resolve(desc, node)
            if ft is VOID or ft is st:
                raise TraceError(sdef.line, sdef.column, code="trace_field_incomplete", name=name,
                                 struct=sdef.name)
            st.fields[name] = (ft, spelling)
        if len(leaves("", st)) > MAX_ELEMENTS:
            raise TraceError(sdef.line, sdef.column, code="trace_struct_size", name=sdef.name,
                             limit=MAX_ELEMENTS)
        return st

    def declare(self, name: str, spelling, ctype, initialized: bool, node) -> Symbol:
        scope = self.scopes[-1]
        if name in scope:
            prev = scope[name]
            if len(self.scopes) == 1 and not (prev.initialized and initialized) and \
                    same_layout(prev.ctype, ctype):
                # C99 6.9.2: `extern T x;` (a header) then the definition `T x = {…};`
                prev.initialized = prev.initialized or initialized
                return prev
            raise TraceError(node.line, node.column, code="trace_declared_twice", name=name,
                             at=f"{prev.line}:{prev.column}")
        f = self.function
        key = name if f is None or not f.prefix else f"{f.prefix}{name}"
        if f is not None and not f.prefix and (self.lookup_global(name) is not None):
            key = f"{f.name}:{name}"  # an entry local that hides a global keeps both visible
        base, n = key, 1
        while key in self.used_keys:
            n += 1
            key = f"{base}#{n}"
        self.used_keys.add(key)
        sym = Symbol(name, spelling, ctype, initialized, node.line, node.column, key)
        scope[name] = sym
        self.roots[key] = ctype
        if isinstance(ctype, ArrT):
            self.arrays[key] = ctype.n
        return sym

    def lookup_global(self, name: str):
        return self.scopes[0].get(name)

    # -- statements
    def visit_Decl(self, s: Decl) -> None:
        for i, (var, init, desc) in enumerate(s.items):
            if isinstance(desc, Arr) and desc.size is None and init is None and \
                    self.function is None and len(self.scopes) == 1:
                desc = self.completed(var.name, desc)
            if isinstance(desc, Arr) and desc.size is None and isinstance(init, InitList):
                desc = Arr(desc.of, Num(len(init.items), str(len(init.items))))
            ctype = self.resolve(desc, s if isinstance(desc, str) else var)
            if init is not None:
                init = self.initializer(init, ctype)
                s.items[i] = (var, init, desc)
            sym = self.declare(var.name, s.type_name, ctype, init is not None, var)
            var.ctype = ctype
            var.sym = sym

    def completed(self, name: str, desc: Arr) -> Arr:
        """``extern T t[];`` (a header) takes its size from the file-scope definition that
        completes it later, ``T t[N]`` or ``T t[] = {…}`` (C99 6.9.2); ``desc`` when none."""
        for s in self.program.statements:
            if isinstance(s, Decl):
                for var, init, d in s.items:
                    if var.name == name and isinstance(d, Arr):
                        if d.size is not None:
                            return Arr(desc.of, d.size)
                        if isinstance(init, InitList):
                            return Arr(desc.of, Num(len(init.items), str(len(init.items))))
        return desc

    def visit_ExprStmt(self, s: ExprStmt) -> None:
        self.expr(s.expr, void_ok=True)

    def visit_If(self, s: If) -> None:
        self.scalar(s.test)
        self.visit(s.then)
        if s.other is not None:
            self.visit(s.other)

    def visit_Loop(self, s: Loop) -> None:
        self.scopes.append({})
        if s.init is not None:
            self.visit(s.init)
        if s.test is not None:
            self.scalar(s.test)
        if s.step is not None:
            self.expr(s.step, void_ok=True)
        self.visit(s.body)
        self.scopes.pop()

    def visit_Return(self, s: Return) -> None:
        f = self.function
        if f.ret is VOID:
            if s.value is not None:
                raise TraceError(s.line, s.column, code="trace_return_void_value", name=f.name)
        elif s.value is None:
            raise TraceError(s.line, s.column, code="trace_return_no_value", name=f.name)
        elif isinstance(f.ret, PtrT):
            vt = self.expr(s.value)
            if not _accepts(f.ret, vt):
                raise TraceError(s.value.line, s.value.column, code="trace_return_type",
                                 name=f.name, ret=describe(f.ret), got=describe(vt))
        elif isinstance(f.ret, StructT):
            vt = self.expr(s.value)
            if vt is not f.ret:
                raise TraceError(s.value.line, s.value.column, code="trace_return_type",
                                 name=f.name, ret=describe(f.ret), got=describe(vt))
        else:
            self.scalar(s.value)

    def visit_Switch(self, s: Switch) -> None:
        self.scalar(s.test)
        seen: dict = {}
        for inner in s.body.statements:
            if isinstance(inner, Label):
                k = None if inner.value is None else constant_value(inner.value,
                                                                    "trace_const_case")
                if k in seen:
                    prev = seen[k]
                    raise TraceError(inner.line, inner.column, code="trace_case_twice",
                                     at=f"{prev.line}:{prev.column}")
                seen[k] = inner
                inner.value_int = k
        self.visit(s.body)

    def visit_Label(self, s: Label) -> None:
        if not hasattr(s, "value_int"):
            raise TraceError(s.line, s.column, code="trace_case_nested")

    def visit_Block(self, s: Block) -> None:
        self.scopes.append({})
        for inner in s.statements:
            self.visit(inner)
        self.scopes.pop()

    def initializer(self, init, t):
        """Type the initializer ``init`` of an object of type ``t``; returns it, a floating
        constant converted to ``t`` (C99 6.7.8p11: as by assignment) where it was one."""
        if isinstance(init, InitList):
            items = init.items
            if isinstance(t, ArrT):
                if len(items) > t.n:
                    raise TraceError(init.line, init.column, code="trace_init_array",
                                     n=len(items), size=t.n)
                items[:] = [self.initializer(item, t.of) for item in items]
            elif isinstance(t, StructT):
                if len(items) > len(t.fields):
                    raise TraceError(init.line, init.column, code="trace_init_struct",
                                     n=len(items), name=t.name, size=len(t.fields))
                items[:] = [self.initializer(item, ft)
                            for item, (ft, _) in zip(items, t.fields.values())]
            elif len(items) == 1 and not isinstance(items[0], InitList):
                items[0] = self.initializer(items[0], t)
            else:
                raise TraceError(init.line, init.column, code="trace_init_braces")
            init.ctype = t
            return init
        init = self.converted(init, t)
        vt = self.expr(init)
        if not _accepts(t, vt):
            raise TraceError(init.line, init.column, code="trace_init_type", dst=describe(t),
                             src=describe(vt))
        return init

    @staticmethod
    def converted(value, t):
        """``value``, or the folded conversion of a floating constant stored in an integer
        of type ``t`` (by initialization or assignment)."""
        if type(value) is FNum and isinstance(t, CType):
            return float_to_int(t.name, value, value, value)
        return value

    # -- expressions
    def expr(self, e, void_ok: bool = False) -> object:
        t = self._expr(e)
        e.ctype = t
        if t is VOID and not void_ok:
            raise TraceError(e.line, e.column, code="trace_void_value", name=e.name)
        return t

    def scalar(self, e) -> CType:
        t = self.expr(e)
        if not isinstance(t, CType):
            raise TraceError(e.line, e.column, code="trace_not_scalar", got=describe(t))
        return t

    def _expr(self, e) -> object:
        target = self.target
        kind = type(e)
        if kind is Num:
            if not isinstance(e.ctype, list):
                return e.ctype
            for name in e.ctype:
                t = target.types[name]
                if e.value <= t.max:
                    return t
            raise TraceError(e.line, e.column, code="trace_constant_large", text=e.text,
                             types=", ".join(e.ctype))
        if kind is Var:
            sym = self.symbol(e)
            e.sym = sym
            return sym.ctype
        if kind is Member:
            flat = _flat_name(e)
            if flat is not None and self.lookup(flat.split(".")[0].split("->")[0]) is None:
                sym = self.lookup(flat)
                if sym is not None:  # a dotted name declared as one variable
                    e.flat = sym
                    return sym.ctype
            bt = self.expr(e.base)
            if e.arrow:
                if not isinstance(bt, PtrT):
                    raise TraceError(e.line, e.column, code="trace_arrow_needs_pointer",
                                     got=describe(bt))
                bt = bt.to
            if not isinstance(bt, StructT):
                name = flat or self.program.source[e.base.start:e.base.end]
                if flat:
                    raise TraceError(e.line, e.column, code="trace_not_struct", name=name)
                raise TraceError(e.line, e.column, code="trace_dot_needs_struct", got=describe(bt))
            field = bt.fields.get(e.field)
            if field is None:
                raise TraceError(e.line, e.column, code="trace_no_field", name=bt.name,
                                 field_name=e.field)
            if isinstance(field[0], Unsupported):
                raise TraceError(e.line, e.column, code="trace_field_unsupported",
                                 name=e.field, struct=bt.name,
                                 reason={"code": field[0].reason["code"], "params": {
                                     k: v for k, v in field[0].reason.items() if k != "code"}})
            return field[0]
        if kind is Index:
            bt = self.expr(e.base)
            self.scalar(e.index)
            if isinstance(bt, ArrT):
                return bt.of
            if isinstance(bt, PtrT):
                return bt.to
            raise TraceError(e.line, e.column, code="trace_index_needs_array", got=describe(bt))
        if kind is Unary:
            if e.op == "&":
                return PtrT(self.expr(e.operand))
            if e.op == "*":
                t = self.expr(e.operand)
                if isinstance(t, (PtrT, ArrT)):
                    return t.to if isinstance(t, PtrT) else t.of
                raise TraceError(e.line, e.column, code="trace_deref_needs_pointer",
                                 got=describe(t))
            t = self.scalar(e.operand)
            return self.int if e.op == "!" else promote(target, t)
        if kind is Binary:
            lt, rt = self.scalar(e.left), self.scalar(e.right)
            if e.op in ("<<", ">>"):
                e.operand_type = promote(target, lt)
                return e.operand_type
            e.operand_type = common_type(target, lt, rt)
            return self.int if e.op in ("<", ">", "<=", ">=", "==", "!=") else e.operand_type
        if kind is Logical:
            self.scalar(e.left)
            self.scalar(e.right)
            return self.int
        if kind is Cond:
            self.scalar(e.test)
            return common_type(target, self.scalar(e.then), self.scalar(e.other))
        if kind is Cast:
            if isinstance(e.type_name, Ptr):
                return self.pointer_cast(e)
            self.scalar(e.operand)
            t = _type_of(target, e.type_name, e)
            if e.folded is not None and not t.min <= int(e.folded) <= t.max:
                raise TraceError(e.line, e.column, code="trace_float_cast_range",
                                 text=repr(e.folded), value=int(e.folded), type=e.type_name)
            return t
        if kind is Assign:
            tt = self.expr(e.target)
            if not isinstance(tt, CType):
                if e.op != "=":
                    raise TraceError(e.line, e.column, code="trace_op_on", op=e.op,
                                     got=describe(tt))
                vt = self.expr(e.value)
                if isinstance(tt, ArrT) or not _accepts(tt, vt):
                    raise TraceError(e.line, e.column, code="trace_assign_type", src=describe(vt),
                                     dst=describe(tt))
                return tt
            if e.op == "=":
                e.value = self.converted(e.value, tt)
            vt = self.scalar(e.value)
            if e.op != "=":
                e.operand_type = promote(target, tt) if e.op in ("<<=", ">>=") \
                    else common_type(target, tt, vt)
            return tt
        if kind is IncDec:
            tt = self.expr(e.target)
            if not isinstance(tt, CType):
                raise TraceError(e.line, e.column, code="trace_op_unsupported", op=e.op,
                                 got=describe(tt))
            e.operand_type = common_type(target, tt, self.int)
            return tt
        if kind is Call:
            return self.call(e)
        if kind is FNum:  # left unfolded: not cast to an integer type
            raise TraceError(e.line, e.column, code="trace_float_constant",
                             text=quoted(e.text))
        raise AssertionError(kind.__name__)  # the parser makes no other node

    def pointer_cast(self, e: Cast) -> PtrT:
        """``(T *)p``: the same object seen as a ``T``; allowed when the layouts match field
        by field, to ``void *``, and from ``void *`` (the object is checked when it runs)."""
        tt = self.resolve(e.type_name, e)
        vt = _decay(self.expr(e.operand))
        text = " ".join(self.program.source[e.start:e.end].split())
        if not isinstance(vt, PtrT):
            raise TraceError(e.line, e.column, code="trace_cast_not_pointer", cast=text,
                             got=describe(vt))
        if not same_layout(vt, tt):
            raise TraceError(e.line, e.column, code="trace_cast_reinterprets", cast=text,
                             src=describe(vt), dst=describe(tt))
        e.from_void = vt.to is VOID and tt.to is not VOID
        return PtrT(tt.to)

    def call(self, e: Call) -> object:
        if e.iq is not None:
            e.func = None
            for a in e.args:
                self.scalar(a)
            return self.long
        f = self.functions.get(e.name)
        if f is None:
            self.refused(e.name, e)
            known = ", ".join(self.program.functions) or "none"
            raise TraceError(e.line, e.column, code="trace_unknown_function", name=e.name,
                             known=known)
        e.func = f
        if self.function is not None:
            self.function.calls.add(f.name)
        if len(e.args) != len(f.params):
            raise TraceError(e.line, e.column, code="trace_builtin_arity", name=e.name,
                             n=len(f.params), got=len(e.args))
        for a, p in zip(e.args, f.params):
            at = self.expr(a)
            if not _accepts(p.ctype, at):
                raise TraceError(a.line, a.column, code="trace_argument_type", name=p.name,
                                 function=e.name, want=describe(p.ctype), got=describe(at))
        return f.ret

    def signature(self, f: Function) -> None:
        node = f.node
        self.function = f
        self.scopes.append({})
        for name, desc, spelling, tok in node.params:
            t = self.resolve(desc, tok)
            f.params.append(self.declare(name, spelling, t, True, tok))
        f.scope = self.scopes.pop()
        self.function = None
        f.ret = self.resolve(node.ret, node)
        if not isinstance(f.ret, (CType, StructT)) and f.ret is not VOID and not (
                isinstance(f.ret, PtrT) and f.ret.n is None):
            raise TraceError(node.line, node.column, code="trace_result_type", name=f.name,
                             ret=describe(f.ret))

    def body(self, f: Function) -> None:
        self.function = f
        self.scopes += [f.scope, {}]
        for s in f.node.body.statements:
            self.visit(s)
        del self.scopes[-2:]
        self.function = None


def _decay(t):
    return PtrT(t.of) if isinstance(t, ArrT) else t


class _Inputs:
    """Which paths may be read before they are given a value (definite assignment, C99
    6.2.4 aside: a global without initializer is an input, not zero)."""

    def __init__(self, checker: _Checker, inputable) -> None:
        self.checker = checker
        self.inputable = inputable  # path -> bool: a name the user can set
        self.inputs: list = []
        self.seen: set = set()
        self.pointers: dict = {}  # pointer path -> the path it points to
        self.active: list = []
        self.visits = 0
        self.returns: list | None = None
        self.results: list = []  # the paths the current function's pointer returns give

    def tick(self, node) -> None:
        self.visits += 1
        if self.visits > MAX_ANALYSIS:
            raise TraceError(node.line, node.column, code="trace_analysis", limit=MAX_ANALYSIS)

    def read(self, path: str, t, assigned) -> None:
        for leaf, _, _ in leaves(path, t):
            if assigned is not None and leaf not in assigned and leaf not in self.seen and \
                    self.inputable(leaf):
                self.seen.add(leaf)
                self.inputs.append(leaf)

    @staticmethod
    def write(path: str, t, assigned) -> None:
        if assigned is not None:
            for leaf, _, _ in leaves(path, t):
                assigned.add(leaf)

    def place(self, e, a) -> str | None:
        """The path ``e`` designates (``None`` when an index is not constant), evaluating
        the sub-expressions it reads."""
        self.tick(e)
        kind = type(e)
        if kind is Var:
            return e.sym.key
        if kind is Member:
            if e.flat is not None:
                return e.flat.key
            if e.arrow:
                base = self.pointer(e.base, a)
            else:
                base = self.place(e.base, a)
            return None if base is None else f"{base}.{e.field}"
        if kind is Index:
            bt = e.base.ctype
            base = self.place(e.base, a) if isinstance(bt, ArrT) else self.pointer(e.base, a)
            self.expr(e.index, a)
            if base is None:
                return None
            try:
                i = constant_value(e.index, "")
            except TraceError:
                return None
            if base.endswith("]") and not isinstance(bt, ArrT):
                head, _, k = base[:-1].rpartition("[")
                return f"{head}[{int(k) + i}]"
            return f"{base}[{i}]"
        return self.pointer(e.operand, a)  # *p

    def pointer(self, e, a) -> str | None:
        """The path a pointer-valued expression points to."""
        t = e.ctype
        if isinstance(t, ArrT):
            base = self.place(e, a)
            return None if base is None else f"{base}[0]"
        if isinstance(e, Unary) and e.op == "&":
            return self.place(e.operand, a)
        if isinstance(e, Cast):
            return self.pointer(e.operand, a)
        if isinstance(e, Call):
            return self.call(e, a)
        path = self.place(e, a) if isinstance(e, (Var, Member, Index)) or (
            isinstance(e, Unary) and e.op == "*") else None
        if path is None:
            return None
        self.read(path, t, a)  # a pointer input read before written
        return self.pointers.get(path)

    def expr(self, e, a) -> None:
        self.tick(e)
        kind = type(e)
        if kind is Num:
            return
        if kind in (Var, Member, Index) or (kind is Unary and e.op == "*"):
            path = self.place(e, a)
            if path is not None:
                self.read(path, e.ctype, a)
            elif isinstance(e, Index) and isinstance(e.base.ctype, ArrT):
                base = self.place(e.base, a)
                if base is not None:  # an element unknown until run time: any of them
                    self.read(base, e.base.ctype, a)
            return
        if kind is Unary:
            if e.op == "&":
                self.place(e.operand, a)
            else:
                self.expr(e.operand, a)
        elif kind is Binary:
            self.expr(e.left, a)
            self.expr(e.right, a)
        elif kind is Logical:
            self.expr(e.left, a)
            self.expr(e.right, None if a is None else set(a))  # may not run
        elif kind is Cond:
            self.expr(e.test, a)
            x = None if a is None else set(a)
            y = None if a is None else set(a)
            self.expr(e.then, x)
            self.expr(e.other, y)
            if a is not None:
                a |= x & y  # what both branches assign
        elif kind is Cast:
            self.expr(e.operand, a)
        elif kind is Assign:
            if e.op != "=":
                self.expr(e.target, a)
            if isinstance(e.ctype, PtrT):
                path = self.place(e.target, a)
                self.pointers[path] = self.pointer(e.value, a)
            else:
                self.expr(e.value, a)
            path = self.place(e.target, a)
            if path is not None:
                self.write(path, e.ctype, a)
        elif kind is IncDec:
            self.expr(e.target, a)
        elif kind is Call:
            self.call(e, a)
        elif kind is InitList:
            for item in e.items:
                self.expr(item, a)

    def call(self, e: Call, a) -> str | None:
        """Follow a call of a function of the code; a pointer result's path when every
        ``return`` gives the same one."""
        f = e.func
        if f is None:
            for arg in e.args:
                self.expr(arg, a)
            return None
        if f.name in self.active:
            raise TraceError(e.line, e.column, code="trace_recursion", name=f.name)
        bound = []
        for arg, p in zip(e.args, f.params):
            if isinstance(p.ctype, PtrT):
                bound.append((p.key, self.pointer(arg, a)))
            else:
                self.expr(arg, a)
        if a is not None:
            for k in [k for k in a if k.startswith(f.prefix)]:
                a.discard(k)
        for p in f.params:
            self.write(p.key, p.ctype, a)
        self.pointers.update(bound)
        self.active.append(f.name)
        outer, outer_results = self.returns, self.results
        self.returns, self.results = [], []
        end = self.block(f.node.body.statements, a)
        ends = self.returns + [end]
        results = set(self.results)
        self.returns, self.results = outer, outer_results
        self.active.pop()
        if a is not None:
            live = [x for x in ends if x is not None]
            if live:  # (a itself may be one of them: intersect before clearing it)
                both = set.intersection(*live)
                a.clear()
                a.update(both)
        return results.pop() if len(results) == 1 else None

    def block(self, statements, a):
        for s in statements:
            a = self.statement(s, a)
        return a

    def statement(self, s, a):
        """Analyse ``s`` given the definitely assigned set ``a`` (None: unreachable);
        returns the set after it."""
        if a is None:
            return None
        if isinstance(s, Decl):
            for var, init, _ in s.items:
                if init is not None:
                    if isinstance(var.ctype, PtrT) and not isinstance(init, InitList):
                        self.pointers[var.sym.key] = self.pointer(init, a)
                    else:
                        self.expr(init, a)
                    self.write(var.sym.key, var.ctype, a)
            return a
        if isinstance(s, ExprStmt):
            self.expr(s.expr, a)
            return a
        if isinstance(s, If):
            self.expr(s.test, a)
            x = self.statement(s.then, set(a))
            y = self.statement(s.other, set(a)) if s.other is not None else a
            if x is None:
                return y
            if y is None:
                return x
            return x & y
        if isinstance(s, Loop):
            if s.init is not None:
                a = self.statement(s.init, a)
            if s.kind == "do":
                a = self.statement(s.body, a) or a
                self.expr(s.test, a)
                return a
            if s.test is not None:
                self.expr(s.test, a)
            inner = self.statement(s.body, set(a))
            if s.step is not None and inner is not None:
                self.expr(s.step, inner)
            if s.test is None:  # for (;;): leaves only by break or return
                return inner if inner is not None else a
            return a
        if isinstance(s, Return):
            if s.value is not None and isinstance(s.value.ctype, PtrT):
                self.results.append(self.pointer(s.value, a))
            elif s.value is not None:
                self.expr(s.value, a)
            if self.returns is not None:
                self.returns.append(a)
            return None
        if isinstance(s, Jump) or isinstance(s, Label):
            return a
        if isinstance(s, Switch):
            self.expr(s.test, a)
            self.statement(s.body, set(a))  # no case may match: nothing is certain after it
            return a
        return self.block(s.statements, a)


def check(program: Program, target: Target, entry: str | None = None) -> Checked:
    """Type every node of ``program`` for ``target``; find declared symbols and inputs.

    Parameters
    ----------
    program : Program
    target : Target
    entry : str, optional
        The function to run (its parameters and the objects they point to become inputs).
        Without it the statements outside functions run.

    Raises
    ------
    TraceError
        An undeclared or twice-declared name, a type the target lacks, a constant
        too large, an annotation naming no variable, a call the subset cannot make.
    InputError
        ``entry`` names no function of the code (field ``entry``).
    """
    c = _Checker(program, target)
    if entry in program.refused or (entry is None and program.refused):
        # without an entry every statement runs: the first one outside the subset is the error
        raise program.refused[entry][0] if entry is not None else \
            next(iter(program.refused.values()))[0]
    if entry is None or entry not in program.functions:
        entries = [*program.functions, *(f"{m}(…)" for m in entry_macros(program))]
        if entry is not None:
            raise InputError("entry", code="trace_no_entry", name=entry,
                             known=", ".join(entries) or "none")
        if entries and not any(not isinstance(s, Decl) for s in program.statements
                               if not isinstance(s, Block)):
            raise InputError("entry", code="trace_choose_entry", known=", ".join(entries))
    skipped = []
    for s in program.statements:
        try:
            c.visit(s)
        except TraceError as err:
            # as the parser does for what the subset lacks: a file-scope declaration of a
            # floating value the entry never uses is refused only where it is used
            if entry is None or not isinstance(s, Decl) or err.reason_error()["code"] not in (
                    "trace_float_constant", "trace_float_operator"):
                raise
            skipped.append(s)
            for var, _, _ in s.items:
                if c.lookup_global(var.name) is None:
                    program.refused[var.name] = (err, False)
    if skipped:
        program.statements[:] = [s for s in program.statements if s not in skipped]
    for name, node in program.functions.items():
        c.functions[name] = Function(node, "" if name == entry else f"{name}:")
    for f in c.functions.values():
        try:
            c.signature(f)
        except TraceError as err:
            if f.name == entry:
                raise
            c.broken[f.name] = err
    for f in c.functions.values():
        if f.name in c.broken:
            continue
        try:
            c.body(f)
        except TraceError as err:
            # A function the entry never calls may use what the subset lacks.
            if f.name == entry or entry is None:
                raise
            c.broken[f.name] = err
            c.scopes[1:] = []
            c.function = None
    for name, err in c.broken.items():
        program.refused[name] = (err, True)
        del c.functions[name]
    if entry is not None:
        _handles(c.functions[entry], c.roots)
    calls = set(c.functions[entry].calls) if entry is not None else set()
    seen: set = set()
    while calls - seen:  # a broken function the entry reaches is an error at its call
        name = (calls - seen).pop()
        seen.add(name)
        if name in program.refused and program.refused[name][1]:
            err = program.refused[name][0]
            raise TraceError(err.line, err.column, code="trace_refused_call", name=name,
                             entry=entry, reason=err.reason_error())
        if name in c.functions:
            calls |= c.functions[name].calls
    # User-facing integers: globals and, for an entry, its parameters, the objects its
    # pointer parameters point to (p.FIELD, *out) and its locals.
    symbols: dict = {}
    settable: set = set()
    pointers: dict = {}  # a pointer the user may set (--set p.h=&p.obj) -> (type, spelling)

    def add(sym_key, t, spelling, line, column, initialized, can_set):
        for path, lt, sp in leaves(sym_key, t, spelling):
            if isinstance(lt, CType):
                symbols[path] = Symbol(path, sp, lt, initialized, line, column)
                if can_set:
                    settable.add(path)
            elif can_set and isinstance(lt, PtrT) and lt.n is None:
                pointers[path] = (lt, sp)

    for sym in c.scopes[0].values():
        add(sym.key, sym.ctype, sym.spelling, sym.line, sym.column, sym.initialized,
            not sym.initialized)
    f = c.functions.get(entry) if entry is not None else None
    objects = dict(c.arrays)
    pointees: dict = {}  # a pointer field of an entry's object -> the object it points to
    if f is not None:
        for p in f.params:
            if isinstance(p.ctype, PtrT):
                path, t, _ = pointee(p)
                add(path, t, p.spelling, p.line, p.column, False, True)
                if isinstance(t, ArrT):
                    objects[path] = t.n
                for ptr, obj, ot, sp in linked(path, t):
                    add(obj, ot, sp, p.line, p.column, False, True)
                    pointees[ptr] = obj
            else:
                add(p.key, p.ctype, p.spelling, p.line, p.column, False, True)
        for sym in _entry_locals(f.node.body):
            add(sym.key, sym.ctype, sym.spelling, sym.line, sym.column, True, False)
        if isinstance(f.ret, StructT):  # a struct result: return.FIELD
            add("return", f.ret, f.ret_spelling, f.node.line, f.node.column, True, False)
    for note in program.notes.values():
        if note.name not in symbols:
            raise TraceError(note.line, note.column, code="trace_note_undeclared",
                             name=note.name)

    def inputable(leaf: str) -> bool:  # a pointer with an object of its own is no input
        return leaf in settable or (leaf in pointers and leaf not in pointees)

    def analyse(seeds: dict) -> list:
        analysis = _Inputs(c, inputable)
        assigned: set = set()
        analysis.block(program.statements, assigned)
        if f is not None:
            for p in f.params:  # every integer parameter is an input, in order
                if isinstance(p.ctype, PtrT):
                    analysis.pointers[p.key] = pointee(p)[2]
                    analysis.pointers.update(pointees)
                elif isinstance(p.ctype, CType):
                    analysis.read(p.key, p.ctype, set())
                    assigned.add(p.key)
            analysis.pointers.update(seeds)
            analysis.active.append(f.name)
            analysis.returns = []
            analysis.block(f.node.body.statements, assigned)
        return analysis.inputs

    checked = Checked(program, target, symbols, analyse({}), c.functions, f, objects)
    checked.roots, checked.pointees, checked.pointers = c.roots, pointees, pointers
    checked.heads = {sym.key for sym in c.scopes[0].values()} | \
        ({p.key for p in f.params} if f is not None else set())
    checked.analyse = analyse
    return checked


def pointee(p: Symbol) -> tuple:
    """The object an entry function's pointer parameter points to: (its path, its type, the
    pointer's value) — ``p`` for a struct, ``*p`` for an integer, ``p[0]…`` for ``T p[N]``."""
    t = p.ctype
    if t.n is not None:
        return p.name, ArrT(t.to, t.n), f"{p.name}[0]"
    path = p.name if isinstance(t.to, StructT) else f"*{p.name}"
    return path, t.to, path


class _Casts(NodeVisitor):
    """The types a parameter ``param`` is cast to, ``(T *)param``, collected in ``seen``."""

    def __init__(self, param) -> None:
        self.param, self.seen = param, set()

    def visit_Cast(self, node: Cast) -> None:
        if isinstance(node.operand, Var) and getattr(node.operand, "sym", None) is self.param \
                and isinstance(node.ctype, PtrT):
            self.seen.add(node.ctype.to)
        self.generic_visit(node)


def _handles(f: Function, roots: dict) -> None:
    """An entry parameter that is an opaque handle (``void *`` or a pointer to a struct never
    defined) points to an object of the type the entry casts it to: ``(PI_Obj *)handle``."""
    for p in f.params:
        if not (isinstance(p.ctype, PtrT) and p.ctype.to is VOID):
            continue
        casts = _Casts(p)
        casts.visit(f.node.body)
        seen = casts.seen
        if len(seen) != 1:
            raise TraceError(p.line, p.column, code="trace_opaque_entry", name=p.name,
                             types=", ".join(describe(t) for t in seen) or "none")
        p.ctype = roots[p.key] = PtrT(seen.pop())


def linked(path: str, t, chain: tuple = ()) -> list:
    """The objects the pointer fields of the object at ``path`` point to, each an object of
    its own named after the field (``rtM.dwork`` → ``rtM.dwork.FIELD``, an integer ``*rtM.n``):
    a list of (pointer path, object path, object type), nested pointers followed, a struct
    already on the way not again (a linked list's next stays unset)."""
    out = []
    chain = chain + (t,)
    for leaf, lt, sp in leaves(path, t):
        if not isinstance(lt, PtrT) or lt.n is not None or lt.to is VOID or lt.to in chain:
            continue
        obj = leaf if isinstance(lt.to, StructT) else f"*{leaf}"
        out.append((leaf, obj, lt.to, sp))
        if isinstance(lt.to, StructT):
            out += linked(obj, lt.to, chain)
    return out


class _Locals(NodeVisitor):
    """The symbols the declarations of a function body declare, in source order."""

    def __init__(self) -> None:
        self.symbols: list = []

    def visit_Decl(self, s: Decl) -> None:
        self.symbols.extend(var.sym for var, _, _ in s.items)


def _entry_locals(body) -> list:
    locals_ = _Locals()
    locals_.visit(body)
    return locals_.symbols
