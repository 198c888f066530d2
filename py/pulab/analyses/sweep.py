"""Sweep a product family: every firmware integer over a range of one or two inputs.

The seed reassures that overflow is usually no concern (seed 1.4-2: "一般情况下
U_n/I_n 还是比定子电阻大很多，所以不用考虑溢出的问题").  A firmware team ships
one code base for a whole range of motors, so this module answers *where*
"usually" ends: it varies one or two numeric inputs (any input path — rated
voltage, current, L, R, f_b, Ts, U_dc, bandwidth, a raw integer …) over a
linear or log range, keeps the rest of the input, and for every integer of the
chosen profile (:mod:`pulab.analyses.integers`) records its quantization error and its
status (ok, zero, store, wrap, div0, invalid).

Where a status changes between two neighbouring points, the boundary is found
by bisection on the input value, evaluating the firmware integers themselves,
down to adjacent doubles (or adjacent integers for a raw axis): ``before`` is
the last value with the old status and ``at`` the first with the new one, and
the raw firmware inputs that differ across it are named.  So a boundary is not
read off a plot: for the seed motor (17 V, f_b 220 Hz) swept in rated current,
LD is stored wrapped from the first double whose ·100 rounds to raw Current 6948
(69.47500000000001 A; 69.475·100 is 6947.4999… in doubles), where m_BaseL drops
to 1, and the code divides by zero from Current 12506 (125.05499999999999 A),
where m_BaseL reaches 0.

A sweep is computed in chunks of points (``start``, ``count``) so a page can
show progress and cancel between chunks; :func:`merge` joins the chunks'
summaries into one, the same as a sweep computed whole.

Examples
--------
>>> seed = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
...     "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4, "bemf_v": 12, "pole_pairs": 4},
...     "drive": {"udc_v": 24, "ts_s": 1e-4}}
>>> s = sweep({"input": seed, "x": {"path": "motor.rated_current_a", "start": 1, "stop": 200,
...     "n": 100}})
>>> [(b["from"], b["to"], b["at"], b["raw"]) for b in s["summary"]["boundaries"]
...  if b["name"] == "vendor.LD"]
[('ok', 'store', 69.47500000000001, {'Current': [6947, 6948]}), ('store', 'div0', 125.05499999999999, {'Current': [12505, 12506]})]
"""

from __future__ import annotations

import math

from typing import NamedTuple

from ..schema.errors import InputError
from ..schema.fields import FIELD
from .loop.inputs import validate as check_analysis
from ..schema.inputs import SECTIONS
from ..schema.validate import object_fields, real, shown
from ..report import require_pmsm
from .integers import RAW_ONLY_NAMES, STATUSES, evaluate, integer_names, profile_name
from ..fixedpoint.qformat import round_half_away
from ..profiles.inovance.code import raw_value

__all__ = ["Axis", "Plan", "make_plan", "chunk", "merge", "sweep", "describe", "MAX_AXIS_POINTS",
           "MAX_POINTS", "ERROR_THRESHOLDS_PCT", "WORST_PER_INTEGER"]

MAX_AXIS_POINTS = 10_000
MAX_POINTS = 250_000
#: |error| thresholds counted per integer (the review's note / warning / error levels).
ERROR_THRESHOLDS_PCT = (0.1, 1.0, 5.0)
WORST_PER_INTEGER = 1
_SCALES = ("linear", "log")
# Inputs the contract takes as integers; a sweep over them steps through integers.
_INTEGER_PATHS = ("motor.pole_pairs", "current_loop.pm_kp", "current_loop.pm_ki")
_RANK = {s: i for i, s in enumerate(STATUSES)}
_RANK["invalid"] = -1  # outside the family: never a "worst case" of the firmware


class Axis(NamedTuple):
    """One swept input: its JSON path and the values it takes, in order."""

    path: str
    scale: str
    values: tuple
    integer: bool


class Plan(NamedTuple):
    """A checked sweep request: base input, axes, profile and its integer names."""

    input: dict
    x: Axis
    y: Axis | None
    profile: str
    names: tuple

    @property
    def total(self) -> int:
        return len(self.x.values) * (len(self.y.values) if self.y else 1)


def _axis(spec, field: str) -> Axis:
    if not isinstance(spec, dict):
        raise InputError(field, code="not_object", got=shown(spec))
    object_fields(spec, field, ("path", "start", "stop", "n", "scale"))
    path = spec.get("path")
    section, _, key = path.partition(".") if isinstance(path, str) else ("", "", "")
    if key not in SECTIONS.get(section, ()) or FIELD[path].kind not in ("number", "integer"):
        raise InputError(f"{field}.path", code="not_numeric_path", got=shown(path))
    start = real(spec.get("start"), f"{field}.start")
    stop = real(spec.get("stop"), f"{field}.stop")
    n = spec.get("n", 200)
    if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= MAX_AXIS_POINTS:
        raise InputError(f"{field}.n", code="integer_range", lo=2, hi=MAX_AXIS_POINTS, got=shown(n))
    scale = spec.get("scale", "linear")
    if scale not in _SCALES:
        raise InputError(f"{field}.scale", code="not_choice", choices=", ".join(_SCALES),
                         got=shown(scale))
    if scale == "log":
        for name, v in (("start", start), ("stop", stop)):
            if v <= 0:
                raise InputError(f"{field}.{name}", code="log_not_positive", value=v)
        ratio = stop / start
        if math.isfinite(ratio):
            values = [start * ratio ** (k / (n - 1)) for k in range(n)]
        else:  # the ratio overflows: interpolate the logarithms
            lo, hi = math.log(start), math.log(stop)
            values = [math.exp(lo * (1 - k / (n - 1)) + hi * (k / (n - 1))) for k in range(n)]
    elif math.isfinite((stop - start) * (n - 1)):
        values = [start + (stop - start) * k / (n - 1) for k in range(n)]
    else:  # the span times k overflows: weighted sums stay finite
        values = [start * (1 - k / (n - 1)) + stop * (k / (n - 1)) for k in range(n)]
    values[-1] = stop  # exactly the range asked for, whatever the rounding above
    integer = section == "raw" or path in _INTEGER_PATHS
    if integer:
        ints = [round_half_away(v) for v in values]
        values = [v for k, v in enumerate(ints) if k == 0 or v != ints[k - 1]]
    return Axis(path, scale, tuple(values), integer)


def make_plan(req: dict) -> Plan:
    """Check a sweep request and fix its points.

    Parameters
    ----------
    req : dict
        ``input`` (a report input: the current motor), ``x`` and optionally ``y``, each
        ``{"path": str, "start": float, "stop": float, "n": int 2..10000 (default 200),
        "scale": "linear"|"log"}``, and ``profile`` (default ``inovance``).
        On a raw or other integer path the values are rounded and repeated ones dropped.

    Raises
    ------
    pulab.InputError
        Naming ``sweep.x.start`` etc. (the base input is checked point by point instead).
    """
    if not isinstance(req, dict):
        raise InputError("sweep", code="not_object", got=shown(req))
    inp = req.get("input")
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    require_pmsm(inp)
    # Simulations do not change a firmware integer: dropped, not echoed with each worst case.
    inp = {k: v for k, v in inp.items() if k != "sim"}
    # The loop analysis is echoed too but checked by no point of an Inovance sweep.
    check_analysis(inp.get("analysis"))
    x = _axis(req.get("x"), "sweep.x")
    y = None if req.get("y") is None else _axis(req["y"], "sweep.y")
    if y is not None and y.path == x.path:
        raise InputError("sweep.y.path", code="same_as", other="sweep.x.path", value=x.path)
    profile = req.get("profile")
    if profile is not None and not isinstance(profile, str):
        raise InputError("sweep.profile", code="unknown_profile", got=shown(profile))
    profile = profile_name(profile)
    try:
        names = integer_names(inp, profile)
    except InputError as e:
        if e.field == "sweep.profile":
            raise
        raise InputError("sweep.profile", code="unknown_profile", got=shown(profile)) from None
    plan = Plan(inp, x, y, profile, names)
    if plan.total > MAX_POINTS:
        raise InputError("sweep", code="too_many_points", total=plan.total, limit=MAX_POINTS)
    return plan


def _set(inp: dict, path: str, value) -> dict:
    section, _, key = path.partition(".")
    sec = inp.get(section)
    if sec is not None and not isinstance(sec, dict):
        return inp  # normalize names the section that is not an object, at every point
    return {**inp, section: {**(sec or {}), key: value}}


def _input_at(plan: Plan, xv, yv) -> dict:
    inp = _set(plan.input, plan.x.path, xv)
    return inp if plan.y is None else _set(inp, plan.y.path, yv)


class _Point(NamedTuple):
    states: dict      # name -> integer dict of pulab.analyses.integers.evaluate (or the point's failure)
    raw: dict | None
    intermediates: dict
    error: str | None
    error_zh: str | None
    unit: str | None = None
    raw_sources: dict = {}


def _evaluate(plan: Plan, inp: dict, only=None) -> _Point:
    try:
        e = evaluate(inp, plan.profile, only)
    except InputError as err:
        msg = f"{err.field}: {err.message}"
        failed = {"status": "invalid", "value": None, "ideal": None, "error_pct": None,
                  "message": msg, "message_zh": f"{err.field}: {err.message_zh}"}
        return _Point({name: failed for name in (only or plan.names)}, None, {}, msg,
                      failed["message_zh"])
    return _Point(e["integers"], e["raw"], e["intermediates"], None, None,
                  e["inductance_unit"], e["raw_sources"])


def _changes(a: dict | None, b: dict | None) -> dict:
    if not a or not b:
        return {}
    return {k: [a[k], b[k]] for k in a if k in b and a[k] != b[k]}


def _bisect(plan: Plan, name: str, axis: str, lo, lo_point: _Point, hi, hi_point: _Point,
            other, lo_status: str) -> tuple:
    """The last value with ``lo_status`` and the first after it with another status."""
    ax = plan.x if axis == "x" else plan.y
    integer, path = ax.integer, ax.path

    def at(v) -> _Point:
        return _evaluate(plan, _input_at(plan, v, other) if axis == "x"
                         else _input_at(plan, other, v), (name,))

    for _ in range(2100):  # ≤ 2098 halvings separate two doubles; ~55 in practice
        step = None if integer or name not in RAW_ONLY_NAMES else \
            _raw_step(lo_point, hi_point, path)
        if step is not None:
            # One raw integer flips between lo and hi and the integer depends on nothing
            # else, so the boundary is where that conversion flips: exact, found cheaply.
            field, target = step
            unit = lo_point.unit
            lo, hi = _first(lambda v: raw_value(field, v, unit) == target, lo, hi)
            break
        mid = (lo + hi) // 2 if integer else lo + (hi - lo) / 2
        if mid == lo or mid == hi:
            break
        p = at(mid)
        if p.states[name]["status"] == lo_status:
            lo, lo_point = mid, p
        else:
            hi, hi_point = mid, p
    return lo, lo_point, hi, hi_point


def _raw_step(a: _Point, b: _Point, path: str):
    """(field, value at b) when a and b differ only in one raw field, by one, fed by ``path``."""
    diff = _changes(a.raw, b.raw)
    if len(diff) != 1:
        return None
    (field, (va, vb)), = diff.items()
    if abs(vb - va) != 1 or a.raw_sources.get(field) != path:
        return None
    return field, vb


def _first(pred, lo: float, hi: float) -> tuple:
    """Adjacent doubles (last with ``pred`` false, first true) between lo and hi."""
    while True:
        mid = lo + (hi - lo) / 2
        if mid == lo or mid == hi:
            return lo, hi
        if pred(mid):
            hi = mid
        else:
            lo = mid


def _boundaries(plan: Plan, name: str, axis: str, a, pa: _Point, b, pb: _Point, other,
                index: int) -> list:
    """Every status change of ``name`` between axis values a and b (a chain a→c→b too)."""
    out = []
    status, target = pa.states[name]["status"], pb.states[name]["status"]
    lo, plo = a, pa
    for _ in range(len(STATUSES)):
        before, p0, at, p1 = _bisect(plan, name, axis, lo, plo, b, pb, other, status)
        new = p1.states[name]["status"]
        rec = {"name": name, "axis": axis, "path": (plan.x if axis == "x" else plan.y).path,
               "from": status, "to": new, "before": before, "at": at, "index": index,
               "other": other, "raw": _changes(p0.raw, p1.raw),
               "intermediates": _changes(p0.intermediates, p1.intermediates)}
        failed = p1.states[name] if p1.states[name]["message"] else p0.states[name]
        if failed["message"]:
            rec["message"], rec["message_zh"] = failed["message"], failed["message_zh"]
        out.append(rec)
        if new == target or at == b:
            break
        status, lo, plo = new, at, p1
    return out


def _score(state: dict) -> tuple:
    err = state["error_pct"]
    return _RANK[state["status"]], abs(err) if err is not None else 0.0


def chunk(plan: Plan, start: int = 0, count: int | None = None) -> dict:
    """Compute points ``start`` … ``start+count−1`` of a sweep and their summary.

    Points are numbered x fastest: point k is (x[k mod nx], y[k div nx]).  Boundaries
    are found between each point and its neighbour before it along x (and along y),
    so every boundary of the sweep belongs to exactly one chunk.

    Returns
    -------
    dict
        ``start``, ``count``, ``total``; ``points``: ``x``, ``y`` (2-D only), ``error``
        (``field: message`` or None) and ``error_zh`` per point, ``integers`` {name: {value, error_pct,
        status}} as columns, ``intermediates`` {name: column}; ``summary`` (see :func:`merge`).
    """
    total = plan.total
    if isinstance(start, bool) or not isinstance(start, int) or not 0 <= start <= total:
        raise InputError("sweep.chunk.start", code="integer_range", lo=0, hi=total, got=shown(start))
    if count is None:
        count = total - start
    if isinstance(count, bool) or not isinstance(count, int) or not 0 <= count <= total - start:
        raise InputError("sweep.chunk.count", code="integer_range", lo=0, hi=total - start,
                         got=shown(count))
    nx = len(plan.x.values)
    ys = plan.y.values if plan.y else (None,)
    cache: dict = {}

    def point(k: int) -> _Point:
        if k not in cache:
            cache[k] = _evaluate(plan, _input_at(plan, plan.x.values[k % nx], ys[k // nx]))
        return cache[k]

    stop = start + count
    cols = {name: {"value": [], "error_pct": [], "status": []} for name in plan.names}
    inter_names: list = []
    pts: dict = {"x": [], "error": [], "error_zh": [], "integers": cols, "intermediates": {}}
    if plan.y:
        pts["y"] = []
    boundaries: list = []
    worst: dict = {}
    per = _new_stats(plan)
    for k in range(start, stop):
        i, j = k % nx, k // nx
        p = point(k)
        pts["x"].append(plan.x.values[i])
        if plan.y:
            pts["y"].append(ys[j])
        pts["error"].append(p.error)
        pts["error_zh"].append(p.error_zh)
        for key, v in p.intermediates.items():
            if key not in pts["intermediates"]:
                inter_names.append(key)
                pts["intermediates"][key] = [None] * (k - start)
        for key in inter_names:
            pts["intermediates"][key].append(p.intermediates.get(key))
        for name in plan.names:
            s = p.states[name]
            c = cols[name]
            c["value"].append(s["value"])
            c["error_pct"].append(s["error_pct"])
            c["status"].append(s["status"])
            st = per[name]
            st["counts"][s["status"]] += 1
            if s["error_pct"] is not None:
                e = abs(s["error_pct"])
                for t in ERROR_THRESHOLDS_PCT:
                    if e >= t:
                        st["over_pct"][f"{t:g}"] += 1
                if st["max_abs_error_pct"] is None or e > st["max_abs_error_pct"]:
                    st["max_abs_error_pct"] = e
            score = _score(s)
            if score[0] >= 0 and (name not in worst or score > worst[name][0]):
                worst[name] = (score, k, s)
        neighbours = []
        if i > 0:
            neighbours.append(("x", k - 1, plan.x.values[i - 1], plan.x.values[i], ys[j]))
        if j > 0:
            neighbours.append(("y", k - nx, ys[j - 1], ys[j], plan.x.values[i]))
        for axis, kp, a, b, other in neighbours:
            q = point(kp)
            for name in plan.names:
                if q.states[name]["status"] != p.states[name]["status"]:
                    boundaries += _boundaries(plan, name, axis, a, q, b, p, other, k)
    summary = {
        "boundaries": boundaries,
        "worst": [_worst_entry(plan, name, k, s, nx) for name, (_, k, s) in worst.items()],
        "per_integer": per,
    }
    if start == 0 and count > 0:
        summary["first"] = {name: cols[name]["status"][0] for name in plan.names}
    return {"start": start, "count": count, "total": total, "points": pts, "summary": summary}


def _worst_entry(plan: Plan, name: str, k: int, s: dict, nx: int) -> dict:
    ys = plan.y.values if plan.y else (None,)
    xv, yv = plan.x.values[k % nx], ys[k // nx]
    return {"name": name, "index": k, "x": xv, "y": yv, "status": s["status"],
            "value": s["value"], "error_pct": s["error_pct"], "message": s["message"],
            "message_zh": s["message_zh"], "input": _input_at(plan, xv, yv)}


def merge(plan: Plan, summaries: list) -> dict:
    """One summary from the summaries of chunks that together cover the sweep.

    Returns
    -------
    dict
        ``boundaries`` (sorted by integer, then position), ``worst`` (per integer the point
        ranked worst: div0 > wrap > store > zero > ok, then by |error|), ``per_integer``
        (``counts`` per status, ``over_pct`` = points with |error| ≥ 0.1, 1, 5 %,
        ``max_abs_error_pct``) and, for a 1-D sweep, ``regions``: per integer the runs of one
        status from boundary to boundary, ``{"status", "from", "to"}`` in axis values.
    """
    try:
        return _merge(plan, summaries)
    except (KeyError, TypeError, AttributeError, ValueError):
        # Summaries come back from a page: anything but chunk summaries of this plan is refused.
        raise InputError("sweep.summaries", code="summaries_list") from None


def _new_stats(plan: Plan) -> dict:
    return {name: {"counts": dict.fromkeys(STATUSES, 0),
                   "over_pct": {f"{t:g}": 0 for t in ERROR_THRESHOLDS_PCT},
                   "max_abs_error_pct": None} for name in plan.names}


def _merge(plan: Plan, summaries: list) -> dict:
    boundaries, worst = [], {}
    per = _new_stats(plan)
    first = None
    for s in summaries:
        boundaries += s["boundaries"]
        first = s.get("first", first)
        for w in s["worst"]:
            score = (_RANK[w["status"]], abs(w["error_pct"] or 0.0), -w["index"])
            if w["name"] not in worst or score > worst[w["name"]][0]:
                worst[w["name"]] = (score, w)
        for name, st in s["per_integer"].items():
            m = per[name]
            for key in ("counts", "over_pct"):
                for k, v in st[key].items():
                    m[key][k] += v
            e = st["max_abs_error_pct"]
            if e is not None and (m["max_abs_error_pct"] is None or e > m["max_abs_error_pct"]):
                m["max_abs_error_pct"] = e
    order = {name: i for i, name in enumerate(plan.names)}
    # Stable: a chain a→c→b found between two points keeps its order.
    boundaries.sort(key=lambda b: (order[b["name"]], b["axis"], b["index"]))
    out = {"boundaries": boundaries,
           "worst": [w for name in plan.names if name in worst for w in [worst[name][1]]],
           "per_integer": per}
    if plan.y is None and first is not None:
        out["regions"] = _regions(plan, boundaries, first)
    return out


def _regions(plan: Plan, boundaries: list, first: dict) -> dict:
    regions = {}
    for name in plan.names:
        runs, status, lo = [], first[name], plan.x.values[0]
        for b in boundaries:
            if b["name"] == name:
                runs.append({"status": status, "from": lo, "to": b["before"]})
                status, lo = b["to"], b["at"]
        runs.append({"status": status, "from": lo, "to": plan.x.values[-1]})
        regions[name] = runs
    return regions


def sweep(req: dict) -> dict:
    """A whole sweep: the plan's axes, every point and the merged summary.

    Parameters
    ----------
    req : dict
        As for :func:`make_plan`.

    Returns
    -------
    dict
        ``profile``, ``names`` (the integers, report paths), ``x`` and ``y`` axes
        (``path``, ``scale``, ``values``, ``integer``), ``points`` (see :func:`chunk`) and
        ``summary`` (see :func:`merge`).
    """
    plan = make_plan(req)
    c = chunk(plan)
    return {**describe(plan), "points": c["points"], "summary": merge(plan, [c["summary"]])}


def describe(plan: Plan) -> dict:
    """The plan as JSON: profile, integer names, axes and the number of points."""
    return {"profile": plan.profile, "names": list(plan.names), "total": plan.total,
            "x": plan.x._asdict() | {"values": list(plan.x.values)},
            "y": None if plan.y is None else plan.y._asdict() | {"values": list(plan.y.values)}}

