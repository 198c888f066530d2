// `npm run bench`, Pyodide side: boots Pyodide from node_modules with the worker's own loader
// (web/src/worker-logic.ts is TypeScript, so the file loading is mirrored here in plain JS),
// runs scripts/bench-report.py inside it and prints the numbers next to CPython's.
import { loadPyodide } from 'pyodide';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../', import.meta.url));
const cpy = JSON.parse(process.argv[2] ?? 'null');

const t0 = performance.now();
const py = await loadPyodide({ indexURL: join(ROOT, 'node_modules/pyodide/') });
const bootMs = performance.now() - t0;
const root = '/home/pyodide/pulab_src';
function copy(dir, rel) {
  for (const f of readdirSync(dir)) {
    const p = join(dir, f);
    if (statSync(p).isDirectory()) {
      if (f !== '__pycache__') copy(p, `${rel}/${f}`);
    } else if (f.endsWith('.py')) {
      py.FS.mkdirTree(`${root}/${rel}`);
      py.FS.writeFile(`${root}/${rel}/${f}`, readFileSync(p, 'utf8'));
    }
  }
}
copy(join(ROOT, 'py/pulab'), 'pulab');
py.runPython(`import sys; sys.path.insert(0, ${JSON.stringify(root)})`);
const t1 = performance.now();
py.runPython('import pulab.api');
const importMs = performance.now() - t1;
py.runPython(readFileSync(join(ROOT, 'scripts/bench-report.py'), 'utf8').replace(/if __name__ == "__main__":[\s\S]*$/, ''));
const pyo = JSON.parse(py.runPython('main()'));

const f = (x, d = 2) => (typeof x === 'number' ? x.toFixed(d) : '—');
console.log(`Pyodide ${py.version}: boot ${f(bootMs, 0)} ms, import pulab ${f(importMs, 0)} ms`);
console.log('');
console.log('                                   CPython     Pyodide/Node   ratio');
const row = (name, a, b, unit, target) =>
  console.log(`${name.padEnd(34)} ${`${f(a, 3)} ${unit}`.padStart(10)}  ${`${f(b, 3)} ${unit}`.padStart(13)}   ${a && b ? `${f(b / a, 1)}×` : '—'}${target ? `   (target ${target})` : ''}`);
row('report() per call', cpy?.report_ms, pyo.report_ms, 'ms', '< 5 ms in Pyodide');
if (pyo.sim) {
  row(`sim: ${pyo.sim.steps} steps × 3 variants`, cpy?.sim?.total_s, pyo.sim.total_s, 's', '< 0.5 s CPython, < 1 s Pyodide');
  row('sim: steps/s (all three)', cpy?.sim?.steps_per_s, pyo.sim.steps_per_s, '/s');
  row('sim: fixed variant, no memo', cpy?.sim?.fixed_no_memo_s, pyo.sim.fixed_no_memo_s, 's');
}
