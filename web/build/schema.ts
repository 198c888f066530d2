// Build time: pulab's input schema (py/pulab/schema/fields.py) written as web/src/generated/schema.json,
// and the report's and the API's shapes (py/pulab/schema/report_shapes.py, api_shapes.py) as
// web/src/generated/report-types.ts and api-types.ts, by the same CPython the prerender runs, so the
// form, its field checks, its labels and the types of what pulab returns are never hand-copied from
// Python. The files are committed (tests and type checks read them without a build);
// tests/py/test_schema.py and tests/py/test_shapes.py fail when they are stale.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { REPO, python } from './prerender';

const GENERATE = [
  'import json, sys',
  'from pulab.schema.fields import schema_json',
  'from pulab.schema.typings import typescript_files',
  'sys.stdout.write(json.dumps({"web/src/generated/schema.json": schema_json(), **typescript_files()}))',
].join('\n');

/** Write each generated file whose text pulab now says differently; returns whether any changed. */
export function writeSchema(): boolean {
  const files = JSON.parse(execFileSync(python(), ['-c', GENERATE], {
    cwd: REPO, env: { ...process.env, PYTHONPATH: resolve(REPO, 'py') },
  }).toString()) as Record<string, string>;
  let changed = false;
  for (const [path, text] of Object.entries(files)) {
    const file = resolve(REPO, path);
    if (existsSync(file) && readFileSync(file, 'utf8') === text) continue;
    writeFileSync(file, text);
    changed = true;
  }
  return changed;
}
