#!/usr/bin/env bash
# Regenerates tests/requirements.txt (every test package, transitive ones included, pinned with
# hashes) from tests/requirements.in. Run it after changing the .in file; commit both.
# pip-tools runs from a throw-away venv, so the lock does not depend on what .venv holds.
set -euo pipefail
cd "$(dirname "$0")/.."
tools=$(mktemp -d)
trap 'rm -rf "$tools"' EXIT
python3 -m venv "$tools"
"$tools/bin/pip" install --quiet --disable-pip-version-check pip-tools==7.6.2
"$tools/bin/pip-compile" --quiet --generate-hashes --allow-unsafe --strip-extras \
  --no-emit-index-url --output-file tests/requirements.txt tests/requirements.in
