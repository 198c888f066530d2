// The compute session without a DOM: what it publishes goes through an injected SessionEnv, and its
// Python calls through a PulabClient on a fake worker that answers at once.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { ComputeSession, type SessionEnv } from '../../web/src/page/session';
import { PulabClient, type WorkerLike } from '../../web/src/rpc';
import { SEED_INPUT, clone, encodeHash, reportKey, type Input } from '../../web/src/state';
import { effectiveInput } from '../../web/src/fields';
import type { ApiResult, MainToWorker } from '../../web/src/protocol';
import type { Report } from '../../web/src/generated/report-types';
import { reportCPython } from '../../web/build/prerender';

/** The seed's real reply (CPython's pulab.api.call_json("report", …), as the prerender makes it). */
const REPLY: ApiResult = JSON.parse(reportCPython(reportKey(SEED_INPUT)));
const REPORT: Report = JSON.parse(reportCPython(reportKey(SEED_INPUT))).report;

function fakeEnv(hash = '', known: Record<string, Report> = {}) {
  const log = { hashes: [] as string[], stored: [] as string[], sources: [] as string[], kept: [] as string[] };
  let current = hash;
  const env: SessionEnv = {
    attrs: {},
    showSource: (s) => void log.sources.push(s),
    mark: () => undefined,
    known: (key) => (known[key] ? { report: known[key], source: 'cached' } : null),
    keep: (key) => void log.kept.push(key),
    hash: () => current,
    replaceHash: (h) => {
      current = h;
      log.hashes.push(h);
    },
    storeInput: (json) => void log.stored.push(json),
    onOnline: () => undefined,
  };
  return { env, log };
}

/** A ready client whose worker answers every call with `answer(payload)`. */
function fakeClient(answer: (payload: unknown) => ApiResult): { client: PulabClient; payloads: unknown[] } {
  const payloads: unknown[] = [];
  const worker: WorkerLike = {
    onmessage: null,
    onerror: null,
    postMessage(m: MainToWorker) {
      if (m.type !== 'call') return;
      const payload: unknown = JSON.parse(m.payload);
      payloads.push(payload);
      queueMicrotask(() => worker.onmessage?.({ data: { type: 'result', id: m.id, kind: m.kind, result: answer(payload), ms: 2 } } as MessageEvent));
    },
  };
  const client = new PulabClient(worker);
  worker.onmessage?.({ data: { type: 'ready', bootMs: 1, pyodideVersion: 'test' } } as MessageEvent);
  return { client, payloads };
}

const events = () => {
  const n = { report: 0, errors: 0 };
  return { n, events: { report: () => void n.report++, sim: () => undefined, errors: () => void n.errors++, busy: () => undefined } };
};
const settle = () => new Promise((res) => setTimeout(res, 20));

function session(input: Input, env: SessionEnv, embed = false) {
  const e = events();
  const s = new ComputeSession(input, embed, e.events, env);
  s.wantsSim = false;
  return { s, n: e.n };
}

describe('ComputeSession with an injected environment', () => {
  it('a live report: timings on <html>, the link and the stored input written, the report kept', async () => {
    const { env, log } = fakeEnv();
    const { s, n } = session(clone(SEED_INPUT), env);
    const { client, payloads } = fakeClient(() => REPLY);
    s.client = client;
    s.schedule(0);
    await settle();
    expect(n.report).toBe(1);
    expect(s.source).toBe('live');
    expect(s.report?.vendor.Rpm.value).toBe(15022);
    expect(payloads).toEqual([JSON.parse(reportKey(SEED_INPUT))]);
    expect(Number(env.attrs.workerMs)).toBe(2);
    expect(env.attrs.reportMs).toMatch(/^\d+\.\d$/);
    expect(env.attrs.busy).toBeUndefined();
    expect(log.sources.at(-1)).toBe('live');
    expect(log.hashes).toEqual([encodeHash(effectiveInput(SEED_INPUT), {})]);
    expect(log.stored).toEqual([JSON.stringify(effectiveInput(SEED_INPUT))]);
    expect(log.kept).toEqual([reportKey(SEED_INPUT)]);
  });

  it('an error reply: the field error is kept, the panels are stale, no report is kept', async () => {
    const { env, log } = fakeEnv();
    const { s } = session(clone(SEED_INPUT), env);
    s.client = fakeClient(() => ({ ok: false, field: 'motor.rs_ohm', message: 'must be > 0, got -1', code: 'not_positive', params: { value: -1 } })).client;
    s.schedule(0);
    await settle();
    expect(s.remoteError?.code).toBe('not_positive');
    expect(s.stale).toBe(true);
    expect(log.kept).toEqual([]);
  });

  it('a field that does not parse makes the numbers stale at once, and live again when fixed', async () => {
    const { env, log } = fakeEnv();
    const { s } = session(clone(SEED_INPUT), env);
    s.client = fakeClient(() => REPLY).client;
    s.schedule(0);
    await settle();
    expect(log.sources.at(-1)).toBe('live');
    s.setLocalError('motor.rs_ohm', 'not a number');
    expect(log.sources.at(-1)).toBe('stale');
    s.setLocalError('motor.rs_ohm', null);
    expect(log.sources.at(-1)).toBe('live');
  });

  it('an embed leaves the address bar and the stored input to its host page', async () => {
    const { env, log } = fakeEnv();
    const { s } = session(clone(SEED_INPUT), env, true);
    s.client = fakeClient(() => REPLY).client;
    s.schedule(0);
    await settle();
    expect(s.source).toBe('live');
    expect(log.hashes).toEqual([]);
    expect(log.stored).toEqual([]);
  });

  it('an opened link that already says the input is not rewritten', async () => {
    const eff = effectiveInput(SEED_INPUT);
    const { env, log } = fakeEnv(encodeHash(eff, {}));
    const { s } = session(clone(SEED_INPUT), env);
    s.client = fakeClient(() => REPLY).client;
    s.schedule(0);
    await settle();
    expect(log.hashes).toEqual([]);
  });

  it('before Python is ready, a known report is painted at once and marked cached', () => {
    const { env, log } = fakeEnv('', { [reportKey(SEED_INPUT)]: REPORT });
    const { s } = session(clone(SEED_INPUT), env);
    expect(s.report).toBe(REPORT);
    s.publish();
    expect(log.sources.at(-1)).toBe('cached');
  });

  it('a form replaced without a simulation section (a blank datasheet) is still simulated', async () => {
    const { env } = fakeEnv();
    const e = events();
    const s = new ComputeSession(clone(SEED_INPUT), false, e.events, env);
    const { client, payloads } = fakeClient(() => REPLY);
    s.client = client;
    s.simClient = client;
    const golden = JSON.parse(readFileSync('tests/golden/datasheets/emrax_228_lv.json', 'utf8')).input as Input;
    s.replaceInput(golden);
    await new Promise((res) => setTimeout(res, 600));
    const simmed = payloads.filter((p) => (p as Input).sim) as Input[];
    expect(simmed.length).toBe(1);
    expect(simmed[0].datasheet).toEqual(golden.datasheet);
  });
});
