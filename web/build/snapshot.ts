// Build time: a Pyodide memory snapshot taken after every pulab module is imported, so a worker
// boots from it in a fraction of a normal boot (issue 8). Pyodide's snapshot API is private
// (`_makeSnapshot`, `makeMemorySnapshot`, `_loadSnapshot`), so it is used only with the version it
// was written against, and every snapshot is loaded back in Node and checked before it ships;
// the worker falls back to a normal boot whenever the snapshot is missing or refused.
import { loadPyodide, version } from 'pyodide';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { writePulab, type PyodideLike } from '../src/worker-logic';

/** The Pyodide release whose private snapshot API this file was written and tested against. */
export const SNAPSHOT_PYODIDE_VERSION = '314.0.7';
/** Above this the snapshot is not shipped: Pyodide sizes the initial heap from it, and a
 * larger heap made loads fail (RangeError) in the spikes of issue 8. */
export const SNAPSHOT_MAX_BYTES = 48 * 1024 * 1024;

interface SnapshotPyodide extends PyodideLike {
  makeMemorySnapshot(): Uint8Array;
  _module: { _malloc(n: number): number; _free(p: number): void; _sbrk(n: number): number; HEAPU8: Uint8Array };
}

/**
 * Zero the heap's free memory below the allocator's break before the snapshot is taken: malloc
 * keeps what freed blocks held, and those pages were shipped (and decompressed, and copied into
 * every runtime's memory) for nothing. Every block malloc hands out below the break is taken,
 * zeroed and given back; what Python holds is not touched. Returns the bytes zeroed.
 */
export function zeroFreeMemory(m: SnapshotPyodide['_module']): number {
  const brk = m._sbrk(0);
  const taken: number[] = [];
  let zeroed = 0;
  for (let size = 1 << 20; size >= 16;) {
    const p = m._malloc(size);
    if (p === 0 || p + size > brk) {
      if (p !== 0) m._free(p);
      size >>= 1;
      continue;
    }
    m.HEAPU8.fill(0, p, p + size);
    taken.push(p);
    zeroed += size;
  }
  for (const p of taken) m._free(p);
  return zeroed;
}

/** py/pulab/**.py keyed as the bundle's glob keys ('../../py/pulab/api.py'), as writePulab takes them. */
export function pulabFiles(repo: string): Record<string, string> {
  const out: Record<string, string> = {};
  const walk = (dir: string): void => {
    for (const f of readdirSync(dir)) {
      const p = join(dir, f);
      if (statSync(p).isDirectory()) walk(p);
      else if (f.endsWith('.py')) out[`../../${relative(repo, p)}`] = readFileSync(p, 'utf8');
    }
  };
  walk(join(repo, 'py/pulab'));
  return out;
}

/**
 * Python run before the snapshot is taken: every module a worker call imports (the loop analysis,
 * the vendor profiles and the C tracer were imported on first use, from source: 0.3 s in the
 * worker for the first panel that asked), and `key`'s report with both optional sections, so
 * the first call after a boot runs warm.
 */
function warm(key: string): string {
  return `import json, pulab, pulab.api, pulab.analyses.sim, pulab.export, pulab.analyses.loop, pulab.profiles, pulab.ctrace, pulab.analyses.sweep, pulab.analyses.batch
seed = json.loads(${JSON.stringify(key)})
pulab.api.call_json("report", json.dumps(seed))
pulab.api.call_json("report", json.dumps({**seed, "profiles": {}, "analysis": {}}))
pulab.api.call_json("trace.examples", "{}")`;
}

export type SnapshotResult = { ok: true; bytes: Uint8Array; ms: number } | { ok: false; reason: string };

/**
 * Make the snapshot in Node and verify it: loaded back, it must give `expected` (the CPython
 * text of pulab.api.call_json("report", key)) for `key`.
 */
export async function makeSnapshot(indexURL: string, files: Record<string, string>, key: string, expected: string): Promise<SnapshotResult> {
  if (version !== SNAPSHOT_PYODIDE_VERSION) return { ok: false, reason: `pyodide ${version} is not ${SNAPSHOT_PYODIDE_VERSION}, the version the snapshot code was checked with` };
  const t0 = performance.now();
  const py = (await loadPyodide({ indexURL, _makeSnapshot: true })) as unknown as SnapshotPyodide;
  writePulab(py, files);
  py.runPython(warm(key));
  py.runPython('import gc; gc.collect()');
  zeroFreeMemory(py._module);
  const bytes = py.makeMemorySnapshot();
  const ms = performance.now() - t0;
  if (bytes.length > SNAPSHOT_MAX_BYTES) return { ok: false, reason: `snapshot ${bytes.length} bytes > ${SNAPSHOT_MAX_BYTES}` };
  try {
    const back = (await loadPyodide({ indexURL, _loadSnapshot: bytes })) as unknown as PyodideLike;
    writePulab(back, files);
    const api = back.pyimport('pulab.api') as { call_json(kind: string, text: string): string };
    const got = api.call_json('report', key);
    if (got !== expected) return { ok: false, reason: 'the snapshot gives another report than CPython' };
  } catch (e) {
    return { ok: false, reason: `the snapshot does not load back: ${e instanceof Error ? e.message : String(e)}` };
  }
  return { ok: true, bytes, ms };
}
