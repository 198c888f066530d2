"""The ``robust`` subcommand: one drive's ``loop.robust``, or a catalogue × tolerance study.

::

    pulab robust INPUT.json                                  # loop.robust as JSON
    pulab robust --catalogue motors.csv --samples N [--seed S] [--jobs N]
                 [--scheduler ADDRESS] [INPUT.json]           # one CSV row per motor

The study: every motor of the CSV (columns as ``pulab batch`` reads them) with the
``analysis`` of INPUT.json (optional; ``{"robust": {}}`` otherwise) gets its worst case and
``N`` tolerance samples drawn with ``random.Random(S + row)`` around it.  One task per motor,
each deterministic, so ``--jobs 1``, ``--jobs N`` (processes of this machine, the standard
library's multiprocessing) and ``--scheduler`` (a Dask scheduler: ``pip install
'pulab[dask]'``) give the same numbers.  A progress bar goes to stderr.

Exit status: 0; 2 with one line ``error: FIELD: MESSAGE`` on stderr when the input is
unusable; 1 when some catalogue rows are errors (one stderr line each, still in the output).
"""

from __future__ import annotations

import json
import os
import sys

from ..schema.errors import InputError

__all__ = ["add_robust_parser", "study_tasks", "run_task", "run_study"]

COLUMNS = ("row", "name", "worst_case", "worst_phase_margin_deg", "min_phase_margin_deg",
           "below", "samples", "error")


def add_robust_parser(sub) -> None:
    p = sub.add_parser("robust", help="current-loop margins of the nominal gains on a drifted "
                                      "motor; a catalogue × tolerance study")
    p.add_argument("input", nargs="?", help="input JSON ('-' = stdin); with --catalogue, the "
                                            "analysis to apply to every motor")
    p.add_argument("--catalogue", help="a motors CSV (as pulab batch reads it)")
    p.add_argument("--samples", type=int, default=1000, help="tolerance samples per motor")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                   help="worker processes on this machine (default: every core)")
    p.add_argument("--scheduler", help="a Dask scheduler address (pip install 'pulab[dask]')")
    p.set_defaults(run=_run)


def study_tasks(csv_text: str, analysis: dict, samples: int, seed: int) -> list:
    """One task tuple per catalogue row: (row, name, input or error text, analysis, n, seed)."""
    from ..analyses.batch import _row_input, read_table
    columns, rows = read_table(csv_text)
    names = [n for n, _ in columns]
    tasks = []
    for k, cells in enumerate(rows):
        name = cells[names.index("name")].strip() if "name" in names else ""
        try:
            inp = _row_input(columns, cells)
        except InputError as e:
            inp = f"{e.field}: {e.message}"
        tasks.append((k + 1, name, inp, analysis, samples, seed + k + 1))
    return tasks


def run_task(task: tuple) -> dict:
    """A study row: the worst case and the tolerance samples of one motor (any process)."""
    from .. import report
    from ..analyses.loop import robust, validate
    row, name, inp, analysis, samples, seed = task
    out = {"row": row, "name": name}
    if isinstance(inp, str):
        return {**out, "error": inp}
    try:
        cfg = validate(analysis)
        r = report(inp)
        out.update(robust.study_row(r, cfg["robust"] or robust.settings({}), cfg["delay"],
                                    samples, seed, 0))
    except InputError as e:
        out["error"] = f"{e.field}: {e.message}"
    return out


def _progress(done: int, total: int) -> None:
    width = 30
    fill = width * done // max(total, 1)
    sys.stderr.write(f"\r[{'#' * fill}{'.' * (width - fill)}] {done}/{total}")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def run_study(tasks: list, jobs: int = 1, scheduler: str | None = None,
              progress=_progress) -> list:
    """Every task's row, in task order, on this process, a local pool or a Dask scheduler."""
    results: list = [None] * len(tasks)
    done = 0
    if scheduler:
        try:
            from dask.distributed import Client, as_completed
        except ImportError:
            raise InputError("--scheduler", code="cli_needs_dask") from None
        with Client(scheduler) as client:
            futures = client.map(run_task, tasks, pure=False)
            index = {f.key: k for k, f in enumerate(futures)}
            for f in as_completed(futures):
                results[index[f.key]] = f.result()
                done += 1
                progress(done, len(tasks))
        return results
    if jobs <= 1:
        for k, t in enumerate(tasks):
            results[k] = run_task(t)
            progress(k + 1, len(tasks))
        return results
    import multiprocessing
    with multiprocessing.get_context("spawn").Pool(jobs) as pool:
        for k, row in enumerate(pool.imap(run_task, tasks)):
            results[k] = row
            progress(k + 1, len(tasks))
    return results


def _run(args) -> int:
    from .family import read_json, read_text
    try:
        if args.jobs < 1:
            raise InputError("--jobs", code="at_least", lo=1, got=args.jobs)
        if args.catalogue is None:
            if args.input is None:
                raise InputError("input", code="cli_input_or_catalogue")
            from .. import report
            inp = read_json(args.input)
            if not isinstance(inp, dict):
                raise InputError("input", code="not_json_object")
            analysis = inp.get("analysis") or {}
            if not isinstance(analysis, dict):
                raise InputError("analysis", code="object_required")
            if analysis.get("robust") is None:
                inp = {**inp, "analysis": {**analysis, "robust": {}}}
            out = report(inp)["loop"]["robust"]
            json.dump(out, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
            sys.stdout.write("\n")
            return 0
        if args.samples < 0:
            raise InputError("--samples", code="at_least", lo=0, got=args.samples)
        analysis = {"robust": {}}
        if args.input is not None:
            inp = read_json(args.input)
            analysis = (inp.get("analysis") if isinstance(inp, dict) else None) or analysis
        from ..analyses.loop import validate
        validate(analysis)
        tasks = study_tasks(read_text(args.catalogue), analysis, args.samples, args.seed)
        rows = run_study(tasks, args.jobs, args.scheduler)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    json.dump(rows, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
    sys.stdout.write("\n")
    bad = [r for r in rows if "error" in r]
    for r in bad:
        print(f"row {r['row']}: {r['error']}", file=sys.stderr)
    return 1 if bad else 0
