// The family-proof benchmark (tests/bench/prove_bench.py) in Pyodide/Node, the Python the page's
// worker runs. Target: a 6-dimensional box decided in ≤ 10 s.
import { it } from 'vitest';
import { readFileSync } from 'node:fs';
import { bootPulab } from '../web/pulab-node';

it('prints the Pyodide proof medians', async () => {
  const { py } = await bootPulab();
  const src = readFileSync(new URL('./prove_bench.py', import.meta.url), 'utf8');
  py.runPython(src.replace(/\nif __name__ == "__main__":[\s\S]*$/, '\n'));
  const text = py.runPython('import sys\nformat_proofs(prove_timing(3), "Pyodide", "≤ 10 s") + "\\n" + format_proposals(propose_timing(1))') as string;
  process.stdout.write(`\nfamily proof benchmark (Pyodide ${String(py.runPython('sys.version.split()[0]'))} in Node):\n${text}\n`);
});
