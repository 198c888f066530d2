// The code-proof benchmark (tests/bench/code_prove_bench.py) in Pyodide/Node, the Python the
// page's worker runs.
import { it } from 'vitest';
import { readFileSync } from 'node:fs';
import { bootPulab } from '../web/pulab-node';

it('prints the Pyodide code-proof medians', async () => {
  const { py } = await bootPulab();
  const src = readFileSync(new URL('./code_prove_bench.py', import.meta.url), 'utf8');
  const code = readFileSync(new URL('./pi_step.c', import.meta.url), 'utf8');
  py.runPython(src.replace(/\nif __name__ == "__main__":[\s\S]*$/, '\n'));
  py.globals.set('PI_CODE', code);
  const text = py.runPython('format_code_proofs(code_prove_timing(PI_CODE))') as string;
  process.stdout.write(`\ncode proof benchmark (Pyodide ${String(py.runPython('import sys; sys.version.split()[0]'))} in Node, 6 ranged inputs):\n${text}\n`);
});
