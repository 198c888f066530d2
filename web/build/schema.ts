// Build time: pulab's input schema (py/pulab/schema/fields.py) written as web/src/generated/schema.json
// by the same CPython the prerender runs, so the form, its field checks and its labels are never
// hand-copied from Python. The file is committed (tests and type checks read it without a build);
// tests/py/test_schema.py fails when it is stale.
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { REPO, python } from './prerender';

export const SCHEMA_FILE = resolve(REPO, 'web/src/generated/schema.json');

/** Write the schema file when pulab's schema says something else; returns whether it changed. */
export function writeSchema(): boolean {
  const text = execFileSync(python(), ['-c', 'import sys; from pulab.schema.fields import schema_json; sys.stdout.write(schema_json())'], {
    cwd: REPO, env: { ...process.env, PYTHONPATH: resolve(REPO, 'py') },
  }).toString();
  if (readFileSync(SCHEMA_FILE, 'utf8') === text) return false;
  writeFileSync(SCHEMA_FILE, text);
  return true;
}
