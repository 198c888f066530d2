#!/usr/bin/env bash
# npm test: Python suite (creates .venv on first use), then the vitest suites, then end-to-end.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/pytest.sh
npx vitest run
node tests/e2e/run.mjs
