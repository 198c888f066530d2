#!/usr/bin/env bash
# Creates .venv with the locked test tools on first use (pulab itself is stdlib-only).
# tests/requirements.txt pins every package, transitive ones too, with hashes (pip then installs
# nothing else); scripts/lock.sh regenerates it from tests/requirements.in.
set -euo pipefail
cd "$(dirname "$0")/.."
stamp=.venv/.requirements.sha
want=$(sha1sum tests/requirements.txt | cut -d' ' -f1)
if [ ! -x .venv/bin/python ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  python3 -m venv .venv
  .venv/bin/pip install --quiet --disable-pip-version-check --require-hashes --no-deps \
    -r tests/requirements.txt
  echo "$want" > "$stamp"
fi
