"""The import graph of pulab is a DAG in declared layers (every import, function-level ones too).

Each module of ``py/pulab`` is parsed with ``ast``; every ``import`` and ``from … import``
in it (at any depth: a deferred import still ties two modules) is an edge.  The graph must
have no cycle, and every edge must go to the module's own layer or one below it in
:data:`LAYERS` — the one place the order is declared.
"""

from __future__ import annotations

import ast

from conftest import ROOT

PACKAGE = ROOT / "py" / "pulab"

#: The layers, lowest first; a module belongs to the layer of its longest listed prefix
#: (``""``: the package's ``__init__``).  A module imports from its own layer and those
#: before it.
LAYERS = (
    ("fixedpoint",),
    ("schema",),
    ("model",),
    # reads a datasheet's values into the input (model.datasheet converts them)
    ("schema.inputs",),
    # the tracer: the profiles run the seed's C through it
    ("ctrace",),
    ("profiles",),
    # the code proof: the box search (fixedpoint.boxsearch) over the tracer's runs, in slices
    # (analyses.slices)
    ("analyses", "ctrace.prove"),
    ("report",),
    # families: each calls report() for every motor, point or box
    ("analyses.integers", "analyses.sweep", "analyses.exercises", "analyses.batch",
     "analyses.prove", "analyses.propose", "analyses.sim.bench", "profiles.translate",
     "analyses.audit"),
    ("export", "html", "qcalc", "benchmark"),
    ("api", "cli"),
    ("__main__", ""),
)

#: Cycles left on purpose, each with its reason (none: a new one fails the test).
KNOWN_CYCLES: tuple = ()


def _modules() -> dict:
    """Dotted name below ``pulab`` (``""`` for the package itself) → (path, is a package)."""
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE).with_suffix("").parts)
        is_pkg = parts[-1] == "__init__"
        out[".".join(parts[:-1] if is_pkg else parts)] = (path, is_pkg)
    return out


def _edges(mods: dict) -> dict:
    """Module → the pulab modules it imports (``from package import name``: the submodule
    ``name`` when it is one, else the package)."""
    edges = {}
    for name, (path, is_pkg) in mods.items():
        here = name.split(".") if name else []
        pkg = here if is_pkg else here[:-1]
        out = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    up = pkg[:len(pkg) - node.level + 1]
                    base = "pulab." + ".".join(up + ([node.module] if node.module else []))
                else:
                    base = node.module or ""
                base = base.rstrip(".")
                subs = [f"{base}.{a.name}" for a in node.names]
                # a name that is no module is read from the package's __init__
                targets = subs + ([base] if any(_local(t) not in mods for t in subs) else [])
            else:
                continue
            out |= {t for t in map(_local, targets) if t in mods and t != name}
        edges[name] = out
    edges["analyses.registry"] |= _lazy_targets()
    return edges


def _lazy_targets() -> set:
    """The modules the analyses' registry imports on first use (its ``Lazy`` functions): edges
    like any import."""
    from pulab.analyses.registry import ANALYSES, Lazy
    return {_local(f.module) for a in ANALYSES for f in vars(a).values() if isinstance(f, Lazy)}


def _local(dotted: str):
    """``pulab.a.b`` → ``a.b`` (``pulab`` → ``""``); None outside pulab."""
    if dotted == "pulab":
        return ""
    return dotted[len("pulab."):] if dotted.startswith("pulab.") else None


def _layer(name: str) -> int:
    best, rank = -1, None
    for i, prefixes in enumerate(LAYERS):
        for p in prefixes:
            if (name == p or name.startswith(p + ".") or p == "") and len(p) > best:
                best, rank = len(p), i
    return rank


def _cycles(edges: dict) -> list:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def test_every_module_has_a_layer():
    assert [m for m in _modules() if _layer(m) is None] == []


def test_the_import_graph_has_no_cycle():
    cycles = [c for c in _cycles(_edges(_modules())) if c not in KNOWN_CYCLES]
    assert cycles == []


def test_every_import_goes_down_or_sideways():
    edges = _edges(_modules())
    up = sorted(f"{a or 'pulab'} -> {b or 'pulab'}" for a, outs in edges.items() for b in outs
                if _layer(b) > _layer(a))
    assert up == []


def test_the_graph_sees_deferred_and_relative_imports():
    edges = _edges(_modules())
    assert "model.bases" in edges["profiles.context"]  # from ..model.bases import …
    assert "profiles.registry" in edges["profiles"]  # from . import limits, registry
    assert "report" in edges["profiles.translate"]
    assert {"analyses.loop", "analyses.sim"} <= edges["analyses.registry"]  # Lazy("pulab.…")
