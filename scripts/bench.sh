#!/usr/bin/env bash
# npm run bench: report() (and the simulation, when present) in CPython and in Pyodide/Node.
# Prints numbers; not a test. The page's own latencies are printed by `node tests/e2e/run.mjs`.
set -euo pipefail
cd "$(dirname "$0")/.."
cpy=$(PYTHONPATH=py python3 scripts/bench-report.py)
node scripts/bench-pyodide.mjs "$cpy"
