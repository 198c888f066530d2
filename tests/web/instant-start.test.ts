// The numbers painted before Python runs must be the numbers Python gives, and every
// fast path of the boot must fall back cleanly.
//   prerender (CPython at build time) = Pyodide: byte for byte for the seed, to 1e-12 for the golden inputs;
//   the build-time memory snapshot loads back and answers alike; a refused snapshot → full boot;
//   one runtime serves several clients (SharedWorker) without one superseding another's calls;
//   the boot timeout counts time without progress, not total time.
import { describe, it, expect, beforeAll } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { loadPyodide } from 'pyodide';
import { bootPulab, INDEX_URL, type NodePulab } from './pulab-node';
import { compareGolden, parseJsonExact } from './json-exact';
import { REPO, reportCPython, seedKey } from '../../web/build/prerender';
import { SNAPSHOT_MAX_BYTES, makeSnapshot, pulabFiles } from '../../web/build/snapshot';
import { createRuntimeHost, fastOrFull, idleTimeout, type PyodideLike, type PyodideLoader } from '../../web/src/worker-logic';
import { PULAB_FILES } from '../../web/src/pysources';
import { reportKey, type Input } from '../../web/src/state';
import type { WorkerToMain } from '../../web/src/protocol';

const GOLDEN = fileURLToPath(new URL('../golden/', import.meta.url));
const goldenKeys = readdirSync(GOLDEN).filter((f) => /^\d\d_.*\.json$/.test(f))
  .map((f) => [f, reportKey(JSON.parse(readFileSync(`${GOLDEN}${f}`, 'utf8')).input as Input)] as const);

let p: NodePulab;
beforeAll(async () => {
  p = await bootPulab();
});

describe('prerendered report = Pyodide report (text of pulab.api.call_json("report", …))', () => {
  it('seed input (the report the build paints): identical text', () => {
    const key = seedKey();
    const cpython = reportCPython(key);
    expect(JSON.parse(cpython).report.vendor.Rpm.value).toBe(15022);
    expect(p.raw('report', key)).toBe(cpython);
  });
  // Integers, strings and keys exactly; floats to 1e-12 relative: the review's phase margin
  // is a root search over libm's sin/cos, whose last bits differ between CPython's glibc and
  // Pyodide's musl (07_mv690: 4.160194652289562 vs …533).
  it.each(goldenKeys)('%s: same report (floats to 1e-12)', (_f, key) => {
    const live = parseJsonExact(p.raw('report', key));
    const built = parseJsonExact(reportCPython(key));
    expect(compareGolden(built, live)).toEqual([]);
    expect(compareGolden(live, built)).toEqual([]);
  });
});

describe('memory snapshot (build time) and its fallback', () => {
  it('is made, fits the size cap, loads back and answers as CPython; a worker boots from it', async () => {
    const key = seedKey();
    const expected = reportCPython(key);
    const r = await makeSnapshot(INDEX_URL, pulabFiles(REPO), key, expected);
    if (!r.ok) throw new Error(r.reason);
    expect(r.bytes.length).toBeLessThanOrEqual(SNAPSHOT_MAX_BYTES);
    const got = await bootHost(async () => (await loadPyodide({ indexURL: INDEX_URL, _loadSnapshot: r.bytes })) as unknown as PyodideLike);
    expect(got.ready).toMatchObject({ type: 'ready', from: 'snapshot' });
    expect(got.result).toBe(asPosted(expected));
  }, 120_000);
  it('a snapshot that is refused (corrupt bytes) → a full boot, same report, the reason noted', async () => {
    const junk = new Uint8Array(1 << 20);
    const got = await bootHost(async () => (await loadPyodide({ indexURL: INDEX_URL, _loadSnapshot: junk })) as unknown as PyodideLike);
    expect(got.ready).toMatchObject({ type: 'ready', from: 'full' });
    expect((got.ready as { note?: string }).note).toMatch(/snapshot refused/);
    expect(got.result).toBe(asPosted(reportCPython(seedKey())));
  }, 120_000);
  it('no snapshot in the build → a full boot', async () => {
    const r = await fastOrFull(null, async () => fakePy());
    expect(r.from).toBe('full');
  });
});

/** The report as the page receives it from the worker (parsed there, posted as an object). */
const asPosted = (text: string): string => JSON.stringify(JSON.parse(text));

/** Boot a runtime host with `fast` (falling back to a full boot), then run the seed report. */
async function bootHost(fast: () => Promise<PyodideLike>): Promise<{ ready: WorkerToMain | undefined; result: string }> {
  const load: PyodideLoader = () => fastOrFull(fast, async () => (await loadPyodide({ indexURL: INDEX_URL })) as unknown as PyodideLike);
  const host = createRuntimeHost(load, PULAB_FILES);
  const got: WorkerToMain[] = [];
  const send = host.connect((m) => got.push(m));
  send({ type: 'init', indexURL: INDEX_URL });
  await host.ready;
  const result = await new Promise<string>((resolve) => {
    const send2 = host.connect((m) => m.type === 'result' && resolve(JSON.stringify(m.result)));
    send2({ type: 'call', id: 1, kind: 'report', payload: seedKey() });
  });
  return { ready: got.find((m) => m.type === 'ready'), result };
}

const echo = (t: string): string => JSON.stringify({ ok: true, echo: t });
/** A stepped entry point of one slice: a generator done at once with `f`'s reply. */
const stepsOf = (f: (t: string) => string) => (_kind: string, t: string) => ({ next: () => ({ done: true, value: f(t) }), return: () => undefined, destroy: () => undefined });
/** A stand-in runtime: call_json echoes its input, so calls can be told apart. */
function fakePy(): PyodideLike {
  return {
    version: 'fake',
    FS: { mkdirTree: () => undefined, writeFile: () => undefined },
    runPython: () => undefined,
    pyimport: () => ({ call_json: (_kind: string, t: string) => echo(t), call_json_steps: stepsOf(echo) }),
  };
}

describe('one runtime, several clients (SharedWorker)', () => {
  it('a client connecting after the boot is told "ready" at once; the same channel of two clients does not coalesce', async () => {
    let boots = 0;
    const host = createRuntimeHost(async () => {
      boots++;
      return fakePy();
    }, PULAB_FILES);
    const a: WorkerToMain[] = [];
    const b: WorkerToMain[] = [];
    const sendA = host.connect((m) => a.push(m));
    sendA({ type: 'init', indexURL: 'x/' });
    await host.ready;
    const sendB = host.connect((m) => b.push(m));
    sendB({ type: 'init', indexURL: 'x/' });
    expect(b.map((m) => m.type)).toEqual(['ready']);
    sendA({ type: 'call', id: 1, kind: 'report', payload: '"a1"', channel: 'report' });
    sendB({ type: 'call', id: 1, kind: 'report', payload: '"b1"', channel: 'report' });
    sendA({ type: 'call', id: 2, kind: 'report', payload: '"a2"', channel: 'report' });
    await new Promise((r) => setTimeout(r, 20));
    expect(a.filter((m) => m.type === 'superseded')).toEqual([{ type: 'superseded', id: 1 }]);
    expect(a.filter((m) => m.type === 'result').map((m) => m.type === 'result' && m.result)).toEqual([{ ok: true, echo: '"a2"' }]);
    expect(b.filter((m) => m.type === 'result').map((m) => m.type === 'result' && m.result)).toEqual([{ ok: true, echo: '"b1"' }]);
    expect(boots).toBe(1);
  });
});

describe('queued calls: the page\'s numbers first', () => {
  it.each([
    ['trace, vendors, report → report first', ['trace', 'vendors', 'report'], ['"report"', '"trace"', '"vendors"']],
    ['report, trace → report first', ['report', 'trace'], ['"report"', '"trace"']],
    ['two channels without priority → in order', ['trace', 'vendors'], ['"trace"', '"vendors"']],
  ])('%s', async (_name, channels, order) => {
    const host = createRuntimeHost(async () => fakePy(), PULAB_FILES);
    const got: WorkerToMain[] = [];
    const send = host.connect((m) => got.push(m));
    send({ type: 'init', indexURL: 'x/' });
    await host.ready;
    await new Promise((r) => setTimeout(r, 5)); // the boot's own drain
    channels.forEach((ch, i) => send({ type: 'call', id: i + 1, kind: 'qcalc', payload: JSON.stringify(ch), channel: ch }));
    await new Promise((r) => setTimeout(r, 20));
    expect(got.filter((m) => m.type === 'result').map((m) => m.type === 'result' && m.result.ok && 'echo' in m.result && m.result.echo)).toEqual(order);
  });
});

describe('warm-up runs after the first report (idle only, never ahead of a call)', () => {
  /** A runtime whose call_json logs every report payload it computes. */
  const logging = (log: string[]): PyodideLike => {
    const run = (kind: string, t: string) => (kind === 'report' && log.push(t), echo(t));
    return { ...fakePy(), pyimport: () => ({ call_json: run, call_json_steps: stepsOf((t: string) => run('report', t)) }) };
  };
  const cases: [string, number, string, string[], string[]][] = [
    ['warmRuns 3, nothing else asked → the first report computed 3 more times', 3, 'report', [], ['"r1"', '"r1"', '"r1"', '"r1"']],
    ['warmRuns 0 → computed once', 0, 'report', [], ['"r1"']],
    ['warmRuns 3, the first report on the simulation channel → computed once (a simulation takes seconds)', 3, 'sim', [], ['"r1"']],
    ['warmRuns 20, a new report posted at once → it is computed before any warm-up run', 20, 'report', ['"r2"'], ['"r1"', '"r2"', '"r1"']],
  ];
  it.each(cases)('%s', async (_name, warmRuns, channel, next, firstComputed) => {
    const log: string[] = [];
    const host = createRuntimeHost(async () => logging(log), PULAB_FILES, { warmRuns });
    const got: WorkerToMain[] = [];
    const send = host.connect((m) => {
      got.push(m);
      // The page answers the first result with its next input at once (typing).
      if (m.type === 'result' && m.id === 1) next.forEach((p, i) => send({ type: 'call', id: 2 + i, kind: 'report', payload: p, channel }));
    });
    send({ type: 'init', indexURL: 'x/' });
    await host.ready;
    send({ type: 'call', id: 1, kind: 'report', payload: '"r1"', channel });
    await new Promise((r) => setTimeout(r, 150));
    expect(log.slice(0, firstComputed.length)).toEqual(firstComputed);
    expect(log.length).toBe(1 + next.length + (channel === 'report' ? warmRuns : 0));
    expect(got.filter((m) => m.type === 'result').length).toBe(1 + next.length);
  });
});

describe('an embed does not start the warm-up (no form to type in)', () => {
  it('embeds\' reports are computed once each; the first report of a page with a form starts the runs', async () => {
    const log: string[] = [];
    const run = (kind: string, t: string) => (kind === 'report' && log.push(t), echo(t));
    const host = createRuntimeHost(async () => ({ ...fakePy(), pyimport: () => ({ call_json: run, call_json_steps: stepsOf((t: string) => run('report', t)) }) }), PULAB_FILES, { warmRuns: 3 });
    const embed = host.connect(() => undefined);
    embed({ type: 'init', indexURL: 'x/', warm: false });
    await host.ready;
    embed({ type: 'call', id: 1, kind: 'report', payload: '"e1"', channel: 'report' });
    await new Promise((r) => setTimeout(r, 100));
    expect(log).toEqual(['"e1"']);
    const page = host.connect(() => undefined);
    page({ type: 'init', indexURL: 'x/' });
    page({ type: 'call', id: 1, kind: 'report', payload: '"p1"', channel: 'report' });
    await new Promise((r) => setTimeout(r, 100));
    expect(log).toEqual(['"e1"', '"p1"', '"p1"', '"p1"', '"p1"']);
  });
});

describe('boot timeout counts time without progress', () => {
  const slowLoader = (steps: number, every: number): PyodideLoader => async (_url, progress) => {
    for (let i = 0; i < steps; i++) {
      await new Promise((r) => setTimeout(r, every));
      progress('runtime', i / steps);
    }
    return fakePy();
  };
  it('a slow boot that keeps progressing (10 × 40 ms, idle limit 100 ms) succeeds', async () => {
    const host = createRuntimeHost(slowLoader(10, 40), PULAB_FILES);
    const got: WorkerToMain[] = [];
    host.connect((m) => got.push(m))({ type: 'init', indexURL: 'x/', timeoutMs: 100 });
    await host.ready;
    expect(got.at(-1)?.type).toBe('ready');
  });
  it('a boot that stalls (one step of 300 ms, idle limit 100 ms) fails with "no progress"', async () => {
    const host = createRuntimeHost(slowLoader(1, 300), PULAB_FILES);
    const got: WorkerToMain[] = [];
    host.connect((m) => got.push(m))({ type: 'init', indexURL: 'x/', timeoutMs: 100 });
    await expect(host.ready).rejects.toThrow(/no progress for/);
    expect(got.at(-1)).toMatchObject({ type: 'fatal' });
  });
  it('progress per network chunk reaches the pages in 1 % steps, and at every stage', async () => {
    const chunks: PyodideLoader = async (_url, progress) => {
      for (let i = 0; i <= 1000; i++) progress('runtime', 0.05 + 0.6 * (i / 1000));
      progress('snapshot', 0.7);
      return fakePy();
    };
    const host = createRuntimeHost(chunks, PULAB_FILES);
    const got: WorkerToMain[] = [];
    host.connect((m) => got.push(m))({ type: 'init', indexURL: 'x/' });
    await host.ready;
    const runtime = got.flatMap((m) => (m.type === 'progress' && m.stage === 'runtime' ? [m.fraction] : []));
    expect(runtime.length).toBeGreaterThanOrEqual(55); // 0.6 of the way in steps of ≥ 0.01
    expect(runtime.length).toBeLessThanOrEqual(61);
    runtime.slice(1).forEach((f, i) => expect(f - runtime[i]).toBeGreaterThanOrEqual(0.01 - 1e-12));
    expect(got.filter((m) => m.type === 'progress').map((m) => (m as { stage: string }).stage).filter((s, i, a) => s !== a[i - 1]))
      .toEqual(['runtime', 'snapshot', 'files', 'import', 'ready']);
  });
  it('idleTimeout: kick() restarts the clock', async () => {
    const w = idleTimeout(60, 'x');
    const t = setInterval(() => w.kick(), 20);
    const raced = await Promise.race([w.expired.then(() => 'expired', () => 'expired'), new Promise((r) => setTimeout(() => r('alive'), 200))]);
    clearInterval(t);
    w.stop();
    expect(raced).toBe('alive');
  });
});
