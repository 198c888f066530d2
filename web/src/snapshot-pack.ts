// The memory snapshot as it is shipped: the heap without its all-zero pages (≈ 45 % of the
// 30 MB heap), put back in place by the worker while the file downloads. The browser then
// decompresses (brotli) 17 MB instead of 30 MB — about a third less of its time — and the worker
// copies only the pages that hold something into a buffer that starts out zeroed.
//
// Layout, little-endian uint32 words: MAGIC, PAGE, heap size, run count, then per run its first
// page and its page count (ascending, not overlapping), then the bytes of every run in order (the
// heap's last page may be short).

export const PACK_MAGIC = 0x314c5550; // 'PUL1'
export const PACK_PAGE = 4096;
const HEAD = 16;

const isZero = (b: Uint8Array, from: number, to: number): boolean => {
  for (let i = from; i < to; i++) if (b[i] !== 0) return false;
  return true;
};

/** The packed form of `heap`. */
export function packSnapshot(heap: Uint8Array): Uint8Array {
  const pages = Math.ceil(heap.length / PACK_PAGE);
  const runs: [number, number][] = [];
  for (let p = 0; p < pages; p++) {
    if (isZero(heap, p * PACK_PAGE, Math.min(heap.length, (p + 1) * PACK_PAGE))) continue;
    const last = runs[runs.length - 1];
    if (last && last[0] + last[1] === p) last[1]++;
    else runs.push([p, 1]);
  }
  const spans = runs.map(([p, n]) => [p * PACK_PAGE, Math.min(heap.length, (p + n) * PACK_PAGE)] as const);
  const head = HEAD + 8 * runs.length;
  const out = new Uint8Array(head + spans.reduce((s, [a, b]) => s + b - a, 0));
  const words = new DataView(out.buffer);
  [PACK_MAGIC, PACK_PAGE, heap.length, runs.length].forEach((w, i) => words.setUint32(4 * i, w, true));
  runs.forEach(([p, n], i) => {
    words.setUint32(HEAD + 8 * i, p, true);
    words.setUint32(HEAD + 8 * i + 4, n, true);
  });
  let at = head;
  for (const [a, b] of spans) {
    out.set(heap.subarray(a, b), at);
    at += b - a;
  }
  return out;
}

/**
 * Puts a packed snapshot, pushed chunk by chunk as it downloads, into `heap` (zeroed, of the
 * heap's size). Throws at the first byte that does not fit the layout or this heap.
 */
export class SnapshotUnpacker {
  private head: Uint8Array = new Uint8Array(HEAD);
  private headAt = 0;
  /** Start and end offset in the heap of each run, once the run table is read. */
  private spans: [number, number][] | null = null;
  private run = 0;
  private inRun = 0;

  constructor(readonly heap: Uint8Array) {}

  push(chunk: Uint8Array): void {
    let at = 0;
    while (at < chunk.length) {
      if (!this.spans) {
        const n = Math.min(this.head.length - this.headAt, chunk.length - at);
        this.head.set(chunk.subarray(at, at + n), this.headAt);
        this.headAt += n;
        at += n;
        if (this.headAt === this.head.length) this.readHead();
        continue;
      }
      const span = this.spans[this.run];
      if (!span) throw new Error('snapshot: longer than its run table');
      const n = Math.min(span[1] - span[0] - this.inRun, chunk.length - at);
      this.heap.set(chunk.subarray(at, at + n), span[0] + this.inRun);
      this.inRun += n;
      at += n;
      if (this.inRun === span[1] - span[0]) {
        this.run++;
        this.inRun = 0;
      }
    }
  }

  /** The runs that hold something, as [start, end) offsets in the heap (the rest is zero); empty before the run table is read. */
  get runs(): readonly (readonly [number, number])[] {
    return this.spans ?? [];
  }

  /** Every byte was pushed: throws if the file ended early. */
  finish(): Uint8Array {
    if (!this.spans || this.run !== this.spans.length) throw new Error('snapshot: shorter than its run table');
    return this.heap;
  }

  private readHead(): void {
    const w = new DataView(this.head.buffer, this.head.byteOffset, this.head.length);
    if (this.head.length === HEAD) {
      const [magic, page, size, runs] = [0, 1, 2, 3].map((i) => w.getUint32(4 * i, true));
      if (magic !== PACK_MAGIC || page !== PACK_PAGE) throw new Error('snapshot: not a packed pulab snapshot');
      if (size !== this.heap.length) throw new Error(`snapshot: a heap of ${size} bytes, not the ${this.heap.length} built`);
      if (runs > Math.ceil(size / PACK_PAGE)) throw new Error('snapshot: a broken run table');
      const grown = new Uint8Array(HEAD + 8 * runs);
      grown.set(this.head);
      this.head = grown;
      if (runs > 0) return;
    }
    const spans: [number, number][] = [];
    let end = 0;
    for (let i = HEAD; i < this.head.length; i += 8) {
      const first = w.getUint32(i, true) * PACK_PAGE;
      const stop = Math.min(this.heap.length, first + w.getUint32(i + 4, true) * PACK_PAGE);
      if (first < end || stop <= first) throw new Error('snapshot: a broken run table');
      spans.push([first, stop]);
      end = stop;
    }
    this.spans = spans;
  }
}

/** Zero every 4-byte word of `mem` in [from, to) that is not zero already, without writing (so making resident) the pages that are. */
function clearNonZero(mem: Int8Array, from: number, to: number): void {
  const words = new Int32Array(mem.buffer, mem.byteOffset, mem.length >>> 2);
  const w0 = Math.ceil(from / 4);
  const w1 = Math.floor(to / 4);
  for (let i = from; i < Math.min(to, w0 * 4); i++) if (mem[i] !== 0) mem[i] = 0;
  for (let i = w0; i < w1; i++) if (words[i] !== 0) words[i] = 0;
  for (let i = Math.max(from, w1 * 4); i < to; i++) if (mem[i] !== 0) mem[i] = 0;
}

/**
 * Pyodide restores the heap with one `HEAP8.set(snapshot)`, which writes every page of the wasm
 * memory — the 14 MB of all-zero pages (46 %) too, each of them resident from then on in the
 * browser's memory. While Pyodide boots, that one call (known by its source: a view of this
 * snapshot's buffer) copies the runs that hold something and leaves the fresh memory, zero
 * already, untouched elsewhere, clearing only what the wasm's instantiation wrote there (its data
 * segments). Returns the undo.
 */
export function restoreSparsely(snapshot: Uint8Array, runs: readonly (readonly [number, number])[]): () => void {
  type Set = (this: ArrayLike<number>, src: ArrayLike<number>, offset?: number) => void;
  const proto = Object.getPrototypeOf(Int8Array.prototype) as { set: Set };
  const set = proto.set;
  proto.set = function (this: ArrayLike<number>, src: ArrayLike<number>, offset = 0) {
    const ours = src instanceof Uint8Array && src.buffer === snapshot.buffer && this instanceof Int8Array && offset === 0
      && src.byteOffset >= snapshot.byteOffset && src.byteOffset + src.length === snapshot.byteOffset + snapshot.length && src.length <= this.length;
    if (!ours) return set.call(this, src, offset);
    const base = src.byteOffset - snapshot.byteOffset; // the heap's start in the snapshot (its header comes first)
    let done = 0;
    for (const [s, e] of runs) {
      const a = Math.max(0, s - base);
      const b = e - base;
      if (b <= a) continue;
      clearNonZero(this, done, a);
      set.call(this, src.subarray(a, b), a);
      done = b;
    }
    clearNonZero(this, done, src.length);
  };
  return () => {
    proto.set = set;
  };
}
