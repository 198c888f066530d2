// The snapshot's free memory is zeroed before it is taken (web/build/snapshot.ts): pages that only
// held freed blocks pack away, and what Python holds is untouched.
import { describe, expect, it } from 'vitest';
import { loadPyodide } from 'pyodide';
import { zeroFreeMemory } from '../../web/build/snapshot';

const dirtyBytes = (heap: Uint8Array): number => {
  let n = 0;
  for (let i = 0; i < heap.length; i += 4) if (heap[i] | heap[i + 1] | heap[i + 2] | heap[i + 3]) n += 4;
  return n;
};

describe('zeroFreeMemory', () => {
  it('zeroes what freed blocks held, and Python goes on as before', async () => {
    const py = await loadPyodide({ indexURL: 'node_modules/pyodide/', _makeSnapshot: true } as Parameters<typeof loadPyodide>[0]);
    const m = (py as unknown as { _module: Parameters<typeof zeroFreeMemory>[0] })._module;
    // 8 MB of bytes objects made and dropped: their memory goes back to malloc, still written.
    py.runPython('keep = [str(i) * 3 for i in range(1000)]\nblobs = [bytes([7]) * 65536 for _ in range(128)]\ndel blobs\nimport gc; gc.collect()');
    const before = dirtyBytes(m.HEAPU8);
    const zeroed = zeroFreeMemory(m);
    const after = dirtyBytes(m.HEAPU8);
    expect(zeroed).toBeGreaterThan(8e6);
    expect(before - after).toBeGreaterThan(7e6);
    expect(py.runPython("sum(len(s) for s in keep), keep[999]").toJs()).toEqual([8670, '999999999']);
  }, 60_000);
});
