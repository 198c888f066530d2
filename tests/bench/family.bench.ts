// The family-view benchmark (tests/bench/family_bench.py) in Pyodide/Node: the sweeps the page
// runs, timed in the same Python the worker runs. Target: a 1,000-point sweep ≤ 1 s.
import { it } from 'vitest';
import { readFileSync } from 'node:fs';
import { bootPulab } from '../web/pulab-node';

it('prints the Pyodide sweep medians', async () => {
  const { py } = await bootPulab();
  const src = readFileSync(new URL('./family_bench.py', import.meta.url), 'utf8');
  py.runPython(src.replace(/\nif __name__ == "__main__":[\s\S]*$/, '\n'));
  const text = py.runPython('import sys\nformat_sweeps(sweep_timing(), "Pyodide " + sys.version.split()[0])') as string;
  process.stdout.write(`\nfamily view benchmark (Pyodide in Node):\n${text}\n`);
});
