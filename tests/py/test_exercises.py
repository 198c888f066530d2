"""The course's exercises (pulab.analyses.exercises) against tests/oracle/course_oracle.py, which
recomputes every expected answer without pulab, for several trainee motors."""

from __future__ import annotations

import json
import math
import pathlib
import sys

import pytest

from pulab import api
from pulab.analyses import exercises
from pulab.schema.errors import InputError

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "oracle"))
import course_oracle  # noqa: E402

#: Floats: the oracle and pulab compute the same formulas in another order; the base frequency of
#: pi-choose-fb is pulab's bisection on its review against the oracle's closed form; the base
#: speed of fw-base is pulab's closed-form MTPA against the oracle's numeric maximum of the torque,
#: whose angle a flat maximum fixes only to about √ε (1e-8 relative); the phase margin of
#: audit-st-pm is pulab's exact polynomial roots against python-control's (the loop goldens' 1e-6).
REL = 1e-9
REL_FB = 1e-6
ROUGH = {"pi-choose-fb", "fw-base", "audit-st-pm"}


@pytest.mark.parametrize("n", sorted(course_oracle.TRAINEES))
def test_trainee_motor_is_pinned(n):
    # a link a trainer handed out must keep its motor
    assert exercises.trainee_input(n) == course_oracle.TRAINEES[n]


@pytest.mark.parametrize("n", sorted(course_oracle.TRAINEES))
def test_answers_match_oracle(n):
    inp = course_oracle.TRAINEES[n]
    want = course_oracle.expected(inp)
    got = {k: v["expected"] for k, v in exercises.answers(inp).items()}
    assert set(got) == set(want)
    for k, w in want.items():
        g = got[k]
        if isinstance(w, float):
            rel = REL_FB if k in ROUGH else REL
            assert isinstance(g, float) and math.isclose(g, w, rel_tol=rel, abs_tol=1e-12), (k, g, w)
        else:
            assert type(g) is type(w) and g == w, (k, g, w)


def test_every_day_one_chapter_has_five_exercises():
    by = {}
    for e in exercises.EXERCISES:
        by.setdefault(e.chapter, []).append(e.id)
    day_one = json.loads((pathlib.Path(__file__).resolve().parents[2] / "docs" / "course.json").read_text())["day_one"]
    for step in day_one:
        for ch in step["chapters"]:
            assert len(by.get(ch, [])) >= 5, ch


def _perturbed(e, v):
    """An answer just outside the stated tolerance."""
    if e.kind == "choice":
        return next(c for c in e.choices if c != v)
    if e.kind == "base":  # above the largest base frequency, or f_n when none is accepted
        return repr(v * 1.01 if v else 1.0 * 10 ** 9)
    if e.kind == "int":
        return str(v + int(e.tol) + 1)
    step = e.tol * 1.5 if e.unit == "%" else abs(v) * e.tol * 1.5
    return repr(v + step)


@pytest.mark.parametrize("n", [0, 3, 14])
def test_check_accepts_oracle_answer_and_rejects_outside_tolerance(n):
    inp = course_oracle.TRAINEES[n]
    want = course_oracle.expected(inp)
    for e in exercises.EXERCISES:
        w = want[e.id]
        typed = w if e.kind == "choice" else (str(w) if e.kind == "int" else
                                               repr(w * (1 - 1e-5)) if e.kind == "base" else f"{w:.6g}")
        assert exercises.check(inp, e.id, typed)["state"] == "correct", (e.id, typed)
        assert exercises.check(inp, e.id, _perturbed(e, w))["state"] == "wrong", e.id


def test_tolerance_edges():
    inp = course_oracle.TRAINEES[0]
    assert exercises.check(inp, "pi-pm-kp", "1181")["state"] == "correct"  # ±1 stated
    assert exercises.check(inp, "pi-pm-kp", "1182")["state"] == "wrong"
    assert exercises.check(inp, "vendor-rpm", "15023")["state"] == "wrong"  # exact
    assert exercises.check(inp, "warmup-ub", "9.86")["state"] == "correct"  # ±1 %
    assert exercises.check(inp, "warmup-ub", "17")["state"] == "wrong"  # the line voltage
    assert exercises.check(inp, "warmup-ub", "９.８１")["state"] == "correct"  # typed like the form


@pytest.mark.parametrize("answer, code", [("", "required"), ("abc", "not_number"), ("1e999", "not_finite")])
def test_bad_answer_names_the_field(answer, code):
    with pytest.raises(InputError) as e:
        exercises.check(course_oracle.TRAINEES[0], "warmup-ub", answer)
    assert e.value.field == "exercise.warmup-ub" and e.value.code == code


def _call(kind, req):
    return json.loads(api.call_json(kind, json.dumps(req, allow_nan=True)))


def test_api_errors_are_data():
    inp = course_oracle.TRAINEES[0]
    r = _call("course.check", {"input": inp, "id": "nope", "answer": 1})
    assert r["ok"] is False and r["field"] == "id" and r["code"] == "unknown_exercise"
    r = _call("course.check", {"input": inp, "id": "q-fit", "answer": "Q99"})
    assert r["field"] == "exercise.q-fit" and r["code"] == "not_choice"
    r = _call("course.check", {"input": {"motor": {}}, "id": "vendor-rpm", "answer": "1"})
    assert r["field"] == "motor.rated_voltage_v"
    r = _call("course.trainees", {"start": 1, "count": 0})
    assert r["field"] == "count"
    r = _call("course.trainees", {"start": 9999, "count": 2})
    assert r["field"] == "trainee"
    r = _call("course.trainees", {"start": 1, "count": 3})
    assert [t["n"] for t in r["trainees"]] == [1, 2, 3]
    assert len(_call("course.spec", {})["exercises"]) == len(exercises.EXERCISES)
    assert _call("course.answers", {"input": inp})["answers"]["vendor-rpm"]["expected"] == 15022


def test_chapters_hold_exactly_the_engines_exercises():
    # docs/{zh,en}/*.md: `::: exercise ID [choice A B …] [trace]` — each id once per language, in the
    # chapter pulab files it under, with pulab's choices in pulab's order.
    import re
    docs = pathlib.Path(__file__).resolve().parents[2] / "docs"
    by_id = {e.id: e for e in exercises.EXERCISES}
    for lang in ("zh", "en"):
        seen = {}
        for f in sorted((docs / lang).glob("*.md")):
            for m in re.finditer(r"^:::\s*exercise\s+(\S+)(.*)$", f.read_text(encoding="utf-8"), re.M):
                ex_id, opts = m.group(1), m.group(2).split()
                assert ex_id in by_id and ex_id not in seen, (lang, f.name, ex_id)
                seen[ex_id] = f.stem
                e = by_id[ex_id]
                assert f.stem == e.chapter, (lang, ex_id)
                choices = tuple(o for o in opts[1:] if o != "trace") if opts[:1] == ["choice"] else ()
                assert choices == e.choices, (lang, ex_id, choices)
        assert set(seen) == set(by_id), (lang, set(by_id) - set(seen))


BAD = [None, True, -1, 0, 1e308, float("nan"), "", "x" * 500, "１２", [], {}, [1], {"a": 1}, "0x10", "1,000"]


def test_course_kinds_never_raise_and_name_a_field():
    # every reply is JSON: ok, or an error with a field (bad input never crashes or hangs)
    inp = course_oracle.TRAINEES[0]
    reqs = [("course.trainees", v) for v in BAD] + [("course.answers", v) for v in BAD]
    reqs += [("course.trainees", {"start": s, "count": c}) for s in BAD[:6] for c in BAD[:6]]
    reqs += [("course.check", {"input": inp, "id": i, "answer": a})
             for i in BAD[:8] + ["q-fit", "vendor-rpm", "warmup-ub", "pi-choose-fb"] for a in BAD]
    reqs += [("course.answers", {"input": v}) for v in BAD]
    for kind, r in reqs:
        out = _call(kind, r)
        assert out["ok"] is True or (isinstance(out["field"], str) and out["field"] and out["message"]), (kind, r, out)
    assert json.loads(api.call_json("course.check", "[1, 2"))["ok"] is False
