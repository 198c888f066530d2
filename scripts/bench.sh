#!/usr/bin/env bash
# npm run bench: speed numbers (not tests). Core in CPython, then the same code in Pyodide/Node.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/venv.sh
out=$(mktemp)
PYTHONPATH=py .venv/bin/python -m pulab.benchmark --json > "$out"
PYTHONPATH=py .venv/bin/python -c "import json,sys; from pulab.benchmark import format_run; print(format_run(json.load(open(sys.argv[1]))))" "$out"
BENCH_CPYTHON_JSON="$out" npx vitest run --config tests/bench/vitest.config.ts --reporter dot
rm -f "$out"
if [ -f tests/e2e/bench-page.mjs ]; then node tests/e2e/bench-page.mjs; fi
# The family view: sweeps and a 10,000-row batch in CPython (the Pyodide sweeps are
# tests/bench/family.bench.ts, in the vitest run above).
PYTHONPATH=py .venv/bin/python tests/bench/family_bench.py
# Family proofs: 6-dimensional boxes (the Pyodide numbers are tests/bench/prove.bench.ts above).
PYTHONPATH=py .venv/bin/python tests/bench/prove_bench.py
# The tracer on its 60-line unit (add --before REV to compare builds side by side).
PYTHONPATH=py .venv/bin/python tests/bench/trace_bench.py
# Code proofs: a PI routine with six ranged inputs (the Pyodide numbers are
# tests/bench/code-prove.bench.ts above).
PYTHONPATH=py .venv/bin/python tests/bench/code_prove_bench.py
