#!/usr/bin/env bash
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/venv.sh
PYTHONPATH=py .venv/bin/python -m pytest -q tests/py "$@"
