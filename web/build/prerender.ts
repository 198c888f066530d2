// Build time: the default (seed) report computed by the same pulab code in CPython, so the page
// paints numbers before Python has started in the browser (issue 8). The page recognises the
// input by its key: the exact JSON text its worker would hand to pulab.api.call_json("report", …).
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { SEED_INPUT, reportKey } from '../src/state';

export const REPO = fileURLToPath(new URL('../../', import.meta.url));

/** The JSON text the page sends for the seed input (`reportInput(effectiveInput(input))`). */
export function seedKey(): string {
  return reportKey(SEED_INPUT);
}

/** The project's Python (the venv if made, else python3 from PATH); pulab needs only the standard library. */
export function python(): string {
  const venv = resolve(REPO, '.venv/bin/python');
  return process.env.PULAB_PYTHON ?? (existsSync(venv) ? venv : 'python3');
}

/** pulab.api.call_json("report", key) in CPython: the exact text the worker's Pyodide returns for `key`. */
export function reportCPython(key: string): string {
  return execFileSync(python(), ['-c', 'import sys; from pulab.api import call_json; sys.stdout.write(call_json("report", sys.stdin.read()))'], {
    cwd: REPO, env: { ...process.env, PYTHONPATH: resolve(REPO, 'py') }, input: key,
  }).toString();
}
