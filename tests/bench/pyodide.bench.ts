// The core benchmark (py/pulab/benchmark.py) in Pyodide/Node, booted the way the worker boots,
// printed next to the CPython numbers that scripts/bench.sh measured just before.
import { it } from 'vitest';
import { readFileSync, existsSync } from 'node:fs';
import { bootPulab } from '../web/pulab-node';

interface Run {
  python: string;
  report_ms: Record<string, number>;
  sim: { steps: number; total_s: number; steps_per_s: number; fixed_no_memo_s: number };
  trace?: { lines: number; median_ms: number; p95_ms: number };
}

it('prints the Pyodide benchmark and the Pyodide/CPython ratio', async () => {
  const pulab = await bootPulab();
  const py = pulab.py;
  const text = py.runPython('import json, pulab.benchmark as b\njson.dumps(b.run())') as string;
  const pyo = JSON.parse(text) as Run;
  const fmt = py.runPython(`b.format_run(json.loads(${JSON.stringify(text)}))`) as string;
  const cpyPath = process.env.BENCH_CPYTHON_JSON ?? '';
  const lines = [`Pyodide boot in Node: ${pulab.bootMs.toFixed(0)} ms`, fmt];
  if (cpyPath && existsSync(cpyPath)) {
    const cpy = JSON.parse(readFileSync(cpyPath, 'utf8')) as Run;
    for (const k of Object.keys(pyo.report_ms)) {
      lines.push(`  Pyodide/CPython report(), ${k}: ${(pyo.report_ms[k] / cpy.report_ms[k]).toFixed(2)}×`);
    }
    lines.push(`  Pyodide/CPython sim: ${(pyo.sim.total_s / cpy.sim.total_s).toFixed(2)}×`);
    if (pyo.trace && cpy.trace) {
      lines.push(`  Pyodide/CPython trace() median: ${(pyo.trace.median_ms / cpy.trace.median_ms).toFixed(2)}×`);
    }
  }
  process.stdout.write(`\n${lines.join('\n')}\n`);
});
