// The shipped snapshot without its zero pages: packed at build time, put back in place chunk by
// chunk as it downloads (web/src/snapshot-pack.ts).
import { describe, expect, it } from 'vitest';
import { PACK_PAGE, SnapshotUnpacker, packSnapshot } from '../../web/src/snapshot-pack';

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
