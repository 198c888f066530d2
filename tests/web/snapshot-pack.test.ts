// The shipped snapshot without its zero pages: packed at build time, put back in place chunk by
// chunk as it downloads (web/src/snapshot-pack.ts).
import { describe, expect, it } from 'vitest';
import { PACK_PAGE, SnapshotUnpacker, packSnapshot, restoreSparsely } from '../../web/src/snapshot-pack';

/** A heap of `pages` pages (the last one `tail` bytes short) where the pages in `used` hold bytes. */
function heap(pages: number, used: number[], tail = 0): Uint8Array {
  const h = new Uint8Array(pages * PACK_PAGE - tail);
  for (const p of used) for (let i = p * PACK_PAGE; i < Math.min(h.length, (p + 1) * PACK_PAGE); i += 97) h[i] = (i % 251) + 1;
  return h;
}
function unpack(packed: Uint8Array, size: number, chunk: number): Uint8Array {
  const u = new SnapshotUnpacker(new Uint8Array(size));
  for (let at = 0; at < packed.length; at += chunk) u.push(packed.subarray(at, at + chunk));
  return u.finish();
}

describe('snapshot packing', () => {
  it.each([
    ['runs at both ends, a short last page', heap(40, [0, 1, 2, 10, 11, 39], 100)],
    ['every page used', heap(8, [0, 1, 2, 3, 4, 5, 6, 7])],
    ['no page used', heap(8, [])],
  ])('%s: unpacked in chunks of any size gives the heap back', (_name, h) => {
    const packed = packSnapshot(h);
    for (const chunk of [1, 7, 4096, 65536, packed.length]) expect(unpack(packed, h.length, chunk)).toEqual(h);
  });

  it('only the used pages are shipped', () => {
    const h = heap(40, [0, 1, 2, 10, 11, 39]);
    expect(packSnapshot(h).length).toBe(16 + 8 * 3 + 6 * PACK_PAGE);
  });

  it('junk, another heap size, a file cut short or too long: refused', () => {
    const h = heap(40, [0, 5, 6]);
    const packed = packSnapshot(h);
    expect(() => unpack(new Uint8Array(4096).fill(7), h.length, 512)).toThrow(/not a packed/);
    expect(() => unpack(packed, h.length + PACK_PAGE, 512)).toThrow(/heap of/);
    expect(() => unpack(packed.subarray(0, packed.length - 1), h.length, 512)).toThrow(/shorter/);
    const longer = new Uint8Array(packed.length + 1);
    longer.set(packed);
    expect(() => unpack(longer, h.length, 512)).toThrow(/longer/);
  });
});

describe('the heap restored sparsely (Pyodide\'s one HEAP8.set of the snapshot)', () => {
  /** A fresh wasm memory: zero, but for "data segments" the instantiation wrote (`segs`: [from, to) byte ranges). */
  const memory = (size: number, segs: [number, number][]): Int8Array => {
    const m = new Int8Array(size);
    for (const [a, b] of segs) for (let i = a; i < b; i++) m[i] = -((i % 120) + 1);
    return m;
  };
  it.each([
    ['header 128 bytes, data segments inside zero pages and straddling runs', 40, [0, 1, 2, 10, 11, 39], 100, 128, [[5, 300], [4000, 9000], [20000, 20003], [41 * 1024, 45 * 1024]]],
    ['header of 3 bytes (unaligned words), segment at the very end', 12, [0, 3, 4, 11], 5, 3, [[7, 11], [12 * PACK_PAGE - 300, 12 * PACK_PAGE - 5 - 3]]],
    ['every page used', 8, [0, 1, 2, 3, 4, 5, 6, 7], 0, 128, [[0, 5000]]],
    ['no page used but the header', 8, [0], 0, 128, [[6000, 7000]]],
  ] as [string, number, number[], number, number, [number, number][]][])('%s: the memory ends equal to a full copy', (_n, pages, used, tail, header, segs) => {
    const snap = heap(pages, used, tail);
    const u = new SnapshotUnpacker(new Uint8Array(snap.length));
    u.push(packSnapshot(snap));
    const got = u.finish();
    const body = got.subarray(header); // Pyodide: t = t.subarray(header); HEAP8.set(t)
    const want = memory(body.length + 64, segs);
    want.set(body);
    const mem = memory(body.length + 64, segs);
    // Count the bytes the engine's own set copies into the memory: only the runs that hold something.
    const proto = Object.getPrototypeOf(Int8Array.prototype) as { set: (this: ArrayLike<number>, s: ArrayLike<number>, o?: number) => void };
    const native = proto.set;
    let copied = 0;
    proto.set = function (src, offset) {
      if (this === mem) copied += src.length;
      return native.call(this, src, offset);
    };
    const undo = restoreSparsely(got, u.runs);
    try {
      mem.set(body);
      // any other set goes through untouched
      const other = new Int8Array(4);
      other.set([1, 2, 3]);
      expect([...other]).toEqual([1, 2, 3, 0]);
    } finally {
      undo();
      proto.set = native;
    }
    expect(mem).toEqual(want);
    const runBytes = u.runs.reduce((n, [a, b]) => n + Math.max(0, b - Math.max(a, header)), 0);
    expect(copied).toBe(runBytes);
    if (used.length < pages) expect(copied).toBeLessThan(body.length);
  });
});
